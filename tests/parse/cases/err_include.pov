// A missing include file.
#include "no_such_file.inc"
