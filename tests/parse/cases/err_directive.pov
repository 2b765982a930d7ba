// #error stops the parse with its message.
#declare V = 3;
#if (V > 2)
  #error concat("V is too big: ", str(V, 0, 0))
#end
