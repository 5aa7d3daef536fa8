/*
 * test_fovpt_acuity.c - fovpt_config_acuity: the layer table, zone radii and selective borders
 * fovpt derives from a display and the eye model.
 *
 * Build and run from the repository root (tests/run_all.sh builds it three ways):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovpt_acuity.c -lm -o build/tests/t
 *
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed".
 * Expected values are computed here, in double, from the published acuity model: the minimum
 * angle of resolution MAR(e) = 1 + 1.32 e arc minutes (Guenter, Finch, Drucker, Tan, Snyder,
 * "Foveated 3D Graphics", 2012: 1 arc minute at the gaze, their conservative slope), the
 * allowed sample spacing quality * MAR(e), and the display's pixels per degree at its axis
 * from its geometry (a monitor: distance / pixel pitch pixels to the eye; a field of view:
 * H / 2 / tan(fov_y / 2)); pixel eccentricities by the test's own vector formula. Never from
 * the code under test. Kim et al. 2021 (Y. Kim, Y. Ko, I. Ihm, "Selective Foveated Ray Tracing
 * for Head-Mounted Displays", ISMAR 2021) give the selective borders 3.3, 5.5, 12.1, 30, 45.
 */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVPT_IMPLEMENTATION
#endif
#include "fovpt.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

static int g_log_count;
static int32_t g_log_code;
static char g_log_msg[256];
static void logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                   void *user)
{
    (void)tag; (void)level; (void)line; (void)user;
    g_log_count++;
    g_log_code = code;
    snprintf(g_log_msg, sizeof g_log_msg, "%s", msg);
}

/* the published model, in degrees */
/* fov_eye's documented default quality (NULL eye): samples at most 0.5 MAR apart */
#define Q0 0.5

static double mar_deg(double q, double e) { return q * (1.0 + 1.32 * e) / 60.0; }
/* the eccentricity where q MAR(e) ppd = s pixels */
static double ecc_of_px(double q, double ppd, double s)
{
    double e = (60.0 * s / (q * ppd) - 1.0) / 1.32;
    return e > 0.0 ? e : 0.0;
}

static void monitor(fovpt_config *c, fovpt_camera *cam, uint32_t w, uint32_t h, double dist_mm)
{
    *c = fovpt_config_default();
    c->logger.func = logger;
    fovpt_camera_init(cam, w, h);
    c->display.pixel_pitch_mm = 0.3113f;
    c->display.distance_mm = (float)dist_mm;
    cam->fov_y_deg = (float)(2.0 * atan(0.5 * h * 0.3113 / dist_mm) * 180.0 / 3.14159265358979);
}

/* the stride of the finest layer whose full-weight region reaches e */
static uint32_t stride_at(const fovpt_layers_cfg *L, double e)
{
    uint32_t n;
    for (n = L->count - 1u; n >= 1u; --n)
        if (e < (double)L->layer[n].radius_deg - 0.5 * (double)L->blend_deg) return L->layer[n].stride;
    return L->layer[0].stride;
}

/* every layer's stride within the eye's allowed spacing at its inner border, innermost 1 */
static int strides_ok(const fovpt_config *c, double q, double ppd, char *why, size_t nw)
{
    const fovpt_layers_cfg *L = &c->layers;
    double b = L->blend_deg > 0.0f ? (double)L->blend_deg : 1.0;
    uint32_t n;
    if (L->count < 2 || L->count > FOVPT_MAX_LAYERS) {
        snprintf(why, nw, "count %u", L->count);
        return 0;
    }
    if (L->layer[L->count - 1].stride != 1) {
        snprintf(why, nw, "innermost stride %u", L->layer[L->count - 1].stride);
        return 0;
    }
    for (n = 0; n + 1u < L->count; ++n) {
        double ein = (double)L->layer[n + 1].radius_deg - 0.5 * b;
        double allowed = mar_deg(q, ein) * ppd;
        if (!((double)L->layer[n].stride <= allowed * (1.0 + 1e-5))) {
            snprintf(why, nw, "layer %u stride %u > allowed %.4f at %.3f deg", n,
                     L->layer[n].stride, allowed, ein);
            return 0;
        }
        if (n >= 1 && !(L->layer[n].radius_deg > L->layer[n + 1].radius_deg)) {
            snprintf(why, nw, "radii not decreasing at %u", n);
            return 0;
        }
    }
    return 1;
}

static void t_allowed(void)
{
    static const double dists[4] = { 300.0, 600.0, 900.0, 1500.0 };
    static const double qs[3] = { 0.5, 1.0, 2.0 };
    int i, k;
    char why[160];
    for (i = 0; i < 4; ++i)
        for (k = 0; k < 3; ++k) {
            fovpt_config c;
            fovpt_camera cam;
            fov_eye eye = { 0.0f, 0.0f, (float)qs[k] };
            double ppd = dists[i] / 0.3113 * 3.14159265358979 / 180.0, mz, in, mid;
            fov_result r;
            monitor(&c, &cam, 1920, 1080, dists[i]);
            r = fovpt_config_acuity(&c, &cam, &eye);
            check(r == FOV_OK, N("acuity ok monitor %.0f mm q %.1f", dists[i], qs[k]), "%d", r);
            why[0] = 0;
            check(strides_ok(&c, qs[k], ppd, why, sizeof why),
                  N("layer strides within quality*MAR*ppd at their inner borders, %.0f mm q %.1f",
                    dists[i], qs[k]), "%s", why);
            /* zones: stride 2 from inner - overlap/2, stride 4 from middle - overlap/2 (the
               overlap in degrees at most overlap_px / ppd at the axis) */
            mz = 0.5 * 4.0 / ppd;
            in = (double)c.zones.inner_deg - mz;
            mid = (double)c.zones.middle_deg - mz;
            check(2.0 <= mar_deg(qs[k], in) * ppd * (1.0 + 1e-5) &&
                  4.0 <= mar_deg(qs[k], mid) * ppd * (1.0 + 1e-5),
                  N("zone strides 2 and 4 within the allowed spacing, %.0f mm q %.1f", dists[i],
                    qs[k]),
                  "inner %.3f middle %.3f: allowed %.3f, %.3f", (double)c.zones.inner_deg,
                  (double)c.zones.middle_deg, mar_deg(qs[k], in) * ppd, mar_deg(qs[k], mid) * ppd);
            /* not wasteful: stride 2 is not allowed a degree before the inner border */
            check(in < ecc_of_px(qs[k], ppd, 2.0) + 0.05 + mz,
                  N("zone inner border at e_half, %.0f mm q %.1f", dists[i], qs[k]),
                  "inner %.3f, e_half %.3f", (double)c.zones.inner_deg,
                  ecc_of_px(qs[k], ppd, 2.0));
            /* selective: e_np at e_full, Kim et al.'s proportions */
            {
                double ef = ecc_of_px(qs[k], ppd, 1.0), s = (double)c.selective.e_deg[3];
                double want = ef > 0.01 ? ef : 0.01;
                check(fabs(s - want) <= 1e-3 * want + 1e-4 &&
                      fabs((double)c.selective.e_deg[0] / s - 3.3 / 30.0) < 1e-4 &&
                      fabs((double)c.selective.e_deg[2] / s - 12.1 / 30.0) < 1e-4 &&
                      fabs((double)c.selective.e_deg[4] / s - 45.0 / 30.0) < 1e-4,
                      N("selective e_np = e_full, Kim et al. 2021 proportions, %.0f mm q %.1f",
                        dists[i], qs[k]),
                      "e_np %.4f want %.4f", s, want);
            }
        }
}

