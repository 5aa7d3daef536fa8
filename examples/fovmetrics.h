/*
 * fovmetrics.h - image-quality metrics for the fov demo, tests and benchmarks:
 * MSE / RMSE / PSNR, SSIM (Wang et al. 2004) and LDR-FLIP (Andersson et
 * al. 2020), each over the whole image or over a selected region
 * (eccentricity band or mask value), plus per-eccentricity-ring summaries.
 *
 * Single-header, stb style. In exactly one C or C++ file:
 *
 *     #define FOVM_IMPLEMENTATION
 *     #include "fovmetrics.h"
 *
 * Hosted C99 with <math.h> (link with -lm); also compiles as C++.
 * No global mutable state; all scratch memory is malloc'ed per call.
 *
 * Inputs: two images `ref` and `test` of w x h pixels with c = 1 (grey) or
 * c = 3 (RGB) interleaved channels, row stride w*c floats, top row first.
 * Values are display-encoded (sRGB) in [0,1]. Internal accumulation is in
 * double precision.
 *
 * Return values: FOVM_OK (0) or a negative FOVM_ERR_* code; outputs are
 * only written on success.
 *
 * ---- Metrics ------------------------------------------------------------
 * MSE   mean over all selected pixels and all channels of (ref-test)^2.
 * RMSE  sqrt(MSE).
 * PSNR  10*log10(1/MSE) (peak 1.0). Identical images (MSE == 0) give
 *       +INFINITY.
 * SSIM  Wang, Bovik, Sheikh, Simoncelli 2004: 11x11 Gaussian window,
 *       sigma 1.5, normalised to sum 1; K1 = 0.01, K2 = 0.03, L = 1
 *       (C1 = (K1 L)^2, C2 = (K2 L)^2). Computed on the display-encoded
 *       luma Y' = 0.299 R + 0.587 G + 0.114 B for RGB input (fovm_ssim), or
 *       per channel with the channel SSIM maps averaged
 *       (fovm_ssim_channels). Like Wang's reference MATLAB code
 *       (ssim_index.m, filter2 'valid') the SSIM map only covers positions
 *       where the whole window fits: it is (w-10) x (h-10), map pixel
 *       (i, j) belongs to the window centre, image pixel (i+5, j+5). No
 *       automatic downsampling is done. Images smaller than 11x11 give
 *       FOVM_ERR_TOO_SMALL.
 * FLIP  LDR-FLIP, implemented from the paper "FLIP: A Difference Evaluator
 *       for Alternating Images" (Andersson, Nilsson, Akenine-Moeller,
 *       Oskarsson, Astrom, Fairchild, HPG 2020). ppd = pixels per degree
 *       of visual angle (FOVM_FLIP_DEFAULT_PPD = 67, the paper's 0.7 m
 *       viewing distance to a 0.7 m wide 3840-pixel monitor). Per-pixel
 *       values are in [0,1]; the map is w x h. Grey input is treated as
 *       R = G = B. Borders are handled by clamping to the edge. Checked
 *       against NVIDIA's reference tool, see tests/flip_reference/.
 *
 * ---- Regions ------------------------------------------------------------
 * A fovm_sel selects pixels of the w x h image grid:
 *   fovm_sel_all()                 every pixel (a NULL fovm_sel * too);
 *   fovm_sel_band(map, lo, hi)     pixels with lo <= map[i] < hi, map is a
 *                                  w*h float map (e.g. eccentricity in
 *                                  degrees; NaN entries never selected);
 *   fovm_sel_mask(mask, value)     pixels with mask[i] == value, mask is a
 *                                  w*h uint8 map (inside/outside a binary
 *                                  mask = value 1 / value 0).
 * The *_sel variants report the number of selected pixels in *count (for
 * SSIM: selected map pixels, i.e. selected window centres inside the
 * valid region). EMPTY SELECTION: the call still returns FOVM_OK, *count
 * is 0 and the mean (MSE, RMSE, PSNR, SSIM, FLIP) is NaN. For SSIM and
 * FLIP the full map is computed over the whole image first and then
 * averaged over the selected pixels, so neighbourhoods cross region
 * borders exactly as in the full-image metric.
 *
 * ---- The eye: a perceptual error that knows the gaze ---------------------
 * fovm_eye describes the viewer as the fov headers' eccentricity model does
 * (fov_ecc_model): the eye sits f_px pixels in front of the image plane on
 * the axis through image point (cx, cy) and looks at the gaze (gx, gy);
 * the eccentricity of an image point is the angle between the eye's rays
 * through it and through the gaze. Its resolution is the linear minimum
 * angle of resolution of Guenter, Finch, Drucker, Tan and Snyder,
 * "Foveated 3D Graphics" (2012), MAR(e) = mar0 + slope e (arc minutes;
 * 0 fields take the defaults 1 and 1.32, as fov_eye's).
 * fovm_eye_filter blurs an image to that resolution: at each pixel a
 * Gaussian of standard deviation
 *     sigma = sqrt(2 ln 2) / pi * MAR(e) = 0.3748 MAR(e)   (degrees),
 * the Gaussian whose response at the grating frequency the MAR just
 * resolves, 1 / (2 MAR) cycles per degree (bar and gap each one MAR wide),
 * is 1/2: gratings the eye resolves pass with more than half their
 * contrast, one twice as fine keeps 1/16, three times as fine 0.2%. In
 * pixels: sigma_x = sigma ppd_x, sigma_y = sigma ppd_y with the local pixels
 * per degree of the flat image along x and y at that pixel (the angle a one
 * pixel step subtends: with v = (x - cx, y - cy, f_px), ppd_x =
 * |v|^2 / sqrt(f_px^2 + v_y^2) * pi / 180, ppd_y likewise with v_x; both
 * f_px pi / 180 on the axis, larger away from it). Two separable passes
 * (rows with sigma_x, then columns with sigma_y; an axis-aligned ellipse,
 * the tilt of the pixel footprint off the axes is ignored), each with the
 * pixel's own sampled Gaussian, radius ceil(3.5 sigma) (sigma quantised
 * in 0.5% steps; below 0.2 px the pixel is copied; sigma is capped at
 * FOVM_EYE_SIGMA_MAX px), clamped at the borders, on linear light (sRGB
 * decoded, filtered, encoded again: a pattern finer than the eye resolves
 * looks like its linear-light mean). Cost: 1920x1080 RGB on a 27-inch
 * screen at 60 cm, gaze at the centre, about 0.6 s on one core (-O2).
 * fovm_perceptual filters both images so and reports PSNR and FLIP of the
 * filtered pair, FLIP at the pixels per degree at the gaze (fovm_eye_ppd);
 * a difference the eye cannot resolve where it is scores as none.
 */
#ifndef FOVMETRICS_H
#define FOVMETRICS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FOVM_FLIP_DEFAULT_PPD 67.0
#define FOVM_SSIM_WIN 11   /* window size; map is (w-10) x (h-10) */
#define FOVM_SSIM_HALF 5   /* map pixel (i,j) <-> image pixel (i+5,j+5) */

enum {
    FOVM_OK = 0,
    FOVM_ERR_ARG = -1,       /* NULL pointer, w/h < 1, c not 1 or 3, bad ppd */
    FOVM_ERR_NOMEM = -2,     /* allocation failed or size overflow */
    FOVM_ERR_TOO_SMALL = -3  /* SSIM: image smaller than 11x11 */
};

enum { FOVM_SEL_ALL = 0, FOVM_SEL_BAND = 1, FOVM_SEL_MASK = 2 };

typedef struct fovm_sel {
    int kind;                   /* FOVM_SEL_ALL / _BAND / _MASK */
    const float *map;           /* BAND: w*h values */
    double lo, hi;              /* BAND: lo <= map[i] < hi */
    const unsigned char *mask;  /* MASK: w*h values */
    unsigned char value;        /* MASK: mask[i] == value */
} fovm_sel;

/* Human-readable text for an error code. */
const char *fovm_strerror(int err);

fovm_sel fovm_sel_all(void);
fovm_sel fovm_sel_band(const float *map, double lo, double hi);
fovm_sel fovm_sel_mask(const unsigned char *mask, unsigned char value);
/* 1 if pixel index i (= y*w + x) is selected (sel NULL = all). */
int fovm_sel_test(const fovm_sel *sel, size_t i);
/* Number of selected pixels of a w x h grid (-1 on bad arguments). */
long fovm_sel_count(const fovm_sel *sel, int w, int h);

