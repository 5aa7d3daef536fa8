/* Compile test: the fovpt.h implementation plus a small program using it (C; fovpt.cc
   compiles this file as C++). Built by tests/compile/run.sh over the compiler x standard x
   optimisation matrix with -Werror; one build per compiler is linked and run. */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "tiny_pt.h"

int main(void)
{
    static uint8_t rgb[TINY_PT_W * TINY_PT_H * 3];
    uint64_t rays = 0;
    fovpt_config resolved;
    fovpt_config cfg = fovpt_config_default();
    float w[4], tau = 0.0f;
    int r = tiny_pt_render(rgb, &rays);
    if (r != 0) return r;
    if (fovpt_config_resolve(&cfg, &resolved) != FOV_OK) return 20;
    if (fovpt_method_name(FOVPT_METHOD_LAYERS) == NULL) return 21;
    fovpt_catmull_rom(0.5f, w);
    if (w[1] + w[2] < 0.5f) return 22;
    if (fovpt_tau_fov(&resolved.selective, 2.0f, &tau) != FOV_OK || !(tau > 1.0f)) return 23;
    return 0;
}
