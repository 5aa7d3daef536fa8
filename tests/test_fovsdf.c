/*
 * test_fovsdf.c - unit tests of fovsdf.h: API and bad input, the four tracers, shading
 * helpers, the eccentricity model (with Table 4.1 of the thesis) and rendering.
 * (Scene programs and numerical stability: tests/test_fovsdf_scene.c.)
 *
 * Build and run from the repository root (C99, also compiles as C++11):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovsdf.c -lm -o build/tests/test_fovsdf
 * It also runs with -DFOV_NO_LIBM (the library's own float math; tolerances below are met
 * by both builds) and under -fsanitize=address,undefined.
 *
 * Output: one "PASS name" or "FAIL name: detail" line per check, then "N passed, N failed";
 * exit status 1 when a check failed. Expected values come from analytic formulas or brute
 * force computed here (mostly in double), never from the library under test.
 *
 * Sections (see main):
 *   1. API and bad input: every NULL pointer, size, NaN/Inf, range and degenerate case with
 *      its exact fov_result; misbehaving user SDFs (NaN, Inf, 1e-30, negative); result
 *      strings, config defaults, the logger; context and stats semantics.
 *   2. Tracers (classic, relaxed, autorelaxed, bv2018) through fovsdf_march and fovsdf_trace:
 *      analytic sphere and plane hits, misses, rays from inside, surfaces near t_max,
 *      evaluation counts, relaxation gains, threshold modes, parameter ranges, exhaustion.
 *   3. Shading (normals, soft shadows, Lambert, shading modes) and eccentricity (the display
 *      model, Table 4.1 of the thesis, symmetry, monotonicity, pixels per degree).
 *   4. Rendering: bands and tiles against one full render, determinism, strides, stats,
 *      supersampling coverage against the documented sample patterns, every built-in
 *      scene x method x shading mode, camera rays and stereo, an analytic sphere image.
 *   5. (FOV_NO_LIBM builds only) the built-in float math against libm.
 *   6. The mandelbulb's and the terrain's own float kernels (every build) against libm.
 * "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
 * Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025.
 */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementation compiled once per build
   (tests/common/fov_impl_sdf.c) instead of compiling it in this file; the private functions
   tested here are called through the test hook's wrappers (tests/common/fov_priv_sdf.h,
   fovtest_*), which are compiled in this file when it holds the implementation */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fov_priv_sdf.h"
#include "fovcheck.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ==== harness ============================================================================ */


#define N fovcheck_name /* tests/common/fovcheck.h */


static const char *rname(fov_result r)
{
    switch ((int)r) {
    case FOV_OK: return "FOV_OK";
    case FOV_ERR_INVALID_ARG: return "FOV_ERR_INVALID_ARG";
    case FOV_ERR_TOO_SMALL: return "FOV_ERR_TOO_SMALL";
    case FOV_ERR_LIMIT: return "FOV_ERR_LIMIT";
    case FOV_ERR_NULL: return "FOV_ERR_NULL";
    case FOV_ERR_NOT_FINITE: return "FOV_ERR_NOT_FINITE";
    case FOV_ERR_DEGENERATE: return "FOV_ERR_DEGENERATE";
    case FOV_ERR_UNSUPPORTED: return "FOV_ERR_UNSUPPORTED";
    default: return "(unknown code)";
    }
}

static void expect_res(const char *name, fov_result got, fov_result want)
{
    check(got == want, name, "got %s (%d), want %s (%d)", rname(got), (int)got, rname(want), (int)want);
}

static float f_nan(void)
{
    volatile float z = 0.0f;
    return z / z;
}
static float f_inf(void)
{
    volatile float z = 0.0f;
    return 1.0f / z;
}
static int fin(float x) { return x - x == 0.0f; }

static const char *kind_name(uint32_t k)
{
    return k == FOVSDF_MISS ? "MISS" : k == FOVSDF_HIT ? "HIT" : k == FOVSDF_EXHAUSTED ? "EXHAUSTED" : "?";
}

/* ==== test distance functions ============================================================ */
enum {
    K_SPHERES = 0, /* union of up to 4 spheres */
    K_PLANE,       /* dot(p, n) + off */
    K_NAN,         /* NaN everywhere */
    K_NAN_HALF,    /* NaN for x > 0, the spheres elsewhere */
    K_INF,         /* +Inf everywhere */
    K_TINY,        /* 1e-30 everywhere */
    K_NEG,         /* -1 everywhere */
    K_WALL_X,      /* the solid z >= 0 and x <= edge: max(-z, x - edge) */
    K_WALL_Y,      /* the solid z >= 0 and y <= edge: max(-z, y - edge) */
    K_CONST,       /* the constant off everywhere */
    K_SPHERES_X2   /* twice the spheres' distance (Lipschitz constant 2) */
};

typedef struct tsdf {
    int kind;
    int ns;
    float sc[4][3], sr[4];
    float n[3], off;
    float edge;
    unsigned long calls;
} tsdf;

static float sph_dist(const tsdf *u, const float p[3])
{
    float d = 1e30f;
    int i;
    for (i = 0; i < u->ns; ++i) {
        float dx = p[0] - u->sc[i][0], dy = p[1] - u->sc[i][1], dz = p[2] - u->sc[i][2];
        float di = sqrtf(dx * dx + dy * dy + dz * dz) - u->sr[i];
        if (di < d) d = di;
    }
    return d;
}

static float tsdf_eval(const float p[3], void *user)
{
    tsdf *u = (tsdf *)user;
    u->calls++;
    switch (u->kind) {
    case K_SPHERES: return sph_dist(u, p);
    case K_PLANE: return p[0] * u->n[0] + p[1] * u->n[1] + p[2] * u->n[2] + u->off;
    case K_NAN: return f_nan();
    case K_NAN_HALF: return p[0] > 0.0f ? f_nan() : sph_dist(u, p);
    case K_INF: return f_inf();
    case K_TINY: return 1e-30f;
    case K_NEG: return -1.0f;
    case K_WALL_X: return fmaxf(-p[2], p[0] - u->edge);
    case K_WALL_Y: return fmaxf(-p[2], p[1] - u->edge);
    case K_CONST: return u->off;
    case K_SPHERES_X2: return 2.0f * sph_dist(u, p);
    default: return 1.0f;
    }
}

static void tsdf_sphere(tsdf *u, float cx, float cy, float cz, float r)
{
    memset(u, 0, sizeof *u);
    u->kind = K_SPHERES;
    u->ns = 1;
    u->sc[0][0] = cx; u->sc[0][1] = cy; u->sc[0][2] = cz;
    u->sr[0] = r;
}

static void tsdf_add_sphere(tsdf *u, float cx, float cy, float cz, float r)
{
    int i = u->ns++;
    u->sc[i][0] = cx; u->sc[i][1] = cy; u->sc[i][2] = cz;
    u->sr[i] = r;
}

static void tsdf_plane(tsdf *u, float nx, float ny, float nz, float off)
{
    memset(u, 0, sizeof *u);
    u->kind = K_PLANE;
    u->n[0] = nx; u->n[1] = ny; u->n[2] = nz;
    u->off = off;
}

static void scene_for(fovsdf_scene *sc, tsdf *u)
{
    fovsdf_scene_init(sc);
    sc->dist = tsdf_eval;
    sc->user = u;
}

/* A camera at pos looking at tgt, up +y. */
static void cam_at(fovsdf_camera *cam, uint32_t w, uint32_t h, float px, float py, float pz, float tx, float ty,
                   float tz)
{
    fovsdf_camera_init(cam, w, h);
    cam->pos[0] = px; cam->pos[1] = py; cam->pos[2] = pz;
    cam->target[0] = tx; cam->target[1] = ty; cam->target[2] = tz;
}

static fov_gaze gaze_at(float x, float y)
{
    fov_gaze g;
    g.x = x;
    g.y = y;
    return g;
}

static fovsdf_march_params mp_make(uint32_t method, float eps, float t_max, uint32_t max_steps)
{
    fovsdf_march_params mp;
    memset(&mp, 0, sizeof mp);
    mp.method = method;
    mp.max_steps = max_steps;
    mp.eps = eps;
    mp.eps_cone = 0.0f;
    mp.t_max = t_max;
    mp.omega = 1.6f;
    mp.ar_beta = 0.3f;
    mp.bv_relax = 0.9f;
    return mp;
}

static const char *const g_mname[4] = { "classic", "relaxed", "autorelaxed", "bv2018" };

/* ==== 1. API and bad input ================================================================ */

/* A valid baseline: unit sphere, 64x36 camera at z = -5, default config, centred gaze. */
typedef struct base_t {
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config cfg;
    fov_gaze gaze;
} base_t;

static void base_init(base_t *b)
{
    tsdf_sphere(&b->u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&b->sc, &b->u);
    cam_at(&b->cam, 64, 36, 0.0f, 0.0f, -5.0f, 0.0f, 0.0f, 0.0f);
    b->cfg = fovsdf_config_default();
    b->gaze = gaze_at(32.0f, 18.0f);
}

static fov_result init_cam(base_t *b, const fovsdf_camera *cam)
{
    fovsdf_ctx ctx;
    return fovsdf_init(&ctx, &b->cfg, &b->sc, cam, b->gaze, NULL, 0);
}
static fov_result init_cfg(base_t *b, const fovsdf_config *cfg)
{
    fovsdf_ctx ctx;
    return fovsdf_init(&ctx, cfg, &b->sc, &b->cam, b->gaze, NULL, 0);
}
static fov_result init_scene(base_t *b, const fovsdf_scene *sc)
{
    fovsdf_ctx ctx;
    return fovsdf_init(&ctx, &b->cfg, sc, &b->cam, b->gaze, NULL, 0);
}

typedef struct logrec {
    int calls;
    int32_t code;
    uint32_t level;
    int tag_ok;
} logrec;

static void test_logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    logrec *r = (logrec *)user;
    (void)msg;
    (void)line;
    r->calls++;
    r->code = code;
    r->level = level;
    r->tag_ok = tag != NULL && strcmp(tag, "fovsdf") == 0;
}

