/* tests/test_fovlp_numerics.c - fovlp.h's float envelope (issue 10, F8 and F9): for finite
   inputs every FOV_OK output is finite and inside its documented range, however large the
   values (colours near FLT_MAX, huge depths, far points, extreme sigma / alpha). Expected
   values are analytic (a mean of two colours, a power-of-two scaling) or double precision.
   Built three ways by tests/run_all.sh (libm, FOV_NO_LIBM, sanitizers).
   "The thesis": K. Andersson, T. Hansson, "Performance Optimizations for Foveated Real-Time
   Raytracing", master's thesis, Lund University, LU-CS-EX 2020-64, 2020. */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVLP_IMPLEMENTATION
#endif
#include "fovlp.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fovcheck.h"

#define W 48
#define H 32
#define NPIX (W * H)

static int log_calls;
static int32_t log_last_code;
static void test_logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                        void *user)
{
    (void)tag; (void)msg; (void)line; (void)user;
    if (level == FOV_LOG_ERROR) { log_calls++; log_last_code = code; }
}

static int all_finite(const float *v, size_t n)
{
    size_t k;
    for (k = 0; k < n; ++k) if (!isfinite(v[k])) return 0;
    return 1;
}

/* ---- TAA driven directly with synthetic current frames -------------------------------------- */
typedef struct taa_env {
    fovlp_ctx ctx;
    void *mem;
    float cur[NPIX * 3], cdep[NPIX];
    float hist[2][NPIX * 3], hdep[2][NPIX];
    uint8_t age[2][NPIX];
    int ping;
} taa_env;

static taa_env g_env;

static fov_result taa_init(taa_env *e, uint32_t clamp)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_FOV, W, H);
    size_t bytes = 0;
    fov_result r;
    void *mem;
    c.taa.enable = 1;
    c.taa.clamp = clamp;
    r = fovlp_memory_size(&c, &bytes);
    if (r != FOV_OK) return r;
    mem = malloc(bytes);
    memset(e, 0, sizeof *e);
    e->mem = mem;
    return fovlp_init(&e->ctx, &c, e->mem, bytes);
}
/* one TAA frame on e->cur / e->cdep; returns the output */
static const float *taa_frame(taa_env *e, const fovlp_camera *cam)
{
    fovlp_taa_io io;
    fov_gaze gz = { 0.5f * W, 0.5f * H };
    fovlp_begin_frame(&e->ctx, gz, cam);
    io.cur_rgb = e->cur;
    io.cur_depth = e->cdep;
    io.prev_rgb = e->hist[e->ping];
    io.prev_depth = e->hdep[e->ping];
    io.prev_age = e->age[e->ping];
    io.out_rgb = e->hist[1 - e->ping];
    io.out_depth = e->hdep[1 - e->ping];
    io.out_age = e->age[1 - e->ping];
    fovlp_taa_rows(&e->ctx, &io, 0, H, NULL);
    e->ping = 1 - e->ping;
    return e->hist[e->ping];
}
static void fill(float *v, size_t n, float x)
{
    size_t k;
    for (k = 0; k < n; ++k) v[k] = x;
}

static const char *clamp_name[3] = { "none", "aabb", "variance" };

/* F8: a still camera, frames of 3e38 then -3e38: the 1/age blend of the two is their mean, 0
   (analytic); the third frame (+3e38, age 3) gives 1e38 */
