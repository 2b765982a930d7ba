// projected_through: a light that shines only through an object it names
// (POV-Ray's TracePointLightShadowRay): a torus and a sphere, not part of
// the scene themselves, cast a lit torus-shaped and disc-shaped patch on
// the wall and floor; between the patches only the shadowless fill light
// reaches. The red sphere (out of view) lies between the torus and the
// light, so it casts no shadow into the ring patch: shadows are tested
// only up to the projecting object. Measured: identical PNGs; without the
// projection (the light everywhere) 8.5 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2, 3, -10> look_at <-1, 1.5, 0> right x*4/3 angle 45 }
plane { y, 0 pigment { rgb 0.9 } }
plane { z, 0 pigment { rgb <0.3, 0.45, 0.7> } hollow on }
#declare Window = union {
  torus { 1.2, 0.3 rotate x*90 translate <-1, 2.5, -4> }
  sphere { <1.5, 1, -4>, 0.6 }
}
sphere { <-0.5, 3.85, -7>, 0.25 pigment { rgb <1, 0.3, 0.2> } }
light_source { <0, 4, -10> rgb 2 projected_through { Window } }
light_source { <0, 3, -9> rgb 0.3 shadowless }
