// The camera resolved in POV-Ray's order (right, direction, angle, up,
// sky, location, look_at, transforms) and every kind of light.
#version 3.7;
camera {
  look_at <0, 1, 0>        // written first, applied last
  location <0, 1, -4>
  angle 60
  right x * 16/9
  rotate <0, 30, 0>
}
light_source { <10, 10, -10> color rgb <1, 0.9, 0.8> }
light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 10 falloff 20 tightness 5 }
light_source { <0, 5, 0> rgb 1 cylinder point_at 0 }
light_source { <0, 5, -5> rgb 1 parallel point_at 0 shadowless }
light_source { <5, 5, 0> rgb 1 area_light x, z, 4, 4 adaptive 1 jitter circular orient
               fade_distance 10 fade_power 2 photons { refraction on reflection off } }
light_source { 0, rgb 1 looks_like { sphere { 0, 0.1 } } translate y }
union { light_source { x, rgb 0.5 } sphere { 0, 1 } translate 2*y }
