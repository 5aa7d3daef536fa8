/*
 * fovimg.h - small float image type and image file I/O for the fov tests.
 *
 * Single-header, stb style. In exactly one C or C++ file:
 *
 *     #define FOVIMG_IMPLEMENTATION
 *     #include "fovimg.h"
 *
 * Hosted C99 (stdio, stdlib, string, math, time); also compiles as C++.
 * No global mutable state. This is test/benchmark tooling, not part of the
 * fov library headers.
 *
 * Image model: fovimg { w, h, c, px } with c = 1 (grey) or 3 (RGB),
 * interleaved, row-major, top row first: px[(y*w + x)*c + ch].
 * Values are plain floats; the 8-bit/16-bit writers and readers map
 * [0,1] <-> [0,maxval] (no colour-space conversion is ever applied
 * implicitly; use fovimg_srgb_to_linear / fovimg_linear_to_srgb).
 *
 * Formats:
 *   .ppm/.pgm/.pnm  binary P6 (RGB) / P5 (grey). Written with maxval 255
 *                   (clamp to [0,1], round half up). Read with maxval
 *                   1..65535 (2 big-endian bytes per sample if > 255),
 *                   values scaled to [0,1] by 1/maxval.
 *   .pfm            "PF" (RGB) / "Pf" (grey) 32-bit float. Written
 *                   little-endian (scale -1.0), rows bottom-to-top as the
 *                   format requires; read either endianness (sign of the
 *                   scale). Rows are flipped on I/O, so in memory the top
 *                   row is first. The |scale| value is not applied.
 *   .png/.exr       through OpenImageIO's command-line tool `oiiotool`
 *                   (fovimg_write_any / fovimg_read_any only):
 *                   write .png: temporary 8-bit PPM/PGM -> oiiotool;
 *                   write .exr: temporary PFM -> oiiotool (float EXR);
 *                   read  .png: oiiotool -> temporary PNM (8/16 bit);
 *                   read  .exr: oiiotool -> temporary uncompressed float
 *                   TIFF, parsed here. Alpha / extra channels are dropped
 *                   (2 channels -> grey, >= 4 -> first three).
 *                   Temporary files go to $TMPDIR (default /tmp) and are
 *                   removed afterwards. FOVIMG_ERR_NOTOOL if oiiotool is
 *                   not on PATH (checked with `command -v oiiotool`).
 *
 * All functions return 0 (FOVIMG_OK) or a negative FOVIMG_ERR_* code and
 * never crash on malformed files: magic, header syntax, dimensions
 * (1..FOVIMG_MAX_DIM each), w*h*c overflow and file length are checked
 * before any pixel buffer is allocated. Readers overwrite *img without
 * freeing it; on failure *img is left as {0, 0, 0, NULL}.
 */
#ifndef FOVIMG_H
#define FOVIMG_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FOVIMG_MAX_DIM 65536

enum {
    FOVIMG_OK = 0,
    FOVIMG_ERR_ARG = -1,         /* invalid argument (NULL, bad w/h/c)  */
    FOVIMG_ERR_NOMEM = -2,       /* allocation failed / size overflow   */
    FOVIMG_ERR_OPEN = -3,        /* cannot open / create the file       */
    FOVIMG_ERR_IO = -4,          /* read or write error, truncated file */
    FOVIMG_ERR_FORMAT = -5,      /* bad magic or malformed header/data  */
    FOVIMG_ERR_SIZE = -6,        /* dimensions out of range             */
    FOVIMG_ERR_UNSUPPORTED = -7, /* unsupported extension/variant       */
    FOVIMG_ERR_NOTOOL = -8,      /* oiiotool not installed              */
    FOVIMG_ERR_TOOL = -9         /* oiiotool failed                     */
};

typedef struct fovimg {
    int w, h, c;   /* width, height, channels (1 or 3) */
    float *px;     /* w*h*c floats, interleaved, top row first */
} fovimg;

/* Allocate a zero-filled image (c must be 1 or 3). */
int fovimg_alloc(fovimg *img, int w, int h, int c);
/* Free the pixels and reset to {0,0,0,NULL}; NULL-safe. */
void fovimg_free(fovimg *img);
/* Deep copy; dst is overwritten (not freed). */
int fovimg_copy(fovimg *dst, const fovimg *src);
/* Human-readable text for an error code. */
const char *fovimg_strerror(int err);

/* Exact IEC 61966-2-1 piecewise sRGB transfer functions (no clamping:
 * values below the threshold use the linear segment, NaN passes through). */
