// POV-Ray's CheckPassThru: target + pass_through + refraction (not off)
// cannot all hold; the keyword given last decides what is turned off.
// A light_group lights only its own objects (global_lights: the scene's too).
// Spirals default to triangle_wave (wave 2 in the dump) unless a wave is given.
#version 3.7;
sphere { 0, 1 photons { target refraction on pass_through } }
sphere { 0, 1 photons { pass_through refraction on target } }
sphere { 0, 1 photons { pass_through target } }
sphere { 0, 1 photons { target pass_through refraction off } }
light_group { light_source { <0, 5, 0>, rgb 1 } sphere { 0, 1 } }
light_group { light_source { <0, 5, 0>, rgb 1 } sphere { 0, 1 } global_lights }
plane { y, 0 pigment { spiral1 3 } }
plane { y, 0 pigment { spiral2 3 ramp_wave } }
