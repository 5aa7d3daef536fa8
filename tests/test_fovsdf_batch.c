/* test_fovsdf_batch.c - the batch distance interface and the batch evaluator of fovsdf.h:
   fovsdf_program_eval_batch gives every point exactly fovsdf_program_eval's distance,
   material and counts (bit for bit) for the six built-in scenes and random scenes, at random
   batch sizes, thresholds and inflations; fovsdf_distance_batch checks its arguments and uses
   a scene's batch callback (or its per-point ones). */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementation compiled once per build
   (tests/common/fov_impl_sdf.c) instead of compiling it in this file; the private functions
   tested here are called through the test hook's wrappers (tests/common/fov_priv_sdf.h),
   which are compiled in this file when it holds the implementation */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fov_priv_sdf.h"
#include "fovcheck.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t g_rng = 12345u;
static const fov_gaze g_gaze = { 0.5f, 0.5f };
static float rnd(void) /* [0, 1) */
{
    g_rng = g_rng * 1664525u + 1013904223u;
    return (float)(g_rng >> 8) * (1.0f / 16777216.0f);
}
static float rr(float a, float b) { return a + (b - a) * rnd(); }
static uint32_t bits(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

#define NPT 3000
static float g_x[NPT], g_y[NPT], g_z[NPT], g_e[NPT], g_d[NPT], g_d2[NPT];
static int32_t g_m[NPT];

/* Points: along the scene camera's rays at random t (near and on surfaces), and in a box. */
static void make_points(const fovsdf_builtin *bi, float ext)
{
    fovsdf_ctx c;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_camera cam = bi->camera;
    uint32_t i;
    cam.width = 64; cam.height = 36;
    if (fovsdf_init(&c, &cfg, &bi->scene, &cam, g_gaze, 0, 0) != FOV_OK) {
        check(0, "init", "fovsdf_init failed");
        return;
    }
    for (i = 0; i < NPT; ++i) {
        if (i % 3 != 2) {
            float ro[3], rd[3], t = rr(0.0f, 1.0f);
            fovsdf_camera_ray(&c, rr(0.0f, 64.0f), rr(0.0f, 36.0f), ro, rd);
            t = t * t * c.t_max; /* denser near the camera */
            if (i % 3 == 1) { /* march to the surface and step around it */
                fovsdf_hit h;
                if (fovsdf_trace(&c, ro, rd, 0.0f, &h, 0) == FOV_OK && h.kind == FOVSDF_HIT)
                    t = h.t + rr(-0.02f, 0.02f);
            }
            g_x[i] = ro[0] + rd[0] * t; g_y[i] = ro[1] + rd[1] * t; g_z[i] = ro[2] + rd[2] * t;
        } else {
            g_x[i] = rr(-ext, ext); g_y[i] = rr(-ext, ext); g_z[i] = rr(-ext, ext);
        }
        g_e[i] = (i % 5 == 0) ? 0.0f : rr(0.0f, 0.05f);
    }
}

/* Compare batch against per-point over all points for one program; returns mismatches. */
static int compare(const char *name, const fovsdf_program *prog, float inflate)
{
    uint32_t i, k, bad_d = 0, bad_m = 0, first = 0xffffffffu;
    uint64_t pp = 0, ps = 0, bp = 0, bs = 0, bp2 = 0, bs2 = 0;
    uint32_t rng0 = g_rng, bad_d2 = 0;
    for (i = 0; i < NPT; ++i) { g_d[i] = -123.0f; g_m[i] = -77; }
    for (k = 0; k < NPT;) {
        fovsdf_batch b;
        uint32_t n = 1u + (uint32_t)(rnd() * 97.0f);
        if (n > NPT - k) n = NPT - k;
        memset(&b, 0, sizeof b);
        b.n = n; b.x = g_x + k; b.y = g_y + k; b.z = g_z + k; b.eps = g_e + k;
        b.inflate = inflate; b.d = g_d + k; b.material = g_m + k;
        fovsdf_program_eval_batch(&b, (void *)(uintptr_t)prog);
        bp += b.prims; bs += b.prims_skipped;
        k += n;
    }
    /* the same batches again without materials (the evaluator then tracks none) */
    g_rng = rng0;
    for (i = 0; i < NPT; ++i) g_d2[i] = -123.0f;
    for (k = 0; k < NPT;) {
        fovsdf_batch b;
        uint32_t n = 1u + (uint32_t)(rnd() * 97.0f);
        if (n > NPT - k) n = NPT - k;
        memset(&b, 0, sizeof b);
        b.n = n; b.x = g_x + k; b.y = g_y + k; b.z = g_z + k; b.eps = g_e + k;
        b.inflate = inflate; b.d = g_d2 + k; b.material = 0;
        fovsdf_program_eval_batch(&b, (void *)(uintptr_t)prog);
        bp2 += b.prims; bs2 += b.prims_skipped;
        k += n;
    }
    for (i = 0; i < NPT; ++i) {
        fovsdf_query q;
        float p[3], d;
        memset(&q, 0, sizeof q);
        q.inflate = inflate; q.eps = g_e[i]; q.want_material = 1;
        p[0] = g_x[i]; p[1] = g_y[i]; p[2] = g_z[i];
        d = fovsdf_program_eval(p, &q, (void *)(uintptr_t)prog);
        pp += q.prims; ps += q.prims_skipped;
        if (bits(d) != bits(g_d[i])) { if (first == 0xffffffffu) first = i; ++bad_d; }
        if (q.material != g_m[i]) ++bad_m;
        if (bits(d) != bits(g_d2[i])) ++bad_d2;
    }
    check(bad_d == 0, fovcheck_name("%s_inflate%g_distance_bits", name, (double)inflate),
          "%u of %d differ (first %u)", bad_d, NPT, first);
    check(bad_m == 0, fovcheck_name("%s_inflate%g_material", name, (double)inflate),
          "%u of %d differ", bad_m, NPT);
    check(pp == bp && ps == bs, fovcheck_name("%s_inflate%g_counts", name, (double)inflate),
          "prims %llu vs %llu, skipped %llu vs %llu", (unsigned long long)pp,
          (unsigned long long)bp, (unsigned long long)ps, (unsigned long long)bs);
    check(bad_d2 == 0 && pp == bp2 && ps == bs2,
          fovcheck_name("%s_inflate%g_no_material", name, (double)inflate),
          "%u of %d distances differ; prims %llu vs %llu, skipped %llu vs %llu", bad_d2, NPT,
          (unsigned long long)pp, (unsigned long long)bp2, (unsigned long long)ps,
          (unsigned long long)bs2);
    return (int)(bad_d + bad_m + bad_d2);
}

/* A random tree of every node type. */
static int32_t rtree(fovsdf_builder *b, int depth)
{
    int32_t x;
    if (depth <= 0 || rnd() < 0.25f) {
        float a[3], c[3];
        switch ((int)(rnd() * 12.0f)) {
        case 0: x = fovsdf_sphere(b, rr(0.1f, 1.0f)); break;
        case 1: x = fovsdf_box(b, rr(0.1f, 1.0f), rr(0.1f, 1.0f), rr(0.1f, 1.0f)); break;
        case 2: x = fovsdf_round_box(b, 0.5f, 0.6f, 0.7f, rr(0.0f, 0.4f)); break;
        case 3: x = fovsdf_box_frame(b, 0.6f, 0.5f, 0.4f, rr(0.02f, 0.1f)); break;
        case 4: x = fovsdf_torus(b, rr(0.2f, 0.8f), rr(0.05f, 0.2f)); break;
        case 5:
            a[0] = rr(-1, 1); a[1] = rr(-1, 1); a[2] = rr(-1, 1);
            c[0] = rr(-1, 1); c[1] = rr(-1, 1); c[2] = rr(-1, 1);
            x = fovsdf_capsule(b, a, c, rr(0.05f, 0.3f));
            break;
        case 6: x = fovsdf_cylinder(b, rr(0.1f, 1.0f), rr(0.1f, 0.5f)); break;
        case 7: x = fovsdf_cone(b, rr(0.2f, 1.0f), rr(0.0f, 0.5f), rr(0.1f, 0.5f)); break;
        case 8: x = fovsdf_plane(b, rr(-1, 1), 1.0f, rr(-1, 1), rr(0.5f, 2.0f)); break;
        case 9: x = fovsdf_menger(b, rr(0.3f, 1.0f), 1 + (int32_t)(rnd() * 3.0f)); break;
        case 10: x = fovsdf_mandelbulb(b, 8.0f, 4); break;
        default: x = fovsdf_terrain(b, rr(0.1f, 0.5f), rr(0.5f, 2.0f), 4); break;
        }
        b->material = (int32_t)(rnd() * 7.0f);
        return x;
    }
    if (rnd() < 0.6f) {
        int32_t y = rtree(b, depth - 1);
        x = rtree(b, depth - 1);
        switch ((int)(rnd() * 6.0f)) {
        case 0: return fovsdf_union(b, x, y);
        case 1: return fovsdf_subtract(b, x, y);
        case 2: return fovsdf_intersect(b, x, y);
        case 3: return fovsdf_smooth_union(b, x, y, rr(0.05f, 0.5f));
        case 4: return fovsdf_smooth_subtract(b, x, y, rr(0.05f, 0.5f));
        default: return fovsdf_smooth_intersect(b, x, y, rr(0.05f, 0.5f));
        }
    }
    x = rtree(b, depth - 1);
    switch ((int)(rnd() * 7.0f)) {
    case 0: return fovsdf_translate(b, x, rr(-2, 2), rr(-2, 2), rr(-2, 2));
    case 1: return fovsdf_rotate(b, x, rr(-1, 1), rr(-1, 1), 1.0f, rr(-180, 180));
    case 2: return fovsdf_scale(b, x, rr(0.3f, 3.0f));
    case 3: return fovsdf_repeat(b, x, rr(1, 4), 0.0f, rr(1, 4), (int32_t)(rnd() * 3.0f), 0, 0);
    case 4: return fovsdf_mirror(b, x, 1 + (int32_t)(rnd() * 7.0f));
    case 5: return fovsdf_round(b, x, rr(0.0f, 0.1f));
    default: return fovsdf_onion(b, x, rr(0.01f, 0.1f));
    }
}

/* Many small primitives in unions (a bounding hierarchy with partial batches). */
static int32_t cluster(fovsdf_builder *b, int n)
{
    int32_t u = -1;
    int i;
    for (i = 0; i < n; ++i) {
        int32_t s = fovsdf_translate(b, rnd() < 0.5f ? fovsdf_sphere(b, rr(0.05f, 0.3f))
                                                     : fovsdf_box(b, 0.2f, 0.1f, 0.3f),
                                     rr(-4, 4), rr(-1, 1), rr(-4, 4));
        b->material = i % 7;
        u = u < 0 ? s : fovsdf_union(b, u, s);
    }
    return u;
}

static float g_user_scale;
static float pp_dist(const float p[3], fovsdf_query *q, void *user)
{
    (void)user;
    q->material = 3;
    return g_user_scale * (p[0] * p[0] + p[1] - p[2]);
}
static void bt_dist(fovsdf_batch *b, void *user)
{
    uint32_t i;
    (void)user;
    for (i = 0; i < b->n; ++i) {
        if (b->x[i] > 1.5f && b->x[i] < 2.5f) continue; /* unwritten: the library makes it a miss */
        b->d[i] = g_user_scale * (b->x[i] * b->x[i] + b->y[i] - b->z[i]);
        if (b->material) b->material[i] = 4;
    }
    b->prims += b->n;
}

/* The lane floor (repeat, menger) against FOV__FLOOR, bit for bit (NaN: NaN), at the edges
   of its integer conversion (2^23), signed zeros, infinities and random bit patterns.
   Skipped with the math hooks (FOV_SQRTF ... FOV_POWF, all or none: the header then sets
   FOV__HOOKED_MATH and the lane floor is the hook); FOV_SQRTF is what is tested here because
   a build linked with the implementation does not see the header's private macros. */
static void check_vfloor(void)
{
#if !defined(FOV_SQRTF)
    static const float v[] = { 0.0f, -0.0f, 0.25f, -0.25f, 0.5f, -0.5f, 1.0f, -1.0f, 1.5f,
                               -1.5f, 2.0f, -2.0f, 1e-40f, -1e-40f, 8388607.5f, -8388607.5f,
                               8388607.0f, -8388607.0f, 8388608.0f, -8388608.0f, 8388609.0f,
                               -8388609.0f, 16777217.0f, 2147483648.0f, -2147483648.0f,
                               4294967296.0f, -4294967296.0f, 1e30f, -1e30f, FLT_MAX, -FLT_MAX };
    uint32_t i, bad = 0, first = 0, r = 7u;
    for (i = 0; i < 200000u + (uint32_t)(sizeof v / sizeof v[0]); ++i) {
        float x, a, b;
        if (i < sizeof v / sizeof v[0]) {
            x = v[i];
        } else {
            uint32_t u;
            r = r * 1664525u + 1013904223u;
            u = (i & 1u) ? r : (r & 0x8fffffffu) | 0x3f000000u; /* any, or |x| near 0.5..2^24 */
            memcpy(&x, &u, 4);
        }
        a = fovtest_sdf_vfloor(x);
        b = fovtest_floor(x);
        if (bits(a) != bits(b) && !(a != a && b != b)) {
            if (!bad) first = bits(x);
            ++bad;
        }
    }
    {
        float inf = FLT_MAX * 2.0f, nan = inf - inf;
        float a = fovtest_sdf_vfloor(inf), b = fovtest_sdf_vfloor(-inf);
        float c = fovtest_sdf_vfloor(nan);
        if (bits(a) != bits(inf) || bits(b) != bits(-inf) || c == c) ++bad;
    }
    check(bad == 0, "lane_floor_equals_floor", "%u differ (first input bits %08x)", bad, first);
#endif
}

int main(void)
{
    static unsigned char mem[1 << 20];
    uint32_t id;
    int r;
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        fovsdf_builtin bi;
        size_t sz = 0;
        if (fovsdf_builtin_size(id, &sz) != FOV_OK || sz > sizeof mem ||
            fovsdf_builtin_init(id, &bi, mem, sizeof mem) != FOV_OK) {
            check(0, "builtin", "scene %u", id);
            continue;
        }
        make_points(&bi, 30.0f);
        compare(bi.name, bi.program, 1.0f);
        compare(bi.name, bi.program, 1.005f);
        compare(bi.name, bi.program, 0.97f);
        {   /* far points: the repeat's floor beyond 2^23 and float range */
            uint32_t rng0 = g_rng;
            char nm[64];
            snprintf(nm, sizeof nm, "%s_far", bi.name);
            make_points(&bi, 3e7f);
            compare(nm, bi.program, 1.0f);
            snprintf(nm, sizeof nm, "%s_very_far", bi.name);
            make_points(&bi, 1e30f);
            compare(nm, bi.program, 1.0f);
            g_rng = rng0; /* the random scenes below stay the ones they were */
        }
    }
    check_vfloor();
    for (r = 0; r < 40; ++r) {
        static fovsdf_node nodes[512];
        static unsigned char pm[1 << 19];
        fovsdf_builder b;
        fovsdf_program prog;
        int32_t root;
        size_t sz;
        uint32_t i;
        fovsdf_builder_init(&b, nodes, 512);
        root = r % 2 ? rtree(&b, 5) : fovsdf_union(&b, cluster(&b, 20 + r), rtree(&b, 3));
        if (root < 0 || fovsdf_program_size(nodes, b.count, root, &sz) != FOV_OK ||
            sz > sizeof pm || fovsdf_program_build(&prog, nodes, b.count, root, pm, sz) != FOV_OK)
            continue;
        for (i = 0; i < NPT; ++i) {
            float s = (i % 2) ? 6.0f : 1.5f;
            g_x[i] = rr(-s, s); g_y[i] = rr(-s, s); g_z[i] = rr(-s, s);
            g_e[i] = (i % 4 == 0) ? 0.0f : rr(0.0f, 0.3f);
        }
        compare(fovcheck_name("random%d", r), &prog, 1.0f);
        compare(fovcheck_name("random%d", r), &prog, 1.1f);
    }
    for (r = 0; r < 24; ++r) {
        /* the mandelbulb and the terrain alone (their own float kernels, vectorised): random
           parameters, points from 1e-25 to 1e30 in magnitude (the terrain's arguments cross
           the kernels' reduction ranges, 8192 and 1e6, and its 1e30 cutoff within a batch),
           the origin, and inf / NaN coordinates */
        static fovsdf_node nodes[8];
        static unsigned char pm[1 << 12];
        fovsdf_builder b;
        fovsdf_program prog;
        int32_t root;
        size_t sz;
        uint32_t i;
        fovsdf_builder_init(&b, nodes, 8);
        if (r % 2)
            root = fovsdf_mandelbulb(&b, rr(2.0f, 16.0f), 1 + (int32_t)(rnd() * 32.0f));
        else
            root = fovsdf_terrain(&b, rr(0.0f, 3.0f), r % 4 ? rr(0.01f, 2.0f) : rr(2.0f, 60.0f),
                                  1 + (int32_t)(rnd() * 12.0f));
        if (r % 3 == 0) root = fovsdf_scale(&b, root, rr(0.3f, 3.0f));
        if (root < 0 || fovsdf_program_size(nodes, b.count, root, &sz) != FOV_OK ||
            sz > sizeof pm || fovsdf_program_build(&prog, nodes, b.count, root, pm, sz) != FOV_OK) {
            check(0, fovcheck_name("mb_terrain%d_build", r), "root %d", (int)root);
            continue;
        }
        for (i = 0; i < NPT; ++i) {
            float sc = (i % 3 == 0) ? rr(0.2f, 1.6f) : (float)pow(10.0, (double)rr(-25.0f, 30.0f));
            g_x[i] = rr(-sc, sc); g_y[i] = rr(-sc, sc); g_z[i] = rr(-sc, sc);
            if (i % 5 == 1) g_y[i] = rr(-2.0f, 2.0f) * rr(0.0f, 1.0f); /* near the terrain */
            g_e[i] = (i % 4 == 0) ? 0.0f : rr(0.0f, 0.3f);
        }
        g_x[7] = g_y[7] = g_z[7] = 0.0f;
        g_x[11] = 1e-30f; g_y[11] = -1e-30f; g_z[11] = 0.0f;
        g_x[13] = 1.0f / (g_e[0] * 0.0f + 0.0f); /* inf */
        g_z[17] = -g_x[13];
        g_y[19] = g_x[13] - g_x[13]; /* NaN */
        g_x[23] = 5e5f; g_z[23] = 7e5f;     /* arguments near 1e6 */
        g_x[29] = 2e29f; g_z[29] = -9e29f; /* near the cutoff */
        {
            char nm[32];
            snprintf(nm, sizeof nm, "%s%d", r % 2 ? "mandelbulb" : "terrain", r);
            compare(nm, &prog, 1.0f);
            compare(nm, &prog, 0.93f);
        }
        {   /* points within the float envelope (|coordinates| <= 1e18, NUMERICS) get a
               finite distance below FLT_MAX: no NaN (which the evaluator would turn into
               FLT_MAX) and no overflow */
            uint32_t bad = 0, first = 0;
            for (i = 0; i < NPT; ++i) {
                fovsdf_query q;
                float p3[3], dd;
                if (!(fabsf(g_x[i]) <= 1e18f && fabsf(g_y[i]) <= 1e18f && fabsf(g_z[i]) <= 1e18f))
                    continue;
                memset(&q, 0, sizeof q);
                p3[0] = g_x[i]; p3[1] = g_y[i]; p3[2] = g_z[i];
                dd = fovsdf_program_eval(p3, &q, &prog);
                if (!(dd > -FLT_MAX && dd < FLT_MAX) && bad++ == 0) first = i;
            }
            check(bad == 0, fovcheck_name("mb_terrain%d_finite", r), "%u points (first %u)", bad,
                  first);
        }
    }
    {   /* bounds nested 24 deep, with points at every level's radius: more pending bounds
           than the batch evaluator keeps (16), so it falls back to point by point */
        static fovsdf_node nodes[256];
        static unsigned char pm[1 << 18];
        fovsdf_builder b;
        fovsdf_program prog;
        int32_t x;
        size_t sz;
        uint32_t i, lv;
        fovsdf_builder_init(&b, nodes, 256);
        x = fovsdf_union(&b, fovsdf_sphere(&b, 0.1f), fovsdf_translate(&b, fovsdf_box(&b, 0.1f,
                         0.1f, 0.1f), 0.3f, 0.0f, 0.0f));
        for (lv = 0; lv < 24; ++lv)
            x = fovsdf_union(&b, fovsdf_scale(&b, x, 0.5f),
                             fovsdf_translate(&b, fovsdf_sphere(&b, 0.2f), 3.0f, 0.0f, 0.0f));
        if (x >= 0 && fovsdf_program_size(nodes, b.count, x, &sz) == FOV_OK && sz <= sizeof pm &&
            fovsdf_program_build(&prog, nodes, b.count, x, pm, sz) == FOV_OK) {
            for (i = 0; i < NPT; ++i) {
                float rad = 4.0f;
                uint32_t k;
                for (k = 0; k < i % 26; ++k) rad *= 0.5f;
                g_x[i] = rad * rr(0.5f, 1.0f); g_y[i] = rad * rr(-0.3f, 0.3f);
                g_z[i] = rad * rr(-0.3f, 0.3f);
                g_e[i] = 0.0f;
            }
            compare("nested24", &prog, 1.0f);
        } else {
            check(0, "nested24_build", "x %d", (int)x);
        }
    }
    {   /* fovsdf_distance_batch: arguments, callbacks, sanitising */
        fovsdf_scene sc;
        fovsdf_ctx c;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_camera cam;
        fovsdf_stats st;
        float x[3] = { 1, 2, 3 }, y[3] = { 0, 1, 2 }, z[3] = { 0.5f, 0, 1 }, d[3];
        int32_t m[3];
        fov_result e;
        fovsdf_scene_init(&sc);
        fovsdf_camera_init(&cam, 8, 8);
        sc.dist_ex = pp_dist;
        g_user_scale = 1.0f;
        e = fovsdf_init(&c, &cfg, &sc, &cam, g_gaze, 0, 0);
        check(e == FOV_OK, "batch_init_point", "%d", (int)e);
        fovsdf_stats_init(&st);
        e = fovsdf_distance_batch(&c, 3, x, y, z, d, m, &st);
        check(e == FOV_OK && d[0] == 0.5f && d[1] == 5.0f && d[2] == 10.0f && m[2] == 3 &&
                  st.evals == 3,
              "batch_per_point_callback", "%d %g %g %g %d", (int)e, (double)d[0], (double)d[1],
              (double)d[2], (int)m[2]);
        sc.dist_batch = bt_dist;
        e = fovsdf_init(&c, &cfg, &sc, &cam, g_gaze, 0, 0);
        fovsdf_stats_init(&st);
        e = fovsdf_distance_batch(&c, 3, x, y, z, d, m, &st);
        check(e == FOV_OK && d[0] == 0.5f && d[1] == FLT_MAX && d[2] == 10.0f && m[0] == 4 &&
                  st.evals == 3 && st.prims == 3,
              "batch_callback_unwritten_is_miss", "%d %g %g %g", (int)e, (double)d[0],
              (double)d[1], (double)d[2]);
        g_user_scale = 0.0f;
        g_user_scale = g_user_scale / g_user_scale; /* NaN */
        e = fovsdf_distance_batch(&c, 3, x, y, z, d, 0, 0);
        check(e == FOV_OK && d[0] == FLT_MAX && d[2] == FLT_MAX, "batch_callback_nan_is_miss",
              "%g", (double)d[0]);
        sc.dist_ex = 0;
        sc.dist = 0;
        e = fovsdf_init(&c, &cfg, &sc, &cam, g_gaze, 0, 0);
        check(e == FOV_OK, "batch_only_scene_accepted", "%d", (int)e);
        g_user_scale = 2.0f;
        {
            float p[3] = { 1.0f, 0.0f, 0.5f };
            float dd = fovsdf_distance(&c, p, 0, 0);
            check(dd == 1.0f, "batch_only_scene_single_point", "%g", (double)dd);
        }
        check(fovsdf_distance_batch(0, 3, x, y, z, d, m, 0) == FOV_ERR_NULL, "batch_null_ctx",
              "-");
        check(fovsdf_distance_batch(&c, 3, 0, y, z, d, m, 0) == FOV_ERR_NULL, "batch_null_x",
              "-");
        check(fovsdf_distance_batch(&c, 3, x, y, z, 0, m, 0) == FOV_ERR_NULL, "batch_null_d",
              "-");
        check(fovsdf_distance_batch(&c, 0, 0, 0, 0, 0, 0, 0) == FOV_OK, "batch_n0_nothing", "-");
        sc.dist_batch = 0;
        e = fovsdf_init(&c, &cfg, &sc, &cam, g_gaze, 0, 0);
        check(e == FOV_ERR_NULL, "no_callback_rejected", "%d", (int)e);
    }
    return fovcheck_summary();
}
