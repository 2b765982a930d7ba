// expect: 2 6
#version 3.7;
camera { location <0, 1, -3> look_at 0 }
light_source { <0, 5, -5>, rgb 1 }
box { 0, 1 pigment { rgbt 1 } hollow interior { media { emission 1
  density { density_file df3 "no_such.df3" interpolate 1 } } } }
