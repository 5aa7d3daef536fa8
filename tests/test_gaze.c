/* test_gaze.c - gaze input of the shared block (fov_gaze_filter: One Euro filter with saccade
   reset, the latency margin, fixed foveation, pixel <-> degree mapping) in fovsdf.h, fovlp.h
   and fovpt.h, and the gaze trace generator (bench/gaze_trace.h). Expected values are
   worked out here from the stated rules (a still input, a step, Gaussian noise of known RMS,
   a ramp), never taken from the code under test. Prints "N passed, N failed". */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOV_IMPL
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"
#include "fovcheck.h"
#include "bench/gaze_trace.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define N fovcheck_name
#define DT_US 8333u /* 120 Hz */

static fov_gaze_filter fresh(void)
{
    fov_gaze_filter f;
    fov_result r = fovsdf_gaze_filter_init(&f, NULL);
    check(r == FOV_OK, N("init_defaults_%d", (int)r), "code %d", (int)r);
    return f;
}

/* constant input: the output is the input, the margin the stated accuracy */
static void test_constant(void)
{
    fov_gaze_filter f = fresh();
    uint32_t i;
    int ok = 1;
    float m = -1.0f;
    for (i = 0; i < 240; ++i) {
        if (fovsdf_gaze_filter_push(&f, 1000u + i * DT_US, 3.25f, -7.5f) != FOV_OK) ok = 0;
        if (!(fabsf(f.x_deg - 3.25f) <= 1e-5f && fabsf(f.y_deg + 7.5f) <= 1e-5f)) ok = 0;
    }
    check(ok, "constant_input_gives_the_input", "last (%g, %g)", (double)f.x_deg, (double)f.y_deg);
    check(f.saccades == 0u && !f.saccade, "constant_input_no_saccade", "%u", f.saccades);
    fovsdf_gaze_margin(&f, 0.7f, 50.0f, &m);
    check(fabsf(m - 0.7f) <= 1e-4f, "constant_input_margin_is_accuracy", "%g", (double)m);
}

/* a step of 10 degrees (a saccade seen at 120 Hz): the window speed (10 deg over <= 20 ms)
   is far above 100 deg/s, so the raw sample passes at once; the landing resets the filter
   there. Stated: the output is within 0.01 degrees of the target from the first sample after
   the step on (0 samples of lag), and a plain low-pass at 0.5 Hz is not (takes > 50). */
static void test_step(void)
{
    fov_gaze_filter f = fresh(), lp;
    fov_gaze_filter_config c = fovsdf_gaze_filter_config_default();
    uint32_t i, first = 0, lp_first = 0;
    int stays = 1;
    c.beta = FOV_GAZE_BETA_NONE;
    c.saccade_deg_s = 2000.0f;
    check(fovsdf_gaze_filter_init(&lp, &c) == FOV_OK, "init_lowpass", "-");
    for (i = 0; i < 240; ++i) {
        float x = i < 120 ? 0.0f : 10.0f;
        fovsdf_gaze_filter_push(&f, i * DT_US, x, 0.0f);
        fovsdf_gaze_filter_push(&lp, i * DT_US, x, 0.0f);
        if (i >= 120) {
            int near = fabsf(f.x_deg - 10.0f) <= 0.01f;
            if (near && !first) first = i - 119;
            if (first && !near) stays = 0;
            if (!lp_first && fabsf(lp.x_deg - 10.0f) <= 0.01f) lp_first = i - 119;
        }
    }
    check(first == 1u && stays, "step_followed_within_1_sample", "first %u stays %d", first,
          stays);
    check(f.saccades == 1u && !f.saccade, "step_one_saccade_landed", "%u %u", f.saccades,
          f.saccade);
    check(lp_first == 0u || lp_first > 50u, "step_lowpass_slower", "%u", lp_first);
}

/* jitter: a still target seen through white noise of RMS 0.5 degrees (2-D) at 120 Hz; the
   RMS error of the output over the last 4 of 5 seconds is at most a third of the raw one's */
static void test_jitter(void)
{
    fov_gaze_filter f = fresh();
    uint64_t rng = 77u;
    double e_raw = 0.0, e_f = 0.0, s = 0.5 / sqrt(2.0);
    int i, n = 0;
    for (i = 0; i < 600; ++i) {
        double x = 2.0 + s * gt_gauss(&rng), y = 1.0 + s * gt_gauss(&rng);
        fovsdf_gaze_filter_push(&f, (uint64_t)i * DT_US, (float)x, (float)y);
        if (i >= 120) {
            e_raw += (x - 2.0) * (x - 2.0) + (y - 1.0) * (y - 1.0);
            e_f += ((double)f.x_deg - 2.0) * ((double)f.x_deg - 2.0) +
                   ((double)f.y_deg - 1.0) * ((double)f.y_deg - 1.0);
            n++;
        }
    }
    e_raw = sqrt(e_raw / n); e_f = sqrt(e_f / n);
    fovcheck_info("jitter: raw %.3f deg RMS, filtered %.3f (ratio %.3f), noise estimate %.3f",
                  e_raw, e_f, e_f / e_raw, (double)f.noise_deg);
    check(fabs(e_raw - 0.5) < 0.05, "jitter_raw_is_0.5", "%g", e_raw);
    check(e_f <= e_raw / 3.0, "jitter_filtered_third_of_raw", "%g vs %g", e_f, e_raw);
    check(f.saccades == 0u, "jitter_no_false_saccades", "%u", f.saccades);
    check(fabs((double)f.noise_deg - 0.5) < 0.15, "jitter_noise_estimate", "%g",
          (double)f.noise_deg);
}