float fovimg_srgb_to_linear(float v);
float fovimg_linear_to_srgb(float v);
/* In-place, every sample of the image. */
void fovimg_image_srgb_to_linear(fovimg *img);
void fovimg_image_linear_to_srgb(fovimg *img);

/* float -> 8 bit: clamp to [0,1] (NaN -> 0), round(v*255) half up. */
unsigned char fovimg_float_to_u8(float v);
/* 8 bit -> float: v / 255. */
float fovimg_u8_to_float(unsigned char v);
/* Whole image to/from 8 bit (out / in have w*h*c bytes). from_u8 allocates. */
int fovimg_to_u8(const fovimg *img, unsigned char *out);
int fovimg_from_u8(fovimg *img, const unsigned char *in, int w, int h, int c);

int fovimg_write_pnm(const char *path, const fovimg *img); /* P6 / P5 */
int fovimg_read_pnm(const char *path, fovimg *img);
int fovimg_write_pfm(const char *path, const fovimg *img); /* PF / Pf */
int fovimg_read_pfm(const char *path, fovimg *img);

/* 1 if `oiiotool` is on PATH, else 0. */
int fovimg_have_oiiotool(void);
/* Dispatch on the (case-insensitive) extension: .ppm .pgm .pnm .pfm
 * natively, .png .exr through oiiotool; anything else is
 * FOVIMG_ERR_UNSUPPORTED. */
int fovimg_write_any(const char *path, const fovimg *img);
int fovimg_read_any(const char *path, fovimg *img);

#ifdef __cplusplus
}
#endif

#endif /* FOVIMG_H */

/* ====================================================================== */
#ifdef FOVIMG_IMPLEMENTATION
#ifndef FOVIMG_IMPLEMENTATION_DONE
#define FOVIMG_IMPLEMENTATION_DONE

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>
#include "../../examples/common.h" /* sRGB encoding, PNM writer, oiiotool bridge */

