/* bench_perceptual.c - the three headers' foveation at equal perceived quality
   (make bench-perceptual): bench/results/perceptual.csv.

   For three displays, gaze at the image centre:
     bench      640x360 at the scene camera's own field of view (as the other benchmarks)
     desktop27  1920x1080 on a 27-inch monitor at 60 cm (fov_display pixel_pitch_mm 0.3113,
                distance_mm 600; the camera's fov_y is the angle the screen height subtends,
                2 atan(168.1 / 600) = 31.3 degrees)
     hmd        1600x1600 per eye over 100 degrees (display and camera fov_y 100)
   every header renders its scenes with its full-resolution method, its fixed presets and its
   acuity-driven configuration (X_config_acuity) at the quality knob 0.25, 0.35, 0.5, 0.7, 1,
   1.5, 2 and 3, and
   each image is compared with a ground truth by the perceptual error of examples/fovmetrics.h:
   both images filtered to the eye's resolution at each pixel's eccentricity (fovm_eye_filter:
   a Gaussian of 0.375 MAR(e), MAR = 1 + 1.32 e arc minutes, Guenter et al. 2012) and FLIP
   (Andersson et al. 2020) of the filtered pair at the display's pixels per degree at the gaze.
     fovsdf  scenes primitives, temple (--scenes-sdf), and columns, thin with fovsdf's rows
             only (--scenes-sdf-only; not in --quick); full resolution: classic; fixed: fipr,
             cone_fov (7.5-degree fovea, mid level beyond); acuity: cone_fov_acuity (and
             fipr_acuity at quality 1). work = distance evaluations (all: head starts, sample
             rays, normals; shading without shadow rays, as bench-lp shades). Ground truth:
             fovsdf_config_ground_truth at --gt-spp samples per pixel (default 4).
     fovlp   the same scenes, shaded by fovsdf per sample (examples/lp_sdf_shade.h, as
             bench-lp); full resolution: lp_full, one shaded sample per pixel centre (the
             classic image above); fixed: lp_c_fov (C Fov, sigma 1.4), lp_fov; acuity:
             lp_acuity. One frame, no TAA. work = shaded samples (fovlp_count_samples). The
             ground truth is fovsdf's.
             lp_acuity_taa (--lp-taa N, default 16; 0: none): the same configuration with
             fovlp's TAA (taa.enable 1, the defaults: 16 Halton phases, age cap 20, no clamp)
             over N frames of a still camera and gaze; the image after frame N against the
             same ground truth. work = shaded samples per frame (the mean over the N frames),
             against lp_full's one sample per pixel per frame. N = 16 is one cycle of the
             jitter (every texel sampled at all 16 offsets; with the age cap 20 the output is
             the plain mean of the 16 frames): a user at a still view sees it after 16 frames
             (0.27 s at 60 Hz) for as long as the view stays; a moving camera jitters nothing
             (the thesis's default) and the history is clipped, so while the view moves the
             one-frame rows apply. lp_full has no TAA: with the same jitter and averaging
             full resolution also improves (--lp-study's lp_full_taaN row).
             --lp-study adds diagnostic rows: lp_full_taaN (full resolution, one sample per
             pixel per frame at the same Halton offsets, averaged over N frames),
             lp_acuity_pre (each LP sample the mean of 4 x 4 points over its texel: what
             point sampling costs; work counts one sample per texel) and the presets' TAA
             rows. --lp-recon bilinear|cubic forces cfg.recon on every fovlp row.
     fovpt   scene cornell (--scenes-pt); full resolution: uniform4 (4 spp, the layers' spp) and
             uniform1 (1 spp, the zones'); fixed: layers (6/10/20-degree radii, strides 1-4, 4
             spp), zones (7.5 / 32.5 degrees, 1 spp); acuity: layers_acuity, zones_acuity.
             work = camera samples (fovpt_stats.samples; every sample is one path).
             The acuity rows' spp are fovpt_config_acuity's (fovpt 0.5: from the eye model, with
             cfg.spp = the reference's, 4 or 1): layers_acuity_qQ / zones_acuity_qQ with
             acuity_budget 0 (each band's eye-filtered noise at the reference's);
             layers_acuity_eqt, zones_acuity_eqt: quality 1, acuity_budget 1 (the reference's
             samples spread for the least mean filtered noise: equal time, saving about 1);
             _bB: quality 1, acuity_budget B < 1 (about 1 / B the saving; --budgets).
             Ground truth: uniform at --gt-spp-pt (default 32) samples per pixel, with its own
             seed (PT_GT_SEED): the rows' random streams (seed 0) are not among its samples.
             (With seed 0 the ground truth's first 4 samples per pixel were uniform4's, which
             lowered uniform4's error by the correlation, about 12 % in noise std: every
             foveated row, whose streams differ, then looked 8-10 % worse where it was not.)
   CSV columns (the first nine are the interface of issue 13):
     header,scene,display,ppd_center,method,saving,perr,perr_ref,equal_quality,
     quality,work,work_ref,work_unit,epsnr,epsnr_ref,psnr_raw,width,height,gt_spp,ref_method
   ppd_center: the display's pixels per degree at the gaze; saving = work_ref / work (the
   full-resolution method's work over the row's); perr = the eye-filtered FLIP (lower is
   better) of the row's image against the ground truth, perr_ref that of ref_method;
   epsnr / epsnr_ref the eye-filtered PSNR (dB) of the same pairs, psnr_raw the plain PSNR of
   the row's image; quality 0 for the full-resolution and fixed rows. equal_quality is 1 when
       perr <= perr_ref + 0.001
   (the foveated image's perceptual error is at most 0.001 above the full-resolution
   method's: see bench/README.md, "Perceptual error", for the reason, a check against
   FovVideoVDP).
   Methods at other qualities are named METHOD_qQ (cone_fov_acuity_q2); METHOD alone is the
   quality 1 (matched to the eye) configuration.

   usage: bench_perceptual [--quick] [--out FILE] [--threads N] [--displays a,b]
                           [--headers sdf,lp,pt] [--scenes-sdf a,b] [--scenes-pt a,b]
                           [--gt-spp N] [--gt-spp-pt N] [--append] [--lp-taa N]
                           [--lp-study] [--lp-recon bilinear|cubic]
   --quick: the bench display and desktop27 only, qualities 0.5, 1 and 2, scene primitives,
   fovpt ground truth 16 spp. make bench-perceptual runs fovpt in a second process beside
   fovsdf and fovlp (--headers pt / --headers sdf,lp) and joins the two CSVs. */
