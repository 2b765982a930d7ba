// expect: 0|2 3
#version 3.7;
global_settings { photons { count 1e12 } }
camera { location <0,1,-3> look_at 0 } light_source { <0,5,-5>, rgb 1 }
light_source { <0, 5, -5>, rgb 1 photons { refraction on reflection on } }
sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 }
         photons { target refraction on reflection on } }
plane { y, -1 pigment { rgb 1 } }
