/* tests/test_fovlp_taa.c - the temporal part of fovlp.h: a still camera converges towards the
   16 spp ground truth and TAA cuts peripheral flicker; a camera moving across a high-contrast
   edge leaves no ghost (near the gaze: none at any frame; in the periphery, where the thesis
   keeps history, none 5 frames after the camera stops); gaze-jump reset, jitter off while
   moving, neighbourhood clamp. Built three ways by tests/run_all.sh.
   "The thesis": K. Andersson, T. Hansson, "Performance Optimizations for Foveated Real-Time
   Raytracing", master's thesis, Lund University, LU-CS-EX 2020-64, 2020. */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVLP_IMPLEMENTATION
#endif
#include "fovlp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fovcheck.h"

#define W 320
#define H 180

typedef struct taa_env {
    fovlp_ctx ctx;
    void *mem;
    float *srgb, *sdep;
    float *cur, *cdep;
    float *hist[2], *hdep[2];
    uint8_t *age[2];
    int ping;
} taa_env;

static void env_init(taa_env *e, const fovlp_config *c)
{
    size_t bytes = 0;
    int i;
    memset(e, 0, sizeof *e);
    fovlp_memory_size(c, &bytes);
    e->mem = malloc(bytes);
    fovlp_init(&e->ctx, c, e->mem, bytes);
    e->srgb = (float *)calloc((size_t)e->ctx.geo.samples * 3u, sizeof(float));
    e->sdep = (float *)calloc((size_t)e->ctx.geo.samples, sizeof(float));
    e->cur = (float *)calloc(W * H * 3, sizeof(float));
    e->cdep = (float *)calloc(W * H, sizeof(float));
    for (i = 0; i < 2; ++i) {
        e->hist[i] = (float *)calloc(W * H * 3, sizeof(float));
        e->hdep[i] = (float *)calloc(W * H, sizeof(float));
        e->age[i] = (uint8_t *)calloc(W * H, 1);
    }
}
static void env_free(taa_env *e)
{
    int i;
    free(e->mem); free(e->srgb); free(e->sdep); free(e->cur); free(e->cdep);
    for (i = 0; i < 2; ++i) { free(e->hist[i]); free(e->hdep[i]); free(e->age[i]); }
}
/* one frame: shade, reconstruct, resolve; returns the TAA output (or the reconstruction when
   TAA is off) */
static const float *frame(taa_env *e, fov_gaze gz, const fovlp_camera *cam, fovlp_shade_fn fn, void *user,
                          fovlp_taa_stats *st)
{
    fovlp_taa_io io;
    fovlp_begin_frame(&e->ctx, gz, cam);
    fovlp_shade_rows(&e->ctx, 0, fovlp_sample_rows(&e->ctx), fn, user, e->srgb, e->sdep, NULL);
    fovlp_reconstruct_rows(&e->ctx, e->srgb, e->sdep, 0, H, e->cur, 0, e->cdep);
    if (!e->ctx.cfg.taa.enable) return e->cur;
    io.cur_rgb = e->cur;
    io.cur_depth = e->cdep;
    io.prev_rgb = e->hist[e->ping];
    io.prev_depth = e->hdep[e->ping];
    io.prev_age = e->age[e->ping];
    io.out_rgb = e->hist[1 - e->ping];
    io.out_depth = e->hdep[1 - e->ping];
    io.out_age = e->age[1 - e->ping];
    fovlp_taa_rows(&e->ctx, &io, 0, H, st);
    e->ping = 1 - e->ping;
    return e->hist[e->ping];
}

/* ---- a still camera --------------------------------------------------------------------- */
static float pattern(float x, float y) { return 0.5f + 0.45f * sinf(x * 0.55f) * sinf(y * 0.45f); }
static void shade_pattern(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)user;
    rgb[0] = rgb[1] = rgb[2] = pattern(x, y);
    if (depth) *depth = 5.0f;
}
static float halton(uint32_t n, uint32_t b)
{
    float f = 1.0f, r = 0.0f;
    while (n) { f /= (float)b; r += f * (float)(n % b); n /= b; }
    return r;
}