/* ---- MSE / RMSE / PSNR ---- */
int fovm_mse(const float *ref, const float *test, int w, int h, int c, double *mse);
int fovm_rmse(const float *ref, const float *test, int w, int h, int c, double *rmse);
int fovm_psnr(const float *ref, const float *test, int w, int h, int c, double *psnr);
/* 10*log10(1/mse); +INFINITY for mse == 0; NaN for NaN or mse < 0. */
double fovm_psnr_from_mse(double mse);
int fovm_mse_sel(const float *ref, const float *test, int w, int h, int c,
                 const fovm_sel *sel, double *mse, long *count);
int fovm_rmse_sel(const float *ref, const float *test, int w, int h, int c,
                  const fovm_sel *sel, double *rmse, long *count);
int fovm_psnr_sel(const float *ref, const float *test, int w, int h, int c,
                  const fovm_sel *sel, double *psnr, long *count);

/* ---- SSIM ---- mean: mean SSIM (may be NULL); map: optional caller
 * buffer of (w-10)*(h-10) floats (may be NULL). */
int fovm_ssim(const float *ref, const float *test, int w, int h, int c,
              double *mean, float *map);
int fovm_ssim_channels(const float *ref, const float *test, int w, int h, int c,
                       double *mean, float *map);
/* per_channel = 0: luma (fovm_ssim), 1: channel mean (fovm_ssim_channels). */
int fovm_ssim_sel(const float *ref, const float *test, int w, int h, int c,
                  int per_channel, const fovm_sel *sel, double *mean, long *count);
/* Average a precomputed (w-10)x(h-10) SSIM map over a selection of the
 * w x h image (map pixel (i,j) counts as image pixel (i+5,j+5)). */
int fovm_ssim_map_mean_sel(const float *map, int w, int h, const fovm_sel *sel,
                           double *mean, long *count);

/* ---- FLIP ---- ppd > 0 (use FOVM_FLIP_DEFAULT_PPD); mean may be NULL;
 * map: optional caller buffer of w*h floats. */
int fovm_flip(const float *ref, const float *test, int w, int h, int c,
              double ppd, double *mean, float *map);
int fovm_flip_sel(const float *ref, const float *test, int w, int h, int c,
                  double ppd, const fovm_sel *sel, double *mean, long *count);
/* Average any full-size w x h map (e.g. a FLIP map) over a selection. */
int fovm_map_mean_sel(const float *map, int w, int h, const fovm_sel *sel,
                      double *mean, long *count);
/* Pixels per degree for a screen of width_m metres and width_px pixels
 * viewed from distance_m metres (small-angle formula used by FLIP):
 * distance_m * (width_px / width_m) * pi / 180. */
double fovm_ppd_from_viewing(double distance_m, double width_m, double width_px);

/* ---- Eccentricity rings ---- */
typedef struct fovm_ring {
    double lo, hi;     /* ring i covers lo <= ecc < hi, lo = i*max/N */
    long count;        /* selected pixels (MSE, PSNR, FLIP) */
    long ssim_count;   /* selected SSIM window centres */
    double mse, psnr, ssim, flip;  /* NaN when the ring is empty */
} fovm_ring;
/* N = nrings equal-width rings from 0 to max_deg over the per-pixel
 * eccentricity map ecc (w*h, degrees); pixels with ecc >= max_deg, < 0 or
 * NaN belong to no ring. SSIM is the luma SSIM; if the image is smaller
 * than 11x11 every ring gets ssim = NaN, ssim_count = 0 (not an error).
 * FLIP uses ppd. The SSIM and FLIP maps are computed once. */
int fovm_ecc_rings(const float *ref, const float *test, int w, int h, int c,
                   const float *ecc, int nrings, double max_deg, double ppd,
                   fovm_ring *rings);

/* ---- the eye (see "The eye" above) ---- */
#define FOVM_EYE_SIGMA_MAX 64.0   /* cap of the filter's sigma, pixels */
typedef struct fovm_eye {
    double cx, cy;        /* where the eye's axis meets the image, pixels */
    double f_px;          /* eye to image plane, pixels, > 0 */
    double gx, gy;        /* the gaze point, pixels (pixel (i,j) covers [i,i+1)x[j,j+1)) */
    double mar0_arcmin;   /* MAR at the gaze, arc minutes, (0, 60]; 0: 1 */
    double slope_arcmin;  /* MAR growth, arc minutes per degree, (0, 60]; 0: 1.32 */
} fovm_eye;
/* An eye on the axis through the image centre with the image height subtending fov_y_deg
 * (the camera's field of view), looking at (gx, gy); default MAR model. */
fovm_eye fovm_eye_from_fov(int w, int h, double fov_y_deg, double gx, double gy);
/* The same for a monitor: f_px = distance_mm / pixel_pitch_mm. */
fovm_eye fovm_eye_from_monitor(int w, int h, double pixel_pitch_mm, double distance_mm,
                               double gx, double gy);
/* FOVM_OK if every field is valid (finite; f_px > 0; MAR fields 0 or in (0, 60]). */
int fovm_eye_check(const fovm_eye *eye);
/* Eccentricity in degrees of image point (x, y) (a pixel centre is (i + 0.5, j + 0.5));
 * NaN for an invalid eye. */
double fovm_eye_ecc(const fovm_eye *eye, double x, double y);
/* MAR(ecc) in degrees; NaN for an invalid eye or ecc < 0. */
double fovm_eye_mar_deg(const fovm_eye *eye, double ecc);
/* Pixels per degree at the gaze (radially, as the headers' fov ppd: (f^2 + r^2) / f * pi/180,
 * r the gaze's distance from the axis); NaN for an invalid eye. */
double fovm_eye_ppd(const fovm_eye *eye);
/* The filter's sigma at pixel (i, j) in pixels along x and y (before the cap). */
int fovm_eye_sigma(const fovm_eye *eye, int i, int j, double *sigma_x, double *sigma_y);
/* out = img filtered to the eye's resolution (w x h x c; out may equal img). */
int fovm_eye_filter(const float *img, int w, int h, int c, const fovm_eye *eye, float *out);
/* PSNR and mean FLIP (at fovm_eye_ppd) of the eye-filtered pair; psnr, flip, map (w*h FLIP
 * values of the filtered pair) may each be NULL. */
int fovm_perceptual(const float *ref, const float *test, int w, int h, int c,
                    const fovm_eye *eye, double *psnr, double *flip, float *map);

#ifdef __cplusplus
}
#endif

#endif /* FOVMETRICS_H */

/* ====================================================================== */
#ifdef FOVM_IMPLEMENTATION
#ifndef FOVM_IMPLEMENTATION_DONE
#define FOVM_IMPLEMENTATION_DONE

#include <stdlib.h>
#include <string.h>
#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- helpers ------------------------------------------------------------ */

/* w*h*c as size_t, or 0 if invalid / overflowing. */
static size_t fovm__n(int w, int h, int c)
{
    size_t n;
    if (w < 1 || h < 1 || (c != 1 && c != 3)) return 0;
    n = (size_t)w;
    if ((size_t)h > ((size_t)-1) / n) return 0;
    n *= (size_t)h;
    if ((size_t)c > ((size_t)-1) / n) return 0;
    n *= (size_t)c;
    if (n > ((size_t)-1) / (8 * sizeof(double))) return 0;
    return n;
}

static double fovm__nan(void)
{
#ifdef NAN
    return (double)NAN;
#else
    return 0.0 / 0.0;
#endif
}

static double fovm__inf(void)
{
#ifdef INFINITY
    return (double)INFINITY;
#else
    return HUGE_VAL;
#endif
}

const char *fovm_strerror(int err)
{
    switch (err) {
    case FOVM_OK: return "ok";
    case FOVM_ERR_ARG: return "invalid argument";
    case FOVM_ERR_NOMEM: return "out of memory or size overflow";
    case FOVM_ERR_TOO_SMALL: return "image smaller than the 11x11 SSIM window";
    default: return "unknown error";
    }
}