static int same(const fov_gaze_filter *a, const fov_gaze_filter *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

/* errors leave the state as it was */
static void test_errors(void)
{
    fov_gaze_filter f, g;
    fov_gaze_filter_config c;
    fov_result r;
    float nan = (float)NAN, inf = (float)INFINITY;
    uint32_t i;
    memset(&f, 0, sizeof f);
    fovsdf_gaze_filter_init(&f, NULL);
    for (i = 0; i < 10; ++i) fovsdf_gaze_filter_push(&f, 1000000u + i * DT_US, 1.0f, 2.0f);
    g = f;
    r = fovsdf_gaze_filter_push(&f, 1000000u, 1.0f, 2.0f);
    check(r == FOV_ERR_INVALID_ARG && same(&f, &g), "err_out_of_order", "%d", (int)r);
    r = fovsdf_gaze_filter_push(&f, 1000000u + 9u * DT_US, 1.0f, 2.0f);
    check(r == FOV_ERR_INVALID_ARG && same(&f, &g), "err_zero_dt", "%d", (int)r);
    r = fovsdf_gaze_filter_push(&f, 1000000u + 9u * DT_US + 500001u, 1.0f, 2.0f);
    check(r == FOV_ERR_LIMIT && same(&f, &g), "err_huge_dt", "%d", (int)r);
    r = fovsdf_gaze_filter_push(&f, 1000000u + 9u * DT_US + 500000u, 1.0f, 2.0f);
    check(r == FOV_OK, "dt_at_the_limit_ok", "%d", (int)r);
    g = f;
    r = fovsdf_gaze_filter_push(&f, 9000000u, nan, 2.0f);
    check(r == FOV_ERR_NOT_FINITE && same(&f, &g), "err_nan_x", "%d", (int)r);
    r = fovsdf_gaze_filter_push(&f, 9000000u, 1.0f, inf);
    check(r == FOV_ERR_NOT_FINITE && same(&f, &g), "err_inf_y", "%d", (int)r);
    r = fovsdf_gaze_filter_push(&f, 9000000u, 91.0f, 0.0f);
    check(r == FOV_ERR_INVALID_ARG && same(&f, &g), "err_beyond_90", "%d", (int)r);
    r = fovsdf_gaze_filter_push(NULL, 9000000u, 1.0f, 0.0f);
    check(r == FOV_ERR_NULL, "err_null", "%d", (int)r);
    /* after the huge gap: reset, then it takes samples again */
    fovsdf_gaze_filter_reset(&f);
    r = fovsdf_gaze_filter_push(&f, 90000000u, 5.0f, 5.0f);
    check(r == FOV_OK && f.x_deg >= 5.0f && f.x_deg <= 5.0f, "reset_then_push", "%d", (int)r);
    /* config errors: f unchanged */
    g = f;
    c = fovsdf_gaze_filter_config_default();
    c.min_cutoff_hz = -1.0f;
    r = fovsdf_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_INVALID_ARG && same(&f, &g), "err_cfg_min_cutoff", "%d", (int)r);
    c = fovsdf_gaze_filter_config_default();
    c.saccade_deg_s = nan;
    r = fovsdf_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_NOT_FINITE && same(&f, &g), "err_cfg_nan", "%d", (int)r);
    c = fovsdf_gaze_filter_config_default();
    c.beta = -0.5f;
    r = fovsdf_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_INVALID_ARG && same(&f, &g), "err_cfg_beta", "%d", (int)r);
    c = fovsdf_gaze_filter_config_default();
    check(c.min_cutoff_hz >= 0.5f && c.min_cutoff_hz <= 0.5f && c.beta >= 0.3f &&
          c.beta <= 0.3f && c.saccade_deg_s >= 100.0f && c.saccade_deg_s <= 100.0f &&
          c.window_ms >= 20.0f && c.window_ms <= 20.0f, "config_defaults_documented", "-");
    {
        float m;
        r = fovsdf_gaze_margin(&f, -1.0f, 10.0f, &m);
        check(r == FOV_ERR_INVALID_ARG, "err_margin_negative_accuracy", "%d", (int)r);
        r = fovsdf_gaze_margin(&f, 0.5f, nan, &m);
        check(r == FOV_ERR_NOT_FINITE, "err_margin_nan_latency", "%d", (int)r);
    }
}

/* the margin grows with the latency and with the speed: ramps at known speeds */
static void ramp(fov_gaze_filter *f, float v)
{
    uint32_t i;
    fovsdf_gaze_filter_init(f, NULL);
    for (i = 0; i < 120; ++i) fovsdf_gaze_filter_push(f, i * DT_US, v * (float)i / 120.0f, 0.0f);
}
static void test_margin(void)
{
    static const float speeds[6] = { 0.0f, 2.0f, 5.0f, 10.0f, 20.0f, 40.0f };
    fov_gaze_filter f;
    float prev = -1.0f, m;
    int i, mono = 1, strict = 1;
    ramp(&f, 10.0f);
    for (i = 0; i <= 30; ++i) {
        fovsdf_gaze_margin(&f, 0.3f, 10.0f * (float)i, &m);
        if (m < prev) mono = 0;
        if (!(m > prev)) strict = 0;
        prev = m;
    }
    check(mono && strict, "margin_increasing_in_latency", "-");
    prev = -1.0f; mono = 1;
    for (i = 0; i < 6; ++i) {
        ramp(&f, speeds[i]);
        fovsdf_gaze_margin(&f, 0.3f, 50.0f, &m);
        fovcheck_info("margin at %g deg/s, 50 ms: %.3f deg (output speed %.2f)",
                      (double)speeds[i], (double)m, (double)f.out_speed_deg_s);
        if (m < prev) mono = 0;
        prev = m;
    }
    check(mono, "margin_nondecreasing_in_ramp_speed", "-");
    /* and in the filter's output speed, everything else held */
    ramp(&f, 10.0f);
    prev = -1.0f; mono = 1;
    for (i = 0; i < 50; ++i) {
        fov_gaze_filter g = f;
        g.out_speed_deg_s = (float)i;
        fovsdf_gaze_margin(&g, 0.3f, 50.0f, &m);
        if (m < prev) mono = 0;
        prev = m;
    }
    check(mono, "margin_nondecreasing_in_speed", "-");
    /* a steady pursuit: the margin covers where the eye is latency later */
    ramp(&f, 20.0f);
    {
        double true_later = 20.0 * (119.0 / 120.0 + 0.050);
        double err = fabs(true_later - (double)f.x_deg);
        fovsdf_gaze_margin(&f, 0.0f, 50.0f, &m);
        check((double)m >= err, "margin_covers_pursuit_at_50ms", "margin %g error %g",
              (double)m, err);
    }
    /* the cap */
    ramp(&f, 20.0f);
    fovsdf_gaze_margin(&f, 0.0f, 1e5f, &m);
    check(m >= 15.0f && m <= 15.0f, "margin_capped", "%g", (double)m);
}

