/* test_fovsdf_props.c - property and regression tests of fovsdf.h's tracers (issue 10).

   Property (every method, every eps mode, 1 and 4 spp, on the six stress kinds of
   tests/common/fovstress.h: thin shells, dust of tiny spheres, objects 1e3 .. 1e6 from the
   origin, grazing floors with low bumps, a camera inside a closed room with thin pillars,
   needles of radius 0.002):
     - no reported hit lies behind the first surface along its ray: with the double-precision
       reference along the library's own ray (fovsdf_camera_ray), t_in = the first t where the
       scene's double distance is below -tol(t), tol(t) = 8 FLT_EPSILON (|camera| + t) + 0.02
       thr(t) (the library's float noise plus 2 % of the ray's hit threshold), a hit at t is
       behind when t > t_in;
     - no hit beyond t_max, every t finite;
     - the head start (`start` output) never exceeds the first hit, the reference's first t
       with f <= 0, for the methods that claim it (CONE, CONE_FOV's traced pixels).
   Each sample ray's t is rebuilt with fovsdf_trace from its pixel's `start` (the same march;
   for spp 1 the rebuilt t is checked against the rendered depth bit for bit).
   IPR, SKIP and FIPR are heuristics in this version: their counts are printed as INFO lines
   unless PROPS_ASSERT_HEURISTIC is 1 (the lead flips it when the safe variants are merged).

   Regression tests: the secant jump through a thin shell (item 1), hits beyond t_max (F3),
   non-finite and overestimating callbacks (F5), wide fields of view and extreme aspect
   ratios (item 5), the cone guarantee far from the origin (item 4). */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementation compiled once per build
   (tests/common/fov_impl_sdf.c) instead of compiling it in this file; the private functions
   tested here are called through the test hook's wrappers (tests/common/fov_priv_sdf.h),
   which are compiled in this file when it holds the implementation */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fov_priv_sdf.h"
#include "fovcheck.h"
#include "fovstress.h"

#include <stdarg.h>
#include <stdlib.h>

/* ---- the one-line switch: 1 = assert IPR / SKIP / FIPR like the others ------------------- */
#define PROPS_ASSERT_HEURISTIC 1

#define TOL_FRAC 0.02

static char g_nm[160];
static const char *N2(const char *fmt, const char *a, const char *b)
{
    snprintf(g_nm, sizeof g_nm, fmt, a, b);
    return g_nm;
}

static int is_heuristic(uint32_t m)
{
    return m == FOVSDF_METHOD_IPR || m == FOVSDF_METHOD_SKIP || m == FOVSDF_METHOD_FIPR;
}
static int claims_start(uint32_t m) { return m == FOVSDF_METHOD_CONE || m == FOVSDF_METHOD_CONE_FOV; }

static void cam_from(fovsdf_camera *cam, const fs_scene *sc, uint32_t w, uint32_t h)
{
    fovsdf_camera_init(cam, w, h);
    memcpy(cam->pos, sc->cam, sizeof cam->pos);
    memcpy(cam->target, sc->target, sizeof cam->target);
    memcpy(cam->up, sc->up, sizeof cam->up);
    cam->fov_y_deg = sc->fov;
}

/* the ray's own eps_cone (pixel-cone growth) as the library documents it */
static double ray_eps_cone(const fovsdf_ctx *c, const float rd[3])
{
    double cz = (double)rd[0] * (double)c->fwd[0] + (double)rd[1] * (double)c->fwd[1] + (double)rd[2] * (double)c->fwd[2];
    if (c->cfg.eps_mode == FOVSDF_EPS_ABSOLUTE) return 0.0;
    if (cz < 0.0) cz = 0.0;
    return (double)c->cfg.eps_px * (double)c->pixel_angle * cz * cz;
}

typedef struct acc {
    long behind, tmax_bad, start_bad, recon_bad, rays, hits, px;
    double worst;
} acc;

typedef struct sref { fs_ref r; float ro[3], rd[3]; } sref;

