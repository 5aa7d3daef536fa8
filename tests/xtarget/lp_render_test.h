/* lp_render_test.h - the cross-target part of fovlp.h, included by render_test.c when
   XT_FOVLP is defined (tests/xtarget/run.sh does when fovlp.h exists). Public fovlp API only,
   static memory, no libm in this file (a triangle-wave test image), the same dump format as
   the fovsdf scenes so compare.c checks them with the same thresholds:
     scene 20 lp_cfov       one frame, C Fov preset, gaze off-centre, reconstruction
     scene 21 lp_kfov       one frame, K Fov preset (plain log-polar, kernel alpha 3)
     scene 22 lp_cfov_taa   C Fov with TAA: the history after 4 jittered frames
   rgb = the reconstruction (8-bit sRGB-free: value * 255), hit = 1 everywhere,
   depth = the reconstructed depth; stats evals = the number of samples shaded. */
#ifndef XT_EXTERNAL_IMPL
#define FOVLP_IMPLEMENTATION
#endif
#include "fovlp.h"

#define XT_LP_SAMPLES 8192u
static uint64_t xt_lp_mem[1024];                    /* 8 KiB of context tables */
static float xt_lp_rgb[XT_LP_SAMPLES * 3];
static float xt_lp_sdep[XT_LP_SAMPLES];
static float xt_lp_img[3][XT_W * XT_H * 3];        /* current, history ping, pong */
static float xt_lp_dep[3][XT_W * XT_H];
static uint8_t xt_lp_age[2][XT_W * XT_H];

/* triangle wave in [0, 1] with period 1 (no libm) */
static float xt_tri(float x)
{
    float f = x - (float)(int32_t)x;
    if (f < 0.0f) f += 1.0f;
    return f < 0.5f ? 2.0f * f : 2.0f - 2.0f * f;
}
static void xt_lp_shade(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)user;
    rgb[0] = 0.1f + 0.8f * xt_tri(x * 0.083f + y * 0.021f);
    rgb[1] = 0.1f + 0.8f * xt_tri(y * 0.067f - x * 0.013f);
    rgb[2] = 0.5f * xt_tri((x + y) * 0.031f) + 0.25f;
    if (depth) *depth = 1.0f + x * 0.01f + y * 0.002f;
}

static int xt_lp_scene(uint32_t id, const char *name, uint32_t preset, int taa_frames)
{
    fovlp_config cfg = fovlp_config_preset(preset, XT_W, XT_H);
    fovlp_ctx ctx;
    fov_gaze gaze;
    fov_result r = FOV_OK;
    const char *step = "ok";
    uint64_t shaded = 0;
    size_t bytes = 0;
    uint32_t x, y, i;
    int f, ping = 1, frames = taa_frames > 0 ? taa_frames : 1;
    const float *out = xt_lp_img[0], *dep = xt_lp_dep[0];

    for (i = 0; i < XT_W * XT_H; i++) { xt_rgb[3 * i] = xt_rgb[3 * i + 1] = xt_rgb[3 * i + 2] = 0; xt_hit[i] = 1; xt_depth[i] = 0.0f; }
    xt_puts("scene "); xt_putu(id); xt_putc(' '); xt_puts(name); xt_endl();
    cfg.taa.enable = taa_frames > 0 ? 1u : 0u;
    gaze.x = 0.41f * (float)XT_W;
    gaze.y = 0.57f * (float)XT_H;
    r = fovlp_memory_size(&cfg, &bytes);
    if (r != FOV_OK) { step = "memory_size"; goto done; }
    xt_puts("memory scene "); xt_putu((uint64_t)bytes); xt_puts(" of "); xt_putu((uint64_t)sizeof xt_lp_mem); xt_endl();
    if (bytes > sizeof xt_lp_mem) { r = FOV_ERR_TOO_SMALL; step = "ctx_memory"; goto done; }
    r = fovlp_init(&ctx, &cfg, xt_lp_mem, sizeof xt_lp_mem);
    if (r != FOV_OK) { step = "init"; goto done; }
    if (ctx.geo.samples > XT_LP_SAMPLES) { r = FOV_ERR_TOO_SMALL; step = "samples"; goto done; }
    for (f = 0; f < frames; f++) {
        r = fovlp_begin_frame(&ctx, gaze, NULL);
        if (r != FOV_OK) { step = "begin_frame"; goto done; }
        r = fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), xt_lp_shade, NULL, xt_lp_rgb,
                             xt_lp_sdep, &shaded);
        if (r != FOV_OK) { step = "shade_rows"; goto done; }
        r = fovlp_reconstruct_rows(&ctx, xt_lp_rgb, xt_lp_sdep, 0, XT_H, xt_lp_img[0], 0,
                                   xt_lp_dep[0]);
        if (r != FOV_OK) { step = "reconstruct_rows"; goto done; }
        if (taa_frames > 0) {
            fovlp_taa_io io;
            io.cur_rgb = xt_lp_img[0]; io.cur_depth = xt_lp_dep[0];
            io.prev_rgb = xt_lp_img[ping]; io.prev_depth = xt_lp_dep[ping]; io.prev_age = xt_lp_age[ping - 1];
            io.out_rgb = xt_lp_img[3 - ping]; io.out_depth = xt_lp_dep[3 - ping]; io.out_age = xt_lp_age[2 - ping];
            r = fovlp_taa_rows(&ctx, &io, 0, XT_H, 0);
            if (r != FOV_OK) { step = "taa_rows"; goto done; }
            ping = 3 - ping;
            out = xt_lp_img[ping];
            dep = xt_lp_dep[ping];
        }
    }
    for (y = 0; y < XT_H; y++)
        for (x = 0; x < XT_W; x++) {
            int c;
            i = y * XT_W + x;
            for (c = 0; c < 3; c++) {
                float v = out[3 * i + (uint32_t)c];
                v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
                xt_rgb[3 * i + (uint32_t)c] = (uint8_t)(v * 255.0f + 0.5f);
            }
            xt_depth[i] = dep[i];
        }
done:
    xt_puts("status "); xt_puti((int32_t)r); xt_putc(' '); xt_puts(step); xt_endl();
    xt_puts("stats evals "); xt_putu(shaded);
    xt_puts(" primary 0 rays 0 hits 0 exhausted 0"); xt_endl();
    xt_dump_image(xt_rgb, xt_hit, xt_depth, XT_W, XT_H);
    xt_puts("end"); xt_endl();
    return (int)r;
}

static int xt_lp_scenes(void)
{
    int s = 0;
    if (xt_lp_scene(20, "lp_cfov", FOVLP_PRESET_C_FOV, 0) != 0) s = 1;
    if (xt_lp_scene(21, "lp_kfov", FOVLP_PRESET_K_FOV, 0) != 0) s = 1;
    if (xt_lp_scene(22, "lp_cfov_taa", FOVLP_PRESET_C_FOV, 4) != 0) s = 1;
    return s;
}
