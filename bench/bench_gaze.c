/* bench_gaze.c - the gaze filter and the latency-safe fovea (fov_gaze_filter of the shared
   block; fovsdf.h's copy) on generated gaze traces with a known true gaze
   (bench/gaze_trace.h: fixations with drift, smooth pursuit, main-sequence saccades,
   a blink). Writes bench/results/gaze.csv:
     trace,latency_ms,noise_deg,mode,inside_pct,work_ratio,jitter_deg_rms,lag_deg,settle_frames,
     region,region_deg,accuracy_deg,margin_deg,covered_pct
   one row per trace, latency (0, 20, 50, 80 ms), tracker noise (RMS in 2-D: 0.25, 0.5, 1
   degrees), mode and full-quality region:
     raw              the newest tracker sample, no margin
     filtered         the One Euro filter with saccade reset (defaults), no margin
     filtered_margin  filtered, the region grown by fovsdf_gaze_margin (accuracy 0.5 deg)
     predicted        fovsdf_gaze_predict (accuracy 0.5 deg): its centre (extrapolated by the
                      latency in pursuit) and its margin
     raw_const_margin the newest tracker sample and one constant margin, the smallest that puts
                      the true gaze inside in 99 % of this row's fixation and pursuit frames
                      (chosen after the fact from the true gaze: an oracle no application has;
                      what a hand-tuned constant margin costs for what the filter buys)
   The tracker (120 Hz; frames at 90 Hz; the frame shown at time T uses the samples taken up
   to T - latency) has a systematic error of 0.5 degrees (its stated accuracy, accuracy_deg:
   a constant offset in a seeded direction per trace and noise) plus the white noise.
   The latency passed to fovsdf_gaze_margin and fovsdf_gaze_predict is the age of the newest
   sample when the frame is seen (the system latency plus up to one tracker period; the
   application knows both clocks).
   Regions (region, region_deg: the full-quality radius without a margin, degrees):
     e_full        e_full of the shared eye model (fov_eye defaults) for a 27" 1920x1080
                   monitor at 60 cm (33.6 pixels per degree): every pixel needs its own sample
     fovsdf_fovea  fovsdf's default acuity.fovea_deg, 7.5 (also fovpt's inner zone radius)
     fovlp_disc    fovlp's default gaze disc, gaze_angle 0.20 rad = 11.46 degrees
   inside_pct: the frames whose true gaze lies within region_deg + margin of the gaze used,
   over fixation and pursuit frames; rows with the trace suffix _saccades count the frames
   from each saccade's onset to its landing plus the latency (no tracker can have reported
   the landing earlier), and leave jitter and lag empty. Blink frames (eyes shut) are in
   neither. covered_pct: the stricter test that the whole full-quality disc around the true
   gaze (radius region_deg) lies inside the one shown (error <= margin). work_ratio: the mean
   area of the full-quality disc against an ideal tracker's (region_deg around the true gaze),
   ((region_deg + margin) / region_deg)^2 (1 without a margin). margin_deg: the mean margin.
   jitter_deg_rms: RMS of shown minus true gaze, less the tracker's known offset, over
   fixation frames at least 150 ms after a landing has been shown. lag_deg: mean |shown -
   true - offset| over pursuit frames. settle_frames: frames from a landing being shown
   (landing + latency) until the shown gaze is within 1 degree of true gaze + offset, mean
   over saccades. Deterministic (seeded). */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "bench/gaze_trace.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RATE_HZ 120.0
#define FRAME_HZ 90.0
#define MAXS 4096
#define MAXF 2048
#define NMODES 5
#define NREG 3

enum { M_RAW, M_FILT, M_MARGIN, M_PRED, M_CONST };
enum { C_COUNT = 0, C_SACC = 1, C_BLINK = 2 };

static gt_trace g_tr;
static uint64_t g_t[MAXS], g_t0[MAXS];
static double g_x[MAXS], g_y[MAXS], g_x0[MAXS], g_y0[MAXS];

