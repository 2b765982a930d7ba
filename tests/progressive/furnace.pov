// SPDX-License-Identifier: MIT
// furnace.pov: a point light of colour 1 at the centre of a closed
// diffuse sphere of albedo a = diffuse x pigment = 0.4, seen from inside
// (radiosity.sh). Direct light renders a = 0.4 everywhere; with
// interreflection every bounce is uniform and the total is a/(1 - a).
#version 3.7;
// recursion_limit 20 (POV-Ray's largest): the global map then carries
// every bounce that matters (a^21 < 1e-8), not only the default 2.
global_settings { assumed_gamma 1 radiosity { recursion_limit 20 } }
camera { location <0, 0, -0.5> look_at <0, 0, 1> angle 70 }
light_source { <0, 0, 0> color rgb 1 }
sphere { 0, 2 pigment { color rgb 0.4 } finish { ambient 0 diffuse 1 } }
