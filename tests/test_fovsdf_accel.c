/* test_fovsdf_accel.c - tests of fovsdf.h's accelerated (head-start) methods.

   The cone pyramid's guarantee: for any distance function that never overestimates, no sample
   ray starts past its first hit. Property test: random scenes (unions of spheres, rotated boxes
   and sometimes a ground plane, built with the scene builder, so the program's bounding volumes
   are exercised too), random cameras, image sizes, tile sizes, levels and samples per pixel.
   The true first hit of every sample ray comes from analytic ray-primitive intersection in
   double precision, independent of the library. Also: proven-empty pixels have no hit, the
   images agree with classic sphere tracing, and bad parameters are rejected.
   The cones run with no stop slack (march until a cone touches a surface): the default slack
   only stops them earlier, and without it a geometric error shows (planted errors in the
   step, the cone angle or the empty-cell rule fail this test; with the default slack they
   hide behind the margin).
   "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
   Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025. */
#define FOVSDF_CONE_SLACK 0.0f
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fovcheck.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static char g_nm[128];
static const char *N(const char *fmt, const char *arg)
{
    snprintf(g_nm, sizeof g_nm, fmt, arg);
    return g_nm;
}

typedef struct rng { uint64_t s; } rng;
static double urand(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}
static double urange(rng *r, double a, double b) { return a + (b - a) * urand(r); }

#define MAXP 24
typedef struct prim {
    int kind;           /* 0 sphere, 1 box (rotated about y), 2 plane y = h */
    double c[3], r, h[3], ang;
} prim;
typedef struct scene_t { prim p[MAXP]; int n; } scene_t;

/* First t > 0 where the ray o + t d enters the primitive (t = 0 when o is inside), or -1. */
static double hit_sphere(const prim *p, const double o[3], const double d[3])
{
    double oc[3] = { o[0] - p->c[0], o[1] - p->c[1], o[2] - p->c[2] };
    double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
    double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - p->r * p->r, disc, t0;
    if (c <= 0.0) return 0.0;
    disc = b * b - c;
    if (disc < 0.0) return -1.0;
    t0 = -b - sqrt(disc);
    return t0 >= 0.0 ? t0 : -1.0;
}
static double hit_box(const prim *p, const double o[3], const double d[3])
{
    /* to box space: translate, rotate by -ang about y */
    double cs = cos(p->ang), sn = sin(p->ang), lo[3], ld[3], tn = -1e300, tf = 1e300;
    double ox = o[0] - p->c[0], oy = o[1] - p->c[1], oz = o[2] - p->c[2];
    int k;
    lo[0] = cs * ox - sn * oz; lo[1] = oy; lo[2] = sn * ox + cs * oz;
    ld[0] = cs * d[0] - sn * d[2]; ld[1] = d[1]; ld[2] = sn * d[0] + cs * d[2];
    for (k = 0; k < 3; ++k) {
        if (fabs(ld[k]) < 1e-300) {
            if (lo[k] < -p->h[k] || lo[k] > p->h[k]) return -1.0;
        } else {
            double t1 = (-p->h[k] - lo[k]) / ld[k], t2 = (p->h[k] - lo[k]) / ld[k];
            if (t1 > t2) { double t = t1; t1 = t2; t2 = t; }
            if (t1 > tn) tn = t1;
            if (t2 < tf) tf = t2;
        }
    }
    if (tn > tf || tf < 0.0) return -1.0;
    return tn > 0.0 ? tn : 0.0;
}
static double hit_plane(const prim *p, const double o[3], const double d[3])
{
    if (o[1] <= p->h[0]) return 0.0;
    if (d[1] >= 0.0) return -1.0;
    return (p->h[0] - o[1]) / d[1];
}
static double first_hit(const scene_t *s, const double o[3], const double d[3])
{
    double best = -1.0;
    int i;
    for (i = 0; i < s->n; ++i) {
        const prim *p = &s->p[i];
        double t = p->kind == 0 ? hit_sphere(p, o, d) : p->kind == 1 ? hit_box(p, o, d) : hit_plane(p, o, d);
        if (t >= 0.0 && (best < 0.0 || t < best)) best = t;
    }
    return best;
}

/* Build the same scene with the library's builder. */
static int build(const scene_t *s, fovsdf_node *nodes, uint32_t cap, fovsdf_program *prog, void *mem, size_t memsz,
                 uint32_t *count)
{
    fovsdf_builder b;
    int32_t r = -1;
    int i;
    fovsdf_builder_init(&b, nodes, cap);
    for (i = 0; i < s->n; ++i) {
        const prim *p = &s->p[i];
        int32_t x;
        b.material = i % 7;
        if (p->kind == 0) x = fovsdf_translate(&b, fovsdf_sphere(&b, (float)p->r), (float)p->c[0], (float)p->c[1], (float)p->c[2]);
        else if (p->kind == 1)
            x = fovsdf_translate(&b, fovsdf_rotate(&b, fovsdf_box(&b, (float)p->h[0], (float)p->h[1], (float)p->h[2]), 0.0f, 1.0f, 0.0f,
                                                   (float)(p->ang * 180.0 / 3.14159265358979323846)),
                                 (float)p->c[0], (float)p->c[1], (float)p->c[2]);
        else x = fovsdf_plane(&b, 0.0f, 1.0f, 0.0f, (float)-p->h[0]);
        r = r < 0 ? x : fovsdf_union(&b, r, x);
    }
    *count = b.count;
    if (b.err != FOV_OK || r < 0) return 0;
    return fovsdf_program_build(prog, nodes, b.count, r, mem, memsz) == FOV_OK;
}

/* The documented sample offsets (fovsdf.h, config comment). */
static void sample_offset(uint32_t spp, uint32_t s, double *ox, double *oy)
{
    static const double p4[4][2] = { { -0.125, -0.375 }, { 0.375, -0.125 }, { 0.125, 0.375 }, { -0.375, 0.125 } };
    static const int ra[4] = { 1, 3, 0, 2 }, rb[4] = { 2, 0, 3, 1 };
    if (spp == 4) { *ox = p4[s][0]; *oy = p4[s][1]; return; }
    if (spp == 16) {
        uint32_t i = s & 3u, j = s >> 2;
        *ox = ((double)(4 * (int)i + ra[j]) + 0.5) / 16.0 - 0.5;
        *oy = ((double)(4 * (int)j + rb[i]) + 0.5) / 16.0 - 0.5;
        return;
    }
    *ox = *oy = 0.0;
}

static void random_scene(rng *g, scene_t *s)
{
    int i, n = 3 + (int)(urand(g) * 18.0);
    s->n = 0;
    for (i = 0; i < n; ++i) {
        prim *p = &s->p[s->n++];
        p->kind = urand(g) < 0.5 ? 0 : 1;
        p->c[0] = urange(g, -4, 4); p->c[1] = urange(g, -1, 3); p->c[2] = urange(g, -4, 4);
        p->r = urange(g, 0.02, 1.0);
        p->h[0] = urange(g, 0.02, 0.8); p->h[1] = urange(g, 0.02, 0.8); p->h[2] = urange(g, 0.02, 0.8);
        p->ang = urange(g, 0, 3.14159);
    }
    if (urand(g) < 0.5) {
        prim *p = &s->p[s->n++];
        memset(p, 0, sizeof *p);
        p->kind = 2;
        p->h[0] = urange(g, -2.0, -1.0);
    }
}

