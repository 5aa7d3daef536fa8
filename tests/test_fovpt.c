/*
 * test_fovpt.c - unit and property tests of fovpt.h.
 *
 * Build and run from the repository root (tests/run_all.sh builds it three ways: libm,
 * -DFOV_NO_LIBM, sanitizers):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovpt.c -lm -o build/tests/test_fovpt
 *
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed".
 * Expected values come from analytic formulas, brute force or independent quadrature done
 * here (in double), or from reference tables worked out by hand from the papers' formulas;
 * never from the code under test. Papers (in full in fovpt.h's REFERENCES): Axblad 2020
 * (T. Axblad, "Impact of Foveated Rendering on Path Tracing Frame Rate in Head-Mounted VR
 * Displays", KTH, 2020), Kim et al. 2021 (Y. Kim, Y. Ko, I. Ihm, "Selective Foveated Ray
 * Tracing for Head-Mounted Displays", ISMAR 2021), Polychronakis 2025 (A. Polychronakis,
 * "Implicit and Foveated Techniques for Real-Time Computer Graphics Rendering", doctoral
 * dissertation, Technical University of Crete, 2025).
 *
 * Sections:
 *   1. API, configs, shared block, eccentricity against fovsdf.
 *   2. Scenes: bad input with exact codes, BVH against brute force on random scenes and
 *      rays, depth cap, the no-BVH path, the user hook.
 *   3. Random streams and BSDF samplers (energy, pdf consistency, Fresnel).
 *   4. Path tracer: furnace tests, NEE on/off, Russian roulette, bounce limit, Whitted,
 *      determinism, row splits, non-finite radiance.
 *   5. Foveation building blocks: Catmull-Rom, tau_fov reference values, alpha(e), presets.
 */
#define FOV_IMPL
#include "fovsdf.h"
#include "fovpt.h"
#include "fovcheck.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name /* tests/common/fovcheck.h */

/* a test-side generator (independent of the library's streams) */
static uint64_t g_rs = 0x9e3779b97f4a7c15ull;
static double urand(void)
{
    g_rs ^= g_rs << 13; g_rs ^= g_rs >> 7; g_rs ^= g_rs << 17;
    return (double)(g_rs >> 11) * (1.0 / 9007199254740992.0);
}
static float frand(float a, float b) { return a + (b - a) * (float)urand(); }

/* malloc: 16-byte aligned on the hosts the tests run on (glibc, x86-64) */
static void *amalloc(size_t n) { return malloc(n + 16u); }

static int g_log_count;
static int32_t g_log_code;
static void logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    (void)tag; (void)level; (void)msg; (void)line; (void)user;
    g_log_count++;
    g_log_code = code;
}

/* ==== 1. API ================================================================================= */
static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    long n;
    char *b;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b = (char *)malloc((size_t)n + 1u);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n) { free(b); b = NULL; }
    if (b) b[n] = 0;
    fclose(f);
    return b;
}
static const char *block(const char *text, size_t *len)
{
    const char *a = strstr(text, "/* ==== FOV_SHARED_BEGIN decl");
    const char *e = a ? strstr(a, "/* ==== FOV_SHARED_END decl") : NULL;
    if (!a || !e) return NULL;
    *len = (size_t)(e - a);
    return a;
}

static void test_api(void)
{
    int r;
    fovpt_config c = fovpt_config_default(), o;
    memset(&o, 0, sizeof o);
    check(strcmp(fovpt_result_string(FOV_OK), "ok") == 0 || strlen(fovpt_result_string(FOV_OK)) == 0, "result_string ok", " ");
    {
        int ok = 1;
        for (r = -10; r <= 2; ++r) if (!fovpt_result_string((fov_result)r)) ok = 0;
        check(ok, "result_string never NULL (-10 .. 2)", " ");
    }
    check(strcmp(fovpt_method_name(FOVPT_METHOD_LAYERS), "layers") == 0 && strcmp(fovpt_method_name(99), "unknown") == 0,
          "method names", " ");
    check(c.spp == 1 && c.max_depth == 8 && c.rr_start == 3 && c.method == 0 && c.mode == 0, "config defaults (spp 1, depth 8, rr 3)",
          "spp %u depth %u rr %u", c.spp, c.max_depth, c.rr_start);
    check(c.layers.count == 4 && fabsf(c.layers.layer[3].radius_deg - 6.0f) < 1e-6f && c.layers.layer[1].stride == 3 &&
              c.layers.layer[0].stride == 4 && c.layers.layer[2].spp == 4,
          "config defaults: Axblad 2020 layers", " ");
    check(fabsf(c.selective.e_deg[3] - 30.0f) < 1e-6f && c.selective.n_sd[0] == 9 && fabsf(c.selective.tau[1] - 0.05f) < 1e-7f &&
              fabsf(c.temporal.alpha[4] - 0.2f) < 1e-7f && c.temporal.n_reuse_max == 5,
          "config defaults: Kim et al. 2021 tables", " ");
    {
        fovpt_config w;
        memset(&w, 0, sizeof w);
        w.mode = FOVPT_MODE_WHITTED;
        check(fovpt_config_resolve(&w, &o) == FOV_OK && o.max_depth == 3, "Whitted default depth 3", "%u", o.max_depth);
    }
    /* bad configs */
#define BADCFG(field_stmt, code, name)                                                  \
    do {                                                                                \
        fovpt_config b = fovpt_config_default();                                        \
        b.logger.func = logger;                                                         \
        g_log_count = 0;                                                                \
        field_stmt;                                                                     \
        r = (int)fovpt_config_resolve(&b, &o);                                          \
        check(r == (int)(code) && g_log_count == 1, N("config rejects %s", name), "got %d (%s), log %d", r, \
              fovpt_result_string((fov_result)r), g_log_count);                        \
    } while (0)
    BADCFG(b.method = 99, FOV_ERR_INVALID_ARG, "method 99");
    BADCFG(b.mode = 5, FOV_ERR_INVALID_ARG, "mode 5");
    BADCFG(b.spp = 70000, FOV_ERR_LIMIT, "spp 70000");
    BADCFG(b.max_depth = 5000, FOV_ERR_LIMIT, "max_depth 5000");
    BADCFG((b.mode = 1, b.max_depth = 40), FOV_ERR_LIMIT, "Whitted depth 40");
    BADCFG(b.layers.layer[2].radius_deg = 30.0f, FOV_ERR_INVALID_ARG, "layer radii not decreasing");
    BADCFG(b.layers.layer[1].stride = 0, FOV_ERR_INVALID_ARG, "layer stride d < 1");
    BADCFG(b.layers.layer[3].spp = 0, FOV_ERR_INVALID_ARG, "layer spp 0");
    BADCFG(b.layers.layer[3].radius_deg = NAN, FOV_ERR_NOT_FINITE, "layer radius NaN");
    BADCFG(b.layers.count = 1, FOV_ERR_INVALID_ARG, "one layer");
    BADCFG(b.layers.count = FOVPT_MAX_LAYERS + 1, FOV_ERR_INVALID_ARG, "too many layers");
    BADCFG(b.layers.layer[0].radius_deg = 15.0f, FOV_ERR_INVALID_ARG, "mask inside layer 1");
    BADCFG(b.layers.blend_deg = INFINITY, FOV_ERR_NOT_FINITE, "blend inf");
    BADCFG(b.zones.middle_deg = 5.0f, FOV_ERR_INVALID_ARG, "zones middle < inner");
    BADCFG(b.selective.e_deg[2] = 4.0f, FOV_ERR_INVALID_ARG, "e_deg not increasing");
    BADCFG(b.selective.tau_shape[2] = 0.1f, FOV_ERR_INVALID_ARG, "tau_fov shape non-monotone");
    BADCFG(b.temporal.n_tpi = 5, FOV_ERR_INVALID_ARG, "n_tpi 5");
    BADCFG(b.temporal.alpha[2] = 1.5f, FOV_ERR_INVALID_ARG, "alpha 1.5");
    BADCFG(b.display.fov_y_deg = NAN, FOV_ERR_NOT_FINITE, "display NaN");
    check(fovpt_config_resolve(NULL, &o) == FOV_ERR_NULL && fovpt_config_resolve(&c, NULL) == FOV_ERR_NULL, "config NULL", " ");
    {
        fovpt_layers_cfg L;
        check(fovpt_layers_preset(&L, FOVPT_LAYERS_KTH_DIAMETER) == FOV_OK && fabsf(L.layer[1].radius_deg - 10.0f) < 1e-6f &&
                  fabsf(L.layer[3].radius_deg - 3.0f) < 1e-6f && L.layer[3].stride == 1 && L.layer[0].stride == 4,
              "preset: 6/10/20 as diameters -> radii 3/5/10, d = 4,3,2,1", " ");
        check(fovpt_layers_preset(&L, FOVPT_LAYERS_KTH_RADIUS) == FOV_OK && fabsf(L.layer[1].radius_deg - 20.0f) < 1e-6f &&
                  fabsf(L.layer[2].radius_deg - 10.0f) < 1e-6f && L.layer[2].stride == 2,
              "preset: 6/10/20 as radii", " ");
        check(fovpt_layers_preset(&L, 7) == FOV_ERR_INVALID_ARG && fovpt_layers_preset(NULL, 0) == FOV_ERR_NULL, "preset bad id", " ");
    }
    /* the shared declarations are byte-for-byte the same as fovsdf.h's (tests/shared.sh: all) */
    {
        char *a = read_file("fovsdf.h"), *b = read_file("fovpt.h");
        size_t la = 0, lb = 0;
        const char *ba = a ? block(a, &la) : NULL, *bb = b ? block(b, &lb) : NULL;
        check(ba && bb && la == lb && memcmp(ba, bb, la) == 0, "shared block identical to fovsdf.h's",
              "found %d %d, lengths %zu %zu", ba != NULL, bb != NULL, la, lb);
        free(a); free(b);
    }
}

static void test_ecc(void)
{
    int i, same = 1, codes = 1;
    float worst = 0.0f;
    for (i = 0; i < 2000; ++i) {
        fov_ecc_model a, b;
        fov_display d;
        fov_gaze g;
        uint32_t w = 1u + (uint32_t)(urand() * 2000.0), h = 1u + (uint32_t)(urand() * 2000.0);
        float fov = frand(1.0f, 179.0f);
        fov_result ra, rb;
        memset(&d, 0, sizeof d);
        if (i % 3 == 1) d.fov_y_deg = frand(10.0f, 170.0f);
        if (i % 3 == 2) { d.pixel_pitch_mm = frand(0.05f, 0.5f); d.distance_mm = frand(100.0f, 1000.0f); }
        d.axis_dx = frand(-50.0f, 50.0f);
        d.axis_dy = frand(-50.0f, 50.0f);
        g.x = frand(-100.0f, (float)w + 100.0f);
        g.y = frand(-100.0f, (float)h + 100.0f);
        if (i % 97 == 0) g.x = NAN;
        if (i % 89 == 0) w = 0;
        ra = fovsdf_ecc_init(&a, &d, fov, w, h, g);
        rb = fovpt_ecc_init(&b, &d, fov, w, h, g);
        if (ra != rb) { codes = 0; continue; }
        if (ra != FOV_OK) continue;
        {
            int k;
            for (k = 0; k < 5; ++k) {
                float x = frand(0.0f, (float)w), y = frand(0.0f, (float)h);
                float ea = fovsdf_ecc_deg(&a, x, y), eb = fovpt_ecc_deg(&b, x, y);
                if (fabsf(ea - eb) > worst) worst = fabsf(ea - eb);
            }
            if (fabsf(fovsdf_ecc_ppd(&a) - fovpt_ecc_ppd(&b)) > 1e-6f * fovsdf_ecc_ppd(&a)) same = 0;
        }
    }
    check(codes, "ecc_init: same result codes as fovsdf_ecc_init (2000 random displays)", " ");
    check(worst <= 0.0f && same, "ecc_deg / ecc_ppd identical to fovsdf's", "max |diff| %g deg", (double)worst);
}

/* Per-eye gaze: fovpt_gaze_from_point is the inverse of fovpt_camera_ray (round trip on
   random cameras, symmetric and asymmetric), analytic values on fovpt_camera_init's former
   default camera, fovpt_camera_eyes' geometry and vergence, bad input. */
static void test_eyes(void)
{
    fovpt_camera c, e[2];
    fov_gaze g, gl, gr;
    float p[3], o[3], dir[3];
    double worst = 0.0;
    int i, k, codes = 1;
    for (i = 0; i < 2000; ++i) {
        double d[3], len = 0.0, cosang = 0.0;
        fovpt_camera_init(&c, 1u + (uint32_t)(urand() * 1500.0), 1u + (uint32_t)(urand() * 1500.0));
        for (k = 0; k < 3; ++k) { c.pos[k] = frand(-5.0f, 5.0f); c.target[k] = frand(-5.0f, 5.0f); c.up[k] = frand(-1.0f, 1.0f); }
        c.fov_y_deg = frand(5.0f, 150.0f);
        if (i % 2) { /* off-axis, the ratio of the tangents the image aspect (square pixels) */
            c.tan_left = frand(0.1f, 2.0f); c.tan_bottom = frand(0.1f, 2.0f); c.tan_top = frand(0.1f, 2.0f);
            c.tan_right = (c.tan_bottom + c.tan_top) * (float)c.width / (float)c.height - c.tan_left;
        }
        if (fovpt_camera_ray(&c, 0.5f, 0.5f, o, dir) != FOV_OK) continue;
        /* a point in front: along the ray through a random image point, at a random depth */
        fovpt_camera_ray(&c, frand(-0.5f, 1.5f) * (float)c.width, frand(-0.5f, 1.5f) * (float)c.height, o, dir);
        { float t = frand(0.1f, 50.0f); for (k = 0; k < 3; ++k) p[k] = o[k] + t * dir[k]; }
        if (fovpt_gaze_from_point(&c, p, &g) != FOV_OK) { codes = 0; continue; }
        fovpt_camera_ray(&c, g.x, g.y, o, dir);
        for (k = 0; k < 3; ++k) { d[k] = (double)p[k] - (double)c.pos[k]; len += d[k] * d[k]; }
        {   /* 1 - cos of the angle, both directions normalised in double */
            double ld = sqrt((double)dir[0] * (double)dir[0] + (double)dir[1] * (double)dir[1] + (double)dir[2] * (double)dir[2]);
            for (k = 0; k < 3; ++k) cosang += d[k] / sqrt(len) * ((double)dir[k] / ld);
        }
        if (1.0 - cosang > worst) worst = 1.0 - cosang;
    }
    check(codes && worst < 1e-9, "gaze_from_point: the camera ray through the gaze passes through the point (2000 random cameras)",
          "codes %d, max 1 - cos %g", codes, worst);
    /* 320x240, 60 degrees, at the origin looking along +z (fovpt_camera_init's former default) */
    fovpt_camera_init(&c, 320, 240);
    c.pos[2] = 0.0f; c.target[2] = 1.0f; /* fovpt_camera_init's former default view */
    p[0] = 0.0f; p[1] = 5.0f * (float)tan(30.0 * 3.14159265358979323846 / 180.0); p[2] = 5.0f;
    fovpt_gaze_from_point(&c, p, &g);
    check(fabsf(g.x - 160.0f) < 1e-3f && fabsf(g.y) < 1e-3f, "gaze_from_point: a point on the upper edge of the view -> (160, 0)",
          "(%g, %g)", (double)g.x, (double)g.y);
    p[1] = 0.0f;
    fovpt_gaze_from_point(&c, p, &g);
    check(fabsf(g.x - 160.0f) < 1e-3f && fabsf(g.y - 120.0f) < 1e-3f, "gaze_from_point: a point on the axis -> the image centre",
          "(%g, %g)", (double)g.x, (double)g.y);
    p[2] = -1.0f;
    check(fovpt_gaze_from_point(&c, p, &g) == FOV_ERR_INVALID_ARG, "gaze_from_point: a point behind the camera", " ");
    p[2] = 0.0f;
    check(fovpt_gaze_from_point(&c, p, &g) == FOV_ERR_INVALID_ARG, "gaze_from_point: the camera position", " ");
    p[0] = 1.0f; p[2] = 1e-9f;
    check(fovpt_gaze_from_point(&c, p, &g) == FOV_ERR_INVALID_ARG, "gaze_from_point: a point in the camera plane", " ");
    p[0] = NAN;
    check(fovpt_gaze_from_point(&c, p, &g) == FOV_ERR_NOT_FINITE, "gaze_from_point: NaN point", " ");
    p[0] = 0.0f; p[2] = 1.0f;
    check(fovpt_gaze_from_point(NULL, p, &g) == FOV_ERR_NULL && fovpt_gaze_from_point(&c, NULL, &g) == FOV_ERR_NULL &&
              fovpt_gaze_from_point(&c, p, NULL) == FOV_ERR_NULL, "gaze_from_point: NULL", " ");
    c.width = 0;
    check(fovpt_gaze_from_point(&c, p, &g) == FOV_ERR_INVALID_ARG, "gaze_from_point: bad camera", " ");
    /* eyes: 64 mm apart, vergence on a point 2 units ahead of the head */
    fovpt_camera_init(&c, 320, 240);
    c.pos[0] = 1.0f; c.pos[1] = 2.0f; c.pos[2] = 3.0f; c.target[0] = 1.0f; c.target[1] = 2.0f; c.target[2] = 4.0f;
    check(fovpt_camera_eyes(&c, 0.064f, e) == FOV_OK, "camera_eyes", " ");
    {
        double sep = 0.0, mid = 0.0, axis = 0.0, xw;
        for (k = 0; k < 3; ++k) {
            double dd = (double)e[1].pos[k] - (double)e[0].pos[k];
            sep += dd * dd;
            mid = fmax(mid, fabs(0.5 * ((double)e[0].pos[k] + (double)e[1].pos[k]) - (double)c.pos[k]));
            axis = fmax(axis, fabs(((double)e[0].target[k] - (double)e[0].pos[k]) - ((double)c.target[k] - (double)c.pos[k])));
            axis = fmax(axis, fabs(((double)e[1].target[k] - (double)e[1].pos[k]) - ((double)c.target[k] - (double)c.pos[k])));
        }
        check(fabs(sqrt(sep) - 0.064) < 1e-6 && mid < 1e-6 && axis < 1e-6 && fabs((double)e[1].pos[1] - 2.0) < 1e-6 &&
                  fabs((double)e[1].pos[2] - 3.0) < 1e-6,
              "camera_eyes: eyes ipd apart across the view, centred on the head, axes parallel", "sep %g mid %g axis %g", sqrt(sep), mid, axis);
        p[0] = 1.0f; p[1] = 2.0f; p[2] = 5.0f;
        fovpt_gaze_from_point(&e[0], p, &gl);
        fovpt_gaze_from_point(&e[1], p, &gr);
        /* the left eye sees the point 0.032 to its right at depth 2: x = 160 + 160 (0.016 / tan_x) */
        xw = 160.0 + 160.0 * (0.016 / (tan(30.0 * 3.14159265358979323846 / 180.0) * 320.0 / 240.0));
        check(fabs((double)gl.x - xw) < 1e-3 && fabs((double)gr.x - (320.0 - xw)) < 1e-3 && fabs((double)gl.y - 120.0) < 1e-3 &&
                  fabs((double)gr.y - 120.0) < 1e-3,
              "camera_eyes + gaze_from_point: vergence puts each eye's gaze inwards by the analytic disparity",
              "left (%g, %g) right (%g, %g), expected x %g / %g", (double)gl.x, (double)gl.y, (double)gr.x, (double)gr.y, xw, 320.0 - xw);
    }
    fovpt_camera_eyes(&c, 0.0f, e);
    check(!memcmp(&e[0], &c, sizeof c) && !memcmp(&e[1], &c, sizeof c), "camera_eyes: ipd 0 gives the head camera twice", " ");
    check(fovpt_camera_eyes(&c, NAN, e) == FOV_ERR_NOT_FINITE && fovpt_camera_eyes(&c, -0.1f, e) == FOV_ERR_INVALID_ARG &&
              fovpt_camera_eyes(NULL, 0.1f, e) == FOV_ERR_NULL && fovpt_camera_eyes(&c, 0.1f, NULL) == FOV_ERR_NULL &&
              fovpt_camera_eyes(&c, 1e38f, e) == FOV_OK,
          "camera_eyes: NaN, negative ipd and NULL", " ");
    {
        fovpt_camera far = c;
        far.pos[0] = far.target[0] = 3e38f;
        check(fovpt_camera_eyes(&far, 3e38f, e) == FOV_ERR_NOT_FINITE, "camera_eyes: an eye position that overflows", " ");
    }
    c.target[2] = 3.0f;
    check(fovpt_camera_eyes(&c, 0.1f, e) == FOV_ERR_DEGENERATE, "camera_eyes: degenerate head camera", " ");
}

/* ==== 2. scenes ============================================================================== */
typedef struct scene_buf {
    fovpt_scene s;
    void *mem;
} scene_buf;
static fov_result build(scene_buf *b, const fovpt_scene_desc *d)
{
    size_t n = 0;
    fov_result r = fovpt_scene_size(d, &n);
    b->mem = NULL;
    if (r != FOV_OK) return r;
    b->mem = amalloc(n + 16u);
    return fovpt_scene_build(&b->s, d, b->mem, n);
}

static void random_scene(fovpt_shape *sh, uint32_t ns, float *pos, uint32_t ntri, int clustered)
{
    uint32_t i, k;
    for (i = 0; i < ns; ++i) {
        float c[3], u[3], v[3];
        uint32_t t = (uint32_t)(urand() * 4.0);
        for (k = 0; k < 3; ++k) c[k] = clustered ? frand(-1.0f, 1.0f) * (i % 2 ? 0.1f : 5.0f) : frand(-5.0f, 5.0f);
        if (t == 0) fovpt_shape_sphere(&sh[i], c[0], c[1], c[2], frand(0.05f, 0.6f), i % 3);
        else if (t == 1) {
            for (k = 0; k < 3; ++k) { u[k] = frand(-1.0f, 1.0f); v[k] = frand(-1.0f, 1.0f); }
            fovpt_shape_quad(&sh[i], c, u, v, i % 3);
        } else if (t == 2) {
            float hi[3];
            for (k = 0; k < 3; ++k) hi[k] = c[k] + frand(0.05f, 1.0f);
            fovpt_shape_box(&sh[i], c, hi, i % 3);
        } else {
            float n[3] = { frand(-1, 1), frand(-1, 1), frand(-1, 1) };
            for (k = 0; k < 3; ++k) c[k] *= 3.0f;
            if (i % 7 == 0) fovpt_shape_plane(&sh[i], c, n, i % 3);
            else fovpt_shape_sphere(&sh[i], c[0], c[1], c[2], frand(0.01f, 0.3f), 0);
        }
    }
    for (i = 0; i < ntri; ++i) {
        float c[3];
        for (k = 0; k < 3; ++k) c[k] = clustered ? frand(-0.5f, 0.5f) : frand(-5.0f, 5.0f);
        for (k = 0; k < 9; ++k) pos[9u * i + k] = c[k % 3] + frand(-0.4f, 0.4f);
    }
}

/* primitives under W-wide node i (recursive) */
static uint32_t wide_prims(const fovpt__node4 *n4, uint32_t i)
{
    uint32_t j, c = 0;
    for (j = 0; j < FOVPT__W; ++j) {
        if (n4[i].b[0][j] > n4[i].b[3][j]) continue;
        c += n4[i].child[j] & FOVPT__LEAF4 ? n4[i].child[j] & 31u : wide_prims(n4, n4[i].child[j]);
    }
    return c;
}
/* bounded shapes (not triangles) under W-wide node i */
static uint32_t wide_shapes(const fovpt__node4 *n4, uint32_t i, const fovpt_scene *s)
{
    const fovpt__prim *pr = (const fovpt__prim *)s->prims;
    uint32_t j, t, c = 0;
    for (j = 0; j < FOVPT__W; ++j) {
        uint32_t ch = n4[i].child[j];
        if (n4[i].b[0][j] > n4[i].b[3][j]) continue;
        if (ch & FOVPT__LEAF4) {
            for (t = (ch & ~FOVPT__LEAF4) >> 5; t < ((ch & ~FOVPT__LEAF4) >> 5) + (ch & 31u); ++t)
                c += s->order[t] < s->num_bounded && pr[s->order[t]].type != FOVPT__TRI;
        } else {
            c += wide_shapes(n4, ch, s);
        }
    }
    return c;
}
/* primitives under binary node i (recursive: the test scenes' trees are shallow) */
static uint32_t subtree_prims(const fovpt__node *n2, uint32_t i)
{
    return n2[i].n ? n2[i].n : subtree_prims(n2, n2[i].a) + subtree_prims(n2, n2[i].a + 1u);
}

