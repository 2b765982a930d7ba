// Parity scene: pattern normals strong enough to tip the perturbed normal
// away from the light and below the surface (agate, granite and brick,
// stronger than in textures/patterns/*.pov). POV-Ray keeps such a normal
// as it is (the spot turns dark, lit by ambient only); iris once reflected
// it back above the surface and lit those spots (30.5 dB here; 27-33 dB
// on those example scenes).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -9> look_at <0, 0.3, 0> right x*4/3 angle 32 }
light_source { <300, 200, -700> color rgb 1 }
plane { y, -1.01 pigment { checker rgb 1.1, rgb 0 } }
sphere { <-1.6, 0, 0>, 1 pigment { rgb 1 } finish { phong 0.8 phong_size 200 }
  normal { agate 3 scale 0.5 } }
box { <-0.75, -0.75, -0.75>, <0.75, 0.75, 0.75> rotate <-30, 30, 0>
  translate x*0.7 pigment { rgb <1, 0.9, 0.8> } normal { granite 3 scale 0.6 } }
cylinder { -z, z, 0.75 rotate <-30, 30, 0> translate <2.5, 0, 0>
  pigment { rgb <0.8, 0.9, 1> } normal { brick 4 scale 0.08 } }
