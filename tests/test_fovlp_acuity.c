/* tests/test_fovlp_acuity.c - fovlp_config_acuity (the log-polar parameters from the shared eye
   model and the display) against an independent double-precision computation.

   The reference, written here from the formulas of the fovlp.h doc block (not by calling the
   library's derivation): f = the eye distance in pixels (distance_mm / pixel_pitch_mm, or
   (H / 2) / tan(fov_y / 2)), ppd = f pi / 180, MAR(e) = (mar0 + slope e) / 60 degrees with the
   fov_eye defaults 1 arcmin and 1.32 arcmin per degree (Guenter et al. 2012), the allowed
   spacing s(r) = quality MAR(atan(r / f)) ppd pixels; the buffer from the config as eq. 3.6 of
   the thesis (K. Andersson, T. Hansson, "Performance Optimizations for Foveated Real-Time
   Raytracing", Lund University, 2020) gives it: h = round(sqrt(W H / lp_aspect) / sigma),
   w = round(h lp_aspect), r_G = f tan(gaze_angle), L = log(diagonal), G = (log r_G / L)^alpha,
   w_C = w / (1 - G), u_G = w G / (1 - G); the sample radii r(u) = exp(L ((u + u_G) /
   w_C)^(1 / alpha)). Checked:
   - for four displays and three quality values, every radial gap r(u + 1) - r(u) (u from 0 in
     steps of 1/8, any jitter) and every arc 2 pi r / h from the disc edge to the diagonal
     within s(r) (1e-3 float slack), and both worst ratios above 0.97 (neither the rows nor
     the columns more than 3 % more than the rule needs); the frame's own radius table (ctx.rho, with TAA jitter,
     four frames) too; the disc at least e_full = (1 / (ppd quality) - mar0) / slope;
   - monotone: the shaded samples per screen pixel (gaze at the centre) never grow with the
     quality knob, with the ppd of a monitor seen from farther away, nor with the pixel count
     over a fixed field of view; over a fixed field of view (100 degrees, 400 x 400 to
     3200 x 3200 pixels) the LP rows stay the same (the arcs depend on angles only) and the
     LP texels grow by less than a tenth of the pixel count's factor 64 (the eye's periphery
     needs about the same samples whatever the pixel count);
   - a display whose pixels are coarser than the eye out to E (10, 20, 30 degrees): every pixel
     whose centre lies within E of the gaze (the reference's angle between the eye's rays) is a
     disc pixel with exactly one sample, in that pixel;
   - every other config field kept, the presets unchanged, and bad input (eye fields, cam,
     config, a display coarser than the eye everywhere) rejected with its code, logged once,
     *cfg untouched.
   Prints one line per check and "N passed, N failed". */
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

#define PI_D 3.14159265358979323846

static int log_calls;
static int32_t log_code;
static char log_msg[160];
static void logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                   void *user)
{
    (void)tag; (void)line; (void)user;
    if (level != FOV_LOG_ERROR) return;
    log_calls++;
    log_code = code;
    snprintf(log_msg, sizeof log_msg, "%s", msg);
}

/* a display case */
typedef struct dcase {
    const char *name;
    uint32_t w, h;
    fov_display d;
    float cam_fov; /* > 0: passed as a fovlp_camera (display all zero) */
} dcase;

/* the reference eye distance in pixels */
static double ref_f(const dcase *c)
{
    if (c->d.fov_y_deg > 0.0f) return 0.5 * c->h / tan(0.5 * (double)c->d.fov_y_deg * PI_D / 180.0);
    if (c->d.pixel_pitch_mm > 0.0f) return (double)c->d.distance_mm / (double)c->d.pixel_pitch_mm;
    return 0.5 * c->h / tan(0.5 * (double)c->cam_fov * PI_D / 180.0);
}
/* the reference allowed spacing in pixels at r pixels from an on-axis gaze */
static double ref_s(double f, double q, double r)
{
    double e = atan(r / f) * 180.0 / PI_D;
    return q * (1.0 + 1.32 * e) / 60.0 * (f * PI_D / 180.0);
}
static double ref_efull(double f, double q)
{
    double e = (60.0 / (f * PI_D / 180.0 * q) - 1.0) / 1.32;
    return e > 0.0 ? e : 0.0;
}

