// expect: 2 5
#version 3.7;
camera { location <0, 1, -3> look_at 0 }
light_source { <0, 5, -5>, rgb 1 }
rainbow { angle 42 width 5 direction z arc_angle 400 color_map { [0 rgb 1] [1 rgb 0] } }