/* one frame of one mode: the error against the true gaze (with and without the tracker's
   offset), the margin and the frame's class */
typedef struct frame {
    double d, dj, margin;
    int cls, pursuit, steady;
} frame;
static frame g_fr[NMODES][MAXF];
static int g_nf;

typedef struct acc {
    double in_n, in_k, cov_k, work, marg, jit2, jit_n, lag, lag_n;
} acc;

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

static void row(FILE *f, const char *trace, const char *suffix, int lat, double noise,
                const char *mode, const acc *a, int sacc_row, double settle, const char *reg,
                double R, double acc_deg)
{
    fprintf(f, "%s%s,%d,%.2f,%s,%.2f,%.3f,", trace, suffix, lat, noise, mode,
            a->in_n > 0 ? 100.0 * a->in_k / a->in_n : 0.0, a->in_n > 0 ? a->work / a->in_n : 1.0);
    if (sacc_row) fprintf(f, ",,");
    else fprintf(f, "%.3f,%.3f,", a->jit_n > 0 ? sqrt(a->jit2 / a->jit_n) : 0.0,
                 a->lag_n > 0 ? a->lag / a->lag_n : 0.0);
    fprintf(f, "%.2f,%s,%.3f,%.2f,%.3f,%.2f\n", settle, reg, R, acc_deg,
            a->in_n > 0 ? a->marg / a->in_n : 0.0, a->in_n > 0 ? 100.0 * a->cov_k / a->in_n : 0.0);
}

/* One mode over the trace: fills g_fr[mo] (g_nf frames) and returns the mean settle frames. */
static double simulate(int mo, int ns, int lat, double acc_deg, double bx, double by)
{
    fov_gaze_filter gf;
    int k = 0, fr, sacc_i = 0, settle_open = -1, have = 0, nf = 0;
    double settle_start = 0.0, settle = 0.0, settle_n = 0.0, ex = 0.0, ey = 0.0;
    uint64_t L = (uint64_t)lat * 1000u, t_new = 0;
    if (fovsdf_gaze_filter_init(&gf, NULL) != FOV_OK) exit(1);
    for (fr = 0;; ++fr) {
        uint64_t T = (uint64_t)((double)fr * 1e6 / FRAME_HZ + 0.5), Ts = T >= L ? T - L : 0u;
        int ms, ph, in_sacc = 0, j;
        double tx, ty, d, dj, margin = 0.0, age_ms;
        frame *F;
        if (T / 1000u >= (uint64_t)g_tr.n_ms || nf >= MAXF) break;
        while (k < ns && g_t[k] <= Ts && T >= L) {
            fov_result r = fovsdf_gaze_filter_push(&gf, g_t[k], (float)g_x[k], (float)g_y[k]);
            if (r == FOV_ERR_LIMIT) {
                fovsdf_gaze_filter_reset(&gf);
                r = fovsdf_gaze_filter_push(&gf, g_t[k], (float)g_x[k], (float)g_y[k]);
            }
            if (r != FOV_OK) {
                fprintf(stderr, "push failed %d\n", (int)r);
                exit(1);
            }
            t_new = g_t[k];
            have = 1;
            k++;
        }
        if (!have) continue;
        /* the newest sample's age when the frame is seen */
        age_ms = (double)(T - t_new) * 1e-3;
        if (mo == M_RAW || mo == M_CONST) {
            ex = g_x[k - 1]; ey = g_y[k - 1];
        } else if (mo == M_PRED) {
            fov_gaze_prediction p;
            if (fovsdf_gaze_predict(&gf, (float)acc_deg, (float)age_ms, &p) != FOV_OK) exit(1);
            ex = p.x_deg; ey = p.y_deg; margin = p.margin_deg;
        } else {
            ex = gf.x_deg; ey = gf.y_deg;
            if (mo == M_MARGIN) {
                float m;
                if (fovsdf_gaze_margin(&gf, (float)acc_deg, (float)age_ms, &m) != FOV_OK)
                    exit(1);
                margin = m;
            }
        }
        ms = gt_ms(&g_tr, T);
        ph = g_tr.phase[ms];
        tx = g_tr.x[ms]; ty = g_tr.y[ms];
        d = sqrt((ex - tx) * (ex - tx) + (ey - ty) * (ey - ty));
        dj = sqrt((ex - bx - tx) * (ex - bx - tx) + (ey - by - ty) * (ey - by - ty));
        for (j = 0; j < g_tr.n_sacc; ++j)
            if ((int)(T / 1000u) >= g_tr.sacc_on[j] && (int)(T / 1000u) < g_tr.sacc_off[j] + lat)
                in_sacc = 1;
        /* settling after the landing of saccade sacc_i has been shown */
        while (sacc_i < g_tr.n_sacc && (int)(T / 1000u) >= g_tr.sacc_off[sacc_i] + lat) {
            settle_open = sacc_i; settle_start = (double)fr; sacc_i++;
        }
        if (settle_open >= 0 && !in_sacc && dj <= 1.0) {
            settle += (double)fr - settle_start; settle_n += 1.0;
            settle_open = -1;
        }
        F = &g_fr[mo][nf++];
        F->d = d; F->dj = dj; F->margin = margin;
        F->cls = ph == GT_BLINK ? C_BLINK : in_sacc ? C_SACC : C_COUNT;
        F->pursuit = ph == GT_PURSUIT;
        F->steady = 0;
        if (ph == GT_FIX) {
            F->steady = 1;
            for (j = 0; j < g_tr.n_sacc; ++j)
                if ((int)(T / 1000u) >= g_tr.sacc_off[j] + lat &&
                    (int)(T / 1000u) < g_tr.sacc_off[j] + lat + 150)
                    F->steady = 0;
        }
    }
    g_nf = nf;
    return settle_n > 0 ? settle / settle_n : 0.0;
}