/* pixels <-> degrees, the pixel push, and the three headers agree */
static void test_pixels(void)
{
    fov_ecc_model em;
    fov_display d;
    fov_gaze g, o1, o2, o3, px;
    fov_gaze_filter a, b, c;
    float deg[2];
    uint32_t i;
    int ok = 1;
    memset(&d, 0, sizeof d);
    d.fov_y_deg = 90.0f;
    g.x = 640.0f; g.y = 360.0f;
    fovsdf_ecc_init(&em, &d, 60.0f, 1280, 720, g);
    /* worked out: f = 360 / tan 45 = 360 px; (1000, 360) is atan(360 / 360) = 45 deg right */
    px.x = 1000.0f; px.y = 360.0f;
    fovlp_gaze_to_deg(&em, px, deg);
    check(fabsf(deg[0] - 45.0f) < 1e-3f && fabsf(deg[1]) < 1e-4f, "to_deg_45_right", "%g %g",
          (double)deg[0], (double)deg[1]);
    px.x = 640.0f; px.y = 0.0f; /* straight up: atan(-360 / 360) = -45 */
    fovpt_gaze_to_deg(&em, px, deg);
    check(fabsf(deg[0]) < 1e-4f && fabsf(deg[1] + 45.0f) < 1e-3f, "to_deg_45_up", "%g %g",
          (double)deg[0], (double)deg[1]);
    for (i = 0; i < 50; ++i) {
        fov_gaze q, r;
        q.x = -300.0f + 41.0f * (float)i; q.y = 700.0f - 13.0f * (float)i;
        fovsdf_gaze_to_deg(&em, q, deg);
        fovsdf_gaze_from_deg(&em, deg, &r);
        if (!(fabsf(r.x - q.x) < 2e-3f && fabsf(r.y - q.y) < 2e-3f)) ok = 0;
    }
    check(ok, "deg_px_round_trip", "-");
    fovsdf_gaze_filter_init(&a, NULL);
    fovlp_gaze_filter_init(&b, NULL);
    fovpt_gaze_filter_init(&c, NULL);
    ok = 1;
    for (i = 0; i < 100; ++i) {
        fov_gaze r;
        r.x = 600.0f + 3.0f * (float)(i % 7); r.y = 300.0f - 2.0f * (float)(i % 5);
        if (i == 50) r.x += 300.0f;
        fovsdf_gaze_filter_push_px(&a, &em, i * DT_US, r, &o1);
        fovlp_gaze_filter_push_px(&b, &em, i * DT_US, r, &o2);
        fovpt_gaze_filter_push_px(&c, &em, i * DT_US, r, &o3);
        if (memcmp(&o1, &o2, sizeof o1) || memcmp(&o1, &o3, sizeof o1)) ok = 0;
    }
    check(ok && same(&a, &b) && same(&a, &c), "three_headers_same_filter", "-");
    check(a.saccades == 1u, "px_jump_is_a_saccade", "%u", a.saccades);
    /* fixed foveation: the display's axis point */
    d.axis_dx = 12.0f; d.axis_dy = -8.0f;
    check(fovsdf_gaze_fixed(&d, 1280, 720, &g) == FOV_OK && g.x >= 652.0f && g.x <= 652.0f &&
          g.y >= 352.0f && g.y <= 352.0f, "fixed_gaze_axis_point", "%g %g", (double)g.x,
          (double)g.y);
    check(fovlp_gaze_fixed(NULL, 1280, 720, &g) == FOV_OK && g.x >= 640.0f && g.x <= 640.0f &&
          g.y >= 360.0f && g.y <= 360.0f, "fixed_gaze_centre", "-");
    check(fovpt_gaze_fixed(NULL, 0, 720, &g) == FOV_ERR_INVALID_ARG, "fixed_gaze_zero_size", "-");
}

/* review item: a pixel push that fails leaves the filter as it was, in every header. A pixel
   at x = 1e12 is atan2(1e12, f) = pi/2 in float, i.e. exactly 90 degrees, which no pixel can
   come back from: it is rejected before the filter sees it. */
