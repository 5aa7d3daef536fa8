/* the C++ build of fovlp.c */
#include "fovlp.c"
