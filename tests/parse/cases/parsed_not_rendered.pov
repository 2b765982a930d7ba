// Features parsed but not rendered warn with a location (mesh_camera and
// density_file, once here, are rendered: meshcam.c, src/image/df3.c; a
// missing df3 is an error as in POV-Ray, tests/badinput/cases/df3_missing.pov);
// transform functions and vturbulence are evaluated.
#version 3.7;
camera {
  direction <0, 0, 1>
  location <0, 0, -1>
}
plane { y, 0 }
#declare F = function { transform { translate <1, 2, 3> } }
#declare V = F(1, 1, 1);
#debug concat("F(1,1,1) = ", vstr(3, V, ", ", 0, 3), "\n")
// pavement (POV-Ray 3.7's polyform paving) is not evaluated by iris
box { 0, 1 pigment { pavement number_of_sides 4 number_of_tiles 2 } }
