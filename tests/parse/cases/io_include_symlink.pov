// Issue 7: inc/escape.inc is a symbolic link to ../../run.sh; the path is
// resolved before the check, so the link cannot lead outside.
#include "inc/escape.inc"
