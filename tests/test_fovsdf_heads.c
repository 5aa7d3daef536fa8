/* test_fovsdf_heads.c - the head starts of IPR, SKIP and FIPR (and CONE_FOV's interpolated
   pixels) in fovsdf.h.

   1. The safe variants (heuristic_start 0, the default): no sample ray starts past its first
      hit. Random stress scenes of the kinds that broke the thesis's heuristics (thin shells of
      thickness 0.002, needles of radius 0.002, dust of tiny spheres, thin pillars in a room
      with the camera inside, a grazing floor with low bumps), random cameras, image sizes,
      tile and block sizes, 1 and 4 spp. The reference is this file's own double-precision SDF
      of the scene, sphere traced in double along the library's rays (fovsdf_camera_ray): a
      start S is a violation when that trace finds a surface (distance below 1e-7) before
      S - tol. The same scenes with heuristic_start 1 must show violations (the test can fail).
   2. The thesis variant (heuristic_start 1) renders the built-in scenes exactly as before
      (hashes of the images, depths and starts: tests/heads_hashes.c, the same loop. First
      recorded from fovsdf.h of commit dcdc067, where it was the only variant, which showed
      the safe variants left it unchanged; refreshed with -DNEWHDR for fovsdf 0.3.0, whose
      shared tracers changed (a verified refinement, hits within t_max, the per-ray pixel
      cone: CLASSIC's images changed too), and again for the refinement's empty-ball
      certificate (CLASSIC's images changed too: primitives 19.8 -> 29.8 dB). gcc -O2 and
      -O1 with sanitizers give the same hashes, FOV_NO_LIBM its own).
   3. Regressions: a 1x1 image sends SKIP's low-resolution ray through its pixel (it went
      outside the image); FIPR / CONE_FOV interpolated pixels never report a depth outside
      [0, t_max] or a non-finite one (a tracer's hit beyond t_max, and a Menger node of
      half-size 4.6e-41 that gave depth inf).
   "The thesis": A. Polychronakis, "Implicit and Foveated Techniques for Real-Time Computer
   Graphics Rendering", doctoral dissertation, Technical University of Crete, 2025. */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fovcheck.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct rng { uint64_t s; } rng;
static double urand(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}
static double urange(rng *r, double a, double b) { return a + (b - a) * urand(r); }

/* ---- the reference scene: exact SDFs in double, and the same scene through the builder ---- */
enum { P_SPHERE, P_SHELL, P_CAPSULE, P_CYL, P_ROOM, P_PLANE };
#define MAXP 96
typedef struct prim { int kind; double c[3], e[3], r, th; } prim;
typedef struct scene_t { prim p[MAXP]; int n; const char *kind; } scene_t;

static double len3(double x, double y, double z) { return sqrt(x * x + y * y + z * z); }
static double sd_box(const double q[3], const double h[3])
{
    double d0 = fabs(q[0]) - h[0], d1 = fabs(q[1]) - h[1], d2 = fabs(q[2]) - h[2];
    double out = len3(d0 > 0 ? d0 : 0, d1 > 0 ? d1 : 0, d2 > 0 ? d2 : 0);
    double in = d0 > d1 ? (d0 > d2 ? d0 : d2) : (d1 > d2 ? d1 : d2);
    return out + (in < 0 ? in : 0);
}
static double sd_prim(const prim *p, const double x[3])
{
    double q[3] = { x[0] - p->c[0], x[1] - p->c[1], x[2] - p->c[2] };
    switch (p->kind) {
    case P_SPHERE: return len3(q[0], q[1], q[2]) - p->r;
    case P_SHELL: return fabs(len3(q[0], q[1], q[2]) - p->r) - p->th;
    case P_CAPSULE: {
        double ba[3] = { p->e[0] - p->c[0], p->e[1] - p->c[1], p->e[2] - p->c[2] };
        double h = (q[0] * ba[0] + q[1] * ba[1] + q[2] * ba[2]) / (ba[0] * ba[0] + ba[1] * ba[1] + ba[2] * ba[2]);
        h = h < 0 ? 0 : (h > 1 ? 1 : h);
        return len3(q[0] - ba[0] * h, q[1] - ba[1] * h, q[2] - ba[2] * h) - p->r;
    }
    case P_CYL: {
        double dx = sqrt(q[0] * q[0] + q[2] * q[2]) - p->r, dy = fabs(q[1]) - p->th;
        double in = dx > dy ? dx : dy;
        return (in < 0 ? in : 0) + sqrt((dx > 0 ? dx * dx : 0) + (dy > 0 ? dy * dy : 0));
    }
    case P_ROOM: {
        double big[3] = { 50, 50, 50 }, a = sd_box(q, big), b = -sd_box(q, p->e);
        return a > b ? a : b;
    }
    default: return x[1] - p->c[1];
    }
}
static double sd_scene(const scene_t *s, const double x[3])
{
    double d = 1e300;
    int i;
    for (i = 0; i < s->n; ++i) {
        double e = sd_prim(&s->p[i], x);
        d = e < d ? e : d;
    }
    return d;
}

