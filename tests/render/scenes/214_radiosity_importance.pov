// SPDX-License-Identifier: MIT
// 214_radiosity_importance.pov: radiosity importance (an object's
// radiosity { importance F }, a CSG's promoted to its children unless
// they give their own, and #default { radiosity { importance F } }). A
// gather ray that hits an object of importance I shades it only if its
// rank in the sample is below I, and then counts count / (I (count - 1)
// + 1) times: fewer rays shaded, the same light in the mean (POV-Ray's
// GatherLight; src/render/gather.c). The floor and the spheres see the
// sky (the default, 0.5) and a glowing box (0.3).
// parity-min-psnr: 32 importance trades noise for rays: POV-Ray's own
// images with +WT1 and +WT2 differ by 35.7 dB, iris's is 33.2-33.5 dB
// from either (iris ignoring importance is 36.0 dB from them: less noise,
// the same mean, so this scene cannot fail without importance; it fails
// when the ranks are biased: ranked in the spiral's golden-angle order the
// first half of the rays lay in one half-plane, 27.7 dB from the image
// without importance in a scene with the default 0.5 alone, now 39.2 dB).
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { count 100 error_bound 0.3 recursion_limit 1 } }
#default { radiosity { importance 0.5 } }
camera { location <0, 2.2, -4> look_at <0, 0.3, 0> angle 45 }
sky_sphere { pigment { rgb <0.2, 0.25, 0.35> } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 } }
box { <-3, 0, 1.5>, <3, 0.6, 1.8> pigment { rgb 1 }
  finish { emission 2 diffuse 0 } radiosity { importance 0.3 } }
union {
  sphere { <-0.8, 0.5, 0>, 0.5 }
  sphere { <0.8, 0.5, 0>, 0.5 radiosity { importance 1 } }
  pigment { rgb <0.9, 0.6, 0.4> } finish { ambient 0 diffuse 0.8 }
  radiosity { importance 0.4 }
}
