// options: -q
// Issue 7: ".." that stays inside the scene's directory is allowed;
// file_exists() reports files the scene may not read as absent.
#fopen In "inc/../inc/data.txt" read
#read (In, A)
#fclose In
#debug concat("A=", str(A, 0, 1), "\n")
#debug concat("inside: ", str(file_exists("inc/data.txt"), 0, 0), "\n")
#debug concat("outside: ", str(file_exists("../run.sh"), 0, 0), "\n")
#debug concat("by a link: ", str(file_exists("inc/escape.inc"), 0, 0), "\n")
