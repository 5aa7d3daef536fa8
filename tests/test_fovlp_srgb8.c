/* test_fovlp_srgb8.c - fovlp.h's 8-bit sRGB output against an independent double-precision
   implementation of the IEC 61966-2-1 encoding.

   Reference: srgb(x) = 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055, in double;
   code(x) = floor(255 srgb(clamp(x, 0, 1)) + 0.5), NaN -> 0. Checked: for each of the 255
   code boundaries the smallest float of the upper code (found here by bisection over float
   bit patterns with the reference) and the float just below it; a sweep over every 97th
   float in [0, 1]; special inputs (signed zeros, negatives, denormals, values > 1, +-inf,
   NaNs); fovlp_srgb8_rows with 3 and 4 channels, strides, row splits, untouched bytes
   outside the rows, and every rejected argument (with a logged message).
   Prints one line per check and "N passed, N failed". */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVLP_IMPLEMENTATION
#endif
#include "fovlp.h"
#include "fovcheck.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double srgb_ref(double x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

static int code_ref(float f)
{
    double x = (double)f;
    if (!(x > 0.0)) return 0; /* NaN, zeros, negatives */
    if (x >= 1.0) return 255;
    return (int)floor(srgb_ref(x) * 255.0 + 0.5);
}

static float from_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static void test_boundaries(void)
{
    const uint32_t one = 0x3f800000u;
    uint32_t k, bad = 0, skipped = 0, worst_k = 0;
    for (k = 0; k < 255; ++k) {
        uint32_t lo = 0, hi = one; /* code_ref(lo) <= k < code_ref(hi) = 255 */
        float f, g;
        while (hi - lo > 1u) {
            uint32_t mid = lo + (hi - lo) / 2u;
            if (code_ref(from_bits(mid)) >= (int)k + 1) hi = mid; else lo = mid;
        }
        f = from_bits(hi);    /* the smallest float of code k + 1 */
        g = from_bits(hi - 1u); /* the largest float below it */
        if (code_ref(f) != (int)k + 1 || code_ref(g) != (int)k) ++skipped;
        if (fovlp_linear_to_srgb8(f) != code_ref(f) || fovlp_linear_to_srgb8(g) != code_ref(g)) {
            if (!bad) worst_k = k;
            ++bad;
        }
    }
    check(skipped == 0, "srgb8_reference_has_every_code", "%u boundaries skip a code", skipped);
    check(bad == 0, "srgb8_every_code_boundary_exact",
          "%u of 255 boundaries wrong (first: code %u -> %u)", bad, worst_k, worst_k + 1);
}

static void test_sweep(void)
{
    uint32_t u, n = 0, bad = 0, nonmono = 0, first = 0;
    int prev = 0;
    for (u = 0; u <= 0x3f800000u; u += 97u) {
        float f = from_bits(u);
        int got = fovlp_linear_to_srgb8(f);
        if (got != code_ref(f)) {
            if (!bad) first = u;
            ++bad;
        }
        if (got < prev) ++nonmono;
        prev = got;
        ++n;
    }
    check(bad == 0, "srgb8_sweep_every_97th_float_in_0_1",
          "%u of %u floats differ from the reference (first bits 0x%08x)", bad, n, first);
    check(nonmono == 0, "srgb8_sweep_monotone", "%u decreases", nonmono);
}

static void test_special(void)
{
    static const uint32_t bits[] = {
        0x00000000u, /* +0 */
        0x80000000u, /* -0 */
        0x00000001u, /* smallest denormal */
        0x007fffffu, /* largest denormal */
        0x00800000u, /* FLT_MIN */
        0x80800000u, /* -FLT_MIN */
        0xbf800000u, /* -1 */
        0xff7fffffu, /* -FLT_MAX */
        0xff800000u, /* -inf */
        0x3f7fffffu, /* largest float below 1 */
        0x3f800000u, /* 1 */
        0x3f800001u, /* just above 1 */
        0x40000000u, /* 2 */
        0x7149f2cau, /* 1e30 */
        0x7f7fffffu, /* FLT_MAX */
        0x7f800000u, /* +inf */
        0x7fc00000u, /* quiet NaN */
        0xffc00000u, /* negative quiet NaN */
        0x7f800001u, /* NaN with the smallest payload */
        0x7fffffffu, /* NaN, all payload bits */
        0x3b4d2e1cu, /* 0.0031308 (the curve's knee) */
    };
    static const int want[] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255,
                                0, 0, 0, 0, 10 };
    size_t i;
    for (i = 0; i < sizeof bits / sizeof bits[0]; ++i) {
        float f = from_bits(bits[i]);
        int got = fovlp_linear_to_srgb8(f);
        /* both the literal expectation and the reference must agree with the encoder */
        check(got == want[i] && got == code_ref(f), fovcheck_name("srgb8_special_0x%08x", bits[i]),
              "got %d, want %d (reference %d)", got, want[i], code_ref(f));
    }
}

