// #end without a matching directive.
#declare A = 1;
#end
