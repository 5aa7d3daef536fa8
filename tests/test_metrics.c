/*
 * test_metrics.c - unit tests for tests/common/fovimg.h and
 * examples/fovmetrics.h.
 *
 * Build and run (from the repository root; no data files are needed, the
 * file-format checks write temporary files to $TMPDIR or /tmp):
 *   gcc -std=c99 -O2 -Itests/common tests/test_metrics.c -lm \
 *       -o /tmp/test_metrics && /tmp/test_metrics
 *
 * Output: one "PASS name" / "FAIL name: detail" line per check, then
 * "N passed, M failed"; exit status 1 if any check failed. PNG/EXR checks
 * need oiiotool; without it they only check the FOVIMG_ERR_NOTOOL result.
 */
#define FOVIMG_IMPLEMENTATION
#include "fovimg.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <math.h>

typedef struct T {
    int pass, fail;
    char tmpdir[512];
    char tag[64]; /* the program's name: two builds of this test may run at once */
} T;

static void check(T *t, int ok, const char *name, const char *fmt, ...)
{
    if (ok) {
        printf("PASS %s\n", name);
        t->pass++;
    } else {
        va_list ap;
        printf("FAIL %s: ", name);
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        printf("\n");
        t->fail++;
    }
}

static int near(double a, double b, double tol)
{
    return fabs(a - b) <= tol;
}

/* deterministic PRNG in [0,1) */
static float rnd(unsigned int *s)
{
    unsigned int x = *s;
    x ^= x << 13; x ^= x >> 17; x ^= x << 5;
    *s = x;
    return (float)(x >> 8) / 16777216.0f;
}

static void tmppath(const T *t, char *buf, size_t sz, const char *name)
{
    snprintf(buf, sz, "%s/fov_test_metrics_%s_%s", t->tmpdir, t->tag, name);
}

static int write_bytes(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    size_t k;
    if (!f) return -1;
    k = fwrite(data, 1, n, f);
    fclose(f);
    return k == n ? 0 : -1;
}

/* ======================================================================= */
/* fovimg                                                                   */
/* ======================================================================= */

static void test_alloc(T *t)
{
    fovimg a;
    int e;
    e = fovimg_alloc(&a, 4, 3, 3);
    check(t, e == 0 && a.w == 4 && a.h == 3 && a.c == 3 && a.px && a.px[35] == 0.0f,
          "img_alloc", "err %d", e);
    fovimg_free(&a);
    check(t, a.px == NULL && a.w == 0, "img_free_resets", "px %p", (void *)a.px);
    check(t, fovimg_alloc(&a, 4, 3, 2) == FOVIMG_ERR_ARG, "img_alloc_rejects_c2", "");
    check(t, fovimg_alloc(&a, 0, 3, 1) == FOVIMG_ERR_SIZE, "img_alloc_rejects_w0", "");
    check(t, fovimg_alloc(&a, 65537, 1, 1) == FOVIMG_ERR_SIZE, "img_alloc_rejects_huge", "");
}

static void test_srgb(T *t)
{
    double maxerr = 0.0;
    int i;
    /* ((0.5 + 0.055) / 1.055)^2.4 = 0.2140411405 */
    check(t, near((double)fovimg_srgb_to_linear(0.5f), 0.2140411405, 1e-7),
          "srgb_to_linear_0.5", "got %.9f", (double)fovimg_srgb_to_linear(0.5f));
    /* linear segment: 0.04 / 12.92 = 0.0030959752 */
    check(t, near((double)fovimg_srgb_to_linear(0.04f), 0.0030959752, 1e-9),
          "srgb_to_linear_linear_segment", "got %.10f", (double)fovimg_srgb_to_linear(0.04f));
    /* 1.055 * 0.18^(1/2.4) - 0.055 = 0.4613561295 */
    check(t, near((double)fovimg_linear_to_srgb(0.18f), 0.4613561295, 1e-7),
          "linear_to_srgb_0.18", "got %.9f", (double)fovimg_linear_to_srgb(0.18f));
    /* 0.002 * 12.92 = 0.02584 */
    check(t, near((double)fovimg_linear_to_srgb(0.002f), 0.02584, 1e-8),
          "linear_to_srgb_linear_segment", "got %.9f", (double)fovimg_linear_to_srgb(0.002f));
    check(t, fovimg_srgb_to_linear(0.0f) == 0.0f && fovimg_srgb_to_linear(1.0f) == 1.0f &&
          fovimg_linear_to_srgb(1.0f) == 1.0f, "srgb_endpoints", "");
    for (i = 0; i <= 1000; i++) {
        float v = (float)i / 1000.0f;
        double e = fabs((double)fovimg_linear_to_srgb(fovimg_srgb_to_linear(v)) - (double)v);
        if (e > maxerr) maxerr = e;
    }
    check(t, maxerr < 1e-6, "srgb_roundtrip", "max error %g", maxerr);
}

static void test_u8(T *t)
{
    check(t, fovimg_float_to_u8(0.5f) == 128, "u8_round_half_up", "got %d", fovimg_float_to_u8(0.5f));
    check(t, fovimg_float_to_u8(0.499f) == 127, "u8_round_down", "got %d", fovimg_float_to_u8(0.499f));
    check(t, fovimg_float_to_u8(-1.0f) == 0 && fovimg_float_to_u8(2.0f) == 255,
          "u8_clamp", "");
    check(t, fovimg_float_to_u8((float)NAN) == 0, "u8_nan_is_0", "");
    {
        int v, ok = 1;
        for (v = 0; v < 256; v++)
            if (fovimg_float_to_u8(fovimg_u8_to_float((unsigned char)v)) != v) ok = 0;
        check(t, ok, "u8_float_roundtrip_all_256", "");
    }
}

static void test_pnm(T *t)
{
    char p[1024];
    fovimg a, b;
    int e, x, same = 1;
    size_t i;
    /* RGB 3x2 with 8-bit representable values */
    fovimg_alloc(&a, 3, 2, 3);
    for (i = 0; i < 18; i++) a.px[i] = fovimg_u8_to_float((unsigned char)(i * 14 + 3));
    tmppath(t, p, sizeof p, "rt.ppm");
    e = fovimg_write_pnm(p, &a);
    if (!e) e = fovimg_read_pnm(p, &b);
    if (!e) {
        same = b.w == 3 && b.h == 2 && b.c == 3;
        for (i = 0; same && i < 18; i++) same = a.px[i] == b.px[i];
        fovimg_free(&b);
    }
    check(t, e == 0 && same, "ppm_roundtrip_exact", "err %d", e);
    /* raw bytes: header + top row first */
    {
        FILE *f = fopen(p, "rb");
        char buf[32];
        size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
        if (f) fclose(f);
        check(t, n == 11 + 18 && memcmp(buf, "P6\n3 2\n255\n", 11) == 0 &&
              (unsigned char)buf[11] == 3 && (unsigned char)buf[12] == 17,
              "ppm_layout", "n %lu", (unsigned long)n);
    }
    remove(p);
    fovimg_free(&a);
    /* grey */
    fovimg_alloc(&a, 5, 1, 1);
    for (x = 0; x < 5; x++) a.px[x] = (float)x / 4.0f;  /* 0, .25, .5, .75, 1 */
    tmppath(t, p, sizeof p, "rt.pgm");
    e = fovimg_write_any(p, &a);
    if (!e) e = fovimg_read_any(p, &b);
    if (!e) {
        /* 0.25*255 = 63.75 -> 64; 0.5 -> 128; 0.75*255 = 191.25 -> 191 */
        same = b.c == 1 && b.px[0] == 0.0f && b.px[1] == 64.0f / 255.0f &&
               b.px[2] == 128.0f / 255.0f && b.px[3] == 191.0f / 255.0f && b.px[4] == 1.0f;
        fovimg_free(&b);
    }
    check(t, e == 0 && same, "pgm_roundtrip_quantised", "err %d", e);
    remove(p);
    fovimg_free(&a);
    /* 16-bit and odd maxval, with a comment in the header */
    {
        static const unsigned char f16[] = "P5\n# comment\n2 1\n65535\n\x80\x00\xff\xff";
        static const unsigned char f10[] = "P5 3 1 1000 \x03\xe8\x01\xf4\x00\x00";
        tmppath(t, p, sizeof p, "16.pgm");
        write_bytes(p, f16, sizeof f16 - 1);
        e = fovimg_read_pnm(p, &b);
        check(t, e == 0 && b.w == 2 && b.h == 1 &&
              near((double)b.px[0], 32768.0 / 65535.0, 1e-7) && b.px[1] == 1.0f,
              "pgm_16bit_read", "err %d", e);
        fovimg_free(&b);
        write_bytes(p, f10, sizeof f10 - 1);
        e = fovimg_read_pnm(p, &b);
        check(t, e == 0 && b.w == 3 && b.px[0] == 1.0f && near((double)b.px[1], 0.5, 1e-7) &&
              b.px[2] == 0.0f, "pgm_maxval_1000", "err %d", e);
        fovimg_free(&b);
        remove(p);
    }
}

