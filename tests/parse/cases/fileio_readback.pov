// A scene reads back what it wrote while writes are refused (the text is
// kept in memory, nothing reaches the disk): #write then a
// #while (defined(F)) #read loop, which ends because a #read at the end
// of the file closes it and undefines F (POV-Ray's rule); #fclose of the
// undefined F is accepted; #include of a written file; file_exists();
// more files opened one after another than may be open at once; a file
// written by a macro of an included library file lands in the scene's
// directory (POV-Ray's working directory), where the scene includes it.
// The sums are exact: sum of I for I = 0..9 is 45, of I*I is 285.
#fopen Out "readback_data.txt" write
#for (I, 0, 9)
  #write (Out, I, ",", <I, I*I, -I>, ",\n")
#end
#fclose Out
#declare N = 0; #declare S = 0; #declare Q = 0;
#fopen In "readback_data.txt" read
#while (defined(In))
  #read (In, A, V)
  #if (defined(In))
    #declare N = N + 1; #declare S = S + A; #declare Q = Q + V.y;
  #end
#end
#fclose In
#debug concat("read ", str(N, 0, 0), " lines, sum ", str(S, 0, 0), ", squares ", str(Q, 0, 0), "\n")
#fopen Inc "readback_gen.inc" write
#write (Inc, "#declare Generated = ", 7*6, ";\n")
#fclose Inc
#include "readback_gen.inc"
#debug concat("Generated = ", str(Generated, 0, 0), ", exists ", str(file_exists("readback_gen.inc"), 0, 0), "\n")
#for (I, 1, 40)
  #fopen T "readback_tmp.txt" write
  #write (T, I)
  #fclose T
#end
#fopen T "readback_tmp.txt" read
#read (T, Last)
#debug concat("last = ", str(Last, 0, 0), "\n")
// A macro of an included library file writes; the scene includes it from
// its own directory: a sphere of radius 2.5.
#include "inc/writer.inc"
Write_Sphere_Inc("readback_sphere.inc", 2.5)
object { #include "readback_sphere.inc" }