static void test_bvh_random(void)
{
    int sc;
    for (sc = 0; sc < 12; ++sc) {
        uint32_t ns = 5u + (uint32_t)(urand() * 200.0), nt = (uint32_t)(urand() * 3000.0), i, mism = 0, hits = 0;
        fovpt_shape *sh = (fovpt_shape *)malloc(sizeof(fovpt_shape) * ns);
        float *pos = (float *)malloc(sizeof(float) * 9u * (nt + 1u));
        fovpt_material m[3];
        fovpt_mesh mesh;
        fovpt_scene_desc d;
        scene_buf b;
        fov_result r;
        random_scene(sh, ns, pos, nt, sc % 3 == 2);
        fovpt_material_init(&m[0]); fovpt_material_init(&m[1]); fovpt_material_init(&m[2]);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = pos; mesh.num_vertices = 3u * nt; mesh.num_triangles = nt; mesh.material = 1;
        fovpt_scene_desc_init(&d);
        d.shapes = sh; d.num_shapes = ns; d.meshes = &mesh; d.num_meshes = 1; d.materials = m; d.num_materials = 3;
        d.bvh_leaf = 1u + (uint32_t)sc % 4u;
        d.bvh_bins = sc % 2 ? 8u : 0u;
        d.skip_degenerate = 1;
        r = build(&b, &d);
        if (!check(r == FOV_OK && b.s.nodes != NULL, N("random scene %d builds a BVH (%u shapes, %u triangles)", sc, ns, nt),
                   "%s", fovpt_result_string(r))) { free(sh); free(pos); free(b.mem); continue; }
        {   /* the W-wide tree (FOVPT__W: 4, or 8 for AVX2): every primitive in exactly one
               leaf slot, every child box inside its parent's, 2..W children per inner node, one
               node per 1..W-1 binary inner nodes (reachable from the root; those of more than
               FOVPT__COMBINE primitives all opened), every node but the root over
               FOVPT__COMBINE primitives or holding a bounded shape (a smaller subtree is a
               leaf child), a leaf of <= 4 in one block of 4 slots unless the padding reserve
               is spent, a leaf with a bounded shape that shape alone (unless centroids
               coincide) */
            static uint32_t seen[4000], stackn[4000];
            uint32_t sp = 0, bad = 0, visited = 0, ninner = 0, nbig = 0, strad = 0, k, j, nshape = 0, shared = 0;
            const fovpt__prim *pr = (const fovpt__prim *)b.s.prims;
            const uint32_t nslots = 4u * ((b.s.num_bounded + 3u) / 4u + (b.s.num_bounded + 15u) / 16u);
            const fovpt__node4 *n4 = (const fovpt__node4 *)b.s.nodes4;
            const fovpt__node *n2 = (const fovpt__node *)b.s.nodes;
            memset(seen, 0, sizeof seen);
            stackn[sp++] = 0;
            while (sp > 0) {
                uint32_t ni = stackn[--sp];
                if (n2[ni].n) continue;
                ++ninner;
                nbig += subtree_prims(n2, ni) > FOVPT__COMBINE;
                stackn[sp++] = n2[ni].a; stackn[sp++] = n2[ni].a + 1u;
            }
            stackn[sp++] = 0;
            while (sp > 0 && bad == 0) {
                uint32_t ni = stackn[--sp], real = 0;
                const fovpt__node4 *q = &n4[ni];
                ++visited;
                for (j = 0; j < FOVPT__W; ++j) {
                    uint32_t c = q->child[j], kk2;
                    if (q->b[0][j] > q->b[3][j]) continue; /* empty slot */
                    ++real;
                    if (c & FOVPT__LEAF4) {
                        uint32_t f = (c & ~FOVPT__LEAF4) >> 5, n = c & 31u, t;
                        uint32_t shp = 0;
                        if (n > 16u || ((f + n - 1u) >> 2) - (f >> 2) > (n - 1u) >> 2) strad++;
                        for (t = f; t < f + n; ++t)
                            if (t >= b.s.num_slots || b.s.order[t] >= b.s.num_bounded || seen[b.s.order[t]]++) bad++;
                            else shp += pr[b.s.order[t]].type != FOVPT__TRI;
                        if (shp > 0u && n > 1u) {
                            /* together only where no split exists: one centroid */
                            float lo0[3], hi0[3], lo1[3], hi1[3];
                            fovpt__prim_box(&pr[b.s.order[f]], lo0, hi0, 1);
                            for (t = f + 1u; t < f + n && t < b.s.num_slots; ++t) {
                                fovpt__prim_box(&pr[b.s.order[t]], lo1, hi1, 1);
                                for (kk2 = 0; kk2 < 3; ++kk2)
                                    if (0.5f * (lo0[kk2] + hi0[kk2]) != 0.5f * (lo1[kk2] + hi1[kk2])) shared++;
                            }
                        }
                    } else {
                        const fovpt__node4 *cq = &n4[c];
                        uint32_t cj, kk;
                        if (c >= b.s.num_nodes4) { bad++; continue; }
                        for (cj = 0; cj < FOVPT__W; ++cj) {
                            if (cq->b[0][cj] > cq->b[3][cj]) continue;
                            for (kk = 0; kk < 3; ++kk)
                                if (cq->b[kk][cj] < q->b[kk][j] || cq->b[3 + kk][cj] > q->b[3 + kk][j]) bad++;
                        }
                        stackn[sp++] = c;
                    }
                }
                if (real < 2u && !(ni == 0 && n2[0].n)) bad++;
                /* a small subtree without shapes is a leaf */
                if (ni != 0 && wide_prims(n4, ni) <= FOVPT__COMBINE && wide_shapes(n4, ni, &b.s) == 0) bad++;
            }
            for (k = 0; k < b.s.num_bounded; ++k) {
                if (seen[k] != 1u) bad++;
                nshape += pr[k].type != FOVPT__TRI;
            }
            check(nshape > 0 && shared == 0, N("random scene %d: each of its %u bounded shapes in a leaf of its own", sc, nshape),
                  "%u leaf primitives beside a shape with another centroid", shared);
            {   /* fovpt_scene_size lays out the bound below, shapes included */
                fovpt__layout L;
                size_t want = (b.s.num_bounded + (FOVPT__COMBINE - 1u) * nshape) / (FOVPT__COMBINE + 1u) + b.s.num_bounded / (FOVPT__W - 1u) + 1u;
                memset(&L, 0, sizeof L);
                check(fovpt__plan(&d, &L) == FOV_OK && (L.order - L.nodes4) / sizeof(fovpt__node4) >= want,
                      N("random scene %d: the W-wide nodes' region holds the bound with its shapes", sc), "%zu < %zu",
                      (size_t)((L.order - L.nodes4) / sizeof(fovpt__node4)), want);
            }
            check(bad == 0 && visited == b.s.num_nodes4 && (FOVPT__W - 1u) * b.s.num_nodes4 >= nbig && b.s.num_nodes4 <= ninner &&
                      b.s.num_nodes4 <= (b.s.num_bounded + (FOVPT__COMBINE - 1u) * nshape) / (FOVPT__COMBINE + 1u) + b.s.num_bounded / (FOVPT__W - 1u) + 1u && /* fovpt_scene_size's bound */
                      b.s.num_slots % 4u == 0 && b.s.num_slots >= b.s.num_bounded && b.s.num_slots <= nslots &&
                      (strad == 0 || b.s.num_slots == nslots),
                  N("random scene %d: %u-wide BVH covers every primitive once, boxes nested, 2-%u children, leaves in blocks", sc, FOVPT__W, FOVPT__W),
                  "bad %u, visited %u of %u nodes4, binary inner %u, slots %u of %u, straddling %u", bad, visited, b.s.num_nodes4, ninner,
                  b.s.num_slots, nslots, strad);
        }
        for (i = 0; i < 3000; ++i) {
            float o[3], dd[3];
            fovpt_hit h1, h2;
            int a1, a2;
            uint32_t k;
            for (k = 0; k < 3; ++k) { o[k] = frand(-8.0f, 8.0f); dd[k] = frand(-1.0f, 1.0f); }
            if (i % 50 == 0) { dd[0] = 0.0f; dd[1] = 0.0f; } /* axis-parallel rays */
            {
                float lim = i % 5 == 0 ? frand(0.1f, 10.0f) : FLT_MAX;
                a1 = fovpt_intersect(&b.s, o, dd, 0.0f, lim, &h1);
                a2 = fovpt_intersect_brute(&b.s, o, dd, 0.0f, FLT_MAX, &h2);
                if (i % 5 != 0) {
                    if (a1 != a2 || (a1 && (!(h1.t <= h2.t && h1.t >= h2.t) || h1.prim != h2.prim))) mism++;
                } else if (a1 ? (!a2 || h1.t < h2.t || h1.t > h2.t) : (a2 && h2.t < lim)) {
                    mism++; /* within a limited range: the global closest hit, or none before lim */
                }
            }
            hits += (uint32_t)a1;
        }
        check(mism == 0 && hits > 100, N("random scene %d: BVH = brute force on 3000 rays (t, primitive)", sc),
              "%u mismatches, %u hits, depth %u, nodes %u", mism, hits, b.s.bvh_depth, b.s.num_nodes);
        free(sh); free(pos); free(b.mem);
    }
}

static void test_scene_bad(void)
{
    fovpt_material m[2];
    fovpt_shape sh[2];
    float pos[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    uint32_t idx[3] = { 0, 1, 2 };
    fovpt_mesh mesh;
    fovpt_scene_desc d;
    scene_buf b;
    size_t n;
    fov_result r;
    fovpt_material_init(&m[0]); fovpt_material_init(&m[1]);
    m[1].emission[0] = 1.0f;
#define RESET()                                                                                  \
    do {                                                                                         \
        fovpt_scene_desc_init(&d);                                                               \
        fovpt_material_init(&m[0]); fovpt_material_init(&m[1]); m[1].emission[0] = 1.0f;        \
        fovpt_shape_sphere(&sh[0], 0, 0, 0, 1, 0);                                               \
        fovpt_shape_sphere(&sh[1], 0, 2, 0, 0.5f, 1);                                            \
        memset(&mesh, 0, sizeof mesh);                                                           \
        pos[0] = 0; pos[1] = 0; pos[2] = 0; pos[3] = 1; pos[4] = 0; pos[5] = 0;                  \
        pos[6] = 0; pos[7] = 1; pos[8] = 0; idx[0] = 0; idx[1] = 1; idx[2] = 2;                 \
        mesh.positions = pos; mesh.num_vertices = 3; mesh.indices = idx; mesh.num_triangles = 1; \
        d.shapes = sh; d.num_shapes = 2; d.meshes = &mesh; d.num_meshes = 1;                     \
        d.materials = m; d.num_materials = 2; d.logger.func = logger;                            \
        g_log_count = 0;                                                                         \
    } while (0)
#define BAD(stmt, code, name)                                                                     \
    do {                                                                                          \
        RESET();                                                                                  \
        stmt;                                                                                     \
        r = fovpt_scene_size(&d, &n);                                                             \
        check(r == (code) && g_log_count >= 1 && g_log_code == (int32_t)(code), N("scene rejects %s", name), \
              "got %d (%s)", (int)r, fovpt_result_string(r));                                     \
    } while (0)
    RESET();
    r = build(&b, &d);
    check(r == FOV_OK && b.s.num_prims == 3 && b.s.num_lights == 1 && b.s.nodes == NULL, "valid 3-primitive scene: no BVH, one light",
          "%s prims %u lights %u", fovpt_result_string(r), b.s.num_prims, b.s.num_lights);
    free(b.mem);
    BAD(pos[3] = 0.0f, FOV_ERR_DEGENERATE, "degenerate triangle (two equal vertices)");
    BAD((pos[3] = 2.0f, pos[4] = 2.0f, pos[6] = 1.0f, pos[7] = 1.0f), FOV_ERR_DEGENERATE, "degenerate triangle (collinear)");
    BAD(pos[4] = NAN, FOV_ERR_NOT_FINITE, "NaN vertex");
    BAD(pos[8] = -INFINITY, FOV_ERR_NOT_FINITE, "infinite vertex");
    BAD(idx[2] = 3, FOV_ERR_INVALID_ARG, "index out of range");
    BAD(mesh.num_triangles = 0xFFFFFFFFu, FOV_ERR_LIMIT, "overflowing triangle count");
    BAD((mesh.indices = NULL, mesh.num_triangles = 2), FOV_ERR_INVALID_ARG, "non-indexed mesh short of vertices");
    BAD(d.num_shapes = 0xFFFFFFF0u, FOV_ERR_LIMIT, "overflowing shape count");
    BAD(sh[0].r = 0.0f, FOV_ERR_DEGENERATE, "sphere radius 0");
    BAD(sh[1].r = -1.0f, FOV_ERR_DEGENERATE, "light sphere radius < 0 (zero-area light)");
    BAD(sh[0].p[1] = INFINITY, FOV_ERR_NOT_FINITE, "infinite sphere centre");
    BAD(sh[0].material = 2, FOV_ERR_INVALID_ARG, "material index out of range");
    BAD(mesh.material = 9, FOV_ERR_INVALID_ARG, "mesh material out of range");
    {
        float c[3] = { 0, 0, 0 }, u[3] = { 1, 0, 0 }, v[3] = { 2, 0, 0 };
        BAD(fovpt_shape_quad(&sh[1], c, u, v, 1), FOV_ERR_DEGENERATE, "zero-area light (quad)");
    }
    BAD((mesh.material = 1, pos[6] = 2.0f, pos[7] = 0.0f), FOV_ERR_DEGENERATE, "zero-area light (triangle)");
    {
        float lo[3] = { 0, 0, 0 }, hi[3] = { 1, -1, 1 };
        BAD(fovpt_shape_box(&sh[0], lo, hi, 0), FOV_ERR_DEGENERATE, "inverted box");
    }
    {
        float p[3] = { 0, 0, 0 }, nz[3] = { 0, 0, 0 };
        BAD(fovpt_shape_plane(&sh[0], p, nz, 0), FOV_ERR_DEGENERATE, "plane with zero normal");
    }
    BAD(sh[0].type = 9, FOV_ERR_INVALID_ARG, "shape type 9");
    BAD(d.materials = NULL, FOV_ERR_NULL, "NULL materials");
    BAD(d.shapes = NULL, FOV_ERR_NULL, "NULL shapes with a count");
    BAD(m[0].albedo[1] = 1.5f, FOV_ERR_INVALID_ARG, "albedo 1.5");
    BAD(m[0].emission[2] = NAN, FOV_ERR_NOT_FINITE, "NaN emission");
    BAD(m[0].type = 11, FOV_ERR_INVALID_ARG, "material type 11");
    BAD((m[0].type = FOVPT_MAT_DIELECTRIC, m[0].ior = 0.0f), FOV_ERR_INVALID_ARG, "ior 0");
    BAD(d.background[0] = NAN, FOV_ERR_NOT_FINITE, "NaN background");
    BAD(d.bvh_bins = 1, FOV_ERR_INVALID_ARG, "bvh_bins 1");
    BAD(d.bvh_leaf = 17, FOV_ERR_INVALID_ARG, "bvh_leaf 17");
    fovpt_material_init(&m[0]);
    /* skip_degenerate */
    RESET();
    pos[3] = 0.0f;
    d.skip_degenerate = 1;
    r = build(&b, &d);
    check(r == FOV_OK && b.s.num_skipped == 1 && b.s.num_prims == 2, "skip_degenerate drops the zero-area triangle",
          "%s skipped %u", fovpt_result_string(r), b.s.num_skipped);
    free(b.mem);
    /* memory */
    RESET();
    r = fovpt_scene_size(&d, &n);
    {
        unsigned char *mem = (unsigned char *)amalloc(n + 32u);
        check(fovpt_scene_build(&b.s, &d, mem, n - 1u) == FOV_ERR_TOO_SMALL, "scene memory too small", " ");
        check(fovpt_scene_build(&b.s, &d, NULL, n) == FOV_ERR_NULL, "scene memory NULL", " ");
        check(fovpt_scene_build(&b.s, &d, mem + 4, n) == FOV_ERR_INVALID_ARG, "scene memory misaligned", " ");
        check(fovpt_scene_size(NULL, &n) == FOV_ERR_NULL && fovpt_scene_size(&d, NULL) == FOV_ERR_NULL, "scene_size NULL", " ");
        free(mem);
    }
    /* over-deep BVH: spheres at exponentially growing distances, one per leaf */
    {
        fovpt_shape ex[40];
        uint32_t i, mism = 0;
        for (i = 0; i < 40; ++i) fovpt_shape_sphere(&ex[i], ldexpf(1.0f, (int)i), 0.0f, 0.0f, 0.25f, 0);
        fovpt_scene_desc_init(&d);
        d.shapes = ex; d.num_shapes = 40; d.materials = m; d.num_materials = 1; d.bvh_leaf = 1; d.bvh_max_depth = 8;
        d.logger.func = logger;
        g_log_count = 0;
        r = build(&b, &d);
        check(r == FOV_ERR_LIMIT && g_log_count == 1, "over-deep BVH (cap 8) is FOV_ERR_LIMIT", "%s", fovpt_result_string(r));
        free(b.mem);
        d.bvh_max_depth = 0;
        r = build(&b, &d);
        for (i = 0; i < 2000 && r == FOV_OK; ++i) {
            float o[3] = { -1.0f, frand(-0.3f, 0.3f), frand(-0.3f, 0.3f) }, dd[3] = { 1.0f, frand(-0.01f, 0.01f), frand(-0.01f, 0.01f) };
            fovpt_hit h1, h2;
            int a1 = fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h1), a2 = fovpt_intersect_brute(&b.s, o, dd, 0.0f, FLT_MAX, &h2);
            if (a1 != a2 || (a1 && h1.prim != h2.prim)) mism++;
        }
        check(r == FOV_OK && b.s.bvh_depth > 8 && mism == 0, "deep BVH within the default cap: same hits as brute force",
              "%s depth %u mismatches %u", fovpt_result_string(r), b.s.bvh_depth, mism);
        free(b.mem);
    }
}

/* user hook: a sphere of radius 1 at (0, 0, 5) */
static int hook_sphere(const float org[3], const float dir[3], float tmin, float tmax, float *t, float n[3],
                       uint32_t *material, void *user)
{
    double oc[3] = { (double)org[0], (double)org[1], (double)org[2] - 5.0 }, a, b, c, disc, t0;
    int k;
    (void)user;
    a = (double)dir[0] * (double)dir[0] + (double)dir[1] * (double)dir[1] + (double)dir[2] * (double)dir[2];
    b = oc[0] * (double)dir[0] + oc[1] * (double)dir[1] + oc[2] * (double)dir[2];
    c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - 1.0;
    disc = b * b - a * c;
    if (disc < 0.0) return 0;
    t0 = (-b - sqrt(disc)) / a;
    if (t0 <= (double)tmin) t0 = (-b + sqrt(disc)) / a;
    if (!(t0 > (double)tmin && t0 < (double)tmax)) return 0;
    *t = (float)t0;
    for (k = 0; k < 3; ++k) n[k] = (float)(oc[k] + t0 * (double)dir[k]);
    *material = 0;
    return 1;
}
static int hook_nan(const float org[3], const float dir[3], float tmin, float tmax, float *t, float n[3],
                    uint32_t *material, void *user)
{
    (void)org; (void)dir; (void)tmax; (void)user;
    *t = tmin + 1.0f;
    n[0] = NAN; n[1] = 0.0f; n[2] = 1.0f;
    *material = 0;
    return 1;
}

/* the hook sphere with its normal scaled by *(const float *)user ("any length") */
static int hook_sphere_scaled(const float org[3], const float dir[3], float tmin, float tmax, float *t, float n[3],
                              uint32_t *material, void *user)
{
    int k, r = hook_sphere(org, dir, tmin, tmax, t, n, material, NULL);
    for (k = 0; k < 3; ++k) n[k] *= *(const float *)user;
    return r;
}

/* vectors of "any length" whose squares under/overflow: hook normals, plane normals, camera
   view and up vectors (review finding: dropped hits, black shading, DEGENERATE cameras) */
static void test_any_length(void)
{
    static const float scales[4] = { 1e-25f, 1e-19f, 1e19f, 1e25f };
    fovpt_material m;
    fovpt_shape sh;
    fovpt_scene_desc d;
    scene_buf a, b;
    int k, i, bad = 0, cams = 0, planes = 0;
    fovpt_material_init(&m);
    fovpt_scene_desc_init(&d);
    fovpt_shape_sphere(&sh, 0.0f, 0.0f, 5.0f, 1.0f, 0);
    d.shapes = &sh; d.num_shapes = 1; d.materials = &m; d.num_materials = 1;
    build(&a, &d);
    for (k = 0; k < 4; ++k) {
        float sc = scales[k];
        d.num_shapes = 0; d.shapes = NULL; d.user_hit = hook_sphere_scaled; d.user = &sc;
        build(&b, &d);
        for (i = 0; i < 200; ++i) {
            float o[3] = { frand(-0.7f, 0.7f), frand(-0.7f, 0.7f), 0.0f }, dd[3] = { 0.0f, 0.0f, 1.0f };
            fovpt_hit h1, h2;
            int a1 = fovpt_intersect(&a.s, o, dd, 0.0f, FLT_MAX, &h1), a2 = fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h2);
            if (a1 != a2 || !a1 || fabsf(h1.n[0] - h2.n[0]) > 1e-3f || fabsf(h1.n[2] - h2.n[2]) > 1e-3f) bad++;
        }
        free(b.mem);
        d.user_hit = NULL; d.user = NULL;
        {   /* a camera whose view vector and up hint are scaled alike gives the same rays */
            fovpt_camera c0, c1;
            float o0[3], d0[3], o1[3], d1[3];
            fovpt_camera_init(&c0, 16, 9);
            c0.pos[0] = 0.0f; c0.pos[1] = 0.0f; c0.pos[2] = 0.0f;
            c0.target[0] = 0.3f; c0.target[1] = 0.2f; c0.target[2] = 1.0f;
            c0.up[0] = 0.0f; c0.up[1] = 1.0f; c0.up[2] = 0.0f;
            c1 = c0;
            c1.target[0] *= sc; c1.target[1] *= sc; c1.target[2] *= sc; c1.up[1] = sc;
            if (fovpt_camera_ray(&c0, 3.5f, 7.25f, o0, d0) == FOV_OK && fovpt_camera_ray(&c1, 3.5f, 7.25f, o1, d1) == FOV_OK &&
                fabsf(d0[0] - d1[0]) < 1e-5f && fabsf(d0[1] - d1[1]) < 1e-5f && fabsf(d0[2] - d1[2]) < 1e-5f)
                cams++;
        }
        {   /* a plane normal of any non-zero length */
            fovpt_shape pl;
            float pp[3] = { 0.0f, -1.0f, 0.0f }, pn[3] = { 0.0f, sc, 0.0f }, o[3] = { 0.0f, 0.0f, 0.0f }, dd[3] = { 0.0f, -1.0f, 0.2f };
            fovpt_hit h;
            fovpt_shape_plane(&pl, pp, pn, 0);
            d.shapes = &pl; d.num_shapes = 1;
            if (build(&b, &d) == FOV_OK) {
                int hit = fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h);
                if (hit && fabsf(h.t - 1.0f) < 1e-4f && fabsf(h.n[1] - 1.0f) < 1e-5f) planes++;
            }
            free(b.mem);
        }
    }
    check(bad == 0, "user hook normals scaled by 1e-25 .. 1e25 shade as the unit normal", "%d of 800 hits differ", bad);
    check(cams == 4, "camera view vector and up hint scaled by 1e-25 .. 1e25: same rays", "%d of 4", cams);
    check(planes == 4, "plane normals of length 1e-25 .. 1e25: accepted, hit with the unit normal", "%d of 4", planes);
    free(a.mem);
}

static void test_user_hook(void)
{
    fovpt_material m;
    fovpt_shape sh;
    fovpt_scene_desc d;
    scene_buf a, b;
    int i, bad = 0;
    fovpt_material_init(&m);
    fovpt_scene_desc_init(&d);
    fovpt_shape_sphere(&sh, 0.0f, 0.0f, 5.0f, 1.0f, 0);
    d.shapes = &sh; d.num_shapes = 1; d.materials = &m; d.num_materials = 1;
    build(&a, &d);
    d.num_shapes = 0; d.shapes = NULL; d.user_hit = hook_sphere;
    build(&b, &d);
    for (i = 0; i < 1000; ++i) {
        float o[3] = { frand(-1.5f, 1.5f), frand(-1.5f, 1.5f), 0.0f }, dd[3] = { frand(-0.1f, 0.1f), frand(-0.1f, 0.1f), 1.0f };
        fovpt_hit h1, h2;
        int a1 = fovpt_intersect(&a.s, o, dd, 0.0f, FLT_MAX, &h1), a2 = fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h2);
        if (a1 != a2) { if (fabsf(o[0] * o[0] + o[1] * o[1] - 1.0f) > 0.05f) bad++; continue; }
        if (a1 && (fabsf(h1.t - h2.t) > 1e-4f || h2.prim != FOVPT_PRIM_USER || fabsf(h1.n[0] - h2.n[0]) > 1e-3f)) bad++;
    }
    check(bad == 0, "user hook sphere = built-in sphere (t, normal; prim FOVPT_PRIM_USER)", "%d bad", bad);
    free(b.mem);
    d.user_hit = hook_nan;
    build(&b, &d);
    {
        float o[3] = { 0, 0, 0 }, dd[3] = { 0, 0, 1 };
        fovpt_hit h;
        check(fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h) == 0, "user hook with a NaN normal is ignored", " ");
    }
    free(a.mem); free(b.mem);
}

/* ==== 3. random streams, BSDFs ================================================================ */
static void test_rng(void)
{
    fovpt_rng a, b;
    int i, same = 1, diff = 0, bins[16] = { 0 };
    double chi = 0.0, mean = 0.0;
    fovpt_rng_init(&a, 7, 100, 3, 2);
    fovpt_rng_init(&b, 7, 100, 3, 2);
    for (i = 0; i < 100; ++i) if (!(fovpt_rng_next(&a) <= fovpt_rng_next(&b) && 1)) same = 0;
    fovpt_rng_init(&a, 7, 100, 3, 2);
    fovpt_rng_init(&b, 7, 100, 3, 2);
    for (i = 0; i < 100; ++i) { float x = fovpt_rng_next(&a), y = fovpt_rng_next(&b); if (x < y || x > y) same = 0; }
    check(same, "rng: same (seed, pixel, sample, frame) -> same stream", " ");
    {
        uint32_t v[4][4] = { { 7, 100, 3, 2 }, { 8, 100, 3, 2 }, { 7, 101, 3, 2 }, { 7, 100, 4, 2 } };
        float first[5];
        int k, j;
        for (k = 0; k < 4; ++k) { fovpt_rng_init(&a, v[k][0], v[k][1], v[k][2], v[k][3]); first[k] = fovpt_rng_next(&a); }
        fovpt_rng_init(&a, 7, 100, 3, 3);
        first[4] = fovpt_rng_next(&a);
        for (k = 0; k < 5; ++k) for (j = k + 1; j < 5; ++j) if (first[k] < first[j] || first[k] > first[j]) diff++;
        check(diff == 10, "rng: seed, pixel, sample and frame each change the stream", "%d of 10 differ", diff);
    }
    for (i = 0; i < 160000; ++i) {
        float x;
        if (i % 16 == 0) fovpt_rng_init(&a, 1, (uint32_t)i / 16u, 0, 0);
        x = fovpt_rng_next(&a);
        if (!(x >= 0.0f && x < 1.0f)) { bins[0] = -1000000; break; }
        bins[(int)(x * 16.0f)]++;
        mean += (double)x;
    }
    for (i = 0; i < 16; ++i) chi += ((double)bins[i] - 10000.0) * ((double)bins[i] - 10000.0) / 10000.0;
    check(chi < 37.7 && fabs(mean / 160000.0 - 0.5) < 0.003, "rng: uniform on [0, 1) (chi-square 16 bins, p = 0.001 bound 37.7)",
          "chi2 %.2f mean %.5f", chi, mean / 160000.0);
}

/* mean of the sampler's weights against independent quadrature of f cos from bsdf_eval */
static void test_bsdf(void)
{
    float n[3] = { 0.0f, 0.0f, 1.0f };
    int t;
    for (t = 0; t < 4; ++t) {
        fovpt_material m;
        float th = (float)t * 0.45f, wo[3] = { sinf(th), 0.0f, cosf(th) };
        double sum[3] = { 0, 0, 0 }, sq = 0.0, quad[3] = { 0, 0, 0 }, pdf_err = 0.0;
        int i, j, ns = 200000, badpdf = 0;
        fovpt_rng rng;
        fovpt_material_init(&m);
        m.type = FOVPT_MAT_PHONG;
        m.albedo[0] = 0.3f; m.albedo[1] = 0.1f; m.albedo[2] = 0.0f;
        m.specular[0] = 0.6f; m.specular[1] = 0.8f; m.specular[2] = 0.9f;
        m.exponent = t == 3 ? 200.0f : 15.0f;
        for (i = 0; i < ns; ++i) {
            float wi[3], w[3], pdf, fc[3], pe;
            fovpt_rng_init(&rng, 3, (uint32_t)i, 0, (uint32_t)t);
            if (!fovpt_bsdf_sample(&m, n, wo, &rng, wi, w, &pdf)) continue;
            for (j = 0; j < 3; ++j) sum[j] += (double)w[j];
            sq += (double)w[1] * (double)w[1];
            fovpt_bsdf_eval(&m, n, wo, wi, fc, &pe);
            if (fabsf(pe - pdf) > 1e-4f * pdf) badpdf++;
            if (fabs((double)fc[1] / (double)pe - (double)w[1]) > 1e-3 * (double)w[1] + 1e-6) pdf_err += 1.0;
        }
        /* quadrature over the hemisphere: theta in 2000 x phi in 400 midpoints (dense near the lobe) */
        {
            int a, c;
            int NT = 3000, NP = 600;
            for (a = 0; a < NT; ++a) {
                double ct = 1.0 - ((double)a + 0.5) / NT, st = sqrt(1.0 - ct * ct);
                for (c = 0; c < NP; ++c) {
                    double ph = 2.0 * 3.141592653589793 * ((double)c + 0.5) / NP;
                    float wi[3] = { (float)(st * cos(ph)), (float)(st * sin(ph)), (float)ct }, fc[3], pe;
                    fovpt_bsdf_eval(&m, n, wo, wi, fc, &pe);
                    for (j = 0; j < 3; ++j) quad[j] += (double)fc[j] * (1.0 / NT) * (2.0 * 3.141592653589793 / NP);
                }
            }
        }
        {
            double m1 = sum[1] / ns, var = sq / ns - m1 * m1, se = sqrt(var / ns);
            double e0 = fabs(sum[0] / ns - quad[0]), e1 = fabs(m1 - quad[1]), e2 = fabs(sum[2] / ns - quad[2]);
            check(e1 < 4.0 * se + 2e-3 && e0 < 0.01 && e2 < 0.01,
                  N("Phong sampler (exponent %g, theta_o %.2f): mean weight = quadrature of f cos", (double)m.exponent, (double)th),
                  "sampled %.4f %.4f %.4f quad %.4f %.4f %.4f se %.4f", sum[0] / ns, m1, sum[2] / ns, quad[0], quad[1], quad[2], se);
            check(quad[0] <= 1.0 + 1e-3 && quad[1] <= 1.0 + 1e-3 && quad[2] <= 1.0 + 1e-3,
                  N("Phong kd + ks <= 1 reflects at most 1 (theta_o %.2f)", (double)th), "%.4f %.4f %.4f", quad[0], quad[1], quad[2]);
            check(badpdf == 0 && pdf_err < 1.0, N("Phong sample pdf = eval pdf, weight = f cos / pdf (theta_o %.2f)", (double)th),
                  "%d pdf mismatches, %g weight mismatches", badpdf, pdf_err);
        }
    }
    {   /* Lambert: weight = albedo exactly, cosine distribution: E[cos] = 2/3 */
        fovpt_material m;
        float wo[3] = { 0.6f, 0.0f, 0.8f };
        double ec = 0.0;
        int i, bad = 0, ns = 100000;
        fovpt_rng rng;
        fovpt_material_init(&m);
        m.albedo[0] = 0.25f; m.albedo[1] = 0.5f; m.albedo[2] = 0.75f;
        for (i = 0; i < ns; ++i) {
            float wi[3], w[3], pdf;
            fovpt_rng_init(&rng, 1, (uint32_t)i, 0, 0);
            if (!fovpt_bsdf_sample(&m, n, wo, &rng, wi, w, &pdf) || w[0] < 0.25f || w[0] > 0.25f || w[2] < 0.75f || w[2] > 0.75f ||
                wi[2] <= 0.0f)
                bad++;
            ec += (double)wi[2];
        }
        check(bad == 0 && fabs(ec / ns - 2.0 / 3.0) < 0.004, "Lambert sampler: weight = albedo, E[cos] = 2/3",
              "%d bad, E[cos] %.4f", bad, ec / ns);
    }
    {   /* mirror and dielectric: energy and Fresnel */
        fovpt_material m;
        float wo[3] = { 0.0f, 0.0f, 1.0f }, wi[3], w[3], pdf;
        int i, refl = 0, ns = 200000, bad = 0;
        fovpt_rng rng;
        fovpt_material_init(&m);
        m.type = FOVPT_MAT_MIRROR;
        fovpt_rng_init(&rng, 0, 0, 0, 0);
        {
            float wo2[3] = { 0.6f, 0.0f, 0.8f };
            fovpt_bsdf_sample(&m, n, wo2, &rng, wi, w, &pdf);
            check(fabsf(wi[0] + 0.6f) < 1e-6f && fabsf(wi[2] - 0.8f) < 1e-6f && fabsf(w[1] - 0.8f) < 1e-6f && pdf <= 0.0f,
                  "mirror: reflected direction, weight = tint, delta pdf", " ");
        }
        m.type = FOVPT_MAT_DIELECTRIC;
        m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
        for (i = 0; i < ns; ++i) {
            fovpt_rng_init(&rng, 2, (uint32_t)i, 0, 0);
            fovpt_bsdf_sample(&m, n, wo, &rng, wi, w, &pdf);
            if (wi[2] > 0.0f) refl++;
            if (w[0] < 1.0f || w[0] > 1.0f) bad++;
        }
        {
            double F = (double)refl / ns, se = sqrt(0.04 * 0.96 / ns);
            check(fabs(F - 0.04) < 4.0 * se && bad == 0, "dielectric n=1.5 at normal incidence: reflects 4 % ((n-1)/(n+1))^2, weight 1 (R + T = 1)",
                  "reflected %.4f (se %.4f), %d bad weights", F, se, bad);
        }
        {   /* total internal reflection from inside at 60 degrees (critical 41.8) */
            float wo3[3] = { 0.866f, 0.0f, -0.5f };
            int all = 1;
            for (i = 0; i < 1000; ++i) {
                fovpt_rng_init(&rng, 5, (uint32_t)i, 0, 0);
                fovpt_bsdf_sample(&m, n, wo3, &rng, wi, w, &pdf);
                if (!(wi[2] < 0.0f)) all = 0;
            }
            check(all, "dielectric: total internal reflection beyond the critical angle", " ");
        }
        {   /* refraction follows Snell: from air at 45 degrees into n = 1.5 */
            float wo4[3] = { 0.70710678f, 0.0f, 0.70710678f };
            int found = 0;
            for (i = 0; i < 100 && !found; ++i) {
                fovpt_rng_init(&rng, 6, (uint32_t)i, 0, 0);
                fovpt_bsdf_sample(&m, n, wo4, &rng, wi, w, &pdf);
                if (wi[2] < 0.0f) {
                    found = 1;
                    check(fabsf(-wi[0] - 0.70710678f / 1.5f) < 1e-5f, "dielectric: Snell's law (sin t = sin i / n)", "sin t %.6f",
                          (double)-wi[0]);
                }
            }
            if (!found) check(0, "dielectric: Snell's law (sin t = sin i / n)", "no refraction drawn");
        }
    }
}