/* Sphere trace o + t d in double from 0 towards S: the first t where the distance drops below
   1e-7 (a surface), or -1 when [0, S] is free, or -2 when the step budget ran out first. */
static double first_surface(const scene_t *s, const double o[3], const double d[3], double S)
{
    double t = 0.0;
    long i;
    for (i = 0; i < 4000000L; ++i) {
        double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] }, e = sd_scene(s, x);
        if (e < 1e-7) return t;
        t += e;
        if (t >= S) return -1.0;
    }
    return -2.0;
}

static int build(const scene_t *s, fovsdf_node *nodes, uint32_t cap, fovsdf_program *prog, void *mem, size_t memsz)
{
    fovsdf_builder b;
    int32_t r = -1;
    int i;
    fovsdf_builder_init(&b, nodes, cap);
    for (i = 0; i < s->n; ++i) {
        const prim *p = &s->p[i];
        float cx = (float)p->c[0], cy = (float)p->c[1], cz = (float)p->c[2];
        int32_t x;
        b.material = i % 7;
        switch (p->kind) {
        case P_SPHERE: x = fovsdf_translate(&b, fovsdf_sphere(&b, (float)p->r), cx, cy, cz); break;
        case P_SHELL: x = fovsdf_translate(&b, fovsdf_onion(&b, fovsdf_sphere(&b, (float)p->r), (float)p->th), cx, cy, cz); break;
        case P_CAPSULE: {
            float a[3] = { cx, cy, cz }, e[3] = { (float)p->e[0], (float)p->e[1], (float)p->e[2] };
            x = fovsdf_capsule(&b, a, e, (float)p->r);
            break;
        }
        case P_CYL: x = fovsdf_translate(&b, fovsdf_cylinder(&b, (float)p->th, (float)p->r), cx, cy, cz); break;
        case P_ROOM:
            x = fovsdf_translate(&b, fovsdf_subtract(&b, fovsdf_box(&b, 50.0f, 50.0f, 50.0f),
                                                     fovsdf_box(&b, (float)p->e[0], (float)p->e[1], (float)p->e[2])),
                                 cx, cy, cz);
            break;
        default: x = fovsdf_plane(&b, 0.0f, 1.0f, 0.0f, -cy); break;
        }
        r = r < 0 ? x : fovsdf_union(&b, r, x);
    }
    if (b.err != FOV_OK || r < 0) return 0;
    return fovsdf_program_build(prog, nodes, b.count, r, mem, memsz) == FOV_OK;
}

static prim *add(scene_t *s, int kind)
{
    prim *p = &s->p[s->n++];
    memset(p, 0, sizeof *p);
    p->kind = kind;
    return p;
}