static void test_px_error_state(void)
{
    fov_ecc_model em;
    fov_display d;
    fov_gaze g, far_px, o;
    fov_gaze_filter a, b, c, a0, b0, c0;
    float deg[2];
    fov_result r1, r2, r3;
    uint32_t i;
    memset(&d, 0, sizeof d);
    d.fov_y_deg = 90.0f;
    g.x = 640.0f; g.y = 360.0f;
    fovsdf_ecc_init(&em, &d, 60.0f, 1280, 720, g);
    fovsdf_gaze_filter_init(&a, NULL);
    fovlp_gaze_filter_init(&b, NULL);
    fovpt_gaze_filter_init(&c, NULL);
    for (i = 0; i < 10; ++i) {
        fovsdf_gaze_filter_push_px(&a, &em, 1000u + i * DT_US, g, &o);
        fovlp_gaze_filter_push_px(&b, &em, 1000u + i * DT_US, g, &o);
        fovpt_gaze_filter_push_px(&c, &em, 1000u + i * DT_US, g, &o);
    }
    a0 = a; b0 = b; c0 = c;
    far_px.x = 1e12f; far_px.y = 360.0f;
    o.x = o.y = -7.0f;
    r1 = fovsdf_gaze_filter_push_px(&a, &em, 1000u + 10u * DT_US, far_px, &o);
    r2 = fovlp_gaze_filter_push_px(&b, &em, 1000u + 10u * DT_US, far_px, &o);
    r3 = fovpt_gaze_filter_push_px(&c, &em, 1000u + 10u * DT_US, far_px, &o);
    check(r1 == FOV_ERR_INVALID_ARG && r2 == FOV_ERR_INVALID_ARG && r3 == FOV_ERR_INVALID_ARG,
          "px_far_rejected", "%d %d %d", (int)r1, (int)r2, (int)r3);
    check(same(&a, &a0) && same(&b, &b0) && same(&c, &c0), "px_far_state_unchanged", "-");
    check(o.x >= -7.0f && o.x <= -7.0f && o.y >= -7.0f && o.y <= -7.0f, "px_far_out_untouched",
          "%g %g", (double)o.x, (double)o.y);
    check(fovsdf_gaze_to_deg(&em, far_px, deg) == FOV_ERR_INVALID_ARG &&
          fovlp_gaze_to_deg(&em, far_px, deg) == FOV_ERR_INVALID_ARG &&
          fovpt_gaze_to_deg(&em, far_px, deg) == FOV_ERR_INVALID_ARG, "to_deg_90_rejected", "-");
    /* and a sample of exactly 90 degrees is rejected by the degree push too (no pixel maps
       there, so the filtered gaze could not be turned back into pixels) */
    r1 = fovsdf_gaze_filter_push(&a, 1000u + 10u * DT_US, 90.0f, 0.0f);
    check(r1 == FOV_ERR_INVALID_ARG && same(&a, &a0), "push_90_rejected", "%d", (int)r1);
    /* a good sample after the rejected ones is taken */
    r1 = fovsdf_gaze_filter_push_px(&a, &em, 1000u + 10u * DT_US, g, &o);
    check(r1 == FOV_OK && a.samples == a0.samples + 1u, "px_after_error_ok", "%d", (int)r1);
}

/* review item: the filter logs every rejected call once, with the code (the logger lives in
   fov_gaze_filter_config, as in the three headers' configs) */
typedef struct logrec { int calls; int32_t code; int level; char msg[200]; char tag[16]; } logrec;
static void log_fn(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                   void *user)
{
    logrec *l = (logrec *)user;
    (void)line;
    l->calls++;
    l->code = code;
    l->level = (int)level;
    snprintf(l->msg, sizeof l->msg, "%s", msg ? msg : "");
    snprintf(l->tag, sizeof l->tag, "%s", tag ? tag : "");
}
static void test_logger(void)
{
    fov_gaze_filter_config c = fovsdf_gaze_filter_config_default();
    fov_gaze_filter f, g;
    fov_ecc_model em;
    fov_display d;
    fov_gaze px, o;
    logrec lr;
    float m;
    uint32_t i;
    memset(&lr, 0, sizeof lr);
    memset(&d, 0, sizeof d);
    d.fov_y_deg = 90.0f;
    px.x = 640.0f; px.y = 360.0f;
    fovsdf_ecc_init(&em, &d, 60.0f, 1280, 720, px);
    c.logger.func = log_fn;
    c.logger.user = &lr;
    c.beta = -0.5f;
    check(fovlp_gaze_filter_init(&f, &c) == FOV_ERR_INVALID_ARG && lr.calls == 1 &&
          lr.code == (int32_t)FOV_ERR_INVALID_ARG && lr.level == (int)FOV_LOG_ERROR &&
          strcmp(lr.tag, "fovlp") == 0, "log_init_bad_beta", "calls %d code %d tag %s",
          lr.calls, (int)lr.code, lr.tag);
#ifndef FOV_NO_ERROR_STRINGS
    check(strstr(lr.msg, "beta") && strstr(lr.msg, "(0: 0.3)"), "log_beta_message_default",
          "\"%s\"", lr.msg);
#endif
    c.beta = 0.0f;
    check(fovsdf_gaze_filter_init(&f, &c) == FOV_OK && lr.calls == 1, "log_init_ok_silent", "%d",
          lr.calls);
    for (i = 0; i < 5; ++i) fovsdf_gaze_filter_push(&f, 1000u + i * DT_US, 1.0f, 2.0f);
    check(lr.calls == 1, "log_push_ok_silent", "%d", lr.calls);
    g = f;
    check(fovsdf_gaze_filter_push(&f, 1000u, 1.0f, 2.0f) == FOV_ERR_INVALID_ARG && lr.calls == 2 &&
          lr.code == (int32_t)FOV_ERR_INVALID_ARG && same(&f, &g), "log_push_out_of_order",
          "calls %d code %d", lr.calls, (int)lr.code);
#ifndef FOV_NO_ERROR_STRINGS
    check(strstr(lr.msg, "timestamp") != NULL, "log_push_message", "\"%s\"", lr.msg);
#endif
    check(fovpt_gaze_filter_push(&f, 9000000u, (float)NAN, 0.0f) == FOV_ERR_NOT_FINITE &&
          lr.calls == 3 && lr.code == (int32_t)FOV_ERR_NOT_FINITE && strcmp(lr.tag, "fovpt") == 0,
          "log_push_nan", "calls %d code %d", lr.calls, (int)lr.code);
    check(fovsdf_gaze_filter_push(&f, 1000u + 4u * DT_US + 600000u, 1.0f, 2.0f) == FOV_ERR_LIMIT &&
          lr.calls == 4 && lr.code == (int32_t)FOV_ERR_LIMIT, "log_push_gap", "calls %d",
          lr.calls);
    px.x = 1e12f;
    check(fovlp_gaze_filter_push_px(&f, &em, 1000u + 5u * DT_US, px, &o) == FOV_ERR_INVALID_ARG &&
          lr.calls == 5 && lr.code == (int32_t)FOV_ERR_INVALID_ARG, "log_push_px_far",
          "calls %d", lr.calls);
    check(fovsdf_gaze_filter_push_px(&f, NULL, 1000u + 5u * DT_US, px, &o) == FOV_ERR_NULL &&
          lr.calls == 6 && lr.code == (int32_t)FOV_ERR_NULL, "log_push_px_null_m", "calls %d",
          lr.calls);
    check(fovpt_gaze_margin(&f, -1.0f, 50.0f, &m) == FOV_ERR_INVALID_ARG && lr.calls == 7 &&
          lr.code == (int32_t)FOV_ERR_INVALID_ARG, "log_margin_bad_accuracy", "calls %d",
          lr.calls);
    check(fovsdf_gaze_margin(&f, 0.5f, (float)INFINITY, &m) == FOV_ERR_NOT_FINITE &&
          lr.calls == 8 && lr.code == (int32_t)FOV_ERR_NOT_FINITE, "log_margin_inf_latency",
          "calls %d", lr.calls);
    check(fovsdf_gaze_margin(&f, 0.5f, 50.0f, &m) == FOV_OK && lr.calls == 8, "log_margin_ok",
          "%d", lr.calls);
}

