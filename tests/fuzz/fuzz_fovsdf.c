/* fuzz_fovsdf.c - libFuzzer harness of fovsdf.h (public API only).

   One input = one scenario, read in this order (tests/fuzz/gen_fovsdf.py writes inputs in
   the same layout; keep the two in step):
     u8 hostile     bit 0 config, 1 camera, 2 lights/sky/scene, 3 single rays, 4 geometry
                    floats: a set bit reads that section's floats with fz_float (sometimes
                    NaN, inf, huge, denormal), a clear bit with fz_unit_range (always in range)
     u8 geometry    0 built-in scene, 1 builder calls, 2 hand-made node array, 3 callback
     geometry bytes (see read_*_scene)
     config bytes   every fovsdf_config field, invalid values included
     camera bytes   size <= 24x24, pos, target, up, fov, eye offset, gaze
     scene bytes    lights, ambient, sky, lipschitz, t_max
     render bytes   strides, the split into rows or tiles, a tile-buffer render
     ray bytes      fovsdf_camera_ray / shade_point / trace / march on hostile rays

   Contract checked (FZ_CHECK aborts): every fovsdf call returns; fovsdf_init that fails
   leaves the context untouched; program_build rejects a node the builder functions would
   reject (the parameter ranges of fovsdf_node_type) and accepts what the builder made; a
   program evaluates to a non-NaN distance at finite points; on FOV_OK every output is
   finite: rgb within [0, bound] (bound: sky, or albedo <= 1 times ambient plus the lights'
   colours; 1 for normal, depth and step shading), depth and start within [0, t_max], hit 0
   or 1, mask 0/1 (FIPR, CONE_FOV) or 1, steps <= spp * max_steps, nothing written outside
   the rows/tiles and strides (canaries, row padding); the image is bit for bit the same
   whatever the split into rows, tiles or tile buffers; camera rays are unit; trace, march
   and shade_point report t within [t_start, t_max]; shade_points_grouped of the shade_point
   positions (one group) keeps the same rgb and t contract.

   -DFZ_VERBOSE prints the scenario (geometry, config, camera) to stderr.
   -DFZ_IGNORE_KNOWN: development switch that steers around the findings F1-F6 of issue 10
   (huge camera vectors and image points, huge or denormal builder parameters, hostile
   callbacks, depth beyond t_max from the head-start methods, unchecked node parameters) and
   N3 (fovsdf_trace of IPR/SKIP/FIPR contexts backing up before t_start) and N4 (CONE's
   head start past t_max), so
   a fuzzing run can find something new before those fixes land. Never used by run.sh. */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fuzz_common.h"

#include <math.h>

#define FZ_MAXW 24
#define FZ_MAXN 16

#ifdef FZ_IGNORE_KNOWN
static const int fz_known_off = 1;
#else
static const int fz_known_off = 0;
#endif

/* a float of a section: hostile (fz_float) or always within [lo, hi] */
static float rf(fz_in *in, float lo, float hi, int hostile)
{
    float v = hostile ? fz_float(in, lo, hi) : fz_unit_range(in, lo, hi);
    if (fz_known_off && hostile && fz_finite(v) && (fabsf(v) > 1e15f || (v != 0.0f && fabsf(v) < 1e-15f)))
        v = lo;
    return v;
}

/* ---- callback scene: a sphere and a floor, with hostile answers in places ---------------- */
typedef struct cb_scene {
    float c[3], r, floor_y;
    uint32_t bad;     /* 0 none, 1 NaN, 2 +inf, 3 -inf, 4 overestimate x factor, 5 FLT_MAX */
    float factor;     /* overestimate */
    float band;       /* bad answers where frac(p.x * 1.7 + p.z * 0.9) < band */
    uint32_t inflate; /* honour fovsdf_query.inflate */
    uint32_t albedo;  /* 0 palette, 1 callback in [0, 1], 2 callback with NaN/inf */
} cb_scene;

static float cb_eval(const cb_scene *s, const float p[3], float inflate)
{
    float q[3], d, e;
    q[0] = p[0] / inflate; q[1] = p[1] / inflate; q[2] = p[2] / inflate;
    d = sqrtf((q[0] - s->c[0]) * (q[0] - s->c[0]) + (q[1] - s->c[1]) * (q[1] - s->c[1]) +
              (q[2] - s->c[2]) * (q[2] - s->c[2])) - s->r;
    e = q[1] - s->floor_y;
    d = (d < e ? d : e) * inflate;
    if (s->bad) {
        float u = p[0] * 1.7f + p[2] * 0.9f;
        u -= floorf(u);
        if (u < s->band) {
            volatile float z = 0.0f;
            switch (s->bad) {
            case 1: return z / z;
            case 2: return 1.0f / z;
            case 3: return -1.0f / z;
            case 4: return d > 0.0f ? d * s->factor : d;
            default: return FLT_MAX;
            }
        }
    }
    return d;
}
static float cb_dist(const float p[3], void *user) { return cb_eval((const cb_scene *)user, p, 1.0f); }
static float cb_dist_ex(const float p[3], fovsdf_query *q, void *user)
{
    const cb_scene *s = (const cb_scene *)user;
    float inf = (q && s->inflate && q->inflate > 0.0f) ? q->inflate : 1.0f;
    if (q && q->want_material) q->material = p[1] > 0.0f ? 2 : 1;
    return cb_eval(s, p, inf);
}
static void cb_albedo(const float p[3], int32_t material, float rgb[3], void *user)
{
    const cb_scene *s = (const cb_scene *)user;
    float u = fabsf(p[0] * 0.37f + p[2] * 0.11f + (float)material * 0.1f);
    u -= floorf(u);
    rgb[0] = u; rgb[1] = 1.0f - u; rgb[2] = 0.5f;
    if (s->albedo == 2 && u < 0.3f) {
        volatile float z = 0.0f;
        rgb[0] = z / z;
        rgb[1] = 1.0f / z;
    }
}

/* ---- node parameter ranges (those of the builder functions) ------------------------------ */
static int pos_(float v) { return v > 0.0f && fz_finite(v); }
static int nonneg_(float v) { return v >= 0.0f && fz_finite(v); }
static int fin_n(const float *f, int n) { return fz_finite_n(f, (size_t)n); }

