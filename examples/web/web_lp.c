/* web_lp.c - glue of the browser demo's fovlp module (examples/web): fovlp.h decides where to
   shade (log-polar kernel foveation, a gaze disc, TAA), fovsdf.h shades a built-in scene.
   A frame in the page: every worker calls lp_begin (same gaze, camera and frame), shades the
   log-polar sample rows of its share (lp_shade: fovlp_samples + fovsdf_shade_points) and hands
   the shaded slots back; worker 0 scatters all of them (lp_scatter) and reconstructs, TAAs
   and encodes the whole frame (lp_finish). The full-resolution reference is sdf_render-like:
   lp_reference renders rows with fovsdf_render_rows (the same fovsdf config, 1 spp).
   Not part of the library; the headers are used through their public API only. */
#ifndef WEB_NATIVE_LIBM /* native_bench.c may use libm instead */
#define FOV_NO_LIBM
#endif
#define FOV_ASSERT(c) ((void)0)
#include "web_rt.h"
#define FOVSDF_IMPLEMENTATION
#include "../../fovsdf.h"
#define FOVLP_IMPLEMENTATION
#include "../../fovlp.h"

static struct {
    fovsdf_builtin bi;
    float base_pos[3];
    uint32_t w, h, ignore_gaze, taa, ping;
    fovlp_ctx lp;
    fovsdf_ctx sdf;
    float *samples, *sdepth, *cur, *cdep, *hist[2], *hdep[2];
    uint8_t *age[2];
    uint8_t *rgb8, *rgba, *tint;
    /* lp_shade's output and lp_scatter's input: n slots, then 4 floats (rgb, depth) each */
    uint32_t *io_slot;
    float *io_val;
    fovlp_sample *smp;
    float *tmp_rgb, *tmp_t;
    size_t cap;
    /* the gaze margin: the config without it, the context's memory (sized for the widest
       margin, max_margin), the margin the context has (quantised up to LP_MARGIN_STEP) and
       its gaze disc radius in degrees; has_disc 0: the preset has no disc to widen */
    fovlp_config base;
    void *lp_mem;
    size_t lp_mem_size;
    float max_margin, margin, disc_deg;
    uint32_t has_disc;
} S;

#define LP_MAX_MARGIN 15.0f   /* the gaze filter's default margin cap (max_margin_deg) */
#define LP_MARGIN_STEP 0.25f  /* a new margin re-initialises the context (TAA restarts) */
#define LP_RAD_TO_DEG 57.2957795f

WEB_EXPORT(rgba_ptr) uint8_t *rgba_ptr(void);
uint8_t *rgba_ptr(void) { return S.rgba; }
WEB_EXPORT(lp_io_slot) uint32_t *lp_io_slot(void);
uint32_t *lp_io_slot(void) { return S.io_slot; }
WEB_EXPORT(lp_io_val) float *lp_io_val(void);
float *lp_io_val(void) { return S.io_val; }
WEB_EXPORT(lp_sample_rows_count) uint32_t lp_sample_rows_count(void);
uint32_t lp_sample_rows_count(void) { return fovlp_sample_rows(&S.lp); }
WEB_EXPORT(lp_fov_y) float lp_fov_y(void);
float lp_fov_y(void) { return S.bi.camera.fov_y_deg > 0.0f ? S.bi.camera.fov_y_deg : 60.0f; }
WEB_EXPORT(lp_disc_radius) float lp_disc_radius(void);
float lp_disc_radius(void) { return S.lp.geo.r_g; }

/* scene 0 .. 5, w x h, preset 0 Fov .. 3 C K Fov, taa 0/1; ignore_gaze as in web_sdf.c */
WEB_EXPORT(lp_setup) int lp_setup(uint32_t scene, uint32_t w, uint32_t h, uint32_t preset,
                                  uint32_t taa, uint32_t ignore_gaze);