/* ==== 4. path tracer ======================================================================== */
typedef struct stat_acc { double s, s2; long n; } stat_acc;
static void acc_add(stat_acc *a, double v) { a->s += v; a->s2 += v * v; a->n++; }
static double acc_mean(const stat_acc *a) { return a->s / (double)a->n; }
static double acc_se(const stat_acc *a)
{
    double m = acc_mean(a);
    return sqrt(fmax(0.0, a->s2 / (double)a->n - m * m) / (double)a->n);
}

static void test_furnace(void)
{
    fovpt_material m;
    fovpt_shape sh;
    fovpt_scene_desc d;
    scene_buf b;
    fovpt_config c = fovpt_config_default();
    fovpt_stats st;
    int i, nee;
    /* (a) a diffuse sphere under a uniform environment: L = albedo * background, exactly */
    fovpt_material_init(&m);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.5f;
    fovpt_scene_desc_init(&d);
    fovpt_shape_sphere(&sh, 0.0f, 0.0f, 0.0f, 1.0f, 0);
    d.shapes = &sh; d.num_shapes = 1; d.materials = &m; d.num_materials = 1;
    d.background[0] = d.background[1] = d.background[2] = 1.0f;
    build(&b, &d);
    memset(&st, 0, sizeof st);
    {
        double worst = 0.0;
        for (i = 0; i < 2000; ++i) {
            float o[3] = { frand(-0.9f, 0.9f), frand(-0.9f, 0.9f), -3.0f }, dd[3] = { 0.0f, 0.0f, 1.0f }, rgb[3];
            fovpt_rng rng;
            fovpt_rng_init(&rng, 0, (uint32_t)i, 0, 0);
            fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, &st);
            if (o[0] * o[0] + o[1] * o[1] < 0.8f) worst = fmax(worst, fabs((double)rgb[1] - 0.5));
        }
        check(worst < 1e-6, "furnace: convex Lambert sphere (albedo 0.5) under background 1 gives 0.5", "max error %g", worst);
        {   /* a rejected ray is logged through the config's logger */
            float o[3] = { NAN, 0.0f, 0.0f }, dd[3] = { 0.0f, 0.0f, 1.0f }, rgb[3];
            fovpt_config cl = c;
            fovpt_rng rng;
            fov_result rr;
            fovpt_rng_init(&rng, 0, 0, 0, 0);
            cl.logger.func = logger;
            g_log_count = 0;
            rr = fovpt_radiance(&b.s, &cl, o, dd, &rng, rgb, NULL);
            check(rr == FOV_ERR_NOT_FINITE && g_log_count == 1 && g_log_code == (int32_t)FOV_ERR_NOT_FINITE && rgb[0] == 0.0f,
                  "radiance: a NaN origin is FOV_ERR_NOT_FINITE, logged once, colour 0", "r %d, %d log calls", (int)rr, g_log_count);
        }
        check(c.no_nee == 0 && b.s.num_lights == 0 && st.shadow_rays == 0 && st.bounce_rays > 0,
              "no emitters: NEE on but no shadow rays traced", "lights %u, shadow rays %llu, bounce rays %llu", b.s.num_lights,
              (unsigned long long)st.shadow_rays, (unsigned long long)st.bounce_rays);
    }
    free(b.mem);
    /* (b) closed emitting diffuse enclosure: L = Le * sum_{k=0}^{D} a^k, NEE on and off */
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.7f;
    m.emission[0] = m.emission[1] = m.emission[2] = 0.3f;
    d.background[0] = d.background[1] = d.background[2] = 0.0f;
    fovpt_shape_sphere(&sh, 0.0f, 0.0f, 0.0f, 2.0f, 0);
    build(&b, &d);
    for (nee = 0; nee < 2; ++nee) {
        int D;
        for (D = 3; D <= 30; D += 27) {
            stat_acc a = { 0, 0, 0 };
            double expect = 0.0, p = 1.0;
            int k;
            for (k = 0; k <= D; ++k) { expect += 0.3 * p; p *= 0.7; }
            c = fovpt_config_default();
            c.no_nee = (uint32_t)(1 - nee);
            c.max_depth = (uint32_t)D;
            memset(&st, 0, sizeof st);
            for (i = 0; i < 40000; ++i) {
                float o[3] = { frand(-1.0f, 1.0f), frand(-1.0f, 1.0f), frand(-1.0f, 1.0f) }, dd[3] = { frand(-1, 1), frand(-1, 1), frand(-1, 1) }, rgb[3];
                fovpt_rng rng;
                fovpt_rng_init(&rng, 11, (uint32_t)i, 0, (uint32_t)D);
                fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, &st);
                acc_add(&a, (double)rgb[0]);
            }
            check(fabs(acc_mean(&a) - expect) < 3.0 * acc_se(&a) + 1e-6 && acc_se(&a) < 0.01,
                  N("furnace: emitting enclosure (a 0.7, Le 0.3), depth %d, NEE %s -> %.5f", D, nee ? "on" : "off", expect),
                  "mean %.5f se %.5f (shadow rays %llu)", acc_mean(&a), acc_se(&a), (unsigned long long)st.shadow_rays);
            if (nee == 1 && D == 3) check(st.shadow_rays > 0, "NEE traces shadow rays towards the emitter", " ");
            if (nee == 0 && D == 3) check(st.shadow_rays == 0, "no NEE: no shadow rays", " ");
        }
    }
    {   /* Russian roulette off vs on: same mean at depth 30 */
        stat_acc a0 = { 0, 0, 0 }, a1 = { 0, 0, 0 };
        fovpt_stats s0, s1;
        memset(&s0, 0, sizeof s0); memset(&s1, 0, sizeof s1);
        for (i = 0; i < 20000; ++i) {
            float o[3] = { 0, 0, 0 }, dd[3] = { frand(-1, 1), frand(-1, 1), 0.5f }, rgb[3];
            fovpt_rng rng;
            c = fovpt_config_default();
            c.max_depth = 30; c.rr_start = FOVPT_RR_OFF;
            fovpt_rng_init(&rng, 12, (uint32_t)i, 0, 0);
            fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, &s0);
            acc_add(&a0, (double)rgb[1]);
            c.rr_start = 1;
            fovpt_rng_init(&rng, 13, (uint32_t)i, 0, 0);
            fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, &s1);
            acc_add(&a1, (double)rgb[1]);
        }
        check(fabs(acc_mean(&a0) - acc_mean(&a1)) < 3.0 * sqrt(acc_se(&a0) * acc_se(&a0) + acc_se(&a1) * acc_se(&a1)) &&
                  s1.bounce_rays < s0.bounce_rays * 6 / 10,
              "Russian roulette: same mean, fewer bounces", "means %.5f %.5f, bounce rays %llu vs %llu", acc_mean(&a0), acc_mean(&a1),
              (unsigned long long)s0.bounce_rays, (unsigned long long)s1.bounce_rays);
    }
    {   /* bounce limit 0: emission only */
        float o[3] = { 0, 0, 0 }, dd[3] = { 0, 1, 0 }, rgb[3];
        fovpt_rng rng;
        c = fovpt_config_default();
        c.max_depth = 0;
        fovpt_rng_init(&rng, 0, 0, 0, 0);
        c.max_depth = 0;
        {
            fovpt_config c0 = c;
            c0.max_depth = 0;
            /* max_depth 0 in a resolved config means no bounce */
            fovpt_radiance(&b.s, &c0, o, dd, &rng, rgb, NULL);
        }
        check(fabsf(rgb[0] - 0.3f) < 1e-6f, "bounce limit 0: emission only", "%g", (double)rgb[0]);
    }
    /* (c) non-finite radiance is replaced and counted */
    free(b.mem);
    m.emission[0] = m.emission[1] = m.emission[2] = 3e38f;
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    check(build(&b, &d) == FOV_ERR_LIMIT, "scene rejects an emitted power that overflows float", " ");
    free(b.mem);
    m.emission[0] = m.emission[1] = m.emission[2] = 2e37f;
    fovpt_shape_sphere(&sh, 0.0f, 0.0f, 0.0f, 0.5f, 0);
    {
        float o[3] = { 0, 0, 0 }, dd[3] = { 0, 1, 0 }, rgb[3] = { 1, 1, 1 };
        fovpt_rng rng;
        fov_result r = build(&b, &d);
        c = fovpt_config_default();
        c.max_depth = 40;
        memset(&st, 0, sizeof st);
        fovpt_rng_init(&rng, 0, 0, 0, 0);
        fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, &st);
        check(r == FOV_OK && st.bad_samples == 1 && rgb[0] <= 0.0f && rgb[0] >= 0.0f, "overflowing radiance -> black, counted in bad_samples",
              "%s bad %llu rgb %g", fovpt_result_string(r), (unsigned long long)st.bad_samples, (double)rgb[0]);
    }
    free(b.mem);
}

/* a small Cornell-like box: Lambert walls, a Phong sphere, a quad light */
static void cornell(fovpt_material *m, fovpt_shape *sh, fovpt_scene_desc *d, int mirror_glass)
{
    float p[3], u[3], v[3], nn[3];
    int i;
    for (i = 0; i < 6; ++i) fovpt_material_init(&m[i]);
    m[1].albedo[1] = m[1].albedo[2] = 0.1f;           /* red */
    m[2].albedo[0] = m[2].albedo[2] = 0.1f;           /* green */
    m[3].emission[0] = m[3].emission[1] = m[3].emission[2] = 15.0f;
    m[4].type = FOVPT_MAT_PHONG;
    m[4].albedo[0] = 0.2f; m[4].albedo[1] = 0.3f; m[4].albedo[2] = 0.5f;
    m[4].specular[0] = m[4].specular[1] = m[4].specular[2] = 0.4f;
    m[4].exponent = 30.0f;
    m[5].type = mirror_glass ? FOVPT_MAT_DIELECTRIC : FOVPT_MAT_MIRROR;
    m[5].albedo[0] = m[5].albedo[1] = m[5].albedo[2] = 0.95f;
    fovpt__set3(p, 0, -1, 0); fovpt__set3(nn, 0, 1, 0); fovpt_shape_plane(&sh[0], p, nn, 0);   /* floor */
    fovpt__set3(p, 0, 1, 0); fovpt__set3(nn, 0, -1, 0); fovpt_shape_plane(&sh[1], p, nn, 0);   /* ceiling */
    fovpt__set3(p, 0, 0, 1); fovpt__set3(nn, 0, 0, -1); fovpt_shape_plane(&sh[2], p, nn, 0);   /* back */
    fovpt__set3(p, -1, -1, -1); fovpt__set3(u, 0, 2, 0); fovpt__set3(v, 0, 0, 2); fovpt_shape_quad(&sh[3], p, u, v, 1);
    fovpt__set3(p, 1, -1, -1); fovpt_shape_quad(&sh[4], p, u, v, 2);
    fovpt__set3(p, -0.25f, 0.999f, -0.25f); fovpt__set3(u, 0.5f, 0, 0); fovpt__set3(v, 0, 0, 0.5f); fovpt_shape_quad(&sh[5], p, u, v, 3);
    fovpt_shape_sphere(&sh[6], -0.4f, -0.6f, 0.3f, 0.4f, 4);
    fovpt_shape_sphere(&sh[7], 0.45f, -0.65f, -0.2f, 0.35f, 5);
    fovpt_scene_desc_init(d);
    d->shapes = sh; d->num_shapes = 8; d->materials = m; d->num_materials = 6;
    d->background[0] = d->background[1] = d->background[2] = 0.05f;
}

static void test_nee_equivalence(void)
{
    fovpt_material m[6];
    fovpt_shape sh[8];
    fovpt_scene_desc d;
    scene_buf b;
    int glass;
    for (glass = 0; glass < 2; ++glass) {
        stat_acc a[2] = { { 0, 0, 0 }, { 0, 0, 0 } };
        int nee, i;
        cornell(m, sh, &d, glass);
        build(&b, &d);
        for (nee = 0; nee < 2; ++nee) {
            fovpt_config c = fovpt_config_default();
            c.no_nee = (uint32_t)(1 - nee);
            for (i = 0; i < 60000; ++i) {
                fovpt_camera cam;
                float o[3], dd[3], rgb[3];
                fovpt_rng rng;
                fovpt_camera_init(&cam, 32, 32);
                cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
                cam.pos[2] = -3.0f;
                fovpt_camera_ray(&cam, frand(0.0f, 32.0f), frand(0.0f, 32.0f), o, dd);
                fovpt_rng_init(&rng, 21 + (uint32_t)nee, (uint32_t)i, 0, 0);
                fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, NULL);
                acc_add(&a[nee], (double)(rgb[0] + rgb[1] + rgb[2]) / 3.0);
            }
        }
        {
            double dm = fabs(acc_mean(&a[0]) - acc_mean(&a[1])), se = sqrt(acc_se(&a[0]) * acc_se(&a[0]) + acc_se(&a[1]) * acc_se(&a[1]));
            check(dm < 3.0 * se && acc_se(&a[1]) < acc_se(&a[0]),
                  N("Cornell box with %s: NEE on and off agree within 3 standard errors, NEE has less noise", glass ? "glass" : "mirror"),
                  "off %.5f (se %.5f) on %.5f (se %.5f)", acc_mean(&a[0]), acc_se(&a[0]), acc_mean(&a[1]), acc_se(&a[1]));
        }
        free(b.mem);
    }
}

static void test_whitted(void)
{
    fovpt_material m[3];
    fovpt_shape sh[3];
    fovpt_scene_desc d;
    scene_buf b;
    fovpt_config c;
    float p[3] = { 0, 0, 0 }, nn[3] = { 0, 1, 0 }, q[3] = { -0.05f, 2.0f, -0.05f }, u[3] = { 0.1f, 0, 0 }, v[3] = { 0, 0, 0.1f };
    float o[3] = { 0, 1, 0 }, dd[3] = { 0, -1, 0 }, rgb[3];
    fovpt_rng rng;
    fovpt_material_init(&m[0]);
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 0.5f;
    fovpt_material_init(&m[1]);
    m[1].emission[0] = m[1].emission[1] = m[1].emission[2] = 10.0f;
    fovpt_shape_plane(&sh[0], p, nn, 0);
    fovpt_shape_quad(&sh[1], q, u, v, 1);
    fovpt_scene_desc_init(&d);
    d.shapes = sh; d.num_shapes = 2; d.materials = m; d.num_materials = 2;
    build(&b, &d);
    memset(&c, 0, sizeof c);
    c.mode = FOVPT_MODE_WHITTED;
    fovpt_config_resolve(&c, &c);
    fovpt_rng_init(&rng, 0, 0, 0, 0);
    fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, NULL);
    {
        double expect = 0.5 / 3.141592653589793 * 10.0 * 0.01 / 4.0;
        check(fabs((double)rgb[0] - expect) < 1e-5 * expect + 1e-9, "Whitted: small quad light over a Lambert plane = kd/pi Le A / d^2",
              "%.7f vs %.7f", (double)rgb[0], expect);
        /* the path tracer converges to nearly the same (the light is small) */
        {
            stat_acc a = { 0, 0, 0 };
            int i;
            fovpt_config pc = fovpt_config_default();
            pc.max_depth = 1;
            for (i = 0; i < 20000; ++i) {
                fovpt_rng_init(&rng, 4, (uint32_t)i, 0, 0);
                fovpt_radiance(&b.s, &pc, o, dd, &rng, rgb, NULL);
                acc_add(&a, (double)rgb[0]);
            }
            check(fabs(acc_mean(&a) - expect) < 3.0 * acc_se(&a) + 0.01 * expect, "path tracer (NEE) agrees with it for a small light",
                  "%.7f (se %.7f) vs %.7f", acc_mean(&a), acc_se(&a), expect);
        }
    }
    free(b.mem);
    /* mirror under a uniform background: tint * background; depth 0 stops before it */
    m[0].type = FOVPT_MAT_MIRROR;
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 0.8f;
    d.num_shapes = 1;
    d.background[0] = d.background[1] = d.background[2] = 1.0f;
    build(&b, &d);
    {
        float dd2[3] = { 0.3f, -1.0f, 0.1f };
        fovpt_radiance(&b.s, &c, o, dd2, &rng, rgb, NULL);
        check(fabsf(rgb[1] - 0.8f) < 1e-6f, "Whitted mirror: tint x background", "%g", (double)rgb[1]);
        c.max_depth = 0;
        fovpt_radiance(&b.s, &c, o, dd2, &rng, rgb, NULL);
        check(rgb[1] <= 0.0f, "Whitted depth 0: no reflection ray", "%g", (double)rgb[1]);
    }
    free(b.mem);
    /* a glass box under a uniform background: both Fresnel branches keep the energy */
    {
        float lo[3] = { -1, -1, -1 }, hi[3] = { 1, 1, 1 };
        float dd3[3] = { 0.2f, -0.1f, 1.0f }, o3[3] = { 0.1f, 0.2f, -5.0f };
        m[0].type = FOVPT_MAT_DIELECTRIC;
        m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 1.0f;
        fovpt_shape_box(&sh[0], lo, hi, 0);
        build(&b, &d);
        c.max_depth = 14;
        fovpt_radiance(&b.s, &c, o3, dd3, &rng, rgb, NULL);
        check(rgb[0] > 0.97f && rgb[0] < 1.0f + 1e-5f, "Whitted glass box, depth 14: reflected + refracted energy ~ 1", "%g", (double)rgb[0]);
        c.max_depth = 1;
        fovpt_radiance(&b.s, &c, o3, dd3, &rng, rgb, NULL);
        check(rgb[0] > 0.03f && rgb[0] < 0.06f, "Whitted glass box, depth 1: only the first reflection (about 4 %)", "%g", (double)rgb[0]);
        free(b.mem);
    }
}

static void test_render(void)
{
    fovpt_material m[6];
    fovpt_shape sh[8];
    fovpt_scene_desc d;
    scene_buf b;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fov_gaze g = { 24.0f, 16.0f };
    size_t n = 0;
    void *mem;
    uint8_t img1[48 * 32 * 3], img2[48 * 32 * 3], img3[48 * 32 * 3];
    float f1[48 * 32 * 3];
    fovpt_output out;
    fovpt_stats st;
    fov_result r;
    cornell(m, sh, &d, 0);
    build(&b, &d);
    fovpt_camera_init(&cam, 48, 32);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -3.0f;
    c.spp = 4;
    r = fovpt_memory_size(&c, &cam, &n);
    check(r == FOV_OK && n == 48u * 32u * 16u, "memory_size UNIFORM = 16 bytes per pixel", "%s %zu", fovpt_result_string(r), n);
    mem = amalloc(n);
    r = fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n);
    check(r == FOV_OK, "init", "%s", fovpt_result_string(r));
    fovpt_output_init(&out);
    out.rgb8 = img1; out.rgb = f1;
    memset(&st, 0, sizeof st);
    fovpt_render(&ctx, 0, &out, &st);
    check(st.camera_rays == 48u * 32u * 4u && st.samples == st.camera_rays && st.rays == st.camera_rays + st.bounce_rays + st.shadow_rays &&
              st.shadow_rays > 0,
          "stats: camera rays = pixels x spp, rays = sum of kinds", "cam %llu rays %llu", (unsigned long long)st.camera_rays,
          (unsigned long long)st.rays);
    {
        int i, finite = 1;
        for (i = 0; i < 48 * 32 * 3; ++i) if (!(f1[i] >= 0.0f && f1[i] < 1e6f)) finite = 0;
        check(finite, "image finite and non-negative", " ");
    }
    out.rgb = NULL;
    out.rgb8 = img2;
    fovpt_render(&ctx, 0, &out, NULL);
    check(memcmp(img1, img2, sizeof img1) == 0, "deterministic: same seed and frame -> identical image", " ");
    /* rows in three uneven bands, in reverse order */
    fovpt_trace_rows(&ctx, 0, 20, 32, NULL);
    fovpt_trace_rows(&ctx, 0, 7, 20, NULL);
    fovpt_trace_rows(&ctx, 0, 0, 7, NULL);
    out.rgb8 = img3;
    fovpt_resolve_rows(&ctx, 0, 32, &out);
    check(memcmp(img1, img3, sizeof img1) == 0, "row bands in any order -> the same image", " ");
    fovpt_render(&ctx, 1, &out, NULL);
    check(memcmp(img1, img3, sizeof img1) != 0, "another frame index -> another noise pattern", " ");
    {
        fovpt_config c2 = c;
        fovpt_ctx ctx2;
        c2.seed = 99;
        fovpt_init(&ctx2, &c2, &b.s, &cam, g, mem, n);
        fovpt_render(&ctx2, 0, &out, NULL);
        check(memcmp(img1, img3, sizeof img1) != 0, "another seed -> another noise pattern", " ");
    }
    /* progressive accumulation: 8 frames of 4 spp = one frame of 32 spp in expectation,
       and the noise falls: compare both against a 256-spp reference */
    {
        static float ref[48 * 32 * 3], acc[48 * 32 * 3], one[48 * 32 * 3];
        fovpt_config ca = c;
        fovpt_ctx cx;
        int f, i;
        double e_acc = 0.0, e_one = 0.0;
        ca.spp = 256; ca.seed = 5;
        fovpt_init(&cx, &ca, &b.s, &cam, g, mem, n);
        out.rgb8 = NULL; out.rgb = ref;
        fovpt_render(&cx, 0, &out, NULL);
        ca.spp = 4; ca.seed = 6;
        fovpt_init(&cx, &ca, &b.s, &cam, g, mem, n);
        out.rgb = one;
        fovpt_render(&cx, 0, &out, NULL);
        ca.accumulate = 1;
        fovpt_init(&cx, &ca, &b.s, &cam, g, mem, n);
        for (f = 0; f < 8; ++f) fovpt_trace_rows(&cx, (uint32_t)f, 0, 32, NULL);
        out.rgb = acc;
        fovpt_resolve_rows(&cx, 0, 32, &out);
        for (i = 0; i < 48 * 32 * 3; ++i) {
            e_acc += ((double)acc[i] - (double)ref[i]) * ((double)acc[i] - (double)ref[i]);
            e_one += ((double)one[i] - (double)ref[i]) * ((double)one[i] - (double)ref[i]);
        }
        check(e_acc < e_one / 4.0, "progressive accumulation: 8 frames x 4 spp have under 1/4 the squared error of 4 spp",
              "sq err %.4f vs %.4f", e_acc, e_one);
        {
            fovpt_camera cam2 = cam;
            cam2.pos[0] = 0.1f;
            fovpt_set_view(&cx, &cam2, g);
            check(cx.accum[3] <= 0.0f, "set_view with a moved camera resets the accumulation", "%g", (double)cx.accum[3]);
        }
    }
    /* bad input */
    {
        fovpt_camera bc = cam;
        fov_gaze bg = { NAN, 0.0f };
        fovpt_config bcfg = c;
        check(fovpt_init(&ctx, &c, &b.s, &cam, bg, mem, n) == FOV_ERR_NOT_FINITE, "init: NaN gaze", " ");
        bc.width = 0;
        check(fovpt_init(&ctx, &c, &b.s, &bc, g, mem, n) == FOV_ERR_INVALID_ARG, "init: width 0", " ");
        bc.width = 70000;
        check(fovpt_init(&ctx, &c, &b.s, &bc, g, mem, n) == FOV_ERR_LIMIT, "init: width above FOVPT_MAX_DIM", " ");
        bc = cam; bc.pos[1] = INFINITY;
        check(fovpt_init(&ctx, &c, &b.s, &bc, g, mem, n) == FOV_ERR_NOT_FINITE, "init: infinite camera", " ");
        bc = cam; bc.target[2] = bc.pos[2];
        check(fovpt_init(&ctx, &c, &b.s, &bc, g, mem, n) == FOV_ERR_DEGENERATE, "init: camera target = position", " ");
        bc = cam; bc.fov_y_deg = 180.0f;
        check(fovpt_init(&ctx, &c, &b.s, &bc, g, mem, n) == FOV_ERR_INVALID_ARG, "init: fov 180", " ");
        check(fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n - 1u) == FOV_ERR_TOO_SMALL, "init: memory too small", " ");
        check(fovpt_init(&ctx, &c, &b.s, &cam, g, NULL, n) == FOV_ERR_NULL, "init: memory NULL", " ");
        bcfg.temporal.reuse = 1;
        check(fovpt_memory_size(&bcfg, &cam, &n) == FOV_ERR_UNSUPPORTED, "temporal reuse with UNIFORM: FOV_ERR_UNSUPPORTED (SELECTIVE, JIN only)", " ");
        fovpt_memory_size(&c, &cam, &n);
        fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n);
        check(fovpt_trace_rows(&ctx, 0, 10, 40, NULL) == FOV_ERR_INVALID_ARG && fovpt_trace_rows(&ctx, 0, 10, 5, NULL) == FOV_ERR_INVALID_ARG,
              "trace_rows: rows outside the image", " ");
        out.rgb8_stride = 10;
        out.rgb8 = img1;
        check(fovpt_resolve_rows(&ctx, 0, 1, &out) == FOV_ERR_INVALID_ARG, "resolve_rows: stride below 3 * width", " ");
        {
            float o[3] = { 0, 0, 0 }, dd[3] = { NAN, 0, 1 }, rgb[3];
            fovpt_rng rng;
            fovpt_rng_init(&rng, 0, 0, 0, 0);
            check(fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, NULL) == FOV_ERR_NOT_FINITE, "radiance: NaN direction", " ");
            dd[0] = 0.0f; dd[2] = 0.0f;
            check(fovpt_radiance(&b.s, &c, o, dd, &rng, rgb, NULL) == FOV_ERR_DEGENERATE, "radiance: zero direction", " ");
        }
    }
    free(mem);
    free(b.mem);
}