/* One stress scene and a camera for it (pos, target, fov). */
static void stress_scene(rng *g, int kind, scene_t *s, float pos[3], float tgt[3], float *fov)
{
    int i, n;
    double ang = urange(g, 0, 6.2831853), dist = urange(g, 4.0, 8.0);
    s->n = 0;
    pos[0] = (float)(dist * cos(ang)); pos[1] = (float)urange(g, -1.0, 2.5); pos[2] = (float)(dist * sin(ang));
    tgt[0] = (float)urange(g, -0.5, 0.5); tgt[1] = (float)urange(g, -0.5, 0.5); tgt[2] = (float)urange(g, -0.5, 0.5);
    *fov = (float)urange(g, 20.0, 90.0);
    switch (kind) {
    case 0: /* thin shells (onion, thickness 0.002), sometimes nested, a floor now and then */
        s->kind = "shells";
        n = 1 + (int)(urand(g) * 4.0);
        for (i = 0; i < n; ++i) {
            prim *p = add(s, P_SHELL);
            p->c[0] = urange(g, -1.5, 1.5); p->c[1] = urange(g, -1, 1); p->c[2] = urange(g, -1.5, 1.5);
            p->r = urange(g, 0.3, 1.6);
            p->th = 0.002;
        }
        if (urand(g) < 0.5) add(s, P_PLANE)->c[1] = urange(g, -2.5, -1.5);
        break;
    case 1: /* needles: capsules of radius 0.002 */
        s->kind = "needles";
        n = 5 + (int)(urand(g) * 16.0);
        for (i = 0; i < n; ++i) {
            prim *p = add(s, P_CAPSULE);
            int k;
            for (k = 0; k < 3; ++k) { p->c[k] = urange(g, -2.5, 2.5); p->e[k] = p->c[k] + urange(g, -2.0, 2.0); }
            p->r = 0.002;
        }
        break;
    case 2: /* dust: tiny spheres around one larger one */
        s->kind = "dust";
        n = 30 + (int)(urand(g) * 50.0);
        for (i = 0; i < n; ++i) {
            prim *p = add(s, P_SPHERE);
            p->c[0] = urange(g, -2, 2); p->c[1] = urange(g, -2, 2); p->c[2] = urange(g, -2, 2);
            p->r = urange(g, 0.002, 0.01);
        }
        {
            prim *p = add(s, P_SPHERE);
            p->r = urange(g, 0.2, 0.6);
        }
        break;
    case 3: /* a closed room with thin pillars, the camera inside */
        s->kind = "room";
        {
            prim *p = add(s, P_ROOM);
            p->e[0] = 4.0; p->e[1] = 2.0; p->e[2] = 4.0;
        }
        n = 3 + (int)(urand(g) * 10.0);
        for (i = 0; i < n; ++i) {
            prim *p = add(s, P_CYL);
            p->c[0] = urange(g, -3.5, 3.5); p->c[2] = urange(g, -3.5, 3.5);
            p->r = urange(g, 0.005, 0.03);
            p->th = 2.0;
        }
        pos[0] = (float)urange(g, -3.0, 3.0); pos[1] = (float)urange(g, -1.5, 1.5); pos[2] = (float)urange(g, -3.0, 3.0);
        tgt[0] = (float)urange(g, -4, 4); tgt[1] = (float)urange(g, -1.5, 1.5); tgt[2] = (float)urange(g, -4, 4);
        if (fabs((double)(tgt[0] - pos[0])) + fabs((double)(tgt[2] - pos[2])) < 0.5) tgt[0] = pos[0] + 1.0f;
        *fov = (float)urange(g, 40.0, 110.0);
        break;
    default: /* a grazing floor with low bumps and a needle lying on it */
        s->kind = "grazing";
        add(s, P_PLANE)->c[1] = 0.0;
        n = 5 + (int)(urand(g) * 20.0);
        for (i = 0; i < n; ++i) {
            prim *p = add(s, P_SPHERE);
            p->r = urange(g, 0.01, 0.1);
            p->c[0] = urange(g, -6, 6); p->c[1] = -0.6 * p->r; p->c[2] = urange(g, -6, 6);
        }
        {
            prim *p = add(s, P_CAPSULE);
            p->c[0] = urange(g, -3, 3); p->c[1] = 0.003; p->c[2] = urange(g, -3, 3);
            p->e[0] = p->c[0] + urange(g, -3, 3); p->e[1] = 0.003; p->e[2] = p->c[2] + urange(g, -3, 3);
            p->r = 0.002;
        }
        pos[0] = (float)(8.0 * cos(ang)); pos[1] = (float)urange(g, 0.003, 0.06); pos[2] = (float)(8.0 * sin(ang));
        tgt[0] = (float)urange(g, -1, 1); tgt[1] = (float)urange(g, 0.0, 0.05); tgt[2] = (float)urange(g, -1, 1);
        *fov = (float)urange(g, 20.0, 70.0);
        break;
    }
}

/* The documented sample offsets (fovsdf.h, config comment). */
static void sample_offset(uint32_t spp, uint32_t s, double *ox, double *oy)
{
    static const double p4[4][2] = { { -0.125, -0.375 }, { 0.375, -0.125 }, { 0.125, 0.375 }, { -0.375, 0.125 } };
    if (spp == 4) { *ox = p4[s][0]; *oy = p4[s][1]; return; }
    *ox = *oy = 0.0;
}

typedef struct tally {
    long rays, bad, unknown, scenes, mid, mid_past, mid_starts, mid_start_bad;
    char first[256];
} tally;