#define _POSIX_C_SOURCE 200809L
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVLP_IMPLEMENTATION
#include "../fovlp.h"
#define FOVPT_IMPLEMENTATION
#include "../fovpt.h"
#include "../examples/lp_sdf_shade.h"
#include "../examples/pt_scenes.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"
#include "../examples/fovrun.h"
#include "../examples/common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define EQ_ABS 0.001 /* equal_quality: perr <= perr_ref + EQ_ABS */
#define PT_GT_SEED 0x5eed6771u /* fovpt ground truth: streams no row uses */

typedef struct disp_t {
    const char *name;
    uint32_t w, h;
    fov_display d;   /* the display */
    float cam_fovy;  /* the camera's fov_y; 0: the scene camera's own */
} disp_t;

static disp_t g_disps[3];
static const char *g_dump; /* --dump DIR: every image as 8-bit sRGB PPM there */
static const float g_qual_all[8] = { 0.25f, 0.35f, 0.5f, 0.7f, 1.0f, 1.5f, 2.0f, 3.0f };
static const float g_qual_quick[3] = { 0.5f, 1.0f, 2.0f };
static float g_qual_user[16];

static void disps_init(void)
{
    memset(g_disps, 0, sizeof g_disps);
    g_disps[0].name = "bench"; g_disps[0].w = 640; g_disps[0].h = 360;
    g_disps[1].name = "desktop27"; g_disps[1].w = 1920; g_disps[1].h = 1080;
    g_disps[1].d.pixel_pitch_mm = 0.3113f; g_disps[1].d.distance_mm = 600.0f;
    g_disps[1].cam_fovy = (float)(2.0 * atan(0.5 * 1080.0 * 0.3113 / 600.0) * 180.0 / 3.14159265358979);
    g_disps[2].name = "hmd"; g_disps[2].w = 1600; g_disps[2].h = 1600;
    g_disps[2].d.fov_y_deg = 100.0f; g_disps[2].cam_fovy = 100.0f;
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

static void logf_(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                  void *user)
{
    (void)level; (void)user;
    fprintf(stderr, "%s %d: %s [line %u]\n", tag, (int)code, msg, (unsigned)line);
}

/* ---- the perceptual measure against one ground truth ------------------------------------- */
#define NB 5 /* eccentricity bands of perr_bK, degrees from the gaze */
static const double g_band[NB + 1] = { 0.0, 2.0, 5.0, 10.0, 20.0, 1e9 };

typedef struct meas_t {
    int W, H;
    fovm_eye eye;
    double ppd;
    float *gt_disp, *gt_f, *disp, *filt, *map, *ecc;
    char tag[96]; /* header_scene_display, for --dump */
} meas_t;

static void dump(const meas_t *m, const char *what, const float *disp)
{
    char path[512];
    if (!g_dump) return;
    snprintf(path, sizeof path, "%s/%s_%s.ppm", g_dump, m->tag, what);
    if (fovex_write_pnm(path, disp, m->W, m->H, 3) != 0) fprintf(stderr, "cannot write %s\n", path);
}

static void to_srgb(const float *lin, float *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        double v = (double)lin[i];
        v = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
        d[i] = (float)(v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055);
    }
}

static int meas_init(meas_t *m, int W, int H, const fov_ecc_model *em, const float *gt_lin)
{
    size_t n = (size_t)W * (size_t)H * 3u, i;
    memset(m, 0, sizeof *m);
    m->W = W; m->H = H;
    m->eye.cx = em->cx; m->eye.cy = em->cy; m->eye.f_px = em->f_px;
    m->eye.gx = em->gx; m->eye.gy = em->gy;
    m->ppd = fovm_eye_ppd(&m->eye);
    m->gt_disp = (float *)malloc(n * sizeof(float)); m->gt_f = (float *)malloc(n * sizeof(float));
    m->disp = (float *)malloc(n * sizeof(float)); m->filt = (float *)malloc(n * sizeof(float));
    m->map = (float *)malloc(n / 3u * sizeof(float)); m->ecc = (float *)malloc(n / 3u * sizeof(float));
    if (!m->gt_disp || !m->gt_f || !m->disp || !m->filt || !m->map || !m->ecc) return -1;
    for (i = 0; i < n / 3u; ++i)
        m->ecc[i] = (float)fovm_eye_ecc(&m->eye, (double)(i % (size_t)W) + 0.5, (double)(i / (size_t)W) + 0.5);
    to_srgb(gt_lin, m->gt_disp, n);
    return fovm_eye_filter(m->gt_disp, W, H, 3, &m->eye, m->gt_f);
}

static void meas_free(meas_t *m)
{
    free(m->gt_disp); free(m->gt_f); free(m->disp); free(m->filt); free(m->map); free(m->ecc);
    memset(m, 0, sizeof *m);
}

typedef struct score_t { double eflip, epsnr, psnr_raw, band[NB]; } score_t;

static score_t meas_img(meas_t *m, const float *lin, const char *what)
{
    score_t s;
    size_t n = (size_t)m->W * (size_t)m->H * 3u;
    int b;
    s.eflip = s.epsnr = s.psnr_raw = NAN;
    for (b = 0; b < NB; ++b) s.band[b] = NAN;
    to_srgb(lin, m->disp, n);
    dump(m, what, m->disp);
    fovm_psnr(m->gt_disp, m->disp, m->W, m->H, 3, &s.psnr_raw);
    if (fovm_eye_filter(m->disp, m->W, m->H, 3, &m->eye, m->filt) != FOVM_OK) return s;
    fovm_psnr(m->gt_f, m->filt, m->W, m->H, 3, &s.epsnr);
    fovm_flip(m->gt_f, m->filt, m->W, m->H, 3, m->ppd, &s.eflip, m->map);
    for (b = 0; b < NB; ++b) {
        fovm_sel sel = fovm_sel_band(m->ecc, g_band[b], g_band[b + 1]);
        long cnt = 0;
        if (fovm_map_mean_sel(m->map, m->W, m->H, &sel, &s.band[b], &cnt) != FOVM_OK || cnt == 0)
            s.band[b] = NAN;
    }
    return s;
}

/* ---- CSV rows ------------------------------------------------------------------------------ */
typedef struct rowctx_t {
    FILE *csv;
    const char *header, *scene;
    const disp_t *D;
    double ppd;
    uint32_t gt_spp;
} rowctx_t;

