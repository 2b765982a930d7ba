// 'open' after a cylinder's modifiers is too late. POV-Ray 3.7 stops on
// line 5: "No matching } in 'cylinder', open found instead" (iris opened
// the cylinder).
#version 3.7;
cylinder { 0, y, 1 pigment { rgb 1 } open }
