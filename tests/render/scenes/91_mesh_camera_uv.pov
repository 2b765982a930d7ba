// mesh_camera distribution 3 with smooth (POV-Ray 3.7's CreateCameraRay,
// MESH_CAMERA; iris's src/render/meshcam.c): the pixel's uv point
// u = (x - 0.5) / W, v = 1 - (y + 0.5) / H is found in the uv map of a
// mesh2 (a quad cut into four triangles about its centre); the ray starts
// at the matching point of the face and leaves along the vertex normals
// weighted by the point's barycentric coordinates. The normals point
// backwards and direction -z reverses them; location z -0.05 moves the
// origins 0.05 against them; rotate and translate move the mesh (origin
// as a point, direction as a normal).
// Before meshcam.c iris ignored the block and rendered the default
// perspective camera: PSNR 15.2 dB (measured with the block removed).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare K = 0.45;
// POV-Ray 3.7 reads a mesh_camera's mesh2 with Parse_Mesh, so a mesh2
// must come as an identifier inside mesh { }
#declare Lens = mesh2 {
    vertex_vectors { 5, <-2, -1.5, 0>, <2, -1.5, 0>, <2, 1.5, 0>,
                        <-2, 1.5, 0>, <0, 0, 0> }
    normal_vectors { 5, <2 * K, 1.5 * K, -1>, <-2 * K, 1.5 * K, -1>,
                        <-2 * K, -1.5 * K, -1>, <2 * K, -1.5 * K, -1>,
                        <0, 0, -1> }
    uv_vectors { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 0.5> }
    face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
}
camera {
    mesh_camera { 1 3
        mesh { Lens rotate y * 10 translate <0, 1.6, -6> }
        smooth
    }
    location <0, 0, -0.05>
    direction <0, 0, -1>
}
light_source { <-10, 20, -20> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>]
                                              [1 rgb <0.1, 0.2, 0.6>] } } }
plane { y, 0 pigment { checker rgb <0.8, 0.7, 0.5> rgb <0.3, 0.4, 0.3>
                       scale 2 } }
sphere { <-1.5, 1.2, 2>, 1.2 pigment { rgb <0.9, 0.3, 0.2> }
         finish { phong 0.5 } }
box { <0.5, 0, 1>, <2.5, 2, 3> rotate y * 30 pigment { rgb <0.2, 0.5, 0.9> } }