static void test_still(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H), cn;
    taa_env e, en;
    fov_gaze gz = { 150.3f, 88.7f };
    float *gt = (float *)malloc(W * H * sizeof(float)), *prev_t = (float *)malloc(W * H * sizeof(float));
    float *prev_r = (float *)malloc(W * H * sizeof(float));
    double se_fov1 = 0, se_fovN = 0, se_all1 = 0, se_allN = 0, fl_taa = 0, fl_raw = 0;
    long n_fov = 0, n_all = 0, n_per = 0;
    float diag = sqrtf((float)(W * W + H * H));
    uint32_t x, y, k, i;
    /* 16 spp ground truth: the box filter over the pixel with Halton(2,3) points 1..16 */
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            float s = 0.0f;
            for (k = 1; k <= 16; ++k) s += pattern((float)x + halton(k, 2), (float)y + halton(k, 3));
            gt[y * W + x] = s / 16.0f;
        }
    c.taa.enable = 1;
    env_init(&e, &c);
    /* the raw jittered frames, no history: TAA on for the jitter, output = reconstruction */
    cn = c;
    env_init(&en, &cn);
    for (k = 0; k < 48; ++k) {
        const float *o = frame(&e, gz, NULL, shade_pattern, NULL, NULL);
        fovlp_begin_frame(&en.ctx, gz, NULL);
        fovlp_shade_rows(&en.ctx, 0, fovlp_sample_rows(&en.ctx), shade_pattern, NULL, en.srgb, NULL, NULL);
        fovlp_reconstruct_rows(&en.ctx, en.srgb, NULL, 0, H, en.cur, 0, NULL);
        for (i = 0; i < W * H; ++i) {
            uint32_t px = i % W, py = i / W;
            float dx = (float)px + 0.5f - gz.x, dy = (float)py + 0.5f - gz.y, r = sqrtf(dx * dx + dy * dy);
            float d = o[3 * i] - gt[i];
            if (k == 0) {
                se_all1 += (double)(d * d);
                if (r < e.ctx.geo.r_g) { se_fov1 += (double)(d * d); n_fov++; }
                n_all++;
            }
            if (k == 47) {
                se_allN += (double)(d * d);
                if (r < e.ctx.geo.r_g) se_fovN += (double)(d * d);
            }
            if (k >= 32 && r > diag / 3.0f) {
                fl_taa += (double)fabsf(o[3 * i] - prev_t[i]);
                fl_raw += (double)fabsf(en.cur[3 * i] - prev_r[i]);
                n_per++;
            }
            prev_t[i] = o[3 * i];
            prev_r[i] = en.cur[3 * i];
        }
    }
    {
        double r1 = sqrt(se_fov1 / (double)n_fov), rN = sqrt(se_fovN / (double)n_fov);
        double a1 = sqrt(se_all1 / (double)n_all), aN = sqrt(se_allN / (double)n_all);
        check(rN < 0.5 * r1, "TAA still: gaze disc RMSE against 16 spp falls below half the single frame's after 48 frames",
              "frame 1 %.4f, frame 48 %.4f", r1, rN);
        check(aN < a1, "TAA still: whole-image RMSE against 16 spp below the single frame's", "frame 1 %.4f, frame 48 %.4f", a1, aN);
        printf("# still camera: RMSE disc %.4f -> %.4f, all %.4f -> %.4f\n", r1, rN, a1, aN);
    }
    check(fl_taa * 4.0 < fl_raw, "TAA still: peripheral flicker (mean |frame-to-frame change| beyond diag/3) cut at least 4x",
          "with TAA %.5f, raw jittered frames %.5f (ratio %.3f)", fl_taa / (double)n_per, fl_raw / (double)n_per,
          fl_raw > 0.0 ? fl_taa / fl_raw : 0.0);
    printf("# flicker with TAA %.5f, without %.5f, ratio %.4f\n", fl_taa / (double)n_per, fl_raw / (double)n_per, fl_taa / fl_raw);
    check(e.ctx.history_valid == 1 && e.ctx.moving == 0, "TAA still: history valid, camera not moving", " ");
    /* a gaze jump resets the history: the output is the current frame */
    {
        fov_gaze far = { 260.0f, 40.0f };
        const float *o = frame(&e, far, NULL, shade_pattern, NULL, NULL);
        check(e.ctx.history_valid == 0 && memcmp(o, e.cur, W * H * 3 * sizeof(float)) == 0,
              "TAA: a gaze jump beyond reset_deg resets the history (output = current frame)", " ");
        o = frame(&e, far, NULL, shade_pattern, NULL, NULL);
        check(e.ctx.history_valid == 1 && memcmp(o, e.cur, W * H * 3 * sizeof(float)) != 0,
              "TAA: the frame after the reset blends again", " ");
    }
    fovlp_reset_history(&e.ctx);
    frame(&e, gz, NULL, shade_pattern, NULL, NULL);
    check(e.ctx.history_valid == 0, "TAA: fovlp_reset_history starts afresh", " ");
    frame(&e, gz, NULL, shade_pattern, NULL, NULL);
    {   /* in-place resolves would read pixels this call already overwrote: refused */
        fovlp_taa_io io;
        int kk, ok = 1;
        for (kk = 0; kk < 4; ++kk) {
            io.cur_rgb = e.cur; io.cur_depth = e.cdep;
            io.prev_rgb = e.hist[e.ping]; io.prev_depth = e.hdep[e.ping]; io.prev_age = e.age[e.ping];
            io.out_rgb = e.hist[1 - e.ping]; io.out_depth = e.hdep[1 - e.ping]; io.out_age = e.age[1 - e.ping];
            if (kk == 0) io.out_rgb = e.cur;
            if (kk == 1) io.out_rgb = e.hist[e.ping];
            if (kk == 2) io.out_depth = e.hdep[e.ping];
            if (kk == 3) io.out_age = e.age[e.ping];
            if (fovlp_taa_rows(&e.ctx, &io, 0, H, NULL) != FOV_ERR_INVALID_ARG) ok = 0;
        }
        check(ok, "TAA: out_rgb / out_depth / out_age aliasing cur_rgb or prev_* is refused", " ");
    }
    env_free(&e);
    env_free(&en);
    free(gt); free(prev_t); free(prev_r);
}

