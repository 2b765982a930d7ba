// An array holds one type: its first element's. POV-Ray 3.7 stops on
// line 8: "Attempted to redefine float identifier as vector identifier."
// (iris stored the vector). Floats, 2-D, 3-D and 4-D vectors and colours
// are apart; a light source is an object.
#version 3.7;
#declare Ok = array[2] { sphere { 0, 1 }, light_source { 0, 1 } }
#declare Ok2 = array[2] { <1,2,3,4,5>, rgb 1 }
#declare A = array[3] { 1, <1,2,3>, 3 }