static void test_f8_still(void)
{
    uint32_t clamp;
    for (clamp = 0; clamp < 3; ++clamp) {
        taa_env *e = &g_env;
        const float *o;
        int fin = 1;
        double worst2 = 0.0, worst3 = 0.0;
        size_t k;
        char name[200];
        if (taa_init(e, clamp) != FOV_OK) { check(0, "F8 setup", "init failed"); return; }
        fill(e->cdep, NPIX, 5.0f);
        fill(e->cur, NPIX * 3, 3e38f);
        o = taa_frame(e, NULL);
        fin &= all_finite(o, NPIX * 3);
        fill(e->cur, NPIX * 3, -3e38f);
        o = taa_frame(e, NULL);
        fin &= all_finite(o, NPIX * 3);
        for (k = 0; k < NPIX * 3; ++k) worst2 = fmax(worst2, fabs((double)o[k]));
        fill(e->cur, NPIX * 3, 3e38f);
        o = taa_frame(e, NULL);
        fin &= all_finite(o, NPIX * 3);
        for (k = 0; k < NPIX * 3; ++k) worst3 = fmax(worst3, fabs((double)o[k] - 1e38) / 1e38);
        snprintf(name, sizeof name, "F8 TAA still camera (clamp %s): frames 3e38, -3e38, 3e38 give the means 0 and 1e38, all finite",
                 clamp_name[clamp]);
        /* with a clamp the uniform neighbourhood box is the current colour itself: the
           history is clipped to it and the output is the current frame */
        if (clamp == 0)
            check(fin && worst2 <= 1e31 && worst3 < 1e-6, name, "finite %d, frame 2 max |out| %g (0 expected), frame 3 max rel. error %g",
                  fin, worst2, worst3);
        else
            check(fin, name, "non-finite output");
        free(e->mem);
    }
}

/* F8 with a moving camera (history reprojected): frames 3e38, -3e38, ... With the thesis's
   unclamped history (thesis_moving) the kept pixels of frame 2 are the mean 0; with a clamp
   or the default variance clip the uniform neighbourhood box is the current colour, so they
   are -3e38; either way the history is kept (age 2) for the pixels whose reprojection stays
   on the screen, not thrown away as non-finite. */
static void test_f8_moving(void)
{
    uint32_t clamp, thesis;
    for (thesis = 0; thesis < 2; ++thesis)
        for (clamp = 0; clamp < 3; ++clamp) {
            taa_env *e = &g_env;
            fovlp_camera cam;
            const float *o;
            int fin = 1, inrange = 1, f;
            uint32_t kept = 0, wrong = 0;
            size_t k;
            char name[240];
            if (taa_init(e, clamp) != FOV_OK) { check(0, "F8 setup", "init failed"); return; }
            e->ctx.cfg.taa.thesis_moving = thesis;
            memset(&cam, 0, sizeof cam);
            cam.right[0] = 1.0f; cam.up[1] = 1.0f; cam.fwd[2] = 1.0f; cam.tan_half_y = 0.5f;
            fill(e->cdep, NPIX, 5.0f);
            for (f = 0; f < 6; ++f) {
                cam.pos[0] = 0.01f * (float)f;
                fill(e->cur, NPIX * 3, (f & 1) ? -3e38f : 3e38f);
                o = taa_frame(e, &cam);
                fin &= all_finite(o, NPIX * 3);
                for (k = 0; k < NPIX * 3; ++k) inrange &= o[k] >= -3e38f && o[k] <= 3e38f;
                if (f == 1)
                    for (k = 0; k < NPIX; ++k) {
                        double want = (thesis && clamp == 0) ? 0.0 : -3e38, got = (double)o[3 * k];
                        if (e->age[e->ping][k] != 2) continue;
                        kept++;
                        if (!(fabs(got - want) <= 1e-6 * 3e38)) wrong++;
                    }
            }
            snprintf(name, sizeof name,
                     "F8 TAA moving camera (clamp %s%s): +-3e38 frames stay finite in [-3e38, 3e38], history kept (age 2) with the analytic value",
                     clamp_name[clamp], thesis ? ", thesis_moving" : "");
            check(fin && inrange && kept > NPIX * 9 / 10 && wrong == 0, name,
                  "finite %d, in range %d, frame 2: %u of %d pixels kept, %u of them off the analytic value",
                  fin, inrange, kept, NPIX, wrong);
            free(e->mem);
        }
}

/* a still camera whose history is a checkerboard of +-3e38: the fetch at the pixel centre
   is the pixel's own value (no 3e38 - (-3e38) overflow): frame 2 of 0 gives +-1.5e38, age 2 */
