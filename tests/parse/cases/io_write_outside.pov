// options: -q -W
// Issue 7: with writes allowed, #fopen write still stays inside the
// scene's directory.
#fopen F "../never_written.txt" write
#write (F, "x")
