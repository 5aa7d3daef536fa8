/* bench/gaze_trace.h - deterministic synthetic gaze traces with a known true gaze, for the gaze
   filter's tests (tests/test_gaze.c) and benchmark (bench/bench_gaze.c). Test code, double
   precision; include it in one program (everything is static).

   A trace is the true gaze, in degrees (x right, y down: the gaze angles of
   fov_gaze_filter_config), at 1 kHz, built from segments:
     fixation  the eye holds a point with fixational drift: a random walk of 0.003 degrees
               per millisecond per axis (about 0.05 degrees over a 300 ms fixation)
     saccade   a jump of amplitude A with the main sequence's peak velocity
               Vp(A) = 600 (1 - exp(-A / 6)) deg/s (the exponential main-sequence form of
               Bahill, Clark and Stark, "The main sequence, a tool for studying human eye
               movements", Mathematical Biosciences 1975; these constants give 170 deg/s
               at 2 degrees, 490 at 10 and 550 at 15, durations 22 / 39 / 51 ms, within
               a few ms of the common rule D = 21 ms + 2.2 ms/deg A) and the bell-shaped
               minimum-jerk velocity profile: x(s) = A (10 s^3 - 15 s^4 + 6 s^5), s = t / D,
               D = 1.875 A / Vp (the profile's peak is 1.875 A / D)
     pursuit   smooth pursuit at a constant velocity (5 to 30 deg/s)
     blink     the eye holds still and the tracker reports nothing (150 ms)
   The tracker samples the true gaze at rate_hz (timestamps in whole microseconds) and adds
   white Gaussian noise of RMS noise_deg in 2-D (sigma noise_deg / sqrt 2 per axis: the
   "precision (SD)" of eye-tracker data sheets); no samples during a blink. Seeds make every
   trace and every noise sequence repeatable. */
#ifndef GAZE_TRACE_H
#define GAZE_TRACE_H
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

enum { GT_FIX = 0, GT_PURSUIT = 1, GT_SACCADE = 2, GT_BLINK = 3 };
#define GT_MAX_MS 20000
#define GT_MAX_SACC 256

typedef struct gt_trace {
    const char *name;
    int n_ms;                       /* length, milliseconds */
    double x[GT_MAX_MS], y[GT_MAX_MS]; /* the true gaze at each millisecond */
    unsigned char phase[GT_MAX_MS];
    int n_sacc;
    int sacc_on[GT_MAX_SACC], sacc_off[GT_MAX_SACC]; /* onset and landing, ms */
} gt_trace;

static uint64_t gt__rng(uint64_t *s) /* splitmix64 */
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double gt_u01(uint64_t *s)
{
    return (double)(gt__rng(s) >> 11) * (1.0 / 9007199254740992.0);
}
static double gt_gauss(uint64_t *s)
{
    double u = gt_u01(s), v = gt_u01(s);
    if (u < 1e-300) u = 1e-300;
    return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}

static double gt_peak_velocity(double amp) { return 600.0 * (1.0 - exp(-amp / 6.0)); }
static double gt_saccade_ms(double amp) { return 1000.0 * 1.875 * amp / gt_peak_velocity(amp); }

typedef struct gt__gen {
    gt_trace *t;
    uint64_t rng;
    double x, y;
} gt__gen;

static void gt__put(gt__gen *g, int ph)
{
    gt_trace *t = g->t;
    if (t->n_ms >= GT_MAX_MS) return;
    t->x[t->n_ms] = g->x; t->y[t->n_ms] = g->y; t->phase[t->n_ms] = (unsigned char)ph;
    t->n_ms++;
}
static void gt_fixation(gt__gen *g, int ms)
{
    int i;
    for (i = 0; i < ms; ++i) {
        g->x += 0.003 * gt_gauss(&g->rng);
        g->y += 0.003 * gt_gauss(&g->rng);
        gt__put(g, GT_FIX);
    }
}
static void gt_blink(gt__gen *g, int ms)
{
    int i;
    for (i = 0; i < ms; ++i) gt__put(g, GT_BLINK);
}
static void gt_saccade(gt__gen *g, double tx, double ty)
{
    double x0 = g->x, y0 = g->y, dx = tx - x0, dy = ty - y0, amp = sqrt(dx * dx + dy * dy);
    int i, n = (int)ceil(gt_saccade_ms(amp));
    gt_trace *t = g->t;
    if (amp < 0.1 || t->n_sacc >= GT_MAX_SACC) { g->x = tx; g->y = ty; return; }
    t->sacc_on[t->n_sacc] = t->n_ms;
    for (i = 1; i <= n; ++i) {
        double s = (double)i / (double)n, p = s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
        g->x = x0 + dx * p; g->y = y0 + dy * p;
        gt__put(g, GT_SACCADE);
    }
    t->sacc_off[t->n_sacc++] = t->n_ms;
}
static void gt_pursuit(gt__gen *g, double vx, double vy, int ms)
{
    int i;
    for (i = 0; i < ms; ++i) {
        g->x += vx * 1e-3; g->y += vy * 1e-3;
        gt__put(g, GT_PURSUIT);
    }
}

