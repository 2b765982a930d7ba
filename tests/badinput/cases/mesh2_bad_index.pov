// expect: 2 7
#version 3.7;
camera { location <0,1,-3> look_at 0 } light_source { <0,5,-5>, rgb 1 }
mesh2 {
    vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
    face_indices { 2,
        <0, 1, 2>, <0, 1, 100>
    }
    pigment { rgb 1 }
}
