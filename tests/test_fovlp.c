/* tests/test_fovlp.c - unit and property tests of fovlp.h (mappings, sizes, presets, the
   thesis's ray counts, sampling, reconstruction, bad input). tests/test_fovlp_taa.c tests
   the temporal part. Built three ways by tests/run_all.sh (libm, FOV_NO_LIBM, sanitizers).
   fovsdf.h is compiled into the same program: the two headers coexist in one translation
   unit, and the eccentricity functions are compared.
   "The thesis": K. Andersson, T. Hansson, "Performance Optimizations for Foveated Real-Time
   Raytracing", master's thesis, Lund University, LU-CS-EX 2020-64, 2020; its equation,
   section and table numbers are cited. */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file; the private function
   tested here is called through the test hook's wrapper (tests/common/fov_priv_lp.h), which
   is compiled in this file when it holds the implementation */
#ifndef FOV_TEST_LINK_IMPL
#define FOV_IMPL
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fov_priv_lp.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fovcheck.h"

/* ---- helpers ----------------------------------------------------------------------------- */
typedef struct lp_env {
    fovlp_ctx ctx;
    void *mem;
    float *srgb, *sdep;
} lp_env;

static fov_result env_init(lp_env *e, const fovlp_config *cfg)
{
    size_t bytes = 0;
    fov_result r;
    memset(e, 0, sizeof *e);
    r = fovlp_memory_size(cfg, &bytes);
    if (r != FOV_OK) return r;
    e->mem = malloc(bytes);
    r = fovlp_init(&e->ctx, cfg, e->mem, bytes);
    if (r != FOV_OK) return r;
    e->srgb = (float *)calloc((size_t)e->ctx.geo.samples * 3u, sizeof(float));
    e->sdep = (float *)calloc((size_t)e->ctx.geo.samples, sizeof(float));
    return FOV_OK;
}
static void env_free(lp_env *e)
{
    free(e->mem);
    free(e->srgb);
    free(e->sdep);
    memset(e, 0, sizeof *e);
}

static uint32_t rng_state = 12345u;
static float frand(void) /* [0, 1) */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (float)(rng_state >> 8) / 16777216.0f;
}

/* a smooth test image: colour of screen point (x, y) */
typedef struct smooth_img {
    float fx, fy;
} smooth_img;
static void smooth_val(float x, float y, const smooth_img *s, float rgb[3])
{
    rgb[0] = 0.5f + 0.25f * sinf(x * s->fx) + 0.2f * cosf(y * s->fy);
    rgb[1] = 0.5f + 0.3f * cosf((x + y) * s->fx * 0.7f);
    rgb[2] = 0.25f + 0.5f * (x + 2.0f * y) / 3000.0f;
}
static void shade_smooth(float x, float y, float rgb[3], float *depth, void *user)
{
    smooth_val(x, y, (const smooth_img *)user, rgb);
    if (depth) *depth = 10.0f + x * 0.001f;
}

static int log_calls;
static int32_t log_last_code;
static uint32_t log_last_level;
static void test_logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                        void *user)
{
    (void)msg; (void)line; (void)user;
    if (strcmp(tag, "fovlp") == 0) {
        log_calls++;
        log_last_code = code;
        log_last_level = level;
    }
}

