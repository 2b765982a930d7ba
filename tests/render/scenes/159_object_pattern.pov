// SPDX-License-Identifier: MIT
// 159_object_pattern.pov: the object pattern (POV-Ray 3.7's
// ObjectPattern): the second colour where the pattern-space point is
// inside the object, the first outside. A plane crosses the object, a
// union holding a difference (box minus sphere), a prism (an outline
// made once: geom_prepare), an intersection with an inverse plane, a
// clipped_by sphere, and a closed mesh2 whose inside comes from its
// inside_vector (the odd crossings of the ray along it). The pattern is
// rotated and moved, which moves the object with it. Before session 6
// iris parsed the pattern and never evaluated it (every point outside):
// 15.8 dB here; advanced/object_pattern.pov 27.0 -> 41.4 dB at 160x120.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at <0, 0, 0> right x*4/3 angle 55 }
light_source { <-5, 8, -10> color rgb 1 }
#declare O = union {
  difference {
    box { <-2.4, -1.7, -1>, <-0.4, 0.1, 1> }
    sphere { <-1.4, -0.8, 0>, 0.6 }
  }
  prism { linear_sweep linear_spline -1, 1, 6,
    <0.3, 0.3>, <1.9, 0.5>, <1.2, 1.8>, <0.8, 1.0>, <0.2, 1.5>, <0.3, 0.3>
    rotate -90*x }
  intersection {
    cylinder { <0, 0, -1>, <0, 0, 1>, 0.9 }
    plane { x, -0.3 inverse }
    translate <-1.2, 1.4, 0>
  }
  box { <-0.2, -2.2, -1>, <1.0, -0.3, 1> clipped_by { sphere { <0.4, -1.2, 0>, 0.75 } } }
  mesh2 {
    vertex_vectors { 4, <1.3, -1.6, -1>, <2.6, -1.6, -1>, <1.9, 0.0, -1>,
                        <1.9, -0.8, 1.5> }
    face_indices { 4, <0, 1, 2>, <0, 1, 3>, <1, 2, 3>, <0, 2, 3> }
    inside_vector <0.3, 0.2, 1>
  }
}
plane { z, 0
  pigment { object { O color rgb <0.9, 0.8, 0.3> color rgb <0.2, 0.3, 0.8> }
            rotate 10*z translate <0.1, 0.05, 0> }
  finish { ambient 0.2 diffuse 0.7 }
}