/* 1 when the builder functions could have made this node (parameters in range) */
static int node_params_ok(const fovsdf_node *n)
{
    const float *f = n->f;
    switch (n->type) {
    case FOVSDF_NODE_SPHERE: return pos_(f[0]);
    case FOVSDF_NODE_BOX: return pos_(f[0]) && pos_(f[1]) && pos_(f[2]);
    case FOVSDF_NODE_ROUND_BOX:
        return pos_(f[0]) && pos_(f[1]) && pos_(f[2]) && nonneg_(f[3]) && f[3] <= f[0] && f[3] <= f[1] && f[3] <= f[2];
    case FOVSDF_NODE_BOX_FRAME: return pos_(f[0]) && pos_(f[1]) && pos_(f[2]) && pos_(f[3]);
    case FOVSDF_NODE_TORUS: return nonneg_(f[0]) && pos_(f[1]);
    case FOVSDF_NODE_CAPSULE: return fin_n(f, 6) && pos_(f[6]);
    case FOVSDF_NODE_CYLINDER: return pos_(f[0]) && pos_(f[1]);
    case FOVSDF_NODE_CONE: return pos_(f[0]) && nonneg_(f[1]) && nonneg_(f[2]) && (f[1] > 0.0f || f[2] > 0.0f);
    case FOVSDF_NODE_PLANE: return fin_n(f, 4) && (f[0] != 0.0f || f[1] != 0.0f || f[2] != 0.0f);
    case FOVSDF_NODE_MENGER: return pos_(f[0]) && n->i[0] >= 1 && n->i[0] <= 8;
    case FOVSDF_NODE_MANDELBULB: return f[0] >= 2.0f && f[0] <= 16.0f && n->i[0] >= 1 && n->i[0] <= 32;
    case FOVSDF_NODE_TERRAIN: return nonneg_(f[0]) && pos_(f[1]) && fz_finite(f[2]) && n->i[0] >= 1 && n->i[0] <= 12;
    case FOVSDF_NODE_UNION: case FOVSDF_NODE_SUBTRACT: case FOVSDF_NODE_INTERSECT: return 1;
    case FOVSDF_NODE_SMOOTH_UNION: case FOVSDF_NODE_SMOOTH_SUBTRACT: case FOVSDF_NODE_SMOOTH_INTERSECT:
        return pos_(f[0]);
    case FOVSDF_NODE_TRANSLATE: return fin_n(f, 3);
    case FOVSDF_NODE_ROTATE: return fin_n(f, 9);
    case FOVSDF_NODE_SCALE: return pos_(f[0]);
    case FOVSDF_NODE_REPEAT:
        return nonneg_(f[0]) && nonneg_(f[1]) && nonneg_(f[2]) && n->i[0] >= 0 && n->i[1] >= 0 && n->i[2] >= 0 &&
               n->i[0] <= 1000000 && n->i[1] <= 1000000 && n->i[2] <= 1000000;
    case FOVSDF_NODE_MIRROR: return n->i[0] >= 1 && n->i[0] <= 7;
    case FOVSDF_NODE_ROUND: return nonneg_(f[0]);
    case FOVSDF_NODE_ONION: return pos_(f[0]);
    default: return 1; /* unknown types: program_build's own check */
    }
}
static int arity(uint32_t t)
{
    if (t >= FOVSDF_NODE_SPHERE && t <= FOVSDF_NODE_TERRAIN) return 0;
    if (t >= FOVSDF_NODE_UNION && t <= FOVSDF_NODE_SMOOTH_INTERSECT) return 2;
    if (t >= FOVSDF_NODE_TRANSLATE && t <= FOVSDF_NODE_ONION) return 1;
    return -1;
}
/* 1 when every node reachable from root has parameters in range (structure assumed valid) */
static int reachable_ok(const fovsdf_node *nd, uint32_t n, int32_t root)
{
    int32_t stack[4 * FZ_MAXN];
    uint8_t seen[FZ_MAXN];
    int sp = 0;
    memset(seen, 0, sizeof seen);
    stack[sp++] = root;
    while (sp > 0) {
        int32_t k = stack[--sp];
        int a;
        if (k < 0 || (uint32_t)k >= n || seen[k]) continue;
        seen[k] = 1;
        if (!node_params_ok(&nd[k])) return 0;
        a = arity(nd[k].type);
        if (a >= 1 && sp < 4 * FZ_MAXN) stack[sp++] = nd[k].a;
        if (a == 2 && sp < 4 * FZ_MAXN) stack[sp++] = nd[k].b;
    }
    return 1;
}

/* ---- the scenario ---------------------------------------------------------------------- */
typedef struct scen {
    fovsdf_scene scene;
    fovsdf_builtin bi;
    void *mem;            /* program or built-in memory */
    fovsdf_program prog;
    fovsdf_node nodes[FZ_MAXN];
    cb_scene cb;
    int have_bi, is_program;
} scen;

static void eval_points(fz_in *in, const fovsdf_program *p)
{
    int k, n = (int)fz_pick(in, 4);
    for (k = 0; k < n; ++k) {
        float q[3];
        fovsdf_query qq;
        float d;
        q[0] = fz_unit_range(in, -8.0f, 8.0f);
        q[1] = fz_unit_range(in, -8.0f, 8.0f);
        q[2] = fz_unit_range(in, -8.0f, 8.0f);
        memset(&qq, 0, sizeof qq);
        qq.inflate = 1.0f;
        qq.eps = 1e-4f;
        qq.want_material = 1;
        d = fovsdf_program_eval(q, &qq, (void *)(uintptr_t)p);
        FZ_CHECK(d == d, "program_eval NaN at finite point (%g, %g, %g)", (double)q[0], (double)q[1], (double)q[2]);
        d = fovsdf_program_eval(q, NULL, (void *)(uintptr_t)p);
        FZ_CHECK(d == d, "program_eval (q NULL) NaN at (%g, %g, %g)", (double)q[0], (double)q[1], (double)q[2]);
    }
}

/* 1 when some node is the child of two operands (or twice of one): a DAG */
static int shares_nodes(const fovsdf_node *nd, uint32_t n)
{
    uint8_t parents[FZ_MAXN];
    uint32_t k;
    memset(parents, 0, sizeof parents);
    for (k = 0; k < n; ++k) {
        int a = arity(nd[k].type);
        if (a >= 1 && nd[k].a >= 0 && (uint32_t)nd[k].a < n && ++parents[nd[k].a] > 1) return 1;
        if (a == 2 && nd[k].b >= 0 && (uint32_t)nd[k].b < n && ++parents[nd[k].b] > 1) return 1;
    }
    return 0;
}

/* builds nodes[0..n) into s->prog; returns 1 when the program is usable. Builder trees must
   compile; a builder DAG (a node used twice) may be refused with FOV_ERR_LIMIT or
   FOV_ERR_TOO_SMALL (the union rebalance unfolds shared subtrees: a 3-node
   union(u, u), u = union(s, s), is FOV_ERR_LIMIT; see tests/fuzz/README.md) */
static int build_program(fz_in *in, scen *s, uint32_t n, int32_t root, int from_builder)
{
    size_t bytes = 0;
    fov_result r = fovsdf_program_size(s->nodes, n, root, &bytes);
    if (r != FOV_OK) {
        FZ_CHECK(!from_builder, "program_size of builder nodes failed: %d", (int)r);
        return 0;
    }
    FZ_CHECK(bytes > 0 && bytes < ((size_t)1 << 24), "program_size %zu", bytes);
    s->mem = fz_alloc(bytes, 0);
    r = fovsdf_program_build(&s->prog, s->nodes, n, root, s->mem, bytes);
    FZ_CHECK(fz_canary_ok(s->mem, bytes), "program_build wrote past its memory");
    if (r != FOV_OK) {
        FZ_CHECK(!from_builder || ((r == FOV_ERR_LIMIT || r == FOV_ERR_TOO_SMALL) && shares_nodes(s->nodes, n)),
                 "program_build of builder nodes failed: %d", (int)r);
        return 0;
    }
    if (!from_builder && !reachable_ok(s->nodes, n, root)) {
        if (fz_known_off) return 0;
        FZ_FAIL("program_build accepted a node the builder rejects (issue 10 F6)");
    }
    eval_points(in, &s->prog);
    fovsdf_scene_set_program(&s->scene, &s->prog);
    s->is_program = 1;
    return 1;
}

