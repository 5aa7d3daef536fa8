/*
 * test_fovsdf_acuity.c - fovsdf's acuity-driven foveation: fovsdf_config_acuity and the
 * quarter level (config.quarter_deg) of FIPR and CONE_FOV.
 *
 * Build and run from the repository root (C99, also as C++):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovsdf_acuity.c -lm -o build/tests/t
 * Output: "PASS name" / "FAIL name: detail" lines, then "N passed, N failed".
 * Expected values are computed here from the published model (MAR(e) = 1 arcmin + 1.32
 * arcmin per degree, Guenter et al. 2012, "Foveated 3D Graphics") and the display geometry
 * in double precision, or from renders of the classic tracer; never from the code under test.
 *
 *   1. the derived parameters against the model, monotone in the display's pixels per degree
 *      and in the quality knob; method and the other fields untouched; bad input.
 *   2. a display coarser than the eye out to E (4 px per degree: E = 10.6 degrees) gets no
 *      reduction inside E: every pixel there traces its own rays (the mask output).
 *   3. the quarter level: fewer evaluations than the mid level alone, the image before
 *      quarter_deg identical to quarter_deg 0's, a smooth image reconstructed within the
 *      bilinear error (no seam, no shift), the mask output, bad quarter_deg rejected.
 *   4. level_filter: less error against a 16-spp ground truth on a checkerboard floor, the
 *      same evaluations, an untextured image unchanged, bad values rejected; refine_contrast:
 *      more pixels traced, less error, bad values rejected.
 *   5. level_filter 2 (the albedo per pixel on the taps' tangent planes): nearer full
 *      resolution than level_filter 1 on the checkerboard, the same evaluations, an
 *      untextured image as the point samples'; geometric refinement (refine_depth,
 *      refine_normal_deg, refine_material): a refined pixel is the full-resolution pixel bit
 *      for bit, a scene without silhouettes, creases or second materials costs no
 *      refinement, the cost monotone in each threshold, nearer full resolution, bad values
 *      rejected with code and message.
 */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI_D 3.14159265358979323846

typedef struct logrec { int calls; int32_t code; char msg[256]; } logrec;
static void rec_logger(const char *tag, uint32_t level, int32_t code, const char *msg,
                       uint32_t line, void *user)
{
    logrec *r = (logrec *)user;
    (void)tag; (void)level; (void)line;
    r->calls++;
    r->code = code;
    snprintf(r->msg, sizeof r->msg, "%s", msg ? msg : "");
}

/* the model's eccentricity from which `density` linear samples per pixel suffice, for a display
   of ppd pixels per degree (double; the published values, quality q) */
/* fov_eye's documented default quality (NULL eye): samples at most 0.5 MAR apart */
#define Q0 0.5

static double model_ecc(double ppd, double density, double q)
{
    double e = (1.0 / (ppd * density * q) - 1.0 / 60.0) / (1.32 / 60.0);
    return e < 0.0 ? 0.0 : (e > 180.0 ? 180.0 : e);
}
/* pixels per degree at the axis of a display whose H pixels span fov_y degrees */
static double ppd_of(double fov_y, uint32_t H)
{
    return 0.5 * (double)H / tan(0.5 * fov_y * PI_D / 180.0) * PI_D / 180.0;
}

static fovsdf_camera cam_make(uint32_t W, uint32_t H, float fov_y)
{
    fovsdf_camera c;
    fovsdf_camera_init(&c, W, H);
    c.fov_y_deg = fov_y;
    return c;
}

