// Compile test: fovpt.c compiled as C++ (C++98, C++11, ...).
#include "fovpt.c"
