/*
 * test_fovpt_points.c - fovpt_shade_points (path tracing at arbitrary image points) and the
 * log-polar pipeline of examples/lp_pt.c (fovlp.h decides where, fovpt.h shades, fovlp.h
 * reconstructs with TAA).
 *
 * Build and run from the repository root (tests/run_all.sh builds it three ways):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovpt_points.c -lm -o build/tests/t
 *
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed".
 * Independent checks: every point's colour is recomputed here through the public one-ray calls
 * the documentation names (fovpt_rng_init, fovpt_camera_ray, fovpt_radiance, the mean in
 * sample order) and its depth by fovpt_intersect; the constant scenes' expected colour is the
 * emission or background the test sets. Bad input: the codes and the logger's codes.
 */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVPT_IMPLEMENTATION
#endif
#include "fovpt.h"
#ifndef FOV_TEST_LINK_IMPL
#define FOVLP_IMPLEMENTATION
#endif
#include "fovlp.h"
#include "fovcheck.h"
#include "examples/pt_scenes.h"
#include "examples/lp_pt_shade.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

static int g_log_count;
static int32_t g_log_code;
static void logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                   void *user)
{
    (void)tag; (void)level; (void)line; (void)user; (void)msg;
    g_log_count++;
    g_log_code = code;
}