static void test_params(void)
{
    static const float fovs[6] = { 100.0f, 60.0f, 45.0f, 30.0f, 20.0f, 10.0f };
    static const float qs[5] = { 0.5f, 0.75f, 1.0f, 1.5f, 2.0f };
    float prev_f = 1e9f, prev_q = 1e9f;
    int i, ok_m = 1, ok_v = 1;
    fovsdf_camera cam = cam_make(640, 360, 45.0f);
    fovsdf_config cfg, before;
    fov_eye eye;
    logrec lr;
    fov_result r;
    /* pixels per degree grows as the same pixels span a smaller field */
    for (i = 0; i < 6; ++i) {
        double ppd = ppd_of((double)fovs[i], 360), eh = model_ecc(ppd, 0.5, Q0),
               eq = model_ecc(ppd, 0.25, Q0);
        cfg = fovsdf_config_default();
        cfg.method = FOVSDF_METHOD_CONE_FOV;
        cfg.display.fov_y_deg = fovs[i];
        r = fovsdf_config_acuity(&cfg, &cam, NULL);
        if (r != FOV_OK) ok_v = 0;
        if (fabs((double)cfg.acuity.fovea_deg - (eh > 1e-3 ? eh : 1e-3)) > 2e-3 * (1.0 + eh) ||
            fabs((double)cfg.quarter_deg - (eq < 180.0 ? eq : 0.0)) > 2e-3 * (1.0 + eq)) {
            ok_v = 0;
            printf("INFO fov_y %g ppd %g: fovea %g (model %g) quarter %g (model %g)\n",
                   (double)fovs[i], ppd, (double)cfg.acuity.fovea_deg, eh,
                   (double)cfg.quarter_deg, eq);
        }
        if (cfg.acuity.fovea_deg > prev_f || cfg.quarter_deg > prev_q) ok_m = 0;
        if (cfg.refresh != 1u || cfg.fov_mask != (uint32_t)FOVSDF_MASK_FOVEA ||
            cfg.level_filter != 2u || !(cfg.refine_depth > 0.0f) ||
            !(cfg.refine_normal_deg > 0.0f) || cfg.refine_material != 1u)
            ok_v = 0;
        prev_f = cfg.acuity.fovea_deg; prev_q = cfg.quarter_deg;
    }
    check(ok_v, "acuity_params_match_model",
          "fovea = e_half, quarter = e_quarter, refresh 1, level_filter 2, refinement on");
    check(ok_m, "acuity_params_monotone_in_ppd", "a finer display has a smaller full-res region");
    /* the 640x360, 45-degree display: 7.58 px/degree; at quality 0.5, e_half
       (60 / (7.58 0.5 0.5) - 1) / 1.32 = 23.2, e_quarter 47.2 */
    cfg = fovsdf_config_default();
    cfg.display.fov_y_deg = 45.0f;
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    check(r == FOV_OK && fabs((double)cfg.acuity.fovea_deg - 23.2) < 0.1 &&
              fabs((double)cfg.quarter_deg - 47.2) < 0.1,
          "acuity_640x360_45deg", "fovea %g quarter %g", (double)cfg.acuity.fovea_deg,
          (double)cfg.quarter_deg);
    /* the quality knob: safer (smaller) quality, a larger full-resolution region */
    ok_m = 1; prev_f = -1.0f; prev_q = -1.0f;
    for (i = 4; i >= 0; --i) {
        memset(&eye, 0, sizeof eye);
        eye.quality = qs[i];
        cfg = fovsdf_config_default();
        cfg.display.fov_y_deg = 45.0f;
        if (fovsdf_config_acuity(&cfg, &cam, &eye) != FOV_OK) ok_m = 0;
        if (fabs((double)cfg.acuity.fovea_deg - model_ecc(ppd_of(45.0, 360), 0.5, (double)qs[i])) >
            0.01)
            ok_m = 0;
        if (cfg.acuity.fovea_deg <= prev_f || cfg.quarter_deg <= prev_q) ok_m = 0;
        prev_f = cfg.acuity.fovea_deg; prev_q = cfg.quarter_deg;
    }
    check(ok_m, "acuity_params_monotone_in_quality", "fovea grows as quality falls");
    /* the monitor geometry (pixel pitch and distance), the camera's field of view unused */
    cfg = fovsdf_config_default();
    cfg.display.pixel_pitch_mm = 0.3113f; cfg.display.distance_mm = 600.0f;
    cam = cam_make(1920, 1080, 31.0f);
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    {
        double ppd = 600.0 / 0.3113 * PI_D / 180.0;
        check(r == FOV_OK && fabs((double)cfg.acuity.fovea_deg - model_ecc(ppd, 0.5, Q0)) < 0.01 &&
                  fabs((double)cfg.quarter_deg - model_ecc(ppd, 0.25, Q0)) < 0.01,
              "acuity_monitor_27in_60cm", "ppd %g fovea %g quarter %g", ppd,
              (double)cfg.acuity.fovea_deg, (double)cfg.quarter_deg);
    }
    /* only the foveation fields change; a non-foveated method stays */
    cfg = fovsdf_config_default();
    cfg.method = FOVSDF_METHOD_CLASSIC; cfg.spp = 4; cfg.eps_px = 0.5f; cfg.seed = 7;
    cfg.refresh = 4; cfg.fov_mask = FOVSDF_MASK_EDGES; cfg.acuity.outer_deg = 3.0f;
    before = cfg;
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    cfg.acuity = before.acuity; cfg.quarter_deg = before.quarter_deg;
    cfg.refresh = before.refresh; cfg.fov_mask = before.fov_mask;
    cfg.level_filter = before.level_filter;
    cfg.refine_depth = before.refine_depth; cfg.refine_normal_deg = before.refine_normal_deg;
    cfg.refine_material = before.refine_material;
    check(r == FOV_OK && memcmp(&cfg, &before, sizeof cfg) == 0, "acuity_other_fields_kept",
          "r %d", (int)r);
    /* the result resolves (outer_deg cleared, quarter_deg >= fovea) */
    cfg = before;
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    check(r == FOV_OK && fovsdf_config_resolve(&cfg, &before) == FOV_OK, "acuity_resolves",
          "r %d", (int)r);
    /* bad input: codes and messages, *cfg unchanged */
    cam = cam_make(640, 360, 45.0f);
    check(fovsdf_config_acuity(NULL, &cam, NULL) == FOV_ERR_NULL, "acuity_null_cfg", "-");
    cfg = fovsdf_config_default();
    memset(&lr, 0, sizeof lr);
    cfg.logger.func = rec_logger; cfg.logger.user = &lr;
    before = cfg;
    r = fovsdf_config_acuity(&cfg, NULL, NULL);
    check(r == FOV_ERR_NULL && lr.calls == 1 && strstr(lr.msg, "cam") != NULL &&
              memcmp(&cfg, &before, sizeof cfg) == 0,
          "acuity_null_cam", "r %d calls %d msg '%s'", (int)r, lr.calls, lr.msg);
    memset(&eye, 0, sizeof eye);
    eye.quality = -1.0f;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, &eye);
    check(r == FOV_ERR_INVALID_ARG && lr.calls == 1 && strstr(lr.msg, "quality") != NULL &&
              memcmp(&cfg, &before, sizeof cfg) == 0,
          "acuity_bad_quality", "r %d msg '%s'", (int)r, lr.msg);
    eye.quality = NAN;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, &eye);
    check(r == FOV_ERR_NOT_FINITE && lr.calls == 1, "acuity_nan_quality", "r %d", (int)r);
    eye.quality = 0.0f;
    eye.slope_arcmin = 100.0f;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, &eye);
    check(r == FOV_ERR_INVALID_ARG && lr.calls == 1 && strstr(lr.msg, "slope_arcmin") != NULL &&
              strstr(lr.msg, "quality") == NULL && memcmp(&cfg, &before, sizeof cfg) == 0,
          "acuity_bad_slope", "r %d msg '%s'", (int)r, lr.msg);
    eye.slope_arcmin = 0.0f;
    eye.mar0_arcmin = -2.0f;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, &eye);
    check(r == FOV_ERR_INVALID_ARG && lr.calls == 1 && strstr(lr.msg, "mar0_arcmin") != NULL &&
              strstr(lr.msg, "slope") == NULL, "acuity_bad_mar0", "r %d msg '%s'", (int)r, lr.msg);
    eye.mar0_arcmin = 0.0f;
    /* a config that is invalid elsewhere: config_acuity reports resolve's error, *cfg kept */
    cfg.spp = 100000u;
    before = cfg;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    check(r != FOV_OK && lr.calls >= 1 && memcmp(&cfg, &before, sizeof cfg) == 0,
          "acuity_invalid_config_rejected", "r %d calls %d", (int)r, lr.calls);
    cfg.spp = 0u;
    before = cfg;
    cam.width = 0;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    check(r != FOV_OK && lr.calls >= 1 && memcmp(&cfg, &before, sizeof cfg) == 0,
          "acuity_bad_camera", "r %d", (int)r);
    cam.width = 640;
    cfg.display.fov_y_deg = NAN;
    lr.calls = 0;
    r = fovsdf_config_acuity(&cfg, &cam, NULL);
    check(r == FOV_ERR_NOT_FINITE && lr.calls >= 1, "acuity_nan_display", "r %d", (int)r);
}