/* Renders one config and checks every traced pixel's sample rays against the reference. */
static void check_starts(const scene_t *s, const fovsdf_ctx *k, tally *ty, int check_mid)
{
    static float start[96 * 72], depth[96 * 72];
    static uint8_t mask[96 * 72];
    fovsdf_output o;
    uint32_t W = k->cam.width, H = k->cam.height, x, y, smp;
    fovsdf_output_init(&o);
    o.start = start; o.mask = mask; o.depth = depth;
    fovsdf_render_rows(k, 0, H, &o, NULL);
    ty->scenes++;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            double S = (double)start[y * W + x];
            if (mask[y * W + x] == 0 && check_mid) {
                /* an interpolated pixel shows its 2x2 cell's centre ray (the mid level). Safe
                   FIPR: that ray's start, recomputed with the library's own calls (the cell's
                   certified start from its 4x4 parent's), must not lie past its first surface.
                   Both variants: count the pixels whose depth lies past it (INFO: the tracer's
                   own refinement, item 1 of issue 10, also does that from a safe start). */
                double o3[3], d3[3], tt, D = (double)depth[y * W + x], T0 = -1.0;
                float ro[3], rd[3];
                uint32_t u = x / 2u, v = y / 2u;
                fovsdf_camera_ray(k, (float)(u * 2u + 1u), (float)(v * 2u + 1u), ro, rd);
                o3[0] = (double)ro[0]; o3[1] = (double)ro[1]; o3[2] = (double)ro[2];
                d3[0] = (double)rd[0]; d3[1] = (double)rd[1]; d3[2] = (double)rd[2];
                if (k->cfg.method == FOVSDF_METHOD_FIPR && !k->cfg.heuristic_start && (x & 1u) == 0 && (y & 1u) == 0) {
                    fovsdf__marcher mm;
                    fovsdf_stats ss;
                    float t4;
                    memset(&ss, 0, sizeof ss);
                    fovsdf__marcher_from_ctx(k, &mm, k->origin);
                    t4 = fovsdf__safe_start(k, &mm, (float)(4u * (x / 4u)), (float)(4u * (y / 4u)), (float)(4u * (x / 4u) + 4u),
                                            (float)(4u * (y / 4u) + 4u), 0.0f, &ss);
                    T0 = (double)fovsdf__safe_start(k, &mm, (float)(2u * u), (float)(2u * v), (float)(2u * u + 2u), (float)(2u * v + 2u), t4, &ss);
                    if (T0 < 0.0) T0 = (double)k->t_max; /* proven empty */
                    ty->mid_starts++;
                    tt = first_surface(s, o3, d3, T0 - 1e-5 * (len3(o3[0], o3[1], o3[2]) + T0));
                    if (tt >= 0.0) ty->mid_start_bad++;
                }
                if (!(D < (double)k->t_max)) continue;
                ty->mid++;
                tt = first_surface(s, o3, d3, D);
                if (tt >= 0.0 && D > tt + 1e-3 * (1.0 + tt)) ty->mid_past++;
                continue;
            }
            if (mask[y * W + x] != 1) continue;
            for (smp = 0; smp < k->cfg.spp; ++smp) {
                double ox, oy, o3[3], d3[3], tt, tol;
                float ro[3], rd[3];
                sample_offset(k->cfg.spp, smp, &ox, &oy);
                fovsdf_camera_ray(k, (float)((double)x + 0.5 + ox), (float)((double)y + 0.5 + oy), ro, rd);
                o3[0] = (double)ro[0]; o3[1] = (double)ro[1]; o3[2] = (double)ro[2];
                d3[0] = (double)rd[0]; d3[1] = (double)rd[1]; d3[2] = (double)rd[2];
                ty->rays++;
                tol = 1e-5 * (len3(o3[0], o3[1], o3[2]) + S);
                if (S <= tol) continue;
                tt = first_surface(s, o3, d3, S - tol);
                if (tt == -2.0) { ty->unknown++; continue; }
                if (tt >= 0.0) {
                    if (!ty->bad)
                        snprintf(ty->first, sizeof ty->first, "%s scene, %s tile %u block %u spp %u, pixel (%u,%u): start %.7g, surface at %.7g",
                                 s->kind, fovsdf_method_name(k->cfg.method), k->cfg.method == FOVSDF_METHOD_CONE_FOV ? k->cfg.cone_tile : k->cfg.ipr_tile,
                                 k->cfg.skip_block, k->cfg.spp, x, y, S, tt);
                    ty->bad++;
                }
            }
        }
}