fovm_sel fovm_sel_all(void)
{
    fovm_sel s;
    memset(&s, 0, sizeof s);
    s.kind = FOVM_SEL_ALL;
    return s;
}

fovm_sel fovm_sel_band(const float *map, double lo, double hi)
{
    fovm_sel s;
    memset(&s, 0, sizeof s);
    s.kind = FOVM_SEL_BAND;
    s.map = map; s.lo = lo; s.hi = hi;
    return s;
}

fovm_sel fovm_sel_mask(const unsigned char *mask, unsigned char value)
{
    fovm_sel s;
    memset(&s, 0, sizeof s);
    s.kind = FOVM_SEL_MASK;
    s.mask = mask; s.value = value;
    return s;
}

int fovm_sel_test(const fovm_sel *sel, size_t i)
{
    if (!sel || sel->kind == FOVM_SEL_ALL) return 1;
    if (sel->kind == FOVM_SEL_BAND) {
        double v = (double)sel->map[i];
        return v >= sel->lo && v < sel->hi;
    }
    if (sel->kind == FOVM_SEL_MASK) return sel->mask[i] == sel->value;
    return 0;
}

static int fovm__sel_ok(const fovm_sel *sel)
{
    if (!sel || sel->kind == FOVM_SEL_ALL) return 1;
    if (sel->kind == FOVM_SEL_BAND) return sel->map != NULL;
    if (sel->kind == FOVM_SEL_MASK) return sel->mask != NULL;
    return 0;
}

long fovm_sel_count(const fovm_sel *sel, int w, int h)
{
    size_t i, n = fovm__n(w, h, 1);
    long cnt = 0;
    if (n == 0 || !fovm__sel_ok(sel)) return -1;
    for (i = 0; i < n; i++) cnt += fovm_sel_test(sel, i);
    return cnt;
}

/* ---- MSE / PSNR --------------------------------------------------------- */

double fovm_psnr_from_mse(double mse)
{
    if (!(mse >= 0.0)) return fovm__nan();
    if (mse == 0.0) return fovm__inf();
    return -10.0 * log10(mse);
}

int fovm_mse_sel(const float *ref, const float *test, int w, int h, int c,
                 const fovm_sel *sel, double *mse, long *count)
{
    size_t n = fovm__n(w, h, c), np, i;
    double sum = 0.0;
    long cnt = 0;
    int k;
    if (!ref || !test || n == 0 || !fovm__sel_ok(sel)) return FOVM_ERR_ARG;
    np = n / (size_t)c;
    for (i = 0; i < np; i++) {
        if (!fovm_sel_test(sel, i)) continue;
        cnt++;
        for (k = 0; k < c; k++) {
            double d = (double)ref[i * (size_t)c + (size_t)k] -
                       (double)test[i * (size_t)c + (size_t)k];
            sum += d * d;
        }
    }
    if (mse) *mse = cnt ? sum / ((double)cnt * (double)c) : fovm__nan();
    if (count) *count = cnt;
    return FOVM_OK;
}

int fovm_rmse_sel(const float *ref, const float *test, int w, int h, int c,
                  const fovm_sel *sel, double *rmse, long *count)
{
    double m = 0.0;
    int err = fovm_mse_sel(ref, test, w, h, c, sel, &m, count);
    if (err) return err;
    if (rmse) *rmse = sqrt(m);
    return FOVM_OK;
}

int fovm_psnr_sel(const float *ref, const float *test, int w, int h, int c,
                  const fovm_sel *sel, double *psnr, long *count)
{
    double m = 0.0;
    int err = fovm_mse_sel(ref, test, w, h, c, sel, &m, count);
    if (err) return err;
    if (psnr) *psnr = fovm_psnr_from_mse(m);
    return FOVM_OK;
}

int fovm_mse(const float *ref, const float *test, int w, int h, int c, double *mse)
{
    return fovm_mse_sel(ref, test, w, h, c, NULL, mse, NULL);
}

int fovm_rmse(const float *ref, const float *test, int w, int h, int c, double *rmse)
{
    return fovm_rmse_sel(ref, test, w, h, c, NULL, rmse, NULL);
}

int fovm_psnr(const float *ref, const float *test, int w, int h, int c, double *psnr)
{
    return fovm_psnr_sel(ref, test, w, h, c, NULL, psnr, NULL);
}

/* ---- SSIM --------------------------------------------------------------- */

/* Sample of row y of an interleaved image: chan >= 0 a channel, chan < 0
 * the luma 0.299 R + 0.587 G + 0.114 B (grey images: the grey value). */
static void fovm__ssim_row(const float *img, int w, int c, int y, int chan,
                           double *out)
{
    const float *p = img + (size_t)y * (size_t)w * (size_t)c;
    int x;
    if (c == 1) {
        for (x = 0; x < w; x++) out[x] = (double)p[x];
    } else if (chan >= 0) {
        for (x = 0; x < w; x++) out[x] = (double)p[(size_t)x * 3 + (size_t)chan];
    } else {
        for (x = 0; x < w; x++) {
            const float *q = p + (size_t)x * 3;
            out[x] = 0.299 * (double)q[0] + 0.587 * (double)q[1] + 0.114 * (double)q[2];
        }
    }
}

/* SSIM over the valid region for one plane (luma or one channel).
 * If map != NULL: map[i] = (accumulate ? map[i] : 0) + wgt * ssim.
 * *sum receives the sum of the SSIM values. */
static int fovm__ssim_plane(const float *ref, const float *test, int w, int h,
                            int c, int chan, float *map, double wgt,
                            int accumulate, double *sum)
{
    const int R = FOVM_SSIM_WIN, HALF = FOVM_SSIM_HALF;
    const double C1 = (0.01 * 1.0) * (0.01 * 1.0);
    const double C2 = (0.03 * 1.0) * (0.03 * 1.0);
    int mw = w - (R - 1);
    double g[FOVM_SSIM_WIN], gs = 0.0, total = 0.0;
    double *rx, *ry, *ring;
    size_t mwz = (size_t)mw, ringsz;
    int k, x, y;
    for (k = 0; k < R; k++) {
        double d = (double)(k - HALF);
        g[k] = exp(-(d * d) / (2.0 * 1.5 * 1.5));
        gs += g[k];
    }
    for (k = 0; k < R; k++) g[k] /= gs;
    /* ring buffer: for each of R rows, 5 horizontally filtered quantities
     * (x, y, x^2, y^2, x*y), each mw wide */
    ringsz = (size_t)R * 5 * mwz;
    ring = (double *)malloc(ringsz * sizeof(double));
    rx = (double *)malloc((size_t)w * sizeof(double));
    ry = (double *)malloc((size_t)w * sizeof(double));
    if (!ring || !rx || !ry) { free(ring); free(rx); free(ry); return FOVM_ERR_NOMEM; }
    for (y = 0; y < h; y++) {
        double *q = ring + (size_t)(y % R) * 5 * mwz;
        fovm__ssim_row(ref, w, c, y, chan, rx);
        fovm__ssim_row(test, w, c, y, chan, ry);
        for (x = 0; x < mw; x++) {
            double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
            for (k = 0; k < R; k++) {
                double a = rx[x + k], b = ry[x + k], gk = g[k];
                sx += gk * a; sy += gk * b;
                sxx += gk * a * a; syy += gk * b * b; sxy += gk * a * b;
            }
            q[x] = sx; q[mwz + (size_t)x] = sy; q[2 * mwz + (size_t)x] = sxx;
            q[3 * mwz + (size_t)x] = syy; q[4 * mwz + (size_t)x] = sxy;
        }
        if (y >= R - 1) {
            int oy = y - (R - 1);   /* output row; window rows oy..y */
            for (x = 0; x < mw; x++) {
                double mx = 0, my = 0, exx = 0, eyy = 0, exy = 0;
                double vx, vy, cxy, s;
                for (k = 0; k < R; k++) {
                    const double *r = ring + (size_t)((oy + k) % R) * 5 * mwz;
                    double gk = g[k];
                    mx += gk * r[x]; my += gk * r[mwz + (size_t)x];
                    exx += gk * r[2 * mwz + (size_t)x];
                    eyy += gk * r[3 * mwz + (size_t)x];
                    exy += gk * r[4 * mwz + (size_t)x];
                }
                vx = exx - mx * mx;
                vy = eyy - my * my;
                cxy = exy - mx * my;
                s = ((2.0 * mx * my + C1) * (2.0 * cxy + C2)) /
                    ((mx * mx + my * my + C1) * (vx + vy + C2));
                total += s;
                if (map) {
                    float *m = map + (size_t)oy * mwz + (size_t)x;
                    *m = (float)((accumulate ? (double)*m : 0.0) + wgt * s);
                }
            }
        }
    }
    free(ring); free(rx); free(ry);
    *sum = total;
    return FOVM_OK;
}