/* ==== 5. foveation building blocks ============================================================ */
static void test_foveation_blocks(void)
{
    int i, ok = 1, lin = 1, ends = 1;
    for (i = 0; i <= 100; ++i) {
        float t = (float)i / 100.0f, w[4], v;
        fovpt_catmull_rom(t, w);
        if (fabsf(w[0] + w[1] + w[2] + w[3] - 1.0f) > 1e-6f) ok = 0;
        v = w[0] * 1.0f + w[1] * 3.0f + w[2] * 5.0f + w[3] * 7.0f; /* a linear ramp 1, 3, 5, 7 */
        if (fabsf(v - (3.0f + 2.0f * t)) > 1e-5f) lin = 0;
    }
    {
        float w[4];
        fovpt_catmull_rom(0.0f, w);
        if (fabsf(w[1] - 1.0f) > 0.0f || fabsf(w[0]) > 0.0f || fabsf(w[2]) > 0.0f) ends = 0;
        fovpt_catmull_rom(1.0f, w);
        if (fabsf(w[2] - 1.0f) > 1e-7f || fabsf(w[1]) > 1e-7f || fabsf(w[3]) > 1e-7f) ends = 0;
    }
    check(ok, "Catmull-Rom weights sum to one (101 values of t)", " ");
    check(lin, "Catmull-Rom reproduces linear ramps", " ");
    check(ends, "Catmull-Rom gives v1 at t = 0 and v2 at t = 1 (the thesis's -1/2 would give 2 v2)", " ");
    {   /* tau_fov against a table worked out by hand (the two shapes of Kim et al. 2021, Fig. 7) */
        static const float e[10] = { 0, 1, 2, 3.3f, 5.5f, 8, 12.1f, 20, 25, 30 };
        static const float r1[10] = { 1.000f, 1.124f, 1.428f, 2.000f, 3.090f, 4.300f, 6.209f, 9.509f, 11.160f, 12.000f };
        static const float r2[10] = { 9.000f, 9.042f, 9.210f, 10.000f, 12.676f, 14.760f, 17.015f, 19.245f, 19.830f, 20.000f };
        fovpt_config c = fovpt_config_default();
        float worst1 = 0.0f, worst2 = 0.0f, v;
        for (i = 0; i < 10; ++i) {
            fovpt_tau_fov(&c.selective, e[i], &v);
            worst1 = fmaxf(worst1, fabsf(v - r1[i]));
        }
        c.selective.tau_shape[0] = 9; c.selective.tau_shape[1] = 10; c.selective.tau_shape[2] = 1.5f; c.selective.tau_shape[3] = 20;
        for (i = 0; i < 10; ++i) {
            fovpt_tau_fov(&c.selective, e[i], &v);
            worst2 = fmaxf(worst2, fabsf(v - r2[i]));
        }
        check(worst1 < 1.5e-3f, "tau_fov (1, 2, 0.5, 12) matches the reference table (10 values)", "max err %g", (double)worst1);
        check(worst2 < 1.5e-3f, "tau_fov (9, 10, 1.5, 20) matches the reference table (10 values)", "max err %g", (double)worst2);
        {
            float a, b2, s0, s1;
            fovpt_tau_fov(&c.selective, 3.3f - 1e-3f, &a);
            fovpt_tau_fov(&c.selective, 3.3f + 1e-3f, &b2);
            fovpt_tau_fov(&c.selective, 1e-3f, &s0);
            fovpt_tau_fov(&c.selective, 30.0f - 1e-3f, &s1);
            check(fabsf((b2 - a) / 2e-3f - 1.5f) < 0.02f && fabsf(s0 - 9.0f) < 1e-4f && fabsf(s1 - 20.0f) < 1e-4f,
                  "tau_fov: slope tau'_f at e_f (C1), flat at 0 and e_np", "slope %g", (double)((b2 - a) / 2e-3f));
        }
        fovpt_tau_fov(&c.selective, 50.0f, &v);
        check(fabsf(v - 20.0f) < 1e-6f, "tau_fov beyond e_np = tau_np", " ");
        c.selective.tau_shape[2] = 0.01f;
        check(fovpt_tau_fov(&c.selective, 2.0f, &v) == FOV_ERR_INVALID_ARG && fovpt_tau_fov(&c.selective, NAN, &v) == FOV_ERR_NOT_FINITE,
              "tau_fov: non-monotone shape and NaN rejected", " ");
    }
    {   /* alpha(e): values worked out by hand from the six nodes (Kim et al. 2021, Sec. 4.7) */
        fovpt_config c = fovpt_config_default();
        float a2 = fovpt_alpha(&c.temporal, &c.selective, 2.0f), a10 = fovpt_alpha(&c.temporal, &c.selective, 10.0f);
        float a20 = fovpt_alpha(&c.temporal, &c.selective, 20.0f), a40 = fovpt_alpha(&c.temporal, &c.selective, 40.0f);
        float a90 = fovpt_alpha(&c.temporal, &c.selective, 90.0f), a0 = fovpt_alpha(&c.temporal, &c.selective, 0.0f);
        check(fabsf(a2 - 0.839f) < 1e-3f && fabsf(a10 - 0.564f) < 1e-3f && fabsf(a20 - 0.368f) < 1e-3f && fabsf(a40 - 0.133f) < 1e-3f &&
                  fabsf(a90 - 0.1f) < 1e-6f && fabsf(a0 - 0.9f) < 1e-6f,
              "alpha(e): 0.9 at 0, 0.839 at 2, 0.564 at 10, 0.368 at 20, 0.133 at 40, 0.1 beyond 45",
              "%g %g %g %g %g", (double)a2, (double)a10, (double)a20, (double)a40, (double)a90);
    }
}


/* ==== 6. LAYERS (Axblad 2020) ================================================================= */
typedef struct layers_fixture {
    fovpt_material m[2];
    fovpt_shape sh[2];
    fovpt_scene_desc d;
    scene_buf b;
} layers_fixture;

/* a large Lambert quad facing the camera, lit by a sphere light: a smooth image (Whitted) */
static void smooth_scene(layers_fixture *F, int empty)
{
    float p[3] = { -50, -50, 5 }, u[3] = { 100, 0, 0 }, v[3] = { 0, 100, 0 };
    fovpt_material_init(&F->m[0]);
    fovpt_material_init(&F->m[1]);
    F->m[1].emission[0] = 40.0f; F->m[1].emission[1] = 30.0f; F->m[1].emission[2] = 20.0f;
    fovpt_shape_quad(&F->sh[0], p, u, v, 0);
    fovpt_shape_sphere(&F->sh[1], 1.0f, 2.0f, -1.0f, 0.3f, 1); /* behind the camera */
    fovpt_scene_desc_init(&F->d);
    F->d.shapes = F->sh; F->d.num_shapes = empty ? 0u : 2u; F->d.materials = F->m; F->d.num_materials = 2;
    F->d.background[0] = 0.3f; F->d.background[1] = 0.2f; F->d.background[2] = 0.1f;
    build(&F->b, &F->d);
}

/* expected lattice counts, computed here from the documented rule with fovsdf's model */
static void expected_targets_lay(const fovpt_layers_cfg *lay, double reach, const fovpt_camera *cam, fov_gaze g, uint64_t *cnt);
static void expected_targets(const fovpt_config *c, const fovpt_camera *cam, fov_gaze g, uint64_t *cnt)
{
    expected_targets_lay(&c->layers, 2.0, cam, g, cnt);
}
static void expected_targets_lay(const fovpt_layers_cfg *lay, double reach, const fovpt_camera *cam, fov_gaze g, uint64_t *cnt)
{
    fov_ecc_model em;
    double f_px = 0.5 * cam->height / tan(0.5 * (double)cam->fov_y_deg * 3.141592653589793 / 180.0);
    uint32_t n, x, y;
    long gx = (long)floor((double)g.x), gy = (long)floor((double)g.y);
    fovsdf_ecc_init(&em, NULL, cam->fov_y_deg, cam->width, cam->height, g);
    for (n = 0; n < lay->count; ++n) {
        long d = (long)lay->layer[n].stride, ox = 0, oy = 0;
        double apron = (reach * sqrt(2.0) * (double)d + 1.0) / f_px * 180.0 / 3.141592653589793, tr;
        double r0 = (double)lay->layer[0].radius_deg;
        if (n > 0 && !lay->snap) { ox = ((gx % d) + d) % d; oy = ((gy % d) + d) % d; }
        if (ox > (long)cam->width - 1) ox = (long)cam->width - 1;    /* at least one lattice point */
        if (oy > (long)cam->height - 1) oy = (long)cam->height - 1;
        if (n == 0) tr = r0 > 0.0 ? r0 + apron : 1e30;
        else {
            tr = (double)lay->layer[n].radius_deg + 0.5 * (double)lay->blend_deg + apron;
            if (r0 > 0.0 && r0 + apron < tr) tr = r0 + apron;
        }
        cnt[n] = 0;
        for (y = 0; y < cam->height; ++y)
            for (x = 0; x < cam->width; ++x)
                if (((long)x - ox) % d == 0 && ((long)y - oy) % d == 0 &&
                    (double)fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f) <= tr + 1e-4)
                    cnt[n]++;
    }
}

static void test_layers(void)
{
    layers_fixture F;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_stats st;
    size_t n = 0, expect_bytes = 0;
    void *mem;
    uint32_t W = 160, H = 120, i, L;
    fovpt_output out;
    static float img[160 * 120 * 3], ref[160 * 120 * 3];
    fov_gaze centre = { 80.3f, 60.7f }, corner = { 2.0f, 3.0f };
    uint64_t rays_centre = 0, rays_corner = 0;
    int gi;
    smooth_scene(&F, 0);
    fovpt_camera_init(&cam, W, H);
    cam.pos[2] = 0.0f; cam.target[2] = 1.0f; /* fovpt_camera_init's former default view */
    cam.fov_y_deg = 90.0f;
    c.method = FOVPT_METHOD_LAYERS;
    c.mode = FOVPT_MODE_WHITTED;
    fovpt_config_resolve(&c, &c);
    for (L = 0; L < 4; ++L) {
        uint32_t d = c.layers.layer[L].stride;
        expect_bytes += (((size_t)(W / d + 2u) * (H / d + 2u) * 16u + 15u) & ~(size_t)15u);
    }
    check(fovpt_memory_size(&c, &cam, &n) == FOV_OK && n == expect_bytes, "LAYERS memory = sum of lattice grids (W/d+2)(H/d+2) x 16 B",
          "%zu vs %zu", n, expect_bytes);
    mem = amalloc(n);
    for (gi = 0; gi < 4; ++gi) {
        fov_gaze g = gi % 2 ? corner : centre;
        uint64_t expect[FOVPT_MAX_LAYERS], total = 0;
        int ok = 1;
        fovpt_config cc = c;
        if (gi >= 2) cc.layers.layer[0].radius_deg = 45.0f; /* an occlusion mask */
        fovpt_init(&ctx, &cc, &F.b.s, &cam, g, mem, n);
        memset(&st, 0, sizeof st);
        fovpt_trace_rows(&ctx, 0, 0, H, &st);
        expected_targets(&cc, &cam, g, expect);
        for (L = 0; L < 4; ++L) {
            if (st.layer_targets[L] != expect[L] || st.layer_samples[L] != 4u * expect[L]) ok = 0;
            total += 4u * expect[L];
        }
        check(ok && st.camera_rays == total,
              N("LAYERS lattice counts per layer match the rule (gaze %s, %s); rays = spp x targets", gi % 2 ? "corner" : "centre",
                gi >= 2 ? "mask 45 deg" : "no mask"),
              "targets %llu %llu %llu %llu, expected %llu %llu %llu %llu", (unsigned long long)st.layer_targets[0],
              (unsigned long long)st.layer_targets[1], (unsigned long long)st.layer_targets[2], (unsigned long long)st.layer_targets[3],
              (unsigned long long)expect[0], (unsigned long long)expect[1], (unsigned long long)expect[2], (unsigned long long)expect[3]);
        if (gi == 2) rays_centre = st.camera_rays;
        if (gi == 3) rays_corner = st.camera_rays;
        if (gi == 0) {
            check(st.layer_targets[3] < st.layer_targets[2] * 4u && st.layer_targets[0] == (uint64_t)(W / 4u) * (H / 4u),
                  "LAYERS: the background lattice covers the image at stride 4", "%llu", (unsigned long long)st.layer_targets[0]);
        }
    }
    check(rays_corner < rays_centre, "LAYERS: a corner gaze with the mask traces fewer rays (layers leave the mask)",
          "corner %llu centre %llu", (unsigned long long)rays_corner, (unsigned long long)rays_centre);
    /* quality on a smooth image: LAYERS vs UNIFORM (both Whitted, 4 spp) per ring */
    {
        fovpt_config cu = c;
        fov_ecc_model em;
        double se[4] = { 0, 0, 0, 0 };
        long cnt[4] = { 0, 0, 0, 0 };
        float rings[4] = { 6.0f, 10.0f, 20.0f, 1000.0f };
        uint32_t x, y;
        void *mu;
        size_t nu;
        cu.method = FOVPT_METHOD_UNIFORM;
        cu.spp = 4;
        fovpt_memory_size(&cu, &cam, &nu);
        mu = amalloc(nu);
        fovpt_init(&ctx, &cu, &F.b.s, &cam, centre, mu, nu);
        fovpt_output_init(&out);
        out.rgb = ref;
        fovpt_render(&ctx, 0, &out, NULL);
        free(mu);
        fovpt_init(&ctx, &c, &F.b.s, &cam, centre, mem, n);
        out.rgb = img;
        fovpt_render(&ctx, 0, &out, NULL);
        fovsdf_ecc_init(&em, NULL, 90.0f, W, H, centre);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float e = fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
                int r = e < rings[0] ? 0 : e < rings[1] ? 1 : e < rings[2] ? 2 : 3;
                for (i = 0; i < 3; ++i) {
                    double dd = (double)img[3u * (y * W + x) + i] - (double)ref[3u * (y * W + x) + i];
                    se[r] += dd * dd;
                }
                cnt[r] += 3;
            }
        for (i = 0; i < 4; ++i) {
            double psnr = 10.0 * log10(1.0 / (se[i] / (double)cnt[i] + 1e-30));
            check(psnr > 40.0, N("LAYERS on a smooth image: PSNR against UNIFORM > 40 dB in ring %u (fill + blend)", i),
                  "%.1f dB", psnr);
        }
    }
    /* constant image: every pixel inside the mask = the background, outside black */
    {
        layers_fixture E;
        fovpt_config ce = c;
        fov_ecc_model em;
        uint32_t x, y, bad = 0;
        int black_ok = 1;
        smooth_scene(&E, 1);
        ce.layers.layer[0].radius_deg = 45.0f;
        fovpt_init(&ctx, &ce, &E.b.s, &cam, corner, mem, n);
        out.rgb = img;
        fovpt_render(&ctx, 0, &out, NULL);
        fovsdf_ecc_init(&em, NULL, 90.0f, W, H, corner);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float e = fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f), *p = img + 3u * (y * W + x);
                if (e < 44.9f && (fabsf(p[0] - 0.3f) > 1e-5f || fabsf(p[2] - 0.1f) > 1e-5f)) bad++;
                if (e > 45.1f && (p[0] > 0.0f || p[1] > 0.0f)) black_ok = 0;
            }
        check(bad == 0, "LAYERS on a constant image reproduces it exactly (interpolation weights sum to 1)", "%u bad pixels", bad);
        check(black_ok, "LAYERS: pixels beyond the occlusion mask are black", " ");
        free(E.b.mem);
    }
    /* row bands: same image */
    {
        static uint8_t a8[160 * 120 * 3], b8[160 * 120 * 3];
        fovpt_config cp = c;
        cp.mode = FOVPT_MODE_PATH;
        fovpt_init(&ctx, &cp, &F.b.s, &cam, centre, mem, n);
        fovpt_output_init(&out);
        out.rgb8 = a8;
        fovpt_render(&ctx, 3, &out, NULL);
        fovpt_trace_rows(&ctx, 3, 50, 120, NULL);
        fovpt_trace_rows(&ctx, 3, 0, 50, NULL);
        fovpt_resolve_rows(&ctx, 60, 120, &out);
        out.rgb8 = b8;
        fovpt_resolve_rows(&ctx, 0, 120, &out);
        check(memcmp(a8, b8, sizeof a8) == 0, "LAYERS (path mode): row bands in any order -> the same image", " ");
    }
    free(mem);
    free(F.b.mem);
}

/* ==== 7. ZONES (Polychronakis 2025, ch. 4) =================================================== */
static void test_zones(void)
{
    layers_fixture F;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default(), cu;
    fovpt_ctx ctx;
    fovpt_stats st, su;
    size_t n = 0, nu = 0;
    void *mem, *mu;
    uint32_t W = 160, H = 120, i;
    fovpt_output out;
    static float img[160 * 120 * 3], ref[160 * 120 * 3];
    fov_gaze g = { 70.2f, 50.9f };
    fov_ecc_model em;
    smooth_scene(&F, 0);
    fovpt_camera_init(&cam, W, H);
    cam.pos[2] = 0.0f; cam.target[2] = 1.0f; /* fovpt_camera_init's former default view */
    cam.fov_y_deg = 90.0f;
    c.method = FOVPT_METHOD_ZONES;
    c.mode = FOVPT_MODE_WHITTED;
    c.spp = 2;
    c.zones.inner_deg = 10.0f;
    c.zones.middle_deg = 25.0f;
    fovpt_config_resolve(&c, &c);
    {
        size_t e = 0;
        uint32_t k, ds[3] = { 4, 2, 1 };
        for (k = 0; k < 3; ++k) e += ((size_t)(W / ds[k] + 2u) * (H / ds[k] + 2u) * 16u + 15u) & ~(size_t)15u;
        check(fovpt_memory_size(&c, &cam, &n) == FOV_OK && n == e, "ZONES memory = lattices of stride 4, 2, 1", "%zu vs %zu", n, e);
    }
    mem = amalloc(n);
    fovpt_init(&ctx, &c, &F.b.s, &cam, g, mem, n);
    memset(&st, 0, sizeof st);
    fovpt_trace_rows(&ctx, 0, 0, H, &st);
    {
        fovpt_layers_cfg lay;
        uint64_t expect[FOVPT_MAX_LAYERS];
        fovsdf_ecc_init(&em, NULL, 90.0f, W, H, g);
        memset(&lay, 0, sizeof lay);
        lay.count = 3;
        lay.layer[0].stride = 4; lay.layer[1].stride = 2; lay.layer[2].stride = 1;
        lay.layer[1].radius_deg = 25.0f; lay.layer[2].radius_deg = 10.0f;
        lay.snap = 1;
        lay.blend_deg = c.zones.overlap_px / fovsdf_ecc_ppd(&em);
        expected_targets_lay(&lay, 3.0, &cam, g, expect);
        check(st.layer_targets[0] == expect[0] && st.layer_targets[1] == expect[1] && st.layer_targets[2] == expect[2] &&
                  expect[0] == (uint64_t)(W / 4u) * (H / 4u) && st.camera_rays == 2u * (expect[0] + expect[1] + expect[2]),
              "ZONES: samples per zone match the rule (stride 4 everywhere, 2 and 1 inside the zones)",
              "%llu %llu %llu vs %llu %llu %llu", (unsigned long long)st.layer_targets[0], (unsigned long long)st.layer_targets[1],
              (unsigned long long)st.layer_targets[2], (unsigned long long)expect[0], (unsigned long long)expect[1],
              (unsigned long long)expect[2]);
    }
    fovpt_output_init(&out);
    out.rgb = img;
    fovpt_resolve_rows(&ctx, 0, H, &out);
    cu = c;
    cu.method = FOVPT_METHOD_UNIFORM;
    fovpt_memory_size(&cu, &cam, &nu);
    mu = amalloc(nu);
    fovpt_init(&ctx, &cu, &F.b.s, &cam, g, mu, nu);
    memset(&su, 0, sizeof su);
    out.rgb = ref;
    fovpt_render(&ctx, 0, &out, &su);
    check(st.camera_rays < su.camera_rays * 6u / 10u, "ZONES trace fewer camera rays than UNIFORM", "%llu vs %llu",
          (unsigned long long)st.camera_rays, (unsigned long long)su.camera_rays);
    {
        double se[3] = { 0, 0, 0 };
        long cnt[3] = { 0, 0, 0 };
        uint32_t x, y;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float e = fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
                int r = e < 10.0f ? 0 : e < 25.0f ? 1 : 2;
                for (i = 0; i < 3; ++i) {
                    double dd = (double)img[3u * (y * W + x) + i] - (double)ref[3u * (y * W + x) + i];
                    se[r] += dd * dd;
                }
                cnt[r] += 3;
            }
        for (i = 0; i < 3; ++i) {
            double psnr = 10.0 * log10(1.0 / (se[i] / (double)(cnt[i] ? cnt[i] : 1) + 1e-30));
            check(cnt[i] > 0 && psnr > 40.0, N("ZONES on a smooth image: PSNR against UNIFORM > 40 dB in zone %u (Lanczos + blend)", i),
                  "%.1f dB", psnr);
        }
    }
    {   /* constant image reproduced */
        layers_fixture E;
        uint32_t x, bad = 0;
        smooth_scene(&E, 1);
        fovpt_init(&ctx, &c, &E.b.s, &cam, g, mem, n);
        out.rgb = img;
        fovpt_render(&ctx, 0, &out, NULL);
        for (x = 0; x < W * H; ++x)
            if (fabsf(img[3u * x] - 0.3f) > 1e-5f || fabsf(img[3u * x + 2u] - 0.1f) > 1e-5f) bad++;
        check(bad == 0, "ZONES on a constant image reproduces it (normalised Lanczos weights)", "%u bad pixels", bad);
        free(E.b.mem);
    }
    free(mu);
    free(mem);
    free(F.b.mem);
}

/* ==== 8. SELECTIVE and JIN (Kim et al. 2021) ================================================== */
static fovpt__pre mkpre(float r, float g, float b, uint32_t poid, float nz, uint32_t psc, uint32_t soid)
{
    fovpt__pre p;
    memset(&p, 0, sizeof p);
    p.col[0] = r; p.col[1] = g; p.col[2] = b;
    p.poid = poid; p.soid = soid;
    p.pn[0] = sqrtf(fmaxf(0.0f, 1.0f - nz * nz)); p.pn[2] = nz;
    p.sn[2] = 1.0f;
    p.sc = psc;
    return p;
}

static void test_selective_rules(void)
{
    fovpt_config c = fovpt_config_default();
    const fovpt_selective_cfg *sc = &c.selective;
    float ct = cosf(10.0f * 3.14159265f / 180.0f);
    fovpt__pre P = mkpre(0.5f, 0.5f, 0.5f, 1, 1.0f, 0, FOVPT_PRIM_NONE), A = P, B = P, C = P;
    const fovpt__pre *Q[3];
    Q[0] = &A; Q[1] = &B; Q[2] = &C;
    check(fabsf(fovpt__tau_sel(sc, &P, Q, ct) - 0.02f) < 1e-7f, "tau_sel: no discordant attribute -> tau_col (0.02)", " ");
    B.poid = 2;
    check(fabsf(fovpt__tau_sel(sc, &P, Q, ct) - 0.05f) < 1e-7f, "tau_sel: another object id -> tau_poid (0.05)", " ");
    B = P;
    C = mkpre(0.5f, 0.5f, 0.5f, 1, cosf(20.0f * 3.14159265f / 180.0f), 0, FOVPT_PRIM_NONE);
    check(fabsf(fovpt__tau_sel(sc, &P, Q, ct) - 0.06f) < 1e-7f, "tau_sel: normals 20 degrees apart (tolerance 10) -> tau_psn (0.06)", " ");
    C = mkpre(0.5f, 0.5f, 0.5f, 1, cosf(5.0f * 3.14159265f / 180.0f), 0, FOVPT_PRIM_NONE);
    check(fabsf(fovpt__tau_sel(sc, &P, Q, ct) - 0.02f) < 1e-7f, "tau_sel: normals 5 degrees apart are concordant", " ");
    A.sc = 1;
    check(fabsf(fovpt__tau_sel(sc, &P, Q, ct) - 0.06f) < 1e-7f, "tau_sel: another shadow count -> tau_psc (0.06)", " ");
    B.soid = 7;
    check(fabsf(fovpt__tau_sel(sc, &P, Q, ct) - 0.02f) < 1e-7f, "tau_sel: several discordant -> the minimum (tau_soid 0.02)", " ");
    /* contrast: channel thresholds tau * (1.36, 1.02, 2.04) */
    A = B = C = P;
    {
        float t = 0.05f, g_below, g_above;
        /* contrast (mx - mn)/(mx + mn) = k  <=>  mx = mn (1 + k) / (1 - k) */
        g_below = 0.5f * (1.0f + 0.99f * t * 1.02f) / (1.0f - 0.99f * t * 1.02f);
        g_above = 0.5f * (1.0f + 1.01f * t * 1.02f) / (1.0f - 1.01f * t * 1.02f);
        A.col[1] = g_below;
        check(!fovpt__contrast(&P, Q, t), "contrast: green just below tau x 1.02 is not problematic", " ");
        A.col[1] = g_above;
        check(fovpt__contrast(&P, Q, t), "contrast: green just above tau x 1.02 is problematic", " ");
        A.col[1] = 0.5f;
        C.col[2] = 0.5f * (1.0f + 1.5f * t * 1.02f) / (1.0f - 1.5f * t * 1.02f); /* 1.5x the green limit, below blue's 2.04 */
        check(!fovpt__contrast(&P, Q, t), "contrast: blue uses the looser 2.04 factor", " ");
        C.col[2] = 0.0f; C.col[0] = 0.0f; C.col[1] = 0.0f;
        check(fovpt__contrast(&P, Q, t), "contrast: black next to grey is problematic", " ");
        A = B = C = P;
        P.col[0] = P.col[1] = P.col[2] = 0.0f;
        A.col[0] = A.col[1] = A.col[2] = 0.0f; B.col[0] = B.col[1] = B.col[2] = 0.0f; C.col[0] = C.col[1] = C.col[2] = 0.0f;
        check(!fovpt__contrast(&P, Q, t), "contrast: all black is not problematic (no division by zero)", " ");
    }
}

static double ring_psnr(const float *a, const float *b, uint32_t W, uint32_t H, fov_gaze g, float fov, float lo, float hi)
{
    fov_ecc_model em;
    double se = 0.0;
    long cnt = 0;
    uint32_t x, y, k;
    fovsdf_ecc_init(&em, NULL, fov, W, H, g);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            float e = fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
            if (e < lo || e >= hi) continue;
            for (k = 0; k < 3; ++k) {
                double va = fmin(1.0, (double)a[3u * (y * W + x) + k]), vb = fmin(1.0, (double)b[3u * (y * W + x) + k]);
                se += (va - vb) * (va - vb);
            }
            cnt += 3;
        }
    return cnt ? 10.0 * log10(1.0 / (se / (double)cnt + 1e-12)) : 0.0;
}