static void test_fetch_checker(void)
{
    taa_env *e = &g_env;
    const float *o;
    double worst = 0.0;
    int ages = 1;
    uint32_t x, y, ch;
    if (taa_init(e, FOVLP_CLAMP_NONE) != FOV_OK) { check(0, "fetch setup", "init failed"); return; }
    fill(e->cdep, NPIX, 5.0f);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x)
            for (ch = 0; ch < 3; ++ch) e->cur[3 * (y * W + x) + ch] = ((x + y) & 1) ? -3e38f : 3e38f;
    taa_frame(e, NULL);
    fill(e->cur, NPIX * 3, 0.0f);
    o = taa_frame(e, NULL);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            double want = ((x + y) & 1) ? -1.5e38 : 1.5e38;
            for (ch = 0; ch < 3; ++ch) worst = fmax(worst, fabs((double)o[3 * (y * W + x) + ch] - want) / 1.5e38);
            ages &= e->age[e->ping][y * W + x] == 2;
        }
    check(worst < 1e-6 && ages,
          "TAA still camera: a +-3e38 checkerboard history is kept (no overflow in the fetch): out = +-1.5e38, age 2",
          "worst rel. error %g, all ages 2: %d", worst, ages);
    free(e->mem);
}

/* the variance clip is scale invariant: colours x 2^66 (squares beyond FLT_MAX) give the
   outputs of colours x 1, times 2^66 */
static void run_clip(float scale, float *out)
{
    taa_env *e = &g_env;
    fovlp_camera cam;
    const float *o;
    uint32_t x, y, ch;
    if (taa_init(e, FOVLP_CLAMP_VARIANCE) != FOV_OK) { fill(out, NPIX * 3, 0.0f); return; }
    memset(&cam, 0, sizeof cam);
    cam.right[0] = 1.0f; cam.up[1] = 1.0f; cam.fwd[2] = 1.0f; cam.tan_half_y = 0.5f;
    fill(e->cdep, NPIX, 5.0f);
    fill(e->cur, NPIX * 3, 2.5f * scale);
    taa_frame(e, &cam);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x)
            for (ch = 0; ch < 3; ++ch)
                e->cur[3 * (y * W + x) + ch] = (((x + y) & 1) ? 1.0f : 3.0f + 0.5f * (float)ch) * scale;
    o = taa_frame(e, &cam);
    memcpy(out, o, sizeof(float) * NPIX * 3);
    free(e->mem);
}
static void test_clip_scale(void)
{
    static float small[NPIX * 3], big[NPIX * 3];
    const float s = 73786976294838206464.0f; /* 2^66 */
    double worst = 0.0, moved = 0.0;
    size_t k;
    run_clip(1.0f, small);
    run_clip(s, big);
    for (k = 0; k < NPIX * 3; ++k) {
        double ref = (double)small[k] * (double)s;
        worst = fmax(worst, fabs((double)big[k] - ref) / fmax(fabs(ref), 1e-30));
    }
    /* control: the clip acts here (some outputs differ from the unclipped (2.5 + cur) / 2) */
    for (k = 0; k < NPIX * 3; ++k) {
        uint32_t x = (uint32_t)(k / 3) % W, y = (uint32_t)(k / 3) / W, ch = (uint32_t)(k % 3);
        double cur = ((x + y) & 1) ? 1.0 : 3.0 + 0.5 * ch;
        moved = fmax(moved, fabs((double)small[k] - 0.5 * (2.5 + cur)));
    }
    check(all_finite(big, NPIX * 3) && worst < 1e-5 && moved > 0.01,
          "TAA variance clip is scale invariant: colours x 2^66 (squares overflow float) give the outputs x 2^66",
          "worst rel. difference %g (the clip moves outputs by up to %g at scale 1)", worst, moved);
}

/* the variance box of a uniform neighbourhood far from 0 is a point: moments about the
   centre pixel do not cancel (E[q^2] - E[q]^2 in float left a box of rounding noise: at 1234.567 a history 0.12 away was kept) */
