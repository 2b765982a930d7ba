// options: -q -w
// Every macro of transforms.inc, math.inc, rand.inc, strings.inc,
// colors.inc and arrays.inc called once or more, its result printed with
// #debug. povray_inc1.expect is NOT iris output: it is POV-Ray 3.7.0.10's
// own #debug output of this file (povray +Ipovray_inc1.pov -D +GDfile,
// run in this directory), so every line must agree with POV-Ray to the
// 6 decimals printed. Fixed by it: a macro whose body ends with
// '#declare G = A' (A an array) followed by a macro call in the caller
// ran that call before G existed (math.inc's Histogram, then
// 'QF(.., HistogramArray[0][0])': "uninitialized identifier").
// math.inc's Histogram reads N, which only GetStats declares (locally):
// POV-Ray stops there too unless the scene declares N.
#version 3.7;
#include "inc/print.inc"
#include "math.inc"
#include "transforms.inc"
QT("shear", Shear_Trans(<1,0.5,0>, <0,1,0.2>, <0.1,0,1>))
QT("matrix", Matrix_Trans(<1,0.5,0>, <0,1,0.2>, <0.1,0,1>, <1,2,3>))
QT("axscale", Axial_Scale_Trans(<1,1,0>, 2))
QT("axrot", Axis_Rotate_Trans(<1,2,3>, 30))
QT("axrot2", Axis_Rotate_Trans(y, -45))
QT("rotaround", Rotate_Around_Trans(<10,20,30>, <1,2,3>))
QT("reorient", Reorient_Trans(x, <1,1,0>))
QT("reorient2", Reorient_Trans(<1,2,3>, <-3,1,0.5>))
QT("reorient_same", Reorient_Trans(y, y))
QT("reorient_opp", Reorient_Trans(y, -y))
QT("pointat", Point_At_Trans(<1,1,1>))
QT("pointat2", Point_At_Trans(<0,-1,0.5>))
#declare O = box { <-1,0,2>, <3,4,5> }
QT("center", Center_Trans(O, x+y+z))
QT("center_x", Center_Trans(O, x))
QT("align", Align_Trans(O, x-y, <10,10,10>))
QT("align2", Align_Trans(O, -z, <0,1,2>))
#declare Sp = spline { natural_spline 0, <0,0,0>, 1, <1,1,0>, 2, <2,0,1>, 3, <3,2,2> }
QT("spline", Spline_Trans(Sp, 1.3, y, 0.1, 0))
QT("spline_bank", Spline_Trans(Sp, 1.5, y, 0.1, 0.5))
QP("vtransform", vtransform(<1,2,3>, transform { rotate <10,20,30> translate 1 }))
QP("vinv", vinv_transform(<1,2,3>, transform { rotate <10,20,30> translate 1 }))
#declare A = array[6] {3, 1, 4, 1, 5, 9}
QF("mean", Mean(A))
QF("stddev", Std_Dev(A, Mean(A)))
GetStats(A)
QF("stats4", StatisticsArray[4])
#declare N = 6; // math.inc bug: Histogram uses N of GetStats
Histogram(A, 3)
QF("hist00", HistogramArray[0][0]) QF("hist01", HistogramArray[0][1])
QF("hist21", HistogramArray[2][1])
QF("interp0", Interpolate(0.3, 0, 1, 10, 20, 0))
QF("interp2", Interpolate(0.3, 0, 1, 10, 20, 2))
QP("interpv", Interpolate(0.5, 0, 2, <1,2,3>, <3,4,5>, 1))
QP("vsqr", VSqr(<1,-2,3>))
QP("vpow", VPow(<1,2,3>, 1.5))
QP5("vpow5d", VPow5D(<1,2,3,4,5>, 2))
QF("veq", VEq(<1,2,3>, <1,2,3>)) QF("veq2", VEq(<1,2,3>, <1,2,4>))
QF("veq5d", VEq5D(<1,2,3,4,5>, <1,2,3,4,5>)) QF("veq5d2", VEq5D(<1,2,3,4,5>, <1,2,3,4,6>))
QF("vzero", VZero(<0,0,0>)) QF("vzero5d", VZero5D(<0,0,0,0,1>))
QF("vlen5d", VLength5D(<1,2,3,4,5>))
QP5("vnorm5d", VNormalize5D(<1,2,3,4,5>))
QF("vdot5d", VDot5D(<1,2,3,4,5>, <5,4,3,2,1>))
QF("vcos", VCos_Angle(<1,0,0>, <1,1,0>))
QF("vangle", VAngle(<1,0,0>, <1,1,0>))
QF("vangled", VAngleD(<1,0,0>, <1,1,0>))
QF("vrot", VRotation(<1,0,0>, <0,1,0>, -z))
QF("vrotd", VRotationD(<1,0,0>, <0,1,0>, z))
QF("vdist", VDist(<1,2,3>, <4,6,3>))
QP("vperp", VPerp_To_Vector(<1,2,3>))
QP("vperp2", VPerp_To_Vector(<3,0.5,2>))
QP("vperp3", VPerp_To_Vector(<0.1,3,2>))
QP("vperp0", VPerp_To_Vector(<0,0,0>))
QP("vperpplane", VPerp_To_Plane(<1,2,3>, <0,1,0>))
QP("vperpadj", VPerp_Adjust(<1,2,3>, y))
QP("vprojplane", VProject_Plane(<1,2,3>, <1,1,0>))
QP("vprojaxis", VProject_Axis(<1,2,3>, <1,1,0>))
QF("vmin", VMin(<3,-1,2>)) QF("vmax", VMax(<3,-1,2>))
QP("vwithlen", VWith_Len(<1,2,2>, 6))
QF("sind", sind(30)) QF("cosd", cosd(60)) QF("tand", tand(45))
QF("asind", asind(0.5)) QF("acosd", acosd(0.5)) QF("atand", atand(1)) QF("atan2d", atan2d(1, -1))
QF("max3", max3(1, 5, 3)) QF("min3", min3(4, 2, 3))
QF("f_sqr", f_sqr(3)) QF("sgn", sgn(-2)) QF("sgn0", sgn(0))
QF("clip", clip(5, 0, 3)) QF("clamp", clamp(-5, 0, 3))
QF("adj_range", adj_range(0.5, 1, 3)) QF("adj_range2", adj_range2(0.5, 0, 1, 1, 3))
QF("even", even(4)) QF("odd", odd(4))
QF("clamp2", clamp(7.5, 1, 3)) QF("sgnp", sgn(0.3))
QF("min3b", min3(-1,-2,-3))
#declare Fn = function (x, y, z) { x*x + 2*y*y + 3*z*z + x*y }
SetGradientAccuracy(0.0001)
#declare GFn = fn_Gradient(Fn)
QF("fn_gradient", GFn(1, 2, 3))
#declare GD = fn_Gradient_Directional(Fn, <1,1,0>)
QF("fn_graddir", GD(1, 2, 3))
#declare Fx = function (x, y, z) { x*y }
#declare Fy = function (x, y, z) { y*z*z }
#declare Fz = function (x, y, z) { x + z*z*z }
#declare DV = fn_Divergence(Fx, Fy, Fz)
QF("fn_div", DV(1, 2, 3))
QP("vgradient", vGradient(Fn, <1,2,3>))
QP("vcurl", vCurl(Fx, Fy, Fz, <1,2,3>))
QF("divergence", Divergence(Fx, Fy, Fz, <1,2,3>))
QF("gradlen", Gradient_Length(Fn, <1,2,3>))
QF("graddir", Gradient_Directional(Fn, <1,2,3>, <0,1,1>))
#include "rand.inc"
#declare R = seed(12345);
QF("prob", Prob(0.5, R)) QF("prob2", Prob(0.5, R))
QF("cauchy", Rand_Cauchy(1, 2, R))
QF("student", Rand_Student(5, R))
QF("normal", Rand_Normal(1, 2, R))
QF("gauss", Rand_Gauss(1, 2, R))
#declare Sp = spline { linear_spline 0, <0,0.2>, 0.5, <0.5,1>, 1, <1,0.1> }
QF("gamma", Rand_Gamma(2.5, 1.5, R))
QF("gamma_small", Rand_Gamma(0.5, 1, R))
QF("beta", Rand_Beta(2, 3, R))
QF("chisq", Rand_Chi_Square(4, R))
QF("fdist", Rand_F_Dist(3, 5, R))
QF("triangle", Rand_Triangle(0, 10, 3, R))
QF("erlang", Rand_Erlang(2, 3, R))
QF("exp", Rand_Exp(1.5, R))
QF("lognormal", Rand_Lognormal(1, 0.5, R))
QF("pareto", Rand_Pareto(2, R))
QF("weibull", Rand_Weibull(2, 1.5, R))
QF("bernoulli", Rand_Bernoulli(0.3, R))
QF("binomial", Rand_Binomial(10, 0.3, R))
QF("geo", Rand_Geo(0.3, R))
QF("poisson", Rand_Poisson(3, R))
QF("srand", SRand(R))
QF("rrand", RRand(5, 10, R))
QP("vrand", VRand(R))
QP("vrandbox", VRand_In_Box(<-1,-2,-3>, <1,2,3>, R))
QP("vrandin", VRand_In_Sphere(R))
QP("vrandon", VRand_On_Sphere(R))
QP("vrandobj", VRand_In_Obj(sphere { <1,2,3>, 2 }, R))
QP("vrandobj2", VRand_In_Obj(torus { 2, 0.5 rotate x*30 }, R))
#declare I = 0; #declare S = 0; #while (I < 200) #declare S = S + Rand_Normal(0, 1, R); #declare I = I + 1; #end
QF("sum200", S)
#include "colors.inc"
#include "strings.inc"
#include "arrays.inc"
QS("crgbft", CRGBFTStr(rgbft <0.1, 0.2, 0.3, 0.4, 0.5>, 0, 3))
QS("crgb", CRGBStr(rgb <0.1, 0.25, 1/3>, 6, 2))
Parse_String("#declare PS = 3*7;")
QF("parse_string", PS)
QS("str", Str(1/3))
QS("vstr2d", VStr2D(<1/3, 2>))
QS("vstr", VStr(<1, 0.5, -2>))
QS("Vstr2d", Vstr2D(<1/3, 2>, 5, 2))
QS("Vstr", Vstr(<1, 0.5, -2>, 0, 1))
#declare TS = Triangle_Str(<0,0,0>, <1,0,0>, <0,1,0>); QS("tri", substr(TS, 1, 40)) QF("trilen", strlen(TS))
#declare TS = Smooth_Triangle_Str(x, y, y, z, z, x); QS("stri", substr(TS, 60, 40)) QF("strilen", strlen(TS))
// colors.inc
QP("ch2rgb", CH2RGB(30)) QP("ch2rgb2", CH2RGB(200)) QP("ch2rgb3", CH2RGB(300))
QF("crgb2h", CRGB2H(<0.2, 0.6, 0.4>, 0.6, 0.4))
QP5("chsl2rgb", CHSL2RGB(<120, 0.5, 0.4, 0.1, 0.2>))
QP5("crgb2hsl", CRGB2HSL(<0.2, 0.6, 0.4, 0.1, 0.2>))
QP5("chsv2rgb", CHSV2RGB(<300, 0.5, 0.8, 0, 0>))
QP5("crgb2hsv", CRGB2HSV(<0.9, 0.3, 0.5, 0, 0.3>))
QP5("crgb2hsv_grey", CRGB2HSV(<0.5, 0.5, 0.5, 0, 0>))
QP5("chsl2rgb_grey", CHSL2RGB(<0, 0, 0.7, 0, 0>))
// arrays.inc
#declare R = seed(7);
#declare A = array[5] {5, 3, 9, 1, 7}
QS("randitem", str(Rand_Array_Item(A, R), 0, 3))
Reverse_Array(A)
QF("rev0", A[0]) QF("rev4", A[4])
Sort_Array(A)
QF("sort0", A[0]) QF("sort2", A[2]) QF("sort4", A[4])
#declare B = array[12] {4, 8, 1, 12, 5, 7, 3, 11, 2, 10, 6, 9}
Sort_Partial_Array(B, 2, 9)
QF("psort0", B[0]) QF("psort2", B[2]) QF("psort5", B[5]) QF("psort9", B[9]) QF("psort10", B[10])
Resize_Array(A, 7)
QF("resize", dimension_size(A, 1)) QF("resize4", A[4])
#ifdef (A[6]) QS("a6", "defined") #else QS("a6", "undefined") #end
Resize_Array(A, 3)
QF("resize2", dimension_size(A, 1)) QF("resize2_2", A[2])
#declare C = array[3] {<3,0,0>, <1,0,0>, <2,0,0>}
#macro Sort_Compare(Array, IdxA, IdxB) (Array[IdxA].x < Array[IdxB].x) #end
Sort_Array(C)
QP("vsort", C[0])
#declare Big = array[40]
#declare I = 0; #while (I < 40) #declare Big[I] = rand(R); #declare I = I + 1; #end
#macro Sort_Compare(Array, IdxA, IdxB) (Array[IdxA] < Array[IdxB]) #end
Sort_Array(Big)
QF("big0", Big[0]) QF("big20", Big[20]) QF("big39", Big[39])
