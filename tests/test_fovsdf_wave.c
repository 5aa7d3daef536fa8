/* test_fovsdf_wave.c - the wavefront renderer of fovsdf.h gives the same bytes whatever feeds
   it: a scene's batch callback or its per-point one, any split of the image into rows and
   tiles, and (for the ray tracers) the point-by-point path of fovsdf_shade_point. Prints
   "INFO hash" lines that tests/wave_variants.sh compares across builds with other
   FOVSDF_BATCH, FOVSDF_WAVE and FOVSDF_NO_SIMD (built with WAVE_HASH_ONLY: the hashes only).
   A quarter of the scene and method pairs render with config.shadow_fov_deg (cheaper shadow
   rays beyond an eccentricity), whose choice per ray must not depend on the path either. */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fovcheck.h"

#include <string.h>

#ifndef IMG_W /* smaller under the sanitizers (10x slower) */
#if defined(__SANITIZE_ADDRESS__)
#define IMG_W 24
#define IMG_H 14
#else
#define IMG_W 48
#define IMG_H 27
#endif
#endif
#define W IMG_W
#define H IMG_H
static float g_rgb[W * H * 3], g_depth[W * H], g_start[W * H];
static uint32_t g_ev[W * H], g_steps[W * H];
static int32_t g_mat[W * H];
static uint8_t g_hit[W * H], g_mask[W * H];
static const fov_gaze g_gaze = { 0.35f, 0.55f };

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i) { h ^= b[i]; h *= 1099511628211ull; }
    return h;
}

static uint64_t g_counts; /* the last render's per-pixel evaluation counts (see render) */

/* Renders into the globals; split: 0 whole, k > 0 rows of k, -k tiles of k x k. Returns the
   hash of the image (every output but the per-pixel evaluation counts); g_counts gets the hash
   of those counts. (The shadow proofs work on groups of rays, so the counts depend on how
   pixels were grouped: the split, FOVSDF_WAVE, the kind of callback; the image never does.) */
static uint64_t render(const fovsdf_ctx *c, int split, fovsdf_stats *st)
{
    fovsdf_output o;
    uint64_t h = 1469598103934665603ull;
    fovsdf_output_init(&o);
    o.rgb = g_rgb; o.depth = g_depth; o.start = g_start; o.evals = g_ev; o.steps = g_steps;
    o.material = g_mat; o.hit = g_hit; o.mask = g_mask;
    memset(g_mask, 9, sizeof g_mask);
    fovsdf_stats_init(st);
    if (split == 0) {
        fovsdf_render_rows(c, 0, H, &o, st);
    } else if (split > 0) {
        uint32_t y, k = (uint32_t)split;
        for (y = 0; y < H; y += k) fovsdf_render_rows(c, y, y + k < H ? y + k : H, &o, st);
    } else {
        uint32_t x, y, k = (uint32_t)-split;
        for (y = 0; y < H; y += k)
            for (x = 0; x < W; x += k)
                fovsdf_render_tile(c, x, y, x + k < W ? x + k : W, y + k < H ? y + k : H, &o, st);
    }
    h = fnv(h, g_rgb, sizeof g_rgb); h = fnv(h, g_depth, sizeof g_depth);
    h = fnv(h, g_start, sizeof g_start);
    g_counts = fnv(1469598103934665603ull, g_ev, sizeof g_ev);
    h = fnv(h, g_steps, sizeof g_steps); h = fnv(h, g_mat, sizeof g_mat);
    h = fnv(h, g_hit, sizeof g_hit); h = fnv(h, g_mask, sizeof g_mask);
    return h;
}
static uint64_t stats_hash(const fovsdf_stats *st)
{
    return fnv(1469598103934665603ull, st, sizeof *st);
}

