/* pt_sampler.c - fovpt's samplers (fovpt.h SAMPLERS) side by side: the same scenes, methods,
   samples and seeds with cfg.sampler RANDOM and SOBOL, each image's error against a
   high-sample UNIFORM reference (RANDOM, its own seed), and the frame time of both, measured
   interleaved in one run.

     make bench-pt-sampler        (bench/results/pt_sampler.csv; about 10 CPU-minutes)
     ./build/pt_sampler [--ref-spp N] [--w W --h H] [--seeds S] [--scene K] [--out FILE]

   Columns: scene, method, spp, sampler, seeds, psnr_db (10 log10(1 / MSE), the MSE over every
   channel of every pixel, both images clamped to [0, 1], averaged over the seeds), mse,
   ms_per_frame (the fastest of the seeds' frames), ref_spp, width, height, gain_db (SOBOL's
   psnr_db minus RANDOM's on the same row's scene, method and spp; 0 on RANDOM's rows). */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "examples/pt_scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void)
{
#if defined(CLOCK_MONOTONIC) && !defined(_WIN32)
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
#else
    return (double)clock() * 1e3 / CLOCKS_PER_SEC;
#endif
}

static void usage(FILE *f, const char *argv0)
{
    fprintf(f, "usage: %s [--ref-spp N] [--w W --h H] [--seeds S] [--scene K] [--out FILE]\n"
               "  --ref-spp N  samples per pixel of the UNIFORM reference (default 2048)\n"
               "  --w W --h H  image size (default 160 x 120)\n"
               "  --seeds S    seeds per row (default 4)\n"
               "  --scene K    one scene only (0 cornell, 1 mesh100k, 2 cubes441, 3 mirrors, 4 interior)\n"
               "  --out FILE   the CSV (default bench/results/pt_sampler.csv)\n", argv0);
}

static int render(pt_scene *S, uint32_t method, uint32_t sampler, uint32_t spp, uint32_t seed, float *img,
                  double *ms)
{
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output out;
    size_t bytes = 0;
    void *mem;
    fov_gaze g;
    double t0;
    int ok;
    g.x = 0.5f * (float)S->cam.width; g.y = 0.5f * (float)S->cam.height;
    c.method = method; c.sampler = sampler; c.spp = spp; c.seed = seed;
    if (fovpt_memory_size(&c, &S->cam, &bytes) != FOV_OK) return 0;
    mem = malloc(bytes);
    ok = mem && fovpt_init(&ctx, &c, &S->scene, &S->cam, g, mem, bytes) == FOV_OK;
    fovpt_output_init(&out); out.rgb = img;
    t0 = now_ms();
    ok = ok && fovpt_render(&ctx, 0, &out, NULL) == FOV_OK;
    if (ms) *ms = now_ms() - t0;
    free(mem);
    return ok;
}

static double mse_of(const float *a, const float *b, size_t n)
{
    double e = 0.0;
    size_t i;
    for (i = 0; i < n; ++i) {
        double x = a[i] < 1.0f ? (double)a[i] : 1.0, y = b[i] < 1.0f ? (double)b[i] : 1.0;
        e += (x - y) * (x - y);
    }
    return e / (double)n;
}

int main(int argc, char **argv)
{
    static const struct { uint32_t method, spp; const char *name; } runs[] = {
        { FOVPT_METHOD_UNIFORM, 1, "uniform" }, { FOVPT_METHOD_UNIFORM, 4, "uniform" },
        { FOVPT_METHOD_UNIFORM, 16, "uniform" }, { FOVPT_METHOD_LAYERS, 0, "layers" },
    };
    uint32_t W = 160, H = 120, ref_spp = 2048, seeds = 4, r, sc, sc0 = 0, sc1 = PT_SCENE_NUM;
    const char *outp = "bench/results/pt_sampler.csv";
    FILE *f;
    int i;
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--ref-spp") && i + 1 < argc) ref_spp = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--w") && i + 1 < argc) W = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--h") && i + 1 < argc) H = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--seeds") && i + 1 < argc) seeds = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--scene") && i + 1 < argc) { sc0 = (uint32_t)atoi(argv[++i]); sc1 = sc0 + 1; }
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) outp = argv[++i];
        else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { usage(stdout, argv[0]); return 0; }
        else { usage(stderr, argv[0]); return 2; }
    }
    if (W < 8 || H < 8 || W > 4096 || H > 4096 || ref_spp < 1 || seeds < 1 || sc1 > PT_SCENE_NUM) {
        fprintf(stderr, "bad arguments\n");
        return 2;
    }
    f = fopen(outp, "w");
    if (!f) { fprintf(stderr, "cannot write %s\n", outp); return 1; }
    fprintf(f, "scene,method,spp,sampler,seeds,psnr_db,mse,ms_per_frame,ref_spp,width,height,gain_db\n");
    for (sc = sc0; sc < sc1; ++sc) {
        pt_scene S;
        size_t n = (size_t)3 * W * H;
        float *ref = (float *)malloc(sizeof(float) * n), *img = (float *)malloc(sizeof(float) * n);
        if (!ref || !img || pt_scene_make(&S, (int)sc) != 0) { fprintf(stderr, "scene %u\n", sc); return 1; }
        S.cam.width = W; S.cam.height = H;
        if (!render(&S, FOVPT_METHOD_UNIFORM, FOVPT_SAMPLER_RANDOM, ref_spp, 0xabcdefu, ref, NULL)) return 1;
        for (r = 0; r < sizeof runs / sizeof runs[0]; ++r) {
            double mse[2] = { 0.0, 0.0 }, best[2] = { 1e30, 1e30 }, psnr[2];
            uint32_t seed, smp;
            for (seed = 1; seed <= seeds; ++seed)
                for (smp = 0; smp < 2; ++smp) { /* interleaved: RANDOM, SOBOL, RANDOM, ... */
                    double ms = 0.0;
                    if (!render(&S, runs[r].method, smp ? FOVPT_SAMPLER_SOBOL : FOVPT_SAMPLER_RANDOM, runs[r].spp,
                                seed, img, &ms))
                        return 1;
                    mse[smp] += mse_of(img, ref, n) / (double)seeds;
                    if (ms < best[smp]) best[smp] = ms;
                }
            for (smp = 0; smp < 2; ++smp) psnr[smp] = 10.0 * log10(1.0 / mse[smp]);
            for (smp = 0; smp < 2; ++smp) {
                fprintf(f, "%s,%s,%u,%s,%u,%.3f,%.6g,%.2f,%u,%u,%u,%.3f\n", pt_scene_names[sc], runs[r].name,
                        runs[r].spp, smp ? "sobol" : "random", seeds, psnr[smp], mse[smp], best[smp], ref_spp, W,
                        H, smp ? psnr[1] - psnr[0] : 0.0);
            }
            printf("%-9s %-8s spp %2u: random %.2f dB, sobol %.2f dB (%+.2f), %.1f / %.1f ms\n", pt_scene_names[sc],
                   runs[r].name, runs[r].spp, psnr[0], psnr[1], psnr[1] - psnr[0], best[0], best[1]);
            fflush(stdout);
        }
        pt_scene_free(&S);
        free(ref); free(img);
    }
    fclose(f);
    return 0;
}
