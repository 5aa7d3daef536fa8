/* Compile test: the fovsdf.h implementation plus a small program using it (C; fovsdf.cc
   compiles this file as C++). Built by tests/compile/run.sh over the compiler x standard x
   optimisation matrix with -Werror; one build per compiler is linked and run. */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "tiny_scene.h"

int main(void)
{
    static uint8_t rgb[TINY_W * TINY_H * 3];
    uint64_t evals = 0;
    size_t bytes = 0;
    fovsdf_config resolved;
    fovsdf_config cfg = fovsdf_config_default();
    int r = tiny_render(rgb, &evals);
    if (r != 0) return r;
    if (fovsdf_config_resolve(&cfg, &resolved) != FOV_OK) return 20;
    if (fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &bytes) != FOV_OK || bytes == 0) return 21;
    if (fovsdf_builtin_size(0x7FFFFFF0u, &bytes) == FOV_OK) return 22;
    if (fovsdf_method_name(FOVSDF_METHOD_RELAXED) == NULL) return 23;
    return 0;
}
