/* Compile test: every present header in one translation unit with FOV_IMPL (the project-wide
   implementation switch), included in one order and then again in the reverse order, so the
   shared blocks (FOV_SHARED_BEGIN decl / impl) and each once-guard are exercised. Compiled as C and as
   C++, linked and run. */
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
/* again, reversed */
#ifdef FOV_HAVE_FOVPT
#include "fovpt.h"
#include "tiny_pt.h"
#endif
#ifdef FOV_HAVE_FOVLP
#include "fovlp.h"
#endif
#ifdef FOV_HAVE_FOVSDF
#include "fovsdf.h"
#include "tiny_scene.h"
#endif
#ifdef FOV_HAVE_FOVLP
#include "tiny_lp.h"
#endif
#include "tiny_all.h"

int main(void)
{
    fov_result r = FOV_OK;
    (void)r;
    {
        int e = tiny_render_all();
        if (e != 0) return e;
    }
#if defined(FOV_HAVE_FOVSDF) && defined(FOV_HAVE_FOVLP) && defined(FOV_HAVE_FOVPT)
    { /* the shared result codes read the same in every header */
        int code;
        for (code = -16; code <= 16; ++code) {
            const char *a = fovsdf_result_string((fov_result)code), *b = fovlp_result_string((fov_result)code),
                       *c = fovpt_result_string((fov_result)code);
            while (*a && *a == *b && *a == *c) { ++a; ++b; ++c; }
            if (*a != *b || *a != *c) return 200;
        }
    }
#endif
    return 0;
}
