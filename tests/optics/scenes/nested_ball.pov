// SPDX-License-Identifier: MIT
// nested_ball.pov (tests/optics/optics.sh, check "nested spheres"): a
// clear sphere (radius 1, index BALL) inside a clear block of index MED
// (MED = 1: no block, the sphere in air), parallel white light from
// straight above, a white floor y = -1.1 inside the block, lit only
// through it. What bends the light at the sphere is the relative index
// BALL/MED: a glass ball in water (1.5 in 1.333: a weak converging lens,
// focus 4.5 radii from its centre) and an air bubble in glass (1 in 1.5:
// a diverging lens that reflects everything beyond the critical impact
// parameter 2/3 totally). The block is 6 wide: light the sphere sends
// sideways comes back off its side faces (TIR and Fresnel) and lands on
// the floor too (the test's tolerance). Image: 120 x 120 pixels over
// x, z in [-0.6, 0.6] about the axis (0.01 a pixel).
#version 3.7;
#ifndef (BALL) #declare BALL = 1.5; #end
#ifndef (MED) #declare MED = 1.333; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.005 autostop 0 }
}
camera { orthographic location <0, -1.05, 0> direction <0, -1, 0>
  right <1.2, 0, 0> up <0, 0, 1.2> }
light_source { <0, 100, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
plane { y, -1.1 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
#if (MED != 1)
box { <-3, -2, -3>, <3, 2, 3>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior MED }
  photons { target refraction on reflection on collect off }
}
#end
sphere { 0, 1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior BALL }
  photons { target refraction on reflection on collect off }
}