/* ---- a moving camera across a high-contrast edge ------------------------------------------ */
/* A bright bar (x in [-1, 1], z = 8) in front of a dark wall (z = 20); the camera at (cx, 0, 0)
   looks along +z. Depth = distance along the unit ray. */
typedef struct scene3 {
    fovlp_camera cam;
} scene3;
static void ray_dir(const fovlp_camera *c, float x, float y, float d[3])
{
    float sx = (x / (float)W * 2.0f - 1.0f) * c->tan_half_y * ((float)W / (float)H);
    float sy = (y / (float)H * 2.0f - 1.0f) * c->tan_half_y, l;
    int i;
    for (i = 0; i < 3; ++i) d[i] = c->fwd[i] + sx * c->right[i] - sy * c->up[i];
    l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (i = 0; i < 3; ++i) d[i] /= l;
}
static float scene_hit(const fovlp_camera *c, float x, float y, float *depth)
{
    float d[3], t, px;
    ray_dir(c, x, y, d);
    t = (8.0f - c->pos[2]) / d[2];
    px = c->pos[0] + t * d[0];
    if (px >= -1.0f && px <= 1.0f) { *depth = t; return 1.0f; }
    t = (20.0f - c->pos[2]) / d[2];
    *depth = t;
    return 0.1f;
}
static void shade_scene(float x, float y, float rgb[3], float *depth, void *user)
{
    const scene3 *s = (const scene3 *)user;
    float dd;
    rgb[0] = rgb[1] = rgb[2] = scene_hit(&s->cam, x, y, &dd);
    if (depth) *depth = dd;
}
/* screen x of the bar's edges for camera c */
static void bar_edges(const fovlp_camera *c, float *xl, float *xr)
{
    float k = (float)W / 2.0f / (c->tan_half_y * ((float)W / (float)H));
    *xl = (float)W / 2.0f + (-1.0f - c->pos[0]) / 8.0f * k;
    *xr = (float)W / 2.0f + (1.0f - c->pos[0]) / 8.0f * k;
}

