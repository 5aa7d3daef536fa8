/* pt_acuity.c - fovpt's acuity-driven configuration (fovpt_config_acuity): what it traces and
   what its reconstruction costs the eye.

   ./build/pt_acuity --counts      camera samples per pixel and the saving against UNIFORM at
                                   the same per-sample spp (LAYERS: 4 spp, as Axblad 2020's
                                   layers; ZONES: 1) for the fixed presets and the acuity-driven
                                   configuration at three displays (below), gaze at the centre
                                   and at a quarter of the width; an empty scene (camera rays
                                   only: the counts do not depend on the scene)
   ./build/pt_acuity --recon [--scene NAME] [--w W --h H] [--ppd P] [--gt-spp N] [--spp N]
                                   the periphery's error by cause: a scene rendered by UNIFORM
                                   (spp), layers_acuity and zones_acuity (their own spp) and the
                                   same two with 64 times the samples per lattice point (almost
                                   noise free: what remains is reconstruction, the blockiness and
                                   aliasing of Catmull-Rom / Lanczos upsampling of point samples),
                                   each against a ground truth (UNIFORM, gt-spp), after both
                                   images are filtered to the eye's resolution (below); PSNR and
                                   FLIP per eccentricity band. Methods: uniform (spp),
                                   layers_acuity and zones_acuity (fovpt_config_acuity, with its
                                   B-spline reconstruction), _catmull / _lanczos (the same with
                                   the methods' own filters), _x64 (64 times the samples),
                                   _eqs (every spp times the saving: about uniform's samples)
   Build: make build/pt_acuity (or cc -O2 -I. bench/pt_acuity.c -lm -o build/pt_acuity).

   Displays of --counts: 640x360 spanning 60 degrees vertically (the camera's field of view);
   1920x1080 on a 27-inch monitor at 60 cm (pixel pitch 0.3113 mm, camera fov_y 31 degrees,
   about 33.6 px/degree at the axis); 1600x1600 over 100 degrees (a headset eye, 6.7 px/degree
   at the axis, more towards the edges of the flat image). --recon: W x H (default 480 x 270)
   with the camera's vertical field of view set so that the display has P px/degree at the axis
   (default 33.6, the monitor: the image is then the monitor's central 14 degrees).

   The eye filter (the perceptual measure of the benchmarks, fovm_eye_filter in
   examples/fovmetrics.h): both images, sRGB-encoded and clamped, are blurred in linear light
   by a Gaussian whose standard deviation at eccentricity e is sqrt(2 ln 2) / pi MAR(e) (0.375
   MAR; MAR = 1 + 1.32 e arc minutes, Guenter et al. 2012): it halves the contrast of the
   grating whose bars are MAR wide, the finest the eye resolves.
   Bands: [0, e_full), [e_full, e_half), [e_half, e_quarter), [e_quarter, inf) of the plan;
   psnr_raw_all: unfiltered, over the image; psnr_eye_all, flip_eye_all: filtered, over it.
   FLIP (Andersson et al. 2020, examples/fovmetrics.h) at the px/degree at the gaze. */
#define _POSIX_C_SOURCE 200809L
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "examples/pt_scenes.h"
#define FOVM_IMPLEMENTATION
#include "examples/fovmetrics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *f)
{
    fprintf(f, "usage: pt_acuity --counts | --recon [--scene NAME] [--w W --h H] [--ppd P]\n"
               "                 [--gt-spp N] [--spp N] [--no-x64] [--only M1,M2]\n"
               "                 [--gt-cache FILE]  (the ground truth read from / written to FILE)\n"
               "                 [--mul K1,K2,..]  (foveated spp times each K; not _x64/_eqs)\n"
               "  --counts  samples per pixel and saving of layers/zones (preset, acuity) at\n"
               "            640x360 over 60 deg, 1920x1080 27-inch at 60 cm, 1600x1600 over 100 deg\n"
               "  --recon   error by cause (noise, reconstruction) per eccentricity band after\n"
               "            an eye-resolution filter (defaults: cornell, 480x270, 33.6 px/deg,\n"
               "            gt 256 spp, spp 4)\n");
}

