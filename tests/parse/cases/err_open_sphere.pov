// 'open' follows the parameters of a cylinder, cone, prism or sor, and
// nothing else takes it. POV-Ray 3.7 stops on line 8: "No matching } in
// 'sphere', open found instead" (iris ignored it).
#version 3.7;
cylinder { 0, y, 1 open pigment { rgb 1 } }
cone { 0, 1, y, 0.5 open }
sor { 4, <0,0>, <1,0>, <1,1>, <0,1> open }
sphere { 0, 1 open }
