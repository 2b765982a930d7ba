// minimal.pov: camera, light, sphere, plane. The plane z = 5 faces the
// camera and the light sits on the camera axis, so at the image centre
// (an odd-sized image has a pixel there) the plane is lit along its
// normal: colour = pigment * (ambient + diffuse) = 0.5 * (0.1 + 0.6) =
// 0.35, which POV-Ray writes to PNG as 160 (povray-3.7-semantics.md §3.9).
// The sphere sits off-centre.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> }
light_source { <0, 0, -5>, rgb 1 }
plane { -z, -5 pigment { rgb 0.5 } }
sphere { <1.2, 0.6, 0>, 0.5 pigment { rgb <1, 0, 0> } }