static void cone_property(void)
{
    rng g = { 12345 };
    static fovsdf_node nodes[4 * MAXP];
    static unsigned char mem[1 << 17];
    int it, bad = 0, empty_bad = 0, builds = 0;
    long rays = 0, hits = 0, empty = 0, fov_px = 0;
    double worst = -1e300;
    char where[256] = "";
    for (it = 0; it < 300; ++it) {
        scene_t s;
        fovsdf_program prog;
        fovsdf_scene sc;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fovsdf_output out;
        fov_gaze gz;
        uint32_t count, W, H, x, y, smp, tiles[4] = { 2, 4, 8, 16 }, spps[3] = { 1, 4, 16 };
        static float start[96 * 64];
        static uint8_t mask[96 * 64];
        double ang;
        random_scene(&g, &s);
        if (!build(&s, nodes, 4 * MAXP, &prog, mem, sizeof mem, &count)) continue;
        ++builds;
        fovsdf_scene_init(&sc);
        fovsdf_scene_set_program(&sc, &prog);
        W = 16 + (uint32_t)(urand(&g) * 80.0);
        H = 9 + (uint32_t)(urand(&g) * 55.0);
        fovsdf_camera_init(&cam, W, H);
        ang = urange(&g, 0, 6.2831853);
        cam.pos[0] = (float)(9.0 * cos(ang)); cam.pos[1] = (float)urange(&g, -0.5, 5.0); cam.pos[2] = (float)(9.0 * sin(ang));
        cam.target[0] = (float)urange(&g, -1, 1); cam.target[1] = (float)urange(&g, -0.5, 1.5); cam.target[2] = (float)urange(&g, -1, 1);
        cam.fov_y_deg = (float)urange(&g, 15.0, 110.0);
        cfg.method = FOVSDF_METHOD_CONE;
        cfg.cone_tile = tiles[it % 4];
        cfg.cone_levels = 1 + (uint32_t)(urand(&g) * 2.0); /* 1 or 2 levels; 0 (default) below */
        if (it % 3 == 0) cfg.cone_levels = 0;
        {   /* levels must not exceed log2(tile) + 1 */
            uint32_t lv = 1, t = cfg.cone_tile;
            while (t > 1) { t >>= 1; ++lv; }
            if (cfg.cone_levels > lv) cfg.cone_levels = lv;
        }
        cfg.spp = spps[it % 3];
        cfg.shading = FOVSDF_SHADE_DEPTH;
        cfg.t_max = 40.0f;
        gz.x = 0.5f * (float)W; gz.y = 0.5f * (float)H;
        if (it % 4 == 1 || it % 4 == 3) { /* CONE_FOV: its traced pixels keep the guarantee */
            cfg.method = FOVSDF_METHOD_CONE_FOV;
            cfg.acuity.fovea_deg = 20.0f;
            gz.x = (float)urange(&g, 0.0, (double)W); gz.y = (float)urange(&g, 0.0, (double)H);
        }
        if (fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0) != FOV_OK) { ++bad; snprintf(where, sizeof where, "init failed at scene %d", it); continue; }
        fovsdf_output_init(&out);
        out.start = start;
        out.mask = mask;
        fovsdf_render_rows(&ctx, 0, H, &out, NULL);
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                double st = (double)start[y * W + x];
                if (mask[y * W + x] != 1) continue; /* CONE_FOV: interpolated from the mid level */
                if (cfg.method == FOVSDF_METHOD_CONE_FOV) ++fov_px;
                for (smp = 0; smp < ctx.cfg.spp; ++smp) {
                    double ox, oy, o[3], d[3], th, tol;
                    float ro[3], rd[3];
                    sample_offset(ctx.cfg.spp, smp, &ox, &oy);
                    fovsdf_camera_ray(&ctx, (float)((double)x + 0.5 + ox), (float)((double)y + 0.5 + oy), ro, rd);
                    o[0] = (double)ro[0]; o[1] = (double)ro[1]; o[2] = (double)ro[2];
                    d[0] = (double)rd[0]; d[1] = (double)rd[1]; d[2] = (double)rd[2];
                    th = first_hit(&s, o, d);
                    ++rays;
                    if (st >= (double)cfg.t_max) { /* proven empty: no hit within t_max */
                        ++empty;
                        if (th >= 0.0 && th < (double)cfg.t_max * 0.9999) {
                            if (!empty_bad) snprintf(where, sizeof where, "scene %d pixel (%u,%u): empty but hit at %.6g", it, x, y, th);
                            ++empty_bad;
                        }
                        continue;
                    }
                    if (th < 0.0) continue;
                    ++hits;
                    /* float rounding of the ray and of the distance: a few ulps of |o| + t */
                    tol = 1e-5 * (sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) + th);
                    if (st - th > worst) worst = st - th;
                    if (st > th + tol) {
                        if (!bad) snprintf(where, sizeof where, "scene %d tile %u levels %u spp %u pixel (%u,%u): start %.7g > hit %.7g",
                                           it, ctx.cfg.cone_tile, ctx.cfg.cone_levels, ctx.cfg.spp, x, y, st, th);
                        ++bad;
                    }
                }
            }
    }
    check(builds >= 280 && rays > 1000000 && hits > 100000 && bad == 0, "cone_start_never_past_first_hit",
          "%d violations of %ld hit rays (%ld rays, %d scenes built); worst start - hit %.3g; first: %s", bad, hits, rays, builds,
          worst, where);
    check(fov_px > 50000, "cone_fov_pixels_in_property_test", "only %ld CONE_FOV pixels traced", fov_px);
    check(empty > 10000 && empty_bad == 0, "cone_empty_cells_have_no_hit", "%d of %ld proven-empty rays do hit; %s", empty_bad,
          empty, where);
}

/* A built-in scene at w x h (free the returned memory). */
static void *load_builtin(uint32_t id, uint32_t w, uint32_t h, fovsdf_builtin *bi)
{
    size_t sz;
    void *mem;
    fovsdf_builtin_size(id, &sz);
    mem = malloc(sz);
    fovsdf_builtin_init(id, bi, mem, sz);
    bi->camera.width = w;
    bi->camera.height = h;
    return mem;
}

/* The cone images agree with classic sphere tracing on the built-in scenes. */
static void cone_vs_classic(void)
{
    uint32_t id;
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        void *mem;
        fovsdf_builtin bi;
        fovsdf_config c0 = fovsdf_config_default(), c1;
        fovsdf_ctx k0, k1;
        fovsdf_output o0, o1;
        fovsdf_stats s0, s1;
        fov_gaze gz = { 60.0f, 34.0f };
        static uint8_t h0[120 * 68], h1[120 * 68];
        static float f0[120 * 68 * 3], f1[120 * 68 * 3];
        uint32_t i, mis = 0;
        double se = 0.0;
        mem = load_builtin(id, 120, 68, &bi);
        c0.shading = FOVSDF_SHADE_NORMALS;
        c1 = c0;
        c1.method = FOVSDF_METHOD_CONE;
        c1.finish = FOVSDF_FINISH_CLASSIC;
        fovsdf_init(&k0, &c0, &bi.scene, &bi.camera, gz, NULL, 0);
        fovsdf_init(&k1, &c1, &bi.scene, &bi.camera, gz, NULL, 0);
        fovsdf_output_init(&o0); o0.hit = h0; o0.rgb = f0;
        fovsdf_output_init(&o1); o1.hit = h1; o1.rgb = f1;
        memset(&s0, 0, sizeof s0); memset(&s1, 0, sizeof s1);
        fovsdf_render_rows(&k0, 0, 68, &o0, &s0);
        fovsdf_render_rows(&k1, 0, 68, &o1, &s1);
        for (i = 0; i < 120u * 68u; ++i) mis += h0[i] != h1[i];
        for (i = 0; i < 120u * 68u * 3u; ++i) se += ((double)f0[i] - (double)f1[i]) * ((double)f0[i] - (double)f1[i]);
        se /= 120.0 * 68.0 * 3.0;
        check(mis <= 24 && se < 3e-3, N("cone_matches_classic_%s", bi.name),
              "hit mismatch %u px of 8160, normal-image MSE %.3g", mis, se);
        check(s1.evals_lowres > 0 && s1.evals_primary + s1.evals_lowres < s0.evals_primary, N("cone_fewer_evals_%s", bi.name),
              "classic %llu primary evaluations, cone %llu low-res + %llu rays", (unsigned long long)s0.evals_primary,
              (unsigned long long)s1.evals_lowres, (unsigned long long)s1.evals_primary);
        free(mem);
    }
}

static fov_result init_with(fovsdf_config c)
{
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fov_gaze gz = { 8.0f, 8.0f };
    fovsdf_scene_init(&sc);
    sc.dist = NULL;
    {
        static fovsdf_node nodes[4];
        static unsigned char mem[8192];
        static fovsdf_program prog;
        fovsdf_builder b;
        int32_t r;
        size_t need;
        fovsdf_builder_init(&b, nodes, 4);
        r = fovsdf_sphere(&b, 1.0f);
        fovsdf_program_size(nodes, b.count, r, &need);
        if (need > sizeof mem || fovsdf_program_build(&prog, nodes, b.count, r, mem, sizeof mem) != FOV_OK) return FOV_ERR_LIMIT;
        fovsdf_scene_set_program(&sc, &prog);
    }
    fovsdf_camera_init(&cam, 16, 16);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    return fovsdf_init(&ctx, &c, &sc, &cam, gz, NULL, 0);
}

static void bad_params(void)
{
    fovsdf_config c = fovsdf_config_default();
    fov_result r;
    c.method = FOVSDF_METHOD_CONE;
    check(init_with(c) == FOV_OK, "cone_default_config_ok", "init failed");
    c.cone_tile = 12;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "cone_tile_not_power_of_two", "got %d", (int)r);
    c.cone_tile = 512;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "cone_tile_above_256", "got %d", (int)r);
    c.cone_tile = 8; c.cone_levels = 5;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "cone_levels_above_log2_tile_plus_1", "got %d", (int)r);
    c.cone_levels = 4;
    r = init_with(c);
    check(r == FOV_OK, "cone_levels_log2_tile_plus_1_ok", "got %d", (int)r);
    c.finish = 99;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "finish_unknown", "got %d", (int)r);
}

/* Head-start cells are grid aligned: rendering by 7-row bands or by 13x11 tiles gives the same
   bytes (colour and head starts) as one full render, as for the plain tracers. */
