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
                   pixel (Halton (2,3) points 1..16 in the pixel, box filtered), sRGB;
                   fovea = eccentricity < 5 degrees (fovlp_ecc_deg)
     flicker_ratio mean |frame-to-frame change| beyond diag/3 from the gaze, over the last
                   half of the frames, of the TAA output / of the raw jittered reconstruction
   then: psnr_fovea_1f, psnr_all_1f, ssim_fovea_1f (a single frame without TAA), flicker_taa,
   flicker_raw, time_fov_ms, time_full_ms, lp_w, lp_h, r_g, width, height, runs, frames, shading, and per
   ring (20 rings of equal eccentricity from 0 to the farthest corner, the thesis's protocol)
   rmse_rK, psnr_rK, ssim_rK for K = 1..20 (TAA output).
   Writes bench/results/lp.csv and, with gnuplot, bench/results/lp_<scene>.png (PSNR per ring)
   and bench/results/lp_speed.png (speed-up against the sample ratio).

   usage: bench_lp [--full] [--hd] [--shadows] [--runs N] [--frames N] [--scenes a,b]
                   [--out FILE]
   Default grid (640x360, shading without shadow rays as bench-sdf does; about 10 minutes on
   an idle 2-core machine): all six scenes, the four presets of Table 5.1 plus C Fov at sigma
   1.7 and 2.0 (Table 5.4). --full: every preset at sigma x {0.8, 1, 1.25, 1.5} of its own.
   --hd: 1280x720. --shadows: with soft shadows (several times slower on the lit scenes). */
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVLP_IMPLEMENTATION
#include "../fovlp.h"
#include "../examples/lp_sdf_shade.h"
#define FOVM_IMPLEMENTATION
#include "../tests/common/fovmetrics.h"

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

typedef struct cfg_t {
    uint32_t preset;
    float sigma;
} cfg_t;

int main(int argc, char **argv)
{
    uint32_t W = 640, H = 360, id;
    int full = 0, runs = 5, frames = 20, a, ncfg = 0, c, shadows = 0;
    const char *scenes = "primitives,columns,temple,atrium,thin,fractals", *outpath = "bench/results/lp.csv";
    cfg_t cfgs[64];
    FILE *csv;
    size_t npx;
    float *gt, *gt_disp, *full_img, *disp, *ecc, *samples, *sdep, *cur, *cdep, *hist[2], *hdep[2], *prev_t, *prev_r;
    uint8_t *age[2];
    double t_start = now_ms();

    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--full")) full = 1;
        else if (!strcmp(argv[a], "--hd")) { W = 1280; H = 720; }
        else if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--frames") && a + 1 < argc) frames = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outpath = argv[++a];
        else if (!strcmp(argv[a], "--shadows")) shadows = 1;
        else { fprintf(stderr, "unknown argument %s (see the comment at the top of bench_lp.c)\n", argv[a]); return 2; }
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
    full_img = (float *)malloc(npx * 3 * sizeof(float));
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
    fprintf(csv, "scene,mode,sigma,alpha,a_g,samples_pct,speedup,psnr_fovea,psnr_all,ssim_fovea,flicker_ratio,"
                 "psnr_fovea_1f,psnr_all_1f,ssim_fovea_1f,flicker_taa,flicker_raw,time_fov_ms,time_full_ms,lp_w,lp_h,r_g,"
                 "width,height,runs,frames,shading");
    for (a = 1; a <= NRINGS; ++a) fprintf(csv, ",rmse_r%d", a);
    for (a = 1; a <= NRINGS; ++a) fprintf(csv, ",psnr_r%d", a);
    for (a = 1; a <= NRINGS; ++a) fprintf(csv, ",ssim_r%d", a);
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
        double tfull[15], t_full, max_ecc = 0.0;
        fov_ecc_model em;
        uint32_t x, y, k;
        if (!strstr(scenes, nm)) continue;
        if (!shadows) scfg.shading = FOVSDF_SHADE_NO_SHADOWS;
        fovsdf_builtin_size(id, &bytes);
        mem = malloc(bytes);
        fovsdf_builtin_init(id, &bi, mem, bytes);
        bi.camera.width = W;
        bi.camera.height = H;
        gaze.x = 0.5f * (float)W;
        gaze.y = 0.5f * (float)H;
        fovsdf_init(&sdf, &scfg, &bi.scene, &bi.camera, gaze, NULL, 0);
        memset(&user, 0, sizeof user);
        user.sdf = &sdf;
        /* ground truth: 16 Halton points per pixel, box filtered */
        fprintf(stderr, "  %s: ground truth (16 spp) ...\n", nm);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float acc[3] = { 0, 0, 0 }, s[3];
                for (k = 1; k <= 16; ++k) {
                    lpsdf_shade((float)x + halton(k, 2), (float)y + halton(k, 3), s, NULL, &user);
                    acc[0] += s[0]; acc[1] += s[1]; acc[2] += s[2];
                }
                for (k = 0; k < 3; ++k) gt[3 * ((size_t)y * W + x) + k] = acc[k] / 16.0f;
            }
        to_disp(gt, gt_disp, npx * 3);
        /* eccentricity map (the shared model, camera field of view) */
        fovlp_ecc_init(&em, NULL, bi.camera.fov_y_deg, W, H, gaze);
        for (i = 0; i < npx; ++i) {
            ecc[i] = fovlp_ecc_deg(&em, (float)(i % W) + 0.5f, (float)(i / W) + 0.5f);
            if ((double)ecc[i] > max_ecc) max_ecc = (double)ecc[i];
        }
        for (c = 0; c < ncfg; ++c) {
            fovlp_config lc = fovlp_config_preset(cfgs[c].preset, W, H);
            fovlp_ctx lp;
            void *lpmem;
            fovlp_counts cnt;
            double tf[15], t_fov, fl_t = 0.0, fl_r = 0.0, pf = 0, pa = 0, sf = 0, pf1 = 0, pa1 = 0, sf1 = 0;
            long nfl = 0, cntsel;
            int f, ping = 0;
            float diag = sqrtf((float)W * (float)W + (float)H * (float)H);
            fovm_sel fov_sel = fovm_sel_band(ecc, 0.0, 5.0);
            fovm_ring rings[NRINGS];
            fovlp_camera cam = lpsdf_camera(&sdf);
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
                double t0 = now_ms();
                for (y = 0; y < H; ++y)
                    for (x = 0; x < W; ++x) lpsdf_shade((float)x + 0.5f, (float)y + 0.5f, full_img + 3 * ((size_t)y * W + x), NULL, &user);
                tfull[a] = now_ms() - t0;
                t0 = now_ms();
                fovlp_begin_frame(&lp, gaze, &cam);
                fovlp_shade_rows(&lp, 0, fovlp_sample_rows(&lp), lpsdf_shade, &user, samples, NULL, NULL);
                fovlp_reconstruct_rows(&lp, samples, NULL, 0, H, cur, 0, NULL);
                tf[a] = now_ms() - t0;
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
                fovlp_taa_io io;
                const float *o;
                fovlp_begin_frame(&lp, gaze, &cam);
                fovlp_shade_rows(&lp, 0, fovlp_sample_rows(&lp), lpsdf_shade, &user, samples, sdep, NULL);
                fovlp_reconstruct_rows(&lp, samples, sdep, 0, H, cur, 0, cdep);
                io.cur_rgb = cur; io.cur_depth = cdep;
                io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
                io.out_rgb = hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
                fovlp_taa_rows(&lp, &io, 0, H, NULL);
                ping = 1 - ping;
                o = hist[ping];
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
            fovm_ecc_rings(gt_disp, disp, (int)W, (int)H, 3, ecc, NRINGS, max_ecc * 1.0001, FOVM_FLIP_DEFAULT_PPD, rings);
            fprintf(csv, "%s,%s,%.3f,%.2f,%.3f,%.3f,%.4f,%.3f,%.3f,%.5f,%.5f,%.3f,%.3f,%.5f,%.6f,%.6f,%.3f,%.3f,%u,%u,%.2f,%u,%u,%d,%d,%s",
                    nm, fovlp_preset_name(cfgs[c].preset), (double)lc.sigma, (double)lc.alpha, (double)lc.gaze_angle,
                    (double)cnt.shaded_pct, t_full / t_fov, pf, pa, sf, fl_r > 0.0 ? fl_t / fl_r : 0.0, pf1, pa1, sf1,
                    nfl ? fl_t / (double)nfl : 0.0, nfl ? fl_r / (double)nfl : 0.0, t_fov, t_full, lp.geo.lp_w, lp.geo.lp_h,
                    (double)lp.geo.r_g, W, H, runs, frames, shadows ? "full" : "no_shadows");
            for (a = 0; a < NRINGS; ++a) fprintf(csv, ",%.5f", sqrt(rings[a].mse));
            for (a = 0; a < NRINGS; ++a) fprintf(csv, ",%.3f", rings[a].psnr);
            for (a = 0; a < NRINGS; ++a) fprintf(csv, ",%.5f", rings[a].ssim);
            fprintf(csv, "\n");
            fflush(csv);
            fprintf(stderr, "  %s %-7s sigma %.2f: %5.1f %% samples, speed-up %.2f (ideal %.2f), fovea %.1f dB (1 frame %.1f), all %.1f dB, flicker ratio %.3f\n",
                    nm, fovlp_preset_name(cfgs[c].preset), (double)lc.sigma, (double)cnt.shaded_pct, t_full / t_fov,
                    100.0 / (double)cnt.shaded_pct, pf, pf1, pa, fl_r > 0.0 ? fl_t / fl_r : 0.0);
            free(samples);
            free(sdep);
            free(lpmem);
        }
        free(mem);
    }
    fclose(csv);
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
                    pclose(gp2);
                    fprintf(stderr, "plots next to %s: lp_<scene>.png, lp_speed.png\n", outpath);
                }
            }
        }
    } else {
        fprintf(stderr, "gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    free(gt); free(gt_disp); free(full_img); free(disp); free(ecc); free(cur); free(cdep); free(prev_t); free(prev_r);
    for (a = 0; a < 2; ++a) { free(hist[a]); free(hdep[a]); free(age[a]); }
    return 0;
}
