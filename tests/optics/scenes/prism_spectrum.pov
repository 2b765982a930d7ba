// SPDX-License-Identifier: MIT
// prism_spectrum.pov (tests/optics/optics.sh, check "prism"): an
// equilateral SCHOTT F2 prism (apex up, axis along z) spreads a narrow
// beam (a cylinder light of radius 0.005, rising at 24 degrees: about
// the minimum deviation) into a spectrum on the wall x = 4. The light is
// the CIE F11 lamp: its emission lines land as three bright spots, where
// the test's Snell's-law trace puts them.
#version 3.7;
#ifndef (LAW) #declare LAW = 0; #end
// GLASS (check "glass catalogue"): 0 F2, 1 fused_silica, 2 N-BAF10 from
// iris's glass "NAME" catalogue, 3 SCHOTT N-SF5's coefficients given
// inline ('sellmeier <B1, B2, B3>, <C1, C2, C3>', C in um^2, copied from
// data/glass_sellmeier.csv); CY, SPAN the wall's window (the test
// centres it on its own prediction: the glasses deviate the beam
// differently)
#ifndef (GLASS) #declare GLASS = 0; #end
// DISP: the 'dispersion' of LAW 1 (POV-Ray's ior/dispersion)
#ifndef (DISP) #declare DISP = 1.03; #end
#ifndef (CY) #declare CY = -0.58; #end
#ifndef (SPAN) #declare SPAN = 0.36; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.00002 autostop 0 }
}
// looking at the wall, y in [CY - SPAN/2, CY + SPAN/2] (by default
// [-0.76, -0.40]), z in [-0.01, 0.01]: image rows run along y (top row
// +y), SPAN/240 (0.0015) a row at +H240
camera { orthographic location <3.5, CY, 0> direction <1, 0, 0>
  right <0, 0, 0.02> up <0, SPAN, 0> }
light_source { <-4.154, -0.562, 0> color rgb 1
  cylinder point_at <-0.5, 1.066, 0> radius 0.005 falloff 0.005 tightness 0
  photons { refraction on reflection off }
  #ifdef (iris_version) spectrum "F11" #end
}
box { <4, -3, -1>, <4.1, 3, 1>
  pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
prism { linear_sweep linear_spline -1.5, 1.5, 4,
  <-1, 0>, <1, 0>, <0, 1.732>, <-1, 0>
  rotate -90 * x
  translate <0, 0.2, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  // LAW (Declare=LAW=k, check "dispersion laws"): 0 SCHOTT F2's
  // Sellmeier curve, 1 POV-Ray's ior/dispersion, 2 Cauchy, 3 Abbe,
  // 4 the exponential ior_decay
  interior { ior 1.62
    #ifdef (iris_version)
      #switch (LAW)
        #case (0)
          #switch (GLASS)
            #case (0) glass "F2" #break
            #case (1) glass "fused_silica" #break
            #case (2) glass "N-BAF10" #break
            #case (3) sellmeier <1.52481889, 0.187085527, 1.42729015>,
              <0.011254756, 0.0588995392, 129.141675> #break
          #end
        #break
        #case (1) dispersion DISP #break
        #case (2) cauchy 1.60, 0.008 #break
        #case (3) abbe 1.62, 30 #break
        #case (4) ior_decay 1.66, 1.61, 100 #break
      #end
    #end
  }
  photons { target refraction on reflection off collect off }
}
