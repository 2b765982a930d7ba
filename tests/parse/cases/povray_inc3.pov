// options: -q -w
// Every macro of meshmaker.inc, screen.inc, functions.inc, textures.inc,
// glass.inc, ior.inc, debug.inc, rad_def.inc, sunpos.inc and
// makegrass.inc called once or more, values and extents printed with
// #debug. povray_inc3.expect is POV-Ray 3.7.0.10's own #debug output of
// this file (povray +Ipovray_inc3.pov -D +GDfile, run in this directory),
// byte for byte (meshmaker.inc's progress lines start with "\r", which
// POV-Ray's debug stream, and now iris's, turns into a line break).
// Fixed by it:
// - a float, vector or colour #declare takes a second ';' (POV-Ray's
//   Parse_Declare: meshmaker.inc's FindPoint() ends its value with ';'
//   and SweepSpline1/2 write '#local P = FindPoint(su,sv);');
// - the period operator leaves the vector's other components where a
//   vector is read: vlength(Waist(su).x) is vlength(Waist(su))
//   (SweepSpline1/2);
// - a sphere under a matrix or transform{} is boxed as POV-Ray's
//   Sphere::Transform does, by its transformed box (screen.inc's
//   Screen_Object);
// - meshes are boxed by their own box transformed (MakePrairie).
#version 3.7;
#include "inc/print.inc"
#include "colors.inc"
#include "meshmaker.inc"
QF("linterp", LInterpolate(0.25, 2, 6))
QF("checkfile_empty", CheckFileName(""))
QF("checkfile_obj", CheckFileName("x.obj"))
QF("checkfile_pcm", CheckFileName("x.pcm"))
QF("checkfile_inc", CheckFileName("x.inc"))
#declare SA = array[5] { <0,0,0>, <1,1,0>, <2,0,1>, <3,1,1>, <4,0,0> }
#declare BS = BuildSpline(SA, "C")
QP("buildspline_c", BS(0.5))
#declare BS2 = BuildSpline(SA, "l")
QP("buildspline_l", BS2(0.75))
#declare VA = array[4] { <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0.5> }
#declare NA = array[4] { z, z, z, <0,0.3,1> }
#declare UA = array[4] { <0,0>, <1,0>, <0,1>, <1,1> }
QE("buildwritemesh2", BuildWriteMesh2(VA, NA, UA, 1, 1, ""))
#declare Sp1 = spline { cubic_spline -1, <1,-1,0>, 0, <1,0,0>, 1, <2,1,0>, 2, <1,2,0>, 3, <1,3,0> }
#declare Sp2 = spline { cubic_spline -1, <1,-1,1>, 0, <1,0,1>, 1, <1.5,1,1>, 2, <1,2,1>, 3, <1,3,1> }
#declare Sp3 = spline { cubic_spline -1, <1,-1,2>, 0, <1,0,2>, 1, <2.5,1,2>, 2, <1,2,2>, 3, <1,3,2> }
#declare Sp4 = spline { cubic_spline -1, <1,-1,3>, 0, <1,0,3>, 1, <1,1,3>, 2, <1,2,3>, 3, <1,3,3> }
#declare SplArr = array[4] { Sp1, Sp2, Sp3, Sp4 }
QE("msm", MSM(SplArr, 8, "c", 10, ""))
QE("msm_l", MSM(SplArr, 6, "l", 5, ""))
QE("parametric", Parametric(function(u,v) { sin(u)*cos(v) }, function(u,v) { sin(u)*sin(v) }, function(u,v) { cos(u) }, <0, 0>, <pi, 2*pi>, 8, 12, ""))
QE("parametric_fromto", Parametric(function(u,v) { u }, function(u,v) { v*v }, function(u,v) { u*v }, <FromU(0), ToV(0)>, <ToU(1), FromV(2)>, 5, 6, ""))
#declare PSp = spline { linear_spline 0, <0,0,1>, 1, <1,0,1>, 2, <1,1,0.5>, 3, <0,0,1> }
QE("prism", Prism(PSp, 12, 2, 3, ""))
#declare HSp = spline { linear_spline 0, <1,0,0>, 1, <2,1,0>, 2, <1,2,0> }
QE("prism1", Prism1(PSp, 12, HSp, 6, ""))
#declare LSp = spline { cubic_spline -1, <0,-1,0>, 0, <0.5,0,0>, 1, <1,1,0>, 2, <0.5,2,0>, 3, <0,3,0> }
QE("lathe", Lathe(LSp, 10, 360, 16, ""))
QE("lathe_half", Lathe(LSp, 6, 180, 8, ""))
#declare C1 = spline { linear_spline 0, <0,0,0>, 1, <1,0,0.3>, 2, <2,0,0> }
#declare C2 = spline { linear_spline 0, <2,0,0>, 1, <2.2,1,0>, 2, <2,2,0> }
#declare C3 = spline { linear_spline 0, <2,2,0>, 1, <1,2,-0.3>, 2, <0,2,0> }
#declare C4 = spline { linear_spline 0, <0,2,0>, 1, <-0.2,1,0>, 2, <0,0,0> }
QE("coons", Coons(C1, C2, C3, C4, 8, 8, ""))
QE("twovarsurf", TwoVarSurf(function(u,v) { sin(u*3)*cos(v*2) }, <-1, 1>, <-1, 2>, 10, 12, ""))
#declare Track = spline { cubic_spline -1, <0,-1,0>, 0, <0,0,0>, 1, <1,1,0>, 2, <2,1,1>, 3, <3,0,2> }
#declare Shape = spline { linear_spline 0, <0.2,0,0>, 1, <0,0.2,0>, 2, <-0.2,0,0>, 3, <0,-0.2,0>, 4, <0.2,0,0> }
#declare Waist = spline { linear_spline 0, <1,0,0>, 1, <0.5,0,0> }
QE("sweepspline1", SweepSpline1(Track, Shape, Waist, 12, 8, ""))
QE("sweepspline2", SweepSpline2(Track, Shape, Waist, 12, 8, ""))
#include "screen.inc"
#include "transforms.inc"
QF("aspect0", Camera_Aspect_Ratio)
Set_Camera_Location(<1,2,-5>)
Set_Camera_Look_At(<0,1,0>)
QT("cam_xf", Camera_Transform)
Set_Camera_Aspect_Ratio(2)
QF("aspect", Camera_Aspect_Ratio)
Set_Camera_Aspect(640, 480)
QF("aspect2", Camera_Aspect_Ratio)
Set_Camera_Sky(<0.1,1,0>)
QP("camr", CamR) QP("camu", CamU)
Set_Camera_Zoom(2)
QF("zoom", Camera_Zoom)
Set_Camera_Angle(60)
QF("zoom_angle", Camera_Zoom)
Set_Camera(<0,3,-8>, <0,0,0>, 45)
QF("zoom_set", Camera_Zoom) QP("camd", CamD)
QE("screen_object", Screen_Object(box { 0, <0.1,0.05,0.01> }, <0.2, 0.8>, 0.01, true, 0.1))
QE("screen_object2", Screen_Object(sphere { 0, 0.05 }, <1, 0>, 0.02, false, 0.2))
QE("screen_plane", Screen_Plane(pigment { checker }, 0.5, <0.1,0.1>, <0.4,0.3>))
Reset_Camera()
QF("zoom_reset", Camera_Zoom)
QP("loc_reset", Camera_Location)
#include "functions.inc"
#include "textures.inc"
#include "glass.inc"
#include "ior.inc"
#include "debug.inc"
#include "rad_def.inc"
#include "sunpos.inc"
#include "makegrass.inc"
// functions.inc eval_pigment
QP5("eval_pigment", eval_pigment(pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } }, <0.25, 0, 0>))
// textures.inc pattern macros, evaluated through eval_pigment
#declare IB = Irregular_Bricks_Ptrn(0.05, 2, 0.2, 4)
QF("irregular_bricks", IB(0.3, 0.2, 0.7))
QF("irregular_bricks2", IB(1.7, 0.6, 0.1))
#declare PH = pigment { Hex_Tiles_Ptrn() }
QP5("hex_tiles", eval_pigment(PH, <0.3, 0.2, 0>))
QP5("hex_tiles2", eval_pigment(PH, <1.3, 0.7, 0>))
#declare PT = pigment { Tiles_Ptrn() color_map { [0 rgb 0] [1 rgb 1] } }
QP5("tiles", eval_pigment(PT, <0.3, 0.1, 0.5>))
QP5("tiles2", eval_pigment(PT, <2.45, -0.7, 3>))
#declare PS = pigment { Star_Ptrn(0.5, 5, 0.3) }
QP5("star", eval_pigment(PS, <0.1, 0.2, 0>))
QP5("star2", eval_pigment(PS, <0.3, -0.1, 0>))
// glass.inc interior macros
#declare IE = interior { I_Glass_Exp(2) }
#declare IS = interior { I_Glass_Sqr(3) }
#declare MG = material { texture { pigment { rgbf 1 } } interior { I_Glass_Exp(0.5) } }
QF("ior_bk7", iorCrownGlassBK7) QF("disp_bk7", dispCrownGlassBK7)
QF("ior_sf11", iorFlintGlassSF11) QF("disp_sf11", dispFlintGlassSF11)
QF("fn_disp", FnPovDispersion(1.5, 0.02))
// debug.inc
Set_Debug(true)
Debug_Message("debug message\n")
Debug(1, "debug true\n")
Debug(0, "debug false\n")
Warning(0, "no warning\n")
Debug_Inc_Stack()
QF("stack", View_POV_Include_Stack)
// sunpos.inc
#declare SP = SunPos(2000, 6, 21, 12, 0, 0, 51.4778, -0.0017);
QP("sunpos", vnormalize(SP)) QF("sun_al", Al) QF("sun_az", Az)
#declare SP2 = SunPos(2026, 11, 22, 9, 30, 15, 48.2, 16.37);
QF("sun_al2", Al) QF("sun_az2", Az)
// rad_def.inc: radiosity blocks (iris warns it does not render them)
global_settings { radiosity { Rad_Settings(Radiosity_Normal, off, off) } }
// makegrass.inc
#declare Blade = MakeBlade(0, <0,0,0>, 30, 10, 10, 1, 0.1, 0.5, <0,1,0.3>, <0,0,1>, 1, 0, 0)
QE("makeblade", Blade)
#declare Blade2 = MakeBlade(1, <1,0,2>, 45, 8, 6, 0.8, 0.1, 0.3, <0,1,0.3>, <0,-1,2>, 2, 1, 0)
QE("makeblade_fold", Blade2)
#declare GP = MakeGrassPatch(20, 5, 60, 6, 10, 1, 0.3, 0, <0,1,0.3>, <0,-1,2>, 3, 18264, 0.5, 360, 3, 0, 0, 0, "")
QE("grasspatch", GP)
#declare PR = MakePrairie(20, 2, 1, 2, GP, 779, 1, 1, 0)
QV3(PR)
