// #fopen/#read/#fclose of a data file; #write is refused without
// allow_writes (a located warning) and its text kept in memory, so the
// scene sees the file exist (file_exists = 1, as in POV-Ray, which writes
// it); #warning; #debug.
// options: -q
#fopen In "inc/data.txt" read
#read (In, A, S, V)
#fclose In
#debug concat("A=", str(A, 0, 1), " S=", S, " V.z=", str(V.z, 0, 0), "\n")
#fopen Out "out.txt" write
#write (Out, "not written\n")
#fclose Out
#warning concat("file_exists(out.txt) = ", str(file_exists("out.txt"), 0, 0))