static void test_pfm(T *t)
{
    char p[1024];
    fovimg a, b;
    int e, same = 1;
    size_t i;
    static const float vals[6] = {0.1f, -2.5f, 1e-30f, 3.0e20f, 0.5f, 1.0f / 3.0f};
    fovimg_alloc(&a, 2, 1, 3);
    memcpy(a.px, vals, sizeof vals);
    tmppath(t, p, sizeof p, "rt.pfm");
    e = fovimg_write_pfm(p, &a);
    if (!e) e = fovimg_read_any(p, &b);
    if (!e) {
        same = b.w == 2 && b.h == 1 && b.c == 3;
        for (i = 0; same && i < 6; i++) same = memcmp(&a.px[i], &b.px[i], 4) == 0;
        fovimg_free(&b);
    }
    check(t, e == 0 && same, "pfm_rgb_roundtrip_exact", "err %d", e);
    fovimg_free(&a);
    /* grey 1x2: top = 1.0, bottom = 2.0 -> file stores bottom row first */
    fovimg_alloc(&a, 1, 2, 1);
    a.px[0] = 1.0f; a.px[1] = 2.0f;
    e = fovimg_write_pfm(p, &a);
    {
        FILE *f = fopen(p, "rb");
        unsigned char buf[64];
        size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
        if (f) fclose(f);
        /* "Pf\n1 2\n-1.0\n" is 12 bytes; 2.0f = 0x40000000 little-endian */
        check(t, e == 0 && n == 20 && memcmp(buf, "Pf\n1 2\n-1.0\n", 12) == 0 &&
              buf[12] == 0 && buf[13] == 0 && buf[14] == 0 && buf[15] == 0x40 &&
              buf[19] == 0x3f, "pfm_layout_bottom_up_little_endian", "n %lu", (unsigned long)n);
    }
    e = fovimg_read_pfm(p, &b);
    check(t, e == 0 && b.c == 1 && b.px[0] == 1.0f && b.px[1] == 2.0f,
          "pfm_grey_roundtrip_flip", "err %d", e);
    fovimg_free(&b);
    fovimg_free(&a);
    /* big-endian file (positive scale), 2x1 grey: 1.0, -2.0 */
    {
        static const unsigned char be[] = "Pf\n2 1\n1.0\n\x3f\x80\x00\x00\xc0\x00\x00\x00";
        write_bytes(p, be, sizeof be - 1);
        e = fovimg_read_pfm(p, &b);
        check(t, e == 0 && b.px[0] == 1.0f && b.px[1] == -2.0f, "pfm_big_endian_read", "err %d", e);
        fovimg_free(&b);
    }
    remove(p);
}

static void test_malformed(T *t)
{
    struct { const char *name, *data; size_t len; int ext_pfm; int want; } cases[] = {
        {"bad_magic_P3", "P3\n1 1\n255\n0 0 0\n", 17, 0, FOVIMG_ERR_FORMAT},
        {"bad_magic_garbage", "hello world", 11, 0, FOVIMG_ERR_FORMAT},
        {"empty_file", "", 0, 0, FOVIMG_ERR_FORMAT},
        {"truncated_header", "P6\n12", 5, 0, FOVIMG_ERR_IO},
        {"truncated_data", "P6\n2 2\n255\nabcdef", 17, 0, FOVIMG_ERR_IO},
        {"huge_width", "P6\n70000 1\n255\n", 15, 0, FOVIMG_ERR_SIZE},
        {"huge_digits", "P6\n99999999999999999999 1\n255\n", 30, 0, FOVIMG_ERR_SIZE},
        {"max_dims_no_data", "P6\n65536 65536\n255\nxyz", 22, 0, FOVIMG_ERR_IO},
        {"zero_width", "P5\n0 4\n255\n", 11, 0, FOVIMG_ERR_SIZE},
        {"maxval_zero", "P5\n1 1\n0\nx", 11, 0, FOVIMG_ERR_FORMAT},
        {"maxval_too_big", "P5\n1 1\n70000\nxx", 16, 0, FOVIMG_ERR_SIZE},
        {"non_numeric", "P5\nab 1\n255\nx", 13, 0, FOVIMG_ERR_FORMAT},
        {"sample_above_maxval", "P5\n1 1\n100\n\xc8", 12, 0, FOVIMG_ERR_FORMAT},
        {"pfm_bad_scale", "PF\n1 1\nabc\n0123456789ab", 23, 1, FOVIMG_ERR_FORMAT},
        {"pfm_zero_scale", "PF\n1 1\n0.0\n0123456789ab", 23, 1, FOVIMG_ERR_FORMAT},
        {"pfm_truncated", "PF\n2 2\n-1.0\n0123", 16, 1, FOVIMG_ERR_IO},
        {"pfm_huge", "Pf\n65536 65536\n-1.0\n0000", 24, 1, FOVIMG_ERR_IO},
        {"pfm_bad_magic", "PX\n1 1\n-1.0\n0000", 16, 1, FOVIMG_ERR_FORMAT}
    };
    size_t k;
    char p[1024], name[128];
    fovimg b;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        int e;
        tmppath(t, p, sizeof p, cases[k].ext_pfm ? "bad.pfm" : "bad.ppm");
        write_bytes(p, cases[k].data, cases[k].len);
        b.px = (float *)&k; /* garbage: must be reset on failure */
        e = cases[k].ext_pfm ? fovimg_read_pfm(p, &b) : fovimg_read_pnm(p, &b);
        snprintf(name, sizeof name, "reject_%s", cases[k].name);
        check(t, e == cases[k].want && b.px == NULL && b.w == 0, name,
              "got %d (%s), want %d", e, fovimg_strerror(e), cases[k].want);
        if (!e) fovimg_free(&b);
        remove(p);
    }
    tmppath(t, p, sizeof p, "does_not_exist.ppm");
    check(t, fovimg_read_pnm(p, &b) == FOVIMG_ERR_OPEN, "reject_missing_file", "");
    check(t, fovimg_read_any("x.bmp", &b) == FOVIMG_ERR_UNSUPPORTED, "reject_unknown_ext", "");
    {
        fovimg a;
        fovimg_alloc(&a, 1, 1, 1);
        check(t, fovimg_write_any("x.jpeg", &a) == FOVIMG_ERR_UNSUPPORTED,
              "write_unknown_ext", "");
        check(t, fovimg_write_pnm("/nonexistent_dir_fov/x.ppm", &a) == FOVIMG_ERR_OPEN,
              "write_unwritable_path", "");
        fovimg_free(&a);
    }
}

static void test_oiio(T *t)
{
    char p[1024];
    fovimg a, b;
    int e, same = 0;
    size_t i;
    if (!fovimg_have_oiiotool()) {
        tmppath(t, p, sizeof p, "x.png");
        fovimg_alloc(&a, 2, 2, 3);
        check(t, fovimg_write_any(p, &a) == FOVIMG_ERR_NOTOOL, "png_without_oiiotool", "");
        fovimg_free(&a);
        return;
    }
    fovimg_alloc(&a, 4, 3, 3);
    for (i = 0; i < 36; i++) a.px[i] = fovimg_u8_to_float((unsigned char)(i * 7));
    tmppath(t, p, sizeof p, "rt.png");
    e = fovimg_write_any(p, &a);
    if (!e) e = fovimg_read_any(p, &b);
    if (!e) {
        same = b.w == 4 && b.h == 3 && b.c == 3;
        for (i = 0; same && i < 36; i++) same = a.px[i] == b.px[i];
        fovimg_free(&b);
    }
    check(t, e == 0 && same, "png_roundtrip_exact (oiiotool)", "err %d (%s)", e, fovimg_strerror(e));
    remove(p);
    for (i = 0; i < 36; i++) a.px[i] = (float)i * 0.37f - 3.0f;
    tmppath(t, p, sizeof p, "rt.exr");
    e = fovimg_write_any(p, &a);
    if (!e) e = fovimg_read_any(p, &b);
    same = 0;
    if (!e) {
        same = b.w == 4 && b.h == 3 && b.c == 3;
        for (i = 0; same && i < 36; i++) same = a.px[i] == b.px[i];
        fovimg_free(&b);
    }
    check(t, e == 0 && same, "exr_roundtrip_exact (oiiotool)", "err %d (%s)", e, fovimg_strerror(e));
    remove(p);
    fovimg_free(&a);
    fovimg_alloc(&a, 3, 2, 1);
    for (i = 0; i < 6; i++) a.px[i] = (float)i / 5.0f;
    tmppath(t, p, sizeof p, "grey.exr");
    e = fovimg_write_any(p, &a);
    if (!e) e = fovimg_read_any(p, &b);
    same = 0;
    if (!e) {
        same = b.c == 1 && b.w == 3;
        for (i = 0; same && i < 6; i++) same = a.px[i] == b.px[i];
        fovimg_free(&b);
    }
    check(t, e == 0 && same, "exr_grey_roundtrip (oiiotool)", "err %d (%s)", e, fovimg_strerror(e));
    remove(p);
    fovimg_free(&a);
    tmppath(t, p, sizeof p, "missing.png");
    check(t, fovimg_read_any(p, &b) == FOVIMG_ERR_OPEN, "png_missing_file", "");
}