/* runs the sequence; ghost counts per frame: near = within diag/3 of the gaze, far = beyond */
static double far_err; /* sum of |out - truth| beyond diag/3 over the moving frames, edge band included */
static void run_moving(const fovlp_config *c, fov_gaze gz, int frames_moving, int frames_still, int *near_ghost, int *far_ghost,
                       int *first_clean, uint32_t *jit_ok)
{
    taa_env e;
    scene3 s;
    float diag = sqrtf((float)(W * W + H * H));
    int f, total = frames_moving + frames_still;
    env_init(&e, c);
    memset(&s, 0, sizeof s);
    s.cam.right[0] = 1.0f; s.cam.up[1] = 1.0f; s.cam.fwd[2] = 1.0f; s.cam.tan_half_y = 0.4f;
    s.cam.pos[0] = -0.6f;
    memset(near_ghost, 0, (size_t)total * sizeof *near_ghost);
    memset(far_ghost, 0, (size_t)total * sizeof *far_ghost);
    *first_clean = -1;
    *jit_ok = 1;
    far_err = 0.0;
    for (f = 0; f < total; ++f) {
        const float *o;
        float xl, xr;
        uint32_t x, y;
        int far_now = 0;
        if (f > 0 && f <= frames_moving) s.cam.pos[0] += 0.12f;
        o = frame(&e, gz, &s.cam, shade_scene, &s, NULL);
        if (f > 0 && f <= frames_moving && !(fabsf(e.ctx.jit_u - 0.5f) < 1e-6f && e.ctx.moving)) *jit_ok = 0;
        bar_edges(&s.cam, &xl, &xr);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float px = (float)x + 0.5f, py = (float)y + 0.5f, dx = px - gz.x, dy = py - gz.y, r = sqrtf(dx * dx + dy * dy);
                float rad, ang, band, dd, truth;
                if (r > diag / 3.0f && f > 0 && f <= frames_moving)
                    far_err += fabs((double)(o[3 * (y * W + x)] - scene_hit(&s.cam, px, py, &dd)));
                fovlp_spacing(&e.ctx, r, &rad, &ang);
                band = 2.0f * fmaxf(rad, ang) + 3.0f; /* reconstruction and history blur of the edge */
                if (fabsf(px - xl) < band || fabsf(px - xr) < band) continue;
                truth = scene_hit(&s.cam, px, py, &dd);
                if (fabsf(o[3 * (y * W + x)] - truth) > 0.1f) {
                    if (r <= diag / 3.0f) { near_ghost[f]++; if (getenv("LPDBG")) printf("  ghost f %d x %u y %u out %g truth %g edges %g %g band %g\n", f, x, y, (double)o[3 * (y * W + x)], (double)truth, (double)xl, (double)xr, (double)band); }
                    else { far_ghost[f]++; far_now = 1; if (getenv("LPDBG")) printf("  far ghost f %d x %u y %u out %g truth %g edges %g %g band %g\n", f, x, y, (double)o[3 * (y * W + x)], (double)truth, (double)xl, (double)xr, (double)band); }
                }
            }
        if (f >= frames_moving && !far_now && *first_clean < 0) *first_clean = f - frames_moving;
        if (far_now) *first_clean = -1;
    }
    env_free(&e);
}

static void test_moving(void)
{
    enum { FM = 14, FS = 10 };
    int near_g[FM + FS], far_g[FM + FS], clean, f, near_sum = 0, far_moving = 0;
    uint32_t jit_ok;
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    fov_gaze centre = { 160.0f, 90.0f }, side = { 10.0f, 90.0f };
    c.taa.enable = 1;
    run_moving(&c, centre, FM, FS, near_g, far_g, &clean, &jit_ok);
    for (f = 1; f < FM + FS; ++f) near_sum += near_g[f];
    check(near_sum == 0, "TAA moving: no ghost (|out - truth| > 0.1 outside the edge band) within diag/3 of the gaze at any frame",
          "%d ghost pixel-frames", near_sum);
    /* the gaze at the left border: the bar lies beyond diag/3, where history is kept */
    {
        fovlp_config craw = c;
        int far_default = 0;
        double e_raw, e_def, e_off;
        craw.taa.thesis_moving = 1;
        run_moving(&craw, side, FM, FS, near_g, far_g, &clean, &jit_ok);
        for (f = 1; f <= FM; ++f) far_moving += far_g[f];
        check(far_moving > 0 && clean >= 0 && clean <= 5,
              "TAA moving, thesis_moving (the thesis's rule: history kept, age reset): peripheral ghosts gone within 5 frames after the camera stops",
              "clean after %d frames (-1: never); peripheral ghost pixel-frames while moving %d", clean, far_moving);
        printf("# moving, thesis's periphery rule: peripheral ghost pixel-frames while moving %d, clean %d frames after the stop\n",
               far_moving, clean);
        e_raw = far_err;
        run_moving(&c, side, FM, FS, near_g, far_g, &clean, &jit_ok);
        for (f = 1; f < FM + FS; ++f) far_default += far_g[f] + near_g[f];
        e_def = far_err;
        craw.taa.enable = 0;
        run_moving(&craw, side, FM, FS, near_g, far_g, &clean, &jit_ok);
        e_off = far_err;
        printf("# moving, gaze at the border: |out - truth| summed beyond diag/3: no TAA %.1f, thesis's rule %.1f, default %.1f\n", e_off, e_raw, e_def);
        check(e_raw > 1.5 * e_off, "TAA moving, thesis_moving: control: the thesis's history ghosts beyond diag/3 (error > 1.5x no TAA)",
              "%.1f vs %.1f", e_raw, e_off);
        check(e_def < 1.1 * e_off, "TAA moving, default: error beyond diag/3 within 10 % of no TAA (no ghost)", "%.1f vs %.1f", e_def, e_off);
        check(far_default == 0, "TAA moving, default (history variance-clipped while moving): no ghost at any frame",
              "%d ghost pixel-frames (thesis's rule: %d)", far_default, far_moving);
    }
    check(jit_ok != 0, "TAA moving: jitter off while the camera moves (thesis)", " ");
    /* teeth: without depth rejection (huge tolerance) and without clamping the bar ghosts */
    {
        fovlp_config c2 = c;
        int ng[FM + FS], fg[FM + FS], cl, sum = 0;
        c2.taa.depth_tol = 1e9f;
        c2.taa.thesis_moving = 1; /* the clamps below only as asked for */
        run_moving(&c2, centre, FM, FS, ng, fg, &cl, &jit_ok);
        for (f = 1; f <= FM; ++f) sum += ng[f];
        check(sum > 100, "TAA moving: control: with depth rejection disabled the bar does ghost near the gaze", "%d", sum);
        c2.taa.clamp = FOVLP_CLAMP_AABB;
        run_moving(&c2, centre, FM, FS, ng, fg, &cl, &jit_ok);
        sum = 0;
        for (f = 1; f <= FM; ++f) sum += ng[f];
        check(sum == 0, "TAA moving: the YCoCg neighbourhood clamp alone removes the ghost near the gaze", "%d", sum);
        c2.taa.clamp = FOVLP_CLAMP_VARIANCE;
        run_moving(&c2, centre, FM, FS, ng, fg, &cl, &jit_ok);
        sum = 0;
        for (f = 1; f <= FM; ++f) sum += ng[f];
        check(sum == 0, "TAA moving: variance clipping alone removes the ghost near the gaze", "%d", sum);
    }
}

