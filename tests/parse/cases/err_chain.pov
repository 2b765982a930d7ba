// An error inside a macro inside an include: the chain is shown.
#include "inc/helper.inc"
#declare Z = 1;
Bad_Macro(Z)