/* ======================================================================= */
/* MSE / PSNR / selections                                                 */
/* ======================================================================= */

static void test_mse(T *t)
{
    /* grey 2x2: diffs 0.1, 0, 0.2, 0 -> squares 0.01 + 0.04 = 0.05, /4 */
    static const float r1[4] = {0.0f, 0.5f, 1.0f, 0.25f};
    static const float t1[4] = {0.1f, 0.5f, 0.8f, 0.25f};
    /* RGB 2x1: diffs 0.5 (R of px 0) and 0.5 (B of px 1): 0.5 / 6 samples */
    static const float r2[6] = {0, 0, 0, 1, 1, 1};
    static const float t2[6] = {0.5f, 0, 0, 1, 1, 0.5f};
    double m = -1, ps = -1, rm = -1;
    int e;
    e = fovm_mse(r1, t1, 2, 2, 1, &m);
    check(t, e == 0 && near(m, 0.0125, 1e-8), "mse_grey_2x2", "mse %.9g", m);
    fovm_rmse(r1, t1, 2, 2, 1, &rm);
    /* sqrt(0.0125) = 0.1118033989 */
    check(t, near(rm, 0.1118033989, 1e-8), "rmse_grey_2x2", "rmse %.9g", rm);
    fovm_psnr(r1, t1, 2, 2, 1, &ps);
    /* 10 log10(1/0.0125) = 10 log10(80) = 19.03089987 */
    check(t, near(ps, 19.03089987, 1e-6), "psnr_grey_2x2", "psnr %.9g", ps);
    fovm_mse(r2, t2, 2, 1, 3, &m);
    fovm_psnr(r2, t2, 2, 1, 3, &ps);
    /* 0.5/6 = 0.0833333; 10 log10(12) = 10.79181246 */
    check(t, near(m, 0.5 / 6.0, 1e-9) && near(ps, 10.79181246, 1e-6), "mse_psnr_rgb_2x1",
          "mse %.9g psnr %.9g", m, ps);
    fovm_psnr(r2, r2, 2, 1, 3, &ps);
    fovm_mse(r2, r2, 2, 1, 3, &m);
    check(t, m == 0.0 && isinf(ps) && ps > 0, "psnr_identical_is_inf", "psnr %g", ps);
    check(t, isnan(fovm_psnr_from_mse(-1.0)) && near(fovm_psnr_from_mse(0.01), 20.0, 1e-12),
          "psnr_from_mse", "");
    check(t, fovm_mse(r1, t1, 0, 2, 1, &m) == FOVM_ERR_ARG &&
          fovm_mse(NULL, t1, 2, 2, 1, &m) == FOVM_ERR_ARG &&
          fovm_mse(r1, t1, 2, 2, 2, &m) == FOVM_ERR_ARG, "mse_bad_args", "");
}

static void test_sel(T *t)
{
    /* 4x1 grey; per-pixel squared errors 0.01, 0.04, 0.09, 0.16 */
    static const float r[4] = {0.5f, 0.5f, 0.5f, 0.5f};
    static const float s[4] = {0.6f, 0.3f, 0.8f, 0.1f};
    static const float ecc[4] = {0.0f, 1.0f, 2.0f, 3.0f};
    static const unsigned char mask[4] = {1, 0, 1, 0};
    float eccn[4] = {0.0f, 1.0f, 2.0f, 3.0f};
    fovm_sel sel;
    double m = 0;
    long cnt = -1;
    sel = fovm_sel_band(ecc, 1.0, 3.0);        /* pixels 1, 2: (0.04+0.09)/2 */
    fovm_mse_sel(r, s, 4, 1, 1, &sel, &m, &cnt);
    check(t, cnt == 2 && near(m, 0.065, 1e-7), "sel_band_mse", "count %ld mse %.9g", cnt, m);
    check(t, fovm_sel_count(&sel, 4, 1) == 2, "sel_band_count", "");
    sel = fovm_sel_band(ecc, 3.0, 3.0);        /* empty: lo <= v < hi */
    fovm_mse_sel(r, s, 4, 1, 1, &sel, &m, &cnt);
    check(t, cnt == 0 && isnan(m), "sel_band_empty_nan", "count %ld mse %g", cnt, m);
    sel = fovm_sel_band(ecc, 3.0, 3.5);        /* hi exclusive, lo inclusive */
    fovm_mse_sel(r, s, 4, 1, 1, &sel, &m, &cnt);
    check(t, cnt == 1 && near(m, 0.16, 1e-7), "sel_band_lo_inclusive", "count %ld", cnt);
    sel = fovm_sel_mask(mask, 1);              /* pixels 0, 2: (0.01+0.09)/2 */
    fovm_mse_sel(r, s, 4, 1, 1, &sel, &m, &cnt);
    check(t, cnt == 2 && near(m, 0.05, 1e-7), "sel_mask_inside", "count %ld mse %.9g", cnt, m);
    sel = fovm_sel_mask(mask, 0);              /* pixels 1, 3: (0.04+0.16)/2 */
    fovm_mse_sel(r, s, 4, 1, 1, &sel, &m, &cnt);
    check(t, cnt == 2 && near(m, 0.10, 1e-7), "sel_mask_outside", "count %ld mse %.9g", cnt, m);
    {
        double ps = 0;
        fovm_psnr_sel(r, s, 4, 1, 1, &sel, &ps, &cnt);  /* 10 log10(1/0.1) = 10 */
        check(t, near(ps, 10.0, 1e-5), "sel_mask_psnr", "psnr %.9g", ps);
    }
    sel = fovm_sel_mask(mask, 7);
    fovm_psnr_sel(r, s, 4, 1, 1, &sel, &m, &cnt);
    check(t, cnt == 0 && isnan(m), "sel_mask_empty_psnr_nan", "count %ld", cnt);
    eccn[1] = (float)NAN;
    sel = fovm_sel_band(eccn, -1.0, 10.0);
    check(t, fovm_sel_count(&sel, 4, 1) == 3, "sel_band_nan_not_selected", "");
    sel = fovm_sel_band(NULL, 0.0, 1.0);
    check(t, fovm_mse_sel(r, s, 4, 1, 1, &sel, &m, &cnt) == FOVM_ERR_ARG, "sel_null_map_rejected", "");
    fovm_mse_sel(r, s, 4, 1, 1, NULL, &m, &cnt);
    check(t, cnt == 4 && near(m, 0.075, 1e-7), "sel_null_is_all", "count %ld", cnt);
}

/* ======================================================================= */
/* SSIM                                                                     */
/* ======================================================================= */

/* Independent brute-force SSIM of one plane (extracted to doubles): direct
 * 11x11 weights, two-pass variance. Returns the map and its mean. */
