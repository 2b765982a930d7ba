// Forms users' scenes write that POV-Ray 3.7 accepts (found by rendering
// hand-written scenes against POV-Ray, issue 4):
// - texture { PigmentId }, texture { NormalId FinishId }: the identifiers
//   replace that part of a plain texture (textures.inc's Jade is a
//   pigment); the dump must show the declared pigment's colour (0.2 0.4
//   0.6) and the finish's phong 0.7;
// - mesh2 face_indices whose texture indices are expressions (mod(I, 2))
//   and three per face: faces alternate textures 0 1 0 1 (blends: 2, 3);
// - isosurface { ... open max_gradient 3 }: 'open' among the isosurface's
//   own keywords, so max_gradient after it is still read (dump: open,
//   max_gradient 3);
// - the spherical camera's 'angle H V' (no comma): vertical angle 60;
// - vstr() prints 2 to 5 components and a float as <f, 0, 0>, not
//   promoted: "[2,0,0] [1,2] [1,2,0,0]" (POV-Ray 3.7 prints the same).
#declare PigId = pigment { color rgb <0.2, 0.4, 0.6> }
#declare FinId = finish { phong 0.7 }
#declare NorId = normal { bumps 0.5 }
camera { spherical location <0, 0, -5> look_at 0 angle 200 60 }
sphere { 0, 1 texture { PigId } }
sphere { 0, 1 texture { NorId FinId } }
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { PigId } }
  face_indices { 4,
    #for (I, 0, 3) <0, 1, 2>, mod(I, 2), #end }
}
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <1,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { PigId } }
  face_indices { 2, <0, 1, 2>, 1, 0, 1, <0, 2, 1>, 0, 1, 1 }
}
isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } }
  open max_gradient 3 }
#debug concat("[", vstr(3, 2, ",", 0, 0), "] [", vstr(1, <1,2,3>, ",", 0, 0), "] [", vstr(4, <1,2>, ",", 0, 0), "]\n")
