// expect: 2 5
#version 3.7;
camera { location <0, 1, -3> look_at 0 }
light_source { <0, 5, -5>, rgb 1 }
sphere { 0, 1 texture { material_map { png "no_such_map.png" texture { pigment { rgb 1 } } } } }