/* One scene, eps mode and spp: references once, then every method. */
static void props_scene(const fs_scene *sc, uint32_t eps_mode, uint32_t spp, uint32_t W, uint32_t H, acc a[_FOVSDF_METHOD_NUM])
{
    fovsdf_scene scene;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fov_gaze gz;
    uint32_t n = W * H * spp, x, y, s, meth;
    sref *ref = (sref *)malloc(sizeof(sref) * n);
    float *depth = (float *)malloc(sizeof(float) * W * H), *start = (float *)malloc(sizeof(float) * W * H);
    uint8_t *hit = (uint8_t *)malloc((size_t)W * H), *mask = (uint8_t *)malloc((size_t)W * H);
    if (!ref || !depth || !start || !hit || !mask) { printf("out of memory\n"); exit(2); }
    fovsdf_scene_init(&scene);
    scene.dist = fs_dist;
    scene.user = (void *)(uintptr_t)0;
    scene.user = (void *)sc;
    scene.t_max = sc->t_max;
    cam_from(&cam, sc, W, H);
    gz.x = 0.5f * (float)W; gz.y = 0.5f * (float)H;
    cfg.spp = spp;
    cfg.eps_mode = eps_mode;
    cfg.shading = FOVSDF_SHADE_DEPTH;
    if (fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) {
        check(0, "props_init", "fovsdf_init failed for scene %s", fs_kind_name[sc->kind]);
        return;
    }
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x)
            for (s = 0; s < spp; ++s) {
                sref *q = &ref[((size_t)y * W + x) * spp + s];
                float ox, oy;
                double cz;
                fovtest_sdf_sample_offset(spp, s, &ox, &oy);
                (void)fovsdf_camera_ray(&ctx, (float)x + 0.5f + ox, (float)y + 0.5f + oy, q->ro, q->rd);
                cz = (double)q->rd[0] * (double)ctx.fwd[0] + (double)q->rd[1] * (double)ctx.fwd[1] + (double)q->rd[2] * (double)ctx.fwd[2];
                q->r = fs_reference(sc, q->ro, q->rd, (double)ctx.t_max, eps_mode == FOVSDF_EPS_CONE ? 0.0 : (double)ctx.cfg.eps,
                                    ray_eps_cone(&ctx, q->rd), TOL_FRAC, (double)ctx.pixel_angle * cz);
            }
    for (meth = 0; meth < (uint32_t)_FOVSDF_METHOD_NUM; ++meth) {
        fovsdf_output out;
        acc *A = &a[meth];
        cfg.method = meth;
        if (fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) { check(0, "props_init_method", "%u", meth); continue; }
        fovsdf_output_init(&out);
        out.depth = depth; out.hit = hit; out.start = start; out.mask = mask;
        memset(mask, 1, (size_t)W * H);
        (void)fovsdf_render_rows(&ctx, 0, H, &out, NULL);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                size_t pi = (size_t)y * W + x;
                double thit_min = (double)INFINITY;
                float tmin_rec = ctx.t_max;
                int any = 0;
                if (!(depth[pi] <= ctx.t_max) || depth[pi] < 0.0f) A->tmax_bad++; /* also NaN */
                if (mask[pi] != 1) continue; /* FIPR / CONE_FOV interpolated pixels: no tracer output */
                A->px++;
                for (s = 0; s < spp; ++s) {
                    const sref *q = &ref[pi * spp + s];
                    fovsdf_hit h;
                    float t0 = start[pi];
                    if (q->r.t_hit < thit_min) thit_min = q->r.t_hit;
                    if (t0 >= ctx.t_max) { h.kind = FOVSDF_MISS; h.t = ctx.t_max; }
                    else {
                        if (t0 > 0.0f && is_heuristic(meth)) { /* the march's start check */
                            float p[3];
                            p[0] = q->ro[0] + q->rd[0] * t0; p[1] = q->ro[1] + q->rd[1] * t0; p[2] = q->ro[2] + q->rd[2] * t0;
                            if (fovsdf_distance(&ctx, p, NULL, NULL) < 0.0f) t0 = 0.0f;
                        }
                        (void)fovsdf_trace(&ctx, q->ro, q->rd, t0, &h, NULL);
                    }
                    A->rays++;
                    if (!(h.t <= ctx.t_max) || !(h.t >= 0.0f)) A->tmax_bad++;
                    if (h.kind == FOVSDF_MISS) continue;
                    A->hits++;
                    any = 1;
                    if (h.t < tmin_rec) tmin_rec = h.t;
                    if (!q->r.capped && (double)h.t > q->r.t_in) {
                        A->behind++;
                        if ((double)h.t - q->r.t_in > A->worst) A->worst = (double)h.t - q->r.t_in;
                    }
                }
                /* the rebuilt sample rays reproduce the rendered pixel */
                if ((any ? tmin_rec : ctx.t_max) != depth[pi]) A->recon_bad++;
                if (start[pi] > 0.0f && start[pi] < ctx.t_max && (double)start[pi] > thit_min) A->start_bad++;
            }
    }
    free(ref); free(depth); free(start); free(hit); free(mask);
}

