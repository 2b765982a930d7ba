// Commas that POV-Ray 3.7 makes optional (its Parse_Comma) where iris
// demanded one, seen in users' scenes: each form must parse to the same
// values as the comma form (the dump shows them: diffuse_back 0.3, gather
// 20 100, expand 0.2 40, the disc's hole 0.2). A two-float 'diffuse 0.6
// 0.3' is the diffuse and back-side amounts, 'disc { C N 0.5 0.2 }' has a
// hole, 'samples 5 10' are a media's minimum and maximum (POV-Ray:
// Parse_Comma, then an optional float). Built-in functions take their
// arguments without commas too (all but min/max): the #debug line must
// read 0,0,-1 8 2 1 -1, as POV-Ray 3.7 prints it (vrotate, pow, select,
// strcmp, vdot). The media line, radiosity's two pairs, photons' radius
// pair and the camera's blur_samples 4 16 (its maximum 16 shown) only have
// to parse as POV-Ray does (iris stopped at each), and so does 'slope { y
// 0.2 0.8 }'. The fractals' 'exterior 1 0.5' takes its factor (it was
// left behind): the second #debug line is POV-Ray's own output,
// 0.070711 0.070711 0.952594 0.525000.
#version 3.7;
global_settings {
  photons { count 1000 gather 20 100 expand_thresholds 0.2 40 radius 0.1 2 }
  radiosity { count 35 400 nearest_count 10 5 } }
camera { location <0, 0, -3> look_at 0 aperture 0.5 blur_samples 4 16 focal_point 0 }
sphere { 0, 1
  pigment { checker warp { planar z 0.5 } warp { black_hole <1, 0, 0> 0.5 } }
  finish { diffuse 0.6 0.3 } }
sphere { 0, 1 finish { diffuse 0.6 } }
disc { <0, 0, 0> <0, 1, 0> 0.5 0.2 }
disc { <0, 0, 0>, <0, 1, 0>, 0.5 pigment { rgb 1 } }
sphere { 0, 1 hollow pigment { rgbt 1 }
  interior { media { absorption 1 samples 5 10 intervals 2 } } }
#declare V = vrotate(<1, 0, 0> <0, 90, 0>);
#debug concat(vstr(3, V ",", 0, 0), " ", str(pow(2 3), 0, 0), " ",
  str(select(-1 2 3, 4), 0, 0), " ", str(strcmp("b" "a"), 0, 0), " ",
  str(vdot(<1, 0, 0> <-1, 0, 0>), 0, 0), "\n")
box { 0, 1 pigment { slope { y 0.2 0.8 } } }
#declare J1 = function { pattern { julia <0.3, 0.2> 30 exterior 1 0.5 interior 1 0.5 } }
#declare J2 = function { pattern { julia <0.3, 0.2> 30 exterior 1, 0.5 interior 1, 0.5 } }
#declare M1 = function { pattern { mandel 20 exterior 2 0.3 } }
#debug concat(str(J1(0.1, 0.1, 0), 0, 6), " ", str(J2(0.1, 0.1, 0), 0, 6), " ",
  str(M1(0.3, 0.6, 0), 0, 6), " ", str(M1(-2, 0.5, 0), 0, 6), "\n")