static void property_test(void)
{
    static fovsdf_node nodes[6 * MAXP];
    static unsigned char mem[1 << 19];
    const uint32_t methods[4] = { FOVSDF_METHOD_IPR, FOVSDF_METHOD_SKIP, FOVSDF_METHOD_FIPR, FOVSDF_METHOD_CONE_FOV };
    const uint32_t iprt[3] = { 8, 16, 32 }, conet[4] = { 4, 8, 16, 32 };
    tally safe[4], thesis[4];
    rng g = { 2026 };
    int it, mi, builds = 0;
    memset(safe, 0, sizeof safe);
    memset(thesis, 0, sizeof thesis);
    for (it = 0; it < 100; ++it) {
        scene_t s;
        fovsdf_program prog;
        fovsdf_scene sc;
        fovsdf_camera cam;
        float pos[3], tgt[3], fov;
        uint32_t W, H, spp = (it & 1) ? 4u : 1u;
        stress_scene(&g, it % 5, &s, pos, tgt, &fov);
        if (!build(&s, nodes, 6 * MAXP, &prog, mem, sizeof mem)) continue;
        ++builds;
        fovsdf_scene_init(&sc);
        fovsdf_scene_set_program(&sc, &prog);
        W = 17 + (uint32_t)(urand(&g) * 79.0);
        H = 9 + (uint32_t)(urand(&g) * 63.0);
        fovsdf_camera_init(&cam, W, H);
        memcpy(cam.pos, pos, sizeof pos);
        memcpy(cam.target, tgt, sizeof tgt);
        cam.fov_y_deg = fov;
        for (mi = 0; mi < 4; ++mi) {
            fovsdf_config c = fovsdf_config_default();
            fovsdf_ctx k;
            fov_gaze gz;
            int v;
            c.method = methods[mi];
            c.spp = spp;
            c.shading = FOVSDF_SHADE_DEPTH;
            c.t_max = 40.0f;
            c.ipr_tile = iprt[(uint32_t)it % 3u];
            c.ipr_levels = 2u + (uint32_t)(urand(&g) * 3.0); /* 2 .. 4 */
            if (c.ipr_tile % (1u << (c.ipr_levels - 1u)) != 0) c.ipr_levels = 3;
            if (methods[mi] == FOVSDF_METHOD_FIPR) c.ipr_levels = 0;
            c.skip_block = 1u + (uint32_t)(urand(&g) * 16.0);
            c.cone_tile = conet[(uint32_t)it % 4u];
            c.cone_levels = 0;
            c.acuity.fovea_deg = (float)urange(&g, 5.0, 40.0);
            gz.x = (float)urange(&g, 0.0, (double)W); gz.y = (float)urange(&g, 0.0, (double)H);
            for (v = 0; v < 2; ++v) {
                if (v == 1 && methods[mi] == FOVSDF_METHOD_CONE_FOV) continue; /* one variant */
                c.heuristic_start = (uint32_t)v;
                if (fovsdf_init(&k, &c, &sc, &cam, gz, NULL, 0) != FOV_OK) {
                    tally *t = v ? &thesis[mi] : &safe[mi];
                    if (!t->bad) snprintf(t->first, sizeof t->first, "init failed (scene %d)", it);
                    t->bad++;
                    continue;
                }
                check_starts(&s, &k, v ? &thesis[mi] : &safe[mi], methods[mi] == FOVSDF_METHOD_FIPR || methods[mi] == FOVSDF_METHOD_CONE_FOV);
            }
        }
    }
    for (mi = 0; mi < 4; ++mi) {
        char nm[96];
        const char *m = fovsdf_method_name(methods[mi]);
        snprintf(nm, sizeof nm, "%s_safe_start_never_past_first_hit", m);
        check(builds >= 95 && safe[mi].rays > 150000 && safe[mi].bad == 0 && safe[mi].unknown * 1000 <= safe[mi].rays, nm,
              "%ld of %ld sample rays start past their first surface (%ld undecided; %d scenes); first: %s", safe[mi].bad,
              safe[mi].rays, safe[mi].unknown, builds, safe[mi].first);
        if (methods[mi] == FOVSDF_METHOD_FIPR) {
            check(safe[mi].mid_starts > 5000 && safe[mi].mid_start_bad == 0, "fipr_safe_mid_starts_never_past_first_hit",
                  "%ld of %ld mid-level rays start past their first surface", safe[mi].mid_start_bad, safe[mi].mid_starts);
        }
        if (methods[mi] == FOVSDF_METHOD_FIPR || methods[mi] == FOVSDF_METHOD_CONE_FOV)
            printf("INFO %s: interpolated pixels whose depth lies past their cell ray's first surface: safe %ld of %ld, thesis %ld of %ld\n", m,
                   safe[mi].mid_past, safe[mi].mid, thesis[mi].mid_past, thesis[mi].mid);
        if (methods[mi] != FOVSDF_METHOD_CONE_FOV) {
            snprintf(nm, sizeof nm, "%s_thesis_variant_selectable_and_unsafe_here", m);
            check(thesis[mi].scenes >= 95 && thesis[mi].bad > 0, nm,
                  "heuristic_start 1: %ld of %ld sample rays start past their first surface (the test sees the thesis's misses)",
                  thesis[mi].bad, thesis[mi].rays);
            printf("INFO %s: safe %ld of %ld sample rays start past the first hit, thesis %ld of %ld (%.3f %%)\n", m, safe[mi].bad,
                   safe[mi].rays, thesis[mi].bad, thesis[mi].rays, 100.0 * (double)thesis[mi].bad / (double)(thesis[mi].rays ? thesis[mi].rays : 1));
        }
    }
}

/* ---- the thesis variant renders as before ------------------------------------------------ */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = (const unsigned char *)p;
    while (n--) { h ^= *c++; h *= 1099511628211ull; }
    return h;
}

