/* bench_sdf_acuity.c - fovsdf's acuity-driven foveation (fovsdf_config_acuity) against full
   resolution, at a given display geometry (make bench-sdf-acuity).

   For each built-in scene (gaze at the image centre, soft shadows, 1 spp): the ground truth
   (fovsdf_config_ground_truth), classic (full resolution, the reference) and the --methods:
     cone_fov, fipr          the fixed angles (7.5-degree fovea, mid level beyond)
     cone_fov_acuity         fovsdf_config_acuity (fovea to e_half, quarter level from
                             e_quarter, fovea-only mask, refresh 1, level filter), one row per
                             --quality (named _q<Q> when there are several)
     fipr_acuity             FIPR with fovsdf_config_acuity
     suffixes (combine them) _edges: the edge mask of Polychronakis 2025 (FOVSDF_MASK_EDGES);
                             _edges1: every edge pixel traced (p = 1); _noq: no quarter level;
                             _pt: point samples (no level filter); _rc<C>: refine_contrast C
   and prints per method: distance evaluations per pixel (all of them: head starts, sample
   rays, normals, shadow rays), the saving (classic's evaluations / the method's), the pixels
   that traced their own rays, and the error against the ground truth after both images are
   filtered to the eye's resolution: a Gaussian per pixel of standard deviation MAR(e) / 2
   (fov_eye defaults: 1 arcmin + 1.32 arcmin per degree, Guenter et al. 2012), e the pixel's
   eccentricity (separable, the pixel's own width along each pass), as PSNR of the sRGB
   values overall, in eccentricity bands (degrees) and in the regions of the first --quality
   acuity config (ePfov: its fovea, ePmid: the mid level, ePqua: the quarter level), and FLIP
   (at the display's pixels per degree) of the filtered images. Equal perceived quality: "equal", eye-filtered PSNR within
   0.5 dB of classic's in every band; "eq45", the same where classic's is below 45 dB and at
   least 45 dB elsewhere (an RMS error of 0.56 % of the sRGB range after the eye's filter);
   else "worse".

   usage: bench_sdf_acuity [--size W H] [--fovy DEG] [--monitor PITCH_MM DIST_MM]
                           [--quality Q[,Q...]] [--scenes a,b] [--threads N] [--methods a,b]
                           [--gt-spp 1|4|16] [--shading fovsdf_shading] [--dump DIR]
   The ground truth has 16 samples per pixel by default (--gt-spp): the image the eye would see
   of the scene, so point-sampling aliasing (of classic's pixels and of the interpolated
   levels alike) counts as error.
   e.g. the 27-inch 1080p monitor at 60 cm: --size 1920 1080 --fovy 31 --monitor 0.3113 600 */
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"
#include "../examples/fovrun.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *g_dump = NULL; /* --dump DIR: PPM images of every render */
static void dump(const char *scene, const char *what, const float *rgb, int w, int h);

static float srgb(float v)
{
    v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

/* One pass of the eye filter along x (dx 1) or y (dx 0): sigma per pixel in pixels. */
static void blur_pass(const float *in, float *out, int w, int h, const float *sig, int horiz)
{
    int x, y, k, c;
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            float s = sig[i], acc[3] = { 0, 0, 0 }, ws = 0.0f;
            int r = (int)ceilf(3.0f * s);
            if (s < 0.25f) {
                for (c = 0; c < 3; ++c) out[3 * i + (size_t)c] = in[3 * i + (size_t)c];
                continue;
            }
            if (r > 24) r = 24;
            for (k = -r; k <= r; ++k) {
                int xx = horiz ? x + k : x, yy = horiz ? y : y + k;
                float g;
                size_t j;
                if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
                g = expf(-0.5f * (float)(k * k) / (s * s));
                j = (size_t)yy * (size_t)w + (size_t)xx;
                for (c = 0; c < 3; ++c) acc[c] += g * in[3 * j + c];
                ws += g;
            }
            for (c = 0; c < 3; ++c) out[3 * i + c] = acc[c] / ws;
        }
}