static int same_bits(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* point i, sample k: the documented recipe through the public one-ray calls */
static void reference_point(const fovpt_scene *s, const fovpt_config *c, const fovpt_camera *cam,
                            float x, float y, float jitter, uint32_t id, uint32_t frame, uint32_t spp,
                            float rgb[3], float *t)
{
    float org[3], dir[3], sum[3] = { 0.0f, 0.0f, 0.0f };
    uint32_t k;
    fovpt_hit h;
    for (k = 0; k < spp; ++k) {
        fovpt_rng rng;
        float c3[3], px = x, py = y;
        fovpt_rng_init(&rng, c->seed, id, k, frame);
        if (jitter > 0.0f) {
            px += (fovpt_rng_next(&rng) - 0.5f) * jitter;
            py += (fovpt_rng_next(&rng) - 0.5f) * jitter;
        }
        fovpt_camera_ray(cam, px, py, org, dir);
        fovpt_radiance(s, c, org, dir, &rng, c3, NULL);
        sum[0] += c3[0]; sum[1] += c3[1]; sum[2] += c3[2];
        if (k == 0) *t = fovpt_intersect(s, org, dir, 0.0f, FLT_MAX, &h) ? h.t : FLT_MAX;
    }
    rgb[0] = sum[0] / (float)spp; rgb[1] = sum[1] / (float)spp; rgb[2] = sum[2] / (float)spp;
}

static void test_equals_reference(void)
{
    pt_scene S;
    fovpt_config c = fovpt_config_default();
    /* pixel centres, corners of pixels, sub-pixel points, off the image, the mirror sphere */
    float xy[2 * 12] = { 80.5f, 60.5f, 0.0f, 0.0f, 159.99f, 119.99f, 33.25f, 71.75f,
                         -20.0f, 50.0f, 200.0f, -10.0f, 57.0f, 31.3f, 100.1f, 90.9f,
                         3.5f, 118.5f, 120.0f, 20.0f, 66.6f, 66.6f, 140.0f, 100.0f };
    float rgb[3 * 12], t[12], rgb2[3 * 12], t2[12];
    uint32_t n = 12, i, mode, bad = 0, badt = 0;
    fovpt_stats st;
    if (!check(pt_scene_make(&S, PT_SCENE_CORNELL) == 0, "cornell scene builds", "pt_scene_make")) return;
    S.cam.width = 160; S.cam.height = 120;
    for (mode = 0; mode < 3; ++mode) {
        /* path tracing at the points, Whitted at the points, path tracing jittered over 1.5 px */
        uint32_t spp = mode == 1 ? 1u : 3u, first = mode == 1 ? 7u : 1000u, frame = mode == 1 ? 0u : 5u;
        float jit = mode == 2 ? 1.5f : 0.0f;
        const char *lbl = mode == 0 ? "path" : mode == 1 ? "whitted" : "path, jitter 1.5";
        bad = badt = 0;
        c = fovpt_config_default();
        c.mode = mode == 1 ? FOVPT_MODE_WHITTED : FOVPT_MODE_PATH;
        c.seed = 99u;
        c.sampler = FOVPT_SAMPLER_RANDOM; /* the fovpt_rng_init recipe (SOBOL's: test_fovpt_sampler.c) */
        fovpt_config_resolve(&c, &c);
        fovpt_stats_init(&st);
        if (!check(fovpt_shade_points(&S.scene, &c, &S.cam, n, xy, 0, first, frame, spp, jit, rgb, t, &st) == FOV_OK,
                   N("shade_points %s FOV_OK", lbl), "error"))
            continue;
        for (i = 0; i < n; ++i) {
            float ref[3], tr;
            reference_point(&S.scene, &c, &S.cam, xy[2 * i], xy[2 * i + 1], jit, first + i, frame, spp, ref, &tr);
            if (!same_bits(rgb[3 * i], ref[0]) || !same_bits(rgb[3 * i + 1], ref[1]) || !same_bits(rgb[3 * i + 2], ref[2])) bad++;
            if (!(same_bits(t[i], tr) || (tr < FLT_MAX && fabsf(t[i] - tr) <= 1e-6f * tr))) {
                badt++;
                printf("INFO point (%g, %g): depth %.9g, fovpt_intersect %.9g\n", (double)xy[2 * i], (double)xy[2 * i + 1], (double)t[i], (double)tr);
            }
        }
        check(bad == 0, N("%s: colours bit for bit camera_ray + radiance on stream (seed, first + i, k, frame)", lbl),
              "%u of %u differ", bad, n);
        check(badt == 0, N("%s: depth = fovpt_intersect's t of the camera ray within 1e-6 (FLT_MAX: miss)", lbl),
              "%u of %u differ", badt, n);
        check(st.samples == (uint64_t)n * spp && st.camera_rays == (uint64_t)n * spp &&
              st.rays == st.camera_rays + st.bounce_rays + st.shadow_rays && st.bounce_rays + st.shadow_rays > 0,
              N("%s: stats samples = camera_rays = n spp, rays = the sum", lbl),
              "samples %llu camera %llu rays %llu", (unsigned long long)st.samples, (unsigned long long)st.camera_rays,
              (unsigned long long)st.rays);
        /* a split batch with `first` continuing the numbering gives the same values */
        if (fovpt_shade_points(&S.scene, &c, &S.cam, 5, xy, 2, first, frame, spp, jit, rgb2, t2, NULL) == FOV_OK &&
            fovpt_shade_points(&S.scene, &c, &S.cam, n - 5, xy + 10, 0, first + 5, frame, spp, jit, rgb2 + 15, t2 + 5, NULL) == FOV_OK)
            check(memcmp(rgb, rgb2, sizeof rgb) == 0 && memcmp(t, t2, sizeof t) == 0,
                  N("%s: two batches (first = 0, 5) equal one", lbl), "differ");
        else
            check(0, N("%s: split batches", lbl), "error");
        bad = 0;
        for (i = 0; i < 3 * n; ++i) bad += !(rgb[i] >= 0.0f && rgb[i] <= FLT_MAX);
        check(bad == 0, N("%s: colours finite, >= 0", lbl), "%u bad", bad);
    }
    /* a strided array (fovlp_sample layout: x, y, slot) gives the same as packed points */
    {
        float s3[3 * 12];
        c = fovpt_config_default();
        for (i = 0; i < n; ++i) { s3[3 * i] = xy[2 * i]; s3[3 * i + 1] = xy[2 * i + 1]; s3[3 * i + 2] = -1.0f; }
        fovpt_shade_points(&S.scene, &c, &S.cam, n, xy, 2, 3, 1, 2, 0.0f, rgb, t, NULL);
        fovpt_shade_points(&S.scene, &c, &S.cam, n, s3, 3, 3, 1, 2, 0.0f, rgb2, NULL, NULL);
        check(memcmp(rgb, rgb2, sizeof rgb) == 0, "stride 3 (x, y, slot) equals stride 2", "differ");
        /* spp 0 takes cfg.spp; other frames and seeds change the noise */
        c.spp = 2;
        fovpt_shade_points(&S.scene, &c, &S.cam, n, xy, 2, 3, 1, 0, 0.0f, rgb2, NULL, NULL);
        check(memcmp(rgb, rgb2, sizeof rgb) == 0, "spp 0 takes cfg.spp", "differ");
        fovpt_shade_points(&S.scene, &c, &S.cam, n, xy, 2, 3, 2, 2, 0.0f, rgb2, NULL, NULL);
        check(memcmp(rgb, rgb2, sizeof rgb) != 0, "another frame: other streams", "identical");
    }
    pt_scene_free(&S);
}

/* jitter 1 at pixel centres, first = y W for row y: UNIFORM's pixels, fovpt_render's own
   image bit for bit (its jitter, streams, path and mean); also with clamp_white set (UNIFORM
   does not clamp and shade_points does not read it; the Cornell light is above 1, so a
   clamp in either would show); also with cfg.robust (the same robust estimate from the same
   samples; 32 spp in 4 groups, which must change some pixels of the plain mean: the Cornell
   box's mirror caustic) */
static void test_equals_uniform(void)
{
    pt_scene S;
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output out;
    const uint32_t W = 48, H = 36;
    size_t bytes = 0;
    void *mem;
    float *img = (float *)malloc((size_t)W * H * 12u), *row = (float *)malloc(W * 12u), *xy = (float *)malloc(W * 8u);
    uint32_t x, y, bad = 0, mode, changed = 0;
    if (!img || !row || !xy || pt_scene_make(&S, PT_SCENE_CORNELL) != 0) { check(0, "uniform: setup", "failed"); free(img); free(row); free(xy); return; }
    S.cam.width = W; S.cam.height = H;
    for (mode = 0; mode < 4; ++mode) {
        fov_gaze g;
        g.x = 20.0f; g.y = 10.0f;
        c = fovpt_config_default();
        c.spp = 3; c.seed = 4242u; c.mode = mode == 1 ? FOVPT_MODE_WHITTED : FOVPT_MODE_PATH;
        if (mode == 2) c.layers.clamp_white = c.zones.clamp_white = 1.0f;
        if (mode == 3) { c.spp = 32; c.robust = 4; }
        fovpt_config_resolve(&c, &c);
        bad = 0;
        fovpt_memory_size(&c, &S.cam, &bytes);
        mem = malloc(bytes);
        fovpt_output_init(&out);
        out.rgb = img;
        if (fovpt_init(&ctx, &c, &S.scene, &S.cam, g, mem, bytes) != FOV_OK || fovpt_render(&ctx, 6, &out, NULL) != FOV_OK) {
            check(0, "uniform: fovpt_render", "failed");
            free(mem);
            continue;
        }
        for (y = 0; y < H; ++y) {
            for (x = 0; x < W; ++x) { xy[2 * x] = (float)x + 0.5f; xy[2 * x + 1] = (float)y + 0.5f; }
            if (fovpt_shade_points(&S.scene, &c, &S.cam, W, xy, 0, y * W, 6, 0, 1.0f, row, NULL, NULL) != FOV_OK) { bad += W; continue; }
            for (x = 0; x < 3 * W; ++x) bad += !same_bits(row[x], img[3 * (size_t)y * W + x]);
            if (mode == 3) { /* the plain mean of the same samples */
                c.robust = 0;
                if (fovpt_shade_points(&S.scene, &c, &S.cam, W, xy, 0, y * W, 6, 0, 1.0f, row, NULL, NULL) != FOV_OK) bad += W;
                for (x = 0; x < 3 * W; ++x) changed += !same_bits(row[x], img[3 * (size_t)y * W + x]);
                c.robust = 4;
            }
        }
        check(bad == 0 && (mode < 3 || changed > 0), N("%s: jitter 1 at pixel centres, first = y W: fovpt_render's UNIFORM image bit for bit",
                mode == 0 ? "path" : mode == 1 ? "whitted" : mode == 2 ? "path, clamp_white 1" : "path, robust 4 at 32 spp (some pixels not the plain mean)"),
              "%u of %u values differ (robust: %u differ from the plain mean)", bad, 3 * W * H, changed);
        free(mem);
    }
    pt_scene_free(&S);
    free(img); free(row); free(xy);
}

static void test_errors(void)
{
    pt_scene S;
    fovpt_config c = fovpt_config_default();
    fovpt_camera cam;
    float xy[4] = { 10.0f, 10.0f, 20.0f, 20.0f }, rgb[6], t[2];
    float nanv = (float)NAN;
    fov_result r;
    int k, unchanged;
    if (pt_scene_make(&S, PT_SCENE_CORNELL) != 0) { check(0, "errors: scene", "build"); return; }
    S.cam.width = 64; S.cam.height = 48;
    c.logger.func = logger;
    check(fovpt_shade_points(&S.scene, NULL, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL) == FOV_ERR_NULL, "NULL config: FOV_ERR_NULL", "other code");
#define EXPECT(call, code, name)                                                                    \
    do {                                                                                            \
        for (k = 0; k < 6; ++k) rgb[k] = -7.0f;                                                     \
        g_log_count = 0; g_log_code = 0;                                                            \
        r = (call);                                                                                 \
        unchanged = 1;                                                                              \
        for (k = 0; k < 6; ++k) unchanged &= rgb[k] == -7.0f;                                      \
        check(r == (code) && g_log_count == 1 && g_log_code == (int32_t)(code) && unchanged, name,       \
              "got %d (%s), logged %d x code %d, rgb %s", (int)r, fovpt_result_string(r), g_log_count, \
              (int)g_log_code, unchanged ? "untouched" : "written");                                 \
    } while (0)
    EXPECT(fovpt_shade_points(NULL, &c, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_NULL, "NULL scene: FOV_ERR_NULL, logged");
    EXPECT(fovpt_shade_points(&S.scene, &c, NULL, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_NULL, "NULL camera: FOV_ERR_NULL");
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, NULL, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_NULL, "NULL xy: FOV_ERR_NULL");
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, NULL, t, NULL), FOV_ERR_NULL, "NULL rgb: FOV_ERR_NULL");
    xy[3] = nanv;
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_NOT_FINITE,
           "NaN y of the 2nd point: FOV_ERR_NOT_FINITE, the 1st not shaded");
    xy[3] = 20.0f; xy[0] = (float)INFINITY;
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_NOT_FINITE, "infinite x: FOV_ERR_NOT_FINITE");
    xy[0] = 3e38f; /* on a 1 x 1 image of 170 degrees the image-plane offset overflows */
    cam = S.cam; cam.width = cam.height = 1; cam.fov_y_deg = 170.0f;
    EXPECT(fovpt_shade_points(&S.scene, &c, &cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_INVALID_ARG,
           "a point whose ray overflows: FOV_ERR_INVALID_ARG");
    xy[0] = 10.0f;
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 1, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_INVALID_ARG, "stride 1: FOV_ERR_INVALID_ARG");
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, -0.5f, rgb, t, NULL), FOV_ERR_INVALID_ARG, "negative jitter: FOV_ERR_INVALID_ARG");
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, nanv, rgb, t, NULL), FOV_ERR_NOT_FINITE, "NaN jitter: FOV_ERR_NOT_FINITE");
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, (float)INFINITY, rgb, t, NULL), FOV_ERR_NOT_FINITE,
           "infinite jitter: FOV_ERR_NOT_FINITE");
    cam = S.cam; cam.width = cam.height = 1; cam.fov_y_deg = 170.0f;
    EXPECT(fovpt_shade_points(&S.scene, &c, &cam, 2, xy, 0, 0, 0, 1, 3e38f, rgb, t, NULL), FOV_ERR_INVALID_ARG,
           "a jitter square whose corner's ray overflows: FOV_ERR_INVALID_ARG");
    /* a camera rolled 45 degrees (r = (s, -s, 0), u = (s, s, 0), s = 1/sqrt 2; 2 x 2 pixels of
       90 degrees: sx = x - 1, sy = 1 - y) and the point (-h, h), jitter 2h, h = 0.45 FLT_MAX:
       at the corners (-2h, 0), (0, 2h) and the point, every ray component is at most
       s (2h + 2) < FLT_MAX, but at the corner (-2h, 2h) the x component s (sx + sy) is about
       -4 s h = -1.27 FLT_MAX: those samples' rays overflow (black samples, were they traced) */
    {
        float far_xy[4] = { -1.53e38f, 1.53e38f, 10.0f, 10.0f }, dd[3], oo[3];
        cam = S.cam; cam.width = cam.height = 2; cam.fov_y_deg = 90.0f;
        cam.pos[0] = cam.pos[1] = cam.pos[2] = 0.0f;
        cam.target[0] = 0.0f; cam.target[1] = 0.0f; cam.target[2] = -1.0f;
        cam.up[0] = 1.0f; cam.up[1] = 1.0f; cam.up[2] = 0.0f;
        /* independent of shade_points: fovpt_camera_ray accepts the point and the two checked
           corners of the old test and rejects the fourth corner */
        check(fovpt_camera_ray(&cam, -1.53e38f, 1.53e38f, oo, dd) == FOV_OK &&
              fovpt_camera_ray(&cam, -3.06e38f, 0.0f, oo, dd) == FOV_OK &&
              fovpt_camera_ray(&cam, 0.0f, 3.06e38f, oo, dd) == FOV_OK &&
              fovpt_camera_ray(&cam, 0.0f, 0.0f, oo, dd) == FOV_OK &&
              fovpt_camera_ray(&cam, -3.06e38f, 3.06e38f, oo, dd) == FOV_ERR_INVALID_ARG,
              "rolled camera: point and 3 corners have rays, the corner (-2h, 2h) overflows", "other codes");
        EXPECT(fovpt_shade_points(&S.scene, &c, &cam, 2, far_xy, 0, 0, 0, 4, 3.06e38f, rgb, t, NULL), FOV_ERR_INVALID_ARG,
               "rolled camera: a jitter square whose anti-diagonal corner's ray overflows: FOV_ERR_INVALID_ARG");
        /* half the jitter: every corner's ray exists, so the points are shaded */
        far_xy[0] = -0.765e38f; far_xy[1] = 0.765e38f;
        check(fovpt_shade_points(&S.scene, &c, &cam, 2, far_xy, 0, 0, 0, 4, 1.53e38f, rgb, t, NULL) == FOV_OK,
              "rolled camera, half the jitter: FOV_OK", "error");
    }
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, FOVPT_MAX_SPP + 1u, 0.0f, rgb, t, NULL), FOV_ERR_LIMIT,
           "spp above FOVPT_MAX_SPP: FOV_ERR_LIMIT");
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 0xFFFFFFFFu, xy, 0xFFFFFFFFu, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_LIMIT,
           "n x stride beyond size_t: FOV_ERR_LIMIT");
    c.mode = 7;
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_INVALID_ARG, "unknown mode: FOV_ERR_INVALID_ARG");
    c.mode = FOVPT_MODE_PATH; c.max_depth = FOVPT_MAX_BOUNCES + 1u;
    EXPECT(fovpt_shade_points(&S.scene, &c, &S.cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_INVALID_ARG, "max_depth above the cap: FOV_ERR_INVALID_ARG");
    c.max_depth = 8;
    cam = S.cam; cam.width = 0;
    EXPECT(fovpt_shade_points(&S.scene, &c, &cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_INVALID_ARG, "camera width 0: FOV_ERR_INVALID_ARG");
    cam = S.cam; cam.pos[1] = nanv;
    EXPECT(fovpt_shade_points(&S.scene, &c, &cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_NOT_FINITE, "NaN camera: FOV_ERR_NOT_FINITE");
    cam = S.cam; memcpy(cam.target, cam.pos, sizeof cam.pos);
    EXPECT(fovpt_shade_points(&S.scene, &c, &cam, 2, xy, 0, 0, 0, 1, 0.0f, rgb, t, NULL), FOV_ERR_DEGENERATE, "target == pos: FOV_ERR_DEGENERATE");
    g_log_count = 0;
    check(fovpt_shade_points(&S.scene, &c, &S.cam, 0, NULL, 0, 0, 0, 1, 0.0f, NULL, NULL, NULL) == FOV_OK && g_log_count == 0,
          "n = 0 with NULL buffers: FOV_OK, nothing logged", "failed");
#undef EXPECT
    pt_scene_free(&S);
}

/* A constant-radiance scene: a black (albedo 0) emitter of radiance c around the camera
   (emissive = 1), or the background c with nothing in view (emissive = 0). Every path then
   returns c exactly, so fovlp's reconstruction (convex combinations of the samples) and TAA
   (blends of equal values) must give c at every pixel. */
static int constant_scene(fovpt_scene *s, fovpt_shape *sh, fovpt_material *m, void **mem, int emissive,
                          const float c[3])
{
    fovpt_scene_desc d;
    size_t bytes = 0;
    fovpt_material_init(m);
    m->albedo[0] = m->albedo[1] = m->albedo[2] = 0.0f;
    fovpt_scene_desc_init(&d);
    if (emissive) {
        memcpy(m->emission, c, 3 * sizeof(float));
        fovpt_shape_sphere(sh, 0.0f, 1.0f, 0.0f, 40.0f, 0);
    } else {
        memcpy(d.background, c, 3 * sizeof(float));
        fovpt_shape_sphere(sh, 0.0f, 1.0f, 30.0f, 0.5f, 0);  /* behind the camera */
    }
    d.shapes = sh; d.num_shapes = 1; d.materials = m; d.num_materials = 1;
    if (fovpt_scene_size(&d, &bytes) != FOV_OK) return -1;
    *mem = malloc(bytes);
    return *mem && fovpt_scene_build(s, &d, *mem, bytes) == FOV_OK ? 0 : -1;
}

static void test_constant_pipeline(void)
{
    const float cval[3] = { 0.3f, 0.55f, 1.7f };
    const uint32_t W = 320, H = 180; /* fovlp_config_acuity needs a display it can reduce */
    int emissive, preset;
    for (emissive = 1; emissive >= 0; --emissive)
        for (preset = 0; preset < 2; ++preset) {
            fovpt_scene scene;
            fovpt_shape sh;
            fovpt_material mat;
            void *smem = NULL, *lmem;
            fovpt_camera cam;
            fovpt_config pc = fovpt_config_default();
            fovlp_config cfg;
            fovlp_camera lcam;
            fovlp_ctx lp;
            size_t bytes = 0, np = (size_t)W * H, i;
            float *samples, *sdep, *cur, *cdep, *hist[2], *hdep[2], worst = 0.0f;
            uint8_t *age[2];
            uint32_t f, frames = 4, taa_bad = 0, one_bad = 0;
            int ping = 0, a, ok = 1;
            const char *nm = emissive ? "black emitter around the camera" : "background only";
            if (constant_scene(&scene, &sh, &mat, &smem, emissive, cval) != 0) { check(0, N("constant scene (%s) builds", nm), "failed"); free(smem); continue; }
            fovpt_camera_init(&cam, W, H);
            cam.pos[0] = 0.0f; cam.pos[1] = 1.0f; cam.pos[2] = 0.0f;
            cam.target[0] = 0.0f; cam.target[1] = 1.0f; cam.target[2] = -1.0f;   /* looking along -z */
            cam.fov_y_deg = 50.0f;
            fovlp_camera_from(&cam, &lcam);
            cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
            cfg.cam_fov_y_deg = cam.fov_y_deg;
            if (preset == 1 && fovlp_config_acuity(&cfg, &lcam, NULL) != FOV_OK) ok = 0;
            cfg.taa.enable = 1;
            if (!ok || fovlp_memory_size(&cfg, &bytes) != FOV_OK) { check(0, N("%s: fovlp config", nm), "failed"); free(smem); continue; }
            lmem = malloc(bytes);
            fovlp_init(&lp, &cfg, lmem, bytes);
            samples = (float *)calloc((size_t)lp.geo.samples * 3, sizeof(float));
            sdep = (float *)calloc(lp.geo.samples, sizeof(float));
            cur = (float *)malloc(np * 3 * sizeof(float));
            cdep = (float *)malloc(np * sizeof(float));
            for (a = 0; a < 2; ++a) {
                hist[a] = (float *)calloc(np * 3, sizeof(float));
                hdep[a] = (float *)calloc(np, sizeof(float));
                age[a] = (uint8_t *)calloc(np, 1);
            }
            for (f = 0; f < frames && ok; ++f) {
                lppt_user u;
                fovlp_taa_io io;
                fov_gaze g;
                g.x = 0.3f * (float)W; g.y = 0.6f * (float)H;
                memset(&u, 0, sizeof u);
                u.scene = &scene; u.cfg = &pc; u.cam = &cam; u.frame = f; u.spp = 2;
                ok = fovlp_begin_frame(&lp, g, &lcam) == FOV_OK &&
                     lppt_shade_samples(&lp, 0, fovlp_sample_rows(&lp), &u, samples, sdep) == FOV_OK &&
                     fovlp_reconstruct_rows(&lp, samples, sdep, 0, H, cur, 0, cdep) == FOV_OK;
                fovlp_taa_io_init(&io);
                io.cur_rgb = cur; io.cur_depth = cdep;
                io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
                io.out_rgb = hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
                ok = ok && fovlp_taa_rows(&lp, &io, 0, H, NULL) == FOV_OK;
                ping = 1 - ping;
                for (i = 0; i < 3 * np && ok; ++i) {
                    float e1 = fabsf(cur[i] - cval[i % 3]), e2 = fabsf(hist[ping][i] - cval[i % 3]);
                    float tol = 1e-6f * cval[i % 3];
                    if (!(e1 <= tol)) one_bad++;
                    if (!(e2 <= tol)) taa_bad++;
                    if (e1 > worst) worst = e1;
                    if (e2 > worst) worst = e2;
                    if (!(e1 <= 1e30f)) worst = 1e30f;
                }
            }
            check(ok, N("%s, %s: pipeline runs (4 frames, TAA)", nm, preset ? "acuity" : "C Fov"), "a call failed");
            check(ok && one_bad == 0 && taa_bad == 0,
                  N("%s, %s: every pixel of every frame (reconstruction and TAA) = the constant within 1e-6", nm,
                    preset ? "acuity" : "C Fov"),
                  "%u reconstructed, %u TAA values off, worst |error| %g", one_bad, taa_bad, (double)worst);
            free(smem); free(lmem); free(samples); free(sdep); free(cur); free(cdep);
            for (a = 0; a < 2; ++a) { free(hist[a]); free(hdep[a]); free(age[a]); }
        }
}

/* examples/lp_pt_shade.h: the sample rows shaded in two ranges (split in the LP rows, at the
   LP / disc boundary, in the disc rows) give the one-range colours and depths bit for bit,
   and the one range writes every sample slot (the split's stream numbering is first + k) */
static void test_row_split(void)
{
    pt_scene S;
    fovpt_config pc = fovpt_config_default();
    fovlp_config cfg;
    fovlp_camera lcam;
    fovlp_ctx lp;
    const uint32_t W = 160, H = 120;
    size_t bytes = 0, ns, i;
    void *lmem = NULL;
    float *rgb1 = NULL, *dep1 = NULL, *rgb2 = NULL, *dep2 = NULL;
    uint32_t rows, k, unset = 0;
    fov_gaze g;
    if (pt_scene_make(&S, PT_SCENE_CORNELL) != 0) { check(0, "row split: scene", "build"); return; }
    S.cam.width = W; S.cam.height = H;
    g.x = 0.4f * (float)W; g.y = 0.55f * (float)H;
    cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    cfg.cam_fov_y_deg = S.cam.fov_y_deg;
    if (fovlp_camera_from(&S.cam, &lcam) != FOV_OK || fovlp_memory_size(&cfg, &bytes) != FOV_OK ||
        !(lmem = malloc(bytes ? bytes : 1u)) || fovlp_init(&lp, &cfg, lmem, bytes) != FOV_OK ||
        fovlp_begin_frame(&lp, g, &lcam) != FOV_OK) {
        check(0, "row split: fovlp setup", "failed");
        free(lmem); pt_scene_free(&S);
        return;
    }
    ns = lp.geo.samples;
    rows = fovlp_sample_rows(&lp);
    rgb1 = (float *)malloc(ns * 12u); dep1 = (float *)malloc(ns * 4u);
    rgb2 = (float *)malloc(ns * 12u); dep2 = (float *)malloc(ns * 4u);
    if (!rgb1 || !dep1 || !rgb2 || !dep2 || rows < 3u || lp.geo.lp_h < 2u || lp.geo.lp_h + 1u >= rows) {
        check(0, "row split: buffers and rows", "failed");
    } else {
        uint32_t split[3];
        lppt_user u;
        split[0] = lp.geo.lp_h / 2u; split[1] = lp.geo.lp_h; split[2] = lp.geo.lp_h + (rows - lp.geo.lp_h) / 2u;
        for (i = 0; i < 3 * ns; ++i) rgb1[i] = -5.0f;
        for (i = 0; i < ns; ++i) dep1[i] = -5.0f;
        memset(&u, 0, sizeof u);
        u.scene = &S.scene; u.cfg = &pc; u.cam = &S.cam; u.frame = 3; u.spp = 2;
        check(lppt_shade_samples(&lp, 0, rows, &u, rgb1, dep1) == FOV_OK, "row split: one range FOV_OK", "error");
        /* the slots no sample row holds keep -5 (fovlp_samples skips them); count the rest */
        for (i = 0; i < ns; ++i) unset += rgb1[3 * i] == -5.0f;
        check(unset < ns, N("row split: the one range shaded %u of %u slots", (unsigned)(ns - unset), (unsigned)ns), "none");
        for (k = 0; k < 3; ++k) {
            u.jitter = k == 2 ? 1.0f : 0.0f; /* the disc split also with lp_render's jitter 1 */
            for (i = 0; i < 3 * ns; ++i) rgb1[i] = rgb2[i] = -5.0f;
            for (i = 0; i < ns; ++i) dep1[i] = dep2[i] = -5.0f;
            if (lppt_shade_samples(&lp, 0, rows, &u, rgb1, dep1) != FOV_OK ||
                lppt_shade_samples(&lp, 0, split[k], &u, rgb2, dep2) != FOV_OK ||
                lppt_shade_samples(&lp, split[k], rows, &u, rgb2, dep2) != FOV_OK) {
                check(0, N("row split at %u: shading", split[k]), "error");
                continue;
            }
            check(memcmp(rgb1, rgb2, ns * 12u) == 0 && memcmp(dep1, dep2, ns * 4u) == 0,
                  N("row split at sample row %u of %u (%s): colours and depths = one range, bit for bit", split[k], rows,
                    k == 0 ? "in the LP rows" : k == 1 ? "LP / disc boundary" : "in the disc rows, jitter 1"),
                  "differ");
        }
    }
    free(rgb1); free(dep1); free(rgb2); free(dep2); free(lmem);
    pt_scene_free(&S);
}

int main(void)
{
    test_equals_reference();
    test_equals_uniform();
    test_row_split();
    test_errors();
    test_constant_pipeline();
    return fovcheck_summary();
}
