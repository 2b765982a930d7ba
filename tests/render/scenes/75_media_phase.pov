// The scattering types side by side: Mie hazy (2), Mie murky (3),
// Rayleigh (4) and Henyey-Greenstein (5) with eccentricity 0.6, in four
// slabs lit from behind by a light slightly off the line of sight, so
// the forward-scattering phase functions glow brightest; extinction 0.5
// for the Rayleigh slab. Deterministic method 3: default 35 dB bar.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <2, 4, 20> color rgb 1 }
plane { y, 0 pigment { rgb 0.3 } }
#macro Slab(T, X)
box { <-0.8, 0.2, -0.5>, <0.8, 2.2, 0.5>
  pigment { rgbt 1 }
  hollow
  interior { media {
    #if (T = 5)
      scattering { T, rgb <0.03, 0.05, 0.07> eccentricity 0.6 }
    #elseif (T = 4)
      scattering { T, rgb <0.03, 0.05, 0.07> extinction 0.5 }
    #else
      scattering { T, rgb <0.03, 0.05, 0.07> }
    #end
  } }
  translate x*X
}
#end
Slab(2, -2.7)
Slab(3, -0.9)
Slab(4, 0.9)
Slab(5, 2.7)