static void thesis_unchanged(void)
{
    /* FNV-1a of rgb, depth and start at 96x64 (gaze (28.8, 38.4), no shadow rays but on the
       odd scenes) with heuristic_start 1 (see the file's comment: first from commit dcdc067,
       before the safe variants; refreshed for the 0.3.0 tracers; the temple and fractals rows
       refreshed when the terrain and the mandelbulb took the library's own float kernels,
       the other rows unchanged). FIPR on primitives, thin and fractals
       is left out: there the F4 fix (a mid-level hit beyond t_max is a miss) changes it. */
    static const uint64_t want[6][3][2] = {
#if defined(FOV_NO_LIBM) && defined(FOV__SQRT_HW)
        /* FOV_NO_LIBM where fov__sqrtf is the target's instruction (correctly rounded, as
           libm's): printed by tests/heads_hashes.c -DFOV_NO_LIBM -DNEWHDR; the primitives,
           atrium, thin and fractals rows are the libm table's, bit for bit (an independent
           check); columns and temple differ by the other built-in approximations */
        { { 0xd4984c54c6e025f8ull, 0x19514123b9c6d828ull }, { 0x1db0b14f56fc82a6ull, 0x6bfaa08a76a24bb9ull }, { 0xdac16f1190dbf061ull, 0x7c8fafc337dfcf17ull } },
        { { 0x6ab22f934be915cbull, 0x29f1617a330e0beaull }, { 0x110452bf0354e858ull, 0x13ecf82594ab72b4ull }, { 0xbe8474f160facc73ull, 0x4f92092fdff1f8c3ull } },
        { { 0xc10870906eb86239ull, 0x329f31fbc7987993ull }, { 0x0eacefad26402f30ull, 0x742626852ec3a513ull }, { 0x5161e28e985a5c35ull, 0x13d394a05efa4511ull } },
        { { 0xe57239c8126ed9f7ull, 0xd7f38ffe5c2abc4aull }, { 0x364557d18b410d51ull, 0x6eef82e96f1d2f29ull }, { 0x3dcf2ff23189d0aaull, 0x3967daabd3405310ull } },
        { { 0xa33e8d2817b598d0ull, 0xbf10229faca7d21aull }, { 0x08d1a2667553ff88ull, 0x509291dfd02778b8ull }, { 0xb2dcd4300715c3f5ull, 0x71f0ab5dac35f799ull } },
        { { 0x6eec472ceae2ffacull, 0x3e94755cb4f365f7ull }, { 0x3e09e1cde0224383ull, 0xb2e2c7740d644e90ull }, { 0xa9fc139cd9aeb049ull, 0x6ec1474841d1a40full } },
#elif defined(FOV_NO_LIBM)
        /* FOV_NO_LIBM with the software square root */
        { { 0xbef8d2c015d99490ull, 0xd8c6fc3006b0a8bdull }, { 0xecc1737bf481841dull, 0x6eee4888ca16e33eull }, { 0x372c287b9a8f6977ull, 0xcb8a74a1bbe963eaull } },
        { { 0xbf2ffd148ca532d8ull, 0x7018226c63296fb4ull }, { 0x32f9b5b0ecf2d2b5ull, 0x794fa77db67a21d4ull }, { 0x2b121fbb3a22a882ull, 0xa3326e38dc4a559aull } },
        { { 0x061e144fafbac68eull, 0x329b538681766347ull }, { 0xb377fbf0245f3494ull, 0x635f6b14bc77b501ull }, { 0xb25e016e954485d2ull, 0xf2aafbeb432eea8aull } },
        { { 0x5611c4e8b583bde5ull, 0x83b8f848a8853c4full }, { 0xd7da5e2b3c9b86c9ull, 0x04e4eb230010496dull }, { 0x5c09867d1bb95c50ull, 0x214c5ab9c5dd45b4ull } },
        { { 0x38b0377060df6a76ull, 0xf00d23d60b5ec6f1ull }, { 0xc8b1de5a8e491874ull, 0x59c1ee522ce6bb1eull }, { 0xeed210cc97f93e74ull, 0x8d603dc63680f539ull } },
        { { 0x8ac1f44c0af4da74ull, 0x97934f17cf3ae020ull }, { 0x71a01d13f56f24c0ull, 0xfe59169ff698f919ull }, { 0x953df364eb2f0fc3ull, 0x692313f3ca739d9full } },
#else
        { { 0xd4984c54c6e025f8ull, 0x19514123b9c6d828ull }, { 0x1db0b14f56fc82a6ull, 0x6bfaa08a76a24bb9ull }, { 0xdac16f1190dbf061ull, 0x7c8fafc337dfcf17ull } },
        { { 0x3fb28fda26388abbull, 0xb317330a582fa892ull }, { 0xfa428435c9deb3a7ull, 0x1f9eaa88f317a669ull }, { 0xd8422df79820f68eull, 0xdf69cab1da78b306ull } },
        { { 0x33c7cf94f218b0a0ull, 0x4088bf196c3e5a8eull }, { 0xf0f5b4df2434ed6eull, 0x084bd92b75ed9ec1ull }, { 0x84a595d7ce26d5f8ull, 0x0118532067f767b0ull } },
        { { 0xe57239c8126ed9f7ull, 0xd7f38ffe5c2abc4aull }, { 0x364557d18b410d51ull, 0x6eef82e96f1d2f29ull }, { 0x3dcf2ff23189d0aaull, 0x3967daabd3405310ull } },
        { { 0xa33e8d2817b598d0ull, 0xbf10229faca7d21aull }, { 0x08d1a2667553ff88ull, 0x509291dfd02778b8ull }, { 0xb2dcd4300715c3f5ull, 0x71f0ab5dac35f799ull } },
        { { 0x6eec472ceae2ffacull, 0x3e94755cb4f365f7ull }, { 0x3e09e1cde0224383ull, 0xb2e2c7740d644e90ull }, { 0xa9fc139cd9aeb049ull, 0x6ec1474841d1a40full } },
#endif
    };
    const uint32_t methods[3] = { FOVSDF_METHOD_IPR, FOVSDF_METHOD_SKIP, FOVSDF_METHOD_FIPR };
    static float rgb[96 * 64 * 3], dep[96 * 64], st[96 * 64];
    uint32_t id, mi, s, same = 0, runs = 0;
    char diff[256] = "";
    for (id = 0; id < 6; ++id) {
        size_t sz;
        void *mem;
        fovsdf_builtin bi;
        fovsdf_builtin_size(id, &sz);
        mem = malloc(sz);
        fovsdf_builtin_init(id, &bi, mem, sz);
        bi.camera.width = 96;
        bi.camera.height = 64;
        for (mi = 0; mi < 3; ++mi)
            for (s = 0; s < 2; ++s) {
                fovsdf_config c = fovsdf_config_default();
                fovsdf_ctx k;
                fovsdf_output o;
                fov_gaze gz = { 28.8f, 38.4f };
                uint64_t h = 1469598103934665603ull;
                if (methods[mi] == FOVSDF_METHOD_FIPR && (id == 0 || id == 4 || id == 5)) continue;
                c.method = methods[mi];
                c.spp = s ? 4u : 1u;
                c.shading = (id & 1) ? FOVSDF_SHADE_FULL : FOVSDF_SHADE_NO_SHADOWS;
                c.heuristic_start = 1;
                fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
                fovsdf_output_init(&o);
                o.rgb = rgb; o.depth = dep; o.start = st;
                memset(rgb, 0, sizeof rgb); memset(dep, 0, sizeof dep); memset(st, 0, sizeof st);
                fovsdf_render_rows(&k, 0, 64, &o, NULL);
                h = fnv(h, rgb, sizeof rgb); h = fnv(h, dep, sizeof dep); h = fnv(h, st, sizeof st);
                ++runs;
                if (h == want[id][mi][s]) ++same;
                else if (!diff[0]) snprintf(diff, sizeof diff, "%s %s %u spp: %016llx, want %016llx", bi.name, fovsdf_method_name(c.method), c.spp,
                                            (unsigned long long)h, (unsigned long long)want[id][mi][s]);
            }
        free(mem);
    }
    check(runs == 30 && same == runs, "thesis_variant_images_unchanged", "%u of %u renders identical to before; first difference: %s",
          same, runs, diff);
}

