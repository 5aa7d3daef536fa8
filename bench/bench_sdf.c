/* bench_sdf.c - run time against error for every fovsdf method (make bench-sdf).

   For every built-in scene, method, samples per pixel and gaze position (and, for foveated
   methods, fovea size and periphery refresh): distance evaluations per pixel (deterministic,
   split by pass), wall time (median of --runs runs, every method in this one process, so the
   time ratio against classic is measured side by side), and the error against the ground truth
   (classic tracer, epsilon 1e-5, 0.01-pixel cone, 4096 steps, same spp): PSNR, SSIM, FLIP,
   hit-mask mismatch and mean |dt|/t. The default figures include soft shadows (since the
   naive baseline and the *_cb rows were added; before, the default run shaded without shadow
   rays and --shadows added them): --no-shadows gives the old shading.

   Beside the library's methods on the built-in programs, at 1 spp:
     naive        what a user writes without the library: the scene as a plain C function
                  (bench/sdf_naive.h, checked against the built-in program by
                  tests/test_sdf_naive.c), a scalar loop per pixel over the same camera:
                  classic sphere tracing with the pixel-cone threshold max(eps, eps_px
                  pixel_angle t) (the library's default eps, eps_px, max_steps, t_max),
                  tetrahedron normals (4 evaluations, step max(1e-4, pixel_angle t / 2)),
                  Lambert and Algorithm 2 soft shadows per light (the scene's lights and k,
                  the default shadow_t0, shadow_steps, shadow_eps), the palette, checkerboard
                  and sky of the library; rows rendered with the same threads as the others
     M_cb_point   method M (classic, cone, cone_fov) driven by that same C function as the
                  user callback scene.dist_ex
     M_cb_batch   the same through the batch callback scene.dist_batch (a loop over the batch
                  calling the C function), when fovsdf.h has it
     M_cb         the faster of M_cb_point and M_cb_batch (a copy of that row)
   so users with their own SDF see what the library gives them, and the interpreter's cost is
   visible (M_cb against M); then, with shadows:
     M_shfov      method M (cone, cone_fov) with cheaper shadow rays beyond 7.5 degrees of the
                  gaze (config.shadow_fov_deg 7.5, the other shadow_fov fields at their
                  defaults; cone_fov's fovea is 7.5 degrees), the last rows of the group

   Writes bench/results/sdf.csv; the first columns are an interface other tools read:
     scene,method,spp,fovea_deg,refresh,gaze,evals_per_px,time_ms,speedup_vs_classic,psnr,ssim,
     flip,hit_mismatch_pct
   then: evals_lowres_per_px,evals_primary_per_px,evals_shading_per_px,evals_total_per_px,
     mean_rel_dt,shading,width,height,runs,psnr_e0_5,psnr_e5_10,psnr_e10_20,psnr_e20_up,
     flip_e0_5,flip_e5_10,flip_e10_20,flip_e20_up,traced_pct,psnr_vs_classic,flip_vs_classic,
     hit_mismatch_vs_classic_pct,
   and (issue 12; other tools read these names too):
     speedup_vs_naive,ns_per_eval,prims_per_eval,frame_ms,threads,shadow_evals_per_px,simd,
     build
   evals_per_px counts the evaluations that find the visible surface (head-start passes plus the
   sample rays), which is what the methods differ in; shading evaluations (normals, shadow rays)
   are reported separately (foveated methods shade fewer rays). psnr_eA_B / flip_eA_B: the error
   over the pixels between A and B degrees of eccentricity from the gaze; traced_pct: pixels
   that traced their own rays (100 but for fipr and cone_fov); *_vs_classic: against classic at
   the same spp and gaze (the same hit threshold: what an acceleration itself changes). Non-foveated methods have
   fovea_deg 0 and refresh 1. refresh is the periphery's rate relative to the fovea (1, 0.5,
   0.25): such a row renders a whole refresh cycle of 1/refresh frames of the static scene; its
   time and evaluations are per frame, its error that of the image after the cycle (equal to
   the refresh-1 image for a static scene; a moving camera would add staleness, not measured
   here). speedup_vs_naive: naive's time_ms / the row's, in the same run (0 in groups without
   a naive row: spp 4 and 16); ns_per_eval: the wall time of the frame rendered on one thread
   (one run) / its evaluations (evals_total); prims_per_eval: primitive evaluations per
   distance evaluation (fovsdf_stats.prims / evals; 0 for naive and the callbacks, which
   report none); frame_ms: the frame rendered on all `threads` cores, median of the runs (the
   time_ms figures when --threads is the number of cores, the default); shadow_evals_per_px:
   shadow-ray evaluations per pixel; simd: the instruction set the build targeted (scalar with
   -DFOVSDF_NO_SIMD, else avx2, sse2, neon, simd128 from the compiler's macros, else scalar);
   build: the build's name (-DBENCH_SDF_BUILD="..."; make bench-sdf-native: native, -O2
   -march=native; make bench-sdf-nosimd: nosimd, -DFOVSDF_NO_SIMD; default: default). With
   gnuplot installed it also draws bench/results/sdf_<scene>.png (speed-up against PSNR).

   usage: bench_sdf [--full] [--hd] [--size W H] [--quick] [--runs N] [--threads N]
                    [--scenes a,b] [--no-shadows] [--out FILE] [--append] [--plots-only]
                    [--fov-grid]
   --plots-only: redraw the plots of FILE; --fov-grid: classic, fipr and cone_fov only, every
   fovea and refresh, 1 and 16 spp, gaze at the centre and the corner. --quick: 1 spp only;
   --size: the image size (default 640x360); --append: add rows to FILE (no header line when
   it has one), how the second builds join the default one's CSV.
   Default grid: every method at 1 spp with the gaze at the centre (fipr and cone_fov with
   the 7.5-degree fovea, refresh 1), naive, the *_cb and *_shfov rows, classic, cone and ipr at 4 and
   16 spp, and cone_fov at 16 spp beside classic at 16 spp (about 11 minutes on 2 cores at
   640x360 without shadows, before the naive and callback rows; shadows and the one-thread
   run of each row make it several times longer). --full: every method at 1, 4, 16 spp, gaze
   at the centre and at a corner (10 % of the width and height), fipr and cone_fov at every
   fovea (2.5, 5, 7.5, 10, 15 degrees) and refresh (1, 1/2, 1/4), naive and the callback rows
   at 1 spp: hours. --hd: 1920x1080. --no-shadows: shading without shadow rays (as in the
   thesis's IPR/FIPR study).
   "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
   Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025. */
