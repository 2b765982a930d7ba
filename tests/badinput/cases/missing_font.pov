// expect: 2 5
#version 3.7;
camera { location <0,1,-3> look_at 0 }
light_source { <0,5,-5>, rgb 1 }
text { ttf "no_such_font" "A", 1, 0 }
