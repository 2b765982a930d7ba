// A vector comparison as an #if condition. POV-Ray 3.7 stops on line 5:
// "Float expected but vector or color expression found."
#version 3.7;
#if ((<1,2,3> = <1,2,3>).z) #end
#if (<1,2,3> = <1,2,4>) #end
