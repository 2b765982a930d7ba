// Issue 7: with the default (restricted) policy an #include may not leave
// the scene's directory and the library paths, here through "..".
#include "../run.sh"