static fov_result make(const dcase *c, float q, fovlp_config *cfg)
{
    fovlp_camera cam;
    fov_eye eye;
    memset(&cam, 0, sizeof cam);
    memset(&eye, 0, sizeof eye);
    eye.quality = q;
    *cfg = fovlp_config_default();
    cfg->width = c->w;
    cfg->height = c->h;
    cfg->display = c->d;
    cfg->logger.func = logger;
    cam.tan_half_y = (float)tan(0.5 * (double)c->cam_fov * PI_D / 180.0);
    return fovlp_config_acuity(cfg, c->cam_fov > 0.0f ? &cam : NULL, &eye);
}

typedef struct env {
    fovlp_ctx ctx;
    void *mem;
} env;
static fov_result env_init(env *e, const fovlp_config *cfg)
{
    size_t bytes = 0;
    fov_result r = fovlp_memory_size(cfg, &bytes);
    e->mem = NULL;
    if (r != FOV_OK) return r;
    e->mem = malloc(bytes);
    return fovlp_init(&e->ctx, cfg, e->mem, bytes);
}

/* shaded samples per screen pixel, gaze at the screen centre */
static double shaded_frac(const fovlp_config *cfg, fovlp_geometry *geo)
{
    env e;
    fovlp_counts n;
    fov_gaze gz;
    double v = -1.0;
    gz.x = 0.5f * (float)cfg->width;
    gz.y = 0.5f * (float)cfg->height;
    if (env_init(&e, cfg) == FOV_OK && fovlp_begin_frame(&e.ctx, gz, NULL) == FOV_OK &&
        fovlp_count_samples(&e.ctx, &n) == FOV_OK) {
        v = (double)n.shaded / ((double)cfg->width * (double)cfg->height);
        if (geo) *geo = e.ctx.geo;
    }
    free(e.mem);
    return v;
}

static const dcase CASES[4] = {
    { "640x360_cam45", 640, 360, { 0, 0, 0, 0, 0 }, 45.0f },
    { "640x360_cam65", 640, 360, { 0, 0, 0, 0, 0 }, 65.0f },
    { "1920x1080_27in_60cm", 1920, 1080, { 0, 0.3113f, 600.0f, 0, 0 }, 31.0f },
    { "1600x1600_100deg", 1600, 1600, { 100.0f, 0, 0, 0, 0 }, 0.0f },
};

