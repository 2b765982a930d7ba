// options: -w
// One of every object type the parser builds.
#version 3.7;
sphere { <1, 2, 3>, 0.5 }
box { <-1, -1, -1>, <1, 1, 1> }
plane { y, -1 }
cylinder { 0, 2*y, 0.5 open }
cone { 0, 1, y, 0.5 }
torus { 1, 0.25 sturm }
disc { 0, y, 1, 0.5 }
triangle { 0, x, y }
smooth_triangle { 0, y, x, y, z, y }
mesh { triangle { 0, x, y } triangle { 0, y, z } inside_vector x }
mesh2 { vertex_vectors { 4, 0, x, y, z } face_indices { 2, <0,1,2>, <0,2,3> } }
polygon { 4, <0,0>, <1,0>, <1,1>, <0,1> }
prism { linear_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,0> }
lathe { cubic_spline 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,2> }
sor { 4, <0,0>, <1,0>, <1,1>, <0,2> }
superellipsoid { <0.5, 0.25> }
blob { threshold 0.6 sphere { 0, 1, 1 } cylinder { 0, x, 0.5, 2 } }
height_field { function 32, 32 { x * z } smooth water_level 0.1 }
text { ttf "timrom.ttf" "iris" 0.25, 0 }
isosurface { function { x*x + y*y + z*z - 1 } contained_by { sphere { 0, 2 } } max_gradient 4 }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
poly { 4, <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,-1> }
cubic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,-1> }
julia_fractal { <-0.08, 0.7, 0, 0> quaternion sqr max_iteration 8 precision 15 }
bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4
  <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,1,0>, <1,1,1>, <2,1,1>, <3,1,0>,
  <0,2,0>, <1,2,1>, <2,2,1>, <3,2,0>, <0,3,0>, <1,3,0>, <2,3,0>, <3,3,0> }
sphere_sweep { linear_spline 2, <0,0,0>, 0.5, <1,0,0>, 0.25 }
ovus { 1, 0.5 }
union { sphere { 0, 1 } box { 0, 1 } }
merge { sphere { 0, 1 } sphere { x, 1 } }
intersection { sphere { 0, 1 } box { 0, 1 } inverse }
difference { box { -1, 1 } sphere { 0, 1.2 } }
// julia_fractal: the function is an enum iris_julia_fn (cube = 1,
// reciprocal = 3, pwr = 17 with its exponent), the slice's w in data[5].
julia_fractal { <0.2, 0.3, 0, 0> quaternion cube slice <0, 0, 1, 0.5>, 0.25 }
julia_fractal { <0.2, 0.3, 0, 0> hypercomplex reciprocal }
julia_fractal { <0.2, 0.3, 0, 0> hypercomplex pwr(2, 0.5) }
