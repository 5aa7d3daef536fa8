/* bench_lp.c - fovlp.h: shaded samples, wall time and error per eccentricity ring (make bench-lp).

   Shading is fovsdf's (examples/lp_sdf_shade.h: one primary ray, normal, Lambert, and with
   --shadows soft shadows, per sample) on its built-in scenes; everything runs in this one process on one thread, so
   the time ratios are measured side by side. For every scene and configuration (preset and
   sigma):
     samples_pct   shaded samples (LP texels on the screen + disc pixels + 1) / pixels * 100,
                   deterministic (fovlp_count_samples), gaze at the centre
     speedup       median wall time of full-resolution shading (one sample per pixel centre
                   through the same shading function) / median wall time of a foveated frame
                   (fovlp_shade_rows + fovlp_reconstruct_rows, no TAA), --runs runs each,
                   alternating (full, foveated) so both see the same machine load
     psnr_fovea, psnr_all, ssim_fovea   the TAA output of a still camera after --frames frames
                   (default 20: the age cap) against the ground truth, 16 samples per
                   pixel (Halton (2,3) points 1..16 moved by (0.029, 0.037) px so that their
                   mean is the pixel centre, box filtered), sRGB; fovea = eccentricity < 5
                   degrees (fovlp_ecc_deg)
     flicker_ratio mean |frame-to-frame change| beyond diag/3 from the gaze, over the last
                   half of the frames, of the TAA output / of the raw jittered reconstruction
   then: psnr_fovea_1f, psnr_all_1f, ssim_fovea_1f (a single frame without TAA), flicker_taa,
   flicker_raw, time_fov_ms, time_full_ms, lp_w, lp_h, r_g, width, height, runs, frames, shading, and per
   ring (20 rings of equal eccentricity from 0 to the farthest corner, the thesis's protocol)
   rmse_rK, psnr_rK, ssim_rK for K = 1..20 (TAA output); then deterministic costs of the first
   timing run (fovsdf_stats): evals_full, evals_fov (distance evaluations of the full-resolution
   and of the foveated frame), evals_px_full (per pixel), evals_smp_fov (per shaded sample),
   hits_pct_full, hits_pct_fov (primary rays that hit), eval_ratio (evals_full / evals_fov: the
   speed-up if time were evaluations); and psnr_fovea_ref (the TAA output against 256 samples
   per pixel, a 16 x 16 grid, fovea pixels only), psnr_gt_fovea_ref (the 16-spp ground truth
   itself against that reference: the measurement's own error in the fovea); prims_px_full,
   prims_smp_fov: primitive evaluations of fovsdf's built-in programs (the part of the
   distance evaluations not skipped by bounds) per pixel and per shaded sample; group: the
   main grid's frames (foveated and full resolution, not the ground truths) shade groups of
   that many samples or pixels from a shared certified cone head start
   (fovsdf_shade_points_grouped, --group G, default 8; 0 as before: every ray from the camera).
   Writes bench/results/lp.csv and, with gnuplot, bench/results/lp_<scene>.png (PSNR per ring)
   and bench/results/lp_speed.png (speed-up against the sample ratio). Then, per scene of
   --moving-scenes, a moving camera and gaze sequence (see moving_seq) into
   bench/results/lp_moving.csv and lp_moving.png (ring RMSE, TAA off / on).

   usage: bench_lp [--full] [--hd] [--shadows] [--group G] [--runs N] [--frames N] [--scenes a,b]
                   [--moving-scenes a,b] [--moving-frames N] [--out FILE]
          bench_lp --fovea-study [--scenes a,b]   what limits the fovea's PSNR (see fovea_study)
          bench_lp --acuity-study [--scenes a,b] [--display cam|monitor|hmd] [--quality Q] [--frames N]
                   what makes fovlp_config_acuity's periphery visible (see acuity_study)
   Default grid (640x360, shading without shadow rays as bench-sdf does, 3 timing runs; about
   10 minutes on a 2-core machine): five scenes (atrium, whose fovea is flat, only with
   --full), the four presets of Table 5.1 plus C Fov at sigma 1.7 and 2.0 (Table 5.4); the
   moving sequence (12 frames) on primitives and columns. --full: all six scenes, every preset at sigma x
   {0.8, 1, 1.25, 1.5} of its own, the moving sequence on every scene.
   --hd: 1280x720. --shadows: with soft shadows (several times slower on the lit scenes).
   "The thesis": K. Andersson, T. Hansson, "Performance Optimizations for Foveated Real-Time
   Raytracing", master's thesis, Lund University, LU-CS-EX 2020-64, 2020. */
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVLP_IMPLEMENTATION
#include "../fovlp.h"
#include "../examples/lp_sdf_shade.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NRINGS 20

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
static float srgb(float v)
{
    v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}
static void to_disp(const float *lin, float *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) d[i] = srgb(lin[i]);
}
static float halton(uint32_t n, uint32_t b)
{
    float f = 1.0f, r = 0.0f;
    while (n) { f /= (float)b; r += f * (float)(n % b); n /= b; }
    return r;
}
static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}
static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Reference image, box filtered: grid 0: n Halton (2, 3) points 1..n moved so that their
   mean is the pixel centre (Halton 1..16 alone average (0.471, 0.463): an image shifted by
   1/30 pixel); grid 1: an n x n grid of cell centres; grid 2: Halton 1..n as they are. With mask, only the pixels whose
   mask value is below lim (the others are left 0). */
/* A built-in scene at W x H with the tracer on it, the gaze at the centre and the shading
   glue pointing at the tracer; returns the scene memory (the caller frees it). */
static void *open_scene(uint32_t id, uint32_t W, uint32_t H, const fovsdf_config *scfg, fovsdf_builtin *bi,
                        fovsdf_ctx *sdf, lpsdf_user *user, fov_gaze *gaze)
{
    size_t bytes = 0;
    void *mem;
    fovsdf_builtin_size(id, &bytes);
    mem = malloc(bytes);
    fovsdf_builtin_init(id, bi, mem, bytes);
    bi->camera.width = W;
    bi->camera.height = H;
    gaze->x = 0.5f * (float)W;
    gaze->y = 0.5f * (float)H;
    fovsdf_init(sdf, scfg, &bi->scene, &bi->camera, *gaze, NULL, 0);
    memset(user, 0, sizeof *user);
    user->sdf = sdf;
    return mem;
}

/* One TAA frame: shade, reconstruct, resolve into the history ping-pong; returns the output. */
static const float *taa_frame(fovlp_ctx *lp, fov_gaze gaze, const fovlp_camera *cam, lpsdf_user *user, float *smp,
                              float *sd, float *cur, float *cd, float *hist[2], float *hd[2], uint8_t *ag[2], int *ping)
{
    fovlp_taa_io io;
    fovlp_begin_frame(lp, gaze, cam);
    memset(smp, 0, (size_t)lp->geo.samples * 3 * sizeof(float)); /* as fovlp_shade_rows */
    memset(sd, 0, (size_t)lp->geo.samples * sizeof(float));
    lpsdf_shade_samples(lp, 0, fovlp_sample_rows(lp), user, smp, sd);
    fovlp_reconstruct_rows(lp, smp, sd, 0, lp->geo.height, cur, 0, cd);
    io.cur_rgb = cur; io.cur_depth = cd;
    io.prev_rgb = hist[*ping]; io.prev_depth = hd[*ping]; io.prev_age = ag[*ping];
    io.out_rgb = hist[1 - *ping]; io.out_depth = hd[1 - *ping]; io.out_age = ag[1 - *ping];
    fovlp_taa_rows(lp, &io, 0, lp->geo.height, NULL);
    *ping = 1 - *ping;
    return hist[*ping];
}