static void partition_invariant(uint32_t method, uint32_t scene, uint32_t spp)
{
    void *mem;
    fovsdf_builtin bi;
    fovsdf_config c = fovsdf_config_default();
    fovsdf_ctx k;
    fovsdf_output o;
    fov_gaze gz = { 50.0f, 30.0f };
    static float a[100 * 57 * 3], b[100 * 57 * 3], sa[100 * 57], sb[100 * 57];
    uint32_t y, x;
    int same;
    mem = load_builtin(scene, 100, 57, &bi);
    c.method = method;
    c.spp = spp;
    fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
    fovsdf_output_init(&o); o.rgb = a; o.start = sa;
    fovsdf_render_rows(&k, 0, 57, &o, NULL);
    o.rgb = b; o.start = sb;
    for (y = 0; y < 57; y += 7) fovsdf_render_rows(&k, y, y + 7 < 57 ? y + 7 : 57, &o, NULL);
    same = memcmp(a, b, sizeof a) == 0 && memcmp(sa, sb, sizeof sa) == 0;
    check(same, N("%s_rows_in_bands_identical", fovsdf_method_name(method)), "differs from the full render");
    memset(b, 0, sizeof b);
    memset(sb, 0, sizeof sb);
    for (y = 0; y < 57; y += 11)
        for (x = 0; x < 100; x += 13) fovsdf_render_tile(&k, x, y, x + 13 < 100 ? x + 13 : 100, y + 11 < 57 ? y + 11 : 57, &o, NULL);
    same = memcmp(a, b, sizeof a) == 0 && memcmp(sa, sb, sizeof sa) == 0;
    check(same, N("%s_tiles_identical", fovsdf_method_name(method)), "13x11 tiles differ from the full render");
    {   /* the same tiles into 13x11 tile buffers (origin at the tile's corner): fixed memory */
        float tb[13 * 11 * 3], ts[13 * 11];
        fov_result r0 = FOV_OK, r1, r2;
        memset(b, 0, sizeof b);
        memset(sb, 0, sizeof sb);
        for (y = 0; y < 57; y += 11)
            for (x = 0; x < 100; x += 13) {
                uint32_t x1 = x + 13 < 100 ? x + 13 : 100, y1 = y + 11 < 57 ? y + 11 : 57, i, j;
                fovsdf_output t;
                fovsdf_output_init(&t);
                t.rgb = tb; t.rgb_stride = 3 * 13; t.start = ts; t.start_stride = 13;
                t.origin_x = x; t.origin_y = y;
                r1 = fovsdf_render_tile(&k, x, y, x1, y1, &t, NULL);
                if (r1 != FOV_OK) r0 = r1;
                for (j = y; j < y1; ++j)
                    for (i = x; i < x1; ++i) {
                        memcpy(b + 3 * (j * 100 + i), tb + 3 * ((j - y) * 13 + (i - x)), 3 * sizeof(float));
                        sb[j * 100 + i] = ts[(j - y) * 13 + (i - x)];
                    }
            }
        same = r0 == FOV_OK && memcmp(a, b, sizeof a) == 0 && memcmp(sa, sb, sizeof sa) == 0;
        check(same, N("%s_tile_buffers_identical", fovsdf_method_name(method)), "tile buffers differ (status %d)", (int)r0);
        o.rgb = tb; o.rgb_stride = 3 * 13; o.start = NULL; o.origin_x = 13; o.origin_y = 11;
        r1 = fovsdf_render_tile(&k, 12, 11, 20, 20, &o, NULL);
        r2 = fovsdf_render_tile(&k, 13, 11, 27, 20, &o, NULL);
        check(r1 == FOV_ERR_INVALID_ARG && r2 == FOV_ERR_TOO_SMALL, N("%s_tile_buffer_bounds", fovsdf_method_name(method)),
              "left of the origin: %d, wider than the stride: %d", (int)r1, (int)r2);
    }
    free(mem);
}

/* ---- IPR ---------------------------------------------------------------------------------- */
static void min_filter_tests(void)
{
    static float in[37 * 23], out[37 * 23];
    rng g = { 777 };
    int bad = 0, above = 0, rad;
    uint32_t x, y, i;
    fov_result r;
    for (i = 0; i < 37u * 23u; ++i) in[i] = (float)urange(&g, 0.0, 100.0);
    for (rad = 0; rad <= 3; ++rad) {
        fovsdf_min_filter(in, 37, 23, rad, out);
        for (y = 0; y < 23; ++y)
            for (x = 0; x < 37; ++x) {
                float mn = 1e30f;
                int u, v;
                for (v = (int)y - rad; v <= (int)y + rad; ++v)
                    for (u = (int)x - rad; u <= (int)x + rad; ++u)
                        if (u >= 0 && v >= 0 && u < 37 && v < 23 && in[v * 37 + u] < mn) mn = in[v * 37 + u];
                if (!(out[y * 37 + x] <= mn && out[y * 37 + x] >= mn)) ++bad;
                if (out[y * 37 + x] > in[y * 37 + x]) ++above;
            }
    }
    check(bad == 0, "min_filter_matches_brute_force", "%d of %d values differ (radii 0..3)", bad, 4 * 37 * 23);
    check(above == 0, "min_filter_never_increases_t", "%d values above their input", above);
    r = fovsdf_min_filter(NULL, 37, 23, 1, out);
    check(r == FOV_ERR_NULL, "min_filter_null", "got %d", (int)r);
    r = fovsdf_min_filter(in, 0, 23, 1, out);
    check(r == FOV_ERR_INVALID_ARG, "min_filter_zero_width", "got %d", (int)r);
    r = fovsdf_min_filter(in, 37, 23, -1, out);
    check(r == FOV_ERR_INVALID_ARG, "min_filter_negative_radius", "got %d", (int)r);
    r = fovsdf_min_filter(in, 37, 23, 1, in);
    check(r == FOV_ERR_INVALID_ARG, "min_filter_in_place_rejected", "got %d", (int)r);
    r = fovsdf_min_filter(in, 37, 23, 65, out);
    check(r == FOV_ERR_LIMIT, "min_filter_radius_above_64_limit", "got %d", (int)r);
    r = fovsdf_min_filter(in, 37, 23, 64, out);   /* the window covers the image: its minimum */
    {
        float mn = in[0];
        for (i = 1; i < 37u * 23u; ++i) mn = in[i] < mn ? in[i] : mn;
        for (i = 0, bad = 0; i < 37u * 23u; ++i) bad += !(out[i] <= mn && out[i] >= mn);
        check(r == FOV_OK && bad == 0, "min_filter_radius_64_whole_image", "got %d, %d values differ", (int)r, bad);
    }
}

static void ipr_bad_params(void)
{
    fovsdf_config c = fovsdf_config_default();
    fov_result r;
    c.method = FOVSDF_METHOD_IPR;
    r = init_with(c);
    check(r == FOV_OK, "ipr_default_config_ok", "got %d", (int)r);
    c.ipr_levels = 7;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "ipr_levels_7", "got %d", (int)r);
    c.ipr_levels = 0; c.ipr_radius = -1;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "ipr_radius_negative", "got %d", (int)r);
    c.ipr_radius = 4;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "ipr_radius_4", "got %d", (int)r);
    c.ipr_radius = 0; c.ipr_tile = 10;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "ipr_tile_not_multiple", "got %d", (int)r);
    c.ipr_tile = 128;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "ipr_tile_128", "got %d", (int)r);
    c.ipr_tile = 64; c.ipr_levels = 6; c.ipr_radius = 3;
    r = init_with(c);
    check(r == FOV_ERR_LIMIT, "ipr_tile_scratch_limit", "got %d (needs %u floats)", (int)r,
          (unsigned)fovsdf__ipr_floats(64, 6, 3));
    c.ipr_no_filter = 2; c.ipr_tile = 0; c.ipr_levels = 0; c.ipr_radius = 0;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "ipr_no_filter_2", "got %d", (int)r);
}

/* Render a built-in scene at w x h with a method; returns visibility evaluations. */
static double vis_evals(uint32_t id, uint32_t method, uint32_t spp, uint32_t w, uint32_t h, uint8_t *hit, float *start,
                        uint32_t levels)
{
    void *mem;
    fovsdf_builtin bi;
    fovsdf_config c = fovsdf_config_default();
    fovsdf_ctx k;
    fovsdf_output o;
    fovsdf_stats st;
    fov_gaze gz;
    mem = load_builtin(id, w, h, &bi);
    gz.x = 0.5f * (float)w; gz.y = 0.5f * (float)h;
    c.method = method; c.spp = spp; c.shading = FOVSDF_SHADE_DEPTH; c.ipr_levels = levels;
    c.finish = FOVSDF_FINISH_CLASSIC;
    fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
    fovsdf_output_init(&o); o.hit = hit; o.start = start;
    memset(&st, 0, sizeof st);
    fovsdf_render_rows(&k, 0, h, &o, &st);
    free(mem);
    return (double)(st.evals_lowres + st.evals_primary);
}