/* the age rule: 1/age blend, capped at max_age */
static void test_age(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    taa_env e;
    fov_gaze gz = { 160.0f, 90.0f };
    int k, ok = 1;
    c.taa.enable = 1;
    c.taa.max_age = 5;
    env_init(&e, &c);
    for (k = 1; k <= 8; ++k) {
        frame(&e, gz, NULL, shade_pattern, NULL, NULL);
        if (e.age[e.ping][W * 90 + 160] != (uint8_t)(k < 5 ? k : 5)) ok = 0;
    }
    check(ok, "TAA: age counts 1, 2, 3, ... and stops at max_age", "age %u", (unsigned)e.age[e.ping][W * 90 + 160]);
    env_free(&e);
}

/* ---- a caller's shading that returns NaN / inf now and then ---------------------------- */
typedef struct bad_shade { int frame; } bad_shade;
static void shade_bad(float x, float y, float rgb[3], float *depth, void *user)
{
    const bad_shade *b = (const bad_shade *)user;
    volatile float zero = 0.0f;
    rgb[0] = rgb[1] = rgb[2] = 0.5f;
    if (depth) *depth = 2.0f;
    if ((b->frame == 0 || b->frame == 10) && fabsf(x - 160.5f) < 1.0f && fabsf(y - 90.5f) < 1.0f) rgb[1] = zero / zero;
    if (b->frame == 20 && x < 40.0f && y < 30.0f) rgb[2] = 1.0f / zero;   /* a peripheral inf */
    if (b->frame == 25 && depth && x > 280.0f) *depth = zero / zero;      /* NaN depths */
}
static void test_bad_samples(void)
{
    uint32_t clamp;
    for (clamp = 0; clamp < 3; ++clamp) {
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
        taa_env e;
        fov_gaze gz = { 160.0f, 90.0f };
        bad_shade b;
        int nonfinite = 0;
        uint32_t i, far = 0;
        double worst = 0.0;
        c.taa.enable = 1;
        c.taa.clamp = clamp;
        env_init(&e, &c);
        for (b.frame = 0; b.frame < 40; ++b.frame) {
            const float *o = frame(&e, gz, NULL, shade_bad, &b, NULL);
            for (i = 0; i < W * H * 3; ++i) {
                if (!isfinite(o[i])) nonfinite++;
                if (b.frame == 39) {
                    double d = fabs((double)o[i] - 0.5);
                    if (d > worst) worst = d;
                    if (d > 1e-3) far++;
                }
            }
        }
        printf("# clamp %u: non-finite %d, worst %.5f, off %u\n", clamp, nonfinite, worst, far);
        check(nonfinite == 0 && worst < 0.05 && far < 16,
              "TAA: NaN / inf colours and NaN depths from the shading never reach the output and fade (clamp none, aabb, variance)",
              "clamp %u: %d non-finite values over 40 frames; frame 39: worst |out - 0.5| %.4f, %u values off by > 1e-3",
              clamp, nonfinite, worst, far);
        env_free(&e);
    }
}