#define FOVSDF_IMPLEMENTATION
#include "../fovsdf.h"
#define FOVIMG_IMPLEMENTATION
#include "../tests/common/fovimg.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"
#include "../examples/fovrun.h"
#include "sdf_naive.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef BENCH_SDF_BUILD
#define BENCH_SDF_BUILD "default"
#endif
/* the instruction set the build targeted (the simd column) */
#if defined(FOVSDF_NO_SIMD)
#define BENCH_SIMD "scalar"
#elif defined(__AVX2__)
#define BENCH_SIMD "avx2"
#elif defined(__SSE2__)
#define BENCH_SIMD "sse2"
#elif defined(__ARM_NEON)
#define BENCH_SIMD "neon"
#elif defined(__wasm_simd128__)
#define BENCH_SIMD "simd128"
#else
#define BENCH_SIMD "scalar"
#endif

/* what a row renders: the library on the built-in program, the naive loop, or the library on
   the scene's C function as a per-point or a batch callback */
enum { K_LIB = 0, K_NAIVE, K_CB_POINT, K_CB_BATCH, K_SHFOV };

typedef struct job_t {
    uint32_t scene, method, spp, corner, refresh, kind;
    float fovea;
} job_t;

static int foveated(uint32_t m) { return m == FOVSDF_METHOD_FIPR || m == FOVSDF_METHOD_CONE_FOV; }

typedef struct img_t {
    float *rgb, *disp, *depth;
    uint8_t *hit;
} img_t;

static void img_alloc(img_t *m, size_t n)
{
    m->rgb = (float *)malloc(n * 3 * sizeof(float));
    m->disp = (float *)malloc(n * 3 * sizeof(float));
    m->depth = (float *)malloc(n * sizeof(float));
    m->hit = (uint8_t *)malloc(n);
}
static void img_free(img_t *m) { free(m->rgb); free(m->disp); free(m->depth); free(m->hit); }

