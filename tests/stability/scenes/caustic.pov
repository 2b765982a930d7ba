// SPDX-License-Identifier: MIT
// caustic.pov: photon flux conservation. A parallel light of colour 1
// shines straight down on a white diffuse floor (diffuse 1, ambient 0);
// an orthographic camera looks straight down, so every pixel covers the
// same floor area and the image mean is the floor's mean irradiance. The
// glass ball (no_image, so the camera sees only the floor) only moves
// light around: it casts a black shadow and a caustic, and with Fresnel
// or without, the flux reaching the floor in view cannot exceed the flux
// of the beam over that area. So mean luminance <= 1 (up to the photon
// estimate's noise), while single pixels in the focus may be far above 1.
// A Monte Carlo trace of the ball (exact Fresnel, TIR, 40 bounces, 20000
// rays) lands 87.6% of the flux it intercepts inside the view, and the
// ball intercepts pi 0.8^2 / 12 = 16.8% of the beam: the mean is 0.979.
#version 3.7;
#ifndef (DISP) #declare DISP = 1; #end
#ifndef (IOR) #declare IOR = 1.5; #end
#ifndef (SPACING) #declare SPACING = 0.02; #end
global_settings {
    assumed_gamma 1
    max_trace_level 12
    photons { spacing SPACING }
}
camera {
    orthographic
    location <0, 10, 0>
    look_at <0, 0, 0>
    sky z
    right x * 4 up z * 3
}
light_source {
    <0, 50, 0>, rgb 1
    parallel point_at <0, 0, 0>
    photons { refraction on reflection on }
}
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
sphere {
    <0, 1, 0>, 0.8
    pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
    interior { ior IOR dispersion DISP dispersion_samples 12 }
    no_image
    photons { target refraction on reflection on }
}
