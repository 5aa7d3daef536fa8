/* Compile test: the fovlp.h implementation plus a small program using it (C; fovlp.cc
   compiles this file as C++). Built by tests/compile/run.sh over the compiler x standard x
   optimisation matrix with -Werror; one build per compiler is linked and run. A 16x9 screen,
   C Fov preset, a constant colour shaded through the callback form and reconstructed. */
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"

static void shade_const(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)x; (void)y; (void)user;
    rgb[0] = 0.25f; rgb[1] = 0.5f; rgb[2] = 0.75f;
    if (depth) *depth = 1.0f;
}

int main(void)
{
    static unsigned char mem[4096];
    static float samples[4096 * 3];
    static float img[16 * 9 * 3];
    fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 16, 9);
    fovlp_ctx ctx;
    fov_gaze gaze;
    size_t bytes = 0;
    unsigned i;
    gaze.x = 5.0f; gaze.y = 4.0f;
    if (fovlp_memory_size(&cfg, &bytes) != FOV_OK || bytes > sizeof mem) return 1;
    if (fovlp_init(&ctx, &cfg, mem, sizeof mem) != FOV_OK) return 2;
    if (fovlp_begin_frame(&ctx, gaze, 0) != FOV_OK) return 3;
    if (ctx.geo.samples > 4096u) return 4;
    if (fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), shade_const, 0, samples, 0, 0) != FOV_OK) return 5;
    if (fovlp_reconstruct_rows(&ctx, samples, 0, 0, 9, img, 0, 0) != FOV_OK) return 6;
    for (i = 0; i < 16u * 9u; ++i)
        if (img[3 * i] < 0.24f || img[3 * i] > 0.26f || img[3 * i + 2] < 0.74f || img[3 * i + 2] > 0.76f) return 7;
    if (fovlp_result_string(FOV_ERR_LIMIT) == 0 || fovlp_preset_name(2) == 0) return 8;
    return 0;
}