/* built-in primitives at W x H with the camera's field of view fov_y */
typedef struct scene_t { fovsdf_builtin bi; void *mem; } scene_t;
static int scene_open(scene_t *s, uint32_t id, uint32_t W, uint32_t H, float fov_y)
{
    size_t sz = 0;
    fovsdf_builtin_size(id, &sz);
    s->mem = malloc(sz);
    if (!s->mem || fovsdf_builtin_init(id, &s->bi, s->mem, sz) != FOV_OK) return 0;
    s->bi.camera.width = W; s->bi.camera.height = H;
    if (fov_y > 0.0f) s->bi.camera.fov_y_deg = fov_y;
    return 1;
}

typedef struct frame_t { float *rgb; uint8_t *mask; fovsdf_stats st; } frame_t;
static int render(const fovsdf_config *cfg, const fovsdf_scene *sc, const fovsdf_camera *cam,
                  frame_t *fr)
{
    fovsdf_ctx ctx;
    fovsdf_output out;
    fov_gaze g;
    size_t n = (size_t)cam->width * cam->height;
    g.x = 0.5f * (float)cam->width; g.y = 0.5f * (float)cam->height;
    if (fovsdf_init(&ctx, cfg, sc, cam, g, NULL, 0) != FOV_OK) return 0;
    fovsdf_output_init(&out);
    out.rgb = fr->rgb; out.mask = fr->mask;
    memset(fr->mask, 9, n);
    fovsdf_stats_init(&fr->st);
    return fovsdf_render_rows(&ctx, 0, cam->height, &out, &fr->st) == FOV_OK;
}
static void frame_alloc(frame_t *f, size_t n)
{
    f->rgb = (float *)calloc(3 * n, sizeof(float));
    f->mask = (uint8_t *)calloc(n, 1);
}
static void frame_free(frame_t *f) { free(f->rgb); free(f->mask); }

/* eccentricity of pixel (x, y) for a gaze at the centre, from the display's geometry (double) */
static double ecc_of(double x, double y, uint32_t W, uint32_t H, double f_px)
{
    double dx = x + 0.5 - 0.5 * W, dy = y + 0.5 - 0.5 * H;
    return atan(sqrt(dx * dx + dy * dy) / f_px) * 180.0 / PI_D;
}