static void *amem(size_t n) { return malloc(n + 16u); }

/* renders cfg once (frame 0) into rgb (may be NULL: counts only); returns 0 on success */
static int render(const fovpt_scene *sc, const fovpt_camera *cam, const fovpt_config *cfg,
                  fov_gaze g, float *rgb, fovpt_stats *st)
{
    size_t n = 0;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    fov_result r;
    fovpt_stats_init(st);
    if (fovpt_memory_size(cfg, cam, &n) != FOV_OK) return -1;
    mem = amem(n);
    r = fovpt_init(&ctx, cfg, sc, cam, g, mem, n);
    if (r == FOV_OK) {
        fovpt_output_init(&out);
        out.rgb = rgb;
        r = fovpt_render(&ctx, 0, &out, st);
    }
    free(mem);
    return r == FOV_OK ? 0 : -1;
}

static void logf_(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                  void *user)
{
    (void)level; (void)user;
    fprintf(stderr, "%s %d: %s [line %u]\n", tag, (int)code, msg, (unsigned)line);
}

typedef struct disp {
    const char *name;
    uint32_t w, h;
    float fov_y, pitch, dist;
} disp;

static int counts(void)
{
    static const disp D[3] = { { "640x360_60deg", 640, 360, 60.0f, 0.0f, 0.0f },
                               { "1920x1080_27in_60cm", 1920, 1080, 31.0f, 0.3113f, 600.0f },
                               { "1600x1600_100deg", 1600, 1600, 100.0f, 0.0f, 0.0f } };
    static const char *const mname[6] = { "uniform4", "layers", "layers_acuity", "uniform1",
                                          "zones", "zones_acuity" };
    fovpt_material mat;
    fovpt_scene_desc desc;
    fovpt_scene sc;
    size_t sb = 0;
    void *smem;
    int d, m, gi;
    fovpt_material_init(&mat);
    fovpt_scene_desc_init(&desc);
    desc.materials = &mat; desc.num_materials = 1;
    if (fovpt_scene_size(&desc, &sb) != FOV_OK) return 1;
    smem = amem(sb);
    if (fovpt_scene_build(&sc, &desc, smem, sb) != FOV_OK) return 1;
    printf("display,ppd_axis,gaze,method,samples_per_px,saving,layers\n");
    for (d = 0; d < 3; ++d) {
        fovpt_camera cam;
        fov_ecc_model em;
        fov_eye_plan plan;
        fovpt_config base = fovpt_config_default();
        double base_spp[2] = { 0.0, 0.0 };
        fovpt_camera_init(&cam, D[d].w, D[d].h);
        cam.fov_y_deg = D[d].fov_y;
        base.display.pixel_pitch_mm = D[d].pitch;
        base.display.distance_mm = D[d].dist;
        base.logger.func = logf_;
        {
            fov_gaze c0 = { 0.5f * (float)D[d].w, 0.5f * (float)D[d].h };
            fovpt_ecc_init(&em, &base.display, cam.fov_y_deg, cam.width, cam.height, c0);
            fovpt_eye_plan(NULL, &em, &plan);
        }
        for (gi = 0; gi < 2; ++gi) {
            fov_gaze g = { gi ? 0.25f * (float)D[d].w : 0.5f * (float)D[d].w,
                           0.5f * (float)D[d].h };
            for (m = 0; m < 6; ++m) {
                fovpt_config c = base;
                fovpt_stats st;
                double spp, px = (double)D[d].w * D[d].h;
                char lay[256] = "";
                c.method = m == 0 || m == 3 ? FOVPT_METHOD_UNIFORM
                         : m < 3 ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_ZONES;
                c.spp = m == 0 ? 4u : 1u;
                if (m == 2 || m == 5) {
                    if (fovpt_config_acuity(&c, &cam, NULL) != FOV_OK) return 1;
                }
                if (render(&sc, &cam, &c, g, NULL, &st) != 0) return 1;
                spp = (double)st.samples / px;
                if (m == 0 || m == 3) base_spp[m == 3] = spp;
                if (m == 1 || m == 2) {
                    uint32_t n, k = 0;
                    for (n = c.layers.count; n-- > 0;)
                        k += (uint32_t)snprintf(lay + k, sizeof lay - k, "%s%.1f:%u",
                                                k ? " " : "", (double)c.layers.layer[n].radius_deg,
                                                c.layers.layer[n].stride);
                } else if (m == 4 || m == 5) {
                    snprintf(lay, sizeof lay, "inner %.2f middle %.2f",
                             (double)c.zones.inner_deg, (double)c.zones.middle_deg);
                }
                printf("%s,%.2f,%s,%s,%.4f,%.2f,%s\n", D[d].name, (double)plan.ppd,
                       gi ? "quarter" : "centre", mname[m], spp,
                       base_spp[m >= 3] / spp, lay);
            }
        }
    }
    free(smem);
    return 0;
}