/* ---- config, presets, sizes --------------------------------------------------------------- */
static void test_config(void)
{
    fovlp_config c = fovlp_config_default(), r, p;
    fovlp_geometry g;
    fov_gaze gz = { 960.0f, 540.0f };
    int i;
    check(fabsf(c.sigma - 1.4f) < 1e-6f && fabsf(c.alpha - 1.0f) < 1e-6f && fabsf(c.gaze_angle - 0.2f) < 1e-6f &&
              c.no_disc == 0 && fabsf(c.match_deg - 15.0f) < 1e-6f && c.taa.phases == 16 &&
              c.taa.halton_start == 1 && c.taa.max_age == 20 && fabsf(c.taa.periphery - 1.0f / 3.0f) < 1e-6f &&
              fabsf(c.blend_start - 1.0f / 6.0f) < 1e-6f,
          "config: defaults filled in (C Fov parameters, TAA 16 phases from index 1, age 20)", "sigma %g", (double)c.sigma);
    check(fovlp_config_resolve(&c, &r) == FOV_ERR_INVALID_ARG, "config: width 0 rejected", " ");
    {
        fovlp_config z;
        memset(&z, 0, sizeof z);
        z.width = 64; z.height = 48;
        check(fovlp_config_resolve(&z, &r) == FOV_OK && fabsf(r.sigma - 1.4f) < 1e-6f && fabsf(r.gaze_angle - 0.2f) < 1e-6f,
              "config: an all-zero config with a size resolves to the defaults", " ");
    }
    for (i = 0; i < 4; ++i) {
        static const float tab[4][4] = { { 0.75f, 1, 0, 1.2f }, { 1, 3, 0, 0.7f }, { 1.4f, 1, 0.2f, 0.33f }, { 1.3f, 2, 0.15f, 0.35f } };
        char name[96];
        p = fovlp_config_preset((uint32_t)i, 1920, 1080);
        snprintf(name, sizeof name, "presets: %s = Table 5.1 (sigma, alpha, a_G, lp_aspect)", fovlp_preset_name((uint32_t)i));
        check(fabsf(p.sigma - tab[i][0]) < 1e-6f && fabsf(p.alpha - tab[i][1]) < 1e-6f &&
                  fabsf(p.gaze_angle - tab[i][2]) < 1e-6f && fabsf(p.lp_aspect - tab[i][3]) < 1e-6f &&
                  p.no_disc == (tab[i][2] > 0.0f ? 0u : 1u),
              name, "%g %g %g %g", (double)p.sigma, (double)p.alpha, (double)p.gaze_angle, (double)p.lp_aspect);
    }
    check(strcmp(fovlp_preset_name(99), "unknown") == 0, "presets: unknown preset name", " ");
    /* eq. 3.6 sizes at 1920x1080 for the Table 5.1 presets, worked out by hand (Fov 2104x1753,
       K Fov 1205x1721, C Fov 591x1791, C K Fov 655x1872) and the C Fov disc (r_G 258, u_G 1533 with the thesis edge formula) */
    {
        static const uint32_t wh[4][2] = { { 2104, 1753 }, { 1205, 1721 }, { 591, 1791 }, { 655, 1872 } };
        int ok = 1;
        for (i = 0; i < 4; ++i) {
            p = fovlp_config_preset((uint32_t)i, 1920, 1080);
            if (fovlp_geometry_get(&p, gz, &g) != FOV_OK || g.lp_w != wh[i][0] || g.lp_h != wh[i][1]) {
                ok = 0;
                printf("  preset %d: %ux%u\n", i, g.lp_w, g.lp_h);
            }
        }
        check(ok, "sizes: eq. 3.6 LP buffer w x h of the four presets at 1920x1080", " ");
        p = fovlp_config_preset(FOVLP_PRESET_C_FOV, 1920, 1080);
        p.edge = FOVLP_EDGE_THESIS;
        fovlp_geometry_get(&p, gz, &g);
        check(fabsf(g.r_g - 257.8f) < 0.5f && fabsf(g.u_g - 1533.4f) < 2.0f && fabsf(g.L - 7.6975f) < 1e-3f,
              "sizes: C Fov r_G = 257.8 px, u_G = 1533.4, L = log(diag) = 7.6975 (eqs. 3.3-3.5, 3.10)",
              "r_G %g u_G %g L %g", (double)g.r_g, (double)g.u_g, (double)g.L);
        p.edge = FOVLP_EDGE_LOG_R;
        fovlp_geometry_get(&p, gz, &g);
        {
            /* with log r_G the LP buffer starts exactly at r_G: K(log r_G / L) w_C - u_G = 0 */
            float u0 = powf(logf(g.r_g) / g.L, 1.0f) * g.w_c - g.u_g;
            check(fabsf(u0) < 1e-2f, "edge: FOVLP_EDGE_LOG_R puts u = 0 exactly on r_G", "u(r_G) = %g", (double)u0);
        }
    }
    /* Meng's normaliser: L = log(farthest corner); with the gaze at the centre r_max = diag/2 */
    p = fovlp_config_preset(FOVLP_PRESET_FOV, 1920, 1080);
    p.norm = FOVLP_NORM_CORNER;
    fovlp_geometry_get(&p, gz, &g);
    check(fabsf(g.L - logf(sqrtf(960.0f * 960.0f + 540.0f * 540.0f))) < 1e-4f && g.lp_cols == g.lp_w,
          "normaliser: FOVLP_NORM_CORNER uses the farthest corner, all columns used", "L %g cols %u/%u", (double)g.L, g.lp_cols, g.lp_w);
    {
        fov_gaze corner = { 0.0f, 0.0f };
        fovlp_geometry_get(&p, corner, &g);
        check(fabsf(g.L - logf(sqrtf(1920.0f * 1920.0f + 1080.0f * 1080.0f))) < 1e-4f,
              "normaliser: CORNER with the gaze in a corner equals the diagonal", "L %g", (double)g.L);
    }
    /* Meng's normaliser at any gaze: the buffer keeps the diagonal's size (no reallocation),
       every column is used and the outermost column edge (u = w) lands on the farthest corner */
    {
        static const float gzs[5][2] = { { 960.0f, 540.0f }, { 100.0f, 200.0f }, { 0.0f, 0.0f }, { 1919.0f, 1079.0f }, { 1500.0f, 900.0f } };
        uint32_t preset, k, bad_size = 0, bad_cols = 0, bad_L = 0, bad_edge = 0, bad_disc = 0;
        for (preset = 0; preset < 4; ++preset)
            for (k = 0; k < 5; ++k) {
                fovlp_config pd = fovlp_config_preset(preset, 1920, 1080), pc;
                fovlp_geometry gd, gc;
                fov_gaze gk;
                lp_env e;
                float cx[4] = { 0.0f, 1920.0f, 0.0f, 1920.0f }, cy[4] = { 0.0f, 0.0f, 1080.0f, 1080.0f }, rmax = 0.0f;
                uint32_t q;
                gk.x = gzs[k][0]; gk.y = gzs[k][1];
                for (q = 0; q < 4; ++q) rmax = fmaxf(rmax, sqrtf((cx[q] - gk.x) * (cx[q] - gk.x) + (cy[q] - gk.y) * (cy[q] - gk.y)));
                pc = pd;
                pc.norm = FOVLP_NORM_CORNER;
                fovlp_geometry_get(&pd, gk, &gd);
                fovlp_geometry_get(&pc, gk, &gc);
                if (gc.lp_w != gd.lp_w || gc.lp_h != gd.lp_h || gc.samples != gd.samples) bad_size++;
                if (gc.lp_cols != gc.lp_w) bad_cols++;
                if (fabsf(gc.L - logf(rmax)) > 1e-4f) bad_L++;
                if (env_init(&e, &pc) != FOV_OK || fovlp_begin_frame(&e.ctx, gk, NULL) != FOV_OK) { bad_edge++; continue; }
                for (q = 0; q < 8; ++q) {
                    float x, y, u, v, vq = (float)e.ctx.geo.lp_h * (float)q / 8.0f;
                    fovlp_lp_to_screen(&e.ctx, (float)e.ctx.geo.lp_w, vq, &x, &y);
                    if (fabsf(sqrtf((x - gk.x) * (x - gk.x) + (y - gk.y) * (y - gk.y)) - rmax) > 1e-3f * rmax) bad_edge++;
                    if (e.ctx.geo.r_g > 0.0f) { /* u = 0 on the disc edge, and back */
                        fovlp_lp_to_screen(&e.ctx, 0.0f, vq, &x, &y);
                        if (fabsf(sqrtf((x - gk.x) * (x - gk.x) + (y - gk.y) * (y - gk.y)) - e.ctx.geo.r_g) > 1e-3f * e.ctx.geo.r_g) bad_disc++;
                        fovlp_screen_to_lp(&e.ctx, x, y, &u, &v);
                        if (fabsf(u) > 2e-2f) bad_disc++;
                    }
                }
                env_free(&e);
            }
        check(bad_size == 0 && bad_cols == 0 && bad_L == 0,
              "normaliser: CORNER at 5 gazes x 4 presets: the diagonal's buffer size, L = log(farthest corner), all columns dispatched",
              "size %u cols %u L %u", bad_size, bad_cols, bad_L);
        check(bad_edge == 0 && bad_disc == 0,
              "normaliser: CORNER: column edge u = w maps onto the farthest corner, u = 0 onto the disc edge (1e-3 relative)",
              "edge %u disc %u", bad_edge, bad_disc);
    }
    /* memory size covers the tables and grows with the buffer */
    {
        size_t b1 = 0, b2 = 0;
        p = fovlp_config_preset(FOVLP_PRESET_FOV, 1920, 1080);
        fovlp_memory_size(&p, &b1);
        p.sigma = 0.5f;
        fovlp_memory_size(&p, &b2);
        check(b1 >= (2104u + 2u * 1753u) * 4u && b2 > b1, "memory: size query covers (w + 2h) floats and grows as sigma falls",
              "%zu %zu", b1, b2);
    }
}

/* ---- bad input ------------------------------------------------------------------------------ */
static void test_bad_input(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, 320, 180), b;
    fovlp_geometry g;
    fovlp_ctx ctx;
    fov_gaze gz = { 160.0f, 90.0f }, nan_gz;
    size_t bytes = 0;
    unsigned char small[8];
    lp_env e;
    float u, v;
    int i;
    nan_gz.x = NAN; nan_gz.y = 90.0f;
    c.logger.func = test_logger;
#define BAD(field_stmt, expect, name)                                                    \
    do {                                                                                 \
        fov_result rr;                                                                   \
        b = c;                                                                           \
        field_stmt;                                                                      \
        log_calls = 0;                                                                   \
        rr = fovlp_geometry_get(&b, gz, &g);                                             \
        check(rr == (expect) && log_calls == 1 && log_last_code == (int32_t)(expect),   \
              name, "got %d (%s), logger calls %d", (int)rr, fovlp_result_string(rr), log_calls); \
    } while (0)
    BAD(b.sigma = -1.0f, FOV_ERR_INVALID_ARG, "bad input: sigma < 0");
    BAD(b.sigma = NAN, FOV_ERR_NOT_FINITE, "bad input: sigma NaN");
    BAD(b.sigma = 1e-5f, FOV_ERR_LIMIT, "bad input: sigma 1e-5 (buffer too large)");
    BAD(b.alpha = -2.0f, FOV_ERR_INVALID_ARG, "bad input: alpha < 0");
    BAD(b.alpha = INFINITY, FOV_ERR_NOT_FINITE, "bad input: alpha infinite");
    BAD(b.alpha = 20.0f, FOV_ERR_INVALID_ARG, "bad input: alpha > 16");
    BAD(b.gaze_angle = -0.1f, FOV_ERR_INVALID_ARG, "bad input: a_G < 0");
    BAD(b.gaze_angle = 1.4f, FOV_ERR_INVALID_ARG, "bad input: a_G whose disc covers the screen");
    BAD(b.lp_aspect = -1.0f, FOV_ERR_INVALID_ARG, "bad input: lp_aspect < 0");
    BAD(b.width = 0, FOV_ERR_INVALID_ARG, "bad input: width 0");
    BAD(b.height = 0, FOV_ERR_INVALID_ARG, "bad input: height 0");
    BAD(b.width = 70000, FOV_ERR_LIMIT, "bad input: width above FOVLP_MAX_DIM");
    BAD((b.width = 65536, b.height = 65536, b.sigma = 0.01f), FOV_ERR_LIMIT, "bad input: 65536^2 at sigma 0.01 overflows the caps");
    BAD(b.norm = 7, FOV_ERR_INVALID_ARG, "bad input: unknown norm");
    BAD(b.edge = 7, FOV_ERR_INVALID_ARG, "bad input: unknown edge");
    BAD(b.taa.phases = 1000, FOV_ERR_INVALID_ARG, "bad input: taa.phases > 256");
    BAD(b.taa.max_age = 300, FOV_ERR_INVALID_ARG, "bad input: taa.max_age > 255");
    BAD(b.taa.clamp = 9, FOV_ERR_INVALID_ARG, "bad input: unknown taa.clamp");
    BAD(b.taa.thesis_moving = 2, FOV_ERR_INVALID_ARG, "bad input: taa.thesis_moving not 0 or 1");
    BAD(b.display.pixel_pitch_mm = 0.2f, FOV_ERR_INVALID_ARG, "bad input: display pitch without distance");
    BAD(b.cam_fov_y_deg = 180.0f, FOV_ERR_INVALID_ARG, "bad input: cam_fov_y_deg 180");
    BAD((b.blend_start = 0.5f, b.blend_end = 0.4f), FOV_ERR_INVALID_ARG, "bad input: blend_end <= blend_start");
