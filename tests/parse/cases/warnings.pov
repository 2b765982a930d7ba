// Features that are parsed but not rendered warn once, with a location;
// scale 0 warns and is taken as 1 as POV-Ray does (rainbow is rendered now).
#version 3.7;
sphere { 0, 1 scale <1, 0, 1> }
sphere { 0, 1 interior { media { absorption 1 } } hollow }
sphere { 0, 1 interior { media { emission 1 } } hollow }
fog { distance 10 color rgb 0.5 }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0,0,1>] } } }
