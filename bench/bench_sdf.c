/* bench_sdf.c - run time against error for every fovsdf method (make bench-sdf).

   For every built-in scene, method, samples per pixel and gaze position (and, for foveated
   methods, fovea size and periphery refresh): distance evaluations per pixel (deterministic,
   split by pass), wall time (median of --runs runs, every method in this one process, so the
   time ratio against classic is measured side by side), and the error against the ground truth
   (classic tracer, epsilon 1e-5, 0.01-pixel cone, 4096 steps, same spp): PSNR, SSIM, FLIP,
   hit-mask mismatch and mean |dt|/t.

   Writes bench/results/sdf.csv; the first columns are an interface other tools read:
     scene,method,spp,fovea_deg,refresh,gaze,evals_per_px,time_ms,speedup_vs_classic,psnr,ssim,
     flip,hit_mismatch_pct
   then: evals_lowres_per_px,evals_primary_per_px,evals_shading_per_px,evals_total_per_px,
     mean_rel_dt,shading,width,height,runs,psnr_e0_5,psnr_e5_10,psnr_e10_20,psnr_e20_up,
     flip_e0_5,flip_e5_10,flip_e10_20,flip_e20_up,traced_pct,psnr_vs_classic,flip_vs_classic,
     hit_mismatch_vs_classic_pct
   evals_per_px counts the evaluations that find the visible surface (head-start passes plus the
   sample rays), which is what the methods differ in; shading evaluations (normals, shadow rays)
   are reported separately (foveated methods shade fewer rays). psnr_eA_B / flip_eA_B: the error
   over the pixels between A and B degrees of eccentricity from the gaze; traced_pct: pixels
   that traced their own rays (100 but for fipr and cone_fov); *_vs_classic: against classic at
   the same spp and gaze (the same hit threshold: what an acceleration itself changes). Non-foveated methods have
   fovea_deg 0 and refresh 1. refresh is the periphery's rate relative to the fovea (1, 0.5,
   0.25): such a row renders a whole refresh cycle of 1/refresh frames of the static scene; its
   time and evaluations are per frame, its error that of the image after the cycle (equal to
   the refresh-1 image for a static scene; a moving camera would add staleness, not measured
   here). With gnuplot installed it also draws bench/results/sdf_<scene>.png (speed-up against
   PSNR).

   usage: bench_sdf [--full] [--hd] [--runs N] [--threads N] [--scenes a,b] [--shadows]
                    [--out FILE] [--plots-only] [--fov-grid]
   --plots-only: redraw the plots of FILE; --fov-grid: classic, fipr and cone_fov only, every
   fovea and refresh, 1 and 16 spp, gaze at the centre and the corner.
   Default grid (about 11 minutes on 2 cores at 640x360): every method at 1 spp with the gaze at
   the centre (fipr and cone_fov with the 7.5-degree fovea, refresh 1), classic, cone and ipr
   at 4 and 16 spp, and cone_fov at 16 spp beside classic at 16 spp. --full: every method at
   1, 4, 16 spp, gaze at the centre and at a corner (10 % of the width and height), fipr and
   cone_fov at every fovea (2.5, 5, 7.5, 10, 15 degrees) and refresh (1, 1/2, 1/4): 1332 rows,
   hours. --hd: 1920x1080. Shading without shadow rays by default (as in the thesis's IPR/FIPR
   study); --shadows adds them.
   "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
   Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025. */
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVIMG_IMPLEMENTATION
#include "../tests/common/fovimg.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"
#include "../examples/fovrun.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct job_t {
    uint32_t scene, method, spp, corner, refresh;
    float fovea;
} job_t;

static int foveated(uint32_t m) { return m == FOVSDF_METHOD_FIPR || m == FOVSDF_METHOD_CONE_FOV; }

typedef struct img_t {
    float *rgb, *disp, *depth;
    uint8_t *hit;
} img_t;