static void test_props(void)
{
    static const uint32_t modes[3] = { FOVSDF_EPS_BOTH, FOVSDF_EPS_ABSOLUTE, FOVSDF_EPS_CONE };
    static const char *const mode_name[3] = { "both", "absolute", "cone" };
    static fs_scene sc;
    int kind, mi, si, seed;
    for (kind = 0; kind < FS_KINDS; ++kind)
        for (mi = 0; mi < 3; ++mi)
            for (si = 0; si < 2; ++si) {
                acc a[_FOVSDF_METHOD_NUM];
                uint32_t spp = si ? 4u : 1u, W = si ? 24u : 40u, H = si ? 14u : 24u, m;
                char tag[64];
                memset(a, 0, sizeof a);
                for (seed = 0; seed < 2; ++seed) {
                    int nobj = kind == FS_DUST ? 40 : (kind == FS_NEEDLE ? 24 : 16);
                    fs_make(&sc, kind, (uint32_t)(100 * kind + 10 * mi + seed + 1), nobj, kind == FS_FAR ? (seed ? 1e6 : 1e3) : 0.0);
                    props_scene(&sc, modes[mi], spp, W, H, a);
                }
                snprintf(tag, sizeof tag, "%s_%s_spp%u", fs_kind_name[kind], mode_name[mi], spp);
                for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m) {
                    const acc *A = &a[m];
                    const char *mn = fovsdf_method_name(m);
                    int assert_it = !is_heuristic(m) || PROPS_ASSERT_HEURISTIC;
                    if (assert_it) {
                        check(A->behind == 0, N2("props_no_hit_behind_first_surface_%s_%s", mn, tag),
                              "%ld of %ld hits (%ld rays) behind t_in, worst by %.3g", A->behind, A->hits, A->rays, A->worst);
                        if (claims_start(m) || (is_heuristic(m) && PROPS_ASSERT_HEURISTIC))
                            check(A->start_bad == 0, N2("props_start_before_first_hit_%s_%s", mn, tag),
                                  "%ld of %ld traced pixels start past their first hit", A->start_bad, A->px);
                        check(A->recon_bad == 0, N2("props_rebuilt_rays_match_render_%s_%s", mn, tag),
                              "%ld of %ld pixels: the rebuilt sample rays do not reproduce the depth", A->recon_bad, A->px);
                    } else {
                        fovcheck_info("props %s %s: %ld of %ld hits behind the first surface (worst %.3g), %ld of %ld traced pixels start past the first hit, %ld rebuilt pixels differ",
                             mn, tag, A->behind, A->hits, A->worst, A->start_bad, A->px, A->recon_bad);
                    }
                    check(A->tmax_bad == 0, N2("props_no_hit_beyond_t_max_%s_%s", mn, tag),
                          "%ld depths or sample t outside [0, t_max] or not finite", A->tmax_bad);
                }
            }
}

/* ---- item 1: the secant step jumped a thin surface -----------------------------------------
   A floor seen at a grazing angle a and a thin wall (a slab 0.01 thick across the ray) just
   past where the loop stops: the loop's last samples see the floor (slope -sin a), the secant
   extrapolates d / sin a ahead, past the wall, and lands on the floor behind it. The wall's
   interior (f < -tol, tol = 2 % of eps here) starts at x = x_w - 0.005 + tol. */