int lp_setup(uint32_t scene, uint32_t w, uint32_t h, uint32_t preset, uint32_t taa,
             uint32_t ignore_gaze)
{
    size_t bytes = 0, npx, ns;
    void *mem;
    fovlp_config cfg;
    fov_result r;
    int a;
    web_heap_reset();
    memset(&S, 0, sizeof S);
    if (w == 0 || h == 0 || w > 4096 || h > 4096) return FOV_ERR_INVALID_ARG;
    if ((r = fovsdf_builtin_size(scene, &bytes)) != FOV_OK) return r;
    if (!(mem = web_alloc(bytes))) return FOV_ERR_TOO_SMALL;
    if ((r = fovsdf_builtin_init(scene, &S.bi, mem, bytes)) != FOV_OK) return r;
    S.bi.camera.width = w;
    S.bi.camera.height = h;
    memcpy(S.base_pos, S.bi.camera.pos, sizeof S.base_pos);
    cfg = fovlp_config_preset(preset, w, h);
    cfg.cam_fov_y_deg = S.bi.camera.fov_y_deg;
    cfg.taa.enable = taa ? 1u : 0u;
    if ((r = fovlp_memory_size(&cfg, &bytes)) != FOV_OK) return r;
    ns = 0;
    S.base = cfg;
    S.has_disc = cfg.no_disc ? 0u : 1u;
    if (S.has_disc) {   /* the widest margin whose disc still fits: memory and slots for it */
        fovlp_config wide;
        fovlp_geometry geo;
        fov_gaze c;
        float m;
        size_t b2 = 0;
        c.x = 0.5f * (float)w; c.y = 0.5f * (float)h;
        for (m = LP_MAX_MARGIN; m > 0.0f; m -= LP_MARGIN_STEP)
            if (fovlp_config_gaze_margin(&cfg, m, &wide) == FOV_OK &&
                fovlp_geometry_get(&wide, c, &geo) == FOV_OK &&
                fovlp_memory_size(&wide, &b2) == FOV_OK)
                break;
        S.max_margin = m > 0.0f ? m : 0.0f;
        if (S.max_margin > 0.0f) {
            if (b2 > bytes) bytes = b2;
            ns = geo.samples;
        }
        if ((r = fovlp_config_gaze_margin(&cfg, 0.0f, &wide)) != FOV_OK) return r;
        S.disc_deg = wide.gaze_angle * LP_RAD_TO_DEG;
    }
    if (!(mem = web_alloc(bytes ? bytes : 16))) return FOV_ERR_TOO_SMALL;
    if ((r = fovlp_init(&S.lp, &cfg, mem, bytes)) != FOV_OK) return r;
    S.lp_mem = mem;
    S.lp_mem_size = bytes;
    npx = (size_t)w * h;
    if (ns < S.lp.geo.samples) ns = S.lp.geo.samples;
    S.cap = ns;
    S.samples = (float *)web_alloc(ns * 3 * sizeof(float));
    S.sdepth = (float *)web_alloc(ns * sizeof(float));
    S.io_slot = (uint32_t *)web_alloc(ns * sizeof(uint32_t));
    S.io_val = (float *)web_alloc(ns * 4 * sizeof(float));
    S.smp = (fovlp_sample *)web_alloc(ns * sizeof(fovlp_sample));
    S.tmp_rgb = (float *)web_alloc(ns * 3 * sizeof(float));
    S.tmp_t = (float *)web_alloc(ns * sizeof(float));
    S.cur = (float *)web_alloc(npx * 3 * sizeof(float));
    S.cdep = (float *)web_alloc(npx * sizeof(float));
    for (a = 0; a < 2; ++a) {
        S.hist[a] = (float *)web_alloc(npx * 3 * sizeof(float));
        S.hdep[a] = (float *)web_alloc(npx * sizeof(float));
        S.age[a] = (uint8_t *)web_alloc(npx);
        if (!S.hist[a] || !S.hdep[a] || !S.age[a]) return FOV_ERR_TOO_SMALL;
    }
    S.rgb8 = (uint8_t *)web_alloc(npx * 3);
    S.rgba = (uint8_t *)web_alloc(npx * 4);
    S.tint = (uint8_t *)web_alloc(npx);
    if (!S.samples || !S.sdepth || !S.io_slot || !S.io_val || !S.smp || !S.tmp_rgb || !S.tmp_t ||
        !S.cur || !S.cdep || !S.rgb8 || !S.rgba || !S.tint)
        return FOV_ERR_TOO_SMALL;
    S.w = w; S.h = h; S.taa = taa ? 1u : 0u; S.ignore_gaze = ignore_gaze;
    return FOV_OK;
}

/* the frame's gaze, camera and gaze margin, on every worker (fovsdf_init + fovlp_begin_frame).
   margin_deg (>= 0; web_gaze.c) widens the gaze disc through fovlp_config_gaze_margin,
   rounded up to LP_MARGIN_STEP and capped at the widest that fits (lp_setup); a preset
   without a disc (Fov, K Fov) has nothing to widen and ignores it. A new margin
   re-initialises the context (TAA history restarts, as on a gaze jump). */
