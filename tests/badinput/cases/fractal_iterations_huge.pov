// expect: 0 8
#version 3.7;
// 1e9 iterations of a fractal pattern: 4 s of CPU per interior point
// (the whole 32x24 image is inside the set), minutes per image. Each
// evaluation stops at IRIS_PATTERN_MAX_ITERATIONS, with a warning at the
// count (the escaping points keep their colours, k / 1e9).
camera { orthographic location <0, 0, -3> look_at 0 right x * 0.2 up y * 0.15 }
plane { z, 0 pigment { mandel 1000000000 } finish { ambient 1 diffuse 0 } }