/* A user batch callback: the program point by point (what a user wraps around a C SDF). */
static void batch_by_points(fovsdf_batch *b, void *user)
{
    uint32_t i;
    for (i = 0; i < b->n; ++i) {
        fovsdf_query q;
        float p[3];
        memset(&q, 0, sizeof q);
        q.inflate = b->inflate; q.eps = b->eps ? b->eps[i] : 0.0f; q.want_material = 1;
        p[0] = b->x[i]; p[1] = b->y[i]; p[2] = b->z[i];
        b->d[i] = fovsdf_program_eval(p, &q, user);
        if (b->material) b->material[i] = q.material;
        b->prims += q.prims; b->prims_skipped += q.prims_skipped;
    }
}

int main(void)
{
    static unsigned char mem[1 << 20];
    uint32_t id, meth;
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        fovsdf_builtin bi;
        fovsdf_camera cam;
        if (fovsdf_builtin_init(id, &bi, mem, sizeof mem) != FOV_OK) {
            check(0, "builtin", "%u", id);
            continue;
        }
        cam = bi.camera; cam.width = W; cam.height = H;
        for (meth = 0; meth < (uint32_t)_FOVSDF_METHOD_NUM; ++meth) {
            fovsdf_config cfg = fovsdf_config_default();
            fovsdf_scene sp = bi.scene, su = bi.scene;
            fovsdf_ctx c;
            fovsdf_stats st, st2;
            uint64_t h0, s0, h1, s1;
            const char *mn = fovsdf_method_name(meth);
            int k, bad;
            cfg.method = meth;
            cfg.spp = (meth + id) % 3 == 0 ? 4u : 1u;
            cfg.heuristic_start = id & 1u;
            cfg.shading = (id == 1 && meth == 2) ? FOVSDF_SHADE_STEPS : FOVSDF_SHADE_FULL;
            /* a quarter of the pairs with cheaper shadow rays beyond 5 degrees of the gaze (the
               gaze near the corner: both sides in the image), one with a step budget too */
            if ((meth + id) % 4u == 2u) cfg.shadow_fov_deg = 5.0f;
            if (id == 2 && meth == 0) cfg.shadow_fov_steps = 6;
            if (fovsdf_init(&c, &cfg, &bi.scene, &cam, g_gaze, 0, 0) != FOV_OK) {
                check(0, "init", "%s %s", bi.name, mn);
                continue;
            }
            h0 = render(&c, 0, &st); s0 = stats_hash(&st) ^ g_counts;
            fovcheck_info("hash %s %s %016llx", bi.name, mn, (unsigned long long)h0);
            fovcheck_info("counts %s %s %016llx", bi.name, mn, (unsigned long long)s0);
#ifdef WAVE_HASH_ONLY /* tests/wave_variants.sh: the hashes are what it compares */
            check(h0 != 0, fovcheck_name("%s_%s_rendered", bi.name, mn), "-");
            continue;
#endif
            /* per-point callbacks only: the library batches around them */
            sp.dist_batch = 0;
            fovsdf_init(&c, &cfg, &sp, &cam, g_gaze, 0, 0);
            h1 = render(&c, 0, &st2); s1 = stats_hash(&st2) ^ g_counts;
            check(h1 == h0 && s1 == s0, fovcheck_name("%s_%s_per_point_same", bi.name, mn),
                  "%016llx vs %016llx", (unsigned long long)h1, (unsigned long long)h0);
            /* a user batch callback that evaluates point by point */
            su.dist_batch = batch_by_points;
            fovsdf_init(&c, &cfg, &su, &cam, g_gaze, 0, 0);
            h1 = render(&c, 0, &st2);
            (void)s1;
            check(h1 == h0, fovcheck_name("%s_%s_user_batch_same", bi.name, mn),
                  "%016llx vs %016llx", (unsigned long long)h1, (unsigned long long)h0);
            /* any split into rows and tiles (the split changes only the cost) */
            fovsdf_init(&c, &cfg, &bi.scene, &cam, g_gaze, 0, 0);
            bad = 0;
            {
                static const int splits[3] = { 1, 5, -7 };
                for (k = 0; k < 3; ++k) {
                    h1 = render(&c, splits[k], &st2);
                    if (h1 != h0) bad |= 1 << k;
                }
            }
            check(bad == 0, fovcheck_name("%s_%s_split_same", bi.name, mn), "splits %x differ",
                  bad);
            /* the ray tracers: each pixel equals the point-by-point path (fovsdf_shade_point) */
            if (meth <= (uint32_t)FOVSDF_METHOD_BV2018 && cfg.spp == 1u && id % 2 == 0 &&
                cfg.shading == FOVSDF_SHADE_FULL) {
                uint32_t x, y, diff = 0;
                (void)render(&c, 0, &st2);
                for (y = 0; y < H; ++y)
                    for (x = 0; x < W; ++x) {
                        float rgb[3], t;
                        int32_t m;
                        fovsdf_shade_point(&c, (float)x + 0.5f, (float)y + 0.5f, rgb, &t, &m, 0);
                        /* (a hit at exactly t_max is depth t_max and material -1 in the image,
                           the hit's material from fovsdf_shade_point) */
                        if (memcmp(rgb, &g_rgb[3 * (y * W + x)], sizeof rgb) != 0 ||
                            memcmp(&t, &g_depth[y * W + x], sizeof t) != 0 ||
                            (t < c.t_max && m != g_mat[y * W + x]))
                            ++diff;
                    }
                check(diff == 0, fovcheck_name("%s_%s_equals_shade_point", bi.name, mn),
                      "%u pixels differ", diff);
            }
        }
    }
    /* fovsdf_shade_points: each point bit for bit fovsdf_shade_point's, counters summed */
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; id += 2) {
        fovsdf_builtin bi;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx c;
        fovsdf_stats s1, s2;
        static float xy[3 * 300], rgb1[3 * 300], rgb2[3 * 300], t1[300], t2[300];
        static int32_t m1[300], m2[300];
        uint32_t i, diff = 0, seed = 7u + id;
        fovsdf_builtin_init(id, &bi, mem, sizeof mem);
        cam = bi.camera; cam.width = W; cam.height = H;
        cfg.method = id == 2 ? FOVSDF_METHOD_CONE : FOVSDF_METHOD_CLASSIC;
        fovsdf_init(&c, &cfg, &bi.scene, &cam, g_gaze, 0, 0);
        for (i = 0; i < 300; ++i) { /* stride 3, as fovlp_sample: x, y, slot */
            seed = seed * 1664525u + 1013904223u;
            xy[3 * i] = (float)(seed >> 8) * (1.3f * (float)W / 16777216.0f) - 0.15f * (float)W;
            seed = seed * 1664525u + 1013904223u;
            xy[3 * i + 1] = (float)(seed >> 8) * (1.3f * (float)H / 16777216.0f) - 0.15f * (float)H;
            xy[3 * i + 2] = -1.0f;
        }
        fovsdf_stats_init(&s1); fovsdf_stats_init(&s2);
        for (i = 0; i < 300; ++i)
            fovsdf_shade_point(&c, xy[3 * i], xy[3 * i + 1], rgb1 + 3 * i, &t1[i], &m1[i], &s1);
        check(fovsdf_shade_points(&c, 300, xy, 3, rgb2, t2, m2, &s2) == FOV_OK,
              fovcheck_name("%s_shade_points_ok", bi.name), "-");
        for (i = 0; i < 300; ++i)
            if (memcmp(rgb1 + 3 * i, rgb2 + 3 * i, 12) || memcmp(&t1[i], &t2[i], 4) ||
                m1[i] != m2[i])
                ++diff;
        /* the same work but for the shadow proofs, which can only save evaluations */
        check(diff == 0 && s1.rays == s2.rays && s1.evals_primary == s2.evals_primary &&
                  s1.evals_normal == s2.evals_normal && s1.hits == s2.hits &&
                  s1.shadow_rays == s2.shadow_rays && s2.evals_shadow <= s1.evals_shadow &&
                  s2.evals <= s1.evals,
              fovcheck_name("%s_shade_points_equal_shade_point", bi.name),
              "%u points differ, evals %llu vs %llu", diff, (unsigned long long)s1.evals,
              (unsigned long long)s2.evals);
        check(fovsdf_shade_points(&c, 300, xy, 3, rgb2, 0, 0, 0) == FOV_OK &&
                  memcmp(rgb1, rgb2, sizeof rgb1) == 0,
              fovcheck_name("%s_shade_points_optional_outputs", bi.name), "-");
        if (id == 0) {
            float bad[4] = { 1.0f, 2.0f, 3.0f, 0.0f };
            fov_result e1, e2, e3, e4, e5;
            bad[3] = bad[3] / bad[3]; /* NaN */
            e1 = fovsdf_shade_points(&c, 2, bad, 0, rgb2, 0, 0, 0);
            e2 = fovsdf_shade_points(&c, 2, 0, 0, rgb2, 0, 0, 0);
            e3 = fovsdf_shade_points(&c, 2, xy, 1, rgb2, 0, 0, 0);
            bad[3] = 3e38f; bad[2] = 3e38f;
            e4 = fovsdf_shade_points(&c, 2, bad, 0, rgb2, 0, 0, 0);
            e5 = fovsdf_shade_points(&c, 0, 0, 0, 0, 0, 0, 0);
            check(e1 == FOV_ERR_NOT_FINITE && e2 == FOV_ERR_NULL && e3 == FOV_ERR_INVALID_ARG &&
                      e5 == FOV_OK && (e4 == FOV_OK || e4 == FOV_ERR_INVALID_ARG),
                  "shade_points_errors", "%d %d %d %d %d", (int)e1, (int)e2, (int)e3, (int)e4,
                  (int)e5);
        }
    }
    /* fovsdf_shade_points_grouped: group 0 and 1 are fovsdf_shade_points bit for bit; with
       groups, no point's hit lies beyond its first hit (the ground truth's: a head start past
       a surface would find the one behind it or miss), and the head starts save primary
       evaluations. Points in clusters of 8 around random centres (radius 0.5, 3 or 20
       pixels), a few scattered wide, off the image too. */
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        fovsdf_builtin bi;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default(), gcfg = fovsdf_config_ground_truth();
        fovsdf_ctx c, gc;
        fovsdf_stats s0, s8;
        enum { NP = 400 };
        static float xy[2 * NP], r0[3 * NP], r1[3 * NP], t0[NP], t1[NP], tg[NP], rg[3];
        static int32_t m0[NP], m1[NP];
        static const uint32_t groups[5] = { 1u, 2u, 8u, 37u, 256u };
        uint32_t i, k, seed = 99u + id, beyond = 0, hits = 0;
        float cx = 0.0f, cy = 0.0f, rad = 1.0f;
        fovsdf_builtin_init(id, &bi, mem, sizeof mem);
        cam = bi.camera; cam.width = W; cam.height = H;
        fovsdf_init(&c, &cfg, &bi.scene, &cam, g_gaze, 0, 0);
        fovsdf_init(&gc, &gcfg, &bi.scene, &cam, g_gaze, 0, 0);
        for (i = 0; i < NP; ++i) {
            float u, v;
            if (i % 8u == 0u) {
                static const float radii[3] = { 0.5f, 3.0f, 20.0f };
                seed = seed * 1664525u + 1013904223u;
                cx = (float)(seed >> 8) * (1.2f * (float)W / 16777216.0f) - 0.1f * (float)W;
                seed = seed * 1664525u + 1013904223u;
                cy = (float)(seed >> 8) * (1.2f * (float)H / 16777216.0f) - 0.1f * (float)H;
                rad = i % 80u == 72u ? 2.0f * (float)W : radii[(i / 8u) % 3u];
            }
            seed = seed * 1664525u + 1013904223u;
            u = (float)(seed >> 8) / 16777216.0f - 0.5f;
            seed = seed * 1664525u + 1013904223u;
            v = (float)(seed >> 8) / 16777216.0f - 0.5f;
            xy[2 * i] = cx + 2.0f * rad * u; xy[2 * i + 1] = cy + 2.0f * rad * v;
        }
        fovsdf_stats_init(&s0);
        check(fovsdf_shade_points(&c, NP, xy, 0, r0, t0, m0, &s0) == FOV_OK,
              fovcheck_name("%s_grouped_reference_ok", bi.name), "-");
        for (k = 0; k < 2u; ++k) {
            check(fovsdf_shade_points_grouped(&c, NP, xy, 2, k, r1, t1, m1, 0) == FOV_OK &&
                      memcmp(r0, r1, sizeof r0) == 0 && memcmp(t0, t1, sizeof t0) == 0 &&
                      memcmp(m0, m1, sizeof m0) == 0,
                  fovcheck_name("%s_grouped_%u_is_shade_points", bi.name, k), "-");
        }
        for (i = 0; i < NP; ++i) {
            fovsdf_shade_point(&gc, xy[2 * i], xy[2 * i + 1], rg, &tg[i], 0, 0);
            if (!(t0[i] <= tg[i] * 1.001f + 1e-3f)) ++beyond; /* the check checks itself */
        }
        check(beyond == 0, fovcheck_name("%s_shade_point_never_beyond_first_hit", bi.name),
              "%u points", beyond);
        for (k = 1; k < 5u; ++k) {
            fovsdf_stats_init(&s8);
            beyond = 0; hits = 0;
            check(fovsdf_shade_points_grouped(&c, NP, xy, 0, groups[k], r1, t1, m1, &s8) ==
                      FOV_OK,
                  fovcheck_name("%s_grouped_%u_ok", bi.name, groups[k]), "-");
            for (i = 0; i < NP; ++i) {
                if (t1[i] < c.t_max) ++hits;
                if (!(t1[i] <= tg[i] * 1.001f + 1e-3f) || !(r1[3 * i] >= 0.0f)) ++beyond;
            }
            check(beyond == 0 && hits > 0,
                  fovcheck_name("%s_grouped_%u_never_beyond_first_hit", bi.name, groups[k]),
                  "%u of %u points beyond (or NaN), %u hits", beyond, (unsigned)NP, hits);
            if (groups[k] == 8u)
                check(s8.evals_lowres > 0 && s8.evals_primary + s8.evals_lowres < s0.evals_primary,
                      fovcheck_name("%s_grouped_8_saves_primary_evaluations", bi.name),
                      "lowres %llu + primary %llu vs %llu", (unsigned long long)s8.evals_lowres,
                      (unsigned long long)s8.evals_primary, (unsigned long long)s0.evals_primary);
        }
        if (id == 0) {
            float bad[4] = { 1.0f, 2.0f, 3.0f, 0.0f };
            fov_result e1, e2, e3, e4;
            bad[3] = bad[3] / bad[3]; /* NaN */
            e1 = fovsdf_shade_points_grouped(&c, 2, bad, 0, 8, r1, 0, 0, 0);
            e2 = fovsdf_shade_points_grouped(&c, 2, xy, 0, 257, r1, 0, 0, 0);
            e3 = fovsdf_shade_points_grouped(&c, 0, 0, 0, 8, 0, 0, 0, 0);
            e4 = fovsdf_shade_points_grouped(0, 2, xy, 0, 8, r1, 0, 0, 0);
            check(e1 == FOV_ERR_NOT_FINITE && e2 == FOV_ERR_INVALID_ARG && e3 == FOV_OK &&
                      e4 == FOV_ERR_NULL,
                  "shade_points_grouped_errors", "%d %d %d %d", (int)e1, (int)e2, (int)e3,
                  (int)e4);
        }
    }
    return fovcheck_summary();
}
