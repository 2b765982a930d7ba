// SPDX-License-Identifier: MIT
// An image map parsed before the scene's #version 3.7 (Quving's
// space-waltz scenes: the sky_sphere's in an include file read before
// the one that sets #version): POV-Ray 3.7 sets its gamma mode anew at
// each #version and reads the image in the mode of the moment, 3.6's
// here, which takes the texels as stored; iris chose by the last
// #version (scene20: 13 dB before session 12). The second image, after
// #version 3.7, is decoded.
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3> look_at 0 angle 40 }
plane { z, 0 pigment { image_map { png "maps/hf_rg.png" interpolate 2 }
                       translate -0.5 * (x + y) scale <2, 1, 1> }
        finish { ambient 1 diffuse 0 } translate 0.5 * y
        clipped_by { plane { -y, 0 } } }
#version 3.7;
plane { z, 0 pigment { image_map { png "maps/hf_rg.png" interpolate 2 }
                       translate -0.5 * (x + y) scale <2, 1, 1> }
        finish { ambient 1 diffuse 0 } clipped_by { plane { y, 0 } } }