static void gt_image(lpsdf_user *user, uint32_t W, uint32_t H, const float *mask, float lim, uint32_t n, int grid,
                     float *out)
{
    float sx = 0.0f, sy = 0.0f, inv;
    uint32_t x, y, k, j, ns = grid == 1 ? n * n : n;
    inv = 1.0f / (float)ns;
    if (grid == 2) {
        grid = 0; /* unmoved Halton points: sx = sy = 0 */
    } else if (!grid) {
        for (k = 1; k <= n; ++k) { sx += halton(k, 2); sy += halton(k, 3); }
        sx = 0.5f - sx / (float)n;
        sy = 0.5f - sy / (float)n;
    }
    /* a row's samples shaded as one batch (fovsdf_shade_points: each exactly
       fovsdf_shade_point's value), summed per pixel in sample order */
    float *xy = (float *)malloc((size_t)W * ns * 2 * sizeof(float));
    float *c = (float *)malloc((size_t)W * ns * 3 * sizeof(float));
    for (y = 0; y < H; ++y) {
        uint32_t m = 0;
        for (x = 0; x < W; ++x) {
            if (mask && !(mask[(size_t)y * W + x] < lim)) continue;
            for (k = 0; k < ns; ++k) {
                float px, py;
                if (grid) { px = ((float)(k % n) + 0.5f) / (float)n; py = ((float)(k / n) + 0.5f) / (float)n; }
                else { px = halton(k + 1, 2) + sx; py = halton(k + 1, 3) + sy; }
                xy[2 * (size_t)m] = (float)x + px; xy[2 * (size_t)m + 1] = (float)y + py;
                ++m;
            }
        }
        if (m) fovsdf_shade_points(user->sdf, m, xy, 2, c, NULL, NULL, &user->stats);
        m = 0;
        for (x = 0; x < W; ++x) {
            float acc[3] = { 0, 0, 0 };
            size_t o = 3 * ((size_t)y * W + x);
            if (mask && !(mask[(size_t)y * W + x] < lim)) { out[o] = out[o + 1] = out[o + 2] = 0.0f; continue; }
            for (k = 0; k < ns; ++k, ++m) {
                acc[0] += c[3 * (size_t)m]; acc[1] += c[3 * (size_t)m + 1]; acc[2] += c[3 * (size_t)m + 2];
            }
            for (j = 0; j < 3; ++j) out[o + j] = acc[j] * inv;
        }
    }
    free(xy); free(c);
}

typedef struct cfg_t {
    uint32_t preset;
    float sigma;
} cfg_t;

/* Moving camera and gaze (item "a moving camera must not ghost", measured): C Fov at its
   preset sigma; the camera slides sideways (0.04 scene units a frame) and the gaze follows a
   slow Lissajous path (under the 2-degree reset); a warm-up begin_frame makes frame 0 a
   moving frame, so jitter is off (thesis) and TAA off / on (clamp column: "thesis" =
   taa.thesis_moving 1, "default" = the library's defaults, "aabb" / "variance" = taa.clamp)
   see the very same samples: one shading per frame, five resolves. Reference per frame: 4 samples
   per pixel (2 x 2 grid). Rings: 20 rings of max_ecc / 20 degrees around the current gaze.
   Error and flicker (mean |e_t - e_(t-1)| of the error e = output - reference, sRGB) over
   frames 1 .. n-1. motion_px: mean screen motion of the hit points per frame (every 7th
   pixel, reprojected with the shaded depth). worst_ring_ratio: the largest ring RMSE of the
   output over the ring RMSE without TAA (above 1 where TAA is worse: ghosting). */
#define NVAR 5
static void moving_seq(FILE *mcsv, uint32_t id, const fovsdf_config *scfg, uint32_t W, uint32_t H, int nfr,
                       double max_ecc, const char *shading)
{
    fovsdf_builtin bi;
    fovsdf_ctx sdf;
    lpsdf_user user;
    fovlp_ctx lp[NVAR];
    void *lpmem[NVAR], *mem;
    fovlp_config lc;
    size_t bytes = 0, npx = (size_t)W * H, i, nsmp;
    float base_pos[3], base_tgt[3], *smp, *sdep, *cur, *cdep, *ref, *refd, *od, *err[NVAR], *hist[NVAR][2], *hdep[NVAR][2];
    uint8_t *age[NVAR][2];
    double motion = 0.0, nmotion = 0.0, se[NVAR][NRINGS], fl[NVAR][NRINGS], flp[NVAR], nflp = 0.0, sea[NVAR], fla[NVAR];
    long cnt[NRINGS], cntf[NRINGS];
    int f, v, ping = 0;
    static const char *vname[NVAR] = { "off", "thesis", "default", "aabb", "variance" };
    float diag = sqrtf((float)W * (float)W + (float)H * (float)H);
    memset(se, 0, sizeof se); memset(fl, 0, sizeof fl); memset(flp, 0, sizeof flp); memset(sea, 0, sizeof sea);
    memset(fla, 0, sizeof fla); memset(cnt, 0, sizeof cnt); memset(cntf, 0, sizeof cntf);
    fovsdf_builtin_size(id, &bytes);
    mem = malloc(bytes);
    fovsdf_builtin_init(id, &bi, mem, bytes);
    bi.camera.width = W;
    bi.camera.height = H;
    memcpy(base_pos, bi.camera.pos, sizeof base_pos);
    memcpy(base_tgt, bi.camera.target, sizeof base_tgt);
    lc = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    lc.cam_fov_y_deg = bi.camera.fov_y_deg;
    for (v = 0; v < NVAR; ++v) {
        lc.taa.enable = v ? 1u : 0u;
        lc.taa.clamp = v == 3 ? (uint32_t)FOVLP_CLAMP_AABB : (v == 4 ? (uint32_t)FOVLP_CLAMP_VARIANCE : 0u);
        lc.taa.thesis_moving = v == 1 ? 1u : 0u;
        fovlp_memory_size(&lc, &bytes);
        lpmem[v] = malloc(bytes);
        fovlp_init(&lp[v], &lc, lpmem[v], bytes);
        err[v] = (float *)malloc(npx * 3 * sizeof(float));
        for (f = 0; f < 2; ++f) {
            hist[v][f] = (float *)malloc(npx * 3 * sizeof(float));
            hdep[v][f] = (float *)malloc(npx * sizeof(float));
            age[v][f] = (uint8_t *)malloc(npx);
        }
    }
    nsmp = lp[0].geo.samples;
    smp = (float *)malloc(nsmp * 3 * sizeof(float));
    sdep = (float *)malloc(nsmp * sizeof(float));
    cur = (float *)malloc(npx * 3 * sizeof(float));
    cdep = (float *)malloc(npx * sizeof(float));
    ref = (float *)malloc(npx * 3 * sizeof(float));
    refd = (float *)malloc(npx * 3 * sizeof(float));
    od = (float *)malloc(npx * 3 * sizeof(float));
    memset(&user, 0, sizeof user);
    user.sdf = &sdf;
    for (f = -1; f < nfr; ++f) {
        fov_gaze gz;
        fov_ecc_model em;
        fovlp_camera cam;
        float ph = 0.2f * (float)f;
        gz.x = (float)W * (0.5f + 0.06f * sinf(ph));
        gz.y = (float)H * (0.5f + 0.06f * sinf(2.0f * ph));
        bi.camera.pos[0] = base_pos[0] + 0.04f * (float)f;
        bi.camera.target[0] = base_tgt[0] + 0.04f * (float)f;
        fovsdf_init(&sdf, scfg, &bi.scene, &bi.camera, gz, NULL, 0);
        fovlp_camera_from(&bi.camera, &cam); /* the camera fovsdf_init just took */
        for (v = 0; v < NVAR; ++v) {
            fovlp_begin_frame(&lp[v], gz, &cam);
            if (f < 0) fovlp_reset_history(&lp[v]); /* warm-up: frame 0 is a moving frame */
        }
        if (f < 0) continue;
        memset(smp, 0, nsmp * 3 * sizeof(float));
        memset(sdep, 0, nsmp * sizeof(float));
        lpsdf_shade_samples(&lp[0], 0, fovlp_sample_rows(&lp[0]), &user, smp, sdep);
        fovlp_reconstruct_rows(&lp[0], smp, sdep, 0, H, cur, 0, cdep);
        gt_image(&user, W, H, NULL, 0.0f, 2, 1, ref);
        if (f >= 1) { /* screen motion of the hit points since the previous frame */
            const fovlp_camera *ca = &lp[1].cam, *pc = &lp[1].prev_cam;
            float asp = (float)W / (float)H;
            for (i = 0; i < npx; i += 7) {
                float hx = (float)(i % W) + 0.5f, hy = (float)(i / W) + 0.5f, d[3], rel[3], z, n;
                float sxn = (hx / (float)W * 2.0f - 1.0f) * ca->tan_half_y * asp, syn = (hy / (float)H * 2.0f - 1.0f) * ca->tan_half_y;
                int ch;
                if (!(cdep[i] < sdf.t_max)) continue;
                for (ch = 0; ch < 3; ++ch) d[ch] = ca->fwd[ch] + sxn * ca->right[ch] - syn * ca->up[ch];
                n = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (ch = 0; ch < 3; ++ch) rel[ch] = ca->pos[ch] + cdep[i] * d[ch] / n - pc->pos[ch];
                z = rel[0] * pc->fwd[0] + rel[1] * pc->fwd[1] + rel[2] * pc->fwd[2];
                if (!(z > 1e-6f)) continue;
                {
                    float px = (rel[0] * pc->right[0] + rel[1] * pc->right[1] + rel[2] * pc->right[2]) / (z * pc->tan_half_y * asp);
                    float py = (rel[0] * pc->up[0] + rel[1] * pc->up[1] + rel[2] * pc->up[2]) / (z * pc->tan_half_y);
                    float mx = (px + 1.0f) * 0.5f * (float)W - hx, my = (1.0f - py) * 0.5f * (float)H - hy;
                    motion += (double)sqrtf(mx * mx + my * my);
                    nmotion += 1.0;
                }
            }
        }
        to_disp(ref, refd, npx * 3);
        fovlp_ecc_init(&em, NULL, bi.camera.fov_y_deg, W, H, gz);
        for (v = 0; v < NVAR; ++v) {
            const float *o = cur;
            if (v) {
                fovlp_taa_io io;
                io.cur_rgb = cur; io.cur_depth = cdep;
                io.prev_rgb = hist[v][ping]; io.prev_depth = hdep[v][ping]; io.prev_age = age[v][ping];
                io.out_rgb = hist[v][1 - ping]; io.out_depth = hdep[v][1 - ping]; io.out_age = age[v][1 - ping];
                fovlp_taa_rows(&lp[v], &io, 0, H, NULL);
                o = hist[v][1 - ping];
            }
            to_disp(o, od, npx * 3);
            for (i = 0; i < npx; ++i) {
                float px = (float)(i % W) + 0.5f, py = (float)(i / W) + 0.5f;
                double e = (double)fovlp_ecc_deg(&em, px, py) / max_ecc * NRINGS;
                int k = e < (double)(NRINGS - 1) ? (int)e : NRINGS - 1, ch;
                float dx = px - gz.x, dy = py - gz.y;
                int periph = dx * dx + dy * dy > diag * diag / 9.0f;
                for (ch = 0; ch < 3; ++ch) {
                    size_t j = 3 * i + (size_t)ch;
                    float ne = od[j] - refd[j];
                    if (f >= 1) { se[v][k] += (double)ne * (double)ne; sea[v] += (double)ne * (double)ne; }
                    if (f >= 2) {
                        double d = fabs((double)(ne - err[v][j]));
                        fl[v][k] += d; fla[v] += d;
                        if (periph) flp[v] += d;
                    }
                    err[v][j] = ne;
                }
                if (v == 0) {
                    if (f >= 1) cnt[k] += 3;
                    if (f >= 2) { cntf[k] += 3; if (periph) nflp += 3.0; }
                }
            }
        }
        ping = 1 - ping;
    }
    {
        long ctot = 0, ftot = 0;
        int k;
        for (k = 0; k < NRINGS; ++k) { ctot += cnt[k]; ftot += cntf[k]; }
        for (v = 0; v < NVAR; ++v) {
            double worst = 0.0;
            for (k = 0; k < NRINGS; ++k)
                if (cnt[k] && se[0][k] > 0.0) {
                    double q = sqrt(se[v][k] / se[0][k]);
                    if (q > worst) worst = q;
                }
            fprintf(mcsv, "%s,C Fov,%.3f,%d,%s,%d,%.2f,%.3f,%.6f,%.6f,%.4f", fovsdf_builtin_name(id), (double)lc.sigma, v ? 1 : 0,
                    vname[v], nfr, nmotion > 0.0 ? motion / nmotion : 0.0, ctot ? 10.0 * log10((double)ctot / sea[v]) : 0.0, ftot ? fla[v] / (double)ftot : 0.0,
                    nflp > 0.0 ? flp[v] / nflp : 0.0, worst);
            for (k = 0; k < NRINGS; ++k) fprintf(mcsv, ",%.5f", cnt[k] ? sqrt(se[v][k] / (double)cnt[k]) : 0.0);
            for (k = 0; k < NRINGS; ++k) fprintf(mcsv, ",%.6f", cntf[k] ? fl[v][k] / (double)cntf[k] : 0.0);
            fprintf(mcsv, ",%s\n", shading);
            fprintf(stderr, "  moving %s TAA %-8s: PSNR %.2f dB, error flicker %.5f (periphery %.5f), worst ring RMSE / TAA off %.3f\n",
                    fovsdf_builtin_name(id), vname[v], ctot ? 10.0 * log10((double)ctot / sea[v]) : 0.0,
                    ftot ? fla[v] / (double)ftot : 0.0, nflp > 0.0 ? flp[v] / nflp : 0.0, worst);
        }
        fflush(mcsv);
    }
    for (v = 0; v < NVAR; ++v) {
        free(lpmem[v]); free(err[v]);
        for (f = 0; f < 2; ++f) { free(hist[v][f]); free(hdep[v][f]); free(age[v][f]); }
    }
    free(smp); free(sdep); free(cur); free(cdep); free(ref); free(refd); free(od); free(mem);
}