static void test_spacing(void)
{
    static const float QS[3] = { 0.5f, 1.0f, 2.0f };
    uint32_t ci, qi;
    for (ci = 0; ci < 4; ++ci) {
        for (qi = 0; qi < 3; ++qi) {
            const dcase *c = &CASES[ci];
            double q = QS[qi], f = ref_f(c), W = c->w, H = c->h, R = sqrt(W * W + H * H);
            double L = log(R), hd, wd, rg, G, wc, ug, al, worst_r = 0.0, worst_a = 0.0, u;
            double worst_tab = 0.0, ef;
            fovlp_config cfg;
            env e;
            fov_result r = make(c, QS[qi], &cfg);
            uint32_t fr, i;
            const char *nm = fovcheck_name("%s_q%.1f", c->name, q);
            char name[96];
            snprintf(name, sizeof name, "%s", nm);
            if (!check(r == FOV_OK, fovcheck_name("acuity_ok_%s", name), "%d %s", (int)r,
                       log_msg))
                continue;
            /* the buffer, independently (eq. 3.6, 3.3-3.5) */
            hd = floor(sqrt(W * H / (double)cfg.lp_aspect) / (double)cfg.sigma + 0.5);
            wd = floor(hd * (double)cfg.lp_aspect + 0.5);
            al = cfg.alpha;
            rg = f * tan(cfg.gaze_angle);
            G = pow(log(rg) / L, al);
            wc = wd / (1.0 - G);
            ug = wd * G / (1.0 - G);
            cfg.taa.enable = 1; /* jittered radius tables below */
            if (!check(env_init(&e, &cfg) == FOV_OK, fovcheck_name("acuity_init_%s", name), " "))
                { free(e.mem); continue; }
            check(e.ctx.geo.lp_w == (uint32_t)wd && e.ctx.geo.lp_h == (uint32_t)hd &&
                      fabs((double)e.ctx.geo.r_g - rg) < 1e-3 * rg + 1e-3 &&
                      fabs((double)e.ctx.geo.w_c - wc) < 1e-3 * wc,
                  fovcheck_name("acuity_geometry_as_eq_3_6_%s", name),
                  "lib %u x %u r_g %g w_c %g, ref %g x %g r_g %g w_c %g", e.ctx.geo.lp_w,
                  e.ctx.geo.lp_h, (double)e.ctx.geo.r_g, (double)e.ctx.geo.w_c, wd, hd, rg, wc);
            for (u = 0.0;; u += 0.125) {
                double r0 = exp(L * pow((u + ug) / wc, 1.0 / al));
                double r1 = exp(L * pow((u + 1.0 + ug) / wc, 1.0 / al));
                double s0 = ref_s(f, q, r0);
                if (r0 > R) break;
                if ((r1 - r0) / s0 > worst_r) worst_r = (r1 - r0) / s0;
                if (2.0 * PI_D * r0 / hd / s0 > worst_a) worst_a = 2.0 * PI_D * r0 / hd / s0;
            }
            if (2.0 * PI_D * R / hd / ref_s(f, q, R) > worst_a)
                worst_a = 2.0 * PI_D * R / hd / ref_s(f, q, R);
            check(worst_r <= 1.001, fovcheck_name("acuity_radial_gap_within_eye_%s", name),
                  "worst gap / allowed %.4f", worst_r);
            check(worst_a <= 1.001, fovcheck_name("acuity_arc_within_eye_%s", name),
                  "worst arc / allowed %.4f", worst_a);
            /* and no direction oversampled: a buffer 3 % smaller would break the rule */
            check(worst_r >= 0.97 && worst_a >= 0.97, fovcheck_name("acuity_tight_%s", name),
                  "worst radial %.4f, angular %.4f of the allowed spacing", worst_r, worst_a);
            /* the frames' own tables: TAA jitter, gazes at the centre and a corner */
            for (fr = 0; fr < 4; ++fr) {
                fov_gaze gz;
                gz.x = fr & 1u ? 0.0f : 0.5f * (float)W;
                gz.y = fr & 1u ? 0.0f : 0.5f * (float)H;
                if (fovlp_begin_frame(&e.ctx, gz, NULL) != FOV_OK) { worst_tab = 99.0; break; }
                for (i = 0; i + 1 < e.ctx.geo.lp_w; ++i) {
                    double r0 = e.ctx.rho[i], r1 = e.ctx.rho[i + 1], s0 = ref_s(f, q, r0);
                    if (r0 > R) break;
                    if ((r1 - r0) / s0 > worst_tab) worst_tab = (r1 - r0) / s0;
                }
                if ((double)e.ctx.rho[0] - rg > ref_s(f, q, rg) * 1.001) worst_tab = 98.0;
            }
            check(worst_tab <= 1.001, fovcheck_name("acuity_frame_radii_within_eye_%s", name),
                  "worst table gap / allowed %.4f", worst_tab);
            ef = ref_efull(f, q);
            check(rg >= f * tan(ef * PI_D / 180.0) * 0.9999 && rg >= 1.0,
                  fovcheck_name("acuity_disc_covers_e_full_%s", name), "r_G %g, e_full %g -> %g",
                  rg, ef, f * tan(ef * PI_D / 180.0));
            if (qi == 1) {
                double sf = shaded_frac(&cfg, NULL);
                fovcheck_info("%s quality 1: sigma %.3f alpha %.3f gaze_angle %.4f r_G %.1f px, "
                              "LP %u x %u, saving %.2fx (gaze at the centre)",
                              c->name, (double)cfg.sigma, (double)cfg.alpha,
                              (double)cfg.gaze_angle, rg, e.ctx.geo.lp_w, e.ctx.geo.lp_h,
                              1.0 / sf);
            }
            free(e.mem);
        }
    }
}

