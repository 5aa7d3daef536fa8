/* bench_pt.c - fovpt benchmark: every method on the code-written scenes (examples/pt_scenes.h),
   gaze at the centre and near the top-left corner; writes bench/results/pt.csv.

   make bench-pt            default run (5 scenes, 320x240, ground truth 512 spp path / 64
                            Whitted; every method and budget; about 10-15 minutes here)
   make bench-pt FULL=1     the same rows at 640x480, ground truth 1024 spp
   ./build/bench_pt [--quick] [--full] [--throughput] [--w W --h H] [--gt-spp N] [--out FILE]
                    [--threads N] [--temporal]
                    (--throughput: only the fovpt / Embree ray-rate rows; --temporal: only
                    pt_temporal.csv, written beside FILE; --fovea-spp: prints how the Cornell
                    box's fovea error falls with spp, see README)

   Columns (the first eleven are the issue's, in order):
     scene,method,gaze,budget,rays_per_s,time_ms,psnr_f1,psnr_f2,psnr_f3,psnr_f4,psnr_all,
     mode,rays,camera_rays,speedup,budget_time_ms,spp_fovea
   - method: uniform4 / uniform1 (the non-foveated renderer at 4 and 1 spp; the regular
     system of Axblad 2020, Sec. 3.1.3, uses 4), layers (Axblad 2020, 6/10/20 deg as radii),
     layers_diam (as diameters), zones (Polychronakis 2025, ch. 4), whitted1 (UNIFORM
     Whitted, 1 spp), selective (Kim et al. 2021), jin (Jin et al. 2009); the papers are
     listed in full at the end of this comment.
   - budget: which budget the row was given.
       default          the method's own settings (the rows above).
       eqrays_<m>       method uniform_eq: UNIFORM at the spp whose camera rays match method
                        <m>'s (equal ray budget).
       eqtime_uniform4  methods layers, layers_diam, zones (all their samples scaled by one
                        factor) and layers_fovea, layers_diam_fovea (only the innermost
                        layer's samples raised): the time of uniform4 in the same run
                        (equal time; calibrated from the default row as a timed pilot,
                        corrected once along the secant when more than 8 % off; the
                        measured time is in time_ms, the target in budget_time_ms).
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
#include "examples/pt_scenes.h"

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
static double render(pt_scene *S, const fovpt_config *cfg, fov_gaze g, float *rgb, fovpt_stats *st, int threads)
{
    size_t n = 0;
    void *mem;
    fovpt_ctx ctx;
    fovpt_output out;
    double t0, t;
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
   nodes, leaf triangles, leaf order; Embree: the device's allocations, vertex and index
   buffers included; tinybvh: its traversal blocks, nodes and triangles). */
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
            /* fovpt: what the traversal reads (W-wide nodes, leaf triangles, leaf order) beside
               the whole scene memory; Embree and tinybvh: the same figure as bytes_per_tri */
            double trav = m == TP_PT ? ((double)tri.num_nodes4 * sizeof(fovpt__node4) + 144.0 * (double)((tri.num_bounded + 3u) / 4u) +
                                        4.0 * tri.num_bounded) / (double)soup.n : bpt[m];
            char lay[64];
            snprintf(lay, sizeof lay, "bvh%u %s", (unsigned)FOVPT_BVH_WIDTH,
                     FOVPT__SIMD == 1 ? (FOVPT_BVH_WIDTH == 8 ? "avx" : "sse") : FOVPT__SIMD == 2 ? "neon" : FOVPT__SIMD == 3 ? "simd128" : "scalar");
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
   t_pilot, sample counts sp), assuming time proportional to samples; when the measured time
   is more than 8 % off, x is corrected once along the secant through the two measurements.
   Returns the measured time; c and st are those of the returned run. */
