/* fov_impl_sdf.c - fovsdf.h's implementation alone, compiled once per build flavour (libm,
   FOV_NO_LIBM, sanitizers) by tests/run_all.sh and linked into the test programs built with
   -DFOV_TEST_LINK_IMPL, which then compile only the declarations: the suite compiles each
   implementation three times instead of three times per test program. The test hook
   (tests/common/fov_priv_sdf.h) then defines its wrappers of the private functions that
   the unit tests call, and the archives export them. */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fov_priv_sdf.h"