static int read_nodes_scene(fz_in *in, scen *s, int hostile)
{
    uint32_t n = 1u + fz_pick(in, FZ_MAXN), k, j;
    int32_t root;
    for (k = 0; k < n; ++k) {
        fovsdf_node *nd = &s->nodes[k];
        float lo = 0.05f, hi = 2.0f;
        memset(nd, 0, sizeof *nd);
        nd->type = fz_pick(in, (uint32_t)_FOVSDF_NODE_NUM + 1u);
        nd->a = (int32_t)fz_pick(in, n + 1u) - 1;
        nd->b = (int32_t)fz_pick(in, n + 1u) - 1;
        nd->material = (int32_t)fz_pick(in, 8);
        for (j = 0; j < 3; ++j) {
            uint8_t sel = fz_u8(in);
            nd->i[j] = sel < 240 ? (int32_t)(sel % 40) - 2 : (int32_t)fz_u32(in);
        }
        if (nd->type == FOVSDF_NODE_TRANSLATE || nd->type == FOVSDF_NODE_ROTATE || nd->type == FOVSDF_NODE_PLANE ||
            nd->type == FOVSDF_NODE_CAPSULE) { lo = -2.0f; hi = 2.0f; }
        for (j = 0; j < 9; ++j) nd->f[j] = hostile ? fz_float(in, lo, hi) : fz_unit_range(in, lo, hi);
        if (nd->type == FOVSDF_NODE_MANDELBULB && !hostile) nd->f[0] = 2.0f + 6.0f * nd->f[0];
    }
    root = (int32_t)fz_pick(in, n + 1u) - 1;
    return build_program(in, s, n, root, 0);
}

static int32_t child(fz_in *in, const int32_t *ids, uint32_t nid)
{
    uint32_t k = fz_pick(in, nid + 2u);
    if (k < nid) return ids[k];
    return k == nid ? -1 : 1000;
}

static int read_builder_scene(fz_in *in, scen *s, int hostile)
{
    fovsdf_builder b;
    int32_t ids[FZ_MAXN], id = -1, last = -1;
    uint32_t nid = 0, nops = 1u + fz_pick(in, 10), k;
    fovsdf_builder_init(&b, s->nodes, FZ_MAXN);
    for (k = 0; k < nops; ++k) {
        uint32_t op = fz_pick(in, 24);
        float a = rf(in, 0.05f, 2.0f, hostile), c = rf(in, 0.05f, 2.0f, hostile);
        float d = rf(in, 0.05f, 2.0f, hostile), e = rf(in, -2.0f, 2.0f, hostile);
        int32_t x = nid ? child(in, ids, nid) : -1, y = nid ? child(in, ids, nid) : -1;
        int32_t iv = (int32_t)fz_pick(in, 12) - 1;
        b.material = (int32_t)fz_pick(in, 8);
#ifdef FZ_VERBOSE
        fprintf(stderr, "builder op %u a %g c %g d %g e %g x %d y %d iv %d\n", op, (double)a, (double)c, (double)d,
                (double)e, x, y, iv);
#endif
        switch (op) {
        case 0: id = fovsdf_sphere(&b, a); break;
        case 1: id = fovsdf_box(&b, a, c, d); break;
        case 2: id = fovsdf_round_box(&b, a, c, d, 0.1f * e); break;
        case 3: id = fovsdf_box_frame(&b, a, c, d, 0.1f * a); break;
        case 4: id = fovsdf_torus(&b, a, 0.3f * c); break;
        case 5: { float p0[3], p1[3]; p0[0] = e; p0[1] = a; p0[2] = -c; p1[0] = -e; p1[1] = -a; p1[2] = d;
                  id = fovsdf_capsule(&b, p0, p1, 0.2f * d); } break;
        case 6: id = fovsdf_cylinder(&b, a, c); break;
        case 7: id = fovsdf_cone(&b, a, c, e); break;
        case 8: id = fovsdf_plane(&b, e, a, c - 1.0f, d); break;
        case 9: id = fovsdf_menger(&b, a, iv > 4 ? 2 : iv); break;
        case 10: id = fovsdf_mandelbulb(&b, 2.0f + 4.0f * a, iv > 6 ? 3 : iv); break;
        case 11: id = fovsdf_terrain(&b, 0.2f * a, c, iv); break;
        case 12: id = fovsdf_union(&b, x, y); break;
        case 13: id = fovsdf_subtract(&b, x, y); break;
        case 14: id = fovsdf_intersect(&b, x, y); break;
        case 15: id = fovsdf_smooth_union(&b, x, y, 0.2f * a); break;
        case 16: id = fovsdf_smooth_subtract(&b, x, y, 0.2f * a); break;
        case 17: id = fovsdf_smooth_intersect(&b, x, y, 0.2f * a); break;
        case 18: id = fovsdf_translate(&b, x, e, a - 1.0f, c); break;
        case 19: id = fovsdf_rotate(&b, x, a, c, e, 90.0f * d); break;
        case 20: id = fovsdf_scale(&b, x, a); break;
        case 21: id = fovsdf_repeat(&b, x, 2.0f * a, 0.0f, 2.0f * c, iv, 0, iv > 3 ? 0 : iv); break;
        case 22: id = fovsdf_mirror(&b, x, iv); break;
        default: id = (k & 1) ? fovsdf_round(&b, x, 0.1f * a) : fovsdf_onion(&b, x, 0.05f * a); break;
        }
        if (id >= 0) { FZ_CHECK(b.err == FOV_OK && (uint32_t)id < b.count, "builder id %d count %u", id, b.count); ids[nid++] = id; last = id; }
        else FZ_CHECK(b.err != FOV_OK, "builder returned -1 without an error");
        if (b.err != FOV_OK) break;
    }
    if (b.err != FOV_OK || last < 0) return 0;
    return build_program(in, s, b.count, last, 1);
}

static int read_builtin_scene(fz_in *in, scen *s)
{
    uint32_t id = fz_pick(in, (uint32_t)_FOVSDF_SCENE_NUM + 1u);
    size_t bytes = 0;
    fov_result r = fovsdf_builtin_size(id, &bytes);
    if (r != FOV_OK) { FZ_CHECK(id >= (uint32_t)_FOVSDF_SCENE_NUM, "builtin_size(%u) failed", id); return 0; }
    s->mem = fz_alloc(bytes, 0);
    r = fovsdf_builtin_init(id, &s->bi, s->mem, bytes);
    FZ_CHECK(r == FOV_OK, "builtin_init(%u) failed: %d", id, (int)r);
    FZ_CHECK(fz_canary_ok(s->mem, bytes), "builtin_init wrote past its memory");
    s->scene = s->bi.scene;
    s->have_bi = 1;
    s->is_program = 1;
    return 1;
}