#ifdef FOV_NO_LIBM
#define MODE "FOV_NO_LIBM"
#else
#define MODE "libm"
#endif

/* a still camera in the gaze disc: after exactly `phases` frames each disc pixel is the box
   estimate of its pixel with the 16 jittered points (eq. 3.11: Halton (2, 3) 1..16 scaled so
   that their mean is 1/2), computed here independently of the library */
static void test_disc_converges(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    taa_env e;
    fov_gaze gz = { 161.0f, 92.0f };
    float sx = 0.0f, sy = 0.0f, worst = 0.0f, diff16 = 0.0f;
    uint32_t k, x, y, n = 0;
    const float *o = NULL;
    c.taa.enable = 1;
    env_init(&e, &c);
    for (k = 1; k <= 16; ++k) { sx += halton(k, 2); sy += halton(k, 3); }
    sx = 0.5f / (sx / 16.0f);
    sy = 0.5f / (sy / 16.0f);
    for (k = 0; k < 16; ++k) o = frame(&e, gz, NULL, shade_pattern, NULL, NULL);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            float dx = (float)x + 0.5f - gz.x, dy = (float)y + 0.5f - gz.y, acc = 0.0f, first;
            if (dx * dx + dy * dy > (e.ctx.geo.r_g - 2.0f) * (e.ctx.geo.r_g - 2.0f)) continue;
            for (k = 1; k <= 16; ++k) acc += pattern((float)x + halton(k, 2) * sx, (float)y + halton(k, 3) * sy);
            acc /= 16.0f;
            worst = fmaxf(worst, fabsf(o[3 * (y * W + x)] - acc));
            first = pattern((float)x + 0.5f, (float)y + 0.5f); /* control: the pixel centre alone */
            diff16 = fmaxf(diff16, fabsf(first - acc));
            n++;
        }
    check(n > 1000 && worst < 2e-5f && diff16 > 100.0f * worst,
          "TAA still: after 16 frames each disc pixel is the mean of its 16 scaled Halton points (1/age blend, no clamp)",
          "%u pixels, worst %g (centre sample differs by %g)", n, (double)worst, (double)diff16);
    env_free(&e);
}

/* review item: the per-frame latency margin (fovlp_set_gaze_margin) keeps the TAA history; a
   per-frame fovlp_init with fovlp_config_gaze_margin (the old recipe) loses it every frame */
