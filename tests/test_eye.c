/* test_eye.c - the shared eye model (fov_eye, fov_eye_plan) of fovsdf.h, fovlp.h and fovpt.h:
   the minimum angle of resolution against the published linear model (Guenter, Finch, Drucker,
   Tan and Snyder, "Foveated 3D Graphics", 2012: slope 1.32-1.65 arc minutes per degree; 1 arc
   minute at the gaze for 20/20 vision), the density a display needs at each eccentricity and
   its inverse, worked out here in double precision from the formula, the plan of a monitor
   given by pixel pitch and distance, monotonicity in ppd and in the quality knob, a display
   coarser than the eye out to E that gets no reduction inside E, bad input, and the same
   answers from the three headers. Prints "N passed, N failed". */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOV_IMPL
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define N fovcheck_name

/* fov_eye's documented default quality (a zero field, or a NULL eye): samples at most 0.5 MAR
   apart, twice the Nyquist rate of the finest grating the eye resolves */
#define Q0 0.5

static fov_eye eye(float mar0, float slope, float q)
{
    fov_eye e;
    e.mar0_arcmin = mar0;
    e.slope_arcmin = slope;
    e.quality = q;
    return e;
}

static int rel_near(double a, double b, double tol)
{
    return fabs(a - b) <= tol * fmax(fabs(b), 1e-30);
}

/* MAR against the published model, worked out by hand: (mar0 + slope e) / 60 degrees */
static void test_mar(void)
{
    static const float ecc[] = { 0.0f, 1.0f, 5.0f, 10.0f, 30.0f, 90.0f };
    fov_eye aggressive = eye(0.0f, 1.65f, 0.0f), twice = eye(0.0f, 0.0f, 2.0f);
    size_t i;
    for (i = 0; i < sizeof ecc / sizeof ecc[0]; i++) {
        double e = ecc[i], want = Q0 * (1.0 + 1.32 * e) / 60.0;
        double got = (double)fovsdf_eye_mar(NULL, ecc[i]);
        check(rel_near(got, want, 1e-5), N("mar_default_%g", e), "%.7g, want %.7g", got, want);
        got = (double)fovsdf_eye_mar(&aggressive, ecc[i]);
        want = Q0 * (1.0 + 1.65 * e) / 60.0; /* quality 0: the default */
        check(rel_near(got, want, 1e-5), N("mar_aggressive_%g", e), "%.7g, want %.7g", got, want);
        got = (double)fovsdf_eye_mar(&twice, ecc[i]);
        want = 2.0 * (1.0 + 1.32 * e) / 60.0;
        check(rel_near(got, want, 1e-5), N("mar_quality2_%g", e), "%.7g, want %.7g", got, want);
    }
    /* a zero-filled eye is the default one */
    {
        fov_eye z;
        memset(&z, 0, sizeof z);
        check(fovsdf_eye_mar(&z, 12.0f) == fovsdf_eye_mar(NULL, 12.0f), "mar_zero_is_default",
              "%g vs %g", (double)fovsdf_eye_mar(&z, 12.0f),
              (double)fovsdf_eye_mar(NULL, 12.0f));
    }
}