/* the table's properties in ppd and in quality */
static void t_monotone(void)
{
    int i, k, bad = 0, badz = 0, bads = 0;
    double prev_s[61], prev_in = 1e9, prev_mid = 1e9, prev_np = 1e9;
    char what[160] = "";
    for (i = 0; i <= 60; ++i) prev_s[i] = 0.0;
    for (i = 0; i < 40; ++i) {
        fovpt_config c;
        fovpt_camera cam;
        double dist = 200.0 + 60.0 * i; /* ppd 11 .. 144 */
        monitor(&c, &cam, 1920, 1080, dist);
        if (fovpt_config_acuity(&c, &cam, NULL) != FOV_OK) { bad = 1; break; }
        for (k = 0; k <= 60; ++k) {
            double s = (double)stride_at(&c.layers, (double)k);
            if (s < prev_s[k]) {
                bad = 1;
                snprintf(what, sizeof what, "stride at %d deg fell %.0f -> %.0f at %.0f mm", k,
                         prev_s[k], s, dist);
            }
            prev_s[k] = s;
        }
        if ((double)c.zones.inner_deg > prev_in || (double)c.zones.middle_deg > prev_mid) badz = 1;
        if ((double)c.selective.e_deg[3] > prev_np) bads = 1;
        prev_in = (double)c.zones.inner_deg;
        prev_mid = (double)c.zones.middle_deg;
        prev_np = (double)c.selective.e_deg[3];
    }
    check(!bad, "layer stride at each eccentricity non-decreasing in ppd (monitor 200 .. 2540 mm)",
          "%s", what);
    check(!badz, "zone radii non-increasing in ppd", "inner %.3f middle %.3f", prev_in, prev_mid);
    check(!bads, "selective e_np non-increasing in ppd", "%.3f", prev_np);
    bad = badz = 0;
    for (k = 0; k <= 60; ++k) prev_s[k] = 0.0;
    prev_in = prev_mid = 1e9;
    for (i = 1; i <= 30; ++i) {
        fovpt_config c;
        fovpt_camera cam;
        fov_eye eye = { 0.0f, 0.0f, 0.1f * (float)i };
        monitor(&c, &cam, 1920, 1080, 600.0);
        if (fovpt_config_acuity(&c, &cam, &eye) != FOV_OK) { bad = 1; break; }
        for (k = 0; k <= 60; ++k) {
            double s = (double)stride_at(&c.layers, (double)k);
            if (s < prev_s[k]) bad = 1;
            prev_s[k] = s;
        }
        if ((double)c.zones.inner_deg > prev_in || (double)c.zones.middle_deg > prev_mid) badz = 1;
        prev_in = (double)c.zones.inner_deg;
        prev_mid = (double)c.zones.middle_deg;
    }
    check(!bad, "layer stride at each eccentricity non-decreasing in quality (0.1 .. 3)", "-");
    check(!badz, "zone radii non-increasing in quality", "-");
}

/* the test's own eccentricity of pixel centre (x, y) for a symmetric camera, gaze g */
static double ecc_px(double f, double W, double H, double x, double y, double gx, double gy)
{
    double a[3] = { x - 0.5 * W, y - 0.5 * H, f }, b[3] = { gx - 0.5 * W, gy - 0.5 * H, f };
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    double nb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    double co = d / (na * nb);
    return acos(co > 1.0 ? 1.0 : co) * 180.0 / 3.14159265358979;
}

/* a display coarser than the eye out to E: no reduction inside E */
static void t_coarse(void)
{
    static const double Es[3] = { 4.0, 10.0, 25.0 };
    fovpt_material mat;
    fovpt_scene_desc desc;
    fovpt_scene sc;
    size_t sb = 0;
    void *smem;
    int i, m;
    fovpt_material_init(&mat);
    fovpt_scene_desc_init(&desc);
    desc.materials = &mat; desc.num_materials = 1;
    fovpt_scene_size(&desc, &sb);
    smem = malloc(sb + 16u);
    check(fovpt_scene_build(&sc, &desc, smem, sb) == FOV_OK, "empty scene builds", "-");
    for (i = 0; i < 3; ++i) {
        /* q MAR(E) ppd = 1: ppd = 60 / (1 + 1.32 E); f = ppd 180 / pi; a 200 x 120 image */
        double E = Es[i], ppd = 60.0 / (1.0 + 1.32 * E), f = ppd * 180.0 / 3.14159265358979;
        double b;
        uint32_t W = 200, H = 120, x, y;
        uint64_t inside = 0;
        fovpt_config c = fovpt_config_default();
        fovpt_camera cam;
        fov_gaze g = { 70.0f, 50.0f };
        fovpt_camera_init(&cam, W, H);
        cam.fov_y_deg = (float)(2.0 * atan(0.5 * H / f) * 180.0 / 3.14159265358979);
        c.logger.func = logger;
        check(fovpt_config_acuity(&c, &cam, NULL) == FOV_OK, N("coarse E %.0f: acuity ok", E), "-");
        b = (double)c.layers.blend_deg > 0.0 ? (double)c.layers.blend_deg : 1.0;
        check(c.layers.layer[c.layers.count - 1].stride == 1 &&
              (double)c.layers.layer[c.layers.count - 1].radius_deg - 0.5 * b >= E - 1e-3,
              N("coarse E %.0f: the stride-1 layer has full weight out to E", E),
              "radius %.3f", (double)c.layers.layer[c.layers.count - 1].radius_deg);
        check((double)c.zones.inner_deg - 0.5 * 4.0 / ppd >= E - 1e-3,
              N("coarse E %.0f: zone inner (less half the overlap) >= E", E), "inner %.3f",
              (double)c.zones.inner_deg);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x)
                if (ecc_px(f, W, H, x + 0.5, y + 0.5, g.x, g.y) < E) inside++;
        for (m = 0; m < 2; ++m) {
            fovpt_ctx ctx;
            fovpt_stats st;
            size_t n = 0;
            void *mem;
            fov_result r;
            uint32_t top;
            c.method = m ? FOVPT_METHOD_ZONES : FOVPT_METHOD_LAYERS;
            fovpt_memory_size(&c, &cam, &n);
            mem = malloc(n + 16u);
            r = fovpt_init(&ctx, &c, &sc, &cam, g, mem, n);
            fovpt_stats_init(&st);
            if (r == FOV_OK) r = fovpt_trace_rows(&ctx, 0, 0, H, &st);
            top = m ? 2u : c.layers.count - 1u;
            check(r == FOV_OK && st.layer_targets[top] >= inside,
                  N("coarse E %.0f %s: every pixel inside E traced at stride 1 (%llu >= %llu)", E,
                    m ? "zones" : "layers", (unsigned long long)st.layer_targets[top],
                    (unsigned long long)inside), "r %d", r);
            free(mem);
        }
    }
    {
        /* coarser than the eye across the image: the stride-1 layer to 179.5 degrees */
        fovpt_config c = fovpt_config_default();
        fovpt_camera cam;
        fovpt_camera_init(&cam, 64, 36);
        cam.fov_y_deg = 120.0f;
        check(fovpt_config_acuity(&c, &cam, NULL) == FOV_OK && c.layers.count == 2 &&
              c.layers.layer[1].stride == 1 && c.layers.layer[1].radius_deg >= 179.0f,
              "coarse everywhere: two layers, stride 1 out to 179.5 degrees", "count %u",
              c.layers.count);
    }
    free(smem);
}

