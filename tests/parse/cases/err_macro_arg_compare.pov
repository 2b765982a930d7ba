// A macro argument (and a #declare value) is a sum of products: a
// comparison needs parentheses. POV-Ray 3.7 stops on line 7: "Expected
// ')', < found instead" (iris passed 1 < 2 as 1).
#version 3.7;
#macro Twice(A) (A * 2) #end
#declare Ok = Twice((1 < 2));
#declare V = Twice(1 < 2);
