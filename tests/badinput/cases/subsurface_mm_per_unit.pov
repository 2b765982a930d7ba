// expect: 0 -
// mm_per_unit 1e300: the sample areas overflow to inf and the dipole's
// exponentials to 0 (inf x 0: NaN); iris drops the BSSRDF's sum where it
// is not finite and renders.
#version 3.7;
global_settings { mm_per_unit 1e300 subsurface { samples 20, 5 } }
camera { location <0, 1, -3> look_at <0, 0.5, 0> }
light_source { <2, 5, -5>, rgb 1 }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.8, 0.5, 0.2> }
         finish { subsurface { translucency 1 } } interior { ior 1.3 } }