static void test_coarse_display(void)
{
    /* 4 px per degree at the axis: f = 4 * 180 / pi = 229.2 px; 640 x 90 reaches 55 degrees
       of eccentricity in its corners (the default quality 0.5: E = e_full 22 degrees, e_half
       44.7: beyond it, a reduction) */
    const uint32_t W = 640, H = 90;
    const double f_px = 4.0 * 180.0 / PI_D, E = model_ecc(4.0, 1.0, Q0);
    const float fov_y = (float)(2.0 * atan(0.5 * H / f_px) * 180.0 / PI_D);
    scene_t s;
    frame_t fr;
    uint32_t m, x, y;
    if (!check(scene_open(&s, FOVSDF_SCENE_PRIMITIVES, W, H, fov_y), "coarse_scene", "-")) return;
    frame_alloc(&fr, (size_t)W * H);
    check(E > 21.0 && E < 23.0, "coarse_model_e_full", "E %g", E);
    for (m = 0; m < 2; ++m) {
        fovsdf_config cfg = fovsdf_config_default();
        long inside = 0, bad = 0, reduced = 0;
        cfg.method = m ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV;
        cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
        if (fovsdf_config_acuity(&cfg, &s.bi.camera, NULL) != FOV_OK ||
            !render(&cfg, &s.bi.scene, &s.bi.camera, &fr)) {
            check(0, "coarse_render", "-");
            continue;
        }
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                double e = ecc_of(x, y, W, H, f_px);
                uint8_t k = fr.mask[(size_t)y * W + x];
                if (e <= E) { ++inside; if (k != 1u) ++bad; }
                else if (k != 1u) ++reduced;
            }
        check(inside > 5000 && bad == 0, fovcheck_name("coarse_no_reduction_inside_E_%s",
                                                       m ? "fipr" : "cone_fov"),
              "%ld of %ld pixels inside E = %.2f degrees not traced", bad, inside, E);
        check(reduced > 0, fovcheck_name("coarse_reduction_outside_%s", m ? "fipr" : "cone_fov"),
              "%ld pixels reduced beyond E", reduced);
    }
    frame_free(&fr);
    free(s.mem);
}

/* a tilted plane (a smooth image under depth shading) */
static float plane_sdf(const float p[3], void *user)
{
    (void)user;
    return 0.28f * p[0] + 0.2f * p[1] + 0.9391f * p[2] + 2.0f; /* unit normal */
}

