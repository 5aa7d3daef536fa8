/* Freestanding compile test: the implementation of every present header alone in a
   translation unit, built by run.sh for wasm32 (clang -ffreestanding -nostdlib) and for
   Cortex-M4F / thumbv7em-eabihf / riscv32 with -DFOV_NO_LIBM '-DFOV_ASSERT(c)='. run.sh then
   checks the object's undefined symbols: only memset/memcpy are allowed (compilers may emit
   them), and no software-double routine (__aeabi_d*, __extendsfdf2, __truncdfsf2, ...). */
#define FOV_IMPL
#ifdef FOV_HAVE_FOVSDF
#include "fovsdf.h"
#endif
#ifdef FOV_HAVE_FOVLP
#include "fovlp.h"
#endif
#ifdef FOV_HAVE_FOVPT
#include "fovpt.h"
#endif
