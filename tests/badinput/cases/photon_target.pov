// expect: 0|2 8
#version 3.7;
// A sane global spacing, one object's 'target 1e-7' asking for 1e19
// photons: the diagnostic points at that target (it pointed at the
// global spacing on line 6, which is not what needs changing).
camera { location <0,1,-3> look_at 0 } light_source { <0,5,-5>, rgb 1 }
global_settings { photons { spacing 0.01 } }
sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 } photons { target 1e-7
         refraction on reflection on } }
light_source { <0, 5, -5>, rgb 1 photons { refraction on reflection on } }
plane { y, -1 pigment { rgb 1 } }