static void test_quarter(void)
{
    const uint32_t W = 192, H = 108;
    scene_t s;
    frame_t q, nq, cl;
    uint32_t m;
    size_t n = (size_t)W * H, i;
    fovsdf_config cfg;
    fov_result r;
    logrec lr;
    if (!check(scene_open(&s, FOVSDF_SCENE_PRIMITIVES, W, H, 45.0f), "quarter_scene", "-")) return;
    frame_alloc(&q, n); frame_alloc(&nq, n); frame_alloc(&cl, n);
    for (m = 0; m < 4; ++m) {
        const char *nm = (m & 1) ? "fipr" : "cone_fov";
        fov_ecc_model em;
        fov_gaze g;
        long before = 0, diff = 0, qpx = 0, qbad = 0;
        cfg = fovsdf_config_default();
        cfg.method = (m & 1) ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV;
        cfg.heuristic_start = m >= 2 ? 1u : 0u;
        cfg.acuity.fovea_deg = 6.0f;
        cfg.fov_mask = FOVSDF_MASK_FOVEA;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &nq)) {
            check(0, "quarter_render", "-");
            continue;
        }
        cfg.quarter_deg = 12.0f;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &q)) {
            check(0, "quarter_render", "-");
            continue;
        }
        g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
        fovsdf_ecc_init(&em, NULL, 45.0f, W, H, g);
        for (i = 0; i < n; ++i) {
            double e = ecc_of((double)(i % W), (double)(i / W), W, H, (double)em.f_px);
            if (e < 12.0 - 1e-3) {
                ++before;
                if (memcmp(&q.rgb[3 * i], &nq.rgb[3 * i], 3 * sizeof(float)) != 0 ||
                    q.mask[i] != nq.mask[i])
                    ++diff;
                if (q.mask[i] == 3u) ++qbad;
            } else if (e > 12.0 + 1e-3) {
                qpx += q.mask[i] == 3u;
                if (q.mask[i] != 3u) ++qbad;
            }
        }
        check(before > 1000 && diff == 0, fovcheck_name("quarter_same_before_%s_h%u", nm, m >> 1),
              "%ld of %ld pixels before quarter_deg differ", diff, before);
        check(qpx > 1000 && qbad == 0, fovcheck_name("quarter_mask3_%s_h%u", nm, m >> 1),
              "%ld quarter pixels, %ld misplaced", qpx, qbad);
        check(q.st.evals < nq.st.evals && q.st.evals_lowres < nq.st.evals_lowres &&
                  q.st.evals_normal < nq.st.evals_normal,
              fovcheck_name("quarter_fewer_evals_%s_h%u", nm, m >> 1),
              "evals %llu (lowres %llu, normals %llu) against %llu (%llu, %llu)",
              (unsigned long long)q.st.evals, (unsigned long long)q.st.evals_lowres,
              (unsigned long long)q.st.evals_normal, (unsigned long long)nq.st.evals,
              (unsigned long long)nq.st.evals_lowres, (unsigned long long)nq.st.evals_normal);
    }
    /* refresh 2 and 4 with the quarter level: a static scene reaches the refresh-1 image after
       `refresh` frames */
    for (m = 2; m <= 4; m += 2) {
        fovsdf_ctx ctx;
        fovsdf_output o;
        fov_gaze g;
        uint32_t fr;
        cfg = fovsdf_config_default();
        cfg.method = FOVSDF_METHOD_CONE_FOV;
        cfg.acuity.fovea_deg = 6.0f;
        cfg.quarter_deg = 12.0f;
        cfg.level_filter = 1;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &nq)) break;
        memset(q.rgb, 0, 3 * n * sizeof(float));
        g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
        cfg.refresh = m;
        for (fr = 0; fr < m; ++fr) {
            cfg.frame = 5u + fr;
            fovsdf_init(&ctx, &cfg, &s.bi.scene, &s.bi.camera, g, NULL, 0);
            fovsdf_output_init(&o);
            o.rgb = q.rgb;
            fovsdf_render_rows(&ctx, 0, H, &o, NULL);
        }
        check(memcmp(q.rgb, nq.rgb, 3 * n * sizeof(float)) == 0,
              fovcheck_name("quarter_refresh_%u_converges", m), "images differ");
    }
    /* a smooth image (depth shading of a tilted plane): the quarter level, the band and the
       mid level reconstruct the traced image within the bilinear error of its curvature; a
       tap shifted by one pixel would err by the gradient (up to 3e-3 per pixel here) */
    {
        fovsdf_scene ps;
        fovsdf_camera cam = cam_make(W, H, 60.0f);
        double worst = 0.0, grad = 0.0;
        fovsdf_scene_init(&ps);
        ps.dist = plane_sdf;
        ps.t_max = 30.0f;
        cam.pos[0] = 0.0f; cam.pos[1] = 0.0f; cam.pos[2] = 3.0f;
        cam.target[0] = 0.0f; cam.target[1] = 0.0f; cam.target[2] = 0.0f;
        for (m = 0; m < 2; ++m) {
            uint32_t x, y;
            long nq3 = 0;
            cfg = fovsdf_config_default();
            cfg.shading = FOVSDF_SHADE_DEPTH;
            if (m == 0 && !render(&cfg, &ps, &cam, &cl)) { check(0, "smooth_render", "-"); break; }
            cfg.method = m ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV;
            cfg.acuity.fovea_deg = 3.0f;
            cfg.fov_mask = FOVSDF_MASK_FOVEA;
            cfg.quarter_deg = 8.0f;
            if (!render(&cfg, &ps, &cam, &q)) { check(0, "smooth_render", "-"); break; }
            worst = 0.0; grad = 0.0;
            for (y = 2; y + 2 < H; ++y)
                for (x = 2; x + 2 < W; ++x) {
                    size_t k = (size_t)y * W + x;
                    double d = fabs((double)q.rgb[3 * k] - (double)cl.rgb[3 * k]);
                    double gx = fabs((double)cl.rgb[3 * k + 3] - (double)cl.rgb[3 * k]);
                    if (q.mask[k] == 3u) ++nq3;
                    if (d > worst) worst = d;
                    if (gx > grad) grad = gx;
                }
            check(nq3 > 1000 && grad > 1e-3 && worst < 0.15 * grad,
                  fovcheck_name("quarter_smooth_%s", m ? "fipr" : "cone_fov"),
                  "largest error %.3g, gradient %.3g per pixel, %ld quarter pixels", worst,
                  grad, nq3);
        }
    }
    /* bad quarter_deg: codes and messages */
    {
        static const float bad[4] = { -1.0f, 3.0f, 181.0f, 0.0f };
        static const fov_result want[4] = { FOV_ERR_INVALID_ARG, FOV_ERR_INVALID_ARG,
                                            FOV_ERR_INVALID_ARG, FOV_ERR_NOT_FINITE };
        fovsdf_config out;
        int k;
        for (k = 0; k < 6; ++k) {
            cfg = fovsdf_config_default();
            cfg.method = FOVSDF_METHOD_CONE_FOV;
            memset(&lr, 0, sizeof lr);
            cfg.logger.func = rec_logger; cfg.logger.user = &lr;
            cfg.quarter_deg = k < 3 ? bad[k] : (k == 3 ? NAN : (k == 4 ? INFINITY : 7.5f));
            r = fovsdf_config_resolve(&cfg, &out);
            if (k < 5)
                check(r == want[k < 3 ? k : 3] && lr.calls == 1 && strstr(lr.msg, "quarter_deg"),
                      fovcheck_name("quarter_bad_%d", k), "quarter_deg %g: r %d msg '%s'",
                      (double)cfg.quarter_deg, (int)r, lr.msg);
            else
                check(r == FOV_OK, "quarter_equal_fovea_ok", "r %d", (int)r);
        }
        /* below a given fovea; and the init path reports it too */
        cfg = fovsdf_config_default();
        cfg.method = FOVSDF_METHOD_FIPR;
        cfg.acuity.fovea_deg = 10.0f;
        cfg.quarter_deg = 9.0f;
        memset(&lr, 0, sizeof lr);
        cfg.logger.func = rec_logger; cfg.logger.user = &lr;
        {
            fovsdf_ctx ctx;
            fov_gaze g = { 10.0f, 10.0f };
            r = fovsdf_init(&ctx, &cfg, &s.bi.scene, &s.bi.camera, g, NULL, 0);
        }
        check(r == FOV_ERR_INVALID_ARG && strstr(lr.msg, "fovea") != NULL,
              "quarter_below_fovea_init", "r %d msg '%s'", (int)r, lr.msg);
    }
    frame_free(&q); frame_free(&nq); frame_free(&cl);
    free(s.mem);
}

/* level_filter: the levels' samples take their cell's mean albedo. Against a 16-spp ground
   truth (the image the eye would see), the periphery's error of the checkerboard floor drops;
   an untextured scene's image does not change; bad values are rejected. */
/* a foveated config without shadows, the fovea only in the mask, a quarter level and the given
   level filter: the setting of the level-filter and refinement tests */