static void test_monotone(void)
{
    static const float QS[6] = { 0.5f, 0.75f, 1.0f, 1.5f, 2.0f, 3.0f };
    static const float DIST[5] = { 300.0f, 450.0f, 600.0f, 900.0f, 1200.0f };
    static const uint32_t SIZE[4] = { 400, 800, 1600, 3200 };
    double prev = 2.0, v, lp0 = 0.0, lpmin = 1e30, lpmax = 0.0;
    uint32_t i, bad = 0, hmin = 0xFFFFFFFFu, hmax = 0;
    fovlp_config cfg;
    fovlp_geometry g;
    dcase c;
    /* quality knob, at each display */
    for (i = 0; i < 24; ++i) {
        const dcase *dc = &CASES[i / 6];
        if (i % 6 == 0) prev = 2.0;
        v = make(dc, QS[i % 6], &cfg) == FOV_OK ? shaded_frac(&cfg, NULL) : 9.0;
        if (!(v > 0.0 && v <= prev)) ++bad;
        prev = v;
    }
    check(bad == 0, "acuity_monotone_in_quality", "%u increases", bad);
    /* ppd: the 27-inch monitor from 30 to 120 cm (ppd 16.8 .. 67.3) */
    c = CASES[2];
    prev = 2.0; bad = 0;
    for (i = 0; i < 5; ++i) {
        c.d.distance_mm = DIST[i];
        v = make(&c, 1.0f, &cfg) == FOV_OK ? shaded_frac(&cfg, NULL) : 9.0;
        if (!(v > 0.0 && v <= prev)) ++bad;
        fovcheck_info("monitor at %.0f mm (ppd %.1f): shaded / pixels %.4f", (double)DIST[i],
                      ref_f(&c) * PI_D / 180.0, v);
        prev = v;
    }
    check(bad == 0, "acuity_monotone_in_ppd_distance", "%u increases", bad);
    /* pixel count over a fixed 100 degree field: fewer samples per pixel, about the same LP */
    c = CASES[3];
    prev = 2.0; bad = 0;
    for (i = 0; i < 4; ++i) {
        c.w = c.h = SIZE[i];
        v = make(&c, 1.0f, &cfg) == FOV_OK ? shaded_frac(&cfg, &g) : 9.0;
        if (!(v > 0.0 && v <= prev)) ++bad;
        lp0 = (double)g.lp_w * g.lp_h;
        if (lp0 < lpmin) lpmin = lp0;
        if (lp0 > lpmax) lpmax = lp0;
        if (g.lp_h < hmin) hmin = g.lp_h;
        if (g.lp_h > hmax) hmax = g.lp_h;
        fovcheck_info("%u x %u over 100 degrees: LP %u x %u, shaded / pixels %.4f", SIZE[i],
                      SIZE[i], g.lp_w, g.lp_h, v);
        prev = v;
    }
    check(bad == 0, "acuity_monotone_in_pixel_count_fixed_fov", "%u increases", bad);
    check(hmax - hmin <= 2u && lpmax <= 0.1 * 64.0 * lpmin,
          "acuity_lp_buffer_grows_slower_than_pixels_fixed_fov",
          "LP rows %u .. %u, LP texels %g .. %g (pixels x64)", hmin, hmax, lpmin, lpmax);
}

