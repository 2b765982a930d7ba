// SPDX-License-Identifier: MIT
// 160_object_uv_mapping.pov: uv_mapping written on the object, before its
// texture (POV-Ray 3.7's UV_FLAG): the whole texture is evaluated at the
// surface's <u, v, 0>, and the object's transforms after it do not move
// the texture (they stay in object space, the uv do not change). Left: a
// bent mesh2 strip whose uv are not its positions, with a checker, then
// scaled and rotated. Right: a mesh2 with a texture_map on gradient x
// (the map pattern and its entries in uv space). Middle: a
// sphere (its uv: POV-Ray's spherical map) with a layered texture.
// Before session 6 iris ignored an object's uv_mapping (patterns at the
// object-space point): 19.5 dB here (80x60, +A0.3, measured before the
// top panel was added), and evaluated the pigments of a uv-mapped
// pigment_map at the object-space point: 28.7 dB with only that undone;
// advanced/benchmark/benchmark.pov's checkered vase and
// advanced/balcony's table cloth border.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -7> look_at <0, 0.5, 0> right x*4/3 angle 58 }
light_source { <-5, 8, -10> color rgb 1 }
#declare Strip = mesh2 {
  vertex_vectors { 12,
    <-1, 0, 0>, <-0.4, 0, -0.6>, <0.4, 0, -0.6>, <1, 0, 0>,
    <-1, 0.8, 0>, <-0.4, 0.8, -0.6>, <0.4, 0.8, -0.6>, <1, 0.8, 0>,
    <-1, 1.6, 0.2>, <-0.4, 1.6, -0.4>, <0.4, 1.6, -0.4>, <1, 1.6, 0.2> }
  normal_vectors { 12,
    <-1, 0, -0.6>, <-0.3, 0, -1>, <0.3, 0, -1>, <1, 0, -0.6>,
    <-1, 0, -0.6>, <-0.3, 0, -1>, <0.3, 0, -1>, <1, 0, -0.6>,
    <-1, 0.2, -0.6>, <-0.3, 0.2, -1>, <0.3, 0.2, -1>, <1, 0.2, -0.6> }
  uv_vectors { 12,
    <0, 0>, <0.333, 0>, <0.667, 0>, <1, 0>,
    <0, 0.5>, <0.333, 0.5>, <0.667, 0.5>, <1, 0.5>,
    <0, 1>, <0.333, 1>, <0.667, 1>, <1, 1> }
  face_indices { 12,
    <0, 1, 5>, <0, 5, 4>, <1, 2, 6>, <1, 6, 5>, <2, 3, 7>, <2, 7, 6>,
    <4, 5, 9>, <4, 9, 8>, <5, 6, 10>, <5, 10, 9>, <6, 7, 11>, <6, 11, 10> }
}
object { Strip
  uv_mapping
  texture { pigment { checker color rgb <1, 0.7, 0.5> color rgb <0, 0, 0.3>
                      scale 0.2 translate 0.03 }
            finish { ambient 0.2 diffuse 0.7 specular 0.3 } }
  scale <1.1, 1.2, 1> rotate 25*y translate <-2.3, -0.3, 0> }
object { Strip
  uv_mapping
  texture {
    gradient x
    texture_map {
      [0.5 pigment { color rgb <0.9, 0.2, 0.1> } finish { ambient 0.2 }]
      [0.5 pigment { gradient y color_map { [0 rgb <0.1, 0.3, 0.9>] [1 rgb <0.9, 0.9, 0.2>] } }
           finish { ambient 0.2 }]
    }
    scale <0.5, 1, 1>
  }
  rotate -20*y scale <1, 1.2, 1> translate <2.3, -0.3, 0> }
sphere { 0, 0.9
  uv_mapping
  texture { pigment { checker color rgb <0.2, 0.8, 0.3> color rgb 1 scale <0.125, 0.25, 1> } }
  texture { pigment { gradient x color_map { [0 rgbt <0, 0, 0, 1>] [0.9 rgbt <0, 0, 0, 1>] [0.9 rgbt <0.5, 0, 0.5, 0>] [1 rgbt <0.5, 0, 0.5, 0>] } } }
  rotate <30, 20, 0> translate <0, 0.5, 0.5> }
// Top: uv_mapping in the texture (not the object) with a pigment_map
// whose entries are patterns: they are evaluated at the uv point too.
#declare Cols = pigment { gradient x triangle_wave
  color_map { [0.1 rgb <0.8, 0.7, 0.4>] [0.1 rgb <0.07, 0.12, 0.4>]
              [0.3 rgb <0.07, 0.12, 0.4>] [0.3 rgb <0.8, 0.7, 0.4>] } }
mesh2 { vertex_vectors { 4, <-2, 1.5, 2>, <2, 1.5, 2>, <2, 2.7, 2>, <-2, 2.7, 2> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  texture { uv_mapping
            pigment { gradient y triangle_wave
                      pigment_map { [0.1 Cols] [0.1 rgb <0.07, 0.12, 0.4>]
                                    [0.3 rgb <0.07, 0.12, 0.4>] [0.3 Cols] }
                      scale 0.5 }
            finish { ambient 0.3 } } }
plane { y, -0.4 pigment { color rgb 0.6 } finish { ambient 0.2 } }