static void method_name(char *buf, size_t n, const char *base, float q)
{
    if (q > 0.0f && fabsf(q - 1.0f) > 1e-6f) snprintf(buf, n, "%s_q%g", base, (double)q);
    else snprintf(buf, n, "%s", base);
}

static void row(const rowctx_t *rc, const char *method, float q, double work, double work_ref,
                const char *unit, score_t s, score_t ref, const char *ref_method)
{
    int eq = s.eflip <= ref.eflip + EQ_ABS, b;
    fprintf(rc->csv, "%s,%s,%s,%.2f,%s,%.3f,%.5f,%.5f,%d,%g,%.0f,%.0f,%s,%.3f,%.3f,%.3f,%u,%u,%u,%s",
            rc->header, rc->scene, rc->D->name, rc->ppd, method, work_ref / work, s.eflip, ref.eflip,
            eq, (double)q, work, work_ref, unit, s.epsnr, ref.epsnr, s.psnr_raw, rc->D->w, rc->D->h,
            rc->gt_spp, ref_method);
    for (b = 0; b < NB; ++b) fprintf(rc->csv, ",%.5f", s.band[b]);
    for (b = 0; b < NB; ++b) fprintf(rc->csv, ",%.5f", ref.band[b]);
    fprintf(rc->csv, "\n");
    fflush(rc->csv);
    fprintf(stderr, "  %-6s %-10s %-9s %-22s saving %6.2f  eFLIP %.4f (ref %.4f)  ePSNR %6.2f (ref %6.2f) bands",
            rc->header, rc->scene, rc->D->name, method, work_ref / work, s.eflip, ref.eflip, s.epsnr,
            ref.epsnr);
    for (b = 0; b < NB; ++b) fprintf(stderr, " %.4f/%.4f", s.band[b], ref.band[b]);
    fprintf(stderr, "%s\n", eq ? "  equal" : "");
}

/* ---- options ------------------------------------------------------------------------------- */
typedef struct opts_t {
    int threads;
    uint32_t gt_spp, gt_spp_pt;
    const float *qual;
    int nqual;
    float budget[16];
    int nbudget;
    const char *displays, *headers, *scenes_sdf, *scenes_pt;
    const char *scenes_sdf_only; /* --scenes-sdf-only: fovsdf's rows only (no fovlp rows) */
    const char *variants; /* --variants: cone_fov_acuity's extra rows (NULL: none) */
    int acuity_only;      /* --acuity-only: no fipr, cone_fov, fipr_acuity rows */
    int lp_taa;   /* --lp-taa N: fovlp's TAA rows after N still frames (0: none) */
    int lp_recon; /* --lp-recon bilinear|cubic: forced on every fovlp config (-1: as configured) */
    int lp_study; /* --lp-study: fovlp's diagnostic rows (prefiltered samples, full with TAA) */
} opts_t;

/* A variant of cone_fov_acuity (--variants): "rdX" refine_depth X, "rcX" refine_contrast X,
   "lfN" level_filter N, "rnX" refine_normal_deg X, "rmN" refine_material N, "nq" no quarter
   level, "pl" the fields
   as fovsdf 0.7.0's fovsdf_config_acuity set them (level filter 1, no refinement);
   parts joined by '+'. 0 when the text is not a variant. */
static int variant_apply(const char *v, size_t n, fovsdf_config *cfg)
{
    size_t i = 0;
    while (i < n) {
        char buf[32];
        size_t k = i;
        double x;
        while (k < n && v[k] != '+') ++k;
        if (k - i >= sizeof buf || k - i < 2) return 0;
        memcpy(buf, v + i, k - i); buf[k - i] = 0;
        x = atof(buf + 2);
        if (!(x >= 0.0 && x <= 1e6)) return 0; /* every part's value: a count or a threshold */
        if (!strncmp(buf, "rd", 2)) cfg->refine_depth = (float)x;
        else if (!strncmp(buf, "rc", 2)) cfg->refine_contrast = (float)x;
        else if (!strncmp(buf, "lf", 2)) cfg->level_filter = (uint32_t)x;
        else if (!strncmp(buf, "rn", 2)) cfg->refine_normal_deg = (float)x;
        else if (!strncmp(buf, "rm", 2)) cfg->refine_material = (uint32_t)x;
        else if (!strcmp(buf, "nq")) cfg->quarter_deg = 0.0f;
        else if (!strcmp(buf, "pl")) {
            cfg->refine_depth = 0.0f; cfg->refine_contrast = 0.0f; cfg->refine_normal_deg = 0.0f;
            cfg->refine_material = 0u; cfg->level_filter = 1u;
        }
        else return 0;
        i = k + 1;
    }
    return 1;
}

/* ---- fovsdf and fovlp on fovsdf's scenes ---------------------------------------------------- */
/* the LP samples of the current frame each replaced by the mean of k x k points over its
   texel (--lp-study's prefiltered rows: what point sampling costs); 0 on success */
static int lp_prefilter(const fovlp_ctx *lp, lpsdf_user *user, float *smp, uint32_t k)
{
    size_t n = 0, i, m, j;
    fovlp_sample *s;
    float *xy, *c;
    uint32_t W = lp->geo.width, H = lp->geo.height;
    int ok = 1;
    if (fovlp_samples(lp, 0, fovlp_sample_rows(lp), NULL, 0, &n) != FOV_OK) return -1;
    s = (fovlp_sample *)malloc(n * sizeof *s);
    xy = (float *)malloc(65536u * 2u * k * k * sizeof(float));
    c = (float *)malloc(65536u * 3u * k * k * sizeof(float));
    if (!s || !xy || !c || fovlp_samples(lp, 0, fovlp_sample_rows(lp), s, n, &n) != FOV_OK) ok = 0;
    for (i = 0; ok && i < n; i += 65536u) {
        size_t e = i + 65536u < n ? i + 65536u : n;
        uint32_t *cnt = (uint32_t *)calloc(e - i, sizeof(uint32_t));
        if (!cnt) { ok = 0; break; }
        m = 0;
        for (j = i; j < e; ++j) {
            uint32_t slot = s[j].slot, a, b;
            if (slot >= lp->geo.lp_slots) continue; /* disc and centre samples: pixel centres */
            for (a = 0; a < k; ++a)
                for (b = 0; b < k; ++b) {
                    float x, y;
                    if (fovlp_lp_to_screen(lp, (float)(slot % lp->geo.lp_w) + ((float)a + 0.5f) / (float)k,
                                           (float)(slot / lp->geo.lp_w) + ((float)b + 0.5f) / (float)k, &x, &y) != FOV_OK)
                        continue;
                    if (!(x >= 0.0f && y >= 0.0f && x < (float)W && y < (float)H)) continue;
                    xy[2 * m] = x; xy[2 * m + 1] = y; ++m; ++cnt[j - i];
                }
        }
        if (m && fovsdf_shade_points_grouped(user->sdf, (uint32_t)m, xy, 2, 0, c, NULL, NULL, &user->stats) != FOV_OK) ok = 0;
        m = 0;
        for (j = i; ok && j < e; ++j) {
            uint32_t q, slot = s[j].slot;
            float acc[3] = { 0.0f, 0.0f, 0.0f };
            if (!cnt[j - i]) continue;
            for (q = 0; q < cnt[j - i]; ++q, ++m) { acc[0] += c[3 * m]; acc[1] += c[3 * m + 1]; acc[2] += c[3 * m + 2]; }
            for (q = 0; q < 3; ++q) smp[3 * (size_t)slot + q] = acc[q] / (float)cnt[j - i];
        }
        free(cnt);
    }
    free(s); free(xy); free(c);
    return ok ? 0 : -1;
}