static void test_selective_render(void)
{
    fovpt_material m[6];
    fovpt_shape sh[8];
    fovpt_scene_desc d;
    scene_buf b;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default(), cj, cr, c1;
    fovpt_ctx ctx;
    fovpt_stats ss, sj, s1;
    fovpt_output out;
    size_t n = 0, nmax = 0;
    void *mem;
    uint32_t W = 96, H = 72, z;
    static float sel[96 * 72 * 3], jin[96 * 72 * 3], ref[96 * 72 * 3], one[96 * 72 * 3];
    fov_gaze g = { 40.0f, 40.0f };
    cornell(m, sh, &d, 0);
    build(&b, &d);
    fovpt_camera_init(&cam, W, H);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -3.0f;
    cam.fov_y_deg = 50.0f;
    c.method = FOVPT_METHOD_SELECTIVE;
    c.mode = FOVPT_MODE_WHITTED;
    fovpt_config_resolve(&c, &c);
    check(fovpt_memory_size(&c, &cam, &n) == FOV_OK && n == (size_t)W * H * 68u, "SELECTIVE memory = 68 bytes per pixel", "%zu", n);
    cr = c; cr.method = FOVPT_METHOD_UNIFORM; cr.spp = 64;
    fovpt_memory_size(&cr, &cam, &nmax);
    mem = amalloc(n > nmax ? n : nmax);
    fovpt_init(&ctx, &cr, &b.s, &cam, g, mem, nmax);
    fovpt_output_init(&out);
    out.rgb = ref;
    fovpt_render(&ctx, 0, &out, NULL);
    c1 = cr; c1.spp = 1; c1.seed = 3;
    fovpt_init(&ctx, &c1, &b.s, &cam, g, mem, nmax);
    memset(&s1, 0, sizeof s1);
    out.rgb = one;
    fovpt_render(&ctx, 0, &out, &s1);
    memset(&ss, 0, sizeof ss);
    fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n);
    out.rgb = sel;
    fovpt_render(&ctx, 0, &out, &ss);
    cj = c; cj.method = FOVPT_METHOD_JIN;
    memset(&sj, 0, sizeof sj);
    fovpt_init(&ctx, &cj, &b.s, &cam, g, mem, n);
    out.rgb = jin;
    fovpt_render(&ctx, 0, &out, &sj);
    {
        int ok = 1;
        for (z = 0; z < 4; ++z) if (ss.extra_samples[z] != c.selective.n_sd[z] * ss.problematic[z]) ok = 0;
        check(ok && ss.problematic[0] > 0 && ss.camera_rays == (uint64_t)W * H + ss.extra_samples[0] + ss.extra_samples[1] +
                                                                    ss.extra_samples[2] + ss.extra_samples[3],
              "SELECTIVE: n_sd (9, 4, 2, 1) samples per problematic subpixel by zone; rays = presamples + extras",
              "problematic %llu %llu %llu %llu extra %llu %llu %llu %llu", (unsigned long long)ss.problematic[0],
              (unsigned long long)ss.problematic[1], (unsigned long long)ss.problematic[2], (unsigned long long)ss.problematic[3],
              (unsigned long long)ss.extra_samples[0], (unsigned long long)ss.extra_samples[1], (unsigned long long)ss.extra_samples[2],
              (unsigned long long)ss.extra_samples[3]);
        check(sj.extra_samples[0] == 4u * sj.problematic[0] && sj.problematic[0] > ss.problematic[0] + ss.problematic[1],
              "JIN: 4 samples per problematic subpixel everywhere, more problematic subpixels than SELECTIVE (tau_fov >= 1)",
              "jin %llu problematic vs selective %llu", (unsigned long long)sj.problematic[0],
              (unsigned long long)(ss.problematic[0] + ss.problematic[1] + ss.problematic[2] + ss.problematic[3]));
    }
    {
        float e_f = c.selective.e_deg[0];
        double pf_sel = ring_psnr(sel, ref, W, H, g, 50.0f, 0.0f, e_f), pf_jin = ring_psnr(jin, ref, W, H, g, 50.0f, 0.0f, e_f);
        double pf_one = ring_psnr(one, ref, W, H, g, 50.0f, 0.0f, e_f);
        double pn_sel = ring_psnr(sel, ref, W, H, g, 50.0f, 12.1f, 30.0f), pn_jin = ring_psnr(jin, ref, W, H, g, 50.0f, 12.1f, 30.0f);
        printf("# SELECTIVE fovea %.2f dB, near periphery %.2f dB; JIN %.2f / %.2f dB; 1 spp fovea %.2f dB; rays sel %llu jin %llu\n",
               pf_sel, pn_sel, pf_jin, pn_jin, pf_one, (unsigned long long)ss.camera_rays, (unsigned long long)sj.camera_rays);
        check(pf_sel > pf_one + 3.0, "SELECTIVE fovea PSNR > 1 spp + 3 dB (against 64 spp)", "%.2f vs %.2f", pf_sel, pf_one);
        check(pf_sel >= pf_jin - 0.5, "SELECTIVE fovea PSNR at least Jin's (9 vs 4 samples per subpixel)", "%.2f vs %.2f", pf_sel, pf_jin);
        check(pn_jin >= pn_sel, "JIN beats SELECTIVE in the near periphery (the pattern of Kim et al. 2021)", "%.2f vs %.2f", pn_jin, pn_sel);
        check(ss.camera_rays < sj.camera_rays, "SELECTIVE traces fewer rays than JIN", "%llu vs %llu", (unsigned long long)ss.camera_rays,
              (unsigned long long)sj.camera_rays);
    }
    {   /* row-band invariance of the refine pass */
        static float b2[96 * 72 * 3];
        fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n);
        fovpt_trace_rows(&ctx, 0, 30, 72, NULL);
        fovpt_trace_rows(&ctx, 0, 0, 30, NULL);
        fovpt_refine_rows(&ctx, 0, 50, 72, NULL);
        fovpt_refine_rows(&ctx, 0, 0, 50, NULL);
        out.rgb = b2;
        fovpt_resolve_rows(&ctx, 0, 72, &out);
        check(memcmp(b2, sel, sizeof b2) == 0, "SELECTIVE: row bands in any order -> the same image", " ");
    }
    free(mem);
    free(b.mem);
}

/* ==== 9. temporal reuse and smoothing (Kim et al. 2021, steps 2 and 4) ======================== */
static void test_temporal(void)
{
    fovpt_material m[6];
    fovpt_shape sh[8];
    fovpt_scene_desc d;
    scene_buf b;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default(), cn;
    fovpt_ctx ctx, cref;
    fovpt_output out;
    fovpt_stats st;
    size_t n = 0, nn = 0;
    void *mem, *mem2;
    uint32_t W = 64, H = 48, f, i, maxf = 0, bg_reused = 0;
    static float img[64 * 48 * 3], ref[64 * 48 * 3];
    fov_gaze g = { 32.0f, 24.0f };
    cornell(m, sh, &d, 0);
    build(&b, &d);
    fovpt_camera_init(&cam, W, H);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -3.0f;
    c.method = FOVPT_METHOD_SELECTIVE;
    c.mode = FOVPT_MODE_WHITTED;
    c.temporal.reuse = 1;
    fovpt_config_resolve(&c, &c);
    check(fovpt_memory_size(&c, &cam, &n) == FOV_OK && n == (size_t)W * H * (68u + 2u * 32u),
          "reuse memory: 68 + 2 frames x 32 bytes per pixel", "%zu", n);
    mem = amalloc(n);
    fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n);
    cn = c; cn.temporal.reuse = 0;
    fovpt_memory_size(&cn, &cam, &nn);
    mem2 = amalloc(nn);
    fovpt_init(&cref, &cn, &b.s, &cam, g, mem2, nn);
    fovpt_output_init(&out);
    {
        static float prev_ref[64 * 48 * 3];
        double se_all = 0.0, se_prev_all = 0.0;
        uint32_t exact_bad = 0;
        for (f = 0; f < 8; ++f) {
            double se = 0.0, se_prev = 0.0;
            memset(&st, 0, sizeof st);
            out.rgb = img;
            fovpt_render(&ctx, f, &out, &st);
            out.rgb = ref;
            fovpt_render(&cref, f, &out, NULL);
            for (i = 0; i < W * H; ++i) {
                const float *h = ctx.hist[ctx.hist_cur] + 8u * i;
                const fovpt__pre *P = (const fovpt__pre *)ctx.pre + i;
                if (h[7] > (float)maxf) maxf = (uint32_t)h[7];
                if (P->poid == FOVPT_PRIM_NONE && h[7] > 0.0f) bg_reused++;
                /* frame 1, static view: a reused pixel is the previous frame's colour */
                if (f == 1 && h[7] > 0.5f && (img[3u * i] < prev_ref[3u * i] || img[3u * i] > prev_ref[3u * i])) exact_bad++;
            }
            for (i = 0; i < W * H * 3u; ++i) {
                double dd = fmin(1.0, (double)img[i]) - fmin(1.0, (double)ref[i]);
                double dp = fmin(1.0, (double)prev_ref[i]) - fmin(1.0, (double)ref[i]);
                se += dd * dd;
                se_prev += dp * dp;
            }
            if (f == 0) check(st.reused == 0, "reuse: nothing reused in the first frame", "%llu", (unsigned long long)st.reused);
            if (f == 1) check(st.reused > (uint64_t)W * H / 4u, "reuse: a static view reuses many pixels in the second frame", "%llu of %u",
                              (unsigned long long)st.reused, W * H);
            /* a reused colour is another frame's independent samples: in expectation it costs
               what one frame of sampling noise costs (summed over frames 1-7: a few light-edge
               pixels dominate single frames) */
            if (f > 0) { se_all += se; se_prev_all += se_prev; }
            memcpy(prev_ref, ref, sizeof prev_ref);
            fovpt_set_view(&ctx, &cam, g);
            fovpt_set_view(&cref, &cam, g);
        }
        check(exact_bad == 0, "reuse: reused pixels carry the previous frame's colour exactly (static view)", "%u differ", exact_bad);
        check(10.0 * log10(se_prev_all / (se_all + 1e-30)) > -1.0,
              "reuse vs no reuse: error within 1 dB of frame-to-frame sampling noise (frames 2-8 summed)", "%.2f dB",
              10.0 * log10(se_prev_all / (se_all + 1e-30)));
    }
    check(maxf == 5, "reuse: a pixel is reused at most n_reuse_max = 5 frames in a row", "max %u", maxf);
    check(bg_reused == 0, "reuse: pixels whose ray misses are never reused", "%u", bg_reused);
    free(mem); free(mem2);
    /* smoothing: static view, path-traced (noisy): the smoothed image is closer to a
       converged one than the raw frame, most of all in the periphery (alpha 0.1 .. 0.2) */
    {
        fovpt_config cs = fovpt_config_default(), cg;
        static float gt[64 * 48 * 3], raw[64 * 48 * 3];
        double e_s = 0.0, e_r = 0.0;
        fov_ecc_model em;
        uint32_t x, y;
        cs.method = FOVPT_METHOD_SELECTIVE;
        cs.temporal.smooth = 1;
        cam.fov_y_deg = 90.0f;
        fovpt_config_resolve(&cs, &cs);
        cg = fovpt_config_default(); cg.spp = 256; cg.seed = 99;
        fovpt_memory_size(&cg, &cam, &nn);
        mem2 = amalloc(nn);
        fovpt_init(&cref, &cg, &b.s, &cam, g, mem2, nn);
        out.rgb = gt;
        fovpt_render(&cref, 0, &out, NULL);
        free(mem2);
        fovpt_memory_size(&cs, &cam, &n);
        check(n == (size_t)W * H * (68u + 5u * 32u), "smoothing memory: 68 + 5 frames x 32 bytes per pixel", "%zu", n);
        mem = amalloc(n);
        fovpt_init(&ctx, &cs, &b.s, &cam, g, mem, n);
        for (f = 0; f < 5; ++f) {
            out.rgb = img;
            fovpt_render(&ctx, f, &out, NULL);
            if (f < 4) fovpt_set_view(&ctx, &cam, g);
        }
        /* the raw frame 4: accumulator without smoothing */
        for (i = 0; i < W * H; ++i) for (x = 0; x < 3; ++x) raw[3u * i + x] = ctx.accum[4u * i + x] / ctx.accum[4u * i + 3u];
        fovsdf_ecc_init(&em, NULL, 90.0f, W, H, g);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                uint32_t k, idx = y * W + x;
                if (fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f) < 30.0f) continue;
                for (k = 0; k < 3; ++k) {
                    double a = fmin(1.0, (double)img[3u * idx + k]) - fmin(1.0, (double)gt[3u * idx + k]);
                    double r = fmin(1.0, (double)raw[3u * idx + k]) - fmin(1.0, (double)gt[3u * idx + k]);
                    e_s += a * a; e_r += r * r;
                }
            }
        check(e_s < 0.6 * e_r, "smoothing (alpha(e), 4 frames) lowers the squared error beyond 30 degrees by over 40 %",
              "%.4f vs %.4f", e_s, e_r);
        /* a moved camera: history whose first hit differs is rejected (no ghosting):
           after a large jump the output equals the raw frame where depths disagree */
        {
            fovpt_camera moved = cam;
            uint32_t same = 0, diff = 0;
            moved.pos[0] = 0.6f;
            moved.target[0] = 0.6f;
            fovpt_set_view(&ctx, &moved, g);
            out.rgb = img;
            fovpt_render(&ctx, 9, &out, NULL);
            for (i = 0; i < W * H; ++i) {
                float r0 = ctx.accum[4u * i] / ctx.accum[4u * i + 3u];
                if (fabsf(r0 - img[3u * i]) < 1e-6f) same++; else diff++;
            }
            check(same > 0 && diff > 0, "smoothing after a camera move: some pixels keep history, disoccluded ones do not",
                  "same %u blended %u", same, diff);
        }
        free(mem);
    }
    free(b.mem);
}

/* LAYERS on images smaller than a layer's stride, the gaze off the image, empty scene: every
   pixel must be the background (a layer without a lattice point read before its buffer and
   left black pixels; review finding). Random layer tables, strides up to 64. */
static void test_layers_tiny(void)
{
    fovpt_material mat;
    fovpt_scene_desc d;
    fovpt_scene sc;
    size_t sb = 0;
    void *smem;
    int k, inits = 0, bad_cfg = 0;
    uint32_t worst = 0;
    fovpt_material_init(&mat);
    fovpt_scene_desc_init(&d);
    d.materials = &mat; d.num_materials = 1;
    d.background[0] = d.background[1] = d.background[2] = 0.5f;
    fovpt_scene_size(&d, &sb);
    smem = amalloc(sb);
    fovpt_scene_build(&sc, &d, smem, sb);
    for (k = 0; k < 150; ++k) {
        fovpt_camera cam;
        fovpt_config c = fovpt_config_default();
        fovpt_ctx ctx;
        fovpt_output out;
        size_t cb = 0;
        void *cmem;
        float *img;
        uint32_t W = 1u + (uint32_t)(urand() * 60.0), H = 1u + (uint32_t)(urand() * 8.0), n, i, wrong = 0;
        fov_gaze g;
        if (k & 1) { uint32_t t = W; W = H; H = t; }
        g.x = frand(-2.0f * (float)W, 3.0f * (float)W);
        g.y = frand(-2.0f * (float)H, 3.0f * (float)H);
        fovpt_camera_init(&cam, W, H);
        cam.pos[2] = 0.0f; cam.target[2] = 1.0f; /* fovpt_camera_init's former default view */
        c.method = FOVPT_METHOD_LAYERS;
        c.layers.count = 2u + (uint32_t)(urand() * 3.0);
        for (n = 0; n < c.layers.count; ++n) {
            /* layer 0 outermost (radius: the occlusion mask, 0 = none), radii decreasing */
            c.layers.layer[n].radius_deg = n == 0 ? ((k & 2) ? 150.0f : 0.0f) : 120.0f / (float)n;
            c.layers.layer[n].stride = 1u + (uint32_t)(urand() * 64.0);
            c.layers.layer[n].spp = 1;
        }
        if (fovpt_memory_size(&c, &cam, &cb) != FOV_OK) { bad_cfg++; continue; }
        cmem = amalloc(cb);
        img = (float *)malloc(sizeof(float) * 3u * W * H);
        if (fovpt_init(&ctx, &c, &sc, &cam, g, cmem, cb) == FOV_OK) {
            fov_ecc_model em;
            inits++;
            fovpt_output_init(&out);
            out.rgb = img;
            fovsdf_ecc_init(&em, NULL, cam.fov_y_deg, W, H, g);
            if (fovpt_render(&ctx, 0, &out, NULL) != FOV_OK) wrong = W * H;
            else
                for (i = 0; i < 3u * W * H; ++i) {
                    /* beyond the occlusion mask (layer 0's radius) the image is black by design */
                    float e = fovsdf_ecc_deg(&em, (float)((i / 3u) % W) + 0.5f, (float)((i / 3u) / W) + 0.5f);
                    float r0 = c.layers.layer[0].radius_deg, want = r0 > 0.0f && e > r0 + 1e-3f ? 0.0f : 0.5f;
                    if (r0 > 0.0f && fabsf(e - r0) <= 1e-3f) continue;   /* on the border: either */
                    wrong += !(fabsf(img[i] - want) <= 1e-5f);
                }
        } else {
            bad_cfg++;
        }
        if (wrong > worst) worst = wrong;
        if (wrong && getenv("DBG")) {
            printf("# k %d: %ux%u gaze (%g, %g) count %u:", k, W, H, (double)g.x, (double)g.y, c.layers.count);
            for (n = 0; n < c.layers.count; ++n) printf(" [r %g d %u o %u,%u n %ux%u]", (double)c.layers.layer[n].radius_deg, c.layers.layer[n].stride,
                                                          ctx.layer_ox[n], ctx.layer_oy[n], ctx.layer_nx[n], ctx.layer_ny[n]);
            printf(" wrong %u img0 %g\n", wrong, (double)img[0]);
        }
        free(img);
        free(cmem);
    }
    check(inits >= 100 && worst == 0,
          "layers: strides up to 64 on images of 1..60 x 1..8, gaze off the image, empty scene: background inside the mask, black beyond",
          "%d of 150 configs ran (%d refused); worst %u wrong values", inits, bad_cfg, worst);
    free(smem);
}

/* a failed fovpt_set_view leaves the view as it was (review finding: it kept the new camera) */
static void test_set_view_atomic(void)
{
    layers_fixture F;
    fovpt_camera cam, cam2;
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output out;
    size_t cb = 0;
    void *cmem;
    static float before[24 * 16 * 3], after[24 * 16 * 3];
    fov_gaze g = { 0.0f, 0.0f }, far = { 3e38f, 0.0f };
    fov_result r;
    smooth_scene(&F, 0);
    fovpt_camera_init(&cam, 24, 16);
    cam.pos[2] = 0.0f; cam.target[2] = 1.0f; /* fovpt_camera_init's former default view */
    c.method = FOVPT_METHOD_LAYERS;
    c.display.axis_dx = -3e38f;   /* legal; with a gaze at 3e38 the gaze ray overflows */
    fovpt_memory_size(&c, &cam, &cb);
    cmem = amalloc(cb);
    r = fovpt_init(&ctx, &c, &F.b.s, &cam, g, cmem, cb);
    fovpt_output_init(&out);
    out.rgb = before;
    if (r == FOV_OK) r = fovpt_render(&ctx, 0, &out, NULL);
    cam2 = cam;
    cam2.pos[0] += 0.5f;
    {
        fov_result rs = fovpt_set_view(&ctx, &cam2, far);
        out.rgb = after;
        if (r == FOV_OK) r = fovpt_render(&ctx, 0, &out, NULL);
        check(r == FOV_OK && rs != FOV_OK && memcmp(before, after, sizeof before) == 0,
              "set_view that fails (gaze ray overflows) leaves the view unchanged: same image", "init/render %d, set_view %d", (int)r, (int)rs);
    }
    free(cmem);
    free(F.b.mem);
}

/* review item: the per-frame latency margin on a context (fovpt_set_gaze_margin) grows the
   layer radii and keeps the lattices' accumulation; a per-frame fovpt_init resets it */
static float max_weight(const fovpt_ctx *ctx)
{
    float w = 0.0f;
    uint32_t n, k;
    for (n = 0; n < ctx->lay.count; ++n)
        for (k = 0; k < ctx->layer_nx[n] * ctx->layer_ny[n]; ++k)
            if (ctx->layer_buf[n][4u * k + 3u] > w) w = ctx->layer_buf[n][4u * k + 3u];
    return w;
}
static void test_set_gaze_margin(void)
{
    layers_fixture F;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default(), z, rc;
    fovpt_ctx ctx, saved;
    fovpt_output out;
    size_t cb = 0;
    void *cmem, *snap;
    static float img[24 * 16 * 3];
    fov_gaze g = { 12.0f, 8.0f };
    float w0, w1, tr0[FOVPT_MAX_LAYERS];
    fov_result r;
    uint32_t n;
    int grew = 1;
    smooth_scene(&F, 0);
    fovpt_camera_init(&cam, 24, 16);
    cam.pos[2] = 0.0f; cam.target[2] = 1.0f;
    c.method = FOVPT_METHOD_LAYERS;
    c.accumulate = 1; /* a still view: the lattices add up frames */
    fovpt_config_resolve(&c, &rc);
    fovpt_memory_size(&c, &cam, &cb);
    cmem = amalloc(cb);
    snap = malloc(cb);
    r = fovpt_init(&ctx, &c, &F.b.s, &cam, g, cmem, cb);
    fovpt_output_init(&out);
    out.rgb = img;
    if (r == FOV_OK) r = fovpt_render(&ctx, 0, &out, NULL);
    w0 = max_weight(&ctx);
    for (n = 0; n < ctx.lay.count; ++n) tr0[n] = ctx.layer_trace_deg[n];
    memcpy(snap, cmem, cb);
    r = r == FOV_OK ? fovpt_set_gaze_margin(&ctx, &c, 2.0f) : r;
    check(r == FOV_OK && memcmp(snap, cmem, cb) == 0,
          "set_gaze_margin: OK, the lattices' accumulation untouched", "%d", (int)r);
    for (n = 1; n < ctx.lay.count; ++n)
        if (!(fabsf(ctx.cfg.layers.layer[n].radius_deg - rc.layers.layer[n].radius_deg - 2.0f) <
                  1e-4f && ctx.layer_trace_deg[n] >= tr0[n] + 1.999f))
            grew = 0;
    check(grew && ctx.lay.count > 1u, "set_gaze_margin: layer radii and trace radii grow by it",
          "count %u", ctx.lay.count);
    fovpt_render(&ctx, 1, &out, NULL);
    {
        /* the lattice points traced before keep their samples; the grown radii trace more */
        const float *a = (const float *)snap;
        uint32_t kept = 1, before = 0, after = 0, k;
        for (n = 0; n < ctx.lay.count; ++n) {
            const float *b = ctx.layer_buf[n];
            const float *a0 = a + (b - (const float *)cmem);
            for (k = 0; k < ctx.layer_nx[n] * ctx.layer_ny[n]; ++k) {
                if (a0[4u * k + 3u] > 0.0f) {
                    before++;
                    if (!(b[4u * k + 3u] > a0[4u * k + 3u])) kept = 0; /* added to */
                }
                if (b[4u * k + 3u] > 0.0f) after++;
            }
        }
        w1 = max_weight(&ctx);
        check(w0 > 0.0f && w1 >= w0 && kept && before > 0u && after > before,
              "set_gaze_margin: traced points accumulate over it, the grown radii trace more",
              "kept %u, points %u -> %u", kept, before, after);
    }
    /* errors leave the context as it was */
    saved = ctx;
    z = c; z.method = FOVPT_METHOD_ZONES;
    check(fovpt_set_gaze_margin(&ctx, &z, 1.0f) == FOV_ERR_INVALID_ARG &&
          memcmp(&saved, &ctx, sizeof ctx) == 0, "set_gaze_margin: another method rejected", "-");
    check(fovpt_set_gaze_margin(&ctx, &c, -1.0f) == FOV_ERR_INVALID_ARG &&
          memcmp(&saved, &ctx, sizeof ctx) == 0, "set_gaze_margin: negative rejected", "-");
    check(fovpt_set_gaze_margin(NULL, &c, 1.0f) == FOV_ERR_NULL, "set_gaze_margin: NULL", "-");
    /* control: fovpt_init with the grown config (the old per-frame recipe) resets it */
    fovpt_config_gaze_margin(&c, 2.0f, &z);
    fovpt_init(&ctx, &z, &F.b.s, &cam, g, cmem, cb);
    check(max_weight(&ctx) <= 0.0f, "set_gaze_margin: control, fovpt_init resets the lattices",
          "%g", (double)max_weight(&ctx));
    free(snap);
    free(cmem);
    free(F.b.mem);
}

/* ==== issue 10: F1 camera rays, F7 BVH box test, BVH = brute force on adversarial scenes === */
/* the camera ray in double, from the documented model: f = normalize(target - pos), right =
   normalize(f x up), up' = right x f, image-plane offsets sx = tan_l + (tan_r - tan_l) x / w,
   sy = tan_t + (tan_b - tan_t) y / h (symmetric: tan_r = -tan_l = ty w / h, ty = tan(fov/2)) */
static int ref_camera_dir(const fovpt_camera *c, double x, double y, double d[3])
{
    double f[3], u[3], r[3], l, ty, tx, sx, sy;
    int k;
    for (k = 0; k < 3; ++k) { f[k] = (double)c->target[k] - (double)c->pos[k]; u[k] = (double)c->up[k]; }
    l = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]); for (k = 0; k < 3; ++k) f[k] /= l;
    l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); for (k = 0; k < 3; ++k) u[k] /= l;
    r[0] = f[1] * u[2] - f[2] * u[1]; r[1] = f[2] * u[0] - f[0] * u[2]; r[2] = f[0] * u[1] - f[1] * u[0];
    l = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]); for (k = 0; k < 3; ++k) r[k] /= l;
    u[0] = r[1] * f[2] - r[2] * f[1]; u[1] = r[2] * f[0] - r[0] * f[2]; u[2] = r[0] * f[1] - r[1] * f[0];
    ty = tan(0.5 * (double)(c->fov_y_deg > 0.0f ? c->fov_y_deg : 60.0f) * 3.14159265358979323846 / 180.0);
    tx = ty * (double)c->width / (double)c->height;
    sx = -tx + 2.0 * tx * x / (double)c->width;
    sy = ty - 2.0 * ty * y / (double)c->height;
    for (k = 0; k < 3; ++k) d[k] = f[k] + sx * r[k] + sy * u[k];
    l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (k = 0; k < 3; ++k) d[k] /= l;
    return fabs(sx) < 1e37 && fabs(sy) < 1e37; /* float image-plane offsets surely finite */
}

static void test_f1_camera_ray(void)
{
    static const float pts[][2] = { { 0.5f, 0.5f }, { 1e30f, 0.5f }, { 0.5f, 1e30f }, { -1e30f, -1e30f }, { 1e20f, -3e19f },
                                    { 3e38f, 0.5f }, { 0.5f, -3e38f }, { 1e-30f, 0.25f }, { 7.0f, 1e36f } };
    static const float ups[][3] = { { 3e38f, 3e38f, 3e38f }, { 0.0f, 1.0f, 0.0f }, { 1e-30f, 3e-30f, 0.0f }, { -3e38f, 3e38f, 1.0f } };
    int np = (int)(sizeof pts / sizeof pts[0]), nu = (int)(sizeof ups / sizeof ups[0]), i, j, c, bad_ok = 0, bad_code = 0, oks = 0,
        errs = 0;
    for (c = 0; c < 3; ++c)
        for (j = 0; j < nu; ++j) {
            fovpt_camera cam;
            fovpt_camera_init(&cam, c == 0 ? 1u : 16u, c == 0 ? 1u : 9u);
            cam.pos[0] = 0.0f; cam.pos[1] = 0.0f; cam.pos[2] = 0.0f;
            cam.target[0] = c == 2 ? 3e38f : 0.1f; cam.target[1] = 0.0f; cam.target[2] = c == 2 ? 3e38f : 1.0f;
            cam.up[0] = ups[j][0]; cam.up[1] = ups[j][1]; cam.up[2] = ups[j][2];
            for (i = 0; i < np; ++i) {
                float o[3], d[3];
                double ref[3], l, cosang;
                int finite_ref = ref_camera_dir(&cam, (double)pts[i][0], (double)pts[i][1], ref);
                fov_result e = fovpt_camera_ray(&cam, pts[i][0], pts[i][1], o, d);
                if (e == FOV_OK) {
                    l = sqrt((double)d[0] * (double)d[0] + (double)d[1] * (double)d[1] + (double)d[2] * (double)d[2]);
                    cosang = ((double)d[0] * ref[0] + (double)d[1] * ref[1] + (double)d[2] * ref[2]) / l;
                    if (!(fabs(l - 1.0) < 1e-6) || !(cosang > 1.0 - 1e-9)) {
                        if (bad_ok < 3)
                            printf("  camera %d up %d point (%g, %g): |dir| %.9g, cos to reference %.12g\n", c, j,
                                   (double)pts[i][0], (double)pts[i][1], l, cosang);
                        bad_ok++;
                    }
                    oks++;
                } else {
                    if (finite_ref || e != FOV_ERR_INVALID_ARG) bad_code++; /* offsets > 1e37: either */
                    errs++;
                }
            }
        }
    check(bad_ok == 0 && oks > 60, "F1: fovpt_camera_ray: every FOV_OK ray is finite, unit and the double-precision ray",
          "%d of %d FOV_OK rays wrong", bad_ok, oks);
    check(bad_code == 0 && errs > 0, "F1: image points whose image-plane offset overflows: FOV_ERR_INVALID_ARG, the others FOV_OK",
          "%d wrong codes of %d errors", bad_code, errs);
    {   /* a view vector that overflows (target - pos beyond FLT_MAX) is degenerate */
        fovpt_camera cam;
        float o[3], d[3];
        fovpt_camera_init(&cam, 1, 1);
        cam.pos[2] = -3e38f; cam.target[2] = 3e38f;
        check(fovpt_camera_ray(&cam, 0.5f, 0.5f, o, d) == FOV_ERR_DEGENERATE, "F1: a view vector beyond FLT_MAX: FOV_ERR_DEGENERATE", " ");
    }
}

static void test_version(void)
{
    char want[32], *src = read_file("fovpt.h"), line1[40];
    snprintf(want, sizeof want, "%d.%d.%d", FOVPT_VERSION_MAJOR, FOVPT_VERSION_MINOR, FOVPT_VERSION_PATCH);
    snprintf(line1, sizeof line1, "- v%s -", FOVPT_VERSION_STRING);
    check(strcmp(want, FOVPT_VERSION_STRING) == 0, "FOVPT_VERSION_STRING matches MAJOR.MINOR.PATCH", "%s vs %s", FOVPT_VERSION_STRING, want);
    check(src && strchr(src, '\n') && strstr(src, line1) && strstr(src, line1) < strchr(src, '\n'),
          "FOVPT_VERSION_STRING matches the version on line 1", "looked for \"%s\"", line1);
    free(src);
}