static float floor_wall(const float p[3], void *u)
{
    const float *k = (const float *)u; /* k[0]: x of the wall's mid-plane */
    float wall = fabsf(p[0] - k[0]) - 0.005f;
    return p[1] < wall ? p[1] : wall;
}
static void test_secant_jump(void)
{
    static const double angs[6] = { 3.0, 5.0, 6.0, 8.0, 10.0, 15.0 };
    float k[1];
    fovsdf_scene sc;
    uint32_t m;
    int ai, oi, bad = 0, n = 0;
    double worst = 0.0;
    fovsdf_scene_init(&sc);
    sc.dist = floor_wall;
    sc.user = k;
    for (m = 0; m <= (uint32_t)FOVSDF_METHOD_BV2018; ++m)
        for (ai = 0; ai < 6; ++ai)
            for (oi = 0; oi < 24; ++oi) {
                fovsdf_march_params mp;
                fovsdf_hit h;
                const float ro[3] = { 0.0f, 1.0f, 0.0f };
                float rd[3];
                double a = angs[ai] * 3.14159265358979323846 / 180.0, tp, xw, tin;
                memset(&mp, 0, sizeof mp);
                mp.method = m; mp.max_steps = 4096; mp.eps = 0.05f; mp.t_max = 100.0f;
                mp.omega = 1.6f; mp.ar_beta = 0.3f; mp.bv_relax = 0.9f;
                rd[0] = (float)cos(a); rd[1] = (float)-sin(a); rd[2] = 0.0f;
                tp = 1.0 / sin(a);                                  /* the floor */
                xw = (tp - 0.05 / sin(a) + 0.02 + 0.02 * oi) * cos(a); /* the wall, before it */
                k[0] = (float)xw;
                tin = ((double)k[0] - 0.005 + TOL_FRAC * 0.05) / (double)rd[0];
                (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
                ++n;
                if (h.kind != FOVSDF_MISS && (double)h.t > tin) {
                    ++bad;
                    if ((double)h.t - tin > worst) worst = (double)h.t - tin;
                }
            }
    check(bad == 0, "secant_never_jumps_a_thin_wall",
          "%d of %d rays (4 tracers, eps 0.05, a floor at 3 .. 15 degrees, a wall 0.01 thick before it) hit behind the wall, worst by %.3g",
          bad, n, worst);
}

static float floor_wall2(const float p[3], void *u)
{
    const float *k = (const float *)u; /* k[0]: x of the wall's mid-plane, k[1]: its thickness */
    float wall = fabsf(p[0] - k[0]) - 0.5f * k[1];
    return p[1] < wall ? p[1] : wall;
}
/* ---- item 1: the empty-ball certificate of the secant step ------------------------------
   At grazing angles the secant's end point lies beyond the last sample's sphere and the hit
   refinement certifies the move with one empty ball off the ray (fovsdf.h, fovsdf__refine).
   (a) A floor alone at 0.5 .. 30 degrees: the hit is exact again (relative 1e-5; the plain
   fallback stops up to thr / sin(angle) short: 1e-4 relative with eps 1e-4 at 0.5 degrees,
   0.2 with a pixel cone of 2.4e-3). (b) A thin wall (0.05 and 0.1 of the threshold thick,
   across the ray) between where the loop stops and the floor behind it: the ball then holds
   part of the wall, f at its centre is smaller than its radius, and the certificate must
   refuse: no hit behind the wall's interior, and the certificate was evaluated to its last
   test (5 evaluations beyond the steps for classic: F, 2 differences, the centre, the plain
   step) on some rays of every angle. */
static float floor_only(const float p[3], void *u)
{
    (void)u;
    return p[1];
}
static void test_ball_certificate(void)
{
    static const double angs[6] = { 0.5, 1.0, 2.0, 5.0, 10.0, 30.0 };
    static const double wang[4] = { 0.5, 1.0, 2.0, 5.0 };
    fovsdf_scene sc;
    uint32_t m;
    int ai, k, mode;
    fovsdf_scene_init(&sc);
    sc.dist = floor_only;
    for (mode = 0; mode < 2; ++mode)
        for (m = 0; m <= (uint32_t)FOVSDF_METHOD_BV2018; ++m) {
            double worst = 0.0;
            int bad = 0, n = 0;
            for (ai = 0; ai < 6; ++ai)
                for (k = 0; k < 16; ++k) {
                    double a = angs[ai] * 3.14159265358979323846 / 180.0, az = 0.1 + 0.4 * k, te, rel;
                    const float ro[3] = { 0.0f, 1.0f, 0.0f };
                    float rd[3];
                    fovsdf_march_params mp;
                    fovsdf_hit h;
                    memset(&mp, 0, sizeof mp);
                    mp.method = m; mp.max_steps = 8192; mp.t_max = 3000.0f;
                    mp.omega = 1.6f; mp.ar_beta = 0.3f; mp.bv_relax = 0.9f;
                    if (mode == 0) mp.eps = 1e-4f; else mp.eps_cone = 2.4e-3f;
                    rd[0] = (float)(cos(a) * cos(az)); rd[1] = (float)-sin(a); rd[2] = (float)(cos(a) * sin(az));
                    te = (double)ro[1] / -(double)rd[1]; /* along the float ray, in double */
                    (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
                    rel = h.kind == FOVSDF_HIT ? fabs((double)h.t - te) / te : 1.0;
                    ++n;
                    if (rel > 1e-5) ++bad;
                    if (rel > worst) worst = rel;
                }
            check(bad == 0, N2("ball_grazing_floor_exact_%s_%s", fovsdf_method_name(m), mode ? "cone" : "eps"),
                  "%d of %d rays (0.5 .. 30 degrees) off the floor by more than 1e-5 relative, worst %.3g", bad, n, worst);
        }
    for (m = 0; m <= (uint32_t)FOVSDF_METHOD_BV2018; ++m) {
        int bad = 0, n = 0, refused[4] = { 0, 0, 0, 0 }, wi;
        double worst = 0.0;
        float kw[2];
        fovsdf_scene_init(&sc);
        sc.dist = floor_wall2;
        sc.user = kw;
        for (ai = 0; ai < 4; ++ai)
            for (wi = 0; wi < 2; ++wi)
                for (k = 0; k < 32; ++k) {
                    const float eps = 0.05f, ro[3] = { 0.0f, 1.0f, 0.0f };
                    double a = wang[ai] * 3.14159265358979323846 / 180.0, tp, span, tin;
                    float rd[3];
                    fovsdf_march_params mp;
                    fovsdf_hit h;
                    memset(&mp, 0, sizeof mp);
                    mp.method = m; mp.max_steps = 8192; mp.eps = eps; mp.t_max = 300.0f;
                    mp.omega = 1.6f; mp.ar_beta = 0.3f; mp.bv_relax = 0.9f;
                    rd[0] = (float)cos(a); rd[1] = (float)-sin(a); rd[2] = 0.0f;
                    tp = 1.0 / sin(a);          /* the floor */
                    span = 1.1 * (double)eps / sin(a);  /* where the loop may stop before it */
                    kw[1] = (float)((wi ? 0.1 : 0.05) * (double)eps); /* the wall's thickness */
                    kw[0] = (float)((tp - span + span * (k + 0.5) / 32.0) * cos(a));
                    tin = ((double)kw[0] - 0.5 * (double)kw[1] + TOL_FRAC * (double)eps) / (double)rd[0];
                    (void)fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL);
                    ++n;
                    if (h.kind != FOVSDF_MISS && (double)h.t > tin) {
                        ++bad;
                        if ((double)h.t - tin > worst) worst = (double)h.t - tin;
                    } else if (m == FOVSDF_METHOD_CLASSIC && h.evals >= h.steps + 5u) {
                        ++refused[ai];
                    }
                }
        check(bad == 0, N2("ball_never_jumps_a_thin_wall_%s%s", fovsdf_method_name(m), ""),
              "%d of %d rays (eps 0.05, a floor at 0.5 .. 5 degrees, a wall 0.0025 or 0.005 thick before it) hit behind the wall, worst by %.3g",
              bad, n, worst);
        if (m == FOVSDF_METHOD_CLASSIC) fovcheck_info("ball certificate refused on %d %d %d %d of 64 wall rays at 0.5/1/2/5 degrees (classic)",
                                            refused[0], refused[1], refused[2], refused[3]);
        if (m == FOVSDF_METHOD_CLASSIC)
            check(refused[0] > 0 && refused[1] > 0 && refused[2] > 0 && refused[3] > 0, "ball_certificate_refuses_the_wall",
                  "rays where the certificate ran to its ball test and refused, per angle 0.5/1/2/5 deg: %d %d %d %d of 64",
                  refused[0], refused[1], refused[2], refused[3]);
    }
}

/* ---- F3: hits beyond t_max (cylinder of radius 180, camera at (180, 180, 180)) ------------ */
static void test_f3_t_max(void)
{
    static const uint32_t meths[5] = { FOVSDF_METHOD_AUTORELAXED, FOVSDF_METHOD_BV2018, FOVSDF_METHOD_CONE, FOVSDF_METHOD_IPR,
                                       FOVSDF_METHOD_SKIP };
    static fs_scene cyl;
    enum { W = 32, H = 18 };
    fovsdf_scene scene;
    fovsdf_camera cam;
    int i;
    memset(&cyl, 0, sizeof cyl);
    fs_add(&cyl, FP_VCYL, 0, 0, 0, 0, 0, 0, 180.0, 180.0);
    fovsdf_scene_init(&scene);
    scene.dist = fs_dist;
    scene.user = &cyl;
    fovsdf_camera_init(&cam, W, H);
    cam.pos[0] = cam.pos[1] = cam.pos[2] = 180.0f;
    for (i = 0; i < 5; ++i) {
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fovsdf_output out;
        float depth[W * H];
        uint8_t hit[W * H];
        fov_gaze gz = { 16.0f, 9.0f };
        int k, bad = 0, wrong_hit = 0;
        cfg.method = meths[i];
        cfg.t_max = 100.0f;
        cfg.shading = FOVSDF_SHADE_DEPTH;
        if (fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) { check(0, "f3_init", "init"); continue; }
        fovsdf_output_init(&out);
        out.depth = depth; out.hit = hit;
        (void)fovsdf_render_rows(&ctx, 0, H, &out, NULL);
        for (k = 0; k < W * H; ++k) {
            float ro[3], rd[3];
            fs_ref r;
            (void)fovsdf_camera_ray(&ctx, (float)(k % W) + 0.5f, (float)(k / W) + 0.5f, ro, rd);
            /* a hit needs the ray to come within the largest threshold (the centre pixel's
               cone, 0.25 pixel_angle t, plus eps and the ulp floor) of the cylinder by t_max */
            r = fs_reference(&cyl, ro, rd, 100.0, 1e-4, 0.0, 0.0, 0.25 * (double)ctx.pixel_angle);
            if (!(depth[k] <= 100.0f)) bad++;
            if (hit[k] && !r.near) wrong_hit++;
        }
        check(bad == 0 && wrong_hit == 0, N2("f3_no_hit_beyond_t_max_%s%s", fovsdf_method_name(meths[i]), ""),
              "%d depths above t_max, %d hits whose ray never comes within the threshold of the cylinder before t_max", bad, wrong_hit);
    }
}

/* ---- F5: non-finite and overestimating callbacks (BV2018 and every tracer) ---------------- */
typedef struct f5u { int mode; long nonfinite_calls; } f5u;
static float f5_dist(const float p[3], fovsdf_query *q, void *user)
{
    f5u *u = (f5u *)user;
    float s = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0f;
    (void)q;
    if (!(p[0] - p[0] == 0.0f) || !(p[1] - p[1] == 0.0f) || !(p[2] - p[2] == 0.0f)) { u->nonfinite_calls++; return 0.0f; }
    if (u->mode == 4) return 1e37f;                                      /* empty, huge steps */
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 1e6f) return 5e-4f; /* a far wall, beyond t_max */
    switch (u->mode) {
    case 0: return p[1] > 0.5f ? NAN : s;               /* NaN in a region */
    case 1: return p[1] > 0.5f ? INFINITY : s;          /* inf in a region */
    case 2: return p[1] > 0.5f ? 3e38f : s;             /* overestimates (huge) */
    default: return p[0] > 0.2f ? 40.0f * (s + 2.0f) : s; /* overestimates (moderate) */
    }
}
static void test_f5_nonfinite(void)
{
    int mode, bad = 0, calls = 0, n = 0, cv;
    uint32_t m;
    for (mode = 0; mode < 4; ++mode)
        for (cv = 0; cv < 2; ++cv)
        for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m) {
            f5u u;
            fovsdf_scene sc;
            fovsdf_camera cam;
            fovsdf_config cfg = fovsdf_config_default();
            fovsdf_ctx ctx;
            fov_gaze gz = { 8.0f, 4.5f };
            int i;
            u.mode = mode; u.nonfinite_calls = 0;
            fovsdf_scene_init(&sc);
            sc.dist_ex = f5_dist;
            sc.user = &u;
            fovsdf_camera_init(&cam, 16, 9);
            cam.pos[1] = 1.0f; cam.pos[2] = -3.0f;
            if (cv) { cam.pos[1] = 0.0f; cam.target[1] = 3.0f; } /* from outside the bad region into it */
            cfg.method = m;
            cfg.t_max = 60.0f;
            if (fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0) != FOV_OK) { bad++; continue; }
            for (i = 0; i < 144; ++i) {
                float ro[3], rd[3], rgb[3], t = -1.0f, ts = (float)(i % 3);
                fovsdf_hit h;
                (void)fovsdf_camera_ray(&ctx, (float)(i % 16) + 0.5f, (float)(i / 16) + 0.5f, ro, rd);
                ++n;
                if (fovsdf_trace(&ctx, ro, rd, ts, &h, NULL) != FOV_OK) bad++;
                else if (h.kind != FOVSDF_MISS && !(h.t >= ts && h.t <= ctx.t_max)) bad++;
                else if (h.kind == FOVSDF_MISS && h.t != ctx.t_max) bad++;
                if (fovsdf_shade_point(&ctx, (float)(i % 16) + 0.5f, (float)(i / 16) + 0.5f, rgb, &t, NULL, NULL) != FOV_OK ||
                    !(t >= 0.0f && t <= ctx.t_max) || !(rgb[0] - rgb[0] == 0.0f))
                    bad++;
            }
            {
                fovsdf_output out;
                float depth[16 * 9];
                int k;
                fovsdf_output_init(&out);
                out.depth = depth;
                (void)fovsdf_render_rows(&ctx, 0, 9, &out, NULL);
                for (k = 0; k < 16 * 9; ++k) if (!(depth[k] >= 0.0f && depth[k] <= ctx.t_max)) bad++;
            }
            calls += (int)u.nonfinite_calls;
        }
    /* a camera near FLT_MAX is rejected (origins beyond 1e18); at the bound, in an empty scene
       with t_max 3e38: a miss (the ulp floor of |camera| + t must not overflow to inf, which
       made every ray hit at its start) */
    for (m = 0; m <= (uint32_t)FOVSDF_METHOD_BV2018; ++m) {
        f5u u;
        fovsdf_scene sc;
        fovsdf_march_params mp;
        fovsdf_hit h;
        const float ro[3] = { 3e38f, 0.0f, 0.0f }, rd[3] = { 1.0f, 0.0f, 0.0f };
        u.mode = 4; u.nonfinite_calls = 0;
        fovsdf_scene_init(&sc);
        sc.dist_ex = f5_dist;
        sc.user = &u;
        memset(&mp, 0, sizeof mp);
        mp.method = m; mp.max_steps = 64; mp.eps = 1e-4f; mp.t_max = 3e38f;
        mp.omega = 1.6f; mp.ar_beta = 0.3f; mp.bv_relax = 0.9f;
        ++n;
        /* beyond the documented origin bound (1e18 per component) it is an error, not a march */
        if (fovsdf_march(&sc, &mp, ro, rd, 0.0f, &h, NULL) != FOV_ERR_INVALID_ARG) bad++;
        {
            const float ro2[3] = { 1e18f, 0.0f, 0.0f };
            ++n;
            if (fovsdf_march(&sc, &mp, ro2, rd, 0.0f, &h, NULL) != FOV_OK || h.kind != FOVSDF_MISS) bad++; /* empty */
        }
        calls += (int)u.nonfinite_calls;
    }
    check(bad == 0, "f5_nonfinite_callbacks_hits_finite_within_range",
          "%d failures over %d rays (trace, shade_point, render; NaN / inf / overestimating callbacks, every method): t outside [t_start, t_max] or not finite",
          bad, n);
    check(calls == 0, "f5_never_evaluates_a_nonfinite_point", "%d evaluations at non-finite points", calls);
}

