// options: -q -L ..
// Issue 7: a +L library path is an allowed tree: with +L.. the file one
// level up may be read.
#debug concat("file_exists: ", str(file_exists("../run.sh"), 0, 0), "\n")
#fopen F "../run.sh" read
#fclose F
