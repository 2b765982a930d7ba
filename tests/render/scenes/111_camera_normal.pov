// camera_normal: a camera normal{} bends every primary ray as a surface
// normal is bent, by the pattern at the image-plane point <x0, y0, 0>
// (x0, y0 in [-0.5, 0.5] across the image) with the normal's own scale,
// then renormalised (POV-Ray's CreateCameraRay). The checker floor and
// the spheres' edges show the wobble; without it iris renders the scene
// unbent. Measured against POV-Ray 3.7.0: 71.3 dB at 80x60 (53.0 dB at
// 320x240, a few isolated pixels); POV-Ray's own image without the
// normal is 15.6 dB from it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  location <0, 3, -7> look_at <0, 1, 0> right x*4/3 angle 45
  normal { bumps 0.05 scale 0.08 }
}
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { checker rgb 1 rgb <0.1, 0.2, 0.1> scale 0.5 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <1.3, 0.8, -0.5>, 0.8 pigment { gradient y color_map { [0 rgb <0, 0, 1>] [1 rgb <1, 1, 0>] } scale 1.6 } }