static void ipr_tests(void)
{
    static uint8_t h0[160 * 90], h1[160 * 90];
    static float s1[160 * 90];
    double r1, r4, r16;
    uint32_t id, i, mis;
    /* agreement with classic: within 0.5 % of the pixels except on thin features */
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        vis_evals(id, FOVSDF_METHOD_CLASSIC, 1, 160, 90, h0, NULL, 0);
        vis_evals(id, FOVSDF_METHOD_IPR, 1, 160, 90, h1, NULL, 0);
        for (mis = 0, i = 0; i < 160u * 90u; ++i) mis += h0[i] != h1[i];
        if (id == FOVSDF_SCENE_THIN)
            check(100.0 * mis / (160.0 * 90.0) <= 5.0, "ipr_thin_misses_bounded",
                  "%.2f %% of the pixels differ from classic (documented: the filter is a heuristic, ~2 %% at 320x180)",
                  100.0 * mis / (160.0 * 90.0));
        else
            check(100.0 * mis / (160.0 * 90.0) <= 0.5, N("ipr_matches_classic_%s", fovsdf_builtin_name(id)),
                  "%.3f %% of the pixels differ", 100.0 * mis / (160.0 * 90.0));
    }
    /* the thesis's claim as evaluation ratios: IPR's gain grows with the samples per pixel */
    r1 = vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_CLASSIC, 1, 96, 54, h0, NULL, 0) /
         vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_IPR, 1, 96, 54, h1, NULL, 0);
    r4 = vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_CLASSIC, 4, 96, 54, h0, NULL, 0) /
         vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_IPR, 4, 96, 54, h1, NULL, 0);
    r16 = vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_CLASSIC, 16, 96, 54, h0, NULL, 0) /
          vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_IPR, 16, 96, 54, h1, NULL, 0);
    check(r1 > 1.0 && r4 > r1 && r16 > r4, "ipr_gain_grows_with_spp", "classic/ipr evaluations: %.2f (1 spp), %.2f (4), %.2f (16)",
          r1, r4, r16);
    /* one level: no head start at all */
    vis_evals(FOVSDF_SCENE_PRIMITIVES, FOVSDF_METHOD_IPR, 1, 96, 54, h1, s1, 1);
    for (mis = 0, i = 0; i < 96u * 54u; ++i) mis += s1[i] > 0.0f;
    check(mis == 0, "ipr_one_level_no_head_start", "%u pixels start past 0", mis);
}

/* ---- Skipping Spheres ---------------------------------------------------------------------- */
typedef struct rec_t { float min_infl, max_infl; float r; } rec_t;
/* A solid sphere of radius r at the origin that records the scales it is asked for. */
static float rec_sphere(const float p[3], fovsdf_query *q, void *user)
{
    rec_t *u = (rec_t *)user;
    float s = q && q->inflate > 0.0f ? q->inflate : 1.0f;
    if (s < u->min_infl) u->min_infl = s;
    if (s > u->max_infl) u->max_infl = s;
    return (sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / s - u->r) * s;
}

static void skip_sign_aware(void)
{
    rec_t u;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config c = fovsdf_config_default();
    fovsdf_ctx k;
    fovsdf_output o;
    fov_gaze gz = { 8.0f, 8.0f };
    fovsdf_scene_init(&sc);
    sc.dist_ex = rec_sphere;
    sc.user = &u;
    fovsdf_camera_init(&cam, 16, 16);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    c.method = FOVSDF_METHOD_SKIP;
    c.heuristic_start = 1; /* the thesis's variant scales the scene; the safe one does not */
    c.skip_scale = 1.05f;
    /* camera outside the sphere: the low-resolution pass inflates */
    u.min_infl = 1e9f; u.max_infl = 0.0f; u.r = 1.0f;
    fovsdf_init(&k, &c, &sc, &cam, gz, NULL, 0);
    fovsdf_output_init(&o);
    fovsdf_render_rows(&k, 0, 16, &o, NULL);
    check(u.max_infl > 1.04f && u.max_infl < 1.06f, "skip_inflates_camera_outside", "largest scale asked %.4f, want 1.05", (double)u.max_infl);
    /* camera inside the sphere: it deflates (1/s) */
    u.min_infl = 1e9f; u.max_infl = 0.0f; u.r = 20.0f;
    fovsdf_init(&k, &c, &sc, &cam, gz, NULL, 0);
    fovsdf_render_rows(&k, 0, 16, &o, NULL);
    check(u.min_infl > 0.94f && u.min_infl < 0.96f && u.max_infl <= 1.0f, "skip_deflates_camera_inside",
          "scales asked %.4f .. %.4f, want 1/1.05 = 0.952 .. 1", (double)u.min_infl, (double)u.max_infl);
}

/* A room: a big box minus a sphere of radius 10, camera in the cavity. Scaling the solid up
   shrinks the subtracted hole, so every low-resolution start stays before the wall at 10. */
static void skip_hole_shrinks(void)
{
    static fovsdf_node nodes[8];
    static unsigned char mem[1 << 14];
    static float start[40 * 30];
    fovsdf_program prog;
    fovsdf_builder b;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config c = fovsdf_config_default();
    fovsdf_ctx k;
    fovsdf_output o;
    fov_gaze gz = { 20.0f, 15.0f };
    int32_t r;
    uint32_t i, past = 0;
    float worst = 0.0f;
    fovsdf_builder_init(&b, nodes, 8);
    r = fovsdf_subtract(&b, fovsdf_box(&b, 30.0f, 30.0f, 30.0f), fovsdf_sphere(&b, 10.0f));
    fovsdf_program_build(&prog, nodes, b.count, r, mem, sizeof mem);
    fovsdf_scene_init(&sc);
    fovsdf_scene_set_program(&sc, &prog);
    fovsdf_camera_init(&cam, 40, 30);
    cam.pos[0] = 0.0f; cam.pos[1] = 0.0f; cam.pos[2] = 0.0f; cam.target[2] = 1.0f;
    cam.fov_y_deg = 90.0f;
    c.method = FOVSDF_METHOD_SKIP;
    c.heuristic_start = 1; /* the thesis's scaled scene (the safe variant has no scaling) */
    c.skip_scale = 1.05f;
    c.skip_eps = 0.001f;
    fovsdf_init(&k, &c, &sc, &cam, gz, NULL, 0);
    fovsdf_output_init(&o); o.start = start;
    fovsdf_render_rows(&k, 0, 30, &o, NULL);
    for (i = 0; i < 40u * 30u; ++i) {
        if (start[i] > 10.0f) ++past;
        if (start[i] > worst) worst = start[i];
    }
    check(past == 0 && worst > 9.0f, "skip_subtracted_hole_shrinks", "%u of 1200 starts past the wall at 10 (largest %.4f; an inflated hole would give ~10.5)",
          past, (double)worst);
}

static void skip_tests(void)
{
    static uint8_t h0[160 * 90], h1[160 * 90];
    fovsdf_config c = fovsdf_config_default();
    fov_result r;
    uint32_t id, i, mis;
    c.method = FOVSDF_METHOD_SKIP;
    r = init_with(c);
    check(r == FOV_OK, "skip_default_config_ok", "got %d", (int)r);
    c.skip_scale = -1.0f;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "skip_scale_negative", "got %d", (int)r);
    c.skip_scale = 3.0f;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "skip_scale_3", "got %d", (int)r);
    c.skip_scale = 0.0f; c.skip_eps = -0.1f;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "skip_eps_negative", "got %d", (int)r);
    c.skip_eps = 0.0f; c.skip_block = 17;
    r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "skip_block_17", "got %d", (int)r);
    /* a heuristic: images within 3 % of classic's hit mask */
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        vis_evals(id, FOVSDF_METHOD_CLASSIC, 1, 160, 90, h0, NULL, 0);
        vis_evals(id, FOVSDF_METHOD_SKIP, 1, 160, 90, h1, NULL, 0);
        for (mis = 0, i = 0; i < 160u * 90u; ++i) mis += h0[i] != h1[i];
        check(100.0 * mis / (160.0 * 90.0) <= 3.0, N("skip_hit_mask_near_classic_%s", fovsdf_builtin_name(id)),
              "%.2f %% of the pixels differ", 100.0 * mis / (160.0 * 90.0));
    }
    skip_sign_aware();
    skip_hole_shrinks();
    {   /* the shadow head start saves shadow evaluations (primitives, full shading) */
        void *mem;
        fovsdf_builtin bi;
        fovsdf_config a = fovsdf_config_default(), bcfg;
        fovsdf_ctx ka, kb;
        fovsdf_output o;
        fovsdf_stats sa, sb;
        fov_gaze gz = { 48.0f, 27.0f };
        mem = load_builtin(FOVSDF_SCENE_PRIMITIVES, 96, 54, &bi);
        a.method = FOVSDF_METHOD_SKIP;
        a.heuristic_start = 1; /* shadow head starts are the thesis variant's */
        bcfg = a;
        bcfg.skip_no_shadow_start = 1;
        fovsdf_init(&ka, &a, &bi.scene, &bi.camera, gz, NULL, 0);
        fovsdf_init(&kb, &bcfg, &bi.scene, &bi.camera, gz, NULL, 0);
        fovsdf_output_init(&o);
        memset(&sa, 0, sizeof sa); memset(&sb, 0, sizeof sb);
        fovsdf_render_rows(&ka, 0, 54, &o, &sa);
        fovsdf_render_rows(&kb, 0, 54, &o, &sb);
        check(sa.evals_shadow * 5 < sb.evals_shadow * 4, "skip_shadow_head_start_saves",
              "full-resolution shadow evaluations with head start %llu, without %llu",
              (unsigned long long)sa.evals_shadow, (unsigned long long)sb.evals_shadow);
        free(mem);
    }
}

