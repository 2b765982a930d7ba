// POV-Ray 3.7's list patterns square (4 entries by the parity of the
// unit squares of the x-z plane), triangular (6 entries around every
// vertex of a lattice of unit triangles in the x-z plane) and cubic (6
// entries on the pyramids towards +x, +y, +z, -x, -y, -z), as colour
// lists, a texture list and a normal list. iris parsed square and
// triangular but evaluated them as 0 (the first entry everywhere: 8.3
// and 6.9 dB on an Insert Menu preview alone) and refused 'cubic' as a
// pattern (a parse error). The third colour is written behind a
// directive, the last one with a trailing ',' (both legal in POV-Ray).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -5.5> look_at <0, 0.3, 0> right x*4/3 }
light_source { <3, 9, -6> color rgb 1 }
plane { y, 0
    pigment { triangular
        color rgb <0.9, 0.2, 0.2>, color rgb <0.2, 0.8, 0.2>,
        #if (1) color rgb <0.2, 0.3, 0.9>, #end
        color rgb <0.9, 0.9, 0.2>, color rgb <0.2, 0.8, 0.8>,
        color rgb <0.8, 0.3, 0.8>,
        scale 0.45 rotate y*10 } }
sphere { <-1.6, 1, 0.5>, 1
    pigment { cubic color rgb <1, 0.2, 0.1>, color rgb <0.2, 1, 0.2>,
              color rgb <0.2, 0.3, 1>, color rgb <1, 1, 0.2>,
              color rgb <0.2, 1, 1>, color rgb <1, 0.2, 1>
              rotate <30, 40, 0> } }
box { <0.4, 0, -0.6>, <2.6, 1.2, 1.2>
    texture { square
        texture { pigment { rgb <0.95, 0.95, 0.9> } }
        texture { pigment { rgb <0.1, 0.1, 0.1> } finish { phong 0.8 } }
        texture { pigment { rgb <0.7, 0.2, 0.1> } }
        texture { pigment { rgb <0.1, 0.3, 0.7> } },
        scale 0.3 rotate <0, 20, 0> } }
sphere { <0.6, 0.45, -1.6>, 0.45
    pigment { rgb <0.9, 0.8, 0.6> }
    normal { square normal { bumps 0.8 scale 0.05 }, normal { dents 0.8 scale 0.05 },
             normal { agate 0.5 scale 0.1 }, normal { granite 0.6 scale 0.2 }
             scale 0.15 } }