#ifdef __cplusplus
extern "C" {
#endif

/* ---- basics ----------------------------------------------------------- */

/* Number of samples w*h*c, or 0 on invalid/overflowing input. */
static size_t fovimg__count(int w, int h, int c)
{
    size_t n;
    if (w < 1 || h < 1 || w > FOVIMG_MAX_DIM || h > FOVIMG_MAX_DIM) return 0;
    if (c != 1 && c != 3) return 0;
    n = (size_t)w;
    if ((size_t)h > ((size_t)-1) / n) return 0;
    n *= (size_t)h;
    if ((size_t)c > ((size_t)-1) / n) return 0;
    n *= (size_t)c;
    if (n > ((size_t)-1) / sizeof(float)) return 0;
    return n;
}

static void fovimg__reset(fovimg *img)
{
    img->w = 0; img->h = 0; img->c = 0; img->px = NULL;
}

int fovimg_alloc(fovimg *img, int w, int h, int c)
{
    size_t n;
    if (!img) return FOVIMG_ERR_ARG;
    fovimg__reset(img);
    if (c != 1 && c != 3) return FOVIMG_ERR_ARG;
    if (w < 1 || h < 1 || w > FOVIMG_MAX_DIM || h > FOVIMG_MAX_DIM)
        return FOVIMG_ERR_SIZE;
    n = fovimg__count(w, h, c);
    if (n == 0) return FOVIMG_ERR_NOMEM;
    img->px = (float *)calloc(n, sizeof(float));
    if (!img->px) return FOVIMG_ERR_NOMEM;
    img->w = w; img->h = h; img->c = c;
    return FOVIMG_OK;
}

void fovimg_free(fovimg *img)
{
    if (!img) return;
    free(img->px);
    fovimg__reset(img);
}

int fovimg_copy(fovimg *dst, const fovimg *src)
{
    int err;
    if (!dst || !src || !src->px) return FOVIMG_ERR_ARG;
    err = fovimg_alloc(dst, src->w, src->h, src->c);
    if (err) return err;
    memcpy(dst->px, src->px, fovimg__count(src->w, src->h, src->c) * sizeof(float));
    return FOVIMG_OK;
}

const char *fovimg_strerror(int err)
{
    switch (err) {
    case FOVIMG_OK: return "ok";
    case FOVIMG_ERR_ARG: return "invalid argument";
    case FOVIMG_ERR_NOMEM: return "out of memory or size overflow";
    case FOVIMG_ERR_OPEN: return "cannot open file";
    case FOVIMG_ERR_IO: return "read/write error or truncated file";
    case FOVIMG_ERR_FORMAT: return "malformed file";
    case FOVIMG_ERR_SIZE: return "image dimensions out of range";
    case FOVIMG_ERR_UNSUPPORTED: return "unsupported format";
    case FOVIMG_ERR_NOTOOL: return "oiiotool not found";
    case FOVIMG_ERR_TOOL: return "oiiotool failed";
    default: return "unknown error";
    }
}

static int fovimg__valid(const fovimg *img)
{
    return img && img->px && fovimg__count(img->w, img->h, img->c) != 0;
}

/* ---- conversions -------------------------------------------------------- */

float fovimg_srgb_to_linear(float v)
{
    double x = (double)v;
    if (x <= 0.04045) return (float)(x / 12.92);
    return (float)pow((x + 0.055) / 1.055, 2.4);
}

float fovimg_linear_to_srgb(float v)
{
    return fovex_linear_to_srgb(v);
}

void fovimg_image_srgb_to_linear(fovimg *img)
{
    size_t i, n;
    if (!fovimg__valid(img)) return;
    n = fovimg__count(img->w, img->h, img->c);
    for (i = 0; i < n; i++) img->px[i] = fovimg_srgb_to_linear(img->px[i]);
}

void fovimg_image_linear_to_srgb(fovimg *img)
{
    size_t i, n;
    if (!fovimg__valid(img)) return;
    n = fovimg__count(img->w, img->h, img->c);
    for (i = 0; i < n; i++) img->px[i] = fovimg_linear_to_srgb(img->px[i]);
}

unsigned char fovimg_float_to_u8(float v)
{
    return fovex_float_to_u8(v);   /* clamp (NaN -> 0), round half up */
}

float fovimg_u8_to_float(unsigned char v)
{
    return (float)v / 255.0f;
}

int fovimg_to_u8(const fovimg *img, unsigned char *out)
{
    size_t i, n;
    if (!fovimg__valid(img) || !out) return FOVIMG_ERR_ARG;
    n = fovimg__count(img->w, img->h, img->c);
    for (i = 0; i < n; i++) out[i] = fovimg_float_to_u8(img->px[i]);
    return FOVIMG_OK;
}

int fovimg_from_u8(fovimg *img, const unsigned char *in, int w, int h, int c)
{
    size_t i, n;
    int err;
    if (!img || !in) return FOVIMG_ERR_ARG;
    err = fovimg_alloc(img, w, h, c);
    if (err) return err;
    n = fovimg__count(w, h, c);
    for (i = 0; i < n; i++) img->px[i] = fovimg_u8_to_float(in[i]);
    return FOVIMG_OK;
}

/* ---- header parsing helpers --------------------------------------------- */

static int fovimg__isspace(int ch)
{
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' ||
           ch == '\v' || ch == '\f';
}

/* Skip whitespace and '#' comments (PNM). Returns the next char or EOF. */
static int fovimg__skip_ws(FILE *f, int allow_comments)
{
    int ch;
    for (;;) {
        ch = fgetc(f);
        if (ch == EOF) return EOF;
        if (allow_comments && ch == '#') {
            do { ch = fgetc(f); } while (ch != EOF && ch != '\n' && ch != '\r');
            if (ch == EOF) return EOF;
            continue;
        }
        if (!fovimg__isspace(ch)) return ch;
    }
}

/* Parse a non-negative decimal integer <= limit. 0 ok, else error code.
 * The whitespace character terminating the number is consumed and
 * stored in *term. */
static int fovimg__read_uint(FILE *f, int allow_comments, long limit,
                             long *out, int *term)
{
    long v = 0;
    int ch = fovimg__skip_ws(f, allow_comments);
    int ndig = 0;
    if (ch == EOF) return FOVIMG_ERR_IO;
    while (ch >= '0' && ch <= '9') {
        v = v * 10 + (ch - '0');
        if (v > limit) return FOVIMG_ERR_SIZE;
        ndig++;
        ch = fgetc(f);
    }
    if (ndig == 0) return FOVIMG_ERR_FORMAT;
    if (ch == EOF) return FOVIMG_ERR_IO;
    if (!fovimg__isspace(ch) && !(allow_comments && ch == '#'))
        return FOVIMG_ERR_FORMAT;
    if (ch == '#') { /* comment right after a number: skip it */
        do { ch = fgetc(f); } while (ch != EOF && ch != '\n' && ch != '\r');
        if (ch == EOF) return FOVIMG_ERR_IO;
    }
    *out = v;
    *term = ch;
    return FOVIMG_OK;
}

/* Bytes from the current position to the end of the file, or -1. */
static long fovimg__remaining(FILE *f)
{
    long pos = ftell(f), end;
    if (pos < 0) return -1;
    if (fseek(f, 0, SEEK_END) != 0) return -1;
    end = ftell(f);
    if (fseek(f, pos, SEEK_SET) != 0) return -1;
    if (end < pos) return -1;
    return end - pos;
}

/* ---- PNM ---------------------------------------------------------------- */

int fovimg_write_pnm(const char *path, const fovimg *img)
{
    int err;
    if (!path || !fovimg__valid(img)) return FOVIMG_ERR_ARG;
    err = fovex_write_pnm(path, img->px, img->w, img->h, img->c);
    if (err == FOVEX_ERR_NOMEM) return FOVIMG_ERR_NOMEM;
    if (err == FOVEX_ERR_OPEN) return FOVIMG_ERR_OPEN;
    return err ? FOVIMG_ERR_IO : FOVIMG_OK;
}

int fovimg_read_pnm(const char *path, fovimg *img)
{
    FILE *f;
    int ch1, ch2, c, term, err, bps;
    long w, h, maxval, rem;
    size_t n, i, nbytes;
    unsigned char *buf = NULL;
    if (!img) return FOVIMG_ERR_ARG;
    fovimg__reset(img);
    if (!path) return FOVIMG_ERR_ARG;
    f = fopen(path, "rb");
    if (!f) return FOVIMG_ERR_OPEN;
    ch1 = fgetc(f);
    ch2 = fgetc(f);
    if (ch1 != 'P' || (ch2 != '5' && ch2 != '6')) { fclose(f); return FOVIMG_ERR_FORMAT; }
    c = ch2 == '6' ? 3 : 1;
    ch1 = fgetc(f);
    if (ch1 == EOF) { fclose(f); return FOVIMG_ERR_IO; }
    if (!fovimg__isspace(ch1)) { fclose(f); return FOVIMG_ERR_FORMAT; }
    err = fovimg__read_uint(f, 1, FOVIMG_MAX_DIM, &w, &term);
    if (!err) err = fovimg__read_uint(f, 1, FOVIMG_MAX_DIM, &h, &term);
    if (!err) err = fovimg__read_uint(f, 1, 65535, &maxval, &term);
    if (err == FOVIMG_ERR_SIZE) {
        fclose(f); return FOVIMG_ERR_SIZE; /* note: also maxval > 65535 */
    }
    if (err) { fclose(f); return err; }
    if (w < 1 || h < 1) { fclose(f); return FOVIMG_ERR_SIZE; }
    if (maxval < 1) { fclose(f); return FOVIMG_ERR_FORMAT; }
    bps = maxval > 255 ? 2 : 1;
    n = fovimg__count((int)w, (int)h, c);
    if (n == 0 || n > ((size_t)-1) / 2) { fclose(f); return FOVIMG_ERR_NOMEM; }
    nbytes = n * (size_t)bps;
    rem = fovimg__remaining(f);
    if (rem < 0) { fclose(f); return FOVIMG_ERR_IO; }
    if ((unsigned long)rem < (unsigned long)nbytes) { fclose(f); return FOVIMG_ERR_IO; }
    buf = (unsigned char *)malloc(nbytes);
    if (!buf) { fclose(f); return FOVIMG_ERR_NOMEM; }
    if (fread(buf, 1, nbytes, f) != nbytes) { free(buf); fclose(f); return FOVIMG_ERR_IO; }
    fclose(f);
    err = fovimg_alloc(img, (int)w, (int)h, c);
    if (err) { free(buf); return err; }
    for (i = 0; i < n; i++) {
        long s = bps == 2 ? ((long)buf[2 * i] << 8) | (long)buf[2 * i + 1] : (long)buf[i];
        if (s > maxval) { free(buf); fovimg_free(img); return FOVIMG_ERR_FORMAT; }
        img->px[i] = (float)((double)s / (double)maxval);
    }
    free(buf);
    return FOVIMG_OK;
}

/* ---- PFM ---------------------------------------------------------------- */

static unsigned long fovimg__f2u(float v)
{
    unsigned int u32 = 0;
    unsigned long u;
    memcpy(&u32, &v, 4);
    u = (unsigned long)u32;
    return u;
}

static float fovimg__u2f(unsigned long u)
{
    unsigned int u32 = (unsigned int)(u & 0xFFFFFFFFul);
    float v;
    memcpy(&v, &u32, 4);
    return v;
}

int fovimg_write_pfm(const char *path, const fovimg *img)
{
    FILE *f;
    unsigned char *row;
    size_t rowlen, i;
    int y, ok = 1;
    if (!path || !fovimg__valid(img)) return FOVIMG_ERR_ARG;
    if (sizeof(unsigned int) < 4 || sizeof(float) != 4) return FOVIMG_ERR_UNSUPPORTED;
    rowlen = (size_t)img->w * (size_t)img->c;
    row = (unsigned char *)malloc(rowlen * 4);
    if (!row) return FOVIMG_ERR_NOMEM;
    f = fopen(path, "wb");
    if (!f) { free(row); return FOVIMG_ERR_OPEN; }
    if (fprintf(f, "%s\n%d %d\n-1.0\n", img->c == 3 ? "PF" : "Pf",
                img->w, img->h) < 0) ok = 0;
    for (y = img->h - 1; ok && y >= 0; y--) {   /* bottom row first */
        const float *src = img->px + (size_t)y * rowlen;
        for (i = 0; i < rowlen; i++) {
            unsigned long u = fovimg__f2u(src[i]);
            row[4 * i + 0] = (unsigned char)(u & 0xFFu);
            row[4 * i + 1] = (unsigned char)((u >> 8) & 0xFFu);
            row[4 * i + 2] = (unsigned char)((u >> 16) & 0xFFu);
            row[4 * i + 3] = (unsigned char)((u >> 24) & 0xFFu);
        }
        if (fwrite(row, 4, rowlen, f) != rowlen) ok = 0;
    }
    if (fclose(f) != 0) ok = 0;
    free(row);
    return ok ? FOVIMG_OK : FOVIMG_ERR_IO;
}

int fovimg_read_pfm(const char *path, fovimg *img)
{
    FILE *f;
    int ch1, ch2, c, term, err, little, y;
    long w, h, rem;
    char tok[64];
    int ntok = 0, ch;
    double scale;
    char *endp;
    size_t n, rowlen, i;
    unsigned char *buf;
    if (!img) return FOVIMG_ERR_ARG;
    fovimg__reset(img);
    if (!path) return FOVIMG_ERR_ARG;
    if (sizeof(unsigned int) < 4 || sizeof(float) != 4) return FOVIMG_ERR_UNSUPPORTED;
    f = fopen(path, "rb");
    if (!f) return FOVIMG_ERR_OPEN;
    ch1 = fgetc(f);
    ch2 = fgetc(f);
    if (ch1 != 'P' || (ch2 != 'F' && ch2 != 'f')) { fclose(f); return FOVIMG_ERR_FORMAT; }
    c = ch2 == 'F' ? 3 : 1;
    ch1 = fgetc(f);
    if (ch1 == EOF) { fclose(f); return FOVIMG_ERR_IO; }
    if (!fovimg__isspace(ch1)) { fclose(f); return FOVIMG_ERR_FORMAT; }
    err = fovimg__read_uint(f, 0, FOVIMG_MAX_DIM, &w, &term);
    if (!err) err = fovimg__read_uint(f, 0, FOVIMG_MAX_DIM, &h, &term);
    if (err) { fclose(f); return err; }
    if (w < 1 || h < 1) { fclose(f); return FOVIMG_ERR_SIZE; }
    /* scale token */
    ch = fovimg__skip_ws(f, 0);
    while (ch != EOF && !fovimg__isspace(ch)) {
        if (ntok >= (int)sizeof(tok) - 1) { fclose(f); return FOVIMG_ERR_FORMAT; }
        tok[ntok++] = (char)ch;
        ch = fgetc(f);
    }
    if (ch == EOF) { fclose(f); return FOVIMG_ERR_IO; }
    tok[ntok] = '\0';
    scale = strtod(tok, &endp);
    if (ntok == 0 || *endp != '\0' || !(scale == scale) || scale == 0.0) {
        fclose(f); return FOVIMG_ERR_FORMAT;
    }
    little = scale < 0.0;
    n = fovimg__count((int)w, (int)h, c);
    if (n == 0 || n > ((size_t)-1) / 4) { fclose(f); return FOVIMG_ERR_NOMEM; }
    rem = fovimg__remaining(f);
    if (rem < 0) { fclose(f); return FOVIMG_ERR_IO; }
    if ((unsigned long)rem / 4ul < (unsigned long)n) { fclose(f); return FOVIMG_ERR_IO; }
    buf = (unsigned char *)malloc(n * 4);
    if (!buf) { fclose(f); return FOVIMG_ERR_NOMEM; }
    if (fread(buf, 4, n, f) != n) { free(buf); fclose(f); return FOVIMG_ERR_IO; }
    fclose(f);
    err = fovimg_alloc(img, (int)w, (int)h, c);
    if (err) { free(buf); return err; }
    rowlen = (size_t)w * (size_t)c;
    for (y = 0; y < (int)h; y++) {
        /* file row y (counted from the bottom) -> memory row h-1-y */
        const unsigned char *src = buf + (size_t)y * rowlen * 4;
        float *dst = img->px + (size_t)((int)h - 1 - y) * rowlen;
        for (i = 0; i < rowlen; i++) {
            const unsigned char *b = src + 4 * i;
            unsigned long u;
            if (little)
                u = (unsigned long)b[0] | ((unsigned long)b[1] << 8) |
                    ((unsigned long)b[2] << 16) | ((unsigned long)b[3] << 24);
            else
                u = (unsigned long)b[3] | ((unsigned long)b[2] << 8) |
                    ((unsigned long)b[1] << 16) | ((unsigned long)b[0] << 24);
            dst[i] = fovimg__u2f(u);
        }
    }
    free(buf);
    return FOVIMG_OK;
}

/* ---- minimal TIFF reader (uncompressed float32 strips, as written by
 *      `oiiotool -d float --compression none`) -------------------------- */

static unsigned long fovimg__tget(const unsigned char *p, int nbytes, int little)
{
    unsigned long v = 0;
    int i;
    for (i = 0; i < nbytes; i++) {
        int k = little ? nbytes - 1 - i : i;
        v = (v << 8) | (unsigned long)p[k];
    }
    return v;
}

/* First value of a SHORT/LONG IFD entry p, inline or at an offset. */
static int fovimg__tfirst(const unsigned char *d, size_t size,
                          const unsigned char *p, int little,
                          unsigned long *out)
{
    unsigned long type = fovimg__tget(p + 2, 2, little);
    unsigned long cnt = fovimg__tget(p + 4, 4, little);
    int esz = type == 3 ? 2 : 4;
    if (type != 3 && type != 4) return -1;
    if (cnt == 0) return -1;
    if (cnt * (unsigned long)esz <= 4ul) {
        *out = fovimg__tget(p + 8, esz, little);
    } else {
        size_t off = (size_t)fovimg__tget(p + 8, 4, little);
        if (off > size || size - off < (size_t)esz) return -1;
        *out = fovimg__tget(d + off, esz, little);
    }
    return 0;
}

static int fovimg__read_tiff_float(const char *path, fovimg *img)
{
    FILE *f;
    long fsz;
    unsigned char *d = NULL;
    size_t size, ifd, nent, e;
    int little, err = FOVIMG_OK, oc;
    unsigned long width = 0, height = 0, spp = 1, comp = 1, planar = 1;
    unsigned long sfmt = 1, bits = 0, rps = 0xFFFFFFFFul;
    unsigned long so_cnt = 0, so_type = 0, sb_cnt = 0, sb_type = 0;
    const unsigned char *so_val = NULL, *sb_val = NULL; /* entry value fields */
    int tiled = 0;
    fovimg__reset(img);
    f = fopen(path, "rb");
    if (!f) return FOVIMG_ERR_OPEN;
    fsz = fovimg__remaining(f);
    if (fsz < 8) { fclose(f); return fsz < 0 ? FOVIMG_ERR_IO : FOVIMG_ERR_FORMAT; }
    size = (size_t)fsz;
    d = (unsigned char *)malloc(size);
    if (!d) { fclose(f); return FOVIMG_ERR_NOMEM; }
    if (fread(d, 1, size, f) != size) { free(d); fclose(f); return FOVIMG_ERR_IO; }
    fclose(f);
#define FOVIMG__TFAIL(code) do { err = (code); goto done; } while (0)
    if (d[0] == 'I' && d[1] == 'I') little = 1;
    else if (d[0] == 'M' && d[1] == 'M') little = 0;
    else FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    if (fovimg__tget(d + 2, 2, little) != 42) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    ifd = (size_t)fovimg__tget(d + 4, 4, little);
    if (ifd > size || size - ifd < 2) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    nent = (size_t)fovimg__tget(d + ifd, 2, little);
    if ((size - ifd - 2) / 12 < nent) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    for (e = 0; e < nent; e++) {
        const unsigned char *p = d + ifd + 2 + 12 * e;
        unsigned long tag = fovimg__tget(p, 2, little);
        unsigned long type = fovimg__tget(p + 2, 2, little);
        unsigned long cnt = fovimg__tget(p + 4, 4, little);
        unsigned long val;
        if (type == 3) val = fovimg__tget(p + 8, 2, little);   /* SHORT */
        else val = fovimg__tget(p + 8, 4, little);             /* LONG/offset */
        switch (tag) {
        case 256: width = val; break;
        case 257: height = val; break;
        case 258: /* BitsPerSample (first value; all assumed equal) */
            if (fovimg__tfirst(d, size, p, little, &bits)) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
            break;
        case 259: comp = val; break;
        case 273: so_cnt = cnt; so_type = type; so_val = p + 8; break;
        case 277: spp = val; break;
        case 278: rps = val; break;
        case 279: sb_cnt = cnt; sb_type = type; sb_val = p + 8; break;
        case 284: planar = val; break;
        case 322: case 323: case 324: case 325: tiled = 1; break;
        case 339: /* SampleFormat (first value; all assumed equal) */
            if (fovimg__tfirst(d, size, p, little, &sfmt)) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
            break;
        default: break;
        }
    }
    if (tiled || comp != 1 || bits != 32 || sfmt != 3 || (planar != 1 && spp > 1))
        FOVIMG__TFAIL(FOVIMG_ERR_UNSUPPORTED);
    if (width < 1 || height < 1 || width > FOVIMG_MAX_DIM || height > FOVIMG_MAX_DIM)
        FOVIMG__TFAIL(FOVIMG_ERR_SIZE);
    if (spp < 1 || spp > 64) FOVIMG__TFAIL(FOVIMG_ERR_UNSUPPORTED);
    if (so_cnt == 0 || so_cnt != sb_cnt || rps == 0) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    if (so_type != 3 && so_type != 4) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    if (sb_type != 3 && sb_type != 4) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
    oc = spp >= 3 ? 3 : 1;
    err = fovimg_alloc(img, (int)width, (int)height, oc);
    if (err) goto done;
    {
        /* Walk the strips; samples are contiguous, rows top to bottom. */
        size_t esz_o = so_type == 3 ? 2 : 4, esz_b = sb_type == 3 ? 2 : 4;
        size_t total = (size_t)width * (size_t)height; /* pixels */
        size_t pix = 0, s, k;
        size_t pxbytes = (size_t)spp * 4;
        const unsigned char *oarr = so_val, *barr = sb_val;
        /* arrays are stored inline in the entry when they fit in 4 bytes */
        if (so_cnt > 4 / esz_o) {
            size_t so_off = (size_t)fovimg__tget(so_val, 4, little);
            if (so_off > size || (size - so_off) / esz_o < so_cnt) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
            oarr = d + so_off;
        }
        if (sb_cnt > 4 / esz_b) {
            size_t sb_off = (size_t)fovimg__tget(sb_val, 4, little);
            if (sb_off > size || (size - sb_off) / esz_b < sb_cnt) FOVIMG__TFAIL(FOVIMG_ERR_FORMAT);
            barr = d + sb_off;
        }
        for (s = 0; s < so_cnt && pix < total; s++) {
            const unsigned char *po = oarr + s * esz_o, *pb = barr + s * esz_b;
            size_t off, len, np;
            off = (size_t)fovimg__tget(po, (int)esz_o, little);
            len = (size_t)fovimg__tget(pb, (int)esz_b, little);
            if (off > size || size - off < len) FOVIMG__TFAIL(FOVIMG_ERR_IO);
            np = len / pxbytes;
            if (np > total - pix) np = total - pix;
            for (k = 0; k < np; k++, pix++) {
                const unsigned char *q = d + off + k * pxbytes;
                int ch;
                for (ch = 0; ch < oc; ch++)
                    img->px[pix * (size_t)oc + (size_t)ch] =
                        fovimg__u2f(fovimg__tget(q + 4 * ch, 4, little));
            }
        }
        if (pix != total) FOVIMG__TFAIL(FOVIMG_ERR_IO);
    }
done:
#undef FOVIMG__TFAIL
    free(d);
    if (err) fovimg_free(img);
    return err;
}

/* ---- oiiotool bridge ---------------------------------------------------- */

int fovimg_have_oiiotool(void)
{
    return fovex_have_oiiotool();
}

/* Lower-case extension including the dot, or "" (copied into out). */
static void fovimg__ext(const char *path, char *out, size_t outsz)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    size_t i;
    out[0] = '\0';
    if (!dot || (slash && slash > dot)) return;
    for (i = 0; dot[i] && i + 1 < outsz; i++) {
        char ch = dot[i];
        if (ch >= 'A' && ch <= 'Z') ch = (char)(ch - 'A' + 'a');
        out[i] = ch;
    }
    out[i] = '\0';
}

