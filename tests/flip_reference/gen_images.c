/*
 * gen_images.c - generates the small test images used by
 * tests/test_flip_reference.c (the committed *.ppm / *.pgm files in this
 * directory were produced by it). Deterministic: no time or libc rand().
 *
 * Build and run from the repository root:
 *   gcc -std=c99 -O2 -Itests/common tests/flip_reference/gen_images.c -lm \
 *       -o /tmp/gen_images && /tmp/gen_images tests/flip_reference
 */
#define FOVIMG_IMPLEMENTATION
#include "fovimg.h"

#include <stdio.h>
#include <string.h>
#include <math.h>

/* small deterministic PRNG (xorshift32) -> [0,1) */
static float rnd(unsigned int *s)
{
    unsigned int x = *s;
    x ^= x << 13; x ^= x >> 17; x ^= x << 5;
    *s = x;
    return (float)(x >> 8) / 16777216.0f;
}

static float clamp01(float v) { return v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v); }

static int save(const char *dir, const char *name, const fovimg *img)
{
    char path[1024];
    int err;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    err = fovimg_write_any(path, img);
    if (err) fprintf(stderr, "writing %s: %s\n", path, fovimg_strerror(err));
    else printf("wrote %s (%dx%d, %d ch)\n", path, img->w, img->h, img->c);
    return err;
}

/* coverage of shape k at (px, py) in pixel units */
static int in_shape(int k, float x, float y)
{
    float dx, dy, d;
    switch (k) {
    case 0: /* red disc */
        dx = x - 20.0f; dy = y - 22.0f;
        return dx * dx + dy * dy < 11.0f * 11.0f;
    case 1: /* green rectangle */
        return x > 34.0f && x < 58.0f && y > 8.0f && y < 26.0f;
    case 2: /* blue triangle */
        return y > 34.0f && y < 58.0f && x > 8.0f + (58.0f - y) * 0.5f &&
               x < 32.0f - (58.0f - y) * 0.5f + 12.0f;
    case 3: /* yellow ring */
        dx = x - 46.0f; dy = y - 46.0f;
        d = sqrtf(dx * dx + dy * dy);
        return d > 7.0f && d < 12.0f;
    default: return 0;
    }
}