static int read_callback_scene(fz_in *in, scen *s, int hostile)
{
    cb_scene *c = &s->cb;
    uint8_t flags = fz_u8(in);
    c->c[0] = rf(in, -2.0f, 2.0f, hostile); c->c[1] = rf(in, -1.0f, 2.0f, hostile); c->c[2] = rf(in, 0.0f, 6.0f, hostile);
    c->r = rf(in, 0.01f, 2.0f, hostile);
    c->floor_y = rf(in, -3.0f, 0.0f, hostile);
    c->bad = fz_pick(in, 6);
    c->factor = fz_unit_range(in, 1.0f, 100.0f);
    c->band = fz_unit_range(in, 0.0f, 1.0f);
    c->inflate = flags & 1u;
    c->albedo = (flags >> 1) % 3u;
    if (fz_known_off) { c->bad = 0; if (c->albedo == 2) c->albedo = 1; }
    s->scene.user = c;
    if (flags & 8u) s->scene.dist = cb_dist;
    else s->scene.dist_ex = cb_dist_ex;
    if (c->albedo) s->scene.albedo = cb_albedo;
    return 1;
}

static void read_config(fz_in *in, fovsdf_config *cfg, int H)
{
    static const uint32_t spp_t[5] = { 0, 1, 4, 16, 2 };
    static const uint32_t steps_t[8] = { 0, 1, 2, 7, 32, 64, 128, 70000 };
    static const uint32_t sh_t[4] = { 0, 1, 8, 64 };
    static const uint32_t ct_t[8] = { 0, 1, 2, 4, 8, 16, 32, 3 };
    static const uint32_t it_t[8] = { 0, 4, 8, 16, 32, 64, 12, 6 };
    static const uint32_t rf_t[5] = { 0, 1, 2, 4, 3 };
    uint8_t disp;
    memset(cfg, 0, sizeof *cfg);
    cfg->method = fz_pick(in, 10);
    cfg->spp = spp_t[fz_pick(in, 5)];
    cfg->eps_mode = fz_pick(in, 4);
    cfg->eps = rf(in, 0.0f, 0.01f, H);
    cfg->eps_px = rf(in, 0.0f, 2.0f, H);
    cfg->max_steps = steps_t[fz_pick(in, 8)];
    cfg->t_max = rf(in, 0.0f, 200.0f, H);
    cfg->omega = rf(in, 0.0f, 2.0f, H);
    cfg->ar_beta = rf(in, 0.0f, 1.0f, H);
    cfg->bv_relax = rf(in, 0.0f, 1.0f, H);
    cfg->shading = fz_pick(in, 6);
    cfg->shadow_steps = sh_t[fz_pick(in, 4)];
    cfg->shadow_eps = rf(in, 0.0f, 0.01f, H);
    cfg->shadow_t0 = rf(in, 0.0f, 0.1f, H);
    cfg->normal_eps = rf(in, 0.0f, 0.01f, H);
    cfg->cone_tile = ct_t[fz_pick(in, 8)];
    cfg->cone_levels = fz_pick(in, 7);
    cfg->ipr_levels = fz_pick(in, 7);
    cfg->ipr_radius = (int32_t)fz_pick(in, 5) - 1;
    cfg->ipr_no_filter = fz_pick(in, 3);
    cfg->ipr_tile = it_t[fz_pick(in, 8)];
    cfg->skip_block = fz_pick(in, 18);
    cfg->skip_scale = rf(in, 0.0f, 2.0f, H);
    cfg->skip_eps = rf(in, 0.0f, 0.1f, H);
    cfg->skip_no_shadow_start = fz_pick(in, 2);
    cfg->finish = fz_pick(in, 6);
    cfg->acuity.A = rf(in, 0.0f, 0.9f, H);
    cfg->acuity.rate = rf(in, 0.0f, 1.0f, H);
    cfg->acuity.C = rf(in, 0.0f, 0.1f, H);
    cfg->acuity.fovea_deg = rf(in, 0.0f, 40.0f, H);
    cfg->acuity.outer_deg = rf(in, 0.0f, 90.0f, H);
    cfg->fov_mask = fz_pick(in, 4);
    cfg->edge_threshold = rf(in, 0.0f, 1.0f, H);
    cfg->refresh = rf_t[fz_pick(in, 5)];
    cfg->frame = fz_u8(in);
    cfg->seed = fz_u32(in);
    disp = fz_u8(in);
    if (disp & 1u) cfg->display.fov_y_deg = rf(in, 0.0f, 179.0f, H);
    if (disp & 2u) { cfg->display.pixel_pitch_mm = rf(in, 0.0f, 1.0f, H); cfg->display.distance_mm = rf(in, 0.0f, 1000.0f, H); }
    if (disp & 4u) { cfg->display.axis_dx = rf(in, -50.0f, 50.0f, H); cfg->display.axis_dy = rf(in, -50.0f, 50.0f, H); }
}

static void read_camera(fz_in *in, fovsdf_camera *cam, fov_gaze *gaze, const scen *s, int H)
{
    uint8_t flags = fz_u8(in);
    uint32_t w = fz_pick(in, FZ_MAXW + 1u), h = fz_pick(in, FZ_MAXW + 1u);
    int k;
    fovsdf_camera_init(cam, w, h);
    if (s->have_bi && (flags & 1u)) { *cam = s->bi.camera; cam->width = w; cam->height = h; }
    for (k = 0; k < 3; ++k) cam->pos[k] = rf(in, -6.0f, 6.0f, H);
    for (k = 0; k < 3; ++k) cam->target[k] = rf(in, -3.0f, 3.0f, H);
    if (flags & 2u) for (k = 0; k < 3; ++k) cam->up[k] = rf(in, -1.0f, 1.0f, H);
    cam->fov_y_deg = rf(in, 0.0f, 180.0f, H);
    cam->eye_offset = (flags & 4u) ? rf(in, -1.0f, 1.0f, H) : 0.0f;
    gaze->x = rf(in, -30.0f, 60.0f, H);
    gaze->y = rf(in, -30.0f, 60.0f, H);
    if (s->have_bi && (flags & 1u) && !(flags & 8u)) { /* keep the suggested view */
        *cam = s->bi.camera; cam->width = w; cam->height = h;
    }
}

static void read_scene_look(fz_in *in, fovsdf_scene *sc, int H)
{
    uint8_t flags = fz_u8(in);
    uint32_t k, j;
    if (flags & 1u) {
        sc->num_lights = fz_pick(in, FOVSDF_MAX_LIGHTS + 2u);
        for (k = 0; k < sc->num_lights && k < FOVSDF_MAX_LIGHTS; ++k) {
            fovsdf_light *L = &sc->lights[k];
            L->type = fz_pick(in, 3);
            for (j = 0; j < 3; ++j) L->v[j] = rf(in, -10.0f, 10.0f, H);
            for (j = 0; j < 3; ++j) L->color[j] = fz_unit_range(in, 0.0f, 2.0f);
            L->range = rf(in, 0.0f, 20.0f, H);
            L->shadow_k = rf(in, -1.0f, 64.0f, H);
        }
    }
    if (flags & 2u) {
        for (j = 0; j < 3; ++j) sc->ambient[j] = fz_unit_range(in, 0.0f, 0.5f);
        for (j = 0; j < 3; ++j) sc->sky_zenith[j] = fz_unit_range(in, 0.0f, 1.0f);
        for (j = 0; j < 3; ++j) sc->sky_horizon[j] = fz_unit_range(in, 0.0f, 1.0f);
    }
    if (flags & 4u) sc->lipschitz = rf(in, 0.0f, 4.0f, H);
    if (flags & 8u) sc->t_max = rf(in, 0.0f, 200.0f, H);
}

