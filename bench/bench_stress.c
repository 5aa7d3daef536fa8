/* bench_stress.c - fovsdf.h on the six stress scenes of issue 10 (tests/common/fovstress.h),
   every method at 1 and 4 spp (and the thesis variants of IPR, SKIP and FIPR, heuristic_start 1,
   as ipr_thesis, skip_thesis, fipr_thesis), against a double-precision ground truth along the library's
   own rays (fovsdf_camera_ray). Per scene, method and spp:
     behind_px   pixels whose reported depth lies behind the first surface (t > t_in of
                 every one of its sample rays: certainly a sample behind it)
     behind_smp  sample rays whose hit lies behind the first surface (t > t_in), each sample's
                 t rebuilt with fovsdf_trace from the pixel's `start` output (the same march)
     start_bad   pixels whose head start lies past the first hit of one of its samples (the
                 reference's first t with f <= 0, itself never early: no tolerance)
     false_hit   sample rays reported as hits whose reference never comes within one pixel
                 footprint (the ray's own, tangential: pixel_angle cos(theta) t) plus eps
     missed      sample rays reported as misses whose reference enters an object before t_max
     evals_px    mean distance evaluations per pixel (primary rays; depth shading)
     ms          render time
   FIPR / CONE_FOV count their traced pixels only (mask 1); interpolated pixels are no
   tracer output. CSV: bench/results/stress.csv (header row). "behind" is defined in
   tests/common/fovstress.h: t > t_in, the first t where the double distance is below
   -(8 FLT_EPSILON (|camera| + t) + 0.02 thr(t)).
   Hits at exhausted steps count as hits (as the library shades them).
   Usage: bench_stress [--size W H] [--out FILE] [--far D] [--kind K (0..5: one scene)]
   "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
   Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025. */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "../tests/common/fovstress.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define TOL_FRAC 0.02

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct smp_ref { fs_ref r; float ro[3], rd[3]; } smp_ref;

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: bench_stress [options]\n"
          "fovsdf on the six stress scenes, every method at 1 and 4 spp (bench/results/stress.csv)\n"
          "  --size W H          image size (default 240 135)\n"
          "  --out FILE          CSV (default bench/results/stress.csv)\n"
          "  --far D             distance of the far stress scene (default 1e6)\n"
          "  --kind K            only stress scene K (0..5)\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 240, H = 135, spps[2] = { 1, 4 };
    const char *outp = "bench/results/stress.csv";
    double far_d = 1e6;
    int a, kind, si, only = -1;
    FILE *csv;
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--size") && a + 2 < argc) { W = (uint32_t)atoi(argv[a + 1]); H = (uint32_t)atoi(argv[a + 2]); a += 2; }
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outp = argv[++a];
        else if (!strcmp(argv[a], "--far") && a + 1 < argc) far_d = atof(argv[++a]);
        else if (!strcmp(argv[a], "--kind") && a + 1 < argc) only = atoi(argv[++a]);
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    csv = fopen(outp, "w");
    if (!csv) { fprintf(stderr, "cannot write %s\n", outp); return 1; }
    fprintf(csv, "scene,spp,method,pixels,samples,traced_px,behind_px,behind_smp,start_bad,false_hit,missed,evals_px,ms,worst_behind,worst_start\n");
    printf("%-7s %3s %-12s %8s %9s %9s %9s %9s %8s %8s %9s %8s %9s\n", "scene", "spp", "method", "traced", "behind_px",
           "behind_s", "start_bad", "false_hit", "missed", "evals/px", "ms", "worst", "worst_st");
    for (kind = 0; kind < FS_KINDS; ++kind) {
        static fs_scene sc;
        fovsdf_scene scene;
        fovsdf_camera cam;
        int nobj = kind == FS_DUST ? 80 : (kind == FS_NEEDLE ? 40 : 30);
        if (only >= 0 && kind != only) continue;
        fs_make(&sc, kind, 7u + (uint32_t)kind, nobj, far_d);
        fovsdf_scene_init(&scene);
        scene.dist = fs_dist;
        scene.user = &sc;
        scene.t_max = sc.t_max;
        fovsdf_camera_init(&cam, W, H);
        memcpy(cam.pos, sc.cam, sizeof cam.pos);
        memcpy(cam.target, sc.target, sizeof cam.target);
        memcpy(cam.up, sc.up, sizeof cam.up);
        cam.fov_y_deg = sc.fov;
        for (si = 0; si < 2; ++si) {
            uint32_t spp = spps[si], n = W * H * spp, meth, mi, x, y, s;
            smp_ref *ref = (smp_ref *)malloc(sizeof(smp_ref) * n);
            float *depth = (float *)malloc(sizeof(float) * W * H), *start = (float *)malloc(sizeof(float) * W * H);
            uint8_t *hit = (uint8_t *)malloc(W * H), *mask = (uint8_t *)malloc(W * H);
            fovsdf_ctx ctx;
            fovsdf_config cfg = fovsdf_config_default();
            fov_gaze gz = { 0.5f * (float)W, 0.5f * (float)H };
            cfg.spp = spp;
            cfg.shading = FOVSDF_SHADE_DEPTH;
            if (fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) { fprintf(stderr, "init failed\n"); return 1; }
            /* the reference of every sample ray (independent of the method) */
            for (y = 0; y < H; ++y)
                for (x = 0; x < W; ++x)
                    for (s = 0; s < spp; ++s) {
                        smp_ref *q = &ref[((size_t)y * W + x) * spp + s];
                        float ox, oy, cz;
                        double foot;
                        fovsdf__sample_offset(spp, s, &ox, &oy);
                        (void)fovsdf_camera_ray(&ctx, (float)x + 0.5f + ox, (float)y + 0.5f + oy, q->ro, q->rd);
                        cz = q->rd[0] * ctx.fwd[0] + q->rd[1] * ctx.fwd[1] + q->rd[2] * ctx.fwd[2];
                        foot = (double)ctx.pixel_angle * (double)cz;
                        q->r = fs_reference(&sc, q->ro, q->rd, (double)ctx.t_max, (double)ctx.cfg.eps,
                                            (double)ctx.cfg.eps_px * foot * (double)cz, TOL_FRAC, foot);
                    }
            for (mi = 0; mi < (uint32_t)_FOVSDF_METHOD_NUM + 3u; ++mi) {
                /* every method (IPR, SKIP, FIPR with their safe default), then the thesis's
                   variants of IPR, SKIP and FIPR (heuristic_start 1) as ipr_thesis, ... */
                static const uint32_t thesis[3] = { FOVSDF_METHOD_IPR, FOVSDF_METHOD_SKIP, FOVSDF_METHOD_FIPR };
                static const char *const thesis_name[3] = { "ipr_thesis", "skip_thesis", "fipr_thesis" };
                fovsdf_output out;
                fovsdf_stats st;
                double t0, ms, worst = 0.0, worst_st = -(double)INFINITY;
                long traced = 0, behind_px = 0, behind_smp = 0, start_bad = 0, false_hit = 0, missed = 0;
                const char *mname;
                meth = mi < (uint32_t)_FOVSDF_METHOD_NUM ? mi : thesis[mi - (uint32_t)_FOVSDF_METHOD_NUM];
                mname = mi < (uint32_t)_FOVSDF_METHOD_NUM ? fovsdf_method_name(meth) : thesis_name[mi - (uint32_t)_FOVSDF_METHOD_NUM];
                cfg.method = meth;
                cfg.heuristic_start = mi < (uint32_t)_FOVSDF_METHOD_NUM ? 0u : 1u;
                if (fovsdf_init(&ctx, &cfg, &scene, &cam, gz, NULL, 0) != FOV_OK) { fprintf(stderr, "init failed\n"); return 1; }
                fovsdf_output_init(&out);
                out.depth = depth; out.hit = hit; out.start = start; out.mask = mask;
                memset(&st, 0, sizeof st);
                memset(mask, 1, W * H);
                t0 = now_s();
                (void)fovsdf_render_rows(&ctx, 0, H, &out, &st);
                ms = 1e3 * (now_s() - t0);
                for (y = 0; y < H; ++y)
                    for (x = 0; x < W; ++x) {
                        size_t pi = (size_t)y * W + x;
                        double tin_max = 0.0, thit_min = (double)INFINITY;
                        if (mask[pi] != 1) continue;
                        ++traced;
                        for (s = 0; s < spp; ++s) {
                            const smp_ref *q = &ref[pi * spp + s];
                            fovsdf_hit h;
                            float t0s = start[pi];
                            if (q->r.t_in > tin_max) tin_max = q->r.t_in;
                            if (q->r.t_hit < thit_min) thit_min = q->r.t_hit;
                            if (t0s >= ctx.t_max) { h.kind = FOVSDF_MISS; h.t = ctx.t_max; }
                            else {
                                if (t0s > 0.0f && (meth == FOVSDF_METHOD_IPR || meth == FOVSDF_METHOD_SKIP || meth == FOVSDF_METHOD_FIPR)) {
                                    float p[3];
                                    p[0] = q->ro[0] + q->rd[0] * t0s; p[1] = q->ro[1] + q->rd[1] * t0s; p[2] = q->ro[2] + q->rd[2] * t0s;
                                    if (fovsdf_distance(&ctx, p, NULL, NULL) < 0.0f) t0s = 0.0f; /* the march's start check */
                                }
                                (void)fovsdf_trace(&ctx, q->ro, q->rd, t0s, &h, NULL);
                            }
                            if (q->r.capped) continue;
                            if (h.kind != FOVSDF_MISS) {
                                if ((double)h.t > q->r.t_in) {
                                    ++behind_smp;
                                    if ((double)h.t - q->r.t_in > worst) worst = (double)h.t - q->r.t_in;
                                }
                                if (!q->r.near) ++false_hit;
                            } else if (q->r.t_in < (double)ctx.t_max) {
                                ++missed;
                            }
                        }
                        if (depth[pi] < ctx.t_max && (double)depth[pi] > tin_max) ++behind_px;
                        if (start[pi] > 0.0f && start[pi] < ctx.t_max && thit_min < (double)INFINITY) {
                            if ((double)start[pi] > thit_min) ++start_bad;
                            if ((double)start[pi] - thit_min > worst_st) worst_st = (double)start[pi] - thit_min;
                        }
                    }
                printf("%-7s %3u %-12s %8ld %9ld %9ld %9ld %9ld %8ld %8.1f %9.1f %8.3g %9.3g\n", fs_kind_name[kind], spp,
                       mname, traced, behind_px, behind_smp, start_bad, false_hit, missed,
                       (double)st.evals / (double)(W * H), ms, worst, worst_st);
                fprintf(csv, "%s,%u,%s,%u,%u,%ld,%ld,%ld,%ld,%ld,%ld,%.2f,%.1f,%.4g,%.4g\n", fs_kind_name[kind], spp,
                        mname, W * H, n, traced, behind_px, behind_smp, start_bad, false_hit, missed,
                        (double)st.evals / (double)(W * H), ms, worst, worst_st);
                fflush(stdout);
            }
            free(ref); free(depth); free(start); free(hit); free(mask);
        }
    }
    fclose(csv);
    printf("wrote %s\n", outp);
    return 0;
}