static void test_clip_uniform(void)
{
    static const float levels[] = { 1234.567f, 77777.77f, 3.3e6f };
    uint32_t li;
    for (li = 0; li < 3; ++li) {
        taa_env *e = &g_env;
        fovlp_camera cam;
        const float *o;
        float lv = levels[li], hv = lv * 1.0001f;
        double worst = 0.0;
        size_t k;
        char name[200];
        if (taa_init(e, FOVLP_CLAMP_VARIANCE) != FOV_OK) { check(0, "clip setup", "init failed"); return; }
        memset(&cam, 0, sizeof cam);
        cam.right[0] = 1.0f; cam.up[1] = 1.0f; cam.fwd[2] = 1.0f; cam.tan_half_y = 0.5f;
        fill(e->cdep, NPIX, 5.0f);
        fill(e->cur, NPIX * 3, hv);
        taa_frame(e, &cam);
        cam.pos[0] = 0.001f;
        fill(e->cur, NPIX * 3, lv);
        o = taa_frame(e, &cam);
        for (k = 0; k < NPIX * 3; ++k) worst = fmax(worst, fabs((double)o[k] - (double)lv));
        snprintf(name, sizeof name, "TAA variance clip: a uniform neighbourhood of %g clips a history of %g to it (box of rounding size)",
                 (double)lv, (double)hv);
        check(worst <= 1e-6 * (double)lv, name, "worst |out - %g| = %g", (double)lv, worst);
        free(e->mem);
    }
}

/* ---- reconstruction and blend of huge sample values ---------------------------------------- */
static uint32_t hash2(float x, float y)
{
    uint32_t a, b, h;
    memcpy(&a, &x, 4); memcpy(&b, &y, 4);
    h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 15; h *= 0x2C1B3C6Du; h ^= h >> 12;
    return h;
}
static int g_shade_mode;
static void shade_huge(float x, float y, float rgb[3], float *depth, void *user)
{
    uint32_t h = hash2(x, y), ch;
    (void)user;
    for (ch = 0; ch < 3; ++ch) {
        if (g_shade_mode == 0) rgb[ch] = FLT_MAX;                              /* all at the top */
        else rgb[ch] = ((h >> ch) & 1u) ? FLT_MAX : -FLT_MAX;                 /* random signs */
    }
    if (depth) *depth = 1e38f;
}
static void test_reconstruct_huge(void)
{
    uint32_t preset, mode;
    for (preset = 0; preset < 4; ++preset)
        for (mode = 0; mode < 2; ++mode) {
            fovlp_config c = fovlp_config_preset(preset, 64, 64);
            fovlp_ctx ctx;
            size_t bytes = 0, k;
            void *mem;
            float *srgb, *sdep;
            static float img[64 * 64 * 3], dep[64 * 64], bl[64 * 64 * 3];
            fov_gaze gz = { 20.3f, 40.7f };
            int fin, inr = 1, binr = 1;
            char name[200];
            c.blend = 1;
            c.blend_start = 0.01f;
            if (fovlp_memory_size(&c, &bytes) != FOV_OK) { check(0, "reconstruct setup", "memory_size"); continue; }
            mem = malloc(bytes);
            if (fovlp_init(&ctx, &c, mem, bytes) != FOV_OK) { check(0, "reconstruct setup", "init"); free(mem); continue; }
            srgb = (float *)calloc((size_t)ctx.geo.samples * 3u, sizeof(float));
            sdep = (float *)calloc((size_t)ctx.geo.samples, sizeof(float));
            g_shade_mode = (int)mode;
            fovlp_begin_frame(&ctx, gz, NULL);
            fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), shade_huge, NULL, srgb, sdep, NULL);
            fovlp_reconstruct_rows(&ctx, srgb, sdep, 0, 64, img, 0, dep);
            fovlp_blend_rows(&ctx, img, 0, 64, bl);
            fin = all_finite(img, 64 * 64 * 3) && all_finite(bl, 64 * 64 * 3);
            /* a convex combination of the samples: all FLT_MAX gives FLT_MAX (to rounding) */
            if (mode == 0)
                for (k = 0; k < 64 * 64 * 3; ++k) {
                    inr &= img[k] >= FLT_MAX * 0.99999f;
                    binr &= bl[k] >= FLT_MAX * 0.99999f;
                }
            snprintf(name, sizeof name, "reconstruction + blend of %s samples (%s): finite%s", mode ? "+-FLT_MAX" : "FLT_MAX",
                     fovlp_preset_name(preset), mode ? "" : ", = FLT_MAX to rounding");
            check(fin && inr && binr, name, "finite %d, reconstruction in range %d, blend in range %d", fin, inr, binr);
            free(srgb); free(sdep); free(mem);
        }
}