static void test_gaze_margin_keeps_history(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H), room, b;
    taa_env e;
    fovlp_ctx saved;
    fov_gaze gz = { 150.0f, 90.0f };
    fovlp_geometry g0;
    uint32_t k, valid = 0, age_gz;
    int sizes_same = 1, r_ok = 1, rc_ok = 1;
    float m;
    c.taa.enable = 1;
    check(fovlp_config_gaze_margin(&c, 15.0f, &room) == FOV_OK, "margin: room config", "-");
    env_init(&e, &room);
    g0 = e.ctx.geo;
    fovlp_config_resolve(&c, &b);
    for (k = 0; k < 12; ++k) {
        float q, want;
        m = 0.6f + 0.9f * (float)(k % 5); /* 0.6 .. 4.2 degrees, changing every frame */
        if (fovlp_set_gaze_margin(&e.ctx, &c, m) != FOV_OK) rc_ok = 0;
        frame(&e, gz, NULL, shade_pattern, NULL, NULL);
        if (k > 0 && e.ctx.history_valid) valid++;
        if (e.ctx.geo.lp_w != g0.lp_w || e.ctx.geo.lp_h != g0.lp_h ||
            e.ctx.geo.samples != g0.samples)
            sizes_same = 0;
        /* worked out: the disc of base + m rounded up to 0.25 degrees, f tan(angle) */
        q = ceilf(m / 0.25f) * 0.25f;
        want = e.ctx.geo.f_px * tanf(b.gaze_angle + q * 0.017453292f);
        if (!(fabsf(e.ctx.geo.r_g - want) <= 1e-3f * want)) r_ok = 0;
    }
    age_gz = e.age[e.ping][(uint32_t)gz.y * W + (uint32_t)gz.x];
    check(rc_ok && valid == 11u && e.ctx.frame == 12u,
          "margin: fovlp_set_gaze_margin every frame keeps the TAA history",
          "rc %d valid %u frame %u", rc_ok, valid, e.ctx.frame);
    check(age_gz >= 10u, "margin: the gaze pixel's history age grows", "age %u", age_gz);
    check(sizes_same, "margin: the context's sizes never change", "-");
    check(r_ok, "margin: disc = base + margin rounded up to 0.25 degrees", "r_g %g",
          (double)e.ctx.geo.r_g);
    /* beyond the room: clamped to the context's disc, FOV_OK */
    check(fovlp_set_gaze_margin(&e.ctx, &c, 40.0f) == FOV_OK &&
          e.ctx.disc_angle >= room.gaze_angle && e.ctx.disc_angle <= room.gaze_angle,
          "margin: beyond the room clamped to it", "%g", (double)e.ctx.disc_angle);
    /* errors leave the context as it was */
    saved = e.ctx;
    check(fovlp_set_gaze_margin(&e.ctx, &c, -1.0f) == FOV_ERR_INVALID_ARG &&
          memcmp(&saved, &e.ctx, sizeof saved) == 0, "margin: negative rejected, ctx unchanged",
          "-");
    check(fovlp_set_gaze_margin(&e.ctx, &c, (float)NAN) == FOV_ERR_NOT_FINITE &&
          memcmp(&saved, &e.ctx, sizeof saved) == 0, "margin: NaN rejected, ctx unchanged", "-");
    check(fovlp_set_gaze_margin(&e.ctx, &room, 0.0f) == FOV_OK, "margin: base = room ok", "-");
    b = c; b.gaze_angle = room.gaze_angle + 0.01f;
    saved = e.ctx;
    check(fovlp_set_gaze_margin(&e.ctx, &b, 0.0f) == FOV_ERR_INVALID_ARG &&
          memcmp(&saved, &e.ctx, sizeof saved) == 0, "margin: base above the room rejected",
          "-");
    b = c; b.no_disc = 1;
    check(fovlp_set_gaze_margin(&e.ctx, &b, 1.0f) == FOV_ERR_UNSUPPORTED,
          "margin: no_disc unsupported", "-");
    /* control: the old recipe (fovlp_init with a new config each frame) never has history */
    {
        fovlp_config cf;
        fovlp_config_gaze_margin(&c, 0.6f, &cf);
        {
            size_t bytes = 0;
            void *mem2;
            fovlp_ctx c2;
            fovlp_memory_size(&cf, &bytes);
            mem2 = malloc(bytes);
            valid = 0;
            for (k = 0; k < 4; ++k) {
                fovlp_init(&c2, &cf, mem2, bytes);
                fovlp_begin_frame(&c2, gz, NULL);
                if (c2.history_valid) valid++;
            }
            check(valid == 0u, "margin: control, a per-frame fovlp_init has no history", "%u",
                  valid);
            free(mem2);
        }
    }
    env_free(&e);
}

/* review item: an off-axis camera (fovlp_camera_from of a fov_camera with tangents) is
   reprojected with its own tangents when config.taa.frustum is left 0: the same output bit
   for bit as with config.taa.frustum set, and not the symmetric reprojection's; a camera
   whose tangents differ from config.taa.frustum is rejected by begin_frame */