static void t_errors(void)
{
    static const struct { float m0, sl, q; int32_t code; const char *what; } B[7] = {
        { NAN, 0, 0, FOV_ERR_NOT_FINITE, "mar0 NaN" },
        { 0, INFINITY, 0, FOV_ERR_NOT_FINITE, "slope inf" },
        { 0, 0, -INFINITY, FOV_ERR_NOT_FINITE, "quality -inf" },
        { -1.0f, 0, 0, FOV_ERR_INVALID_ARG, "mar0 -1" },
        { 61.0f, 0, 0, FOV_ERR_INVALID_ARG, "mar0 61" },
        { 0, -0.5f, 0, FOV_ERR_INVALID_ARG, "slope -0.5" },
        { 0, 0, 101.0f, FOV_ERR_INVALID_ARG, "quality 101" } };
    int i;
    fovpt_config c, keep;
    fovpt_camera cam;
    monitor(&c, &cam, 640, 360, 600.0);
    for (i = 0; i < 7; ++i) {
        fov_eye eye = { B[i].m0, B[i].sl, B[i].q };
        fov_result r;
        keep = c;
        g_log_count = 0; g_log_code = 0;
        r = fovpt_config_acuity(&c, &cam, &eye);
        check((int32_t)r == B[i].code && g_log_count == 1 && g_log_code == B[i].code &&
              strstr(g_log_msg, "eye.") != NULL && memcmp(&c, &keep, sizeof c) == 0,
              N("bad eye %s: code %d, one message naming the field, cfg unchanged", B[i].what,
                (int)B[i].code), "r %d, %d messages, code %d, '%s'", r, g_log_count,
              (int)g_log_code, g_log_msg);
    }
    check(fovpt_config_acuity(NULL, &cam, NULL) == FOV_ERR_NULL, "NULL cfg: FOV_ERR_NULL", "-");
    g_log_count = 0;
    check(fovpt_config_acuity(&c, NULL, NULL) == FOV_ERR_NULL && g_log_count == 1,
          "NULL cam: FOV_ERR_NULL, logged", "%d messages", g_log_count);
    keep = c;
    c.display.distance_mm = 0.0f; /* a pitch without a distance */
    g_log_count = 0;
    check(fovpt_config_acuity(&c, &cam, NULL) == FOV_ERR_INVALID_ARG && g_log_count == 1,
          "bad display: FOV_ERR_INVALID_ARG, logged", "%d messages", g_log_count);
    c = keep;
    cam.width = 0;
    g_log_count = 0;
    check(fovpt_config_acuity(&c, &cam, NULL) == FOV_ERR_INVALID_ARG && g_log_count == 1 &&
          memcmp(&c, &keep, sizeof c) == 0,
          "bad camera: FOV_ERR_INVALID_ARG, logged, cfg unchanged", "%d messages", g_log_count);
}

static void t_fields(void)
{
    fovpt_config c, a, b2;
    fovpt_camera cam;
    fovpt_layers_cfg p;
    uint32_t n;
    int same;
    monitor(&c, &cam, 1920, 1080, 600.0);
    c.method = FOVPT_METHOD_ZONES; c.spp = 3; c.seed = 77; c.zones.overlap_px = 6.0f;
    c.selective.n_sd[0] = 16; c.temporal.smooth = 1; c.layers.blend_deg = 2.0f;
    c.layers.layer[3].spp = 9; c.layers.layer[2].spp = 5; c.layers.layer[0].spp = 2;
    a = c;
    check(fovpt_config_acuity(&a, &cam, NULL) == FOV_OK, "acuity on a customised config", "-");
    check(a.method == c.method && a.spp == 3 && a.seed == 77 && a.zones.overlap_px >= 6.0f &&
          a.zones.overlap_px <= 6.0f && a.selective.n_sd[0] == 16 && a.temporal.smooth == 1 &&
          a.layers.blend_deg >= 2.0f && a.layers.blend_deg <= 2.0f &&
          memcmp(&a.display, &c.display, sizeof c.display) == 0 &&
          memcmp(&a.selective.tau, &c.selective.tau, sizeof c.selective.tau) == 0,
          "fields outside the foveation parameters stay as the caller set them", "-");
    n = a.layers.count;
    check(a.layers.layer[n - 1].spp == 3 && a.zones.spp[0] == 3,
          "spp: the stride-1 layer and the inner zone take cfg.spp (budget 0)", "%u %u",
          a.layers.layer[n - 1].spp, a.zones.spp[0]);
    check(a.layers.bspline == 1 && a.zones.bspline == 1 && a.layers.hollow == 1 &&
              a.zones.hollow == 1 && a.layers.cell_jitter == 1 && a.zones.cell_jitter == 1 &&
              a.layers.clamp_white >= 1.0f && a.layers.clamp_white <= 1.0f,
          "B-spline, hollow, cell_jitter and clamp_white 1 for layers and zones", "%u %u %u %u",
          a.layers.bspline, a.zones.bspline, a.layers.hollow, a.zones.hollow);
    b2 = a;
    check(fovpt_config_acuity(&b2, &cam, NULL) == FOV_OK && memcmp(&a, &b2, sizeof a) == 0,
          "a second call changes nothing", "-");
    check(fovpt_config_resolve(&a, &b2) == FOV_OK, "the result validates", "-");
    same = fovpt_layers_preset(&p, FOVPT_LAYERS_KTH_RADIUS) == FOV_OK && p.count == 4 &&
           p.layer[1].radius_deg >= 20.0f && p.layer[1].radius_deg <= 20.0f &&
           p.layer[3].radius_deg >= 6.0f && p.layer[3].radius_deg <= 6.0f;
    check(same, "preset FOVPT_LAYERS_KTH_RADIUS still 6/10/20 degrees", "-");
    {
        /* all-zero display: the camera's frustum, here off-axis (f = H / (t + b)) */
        fovpt_config z = fovpt_config_default();
        fovpt_camera oc;
        char why[160] = "";
        double f, ppd;
        fovpt_camera_init(&oc, 800, 600);
        oc.tan_left = 1.2f; oc.tan_right = 1.4666667f; oc.tan_top = 0.9f; oc.tan_bottom = 1.1f; /* 4:3 */
        f = 600.0 / (0.9 + 1.1);
        ppd = f * 3.14159265358979 / 180.0;
        check(fovpt_config_acuity(&z, &oc, NULL) == FOV_OK && strides_ok(&z, Q0, ppd, why, 160) &&
              fabs((double)z.selective.e_deg[3] - ecc_of_px(Q0, ppd, 1.0)) < 2e-3,
              "off-axis camera, no display: the frustum's ppd (H / (t + b) pixels)", "%s", why);
    }
}

