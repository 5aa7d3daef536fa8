/* Compile test (stb test_cpp_compilation style): every FOV_* hook defined to the user's own
   functions before the implementation is included, in either macro form:
     default              object-like:   #define FOV_SQRTF hook_sqrtf
     HOOKS_FUNCTION_LIKE  function-like: #define FOV_SQRTF(x) hook_sqrtf(x)
   The hook functions live in hooks_stub_fns.c (they count their calls and forward to the C
   library). run.sh checks that this object references no libm function, no assert helper
   and no C library function except memset/memcpy (which compilers may emit for struct
   copies), links it with hooks_stub_fns.c and runs it: the render must use the hooks.
   HOOKS_PARTIAL defines only FOV_SQRTF: the header must stop with an #error. */
#include "hooks_stub.h"

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
#include "tiny_all.h"

/* 0 on success */
int hooks_stub_render(void)
{
    return tiny_render_all();
}