static void test_null_pointers(void)
{
    base_t b;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_hit hit;
    fovsdf_march_params mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 10.0f, 64);
    float ro[3] = { 0.0f, 0.0f, -5.0f }, rd[3] = { 0.0f, 0.0f, 1.0f }, v3[3], w3[3], x3[3];
    fovsdf_node nodes[4];
    fovsdf_builder bl;
    fovsdf_program prog;
    fovsdf_builtin bi;
    size_t bytes = 0;
    unsigned char mem[256];
    fov_ecc_model em;
    fovsdf_config cfg;
    fov_display disp;

    base_init(&b);
    expect_res("init_baseline_ok", fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, b.gaze, NULL, 0), FOV_OK);
    expect_res("init_null_cfg_means_defaults", fovsdf_init(&ctx, NULL, &b.sc, &b.cam, b.gaze, NULL, 0), FOV_OK);
    expect_res("null_init_ctx", fovsdf_init(NULL, &b.cfg, &b.sc, &b.cam, b.gaze, NULL, 0), FOV_ERR_NULL);
    expect_res("null_init_scene", fovsdf_init(&ctx, &b.cfg, NULL, &b.cam, b.gaze, NULL, 0), FOV_ERR_NULL);
    expect_res("null_init_cam", fovsdf_init(&ctx, &b.cfg, &b.sc, NULL, b.gaze, NULL, 0), FOV_ERR_NULL);

    fovsdf_output_init(&out);
    expect_res("null_render_rows_ctx", fovsdf_render_rows(NULL, 0, 1, &out, NULL), FOV_ERR_NULL);
    expect_res("null_render_rows_out", fovsdf_render_rows(&ctx, 0, 1, NULL, NULL), FOV_ERR_NULL);
    expect_res("null_render_tile_ctx", fovsdf_render_tile(NULL, 0, 0, 1, 1, &out, NULL), FOV_ERR_NULL);
    expect_res("null_render_tile_out", fovsdf_render_tile(&ctx, 0, 0, 1, 1, NULL, NULL), FOV_ERR_NULL);

    expect_res("null_trace_ctx", fovsdf_trace(NULL, ro, rd, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_trace_ro", fovsdf_trace(&ctx, NULL, rd, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_trace_rd", fovsdf_trace(&ctx, ro, NULL, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_trace_hit", fovsdf_trace(&ctx, ro, rd, 0.0f, NULL, NULL), FOV_ERR_NULL);

    expect_res("null_march_scene", fovsdf_march(NULL, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_march_params", fovsdf_march(&b.sc, NULL, ro, rd, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_march_ro", fovsdf_march(&b.sc, &mp, NULL, rd, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_march_rd", fovsdf_march(&b.sc, &mp, ro, NULL, 0.0f, &hit, NULL), FOV_ERR_NULL);
    expect_res("null_march_hit", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, NULL, NULL), FOV_ERR_NULL);

    expect_res("null_camera_ray_ctx", fovsdf_camera_ray(NULL, 1.0f, 1.0f, v3, w3), FOV_ERR_NULL);
    expect_res("null_camera_ray_ro", fovsdf_camera_ray(&ctx, 1.0f, 1.0f, NULL, w3), FOV_ERR_NULL);
    expect_res("null_camera_ray_rd", fovsdf_camera_ray(&ctx, 1.0f, 1.0f, v3, NULL), FOV_ERR_NULL);

    expect_res("null_camera_basis_cam", fovsdf_camera_basis(NULL, v3, w3, x3), FOV_ERR_NULL);
    expect_res("null_camera_basis_right", fovsdf_camera_basis(&b.cam, NULL, w3, x3), FOV_ERR_NULL);
    expect_res("null_camera_basis_up", fovsdf_camera_basis(&b.cam, v3, NULL, x3), FOV_ERR_NULL);
    expect_res("null_camera_basis_fwd", fovsdf_camera_basis(&b.cam, v3, w3, NULL), FOV_ERR_NULL);

    fovsdf_builder_init(&bl, nodes, 4);
    (void)fovsdf_sphere(&bl, 1.0f);
    expect_res("null_program_size_nodes", fovsdf_program_size(NULL, 1, 0, &bytes), FOV_ERR_NULL);
    expect_res("null_program_size_bytes", fovsdf_program_size(nodes, 1, 0, NULL), FOV_ERR_NULL);
    expect_res("null_program_build_prog", fovsdf_program_build(NULL, nodes, 1, 0, mem, sizeof mem), FOV_ERR_NULL);
    expect_res("null_program_build_nodes", fovsdf_program_build(&prog, NULL, 1, 0, mem, sizeof mem), FOV_ERR_NULL);
    expect_res("null_program_build_mem", fovsdf_program_build(&prog, nodes, 1, 0, NULL, sizeof mem), FOV_ERR_NULL);

    expect_res("null_builtin_size_bytes", fovsdf_builtin_size(0, NULL), FOV_ERR_NULL);
    expect_res("null_builtin_init_out", fovsdf_builtin_init(0, NULL, mem, sizeof mem), FOV_ERR_NULL);
    expect_res("null_builtin_init_mem", fovsdf_builtin_init(0, &bi, NULL, 1u << 20), FOV_ERR_NULL);

    memset(&disp, 0, sizeof disp);
    expect_res("null_ecc_init_model", fovsdf_ecc_init(NULL, &disp, 60.0f, 64, 36, b.gaze), FOV_ERR_NULL);
    expect_res("ecc_init_null_display_means_zero", fovsdf_ecc_init(&em, NULL, 60.0f, 64, 36, b.gaze), FOV_OK);

    {
        /* functions without a result code: NULL pointers are ignored (no crash, no NaN;
           the soft shadow stays in its documented range [0, 1]) */
        fovsdf_stats st;
        float n3[3], c3[3], p3[3] = { 0.0f, 0.0f, 0.0f };
        float sh, dd, ed, pp;
        memset(&st, 0, sizeof st);
        fovsdf_camera_init(NULL, 4, 4);
        fovsdf_scene_init(NULL);
        fovsdf_scene_set_program(NULL, NULL);
        fovsdf_output_init(NULL);
        fovsdf_stats_add(NULL, &st);
        fovsdf_stats_add(&st, NULL);
        fovsdf_builder_init(NULL, nodes, 4);
        fovsdf_normal(NULL, p3, 1e-3f, n3, NULL);
        fovsdf_normal(&ctx, NULL, 1e-3f, n3, NULL);
        fovsdf_normal(&ctx, p3, 1e-3f, NULL, NULL);
        fovsdf_shade(NULL, p3, p3, p3, 0, c3, NULL);
        fovsdf_shade(&ctx, p3, p3, p3, 0, NULL, NULL);
        fovsdf_sky(NULL, p3, c3);
        fovsdf_sky(&ctx, p3, NULL);
        sh = fovsdf_soft_shadow(NULL, p3, p3, 0.0f, 1.0f, 16.0f, NULL);
        dd = fovsdf_distance(NULL, p3, NULL, NULL);
        ed = fovsdf_ecc_deg(NULL, 1.0f, 1.0f);
        pp = fovsdf_ecc_ppd(NULL);
        check(sh >= 0.0f && sh <= 1.0f && dd == dd && ed == ed && pp == pp, "null_void_functions_no_crash", "soft_shadow(NULL) %g, distance(NULL) %g, ecc_deg(NULL) %g, ecc_ppd(NULL) %g",
              (double)sh, (double)dd, (double)ed, (double)pp);
    }
    cfg = fovsdf_config_default();
    expect_res("null_config_resolve_in", fovsdf_config_resolve(NULL, &cfg), FOV_ERR_NULL);
    expect_res("null_config_resolve_out", fovsdf_config_resolve(&cfg, NULL), FOV_ERR_NULL);
    expect_res("null_memory_size_bytes", fovsdf_memory_size(&cfg, &b.cam, NULL), FOV_ERR_NULL);
}

static void test_sizes(void)
{
    base_t b;
    fovsdf_camera cam;
    fov_ecc_model em;
    size_t bytes = 0;
    base_init(&b);
    cam = b.cam; cam.width = 0;
    expect_res("init_width_0", init_cam(&b, &cam), FOV_ERR_INVALID_ARG);
    cam = b.cam; cam.height = 0;
    expect_res("init_height_0", init_cam(&b, &cam), FOV_ERR_INVALID_ARG);
    cam = b.cam; cam.width = FOVSDF_MAX_DIM + 1u;
    expect_res("init_width_above_max_dim", init_cam(&b, &cam), FOV_ERR_LIMIT);
    cam = b.cam; cam.height = FOVSDF_MAX_DIM + 1u;
    expect_res("init_height_above_max_dim", init_cam(&b, &cam), FOV_ERR_LIMIT);
    cam = b.cam; cam.width = FOVSDF_MAX_DIM; cam.height = 1;
    expect_res("init_width_at_max_dim_ok", init_cam(&b, &cam), FOV_OK);
    cam = b.cam; cam.width = 0xFFFFFFFFu;
    expect_res("init_width_uint32_max", init_cam(&b, &cam), FOV_ERR_LIMIT);
    expect_res("ecc_init_width_0", fovsdf_ecc_init(&em, NULL, 60.0f, 0, 36, b.gaze), FOV_ERR_INVALID_ARG);
    expect_res("ecc_init_height_0", fovsdf_ecc_init(&em, NULL, 60.0f, 64, 0, b.gaze), FOV_ERR_INVALID_ARG);
    expect_res("ecc_init_width_above_max_dim", fovsdf_ecc_init(&em, NULL, 60.0f, FOVSDF_MAX_DIM + 1u, 36, b.gaze),
               FOV_ERR_LIMIT);
    expect_res("ecc_init_height_above_max_dim", fovsdf_ecc_init(&em, NULL, 60.0f, 64, FOVSDF_MAX_DIM + 1u, b.gaze),
               FOV_ERR_LIMIT);
    { /* a finite gaze however far off-screen is valid (the shared block says so): the model
         keeps its direction; eccentricities against a double-precision reference */
        static const float far[4][2] = { { 3e38f, -3e38f }, { 2e19f, 0.0f }, { -1e30f, 1e30f }, { 0.0f, 5e25f } };
        int k, ok_codes = 1, ok_deg = 1;
        double worst = 0.0;
        for (k = 0; k < 4; k++) {
            fov_gaze gf = gaze_at(far[k][0], far[k][1]);
            fovsdf_ctx fctx;
            int x, y;
            if (fovsdf_ecc_init(&em, NULL, 60.0f, 64, 36, gf) != FOV_OK ||
                fovsdf_init(&fctx, &b.cfg, &b.sc, &b.cam, gf, NULL, 0) != FOV_OK) { ok_codes = 0; continue; }
            for (y = 0; y < 36; y += 7)
                for (x = 0; x < 64; x += 9) {
                    /* the gaze ray's direction: (gx - cx, gy - cy, f) scaled, in double */
                    double f = 18.0 / tan(30.0 * 3.14159265358979323846 / 180.0), gx = (double)far[k][0] - 32.0, gy = (double)far[k][1] - 18.0;
                    double sc = fabs(gx) > fabs(gy) ? fabs(gx) : fabs(gy), g0 = gx / sc, g1 = gy / sc, g2 = f / sc;
                    double v0 = x + 0.5 - 32.0, v1 = y + 0.5 - 18.0, v2 = f;
                    double c = (v0 * g0 + v1 * g1 + v2 * g2) / sqrt((v0 * v0 + v1 * v1 + v2 * v2) * (g0 * g0 + g1 * g1 + g2 * g2));
                    double ref = acos(c < -1.0 ? -1.0 : c > 1.0 ? 1.0 : c) * 180.0 / 3.14159265358979323846;
                    double got = (double)fovsdf_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f), e = fabs(got - ref);
                    if (!(e <= 0.01)) ok_deg = 0;
                    if (e > worst || e != e) worst = e;
                }
        }
        check(ok_codes, "far_offscreen_gaze_accepted", "ecc_init and init with gazes up to 3e38 px off the screen");
        check(ok_deg, "far_offscreen_gaze_ecc_deg", "worst |ecc - double reference| = %g deg (limit 0.01)", worst);
    }
    cam = b.cam; cam.width = 0;
    expect_res("memory_size_width_0", fovsdf_memory_size(&b.cfg, &cam, &bytes), FOV_ERR_INVALID_ARG);
    cam = b.cam; cam.height = FOVSDF_MAX_DIM + 1u;
    expect_res("memory_size_height_above_max_dim", fovsdf_memory_size(&b.cfg, &cam, &bytes), FOV_ERR_LIMIT);
    bytes = 12345;
    expect_res("memory_size_ok", fovsdf_memory_size(&b.cfg, &b.cam, &bytes), FOV_OK);
    check(bytes == 0, "memory_size_is_0", "bytes = %lu, documented 0 for this version", (unsigned long)bytes);
}

static void test_not_finite(void)
{
    static const char *const vn[3] = { "nan", "pinf", "ninf" };
    base_t b;
    int k;
    base_init(&b);
    for (k = 0; k < 3; ++k) {
        float v = k == 0 ? f_nan() : k == 1 ? f_inf() : -f_inf();
        fovsdf_camera cam;
        fovsdf_config cfg;
        fovsdf_ctx ctx;
        fov_gaze g;
        int i;
        for (i = 0; i < 3; ++i) {
            cam = b.cam; cam.pos[i] = v;
            expect_res(N("camera_pos%d_%s", i, vn[k]), init_cam(&b, &cam), FOV_ERR_NOT_FINITE);
            cam = b.cam; cam.target[i] = v;
            expect_res(N("camera_target%d_%s", i, vn[k]), init_cam(&b, &cam), FOV_ERR_NOT_FINITE);
            cam = b.cam; cam.up[i] = v;
            expect_res(N("camera_up%d_%s", i, vn[k]), init_cam(&b, &cam), FOV_ERR_NOT_FINITE);
        }
        cam = b.cam; cam.fov_y_deg = v;
        expect_res(N("camera_fov_y_%s", vn[k]), init_cam(&b, &cam), FOV_ERR_NOT_FINITE);
        cam = b.cam; cam.eye_offset = v;
        expect_res(N("camera_eye_offset_%s", vn[k]), init_cam(&b, &cam), FOV_ERR_NOT_FINITE);
        g = b.gaze; g.x = v;
        expect_res(N("gaze_x_%s", vn[k]), fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, g, NULL, 0), FOV_ERR_NOT_FINITE);
        g = b.gaze; g.y = v;
        expect_res(N("gaze_y_%s", vn[k]), fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, g, NULL, 0), FOV_ERR_NOT_FINITE);
        {
            fov_ecc_model em;
            g = b.gaze; g.x = v;
            expect_res(N("ecc_init_gaze_x_%s", vn[k]), fovsdf_ecc_init(&em, NULL, 60.0f, 64, 36, g), FOV_ERR_NOT_FINITE);
        }
        cfg = b.cfg; cfg.eps = v;
        expect_res(N("config_eps_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.t_max = v;
        expect_res(N("config_t_max_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.omega = v;
        expect_res(N("config_omega_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.display.fov_y_deg = v;
        expect_res(N("config_display_fov_y_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.display.pixel_pitch_mm = v;
        expect_res(N("config_display_pitch_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.display.distance_mm = v;
        expect_res(N("config_display_distance_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.display.axis_dx = v;
        expect_res(N("config_display_axis_dx_%s", vn[k]), init_cfg(&b, &cfg), FOV_ERR_NOT_FINITE);
        cfg = b.cfg; cfg.eps = v;
        expect_res(N("config_resolve_eps_%s", vn[k]), fovsdf_config_resolve(&cfg, &cfg), FOV_ERR_NOT_FINITE);
    }
}

static void test_ranges(void)
{
    base_t b;
    fovsdf_camera cam;
    fovsdf_config cfg, res;
    fovsdf_scene sc;
    fovsdf_ctx ctx;
    fovsdf_hit hit;
    fovsdf_march_params mp;
    float ro[3] = { 0.0f, 0.0f, -5.0f }, rd[3] = { 0.0f, 0.0f, 1.0f };
    base_init(&b);

    cam = b.cam; cam.fov_y_deg = 180.0f;
    expect_res("camera_fov_y_180", init_cam(&b, &cam), FOV_ERR_INVALID_ARG);
    cam = b.cam; cam.fov_y_deg = 200.0f;
    expect_res("camera_fov_y_200", init_cam(&b, &cam), FOV_ERR_INVALID_ARG);
    cam = b.cam; cam.fov_y_deg = -1.0f;
    expect_res("camera_fov_y_negative", init_cam(&b, &cam), FOV_ERR_INVALID_ARG);
    cam = b.cam; cam.fov_y_deg = 179.0f;
    expect_res("camera_fov_y_179_ok", init_cam(&b, &cam), FOV_OK);
    cam = b.cam; cam.target[0] = cam.pos[0]; cam.target[1] = cam.pos[1]; cam.target[2] = cam.pos[2];
    expect_res("camera_target_equals_pos", init_cam(&b, &cam), FOV_ERR_DEGENERATE);
    cam = b.cam; cam.up[0] = 0.0f; cam.up[1] = 0.0f; cam.up[2] = 2.0f;
    expect_res("camera_up_parallel_to_view", init_cam(&b, &cam), FOV_ERR_DEGENERATE);
    cam = b.cam; cam.up[0] = 0.0f; cam.up[1] = 0.0f; cam.up[2] = -1.0f;
    expect_res("camera_up_antiparallel_to_view", init_cam(&b, &cam), FOV_ERR_DEGENERATE);
    cam = b.cam; cam.pos[0] = 0.0f; cam.pos[1] = 5.0f; cam.pos[2] = 0.0f; /* looking straight down, up +y */
    expect_res("camera_looking_down_up_y", init_cam(&b, &cam), FOV_ERR_DEGENERATE);

    cfg = b.cfg; cfg.max_steps = FOVSDF_MAX_STEPS + 1u;
    expect_res("config_max_steps_above_cap", init_cfg(&b, &cfg), FOV_ERR_LIMIT);
    expect_res("config_resolve_max_steps_above_cap", fovsdf_config_resolve(&cfg, &res), FOV_ERR_LIMIT);
    cfg = b.cfg; cfg.max_steps = FOVSDF_MAX_STEPS;
    expect_res("config_max_steps_at_cap_ok", init_cfg(&b, &cfg), FOV_OK);
    cfg = b.cfg; cfg.spp = 3;
    expect_res("config_spp_3", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.spp = 8;
    expect_res("config_spp_8", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.method = (uint32_t)_FOVSDF_METHOD_NUM;
    expect_res("config_unknown_method", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.shading = (uint32_t)_FOVSDF_SHADE_NUM;
    expect_res("config_unknown_shading", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.eps_mode = (uint32_t)_FOVSDF_EPS_NUM;
    expect_res("config_unknown_eps_mode", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.eps = -1e-3f;
    expect_res("config_negative_eps", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.omega = 0.5f;
    expect_res("config_omega_0.5", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.omega = 2.0f;
    expect_res("config_omega_2", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.omega = 1.0f;
    expect_res("config_omega_1_ok", init_cfg(&b, &cfg), FOV_OK);
    cfg = b.cfg; cfg.ar_beta = 1.5f;
    expect_res("config_ar_beta_above_1", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.display.fov_y_deg = 180.0f;
    expect_res("config_display_fov_180", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);

    /* fovsdf_march: explicit parameters, 0 is not "default" */
    mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 10.0f, 0);
    expect_res("march_max_steps_0", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 10.0f, FOVSDF_MAX_STEPS + 1u);
    expect_res("march_max_steps_above_cap", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_LIMIT);
    mp = mp_make(FOVSDF_METHOD_RELAXED, 1e-4f, 10.0f, 64); mp.omega = 0.0f;
    expect_res("march_relaxed_omega_0", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make(FOVSDF_METHOD_AUTORELAXED, 1e-4f, 10.0f, 64); mp.ar_beta = 0.0f;
    expect_res("march_autorelaxed_beta_0", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make(FOVSDF_METHOD_CLASSIC, 0.0f, 10.0f, 64);
    expect_res("march_eps_and_cone_0", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 0.0f, 64);
    expect_res("march_t_max_0", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make(99u, 1e-4f, 10.0f, 64);
    expect_res("march_unknown_method", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make((uint32_t)FOVSDF_METHOD_CONE, 1e-4f, 10.0f, 64);
    expect_res("march_rejects_per_image_method", fovsdf_march(&b.sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 10.0f, 64);
    expect_res("march_negative_t_start", fovsdf_march(&b.sc, &mp, ro, rd, -1.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
    {
        float rd2[3] = { 0.0f, 0.0f, 2.0f }, rdh[3] = { 0.0f, 0.0f, 0.5f }, rdn[3] = { 0.0f, 0.0f, 1.0f };
        rdn[1] = f_nan();
        expect_res("march_rd_not_unit", fovsdf_march(&b.sc, &mp, ro, rd2, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
        expect_res("march_rd_nan", fovsdf_march(&b.sc, &mp, ro, rdn, 0.0f, &hit, NULL), FOV_ERR_NOT_FINITE);
        expect_res("init_for_trace_ok", fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, b.gaze, NULL, 0), FOV_OK);
        expect_res("trace_rd_length_2", fovsdf_trace(&ctx, ro, rd2, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
        expect_res("trace_rd_length_0.5", fovsdf_trace(&ctx, ro, rdh, 0.0f, &hit, NULL), FOV_ERR_INVALID_ARG);
        expect_res("trace_rd_nan", fovsdf_trace(&ctx, ro, rdn, 0.0f, &hit, NULL), FOV_ERR_NOT_FINITE);
        expect_res("trace_negative_t_start", fovsdf_trace(&ctx, ro, rd, -0.5f, &hit, NULL), FOV_ERR_INVALID_ARG);
        expect_res("trace_unit_rd_ok", fovsdf_trace(&ctx, ro, rd, 0.0f, &hit, NULL), FOV_OK);
    }

    /* render ranges and output strides */
    {
        static float rgb[64 * 36 * 3];
        static uint8_t b8[64 * 36 * 3];
        static float depth[64 * 36];
        static uint8_t hb[64 * 36];
        static uint32_t ev[64 * 36], st[64 * 36];
        static int32_t mat[64 * 36];
        fovsdf_output o;
        fovsdf_output_init(&o);
        o.depth = depth;
        expect_res("render_rows_y1_above_height", fovsdf_render_rows(&ctx, 0, 37, &o, NULL), FOV_ERR_INVALID_ARG);
        expect_res("render_rows_y0_above_y1", fovsdf_render_rows(&ctx, 5, 4, &o, NULL), FOV_ERR_INVALID_ARG);
        expect_res("render_rows_empty_ok", fovsdf_render_rows(&ctx, 4, 4, &o, NULL), FOV_OK);
        expect_res("render_tile_x1_above_width", fovsdf_render_tile(&ctx, 0, 0, 65, 1, &o, NULL), FOV_ERR_INVALID_ARG);
        expect_res("render_tile_x0_above_x1", fovsdf_render_tile(&ctx, 3, 0, 2, 1, &o, NULL), FOV_ERR_INVALID_ARG);
        expect_res("render_tile_y1_above_height", fovsdf_render_tile(&ctx, 0, 30, 4, 37, &o, NULL), FOV_ERR_INVALID_ARG);
        fovsdf_output_init(&o); o.rgb = rgb; o.rgb_stride = 3 * 64 - 1;
        expect_res("stride_rgb_too_small", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        fovsdf_output_init(&o); o.rgb8 = b8; o.rgb8_stride = 3 * 64 - 1;
        expect_res("stride_rgb8_too_small", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        fovsdf_output_init(&o); o.depth = depth; o.depth_stride = 63;
        expect_res("stride_depth_too_small", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        fovsdf_output_init(&o); o.hit = hb; o.hit_stride = 63;
        expect_res("stride_hit_too_small", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        fovsdf_output_init(&o); o.evals = ev; o.evals_stride = 63;
        expect_res("stride_evals_too_small", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        fovsdf_output_init(&o); o.steps = st; o.steps_stride = 63;
        expect_res("stride_steps_too_small", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        fovsdf_output_init(&o); o.material = mat; o.material_stride = 63;
        expect_res("stride_material_too_small", fovsdf_render_tile(&ctx, 0, 0, 64, 1, &o, NULL), FOV_ERR_TOO_SMALL);
        /* the rule is the widest row written: a 1-pixel tile fits a 63-element stride, 64 do not */
        expect_res("stride_checked_against_the_region", fovsdf_render_tile(&ctx, 0, 0, 1, 1, &o, NULL), FOV_OK);
        fovsdf_output_init(&o); o.rgb = rgb; o.rgb_stride = 3 * 64;
        expect_res("stride_rgb_exact_ok", fovsdf_render_rows(&ctx, 0, 1, &o, NULL), FOV_OK);
    }

    /* scenes */
    sc = b.sc; sc.dist = NULL; sc.dist_ex = NULL;
    expect_res("scene_without_distance", init_scene(&b, &sc), FOV_ERR_NULL);
    mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 10.0f, 64);
    expect_res("march_scene_without_distance", fovsdf_march(&sc, &mp, ro, rd, 0.0f, &hit, NULL), FOV_ERR_NULL);
    sc = b.sc; sc.num_lights = FOVSDF_MAX_LIGHTS + 1u;
    expect_res("scene_num_lights_above_max", init_scene(&b, &sc), FOV_ERR_LIMIT);
    sc = b.sc; sc.num_lights = FOVSDF_MAX_LIGHTS;
    expect_res("scene_num_lights_at_max_ok", init_scene(&b, &sc), FOV_OK);
    sc = b.sc; sc.lights[0].color[1] = f_nan();
    expect_res("scene_light_nan_color", init_scene(&b, &sc), FOV_ERR_NOT_FINITE);
    sc = b.sc; sc.lights[0].v[2] = f_inf();
    expect_res("scene_light_inf_vector", init_scene(&b, &sc), FOV_ERR_NOT_FINITE);
    sc = b.sc; sc.lipschitz = -1.0f;
    expect_res("scene_negative_lipschitz", init_scene(&b, &sc), FOV_ERR_INVALID_ARG);
}

static void test_strings_and_defaults(void)
{
    static const int codes[] = { 0, -1, -2, -3, -4, -5, -6, -7, -8, 1, 12345, -99999 };
    unsigned i;
    fovsdf_config z, c, g;
    int ok = 1;
    for (i = 0; i < sizeof codes / sizeof codes[0]; ++i) {
        const char *s = fovsdf_result_string((fov_result)codes[i]);
        check(s != NULL && s[0] != '\0', N("result_string_%d", codes[i]), "returned %s",
              s ? "an empty string" : "NULL");
    }
    {
        const char *a = fovsdf_result_string(FOV_ERR_NULL), *u = fovsdf_result_string((fov_result)-99999);
        check(strcmp(a, u) != 0, "result_string_unknown_differs", "known and unknown codes share \"%s\"", a);
    }
    for (i = 0; i < 6; ++i) {
        const char *s = fovsdf_method_name(i);
        int want_known = i < 4;
        check(s != NULL && (want_known ? strcmp(s, g_mname[i]) == 0 : s[0] != '\0'), N("method_name_%u", i),
              "got \"%s\"", s ? s : "(null)");
    }
    for (i = 0; i < 8; ++i) {
        const char *s = fovsdf_builtin_name(i);
        check(s != NULL && s[0] != '\0', N("builtin_name_%u", i), "got %s", s ? "\"\"" : "NULL");
    }
    /* a zero-filled config resolves to the documented defaults */
    memset(&z, 0, sizeof z);
    expect_res("config_resolve_zero_ok", fovsdf_config_resolve(&z, &c), FOV_OK);
    ok = c.method == 0 && c.spp == 1 && c.eps_mode == 0 && c.eps == 1e-4f && c.eps_px == 0.25f && c.max_steps == 256 &&
         c.t_max == 0.0f && c.omega == 1.6f && c.ar_beta == 0.3f && c.bv_relax == 0.9f && c.shading == 0 &&
         c.shadow_steps == 64 && c.shadow_eps == 1e-3f && c.shadow_t0 == 1e-2f;
    check(ok, "config_defaults_documented",
          "spp %u eps %g eps_px %g max_steps %u omega %g ar_beta %g bv_relax %g shadow_steps %u shadow_eps %g t0 %g", c.spp,
          (double)c.eps, (double)c.eps_px, c.max_steps, (double)c.omega, (double)c.ar_beta, (double)c.bv_relax,
          c.shadow_steps, (double)c.shadow_eps, (double)c.shadow_t0);
    c = fovsdf_config_default();
    check(c.eps == 1e-4f && c.max_steps == 256 && c.spp == 1, "config_default_resolved", "eps %g max_steps %u spp %u",
          (double)c.eps, c.max_steps, c.spp);
    g = fovsdf_config_ground_truth();
    check(g.method == FOVSDF_METHOD_CLASSIC && g.eps == 1e-5f && g.eps_px == 0.01f && g.max_steps == 4096,
          "config_ground_truth_documented", "method %u eps %g eps_px %g max_steps %u", g.method, (double)g.eps,
          (double)g.eps_px, g.max_steps);
}

static void test_logger_codes(void)
{
    base_t b;
    fovsdf_config cfg;
    fovsdf_ctx ctx;
    fovsdf_camera cam;
    fovsdf_scene sc;
    logrec lr;
    fov_gaze g;
    base_init(&b);
    b.cfg.logger.func = test_logger;
    b.cfg.logger.user = &lr;

    memset(&lr, 0, sizeof lr);
    (void)init_cfg(&b, &b.cfg);
    check(lr.calls == 0, "logger_silent_on_success", "%d calls", lr.calls);

    memset(&lr, 0, sizeof lr);
    cfg = b.cfg; cfg.spp = 3;
    (void)init_cfg(&b, &cfg);
    check(lr.calls >= 1 && lr.code == FOV_ERR_INVALID_ARG && lr.tag_ok && lr.level == FOV_LOG_ERROR,
          "logger_spp_3_invalid_arg", "calls %d, code %d, level %u, tag ok %d", lr.calls, (int)lr.code, lr.level, lr.tag_ok);

    memset(&lr, 0, sizeof lr);
    cfg = b.cfg; cfg.max_steps = FOVSDF_MAX_STEPS + 1u;
    (void)fovsdf_config_resolve(&cfg, &cfg);
    check(lr.calls >= 1 && lr.code == FOV_ERR_LIMIT, "logger_config_resolve_limit", "calls %d, code %d", lr.calls,
          (int)lr.code);

    memset(&lr, 0, sizeof lr);
    g = b.gaze; g.y = f_nan();
    (void)fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, g, NULL, 0);
    check(lr.calls >= 1 && lr.code == FOV_ERR_NOT_FINITE, "logger_nan_gaze_not_finite", "calls %d, code %d", lr.calls,
          (int)lr.code);

    memset(&lr, 0, sizeof lr);
    cam = b.cam; cam.target[2] = cam.pos[2];
    (void)init_cam(&b, &cam);
    check(lr.calls >= 1 && lr.code == FOV_ERR_DEGENERATE, "logger_degenerate_camera", "calls %d, code %d", lr.calls,
          (int)lr.code);

    memset(&lr, 0, sizeof lr);
    sc = b.sc; sc.num_lights = 99;
    (void)init_scene(&b, &sc);
    check(lr.calls >= 1 && lr.code == FOV_ERR_LIMIT, "logger_too_many_lights_limit", "calls %d, code %d", lr.calls,
          (int)lr.code);

    memset(&lr, 0, sizeof lr);
    (void)fovsdf_init(NULL, &b.cfg, &b.sc, &b.cam, b.gaze, NULL, 0);
    check(lr.calls >= 1 && lr.code == FOV_ERR_NULL, "logger_null_ctx", "calls %d, code %d", lr.calls, (int)lr.code);

    memset(&lr, 0, sizeof lr);
    cam = b.cam; cam.width = 0;
    (void)init_cam(&b, &cam);
    check(lr.calls == 1 && lr.code == FOV_ERR_INVALID_ARG, "logger_width_0_once", "calls %d, code %d", lr.calls,
          (int)lr.code);
}

/* ---- misbehaving user distance functions ------------------------------------------------- */
typedef struct imgbuf {
    uint32_t w, h;
    float *rgb;
    uint8_t *rgb8;
    float *depth;
    uint8_t *hit;
    uint32_t *evals, *steps;
    int32_t *mat;
} imgbuf;

static void ib_alloc(imgbuf *b, uint32_t w, uint32_t h)
{
    size_t n = (size_t)w * h;
    b->w = w;
    b->h = h;
    b->rgb = (float *)calloc(3 * n, sizeof(float));
    b->rgb8 = (uint8_t *)calloc(3 * n, 1);
    b->depth = (float *)calloc(n, sizeof(float));
    b->hit = (uint8_t *)calloc(n, 1);
    b->evals = (uint32_t *)calloc(n, sizeof(uint32_t));
    b->steps = (uint32_t *)calloc(n, sizeof(uint32_t));
    b->mat = (int32_t *)calloc(n, sizeof(int32_t));
    if (!b->rgb || !b->rgb8 || !b->depth || !b->hit || !b->evals || !b->steps || !b->mat) {
        printf("FAIL out_of_memory: %lu pixels\n", (unsigned long)n);
        exit(1);
    }
}

static void ib_free(imgbuf *b)
{
    free(b->rgb); free(b->rgb8); free(b->depth); free(b->hit); free(b->evals); free(b->steps); free(b->mat);
    memset(b, 0, sizeof *b);
}

static void ib_out(const imgbuf *b, fovsdf_output *o)
{
    fovsdf_output_init(o);
    o->rgb = b->rgb; o->rgb8 = b->rgb8; o->depth = b->depth; o->hit = b->hit;
    o->evals = b->evals; o->steps = b->steps; o->material = b->mat;
}

/* Number of non-finite values in the rgb and depth buffers. */
static size_t ib_nonfinite(const imgbuf *b)
{
    size_t i, n = (size_t)b->w * b->h, bad = 0;
    for (i = 0; i < 3 * n; ++i) bad += !fin(b->rgb[i]);
    for (i = 0; i < n; ++i) bad += !fin(b->depth[i]);
    return bad;
}

static size_t ib_hits(const imgbuf *b)
{
    size_t i, n = (size_t)b->w * b->h, c = 0;
    for (i = 0; i < n; ++i) c += b->hit[i] != 0;
    return c;
}

static void test_bad_sdfs(void)
{
    static const int kinds[3] = { K_NAN, K_NAN_HALF, K_INF };
    static const char *const kn[3] = { "nan_everywhere", "nan_for_x_positive", "inf_everywhere" };
    const uint32_t W = 64, H = 36;
    imgbuf ib;
    int k;
    uint32_t m;
    ib_alloc(&ib, W, H);
    for (k = 0; k < 3; ++k) {
        tsdf u;
        fovsdf_scene sc;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fovsdf_output o;
        fovsdf_stats st;
        fov_result r;
        size_t bad, hits, i, nmax = 0;
        tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
        u.kind = kinds[k];
        scene_for(&sc, &u);
        cam_at(&cam, W, H, 0.0f, 0.0f, -4.0f, 0.0f, 0.0f, 0.0f);
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
        expect_res(N("bad_sdf_%s_init", kn[k]), r, FOV_OK);
        if (r != FOV_OK) continue;
        ib_out(&ib, &o);
        memset(&st, 0, sizeof st);
        r = fovsdf_render_rows(&ctx, 0, H, &o, &st);
        expect_res(N("bad_sdf_%s_render_completes", kn[k]), r, FOV_OK);
        bad = ib_nonfinite(&ib);
        hits = ib_hits(&ib);
        for (i = 0; i < (size_t)W * H; ++i) nmax += ib.depth[i] == ctx.t_max;
        check(bad == 0, N("bad_sdf_%s_output_finite", kn[k]), "%lu non-finite rgb/depth values", (unsigned long)bad);
        if (k == 1)
            check(hits > 0 && hits < (size_t)W * H, N("bad_sdf_%s_finite_half_still_hits", kn[k]),
                  "%lu hit pixels of %u", (unsigned long)hits, W * H);
        else
            check(hits == 0 && nmax == (size_t)W * H, N("bad_sdf_%s_all_miss", kn[k]),
                  "%lu hit pixels, %lu pixels at depth t_max", (unsigned long)hits, (unsigned long)nmax);
    }

    /* always 1e-30: with a threshold that stays below 1e-30 (cone epsilon from a camera at the
       origin) the march can only end by its step budget */
    for (m = 0; m < 4; ++m) {
        tsdf u;
        fovsdf_scene sc;
        fovsdf_march_params mp;
        fovsdf_hit hit;
        float ro[3] = { 0.0f, 0.0f, 0.0f }, rd[3] = { 0.0f, 0.6f, 0.8f };
        fov_result r;
        memset(&u, 0, sizeof u);
        u.kind = K_TINY;
        scene_for(&sc, &u);
        mp = mp_make(m, 0.0f, 100.0f, FOVSDF_MAX_STEPS);
        mp.eps_cone = 1e-30f;
        memset(&hit, 0, sizeof hit);
        r = fovsdf_march(&sc, &mp, ro, rd, 0.0f, &hit, NULL);
        check(r == FOV_OK && hit.kind == FOVSDF_EXHAUSTED && hit.steps == FOVSDF_MAX_STEPS && hit.evals == FOVSDF_MAX_STEPS &&
                  u.calls == FOVSDF_MAX_STEPS && fin(hit.t) && hit.t < mp.t_max,
              N("bad_sdf_tiny_march_exhausts_%s", g_mname[m]), "result %s, kind %s, steps %u, evals %u, calls %lu, t %g",
              rname(r), kind_name(hit.kind), hit.steps, hit.evals, u.calls, (double)hit.t);
    }
    for (m = 0; m < 4; ++m) {
        tsdf u;
        fovsdf_scene sc;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fovsdf_output o;
        fovsdf_stats st;
        fov_result r;
        size_t i, n64 = 0;
        memset(&u, 0, sizeof u);
        u.kind = K_TINY;
        scene_for(&sc, &u);
        cam_at(&cam, W, H, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f);
        cfg.method = m;
        cfg.eps_mode = FOVSDF_EPS_CONE;
        cfg.max_steps = 64;
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
        if (r == FOV_OK) {
            ib_out(&ib, &o);
            memset(&st, 0, sizeof st);
            r = fovsdf_render_rows(&ctx, 0, H, &o, &st);
        }
        for (i = 0; i < (size_t)W * H; ++i) n64 += ib.steps[i] == 64;
        check(r == FOV_OK && n64 == (size_t)W * H && st.exhausted == st.rays && st.rays == (uint64_t)W * H &&
                  ib_nonfinite(&ib) == 0,
              N("bad_sdf_tiny_render_exhausts_%s", g_mname[m]),
              "result %s, %lu of %u pixels with 64 steps, exhausted %lu of %lu rays, %lu non-finite", rname(r),
              (unsigned long)n64, W * H, (unsigned long)st.exhausted, (unsigned long)st.rays,
              (unsigned long)ib_nonfinite(&ib));
    }
    {
        /* with the default absolute epsilon a distance of 1e-30 is a hit at once */
        tsdf u;
        fovsdf_scene sc;
        fovsdf_march_params mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-4f, 100.0f, 256);
        fovsdf_hit hit;
        float ro[3] = { 1.0f, 2.0f, 3.0f }, rd[3] = { 0.0f, 0.0f, 1.0f };
        memset(&u, 0, sizeof u);
        u.kind = K_TINY;
        scene_for(&sc, &u);
        (void)fovsdf_march(&sc, &mp, ro, rd, 0.5f, &hit, NULL);
        check(hit.kind == FOVSDF_HIT && hit.t == 0.5f && hit.steps == 1, "bad_sdf_tiny_below_eps_hits_at_start",
              "kind %s t %g steps %u", kind_name(hit.kind), (double)hit.t, hit.steps);
    }

    /* negative everywhere: a hit at t_start */
    for (m = 0; m < 4; ++m) {
        tsdf u;
        fovsdf_scene sc;
        fovsdf_march_params mp = mp_make(m, 1e-4f, 50.0f, 256);
        fovsdf_hit h0, h1;
        float ro[3] = { 0.5f, -1.0f, 2.0f }, rd[3] = { 0.0f, 0.8f, -0.6f };
        fov_result r0, r1;
        memset(&u, 0, sizeof u);
        u.kind = K_NEG;
        scene_for(&sc, &u);
        r0 = fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h0, NULL);
        r1 = fovsdf_march(&sc, &mp, ro, rd, 0.25f, &h1, NULL);
        check(r0 == FOV_OK && r1 == FOV_OK && h0.kind == FOVSDF_HIT && h0.t == 0.0f && h1.kind == FOVSDF_HIT &&
                  h1.t == 0.25f,
              N("bad_sdf_negative_hits_at_t_start_%s", g_mname[m]), "t_start 0: %s t %g; t_start 0.25: %s t %g",
              kind_name(h0.kind), (double)h0.t, kind_name(h1.kind), (double)h1.t);
    }
    {
        tsdf u;
        fovsdf_scene sc;
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        fovsdf_output o;
        fov_result r;
        size_t i, n0 = 0;
        memset(&u, 0, sizeof u);
        u.kind = K_NEG;
        scene_for(&sc, &u);
        cam_at(&cam, W, H, 0.0f, 1.0f, -4.0f, 0.0f, 0.0f, 0.0f);
        r = fovsdf_init(&ctx, NULL, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
        if (r == FOV_OK) {
            ib_out(&ib, &o);
            r = fovsdf_render_rows(&ctx, 0, H, &o, NULL);
        }
        for (i = 0; i < (size_t)W * H; ++i) n0 += ib.depth[i] == 0.0f && ib.hit[i] == 1;
        check(r == FOV_OK && n0 == (size_t)W * H && ib_nonfinite(&ib) == 0, "bad_sdf_negative_render_depth_0",
              "result %s, %lu of %u pixels hit at depth 0, %lu non-finite", rname(r), (unsigned long)n0, W * H,
              (unsigned long)ib_nonfinite(&ib));
    }
    ib_free(&ib);
}

/* ==== 2. tracers ========================================================================== */

/* First intersection of ro + t rd with the sphere (c, r), in double; -1 when none. */
static double ray_sphere(const float ro[3], const float rd[3], const float c[3], float r)
{
    double o[3], d[3], a = 0.0, b = 0.0, cc = 0.0, disc;
    int i;
    for (i = 0; i < 3; ++i) {
        o[i] = (double)ro[i] - (double)c[i];
        d[i] = (double)rd[i];
        a += d[i] * d[i];
        b += 2.0 * o[i] * d[i];
        cc += o[i] * o[i];
    }
    cc -= (double)r * (double)r;
    disc = b * b - 4.0 * a * cc;
    if (disc < 0.0) return -1.0;
    return (-b - sqrt(disc)) / (2.0 * a);
}

/* Unit float direction from a to b (normalised in double). */
static void dir_to(const float a[3], const double b[3], float rd[3])
{
    double d[3], l;
    int i;
    for (i = 0; i < 3; ++i) d[i] = b[i] - (double)a[i];
    l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (i = 0; i < 3; ++i) rd[i] = (float)(d[i] / l);
}

/* A context whose tracer matches fovsdf_march with mp_make(m, eps, t_max, steps). */
static fov_result trace_ctx(fovsdf_ctx *ctx, const fovsdf_scene *sc, uint32_t m, float eps, float t_max,
                            uint32_t steps)
{
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    cam_at(&cam, 64, 36, 0.0f, 0.0f, -5.0f, 0.0f, 0.0f, 0.0f);
    cfg.method = m;
    cfg.eps_mode = FOVSDF_EPS_ABSOLUTE;
    cfg.eps = eps;
    cfg.t_max = t_max;
    cfg.max_steps = steps;
    return fovsdf_init(ctx, &cfg, sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
}

static double dmax(double a, double b) { return a > b ? a : b; }

static void test_sphere_rays(void)
{
    static const double tg[6][3] = { { 0.0, 0.0, 0.0 }, { 0.3, 0.2, 0.0 }, { -0.5, 0.4, 0.1 },
                                     { 0.7, -0.3, 0.0 }, { 0.1, 0.85, -0.2 }, { -0.2, -0.6, 0.5 } };
    const float ro[3] = { 0.3f, -0.2f, -4.5f };
    const float eps = 1e-4f;
    tsdf u;
    fovsdf_scene sc;
    uint32_t m;
    int i;
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    for (m = 0; m < 4; ++m) {
        fovsdf_march_params mp = mp_make(m, eps, 20.0f, 512);
        fovsdf_ctx ctx;
        fov_result rc = trace_ctx(&ctx, &sc, m, eps, 20.0f, 512);
        for (i = 0; i < 6; ++i) {
            float rd[3];
            fovsdf_hit h, g;
            fov_result r1, r2 = FOV_ERR_NULL;
            double te, tol;
            dir_to(ro, tg[i], rd);
            te = ray_sphere(ro, rd, u.sc[0], 1.0f);
            tol = dmax((double)eps, 1e-4 * te);
            memset(&h, 0, sizeof h);
            memset(&g, 0, sizeof g);
            r1 = fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
            check(r1 == FOV_OK && h.kind == FOVSDF_HIT && fabs((double)h.t - te) <= tol,
                  N("march_sphere_%s_ray%d", g_mname[m], i), "%s kind %s t %.7g, analytic %.7g (|dt| %.3g > tol %.3g?)",
                  rname(r1), kind_name(h.kind), (double)h.t, te, fabs((double)h.t - te), tol);
            if (rc == FOV_OK) r2 = fovsdf_trace(&ctx, ro, rd, 0.0f, &g, NULL);
            check(r2 == FOV_OK && g.kind == FOVSDF_HIT && fabs((double)g.t - te) <= tol,
                  N("trace_sphere_%s_ray%d", g_mname[m], i), "%s kind %s t %.7g, analytic %.7g (|dt| %.3g, tol %.3g)",
                  rname(r2), kind_name(g.kind), (double)g.t, te, fabs((double)g.t - te), tol);
        }
    }
}

static void test_plane_rays(void)
{
    static const double ang[6] = { 60.0, 30.0, 10.0, 3.0, 1.0, 0.5 };
    const float ro[3] = { 0.0f, 1.0f, 0.0f };
    const float eps = 1e-4f, tmax = 300.0f;
    tsdf u;
    fovsdf_scene sc;
    uint32_t m;
    int i;
    tsdf_plane(&u, 0.0f, 1.0f, 0.0f, 0.0f);
    scene_for(&sc, &u);
    for (m = 0; m < 4; ++m) {
        fovsdf_march_params mp = mp_make(m, eps, tmax, 8192);
        fovsdf_ctx ctx;
        fov_result rc = trace_ctx(&ctx, &sc, m, eps, tmax, 8192);
        for (i = 0; i < 6; ++i) {
            double a = ang[i] * 3.14159265358979323846 / 180.0, az = 0.3 + 0.7 * i;
            float rd[3];
            fovsdf_hit h, g;
            fov_result r1, r2 = FOV_ERR_NULL;
            double te, tol;
            rd[0] = (float)(cos(a) * cos(az));
            rd[1] = (float)(-sin(a));
            rd[2] = (float)(cos(a) * sin(az));
            te = (double)ro[1] / -(double)rd[1];
            /* exact up to 1e-4 t: the hit refinement's secant step, certified by an empty ball
               where the spheres cannot verify it (grazing angles; fovsdf.h, fovsdf__refine) */
            tol = dmax((double)eps, 1e-4 * te);
            memset(&h, 0, sizeof h);
            memset(&g, 0, sizeof g);
            r1 = fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
            check(r1 == FOV_OK && h.kind == FOVSDF_HIT && fabs((double)h.t - te) <= tol,
                  N("march_plane_%s_%gdeg", g_mname[m], ang[i]), "%s kind %s t %.7g, analytic %.7g (|dt| %.3g, tol %.3g), %u steps",
                  rname(r1), kind_name(h.kind), (double)h.t, te, fabs((double)h.t - te), tol, h.steps);
            if (rc == FOV_OK) r2 = fovsdf_trace(&ctx, ro, rd, 0.0f, &g, NULL);
            check(r2 == FOV_OK && g.kind == FOVSDF_HIT && fabs((double)g.t - te) <= tol,
                  N("trace_plane_%s_%gdeg", g_mname[m], ang[i]), "%s kind %s t %.7g, analytic %.7g (|dt| %.3g, tol %.3g), %u steps",
                  rname(r2), kind_name(g.kind), (double)g.t, te, fabs((double)g.t - te), tol, g.steps);
        }
    }
}

static void test_miss_inside_tmax(void)
{
    tsdf u;
    fovsdf_scene sc;
    uint32_t m;
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    for (m = 0; m < 4; ++m) {
        const float ro[3] = { 0.0f, 0.0f, -5.0f };
        float away[3] = { 0.0f, 0.0f, -1.0f }, past[3];
        const double pt[3] = { 1.5, 0.0, 0.0 };
        fovsdf_march_params mp = mp_make(m, 1e-4f, 20.0f, 512);
        fovsdf_ctx ctx;
        fovsdf_hit h1, h2, g1;
        fov_result rc = trace_ctx(&ctx, &sc, m, 1e-4f, 20.0f, 512);
        dir_to(ro, pt, past);
        (void)fovsdf_march(&sc, &mp, ro, away, 0.0f, &h1, NULL);
        (void)fovsdf_march(&sc, &mp, ro, past, 0.0f, &h2, NULL);
        check(h1.kind == FOVSDF_MISS && h1.t == 20.0f && h2.kind == FOVSDF_MISS && h2.t == 20.0f,
              N("march_miss_t_is_t_max_%s", g_mname[m]), "away: %s t %g; passing by: %s t %g (t_max 20)",
              kind_name(h1.kind), (double)h1.t, kind_name(h2.kind), (double)h2.t);
        memset(&g1, 0, sizeof g1);
        if (rc == FOV_OK) (void)fovsdf_trace(&ctx, ro, past, 0.0f, &g1, NULL);
        check(rc == FOV_OK && g1.kind == FOVSDF_MISS && g1.t == 20.0f, N("trace_miss_t_is_t_max_%s", g_mname[m]),
              "%s t %g (t_max 20)", kind_name(g1.kind), (double)g1.t);
    }
    for (m = 0; m < 4; ++m) {
        const float o1[3] = { 0.0f, 0.0f, 0.0f }, o2[3] = { 0.0f, 0.0f, -0.5f }, rd[3] = { 0.0f, 0.0f, 1.0f };
        fovsdf_march_params mp = mp_make(m, 1e-4f, 20.0f, 512);
        fovsdf_ctx ctx;
        fovsdf_hit h1, h2, g1;
        fov_result rc = trace_ctx(&ctx, &sc, m, 1e-4f, 20.0f, 512);
        (void)fovsdf_march(&sc, &mp, o1, rd, 0.0f, &h1, NULL);
        (void)fovsdf_march(&sc, &mp, o2, rd, 0.2f, &h2, NULL);
        check(h1.kind == FOVSDF_HIT && h1.t == 0.0f && h2.kind == FOVSDF_HIT && h2.t == 0.2f,
              N("march_inside_hits_at_t_start_%s", g_mname[m]), "t_start 0: %s t %g; t_start 0.2: %s t %g",
              kind_name(h1.kind), (double)h1.t, kind_name(h2.kind), (double)h2.t);
        memset(&g1, 0, sizeof g1);
        if (rc == FOV_OK) (void)fovsdf_trace(&ctx, o2, rd, 0.2f, &g1, NULL);
        check(rc == FOV_OK && g1.kind == FOVSDF_HIT && g1.t == 0.2f, N("trace_inside_hits_at_t_start_%s", g_mname[m]),
              "%s t %g", kind_name(g1.kind), (double)g1.t);
    }
    /* the sphere surface at t = 4 (ray offset 0.6 from the centre): found with t_max 4.05 and
       4.5, missed with t_max 3.95 */
    for (m = 0; m < 4; ++m) {
        static const float tms[3] = { 4.05f, 4.5f, 3.95f };
        const float ro[3] = { 0.0f, 0.6f, -4.8f }, rd[3] = { 0.0f, 0.0f, 1.0f };
        double te = ray_sphere(ro, rd, u.sc[0], 1.0f);
        int j;
        for (j = 0; j < 3; ++j) {
            fovsdf_march_params mp = mp_make(m, 1e-4f, tms[j], 512);
            fovsdf_ctx ctx;
            fovsdf_hit h, g;
            fov_result rc = trace_ctx(&ctx, &sc, m, 1e-4f, tms[j], 512);
            double tol = dmax(1e-4, 1e-4 * te);
            memset(&g, 0, sizeof g);
            (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
            if (rc == FOV_OK) (void)fovsdf_trace(&ctx, ro, rd, 0.0f, &g, NULL);
            if (j < 2) {
                check(h.kind == FOVSDF_HIT && fabs((double)h.t - te) <= tol && g.kind == FOVSDF_HIT &&
                          fabs((double)g.t - te) <= tol,
                      N("surface_near_t_max_%g_found_%s", (double)tms[j], g_mname[m]),
                      "march %s t %.7g, trace %s t %.7g, analytic %.7g", kind_name(h.kind), (double)h.t,
                      kind_name(g.kind), (double)g.t, te);
            } else {
                check(h.kind == FOVSDF_MISS && h.t == tms[j] && g.kind == FOVSDF_MISS && g.t == tms[j],
                      N("surface_beyond_t_max_%g_missed_%s", (double)tms[j], g_mname[m]),
                      "march %s t %.7g, trace %s t %.7g, surface at %.7g", kind_name(h.kind), (double)h.t,
                      kind_name(g.kind), (double)g.t, te);
            }
        }
    }
}

static void test_eval_counts(void)
{
    static const double tg[5][3] = { { 0.0, 0.0, 0.0 }, { 0.6, 0.5, 0.0 }, { 3.0, 0.0, 0.0 },
                                     { 0.0, 0.98, 0.0 }, { -0.9, 0.0, 0.4 } };
    tsdf u;
    fovsdf_scene sc;
    uint32_t m;
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    for (m = 0; m < 4; ++m) {
        const float ro[3] = { 0.1f, 0.2f, -4.0f };
        fovsdf_march_params mp = mp_make(m, 1e-4f, 20.0f, 512);
        fovsdf_ctx ctx;
        fovsdf_stats st1, st2;
        unsigned long tot1 = 0, tot2 = 0;
        int i, bad1 = -1, bad2 = -1;
        uint32_t e1 = 0, e2 = 0;
        unsigned long c1 = 0, c2 = 0;
        fov_result rc = trace_ctx(&ctx, &sc, m, 1e-4f, 20.0f, 512);
        memset(&st1, 0, sizeof st1);
        memset(&st2, 0, sizeof st2);
        for (i = 0; i < 5; ++i) {
            float rd[3];
            fovsdf_hit h;
            dir_to(ro, tg[i], rd);
            u.calls = 0;
            (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, &st1);
            tot1 += u.calls;
            if (h.evals != u.calls && bad1 < 0) { bad1 = i; e1 = h.evals; c1 = u.calls; }
            if (rc == FOV_OK) {
                u.calls = 0;
                (void)fovsdf_trace(&ctx, ro, rd, 0.0f, &h, &st2);
                tot2 += u.calls;
                if (h.evals != u.calls && bad2 < 0) { bad2 = i; e2 = h.evals; c2 = u.calls; }
            }
        }
        check(bad1 < 0, N("march_hit_evals_equal_callbacks_%s", g_mname[m]), "ray %d: hit.evals %u, callbacks %lu", bad1,
              e1, c1);
        check(st1.evals == tot1, N("march_stats_evals_accumulate_%s", g_mname[m]), "stats.evals %lu, callbacks %lu",
              (unsigned long)st1.evals, tot1);
        check(rc == FOV_OK && bad2 < 0, N("trace_hit_evals_equal_callbacks_%s", g_mname[m]),
              "ray %d: hit.evals %u, callbacks %lu", bad2, e2, c2);
        check(rc == FOV_OK && st2.evals == tot2 && tot2 > 0, N("trace_stats_evals_accumulate_%s", g_mname[m]),
              "stats.evals %lu, callbacks %lu", (unsigned long)st2.evals, tot2);
    }
}

/* Relaxed methods against classic on a ray nearly parallel to the plane y = 1 (from the
   origin), and on one exactly parallel to it. */
static void test_relaxation_gain(void)
{
    static const double ang[2] = { 2.0, 0.0 };
    tsdf u;
    fovsdf_scene sc;
    int i;
    tsdf_plane(&u, 0.0f, -1.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    for (i = 0; i < 2; ++i) {
        const float ro[3] = { 0.0f, 0.0f, 0.0f };
        double a = ang[i] * 3.14159265358979323846 / 180.0, te;
        float rd[3];
        uint32_t ev[4], m;
        fovsdf_hit h[4];
        rd[0] = (float)cos(a);
        rd[1] = (float)sin(a);
        rd[2] = 0.0f;
        te = i == 0 ? 1.0 / (double)rd[1] : 100.0;
        for (m = 0; m < 4; ++m) {
            fovsdf_march_params mp = mp_make(m, 1e-4f, 100.0f, 4096);
            u.calls = 0;
            (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h[m], NULL);
            ev[m] = (uint32_t)u.calls;
            check(h[m].kind == (i == 0 ? (uint32_t)FOVSDF_HIT : (uint32_t)FOVSDF_MISS) &&
                      fabs((double)h[m].t - te) <= dmax(1e-4, 1e-4 * te),
                  N("near_parallel_%gdeg_%s_result", ang[i], g_mname[m]), "%s t %.7g, expected %s t %.7g",
                  kind_name(h[m].kind), (double)h[m].t, i == 0 ? "HIT" : "MISS", te);
        }
        for (m = 1; m < 4; ++m)
            check(ev[m] <= ev[0], N("near_parallel_%gdeg_%s_evals_le_classic", ang[i], g_mname[m]),
                  "%s %u evaluations, classic %u", g_mname[m], ev[m], ev[0]);
    }
}

/* ==== 3. shading and eccentricity ======================================================== */

static void test_normals(void)
{
    static const double dirs[8][3] = { { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 1, 1, 1 },
                                       { -0.3, 0.8, -0.5 }, { 0.9, -0.1, 0.4 }, { -1, -2, 0.5 }, { 0.2, 0.1, -1 } };
    tsdf u;
    fovsdf_scene sc;
    fovsdf_ctx ctx;
    fov_result rc;
    int i;
    tsdf_sphere(&u, 0.2f, -0.1f, 0.3f, 1.3f);
    scene_for(&sc, &u);
    rc = trace_ctx(&ctx, &sc, FOVSDF_METHOD_CLASSIC, 1e-4f, 20.0f, 256);
    expect_res("normal_ctx_init", rc, FOV_OK);
    if (rc != FOV_OK) return;
    for (i = 0; i < 8; ++i) {
        double d[3], l = sqrt(dirs[i][0] * dirs[i][0] + dirs[i][1] * dirs[i][1] + dirs[i][2] * dirs[i][2]), err = 0.0;
        float p[3], n[3] = { 0.0f, 0.0f, 0.0f };
        fovsdf_stats st;
        int j;
        for (j = 0; j < 3; ++j) {
            d[j] = dirs[i][j] / l;
            p[j] = (float)((double)u.sc[0][j] + 1.3 * d[j]);
        }
        memset(&st, 0, sizeof st);
        u.calls = 0;
        fovsdf_normal(&ctx, p, 1e-3f, n, &st);
        for (j = 0; j < 3; ++j) err = dmax(err, fabs((double)n[j] - d[j]));
        check(err <= 1e-3, N("normal_sphere_radial_dir%d", i), "n (%.6f %.6f %.6f), radial (%.6f %.6f %.6f), max err %.3g",
              (double)n[0], (double)n[1], (double)n[2], d[0], d[1], d[2], err);
        check(st.evals == 4 && st.evals_normal == 4 && u.calls == 4, N("normal_sphere_4_evals_dir%d", i),
              "stats.evals %lu, evals_normal %lu, callbacks %lu", (unsigned long)st.evals,
              (unsigned long)st.evals_normal, u.calls);
    }
}

/* Brute-force minimum over t in [t0, t1] of k * h(p + t l) / t (dense sampling, double). */
static double penumbra_min(const tsdf *u, const float p[3], const float l[3], double t0, double t1, double k)
{
    double best = 1e30;
    int i, n = 200000;
    for (i = 0; i <= n; ++i) {
        double t = t0 + (t1 - t0) * (double)i / (double)n, h = 1e30;
        int j;
        for (j = 0; j < u->ns; ++j) {
            double dx = (double)p[0] + t * (double)l[0] - (double)u->sc[j][0];
            double dy = (double)p[1] + t * (double)l[1] - (double)u->sc[j][1];
            double dz = (double)p[2] + t * (double)l[2] - (double)u->sc[j][2];
            double hj = sqrt(dx * dx + dy * dy + dz * dz) - (double)u->sr[j];
            if (hj < h) h = hj;
        }
        if (k * h / t < best) best = k * h / t;
    }
    return best;
}

static void test_soft_shadows(void)
{
    tsdf u;
    fovsdf_scene sc;
    fovsdf_ctx ctx;
    fovsdf_stats st;
    fov_result rc;
    const float p[3] = { 0.0f, 0.0f, 0.0f }, l[3] = { 0.0f, 1.0f, 0.0f };
    float s;
    double lo;
    tsdf_sphere(&u, 5.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    rc = trace_ctx(&ctx, &sc, FOVSDF_METHOD_CLASSIC, 1e-4f, 50.0f, 256);
    expect_res("shadow_ctx_init", rc, FOV_OK);
    if (rc != FOV_OK) return;

    /* unoccluded: the brute-force penumbra minimum is above 1 */
    lo = penumbra_min(&u, p, l, 0.01, 10.0, 16.0);
    memset(&st, 0, sizeof st);
    u.calls = 0;
    s = fovsdf_soft_shadow(&ctx, p, l, 0.01f, 10.0f, 16.0f, &st);
    check(lo >= 1.0 && s == 1.0f, "soft_shadow_unoccluded_is_1", "shadow %.6g (brute-force penumbra minimum %.4g)",
          (double)s, lo);
    check(st.shadow_rays == 1 && st.evals_shadow == st.evals && st.evals == u.calls && u.calls > 0,
          "soft_shadow_stats", "shadow_rays %lu, evals_shadow %lu, evals %lu, callbacks %lu",
          (unsigned long)st.shadow_rays, (unsigned long)st.evals_shadow, (unsigned long)st.evals, u.calls);

    /* a large sphere across the ray: full shadow */
    tsdf_sphere(&u, 0.0f, 5.0f, 0.0f, 2.0f);
    s = fovsdf_soft_shadow(&ctx, p, l, 0.01f, 10.0f, 16.0f, NULL);
    check(s == 0.0f, "soft_shadow_occluded_is_0", "shadow %.6g, want 0", (double)s);

    /* grazing: the ray passes 0.05 from a unit sphere at t = 5 */
    tsdf_sphere(&u, 1.05f, 5.0f, 0.0f, 1.0f);
    lo = penumbra_min(&u, p, l, 0.01, 10.0, 16.0);
    s = fovsdf_soft_shadow(&ctx, p, l, 0.01f, 10.0f, 16.0f, NULL);
    check(s > 0.0f && s < 1.0f && (double)s >= lo * (1.0 - 1e-3), "soft_shadow_grazing_partial",
          "shadow %.6g, want in (0, 1) and >= the brute-force penumbra minimum %.6g", (double)s, lo);

    /* head start past an occluder at t in [0.5, 1.5] */
    tsdf_sphere(&u, 0.0f, 1.0f, 0.0f, 0.5f);
    s = fovsdf_soft_shadow(&ctx, p, l, 0.01f, 10.0f, 16.0f, NULL);
    check(s == 0.0f, "soft_shadow_no_head_start_occluded", "shadow %.6g, want 0", (double)s);
    lo = penumbra_min(&u, p, l, 3.0, 10.0, 16.0);
    s = fovsdf_soft_shadow(&ctx, p, l, 3.0f, 10.0f, 16.0f, NULL);
    check(lo >= 1.0 && s == 1.0f, "soft_shadow_head_start_past_occluder_is_1",
          "shadow %.6g (brute-force penumbra minimum from t = 3: %.4g)", (double)s, lo);

    /* two occluders: the nearer one alone decides nothing when the head start skips it */
    tsdf_sphere(&u, 0.0f, 1.0f, 0.0f, 0.5f);
    tsdf_add_sphere(&u, 0.0f, 8.0f, 0.0f, 0.5f);
    s = fovsdf_soft_shadow(&ctx, p, l, 3.0f, 10.0f, 16.0f, NULL);
    check(s == 0.0f, "soft_shadow_head_start_second_occluder_is_0", "shadow %.6g, want 0", (double)s);
}

static void const_albedo(const float p[3], int32_t material, float rgb[3], void *user)
{
    (void)p;
    (void)material;
    (void)user;
    rgb[0] = 0.5f;
    rgb[1] = 0.25f;
    rgb[2] = 1.0f;
}

/* fovsdf_shade: albedo * (ambient + sum colour * max(n.l, 0) * falloff) without occluders. */
static void test_shade(void)
{
    tsdf u;
    fovsdf_scene sc;
    fovsdf_ctx ctx;
    fov_result rc;
    const float p[3] = { 0.0f, 0.0f, 0.0f }, n[3] = { 0.0f, 1.0f, 0.0f }, rd[3] = { 0.0f, -1.0f, 0.0f };
    float rgb[3];
    double lv[3] = { -0.5, 0.8, -0.3 }, ll, ndl, want[3], err = 0.0, d2, att, ndl2;
    const double alb[3] = { 0.5, 0.25, 1.0 };
    int i;
    tsdf_plane(&u, 0.0f, 1.0f, 0.0f, 0.0f);
    scene_for(&sc, &u);
    sc.albedo = const_albedo;
    sc.num_lights = 2;
    sc.lights[0].type = FOVSDF_LIGHT_DIRECTIONAL;
    sc.lights[0].v[0] = -0.5f; sc.lights[0].v[1] = 0.8f; sc.lights[0].v[2] = -0.3f;
    sc.lights[0].color[0] = 1.0f; sc.lights[0].color[1] = 0.5f; sc.lights[0].color[2] = 0.25f;
    memset(&sc.lights[1], 0, sizeof sc.lights[1]);
    sc.lights[1].type = FOVSDF_LIGHT_POINT;
    sc.lights[1].v[0] = 1.0f; sc.lights[1].v[1] = 2.0f; sc.lights[1].v[2] = 2.0f;
    sc.lights[1].color[0] = 0.3f; sc.lights[1].color[1] = 0.6f; sc.lights[1].color[2] = 0.9f;
    sc.lights[1].range = 2.0f;
    sc.ambient[0] = 0.1f; sc.ambient[1] = 0.2f; sc.ambient[2] = 0.3f;
    rc = trace_ctx(&ctx, &sc, FOVSDF_METHOD_CLASSIC, 1e-4f, 50.0f, 256);
    expect_res("shade_ctx_init", rc, FOV_OK);
    if (rc != FOV_OK) return;
    fovsdf_shade(&ctx, p, n, rd, 0, rgb, NULL);
    ll = sqrt(lv[0] * lv[0] + lv[1] * lv[1] + lv[2] * lv[2]);
    ndl = lv[1] / ll;
    d2 = 1.0 + 4.0 + 4.0;
    att = 1.0 / (1.0 + d2 / 4.0);
    ndl2 = 2.0 / sqrt(d2);
    want[0] = alb[0] * (0.1 + 1.0 * ndl + 0.3 * ndl2 * att);
    want[1] = alb[1] * (0.2 + 0.5 * ndl + 0.6 * ndl2 * att);
    want[2] = alb[2] * (0.3 + 0.25 * ndl + 0.9 * ndl2 * att);
    for (i = 0; i < 3; ++i) err = dmax(err, fabs((double)rgb[i] - want[i]));
    check(err <= 1e-4, "shade_lambert_ambient_point_falloff", "rgb (%.6f %.6f %.6f), want (%.6f %.6f %.6f)",
          (double)rgb[0], (double)rgb[1], (double)rgb[2], want[0], want[1], want[2]);
}

/* Angle in degrees between the eye rays through (x, y) and (gx, gy): eye on the axis at
   (cx, cy), f pixels from the image (double, independent of the library). */
static double ecc_ref(double cx, double cy, double f, double gx, double gy, double x, double y)
{
    double a[3], b[3], c[3], s, co;
    a[0] = x - cx; a[1] = y - cy; a[2] = f;
    b[0] = gx - cx; b[1] = gy - cy; b[2] = f;
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    s = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    co = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return atan2(s, co) * 180.0 / 3.14159265358979323846;
}

static void test_ecc_basic(void)
{
    static const float fovs[4] = { 30.0f, 60.0f, 90.0f, 110.0f };
    fov_ecc_model m;
    fov_display d;
    fov_result r;
    float e, e2;
    int i;
    memset(&d, 0, sizeof d);
    r = fovsdf_ecc_init(&m, &d, 60.0f, 65, 37, gaze_at(32.5f, 18.5f));
    e = fovsdf_ecc_deg(&m, 32.5f, 18.5f);
    check(r == FOV_OK && fabsf(e) <= 1e-6f, "ecc_centre_pixel_is_0", "%s, centre pixel (32, 18) of 65x37: %g deg",
          rname(r), (double)e);
    for (i = 0; i < 4; ++i) {
        memset(&d, 0, sizeof d);
        d.fov_y_deg = fovs[i];
        r = fovsdf_ecc_init(&m, &d, 60.0f, 64, 36, gaze_at(32.0f, 18.0f));
        e = fovsdf_ecc_deg(&m, 32.0f, 0.0f);
        e2 = fovsdf_ecc_deg(&m, 32.0f, 36.0f);
        check(r == FOV_OK && fabs((double)e - 0.5 * (double)fovs[i]) <= 1e-3 &&
                  fabs((double)e2 - 0.5 * (double)fovs[i]) <= 1e-3,
              N("ecc_display_fov_%g_top_edge_is_half", (double)fovs[i]), "%s, (w/2, 0): %.6f deg, (w/2, h): %.6f, want %g",
              rname(r), (double)e, (double)e2, 0.5 * (double)fovs[i]);
    }
    memset(&d, 0, sizeof d);
    r = fovsdf_ecc_init(&m, &d, 70.0f, 64, 36, gaze_at(32.0f, 18.0f));
    e = fovsdf_ecc_deg(&m, 32.0f, 0.0f);
    check(r == FOV_OK && fabs((double)e - 35.0) <= 1e-3, "ecc_zero_display_uses_camera_fov",
          "%s, (w/2, 0) with camera fov 70: %.6f deg", rname(r), (double)e);
    r = fovsdf_ecc_init(&m, NULL, 70.0f, 64, 36, gaze_at(32.0f, 18.0f));
    e = fovsdf_ecc_deg(&m, 32.0f, 0.0f);
    check(r == FOV_OK && fabs((double)e - 35.0) <= 1e-3, "ecc_null_display_uses_camera_fov",
          "%s, (w/2, 0) with camera fov 70: %.6f deg", rname(r), (double)e);
    {
        /* the context's model: zero display in the config, camera fov 50 (and 0 = 60) */
        tsdf u;
        fovsdf_scene sc;
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
        scene_for(&sc, &u);
        cam_at(&cam, 64, 36, 0.0f, 0.0f, -5.0f, 0.0f, 0.0f, 0.0f);
        cam.fov_y_deg = 50.0f;
        r = fovsdf_init(&ctx, NULL, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
        e = fovsdf_ecc_deg(&ctx.ecc, 32.0f, 0.0f);
        check(r == FOV_OK && fabs((double)e - 25.0) <= 1e-3, "ecc_ctx_uses_camera_fov",
              "%s, ctx.ecc (w/2, 0) with camera fov 50: %.6f deg", rname(r), (double)e);
        cam.fov_y_deg = 0.0f;
        r = fovsdf_init(&ctx, NULL, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
        e = fovsdf_ecc_deg(&ctx.ecc, 32.0f, 0.0f);
        check(r == FOV_OK && fabs((double)e - 30.0) <= 1e-3, "ecc_ctx_camera_fov_0_is_60",
              "%s, ctx.ecc (w/2, 0) with camera fov 0 (= 60): %.6f deg", rname(r), (double)e);
    }
    {
        /* general position: off-centre gaze, shifted axis, against the double formula */
        const double F = 75.0, W = 640.0, H = 360.0, dx = 13.0, dy = -7.5;
        double f = 0.5 * H / tan(0.5 * F * 3.14159265358979323846 / 180.0), worst = 0.0;
        double cx = 0.5 * W + dx, cy = 0.5 * H + dy, gx = 123.25, gy = 301.5;
        int x, y;
        memset(&d, 0, sizeof d);
        d.fov_y_deg = (float)F;
        d.axis_dx = (float)dx;
        d.axis_dy = (float)dy;
        r = fovsdf_ecc_init(&m, &d, 60.0f, 640, 360, gaze_at((float)gx, (float)gy));
        for (y = 0; y <= 360; y += 24)
            for (x = 0; x <= 640; x += 32) {
                double ref = ecc_ref(cx, cy, f, gx, gy, (double)x + 0.5, (double)y + 0.5);
                double got = (double)fovsdf_ecc_deg(&m, (float)x + 0.5f, (float)y + 0.5f);
                worst = dmax(worst, fabs(got - ref));
            }
        check(r == FOV_OK && worst <= 1e-3, "ecc_matches_reference_formula", "%s, worst |diff| %.3g deg over a grid",
              rname(r), worst);
        memset(&d, 0, sizeof d);
        d.pixel_pitch_mm = 0.25f;
        d.distance_mm = 600.0f;
        r = fovsdf_ecc_init(&m, &d, 60.0f, 640, 360, gaze_at((float)gx, (float)gy));
        worst = 0.0;
        for (y = 0; y <= 360; y += 24)
            for (x = 0; x <= 640; x += 32) {
                double ref = ecc_ref(320.0, 180.0, 2400.0, gx, gy, (double)x + 0.5, (double)y + 0.5);
                double got = (double)fovsdf_ecc_deg(&m, (float)x + 0.5f, (float)y + 0.5f);
                worst = dmax(worst, fabs(got - ref));
            }
        check(r == FOV_OK && worst <= 1e-3, "ecc_physical_display_matches_reference", "%s, worst |diff| %.3g deg",
              rname(r), worst);
    }
}

/* Table 4.1 of the thesis: speed-up of a three-zone foveated renderer (fovea at full rate,
   middle at 1/4, outer at 1/16) on a 27" 16:9 1920x1080 monitor at 500 mm, gaze at the
   centre. A zone angle theta is a full cone: pixel centres with eccentricity <= theta/2. */
static void test_table41(void)
{
    static const int fov_deg[6] = { 5, 10, 15, 20, 25, 30 }, mid_deg[6] = { 50, 55, 60, 65, 70, 75 };
    static const double table[6][6] = { { 4.98, 4.56, 4.19, 3.95, 3.91, 3.91 }, { 4.6, 4.23, 3.91, 3.7, 3.67, 3.67 },
                                        { 4.07, 3.78, 3.52, 3.35, 3.32, 3.32 }, { 3.49, 3.28, 3.08, 2.95, 2.93, 2.93 },
                                        { 2.95, 2.79, 2.65, 2.55, 2.53, 2.53 }, { 2.47, 2.36, 2.25, 2.18, 2.17, 2.17 } };
    const uint32_t W = 1920, H = 1080;
    fov_display d;
    fov_ecc_model m;
    fov_result r;
    double pitch = (27.0 * 25.4 * 16.0 / sqrt(16.0 * 16.0 + 9.0 * 9.0)) / 1920.0;
    unsigned long cf[6] = { 0 }, cm[6] = { 0 };
    float thf[6], thm[6];
    uint32_t x, y;
    int i, j;
    memset(&d, 0, sizeof d);
    d.pixel_pitch_mm = (float)pitch;
    d.distance_mm = 500.0f;
    r = fovsdf_ecc_init(&m, &d, 60.0f, W, H, gaze_at(960.0f, 540.0f));
    expect_res("table41_ecc_init", r, FOV_OK);
    if (r != FOV_OK) return;
    for (i = 0; i < 6; ++i) {
        thf[i] = 0.5f * (float)fov_deg[i];
        thm[i] = 0.5f * (float)mid_deg[i];
    }
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            float e = fovsdf_ecc_deg(&m, (float)x + 0.5f, (float)y + 0.5f);
            for (i = 0; i < 6; ++i) {
                cf[i] += e <= thf[i];
                cm[i] += e <= thm[i];
            }
        }
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) {
            double nf = (double)cf[i], nm = (double)cm[j] - nf, no = (double)W * H - (double)cm[j];
            double rays = nf + nm / 4.0 + no / 16.0, sp = (double)W * H / rays;
            check(fabs(sp - table[i][j]) <= 0.01, N("table41_fovea%d_middle%d", fov_deg[i], mid_deg[j]),
                  "speed-up %.4f, thesis %.2f (fovea %lu px, middle+fovea %lu px)", sp, table[i][j], cf[i], cm[j]);
        }
}

static void test_ecc_shape(void)
{
    fov_display d;
    fov_ecc_model m;
    fov_result r;
    double worst = 0.0;
    int i, k;
    static const float offs[6][2] = { { 10.5f, 3.25f }, { 100.0f, 50.0f }, { 250.0f, 170.0f },
                                      { 0.5f, 120.0f }, { 319.0f, 0.5f }, { 33.3f, 77.7f } };
    memset(&d, 0, sizeof d);
    d.fov_y_deg = 90.0f;
    r = fovsdf_ecc_init(&m, &d, 60.0f, 640, 360, gaze_at(320.0f, 180.0f));
    for (i = 0; i < 6; ++i) {
        float a = fovsdf_ecc_deg(&m, 320.0f + offs[i][0], 180.0f + offs[i][1]);
        float b = fovsdf_ecc_deg(&m, 320.0f - offs[i][0], 180.0f + offs[i][1]);
        float c = fovsdf_ecc_deg(&m, 320.0f + offs[i][0], 180.0f - offs[i][1]);
        float e = fovsdf_ecc_deg(&m, 320.0f - offs[i][0], 180.0f - offs[i][1]);
        worst = dmax(worst, fabs((double)a - (double)b));
        worst = dmax(worst, fabs((double)a - (double)c));
        worst = dmax(worst, fabs((double)a - (double)e));
    }
    check(r == FOV_OK && worst <= 1e-4, "ecc_symmetric_about_centred_gaze", "worst asymmetry %.3g deg", worst);

    /* monotonic along rows away from the gaze: the gaze row and one 97 px above it for the
       centred gaze; the gaze row for an off-centre gaze (a straight line through the gaze:
       the zones are convex conics around it). Off the gaze row of an off-centre gaze the
       minimum is not above the gaze, so that row is not tested. */
    for (k = 0; k < 2; ++k) {
        float gx = k == 0 ? 320.0f : 100.25f, gy = k == 0 ? 180.0f : 250.5f;
        float rows[2];
        int viol = 0, rr, x, xv = -1;
        float ev0 = 0.0f, ev1 = 0.0f;
        rows[0] = gy;
        rows[1] = gy - 97.0f;
        r = fovsdf_ecc_init(&m, &d, 60.0f, 640, 360, gaze_at(gx, gy));
        for (rr = 0; rr < (k == 0 ? 2 : 1); ++rr) {
            float prev = fovsdf_ecc_deg(&m, gx, rows[rr]);
            for (x = 1; (float)x + gx <= 640.0f; ++x) {
                float e = fovsdf_ecc_deg(&m, gx + (float)x, rows[rr]);
                if (!(e > prev) && !viol++) { xv = x; ev0 = prev; ev1 = e; }
                prev = e;
            }
            prev = fovsdf_ecc_deg(&m, gx, rows[rr]);
            for (x = 1; gx - (float)x >= 0.0f; ++x) {
                float e = fovsdf_ecc_deg(&m, gx - (float)x, rows[rr]);
                if (!(e > prev) && !viol++) { xv = -x; ev0 = prev; ev1 = e; }
                prev = e;
            }
        }
        check(r == FOV_OK && viol == 0, N("ecc_monotonic_along_rows_gaze%d", k),
              "%d violations; first at dx %d: %.7g then %.7g", viol, xv, (double)ev0, (double)ev1);
    }

    /* pixels per degree at the gaze against a central difference of ecc_deg along the
       radial direction (any direction for a centred gaze) */
    for (k = 0; k < 3; ++k) {
        float gx = k == 0 ? 320.0f : k == 1 ? 40.0f : 600.0f, gy = k == 0 ? 180.0f : k == 1 ? 300.0f : 20.0f;
        double ux = 1.0, uy = 0.0, h = 1.0, fd, ppd;
        memset(&d, 0, sizeof d);
        if (k == 2) {
            d.pixel_pitch_mm = 0.311f;
            d.distance_mm = 500.0f;
        } else {
            d.fov_y_deg = 90.0f;
        }
        r = fovsdf_ecc_init(&m, &d, 60.0f, 640, 360, gaze_at(gx, gy));
        if (k > 0) {
            double rx = (double)gx - 320.0, ry = (double)gy - 180.0, rl = sqrt(rx * rx + ry * ry);
            ux = rx / rl;
            uy = ry / rl;
        }
        fd = ((double)fovsdf_ecc_deg(&m, (float)((double)gx + h * ux), (float)((double)gy + h * uy)) +
              (double)fovsdf_ecc_deg(&m, (float)((double)gx - h * ux), (float)((double)gy - h * uy))) /
             (2.0 * h);
        ppd = (double)fovsdf_ecc_ppd(&m);
        check(r == FOV_OK && fabs(ppd * fd - 1.0) <= 0.01, N("ecc_ppd_matches_finite_difference_%d", k),
              "ppd %.5g, finite difference %.5g px/deg", ppd, 1.0 / fd);
    }
}

/* ==== 4. rendering ======================================================================== */

static const char *const g_shname[5] = { "full", "no_shadows", "normals", "depth", "steps" };

static void *load_builtin(uint32_t id, fovsdf_builtin *bi, uint32_t w, uint32_t h)
{
    size_t bytes = 0;
    void *mem;
    fov_result r = fovsdf_builtin_size(id, &bytes);
    if (r != FOV_OK || bytes == 0) {
        check(0, N("builtin_size_%u", id), "%s, %lu bytes", rname(r), (unsigned long)bytes);
        return NULL;
    }
    mem = malloc(bytes);
    if (!mem) return NULL;
    r = fovsdf_builtin_init(id, bi, mem, bytes);
    if (r != FOV_OK) {
        check(0, N("builtin_init_%u", id), "%s", rname(r));
        free(mem);
        return NULL;
    }
    bi->camera.width = w;
    bi->camera.height = h;
    return mem;
}

/* Name of the first field where two stats differ, or NULL. */
static const char *stats_diff(const fovsdf_stats *a, const fovsdf_stats *b)
{
    if (a->evals != b->evals) return "evals";
    if (a->evals_primary != b->evals_primary) return "evals_primary";
    if (a->evals_normal != b->evals_normal) return "evals_normal";
    if (a->evals_shadow != b->evals_shadow) return "evals_shadow";
    if (a->evals_lowres != b->evals_lowres) return "evals_lowres";
    if (a->rays != b->rays) return "rays";
    if (a->shadow_rays != b->shadow_rays) return "shadow_rays";
    if (a->hits != b->hits) return "hits";
    if (a->exhausted != b->exhausted) return "exhausted";
    if (a->prims != b->prims) return "prims";
    if (a->prims_skipped != b->prims_skipped) return "prims_skipped";
    return NULL;
}

/* Compares the seven buffers; one check per buffer. */
static void ib_compare(const char *what_in, const imgbuf *a, const imgbuf *b)
{
    size_t n = (size_t)a->w * a->h;
    char what[96]; /* what_in may be the N() buffer itself */
    snprintf(what, sizeof what, "%s", what_in);
    check(memcmp(a->rgb, b->rgb, 3 * n * sizeof(float)) == 0, N("%s_rgb_identical", what), "rgb differs");
    check(memcmp(a->rgb8, b->rgb8, 3 * n) == 0, N("%s_rgb8_identical", what), "rgb8 differs");
    check(memcmp(a->depth, b->depth, n * sizeof(float)) == 0, N("%s_depth_identical", what), "depth differs");
    check(memcmp(a->hit, b->hit, n) == 0, N("%s_hit_identical", what), "hit differs");
    check(memcmp(a->evals, b->evals, n * sizeof(uint32_t)) == 0, N("%s_evals_identical", what), "evals differs");
    check(memcmp(a->steps, b->steps, n * sizeof(uint32_t)) == 0, N("%s_steps_identical", what), "steps differs");
    check(memcmp(a->mat, b->mat, n * sizeof(int32_t)) == 0, N("%s_material_identical", what), "material differs");
}

static void ib_poison(imgbuf *b)
{
    size_t n = (size_t)b->w * b->h;
    memset(b->rgb, 0x5A, 3 * n * sizeof(float));
    memset(b->rgb8, 0x5A, 3 * n);
    memset(b->depth, 0x5A, n * sizeof(float));
    memset(b->hit, 0x5A, n);
    memset(b->evals, 0x5A, n * sizeof(uint32_t));
    memset(b->steps, 0x5A, n * sizeof(uint32_t));
    memset(b->mat, 0x5A, n * sizeof(int32_t));
}

static void test_partition(const char *tag, uint32_t id, uint32_t method, uint32_t spp)
{
    const uint32_t W = 64, H = 36;
    fovsdf_builtin bi;
    void *mem = load_builtin(id, &bi, W, H);
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fovsdf_output o;
    fovsdf_stats sf, sb, stl, s2;
    imgbuf full, bands, tiles, again;
    fov_result r, rb = FOV_OK, rt = FOV_OK;
    uint32_t y, x;
    const char *dd;
    if (!mem) return;
    cfg.method = method;
    cfg.spp = spp;
    r = fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze_at(20.0f, 10.0f), NULL, 0);
    expect_res(N("%s_init", tag), r, FOV_OK);
    if (r != FOV_OK) { free(mem); return; }
    ib_alloc(&full, W, H);
    ib_alloc(&bands, W, H);
    ib_alloc(&tiles, W, H);
    ib_alloc(&again, W, H);
    ib_poison(&full); ib_poison(&bands); ib_poison(&tiles); ib_poison(&again);
    memset(&sf, 0, sizeof sf); memset(&sb, 0, sizeof sb); memset(&stl, 0, sizeof stl); memset(&s2, 0, sizeof s2);
    ib_out(&full, &o);
    r = fovsdf_render_rows(&ctx, 0, H, &o, &sf);
    expect_res(N("%s_full_render", tag), r, FOV_OK);
    ib_out(&bands, &o);
    for (y = 0; y < H; y += 7) {
        fovsdf_stats s;
        memset(&s, 0, sizeof s);
        r = fovsdf_render_rows(&ctx, y, y + 7 < H ? y + 7 : H, &o, &s);
        if (r != FOV_OK) rb = r;
        fovsdf_stats_add(&sb, &s);
    }
    expect_res(N("%s_bands_of_7_render", tag), rb, FOV_OK);
    ib_out(&tiles, &o);
    for (y = 0; y < H; y += 11)
        for (x = 0; x < W; x += 13) {
            /* accumulate directly into the sum: render_tile adds to stats */
            r = fovsdf_render_tile(&ctx, x, y, x + 13 < W ? x + 13 : W, y + 11 < H ? y + 11 : H, &o, &stl);
            if (r != FOV_OK) rt = r;
        }
    expect_res(N("%s_tiles_13x11_render", tag), rt, FOV_OK);
    ib_compare(N("%s_bands", tag), &full, &bands);
    ib_compare(N("%s_tiles", tag), &full, &tiles);
    dd = stats_diff(&sf, &sb);
    check(dd == NULL, N("%s_bands_stats_sum", tag), "field %s differs (evals %lu vs %lu)", dd ? dd : "",
          (unsigned long)sf.evals, (unsigned long)sb.evals);
    dd = stats_diff(&sf, &stl);
    check(dd == NULL, N("%s_tiles_stats_sum", tag), "field %s differs (evals %lu vs %lu)", dd ? dd : "",
          (unsigned long)sf.evals, (unsigned long)stl.evals);
    ib_out(&again, &o);
    (void)fovsdf_render_rows(&ctx, 0, H, &o, &s2);
    ib_compare(N("%s_second_render", tag), &full, &again);
    dd = stats_diff(&sf, &s2);
    check(dd == NULL, N("%s_second_render_stats", tag), "field %s differs", dd ? dd : "");
    {
        uint64_t sum = 0, sumsteps = 0, hits = 0;
        size_t i;
        for (i = 0; i < (size_t)W * H; ++i) {
            sum += full.evals[i];
            sumsteps += full.steps[i];
            hits += full.hit[i];
        }
        check(sf.evals == sf.evals_primary + sf.evals_normal + sf.evals_shadow + sf.evals_lowres,
              N("%s_stats_identity", tag), "evals %lu != primary %lu + normal %lu + shadow %lu + lowres %lu",
              (unsigned long)sf.evals, (unsigned long)sf.evals_primary, (unsigned long)sf.evals_normal,
              (unsigned long)sf.evals_shadow, (unsigned long)sf.evals_lowres);
        check(sum == sf.evals, N("%s_pixel_evals_sum_to_stats", tag), "sum of the evals buffer %lu, stats.evals %lu",
              (unsigned long)sum, (unsigned long)sf.evals);
        check(sf.rays == (uint64_t)W * H * spp, N("%s_stats_rays", tag), "rays %lu, want %lu", (unsigned long)sf.rays,
              (unsigned long)((uint64_t)W * H * spp));
        /* the hit refinement costs at most 6 evaluations per hit beyond the steps (a second
           sample, the empty-ball certificate's 4, the plain step; fovsdf.h NUMERICS) */
        check(sumsteps <= sf.evals_primary && sf.evals_primary <= sumsteps + 6u * sf.hits,
              N("%s_steps_vs_primary_evals", tag), "sum of steps %lu, evals_primary %lu, hits %lu",
              (unsigned long)sumsteps, (unsigned long)sf.evals_primary, (unsigned long)sf.hits);
        check(sf.evals_normal > 0 && sf.evals_shadow > 0 && sf.shadow_rays > 0 && sf.hits > 0,
              N("%s_scene_exercises_shading", tag), "hits %lu of %lu rays, evals_normal %lu, evals_shadow %lu",
              (unsigned long)sf.hits, (unsigned long)sf.rays, (unsigned long)sf.evals_normal,
              (unsigned long)sf.evals_shadow);
        if (spp == 1)
            check(hits == sf.hits, N("%s_hit_buffer_matches_stats", tag), "hit pixels %lu, stats.hits %lu",
                  (unsigned long)hits, (unsigned long)sf.hits);
    }

    /* strides larger than the width: the padding stays untouched, the pixels match */
    {
        const uint32_t prgb = 3 * W + 7, p8 = 3 * W + 5, pd = W + 3, ph = W + 9, pe = W + 2, ps = W + 4, pm = W + 1;
        float *rgb = (float *)malloc((size_t)prgb * H * sizeof(float));
        uint8_t *b8 = (uint8_t *)malloc((size_t)p8 * H);
        float *dep = (float *)malloc((size_t)pd * H * sizeof(float));
        uint8_t *hb = (uint8_t *)malloc((size_t)ph * H);
        uint32_t *ev = (uint32_t *)malloc((size_t)pe * H * sizeof(uint32_t));
        uint32_t *stp = (uint32_t *)malloc((size_t)ps * H * sizeof(uint32_t));
        int32_t *mat = (int32_t *)malloc((size_t)pm * H * sizeof(int32_t));
        unsigned long pad_bad = 0, px_bad = 0;
        if (rgb && b8 && dep && hb && ev && stp && mat) {
            memset(rgb, 0xA5, (size_t)prgb * H * sizeof(float));
            memset(b8, 0xA5, (size_t)p8 * H);
            memset(dep, 0xA5, (size_t)pd * H * sizeof(float));
            memset(hb, 0xA5, (size_t)ph * H);
            memset(ev, 0xA5, (size_t)pe * H * sizeof(uint32_t));
            memset(stp, 0xA5, (size_t)ps * H * sizeof(uint32_t));
            memset(mat, 0xA5, (size_t)pm * H * sizeof(int32_t));
            fovsdf_output_init(&o);
            o.rgb = rgb; o.rgb_stride = prgb;
            o.rgb8 = b8; o.rgb8_stride = p8;
            o.depth = dep; o.depth_stride = pd;
            o.hit = hb; o.hit_stride = ph;
            o.evals = ev; o.evals_stride = pe;
            o.steps = stp; o.steps_stride = ps;
            o.material = mat; o.material_stride = pm;
            r = fovsdf_render_rows(&ctx, 0, H, &o, NULL);
            expect_res(N("%s_padded_render", tag), r, FOV_OK);
            for (y = 0; y < H; ++y) {
#define T_PAD(buf, stride, used, type)                                                                    \
    do {                                                                                                  \
        const unsigned char *q = (const unsigned char *)((buf) + (size_t)y * (stride) + (used));          \
        size_t z;                                                                                         \
        for (z = 0; z < ((stride) - (used)) * sizeof(type); ++z) pad_bad += q[z] != 0xA5;                 \
    } while (0)
                T_PAD(rgb, prgb, 3 * W, float);
                T_PAD(b8, p8, 3 * W, uint8_t);
                T_PAD(dep, pd, W, float);
                T_PAD(hb, ph, W, uint8_t);
                T_PAD(ev, pe, W, uint32_t);
                T_PAD(stp, ps, W, uint32_t);
                T_PAD(mat, pm, W, int32_t);
#undef T_PAD
                px_bad += memcmp(rgb + (size_t)y * prgb, full.rgb + (size_t)y * 3 * W, 3 * W * sizeof(float)) != 0;
                px_bad += memcmp(b8 + (size_t)y * p8, full.rgb8 + (size_t)y * 3 * W, 3 * W) != 0;
                px_bad += memcmp(dep + (size_t)y * pd, full.depth + (size_t)y * W, W * sizeof(float)) != 0;
                px_bad += memcmp(hb + (size_t)y * ph, full.hit + (size_t)y * W, W) != 0;
                px_bad += memcmp(ev + (size_t)y * pe, full.evals + (size_t)y * W, W * sizeof(uint32_t)) != 0;
                px_bad += memcmp(stp + (size_t)y * ps, full.steps + (size_t)y * W, W * sizeof(uint32_t)) != 0;
                px_bad += memcmp(mat + (size_t)y * pm, full.mat + (size_t)y * W, W * sizeof(int32_t)) != 0;
            }
            check(pad_bad == 0, N("%s_stride_padding_untouched", tag), "%lu padding bytes written", pad_bad);
            check(px_bad == 0, N("%s_stride_pixels_match_packed", tag), "%lu buffer rows differ from the packed render",
                  px_bad);
        }
        free(rgb); free(b8); free(dep); free(hb); free(ev); free(stp); free(mat);
    }
    ib_free(&full);
    ib_free(&bands);
    ib_free(&tiles);
    ib_free(&again);
    free(mem);
}

/* Every built-in scene, method and shading mode at 80x45: finite output, consistent stats. */
static void test_builtin_sweep(void)
{
    const uint32_t W = 80, H = 45;
    uint32_t id, m, sh;
    imgbuf ib;
    ib_alloc(&ib, W, H);
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        fovsdf_builtin bi;
        void *mem = load_builtin(id, &bi, W, H);
        char bad_id[96] = "";
        int n_id_bad = 0;
        if (!mem) continue;
        for (m = 0; m < 4; ++m)
            for (sh = 0; sh < 5; ++sh) {
                fovsdf_config cfg = fovsdf_config_default();
                fovsdf_ctx ctx;
                fovsdf_output o;
                fovsdf_stats st;
                fov_result r;
                size_t bad = 0, i, deprange = 0;
                uint64_t sum = 0;
                cfg.method = m;
                cfg.shading = sh;
                memset(&st, 0, sizeof st);
                ib_poison(&ib);
                r = fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze_at(40.0f, 22.5f), NULL, 0);
                if (r == FOV_OK) {
                    ib_out(&ib, &o);
                    r = fovsdf_render_rows(&ctx, 0, H, &o, &st);
                }
                if (r == FOV_OK) {
                    bad = ib_nonfinite(&ib);
                    for (i = 0; i < (size_t)W * H; ++i) {
                        sum += ib.evals[i];
                        deprange += !(ib.depth[i] >= 0.0f && ib.depth[i] <= ctx.t_max);
                    }
                }
                check(r == FOV_OK && bad == 0 && deprange == 0,
                      N("builtin_%s_%s_%s_finite", fovsdf_builtin_name(id), g_mname[m], g_shname[sh]),
                      "%s, %lu non-finite rgb/depth values, %lu depths outside [0, t_max]", rname(r),
                      (unsigned long)bad, (unsigned long)deprange);
                if (r == FOV_OK && (st.evals != st.evals_primary + st.evals_normal + st.evals_shadow + st.evals_lowres ||
                                    sum != st.evals || st.rays != (uint64_t)W * H)) {
                    if (!n_id_bad++)
                        snprintf(bad_id, sizeof bad_id, "%s/%s: evals %lu, parts %lu, pixel sum %lu, rays %lu", g_mname[m],
                                 g_shname[sh], (unsigned long)st.evals,
                                 (unsigned long)(st.evals_primary + st.evals_normal + st.evals_shadow + st.evals_lowres),
                                 (unsigned long)sum, (unsigned long)st.rays);
                }
            }
        check(n_id_bad == 0, N("builtin_%s_stats_identity_all_configs", fovsdf_builtin_name(id)),
              "%d of 20 renders break evals == primary + normal + shadow + lowres == sum of pixel evals; first %s",
              n_id_bad, bad_id);
        free(mem);
    }
    ib_free(&ib);
}

static void white_albedo(const float p[3], int32_t material, float rgb[3], void *user)
{
    (void)p;
    (void)material;
    (void)user;
    rgb[0] = rgb[1] = rgb[2] = 1.0f;
}

/* Renders the wall whose edge crosses column (axis 0) or row (axis 1) `col` at fraction
   frac of the pixel, and summarises the edge pixels (coverage in samples, all rows or
   columns must agree) and the pixels on either side. */
typedef struct edge_res {
    fov_result rc;
    int cov_min, cov_max;          /* coverage of the edge pixels, in samples */
    unsigned long not_multiple;    /* edge pixels whose value is not k / spp */
    unsigned long hit_bad;         /* edge pixels whose hit flag is not (2 cov >= spp) */
    unsigned long in_bad, out_bad; /* covered pixels not 1, uncovered not 0 */
    unsigned long depth_bad;       /* depth t_max exactly when no sample hit, else in [1, 1.6] (the corner ray has t = 1.55) */
} edge_res;

static void render_edge(imgbuf *ib, int axis, uint32_t col, double frac, uint32_t spp, edge_res *er)
{
    const uint32_t W = ib->w, H = ib->h;
    const double T = tan(30.0 * 3.14159265358979323846 / 180.0), A = (double)W / (double)H;
    double edge_px = (double)col + frac;
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fovsdf_output o;
    uint32_t x, y;
    memset(er, 0, sizeof *er);
    er->cov_min = 1 << 30;
    er->cov_max = -1;
    memset(&u, 0, sizeof u);
    /* camera at z = -1 looking +z: right = -x, up = +y; the wall z = 0 is at unit distance,
       so image point px maps to world x = -u(px), py to world y = v(py) */
    if (axis == 0) {
        u.kind = K_WALL_X;
        u.edge = (float)(-((edge_px / (double)W) * 2.0 - 1.0) * T * A);
    } else {
        u.kind = K_WALL_Y;
        u.edge = (float)((1.0 - (edge_px / (double)H) * 2.0) * T);
    }
    scene_for(&sc, &u);
    sc.albedo = white_albedo;
    sc.num_lights = 0;
    sc.ambient[0] = sc.ambient[1] = sc.ambient[2] = 1.0f;
    memset(sc.sky_zenith, 0, sizeof sc.sky_zenith);
    memset(sc.sky_horizon, 0, sizeof sc.sky_horizon);
    cam_at(&cam, W, H, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f);
    cfg.spp = spp;
    cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
    cfg.t_max = 20.0f;
    /* a tight absolute threshold: the default cone threshold (a quarter pixel) would, by
       design, count rays passing that close to the edge as hits */
    cfg.eps_mode = FOVSDF_EPS_ABSOLUTE;
    cfg.eps = 1e-5f;
    er->rc = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(0.5f * (float)W, 0.5f * (float)H), NULL, 0);
    if (er->rc == FOV_OK) {
        ib_out(ib, &o);
        er->rc = fovsdf_render_rows(&ctx, 0, H, &o, NULL);
    }
    if (er->rc != FOV_OK) return;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            uint32_t c = axis == 0 ? x : y;
            size_t i = (size_t)y * W + x;
            float v = ib->rgb[3 * i], dep = ib->depth[i];
            if (c == col) {
                double cv = (double)v * (double)spp;
                int k = (int)floor(cv + 0.5);
                if (fabs(cv - (double)k) > 1e-4 || ib->rgb[3 * i + 1] != v || ib->rgb[3 * i + 2] != v) ++er->not_multiple;
                if (k < er->cov_min) er->cov_min = k;
                if (k > er->cov_max) er->cov_max = k;
                if (ib->hit[i] != (2 * k >= (int)spp ? 1 : 0)) ++er->hit_bad;
                if (k == 0 ? dep != 20.0f : !(dep >= 1.0f && dep <= 1.6f)) ++er->depth_bad;
            } else if (c > col) {
                er->in_bad += v != 1.0f;
                er->depth_bad += !(dep >= 1.0f && dep <= 1.6f);
            } else {
                er->out_bad += v != 0.0f;
                er->depth_bad += dep != 20.0f;
            }
        }
}

/* Supersampling: a wall (z >= 0) cut at a vertical (horizontal) edge that crosses a pixel
   column (row) at a known fraction; a constant white albedo with ambient 1 and no lights
   gives colour 1 on hits and 0 (black sky) on misses, so a pixel's value is its hit
   coverage. Expected coverage from the documented sample patterns:
     1 spp: the centre; 4 spp: x offsets -1/8, 3/8, 1/8, -3/8 and y offsets -3/8, -1/8, 3/8,
     1/8; 16 spp: n-rooks on a 16x16 grid, so each fine column (row) holds exactly one
     sample: an edge on the fine-grid line k/16 leaves 16 - k samples on the covered side
     wherever a sample sits inside its fine cell. */
static int doc_offsets(uint32_t spp, int axis, double *off)
{
    static const double p4[4][2] = { { -0.125, -0.375 }, { 0.375, -0.125 }, { 0.125, 0.375 }, { -0.375, 0.125 } };
    int i;
    if (spp == 1) { off[0] = 0.0; return 1; }
    if (spp == 4) { for (i = 0; i < 4; ++i) off[i] = p4[i][axis]; return 4; }
    for (i = 0; i < 16; ++i) off[i] = ((double)i + 0.5) / 16.0 - 0.5; /* one per fine cell */
    return 16;
}

static void test_supersampling(void)
{
    static const uint32_t spps[3] = { 1, 4, 16 };
    static const double fracs[2] = { 5.0 / 16.0, 11.0 / 16.0 };
    imgbuf ib, sm;
    int axis, fi, k;
    uint32_t si;
    ib_alloc(&ib, 64, 36);
    ib_alloc(&sm, 24, 14);
    for (axis = 0; axis < 2; ++axis)
        for (fi = 0; fi < 2; ++fi)
            for (si = 0; si < 3; ++si) {
                uint32_t spp = spps[si], col = axis == 0 ? 20u : 10u;
                const char *an = axis == 0 ? "vertical" : "horizontal";
                double off[16];
                int ns = doc_offsets(spp, axis, off), i, want = 0;
                edge_res er;
                for (i = 0; i < ns; ++i) want += 0.5 + off[i] >= fracs[fi];
                render_edge(&ib, axis, col, fracs[fi], spp, &er);
                check(er.rc == FOV_OK && er.not_multiple == 0 && er.cov_min == want && er.cov_max == want,
                      N("supersample_%s_edge_at_%g_16ths_spp%u_coverage", an, fracs[fi] * 16.0, spp),
                      "%s; edge pixel coverage %d..%d of %u samples, documented pattern gives %d; %lu values not k/%u",
                      rname(er.rc), er.cov_min, er.cov_max, spp, want, er.not_multiple, spp);
                check(er.rc == FOV_OK && er.hit_bad == 0 && er.in_bad == 0 && er.out_bad == 0 && er.depth_bad == 0,
                      N("supersample_%s_edge_at_%g_16ths_spp%u_flags_interior_depth", an, fracs[fi] * 16.0, spp),
                      "%lu hit flags wrong, %lu covered pixels not 1, %lu uncovered not 0, %lu depths wrong", er.hit_bad,
                      er.in_bad, er.out_bad, er.depth_bad);
            }
    /* sweeps on a small image: 16 spp across every fine-grid line, 4 spp across the
       quarter lines (which pass between the rotated-grid samples) */
    for (axis = 0; axis < 2; ++axis) {
        const char *an = axis == 0 ? "columns" : "rows";
        uint32_t col = axis == 0 ? 7u : 5u;
        char first[96] = "";
        int bad = 0;
        for (k = 1; k < 16; ++k) {
            edge_res er;
            render_edge(&sm, axis, col, (double)k / 16.0, 16, &er);
            if (er.rc != FOV_OK || er.not_multiple || er.cov_min != 16 - k || er.cov_max != 16 - k || er.in_bad ||
                er.out_bad) {
                if (!bad++)
                    snprintf(first, sizeof first, "edge at %d/16: coverage %d..%d, want %d (%s)", k, er.cov_min, er.cov_max,
                             16 - k, rname(er.rc));
            }
        }
        check(bad == 0, N("supersample_16_nrooks_one_sample_per_fine_%s", an), "%d of 15 edge positions wrong; first %s",
              bad, first);
        bad = 0;
        for (k = 1; k < 4; ++k) {
            edge_res er;
            double off[4];
            int i, want = 0;
            (void)doc_offsets(4, axis, off);
            for (i = 0; i < 4; ++i) want += 0.5 + off[i] >= (double)k / 4.0;
            render_edge(&sm, axis, col, (double)k / 4.0, 4, &er);
            if (er.rc != FOV_OK || er.not_multiple || er.cov_min != want || er.cov_max != want) {
                if (!bad++)
                    snprintf(first, sizeof first, "edge at %d/4: coverage %d..%d, want %d (%s)", k, er.cov_min, er.cov_max,
                             want, rname(er.rc));
            }
        }
        check(bad == 0, N("supersample_4_rotated_grid_%s", an), "%d of 3 edge positions wrong; first %s", bad, first);
    }
    ib_free(&ib);
    ib_free(&sm);
}

static void test_camera_rays(void)
{
    const uint32_t W = 64, H = 36;
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx, cl, cr;
    fov_result r, r1, r2;
    double f[3], up[3] = { 0.1, 1.0, 0.0 }, rt[3], uu[3], l, T, worst = 0.0;
    static const float pts[5][2] = { { 0.5f, 0.5f }, { 32.0f, 18.0f }, { 63.5f, 35.5f }, { 10.25f, 30.75f }, { 64.0f, 0.0f } };
    int i, j;
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    cam_at(&cam, W, H, 1.0f, 2.0f, -3.0f, 0.5f, 0.0f, 2.0f);
    cam.up[0] = 0.1f; cam.up[1] = 1.0f; cam.up[2] = 0.0f;
    cam.fov_y_deg = 50.0f;
    r = fovsdf_init(&ctx, NULL, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
    expect_res("camera_ray_ctx_init", r, FOV_OK);
    if (r != FOV_OK) return;
    /* the documented basis, in double */
    f[0] = 0.5 - 1.0; f[1] = 0.0 - 2.0; f[2] = 2.0 + 3.0;
    l = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (j = 0; j < 3; ++j) f[j] /= l;
    rt[0] = f[1] * up[2] - f[2] * up[1];
    rt[1] = f[2] * up[0] - f[0] * up[2];
    rt[2] = f[0] * up[1] - f[1] * up[0];
    l = sqrt(rt[0] * rt[0] + rt[1] * rt[1] + rt[2] * rt[2]);
    for (j = 0; j < 3; ++j) rt[j] /= l;
    uu[0] = rt[1] * f[2] - rt[2] * f[1];
    uu[1] = rt[2] * f[0] - rt[0] * f[2];
    uu[2] = rt[0] * f[1] - rt[1] * f[0];
    T = tan(25.0 * 3.14159265358979323846 / 180.0);
    for (i = 0; i < 5; ++i) {
        float ro[3], rd[3];
        double d[3], su = ((double)pts[i][0] / W * 2.0 - 1.0) * T * ((double)W / H), sv = ((double)pts[i][1] / H * 2.0 - 1.0) * T;
        r1 = fovsdf_camera_ray(&ctx, pts[i][0], pts[i][1], ro, rd);
        for (j = 0; j < 3; ++j) d[j] = f[j] + su * rt[j] - sv * uu[j];
        l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (j = 0; j < 3; ++j) {
            worst = dmax(worst, fabs((double)rd[j] - d[j] / l));
            worst = dmax(worst, fabs((double)ro[j] - (double)cam.pos[j]));
        }
        if (r1 != FOV_OK) worst = 1e9;
    }
    check(worst <= 1e-5, "camera_ray_matches_documented_formula", "worst component error %.3g", worst);
    {
        float rr[3], uq[3], fq[3];
        fovsdf_camera c2;
        cam_at(&c2, W, H, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f);
        r1 = fovsdf_camera_basis(&c2, rr, uq, fq);
        check(r1 == FOV_OK && fabsf(rr[0] + 1.0f) < 1e-6f && fabsf(rr[1]) < 1e-6f && fabsf(rr[2]) < 1e-6f &&
                  fabsf(uq[1] - 1.0f) < 1e-6f,
              "camera_basis_up_y_fwd_z_right_is_minus_x", "right (%g %g %g), up (%g %g %g)", (double)rr[0],
              (double)rr[1], (double)rr[2], (double)uq[0], (double)uq[1], (double)uq[2]);
    }

    /* stereo: eye_offset moves the origin along ctx.right, directions unchanged */
    cam.eye_offset = -0.032f;
    r1 = fovsdf_init(&cl, NULL, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
    cam.eye_offset = 0.032f;
    r2 = fovsdf_init(&cr, NULL, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
    if (r1 == FOV_OK && r2 == FOV_OK) {
        float rol[3], rdl[3], ror[3], rdr[3], rom[3], rdm[3];
        double e_off = 0.0, e_dir = 0.0, e_mid = 0.0;
        (void)fovsdf_camera_ray(&cl, 17.5f, 9.5f, rol, rdl);
        (void)fovsdf_camera_ray(&cr, 17.5f, 9.5f, ror, rdr);
        (void)fovsdf_camera_ray(&ctx, 17.5f, 9.5f, rom, rdm);
        for (j = 0; j < 3; ++j) {
            e_off = dmax(e_off, fabs(((double)ror[j] - (double)rol[j]) - 0.064 * rt[j]));
            e_off = dmax(e_off, fabs(((double)ror[j] - (double)ctx.right[j] * 0.032) - (double)cam.pos[j]));
            e_mid = dmax(e_mid, fabs(0.5 * ((double)ror[j] + (double)rol[j]) - (double)rom[j]));
            e_dir = dmax(e_dir, fabs((double)rdl[j] - (double)rdr[j]));
        }
        check(e_off <= 1e-6 && e_mid <= 1e-6, "stereo_origins_offset_along_right",
              "origin error %.3g, midpoint error %.3g (left %g %g %g, right %g %g %g)", e_off, e_mid, (double)rol[0],
              (double)rol[1], (double)rol[2], (double)ror[0], (double)ror[1], (double)ror[2]);
        check(e_dir <= 1e-7, "stereo_directions_unchanged", "direction difference %.3g", e_dir);
    } else {
        check(0, "stereo_origins_offset_along_right", "init %s / %s", rname(r1), rname(r2));
    }
    check(fabs((double)ctx.right[0] - rt[0]) < 1e-6 && fabs((double)ctx.right[1] - rt[1]) < 1e-6 &&
              fabs((double)ctx.right[2] - rt[2]) < 1e-6,
          "ctx_right_is_fwd_cross_up", "ctx.right (%g %g %g), expected (%g %g %g)", (double)ctx.right[0],
          (double)ctx.right[1], (double)ctx.right[2], rt[0], rt[1], rt[2]);
}

/* ==== more checks of sections 1 to 4 (API semantics, thresholds, shading modes, rendering) == */

static void test_api_semantics(void)
{
    base_t b;
    fovsdf_ctx ctx, before;
    fovsdf_config cfg;
    fovsdf_output o;
    fovsdf_stats st;
    fov_result r;
    float ro[3], rd[3];
    base_init(&b);

    r = fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, b.gaze, NULL, 0);
    expect_res("camera_ray_nan_px", fovsdf_camera_ray(&ctx, f_nan(), 1.0f, ro, rd), FOV_ERR_NOT_FINITE);
    expect_res("camera_ray_inf_py", fovsdf_camera_ray(&ctx, 1.0f, f_inf(), ro, rd), FOV_ERR_NOT_FINITE);
    expect_res("init_gaze_off_screen_ok", fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, gaze_at(-100.0f, 5000.0f), NULL, 0),
               FOV_OK);
    cfg = b.cfg;
    cfg.spp = 0;
    r = fovsdf_init(&ctx, &cfg, &b.sc, &b.cam, b.gaze, NULL, 0);
    check(r == FOV_OK && ctx.cfg.spp == 1, "config_spp_0_means_1", "%s, ctx.cfg.spp %u", rname(r), ctx.cfg.spp);

    /* t_max: config, else scene, else 100; a miss reports it */
    {
        static const float ct[3] = { 0.0f, 0.0f, 9.0f }, stm[3] = { 0.0f, 7.0f, 0.0f }, want[3] = { 100.0f, 7.0f, 9.0f };
        int i;
        for (i = 0; i < 3; ++i) {
            fovsdf_scene sc = b.sc;
            fovsdf_hit h;
            float o3[3] = { 0.0f, 0.0f, -5.0f }, away[3] = { 0.0f, 0.0f, -1.0f };
            cfg = b.cfg;
            cfg.t_max = ct[i];
            sc.t_max = stm[i];
            r = fovsdf_init(&ctx, &cfg, &sc, &b.cam, b.gaze, NULL, 0);
            memset(&h, 0, sizeof h);
            if (r == FOV_OK) r = fovsdf_trace(&ctx, o3, away, 0.0f, &h, NULL);
            check(r == FOV_OK && ctx.t_max == want[i] && h.kind == FOVSDF_MISS && h.t == want[i],
                  N("t_max_config_%g_scene_%g", (double)ct[i], (double)stm[i]), "%s, ctx.t_max %g, miss t %g, want %g",
                  rname(r), (double)ctx.t_max, (double)h.t, (double)want[i]);
        }
    }

    /* the context is read-only: rendering and tracing leave it unchanged */
    r = fovsdf_init(&ctx, &b.cfg, &b.sc, &b.cam, b.gaze, NULL, 0);
    memcpy(&before, &ctx, sizeof ctx);
    {
        static float depth[64 * 36];
        fovsdf_hit h;
        float o3[3] = { 0.0f, 0.0f, -5.0f }, d3[3] = { 0.0f, 0.0f, 1.0f };
        fovsdf_output_init(&o);
        o.depth = depth;
        memset(&st, 0, sizeof st);
        (void)fovsdf_render_rows(&ctx, 0, 36, &o, &st);
        (void)fovsdf_trace(&ctx, o3, d3, 0.0f, &h, &st);
    }
    check(memcmp(&before, &ctx, sizeof ctx) == 0, "ctx_unchanged_by_render_and_trace", "context bytes changed");
    fovsdf_output_init(&o);
    memset(&st, 0, sizeof st);
    r = fovsdf_render_rows(&ctx, 0, 36, &o, &st);
    check(r == FOV_OK && st.rays == 64u * 36u, "render_without_buffers_ok", "%s, rays %lu", rname(r),
          (unsigned long)st.rays);
    {
        /* stats are added to, not overwritten */
        fovsdf_stats s1, s2;
        memset(&s1, 0, sizeof s1);
        (void)fovsdf_render_rows(&ctx, 3, 9, &o, &s1);
        memset(&s2, 0, sizeof s2);
        s2.evals = 1000; s2.rays = 7; s2.hits = 5;
        (void)fovsdf_render_rows(&ctx, 3, 9, &o, &s2);
        check(s2.evals == s1.evals + 1000 && s2.rays == s1.rays + 7 && s2.hits == s1.hits + 5, "render_adds_to_stats",
              "evals %lu (fresh %lu + 1000), rays %lu (fresh %lu + 7)", (unsigned long)s2.evals,
              (unsigned long)s1.evals, (unsigned long)s2.rays, (unsigned long)s1.rays);
    }
    {
        /* fovsdf_distance: one counted evaluation of the scene */
        float p[3] = { 0.0f, 3.0f, 4.0f };
        float dd;
        memset(&st, 0, sizeof st);
        b.u.calls = 0;
        dd = fovsdf_distance(&ctx, p, NULL, &st);
        check(fabsf(dd - 4.0f) < 1e-6f && st.evals == 1 && b.u.calls == 1, "distance_one_evaluation",
              "d %g (want 4), stats.evals %lu, callbacks %lu", (double)dd, (unsigned long)st.evals, b.u.calls);
    }
    {
        /* sky: horizon colour at and below the horizon, zenith straight up */
        float up[3] = { 0.0f, 1.0f, 0.0f }, hz[3] = { 1.0f, 0.0f, 0.0f }, dn[3] = { 0.0f, -1.0f, 0.0f }, mid[3];
        float c1[3], c2[3], c3[3], c4[3];
        double e = 0.0;
        int i;
        mid[0] = 0.8f; mid[1] = 0.6f; mid[2] = 0.0f;
        fovsdf_sky(&ctx, up, c1);
        fovsdf_sky(&ctx, hz, c2);
        fovsdf_sky(&ctx, dn, c3);
        fovsdf_sky(&ctx, mid, c4);
        for (i = 0; i < 3; ++i) {
            double zen = (double)b.sc.sky_zenith[i], hor = (double)b.sc.sky_horizon[i];
            e = dmax(e, fabs((double)c1[i] - zen));
            e = dmax(e, fabs((double)c2[i] - hor));
            e = dmax(e, fabs((double)c3[i] - hor));
            e = dmax(e, fabs((double)c4[i] - (hor + (zen - hor) * 0.6)));
        }
        check(e <= 1e-6, "sky_gradient", "worst error %.3g", e);
    }
}

/* Threshold semantics with a constant distance c = 0.01 marched from the origin: classic
   steps of exactly c, so the hit step tells which threshold applied. */
static void test_thresholds(void)
{
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_hit h;
    fov_result r;
    const float ro[3] = { 0.0f, 0.0f, 0.0f }, rd[3] = { 0.0f, 0.0f, 1.0f };
    const double pa = 2.0 * tan(30.0 * 3.14159265358979323846 / 180.0) / 36.0; /* pixel angle, 36 rows, fov 60 */
    int n_cone;
    static const uint32_t modes[4] = { FOVSDF_EPS_ABSOLUTE, FOVSDF_EPS_ABSOLUTE, FOVSDF_EPS_CONE, FOVSDF_EPS_BOTH };
    static const float epss[4] = { 0.02f, 0.005f, 0.02f, 0.005f };
    static const char *const names[4] = { "eps_absolute_above_d_hits_at_once", "eps_absolute_below_d_misses",
                                          "eps_cone_ignores_eps", "eps_both_cone_grows_past_d" };
    int i;
    memset(&u, 0, sizeof u);
    u.kind = K_CONST;
    u.off = 0.01f;
    scene_for(&sc, &u);
    cam_at(&cam, 64, 36, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f);
    /* cone hit at the first n with c < 0.25 * pa * n c, i.e. n > 4 / pa */
    n_cone = (int)floor(4.0 / pa) + 1;
    for (i = 0; i < 4; ++i) {
        fovsdf_config cfg = fovsdf_config_default();
        cfg.eps_mode = modes[i];
        cfg.eps = epss[i];
        cfg.t_max = 5.0f;
        cfg.max_steps = 2048;
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(32.0f, 18.0f), NULL, 0);
        memset(&h, 0, sizeof h);
        if (r == FOV_OK) r = fovsdf_trace(&ctx, ro, rd, 0.0f, &h, NULL);
        if (i == 0)
            check(r == FOV_OK && h.kind == FOVSDF_HIT && h.t == 0.0f && h.steps == 1, names[i], "%s %s t %g steps %u",
                  rname(r), kind_name(h.kind), (double)h.t, h.steps);
        else if (i == 1)
            check(r == FOV_OK && h.kind == FOVSDF_MISS && h.t == 5.0f, names[i], "%s %s t %g steps %u", rname(r),
                  kind_name(h.kind), (double)h.t, h.steps);
        else
            check(r == FOV_OK && h.kind == FOVSDF_HIT && h.steps == (uint32_t)n_cone + 1 &&
                      fabs((double)h.t - 0.01 * n_cone) <= 1e-4,
                  names[i], "%s %s t %g steps %u, want t %g after %d steps", rname(r), kind_name(h.kind), (double)h.t,
                  h.steps, 0.01 * n_cone, n_cone + 1);
    }
    /* the ulp floor: 8 FLT_EPSILON (|ro| + t) is about 9.5e-3 at 1e4 from the origin, above
       the constant 5e-3, so even eps = 1e-6 hits at once; near the origin it does not */
    {
        fovsdf_march_params mp = mp_make(FOVSDF_METHOD_CLASSIC, 1e-6f, 1.0f, 1024);
        float far_o[3] = { 1e4f, 0.0f, 0.0f };
        fovsdf_hit h2;
        u.off = 5e-3f;
        (void)fovsdf_march(&sc, &mp, far_o, rd, 0.0f, &h, NULL);
        (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h2, NULL);
        check(h.kind == FOVSDF_HIT && h.t == 0.0f && h2.kind == FOVSDF_MISS, "threshold_ulp_floor_far_from_origin",
              "at 1e4: %s t %g; at the origin: %s t %g", kind_name(h.kind), (double)h.t, kind_name(h2.kind),
              (double)h2.t);
    }
    /* Lipschitz: twice the distance with lipschitz 2 marches exactly like the exact SDF */
    {
        tsdf u1, u2;
        fovsdf_scene s1, s2;
        uint32_t m;
        const float o3[3] = { 0.3f, 0.4f, -4.0f };
        float d3[3];
        const double tgt[3] = { 0.5, -0.2, 0.0 };
        tsdf_sphere(&u1, 0.0f, 0.0f, 0.0f, 1.0f);
        tsdf_sphere(&u2, 0.0f, 0.0f, 0.0f, 1.0f);
        u2.kind = K_SPHERES_X2;
        scene_for(&s1, &u1);
        scene_for(&s2, &u2);
        s2.lipschitz = 2.0f;
        dir_to(o3, tgt, d3);
        for (m = 0; m < 4; ++m) {
            fovsdf_march_params mp = mp_make(m, 1e-4f, 20.0f, 512);
            fovsdf_hit a, c;
            double te = ray_sphere(o3, d3, u1.sc[0], 1.0f);
            (void)fovsdf_march(&s1, &mp, o3, d3, 0.0f, &a, NULL);
            (void)fovsdf_march(&s2, &mp, o3, d3, 0.0f, &c, NULL);
            check(c.kind == FOVSDF_HIT && fabs((double)c.t - te) <= 1e-4 * te && c.steps == a.steps,
                  N("lipschitz_2_scaled_sdf_%s", g_mname[m]), "scaled: %s t %.7g steps %u; exact: t %.7g steps %u; analytic %.7g",
                  kind_name(c.kind), (double)c.t, c.steps, (double)a.t, a.steps, te);
        }
    }
}

/* Every tracer parameter at the ends of its range still finds the analytic hits. */
static void test_param_variants(void)
{
    static const double tg[4][3] = { { 0.0, 0.0, 0.0 }, { 0.5, 0.3, 0.0 }, { -0.7, 0.6, 0.1 }, { 0.0, -0.9, 0.3 } };
    tsdf u, pl;
    fovsdf_scene sc, sp;
    int v;
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    tsdf_plane(&pl, 0.0f, 1.0f, 0.0f, 0.0f);
    scene_for(&sp, &pl);
    for (v = 0; v < 7; ++v) {
        fovsdf_march_params mp = mp_make(FOVSDF_METHOD_RELAXED, 1e-4f, 200.0f, 8192);
        const float ro[3] = { -0.2f, 0.1f, -3.5f }, rp[3] = { 0.0f, 1.0f, 0.0f };
        float rd[3], gd[3];
        double worst = 0.0, a = 10.0 * 3.14159265358979323846 / 180.0, tp;
        int i, bad = 0;
        char label[48];
        fovsdf_hit h;
        switch (v) {
        case 0: mp.omega = 1.0f; snprintf(label, sizeof label, "relaxed_omega_1"); break;
        case 1: mp.omega = 1.95f; snprintf(label, sizeof label, "relaxed_omega_1.95"); break;
        case 2: mp.method = FOVSDF_METHOD_AUTORELAXED; mp.ar_beta = 0.05f; snprintf(label, sizeof label, "autorelaxed_beta_0.05"); break;
        case 3: mp.method = FOVSDF_METHOD_AUTORELAXED; mp.ar_beta = 1.0f; snprintf(label, sizeof label, "autorelaxed_beta_1"); break;
        case 4: mp.method = FOVSDF_METHOD_BV2018; mp.bv_relax = 0.05f; snprintf(label, sizeof label, "bv2018_relax_0.05"); break;
        case 5: mp.method = FOVSDF_METHOD_BV2018; mp.bv_relax = 1.0f; snprintf(label, sizeof label, "bv2018_relax_1"); break;
        default: mp.method = FOVSDF_METHOD_CLASSIC; mp.eps = 0.0f; mp.eps_cone = 1e-4f; snprintf(label, sizeof label, "classic_cone_only"); break;
        }
        for (i = 0; i < 4; ++i) {
            double te;
            dir_to(ro, tg[i], rd);
            te = ray_sphere(ro, rd, u.sc[0], 1.0f);
            (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
            if (h.kind != FOVSDF_HIT) ++bad;
            worst = dmax(worst, fabs((double)h.t - te) / dmax(1e-4, 1e-4 * te));
        }
        gd[0] = (float)cos(a); gd[1] = (float)-sin(a); gd[2] = 0.0f;
        tp = 1.0 / -(double)gd[1];
        (void)fovsdf_march(&sp, &mp, rp, gd, 0.0f, &h, NULL);
        if (h.kind != FOVSDF_HIT) ++bad;
        worst = dmax(worst, fabs((double)h.t - tp) / dmax(1e-4, 1e-4 * tp));
        check(bad == 0 && worst <= 1.0, N("params_%s_hits_analytic", label),
              "%d rays did not hit; worst |dt| / max(eps, 1e-4 t) = %.3g", bad, worst);
    }
    /* hit refinement (fovsdf.h, fovsdf__refine): a secant step through the last two samples,
       kept only when its end point's sphere overlaps the last sample's (near normal incidence:
       90, 80 degrees) or when one empty ball off the ray contains the segment it jumps
       (grazing angles; issue 10 item 1: the unverified secant jumped thin surfaces). With a
       coarse threshold eps = 1e-2 the unrefined hit lies up to eps / sin(angle) before the
       plane; the step should land on the plane up to float rounding (the slope from samples
       1e-2 apart costs about 1e-4 relative here), so 1e-3 is the tolerance. */
    {
        static const double ang[10] = { 90.0, 80.0, 30.0, 10.0, 5.0, 2.0, 1.0, 2.0, 2.0, 2.0 };
        static const uint32_t meth[10] = { 0, 0, 0, 0, 0, 0, 0, 1, 2, 3 };
        for (v = 0; v < 10; ++v) {
            fovsdf_march_params mp = mp_make(meth[v], 1e-2f, 300.0f, 8192);
            const float rp[3] = { 0.0f, 1.0f, 0.0f };
            float gd[3];
            double a = ang[v] * 3.14159265358979323846 / 180.0, tp;
            fovsdf_hit h;
            gd[0] = (float)cos(a); gd[1] = (float)-sin(a); gd[2] = 0.0f;
            tp = 1.0 / -(double)gd[1];
            (void)fovsdf_march(&sp, &mp, rp, gd, 0.0f, &h, NULL);
            check(h.kind == FOVSDF_HIT && fabs((double)h.t - tp) <= 1e-3,
                  N("plane_secant_refinement_exact_%s_%gdeg", g_mname[meth[v]], ang[v]),
                  "%s t %.6f, plane at %.6f (|dt| %.3g; unrefined bound eps/sin = %.3g), dist at t %.3g", kind_name(h.kind),
                  (double)h.t, tp, fabs((double)h.t - tp), 1e-2 / sin(a), (double)h.dist);
        }
    }
    /* a grazing ray with too few steps: EXHAUSTED with the t reached, short of the plane */
    {
        uint32_t m;
        for (m = 0; m < 4; ++m) {
            fovsdf_march_params mp = mp_make(m, 1e-4f, 300.0f, 20);
            const float rp[3] = { 0.0f, 1.0f, 0.0f };
            float gd[3];
            double a = 0.5 * 3.14159265358979323846 / 180.0, tp;
            fovsdf_hit h;
            gd[0] = (float)cos(a); gd[1] = (float)-sin(a); gd[2] = 0.0f;
            tp = 1.0 / -(double)gd[1];
            (void)fovsdf_march(&sp, &mp, rp, gd, 0.0f, &h, NULL);
            check(h.kind == FOVSDF_EXHAUSTED && h.steps == 20 && h.t > 0.0f && (double)h.t < tp,
                  N("grazing_exhausted_reports_t_reached_%s", g_mname[m]), "%s steps %u t %g (plane at %g)",
                  kind_name(h.kind), h.steps, (double)h.t, tp);
        }
    }
}

/* Shading modes and light rules on simple scenes. */
static void test_shading_modes(void)
{
    const uint32_t W = 65, H = 37;
    imgbuf ib;
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_output o;
    fov_result r;
    size_t c = (size_t)18 * W + 32; /* centre pixel: its ray is the optical axis */
    ib_alloc(&ib, W, H);
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    cam_at(&cam, W, H, 0.0f, 0.0f, -5.0f, 0.0f, 0.0f, 0.0f);
    {
        fovsdf_config cfg = fovsdf_config_default();
        cfg.shading = FOVSDF_SHADE_DEPTH;
        cfg.t_max = 10.0f;
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(32.5f, 18.5f), NULL, 0);
        if (r == FOV_OK) { ib_out(&ib, &o); r = fovsdf_render_rows(&ctx, 0, H, &o, NULL); }
        check(r == FOV_OK && fabs((double)ib.rgb[3 * c] - 0.6) <= 1e-4 && ib.rgb[0] == 0.0f &&
                  fabs((double)ib.depth[c] - 4.0) <= 1e-4 && ib.mat[c] == 0 && ib.mat[0] == -1 && ib.depth[0] == 10.0f,
              "shade_depth_grey_1_minus_t_over_t_max",
              "%s, centre grey %.6f (want 0.6), depth %.6f (want 4), corner grey %g (want 0), material centre %d corner %d, "
              "corner depth %g",
              rname(r), (double)ib.rgb[3 * c], (double)ib.depth[c], (double)ib.rgb[0], (int)ib.mat[c], (int)ib.mat[0],
              (double)ib.depth[0]);
    }
    {
        fovsdf_config cfg = fovsdf_config_default();
        cfg.shading = FOVSDF_SHADE_NORMALS;
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(32.5f, 18.5f), NULL, 0);
        if (r == FOV_OK) { ib_out(&ib, &o); r = fovsdf_render_rows(&ctx, 0, H, &o, NULL); }
        check(r == FOV_OK && fabs((double)ib.rgb[3 * c] - 0.5) <= 1e-3 && fabs((double)ib.rgb[3 * c + 1] - 0.5) <= 1e-3 &&
                  fabs((double)ib.rgb[3 * c + 2]) <= 1e-3,
              "shade_normals_half_plus_half_n", "%s, centre (%.5f %.5f %.5f), want (0.5 0.5 0) for n = (0 0 -1)", rname(r),
              (double)ib.rgb[3 * c], (double)ib.rgb[3 * c + 1], (double)ib.rgb[3 * c + 2]);
    }
    {
        /* heat map: 1 evaluation is blue (negative SDF: every ray hits at once, no normals
           in this mode); 256 evaluations are red (tiny SDF, 256 steps from the origin) */
        tsdf un, ut;
        fovsdf_scene sn, stn;
        fovsdf_camera c0;
        fovsdf_config cfg = fovsdf_config_default();
        size_t i, nblue = 0, nred = 0;
        memset(&un, 0, sizeof un);
        un.kind = K_NEG;
        scene_for(&sn, &un);
        cfg.shading = FOVSDF_SHADE_STEPS;
        r = fovsdf_init(&ctx, &cfg, &sn, &cam, gaze_at(32.5f, 18.5f), NULL, 0);
        if (r == FOV_OK) { ib_out(&ib, &o); r = fovsdf_render_rows(&ctx, 0, H, &o, NULL); }
        for (i = 0; i < (size_t)W * H; ++i)
            nblue += ib.rgb[3 * i] == 0.0f && ib.rgb[3 * i + 1] == 0.0f && ib.rgb[3 * i + 2] == 1.0f && ib.evals[i] == 1;
        check(r == FOV_OK && nblue == (size_t)W * H, "shade_steps_one_eval_blue", "%s, %lu of %u pixels blue with 1 eval",
              rname(r), (unsigned long)nblue, W * H);
        memset(&ut, 0, sizeof ut);
        ut.kind = K_TINY;
        scene_for(&stn, &ut);
        cam_at(&c0, W, H, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f);
        cfg.eps_mode = FOVSDF_EPS_ABSOLUTE;
        cfg.eps = 1e-31f;
        cfg.max_steps = 256;
        r = fovsdf_init(&ctx, &cfg, &stn, &c0, gaze_at(32.5f, 18.5f), NULL, 0);
        if (r == FOV_OK) { ib_out(&ib, &o); r = fovsdf_render_rows(&ctx, 0, H, &o, NULL); }
        for (i = 0; i < (size_t)W * H; ++i)
            nred += fabsf(ib.rgb[3 * i] - 1.0f) < 1e-5f && fabsf(ib.rgb[3 * i + 1]) < 1e-5f &&
                    fabsf(ib.rgb[3 * i + 2]) < 1e-5f && ib.evals[i] == 256 && ib.hit[i] == 1;
        check(r == FOV_OK && nred == (size_t)W * H, "shade_steps_256_evals_red", "%s, %lu of %u pixels red with 256 evals (first: %g %g %g, %u evals)",
              rname(r), (unsigned long)nred, W * H, (double)ib.rgb[0], (double)ib.rgb[1], (double)ib.rgb[2], ib.evals[0]);
    }
    ib_free(&ib);

    /* light rules with fovsdf_shade at p = origin, n = +y, a blocker sphere straight above */
    {
        tsdf ub;
        fovsdf_scene s2;
        const float p[3] = { 0.0f, 0.0f, 0.0f }, n[3] = { 0.0f, 1.0f, 0.0f }, rd[3] = { 0.0f, -1.0f, 0.0f };
        float rgb[3];
        int k;
        tsdf_sphere(&ub, 0.0f, 3.0f, 0.0f, 0.5f);
        tsdf_add_sphere(&ub, 0.0f, -50.0f, 0.0f, 0.1f);
        scene_for(&s2, &ub);
        s2.albedo = white_albedo;
        s2.ambient[0] = s2.ambient[1] = s2.ambient[2] = 0.25f;
        s2.num_lights = 1;
        memset(&s2.lights[0], 0, sizeof s2.lights[0]);
        s2.lights[0].type = FOVSDF_LIGHT_DIRECTIONAL;
        s2.lights[0].v[1] = 2.0f; /* need not be unit */
        s2.lights[0].color[0] = s2.lights[0].color[1] = s2.lights[0].color[2] = 1.0f;
        for (k = 0; k < 5; ++k) {
            double want;
            const char *nm;
            fovsdf_config cfg = fovsdf_config_default();
            s2.lights[0].shadow_k = 0.0f;
            s2.lights[0].type = FOVSDF_LIGHT_DIRECTIONAL;
            s2.lights[0].v[0] = 0.0f; s2.lights[0].v[1] = 2.0f; s2.lights[0].v[2] = 0.0f;
            s2.lights[0].range = 0.0f;
            switch (k) {
            case 0: want = 0.25; nm = "shade_directional_blocked_ambient_only"; break;
            case 1: s2.lights[0].shadow_k = -1.0f; want = 1.25; nm = "shade_negative_shadow_k_casts_no_shadow"; break;
            case 2: cfg.shading = FOVSDF_SHADE_NO_SHADOWS; want = 1.25; nm = "shade_no_shadows_mode_ignores_blocker"; break;
            case 3: s2.lights[0].v[1] = -1.0f; s2.lights[0].shadow_k = -1.0f; want = 0.25; nm = "shade_light_behind_surface_dark"; break;
            default:
                s2.lights[0].type = FOVSDF_LIGHT_POINT;
                s2.lights[0].v[0] = 0.0f; s2.lights[0].v[1] = 9.0f; s2.lights[0].v[2] = 0.0f;
                s2.lights[0].range = 1.0f;
                s2.lights[0].shadow_k = -1.0f;
                want = 0.25; /* 9 > 8 * range: no light at all */
                nm = "shade_point_light_beyond_8_range_dark";
                break;
            }
            r = fovsdf_init(&ctx, &cfg, &s2, &cam, gaze_at(32.5f, 18.5f), NULL, 0);
            rgb[0] = rgb[1] = rgb[2] = -1.0f;
            if (r == FOV_OK) fovsdf_shade(&ctx, p, n, rd, 0, rgb, NULL);
            check(r == FOV_OK && fabs((double)rgb[0] - want) <= 1e-5 && rgb[1] == rgb[0] && rgb[2] == rgb[0], nm,
                  "%s, rgb (%.6f %.6f %.6f), want %.6f", rname(r), (double)rgb[0], (double)rgb[1], (double)rgb[2], want);
        }
    }
}

/* A unit sphere rendered head on: hit mask and depth against the analytic pixel rays, and
   the 8-bit output against an independent sRGB encoding. */
static double srgb_ref(double x)
{
    if (!(x > 0.0)) return 0.0;
    if (x >= 1.0) return 1.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

static void test_render_sphere(void)
{
    const uint32_t W = 96, H = 54;
    const double T = tan(25.0 * 3.14159265358979323846 / 180.0), A = (double)W / (double)H;
    imgbuf ib;
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fovsdf_output o;
    fov_result r;
    uint32_t x, y;
    unsigned long mask_bad = 0, dep_bad = 0, mat_bad = 0, s8_bad = 0, considered = 0;
    double worst_dt = 0.0;
    int worst8 = 0;
    ib_alloc(&ib, W, H);
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    cam_at(&cam, W, H, 0.0f, 0.0f, -4.0f, 0.0f, 0.0f, 0.0f);
    cam.fov_y_deg = 50.0f;
    cfg.eps_mode = FOVSDF_EPS_ABSOLUTE;
    cfg.eps = 1e-4f;
    cfg.t_max = 20.0f;
    r = fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(48.0f, 27.0f), NULL, 0);
    if (r == FOV_OK) { ib_out(&ib, &o); r = fovsdf_render_rows(&ctx, 0, H, &o, NULL); }
    expect_res("render_sphere_ok", r, FOV_OK);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            /* fwd +z, right -x, up +y */
            double su = (((double)x + 0.5) / W * 2.0 - 1.0) * T * A, sv = (((double)y + 0.5) / H * 2.0 - 1.0) * T;
            double d[3], l, b, cc, disc, te, closest;
            size_t i = (size_t)y * W + x, c;
            d[0] = -su; d[1] = -sv; d[2] = 1.0;
            l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            d[0] /= l; d[1] /= l; d[2] /= l;
            b = -4.0 * d[2]; /* o . d with o = (0, 0, -4) */
            cc = 16.0 - 1.0;
            disc = b * b - cc;
            closest = sqrt(dmax(0.0, 16.0 - b * b)); /* distance of the ray from the centre */
            if (fabs(closest - 1.0) < 2e-3) continue; /* silhouette pixels: either answer is fine */
            ++considered;
            te = disc > 0.0 ? -b - sqrt(disc) : -1.0;
            if ((te > 0.0) != (ib.hit[i] == 1)) ++mask_bad;
            if (te > 0.0) {
                worst_dt = dmax(worst_dt, fabs((double)ib.depth[i] - te));
                if (fabs((double)ib.depth[i] - te) > 1e-3) ++dep_bad;
                if (ib.mat[i] != 0) ++mat_bad;
            } else {
                if (ib.depth[i] != 20.0f) ++dep_bad;
                if (ib.mat[i] != -1) ++mat_bad;
            }
            for (c = 0; c < 3; ++c) {
                int want = (int)floor(srgb_ref((double)ib.rgb[3 * i + c]) * 255.0 + 0.5), got = ib.rgb8[3 * i + c];
                if (abs(want - got) > abs(worst8)) worst8 = got - want;
                if (abs(want - got) > 1) ++s8_bad;
            }
        }
    check(mask_bad == 0, "render_sphere_hit_mask_analytic", "%lu of %lu pixels disagree with the analytic ray test",
          mask_bad, considered);
    check(dep_bad == 0, "render_sphere_depth_analytic", "%lu pixels off by more than 1e-3 (worst hit |dt| %.3g)", dep_bad,
          worst_dt);
    check(mat_bad == 0, "render_sphere_material_0_hit_minus1_miss", "%lu pixels with a wrong material id", mat_bad);
    check(s8_bad == 0, "render_rgb8_is_srgb_of_rgb", "%lu channels off by more than 1 (worst %+d)", s8_bad, worst8);
    ib_free(&ib);
}

/* The mandelbulb's and the terrain's own float kernels (every build) against libm in double,
   over dense samples: errors in ulps of the exact value (sin and cos: where it is at least
   2^-10 in magnitude, an absolute error below 2^-32 under that), the bounds the header
   documents. */
static double kulp(double v) /* the ulp of the float nearest v */
{
    int e;
    v = fabs(v);
    if (v < 1.17549435e-38) return ldexp(1.0, -149);
    (void)frexp(v, &e);
    return ldexp(1.0, e - 24);
}
typedef struct ksc_err { double ulp, abs; float at; } ksc_err;
static void ksc_acc(ksc_err *e, double got, double want, float x)
{
    if (fabs(want) >= 1.0 / 1024.0) {
        double u = fabs(got - want) / kulp(want);
        if (u > e->ulp) { e->ulp = u; e->at = x; }
    } else if (fabs(got - want) > e->abs) {
        e->abs = fabs(got - want);
    }
}
static void ksc_check(const ksc_err *e, const char *name)
{
    check(e->ulp <= 4.0 && e->abs <= ldexp(1.0, -32), name,
          "%.2f ulp (at %.9g), absolute %.3g near zeros", e->ulp, (double)e->at, e->abs);
}
static void test_prim_kernels(void)
{
    ksc_err e1, e2, e3, e4, e5;
    uint32_t u, n;
    double w;
    float x, s, c, xs[4];
    memset(&e1, 0, sizeof e1); e2 = e3 = e4 = e5 = e1;
    /* every 29th float in [0, 8192): sin (the terrain's and the mandelbulb's) and cos */
    for (u = 0; u < 0x46000000u; u += 29u) {
        memcpy(&x, &u, 4);
        ksc_acc(&e1, (double)fovtest_sdf_ksin(x), sin((double)x), x);
        ksc_acc(&e1, (double)fovtest_sdf_ksin(-x), sin(-(double)x), -x);
        ksc_acc(&e2, (double)fovtest_sdf_kcos(x), cos((double)x), x);
        ksc_acc(&e2, (double)fovtest_sdf_kcos(-x), cos(-(double)x), -x);
    }
    ksc_check(&e1, "kernel_sin_below_8192");
    ksc_check(&e2, "kernel_cos_below_8192");
    /* [8192, 1e6): the wide reduction; every float there with a stride */
    for (u = 0x46000000u; u < 0x49742400u; u += 17u) {
        memcpy(&x, &u, 4);
        fovtest_sdf_ksincos_w(x, &s, &c);
        ksc_acc(&e3, (double)s, sin((double)x), x);
        ksc_acc(&e3, (double)c, cos((double)x), x);
        ksc_acc(&e3, (double)fovtest_sdf_ksin1(-x), sin(-(double)x), -x);
    }
    ksc_check(&e3, "kernel_sincos_wide_8192_to_1e6");
    /* 1e6 to FLT_MAX: Payne-Hanek (fovsdf__ksin1), the 1e30 cutoff included */
    for (u = 0x49742400u; u < 0x7f800000u; u += 2039u) {
        memcpy(&x, &u, 4);
        ksc_acc(&e4, (double)fovtest_sdf_ksin1(x), sin((double)x), x);
        ksc_acc(&e4, (double)fovtest_sdf_ksin1(-x), sin(-(double)x), -x);
    }
    for (n = 0; n < 100000u; ++n) { /* near 1e30 */
        x = 1e30f * (1.0f + (float)n * 1e-7f);
        ksc_acc(&e4, (double)fovtest_sdf_ksin1(x), sin((double)x), x);
    }
    ksc_check(&e4, "kernel_sin_beyond_1e6");
    /* the terrain's arguments: 12 octaves of rotation and 2.03 scaling from random points */
    xs[0] = 0.0f;
    for (n = 0; n < 100000u; ++n) {
        float fx = (float)(pow(10.0, -3.0 + 9.0 * (double)(n % 1000u) / 1000.0) *
                           sin(1.7 * (double)n)), fz = fx * 0.37f + (float)n * 1e-3f;
        int o;
        for (o = 0; o < 12; ++o) {
            float nx;
            if (!(fabsf(fx) < 1e30f && fabsf(fz) < 1e30f)) break;
            ksc_acc(&e5, (double)fovtest_sdf_ksin1(fx), sin((double)fx), fx);
            ksc_acc(&e5, (double)fovtest_sdf_ksin1(fz), sin((double)fz), fz);
            nx = (0.8f * fx - 0.6f * fz) * 2.03f;
            fz = (0.6f * fx + 0.8f * fz) * 2.03f;
            fx = nx;
        }
    }
    ksc_check(&e5, "kernel_sin_terrain_octaves");
    {   /* inf and NaN: NaN, no trap */
        float inf = FLT_MAX * (xs[0] + 2.0f), nan = inf - inf;
        s = fovtest_sdf_ksin(inf);
        c = fovtest_sdf_kcos(nan);
        check(s != s && c != c && fovtest_sdf_ksin(-inf) != fovtest_sdf_ksin(-inf) &&
                  fovtest_sdf_ksin1(nan) != fovtest_sdf_ksin1(nan) && fovtest_sdf_ksin1(inf) != fovtest_sdf_ksin1(inf),
              "kernel_sin_inf_nan_is_nan", "sin(inf) %g cos(inf) %g", (double)s, (double)c);
        check(fovtest_sdf_katan2(nan, 1.0f) != fovtest_sdf_katan2(nan, 1.0f) &&
                  fovtest_sdf_klog(nan) != fovtest_sdf_klog(nan) && fovtest_sdf_klog(-1.0f) != fovtest_sdf_klog(-1.0f) &&
                  fovtest_sdf_klog(inf) == inf && fovtest_sdf_klog(0.0f) == -inf && fovtest_sdf_klog(-0.0f) == -inf,
              "kernel_atan2_log_special", "log(inf) %g log(0) %g", (double)fovtest_sdf_klog(inf),
              (double)fovtest_sdf_klog(0.0f));
        {   /* atan2's zeros and infinities as C99's atan2 */
            static const float v[] = { 0.0f, -0.0f, 1.0f, -1.0f, 3e38f, -3e38f, 1e-40f, -1e-40f };
            uint32_t i, j, bad = 0;
            float vv[10];
            for (i = 0; i < 8; ++i) vv[i] = v[i];
            vv[8] = inf; vv[9] = -inf;
            for (i = 0; i < 10; ++i)
                for (j = 0; j < 10; ++j) {
                    double want = atan2((double)vv[i], (double)vv[j]);
                    float got = fovtest_sdf_katan2(vv[i], vv[j]);
                    uint32_t gb, wb;
                    float wf = (float)want;
                    memcpy(&gb, &got, 4); memcpy(&wb, &wf, 4);
                    if (fabs((double)got - want) > 3.0 * kulp(want) || (gb >> 31) != (wb >> 31))
                        ++bad;
                }
            check(bad == 0, "kernel_atan2_zeros_infinities", "%u of 100 pairs", bad);
        }
    }
    /* atan2 over dense (y, x) pairs of every sign and ratio */
    w = 0.0;
    for (n = 0; n < 1000000u; ++n) {
        float yy = (float)(((n * 2654435761u) >> 8) & 0xffffffu) / 16777216.0f * 8.0f - 4.0f;
        float xx = (float)((n * 40503u + 12345u) % 1000003u) / 1000003.0f * 8.0f - 4.0f;
        double want;
        if (n % 4 == 1) yy *= 1e-6f;
        if (n % 4 == 2) xx *= 1e-6f;
        want = atan2((double)yy, (double)xx);
        if (want != 0.0) w = dmax(w, fabs((double)fovtest_sdf_katan2(yy, xx) - want) / kulp(want));
    }
    check(w <= 3.0, "kernel_atan2_3ulp", "%.2f ulp", w);
    /* log: every 127th positive float, subnormals included */
    w = 0.0;
    for (u = 1; u < 0x7f800000u; u += 127u) {
        double want;
        memcpy(&x, &u, 4);
        want = log((double)x);
        if (want != 0.0) w = dmax(w, fabs((double)fovtest_sdf_klog(x) - want) / kulp(want));
    }
    check(w <= 1.0, "kernel_log_1ulp", "%.2f ulp", w);
    /* pow: x in [1e-20, 1e4], y in [-16, 16] (the mandelbulb's power - 1 is in [1, 15]) */
    w = 0.0;
    for (n = 0; n < 1000000u; ++n) {
        float px = (float)pow(10.0, -20.0 + 24.0 * (double)((n * 2654435761u) >> 8) / 16777216.0);
        float py = (float)((n * 40503u) % 65521u) / 65521.0f * 32.0f - 16.0f;
        double want;
        if (n % 3 == 0) py = 1.0f + (float)(n % 15u) + (float)(n % 7u) * 0.125f;
        want = pow((double)px, (double)py);
        if (want < 1.17549435e-38 || want > 3.4e38) continue;
        w = dmax(w, fabs((double)fovtest_sdf_kpow(px, py) - want) / kulp(want));
    }
    check(w <= 3.0, "kernel_pow_3ulp", "%.2f ulp", w);
}

#ifdef FOV_NO_LIBM
/* The built-in float approximations against libm (double). */
static void test_nolibm_math(void)
{
    double w;
    int i;
    float x;
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        double rf;
        x = (float)pow(10.0, -30.0 + 60.0 * i / 100000.0);
        rf = sqrt((double)x);
        w = dmax(w, fabs((double)fovtest_sqrtf(x) - rf) / rf);
    }
    check(w <= 1e-6, "nolibm_sqrt_rel_1e-6", "max relative error %.3g on [1e-30, 1e30]", w);
    if (fovtest_sqrt_hw() != 0) {
        /* FOV__SQRT_HW, the target's square root instruction: libm's correctly rounded value,
           bit for bit, on every 997th float bit pattern (subnormals, infinities and NaNs
           included) */
        uint32_t u, bad = 0, first = 0;
        for (u = 0; u < 0xFFFFFFFFu - 997u; u += 997u) {
            float xs, a, b;
            uint32_t ua, ub;
            memcpy(&xs, &u, 4);
            a = fovtest_sqrtf(xs);
            b = sqrtf(xs);
            memcpy(&ua, &a, 4);
            memcpy(&ub, &b, 4);
            if (ua != ub && !(isnan(a) && isnan(b))) { if (!bad) first = u; bad++; }
        }
        check(bad == 0, "nolibm_sqrt_hw_exact", "%u bit patterns differ from sqrtf (first 0x%08x); FOV__SQRT_HW %d",
              (unsigned)bad, (unsigned)first, fovtest_sqrt_hw());
    }
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        x = (float)(-20.0 + 40.0 * i / 100000.0);
        w = dmax(w, fabs((double)fovtest_sinf(x) - sin((double)x)));
        w = dmax(w, fabs((double)fovtest_cosf(x) - cos((double)x)));
    }
    check(w <= 1e-6, "nolibm_sin_cos_abs_1e-6", "max absolute error %.3g on [-20, 20]", w);
    w = 0.0;
    for (i = 1; i < 100000; ++i) {
        double t;
        x = (float)(1.55 * i / 100000.0);
        t = tan((double)x);
        w = dmax(w, fabs((double)(fovtest_sinf(x) / fovtest_cosf(x)) - t) / t);
    }
    check(w <= 1e-6, "nolibm_tan_rel_1e-6", "max relative error %.3g on (0, 1.55]", w);
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        double a = 2.0 * 3.14159265358979323846 * i / 100000.0;
        float yy = (float)(sin(a) * (1 + i % 7)), xx = (float)(cos(a) * (1 + i % 7));
        w = dmax(w, fabs((double)fovtest_atan2f(yy, xx) - atan2((double)yy, (double)xx)));
    }
    check(w <= 1e-6, "nolibm_atan2_abs_1e-6", "max absolute error %.3g rad over the circle", w);
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        double rf;
        x = (float)(-80.0 + 160.0 * i / 100000.0);
        rf = exp((double)x);
        w = dmax(w, fabs((double)fovtest_expf(x) - rf) / rf);
    }
    check(w <= 1e-6, "nolibm_exp_rel_1e-6", "max relative error %.3g on [-80, 80]", w);
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        double rf;
        x = (float)pow(10.0, -30.0 + 60.0 * i / 100000.0);
        rf = log((double)x);
        w = dmax(w, fabs((double)fovtest_logf(x) - rf) / dmax(1.0, fabs(rf)));
    }
    check(w <= 1e-6, "nolibm_log_1e-6", "max error / max(1, |log x|) %.3g on [1e-30, 1e30]", w);
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        double rf;
        x = (float)(0.003 + 0.997 * i / 100000.0);
        rf = pow((double)x, (double)(1.0f / 2.4f));
        w = dmax(w, fabs((double)fovtest_powf(x, 1.0f / 2.4f) - rf) / rf);
    }
    check(w <= 1e-6, "nolibm_pow_srgb_rel_1e-6", "max relative error %.3g for x^(1/2.4), x in [0.003, 1]", w);
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        double rf;
        float yy = (float)(1 + i % 8);
        x = (float)(0.3 + 1.7 * i / 100000.0);
        rf = pow((double)x, (double)yy);
        w = dmax(w, fabs((double)fovtest_powf(x, yy) - rf) / rf);
    }
    /* exp(y log x) in float: the rounding of y log x alone costs |y log x| * 6e-8 */
    check(w <= 2e-6, "nolibm_pow_power_rel_2e-6", "max relative error %.3g for x^y, x in [0.3, 2], y in 1..8", w);
    w = 0.0;
    for (i = 0; i <= 100000; ++i) {
        x = (float)(-1e7 + 2e7 * i / 100000.0) + 0.37f;
        w = dmax(w, fabs((double)fovtest_floorf(x) - floor((double)x)));
        w = dmax(w, fabs((double)fovtest_floorf(-0.5f * x) - floor(-0.5 * (double)x)));
    }
    check(w == 0.0, "nolibm_floor_exact", "max error %.3g", w);
    check(fovtest_sqrtf(0.0f) == 0.0f && fovtest_sqrtf(-1.0f) != fovtest_sqrtf(-1.0f) && fovtest_expf(-200.0f) == 0.0f &&
              !fin(fovtest_expf(100.0f)) && fovtest_logf(0.0f) < -3e38f && fovtest_logf(-1.0f) != fovtest_logf(-1.0f) &&
              fovtest_floorf(-0.5f) == -1.0f && fovtest_atan2f(0.0f, 0.0f) == 0.0f && fovtest_powf(2.0f, 0.0f) == 1.0f,
          "nolibm_special_values", "sqrt(0) %g sqrt(-1) %g exp(-200) %g exp(100) %g log(0) %g log(-1) %g floor(-0.5) %g",
          (double)fovtest_sqrtf(0.0f), (double)fovtest_sqrtf(-1.0f), (double)fovtest_expf(-200.0f),
          (double)fovtest_expf(100.0f), (double)fovtest_logf(0.0f), (double)fovtest_logf(-1.0f),
          (double)fovtest_floorf(-0.5f));
}
#endif

/* ==== more checks of sections 1, 2 and 4 (exhaustion, t_start, extended callbacks, ranges) = */

/* An exhausted ray is "reported as FOVSDF_EXHAUSTED with the t reached, and shaded as hits
   there": that t must never lie past the first surface (a shading point inside or behind
   geometry). Sphere hit at t = 4.046 along a ray 0.3 off the centre, budgets 1..6 steps. */
static void test_exhausted_safe(void)
{
    tsdf u;
    fovsdf_scene sc;
    uint32_t m, s;
    const float ro[3] = { 0.0f, 0.3f, -5.0f }, rd[3] = { 0.0f, 0.0f, 1.0f };
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    for (m = 0; m < 4; ++m) {
        double te = ray_sphere(ro, rd, u.sc[0], 1.0f);
        uint32_t bad_steps = 0;
        float bad_t = 0.0f;
        int nbad = 0;
        for (s = 1; s <= 6; ++s) {
            fovsdf_march_params mp = mp_make(m, 1e-4f, 20.0f, s);
            fovsdf_hit h;
            (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
            if (h.kind == FOVSDF_MISS || (double)h.t > te + 1e-4) {
                if (!nbad++) { bad_steps = s; bad_t = h.t; }
            }
        }
        check(nbad == 0, N("exhausted_t_not_past_surface_%s", g_mname[m]),
              "%d of 6 step budgets report a t past the surface at %.5f; first: max_steps %u gives t %.5f", nbad, te,
              bad_steps, (double)bad_t);
    }
}

/* t_start beyond t_max: "rays beyond it miss" (or the call may reject the input); every
   method must agree. Negative SDF everywhere, t_start 30, t_max 20. */
static void test_t_start_beyond_t_max(void)
{
    tsdf u;
    fovsdf_scene sc;
    uint32_t m;
    const float ro[3] = { 0.0f, 0.0f, 0.0f }, rd[3] = { 0.0f, 0.0f, 1.0f };
    memset(&u, 0, sizeof u);
    u.kind = K_NEG;
    scene_for(&sc, &u);
    for (m = 0; m < 4; ++m) {
        fovsdf_march_params mp = mp_make(m, 1e-4f, 20.0f, 64);
        fovsdf_hit h;
        fov_result r;
        memset(&h, 0, sizeof h);
        r = fovsdf_march(&sc, &mp, ro, rd, 30.0f, &h, NULL);
        check(r == FOV_ERR_INVALID_ARG || (r == FOV_OK && h.kind == FOVSDF_MISS && h.t == 20.0f),
              N("t_start_beyond_t_max_misses_%s", g_mname[m]),
              "%s, %s at t %g (t_start 30 > t_max 20: want MISS at t_max, as classic reports, or INVALID_ARG)", rname(r),
              kind_name(h.kind), (double)h.t);
    }
}

/* Extended callbacks: used instead of dist, material and primitive counts reported. */
typedef struct exuser {
    tsdf s;
    unsigned long calls, bad_inflate, want_mat;
} exuser;

static float ex_dist(const float p[3], fovsdf_query *q, void *user)
{
    exuser *e = (exuser *)user;
    e->calls++;
    if (!q || q->inflate != 1.0f) e->bad_inflate++;
    if (q) {
        e->want_mat += q->want_material != 0;
        q->material = 7;
        q->prims += 2;
        q->prims_skipped += 1;
    }
    return sph_dist(&e->s, p);
}

static float far_dist(const float p[3], void *user)
{
    (void)p;
    (void)user;
    return 1000.0f;
}

static void test_dist_ex(void)
{
    const uint32_t W = 48, H = 27;
    exuser e;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_output o;
    fovsdf_stats st;
    imgbuf ib;
    fov_result r;
    size_t i, nhit = 0, matbad = 0;
    memset(&e, 0, sizeof e);
    tsdf_sphere(&e.s, 0.0f, 0.0f, 0.0f, 1.0f);
    fovsdf_scene_init(&sc);
    sc.dist = far_dist; /* must be ignored: dist_ex wins */
    sc.dist_ex = ex_dist;
    sc.user = &e;
    cam_at(&cam, W, H, 0.0f, 0.0f, -4.0f, 0.0f, 0.0f, 0.0f);
    ib_alloc(&ib, W, H);
    r = fovsdf_init(&ctx, NULL, &sc, &cam, gaze_at(24.0f, 13.5f), NULL, 0);
    memset(&st, 0, sizeof st);
    if (r == FOV_OK) {
        e.calls = 0;
        ib_out(&ib, &o);
        r = fovsdf_render_rows(&ctx, 0, H, &o, &st);
    }
    for (i = 0; i < (size_t)W * H; ++i) {
        nhit += ib.hit[i];
        matbad += ib.hit[i] ? ib.mat[i] != 7 : ib.mat[i] != -1;
    }
    check(r == FOV_OK && nhit > 0 && matbad == 0, "dist_ex_used_and_material_reported",
          "%s, %lu hit pixels, %lu pixels with a material other than 7 (hit) / -1 (miss)", rname(r), (unsigned long)nhit,
          (unsigned long)matbad);
    check(e.bad_inflate == 0 && e.calls == st.evals, "dist_ex_query_inflate_1_and_counted",
          "%lu calls with inflate != 1; %lu calls, stats.evals %lu", e.bad_inflate, e.calls, (unsigned long)st.evals);
    check(st.prims == 2 * st.evals && st.prims_skipped == st.evals, "dist_ex_prims_accumulated",
          "stats.prims %lu (want 2 x %lu), prims_skipped %lu", (unsigned long)st.prims, (unsigned long)st.evals,
          (unsigned long)st.prims_skipped);
    ib_free(&ib);
}

/* Further range checks of the config, scene and display. */
static void test_more_ranges(void)
{
    base_t b;
    fovsdf_config cfg;
    fovsdf_scene sc;
    fov_ecc_model m;
    fov_display d;
    fov_result r;
    base_init(&b);
    cfg = b.cfg; cfg.shadow_steps = FOVSDF_MAX_STEPS + 1u;
    expect_res("config_shadow_steps_above_cap", init_cfg(&b, &cfg), FOV_ERR_LIMIT);
    cfg = b.cfg; cfg.bv_relax = 1.5f;
    expect_res("config_bv_relax_above_1", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.eps_px = -0.25f;
    expect_res("config_negative_eps_px", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.ar_beta = -0.5f;
    expect_res("config_negative_ar_beta", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    cfg = b.cfg; cfg.display.distance_mm = -500.0f;
    expect_res("config_display_negative_distance", init_cfg(&b, &cfg), FOV_ERR_INVALID_ARG);
    sc = b.sc; sc.lights[0].type = (uint32_t)_FOVSDF_LIGHT_NUM;
    expect_res("scene_unknown_light_type", init_scene(&b, &sc), FOV_ERR_INVALID_ARG);
    sc = b.sc; sc.lights[0].range = -1.0f;
    expect_res("scene_light_negative_range", init_scene(&b, &sc), FOV_ERR_INVALID_ARG);
    sc = b.sc; sc.t_max = -1.0f;
    expect_res("scene_negative_t_max", init_scene(&b, &sc), FOV_ERR_INVALID_ARG);
    sc = b.sc; sc.ambient[2] = f_nan();
    expect_res("scene_nan_ambient", init_scene(&b, &sc), FOV_ERR_NOT_FINITE);
    sc = b.sc; sc.lipschitz = f_inf();
    expect_res("scene_inf_lipschitz", init_scene(&b, &sc), FOV_ERR_NOT_FINITE);
    memset(&d, 0, sizeof d);
    d.fov_y_deg = -10.0f;
    expect_res("ecc_display_negative_fov", fovsdf_ecc_init(&m, &d, 60.0f, 64, 36, b.gaze), FOV_ERR_INVALID_ARG);
    memset(&d, 0, sizeof d);
    expect_res("ecc_zero_display_bad_camera_fov", fovsdf_ecc_init(&m, &d, 180.0f, 64, 36, b.gaze), FOV_ERR_INVALID_ARG);
    /* a monitor given only half its geometry is neither "a monitor" nor "all zero" (fov_display):
       it must not silently fall back to the camera's field of view */
    memset(&d, 0, sizeof d);
    d.pixel_pitch_mm = 0.3f;
    r = fovsdf_ecc_init(&m, &d, 60.0f, 64, 36, b.gaze);
    check(r == FOV_ERR_INVALID_ARG || r == FOV_ERR_DEGENERATE, "ecc_display_pitch_without_distance_rejected",
          "got %s: pitch 0.3 mm with distance 0 is accepted (f = %g px, the camera fov's %g)", rname(r), (double)m.f_px,
          18.0 / tan(30.0 * 3.14159265358979323846 / 180.0));
    memset(&d, 0, sizeof d);
    d.distance_mm = 500.0f;
    r = fovsdf_ecc_init(&m, &d, 60.0f, 64, 36, b.gaze);
    check(r == FOV_ERR_INVALID_ARG || r == FOV_ERR_DEGENERATE, "ecc_display_distance_without_pitch_rejected",
          "got %s: distance 500 mm with pitch 0 is accepted (f = %g px)", rname(r), (double)m.f_px);
}

/* ==== main ================================================================================ */
/* Build with -DTEST_FOVSDF_SECTION_COUNTS to get the number of checks per section on
   stderr (the normal output is only the check lines and the summary). */

/* ==== 6. cheaper shadow rays beyond an eccentricity (config.shadow_fov_deg) ================ */

typedef struct msgrec {
    int calls;
    int32_t code;
    char msg[256];
} msgrec;
static void msg_logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    msgrec *r = (msgrec *)user;
    (void)tag; (void)level; (void)line;
    r->calls++;
    r->code = code;
    snprintf(r->msg, sizeof r->msg, "%s", msg ? msg : "");
}

/* bad values: the code, and a message naming the field */
static void test_shadow_fov_config(void)
{
    static const struct { const char *name, *field; int which; float v; fov_result want; } bad[] = {
        { "deg_negative", "shadow_fov_deg", 0, -1.0f, FOV_ERR_INVALID_ARG },
        { "deg_above_180", "shadow_fov_deg", 0, 180.5f, FOV_ERR_INVALID_ARG },
        { "deg_nan", "shadow_fov_deg", 0, 0.0f, FOV_ERR_NOT_FINITE },
        { "deg_inf", "shadow_fov_deg", 0, 1.0f, FOV_ERR_NOT_FINITE },
        { "steps_above_shadow_steps", "shadow_fov_steps", 1, 65.0f, FOV_ERR_INVALID_ARG },
        { "t0_px_negative", "shadow_fov_t0_px", 2, -0.5f, FOV_ERR_INVALID_ARG },
        { "t0_px_above_1e6", "shadow_fov_t0_px", 2, 2e6f, FOV_ERR_INVALID_ARG },
        { "t0_px_nan", "shadow_fov_t0_px", 2, 0.0f, FOV_ERR_NOT_FINITE },
        { "t0_px_inf", "shadow_fov_t0_px", 2, 1.0f, FOV_ERR_NOT_FINITE },
    };
    unsigned i;
    fovsdf_config z, c, o;
    memset(&z, 0, sizeof z);
    expect_res("shadow_fov_resolve_zero", fovsdf_config_resolve(&z, &c), FOV_OK);
    check(c.shadow_fov_deg == 0.0f && c.shadow_fov_steps == 0u && c.shadow_fov_t0_px == 4.0f,
          "shadow_fov_defaults_documented", "deg %g steps %u t0_px %g", (double)c.shadow_fov_deg,
          c.shadow_fov_steps, (double)c.shadow_fov_t0_px);
    /* a default config with fewer shadow steps stays valid (shadow_fov_steps 0: shadow_steps) */
    z = fovsdf_config_default();
    z.shadow_steps = 8;
    expect_res("shadow_fov_resolve_small_budget", fovsdf_config_resolve(&z, &c), FOV_OK);
    check(c.shadow_fov_steps == 0u, "shadow_fov_steps_kept_0", "%u", c.shadow_fov_steps);
    z = fovsdf_config_default();
    z.shadow_fov_deg = 180.0f; z.shadow_fov_steps = 64; z.shadow_fov_t0_px = 1e6f;
    expect_res("shadow_fov_resolve_edges_ok", fovsdf_config_resolve(&z, &c), FOV_OK);
    for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        msgrec lr;
        fov_result r;
        float v = bad[i].v;
        if (bad[i].want == FOV_ERR_NOT_FINITE) v = bad[i].v > 0.0f ? f_inf() : f_nan();
        c = fovsdf_config_default();
        memset(&lr, 0, sizeof lr);
        c.logger.func = msg_logger;
        c.logger.user = &lr;
        if (bad[i].which == 0) c.shadow_fov_deg = v;
        else if (bad[i].which == 1) c.shadow_fov_steps = (uint32_t)v;
        else c.shadow_fov_t0_px = v;
        o = c;
        r = fovsdf_config_resolve(&c, &o);
        check(r == bad[i].want && lr.calls >= 1 && strstr(lr.msg, bad[i].field) != NULL,
              N("shadow_fov_rejects_%s", bad[i].name), "got %s, want %s, message \"%s\"", rname(r),
              rname(bad[i].want), lr.msg);
    }
}

/* The eccentricity test of the shaded rays against fovsdf_ecc_deg, with an off-centre gaze
   and a display other than the camera (its own field of view, an axis offset). */
static void test_shadow_fov_ecc(void)
{
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    tsdf u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    uint32_t k, bad = 0, nfar = 0, nnear = 0;
    static const float degs[4] = { 2.0f, 7.5f, 20.0f, 100.0f };
    tsdf_sphere(&u, 0.0f, 0.0f, 0.0f, 1.0f);
    scene_for(&sc, &u);
    cam_at(&cam, 160, 90, 0.3f, 0.2f, -5.0f, 0.0f, 0.1f, 0.0f);
    cam.fov_y_deg = 70.0f;
    cfg.display.fov_y_deg = 40.0f;
    cfg.display.axis_dx = 12.0f;
    cfg.display.axis_dy = -7.0f;
    for (k = 0; k < 4; ++k) {
        uint32_t x, y;
        cfg.shadow_fov_deg = degs[k];
        if (fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(101.0f, 30.0f), NULL, 0) != FOV_OK) {
            check(0, N("shadow_fov_ecc_init_%u", k), "-");
            continue;
        }
        for (y = 0; y < 90; ++y)
            for (x = 0; x < 160; ++x) {
                float ro[3], rd[3], px = (float)x + 0.25f, py = (float)y + 0.75f;
                float e = fovsdf_ecc_deg(&ctx.ecc, px, py);
                int far;
                fovtest_sdf_ray(&ctx, px, py, ro, rd);
                far = fovtest_sdf_shadow_far(&ctx, rd);
                if (fabsf(e - degs[k]) < 0.05f) continue; /* rounding at the boundary */
                if (far != (e > degs[k])) ++bad;
                if (far) ++nfar; else ++nnear;
            }
    }
    check(bad == 0 && nfar > 1000 && nnear > 1000, "shadow_fov_ecc_matches_ecc_deg",
          "%u mismatches (%u far, %u near)", bad, nfar, nnear);
    cfg.shadow_fov_deg = 0.0f;
    fovsdf_init(&ctx, &cfg, &sc, &cam, gaze_at(101.0f, 30.0f), NULL, 0);
    {
        float rd[3] = { 0.0f, 0.0f, -1.0f };
        check(fovtest_sdf_shadow_far(&ctx, rd) == 0, "shadow_fov_off_never_far", "-");
    }
}

/* Off: the shadow_fov fields do nothing (every image and counter as without them); on: the
   fovea's pixels are the off image's bit for bit, fewer shadow evaluations, finite images. */
static void test_shadow_fov_render(void)
{
    enum { SW = 128, SH = 72 };
    static float a[SW * SH * 3], b[SW * SH * 3], d1[SW * SH], d2[SW * SH];
    static uint32_t e1[SW * SH], e2[SW * SH];
    static unsigned char mem[1 << 20];
    static const uint32_t scenes[3] = { FOVSDF_SCENE_PRIMITIVES, FOVSDF_SCENE_COLUMNS, FOVSDF_SCENE_TEMPLE };
    static const uint32_t methods[5] = { FOVSDF_METHOD_CLASSIC, FOVSDF_METHOD_CONE, FOVSDF_METHOD_SKIP,
                                         FOVSDF_METHOD_FIPR, FOVSDF_METHOD_CONE_FOV };
    uint32_t si, mi;
    for (si = 0; si < 3; ++si)
        for (mi = 0; mi < 5; ++mi) {
            fovsdf_builtin bi;
            fovsdf_camera cam;
            fovsdf_config cfg;
            fovsdf_ctx ctx;
            fovsdf_output o;
            fovsdf_stats s0, s1;
            fov_gaze g;
            uint32_t i, inner = 0, nin = 0, ndiff = 0, nbad = 0, v;
            const char *tag;
            if (fovsdf_builtin_init(scenes[si], &bi, mem, sizeof mem) != FOV_OK) {
                check(0, N("shadow_fov_builtin_%u", scenes[si]), "-");
                continue;
            }
            tag = bi.name;
            cam = bi.camera; cam.width = SW; cam.height = SH;
            g = gaze_at(0.4f * (float)SW, 0.55f * (float)SH);
            cfg = fovsdf_config_default();
            cfg.method = methods[mi];
            cfg.quarter_deg = mi == 4 ? 12.0f : 0.0f; /* CONE_FOV's quarter level too */
            for (v = 0; v < 3; ++v) { /* off: 0 default fields, 1 the other fields set, 2 180 deg */
                fovsdf_config c2 = cfg;
                float *img = v == 0 ? a : b;
                if (v >= 1) { c2.shadow_fov_steps = 4; c2.shadow_fov_t0_px = 30.0f; }
                if (v == 2) c2.shadow_fov_deg = 180.0f;
                fovsdf_init(&ctx, &c2, &bi.scene, &cam, g, NULL, 0);
                fovsdf_output_init(&o);
                o.rgb = img; o.depth = v == 0 ? d1 : d2; o.evals = v == 0 ? e1 : e2;
                fovsdf_stats_init(v == 0 ? &s0 : &s1);
                fovsdf_render_rows(&ctx, 0, SH, &o, v == 0 ? &s0 : &s1);
                if (v >= 1)
                    check(memcmp(a, b, sizeof a) == 0 && memcmp(d1, d2, sizeof d1) == 0 &&
                              memcmp(e1, e2, sizeof e1) == 0 && memcmp(&s0, &s1, sizeof s0) == 0,
                          N("shadow_fov_%s_%s_off_%s_unchanged", tag, fovsdf_method_name(cfg.method),
                            v == 1 ? "fields" : "180"),
                          "images or counters differ");
            }
            /* on: 8 degrees, the default start (4 pixel footprints), or a small budget too */
            cfg.shadow_fov_deg = 8.0f;
            if (si == 1) cfg.shadow_fov_steps = 8;
            fovsdf_init(&ctx, &cfg, &bi.scene, &cam, g, NULL, 0);
            fovsdf_output_init(&o);
            o.rgb = b;
            fovsdf_stats_init(&s1);
            fovsdf_render_rows(&ctx, 0, SH, &o, &s1);
            for (i = 0; i < SW * SH; ++i) {
                /* the pixel's samples and the level samples that reach it (a quarter-level cell
                   spans 4 pixels: ~3 degrees here) stay inside the threshold */
                float e = fovsdf_ecc_deg(&ctx.ecc, (float)(i % SW) + 0.5f, (float)(i / SW) + 0.5f);
                int same = memcmp(a + 3 * i, b + 3 * i, 12) == 0;
                uint32_t k;
                for (k = 0; k < 3; ++k)
                    if (!(b[3 * i + k] >= 0.0f && b[3 * i + k] <= 1e4f)) ++nbad;
                if (e < 8.0f - 3.5f) { ++nin; if (!same) ++inner; }
                else if (!same) ++ndiff;
            }
            check(nin > 20 && inner == 0, N("shadow_fov_%s_%s_fovea_unchanged", tag, fovsdf_method_name(cfg.method)),
                  "%u of %u fovea pixels differ", inner, nin);
            check(s1.evals_shadow < s0.evals_shadow,
                  N("shadow_fov_%s_%s_fewer_shadow_evals", tag, fovsdf_method_name(cfg.method)),
                  "%llu vs %llu (off)", (unsigned long long)s1.evals_shadow, (unsigned long long)s0.evals_shadow);
            check(nbad == 0 && ndiff > 0, N("shadow_fov_%s_%s_finite_changed", tag, fovsdf_method_name(cfg.method)),
                  "%u bad values, %u periphery pixels changed", nbad, ndiff);
        }
}

#ifdef TEST_FOVSDF_SECTION_COUNTS
#define T_SECTION(name)                                                                          \
    do {                                                                                         \
        fprintf(stderr, "section %-28s %d checks\n", name, g_pass + g_fail - g_sec_last);       \
        g_sec_last = g_pass + g_fail;                                                            \
    } while (0)
static int g_sec_last;
#else
#define T_SECTION(name) ((void)0)
#endif

int main(void)
{
    /* 1. API and bad input */
    test_null_pointers();
    test_sizes();
    test_not_finite();
    test_ranges();
    test_more_ranges();
    test_strings_and_defaults();
    test_logger_codes();
    test_api_semantics();
    test_bad_sdfs();
    T_SECTION("1 api_bad_input");
    /* 2. tracers */
    test_sphere_rays();
    test_plane_rays();
    test_miss_inside_tmax();
    test_eval_counts();
    test_relaxation_gain();
    test_thresholds();
    test_param_variants();
    test_exhausted_safe();
    test_t_start_beyond_t_max();
    T_SECTION("2 tracers");
    /* 3. shading and eccentricity */
    test_normals();
    test_soft_shadows();
    test_shade();
    test_shading_modes();
    test_ecc_basic();
    test_table41();
    test_ecc_shape();
    T_SECTION("3 shading_eccentricity");
    /* 4. rendering */
    test_camera_rays();
    test_supersampling();
    test_partition("render_primitives_classic_spp1", FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_CLASSIC, 1);
    test_partition("render_columns_autorelaxed_spp4", FOVSDF_SCENE_COLUMNS, FOVSDF_METHOD_AUTORELAXED, 4);
    test_builtin_sweep();
    test_render_sphere();
    test_dist_ex();
    T_SECTION("4 rendering");
    /* 6. cheaper shadow rays beyond an eccentricity */
    test_shadow_fov_config();
    test_shadow_fov_ecc();
    test_shadow_fov_render();
    T_SECTION("6 shadow_fov");
    /* 7. the mandelbulb's and the terrain's own float kernels against libm */
    test_prim_kernels();
    T_SECTION("7 prim_kernels");
#ifdef FOV_NO_LIBM
    /* 5. the FOV_NO_LIBM math approximations against libm */
    test_nolibm_math();
    T_SECTION("5 nolibm_math");
#endif
    return fovcheck_summary();
}