/* one fovlp frame of config c (gaze, camera still): mode 0 point samples, 1 prefiltered
   samples (4 x 4 per texel), 2 TAA over nfr still frames (the library's jitter and history;
   the image after the last frame). The image in img; the shaded samples per frame (mean over
   the frames) in *work. 0 on success. */
static int lp_render(const fovlp_config *c0, int mode, int nfr, fov_gaze gaze, const fovlp_camera *lcam,
                     lpsdf_user *user, float *img, double *work)
{
    fovlp_config c = *c0;
    fovlp_ctx lp;
    fovlp_counts cnt;
    size_t bytes = 0, npx = (size_t)c.width * c.height;
    void *mem;
    float *smp, *sd, *cd, *hist[2] = { NULL, NULL }, *hd[2] = { NULL, NULL };
    uint8_t *ag[2] = { NULL, NULL };
    int fi, ping = 0, k, ok = 1;
    double sum = 0.0;
    c.taa.enable = mode == 2 ? 1u : 0u;
    if (mode != 2) nfr = 1;
    if (fovlp_memory_size(&c, &bytes) != FOV_OK) return -1;
    mem = malloc(bytes);
    if (!mem || fovlp_init(&lp, &c, mem, bytes) != FOV_OK) { free(mem); return -1; }
    smp = (float *)calloc((size_t)lp.geo.samples * 3, sizeof(float));
    sd = (float *)calloc((size_t)lp.geo.samples, sizeof(float));
    cd = (float *)malloc(npx * sizeof(float));
    if (mode == 2)
        for (k = 0; k < 2; ++k) {
            hist[k] = (float *)calloc(npx * 3, sizeof(float)); hd[k] = (float *)calloc(npx, sizeof(float));
            ag[k] = (uint8_t *)calloc(npx, 1);
            if (!hist[k] || !hd[k] || !ag[k]) ok = 0;
        }
    if (!smp || !sd || !cd) ok = 0;
    for (fi = 0; ok && fi < nfr; ++fi) {
        fovlp_taa_io io;
        fovlp_begin_frame(&lp, gaze, lcam);
        if (lpsdf_shade_samples(&lp, 0, fovlp_sample_rows(&lp), user, smp, sd) != 0) ok = 0;
        if (ok && mode == 1 && lp_prefilter(&lp, user, smp, 4u) != 0) ok = 0;
        fovlp_count_samples(&lp, &cnt);
        sum += (double)cnt.shaded;
        if (!ok) break;
        if (mode != 2) { fovlp_reconstruct_rows(&lp, smp, sd, 0, c.height, img, 0, cd); break; }
        fovlp_reconstruct_rows(&lp, smp, sd, 0, c.height, img, 0, cd);
        fovlp_taa_io_init(&io);
        io.cur_rgb = img; io.cur_depth = cd;
        io.prev_rgb = hist[ping]; io.prev_depth = hd[ping]; io.prev_age = ag[ping];
        io.out_rgb = hist[1 - ping]; io.out_depth = hd[1 - ping]; io.out_age = ag[1 - ping];
        if (fovlp_taa_rows(&lp, &io, 0, c.height, NULL) != FOV_OK) ok = 0;
        ping = 1 - ping;
    }
    if (ok && mode == 2) memcpy(img, hist[ping], npx * 3 * sizeof(float));
    *work = sum / (double)(fi < nfr ? fi + 1 : nfr);
    for (k = 0; k < 2; ++k) { free(hist[k]); free(hd[k]); free(ag[k]); }
    free(smp); free(sd); free(cd); free(mem);
    return ok ? 0 : -1;
}

/* full resolution with the same jitter and averaging as TAA over nfr still frames (one
   sample per pixel per frame at the Halton (2, 3) points fovlp uses, averaged: what TAA gives
   the full-resolution method; --lp-study) */
static void full_taa(lpsdf_user *user, uint32_t W, uint32_t H, int nfr, float *img)
{
    float *xy = (float *)malloc((size_t)W * 2 * sizeof(float)), *c = (float *)malloc((size_t)W * 3 * sizeof(float));
    uint32_t x, y;
    int f;
    memset(img, 0, (size_t)W * H * 3 * sizeof(float));
    for (f = 0; f < nfr; ++f) {
        float jx = 0.0f, jy = 0.0f, inv;
        uint32_t i, b;
        for (i = (uint32_t)(f % 16) + 1, inv = 0.5f; i; i /= 2, inv *= 0.5f) jx += inv * (float)(i % 2);
        for (i = (uint32_t)(f % 16) + 1, inv = 1.0f / 3.0f; i; i /= 3, inv /= 3.0f) jy += inv * (float)(i % 3);
        for (y = 0; y < H; ++y) {
            for (x = 0; x < W; ++x) { xy[2 * x] = (float)x + jx; xy[2 * x + 1] = (float)y + jy; }
            fovsdf_shade_points_grouped(user->sdf, W, xy, 2, 0, c, NULL, NULL, &user->stats);
            for (b = 0; b < 3 * W; ++b) img[3 * (size_t)y * W + b] += c[b] / (float)nfr;
        }
    }
    free(xy); free(c);
}