/* a display coarser than the eye out to E: no reduction inside E */
static void test_coarse(void)
{
    static const double ES[3] = { 10.0, 20.0, 30.0 };
    uint32_t k;
    for (k = 0; k < 3; ++k) {
        double E = ES[k], ppd = 60.0 / (1.0 + 1.32 * E) * 0.98, f = ppd * 180.0 / PI_D;
        dcase c = { "coarse", 640, 360, { 0, 0, 0, 0, 0 }, 0.0f };
        fovlp_config cfg;
        env e;
        fov_gaze gz = { 320.0f, 180.0f };
        size_t n = 0, j;
        fovlp_sample *smp;
        uint32_t x, y, inside = 0, miss = 0;
        unsigned char *hits;
        c.d.fov_y_deg = (float)(2.0 * atan(180.0 / f) * 180.0 / PI_D);
        if (!check(make(&c, 1.0f, &cfg) == FOV_OK, fovcheck_name("coarse_ok_E%.0f", E), "%s",
                   log_msg))
            continue;
        if (env_init(&e, &cfg) != FOV_OK || fovlp_begin_frame(&e.ctx, gz, NULL) != FOV_OK) {
            check(0, fovcheck_name("coarse_init_E%.0f", E), " ");
            free(e.mem);
            continue;
        }
        fovlp_samples(&e.ctx, 0, fovlp_sample_rows(&e.ctx), NULL, 0, &n);
        smp = (fovlp_sample *)malloc(n * sizeof *smp);
        hits = (unsigned char *)calloc(640u * 360u, 1);
        fovlp_samples(&e.ctx, 0, fovlp_sample_rows(&e.ctx), smp, n, &n);
        for (j = 0; j < n; ++j) { /* disc samples: count them per pixel */
            uint32_t sl = smp[j].slot;
            if (sl >= e.ctx.geo.disc_offset && sl < e.ctx.geo.centre_slot) {
                uint32_t px = (uint32_t)smp[j].x, py = (uint32_t)smp[j].y;
                if (px < 640 && py < 360 && hits[py * 640 + px] < 255) hits[py * 640 + px]++;
            }
        }
        for (y = 0; y < 360; ++y)
            for (x = 0; x < 640; ++x) {
                /* the angle between the eye's rays through the pixel centre and the gaze */
                double a[3] = { x + 0.5 - 320.0, y + 0.5 - 180.0, f }, b[3] = { 0, 0, f };
                double cr = sqrt(pow(a[1] * b[2] - a[2] * b[1], 2) +
                                 pow(a[2] * b[0] - a[0] * b[2], 2) +
                                 pow(a[0] * b[1] - a[1] * b[0], 2));
                double ecc = atan2(cr, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) * 180.0 / PI_D;
                if (ecc >= E) continue;
                ++inside;
                if (hits[y * 640 + x] != 1) ++miss;
            }
        check(inside > 0 && miss == 0, fovcheck_name("coarse_every_pixel_inside_E%.0f_traced", E),
              "%u of %u pixels inside %.0f degrees without exactly one disc sample", miss, inside,
              E);
        free(smp); free(hits); free(e.mem);
    }
}

/* FOVLP_RECON_CUBIC (what fovlp_config_acuity selects): LP samples holding sinusoids of period 8
   texels along v (channel 0) and along u (channel 1) and a ramp along u (channel 2), gaze at
   the centre, no TAA; at every pixel whose LP coordinate lies away from the first and last
   columns and the angle seam, 3 sample spacings or more from the screen's border, the
   reconstruction against the continuous functions the
   samples were taken from: Catmull-Rom's error below 0.35 of bilinear's on both sinusoids
   (bilinear flattens them), the ramp the same as bilinear's (both reproduce linear
   functions), every pixel inside the samples' range; a recon value out of range rejected. */