/* ---- item 5: wide fields of view and extreme aspect ratios ---------------------------------
   Spheres around the camera; a reported hit is false when the double reference ray never
   comes within eps + one pixel footprint (the ray's own, the larger tangential one:
   pixel_angle cos(theta) t) of a surface. */
static void test_wide_fov(void)
{
    static const float fovs[6] = { 100.0f, 110.0f, 150.0f, 179.9f, 60.0f, 60.0f };
    static const uint32_t ws[6] = { 64, 64, 64, 64, 4096, 1 }, hs[6] = { 36, 36, 36, 36, 1, 4096 };
    static fs_scene sc;
    int c, i;
    memset(&sc, 0, sizeof sc);
    {   /* spheres in every direction in front of the camera, and bands in the planes y = 0
           and x = 0 for the 4096x1 and 1x4096 images */
        uint32_t rs = 99u;
        for (i = 0; i < 300; ++i) {
            double th = fs_ur(&rs, -1.57, 1.57), ph = fs_ur(&rs, -1.5, 1.5), d = fs_ur(&rs, 2.0, 8.0);
            if (i >= 200 && i < 250) { ph = fs_ur(&rs, -0.02, 0.02); th = (i & 1 ? 1.0 : -1.0) * fs_ur(&rs, 1.1, 1.45); }
            if (i >= 250) { ph = fs_ur(&rs, -0.52, 0.52); th = fs_ur(&rs, -0.02, 0.02); }
            fs_add(&sc, FP_SPHERE, d * cos(ph) * sin(th), d * sin(ph), d * cos(ph) * cos(th), 0, 0, 0, fs_ur(&rs, 0.03, 0.3), 0);
        }
    }
    for (c = 0; c < 6; ++c) {
        fovsdf_scene scene;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fov_gaze gz;
        uint32_t W = ws[c], H = hs[c], k;
        long hits = 0, falseh = 0;
        uint8_t *hit = (uint8_t *)malloc((size_t)W * H);
        fovsdf_output out;
        char nm[96];
        fovsdf_scene_init(&scene);
        scene.dist = fs_dist;
        scene.user = &sc;
        fovsdf_camera_init(&cam, W, H);
        cam.pos[0] = cam.pos[1] = cam.pos[2] = 0.0f;
        cam.target[0] = cam.target[1] = 0.0f;
        cam.target[2] = 1.0f;
        cam.fov_y_deg = fovs[c];
        cfg.t_max = 20.0f;
        cfg.shading = FOVSDF_SHADE_DEPTH;
        gz.x = 0.5f * (float)W; gz.y = 0.5f * (float)H;
        if (!hit || fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) { check(0, "wide_init", "init"); free(hit); continue; }
        fovsdf_output_init(&out);
        out.hit = hit;
        (void)fovsdf_render_rows(&ctx, 0, H, &out, NULL);
        for (k = 0; k < W * H; ++k) {
            float ro[3], rd[3];
            double cz;
            fs_ref r;
            if (!hit[k]) continue;
            ++hits;
            (void)fovsdf_camera_ray(&ctx, (float)(k % W) + 0.5f, (float)(k / W) + 0.5f, ro, rd);
            cz = (double)rd[0] * (double)ctx.fwd[0] + (double)rd[1] * (double)ctx.fwd[1] + (double)rd[2] * (double)ctx.fwd[2];
            r = fs_reference(&sc, ro, rd, (double)ctx.t_max, 1e-4, 0.0, 0.0, (double)ctx.pixel_angle * cz);
            if (!r.near) ++falseh;
        }
        snprintf(nm, sizeof nm, "wide_no_false_hits_fov%g_%ux%u", (double)fovs[c], W, H);
        fovcheck_info("%s: %ld false hits of %ld hits, %u pixels (%.2f %% of the pixels)", nm, falseh, hits, W * H,
             100.0 * (double)falseh / (double)(W * H));
        check(falseh == 0, nm, "%ld of %ld hits (%u pixels) where the reference ray never comes within one pixel footprint",
              falseh, hits, W * H);
        free(hit);
    }
}