#undef BAD
    log_calls = 0;
    check(fovlp_geometry_get(&c, nan_gz, &g) == FOV_ERR_NOT_FINITE && log_calls == 1, "bad input: NaN gaze", " ");
    check(fovlp_geometry_get(NULL, gz, &g) == FOV_ERR_NULL && fovlp_geometry_get(&c, gz, NULL) == FOV_ERR_NULL &&
              fovlp_memory_size(NULL, &bytes) == FOV_ERR_NULL && fovlp_memory_size(&c, NULL) == FOV_ERR_NULL &&
              fovlp_config_resolve(NULL, &b) == FOV_ERR_NULL,
          "bad input: NULL config or output", " ");
    fovlp_memory_size(&c, &bytes);
    check(fovlp_init(&ctx, &c, NULL, bytes) == FOV_ERR_NULL && fovlp_init(&ctx, &c, small, sizeof small) == FOV_ERR_TOO_SMALL &&
              fovlp_init(NULL, &c, small, sizeof small) == FOV_ERR_NULL,
          "bad input: init with NULL or too small memory", " ");
    check(env_init(&e, &c) == FOV_OK, "bad input: a valid init", " ");
    /* before begin_frame */
    check(fovlp_screen_to_lp(&e.ctx, 1, 1, &u, &v) == FOV_ERR_INVALID_ARG && fovlp_sample_rows(&e.ctx) == 0 &&
              fovlp_reconstruct_rows(&e.ctx, e.srgb, NULL, 0, 1, e.srgb, 0, NULL) == FOV_ERR_INVALID_ARG,
          "bad input: calls before the first begin_frame are errors", " ");
    check(fovlp_begin_frame(&e.ctx, nan_gz, NULL) == FOV_ERR_NOT_FINITE, "bad input: begin_frame with a NaN gaze", " ");
    {
        fovlp_camera cam;
        memset(&cam, 0, sizeof cam);
        cam.fwd[2] = 1.0f; cam.right[0] = 1.0f; cam.up[1] = 1.0f; cam.tan_half_y = 0.5f;
        cam.pos[0] = NAN;
        check(fovlp_begin_frame(&e.ctx, gz, &cam) == FOV_ERR_NOT_FINITE, "bad input: camera with NaN position", " ");
        cam.pos[0] = 0.0f; cam.tan_half_y = 0.0f;
        check(fovlp_begin_frame(&e.ctx, gz, &cam) == FOV_ERR_DEGENERATE, "bad input: camera with zero field of view", " ");
    }
    check(fovlp_begin_frame(&e.ctx, gz, NULL) == FOV_OK, "bad input: begin_frame after the errors", " ");
    {
        uint32_t rows = fovlp_sample_rows(&e.ctx);
        size_t n = 0;
        fovlp_sample few[4];
        float img[320 * 3];
        int oks = fovlp_samples(&e.ctx, 0, rows + 1, NULL, 0, &n) == FOV_ERR_INVALID_ARG &&
                  fovlp_samples(&e.ctx, 5, 4, NULL, 0, &n) == FOV_ERR_INVALID_ARG &&
                  fovlp_samples(&e.ctx, 0, rows, few, 4, &n) == FOV_ERR_TOO_SMALL && n > 4 &&
                  fovlp_samples(&e.ctx, 0, rows, NULL, 0, NULL) == FOV_ERR_NULL;
        check(oks, "bad input: sample rows out of range, output too small, NULL count", "n %zu", n);
        check(fovlp_shade_rows(&e.ctx, 0, rows, NULL, NULL, e.srgb, NULL, NULL) == FOV_ERR_NULL &&
                  fovlp_shade_rows(&e.ctx, 0, rows, shade_smooth, NULL, NULL, NULL, NULL) == FOV_ERR_NULL,
              "bad input: shade_rows without callback or buffer", " ");
        check(fovlp_reconstruct_rows(&e.ctx, e.srgb, NULL, 0, 181, img, 0, NULL) == FOV_ERR_INVALID_ARG &&
                  fovlp_reconstruct_rows(&e.ctx, NULL, NULL, 0, 1, img, 0, NULL) == FOV_ERR_NULL &&
                  fovlp_reconstruct_rows(&e.ctx, e.srgb, NULL, 0, 1, img, 5, NULL) == FOV_ERR_INVALID_ARG &&
                  fovlp_reconstruct_tile(&e.ctx, e.srgb, NULL, 10, 0, 400, 1, img, 0, NULL) == FOV_ERR_INVALID_ARG,
              "bad input: reconstruction rows/tile out of range, NULL samples, short stride", " ");
        check(fovlp_blend_rows(&e.ctx, img, 0, 1, img) == FOV_ERR_INVALID_ARG, "bad input: blend in place", " ");
        check(fovlp_lp_to_screen(&e.ctx, NAN, 1, &u, &v) == FOV_ERR_NOT_FINITE &&
                  fovlp_screen_to_lp(&e.ctx, 1, INFINITY, &u, &v) == FOV_ERR_NOT_FINITE &&
                  fovlp_lp_to_screen(&e.ctx, -1e9f, 1, &u, &v) == FOV_ERR_INVALID_ARG,
              "bad input: NaN/inf points in the mappings, LP point inside the disc", " ");
        {   /* finite but huge: screen_to_lp stays finite, lp_to_screen says LIMIT (not inf) */
            float uu = -1.0f, vv = -1.0f, xx = 0.0f, yy = 0.0f;
            fov_result r1 = fovlp_screen_to_lp(&e.ctx, 3e38f, -3e38f, &uu, &vv);
            fov_result r2 = fovlp_lp_to_screen(&e.ctx, 1e30f, 3.0f, &xx, &yy);
            check(r1 == FOV_OK && isfinite(uu) && isfinite(vv) && uu > 0.0f && r2 == FOV_ERR_LIMIT && isfinite(xx) && isfinite(yy),
                  "bad input: mappings of points near the float range stay finite (LIMIT beyond)", "u %g v %g (%d), x %g y %g (%d)",
                  (double)uu, (double)vv, (int)r1, (double)xx, (double)yy, (int)r2);
        }
        {
            float dimg[320];
            check(fovlp_reconstruct_rows(&e.ctx, e.srgb, NULL, 0, 1, img, 0, dimg) == FOV_ERR_NULL,
                  "bad input: out_depth without sample_depth", " ");
        }
        {
            fovlp_taa_io io;
            memset(&io, 0, sizeof io);
            check(fovlp_taa_rows(&e.ctx, &io, 0, 1, NULL) == FOV_ERR_INVALID_ARG, "bad input: taa_rows with TAA disabled", " ");
        }
    }
    env_free(&e);
    /* off-screen gaze: documented clamp with a warning */
    {
        fov_gaze off = { -50.0f, 1000.0f };
        c.logger.func = test_logger;
        env_init(&e, &c);
        log_calls = 0;
        check(fovlp_begin_frame(&e.ctx, off, NULL) == FOV_OK && fabsf(e.ctx.gaze.x) < 1e-6f &&
                  fabsf(e.ctx.gaze.y - 180.0f) < 1e-6f && log_calls == 1 && log_last_level == FOV_LOG_WARN,
              "bad input: off-screen gaze clamped to the screen with a warning", "gaze %g %g calls %d",
              (double)e.ctx.gaze.x, (double)e.ctx.gaze.y, log_calls);
        env_free(&e);
    }
    /* result strings: never NULL */
    {
        int ok = 1;
        for (i = -10; i <= 2; ++i) ok = ok && fovlp_result_string((fov_result)i) != NULL;
        ok = ok && fovlp_result_string((fov_result)0x1234) != NULL && strcmp(fovlp_result_string(FOV_OK), "ok") == 0;
        check(ok, "result strings: never NULL", " ");
    }
}

