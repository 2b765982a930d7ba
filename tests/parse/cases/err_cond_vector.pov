// A vector as the condition of '?:'. POV-Ray 3.7 stops on line 6:
// "Conditional must evaluate to a float." (iris took its first
// component).
#version 3.7;
#declare Ok = ((<1,2,3> = <1,2,3>).x ? 5 : 6);
#declare V = ((<1,2,3> = <1,2,4>) ? 5 : 6);