/* one triangle or quad scene for the F7 cases */
static fov_result f7_scene(scene_buf *b, const float *pos, uint32_t ntri, const fovpt_shape *sh, uint32_t ns, uint32_t min_prims,
                           fovpt_mesh *mesh, fovpt_material *m)
{
    fovpt_scene_desc d;
    fovpt_material_init(m);
    memset(mesh, 0, sizeof *mesh);
    mesh->positions = pos; mesh->num_vertices = 3u * ntri; mesh->num_triangles = ntri;
    fovpt_scene_desc_init(&d);
    d.meshes = ntri ? mesh : NULL; d.num_meshes = ntri ? 1u : 0u;
    d.shapes = sh; d.num_shapes = ns;
    d.materials = m; d.num_materials = 1;
    d.bvh_min_prims = min_prims;
    return build(b, &d);
}

static void test_f7_regressions(void)
{
    fovpt_material m;
    fovpt_mesh mesh;
    scene_buf b;
    fovpt_hit h, hb;
    memset(&h, 0, sizeof h); memset(&hb, 0, sizeof hb);
    {   /* (a) an axis-parallel ray lying in the box's max face x = 1 */
        static const float tri[9] = { -2, -2, 0, 1, -2, 0, 1, 1, 0 };
        const float o[3] = { 1.0f, 0.0f, 1.0f }, d[3] = { 0.0f, 0.0f, -1.0f };
        int a = 0, ab = 0, oc = 0;
        if (f7_scene(&b, tri, 1, NULL, 0, 1, &mesh, &m) == FOV_OK && b.s.nodes) {
            a = fovpt_intersect(&b.s, o, d, 0.0f, FLT_MAX, &h);
            ab = fovpt_intersect_brute(&b.s, o, d, 0.0f, FLT_MAX, &hb);
            oc = fovpt_occluded(&b.s, o, d, 0.0f, 2.0f);
        }
        /* independent: the point (1, 0, 0) lies on the edge x = 1 of the triangle, t = 1 */
        check(ab && hb.t == 1.0f, "F7a: brute force hits the edge x = 1 at t = 1 (reference)", "hit %d t %g", ab, (double)hb.t);
        check(a && h.t == 1.0f, "F7a: fovpt_intersect: a ray along -z in the box's max face hits at t = 1", "hit %d t %g", a,
              (double)h.t);
        check(oc == 1, "F7a: fovpt_occluded: the same ray is occluded before t = 2", "occluded %d", oc);
        free(b.mem);
    }
    {   /* (b) a flat square [-1, 0]^2 at z = -1 (two triangles; as a quad), a ray that needs a
           rounding margin in the box test */
        static const float sq[18] = { -1, -1, -1, 0, -1, -1, 0, 0, -1, -1, -1, -1, 0, 0, -1, -1, 0, -1 };
        const float o[3] = { 2.558f, 1.0000001f, 1.0000001f }, d[3] = { -1.558f, -0.5f, -1.0f };
        fovpt_shape q;
        const float qp[3] = { -1, -1, -1 }, qu[3] = { 1, 0, 0 }, qv[3] = { 0, 1, 0 };
        int rep;
        fovpt_shape_quad(&q, qp, qu, qv, 0);
        for (rep = 0; rep < 2; ++rep) {
            int a = 0, ab = 0, oc = 0, ok;
            if (rep == 0) ok = f7_scene(&b, sq, 2, NULL, 0, 1, &mesh, &m) == FOV_OK;
            else ok = f7_scene(&b, NULL, 0, &q, 1, 1, &mesh, &m) == FOV_OK;
            if (ok && b.s.nodes) {
                a = fovpt_intersect(&b.s, o, d, 0.0f, FLT_MAX, &h);
                ab = fovpt_intersect_brute(&b.s, o, d, 0.0f, FLT_MAX, &hb);
                oc = fovpt_occluded(&b.s, o, d, 0.0f, 3.0f);
            }
            check(ok && b.s.nodes && a == ab && (!a || h.t == hb.t) && oc == ab,
                  N("F7b: flat square as %s: BVH = brute force on a ray 1 ulp outside its box", rep ? "a quad" : "two triangles"),
                  "BVH %d (t %g), brute %d (t %g), occluded %d", a, (double)h.t, ab, (double)hb.t, oc);
            if (rep == 0) check(ab && fabsf(hb.t - 2.0f) < 1e-6f, "F7b: brute force hits the two-triangle square at t = 2", "%d %g", ab, (double)hb.t);
            free(b.mem);
        }
    }
}

/* BVH = brute force on adversarial scenes: axis-aligned flat quads (two triangles and quad
   shapes), triangles on a grid (shared edges and vertices, axis-parallel edges), boxes of
   zero thickness, scales 1e-3 .. 1e5 (some far from the origin); rays along axes, lying in
   box faces, from grid points (on faces and edges), aimed at vertices and edge points,
   grazing; negative, zero and positive tmin; bvh_min_prims and bvh_leaf 1 .. 4. The two
   traversals run the same per-primitive tests, so any difference is a box test that culled
   a node holding a hit. */
static float adv_grid(float S, float O, int lo, int hi) { return O + S * 0.25f * (float)(lo + (int)(urand() * (double)(hi - lo + 1))); }
/* 1 when the brute-force hit point o + t d (in double) lies outside its primitive's box (in
   double, from the primitive record; 1e-6 of the scale as tolerance): the triangle or quad
   test's t of a ray lying (almost) in the primitive's plane, ill-conditioned, not a hit a
   bounding box can hold */
static int adv_spurious(const fovpt_scene *s, const fovpt_hit *h, const float o[3], const float d[3])
{
    const fovpt__prim *p = (const fovpt__prim *)s->prims + h->slot;
    double lo[3], hi[3], P, tol;
    int k;
    if (p->type != FOVPT__TRI && p->type != FOVPT_SHAPE_QUAD) return 0;
    for (k = 0; k < 3; ++k) {
        double x0 = (double)p->a[k], x1 = x0 + (double)p->b[k], x2 = x0 + (double)p->c[k], x3 = x1 + (double)p->c[k];
        if (p->type == FOVPT__TRI) x3 = x0;
        lo[k] = fmin(fmin(x0, x1), fmin(x2, x3)); hi[k] = fmax(fmax(x0, x1), fmax(x2, x3));
    }
    for (k = 0; k < 3; ++k) {
        P = (double)o[k] + (double)h->t * (double)d[k];
        tol = 1e-6 * (fabs(lo[k]) + fabs(hi[k]) + fabs(P) + (hi[k] - lo[k]));
        if (P < lo[k] - tol || P > hi[k] + tol) return 1;
    }
    return 0;
}
/* The scene-memory size query against the build's new rules (leaves combined up to one
   block, padded to whole blocks, the W-wide node bound): 1 .. 70 primitives all identical,
   on a line, at exponentially growing distances (a caterpillar tree: leaves of 1 beside
   subtrees) and random; default, 1, 3 and 16 per leaf. Each build into exactly
   fovpt_scene_size bytes, the 64 bytes after them untouched, the node and slot counts within
   the documented bounds, hits = brute force. */
static void test_bvh_size_bound(void)
{
    static const uint32_t leafs[4] = { 0u, 1u, 3u, 16u };
    uint32_t kind, n, li, builds = 0, fails = 0, over = 0, guard = 0, mism = 0, hits = 0, rays = 0;
    for (kind = 0; kind < 4u; ++kind)
        for (n = 1; n <= 70u; ++n)
            for (li = 0; li < 4u; ++li) {
                float pos[9u * 70u];
                fovpt_material m;
                fovpt_mesh mesh;
                fovpt_scene_desc d;
                fovpt_scene sc;
                size_t bytes = 0, j;
                unsigned char *mem;
                uint32_t i, k, reserve;
                for (i = 0; i < n; ++i) {
                    float c[3], z = 1.0f; /* z: the triangle's size */
                    if (kind == 0) { c[0] = 0.5f; c[1] = -0.25f; c[2] = 1.0f; }
                    else if (kind == 1) { c[0] = 0.75f * (float)i; c[1] = 0.0f; c[2] = 2.0f; }
                    else if (kind == 2) { c[0] = ldexpf(1.0f, (int)(i % 40u)); c[1] = 0.0f; c[2] = 0.0f; z = 0.25f * c[0] + 1.0f; }
                    else { for (k = 0; k < 3; ++k) c[k] = frand(-3.0f, 3.0f); }
                    for (k = 0; k < 3; ++k) {
                        pos[9u * i + k] = c[k] - (k == 1 ? 0.3f * z : 0.0f);
                        pos[9u * i + 3u + k] = c[k] + (k == 0 ? 0.4f * z : 0.0f);
                        pos[9u * i + 6u + k] = c[k] + (k == 1 ? 0.3f * z : k == 2 ? 0.2f * z : 0.0f);
                    }
                }
                fovpt_material_init(&m);
                memset(&mesh, 0, sizeof mesh);
                mesh.positions = pos; mesh.num_vertices = 3u * n; mesh.num_triangles = n;
                fovpt_scene_desc_init(&d);
                d.meshes = &mesh; d.num_meshes = 1; d.materials = &m; d.num_materials = 1;
                d.bvh_min_prims = 1; d.bvh_leaf = leafs[li];
                if (fovpt_scene_size(&d, &bytes) != FOV_OK) { fails++; continue; }
                mem = (unsigned char *)amalloc(bytes + 64u);
                memset(mem, 0xA5, bytes + 64u);
                builds++;
                if (fovpt_scene_build(&sc, &d, mem, bytes) != FOV_OK || !sc.nodes) { fails++; free(mem); continue; }
                for (j = bytes; j < bytes + 64u; ++j) guard += mem[j] != 0xA5u;
                reserve = 4u * ((n + 3u) / 4u + (n + 15u) / 16u);
                if (sc.num_nodes4 > n / (FOVPT__COMBINE + 1u) + n / (FOVPT__W - 1u) + 1u || sc.num_slots > reserve ||
                    sc.num_slots < n || sc.num_slots % 4u != 0)
                    over++;
                {   /* and within the regions fovpt_scene_size laid out */
                    fovpt__layout L;
                    if (fovpt__plan(&d, &L) != FOV_OK || L.total != bytes ||
                        (L.order - L.nodes4) / sizeof(fovpt__node4) < sc.num_nodes4 ||
                        (L.lights - L.order) / 4u < sc.num_slots || (L.total - L.pbox) / (4u * FOVPT__LBLK) < sc.num_slots / 4u)
                        over++;
                }
                for (i = 0; i < 24u; ++i) {
                    float o[3], dd[3];
                    fovpt_hit h1, h2;
                    int a1, a2;
                    const float *t = pos + 9u * (i % n);
                    for (k = 0; k < 3; ++k) {
                        o[k] = frand(-4.0f, 4.0f) + (kind == 1 ? 0.375f * (float)n : 0.0f);
                        dd[k] = (t[k] + t[3u + k] + t[6u + k]) / 3.0f - o[k] + frand(-0.1f, 0.1f);
                    }
                    a1 = fovpt_intersect(&sc, o, dd, 0.0f, FLT_MAX, &h1);
                    a2 = fovpt_intersect_brute(&sc, o, dd, 0.0f, FLT_MAX, &h2);
                    if (a1 != a2 || (a1 && (!(h1.t <= h2.t && h1.t >= h2.t) || h1.prim != h2.prim))) mism++;
                    hits += (uint32_t)a1;
                    rays++;
                }
                free(mem);
            }
    check(fails == 0 && builds == 4u * 70u * 4u && guard == 0 && over == 0,
          "BVH size query: 1..70 identical / collinear / exponential / random triangles, leaf 0, 1, 3, 16: "
          "builds fit, nodes and leaf slots within the bounds",
          "fails %u of %u builds, %u guard bytes written, %u over a bound", fails, builds, guard, over);
    check(mism == 0 && hits > rays / 4u, "BVH size query scenes: BVH = brute force (t, primitive)",
          "%u mismatches, %u hits of %u rays", mism, hits, rays);
}

/* shapes that share one centroid (concentric spheres, boxes about one centre, with triangles
   around them): no split separates them, so they may share a leaf, but never more than
   FOVPT__LEAF_MAX (a leaf child's count has 5 bits); the BVH still equals brute force */
static void test_bvh_concentric(void)
{
    static const uint32_t counts[4] = { 3, 16, 17, 40 };
    int ci;
    for (ci = 0; ci < 4; ++ci) {
        uint32_t n = counts[ci], nt = 20, i, k, mism = 0, hits = 0, bad = 0, j;
        fovpt_shape sh[40];
        float pos[9u * 20u];
        fovpt_material m;
        fovpt_mesh mesh;
        fovpt_scene_desc d;
        scene_buf b;
        for (i = 0; i < n; ++i) {
            float lo[3], hi[3], r = 0.1f + 0.05f * (float)i;
            if (i % 3 == 2) {
                for (k = 0; k < 3; ++k) { lo[k] = 1.0f - r; hi[k] = 1.0f + r; }
                fovpt_shape_box(&sh[i], lo, hi, 0);
            } else {
                fovpt_shape_sphere(&sh[i], 1.0f, 1.0f, 1.0f, r, 0);
            }
        }
        for (i = 0; i < 9u * nt; ++i) pos[i] = frand(-6.0f, 6.0f);
        fovpt_material_init(&m);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = pos; mesh.num_vertices = 3u * nt; mesh.num_triangles = nt;
        fovpt_scene_desc_init(&d);
        d.shapes = sh; d.num_shapes = n; d.meshes = &mesh; d.num_meshes = 1; d.materials = &m; d.num_materials = 1;
        d.bvh_min_prims = 1; d.skip_degenerate = 1;
        if (!check(build(&b, &d) == FOV_OK && b.s.nodes4 != NULL, N("%u concentric shapes build a BVH", n), "no BVH")) {
            free(b.mem);
            continue;
        }
        {
            const fovpt__node4 *n4 = (const fovpt__node4 *)b.s.nodes4;
            for (i = 0; i < b.s.num_nodes4; ++i)
                for (j = 0; j < FOVPT__W; ++j)
                    if (!(n4[i].b[0][j] > n4[i].b[3][j]) && (n4[i].child[j] & FOVPT__LEAF4) &&
                        (n4[i].child[j] & 31u) > FOVPT__LEAF_MAX)
                        bad++;
        }
        for (i = 0; i < 3000; ++i) {
            float o[3], dd[3];
            fovpt_hit h1, h2;
            int a1, a2;
            for (k = 0; k < 3; ++k) { o[k] = frand(-5.0f, 7.0f); dd[k] = frand(-1.0f, 1.0f); }
            a1 = fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h1);
            a2 = fovpt_intersect_brute(&b.s, o, dd, 0.0f, FLT_MAX, &h2);
            if (a1 != a2 || (a1 && (!(h1.t <= h2.t && h1.t >= h2.t) || h1.prim != h2.prim))) mism++;
            hits += (uint32_t)a2;
        }
        check(bad == 0 && mism == 0 && hits > 300,
              N("%u concentric shapes: leaves of at most %u, BVH = brute force on 3000 rays", n, FOVPT__LEAF_MAX),
              "%u leaves over the limit, %u mismatches, %u hits", bad, mism, hits);
        free(b.mem);
    }
}

static void test_bvh_adversarial(void)
{
    static const float scales[6] = { 1e-3f, 0.1f, 1.0f, 10.0f, 1e3f, 1e5f };
#ifndef ADV_SCENES
#define ADV_SCENES 48
#endif
    int sc, nsc = ADV_SCENES;
    uint32_t total = 0, mism = 0, occ_mism = 0, hits = 0, built = 0, spurious = 0;
    for (sc = 0; sc < nsc; ++sc) {
        float S = scales[sc % 6], O = (sc / 6) % 4 == 3 ? 37.0f * S : 0.0f;
        float pos[9u * 64u];
        fovpt_shape sh[16];
        uint32_t nt = 0, ns = 0, i, k, ray;
        fovpt_material m;
        fovpt_mesh mesh;
        fovpt_scene_desc d;
        scene_buf b;
        uint32_t nq = 2u + (uint32_t)(urand() * 12.0);
        for (i = 0; i < nq && nt + 2u <= 64u; ++i) { /* axis-aligned flat rectangles, two triangles */
            uint32_t ax = (uint32_t)(urand() * 3.0) % 3u, a1 = (ax + 1u) % 3u, a2 = (ax + 2u) % 3u;
            float lv = adv_grid(S, O, -8, 8), x0 = adv_grid(S, O, -8, 4), y0 = adv_grid(S, O, -8, 4);
            float x1 = x0 + S * 0.25f * (float)(1 + (int)(urand() * 8.0)), y1 = y0 + S * 0.25f * (float)(1 + (int)(urand() * 8.0));
            float *p = pos + 9u * nt;
            p[ax] = p[3 + ax] = p[6 + ax] = p[9 + ax] = p[12 + ax] = p[15 + ax] = lv;
            p[a1] = x0; p[a2] = y0; p[3 + a1] = x1; p[3 + a2] = y0; p[6 + a1] = x1; p[6 + a2] = y1;
            p[9 + a1] = x0; p[9 + a2] = y0; p[12 + a1] = x1; p[12 + a2] = y1; p[15 + a1] = x0; p[15 + a2] = y1;
            nt += 2u;
        }
        while (nt < 24u + (uint32_t)(sc % 3) * 12u) { /* triangles on the grid */
            for (k = 0; k < 9; ++k) pos[9u * nt + k] = adv_grid(S, O, -8, 8);
            if (urand() < 0.3) pos[9u * nt + 2] = pos[9u * nt + 5] = pos[9u * nt + 8]; /* flat in z */
            nt++;
        }
        for (i = 0; i < 6u; ++i) { /* quads and boxes, some of zero thickness */
            float lo[3], hi[3], u[3] = { 0, 0, 0 }, v[3] = { 0, 0, 0 };
            for (k = 0; k < 3; ++k) { lo[k] = adv_grid(S, O, -8, 6); hi[k] = lo[k] + S * 0.25f * (float)(int)(urand() * 6.0); }
            if (i % 2 == 0) {
                uint32_t ax = i / 2u;
                u[(ax + 1u) % 3u] = S * 0.25f * (float)(1 + (int)(urand() * 6.0));
                v[(ax + 2u) % 3u] = S * 0.25f * (float)(1 + (int)(urand() * 6.0));
                fovpt_shape_quad(&sh[ns++], lo, u, v, 0);
            } else {
                int flat = 0; /* at most one axis of zero thickness (two: rejected) */
                for (k = 0; k < 3; ++k) if (!(hi[k] > lo[k]) && flat++) hi[k] = lo[k] + S;
                fovpt_shape_box(&sh[ns++], lo, hi, 0);
            }
        }
        fovpt_material_init(&m);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = pos; mesh.num_vertices = 3u * nt; mesh.num_triangles = nt;
        fovpt_scene_desc_init(&d);
        d.meshes = &mesh; d.num_meshes = 1; d.shapes = sh; d.num_shapes = ns;
        d.materials = &m; d.num_materials = 1;
        d.bvh_min_prims = 1u + (uint32_t)sc % 4u;
        d.bvh_leaf = 1u + (uint32_t)(sc / 4) % 4u;
        d.skip_degenerate = 1;
        { fov_result br = build(&b, &d); if (br != FOV_OK || !b.s.nodes) { printf("  scene %d: %s\n", sc, fovpt_result_string(br)); free(b.mem); continue; } }
        built++;
        for (ray = 0; ray < 2500u; ++ray) {
            float o[3], dd[3], tmin = 0.0f, tmax = FLT_MAX;
            fovpt_hit h1, h2;
            int a1, a2, oc, mode = (int)(ray % 6u);
            for (k = 0; k < 3; ++k) o[k] = adv_grid(S, O, -12, 12);
            if (ray % 11u == 5u) for (k = 0; k < 3; ++k) o[k] = adv_grid(S * 100.0f, O, -12, 12); /* far origins */
            if (mode == 0) { /* along an axis, from a grid point */
                k = (uint32_t)(urand() * 3.0) % 3u;
                dd[0] = dd[1] = dd[2] = 0.0f; dd[k] = urand() < 0.5 ? -1.0f : 1.0f;
            } else if (mode == 1) { /* in a grid plane */
                for (k = 0; k < 3; ++k) dd[k] = frand(-1.0f, 1.0f);
                dd[(uint32_t)(urand() * 3.0) % 3u] = 0.0f;
            } else if (mode == 2 || mode == 3) { /* at a vertex, an edge point or a face point */
                const float *t = pos + 9u * (uint32_t)(urand() * (double)nt);
                uint32_t e0 = (uint32_t)(urand() * 3.0) % 3u, e1 = (e0 + 1u) % 3u;
                float w = mode == 2 ? (urand() < 0.3 ? 0.0f : (float)urand()) : 0.5f, tp[3];
                for (k = 0; k < 3; ++k) tp[k] = t[3u * e0 + k] + w * (t[3u * e1 + k] - t[3u * e0 + k]);
                if (mode == 3) for (k = 0; k < 3; ++k) tp[k] = 0.25f * tp[k] + 0.5f * t[3u * ((e1 + 1u) % 3u) + k] * 0.5f + 0.25f * t[3u * e0 + k];
                if (urand() < 0.3) { k = (uint32_t)(urand() * 3.0) % 3u; o[k] = tp[k]; } /* in the plane of an axis */
                for (k = 0; k < 3; ++k) dd[k] = tp[k] - o[k];
            } else if (mode == 4) { /* grazing: one component 1e-7 of the others */
                for (k = 0; k < 3; ++k) dd[k] = frand(-1.0f, 1.0f);
                dd[(uint32_t)(urand() * 3.0) % 3u] *= 1e-7f;
            } else {
                for (k = 0; k < 3; ++k) dd[k] = frand(-1.0f, 1.0f);
            }
            if (!(dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2] > 0.0f)) dd[2] = 1.0f;
            if (ray % 7u == 1u) tmin = -frand(0.0f, 30.0f);
            if (ray % 7u == 2u) tmin = frand(0.0f, 0.5f);
            if (ray % 5u == 3u) tmax = tmin + frand(0.01f, 4.0f);
            a1 = fovpt_intersect(&b.s, o, dd, tmin, tmax, &h1);
            a2 = fovpt_intersect_brute(&b.s, o, dd, tmin, tmax, &h2);
            oc = fovpt_occluded(&b.s, o, dd, tmin, tmax);
            total++;
            hits += (uint32_t)a2;
            if ((a1 != a2 || (a1 && !(h1.t <= h2.t && h1.t >= h2.t)) || oc != a2) && a2 && adv_spurious(&b.s, &h2, o, dd)) {
                spurious++;
                continue;
            }
            if (a1 != a2 || (a1 && !(h1.t <= h2.t && h1.t >= h2.t))) {
                if (mism < 4)
                    printf("  scene %d ray %u (mode %d): o (%.9g %.9g %.9g) d (%.9g %.9g %.9g) tmin %g: BVH %d t %.9g, brute %d t %.9g\n",
                           sc, ray, mode, (double)o[0], (double)o[1], (double)o[2], (double)dd[0], (double)dd[1], (double)dd[2],
                           (double)tmin, a1, a1 ? (double)h1.t : 0.0, a2, a2 ? (double)h2.t : 0.0);
                if (mism < 4 && a2) { const fovpt__prim *pp = (const fovpt__prim *)b.s.prims + h2.slot;
                    printf("   DBG type %u a %.9g %.9g %.9g b %.9g %.9g %.9g c %.9g %.9g %.9g\n", pp->type, (double)pp->a[0], (double)pp->a[1], (double)pp->a[2], (double)pp->b[0], (double)pp->b[1], (double)pp->b[2], (double)pp->c[0], (double)pp->c[1], (double)pp->c[2]); }
                mism++;
            }
            if (oc != a2) occ_mism++;
        }
        free(b.mem);
    }
    check(built == (uint32_t)nsc && mism == 0 && hits > total / 8u,
          N("BVH = brute force on adversarial scenes (closest t, %u rays): flat quads, rays in faces and along axes, grazing, 1e-3 .. 1e5", total),
          "%u of %u rays differ (%u hits), %u of %d scenes built", mism, total, hits, built, nsc);
    check(built == (uint32_t)nsc && occ_mism == 0, "fovpt_occluded = brute force on the same rays", "%u of %u differ", occ_mism, total);
    check(spurious <= total / 10000u, "brute-force hits outside their primitive's box (rays in its plane, ill-conditioned t): < 1e-4",
          "%u of %u rays", spurious, total);
    printf("# adversarial BVH test: %u rays, %u hits, %u brute-force hits outside their primitive's box (not counted)\n", total, hits, spurious);
}

/* Watertightness of the triangle test (measured, not a contract): rays aimed at points of
   the shared edge of two triangles (a planar pair: a quad split along a diagonal; a folded
   pair) must hit one of them. The test is Moller-Trumbore with the edges of each triangle
   from its own v0, so the shared edge is evaluated differently from the two sides; the
   leaks are counted and printed. */
/* Rays with a direction component below FLT_MIN in magnitude but not 0 (1/d overflows, or
   its product with the box test's margin does): the BVH must still find every hit the brute-
   force loop finds (NUMERICS). A tilted triangle strip whose x extent is 2^-100, origins a few
   ulps around 2^-121, the tiny component on x, both signs, tmin -2000 and 0 (a reviewer's
   construction: main lost every hit for |d| <= 2^-128, the folded margin also for the next
   floats above). */
static void test_tiny_dir(void)
{
    static const uint32_t bits[5] = { 0x00200001u, 0x00200000u, 0x00100000u, 0x00000001u, 0x007fffffu };
    float pos[9 * 8], e = 7.888609052210118e-31f; /* 2^-100 */
    float tri[9] = { 0.0f, -1000.0f, -1000.0f, 0.0f, 1000.0f, -1000.0f, 0.0f, 0.0f, 1000.0f };
    fovpt_mesh m;
    fovpt_material mat;
    fovpt_scene_desc d;
    fovpt_scene s;
    size_t sz = 0;
    void *mem;
    uint32_t i, b, lost = 0, occl = 0, tried = 0, hits = 0;
    tri[6] = -e;
    for (i = 0; i < 8; ++i) {
        memcpy(pos + 9 * i, tri, sizeof tri);
        pos[9 * i + 1] += 3000.0f * (float)i; pos[9 * i + 4] += 3000.0f * (float)i; pos[9 * i + 7] += 3000.0f * (float)i;
    }
    memset(&m, 0, sizeof m);
    m.positions = pos; m.num_vertices = 24; m.num_triangles = 8;
    fovpt_material_init(&mat);
    fovpt_scene_desc_init(&d);
    d.meshes = &m; d.num_meshes = 1; d.materials = &mat; d.num_materials = 1;
    if (!check(fovpt_scene_size(&d, &sz) == FOV_OK, "tiny-direction scene: size", "error")) return;
    mem = malloc(sz);
    if (!check(mem && fovpt_scene_build(&s, &d, mem, sz) == FOV_OK, "tiny-direction scene builds", "error")) {
        free(mem);
        return;
    }
    for (b = 0; b < 5; ++b) {
        uint32_t sg, k;
        float dx;
        memcpy(&dx, &bits[b], sizeof dx);
        for (sg = 0; sg < 4; ++sg) { /* +dir with tmin -2000, -dir with tmin 0, and the mirror images */
            float o0 = 1.0f, sx = (sg & 1u) ? -1.0f : 1.0f, tmin = (sg & 2u) ? 0.0f : -2000.0f;
            for (k = 0; k < 121; ++k) o0 *= 0.5f;
            for (k = 1; k < 400; k += 3) {
                fovpt_hit h1, h2;
                float org[3], dir[3];
                uint32_t u;
                int a, c, oc;
                memcpy(&u, &o0, sizeof u); u += k; memcpy(&org[0], &u, sizeof u);
                org[0] *= sx; org[1] = 0.0f; org[2] = 0.0f;
                dir[0] = (sg & 2u) ? -sx * dx : sx * dx; dir[1] = 0.0f; dir[2] = (sg & 2u) ? -1.0f : 1.0f;
                a = fovpt_intersect(&s, org, dir, tmin, 2000.0f, &h1);
                c = fovpt_intersect_brute(&s, org, dir, tmin, 2000.0f, &h2);
                oc = fovpt_occluded(&s, org, dir, tmin, 2000.0f);
                tried++;
                hits += (uint32_t)(c != 0);
                if (c && (!a || h1.t != h2.t)) lost++;
                if (oc != c) occl++;
            }
        }
    }
    check(hits > tried / 4u, "tiny-direction rays: the brute-force loop hits (the test has hits to lose)", "%u of %u",
          hits, tried);
    check(lost == 0, "tiny-direction rays (|d_x| < FLT_MIN, not 0): BVH hit = brute-force hit", "%u of %u lost", lost,
          hits);
    check(occl == 0, "tiny-direction rays: fovpt_occluded agrees with the brute-force hit", "%u of %u differ", occl,
          tried);
    free(mem);
}

