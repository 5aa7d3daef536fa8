/* bench_gaze.c - the gaze filter and the latency-safe fovea (fov_gaze_filter of the shared
   block; fovsdf.h's copy) on generated gaze traces with a known true gaze
   (bench/gaze_trace.h: fixations with drift, smooth pursuit, main-sequence saccades,
   a blink). Writes bench/results/gaze.csv:
     trace,latency_ms,noise_deg,mode,inside_pct,work_ratio,jitter_deg_rms,lag_deg,settle_frames
   one row per trace, latency (0, 20, 50, 80 ms), tracker noise (RMS in 2-D: 0.25, 0.5, 1
   degrees) and mode: raw (the newest tracker sample), filtered (the One Euro filter with
   saccade reset, defaults), filtered_margin (filtered, full-quality radius grown by
   fovsdf_gaze_margin with the latency). The tracker samples at 120 Hz, frames at 90 Hz; the
   frame shown at time T uses the samples taken up to T - latency.
   Full-quality region: a disc of radius r_full around the gaze used, r_full = e_full of the
   shared eye model (fov_eye defaults) for a 27" 1920x1080 monitor at 60 cm (33.6 pixels per
   degree): the eccentricity inside which every pixel needs its own sample. inside_pct: the
   frames whose true gaze lies inside that region (inside r_full + margin for
   filtered_margin), over fixation and pursuit frames; rows with the trace suffix _saccades
   count the frames from each saccade's onset to its landing plus the latency (no tracker can
   have reported the landing earlier), and leave jitter and lag empty. Blink frames (eyes
   shut) are in neither. work_ratio: the mean area of the full-quality disc against an ideal
   tracker's (r_full around the true gaze), ((r_full + margin) / r_full)^2 (1 without a
   margin). jitter_deg_rms: RMS of shown minus true gaze over fixation frames at least
   150 ms after a landing has been shown. lag_deg: mean |shown - true| over pursuit frames.
   settle_frames: frames from a landing being shown (landing + latency) until the shown gaze
   is within 1 degree of the true gaze, mean over saccades. Deterministic (seeded). */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "bench/gaze_trace.h"

#include <stdio.h>
#include <string.h>

#define RATE_HZ 120.0
#define FRAME_HZ 90.0
#define MAXS 4096

static gt_trace g_tr;
static uint64_t g_t[MAXS];
static double g_x[MAXS], g_y[MAXS];

typedef struct acc {
    double in_n, in_k, work, jit2, jit_n, lag, lag_n, settle, settle_n;
} acc;

static void row(FILE *f, const char *trace, const char *suffix, int lat, double noise,
                const char *mode, const acc *a, int sacc_row)
{
    fprintf(f, "%s%s,%d,%.2f,%s,%.2f,%.3f,", trace, suffix, lat, noise, mode,
            a->in_n > 0 ? 100.0 * a->in_k / a->in_n : 0.0, a->in_n > 0 ? a->work / a->in_n : 1.0);
    if (sacc_row) fprintf(f, ",,");
    else fprintf(f, "%.3f,%.3f,", a->jit_n > 0 ? sqrt(a->jit2 / a->jit_n) : 0.0,
                 a->lag_n > 0 ? a->lag / a->lag_n : 0.0);
    fprintf(f, "%.2f\n", a->settle_n > 0 ? a->settle / a->settle_n : 0.0);
}

