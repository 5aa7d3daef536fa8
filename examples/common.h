/* common.h - image output for the fov examples: the sRGB encoding, 8-bit PPM/PGM writing and
   PNG writing through OpenImageIO's command-line tool (oiiotool) when it is installed.
   Hosted C99 (stdio, stdlib, string, math); also compiles as C++. All functions are static
   inline, so including this file in several translation units is fine and unused ones do not
   warn. No global state. tests/common/fovimg.h builds its writers on these functions (the
   tests may use the examples' helpers, never the reverse).

   To copy an example out of the repository, take the fov headers and the files of examples/
   that it includes (this one, and fovmetrics.h and fovrun.h for sdf_scenes.c). */
#ifndef FOVEX_COMMON_H
#define FOVEX_COMMON_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Error codes (0 = ok). */
#define FOVEX_ERR_NOMEM (-1)
#define FOVEX_ERR_OPEN  (-2)
#define FOVEX_ERR_IO    (-3)
#define FOVEX_ERR_ARG   (-4)
#define FOVEX_ERR_TOOL  (-5)

/* The IEC 61966-2-1 sRGB encoding of a linear value (no clamping; computed in double). */
static inline float fovex_linear_to_srgb(float v)
{
    double x = (double)v;
    if (x <= 0.0031308) return (float)(x * 12.92);
    return (float)(1.055 * pow(x, 1.0 / 2.4) - 0.055);
}

/* [0,1] -> 0..255: clamp (NaN -> 0), round half up. */
static inline unsigned char fovex_float_to_u8(float v)
{
    double x = (double)v;
    if (!(x > 0.0)) return 0;
    if (x >= 1.0) return 255;
    return (unsigned char)floor(x * 255.0 + 0.5);
}

/* Writes w x h pixels of c = 3 (P6) or c = 1 (P5) interleaved floats in [0,1], top row first,
   as a binary PNM with maxval 255 (no colour-space conversion). */
static inline int fovex_write_pnm(const char *path, const float *px, int w, int h, int c)
{
    FILE *f;
    unsigned char *row;
    size_t rowlen, y, i;
    int ok = 1;
    if (!path || !px || w < 1 || h < 1 || (c != 1 && c != 3)) return FOVEX_ERR_ARG;
    rowlen = (size_t)w * (size_t)c;
    row = (unsigned char *)malloc(rowlen);
    if (!row) return FOVEX_ERR_NOMEM;
    f = fopen(path, "wb");
    if (!f) { free(row); return FOVEX_ERR_OPEN; }
    if (fprintf(f, "%s\n%d %d\n255\n", c == 3 ? "P6" : "P5", w, h) < 0) ok = 0;
    for (y = 0; ok && y < (size_t)h; y++) {
        const float *src = px + y * rowlen;
        for (i = 0; i < rowlen; i++) row[i] = fovex_float_to_u8(src[i]);
        if (fwrite(row, 1, rowlen, f) != rowlen) ok = 0;
    }
    if (fclose(f) != 0) ok = 0;
    free(row);
    return ok ? 0 : FOVEX_ERR_IO;
}

/* 1 if oiiotool is on PATH. */
static inline int fovex_have_oiiotool(void)
{
    return system("command -v oiiotool >/dev/null 2>&1") == 0;
}

/* Appends s to dst (capacity cap) in single quotes for sh; 0 if it does not fit. */
static inline int fovex_shquote(char *dst, size_t cap, const char *s)
{
    size_t len = strlen(dst);
    const char *p;
    if (len + 2 >= cap) return 0;
    dst[len++] = '\'';
    for (p = s; *p; p++) {
        if (*p == '\'') {
            if (len + 5 >= cap) return 0;
            memcpy(dst + len, "'\\''", 4);
            len += 4;
        } else {
            if (len + 2 >= cap) return 0;
            dst[len++] = *p;
        }
    }
    if (len + 2 >= cap) return 0;
    dst[len++] = '\'';
    dst[len] = '\0';
    return 1;
}

/* Runs "oiiotool <in> [extra] -o <out>" quietly. */
static inline int fovex_oiiotool(const char *in, const char *extra, const char *out)
{
    size_t cap = strlen(in) * 4 + strlen(out) * 4 + strlen(extra) + 96;
    char *cmd = (char *)malloc(cap);
    int rc, ok;
    if (!cmd) return FOVEX_ERR_NOMEM;
    strcpy(cmd, "oiiotool ");
    ok = fovex_shquote(cmd, cap, in);
    if (ok) { strcat(cmd, " "); strcat(cmd, extra); strcat(cmd, " -o "); }
    ok = ok && fovex_shquote(cmd, cap, out);
    if (ok) strcat(cmd, " >/dev/null 2>&1");
    if (!ok) { free(cmd); return FOVEX_ERR_ARG; }
    rc = system(cmd);
    free(cmd);
    return rc == 0 ? 0 : FOVEX_ERR_TOOL;
}

/* Writes an 8-bit PNG through oiiotool: the pixels go to "<path>.tmp.ppm" (or .pgm) first,
   which is removed afterwards. --nosoftwareattrib keeps the command line (with the temporary
   name) out of the file's metadata, so the same pixels give the same bytes.
   FOVEX_ERR_TOOL when oiiotool is missing or fails. */
static inline int fovex_write_png(const char *path, const float *px, int w, int h, int c)
{
    char tmp[4096];
    int err;
    if (!path || strlen(path) + 9 > sizeof tmp) return FOVEX_ERR_ARG;
    sprintf(tmp, "%s.tmp.%s", path, c == 3 ? "ppm" : "pgm");
    err = fovex_write_pnm(tmp, px, w, h, c);
    if (!err) err = fovex_oiiotool(tmp, "--nosoftwareattrib", path);
    remove(tmp);
    return err;
}
#endif