/* The mean over a stride-4 lattice's pixel offsets t = 0, 1/4, 1/2, 3/4 of the sum of squared
   weights of filter f (0 Catmull-Rom, 1 cubic B-spline, 2 Lanczos-3 normalised), computed here
   in double: the variance of independent lattice noise after the filter, per axis. */
static double sumsq(int f)
{
    double acc = 0.0;
    int i, k;
    for (i = 0; i < 4; ++i) {
        double t = i / 4.0, u = 1.0 - t, w[6], ws = 0.0, q = 0.0;
        int n = f == 2 ? 6 : 4;
        if (f == 0) {
            w[0] = (-t * t * t + 2 * t * t - t) / 2; w[1] = (3 * t * t * t - 5 * t * t + 2) / 2;
            w[2] = (-3 * t * t * t + 4 * t * t + t) / 2; w[3] = (t * t * t - t * t) / 2;
        } else if (f == 1) {
            w[0] = u * u * u / 6.0; w[1] = (3 * t * t * t - 6 * t * t + 4) / 6.0;
            w[2] = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0; w[3] = t * t * t / 6.0;
        } else {
            for (k = 0; k < 6; ++k) {
                double x = t - (k - 2), px = 3.14159265358979 * x;
                w[k] = fabs(x) < 1e-9 ? 1.0 : 3.0 * sin(px) * sin(px / 3.0) / (px * px);
            }
        }
        for (k = 0; k < n; ++k) ws += w[k];
        for (k = 0; k < n; ++k) q += (w[k] / ws) * (w[k] / ws);
        acc += q / 4.0;
    }
    return acc;
}

/* A Lambert floor (y = -1) under a sphere lamp (emission 3) of radius r at height y: built into
   sc (materials and shapes in the caller's mat and sh) with the check `name`; the scene's
   memory (free it), NULL when it did not build */
static void *lamp_floor_scene(fovpt_scene *sc, fovpt_material mat[2], fovpt_shape sh[2], float y,
                              float r, const char *name)
{
    fovpt_scene_desc desc;
    size_t sb = 0;
    void *smem;
    float p0[3] = { 0.0f, -1.0f, 0.0f }, nrm[3] = { 0.0f, 1.0f, 0.0f };
    fovpt_material_init(&mat[0]);
    fovpt_material_init(&mat[1]);
    mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 3.0f;
    fovpt_shape_plane(&sh[0], p0, nrm, 0);
    fovpt_shape_sphere(&sh[1], 0.0f, y, 0.0f, r, 1);
    fovpt_scene_desc_init(&desc);
    desc.shapes = sh; desc.num_shapes = 2; desc.materials = mat; desc.num_materials = 2;
    fovpt_scene_size(&desc, &sb);
    smem = malloc(sb + 16u);
    if (!check(smem != NULL && fovpt_scene_build(sc, &desc, smem, sb) == FOV_OK, name, "-")) {
        free(smem);
        return NULL;
    }
    return smem;
}

/* layers.bspline and zones.bspline: a flat, noisy field (a Lambert floor under a sphere lamp,
   path traced) reconstructed from a stride-4 lattice: the B-spline's per-pixel noise variance
   against Catmull-Rom's (LAYERS) or Lanczos-3's (ZONES) should follow the filters' sums of
   squared weights (sumsq, squared for two axes); the mean is kept (weights sum to 1) */