/* Create a fresh, empty temporary file named <tmpdir>/fovimg_<hex><ext>. */
static int fovimg__mktemp(char *buf, size_t bufsz, const char *ext)
{
    const char *dir = getenv("TMPDIR");
    int attempt;
    unsigned long seed;
    int local = 0;
    if (!dir || !dir[0]) dir = "/tmp";
    seed = (unsigned long)time(NULL) ^ ((unsigned long)clock() << 16) ^
           (unsigned long)(size_t)&local ^ (unsigned long)(size_t)buf;
    for (attempt = 0; attempt < 100; attempt++) {
        FILE *f;
        seed = (seed * 1103515245ul + 12345ul) & 0xFFFFFFFFul;
        seed ^= seed >> 13;
        if (strlen(dir) + strlen(ext) + 32 > bufsz) return FOVIMG_ERR_ARG;
        sprintf(buf, "%s/fovimg_%08lx%s", dir, seed & 0xFFFFFFFFul, ext);
        f = fopen(buf, "wx");
        if (f) { fclose(f); return FOVIMG_OK; }
    }
    return FOVIMG_ERR_OPEN;
}

/* Run: oiiotool <in> [extra] -o <out>, quietly. */
static int fovimg__oiio(const char *in, const char *extra, const char *out)
{
    int err = fovex_oiiotool(in, extra, out);
    if (err == FOVEX_ERR_NOMEM) return FOVIMG_ERR_NOMEM;
    if (err == FOVEX_ERR_ARG) return FOVIMG_ERR_ARG;
    return err ? FOVIMG_ERR_TOOL : FOVIMG_OK;
}

