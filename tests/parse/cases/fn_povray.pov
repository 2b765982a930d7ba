// options: -q -w
// functions.inc internals, pattern functions, sum()/prod(), pigment
// functions and vturbulence at three points. fn_povray.expect is NOT
// iris output: it is POV-Ray 3.7.0.10's own #debug output of this file
// (povray +Ifn_povray.pov -D), so every value must agree with POV-Ray to
// the 12 decimals printed.
#version 3.7;
#include "functions.inc"
#declare P = array[3] { <0.3, 0.7, -0.4>, <1.37, -0.21, 2.9>, <-2.1, 0.45, 0.83> };
#macro Out(Name, V)
  #debug concat(Name, " ", str(V, 0, 12), "\n")
#end
#for (I, 0, 2)
  #declare X = P[I].x; #declare Y = P[I].y; #declare Z = P[I].z;
  Out(concat("noise3d ", str(I,0,0)), f_noise3d(X, Y, Z))
  Out(concat("snoise3d ", str(I,0,0)), f_snoise3d(X, Y, Z))
  Out(concat("noise_gen1 ", str(I,0,0)), f_noise_generator(X, Y, Z, 1))
  Out(concat("noise_gen3 ", str(I,0,0)), f_noise_generator(X, Y, Z, 3))
  Out(concat("ridged_mf ", str(I,0,0)), f_ridged_mf(X, Y, Z, 0.5, 2, 6, 1, 2, 2))
  Out(concat("ridge ", str(I,0,0)), f_ridge(X, Y, Z, 2, 5.5, 0.6, 0.1, 0.3, 2))
  Out(concat("hetero_mf ", str(I,0,0)), f_hetero_mf(X, Y, Z, 0.5, 2, 4.5, 0.3, 1, 2))
  Out(concat("heart ", str(I,0,0)), f_heart(X, Y, Z, 1))
  Out(concat("helix1 ", str(I,0,0)), f_helix1(X, Y, Z, 2, 3, 0.2, 1, 1.5, 0.5, 30))
  Out(concat("helix2 ", str(I,0,0)), f_helix2(X, Y, Z, 0, 3, 0.3, 0.5, 0, 2, 0))
  Out(concat("spiral ", str(I,0,0)), f_spiral(X, Y, Z, 0.5, 0.1, 3, 0, 0, 1.5))
  Out(concat("mesh1 ", str(I,0,0)), f_mesh1(X, Y, Z, 0.5, 0.7, 1, 0.1, 2))
  Out(concat("blob ", str(I,0,0)), f_blob(X, Y, Z, 1, 2, 0.8, 1.5, 0.6))
  Out(concat("blob2 ", str(I,0,0)), f_blob2(X, Y, Z, 1, 2, 0.8, 0.5))
  Out(concat("torus_gumdrop ", str(I,0,0)), f_torus_gumdrop(X, Y, Z, 0.2))
  Out(concat("rounded_box ", str(I,0,0)), f_rounded_box(X, Y, Z, 0.1, 1, 0.5, 0.7))
  Out(concat("algbr_cyl1 ", str(I,0,0)), f_algbr_cyl1(X, Y, Z, 1, 5, 1, 0.5, 20))
  Out(concat("comma ", str(I,0,0)), f_comma(X, Y, Z, 1.5))
  Out(concat("enneper ", str(I,0,0)), f_enneper(X, Y, Z, 0.5))
  Out(concat("helical_torus ", str(I,0,0)), f_helical_torus(X, Y, Z, 2, 3, 1, 0.3, 0.2, 0.3, 1, 2, 0.5, 1))
  Out(concat("hex_y ", str(I,0,0)), f_hex_y(X, Y, Z, 0))
  Out(concat("quantum ", str(I,0,0)), f_quantum(X, Y, Z, 0))
  Out(concat("polytubes ", str(I,0,0)), f_polytubes(X, Y, Z, 5, 0.5, 0.1, 0, 0, 0))
  Out(concat("piriform ", str(I,0,0)), f_piriform(X, Y, Z, 0.5))
  Out(concat("kampyle2d ", str(I,0,0)), f_kampyle_of_eudoxus_2d(X, Y, Z, 1, 0.5, 2, 1, 0.3, 10))
  Out(concat("agate ", str(I,0,0)), f_agate(X, Y, Z))
  Out(concat("granite ", str(I,0,0)), f_granite(X, Y, Z))
  Out(concat("wood ", str(I,0,0)), f_wood(X, Y, Z))
  Out(concat("bozo ", str(I,0,0)), f_bozo(X, Y, Z))
  Out(concat("dents ", str(I,0,0)), f_dents(X, Y, Z))
  Out(concat("wrinkles ", str(I,0,0)), f_wrinkles(X, Y, Z))
  Out(concat("ripples ", str(I,0,0)), f_ripples(X, Y, Z))
  Out(concat("crackle ", str(I,0,0)), f_crackle(X, Y, Z))
  Out(concat("spiral1 ", str(I,0,0)), f_spiral1(X, Y, Z))
#end
#declare S = function { sum(i, 1, 4, i * x) + prod(k, 1, 3, k + y) }
Out("sumprod", S(0.5, 2, 0))
#declare PG = function { pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } }
Out("pig_red", PG(0.25, 0, 0).red)
Out("pig_blue", PG(0.25, 0, 0).blue)
Out("pig_gray", PG(0.25, 0, 0).gray)
#declare PF = function { PG(x, y, z).blue * 2 }
Out("pig_in_fn", PF(0.75, 0, 0))
#declare V = vturbulence(2, 0.5, 6, <0.3, 0.7, -0.4>);
Out("vturb_x", V.x) Out("vturb_y", V.y) Out("vturb_z", V.z)