static void to_display(img_t *m, size_t n)
{
    size_t i;
    for (i = 0; i < n * 3; ++i) {
        float v = m->rgb[i];
        m->disp[i] = fovimg_linear_to_srgb(v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v));
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

static void progress(int done, int total, const char *what)
{
    int i, w = 30, f = total ? done * w / total : w;
    fprintf(stderr, "\r[");
    for (i = 0; i < w; ++i) fputc(i < f ? '#' : '-', stderr);
    fprintf(stderr, "] %3d/%d %-40.40s", done, total, what);
    if (done == total) fputc('\n', stderr);
    fflush(stderr);
}

/* ---- the scene's C function as user callbacks ------------------------------------------ */
static float cb_point(const float p[3], fovsdf_query *q, void *user)
{
    naive_fn fn = *(const naive_fn *)user;
    int32_t m = 0;
    float d = fn(p, &m);
    q->material = m;
    return d;
}
#ifdef FOVSDF_BATCH
static void cb_batch(fovsdf_batch *b, void *user)
{
    naive_fn fn = *(const naive_fn *)user;
    uint32_t i;
    for (i = 0; i < b->n; ++i) {
        float p[3];
        int32_t m = 0;
        p[0] = b->x[i]; p[1] = b->y[i]; p[2] = b->z[i];
        b->d[i] = fn(p, &m);
        if (b->material) b->material[i] = m;
    }
}
#endif

/* ---- naive: a plain scalar loop per pixel, what a user writes without the library ------ */
typedef struct naive_view {
    naive_fn fn;
    uint32_t width, height, max_steps, shadow_steps, num_lights, shadows;
    float origin[3], right[3], up[3], fwd[3], tan_half_y, aspect, pixel_angle;
    float eps, eps_px, t_max, shadow_t0, shadow_eps;
    fovsdf_light lights[FOVSDF_MAX_LIGHTS];
    float ambient[3], sky_zenith[3], sky_horizon[3];
    float *rgb, *depth; /* outputs, width x height */
    uint8_t *hit;
} naive_view;

static float nvb_dot(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static float nvb_normalize(float v[3])
{
    float l = sqrtf(nvb_dot(v, v));
    if (l > 0.0f) { v[0] /= l; v[1] /= l; v[2] /= l; }
    return l;
}

static void naive_pixel(const naive_view *v, uint32_t x, uint32_t y, fovsdf_stats *st)
{
    static const float pal[8][3] = {
        { 0.80f, 0.80f, 0.80f }, { 0.0f, 0.0f, 0.0f }, { 0.85f, 0.30f, 0.25f },
        { 0.30f, 0.55f, 0.85f }, { 0.90f, 0.75f, 0.30f }, { 0.35f, 0.75f, 0.40f },
        { 0.70f, 0.45f, 0.80f }, { 0.92f, 0.90f, 0.85f }
    };
    static const float tet[4][3] = { { 1.0f, -1.0f, -1.0f }, { -1.0f, -1.0f, 1.0f },
                                     { -1.0f, 1.0f, -1.0f }, { 1.0f, 1.0f, 1.0f } };
    float u = (((float)x + 0.5f) / (float)v->width * 2.0f - 1.0f) * v->tan_half_y * v->aspect;
    float w = (1.0f - ((float)y + 0.5f) / (float)v->height * 2.0f) * v->tan_half_y;
    float rd[3], p[3], t = 0.0f, d = 0.0f, col[3], eps_cone = v->eps_px * v->pixel_angle;
    int32_t mat = 0;
    uint32_t i, k, hit = 0, steps = 0;
    size_t at = (size_t)y * v->width + x;
    for (k = 0; k < 3; ++k) rd[k] = v->fwd[k] + u * v->right[k] + w * v->up[k];
    nvb_normalize(rd);
    for (;;) { /* classic sphere tracing */
        if (t > v->t_max) break;
        if (steps >= v->max_steps) { hit = 1; break; } /* out of steps: a hit, as the library */
        for (k = 0; k < 3; ++k) p[k] = v->origin[k] + rd[k] * t;
        d = v->fn(p, &mat);
        ++steps;
        if (d < (v->eps > eps_cone * t ? v->eps : eps_cone * t)) { hit = 1; break; }
        t += d;
    }
    st->evals += steps;
    st->evals_primary += steps;
    st->rays++;
    if (hit) {
        float n[3] = { 0.0f, 0.0f, 0.0f }, h = 0.5f * v->pixel_angle * t, alb[3], acc[3];
        st->hits++;
        if (h < 1e-4f) h = 1e-4f;
        for (k = 0; k < 3; ++k) p[k] = v->origin[k] + rd[k] * t;
        for (i = 0; i < 4; ++i) { /* tetrahedron normal */
            float q[3], e;
            for (k = 0; k < 3; ++k) q[k] = p[k] + h * tet[i][k];
            e = v->fn(q, NULL);
            for (k = 0; k < 3; ++k) n[k] += tet[i][k] * e;
        }
        st->evals += 4;
        st->evals_normal += 4;
        if (!(nvb_normalize(n) > 0.0f)) { n[0] = 0.0f; n[1] = 1.0f; n[2] = 0.0f; }
        if (mat == 1) { /* checkerboard on x/z */
            int32_t ix = (int32_t)floorf(p[0]), iz = (int32_t)floorf(p[2]);
            alb[0] = alb[1] = alb[2] = ((ix + iz) & 1) ? 0.85f : 0.30f;
        } else {
            int32_t m = mat < 0 ? 0 : mat & 7;
            alb[0] = pal[m][0]; alb[1] = pal[m][1]; alb[2] = pal[m][2];
        }
        acc[0] = v->ambient[0]; acc[1] = v->ambient[1]; acc[2] = v->ambient[2];
        for (i = 0; i < v->num_lights; ++i) {
            const fovsdf_light *L = &v->lights[i];
            float l[3], dist, att = 1.0f, ndl, sh = 1.0f;
            if (L->type == FOVSDF_LIGHT_POINT) {
                for (k = 0; k < 3; ++k) l[k] = L->v[k] - p[k];
                dist = nvb_normalize(l);
                if (L->range > 0.0f) {
                    if (dist > 8.0f * L->range) continue;
                    att = 1.0f / (1.0f + dist * dist / (L->range * L->range));
                }
            } else {
                for (k = 0; k < 3; ++k) l[k] = L->v[k];
                nvb_normalize(l);
                dist = v->t_max;
            }
            ndl = nvb_dot(n, l);
            if (ndl <= 0.0f) continue;
            if (v->shadows && L->shadow_k >= 0.0f) { /* Algorithm 2 soft shadow */
                float kk = L->shadow_k > 0.0f ? L->shadow_k : 16.0f, s = v->shadow_t0, q[3];
                float o[3], res = 1.0f;
                uint32_t j;
                for (k = 0; k < 3; ++k) o[k] = p[k] + n[k] * 2.0f * v->eps;
                st->shadow_rays++;
                for (j = 0; j < v->shadow_steps && s < dist; ++j) {
                    float e;
                    for (k = 0; k < 3; ++k) q[k] = o[k] + l[k] * s;
                    e = v->fn(q, NULL);
                    st->evals++;
                    st->evals_shadow++;
                    if (kk * e / s < res) res = kk * e / s;
                    if (res < v->shadow_eps) { res = 0.0f; break; }
                    s += e;
                }
                sh = res < 0.0f ? 0.0f : (res > 1.0f ? 1.0f : res);
            }
            for (k = 0; k < 3; ++k) acc[k] += L->color[k] * ndl * att * sh;
        }
        for (k = 0; k < 3; ++k) {
            float c = alb[k] * acc[k];
            col[k] = c > 0.0f ? (c < 65504.0f ? c : 65504.0f) : 0.0f;
        }
    } else { /* sky */
        float s = rd[1] < 0.0f ? 0.0f : (rd[1] > 1.0f ? 1.0f : rd[1]);
        for (k = 0; k < 3; ++k) col[k] = v->sky_horizon[k] + (v->sky_zenith[k] - v->sky_horizon[k]) * s;
        t = v->t_max;
    }
    v->rgb[3 * at] = col[0]; v->rgb[3 * at + 1] = col[1]; v->rgb[3 * at + 2] = col[2];
    v->depth[at] = t;
    v->hit[at] = (uint8_t)hit;
}

typedef struct naive_job {
    const naive_view *v;
    uint32_t band, first, step;
    fovsdf_stats stats;
} naive_job;

static void *naive_worker(void *arg)
{
    naive_job *j = (naive_job *)arg;
    uint32_t y, x;
    for (y = j->first * j->band; y < j->v->height; y += j->step * j->band) {
        uint32_t y1 = y + j->band < j->v->height ? y + j->band : j->v->height, yy;
        for (yy = y; yy < y1; ++yy)
            for (x = 0; x < j->v->width; ++x) naive_pixel(j->v, x, yy, &j->stats);
    }
    return NULL;
}

/* the naive frame on nthreads threads, bands of 8 rows round robin (as fovrun_render) */
static double naive_render(const naive_view *v, int nthreads, fovsdf_stats *st)
{
    pthread_t th[64];
    naive_job jobs[64];
    int i;
    double t0 = fovrun_now_ms();
    if (nthreads < 1) nthreads = 1;
    if (nthreads > 64) nthreads = 64;
    for (i = 0; i < nthreads; ++i) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].v = v; jobs[i].band = 8; jobs[i].first = (uint32_t)i; jobs[i].step = (uint32_t)nthreads;
        pthread_create(&th[i], NULL, naive_worker, &jobs[i]);
    }
    memset(st, 0, sizeof *st);
    for (i = 0; i < nthreads; ++i) {
        pthread_join(th[i], NULL);
        fovsdf_stats_add(st, &jobs[i].stats);
    }
    return fovrun_now_ms() - t0;
}