/* --fovea-study: what limits the fovea's PSNR (C Fov, still camera, gaze at the centre,
   fovea pixels only): ground truths of 16 samples (Halton unmoved / centred) against 256 (16 x
   16 grid), and the TAA output after 16 and 20 frames (and with variance clipping) against
   each. Prints to stderr; writes nothing. */
static void fovea_study(uint32_t id, const fovsdf_config *scfg, uint32_t W, uint32_t H)
{
    fovsdf_builtin bi;
    fovsdf_ctx sdf;
    lpsdf_user user;
    size_t bytes = 0, npx = (size_t)W * H, i;
    void *mem;
    fov_gaze gaze;
    fov_ecc_model em;
    float *ecc = (float *)malloc(npx * sizeof(float)), *im[4], *tmp = (float *)malloc(npx * 3 * sizeof(float));
    const char *nm = fovsdf_builtin_name(id);
    fovm_sel sel;
    double p = 0.0;
    long cnt;
    int k, v;
    mem = open_scene(id, W, H, scfg, &bi, &sdf, &user, &gaze);
    fovlp_ecc_init(&em, NULL, bi.camera.fov_y_deg, W, H, gaze);
    for (i = 0; i < npx; ++i) ecc[i] = fovlp_ecc_deg(&em, (float)(i % W) + 0.5f, (float)(i / W) + 0.5f);
    sel = fovm_sel_band(ecc, 0.0, 5.0);
    for (k = 0; k < 4; ++k) im[k] = (float *)malloc(npx * 3 * sizeof(float));
    gt_image(&user, W, H, ecc, 5.0f, 16, 1, tmp); to_disp(tmp, im[0], npx * 3);  /* 256 spp */
    gt_image(&user, W, H, ecc, 5.0f, 16, 2, tmp); to_disp(tmp, im[1], npx * 3);  /* 16 unmoved */
    gt_image(&user, W, H, ecc, 5.0f, 16, 0, tmp); to_disp(tmp, im[2], npx * 3);  /* 16 centred */
    fovm_psnr_sel(im[0], im[1], (int)W, (int)H, 3, &sel, &p, &cnt);
    fprintf(stderr, "  %s fovea: 16 spp, Halton 1..16 unmoved, against 256 spp: %.2f dB\n", nm, p);
    fovm_psnr_sel(im[0], im[2], (int)W, (int)H, 3, &sel, &p, &cnt);
    fprintf(stderr, "  %s fovea: 16 spp, Halton 1..16 centred (the ground truth), against 256 spp: %.2f dB\n", nm, p);
    for (v = 0; v < 3; ++v) {
        fovlp_config lc = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
        fovlp_ctx lp;
        void *lm;
        float *smp, *sd, *cur, *cd, *hist[2], *hd[2];
        uint8_t *ag[2];
        int f, ping = 0, nfr = v == 0 ? 16 : 20;
        fovlp_camera cam;
        fovlp_camera_from(&bi.camera, &cam); /* the camera of open_scene's fovsdf_init */
        lc.cam_fov_y_deg = bi.camera.fov_y_deg;
        lc.taa.enable = 1;
        lc.taa.clamp = v == 2 ? (uint32_t)FOVLP_CLAMP_VARIANCE : 0u;
        fovlp_memory_size(&lc, &bytes);
        lm = malloc(bytes);
        fovlp_init(&lp, &lc, lm, bytes);
        smp = (float *)malloc((size_t)lp.geo.samples * 3 * sizeof(float));
        sd = (float *)malloc((size_t)lp.geo.samples * sizeof(float));
        cur = (float *)malloc(npx * 3 * sizeof(float));
        cd = (float *)malloc(npx * sizeof(float));
        for (f = 0; f < 2; ++f) { hist[f] = (float *)malloc(npx * 3 * sizeof(float)); hd[f] = (float *)malloc(npx * sizeof(float)); ag[f] = (uint8_t *)malloc(npx); }
        for (f = 0; f < nfr; ++f) taa_frame(&lp, gaze, &cam, &user, smp, sd, cur, cd, hist, hd, ag, &ping);
        to_disp(hist[ping], im[3], npx * 3);
        fprintf(stderr, "  %s fovea: C Fov TAA after %d still frames%s against", nm, nfr, v == 2 ? ", variance clipping" : "");
        for (k = 0; k < 3; ++k) {
            fovm_psnr_sel(im[k], im[3], (int)W, (int)H, 3, &sel, &p, &cnt);
            fprintf(stderr, " %s %.2f dB", k == 0 ? "256 spp" : (k == 1 ? ", 16 unmoved" : ", 16 centred"), p);
        }
        fprintf(stderr, "\n");
        for (f = 0; f < 2; ++f) { free(hist[f]); free(hd[f]); free(ag[f]); }
        free(lm); free(smp); free(sd); free(cur); free(cd);
    }
    for (k = 0; k < 4; ++k) free(im[k]);
    free(ecc); free(tmp); free(mem);
}

