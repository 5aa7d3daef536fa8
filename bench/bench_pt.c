/* bench_pt.c - fovpt benchmark: every method on the code-written scenes (examples/pt_scenes.h),
   gaze at the centre and near the top-left corner; writes bench/results/pt.csv.

   make bench-pt            default run (5 scenes, 320x240, ground truth 512 spp path / 64
                            Whitted; every method and budget; about 10-15 minutes here)
   make bench-pt FULL=1     the same rows at 640x480, ground truth 1024 spp
   ./build/bench_pt [--quick] [--full] [--throughput] [--w W --h H] [--gt-spp N] [--out FILE]
                    [--threads N] [--temporal] [--lp] [--denoise] [--robust] [--mirror-nee]
                    [--ref-floor] [--scene N] [--gt-fovea-spp N] [--dn-no-sure] [--seeds N]
                    (--throughput: only the fovpt / Embree ray-rate rows; --temporal: only
                    pt_temporal.csv, written beside FILE; --fovea-spp: prints how the Cornell
                    box's fovea error falls with spp, see README; --denoise, --robust,
                    --mirror-nee: only the _dn / _rb / _mn rows, see below; --ref-floor:
                    only pt_ref_floor.csv, the ground truth's own noise)

   Columns (the first eleven are the issue's, in order):
     scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,
     mode,rays,camera_rays,speedup,budget_time_ms,spp_fovea
   - method: uniform4 / uniform1 (the non-foveated renderer at 4 and 1 spp; the regular
     system of Axblad 2020, Sec. 3.1.3, uses 4), layers (Axblad 2020, 6/10/20 deg as radii),
     layers_diam (as diameters), zones (Polychronakis 2025, ch. 4), whitted1 (UNIFORM
     Whitted, 1 spp), selective (Kim et al. 2021), jin (Jin et al. 2009); the papers are
     listed in full at the end of this comment. lp_cfov, lp_cfov_taa, lp_cfov_fovea, lp_acuity,
     lp_acuity_taa, lp_acuity_fovea: path tracing at fovlp.h's log-polar positions (fovpt_shade_points; Koskela
     et al. 2019 on the GPU), see "path tracing in log-polar space" below; --lp runs only them
     and the rows they sit beside. <method>_dn: with the denoiser (below); <method>_rb: with
     cfg.robust = 4 (fovpt.h ROBUST PIXEL ESTIMATE) for uniform4, layers, layers_diam at their
     default budgets and layers, layers_fovea, layers_diam, layers_diam_fovea at
     eqtime_uniform4 (each its own pilot; uniform4's time is the plain one), with
     pt_robust.csv beside the CSV (scene, method, gaze, budget, psnr_f1..f4, psnr_all, flip,
     flip_f1, time_ms, spp_fovea: every _rb row with its plain twin of the same run).
     <method>_mn: the same rows with cfg.mirror_nee = 1 (fovpt.h NEXT-EVENT ESTIMATION THROUGH
     MIRRORS) instead, pt_mirror_nee.csv beside (--mirror-nee; its ground truth is rendered
     with cfg.mirror_nee too: the same mean, less noise; the plain twins and uniform4's time
     are measured against it).
   - budget: which budget the row was given.
       default          the method's own settings (the rows above).
       eqrays_<m>       method uniform_eq: UNIFORM at the spp whose camera rays match method
                        <m>'s (equal ray budget).
       eqtime_uniform4  methods layers, layers_diam, zones (all their samples scaled by one
                        factor) and layers_fovea, layers_diam_fovea (only the innermost
                        layer's samples raised): the time of uniform4 in the same run
                        (equal time; calibrated from the default row as a timed pilot,
                        corrected along the secant while more than 8 % off, at most
                        EQT_RUNS = 4 timed runs; a row still outside +-8 % is written
                        all the same with a WARNING line on stdout; the measured time is
                        in time_ms, the target in budget_time_ms).
       eqtime_<m>       method uniform_eqt: UNIFORM at the spp whose time matches method
                        <m>'s (spp = time of <m> / time of uniform1 or whitted1, rounded).
   - mode: path (path tracing, max depth 8, NEE) for uniform/layers/zones; whitted (depth 3) for
     selective/jin/whitted1 (Kim et al. 2021 is a Whitted ray tracer); each against the ground
     truth of its own mode: UNIFORM at --gt-spp samples (path) or 64 (Whitted).
   - rays_per_s: all rays (camera, bounce, shadow) / time, ONE thread (per core);
     time_ms: CPU time of the one thread that renders the method (trace + refine + resolve;
     thread CPU time, so other jobs on the shared cores do not stretch it).
   - psnr_f1..f4: PSNR (peak 1, sRGB-encoded clamped values) over the annuli of eccentricity
     [0, 3.3), [3.3, 5.5), [5.5, 12.1), [12.1, 30) degrees (the fovea, parafovea, perifovea
     and near periphery of Kim et al. 2021, Sec. 4.1), psnr_all over the image; eccentricity
     from the camera's field of view (fovpt_ecc_*). An empty annulus gives nan.
   - speedup: time of uniform4 / time of the row (same scene and gaze).
   - budget_time_ms: the time the row was matched to (eq rows; nan for default rows).
   - spp_fovea: samples per target pixel in the fovea (UNIFORM, ZONES: spp; LAYERS: the
     innermost layer's); 0 where not fixed (SELECTIVE, JIN: 1 + adaptive extra samples).
   Embree rows (built with -DPT_HAVE_EMBREE -lembree3, which the Makefile adds when
   <embree3/rtcore.h> exists; Debian's libembree-dev): on the triangles of mesh100k alone,
   the same ray set (every pixel-centre camera ray, plus one cosine-distributed bounce ray
   from each camera hit, from a fixed-seed generator) is traced for the closest hit by
   fovpt_intersect and by Embree 3 (rtcIntersect1, a device with threads=1), one thread
   each, best of 5 runs interleaved (fovpt, Embree, fovpt, ...; thread CPU time); rows fovpt_bvh and embree, budget rays_<N>, mode
   closest_hit, speedup = Embree's time / this row's time; the hit agreement (same hit or
   miss, |dt| <= 1e-4 t) is printed.

   Papers: Axblad 2020 = T. Axblad, "Impact of Foveated Rendering on Path Tracing Frame Rate
   in Head-Mounted VR Displays", master's thesis, KTH, 2020. Kim et al. 2021 = Y. Kim, Y. Ko,
   I. Ihm, "Selective Foveated Ray Tracing for Head-Mounted Displays", IEEE ISMAR 2021.
   Polychronakis 2025 = A. Polychronakis, "Implicit and Foveated Techniques for Real-Time
   Computer Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025.
   Jin et al. 2009 = B. Jin, I. Ihm et al., "Selective and Adaptive Supersampling for
   Real-Time Ray Tracing", High Performance Graphics 2009. */
#define _POSIX_C_SOURCE 200809L
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#include "examples/pt_scenes.h"
#include "examples/lp_pt_shade.h"
#define FOVM_IMPLEMENTATION
#include "examples/fovmetrics.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef PT_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
/* CPU time of the calling thread: the time of a one-thread run on a core of its own, not
   stretched when other jobs share the cores (this machine's two cores are shared) */
static double cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

typedef struct job {
    fovpt_ctx *ctx;
    uint32_t y0, y1, frame;
    fovpt_stats st;
} job;
static void *worker(void *a)
{
    job *j = (job *)a;
    fovpt_trace_rows(j->ctx, j->frame, j->y0, j->y1, &j->st);
    return NULL;
}

/* renders with cfg; threads > 1 only for ground truths (UNIFORM: no refine phase) */
static int g_dn;
static uint32_t g_rb;            /* --robust rows: cfg.robust of the timed renders (0: off) */
static uint32_t g_mn;            /* --mirror-nee rows: cfg.mirror_nee of every render (0: off) */
static double render_dn(pt_scene *S, const fovpt_config *cfg, fov_gaze g, float *rgb, fovpt_stats *st);
static double render(pt_scene *S, const fovpt_config *cfg, fov_gaze g, float *rgb, fovpt_stats *st, int threads)
{
    size_t n = 0;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_config cr;
    double t0, t;
    if (g_rb && threads <= 1) { cr = *cfg; cr.robust = g_rb; cfg = &cr; }
    if (g_mn) { cr = *cfg; cr.mirror_nee = 1u; cfg = &cr; }
    if (g_dn && threads <= 1) return render_dn(S, cfg, g, rgb, st); /* --denoise rows */
    memset(st, 0, sizeof *st);
    if (fovpt_memory_size(cfg, &S->cam, &n) != FOV_OK) return -1.0;
    mem = malloc(n + 16u);
    if (fovpt_init(&ctx, cfg, &S->scene, &S->cam, g, mem, n) != FOV_OK) { free(mem); return -1.0; }
    fovpt_output_init(&out);
    out.rgb = rgb;
    t0 = threads <= 1 ? cpu_ms() : now_ms();
    if (threads <= 1) {
        fovpt_render(&ctx, 0, &out, st);
        t = cpu_ms() - t0;
    } else {
        pthread_t th[16];
        job jobs[16];
        int i;
        uint32_t H = S->cam.height;
        for (i = 0; i < threads; ++i) {
            memset(&jobs[i], 0, sizeof jobs[i]);
            jobs[i].ctx = &ctx;
            jobs[i].y0 = H * (uint32_t)i / (uint32_t)threads;
            jobs[i].y1 = H * (uint32_t)(i + 1) / (uint32_t)threads;
            pthread_create(&th[i], NULL, worker, &jobs[i]);
        }
        for (i = 0; i < threads; ++i) {
            pthread_join(th[i], NULL);
            st->rays += jobs[i].st.rays;
            st->camera_rays += jobs[i].st.camera_rays;
        }
        fovpt_refine_rows(&ctx, 0, 0, H, st);
        fovpt_resolve_rows(&ctx, 0, H, &out);
        t = now_ms() - t0;
    }
    free(mem);
    return t;
}