/* ---- item 4: the cone guarantee far from the origin ----------------------------------------
   Single-pixel cones (k ~ 5e-5) seen 1e6 units from the origin approach a box face at normal
   incidence: the cone stops t k (~1e-3) short of it while the float evaluation errs by a few
   ulps of 1e6 (0.06 each): without a margin the pixels start past the face. */
static void test_cone_far(void)
{
    static const double Ds[3] = { 1e4, 1e5, 1e6 };
    static fs_scene sc;
    int di;
    for (di = 0; di < 3; ++di) {
        double D = Ds[di];
        fovsdf_scene scene;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fovsdf_output out;
        enum { W = 64, H = 64 };
        float start[W * H];
        fov_gaze gz = { 32.0f, 32.0f };
        uint32_t m;
        char nm[64];
        memset(&sc, 0, sizeof sc);
        fs_add(&sc, FP_BOX, D * 0.6, D * 0.48, D * 0.64 + 20.0, 3.0, 3.0, 0.5, 0, 0);
        fs_add(&sc, FP_MENGER, D * 0.6 + 1.0, D * 0.48 + 0.5, D * 0.64 + 17.0, 0, 0, 0, 1.3, 0);
        fovsdf_scene_init(&scene);
        scene.dist = fs_dist;
        scene.user = &sc;
        fovsdf_camera_init(&cam, W, H);
        cam.pos[0] = (float)(D * 0.6); cam.pos[1] = (float)(D * 0.48); cam.pos[2] = (float)(D * 0.64);
        cam.target[0] = cam.pos[0]; cam.target[1] = cam.pos[1]; cam.target[2] = cam.pos[2] + 10.0f;
        cam.fov_y_deg = 2.0f;
        cfg.cone_tile = 16;
        cfg.cone_levels = 5; /* down to single pixels */
        cfg.t_max = 60.0f;
        cfg.shading = FOVSDF_SHADE_DEPTH;
        for (m = FOVSDF_METHOD_CONE; m <= FOVSDF_METHOD_CONE_FOV; m += 4u) {
            long bad = 0, n = 0;
            double worst = -(double)INFINITY;
            int k;
            uint8_t mask[W * H];
            cfg.method = m;
            if (fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) { check(0, "cone_far_init", "init"); continue; }
            fovsdf_output_init(&out);
            out.start = start; out.mask = mask;
            memset(mask, 1, sizeof mask);
            (void)fovsdf_render_rows(&ctx, 0, H, &out, NULL);
            for (k = 0; k < W * H; ++k) {
                float ro[3], rd[3];
                fs_ref r;
                if (mask[k] != 1 || !(start[k] > 0.0f) || start[k] >= ctx.t_max) continue;
                (void)fovsdf_camera_ray(&ctx, (float)(k % W) + 0.5f, (float)(k / W) + 0.5f, ro, rd);
                r = fs_reference(&sc, ro, rd, (double)ctx.t_max, 1e-4, 0.0, 0.0, 0.0);
                ++n;
                if ((double)start[k] - r.t_hit > worst) worst = (double)start[k] - r.t_hit;
                if ((double)start[k] > r.t_hit) ++bad;
            }
            snprintf(nm, sizeof nm, "cone_far%.0e_start_before_first_hit_%s", D, fovsdf_method_name(m));
            check(bad == 0 && n > 0, nm, "%ld of %ld pixels start past their first hit (worst by %.3g)", bad, n, worst);
        }
    }
}

int main(void)
{
    test_secant_jump();
    test_ball_certificate();
    test_f3_t_max();
    test_f5_nonfinite();
    test_wide_fov();
    test_cone_far();
    test_props();
    return fovcheck_summary();
}