/* ---- mappings ----------------------------------------------------------------------------- */
static void test_round_trip(void)
{
    static const uint32_t sizes[3][2] = { { 320, 180 }, { 1920, 1080 }, { 7680, 4320 } };
    int s, p;
    for (s = 0; s < 3; ++s)
        for (p = 0; p < 4; ++p) {
            fovlp_config c = fovlp_config_preset((uint32_t)p, sizes[s][0], sizes[s][1]);
            lp_env e;
            float worst = 0.0f, worst_lp = 0.0f;
            int k, ok;
            char name[128];
            fov_gaze gz;
            env_init(&e, &c);
            gz.x = 0.37f * (float)c.width; gz.y = 0.61f * (float)c.height;
            fovlp_begin_frame(&e.ctx, gz, NULL);
            for (k = 0; k < 4000; ++k) {
                float x = frand() * (float)c.width, y = frand() * (float)c.height, u = 0, v = 0, x2 = 0, y2 = 0, u2 = 0, v2 = 0, dx, dy, r, du;
                dx = x - gz.x; dy = y - gz.y;
                r = sqrtf(dx * dx + dy * dy);
                if (r < fmaxf(e.ctx.geo.r_g, 1.0f) + 0.01f) continue;
                fovlp_screen_to_lp(&e.ctx, x, y, &u, &v);
                fovlp_lp_to_screen(&e.ctx, u, v, &x2, &y2);
                worst = fmaxf(worst, hypotf(x2 - x, y2 - y) / r);
                /* and LP -> screen -> LP */
                fovlp_screen_to_lp(&e.ctx, x2, y2, &u2, &v2);
                du = fabsf(v2 - v);
                if (du > 0.5f * (float)e.ctx.geo.lp_h) du = (float)e.ctx.geo.lp_h - du; /* wrap */
                worst_lp = fmaxf(worst_lp, fmaxf(fabsf(u2 - u), du));
            }
            ok = worst < 1e-3f && worst_lp < 0.05f;
            snprintf(name, sizeof name, "round trip: %s %ux%u screen->LP->screen within 1e-3 r, LP->screen->LP within 0.05 texel",
                     fovlp_preset_name((uint32_t)p), c.width, c.height);
            check(ok, name, "worst %g (relative), %g texel", (double)worst, (double)worst_lp);
            env_free(&e);
        }
}

/* the reconstruction's own mapping (fovlp__to_lp_fast: polynomial atan, no atan2 call)
   agrees with the reference fovlp_screen_to_lp within the tolerance stated in the header:
   |du| <= 1e-4 (|u| + 1), |dv| <= 2e-6 h (wrapped); pixel centres on the axes through the
   gaze included. The comparator rejects an error ten times the tolerance (it can fail). */
static int fast_map_ok(float du, float dv, float u, float h)
{
    dv = fabsf(dv);
    if (dv > 0.5f * h) dv = h - dv;
    return fabsf(du) <= 1e-4f * (fabsf(u) + 1.0f) && dv <= 2e-6f * h;
}
static void test_fast_mapping(void)
{
    static const uint32_t sizes[3][2] = { { 321, 181 }, { 1920, 1080 }, { 7680, 4320 } };
    int s, p, g;
    for (s = 0; s < 3; ++s)
        for (p = 0; p < 4; ++p)
            for (g = 0; g < 2; ++g) {
                fovlp_config c = fovlp_config_preset((uint32_t)p, sizes[s][0], sizes[s][1]);
                lp_env e;
                float worst_u = 0.0f, worst_v = 0.0f, h;
                int k, bad = 0;
                char name[160];
                fov_gaze gz;
                env_init(&e, &c);
                /* a gaze on a pixel centre (pixels on the axes: dx or dy exactly 0), and off it */
                gz.x = g ? 0.37f * (float)c.width : (float)(c.width / 2u) + 0.5f;
                gz.y = g ? 0.61f * (float)c.height : (float)(c.height / 3u) + 0.5f;
                fovlp_begin_frame(&e.ctx, gz, NULL);
                h = (float)e.ctx.geo.lp_h;
                for (k = 0; k < 6000; ++k) {
                    uint32_t px = (uint32_t)(frand() * (float)c.width) % c.width;
                    uint32_t py = (uint32_t)(frand() * (float)c.height) % c.height;
                    float x, y, dx, dy, u = 0, v = 0, uf = 0, vf = 0, dv;
                    if (k % 4 == 0) px = (uint32_t)gz.x;        /* the vertical axis when g = 0 */
                    if (k % 4 == 1) py = (uint32_t)gz.y;        /* the horizontal axis */
                    x = (float)px + 0.5f; y = (float)py + 0.5f;
                    dx = x - e.ctx.gaze.x; dy = y - e.ctx.gaze.y;
                    fovlp_screen_to_lp(&e.ctx, x, y, &u, &v);
                    fovtest_lp_to_lp_fast(&e.ctx, dx, dy, dx * dx + dy * dy, &uf, &vf);
                    dv = fabsf(vf - v);
                    if (dv > 0.5f * h) dv = h - dv;
                    worst_u = fmaxf(worst_u, fabsf(uf - u) / (fabsf(u) + 1.0f));
                    worst_v = fmaxf(worst_v, dv / h);
                    bad += !fast_map_ok(uf - u, vf - v, u, h) || !(vf >= 0.0f && vf < h);
                }
                snprintf(name, sizeof name, "fast mapping: %s %ux%u gaze %s matches screen_to_lp (|du| <= 1e-4 (u+1), |dv| <= 2e-6 h)",
                         fovlp_preset_name((uint32_t)p), c.width, c.height, g ? "off-centre" : "on a pixel centre");
                check(bad == 0, name, "%d outside; worst du/(u+1) %g, dv/h %g", bad, (double)worst_u, (double)worst_v);
                if (s == 0 && p == 0 && g == 0)
                    check(!fast_map_ok(0.0f, 2e-5f * h, 1.0f, h) && !fast_map_ok(1e-3f * 2.0f, 0.0f, 1.0f, h) &&
                              fast_map_ok(0.0f, h - 1e-6f * h, 1.0f, h),
                          "fast mapping: the comparator rejects 10x the tolerance and wraps v", "h %g", (double)h);
                env_free(&e);
            }
}

