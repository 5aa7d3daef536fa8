/* pt_rays.c - fovpt closest-hit throughput on the same rays natively and in WebAssembly
   (make bench-pt-wasm; bench/wasm/pt_rays.mjs runs the builds interleaved and prints the table).
   One source, built three ways into build/ptw/:
     rays_native, rays_native_scalar  gcc -O2 (SSE2 traversal; -DFOVPT_NO_SIMD), libm; the
                                      program prints "camera_ms bounce_ms checksums" for one
                                      traversal pass of each ray set after a warm-up pass
     rays.wasm, rays.simd.wasm        clang --target=wasm32 -ffreestanding -nostdlib, the
                                      browser demo's flags (examples/web/build.sh) and
                                      FOV_NO_LIBM; without / with -msimd128 (fovpt's SIMD128
                                      traversal); exports rays_setup, rays_trace, rays_count
   The scene: a 224 x 224 height field (100 352 triangles, like bench_pt's mesh100k, with
   polynomial instead of sine bumps so that no libm is needed: every build makes the same
   bits). Rays: every pixel-centre ray of a W x H pinhole camera (camera), and one bounce ray
   per camera hit from the hit point, offset 1e-3 along the normal, in a hashed direction of
   the normal's hemisphere (bounce). Only +, -, *, / and a correctly rounded square root make
   them, so every build traces the same rays; the checksums (hit count, sum of t) show it.
   Not part of the library. */
#if defined(WEB_NATIVE) && !defined(_POSIX_C_SOURCE)
#define _POSIX_C_SOURCE 200809L
#endif
#include <stddef.h>
#include <stdint.h>
#ifndef WEB_NATIVE
#define FOV_NO_LIBM
#endif
#define FOV_ASSERT(c) ((void)0)
#include "../../examples/web/web_rt.h"
#define FOVPT_IMPLEMENTATION
#include "../../fovpt.h"

#define RAYS_N 224u

static struct {
    fovpt_scene scene;
    float *org, *dir;        /* camera rays, then bounce rays */
    uint32_t n_cam, n_all;
    double t_sum[2];
    uint32_t hits[2];
} R;

static float rays_floor(float x)
{
    float t = (float)(int32_t)x;
    return t > x ? t - 1.0f : t;
}
/* a smooth-ish periodic bump in [-1, 1] of period 1 (two parabolas) */
static float rays_wave(float t)
{
    float f = t - rays_floor(t);
    return f < 0.5f ? 16.0f * f * (0.5f - f) : -16.0f * (f - 0.5f) * (1.0f - f);
}
static float rays_norm(float v[3])
{
    float l = __builtin_sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l; v[1] /= l; v[2] /= l;
    return l;
}
static uint32_t rays_hash(uint32_t x)
{
    x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
    return x;
}
static float rays_u(uint32_t h) { return (float)(h >> 8) * (2.0f / 16777216.0f) - 1.0f; } /* [-1, 1) */