/* ---- FIPR building blocks: acuity, deterministic uniforms, Bernoulli mask density --------- */
static void acuity_tests(void)
{
    fovsdf_acuity a = fovsdf_acuity_default();
    const double w[9] = { 0, 2.5, 5, 6, 7.5, 10, 15, 20, 30 };
    int i, bad = 0;
    double worst = 0.0;
    a.fovea_deg = -1.0f; /* the raw curve */
    for (i = 0; i < 9; ++i) {
        double want = 0.90964 * exp(-0.20651 * w[i]) + 0.00792, got = (double)fovsdf_acuity_p(&a, (float)w[i]);
        if (fabs(got - want) > worst) worst = fabs(got - want);
        if (fabs(got - want) > 1e-5) ++bad;
    }
    check(bad == 0, "acuity_curve_values", "%d of 9 values off by more than 1e-5 (worst %.3g)", bad, worst);
    /* p(w) = 0.90964 exp(-0.20651 w) + 0.00792 (the thesis's Eq. 4.1 as fovsdf.h reads it)
       worked out by hand at 0 2.5 5 6 7.5 10 15 20 30 degrees: 0.918 0.551 0.332 0.271 0.201
       0.123 0.049 0.023 0.010 */
    check(fabs((double)fovsdf_acuity_p(&a, 6.0f) - 0.271) < 5e-4 && fabs((double)fovsdf_acuity_p(&a, 0.0f) - 0.918) < 5e-4 &&
              fabs((double)fovsdf_acuity_p(&a, 30.0f) - 0.010) < 5e-4,
          "acuity_matches_reference_table", "p(0) %.4f p(6) %.4f p(30) %.4f", (double)fovsdf_acuity_p(&a, 0.0f),
          (double)fovsdf_acuity_p(&a, 6.0f), (double)fovsdf_acuity_p(&a, 30.0f));
    a = fovsdf_acuity_default();
    a.outer_deg = 25.0f;
    check(fovsdf_acuity_p(&a, 7.0f) >= 1.0f && fovsdf_acuity_p(&a, 8.0f) < 0.3f && fovsdf_acuity_p(&a, 26.0f) <= 0.0f,
          "acuity_zones", "fovea %.3f, periphery %.3f, outer %.3f", (double)fovsdf_acuity_p(&a, 7.0f),
          (double)fovsdf_acuity_p(&a, 8.0f), (double)fovsdf_acuity_p(&a, 26.0f));
    check(fovsdf_acuity_p(NULL, 3.0f) <= 0.0f && fovsdf_acuity_p(&a, (float)NAN) <= 0.0f, "acuity_bad_input", "nonzero");
}

static void u01_tests(void)
{
    uint32_t x, y, hist[16] = { 0 }, n = 0, same = 0, diff_seed = 0;
    double chi = 0.0;
    for (y = 0; y < 256; ++y)
        for (x = 0; x < 256; ++x) {
            float u = fovsdf_u01(7u, x, y, 3u);
            if (!(u >= 0.0f && u < 1.0f)) { ++n; continue; }
            hist[(int)(u * 16.0f)]++;
            same += fovsdf_u01(7u, x, y, 3u) >= u && fovsdf_u01(7u, x, y, 3u) <= u;
            diff_seed += fovsdf_u01(8u, x, y, 3u) < u || fovsdf_u01(8u, x, y, 3u) > u;
        }
    for (x = 0; x < 16; ++x) chi += ((double)hist[x] - 4096.0) * ((double)hist[x] - 4096.0) / 4096.0;
    check(n == 0 && same == 65536, "u01_range_and_determinism", "%u out of range, %u of 65536 repeat", n, same);
    check(diff_seed > 65000, "u01_seed_changes_values", "%u of 65536 differ", diff_seed);
    /* 15 degrees of freedom: chi^2 above 37.7 has probability 0.001 */
    check(chi < 37.7, "u01_uniform_chi_square", "chi^2 = %.2f over 16 bins", chi);
}

/* Bernoulli mask (u < p(w)) over an image: the traced fraction per eccentricity ring matches the
   ring's mean p within 4 binomial standard deviations. */
static void mask_density_tests(void)
{
    fovsdf_acuity a = fovsdf_acuity_default();
    fov_ecc_model m;
    fov_display d;
    fov_gaze g = { 320.0f, 180.0f };
    double sum_p[8] = { 0 }, cnt[8] = { 0 }, traced[8] = { 0 };
    uint32_t x, y, k, bad = 0, rep2 = 0;
    char where[160] = "";
    memset(&d, 0, sizeof d);
    fovsdf_ecc_init(&m, &d, 60.0f, 640, 360, g);
    for (y = 0; y < 360; ++y)
        for (x = 0; x < 640; ++x) {
            float w = fovsdf_ecc_deg(&m, (float)x + 0.5f, (float)y + 0.5f), p = fovsdf_acuity_p(&a, w);
            int ring = (int)(w / 5.0f);
            if (ring > 7) ring = 7;
            sum_p[ring] += (double)p;
            cnt[ring] += 1.0;
            traced[ring] += fovsdf_u01(42u, x, y, 0u) < p ? 1.0 : 0.0;
            rep2 += (fovsdf_u01(42u, x, y, 0u) < p) == (fovsdf_u01(42u, x, y, 0u) < p);
        }
    for (k = 0; k < 8; ++k) {
        double mean, var, sd;
        if (cnt[k] < 100.0) continue;
        mean = sum_p[k];
        var = 0.0;
        /* variance of a sum of independent Bernoullis <= n/4; use the ring's p(1-p) bound */
        var = mean * (1.0 - mean / cnt[k]);
        sd = sqrt(var > 1.0 ? var : 1.0);
        if (fabs(traced[k] - mean) > 4.0 * sd) {
            ++bad;
            snprintf(where, sizeof where, "ring %u: traced %.0f of %.0f, expected %.1f (sd %.1f)", k, traced[k], cnt[k], mean, sd);
        }
    }
    check(bad == 0, "mask_density_matches_acuity", "%u rings outside 4 sd; %s", bad, where);
    check(rep2 == 640u * 360u, "mask_deterministic_for_seed", "%u of %u repeat", rep2, 640u * 360u);
}

/* ---- FIPR and CONE_FOV -------------------------------------------------------------------- */
/* Renders a built-in scene at 96x64 with a method and config tweaks; returns 0 on init failure. */
typedef struct fovimgs { float rgb[96 * 64 * 3], depth[96 * 64], start[96 * 64]; uint8_t hit[96 * 64], mask[96 * 64]; } fovimgs;
static int render96(const fovsdf_builtin *bi, const fovsdf_config *c, fov_gaze gz, fovimgs *im, fovsdf_stats *st)
{
    fovsdf_ctx k;
    fovsdf_output o;
    if (fovsdf_init(&k, c, &bi->scene, &bi->camera, gz, NULL, 0) != FOV_OK) return 0;
    fovsdf_output_init(&o);
    o.rgb = im->rgb; o.depth = im->depth; o.start = im->start; o.hit = im->hit; o.mask = im->mask;
    fovsdf_render_rows(&k, 0, 64, &o, st);
    return 1;
}

/* With a fovea that covers everything, FIPR is IPR (3 levels) and CONE_FOV is CONE (2x2
   leaves), bit for bit: the foveated pipelines add nothing where every pixel is traced. */
static void fov_equal_unfoveated(void)
{
    static fovimgs a, b;
    uint32_t ids[2] = { FOVSDF_SCENE_PRIMITIVES, FOVSDF_SCENE_TEMPLE }, i, m;
    fov_gaze gz = { 30.0f, 20.0f };
    for (i = 0; i < 2; ++i)
        for (m = 0; m < 3; ++m) { /* m 2: FIPR and IPR with the thesis's head starts */
            fovsdf_builtin bi;
            void *mem = load_builtin(ids[i], 96, 64, &bi);
            fovsdf_config c = fovsdf_config_default(), d;
            uint32_t p, all1 = 1;
            c.spp = 4;
            c.shading = FOVSDF_SHADE_NO_SHADOWS;
            c.heuristic_start = m == 2u;
            c.method = m == 1u ? FOVSDF_METHOD_CONE : FOVSDF_METHOD_IPR;
            d = c;
            d.method = m == 1u ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
            d.acuity.fovea_deg = 180.0f;
            memset(&a, 0, sizeof a); memset(&b, 0, sizeof b);
            render96(&bi, &c, gz, &a, NULL);
            render96(&bi, &d, gz, &b, NULL);
            for (p = 0; p < 96u * 64u; ++p) all1 &= b.mask[p] == 1;
            check(all1 && memcmp(a.rgb, b.rgb, sizeof a.rgb) == 0 && memcmp(a.depth, b.depth, sizeof a.depth) == 0 &&
                      memcmp(a.start, b.start, sizeof a.start) == 0,
                  N(m == 1u ? "cone_fov_full_fovea_is_cone_%s" : m ? "fipr_thesis_full_fovea_is_ipr_%s" : "fipr_full_fovea_is_ipr_%s",
                    bi.name), "images differ (all mask 1: %u)", all1);
            free(mem);
        }
}

/* Temporal reuse: a static scene and gaze rendered for `refresh` consecutive frames into the
   same buffers gives exactly the image of refresh 1; before the last frame some pixels are
   still untouched (the refresh really skips them). */
