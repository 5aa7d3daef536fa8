/* bench_heads.c - the safe head starts of IPR, SKIP and FIPR against the thesis's heuristic
   ones (fovsdf_config.heuristic_start 0 and 1), side by side in one process.

   For the six built-in scenes and two stress scenes (thin shells of thickness 0.002 and needles
   of radius 0.002, made with the scene builder), 1 spp, no shadow rays:
     evals/px   distance evaluations that find the visible surface (head-start passes plus the
                sample rays) per pixel;
     ms         wall time per frame, median of --runs runs, one thread, the two variants
                alternating run by run;
     past       traced pixels whose head start lies past the ground truth's hit (classic, eps
                1e-5, 0.01-pixel cone, 4096 steps) by more than 1e-4 (1 + t) (the thesis
                variant's start check restarts those that land inside a surface);
     behind     pixels whose reported depth lies past the ground truth's by more than
                0.01 (1 + t): what reaches the image (CLASSIC's own count is the tracer's);
     PSNR       of the sRGB image against that ground truth, dB.
   CLASSIC and CONE are printed for reference (heuristic_start does not apply to them).

   usage: bench_heads [--size W H] [--runs N] [--scenes a,b]     (default 320 180, 3 runs)
   build: gcc -std=c99 -O2 -I. bench/bench_heads.c -lm -pthread -o build/bench_heads
   "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
   Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025. */
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVIMG_IMPLEMENTATION
#include "../tests/common/fovimg.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"
#include "../examples/fovrun.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NSCENES 8
static const char *g_names[NSCENES] = { "primitives", "columns", "temple", "atrium", "thin", "fractals", "shells", "needles" };

/* The stress scenes: nested thin shells over a floor; needles in front of a sphere. */
static int stress_scene(int which, fovsdf_builtin *bi, fovsdf_node *nodes, uint32_t cap, fovsdf_program *prog, void *mem,
                        size_t memsz)
{
    fovsdf_builder b;
    int32_t r;
    uint64_t s = 7;
    int i;
    fovsdf_builder_init(&b, nodes, cap);
    b.material = 1;
    r = fovsdf_plane(&b, 0.0f, 1.0f, 0.0f, 1.5f);
    if (which == 0) {
        for (i = 0; i < 4; ++i) {
            b.material = 2 + i;
            r = fovsdf_union(&b, r, fovsdf_translate(&b, fovsdf_onion(&b, fovsdf_sphere(&b, 0.4f + 0.35f * (float)i), 0.002f),
                                                     0.3f * (float)(i & 1), 0.0f, 0.2f * (float)i));
        }
    } else {
        b.material = 3;
        r = fovsdf_union(&b, r, fovsdf_translate(&b, fovsdf_sphere(&b, 0.8f), 0.0f, 0.0f, 2.0f));
        for (i = 0; i < 40; ++i) {
            float a[3], e[3];
            int k;
            for (k = 0; k < 3; ++k) {
                s = s * 6364136223846793005ull + 1442695040888963407ull;
                a[k] = (float)((double)(s >> 11) / 9007199254740992.0 * 4.0 - 2.0);
                s = s * 6364136223846793005ull + 1442695040888963407ull;
                e[k] = a[k] + (float)((double)(s >> 11) / 9007199254740992.0 * 3.0 - 1.5);
            }
            b.material = 4 + (i % 3);
            r = fovsdf_union(&b, r, fovsdf_capsule(&b, a, e, 0.002f));
        }
    }
    if (b.err != FOV_OK || fovsdf_program_build(prog, nodes, b.count, r, mem, memsz) != FOV_OK) return 0;
    memset(bi, 0, sizeof *bi);
    fovsdf_scene_init(&bi->scene);
    fovsdf_scene_set_program(&bi->scene, prog);
    bi->scene.t_max = 40.0f;
    fovsdf_camera_init(&bi->camera, 640, 360);
    bi->camera.pos[0] = 0.4f; bi->camera.pos[1] = 0.6f; bi->camera.pos[2] = -5.0f;
    bi->camera.target[0] = 0.0f; bi->camera.target[1] = 0.0f; bi->camera.target[2] = 0.5f;
    bi->camera.fov_y_deg = 50.0f;
    bi->name = g_names[6 + which];
    return 1;
}

