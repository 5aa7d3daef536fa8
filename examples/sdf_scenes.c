/* sdf_scenes.c - the fovsdf demo: renders every built-in scene with every tracer and with the
   ground truth (classic sphere tracing with a tight epsilon), writes the images to out/, and
   prints per method the distance evaluations per pixel, the time and the error against the
   ground truth (PSNR, SSIM, FLIP, hit-mask mismatch, mean |dt|/t).

   Threads live here, never in the header: each thread renders its own row bands through
   fovsdf_render_rows and keeps its own fovsdf_stats.

   usage: sdf_scenes [--width W] [--height H] [--spp N] [--gaze X,Y] [--threads N]
                     [--scenes a,b,...] [--out DIR] [--check] [--no-images]
   --check makes it a test (exit 1 on failure): every relaxed tracer, the cone pyramid and
   the (safe, default) IPR and SKIP must match the classic tracer at the same epsilon (hit
   masks on >= 99.5% of the pixels) and be no less accurate than it (PSNR against the ground
   truth at most 0.5 dB below classic's: each tracer stops anywhere within its threshold, so
   textures on grazing surfaces slide by up to eps_px of a pixel differently in each tracer,
   and a PSNR between two tracers measures that, not their accuracy); IPR and SKIP with
   heuristic_start 1 are not checked here; FIPR and CONE_FOV must equal IPR and CONE in the inner 5 degrees
   (PSNR >= 60 dB) with hit masks within 5 % of classic's over the image, and the
   classic tracer must match the ground truth's hit mask on >= 95% of the pixels (its quarter
   pixel cone dilates sub-pixel wires, more so at small sizes) with a finite image.          */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "common.h"
#define FOVM_IMPLEMENTATION
#include "fovmetrics.h"
#include "fovrun.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct frame {
    float *rgb, *depth;
    uint8_t *hit;
    uint32_t *evals;
} frame;

static void to_display(const float *lin, float *disp, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) disp[i] = fovex_linear_to_srgb(lin[i] < 0.0f ? 0.0f : (lin[i] > 1.0f ? 1.0f : lin[i]));
}