/* each header's config_gaze_margin */
static void test_apply(void)
{
    fovsdf_config s0 = fovsdf_config_default(), s1;
    fovlp_config l0 = fovlp_config_preset(FOVLP_PRESET_C_FOV, 640, 360), l1;
    fovpt_config p0 = fovpt_config_default(), p1, pr;
    fov_result r;
    uint32_t i;
    int ok;
    r = fovsdf_config_gaze_margin(&s0, 1.5f, &s1);
    check(r == FOV_OK && fabsf(s1.acuity.fovea_deg - 9.0f) < 1e-5f, "sdf_fovea_grows",
          "%d %g", (int)r, (double)s1.acuity.fovea_deg);
    r = fovsdf_config_gaze_margin(&s0, FOV_GAZE_FIXED_MARGIN_DEG, &s1);
    check(r == FOV_OK && fabsf(s1.acuity.fovea_deg - 22.5f) < 1e-5f, "sdf_fixed_foveation",
          "%g", (double)s1.acuity.fovea_deg);
    check(fovsdf_config_gaze_margin(&s0, -1.0f, &s1) == FOV_ERR_INVALID_ARG, "sdf_neg", "-");
    check(fovsdf_config_gaze_margin(&s0, 175.0f, &s1) == FOV_ERR_LIMIT, "sdf_limit", "-");
    r = fovlp_config_resolve(&l0, &l1);
    {
        float a0 = l1.gaze_angle;
        r = fovlp_config_gaze_margin(&l0, 2.0f, &l1);
        check(r == FOV_OK && fabsf(l1.gaze_angle - (a0 + 2.0f * 0.01745329f)) < 1e-5f,
              "lp_disc_grows", "%d %g", (int)r, (double)l1.gaze_angle);
    }
    l0.no_disc = 1;
    check(fovlp_config_gaze_margin(&l0, 2.0f, &l1) == FOV_ERR_UNSUPPORTED, "lp_no_disc", "-");
    fovpt_config_resolve(&p0, &pr);
    r = fovpt_config_gaze_margin(&p0, 1.0f, &p1);
    ok = r == FOV_OK && fabsf(p1.zones.inner_deg - pr.zones.inner_deg - 1.0f) < 1e-5f &&
         fabsf(p1.zones.middle_deg - pr.zones.middle_deg - 1.0f) < 1e-5f;
    for (i = 1; i < pr.layers.count; ++i)
        if (!(fabsf(p1.layers.layer[i].radius_deg - pr.layers.layer[i].radius_deg - 1.0f) <
              1e-5f))
            ok = 0;
    for (i = 0; i < 5; ++i)
        if (!(fabsf(p1.selective.e_deg[i] - pr.selective.e_deg[i] - 1.0f) < 1e-5f)) ok = 0;
    check(ok, "pt_radii_grow", "%d", (int)r);
    check(fovpt_config_gaze_margin(&p0, (float)NAN, &p1) == FOV_ERR_NOT_FINITE, "pt_nan", "-");
    /* a grown config still initialises */
    {
        fovpt_camera cam;
        size_t need;
        fovpt_camera_init(&cam, 64, 48);
        p0.method = FOVPT_METHOD_ZONES;
        fovpt_config_gaze_margin(&p0, 3.0f, &p1);
        check(fovpt_memory_size(&p1, &cam, &need) == FOV_OK, "pt_grown_config_valid", "-");
    }
}

/* the generator: saccades follow the main sequence stated in gaze_trace.h, measured here from
   the position samples; the tracker's noise has the stated RMS */