static void t_bspline(void)
{
    fovpt_material mat[2];
    fovpt_shape sh[2];
    fovpt_scene sc;
    void *smem = lamp_floor_scene(&sc, mat, sh, 6.0f, 2.0f, "floor scene builds");
    uint32_t W = 160, H = 120;
    int m, z;
    if (!smem) return;
    for (z = 0; z < 2; ++z) {
        double mean[3], var[3];
        for (m = 0; m < 3; ++m) { /* the method's filter, B-spline, UNIFORM (the mean) */
            fovpt_config c = fovpt_config_default();
            fovpt_camera cam;
            fovpt_ctx ctx;
            fovpt_output out;
            size_t n = 0;
            void *mem;
            float *rgb = (float *)malloc(sizeof(float) * 3u * W * H);
            fov_gaze g = { 0.5f, 0.5f };
            double s = 0.0, s2 = 0.0;
            long cnt = 0;
            uint32_t x, y;
            fovpt_camera_init(&cam, W, H);
            cam.pos[0] = 0.0f; cam.pos[1] = 3.0f; cam.pos[2] = 0.0f;
            cam.target[0] = 0.0f; cam.target[1] = -1.0f; cam.target[2] = 0.0f;
            cam.up[0] = 0.0f; cam.up[1] = 0.0f; cam.up[2] = 1.0f;
            if (z == 0) {
                c.method = FOVPT_METHOD_LAYERS;
                c.layers.count = 2; /* stride 4 beyond 0.5 degrees (the gaze in a corner) */
                c.layers.layer[0].stride = 4; c.layers.layer[0].spp = 16;
                c.layers.layer[1].stride = 1; c.layers.layer[1].spp = 1;
                c.layers.layer[1].radius_deg = 0.5f;
                c.layers.bspline = m == 1 ? 1u : 0u;
            } else {
                c.method = FOVPT_METHOD_ZONES; /* the 1/16 zone beyond 0.6 degrees */
                c.spp = 16;
                c.zones.inner_deg = 0.3f; c.zones.middle_deg = 0.6f; c.zones.overlap_px = 1.0f;
                c.zones.bspline = m == 1 ? 1u : 0u;
            }
            if (m == 2) { c.method = FOVPT_METHOD_UNIFORM; c.spp = 32; }
            fovpt_memory_size(&c, &cam, &n);
            mem = malloc(n + 16u);
            fovpt_output_init(&out);
            out.rgb = rgb;
            if (fovpt_init(&ctx, &c, &sc, &cam, g, mem, n) == FOV_OK &&
                fovpt_render(&ctx, 0, &out, NULL) == FOV_OK) {
                for (y = 20; y < H - 8; ++y)
                    for (x = 20; x < W - 8; ++x) {
                        double v = (double)rgb[3u * (y * W + x) + 1u];
                        s += v; s2 += v * v; cnt++;
                    }
            }
            mean[m] = cnt ? s / (double)cnt : 0.0;
            var[m] = cnt ? s2 / (double)cnt - mean[m] * mean[m] : 0.0;
            free(mem);
            free(rgb);
        }
        {
            double a = sumsq(1), b = sumsq(z ? 2 : 0), want = (a * a) / (b * b);
            double got = var[1] / var[0];
            fovcheck_info("%s: variance ratio B-spline / the method's filter %.3f (weights: %.3f)",
                          z ? "zones" : "layers", got, want);
            check(got > 0.7 * want && got < 1.4 * want,
                  N("%s.bspline: noise variance / %s's near the weights' ratio", z ? "zones" : "layers",
                    z ? "Lanczos" : "Catmull-Rom"), "got %.3f want %.3f", got, want);
            /* the same lattice: the same mean; against UNIFORM within the lattice's offset
               (its points sit at the cells' top-left pixels, the lamp's light is not flat) */
            check(fabs(mean[1] - mean[0]) < 0.01 * mean[0] &&
                  fabs(mean[1] - mean[2]) < 0.03 * mean[2] && mean[2] > 0.1,
                  N("%s.bspline: the mean of the field kept", z ? "zones" : "layers"),
                  "%.4f vs %.4f (UNIFORM %.4f)", mean[1], mean[0], mean[2]);
        }
    }
    {
        fovpt_config c = fovpt_config_default(), o;
        c.logger.func = logger;
        c.layers.bspline = 2;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "layers.bspline 2 rejected", "-");
        c.layers.bspline = 0;
        c.zones.bspline = 3;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "zones.bspline 3 rejected", "-");
    }
    free(smem);
}

/* an empty scene (every ray misses: cheap) for sample counts */
static void *empty_scene(fovpt_scene *sc, fovpt_material *mat)
{
    fovpt_scene_desc desc;
    size_t sb = 0;
    void *smem;
    fovpt_material_init(mat);
    fovpt_scene_desc_init(&desc);
    desc.materials = mat; desc.num_materials = 1;
    fovpt_scene_size(&desc, &sb);
    smem = malloc(sb + 16u);
    if (fovpt_scene_build(sc, &desc, smem, sb) != FOV_OK) { free(smem); return NULL; }
    return smem;
}

/* render cfg (frame 0): samples into *samples, the float image into rgb (may be NULL) */
static fov_result render_cfg(const fovpt_scene *sc, const fovpt_config *c, const fovpt_camera *cam,
                             fov_gaze g, float *rgb, uint64_t *samples, fovpt_ctx *keep, void **keep_mem)
{
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    size_t n = 0;
    void *mem;
    fov_result r = fovpt_memory_size(c, cam, &n);
    if (r != FOV_OK) return r;
    mem = malloc(n + 16u);
    fovpt_stats_init(&st);
    fovpt_output_init(&out);
    out.rgb = rgb;
    r = fovpt_init(&ctx, c, sc, cam, g, mem, n);
    if (r == FOV_OK) r = fovpt_render(&ctx, 0, &out, &st);
    *samples = st.samples;
    if (keep) { *keep = ctx; *keep_mem = mem; }
    else free(mem);
    return r;
}

/* the degenerate case: a display coarser than the eye across the image (the bench's 640 x 360
   at 45 degrees with quality 0.25). The acuity table costs exactly UNIFORM's samples and gives
   UNIFORM's image bit for bit (layers.hollow: no layer traced under the stride-1 one, the same
   streams), LAYERS and ZONES; a noisy scene (a floor under a lamp, path traced) */