static double srgb(double v)
{
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

/* PSNR over eccentricity annuli [lo, hi) */
static void psnr_fields(const float *a, const float *ref, const float *ecc, size_t np, double out[5])
{
    static const double lo[5] = { 0.0, 3.3, 5.5, 12.1, -1.0 }, hi[5] = { 3.3, 5.5, 12.1, 30.0, 1e9 };
    int f;
    for (f = 0; f < 5; ++f) {
        double se = 0.0;
        size_t i, cnt = 0;
        int k;
        for (i = 0; i < np; ++i) {
            if (ecc[i] < lo[f] || ecc[i] >= hi[f]) continue;
            for (k = 0; k < 3; ++k) {
                double d = srgb(a[3 * i + k]) - srgb(ref[3 * i + k]);
                se += d * d;
            }
            cnt += 3;
        }
        out[f] = cnt ? (se > 0.0 ? 10.0 * log10((double)cnt / se) : 99.0) : NAN;
    }
}

/* ---- ray throughput on triangles: fovpt's BVH against Embree and tinybvh (one thread each) --
   Per scene, one triangle soup (tp_soup) traced by every method: mesh100k's terrain alone (as
   before); cubes441, cornell and interior with their quads as 2 triangles, boxes as 12,
   spheres as 16 x 32 latitude-longitude triangles and cubes441's floor plane as a 200 x 200
   quad. Rays: every pixel-centre camera ray (mode camera) and one cosine-distributed bounce ray
   from each camera hit, offset 1e-3 along the normal, from a fixed-seed generator (mode
   bounce); closest_hit: both sets in one loop (the row kept from before). Closest hit, tnear 0,
   tfar 1e30; best of 5 runs interleaved (fovpt, Embree, tinybvh, fovpt, ...; thread CPU time).
   speedup = Embree's time / this row's time. pt_bvh.csv beside the CSV: build time (best of 3,
   thread CPU time) and bytes per triangle of each acceleration structure (fovpt: the whole
   scene memory of fovpt_scene_size, and in traversal_bytes_per_tri what the traversal reads:
   nodes, leaf blocks (triangles, slot, id, material); Embree: the device's allocations,
   vertex and index buffers included; tinybvh: its traversal blocks, nodes and triangles). */
static uint64_t g_rng = 0x243f6a8885a308d3ull;
static float rnd01(void)
{
    g_rng ^= g_rng << 13; g_rng ^= g_rng >> 7; g_rng ^= g_rng << 17;
    return (float)(g_rng >> 40) * (1.0f / 16777216.0f);
}
#ifdef PT_HAVE_TINYBVH
const char *tbvh_layout(void);
void *tbvh_build(const float *tri, uint32_t ntri, size_t *bytes);
void tbvh_trace(void *h, const float *org, const float *dir, size_t n, float *t_out);
void tbvh_free(void *h);
#endif

typedef struct tp_soup { float *v; uint32_t n, cap; } tp_soup;
static void tp_tri(tp_soup *s, const float *a, const float *b, const float *c)
{
    if (s->n == s->cap) { s->cap = s->cap ? 2u * s->cap : 1024u; s->v = (float *)realloc(s->v, 36u * s->cap); }
    memcpy(s->v + 9u * s->n, a, 12); memcpy(s->v + 9u * s->n + 3, b, 12); memcpy(s->v + 9u * s->n + 6, c, 12);
    s->n++;
}
static void tp_quad(tp_soup *s, const float *p, const float *u, const float *v)
{
    float a[3], b[3], c[3], d[3];
    int k;
    for (k = 0; k < 3; ++k) { a[k] = p[k]; b[k] = p[k] + u[k]; c[k] = p[k] + u[k] + v[k]; d[k] = p[k] + v[k]; }
    tp_tri(s, a, b, c); tp_tri(s, a, c, d);
}
static void tp_soup_make(const pt_scene *S, int sc, tp_soup *out)
{
    uint32_t i, k;
    memset(out, 0, sizeof *out);
    if (sc == PT_SCENE_MESH) { /* the terrain alone */
        for (i = 0; i < S->mesh.num_triangles; ++i)
            tp_tri(out, S->mesh.positions + 3u * S->mesh.indices[3u * i], S->mesh.positions + 3u * S->mesh.indices[3u * i + 1u],
                   S->mesh.positions + 3u * S->mesh.indices[3u * i + 2u]);
        return;
    }
    for (i = 0; i < S->num_shapes; ++i) {
        const fovpt_shape *sh = &S->shapes[i];
        if (sh->type == FOVPT_SHAPE_QUAD) {
            tp_quad(out, sh->p, sh->u, sh->v);
        } else if (sh->type == FOVPT_SHAPE_PLANE) { /* the floor y = p.y as a 200 x 200 quad */
            float p[3], u[3] = { 0.0f, 0.0f, 200.0f }, v[3] = { 200.0f, 0.0f, 0.0f };
            p[0] = -100.0f; p[1] = sh->p[1]; p[2] = -100.0f;
            tp_quad(out, p, u, v);
        } else if (sh->type == FOVPT_SHAPE_BOX) {
            const float *lo = sh->p, *hi = sh->u;
            float e[3], p[3], u[3], v[3];
            for (k = 0; k < 3; ++k) e[k] = hi[k] - lo[k];
            for (k = 0; k < 3; ++k) { /* two faces per axis */
                uint32_t k1 = (k + 1u) % 3u, k2 = (k + 2u) % 3u;
                memset(u, 0, sizeof u); memset(v, 0, sizeof v);
                u[k1] = e[k1]; v[k2] = e[k2];
                memcpy(p, lo, 12); tp_quad(out, p, v, u);
                memcpy(p, lo, 12); p[k] = hi[k]; tp_quad(out, p, u, v);
            }
        } else if (sh->type == FOVPT_SHAPE_SPHERE) {
            const uint32_t nt = 16u, np = 32u;
            uint32_t a, b;
            for (a = 0; a < nt; ++a)
                for (b = 0; b < np; ++b) {
                    float q[4][3];
                    uint32_t c;
                    for (c = 0; c < 4; ++c) {
                        float th = 3.14159265f * (float)(a + (c >> 1)) / (float)nt, ph = 6.2831853f * (float)(b + ((c ^ (c >> 1)) & 1u)) / (float)np;
                        q[c][0] = sh->p[0] + sh->r * sinf(th) * cosf(ph);
                        q[c][1] = sh->p[1] + sh->r * cosf(th);
                        q[c][2] = sh->p[2] + sh->r * sinf(th) * sinf(ph);
                    }
                    if (a > 0) tp_tri(out, q[0], q[1], q[2]);
                    if (a + 1u < nt) tp_tri(out, q[0], q[2], q[3]);
                }
        }
    }
}

/* camera rays (n_cam) then bounce rays, from fovpt hits on the soup's scene */
static size_t tp_rays(const fovpt_scene *tri, const fovpt_camera *cam, float *org, float *dir, size_t *n_cam)
{
    size_t nr = 0, i, nc;
    uint32_t x, y;
    g_rng = 0x243f6a8885a308d3ull;
    for (y = 0; y < cam->height; ++y)
        for (x = 0; x < cam->width; ++x) {
            fovpt_camera_ray(cam, (float)x + 0.5f, (float)y + 0.5f, org + 3 * nr, dir + 3 * nr);
            nr++;
        }
    nc = nr;
    for (i = 0; i < nc; ++i) { /* one bounce ray per camera hit */
        fovpt_hit h;
        if (fovpt_intersect(tri, org + 3 * i, dir + 3 * i, 0.0f, 1e30f, &h)) {
            float n[3], t1[3], b1[3], u1 = rnd01(), u2 = rnd01(), r = sqrtf(u1), ph = 6.2831853f * u2, lx, ly, lz;
            float sg = (h.n[0] * dir[3 * i] + h.n[1] * dir[3 * i + 1] + h.n[2] * dir[3 * i + 2]) > 0.0f ? -1.0f : 1.0f;
            int k;
            for (k = 0; k < 3; ++k) n[k] = sg * h.n[k];
            if (fabsf(n[0]) > 0.5f) { t1[0] = n[1]; t1[1] = -n[0]; t1[2] = 0.0f; } else { t1[0] = 0.0f; t1[1] = n[2]; t1[2] = -n[1]; }
            { float l = sqrtf(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]); t1[0] /= l; t1[1] /= l; t1[2] /= l; }
            b1[0] = n[1] * t1[2] - n[2] * t1[1]; b1[1] = n[2] * t1[0] - n[0] * t1[2]; b1[2] = n[0] * t1[1] - n[1] * t1[0];
            lx = r * cosf(ph); ly = r * sinf(ph); lz = sqrtf(1.0f - u1);
            for (k = 0; k < 3; ++k) {
                org[3 * nr + k] = h.p[k] + 1e-3f * n[k];
                dir[3 * nr + k] = lx * t1[k] + ly * b1[k] + lz * n[k];
            }
            nr++;
        }
    }
    *n_cam = nc;
    return nr;
}

#ifdef PT_HAVE_EMBREE
static ptrdiff_t g_em_bytes;
static bool em_monitor(void *user, ssize_t bytes, bool post)
{
    (void)user; (void)post;
    g_em_bytes += bytes;
    return true;
}
static void em_trace(RTCScene sc, const float *org, const float *dir, size_t n, float *t_out)
{
    struct RTCIntersectContext ictx;
    size_t i;
    rtcInitIntersectContext(&ictx);
    for (i = 0; i < n; ++i) {
        struct RTCRayHit rh;
        rh.ray.org_x = org[3 * i]; rh.ray.org_y = org[3 * i + 1]; rh.ray.org_z = org[3 * i + 2];
        rh.ray.dir_x = dir[3 * i]; rh.ray.dir_y = dir[3 * i + 1]; rh.ray.dir_z = dir[3 * i + 2];
        rh.ray.tnear = 0.0f; rh.ray.tfar = 1e30f; rh.ray.time = 0.0f; rh.ray.mask = 0xFFFFFFFFu; rh.ray.id = 0; rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(sc, &ictx, &rh);
        t_out[i] = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : -1.0f;
    }
}
#endif
static void pt_trace(const fovpt_scene *s, const float *org, const float *dir, size_t n, float *t_out)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        fovpt_hit h;
        t_out[i] = fovpt_intersect(s, org + 3 * i, dir + 3 * i, 0.0f, 1e30f, &h) ? h.t : -1.0f;
    }
}
static size_t tp_agree(const float *a, const float *b, size_t n)
{
    size_t i, ag = 0;
    for (i = 0; i < n; ++i)
        if ((a[i] < 0.0f && b[i] < 0.0f) || (a[i] >= 0.0f && b[i] >= 0.0f && fabsf(a[i] - b[i]) <= 1e-4f * a[i])) ag++;
    return ag;
}

enum { TP_PT, TP_EM, TP_TB, TP_NM };
static void tp_scene(FILE *csv, FILE *bcsv, int sc, uint32_t W, uint32_t H)
{
    static const char *const mname[TP_NM] = { "fovpt_bvh", "embree", "tinybvh" };
    static const char *const modes[3] = { "camera", "bounce", "closest_hit" };
    pt_scene S;
    tp_soup soup;
    fovpt_scene tri;
    fovpt_scene_desc d;
    fovpt_mesh mesh;
    size_t bytes = 0, nr, nc, cap, m_off[3], m_n[3], agree[TP_NM];
    float *org, *dir, *t_m[TP_NM];
    void *mem = NULL;
    double best[TP_NM][3], build_ms[TP_NM], bpt[TP_NM];
    int have[TP_NM] = { 1, 0, 0 }, rep, m, md;
    const char *nm = pt_scene_names[sc];
#ifdef PT_HAVE_EMBREE
    RTCDevice dev = NULL;
    RTCScene esc = NULL;
#endif
#ifdef PT_HAVE_TINYBVH
    void *tb = NULL;
#endif
    if (pt_scene_make(&S, sc) != 0) return;
    S.cam.width = W; S.cam.height = H;
    tp_soup_make(&S, sc, &soup);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = soup.v; mesh.num_vertices = 3u * soup.n; mesh.num_triangles = soup.n; mesh.material = 0;
    fovpt_scene_desc_init(&d);
    d.meshes = &mesh; d.num_meshes = 1; d.materials = S.mats; d.num_materials = S.num_mats;
    d.skip_degenerate = 1;
    if (fovpt_scene_size(&d, &bytes) != FOV_OK) return;
    mem = malloc(bytes + 16u);
    build_ms[TP_PT] = 1e30;
    for (rep = 0; rep < 3; ++rep) {
        double t0 = cpu_ms();
        if (fovpt_scene_build(&tri, &d, mem, bytes) != FOV_OK) { fprintf(stderr, "%s: build failed\n", nm); return; }
        t0 = cpu_ms() - t0;
        if (t0 < build_ms[TP_PT]) build_ms[TP_PT] = t0;
    }
    bpt[TP_PT] = (double)bytes / (double)soup.n;
    cap = 2u * (size_t)W * H;
    org = (float *)malloc(cap * 12u); dir = (float *)malloc(cap * 12u);
    for (m = 0; m < TP_NM; ++m) t_m[m] = (float *)malloc(cap * 4u);
    nr = tp_rays(&tri, &S.cam, org, dir, &nc);
    m_off[0] = 0; m_n[0] = nc; m_off[1] = nc; m_n[1] = nr - nc; m_off[2] = 0; m_n[2] = nr;
#ifdef PT_HAVE_EMBREE
    {
        RTCGeometry g;
        double t0;
        float *vb;
        unsigned *ib;
        uint32_t i;
        build_ms[TP_EM] = 1e30;
        for (rep = 0; rep < 3; ++rep) {
            if (esc) { rtcReleaseScene(esc); rtcReleaseDevice(dev); }
            dev = rtcNewDevice("threads=1");
            g_em_bytes = 0;
            rtcSetDeviceMemoryMonitorFunction(dev, em_monitor, NULL);
            t0 = cpu_ms();
            esc = rtcNewScene(dev);
            g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
            vb = (float *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 3u * soup.n);
            ib = (unsigned *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, soup.n);
            memcpy(vb, soup.v, 36u * soup.n);
            for (i = 0; i < 3u * soup.n; ++i) ib[i] = i;
            rtcCommitGeometry(g);
            rtcAttachGeometry(esc, g);
            rtcReleaseGeometry(g);
            rtcCommitScene(esc);
            t0 = cpu_ms() - t0;
            if (t0 < build_ms[TP_EM]) build_ms[TP_EM] = t0;
        }
        bpt[TP_EM] = (double)g_em_bytes / (double)soup.n; /* everything the device holds, buffers included */
        have[TP_EM] = 1;
    }
#endif
#ifdef PT_HAVE_TINYBVH
    {
        size_t tbytes = 0;
        build_ms[TP_TB] = 1e30;
        for (rep = 0; rep < 3; ++rep) {
            double t0;
            if (tb) tbvh_free(tb);
            t0 = cpu_ms();
            tb = tbvh_build(soup.v, soup.n, &tbytes);
            t0 = cpu_ms() - t0;
            if (t0 < build_ms[TP_TB]) build_ms[TP_TB] = t0;
        }
        bpt[TP_TB] = (double)tbytes / (double)soup.n;
        have[TP_TB] = tb != NULL;
    }
#endif
    for (m = 0; m < TP_NM; ++m) for (md = 0; md < 3; ++md) best[m][md] = 1e30;
    for (rep = 0; rep < 5; ++rep) /* interleaved, so load from other jobs hits all alike */
        for (md = 0; md < 3; ++md)
            for (m = 0; m < TP_NM; ++m) {
                const float *o = org + 3u * m_off[md], *dr = dir + 3u * m_off[md];
                float *to = t_m[m] + m_off[md];
                double t0;
                if (!have[m]) continue;
                t0 = cpu_ms();
                if (m == TP_PT) pt_trace(&tri, o, dr, m_n[md], to);
#ifdef PT_HAVE_EMBREE
                if (m == TP_EM) em_trace(esc, o, dr, m_n[md], to);
#endif
#ifdef PT_HAVE_TINYBVH
                if (m == TP_TB) tbvh_trace(tb, o, dr, m_n[md], to);
#endif
                t0 = cpu_ms() - t0;
                if (t0 < best[m][md]) best[m][md] = t0;
            }
    for (m = 0; m < TP_NM; ++m) agree[m] = have[m] ? tp_agree(t_m[TP_PT], t_m[m], nr) : 0;
    printf("%-9s %u triangles, %zu camera + %zu bounce rays (one thread, best of 5 interleaved runs), Mrays/s:\n", nm, soup.n, nc, nr - nc);
    for (m = 0; m < TP_NM; ++m) {
        if (!have[m]) {
            printf("  %-9s not built in (%s)\n", mname[m], m == TP_EM ? "apt-get install libembree-dev" : "make bench-pt TINYBVH=/path/to/tiny_bvh.h");
            continue;
        }
        printf("  %-9s camera %6.2f  bounce %6.2f  all %6.2f", mname[m], (double)m_n[0] / (best[m][0] * 1e3), (double)m_n[1] / (best[m][1] * 1e3),
               (double)m_n[2] / (best[m][2] * 1e3));
        if (m != TP_PT)
            printf("   fovpt/%s camera %.2f bounce %.2f; hits agree with fovpt on %.3f %%", mname[m], best[m][0] / best[TP_PT][0],
                   best[m][1] / best[TP_PT][1], 100.0 * (double)agree[m] / (double)nr);
        printf("\n");
        for (md = 0; md < 3; ++md) {
            double em = have[TP_EM] ? best[TP_EM][md] : -1.0;
            if (md == 2 && sc != PT_SCENE_MESH) continue; /* closest_hit: the row kept from before (terrain) */
            fprintf(csv, "%s,%s,centre,rays_%zu,%.0f,%.2f,nan,nan,nan,nan,nan,%s,%zu,%u,%.3f,nan,0\n", nm, mname[m], m_n[md],
                    (double)m_n[md] / (best[m][md] * 1e-3), best[m][md], modes[md], m_n[md], W * H, em > 0.0 ? em / best[m][md] : 0.0);
        }
        if (bcsv) {
            /* fovpt: what the traversal reads (W-wide nodes, leaf blocks: triangles with their
               slot, id and material) beside the whole scene memory; Embree and tinybvh: the
               same figure as bytes_per_tri */
            double trav = m == TP_PT ? ((double)tri.num_nodes4 * sizeof(fovpt__node4) +
                                        FOVPT__LBLK * (double)tri.num_slots) / (double)soup.n : bpt[m];
            char lay[64];
            /* the node test's instructions: one AVX pass of 8 lanes, or SSE passes of 4 */
#if FOVPT__SIMD == 1 && FOVPT_BVH_WIDTH == 8 && defined(__AVX__)
            const int fovpt__avx_walk = 1;
#else
            const int fovpt__avx_walk = 0;
#endif
            snprintf(lay, sizeof lay, "bvh%u %s", (unsigned)FOVPT_BVH_WIDTH,
                     FOVPT__SIMD == 1 ? (fovpt__avx_walk ? "avx" : "sse") : FOVPT__SIMD == 2 ? "neon" : FOVPT__SIMD == 3 ? "simd128" : "scalar");
            fprintf(bcsv, "%s,%s,%u,%.2f,%.1f,%s,%.1f\n", nm, mname[m], soup.n, build_ms[m], bpt[m],
                    m == TP_PT ? lay : m == TP_EM ? "embree3 default" :
#ifdef PT_HAVE_TINYBVH
                    tbvh_layout(),
#else
                    "",
#endif
                    trav);
        }
    }
    fflush(csv);
#ifdef PT_HAVE_EMBREE
    if (esc) { rtcReleaseScene(esc); rtcReleaseDevice(dev); }
#endif
#ifdef PT_HAVE_TINYBVH
    tbvh_free(tb);
#endif
    for (m = 0; m < TP_NM; ++m) free(t_m[m]);
    free(org); free(dir); free(mem); free(soup.v);
    pt_scene_free(&S);
}