static void test_trace(void)
{
    static gt_trace t;
    static uint64_t ts[2000];
    static double xs[2000], ys[2000];
    int k, ok = 1, n, blink = 0;
    double e2 = 0.0;
    gt_make(&t, 0, 1u);
    check(t.n_ms >= 12000 && t.n_sacc >= 10, "trace_has_saccades", "%d ms %d saccades", t.n_ms,
          t.n_sacc);
    for (k = 0; k < t.n_sacc; ++k) {
        int a = t.sacc_on[k] - 1, b = t.sacc_off[k] - 1, i;
        double amp = hypot(t.x[b] - t.x[a], t.y[b] - t.y[a]), vp = 0.0, want;
        for (i = a + 1; i <= b; ++i)
            vp = fmax(vp, 1000.0 * hypot(t.x[i] - t.x[i - 1], t.y[i] - t.y[i - 1]));
        want = 600.0 * (1.0 - exp(-amp / 6.0));
        /* 1 ms steps of a minimum-jerk profile: the peak within 5 % */
        if (!(fabs(vp - want) <= 0.05 * want)) ok = 0;
        if (!(fabs((double)(b - a) - (21.0 + 2.2 * amp)) <= 8.0)) ok = 0;
    }
    check(ok, "trace_main_sequence", "-");
    for (k = 0; k < t.n_ms; ++k) blink += t.phase[k] == GT_BLINK;
    check(blink == 150, "trace_one_blink_150ms", "%d", blink);
    n = gt_track(&t, 120.0, 0.5, 3u, ts, xs, ys, 2000);
    for (k = 0; k < n; ++k) {
        int ms = gt_ms(&t, ts[k]);
        e2 += (xs[k] - t.x[ms]) * (xs[k] - t.x[ms]) + (ys[k] - t.y[ms]) * (ys[k] - t.y[ms]);
    }
    check(fabs(sqrt(e2 / n) - 0.5) < 0.03, "trace_noise_rms", "%g", sqrt(e2 / n));
    {
        /* every 1/120 s over the trace, less the 150 ms blink: 18 samples (150 / 8.33) */
        int all = (int)floor((double)(t.n_ms - 1) * 120.0 / 1000.0) + 1, inblink = 0;
        for (k = 0; k < n; ++k) inblink += t.phase[gt_ms(&t, ts[k])] == GT_BLINK;
        check(inblink == 0 && abs(all - n - 18) <= 1, "trace_no_samples_in_blink",
              "%d in the blink, %d missing", inblink, all - n);
    }
}

/* ---- latency compensation (_gaze_predict) ---------------------------------------------- */
/* a noiseless constant-velocity pursuit: the line through the samples is the motion itself, so
   once the fit has FOV_GAZE_FIT_MIN samples over FOV_GAZE_FIT_MIN_MS the prediction is where
   the eye is latency_ms after the newest sample: x0 + v (t_last + latency), computed here in
   double. Tolerance 1e-3 degrees (float sums of 24 samples of up to 10 degrees, extrapolated
   by 0.15 s: about 1e-5 degrees of rounding, two orders below it). */
static void test_predict_pursuit(void)
{
    fov_gaze_filter f;
    fov_gaze_prediction p;
    const double vx = 20.0, vy = -8.0, x0 = -5.0, y0 = 3.0;
    uint32_t i;
    int ok = 1, mode_ok = 1, first = -1;
    double worst = 0.0;
    fovsdf_gaze_filter_init(&f, NULL);
    for (i = 0; i < 60; ++i) {
        double t = (double)(i * DT_US) * 1e-6, ex, ey;
        fovsdf_gaze_filter_push(&f, i * DT_US, (float)(x0 + vx * t), (float)(y0 + vy * t));
        if (fovsdf_gaze_predict(&f, 0.5f, 50.0f, &p) != FOV_OK) ok = 0;
        ex = x0 + vx * (t + 0.050);
        ey = y0 + vy * (t + 0.050);
        /* settled: 8 samples spanning >= 40 ms (t >= 58 ms at 120 Hz) */
        if (i + 1 >= FOV_GAZE_FIT_MIN && t >= 0.040) {
            double e = hypot((double)p.x_deg - ex, (double)p.y_deg - ey);
            if (p.mode != FOV_GAZE_PURSUIT) mode_ok = 0;
            if (e > worst) worst = e;
            if (first < 0) first = (int)i;
        } else if (p.mode != FOV_GAZE_SETTLING) {
            mode_ok = 0;
        }
    }
    check(ok, "predict_ok", "-");
    check(mode_ok, "predict_pursuit_mode_after_settling", "mode %d", (int)p.mode);
    check(worst <= 1e-3, "predict_exact_on_constant_velocity", "worst %g deg from sample %d",
          worst, first);
    check(fabs((double)p.vx - vx) <= 1e-2 && fabs((double)p.vy - vy) <= 1e-2,
          "predict_velocity_exact", "(%g, %g)", (double)p.vx, (double)p.vy);
    /* the margin covers the accuracy and next to nothing else (no noise) */
    check(p.margin_deg >= 0.5f && p.margin_deg <= 0.51f, "predict_margin_accuracy_only", "%g",
          (double)p.margin_deg);
    /* the filtered gaze (One Euro) lags: the prediction is the better point by far */
    {
        double t = (double)(59u * DT_US) * 1e-6;
        double ef = hypot((double)f.x_deg - (x0 + vx * (t + 0.05)),
                          (double)f.y_deg - (y0 + vy * (t + 0.05)));
        check(ef > 1.0, "predict_filtered_gaze_lags", "%g", ef);
    }
    /* the three headers agree bit for bit */
    {
        fov_gaze_prediction q, r;
        fovlp_gaze_predict(&f, 0.5f, 50.0f, &q);
        fovpt_gaze_predict(&f, 0.5f, 50.0f, &r);
        check(!memcmp(&p, &q, sizeof p) && !memcmp(&p, &r, sizeof p), "predict_three_headers",
              "-");
    }
}

/* the same pursuit through tracker noise of 0.5 degrees RMS (2-D, seeded): over the steady
   part the prediction's error against the true position latency later is well below the
   filtered gaze's (which lags by the speed times latency plus smoothing lag: 20 deg/s x
   50 ms alone is 1 degree) and inside the margin in at least 95 % of samples (the margin is
   stated for 2.5 times the prediction's RMS: 0.2 % of Gaussian errors miss it, the rest is
   the noise of the residual estimate from 24 samples) */
