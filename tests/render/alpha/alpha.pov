// alpha.pov: the +UA scene of tests/render/alpha.sh. The default
// background (black, transmit 1) is transparent under +UA; an opaque
// sphere, a transmitting one (two surfaces: transmit 0.6 x 0.6 of the
// background shows, alpha 0.64), a filtering one and a phong highlight on
// the transmitting one (brighter than its alpha: POV-Ray raises the
// alpha there when it writes straight alpha; Declare=PHONG=0 removes it).
#version 3.7;
#ifndef (PHONG) #declare PHONG = 1; #end
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at <0, 0.5, 0> right x*4/3 angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
sphere { <-1, 0.5, 0>, 0.5 pigment { rgb <1, 0.4, 0.2> } }
sphere { <0.6, 0.5, 0>, 0.5 pigment { rgbt <0.3, 1, 0.3, 0.6> }
         finish { phong PHONG phong_size 20 } }
sphere { <1.6, 0.5, 0>, 0.3 pigment { rgbf <0.3, 0.3, 1, 0.6> } }
sphere { <-0.2, 1.4, 1>, 0.3 pigment { rgb 1 } }
