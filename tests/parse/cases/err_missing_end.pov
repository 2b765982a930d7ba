// #if without #end. POV-Ray 3.7 stops at the file's last token: "line 5:
// End of file reached but #end expected"; iris names that line too, and
// the #if that is open.
#if (1)
  sphere { 0, 1 }