static double eqtime_render(pt_scene *S, int m, int fov_only, double t_target, double t_pilot, const fovpt_stats *sp, fov_gaze g,
                            float *img, fovpt_config *c, fovpt_stats *st)
{
    fovpt_config base;
    double x0, t0 = t_pilot, x1, t1 = t_pilot;
    uint32_t l, n;
    int it;
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
    for (it = 0; it < 2; ++it) {
        double xn;
        *c = base;
        if (m == 4) c->spp = spp_of(4.0 * x1);
        else if (fov_only) c->layers.layer[n - 1u].spp = spp_of(x1);
        else
            for (l = 0; l < n; ++l) c->layers.layer[l].spp = spp_of((double)base.layers.layer[l].spp * x1);
        t1 = render(S, c, g, img, st, 1);
        if (fabs(t1 / t_target - 1.0) <= 0.08 || it == 1) break;
        xn = (t1 > t0 && x1 != x0) ? x1 + (t_target - t1) * (x1 - x0) / (t1 - t0) : x1 * t_target / t1;
        x0 = x1; t0 = t1; x1 = xn;
    }
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
          "  --w W, --h H        image size (default 320 x 240)\n"
          "  --gt-spp N          ground truth samples per pixel of the path modes (default 512)\n"
          "  --threads N         render threads (default 2)\n"
          "  --out FILE          CSV (default bench/results/pt.csv)\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 320, H = 240, gt_spp = 512;
    int full = 0, quick = 0, only_tp = 0, only_temporal = 0, threads = 2, i, sc, gi;
    const char *out_path = "bench/results/pt.csv";
    FILE *csv;
    double t_start = now_ms();
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[i], "--full")) full = 1;
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--throughput")) only_tp = 1;
        else if (!strcmp(argv[i], "--temporal")) only_temporal = 1;
        else if (!strcmp(argv[i], "--fovea-spp")) { fovea_spp_curve(); return 0; }
        else if (!strcmp(argv[i], "--w") && i + 1 < argc) W = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--h") && i + 1 < argc) H = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--gt-spp") && i + 1 < argc) gt_spp = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) out_path = argv[++i];
        else { fprintf(stderr, "unknown option %s\n", argv[i]); usage(stderr); return 2; }
    }
    if (quick) { W = 96; H = 72; gt_spp = 32; }
    if (full) { W = 640; H = 480; gt_spp = 1024; }
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
            fov_ecc_model em;
            double t_u4 = 0.0, t, t_m[8], f1_u4 = 0.0;
            fovpt_stats st_m[8];
            const char *nm = pt_scene_names[sc], *gz = gi ? "corner" : "centre";
            uint32_t x, y, m;
            uint64_t cam_rays[8];
            g.x = gi ? 0.08f * (float)W : 0.5f * (float)W;
            g.y = gi ? 0.08f * (float)H : 0.5f * (float)H;
            fovpt_ecc_init(&em, NULL, S.cam.fov_y_deg, W, H, g);
            for (y = 0; y < H; ++y)
                for (x = 0; x < W; ++x) ecc[(size_t)y * W + x] = fovpt_ecc_deg(&em, (float)x + 0.5f, (float)y + 0.5f);
            c = base; c.spp = gt_spp; c.seed = 777;
            t = render(&S, &c, g, ref_p, &st, threads);
            printf("%-9s %-6s ground truth (path, %u spp): %.0f ms\n", pt_scene_names[sc], gi ? "corner" : "centre", gt_spp, t);
            c = base; c.mode = FOVPT_MODE_WHITTED; c.spp = 64; c.seed = 777;
            render(&S, &c, g, ref_w, &st, threads);
            for (m = 0; m < 8; ++m) {
                double ps[5];
                int whitted = m >= 5;
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
            for (m = 2; m < 8; ++m) {
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
               a timed pilot, the default row, and corrected once by the measured time) */
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
            /* equal time, 2: UNIFORM at the spp whose time matches each foveated method's */
            for (m = 2; m < 8; ++m) {
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
            fflush(csv);
        }
        pt_scene_free(&S);
        free(ref_p); free(ref_w); free(img); free(ecc);
    }
    if (!quick) throughput_rows(csv, out_path, W, H);
    if (!only_tp) {
        char tpath[1024];
        const char *sl = strrchr(out_path, '/');
        snprintf(tpath, sizeof tpath, "%.*spt_temporal.csv", sl ? (int)(sl - out_path + 1) : 0, out_path);
        temporal_rows(tpath, W, H, quick, threads);
    }
    fclose(csv);
    printf("wrote %s (%.0f s)\n", out_path, (now_ms() - t_start) * 1e-3);
    /* plots next to the CSV: pt_<scene>.png, speed-up over uniform4 against fovea PSNR (f1)
       and near-periphery PSNR (f4), every method, both gazes */
    if (!only_tp && system("command -v gnuplot > /dev/null 2>&1") == 0) {
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
    } else if (!only_tp) {
        printf("gnuplot not installed: no plots (apt-get install gnuplot-nox)\n");
    }
    return 0;
}
