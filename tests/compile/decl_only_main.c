/* Compile test: declarations only (no implementation macro); links against decl_then_impl.c
   (possibly compiled in the other language: C main with a C++ implementation object and the
   reverse, which checks the extern "C" blocks) and calls a few functions. */
#ifdef FOV_HAVE_FOVSDF
#include "fovsdf.h"
#include "tiny_scene.h"
#endif
#ifdef FOV_HAVE_FOVLP
#include "fovlp.h"
#endif
#ifdef FOV_HAVE_FOVPT
#include "fovpt.h"
#endif

#ifdef __cplusplus
extern "C" int decl_then_impl_probe(void);
#else
int decl_then_impl_probe(void);
#endif

int main(void)
{
    if (!decl_then_impl_probe()) return 10;
#ifdef FOV_HAVE_FOVSDF
    {
        static uint8_t rgb[TINY_W * TINY_H * 3];
        uint64_t evals = 0;
        size_t bytes = 0;
        int r = tiny_render(rgb, &evals);
        if (r != 0) return r;
        if (fovsdf_builtin_size(FOVSDF_SCENE_THIN, &bytes) != FOV_OK || bytes == 0) return 11;
        if (fovsdf_builtin_name(FOVSDF_SCENE_THIN) == NULL) return 12;
    }
#endif
    return 0;
}