/* --acuity-study: what makes fovlp_config_acuity's periphery visible (still camera, gaze at
   the centre). Both images are filtered to the eye's resolution first: a Gaussian of sigma =
   MAR(e) ppd / 2 pixels at each pixel (separable; the shared fov_eye model with its defaults,
   quality 1, whatever --quality configures; ppd the display's at its axis), then encoded to
   sRGB; PSNR and FLIP (at the display's ppd) per
   eccentricity band, against the ground truth (16 samples per pixel, as gt_image). Rows:
   full (one sample per pixel centre, the full-resolution method); lp_acuity 1 frame (no
   TAA: point samples); lp_acuity prefiltered (the same buffer and reconstruction, each LP
   sample the mean of 4 x 4 points over its texel: what point sampling costs); lp_acuity with
   TAA after 1, 4, 8 and --frames still frames; C Fov with TAA after --frames. Then per band:
   detail (the variance of each image minus its 5 x 5 box mean, after the eye filter) of the
   output over the ground truth's (below 1: contrast lost), and flicker (mean |change| per
   frame after the eye filter, last half of the frames) of the raw jittered reconstruction and
   of the TAA output. Displays (--display): cam (W x H spanning the scene camera's field of
   view, as bench-lp), monitor (1920 x 1080, 0.3113 mm pixels at 600 mm: 33.6 ppd) and hmd
   (1600 x 1600 over 100 degrees); the camera's field of view is the display's. Prints to
   stderr; writes nothing. */
