/* Compile test (stb test_cpp_compilation style): every FOV_* hook defined to the user's own
   functions before the implementation is included, in either macro form:
     default              object-like:   #define FOV_SQRTF hook_sqrtf
     HOOKS_FUNCTION_LIKE  function-like: #define FOV_SQRTF(x) hook_sqrtf(x)
   The hook functions live in hooks_stub_fns.c (they count their calls and forward to the C
   library). run.sh checks that this object references no libm function, no assert helper
   and no C library function except memset/memcpy (which compilers may emit for struct
   copies), links it with hooks_stub_fns.c and runs it: the render must use the hooks.
   HOOKS_PARTIAL defines only FOV_SQRTF: the header must stop with an #error. */
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif
float hook_sqrtf(float x);
float hook_floorf(float x);
float hook_sinf(float x);
float hook_cosf(float x);
float hook_tanf(float x);
float hook_atan2f(float y, float x);
float hook_expf(float x);
float hook_logf(float x);
float hook_powf(float x, float y);
void *hook_memset(void *p, int v, size_t n);
void *hook_memcpy(void *d, const void *s, size_t n);
void hook_assert(int ok, const char *what, int line);
int hooks_stub_render(void);
#ifdef __cplusplus
}
#endif

#if defined(HOOKS_PARTIAL)
#define FOV_SQRTF(x) hook_sqrtf(x)
#elif defined(HOOKS_FUNCTION_LIKE)
#define FOV_SQRTF(x) hook_sqrtf(x)
#define FOV_FLOORF(x) hook_floorf(x)
#define FOV_SINF(x) hook_sinf(x)
#define FOV_COSF(x) hook_cosf(x)
#define FOV_TANF(x) hook_tanf(x)
#define FOV_ATAN2F(y, x) hook_atan2f(y, x)
#define FOV_EXPF(x) hook_expf(x)
#define FOV_LOGF(x) hook_logf(x)
#define FOV_POWF(x, y) hook_powf(x, y)
#define FOV_MEMSET(p, v, n) hook_memset(p, v, n)
#define FOV_MEMCPY(d, s, n) hook_memcpy(d, s, n)
#define FOV_ASSERT(c) hook_assert((c) ? 1 : 0, #c, __LINE__)
#else
#define FOV_SQRTF hook_sqrtf
#define FOV_FLOORF hook_floorf
#define FOV_SINF hook_sinf
#define FOV_COSF hook_cosf
#define FOV_TANF hook_tanf
#define FOV_ATAN2F hook_atan2f
#define FOV_EXPF hook_expf
#define FOV_LOGF hook_logf
#define FOV_POWF hook_powf
#define FOV_MEMSET hook_memset
#define FOV_MEMCPY hook_memcpy
#define FOV_ASSERT(c) hook_assert((c) ? 1 : 0, #c, __LINE__)
#endif

#define FOV_IMPL
#ifdef FOV_HAVE_FOVSDF
#include "fovsdf.h"
#include "tiny_scene.h"
#endif
#ifdef FOV_HAVE_FOVLP
#include "fovlp.h"
#include "tiny_lp.h"
#endif
#ifdef FOV_HAVE_FOVPT
#include "fovpt.h"
#include "tiny_pt.h"
#endif

/* 0 on success */
int hooks_stub_render(void)
{
#ifdef FOV_HAVE_FOVSDF
    {
        static uint8_t rgb[TINY_W * TINY_H * 3];
        uint64_t evals = 0;
        int e = tiny_render(rgb, &evals);
        if (e != 0) return e;
    }
#endif
#ifdef FOV_HAVE_FOVPT
    {
        static uint8_t rgb2[TINY_PT_W * TINY_PT_H * 3];
        uint64_t rays = 0;
        int e = tiny_pt_render(rgb2, &rays);
        if (e != 0) return 100 + e;
    }
#endif
#ifdef FOV_HAVE_FOVLP
    if (tiny_lp() != 0) return tiny_lp();
#endif
    return 0;
}