/* density = min(1, 1 / (ppd quality MAR)) and its inverse */
static void test_density(void)
{
    static const float ppds[] = { 4.0f, 7.58f, 12.6f, 16.0f, 33.6f, 40.0f, 60.0f, 120.0f };
    static const float dens[] = { 1.0f, 0.75f, 0.5f, 0.25f, 0.1f };
    size_t i, j;
    for (i = 0; i < sizeof ppds / sizeof ppds[0]; i++) {
        double ppd = (double)ppds[i];
        for (j = 0; j < 6; j++) {
            double e = 7.0 * (double)j, want = 1.0 / (ppd * Q0 * (1.0 + 1.32 * e) / 60.0);
            double got = (double)fovsdf_eye_density(NULL, ppds[i], (float)e);
            if (want > 1.0) want = 1.0;
            check(rel_near(got, want, 1e-5), N("density_ppd%g_e%g", ppd, e), "%.7g, want %.7g",
                  got, want);
        }
        for (j = 0; j < sizeof dens / sizeof dens[0]; j++) {
            /* the eccentricity where 1 / (ppd Q0 (1 + 1.32 e) / 60) = d, clamped to [0, 180] */
            double d = (double)dens[j], want = (60.0 / (ppd * Q0 * d) - 1.0) / 1.32;
            float gotf = fovsdf_eye_ecc(NULL, ppds[i], dens[j]);
            double got = (double)gotf;
            if (want < 0.0) want = 0.0;
            if (want > 180.0) want = 180.0;
            check(fabs(got - want) <= 1e-4 * fmax(want, 1.0), N("ecc_ppd%g_d%g", ppd, d),
                  "%.7g, want %.7g", got, want);
            if (want > 0.0 && want < 180.0 && d < 1.0) {
                double back = (double)fovsdf_eye_density(NULL, ppds[i], gotf);
                check(rel_near(back, d, 1e-4), N("ecc_inverse_ppd%g_d%g", ppd, d),
                      "density at %g = %g, want %g", got, back, d);
            }
        }
    }
    /* a display finer than Q0 arc minutes per pixel needs less than every pixel at the gaze
       (240 px/degree: 0.25 arc minutes per pixel, half the default spacing 0.5 arc minutes) */
    check(fovsdf_eye_ecc(NULL, 240.0f, 1.0f) == 0.0f && fovsdf_eye_density(NULL, 240.0f, 0.0f)
          < 0.51f, "finer_than_eye_at_gaze", "ecc %g density %g",
          (double)fovsdf_eye_ecc(NULL, 240.0f, 1.0f),
          (double)fovsdf_eye_density(NULL, 240.0f, 0.0f));
}

/* a display coarser than the eye out to E: no reduction inside E (ppd 4: 15 arc minutes per
   pixel; the default spacing Q0 MAR(E) reaches it at E = (15 / Q0 - 1) / 1.32 = 22.0 degrees) */
static void test_coarse_display(void)
{
    double E = (60.0 / 4.0 / Q0 - 1.0) / 1.32;
    float e;
    int all = 1;
    fov_eye_plan p;
    fov_ecc_model m;
    fov_display d;
    fov_gaze g;
    memset(&d, 0, sizeof d);
    g.x = 100.0f; g.y = 50.0f;
    /* 4 ppd: f = 4 * 180 / pi pixels; a display of vertical field 2 atan(h / 2 / f) */
    d.fov_y_deg = (float)(2.0 * atan(0.5 * 400.0 / (4.0 * 180.0 / 3.14159265358979)) *
                          180.0 / 3.14159265358979);
    check(fovsdf_ecc_init(&m, &d, 0.0f, 600, 400, g) == FOV_OK, "coarse_ecc_init", "-");
    check(fovsdf_eye_plan(NULL, &m, &p) == FOV_OK, "coarse_plan", "-");
    check(rel_near((double)p.ppd, 4.0, 1e-4), "coarse_plan_ppd", "%g", (double)p.ppd);
    check(p.e_full >= (float)E * 0.9999f, "coarse_plan_e_full_covers_E", "%g, E %g",
          (double)p.e_full, E);
    for (e = 0.0f; e < (float)E * 0.999f; e += 0.05f)
        if (fovsdf_eye_density(NULL, p.ppd, e) != 1.0f) all = 0;
    check(all, "coarse_no_reduction_inside_E", "a density below 1 inside %g degrees", E);
    check(fovsdf_eye_density(NULL, p.ppd, (float)E + 1.0f) < 1.0f, "coarse_reduction_beyond_E",
          "%g", (double)fovsdf_eye_density(NULL, p.ppd, (float)E + 1.0f));
}