static double ssim_brute(const double *x, const double *y, int w, int h, double *map)
{
    double wt[11][11], s = 0.0, total = 0.0;
    const double C1 = 0.0001, C2 = 0.0009;
    int i, j, cx, cy, mw = w - 10, mh = h - 10;
    for (j = 0; j < 11; j++)
        for (i = 0; i < 11; i++) {
            wt[j][i] = exp(-((double)((i - 5) * (i - 5) + (j - 5) * (j - 5))) / (2.0 * 1.5 * 1.5));
            s += wt[j][i];
        }
    for (j = 0; j < 11; j++)
        for (i = 0; i < 11; i++) wt[j][i] /= s;
    for (cy = 0; cy < mh; cy++) {
        for (cx = 0; cx < mw; cx++) {
            double mx = 0, my = 0, vx = 0, vy = 0, cv = 0, v;
            for (j = 0; j < 11; j++)
                for (i = 0; i < 11; i++) {
                    mx += wt[j][i] * x[(cy + j) * w + cx + i];
                    my += wt[j][i] * y[(cy + j) * w + cx + i];
                }
            for (j = 0; j < 11; j++)
                for (i = 0; i < 11; i++) {
                    double dx = x[(cy + j) * w + cx + i] - mx;
                    double dy = y[(cy + j) * w + cx + i] - my;
                    vx += wt[j][i] * dx * dx;
                    vy += wt[j][i] * dy * dy;
                    cv += wt[j][i] * dx * dy;
                }
            v = (2 * mx * my + C1) * (2 * cv + C2) / ((mx * mx + my * my + C1) * (vx + vy + C2));
            map[cy * mw + cx] = v;
            total += v;
        }
    }
    return total / ((double)mw * (double)mh);
}

static void test_ssim(T *t)
{
    enum { W = 23, H = 17 };
    unsigned int seed = 99u;
    static float a[W * H * 3], b[W * H * 3];
    static float map[(W - 10) * (H - 10)];
    static double px[W * H], py[W * H], bmap[(W - 10) * (H - 10)], bsum[(W - 10) * (H - 10)];
    double mean = 0, ref, maxd = 0;
    int i, k, e;

    for (i = 0; i < W * H * 3; i++) {
        a[i] = rnd(&seed);
        b[i] = 0.7f * a[i] + 0.3f * rnd(&seed);
    }
    /* identical images */
    e = fovm_ssim(a, a, W, H, 3, &mean, map);
    {
        int allone = 1;
        for (i = 0; i < (W - 10) * (H - 10); i++) if (fabs((double)map[i] - 1.0) > 1e-6) allone = 0;
        check(t, e == 0 && near(mean, 1.0, 1e-9) && allone, "ssim_identical_is_1", "mean %.12f", mean);
    }
    /* constant images x = 0.2, y = 0.5 (grey): variances vanish, so
     * SSIM = (2*0.2*0.5 + C1) / (0.2^2 + 0.5^2 + C1), C1 = 1e-4
     *      = 0.2001 / 0.2901 = 0.68976215... */
    {
        static float cx[16 * 16], cy[16 * 16];
        float cmap[6 * 6];
        int ok = 1;
        for (i = 0; i < 256; i++) { cx[i] = 0.2f; cy[i] = 0.5f; }
        e = fovm_ssim(cx, cy, 16, 16, 1, &mean, cmap);
        ref = (2.0 * 0.2 * 0.5 + 1e-4) / (0.04 + 0.25 + 1e-4);
        for (i = 0; i < 36; i++) if (!near((double)cmap[i], ref, 1e-6)) ok = 0;
        check(t, e == 0 && near(mean, 0.6897621510, 1e-6) && near(mean, ref, 1e-6) && ok,
              "ssim_constant_closed_form", "mean %.9f want %.9f", mean, ref);
    }
    /* constant RGB offset: luma of (0.2,0.4,0.6) = 0.0598+0.2348+0.0684 =
     * 0.363, of (0.3,0.5,0.7) = 0.463 */
    {
        static float cx[12 * 12 * 3], cy[12 * 12 * 3];
        for (i = 0; i < 144; i++) {
            cx[3 * i] = 0.2f; cx[3 * i + 1] = 0.4f; cx[3 * i + 2] = 0.6f;
            cy[3 * i] = 0.3f; cy[3 * i + 1] = 0.5f; cy[3 * i + 2] = 0.7f;
        }
        e = fovm_ssim(cx, cy, 12, 12, 3, &mean, NULL);
        ref = (2.0 * 0.363 * 0.463 + 1e-4) / (0.363 * 0.363 + 0.463 * 0.463 + 1e-4);
        check(t, e == 0 && near(mean, ref, 1e-6), "ssim_constant_rgb_luma",
              "mean %.9f want %.9f", mean, ref);
        /* channel mean: average of the three per-channel closed forms */
        e = fovm_ssim_channels(cx, cy, 12, 12, 3, &mean, NULL);
        ref = ((2 * 0.2 * 0.3 + 1e-4) / (0.04 + 0.09 + 1e-4) +
               (2 * 0.4 * 0.5 + 1e-4) / (0.16 + 0.25 + 1e-4) +
               (2 * 0.6 * 0.7 + 1e-4) / (0.36 + 0.49 + 1e-4)) / 3.0;
        check(t, e == 0 && near(mean, ref, 1e-6), "ssim_constant_rgb_channel_mean",
              "mean %.9f want %.9f", mean, ref);
    }
    /* random pair vs brute force, luma */
    for (i = 0; i < W * H; i++) {
        px[i] = 0.299 * (double)a[3 * i] + 0.587 * (double)a[3 * i + 1] + 0.114 * (double)a[3 * i + 2];
        py[i] = 0.299 * (double)b[3 * i] + 0.587 * (double)b[3 * i + 1] + 0.114 * (double)b[3 * i + 2];
    }
    ref = ssim_brute(px, py, W, H, bmap);
    e = fovm_ssim(a, b, W, H, 3, &mean, map);
    for (i = 0; i < (W - 10) * (H - 10); i++)
        if (fabs((double)map[i] - bmap[i]) > maxd) maxd = fabs((double)map[i] - bmap[i]);
    check(t, e == 0 && near(mean, ref, 1e-9) && maxd < 1e-6 && ref < 0.95 && ref > 0.2,
          "ssim_random_vs_bruteforce_luma", "ours %.12f brute %.12f map maxdiff %g", mean, ref, maxd);
    /* per channel */
    {
        double acc = 0;
        for (i = 0; i < (W - 10) * (H - 10); i++) bsum[i] = 0;
        for (k = 0; k < 3; k++) {
            for (i = 0; i < W * H; i++) { px[i] = (double)a[3 * i + k]; py[i] = (double)b[3 * i + k]; }
            acc += ssim_brute(px, py, W, H, bmap) / 3.0;
            for (i = 0; i < (W - 10) * (H - 10); i++) bsum[i] += bmap[i] / 3.0;
        }
        e = fovm_ssim_channels(a, b, W, H, 3, &mean, map);
        maxd = 0;
        for (i = 0; i < (W - 10) * (H - 10); i++)
            if (fabs((double)map[i] - bsum[i]) > maxd) maxd = fabs((double)map[i] - bsum[i]);
        check(t, e == 0 && near(mean, acc, 1e-9) && maxd < 1e-6,
              "ssim_random_vs_bruteforce_channels", "ours %.12f brute %.12f", mean, acc);
    }
    /* grey input == luma path on a grey plane */
    {
        static float ga[W * H], gb[W * H];
        for (i = 0; i < W * H; i++) { ga[i] = a[3 * i]; gb[i] = b[3 * i]; px[i] = (double)ga[i]; py[i] = (double)gb[i]; }
        ref = ssim_brute(px, py, W, H, bmap);
        e = fovm_ssim(ga, gb, W, H, 1, &mean, NULL);
        check(t, e == 0 && near(mean, ref, 1e-9), "ssim_grey_vs_bruteforce", "ours %.12f brute %.12f", mean, ref);
    }
    /* sizes */
    check(t, fovm_ssim(a, b, 10, 20, 1, &mean, NULL) == FOVM_ERR_TOO_SMALL &&
          fovm_ssim(a, b, 20, 10, 3, &mean, NULL) == FOVM_ERR_TOO_SMALL,
          "ssim_too_small_error", "");
    {
        float one[1];
        e = fovm_ssim(a, b, 11, 11, 3, &mean, one);
        check(t, e == 0 && near((double)one[0], mean, 1e-6), "ssim_11x11_single_value", "err %d", e);
    }
    /* selection: window centre semantics. W x H = 23 x 17, mask = left
     * part x < 8. Valid centres x in 5..17, y in 5..11 -> selected x in
     * 5..7: 3 * 7 = 21 centres. */
    {
        static unsigned char mask[W * H];
        long cnt = 0;
        double want = 0.0;
        int x, y, n = 0;
        for (y = 0; y < H; y++) for (x = 0; x < W; x++) mask[y * W + x] = (unsigned char)(x < 8);
        for (i = 0; i < W * H; i++) {
            px[i] = 0.299 * (double)a[3 * i] + 0.587 * (double)a[3 * i + 1] + 0.114 * (double)a[3 * i + 2];
            py[i] = 0.299 * (double)b[3 * i] + 0.587 * (double)b[3 * i + 1] + 0.114 * (double)b[3 * i + 2];
        }
        ssim_brute(px, py, W, H, bmap);
        for (y = 0; y < H - 10; y++)
            for (x = 0; x < W - 10; x++)
                if (x + 5 < 8) { want += bmap[y * (W - 10) + x]; n++; }
        want /= n;
        {
            fovm_sel sel = fovm_sel_mask(mask, 1);
            e = fovm_ssim_sel(a, b, W, H, 3, 0, &sel, &mean, &cnt);
        }
        check(t, e == 0 && cnt == 21 && n == 21 && near(mean, want, 1e-6), "ssim_sel_mask_centres",
              "count %ld mean %.9f want %.9f", cnt, mean, want);
        {
            /* band on an "eccentricity" = x: [0, 5) selects no centre */
            static float ex[W * H];
            fovm_sel sel;
            for (y = 0; y < H; y++) for (x = 0; x < W; x++) ex[y * W + x] = (float)x;
            sel = fovm_sel_band(ex, 0.0, 5.0);
            e = fovm_ssim_sel(a, b, W, H, 3, 0, &sel, &mean, &cnt);
            check(t, e == 0 && cnt == 0 && isnan(mean), "ssim_sel_border_band_empty",
                  "count %ld", cnt);
            sel = fovm_sel_band(ex, 0.0, 100.0);
            e = fovm_ssim_sel(a, b, W, H, 3, 0, &sel, &mean, &cnt);
            ref = 0;
            fovm_ssim(a, b, W, H, 3, &ref, NULL);
            check(t, e == 0 && cnt == (W - 10) * (H - 10) && near(mean, ref, 1e-6),
                  "ssim_sel_all_equals_mean", "count %ld", cnt);
        }
    }
}