static void throughput_rows(FILE *csv, const char *out_path, uint32_t W, uint32_t H)
{
    static const int scenes[4] = { PT_SCENE_MESH, PT_SCENE_CUBES, PT_SCENE_CORNELL, PT_SCENE_INTERIOR };
    char bpath[1024];
    const char *sl = strrchr(out_path, '/');
    FILE *bcsv;
    int i;
    snprintf(bpath, sizeof bpath, "%.*spt_bvh.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
    bcsv = fopen(bpath, "w");
    if (bcsv) fprintf(bcsv, "scene,method,triangles,build_ms,bytes_per_tri,layout,traversal_bytes_per_tri\n");
    for (i = 0; i < 4; ++i) tp_scene(csv, bcsv, scenes[i], W, H);
    if (bcsv) { fclose(bcsv); printf("wrote %s\n", bpath); }
}

/* ---- temporal options of SELECTIVE (Kim et al. 2021, steps 2 and 4): flicker, alpha sweep --
   Per scene, gaze at the centre, SELECTIVE in Whitted mode, TF frames each:
   - a moving view (turning 0.1 degree per frame about the vertical, about a third of a
     pixel): PSNR per visual field of the last frame against UNIFORM Whitted at 64 spp of the
     last frame's view (Kim et al. 2021, Table 3, compares against a high-spp reference);
   - a static view: flicker = per pixel and channel the standard deviation over frames
     n_tpi + 1 .. TF - 1 (history full) of the sRGB value, root-mean-square over a field.
   Options: off, reuse, smoothing with alpha(e) (Kim et al.'s curve), smoothing with a fixed
   alpha (0.1 .. 0.9, Table 3's sweep), reuse + smoothing. Writes pt_temporal.csv beside
   pt.csv. */
#define TF 10u
static void turn_cam(const fovpt_camera *c0, float deg, fovpt_camera *c)
{
    float dx = c0->target[0] - c0->pos[0], dz = c0->target[2] - c0->pos[2];
    float a = deg * 3.14159265f / 180.0f, ca = cosf(a), sa = sinf(a);
    *c = *c0;
    c->target[0] = c0->pos[0] + dx * ca + dz * sa;
    c->target[2] = c0->pos[2] - dx * sa + dz * ca;
}
static double temporal_seq(pt_scene *S, const fovpt_config *c, fov_gaze g, int moving, float *img, double *var, uint64_t *reused)
{
    size_t n = 0, np = (size_t)S->cam.width * S->cam.height, i;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    fovpt_camera cam;
    double *mean = NULL, t = 0.0;
    uint32_t f, k0 = c->temporal.smooth ? 5u : 1u, cnt = 0; /* static view: frames from n_tpi + 1 */
    *reused = 0;
    if (fovpt_memory_size(c, &S->cam, &n) != FOV_OK) return -1.0;
    mem = malloc(n + 16u);
    if (fovpt_init(&ctx, c, &S->scene, &S->cam, g, mem, n) != FOV_OK) { free(mem); return -1.0; }
    if (!moving) { mean = (double *)calloc(np * 3u, sizeof(double)); for (i = 0; i < np * 3u; ++i) var[i] = 0.0; }
    fovpt_output_init(&out);
    out.rgb = img;
    for (f = 0; f < TF; ++f) {
        double t0;
        turn_cam(&S->cam, moving ? 0.1f * (float)f : 0.0f, &cam);
        if (f > 0) fovpt_set_view(&ctx, &cam, g);
        memset(&st, 0, sizeof st);
        t0 = cpu_ms();
        fovpt_render(&ctx, f, &out, &st);
        t += cpu_ms() - t0;
        *reused += st.reused;
        if (!moving && f >= k0) { /* Welford, on sRGB values */
            ++cnt;
            for (i = 0; i < np * 3u; ++i) {
                double v = srgb(img[i]), d = v - mean[i];
                mean[i] += d / cnt;
                var[i] += d * (v - mean[i]);
            }
        }
    }
    if (!moving) { for (i = 0; i < np * 3u; ++i) var[i] = cnt > 1 ? var[i] / (cnt - 1u) : 0.0; free(mean); }
    free(mem);
    return t / TF;
}
static void temporal_rows(const char *path, uint32_t W, uint32_t H, int quick, int threads)
{
    static const char *const opt[] = { "off", "reuse", "smooth_alpha_e", "smooth", "smooth", "smooth", "smooth", "smooth", "reuse_smooth" };
    static const float fixed[] = { 0, 0, 0, 0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 0 };
    FILE *csv = fopen(path, "w");
    int sc, o;
    size_t np = (size_t)W * H, i;
    float *img = (float *)malloc(np * 12u), *ref = (float *)malloc(np * 12u), *ecc = (float *)malloc(np * 4u);
    double *var = (double *)malloc(np * 3u * sizeof(double));
    if (!csv) { fprintf(stderr, "cannot write %s\n", path); return; }
    fprintf(csv, "scene,option,alpha,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,flicker_f1,flicker_f2,flicker_f3,flicker_f4,flicker_all,"
                 "reused_pct,time_ms\n");
    printf("temporal options (SELECTIVE, Whitted, %u frames; PSNR of the last frame of a turning view, flicker on a static view):\n", TF);
    for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
        pt_scene S;
        fov_gaze g;
        fov_ecc_model em;
        fovpt_config c;
        fovpt_stats st;
        fovpt_camera last;
        uint32_t x, y;
        if (quick && sc != PT_SCENE_CORNELL && sc != PT_SCENE_CUBES) continue;
        if (pt_scene_make(&S, sc) != 0) continue;
        S.cam.width = W; S.cam.height = H;
        g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
        fovpt_ecc_init(&em, NULL, S.cam.fov_y_deg, W, H, g);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) ecc[(size_t)y * W + x] = fovpt_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
        /* reference: the last frame's view */
        turn_cam(&S.cam, 0.1f * (float)(TF - 1u), &last);
        {
            pt_scene R = S;
            R.cam = last;
            c = fovpt_config_default(); c.mode = FOVPT_MODE_WHITTED; c.spp = 64; c.seed = 777;
            render(&R, &c, g, ref, &st, threads);
        }
        for (o = 0; o < (int)(sizeof opt / sizeof opt[0]); ++o) {
            double ps[5], fl[5], t;
            char al[16];
            uint64_t reused, reused_s;
            int f, k;
            c = fovpt_config_default();
            c.mode = FOVPT_MODE_WHITTED;
            c.method = FOVPT_METHOD_SELECTIVE;
            c.temporal.reuse = (o == 1 || o == 8) ? 1u : 0u;
            c.temporal.smooth = o >= 2 && o != 1 ? 1u : 0u;
            if (fixed[o] > 0.0f) for (k = 0; k < 6; ++k) c.temporal.alpha[k] = fixed[o];
            t = temporal_seq(&S, &c, g, 1, img, var, &reused);
            psnr_fields(img, ref, ecc, np, ps);
            temporal_seq(&S, &c, g, 0, img, var, &reused_s);
            for (f = 0; f < 5; ++f) {
                static const double lo[5] = { 0.0, 3.3, 5.5, 12.1, -1.0 }, hi[5] = { 3.3, 5.5, 12.1, 30.0, 1e9 };
                double sum = 0.0;
                size_t cnt = 0;
                for (i = 0; i < np; ++i) {
                    if (ecc[i] < lo[f] || ecc[i] >= hi[f]) continue;
                    sum += var[3 * i] + var[3 * i + 1] + var[3 * i + 2];
                    cnt += 3;
                }
                fl[f] = cnt ? sqrt(sum / (double)cnt) : NAN;
            }
            if (fixed[o] > 0.0f) snprintf(al, sizeof al, "%.1f", (double)fixed[o]);
            else snprintf(al, sizeof al, "%s", c.temporal.smooth ? "alpha_e" : "none");
            fprintf(csv, "%s,%s,%s,%.2f,%.2f,%.2f,%.2f,%.2f,%.5f,%.5f,%.5f,%.5f,%.5f,%.2f,%.2f\n", pt_scene_names[sc], opt[o], al, ps[0], ps[1],
                    ps[2], ps[3], ps[4], fl[0], fl[1], fl[2], fl[3], fl[4], 100.0 * (double)reused / ((double)np * TF), t);
            printf("  %-9s %-15s alpha %-7s PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f  flicker f1..f4 %.4f %.4f %.4f %.4f all %.4f  reused %5.1f %%  %.1f ms/frame\n",
                   pt_scene_names[sc], opt[o], al, ps[0], ps[1], ps[2], ps[3], ps[4], fl[0],
                   fl[1], fl[2], fl[3], fl[4], 100.0 * (double)reused / ((double)np * TF), t);
            fflush(stdout);
        }
        pt_scene_free(&S);
    }
    fclose(csv);
    free(img); free(ref); free(ecc); free(var);
}

/* ---- --fovea-spp: how the Cornell box's fovea error falls with spp ---------------------
   UNIFORM on the rows through the fovea (gaze at the centre, 320x240) at 4, 16, 64, 256 spp
   against 2048 spp: fovea PSNR, PSNR without the worst 1 % of the pixels, and the share of
   the squared error those carry (heavy tails against a few fireflies). */
static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}
static void fovea_rows(pt_scene *S, uint32_t spp, uint32_t seed, uint32_t y0, uint32_t y1, fov_gaze g, float *img)
{
    fovpt_config c = fovpt_config_default();
    size_t n = 0;
    void *m;
    fovpt_ctx ctx;
    fovpt_output o;
    c.spp = spp; c.seed = seed;
    fovpt_memory_size(&c, &S->cam, &n);
    m = malloc(n + 16u);
    fovpt_init(&ctx, &c, &S->scene, &S->cam, g, m, n);
    fovpt_output_init(&o);
    o.rgb = img;
    fovpt_trace_rows(&ctx, 0, y0, y1, NULL);
    fovpt_resolve_rows(&ctx, y0, y1, &o);
    free(m);
}
static void fovea_spp_curve(void)
{
    pt_scene S;
    const uint32_t W = 320, H = 240, y0 = 106, y1 = 134, sp[4] = { 4, 16, 64, 256 };
    fov_gaze g;
    fov_ecc_model em;
    float *gt = (float *)malloc((size_t)W * H * 12u), *im = (float *)malloc((size_t)W * H * 12u);
    double *err = (double *)malloc((size_t)W * H * sizeof(double));
    uint32_t x, y;
    int k;
    if (pt_scene_make(&S, PT_SCENE_CORNELL) != 0) return;
    S.cam.width = W; S.cam.height = H;
    g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
    fovpt_ecc_init(&em, NULL, S.cam.fov_y_deg, W, H, g);
    fovea_rows(&S, 2048, 777, y0, y1, g, gt);
    for (k = 0; k < 4; ++k) {
        size_t n = 0, i;
        double se = 0.0, se99 = 0.0;
        fovea_rows(&S, sp[k], 1, y0, y1, g, im);
        for (y = y0; y < y1; ++y)
            for (x = 0; x < W; ++x) {
                size_t p = (size_t)y * W + x;
                int c;
                double e = 0.0;
                if (fovpt_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f) >= 3.3f) continue;
                for (c = 0; c < 3; ++c) { double d = srgb(im[3 * p + c]) - srgb(gt[3 * p + c]); e += d * d; }
                err[n++] = e;
                se += e;
            }
        qsort(err, n, sizeof(double), cmp_desc);
        for (i = n / 100u; i < n; ++i) se99 += err[i];
        printf("cornell fovea, %3u spp against 2048: %zu pixels, PSNR %.2f dB, without the worst 1 %% %.2f dB, the worst 1 %% carry %.0f %% of the squared error\n",
               sp[k], n, 10.0 * log10(3.0 * (double)n / se), 10.0 * log10(3.0 * (double)(n - n / 100u) / se99), 100.0 * (se - se99) / se);
    }
    pt_scene_free(&S);
    free(gt); free(im); free(err);
}