int fovimg_write_any(const char *path, const fovimg *img)
{
    char ext[16], tmp[4096];
    int err;
    if (!path || !fovimg__valid(img)) return FOVIMG_ERR_ARG;
    fovimg__ext(path, ext, sizeof ext);
    if (!strcmp(ext, ".ppm") || !strcmp(ext, ".pgm") || !strcmp(ext, ".pnm"))
        return fovimg_write_pnm(path, img);
    if (!strcmp(ext, ".pfm")) return fovimg_write_pfm(path, img);
    if (strcmp(ext, ".png") != 0 && strcmp(ext, ".exr") != 0)
        return FOVIMG_ERR_UNSUPPORTED;
    if (!fovimg_have_oiiotool()) return FOVIMG_ERR_NOTOOL;
    if (!strcmp(ext, ".png")) {
        err = fovimg__mktemp(tmp, sizeof tmp, img->c == 3 ? ".ppm" : ".pgm");
        if (err) return err;
        err = fovimg_write_pnm(tmp, img);
    } else {
        err = fovimg__mktemp(tmp, sizeof tmp, ".pfm");
        if (err) return err;
        err = fovimg_write_pfm(tmp, img);
    }
    if (!err) err = fovimg__oiio(tmp, "", path);
    remove(tmp);
    return err;
}