static double g8(double t) { return 0.5 + 0.5 * sin(2.0 * PI_D * t / 8.0); }
static void test_cubic(void)
{
    static const dcase dc = { "640x360 at 45 degrees", 640, 360, { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f }, 45.0f };
    fovlp_config cfg[2];
    env e[2];
    fov_gaze gz = { 320.0f, 180.0f };
    float *smp = NULL, *img[2] = { NULL, NULL };
    double err[2][2] = { { 0, 0 }, { 0, 0 } }, ramp = 0.0;
    float lo = 1.0f, hi = 0.0f;
    long n = 0;
    uint32_t k, x, y;
    fov_result r;
    int ok = make(&dc, 1.0f, &cfg[0]) == FOV_OK;
    e[0].mem = e[1].mem = NULL; /* freed below whatever failed */
    check(ok && cfg[0].recon == (uint32_t)FOVLP_RECON_CUBIC, "acuity_selects_cubic", "%u",
          (unsigned)cfg[0].recon);
    cfg[1] = cfg[0];
    cfg[1].recon = FOVLP_RECON_BILINEAR;
    for (k = 0; k < 2 && ok; ++k) {
        ok = env_init(&e[k], &cfg[k]) == FOV_OK && fovlp_begin_frame(&e[k].ctx, gz, NULL) == FOV_OK;
        img[k] = (float *)malloc((size_t)dc.w * dc.h * 3 * sizeof(float));
    }
    if (ok) {
        const fovlp_geometry *g = &e[0].ctx.geo;
        smp = (float *)malloc((size_t)g->samples * 3 * sizeof(float));
        for (k = 0; k < g->samples; ++k) {
            uint32_t u = k % g->lp_w, v = k / g->lp_w;
            int lp = k < g->lp_slots;
            smp[3 * k] = lp ? (float)g8((double)v) : 0.5f;
            smp[3 * k + 1] = lp ? (float)g8((double)u) : 0.5f;
            smp[3 * k + 2] = lp ? (float)u / (float)g->lp_w : 0.5f;
        }
        for (k = 0; k < 2; ++k)
            ok = ok && fovlp_reconstruct_rows(&e[k].ctx, smp, NULL, 0, dc.h, img[k], 0, NULL) == FOV_OK;
    }
    for (y = 0; ok && y < dc.h; ++y)
        for (x = 0; x < dc.w; ++x) {
            const float *a = img[0] + 3 * ((size_t)y * dc.w + x), *b = img[1] + 3 * ((size_t)y * dc.w + x);
            float u, v;
            double su, sv;
            for (k = 0; k < 3; ++k) { lo = fminf(lo, a[k]); hi = fmaxf(hi, a[k]); }
            if (fovlp_screen_to_lp(&e[0].ctx, (float)x + 0.5f, (float)y + 0.5f, &u, &v) != FOV_OK) continue;
            su = (double)u - (double)e[0].ctx.jit_u;   /* in sample indices */
            sv = (double)v - (double)e[0].ctx.jit_v;
            if (su < 2.0 || su > (double)e[0].ctx.geo.lp_cols - 4.0 || sv < 2.0 ||
                sv > (double)e[0].ctx.geo.lp_h - 3.0)
                continue;
            {   /* the 4 x 4 taps on the screen: 3 sample spacings from every border */
                float dx = (float)x + 0.5f - gz.x, dy = (float)y + 0.5f - gz.y, rs, as;
                float bd = fminf(fminf((float)x + 0.5f, (float)dc.w - (float)x - 0.5f),
                                 fminf((float)y + 0.5f, (float)dc.h - (float)y - 0.5f));
                if (fovlp_spacing(&e[0].ctx, sqrtf(dx * dx + dy * dy), &rs, &as) != FOV_OK ||
                    bd < 3.0f * fmaxf(rs, as))
                    continue;
            }
            err[0][0] += ((double)a[0] - g8(sv)) * ((double)a[0] - g8(sv));
            err[1][0] += ((double)b[0] - g8(sv)) * ((double)b[0] - g8(sv));
            err[0][1] += ((double)a[1] - g8(su)) * ((double)a[1] - g8(su));
            err[1][1] += ((double)b[1] - g8(su)) * ((double)b[1] - g8(su));
            ramp = fmax(ramp, fabs((double)a[2] - (double)b[2]));
            ++n;
        }
    fovcheck_info("cubic: %ld pixels, RMS error along v %.5f (bilinear %.5f), along u %.5f (bilinear %.5f)", n,
                  sqrt(err[0][0] / (double)(n ? n : 1)), sqrt(err[1][0] / (double)(n ? n : 1)),
                  sqrt(err[0][1] / (double)(n ? n : 1)), sqrt(err[1][1] / (double)(n ? n : 1)));
    check(ok && n > 10000 && err[0][0] < 0.35 * 0.35 * err[1][0] && err[0][1] < 0.35 * 0.35 * err[1][1],
          "cubic_keeps_the_contrast_bilinear_loses",
          "%ld pixels, RMS error along v %.5f (bilinear %.5f), along u %.5f (bilinear %.5f)", n,
          sqrt(err[0][0] / (double)(n ? n : 1)), sqrt(err[1][0] / (double)(n ? n : 1)),
          sqrt(err[0][1] / (double)(n ? n : 1)), sqrt(err[1][1] / (double)(n ? n : 1)));
    check(ok && ramp < 1e-5, "cubic_reproduces_a_ramp", "max |cubic - bilinear| %g", ramp);
    check(ok && lo >= 0.0f && hi <= 1.0f, "cubic_inside_the_samples_range", "[%g, %g]", (double)lo,
          (double)hi);
    for (k = 0; k < 2; ++k) { free(e[k].mem); free(img[k]); }
    free(smp);
    cfg[0] = fovlp_config_default();
    cfg[0].width = 64; cfg[0].height = 64; cfg[0].logger.func = logger;
    cfg[0].recon = (uint32_t)_FOVLP_RECON_NUM;
    log_calls = 0; log_msg[0] = 0;
    r = fovlp_config_resolve(&cfg[0], &cfg[1]);
    check(r == FOV_ERR_INVALID_ARG && log_calls == 1 && strstr(log_msg, "recon") != NULL,
          "bad_config_recon", "%d, %d logger calls, \"%s\"", (int)r, log_calls, log_msg);
}