int main(int argc, char **argv)
{
    static const int lats[4] = { 0, 20, 50, 80 };
    static const double noises[3] = { 0.25, 0.5, 1.0 };
    static const char *const modes[NMODES] = { "raw", "filtered", "filtered_margin", "predicted",
                                               "raw_const_margin" };
    static const char *const regs[NREG] = { "e_full", "fovsdf_fovea", "fovlp_disc" };
    static double dsort[MAXF];
    const char *out = "bench/results/gaze.csv";
    double regdeg[NREG];
    fov_display disp;
    fov_ecc_model em;
    fov_eye_plan plan;
    fov_gaze g0;
    static const double accs[2] = { 0.5, 0.0 };
    int tr, li, ni, mo, rg, i, ai;
    FILE *f;
    if (argc > 1) {
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        if (!help && !strcmp(argv[1], "--out") && argc == 3) {
            out = argv[2];
        } else {
            fputs("usage: bench_gaze [--out FILE]\n  the gaze filter, latency margin and "
                  "prediction on generated gaze traces;\n  writes bench/results/gaze.csv (or "
                  "FILE)\n  -h, --help  this text\n", help ? stdout : stderr);
            return help ? 0 : 2;
        }
    }
    memset(&disp, 0, sizeof disp);
    disp.pixel_pitch_mm = (float)(27.0 * 25.4 / sqrt(1920.0 * 1920.0 + 1080.0 * 1080.0));
    disp.distance_mm = 600.0f;
    g0.x = 960.0f; g0.y = 540.0f;
    if (fovsdf_ecc_init(&em, &disp, 60.0f, 1920, 1080, g0) != FOV_OK ||
        fovsdf_eye_plan(NULL, &em, &plan) != FOV_OK) {
        fprintf(stderr, "eye plan failed\n");
        return 1;
    }
    {
        fovsdf_config c = fovsdf_config_default(), rc;
        if (fovsdf_config_resolve(&c, &rc) != FOV_OK) { fprintf(stderr, "resolve\n"); return 1; }
        regdeg[0] = plan.e_full;
        regdeg[1] = rc.acuity.fovea_deg;
        regdeg[2] = 0.20 * 180.0 / 3.14159265358979; /* fovlp's default gaze_angle */
    }
    f = fopen(out, "w");
    if (!f) { fprintf(stderr, "cannot write %s\n", out); return 1; }
    printf("display 27\" 1920x1080 at 60 cm: %.1f ppd; regions e_full %.3f, fovsdf fovea %.2f, "
           "fovlp disc %.2f deg\n", (double)plan.ppd, regdeg[0], regdeg[1], regdeg[2]);
    fprintf(f, "trace,latency_ms,noise_deg,mode,inside_pct,work_ratio,jitter_deg_rms,lag_deg,"
               "settle_frames,region,region_deg,accuracy_deg,margin_deg,covered_pct\n");
    for (tr = 0; tr < GT_NUM_TRACES; ++tr) {
        gt_make(&g_tr, tr, 2026u);
        for (ni = 0; ni < 3; ++ni) {
            uint64_t bs = (uint64_t)(7 * tr + ni + 1) * UINT64_C(0x9E3779B97F4A7C15);
            double ba = 6.283185307179586 * gt_u01(&bs);
            int ns0 = gt_track(&g_tr, RATE_HZ, noises[ni], (uint64_t)(100 * tr + ni), g_t0, g_x0,
                               g_y0, MAXS);
            for (li = 0; li < 4; ++li)
                for (ai = 0; ai < 2; ++ai) {
                    double settle[NMODES], ac = accs[ai], bx = ac * cos(ba), by = ac * sin(ba);
                    for (i = 0; i < ns0; ++i) {
                        g_t[i] = g_t0[i]; g_x[i] = g_x0[i] + bx; g_y[i] = g_y0[i] + by;
                    }
                    for (mo = 0; mo < NMODES; ++mo)
                        settle[mo] = simulate(mo, ns0, lats[li], ac, bx, by);
                    for (rg = 0; rg < (ai == 0 ? NREG : 1); ++rg) {
                        double R = regdeg[rg], cm = 0.0;
                        /* the constant margin for 99 % inside: the 99th percentile of the raw
                           error over fixation and pursuit frames, less the region */
                        {
                            int n = 0, q;
                            for (i = 0; i < g_nf; ++i)
                                if (g_fr[M_CONST][i].cls == C_COUNT)
                                    dsort[n++] = g_fr[M_CONST][i].d;
                            qsort(dsort, (size_t)n, sizeof dsort[0], cmp_d);
                            q = (int)ceil(0.99 * (double)n) - 1;
                            if (q < 0) q = 0;
                            cm = n > 0 && dsort[q] > R ? dsort[q] - R : 0.0;
                        }
                        for (mo = 0; mo < NMODES; ++mo) {
                            acc A, S;
                            memset(&A, 0, sizeof A); memset(&S, 0, sizeof S);
                            for (i = 0; i < g_nf; ++i) {
                                const frame *F = &g_fr[mo][i];
                                double m = mo == M_CONST ? cm : F->margin, Rm = R + m;
                                acc *a = F->cls == C_SACC ? &S : &A;
                                if (F->cls == C_BLINK) continue;
                                a->in_n += 1.0;
                                a->in_k += F->d <= Rm ? 1.0 : 0.0;
                                a->cov_k += F->d <= m ? 1.0 : 0.0;
                                a->work += (Rm / R) * (Rm / R);
                                a->marg += m;
                                if (F->cls != C_COUNT) continue;
                                if (F->pursuit) { A.lag += F->dj; A.lag_n += 1.0; }
                                if (F->steady) { A.jit2 += F->dj * F->dj; A.jit_n += 1.0; }
                            }
                            row(f, g_tr.name, "", lats[li], noises[ni], modes[mo], &A, 0,
                                settle[mo], regs[rg], R, ac);
                            row(f, g_tr.name, "_saccades", lats[li], noises[ni], modes[mo], &S,
                                1, settle[mo], regs[rg], R, ac);
                        }
                    }
                }
        }
    }
    fclose(f);
    printf("wrote %s\n", out);
    return 0;
}
