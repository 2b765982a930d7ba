// expect: 2 5
#version 3.7;
camera { location <0,1,-3> look_at 0 }
light_source { <0,5,-5>, rgb 1 }
plane { y, 0 pigment { image_map { png "no_such_image.png" } } }
text { ttf "no_such_font" "A", 1, 0 }
