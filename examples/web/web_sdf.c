/* web_sdf.c - glue of the browser demo's fovsdf module (examples/web): a built-in scene
   rendered band by band with fovsdf_render_rows, foveated (CONE_FOV or FIPR) or at full
   resolution (CONE, the reference), into an RGBA8 image the page draws.
   Exports: sdf_setup, sdf_render, rgba_ptr, stats_ptr, sdf_fov_y, sdf_fovea_deg.
   The gaze margin (GAZE INPUT) comes with each frame (sdf_render's margin_deg).
   Not part of the library; the headers are used through their public API only. */
#ifndef WEB_NATIVE_LIBM /* native_bench.c may use libm instead */
#define FOV_NO_LIBM
#endif
#define FOV_ASSERT(c) ((void)0)
#include "web_rt.h"
#define FOVSDF_IMPLEMENTATION
#include "../../fovsdf.h"

static struct {
    fovsdf_builtin bi;
    float base_pos[3];
    uint32_t w, h, ignore_gaze;
    uint8_t *rgb8, *rgba, *mask, *tint;
    uint32_t *evals;
} S;

WEB_EXPORT(rgba_ptr) uint8_t *rgba_ptr(void);
uint8_t *rgba_ptr(void) { return S.rgba; }

/* a built-in scene (0 .. 5) at w x h; ignore_gaze 1: every frame foveates at the image centre
   whatever the gaze (the negative control of tests/web). Returns a fov_result. */
WEB_EXPORT(sdf_setup) int sdf_setup(uint32_t scene, uint32_t w, uint32_t h, uint32_t ignore_gaze);
int sdf_setup(uint32_t scene, uint32_t w, uint32_t h, uint32_t ignore_gaze)
{
    size_t bytes = 0, npx;
    void *mem;
    fov_result r;
    web_heap_reset();
    memset(&S, 0, sizeof S);
    if (w == 0 || h == 0 || w > 4096 || h > 4096) return FOV_ERR_INVALID_ARG;
    if ((r = fovsdf_builtin_size(scene, &bytes)) != FOV_OK) return r;
    if (!(mem = web_alloc(bytes))) return FOV_ERR_TOO_SMALL;
    if ((r = fovsdf_builtin_init(scene, &S.bi, mem, bytes)) != FOV_OK) return r;
    S.bi.camera.width = w;
    S.bi.camera.height = h;
    memcpy(S.base_pos, S.bi.camera.pos, sizeof S.base_pos);
    npx = (size_t)w * h;
    S.rgb8 = (uint8_t *)web_alloc(npx * 3);
    S.rgba = (uint8_t *)web_alloc(npx * 4);
    S.mask = (uint8_t *)web_alloc(npx);
    S.tint = (uint8_t *)web_alloc(npx);
    S.evals = (uint32_t *)web_alloc(npx * 4);
    if (!S.rgb8 || !S.rgba || !S.mask || !S.tint || !S.evals) return FOV_ERR_TOO_SMALL;
    S.w = w; S.h = h; S.ignore_gaze = ignore_gaze;
    return FOV_OK;
}

WEB_EXPORT(sdf_fov_y) float sdf_fov_y(void);
float sdf_fov_y(void) { return S.bi.camera.fov_y_deg > 0.0f ? S.bi.camera.fov_y_deg : 60.0f; }
/* the fovea radius (degrees of eccentricity) of the default acuity model */
WEB_EXPORT(sdf_fovea_deg) float sdf_fovea_deg(void);
float sdf_fovea_deg(void) { return fovsdf_acuity_default().fovea_deg; }

/* Rows [y0, y1) of one frame: method 8 CONE_FOV, 7 FIPR (foveated) or 4 CONE (reference), gaze
   (gx, gy) in pixels, the camera orbited by cam_angle radians; overlay 1 tints the pixels that
   traced their own rays (mask 1) and the quarter level (mask 3); margin_deg (>= 0) the gaze
   margin (web_gaze.c), added to the fovea by fovsdf_config_gaze_margin. web_stats: [0] distance
   evaluations, [1] primary rays, [2] pixels that traced their own rays, [3] pixels, [4] the
   fovea radius rendered with (acuity.fovea_deg of the config with the margin), degrees. */
WEB_EXPORT(sdf_render) int sdf_render(uint32_t method, float gx, float gy, float cam_angle,
                                      uint32_t y0, uint32_t y1, uint32_t overlay, uint32_t frame,
                                      float margin_deg);
int sdf_render(uint32_t method, float gx, float gy, float cam_angle, uint32_t y0, uint32_t y1,
               uint32_t overlay, uint32_t frame, float margin_deg)
{
    fovsdf_config cfg = fovsdf_config_default(), wide;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats st;
    fov_gaze gaze;
    fov_result r;
    size_t i, traced = 0;
    if (!S.rgba) return FOV_ERR_NULL;
    if (y0 > y1 || y1 > S.h) return FOV_ERR_INVALID_ARG;
    cfg.method = method;
    cfg.frame = frame;
    if ((r = fovsdf_config_gaze_margin(&cfg, margin_deg, &wide)) != FOV_OK) return r;
    if (margin_deg > 0.0f) cfg = wide;   /* margin 0: the config as before, unresolved */
    cam = S.bi.camera;
    if (web_orbit(S.base_pos, cam.target, cam_angle, cam.pos) != 0) return FOV_ERR_INVALID_ARG;
    gaze.x = S.ignore_gaze ? 0.5f * (float)S.w : gx;
    gaze.y = S.ignore_gaze ? 0.5f * (float)S.h : gy;
    if ((r = fovsdf_init(&ctx, &cfg, &S.bi.scene, &cam, gaze, NULL, 0)) != FOV_OK) return r;
    fovsdf_output_init(&out);
    out.rgb8 = S.rgb8;
    out.mask = S.mask;
    out.evals = S.evals;
    fovsdf_stats_init(&st);
    for (i = (size_t)y0 * S.w; i < (size_t)y1 * S.w; ++i) S.mask[i] = 1;
    if ((r = fovsdf_render_rows(&ctx, y0, y1, &out, &st)) != FOV_OK) return r;
    for (i = (size_t)y0 * S.w; i < (size_t)y1 * S.w; ++i) {
        uint8_t m = S.mask[i];
        traced += m == 1;
        S.tint[i] = (uint8_t)(!overlay ? 0 : m == 1 ? 1 : m == 3 ? 3 : 0);
    }
    web_rgba_rows(S.rgb8, S.rgba, S.tint, S.w, y0, y1);
    web_stats[0] = (double)st.evals;
    web_stats[1] = (double)st.rays;
    web_stats[2] = (double)traced;
    web_stats[3] = (double)((size_t)(y1 - y0) * S.w);
    web_stats[4] = (double)wide.acuity.fovea_deg;
    return FOV_OK;
}
