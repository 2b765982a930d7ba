// A spline key's value is a float or a vector: a colour keyword there is
// refused. POV-Ray 3.7 stops on line 6: "Expected 'numeric expression',
// color keyword 'rgb' found instead" (iris read the colour).
#version 3.7;
#declare Ok = spline { linear_spline 0, <1,0,0> 1, <0,0,1> }
#declare S = spline { linear_spline 0, rgb <1,0,0> 1, rgb <0,0,1> }
