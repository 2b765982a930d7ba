// A file that includes itself stops at the include depth limit.
#include "err_self_include.pov"