/* linear rgb -> eye-filtered sRGB */
static void eye_filter(const float *rgb, float *out, float *tmp, int w, int h, const float *sig)
{
    size_t i, n = (size_t)w * (size_t)h * 3u;
    blur_pass(rgb, tmp, w, h, sig, 1);
    blur_pass(tmp, out, w, h, sig, 0);
    for (i = 0; i < n; ++i) out[i] = srgb(out[i]);
}

static void dump(const char *scene, const char *what, const float *rgb, int w, int h)
{
    char path[512];
    FILE *f;
    size_t i, n = (size_t)w * (size_t)h * 3u;
    if (!g_dump) return;
    snprintf(path, sizeof path, "%s/%s_%s.ppm", g_dump, scene, what);
    f = fopen(path, "wb");
    if (!f) return;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (i = 0; i < n; ++i) fputc((int)(srgb(rgb[i]) * 255.0f + 0.5f), f);
    fclose(f);
}

static void usage(FILE *f)
{
    fprintf(f, "usage: bench_sdf_acuity [--size W H] [--fovy DEG] [--monitor PITCH_MM DIST_MM]\n"
               "         [--quality Q[,Q...]] [--scenes a,b] [--threads N] [--methods a,b]\n"
               "         [--gt-spp 1|4|16] [--shading fovsdf_shading] [--dump DIR]\n"
               "  methods: cone_fov or fipr, optionally _acuity (fovsdf_config_acuity) with\n"
               "  _edges, _edges1, _noq, _pt (see the file's header); classic always runs\n");
}

#define NB 8
/* fixed bands, all, then the acuity config's (first --quality) fovea, mid and quarter regions */
static double band_lo[NB] = { 0, 5, 10, 20, 0, 0, 0, 0 }, band_hi[NB] = { 5, 10, 20, 1e9, 1e9,
                                                                           0, 0, 0 };

typedef struct res_t { double evpp, traced, psnr[NB], flip; } res_t;