static void test_predict_noisy(void)
{
    fov_gaze_filter f;
    fov_gaze_prediction p;
    uint64_t rng = 77u;
    const double v = 20.0, sd = 0.5 / sqrt(2.0);
    uint32_t i;
    double ep2 = 0.0, ef2 = 0.0;
    int n = 0, in = 0, pur = 0;
    fovsdf_gaze_filter_init(&f, NULL);
    for (i = 0; i < 600; ++i) {
        double t = (double)(i * DT_US) * 1e-6, tx = -20.0 + v * t, ty = 0.5 * v * t - 5.0;
        fovsdf_gaze_filter_push(&f, i * DT_US, (float)(tx + sd * gt_gauss(&rng)),
                                (float)(ty + sd * gt_gauss(&rng)));
        fovsdf_gaze_predict(&f, 0.0f, 50.0f, &p);
        if (i >= 60) {
            double ax = -20.0 + v * (t + 0.05), ay = 0.5 * v * (t + 0.05) - 5.0;
            double ep = hypot((double)p.x_deg - ax, (double)p.y_deg - ay);
            double ef = hypot((double)f.x_deg - ax, (double)f.y_deg - ay);
            ep2 += ep * ep; ef2 += ef * ef; n++;
            in += ep <= (double)p.margin_deg;
            pur += p.mode == FOV_GAZE_PURSUIT;
        }
    }
    fovcheck_info("noisy pursuit 22.4 deg/s, 50 ms: predicted RMS %.3f, filtered RMS %.3f deg, "
                  "inside the margin %.1f %%, pursuit mode %.1f %%", sqrt(ep2 / n),
                  sqrt(ef2 / n), 100.0 * in / n, 100.0 * pur / n);
    check(sqrt(ep2 / n) < 0.5 * sqrt(ef2 / n), "predict_noisy_beats_filtered", "%g vs %g",
          sqrt(ep2 / n), sqrt(ef2 / n));
    check(in >= (95 * n) / 100, "predict_noisy_margin_covers_95pct", "%d of %d", in, n);
    check(pur >= (95 * n) / 100, "predict_noisy_pursuit_detected", "%d of %d", pur, n);
}

/* a pursuit at 30 deg/s, then a 10-degree saccade onto a still target: from the landing on,
   the prediction never extrapolates the pursuit or the saccade (the fit sees only samples
   after the landing). Noiseless: every prediction after the landing is the target within
   1e-4 degrees (the pursuit's 30 deg/s x 50 ms would be 1.5 degrees, the saccade's hundreds
   of deg/s far more). With 0.5 degrees of noise: within 1 degree (2 x the raw RMS) of the
   target in every frame of the 400 ms after the landing; the mean error below half of the
   raw noise. */
static void test_predict_saccade(void)
{
    int noisy;
    for (noisy = 0; noisy < 2; ++noisy) {
        fov_gaze_filter f;
        fov_gaze_prediction p;
        uint64_t rng = 99u;
        const double sd = noisy ? 0.5 / sqrt(2.0) : 0.0;
        uint32_t i, k = 0;
        int landed = -1, ok = 1, extrap = 0;
        double worst = 0.0, sum = 0.0, tx = 0.0, ty = 0.0;
        fovsdf_gaze_filter_init(&f, NULL);
        for (i = 0; i < 60 + 4 + 48; ++i) {
            double t = (double)(i * DT_US) * 1e-6;
            if (i < 60) { tx = -10.0 + 30.0 * t; ty = 2.0; }
            else if (i < 64) { double s = (double)(i - 59) / 5.0; tx = 4.75 + 10.0 * s; }
            else { tx = 14.75; }
            fovsdf_gaze_filter_push(&f, i * DT_US, (float)(tx + sd * gt_gauss(&rng)),
                                    (float)(ty + sd * gt_gauss(&rng)));
            if (fovsdf_gaze_predict(&f, 0.5f, 50.0f, &p) != FOV_OK) ok = 0;
            if (i >= 64 && !f.saccade && landed < 0) landed = (int)i;
            if (landed >= 0) {
                double e = hypot((double)p.x_deg - tx, (double)p.y_deg - ty);
                if (e > worst) worst = e;
                sum += e; k++;
                extrap += p.mode == FOV_GAZE_PURSUIT;
            }
        }
        check(ok && f.saccades == 1u && landed >= 0 && landed <= 67,
              N("predict_saccade_detected_%s", noisy ? "noisy" : "clean"), "landed at %d, %u",
              landed, f.saccades);
        if (!noisy) {
            check(worst <= 1e-4 && extrap == 0, "predict_no_overshoot_after_landing",
                  "worst %g deg, %d extrapolated", worst, extrap);
        } else {
            fovcheck_info("after a landing, 0.5 deg noise: worst %.3f, mean %.3f deg, %d of %u "
                          "extrapolated", worst, sum / (double)k, extrap, k);
            check(worst <= 1.0 && sum / (double)k <= 0.25, "predict_noisy_no_overshoot",
                  "worst %g mean %g", worst, sum / (double)k);
        }
    }
}

/* the margin grows with the latency (every state) and with the speed: the same noise sequence
   on ramps of increasing speed has the same residuals (a line added to the data leaves a
   line fit's residuals alone, up to float rounding: 1e-5 degrees allowed), so only the speed
   differs; the latency: nondecreasing in every state, increasing in pursuit */
static void test_predict_monotone(void)
{
    static const double speeds[8] = { 0.0, 1.0, 2.0, 4.0, 8.0, 15.0, 30.0, 60.0 };
    fov_gaze_filter f;
    fov_gaze_prediction p;
    float prev;
    int s, i, mono_lat = 1, mono_v = 1, modes = 0;
    float mv[8];
    for (s = 0; s < 8; ++s) {
        uint64_t rng = 5u;
        uint32_t k;
        fovsdf_gaze_filter_init(&f, NULL);
        for (k = 0; k < 40; ++k) {
            double t = (double)(k * DT_US) * 1e-6;
            fovsdf_gaze_filter_push(&f, k * DT_US,
                                    (float)(speeds[s] * t + 0.35 * gt_gauss(&rng)),
                                    (float)(0.35 * gt_gauss(&rng)));
        }
        prev = -1.0f;
        for (i = 0; i <= 20; ++i) {
            fovsdf_gaze_predict(&f, 0.3f, 10.0f * (float)i, &p);
            if (p.margin_deg < prev || (p.mode == FOV_GAZE_PURSUIT && !(p.margin_deg > prev)))
                mono_lat = 0;
            prev = p.margin_deg;
        }
        fovsdf_gaze_predict(&f, 0.3f, 50.0f, &p);
        mv[s] = p.margin_deg;
        modes |= 1 << (int)p.mode;
        fovcheck_info("predict at %g deg/s, 50 ms: margin %.3f deg, mode %d, n %u",
                      speeds[s], (double)p.margin_deg, (int)p.mode, p.n);
    }
    for (s = 1; s < 8; ++s)
        if (mv[s] < mv[s - 1] - 1e-5f) mono_v = 0; /* equal residuals up to float rounding */
    check(mono_lat, "predict_margin_increasing_in_latency", "-");
    check(mono_v, "predict_margin_nondecreasing_in_speed", "-");
    check((modes & (1 << FOV_GAZE_FIXATION)) && (modes & (1 << FOV_GAZE_PURSUIT)),
          "predict_monotone_spans_both_modes", "%x", modes);
}