/* the plan of a 27-inch 1920x1080 monitor at 60 cm: f = 600 / 0.3113 pixels */
static void test_plan_monitor(void)
{
    double f = 600.0 / 0.3113, ppd = f * 3.14159265358979 / 180.0;
    double want[3];
    double got[3];
    fov_eye_plan p;
    fov_ecc_model m;
    fov_display d;
    fov_gaze g;
    int k;
    memset(&d, 0, sizeof d);
    d.pixel_pitch_mm = 0.3113f;
    d.distance_mm = 600.0f;
    g.x = 960.0f; g.y = 540.0f;
    check(fovsdf_ecc_init(&m, &d, 0.0f, 1920, 1080, g) == FOV_OK, "monitor_ecc_init", "-");
    check(fovsdf_eye_plan(NULL, &m, &p) == FOV_OK, "monitor_plan", "-");
    check(rel_near((double)p.ppd, ppd, 1e-5), "monitor_ppd", "%g, want %g", (double)p.ppd, ppd);
    for (k = 0; k < 3; k++)
        want[k] = (60.0 / (ppd * Q0 * (k == 0 ? 1.0 : k == 1 ? 0.5 : 0.25)) - 1.0) / 1.32;
    got[0] = (double)p.e_full; got[1] = (double)p.e_half; got[2] = (double)p.e_quarter;
    for (k = 0; k < 3; k++)
        check(fabs(got[k] - want[k]) <= 1e-4 * fmax(want[k], 1.0), N("monitor_e_%d", k),
              "%g, want %g", got[k], want[k]);
    check(p.e_full <= p.e_half && p.e_half <= p.e_quarter, "monitor_plan_ordered", "%g %g %g",
          got[0], got[1], got[2]);
    /* the plan does not depend on the gaze */
    {
        fov_eye_plan q;
        g.x = 10.0f; g.y = 1000.0f;
        fovsdf_ecc_init(&m, &d, 0.0f, 1920, 1080, g);
        fovsdf_eye_plan(NULL, &m, &q);
        check(!memcmp(&p, &q, sizeof p), "monitor_plan_gaze_independent", "-");
    }
}

/* larger regions of full density on coarser displays and for safer quality */
static void test_monotone(void)
{
    static const float qs[] = { 0.25f, 0.5f, 1.0f, 1.5f, 2.0f, 4.0f };
    float ppd, last[3] = { 1e9f, 1e9f, 1e9f };
    int ok = 1, okq = 1;
    size_t i;
    for (ppd = 2.0f; ppd <= 120.0f; ppd *= 1.1f) {
        float e[3];
        e[0] = fovlp_eye_ecc(NULL, ppd, 1.0f);
        e[1] = fovlp_eye_ecc(NULL, ppd, 0.5f);
        e[2] = fovlp_eye_ecc(NULL, ppd, 0.25f);
        if (e[0] > last[0] || e[1] > last[1] || e[2] > last[2]) ok = 0;
        if (!(e[0] <= e[1] && e[1] <= e[2])) ok = 0;
        memcpy(last, e, sizeof last);
    }
    check(ok, "monotone_in_ppd", "an eccentricity grew with ppd or the order broke");
    last[0] = last[1] = last[2] = 1e9f;
    for (i = 0; i < sizeof qs / sizeof qs[0]; i++) {
        fov_eye q = eye(0.0f, 0.0f, qs[i]);
        float e[3];
        e[0] = fovpt_eye_ecc(&q, 12.0f, 1.0f);
        e[1] = fovpt_eye_ecc(&q, 12.0f, 0.5f);
        e[2] = fovpt_eye_ecc(&q, 12.0f, 0.25f);
        if (e[0] > last[0] || e[1] > last[1] || e[2] > last[2]) okq = 0;
        memcpy(last, e, sizeof last);
    }
    check(okq, "monotone_in_quality", "an eccentricity grew with the quality knob");
    check(fovpt_eye_ecc(NULL, 12.0f, 0.5f) < fovpt_eye_ecc(NULL, 8.0f, 0.5f),
          "strictly_monotone_in_ppd", "-");
}

