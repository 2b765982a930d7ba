// A float #declare without its ';' before a directive. POV-Ray 3.7 stops
// on line 6, where the value ends: "All #declares of float, vector, and
// color require semi-colon ';' at end if the language version is set to
// 3.5 or higher" (iris took the ';' as optional). A string, an object or
// a #version 3.1 scene needs none (povray_user_forms.pov's Parse_String).
#declare Radius = 1.5
#declare Name = "ball"
sphere { 0, Radius }
