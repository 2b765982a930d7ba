// Wrong macro argument count.
#macro M(A, B) A + B #end
#declare X = M(1);