static void lp_rows(const rowctx_t *rc0, const opts_t *o, fovsdf_builtin *bi, const fovsdf_config *shade_cfg,
                    fov_gaze gaze, meas_t *m, score_t full, float *img)
{
    rowctx_t rc = *rc0;
    fovsdf_ctx sdf;
    lpsdf_user user;
    fovlp_camera lcam;
    uint32_t W = rc.D->w, H = rc.D->h;
    size_t npx = (size_t)W * H;
    double work_ref = (double)npx;
    int k, nk = 2 + o->nqual;
    rc.header = "fovlp";
    if (fovsdf_init(&sdf, shade_cfg, &bi->scene, &bi->camera, gaze, NULL, 0) != FOV_OK) return;
    memset(&user, 0, sizeof user);
    user.sdf = &sdf;
    fovlp_camera_from(&bi->camera, &lcam);
    row(&rc, "lp_full", 0.0f, work_ref, work_ref, "samples", full, full, "lp_full");
    if (o->lp_study && o->lp_taa > 0) {
        char name[64];
        full_taa(&user, W, H, o->lp_taa, img);
        snprintf(name, sizeof name, "lp_full_taa%d", o->lp_taa);
        row(&rc, name, 0.0f, work_ref, work_ref, "samples", meas_img(m, img, name), full, "lp_full");
    }
    for (k = 0; k < nk; ++k) {
        fovlp_config c;
        float q = k >= 2 ? o->qual[k - 2] : 0.0f;
        char name[64], base[24];
        double work;
        int mode;
        fov_result r;
        if (k < 2) {
            c = fovlp_config_preset(k == 0 ? FOVLP_PRESET_C_FOV : FOVLP_PRESET_FOV, W, H);
            c.display = rc.D->d;
            c.cam_fov_y_deg = bi->camera.fov_y_deg;
            snprintf(base, sizeof base, "%s", k == 0 ? "lp_c_fov" : "lp_fov");
        } else {
            fov_eye eye;
            memset(&eye, 0, sizeof eye);
            eye.quality = q;
            c = fovlp_config_default();
            c.width = W; c.height = H;
            c.display = rc.D->d;
            c.cam_fov_y_deg = bi->camera.fov_y_deg;
            c.logger.func = logf_;
            if ((r = fovlp_config_acuity(&c, &lcam, &eye)) != FOV_OK) {
                fprintf(stderr, "  fovlp_config_acuity (quality %g): %s\n", (double)q, fovlp_result_string(r));
                continue;
            }
            snprintf(base, sizeof base, "lp_acuity");
        }
        c.logger.func = logf_;
        if (o->lp_recon >= 0) c.recon = (uint32_t)o->lp_recon;
        /* 0 one frame of point samples; 1 prefiltered (--lp-study); 2 TAA after --lp-taa frames */
        for (mode = 0; mode < 3; ++mode) {
            char b2[40];
            if (mode == 1 && !(o->lp_study && k >= 2)) continue;
            if (mode == 2 && !(o->lp_taa > 0 && (k >= 2 || o->lp_study))) continue;
            snprintf(b2, sizeof b2, "%s%s", base, mode == 1 ? "_pre" : (mode == 2 ? "_taa" : ""));
            method_name(name, sizeof name, b2, q);
            if (lp_render(&c, mode, o->lp_taa, gaze, &lcam, &user, img, &work) != 0) continue;
            row(&rc, name, q, work, work_ref, "samples", meas_img(m, img, name), full, "lp_full");
        }
    }
}

static void sdf_scene(FILE *csv, const opts_t *o, const disp_t *D, uint32_t id, int sdf_only)
{
    fovsdf_builtin bi;
    size_t bytes = 0, npx = (size_t)D->w * D->h;
    void *mem;
    fovsdf_config cfg, shade_cfg;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats st;
    fov_gaze gaze;
    fov_ecc_model em;
    meas_t m;
    rowctx_t rc;
    score_t full;
    double work_ref;
    float *img = (float *)malloc(npx * 3 * sizeof(float));
    int k, nk;
    fovsdf_builtin_size(id, &bytes);
    mem = malloc(bytes);
    if (!img || !mem || fovsdf_builtin_init(id, &bi, mem, bytes) != FOV_OK) { free(img); free(mem); return; }
    bi.camera.width = D->w; bi.camera.height = D->h;
    if (D->cam_fovy > 0.0f) bi.camera.fov_y_deg = D->cam_fovy;
    gaze.x = 0.5f * (float)D->w; gaze.y = 0.5f * (float)D->h;
    if (fovsdf_ecc_init(&em, &D->d, bi.camera.fov_y_deg, D->w, D->h, gaze) != FOV_OK) { free(img); free(mem); return; }
    /* ground truth */
    cfg = fovsdf_config_ground_truth();
    cfg.spp = o->gt_spp;
    cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
    cfg.display = D->d;
    cfg.logger.func = logf_;
    fprintf(stderr, "fovsdf %s %s %ux%u: ground truth %u spp\n", bi.name, D->name, D->w, D->h, o->gt_spp);
    if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) { free(img); free(mem); return; }
    fovsdf_output_init(&out);
    out.rgb = img;
    fovrun_render(&ctx, &out, o->threads, &st);
    if (meas_init(&m, (int)D->w, (int)D->h, &em, img) != 0) { meas_free(&m); free(img); free(mem); return; }
    snprintf(m.tag, sizeof m.tag, "sdf_%s_%s", bi.name, D->name);
    dump(&m, "gt", m.gt_disp);
    rc.csv = csv; rc.header = "fovsdf"; rc.scene = bi.name; rc.D = D; rc.ppd = m.ppd; rc.gt_spp = o->gt_spp;
    /* full resolution: classic */
    shade_cfg = fovsdf_config_default();
    shade_cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
    shade_cfg.display = D->d;
    shade_cfg.logger.func = logf_;
    cfg = shade_cfg;
    cfg.method = FOVSDF_METHOD_CLASSIC;
    fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
    fovrun_render(&ctx, &out, o->threads, &st);
    work_ref = (double)st.evals;
    full = meas_img(&m, img, "classic");
    if (listed(o->headers, "sdf")) row(&rc, "classic", 0.0f, work_ref, work_ref, "evaluations", full, full, "classic");
    nk = 3 + o->nqual;
    for (k = o->acuity_only ? 3 : 0; k < nk && listed(o->headers, "sdf"); ++k) {
        /* 0 fipr, 1 cone_fov (fixed), 2 fipr_acuity (quality 1), 3.. cone_fov_acuity */
        float q = k == 2 ? 1.0f : (k >= 3 ? o->qual[k - 3] : 0.0f);
        char name[128];
        cfg = shade_cfg;
        cfg.method = (k == 0 || k == 2) ? FOVSDF_METHOD_FIPR : FOVSDF_METHOD_CONE_FOV;
        if (k >= 2) {
            fov_eye eye;
            fov_result r;
            memset(&eye, 0, sizeof eye);
            eye.quality = q;
            if ((r = fovsdf_config_acuity(&cfg, &bi.camera, &eye)) != FOV_OK) {
                fprintf(stderr, "  fovsdf_config_acuity (quality %g): %s\n", (double)q, fovsdf_result_string(r));
                continue;
            }
            method_name(name, sizeof name, k == 2 ? "fipr_acuity" : "cone_fov_acuity", q);
        } else {
            snprintf(name, sizeof name, "%s", k == 0 ? "fipr" : "cone_fov");
        }
        if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) continue;
        fovrun_render(&ctx, &out, o->threads, &st);
        row(&rc, name, q, (double)st.evals, work_ref, "evaluations", meas_img(&m, img, name), full, "classic");
        if (k >= 3 && o->variants) { /* the variants at this quality */
            const char *v = o->variants;
            fovsdf_config acfg = cfg;
            while (*v) {
                size_t n = strcspn(v, ",");
                char base[64];
                cfg = acfg;
                if (n > 0 && n < 40 && variant_apply(v, n, &cfg)) {
                    snprintf(base, sizeof base, "cone_fov_acuity_%.*s", (int)n, v);
                    method_name(name, sizeof name, base, q);
                    if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) == FOV_OK) {
                        fovrun_render(&ctx, &out, o->threads, &st);
                        row(&rc, name, q, (double)st.evals, work_ref, "evaluations",
                            meas_img(&m, img, name), full, "classic");
                    }
                } else {
                    fprintf(stderr, "--variants: cannot read '%.*s'\n", (int)n, v);
                }
                v += n;
                if (*v == ',') ++v;
            }
        }
    }
    if (listed(o->headers, "lp") && !sdf_only)
        lp_rows(&rc, o, &bi, &shade_cfg, gaze, &m, full, img);
    meas_free(&m);
    free(img);
    free(mem);
}

