/* test_fovsdf_prune.c - per-tile pruning of the built-in program in fovsdf.h (fovsdf__prune,
   issue 12): wherever the library may use a pruned program (a point that fovsdf__in_cone
   admits, a threshold in the pruned range, inflate 1), it gives exactly the full program's
   distance, material, prims and prims_skipped, bit for bit.
   1. Property test: random scenes from the builder (random primitives, operators, transforms,
      clusters of small primitives under nested transforms, so that bounds nest and sit under
      translate / rotate / scale / mirror / repeat), random cones (apex, axis, half-angle from
      0.001 to 1.5, t ranges short and long) and thresholds, random points inside each cone
      (a share on its boundary): the pruned program against the full one, through
      fovsdf_program_eval and fovsdf_program_eval_batch. Each rule must have fired, and the
      same comparison at points outside the cones must find differences (it can fail).
   2. The built-in scenes with their real tile cones (CONE's tiles, CONE_FOV's tiles with their
      apron), the same comparison.
   3. Renders: every built-in scene with CONE and CONE_FOV, pruning forced on for every tile
      (FOVSDF_PRUNE_MIN 0), against the same scene behind wrapper callbacks (the library
      cannot prune those; their batch callback gets the tile's cone): identical images, depths,
      materials, evaluation counts and stats; every point of a batch that comes with a cone lies
      in it (checked in double). */
#define FOVSDF_PRUNE_CODE 2048 /* pruning on (default 0), long enough for the random programs */
#define FOVSDF_PRUNE_MIN 0     /* every tile that can be pruned uses its pruned program */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