/* ---- regressions ------------------------------------------------------------------------- */
/* A 1x1 image: SKIP's low-resolution ray goes through the pixel (it went through (2, 2) with
   the default 4-pixel block: 60 degrees off the axis, past the sphere the pixel sees). */
static void skip_1x1(void)
{
    static fovsdf_node nodes[4];
    static unsigned char mem[8192];
    fovsdf_program prog;
    fovsdf_builder b;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx k;
    fovsdf_output o;
    fov_gaze gz = { 0.5f, 0.5f };
    float start[2], depth[1];
    int v;
    int32_t root;
    fov_result rb;
    fovsdf_builder_init(&b, nodes, 4);
    root = fovsdf_sphere(&b, 1.0f); /* before b.count is read */
    rb = fovsdf_program_build(&prog, nodes, b.count, root, mem, sizeof mem);
    fovsdf_scene_init(&sc);
    fovsdf_scene_set_program(&sc, &prog);
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* the pixel's ray meets the sphere at t = 4 */
    for (v = 0; v < 2; ++v) {
        fovsdf_config c = fovsdf_config_default();
        fov_result r;
        c.method = FOVSDF_METHOD_SKIP;
        c.heuristic_start = (uint32_t)v;
        c.skip_scale = 1.0f; /* no scaling: the low-resolution ray stops at 4 - skip_eps */
        r = fovsdf_init(&k, &c, &sc, &cam, gz, NULL, 0);
        fovsdf_output_init(&o);
        o.start = start; o.depth = depth;
        start[0] = -1.0f;
        fovsdf_render_rows(&k, 0, 1, &o, NULL);
        /* thesis: the low-resolution ray is the pixel's own, stopped at 4 - skip_eps; safe: the
           pixel's cone (a 60-degree pixel) stops earlier, but after the camera */
        check(rb == FOV_OK && r == FOV_OK && start[0] > (v ? 3.5f : 0.5f) && start[0] <= 4.0f && fabs((double)depth[0] - 4.0) < 1e-3,
              v ? "skip_thesis_1x1_low_res_ray_in_image" : "skip_safe_1x1_head_start",
              "start %.6g (want in (%.1f, 4]: the pixel's own ray meets the sphere at 4), depth %.6g", (double)start[0],
              v ? 3.5 : 0.5, (double)depth[0]);
    }
}