/* FZ_IGNORE_KNOWN: may this context report t beyond t_max (issue 10 F3, F4)? */
static int known_tmax(const fovsdf_ctx *c)
{
    uint32_t tracer = c->cfg.method <= FOVSDF_METHOD_BV2018 ? c->cfg.method : c->cfg.finish - 1u;
    return fz_known_off && (c->cfg.method >= FOVSDF_METHOD_CONE || tracer == FOVSDF_METHOD_AUTORELAXED ||
                            tracer == FOVSDF_METHOD_BV2018);
}

/* upper bound of a shaded channel */
static float rgb_bound(const fovsdf_ctx *c)
{
    const fovsdf_scene *s = &c->scene;
    float sky = 0.0f, lit = 0.0f, hi;
    uint32_t k, j;
    if (c->cfg.shading >= FOVSDF_SHADE_NORMALS) return 1.0f + 1e-5f; /* a unit normal's last ulp */
    for (j = 0; j < 3; ++j) {
        float a = s->ambient[j];
        if (s->sky_zenith[j] > sky) sky = s->sky_zenith[j];
        if (s->sky_horizon[j] > sky) sky = s->sky_horizon[j];
        for (k = 0; k < s->num_lights; ++k) a += s->lights[k].color[j] > 0.0f ? s->lights[k].color[j] : 0.0f;
        if (a > lit) lit = a;
    }
    hi = sky > lit ? sky : lit;
    return hi * (1.0f + 1e-5f) + 1e-6f;
}
static float rgb_floor(const fovsdf_ctx *c)
{
    const fovsdf_scene *s = &c->scene;
    float lo = 0.0f;
    uint32_t j;
    for (j = 0; j < 3; ++j) {
        if (s->ambient[j] < lo) lo = s->ambient[j];
        if (s->sky_zenith[j] < lo) lo = s->sky_zenith[j];
        if (s->sky_horizon[j] < lo) lo = s->sky_horizon[j];
    }
    return lo - 1e-5f; /* 0.5 + 0.5 n of a unit normal can round below 0 */
}

/* ---- image buffers ------------------------------------------------------------------- */
enum { B_RGB, B_RGB8, B_DEPTH, B_HIT, B_EVALS, B_STEPS, B_START, B_MAT, B_MASK, B_NUM };
static const size_t b_elem[B_NUM] = { 4, 1, 4, 1, 4, 4, 4, 4, 1 };
static const uint32_t b_comp[B_NUM] = { 3, 3, 1, 1, 1, 1, 1, 1, 1 };
static const int b_fill[B_NUM] = { 0xFF, 0xEE, 0xFF, 0xEE, 0xEE, 0xEE, 0xFF, 0xEE, 0xEE };

typedef struct imgset {
    void *p[B_NUM];
    size_t bytes[B_NUM];
    uint32_t stride[B_NUM]; /* elements per row as passed (0: packed) */
    uint32_t row[B_NUM];    /* actual elements per row */
    uint32_t w, h;          /* pixels covered */
    fovsdf_output out;
} imgset;

static void img_alloc(imgset *m, uint32_t w, uint32_t h, uint32_t pad, uint32_t ox, uint32_t oy, uint32_t keep)
{
    int k;
    memset(m, 0, sizeof *m);
    m->w = w; m->h = h;
    fovsdf_output_init(&m->out);
    m->out.origin_x = ox; m->out.origin_y = oy;
    for (k = 0; k < B_NUM; ++k) {
        uint32_t comp = b_comp[k];
        if (!(keep & (1u << k))) continue;
        m->stride[k] = pad ? comp * (w + pad) : 0u;
        m->row[k] = pad ? comp * (w + pad) : comp * w;
        m->bytes[k] = ((size_t)(h - 1u) * m->row[k] + (size_t)comp * w) * b_elem[k];
        m->p[k] = fz_alloc(m->bytes[k], b_fill[k]);
    }
    m->out.rgb = (float *)m->p[B_RGB]; m->out.rgb_stride = m->stride[B_RGB];
    m->out.rgb8 = (uint8_t *)m->p[B_RGB8]; m->out.rgb8_stride = m->stride[B_RGB8];
    m->out.depth = (float *)m->p[B_DEPTH]; m->out.depth_stride = m->stride[B_DEPTH];
    m->out.hit = (uint8_t *)m->p[B_HIT]; m->out.hit_stride = m->stride[B_HIT];
    m->out.evals = (uint32_t *)m->p[B_EVALS]; m->out.evals_stride = m->stride[B_EVALS];
    m->out.steps = (uint32_t *)m->p[B_STEPS]; m->out.steps_stride = m->stride[B_STEPS];
    m->out.start = (float *)m->p[B_START]; m->out.start_stride = m->stride[B_START];
    m->out.material = (int32_t *)m->p[B_MAT]; m->out.material_stride = m->stride[B_MAT];
    m->out.mask = (uint8_t *)m->p[B_MASK]; m->out.mask_stride = m->stride[B_MASK];
}
static void img_free(imgset *m)
{
    int k;
    for (k = 0; k < B_NUM; ++k) free(m->p[k]);
}
/* canaries and row padding untouched */
static void img_guard(const imgset *m, const char *what)
{
    int k;
    uint32_t y;
    for (k = 0; k < B_NUM; ++k) {
        const uint8_t *b = (const uint8_t *)m->p[k];
        size_t rowb = (size_t)m->row[k] * b_elem[k], used = (size_t)b_comp[k] * m->w * b_elem[k], i;
        if (!b) continue;
        FZ_CHECK(fz_canary_ok(b, m->bytes[k]), "%s: buffer %d overrun", what, k);
        for (y = 0; y + 1u < m->h; ++y)
            for (i = used; i < rowb; ++i)
                FZ_CHECK(b[(size_t)y * rowb + i] == (uint8_t)b_fill[k], "%s: buffer %d row %u padding written", what, k, y);
    }
}
/* element (x, y) of buffer k (x, y relative to the buffer), component c */
static const uint8_t *img_at(const imgset *m, int k, uint32_t x, uint32_t y, uint32_t c)
{
    return (const uint8_t *)m->p[k] + ((size_t)y * m->row[k] + (size_t)b_comp[k] * x + c) * b_elem[k];
}
static int untouched(const uint8_t *e, size_t n, int fill)
{
    size_t i;
    for (i = 0; i < n; ++i) if (e[i] != (uint8_t)fill) return 0;
    return 1;
}

