/* Compile test (stb_howto): include every header first as declarations only, use them, then
   include them again with FOV_IMPL in the same translation unit. The declaration guard must
   not hide the implementation, and the implementation must not clash with the declarations
   seen before it. Linked with decl_only_main.c, which only sees declarations.
   run.sh defines FOV_HAVE_FOVSDF / FOV_HAVE_FOVLP / FOV_HAVE_FOVPT for the headers present. */
#ifdef FOV_HAVE_FOVSDF
#include "fovsdf.h"
#endif
#ifdef FOV_HAVE_FOVLP
#include "fovlp.h"
#endif
#ifdef FOV_HAVE_FOVPT
#include "fovpt.h"
#endif

/* uses the declarations before the implementation is seen */
#ifdef __cplusplus
extern "C" int decl_then_impl_probe(void);
#else
int decl_then_impl_probe(void);
#endif
int decl_then_impl_probe(void)
{
    int ok = 1;
#ifdef FOV_HAVE_FOVSDF
    {
        fovsdf_config c = fovsdf_config_default();
        ok = ok && c.method == FOVSDF_METHOD_CLASSIC && fovsdf_result_string(FOV_OK) != NULL;
    }
#endif
    return ok;
}

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
