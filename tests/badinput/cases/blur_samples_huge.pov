// expect: 2 7
// blur_samples 1e9: the focal blur tables alone would take 24 GB (found
// by hand, session 7: it allocated until the machine ran out). A located
// error at the keyword, before any allocation.
#version 3.7;
camera { location <0, 1, -3> look_at <0, 1, 0> aperture 0.5
         blur_samples 1e9 }
sphere { <0, 1, 0>, 0.5 pigment { rgb 1 } }
light_source { <0, 5, -5>, rgb 1 }