static void test_bad_input(void)
{
    static const float bad[] = { -1.0f, 61.0f };
    fov_eye_plan p;
    fov_ecc_model m;
    fov_display d;
    fov_gaze g;
    fov_eye e;
    size_t i;
    memset(&d, 0, sizeof d);
    g.x = g.y = 8.0f;
    fovsdf_ecc_init(&m, &d, 60.0f, 16, 16, g);
    check(fovsdf_eye_plan(NULL, NULL, &p) == FOV_ERR_NULL, "bad_plan_null_model", "-");
    check(fovsdf_eye_plan(NULL, &m, NULL) == FOV_ERR_NULL, "bad_plan_null_out", "-");
    for (i = 0; i < 2; i++) {
        e = eye(bad[i], 0.0f, 0.0f);
        check(fovsdf_eye_plan(&e, &m, &p) == FOV_ERR_INVALID_ARG, N("bad_mar0_%g", (double)bad[i]),
              "-");
        check(fovsdf_eye_mar(&e, 1.0f) == 0.0f && fovsdf_eye_density(&e, 10.0f, 5.0f) == 1.0f &&
              fovsdf_eye_ecc(&e, 10.0f, 0.5f) == 180.0f,
              N("bad_mar0_safe_answers_%g", (double)bad[i]), "-");
        e = eye(0.0f, bad[i], 0.0f);
        check(fovsdf_eye_plan(&e, &m, &p) == FOV_ERR_INVALID_ARG, N("bad_slope_%g", (double)bad[i]),
              "-");
    }
    e = eye(0.0f, 0.0f, 101.0f);
    check(fovsdf_eye_plan(&e, &m, &p) == FOV_ERR_INVALID_ARG, "bad_quality_large", "-");
    e = eye(0.0f, 0.0f, -0.5f);
    check(fovsdf_eye_plan(&e, &m, &p) == FOV_ERR_INVALID_ARG, "bad_quality_negative", "-");
    e = eye((float)NAN, 0.0f, 0.0f);
    check(fovsdf_eye_plan(&e, &m, &p) == FOV_ERR_NOT_FINITE, "bad_mar0_nan", "-");
    e = eye(0.0f, 0.0f, (float)INFINITY);
    check(fovsdf_eye_plan(&e, &m, &p) == FOV_ERR_NOT_FINITE, "bad_quality_inf", "-");
    check(fovsdf_eye_mar(NULL, -1.0f) == 0.0f && fovsdf_eye_mar(NULL, (float)NAN) == 0.0f,
          "bad_ecc_mar_zero", "-");
    check(fovsdf_eye_density(NULL, 0.0f, 5.0f) == 1.0f &&
          fovsdf_eye_density(NULL, (float)NAN, 5.0f) == 1.0f &&
          fovsdf_eye_density(NULL, 10.0f, (float)NAN) == 1.0f, "bad_density_is_full", "-");
    check(fovsdf_eye_ecc(NULL, 10.0f, 0.0f) == 180.0f &&
          fovsdf_eye_ecc(NULL, 10.0f, (float)NAN) == 180.0f &&
          fovsdf_eye_ecc(NULL, (float)INFINITY, 0.5f) == 180.0f &&
          fovsdf_eye_ecc(NULL, -3.0f, 1.0f) == 0.0f, "bad_ecc_safe", "-");
    /* extreme but valid: the answers stay in range */
    check(fovsdf_eye_ecc(NULL, 1e-30f, 1e-30f) == 180.0f &&
          fovsdf_eye_ecc(NULL, 3e38f, 1.0f) == 0.0f, "extreme_in_range", "-");
}

/* one model, three headers */
static void test_three_headers(void)
{
    fov_eye e = eye(1.2f, 1.5f, 1.3f);
    int ok = 1;
    float x;
    for (x = 0.0f; x < 60.0f; x += 3.7f) {
        if (fovsdf_eye_mar(&e, x) != fovlp_eye_mar(&e, x) ||
            fovsdf_eye_mar(&e, x) != fovpt_eye_mar(&e, x))
            ok = 0;
        if (fovsdf_eye_density(&e, 20.0f, x) != fovlp_eye_density(&e, 20.0f, x) ||
            fovsdf_eye_density(&e, 20.0f, x) != fovpt_eye_density(&e, 20.0f, x))
            ok = 0;
    }
    check(ok, "three_headers_agree", "-");
}

int main(int argc, char **argv)
{
    if (argc > 1 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        printf("usage: %s\n  checks the shared eye model (fov_eye): MAR against Guenter et al. "
               "2012,\n  densities, plans, monotonicity, bad input, three headers\n", argv[0]);
        return 0;
    }
    test_mar();
    test_density();
    test_coarse_display();
    test_plan_monitor();
    test_monotone();
    test_bad_input();
    test_three_headers();
    return fovcheck_summary();
}