static void t_degenerate(void)
{
    fovpt_material mat[2];
    fovpt_shape sh[2];
    fovpt_scene_desc desc;
    fovpt_scene sc;
    size_t sb = 0;
    void *smem;
    float p0[3] = { 0.0f, -1.0f, 0.0f }, nrm[3] = { 0.0f, 1.0f, 0.0f };
    uint32_t W = 160, H = 90, m;
    float *ref = (float *)malloc(sizeof(float) * 3u * W * H), *img = (float *)malloc(sizeof(float) * 3u * W * H);
    fovpt_camera cam;
    fov_gaze g = { 60.0f, 40.0f };
    fov_eye eye = { 0.0f, 0.0f, 0.25f };
    uint64_t n_ref = 0, n_img = 0;
    double f = 0.5 * H / tan(0.5 * 45.0 * 3.14159265358979 / 180.0), ppd = f * 3.14159265358979 / 180.0;
    fovpt_material_init(&mat[0]);
    fovpt_material_init(&mat[1]);
    mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 3.0f;
    fovpt_shape_plane(&sh[0], p0, nrm, 0);
    fovpt_shape_sphere(&sh[1], 0.0f, 2.0f, -1.0f, 0.7f, 1);
    fovpt_scene_desc_init(&desc);
    desc.shapes = sh; desc.num_shapes = 2; desc.materials = mat; desc.num_materials = 2;
    fovpt_scene_size(&desc, &sb);
    smem = malloc(sb + 16u);
    check(fovpt_scene_build(&sc, &desc, smem, sb) == FOV_OK, "degenerate: scene builds", "-");
    fovpt_camera_init(&cam, W, H);
    cam.fov_y_deg = 45.0f;
    /* the premise, from the model: 0.25 MAR(e) ppd < 1 pixel out to the image's corners */
    check(0.25 * (1.0 + 1.32 * ecc_px(f, W, H, 0.5, 0.5, W - 0.5, H - 0.5)) / 60.0 * ppd < 1.0,
          "degenerate: quality 0.25 finer than the pixels across the image (premise)", "-");
    {
        fovpt_config u = fovpt_config_default();
        u.spp = 4;
        check(render_cfg(&sc, &u, &cam, g, ref, &n_ref, NULL, NULL) == FOV_OK &&
              n_ref == 4u * W * H, "degenerate: UNIFORM 4 spp renders", "%llu", (unsigned long long)n_ref);
    }
    for (m = 0; m < 2; ++m) {
        fovpt_config c = fovpt_config_default();
        size_t i, diff = 0;
        c.method = m ? FOVPT_METHOD_ZONES : FOVPT_METHOD_LAYERS;
        c.spp = 4;
        c.logger.func = logger;
        check(fovpt_config_acuity(&c, &cam, &eye) == FOV_OK, N("degenerate %s: acuity ok", m ? "zones" : "layers"), "-");
        check(render_cfg(&sc, &c, &cam, g, img, &n_img, NULL, NULL) == FOV_OK && n_img == n_ref,
              N("degenerate %s: UNIFORM's samples (%llu, UNIFORM %llu)", m ? "zones" : "layers",
                (unsigned long long)n_img, (unsigned long long)n_ref), "-");
        /* ZONES reads its stride-1 lattice through Lanczos-3, whose float weights at integer
           offsets are 1 and sin(pi k) ~ 1e-7: equal to float rounding */
        for (i = 0; i < 3u * W * H; ++i)
            diff += m ? fabs((double)img[i] - (double)ref[i]) > 1e-5 * (1.0 + fabs((double)ref[i]))
                      : memcmp(&img[i], &ref[i], sizeof(float)) != 0;
        check(diff == 0, N("degenerate %s: UNIFORM's image %s", m ? "zones" : "layers",
                           m ? "(to 1e-5)" : "bit for bit"), "%zu values differ", diff);
        /* the same table without hollow (Axblad 2020's overlapping layers) costs more */
        if (m == 0) {
            c.layers.hollow = 0;
            check(render_cfg(&sc, &c, &cam, g, img, &n_img, NULL, NULL) == FOV_OK && n_img > n_ref,
                  "degenerate layers: hollow 0 traces the background under the stride-1 layer too",
                  "%llu vs %llu", (unsigned long long)n_img, (unsigned long long)n_ref);
        }
    }
    free(smem);
    free(ref);
    free(img);
}

/* hollow: a lattice point is traced iff some pixel's resolve can read it. Checked on the
   preset table (4 layers) with the test's own eccentricities: every point within a layer's
   needed ring [r_(n+1) - blend/2, r_n + blend/2] is traced, none deeper than the filter's reach
   (2 sqrt 2 d + 1 pixels, in degrees at the gaze) inside it; and hollow 1 traces fewer points */
static void t_hollow(void)
{
    fovpt_material mat;
    fovpt_scene sc;
    void *smem = empty_scene(&sc, &mat), *mem = NULL;
    fovpt_camera cam;
    fovpt_ctx ctx;
    fov_gaze g = { 130.0f, 70.0f };
    uint32_t W = 320, H = 180, n, k, l;
    double f;
    uint64_t s1 = 0, s0 = 0;
    int bad_needed = 0, bad_deep = 0;
    fovpt_config c = fovpt_config_default();
    fovpt_camera_init(&cam, W, H);
    cam.fov_y_deg = 60.0f;
    f = 0.5 * H / tan(30.0 * 3.14159265358979 / 180.0);
    c.method = FOVPT_METHOD_LAYERS;
    c.layers.hollow = 1;
    if (!check(smem != NULL && render_cfg(&sc, &c, &cam, g, NULL, &s1, &ctx, &mem) == FOV_OK,
               "hollow: preset renders", "-")) {
        free(mem);
        free(smem);
        return;
    }
    for (n = 0; n < ctx.lay.count; ++n) {
        double d = (double)ctx.lay.layer[n].stride, b = (double)ctx.lay.blend_deg;
        double hi = n ? (double)ctx.lay.layer[n].radius_deg + 0.5 * b : 1e9;
        double lo = n + 1u < ctx.lay.count ? (double)ctx.lay.layer[n + 1].radius_deg - 0.5 * b : -1.0;
        double reach = (2.0 * sqrt(2.0) * d + 1.0) / f * 180.0 / 3.14159265358979;
        for (l = 0; l < ctx.layer_ny[n]; ++l)
            for (k = 0; k < ctx.layer_nx[n]; ++k) {
                double x = ctx.layer_ox[n] + k * d + 0.5, y = ctx.layer_oy[n] + l * d + 0.5;
                double e = ecc_px(f, W, H, x, y, g.x, g.y);
                int traced = ctx.layer_buf[n][4u * ((size_t)l * ctx.layer_nx[n] + k) + 3u] > 0.0f;
                if (!traced && e >= lo + 1e-3 && e <= hi - 1e-3) bad_needed++;
                if (traced && e < lo - reach - 1e-3) bad_deep++;
            }
    }
    check(bad_needed == 0, "hollow: every point of a layer's ring traced", "%d missing", bad_needed);
    check(bad_deep == 0, "hollow: nothing traced deeper than the filter's reach inside the ring",
          "%d points", bad_deep);
    free(mem);
    c.layers.hollow = 0;
    check(render_cfg(&sc, &c, &cam, g, NULL, &s0, NULL, NULL) == FOV_OK && s1 < s0,
          "hollow: fewer samples than the overlapping layers", "%llu vs %llu",
          (unsigned long long)s1, (unsigned long long)s0);
    {
        fovpt_config o;
        c.logger.func = logger;
        c.layers.hollow = 2;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "layers.hollow 2 rejected", "-");
        c.layers.hollow = 0; c.zones.hollow = 5;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "zones.hollow 5 rejected", "-");
        c.zones.hollow = 0; c.zones.spp[1] = FOVPT_MAX_SPP + 1u;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_LIMIT && g_log_count == 1,
              "zones.spp above FOVPT_MAX_SPP rejected", "-");
        c.zones.spp[1] = 0; c.acuity_budget = -1.0f;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "acuity_budget -1 rejected", "-");
        c.acuity_budget = NAN;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_NOT_FINITE && g_log_count == 1,
              "acuity_budget NaN rejected", "-");
        c.acuity_budget = 0.0f;
        check(fovpt_config_resolve(&c, &o) == FOV_OK && o.zones.spp[0] == 0 &&
                  o.layers.hollow == 0 && o.zones.hollow == 0,
              "zero fields: defaults (zones.spp 0 = cfg.spp at use, hollow off)", "-");
    }
    free(smem);
}