/* ---- one row's rendering: kind, config, scene; returns ms per frame, stats per cycle ------ */
typedef struct render_req {
    uint32_t kind;
    fovsdf_config cfg;
    const fovsdf_scene *scene;
    const fovsdf_camera *cam;
    fov_gaze gaze;
    fovsdf_output out;
    naive_view nv;
    uint32_t refresh; /* frames per cycle (1 but for foveated rows) */
} render_req;

static double render_once(render_req *rq, int nthreads, fovsdf_stats *st)
{
    fovsdf_ctx ctx;
    fovsdf_stats s1;
    double ms = 0.0;
    uint32_t f;
    if (rq->kind == K_NAIVE) { rq->refresh = 1; return naive_render(&rq->nv, nthreads, st); }
    memset(st, 0, sizeof *st);
    /* a refresh cycle of `refresh` frames (static scene and gaze): the time is per frame */
    for (f = 0; f < rq->cfg.refresh + (rq->cfg.refresh == 0); ++f) {
        rq->cfg.frame = f;
        if (fovsdf_init(&ctx, &rq->cfg, rq->scene, rq->cam, rq->gaze, NULL, 0) != FOV_OK) {
            fprintf(stderr, "init failed\n");
            exit(1);
        }
        ms += fovrun_render(&ctx, &rq->out, nthreads, &s1);
        fovsdf_stats_add(st, &s1);
        rq->refresh = ctx.cfg.refresh;
    }
    return ms / (double)rq->refresh;
}

static double median_of(double *t, int n)
{
    qsort(t, (size_t)n, sizeof t[0], cmp_double);
    return t[n / 2];
}

/* one CSV row, kept until its (scene, spp, gaze) group is complete (speedup_vs_naive) */
typedef struct row_t {
    char scene[16], method[32], gaze[8], shading[12];
    uint32_t spp, width, height;
    int runs, threads, has_fovea;
    double fovea, refresh, evals_per_px, ms, speedup_classic, psnr, ssim, flip, mismatch;
    double ev_low, ev_prim, ev_shade, ev_total, rel, bp[4], bf[4], traced, psnr_cl, flip_cl;
    double mis_cl, ns_per_eval, prims_per_eval, frame_ms, shadow_per_px;
} row_t;

static void row_print(FILE *csv, const row_t *r, double naive_ms)
{
    fprintf(csv, "%s,%s,%u,%g,%g,%s,%.4f,%.3f,%.4f,%.4f,%.6f,%.6f,%.5f,%.4f,%.4f,%.4f,%.4f,%.4e,%s,%u,%u,%d,"
                 "%.4f,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f,%.3f,%.4f,%.6f,%.5f,"
                 "%.4f,%.3f,%.4f,%.3f,%d,%.4f,%s,%s\n",
            r->scene, r->method, r->spp, r->fovea, r->refresh, r->gaze, r->evals_per_px, r->ms,
            r->speedup_classic, r->psnr, r->ssim, r->flip, r->mismatch, r->ev_low, r->ev_prim,
            r->ev_shade, r->ev_total, r->rel, r->shading, r->width, r->height, r->runs, r->bp[0],
            r->bp[1], r->bp[2], r->bp[3], r->bf[0], r->bf[1], r->bf[2], r->bf[3], r->traced,
            r->psnr_cl, r->flip_cl, r->mis_cl, naive_ms > 0.0 ? naive_ms / r->ms : 0.0,
            r->ns_per_eval, r->prims_per_eval, r->frame_ms, r->threads, r->shadow_per_px,
            BENCH_SIMD, BENCH_SDF_BUILD);
}

/* the length of M in a row named M_cb_point or M_cb_batch, else 0 */
static size_t cb_prefix(const char *method)
{
    size_t l = strlen(method);
    if (l > 9 && (!strcmp(method + l - 9, "_cb_point") || !strcmp(method + l - 9, "_cb_batch"))) return l - 9;
    return 0;
}

/* prints a group's rows, and after the last M_cb_* row of each M the row M_cb: a copy of the
   faster of M_cb_point and M_cb_batch */
