// Parity scene: a mesh2 whose faces pick textures from its texture_list
// by expressions (mod(I + J, 2), as loops that generate meshes write
// them), some with three (equal) indices, and a row of faces with none,
// which take the object's texture (POV-Ray's Texture = -1). iris read
// only a plain number or float identifier there and rejected the scene
// (reverted: "expected '}' (more faces than the count?)").
// (Three different indices blend the textures across the face: scene
// 187.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0, 0> angle 50 }
light_source { <3, 8, -4> color rgb 1 }
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
      #if (J = N - 1)
        <A, A + 1, A + N + 2>, <A, A + N + 2, A + N + 1>,
      #elseif (J = 0)
        <A, A + 1, A + N + 2>, 2, 2, 2, <A, A + N + 2, A + N + 1>, mod(I, 2), mod(I, 2), mod(I, 2),
      #else
        <A, A + 1, A + N + 2>, mod(I + J, 2), <A, A + N + 2, A + N + 1>, mod(I + J, 2),
      #end
    #end #end }
  pigment { rgb <0.3, 0.9, 0.4> }
}