#define ACU_NB 5
static const double acu_band[ACU_NB + 1] = { 0.0, 5.0, 10.0, 20.0, 30.0, 180.0 };
typedef struct acu_env {
    uint32_t W, H;
    double ppd;
    const float *ecc, *sig;
} acu_env;
/* linear in, eye-filtered sRGB out (tmp: 3 W H floats) */
static void acu_filter(const acu_env *e, const float *in, float *tmp, float *out)
{
    uint32_t x, y, W = e->W, H = e->H;
    int pass;
    for (pass = 0; pass < 2; ++pass) {
        const float *src = pass ? tmp : in;
        float *dst = pass ? out : tmp;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                size_t i = (size_t)y * W + x;
                float s = e->sig[i];
                double acc[3] = { 0, 0, 0 }, ws = 0.0;
                int R = s < 0.25f ? 0 : (int)ceilf(2.5f * s), d;
                for (d = -R; d <= R; ++d) {
                    int xx = pass ? (int)x : (int)x + d, yy = pass ? (int)y + d : (int)y;
                    double w;
                    const float *p;
                    if (xx < 0 || yy < 0 || xx >= (int)W || yy >= (int)H) continue;
                    w = R ? exp(-(double)(d * d) / (2.0 * (double)s * (double)s)) : 1.0;
                    p = src + 3 * ((size_t)yy * W + (size_t)xx);
                    acc[0] += w * (double)p[0]; acc[1] += w * (double)p[1]; acc[2] += w * (double)p[2];
                    ws += w;
                }
                for (d = 0; d < 3; ++d) dst[3 * i + (size_t)d] = (float)(acc[d] / ws);
            }
    }
    for (x = 0; x < W * H * 3; ++x) out[x] = srgb(out[x]);
}
static void acu_row(const acu_env *e, const char *name, const float *gtf, const float *img, float *tmp, float *f)
{
    int b;
    double p = 0.0, fl = 0.0;
    long n;
    acu_filter(e, img, tmp, f);
    fprintf(stderr, "  %-24s", name);
    for (b = 0; b < ACU_NB; ++b) {
        fovm_sel sel = fovm_sel_band(e->ecc, acu_band[b], acu_band[b + 1]);
        fovm_psnr_sel(gtf, f, (int)e->W, (int)e->H, 3, &sel, &p, &n);
        fovm_flip_sel(gtf, f, (int)e->W, (int)e->H, 3, e->ppd, &sel, &fl, &n);
        if (n) fprintf(stderr, " | %5.1f %.3f", p, fl); else fprintf(stderr, " |    -      - ");
    }
    fovm_psnr(gtf, f, (int)e->W, (int)e->H, 3, &p);
    fovm_flip(gtf, f, (int)e->W, (int)e->H, 3, e->ppd, &fl, NULL);
    fprintf(stderr, " || %5.1f %.3f\n", p, fl);
}
/* detail energy of f over gtf per band (both eye-filtered sRGB) */
static void acu_detail(const acu_env *e, const char *name, const float *gtf, const float *f)
{
    double et[ACU_NB], eg[ACU_NB];
    uint32_t x, y, W = e->W;
    int b, c, dx, dy;
    memset(et, 0, sizeof et); memset(eg, 0, sizeof eg);
    for (y = 2; y + 2 < e->H; ++y)
        for (x = 2; x + 2 < W; ++x) {
            size_t i = (size_t)y * W + x;
            for (b = 0; b < ACU_NB && !((double)e->ecc[i] < acu_band[b + 1]); ++b) {}
            if (b == ACU_NB) continue;
            for (c = 0; c < 3; ++c) {
                double mt = 0.0, mg = 0.0;
                for (dy = -2; dy <= 2; ++dy)
                    for (dx = -2; dx <= 2; ++dx) {
                        size_t j = 3 * ((size_t)((int)y + dy) * W + (size_t)((int)x + dx)) + (size_t)c;
                        mt += (double)f[j]; mg += (double)gtf[j];
                    }
                mt = (double)f[3 * i + (size_t)c] - mt / 25.0; mg = (double)gtf[3 * i + (size_t)c] - mg / 25.0;
                et[b] += mt * mt; eg[b] += mg * mg;
            }
        }
    fprintf(stderr, "  %-24s detail / ground truth's:", name);
    for (b = 0; b < ACU_NB; ++b) fprintf(stderr, " %.2f", eg[b] > 0.0 ? et[b] / eg[b] : 0.0);
    fprintf(stderr, "\n");
}
static void acuity_study(uint32_t id, const fovsdf_config *scfg, uint32_t W, uint32_t H, int display, float q,
                         int nfr)
{
    fovsdf_builtin bi;
    fovsdf_ctx sdf;
    lpsdf_user user;
    size_t bytes = 0, npx, i;
    void *mem;
    fov_gaze gaze;
    fov_ecc_model em;
    fov_eye eye, eye1 = { 0.0f, 0.0f, 1.0f }; /* eye1: the eye itself (quality 1) */
    fovlp_config ac;
    fovlp_camera cam;
    acu_env e;
    float *ecc, *sig, *gt, *gtf, *tmp, *f, *img, *prevr, *prevo, *fr, *fo;
    const char *nm = fovsdf_builtin_name(id);
    int mode, k;
    fov_result r;
    if (display == 1) { W = 1920; H = 1080; }
    if (display == 2) { W = H = 1600; }
    npx = (size_t)W * H;
    fovsdf_builtin_size(id, &bytes);
    mem = malloc(bytes);
    fovsdf_builtin_init(id, &bi, mem, bytes);
    bi.camera.width = W;
    bi.camera.height = H;
    ac = fovlp_config_default();
    ac.width = W; ac.height = H;
    if (display == 1) { ac.display.pixel_pitch_mm = 0.3113f; ac.display.distance_mm = 600.0f; }
    if (display == 2) ac.display.fov_y_deg = 100.0f;
    if (display == 1) bi.camera.fov_y_deg = 2.0f * atanf(0.5f * (float)H * 0.3113f / 600.0f) * 57.2957795f;
    if (display == 2) bi.camera.fov_y_deg = 100.0f;
    gaze.x = 0.5f * (float)W; gaze.y = 0.5f * (float)H;
    fovsdf_init(&sdf, scfg, &bi.scene, &bi.camera, gaze, NULL, 0);
    memset(&user, 0, sizeof user);
    user.sdf = &sdf;
    fovlp_camera_from(&bi.camera, &cam);
    memset(&eye, 0, sizeof eye);
    eye.quality = q;
    if ((r = fovlp_config_acuity(&ac, &cam, &eye)) != FOV_OK) {
        fprintf(stderr, "  %s: fovlp_config_acuity: %s\n", nm, fovlp_result_string(r));
        free(mem);
        return;
    }
    fovlp_ecc_init(&em, &ac.display, bi.camera.fov_y_deg, W, H, gaze);
    ecc = (float *)malloc(npx * sizeof(float)); sig = (float *)malloc(npx * sizeof(float));
    e.W = W; e.H = H; e.ppd = (double)em.f_px * 3.14159265358979 / 180.0; e.ecc = ecc; e.sig = sig;
    for (i = 0; i < npx; ++i) {
        ecc[i] = fovlp_ecc_deg(&em, (float)(i % W) + 0.5f, (float)(i / W) + 0.5f);
        sig[i] = 0.5f * fovlp_eye_mar(&eye1, ecc[i]) * (float)e.ppd; /* the eye: quality 1 */
    }
    gt = (float *)malloc(npx * 3 * sizeof(float)); gtf = (float *)malloc(npx * 3 * sizeof(float));
    tmp = (float *)malloc(npx * 3 * sizeof(float)); f = (float *)malloc(npx * 3 * sizeof(float));
    img = (float *)malloc(npx * 3 * sizeof(float));
    prevr = (float *)malloc(npx * 3 * sizeof(float)); prevo = (float *)malloc(npx * 3 * sizeof(float));
    fr = (float *)malloc(npx * 3 * sizeof(float)); fo = (float *)malloc(npx * 3 * sizeof(float));
    fprintf(stderr, "%s, %ux%u, %.1f ppd, camera %.1f degrees, quality %.2f: sigma %.3f alpha %.3f gaze_angle %.4f "
            "lp_aspect %.3f\n", nm, W, H, e.ppd, (double)bi.camera.fov_y_deg, (double)q, (double)ac.sigma,
            (double)ac.alpha, (double)ac.gaze_angle, (double)ac.lp_aspect);
    fprintf(stderr, "  %-24s", "eye-filtered PSNR FLIP:");
    for (k = 0; k < ACU_NB; ++k) fprintf(stderr, " | %3.0f-%-3.0f deg ", acu_band[k], acu_band[k + 1]);
    fprintf(stderr, " || whole image\n");
    gt_image(&user, W, H, NULL, 0.0f, 16, 0, gt);
    acu_filter(&e, gt, tmp, gtf);
    gt_image(&user, W, H, NULL, 0.0f, 1, 1, img);
    acu_row(&e, "full (1 spp)", gtf, img, tmp, f);
    acu_detail(&e, "full (1 spp)", gtf, f);
    for (mode = 0; mode < 4; ++mode) {
        /* 0 lp_acuity 1 frame, 1 prefiltered, 2 lp_acuity TAA, 3 C Fov TAA */
        fovlp_config c = mode == 3 ? fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H) : ac;
        fovlp_ctx lp;
        fovlp_counts cnt;
        void *lm;
        float *smp, *sd, *cur, *cd, *hist[2], *hd[2];
        uint8_t *ag[2];
        int fi, ping = 0, n = mode >= 2 ? nfr : 1;
        double flr[ACU_NB], flo[ACU_NB], fln[ACU_NB];
        const float *out = NULL;
        char label[64];
        memset(flr, 0, sizeof flr); memset(flo, 0, sizeof flo); memset(fln, 0, sizeof fln);
        if (mode == 3) { c.display = ac.display; c.cam_fov_y_deg = bi.camera.fov_y_deg; }
        c.taa.enable = mode >= 2 ? 1u : 0u;
        fovlp_memory_size(&c, &bytes);
        lm = malloc(bytes);
        fovlp_init(&lp, &c, lm, bytes);
        smp = (float *)calloc((size_t)lp.geo.samples * 3, sizeof(float));
        sd = (float *)calloc((size_t)lp.geo.samples, sizeof(float));
        cur = (float *)malloc(npx * 3 * sizeof(float)); cd = (float *)malloc(npx * sizeof(float));
        for (k = 0; k < 2; ++k) {
            hist[k] = (float *)calloc(npx * 3, sizeof(float)); hd[k] = (float *)calloc(npx, sizeof(float));
            ag[k] = (uint8_t *)calloc(npx, 1);
        }
        for (fi = 0; fi < n; ++fi) {
            if (mode >= 2) {
                out = taa_frame(&lp, gaze, &cam, &user, smp, sd, cur, cd, hist, hd, ag, &ping);
            } else {
                fovlp_begin_frame(&lp, gaze, &cam);
                lpsdf_shade_samples(&lp, 0, fovlp_sample_rows(&lp), &user, smp, sd);
                if (mode == 1) {
                    uint32_t u, v;
                    for (v = 0; v < lp.geo.lp_h; ++v)
                        for (u = 0; u < lp.geo.lp_cols; ++u) {
                            float acc[3] = { 0, 0, 0 }, cc[3], x, y;
                            int a, b, m = 0;
                            for (a = 0; a < 4; ++a)
                                for (b = 0; b < 4; ++b) {
                                    if (fovlp_lp_to_screen(&lp, (float)u + ((float)a + 0.5f) / 4.0f,
                                                           (float)v + ((float)b + 0.5f) / 4.0f, &x, &y) != FOV_OK)
                                        continue;
                                    if (x < 0.0f || y < 0.0f || x >= (float)W || y >= (float)H) continue;
                                    lpsdf_shade(x, y, cc, NULL, &user);
                                    acc[0] += cc[0]; acc[1] += cc[1]; acc[2] += cc[2]; ++m;
                                }
                            if (m) for (a = 0; a < 3; ++a) smp[3 * ((size_t)v * lp.geo.lp_w + u) + (size_t)a] = acc[a] / (float)m;
                        }
                }
                fovlp_reconstruct_rows(&lp, smp, sd, 0, H, cur, 0, cd);
                out = cur;
            }
            if (mode == 2 && (fi == 0 || fi == 3 || fi == 7) && fi + 1 < n) {
                snprintf(label, sizeof label, "lp_acuity TAA %d", fi + 1);
                acu_row(&e, label, gtf, out, tmp, f);
            }
            if (mode >= 2 && fi >= n / 2) { /* flicker of the raw reconstruction and the output */
                acu_filter(&e, cur, tmp, fr);
                acu_filter(&e, out, tmp, fo);
                if (fi > n / 2)
                    for (i = 0; i < npx; ++i) {
                        for (k = 0; k < ACU_NB && !((double)ecc[i] < acu_band[k + 1]); ++k) {}
                        if (k == ACU_NB) continue;
                        for (int ch = 0; ch < 3; ++ch) {
                            flr[k] += fabs((double)fr[3 * i + (size_t)ch] - (double)prevr[3 * i + (size_t)ch]);
                            flo[k] += fabs((double)fo[3 * i + (size_t)ch] - (double)prevo[3 * i + (size_t)ch]);
                        }
                        fln[k] += 3.0;
                    }
                memcpy(prevr, fr, npx * 3 * sizeof(float)); memcpy(prevo, fo, npx * 3 * sizeof(float));
            }
        }
        fovlp_count_samples(&lp, &cnt);
        snprintf(label, sizeof label, "%s%s", mode == 3 ? "C Fov" : "lp_acuity",
                 mode == 0 ? " 1 frame" : (mode == 1 ? " prefiltered" : ""));
        if (mode >= 2) snprintf(label + strlen(label), sizeof label - strlen(label), " TAA %d", n);
        fprintf(stderr, "  [%s: LP %u x %u, r_G %.1f px, saving %.2fx (pixels / shaded samples)]\n", label,
                lp.geo.lp_w, lp.geo.lp_h, (double)lp.geo.r_g, 100.0 / (double)cnt.shaded_pct);
        acu_row(&e, label, gtf, out, tmp, f);
        acu_detail(&e, label, gtf, f);
        if (mode >= 2) {
            fprintf(stderr, "  %-24s flicker raw / TAA:", label);
            for (k = 0; k < ACU_NB; ++k)
                fprintf(stderr, " %.4f / %.4f", fln[k] > 0 ? flr[k] / fln[k] : 0.0, fln[k] > 0 ? flo[k] / fln[k] : 0.0);
            fprintf(stderr, "\n");
        }
        for (k = 0; k < 2; ++k) { free(hist[k]); free(hd[k]); free(ag[k]); }
        free(lm); free(smp); free(sd); free(cur); free(cd);
    }
    free(ecc); free(sig); free(gt); free(gtf); free(tmp); free(f); free(img); free(prevr); free(prevo); free(fr);
    free(fo); free(mem);
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: bench_lp [options]\n"
          "fovlp samples, speed-up and error per ring (bench/results/lp.csv), then a moving sequence\n"
          "  --full              every scene and preset at four sigmas (hours)\n"
          "  --hd                1280x720 (default 640x360)\n"
          "  --shadows           shade with soft shadows\n"
          "  --group G           the main grid's frames shade groups of G samples (foveated) or\n"
          "                      pixels (full resolution) from a shared cone head start\n"
          "                      (fovsdf_shade_points_grouped; default 8; 0: none)\n"
          "  --runs N            timing runs (default 3)\n"
          "  --frames N          frames per configuration (default 20)\n"
          "  --scenes a,b,...    scenes\n"
          "  --moving-scenes a,b scenes of the moving camera and gaze sequence (default primitives,columns)\n"
          "  --moving-frames N   frames of the moving sequence (default 12)\n"
          "  --out FILE          CSV (default bench/results/lp.csv)\n"
          "  --fovea-study       what limits the fovea's PSNR, printed\n"
          "  --acuity-study      what makes fovlp_config_acuity's periphery visible, printed\n"
          "  --quality Q         --acuity-study: the fov_eye quality knob (default 1)\n"
          "  --display D         --acuity-study: cam (default), monitor or hmd\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 640, H = 360, id;
    int study = 0, astudy = 0, adisp = 0, full = 0, runs = 3, frames = 20, a, ncfg = 0, c, shadows = 0, mframes = 12;
    uint32_t group = 8;
    const char *scenes = NULL, *outpath = "bench/results/lp.csv", *mscenes = NULL;
    char mpath[600];
    cfg_t cfgs[64];
    FILE *csv, *mcsv;
    size_t npx;
    float *gt, *gt_disp, *gtref, *gtref_disp, *full_img, *centres, *disp, *ecc, *samples, *sdep, *cur, *cdep, *hist[2], *hdep[2], *prev_t, *prev_r;
    uint8_t *age[2];
    double t_start = now_ms();
    float aq = 1.0f;

    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--full")) full = 1;
        else if (!strcmp(argv[a], "--hd")) { W = 1280; H = 720; }
        else if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--frames") && a + 1 < argc) frames = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outpath = argv[++a];
        else if (!strcmp(argv[a], "--shadows")) shadows = 1;
        else if (!strcmp(argv[a], "--group") && a + 1 < argc) {
            int g = atoi(argv[++a]);
            if (g < 0 || g > (int)FOVSDF_MAX_GROUP) { fprintf(stderr, "--group: 0 .. %u\n", (unsigned)FOVSDF_MAX_GROUP); return 2; }
            group = (uint32_t)g;
        }
        else if (!strcmp(argv[a], "--fovea-study")) study = 1;
        else if (!strcmp(argv[a], "--acuity-study")) astudy = 1;
        else if (!strcmp(argv[a], "--quality") && a + 1 < argc) aq = (float)atof(argv[++a]);
        else if (!strcmp(argv[a], "--display") && a + 1 < argc) {
            ++a;
            adisp = !strcmp(argv[a], "monitor") ? 1 : (!strcmp(argv[a], "hmd") ? 2 : (!strcmp(argv[a], "cam") ? 0 : -1));
            if (adisp < 0) { fprintf(stderr, "unknown display %s\n", argv[a]); usage(stderr); return 2; }
        }
        else if (!strcmp(argv[a], "--moving-scenes") && a + 1 < argc) mscenes = argv[++a];
        else if (!strcmp(argv[a], "--moving-frames") && a + 1 < argc) mframes = atoi(argv[++a]);
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (!scenes) scenes = full ? "primitives,columns,temple,atrium,thin,fractals" : "primitives,columns,temple,thin,fractals";
    if (!mscenes) mscenes = full ? scenes : "primitives,columns";
    if (mframes < 3) mframes = 3;
    if (astudy) {
        fovsdf_config scfg = fovsdf_config_default();
        scfg.shading = shadows ? scfg.shading : FOVSDF_SHADE_NO_SHADOWS;
        for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id)
            if (strstr(scenes, fovsdf_builtin_name(id))) acuity_study(id, &scfg, W, H, adisp, aq, frames);
        return 0;
    }
    if (study) {
        fovsdf_config scfg = fovsdf_config_default();
        scfg.shading = shadows ? scfg.shading : FOVSDF_SHADE_NO_SHADOWS;
        for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id)
            if (strstr(scenes, fovsdf_builtin_name(id))) fovea_study(id, &scfg, W, H);
        return 0;
    }
    if (runs < 1) runs = 1;
    if (runs > 15) runs = 15;
    if (frames < 4) frames = 4;
    {
        static const float preset_sigma[4] = { 0.75f, 1.0f, 1.4f, 1.3f };
        static const float mult[4] = { 0.8f, 1.0f, 1.25f, 1.5f };
        uint32_t p;
        int k;
        for (p = 0; p < 4; ++p) {
            if (full) {
                for (k = 0; k < 4; ++k) { cfgs[ncfg].preset = p; cfgs[ncfg].sigma = preset_sigma[p] * mult[k]; ncfg++; }
            } else {
                cfgs[ncfg].preset = p; cfgs[ncfg].sigma = preset_sigma[p]; ncfg++;
            }
        }
        if (!full) {
            cfgs[ncfg].preset = FOVLP_PRESET_C_FOV; cfgs[ncfg].sigma = 1.7f; ncfg++;
            cfgs[ncfg].preset = FOVLP_PRESET_C_FOV; cfgs[ncfg].sigma = 2.0f; ncfg++;
        }
    }
    npx = (size_t)W * H;
    gt = (float *)malloc(npx * 3 * sizeof(float));
    gt_disp = (float *)malloc(npx * 3 * sizeof(float));
    gtref = (float *)malloc(npx * 3 * sizeof(float));
    gtref_disp = (float *)malloc(npx * 3 * sizeof(float));
    full_img = (float *)malloc(npx * 3 * sizeof(float));
    centres = (float *)malloc(npx * 2 * sizeof(float));
    for (size_t q = 0; q < npx; ++q) {
        centres[2 * q] = (float)(q % W) + 0.5f;
        centres[2 * q + 1] = (float)(q / W) + 0.5f;
    }
    disp = (float *)malloc(npx * 3 * sizeof(float));
    ecc = (float *)malloc(npx * sizeof(float));
    cur = (float *)malloc(npx * 3 * sizeof(float));
    cdep = (float *)malloc(npx * sizeof(float));
    prev_t = (float *)malloc(npx * 3 * sizeof(float));
    prev_r = (float *)malloc(npx * 3 * sizeof(float));
    for (a = 0; a < 2; ++a) {
        hist[a] = (float *)malloc(npx * 3 * sizeof(float));
        hdep[a] = (float *)malloc(npx * sizeof(float));
        age[a] = (uint8_t *)malloc(npx);
    }
    csv = fopen(outpath, "w");
    if (!csv) { fprintf(stderr, "cannot write %s (run from the repository root)\n", outpath); return 1; }
    {
        size_t L = strlen(outpath);
        if (L > 4 && !strcmp(outpath + L - 4, ".csv")) L -= 4;
        snprintf(mpath, sizeof mpath, "%.*s_moving.csv", (int)L, outpath);
    }
    mcsv = fopen(mpath, "w");
    if (!mcsv) { fprintf(stderr, "cannot write %s\n", mpath); return 1; }
    fprintf(mcsv, "scene,mode,sigma,taa,clamp,frames,motion_px,psnr_all,flicker_all,flicker_periph,worst_ring_ratio");
    for (a = 1; a <= NRINGS; ++a) fprintf(mcsv, ",rmse_r%d", a);
    for (a = 1; a <= NRINGS; ++a) fprintf(mcsv, ",flicker_r%d", a);
    fprintf(mcsv, ",shading\n");
    fprintf(csv, "scene,mode,sigma,alpha,a_g,samples_pct,speedup,psnr_fovea,psnr_all,ssim_fovea,flicker_ratio,"
                 "psnr_fovea_1f,psnr_all_1f,ssim_fovea_1f,flicker_taa,flicker_raw,time_fov_ms,time_full_ms,lp_w,lp_h,r_g,"
                 "width,height,runs,frames,shading");
    for (a = 1; a <= NRINGS; ++a) fprintf(csv, ",rmse_r%d", a);
    for (a = 1; a <= NRINGS; ++a) fprintf(csv, ",psnr_r%d", a);
    for (a = 1; a <= NRINGS; ++a) fprintf(csv, ",ssim_r%d", a);
    fprintf(csv, ",evals_full,evals_fov,evals_px_full,evals_smp_fov,hits_pct_full,hits_pct_fov,eval_ratio,"
                 "psnr_fovea_ref,psnr_gt_fovea_ref,prims_px_full,prims_smp_fov,group");
    fprintf(csv, "\n");
    fprintf(stderr, "bench-lp: %ux%u, %d configurations per scene, median of %d runs, %d TAA frames, one thread\n", W, H,
            ncfg, runs, frames);

    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        const char *nm = fovsdf_builtin_name(id);
        fovsdf_builtin bi;
        fovsdf_config scfg = fovsdf_config_default();
        fovsdf_ctx sdf;
        size_t bytes = 0, i;
        void *mem;
        fov_gaze gaze;
        lpsdf_user user;
        double tfull[15], t_full, max_ecc = 0.0, p_gt_ref = 0.0;
        long cnt_ref = 0;
        fovm_sel fovea_all;
        fov_ecc_model em;
        if (!strstr(scenes, nm)) continue;
        if (!shadows) scfg.shading = FOVSDF_SHADE_NO_SHADOWS;
        mem = open_scene(id, W, H, &scfg, &bi, &sdf, &user, &gaze);
        /* ground truth: 16 Halton points per pixel, moved so that their mean is the pixel
           centre, box filtered */
        fprintf(stderr, "  %s: ground truth (16 spp) ...\n", nm);
        gt_image(&user, W, H, NULL, 0.0f, 16, 0, gt);
        to_disp(gt, gt_disp, npx * 3);
        /* eccentricity map (the shared model, camera field of view) */
        fovlp_ecc_init(&em, NULL, bi.camera.fov_y_deg, W, H, gaze);
        for (i = 0; i < npx; ++i) {
            ecc[i] = fovlp_ecc_deg(&em, (float)(i % W) + 0.5f, (float)(i / W) + 0.5f);
            if ((double)ecc[i] > max_ecc) max_ecc = (double)ecc[i];
        }
        /* the fovea's own reference: 256 samples per pixel (16 x 16 grid), fovea pixels only,
           to measure the 16-spp ground truth's own error there */
        fovea_all = fovm_sel_band(ecc, 0.0, 5.0);
        gt_image(&user, W, H, ecc, 5.0f, 16, 1, gtref);
        to_disp(gtref, gtref_disp, npx * 3);
        fovm_psnr_sel(gtref_disp, gt_disp, (int)W, (int)H, 3, &fovea_all, &p_gt_ref, &cnt_ref);
        user.group = group; /* the ground truths above: every ray from the camera */
        for (c = 0; c < ncfg; ++c) {
            fovlp_config lc = fovlp_config_preset(cfgs[c].preset, W, H);
            fovlp_ctx lp;
            void *lpmem;
            fovlp_counts cnt;
            fovsdf_stats st_full, st_fov;
            memset(&st_full, 0, sizeof st_full);
            memset(&st_fov, 0, sizeof st_fov);
            double p_ref = 0.0, tf[15], t_fov, fl_t = 0.0, fl_r = 0.0, pf = 0, pa = 0, sf = 0, pf1 = 0, pa1 = 0, sf1 = 0;
            long nfl = 0, cntsel;
            int f, ping = 0;
            float diag = sqrtf((float)W * (float)W + (float)H * (float)H);
            fovm_sel fov_sel = fovm_sel_band(ecc, 0.0, 5.0);
            fovm_ring rings[NRINGS];
            fovlp_camera cam;
            fovlp_camera_from(&bi.camera, &cam); /* the camera of open_scene's fovsdf_init */
            lc.sigma = cfgs[c].sigma;
            lc.cam_fov_y_deg = bi.camera.fov_y_deg;
            lc.taa.enable = 0;
            fovlp_memory_size(&lc, &bytes);
            lpmem = malloc(bytes);
            if (fovlp_init(&lp, &lc, lpmem, bytes) != FOV_OK) { fprintf(stderr, "fovlp_init failed\n"); return 1; }
            samples = (float *)malloc((size_t)lp.geo.samples * 3 * sizeof(float));
            sdep = (float *)malloc((size_t)lp.geo.samples * sizeof(float));
            /* timing, side by side: full resolution (one sample per pixel centre through the
               same shading) and a foveated frame without TAA, alternately, medians */
            for (a = 0; a < runs; ++a) {
                double t0;
                memset(&user.stats, 0, sizeof user.stats); /* deterministic counts of the first run */
                t0 = now_ms();
                if (fovsdf_shade_points_grouped(user.sdf, (uint32_t)npx, centres, 2, group, full_img, NULL, NULL,
                                                &user.stats) != FOV_OK) {
                    fprintf(stderr, "fovsdf_shade_points_grouped failed\n");
                    return 1;
                }
                tfull[a] = now_ms() - t0;
                if (a == 0) st_full = user.stats;
                memset(&user.stats, 0, sizeof user.stats);
                t0 = now_ms();
                fovlp_begin_frame(&lp, gaze, &cam);
                memset(samples, 0, (size_t)lp.geo.samples * 3 * sizeof(float));
                lpsdf_shade_samples(&lp, 0, fovlp_sample_rows(&lp), &user, samples, NULL);
                fovlp_reconstruct_rows(&lp, samples, NULL, 0, H, cur, 0, NULL);
                tf[a] = now_ms() - t0;
                if (a == 0) st_fov = user.stats;
            }
            t_fov = median(tf, runs);
            t_full = median(tfull, runs);
            fovlp_count_samples(&lp, &cnt);
            to_disp(cur, disp, npx * 3);
            fovm_psnr_sel(gt_disp, disp, (int)W, (int)H, 3, &fov_sel, &pf1, &cntsel);
            fovm_psnr(gt_disp, disp, (int)W, (int)H, 3, &pa1);
            fovm_ssim_sel(gt_disp, disp, (int)W, (int)H, 3, 0, &fov_sel, &sf1, &cntsel);
            /* TAA on a still camera: the raw jittered frames (cur) and the TAA output */
            lc.taa.enable = 1;
            fovlp_init(&lp, &lc, lpmem, bytes);
            for (f = 0; f < frames; ++f) {
                const float *o = taa_frame(&lp, gaze, &cam, &user, samples, sdep, cur, cdep, hist, hdep, age, &ping);
                for (i = 0; i < npx; ++i) {
                    float dx = (float)(i % W) + 0.5f - gaze.x, dy = (float)(i / W) + 0.5f - gaze.y;
                    if (f >= frames / 2 && dx * dx + dy * dy > diag * diag / 9.0f) {
                        int ch;
                        for (ch = 0; ch < 3; ++ch) {
                            fl_t += fabs((double)(srgb(o[3 * i + (size_t)ch]) - prev_t[3 * i + (size_t)ch]));
                            fl_r += fabs((double)(srgb(cur[3 * i + (size_t)ch]) - prev_r[3 * i + (size_t)ch]));
                        }
                        nfl += 3;
                    }
                }
                for (i = 0; i < npx * 3; ++i) { prev_t[i] = srgb(o[i]); prev_r[i] = srgb(cur[i]); }
            }
            to_disp(hist[ping], disp, npx * 3);
            fovm_psnr_sel(gt_disp, disp, (int)W, (int)H, 3, &fov_sel, &pf, &cntsel);
            fovm_psnr(gt_disp, disp, (int)W, (int)H, 3, &pa);
            fovm_ssim_sel(gt_disp, disp, (int)W, (int)H, 3, 0, &fov_sel, &sf, &cntsel);
            fovm_psnr_sel(gtref_disp, disp, (int)W, (int)H, 3, &fov_sel, &p_ref, &cntsel);
            fovm_ecc_rings(gt_disp, disp, (int)W, (int)H, 3, ecc, NRINGS, max_ecc * 1.0001, FOVM_FLIP_DEFAULT_PPD, rings);
            fprintf(csv, "%s,%s,%.3f,%.2f,%.3f,%.3f,%.4f,%.3f,%.3f,%.5f,%.5f,%.3f,%.3f,%.5f,%.6f,%.6f,%.3f,%.3f,%u,%u,%.2f,%u,%u,%d,%d,%s",
                    nm, fovlp_preset_name(cfgs[c].preset), (double)lc.sigma, (double)lc.alpha, (double)lc.gaze_angle,
                    (double)cnt.shaded_pct, t_full / t_fov, pf, pa, sf, fl_r > 0.0 ? fl_t / fl_r : 0.0, pf1, pa1, sf1,
                    nfl ? fl_t / (double)nfl : 0.0, nfl ? fl_r / (double)nfl : 0.0, t_fov, t_full, lp.geo.lp_w, lp.geo.lp_h,
                    (double)lp.geo.r_g, W, H, runs, frames, shadows ? "full" : "no_shadows");
            for (a = 0; a < NRINGS; ++a) fprintf(csv, ",%.5f", sqrt(rings[a].mse));
            for (a = 0; a < NRINGS; ++a) fprintf(csv, ",%.3f", rings[a].psnr);
            for (a = 0; a < NRINGS; ++a) fprintf(csv, ",%.5f", rings[a].ssim);
            fprintf(csv, ",%llu,%llu,%.3f,%.3f,%.2f,%.2f,%.4f,%.3f,%.3f", (unsigned long long)st_full.evals,
                    (unsigned long long)st_fov.evals, (double)st_full.evals / (double)npx,
                    (double)st_fov.evals / (double)cnt.shaded, 100.0 * (double)st_full.hits / (double)st_full.rays,
                    100.0 * (double)st_fov.hits / (double)st_fov.rays, (double)st_full.evals / (double)st_fov.evals,
                    p_ref, p_gt_ref);
            fprintf(csv, ",%.2f,%.2f,%u\n", (double)st_full.prims / (double)npx, (double)st_fov.prims / (double)cnt.shaded,
                    group);
            fflush(csv);
            fprintf(stderr, "  %s %-7s sigma %.2f: %5.1f %% samples, speed-up %.2f (ideal %.2f), fovea %.1f dB (1 frame %.1f), all %.1f dB, flicker ratio %.3f\n",
                    nm, fovlp_preset_name(cfgs[c].preset), (double)lc.sigma, (double)cnt.shaded_pct, t_full / t_fov,
                    100.0 / (double)cnt.shaded_pct, pf, pf1, pa, fl_r > 0.0 ? fl_t / fl_r : 0.0);
            free(samples);
            free(sdep);
            free(lpmem);
        }
        free(mem);
        if (strstr(mscenes, nm)) {
            fprintf(stderr, "  %s: moving camera and gaze, %d frames ...\n", nm, mframes);
            moving_seq(mcsv, id, &scfg, W, H, mframes, max_ecc, shadows ? "full" : "no_shadows");
        }
    }
    fclose(csv);
    fclose(mcsv);
    fprintf(stderr, "wrote %s (%.0f s)\n", outpath, (now_ms() - t_start) / 1000.0);

    if (system("command -v gnuplot > /dev/null 2>&1") == 0) {
        const char *slash = strrchr(outpath, '/');
        int dirlen = slash ? (int)(slash - outpath + 1) : 0;
        /* the ring plots read a transposed table written here (one block per configuration) */
        {
            FILE *in = fopen(outpath, "r");
            char line[8192];
            char rpath[600];
            if (in) {
                FILE *gp2;
                snprintf(rpath, sizeof rpath, "build/lp_rings.dat"); /* plot input, not a result */
                {
                    FILE *o = fopen(rpath, "w");
                    int row = 0;
                    if (o) {
                        if (!fgets(line, sizeof line, in)) line[0] = 0;
                        while (fgets(line, sizeof line, in)) {
                            char *tok[128];
                            int n = 0, r;
                            char *p = strtok(line, ",\n");
                            while (p && n < 128) { tok[n++] = p; p = strtok(NULL, ",\n"); }
                            if (n < 26 + 3 * NRINGS) continue;
                            fprintf(o, "\"%s sigma %s\"\n", tok[1], tok[2]);
                            for (r = 0; r < NRINGS; ++r) fprintf(o, "%d %s\n", r + 1, tok[26 + NRINGS + r]);
                            fprintf(o, "\n\n");
                            row++;
                        }
                        fclose(o);
                    }
                    (void)row;
                }
                fclose(in);
                gp2 = popen("gnuplot", "w");
                if (gp2) {
                    uint32_t s0;
                    int blk = 0;
                    for (s0 = 0; s0 < (uint32_t)_FOVSDF_SCENE_NUM; ++s0) {
                        const char *nm = fovsdf_builtin_name(s0);
                        if (!strstr(scenes, nm)) continue;
                        fprintf(gp2, "set terminal pngcairo size 900,500; set output '%.*slp_%s.png'\n", dirlen, outpath, nm);
                        fprintf(gp2, "set grid; set key outside right font ',8'\n");
                        fprintf(gp2, "set title '%s: PSNR per eccentricity ring, TAA still camera vs 16 spp (%ux%u)'\n", nm, W, H);
                        fprintf(gp2, "set xlabel 'ring (20 equal-angle rings, gaze to corner)'; set ylabel 'PSNR (dB)'\n");
                        fprintf(gp2, "plot for [i=%d:%d] '%s' index i using 1:2 with linespoints title columnheader(1)\n", blk,
                                blk + ncfg - 1, rpath);
                        blk += ncfg;
                    }
                    fprintf(gp2, "set terminal pngcairo size 800,500; set output '%.*slp_speed.png'\n", dirlen, outpath);
                    fprintf(gp2, "set datafile separator ','; set grid; set key off\n");
                    fprintf(gp2, "set title 'fovlp: wall-time speed-up against the sample ratio (same run)'\n");
                    fprintf(gp2, "set xlabel 'pixels / shaded samples'; set ylabel 'time full resolution / time foveated'\n");
                    fprintf(gp2, "plot '%s' every ::1 using (100/$6):7:(sprintf('%%s %%s %%.2f', strcol(1), strcol(2), $3)) with labels point pt 7 offset 0.5,0.5 font ',7', x with lines lc 'grey', 0.8*x with lines lc 'grey' dt 2\n", outpath);
                    /* the moving sequence: ring RMSE per TAA variant */
                    {
                        FILE *mi = fopen(mpath, "r"), *mo = fopen("build/lp_moving_rings.dat", "w");
                        int nblk = 0;
                        if (mi && mo) {
                            if (!fgets(line, sizeof line, mi)) line[0] = 0;
                            while (fgets(line, sizeof line, mi)) {
                                char *tok[64];
                                int n = 0, r;
                                char *p = strtok(line, ",\n");
                                while (p && n < 64) { tok[n++] = p; p = strtok(NULL, ",\n"); }
                                if (n < 11 + NRINGS) continue;
                                fprintf(mo, "\"%s TAA %s\"\n", tok[0], tok[4]);
                                for (r = 0; r < NRINGS; ++r) fprintf(mo, "%d %s\n", r + 1, tok[11 + r]);
                                fprintf(mo, "\n\n");
                                nblk++;
                            }
                        }
                        if (mi) fclose(mi);
                        if (mo) fclose(mo);
                        if (nblk > 0) {
                            char mpng[600];
                            snprintf(mpng, sizeof mpng, "%.*s.png", (int)(strlen(mpath) - 4), mpath);
                            fprintf(gp2, "set terminal pngcairo size 900,500; set output '%s'\n", mpng);
                            fprintf(gp2, "set datafile separator whitespace; set grid; set key outside right font ',8'\n");
                            fprintf(gp2, "set title 'fovlp C Fov, moving camera and gaze: RMSE per ring against 4 spp (%ux%u, %d frames)'\n", W, H, mframes);
                            fprintf(gp2, "set xlabel 'ring (20 equal-angle rings around the gaze)'; set ylabel 'RMSE (sRGB)'\n");
                            fprintf(gp2, "plot for [i=0:%d] 'build/lp_moving_rings.dat' index i using 1:2 with linespoints title columnheader(1)\n", nblk - 1);
                        }
                    }
                    pclose(gp2);
                    fprintf(stderr, "plots next to %s: lp_<scene>.png, lp_speed.png, %s.png\n", outpath, "lp_moving");
                }
            }
        }
    } else {
        fprintf(stderr, "gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    free(gt); free(gt_disp); free(gtref); free(gtref_disp); free(full_img); free(centres); free(disp); free(ecc); free(cur); free(cdep); free(prev_t); free(prev_r);
    for (a = 0; a < 2; ++a) { free(hist[a]); free(hdep[a]); free(age[a]); }
    return 0;
}
