// An element written later must have the array's type too. POV-Ray 3.7
// stops on line 6: "Attempted to redefine float identifier as uv vector
// identifier." (iris stored it).
#version 3.7;
#declare A = array[2]; #declare A[0] = 1;
#declare A[1] = <1, 2>;
