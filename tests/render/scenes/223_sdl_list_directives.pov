// SDL forms POV-Ray 3.7 accepts that iris refused (session 10's users'
// scenes; each was a located parse error, so the scene did not render):
// - a directive before an optional comma between the points of a prism
//   or polygon runs first, as POV-Ray's Parse_Comma reads on: 'Pts[I]
//   #if (I < N) , #end' built from an array in a #for loop;
// - the loop also fills a mesh and a color_map and a pigment_map, the
//   ways users write them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, -1 pigment { rgb 0.7 } }
#declare N = 7;
#declare Pts = array[N + 1];
#for (I, 0, N)
  #declare Pts[I] = <cos(2 * pi * I / N), sin(2 * pi * I / N)> * (mod(I, 2) ? 0.5 : 1);
#end
prism { linear_sweep linear_spline 0, 0.5, N + 1,
  #for (I, 0, N) Pts[I] #if (I < N) , #end #end
  pigment { rgb <1, 0.5, 0> } translate <-3, 0, 0> }
polygon { N + 1 #for (I, 0, N) Pts[I] #end pigment { rgb <0, 0.5, 1> } rotate x * 90 translate <0, 0, 0> }
mesh {
  #for (I, 0, 9)
    #for (J, 0, 9)
      #local P00 = <I / 10, sin(I / 3) * cos(J / 3) * 0.3, J / 10>;
      #local P10 = <(I + 1) / 10, sin((I + 1) / 3) * cos(J / 3) * 0.3, J / 10>;
      #local P01 = <I / 10, sin(I / 3) * cos((J + 1) / 3) * 0.3, (J + 1) / 10>;
      #local P11 = <(I + 1) / 10, sin((I + 1) / 3) * cos((J + 1) / 3) * 0.3, (J + 1) / 10>;
      triangle { P00, P10, P11 }
      triangle { P00 P11 P01 }
    #end
  #end
  pigment { rgb <0.3, 1, 0.3> } scale 2 translate <1.5, -0.5, -1>
}
sphere { <-1, 1.5, 2>, 1
  pigment { gradient y
    color_map { #for (I, 0, 4) [I / 4 color rgb <I / 4, 1 - I / 4, #if (mod(I, 2)) 1 #else 0 #end>] #end }
    scale 2 translate -y }
}
sphere_sweep { linear_spline 4 <-2,0,2> 0.2 <-1,1,2> 0.3 <0,0,2> 0.2 <1,1,2> 0.3 pigment { rgb 1 } translate <2, 0, 0> }
#declare Pm = pigment { pigment_map { #for (I, 0, 2) [I / 2 checker rgb I / 2 rgb 1 - I / 2 scale 0.1] #end } }
box { <-4, -1, 3>, <4, 0, 4> pigment { gradient x pigment_map { [0 Pm] [1 rgb <1,0,0>] } scale 8 translate -4 * x } }
