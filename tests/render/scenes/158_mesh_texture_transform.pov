// SPDX-License-Identifier: MIT
// 158_mesh_texture_transform.pov: a mesh's own textures (mesh2's
// texture_list, a mesh triangle's texture) move with the mesh when the
// mesh is transformed, as POV-Ray 3.7's Mesh::Transform transforms its
// texture array with the shape. One declared mesh2 (two quads, two
// textures from its texture_list) is used twice with different scales,
// rotations and translations (the copies share the declared texture
// array, which must stay untransformed for the second copy), beside a
// mesh { triangle { ... texture {} } } moved the same way. The patterns
// are fine enough (0.25 units) that an unmoved texture shows a different
// picture. With the textures left where they were parsed (iris before
// session 6) 22.0 dB; camera/mesh_camera/*.pov, whose Wings3D vases are
// declared mesh2 with a texture_list and then scaled, rose from 25-29 dB
// to 41-46 dB at 160x120 with the fix.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -10> look_at <0, 0, 0> right x*4/3 angle 40 }
light_source { <-20, 30, -40> color rgb 1 }
background { rgb <0.1, 0.15, 0.3> }
#declare Q = mesh2 {
  vertex_vectors { 6, <0, 0, 0>, <1, 0, 0>, <2, 0, 0>,
                      <0, 1, 0>, <1, 1, 0>, <2, 1, 0> }
  texture_list { 2,
    texture { pigment { gradient x color_map { [0 rgb <1, 0.9, 0.3>]
                                               [1 rgb <0.8, 0.1, 0.1>] }
                        scale 0.25 } finish { ambient 0.1 diffuse 0.8 } }
    texture { pigment { checker rgb <0.2, 0.6, 0.3>, rgb <0.9, 0.9, 0.9>
                        scale 0.25 } finish { ambient 0.1 diffuse 0.8 } } }
  face_indices { 4, <0, 1, 4>, 0, <0, 4, 3>, 0, <1, 2, 5>, 1, <1, 5, 4>, 1 }
}
object { Q scale 1.7 translate <-3.6, 0.3, 0> }
object { Q scale <1.2, 1.7, 1> rotate 20*z translate <0.9, -2.6, 0> }
// a mesh triangle's texture must be an identifier in POV-Ray
#declare Onion = texture { pigment { onion scale 0.3
    color_map { [0 rgb <0.2, 0.3, 1>] [1 rgb 1] } }
  finish { ambient 0.1 diffuse 0.8 } }
#declare Bozo = texture { pigment { bozo
    color_map { [0 rgb <0.9, 0.5, 0.1>] [1 rgb <0.1, 0.1, 0.4>] } scale 0.2 }
  finish { ambient 0.1 diffuse 0.8 } }
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> texture { Onion } }
  triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> texture { Bozo } }
  scale 2.2 rotate -15*z translate <0.6, 0.6, -0.5>
}