static void to_display(const float *rgb, float *disp, size_t n)
{
    size_t i;
    for (i = 0; i < n * 3; ++i) {
        float v = rgb[i];
        disp[i] = fovimg_linear_to_srgb(v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v));
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: bench_heads [options]\n"
          "safe against heuristic head starts of IPR, SKIP and FIPR (heuristic_start 0 and 1)\n"
          "  --size W H          image size (default 320 180)\n"
          "  --runs N            timing runs, median (default 3, at most 31)\n"
          "  --scenes a,b,...    scenes (default primitives,columns,temple,atrium,thin,fractals,shells,needles)\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 320, H = 180, id;
    int runs = 3, a;
    const char *scenes = "primitives,columns,temple,atrium,thin,fractals,shells,needles";
    static fovsdf_node nodes[256];
    static unsigned char pmem[1 << 18];
    fovsdf_program prog;
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--size") && a + 2 < argc) { W = (uint32_t)atoi(argv[a + 1]); H = (uint32_t)atoi(argv[a + 2]); a += 2; }
        else if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (runs < 1) runs = 1;
    if (runs > 31) runs = 31;
    printf("bench_heads: %ux%u, 1 spp, no shadow rays, median of %d runs, 1 thread\n", W, H, runs);
    printf("%-10s %-8s %-7s %9s %9s %7s %7s %8s\n", "scene", "method", "variant", "evals/px", "ms", "past", "behind", "PSNR");
    for (id = 0; id < NSCENES; ++id) {
        size_t npx = (size_t)W * H, sz;
        void *mem = NULL;
        fovsdf_builtin bi;
        float *gt_rgb, *gt_disp, *gt_depth, *rgb, *disp, *start, *depth;
        uint8_t *gt_hit, *mask;
        fovsdf_config cfg;
        fovsdf_ctx ctx;
        fovsdf_output out;
        fovsdf_stats st;
        fov_gaze gaze;
        const uint32_t methods[5] = { FOVSDF_METHOD_CLASSIC, FOVSDF_METHOD_CONE, FOVSDF_METHOD_IPR, FOVSDF_METHOD_SKIP,
                                      FOVSDF_METHOD_FIPR };
        uint32_t mi;
        const char *p = strstr(scenes, g_names[id]);
        if (!p) continue;
        if (id < 6) {
            fovsdf_builtin_size(id, &sz);
            mem = malloc(sz);
            if (fovsdf_builtin_init(id, &bi, mem, sz) != FOV_OK) return 1;
        } else if (!stress_scene((int)id - 6, &bi, nodes, 256, &prog, pmem, sizeof pmem)) {
            fprintf(stderr, "stress scene failed\n");
            return 1;
        }
        bi.camera.width = W;
        bi.camera.height = H;
        gaze.x = 0.5f * (float)W; gaze.y = 0.5f * (float)H;
        gt_rgb = (float *)malloc(npx * 12); gt_disp = (float *)malloc(npx * 12); gt_depth = (float *)malloc(npx * 4);
        rgb = (float *)malloc(npx * 12); disp = (float *)malloc(npx * 12); start = (float *)malloc(npx * 4);
        depth = (float *)malloc(npx * 4);
        gt_hit = (uint8_t *)malloc(npx); mask = (uint8_t *)malloc(npx);
        cfg = fovsdf_config_ground_truth();
        cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
        fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
        fovsdf_output_init(&out);
        out.rgb = gt_rgb; out.depth = gt_depth; out.hit = gt_hit;
        fovrun_render(&ctx, &out, 2, &st);
        to_display(gt_rgb, gt_disp, npx);
        for (mi = 0; mi < 5; ++mi) {
            double times[2][32], psnr[2] = { 0, 0 }, evpx[2] = { 0, 0 };
            long past[2] = { 0, 0 }, behind[2] = { 0, 0 };
            int v, r, nv = methods[mi] >= FOVSDF_METHOD_IPR ? 2 : 1;
            for (r = 0; r < runs; ++r)
                for (v = 0; v < nv; ++v) {
                    size_t i;
                    cfg = fovsdf_config_default();
                    cfg.method = methods[mi];
                    cfg.shading = FOVSDF_SHADE_NO_SHADOWS;
                    cfg.heuristic_start = (uint32_t)v;
                    if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) return 1;
                    fovsdf_output_init(&out);
                    out.rgb = rgb; out.start = start; out.mask = mask; out.depth = depth;
                    times[v][r] = fovrun_render(&ctx, &out, 1, &st);
                    if (r > 0) continue;
                    evpx[v] = (double)(st.evals_lowres + st.evals_primary) / (double)npx;
                    for (i = 0; i < npx; ++i)
                        if (mask[i] == 1 && gt_hit[i] && (double)start[i] > (double)gt_depth[i] + 1e-4 * (1.0 + (double)gt_depth[i]))
                            ++past[v];
                    for (i = 0; i < npx; ++i)
                        if (gt_hit[i] && (double)depth[i] > (double)gt_depth[i] + 1e-2 * (1.0 + (double)gt_depth[i])) ++behind[v];
                    to_display(rgb, disp, npx);
                    fovm_psnr(gt_disp, disp, (int)W, (int)H, 3, &psnr[v]);
                }
            for (v = 0; v < nv; ++v) {
                qsort(times[v], (size_t)runs, sizeof times[v][0], cmp_double);
                printf("%-10s %-8s %-7s %9.2f %9.1f %7ld %7ld %8.2f\n", bi.name, fovsdf_method_name(methods[mi]),
                       nv == 1 ? "-" : (v ? "thesis" : "safe"), evpx[v], times[v][runs / 2], past[v], behind[v], psnr[v]);
            }
            fflush(stdout);
        }
        free(gt_rgb); free(gt_disp); free(gt_depth); free(rgb); free(disp); free(start); free(depth); free(gt_hit); free(mask);
        free(mem);
    }
    return 0;
}