/* spp from the eye model at the 27-inch monitor (33.6 px/degree), cfg.spp 4.
   budget 0: the model's rule, spp_n = floor(0.99 spp cl / cu) + 1 with cu, cl the band means
   of 1 / (1 + 4 pi t^2) (t^2 = s^2 for UNIFORM, 1/3 + s^2 / d^2 for a stride-d B-spline lattice,
   s = 0.3748 MAR(e) ppd pixels, the eye filter of examples/fovmetrics.h): between 1 and d^2 spp
   (never denser than UNIFORM), non-decreasing with the stride, the stride-1 layer exactly spp;
   each band's noise, recomputed here at the band's inner and outer edge, within the rule.
   budget B > 0: the samples rendered within 15 % of B W H spp, increasing with B. */
static void t_spp(void)
{
    fovpt_material mat;
    fovpt_scene sc;
    void *smem = empty_scene(&sc, &mat);
    fovpt_config c;
    fovpt_camera cam;
    fov_gaze g = { 960.0f, 540.0f };
    double ppd = 600.0 / 0.3113 * 3.14159265358979 / 180.0;
    uint32_t n;
    int ok = 1, k;
    uint64_t prev = 0;
    char why[200] = "";
    /* the image's corners: half the diagonal, 1101.4 pixels of 0.3113 mm at 600 mm */
    const double emax = atan(sqrt(960.0 * 960.0 + 540.0 * 540.0) * 0.3113 / 600.0) * 180.0 /
                        3.14159265358979;
    int inside = 0;
    monitor(&c, &cam, 1920, 1080, 600.0);
    c.method = FOVPT_METHOD_LAYERS;
    c.spp = 4;
    check(fovpt_config_acuity(&c, &cam, NULL) == FOV_OK && c.layers.count >= 3,
          "spp: acuity at the monitor", "count %u", c.layers.count);
    check(c.layers.layer[c.layers.count - 1].spp == 4, "spp: the stride-1 layer takes cfg.spp", "%u",
          c.layers.layer[c.layers.count - 1].spp);
    {   /* any cfg.spp: the stride-1 layer and the inner zone take it exactly (a ratio of 1) */
        static const uint32_t big[3] = { 101u, 200u, 1000u };
        fovpt_config cb;
        fovpt_camera cc;
        int okb = 1;
        for (k = 0; k < 3; ++k) {
            monitor(&cb, &cc, 1920, 1080, 600.0);
            cb.method = FOVPT_METHOD_LAYERS;
            cb.spp = big[k];
            if (fovpt_config_acuity(&cb, &cc, NULL) != FOV_OK ||
                cb.layers.layer[cb.layers.count - 1].spp != big[k] || cb.zones.spp[0] != big[k]) {
                okb = 0;
                snprintf(why, sizeof why, "spp %u: stride-1 layer %u, inner zone %u", big[k],
                         cb.layers.layer[cb.layers.count - 1].spp, cb.zones.spp[0]);
            }
        }
        check(okb, "spp: the stride-1 layer and the inner zone take cfg.spp above 100 too", "%s",
              why);
        why[0] = 0;
    }
    for (n = 0; n + 1u < c.layers.count; ++n) {
        uint32_t d = c.layers.layer[n].stride, sp = c.layers.layer[n].spp;
        double ein = (double)c.layers.layer[n + 1].radius_deg, r, lo, hi;
        double s = 0.3748 * (1.0 + 1.32 * ein) / 60.0 * ppd;
        if (ein > emax) continue; /* a band beyond the image's corners has no pixels */
        ++inside;
        if (!(sp >= 1u && sp <= 4u * d * d)) { ok = 0; snprintf(why, sizeof why, "layer %u spp %u", n, sp); }
        if (n > 0 && sp > c.layers.layer[n - 1].spp) { ok = 0; snprintf(why, sizeof why, "layer %u spp above its outer neighbour's", n); }
        /* the rule's ratio at the inner edge is the smallest in the band */
        r = (1.0 + 4.0 * 3.14159265358979 * s * s) /
            (1.0 + 4.0 * 3.14159265358979 * (1.0 / 3.0 + s * s / (double)(d * d)));
        lo = 4.0 * r * 0.99;
        hi = 4.0 * (double)(d * d) + 1.0;
        if (!((double)sp + 1e-9 >= lo && (double)sp <= hi)) {
            ok = 0;
            snprintf(why, sizeof why, "layer %u (stride %u): spp %u, edge ratio %.3f", n, d, sp, r);
        }
    }
    check(ok && inside >= 3,
          "spp: each layer between the noise rule at its inner edge and UNIFORM's density", "%s (%d "
          "layers inside the image)", why, inside);
    for (k = 0; k < 3; ++k) {
        static const float B[3] = { 0.25f, 0.5f, 1.0f };
        uint64_t got = 0;
        double want = (double)B[k] * 1920.0 * 1080.0 * 4.0;
        monitor(&c, &cam, 1920, 1080, 600.0);
        c.method = k == 1 ? FOVPT_METHOD_ZONES : FOVPT_METHOD_LAYERS;
        c.spp = 4;
        c.acuity_budget = B[k];
        check(fovpt_config_acuity(&c, &cam, NULL) == FOV_OK &&
                  render_cfg(&sc, &c, &cam, g, NULL, &got, NULL, NULL) == FOV_OK &&
                  fabs((double)got / want - 1.0) < 0.15,
              N("spp: acuity_budget %.2f (%s): samples %.3f x the budget", (double)B[k],
                k == 1 ? "zones" : "layers", (double)got / want), "-");
        if (c.method == FOVPT_METHOD_LAYERS) {
            check(got > prev, N("spp: budget %.2f more samples than the smaller budget", (double)B[k]), "-");
            prev = got;
        }
    }
    free(smem);
}

/* clamp_white: a stride >= 2 lattice point averages groups of cfg.spp samples whose means are
   clamped at clamp_white, so (B-spline weights >= 0, sum 1) no resolved pixel of the coarse
   layer exceeds it, where without the clamp the lamp (emission 3) does; cell_jitter and
   clamp_white validated */