/* The benchmark's gaze gi (0: the image centre, 1: near the top-left corner) and every
   pixel's eccentricity from the camera's field of view (fovpt_ecc_*) into ecc. */
static fov_gaze bench_gaze(const pt_scene *S, int gi, float *ecc)
{
    uint32_t W = S->cam.width, H = S->cam.height, x, y;
    fov_gaze g;
    fov_ecc_model em;
    g.x = gi ? 0.08f * (float)W : 0.5f * (float)W;
    g.y = gi ? 0.08f * (float)H : 0.5f * (float)H;
    fovpt_ecc_init(&em, NULL, S->cam.fov_y_deg, W, H, g);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) ecc[(size_t)y * W + x] = fovpt_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
    return g;
}

/* ---- the methods of the default rows, equal-time calibration, CSV rows ------------------ */
static const char *const names[] = { "uniform4", "uniform1", "layers", "layers_diam", "zones", "whitted1", "selective", "jin" };

static void method_cfg(fovpt_config *c, int m)
{
    *c = fovpt_config_default();
    switch (m) {
    case 0: c->spp = 4; break;
    case 1: c->spp = 1; break;
    case 2: c->method = FOVPT_METHOD_LAYERS; fovpt_layers_preset(&c->layers, FOVPT_LAYERS_KTH_RADIUS); break;
    case 3: c->method = FOVPT_METHOD_LAYERS; fovpt_layers_preset(&c->layers, FOVPT_LAYERS_KTH_DIAMETER); break;
    case 4: c->method = FOVPT_METHOD_ZONES; c->spp = 4; break;
    case 5: c->mode = FOVPT_MODE_WHITTED; c->spp = 1; break;
    case 6: c->mode = FOVPT_MODE_WHITTED; c->method = FOVPT_METHOD_SELECTIVE; break;
    default: c->mode = FOVPT_MODE_WHITTED; c->method = FOVPT_METHOD_JIN; break;
    }
}

/* samples per target pixel in the fovea: UNIFORM, ZONES cfg.spp; LAYERS the innermost
   layer's; 0 = not a fixed number (SELECTIVE, JIN: 1 + the extra samples of problematic
   subpixels) */
static uint32_t fovea_spp(const fovpt_config *c)
{
    if (c->method == FOVPT_METHOD_LAYERS) return c->layers.layer[c->layers.count - 1u].spp;
    if (c->method == FOVPT_METHOD_UNIFORM || c->method == FOVPT_METHOD_ZONES) return c->spp ? c->spp : 1u;
    return 0;
}

static uint32_t spp_of(double v)
{
    if (!(v >= 1.0)) return 1u;
    if (v > 65536.0) return 65536u;
    return (uint32_t)(v + 0.5);
}

/* Method m (LAYERS, LAYERS diameter or ZONES) with the time t_target: its samples scaled by
   x, all layers alike (fov_only = 0: x multiplies every spp) or the innermost layer only
   (fov_only = 1: x is its spp). The first x comes from the pilot (the default row: time
   t_pilot, sample counts sp), assuming time proportional to samples; while the measured time
   is more than 8 % off, x is corrected along the secant through the last two measurements
   (a step the spp rounding would undo moves on to the neighbouring config), at most EQT_RUNS
   timed runs; a result still outside +-8 % is returned all the same (the row is written)
   after a WARNING line on stdout. Returns the measured time; c and st are those of the
   returned run (the last). */
#define EQT_RUNS 4
#define EQT_TOL 0.08
static void eqtime_cfg(const fovpt_config *base, int m, int fov_only, double x, fovpt_config *c)
{
    uint32_t l, n = base->layers.count;
    *c = *base;
    if (m == 4) c->spp = spp_of(4.0 * x);
    else if (fov_only) c->layers.layer[n - 1u].spp = spp_of(x);
    else
        for (l = 0; l < n; ++l) c->layers.layer[l].spp = spp_of((double)base->layers.layer[l].spp * x);
}
static double eqtime_render(pt_scene *S, int m, int fov_only, double t_target, double t_pilot, const fovpt_stats *sp, fov_gaze g,
                            float *img, fovpt_config *c, fovpt_stats *st)
{
    fovpt_config base, next;
    double x0, t0 = t_pilot, x1, t1 = t_pilot;
    uint32_t l, n;
    int it, runs = 0, k;
    method_cfg(&base, m);
    n = base.layers.count;
    if (!fov_only) {
        x0 = 1.0;
        x1 = t_target / t_pilot;
    } else {
        double tot = 0.0, in = (double)sp->layer_samples[n - 1u];
        for (l = 0; l < n; ++l) tot += (double)sp->layer_samples[l];
        x0 = (double)base.layers.layer[n - 1u].spp;
        x1 = x0 * (1.0 + (t_target / t_pilot - 1.0) * tot / (in > 0.0 ? in : 1.0));
    }
    for (it = 0; it < EQT_RUNS; ++it) {
        double xn;
        eqtime_cfg(&base, m, fov_only, x1, c);
        t1 = render(S, c, g, img, st, 1);
        runs++;
        if (!(t1 > 0.0) || fabs(t1 / t_target - 1.0) <= EQT_TOL) break;
        xn = (t1 > t0 && x1 != x0) ? x1 + (t_target - t1) * (x1 - x0) / (t1 - t0) : x1 * t_target / t1;
        if (!(xn > 0.0)) xn = x1 * t_target / t1;
        eqtime_cfg(&base, m, fov_only, xn, &next);
        for (k = 0; k < 200 && memcmp(&next, c, sizeof next) == 0; ++k) { /* rounded to the same run */
            xn *= t1 > t_target ? 0.97 : 1.03;
            eqtime_cfg(&base, m, fov_only, xn, &next);
        }
        if (memcmp(&next, c, sizeof next) == 0) break; /* no other config in that direction */
        x0 = x1; t0 = t1; x1 = xn;
    }
    if (t1 > 0.0 && fabs(t1 / t_target - 1.0) > EQT_TOL)
        printf("  WARNING method %d%s: equal time not reached, time / target %.2f after %d run(s) (row written)\n", m,
               fov_only ? " (fovea only)" : "", t1 / t_target, runs);
    return t1;
}

static void row(FILE *csv, const char *scene, const char *method, const char *gaze, const char *budget, const fovpt_stats *st, double t,
                const double ps[5], int whitted, double t_u4, double budget_t, uint32_t spp_f)
{
    fprintf(csv, "%s,%s,%s,%s,%.0f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%s,%llu,%llu,%.3f,", scene, method, gaze, budget,
            (double)st->rays / (t * 1e-3), t, ps[0], ps[1], ps[2], ps[3], ps[4], whitted ? "whitted" : "path",
            (unsigned long long)st->rays, (unsigned long long)st->camera_rays, t_u4 / t);
    if (budget_t > 0.0) fprintf(csv, "%.2f,%u\n", budget_t, spp_f);
    else fprintf(csv, "nan,%u\n", spp_f);
}

/* ---- path tracing in log-polar space: fovlp decides where, fovpt shades, fovlp reconstructs -
   (examples/lp_pt.c's pipeline; Koskela et al. 2019 = M. Koskela, A. Lotvonen, M. Makitalo,
   P. Kivi, T. Viitanen, P. Jaaskelainen, "Foveated Real-Time Path Tracing in Visual-Polar
   Space", EGSR 2019, do this on the GPU; the mapping is fovlp.h's kernel log-polar one, Meng et
   al. 2018, "Kernel Foveated Rendering", with Andersson & Hansson 2020's gaze disc).
   Rows (mode path, fovpt_config_default's path tracer, as uniform4; the LP positions are shaded
   as they are; the gaze disc's pixels with fovpt_shade_points' jitter 1, UNIFORM's box filter,
   in one frame, and at fovlp's jittered positions under TAA):
     lp_cfov          fovlp's C Fov preset (Andersson & Hansson 2020, Table 5.1), one frame;
                      default: 4 path samples per position (uniform4's spp); eqtime_uniform4:
                      the samples per position scaled to uniform4's time
     lp_cfov_taa      the same over F frames of fovlp's TAA (still camera and gaze, the jitter
                      moves the positions; the image is the last TAA output), eqtime_uniform4:
                      the whole sequence takes uniform4's time (F = 16, one Halton cycle, with
                      the spp per frame scaled; fewer frames at 1 spp when 16 do not fit)
     lp_cfov_fovea    one frame, the LP positions at 4 spp and only the gaze disc's (and the
                      centre sample's) spp raised to uniform4's time (as layers_fovea)
     lp_acuity, lp_acuity_taa, lp_acuity_fovea   the same with fovlp_config_acuity (the eye model, quality 0.5,
                      at the camera's field of view; Catmull-Rom reconstruction)
   time_ms: the thread CPU time of every frame (sample list, path tracing, reconstruction, TAA);
   camera_rays: the positions shaded x spp, summed over the frames; spp_fovea: path samples per
   fovea pixel in the output (spp per frame x frames: the gaze disc shades every pixel once). */
static double lp_render(pt_scene *S, const fovlp_config *lc0, fov_gaze g, uint32_t frames, uint32_t spp, uint32_t spp_disc,
                        float *img, fovpt_stats *st, fovlp_counts *cnt)
{
    fovlp_config lc = *lc0;
    fovlp_ctx lp;
    fovlp_camera lcam;
    fovpt_config pc = fovpt_config_default();
    size_t bytes = 0, np = (size_t)S->cam.width * S->cam.height;
    void *mem;
    float *smp, *sdep, *cur, *cdep, *hist[2], *hdep[2];
    uint8_t *age[2];
    uint32_t f, H = S->cam.height;
    int ping = 0, a, ok = 1;
    double t0, t;
    memset(st, 0, sizeof *st);
    lc.taa.enable = frames > 1 ? 1u : 0u;
    if (fovlp_camera_from(&S->cam, &lcam) != FOV_OK || fovlp_memory_size(&lc, &bytes) != FOV_OK) {
        printf("  lp_render: fovlp_camera_from / fovlp_memory_size failed\n");
        return -1.0;
    }
    mem = malloc(bytes ? bytes : 1u);
    if (!mem || fovlp_init(&lp, &lc, mem, bytes) != FOV_OK) {
        printf("  lp_render: %s\n", mem ? "fovlp_init failed" : "out of memory");
        free(mem);
        return -1.0;
    }
    smp = (float *)calloc((size_t)lp.geo.samples * 3u, sizeof(float));
    sdep = (float *)calloc(lp.geo.samples, sizeof(float));
    cur = (float *)malloc(np * 12u);
    cdep = (float *)malloc(np * 4u);
    for (a = 0; a < 2; ++a) {
        hist[a] = (float *)calloc(np * 3u, sizeof(float));
        hdep[a] = (float *)calloc(np, sizeof(float));
        age[a] = (uint8_t *)calloc(np, 1);
    }
    if (!smp || !sdep || !cur || !cdep || !hist[0] || !hist[1] || !hdep[0] || !hdep[1] || !age[0] || !age[1]) {
        printf("  lp_render: out of memory\n");
        ok = 0;
    }
    memset(cnt, 0, sizeof *cnt);
    t0 = cpu_ms();
    for (f = 0; f < frames && ok; ++f) {
        lppt_user u;
        memset(&u, 0, sizeof u);
        u.scene = &S->scene; u.cfg = &pc; u.cam = &S->cam; u.frame = f; u.spp = spp;
        /* the LP rows at spp, the gaze disc's rows and the centre sample at spp_disc */
        ok = fovlp_begin_frame(&lp, g, &lcam) == FOV_OK && lppt_shade_samples(&lp, 0, lp.geo.lp_h, &u, smp, sdep) == FOV_OK;
        u.spp = spp_disc;
        u.jitter = lc.taa.enable ? 0.0f : 1.0f; /* one frame: the disc pixels box-filtered as UNIFORM's */
        ok = ok && lppt_shade_samples(&lp, lp.geo.lp_h, fovlp_sample_rows(&lp), &u, smp, sdep) == FOV_OK;
        if (!ok) { printf("  lp_render: frame %u: fovlp_begin_frame / lppt_shade_samples failed\n", f); break; }
        if (fovlp_reconstruct_rows(&lp, smp, sdep, 0, H, lc.taa.enable ? cur : img, 0, cdep) != FOV_OK) {
            printf("  lp_render: frame %u: fovlp_reconstruct_rows failed\n", f);
            ok = 0;
        }
        if (ok && lc.taa.enable) {
            fovlp_taa_io io;
            fovlp_taa_io_init(&io);
            io.cur_rgb = cur; io.cur_depth = cdep;
            io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
            io.out_rgb = f + 1u == frames ? img : hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
            ok = fovlp_taa_rows(&lp, &io, 0, H, NULL) == FOV_OK;
            if (!ok) printf("  lp_render: frame %u: fovlp_taa_rows failed\n", f);
            ping = 1 - ping;
        }
        fovpt_stats_add(st, &u.stats);
    }
    t = cpu_ms() - t0;
    if (ok && fovlp_count_samples(&lp, cnt) != FOV_OK) { printf("  lp_render: fovlp_count_samples failed\n"); ok = 0; }
    free(mem); free(smp); free(sdep); free(cur); free(cdep);
    for (a = 0; a < 2; ++a) { free(hist[a]); free(hdep[a]); free(age[a]); }
    return ok ? t : -1.0;
}

/* x path samples per position in all (frame-spp units) as frames x spp: one frame without TAA,
   else 16 frames (one Halton cycle) with the spp scaled, or fewer frames at 1 spp */
