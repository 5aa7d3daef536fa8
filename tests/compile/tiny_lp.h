/* tiny_lp.h - a tiny fovlp frame shared by the compile tests (include fovlp.h first): a 16x9
   screen, C Fov preset, a constant colour shaded through the callback form, reconstructed.
   Defines one static function, tiny_lp(), so every includer must call it. Returns 0 on
   success, else a small positive code (40 + the step that failed). */
#ifndef TINY_LP_H
#define TINY_LP_H

static void tiny_lp_shade(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)x; (void)y; (void)user;
    rgb[0] = 0.25f; rgb[1] = 0.5f; rgb[2] = 0.75f;
    if (depth) *depth = 1.0f;
}

static int tiny_lp(void)
{
    static uint64_t mem[512];
    static float samples[4096 * 3];
    static float img[16 * 9 * 3];
    fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 16, 9);
    fovlp_ctx ctx;
    fov_gaze gaze;
    size_t bytes = 0;
    unsigned i;
    gaze.x = 5.0f; gaze.y = 4.0f;
    if (fovlp_memory_size(&cfg, &bytes) != FOV_OK || bytes > sizeof mem) return 41;
    if (fovlp_init(&ctx, &cfg, mem, sizeof mem) != FOV_OK) return 42;
    if (fovlp_begin_frame(&ctx, gaze, 0) != FOV_OK || ctx.geo.samples > 4096u) return 43;
    if (fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), tiny_lp_shade, 0, samples, 0, 0) != FOV_OK) return 44;
    if (fovlp_reconstruct_rows(&ctx, samples, 0, 0, 9, img, 0, 0) != FOV_OK) return 45;
    for (i = 0; i < 16u * 9u; ++i)
        if (img[3 * i] < 0.24f || img[3 * i] > 0.26f || img[3 * i + 2] < 0.74f || img[3 * i + 2] > 0.76f) return 46;
    return 0;
}
#endif