typedef struct offcam { fovlp_camera c; } offcam;
static void shade_off(float x, float y, float rgb[3], float *depth, void *user)
{
    const fovlp_camera *c = &((const offcam *)user)->c;
    float sx = -c->tan4[0] + (c->tan4[0] + c->tan4[1]) * (x / (float)W);
    float sy = -c->tan4[3] + (c->tan4[2] + c->tan4[3]) * (y / (float)H);
    float d[3], l, t, px, py;
    int i;
    for (i = 0; i < 3; ++i) d[i] = c->fwd[i] + sx * c->right[i] - sy * c->up[i];
    l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (i = 0; i < 3; ++i) d[i] /= l;
    t = (10.0f - c->pos[2]) / d[2]; /* the plane z = 10 */
    px = c->pos[0] + t * d[0]; py = c->pos[1] + t * d[1];
    rgb[0] = rgb[1] = rgb[2] = 0.5f + 0.4f * sinf(1.1f * px) * cosf(0.9f * py);
    if (depth) *depth = t;
}
static void run_off(const fovlp_config *c, int sym, float *out, uint32_t *rejected,
                    double *err_out)
{
    taa_env e;
    fov_camera fc;
    offcam oc;
    fov_gaze gz = { 170.0f, 80.0f };
    fovlp_taa_stats st;
    int f;
    env_init(&e, c);
    memset(&fc, 0, sizeof fc);
    fc.target[2] = 1.0f; fc.up[1] = 1.0f; fc.width = W; fc.height = H;
    fc.tan_left = 1.2f; fc.tan_right = 0.8f; fc.tan_bottom = 0.6f; fc.tan_top = 0.525f;
    fovlp_taa_stats_init(&st);
    for (f = 0; f < 6; ++f) {
        fovlp_camera lc;
        fc.pos[2] = 0.4f * (float)f; fc.target[2] = fc.pos[2] + 1.0f; /* towards the plane */
        fovlp_camera_from(&fc, &lc);
        oc.c = lc; /* the scene is shaded through the true (off-axis) camera */
        if (sym) memset(lc.tan4, 0, sizeof lc.tan4); /* what the reprojection used to get */
        frame(&e, gz, &lc, shade_off, &oc, f == 5 ? &st : NULL);
    }
    memcpy(out, e.hist[e.ping], sizeof(float) * W * H * 3);
    *rejected = (uint32_t)st.rejected;
    { /* mean error against the true image of the last camera at the pixel centres */
        double err = 0.0;
        uint32_t i;
        for (i = 0; i < W * H; ++i) {
            float t[3];
            shade_off((float)(i % W) + 0.5f, (float)(i / W) + 0.5f, t, NULL, &oc);
            err += fabs((double)out[3 * i] - (double)t[0]);
        }
        *err_out = err / (double)(W * H);
    }
    env_free(&e);
}
static void test_off_axis_camera(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H), cf;
    float *a = (float *)malloc(sizeof(float) * W * H * 3), *b = (float *)malloc(sizeof(float) * W * H * 3);
    float *s = (float *)malloc(sizeof(float) * W * H * 3);
    uint32_t ra, rb, rs;
    double ea, eb, es;
    c.taa.enable = 1;
    cf = c;
    cf.taa.frustum[0] = 1.2f; cf.taa.frustum[1] = 0.8f; cf.taa.frustum[2] = 0.6f;
    cf.taa.frustum[3] = 0.525f;
    run_off(&c, 0, a, &ra, &ea);  /* frustum left 0: the camera's tangents */
    run_off(&cf, 0, b, &rb, &eb); /* frustum set */
    run_off(&c, 1, s, &rs, &es);  /* the symmetric reprojection (tangents dropped) */
    check(memcmp(a, b, sizeof(float) * W * H * 3) == 0 && ra == rb,
          "off-axis camera: its own tangents = config.taa.frustum, bit for bit",
          "rejected %u vs %u", ra, rb);
    fovcheck_info("off-axis TAA: mean error own tangents %.4f, symmetric %.4f (rejected %u, %u)",
                  ea, es, ra, rs);
    check(memcmp(a, s, sizeof(float) * W * H * 3) != 0 && es > 1.5 * ea,
          "off-axis camera: the symmetric reprojection differs and is further from the truth",
          "error %g (own) vs %g (symmetric)", ea, es);
    {
        taa_env e;
        fov_camera fc;
        fovlp_camera lc;
        fov_gaze gz = { 170.0f, 80.0f };
        fovlp_config cm = cf;
        cm.taa.frustum[0] = 1.0f; cm.taa.frustum[1] = 1.0f; /* another frustum, same aspect */
        env_init(&e, &cm);
        check(e.ctx.rho != NULL, "off-axis camera: context with another frustum", "-");
        memset(&fc, 0, sizeof fc);
        fc.target[2] = 1.0f; fc.up[1] = 1.0f; fc.width = W; fc.height = H;
        fc.tan_left = 1.2f; fc.tan_right = 0.8f; fc.tan_bottom = 0.6f; fc.tan_top = 0.525f;
        fovlp_camera_from(&fc, &lc);
        check(fovlp_begin_frame(&e.ctx, gz, &lc) == FOV_ERR_INVALID_ARG,
              "off-axis camera: tangents != config.taa.frustum rejected", "-");
        lc.tan4[0] = -5.0f;
        check(fovlp_begin_frame(&e.ctx, gz, &lc) == FOV_ERR_INVALID_ARG,
              "off-axis camera: bad tan4 rejected", "-");
        lc.tan4[0] = (float)NAN;
        check(fovlp_begin_frame(&e.ctx, gz, &lc) == FOV_ERR_NOT_FINITE,
              "off-axis camera: NaN tan4 rejected", "-");
        env_free(&e);
    }
    free(a); free(b); free(s);
}

int main(void)
{
    printf("# fovlp.h TAA tests (%s)\n", MODE);
    test_still();
    test_disc_converges();
    test_moving();
    test_age();
    test_bad_samples();
    test_gaze_margin_keeps_history();
    test_off_axis_camera();
    return fovcheck_summary();
}