static void flush_group(FILE *csv, row_t *rows, int n)
{
    double naive_ms = 0.0;
    int i, j;
    for (i = 0; i < n; ++i)
        if (!strcmp(rows[i].method, "naive")) naive_ms = rows[i].ms;
    for (i = 0; i < n; ++i) {
        size_t l = cb_prefix(rows[i].method);
        int last = 1, best = i;
        row_print(csv, &rows[i], naive_ms);
        if (l == 0) continue;
        for (j = 0; j < n; ++j)
            if (j != i && cb_prefix(rows[j].method) == l && !strncmp(rows[j].method, rows[i].method, l)) {
                if (j > i) last = 0;
                if (rows[j].ms < rows[best].ms) best = j;
            }
        if (last) {
            row_t b = rows[best];
            snprintf(b.method, sizeof b.method, "%.*s_cb", (int)l, rows[i].method);
            row_print(csv, &b, naive_ms);
        }
    }
    fflush(csv);
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: bench_sdf [options]\n"
          "run time against error for every fovsdf method (bench/results/sdf.csv)\n"
          "  --full              every method, spp, gaze, fovea and refresh (hours)\n"
          "  --hd                1920x1080 (default 640x360)\n"
          "  --size W H          image size\n"
          "  --quick             1 spp only\n"
          "  --runs N            timing runs, median (default 5)\n"
          "  --threads N         render threads (default the number of cores)\n"
          "  --scenes a,b,...    scenes (default primitives,columns,temple,atrium,thin,fractals)\n"
          "  --no-shadows        shade without shadow rays (default: soft shadows)\n"
          "  --shadows           soft shadows (the default)\n"
          "  --out FILE          CSV (default bench/results/sdf.csv)\n"
          "  --append            add the rows to FILE (a second build's rows)\n"
          "  --plots-only        only redraw the plots of FILE\n"
          "  --fov-grid          classic, fipr and cone_fov at every fovea and refresh, 1 and 16 spp\n"
          "  -h, --help          this text\n", f);
}

static const char *row_method(const job_t *jb, char *buf, size_t n)
{
    if (jb->kind == K_NAIVE) return "naive";
    if (jb->kind == K_LIB) return fovsdf_method_name(jb->method);
    if (jb->kind == K_SHFOV) { snprintf(buf, n, "%s_shfov", fovsdf_method_name(jb->method)); return buf; }
    snprintf(buf, n, "%s_cb_%s", fovsdf_method_name(jb->method), jb->kind == K_CB_POINT ? "point" : "batch");
    return buf;
}