int fovimg_read_any(const char *path, fovimg *img)
{
    char ext[16], tmp[4096];
    int err;
    FILE *f;
    if (!img) return FOVIMG_ERR_ARG;
    fovimg__reset(img);
    if (!path) return FOVIMG_ERR_ARG;
    fovimg__ext(path, ext, sizeof ext);
    if (!strcmp(ext, ".ppm") || !strcmp(ext, ".pgm") || !strcmp(ext, ".pnm"))
        return fovimg_read_pnm(path, img);
    if (!strcmp(ext, ".pfm")) return fovimg_read_pfm(path, img);
    if (strcmp(ext, ".png") != 0 && strcmp(ext, ".exr") != 0)
        return FOVIMG_ERR_UNSUPPORTED;
    f = fopen(path, "rb");
    if (!f) return FOVIMG_ERR_OPEN;
    fclose(f);
    if (!fovimg_have_oiiotool()) return FOVIMG_ERR_NOTOOL;
    if (!strcmp(ext, ".png")) {
        err = fovimg__mktemp(tmp, sizeof tmp, ".pnm");
        if (err) return err;
        err = fovimg__oiio(path, "", tmp);
        if (!err) err = fovimg_read_pnm(tmp, img);
    } else {
        err = fovimg__mktemp(tmp, sizeof tmp, ".tif");
        if (err) return err;
        err = fovimg__oiio(path, "-d float --compression none", tmp);
        if (!err) err = fovimg__read_tiff_float(tmp, img);
    }
    remove(tmp);
    return err;
}

#ifdef __cplusplus
}
#endif

#endif /* FOVIMG_IMPLEMENTATION_DONE */
#endif /* FOVIMG_IMPLEMENTATION */