static void lp_split(double x, int taa, uint32_t *frames, uint32_t *spp)
{
    if (!taa) { *frames = 1; *spp = spp_of(x); return; }
    if (x >= 16.0) { *frames = 16; *spp = spp_of(x / 16.0); return; }
    *frames = x >= 2.0 ? (uint32_t)(x + 0.5) : 2u;
    *spp = 1;
}

/* the frames, spp per LP position and spp per disc position of x (var as in lp_rows) */
static void lp_budget(double x, int var, uint32_t *frames, uint32_t *spp, uint32_t *spp_disc)
{
    if (var == 2) { *frames = 1; *spp = 4; *spp_disc = spp_of(x); return; }
    lp_split(x, var == 1, frames, spp);
    *spp_disc = *spp;
}

/* The lp_ rows of one scene and gaze beside uniform4 (time t_u4, fovea PSNR f1_u4) */
static void lp_rows(FILE *csv, pt_scene *S, const char *nm, const char *gz, fov_gaze g, const float *ref, const float *ecc, size_t np,
                    double t_u4, double f1_u4, float *img)
{
    int v, var;
    for (v = 0; v < 2; ++v) {
        fovlp_config lc = fovlp_config_preset(FOVLP_PRESET_C_FOV, S->cam.width, S->cam.height);
        fovlp_camera lcam;
        fovlp_counts cnt, cnt_p;
        fovpt_stats st;
        double t_p, t, ps[5];
        const char *base = v ? "lp_acuity" : "lp_cfov";
        lc.cam_fov_y_deg = S->cam.fov_y_deg;
        if (v && (fovlp_camera_from(&S->cam, &lcam) != FOV_OK || fovlp_config_acuity(&lc, &lcam, NULL) != FOV_OK)) {
            printf("  %-12s fovlp_config_acuity: no reduction at this display (skipped)\n", base);
            continue;
        }
        /* the pilot: one frame, 4 spp per position (uniform4's spp): the default row */
        t_p = lp_render(S, &lc, g, 1, 4, 4, img, &st, &cnt_p);
        if (t_p <= 0.0) { printf("  %-12s failed (rows skipped)\n", base); continue; }
        psnr_fields(img, ref, ecc, np, ps);
        row(csv, nm, base, gz, "default", &st, t_p, ps, 0, t_u4, -1.0, 4);
        printf("  %-12s %9.1f ms (%.1f %% of the pixels shaded, %llu in the gaze disc) PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f  speedup %.2f\n",
               base, t_p, (double)cnt_p.shaded_pct, (unsigned long long)cnt_p.disc_shaded,
               ps[0], ps[1], ps[2], ps[3], ps[4], t_u4 / t_p);
        /* var 0: every position's samples scaled; 1: over 16 TAA frames; 2: only the gaze disc's
           (and the centre sample's) samples raised, the LP samples kept at 4 (as layers_fovea) */
        for (var = 0; var < 3; ++var) {
            double x1, x0 = 4.0, t0 = t_p, share = (double)cnt_p.disc_shaded / (double)(cnt_p.shaded ? cnt_p.shaded : 1u);
            uint32_t fr = 1, spp = 4, sppd = 4;
            int it, runs = 0, k;
            char mname[64];
            if (var == 2 && cnt_p.disc_shaded == 0) continue;
            x1 = var == 2 ? 4.0 * (1.0 + (t_u4 / t_p - 1.0) / (share > 0.01 ? share : 0.01)) : 4.0 * t_u4 / t_p;
            snprintf(mname, sizeof mname, "%s%s", base, var == 1 ? "_taa" : var == 2 ? "_fovea" : "");
            /* equal time: from the pilot, corrected along the secant through the last two runs
               while more than EQT_TOL (8 %) off, at most EQT_RUNS (4) timed runs (a step the
               rounding to frames and spp would undo moves on to the neighbouring split); a row
               still outside is written all the same, with a WARNING line */
            t = -1.0;
            for (it = 0; it < EQT_RUNS; ++it) {
                double xn;
                uint32_t nf, ns, nd;
                lp_budget(x1, var, &fr, &spp, &sppd);
                t = lp_render(S, &lc, g, fr, spp, sppd, img, &st, &cnt);
                runs++;
                if (t <= 0.0 || fabs(t / t_u4 - 1.0) <= EQT_TOL) break;
                xn = (t > t0 && x1 != x0) ? x1 + (t_u4 - t) * (x1 - x0) / (t - t0) : x1 * t_u4 / t;
                if (!(xn > 0.0)) xn = x1 * t_u4 / t;
                lp_budget(xn, var, &nf, &ns, &nd);
                for (k = 0; k < 200 && nf == fr && ns == spp && nd == sppd; ++k) { /* rounded to the same run */
                    xn *= t > t_u4 ? 0.97 : 1.03;
                    lp_budget(xn, var, &nf, &ns, &nd);
                }
                if (nf == fr && ns == spp && nd == sppd) break; /* no other split in that direction */
                x0 = x1; t0 = t; x1 = xn;
            }
            if (t <= 0.0) { printf("  %-16s lp_render failed (row skipped)\n", mname); continue; }
            if (fabs(t / t_u4 - 1.0) > EQT_TOL)
                printf("  WARNING %s: equal time not reached, time / target %.2f after %d run(s) (row written)\n", mname, t / t_u4,
                       runs);
            psnr_fields(img, ref, ecc, np, ps);
            row(csv, nm, mname, gz, "eqtime_uniform4", &st, t, ps, 0, t_u4, t_u4, fr * sppd);
            printf("  %-16s at uniform4's time (%.1f ms): %8.1f ms, %u frame(s) x %u spp (disc %u), PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f"
                   " (uniform4 f1 %.2f: %+.2f dB)\n", mname, t_u4, t, fr, spp, sppd, ps[0], ps[1], ps[2], ps[3], ps[4], f1_u4, ps[0] - f1_u4);
        }
    }
}

/* ---- denoised rows (_dn): guide buffers + fovpt_denoise (issue 14) -----------------------
   For the path methods (uniform4, uniform1, layers, layers_diam, zones) at their default
   budget and at eqtime_uniform4 (layers, layers_diam, zones, layers_fovea, layers_diam_fovea:
   the time of uniform4 WITHOUT a denoiser in the same run, the denoiser's cost counted in the
   row's time): rows <method>_dn in pt.csv (same columns; time_ms = trace with guides +
   refine + resolve + denoise, one thread; a single frame, so no history: the spatial filter
   alone). Beside pt.csv, pt_denoise.csv: scene,method,gaze,budget,psnr_f1..f4,psnr_all,
   flip,flip_f1,time_ms,dn_ms (flip: mean LDR-FLIP of the eye-filtered pair,
   examples/fovmetrics.h fovm_perceptual, the camera's field of view as the display; flip_f1
   the same over the fovea annulus only... computed on the eye-filtered FLIP map), with the
   undenoised method in the same run beside each _dn row.
   Flicker (pt_flicker.csv: scene,method,flicker_static,flicker_moving,psnr_f1_static,
   psnr_all_static; gaze at the centre,
   DN_TF frames, the default budgets of uniform4, layers, zones with and without the
   denoiser, which keeps its history across the frames): per pixel of the periphery (e >= 12.1
   degrees) the mean absolute frame-to-frame difference of the sRGB values, frames 2 .. DN_TF
   - 1; the moving view turns 0.1 degree per frame about the vertical and the previous frame
   is first warped to the current view (a pure rotation: exact per pixel, bilinear), so a
   static scene seen by a noiseless renderer scores about its bilinear warp error.
   psnr_f1_static / psnr_all_static: the last frame of the static view against the ground
   truth (what DN_TF frames of temporal accumulation reach). */
#define DN_TF 8u
/* g_dn (declared above render()): 1 = trace with guides and denoise */
static double g_dn_ms;           /* the denoiser's share of the last render, ms */
static int g_dn_scene = -1;      /* --denoise --scene N: that scene only */

static uint32_t g_dn_no_sure; /* --dn-no-sure: the denoiser with cfg.no_sure = 1 */
static int g_dn_seeds = 1;    /* --seeds N: the _dn rows' and their twins' PSNR over N seeds */

static double render_dn(pt_scene *S, const fovpt_config *cfg, fov_gaze g, float *rgb, fovpt_stats *st)
{
    size_t n = 0, dnb = 0, np = (size_t)S->cam.width * S->cam.height;
    void *mem, *dmem;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_guide gd;
    fovpt_denoise dn;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    dc.no_sure = g_dn_no_sure;
    float *noisy = (float *)malloc(np * 12u), *gb = (float *)malloc(np * 32u);
    double t0, t1, t;
    fov_result e;
    memset(st, 0, sizeof *st);
    dc.width = S->cam.width; dc.height = S->cam.height;
    if (fovpt_memory_size(cfg, &S->cam, &n) != FOV_OK || fovpt_denoise_size(&dc, &dnb) != FOV_OK) return -1.0;
    mem = malloc(n + 16u);
    dmem = malloc(dnb);
    if (fovpt_init(&ctx, cfg, &S->scene, &S->cam, g, mem, n) != FOV_OK || fovpt_denoise_init(&dn, &dc, dmem, dnb) != FOV_OK) {
        free(mem); free(dmem); return -1.0;
    }
    fovpt_guide_init(&gd);
    gd.albedo = gb; gd.normal = gb + 3u * np; gd.depth = gb + 6u * np; gd.spp = gb + 7u * np;
    gd.var = (float *)malloc(np * 4u);
    fovpt_output_init(&out);
    out.rgb = noisy;
    t0 = cpu_ms();
    e = fovpt_render_guide(&ctx, 0, &out, &gd, st);
    t1 = cpu_ms();
    if (e == FOV_OK) e = fovpt_denoise_frame(&dn, &S->cam, g, noisy, 0, &gd);
    out.rgb = rgb;
    if (e == FOV_OK) e = fovpt_denoise_run(&dn, &out);
    t = cpu_ms() - t0;
    if (e != FOV_OK) { /* a bug, not a figure: stop rather than write a row of garbage */
        fprintf(stderr, "bench_pt --denoise: render_guide / denoiser failed: %s\n", fovpt_result_string(e));
        exit(1);
    }
    g_dn_ms = cpu_ms() - t1;
    free(gd.var); free(noisy); free(gb); free(mem); free(dmem);
    return t;
}

static void srgb_img(const float *a, float *o, size_t n3)
{
    size_t i;
    for (i = 0; i < n3; ++i) o[i] = (float)srgb((double)a[i]);
}

/* FLIP of the eye-filtered pair over the image and over the fovea annulus (e < 3.3) */
static void flip_of(const float *img, const float *ref, const float *ecc, uint32_t W, uint32_t H, float fovy, fov_gaze g,
                    double *flip_all, double *flip_f1)
{
    size_t np = (size_t)W * H, i, c = 0;
    float *a = (float *)calloc(np * 3u, 4u), *b = (float *)calloc(np * 3u, 4u), *map = (float *)calloc(np, 4u);
    fovm_eye eye = fovm_eye_from_fov((int)W, (int)H, (double)fovy, (double)g.x, (double)g.y);
    double s = 0.0;
    srgb_img(img, a, np * 3u);
    srgb_img(ref, b, np * 3u);
    *flip_all = NAN; *flip_f1 = NAN;
    if (fovm_perceptual(b, a, (int)W, (int)H, 3, &eye, NULL, flip_all, map) == FOVM_OK) {
        for (i = 0; i < np; ++i)
            if (ecc[i] < 3.3f) { s += map[i]; c++; }
        *flip_f1 = c ? s / (double)c : NAN;
    }
    free(a); free(b); free(map);
}

static void dn_side_row(FILE *side, const char *scene, const char *method, const char *gz, const char *budget, const double ps[5],
                        double fl, double fl1, double t, double tdn)
{
    fprintf(side, "%s,%s,%s,%s,%.2f,%.2f,%.2f,%.2f,%.2f,%.4f,%.4f,%.2f,%.2f\n", scene, method, gz, budget, ps[0], ps[1], ps[2], ps[3], ps[4],
            fl, fl1, t, tdn);
}

/* --seeds N: ps (the PSNR of the run with config c, seed c->seed) replaced by the PSNR of
   the mean MSE per field over N renders of c, with the seeds c->seed + 7919 s (s = 0 .. N - 1;
   s = 0 is the image already measured), with the denoiser when dn; the time, FLIP and the
   equal-time calibration stay those of the first run */
static void seeds_psnr(pt_scene *S, const fovpt_config *c, int dn, fov_gaze g, const float *ref, const float *ecc, double ps[5])
{
    size_t np = (size_t)S->cam.width * S->cam.height;
    double mse[5], p2[5];
    float *tmp;
    int s, f;
    if (g_dn_seeds <= 1) return;
    tmp = (float *)malloc(np * 12u);
    for (f = 0; f < 5; ++f) mse[f] = pow(10.0, -ps[f] / 10.0);
    for (s = 1; s < g_dn_seeds; ++s) {
        fovpt_config cs = *c;
        fovpt_stats st;
        cs.seed = c->seed + 7919u * (uint32_t)s;
        g_dn = dn;
        render(S, &cs, g, tmp, &st, 1);
        g_dn = 0;
        psnr_fields(tmp, ref, ecc, np, p2);
        for (f = 0; f < 5; ++f) mse[f] += pow(10.0, -p2[f] / 10.0);
    }
    for (f = 0; f < 5; ++f) ps[f] = -10.0 * log10(mse[f] / (double)g_dn_seeds);
    free(tmp);
}

