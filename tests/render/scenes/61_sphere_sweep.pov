// sphere_sweep: linear_spline with varying radii, b_spline and
// cubic_spline (Catmull-Rom), and CSG against the sweep's inside.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 0.5, 0> right x*4/3 angle 45 }
light_source { <-5, 8, -10> color rgb 1 }
light_source { <6, 4, -4> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
sphere_sweep { linear_spline 4, <-3.5, -0.5, 0>, 0.3 <-2.5, 1.2, 0>, 0.5
               <-1.5, 0, 0>, 0.2 <-0.5, 1, 0>, 0.35
  pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 } }
sphere_sweep { b_spline 6, <0, -0.5, 0>, 0.3 <0.5, 1.5, 0>, 0.4
               <1.5, -0.5, -0.5>, 0.3 <2.5, 1.5, 0>, 0.5 <3, 0, 0>, 0.2
               <3.5, 1, 0>, 0.3
  pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.6 } }
intersection {
  sphere_sweep { cubic_spline 6, <-3, 0, 2>, 0.3 <-2, -0.5, 1.5>, 0.25
                 <-1, 1.5, 1.5>, 0.4 <1, 0.5, 2>, 0.3 <2, 2, 2>, 0.2
                 <3, 0, 2>, 0.3 tolerance 1e-4 }
  box { <-4, -1, 1.9>, <4, 3, 3> }
  pigment { rgb <0.4, 0.5, 1> } finish { phong 0.6 }
}
