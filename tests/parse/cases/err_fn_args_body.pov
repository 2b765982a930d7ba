// options: -q
// A call in a function body with the wrong argument count: POV-Ray 3.7
// stops on line 6 with "Invalid number of parameters: 3 supplied, 2
// required!" (iris used to take any count).
#declare F = function(a, b) { a + b }
#declare G = function { F(x, y, z) }