static void img_alloc(img_t *m, size_t n)
{
    m->rgb = (float *)malloc(n * 3 * sizeof(float));
    m->disp = (float *)malloc(n * 3 * sizeof(float));
    m->depth = (float *)malloc(n * sizeof(float));
    m->hit = (uint8_t *)malloc(n);
}
static void img_free(img_t *m) { free(m->rgb); free(m->disp); free(m->depth); free(m->hit); }

static void to_display(img_t *m, size_t n)
{
    size_t i;
    for (i = 0; i < n * 3; ++i) {
        float v = m->rgb[i];
        m->disp[i] = fovimg_linear_to_srgb(v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v));
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

static void progress(int done, int total, const char *what)
{
    int i, w = 30, f = total ? done * w / total : w;
    fprintf(stderr, "\r[");
    for (i = 0; i < w; ++i) fputc(i < f ? '#' : '-', stderr);
    fprintf(stderr, "] %3d/%d %-40.40s", done, total, what);
    if (done == total) fputc('\n', stderr);
    fflush(stderr);
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: bench_sdf [options]\n"
          "run time against error for every fovsdf method (bench/results/sdf.csv)\n"
          "  --full              every method, spp, gaze, fovea and refresh (hours)\n"
          "  --hd                1920x1080 (default 640x360)\n"
          "  --runs N            timing runs, median (default 5)\n"
          "  --threads N         render threads (default the number of cores)\n"
          "  --scenes a,b,...    scenes (default primitives,columns,temple,atrium,thin,fractals)\n"
          "  --shadows           shade with shadow rays\n"
          "  --out FILE          CSV (default bench/results/sdf.csv)\n"
          "  --plots-only        only redraw the plots of FILE\n"
          "  --fov-grid          classic, fipr and cone_fov at every fovea and refresh, 1 and 16 spp\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 640, H = 360;
    int plots_only = 0, fov_grid = 0, full = 0, runs = 5, nthreads = (int)sysconf(_SC_NPROCESSORS_ONLN), shadows = 0, a, njobs = 0, done = 0;
    const char *scenes = "primitives,columns,temple,atrium,thin,fractals", *outpath = "bench/results/sdf.csv";
    static job_t jobs[4096];
    const float foveas[5] = { 2.5f, 5.0f, 7.5f, 10.0f, 15.0f };
    const uint32_t refreshes[3] = { 1, 2, 4 };
    uint32_t fi, ri;
    FILE *csv;
    uint32_t id, m, s, g;
    const uint32_t spps[3] = { 1, 4, 16 };

    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--full")) full = 1;
        else if (!strcmp(argv[a], "--hd")) { W = 1920; H = 1080; }
        else if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--threads") && a + 1 < argc) nthreads = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else if (!strcmp(argv[a], "--shadows")) shadows = 1;
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outpath = argv[++a];
        else if (!strcmp(argv[a], "--plots-only")) plots_only = 1;
        else if (!strcmp(argv[a], "--fov-grid")) fov_grid = 1;
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (runs < 1) runs = 1;

    /* the grid: classic first in every (scene, spp, gaze) group, for the side-by-side ratio */
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        const char *nm = fovsdf_builtin_name(id), *p = strstr(scenes, nm);
        if (!p || (p != scenes && p[-1] != ',') || (p[strlen(nm)] != ',' && p[strlen(nm)] != 0)) continue;
        for (g = 0; g < (full || fov_grid ? 2u : 1u); ++g)
            for (s = 0; s < 3; ++s)
                for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m)
                    for (fi = 0; fi < 5; ++fi)
                        for (ri = 0; ri < 3; ++ri) {
                            /* default grid: every method at 1 spp (foveated ones at 7.5 degrees,
                               refresh 1), classic, cone and ipr at 4 and 16 spp, cone_fov at 16 spp
                               beside classic; --full: everything, foveated ones over the fovea x
                               refresh grid */
                            int def = (spps[s] == 1 || m == FOVSDF_METHOD_CLASSIC || m == FOVSDF_METHOD_CONE ||
                                       m == FOVSDF_METHOD_IPR || (m == FOVSDF_METHOD_CONE_FOV && spps[s] == 16)) &&
                                      fi == 2 && ri == 0;
                            if (!foveated(m) && (fi != 2 || ri != 0)) continue;
                            if (fov_grid) /* classic and the foveated methods over fovea x refresh, 1 and 16 spp */
                                def = spps[s] != 4 && (foveated(m) || m == FOVSDF_METHOD_CLASSIC);
                            if (!((full && !fov_grid) || def) || njobs >= 4096) continue;
                            jobs[njobs].scene = id; jobs[njobs].method = m; jobs[njobs].spp = spps[s]; jobs[njobs].corner = g;
                            jobs[njobs].fovea = foveated(m) ? foveas[fi] : 0.0f;
                            jobs[njobs].refresh = foveated(m) ? refreshes[ri] : 1u;
                            ++njobs;
                        }
    }
    if (plots_only) goto plots;
    csv = fopen(outpath, "w");
    if (!csv) { fprintf(stderr, "cannot write %s (run from the repository root)\n", outpath); return 1; }
    fprintf(csv, "scene,method,spp,fovea_deg,refresh,gaze,evals_per_px,time_ms,speedup_vs_classic,psnr,ssim,flip,hit_mismatch_pct,"
                 "evals_lowres_per_px,evals_primary_per_px,evals_shading_per_px,evals_total_per_px,mean_rel_dt,shading,width,height,runs,"
                 "psnr_e0_5,psnr_e5_10,psnr_e10_20,psnr_e20_up,flip_e0_5,flip_e5_10,flip_e10_20,flip_e20_up,traced_pct,"
                 "psnr_vs_classic,flip_vs_classic,hit_mismatch_vs_classic_pct\n");
    fprintf(stderr, "bench-sdf: %ux%u, %d configurations, median of %d runs, %d threads, %s\n", W, H, njobs, runs, nthreads,
            shadows ? "with shadows" : "no shadow rays");

    {
        size_t npx = (size_t)W * H, sz = 0;
        img_t gt, im;
        float *ecc = (float *)malloc(npx * sizeof(float)), *flipmap = (float *)malloc(npx * sizeof(float));
        uint8_t *mask = (uint8_t *)malloc(npx), *cl_hit = (uint8_t *)malloc(npx);
        float *cl_disp = (float *)malloc(npx * 3 * sizeof(float));
        void *mem = NULL;
        fovsdf_builtin bi;
        uint32_t cur_scene = 0xffffffffu, cur_spp = 0, cur_g = 2;
        double classic_ms = 0.0;
        int j;
        img_alloc(&gt, npx);
        img_alloc(&im, npx);
        for (j = 0; j < njobs; ++j) {
            const job_t *jb = &jobs[j];
            fovsdf_config cfg;
            fovsdf_ctx ctx;
            fovsdf_output out;
            fovsdf_stats st;
            fov_gaze gaze;
            double times[64], ms, psnr = 0.0, ssim = 0.0, flip = 0.0, rel = 0.0, bp[4], bf[4];
            const double edges[5] = { 0.0, 5.0, 10.0, 20.0, 1e9 };
            long mismatch = 0, nrel = 0, traced = 0, cnt, mis_cl = 0;
            double psnr_cl = 0.0, flip_cl = 0.0;
            uint64_t ev_frames = 0, ev_low = 0, ev_prim = 0, ev_shade = 0;
            size_t i;
            int r;
            char what[96];
            if (jb->scene != cur_scene) {
                free(mem);
                fovsdf_builtin_size(jb->scene, &sz);
                mem = malloc(sz);
                if (fovsdf_builtin_init(jb->scene, &bi, mem, sz) != FOV_OK) { fprintf(stderr, "scene init failed\n"); return 1; }
                bi.camera.width = W;
                bi.camera.height = H;
                cur_scene = jb->scene;
                cur_spp = 0;
            }
            gaze.x = jb->corner ? 0.1f * (float)W : 0.5f * (float)W;
            gaze.y = jb->corner ? 0.1f * (float)H : 0.5f * (float)H;
            if (jb->spp != cur_spp || jb->corner != cur_g) { /* ground truth of this group */
                snprintf(what, sizeof what, "%s ground truth %u spp", bi.name, jb->spp);
                progress(done, njobs, what);
                cfg = fovsdf_config_ground_truth();
                cfg.spp = jb->spp;
                cfg.shading = shadows ? FOVSDF_SHADE_FULL : FOVSDF_SHADE_NO_SHADOWS;
                fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
                fovsdf_output_init(&out);
                out.rgb = gt.rgb; out.depth = gt.depth; out.hit = gt.hit;
                fovrun_render(&ctx, &out, nthreads, &st);
                to_display(&gt, npx);
                for (i = 0; i < npx; ++i) ecc[i] = fovsdf_ecc_deg(&ctx.ecc, (float)(i % W) + 0.5f, (float)(i / W) + 0.5f);
                cur_spp = jb->spp;
                cur_g = jb->corner;
            }
            snprintf(what, sizeof what, "%s %s %u spp%s %g/%u", bi.name, fovsdf_method_name(jb->method), jb->spp,
                     jb->corner ? " corner" : "", (double)jb->fovea, jb->refresh);
            progress(done, njobs, what);
            cfg = fovsdf_config_default();
            cfg.method = jb->method;
            cfg.spp = jb->spp;
            cfg.shading = shadows ? FOVSDF_SHADE_FULL : FOVSDF_SHADE_NO_SHADOWS;
            if (foveated(jb->method)) { cfg.acuity.fovea_deg = jb->fovea; cfg.refresh = jb->refresh; }
            fovsdf_output_init(&out);
            out.rgb = im.rgb; out.depth = im.depth; out.hit = im.hit; out.mask = mask;
            /* a refresh cycle of `refresh` frames (static scene and gaze): the time and the
               evaluations are per frame, the error is that of the image after the cycle */
            for (r = 0; r < runs && r < 64; ++r) {
                uint32_t f;
                times[r] = 0.0;
                ev_frames = ev_low = ev_prim = ev_shade = 0;
                for (f = 0; f < cfg.refresh + (cfg.refresh == 0); ++f) {
                    cfg.frame = f;
                    if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) { fprintf(stderr, "init failed\n"); return 1; }
                    times[r] += fovrun_render(&ctx, &out, nthreads, &st);
                    ev_frames += st.evals; ev_low += st.evals_lowres; ev_prim += st.evals_primary;
                    ev_shade += st.evals_normal + st.evals_shadow;
                }
                times[r] /= (double)ctx.cfg.refresh;
            }
            for (i = 0; i < npx; ++i) traced += mask[i] == 1;
            qsort(times, (size_t)(runs < 64 ? runs : 64), sizeof times[0], cmp_double);
            ms = times[(runs < 64 ? runs : 64) / 2];
            if (jb->method == FOVSDF_METHOD_CLASSIC) classic_ms = ms;
            to_display(&im, npx);
            fovm_psnr(gt.disp, im.disp, (int)W, (int)H, 3, &psnr);
            fovm_ssim(gt.disp, im.disp, (int)W, (int)H, 3, &ssim, NULL);
            fovm_flip(gt.disp, im.disp, (int)W, (int)H, 3, FOVM_FLIP_DEFAULT_PPD, &flip, flipmap);
            for (r = 0; r < 4; ++r) { /* per eccentricity band (degrees from the gaze) */
                fovm_sel sel = fovm_sel_band(ecc, edges[r], edges[r + 1]);
                if (fovm_psnr_sel(gt.disp, im.disp, (int)W, (int)H, 3, &sel, &bp[r], &cnt) != 0 || cnt == 0) bp[r] = NAN;
                if (fovm_map_mean_sel(flipmap, (int)W, (int)H, &sel, &bf[r], &cnt) != 0 || cnt == 0) bf[r] = NAN;
            }
            if (jb->method == FOVSDF_METHOD_CLASSIC) { /* the same-threshold reference of this group */
                memcpy(cl_disp, im.disp, npx * 3 * sizeof(float));
                memcpy(cl_hit, im.hit, npx);
            }
            fovm_psnr(cl_disp, im.disp, (int)W, (int)H, 3, &psnr_cl);
            fovm_flip(cl_disp, im.disp, (int)W, (int)H, 3, FOVM_FLIP_DEFAULT_PPD, &flip_cl, NULL);
            for (i = 0; i < npx; ++i) mis_cl += cl_hit[i] != im.hit[i];
            for (i = 0; i < npx; ++i) {
                if (gt.hit[i] != im.hit[i]) ++mismatch;
                else if (gt.hit[i]) { rel += fabs((double)im.depth[i] - (double)gt.depth[i]) / (double)gt.depth[i]; ++nrel; }
            }
            {
                double fr = (double)ctx.cfg.refresh * (double)npx; /* per frame and pixel */
                fprintf(csv, "%s,%s,%u,%g,%g,%s,%.4f,%.3f,%.4f,%.4f,%.6f,%.6f,%.5f,%.4f,%.4f,%.4f,%.4f,%.4e,%s,%u,%u,%d,"
                             "%.4f,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f,%.3f,%.4f,%.6f,%.5f\n",
                        bi.name, fovsdf_method_name(jb->method), jb->spp, (double)jb->fovea, 1.0 / (double)jb->refresh,
                        jb->corner ? "corner" : "center", (double)(ev_low + ev_prim) / fr, ms,
                        classic_ms > 0.0 ? classic_ms / ms : 0.0, psnr, ssim, flip, 100.0 * (double)mismatch / (double)npx,
                        (double)ev_low / fr, (double)ev_prim / fr, (double)ev_shade / fr, (double)ev_frames / fr,
                        nrel ? rel / (double)nrel : 0.0, shadows ? "full" : "no_shadows", W, H, runs, bp[0], bp[1], bp[2], bp[3],
                        bf[0], bf[1], bf[2], bf[3], 100.0 * (double)traced / (double)npx, psnr_cl, flip_cl,
                        100.0 * (double)mis_cl / (double)npx);
            }
            fflush(csv);
            ++done;
        }
        progress(done, njobs, "done");
        free(mem);
        free(ecc); free(flipmap); free(mask); free(cl_hit); free(cl_disp);
        img_free(&gt);
        img_free(&im);
    }
    fclose(csv);
    fprintf(stderr, "wrote %s\n", outpath);