static void check_pixels(const fovsdf_ctx *c, const imgset *m)
{
    float hi = rgb_bound(c), lo = rgb_floor(c), tmax = c->t_max;
    int fov = c->cfg.method == FOVSDF_METHOD_FIPR || c->cfg.method == FOVSDF_METHOD_CONE_FOV;
    uint64_t smax = (uint64_t)c->cfg.spp * c->cfg.max_steps;
    uint32_t x, y, j;
    for (y = 0; y < m->h; ++y)
        for (x = 0; x < m->w; ++x) {
            uint8_t mask, hit;
            float v;
            uint32_t u;
            if (m->p[B_MASK]) {
                mask = *img_at(m, B_MASK, x, y, 0);
                if (mask == 2) { /* kept from an earlier frame: nothing else written */
                    FZ_CHECK(fov && c->cfg.refresh > 1, "pixel (%u, %u) mask 2 (method %u, refresh %u)", x, y,
                             c->cfg.method, c->cfg.refresh);
                    FZ_CHECK(!m->p[B_RGB] || untouched(img_at(m, B_RGB, x, y, 0), 12, 0xFF),
                             "pixel (%u, %u): mask 2 (kept) but rgb written", x, y);
                    FZ_CHECK(!m->p[B_DEPTH] || untouched(img_at(m, B_DEPTH, x, y, 0), 4, 0xFF),
                             "pixel (%u, %u): mask 2 (kept) but depth written", x, y);
                    continue;
                }
                FZ_CHECK(fov ? mask <= 1 : mask == 1, "pixel (%u, %u) mask %u (method %u)", x, y, mask, c->cfg.method);
            } else if (fov && c->cfg.refresh > 1 && m->p[B_RGB] && untouched(img_at(m, B_RGB, x, y, 0), 12, 0xFF)) {
                continue; /* kept (no mask buffer to say so) */
            }
            if (m->p[B_RGB])
                for (j = 0; j < 3; ++j) {
                    memcpy(&v, img_at(m, B_RGB, x, y, j), 4);
                    if (known_tmax(c) && c->cfg.shading == FOVSDF_SHADE_DEPTH && v < 0.0f && v >= -1.0f) continue;
                    FZ_CHECK(fz_finite(v) && v >= lo && v <= hi,
                             "pixel (%u, %u) rgb[%u] = %g outside [%g, %g] (method %u, shading %u)", x, y, j, (double)v,
                             (double)lo, (double)hi, c->cfg.method, c->cfg.shading);
                }
            if (m->p[B_DEPTH]) {
                memcpy(&v, img_at(m, B_DEPTH, x, y, 0), 4);
                if (!(known_tmax(c) && v > tmax))
                    FZ_CHECK(fz_finite(v) && v >= 0.0f && v <= tmax, "pixel (%u, %u) depth %g outside [0, t_max %g] (method %u)",
                             x, y, (double)v, (double)tmax, c->cfg.method);
            }
            if (m->p[B_START]) {
                memcpy(&v, img_at(m, B_START, x, y, 0), 4);
                if (!(known_tmax(c) && v > tmax)) /* N4 */
                    FZ_CHECK(fz_finite(v) && v >= 0.0f && v <= tmax, "pixel (%u, %u) start %g outside [0, t_max %g] (method %u)",
                             x, y, (double)v, (double)tmax, c->cfg.method);
            }
            if (m->p[B_HIT]) {
                hit = *img_at(m, B_HIT, x, y, 0);
                FZ_CHECK(hit <= 1, "pixel (%u, %u) hit %u", x, y, hit);
            }
            if (m->p[B_STEPS]) {
                memcpy(&u, img_at(m, B_STEPS, x, y, 0), 4);
                FZ_CHECK((uint64_t)u <= smax, "pixel (%u, %u) steps %u above spp * max_steps %llu", x, y, u,
                         (unsigned long long)smax);
            }
        }
}

/* a's pixels [x0, x1) x [y0, y1) equal b's (b may be a tile buffer with its own origin) */
static void img_same(const imgset *a, const imgset *b, uint32_t bx, uint32_t by, const char *what)
{
    int k;
    uint32_t x, y;
    for (k = 0; k < B_NUM; ++k) {
        size_t n = (size_t)b_comp[k] * b_elem[k];
        if (!a->p[k] || !b->p[k]) continue;
        for (y = 0; y < b->h; ++y)
            for (x = 0; x < b->w; ++x)
                FZ_CHECK(!memcmp(img_at(a, k, bx + x, by + y, 0), img_at(b, k, x, y, 0), n),
                         "%s: buffer %d differs at pixel (%u, %u)", what, k, bx + x, by + y);
    }
}

/* sorted cut points: 0 = c[0] < ... < c[n] = len */
static uint32_t cuts(fz_in *in, uint32_t len, uint32_t *c, uint32_t maxn)
{
    uint32_t n = 1, k = fz_pick(in, maxn), i;
    c[0] = 0;
    for (i = 0; i < k && len > 1; ++i) {
        uint32_t v = 1u + fz_pick(in, len - 1u), j;
        for (j = 0; j < n; ++j) if (c[j] == v) break;
        if (j == n) c[n++] = v;
    }
    c[n] = len;
    /* insertion sort of c[1..n-1] */
    for (i = 2; i < n; ++i) {
        uint32_t v = c[i], j = i;
        while (j > 1 && c[j - 1] > v) { c[j] = c[j - 1]; --j; }
        c[j] = v;
    }
    return n;
}

static void render_checks(fz_in *in, const fovsdf_ctx *ctx)
{
    uint32_t w = ctx->cam.width, h = ctx->cam.height, pad = fz_pick(in, 3), keep = fz_u16(in) | 1u;
    uint32_t split = fz_pick(in, 3), xc[8], yc[8], nx, ny, i, j;
    imgset A, B;
    fov_result r;
    fovsdf_stats st;
    memset(&st, 0, sizeof st);
    if (fz_pick(in, 4) == 0) keep = 0x1FF;
    img_alloc(&A, w, h, pad, 0, 0, keep);
    r = fovsdf_render_rows(ctx, 0, h, &A.out, &st);
    FZ_CHECK(r == FOV_OK, "render_rows(0, %u) of a valid context: %d", h, (int)r);
    img_guard(&A, "whole image");
    check_pixels(ctx, &A);
    FZ_CHECK(st.hits <= st.rays && st.exhausted <= st.rays, "stats: hits %llu exhausted %llu rays %llu",
             (unsigned long long)st.hits, (unsigned long long)st.exhausted, (unsigned long long)st.rays);
    /* out-of-range calls write nothing */
    r = fovsdf_render_rows(ctx, h, h + 1u, &A.out, NULL);
    FZ_CHECK(r != FOV_OK, "render_rows past the image returned FOV_OK");
    r = fovsdf_render_tile(ctx, 0, 0, w + 1u, 1, &A.out, NULL);
    FZ_CHECK(r != FOV_OK, "render_tile past the image returned FOV_OK");
    img_guard(&A, "after out-of-range calls");

    /* the same image from a split into rows or tiles */
    img_alloc(&B, w, h, fz_pick(in, 3), 0, 0, keep);
    ny = cuts(in, h, yc, 4);
    if (split == 0) {
        for (j = 0; j < ny; ++j) {
            uint32_t jj = (yc[1] & 1u) ? j : ny - 1u - j; /* forwards or backwards */
            FZ_CHECK(fovsdf_render_rows(ctx, yc[jj], yc[jj + 1], &B.out, NULL) == FOV_OK, "render_rows band");
        }
    } else {
        nx = cuts(in, w, xc, 4);
        for (j = 0; j < ny; ++j)
            for (i = 0; i < nx; ++i) {
                uint32_t ii = split == 1 ? i : nx - 1u - i;
                FZ_CHECK(fovsdf_render_tile(ctx, xc[ii], yc[j], xc[ii + 1], yc[j + 1], &B.out, NULL) == FOV_OK,
                         "render_tile (%u, %u)-(%u, %u)", xc[ii], yc[j], xc[ii + 1], yc[j + 1]);
            }
    }
    img_guard(&B, "split image");
    img_same(&A, &B, 0, 0, "split into rows/tiles");
    img_free(&B);

    /* one tile into a tile buffer (origin_x/y) */
    if (fz_u8(in) & 1u) {
        uint32_t x0 = fz_pick(in, w), y0 = fz_pick(in, h);
        uint32_t x1 = x0 + 1u + fz_pick(in, w - x0), y1 = y0 + 1u + fz_pick(in, h - y0);
        imgset T;
        img_alloc(&T, x1 - x0, y1 - y0, fz_pick(in, 3), x0, y0, keep);
        /* a zero stride means rows of width - origin_x pixels: give explicit strides when the
           tile is narrower than that */
        if (x1 < w) {
            int k;
            for (k = 0; k < B_NUM; ++k) if (!T.stride[k]) T.stride[k] = T.row[k];
            T.out.rgb_stride = T.stride[B_RGB]; T.out.rgb8_stride = T.stride[B_RGB8];
            T.out.depth_stride = T.stride[B_DEPTH]; T.out.hit_stride = T.stride[B_HIT];
            T.out.evals_stride = T.stride[B_EVALS]; T.out.steps_stride = T.stride[B_STEPS];
            T.out.start_stride = T.stride[B_START]; T.out.material_stride = T.stride[B_MAT];
            T.out.mask_stride = T.stride[B_MASK];
        }
        r = fovsdf_render_tile(ctx, x0, y0, x1, y1, &T.out, NULL);
        FZ_CHECK(r == FOV_OK, "render_tile into a tile buffer: %d", (int)r);
        img_guard(&T, "tile buffer");
        img_same(&A, &T, x0, y0, "tile buffer");
        if (x0 > 0 || y0 > 0) {
            r = fovsdf_render_tile(ctx, 0, 0, x1, y1, &T.out, NULL);
            FZ_CHECK(r != FOV_OK, "render_tile left of / above the buffer origin returned FOV_OK");
            img_guard(&T, "tile buffer after a refused call");
        }
        img_free(&T);
    }
    img_free(&A);
}