/* ---- F9: spacing, density, eccentricity at extreme radii and kernels ----------------------- */
static void test_f9_spacing(void)
{
    static const float alphas[] = { 0.0625f, 0.5f, 1.0f, 2.0f, 3.0f, 16.0f };
    uint32_t ai;
    int bad_ok = 0, wrong = 0, limit_logged = 1, nlimit = 0, nok = 0, dens_bad = 0;
    double worst = 0.0;
    for (ai = 0; ai < sizeof alphas / sizeof alphas[0]; ++ai) {
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_K_FOV, 320, 180);
        fovlp_ctx ctx;
        size_t bytes = 0;
        void *mem;
        fov_gaze gz = { 100.0f, 50.0f };
        int e;
        c.alpha = alphas[ai];
        c.logger.func = test_logger;
        if (fovlp_memory_size(&c, &bytes) != FOV_OK) { check(0, "F9 setup", "alpha %g", (double)c.alpha); continue; }
        mem = malloc(bytes);
        fovlp_init(&ctx, &c, mem, bytes);
        fovlp_begin_frame(&ctx, gz, NULL);
        for (e = -2; e <= 128; ++e) {
            float r = e == 128 ? FLT_MAX : ldexpf(1.0f, e), rad = -1.0f, ang = -1.0f;
            fov_result res;
            log_calls = 0;
            res = fovlp_spacing(&ctx, r, &rad, &ang);
            if (res == FOV_OK) {
                nok++;
                if (!(isfinite(rad) && isfinite(ang) && rad >= 0.0f && ang > 0.0f)) bad_ok++;
                else if (r > 1.0f && rad < FLT_MAX) {
                    /* double reference: radial = 1 / (du/dr), du/dr = alpha q^(alpha-1) w_C / (L r) */
                    double L = (double)ctx.geo.L, q = log((double)r) / L, a = (double)c.alpha;
                    double dudr = a * pow(q, a - 1.0) * (double)ctx.geo.w_c / (L * (double)r);
                    double rr = 1.0 / dudr, aa = 2.0 * 3.14159265358979 * (double)r / ctx.geo.lp_h;
                    double er = fmax(fabs((double)rad - rr) / rr, fabs((double)ang - aa) / aa);
                    if (er > worst) worst = er;
                    if (er > 1e-3) wrong++;
                }
            } else {
                nlimit++;
                if (res != FOV_ERR_LIMIT || log_calls != 1 || log_last_code != FOV_ERR_LIMIT) limit_logged = 0;
            }
        }
        {
            /* density at far points: finite, >= 0 */
            static const float xs[] = { -FLT_MAX, -1e30f, -1e19f, 0.0f, 100.0f, 100.5f, 1e19f, 1e30f, FLT_MAX };
            uint32_t i, j;
            for (i = 0; i < 9; ++i)
                for (j = 0; j < 9; ++j) {
                    float d = fovlp_density(&ctx, xs[i], xs[j]);
                    if (!(isfinite(d) && d >= 0.0f)) dens_bad++;
                }
        }
        free(mem);
    }
    check(bad_ok == 0 && limit_logged && nlimit > 0 && nok > 100,
          "F9 fovlp_spacing: r up to FLT_MAX, alpha 1/16 .. 16: FOV_OK with finite spacings, or FOV_ERR_LIMIT logged",
          "%d FOV_OK with a non-finite or negative spacing, %d OK, %d errors (all LIMIT and logged: %d)",
          bad_ok, nok, nlimit, limit_logged);
    check(wrong == 0, "F9 fovlp_spacing: the finite results match the double-precision formula within 1e-3",
          "%d off, worst rel. error %g", wrong, worst);
    check(dens_bad == 0, "fovlp_density at points up to +-FLT_MAX: finite and >= 0 for alpha 1/16 .. 16",
          "%d non-finite or negative", dens_bad);
}