/* F4: FIPR and CONE_FOV interpolated pixels keep their depth within [0, t_max]. */
static void f4_depth_range(void)
{
    size_t sz;
    void *mem;
    fovsdf_builtin bi;
    uint32_t m, bad = 0, px = 0;
    float worst = 0.0f;
    fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &sz);
    mem = malloc(sz);
    fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &bi, mem, sz);
    bi.camera.width = 10; bi.camera.height = 7;
    bi.camera.pos[0] = 0.0f; bi.camera.pos[1] = 2.6f; bi.camera.pos[2] = -7.0f;
    bi.camera.target[0] = 0.0f; bi.camera.target[1] = 0.4f; bi.camera.target[2] = 2.5f;
    bi.camera.up[0] = -0.375f; bi.camera.up[1] = 1.4e-45f; bi.camera.up[2] = -1.0f;
    bi.camera.fov_y_deg = 50.0f;
    for (m = 0; m < 2; ++m) {
        fovsdf_config c = fovsdf_config_default();
        fovsdf_ctx k;
        fovsdf_output o;
        fov_gaze gz = { -4.34f, 0.0f };
        float depth[70];
        uint8_t mask[70];
        uint32_t i;
        c.method = m ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
        c.shading = FOVSDF_SHADE_DEPTH;
        fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
        fovsdf_output_init(&o);
        o.depth = depth; o.mask = mask;
        fovsdf_render_rows(&k, 0, 7, &o, NULL);
        for (i = 0; i < 70; ++i) {
            if (mask[i] != 0) continue;
            ++px;
            if (!(depth[i] >= 0.0f && depth[i] <= k.t_max)) { ++bad; if (!(depth[i] <= worst)) worst = depth[i]; }
        }
    }
    check(bad == 0 && px > 60, "f4_interpolated_depth_within_t_max", "%u of %u interpolated pixels have depth outside [0, 60] (up to %g)", bad,
          px, (double)worst);
    free(mem);
    {   /* a Menger node of half-size 4.6e-41 (program_build takes it): depth inf before */
        static unsigned char pm[65536];
        fovsdf_node n;
        fovsdf_program p;
        fovsdf_scene sc;
        rng g = { 99 };
        uint32_t it, nbad = 0, npx = 0;
        for (it = 0; it < 60; ++it) {
            fovsdf_camera cam;
            fovsdf_config c = fovsdf_config_default();
            fovsdf_ctx k;
            fovsdf_output o;
            fov_gaze gz;
            static float depth[20 * 20];
            static uint8_t mask[20 * 20];
            uint32_t i;
            memset(&n, 0, sizeof n);
            n.type = FOVSDF_NODE_MENGER; n.a = n.b = -1; n.f[0] = 4.6e-41f; n.i[0] = 1 + (int32_t)(it % 5u);
            if (fovsdf_program_build(&p, &n, 1, 0, pm, sizeof pm) != FOV_OK) continue;
            fovsdf_scene_init(&sc);
            fovsdf_scene_set_program(&sc, &p);
            fovsdf_camera_init(&cam, 4 + (uint32_t)(urand(&g) * 16.0), 4 + (uint32_t)(urand(&g) * 16.0));
            cam.pos[0] = (float)urange(&g, -5, 5); cam.pos[1] = (float)urange(&g, -5, 5); cam.pos[2] = (float)urange(&g, -5, 5);
            cam.target[0] = (float)urange(&g, -1e-3, 1e-3); cam.target[1] = (float)urange(&g, -1e-3, 1e-3);
            cam.target[2] = (float)urange(&g, -1e-3, 1e-3);
            cam.fov_y_deg = (float)urange(&g, 5, 150);
            c.method = (it & 1) ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
            c.shading = FOVSDF_SHADE_DEPTH;
            c.cone_tile = 4u << (it % 3u);
            gz.x = -100.0f; gz.y = -100.0f; /* all periphery */
            if (fovsdf_init(&k, &c, &sc, &cam, gz, NULL, 0) != FOV_OK) continue;
            fovsdf_output_init(&o);
            o.depth = depth; o.mask = mask;
            fovsdf_render_rows(&k, 0, cam.height, &o, NULL);
            for (i = 0; i < cam.width * cam.height; ++i) {
                if (mask[i] != 0) continue;
                ++npx;
                if (!(depth[i] >= 0.0f && depth[i] <= k.t_max)) ++nbad;
            }
        }
        check(nbad == 0 && npx > 3000, "f4_tiny_menger_depth_finite", "%u of %u interpolated pixels have depth outside [0, t_max]", nbad, npx);
    }
}

static void config_tests(void)
{
    fovsdf_config c = fovsdf_config_default(), r;
    fov_result e;
    check(c.heuristic_start == 0, "heuristic_start_default_safe", "default %u", c.heuristic_start);
    c.heuristic_start = 1;
    e = fovsdf_config_resolve(&c, &r);
    check(e == FOV_OK && r.heuristic_start == 1, "heuristic_start_1_ok", "got %d", (int)e);
    c.heuristic_start = 2;
    e = fovsdf_config_resolve(&c, &r);
    check(e == FOV_ERR_INVALID_ARG, "heuristic_start_2_rejected", "got %d", (int)e);
}

int main(void)
{
    config_tests();
    skip_1x1();
    f4_depth_range();
    thesis_unchanged();
    property_test();
    return fovcheck_summary();
}
