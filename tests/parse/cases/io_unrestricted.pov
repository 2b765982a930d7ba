// options: -q -U
// Issue 7: with IRIS_IO_UNRESTRICTED (--unrestricted-io) any file may be
// read, through ".." or a link.
#debug concat("file_exists: ", str(file_exists("/etc/passwd"), 0, 0), "\n")
#fopen F "../run.sh" read
#fclose F
#fopen G "inc/escape.inc" read
#fclose G