static void make_shapes(fovimg *img)
{
    static const float col[4][3] = {
        {0.85f, 0.12f, 0.10f}, {0.15f, 0.75f, 0.20f},
        {0.10f, 0.20f, 0.85f}, {0.95f, 0.85f, 0.15f}
    };
    int x, y, k, sx, sy;
    for (y = 0; y < img->h; y++) {
        for (x = 0; x < img->w; x++) {
            float acc[3] = {0, 0, 0};
            for (sy = 0; sy < 4; sy++) {
                for (sx = 0; sx < 4; sx++) {
                    float fx = (float)x + ((float)sx + 0.5f) / 4.0f;
                    float fy = (float)y + ((float)sy + 0.5f) / 4.0f;
                    float c[3];
                    c[0] = 0.45f + 0.1f * fy / 64.0f;
                    c[1] = 0.50f;
                    c[2] = 0.60f - 0.1f * fy / 64.0f;
                    for (k = 0; k < 4; k++) {
                        if (in_shape(k, fx, fy)) {
                            c[0] = col[k][0]; c[1] = col[k][1]; c[2] = col[k][2];
                        }
                    }
                    acc[0] += c[0]; acc[1] += c[1]; acc[2] += c[2];
                }
            }
            for (k = 0; k < 3; k++)
                img->px[((size_t)y * (size_t)img->w + (size_t)x) * 3 + (size_t)k] = acc[k] / 16.0f;
        }
    }
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "tests/flip_reference";
    fovimg a, b;
    int x, y, k, err = 0;
    unsigned int seed = 0x12345678u;
    size_t i, n;

    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) { /* -h / --help: exit 0; else 2 */
        int help = argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"));
        fputs("usage: gen_images [DIR]\n  writes the test images of tests/test_flip_reference.c into DIR"
              " (default tests/flip_reference)\n  -h, --help  this text\n", help ? stdout : stderr);
        return help ? 0 : 2;
    }

    /* 1. gradient and a dimmed copy */
    fovimg_alloc(&a, 64, 64, 3);
    fovimg_alloc(&b, 64, 64, 3);
    for (y = 0; y < 64; y++) {
        for (x = 0; x < 64; x++) {
            float *p = a.px + ((size_t)y * 64 + (size_t)x) * 3;
            float *q = b.px + ((size_t)y * 64 + (size_t)x) * 3;
            p[0] = (float)x / 63.0f;
            p[1] = (float)y / 63.0f;
            p[2] = 0.25f + 0.5f * (1.0f - (float)x / 63.0f);
            for (k = 0; k < 3; k++) q[k] = 0.9f * p[k];
        }
    }
    err |= save(dir, "gradient.ppm", &a);
    err |= save(dir, "gradient_dim.ppm", &b);
    fovimg_free(&a); fovimg_free(&b);

    /* 2. checkerboard (8 px squares) and a copy shifted by (2, 1) */
    fovimg_alloc(&a, 64, 64, 3);
    fovimg_alloc(&b, 64, 64, 3);
    for (y = 0; y < 64; y++) {
        for (x = 0; x < 64; x++) {
            int xs = (x + 64 - 2) % 64, ys = (y + 64 - 1) % 64;
            float v = ((x / 8 + y / 8) & 1) ? 0.85f : 0.15f;
            float u = ((xs / 8 + ys / 8) & 1) ? 0.85f : 0.15f;
            float *p = a.px + ((size_t)y * 64 + (size_t)x) * 3;
            float *q = b.px + ((size_t)y * 64 + (size_t)x) * 3;
            p[0] = v; p[1] = v; p[2] = 0.9f * v + 0.05f;
            q[0] = u; q[1] = u; q[2] = 0.9f * u + 0.05f;
        }
    }
    err |= save(dir, "checker.ppm", &a);
    err |= save(dir, "checker_shift.ppm", &b);
    fovimg_free(&a); fovimg_free(&b);

    /* 3. coloured shapes; noisy, blurred and recoloured copies */
    fovimg_alloc(&a, 64, 64, 3);
    make_shapes(&a);
    err |= save(dir, "shapes.ppm", &a);
    fovimg_copy(&b, &a);
    n = (size_t)64 * 64 * 3;
    for (i = 0; i < n; i++) b.px[i] = clamp01(b.px[i] + 0.16f * (rnd(&seed) - 0.5f));
    err |= save(dir, "shapes_noise.ppm", &b);
    for (y = 0; y < 64; y++) {          /* 5x5 box blur, edge clamped */
        for (x = 0; x < 64; x++) {
            for (k = 0; k < 3; k++) {
                float s = 0.0f;
                int dx, dy;
                for (dy = -2; dy <= 2; dy++) {
                    for (dx = -2; dx <= 2; dx++) {
                        int xx = x + dx, yy = y + dy;
                        xx = xx < 0 ? 0 : (xx > 63 ? 63 : xx);
                        yy = yy < 0 ? 0 : (yy > 63 ? 63 : yy);
                        s += a.px[((size_t)yy * 64 + (size_t)xx) * 3 + (size_t)k];
                    }
                }
                b.px[((size_t)y * 64 + (size_t)x) * 3 + (size_t)k] = s / 25.0f;
            }
        }
    }
    err |= save(dir, "shapes_blur.ppm", &b);
    for (i = 0; i < n; i += 3) {        /* hue change: rotate channels */
        b.px[i] = a.px[i + 1];
        b.px[i + 1] = a.px[i + 2];
        b.px[i + 2] = a.px[i];
    }
    err |= save(dir, "shapes_recolor.ppm", &b);
    fovimg_free(&a); fovimg_free(&b);

    /* 4. non-square smooth colour pattern and a 5-level quantised copy */
    fovimg_alloc(&a, 96, 40, 3);
    fovimg_alloc(&b, 96, 40, 3);
    for (y = 0; y < 40; y++) {
        for (x = 0; x < 96; x++) {
            float *p = a.px + ((size_t)y * 96 + (size_t)x) * 3;
            float *q = b.px + ((size_t)y * 96 + (size_t)x) * 3;
            p[0] = 0.5f + 0.45f * sinf(0.21f * (float)x) * cosf(0.13f * (float)y);
            p[1] = 0.5f + 0.45f * sinf(0.07f * (float)(x + 2 * y));
            p[2] = 0.5f + 0.45f * cosf(0.17f * (float)y - 0.05f * (float)x);
            for (k = 0; k < 3; k++) q[k] = floorf(p[k] * 4.0f + 0.5f) / 4.0f;
        }
    }
    err |= save(dir, "wide.ppm", &a);
    err |= save(dir, "wide_quant.ppm", &b);
    fovimg_free(&a); fovimg_free(&b);

    /* 5. grey: thin diagonal lines and a copy moved by one pixel */
    fovimg_alloc(&a, 48, 48, 1);
    fovimg_alloc(&b, 48, 48, 1);
    for (y = 0; y < 48; y++) {
        for (x = 0; x < 48; x++) {
            a.px[(size_t)y * 48 + (size_t)x] = ((x + y) % 6 == 0) ? 0.9f : 0.2f;
            b.px[(size_t)y * 48 + (size_t)x] = ((x + y + 1) % 6 == 0) ? 0.9f : 0.2f;
        }
    }
    err |= save(dir, "lines.pgm", &a);
    err |= save(dir, "lines_moved.pgm", &b);
    fovimg_free(&a); fovimg_free(&b);

    return err ? 1 : 0;
}
