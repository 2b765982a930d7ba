// SPDX-License-Identifier: MIT
// demo.pov: the iris demo. A dispersive glass ball on a white floor under a
// small bright light: the ball throws a caustic whose edge splits into
// colours. The same file renders in POV-Ray 3.7 (+Q9 for photons).
#version 3.7;

// iris's photons each carry one wavelength and take one path, where
// POV-Ray splits a photon into dispersion_samples colours at the glass:
// iris asks for 4x the photons (646 k stored; +1 s at 640x480 on 2
// cores) to keep the colour noise of its caustic low.
#ifdef (iris_version)
    #declare Spacing = 0.002;
#else
    #declare Spacing = 0.004;
#end

global_settings {
    assumed_gamma 1.0
    max_trace_level 10
    photons { spacing Spacing autostop 0 jitter 0.4 }
}

camera {
    location <0, 3.2, -5.5>
    look_at <0, 0.55, 0.4>
    angle 40
    right x * image_width / image_height
}

light_source {
    <-3, 7, 3>, rgb 1.4
    photons { refraction on reflection on }
}

light_source { <4, 5, -6>, rgb 0.25 shadowless }

plane {
    y, 0
    pigment { checker rgb 0.95, rgb 0.75 scale 0.5 }
    finish { ambient 0 diffuse 0.9 }
}

sphere {
    <0.1, 1, 0>, 1
    pigment { rgbf <1, 1, 1, 1> }
    finish { ambient 0 diffuse 0 specular 0.6 roughness 0.002
             reflection { 0.02, 1 fresnel on } conserve_energy }
    interior {
        ior 1.52
        dispersion 1.06
        dispersion_samples 24
        #ifdef (iris_version)
            glass "N-SF11"
        #end
    }
    photons { target refraction on reflection on collect off }
}

box {
    <-2.6, 0, 1.4>, <-1.6, 0.8, 2.4>
    rotate y * 25
    pigment { rgb <0.8, 0.3, 0.2> }
    finish { ambient 0 diffuse 0.8 phong 0.3 }
}
