// Parity scene: an average texture_map (weighted entries, whole textures
// shaded and mixed), the mandel and julia patterns, and turbulence on a
// pattern whose entries are pigments and normals (POV-Ray evaluates the
// entries at the warped point).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -8> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -0.2 pigment { checker
    pigment { gradient x color_map { [0 rgb <1, 0.5, 0.2>] [1 rgb <0.2, 0.2, 0.6>] } }
    pigment { gradient z color_map { [0 rgb 1] [1 rgb 0.3] } }
    turbulence 0.4 scale 1.5 } }
box { <-3.2, 0, -0.3>, <-1.2, 2, 0.3>
  texture { average texture_map {
    [3 pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.8 }]
    [1 pigment { radial frequency 8 rotate 90*x } finish { diffuse 0.9 }]
    [pigment { bozo color_map { [0 rgb 0] [1 rgb <0.2, 0.9, 0.3>] } scale 0.3 }] } } }
box { <-1, 0, -0.3>, <1, 2, 0.3>
  pigment { mandel 30 color_map { [0 rgb 0] [0.2 rgb <0.2, 0.4, 1>] [0.5 rgb 1] [1 rgb <1, 0.8, 0.1>] }
            scale 0.8 translate <-0.3, 1, 0> } }
box { <1.2, 0, -0.3>, <3.2, 2, 0.3>
  pigment { julia <-0.745, 0.11>, 40 color_map { [0 rgb 0] [0.3 rgb <0.9, 0.2, 0.5>] [1 rgb 1] }
            scale 0.9 translate <2.2, 1, 0> }
  normal { checker normal { gradient x 0.6 scale 0.2 } normal { gradient y 0.6 scale 0.2 }
           turbulence 0.3 scale 0.5 } }