static void check_hit(const fovsdf_hit *h, float t_start, float t_max, uint32_t max_steps, const char *what)
{
    FZ_CHECK(h->kind <= FOVSDF_EXHAUSTED, "%s: kind %u", what, h->kind);
    FZ_CHECK(fz_finite(h->t), "%s: t %g not finite (kind %u)", what, (double)h->t, h->kind);
    FZ_CHECK(h->steps <= max_steps, "%s: steps %u above max_steps %u", what, h->steps, max_steps);
    if (t_start <= t_max) {
        FZ_CHECK(h->t >= t_start && h->t <= t_max, "%s: t %g outside [t_start %g, t_max %g] (kind %u)", what, (double)h->t,
                 (double)t_start, (double)t_max, h->kind);
    }
    if (h->kind == FOVSDF_MISS && t_start <= t_max)
        FZ_CHECK(h->t == t_max, "%s: miss with t %g, not t_max %g", what, (double)h->t, (double)t_max);
}

static void ray_checks(fz_in *in, const fovsdf_ctx *ctx, const scen *s, int H)
{
    float w = (float)ctx->cam.width, hgt = (float)ctx->cam.height, hi = rgb_bound(ctx), lo = rgb_floor(ctx);
    uint32_t n = fz_pick(in, 4), k, j, np = 0;
    float pxy[8], prgb[12], pt[4];
    for (k = 0; k < n; ++k) {
        float px = rf(in, -w, 2.0f * w, H), py = rf(in, -hgt, 2.0f * hgt, H), ro[3], rd[3], rgb[3], t = -1.0f;
        double l;
        int32_t mat = 7;
        fov_result r;
        if (fz_known_off && (fabsf(px) > 1e6f || fabsf(py) > 1e6f)) continue;
        r = fovsdf_camera_ray(ctx, px, py, ro, rd);
        if (r == FOV_OK) {
            FZ_CHECK(fz_finite_n(ro, 3) && fz_finite_n(rd, 3), "camera_ray(%g, %g): not finite", (double)px, (double)py);
            l = sqrt((double)rd[0] * rd[0] + (double)rd[1] * rd[1] + (double)rd[2] * rd[2]);
            FZ_CHECK(fabs(l - 1.0) < 1e-4, "camera_ray(%g, %g): |rd| = %g", (double)px, (double)py, l);
        } else {
            FZ_CHECK(!fz_finite(px) || !fz_finite(py), "camera_ray(%g, %g) refused: %d", (double)px, (double)py, (int)r);
        }
        r = fovsdf_shade_point(ctx, px, py, rgb, &t, &mat, NULL);
        if (r == FOV_OK) {
            for (j = 0; j < 3; ++j)
                FZ_CHECK(fz_finite(rgb[j]) && rgb[j] >= lo && rgb[j] <= hi, "shade_point(%g, %g) rgb[%u] = %g outside [%g, %g]",
                         (double)px, (double)py, j, (double)rgb[j], (double)lo, (double)hi);
            if (!(known_tmax(ctx) && t > ctx->t_max))
                FZ_CHECK(fz_finite(t) && t >= 0.0f && t <= ctx->t_max, "shade_point(%g, %g) t = %g outside [0, t_max %g]",
                     (double)px, (double)py, (double)t, (double)ctx->t_max);
            pxy[2 * np] = px; pxy[2 * np + 1] = py; ++np;
        }
    }
    /* the same points as one group with a shared cone head start: the same contract */
    if (np > 0 && fovsdf_shade_points_grouped(ctx, np, pxy, 2, np, prgb, pt, NULL, NULL) == FOV_OK) {
        for (k = 0; k < np; ++k) {
            for (j = 0; j < 3; ++j)
                FZ_CHECK(fz_finite(prgb[3 * k + j]) && prgb[3 * k + j] >= lo && prgb[3 * k + j] <= hi,
                         "shade_points_grouped(%g, %g) rgb[%u] = %g outside [%g, %g]", (double)pxy[2 * k],
                         (double)pxy[2 * k + 1], j, (double)prgb[3 * k + j], (double)lo, (double)hi);
            if (!(known_tmax(ctx) && pt[k] > ctx->t_max))
                FZ_CHECK(fz_finite(pt[k]) && pt[k] >= 0.0f && pt[k] <= ctx->t_max,
                         "shade_points_grouped(%g, %g) t = %g outside [0, t_max %g]", (double)pxy[2 * k],
                         (double)pxy[2 * k + 1], (double)pt[k], (double)ctx->t_max);
        }
    }
    /* fovsdf_trace and fovsdf_march on hostile rays */
    n = fz_pick(in, 3);
    for (k = 0; k < n; ++k) {
        float ro[3], d[3], rd[3], t0;
        double l;
        fovsdf_hit hit;
        fov_result r;
        fovsdf_march_params mp;
        static const uint32_t ms_t[6] = { 0, 1, 3, 16, 64, 70000 };
        for (j = 0; j < 3; ++j) ro[j] = ctx->origin[j] + rf(in, -1.0f, 1.0f, H);
        for (j = 0; j < 3; ++j) d[j] = rf(in, -1.0f, 1.0f, H);
        t0 = rf(in, 0.0f, 20.0f, H);
        l = sqrt((double)d[0] * d[0] + (double)d[1] * d[1] + (double)d[2] * d[2]);
        for (j = 0; j < 3; ++j) rd[j] = (l > 0.0 && l < 1e300) ? (float)(d[j] / l) : d[j];
        if (fz_u8(in) & 1u) { rd[0] = d[0]; rd[1] = d[1]; rd[2] = d[2]; } /* not unit */
        memset(&hit, 0, sizeof hit);
        r = fovsdf_trace(ctx, ro, rd, t0, &hit, NULL);
        if (r == FOV_OK && !(known_tmax(ctx) && hit.t > ctx->t_max) &&
            !(fz_known_off && hit.t < t0 && (ctx->cfg.method == FOVSDF_METHOD_IPR || ctx->cfg.method == FOVSDF_METHOD_SKIP ||
                                             ctx->cfg.method == FOVSDF_METHOD_FIPR))) /* N3 */
            check_hit(&hit, t0, ctx->t_max, ctx->cfg.max_steps, "trace");
        memset(&mp, 0, sizeof mp);
        mp.method = fz_pick(in, 5);
        mp.max_steps = ms_t[fz_pick(in, 6)];
        mp.eps = rf(in, 0.0f, 0.01f, H);
        mp.eps_cone = rf(in, 0.0f, 0.01f, H);
        mp.t_max = rf(in, 0.0f, 100.0f, H);
        mp.omega = rf(in, 1.0f, 2.0f, H);
        mp.ar_beta = rf(in, 0.0f, 1.0f, H);
        mp.bv_relax = rf(in, 0.0f, 1.0f, H);
        memset(&hit, 0, sizeof hit);
        r = fovsdf_march(&s->scene, &mp, ro, rd, t0, &hit, NULL);
        if (r == FOV_OK && !(fz_known_off && mp.method >= FOVSDF_METHOD_AUTORELAXED && hit.t > mp.t_max))
            check_hit(&hit, t0, mp.t_max, mp.max_steps, "march");
        if (s->is_program && fz_finite_n(ro, 3) && fabsf(ro[0]) < 1e4f && fabsf(ro[1]) < 1e4f && fabsf(ro[2]) < 1e4f) {
            float dd = fovsdf_distance(ctx, ro, NULL, NULL);
            FZ_CHECK(dd == dd, "fovsdf_distance NaN at (%g, %g, %g)", (double)ro[0], (double)ro[1], (double)ro[2]);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_begin(data, size);
    uint8_t hostile = fz_u8(&in);
    uint32_t geom = fz_pick(&in, 4);
    int Hc = hostile & 1, Hm = (hostile >> 1) & 1, Hs = (hostile >> 2) & 1, Hr = (hostile >> 3) & 1, Hg = (hostile >> 4) & 1;
    static scen s; /* large: not on the stack */
    fovsdf_config cfg;
    fovsdf_camera cam;
    fov_gaze gaze;
    fovsdf_ctx ctx, before;
    fov_result r;
    int ok;
    size_t need = 0;
    void *work = NULL;
    memset(&s, 0, sizeof s);
    fovsdf_scene_init(&s.scene);
    if (fz_known_off) Hg = Hg && geom != 1;
    switch (geom) {
    case 0: ok = read_builtin_scene(&in, &s); break;
    case 1: ok = read_builder_scene(&in, &s, Hg); break;
    case 2: ok = read_nodes_scene(&in, &s, Hg); break;
    default: ok = read_callback_scene(&in, &s, Hg); break;
    }
    if (!ok) { free(s.mem); return 0; }
    read_config(&in, &cfg, Hc);
    read_camera(&in, &cam, &gaze, &s, Hm);
    read_scene_look(&in, &s.scene, Hs);
    if (fz_known_off && (fabsf(cam.eye_offset) > 1e6f || fabsf(cam.up[0]) > 1e6f || fabsf(cam.up[1]) > 1e6f ||
                         fabsf(cam.up[2]) > 1e6f)) { free(s.mem); return 0; }
    /* keep each input fast: at most 1024 sample rays per image */
    while (cfg.spp > 1 && (uint64_t)cam.width * cam.height * cfg.spp > 1024u) cfg.spp = cfg.spp == 16 ? 4 : 1;
    if (s.have_bi) { /* the built-in scenes cost up to 100 times a callback's evaluation */
        if (cam.width > 8) cam.width = 8;
        if (cam.height > 8) cam.height = 8;
        if (cfg.spp > 1 && cfg.spp <= 16) cfg.spp = 1;
        if (cfg.max_steps == 0 || (cfg.max_steps > 64 && cfg.max_steps <= FOVSDF_MAX_STEPS)) cfg.max_steps = 64;
        if (cfg.shadow_steps == 0 || cfg.shadow_steps > 16) cfg.shadow_steps = 16;
    }

#ifdef FZ_VERBOSE
    fprintf(stderr, "geometry %u hostile 0x%x method %u finish %u spp %u eps_mode %u eps %g eps_px %g steps %u t_max %g "
            "shading %u lipschitz %g scene t_max %g cam %ux%u pos (%g %g %g) target (%g %g %g) up (%g %g %g) fov %g\n",
            geom, hostile, cfg.method, cfg.finish, cfg.spp, cfg.eps_mode, (double)cfg.eps, (double)cfg.eps_px,
            cfg.max_steps, (double)cfg.t_max, cfg.shading, (double)s.scene.lipschitz, (double)s.scene.t_max, cam.width,
            cam.height, (double)cam.pos[0], (double)cam.pos[1], (double)cam.pos[2], (double)cam.target[0],
            (double)cam.target[1], (double)cam.target[2], (double)cam.up[0], (double)cam.up[1], (double)cam.up[2],
            (double)cam.fov_y_deg);
    if (s.have_bi) fprintf(stderr, "builtin %s, %u lights, ambient %g\n", s.bi.name, s.scene.num_lights, (double)s.scene.ambient[0]);
    if (geom == 3)
        fprintf(stderr, "callback sphere (%g %g %g) r %g floor %g bad %u flags: inflate %u albedo %u plain %d\n",
                (double)s.cb.c[0], (double)s.cb.c[1], (double)s.cb.c[2], (double)s.cb.r, (double)s.cb.floor_y, s.cb.bad,
                s.cb.inflate, s.cb.albedo, s.scene.dist != NULL);
#endif
    memset(&ctx, 0x5A, sizeof ctx);
    memcpy(&before, &ctx, sizeof ctx);
    if (fovsdf_memory_size(&cfg, &cam, &need) == FOV_OK && need > 0 && need < ((size_t)1 << 26)) {
        work = fz_alloc(need, 0);
    } else {
        need = 0;
    }
    r = fovsdf_init(&ctx, &cfg, &s.scene, &cam, gaze, work, need);
    if (r != FOV_OK) {
        FZ_CHECK(!memcmp(&ctx, &before, sizeof ctx), "a failed fovsdf_init (%d) changed the context", (int)r);
        FZ_CHECK(r < 0 && r >= FOV_ERR_UNSUPPORTED, "fovsdf_init returned %d", (int)r);
        free(work);
        free(s.mem);
        return 0;
    }
    FZ_CHECK(fz_finite(ctx.t_max) && ctx.t_max > 0.0f, "ctx t_max %g", (double)ctx.t_max);
    FZ_CHECK(fovsdf_band_rows(&ctx) >= 1, "band_rows 0");
    render_checks(&in, &ctx);
    ray_checks(&in, &ctx, &s, Hr);
    if (work) FZ_CHECK(fz_canary_ok(work, need), "working memory overrun");
    free(work);
    free(s.mem);
    return 0;
}