/* ---- fovlp_srgb8_rows ------------------------------------------------------------------- */
typedef struct logcap { int calls; int empty; int32_t code; } logcap;
static void logfn(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                  void *user)
{
    logcap *l = (logcap *)user;
    (void)tag; (void)level; (void)line;
    l->calls++;
    l->code = code;
    if (!msg || !msg[0]) l->empty++;
}

/* a value per (x, y, channel): a spread over [-0.25, 1.25] plus NaN and inf now and then */
static float value_at(uint32_t x, uint32_t y, uint32_t c)
{
    uint32_t h = (x * 73856093u) ^ (y * 19349663u) ^ (c * 83492791u);
    h ^= h >> 13; h *= 0x5bd1e995u; h ^= h >> 15;
    if (h % 97u == 0u) return (h & 1u) ? NAN : ((h & 2u) ? INFINITY : -INFINITY);
    return (float)((double)(h & 0xffffffu) / 16777216.0 * 1.5 - 0.25);
}

static void test_rows(void)
{
    const uint32_t W = 37, H = 23, IS = 3u * W + 5u;
    fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    fovlp_ctx ctx, zero;
    logcap lc;
    size_t bytes = 0;
    void *mem;
    float *img = (float *)malloc(sizeof(float) * IS * H);
    uint8_t *o8 = (uint8_t *)malloc(4u * W * H + 64u * H), *o8b = (uint8_t *)malloc(4u * W * H);
    uint32_t x, y, c, ch;
    fov_result r;
    memset(&lc, 0, sizeof lc);
    cfg.logger.func = logfn;
    cfg.logger.user = &lc;
    r = fovlp_memory_size(&cfg, &bytes);
    mem = malloc(bytes ? bytes : 1u);
    if (r == FOV_OK) r = fovlp_init(&ctx, &cfg, mem, bytes);
    check(r == FOV_OK, "srgb8_rows_ctx", "init: %s", fovlp_result_string(r));
    if (r != FOV_OK || !img || !o8 || !o8b) return;
    for (y = 0; y < H; ++y)
        for (x = 0; x < IS; ++x)
            img[(size_t)y * IS + x] = x < 3u * W ? value_at(x / 3u, y, x % 3u) : -7.0f;
    for (ch = 3; ch <= 4; ++ch) {
        const uint32_t OS = ch * W + 11u, y0 = 4, y1 = 19;
        uint32_t bad = 0, touched = 0, alpha = 0;
        memset(o8, 0xA5, (size_t)OS * H);
        r = fovlp_srgb8_rows(&ctx, img, IS, y0, y1, o8, OS, ch);
        for (y = 0; y < H; ++y)
            for (x = 0; x < OS; ++x) {
                uint8_t b = o8[(size_t)y * OS + x];
                if (y < y0 || y >= y1 || x >= ch * W) { if (b != 0xA5) ++touched; continue; }
                c = x % ch;
                if (c == 3u) { if (b != 255u) ++alpha; continue; }
                if (b != code_ref(img[(size_t)y * IS + 3u * (x / ch) + c])) ++bad;
            }
        check(r == FOV_OK && bad == 0 && alpha == 0 && touched == 0,
              fovcheck_name("srgb8_rows_%u_channels_strided", ch),
              "%s, %u bytes differ from the reference, %u alpha bytes not 255, %u bytes outside "
              "the rows or padding written", fovlp_result_string(r), bad, alpha, touched);
        /* packed strides (0) and the rows in three calls give the same bytes as one call */
        r = fovlp_srgb8_rows(&ctx, img, IS, 0, H, o8b, 0, ch);
        memset(o8, 0x5A, (size_t)ch * W * H);
        if (r == FOV_OK) r = fovlp_srgb8_rows(&ctx, img, IS, 0, 7, o8, 0, ch);
        if (r == FOV_OK) r = fovlp_srgb8_rows(&ctx, img, IS, 7, 7, o8, 0, ch);
        if (r == FOV_OK) r = fovlp_srgb8_rows(&ctx, img, IS, 7, H, o8, 0, ch);
        check(r == FOV_OK && memcmp(o8, o8b, (size_t)ch * W * H) == 0,
              fovcheck_name("srgb8_rows_%u_channels_split_equals_whole", ch), "%s, %s",
              fovlp_result_string(r), memcmp(o8, o8b, (size_t)ch * W * H) ? "differ" : "same");
    }
    {
        /* a packed float image (stride 0) is 3 W floats per row */
        float *packed = (float *)malloc(sizeof(float) * 3u * W * H);
        uint32_t bad = 0;
        if (packed) {
            for (y = 0; y < H; ++y)
                memcpy(packed + (size_t)y * 3u * W, img + (size_t)y * IS, sizeof(float) * 3u * W);
            r = fovlp_srgb8_rows(&ctx, packed, 0, 0, H, o8, 0, 3);
            for (x = 0; x < 3u * W * H; ++x) if (o8[x] != code_ref(packed[x])) ++bad;
            check(r == FOV_OK && bad == 0, "srgb8_rows_packed_input", "%s, %u bytes differ",
                  fovlp_result_string(r), bad);
            free(packed);
        }
    }
    {
        /* every rejection returns its code, writes nothing and logs a non-empty message */
        struct { const char *name; fov_result want; int which; } cases[] = {
            { "channels_0", FOV_ERR_INVALID_ARG, 0 }, { "channels_2", FOV_ERR_INVALID_ARG, 1 },
            { "channels_5", FOV_ERR_INVALID_ARG, 2 }, { "y1_above_height", FOV_ERR_INVALID_ARG, 3 },
            { "y0_above_y1", FOV_ERR_INVALID_ARG, 4 },
            { "rgb_stride_short", FOV_ERR_INVALID_ARG, 5 },
            { "out_stride_short", FOV_ERR_INVALID_ARG, 6 },
        };
        size_t i;
        for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
            int w = cases[i].which;
            memset(o8, 0xA5, 4u * W * H);
            memset(&lc, 0, sizeof lc);
            r = fovlp_srgb8_rows(&ctx, img, w == 5 ? 3u * W - 1u : IS, w == 4 ? 5u : 0u,
                                 w == 3 ? H + 1u : (w == 4 ? 4u : H), o8, w == 6 ? 4u * W - 1u : 0u,
                                 w == 0 ? 0u : w == 1 ? 2u : w == 2 ? 5u : 4u);
            for (x = 0, y = 0; x < 4u * W * H; ++x) y += o8[x] != 0xA5;
            check(r == cases[i].want && y == 0 && lc.calls == 1 && lc.empty == 0 &&
                      lc.code == (int32_t)r,
                  fovcheck_name("srgb8_rows_rejects_%s", cases[i].name),
                  "%s (want %s), %u bytes written, %d log calls, %d empty", fovlp_result_string(r),
                  fovlp_result_string(cases[i].want), y, lc.calls, lc.empty);
        }
        r = fovlp_srgb8_rows(NULL, img, 0, 0, H, o8, 0, 3);
        check(r == FOV_ERR_NULL, "srgb8_rows_rejects_null_ctx", "%s", fovlp_result_string(r));
        r = fovlp_srgb8_rows(&ctx, NULL, 0, 0, H, o8, 0, 3);
        check(r == FOV_ERR_NULL, "srgb8_rows_rejects_null_rgb", "%s", fovlp_result_string(r));
        r = fovlp_srgb8_rows(&ctx, img, 0, 0, H, NULL, 0, 3);
        check(r == FOV_ERR_NULL, "srgb8_rows_rejects_null_out", "%s", fovlp_result_string(r));
        memset(&zero, 0, sizeof zero);
        r = fovlp_srgb8_rows(&zero, img, 0, 0, 1, o8, 0, 3);
        check(r == FOV_ERR_INVALID_ARG, "srgb8_rows_rejects_uninitialised_ctx", "%s",
              fovlp_result_string(r));
    }
    free(mem); free(img); free(o8); free(o8b);
}

int main(void)
{
    test_boundaries();
    test_sweep();
    test_special();
    test_rows();
    return fovcheck_summary();
}