/* the _dn rows of one scene and gaze; t_u4 = uniform4's time without a denoiser (same run) */
static void dn_rows(FILE *csv, FILE *side, pt_scene *S, const char *nm, const char *gz, fov_gaze g, const float *ref, const float *ecc,
                    double t_u4)
{
    uint32_t W = S->cam.width, H = S->cam.height;
    size_t np = (size_t)W * H;
    float *img = (float *)malloc(np * 12u);
    double t_m[5][2], f1_u4 = NAN;
    fovpt_stats st_m[5][2], st;
    fovpt_config c;
    int m;
    for (m = 0; m <= 4; ++m) { /* default budgets, with and without the denoiser */
        double ps[5], fl, fl1, t;
        char mname[64];
        int d;
        for (d = 0; d < 2; ++d) {
            method_cfg(&c, m);
            g_dn = d;
            t = render(S, &c, g, img, &st, 1);
            g_dn = 0;
            psnr_fields(img, ref, ecc, np, ps);
            flip_of(img, ref, ecc, W, H, S->cam.fov_y_deg, g, &fl, &fl1);
            seeds_psnr(S, &c, d, g, ref, ecc, ps);
            snprintf(mname, sizeof mname, "%s%s", names[m], d ? "_dn" : "");
            if (d) row(csv, nm, mname, gz, "default", &st, t, ps, 0, t_u4, -1.0, fovea_spp(&c));
            t_m[m][d] = t; /* the pilots of the equal-time rows, each its own */
            st_m[m][d] = st;
            if (m == 0 && !d) f1_u4 = ps[0];
            dn_side_row(side, nm, mname, gz, "default", ps, fl, fl1, t, d ? g_dn_ms : 0.0);
            printf("  %-20s %8.1f ms (denoise %5.1f) PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f FLIP %.4f (f1 %.4f)\n", mname, t,
                   d ? g_dn_ms : 0.0, ps[0], ps[1], ps[2], ps[3], ps[4], fl, fl1);
        }
    }
    for (m = 2; m <= 4; ++m) { /* equal time with uniform4 (no denoiser), the denoiser's cost counted */
        int fov_only;
        for (fov_only = 0; fov_only < (m == 4 ? 1 : 2); ++fov_only) {
            double ps[5], fl, fl1, t;
            char mname[64];
            int d;
            for (d = 0; d < 2; ++d) {
                g_dn = d;
                t = eqtime_render(S, m, fov_only, t_u4, t_m[m][d], &st_m[m][d], g, img, &c, &st);
                g_dn = 0;
                psnr_fields(img, ref, ecc, np, ps);
                flip_of(img, ref, ecc, W, H, S->cam.fov_y_deg, g, &fl, &fl1);
                seeds_psnr(S, &c, d, g, ref, ecc, ps);
                snprintf(mname, sizeof mname, "%s%s%s", names[m], fov_only ? "_fovea" : "", d ? "_dn" : "");
                if (d) row(csv, nm, mname, gz, "eqtime_uniform4", &st, t, ps, 0, t_u4, t_u4, fovea_spp(&c));
                dn_side_row(side, nm, mname, gz, "eqtime_uniform4", ps, fl, fl1, t, d ? g_dn_ms : 0.0);
                printf("  %-20s at uniform4's time (%.1f ms): %8.1f ms, fovea spp %u, PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f FLIP %.4f"
                       " (uniform4 f1 %.2f: %+.2f dB)\n", mname, t_u4, t, fovea_spp(&c), ps[0], ps[1], ps[2], ps[3], ps[4], fl, f1_u4, ps[0] - f1_u4);
            }
        }
    }
    fflush(csv);
    fflush(side);
    free(img);
}

/* bilinear sample of img (W x H x 3) at continuous pixel point (x, y); 0 outside */
static int bilin(const float *img, uint32_t W, uint32_t H, float x, float y, float o[3])
{
    int ix, iy, k;
    float fx, fy;
    x -= 0.5f; y -= 0.5f;
    if (!(x >= 0.0f && y >= 0.0f && x <= (float)W - 1.0f && y <= (float)H - 1.0f)) return 0;
    ix = (int)x; iy = (int)y;
    if (ix >= (int)W - 1) ix = (int)W - 2;
    if (iy >= (int)H - 1) iy = (int)H - 2;
    fx = x - (float)ix; fy = y - (float)iy;
    for (k = 0; k < 3; ++k) {
        const float *p = img + 3 * ((size_t)iy * W + (size_t)ix) + k;
        o[k] = (1 - fx) * (1 - fy) * p[0] + fx * (1 - fy) * p[3] + (1 - fx) * fy * p[3 * W] + fx * fy * p[3 * W + 3];
    }
    return 1;
}

/* flicker of one method over DN_TF frames (moving 0/1); dn: with the denoiser (history kept) */
static double flicker_seq(pt_scene *S, const fovpt_config *c, fov_gaze g, int moving, int dn_on, const float *ecc, const float *ref,
                          double ps[5])
{
    uint32_t W = S->cam.width, H = S->cam.height, f, x, y;
    size_t np = (size_t)W * H, n = 0, dnb = 0, cnt = 0;
    void *mem, *dmem;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_guide gd;
    fovpt_denoise dn;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    dc.no_sure = g_dn_no_sure;
    fovpt_camera cam, prev;
    float *noisy = (float *)malloc(np * 12u), *gb = (float *)malloc(np * 36u), *cur = (float *)malloc(np * 12u),
          *old = (float *)malloc(np * 12u);
    double sum = 0.0;
    dc.width = W; dc.height = H;
    fovpt_memory_size(c, &S->cam, &n);
    fovpt_denoise_size(&dc, &dnb);
    mem = malloc(n + 16u);
    dmem = malloc(dnb);
    if (fovpt_init(&ctx, c, &S->scene, &S->cam, g, mem, n) != FOV_OK || fovpt_denoise_init(&dn, &dc, dmem, dnb) != FOV_OK) {
        fprintf(stderr, "bench_pt --denoise (flicker): fovpt_init / fovpt_denoise_init failed\n");
        exit(1);
    }
    fovpt_guide_init(&gd);
    gd.albedo = gb; gd.normal = gb + 3u * np; gd.depth = gb + 6u * np; gd.spp = gb + 7u * np; gd.var = gb + 8u * np;
    prev = S->cam;
    for (f = 0; f < DN_TF; ++f) {
        turn_cam(&S->cam, moving ? 0.1f * (float)f : 0.0f, &cam);
        if (f > 0) fovpt_set_view(&ctx, &cam, g);
        fovpt_output_init(&out);
        out.rgb = dn_on ? noisy : cur;
        if (dn_on) {
            fov_result e = fovpt_render_guide(&ctx, f, &out, &gd, NULL);
            if (e == FOV_OK) e = fovpt_denoise_frame(&dn, &cam, g, noisy, 0, &gd);
            out.rgb = cur;
            if (e == FOV_OK) e = fovpt_denoise_run(&dn, &out);
            if (e != FOV_OK) {
                fprintf(stderr, "bench_pt --denoise (flicker): render_guide / denoiser failed: %s\n", fovpt_result_string(e));
                exit(1);
            }
        } else {
            fovpt_render(&ctx, f, &out, NULL);
        }
        if (f >= 2) {
            for (y = 0; y < H; ++y)
                for (x = 0; x < W; ++x) {
                    size_t i = (size_t)y * W + x;
                    float o[3], p[3], d[3];
                    int k;
                    if (ecc[i] < 12.1f) continue;
                    /* the previous view's pixel that sees this pixel's direction */
                    fovpt_camera_ray(&cam, (float)x + 0.5f, (float)y + 0.5f, o, d);
                    for (k = 0; k < 3; ++k) p[k] = o[k] + d[k];
                    {
                        fov_gaze q;
                        float v[3];
                        if (fovpt_gaze_from_point(&prev, p, &q) != FOV_OK || !bilin(old, W, H, q.x, q.y, v)) continue;
                        for (k = 0; k < 3; ++k) sum += fabs(srgb((double)cur[3 * i + (size_t)k]) - srgb((double)v[k]));
                        cnt += 3;
                    }
                }
        }
        memcpy(old, cur, np * 12u);
        prev = cam;
    }
    if (ref) psnr_fields(cur, ref, ecc, np, ps); /* the last frame of the static view */
    free(noisy); free(gb); free(cur); free(old); free(mem); free(dmem);
    return cnt ? sum / (double)cnt : NAN;
}

static void flicker_rows(FILE *fc, pt_scene *S, const char *nm, fov_gaze g, const float *ecc, const float *ref)
{
    static const int ms[3] = { 0, 2, 4 };
    int i, d;
    for (i = 0; i < 3; ++i)
        for (d = 0; d < 2; ++d) {
            fovpt_config c;
            double fs, fm, ps[5];
            method_cfg(&c, ms[i]);
            fs = flicker_seq(S, &c, g, 0, d, ecc, ref, ps);
            fm = flicker_seq(S, &c, g, 1, d, ecc, NULL, ps);
            fprintf(fc, "%s,%s%s,%.5f,%.5f,%.2f,%.2f\n", nm, names[ms[i]], d ? "_dn" : "", fs, fm, ps[0], ps[4]);
            printf("  flicker %-12s%s static %.5f moving %.5f; static view, frame %u: PSNR f1 %.2f all %.2f\n", names[ms[i]], d ? "_dn" : "   ", fs, fm,
                   DN_TF, ps[0], ps[4]);
        }
    fflush(fc);
}

/* The reference's own noise (pt_ref_floor.csv): a second UNIFORM image at gt_spp / 4 (at least
   1) with its own seed (778) against the ground truth (seed 777) has, per field, the expected
   MSE v_ref (1 + gt_spp / check_spp) (independent estimates, variance falling as 1 / spp), so
   v_ref = MSE / (1 + gt_spp / check_spp); floor = 10 log10(1 / v_ref) dB. Any image's MSE
   against the ground truth is its own MSE against the exact image plus v_ref (in expectation),
   so a row's PSNR stays below the floor however good the image is, and a difference between
   two rows close to it is compressed: MSE_true ~ 10^(-PSNR / 10) - v_ref. Costs a quarter of
   the ground truth's samples. */
static uint32_t g_gt_fovea_spp; /* --gt-fovea-spp N: the fovea's ground truth at N spp (0: off) */

/* the fovea's pixels (e < 3.3 degrees) of ref replaced by a UNIFORM image at spp samples (seed
   779; only the rows that hold them are traced, threads of them at once) */
static void fovea_ref(pt_scene *S, fov_gaze g, uint32_t spp, const float *ecc, float *ref, int threads)
{
    uint32_t W = S->cam.width, H = S->cam.height, ya = H, yb = 0, x, y;
    size_t n = 0;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    fovpt_config c = fovpt_config_default();
    float *img = (float *)calloc((size_t)W * H * 3u, 4u);
    pthread_t th[16];
    job jobs[16];
    int i;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x)
            if (ecc[(size_t)y * W + x] < 3.3f) { if (y < ya) ya = y; yb = y + 1u; }
    c.spp = spp; c.seed = 779; c.mirror_nee = g_mn;
    if (threads < 1) threads = 1;
    if (threads > 16) threads = 16;
    if (ya >= yb || fovpt_memory_size(&c, &S->cam, &n) != FOV_OK) { free(img); return; }
    mem = malloc(n + 16u);
    if (fovpt_init(&ctx, &c, &S->scene, &S->cam, g, mem, n) != FOV_OK) { free(mem); free(img); return; }
    for (i = 0; i < threads; ++i) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].ctx = &ctx;
        jobs[i].y0 = ya + (yb - ya) * (uint32_t)i / (uint32_t)threads;
        jobs[i].y1 = ya + (yb - ya) * (uint32_t)(i + 1) / (uint32_t)threads;
        pthread_create(&th[i], NULL, worker, &jobs[i]);
    }
    for (i = 0; i < threads; ++i) pthread_join(th[i], NULL);
    memset(&st, 0, sizeof st);
    fovpt_refine_rows(&ctx, 0, ya, yb, &st);
    fovpt_output_init(&out);
    out.rgb = img;
    fovpt_resolve_rows(&ctx, ya, yb, &out);
    for (y = ya; y < yb; ++y)
        for (x = 0; x < W; ++x) {
            size_t q = (size_t)y * W + x;
            if (ecc[q] < 3.3f) memcpy(ref + 3u * q, img + 3u * q, 12u);
        }
    free(mem);
    free(img);
}

/* the ground truth of S at gaze g: UNIFORM at gt_spp (seed 777), the fovea's pixels at
   --gt-fovea-spp where that is more */
static void ground_truth(pt_scene *S, fov_gaze g, uint32_t gt_spp, const float *ecc, float *ref, int threads)
{
    fovpt_config c = fovpt_config_default();
    fovpt_stats st;
    c.spp = gt_spp; c.seed = 777;
    render(S, &c, g, ref, &st, threads);
    if (g_gt_fovea_spp > gt_spp) fovea_ref(S, g, g_gt_fovea_spp, ecc, ref, threads);
}

static void ref_floor(pt_scene *S, fov_gaze g, uint32_t gt_spp, const float *ref, const float *ecc, int threads, uint32_t *check_spp,
                      double fl[5])
{
    static const double lo[5] = { 0.0, 3.3, 5.5, 12.1, -1.0 }, hi[5] = { 3.3, 5.5, 12.1, 30.0, 1e9 };
    size_t np = (size_t)S->cam.width * S->cam.height, i;
    float *chk = (float *)malloc(np * 12u);
    fovpt_config c = fovpt_config_default();
    fovpt_stats st;
    int f;
    *check_spp = gt_spp / 4u ? gt_spp / 4u : 1u;
    c.spp = *check_spp; c.seed = 778;
    render(S, &c, g, chk, &st, threads);
    for (f = 0; f < 5; ++f) {
        double se = 0.0, v;
        size_t cnt = 0, k;
        for (i = 0; i < np; ++i) {
            /* the pixel's ground truth samples: the fovea's own with --gt-fovea-spp */
            double gs = (g_gt_fovea_spp > gt_spp && ecc[i] < 3.3f) ? (double)g_gt_fovea_spp : (double)gt_spp;
            if (ecc[i] < lo[f] || ecc[i] >= hi[f]) continue;
            for (k = 0; k < 3; ++k) {
                double d = srgb(chk[3 * i + k]) - srgb(ref[3 * i + k]);
                se += d * d / (1.0 + gs / (double)*check_spp);
            }
            cnt += 3;
        }
        v = cnt ? se / (double)cnt : NAN;
        fl[f] = cnt ? (v > 0.0 ? 10.0 * log10(1.0 / v) : 99.0) : NAN;
    }
    free(chk);
}

