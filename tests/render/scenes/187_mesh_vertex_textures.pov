// Parity scene: mesh faces with three textures. A mesh2 face with three
// texture indices, and a mesh triangle with texture_list { A, B, C },
// shade all three textures and mix them by the point's place on the face
// (POV-Ray's Mesh::Determine_Textures: the weight of a corner's texture is
// 1 - Calculate_Smooth_T, the barycentric coordinate), so colours run
// smoothly across the mesh. Here a wavy mesh2 grid whose vertices carry
// one of three textures (one with a phong highlight), scaled and rotated
// after the parse, and beside it a mesh with texture_list triangles, one
// texture a checker, declared and used twice through object{} with
// different transforms. iris took the first index of each mesh2 face (a
// patchwork of flat faces: reverted 21.1 dB at 80x60 +A0.3, the mesh{}
// blended) and stopped at a triangle's texture_list with a parse error;
// with the blend 84.9 dB (the mesh2 alone identical).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 3.4, -4.2> look_at <0.3, 0, 0.5> angle 60 }
light_source { <3, 8, -4> color rgb 1 }
background { rgb <0.1, 0.15, 0.3> }
#declare N = 6;
mesh2 {
  vertex_vectors { (N + 1) * (N + 1),
    #for (J, 0, N) #for (I, 0, N)
      <I / N * 4 - 2, 0.3 * sin(I / N * 2 * pi) * cos(J / N * 2 * pi), J / N * 4 - 2>
    #end #end }
  texture_list { 3,
    texture { pigment { rgb <1, 0.2, 0.1> } }
    texture { pigment { rgb <1, 0.9, 0.2> } finish { phong 0.5 } }
    texture { pigment { rgb <0.2, 0.4, 1> } } }
  face_indices { N * N * 2,
    #for (J, 0, N - 1) #for (I, 0, N - 1)
      #local A = J * (N + 1) + I;
      <A, A + 1, A + N + 2>, mod(A, 3), mod(A + 1, 3), mod(A + N + 2, 3),
      <A, A + N + 2, A + N + 1>, mod(A, 3), mod(A + N + 2, 3), mod(A + N + 1, 3),
    #end #end }
  pigment { rgb <0.3, 0.9, 0.4> }
  scale <0.8, 1, 0.8> rotate 20 * y translate <-0.9, 0, 0.6>
}
#declare TA = texture { pigment { rgb <0.9, 0.1, 0.6> } }
#declare TB = texture { pigment { rgb <0.1, 0.9, 0.8> } finish { phong 0.5 } }
#declare TC = texture { pigment { checker rgb <1, 0.6, 0.1> rgb 1 scale 0.15 } }
#declare M = mesh {
  triangle { <-1, 0, -1>, <0, 0.4, 1>, <1, -0.1, -1> texture_list { TA, TB, TC } }
  smooth_triangle { <-1, 0, -1>, <0, 1, 0>, <-1.2, 0.1, 1>, <0.3, 1, 0>,
                    <0, 0.4, 1>, <0, 1, -0.3> texture_list { TC TA TB } }
  triangle { <1, -0.1, -1>, <0, 0.4, 1>, <1.3, 0, 0.8> texture { TB } }
  pigment { rgb <0.3, 0.9, 0.4> }
}
object { M scale 0.8 rotate -25 * y translate <1.7, 0.3, -0.4> }
object { M scale <0.6, 1, 0.6> rotate 150 * y translate <1.6, -0.3, 2> }