plots: /* speed-up against PSNR per scene */
    if (system("command -v gnuplot > /dev/null 2>&1") == 0) {
        FILE *gp = popen("gnuplot", "w");
        const char *slash = strrchr(outpath, '/');
        const char *dot = strrchr(outpath, '.');
        int stem = dot && (!slash || dot > slash) ? (int)(dot - outpath) : (int)strlen(outpath);
        if (gp) {
            for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
                const char *nm = fovsdf_builtin_name(id);
                if (!strstr(scenes, nm)) continue;
                /* next to the CSV, named after it: bench/results/sdf.csv -> sdf_<scene>.png */
                fprintf(gp, "set terminal pngcairo size 800,500 noenhanced; set output '%.*s_%s.png'\n", stem, outpath, nm);
                fprintf(gp, "set datafile separator ','; set key off; set grid; set logscale x 2\n");
                fprintf(gp, "set title '%s: speed-up against classic vs error (%ux%u)'\n", nm, W, H);
                fprintf(gp, "set xlabel 'time ratio classic / method (same run)'; set ylabel 'PSNR against ground truth (dB)'\n");
                fprintf(gp, "plot '%s' every ::1 using (strcol(1) eq '%s' && $9 > 0 ? $9 : 1/0):10:(sprintf('%%s %%d', strcol(2), $3)) with labels point pt 7 offset 0.3,0.4 left font ',7'\n",
                        outpath, nm);
            }
            pclose(gp);
            fprintf(stderr, "plots: %.*s_<scene>.png\n", stem, outpath);
        }
    } else {
        fprintf(stderr, "gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    return 0;
}