int main(int argc, char **argv)
{
    uint32_t W = 640, H = 360;
    int ncores = (int)sysconf(_SC_NPROCESSORS_ONLN);
    int plots_only = 0, fov_grid = 0, full = 0, quick = 0, runs = 5, nthreads = ncores, shadows = 1, append = 0;
    int a, njobs = 0, done = 0;
    const char *scenes = "primitives,columns,temple,atrium,thin,fractals", *outpath = "bench/results/sdf.csv";
    static job_t jobs[4096];
    const float foveas[5] = { 2.5f, 5.0f, 7.5f, 10.0f, 15.0f };
    const uint32_t refreshes[3] = { 1, 2, 4 };
    /* the library's methods driven by the scene's C function */
    const uint32_t cb_methods[3] = { FOVSDF_METHOD_CLASSIC, FOVSDF_METHOD_CONE, FOVSDF_METHOD_CONE_FOV };
    uint32_t fi, ri;
    FILE *csv;
    uint32_t id, m, s, g;
    const uint32_t spps[3] = { 1, 4, 16 };

    if (ncores < 1) ncores = 1;
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--full")) full = 1;
        else if (!strcmp(argv[a], "--hd")) { W = 1920; H = 1080; }
        else if (!strcmp(argv[a], "--size") && a + 2 < argc) { W = (uint32_t)atoi(argv[a + 1]); H = (uint32_t)atoi(argv[a + 2]); a += 2; }
        else if (!strcmp(argv[a], "--quick")) quick = 1;
        else if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--threads") && a + 1 < argc) nthreads = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--scenes") && a + 1 < argc) scenes = argv[++a];
        else if (!strcmp(argv[a], "--shadows")) shadows = 1;
        else if (!strcmp(argv[a], "--no-shadows")) shadows = 0;
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) outpath = argv[++a];
        else if (!strcmp(argv[a], "--append")) append = 1;
        else if (!strcmp(argv[a], "--plots-only")) plots_only = 1;
        else if (!strcmp(argv[a], "--fov-grid")) fov_grid = 1;
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (runs < 1) runs = 1;
    if (runs > 64) runs = 64;
    if (nthreads < 1) nthreads = 1;
    if (W < 1 || H < 1 || W > 8192 || H > 8192) { fprintf(stderr, "--size: 1 .. 8192\n"); return 2; }

    /* the grid: classic first in every (scene, spp, gaze) group, for the side-by-side ratio */
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        const char *nm = fovsdf_builtin_name(id), *p = strstr(scenes, nm);
        if (!p || (p != scenes && p[-1] != ',') || (p[strlen(nm)] != ',' && p[strlen(nm)] != 0)) continue;
        for (g = 0; g < (full || fov_grid ? 2u : 1u); ++g)
            for (s = 0; s < (quick ? 1u : 3u); ++s) {
                for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m)
                    for (fi = 0; fi < 5; ++fi)
                        for (ri = 0; ri < 3; ++ri) {
                            /* default grid: every method at 1 spp (foveated ones at 7.5 degrees,
                               refresh 1), classic, cone and ipr at 4 and 16 spp, cone_fov at 16 spp
                               beside classic; --full: everything, foveated ones over the fovea x
                               refresh grid */
                            int def = (spps[s] == 1 || m == FOVSDF_METHOD_CLASSIC || m == FOVSDF_METHOD_CONE ||
                                       m == FOVSDF_METHOD_IPR || (m == FOVSDF_METHOD_CONE_FOV && spps[s] == 16)) &&
                                      fi == 2 && ri == 0;
                            if (!foveated(m) && (fi != 2 || ri != 0)) continue;
                            if (fov_grid) /* classic and the foveated methods over fovea x refresh, 1 and 16 spp */
                                def = spps[s] != 4 && (foveated(m) || m == FOVSDF_METHOD_CLASSIC);
                            if (!((full && !fov_grid) || def) || njobs >= 4096) continue;
                            jobs[njobs].scene = id; jobs[njobs].method = m; jobs[njobs].spp = spps[s]; jobs[njobs].corner = g;
                            jobs[njobs].fovea = foveated(m) ? foveas[fi] : 0.0f;
                            jobs[njobs].refresh = foveated(m) ? refreshes[ri] : 1u;
                            jobs[njobs].kind = K_LIB;
                            ++njobs;
                        }
                /* at 1 spp: naive, then the callback rows (per-point, batch), foveated ones at
                   7.5 degrees, refresh 1 */
                if (spps[s] != 1 || fov_grid) continue;
                for (m = 0; m < 7 && njobs < 4096; ++m) {
                    job_t *jb = &jobs[njobs];
                    uint32_t cm = m == 0 ? 0u : cb_methods[(m - 1) / 2];
                    jb->kind = m == 0 ? K_NAIVE : ((m - 1) % 2 == 0 ? K_CB_POINT : K_CB_BATCH);
#ifndef FOVSDF_BATCH
                    if (jb->kind == K_CB_BATCH) continue; /* no batch callbacks in this fovsdf.h */
#endif
                    jb->scene = id; jb->method = cm; jb->spp = 1; jb->corner = g;
                    jb->fovea = foveated(cm) ? 7.5f : 0.0f;
                    jb->refresh = 1;
                    ++njobs;
                }
                /* then, with shadows, cone and cone_fov with cheaper shadow rays beyond 7.5
                   degrees (cone_fov's fovea): the rows cone_shfov and cone_fov_shfov */
                for (m = 0; m < 2 && shadows && njobs < 4096; ++m) {
                    job_t *jb = &jobs[njobs];
                    jb->kind = K_SHFOV;
                    jb->method = m == 0 ? FOVSDF_METHOD_CONE : FOVSDF_METHOD_CONE_FOV;
                    jb->scene = id; jb->spp = 1; jb->corner = g;
                    jb->fovea = foveated(jb->method) ? 7.5f : 0.0f;
                    jb->refresh = 1;
                    ++njobs;
                }
            }
    }
    if (plots_only) goto plots;
    {
        FILE *prev = append ? fopen(outpath, "r") : NULL;
        int has_header = prev && fgetc(prev) != EOF;
        if (prev) fclose(prev);
        csv = fopen(outpath, append ? "a" : "w");
        if (!csv) { fprintf(stderr, "cannot write %s (run from the repository root)\n", outpath); return 1; }
        if (!has_header)
            fprintf(csv, "scene,method,spp,fovea_deg,refresh,gaze,evals_per_px,time_ms,speedup_vs_classic,psnr,ssim,flip,hit_mismatch_pct,"
                         "evals_lowres_per_px,evals_primary_per_px,evals_shading_per_px,evals_total_per_px,mean_rel_dt,shading,width,height,runs,"
                         "psnr_e0_5,psnr_e5_10,psnr_e10_20,psnr_e20_up,flip_e0_5,flip_e5_10,flip_e10_20,flip_e20_up,traced_pct,"
                         "psnr_vs_classic,flip_vs_classic,hit_mismatch_vs_classic_pct,"
                         "speedup_vs_naive,ns_per_eval,prims_per_eval,frame_ms,threads,shadow_evals_per_px,simd,build\n");
    }
    fprintf(stderr, "bench-sdf (%s, %s): %ux%u, %d configurations, median of %d runs, %d threads, %s\n", BENCH_SDF_BUILD,
            BENCH_SIMD, W, H, njobs, runs, nthreads, shadows ? "soft shadows" : "no shadow rays");

    {
        size_t npx = (size_t)W * H, sz = 0;
        img_t gt, im;
        float *ecc = (float *)malloc(npx * sizeof(float)), *flipmap = (float *)malloc(npx * sizeof(float));
        uint8_t *mask = (uint8_t *)malloc(npx), *cl_hit = (uint8_t *)malloc(npx);
        float *cl_disp = (float *)malloc(npx * 3 * sizeof(float));
        void *mem = NULL;
        fovsdf_builtin bi;
        fovsdf_scene cb_scene;
        naive_fn fn = NULL;
        uint32_t cur_scene = 0xffffffffu, cur_spp = 0, cur_g = 2;
        double classic_ms = 0.0;
        static row_t rows[256];
        int nrows = 0, j;
        img_alloc(&gt, npx);
        img_alloc(&im, npx);
        for (j = 0; j < njobs; ++j) {
            const job_t *jb = &jobs[j];
            fovsdf_config cfg;
            fovsdf_ctx ctx;
            fovsdf_output out;
            fovsdf_stats st, st1;
            fov_gaze gaze;
            render_req rq;
            double times[64], ms, t1, psnr = 0.0, ssim = 0.0, flip = 0.0, rel = 0.0, bp[4], bf[4];
            const double edges[5] = { 0.0, 5.0, 10.0, 20.0, 1e9 };
            long mismatch = 0, nrel = 0, traced = 0, cnt, mis_cl = 0;
            double psnr_cl = 0.0, flip_cl = 0.0;
            size_t i;
            int r;
            char what[96], mbuf[32];
            const char *mname = row_method(jb, mbuf, sizeof mbuf);
            row_t *row;
            if (jb->scene != cur_scene || jb->spp != cur_spp || jb->corner != cur_g) { /* a new group */
                flush_group(csv, rows, nrows);
                nrows = 0;
            }
            if (jb->scene != cur_scene) {
                free(mem);
                fovsdf_builtin_size(jb->scene, &sz);
                mem = malloc(sz);
                if (fovsdf_builtin_init(jb->scene, &bi, mem, sz) != FOV_OK) { fprintf(stderr, "scene init failed\n"); return 1; }
                bi.camera.width = W;
                bi.camera.height = H;
                cur_scene = jb->scene;
                cur_spp = 0;
                fn = naive_scene(jb->scene);
            }
            gaze.x = jb->corner ? 0.1f * (float)W : 0.5f * (float)W;
            gaze.y = jb->corner ? 0.1f * (float)H : 0.5f * (float)H;
            if (jb->spp != cur_spp || jb->corner != cur_g) { /* ground truth of this group */
                snprintf(what, sizeof what, "%s ground truth %u spp", bi.name, jb->spp);
                progress(done, njobs, what);
                cfg = fovsdf_config_ground_truth();
                cfg.spp = jb->spp;
                cfg.shading = shadows ? FOVSDF_SHADE_FULL : FOVSDF_SHADE_NO_SHADOWS;
                fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
                fovsdf_output_init(&out);
                out.rgb = gt.rgb; out.depth = gt.depth; out.hit = gt.hit;
                fovrun_render(&ctx, &out, nthreads, &st);
                to_display(&gt, npx);
                for (i = 0; i < npx; ++i) ecc[i] = fovsdf_ecc_deg(&ctx.ecc, (float)(i % W) + 0.5f, (float)(i / W) + 0.5f);
                cur_spp = jb->spp;
                cur_g = jb->corner;
            }
            snprintf(what, sizeof what, "%s %s %u spp%s %g/%u", bi.name, mname, jb->spp,
                     jb->corner ? " corner" : "", (double)jb->fovea, jb->refresh);
            progress(done, njobs, what);
            cfg = fovsdf_config_default();
            cfg.method = jb->method;
            cfg.spp = jb->spp;
            cfg.shading = shadows ? FOVSDF_SHADE_FULL : FOVSDF_SHADE_NO_SHADOWS;
            if (foveated(jb->method)) { cfg.acuity.fovea_deg = jb->fovea; cfg.refresh = jb->refresh; }
            if (jb->kind == K_SHFOV) cfg.shadow_fov_deg = 7.5f; /* the defaults otherwise */
            fovsdf_output_init(&out);
            out.rgb = im.rgb; out.depth = im.depth; out.hit = im.hit; out.mask = mask;
            memset(&rq, 0, sizeof rq);
            rq.kind = jb->kind; rq.cfg = cfg; rq.scene = &bi.scene; rq.cam = &bi.camera; rq.gaze = gaze; rq.out = out;
            if (jb->kind == K_CB_POINT || jb->kind == K_CB_BATCH) { /* the C function as the user's callback */
                cb_scene = bi.scene;
                cb_scene.dist = NULL;
                cb_scene.dist_ex = jb->kind == K_CB_POINT ? cb_point : NULL;
                cb_scene.user = (void *)&fn;
#ifdef FOVSDF_BATCH
                cb_scene.dist_batch = jb->kind == K_CB_BATCH ? cb_batch : NULL;
#endif
                rq.scene = &cb_scene;
            }
            if (jb->kind == K_NAIVE) { /* the same camera, thresholds and lights, from the library's defaults */
                fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0);
                rq.nv.fn = fn;
                rq.nv.width = W; rq.nv.height = H;
                rq.nv.max_steps = ctx.cfg.max_steps; rq.nv.shadow_steps = ctx.cfg.shadow_steps;
                rq.nv.shadows = (uint32_t)shadows;
                for (i = 0; i < 3; ++i) {
                    rq.nv.origin[i] = ctx.origin[i]; rq.nv.right[i] = ctx.right[i]; rq.nv.up[i] = ctx.up[i];
                    rq.nv.fwd[i] = ctx.fwd[i]; rq.nv.ambient[i] = bi.scene.ambient[i];
                    rq.nv.sky_zenith[i] = bi.scene.sky_zenith[i]; rq.nv.sky_horizon[i] = bi.scene.sky_horizon[i];
                }
                rq.nv.tan_half_y = ctx.tan_half_y; rq.nv.aspect = ctx.aspect; rq.nv.pixel_angle = ctx.pixel_angle;
                rq.nv.eps = ctx.cfg.eps; rq.nv.eps_px = ctx.cfg.eps_px; rq.nv.t_max = ctx.t_max;
                rq.nv.shadow_t0 = ctx.cfg.shadow_t0; rq.nv.shadow_eps = ctx.cfg.shadow_eps;
                rq.nv.num_lights = bi.scene.num_lights;
                memcpy(rq.nv.lights, bi.scene.lights, sizeof rq.nv.lights);
                rq.nv.rgb = im.rgb; rq.nv.depth = im.depth; rq.nv.hit = im.hit;
                memset(mask, 1, npx);
            }
            for (r = 0; r < runs; ++r) times[r] = render_once(&rq, nthreads, &st);
            ms = median_of(times, runs);
            row = nrows < 256 ? &rows[nrows++] : &rows[255];
            memset(row, 0, sizeof *row);
            if (nthreads == ncores) {
                row->frame_ms = ms;
            } else { /* the same frame on every core */
                for (r = 0; r < runs; ++r) times[r] = render_once(&rq, ncores, &st1);
                row->frame_ms = median_of(times, runs);
            }
            t1 = nthreads == 1 ? ms : render_once(&rq, 1, &st1); /* one thread, one run */
            for (i = 0; i < npx; ++i) traced += mask[i] == 1;
            if (jb->kind == K_LIB && jb->method == FOVSDF_METHOD_CLASSIC) classic_ms = ms;
            to_display(&im, npx);
            fovm_psnr(gt.disp, im.disp, (int)W, (int)H, 3, &psnr);
            fovm_ssim(gt.disp, im.disp, (int)W, (int)H, 3, &ssim, NULL);
            fovm_flip(gt.disp, im.disp, (int)W, (int)H, 3, FOVM_FLIP_DEFAULT_PPD, &flip, flipmap);
            for (r = 0; r < 4; ++r) { /* per eccentricity band (degrees from the gaze) */
                fovm_sel sel = fovm_sel_band(ecc, edges[r], edges[r + 1]);
                if (fovm_psnr_sel(gt.disp, im.disp, (int)W, (int)H, 3, &sel, &bp[r], &cnt) != 0 || cnt == 0) bp[r] = NAN;
                if (fovm_map_mean_sel(flipmap, (int)W, (int)H, &sel, &bf[r], &cnt) != 0 || cnt == 0) bf[r] = NAN;
            }
            if (jb->kind == K_LIB && jb->method == FOVSDF_METHOD_CLASSIC) { /* the same-threshold reference of this group */
                memcpy(cl_disp, im.disp, npx * 3 * sizeof(float));
                memcpy(cl_hit, im.hit, npx);
            }
            fovm_psnr(cl_disp, im.disp, (int)W, (int)H, 3, &psnr_cl);
            fovm_flip(cl_disp, im.disp, (int)W, (int)H, 3, FOVM_FLIP_DEFAULT_PPD, &flip_cl, NULL);
            for (i = 0; i < npx; ++i) mis_cl += cl_hit[i] != im.hit[i];
            for (i = 0; i < npx; ++i) {
                if (gt.hit[i] != im.hit[i]) ++mismatch;
                else if (gt.hit[i]) { rel += fabs((double)im.depth[i] - (double)gt.depth[i]) / (double)gt.depth[i]; ++nrel; }
            }
            {
                double fr = (double)rq.refresh * (double)npx; /* per frame and pixel */
                snprintf(row->scene, sizeof row->scene, "%s", bi.name);
                snprintf(row->method, sizeof row->method, "%s", mname);
                snprintf(row->gaze, sizeof row->gaze, "%s", jb->corner ? "corner" : "center");
                snprintf(row->shading, sizeof row->shading, "%s", shadows ? "full" : "no_shadows");
                row->spp = jb->spp; row->fovea = (double)jb->fovea; row->refresh = 1.0 / (double)jb->refresh;
                row->evals_per_px = (double)(st.evals_lowres + st.evals_primary) / fr;
                row->ms = ms;
                row->speedup_classic = classic_ms > 0.0 ? classic_ms / ms : 0.0;
                row->psnr = psnr; row->ssim = ssim; row->flip = flip;
                row->mismatch = 100.0 * (double)mismatch / (double)npx;
                row->ev_low = (double)st.evals_lowres / fr; row->ev_prim = (double)st.evals_primary / fr;
                row->ev_shade = (double)(st.evals_normal + st.evals_shadow) / fr;
                row->ev_total = (double)st.evals / fr;
                row->rel = nrel ? rel / (double)nrel : 0.0;
                row->width = W; row->height = H; row->runs = runs;
                for (r = 0; r < 4; ++r) { row->bp[r] = bp[r]; row->bf[r] = bf[r]; }
                row->traced = 100.0 * (double)traced / (double)npx;
                row->psnr_cl = psnr_cl; row->flip_cl = flip_cl; row->mis_cl = 100.0 * (double)mis_cl / (double)npx;
                row->ns_per_eval = st.evals ? t1 * 1e6 / ((double)st.evals / (double)rq.refresh) : 0.0;
                row->prims_per_eval = st.evals ? (double)st.prims / (double)st.evals : 0.0;
                row->threads = ncores;
                row->shadow_per_px = (double)st.evals_shadow / fr;
            }
            ++done;
        }
        flush_group(csv, rows, nrows);
        progress(done, njobs, "done");
        free(mem);
        free(ecc); free(flipmap); free(mask); free(cl_hit); free(cl_disp);
        img_free(&gt);
        img_free(&im);
    }
    fclose(csv);
    fprintf(stderr, "wrote %s\n", outpath);

