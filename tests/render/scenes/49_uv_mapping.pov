// Parity scene: uv_mapping in a pigment, a normal and a texture. POV-Ray
// evaluates the pattern at the surface's <u, v, 0> (its UV_MAP_PATTERN),
// where no transform of the object reaches it, and a sphere's u runs
// from +x towards +z. iris once ignored the keyword and used the 3D
// point (objects/mesh2.pov: 11.2 dB; 18.3 dB here), and its sphere u ran
// towards -z. The rest (44.9 dB at 80x60) is the gradient normal on the
// sphere, along the checker edges.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> right x*4/3 angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
mesh2 { vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 2, 0>, <-1, 2, 0> }
  uv_vectors { 4, <0, 0>, <2, 0>, <2, 1.5>, <0, 1.5> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { uv_mapping spiral2 5 color_map { [0.5 rgb <0.6, 0.1, 0>] [0.5 rgb 1] } scale 0.4 translate <1, 0.7, 0> }
  rotate y*-20 translate <-1.4, 0, 1> }
sphere { <1.4, 1, 0>, 1
  texture { uv_mapping pigment { checker rgb <0.1, 0.3, 0.8>, rgb 1 scale <0.1, 0.2, 1> }
    normal { gradient x 2 scale 0.05 } }
  rotate y*30 }