/* the angle convention: atan2 wrapped to [0, 2 pi); v grows from +x towards +y */
static void test_angles(void)
{
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_FOV, 400, 400);
    lp_env e;
    fov_gaze gz = { 200.0f, 200.0f };
    float u, v[4], h;
    env_init(&e, &c);
    fovlp_begin_frame(&e.ctx, gz, NULL);
    h = (float)e.ctx.geo.lp_h;
    fovlp_screen_to_lp(&e.ctx, 300, 200, &u, &v[0]);
    fovlp_screen_to_lp(&e.ctx, 200, 300, &u, &v[1]);
    fovlp_screen_to_lp(&e.ctx, 100, 200, &u, &v[2]);
    fovlp_screen_to_lp(&e.ctx, 200, 100, &u, &v[3]);
    check(fabsf(v[0]) < 1e-3f && fabsf(v[1] - 0.25f * h) < 1e-2f && fabsf(v[2] - 0.5f * h) < 1e-2f &&
              fabsf(v[3] - 0.75f * h) < 1e-2f,
          "angles: atan2 in all four quadrants, v in [0, h) (eq. 3.9 read as atan2)", "%g %g %g %g of %g",
          (double)v[0], (double)v[1], (double)v[2], (double)v[3], (double)h);
    fovlp_screen_to_lp(&e.ctx, 300, 199.999f, &u, &v[0]);
    check(v[0] > 0.99f * h && v[0] < h, "angles: just below the +x axis maps to v just below h (wrap)", "v %g", (double)v[0]);
    env_free(&e);
}

/* density (LP texels per pixel area) falls with eccentricity for alpha > 1, and the kernel
   moves samples outwards: the ratio to the alpha = 1 density grows with r (thesis Sec. 3.3.2) */
static void test_density(void)
{
    float alphas[3] = { 2.0f, 3.0f, 4.0f };
    int a;
    for (a = 0; a < 3; ++a) {
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_K_FOV, 1920, 1080), c1;
        lp_env e, e1;
        fov_gaze gz = { 960.0f, 540.0f };
        float rstar, prev = FLT_MAX, prev_ratio = 0.0f, r;
        int mono = 1, outward = 1, k;
        char name[160];
        c.alpha = alphas[a];
        c1 = c;
        c1.alpha = 1.0f;
        env_init(&e, &c);
        env_init(&e1, &c1);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        fovlp_begin_frame(&e1.ctx, gz, NULL);
        rstar = expf((alphas[a] - 1.0f) * 0.5f); /* the density's maximum, d/dr = 0 */
        for (k = 0; k < 400; ++k) {
            float th = 0.7f, d, d1, ratio;
            r = rstar * powf(1100.0f / rstar, (float)k / 399.0f);
            d = fovlp_density(&e.ctx, 960.0f + r * cosf(th), 540.0f + r * sinf(th));
            d1 = fovlp_density(&e1.ctx, 960.0f + r * cosf(th), 540.0f + r * sinf(th));
            ratio = d / d1;
            if (k > 0 && !(d < prev)) mono = 0;
            if (k > 0 && !(ratio > prev_ratio)) outward = 0;
            prev = d;
            prev_ratio = ratio;
        }
        snprintf(name, sizeof name, "density: alpha %g falls monotonically with r beyond its maximum at r* = exp((alpha-1)/2) = %.2f px",
                 (double)alphas[a], (double)rstar);
        check(mono, name, " ");
        snprintf(name, sizeof name, "density: alpha %g / alpha 1 grows with r (the kernel moves samples outwards)", (double)alphas[a]);
        check(outward, name, " ");
        env_free(&e);
        env_free(&e1);
    }
    /* the density matches counting samples in an annulus (independent check of the Jacobian) */
    {
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_K_FOV, 1920, 1080);
        lp_env e;
        fov_gaze gz = { 960.0f, 540.0f };
        fovlp_sample *s;
        size_t n = 0, i, cnt = 0;
        float r0 = 200.0f, r1 = 260.0f, rm = 230.0f, expect, got;
        env_init(&e, &c);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        fovlp_samples(&e.ctx, 0, fovlp_sample_rows(&e.ctx), NULL, 0, &n);
        s = (fovlp_sample *)malloc(n * sizeof *s);
        fovlp_samples(&e.ctx, 0, fovlp_sample_rows(&e.ctx), s, n, &n);
        for (i = 0; i < n; ++i) {
            float r = hypotf(s[i].x - gz.x, s[i].y - gz.y);
            if (r >= r0 && r < r1) cnt++;
        }
        expect = fovlp_density(&e.ctx, gz.x + rm, gz.y) * 3.14159265f * (r1 * r1 - r0 * r0);
        got = (float)cnt;
        check(fabsf(got - expect) < 0.03f * expect, "density: the Jacobian matches the samples counted in an annulus (3 %)",
              "counted %g, density integral %g", (double)got, (double)expect);
        free(s);
        env_free(&e);
    }
}

/* aspect matching (section 1.10): lp_aspect 0 equalises the spacings at match_deg */
static void test_aspect_match(void)
{
    int p;
    for (p = 0; p < 4; ++p) {
        fovlp_config c = fovlp_config_preset((uint32_t)p, 1920, 1080);
        lp_env e;
        fov_gaze gz = { 960.0f, 540.0f };
        float rad, ang, r;
        char name[128];
        c.lp_aspect = 0.0f;
        env_init(&e, &c);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        r = e.ctx.geo.f_px * tanf(15.0f * 3.14159265f / 180.0f);
        fovlp_spacing(&e.ctx, r, &rad, &ang);
        snprintf(name, sizeof name, "aspect match: %s radial = angular spacing at 15 deg within 3 %% (aspect %.3f)",
                 fovlp_preset_name((uint32_t)p), (double)e.ctx.geo.lp_aspect);
        /* the rounding of w and h to integers leaves about 1 % */
        check(fabsf(rad / ang - 1.0f) < 0.03f, name, "radial %g angular %g", (double)rad, (double)ang);
        if (p == FOVLP_PRESET_FOV)
            check(fabsf(e.ctx.geo.lp_aspect - 7.6975f / 6.2831853f) < 2e-3f,
                  "aspect match: alpha 1 without disc gives L / (2 pi) = 1.225 (thesis Fov tuned 1.2)", "%g",
                  (double)e.ctx.geo.lp_aspect);
        env_free(&e);
    }
}

/* ---- the thesis's ray counts (Table 5.3) ------------------------------------------------------ */
static void test_ray_counts(void)
{
    /* thesis (dispatched, traced) and an independent model of eqs. 3.2-3.10 (a Python script
       outside this repository: every LP texel's sample tested against the screen, the disc's
       pixels against the circle; 1920x1080, gaze at the centre, eye distance diag / tan 60) */
    static const float thesis[4][2] = { { 162.0f, 154.0f }, { 75.4f, 65.7f }, { 48.3f, 37.5f }, { 47.6f, 37.7f } };
    static const float model[4][2] = { { 161.9f, 153.4f }, { 75.4f, 64.4f }, { 47.4f, 35.9f }, { 47.2f, 36.4f } };
    int p, edge;
    for (edge = 0; edge < 2; ++edge)
        for (p = 0; p < 4; ++p) {
            fovlp_config c = fovlp_config_preset((uint32_t)p, 1920, 1080);
            lp_env e;
            fov_gaze gz = { 960.0f, 540.0f };
            fovlp_counts n;
            char name[200];
            size_t cnt = 0;
            c.edge = edge ? FOVLP_EDGE_THESIS : FOVLP_EDGE_LOG_R;
            env_init(&e, &c);
            fovlp_begin_frame(&e.ctx, gz, NULL);
            fovlp_count_samples(&e.ctx, &n);
            snprintf(name, sizeof name, "ray counts: %s 1920x1080 (%s) dispatched %.1f %% / shaded %.1f %% vs thesis %.1f / %.1f within 2 pp",
                     fovlp_preset_name((uint32_t)p), edge ? "thesis edge" : "log r_G edge", (double)n.dispatched_pct,
                     (double)n.shaded_pct, (double)thesis[p][0], (double)thesis[p][1]);
            check(fabsf(n.dispatched_pct - thesis[p][0]) <= 2.0f && fabsf(n.shaded_pct - thesis[p][1]) <= 2.0f, name, " ");
            if (edge) {
                snprintf(name, sizeof name, "ray counts: %s with the thesis edge matches an independent model (%.1f / %.1f) within 0.3 pp",
                         fovlp_preset_name((uint32_t)p), (double)model[p][0], (double)model[p][1]);
                check(fabsf(n.dispatched_pct - model[p][0]) <= 0.3f && fabsf(n.shaded_pct - model[p][1]) <= 0.3f, name,
                      "%.2f %.2f", (double)n.dispatched_pct, (double)n.shaded_pct);
            }
            /* the sample list has exactly the shaded count */
            fovlp_samples(&e.ctx, 0, fovlp_sample_rows(&e.ctx), NULL, 0, &cnt);
            if (p == 2 && edge == 0)
                check((uint64_t)cnt == n.shaded, "ray counts: fovlp_samples lists exactly the shaded samples", "%zu vs %llu",
                      cnt, (unsigned long long)n.shaded);
            env_free(&e);
        }
}

