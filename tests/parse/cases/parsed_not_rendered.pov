// Features parsed (so that the scene parses) but not rendered, each with a
// located warning (mesh_camera, once here, is rendered: meshcam.c),
// density_file reads as 0 (its interpolate is accepted), transform
// functions and vturbulence are evaluated.
#version 3.7;
camera {
  direction <0, 0, 1>
  location <0, 0, -1>
}
plane { y, 0 pigment { density_file df3 "missing.df3" interpolate 1 } }
#declare F = function { transform { translate <1, 2, 3> } }
#declare V = F(1, 1, 1);
#debug concat("F(1,1,1) = ", vstr(3, V, ", ", 0, 3), "\n")
