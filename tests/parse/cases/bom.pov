// A UTF-8 byte order mark is skipped.
sphere { 0, 1 }