/* ---- sampling ------------------------------------------------------------------------------ */
typedef struct pos_log {
    float *xy;
    size_t n, cap;
} pos_log;
static void shade_log(float x, float y, float rgb[3], float *depth, void *user)
{
    pos_log *l = (pos_log *)user;
    if (l->n < l->cap) { l->xy[2 * l->n] = x; l->xy[2 * l->n + 1] = y; }
    l->n++;
    rgb[0] = x; rgb[1] = y; rgb[2] = 1.0f;
    if (depth) *depth = 1.0f;
}
static void test_sampling(void)
{
    int p;
    for (p = 0; p < 4; ++p) {
        fovlp_config c = fovlp_config_preset((uint32_t)p, 320, 180);
        lp_env e;
        fov_gaze gz = { 101.3f, 77.7f };
        fovlp_sample *s;
        size_t n = 0, i;
        uint32_t rows, half;
        pos_log lg;
        uint64_t shaded = 0;
        unsigned char *seen;
        int on = 1, uniq = 1, same = 1, slots_ok = 1;
        char name[160];
        c.taa.enable = 1; /* jittered positions */
        env_init(&e, &c);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        fovlp_begin_frame(&e.ctx, gz, NULL); /* phase 1 */
        rows = fovlp_sample_rows(&e.ctx);
        fovlp_samples(&e.ctx, 0, rows, NULL, 0, &n);
        s = (fovlp_sample *)malloc(n * sizeof *s);
        /* the array form in two halves equals one call */
        half = rows / 2;
        {
            size_t n1 = 0, n2 = 0;
            fovlp_samples(&e.ctx, 0, half, s, n, &n1);
            fovlp_samples(&e.ctx, half, rows, s + n1, n - n1, &n2);
            if (n1 + n2 != n) same = 0;
        }
        seen = (unsigned char *)calloc(e.ctx.geo.samples, 1);
        for (i = 0; i < n; ++i) {
            if (!(s[i].x >= 0.0f && s[i].x < 320.0f && s[i].y >= 0.0f && s[i].y < 180.0f)) on = 0;
            if (s[i].slot >= e.ctx.geo.samples) { slots_ok = 0; continue; }
            if (seen[s[i].slot]) uniq = 0;
            seen[s[i].slot] = 1;
        }
        /* the callback form shades the same positions into the same slots */
        lg.cap = n;
        lg.n = 0;
        lg.xy = (float *)malloc(2 * n * sizeof(float));
        fovlp_shade_rows(&e.ctx, 0, rows, shade_log, &lg, e.srgb, e.sdep, &shaded);
        if (lg.n != n || shaded != n) same = 0;
        for (i = 0; i < n && same; ++i) {
            const float *q = e.srgb + 3u * s[i].slot;
            if (fabsf(q[0] - s[i].x) > 0.0f || fabsf(q[1] - s[i].y) > 0.0f || !(q[2] > 0.5f)) same = 0;
        }
        snprintf(name, sizeof name, "sampling: %s every sample on-screen, slots unique and in range", fovlp_preset_name((uint32_t)p));
        check(on && uniq && slots_ok, name, "on %d uniq %d slots %d", on, uniq, slots_ok);
        snprintf(name, sizeof name, "sampling: %s array form (split rows) and callback form agree on %zu samples",
                 fovlp_preset_name((uint32_t)p), n);
        check(same, name, "callback %zu shaded %llu", lg.n, (unsigned long long)shaded);
        /* the jitter moved the LP samples off the texel centres */
        if (p == 0)
            check(fabsf(e.ctx.jit_u - 0.5f) > 0.01f && e.ctx.jit_u < 1.0f && e.ctx.jit_v < 1.0f,
                  "sampling: TAA jitter offsets inside the texel (Halton index 2 scaled)", "%g %g",
                  (double)e.ctx.jit_u, (double)e.ctx.jit_v);
        free(seen);
        free(lg.xy);
        free(s);
        env_free(&e);
    }
    /* eq. 3.11: the 16 scaled offsets average to 0.5; start index 1 keeps them inside the texel */
    {
        fovlp_config c = fovlp_config_default();
        float mu = 0, mv = 0, mx = 0, ou, ov;
        uint32_t k;
        for (k = 0; k < 16; ++k) {
            fovlp_jitter(&c, k, &ou, &ov);
            mu += ou; mv += ov;
            mx = fmaxf(mx, fmaxf(ou, ov));
        }
        check(fabsf(mu / 16.0f - 0.5f) < 1e-5f && fabsf(mv / 16.0f - 0.5f) < 1e-5f && mx < 1.0f,
              "jitter: 16 scaled Halton(2,3) offsets average 0.5, all < 1 texel (start index 1)", "%g %g max %g",
              (double)(mu / 16.0f), (double)(mv / 16.0f), (double)mx);
        fovlp_jitter(&c, 0, &ou, &ov);
        check(fabsf(ou - 0.5f * 1.062241f) < 1e-4f && fabsf(ov - (1.0f / 3.0f) * 1.08f) < 1e-4f,
              "jitter: phase 0 = Halton index 1 = (1/2, 1/3) scaled by 1.062241 / 1.08 (thesis eq. 3.11)", "%g %g",
              (double)ou, (double)ov);
        c.taa.halton_start = 16;
        fovlp_jitter(&c, 0, &ou, &ov);
        check(fabsf(ou - 0.0625f * 0.5f / 0.5f) > 0.0f, "jitter: a settable start index", " ");
        {   /* every (phases, start) keeps every offset inside [0, 1): a disc sample of the last
               column must not land at x = W (3 phases from index 2 scale 0.5 to exactly 1) */
            uint32_t ph, st, worst_ph = 0, worst_st = 0;
            float worst = 0.0f;
            for (ph = 1; ph <= 64; ++ph)
                for (st = 0; st <= 40; ++st) {
                    c.taa.phases = ph; c.taa.halton_start = st;
                    for (k = 0; k < ph; ++k)
                        if (fovlp_jitter(&c, k, &ou, &ov) == FOV_OK) {
                            float m = fmaxf(ou, ov);
                            if (m > worst || !(ou >= 0.0f && ov >= 0.0f)) { worst = m; worst_ph = ph; worst_st = st; }
                        }
                }
            check(worst < 1.0f, "jitter: offsets stay in [0, 1) for phases 1..64, start 0..40", "max %.9g at phases %u start %u",
                  (double)worst, worst_ph, worst_st);
        }
    }
}

/* ---- reconstruction --------------------------------------------------------------------------- */
static void recon(lp_env *e, const smooth_img *si, float *img, float *dep)
{
    fovlp_shade_rows(&e->ctx, 0, fovlp_sample_rows(&e->ctx), shade_smooth, (void *)si, e->srgb, e->sdep, NULL);
    fovlp_reconstruct_rows(&e->ctx, e->srgb, e->sdep, 0, e->ctx.geo.height, img, 0, dep);
}

