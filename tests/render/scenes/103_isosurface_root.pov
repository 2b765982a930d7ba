// Parity scene: isosurface roots and normals as POV-Ray finds them
// (isosurface.cpp): the container interval is halved until shorter than
// 'accuracy' in ray units and the first piece whose far end is inside
// gives that end as the hit, up to 'accuracy' inside the surface; the
// normal is a forward difference of step 'accuracy'. A fine granite
// normal (scale 0.02) on a noise terrain, and noisy rocks scaled down
// (accuracy is in world units, so coarse for them), show every
// difference in the hit point; the rocks' shadows on the terrain are rays
// leaving an isosurface. iris once refined roots to double precision
// with central differences (advanced/isocacti.pov at 15.2 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location <2.5, 5, -5> look_at <0, 0, 0> right x*4/3 angle 45 }
light_source { <-60, 90, -90> color rgb 1.3 }
background { rgb <0.3, 0.4, 0.7> }
isosurface {
  function { y - f_snoise3d(x / 3, 0, z / 1.5) * 0.5 }
  max_gradient 1.1
  contained_by { box { <-20, -3, -20>, <20, 1, 20> } }
  texture { pigment { rgb <1, 0.9, 0.65> } normal { granite 0.2 scale 0.02 }
            finish { specular 0.3 } } }
#declare Rock = isosurface {
  function { f_r(x, y, z) - 1 + f_noise3d(x * 2, y * 2, z * 2) * 0.5 }
  contained_by { sphere { 0, 1 } }
  texture { pigment { rgb <0.5, 0.45, 0.4> } normal { granite 0.5 scale 0.05 } } }
object { Rock scale 0.6 translate <-1, 0.3, 0> }
object { Rock scale 0.35 rotate 40 * y translate <0.6, 0.3, -0.8> }
object { Rock scale 0.12 translate <1.2, 0.2, 0.6> }
