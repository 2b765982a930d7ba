// Parity scene: the normal the slope pattern sees. POV-Ray's slope reads
// Intersection->PNormal, which every layer with a normal{} overwrites with
// its perturbed normal (Perturb_Normal) and which is reset to the raw
// normal only at the next hit. A texture_map evaluates its 'cur' entry
// before its 'prev' one, so here the second copy of the slope map sees
// the bumps of the first copy's green entry, and the green/sand border
// frays where the gradient mixes the two (textures/patterns/slopemt_37,
// a slope map under a gradient map). iris once gave every pattern the
// raw normal (30.4 dB here, 72.6 with the fix; slopemt_37 33.0 -> 55.4
// dB at 160x120).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0, 0> right x*4/3 angle 50 }
light_source { <200, 200, -200>, color rgb 1.2 }
#declare V = texture { pigment { color <0.2, 0.5, 0.1>*0.5 }
                       normal { bumps 0.5 scale 0.05 } }
#declare S = texture { pigment { color <0.7, 0.6, 0.3> } }
#declare VS = texture { slope { -y*3, 0, 0.5 } texture_map { [0.45 V] [0.55 S] } }
sphere { 0, 1.2 texture { gradient x scale 10 texture_map { [0 VS] [1 VS] } } }
