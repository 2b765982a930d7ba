// Parity scene: which faces of a prism count as inside. POV-Ray's
// Prism::Inside takes height1 <= y < height2 (the bottom inside, the top
// not). An object pattern (Inside_Object) shows it on a wall lying exactly
// on those faces: an orthographic camera along +z meets z = 0 exactly, and
// a matrix that swaps y and z (no rotation's rounding) puts each prism's
// heights on z. Left: a prism whose bottom lies on the wall (its outline
// shows); right: one whose top does (it does not). (Text, 0 <= z <= depth
// in TrueType::Inside, is not shown: POV-Ray's own render of a letter's
// front face on such a wall leaves parts of the letter out, a cause not
// traced.) iris once took both faces as outside: 20.38 dB here (inf with
// the fix).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> direction z right 8 * x up 6 * y }
light_source { <0, 0, -20> color rgb 1 }
#declare SwapYZ = transform { matrix <1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0> }
#declare Shapes = union {
  prism { linear_sweep linear_spline 0, 1, 4,
          <-3.6, -2.5>, <-2.2, -2.5>, <-2.9, 2.5>, <-3.6, -2.5>
          transform SwapYZ }
  prism { linear_sweep linear_spline -1, 0, 4,
          <3.6, -2.5>, <2.2, -2.5>, <2.9, 2.5>, <3.6, -2.5>
          transform SwapYZ }
}
plane { -z, 0
  pigment { object { Shapes rgb <0.2, 0.3, 0.5> rgb <1, 0.8, 0.3> } }
  finish { ambient 0.1 diffuse 0.9 }
}
