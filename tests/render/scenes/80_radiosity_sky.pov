// SPDX-License-Identifier: MIT
// 80_radiosity_sky.pov: an outdoor scene lit by a graded sky and a sun
// through radiosity{} (iris: the final gather of src/render/gather.c;
// POV-Ray: its radiosity). The sky light on the ground and in the
// shadow side of the block reaches iris only through the gather.
// parity-min-psnr: 38 both renderers estimate the gather with 35 rays
// per cached sample from their own direction sets and cache placement
// (iris: a fixed golden-angle spiral and a pretrace grid; POV-Ray: its
// direction pool and octree), so the sky-lit faces differ by a few
// percent of noise and bias; measured 42.2-42.6 dB over 3 runs (POV-Ray's
// threaded radiosity varies from run to run). The sky's light bounced off
// the ground reaches the block through the gather rays' own gathers
// (recursion_limit 2); with the global photon map alone there (it holds
// only the sun's light) 31.5 dB, without a gather 11.1 dB
#version 3.7;
global_settings { assumed_gamma 1 radiosity { } }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1.0>] [1 rgb <0.2, 0.3, 0.8>] } }
}
camera { location <3, 4, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-20, 30, -10> color rgb 1.2 }
plane { y, 0 pigment { rgb <0.7, 0.6, 0.5> } finish { ambient 0 diffuse 0.8 } }
box { <-1, 0, -1>, <1, 2, 1> rotate 30 * y
  pigment { rgb 0.8 } finish { ambient 0 diffuse 0.7 } }
sphere { <2, 0.6, -1>, 0.6 pigment { rgb <0.9, 0.2, 0.1> }
  finish { ambient 0 diffuse 0.8 } }