static void save(const char *dir, const char *scene, const char *what, const float *disp, int w, int h, int png)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s_%s.%s", dir, scene, what, png ? "png" : "ppm");
    if ((png ? fovex_write_png(path, disp, w, h, 3) : fovex_write_pnm(path, disp, w, h, 3)) != 0 && png) {
        snprintf(path, sizeof path, "%s/%s_%s.ppm", dir, scene, what);
        fovex_write_pnm(path, disp, w, h, 3);
    }
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: sdf_scenes [options]\n"
          "renders every built-in scene with every fovsdf tracer and the ground truth, prints the figures\n"
          "  --width W           image width (default 640)\n"
          "  --height H          image height (default 360)\n"
          "  --spp N             samples per pixel (default 1)\n"
          "  --gaze X,Y          gaze point in pixels (default the image centre)\n"
          "  --threads N         render threads (default the number of cores)\n"
          "  --scenes a,b,...    scenes (default primitives,columns,temple,atrium,thin,fractals)\n"
          "  --out DIR           images and DIR/demo.csv (default out)\n"
          "  --check             test mode: each tracer against classic and the ground truth; exit 1 on failure\n"
          "  --no-images         write no images and no CSV\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 640, H = 360, spp = 1;
    double psnr_classic = 0.0;
    int nthreads = (int)sysconf(_SC_NPROCESSORS_ONLN), check = 0, images = 1, png, a, failures = 0, passes = 0;
    const char *outdir = "out", *scenes = "primitives,columns,temple,atrium,thin,fractals";
    float gx = -1.0f, gy = -1.0f;
    uint32_t id, m;
    FILE *csv;
    char path[512];

    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--width") && a + 1 < argc) W = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--height") && a + 1 < argc) H = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--spp") && a + 1 < argc) spp = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--threads") && a + 1 < argc) nthreads = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--gaze") && a + 1 < argc) sscanf(argv[++a], "%f,%f", &gx, &gy);
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outdir = argv[++a];
        else if (!strcmp(argv[a], "--check")) check = 1;
        else if (!strcmp(argv[a], "--no-images")) images = 0;
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (nthreads < 1) nthreads = 1;
    if (gx < 0.0f) { gx = 0.5f * (float)W; gy = 0.5f * (float)H; }
    png = fovex_have_oiiotool();
    if (images) {
        snprintf(path, sizeof path, "mkdir -p '%s'", outdir);
        if (system(path) != 0) { fprintf(stderr, "cannot create %s\n", outdir); return 1; }
    }
    snprintf(path, sizeof path, "%s/demo.csv", outdir);
    csv = images ? fopen(path, "w") : NULL;
    if (csv) fprintf(csv, "scene,method,spp,evals_per_px,primary,normal,shadow,prims_skipped_pct,time_ms,psnr,ssim,flip,hit_mismatch_pct,mean_rel_dt,psnr_fovea5\n");

    printf("fovsdf demo: %ux%u, %u spp, gaze (%.0f, %.0f), %d threads; images in %s/\n", W, H, spp, (double)gx, (double)gy,
           nthreads, images ? outdir : "(none)");
    printf("%-11s %-12s %9s %8s %8s %8s %7s %9s %8s %7s %7s %8s %9s\n", "scene", "method", "evals/px", "primary", "normal",
           "shadow", "skip%", "time ms", "psnr", "ssim", "flip", "hit mis%", "|dt|/t");
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        const char *name = fovsdf_builtin_name(id);
        size_t sz, npx = (size_t)W * H;
        void *mem;
        fovsdf_builtin bi;
        frame gt, fr;
        float *gt_disp, *disp, *ecc, *cl_disp, *ipr_disp, *cone_disp;
        uint8_t *cl_hit;
        fovsdf_output out;
        fovsdf_stats st;
        fovsdf_ctx ctx;
        fovsdf_config cfg;
        fov_gaze gaze;
        fov_result r;
        double ms;
        const char *p = strstr(scenes, name);
        if (!p || (p != scenes && p[-1] != ',') || (p[strlen(name)] != ',' && p[strlen(name)] != 0)) continue;

        fovsdf_builtin_size(id, &sz);
        mem = malloc(sz);
        r = fovsdf_builtin_init(id, &bi, mem, sz);
        if (r != FOV_OK) { fprintf(stderr, "%s: %s\n", name, fovsdf_result_string(r)); return 1; }
        bi.camera.width = W;
        bi.camera.height = H;
        gaze.x = gx; gaze.y = gy;
        gt.rgb = (float *)malloc(npx * 3 * sizeof(float)); gt.depth = (float *)malloc(npx * sizeof(float));
        gt.hit = (uint8_t *)malloc(npx); gt.evals = (uint32_t *)malloc(npx * sizeof(uint32_t));
        fr.rgb = (float *)malloc(npx * 3 * sizeof(float)); fr.depth = (float *)malloc(npx * sizeof(float));
        fr.hit = (uint8_t *)malloc(npx); fr.evals = (uint32_t *)malloc(npx * sizeof(uint32_t));
        gt_disp = (float *)malloc(npx * 3 * sizeof(float)); disp = (float *)malloc(npx * 3 * sizeof(float));
        cl_disp = (float *)malloc(npx * 3 * sizeof(float)); cl_hit = (uint8_t *)malloc(npx);
        ecc = (float *)malloc(npx * sizeof(float));
        ipr_disp = (float *)calloc(npx * 3, sizeof(float));
        cone_disp = (float *)calloc(npx * 3, sizeof(float));

        /* ground truth */
        cfg = fovsdf_config_ground_truth();
        cfg.spp = spp;
        r = fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
        if (r != FOV_OK) { fprintf(stderr, "%s: %s\n", name, fovsdf_result_string(r)); return 1; }
        {
            uint32_t x, y;
            for (y = 0; y < H; ++y)
                for (x = 0; x < W; ++x) ecc[(size_t)y * W + x] = fovsdf_ecc_deg(&ctx.ecc, (float)x + 0.5f, (float)y + 0.5f);
        }
        fovsdf_output_init(&out);
        out.rgb = gt.rgb; out.depth = gt.depth; out.hit = gt.hit; out.evals = gt.evals;
        ms = fovrun_render(&ctx, &out, nthreads, &st);
        to_display(gt.rgb, gt_disp, npx * 3);
        if (images) save(outdir, name, "gt", gt_disp, (int)W, (int)H, png);
        printf("%-11s %-12s %9.1f %8.1f %8.1f %8.1f %7.1f %9.1f %8s %7s %7s %8s %9s\n", name, "groundtruth",
               (double)st.evals / (double)npx, (double)st.evals_primary / (double)npx, (double)st.evals_normal / (double)npx,
               (double)st.evals_shadow / (double)npx, 100.0 * (double)st.prims_skipped / (double)(st.prims + st.prims_skipped + 1),
               ms, "-", "-", "-", "-", "-");

        psnr_classic = 0.0;
        for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m) {
            double psnr = 0.0, ssim = 0.0, flip = 0.0, psnr5 = 0.0, rel = 0.0;
            long mismatch = 0, nrel = 0, cnt;
            size_t i;
            fovm_sel sel5;
            cfg = fovsdf_config_default();
            cfg.method = m;
            cfg.spp = spp;
            fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
            fovsdf_output_init(&out);
            out.rgb = fr.rgb; out.depth = fr.depth; out.hit = fr.hit; out.evals = fr.evals;
            ms = fovrun_render(&ctx, &out, nthreads, &st);
            to_display(fr.rgb, disp, npx * 3);
            if (images) save(outdir, name, fovsdf_method_name(m), disp, (int)W, (int)H, png);
            if (images && m == 0) { /* the evaluation heat map of the classic tracer */
                fovsdf_config hc = cfg;
                fovsdf_stats hs;
                hc.shading = FOVSDF_SHADE_STEPS;
                fovsdf_init(&ctx, &hc, &bi.scene, &bi.camera, gaze, NULL, 0);
                out.depth = NULL; out.hit = NULL; out.evals = NULL;
                fovrun_render(&ctx, &out, nthreads, &hs);
                to_display(fr.rgb, disp, npx * 3);
                save(outdir, name, "classic_evals", disp, (int)W, (int)H, png);
                to_display(fr.rgb, disp, npx * 3);
                fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
                out.depth = fr.depth; out.hit = fr.hit; out.evals = fr.evals;
                fovrun_render(&ctx, &out, nthreads, &hs);
                to_display(fr.rgb, disp, npx * 3);
            }
            fovm_psnr(gt_disp, disp, (int)W, (int)H, 3, &psnr);
            fovm_ssim(gt_disp, disp, (int)W, (int)H, 3, &ssim, NULL);
            fovm_flip(gt_disp, disp, (int)W, (int)H, 3, FOVM_FLIP_DEFAULT_PPD, &flip, NULL);
            sel5 = fovm_sel_band(ecc, 0.0, 5.0);
            if (fovm_psnr_sel(gt_disp, disp, (int)W, (int)H, 3, &sel5, &psnr5, &cnt) != 0) psnr5 = NAN;
            for (i = 0; i < npx; ++i) {
                if (gt.hit[i] != fr.hit[i]) ++mismatch;
                else if (gt.hit[i]) { rel += fabs((double)fr.depth[i] - (double)gt.depth[i]) / (double)gt.depth[i]; ++nrel; }
            }
            rel = nrel ? rel / (double)nrel : 0.0;
            printf("%-11s %-12s %9.1f %8.1f %8.1f %8.1f %7.1f %9.1f %8.2f %7.4f %7.4f %8.3f %9.2e\n", name, fovsdf_method_name(m),
                   (double)st.evals / (double)npx, (double)st.evals_primary / (double)npx, (double)st.evals_normal / (double)npx,
                   (double)st.evals_shadow / (double)npx, 100.0 * (double)st.prims_skipped / (double)(st.prims + st.prims_skipped + 1),
                   ms, psnr, ssim, flip, 100.0 * (double)mismatch / (double)npx, rel);
            if (csv)
                fprintf(csv, "%s,%s,%u,%.3f,%.3f,%.3f,%.3f,%.2f,%.2f,%.3f,%.5f,%.5f,%.4f,%.3e,%.3f\n", name, fovsdf_method_name(m), spp,
                        (double)st.evals / (double)npx, (double)st.evals_primary / (double)npx,
                        (double)st.evals_normal / (double)npx, (double)st.evals_shadow / (double)npx,
                        100.0 * (double)st.prims_skipped / (double)(st.prims + st.prims_skipped + 1), ms, psnr, ssim, flip,
                        100.0 * (double)mismatch / (double)npx, rel, psnr5);
            if (check) {
                double ps_c = 0.0, fin = 1.0;
                long mis_c = 0;
                const char *what;
                int ok;
                for (i = 0; i < npx * 3; ++i) if (!(fr.rgb[i] - fr.rgb[i] == 0.0f)) fin = 0.0;
                if (m == 0) {
                    memcpy(cl_disp, disp, npx * 3 * sizeof(float));
                    memcpy(cl_hit, fr.hit, npx);
                    what = "vs ground truth";
                    ok = fin > 0.0 && 100.0 * (double)mismatch / (double)npx <= 5.0;
                    ps_c = psnr; mis_c = mismatch;
                    psnr_classic = psnr;
                } else {
                    for (i = 0; i < npx; ++i) mis_c += cl_hit[i] != fr.hit[i];
                    fovm_psnr(cl_disp, disp, (int)W, (int)H, 3, &ps_c);
                    what = "vs classic";
                    if (m == FOVSDF_METHOD_FIPR || m == FOVSDF_METHOD_CONE_FOV) {
                        /* foveated: inside the 7.5-degree fovea the image is that of the unfoveated
                           method (IPR, CONE), outside it is interpolated from the mid level */
                        long c5;
                        what = m == FOVSDF_METHOD_FIPR ? "vs ipr, inner 5 degrees" : "vs cone, inner 5 degrees";
                        if (fovm_psnr_sel(m == FOVSDF_METHOD_FIPR ? ipr_disp : cone_disp, disp, (int)W, (int)H, 3, &sel5, &ps_c,
                                          &c5) != 0 || c5 < 10)
                            ps_c = 0.0;
                        ok = fin > 0.0 && 100.0 * (double)mis_c / (double)npx <= 5.0 && ps_c >= 60.0;
                    } else {
                        /* as accurate as classic against the ground truth, same hit mask */
                        what = "vs classic (hits); psnr vs ground truth";
                        ps_c = psnr;
                        ok = fin > 0.0 && 100.0 * (double)mis_c / (double)npx <= 0.5 && psnr >= psnr_classic - 0.5;
                    }
                }
                if (m == FOVSDF_METHOD_IPR) memcpy(ipr_disp, disp, npx * 3 * sizeof(float));
                if (m == FOVSDF_METHOD_CONE) memcpy(cone_disp, disp, npx * 3 * sizeof(float));
                printf("%s %s %s %s: hit mismatch %.3f%%, psnr %.2f dB%s\n", ok ? "PASS" : "FAIL", name,
                       fovsdf_method_name(m), what, 100.0 * (double)mis_c / (double)npx, ps_c, fin > 0.0 ? "" : ", NON-FINITE pixels");
                if (ok) ++passes; else ++failures;
            }
        }
        free(mem); free(gt.rgb); free(gt.depth); free(gt.hit); free(gt.evals); free(fr.rgb); free(fr.depth);
        free(fr.hit); free(fr.evals); free(gt_disp); free(disp); free(ecc); free(cl_disp); free(cl_hit);
        free(ipr_disp); free(cone_disp);
    }
    if (csv) fclose(csv);
    printf("evals/px: all distance evaluations per pixel (primary rays + normals + shadow rays); skip%%: primitive\n"
           "evaluations the bounding volumes saved; time: wall clock of this run (noisy; compare ratios);\n"
           "psnr/ssim/flip: against the ground truth (classic, eps 1e-5, 0.01 pixel cone, 4096 steps).\n");
    if (check) {
        printf("%d passed, %d failed\n", passes, failures);
        return failures ? 1 : 0;
    }
    return 0;
}