plots: /* speed-up against PSNR per scene */
    if (system("command -v gnuplot > /dev/null 2>&1") == 0) {
        FILE *gp = popen("gnuplot", "w");
        const char *slash = strrchr(outpath, '/');
        const char *dot = strrchr(outpath, '.');
        int stem = dot && (!slash || dot > slash) ? (int)(dot - outpath) : (int)strlen(outpath);
        if (gp) {
            for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
                const char *nm = fovsdf_builtin_name(id);
                if (!strstr(scenes, nm)) continue;
                /* next to the CSV, named after it: bench/results/sdf.csv -> sdf_<scene>.png */
                fprintf(gp, "set terminal pngcairo size 800,500 noenhanced; set output '%.*s_%s.png'\n", stem, outpath, nm);
                fprintf(gp, "set datafile separator ','; set key off; set grid; set logscale x 2\n");
                fprintf(gp, "set title '%s: speed-up against classic vs error (%ux%u)'\n", nm, W, H);
                fprintf(gp, "set xlabel 'time ratio classic / method (same run)'; set ylabel 'PSNR against ground truth (dB)'\n");
                fprintf(gp, "plot '%s' every ::1 using (strcol(1) eq '%s' && $9 > 0 ? $9 : 1/0):10:(sprintf('%%s %%d', strcol(2), $3)) with labels point pt 7 offset 0.3,0.4 left font ',7'\n",
                        outpath, nm);
            }
            pclose(gp);
            fprintf(stderr, "plots: %.*s_<scene>.png\n", stem, outpath);
        }
    } else {
        fprintf(stderr, "gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    return 0;
}
