/* Compile test: the second translation unit of two_static_copies_a.c (see there), the same
   private copies of the headers behind the wrapper two_static_copy_b. */
#define TWO_STATIC_COPY two_static_copy_b
#include "two_static_copies_a.c"