/* builds the terrain and the w x h camera rays and their bounce rays; 0 or a fov_result */
WEB_EXPORT(rays_setup) int rays_setup(uint32_t w, uint32_t h);
int rays_setup(uint32_t w, uint32_t h)
{
    const uint32_t n = RAYS_N, nv = (RAYS_N + 1u) * (RAYS_N + 1u);
    float *pos, fwd[3], right[3], up[3], cam[3] = { 0.0f, 2.5f, -9.0f };
    const float tan_half = 0.52056705f; /* tan(27.5 degrees): a 55 degree vertical field */
    uint32_t *idx, i, j, k = 0, x, y, nr;
    fovpt_mesh mesh;
    fovpt_material mat;
    fovpt_scene_desc d;
    size_t bytes;
    void *mem;
    fov_result r;
    web_heap_reset();
    if (w == 0 || h == 0 || w > 2048 || h > 2048) return FOV_ERR_INVALID_ARG;
    pos = (float *)web_alloc(sizeof(float) * 3u * nv);
    idx = (uint32_t *)web_alloc(sizeof(uint32_t) * 6u * n * n);
    R.org = (float *)web_alloc(sizeof(float) * 6u * w * h);
    R.dir = (float *)web_alloc(sizeof(float) * 6u * w * h);
    if (!pos || !idx || !R.org || !R.dir) return FOV_ERR_TOO_SMALL;
    for (j = 0; j <= n; ++j)
        for (i = 0; i <= n; ++i) {
            float px = -10.0f + 20.0f * (float)i / (float)n, pz = -10.0f + 20.0f * (float)j / (float)n;
            float *p = pos + 3u * (j * (n + 1u) + i);
            p[0] = px; p[2] = pz;
            p[1] = 0.6f * rays_wave(0.143f * px) * rays_wave(0.111f * pz + 0.25f) +
                   0.25f * rays_wave(0.43f * px + 0.207f * pz) +
                   0.08f * rays_wave(1.43f * px) * rays_wave(1.27f * pz);
        }
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            uint32_t a = j * (n + 1u) + i, b = a + 1u, c = a + n + 1u, e = c + 1u;
            idx[k++] = a; idx[k++] = c; idx[k++] = b;
            idx[k++] = b; idx[k++] = c; idx[k++] = e;
        }
    fovpt_material_init(&mat);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos; mesh.num_vertices = nv; mesh.indices = idx;
    mesh.num_triangles = 2u * n * n; mesh.material = 0;
    fovpt_scene_desc_init(&d);
    d.meshes = &mesh; d.num_meshes = 1; d.materials = &mat; d.num_materials = 1;
    if ((r = fovpt_scene_size(&d, &bytes)) != FOV_OK) return r;
    if (!(mem = web_alloc(bytes))) return FOV_ERR_TOO_SMALL;
    if ((r = fovpt_scene_build(&R.scene, &d, mem, bytes)) != FOV_OK) return r;
    /* camera at (0, 2.5, -9) looking at the origin, y up */
    fwd[0] = -cam[0]; fwd[1] = -cam[1]; fwd[2] = -cam[2];
    rays_norm(fwd);
    right[0] = fwd[2]; right[1] = 0.0f; right[2] = -fwd[0]; /* (0, 1, 0) x fwd */
    rays_norm(right);
    up[0] = fwd[1] * right[2] - fwd[2] * right[1];
    up[1] = fwd[2] * right[0] - fwd[0] * right[2];
    up[2] = fwd[0] * right[1] - fwd[1] * right[0];
    nr = 0;
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x, ++nr) {
            float sx = (2.0f * ((float)x + 0.5f) / (float)w - 1.0f) * tan_half * (float)w / (float)h;
            float sy = (1.0f - 2.0f * ((float)y + 0.5f) / (float)h) * tan_half;
            float *o = R.org + 3u * nr, *v = R.dir + 3u * nr;
            for (k = 0; k < 3; ++k) { o[k] = cam[k]; v[k] = fwd[k] + sx * right[k] + sy * up[k]; }
            rays_norm(v);
        }
    R.n_cam = nr;
    for (i = 0; i < R.n_cam; ++i) {
        fovpt_hit ht;
        if (fovpt_intersect(&R.scene, R.org + 3u * i, R.dir + 3u * i, 0.0f, 1e30f, &ht)) {
            const float *v = R.dir + 3u * i;
            float nn[3], b[3], s = ht.n[0] * v[0] + ht.n[1] * v[1] + ht.n[2] * v[2] > 0.0f ? -1.0f : 1.0f;
            for (k = 0; k < 3; ++k) nn[k] = s * ht.n[k];
            for (k = 0; k < 3; ++k) b[k] = rays_u(rays_hash(3u * i + k + 1u));
            b[1] += 1e-3f;                                  /* never the zero vector */
            s = b[0] * nn[0] + b[1] * nn[1] + b[2] * nn[2] < 0.0f ? -1.0f : 1.0f;
            for (k = 0; k < 3; ++k) {
                R.org[3u * nr + k] = ht.p[k] + 1e-3f * nn[k];
                R.dir[3u * nr + k] = s * b[k] + 0.25f * nn[k];
            }
            rays_norm(R.dir + 3u * nr);
            nr++;
        }
    }
    R.n_all = nr;
    return FOV_OK;
}

/* traces the camera (which 0) or the bounce rays (1) once; returns the number of hits */
WEB_EXPORT(rays_trace) int rays_trace(uint32_t which);
int rays_trace(uint32_t which)
{
    uint32_t i0 = which ? R.n_cam : 0u, i1 = which ? R.n_all : R.n_cam, i, hits = 0;
    double ts = 0.0;
    for (i = i0; i < i1; ++i) {
        fovpt_hit ht;
        if (fovpt_intersect(&R.scene, R.org + 3u * i, R.dir + 3u * i, 0.0f, 1e30f, &ht)) {
            hits++;
            ts += (double)ht.t;
        }
    }
    R.hits[which ? 1 : 0] = hits;
    R.t_sum[which ? 1 : 0] = ts;
    return (int)hits;
}
/* the number of camera (which 0) or bounce rays (1) */
WEB_EXPORT(rays_count) int rays_count(uint32_t which);
int rays_count(uint32_t which) { return (int)(which ? R.n_all - R.n_cam : R.n_cam); }
/* the sum of the hit distances of the last rays_trace(which) */
WEB_EXPORT(rays_tsum) double rays_tsum(uint32_t which);
double rays_tsum(uint32_t which) { return R.t_sum[which ? 1 : 0]; }

#ifdef WEB_NATIVE
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double rays_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts); /* thread CPU time: other load on the machine counts less */
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
/* rays_native W H [PASSES]: prints "camera_ms bounce_ms n_cam n_bounce hits_cam hits_bounce
   tsum_cam tsum_bounce" (the fastest of PASSES, default 1, after a warm-up pass) */
int main(int argc, char **argv)
{
    uint32_t w = argc > 1 ? (uint32_t)atoi(argv[1]) : 320u, h = argc > 2 ? (uint32_t)atoi(argv[2]) : 240u;
    int passes = argc > 3 ? atoi(argv[3]) : 1, p, which;
    double best[2] = { 1e300, 1e300 };
    int r = rays_setup(w, h);
    if (r != FOV_OK) { fprintf(stderr, "rays_setup: %d\n", r); return 1; }
    for (which = 0; which < 2; ++which) rays_trace((uint32_t)which); /* warm-up */
    for (p = 0; p < passes; ++p)
        for (which = 0; which < 2; ++which) {
            double t0 = rays_now_ms(), t;
            rays_trace((uint32_t)which);
            t = rays_now_ms() - t0;
            if (t < best[which]) best[which] = t;
        }
    printf("%.4f %.4f %d %d %u %u %.17g %.17g\n", best[0], best[1], rays_count(0), rays_count(1),
           R.hits[0], R.hits[1], R.t_sum[0], R.t_sum[1]);
    return 0;
}
#endif