static int fovm__ssim_any(const float *ref, const float *test, int w, int h,
                          int c, int per_channel, double *mean, float *map)
{
    double sum = 0.0, s = 0.0, npx;
    int err, k;
    if (!ref || !test || fovm__n(w, h, c) == 0) return FOVM_ERR_ARG;
    if (w < FOVM_SSIM_WIN || h < FOVM_SSIM_WIN) return FOVM_ERR_TOO_SMALL;
    npx = (double)(w - (FOVM_SSIM_WIN - 1)) * (double)(h - (FOVM_SSIM_WIN - 1));
    if (!per_channel || c == 1) {
        err = fovm__ssim_plane(ref, test, w, h, c, -1, map, 1.0, 0, &sum);
        if (err) return err;
        if (mean) *mean = sum / npx;
        return FOVM_OK;
    }
    for (k = 0; k < c; k++) {
        err = fovm__ssim_plane(ref, test, w, h, c, k, map, 1.0 / (double)c, k > 0, &s);
        if (err) return err;
        sum += s;
    }
    if (mean) *mean = sum / (npx * (double)c);
    return FOVM_OK;
}

int fovm_ssim(const float *ref, const float *test, int w, int h, int c,
              double *mean, float *map)
{
    return fovm__ssim_any(ref, test, w, h, c, 0, mean, map);
}

int fovm_ssim_channels(const float *ref, const float *test, int w, int h, int c,
                       double *mean, float *map)
{
    return fovm__ssim_any(ref, test, w, h, c, 1, mean, map);
}

int fovm_ssim_map_mean_sel(const float *map, int w, int h, const fovm_sel *sel,
                           double *mean, long *count)
{
    int mw, mh, x, y;
    double sum = 0.0;
    long cnt = 0;
    if (!map || fovm__n(w, h, 1) == 0 || !fovm__sel_ok(sel)) return FOVM_ERR_ARG;
    if (w < FOVM_SSIM_WIN || h < FOVM_SSIM_WIN) return FOVM_ERR_TOO_SMALL;
    mw = w - (FOVM_SSIM_WIN - 1);
    mh = h - (FOVM_SSIM_WIN - 1);
    for (y = 0; y < mh; y++) {
        for (x = 0; x < mw; x++) {
            size_t i = (size_t)(y + FOVM_SSIM_HALF) * (size_t)w + (size_t)(x + FOVM_SSIM_HALF);
            if (!fovm_sel_test(sel, i)) continue;
            sum += (double)map[(size_t)y * (size_t)mw + (size_t)x];
            cnt++;
        }
    }
    if (mean) *mean = cnt ? sum / (double)cnt : fovm__nan();
    if (count) *count = cnt;
    return FOVM_OK;
}

int fovm_ssim_sel(const float *ref, const float *test, int w, int h, int c,
                  int per_channel, const fovm_sel *sel, double *mean, long *count)
{
    float *map;
    int err;
    if (!ref || !test || fovm__n(w, h, c) == 0 || !fovm__sel_ok(sel)) return FOVM_ERR_ARG;
    if (w < FOVM_SSIM_WIN || h < FOVM_SSIM_WIN) return FOVM_ERR_TOO_SMALL;
    map = (float *)malloc((size_t)(w - 10) * (size_t)(h - 10) * sizeof(float));
    if (!map) return FOVM_ERR_NOMEM;
    err = fovm__ssim_any(ref, test, w, h, c, per_channel, NULL, map);
    if (!err) err = fovm_ssim_map_mean_sel(map, w, h, sel, mean, count);
    free(map);
    return err;
}

/* ---- FLIP --------------------------------------------------------------- */
/*
 * Implementation notes (all constants from the FLIP paper):
 *  colour pipeline
 *   1. sRGB -> linear RGB -> XYZ (D65, sRGB primaries) -> YCxCz:
 *      Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn),
 *      with the white (Xn,Yn,Zn) = XYZ of linear RGB (1,1,1).
 *   2. Contrast sensitivity: per channel a spatial filter that is the
 *      inverse Fourier transform of a sum of Gaussians in frequency:
 *      S(f) = a1 exp(-b1 f^2) + a2 exp(-b2 f^2)  ->
 *      s(x) = sum_i a_i sqrt(pi/b_i) exp(-pi^2 x^2 / b_i)   (x in degrees),
 *      achromatic (a1,b1,a2,b2) = (1, 0.0047, 0, 1e-5),
 *      red-green            = (1, 0.0053, 0, 1e-5),
 *      blue-yellow          = (34.1, 0.04, 13.5, 0.025).
 *      All three filters share the radius ceil(3 sqrt(b_max/(2 pi^2)) ppd)
 *      pixels (b_max = 0.04, i.e. three standard deviations of the widest
 *      Gaussian), are evaluated on the pixel grid at x = d/ppd degrees and
 *      normalised to sum 1. Every term is a separable isotropic 2-D
 *      Gaussian, so the filters are applied as 1-D passes.
 *   3. Filtered YCxCz -> XYZ -> linear RGB, clamped to [0,1] -> CIELAB
 *      (same white) -> Hunt adjustment a' = 0.01 L a, b' = 0.01 L b.
 *   4. HyAB distance |dL| + sqrt(da'^2 + db'^2), raised to qc = 0.7, then
 *      remapped with cmax = HyAB(Hunt(green), Hunt(blue))^qc, pc = 0.4,
 *      pt = 0.95:  e < pc cmax: e pt / (pc cmax);
 *                  else: pt + (e - pc cmax)/(cmax - pc cmax) (1 - pt).
 *  feature pipeline (on the unfiltered luminance Y/Yn in [0,1])
 *   5. Gaussian with sigma = 0.5 w ppd pixels, w = 0.082 degrees, radius
 *      ceil(3 sigma). Edge kernel = first derivative of the Gaussian along
 *      one axis times the Gaussian (sum 1) along the other; point kernel =
 *      second derivative likewise. First-derivative kernel: positive
 *      weights sum to 1 (negative to -1); second-derivative kernel:
 *      positive and negative weights scaled separately to sum to +1 / -1.
 *      Edge / point magnitude = length of the (x, y) response vector.
 *   6. df = (max(|edge_r - edge_t|, |point_r - point_t|) / sqrt(2))^qf,
 *      qf = 0.5.
 *  7. FLIP = dc^(1 - df).
 *  Convolutions clamp coordinates to the image (edge replication).
 */

/* linear sRGB -> XYZ (D65), IEC 61966-2-1 / Lindbloom values */
static const double fovm__rgb2xyz[9] = {
    0.4124564, 0.3575761, 0.1804375,
    0.2126729, 0.7151522, 0.0721750,
    0.0193339, 0.1191920, 0.9503041
};

typedef struct fovm__flipctx {
    double xyz2rgb[9];
    double wx, wy, wz;          /* white point (XYZ of RGB 1,1,1) */
} fovm__flipctx;

static void fovm__flip_init(fovm__flipctx *ctx)
{
    const double *m = fovm__rgb2xyz;
    double det;
    double *o = ctx->xyz2rgb;
    o[0] = m[4] * m[8] - m[5] * m[7];
    o[1] = m[2] * m[7] - m[1] * m[8];
    o[2] = m[1] * m[5] - m[2] * m[4];
    o[3] = m[5] * m[6] - m[3] * m[8];
    o[4] = m[0] * m[8] - m[2] * m[6];
    o[5] = m[2] * m[3] - m[0] * m[5];
    o[6] = m[3] * m[7] - m[4] * m[6];
    o[7] = m[1] * m[6] - m[0] * m[7];
    o[8] = m[0] * m[4] - m[1] * m[3];
    det = m[0] * o[0] + m[1] * o[3] + m[2] * o[6];
    {
        int i;
        for (i = 0; i < 9; i++) o[i] /= det;
    }
    ctx->wx = m[0] + m[1] + m[2];
    ctx->wy = m[3] + m[4] + m[5];
    ctx->wz = m[6] + m[7] + m[8];
}