WEB_EXPORT(lp_begin) int lp_begin(float gx, float gy, float cam_angle, float margin_deg);
int lp_begin(float gx, float gy, float cam_angle, float margin_deg)
{
    fovsdf_config scfg = fovsdf_config_default();
    fovsdf_camera cam;
    fovlp_camera lcam;
    fov_gaze gaze;
    fov_result r;
    float mq;
    if (!S.rgba) return FOV_ERR_NULL;
    if (!(margin_deg >= 0.0f && margin_deg <= 90.0f)) return FOV_ERR_INVALID_ARG;
    mq = 0.0f;
    if (S.has_disc) {
        while (mq < margin_deg && mq < S.max_margin) mq += LP_MARGIN_STEP;
        if (mq > S.max_margin) mq = S.max_margin;
    }
    if (mq < S.margin || mq > S.margin) {
        fovlp_config c = S.base;
        size_t need = 0;
        if (mq > 0.0f && (r = fovlp_config_gaze_margin(&S.base, mq, &c)) != FOV_OK) return r;
        if ((r = fovlp_memory_size(&c, &need)) != FOV_OK) return r;
        if (need > S.lp_mem_size) return FOV_ERR_TOO_SMALL;
        if ((r = fovlp_init(&S.lp, &c, S.lp_mem, S.lp_mem_size)) != FOV_OK) return r;
        if (S.lp.geo.samples > S.cap) return FOV_ERR_TOO_SMALL;
        if ((r = fovlp_config_gaze_margin(&S.base, mq, &c)) != FOV_OK) return r;
        S.margin = mq;
        S.disc_deg = c.gaze_angle * LP_RAD_TO_DEG;
    }
    cam = S.bi.camera;
    if (web_orbit(S.base_pos, cam.target, cam_angle, cam.pos) != 0) return FOV_ERR_INVALID_ARG;
    gaze.x = S.ignore_gaze ? 0.5f * (float)S.w : gx;
    gaze.y = S.ignore_gaze ? 0.5f * (float)S.h : gy;
    if ((r = fovsdf_init(&S.sdf, &scfg, &S.bi.scene, &cam, gaze, NULL, 0)) != FOV_OK) return r;
    if ((r = fovlp_camera_from(&cam, &lcam)) != FOV_OK) return r;
    return fovlp_begin_frame(&S.lp, gaze, &lcam);
}

/* shades the samples of sample rows [r0, r1): their slots into lp_io_slot, rgb and depth
   into lp_io_val (4 floats each). Returns the count (>= 0) or a negative fov_result.
   web_stats: [0] distance evaluations, [1] samples shaded. */
WEB_EXPORT(lp_shade) int lp_shade(uint32_t r0, uint32_t r1);
int lp_shade(uint32_t r0, uint32_t r1)
{
    size_t n = 0, i;
    fovsdf_stats st;
    fov_result r;
    if (!S.rgba) return FOV_ERR_NULL;
    if ((r = fovlp_samples(&S.lp, r0, r1, S.smp, S.cap, &n)) != FOV_OK) return r;
    fovsdf_stats_init(&st);
    if (n > 0 && (r = fovsdf_shade_points(&S.sdf, (uint32_t)n, &S.smp[0].x,
                                          (uint32_t)(sizeof *S.smp / sizeof(float)), S.tmp_rgb,
                                          S.tmp_t, NULL, &st)) != FOV_OK)
        return r;
    for (i = 0; i < n; ++i) {
        S.io_slot[i] = S.smp[i].slot;
        S.io_val[4 * i] = S.tmp_rgb[3 * i];
        S.io_val[4 * i + 1] = S.tmp_rgb[3 * i + 1];
        S.io_val[4 * i + 2] = S.tmp_rgb[3 * i + 2];
        S.io_val[4 * i + 3] = S.tmp_t[i];
    }
    web_stats[0] = (double)st.evals;
    web_stats[1] = (double)n;
    return (int)n;
}

/* n shaded slots from lp_io_slot / lp_io_val into the frame's sample buffers */
WEB_EXPORT(lp_scatter) int lp_scatter(uint32_t n);
int lp_scatter(uint32_t n)
{
    uint32_t i;
    if (!S.rgba) return FOV_ERR_NULL;
    if (n > S.cap) return FOV_ERR_INVALID_ARG;
    for (i = 0; i < n; ++i) {
        size_t s = S.io_slot[i];
        if (s >= S.cap) return FOV_ERR_INVALID_ARG;
        S.samples[3 * s] = S.io_val[4 * i];
        S.samples[3 * s + 1] = S.io_val[4 * i + 1];
        S.samples[3 * s + 2] = S.io_val[4 * i + 2];
        S.sdepth[s] = S.io_val[4 * i + 3];
    }
    return FOV_OK;
}

