// Textures: layers, maps (new and old forms), list patterns, warps and
// transforms applied before and after the texture.
#version 3.7;
#declare P = pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } scale 2 }
sphere { 0, 1 pigment { P } translate x }
sphere { 0, 1 translate x pigment { P } }
sphere { 0, 1 pigment { checker color rgb <1,0,0> color rgb <0,0,1> } }
sphere { 0, 1 pigment { checker pigment { P }, pigment { rgb 1 } } }
sphere { 0, 1 pigment { bozo color_map { [0, 0.5 color rgb 0 color rgb 1] [0.5, 1 color rgb 1 color rgb 0.5] } } }
sphere { 0, 1 pigment { marble turbulence 0.5 octaves 4 lambda 3 sine_wave frequency 2
                        color_map { [0 rgbf <1,1,1,0.5>] [1 rgbt <0,0,0,0.25>] } } }
sphere { 0, 1 pigment { wood warp { repeat x flip y } pigment_map { [0 P] [1 rgb 1] } } }
sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt <1,0,0,0.5> } normal { bumps 0.4 scale 0.1 } } }
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } scale 0.5 } }
sphere { 0, 1 texture { gradient x texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 } finish { phong 1 }] } } }
sphere { 0, 1 normal { gradient x, 0.5 slope_map { [0 <0, 1>] [1 <1, 0>] } } }
