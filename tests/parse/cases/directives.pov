// Directives: include search (-L), #local scope of include files,
// macros returning objects, #while/#for/#switch, #default, #undef.
#version 3.7;
#include "inc/helper.inc"
#ifdef (Hidden) #error "include-local #local leaked" #end
#debug concat("Helper_Value = ", str(Helper_Value, 0, 0), "\n")
#default { finish { ambient 0 diffuse 0.8 } }
#declare N = 0;
#while (N < 3)
  object { Make_Ball(0.25) translate <N, 0, 0> }
  #declare N = N + 1;
#end
#for (I, 1, 2)
  #switch (I)
    #case (1) box { 0, 1 } #break
    #else cylinder { 0, y, 0.5 }
  #end
#end
#declare Tmp = 1;
#undef Tmp
#ifndef (Tmp) #debug "Tmp undefined\n" #end