/* reconstruction, TAA (when on) and sRGB of the whole frame into rgba; overlay 1 tints the
   gaze disc (the pixels shaded at full resolution). web_stats[2]: pixels shaded inside the
   disc; [3]: samples shaded in the frame (fovlp_count_samples); [4] the gaze disc's radius
   (gaze_angle of the config with the margin), degrees (0: no disc). */
WEB_EXPORT(lp_finish) int lp_finish(uint32_t overlay);
int lp_finish(uint32_t overlay)
{
    const float *img = S.cur;
    fovlp_counts cnt;
    fov_result r;
    size_t i, disc = 0;
    float rg2 = S.lp.geo.r_g * S.lp.geo.r_g;
    if (!S.rgba) return FOV_ERR_NULL;
    if ((r = fovlp_reconstruct_rows(&S.lp, S.samples, S.sdepth, 0, S.h, S.cur, 0, S.cdep)) != FOV_OK)
        return r;
    if (S.taa) {
        fovlp_taa_io io;
        fovlp_taa_io_init(&io);
        io.cur_rgb = S.cur; io.cur_depth = S.cdep;
        io.prev_rgb = S.hist[S.ping]; io.prev_depth = S.hdep[S.ping]; io.prev_age = S.age[S.ping];
        io.out_rgb = S.hist[1 - S.ping]; io.out_depth = S.hdep[1 - S.ping]; io.out_age = S.age[1 - S.ping];
        if ((r = fovlp_taa_rows(&S.lp, &io, 0, S.h, NULL)) != FOV_OK) return r;
        S.ping = 1 - S.ping;
        img = S.hist[S.ping];
    }
    if ((r = fovlp_srgb8_rows(&S.lp, img, 0, 0, S.h, S.rgb8, 0, 3)) != FOV_OK) return r;
    for (i = 0; i < (size_t)S.w * S.h; ++i) {
        float dx = (float)(i % S.w) + 0.5f - S.lp.gaze.x, dy = (float)(i / S.w) + 0.5f - S.lp.gaze.y;
        int in = dx * dx + dy * dy < rg2;
        disc += (size_t)in;
        S.tint[i] = (uint8_t)(overlay && in ? 1 : 0);
    }
    web_rgba_rows(S.rgb8, S.rgba, S.tint, S.w, 0, S.h);
    if ((r = fovlp_count_samples(&S.lp, &cnt)) != FOV_OK) return r;
    web_stats[2] = (double)disc;
    web_stats[3] = (double)cnt.shaded;
    web_stats[4] = (double)S.disc_deg;
    return FOV_OK;
}

/* the reference: rows [y0, y1) of the frame at full resolution (fovsdf_render_rows, the same
   fovsdf config, 1 spp at the pixel centres), camera orbited by cam_angle; it does not touch
   the fovlp context (no begin_frame: the TAA history and jitter phase stay as they were).
   web_stats[0] evaluations, [1] rays. */
WEB_EXPORT(lp_reference) int lp_reference(float cam_angle, uint32_t y0, uint32_t y1);
int lp_reference(float cam_angle, uint32_t y0, uint32_t y1)
{
    fovsdf_config scfg = fovsdf_config_default();
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats st;
    fov_gaze gaze;
    fov_result r;
    if (!S.rgba) return FOV_ERR_NULL;
    if (y0 > y1 || y1 > S.h) return FOV_ERR_INVALID_ARG;
    cam = S.bi.camera;
    if (web_orbit(S.base_pos, cam.target, cam_angle, cam.pos) != 0) return FOV_ERR_INVALID_ARG;
    gaze.x = 0.5f * (float)S.w;
    gaze.y = 0.5f * (float)S.h;
    if ((r = fovsdf_init(&ctx, &scfg, &S.bi.scene, &cam, gaze, NULL, 0)) != FOV_OK) return r;
    fovsdf_output_init(&out);
    out.rgb8 = S.rgb8;
    fovsdf_stats_init(&st);
    if ((r = fovsdf_render_rows(&ctx, y0, y1, &out, &st)) != FOV_OK) return r;
    web_rgba_rows(S.rgb8, S.rgba, NULL, S.w, y0, y1);
    web_stats[0] = (double)st.evals;
    web_stats[1] = (double)st.rays;
    return FOV_OK;
}