/* ---- fovpt -------------------------------------------------------------------------------- */
typedef struct pt_job {
    fovpt_ctx *ctx;
    uint32_t frame, first, step, band, height;
    fovpt_stats st;
    fov_result r;
} pt_job;

static void *pt_worker(void *arg)
{
    pt_job *j = (pt_job *)arg;
    uint32_t y;
    for (y = j->first * j->band; y < j->height && j->r == FOV_OK; y += j->step * j->band) {
        uint32_t y1 = y + j->band < j->height ? y + j->band : j->height;
        j->r = fovpt_trace_rows(j->ctx, j->frame, y, y1, &j->st);
    }
    return NULL;
}

/* cfg rendered (frame 0) into rgb on nthreads threads (trace in bands of 8 rows, then refine
   and resolve); 0 on success */
static int pt_render(const fovpt_scene *sc, const fovpt_camera *cam, const fovpt_config *cfg, fov_gaze g,
                     float *rgb, int nthreads, fovpt_stats *st)
{
    size_t n = 0;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    fov_result r;
    pthread_t th[16];
    pt_job jobs[16];
    int i;
    fovpt_stats_init(st);
    if (nthreads < 1) nthreads = 1;
    if (nthreads > 16) nthreads = 16;
    if (fovpt_memory_size(cfg, cam, &n) != FOV_OK) return -1;
    mem = malloc(n + 16u);
    if (!mem) return -1;
    r = fovpt_init(&ctx, cfg, sc, cam, g, mem, n);
    if (r == FOV_OK) {
        for (i = 0; i < nthreads; ++i) {
            memset(&jobs[i], 0, sizeof jobs[i]);
            jobs[i].ctx = &ctx; jobs[i].first = (uint32_t)i; jobs[i].step = (uint32_t)nthreads;
            jobs[i].band = 8; jobs[i].height = cam->height; jobs[i].r = FOV_OK;
            pthread_create(&th[i], NULL, pt_worker, &jobs[i]);
        }
        for (i = 0; i < nthreads; ++i) {
            pthread_join(th[i], NULL);
            if (jobs[i].r != FOV_OK) r = jobs[i].r;
            fovpt_stats_add(st, &jobs[i].st);
        }
    }
    if (r == FOV_OK) r = fovpt_refine_rows(&ctx, 0, 0, cam->height, st);
    if (r == FOV_OK) {
        fovpt_output_init(&out);
        out.rgb = rgb;
        r = fovpt_resolve_rows(&ctx, 0, cam->height, &out);
    }
    free(mem);
    return r == FOV_OK ? 0 : -1;
}