static void test_reconstruction(void)
{
    int p;
    smooth_img si = { 1.0f / 23.0f, 1.0f / 31.0f };
    for (p = 0; p < 4; ++p) {
        uint32_t W = 480, H = 270, x, y;
        fovlp_config c = fovlp_config_preset((uint32_t)p, W, H);
        lp_env e;
        fov_gaze gz = { 201.3f, 120.6f };
        float *img = (float *)malloc(W * H * 3 * sizeof(float)), *dep = (float *)malloc(W * H * sizeof(float));
        float worst_rel = 0.0f, worst_seam = 0.0f, worst_opp = 0.0f, worst_centre = 0.0f, worst_disc = 0.0f;
        int finite = 1;
        char name[200];
        env_init(&e, &c);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        recon(&e, &si, img, dep);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float px = (float)x + 0.5f, py = (float)y + 0.5f, t[3], err = 0.0f, dx = px - gz.x, dy = py - gz.y;
                float r = sqrtf(dx * dx + dy * dy), rad, ang, sp, bound;
                int ch;
                smooth_val(px, py, &si, t);
                for (ch = 0; ch < 3; ++ch) {
                    float v = img[3 * (y * W + x) + (uint32_t)ch];
                    if (!isfinite(v)) finite = 0;
                    err = fmaxf(err, fabsf(v - t[ch]));
                }
                if (e.ctx.geo.r_g > 0.0f && r < e.ctx.geo.r_g) { worst_disc = fmaxf(worst_disc, err); continue; }
                /* bilinear interpolation error <= spacing^2 / 8 * max second derivative (about
                   0.25/23^2 + 0.2/31^2 + 0.3 * 2 * (0.7/23)^2 per unit^2), with a margin of 2 for
                   the skewed LP cells; near the screen border a tap may be missing (factor 2) */
                fovlp_spacing(&e.ctx, r, &rad, &ang);
                sp = fmaxf(rad, ang) + 0.5f;
                bound = 2.0f * sp * sp / 8.0f * (0.25f / (23.0f * 23.0f) + 0.2f / (31.0f * 31.0f) + 0.6f * 0.49f / (23.0f * 23.0f)) + 2e-3f;
                if (x < 4 || y < 4 || x >= W - 4 || y >= H - 4) bound = 2.0f * bound + 0.5f * sp * (0.25f / 23.0f + 0.2f / 31.0f + 0.3f * 1.4f * 0.7f / 23.0f);
                if (err / bound > worst_rel && getenv("LPDBG")) printf("  worst at %u %u r %g err %g bound %g\n", x, y, (double)r, (double)err, (double)bound);
                worst_rel = fmaxf(worst_rel, err / bound);
                if (r < 4.0f) worst_centre = fmaxf(worst_centre, err);
                if (r > 20.0f && fabsf(dy) < 2.0f) {
                    if (dx > 0.0f) worst_seam = fmaxf(worst_seam, err / bound);
                    else worst_opp = fmaxf(worst_opp, err / bound);
                }
            }
        snprintf(name, sizeof name, "reconstruction: %s smooth image, error within the bilinear bound everywhere (worst %.2f of the bound)",
                 fovlp_preset_name((uint32_t)p), (double)worst_rel);
        check(finite && worst_rel <= 1.0f, name, "finite %d", finite);
        snprintf(name, sizeof name, "reconstruction: %s no seam along the +x ray (worst %.2f of the bound there, %.2f along -x)",
                 fovlp_preset_name((uint32_t)p), (double)worst_seam, (double)worst_opp);
        check(worst_seam <= 1.0f && worst_seam <= 2.0f * worst_opp + 0.1f, name, " ");
        if (e.ctx.geo.r_g > 0.0f) {
            snprintf(name, sizeof name, "reconstruction: %s disc pixels are their own samples, 1:1", fovlp_preset_name((uint32_t)p));
            check(worst_disc < 1e-6f, name, "worst %g", (double)worst_disc);
        } else {
            snprintf(name, sizeof name, "reconstruction: %s centre (r < 4 px) without singularity, error %.4f < 0.01",
                     fovlp_preset_name((uint32_t)p), (double)worst_centre);
            check(worst_centre < 0.01f, name, " ");
        }
        free(img);
        free(dep);
        env_free(&e);
    }
    /* the seam, directly: a colour that depends on the angle only through cos/sin is
       continuous; compare the pixels just above and just below the +x ray */
    {
        uint32_t W = 400, H = 300, x;
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_K_FOV, W, H);
        lp_env e;
        fov_gaze gz = { 150.0f, 150.0f };
        float *img = (float *)malloc(W * H * 3 * sizeof(float)), jump = 0.0f, ref = 0.0f;
        smooth_img s2 = { 1.0f / 40.0f, 1.0f / 40.0f };
        env_init(&e, &c);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        recon(&e, &s2, img, NULL);
        for (x = 170; x < W; ++x) {
            /* rows 149 and 150 straddle the +x ray (y = 150); rows 99/100 straddle nothing */
            jump = fmaxf(jump, fabsf(img[3 * (149 * W + x)] - img[3 * (150 * W + x)]));
        }
        for (x = 170; x < W; ++x) ref = fmaxf(ref, fabsf(img[3 * (99 * W + x)] - img[3 * (100 * W + x)]));
        check(jump < 0.02f && jump <= 2.0f * ref + 0.005f, "reconstruction: step across the +x ray no larger than across another row pair",
              "across the ray %g, elsewhere %g", (double)jump, (double)ref);
        free(img);
        env_free(&e);
    }
    /* tiny screens and the corner gaze: every pixel finite, 1x1 is the centre sample */
    {
        static const uint32_t tiny[4][2] = { { 1, 1 }, { 2, 1 }, { 3, 7 }, { 16, 9 } };
        int t, ok = 1;
        for (t = 0; t < 4; ++t) {
            int pp;
            for (pp = 0; pp < 4; ++pp) {
                uint32_t W = tiny[t][0], H = tiny[t][1], i;
                fovlp_config c = fovlp_config_preset((uint32_t)pp, W, H);
                lp_env e;
                fov_gaze gz;
                float img[16 * 9 * 3];
                smooth_img s3 = { 0.3f, 0.2f };
                gz.x = (float)W; gz.y = 0.0f; /* a corner */
                if (env_init(&e, &c) != FOV_OK || fovlp_begin_frame(&e.ctx, gz, NULL) != FOV_OK) { ok = 0; env_free(&e); continue; }
                recon(&e, &s3, img, NULL);
                for (i = 0; i < W * H * 3; ++i)
                    if (!(img[i] >= -0.5f && img[i] <= 1.5f)) ok = 0;
                if (W == 1 && H == 1) {
                    float tv[3];
                    smooth_val(fminf(gz.x, 0.5f), 0.0f, &s3, tv);
                    (void)tv;
                }
                env_free(&e);
            }
        }
        check(ok, "reconstruction: screens 1x1, 2x1, 3x7, 16x9 with the gaze in a corner, all presets: finite, in range", " ");
    }
    /* 8K: sizes and memory, and a row of reconstruction */
    {
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, 7680, 4320);
        fovlp_geometry g;
        fov_gaze gz = { 3840.0f, 2160.0f };
        size_t bytes = 0;
        int ok8 = fovlp_geometry_get(&c, gz, &g) == FOV_OK && fovlp_memory_size(&c, &bytes) == FOV_OK;
        check(ok8 && bytes <= (g.lp_w + 2u * g.lp_h) * 4u + 64u && g.samples < 7680u * 4320u,
              "8K: geometry, memory ((w + 2h) floats of tables) and fewer slots than pixels", "%ux%u, %zu bytes, %u slots",
              g.lp_w, g.lp_h, bytes, g.samples);
    }
    /* strip screens: the disc buffer is min(S, W) x min(S, H), not a square of the long side */
    {
        static const uint32_t dims[5][2] = { { 65536, 1 }, { 65536, 16 }, { 20000, 8 }, { 7680, 64 }, { 7680, 1080 } };
        int k, ok = 1;
        double worst = 0.0;
        for (k = 0; k < 5; ++k) {
            fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, dims[k][0], dims[k][1]);
            fovlp_geometry g;
            fov_gaze gz;
            double ratio;
            gz.x = 0.5f * (float)dims[k][0]; gz.y = 0.5f * (float)dims[k][1];
            if (fovlp_geometry_get(&c, gz, &g) != FOV_OK) { ok = 0; continue; }
            ratio = (double)g.samples / ((double)dims[k][0] * (double)dims[k][1]);
            if (g.disc_cols != (g.disc_side < dims[k][0] ? g.disc_side : dims[k][0]) ||
                g.disc_rows != (g.disc_side < dims[k][1] ? g.disc_side : dims[k][1]) ||
                g.samples != g.lp_slots + g.disc_cols * g.disc_rows + 1u || g.disc_w > g.disc_cols || g.disc_h > g.disc_rows)
                ok = 0;
            if (ratio > worst) worst = ratio;
        }
        check(ok && worst < 4.0, "strip screens (65536x1 .. 7680x1080): disc buffer min(S,W) x min(S,H), slots < 4 per pixel",
              "worst %.2f slots per pixel", worst);
    }
    /* rows and tiles: any split gives the same image */
    {
        uint32_t W = 160, H = 90, y;
        fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_K_FOV, W, H);
        lp_env e;
        fov_gaze gz = { 70.2f, 40.9f };
        float *a = (float *)calloc(W * H * 3, sizeof(float)), *b = (float *)calloc(W * H * 3, sizeof(float));
        uint32_t rows, r;
        env_init(&e, &c);
        fovlp_begin_frame(&e.ctx, gz, NULL);
        rows = fovlp_sample_rows(&e.ctx);
        for (r = 0; r < rows; r += 7) fovlp_shade_rows(&e.ctx, r, r + 7 < rows ? r + 7 : rows, shade_smooth, &si, e.srgb, NULL, NULL);
        fovlp_reconstruct_rows(&e.ctx, e.srgb, NULL, 0, H, a, 0, NULL);
        for (y = 0; y < H; y += 16) {
            uint32_t x;
            for (x = 0; x < W; x += 32)
                fovlp_reconstruct_tile(&e.ctx, e.srgb, NULL, x, y, x + 32 < W ? x + 32 : W, y + 16 < H ? y + 16 : H, b, 0, NULL);
        }
        check(memcmp(a, b, W * H * 3 * sizeof(float)) == 0, "threading: rows in chunks of 7, tiles of 32x16: identical image", " ");
        free(a);
        free(b);
        env_free(&e);
    }
}