int main(int argc, char **argv)
{
    static const int lats[4] = { 0, 20, 50, 80 };
    static const double noises[3] = { 0.25, 0.5, 1.0 };
    static const char *const modes[3] = { "raw", "filtered", "filtered_margin" };
    const char *out = "bench/results/gaze.csv";
    fov_display disp;
    fov_ecc_model em;
    fov_eye_plan plan;
    fov_gaze g0;
    double r_full;
    int tr, li, ni, mo;
    FILE *f;
    if (argc > 1) {
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        if (!help && !strcmp(argv[1], "--out") && argc == 3) {
            out = argv[2];
        } else {
            fputs("usage: bench_gaze [--out FILE]\n  the gaze filter and latency margin on "
                  "generated gaze traces;\n  writes bench/results/gaze.csv (or FILE)\n"
                  "  -h, --help  this text\n", help ? stdout : stderr);
            return help ? 0 : 2;
        }
    }
    f = fopen(out, "w");
    if (!f) { fprintf(stderr, "cannot write %s\n", out); return 1; }
    memset(&disp, 0, sizeof disp);
    disp.pixel_pitch_mm = (float)(27.0 * 25.4 / sqrt(1920.0 * 1920.0 + 1080.0 * 1080.0));
    disp.distance_mm = 600.0f;
    g0.x = 960.0f; g0.y = 540.0f;
    if (fovsdf_ecc_init(&em, &disp, 60.0f, 1920, 1080, g0) != FOV_OK ||
        fovsdf_eye_plan(NULL, &em, &plan) != FOV_OK) {
        fprintf(stderr, "eye plan failed\n");
        return 1;
    }
    r_full = plan.e_full;
    printf("display 27\" 1920x1080 at 60 cm: %.1f ppd, r_full = e_full = %.3f deg\n",
           (double)plan.ppd, r_full);
    fprintf(f, "trace,latency_ms,noise_deg,mode,inside_pct,work_ratio,jitter_deg_rms,lag_deg,"
               "settle_frames\n");
    for (tr = 0; tr < GT_NUM_TRACES; ++tr) {
        gt_make(&g_tr, tr, 2026u);
        for (ni = 0; ni < 3; ++ni) {
            int ns = gt_track(&g_tr, RATE_HZ, noises[ni], (uint64_t)(100 * tr + ni), g_t, g_x,
                              g_y, MAXS);
            for (li = 0; li < 4; ++li)
                for (mo = 0; mo < 3; ++mo) {
                    fov_gaze_filter gf;
                    acc A, S;
                    int k = 0, fr, sacc_i = 0, settle_open = -1;
                    double settle_start = 0.0, margin = 0.0, ex = 0.0, ey = 0.0;
                    int have = 0;
                    memset(&A, 0, sizeof A); memset(&S, 0, sizeof S);
                    if (fovsdf_gaze_filter_init(&gf, NULL) != FOV_OK) return 1;
                    for (fr = 0;; ++fr) {
                        uint64_t T = (uint64_t)((double)fr * 1e6 / FRAME_HZ + 0.5);
                        uint64_t L = (uint64_t)lats[li] * 1000u, Ts = T >= L ? T - L : 0u;
                        int ms, ph, in_sacc = 0, j;
                        double tx, ty, d, R;
                        if (T / 1000u >= (uint64_t)g_tr.n_ms) break;
                        while (k < ns && g_t[k] <= Ts && T >= (uint64_t)lats[li] * 1000u) {
                            fov_result r = fovsdf_gaze_filter_push(&gf, g_t[k], (float)g_x[k],
                                                                    (float)g_y[k]);
                            if (r == FOV_ERR_LIMIT) {
                                fovsdf_gaze_filter_reset(&gf);
                                r = fovsdf_gaze_filter_push(&gf, g_t[k], (float)g_x[k],
                                                            (float)g_y[k]);
                            }
                            if (r != FOV_OK) {
                                fprintf(stderr, "push failed %d\n", (int)r);
                                return 1;
                            }
                            if (mo == 0) { ex = g_x[k]; ey = g_y[k]; }
                            else { ex = gf.x_deg; ey = gf.y_deg; }
                            have = 1;
                            k++;
                        }
                        if (!have) continue;
                        margin = 0.0;
                        if (mo == 2) {
                            float m;
                            /* latency: the system's plus the age of the newest sample (up to
                               one tracker period) */
                            fovsdf_gaze_margin(&gf, 0.0f,
                                               (float)lats[li] + (float)(1000.0 / RATE_HZ), &m);
                            margin = m;
                        }
                        R = r_full + margin;
                        ms = gt_ms(&g_tr, T);
                        ph = g_tr.phase[ms];
                        tx = g_tr.x[ms]; ty = g_tr.y[ms];
                        d = sqrt((ex - tx) * (ex - tx) + (ey - ty) * (ey - ty));
                        for (j = 0; j < g_tr.n_sacc; ++j)
                            if ((int)(T / 1000u) >= g_tr.sacc_on[j] &&
                                (int)(T / 1000u) < g_tr.sacc_off[j] + lats[li])
                                in_sacc = 1;
                        /* settling after the landing of saccade sacc_i has been shown */
                        while (sacc_i < g_tr.n_sacc &&
                               (int)(T / 1000u) >= g_tr.sacc_off[sacc_i] + lats[li]) {
                            settle_open = sacc_i; settle_start = (double)fr; sacc_i++;
                        }
                        if (settle_open >= 0 && !in_sacc && d <= 1.0) {
                            A.settle += (double)fr - settle_start; A.settle_n += 1.0;
                            settle_open = -1;
                        }
                        if (ph == GT_BLINK) continue;
                        if (in_sacc) {
                            S.in_n += 1.0; S.in_k += d <= R ? 1.0 : 0.0;
                            S.work += (R / r_full) * (R / r_full);
                            continue;
                        }
                        A.in_n += 1.0; A.in_k += d <= R ? 1.0 : 0.0;
                        A.work += (R / r_full) * (R / r_full);
                        if (ph == GT_PURSUIT) { A.lag += d; A.lag_n += 1.0; }
                        if (ph == GT_FIX) {
                            int steady = 1;
                            for (j = 0; j < g_tr.n_sacc; ++j)
                                if ((int)(T / 1000u) >= g_tr.sacc_off[j] + lats[li] &&
                                    (int)(T / 1000u) < g_tr.sacc_off[j] + lats[li] + 150)
                                    steady = 0;
                            if (steady) { A.jit2 += d * d; A.jit_n += 1.0; }
                        }
                    }
                    S.settle = A.settle; S.settle_n = A.settle_n;
                    row(f, g_tr.name, "", lats[li], noises[ni], modes[mo], &A, 0);
                    row(f, g_tr.name, "_saccades", lats[li], noises[ni], modes[mo], &S, 1);
                }
        }
    }
    fclose(f);
    printf("wrote %s\n", out);
    return 0;
}