/* ---- the eye filter --------------------------------------------------------------------- */
static double srgb_enc(double v)
{
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}
/* in: linear rgb; out: sRGB-encoded, clamped, then filtered to the eye's resolution
   (fovm_eye_filter, examples/fovmetrics.h) */
static int eye_filter(const float *in, float *out, int w, int h, const fovm_eye *eye)
{
    float *e = (float *)malloc(sizeof(float) * 3u * (size_t)w * (size_t)h);
    int k, r;
    for (k = 0; k < 3 * w * h; ++k) e[k] = (float)srgb_enc(in[k]);
    r = fovm_eye_filter(e, w, h, 3, eye, out);
    free(e);
    return r;
}

/* name is one of the comma-separated entries of list */
static int listed(const char *list, const char *name)
{
    size_t n = strlen(name);
    const char *p = list;
    while ((p = strstr(p, name)) != NULL) {
        if ((p == list || p[-1] == ',') && (p[n] == 0 || p[n] == ',')) return 1;
        p += n;
    }
    return 0;
}

static int recon(const char *scene_name, uint32_t W, uint32_t H, float ppd, uint32_t gt_spp,
                 uint32_t spp, int no_x64, const char *only, const char *cache,
                 const uint32_t *fmuls, int nmul)
{
    static const char *const mname[11] = { "uniform", "layers_acuity", "layers_acuity_x64",
                                           "layers_acuity_catmull", "layers_acuity_catmull_x64",
                                           "zones_acuity", "zones_acuity_x64",
                                           "zones_acuity_lanczos", "zones_acuity_lanczos_x64",
                                           "layers_acuity_eqs", "zones_acuity_eqs" };
    pt_scene S;
    int id, m, b, i, mi;
    size_t np = (size_t)W * H;
    float *gt = (float *)malloc(sizeof(float) * 3u * np), *img = (float *)malloc(sizeof(float) * 3u * np);
    float *fgt = (float *)malloc(sizeof(float) * 3u * np), *fim = (float *)malloc(sizeof(float) * 3u * np);
    float *ecc = (float *)malloc(sizeof(float) * np);
    fovm_eye eye;
    fovpt_config base = fovpt_config_default();
    fovpt_stats st;
    fov_ecc_model em;
    fov_eye_plan plan;
    fov_gaze g = { 0.5f * (float)W, 0.5f * (float)H };
    double lo[4], hi[4];
    for (id = 0; id < PT_SCENE_NUM; ++id)
        if (!strcmp(pt_scene_names[id], scene_name)) break;
    if (id == PT_SCENE_NUM) { fprintf(stderr, "unknown scene %s\n", scene_name); return 2; }
    if (pt_scene_make(&S, id) != 0) return 1;
    S.cam.width = W; S.cam.height = H;
    /* vertical field of view for ppd px/degree at the axis: f = ppd * 180 / pi */
    S.cam.fov_y_deg = (float)(2.0 * atan(0.5 * H / (ppd * 180.0 / 3.14159265358979)) * 180.0 / 3.14159265358979);
    base.logger.func = logf_;
    fovpt_ecc_init(&em, &base.display, S.cam.fov_y_deg, W, H, g);
    fovpt_eye_plan(NULL, &em, &plan);
    for (i = 0; i < (int)np; ++i) {
        float e = fovpt_ecc_deg(&em, (float)(i % (int)W) + 0.5f, (float)(i / (int)W) + 0.5f);
        ecc[i] = e;
    }
    eye = fovm_eye_from_fov((int)W, (int)H, (double)S.cam.fov_y_deg, (double)g.x, (double)g.y);
    lo[0] = 0.0; hi[0] = plan.e_full; lo[1] = plan.e_full; hi[1] = plan.e_half;
    lo[2] = plan.e_half; hi[2] = plan.e_quarter; lo[3] = plan.e_quarter; hi[3] = 1e9;
    printf("# %s %ux%u, fov_y %.2f deg, ppd %.2f, e_full %.2f e_half %.2f e_quarter %.2f, gt %u spp\n",
           scene_name, W, H, (double)S.cam.fov_y_deg, (double)plan.ppd, (double)plan.e_full,
           (double)plan.e_half, (double)plan.e_quarter, gt_spp);
    {
        fovpt_config c = base;
        c.spp = gt_spp;
        c.seed = 0x5eed6771u; /* streams no compared image uses */
        FILE *f = cache ? fopen(cache, "rb") : NULL;
        size_t got = f ? fread(gt, sizeof(float), 3u * np, f) : 0u;
        if (f) fclose(f);
        if (got != 3u * np) {
            if (render(&S.scene, &S.cam, &c, g, gt, &st) != 0) return 1;
            f = cache ? fopen(cache, "wb") : NULL;
            if (f) { fwrite(gt, sizeof(float), 3u * np, f); fclose(f); }
        }
        if (eye_filter(gt, fgt, (int)W, (int)H, &eye) != FOVM_OK) return 1;
    }
    printf("method,samples_per_px");
    for (b = 0; b < 4; ++b) printf(",psnr_b%d", b);
    for (b = 0; b < 4; ++b) printf(",flip_b%d", b);
    printf(",psnr_raw_all,psnr_eye_all,flip_eye_all\n");
    for (mi = 0; mi < nmul; ++mi)
    for (m = 0; m < 11; ++m) {
        fovpt_config c = base;
        uint32_t n, mul = (m == 2 || m == 4 || m == 6 || m == 8) ? 64u : 1u, div = mul;
        uint32_t fmul = fmuls[mi];
        double v, raw = 0.0;
        if (mul > 1u && no_x64) continue;
        if (only && !listed(only, mname[m])) continue;
        if (mi > 0 && (m == 0 || mul > 1u || m >= 9)) continue; /* once: uniform, _x64, _eqs */
        c.spp = spp;
        if (m > 0) {
            c.method = m <= 4 || m == 9 ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_ZONES;
            if (fovpt_config_acuity(&c, &S.cam, NULL) != FOV_OK) return 1;
            if (m == 3 || m == 4) c.layers.bspline = 0; /* the acuity config's B-spline off */
            if (m == 7 || m == 8) c.zones.bspline = 0;
            /* the spp per layer / zone are fovpt_config_acuity's (from the eye model, c.spp the
               reference) */
            if (mul == 1u && m < 9) mul = fmul; /* --mul: the foveated spp times K */
            if (m >= 9) { /* _eqs: every spp raised by the saving (equal samples to uniform) */
                if (render(&S.scene, &S.cam, &c, g, NULL, &st) != 0) return 1;
                mul = (uint32_t)((double)spp * (double)np / (double)st.samples);
                if (mul < 1u) mul = 1u;
            }
            for (n = 0; n < c.layers.count; ++n) c.layers.layer[n].spp *= mul;
            for (n = 0; n < 3; ++n) c.zones.spp[n] *= mul;
            c.spp = spp * mul;

        }
        if (render(&S.scene, &S.cam, &c, g, img, &st) != 0) return 1;
        {   /* unfiltered PSNR over the image, for comparison */
            float *a = (float *)malloc(sizeof(float) * 3u * np), *r = (float *)malloc(sizeof(float) * 3u * np);
            for (i = 0; i < (int)(3 * np); ++i) { a[i] = (float)srgb_enc(img[i]); r[i] = (float)srgb_enc(gt[i]); }
            fovm_psnr(r, a, (int)W, (int)H, 3, &raw);
            free(a); free(r);
        }
        if (eye_filter(img, fim, (int)W, (int)H, &eye) != FOVM_OK) return 1;
        if (fmul > 1u && m > 0 && m < 9 && mul == fmul)
            printf("%s_spp%u,%.3f", mname[m], spp * fmul, (double)st.samples / (double)np);
        else
            printf("%s,%.3f", mname[m], (double)st.samples / (double)np / (double)div);
        for (b = 0; b < 4; ++b) {
            fovm_sel sel = fovm_sel_band(ecc, lo[b], hi[b]);
            long cnt = 0;
            if (fovm_psnr_sel(fgt, fim, (int)W, (int)H, 3, &sel, &v, &cnt) != FOVM_OK || cnt == 0)
                v = NAN;
            printf(",%.2f", v);
        }
        for (b = 0; b < 4; ++b) {
            fovm_sel sel = fovm_sel_band(ecc, lo[b], hi[b]);
            long cnt = 0;
            if (fovm_flip_sel(fgt, fim, (int)W, (int)H, 3, fovm_eye_ppd(&eye), &sel, &v, &cnt) != FOVM_OK ||
                cnt == 0)
                v = NAN;
            printf(",%.4f", v);
        }
        {
            double pa = NAN, fa = NAN;
            if (fovm_psnr(fgt, fim, (int)W, (int)H, 3, &pa) != FOVM_OK) pa = NAN;
            if (fovm_flip(fgt, fim, (int)W, (int)H, 3, fovm_eye_ppd(&eye), &fa, NULL) != FOVM_OK)
                fa = NAN;
            printf(",%.2f,%.2f,%.4f\n", raw, pa, fa);
        }
        fflush(stdout);
    }
    pt_scene_free(&S);
    free(gt); free(img); free(fgt); free(fim); free(ecc);
    return 0;
}