static void fov_temporal_reuse(void)
{
    static fovimgs ref, im;
    uint32_t m, k;
    fov_gaze gz = { 20.0f, 14.0f };
    fovsdf_builtin bi;
    void *mem = load_builtin(FOVSDF_SCENE_PRIMITIVES, 96, 64, &bi);
    for (m = 0; m < 2; ++m)
        for (k = 2; k <= 4; k += 2) {
            fovsdf_config c = fovsdf_config_default();
            uint32_t f, p, untouched_before = 0, kept_last = 0, interp = 0;
            fovsdf_stats s1, sk;
            c.method = m ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
            c.shading = FOVSDF_SHADE_NO_SHADOWS;
            c.acuity.fovea_deg = 5.0f;
            c.fov_mask = FOVSDF_MASK_ACUITY;
            c.seed = 7u;
            c.ipr_tile = 8; /* refresh turns go by tile: 96 tiles share the 2 or 4 turns evenly */
            c.cone_tile = 8;
            c.cone_levels = 0;
            memset(&s1, 0, sizeof s1); memset(&sk, 0, sizeof sk);
            render96(&bi, &c, gz, &ref, &s1);
            for (p = 0; p < 96u * 64u; ++p) interp += ref.mask[p] == 0;
            c.refresh = k;
            for (p = 0; p < 96u * 64u * 3u; ++p) im.rgb[p] = -1.0f;
            for (f = 0; f < k; ++f) {
                fovsdf_stats s;
                memset(&s, 0, sizeof s);
                c.frame = 100u + f; /* any k consecutive frames */
                render96(&bi, &c, gz, &im, &s);
                if (f + 2u == k)
                    for (p = 0; p < 96u * 64u; ++p) untouched_before += im.rgb[3 * p] < 0.0f;
                if (f + 1u == k) {
                    for (p = 0; p < 96u * 64u; ++p) kept_last += im.mask[p] == 2;
                    sk = s;
                }
            }
            check(interp > 2000 && untouched_before > interp / (2u * k) && memcmp(ref.rgb, im.rgb, sizeof im.rgb) == 0,
                  N(m ? "cone_fov_refresh_%s_static_equals_full" : "fipr_refresh_%s_static_equals_full", k == 2 ? "2" : "4"),
                  "%u interpolated pixels, %u untouched before the last frame, images %s", interp, untouched_before,
                  memcmp(ref.rgb, im.rgb, sizeof im.rgb) ? "differ" : "equal");
            /* one frame refreshes about 1/k of the interpolated pixels (whole tiles) and costs less */
            check(fabs((double)kept_last - (double)interp * (double)(k - 1u) / (double)k) < 0.1 * (double)interp &&
                      sk.evals < s1.evals,
                  N(m ? "cone_fov_refresh_%s_skips_its_share" : "fipr_refresh_%s_skips_its_share", k == 2 ? "2" : "4"),
                  "%u kept of %u interpolated; evaluations %llu vs %llu at refresh 1", kept_last, interp,
                  (unsigned long long)sk.evals, (unsigned long long)s1.evals);
        }
    free(mem);
}

/* The mask: the fovea is always traced; FOVEA policy = exactly the fovea; the ACUITY policy's
   density per ring follows p(w); the EDGES mask is a subset of the ACUITY mask (same seed) and,
   with p = 1 everywhere, it marks the silhouettes (every hit/miss boundary of a classic render
   is in it, and everything in it lies within a few pixels of a depth discontinuity). */
static void fov_mask_tests(void)
{
    static fovimgs ac, ed, fo, cl, s2;
    fovsdf_builtin bi;
    void *mem = load_builtin(FOVSDF_SCENE_PRIMITIVES, 96, 64, &bi);
    uint32_t m;
    fov_gaze gz = { 40.0f, 30.0f };
    for (m = 0; m < 2; ++m) {
        fovsdf_config c = fovsdf_config_default();
        fovsdf_ctx k;
        uint32_t x, y, bad_fovea = 0, bad_policy = 0, not_subset = 0, n_ed = 0, n_ac = 0, diff_seed = 0;
        c.method = m ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
        c.shading = FOVSDF_SHADE_NO_SHADOWS;
        c.acuity.fovea_deg = 6.0f;
        c.acuity.rate = 0.02f; /* a slow fall-off: many periphery pixels in play */
        c.seed = 3u;
        fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
        c.fov_mask = FOVSDF_MASK_ACUITY; render96(&bi, &c, gz, &ac, NULL);
        c.fov_mask = FOVSDF_MASK_EDGES; render96(&bi, &c, gz, &ed, NULL);
        c.fov_mask = FOVSDF_MASK_FOVEA; render96(&bi, &c, gz, &fo, NULL);
        c.fov_mask = FOVSDF_MASK_EDGES; c.seed = 4u; render96(&bi, &c, gz, &s2, NULL);
        for (y = 0; y < 64; ++y)
            for (x = 0; x < 96; ++x) {
                uint32_t p = y * 96 + x;
                float w = fovsdf_ecc_deg(&k.ecc, (float)x + 0.5f, (float)y + 0.5f);
                if (w <= 6.0f && (ac.mask[p] != 1 || ed.mask[p] != 1 || fo.mask[p] != 1)) ++bad_fovea;
                if ((fo.mask[p] == 1) != (w <= 6.0f)) ++bad_policy;
                if (ed.mask[p] == 1 && ac.mask[p] != 1) ++not_subset;
                n_ed += ed.mask[p] == 1 && w > 6.0f;
                n_ac += ac.mask[p] == 1 && w > 6.0f;
                diff_seed += (ed.mask[p] == 1) != (s2.mask[p] == 1);
            }
        check(bad_fovea == 0 && bad_policy == 0, N("%s_fovea_always_traced", fovsdf_method_name(c.method)),
              "%u fovea pixels not traced, %u FOVEA-policy pixels wrong", bad_fovea, bad_policy);
        check(not_subset == 0 && n_ed > 20 && n_ed < n_ac && diff_seed > 0,
              N("%s_edge_mask_subset_of_acuity", fovsdf_method_name(c.method)),
              "%u edge-mask pixels outside the acuity mask; periphery traced %u (edges) vs %u (acuity); %u differ with another seed",
              not_subset, n_ed, n_ac, diff_seed);
        {   /* p = 1 everywhere (rate ~0, A + C = 1): the EDGES mask outside the fovea = the edges */
            fovsdf_config g = fovsdf_config_default();
            uint32_t missed = 0, boundary = 0, far_from_edge = 0, marked = 0;
            c.acuity.A = 0.999f; c.acuity.C = 0.001f; c.acuity.rate = 1e-9f; c.acuity.fovea_deg = 1.0f;
            c.seed = 3u;
            render96(&bi, &c, gz, &ed, NULL);
            g.shading = FOVSDF_SHADE_NO_SHADOWS;
            render96(&bi, &g, gz, &cl, NULL);
            for (y = 1; y < 63; ++y)
                for (x = 1; x < 95; ++x) {
                    uint32_t p = y * 96 + x, i, j, near = 0;
                    int bnd = cl.hit[p] != cl.hit[p + 1] || cl.hit[p] != cl.hit[p + 96];
                    if (bnd) { ++boundary; if (ed.mask[p] != 1) ++missed; }
                    if (ed.mask[p] != 1) continue;
                    ++marked;
                    /* a relative depth jump of >= 5 % between pixels within 6 of this one */
                    {   /* the Sobel window: 3x3 cells of 4 (FIPR) or 2 (CONE_FOV) pixels */
                        uint32_t R = m ? 4u : 8u;
                        float lo = 1e30f, hi = 0.0f;
                        for (j = y > R ? y - R : 0; j < (y + R + 1 < 64 ? y + R + 1 : 64); ++j)
                            for (i = x > R ? x - R : 0; i < (x + R + 1 < 96 ? x + R + 1 : 96); ++i) {
                                float d0 = cl.depth[j * 96 + i];
                                lo = d0 < lo ? d0 : lo; hi = d0 > hi ? d0 : hi;
                            }
                        near = hi > 1.1f * lo; /* a relative depth change of 10 % somewhere */
                    }
                    if (!near) ++far_from_edge;
                }
            check(boundary > 50 && missed == 0 && marked > boundary && far_from_edge == 0,
                  N("%s_edges_are_silhouettes", fovsdf_method_name(c.method)),
                  "%u of %u silhouette pixels not marked; %u marked pixels, %u far from any depth jump", missed, boundary,
                  marked, far_from_edge);
        }
    }
    {   /* ACUITY density per 5-degree ring at 320x180 (CONE_FOV, cheap at 1 spp) */
        static uint8_t mk[320 * 180];
        fovsdf_builtin b2;
        void *m2 = load_builtin(FOVSDF_SCENE_PRIMITIVES, 320, 180, &b2);
        fovsdf_config c = fovsdf_config_default();
        fovsdf_ctx k;
        fovsdf_output o;
        fov_gaze g2 = { 100.0f, 60.0f };
        double sp[8] = { 0 }, n[8] = { 0 }, tr[8] = { 0 };
        uint32_t x, y, r, bad = 0;
        char where[128] = "";
        c.method = FOVSDF_METHOD_CONE_FOV;
        c.shading = FOVSDF_SHADE_DEPTH;
        c.fov_mask = FOVSDF_MASK_ACUITY;
        c.seed = 11u;
        fovsdf_init(&k, &c, &b2.scene, &b2.camera, g2, NULL, 0);
        fovsdf_output_init(&o);
        o.mask = mk;
        fovsdf_render_rows(&k, 0, 180, &o, NULL);
        for (y = 0; y < 180; ++y)
            for (x = 0; x < 320; ++x) {
                float w = fovsdf_ecc_deg(&k.ecc, (float)x + 0.5f, (float)y + 0.5f);
                fovsdf_acuity a = k.cfg.acuity;
                r = (uint32_t)(w / 5.0f);
                if (r > 7) r = 7;
                sp[r] += (double)fovsdf_acuity_p(&a, w);
                n[r] += 1.0;
                tr[r] += mk[y * 320 + x] == 1;
            }
        for (r = 0; r < 8; ++r) {
            double sd = sqrt(sp[r] * (1.0 - sp[r] / (n[r] > 0 ? n[r] : 1)) + 1.0);
            if (n[r] > 100 && fabs(tr[r] - sp[r]) > 4.0 * sd) {
                ++bad;
                snprintf(where, sizeof where, "ring %u: %.0f traced, %.1f expected of %.0f", r, tr[r], sp[r], n[r]);
            }
        }
        check(bad == 0, "cone_fov_acuity_mask_density", "%u rings off by more than 4 sd; %s", bad, where);
        free(m2);
    }
    free(mem);
}