/* --denoise: only the _dn rows (and their undenoised twins in pt_denoise.csv), pt_flicker.csv
   and pt_ref_floor.csv; floor_only (--ref-floor): only pt_ref_floor.csv */
static void denoise_only(const char *out_path, uint32_t W, uint32_t H, uint32_t gt_spp, int quick, int threads, int floor_only)
{
    char spath[1024], fpath[1024], rpath[1024];
    const char *sl = strrchr(out_path, '/');
    FILE *csv = NULL, *side = NULL, *fc = NULL, *rf;
    int sc, gi;
    snprintf(spath, sizeof spath, "%.*spt_denoise.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
    snprintf(fpath, sizeof fpath, "%.*spt_flicker.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
    snprintf(rpath, sizeof rpath, "%.*spt_ref_floor.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
    rf = fopen(rpath, "w");
    if (!rf) { fprintf(stderr, "cannot write %s\n", rpath); return; }
    fprintf(rf, "scene,gaze,gt_spp,gt_fovea_spp,check_spp,floor_f1,floor_f2,floor_f3,floor_f4,floor_all\n");
    if (!floor_only) {
        csv = fopen(out_path, "w");
        side = fopen(spath, "w");
        fc = fopen(fpath, "w");
        if (!csv || !side || !fc) { fprintf(stderr, "cannot write %s / %s / %s\n", out_path, spath, fpath); return; }
    }
    if (floor_only) goto scenes;
    fprintf(csv, "scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,mode,rays,camera_rays,speedup,budget_time_ms,spp_fovea\n");
    fprintf(side, "scene,method,gaze,budget,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,flip,flip_f1,time_ms,dn_ms\n");
    fprintf(fc, "scene,method,flicker_static,flicker_moving,psnr_f1_static,psnr_all_static\n");
scenes:
    for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
        pt_scene S;
        size_t np = (size_t)W * H;
        float *ref, *img, *ecc;
        if (quick && sc != PT_SCENE_CORNELL && sc != PT_SCENE_CUBES) continue;
        if (g_dn_scene >= 0 && sc != g_dn_scene) continue;
        if (pt_scene_make(&S, sc) != 0) continue;
        ref = (float *)malloc(np * 12u); img = (float *)malloc(np * 12u); ecc = (float *)malloc(np * 4u);
        S.cam.width = W; S.cam.height = H;
        for (gi = 0; gi < 2; ++gi) {
            fov_gaze g;
            fovpt_config c;
            fovpt_stats st;
            double t_u4;
            g = bench_gaze(&S, gi, ecc);
            ground_truth(&S, g, gt_spp, ecc, ref, threads);
            {
                double fl[5];
                uint32_t cs, gf = g_gt_fovea_spp > gt_spp ? g_gt_fovea_spp : gt_spp;
                ref_floor(&S, g, gt_spp, ref, ecc, threads, &cs, fl);
                fprintf(rf, "%s,%s,%u,%u,%u,%.2f,%.2f,%.2f,%.2f,%.2f\n", pt_scene_names[sc], gi ? "corner" : "centre", gt_spp, gf, cs, fl[0],
                        fl[1], fl[2], fl[3], fl[4]);
                fflush(rf);
                printf("%s %s: the reference's own noise (%u spp, fovea %u), floor f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f dB (check %u spp)\n",
                       pt_scene_names[sc], gi ? "corner" : "centre", gt_spp, gf, fl[0], fl[1], fl[2], fl[3], fl[4], cs);
                if (floor_only) continue;
            }
            method_cfg(&c, 0);
            t_u4 = render(&S, &c, g, img, &st, 1);
            printf("%s %s (uniform4 %.1f ms):\n", pt_scene_names[sc], gi ? "corner" : "centre", t_u4);
            dn_rows(csv, side, &S, pt_scene_names[sc], gi ? "corner" : "centre", g, ref, ecc, t_u4);
            if (!gi) flicker_rows(fc, &S, pt_scene_names[sc], g, ecc, ref);
        }
        pt_scene_free(&S);
        free(ref); free(img); free(ecc);
    }
    fclose(rf);
    if (floor_only) { printf("wrote %s\n", rpath); return; }
    fclose(csv); fclose(side); fclose(fc);
    printf("wrote %s, %s, %s, %s\n", out_path, spath, fpath, rpath);
}

/* --robust: rows <method>_rb (fovpt.h ROBUST PIXEL ESTIMATE, cfg.robust = RB_GROUPS) beside
   their plain twins of the same run, every scene (or --scene N), gaze at the centre and near a
   corner: uniform4 and layers, layers_diam at their default budgets; layers, layers_fovea,
   layers_diam, layers_diam_fovea at eqtime_uniform4 (uniform4's time, plain, in the same run;
   each its own pilot). FILE (pt.csv's columns) gets the _rb rows; pt_robust.csv beside it
   (scene, method, gaze, budget, psnr_f1..f4, psnr_all, flip, flip_f1, time_ms, spp_fovea)
   both. The ground truth is the plain mean (unbiased), as for every row. */
#define RB_GROUPS 4u
static void rb_side_header(FILE *side)
{
    fprintf(side, "scene,method,gaze,budget,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,flip,flip_f1,time_ms,spp_fovea\n");
}
/* the _rb rows of one scene and gaze; t_u4 = uniform4's (plain) time in the same run */
static int g_variant; /* rb_rows' variant: 0 cfg.robust (_rb), 1 cfg.mirror_nee (_mn) */
static void variant_set(int on)
{
    if (g_variant) g_mn = on ? 1u : 0u;
    else g_rb = on ? RB_GROUPS : 0u;
}
static void rb_rows(FILE *csv, FILE *side, pt_scene *S, const char *nm, const char *gz, fov_gaze g, const float *ref, const float *ecc,
                    double t_u4)
{
    const char *suf = g_variant ? "_mn" : "_rb";
    uint32_t W = S->cam.width, H = S->cam.height;
    size_t np = (size_t)W * H;
    float *img = (float *)malloc(np * 12u);
    fovpt_config c;
    fovpt_stats st, st_m[4][2];
    double t_m[4][2], f1_u4 = NAN;
    int m, d, fov_only;
    for (m = 0; m <= 3; ++m) { /* default budgets: uniform4, (uniform1 skipped), layers, layers_diam */
        if (m == 1) continue;
        for (d = 0; d < 2; ++d) {
            double ps[5], fl, fl1, t;
            char mname[64];
            method_cfg(&c, m);
            variant_set(d);
            t = render(S, &c, g, img, &st, 1);
            variant_set(0);
            psnr_fields(img, ref, ecc, np, ps);
            flip_of(img, ref, ecc, W, H, S->cam.fov_y_deg, g, &fl, &fl1);
            snprintf(mname, sizeof mname, "%s%s", names[m], d ? suf : "");
            if (d) row(csv, nm, mname, gz, "default", &st, t, ps, 0, t_u4, -1.0, fovea_spp(&c));
            fprintf(side, "%s,%s,%s,default,%.2f,%.2f,%.2f,%.2f,%.2f,%.4f,%.4f,%.2f,%u\n", nm, mname, gz, ps[0], ps[1], ps[2], ps[3],
                    ps[4], fl, fl1, t, fovea_spp(&c));
            t_m[m][d] = t;
            st_m[m][d] = st;
            if (m == 0 && !d) f1_u4 = ps[0];
            printf("  %-22s %8.1f ms PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f FLIP %.4f (f1 %.4f)\n", mname, t, ps[0], ps[1], ps[2],
                   ps[3], ps[4], fl, fl1);
        }
    }
    for (m = 2; m <= 3; ++m)
        for (fov_only = 0; fov_only < 2; ++fov_only)
            for (d = 0; d < 2; ++d) {
                double ps[5], fl, fl1, t;
                char mname[64];
                variant_set(d);
                t = eqtime_render(S, m, fov_only, t_u4, t_m[m][d], &st_m[m][d], g, img, &c, &st);
                variant_set(0);
                psnr_fields(img, ref, ecc, np, ps);
                flip_of(img, ref, ecc, W, H, S->cam.fov_y_deg, g, &fl, &fl1);
                snprintf(mname, sizeof mname, "%s%s%s", names[m], fov_only ? "_fovea" : "", d ? suf : "");
                if (d) row(csv, nm, mname, gz, "eqtime_uniform4", &st, t, ps, 0, t_u4, t_u4, fovea_spp(&c));
                fprintf(side, "%s,%s,%s,eqtime_uniform4,%.2f,%.2f,%.2f,%.2f,%.2f,%.4f,%.4f,%.2f,%u\n", nm, mname, gz, ps[0], ps[1],
                        ps[2], ps[3], ps[4], fl, fl1, t, fovea_spp(&c));
                printf("  %-22s at uniform4's time (%.1f ms): %8.1f ms, fovea spp %u, PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f"
                       " FLIP %.4f (uniform4 f1 %.2f: %+.2f dB)\n", mname, t_u4, t, fovea_spp(&c), ps[0], ps[1], ps[2], ps[3], ps[4], fl,
                       f1_u4, ps[0] - f1_u4);
            }
    fflush(csv);
    fflush(side);
    free(img);
}
static void robust_only(const char *out_path, uint32_t W, uint32_t H, uint32_t gt_spp, int threads)
{
    char spath[1024];
    const char *sl = strrchr(out_path, '/');
    FILE *csv = fopen(out_path, "w"), *side;
    int sc, gi;
    snprintf(spath, sizeof spath, "%.*s%s", sl ? (int)(sl - out_path + 1) : 0, out_path,
             g_variant ? "pt_mirror_nee.csv" : "pt_robust.csv");
    side = fopen(spath, "w");
    if (!csv || !side) { fprintf(stderr, "cannot write %s / %s\n", out_path, spath); return; }
    fprintf(csv, "scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,mode,rays,camera_rays,speedup,budget_time_ms,spp_fovea\n");
    rb_side_header(side);
    for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
        pt_scene S;
        size_t np = (size_t)W * H;
        float *ref, *img, *ecc;
        if (g_dn_scene >= 0 && sc != g_dn_scene) continue;
        if (pt_scene_make(&S, sc) != 0) continue;
        ref = (float *)malloc(np * 12u); img = (float *)malloc(np * 12u); ecc = (float *)malloc(np * 4u);
        S.cam.width = W; S.cam.height = H;
        for (gi = 0; gi < 2; ++gi) {
            fov_gaze g;
            fovpt_config c;
            fovpt_stats st;
            double t_u4;
            g = bench_gaze(&S, gi, ecc);
            g_mn = g_variant ? 1u : 0u; /* --mirror-nee: the ground truth with it (the same mean, less noise) */
            ground_truth(&S, g, gt_spp, ecc, ref, threads);
            g_mn = 0;
            method_cfg(&c, 0);
            t_u4 = render(&S, &c, g, img, &st, 1);
            printf("%s %s (uniform4 %.1f ms):\n", pt_scene_names[sc], gi ? "corner" : "centre", t_u4);
            rb_rows(csv, side, &S, pt_scene_names[sc], gi ? "corner" : "centre", g, ref, ecc, t_u4);
        }
        pt_scene_free(&S);
        free(ref); free(img); free(ecc);
    }
    fclose(csv); fclose(side);
    printf("wrote %s, %s\n", out_path, spath);
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: bench_pt [options]\n"
          "every fovpt method on the code-written scenes, gaze at the centre and near a corner\n"
          "  --quick             fewer scenes\n"
          "  --full              640x480, ground truth 1024 spp\n"
          "  --throughput        only the fovpt / Embree ray-rate rows\n"
          "  --temporal          only pt_temporal.csv, written beside FILE\n"
          "  --fovea-spp         prints how the Cornell box's fovea error falls with spp\n"
          "  --lp                only the lp_ rows (fovlp + fovpt) and the rows they sit beside\n"
          "                      (uniform4, layers, layers_diam, zones, selective default, the\n"
          "                      eqtime_uniform4 rows), to FILE (default build/pt_lp.csv)\n"
          "  --denoise           only the denoised (_dn) rows: FILE (default\n"
          "                      bench/results/pt_dn.csv), pt_denoise.csv, pt_flicker.csv\n"
          "                      and pt_ref_floor.csv (the reference's own noise per field)\n"
          "  --robust            only the cfg.robust (_rb) rows and their plain twins: FILE\n"
          "                      (default bench/results/pt_rb.csv), pt_robust.csv beside it\n"
          "  --mirror-nee        only the cfg.mirror_nee (_mn) rows and their plain twins (as --robust's),\n"
          "                      the ground truth with cfg.mirror_nee: FILE (default\n"
          "                      bench/results/pt_mn.csv), pt_mirror_nee.csv beside it\n"
          "  --ref-floor         only pt_ref_floor.csv beside FILE (default bench/results/)\n"
          "  --scene N           with --denoise / --robust / --mirror-nee / --ref-floor: scene N only (0 cornell .. 4 interior)\n"
          "  --w W, --h H        image size (default 320 x 240)\n"
          "  --gt-spp N          ground truth samples per pixel of the path modes (default 512)\n"
          "  --gt-fovea-spp N    with --denoise / --robust / --mirror-nee / --ref-floor: the fovea's (e < 3.3 degrees)\n"
          "                      ground truth at N spp (default: --gt-spp)\n"
          "  --dn-no-sure        with --denoise: the denoiser without its SURE selection (cfg.no_sure)\n"
          "  --seeds N           with --denoise: the _dn rows' and their twins' PSNR from the mean MSE\n"
          "                      over N seeds (each row's config, calibrated once; default 1)\n"
          "  --threads N         render threads (default 2)\n"
          "  --out FILE          CSV (default bench/results/pt.csv)\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 320, H = 240, gt_spp = 512;
    int full = 0, quick = 0, only_tp = 0, only_temporal = 0, only_lp = 0, only_dn = 0, only_rb = 0, only_floor = 0, out_set = 0,
        threads = 2, i, sc, gi;
    const char *out_path = "bench/results/pt.csv";
    FILE *csv, *dn_side = NULL, *dn_flicker = NULL, *rb_side = NULL;
    double t_start = now_ms();
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[i], "--full")) full = 1;
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--throughput")) only_tp = 1;
        else if (!strcmp(argv[i], "--temporal")) only_temporal = 1;
        else if (!strcmp(argv[i], "--lp")) only_lp = 1;
        else if (!strcmp(argv[i], "--denoise")) only_dn = 1;
        else if (!strcmp(argv[i], "--robust")) only_rb = 1;
        else if (!strcmp(argv[i], "--mirror-nee")) { only_rb = 1; g_variant = 1; }
        else if (!strcmp(argv[i], "--ref-floor")) only_floor = 1;
        else if (!strcmp(argv[i], "--scene") && i + 1 < argc) g_dn_scene = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--fovea-spp")) { fovea_spp_curve(); return 0; }
        else if (!strcmp(argv[i], "--w") && i + 1 < argc) W = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--h") && i + 1 < argc) H = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--gt-spp") && i + 1 < argc) gt_spp = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--gt-fovea-spp") && i + 1 < argc) g_gt_fovea_spp = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--dn-no-sure")) g_dn_no_sure = 1;
        else if (!strcmp(argv[i], "--seeds") && i + 1 < argc) {
            g_dn_seeds = atoi(argv[++i]);
            if (g_dn_seeds < 1 || g_dn_seeds > 1000) { fprintf(stderr, "--seeds must be in [1, 1000]\n"); return 2; }
        }
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) { out_path = argv[++i]; out_set = 1; }
        else { fprintf(stderr, "unknown option %s\n", argv[i]); usage(stderr); return 2; }
    }
    if (only_lp && !out_set) out_path = "build/pt_lp.csv"; /* pt.csv is left alone */
    if (quick) { W = 96; H = 72; gt_spp = 32; }
    if (full) { W = 640; H = 480; gt_spp = 1024; }
    if (only_rb) {
        if (!strcmp(out_path, "bench/results/pt.csv")) out_path = g_variant ? "bench/results/pt_mn.csv" : "bench/results/pt_rb.csv";
        robust_only(out_path, W, H, gt_spp, threads);
        printf("(%.0f s)\n", (now_ms() - t_start) * 1e-3);
        return 0;
    }
    if (only_dn || only_floor) {
        if (!strcmp(out_path, "bench/results/pt.csv")) out_path = "bench/results/pt_dn.csv";
        denoise_only(out_path, W, H, gt_spp, quick, threads, only_floor && !only_dn);
        printf("(%.0f s)\n", (now_ms() - t_start) * 1e-3);
        return 0;
    }
    if (only_temporal) { /* pt_temporal.csv beside --out only */
        char tpath[1024];
        const char *sl = strrchr(out_path, '/');
        snprintf(tpath, sizeof tpath, "%.*spt_temporal.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
        temporal_rows(tpath, W, H, quick, threads);
        printf("wrote %s (%.0f s)\n", tpath, (now_ms() - t_start) * 1e-3);
        return 0;
    }
    csv = fopen(out_path, "w");
    if (!csv) { fprintf(stderr, "cannot write %s\n", out_path); return 1; }
    {
        char p1[1024], p2[1024];
        const char *sl = strrchr(out_path, '/');
        snprintf(p1, sizeof p1, "%.*spt_denoise.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
        snprintf(p2, sizeof p2, "%.*spt_flicker.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
        if (!only_tp && !only_lp) { dn_side = fopen(p1, "w"); dn_flicker = fopen(p2, "w"); }
        snprintf(p1, sizeof p1, "%.*spt_robust.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
        if (!only_tp && !only_lp && (rb_side = fopen(p1, "w")) != NULL) rb_side_header(rb_side);
        if (dn_side) fprintf(dn_side, "scene,method,gaze,budget,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,flip,flip_f1,time_ms,dn_ms\n");
        if (dn_flicker) fprintf(dn_flicker, "scene,method,flicker_static,flicker_moving,psnr_f1_static,psnr_all_static\n");
    }
    fprintf(csv, "scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,mode,rays,camera_rays,speedup,budget_time_ms,spp_fovea\n");
    printf("fovpt benchmark: %ux%u, ground truth %u spp (path) / 64 spp (Whitted), one thread per method\n", W, H, gt_spp);
    for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
        pt_scene S;
        size_t np = (size_t)W * H;
        float *ref_p = (float *)malloc(np * 12u), *ref_w = (float *)malloc(np * 12u), *img = (float *)malloc(np * 12u);
        float *ecc = (float *)malloc(np * 4u);
        if ((quick && sc != PT_SCENE_CORNELL && sc != PT_SCENE_CUBES) || only_tp || only_temporal) continue;
        if (pt_scene_make(&S, sc) != 0) { fprintf(stderr, "scene %s failed\n", pt_scene_names[sc]); return 1; }
        S.cam.width = W; S.cam.height = H;
        for (gi = 0; gi < 2; ++gi) {
            fov_gaze g;
            fovpt_config base = fovpt_config_default(), c;
            fovpt_stats st;
            double t_u4 = 0.0, t, t_m[8], f1_u4 = 0.0;
            fovpt_stats st_m[8];
            const char *nm = pt_scene_names[sc], *gz = gi ? "corner" : "centre";
            uint32_t m;
            uint64_t cam_rays[8];
            g = bench_gaze(&S, gi, ecc);
            c = base; c.spp = gt_spp; c.seed = 777;
            t = render(&S, &c, g, ref_p, &st, threads);
            printf("%-9s %-6s ground truth (path, %u spp): %.0f ms\n", pt_scene_names[sc], gi ? "corner" : "centre", gt_spp, t);
            c = base; c.mode = FOVPT_MODE_WHITTED; c.spp = 64; c.seed = 777;
            render(&S, &c, g, ref_w, &st, threads);
            for (m = 0; m < 8; ++m) {
                double ps[5];
                int whitted = m >= 5;
                if (only_lp && (m == 1 || m == 5 || m == 7)) { t_m[m] = 1.0; continue; }
                method_cfg(&c, (int)m);
                t = render(&S, &c, g, img, &st, 1);
                if (m == 0) t_u4 = t;
                t_m[m] = t;
                st_m[m] = st;
                cam_rays[m] = st.camera_rays;
                psnr_fields(img, whitted ? ref_w : ref_p, ecc, np, ps);
                if (m == 0) f1_u4 = ps[0];
                row(csv, nm, names[m], gz, "default", &st, t, ps, whitted, t_u4, -1.0, fovea_spp(&c));
                printf("  %-12s %9.1f ms %6.2f Mrays/s  PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f  speedup %.2f\n", names[m], t,
                       (double)st.rays / (t * 1e3), ps[0], ps[1], ps[2], ps[3], ps[4], t_u4 / t);
            }
            /* equal ray budget: UNIFORM at the camera-ray count of each foveated method */
            for (m = 2; m < 8 && !only_lp; ++m) {
                double ps[5];
                uint32_t spp = (uint32_t)((double)cam_rays[m] / (double)np + 0.5);
                int whitted = m >= 5;
                char bud[64];
                if (m == 5) continue;
                if (spp < 1) spp = 1;
                method_cfg(&c, whitted ? 5 : 1);
                c.spp = spp;
                t = render(&S, &c, g, img, &st, 1);
                psnr_fields(img, whitted ? ref_w : ref_p, ecc, np, ps);
                snprintf(bud, sizeof bud, "eqrays_%s", names[m]);
                row(csv, nm, "uniform_eq", gz, bud, &st, t, ps, whitted, t_u4, t_m[m], spp);
                printf("  uniform_eq(%s, %u spp) %8.1f ms PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f\n", names[m], spp, t, ps[0], ps[1],
                       ps[2], ps[3], ps[4]);
            }
            /* equal time, 1: each foveated path method gets uniform4's time (samples scaled by
               a timed pilot, the default row, and corrected by the measured times: eqtime_render) */
            for (m = 2; m <= 4; ++m) {
                int fov_only;
                for (fov_only = 0; fov_only < (m == 4 ? 1 : 2); ++fov_only) {
                    double ps[5];
                    char mname[64];
                    t = eqtime_render(&S, (int)m, fov_only, t_u4, t_m[m], &st_m[m], g, img, &c, &st);
                    psnr_fields(img, ref_p, ecc, np, ps);
                    snprintf(mname, sizeof mname, "%s%s", names[m], fov_only ? "_fovea" : "");
                    row(csv, nm, mname, gz, "eqtime_uniform4", &st, t, ps, 0, t_u4, t_u4, fovea_spp(&c));
                    printf("  %-12s at uniform4's time (%.1f ms): %8.1f ms, fovea spp %u, PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f"
                           " (uniform4 f1 %.2f: %+.2f dB)\n", mname, t_u4, t, fovea_spp(&c), ps[0], ps[1], ps[2], ps[3], ps[4], f1_u4, ps[0] - f1_u4);
                }
            }
            /* path tracing in log-polar space (fovlp + fovpt): the lp_ rows */
            lp_rows(csv, &S, nm, gz, g, ref_p, ecc, np, t_u4, f1_u4, img);
            /* equal time, 2: UNIFORM at the spp whose time matches each foveated method's */
            for (m = 2; m < 8 && !only_lp; ++m) {
                double ps[5];
                int whitted = m >= 5;
                double unit = whitted ? t_m[5] : t_m[1];
                uint32_t spp = (uint32_t)(t_m[m] / unit + 0.5);
                char bud[64];
                if (m == 5) continue;
                if (spp < 1) spp = 1;
                method_cfg(&c, whitted ? 5 : 1);
                c.spp = spp;
                t = render(&S, &c, g, img, &st, 1);
                psnr_fields(img, whitted ? ref_w : ref_p, ecc, np, ps);
                snprintf(bud, sizeof bud, "eqtime_%s", names[m]);
                row(csv, nm, "uniform_eqt", gz, bud, &st, t, ps, whitted, t_u4, t_m[m], spp);
                printf("  uniform_eqt(%s, %u spp) %8.1f ms (method %.1f ms) PSNR f1..f4 %6.2f %6.2f %6.2f %6.2f all %6.2f\n", names[m], spp, t,
                       t_m[m], ps[0], ps[1], ps[2], ps[3], ps[4]);
            }
            /* the denoised rows (_dn) and, gaze at the centre, the flicker */
            if (dn_side) dn_rows(csv, dn_side, &S, nm, gz, g, ref_p, ecc, t_u4);
            if (dn_flicker && !gi) flicker_rows(dn_flicker, &S, nm, g, ecc, ref_p);
            /* the robust rows (_rb, cfg.robust) beside their plain twins */
            if (rb_side) rb_rows(csv, rb_side, &S, nm, gz, g, ref_p, ecc, t_u4);
            fflush(csv);
        }
        pt_scene_free(&S);
        free(ref_p); free(ref_w); free(img); free(ecc);
    }
    if (!quick && !only_lp) throughput_rows(csv, out_path, W, H);
    if (!only_tp && !only_lp) {
        char tpath[1024];
        const char *sl = strrchr(out_path, '/');
        snprintf(tpath, sizeof tpath, "%.*spt_temporal.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
        temporal_rows(tpath, W, H, quick, threads);
    }
    fclose(csv);
    if (dn_side) fclose(dn_side);
    if (dn_flicker) fclose(dn_flicker);
    if (rb_side) fclose(rb_side);
    printf("wrote %s (%.0f s)\n", out_path, (now_ms() - t_start) * 1e-3);
    /* plots next to the CSV: pt_<scene>.png, speed-up over uniform4 against fovea PSNR (f1)
       and near-periphery PSNR (f4), every method, both gazes */
    if (!only_tp && !only_lp && system("command -v gnuplot > /dev/null 2>&1") == 0) {
        FILE *gp = popen("gnuplot", "w");
        const char *slash = strrchr(out_path, '/');
        int dirlen = slash ? (int)(slash - out_path + 1) : 0;
        if (gp) {
            for (sc = 0; sc < PT_SCENE_NUM; ++sc) {
                const char *nm = pt_scene_names[sc];
                if (quick && sc != PT_SCENE_CORNELL && sc != PT_SCENE_CUBES) continue;
                fprintf(gp, "set terminal pngcairo size 900,500; set output '%.*spt_%s.png'\n", dirlen, out_path, nm);
                fprintf(gp, "set datafile separator ','; set grid; set key bottom right\n");
                fprintf(gp, "set title '%s: speed-up over uniform 4 spp vs PSNR (%ux%u; default budgets)'\n", nm, W, H);
                fprintf(gp, "set xlabel 'time of uniform4 / time of the method (same run, one thread)'; set ylabel 'PSNR (dB)'\n");
                fprintf(gp, "plot '%s' every ::1 using ((strcol(1) eq '%s' && strcol(4) eq 'default') ? $15 : 1/0):7:(sprintf('%%s %%s', strcol(2), strcol(3))) "
                            "with labels point pt 7 offset 0.5,0.5 font ',7' title 'fovea (f1)', "
                            "'' every ::1 using ((strcol(1) eq '%s' && strcol(4) eq 'default') ? $15 : 1/0):10 with points pt 6 title 'near periphery (f4)'\n",
                        out_path, nm, nm);
            }
            pclose(gp);
            printf("plots next to %s: pt_<scene>.png\n", out_path);
        }
    } else if (!only_tp && !only_lp) {
        printf("gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    return 0;
}
