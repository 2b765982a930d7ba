// Atmospheric media: a media{} at the top level of the scene applies
// along every ray outside non-hollow objects, from the camera to the hit
// (the room's walls close the scene, as POV-Ray's documentation asks:
// a ray that meets nothing would cross 2e10 units of it). A point light
// and a spotlight scatter in it, the shadow rays are dimmed by it
// (media_attenuation), and the boxes cast shadows into the haze. The
// room is hollow, as the camera is inside it. Deterministic: 35 dB bar.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 1.5, 0> right x*4/3 }
media {
  scattering { 2, rgb 0.04 }
  absorption rgb <0.01, 0.02, 0.03>
  samples 6 intervals 3
}
light_source { <3, 4.5, 2> color rgb <1, 0.9, 0.7> media_attenuation on }
light_source { <-2, 5.5, -1> color rgb 2
  spotlight point_at <-1, 0, 1> radius 10 falloff 14
  media_attenuation on
}
box { <-6, 0, -9>, <6, 6, 6> pigment { rgb 0.7 } hollow }
box { <-0.5, 0, 0>, <0.5, 2.5, 1> pigment { rgb <0.3, 0.5, 0.9> } }
sphere { <1.8, 0.8, -0.5>, 0.8 pigment { rgb <0.9, 0.5, 0.2> } }