/* the Gaussian blend (eq. 3.13): identity inside diag/6, the full 3x3 Gaussian beyond blend_end */
static void test_blend(void)
{
    uint32_t W = 200, H = 100, i;
    fovlp_config c = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    lp_env e;
    fov_gaze gz = { 100.0f, 50.0f };
    float *in = (float *)malloc(W * H * 3 * sizeof(float)), *out = (float *)malloc(W * H * 3 * sizeof(float));
    float diag = sqrtf(200.0f * 200.0f + 100.0f * 100.0f), inner = 0.0f, outer = 0.0f;
    c.blend = 1;
    env_init(&e, &c);
    fovlp_begin_frame(&e.ctx, gz, NULL);
    for (i = 0; i < W * H * 3; ++i) in[i] = frand();
    fovlp_blend_rows(&e.ctx, in, 0, H, out);
    {
        uint32_t x, y;
        for (y = 1; y + 1 < H; ++y)
            for (x = 1; x + 1 < W; ++x) {
                float dx = (float)x + 0.5f - gz.x, dy = (float)y + 0.5f - gz.y, r = sqrtf(dx * dx + dy * dy);
                size_t o = 3u * (y * W + x);
                if (r <= diag / 6.0f) inner = fmaxf(inner, fabsf(out[o] - in[o]));
                if (r >= diag / 2.0f) {
                    float g = 0.0f;
                    int a, b;
                    for (b = -1; b <= 1; ++b)
                        for (a = -1; a <= 1; ++a) g += (float)((2 - abs(a)) * (2 - abs(b))) / 16.0f * in[3u * ((y + (uint32_t)b) * W + x + (uint32_t)a)];
                    outer = fmaxf(outer, fabsf(out[o] - g));
                }
            }
    }
    check(inner < 1e-7f && outer < 1e-5f, "blend: identity within diag/6, 1/16 [1 2 1; 2 4 2; 1 2 1] beyond diag/2", "%g %g",
          (double)inner, (double)outer);
    free(in);
    free(out);
    env_free(&e);
}

/* the shared eccentricity model: fovlp_ecc_* agree with fovsdf_ecc_* on random inputs */
static void test_ecc(void)
{
    int k, ok = 1, errs = 1;
    for (k = 0; k < 2000; ++k) {
        fov_display d;
        fov_ecc_model a, b;
        fov_gaze gz;
        uint32_t W = 1 + (uint32_t)(frand() * 4000.0f), H = 1 + (uint32_t)(frand() * 3000.0f);
        float fov = 10.0f + frand() * 150.0f, x = frand() * (float)W * 1.4f - 0.2f * (float)W, y = frand() * (float)H;
        fov_result ra, rb;
        memset(&d, 0, sizeof d);
        if (k % 3 == 1) d.fov_y_deg = 20.0f + frand() * 100.0f;
        if (k % 3 == 2) { d.pixel_pitch_mm = 0.1f + frand() * 0.3f; d.distance_mm = 300.0f + frand() * 600.0f; }
        d.axis_dx = frand() * 10.0f - 5.0f;
        gz.x = frand() * (float)W; gz.y = frand() * (float)H;
        ra = fovlp_ecc_init(&a, &d, fov, W, H, gz);
        rb = fovsdf_ecc_init(&b, &d, fov, W, H, gz);
        if (ra != rb || memcmp(&a, &b, sizeof a) != 0) ok = 0;
        if (fabsf(fovlp_ecc_deg(&a, x, y) - fovsdf_ecc_deg(&b, x, y)) > 0.0f || fabsf(fovlp_ecc_ppd(&a) - fovsdf_ecc_ppd(&b)) > 0.0f) ok = 0;
    }
    check(ok, "eccentricity: fovlp_ecc_init/deg/ppd identical to fovsdf's on 2000 random displays, gazes and points", " ");
    {
        fov_ecc_model m;
        fov_gaze gz = { 1, 1 }, bad = { NAN, 1 };
        fov_display d;
        memset(&d, 0, sizeof d);
        errs = fovlp_ecc_init(&m, NULL, 60, 0, 10, gz) == FOV_ERR_INVALID_ARG && fovlp_ecc_init(&m, NULL, 60, 10, 10, bad) == FOV_ERR_NOT_FINITE &&
               fovlp_ecc_init(NULL, NULL, 60, 10, 10, gz) == FOV_ERR_NULL && fovlp_ecc_init(&m, &d, 0, 10, 10, gz) == FOV_ERR_INVALID_ARG;
        check(errs, "eccentricity: bad sizes, NaN gaze, NULL, no field of view rejected as fovsdf does", " ");
    }
}

#ifdef FOV_NO_LIBM
#define MODE "FOV_NO_LIBM"
#else
#define MODE "libm"
#endif

int main(void)
{
    printf("# fovlp.h tests (%s)\n", MODE);
    test_config();
    test_bad_input();
    test_round_trip();
    test_angles();
    test_density();
    test_aspect_match();
    test_fast_mapping();
    test_ray_counts();
    test_sampling();
    test_reconstruction();
    test_blend();
    test_ecc();
    return fovcheck_summary();
}