/* The traces: 0 "fixations" (fixations of 200-600 ms and saccades of 2-15 degrees within
   +-15 degrees), 1 "pursuit" (pursuit at 5, 10, 20 and 30 deg/s in turn, with saccades back
   to the centre and short fixations), 2 "mixed" (either, at random); each 12 s with one blink
   of 150 ms in a fixation near 6 s. */
#define GT_NUM_TRACES 3
static void gt_make(gt_trace *t, int which, uint64_t seed)
{
    static const char *const names[GT_NUM_TRACES] = { "fixations", "pursuit", "mixed" };
    static const double speeds[4] = { 5.0, 10.0, 20.0, 30.0 };
    gt__gen g;
    int blinked = 0, k = 0;
    t->name = names[which % GT_NUM_TRACES];
    t->n_ms = 0; t->n_sacc = 0;
    g.t = t;
    g.rng = seed * UINT64_C(0x632BE59BD9B4E019) + (uint64_t)(which + 1);
    g.x = 0.0; g.y = 0.0;
    gt_fixation(&g, 400);
    while (t->n_ms < 12000) {
        int pursue = which == 1 || (which == 2 && gt_u01(&g.rng) < 0.4);
        if (!blinked && t->n_ms > 6000) {
            gt_fixation(&g, 150);
            gt_blink(&g, 150);
            gt_fixation(&g, 150);
            blinked = 1;
        }
        if (pursue) {
            double v = which == 1 ? speeds[k++ % 4] : 5.0 + 25.0 * gt_u01(&g.rng);
            double a = 6.283185307179586 * gt_u01(&g.rng), vx = v * cos(a), vy = v * sin(a);
            int ms = 600 + (int)(600.0 * gt_u01(&g.rng));
            /* keep the pursuit within 20 degrees of the centre: start opposite */
            gt_saccade(&g, -vx * (double)ms * 0.5e-3, -vy * (double)ms * 0.5e-3);
            gt_fixation(&g, 150 + (int)(100.0 * gt_u01(&g.rng)));
            gt_pursuit(&g, vx, vy, ms);
            gt_fixation(&g, 200 + (int)(200.0 * gt_u01(&g.rng)));
        } else {
            double tx, ty, dx, dy, amp;
            do {
                tx = -15.0 + 30.0 * gt_u01(&g.rng); ty = -10.0 + 20.0 * gt_u01(&g.rng);
                dx = tx - g.x; dy = ty - g.y; amp = sqrt(dx * dx + dy * dy);
            } while (amp < 2.0 || amp > 15.0);
            gt_saccade(&g, tx, ty);
            gt_fixation(&g, 200 + (int)(400.0 * gt_u01(&g.rng)));
        }
    }
}

/* The true gaze at time t_us (the millisecond sample at or before it; the last one after). */
static int gt_ms(const gt_trace *t, uint64_t t_us)
{
    uint64_t ms = t_us / 1000u;
    return ms < (uint64_t)t->n_ms ? (int)ms : t->n_ms - 1;
}

/* Tracker samples at rate_hz with noise (RMS noise_deg in 2-D): fills t_us[], x[], y[] and
   returns the count (at most cap). No samples while the eye blinks. */
static int gt_track(const gt_trace *t, double rate_hz, double noise_deg, uint64_t seed,
                    uint64_t *ts, double *xs, double *ys, int cap)
{
    uint64_t rng = seed * 0x9E3779B97F4A7C15ull + 12345u, tu;
    double s = noise_deg / sqrt(2.0);
    int n = 0, k;
    for (k = 0;; ++k) {
        int ms;
        tu = (uint64_t)((double)k * 1e6 / rate_hz + 0.5);
        if (tu / 1000u >= (uint64_t)t->n_ms || n >= cap) break;
        ms = gt_ms(t, tu);
        if (t->phase[ms] == GT_BLINK) continue;
        ts[n] = tu;
        xs[n] = t->x[ms] + s * gt_gauss(&rng);
        ys[n] = t->y[ms] + s * gt_gauss(&rng);
        n++;
    }
    return n;
}
#endif