static void test_fields_and_errors(void)
{
    fovlp_config cfg, keep;
    fov_eye eye;
    fovlp_camera cam;
    fov_result r;
    int ok;
    /* other fields kept */
    cfg = fovlp_config_default();
    cfg.width = 800; cfg.height = 600;
    cfg.taa.enable = 1; cfg.blend = 1; cfg.match_deg = 20.0f; cfg.display.fov_y_deg = 60.0f;
    cfg.taa.max_age = 7; cfg.logger.func = logger;
    keep = cfg;
    r = fovlp_config_acuity(&cfg, NULL, NULL);
    keep.sigma = cfg.sigma; keep.alpha = cfg.alpha; keep.gaze_angle = cfg.gaze_angle;
    keep.lp_aspect = cfg.lp_aspect; keep.recon = cfg.recon;
    check(r == FOV_OK && memcmp(&keep, &cfg, sizeof cfg) == 0,
          "acuity_fills_only_the_foveation_fields", "%d", (int)r);
    /* the presets */
    cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 640, 360);
    check(fabsf(cfg.sigma - 1.4f) < 1e-6f && fabsf(cfg.gaze_angle - 0.2f) < 1e-6f &&
              cfg.recon == (uint32_t)FOVLP_RECON_BILINEAR &&
              fabsf(cfg.lp_aspect - 0.33f) < 1e-6f && !strcmp(fovlp_preset_name(2), "C Fov"),
          "presets_unchanged", " ");
    /* bad input */