static void pt_scene_rows(FILE *csv, const opts_t *o, const disp_t *D, int id)
{
    pt_scene S;
    size_t npx = (size_t)D->w * D->h;
    float *img = (float *)malloc(npx * 3 * sizeof(float));
    fovpt_config base = fovpt_config_default(), c;
    fovpt_stats st;
    fov_gaze g;
    fov_ecc_model em;
    meas_t m;
    rowctx_t rc;
    score_t ref4, ref1;
    double w4, w1;
    int fam, k;
    if (!img || pt_scene_make(&S, id) != 0) { free(img); return; }
    S.cam.width = D->w; S.cam.height = D->h;
    if (D->cam_fovy > 0.0f) S.cam.fov_y_deg = D->cam_fovy;
    g.x = 0.5f * (float)D->w; g.y = 0.5f * (float)D->h;
    base.display = D->d;
    base.logger.func = logf_;
    if (fovpt_ecc_init(&em, &base.display, S.cam.fov_y_deg, D->w, D->h, g) != FOV_OK) goto done;
    fprintf(stderr, "fovpt %s %s %ux%u: ground truth %u spp\n", pt_scene_names[id], D->name, D->w, D->h,
            o->gt_spp_pt);
    c = base;
    c.spp = o->gt_spp_pt;
    c.seed = PT_GT_SEED; /* independent of every row's streams (seed 0) */
    if (pt_render(&S.scene, &S.cam, &c, g, img, o->threads, &st) != 0) goto done;
    if (meas_init(&m, (int)D->w, (int)D->h, &em, img) != 0) { meas_free(&m); goto done; }
    snprintf(m.tag, sizeof m.tag, "pt_%s_%s", pt_scene_names[id], D->name);
    dump(&m, "gt", m.gt_disp);
    rc.csv = csv; rc.header = "fovpt"; rc.scene = pt_scene_names[id]; rc.D = D; rc.ppd = m.ppd;
    rc.gt_spp = o->gt_spp_pt;
    c = base; c.spp = 4;
    if (pt_render(&S.scene, &S.cam, &c, g, img, o->threads, &st) != 0) { meas_free(&m); goto done; }
    w4 = (double)st.samples; ref4 = meas_img(&m, img, "uniform4");
    row(&rc, "uniform4", 0.0f, w4, w4, "samples", ref4, ref4, "uniform4");
    c = base; c.spp = 1;
    if (pt_render(&S.scene, &S.cam, &c, g, img, o->threads, &st) != 0) { meas_free(&m); goto done; }
    w1 = (double)st.samples; ref1 = meas_img(&m, img, "uniform1");
    row(&rc, "uniform1", 0.0f, w1, w1, "samples", ref1, ref1, "uniform1");
    for (fam = 0; fam < 2; ++fam) /* 0 layers (4 spp per layer, the preset's), 1 zones (1 spp) */
        for (k = 0; k <= o->nqual; ++k) {
            float q = k ? o->qual[k - 1] : 0.0f;
            char name[64];
            c = base;
            c.method = fam ? FOVPT_METHOD_ZONES : FOVPT_METHOD_LAYERS;
            c.spp = fam ? 1u : 4u;
            if (k) {
                fov_eye eye;
                memset(&eye, 0, sizeof eye);
                eye.quality = q;
                if (fovpt_config_acuity(&c, &S.cam, &eye) != FOV_OK) continue;
                method_name(name, sizeof name, fam ? "zones_acuity" : "layers_acuity", q);
            } else {
                snprintf(name, sizeof name, "%s", fam ? "zones" : "layers");
            }
            if (pt_render(&S.scene, &S.cam, &c, g, img, o->threads, &st) != 0) continue;
            row(&rc, name, q, (double)st.samples, fam ? w1 : w4, "samples", meas_img(&m, img, name),
                fam ? ref1 : ref4, fam ? "uniform1" : "uniform4");
            if (k && fabsf(q - 1.0f) < 1e-6f) {
                /* acuity_budget: the samples spread to minimise the mean eye-filtered noise,
                   about budget x the full-resolution method's: _eqt at 1 (equal time), _bB
                   below 1 (the saving at equal quality is about 1 / B where perr reaches
                   perr_ref) */
                int kb;
                for (kb = 0; kb < o->nbudget; ++kb) {
                    float bu = o->budget[kb];
                    fov_eye eye;
                    memset(&eye, 0, sizeof eye);
                    eye.quality = q;
                    c = base;
                    c.method = fam ? FOVPT_METHOD_ZONES : FOVPT_METHOD_LAYERS;
                    c.spp = fam ? 1u : 4u;
                    c.acuity_budget = bu;
                    if (fovpt_config_acuity(&c, &S.cam, &eye) != FOV_OK) continue;
                    if (fabsf(bu - 1.0f) < 1e-6f)
                        snprintf(name, sizeof name, "%s_eqt", fam ? "zones_acuity" : "layers_acuity");
                    else
                        snprintf(name, sizeof name, "%s_b%g", fam ? "zones_acuity" : "layers_acuity", (double)bu);
                    if (pt_render(&S.scene, &S.cam, &c, g, img, o->threads, &st) != 0) continue;
                    row(&rc, name, q, (double)st.samples, fam ? w1 : w4, "samples", meas_img(&m, img, name),
                        fam ? ref1 : ref4, fam ? "uniform1" : "uniform4");
                }
            }
        }
    meas_free(&m);
done:
    pt_scene_free(&S);
    free(img);
}

static void usage(FILE *f)
{
    fputs("usage: bench_perceptual [options]   (bench/results/perceptual.csv)\n"
          "  --quick              bench and desktop27, qualities 0.5,1,2, one scene per header\n"
          "  --displays a,b       of bench,desktop27,hmd (default all)\n"
          "  --headers a,b        of sdf,lp,pt (default all)\n"
          "  --scenes-sdf a,b     fovsdf / fovlp scenes (default primitives,temple)\n"
          "  --scenes-sdf-only a,b  more scenes with fovsdf's rows only (default columns,thin;\n"
          "                       \"\" for none)\n"
          "  --scenes-pt a,b      fovpt scenes (default cornell)\n"
          "  --qualities a,b      the acuity rows' quality knobs (default 0.25,0.35,0.5,0.7,1,1.5,2,3)\n"
          "  --budgets a,b        fovpt acuity_budget rows at quality 1 (default 1,0.5,0.35,0.25,0.15)\n"
          "  --variants a,b       also cone_fov_acuity with rdX (refine_depth X),\n"
          "                       rcX (refine_contrast X),\n"
          "                       lfN (level_filter N), rnX (refine_normal_deg X),\n"
          "                       rmN (refine_material N),\n"
          "                       nq (quarter_deg 0: no quarter level),\n"
          "                       pl (0.7.0's acuity: level_filter 1, no refinement); '+' joins\n"
          "                       parts: rows cone_fov_acuity_<variant>[_qQ]\n"
          "  --acuity-only        no fipr, cone_fov and fipr_acuity rows\n"
          "  --gt-spp N           fovsdf ground truth samples per pixel (default 4)\n"
          "  --gt-spp-pt N        fovpt ground truth samples per pixel (default 32)\n"
          "  --threads N          render threads (default the number of cores)\n"
          "  --out FILE           the CSV (default bench/results/perceptual.csv)\n"
          "  --append             add rows to FILE without a header line\n"
          "  --dump DIR           write every image (and the ground truth) as sRGB PPM into DIR\n"
          "  --lp-taa N           fovlp's TAA rows after N still frames (default 16; 0: none)\n"
          "  --lp-study           fovlp's diagnostic rows (prefiltered samples, full resolution with TAA)\n"
          "  --lp-recon R         bilinear or cubic: cfg.recon of every fovlp row (default as configured)\n", f);
}