int main(int argc, char **argv)
{
    int W = 640, H = 360, nthreads = 2, a, si, mi, gt_spp = 16, shading = 0;
    float fovy = 0.0f, pitch = 0.0f, dist = 0.0f, quality = 1.0f, qlist[8] = { 1.0f };
    int nq = 1, qi;
    fov_eye eye1 = { 0.0f, 0.0f, 1.0f }; /* the eye itself (quality 1), for its filter */
    const char *scenes = "primitives,columns,temple,atrium,thin,fractals";
    const char *methods = "cone_fov,cone_fov_acuity,cone_fov_acuity_edges,cone_fov_acuity_noq,"
                          "fipr_acuity";
    char mlist[512], *all[32];
    int nall = 0;
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--size") && a + 2 < argc) { W = atoi(argv[++a]); H = atoi(argv[++a]); }
        else if (!strcmp(argv[a], "--fovy") && a + 1 < argc) fovy = (float)atof(argv[++a]);
        else if (!strcmp(argv[a], "--monitor") && a + 2 < argc) {
            pitch = (float)atof(argv[++a]); dist = (float)atof(argv[++a]);
        } else if (!strcmp(argv[a], "--quality") && a + 1 < argc) {
            char *e = argv[++a];
            for (nq = 0; nq < 8 && *e;) { /* a comma-separated list */
                qlist[nq++] = (float)strtod(e, &e);
                if (*e == ',') ++e;
                else break;
            }
            quality = qlist[0];
        }
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else if (!strcmp(argv[a], "--methods") && a + 1 < argc) methods = argv[++a];
        else if (!strcmp(argv[a], "--threads") && a + 1 < argc) nthreads = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--gt-spp") && a + 1 < argc) gt_spp = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--dump") && a + 1 < argc) g_dump = argv[++a];
        else if (!strcmp(argv[a], "--shading") && a + 1 < argc) shading = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else { usage(stderr); return 2; }
    }
    /* classic first, then the listed methods: cone_fov or fipr, with _acuity (fovsdf_config_acuity)
       and its variants _edges (edge mask), _noq (no quarter level), _pt (point samples: no level
       filter) */
    snprintf(mlist, sizeof mlist, "classic,%s", methods);
    for (all[nall++] = strtok(mlist, ","); nall < 32 && (all[nall] = strtok(NULL, ",")) != NULL;)
        ++nall;
    {
        size_t npx = (size_t)W * (size_t)H;
        float *rgb = malloc(npx * 3 * sizeof(float)), *gt = malloc(npx * 3 * sizeof(float));
        float *fim = malloc(npx * 3 * sizeof(float)), *tmp = malloc(npx * 3 * sizeof(float));
        float *sig = malloc(npx * sizeof(float)), *ecc = malloc(npx * sizeof(float));
        uint8_t *mask = malloc(npx);
        fov_eye eye = { 0.0f, 0.0f, 0.0f };
        eye.quality = quality;
        for (si = 0; si < (int)_FOVSDF_SCENE_NUM; ++si) {
            fovsdf_builtin bi;
            size_t sz = 0, i;
            void *mem;
            fovsdf_config cfg;
            fovsdf_ctx ctx;
            fovsdf_output out;
            fovsdf_stats st;
            fov_gaze gaze;
            fov_eye_plan pl;
            double ev_classic = 0.0, ppd;
            res_t ref;
            if (!strstr(scenes, fovsdf_builtin_name((uint32_t)si))) continue;
            fovsdf_builtin_size((uint32_t)si, &sz);
            mem = malloc(sz);
            if (fovsdf_builtin_init((uint32_t)si, &bi, mem, sz) != FOV_OK) return 1;
            bi.camera.width = (uint32_t)W; bi.camera.height = (uint32_t)H;
            if (fovy > 0.0f) bi.camera.fov_y_deg = fovy;
            gaze.x = 0.5f * (float)W; gaze.y = 0.5f * (float)H;
            cfg = fovsdf_config_ground_truth();
            cfg.spp = (uint32_t)gt_spp;
            cfg.shading = (uint32_t)shading;
            cfg.display.pixel_pitch_mm = pitch; cfg.display.distance_mm = dist;
            if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) return 1;
            fovsdf_output_init(&out);
            out.rgb = rgb;
            fovrun_render(&ctx, &out, nthreads, &st);
            fovsdf_eye_plan(NULL, &ctx.ecc, &pl);
            ppd = (double)pl.ppd;
            for (i = 0; i < npx; ++i) {
                float e = fovsdf_ecc_deg(&ctx.ecc, (float)(i % (size_t)W) + 0.5f,
                                         (float)(i / (size_t)W) + 0.5f);
                ecc[i] = e;
                sig[i] = 0.5f * fovsdf_eye_mar(&eye1, e) * pl.ppd; /* the eye: quality 1 */
            }
            dump(bi.name, "gt", rgb, W, H);
            eye_filter(rgb, gt, tmp, W, H, sig);
            {
                fovsdf_config ca = fovsdf_config_default();
                fov_eye_plan pq;
                eye.quality = qlist[0];
                fovsdf_eye_plan(&eye, &ctx.ecc, &pq);
                ca.display = cfg.display;
                fovsdf_config_acuity(&ca, &bi.camera, &eye);
                band_lo[5] = 0.0; band_hi[5] = (double)ca.acuity.fovea_deg;
                band_lo[6] = band_hi[5];
                band_hi[6] = ca.quarter_deg > 0.0f ? (double)ca.quarter_deg : 1e9;
                band_lo[7] = band_hi[6]; band_hi[7] = 1e9;
                printf("%s %dx%d fov_y %.1f ppd %.2f: plan e_full %.2f e_half %.2f e_quarter "
                       "%.2f (quality %.2f); acuity config: fovea %.2f quarter %.2f\n",
                       bi.name, W, H, (double)bi.camera.fov_y_deg, ppd, (double)pq.e_full,
                       (double)pq.e_half, (double)pq.e_quarter, (double)quality,
                       (double)ca.acuity.fovea_deg, (double)ca.quarter_deg);
            }
            printf("  %-26s %8s %7s %7s %7s %7s %7s %7s %7s %7s %7s %7s %7s\n", "method",
                   "eval/px", "saving", "traced", "eP0-5", "eP5-10", "eP10-20", "eP20+", "ePall",
                   "ePfov", "ePmid", "ePqua", "eFLIP");
            for (mi = 0; mi < nall; ++mi)
            for (qi = 0; qi < (strstr(all[mi], "acuity") ? nq : 1); ++qi) {
                const char *m = all[mi];
                char label[64];
                res_t r;
                int b;
                long tr = 0;
                cfg = fovsdf_config_default();
                cfg.display.pixel_pitch_mm = pitch; cfg.display.distance_mm = dist;
                cfg.shading = (uint32_t)shading;
                if (!strncmp(m, "cone_fov", 8)) cfg.method = FOVSDF_METHOD_CONE_FOV;
                if (!strncmp(m, "fipr", 4)) cfg.method = FOVSDF_METHOD_FIPR;
                snprintf(label, sizeof label, "%s", m);
                if (strstr(m, "acuity")) {
                    eye.quality = qlist[qi];
                    if (nq > 1) snprintf(label, sizeof label, "%s_q%.2f", m, (double)qlist[qi]);
                    if (fovsdf_config_acuity(&cfg, &bi.camera, &eye) != FOV_OK) return 1;
                    if (strstr(m, "_edges")) cfg.fov_mask = FOVSDF_MASK_EDGES;
                    if (strstr(m, "_edges1")) { /* every edge pixel: p = 1 */
                        cfg.acuity.A = 1e-6f; cfg.acuity.C = 1.0f - 1e-6f;
                    }
                    if (strstr(m, "_noq")) cfg.quarter_deg = 0.0f;
                    if (strstr(m, "_pt")) cfg.level_filter = 0u;
                    if (strstr(m, "_rc")) cfg.refine_contrast = (float)atof(strstr(m, "_rc") + 3);
                }
                if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) {
                    fprintf(stderr, "init %s failed\n", m);
                    return 1;
                }
                fovsdf_output_init(&out);
                out.rgb = rgb; out.mask = mask;
                memset(mask, 1, npx);
                fovrun_render(&ctx, &out, nthreads, &st);
                for (i = 0; i < npx; ++i) tr += mask[i] == 1u;
                dump(bi.name, label, rgb, W, H);
                eye_filter(rgb, fim, tmp, W, H, sig);
                r.evpp = (double)st.evals / (double)npx;
                r.traced = 100.0 * (double)tr / (double)npx;
                for (b = 0; b < NB; ++b) {
                    fovm_sel sel = fovm_sel_band(ecc, band_lo[b], band_hi[b]);
                    long cnt = 0;
                    r.psnr[b] = NAN;
                    fovm_psnr_sel(gt, fim, W, H, 3, &sel, &r.psnr[b], &cnt);
                    if (cnt == 0) r.psnr[b] = NAN;
                }
                fovm_flip(gt, fim, W, H, 3, ppd, &r.flip, NULL);
                if (mi == 0) { ev_classic = r.evpp; ref = r; }
                printf("  %-26s %8.2f %7.2f %7.1f", label, r.evpp, ev_classic / r.evpp, r.traced);
                for (b = 0; b < NB; ++b) printf(" %7.2f", r.psnr[b]);
                printf(" %7.4f", r.flip);
                if (mi > 0) {
                    int eq = 1, eq45 = 1;
                    for (b = 0; b < NB; ++b) {
                        if (isnan(r.psnr[b]) || isnan(ref.psnr[b])) continue;
                        if (r.psnr[b] < ref.psnr[b] - 0.5) eq = 0;
                        if (r.psnr[b] < (ref.psnr[b] < 45.0 ? ref.psnr[b] - 0.5 : 45.0)) eq45 = 0;
                    }
                    printf("  %s", eq ? "equal" : (eq45 ? "eq45" : "worse"));
                }
                printf("\n");
                fflush(stdout);
            }
            free(mem);
        }
        free(rgb); free(gt); free(fim); free(tmp); free(sig); free(ecc); free(mask);
    }
    return 0;
}