/* Pixels in the mask are exactly the unfoveated method's pixels (IPR for FIPR, CONE for
   CONE_FOV); the others are the bilinear interpolation (weights 3/4, 1/4) of the mid level,
   whose rays are the pixel centres of the half-resolution image: checked against a classic
   half-resolution render interpolated here (depth shading, so colour = hit distance). */
static void fov_quality(void)
{
    static fovimgs f, u, t;
    static fovimgs h; /* 48x32 used */
    fovsdf_builtin bi, bh;
    void *mem = load_builtin(FOVSDF_SCENE_TEMPLE, 96, 64, &bi), *mh = load_builtin(FOVSDF_SCENE_TEMPLE, 48, 32, &bh);
    uint32_t m;
    fov_gaze gz = { 30.0f, 32.0f };
    for (m = 0; m < 2; ++m) {
        fovsdf_config c = fovsdf_config_default(), cu, ch = fovsdf_config_default();
        fovsdf_ctx kh;
        fovsdf_output oh;
        uint32_t x, y, traced = 0, same = 0, interp = 0, close = 0;
        double sad = 0.0;
        c.method = m ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
        c.shading = FOVSDF_SHADE_DEPTH;
        c.acuity.fovea_deg = 10.0f;
        c.fov_mask = FOVSDF_MASK_ACUITY;
        c.finish = FOVSDF_FINISH_CLASSIC; /* the reference's tracer, */
        c.max_steps = 4096;               /* and no ray runs out of steps at the horizon; */
        c.eps_mode = FOVSDF_EPS_ABSOLUTE; /* a pixel-cone epsilon would depend on the resolution */
        cu = c;
        cu.method = m ? FOVSDF_METHOD_CONE : FOVSDF_METHOD_IPR;
        render96(&bi, &c, gz, &f, NULL);
        render96(&bi, &cu, gz, &u, NULL);
        ch.shading = FOVSDF_SHADE_DEPTH;
        ch.max_steps = 4096;
        ch.eps_mode = FOVSDF_EPS_ABSOLUTE;
        fovsdf_init(&kh, &ch, &bh.scene, &bh.camera, gz, NULL, 0);
        fovsdf_output_init(&oh);
        oh.rgb = h.rgb;
        fovsdf_render_rows(&kh, 0, 32, &oh, NULL);
        (void)t;
        for (y = 0; y < 64; ++y)
            for (x = 0; x < 96; ++x) {
                uint32_t p = y * 96 + x;
                if (f.mask[p] == 1) {
                    ++traced;
                    same += memcmp(f.rgb + 3 * p, u.rgb + 3 * p, 3 * sizeof(float)) == 0;
                } else if (x >= 1 && y >= 1 && x + 1 < 96 && y + 1 < 64) {
                    int32_t ua = (x & 1) ? (int32_t)(x / 2) : (int32_t)(x / 2) - 1, va = (y & 1) ? (int32_t)(y / 2) : (int32_t)(y / 2) - 1;
                    double wx = (x & 1) ? 0.25 : 0.75, wy = (y & 1) ? 0.25 : 0.75, ref, d;
                    ref = (1 - wx) * (1 - wy) * (double)h.rgb[3 * (va * 48 + ua)] + wx * (1 - wy) * (double)h.rgb[3 * (va * 48 + ua + 1)] +
                          (1 - wx) * wy * (double)h.rgb[3 * ((va + 1) * 48 + ua)] + wx * wy * (double)h.rgb[3 * ((va + 1) * 48 + ua + 1)];
                    d = fabs(ref - (double)f.rgb[3 * p]);
                    ++interp;
                    close += d < 0.01;
                    sad += d;
                }
            }
        check(traced > 300 && same == traced, N("%s_traced_pixels_are_unfoveated", fovsdf_method_name(c.method)),
              "%u of %u traced pixels equal the unfoveated render", same, traced);
        check(interp > 2000 && close >= interp - interp / 100 && sad / interp < 2e-3,
              N("%s_interpolation_is_bilinear_of_mid_level", fovsdf_method_name(c.method)),
              "%u of %u interpolated pixels within 0.01 of the half-resolution classic render, mean |d| %.3g", close,
              interp, sad / (interp ? interp : 1));
    }
    free(mem);
    free(mh);
}

static void fov_bad_params(void)
{
    fovsdf_config c = fovsdf_config_default();
    fov_result r;
    c.method = FOVSDF_METHOD_FIPR;
    check(init_with(c) == FOV_OK, "fipr_default_config_ok", "init failed");
    c.refresh = 3; r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "fov_refresh_3_rejected", "got %d", (int)r);
    c.refresh = 4; c.edge_threshold = -0.1f; r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "fov_edge_threshold_negative", "got %d", (int)r);
    c.edge_threshold = 0.0f; c.acuity.fovea_deg = 10.0f; c.acuity.outer_deg = 5.0f; r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "fov_outer_inside_fovea", "got %d", (int)r);
    c.acuity.outer_deg = 0.0f; c.acuity.rate = NAN; r = init_with(c);
    check(r == FOV_ERR_NOT_FINITE, "fov_acuity_nan", "got %d", (int)r);
    c.acuity.rate = 0.0f; c.acuity.A = 0.995f; r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "fov_acuity_above_one", "got %d", (int)r);
    c.acuity.A = 0.0f; c.fov_mask = 3; r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "fov_mask_unknown", "got %d", (int)r);
    c.fov_mask = 0; c.ipr_tile = 64; r = init_with(c);
    check(r == FOV_ERR_LIMIT, "fipr_tile_above_scratch", "got %d", (int)r);
    c.ipr_tile = 0; c.method = FOVSDF_METHOD_CONE_FOV; c.cone_tile = 2; r = init_with(c);
    check(r == FOV_ERR_INVALID_ARG, "cone_fov_tile_2_rejected", "got %d", (int)r);
    c.cone_tile = 64; r = init_with(c);
    check(r == FOV_ERR_LIMIT, "cone_fov_tile_above_scratch", "got %d", (int)r);
    c.cone_tile = 32; r = init_with(c);
    check(r == FOV_OK, "cone_fov_tile_32_ok", "got %d", (int)r);
}

/* fovsdf_mask_blur: copies every pixel away from a traced/interpolated border, blurs the
   border pixels with the Gaussian computed here in double, keeps a constant image constant. */