static void test_ecc_far(void)
{
    fov_ecc_model m;
    fov_display d;
    fov_gaze gz = { 160.0f, 90.0f };
    static const float xs[] = { -FLT_MAX, -3e38f, -1e30f, -1e19f, 0.0f, 160.0f, 1e19f, 1e30f, 3e38f, FLT_MAX };
    uint32_t i, j, bad = 0;
    float far_x;
    memset(&d, 0, sizeof d);
    d.axis_dx = -3e38f;   /* the eye's axis far to the left: x - cx overflows for x = FLT_MAX */
    fovlp_ecc_init(&m, &d, 60.0f, 320, 180, gz);
    for (i = 0; i < 10; ++i)
        for (j = 0; j < 10; ++j) {
            float a = fovlp_ecc_deg(&m, xs[i], xs[j]);
            if (!(isfinite(a) && a >= 0.0f && a <= 180.0f)) bad++;
        }
    d.axis_dx = 0.0f;
    fovlp_ecc_init(&m, &d, 60.0f, 320, 180, gz);
    far_x = fovlp_ecc_deg(&m, FLT_MAX, 90.0f);   /* a point at x = +inf in effect: 90 degrees */
    for (i = 0; i < 10; ++i)
        for (j = 0; j < 10; ++j) {
            float a = fovlp_ecc_deg(&m, xs[i], xs[j]);
            if (!(isfinite(a) && a >= 0.0f && a <= 180.0f)) bad++;
        }
    check(bad == 0 && fabsf(far_x - 90.0f) < 0.01f,
          "fovlp_ecc_deg at points up to +-FLT_MAX (and an axis at -3e38): finite, in [0, 180]; (FLT_MAX, gaze y) is 90 deg",
          "%u bad, far point %g deg", bad, (double)far_x);
}

/* ---- the version macros agree with each other and with line 1 --------------------------- */
#define STR2(x) #x
#define STR(x) STR2(x)
static void test_version(void)
{
    const char *want = STR(FOVLP_VERSION_MAJOR) "." STR(FOVLP_VERSION_MINOR) "." STR(FOVLP_VERSION_PATCH);
    char line[256], tag[64];
    FILE *f = fopen("fovlp.h", "r");
    int line_ok = 0;
    if (f) {
        if (fgets(line, sizeof line, f)) {
            snprintf(tag, sizeof tag, "- v%s -", FOVLP_VERSION_STRING);
            line_ok = strstr(line, tag) != NULL;
        }
        fclose(f);
    }
    check(strcmp(want, FOVLP_VERSION_STRING) == 0 && line_ok,
          "FOVLP_VERSION_STRING matches MAJOR.MINOR.PATCH and the version on line 1 of fovlp.h",
          "string \"%s\", macros \"%s\", line 1 has \"- v%s -\": %d (run from the repository root)",
          FOVLP_VERSION_STRING, want, FOVLP_VERSION_STRING, line_ok);
}

#ifdef FOV_NO_LIBM
#define MODE "FOV_NO_LIBM"
#else
#define MODE "libm"
#endif

int main(void)
{
    printf("# fovlp.h numerics tests (%s)\n", MODE);
    test_f8_still();
    test_f8_moving();
    test_fetch_checker();
    test_clip_scale();
    test_clip_uniform();
    test_reconstruct_huge();
    test_f9_spacing();
    test_ecc_far();
    test_version();
    return fovcheck_summary();
}