/* ======================================================================= */
/* FLIP                                                                     */
/* ======================================================================= */

/* Independent colour-only FLIP for two constant sRGB colours (features
 * are zero on constant images and the CSF filters have unit DC gain). */
static double lab_f(double t)
{
    return t > 216.0 / 24389.0 ? pow(t, 1.0 / 3.0) : (24389.0 / 27.0 * t + 16.0) / 116.0;
}
static void hunt_lab(const double srgb[3], double out[3])
{
    double lin[3], X, Y, Z, fx, fy, fz;
    int k;
    for (k = 0; k < 3; k++)
        lin[k] = srgb[k] <= 0.04045 ? srgb[k] / 12.92 : pow((srgb[k] + 0.055) / 1.055, 2.4);
    X = 0.4124564 * lin[0] + 0.3575761 * lin[1] + 0.1804375 * lin[2];
    Y = 0.2126729 * lin[0] + 0.7151522 * lin[1] + 0.0721750 * lin[2];
    Z = 0.0193339 * lin[0] + 0.1191920 * lin[1] + 0.9503041 * lin[2];
    fx = lab_f(X / 0.9504700);
    fy = lab_f(Y / 1.0000001);
    fz = lab_f(Z / 1.0888300);
    out[0] = 116 * fy - 16;
    out[1] = out[0] / 100.0 * 500 * (fx - fy);
    out[2] = out[0] / 100.0 * 200 * (fy - fz);
}
static double flip_constant(const double c1[3], const double c2[3])
{
    static const double green[3] = {0, 1, 0}, blue[3] = {0, 0, 1};
    double l1[3], l2[3], cmax, e;
    hunt_lab(green, l1);
    hunt_lab(blue, l2);
    cmax = pow(fabs(l1[0] - l2[0]) + hypot(l1[1] - l2[1], l1[2] - l2[2]), 0.7);
    hunt_lab(c1, l1);
    hunt_lab(c2, l2);
    e = pow(fabs(l1[0] - l2[0]) + hypot(l1[1] - l2[1], l1[2] - l2[2]), 0.7);
    if (e < 0.4 * cmax) return 0.95 * e / (0.4 * cmax);
    return 0.95 + 0.05 * (e - 0.4 * cmax) / (0.6 * cmax);
}

static void test_flip(T *t)
{
    enum { W = 40, H = 30 };
    static float a[W * H * 3], b[W * H * 3], map[W * H], map2[W * H];
    unsigned int seed = 7u;
    double mean = -1, mean2 = -1, s;
    int i, e, inrange = 1;

    for (i = 0; i < W * H * 3; i++) {
        a[i] = rnd(&seed);
        b[i] = i % 5 == 0 ? rnd(&seed) : a[i];
    }
    e = fovm_flip(a, a, W, H, 3, FOVM_FLIP_DEFAULT_PPD, &mean, map);
    {
        int allzero = 1;
        for (i = 0; i < W * H; i++) if (map[i] != 0.0f) allzero = 0;
        check(t, e == 0 && mean == 0.0 && allzero, "flip_identical_is_0", "mean %g", mean);
    }
    e = fovm_flip(a, b, W, H, 3, FOVM_FLIP_DEFAULT_PPD, &mean, map);
    s = 0;
    for (i = 0; i < W * H; i++) {
        if (!(map[i] >= 0.0f && map[i] <= 1.0f)) inrange = 0;
        s += (double)map[i];
    }
    check(t, e == 0 && inrange && mean > 0.0 && mean < 1.0, "flip_in_0_1", "mean %g", mean);
    check(t, near(s / (W * H), mean, 1e-6), "flip_mean_is_map_mean", "map mean %.9f mean %.9f", s / (W * H), mean);
    e = fovm_flip(b, a, W, H, 3, FOVM_FLIP_DEFAULT_PPD, &mean2, NULL);
    check(t, e == 0 && near(mean, mean2, 1e-6), "flip_symmetric", "%.9f vs %.9f", mean, mean2);
    /* black vs white: HyAB = 100, 100^0.7 = 25.119 > 0.4 cmax (cmax =
     * 203.3^0.7 = 41.27), so FLIP = 0.95 + 0.05 (25.12-16.51)/(41.27-16.51)
     * = 0.9674 */
    {
        static float k0[16 * 16], k1[16 * 16];
        static const double black[3] = {0, 0, 0}, white[3] = {1, 1, 1};
        double want = flip_constant(black, white);
        for (i = 0; i < 256; i++) { k0[i] = 0.0f; k1[i] = 1.0f; }
        e = fovm_flip(k0, k1, 16, 16, 1, 67.0, &mean, NULL);
        check(t, e == 0 && near(want, 0.9674, 2e-4) && near(mean, want, 1e-5),
              "flip_constant_black_white", "ours %.6f independent %.6f", mean, want);
    }
    /* constant colours in the linear branch and in the upper branch */
    {
        static float k0[12 * 12 * 3], k1[12 * 12 * 3];
        static const double c0[3] = {0.5, 0.5, 0.5}, c1[3] = {0.55, 0.5, 0.45};
        static const double c2[3] = {0.8, 0.1, 0.1}, c3[3] = {0.1, 0.1, 0.8};
        double want;
        for (i = 0; i < 144; i++) {
            int k;
            for (k = 0; k < 3; k++) { k0[3 * i + k] = (float)c0[k]; k1[3 * i + k] = (float)c1[k]; }
        }
        want = flip_constant(c0, c1);
        e = fovm_flip(k0, k1, 12, 12, 3, 67.0, &mean, NULL);
        check(t, e == 0 && want < 0.5 && near(mean, want, 1e-5), "flip_constant_small_diff",
              "ours %.6f independent %.6f", mean, want);
        for (i = 0; i < 144; i++) {
            int k;
            for (k = 0; k < 3; k++) { k0[3 * i + k] = (float)c2[k]; k1[3 * i + k] = (float)c3[k]; }
        }
        want = flip_constant(c2, c3);
        e = fovm_flip(k0, k1, 12, 12, 3, 30.0, &mean, NULL);
        check(t, e == 0 && want > 0.95 && near(mean, want, 1e-5), "flip_constant_red_blue",
              "ours %.6f independent %.6f", mean, want);
    }
    /* grey == RGB with equal channels */
    {
        static float g0[W * H], g1[W * H], r0[W * H * 3], r1[W * H * 3];
        for (i = 0; i < W * H; i++) {
            g0[i] = a[3 * i]; g1[i] = b[3 * i];
            r0[3 * i] = r0[3 * i + 1] = r0[3 * i + 2] = g0[i];
            r1[3 * i] = r1[3 * i + 1] = r1[3 * i + 2] = g1[i];
        }
        fovm_flip(g0, g1, W, H, 1, 67.0, &mean, NULL);
        fovm_flip(r0, r1, W, H, 3, 67.0, &mean2, NULL);
        check(t, near(mean, mean2, 1e-7) && mean > 0, "flip_grey_equals_rgb", "%.9f vs %.9f", mean, mean2);
    }
    check(t, fovm_flip(a, b, W, H, 3, 0.0, &mean, NULL) == FOVM_ERR_ARG &&
          fovm_flip(a, b, W, H, 3, -5.0, &mean, NULL) == FOVM_ERR_ARG &&
          fovm_flip(a, b, W, H, 3, (double)NAN, &mean, NULL) == FOVM_ERR_ARG,
          "flip_bad_ppd", "");
    /* tiny images work (1x1, 2x3) */
    check(t, fovm_flip(a, b, 1, 1, 3, 67.0, &mean, NULL) == 0 && mean >= 0.0 && mean <= 1.0 &&
          fovm_flip(a, b, 2, 3, 3, 67.0, &mean, NULL) == 0, "flip_tiny_images", "");
    /* ppd changes the result */
    fovm_flip(a, b, W, H, 3, 67.0, &mean, NULL);
    fovm_flip(a, b, W, H, 3, 20.0, &mean2, NULL);
    check(t, fabs(mean - mean2) > 1e-3, "flip_depends_on_ppd", "%.6f vs %.6f", mean, mean2);
    check(t, near(fovm_ppd_from_viewing(0.7, 0.7, 3840.0), 67.020643, 1e-5), "ppd_from_viewing",
          "%.6f", fovm_ppd_from_viewing(0.7, 0.7, 3840.0));
    /* regions: mask halves combine to the full mean */
    {
        static unsigned char mask[W * H];
        fovm_sel in, out;
        long c1 = 0, c2 = 0;
        double m1 = 0, m2 = 0, full = 0;
        int x, y;
        for (y = 0; y < H; y++) for (x = 0; x < W; x++) mask[y * W + x] = (unsigned char)(x < 10 && y < 12);
        in = fovm_sel_mask(mask, 1);
        out = fovm_sel_mask(mask, 0);
        fovm_flip(a, b, W, H, 3, 67.0, &full, map2);
        fovm_flip_sel(a, b, W, H, 3, 67.0, &in, &m1, &c1);
        fovm_flip_sel(a, b, W, H, 3, 67.0, &out, &m2, &c2);
        s = 0;
        for (y = 0; y < 12; y++) for (x = 0; x < 10; x++) s += (double)map2[y * W + x];
        check(t, c1 == 120 && c2 == W * H - 120 && near(m1, s / 120.0, 1e-9) &&
              near((m1 * (double)c1 + m2 * (double)c2) / (W * H), full, 1e-6),
              "flip_sel_mask_halves", "counts %ld %ld means %.6f %.6f full %.6f", c1, c2, m1, m2, full);
    }
}