static uint32_t g_rng = 424242u;
static float rnd(void) /* [0, 1) */
{
    g_rng = g_rng * 1664525u + 1013904223u;
    return (float)(g_rng >> 8) * (1.0f / 16777216.0f);
}
static float rr(float a, float b) { return a + (b - a) * rnd(); }
static uint32_t bits(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

/* ---- random scenes ---------------------------------------------------------------------- */
static int32_t rprim(fovsdf_builder *b, int allow_unbounded)
{
    int32_t x;
    int k = (int)(rnd() * (allow_unbounded ? 12.0f : 8.0f));
    switch (k) {
    case 0: x = fovsdf_sphere(b, rr(0.05f, 1.0f)); break;
    case 1: x = fovsdf_box(b, rr(0.05f, 1.0f), rr(0.05f, 1.0f), rr(0.05f, 1.0f)); break;
    case 2: x = fovsdf_round_box(b, rr(0.2f, 1.0f), rr(0.2f, 1.0f), rr(0.2f, 1.0f), rr(0.0f, 0.2f));
        break;
    case 3:
        x = fovsdf_box_frame(b, rr(0.2f, 1.0f), rr(0.2f, 1.0f), rr(0.2f, 1.0f), rr(0.02f, 0.1f));
        break;
    case 4: x = fovsdf_torus(b, rr(0.0f, 1.0f), rr(0.05f, 0.3f)); break;
    case 5: {
        float a[3], c[3];
        a[0] = rr(-1, 1); a[1] = rr(-1, 1); a[2] = rr(-1, 1);
        c[0] = rr(-1, 1); c[1] = rr(-1, 1); c[2] = rr(-1, 1);
        x = fovsdf_capsule(b, a, c, rr(0.05f, 0.3f));
        break;
    }
    case 6: x = fovsdf_cylinder(b, rr(0.1f, 1.0f), rr(0.1f, 0.5f)); break;
    case 7: x = fovsdf_cone(b, rr(0.2f, 1.0f), rr(0.0f, 0.5f), rr(0.1f, 0.5f)); break;
    case 8: x = fovsdf_plane(b, rr(-1, 1), 1.0f, rr(-1, 1), rr(0.5f, 4.0f)); break;
    case 9: x = fovsdf_menger(b, rr(0.3f, 1.0f), 1 + (int32_t)(rnd() * 3.0f)); break;
    case 10: x = fovsdf_mandelbulb(b, 8.0f, 4); break;
    default: x = fovsdf_terrain(b, rr(0.1f, 0.5f), rr(0.5f, 2.0f), 3); break;
    }
    b->material = (int32_t)(rnd() * 7.0f);
    return x;
}

static int32_t rxform(fovsdf_builder *b, int32_t x)
{
    switch ((int)(rnd() * 6.0f)) {
    case 0: case 1: return fovsdf_translate(b, x, rr(-6, 6), rr(-2, 2), rr(-6, 6));
    case 2: return fovsdf_rotate(b, x, rr(-1, 1), rr(-1, 1), 1.0f, rr(-180, 180));
    case 3: return fovsdf_scale(b, x, rr(0.3f, 3.0f));
    case 4: return fovsdf_repeat(b, x, rr(1, 6), 0.0f, rr(1, 6), (int32_t)(rnd() * 3.0f), 0,
                                 (int32_t)(rnd() * 3.0f));
    default: return fovsdf_mirror(b, x, 1 + (int32_t)(rnd() * 7.0f));
    }
}

/* A cluster of small bounded primitives in plain unions (the build turns it into a bounding
   hierarchy), some of them clusters again under a transform (bounds under transforms). */
static int32_t cluster(fovsdf_builder *b, int n, int depth)
{
    int32_t u = -1;
    int i;
    for (i = 0; i < n; ++i) {
        int32_t s;
        if (depth > 0 && rnd() < 0.2f)
            s = rxform(b, cluster(b, 3 + (int)(rnd() * 5.0f), depth - 1));
        else
            s = rprim(b, 0);
        s = fovsdf_translate(b, s, rr(-8, 8), rr(-2, 2), rr(-8, 8));
        u = u < 0 ? s : fovsdf_union(b, u, s);
    }
    return u;
}

static int32_t rtree(fovsdf_builder *b, int depth)
{
    int32_t x, y;
    if (depth == 0 || rnd() < 0.25f) return rprim(b, 1);
    if (rnd() < 0.3f) return cluster(b, 2 + (int)(rnd() * 8.0f), 1);
    if (rnd() < 0.6f) {
        y = rtree(b, depth - 1);
        x = rtree(b, depth - 1);
        switch ((int)(rnd() * 8.0f)) {
        case 0: case 1: case 2: return fovsdf_union(b, x, y);
        case 3: return fovsdf_subtract(b, x, y);
        case 4: return fovsdf_intersect(b, x, y);
        case 5: return fovsdf_smooth_union(b, x, y, rr(0.05f, 0.5f));
        case 6: return fovsdf_smooth_subtract(b, x, y, rr(0.05f, 0.5f));
        default: return fovsdf_smooth_intersect(b, x, y, rr(0.05f, 0.5f));
        }
    }
    x = rtree(b, depth - 1);
    if (rnd() < 0.2f) return fovsdf_round(b, x, rr(0.0f, 0.1f));
    if (rnd() < 0.2f) return fovsdf_onion(b, x, rr(0.01f, 0.1f));
    return rxform(b, x);
}

/* ---- the comparison ------------------------------------------------------------------------ */
#define NPT 512
static float g_x[NPT], g_y[NPT], g_z[NPT], g_e[NPT];

typedef struct tally {
    uint64_t points, admitted, bad_value, bad_mat, bad_counts, bad_batch;
    uint64_t ins_full, ins_pruned, prims_full, prims_pruned, rules[3], programs;
} tally;

/* A random point of cone q: t in [t0, t1], angle up to the half-angle (some on the boundary,
   some at the ends of the t range). */
static void cone_point(const fovsdf_ray_cone *q, float p[3])
{
    double a[3] = { (double)q->axis[0], (double)q->axis[1], (double)q->axis[2] };
    double u1[3], u2[3], l, th, ph, t, d[3];
    double alpha = atan((double)q->tan_half);
    int k;
    /* an orthonormal basis around the axis */
    if (fabs(a[0]) < 0.6) { u1[0] = 0.0; u1[1] = -a[2]; u1[2] = a[1]; }
    else { u1[0] = -a[2]; u1[1] = 0.0; u1[2] = a[0]; }
    l = sqrt(u1[0] * u1[0] + u1[1] * u1[1] + u1[2] * u1[2]);
    for (k = 0; k < 3; ++k) u1[k] /= l;
    u2[0] = a[1] * u1[2] - a[2] * u1[1];
    u2[1] = a[2] * u1[0] - a[0] * u1[2];
    u2[2] = a[0] * u1[1] - a[1] * u1[0];
    th = rnd() < 0.25f ? alpha * (1.0 - 1e-6) : alpha * sqrt((double)rnd());
    ph = 6.283185307179586 * (double)rnd();
    t = rnd() < 0.1f ? (rnd() < 0.5f ? (double)q->t0 * (1.0 + 1e-6) : (double)q->t1 * (1.0 - 1e-6))
                     : (double)q->t0 + ((double)q->t1 - (double)q->t0) * (double)rnd();
    for (k = 0; k < 3; ++k)
        d[k] = cos(th) * a[k] + sin(th) * (cos(ph) * u1[k] + sin(ph) * u2[k]);
    for (k = 0; k < 3; ++k) p[k] = (float)((double)q->apex[k] + t * d[k]);
}

/* Points of cone q (inside: 1) or beside it (0), thresholds in [e_lo, e_hi]; compares the
   pruned program with the full one at the points fovsdf__in_cone admits (inside) or at every
   point (outside: the control). Returns the number of points compared. */
static uint32_t compare(const fovsdf_program *full, const fovsdf__pruned *pv, int inside,
                        tally *ty)
{
    const fovsdf_ray_cone *q = &pv->cone;
    uint32_t n = 0, i, tries;
    float bd[2][NPT];
    int32_t bm[2][NPT];
    for (tries = 0; tries < 4 * NPT && n < NPT; ++tries) {
        float p[3];
        if (inside) {
            cone_point(q, p);
            ty->points++;
            if (!fovsdf__in_cone(q, p[0], p[1], p[2])) continue;
            ty->admitted++;
        } else { /* beside the cone: within a few of its radii */
            fovsdf_ray_cone w = *q;
            w.tan_half = q->tan_half * rr(1.5f, 4.0f) + 0.05f;
            w.t1 = q->t1 * 1.5f + 1.0f;
            cone_point(&w, p);
            if (fovsdf__in_cone(q, p[0], p[1], p[2])) continue;
        }
        g_x[n] = p[0]; g_y[n] = p[1]; g_z[n] = p[2];
        g_e[n] = rnd() < 0.2f ? (rnd() < 0.5f ? pv->e_lo : pv->e_hi) : rr(pv->e_lo, pv->e_hi);
        ++n;
    }
    for (i = 0; i < n; ++i) {
        fovsdf_query qa, qb;
        float p[3], da, db;
        p[0] = g_x[i]; p[1] = g_y[i]; p[2] = g_z[i];
        memset(&qa, 0, sizeof qa); qa.inflate = 1.0f; qa.eps = g_e[i]; qa.want_material = 1;
        qb = qa;
        da = fovsdf_program_eval(p, &qa, (void *)(uintptr_t)full);
        db = fovsdf_program_eval(p, &qb, (void *)(uintptr_t)&pv->prog);
        if (bits(da) != bits(db)) ty->bad_value++;
        if (qa.material != qb.material) ty->bad_mat++;
        if (qa.prims != qb.prims || qa.prims_skipped != qb.prims_skipped) ty->bad_counts++;
        ty->prims_full += qa.prims; ty->prims_pruned += qb.prims;
    }
    { /* the batch evaluator, in batches of random sizes */
        uint32_t k, s;
        uint64_t cp[2] = { 0, 0 }, cs[2] = { 0, 0 };
        for (s = 0; s < 2; ++s) {
            const fovsdf_program *pg = s == 0 ? full : &pv->prog;
            for (k = 0; k < n;) {
                fovsdf_batch b;
                uint32_t m = 1u + (uint32_t)(rnd() * (float)FOVSDF_BATCH);
                if (m > n - k) m = n - k;
                memset(&b, 0, sizeof b);
                b.n = m; b.x = g_x + k; b.y = g_y + k; b.z = g_z + k; b.eps = g_e + k;
                b.inflate = 1.0f; b.d = bd[s] + k; b.material = bm[s] + k; b.cone = q;
                fovsdf_program_eval_batch(&b, (void *)(uintptr_t)pg);
                cp[s] += b.prims; cs[s] += b.prims_skipped;
                k += m;
            }
        }
        for (i = 0; i < n; ++i)
            if (bits(bd[0][i]) != bits(bd[1][i]) || bm[0][i] != bm[1][i]) ty->bad_batch++;
        if (cp[0] != cp[1] || cs[0] != cs[1]) ty->bad_batch++;
    }
    return n;
}

static void add_rules(tally *ty, const fovsdf_program *full, const fovsdf__pruned *pv)
{
    ty->programs++;
    ty->ins_full += full->count; ty->ins_pruned += pv->prog.count;
    ty->rules[0] += pv->rules[0]; ty->rules[1] += pv->rules[1]; ty->rules[2] += pv->rules[2];
}

static int report(const char *name_in, const tally *ty)
{
    char name[64]; /* name_in may be the N() buffer itself */
    int ok;
    snprintf(name, sizeof name, "%s", name_in);
    ok = check(ty->bad_value == 0 && ty->bad_mat == 0 && ty->bad_counts == 0 &&
                       ty->bad_batch == 0 && ty->admitted > 0,
                   N("%s_pruned_equals_full", name),
                   "of %llu points: %llu values, %llu materials, %llu counts, %llu batch differ",
                   (unsigned long long)ty->admitted, (unsigned long long)ty->bad_value,
                   (unsigned long long)ty->bad_mat, (unsigned long long)ty->bad_counts,
                   (unsigned long long)ty->bad_batch);
    fovcheck_info("%s: %llu programs, instructions %.1f -> %.1f, rules a %.2f b %.2f c %.2f per "
                  "program, prims per eval %.3f -> %.3f, %llu of %llu cone points admitted",
                  name, (unsigned long long)ty->programs,
                  (double)ty->ins_full / (double)(ty->programs ? ty->programs : 1),
                  (double)ty->ins_pruned / (double)(ty->programs ? ty->programs : 1),
                  (double)ty->rules[0] / (double)(ty->programs ? ty->programs : 1),
                  (double)ty->rules[1] / (double)(ty->programs ? ty->programs : 1),
                  (double)ty->rules[2] / (double)(ty->programs ? ty->programs : 1),
                  (double)ty->prims_full / (double)(ty->admitted ? ty->admitted : 1),
                  (double)ty->prims_pruned / (double)(ty->admitted ? ty->admitted : 1),
                  (unsigned long long)ty->admitted, (unsigned long long)ty->points);
    return ok;
}

/* ---- 1. random scenes, random cones -------------------------------------------------------- */
static void test_random(void)
{
    static fovsdf_node nodes[1024];
    static unsigned char pm[1 << 20];
    static fovsdf__pruned pv;
    tally ty, out;
    uint64_t outside_diff = 0, outside_pts = 0;
    int r, built = 0, pruned = 0;
    memset(&ty, 0, sizeof ty);
    memset(&out, 0, sizeof out);
    for (r = 0; r < 160; ++r) {
        fovsdf_builder b;
        fovsdf_program prog;
        fovsdf_scene sc;
        int32_t root;
        size_t sz;
        int c;
        fovsdf_builder_init(&b, nodes, 1024);
        switch (r % 4) {
        case 0: root = cluster(&b, 10 + r % 30, 2); break;
        case 1: root = fovsdf_union(&b, cluster(&b, 8 + r % 20, 2), rprim(&b, 1)); break;
        case 2: root = rtree(&b, 5); break;
        default: root = fovsdf_union(&b, rtree(&b, 3), cluster(&b, 6 + r % 10, 1)); break;
        }
        if (root < 0 || fovsdf_program_size(nodes, b.count, root, &sz) != FOV_OK ||
            sz > sizeof pm || fovsdf_program_build(&prog, nodes, b.count, root, pm, sz) != FOV_OK)
            continue;
        ++built;
        memset(&sc, 0, sizeof sc);
        fovsdf_scene_set_program(&sc, &prog);
        for (c = 0; c < 12; ++c) {
            fovsdf_ray_cone q;
            float ax[3], l, e_lo, e_hi;
            int k;
            q.apex[0] = rr(-10, 10); q.apex[1] = rr(-3, 3); q.apex[2] = rr(-10, 10);
            do {
                ax[0] = rr(-1, 1); ax[1] = rr(-1, 1); ax[2] = rr(-1, 1);
                l = sqrtf(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
            } while (l < 0.1f || l > 1.0f);
            if (c % 3 == 0) { /* towards the scene's middle: many bounds around the cone */
                ax[0] = -q.apex[0] + rr(-2, 2); ax[1] = -q.apex[1]; ax[2] = -q.apex[2] + rr(-2, 2);
                l = sqrtf(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
                if (!(l > 1e-3f)) { ax[0] = 1.0f; ax[1] = 0.0f; ax[2] = 0.0f; l = 1.0f; }
            }
            for (k = 0; k < 3; ++k) q.axis[k] = ax[k] / l;
            q.tan_half = expf(rr(logf(0.001f), logf(1.5f)));
            q.t0 = rnd() < 0.3f ? 0.0f : rr(0.0f, 12.0f);
            q.t1 = q.t0 + (rnd() < 0.5f ? rr(0.01f, 3.0f) : rr(3.0f, 40.0f));
            e_lo = rnd() < 0.3f ? 0.0f : rr(0.0f, 0.01f);
            e_hi = e_lo + (rnd() < 0.3f ? 0.0f : rr(0.0f, 0.2f));
            if (!fovsdf__prune_cone(&sc, &q, e_lo, e_hi, &pv)) continue;
            ++pruned;
            add_rules(&ty, &prog, &pv);
            (void)compare(&prog, &pv, 1, &ty);
            { /* the control: beside the cone the pruned program may differ, and does */
                uint64_t bv = out.bad_value, bm = out.bad_mat, bc = out.bad_counts;
                outside_pts += compare(&prog, &pv, 0, &out);
                outside_diff += (out.bad_value - bv) + (out.bad_mat - bm) + (out.bad_counts - bc);
            }
        }
    }
    check(built >= 120 && pruned >= 1000, "random_scenes_built_and_pruned", "%d scenes, %d cones",
          built, pruned);
    report("random", &ty);
    check(ty.rules[0] > 0 && ty.rules[1] > 0 && ty.rules[2] > 0, "random_every_rule_fired",
          "rules a %llu b %llu c %llu", (unsigned long long)ty.rules[0],
          (unsigned long long)ty.rules[1], (unsigned long long)ty.rules[2]);
    check(ty.admitted * 10 >= ty.points * 9, "random_cone_points_admitted",
          "%llu of %llu", (unsigned long long)ty.admitted, (unsigned long long)ty.points);
    check(outside_diff > 0, "random_outside_the_cone_differs",
          "0 differences at %llu points beside the cones: the comparison would miss a bad prune",
          (unsigned long long)outside_pts);
}

/* ---- 2. the built-in scenes with their real tile cones ------------------------------------ */
static void test_builtin_tiles(void)
{
    uint32_t id, W = 160, H = 90;
    static fovsdf__pruned pv;
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        size_t sz;
        void *mem;
        fovsdf_builtin bi;
        fovsdf_ctx ctx;
        fovsdf_config cfg;
        fov_gaze g;
        fovsdf__marcher m, mp;
        uint32_t tx, ty, T, meth;
        tally tl;
        memset(&tl, 0, sizeof tl);
        if (fovsdf_builtin_size(id, &sz) != FOV_OK || !(mem = malloc(sz))) continue;
        if (fovsdf_builtin_init(id, &bi, mem, sz) != FOV_OK) { free(mem); continue; }
        bi.camera.width = W; bi.camera.height = H;
        g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
        for (meth = 0; meth < 2; ++meth) {
            cfg = fovsdf_config_default();
            cfg.method = meth ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_CONE;
            if (fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, g, NULL, 0) != FOV_OK) {
                check(0, N("builtin_%s_init", bi.name), "fovsdf_init failed");
                continue;
            }
            fovsdf__marcher_from_ctx(&ctx, &m, ctx.origin);
            mp = m;
            mp.method = ctx.cfg.finish - 1u;
            T = ctx.cfg.cone_tile;
            for (ty = 0; ty < H; ty += T)
                for (tx = 0; tx < W; tx += T) {
                    /* as fovsdf__cone_tile and fovsdf__fov_tile */
                    float x0 = meth ? (float)tx - 2.0f : (float)tx,
                          y0 = meth ? (float)ty - 2.0f : (float)ty;
                    float x1 = meth ? (float)(tx + T) + 2.0f : (float)(tx + T < W ? tx + T : W);
                    float y1 = meth ? (float)(ty + T) + 2.0f : (float)(ty + T < H ? ty + T : H);
                    if (!fovsdf__tile_cone(&ctx, &m, &mp, x0, y0, x1, y1, &pv) || !pv.pruned)
                        continue;
                    add_rules(&tl, bi.program, &pv);
                    (void)compare(bi.program, &pv, 1, &tl);
                }
        }
        check(tl.programs > 0, N("builtin_%s_tiles_pruned", bi.name), "no tile was pruned");
        report(N("builtin_%s", bi.name), &tl);
        free(mem);
    }
}

/* ---- 3. renders: pruned against unprunable wrappers ---------------------------------------- */
typedef struct wrap { const fovsdf_program *prog; uint64_t cones, outside, batches; } wrap;
static float w_dist(const float p[3], fovsdf_query *q, void *user)
{
    return fovsdf_program_eval(p, q, (void *)(uintptr_t)((wrap *)user)->prog);
}
static void w_batch(fovsdf_batch *b, void *user)
{
    wrap *w = (wrap *)user;
    w->batches++;
    if (b->cone) { /* every point inside (in double, 1e-5 of slack for the float rounding) */
        const fovsdf_ray_cone *q = b->cone;
        uint32_t i;
        w->cones++;
        for (i = 0; i < b->n; ++i) {
            double v[3] = { (double)b->x[i] - (double)q->apex[0],
                            (double)b->y[i] - (double)q->apex[1],
                            (double)b->z[i] - (double)q->apex[2] };
            double t = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            double al = v[0] * (double)q->axis[0] + v[1] * (double)q->axis[1] +
                v[2] * (double)q->axis[2];
            double pe = sqrt(fmax(t * t - al * al, 0.0)), sl = 1e-5 * (t + 1.0);
            if (t < (double)q->t0 - sl || t > (double)q->t1 + sl || al <= 0.0 ||
                pe > (double)q->tan_half * al + sl)
                w->outside++;
        }
    }
    fovsdf_program_eval_batch(b, (void *)(uintptr_t)w->prog);
}

static void test_renders(void)
{
    const uint32_t W = 96, H = 64;
    uint32_t id, meth;
    static float rgb[2][96 * 64 * 3], dep[2][96 * 64];
    static int32_t mat[2][96 * 64];
    static uint32_t ev[2][96 * 64];
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        size_t sz;
        void *mem;
        fovsdf_builtin bi;
        if (fovsdf_builtin_size(id, &sz) != FOV_OK || !(mem = malloc(sz))) continue;
        if (fovsdf_builtin_init(id, &bi, mem, sz) != FOV_OK) { free(mem); continue; }
        bi.camera.width = W; bi.camera.height = H;
        for (meth = 0; meth < 2; ++meth) {
            fovsdf_stats st[2];
            wrap w;
            int s, ok = 1;
            const char *sd = NULL;
            memset(&w, 0, sizeof w);
            w.prog = bi.program;
            for (s = 0; s < 2; ++s) {
                fovsdf_scene sc = bi.scene;
                fovsdf_config cfg = fovsdf_config_default();
                fovsdf_ctx ctx;
                fovsdf_output o;
                fov_gaze g;
                g.x = 0.4f * (float)W; g.y = 0.6f * (float)H;
                if (s == 1) {
                    sc.dist = 0; sc.dist_ex = w_dist; sc.dist_batch = w_batch; sc.user = &w;
                }
                cfg.method = meth ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_CONE;
                memset(&st[s], 0, sizeof st[s]);
                fovsdf_output_init(&o);
                o.rgb = rgb[s]; o.depth = dep[s]; o.material = mat[s]; o.evals = ev[s];
                if (fovsdf_init(&ctx, &cfg, &sc, &bi.camera, g, NULL, 0) != FOV_OK ||
                    fovsdf_render_rows(&ctx, 0, H, &o, &st[s]) != FOV_OK)
                    ok = 0;
            }
            if (memcmp(&st[0], &st[1], sizeof st[0]) != 0) sd = "stats";
            check(ok && memcmp(rgb[0], rgb[1], sizeof rgb[0]) == 0 &&
                      memcmp(dep[0], dep[1], sizeof dep[0]) == 0 &&
                      memcmp(mat[0], mat[1], sizeof mat[0]) == 0 &&
                      memcmp(ev[0], ev[1], sizeof ev[0]) == 0 && !sd,
                  N("render_%s_%s_pruned_identical", bi.name, meth ? "cone_fov" : "cone"),
                  "ok %d, rgb %d depth %d material %d evals %d, %s", ok,
                  memcmp(rgb[0], rgb[1], sizeof rgb[0]) != 0,
                  memcmp(dep[0], dep[1], sizeof dep[0]) != 0,
                  memcmp(mat[0], mat[1], sizeof mat[0]) != 0,
                  memcmp(ev[0], ev[1], sizeof ev[0]) != 0, sd ? sd : "stats equal");
            check(w.cones > 0 && w.outside == 0,
                  N("render_%s_%s_batch_cone_contains_batch", bi.name,
                    meth ? "cone_fov" : "cone"),
                  "%llu of %llu batches had a cone, %llu points outside it",
                  (unsigned long long)w.cones, (unsigned long long)w.batches,
                  (unsigned long long)w.outside);
        }
        free(mem);
    }
}

int main(void)
{
    test_random();
    test_builtin_tiles();
    test_renders();
    return fovcheck_summary();
}
