// Compile test: fovsdf.c compiled as C++ (C++98, C++11, ...).
#include "fovsdf.c"