static double fovm__srgb2lin(double v)
{
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

static double fovm__labf(double t)
{
    const double d = 6.0 / 29.0;
    return t > d * d * d ? cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

/* linear RGB -> Hunt-adjusted L*a*b* */
static void fovm__rgb2hunt(const fovm__flipctx *ctx, double r, double g, double b,
                           double *L, double *A, double *B)
{
    const double *m = fovm__rgb2xyz;
    double X = m[0] * r + m[1] * g + m[2] * b;
    double Y = m[3] * r + m[4] * g + m[5] * b;
    double Z = m[6] * r + m[7] * g + m[8] * b;
    double fx = fovm__labf(X / ctx->wx), fy = fovm__labf(Y / ctx->wy);
    double fz = fovm__labf(Z / ctx->wz);
    double l = 116.0 * fy - 16.0;
    *L = l;
    *A = 0.01 * l * 500.0 * (fx - fy);
    *B = 0.01 * l * 200.0 * (fy - fz);
}

static double fovm__hyab(double L1, double A1, double B1, double L2, double A2, double B2)
{
    double da = A1 - A2, db = B1 - B2;
    return fabs(L1 - L2) + sqrt(da * da + db * db);
}

/* Scratch for separable clamped convolutions of w x h float planes. */
typedef struct fovm__conv {
    int w, h;
    float *tmp;     /* w*h */
    double *acc;    /* w */
    float *pad;     /* w + 2*rmax */
} fovm__conv;

/* dst = (kx (x) ky) * src with edge clamping; kx, ky have 2r+1 taps.
 * dst may equal src. */
static void fovm__conv_sep(fovm__conv *cv, const float *src, float *dst,
                           const double *kx, const double *ky, int r)
{
    int w = cv->w, h = cv->h, x, y, k, n = 2 * r + 1;
    size_t wz = (size_t)w;
    for (y = 0; y < h; y++) {
        const float *s = src + (size_t)y * wz;
        float *t = cv->tmp + (size_t)y * wz;
        for (x = 0; x < w + 2 * r; x++) {
            int xx = x - r;
            xx = xx < 0 ? 0 : (xx > w - 1 ? w - 1 : xx);
            cv->pad[x] = s[xx];
        }
        for (x = 0; x < w; x++) {
            double a = 0.0;
            const float *p = cv->pad + x;
            for (k = 0; k < n; k++) a += kx[k] * (double)p[k];
            t[x] = (float)a;
        }
    }
    for (y = 0; y < h; y++) {
        double *acc = cv->acc;
        float *d = dst + (size_t)y * wz;
        for (x = 0; x < w; x++) acc[x] = 0.0;
        for (k = 0; k < n; k++) {
            int yy = y + k - r;
            const float *t;
            double kk = ky[k];
            yy = yy < 0 ? 0 : (yy > h - 1 ? h - 1 : yy);
            t = cv->tmp + (size_t)yy * wz;
            for (x = 0; x < w; x++) acc[x] += kk * (double)t[x];
        }
        for (x = 0; x < w; x++) d[x] = (float)acc[x];
    }
}

/* Precomputed FLIP kernels for one ppd. */
typedef struct fovm__flipk {
    int rc;              /* CSF radius */
    int rf;              /* feature radius */
    double *ga, *grg, *gby1, *gby2;  /* normalised 1-D CSF Gaussians */
    double wby1, wby2;   /* weights of the two blue-yellow terms */
    double *fg, *fd1, *fd2;          /* feature: gauss, 1st, 2nd derivative */
    double *mem;
} fovm__flipk;

static void fovm__csf_gauss(double *g, int r, double ppd, double b, double *sum)
{
    const double PI = 3.14159265358979323846;
    int i;
    double s = 0.0;
    for (i = -r; i <= r; i++) {
        double x = (double)i / ppd;
        g[i + r] = exp(-PI * PI * x * x / b);
        s += g[i + r];
    }
    for (i = 0; i < 2 * r + 1; i++) g[i] /= s;
    *sum = s;
}

static int fovm__flipk_init(fovm__flipk *K, double ppd)
{
    const double PI = 3.14159265358979323846;
    const double bmax = 0.04;
    double s, s1, s2, a1, a2, sigma, sp, sn;
    int rc, rf, i, nc, nf;
    memset(K, 0, sizeof *K);
    rc = (int)ceil(3.0 * sqrt(bmax / (2.0 * PI * PI)) * ppd);
    sigma = 0.5 * 0.082 * ppd;
    rf = (int)ceil(3.0 * sigma);
    if (rc < 0 || rf < 0 || rc > 1000000 || rf > 1000000) return FOVM_ERR_ARG;
    nc = 2 * rc + 1;
    nf = 2 * rf + 1;
    K->mem = (double *)malloc((size_t)(4 * nc + 3 * nf) * sizeof(double));
    if (!K->mem) return FOVM_ERR_NOMEM;
    K->rc = rc; K->rf = rf;
    K->ga = K->mem; K->grg = K->ga + nc; K->gby1 = K->grg + nc; K->gby2 = K->gby1 + nc;
    K->fg = K->gby2 + nc; K->fd1 = K->fg + nf; K->fd2 = K->fd1 + nf;
    fovm__csf_gauss(K->ga, rc, ppd, 0.0047, &s);
    fovm__csf_gauss(K->grg, rc, ppd, 0.0053, &s);
    fovm__csf_gauss(K->gby1, rc, ppd, 0.04, &s1);
    fovm__csf_gauss(K->gby2, rc, ppd, 0.025, &s2);
    /* 2-D blue-yellow kernel = a1 sqrt(pi/b1) G1 + a2 sqrt(pi/b2) G2
     * (unnormalised G_i = g_i (x) g_i, sum s_i^2), normalised to sum 1. */
    a1 = 34.1 * sqrt(PI / 0.04) * s1 * s1;
    a2 = 13.5 * sqrt(PI / 0.025) * s2 * s2;
    K->wby1 = a1 / (a1 + a2);
    K->wby2 = a2 / (a1 + a2);
    /* feature kernels */
    s = 0.0; sp = 0.0; sn = 0.0;
    for (i = -rf; i <= rf; i++) {
        double x = (double)i;
        double g = sigma > 0.0 ? exp(-(x * x) / (2.0 * sigma * sigma)) : (i == 0 ? 1.0 : 0.0);
        K->fg[i + rf] = g;
        s += g;
        K->fd1[i + rf] = sigma > 0.0 ? -x * g : 0.0;
        K->fd2[i + rf] = sigma > 0.0 ? (x * x / (sigma * sigma) - 1.0) * g : 0.0;
    }
    for (i = 0; i < nf; i++) K->fg[i] /= s;
    for (i = 0; i < nf; i++) if (K->fd1[i] > 0.0) sp += K->fd1[i];
    for (i = 0; i < nf; i++) if (sp > 0.0) K->fd1[i] /= sp;
    sp = 0.0;
    for (i = 0; i < nf; i++) {
        if (K->fd2[i] > 0.0) sp += K->fd2[i];
        else sn -= K->fd2[i];
    }
    for (i = 0; i < nf; i++) {
        if (K->fd2[i] > 0.0) { if (sp > 0.0) K->fd2[i] /= sp; }
        else if (sn > 0.0) K->fd2[i] /= sn;
    }
    return FOVM_OK;
}

/* Per-image FLIP preparation: Hunt-Lab planes (3) of the CSF-filtered
 * image and edge / point magnitude planes. Work planes: w0, w1. */
static void fovm__flip_prepare(const fovm__flipctx *ctx, const fovm__flipk *K,
                               fovm__conv *cv, const float *img, int c,
                               float *P0, float *P1, float *P2,
                               float *edge, float *point, float *w0, float *w1)
{
    size_t n = (size_t)cv->w * (size_t)cv->h, i;
    const double *m = fovm__rgb2xyz;
    /* 1. sRGB -> linear -> XYZ -> YCxCz; feature luminance Y/Yn in w0 */
    for (i = 0; i < n; i++) {
        double r, g, b, X, Y, Z, xn, yn, zn;
        if (c == 3) {
            r = fovm__srgb2lin((double)img[3 * i]);
            g = fovm__srgb2lin((double)img[3 * i + 1]);
            b = fovm__srgb2lin((double)img[3 * i + 2]);
        } else {
            r = g = b = fovm__srgb2lin((double)img[i]);
        }
        X = m[0] * r + m[1] * g + m[2] * b;
        Y = m[3] * r + m[4] * g + m[5] * b;
        Z = m[6] * r + m[7] * g + m[8] * b;
        xn = X / ctx->wx; yn = Y / ctx->wy; zn = Z / ctx->wz;
        P0[i] = (float)(116.0 * yn - 16.0);
        P1[i] = (float)(500.0 * (xn - yn));
        P2[i] = (float)(200.0 * (yn - zn));
        w0[i] = (float)yn;
    }
    /* 5. features on w0 (edge -> edge plane, point -> point plane) */
    fovm__conv_sep(cv, w0, edge, K->fd1, K->fg, K->rf);   /* d/dx */
    fovm__conv_sep(cv, w0, w1, K->fg, K->fd1, K->rf);     /* d/dy */
    for (i = 0; i < n; i++) {
        double a = (double)edge[i], b = (double)w1[i];
        edge[i] = (float)sqrt(a * a + b * b);
    }
    fovm__conv_sep(cv, w0, point, K->fd2, K->fg, K->rf);  /* d2/dx2 */
    fovm__conv_sep(cv, w0, w1, K->fg, K->fd2, K->rf);     /* d2/dy2 */
    for (i = 0; i < n; i++) {
        double a = (double)point[i], b = (double)w1[i];
        point[i] = (float)sqrt(a * a + b * b);
    }
    /* 2. CSF filtering */
    fovm__conv_sep(cv, P0, P0, K->ga, K->ga, K->rc);
    fovm__conv_sep(cv, P1, P1, K->grg, K->grg, K->rc);
    fovm__conv_sep(cv, P2, w0, K->gby2, K->gby2, K->rc);
    fovm__conv_sep(cv, P2, P2, K->gby1, K->gby1, K->rc);
    for (i = 0; i < n; i++)
        P2[i] = (float)(K->wby1 * (double)P2[i] + K->wby2 * (double)w0[i]);
    /* 3. back to linear RGB, clamp, to Hunt-adjusted L*a*b* */
    for (i = 0; i < n; i++) {
        const double *q = ctx->xyz2rgb;
        double yn = ((double)P0[i] + 16.0) / 116.0;
        double xn = (double)P1[i] / 500.0 + yn;
        double zn = yn - (double)P2[i] / 200.0;
        double X = xn * ctx->wx, Y = yn * ctx->wy, Z = zn * ctx->wz;
        double r = q[0] * X + q[1] * Y + q[2] * Z;
        double g = q[3] * X + q[4] * Y + q[5] * Z;
        double b = q[6] * X + q[7] * Y + q[8] * Z;
        double L, A, B;
        r = r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
        g = g < 0.0 ? 0.0 : (g > 1.0 ? 1.0 : g);
        b = b < 0.0 ? 0.0 : (b > 1.0 ? 1.0 : b);
        fovm__rgb2hunt(ctx, r, g, b, &L, &A, &B);
        P0[i] = (float)L; P1[i] = (float)A; P2[i] = (float)B;
    }
}

int fovm_flip(const float *ref, const float *test, int w, int h, int c,
              double ppd, double *mean, float *map)
{
    const double qc = 0.7, pc = 0.4, pt = 0.95, qf = 0.5;
    size_t n = fovm__n(w, h, c), np, i;
    fovm__flipctx ctx;
    fovm__flipk K;
    fovm__conv cv;
    float *mem, *pl[13];
    double cmax, sum = 0.0;
    int err, k;
    if (!ref || !test || n == 0) return FOVM_ERR_ARG;
    if (!(ppd > 0.0) || !(ppd < 1e6)) return FOVM_ERR_ARG;
    np = n / (size_t)c;
    if (np > ((size_t)-1) / (sizeof(float) * 14)) return FOVM_ERR_NOMEM;
    fovm__flip_init(&ctx);
    err = fovm__flipk_init(&K, ppd);
    if (err) return err;
    cv.w = w; cv.h = h;
    mem = (float *)malloc(np * 14 * sizeof(float));
    cv.acc = (double *)malloc((size_t)w * sizeof(double));
    cv.pad = (float *)malloc(((size_t)w + 2 * (size_t)(K.rc > K.rf ? K.rc : K.rf)) * sizeof(float));
    if (!mem || !cv.acc || !cv.pad) {
        free(mem); free(cv.acc); free(cv.pad); free(K.mem);
        return FOVM_ERR_NOMEM;
    }
    for (k = 0; k < 13; k++) pl[k] = mem + (size_t)k * np;
    cv.tmp = mem + 13 * np;
    /* ref: pl[0..4], test: pl[5..9], work: pl[10], pl[11] */
    fovm__flip_prepare(&ctx, &K, &cv, ref, c, pl[0], pl[1], pl[2], pl[3], pl[4], pl[10], pl[11]);
    fovm__flip_prepare(&ctx, &K, &cv, test, c, pl[5], pl[6], pl[7], pl[8], pl[9], pl[10], pl[11]);
    {
        double L1, A1, B1, L2, A2, B2;
        fovm__rgb2hunt(&ctx, 0.0, 1.0, 0.0, &L1, &A1, &B1);
        fovm__rgb2hunt(&ctx, 0.0, 0.0, 1.0, &L2, &A2, &B2);
        cmax = pow(fovm__hyab(L1, A1, B1, L2, A2, B2), qc);
    }
    for (i = 0; i < np; i++) {
        double e = pow(fovm__hyab((double)pl[0][i], (double)pl[1][i], (double)pl[2][i],
                                  (double)pl[5][i], (double)pl[6][i], (double)pl[7][i]), qc);
        double de = fabs((double)pl[3][i] - (double)pl[8][i]);
        double dp = fabs((double)pl[4][i] - (double)pl[9][i]);
        double df, dc, f;
        if (e < pc * cmax) dc = e * pt / (pc * cmax);
        else dc = pt + (e - pc * cmax) / (cmax - pc * cmax) * (1.0 - pt);
        df = pow((de > dp ? de : dp) / sqrt(2.0), qf);
        f = pow(dc, 1.0 - df);
        sum += f;
        if (map) map[i] = (float)f;
    }
    if (mean) *mean = sum / (double)np;
    free(mem); free(cv.acc); free(cv.pad); free(K.mem);
    return FOVM_OK;
}

int fovm_map_mean_sel(const float *map, int w, int h, const fovm_sel *sel,
                      double *mean, long *count)
{
    size_t n = fovm__n(w, h, 1), i;
    double sum = 0.0;
    long cnt = 0;
    if (!map || n == 0 || !fovm__sel_ok(sel)) return FOVM_ERR_ARG;
    for (i = 0; i < n; i++) {
        if (!fovm_sel_test(sel, i)) continue;
        sum += (double)map[i];
        cnt++;
    }
    if (mean) *mean = cnt ? sum / (double)cnt : fovm__nan();
    if (count) *count = cnt;
    return FOVM_OK;
}

int fovm_flip_sel(const float *ref, const float *test, int w, int h, int c,
                  double ppd, const fovm_sel *sel, double *mean, long *count)
{
    float *map;
    int err;
    size_t n = fovm__n(w, h, c);
    if (!ref || !test || n == 0 || !fovm__sel_ok(sel)) return FOVM_ERR_ARG;
    map = (float *)malloc(n / (size_t)c * sizeof(float));
    if (!map) return FOVM_ERR_NOMEM;
    err = fovm_flip(ref, test, w, h, c, ppd, NULL, map);
    if (!err) err = fovm_map_mean_sel(map, w, h, sel, mean, count);
    free(map);
    return err;
}

double fovm_ppd_from_viewing(double distance_m, double width_m, double width_px)
{
    const double PI = 3.14159265358979323846;
    return distance_m * (width_px / width_m) * PI / 180.0;
}

/* ---- eccentricity rings --------------------------------------------------- */

int fovm_ecc_rings(const float *ref, const float *test, int w, int h, int c,
                   const float *ecc, int nrings, double max_deg, double ppd,
                   fovm_ring *rings)
{
    size_t n = fovm__n(w, h, c), np;
    float *fmap = NULL, *smap = NULL;
    int err, i, have_ssim;
    if (!ref || !test || !ecc || !rings || n == 0 || nrings < 1) return FOVM_ERR_ARG;
    if (!(max_deg > 0.0) || !(ppd > 0.0)) return FOVM_ERR_ARG;
    np = n / (size_t)c;
    have_ssim = w >= FOVM_SSIM_WIN && h >= FOVM_SSIM_WIN;
    fmap = (float *)malloc(np * sizeof(float));
    if (have_ssim)
        smap = (float *)malloc((size_t)(w - 10) * (size_t)(h - 10) * sizeof(float));
    if (!fmap || (have_ssim && !smap)) { free(fmap); free(smap); return FOVM_ERR_NOMEM; }
    err = fovm_flip(ref, test, w, h, c, ppd, NULL, fmap);
    if (!err && have_ssim) err = fovm_ssim(ref, test, w, h, c, NULL, smap);
    for (i = 0; !err && i < nrings; i++) {
        fovm_ring *r = rings + i;
        fovm_sel sel;
        r->lo = max_deg * (double)i / (double)nrings;
        r->hi = i == nrings - 1 ? max_deg : max_deg * (double)(i + 1) / (double)nrings;
        sel = fovm_sel_band(ecc, r->lo, r->hi);
        err = fovm_mse_sel(ref, test, w, h, c, &sel, &r->mse, &r->count);
        if (err) break;
        r->psnr = fovm_psnr_from_mse(r->mse);
        err = fovm_map_mean_sel(fmap, w, h, &sel, &r->flip, NULL);
        if (err) break;
        if (have_ssim) {
            err = fovm_ssim_map_mean_sel(smap, w, h, &sel, &r->ssim, &r->ssim_count);
        } else {
            r->ssim = fovm__nan();
            r->ssim_count = 0;
        }
    }
    free(fmap);
    free(smap);
    return err;
}

/* ---- the eye: filter to its resolution, perceptual error ------------------ */

#define FOVM__PI 3.14159265358979323846
#define FOVM__EYE_K 0.37478125  /* sqrt(2 ln 2) / pi: response 1/2 at 1 / (2 MAR) */
#define FOVM__SIG_MIN 0.2       /* below: the pixel is copied */
#define FOVM__SIG_STEP 1.005    /* sigma quantisation ratio */

static int fovm__finite(double x)
{
    return fabs(x) <= 1.7976931348623157e308;
}

fovm_eye fovm_eye_from_fov(int w, int h, double fov_y_deg, double gx, double gy)
{
    fovm_eye e;
    memset(&e, 0, sizeof e);
    e.cx = 0.5 * (double)w;
    e.cy = 0.5 * (double)h;
    if (fov_y_deg > 0.0 && fov_y_deg < 180.0)
        e.f_px = 0.5 * (double)h / tan(0.5 * fov_y_deg * FOVM__PI / 180.0);
    e.gx = gx;
    e.gy = gy;
    return e;
}

fovm_eye fovm_eye_from_monitor(int w, int h, double pixel_pitch_mm, double distance_mm,
                               double gx, double gy)
{
    fovm_eye e = fovm_eye_from_fov(w, h, 0.0, gx, gy);
    if (pixel_pitch_mm > 0.0 && distance_mm > 0.0) e.f_px = distance_mm / pixel_pitch_mm;
    return e;
}

/* MAR model in degrees (defaults for 0 fields); 0 for an invalid eye. */
static int fovm__eye_get(const fovm_eye *e, double *m0, double *sl)
{
    double a, b;
    if (!e) return 0;
    if (!fovm__finite(e->cx) || !fovm__finite(e->cy) || !fovm__finite(e->gx) ||
        !fovm__finite(e->gy) || !fovm__finite(e->f_px) || !(e->f_px > 0.0) ||
        !(e->f_px < 1e12) || !(fabs(e->cx) < 1e12) || !(fabs(e->cy) < 1e12) ||
        !(fabs(e->gx) < 1e12) || !(fabs(e->gy) < 1e12))
        return 0;
    a = e->mar0_arcmin; b = e->slope_arcmin;
    if (!(a >= 0.0 && a <= 60.0) || !(b >= 0.0 && b <= 60.0)) return 0;
    if (!(a > 0.0)) a = 1.0;
    if (!(b > 0.0)) b = 1.32;
    *m0 = a / 60.0;
    *sl = b / 60.0;
    return 1;
}

int fovm_eye_check(const fovm_eye *eye)
{
    double a, b;
    return fovm__eye_get(eye, &a, &b) ? FOVM_OK : FOVM_ERR_ARG;
}

/* angle in degrees between v = (vx, vy, f) and the unit gaze direction g */
static double fovm__angle(double vx, double vy, double f, const double g[3])
{
    double c0 = vy * g[2] - f * g[1], c1 = f * g[0] - vx * g[2], c2 = vx * g[1] - vy * g[0];
    return atan2(sqrt(c0 * c0 + c1 * c1 + c2 * c2), vx * g[0] + vy * g[1] + f * g[2]) *
           (180.0 / FOVM__PI);
}

static void fovm__gaze_dir(const fovm_eye *e, double g[3])
{
    double n;
    g[0] = e->gx - e->cx; g[1] = e->gy - e->cy; g[2] = e->f_px;
    n = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    g[0] /= n; g[1] /= n; g[2] /= n;
}

double fovm_eye_ecc(const fovm_eye *eye, double x, double y)
{
    double a, b, g[3];
    if (!fovm__eye_get(eye, &a, &b) || !fovm__finite(x) || !fovm__finite(y)) return fovm__nan();
    fovm__gaze_dir(eye, g);
    return fovm__angle(x - eye->cx, y - eye->cy, eye->f_px, g);
}

double fovm_eye_mar_deg(const fovm_eye *eye, double ecc)
{
    double a, b;
    if (!fovm__eye_get(eye, &a, &b) || !(ecc >= 0.0 && ecc <= 180.0)) return fovm__nan();
    return a + b * ecc;
}

double fovm_eye_ppd(const fovm_eye *eye)
{
    double a, b, rx, ry;
    if (!fovm__eye_get(eye, &a, &b)) return fovm__nan();
    rx = eye->gx - eye->cx; ry = eye->gy - eye->cy;
    return (eye->f_px * eye->f_px + rx * rx + ry * ry) / eye->f_px * (FOVM__PI / 180.0);
}

/* sigma in pixels along x and y at image point (x, y) */
static void fovm__eye_sig(const fovm_eye *e, double m0, double sl, const double g[3],
                          double x, double y, double *sx, double *sy)
{
    double vx = x - e->cx, vy = y - e->cy, f = e->f_px;
    double n2 = vx * vx + vy * vy + f * f;
    double s = FOVM__EYE_K * (m0 + sl * fovm__angle(vx, vy, f, g)) * (FOVM__PI / 180.0);
    *sx = s * n2 / sqrt(f * f + vy * vy);
    *sy = s * n2 / sqrt(f * f + vx * vx);
}

int fovm_eye_sigma(const fovm_eye *eye, int i, int j, double *sigma_x, double *sigma_y)
{
    double a, b, g[3], sx, sy;
    if (!fovm__eye_get(eye, &a, &b)) return FOVM_ERR_ARG;
    fovm__gaze_dir(eye, g);
    fovm__eye_sig(eye, a, b, g, (double)i + 0.5, (double)j + 0.5, &sx, &sy);
    if (sigma_x) *sigma_x = sx;
    if (sigma_y) *sigma_y = sy;
    return FOVM_OK;
}

/* quantised sigma index: -1 below FOVM__SIG_MIN (copy), else round(log_step(s / min)) */
static int fovm__sig_q(double s)
{
    double q;
    if (!(s >= FOVM__SIG_MIN)) return -1;
    if (s > FOVM_EYE_SIGMA_MAX) s = FOVM_EYE_SIGMA_MAX;
    q = floor(log(s / FOVM__SIG_MIN) / log(FOVM__SIG_STEP) + 0.5);
    return (int)q;
}

static double fovm__lin2srgb(double v)
{
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

/* Kernels for quantised sigmas qlo..qhi: taps + off[q - qlo], radius rad[q - qlo]. */
typedef struct fovm__ktab {
    int qlo, nq, rmax;
    int *off, *rad;
    float *taps;
} fovm__ktab;

static int fovm__ktab_init(fovm__ktab *T, int qlo, int qhi)
{
    int q, i;
    size_t total = 0;
    memset(T, 0, sizeof *T);
    if (qhi < qlo) return FOVM_OK;
    T->qlo = qlo; T->nq = qhi - qlo + 1;
    T->off = (int *)malloc((size_t)T->nq * 2 * sizeof(int));
    if (!T->off) return FOVM_ERR_NOMEM;
    T->rad = T->off + T->nq;
    for (q = qlo; q <= qhi; q++) {
        double s = FOVM__SIG_MIN * pow(FOVM__SIG_STEP, (double)q);
        int r = (int)ceil(3.5 * s);
        T->rad[q - qlo] = r;
        T->off[q - qlo] = (int)total;
        total += (size_t)(2 * r + 1);
        if (r > T->rmax) T->rmax = r;
    }
    T->taps = (float *)malloc(total * sizeof(float));
    if (!T->taps) { free(T->off); T->off = NULL; return FOVM_ERR_NOMEM; }
    for (q = qlo; q <= qhi; q++) {
        double s = FOVM__SIG_MIN * pow(FOVM__SIG_STEP, (double)q), sum = 0.0;
        int r = T->rad[q - qlo];
        float *k = T->taps + T->off[q - qlo];
        for (i = -r; i <= r; i++) sum += exp(-(double)(i * i) / (2.0 * s * s));
        for (i = -r; i <= r; i++) k[i + r] = (float)(exp(-(double)(i * i) / (2.0 * s * s)) / sum);
    }
    return FOVM_OK;
}

/* Filter each row of the w x h plane p in place; Q[y*w + x] is the kernel index of the
 * output pixel (-1: copy). pad has room for w + 2 rmax floats. */
static void fovm__rows_var(float *p, int w, int h, const int *Q, const fovm__ktab *T, float *pad)
{
    int x, y, j, R = T->rmax;
    for (y = 0; y < h; y++) {
        float *row = p + (size_t)y * (size_t)w;
        const int *qr = Q + (size_t)y * (size_t)w;
        for (x = 0; x < w + 2 * R; x++) {
            int xx = x - R;
            xx = xx < 0 ? 0 : (xx > w - 1 ? w - 1 : xx);
            pad[x] = row[xx];
        }
        for (x = 0; x < w; x++) {
            int q = qr[x], r, n;
            const float *k, *s;
            float a0 = 0.0f, a1 = 0.0f, a2 = 0.0f, a3 = 0.0f;
            if (q < 0) continue; /* row[x] is already the copy */
            r = T->rad[q - T->qlo];
            k = T->taps + T->off[q - T->qlo];
            s = pad + R + x - r;
            n = 2 * r + 1;
            for (j = 0; j + 3 < n; j += 4) {
                a0 += k[j] * s[j];
                a1 += k[j + 1] * s[j + 1];
                a2 += k[j + 2] * s[j + 2];
                a3 += k[j + 3] * s[j + 3];
            }
            for (; j < n; j++) a0 += k[j] * s[j];
            row[x] = (a0 + a1) + (a2 + a3);
        }
    }
}

/* dst (h x w) = transpose of src (w x h) */
static void fovm__transpose(const float *src, float *dst, int w, int h)
{
    int x, y, bx, by;
    const int B = 32;
    for (by = 0; by < h; by += B)
        for (bx = 0; bx < w; bx += B)
            for (y = by; y < by + B && y < h; y++)
                for (x = bx; x < bx + B && x < w; x++)
                    dst[(size_t)x * (size_t)h + (size_t)y] = src[(size_t)y * (size_t)w + (size_t)x];
}

int fovm_eye_filter(const float *img, int w, int h, int c, const fovm_eye *eye, float *out)
{
    size_t n = fovm__n(w, h, c), np, i;
    double m0, sl, g[3];
    int *qx = NULL, *qyt = NULL, qlo = 1 << 30, qhi = -1, x, y, ch, err;
    float *pa = NULL, *pb = NULL, *pad = NULL;
    fovm__ktab T;
    if (!img || !out || n == 0) return FOVM_ERR_ARG;
    if (!fovm__eye_get(eye, &m0, &sl)) return FOVM_ERR_ARG;
    np = n / (size_t)c;
    if (np > ((size_t)-1) / 16) return FOVM_ERR_NOMEM;
    qx = (int *)malloc(np * sizeof(int));
    qyt = (int *)malloc(np * sizeof(int));
    pa = (float *)malloc(np * sizeof(float));
    pb = (float *)malloc(np * sizeof(float));
    if (!qx || !qyt || !pa || !pb) {
        free(qx); free(qyt); free(pa); free(pb);
        return FOVM_ERR_NOMEM;
    }
    fovm__gaze_dir(eye, g);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double sx, sy;
            int a, b;
            fovm__eye_sig(eye, m0, sl, g, (double)x + 0.5, (double)y + 0.5, &sx, &sy);
            a = fovm__sig_q(sx);
            b = fovm__sig_q(sy);
            qx[(size_t)y * (size_t)w + (size_t)x] = a;
            qyt[(size_t)x * (size_t)h + (size_t)y] = b;
            if (a >= 0) { if (a < qlo) qlo = a; if (a > qhi) qhi = a; }
            if (b >= 0) { if (b < qlo) qlo = b; if (b > qhi) qhi = b; }
        }
    err = fovm__ktab_init(&T, qlo, qhi);
    if (!err) {
        pad = (float *)malloc(((size_t)(w > h ? w : h) + 2 * (size_t)T.rmax) * sizeof(float));
        if (!pad) err = FOVM_ERR_NOMEM;
    }
    for (ch = 0; !err && ch < c; ch++) {
        for (i = 0; i < np; i++) {
            double v = (double)img[i * (size_t)c + (size_t)ch];
            v = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
            pa[i] = (float)fovm__srgb2lin(v);
        }
        if (qhi >= 0) {
            fovm__rows_var(pa, w, h, qx, &T, pad);
            fovm__transpose(pa, pb, w, h);
            fovm__rows_var(pb, h, w, qyt, &T, pad);
            fovm__transpose(pb, pa, h, w);
        }
        for (i = 0; i < np; i++) {
            double v = (double)pa[i];
            v = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
            out[i * (size_t)c + (size_t)ch] = (float)fovm__lin2srgb(v);
        }
    }
    free(qx); free(qyt); free(pa); free(pb); free(pad);
    if (T.off) free(T.off);
    if (T.taps) free(T.taps);
    return err;
}

int fovm_perceptual(const float *ref, const float *test, int w, int h, int c,
                    const fovm_eye *eye, double *psnr, double *flip, float *map)
{
    size_t n = fovm__n(w, h, c);
    float *fr, *ft;
    double ppd, p = 0.0, f = 0.0;
    int err;
    if (!ref || !test || n == 0 || fovm_eye_check(eye) != FOVM_OK) return FOVM_ERR_ARG;
    ppd = fovm_eye_ppd(eye);
    if (!(ppd > 0.0) || !(ppd < 1e6)) return FOVM_ERR_ARG;
    fr = (float *)malloc(n * sizeof(float));
    ft = (float *)malloc(n * sizeof(float));
    if (!fr || !ft) { free(fr); free(ft); return FOVM_ERR_NOMEM; }
    err = fovm_eye_filter(ref, w, h, c, eye, fr);
    if (!err) err = fovm_eye_filter(test, w, h, c, eye, ft);
    if (!err) err = fovm_psnr(fr, ft, w, h, c, &p);
    if (!err && (flip || map)) err = fovm_flip(fr, ft, w, h, c, ppd, &f, map);
    if (!err) {
        if (psnr) *psnr = p;
        if (flip) *flip = f;
    }
    free(fr); free(ft);
    return err;
}

#ifdef __cplusplus
}
#endif

#endif /* FOVM_IMPLEMENTATION_DONE */
#endif /* FOVM_IMPLEMENTATION */
