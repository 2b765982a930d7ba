// A macro argument that is an undeclared identifier: POV-Ray 3.7 stops at
// this line with "Cannot pass uninitialized identifier as macro parameter.
// Initialize identifier first." (iris used to pass it on undefined and
// stop, if at all, where the macro read it, on another line).
#macro Decl(Name) #declare Name = 42; #end
Decl(NewVar)
#debug str(NewVar, 0, 0)