static void test_rings(T *t)
{
    enum { W = 32, H = 24 };
    static float a[W * H * 3], b[W * H * 3], ecc[W * H];
    fovm_ring rings[5];
    unsigned int seed = 1234u;
    int i, x, y, e, ok;
    long total = 0;
    for (i = 0; i < W * H * 3; i++) {
        a[i] = rnd(&seed);
        b[i] = 0.8f * a[i] + 0.2f * rnd(&seed);
    }
    /* ecc = column index / 4 degrees: 0 .. 7.75; 4 rings to 8 degrees ->
     * each ring is 8 columns = 8 * 24 = 192 pixels */
    for (y = 0; y < H; y++) for (x = 0; x < W; x++) ecc[y * W + x] = (float)x / 4.0f;
    e = fovm_ecc_rings(a, b, W, H, 3, ecc, 4, 8.0, 67.0, rings);
    ok = e == 0;
    for (i = 0; ok && i < 4; i++) {
        if (rings[i].count != 192) ok = 0;
        if (!near(rings[i].lo, 2.0 * i, 1e-12) || !near(rings[i].hi, 2.0 * (i + 1), 1e-12)) ok = 0;
    }
    check(t, ok, "rings_counts_and_bounds", "err %d count0 %ld", e, rings[0].count);
    /* SSIM centres: x in 5..26, y in 5..18 (14 rows); ring 0 (x 0..7):
     * 3 columns -> 42; ring 1 (8..15): 8 -> 112; ring 2: 112; ring 3
     * (24..31): x 24..26 -> 42 */
    check(t, rings[0].ssim_count == 42 && rings[1].ssim_count == 112 &&
          rings[2].ssim_count == 112 && rings[3].ssim_count == 42, "rings_ssim_counts",
          "%ld %ld %ld %ld", rings[0].ssim_count, rings[1].ssim_count,
          rings[2].ssim_count, rings[3].ssim_count);
    ok = 1;
    for (i = 0; i < 4; i++) {
        fovm_sel sel = fovm_sel_band(ecc, rings[i].lo, rings[i].hi);
        double m = 0, s = 0, f = 0, p = 0;
        long c = 0;
        fovm_mse_sel(a, b, W, H, 3, &sel, &m, &c);
        fovm_psnr_sel(a, b, W, H, 3, &sel, &p, &c);
        fovm_ssim_sel(a, b, W, H, 3, 0, &sel, &s, &c);
        fovm_flip_sel(a, b, W, H, 3, 67.0, &sel, &f, &c);
        if (!near(m, rings[i].mse, 1e-12) || !near(p, rings[i].psnr, 1e-9) ||
            !near(s, rings[i].ssim, 1e-9) || !near(f, rings[i].flip, 1e-9)) ok = 0;
        total += rings[i].count;
    }
    check(t, ok && total == W * H, "rings_match_sel_variants", "total %ld", total);
    /* rings beyond the data are empty -> NaN; pixels >= max_deg excluded */
    e = fovm_ecc_rings(a, b, W, H, 3, ecc, 5, 20.0, 67.0, rings);
    /* ring width 4: ring 0 = x 0..15 (384 px), ring 1 = x 16..31, rest empty */
    check(t, e == 0 && rings[0].count == 384 && rings[1].count == 384 && rings[2].count == 0 &&
          isnan(rings[2].mse) && isnan(rings[3].flip) && isnan(rings[4].ssim) &&
          isnan(rings[4].psnr), "rings_empty_nan", "err %d counts %ld %ld %ld",
          e, rings[0].count, rings[1].count, rings[2].count);
    e = fovm_ecc_rings(a, b, W, H, 3, ecc, 2, 4.0, 67.0, rings);
    check(t, e == 0 && rings[0].count + rings[1].count == 16 * H, "rings_exclude_beyond_max",
          "counts %ld %ld", rings[0].count, rings[1].count);
    e = fovm_ecc_rings(a, b, 8, 8, 3, ecc, 2, 4.0, 67.0, rings);
    check(t, e == 0 && isnan(rings[0].ssim) && rings[0].ssim_count == 0 && !isnan(rings[0].flip),
          "rings_small_image_ssim_nan", "err %d", e);
    check(t, fovm_ecc_rings(a, b, W, H, 3, ecc, 0, 4.0, 67.0, rings) == FOVM_ERR_ARG &&
          fovm_ecc_rings(a, b, W, H, 3, NULL, 2, 4.0, 67.0, rings) == FOVM_ERR_ARG,
          "rings_bad_args", "");
}

/* ======================================================================= */
/* the eye filter and the perceptual error                                  */
/* ======================================================================= */

/* The filter's sigma in pixels, computed here from the documented model: MAR(e) = 1 + 1.32 e
 * arc minutes; sigma = sqrt(2 ln 2) / pi MAR (the Gaussian with response 1/2 at 1 / (2 MAR)
 * cycles per degree: exp(-2 pi^2 sigma^2 f^2) = 1/2); along y at a point X pixels beside the
 * axis on the axis row (the gaze on the axis) a pixel subtends 1 / sqrt(f^2 + X^2) radians. */
static double expect_sigma_y(double f, double X)
{
    const double PI = 3.14159265358979323846;
    double e = atan(fabs(X) / f) * 180.0 / PI;
    double mar_deg = (1.0 + 1.32 * e) / 60.0;
    double sig_deg = mar_deg * sqrt(log(2.0) / 2.0) / (PI * 0.5);
    return sig_deg * PI / 180.0 * sqrt(f * f + X * X);
}