static void mask_blur_tests(void)
{
    enum { W = 40, H = 30 };
    static float in[W * H * 3], out[W * H * 3], cst[W * H * 3], o2[W * H * 3];
    static uint8_t mk[W * H];
    uint32_t x, y, i, copied = 0, notcopied = 0, blurred = 0, badblur = 0, n_border = 0;
    double worst = 0.0;
    fov_result r, e1, e2, e3, e4, e5;
    rng g = { 99 };
    for (i = 0; i < W * H * 3; ++i) { in[i] = (float)urand(&g); cst[i] = 0.375f; }
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) mk[y * W + x] = (uint8_t)((x - 20) * (x - 20) + (y - 15) * (y - 15) < 64 ? 1 : (x % 7 == 0 ? 2 : 0));
    r = fovsdf_mask_blur(in, 0, mk, 0, W, H, 1.5f, out, 0);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            int has1 = 0, has0 = 0, a, b;
            for (b = -1; b <= 1; ++b)
                for (a = -1; a <= 1; ++a) {
                    int xx = (int)x + a, yy = (int)y + b;
                    if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
                    if (mk[yy * W + xx] == 1) has1 = 1; else has0 = 1;
                }
            if (!(has1 && has0)) {
                if (memcmp(out + 3 * (y * W + x), in + 3 * (y * W + x), 3 * sizeof(float)) == 0) ++copied; else ++notcopied;
            } else {
                double acc[3] = { 0, 0, 0 }, s = 0.0;
                int R = 5, c;
                ++n_border;
                for (b = -R; b <= R; ++b)
                    for (a = -R; a <= R; ++a) {
                        int xx = (int)x + a, yy = (int)y + b;
                        double k;
                        if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
                        k = exp(-0.5 * (a * a + b * b) / (1.5 * 1.5));
                        for (c = 0; c < 3; ++c) acc[c] += k * (double)in[3 * (yy * W + xx) + c];
                        s += k;
                    }
                for (c = 0; c < 3; ++c) {
                    double d = fabs(acc[c] / s - (double)out[3 * (y * W + x) + (uint32_t)c]);
                    if (d > worst) worst = d;
                    if (d > 1e-5) ++badblur;
                }
                ++blurred;
            }
        }
    check(r == FOV_OK && notcopied == 0 && n_border > 40 && badblur == 0, "mask_blur_border_only",
          "status %d; %u of %u non-border pixels changed; %u border pixels, worst difference to the Gaussian %.3g", (int)r,
          notcopied, copied + notcopied, blurred, worst);
    r = fovsdf_mask_blur(cst, 0, mk, 0, W, H, 3.0f, o2, 0);
    for (i = 0, notcopied = 0; i < W * H * 3; ++i) notcopied += fabsf(o2[i] - 0.375f) > 1e-6f;
    check(r == FOV_OK && notcopied == 0, "mask_blur_keeps_constant", "%u values changed", notcopied);
    e1 = fovsdf_mask_blur(NULL, 0, mk, 0, W, H, 1.0f, out, 0);
    e2 = fovsdf_mask_blur(in, 0, mk, 0, W, H, 0.0f, out, 0);
    e3 = fovsdf_mask_blur(in, 0, mk, 0, W, H, NAN, out, 0);
    e4 = fovsdf_mask_blur(in, 0, mk, 0, W, H, 1.0f, in, 0);
    e5 = fovsdf_mask_blur(in, 3 * W - 1, mk, 0, W, H, 1.0f, out, 0);
    {   /* the smallest sigma accepted gives finite values; below it (sigma^2 underflows) an error */
        fov_result e6 = fovsdf_mask_blur(in, 0, mk, 0, W, H, 0.05f, o2, 0), e7 = fovsdf_mask_blur(in, 0, mk, 0, W, H, 1e-30f, o2, 0);
        uint32_t nf = 0;
        for (i = 0; i < W * H * 3; ++i) nf += !(o2[i] >= 0.0f && o2[i] <= 1.0f);
        check(e6 == FOV_OK && nf == 0 && e7 == FOV_ERR_INVALID_ARG, "mask_blur_small_sigma", "status %d, %u bad values, tiny sigma %d",
              (int)e6, nf, (int)e7);
    }
    check(e1 == FOV_ERR_NULL && e2 == FOV_ERR_INVALID_ARG && e3 == FOV_ERR_NOT_FINITE && e4 == FOV_ERR_INVALID_ARG &&
              e5 == FOV_ERR_TOO_SMALL,
          "mask_blur_bad_params", "got %d %d %d %d %d", (int)e1, (int)e2, (int)e3, (int)e4, (int)e5);
}

/* Every method at tiny and odd sizes, every spp, gaze inside and far outside the image: no
   crash (the sanitizer build runs this too), finite colours, every pixel written. */
static void tiny_sizes(void)
{
    static const uint32_t sz[6][2] = { { 1, 1 }, { 2, 3 }, { 5, 1 }, { 1, 7 }, { 17, 9 }, { 33, 31 } };
    uint32_t s, m, k, bad = 0, runs = 0;
    char where[160] = "";
    for (s = 0; s < 6; ++s)
        for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m)
            for (k = 0; k < 3; ++k) {
                fovsdf_builtin bi;
                void *mem = load_builtin(FOVSDF_SCENE_PRIMITIVES, sz[s][0], sz[s][1], &bi);
                fovsdf_config c = fovsdf_config_default();
                fovsdf_ctx ctx;
                fovsdf_output o;
                fov_gaze gz;
                static float rgb[33 * 31 * 3];
                uint32_t i, n = sz[s][0] * sz[s][1] * 3;
                fov_result r;
                c.method = m;
                c.spp = k == 0 ? 1u : (k == 1 ? 4u : 16u);
                c.refresh = k == 2 ? 4u : 1u;
                c.frame = k;
                gz.x = k == 1 ? -500.0f : 0.3f * (float)sz[s][0];
                gz.y = k == 1 ? 900.0f : 0.6f * (float)sz[s][1];
                for (i = 0; i < n; ++i) rgb[i] = -1.0f;
                r = fovsdf_init(&ctx, &c, &bi.scene, &bi.camera, gz, NULL, 0);
                if (r == FOV_OK) {
                    fovsdf_output_init(&o);
                    o.rgb = rgb;
                    r = fovsdf_render_rows(&ctx, 0, sz[s][1], &o, NULL);
                }
                ++runs;
                for (i = 0; i < n; ++i)
                    if (!(rgb[i] >= 0.0f && rgb[i] < 100.0f) && !(c.refresh > 1u && rgb[i] == -1.0f)) break;
                if (r != FOV_OK || i < n) {
                    ++bad;
                    snprintf(where, sizeof where, "%ux%u %s spp %u: status %d, value %g at %u", sz[s][0], sz[s][1],
                             fovsdf_method_name(m), c.spp, (int)r, i < n ? (double)rgb[i] : 0.0, i);
                }
                free(mem);
            }
    check(bad == 0 && runs == 6u * 3u * (uint32_t)_FOVSDF_METHOD_NUM, "all_methods_tiny_sizes",
          "%u of %u renders failed; %s", bad, runs, where);
}

/* fovsdf_shade_point at the pixel centres gives the 1-spp render's pixels bit for bit, for a
   plain tracer and for a head-start method's finishing tracer; bad input is refused. */
static void shade_point_tests(void)
{
    fovsdf_builtin bi;
    void *mem = load_builtin(FOVSDF_SCENE_TEMPLE, 48, 32, &bi);
    static float img[48 * 32 * 3], dep[48 * 32];
    uint32_t m, x, y, same = 0, dsame = 0;
    fov_gaze gz = { 24.0f, 16.0f };
    fov_result e1 = FOV_OK, e2 = FOV_OK; /* assigned at m == 0; initialised for gcc -O2 -Wmaybe-uninitialized */
    for (m = 0; m < 2; ++m) {
        fovsdf_config c = fovsdf_config_default();
        fovsdf_ctx k;
        fovsdf_output o;
        c.method = m ? FOVSDF_METHOD_BV2018 : FOVSDF_METHOD_CLASSIC;
        fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
        fovsdf_output_init(&o);
        o.rgb = img; o.depth = dep;
        fovsdf_render_rows(&k, 0, 32, &o, NULL);
        for (y = 0; y < 32; ++y)
            for (x = 0; x < 48; ++x) {
                float rgb[3], t;
                int32_t mat;
                fovsdf_shade_point(&k, (float)x + 0.5f, (float)y + 0.5f, rgb, &t, &mat, NULL);
                same += memcmp(rgb, img + 3 * (y * 48 + x), sizeof rgb) == 0;
                dsame += t == dep[y * 48 + x];
            }
        if (m == 0) {
            float rgb[3];
            e1 = fovsdf_shade_point(&k, NAN, 1.0f, rgb, NULL, NULL, NULL);
            e2 = fovsdf_shade_point(&k, 1.0f, 1.0f, NULL, NULL, NULL, NULL);
        }
    }
    check(same == 2u * 48u * 32u && dsame == 2u * 48u * 32u && e1 == FOV_ERR_NOT_FINITE && e2 == FOV_ERR_NULL,
          "shade_point_equals_render", "%u of %u colours and %u depths equal; errors %d %d", same, 2u * 48u * 32u, dsame,
          (int)e1, (int)e2);
    free(mem);
}

int main(void)
{
    acuity_tests();
    u01_tests();
    mask_density_tests();
    skip_tests();
    min_filter_tests();
    ipr_bad_params();
    ipr_tests();
    partition_invariant(FOVSDF_METHOD_CONE, FOVSDF_SCENE_PRIMITIVES, 4);
    partition_invariant(FOVSDF_METHOD_IPR, FOVSDF_SCENE_ATRIUM, 1);
    partition_invariant(FOVSDF_METHOD_SKIP, FOVSDF_SCENE_COLUMNS, 1);
    partition_invariant(FOVSDF_METHOD_FIPR, FOVSDF_SCENE_TEMPLE, 4);
    partition_invariant(FOVSDF_METHOD_CONE_FOV, FOVSDF_SCENE_PRIMITIVES, 1);
    fov_bad_params();
    fov_equal_unfoveated();
    fov_temporal_reuse();
    fov_mask_tests();
    fov_quality();
    mask_blur_tests();
    tiny_sizes();
    shade_point_tests();
    bad_params();
    cone_vs_classic();
    cone_property();
    return fovcheck_summary();
}