static fovsdf_config level_cfg(uint32_t method, float fovea, float quarter, uint32_t lf)
{
    fovsdf_config cfg = fovsdf_config_default();
    cfg.method = method;
    cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
    cfg.fov_mask = FOVSDF_MASK_FOVEA;
    cfg.acuity.fovea_deg = fovea;
    cfg.quarter_deg = quarter;
    cfg.level_filter = lf;
    return cfg;
}

/* the plane of test_quarter in one colour (untextured), CONE_FOV with a quarter level: the
   largest channel difference between level_filter 0 and level_filter lf (-1: a render failed) */
static double untextured_diff(uint32_t lf, uint32_t W, uint32_t H, frame_t *a, frame_t *b)
{
    fovsdf_scene ps;
    fovsdf_camera cam = cam_make(W, H, 60.0f);
    fovsdf_config cfg = level_cfg(FOVSDF_METHOD_CONE_FOV, 3.0f, 8.0f, 0u);
    double worst = -1.0;
    size_t i, n = (size_t)W * H;
    cfg.fov_mask = fovsdf_config_default().fov_mask; /* the default mask, as before */
    fovsdf_scene_init(&ps);
    ps.dist = plane_sdf;
    ps.t_max = 30.0f;
    cam.pos[0] = 0.0f; cam.pos[1] = 0.0f; cam.pos[2] = 3.0f;
    if (render(&cfg, &ps, &cam, a)) {
        cfg.level_filter = lf;
        if (render(&cfg, &ps, &cam, b))
            for (worst = 0.0, i = 0; i < 3 * n; ++i)
                worst = fmax(worst, fabs((double)a->rgb[i] - (double)b->rgb[i]));
    }
    return worst;
}

static void test_level_filter(void)
{
    const uint32_t W = 192, H = 108;
    size_t n = (size_t)W * H, i;
    scene_t s;
    frame_t gt, a, b;
    fovsdf_config cfg, out;
    fov_ecc_model em;
    fov_gaze g;
    uint32_t m;
    if (!check(scene_open(&s, FOVSDF_SCENE_PRIMITIVES, W, H, 45.0f), "lf_scene", "-")) return;
    frame_alloc(&gt, n); frame_alloc(&a, n); frame_alloc(&b, n);
    cfg = fovsdf_config_ground_truth();
    cfg.spp = 16;
    cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
    if (!check(render(&cfg, &s.bi.scene, &s.bi.camera, &gt), "lf_gt", "-")) goto done;
    g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
    fovsdf_ecc_init(&em, NULL, 45.0f, W, H, g);
    for (m = 0; m < 2; ++m) {
        double e0 = 0.0, e1 = 0.0;
        long cnt = 0;
        cfg = fovsdf_config_default();
        cfg.method = m ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV;
        cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
        cfg.acuity.fovea_deg = 4.0f;
        cfg.fov_mask = FOVSDF_MASK_FOVEA;
        cfg.quarter_deg = 10.0f;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &a)) break;
        cfg.level_filter = 1;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &b)) break;
        for (i = 0; i < n; ++i) {
            size_t k;
            if (a.mask[i] == 1u) continue;
            ++cnt;
            for (k = 0; k < 3; ++k) {
                double d0 = (double)a.rgb[3 * i + k] - (double)gt.rgb[3 * i + k];
                double d1 = (double)b.rgb[3 * i + k] - (double)gt.rgb[3 * i + k];
                e0 += d0 * d0; e1 += d1 * d1;
            }
        }
        check(cnt > 10000 && e1 < 0.8 * e0,
              fovcheck_name("lf_less_error_%s", m ? "fipr" : "cone_fov"),
              "squared error %g against %g over %ld interpolated pixels", e1, e0, cnt);
        check(a.st.evals == b.st.evals, fovcheck_name("lf_same_evals_%s", m ? "fipr" : "cone_fov"),
              "%llu against %llu", (unsigned long long)b.st.evals, (unsigned long long)a.st.evals);
    }
    {   /* untextured: the level filter changes nothing */
        double worst = untextured_diff(1u, W, H, &a, &b);
        check(worst >= 0.0 && worst < 1e-5, "lf_untextured_unchanged", "largest difference %g",
              worst);
    }
    cfg = fovsdf_config_default();
    cfg.level_filter = 3;
    check(fovsdf_config_resolve(&cfg, &out) == FOV_ERR_INVALID_ARG, "lf_bad_value", "-");
    /* refine_contrast: pixels whose taps differ trace their own rays (more traced pixels, not
       all); the error against the ground truth drops; bad values rejected */
    {
        long tr0 = 0, tr1 = 0;
        double e0 = 0.0, e1 = 0.0;
        cfg = fovsdf_config_default();
        cfg.method = FOVSDF_METHOD_CONE_FOV;
        cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
        cfg.acuity.fovea_deg = 4.0f;
        cfg.fov_mask = FOVSDF_MASK_FOVEA;
        cfg.quarter_deg = 10.0f;
        cfg.level_filter = 1;
        if (render(&cfg, &s.bi.scene, &s.bi.camera, &a)) {
            cfg.refine_contrast = 0.1f;
            if (render(&cfg, &s.bi.scene, &s.bi.camera, &b))
                for (i = 0; i < n; ++i) {
                    size_t k;
                    tr0 += a.mask[i] == 1u;
                    tr1 += b.mask[i] == 1u;
                    for (k = 0; k < 3; ++k) {
                        double d0 = (double)a.rgb[3 * i + k] - (double)gt.rgb[3 * i + k];
                        double d1 = (double)b.rgb[3 * i + k] - (double)gt.rgb[3 * i + k];
                        e0 += d0 * d0; e1 += d1 * d1;
                    }
                }
        }
        check(tr1 > tr0 && tr1 < (long)n && e1 < 0.8 * e0, "refine_contrast_traces_edges",
              "traced %ld -> %ld of %ld, squared error %g -> %g", tr0, tr1, (long)n, e0, e1);
        cfg.refine_contrast = -0.1f;
        check(fovsdf_config_resolve(&cfg, &out) == FOV_ERR_INVALID_ARG, "refine_negative", "-");
        cfg.refine_contrast = NAN;
        check(fovsdf_config_resolve(&cfg, &out) == FOV_ERR_NOT_FINITE, "refine_nan", "-");
    }