/* standard deviation of the line-spread function: the differences of the linear-light step
 * response along a column (dy = 1) or a row (dy = 0) of a c = 1 image */
static double lsf_sigma(const float *img, int w, int h, int col_or_row, int along_y)
{
    double s0 = 0, s1 = 0, s2 = 0, mu;
    int n = along_y ? h : w, k;
    for (k = 0; k + 1 < n; k++) {
        size_t i0 = along_y ? (size_t)k * (size_t)w + (size_t)col_or_row
                            : (size_t)col_or_row * (size_t)w + (size_t)k;
        size_t i1 = along_y ? i0 + (size_t)w : i0 + 1;
        double d = (double)fovimg_srgb_to_linear(img[i1]) - (double)fovimg_srgb_to_linear(img[i0]);
        double pos = (double)k + 1.0;
        s0 += d; s1 += d * pos; s2 += d * pos * pos;
    }
    if (!(s0 > 0.0)) return -1.0;
    mu = s1 / s0;
    return sqrt(s2 / s0 - mu * mu);
}

static void test_eye_geometry(T *t)
{
    const double PI = 3.14159265358979323846;
    double f = 40.0 * 180.0 / PI; /* 40 px per degree on the axis */
    fovm_eye e;
    double X = f * tan(30.0 * PI / 180.0), ecc, sx, sy;
    memset(&e, 0, sizeof e);
    e.cx = 100.0; e.cy = 50.0; e.f_px = f; e.gx = 100.0; e.gy = 50.0;
    ecc = fovm_eye_ecc(&e, 100.0 + X, 50.0);
    check(t, near(ecc, 30.0, 1e-9), "eye_ecc_30deg", "got %.12f", ecc);
    check(t, near(fovm_eye_ppd(&e), 40.0, 1e-9), "eye_ppd_axis", "got %.12f", fovm_eye_ppd(&e));
    /* gaze r pixels off the axis: radial ppd (f^2 + r^2) / f pi / 180 */
    e.gx = 100.0 + 500.0;
    check(t, near(fovm_eye_ppd(&e), (f * f + 250000.0) / f * PI / 180.0, 1e-9),
          "eye_ppd_off_axis", "got %.9f", fovm_eye_ppd(&e));
    /* the gaze off the axis: the angle between the two rays, here both on the axis row */
    ecc = fovm_eye_ecc(&e, 100.0, 50.0);
    check(t, near(ecc, atan(500.0 / f) * 180.0 / PI, 1e-9), "eye_ecc_off_axis", "got %.9f", ecc);
    check(t, near(fovm_eye_mar_deg(&e, 10.0), (1.0 + 13.2) / 60.0, 1e-12) &&
          isnan(fovm_eye_mar_deg(&e, -1.0)), "eye_mar_default", "%.9f",
          fovm_eye_mar_deg(&e, 10.0));
    e.mar0_arcmin = 2.0; e.slope_arcmin = 1.65;
    check(t, near(fovm_eye_mar_deg(&e, 10.0), (2.0 + 16.5) / 60.0, 1e-12), "eye_mar_fields", "");
    e.mar0_arcmin = 0.0; e.slope_arcmin = 0.0;
    e.gx = 100.0;
    /* the reported sigma against the independent formula: the pixel column at 30 degrees */
    {
        int i = (int)floor(100.0 + X);
        double Xc = (double)i + 0.5 - 100.0;
        fovm_eye_sigma(&e, i, 49, &sx, &sy); /* row 49: centre 49.5, half a pixel off-axis */
        check(t, near(sy, expect_sigma_y(f, Xc), 0.002 * sy), "eye_sigma_formula",
              "got %.5f want %.5f", sy, expect_sigma_y(f, Xc));
        check(t, sx > sy, "eye_sigma_radial_wider", "sx %.4f sy %.4f", sx, sy);
    }
    /* from_fov / from_monitor */
    e = fovm_eye_from_fov(640, 360, 45.0, 320.0, 180.0);
    check(t, near(e.f_px, 180.0 / tan(22.5 * PI / 180.0), 1e-9) && e.cx == 320.0 &&
          e.cy == 180.0 && fovm_eye_check(&e) == FOVM_OK, "eye_from_fov", "f %.6f", e.f_px);
    e = fovm_eye_from_monitor(1920, 1080, 0.3113, 600.0, 960.0, 540.0);
    check(t, near(e.f_px, 600.0 / 0.3113, 1e-9) && fovm_eye_check(&e) == FOVM_OK,
          "eye_from_monitor", "f %.6f", e.f_px);
}

static void test_eye_filter_sigma(T *t)
{
    /* A horizontal step edge on the gaze row (gaze on the axis), filtered: the column at
     * eccentricity E blurs it with sigma_y (eccentricity changes only to second order along
     * that column); the same with a vertical edge, the rows below the gaze and sigma_x. */
    const double PI = 3.14159265358979323846;
    const int W = 720, H = 200;
    double f = 20.0 * 180.0 / PI, g0 = 30.5, gy = 100.0;
    float *img = (float *)malloc((size_t)W * (size_t)H * sizeof(float));
    float *out = (float *)malloc((size_t)W * (size_t)H * sizeof(float));
    fovm_eye e;
    int x, y, k, ok, err;
    const double eccs[2] = { 10.0, 30.0 };
    memset(&e, 0, sizeof e);
    if (!img || !out) { check(t, 0, "eye_filter_alloc", ""); free(img); free(out); return; }
    e.cx = g0; e.cy = gy; e.f_px = f; e.gx = g0; e.gy = gy;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) img[y * W + x] = y < 100 ? 0.0f : 1.0f;
    err = fovm_eye_filter(img, W, H, 1, &e, out);
    for (k = 0; k < 2; k++) {
        int col = (int)floor(g0 + f * tan(eccs[k] * PI / 180.0));
        double X = (double)col + 0.5 - g0, want = expect_sigma_y(f, X);
        double got = lsf_sigma(out, W, H, col, 1);
        check(t, err == 0 && fabs(got - want) <= 0.02 * want, k ? "eye_filter_sigma_y_30deg" :
              "eye_filter_sigma_y_10deg", "err %d got %.4f px want %.4f px", err, got, want);
    }
    /* at the gaze: sigma = 0.37 arcmin = 0.12 px, below the 0.2 px copy threshold (up to
     * 0.45 degrees = 9 px from the gaze): the edge's pixels are copied unchanged */
    ok = err == 0;
    for (y = 92; y < 108; y++)
        if (out[y * W + 30] != img[y * W + 30]) ok = 0;
    check(t, ok, "eye_filter_gaze_unchanged", "");
    /* transposed: vertical edge at x = 100, gaze at (100, 30.5), columns below it */
    {
        const int W2 = 200, H2 = 720;
        e.cx = 100.0; e.cy = g0; e.gx = 100.0; e.gy = g0;
        for (y = 0; y < H2; y++)
            for (x = 0; x < W2; x++) img[y * W2 + x] = x < 100 ? 0.0f : 1.0f;
        err = fovm_eye_filter(img, W2, H2, 1, &e, out);
        for (k = 0; k < 2; k++) {
            int row = (int)floor(g0 + f * tan(eccs[k] * PI / 180.0));
            double Y = (double)row + 0.5 - g0, want = expect_sigma_y(f, Y);
            double got = lsf_sigma(out, W2, H2, row, 0);
            check(t, err == 0 && fabs(got - want) <= 0.02 * want, k ? "eye_filter_sigma_x_30deg"
                  : "eye_filter_sigma_x_10deg", "err %d got %.4f px want %.4f px", err, got, want);
        }
    }
    /* in place gives the same */
    memcpy(out, img, (size_t)W * (size_t)H * sizeof(float));
    {
        float *ref = (float *)malloc((size_t)W * (size_t)H * sizeof(float));
        ok = ref && fovm_eye_filter(img, 200, 720, 1, &e, ref) == 0 &&
             fovm_eye_filter(out, 200, 720, 1, &e, out) == 0 &&
             memcmp(ref, out, (size_t)W * (size_t)H * sizeof(float)) == 0;
        check(t, ok, "eye_filter_in_place", "");
        free(ref);
    }
    free(img);
    free(out);
}

/* grey background of linear 0.5 (sRGB 0.7354), gaze at (40.5, 64) on the axis, 40 px per
 * degree there; patch: kind 0 a pixel checkerboard 0/1 (linear mean 0.5) 16 x 16 px, kind 1 a
 * 96 x 96 px square of sRGB 0.2, centred at ecc degrees right of the gaze */
