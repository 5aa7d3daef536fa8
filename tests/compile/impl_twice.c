/* Compile test: each present header included twice with its own implementation macro (the
   once-guard FOVxx_IMPL_INCLUDED must make the second inclusion a no-op), then a program. */
#ifdef FOV_HAVE_FOVSDF
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fovsdf.h"
#endif
#ifdef FOV_HAVE_FOVLP
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#include "fovlp.h"
#endif
#ifdef FOV_HAVE_FOVPT
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "fovpt.h"
#endif

int main(void)
{
#ifdef FOV_HAVE_FOVSDF
    if (fovsdf_result_string(FOV_ERR_LIMIT) == NULL) return 1;
#endif
    return 0;
}
