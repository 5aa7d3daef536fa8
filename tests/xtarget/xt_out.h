/* xt_out.h - text output of the cross-target test programs (render_test.c, mem_test.c):
   whole lines through stdio (hosted, wasm32-wasi) or ARM semihosting (XT_SEMIHOSTING, via
   xt_write() of m4_startup.c), with no printf and no double. Define XT_W (image width) first. */
#ifndef XT_OUT_H
#define XT_OUT_H
#ifdef XT_SEMIHOSTING
void xt_write(const void *buf, size_t n);
static void xt_out(const char *s, size_t n) { xt_write(s, n); }
#else
#include <stdio.h>
static void xt_out(const char *s, size_t n) { (void)fwrite(s, 1, n, stdout); }
#endif

/* ---- a small line buffer; every line is flushed whole ---- */
static char xt_line[XT_W * 9 + 64];
static size_t xt_len;

static void xt_flush(void)
{
    if (xt_len > 0) xt_out(xt_line, xt_len);
    xt_len = 0;
}

static void xt_putc(char c)
{
    if (xt_len == sizeof xt_line) xt_flush();
    xt_line[xt_len++] = c;
}

static void xt_puts(const char *s)
{
    while (*s) xt_putc(*s++);
}

static void xt_putu(uint64_t v)
{
    char tmp[24];
    int n = 0;
    do { tmp[n++] = (char)('0' + (int)(v % 10u)); v /= 10u; } while (v > 0u);
    while (n > 0) xt_putc(tmp[--n]);
}

static void xt_puti(int32_t v)
{
    if (v < 0) { xt_putc('-'); xt_putu((uint64_t)(-(int64_t)v)); }
    else xt_putu((uint64_t)v);
}

static void xt_puthex(uint32_t v, int digits)
{
    static const char hex[] = "0123456789abcdef";
    int i;
    for (i = digits - 1; i >= 0; i--) xt_putc(hex[(v >> (4 * i)) & 15u]);
}

static void xt_endl(void)
{
    xt_putc('\n');
    xt_flush();
}

static uint32_t xt_float_bits(float f)
{
    union { float f; uint32_t u; } cv;
    cv.f = f;
    return cv.u;
}

/* One image row of the dump format (render_test.c): hex sRGB bytes, 0/1 hits, hex float bits. */
static void xt_row_rgb(const uint8_t *row, uint32_t w)
{
    uint32_t x;
    for (x = 0; x < w * 3u; x++) xt_puthex(row[x], 2);
    xt_endl();
}
static void xt_row_hit(const uint8_t *row, uint32_t w)
{
    uint32_t x;
    for (x = 0; x < w; x++) xt_putc(row[x] ? '1' : '0');
    xt_endl();
}
static void xt_row_depth(const float *row, uint32_t w)
{
    uint32_t x;
    for (x = 0; x < w; x++) xt_puthex(xt_float_bits(row[x]), 8);
    xt_endl();
}
#ifndef XT_NO_DUMP_IMAGE /* a program that streams rows defines it (mem_test.c) */
/* The rgb, hit and depth sections of a whole w x h image (hit or depth NULL: section left out). */
static void xt_dump_image(const uint8_t *rgb, const uint8_t *hit, const float *depth, uint32_t w, uint32_t h)
{
    uint32_t y;
    xt_puts("rgb"); xt_endl();
    for (y = 0; y < h; y++) xt_row_rgb(rgb + (size_t)y * w * 3u, w);
    if (hit) {
        xt_puts("hit"); xt_endl();
        for (y = 0; y < h; y++) xt_row_hit(hit + (size_t)y * w, w);
    }
    if (depth) {
        xt_puts("depth"); xt_endl();
        for (y = 0; y < h; y++) xt_row_depth(depth + (size_t)y * w, w);
    }
}
#endif
#endif