static void make_patch(float *img, int W, int H, double f, double ecc, int kind)
{
    const double PI = 3.14159265358979323846;
    int half = kind ? 48 : 8, x, y;
    int cx = (int)floor(40.5 + f * tan(ecc * PI / 180.0));
    float grey = fovimg_linear_to_srgb(0.5f);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            float v = grey;
            if (x >= cx - half && x < cx + half && y >= 64 - half && y < 64 + half)
                v = kind ? 0.2f : (float)((x + y) & 1);
            img[y * W + x] = v;
        }
}

static void test_perceptual(T *t)
{
    const double PI = 3.14159265358979323846;
    const int W = 1450, H = 128;
    double f = 40.0 * 180.0 / PI, p_far, f_far, p_gaze, f_gaze, p_c, f_c, p_raw, mx_far, mx_g;
    float *ref = (float *)malloc((size_t)W * (size_t)H * sizeof(float));
    float *img = (float *)malloc((size_t)W * (size_t)H * sizeof(float));
    float *map = (float *)malloc((size_t)W * (size_t)H * sizeof(float));
    fovm_eye e;
    int err, i, ok;
    size_t n = (size_t)W * (size_t)H;
    if (!ref || !img || !map) {
        check(t, 0, "perceptual_alloc", "");
        free(ref); free(img); free(map);
        return;
    }
    memset(&e, 0, sizeof e);
    e.cx = 40.5; e.cy = 64.0; e.f_px = f; e.gx = 40.5; e.gy = 64.0;
    make_patch(ref, W, H, f, 0.0, 0);
    for (i = 0; i < W * H; i++) ref[i] = fovimg_linear_to_srgb(0.5f);
    /* identical images */
    p_far = 0; f_far = -1;
    err = fovm_perceptual(ref, ref, W, H, 1, &e, &p_far, &f_far, NULL);
    check(t, err == 0 && isinf(p_far) && p_far > 0 && f_far == 0.0, "perceptual_identical",
          "err %d psnr %g flip %g", err, p_far, f_far);
    /* a pixel checkerboard at 30 degrees: far finer than the MAR there (0.68 deg = 36 px) */
    make_patch(img, W, H, f, 30.0, 0);
    fovm_psnr(ref, img, W, H, 1, &p_raw);
    err = fovm_perceptual(ref, img, W, H, 1, &e, &p_far, &f_far, map);
    mx_far = 0;
    for (i = 0; i < W * H; i++) if ((double)map[i] > mx_far) mx_far = (double)map[i];
    check(t, err == 0 && p_raw < 40.0 && p_far > 60.0 && f_far < 1e-4 && mx_far < 0.01,
          "perceptual_fine_30deg_invisible", "err %d raw psnr %.2f filtered psnr %.2f "
          "flip %.3g max %.3g", err, p_raw, p_far, f_far, mx_far);
    /* the same checkerboard at the gaze */
    make_patch(img, W, H, f, 0.0, 0);
    err = fovm_perceptual(ref, img, W, H, 1, &e, &p_gaze, &f_gaze, map);
    mx_g = 0;
    for (i = 0; i < W * H; i++) if ((double)map[i] > mx_g) mx_g = (double)map[i];
    check(t, err == 0 && p_gaze < 40.0 && f_gaze > 10.0 * f_far && mx_g > 0.1 &&
          mx_g > 20.0 * mx_far,
          "perceptual_fine_gaze_visible", "err %d psnr %.2f flip %.3g max %.3g", err, p_gaze,
          f_gaze, mx_g);
    /* a coarse change at 30 degrees (96 px = 1.8 deg, wider than the 0.68 deg MAR) */
    make_patch(img, W, H, f, 30.0, 1);
    err = fovm_perceptual(ref, img, W, H, 1, &e, &p_c, &f_c, map);
    ok = 0;
    for (i = 0; i < W * H; i++) if (map[i] > 0.3f) ok = 1;
    check(t, err == 0 && p_c < 35.0 && f_c > 100.0 * f_far && ok, "perceptual_coarse_30deg_visible",
          "err %d psnr %.2f flip %.3g", err, p_c, f_c);
    /* RGB: the same as grey replicated */
    {
        float *r3 = (float *)malloc(n * 3 * sizeof(float)), *i3 = (float *)malloc(n * 3 * sizeof(float));
        double p3 = 0, f3 = 0;
        size_t k;
        ok = r3 && i3;
        for (k = 0; ok && k < n * 3; k++) { r3[k] = ref[k / 3]; i3[k] = img[k / 3]; }
        ok = ok && fovm_perceptual(r3, i3, W, H, 3, &e, &p3, &f3, NULL) == 0 &&
             near(p3, p_c, 1e-6) && near(f3, f_c, 1e-6);
        check(t, ok, "perceptual_rgb_matches_grey", "%.6f %.6f / %.6f %.6f", p3, f3, p_c, f_c);
        free(r3); free(i3);
    }
    /* bad arguments: an error code, outputs untouched */
    {
        fovm_eye b = e;
        double p = 123.0, fl = 456.0;
        ok = fovm_perceptual(NULL, img, W, H, 1, &e, &p, &fl, NULL) == FOVM_ERR_ARG &&
             fovm_perceptual(ref, NULL, W, H, 1, &e, &p, &fl, NULL) == FOVM_ERR_ARG &&
             fovm_perceptual(ref, img, 0, H, 1, &e, &p, &fl, NULL) == FOVM_ERR_ARG &&
             fovm_perceptual(ref, img, W, H, 2, &e, &p, &fl, NULL) == FOVM_ERR_ARG &&
             fovm_perceptual(ref, img, W, H, 1, NULL, &p, &fl, NULL) == FOVM_ERR_ARG &&
             fovm_eye_filter(ref, W, H, 1, &e, NULL) == FOVM_ERR_ARG &&
             fovm_eye_filter(NULL, W, H, 1, &e, img) == FOVM_ERR_ARG;
        b.f_px = 0.0;
        ok = ok && fovm_perceptual(ref, img, W, H, 1, &b, &p, &fl, NULL) == FOVM_ERR_ARG;
        b.f_px = -5.0;
        ok = ok && fovm_eye_check(&b) == FOVM_ERR_ARG;
        b = e; b.f_px = (double)NAN;
        ok = ok && fovm_eye_filter(ref, W, H, 1, &b, img) == FOVM_ERR_ARG;
        b = e; b.gx = (double)INFINITY;
        ok = ok && fovm_eye_check(&b) == FOVM_ERR_ARG && isnan(fovm_eye_ppd(&b)) &&
             isnan(fovm_eye_ecc(&b, 1.0, 1.0));
        b = e; b.mar0_arcmin = -1.0;
        ok = ok && fovm_eye_check(&b) == FOVM_ERR_ARG;
        b = e; b.slope_arcmin = 61.0;
        ok = ok && fovm_eye_check(&b) == FOVM_ERR_ARG;
        b = e; b.mar0_arcmin = (double)NAN;
        ok = ok && fovm_eye_check(&b) == FOVM_ERR_ARG && fovm_eye_sigma(&b, 0, 0, NULL, NULL) ==
             FOVM_ERR_ARG;
        b = fovm_eye_from_fov(W, H, 0.0, 1.0, 1.0); /* no field of view: f_px 0 */
        ok = ok && fovm_eye_check(&b) == FOVM_ERR_ARG;
        check(t, ok && p == 123.0 && fl == 456.0, "perceptual_bad_args", "p %g fl %g", p, fl);
    }
    free(ref); free(img); free(map);
}

int main(int argc, char **argv)
{
    T t;
    const char *tmp = getenv("TMPDIR");
    const char *base = argc > 0 && argv[0] ? argv[0] : "test_metrics", *c;
    memset(&t, 0, sizeof t);
    snprintf(t.tmpdir, sizeof t.tmpdir, "%s", (tmp && tmp[0]) ? tmp : "/tmp");
    for (c = base; *c; ++c)
        if (*c == '/' || *c == '\\') base = c + 1;
    snprintf(t.tag, sizeof t.tag, "%s", base);
    test_alloc(&t);
    test_srgb(&t);
    test_u8(&t);
    test_pnm(&t);
    test_pfm(&t);
    test_malformed(&t);
    test_oiio(&t);
    test_mse(&t);
    test_sel(&t);
    test_ssim(&t);
    test_flip(&t);
    test_rings(&t);
    test_eye_geometry(&t);
    test_eye_filter_sigma(&t);
    test_perceptual(&t);
    printf("%d passed, %d failed\n", t.pass, t.fail);
    return t.fail ? 1 : 0;
}