/* fovpt__rev32 (the SOBOL sampler's bit reversal) against a loop over the bits; the
   FOVPT_NO_SIMD build defines FOVPT__BITREV 0, so the portable path is checked there and the
   compiler's builtin path in the others (tests/xtarget: wasm32, AArch64) */
/* fovpt__dir_class (one pass per ray) against its two rules, evaluated here in double on
   every combination of edge values: bit 1 when max |d| is outside [2^-32, 2^32], bit 2 when
   some component is not 0 but below FLT_MIN in magnitude */
static void test_dir_class(void)
{
    static const uint32_t bits[] = { 0x00000000u, 0x80000000u, 0x00000001u, 0x807fffffu, 0x007fffffu,
        0x00800000u, 0x80800000u, 0x2f7fffffu, 0x2f800000u, 0x4f800000u, 0x4f800001u, 0x3f800000u,
        0xbf000000u, 0x7f7fffffu, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0x00400000u };
    const uint32_t nb = (uint32_t)(sizeof bits / sizeof bits[0]);
    uint32_t i, j, k, bad = 0, n = 0;
    for (i = 0; i < nb; ++i)
        for (j = 0; j < nb; ++j)
            for (k = 0; k < nb; ++k) {
                float d[3];
                double m = 0.0;
                int want = 0, tiny = 0, nan = 0, c;
                uint32_t q, b3[3];
                b3[0] = bits[i]; b3[1] = bits[j]; b3[2] = bits[k];
                for (q = 0; q < 3; ++q) {
                    double a;
                    memcpy(&d[q], &b3[q], sizeof d[q]);
                    a = fabs((double)d[q]);
                    if (a != a) nan = 1;
                    else if (a > m) m = a;
                    if (a > 0.0 && a < 1.1754943508222875e-38) tiny = 1;
                }
                if (m < 2.3283064365386963e-10 || m > 4294967296.0) want |= 1;
                if (tiny) want |= 2;
                c = fovpt__dir_class(d);
                ++n;
                /* a NaN component: bit 1 is not specified (the caller rejects non-finite
                   directions next); bit 2 still is */
                if (nan ? (c & 2) != (want & 2) : c != want) ++bad;
            }
    check(bad == 0, "fovpt__dir_class: rescale and tiny-component bits on 18^3 edge-value directions", "%u of %u differ", bad, n);
}

/* fovpt__ray_fast (the SIMD entry of fovpt_intersect / fovpt_occluded) against its scalar
   twin: it takes a ray exactly when the rules, evaluated here in double, say the scalar
   entry would route it to the walk with nothing to rescale and no zero or subnormal
   direction component (origin finite; every |d| in [FLT_MIN, 2^32], the largest >= 2^-32),
   and then its record equals fovpt__ray_set's bit for bit (o, d, 1 / d, 1 / d * GROW, the
   octant). Edge-value directions (18^3) times origins with a huge, infinite, NaN, -0 or
   subnormal component, then 200k random directions over the whole exponent range. The
   origin and direction live in 12-byte heap blocks, so a load past float[3] is an
   out-of-bounds read under the sanitizers. */
static void test_ray_fast(void)
{
#if FOVPT__SIMD
    static const uint32_t bits[] = { 0x00000000u, 0x80000000u, 0x00000001u, 0x807fffffu, 0x007fffffu,
        0x00800000u, 0x80800000u, 0x2f7fffffu, 0x2f800000u, 0x4f800000u, 0x4f800001u, 0x3f800000u,
        0xbf000000u, 0x7f7fffffu, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0x00400000u };
    static const float org_base[3] = { 0.5f, -2.0f, 3.0f };
    const uint32_t nb = (uint32_t)(sizeof bits / sizeof bits[0]);
    float *o = (float *)malloc(3u * sizeof(float)), *d = (float *)malloc(3u * sizeof(float));
    uint32_t i, k, oi, q, bad_route = 0, bad_rec = 0, n = 0, taken = 0, x = 0x9e3779b9u;
    if (!o || !d) { check(0, "test_ray_fast: malloc", " "); free(o); free(d); return; }
    for (i = 0; i < nb * nb * nb * 6u + 200000u; ++i) {
        fovpt__ray r1, r2;
        int want = 1, got;
        double m = 0.0;
        if (i < nb * nb * nb * 6u) {
            uint32_t b3[3], e = i / 6u;
            b3[0] = bits[e % nb]; b3[1] = bits[(e / nb) % nb]; b3[2] = bits[e / (nb * nb)];
            for (q = 0; q < 3; ++q) memcpy(&d[q], &b3[q], sizeof d[q]);
            oi = i % 6u;
        } else {
            for (q = 0; q < 3; ++q) {
                uint32_t u;
                x = x * 1664525u + 1013904223u;
                u = x; /* any sign, exponent and mantissa: NaN, inf, subnormal and 0 included */
                if ((x >> 29) == 0u) u &= 0x80000000u; /* some exact zeros */
                else if ((x >> 30) != 0u) /* mostly exponents around [2^-32, 2^32] */
                    u = (u & 0x807fffffu) | ((80u + (x >> 8) % 100u) << 23);
                memcpy(&d[q], &u, sizeof d[q]);
            }
            oi = (i >> 3) % 6u;
        }
        memcpy(o, org_base, sizeof org_base);
        if (oi == 1) o[1] = FLT_MAX;
        else if (oi == 2) o[2] = (float)HUGE_VAL;
        else if (oi == 3) { uint32_t u = 0x7fc00000u; memcpy(&o[0], &u, sizeof u); }
        else if (oi == 4) o[0] = -0.0f;
        else if (oi == 5) o[1] = 1e-40f;
        for (q = 0; q < 3; ++q) {
            const double a = fabs((double)d[q]);
            if (!(fabs((double)o[q]) <= (double)FLT_MAX)) want = 0;
            if (!(a >= 1.1754943508222875e-38 && a <= 4294967296.0)) want = 0; /* NaN too */
            if (a > m) m = a;
        }
        if (!(m >= 2.3283064365386963e-10)) want = 0;
        memset(&r1, 0x5a, sizeof r1);
        got = fovpt__ray_fast(&r1, o, d);
        ++n;
        if (got != want) { ++bad_route; continue; }
        if (!got) continue;
        ++taken;
        /* the scalar entry's view of the same ray: no rescale, nothing tiny, finite */
        if (fovpt__dir_class(d) != 0 || !fov__finite3(o) || !fov__finite3(d)) { ++bad_route; continue; }
        memset(&r2, 0x5a, sizeof r2);
        fovpt__ray_set(&r2, o, d);
        for (k = 0; k < 3; ++k)
            if (memcmp(&r1.o[k], &r2.o[k], 4) || memcmp(&r1.d[k], &r2.d[k], 4) ||
                memcmp(&r1.inv[k], &r2.inv[k], 4) || memcmp(&r1.ig[k], &r2.ig[k], 4))
                break;
        if (k < 3 || r1.oct != r2.oct) ++bad_rec;
    }
    check(bad_route == 0 && bad_rec == 0 && taken > 20000u,
          "SIMD ray entry = the scalar entry: routing on edge-value and random rays, the record bit for bit",
          "%u misrouted, %u records differ, %u of %u taken", bad_route, bad_rec, taken, n);
    free(o);
    free(d);
#endif
}

static void test_rev32(void)
{
    uint32_t i, x = 0x12345678u, bad = 0;
    for (i = 0; i < 200000u; ++i) {
        uint32_t r = 0, b;
        x = x * 1664525u + 1013904223u;
        for (b = 0; b < 32u; ++b) r |= ((x >> b) & 1u) << (31u - b);
        bad += fovpt__rev32(x) != r;
    }
    bad += fovpt__rev32(0u) != 0u || fovpt__rev32(1u) != 0x80000000u || fovpt__rev32(0xffffffffu) != 0xffffffffu;
    check(bad == 0, N("fovpt__rev32 = a bit loop on 200k values (FOVPT__BITREV %d)", (int)FOVPT__BITREV), "%u differ",
          bad);
}

static void test_watertight(void)
{
    uint32_t n = 0, leak_flat = 0, leak_fold = 0, nflat = 0, nfold = 0, i, k;
    for (i = 0; i < 40000u; ++i) {
        int fold = (int)(i & 1u);
        float S = (float)pow(10.0, -2.0 + 5.0 * urand()), pos[18], P[3], Q[3], R1[3], R2[3], o[3], d[3], X[3];
        double w = urand();
        fovpt_material m;
        fovpt_mesh mesh;
        scene_buf b;
        fovpt_hit h;
        for (k = 0; k < 3; ++k) { P[k] = frand(-1.0f, 1.0f) * S; Q[k] = frand(-1.0f, 1.0f) * S; }
        {   /* R1, R2 on either side of PQ: mid +- a vector across it (planar: opposite) */
            float a[3], e[3], c[3];
            for (k = 0; k < 3; ++k) { e[k] = Q[k] - P[k]; a[k] = frand(-1.0f, 1.0f) * S; }
            c[0] = e[1] * a[2] - e[2] * a[1]; c[1] = e[2] * a[0] - e[0] * a[2]; c[2] = e[0] * a[1] - e[1] * a[0];
            for (k = 0; k < 3; ++k) {
                float mid = 0.5f * (P[k] + Q[k]), sc = 1.0f / S;
                R1[k] = mid + c[k] * sc;
                R2[k] = mid - (fold ? (c[k] * 0.7f + a[k] * 0.5f) : c[k]) * sc;
            }
        }
        /* P Q R1 and Q P R2: consistent winding, the edge from both sides */
        memcpy(pos, P, 12); memcpy(pos + 3, Q, 12); memcpy(pos + 6, R1, 12);
        memcpy(pos + 9, Q, 12); memcpy(pos + 12, P, 12); memcpy(pos + 15, R2, 12);
        for (k = 0; k < 3; ++k) X[k] = (float)((double)P[k] + w * ((double)Q[k] - (double)P[k]));
        for (k = 0; k < 3; ++k) o[k] = X[k] + frand(-3.0f, 3.0f) * S;
        for (k = 0; k < 3; ++k) d[k] = X[k] - o[k];
        if (f7_scene(&b, pos, 2, NULL, 0, 100, &mesh, &m) != FOV_OK) { free(b.mem); continue; }
        {   /* count only rays that cross the pair's plane region transversally (|cos| > 0.05) */
            float n1[3], e1[3], e2[3], dl = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), nl, c;
            for (k = 0; k < 3; ++k) { e1[k] = Q[k] - P[k]; e2[k] = R1[k] - P[k]; }
            n1[0] = e1[1] * e2[2] - e1[2] * e2[1]; n1[1] = e1[2] * e2[0] - e1[0] * e2[2]; n1[2] = e1[0] * e2[1] - e1[1] * e2[0];
            nl = sqrtf(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
            c = fabsf(n1[0] * d[0] + n1[1] * d[1] + n1[2] * d[2]) / (nl * dl);
            if (!(c > 0.05f)) { free(b.mem); continue; }
        }
        n++;
        if (fold) nfold++; else nflat++;
        if (!fovpt_intersect_brute(&b.s, o, d, 0.0f, FLT_MAX, &h)) { if (fold) leak_fold++; else leak_flat++; }
        free(b.mem);
    }
    printf("# watertightness (Moller-Trumbore, not watertight): rays at a shared edge that hit neither triangle: planar pairs %u of %u (%.3f %%), folded pairs %u of %u (%.3f %%)\n",
           leak_flat, nflat, 100.0 * (double)leak_flat / (double)(nflat ? nflat : 1u), leak_fold, nfold,
           100.0 * (double)leak_fold / (double)(nfold ? nfold : 1u));
    check(n > 10000u, "watertightness measurement ran", "%u rays", n);
    {   /* a closed mesh: a cube's faces on a 16 x 16 grid each, projected to the unit sphere,
           vertices shared by index; random rays from inside must all hit it */
        enum { G = 16 };
        static float vpos[6 * (G + 1) * (G + 1) * 3];
        static uint32_t idx[6 * G * G * 6];
        uint32_t f, a, c, nv = 0, ni = 0, misses = 0, rays = 200000u;
        fovpt_material m;
        fovpt_mesh mesh;
        fovpt_scene_desc d;
        scene_buf b;
        for (f = 0; f < 6; ++f) {
            uint32_t base = nv, ax = f % 3u;
            float sg = f < 3 ? 1.0f : -1.0f;
            for (a = 0; a <= G; ++a)
                for (c = 0; c <= G; ++c) {
                    double p[3], l;
                    p[ax] = (double)sg; p[(ax + 1u) % 3u] = -1.0 + 2.0 * a / G; p[(ax + 2u) % 3u] = (-1.0 + 2.0 * c / G) * (double)sg;
                    l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                    for (k = 0; k < 3; ++k) vpos[3u * nv + k] = (float)(p[k] / l);
                    nv++;
                }
            for (a = 0; a < G; ++a)
                for (c = 0; c < G; ++c) {
                    uint32_t v00 = base + a * (G + 1) + c, v01 = v00 + 1u, v10 = v00 + G + 1, v11 = v10 + 1u;
                    idx[ni++] = v00; idx[ni++] = v10; idx[ni++] = v11;
                    idx[ni++] = v00; idx[ni++] = v11; idx[ni++] = v01;
                }
        }
        /* the cube's edges: weld duplicated vertices (same float position) to one index */
        for (i = 0; i < ni; ++i) {
            uint32_t j;
            for (j = 0; j < idx[i]; ++j)
                if (memcmp(vpos + 3u * j, vpos + 3u * idx[i], 12) == 0) { idx[i] = j; break; }
        }
        fovpt_material_init(&m);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = vpos; mesh.num_vertices = nv; mesh.indices = idx; mesh.num_triangles = ni / 3u;
        fovpt_scene_desc_init(&d);
        d.meshes = &mesh; d.num_meshes = 1; d.materials = &m; d.num_materials = 1;
        if (check(build(&b, &d) == FOV_OK, "closed sphere mesh builds", " ")) {
            for (i = 0; i < rays; ++i) {
                float o[3], dd[3];
                fovpt_hit h;
                for (k = 0; k < 3; ++k) { o[k] = frand(-0.5f, 0.5f); dd[k] = frand(-1.0f, 1.0f); }
                if (i % 4u == 0u) { o[0] = o[1] = o[2] = 0.0f; } /* from the centre: through vertices and edges */
                if (!fovpt_intersect(&b.s, o, dd, 0.0f, FLT_MAX, &h)) misses++;
            }
            printf("# watertightness, closed mesh (%u triangles, welded): %u of %u random rays from inside leak (%.4f %%)\n",
                   ni / 3u, misses, rays, 100.0 * (double)misses / (double)rays);
        }
        free(b.mem);
    }
}

/* fuzzing findings (tests/fuzz/fuzz_fovpt.c): directions of any length, a sphere whose
   radius is below its centre's resolution, triangles whose squared area overflows */
static void test_fuzz_findings(void)
{
    fovpt_material m;
    fovpt_mesh mesh;
    scene_buf b;
    fovpt_hit h;
    memset(&h, 0, sizeof h);
    {   /* a triangle at scale 1e5 and a direction of length 1.4e30: t = 2.5e-25 (brute force
           and BVH missed: the triangle test's products overflowed) */
        static const float tri[9] = { 0, 0, 0, 4e5f, 0, 0, 0, 4e5f, 0 };
        const float o[3] = { 1e5f, 4.5e5f, 3.5e5f }, d[3] = { -1.0f, -1e30f, -1e30f };
        int a = 0, ab = 0, oc = 0;
        double t_ref = 3.5e5 / 1e30; /* z reaches 0 */
        if (f7_scene(&b, tri, 1, NULL, 0, 1, &mesh, &m) == FOV_OK) {
            /* the hit (1e5, 1e5, 0) lies inside the triangle */
            a = fovpt_intersect(&b.s, o, d, 0.0f, FLT_MAX, &h);
            ab = fovpt_intersect_brute(&b.s, o, d, 0.0f, FLT_MAX, &h);
            oc = fovpt_occluded(&b.s, o, d, 0.0f, FLT_MAX);
        }
        check(a && ab && oc && fabs((double)h.t - t_ref) < 1e-5 * t_ref, "direction of length 1.4e30: hit at t = 3.5e-25 (BVH, brute force, occluded)",
              "BVH %d brute %d occluded %d t %g", a, ab, oc, (double)h.t);
        free(b.mem);
    }
    {   /* session 11, CI fuzzer: a direction of length 1e-20 rescales tmin = -1e30 to -inf, the
           box test then passes every box, also the empty children of the 4-wide nodes
           (count 0): the leaf loop ran from slot 0 to 2^32 (a crash). Scenes of 1 to 40
           triangles on a line (nodes with 2, 3 and 4 children); hits as brute force. */
        static float tri[9 * 40];
        uint32_t n, i, bad = 0, crashes_avoided = 0;
        for (i = 0; i < 40u; ++i) {
            const float x = (float)i * 3.0f;
            const float v[9] = { x, -1, 2, x + 2, -1, 2, x, 1, 2 };
            memcpy(tri + 9u * i, v, sizeof v);
        }
        for (n = 1; n <= 40u; ++n) {
            if (f7_scene(&b, tri, n, NULL, 0, 1, &mesh, &m) != FOV_OK) { ++bad; continue; }
            for (i = 0; i < n; ++i) {
                /* towards (3i + 0.5, -0.5, 2), inside triangle i */
                const float o[3] = { (float)i * 3.0f + 1.5f, 0.5f, 3.0f }, d[3] = { -2.37322025e14f, -2.37322025e14f, -2.37322025e14f };
                fovpt_hit hb;
                int a = fovpt_intersect(&b.s, o, d, -1e30f, FLT_MAX, &h);
                int ab = fovpt_intersect_brute(&b.s, o, d, -1e30f, FLT_MAX, &hb);
                int oc = fovpt_occluded(&b.s, o, d, -1e30f, FLT_MAX);
                if (a != ab || a != oc || (a && (h.prim != hb.prim || h.t != hb.t))) ++bad;
                ++crashes_avoided;
            }
            free(b.mem);
        }
        check(bad == 0 && crashes_avoided == 820u, "tmin rescaled to -inf (direction of length 4e14, tmin -1e30): BVH = brute force = occluded over 1..40 triangles",
              "%u mismatches of %u rays", bad, crashes_avoided);
    }
    {   /* a sphere of radius 1e18 at 2.3e27 hit where the point rounds onto the centre:
           the normal stays unit */
        fovpt_shape sp;
        const float o[3] = { 2.3e27f, 2.3e27f, 0.0f }, d[3] = { 0.0f, 0.0f, 1.0f };
        fovpt_shape_sphere(&sp, 2.3e27f, 2.3e27f, 2.3e27f, 1e18f, 0);
        if (check(f7_scene(&b, NULL, 0, &sp, 1, 1, &mesh, &m) == FOV_OK, "sphere of radius 1e18 at 2.3e27 builds", " ")) {
            int a = fovpt_intersect(&b.s, o, d, 0.0f, FLT_MAX, &h);
            double nl = (double)h.n[0] * (double)h.n[0] + (double)h.n[1] * (double)h.n[1] + (double)h.n[2] * (double)h.n[2];
            check(a && nl > 0.999 && nl < 1.001, "sphere hit at a point that rounds onto its centre: unit normal", "hit %d |n|^2 %g", a, nl);
        }
        free(b.mem);
    }
    {   /* a triangle with edges of 1e10 (|e1 x e2|^2 = 1e40 overflows): a valid triangle */
        static const float tri[9] = { 0, 0, 5, 1e10f, 0, 5, 0, 1e10f, 5 };
        const float o[3] = { 1e3f, 1e3f, 0.0f }, d[3] = { 0.0f, 0.0f, 1.0f };
        fov_result r = f7_scene(&b, tri, 1, NULL, 0, 1, &mesh, &m);
        int a = r == FOV_OK ? fovpt_intersect(&b.s, o, d, 0.0f, FLT_MAX, &h) : 0;
        check(r == FOV_OK && a && fabsf(h.t - 5.0f) < 1e-5f, "triangle with edges of 1e10: builds (was DEGENERATE) and is hit at t = 5",
              "%s, hit %d t %g", fovpt_result_string(r), a, (double)h.t);
        free(b.mem);
    }
    {   /* session 14, fuzzer: an emission near FLT_MAX is finite per sample, but two
           samples summed to +inf in the image (a lamp of FLT_MAX itself is rejected: its
           power overflows). Each sample is now clamped per channel at
           FOVPT_MAX_RADIANCE: every method's image finite, a ray at the lamp returns the cap,
           and an emission below the cap is returned unchanged. */
        fovpt_material cm[6];
        fovpt_shape csh[8];
        fovpt_scene_desc cd;
        static const float ems[3] = { 1e38f, 3e37f, 1e15f };
        uint32_t e, meth, bad = 0, runs = 0, radiance_ok = 0;
        for (e = 0; e < 3u; ++e) {
            cornell(cm, csh, &cd, 0);
            cm[3].emission[0] = cm[3].emission[1] = cm[3].emission[2] = ems[e];
            cm[3].albedo[0] = cm[3].albedo[1] = cm[3].albedo[2] = 0.0f; /* the lamp reflects nothing */
            if (build(&b, &cd) != FOV_OK) { ++bad; continue; }
            {   /* straight up at the lamp (y = 0.999, |x|, |z| < 0.25) */
                fovpt_config c = fovpt_config_default();
                fovpt_rng rng;
                float rgb[3] = { 0, 0, 0 }, want = e < 2u ? (float)FOVPT_MAX_RADIANCE : ems[e];
                const float o[3] = { 0.0f, 0.0f, 0.0f }, d[3] = { 0.0f, 1.0f, 0.0f };
                fovpt_rng_init(&rng, 1u, 2u, 0u, 0u);
                if (fovpt_radiance(&b.s, &c, o, d, &rng, rgb, NULL) == FOV_OK && rgb[0] == want && rgb[1] == want &&
                    rgb[2] == want)
                    ++radiance_ok;
            }
            for (meth = 0; meth < (uint32_t)_FOVPT_METHOD_NUM; ++meth) {
                uint32_t mode;
                for (mode = 0; mode < 2u; ++mode) {
                    fovpt_config c = fovpt_config_default();
                    fovpt_camera cam;
                    fovpt_ctx ctx;
                    fovpt_output out;
                    fov_gaze g = { 8.0f, 6.0f };
                    float img[16 * 12 * 3];
                    size_t n = 0;
                    void *mem;
                    uint32_t i, f;
                    c.method = meth; c.mode = mode; c.spp = 4; c.accumulate = 1;
                    fovpt_camera_init(&cam, 16, 12);
                    cam.pos[2] = -3.0f; cam.target[1] = 0.6f;
                    if (fovpt_memory_size(&c, &cam, &n) != FOV_OK) { ++bad; continue; }
                    mem = amalloc(n);
                    if (fovpt_init(&ctx, &c, &b.s, &cam, g, mem, n) != FOV_OK) { ++bad; free(mem); continue; }
                    fovpt_output_init(&out);
                    out.rgb = img;
                    for (f = 0; f < 3u; ++f) {
                        if (fovpt_render(&ctx, f, &out, NULL) != FOV_OK) ++bad;
                        for (i = 0; i < 16u * 12u * 3u; ++i) if (!(img[i] >= 0.0f && img[i] <= FLT_MAX)) ++bad;
                    }
                    ++runs;
                    free(mem);
                }
            }
            free(b.mem);
        }
        check(bad == 0 && runs == 3u * 2u * (uint32_t)_FOVPT_METHOD_NUM,
              "a lamp of emission 1e38 / 3e37 / 1e15: every method, path and Whitted, 3 accumulated frames: finite images",
              "%u non-finite values or errors in %u runs", bad, runs);
        check(radiance_ok == 3u, "radiance at the lamp: FOVPT_MAX_RADIANCE for 1e38 and 3e37, 1e15 unchanged", "%u of 3", radiance_ok);
    }
    {   /* skip_degenerate keeps the documented ids: triangle k reports num_shapes + k */
        static const float tri[18] = { 0, 0, 0, 0, 0, 0, 1, 1, 0, -1, -1, 2, 1, -1, 2, 0, 1, 2 };
        const float o[3] = { 0.0f, 0.0f, 0.0f }, d[3] = { 0.0f, 0.0f, 1.0f };
        fovpt_scene_desc dd;
        fovpt_material_init(&m);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = tri; mesh.num_vertices = 6; mesh.num_triangles = 2;
        fovpt_scene_desc_init(&dd);
        dd.meshes = &mesh; dd.num_meshes = 1; dd.materials = &m; dd.num_materials = 1; dd.skip_degenerate = 1;
        if (build(&b, &dd) == FOV_OK) {
            int a = fovpt_intersect(&b.s, o, d, 0.0f, FLT_MAX, &h);
            check(a && h.prim == 1u && b.s.num_skipped == 1u, "skip_degenerate: the triangle after a dropped one keeps id k = 1",
                  "hit %d prim %u skipped %u", a, h.prim, b.s.num_skipped);
        } else check(0, "skip_degenerate scene builds", " ");
        free(b.mem);
    }
}

/* session 14: the resolve's shortcuts against their exact forms. The Lanczos weights of one
   axis (three sines by the angle sum) against sinc(x) sinc(x / a) in double; the eccentricity
   side test (no atan2) against fovpt_ecc_deg: a decided side always agrees, and it decides
   almost every pixel (else the shortcut would do nothing). */
static void test_resolve_shortcuts(void)
{
    static const float fr[9] = { 0.0f, 1e-7f, 0.125f, 0.25f, 1.0f / 3.0f, 0.5f, 0.7f, 0.875f, 0.99999994f };
    double worst = 0.0;
    uint32_t a, i, k, decided = 0, tried = 0, wrong = 0;
    for (a = 2; a <= 3u; ++a)
        for (k = 0; k < 9u; ++k) {
            float w[6];
            fovpt__lanczos_axis(fr[k], (int32_t)a, w);
            for (i = 0; i < 2u * a; ++i) {
                double x = (double)fr[k] + (double)a - 1.0 - (double)i, ref, px = 3.14159265358979323846 * x;
                if (fabs(x) < 1e-6) ref = 1.0;
                else if (fabs(x) >= (double)a) ref = 0.0;
                else ref = (double)a * sin(px) * sin(px / (double)a) / (px * px);
                if (fabs((double)w[i] - ref) > worst) worst = fabs((double)w[i] - ref);
            }
        }
    check(worst < 2e-6, "Lanczos weights of one axis (a = 2, 3; nine fractions) = sinc(x) sinc(x/a) in double", "worst %g", worst);
    {
        uint32_t seed = 12345u, g, p, t;
        for (g = 0; g < 32u; ++g) {
            fov_ecc_model m;
            fov_gaze gz;
            float fov = g < 24u ? fminf(20.0f + 7.0f * (float)g, 170.0f) : 170.0f + (float)(g - 24u);
            uint32_t Wd = 64u + 37u * g, Hd = 48u + 23u * g;
            seed = seed * 1664525u + 1013904223u;
            gz.x = (float)(seed >> 8) / 16777216.0f * 1.6f * (float)Wd - 0.3f * (float)Wd;
            seed = seed * 1664525u + 1013904223u;
            gz.y = (float)(seed >> 8) / 16777216.0f * 1.6f * (float)Hd - 0.3f * (float)Hd;
            if (fovpt_ecc_init(&m, NULL, fov, Wd, Hd, gz) != FOV_OK) { ++wrong; continue; }
            for (p = 0; p < 400u; ++p) {
                float x, y, s2, co, e;
                seed = seed * 1664525u + 1013904223u;
                x = (float)((seed >> 8) % Wd) + 0.5f;
                seed = seed * 1664525u + 1013904223u;
                y = (float)((seed >> 8) % Hd) + 0.5f;
                fovpt__ecc_s2co(&m, x, y, &s2, &co);
                e = fovpt_ecc_deg(&m, x, y);
                for (t = 0; t < 10u; ++t) {
                    /* thresholds away from e (offsets in degrees: these must be decided), and
                       within a few float roundings of e (relative: must never be wrong) */
                    static const float off[6] = { -30.0f, -1.0f, -1e-3f, 1e-3f, 1.0f, 30.0f };
                    static const int ulps[4] = { -4, 0, 1, 4 };
                    float T = e;
                    if (t < 6u) T = e + off[t];
                    else { /* T a few ulps from e */
                        int32_t bits;
                        memcpy(&bits, &T, sizeof bits);
                        bits += ulps[t - 6u];
                        memcpy(&T, &bits, sizeof T);
                    }
                    int side;
                    if (!(T > 0.0f && T < 89.5f)) continue;
                    side = fovpt__ecc_side(s2, co, fovpt__tan2_deg(T));
                    if (t < 6u && T >= 2.0f && T <= 60.0f) ++tried; /* the fast test's domain */
                    if (side == 0) continue;
                    if (t < 6u && T >= 2.0f && T <= 60.0f) ++decided;
                    if ((side < 0 && !(e < T)) || (side > 0 && !(e > T))) ++wrong;
                }
            }
        }
        check(wrong == 0 && tried > 20000u && decided >= tried - tried / 100u,
              "resolve's eccentricity side test: agrees with fovpt_ecc_deg whenever it decides (T = e too, fields of view up to 177 degrees), and decides >= 99 %",
              "%u wrong, %u of %u decided", wrong, decided, tried);
    }
}