static void t_clamp(void)
{
    fovpt_material mat[2];
    fovpt_shape sh[2];
    fovpt_scene sc;
    void *smem = lamp_floor_scene(&sc, mat, sh, 0.0f, 1.0f, "clamp: scene builds");
    uint32_t W = 120, H = 80, m;
    float *img = (float *)malloc(sizeof(float) * 3u * W * H), mx[2] = { 0.0f, 0.0f };
    fovpt_camera cam;
    fov_gaze g = { 2.0f, 2.0f };
    uint64_t ns = 0;
    if (!smem) { free(img); return; }
    fovpt_camera_init(&cam, W, H);
    for (m = 0; m < 2; ++m) {
        fovpt_config c = fovpt_config_default();
        uint32_t i;
        c.method = FOVPT_METHOD_LAYERS;
        c.spp = 2;
        c.layers.count = 2; /* stride 4 beyond 0.5 degrees of a gaze in the corner */
        c.layers.layer[0].stride = 4; c.layers.layer[0].spp = 8;
        c.layers.layer[1].stride = 1; c.layers.layer[1].spp = 2;
        c.layers.layer[1].radius_deg = 0.5f;
        c.layers.bspline = 1; c.layers.hollow = 1; c.layers.cell_jitter = 1;
        c.layers.clamp_white = m ? 1.0f : 0.0f;
        check(render_cfg(&sc, &c, &cam, g, img, &ns, NULL, NULL) == FOV_OK, "clamp: renders", "-");
        for (i = 0; i < W * H; ++i) {
            uint32_t x = i % W, y = i / W, k;
            if (x < 12u && y < 12u) continue; /* the stride-1 corner and its blend */
            for (k = 0; k < 3; ++k) mx[m] = img[3u * i + k] > mx[m] ? img[3u * i + k] : mx[m];
        }
    }
    check(mx[0] > 1.5f && mx[1] <= 1.0f + 1e-5f,
          "clamp_white 1: the coarse layer's pixels at most 1 (unclamped: the lamp's 3)",
          "max %.4f unclamped, %.4f clamped", (double)mx[0], (double)mx[1]);
    {
        fovpt_config c = fovpt_config_default(), o;
        c.logger.func = logger;
        c.layers.cell_jitter = 2;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "layers.cell_jitter 2 rejected", "-");
        c.layers.cell_jitter = 0; c.zones.cell_jitter = 2;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "zones.cell_jitter 2 rejected", "-");
        c.zones.cell_jitter = 0; c.layers.clamp_white = -1.0f;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_INVALID_ARG && g_log_count == 1,
              "layers.clamp_white -1 rejected", "-");
        c.layers.clamp_white = 0.0f; c.zones.clamp_white = INFINITY;
        g_log_count = 0;
        check(fovpt_config_resolve(&c, &o) == FOV_ERR_NOT_FINITE && g_log_count == 1,
              "zones.clamp_white inf rejected", "-");
    }
    free(img);
    free(smem);
}

/* SELECTIVE: the scaled borders keep tau_fov's shape as a function of e / k (a metamorphic
   check: tau_fov of the default borders at e equals the scaled one's at k e; tau_fov's own
   values are checked against Kim et al. 2021's in test_fovpt.c) */
static void t_selective(void)
{
    fovpt_config c, r0, r1;
    fovpt_camera cam;
    double k, worst = 0.0;
    int i, ok = 1;
    monitor(&c, &cam, 1920, 1080, 600.0);
    fovpt_config_resolve(&c, &r0);
    check(fovpt_config_acuity(&c, &cam, NULL) == FOV_OK && fovpt_config_resolve(&c, &r1) == FOV_OK,
          "selective: acuity config resolves", "-");
    k = (double)r1.selective.e_deg[3] / 30.0;
    for (i = 0; i <= 60; ++i) {
        float e = 0.75f * (float)i, t0 = 0.0f, t1 = 0.0f;
        ok &= fovpt_tau_fov(&r0.selective, e, &t0) == FOV_OK;
        ok &= fovpt_tau_fov(&r1.selective, (float)(k * (double)e), &t1) == FOV_OK;
        if (fabs((double)t1 - (double)t0) > worst) worst = fabs((double)t1 - (double)t0);
    }
    check(ok && worst < 1e-3, "selective: tau_fov(k e) of the scaled borders = tau_fov(e) of Kim's",
          "worst %.5f", worst);
}

/* extreme eyes and displays: always a valid table within the allowed spacing */
static void t_extremes(void)
{
    static const double dists[5] = { 50.0, 300.0, 600.0, 3000.0, 20000.0 };
    static const float qs[5] = { 0.01f, 1.0f, 5.0f, 20.0f, 100.0f };
    static const float m0[3] = { 0.0f, 0.1f, 60.0f }, sl[3] = { 0.0f, 0.05f, 60.0f };
    int i, k, j, bad = 0;
    char what[200] = "";
    for (i = 0; i < 5; ++i)
        for (k = 0; k < 5; ++k)
            for (j = 0; j < 3; ++j) {
                fovpt_config c, r;
                fovpt_camera cam;
                fov_eye eye = { m0[j], sl[j], qs[k] };
                double ppd = dists[i] / 0.3113 * 3.14159265358979 / 180.0;
                double w0 = j ? (double)m0[j] : 1.0, sp = j ? (double)sl[j] : 1.32;
                double b = 1.0, allowed;
                uint32_t n;
                monitor(&c, &cam, 1920, 1080, dists[i]);
                if (fovpt_config_acuity(&c, &cam, &eye) != FOV_OK ||
                    fovpt_config_resolve(&c, &r) != FOV_OK) {
                    bad++;
                    snprintf(what, sizeof what, "fails at %.0f mm, q %.2f, eye %d", dists[i],
                             (double)qs[k], j);
                    continue;
                }
                for (n = 0; n + 1u < c.layers.count; ++n) {
                    double ein = (double)c.layers.layer[n + 1].radius_deg - 0.5 * b;
                    allowed = (double)qs[k] * (w0 + sp * (ein > 0.0 ? ein : 0.0)) / 60.0 * ppd;
                    if ((double)c.layers.layer[n].stride > allowed * (1.0 + 1e-5) &&
                        c.layers.layer[n].stride > 1u) {
                        bad++;
                        snprintf(what, sizeof what, "%.0f mm q %.2f eye %d: layer %u stride %u > %.3f",
                                 dists[i], (double)qs[k], j, n, c.layers.layer[n].stride, allowed);
                    }
                }
            }
    check(bad == 0, "extreme eyes (quality 0.01 .. 100, MAR 0.1 .. 60) and displays (50 mm .. 20 m): "
          "valid tables within the allowed spacing", "%d bad: %s", bad, what);
}

int main(void)
{
    t_degenerate();
    t_hollow();
    t_spp();
    t_clamp();
    t_extremes();
    t_selective();
    t_bspline();
    t_allowed();
    t_monotone();
    t_coarse();
    t_errors();
    t_fields();
    return fovcheck_summary();
}
