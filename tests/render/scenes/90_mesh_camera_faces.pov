// mesh_camera distribution 0 (POV-Ray 3.7's CreateCameraRay, MESH_CAMERA;
// iris's src/render/meshcam.c): pixel (x, y) of the 80x60 image is face
// 80 y + x of a mesh built here, one small triangle per pixel whose normal
// fans out like a 60-degree perspective view. Two rays per pixel: ray 0
// from mesh M, ray 1 from the copy moved by a transform (mesh { M ... }),
// averaged. location z 0.2 moves every origin 0.2 along its normal. The
// scene is smooth across pixels so that antialiasing samples falling on a
// neighbour's face change little.
// Before meshcam.c iris ignored the block and rendered the default
// perspective camera: PSNR 10.7 dB (measured with the block removed).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare W = 80;
#declare H = 60;
#declare M = mesh {
    #declare J = 0;
    #while (J < H)
        #declare I = 0;
        #while (I < W)
            #declare X0 = (I + 0.5) / W - 0.5;
            #declare Y0 = 0.5 - (J + 0.5) / H;
            #declare D = vnormalize(<X0 * 1.33, Y0, 1.1>);
            #declare T1 = vnormalize(vcross(y, D));
            #declare T2 = vcross(D, T1);
            #declare C = <X0 * 0.4, 1.5 + Y0 * 0.3, -6>;
            // (P3 - P1) x (P2 - P1) = a^2 T1 x T2 = a^2 D: the normal is D
            triangle { C, C + 0.01 * T2, C + 0.01 * T1 }
            #declare I = I + 1;
        #end
        #declare J = J + 1;
    #end
}
camera {
    mesh_camera { 2 0 mesh { M } mesh { M translate <0.3, 0, 0> } }
    location <0, 0, 0.2>
}
light_source { <-10, 20, -20> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>]
                                              [1 rgb <0.1, 0.2, 0.6>] } } }
plane { y, 0 pigment { checker rgb <0.8, 0.7, 0.5> rgb <0.3, 0.4, 0.3>
                       scale 2 } }
sphere { <-1.5, 1.2, 2>, 1.2 pigment { rgb <0.9, 0.3, 0.2> }
         finish { phong 0.5 } }
box { <0.5, 0, 1>, <2.5, 2, 3> rotate y * 30 pigment { rgb <0.2, 0.5, 0.9> } }