int main(int argc, char **argv)
{
    int i, mode = 0, no_x64 = 0;
    const char *scene = "cornell", *only = NULL, *cache = NULL;
    uint32_t W = 480, H = 270, gt_spp = 256, spp = 4, fmuls[16] = { 1 };
    int nmul = 1;
    float ppd = 33.6f;
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[i], "--counts")) mode = 1;
        else if (!strcmp(argv[i], "--recon")) mode = 2;
        else if (!strcmp(argv[i], "--no-x64")) no_x64 = 1;
        else if (!strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
        else if (!strcmp(argv[i], "--gt-cache") && i + 1 < argc) cache = argv[++i];
        else if (!strcmp(argv[i], "--mul") && i + 1 < argc) {
            const char *p = argv[++i];
            nmul = 0;
            while (*p && nmul < 16) {
                fmuls[nmul++] = (uint32_t)atoi(p);
                while (*p && *p != ',') ++p;
                if (*p == ',') ++p;
            }
        }
        else if (!strcmp(argv[i], "--scene") && i + 1 < argc) scene = argv[++i];
        else if (!strcmp(argv[i], "--w") && i + 1 < argc) W = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--h") && i + 1 < argc) H = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--ppd") && i + 1 < argc) ppd = (float)atof(argv[++i]);
        else if (!strcmp(argv[i], "--gt-spp") && i + 1 < argc) gt_spp = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--spp") && i + 1 < argc) spp = (uint32_t)atoi(argv[++i]);
        else { fprintf(stderr, "unknown option %s\n", argv[i]); usage(stderr); return 2; }
    }
    if (mode == 1) return counts();
    if (mode == 2) {
        for (i = 0; i < nmul; ++i)
            if (fmuls[i] < 1u || fmuls[i] > 1024u) nmul = 0;
        if (W < 16 || H < 16 || W > 4096 || H > 4096 || !(ppd > 0.5f && ppd < 500.0f) || gt_spp < 1 ||
            spp < 1 || nmul < 1) {
            fprintf(stderr, "bad size, ppd or spp\n");
            return 2;
        }
        return recon(scene, W, H, ppd, gt_spp, spp, no_x64, only, cache, fmuls, nmul);
    }
    usage(stderr);
    return 2;
}