/* ROBUST PIXEL ESTIMATE (cfg.robust): the group count, the combination against the Gini
   coefficient by its pairwise definition in double, and on a firefly scene (the Cornell box
   with a mirror sphere, whose caustic next-event estimation cannot sample) the error against
   a 2048-spp plain reference below the plain mean's. */
static double ref_gini(const double *l, uint32_t g)
{
    double sum = 0.0, mu = 0.0;
    uint32_t i, j;
    for (i = 0; i < g; ++i) mu += l[i] / g;
    for (i = 0; i < g; ++i)
        for (j = 0; j < g; ++j) sum += fabs(l[i] - l[j]);
    return sum / (2.0 * g * g * mu);
}
/* One frame of c (UNIFORM unless set) into img through the public API: fovpt_render's
   result, FOV_ERR_* from a failed init; st (may be NULL) cleared and counted. */
static fov_result render_cfg(const fovpt_scene *sc, const fovpt_camera *cam, fov_gaze gz, const fovpt_config *c,
                             float *img, fovpt_stats *st)
{
    fovpt_ctx ctx;
    fovpt_output out;
    size_t need = 0;
    void *mem;
    fov_result e = fovpt_memory_size(c, cam, &need);
    if (e != FOV_OK) return e;
    mem = amalloc(need);
    e = fovpt_init(&ctx, c, sc, cam, gz, mem, need);
    if (e == FOV_OK) {
        fovpt_output_init(&out);
        out.rgb = img;
        if (st) memset(st, 0, sizeof *st);
        e = fovpt_render(&ctx, 0, &out, st);
    }
    free(mem);
    return e;
}

/* test_robust's pairs: c with robust 0 into im[0] and robust 4 into im[1] (allocated here),
   W x H from (0, 0, -3), gaze at (12, 8) */
static void render_robust_pair(const fovpt_scene *sc, uint32_t W, uint32_t H, fovpt_config c, float *im[2])
{
    fovpt_camera cam;
    fov_gaze gz;
    uint32_t r;
    fovpt_camera_init(&cam, W, H);
    cam.pos[2] = -3.0f;
    gz.x = 12.0f; gz.y = 8.0f;
    for (r = 0; r < 2; ++r) {
        im[r] = (float *)malloc(W * H * 12u);
        c.robust = r ? 4u : 0u;
        render_cfg(sc, &cam, gz, &c, im[r], NULL);
    }
}

static void test_robust(void)
{
    uint32_t bad = 0, tried = 0, spp, g, i, trial, k;
    /* the group count: min(robust, spp / 8), none below 3 groups or with robust < 3 */
    for (spp = 1; spp <= 300; ++spp)
        for (g = 0; g <= FOVPT_ROBUST_MAX; ++g) {
            uint32_t want = spp / 8u < g ? spp / 8u : g;
            if (g < 3u || want < 3u) want = 0;
            bad += fovpt__robust_groups(g, spp) != want;
            if (want) { /* the groups: in order, sizes differing by at most one, all used */
                uint32_t cnt[FOVPT_ROBUST_MAX] = {0}, s, last = 0, mn = 1000, mx = 0;
                for (s = 0; s < spp; ++s) {
                    uint32_t j = fovpt__robust_group_of(s, want, spp);
                    if (j >= want || j < last) { ++bad; break; }
                    last = j;
                    cnt[j]++;
                }
                for (s = 0; s < want; ++s) { mn = cnt[s] < mn ? cnt[s] : mn; mx = cnt[s] > mx ? cnt[s] : mx; }
                bad += mx - mn > 1u || mn == 0u;
            }
        }
    check(bad == 0, "robust: group count min(robust, spp / 8) from 3 groups on; groups in sample order, sizes within one", "%u wrong", bad);
    /* the combination on random group sums (one group made an outlier in half the trials) */
    bad = 0;
    for (trial = 0; trial < 20000u; ++trial) {
        float gs[FOVPT_ROBUST_MAX][3], sum[3], lc[3] = {0.0f, 0.0f, 0.0f};
        double l[FOVPT_ROBUST_MAX], n[FOVPT_ROBUST_MAX], plain[3] = {0, 0, 0}, want[3], G;
        uint32_t ord[FOVPT_ROBUST_MAX];
        g = 3u + (uint32_t)(urand() * (FOVPT_ROBUST_MAX - 2));
        if (g > FOVPT_ROBUST_MAX) g = FOVPT_ROBUST_MAX;
        spp = g * 8u + (uint32_t)(urand() * 40.0);
        for (i = 0; i < g; ++i) {
            n[i] = 0;
            for (k = 0; k < spp; ++k) n[i] += fovpt__robust_group_of(k, g, spp) == i;
            for (k = 0; k < 3; ++k) gs[i][k] = (float)n[i] * frand(0.1f, 1.0f);
        }
        if (trial & 1u) { /* a firefly in one group */
            i = (uint32_t)(urand() * g) % g;
            for (k = 0; k < 3; ++k) gs[i][k] += frand(1.0f, 40.0f);
        }
        if (trial % 7u == 3u) for (i = 0; i < g; ++i) for (k = 0; k < 3; ++k) gs[i][k] = 0.0f; /* black */
        if (trial & 2u) for (k = 0; k < 3; ++k) lc[k] = frand(0.0f, 50.0f) * (float)spp; /* the specular chains' sum */
        for (i = 0; i < g; ++i) {
            l[i] = (0.2126 * (double)gs[i][0] + 0.7152 * (double)gs[i][1] + 0.0722 * (double)gs[i][2]) / n[i];
            for (k = 0; k < 3; ++k) plain[k] += (double)gs[i][k];
            ord[i] = i;
        }
        for (i = 1; i < g; ++i) /* by luminance, ties by index */
            for (k = i; k > 0 && (l[ord[k - 1]] > l[ord[k]] || (l[ord[k - 1]] == l[ord[k]] && ord[k - 1] > ord[k])); --k) {
                uint32_t t = ord[k]; ord[k] = ord[k - 1]; ord[k - 1] = t;
            }
        G = plain[0] + plain[1] + plain[2] > 0.0 ? ref_gini(l, g) : 0.0;
        if (fabs(G - 0.25) < 1e-4) continue; /* float and double may decide differently */
        ++tried;
        for (k = 0; k < 3; ++k) {
            uint32_t a = ord[(g - 1) / 2], b = ord[g / 2];
            want[k] = (double)lc[k] + (G > 0.25 ? 0.5 * ((double)gs[a][k] / n[a] + (double)gs[b][k] / n[b]) * spp : plain[k]);
        }
        fovpt__robust_sum(gs, lc, g, spp, sum);
        for (k = 0; k < 3; ++k)
            if (!(fabs((double)sum[k] - want[k]) <= 1e-5 * want[k] + 1e-6)) { ++bad; break; }
    }
    check(bad == 0 && tried > 19000u, "robust: the specular chains' sum plus the median group's mean where the group means' Gini coefficient (pairwise, in double) exceeds 0.25, else plus the plain sum",
          "%u of %u wrong", bad, tried);
    {   /* the firefly scene: the Cornell box with a mirror sphere (its caustic lights the
           ceiling: rare samples of radiance 20-80 where the pixel's mean is 0.3-0.7), 40 x 32,
           against 512 plain spp: at 64 spp robust 4 leaves at most half the specks (a channel
           more than 0.15 above the reference), and it is consistent: at 256 spp (groups of
           64) its error is within 20 % of the plain mean's of the same samples, and it differs
           from that mean by less than half as much as at 64 spp */
        fovpt_material m[6];
        fovpt_shape sh[8];
        fovpt_scene_desc d;
        scene_buf b;
        fovpt_camera cam;
        const uint32_t W = 32, H = 24;
        float *ref = (float *)malloc(W * H * 12u), *im[4];
        double se[4] = {0.0, 0.0, 0.0, 0.0}, dd[2] = {0.0, 0.0};
        uint32_t specks[4] = {0, 0, 0, 0};
        int r;
        fov_gaze gz;
        cornell(m, sh, &d, 0);
        build(&b, &d);
        fovpt_camera_init(&cam, W, H);
        cam.pos[2] = -3.0f;
        gz.x = 16.0f; gz.y = 12.0f;
        for (r = -1; r < 4; ++r) {
            fovpt_config c = fovpt_config_default();
            c.spp = r < 0 ? 512u : r >= 2 ? 256u : 64u;
            c.seed = r < 0 ? 99u : 5u;
            c.robust = r == 1 || r == 2 ? 4u : 0u;
            if (r >= 0) im[r] = (float *)malloc(W * H * 12u);
            render_cfg(&b.s, &cam, gz, &c, r < 0 ? ref : im[r], NULL);
            if (r >= 0)
                for (i = 0; i < 3u * W * H; ++i) {
                    double a = im[r][i] < 1.0f ? (double)im[r][i] : 1.0, e = ref[i] < 1.0f ? (double)ref[i] : 1.0;
                    se[r] += (a - e) * (a - e);
                    specks[r] += a > e + 0.15;
                }
        }
        for (i = 0; i < 3u * W * H; ++i) { /* robust - plain, same samples, 64 and 256 spp */
            dd[0] += ((double)im[1][i] - (double)im[0][i]) * ((double)im[1][i] - (double)im[0][i]);
            dd[1] += ((double)im[2][i] - (double)im[3][i]) * ((double)im[2][i] - (double)im[3][i]);
        }
        check(specks[0] >= 4u && 2u * specks[1] <= specks[0], "robust: Cornell box with a mirror sphere, 64 spp: half the specks of the plain mean or fewer",
              "specks: plain %u robust %u", specks[0], specks[1]);
        check(se[3] > 0.0 && se[2] <= 1.2 * se[3] && dd[1] < 0.5 * dd[0], "robust: consistent: at 256 spp its error within 20 % of the plain mean's, and its difference from the plain mean under half that at 64 spp",
              "error: robust 64 spp %.5f, 256 spp %.5f; plain 256 spp %.5f; robust - plain: %.5f at 64, %.5f at 256", se[1], se[2], se[3], dd[0], dd[1]);
        free(ref); free(b.mem);
        for (r = 0; r < 4; ++r) free(im[r]);
    }
    {   /* the specular chains are not grouped: a light (albedo 0: no bounce off it) seen
           directly and in a mirror sphere, nothing else, black background: every sample is a
           chain's, so robust 4 gives the plain mean at every pixel, the edges' partial
           coverage included (grouped, they would take a median group) */
        fovpt_material m[2];
        fovpt_shape sh[26];
        fovpt_scene_desc d;
        scene_buf b;
        const uint32_t W = 24, H = 16;
        float *im[2];
        uint32_t edge = 0, diff = 0;
        fovpt_material_init(&m[0]); fovpt_material_init(&m[1]);
        m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 0.0f;
        m[0].emission[0] = 20.0f; m[0].emission[1] = 10.0f; m[0].emission[2] = 5.0f;
        m[1].type = FOVPT_MAT_MIRROR;
        for (i = 0; i < 24u; ++i) /* small lights, each a fraction of a pixel */
            fovpt_shape_sphere(&sh[i], -1.4f + 0.25f * (float)(i % 6u) + 0.031f * (float)i, -0.7f + 0.37f * (float)(i / 6u), 0.4f, 0.012f + 0.001f * (float)i, 0);
        fovpt_shape_sphere(&sh[24], -0.6f, 0.2f, 0.5f, 0.35f, 0);
        fovpt_shape_sphere(&sh[25], 0.8f, -0.1f, 0.3f, 0.5f, 1);
        fovpt_scene_desc_init(&d);
        d.shapes = sh; d.num_shapes = 26; d.materials = m; d.num_materials = 2;
        d.background[0] = 0.3f; d.background[1] = 0.5f; d.background[2] = 0.7f; /* a chain's too */
        build(&b, &d);
        {
            fovpt_config c = fovpt_config_default();
            c.spp = 48u; c.seed = 3u;
            render_robust_pair(&b.s, W, H, c, im);
        }
        for (i = 0; i < W * H; ++i) {
            edge += im[0][3 * i] > 0.05f && im[0][3 * i] < 6.0f; /* under 30 % covered */
            for (k = 0; k < 3; ++k) diff += !(fabsf(im[0][3 * i + k] - im[1][3 * i + k]) <= 1e-5f * im[0][3 * i + k] + 1e-7f);
        }
        check(diff == 0 && edge >= 8u, "robust: specular chains only (a light seen directly and in a mirror, the background): the plain mean at every pixel, partly covered edges included",
              "%u values differ, %u edge pixels", diff, edge);
        free(im[0]); free(im[1]); free(b.mem);
    }
    {   /* Whitted mode (no random numbers along a ray: every sample the chain's) gives the
           plain mean bit for bit on the Cornell box, and a sample that comes out NaN (a light
           1e9 wide at 1e-11 from a lit quad: the light's g overflows, 0 * inf) is dropped as
           with robust 0, not passed into the pixel (the review R3's reproducer) */
        fovpt_material m[6];
        fovpt_shape sh[8];
        fovpt_scene_desc d;
        scene_buf b;
        fovpt_camera cam;
        const uint32_t W = 24, H = 16;
        float *im[2];
        uint32_t diff = 0, nan1 = 0, r;
        fov_gaze gz;
        cornell(m, sh, &d, 0);
        build(&b, &d);
        {
            fovpt_config c = fovpt_config_default();
            c.mode = FOVPT_MODE_WHITTED; c.spp = 32u; c.seed = 8u;
            render_robust_pair(&b.s, W, H, c, im);
        }
        for (i = 0; i < 3u * W * H; ++i) diff += memcmp(&im[0][i], &im[1][i], sizeof(float)) != 0;
        free(im[0]); free(im[1]); free(b.mem);
        {
            fovpt_material mw[2];
            fovpt_shape sw[2];
            float c0[3] = {-5e8f, -5e8f, 0.0f}, u0[3] = {1e9f, 0.0f, 0.0f}, v0[3] = {0.0f, 1e9f, 0.0f};
            float c1[3] = {-0.5f, -0.5f, -1e-11f}, u1[3] = {1.0f, 0.0f, 0.0f}, v1[3] = {0.0f, 1.0f, 0.0f};
            fovpt_material_init(&mw[0]); fovpt_material_init(&mw[1]);
            mw[0].albedo[0] = mw[0].albedo[1] = mw[0].albedo[2] = 0.0f;
            mw[0].emission[0] = mw[0].emission[1] = mw[0].emission[2] = 1.0f;
            mw[1].albedo[0] = 1.0f; mw[1].albedo[1] = mw[1].albedo[2] = 0.0f;
            fovpt_shape_quad(&sw[0], c0, u0, v0, 0); fovpt_shape_quad(&sw[1], c1, u1, v1, 1);
            fovpt_scene_desc_init(&d);
            d.shapes = sw; d.num_shapes = 2; d.materials = mw; d.num_materials = 2;
            build(&b, &d);
            fovpt_camera_init(&cam, 8, 8);
            cam.pos[0] = cam.pos[1] = 0.0f; cam.pos[2] = -5e-12f;
            cam.target[0] = cam.target[1] = 0.0f; cam.target[2] = -1.0f;
            for (r = 0; r < 2; ++r) {
                fovpt_config c = fovpt_config_default();
                fovpt_stats st;
                float img[8 * 8 * 3];
                uint32_t nn = 0;
                c.mode = FOVPT_MODE_WHITTED; c.spp = 24u; c.robust = r ? 4u : 0u;
                gz.x = 4.0f; gz.y = 4.0f;
                memset(&st, 0, sizeof st);
                if (render_cfg(&b.s, &cam, gz, &c, img, &st) != FOV_OK) nn += 2000u;
                for (i = 0; i < 192u; ++i) nn += !(img[i] >= 0.0f && img[i] <= FLT_MAX);
                if (r) nan1 = nn + (st.bad_samples == 0 ? 1000u : 0u); /* the scene must produce them */
                else nan1 += nn;
            }
            free(b.mem);
        }
        check(diff == 0 && nan1 == 0, "robust: Whitted mode gives the plain mean bit for bit, and a NaN sample is dropped (no NaN pixel)",
              "%u values differ; %u non-finite or negative values (1000: no bad sample to test)", diff, nan1);
    }
    {   /* an emission of 1e38 seen directly: the sample is capped at FOVPT_MAX_RADIANCE, and
           so is its chain's part: the pixel stays the cap, finite, robust or not */
        fovpt_material m[1];
        fovpt_shape sh[1];
        fovpt_scene_desc d;
        scene_buf b;
        fovpt_camera cam;
        float img[4 * 4 * 3];
        uint32_t off = 0, r;
        fov_gaze gz;
        fovpt_material_init(&m[0]);
        m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 0.0f;
        m[0].emission[0] = m[0].emission[1] = m[0].emission[2] = 1e38f;
        fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 0.1f, 0); /* small: its power stays finite */
        fovpt_scene_desc_init(&d);
        d.shapes = sh; d.num_shapes = 1; d.materials = m; d.num_materials = 1;
        if (!check(build(&b, &d) == FOV_OK, "robust: a lamp of 1e38 builds", " ")) return;
        fovpt_camera_init(&cam, 4, 4);
        cam.pos[2] = -0.15f; /* the lamp fills the view (40 degrees of half-angle) */
        gz.x = 2.0f; gz.y = 2.0f;
        for (r = 0; r < 2; ++r) {
            fovpt_config c = fovpt_config_default();
            c.spp = 32u; c.robust = r ? 16u : 0u;
            if (render_cfg(&b.s, &cam, gz, &c, img, NULL) != FOV_OK) { off += 1000u; continue; }
            for (i = 0; i < 48u; ++i) off += !(fabsf(img[i] - (float)FOVPT_MAX_RADIANCE) <= 1e-5f * (float)FOVPT_MAX_RADIANCE);
        }
        free(b.mem);
        check(off == 0, "robust: a 1e38 emission seen directly stays at FOVPT_MAX_RADIANCE with robust 16, as without", "%u values off", off);
    }
    {   /* LAYERS: robust groups a stride-1 point's samples, and a coarser point's where it does
           not group them for clamp_white; with clamp_white 1 the coarse layers are unchanged */
        fovpt_material m[6];
        fovpt_shape sh[8];
        fovpt_scene_desc d;
        scene_buf b;
        fovpt_camera cam;
        uint32_t changed[2][2] = {{0, 0}, {0, 0}}, cw, n;
        fov_gaze gz;
        cornell(m, sh, &d, 0);
        build(&b, &d);
        fovpt_camera_init(&cam, 48, 32);
        cam.pos[2] = -3.0f;
        gz.x = 24.0f; gz.y = 16.0f;
        for (cw = 0; cw < 2; ++cw) {
            fovpt_ctx ctx[2];
            void *mem[2];
            uint32_t r;
            for (r = 0; r < 2; ++r) {
                fovpt_config c = fovpt_config_default();
                size_t need = 0;
                c.method = FOVPT_METHOD_LAYERS;
                fovpt_layers_preset(&c.layers, FOVPT_LAYERS_KTH_RADIUS);
                for (n = 0; n < c.layers.count; ++n) c.layers.layer[n].spp = 32u;
                c.layers.clamp_white = cw ? 1.0f : 0.0f;
                c.robust = r ? 4u : 0u;
                fovpt_memory_size(&c, &cam, &need);
                mem[r] = amalloc(need);
                fovpt_init(&ctx[r], &c, &b.s, &cam, gz, mem[r], need);
                fovpt_trace_rows(&ctx[r], 0, 0, 32, NULL);
            }
            for (n = 0; n < ctx[0].lay.count; ++n) {
                size_t q, cnt = (size_t)ctx[0].layer_nx[n] * ctx[0].layer_ny[n] * 4u;
                for (q = 0; q < cnt; ++q)
                    changed[cw][ctx[0].lay.layer[n].stride >= 2u] += memcmp(&ctx[0].layer_buf[n][q], &ctx[1].layer_buf[n][q], sizeof(float)) != 0;
            }
            free(mem[0]); free(mem[1]);
        }
        free(b.mem);
        check(changed[0][0] > 0 && changed[0][1] > 0 && changed[1][0] > 0 && changed[1][1] == 0,
              "robust: LAYERS groups the stride-1 points and the coarse ones, except the coarse ones clamp_white groups",
              "values changed: stride 1 %u, coarse %u; with clamp_white: stride 1 %u, coarse %u", changed[0][0], changed[0][1], changed[1][0], changed[1][1]);
    }
}

/* The Lanczos upsampling of ZONES written out directly, in double (the test's own
   reference: L(x) = sinc(x) sinc(x / a) from sin per tap): lattice n of ctx at pixel
   (x, y), 2a taps per axis clamped to the lattice, untraced taps dropped and the weights
   renormalised, unavailable (0) when they sum to at most 0.05; *ws_out the sum. */
static double ref_sinc(double x)
{
    const double pi = 3.14159265358979323846;
    return fabs(x) < 1e-9 ? 1.0 : sin(pi * x) / (pi * x);
}
static int ref_lanczos(const fovpt_ctx *ctx, uint32_t n, uint32_t x, uint32_t y, double c[3],
                       double *ws_out)
{
    const float *buf = ctx->layer_buf[n];
    int32_t d = (int32_t)ctx->lay.layer[n].stride, nx = (int32_t)ctx->layer_nx[n],
        ny = (int32_t)ctx->layer_ny[n], a = (int32_t)ctx->lanczos, i, j;
    int32_t rx = (int32_t)x - (int32_t)ctx->layer_ox[n], ry = (int32_t)y - (int32_t)ctx->layer_oy[n];
    /* the lattice cell left of / above the pixel (floor division) and the fraction in it */
    int32_t kx = (int32_t)floor((double)rx / d), ky = (int32_t)floor((double)ry / d);
    double fx = (double)(rx - kx * d) / d, fy = (double)(ry - ky * d) / d, ws = 0.0;
    c[0] = c[1] = c[2] = 0.0;
    for (j = 1 - a; j <= a; ++j)
        for (i = 1 - a; i <= a; ++i) {
            double tx = fx - i, ty = fy - j, w;
            int32_t ki = kx + i, lj = ky + j;
            const float *p;
            if (fabs(tx) >= a || fabs(ty) >= a) continue;
            w = ref_sinc(tx) * ref_sinc(tx / a) * ref_sinc(ty) * ref_sinc(ty / a);
            ki = ki < 0 ? 0 : (ki >= nx ? nx - 1 : ki);
            lj = lj < 0 ? 0 : (lj >= ny ? ny - 1 : lj);
            p = buf + 4u * ((size_t)lj * (size_t)nx + (size_t)ki);
            if (!(p[3] > 0.0f)) continue;
            ws += w;
            w /= (double)p[3];
            c[0] += w * (double)p[0]; c[1] += w * (double)p[1]; c[2] += w * (double)p[2];
        }
    *ws_out = ws;
    if (!(ws > 0.05)) return 0;
    for (i = 0; i < 3; ++i) c[i] = c[i] / ws > 0.0 ? c[i] / ws : 0.0;
    return 1;
}

/* session 14: the resolve's column cache (fovpt__layer_value_cc) against the direct filters
   at every pixel of every layer: LAYERS (Catmull-Rom; B-spline and hollow, whose untraced
   lattice points take the bilinear fallback) against fovpt__layer_value, ZONES (Lanczos 3
   and 2) against ref_lanczos above, ZONES B-spline against fovpt__layer_value; gaze at the
   centre and off the image: the same availability (a Lanczos weight sum within 1e-4 of the
   0.05 cut is not counted either way), colours within 1e-5 relative (the sums' order
   differs) or 1e-4 against the double Lanczos. */
static void test_resolve_cache(void)
{
    fovpt_material m[6];
    fovpt_shape sh[8];
    fovpt_scene_desc d;
    scene_buf b;
    uint32_t v, bad = 0, values = 0, fallbacks = 0, lanczos = 0;
    cornell(m, sh, &d, 0);
    if (!check(build(&b, &d) == FOV_OK, "resolve cache: scene builds", " ")) return;
    for (v = 0; v < 10u; ++v) {
        fovpt_config c = fovpt_config_default();
        fovpt_camera cam;
        fovpt_ctx ctx;
        fov_gaze g;
        size_t need = 0;
        void *mem;
        uint32_t n, x, y, count;
        fovpt_camera_init(&cam, 61, 47);
        cam.pos[2] = -3.0f;
        g.x = (v & 1u) ? 70.0f : 30.5f; g.y = (v & 1u) ? -9.0f : 23.5f;
        c.spp = 1;
        c.method = v < 4u ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_ZONES;
        if (v == 2u || v == 3u) { c.layers.bspline = 1; c.layers.hollow = 1; }
        if (v == 6u || v == 7u) c.zones.lanczos_a = 2;
        if (v >= 8u) { c.zones.bspline = 1; c.zones.hollow = 1; }
        if (fovpt_memory_size(&c, &cam, &need) != FOV_OK) { ++bad; continue; }
        mem = amalloc(need);
        if (fovpt_init(&ctx, &c, &b.s, &cam, g, mem, need) != FOV_OK) { ++bad; free(mem); continue; }
        fovpt_trace_rows(&ctx, 0, 0, 47, NULL);
        fovpt_refine_rows(&ctx, 0, 0, 47, NULL);
        count = ctx.lay.count;
        for (n = 0; n < count; ++n)
            for (y = 0; y < 47u; ++y) {
                fovpt__cc cc;
                cc.row = UINT32_MAX;
                for (x = 0; x < 61u; ++x) {
                    float c1[3] = { -1, -1, -1 }, c2[3] = { -2, -2, -2 };
                    double r[3], ws = 1.0;
                    const int lz = ctx.lanczos && !(ctx.lay.bspline && ctx.lay.layer[n].stride >= 2);
                    int a1, a2 = fovpt__layer_value_cc(&ctx, n, x, y, c2, &cc), k;
                    if (lz) {
                        a1 = ref_lanczos(&ctx, n, x, y, r, &ws);
                        for (k = 0; k < 3; ++k) c1[k] = (float)r[k];
                        ++lanczos;
                    } else
                        a1 = fovpt__layer_value(&ctx, n, x, y, c1);
                    ++values;
                    if (lz && fabs(ws - 0.05) < 1e-4) continue;
                    if (a1 != a2) { ++bad; continue; }
                    if (!a1) { ++fallbacks; continue; }
                    for (k = 0; k < 3; ++k)
                        if (!(fabsf(c1[k] - c2[k]) <= (lz ? 1e-4f : 1e-5f) * fabsf(c1[k]) + 1e-6f)) ++bad;
                }
            }
        free(mem);
    }
    free(b.mem);
    check(bad == 0 && values > 40000u && lanczos > 10000u, "resolve's column cache = the direct filters at every pixel of every layer (LAYERS, ZONES' Lanczos against a double reference, B-spline, hollow)",
          "%u mismatches of %u values (%u Lanczos, %u unavailable)", bad, values, lanczos, fallbacks);
}

int main(void)
{
#ifdef FOVPT_TEST_BVH_ONLY
    /* the BVH = brute force sections alone (tests/xtarget runs them on each SIMD path:
       wasm32 scalar and SIMD128, AArch64 NEON under qemu-user) */
    test_f7_regressions();
    test_scene_bad();
    test_bvh_random();
    test_bvh_concentric();
    test_bvh_size_bound();
    test_any_length();
    test_bvh_adversarial();
    test_watertight();
    test_tiny_dir();
    test_dir_class();
    test_ray_fast();
    test_rev32();
    return fovcheck_summary();
#endif
    test_version();
    test_f1_camera_ray();
    test_f7_regressions();
    test_fuzz_findings();
    test_resolve_shortcuts();
    test_resolve_cache();
    test_robust();
    test_api();
    test_ecc();
    test_eyes();
    test_scene_bad();
    test_bvh_random();
    test_bvh_concentric();
    test_bvh_size_bound();
    test_user_hook();
    test_any_length();
    test_rng();
    test_bsdf();
    test_furnace();
    test_nee_equivalence();
    test_whitted();
    test_render();
    test_foveation_blocks();
    test_layers();
    test_layers_tiny();
    test_set_view_atomic();
    test_set_gaze_margin();
    test_zones();
    test_selective_rules();
    test_selective_render();
    test_temporal();
    test_bvh_adversarial();
    test_watertight();
    test_tiny_dir();
    test_dir_class();
    test_ray_fast();
    test_rev32();
    return fovcheck_summary();
}