done:
    frame_free(&gt); frame_free(&a); frame_free(&b);
    free(s.mem);
}

/* a tilted plane with one material and no silhouette in view (for the no-refinement case) */
static float wall_sdf(const float p[3], void *user)
{
    (void)user;
    return 0.1f * p[0] + 0.05f * p[1] + 0.9937f * p[2] + 2.0f; /* unit normal, facing +z */
}

static long count_mask(const frame_t *f, size_t n, uint8_t v)
{
    long k = 0;
    size_t i;
    for (i = 0; i < n; ++i) k += f->mask[i] == v;
    return k;
}

static double sq_err(const frame_t *a, const frame_t *gt, size_t n)
{
    double e = 0.0;
    size_t i;
    for (i = 0; i < 3 * n; ++i) {
        double d = (double)a->rgb[i] - (double)gt->rgb[i];
        e += d * d;
    }
    return e;
}

static void test_refine(void)
{
    const uint32_t W = 192, H = 108;
    size_t n = (size_t)W * H, i;
    scene_t s;
    frame_t gt, a, b, full; /* gt: classic (full resolution, one ray per pixel) */
    fovsdf_config cfg, base, out;
    uint32_t m;
    logrec lr;
    if (!check(scene_open(&s, FOVSDF_SCENE_PRIMITIVES, W, H, 45.0f), "refine_scene", "-")) return;
    frame_alloc(&gt, n); frame_alloc(&a, n); frame_alloc(&b, n); frame_alloc(&full, n);
    /* the reference: full resolution, one ray per pixel (the classic tracer) */
    cfg = fovsdf_config_default();
    cfg.method = FOVSDF_METHOD_CLASSIC;
    cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
    if (!check(render(&cfg, &s.bi.scene, &s.bi.camera, &gt), "refine_classic", "-")) goto done;
    /* level_filter 2: the checkerboard at each pixel's own point, so the interpolated pixels
       come far closer to full resolution's than with the cell's mean albedo */
    for (m = 0; m < 2; ++m) {
        double e1, e2;
        cfg = level_cfg(m ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV, 4.0f, 10.0f, 1u);
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &a)) break;
        cfg.level_filter = 2;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &b)) break;
        e1 = sq_err(&a, &gt, n); e2 = sq_err(&b, &gt, n);
        check(e2 < 0.5 * e1, fovcheck_name("lf2_nearer_full_res_%s", m ? "fipr" : "cone_fov"),
              "squared difference to classic %g against level_filter 1's %g", e2, e1);
        check(a.st.evals == b.st.evals, fovcheck_name("lf2_same_evals_%s", m ? "fipr" : "cone_fov"),
              "%llu against %llu", (unsigned long long)b.st.evals, (unsigned long long)a.st.evals);
    }
    {   /* untextured (one colour): level_filter 2 is the point samples' image */
        double worst = untextured_diff(2u, W, H, &a, &b);
        check(worst >= 0.0 && worst < 1e-5, "lf2_untextured_unchanged", "largest difference %g",
              worst);
    }
    /* a refined pixel is the full-resolution pixel (the fovea over the whole image; no quarter
       level, so every 2x2 cell's cone is the same) bit for bit */
    for (m = 0; m < 2; ++m) {
        long bad = 0, refined, traced0;
        base = fovsdf_config_default();
        base.method = m ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV;
        base.shading = FOVSDF_SHADE_NO_SHADOWS;
        base.fov_mask = FOVSDF_MASK_FOVEA;
        base.level_filter = 2;
        cfg = base;
        cfg.acuity.fovea_deg = 179.0f;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &full)) break;
        cfg = base;
        cfg.acuity.fovea_deg = 4.0f;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &a)) break;
        cfg.refine_depth = 0.1f; cfg.refine_normal_deg = 30.0f; cfg.refine_material = 1;
        if (!render(&cfg, &s.bi.scene, &s.bi.camera, &b)) break;
        traced0 = count_mask(&a, n, 1u);
        refined = count_mask(&b, n, 1u) - traced0;
        for (i = 0; i < n; ++i)
            if (b.mask[i] == 1u && memcmp(&b.rgb[3 * i], &full.rgb[3 * i], 3 * sizeof(float)))
                ++bad;
        check(refined > 200 && refined < (long)n / 2 && bad == 0,
              fovcheck_name("refine_pixels_are_full_res_%s", m ? "fipr" : "cone_fov"),
              "%ld refined (%ld traced before), %ld traced pixels differ from full resolution",
              refined, traced0, bad);
        check(b.st.evals > a.st.evals && sq_err(&b, &full, n) < 0.7 * sq_err(&a, &full, n),
              fovcheck_name("refine_costs_and_helps_%s", m ? "fipr" : "cone_fov"),
              "evaluations %llu -> %llu, squared difference to full resolution %g -> %g",
              (unsigned long long)a.st.evals, (unsigned long long)b.st.evals, sq_err(&a, &full, n),
              sq_err(&b, &full, n));
    }
    /* the cost is monotone in each threshold (a lower threshold refines a superset) */
    {
        static const float rd[3] = { 0.4f, 0.1f, 0.02f }, rn[3] = { 60.0f, 30.0f, 10.0f };
        long prev_t = -1;
        unsigned long long prev_e = 0;
        int ok = 1, k, which;
        for (which = 0; which < 2; ++which)
            for (k = 0, prev_t = -1, prev_e = 0; k < 3; ++k) {
                cfg = level_cfg(FOVSDF_METHOD_CONE_FOV, 4.0f, 10.0f, 2u);
                if (which == 0) cfg.refine_depth = rd[k];
                else cfg.refine_normal_deg = rn[k];
                if (!render(&cfg, &s.bi.scene, &s.bi.camera, &a)) { ok = 0; break; }
                if (count_mask(&a, n, 1u) < prev_t || a.st.evals < prev_e) ok = 0;
                prev_t = count_mask(&a, n, 1u); prev_e = a.st.evals;
            }
        check(ok, "refine_cost_monotone", "traced pixels and evaluations grow as thresholds fall");
    }
    {   /* no silhouette, crease or second material in view: no pixel refined, no evaluation more */
        fovsdf_scene ps;
        fovsdf_camera cam = cam_make(W, H, 60.0f);
        long t0, t1;
        fovsdf_scene_init(&ps);
        ps.dist = wall_sdf;
        ps.t_max = 30.0f;
        cam.pos[0] = 0.0f; cam.pos[1] = 0.0f; cam.pos[2] = 3.0f;
        cfg = level_cfg(FOVSDF_METHOD_CONE_FOV, 3.0f, 8.0f, 2u);
        if (render(&cfg, &ps, &cam, &a)) {
            cfg.refine_depth = 0.05f; cfg.refine_normal_deg = 5.0f; cfg.refine_material = 1;
            if (render(&cfg, &ps, &cam, &b)) {
                t0 = count_mask(&a, n, 1u); t1 = count_mask(&b, n, 1u);
                check(t0 == t1 && t0 < (long)n / 4 && a.st.evals == b.st.evals &&
                          count_mask(&a, n, 0u) + count_mask(&a, n, 3u) > (long)n / 2,
                      "refine_nothing_without_edges", "traced %ld -> %ld, evaluations %llu -> %llu",
                      t0, t1, (unsigned long long)a.st.evals, (unsigned long long)b.st.evals);
            }
        }
    }
    /* bad values: code and message */
    {
        static const struct { int field; float v; fov_result code; const char *word; } bad[7] = {
            { 0, -0.1f, FOV_ERR_INVALID_ARG, "refine_depth" },
            { 0, NAN, FOV_ERR_NOT_FINITE, "refine_depth" },
            { 1, -1.0f, FOV_ERR_INVALID_ARG, "refine_normal_deg" },
            { 1, 181.0f, FOV_ERR_INVALID_ARG, "refine_normal_deg" },
            { 1, INFINITY, FOV_ERR_NOT_FINITE, "refine_normal_deg" },
            { 2, 2.0f, FOV_ERR_INVALID_ARG, "refine_material" },
            { 3, 3.0f, FOV_ERR_INVALID_ARG, "level_filter" } };
        int k;
        for (k = 0; k < 7; ++k) {
            fov_result r;
            cfg = fovsdf_config_default();
            cfg.method = FOVSDF_METHOD_CONE_FOV;
            cfg.logger.func = rec_logger; cfg.logger.user = &lr;
            if (bad[k].field == 0) cfg.refine_depth = bad[k].v;
            else if (bad[k].field == 1) cfg.refine_normal_deg = bad[k].v;
            else if (bad[k].field == 2) cfg.refine_material = (uint32_t)bad[k].v;
            else cfg.level_filter = (uint32_t)bad[k].v;
            memset(&lr, 0, sizeof lr);
            r = fovsdf_config_resolve(&cfg, &out);
            check(r == bad[k].code && lr.calls == 1 && lr.code == (int32_t)bad[k].code &&
                      strstr(lr.msg, bad[k].word) != NULL,
                  fovcheck_name("refine_bad_value_%d", k), "r %d, log %d '%s'", (int)r, lr.calls,
                  lr.msg);
        }
        cfg = fovsdf_config_default();
        cfg.refine_normal_deg = 180.0f; cfg.refine_material = 1; cfg.refine_depth = 1e3f;
        cfg.level_filter = 2;
        check(fovsdf_config_resolve(&cfg, &out) == FOV_OK && out.refine_normal_deg == 180.0f &&
                  out.refine_material == 1u && out.level_filter == 2u,
              "refine_good_values", "-");
    }
done:
    frame_free(&gt); frame_free(&a); frame_free(&b); frame_free(&full);
    free(s.mem);
}

int main(void)
{
    test_params();
    test_coarse_display();
    test_quarter();
    test_level_filter();
    test_refine();
    return fovcheck_summary();
}
