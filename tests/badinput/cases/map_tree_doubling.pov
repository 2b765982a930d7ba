// expect: 2 11
#version 3.7;
// Found by libFuzzer (CI, session 13): a pigment_map whose entries share
// one declared pigment doubles its tree at each level while its memory
// stays small; 40 levels make a tree of 2^40 pigments, and every walk
// over it (the parser's transform sharing, the renderer's texture
// checks) ran for ever. The parser counts the tree as it is built and
// stops at the level that passes 2^18 pigments, with the map's place.
#declare P = pigment { checker rgb 0 rgb 1 }
#for (I, 1, 40)
  #declare P = pigment { checker P P scale 0.5 }
#end
camera { location -3*z look_at 0 }
light_source { <1, 2, -3> rgb 1 }
sphere { 0, 1 pigment { P rotate 10*y } }