/* bad input: clear codes, the filter unchanged (only read), *out the safe answer */
static void test_predict_errors(void)
{
    fov_gaze_filter f, g;
    fov_gaze_prediction p;
    fov_gaze_filter_config c;
    fov_result r;
    uint32_t i;
    const float nan = (float)NAN;
    fovsdf_gaze_filter_init(&f, NULL);
    for (i = 0; i < 30; ++i)
        fovsdf_gaze_filter_push(&f, i * DT_US, 10.0f * (float)i / 120.0f, 1.0f);
    g = f;
    r = fovsdf_gaze_predict(&f, 0.5f, nan, &p);
    check(r == FOV_ERR_NOT_FINITE && p.margin_deg >= 15.0f && p.x_deg >= f.x_deg &&
          p.x_deg <= f.x_deg, "predict_err_nan_latency", "%d %g", (int)r, (double)p.margin_deg);
    r = fovsdf_gaze_predict(&f, -0.1f, 50.0f, &p);
    check(r == FOV_ERR_INVALID_ARG, "predict_err_negative_accuracy", "%d", (int)r);
    r = fovlp_gaze_predict(&f, 0.5f, -1.0f, &p);
    check(r == FOV_ERR_INVALID_ARG, "predict_err_negative_latency", "%d", (int)r);
    r = fovpt_gaze_predict(&f, 0.5f, 2e6f, &p);
    check(r == FOV_ERR_INVALID_ARG, "predict_err_huge_latency", "%d", (int)r);
    check(fovsdf_gaze_predict(&f, 0.5f, 50.0f, NULL) == FOV_ERR_NULL &&
              fovsdf_gaze_predict(NULL, 0.5f, 50.0f, &p) == FOV_ERR_NULL,
          "predict_err_null", "-");
    check(!memcmp(&f, &g, sizeof f), "predict_err_state_unchanged", "-");
    /* before any sample: the cap, settling */
    fovsdf_gaze_filter_init(&g, NULL);
    r = fovsdf_gaze_predict(&g, 0.5f, 50.0f, &p);
    check(r == FOV_OK && p.mode == FOV_GAZE_SETTLING && p.margin_deg >= 15.0f,
          "predict_no_samples_cap", "%d %g", (int)r, (double)p.margin_deg);
    /* a pursuit extrapolated past 90 degrees: the filtered gaze and the cap, not an angle the
       gaze angles cannot hold */
    fovsdf_gaze_filter_init(&g, NULL);
    for (i = 0; i < 8; ++i) /* 88 .. 89.75 degrees at 30 deg/s, then 100 ms ahead */
        fovsdf_gaze_filter_push(&g, i * DT_US, 88.0f + 30.0f * (float)i / 120.0f, 0.0f);
    r = fovsdf_gaze_predict(&g, 0.5f, 100.0f, &p);
    check(r == FOV_OK && p.mode == FOV_GAZE_SETTLING && p.margin_deg >= 15.0f &&
              p.x_deg >= g.x_deg && p.x_deg <= g.x_deg && p.x_deg < 90.0f,
          "predict_beyond_90_falls_back", "%d mode %d x %g m %g", (int)r, (int)p.mode,
          (double)p.x_deg, (double)p.margin_deg);
    /* the window's config field */
    c = fovsdf_gaze_filter_config_default();
    check(c.predict_ms >= 200.0f && c.predict_ms <= 200.0f, "predict_ms_default_200", "%g",
          (double)c.predict_ms);
    g = f;
    c.predict_ms = 10.0f;
    r = fovsdf_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_INVALID_ARG && !memcmp(&f, &g, sizeof f), "predict_ms_too_small", "%d",
          (int)r);
    c.predict_ms = 39.0f; /* a window shorter than FOV_GAZE_FIT_MIN_MS (40 ms) could never fit */
    r = fovsdf_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_INVALID_ARG && !memcmp(&f, &g, sizeof f), "predict_ms_below_fit_span", "%d",
          (int)r);
    c.predict_ms = 40.0f;
    r = fovpt_gaze_filter_init(&f, &c);
    check(r == FOV_OK && f.cfg.predict_ms >= 40.0f && f.cfg.predict_ms <= 40.0f, "predict_ms_40_accepted",
          "%d", (int)r);
    f = g;
    c.predict_ms = nan;
    r = fovlp_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_NOT_FINITE && !memcmp(&f, &g, sizeof f), "predict_ms_nan", "%d", (int)r);
    c.predict_ms = 2001.0f;
    r = fovpt_gaze_filter_init(&f, &c);
    check(r == FOV_ERR_INVALID_ARG && !memcmp(&f, &g, sizeof f), "predict_ms_too_large", "%d",
          (int)r);
}

int main(void)
{
    test_constant();
    test_step();
    test_jitter();
    test_errors();
    test_margin();
    test_pixels();
    test_px_error_state();
    test_logger();
    test_apply();
    test_trace();
    test_predict_pursuit();
    test_predict_noisy();
    test_predict_saccade();
    test_predict_monotone();
    test_predict_errors();
    return fovcheck_summary();
}