#define BAD(expr_setup, expect, name, word)                                                    \
    do {                                                                                       \
        cfg = fovlp_config_default();                                                          \
        cfg.width = 640; cfg.height = 360; cfg.logger.func = logger;                           \
        memset(&eye, 0, sizeof eye);                                                           \
        memset(&cam, 0, sizeof cam); cam.tan_half_y = 0.4f;                                    \
        expr_setup;                                                                            \
        keep = cfg; log_calls = 0; log_msg[0] = 0;                                             \
        r = fovlp_config_acuity(&cfg, &cam, &eye);                                             \
        ok = r == (expect) && log_calls == 1 && log_code == (int32_t)(expect) &&               \
             strstr(log_msg, word) != NULL && memcmp(&keep, &cfg, sizeof cfg) == 0;            \
        check(ok, name, "got %d, %d logger calls, \"%s\"", (int)r, log_calls, log_msg);        \
    } while (0)
    BAD(eye.mar0_arcmin = NAN, FOV_ERR_NOT_FINITE, "bad_eye_mar0_nan", "mar0_arcmin");
    BAD(eye.mar0_arcmin = -1.0f, FOV_ERR_INVALID_ARG, "bad_eye_mar0_negative", "mar0_arcmin");
    BAD(eye.mar0_arcmin = 61.0f, FOV_ERR_INVALID_ARG, "bad_eye_mar0_over_60", "mar0_arcmin");
    BAD(eye.slope_arcmin = INFINITY, FOV_ERR_NOT_FINITE, "bad_eye_slope_inf", "slope_arcmin");
    BAD(eye.slope_arcmin = -0.5f, FOV_ERR_INVALID_ARG, "bad_eye_slope_negative", "slope_arcmin");
    BAD(eye.slope_arcmin = 75.0f, FOV_ERR_INVALID_ARG, "bad_eye_slope_over_60", "slope_arcmin");
    BAD(eye.quality = -NAN, FOV_ERR_NOT_FINITE, "bad_eye_quality_nan", "quality");
    BAD(eye.quality = -2.0f, FOV_ERR_INVALID_ARG, "bad_eye_quality_negative", "quality");
    BAD(eye.quality = 101.0f, FOV_ERR_INVALID_ARG, "bad_eye_quality_over_100", "quality");
    BAD(cam.tan_half_y = NAN, FOV_ERR_NOT_FINITE, "bad_cam_tan_nan", "tan_half_y");
    BAD(cam.tan_half_y = 0.0f, FOV_ERR_INVALID_ARG, "bad_cam_tan_zero", "tan_half_y");
    BAD(cam.tan_half_y = -1.0f, FOV_ERR_INVALID_ARG, "bad_cam_tan_negative", "tan_half_y");
    BAD(cfg.width = 0, FOV_ERR_INVALID_ARG, "bad_config_width_zero", "width");
    BAD(cfg.display.fov_y_deg = 200.0f, FOV_ERR_INVALID_ARG, "bad_config_display_fov",
        "fov_y_deg");
    BAD(cfg.taa.phases = 999, FOV_ERR_INVALID_ARG, "bad_config_other_field", "phases");
    /* 64 x 36 seen over 170 degrees: coarser than the eye nearly everywhere */
    BAD((cfg.width = 64, cfg.height = 36, cfg.display.fov_y_deg = 170.0f), FOV_ERR_UNSUPPORTED,
        "coarse_everywhere_unsupported", "every pixel");
    check(fovlp_config_acuity(NULL, NULL, NULL) == FOV_ERR_NULL, "null_config", " ");
    /* cam: written to cam_fov_y_deg when the display is all zero, ignored otherwise */
    cfg = fovlp_config_default();
    cfg.width = 640; cfg.height = 360;
    cam.tan_half_y = (float)tan(22.5 * PI_D / 180.0);
    r = fovlp_config_acuity(&cfg, &cam, NULL);
    check(r == FOV_OK && fabsf(cfg.cam_fov_y_deg - 45.0f) < 1e-3f, "cam_sets_cam_fov_y_deg",
          "%d %g", (int)r, (double)cfg.cam_fov_y_deg);
    keep = cfg; /* the same model from cfg.cam_fov_y_deg without a camera (the camera's
                   45 degrees through tan and atan: equal up to float rounding) */
    cfg = fovlp_config_default();
    cfg.width = 640; cfg.height = 360; cfg.cam_fov_y_deg = 45.0f;
    r = fovlp_config_acuity(&cfg, NULL, NULL);
    check(r == FOV_OK && fabsf(keep.sigma - cfg.sigma) <= 1e-4f * cfg.sigma &&
              fabsf(keep.alpha - cfg.alpha) <= 1e-4f * cfg.alpha &&
              fabsf(keep.gaze_angle - cfg.gaze_angle) <= 1e-4f * cfg.gaze_angle &&
              fabsf(keep.lp_aspect - cfg.lp_aspect) <= 1e-4f * cfg.lp_aspect,
          "cam_fov_y_deg_without_cam_same",
          "%d: sigma %g / %g", (int)r, (double)cfg.sigma, (double)keep.sigma);
    cfg = fovlp_config_default(); /* neither: the thesis's viewing distance, as fovlp_init */
    cfg.width = 640; cfg.height = 360;
    r = fovlp_config_acuity(&cfg, NULL, NULL);
    {
        fovlp_geometry g;
        fov_gaze gz = { 320.0f, 180.0f };
        double f = sqrt(640.0 * 640.0 + 360.0 * 360.0) / tan(60.0 * PI_D / 180.0);
        int okg = r == FOV_OK && fovlp_geometry_get(&cfg, gz, &g) == FOV_OK;
        check(okg && fabs((double)g.f_px - f) < 1e-3 * f &&
                  (double)g.r_g >= f * tan(ref_efull(f, 1.0) * PI_D / 180.0) * 0.9999,
              "no_display_no_cam_thesis_distance", "%d f %g (ref %g) r_g %g", (int)r,
              okg ? (double)g.f_px : 0.0, f, okg ? (double)g.r_g : 0.0);
    }
    cfg = fovlp_config_default();
    cfg.width = 640; cfg.height = 360; cfg.display.fov_y_deg = 45.0f;
    r = fovlp_config_acuity(&cfg, &cam, NULL);
    check(r == FOV_OK && !(cfg.cam_fov_y_deg > 0.0f) && !(cfg.cam_fov_y_deg < 0.0f), "cam_ignored_with_a_display",
          "%d %g", (int)r, (double)cfg.cam_fov_y_deg);
}

int main(void)
{
    test_spacing();
    test_monotone();
    test_coarse();
    test_fields_and_errors();
    test_cubic();
    return fovcheck_summary();
}