int main(int argc, char **argv)
{
    opts_t o;
    const char *outpath = "bench/results/perceptual.csv";
    int a, d, append = 0, quick = 0;
    FILE *csv;
    memset(&o, 0, sizeof o);
    o.threads = (int)sysconf(_SC_NPROCESSORS_ONLN);
    o.gt_spp = 4; o.gt_spp_pt = 32;
    o.lp_taa = 16;
    o.lp_recon = -1;
    o.qual = g_qual_all; o.nqual = 8;
    o.budget[0] = 1.0f; o.budget[1] = 0.5f; o.budget[2] = 0.35f; o.budget[3] = 0.25f;
    o.budget[4] = 0.15f; o.nbudget = 5;
    o.displays = "bench,desktop27,hmd"; o.headers = "sdf,lp,pt";
    o.scenes_sdf = "primitives,temple"; o.scenes_pt = "cornell";
    o.scenes_sdf_only = "columns,thin";
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--quick")) quick = 1;
        else if (!strcmp(argv[a], "--lp-study")) o.lp_study = 1;
        else if (!strcmp(argv[a], "--lp-recon") && a + 1 < argc) {
            ++a;
            if (!strcmp(argv[a], "bilinear")) o.lp_recon = 0;
            else if (!strcmp(argv[a], "cubic")) o.lp_recon = 1;
            else { fprintf(stderr, "--lp-recon bilinear or cubic\n"); return 2; }
        }
        else if (!strcmp(argv[a], "--lp-taa") && a + 1 < argc) {
            o.lp_taa = atoi(argv[++a]);
            if (o.lp_taa < 0 || o.lp_taa > 1000) { fprintf(stderr, "--lp-taa 0..1000\n"); return 2; }
        }
        else if (!strcmp(argv[a], "--append")) append = 1;
        else if (!strcmp(argv[a], "--dump") && a + 1 < argc) g_dump = argv[++a];
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outpath = argv[++a];
        else if (!strcmp(argv[a], "--threads") && a + 1 < argc) o.threads = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--displays") && a + 1 < argc) o.displays = argv[++a];
        else if (!strcmp(argv[a], "--headers") && a + 1 < argc) o.headers = argv[++a];
        else if (!strcmp(argv[a], "--scenes-sdf") && a + 1 < argc) o.scenes_sdf = argv[++a];
        else if (!strcmp(argv[a], "--scenes-sdf-only") && a + 1 < argc)
            o.scenes_sdf_only = argv[++a];
        else if (!strcmp(argv[a], "--scenes-pt") && a + 1 < argc) o.scenes_pt = argv[++a];
        else if (!strcmp(argv[a], "--variants") && a + 1 < argc) o.variants = argv[++a];
        else if (!strcmp(argv[a], "--acuity-only")) o.acuity_only = 1;
        else if (!strcmp(argv[a], "--qualities") && a + 1 < argc) {
            char *p = argv[++a];
            o.nqual = 0;
            while (*p && o.nqual < 16) {
                g_qual_user[o.nqual] = (float)strtod(p, &p);
                if (!(g_qual_user[o.nqual] > 0.0f && g_qual_user[o.nqual] <= 100.0f)) {
                    fprintf(stderr, "--qualities: numbers in (0, 100], comma-separated\n");
                    return 2;
                }
                ++o.nqual;
                if (*p == ',') ++p;
                else break;
            }
            o.qual = g_qual_user;
        }
        else if (!strcmp(argv[a], "--budgets") && a + 1 < argc) {
            char *p = argv[++a];
            o.nbudget = 0;
            while (*p && o.nbudget < 16) {
                o.budget[o.nbudget] = (float)strtod(p, &p);
                if (!(o.budget[o.nbudget] > 0.0f && o.budget[o.nbudget] <= 64.0f)) {
                    fprintf(stderr, "--budgets: numbers in (0, 64], comma-separated\n");
                    return 2;
                }
                ++o.nbudget;
                if (*p == ',') ++p;
                else break;
            }
        }
        else if (!strcmp(argv[a], "--gt-spp") && a + 1 < argc) o.gt_spp = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--gt-spp-pt") && a + 1 < argc) o.gt_spp_pt = (uint32_t)atoi(argv[++a]);
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (quick) { /* the options given on the command line keep their values */
        int k;
        const char *given = "";
        for (k = 1; k < argc; ++k)
            if (!strcmp(argv[k], "--displays")) given = "d";
        if (!*given) o.displays = "bench,desktop27";
        if (o.qual != g_qual_user) { o.qual = g_qual_quick; o.nqual = 3; }
        for (k = 1; k < argc; ++k) if (!strcmp(argv[k], "--gt-spp-pt")) break;
        if (k == argc) o.gt_spp_pt = 16;
        for (k = 1; k < argc; ++k) if (!strcmp(argv[k], "--scenes-sdf")) break;
        if (k == argc) o.scenes_sdf = "primitives";
        for (k = 1; k < argc; ++k) if (!strcmp(argv[k], "--scenes-sdf-only")) break;
        if (k == argc) o.scenes_sdf_only = "";
    }
    if (o.threads < 1) o.threads = 1;
    if (o.gt_spp < 1 || o.gt_spp > 256 || o.gt_spp_pt < 1 || o.gt_spp_pt > 4096) {
        fprintf(stderr, "--gt-spp 1..256, --gt-spp-pt 1..4096\n");
        return 2;
    }
    disps_init();
    csv = fopen(outpath, append ? "a" : "w");
    if (!csv) { fprintf(stderr, "cannot write %s (run from the repository root)\n", outpath); return 1; }
    if (!append)
        fprintf(csv, "header,scene,display,ppd_center,method,saving,perr,perr_ref,equal_quality,"
                     "quality,work,work_ref,work_unit,epsnr,epsnr_ref,psnr_raw,width,height,gt_spp,ref_method,"
                     "perr_e0_2,perr_e2_5,perr_e5_10,perr_e10_20,perr_e20_up,"
                     "perr_ref_e0_2,perr_ref_e2_5,perr_ref_e5_10,perr_ref_e10_20,perr_ref_e20_up\n");
    for (d = 0; d < 3; ++d) {
        uint32_t id;
        int p;
        if (!listed(o.displays, g_disps[d].name)) continue;
        if (listed(o.headers, "sdf") || listed(o.headers, "lp"))
            for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
                if (listed(o.scenes_sdf, fovsdf_builtin_name(id)))
                    sdf_scene(csv, &o, &g_disps[d], id, 0);
                else if (listed(o.headers, "sdf") &&
                         listed(o.scenes_sdf_only, fovsdf_builtin_name(id)))
                    sdf_scene(csv, &o, &g_disps[d], id, 1);
            }
        if (listed(o.headers, "pt"))
            for (p = 0; p < PT_SCENE_NUM; ++p)
                if (listed(o.scenes_pt, pt_scene_names[p])) pt_scene_rows(csv, &o, &g_disps[d], p);
    }
    fclose(csv);
    return 0;
}
