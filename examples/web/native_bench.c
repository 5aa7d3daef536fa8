/* native_bench.c - the browser demo's frames measured natively, to compare with WebAssembly:
   the same glue (web_sdf.c, web_lp.c or web_pt.c, built with -DWEB_NATIVE; -DWEB_NATIVE_LIBM
   uses libm instead of FOV_NO_LIBM, whose square root on x86 is a software Newton iteration
   about 2x slower in fovsdf, where wasm's is one f32.sqrt), the same calls
   the page makes with one worker (the whole image as one band), one thread. Prints CSV rows
   with the columns of bench/results/web.csv (workers 1, simd "native"): the fastest frame
   time of the foveated and of the reference frame (the least disturbed by other load, as the
   page's fovDemo.measure), measured interleaved.
     for m in sdf lp pt; do
       cc -std=c99 -O2 -ffp-contract=off -DWEB_NATIVE -DWEB_NATIVE_LIBM -DWEB_MODULE_$m \
          examples/web/native_bench.c -lm -o build/native_bench_$m && ./build/native_bench_$m; done
   (make bench-web-native does this). frames: 7 of each by default, after one warm-up pair.
   Not part of the library. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#if defined(WEB_MODULE_sdf)
#include "web_sdf.c"
#elif defined(WEB_MODULE_lp)
#include "web_lp.c"
#else
#include "web_pt.c"
#endif

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
static double fastest(const double *v, int n)
{
    double m = v[0];
    int i;
    for (i = 1; i < n; ++i) m = v[i] < m ? v[i] : m;
    return m;
}

/* one frame of the mode, the whole image; ref 1: the reference */
static int frame(int mode, uint32_t w, uint32_t h, int ref, uint32_t k)
{
    float gx = 0.5f * (float)w, gy = 0.5f * (float)h;
    (void)mode; (void)k;
#if defined(WEB_MODULE_sdf)
    return sdf_render(ref ? 4u : (mode == 0 ? 8u : 7u), gx, gy, 0.0f, 0, h, 0, k, 0.0f);
#elif defined(WEB_MODULE_lp)
    if (ref) return lp_reference(0.0f, 0, h);
    {
        int n, r = lp_begin(gx, gy, 0.0f, 0.0f);
        if (r != 0) return r;
        n = lp_shade(0, lp_sample_rows_count());
        if (n < 0) return n;
        if ((r = lp_scatter((uint32_t)n)) != 0) return r;
        return lp_finish(0);
    }
#else
    return pt_render(ref ? 1u : 0u, gx, gy, 0.0f, 0, h, 0, 0.0f);
#endif
}

int main(int argc, char **argv)
{
    int frames = argc > 1 ? atoi(argv[1]) : 7, mode, s, i, r;
    static const uint32_t size[2][2] = { { 320, 180 }, { 640, 360 } };
#if defined(WEB_MODULE_sdf)
    static const char *names[] = { "sdf_cone_fov", "sdf_fipr" };
    const char *scene = "primitives";
    int modes = 2;
#elif defined(WEB_MODULE_lp)
    static const char *names[] = { "lp_c_fov" };
    const char *scene = "primitives";
    int modes = 1;
#else
    static const char *names[] = { "pt_layers", "pt_selective" };
    const char *scene = "cornell";
    int modes = 2;
#endif
    double tf[64], tr[64];
    if (frames < 1 || frames > 64) frames = 7;
    for (mode = 0; mode < modes; ++mode)
        for (s = 0; s < 2; ++s) {
            uint32_t w = size[s][0], h = size[s][1];
#if defined(WEB_MODULE_sdf)
            r = sdf_setup(0, w, h, 0);
#elif defined(WEB_MODULE_lp)
            r = lp_setup(0, w, h, 2, 1, 0);
#else
            r = pt_setup(w, h, mode == 0 ? 1u : 3u, 0);
#endif
            if (r != 0) { fprintf(stderr, "%s setup: %d\n", names[mode], r); return 1; }
            if ((r = frame(mode, w, h, 0, 0)) != 0 || (r = frame(mode, w, h, 1, 0)) != 0) {
                fprintf(stderr, "%s frame: %d\n", names[mode], r);
                return 1;
            }
            for (i = 0; i < frames; ++i) {   /* a failing frame is an error, never a fast one */
                double t0 = now_ms();
                int rf = frame(mode, w, h, 0, (uint32_t)i + 1u), rr;
                tf[i] = now_ms() - t0;
                t0 = now_ms();
                rr = frame(mode, w, h, 1, (uint32_t)i + 1u);
                tr[i] = now_ms() - t0;
                if (rf != 0 || rr != 0) {
                    fprintf(stderr, "%s %ux%u frame %d: %d (foveated) %d (reference)\n", names[mode],
                            w, h, i + 1, rf, rr);
                    return 1;
                }
            }
            {
                double ff = 1000.0 / fastest(tf, frames), fr = 1000.0 / fastest(tr, frames);
                printf("%s,%s,%u,%u,1,native,%.2f,%.2f,%.3f\n", names[mode], scene, w, h, ff, fr, ff / fr);
            }
        }
    return 0;
}
