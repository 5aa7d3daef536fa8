/*
 * test_fovsdf_scene.c - scene-program correctness, bounding volumes and numerical stability
 * of fovsdf.h.
 *
 * Build and run (from the repository root):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovsdf_scene.c -lm -o build/tests/test_fovsdf_scene
 *   ./build/tests/test_fovsdf_scene
 * Also built with -DFOV_NO_LIBM and with -fsanitize=address,undefined (tests/run_all.sh), and
 * it compiles as C++11.
 *
 * Output: one "PASS name" or "FAIL name: detail" line per check, "INFO ..." lines with
 * measured figures, and the closing line "N passed, N failed"; exit status 1 on a failure.
 *
 * Sections:
 *   s1  every primitive and operator against an independent double implementation of the
 *       canonical formulas (Quilez's exact SDFs, the polynomial smooth operators; the cone and
 *       cylinder by brute 2D geometry), materials, sphere tracing of each multi-primitive case
 *   s2  bounding volumes: 200 random scenes (value <= exact, equal near surfaces, skipped-work
 *       accounting, sphere tracing the program vs tracing the exact double function), 40 more
 *       with groups under round / onion / smooth union, malformed node graphs
 *   s3  the six built-in scenes (no independent reference for fractals and terrain: bounded
 *       vs unbounded evaluation of the same program, camera outside, finite values)
 *   s4  numerical stability: far cameras, large and small objects, grazing rays, rays that
 *       start inside, rendered images; the measured depth error against the NUMERICS envelope
 * Expected values come from the double reference in this file, never from fovsdf.h.
 *
 * Bounds and the query: q.eps = 1e4 makes every bounding sphere's skip margin (1.25 r + 4 eps)
 * larger than the sampled region, so the program must equal the exact value everywhere;
 * q.eps = 0.0125 makes every skipped bound report more than 4 * 0.0125 = 0.05, so the program
 * must equal the exact value wherever that is below 0.05 (NEAR_THR), and never exceed it.
 */
#define FOVSDF_IMPLEMENTATION
#define FOVSDF_DOUBLE
#include "fovsdf.h"
#include "fovcheck.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <math.h>
#include <float.h>
#include <time.h>

/* ==== checks ============================================================================== */



/* ==== deterministic random numbers ======================================================== */
typedef struct Rng { uint64_t s; } Rng;

static uint64_t rng_next(Rng *r)
{
    uint64_t x = r->s;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    r->s = x;
    return x;
}
static double urand(Rng *r) { return (double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0); }
static double urange(Rng *r, double a, double b) { return a + (b - a) * urand(r); }
static int irange(Rng *r, int a, int b) { return a + (int)(rng_next(r) % (uint64_t)(b - a + 1)); }

/* ==== double vector helpers =============================================================== */
static double dmin(double a, double b) { return a < b ? a : b; }
static double dmax(double a, double b) { return a > b ? a : b; }
static double dclamp(double x, double a, double b) { return x < a ? a : (x > b ? b : x); }
static double len2d(double x, double y) { return sqrt(x * x + y * y); }
static double len3d(double x, double y, double z) { return sqrt(x * x + y * y + z * z); }
static double dot3d(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double rf(double x) { return (double)(float)x; } /* the value a float parameter holds */
static int finite_d(double x) { return x - x == 0.0; }

/* ==== canonical exact SDFs in double (after Inigo Quilez) ================================= */
static double ref_box(const double p[3], double bx, double by, double bz)
{
    double qx = fabs(p[0]) - bx, qy = fabs(p[1]) - by, qz = fabs(p[2]) - bz;
    return len3d(dmax(qx, 0.0), dmax(qy, 0.0), dmax(qz, 0.0)) + dmin(dmax(qx, dmax(qy, qz)), 0.0);
}
/* sdRoundBox: b are the OUTER half extents, r the rounding radius */
static double ref_round_box(const double p[3], double bx, double by, double bz, double r)
{
    double qx = fabs(p[0]) - bx + r, qy = fabs(p[1]) - by + r, qz = fabs(p[2]) - bz + r;
    return len3d(dmax(qx, 0.0), dmax(qy, 0.0), dmax(qz, 0.0)) + dmin(dmax(qx, dmax(qy, qz)), 0.0) - r;
}
static double ref_frame3(double x, double y, double z)
{
    return len3d(dmax(x, 0.0), dmax(y, 0.0), dmax(z, 0.0)) + dmin(dmax(x, dmax(y, z)), 0.0);
}
static double ref_box_frame(const double p_in[3], double bx, double by, double bz, double e)
{
    double px = fabs(p_in[0]) - bx, py = fabs(p_in[1]) - by, pz = fabs(p_in[2]) - bz;
    double qx = fabs(px + e) - e, qy = fabs(py + e) - e, qz = fabs(pz + e) - e;
    return dmin(dmin(ref_frame3(px, qy, qz), ref_frame3(qx, py, qz)), ref_frame3(qx, qy, pz));
}
static double ref_torus(const double p[3], double R, double r)
{
    return len2d(len2d(p[0], p[2]) - R, p[1]) - r;
}
static double ref_capsule(const double p[3], const double a[3], const double b[3], double r)
{
    double pa[3], ba[3], h;
    int k;
    for (k = 0; k < 3; ++k) { pa[k] = p[k] - a[k]; ba[k] = b[k] - a[k]; }
    h = dot3d(ba, ba) > 0.0 ? dclamp(dot3d(pa, ba) / dot3d(ba, ba), 0.0, 1.0) : 0.0; /* a == b: a sphere */
    return len3d(pa[0] - ba[0] * h, pa[1] - ba[1] * h, pa[2] - ba[2] * h) - r;
}
/* distance from (px, py) to the segment a-b in 2D */
static double seg2(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, h;
    h = l2 > 0.0 ? dclamp(((px - ax) * dx + (py - ay) * dy) / l2, 0.0, 1.0) : 0.0;
    return len2d(px - ax - dx * h, py - ay - dy * h);
}
/* Solid of revolution about y of the trapezoid (0,-h) (r1,-h) (r2,h) (0,h): the capped cone
   (and, with r1 = r2, the capped cylinder). Exact distance by brute 2D geometry in the
   (radius, y) half plane: distance to the three surface edges, negative inside. This does
   not use Quilez's closed form, so it checks it independently. */
static double ref_revolved_trapezoid(const double p[3], double h, double r1, double r2)
{
    double x = len2d(p[0], p[2]), y = p[1];
    double d = dmin(dmin(seg2(x, y, 0.0, -h, r1, -h), seg2(x, y, r1, -h, r2, h)), seg2(x, y, r2, h, 0.0, h));
    int inside = fabs(y) <= h && x <= r1 + (r2 - r1) * (y + h) / (2.0 * h);
    return inside ? -d : d;
}

/* ==== a scene built twice: through the builder, and as a double reference tree ============ */
#define SC_CAP 1024

typedef struct RNode {
    uint32_t type;
    int a, b, mat;
    int iv[3];
    double f[9];
    double R[9]; /* rotate: object -> world, row-major */
} RNode;

typedef struct Sc {
    fovsdf_node nodes[SC_CAP];
    fovsdf_builder b;
    RNode r[SC_CAP];
    int n;          /* reference nodes (must track the builder's count) */
    int ok;         /* every builder call returned the index the reference expected */
    fovsdf_program prog;
    void *mem;
    size_t mem_size;
} Sc;

static Sc *sc_new(void)
{
    Sc *s = (Sc *)calloc(1, sizeof(Sc));
    if (!s) { printf("out of memory\n"); exit(2); }
    fovsdf_builder_init(&s->b, s->nodes, SC_CAP);
    s->ok = 1;
    return s;
}
static void sc_free(Sc *s)
{
    if (!s) return;
    free(s->mem);
    free(s);
}
static void sc_reset(Sc *s)
{
    free(s->mem);
    memset(s, 0, sizeof *s);
    fovsdf_builder_init(&s->b, s->nodes, SC_CAP);
    s->ok = 1;
}
static void sc_mat(Sc *s, int m) { s->b.material = m; }

static RNode *sc_add(Sc *s, int32_t id, uint32_t type)
{
    static RNode dummy;
    RNode *n;
    if (id < 0 || id != s->n || s->n >= SC_CAP) { s->ok = 0; return &dummy; }
    n = &s->r[s->n++];
    memset(n, 0, sizeof *n);
    n->type = type;
    n->a = n->b = -1;
    n->mat = s->b.material;
    return n;
}

static int sc_sphere(Sc *s, double r)
{
    int32_t id = fovsdf_sphere(&s->b, (float)r);
    RNode *n = sc_add(s, id, FOVSDF_NODE_SPHERE);
    n->f[0] = rf(r);
    return id;
}
static int sc_box(Sc *s, double x, double y, double z)
{
    int32_t id = fovsdf_box(&s->b, (float)x, (float)y, (float)z);
    RNode *n = sc_add(s, id, FOVSDF_NODE_BOX);
    n->f[0] = rf(x); n->f[1] = rf(y); n->f[2] = rf(z);
    return id;
}
static int sc_round_box(Sc *s, double x, double y, double z, double r)
{
    int32_t id = fovsdf_round_box(&s->b, (float)x, (float)y, (float)z, (float)r);
    RNode *n = sc_add(s, id, FOVSDF_NODE_ROUND_BOX);
    n->f[0] = rf(x); n->f[1] = rf(y); n->f[2] = rf(z); n->f[3] = rf(r);
    return id;
}
static int sc_box_frame(Sc *s, double x, double y, double z, double e)
{
    int32_t id = fovsdf_box_frame(&s->b, (float)x, (float)y, (float)z, (float)e);
    RNode *n = sc_add(s, id, FOVSDF_NODE_BOX_FRAME);
    n->f[0] = rf(x); n->f[1] = rf(y); n->f[2] = rf(z); n->f[3] = rf(e);
    return id;
}
static int sc_torus(Sc *s, double R, double r)
{
    int32_t id = fovsdf_torus(&s->b, (float)R, (float)r);
    RNode *n = sc_add(s, id, FOVSDF_NODE_TORUS);
    n->f[0] = rf(R); n->f[1] = rf(r);
    return id;
}
static int sc_capsule(Sc *s, const double a[3], const double c[3], double r)
{
    float af[3], cf[3];
    int32_t id;
    RNode *n;
    int k;
    for (k = 0; k < 3; ++k) { af[k] = (float)a[k]; cf[k] = (float)c[k]; }
    id = fovsdf_capsule(&s->b, af, cf, (float)r);
    n = sc_add(s, id, FOVSDF_NODE_CAPSULE);
    for (k = 0; k < 3; ++k) { n->f[k] = (double)af[k]; n->f[3 + k] = (double)cf[k]; }
    n->f[6] = rf(r);
    return id;
}
static int sc_cylinder(Sc *s, double hh, double r)
{
    int32_t id = fovsdf_cylinder(&s->b, (float)hh, (float)r);
    RNode *n = sc_add(s, id, FOVSDF_NODE_CYLINDER);
    n->f[0] = rf(hh); n->f[1] = rf(r);
    return id;
}
static int sc_cone(Sc *s, double hh, double r1, double r2)
{
    int32_t id = fovsdf_cone(&s->b, (float)hh, (float)r1, (float)r2);
    RNode *n = sc_add(s, id, FOVSDF_NODE_CONE);
    n->f[0] = rf(hh); n->f[1] = rf(r1); n->f[2] = rf(r2);
    return id;
}
static int sc_plane(Sc *s, double nx, double ny, double nz, double o)
{
    int32_t id = fovsdf_plane(&s->b, (float)nx, (float)ny, (float)nz, (float)o);
    RNode *n = sc_add(s, id, FOVSDF_NODE_PLANE);
    double l = len3d(rf(nx), rf(ny), rf(nz));
    n->f[0] = rf(nx) / l; n->f[1] = rf(ny) / l; n->f[2] = rf(nz) / l; n->f[3] = rf(o);
    return id;
}
static int sc_bin(Sc *s, uint32_t type, int x, int y, double k)
{
    int32_t id;
    RNode *n;
    switch (type) {
    case FOVSDF_NODE_UNION: id = fovsdf_union(&s->b, x, y); break;
    case FOVSDF_NODE_SUBTRACT: id = fovsdf_subtract(&s->b, x, y); break;
    case FOVSDF_NODE_INTERSECT: id = fovsdf_intersect(&s->b, x, y); break;
    case FOVSDF_NODE_SMOOTH_UNION: id = fovsdf_smooth_union(&s->b, x, y, (float)k); break;
    case FOVSDF_NODE_SMOOTH_SUBTRACT: id = fovsdf_smooth_subtract(&s->b, x, y, (float)k); break;
    default: id = fovsdf_smooth_intersect(&s->b, x, y, (float)k); break;
    }
    n = sc_add(s, id, type);
    n->a = x; n->b = y; n->f[0] = rf(k);
    return id;
}
static int sc_union(Sc *s, int x, int y) { return sc_bin(s, FOVSDF_NODE_UNION, x, y, 0.0); }
static int sc_translate(Sc *s, int x, double tx, double ty, double tz)
{
    int32_t id = fovsdf_translate(&s->b, x, (float)tx, (float)ty, (float)tz);
    RNode *n = sc_add(s, id, FOVSDF_NODE_TRANSLATE);
    n->a = x; n->f[0] = rf(tx); n->f[1] = rf(ty); n->f[2] = rf(tz);
    return id;
}
/* rotation by angle_deg about the axis, object -> world (right-handed, Rodrigues in double) */
static void rot_matrix(double ax, double ay, double az, double deg, double R[9])
{
    double l = len3d(ax, ay, az), x = ax / l, y = ay / l, z = az / l;
    double a = deg * 3.14159265358979323846 / 180.0, c = cos(a), s = sin(a), t = 1.0 - c;
    R[0] = c + x * x * t;     R[1] = x * y * t - z * s; R[2] = x * z * t + y * s;
    R[3] = y * x * t + z * s; R[4] = c + y * y * t;     R[5] = y * z * t - x * s;
    R[6] = z * x * t - y * s; R[7] = z * y * t + x * s; R[8] = c + z * z * t;
}
static int sc_rotate(Sc *s, int x, double ax, double ay, double az, double deg)
{
    int32_t id = fovsdf_rotate(&s->b, x, (float)ax, (float)ay, (float)az, (float)deg);
    RNode *n = sc_add(s, id, FOVSDF_NODE_ROTATE);
    n->a = x;
    rot_matrix(rf(ax), rf(ay), rf(az), rf(deg), n->R);
    return id;
}
static int sc_scale(Sc *s, int x, double k)
{
    int32_t id = fovsdf_scale(&s->b, x, (float)k);
    RNode *n = sc_add(s, id, FOVSDF_NODE_SCALE);
    n->a = x; n->f[0] = rf(k);
    return id;
}
static int sc_repeat(Sc *s, int x, double px, double py, double pz, int nx, int ny, int nz)
{
    int32_t id = fovsdf_repeat(&s->b, x, (float)px, (float)py, (float)pz, nx, ny, nz);
    RNode *n = sc_add(s, id, FOVSDF_NODE_REPEAT);
    n->a = x; n->f[0] = rf(px); n->f[1] = rf(py); n->f[2] = rf(pz);
    n->iv[0] = nx; n->iv[1] = ny; n->iv[2] = nz;
    return id;
}
static int sc_mirror(Sc *s, int x, int axes)
{
    int32_t id = fovsdf_mirror(&s->b, x, axes);
    RNode *n = sc_add(s, id, FOVSDF_NODE_MIRROR);
    n->a = x; n->iv[0] = axes;
    return id;
}
static int sc_round(Sc *s, int x, double r)
{
    int32_t id = fovsdf_round(&s->b, x, (float)r);
    RNode *n = sc_add(s, id, FOVSDF_NODE_ROUND);
    n->a = x; n->f[0] = rf(r);
    return id;
}
static int sc_onion(Sc *s, int x, double t)
{
    int32_t id = fovsdf_onion(&s->b, x, (float)t);
    RNode *n = sc_add(s, id, FOVSDF_NODE_ONION);
    n->a = x; n->f[0] = rf(t);
    return id;
}

/* Reference evaluation in double. mat: material of the operand that decides the value
   (the nearest surface); gap: the smallest margin of any such decision on the way (points
   with a tiny gap have an ambiguous material). */
static double ref_eval(const Sc *s, int id, const double p[3], int *mat, double *gap)
{
    const RNode *n = &s->r[id];
    const double *f = n->f;
    double q[3], a, b, h, r;
    int ma = -1, mb = -1, k;
    switch (n->type) {
    case FOVSDF_NODE_SPHERE: *mat = n->mat; return len3d(p[0], p[1], p[2]) - f[0];
    case FOVSDF_NODE_BOX: *mat = n->mat; return ref_box(p, f[0], f[1], f[2]);
    case FOVSDF_NODE_ROUND_BOX: *mat = n->mat; return ref_round_box(p, f[0], f[1], f[2], f[3]);
    case FOVSDF_NODE_BOX_FRAME: *mat = n->mat; return ref_box_frame(p, f[0], f[1], f[2], f[3]);
    case FOVSDF_NODE_TORUS: *mat = n->mat; return ref_torus(p, f[0], f[1]);
    case FOVSDF_NODE_CAPSULE: *mat = n->mat; return ref_capsule(p, f, f + 3, f[6]);
    case FOVSDF_NODE_CYLINDER: *mat = n->mat; return ref_revolved_trapezoid(p, f[0], f[1], f[1]);
    case FOVSDF_NODE_CONE: *mat = n->mat; return ref_revolved_trapezoid(p, f[0], f[1], f[2]);
    case FOVSDF_NODE_PLANE: *mat = n->mat; return p[0] * f[0] + p[1] * f[1] + p[2] * f[2] + f[3];
    case FOVSDF_NODE_UNION: case FOVSDF_NODE_SUBTRACT: case FOVSDF_NODE_INTERSECT:
    case FOVSDF_NODE_SMOOTH_UNION: case FOVSDF_NODE_SMOOTH_SUBTRACT: case FOVSDF_NODE_SMOOTH_INTERSECT:
        a = ref_eval(s, n->a, p, &ma, gap);
        b = ref_eval(s, n->b, p, &mb, gap);
        switch (n->type) {
        case FOVSDF_NODE_UNION: r = dmin(a, b); *mat = a < b ? ma : mb; *gap = dmin(*gap, fabs(a - b)); break;
        case FOVSDF_NODE_SUBTRACT: r = dmax(a, -b); *mat = a > -b ? ma : mb; *gap = dmin(*gap, fabs(a + b)); break;
        case FOVSDF_NODE_INTERSECT: r = dmax(a, b); *mat = a > b ? ma : mb; *gap = dmin(*gap, fabs(a - b)); break;
        case FOVSDF_NODE_SMOOTH_UNION: /* h = clamp(0.5+0.5(b-a)/k), mix(b,a,h) - k h (1-h) */
            h = dclamp(0.5 + 0.5 * (b - a) / f[0], 0.0, 1.0);
            r = b * (1.0 - h) + a * h - f[0] * h * (1.0 - h);
            *mat = a < b ? ma : mb; *gap = dmin(*gap, fabs(a - b)); break;
        case FOVSDF_NODE_SMOOTH_SUBTRACT: /* h = clamp(0.5-0.5(a+b)/k), mix(a,-b,h) + k h(1-h) */
            h = dclamp(0.5 - 0.5 * (a + b) / f[0], 0.0, 1.0);
            r = a * (1.0 - h) - b * h + f[0] * h * (1.0 - h);
            *mat = a > -b ? ma : mb; *gap = dmin(*gap, fabs(a + b)); break;
        default: /* h = clamp(0.5-0.5(b-a)/k), mix(b,a,h) + k h(1-h) */
            h = dclamp(0.5 - 0.5 * (b - a) / f[0], 0.0, 1.0);
            r = b * (1.0 - h) + a * h + f[0] * h * (1.0 - h);
            *mat = a > b ? ma : mb; *gap = dmin(*gap, fabs(a - b)); break;
        }
        return r;
    case FOVSDF_NODE_TRANSLATE:
        q[0] = p[0] - f[0]; q[1] = p[1] - f[1]; q[2] = p[2] - f[2];
        return ref_eval(s, n->a, q, mat, gap);
    case FOVSDF_NODE_ROTATE: /* world -> object: R^T p */
        for (k = 0; k < 3; ++k) q[k] = n->R[k] * p[0] + n->R[3 + k] * p[1] + n->R[6 + k] * p[2];
        return ref_eval(s, n->a, q, mat, gap);
    case FOVSDF_NODE_SCALE:
        q[0] = p[0] / f[0]; q[1] = p[1] / f[0]; q[2] = p[2] / f[0];
        return f[0] * ref_eval(s, n->a, q, mat, gap);
    case FOVSDF_NODE_REPEAT: /* p - c * round(p / c), round clamped to [-n, n] when limited */
        for (k = 0; k < 3; ++k) {
            q[k] = p[k];
            if (f[k] > 0.0) {
                double c = floor(p[k] / f[k] + 0.5);
                if (n->iv[k] > 0) c = dclamp(c, -(double)n->iv[k], (double)n->iv[k]);
                q[k] = p[k] - f[k] * c;
            }
        }
        return ref_eval(s, n->a, q, mat, gap);
    case FOVSDF_NODE_MIRROR:
        for (k = 0; k < 3; ++k) q[k] = (n->iv[0] & (1 << k)) ? fabs(p[k]) : p[k];
        return ref_eval(s, n->a, q, mat, gap);
    case FOVSDF_NODE_ROUND: return ref_eval(s, n->a, p, mat, gap) - f[0];
    case FOVSDF_NODE_ONION: return fabs(ref_eval(s, n->a, p, mat, gap)) - f[0];
    default: *mat = -99; return 1e30;
    }
}

static double ref_at(const Sc *s, int root, const double p[3], int *mat, double *gap)
{
    int m = -1;
    double g = 1e30, d = ref_eval(s, root, p, &m, &g);
    if (mat) *mat = m;
    if (gap) *gap = g;
    return d;
}

/* Number of primitive nodes reachable from root (counting shared ones once per use). */
static int ref_prims(const Sc *s, int id)
{
    const RNode *n = &s->r[id];
    if (n->type >= FOVSDF_NODE_SPHERE && n->type <= FOVSDF_NODE_TERRAIN) return 1;
    return (n->a >= 0 ? ref_prims(s, n->a) : 0) + (n->b >= 0 ? ref_prims(s, n->b) : 0);
}

/* Compile the builder's nodes under root into s->prog. */
static fov_result sc_build(Sc *s, int root)
{
    size_t bytes = 0;
    fov_result r;
    if (!s->ok || s->b.err != FOV_OK) return FOV_ERR_INVALID_ARG;
    r = fovsdf_program_size(s->nodes, s->b.count, root, &bytes);
    if (r != FOV_OK) return r;
    free(s->mem);
    s->mem = malloc(bytes);
    s->mem_size = bytes;
    if (!s->mem) return FOV_ERR_TOO_SMALL;
    return fovsdf_program_build(&s->prog, s->nodes, s->b.count, root, s->mem, bytes);
}

/* Program value at the float point; eps < 0: no query (q = NULL). */
typedef struct PEval {
    double d;
    int mat;
    uint32_t prims, skipped;
} PEval;

static PEval prog_eval(const fovsdf_program *prog, const double p[3], double eps)
{
    PEval e;
    float pf[3];
    pf[0] = (float)p[0]; pf[1] = (float)p[1]; pf[2] = (float)p[2];
    if (eps < 0.0) {
        e.d = (double)fovsdf_program_eval(pf, NULL, (void *)(uintptr_t)prog);
        e.mat = -2; e.prims = 0; e.skipped = 0;
    } else {
        fovsdf_query q;
        q.inflate = 1.0f; q.eps = (float)eps; q.want_material = 1; q.material = -3;
        q.prims = 0; q.prims_skipped = 0;
        e.d = (double)fovsdf_program_eval(pf, &q, (void *)(uintptr_t)prog);
        e.mat = q.material; e.prims = q.prims; e.skipped = q.prims_skipped;
    }
    return e;
}

/* The point as the program sees it: rounded to float. */
static void fpoint(double p[3])
{
    p[0] = rf(p[0]); p[1] = rf(p[1]); p[2] = rf(p[2]);
}

static double tol_of(double ref) { return 1e-4 * dmax(1.0, fabs(ref)); }

/* q.eps that disables every bound within 1e4 units of it (lim = 1.25 r + 4 eps) */
#define EPS_NO_BOUNDS 1e4
/* q.eps for which a skipped bound is farther than 4 * 0.0125 = 0.05 */
#define EPS_NEAR 0.0125
#define NEAR_THR 0.05

/* ==== section 1: primitives and operators vs the canonical formulas ======================= */

typedef struct Stat {
    int n, bad;
    double max_err;
    double wp[3], wref, wprog; /* worst point */
} Stat;

static void stat_init(Stat *st) { memset(st, 0, sizeof *st); }
static void stat_add(Stat *st, const double p[3], double ref, double prog)
{
    double e = fabs(prog - ref);
    st->n++;
    if (!(e <= tol_of(ref))) st->bad++;
    if (!(e <= st->max_err)) {
        st->max_err = e;
        st->wp[0] = p[0]; st->wp[1] = p[1]; st->wp[2] = p[2];
        st->wref = ref; st->wprog = prog;
    }
}
static void stat_check(const Stat *st, const char *name)
{
    check(st->n > 0 && st->bad == 0, name,
          "%d of %d points off by more than 1e-4 (abs/rel); worst %.3g at (%.5g, %.5g, %.5g): program %.9g, exact %.9g",
          st->bad, st->n, st->max_err, st->wp[0], st->wp[1], st->wp[2], st->wprog, st->wref);
}

static int g_far_wrong, g_far_n; /* s1: far points whose material is neither the nearest nor -1 */

/* a point near the surface under root: a random point in the cube, moved onto the surface by
   a few Newton steps along the reference gradient, then jittered by up to 0.05 */
static void near_point(const Sc *s, int root, Rng *g, const double c[3], double L, double p[3])
{
    int it, k;
    for (k = 0; k < 3; ++k) p[k] = c[k] + urange(g, -L, L);
    for (it = 0; it < 8; ++it) {
        double d = ref_at(s, root, p, NULL, NULL), gr[3], l2 = 0.0, h = 1e-6;
        for (k = 0; k < 3; ++k) {
            double a[3], b[3];
            memcpy(a, p, sizeof a); memcpy(b, p, sizeof b);
            a[k] += h; b[k] -= h;
            gr[k] = (ref_at(s, root, a, NULL, NULL) - ref_at(s, root, b, NULL, NULL)) / (2.0 * h);
            l2 += gr[k] * gr[k];
        }
        if (!(l2 > 1e-18)) break;
        for (k = 0; k < 3; ++k) p[k] -= d * gr[k] / l2;
    }
    for (k = 0; k < 3; ++k) p[k] += urange(g, -0.05, 0.05);
    fpoint(p);
}

static void pinhole_ray(const double pos[3], const double target[3], double fov_deg, int w, int h, int i, int j,
                        double ro[3], double rd[3]);
static fovsdf_march_params march_params(uint32_t method, uint32_t max_steps, double eps, double eps_cone, double t_max);
static double ref_dist_d(const double p[3], void *user);
typedef struct RefCtx { const Sc *s; int root; } RefCtx;

/* Sphere trace a w x h pinhole image of the program (classic, float) and of the exact
   function (fovsdf_trace_ref, double); count hit/miss disagreements and depths that differ
   by more than 1e-3 relative. */
static void trace_compare(const Sc *s, int root, const double cam[3], const double tgt[3], int w, int h, double t_max,
                          int *rays, int *hm_bad, int *both, int *depth_bad, double *worst_rel)
{
    fovsdf_scene fs, ds;
    RefCtx rc;
    fovsdf_march_params mp = march_params(FOVSDF_METHOD_CLASSIC, 1024, 1e-4, 0.0, t_max);
    int i, j, k;
    fovsdf_scene_init(&fs);
    fovsdf_scene_set_program(&fs, &s->prog);
    fovsdf_scene_init(&ds);
    rc.s = s; rc.root = root;
    ds.dist_d = ref_dist_d;
    ds.user = &rc;
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            double ro[3], rd[3], tr = 0.0;
            float rof[3], rdf[3];
            uint32_t kr = 0;
            fovsdf_hit hh;
            fov_result r1, r2;
            int hf, hr;
            pinhole_ray(cam, tgt, 50.0, w, h, i, j, ro, rd);
            for (k = 0; k < 3; ++k) { rof[k] = (float)ro[k]; rdf[k] = (float)rd[k]; }
            r1 = fovsdf_march(&fs, &mp, rof, rdf, 0.0f, &hh, NULL);
            r2 = fovsdf_trace_ref(&ds, ro, rd, 0.0, t_max, 1e-4, 1024, &tr, &kr);
            (*rays)++;
            if (r1 != FOV_OK || r2 != FOV_OK) { (*hm_bad)++; continue; }
            hf = hh.kind != FOVSDF_MISS;
            hr = kr != FOVSDF_MISS;
            if (hf != hr) { (*hm_bad)++; continue; }
            if (hh.kind == FOVSDF_HIT && kr == FOVSDF_HIT) {
                double rel = fabs((double)hh.t - tr) / tr;
                (*both)++;
                if (rel > 1e-3) (*depth_bad)++;
                if (rel > *worst_rel) *worst_rel = rel;
            }
        }
}

static void rand_point(Rng *g, const double c[3], double L, double p[3])
{
    p[0] = c[0] + urange(g, -L, L);
    p[1] = c[1] + urange(g, -L, L);
    p[2] = c[2] + urange(g, -L, L);
    fpoint(p);
}

/* Single-primitive programs (no bounds): the program must equal the exact value everywhere. */
static void s1_single(const char *name, Sc *s, int root, const double c[3], double L, int npts, uint64_t seed)
{
    char nm[160];
    Stat st;
    Rng g;
    int i;
    fov_result r = sc_build(s, root);
    snprintf(nm, sizeof nm, "s1_%s", name);
    if (r != FOV_OK) {
        check(0, nm, "build failed: %s (builder ok %d, err %d)", fovsdf_result_string(r), s->ok, (int)s->b.err);
        return;
    }
    g.s = seed;
    stat_init(&st);
    for (i = 0; i < npts; ++i) {
        double p[3], ref;
        PEval e;
        rand_point(&g, c, L, p);
        ref = ref_at(s, root, p, NULL, NULL);
        e = prog_eval(&s->prog, p, -1.0);
        stat_add(&st, p, ref, e.d);
        e = prog_eval(&s->prog, p, 0.0);
        stat_add(&st, p, ref, e.d);
    }
    stat_check(&st, nm);
    snprintf(nm, sizeof nm, "s1_%s_no_bounds", name);
    check(s->prog.bounds == 0 && s->prog.prims == 1, nm, "single primitive compiled with %u bounds, %u prims",
          s->prog.bounds, s->prog.prims);
}

/* Programs with several primitives. With bounds switched off (q.eps huge) the program equals
   the exact value everywhere; with bounds (q = NULL, or q.eps = 0.0125) it is <= exact + tol
   everywhere, and with q.eps = 0.0125 equal wherever exact < 0.05. Materials: the material of
   the operand that decides the value wherever that decision is not a near tie. */
static void s1_multi(const char *name, Sc *s, int root, const double c[3], double L, int npts, uint64_t seed,
                     int check_mat)
{
    char nm[160];
    Stat ex;
    Rng g;
    int i, above = 0, near_bad = 0, near_n = 0, near_diff_null = 0, mat_bad = 0, mat_n = 0, mat_near_bad = 0;
    int mat_near_n = 0, far_minus1 = 0;
    double worst_above = 0.0, wa_p[3] = { 0, 0, 0 }, wa_ref = 0, wa_prog = 0;
    int wm_ref = 0, wm_prog = 0;
    double wm_p[3] = { 0, 0, 0 };
    fov_result r = sc_build(s, root);
    snprintf(nm, sizeof nm, "s1_%s", name);
    if (r != FOV_OK) {
        check(0, nm, "build failed: %s (builder ok %d, err %d)", fovsdf_result_string(r), s->ok, (int)s->b.err);
        return;
    }
    g.s = seed;
    stat_init(&ex);
    for (i = 0; i < npts; ++i) {
        double p[3], ref, gap;
        int mref;
        PEval e0, e1, e2;
        if (i & 1) near_point(s, root, &g, c, L, p);
        else rand_point(&g, c, L, p);
        ref = ref_at(s, root, p, &mref, &gap);
        e0 = prog_eval(&s->prog, p, EPS_NO_BOUNDS);
        stat_add(&ex, p, ref, e0.d);
        e1 = prog_eval(&s->prog, p, -1.0);
        e2 = prog_eval(&s->prog, p, EPS_NEAR);
        if (e1.d > ref + tol_of(ref) || e2.d > ref + tol_of(ref)) {
            above++;
            if (dmax(e1.d, e2.d) - ref > worst_above) {
                worst_above = dmax(e1.d, e2.d) - ref;
                memcpy(wa_p, p, sizeof wa_p); wa_ref = ref; wa_prog = dmax(e1.d, e2.d);
            }
        }
        if (ref < NEAR_THR) {
            near_n++;
            if (fabs(e2.d - ref) > tol_of(ref)) near_bad++;
            if (fabs(e1.d - ref) > tol_of(ref)) near_diff_null++;
        }
        if (check_mat && gap > 1e-3) {
            mat_n++;
            if (e0.mat != mref) {
                if (mat_bad == 0) { wm_ref = mref; wm_prog = e0.mat; memcpy(wm_p, p, sizeof wm_p); }
                mat_bad++;
            }
            if (ref < NEAR_THR) {
                mat_near_n++;
                if (e2.mat != mref) mat_near_bad++;
            } else {
                g_far_n++;
                if (e2.mat != mref) far_minus1++;
                if (e2.mat != mref && e2.mat != -1) g_far_wrong++; /* -1 is documented far away */
            }
        }
    }
    snprintf(nm, sizeof nm, "s1_%s_exact_without_bounds", name);
    stat_check(&ex, nm);
    snprintf(nm, sizeof nm, "s1_%s_bounds_below_exact", name);
    check(above == 0, nm, "%d of %d points where the program exceeds exact + tol; worst +%.3g at (%.5g, %.5g, %.5g): program %.9g, exact %.9g",
          above, npts, worst_above, wa_p[0], wa_p[1], wa_p[2], wa_prog, wa_ref);
    snprintf(nm, sizeof nm, "s1_%s_bounds_exact_near_surface", name);
    check(near_n > 0 && near_bad == 0, nm, "%d of %d points with exact < %.2g where the program (q.eps %.4g) differs",
          near_bad, near_n, NEAR_THR, EPS_NEAR);
    if (near_diff_null) fovcheck_info("s1_%s: with q = NULL the program differs from exact at %d of %d points with exact < %.2g (bounds of small groups)",
                             name, near_diff_null, near_n, NEAR_THR);
    {   /* sphere tracing the program vs the exact function */
        int rays = 0, hm = 0, both = 0, dbad = 0;
        double worst = 0.0, cam[3];
        cam[0] = c[0] + 0.4 * L; cam[1] = c[1] + 0.7 * L; cam[2] = c[2] - 2.5 * L;
        trace_compare(s, root, cam, c, 32, 18, 8.0 * L, &rays, &hm, &both, &dbad, &worst);
        snprintf(nm, sizeof nm, "s1_%s_trace", name);
        check(rays > 0 && both > 0 && hm * 1000 <= rays && dbad == 0, nm,
              "%d of %d rays disagree on hit/miss, %d of %d common hits differ in depth by > 1e-3 relative (worst %.3g)", hm, rays,
              dbad, both, worst);
    }
    if (check_mat) {
        snprintf(nm, sizeof nm, "s1_%s_material", name);
        check(mat_n > 0 && mat_bad == 0, nm, "%d of %d points with the wrong material; first at (%.5g, %.5g, %.5g): program %d, expected %d",
              mat_bad, mat_n, wm_p[0], wm_p[1], wm_p[2], wm_prog, wm_ref);
        snprintf(nm, sizeof nm, "s1_%s_material_near_surface_with_bounds", name);
        check(mat_near_n > 0 && mat_near_bad == 0, nm, "%d of %d near-surface points with the wrong material", mat_near_bad, mat_near_n);

    }
}

static void section1(void)
{
    Sc *s = sc_new();
    double o[3] = { 0.0, 0.0, 0.0 };
    int x, y, z, w;
    const int N = 400;
    double ca[3], cc[3];

    /* primitives */
    sc_reset(s); x = sc_sphere(s, 0.7);                      s1_single("sphere", s, x, o, 1.5, N, 11);
    sc_reset(s); x = sc_box(s, 0.5, 0.3, 0.8);               s1_single("box", s, x, o, 1.5, N, 12);
    sc_reset(s); x = sc_round_box(s, 0.5, 0.3, 0.8, 0.12);   s1_single("round_box", s, x, o, 1.5, N, 13);
    sc_reset(s); x = sc_round_box(s, 0.4, 0.4, 0.4, 0.4);    s1_single("round_box_full_radius", s, x, o, 1.2, N, 14);
    sc_reset(s); x = sc_box_frame(s, 0.5, 0.4, 0.6, 0.05);   s1_single("box_frame", s, x, o, 1.0, N, 15);
    sc_reset(s); x = sc_torus(s, 0.6, 0.2);                  s1_single("torus", s, x, o, 1.2, N, 16);
    ca[0] = -0.3; ca[1] = 0.2; ca[2] = 0.1; cc[0] = 0.4; cc[1] = -0.5; cc[2] = 0.3;
    sc_reset(s); x = sc_capsule(s, ca, cc, 0.25);            s1_single("capsule", s, x, o, 1.2, N, 17);
    sc_reset(s); x = sc_capsule(s, ca, ca, 0.25);            s1_single("capsule_degenerate", s, x, o, 1.0, N, 18);
    sc_reset(s); x = sc_cylinder(s, 0.6, 0.3);               s1_single("cylinder", s, x, o, 1.2, N, 19);
    sc_reset(s); x = sc_cone(s, 0.5, 0.5, 0.15);             s1_single("cone", s, x, o, 1.2, N, 20);
    sc_reset(s); x = sc_cone(s, 0.7, 0.0, 0.4);              s1_single("cone_inverted_pointed", s, x, o, 1.2, N, 21);
    sc_reset(s); x = sc_cone(s, 0.3, 0.6, 0.0);              s1_single("cone_pointed", s, x, o, 1.2, N, 22);
    sc_reset(s); x = sc_cone(s, 0.4, 0.35, 0.35);            s1_single("cone_as_cylinder", s, x, o, 1.0, N, 23);
    sc_reset(s); x = sc_plane(s, 1.0, 2.0, -0.5, 0.3);       s1_single("plane", s, x, o, 3.0, N, 24);

    /* point operators and unary operators on single primitives (still no bounds) */
    sc_reset(s); x = sc_translate(s, sc_sphere(s, 0.4), 0.3, -1.2, 2.0);
    ca[0] = 0.3; ca[1] = -1.2; ca[2] = 2.0;                  s1_single("translate", s, x, ca, 1.0, N, 30);
    sc_reset(s); x = sc_rotate(s, sc_box(s, 0.8, 0.2, 0.1), 1.0, 1.0, 0.0, 30.0);
    s1_single("rotate", s, x, o, 1.0, N, 31);
    sc_reset(s); x = sc_rotate(s, sc_box(s, 0.8, 0.1, 0.1), 0.0, 0.0, 1.0, 90.0);
    s1_single("rotate_z90", s, x, o, 1.0, N, 32);
    {   /* the direction: +90 degrees about z takes the object's +x axis to world +y */
        float p1[3] = { 0.0f, 0.85f, 0.0f }, p2[3] = { 0.85f, 0.0f, 0.0f };
        float d1 = fovsdf_program_eval(p1, NULL, (void *)&s->prog), d2 = fovsdf_program_eval(p2, NULL, (void *)&s->prog);
        check(fabs((double)d1 - 0.05) < 1e-4 && fabs((double)d2 - 0.75) < 1e-4, "s1_rotate_object_to_world",
              "rotate(box 0.8x0.1x0.1, z, 90): d(0,0.85,0) = %.6g (want 0.05), d(0.85,0,0) = %.6g (want 0.75)",
              (double)d1, (double)d2);
    }
    sc_reset(s); x = sc_rotate(s, sc_torus(s, 0.5, 0.1), -0.3, 0.2, 0.9, -137.0);
    s1_single("rotate_torus", s, x, o, 1.0, N, 33);
    sc_reset(s); x = sc_scale(s, sc_box(s, 0.5, 0.3, 0.2), 1.7); s1_single("scale_up", s, x, o, 1.5, N, 34);
    sc_reset(s); x = sc_scale(s, sc_torus(s, 0.6, 0.2), 0.4);    s1_single("scale_down", s, x, o, 0.6, N, 35);
    sc_reset(s); x = sc_repeat(s, sc_translate(s, sc_sphere(s, 0.2), 0.1, 0.05, -0.1), 1.0, 0.0, 0.8, 2, 0, 1);
    s1_single("repeat_limited", s, x, o, 3.5, N, 36);
    sc_reset(s); x = sc_repeat(s, sc_box(s, 0.2, 0.3, 0.1), 0.0, 0.9, 0.0, 0, 3, 0);
    s1_single("repeat_limited_y", s, x, o, 4.0, N, 37);
    sc_reset(s); x = sc_repeat(s, sc_translate(s, sc_sphere(s, 0.25), 0.1, 0.0, 0.0), 1.2, 1.2, 0.0, 0, 0, 0);
    s1_single("repeat_infinite", s, x, o, 9.0, N, 38);
    sc_reset(s); x = sc_repeat(s, sc_torus(s, 0.3, 0.1), 0.9, 0.0, 1.1, 0, 0, 3);
    s1_single("repeat_mixed", s, x, o, 6.0, N, 39);
    sc_reset(s); x = sc_mirror(s, sc_translate(s, sc_box(s, 0.2, 0.3, 0.1), 0.5, 0.2, -0.4), 1 | 4);
    s1_single("mirror_xz", s, x, o, 1.5, N, 40);
    sc_reset(s); x = sc_mirror(s, sc_translate(s, sc_sphere(s, 0.3), 0.2, 0.6, 0.1), 2);
    s1_single("mirror_y", s, x, o, 1.5, N, 41);
    sc_reset(s); x = sc_round(s, sc_box(s, 0.4, 0.3, 0.2), 0.1); s1_single("round", s, x, o, 1.2, N, 42);
    sc_reset(s); x = sc_onion(s, sc_sphere(s, 0.6), 0.05);       s1_single("onion", s, x, o, 1.2, N, 43);
    sc_reset(s); x = sc_onion(s, sc_onion(s, sc_box(s, 0.5, 0.4, 0.3), 0.1), 0.02);
    s1_single("onion_twice", s, x, o, 1.2, N, 44);
    sc_reset(s);
    x = sc_translate(s, sc_rotate(s, sc_scale(s, sc_round(s, sc_onion(s, sc_cone(s, 0.4, 0.3, 0.1), 0.03), 0.02), 1.3),
                                  0.2, -1.0, 0.4, 71.0), 0.5, 0.25, -0.75);
    ca[0] = 0.5; ca[1] = 0.25; ca[2] = -0.75;                s1_single("nested_transforms", s, x, ca, 1.2, N, 45);

    /* binary operators (two primitives: bounds may be placed) */
#define S1_PAIR(nm_, type_, k_, seed_)                                                           \
    sc_reset(s);                                                                                \
    sc_mat(s, 3); x = sc_sphere(s, 0.5);                                                        \
    sc_mat(s, 7); y = sc_translate(s, sc_rotate(s, sc_box(s, 0.4, 0.25, 0.3), 0.3, 1.0, 0.2, 25.0), 0.45, 0.1, 0.05); \
    z = sc_bin(s, type_, x, y, k_);                                                            \
    s1_multi(nm_, s, z, o, 1.5, 600, seed_, 1)
    S1_PAIR("union", FOVSDF_NODE_UNION, 0.0, 50);
    S1_PAIR("subtract", FOVSDF_NODE_SUBTRACT, 0.0, 51);
    S1_PAIR("intersect", FOVSDF_NODE_INTERSECT, 0.0, 52);
    S1_PAIR("smooth_union", FOVSDF_NODE_SMOOTH_UNION, 0.3, 53);
    S1_PAIR("smooth_subtract", FOVSDF_NODE_SMOOTH_SUBTRACT, 0.2, 54);
    S1_PAIR("smooth_intersect", FOVSDF_NODE_SMOOTH_INTERSECT, 0.25, 55);
    S1_PAIR("smooth_union_wide", FOVSDF_NODE_SMOOTH_UNION, 1.5, 56);
#undef S1_PAIR

    /* operators around groups, groups inside transforms */
    sc_reset(s);
    sc_mat(s, 1); x = sc_translate(s, sc_sphere(s, 0.3), -0.6, 0.0, 0.0);
    sc_mat(s, 2); y = sc_translate(s, sc_box(s, 0.2, 0.2, 0.2), 0.6, 0.0, 0.0);
    sc_mat(s, 3); z = sc_translate(s, sc_torus(s, 0.3, 0.08), 0.0, 0.6, 0.0);
    sc_mat(s, 4); w = sc_translate(s, sc_cylinder(s, 0.3, 0.15), 0.0, -0.6, 0.3);
    x = sc_union(s, sc_union(s, x, y), sc_union(s, z, w));
    s1_multi("union4_materials", s, x, o, 2.0, 600, 60, 1);
    y = x;
    z = sc_scale(s, x, 2.5);
    s1_multi("union4_scaled_up", s, z, o, 5.0, 600, 67, 1);
    z = sc_round(s, x, 0.4);
    s1_multi("union4_round_large", s, z, o, 3.0, 600, 68, 1);
    x = y;
    x = sc_scale(s, sc_rotate(s, x, 1.0, 0.0, 1.0, 40.0), 0.7);
    s1_multi("union4_scaled_rotated", s, x, o, 1.5, 600, 61, 1);
    x = sc_onion(s, sc_round(s, x, 0.05), 0.03);
    s1_multi("union4_round_onion", s, x, o, 1.5, 600, 62, 1);
    x = sc_repeat(s, x, 2.5, 0.0, 2.5, 1, 0, 1);
    s1_multi("union4_repeat_limited", s, x, o, 4.5, 600, 63, 1);
    x = sc_mirror(s, sc_translate(s, x, 1.0, 0.5, 0.0), 1 | 2);
    s1_multi("union4_mirror", s, x, o, 6.0, 600, 64, 1);

    sc_reset(s); /* smooth union of groups, subtract a group, intersect with a group */
    sc_mat(s, 1); x = sc_union(s, sc_translate(s, sc_sphere(s, 0.3), -0.3, 0.0, 0.0), sc_translate(s, sc_sphere(s, 0.25), 0.3, 0.1, 0.0));
    sc_mat(s, 2); y = sc_union(s, sc_translate(s, sc_box(s, 0.2, 0.1, 0.2), 0.0, 0.35, 0.0), sc_translate(s, sc_capsule(s, ca, cc, 0.05), 0.0, -0.2, 0.0));
    z = sc_bin(s, FOVSDF_NODE_SMOOTH_UNION, x, y, 0.2);
    s1_multi("smooth_union_of_groups", s, z, o, 1.5, 600, 65, 1);
    sc_mat(s, 5); w = sc_box(s, 1.2, 0.8, 1.0);
    z = sc_bin(s, FOVSDF_NODE_INTERSECT, w, sc_bin(s, FOVSDF_NODE_SMOOTH_INTERSECT, z, sc_sphere(s, 0.9), 0.1), 0.0);
    s1_multi("intersect_of_groups", s, z, o, 1.5, 600, 66, 1);
    /* fovsdf_query.material is documented as the nearest surface's, or -1 far from every
       surface where a bounding sphere stood in for the nearest subtree: never a wrong id */
    check(g_far_n > 0 && g_far_wrong == 0, "s1_material_far_points_with_bounds",
          "material is neither the nearest surface's nor -1 at %d of %d points farther than %.2g from every surface",
          g_far_wrong, g_far_n, NEAR_THR);
    sc_free(s);
}


/* ==== section 2: bounding volumes on random scenes, malformed graphs ====================== */

/* A random primitive, every size in [0.05, 1]. */
static int rand_prim(Sc *s, Rng *g)
{
    int t = irange(g, 0, 7);
    double a = urange(g, 0.05, 1.0), b = urange(g, 0.05, 1.0), c = urange(g, 0.05, 1.0), m = dmin(a, dmin(b, c));
    double p0[3], p1[3];
    int k;
    sc_mat(s, irange(g, 0, 9));
    switch (t) {
    case 0: return sc_sphere(s, a);
    case 1: return sc_box(s, a, b, c);
    case 2: return sc_round_box(s, a, b, c, urange(g, 0.0, m));
    case 3: return sc_box_frame(s, a, b, c, dmax(0.01, urange(g, 0.05, 0.3) * m));
    case 4: return sc_torus(s, a, urange(g, 0.05, 0.05 + 0.5 * a));
    case 5:
        for (k = 0; k < 3; ++k) { p0[k] = urange(g, -a, a); p1[k] = urange(g, -a, a); }
        return sc_capsule(s, p0, p1, urange(g, 0.05, 0.5));
    case 6: return sc_cylinder(s, a, b);
    default: return sc_cone(s, a, b, urand(g) < 0.25 ? 0.0 : c);
    }
}

static int rand_place(Sc *s, Rng *g, int x)
{
    x = sc_rotate(s, x, urange(g, -1, 1), urange(g, -1, 1), urange(g, 0.1, 1), urange(g, 0.0, 360.0));
    return sc_translate(s, x, urange(g, -3.0, 3.0), urange(g, -0.5, 2.0), urange(g, -3.0, 3.0));
}

typedef struct RandScene {
    int root, prims, leaves, plane;
} RandScene;

/* 3..20 primitives: single primitives, subtractions, smooth unions and smooth subtractions,
   each placed at random; their union, with a ground plane half of the time. */
static RandScene rand_scene(Sc *s, Rng *g, int grouped)
{
    RandScene rs;
    int target = irange(g, 3, 20), root = -1, plane_at;
    memset(&rs, 0, sizeof rs);
    rs.plane = urand(g) < 0.5;
    plane_at = irange(g, 0, 1);
    if (rs.plane && plane_at == 0) { sc_mat(s, 1); root = sc_plane(s, urange(g, -0.1, 0.1), 1.0, urange(g, -0.1, 0.1), 1.0); }
    while (rs.prims < target) {
        double u = urand(g);
        int x;
        if (grouped && urand(g) < 0.5 && target - rs.prims >= 3) {
            /* a group of 2 or 3 primitives under a round, an onion or a smooth union */
            int k, np = irange(g, 2, 3), w = irange(g, 0, 2);
            x = -1;
            for (k = 0; k < np; ++k) {
                int y = sc_translate(s, rand_prim(s, g), urange(g, -0.6, 0.6), urange(g, -0.6, 0.6), urange(g, -0.6, 0.6));
                x = x < 0 ? y : sc_union(s, x, y);
            }
            if (w == 0) x = sc_round(s, x, urange(g, 0.02, 0.3));
            else if (w == 1) x = sc_onion(s, x, urange(g, 0.02, 0.2));
            else { x = sc_bin(s, FOVSDF_NODE_SMOOTH_UNION, x, rand_prim(s, g), urange(g, 0.1, 0.6)); np++; }
            rs.prims += np;
        } else if (u < 0.55 || target - rs.prims < 2) {
            x = rand_prim(s, g);
            rs.prims += 1;
        } else {
            int a = rand_prim(s, g), b;
            b = sc_translate(s, rand_prim(s, g), urange(g, -0.5, 0.5), urange(g, -0.5, 0.5), urange(g, -0.5, 0.5));
            if (u < 0.7) x = sc_bin(s, FOVSDF_NODE_SUBTRACT, a, b, 0.0);
            else if (u < 0.8) x = sc_bin(s, FOVSDF_NODE_SMOOTH_SUBTRACT, a, b, urange(g, 0.05, 0.3));
            else x = sc_bin(s, FOVSDF_NODE_SMOOTH_UNION, a, b, urange(g, 0.05, 0.3));
            rs.prims += 2;
        }
        x = rand_place(s, g, x);
        root = root < 0 ? x : sc_union(s, root, x);
        rs.leaves++;
    }
    if (rs.plane && plane_at == 1) { sc_mat(s, 1); root = sc_union(s, root, sc_plane(s, 0.0, 1.0, urange(g, -0.1, 0.1), 1.0)); }
    rs.root = root;
    return rs;
}

static double ref_dist_d(const double p[3], void *user)
{
    const RefCtx *rc = (const RefCtx *)user;
    return ref_at(rc->s, rc->root, p, NULL, NULL);
}

/* central-difference gradient of the reference */
static void ref_grad(const Sc *s, int root, const double p[3], double gr[3])
{
    int k;
    for (k = 0; k < 3; ++k) {
        double a[3], b[3], h = 1e-6;
        memcpy(a, p, sizeof a); memcpy(b, p, sizeof b);
        a[k] += h; b[k] -= h;
        gr[k] = (ref_at(s, root, a, NULL, NULL) - ref_at(s, root, b, NULL, NULL)) / (2.0 * h);
    }
}

/* a point within about 0.06 of the scene's surface */
static void near_surface_point(const Sc *s, int root, Rng *g, double p[3])
{
    int it, k;
    p[0] = urange(g, -4.0, 4.0); p[1] = urange(g, -1.2, 3.0); p[2] = urange(g, -4.0, 4.0);
    for (it = 0; it < 6; ++it) {
        double d = ref_at(s, root, p, NULL, NULL), gr[3], l;
        ref_grad(s, root, p, gr);
        l = len3d(gr[0], gr[1], gr[2]);
        if (!(l > 1e-9)) break;
        for (k = 0; k < 3; ++k) p[k] -= d * gr[k] / (l * l);
    }
    for (k = 0; k < 3; ++k) p[k] += urange(g, -0.06, 0.06);
    fpoint(p);
}

/* pinhole rays of a w x h image, in double, rounded to float (as fovsdf_march sees them) */
static void pinhole_ray(const double pos[3], const double target[3], double fov_deg, int w, int h, int i, int j,
                        double ro[3], double rd[3])
{
    double f[3], r[3], u[3], l, th = tan(0.5 * fov_deg * 3.14159265358979323846 / 180.0), su, sv;
    int k;
    for (k = 0; k < 3; ++k) f[k] = target[k] - pos[k];
    l = len3d(f[0], f[1], f[2]);
    for (k = 0; k < 3; ++k) f[k] /= l;
    r[0] = f[1] * 0.0 - f[2] * 1.0; r[1] = f[2] * 0.0 - f[0] * 0.0; r[2] = f[0] * 1.0 - f[1] * 0.0; /* f x (0,1,0) */
    l = len3d(r[0], r[1], r[2]);
    for (k = 0; k < 3; ++k) r[k] /= l;
    u[0] = r[1] * f[2] - r[2] * f[1]; u[1] = r[2] * f[0] - r[0] * f[2]; u[2] = r[0] * f[1] - r[1] * f[0];
    su = ((i + 0.5) / w * 2.0 - 1.0) * th * (double)w / (double)h;
    sv = (1.0 - (j + 0.5) / h * 2.0) * th;
    for (k = 0; k < 3; ++k) rd[k] = f[k] + su * r[k] + sv * u[k];
    l = len3d(rd[0], rd[1], rd[2]);
    for (k = 0; k < 3; ++k) { rd[k] = rf(rd[k] / l); ro[k] = rf(pos[k]); }
}

static fovsdf_march_params march_params(uint32_t method, uint32_t max_steps, double eps, double eps_cone, double t_max)
{
    fovsdf_march_params mp;
    memset(&mp, 0, sizeof mp);
    mp.method = method;
    mp.max_steps = max_steps;
    mp.eps = (float)eps;
    mp.eps_cone = (float)eps_cone;
    mp.t_max = (float)t_max;
    mp.omega = 1.6f;
    mp.ar_beta = 0.3f;
    mp.bv_relax = 0.9f;
    return mp;
}

static void march_f(const fovsdf_scene *sc, const fovsdf_march_params *mp, const double ro[3], const double rd[3],
                    double t0, fovsdf_hit *h, fov_result *res)
{
    float rof[3], rdf[3];
    int k;
    for (k = 0; k < 3; ++k) { rof[k] = (float)ro[k]; rdf[k] = (float)rd[k]; }
    *res = fovsdf_march(sc, mp, rof, rdf, (float)t0, h, NULL);
}

static void section2_random(const char *pre, int NSCENES, int grouped)
{
    enum { NPTS = 300, NFAR = 20, W = 64, H = 36 };
    char nm[128];
    Sc *s = sc_new();
    Rng g;
    int sc_i, build_bad = 0, count_bad = 0;
    long n_pts = 0, above = 0, exact_bad = 0, near_n = 0, near_bad = 0, near_null_diff = 0;
    long acc_n = 0, acc_bad = 0, far_n = 0, far_noskip = 0, mat_n = 0, mat_bad = 0;
    long rays = 0, hm_bad = 0, both_hit = 0, depth_bad = 0, trace_err = 0;
    int scenes_hm_over = 0, worst_hm_scene = -1, worst_hm = 0;
    double worst_above = 0.0, worst_exact = 0.0, worst_near = 0.0, worst_depth = 0.0;
    double wd_t = 0, wd_ref = 0;
    int wd_scene = -1;
    char detail[256] = "";
    const double cam_pos[3] = { 0.0, 2.5, -9.0 }, cam_tgt[3] = { 0.0, 0.3, 0.0 };
    g.s = grouped ? 0x2545F4914F6CDD1Dull : 0x9E3779B97F4A7C15ull;
    for (sc_i = 0; sc_i < NSCENES; ++sc_i) {
        RandScene rs;
        fov_result r;
        int i, j, hm = 0;
        fovsdf_scene fs, ds;
        RefCtx rc;
        fovsdf_march_params mp;
        sc_reset(s);
        rs = rand_scene(s, &g, grouped);
        r = sc_build(s, rs.root);
        if (r != FOV_OK) {
            if (build_bad++ == 0) snprintf(detail, sizeof detail, "scene %d: %s", sc_i, fovsdf_result_string(r));
            continue;
        }
        if ((int)s->prog.prims != ref_prims(s, rs.root)) count_bad++;
        /* (a), (b), (c), materials */
        for (i = 0; i < NPTS + NFAR; ++i) {
            double p[3], ref, gap;
            int mref;
            PEval e0, e1, e2;
            if (i < NPTS / 2) {
                p[0] = urange(&g, -4.5, 4.5); p[1] = urange(&g, -1.5, 3.5); p[2] = urange(&g, -4.5, 4.5);
                fpoint(p);
            } else if (i < NPTS) {
                near_surface_point(s, rs.root, &g, p);
            } else { /* far from every object (above the ground) */
                double th = urange(&g, 0.0, 6.283185307179586), rr = urange(&g, 30.0, 60.0);
                p[0] = rr * cos(th); p[1] = urange(&g, 0.0, 20.0); p[2] = rr * sin(th);
                fpoint(p);
            }
            ref = ref_at(s, rs.root, p, &mref, &gap);
            e0 = prog_eval(&s->prog, p, EPS_NO_BOUNDS);
            e1 = prog_eval(&s->prog, p, 0.0);
            e2 = prog_eval(&s->prog, p, EPS_NEAR);
            n_pts++;
            if (fabs(e0.d - ref) > tol_of(ref)) { exact_bad++; worst_exact = dmax(worst_exact, fabs(e0.d - ref)); }
            if (e1.d > ref + tol_of(ref) || e2.d > ref + tol_of(ref)) {
                above++;
                worst_above = dmax(worst_above, dmax(e1.d, e2.d) - ref);
            }
            if (ref < NEAR_THR) {
                near_n++;
                if (fabs(e2.d - ref) > tol_of(ref)) { near_bad++; worst_near = dmax(worst_near, fabs(e2.d - ref)); }
                if (fabs(e1.d - ref) > tol_of(ref)) near_null_diff++;
                if (gap > 1e-3) {
                    mat_n++;
                    if (e2.mat != mref) mat_bad++;
                }
            }
            acc_n += 3;
            if (e0.prims + e0.skipped != s->prog.prims) acc_bad++;
            if (e1.prims + e1.skipped != s->prog.prims) acc_bad++;
            if (e2.prims + e2.skipped != s->prog.prims) acc_bad++;
            if (i >= NPTS && rs.leaves >= 4) {
                far_n++;
                if (e1.skipped == 0) far_noskip++;
            }
        }
        /* (d) sphere tracing: the program (float, classic) vs the exact function (double) */
        fovsdf_scene_init(&fs);
        fovsdf_scene_set_program(&fs, &s->prog);
        fovsdf_scene_init(&ds);
        rc.s = s; rc.root = rs.root;
        ds.dist_d = ref_dist_d;
        ds.user = &rc;
        mp = march_params(FOVSDF_METHOD_CLASSIC, 1024, 1e-4, 0.0, 40.0);
        for (j = 0; j < H; ++j)
            for (i = 0; i < W; ++i) {
                double ro[3], rd[3], tr = 0.0;
                uint32_t kr = 0;
                fovsdf_hit h;
                fov_result r1, r2;
                int hf, hr;
                pinhole_ray(cam_pos, cam_tgt, 60.0, W, H, i, j, ro, rd);
                march_f(&fs, &mp, ro, rd, 0.0, &h, &r1);
                r2 = fovsdf_trace_ref(&ds, ro, rd, 0.0, 40.0, 1e-4, 1024, &tr, &kr);
                rays++;
                if (r1 != FOV_OK || r2 != FOV_OK) { trace_err++; continue; }
                hf = h.kind != FOVSDF_MISS;
                hr = kr != FOVSDF_MISS;
                if (hf != hr) { hm++; continue; }
                if (hf && hr && h.kind == FOVSDF_HIT && kr == FOVSDF_HIT) {
                    double rel = fabs((double)h.t - tr) / tr;
                    both_hit++;
                    if (rel > 1e-3) depth_bad++;
                    if (rel > worst_depth) { worst_depth = rel; wd_t = (double)h.t; wd_ref = tr; wd_scene = sc_i; }
                }
            }
        hm_bad += hm;
        if (hm * 1000 > W * H) scenes_hm_over++;
        if (hm > worst_hm) { worst_hm = hm; worst_hm_scene = sc_i; }
    }
    snprintf(nm, sizeof nm, "%s_scenes_build", pre);
    check(build_bad == 0, nm, "%d of %d scenes failed to build (first: %s)", build_bad, NSCENES, detail);
    snprintf(nm, sizeof nm, "%s_prims_count", pre);
    check(count_bad == 0, nm, "%d scenes where program.prims differs from the number of primitives", count_bad);
    snprintf(nm, sizeof nm, "%s_exact_without_bounds", pre);
    check(n_pts > 0 && exact_bad == 0, nm,
          "%ld of %ld points differ from exact with bounds disabled (worst %.3g)", exact_bad, n_pts, worst_exact);
    snprintf(nm, sizeof nm, "%s_bounds_below_exact", pre);
    check(n_pts > 0 && above == 0, nm, "%ld of %ld points where the program exceeds exact + tol (worst +%.3g)",
          above, n_pts, worst_above);
    snprintf(nm, sizeof nm, "%s_bounds_exact_near_surface", pre);
    check(near_n > 1000 && near_bad == 0, nm,
          "%ld of %ld points with exact < %.2g where the program (q.eps %.4g) differs (worst %.3g)", near_bad, near_n, NEAR_THR,
          EPS_NEAR, worst_near);
    fovcheck_info("%s: with q.eps = 0 the bounded program differs from exact at %ld of %ld points with exact < %.2g (%.2f%%)", pre,
         near_null_diff, near_n, NEAR_THR, near_n ? 100.0 * (double)near_null_diff / (double)near_n : 0.0);
    snprintf(nm, sizeof nm, "%s_prims_accounting", pre);
    check(acc_n > 0 && acc_bad == 0, nm, "%ld of %ld evaluations where prims + prims_skipped != program.prims",
          acc_bad, acc_n);
    snprintf(nm, sizeof nm, "%s_far_points_skip", pre);
    check(far_n > 0 && far_noskip == 0, nm, "%ld of %ld far points (scenes with >= 4 objects) skipped nothing",
          far_noskip, far_n);
    snprintf(nm, sizeof nm, "%s_material_near_surface", pre);
    check(mat_n > 1000 && mat_bad == 0, nm, "%ld of %ld near-surface points with the wrong material",
          mat_bad, mat_n);
    snprintf(nm, sizeof nm, "%s_trace_calls", pre);
    check(trace_err == 0, nm, "%ld rays where fovsdf_march or fovsdf_trace_ref returned an error", trace_err);
    snprintf(nm, sizeof nm, "%s_trace_hit_agreement", pre);
    check(rays > 0 && scenes_hm_over == 0, nm,
          "%d scenes with more than 0.1%% hit/miss disagreement; worst scene %d: %d of %d rays; total %ld of %ld",
          scenes_hm_over, worst_hm_scene, worst_hm, W * H, hm_bad, rays);
    fovcheck_info("%s: hit/miss disagreements %ld of %ld rays (%.4f%%)", pre, hm_bad, rays, rays ? 100.0 * (double)hm_bad / (double)rays : 0.0);
    snprintf(nm, sizeof nm, "%s_trace_depth", pre);
    check(both_hit > 0 && depth_bad == 0, nm,
          "%ld of %ld rays where both hit with |t - t_ref| / t_ref > 1e-3; worst %.3g (scene %d: t %.7g, t_ref %.7g)", depth_bad,
          both_hit, worst_depth, wd_scene, wd_t, wd_ref);
    fovcheck_info("%s: worst relative depth difference %.3g over %ld rays that both hit", pre, worst_depth, both_hit);
    sc_free(s);
}


static fovsdf_node raw_node(uint32_t type, int32_t a, int32_t b, float f0)
{
    fovsdf_node n;
    memset(&n, 0, sizeof n);
    n.type = type; n.a = a; n.b = b; n.f[0] = f0;
    return n;
}

/* build a raw node array; returns the result (memory sized by fovsdf_program_size, or 1 MiB
   when the size query itself fails) */
static fov_result raw_build(const fovsdf_node *nodes, uint32_t count, int32_t root, fovsdf_program *prog)
{
    size_t bytes = 0;
    void *mem;
    fov_result r = fovsdf_program_size(nodes, count, root, &bytes);
    if (r != FOV_OK) bytes = 1u << 20;
    mem = malloc(bytes);
    if (!mem) return FOV_ERR_TOO_SMALL;
    r = fovsdf_program_build(prog, nodes, count, root, mem, bytes);
    free(mem);
    return r;
}

/* compare a program against the reference at random points (bounds disabled and enabled) */
static int compare_random(Sc *s, int root, const double c[3], double L, int npts, uint64_t seed, double *worst)
{
    Rng g;
    int i, bad = 0;
    g.s = seed;
    *worst = 0.0;
    for (i = 0; i < npts; ++i) {
        double p[3], ref;
        PEval e0, e1;
        rand_point(&g, c, L, p);
        ref = ref_at(s, root, p, NULL, NULL);
        e0 = prog_eval(&s->prog, p, EPS_NO_BOUNDS);
        e1 = prog_eval(&s->prog, p, EPS_NEAR);
        if (!(fabs(e0.d - ref) <= tol_of(ref))) bad++;
        if (!(e1.d <= ref + tol_of(ref)) || (ref < NEAR_THR && !(fabs(e1.d - ref) <= tol_of(ref)))) bad++;
        *worst = dmax(*worst, fabs(e0.d - ref));
    }
    return bad;
}

static void section2_graphs(void)
{
    fovsdf_node nd[8];
    fovsdf_program prog;
    fov_result r;
    Sc *s = sc_new();
    int k, x, leaf[200];
    double o[3] = { 0, 0, 0 }, worst;
    clock_t t0;

    /* child index out of range (binary, unary, negative) */
    nd[0] = raw_node(FOVSDF_NODE_SPHERE, -1, -1, 1.0f);
    nd[1] = raw_node(FOVSDF_NODE_UNION, 0, 7, 0.0f);
    r = raw_build(nd, 2, 1, &prog);
    check(r != FOV_OK, "s2_graph_child_out_of_range", "union(0, 7) of 2 nodes built: %s", fovsdf_result_string(r));
    nd[1] = raw_node(FOVSDF_NODE_TRANSLATE, 2, -1, 0.0f);
    r = raw_build(nd, 2, 1, &prog);
    check(r != FOV_OK, "s2_graph_unary_child_out_of_range", "translate(2) of 2 nodes built: %s", fovsdf_result_string(r));
    nd[1] = raw_node(FOVSDF_NODE_SUBTRACT, 0, -5, 0.0f);
    r = raw_build(nd, 2, 1, &prog);
    check(r != FOV_OK, "s2_graph_child_negative", "subtract(0, -5) built: %s", fovsdf_result_string(r));
    nd[1] = raw_node(999u, 0, 0, 0.0f);
    r = raw_build(nd, 2, 0, &prog);
    check(r != FOV_OK, "s2_graph_bad_node_type", "a node of type 999 (unreachable) built: %s", fovsdf_result_string(r));
    nd[1] = raw_node(FOVSDF_NODE_UNION, 0, 0, 0.0f);
    r = raw_build(nd, 2, 2, &prog);
    check(r != FOV_OK, "s2_graph_root_out_of_range", "root 2 of 2 nodes built: %s", fovsdf_result_string(r));

    /* cycles: node 0 = union(1, 2), node 1 = translate(0); a self loop; a union-only cycle */
    nd[0] = raw_node(FOVSDF_NODE_UNION, 1, 2, 0.0f);
    nd[1] = raw_node(FOVSDF_NODE_TRANSLATE, 0, -1, 0.5f);
    nd[2] = raw_node(FOVSDF_NODE_SPHERE, -1, -1, 1.0f);
    t0 = clock();
    r = raw_build(nd, 3, 0, &prog);
    check(r != FOV_OK && (double)(clock() - t0) / CLOCKS_PER_SEC < 2.0, "s2_graph_cycle",
          "union(1,2) / translate(0) cycle: %s after %.2f s", fovsdf_result_string(r), (double)(clock() - t0) / CLOCKS_PER_SEC);
    r = raw_build(nd, 3, 1, &prog);
    check(r != FOV_OK, "s2_graph_cycle_other_root", "the same cycle from node 1: %s", fovsdf_result_string(r));
    nd[0] = raw_node(FOVSDF_NODE_TRANSLATE, 0, -1, 0.5f);
    r = raw_build(nd, 1, 0, &prog);
    check(r != FOV_OK, "s2_graph_self_loop", "translate(itself): %s", fovsdf_result_string(r));
    nd[0] = raw_node(FOVSDF_NODE_UNION, 1, 2, 0.0f);
    nd[1] = raw_node(FOVSDF_NODE_UNION, 0, 2, 0.0f);
    r = raw_build(nd, 3, 0, &prog);
    check(r != FOV_OK, "s2_graph_union_cycle", "union(1,2) / union(0,2): %s", fovsdf_result_string(r));
    nd[0] = raw_node(FOVSDF_NODE_SMOOTH_UNION, 2, 1, 0.1f);
    nd[1] = raw_node(FOVSDF_NODE_SCALE, 1, -1, 2.0f);
    r = raw_build(nd, 3, 0, &prog);
    check(r != FOV_OK, "s2_graph_unary_self_loop_below_root", "scale(itself) under a smooth union: %s", fovsdf_result_string(r));

    /* a chain of 200 unions, built the usual way (r = union(r, next): left-deep) */
    sc_reset(s);
    for (k = 0; k < 200; ++k) {
        sc_mat(s, k % 10);
        leaf[k] = sc_translate(s, sc_sphere(s, 0.05 + 0.002 * k), 0.37 * (k % 13) - 2.2, 0.29 * (k % 7) - 0.9, 0.23 * (k % 17) - 1.9);
    }
    x = leaf[0];
    for (k = 1; k < 200; ++k) x = sc_union(s, x, leaf[k]);
    r = sc_build(s, x);
    if (r == FOV_OK) {
        int bad = compare_random(s, x, o, 3.0, 2000, 70, &worst);
        check(bad == 0 && s->prog.prims == 200, "s2_graph_union_chain_200_left", "%d mismatches (worst %.3g), %u prims", bad, worst,
              s->prog.prims);
    } else {
        check(0, "s2_graph_union_chain_200_left", "fovsdf_program_build: %s (expected FOV_OK: union clusters are rebalanced)",
              fovsdf_result_string(r));
    }
    /* the same leaves, right-deep: union(leaf0, union(leaf1, ...)) */
    x = leaf[199];
    for (k = 198; k >= 0; --k) x = sc_union(s, leaf[k], x);
    r = sc_build(s, x);
    if (r == FOV_OK) {
        int bad = compare_random(s, x, o, 3.0, 2000, 71, &worst);
        check(bad == 0 && s->prog.prims == 200, "s2_graph_union_chain_200_right", "%d mismatches (worst %.3g), %u prims", bad, worst,
              s->prog.prims);
    } else {
        check(0, "s2_graph_union_chain_200_right", "fovsdf_program_build: %s (expected FOV_OK: union clusters are rebalanced)",
              fovsdf_result_string(r));
    }
    /* a balanced union tree of the 200 leaves (depth 8) */
    {
        int lv[200], n = 200;
        memcpy(lv, leaf, sizeof lv);
        while (n > 1) {
            int m = 0;
            for (k = 0; k + 1 < n; k += 2) lv[m++] = sc_union(s, lv[k], lv[k + 1]);
            if (n & 1) lv[m++] = lv[n - 1];
            n = m;
        }
        x = lv[0];
        r = sc_build(s, x);
        if (r == FOV_OK) {
            int bad = compare_random(s, x, o, 3.0, 2000, 72, &worst);
            check(bad == 0 && s->prog.prims == 200 && s->prog.bounds > 0, "s2_graph_union_tree_200_balanced",
                  "%d mismatches (worst %.3g), %u prims, %u bounds", bad, worst, s->prog.prims, s->prog.bounds);
        } else {
            check(0, "s2_graph_union_tree_200_balanced", "fovsdf_program_build: %s", fovsdf_result_string(r));
        }
    }

    /* 200 nested translates: FOV_ERR_LIMIT; 30 nested: fine */
    sc_reset(s);
    x = sc_sphere(s, 0.5);
    for (k = 0; k < 200; ++k) x = sc_translate(s, x, 0.01, 0.0, -0.005);
    r = sc_build(s, x);
    check(r == FOV_ERR_LIMIT, "s2_graph_translate_chain_200", "fovsdf_program_build: %s (expected FOV_ERR_LIMIT)",
          fovsdf_result_string(r));
    sc_reset(s);
    x = sc_sphere(s, 0.5);
    for (k = 0; k < 30; ++k) x = sc_translate(s, x, 0.01, 0.0, -0.005);
    r = sc_build(s, x);
    if (r == FOV_OK) {
        int bad = compare_random(s, x, o, 1.5, 500, 73, &worst);
        check(bad == 0, "s2_graph_translate_chain_30", "%d mismatches (worst %.3g)", bad, worst);
    } else {
        check(0, "s2_graph_translate_chain_30", "fovsdf_program_build: %s", fovsdf_result_string(r));
    }

    /* value stack: a right-deep chain of 40 smooth unions needs 41 stack slots (> 32) */
    sc_reset(s);
    for (k = 0; k < 41; ++k) leaf[k] = sc_translate(s, sc_sphere(s, 0.1), 0.15 * k - 3.0, 0.0, 0.0);
    x = leaf[40];
    for (k = 39; k >= 0; --k) x = sc_bin(s, FOVSDF_NODE_SMOOTH_UNION, leaf[k], x, 0.05);
    r = sc_build(s, x);
    if (r == FOV_OK) {
        int bad = compare_random(s, x, o, 3.5, 1000, 74, &worst);
        check(bad == 0, "s2_graph_value_stack_deep", "built (FOV_OK) but %d mismatches (worst %.3g)", bad, worst);
    } else {
        check(r == FOV_ERR_LIMIT, "s2_graph_value_stack_deep", "fovsdf_program_build: %s (expected FOV_ERR_LIMIT or a correct program)",
              fovsdf_result_string(r));
    }
    /* 30 deep: fits */
    x = leaf[29];
    for (k = 28; k >= 0; --k) x = sc_bin(s, FOVSDF_NODE_SMOOTH_UNION, leaf[k], x, 0.05);
    r = sc_build(s, x);
    if (r == FOV_OK) {
        int bad = compare_random(s, x, o, 3.5, 1000, 75, &worst);
        check(bad == 0, "s2_graph_value_stack_30", "%d mismatches (worst %.3g)", bad, worst);
    } else {
        check(0, "s2_graph_value_stack_30", "fovsdf_program_build: %s", fovsdf_result_string(r));
    }

    /* a DAG: one primitive used twice, and a shared group */
    sc_reset(s);
    sc_mat(s, 4);
    k = sc_box(s, 0.3, 0.2, 0.25);
    x = sc_union(s, sc_translate(s, k, -0.5, 0.0, 0.0), sc_rotate(s, sc_translate(s, k, 0.5, 0.1, 0.0), 0.0, 1.0, 0.0, 30.0));
    x = sc_union(s, sc_translate(s, x, 0.0, 0.6, 0.0), sc_scale(s, x, 0.5));
    r = sc_build(s, x);
    if (r == FOV_OK) {
        int bad = compare_random(s, x, o, 1.5, 1000, 76, &worst);
        check(bad == 0 && s->prog.prims == 4, "s2_graph_shared_nodes", "%d mismatches (worst %.3g), %u prims", bad, worst, s->prog.prims);
    } else {
        check(0, "s2_graph_shared_nodes", "fovsdf_program_build: %s", fovsdf_result_string(r));
    }
    /* an exponential DAG (2^40 paths): an error, quickly, not a hang */
    sc_reset(s);
    x = sc_sphere(s, 0.5);
    for (k = 0; k < 40; ++k) x = sc_bin(s, FOVSDF_NODE_SMOOTH_UNION, sc_translate(s, x, 0.01, 0.0, 0.0), x, 0.1);
    t0 = clock();
    r = sc_build(s, x);
    check(r != FOV_OK && (double)(clock() - t0) / CLOCKS_PER_SEC < 10.0, "s2_graph_exponential_dag",
          "fovsdf_program_build: %s after %.2f s", fovsdf_result_string(r), (double)(clock() - t0) / CLOCKS_PER_SEC);

    /* memory: too little -> FOV_ERR_TOO_SMALL; exactly the size at a misaligned address works */
    sc_reset(s);
    x = sc_union(s, sc_union(s, sc_translate(s, sc_sphere(s, 0.3), 1.0, 0.0, 0.0), sc_box(s, 0.2, 0.3, 0.4)),
                 sc_translate(s, sc_torus(s, 0.3, 0.1), -1.0, 0.0, 0.0));
    {
        size_t need = 0;
        unsigned char *mem;
        fov_result r1, r2, r3, r4;
        r = fovsdf_program_size(s->nodes, s->b.count, x, &need);
        mem = (unsigned char *)malloc(need + 1);
        r1 = fovsdf_program_build(&prog, s->nodes, s->b.count, x, mem, need - 1);
        r2 = fovsdf_program_build(&prog, s->nodes, s->b.count, x, mem, need / 2);
        r3 = fovsdf_program_build(&prog, s->nodes, s->b.count, x, mem, 0);
        check(r == FOV_OK && r1 == FOV_ERR_TOO_SMALL && r2 == FOV_ERR_TOO_SMALL && r3 == FOV_ERR_TOO_SMALL, "s2_graph_memory_too_small",
              "size %s (%lu bytes); build with need-1: %s, need/2: %s, 0: %s", fovsdf_result_string(r), (unsigned long)need,
              fovsdf_result_string(r1), fovsdf_result_string(r2), fovsdf_result_string(r3));
        r4 = fovsdf_program_build(&s->prog, s->nodes, s->b.count, x, mem + 1, need); /* ASan: no overrun */
        if (r4 == FOV_OK) {
            int bad = compare_random(s, x, o, 2.0, 500, 77, &worst);
            check(bad == 0, "s2_graph_memory_exact_misaligned", "%d mismatches (worst %.3g)", bad, worst);
        } else {
            check(0, "s2_graph_memory_exact_misaligned", "build into the exact size at an odd address: %s", fovsdf_result_string(r4));
        }
        free(mem);
    }

    /* a bounded group as the subtrahend: inside the solid the value stays negative and no
       larger in magnitude than exact (a conservative step from inside), equal near surfaces */
    sc_reset(s);
    x = sc_box(s, 1.5, 1.0, 1.0);
    k = sc_union(s, sc_translate(s, sc_sphere(s, 0.1), 1.3, 0.0, 0.0), sc_translate(s, sc_sphere(s, 0.1), 1.3, 0.25, 0.0));
    x = sc_bin(s, FOVSDF_NODE_SUBTRACT, x, k, 0.0);
    r = sc_build(s, x);
    if (r == FOV_OK) {
        Rng g;
        int i, bad = 0, larger = 0;
        g.s = 78;
        for (i = 0; i < 2000; ++i) {
            double p[3], ref;
            PEval e;
            rand_point(&g, o, 2.0, p);
            ref = ref_at(s, x, p, NULL, NULL);
            e = prog_eval(&s->prog, p, 0.0);
            if (fabs(ref) > 1e-4 && ((ref < 0.0) != (e.d < 0.0))) bad++;
            if (fabs(e.d) > fabs(ref) + tol_of(ref)) bad++;
            if (ref < NEAR_THR && ref > -NEAR_THR && fabs(prog_eval(&s->prog, p, EPS_NEAR).d - ref) > tol_of(ref)) bad++;
            if (e.d > ref + tol_of(ref)) larger++;
        }
        check(bad == 0, "s2_graph_bounded_subtrahend_conservative", "%d violations (sign, |value| > |exact|, or near-surface)", bad);
        fovcheck_info("s2: bounded subtrahend group: program > exact (less deep inside the solid, conservative) at %d of 2000 points", larger);
    } else {
        check(0, "s2_graph_bounded_subtrahend_conservative", "fovsdf_program_build: %s", fovsdf_result_string(r));
    }
    sc_free(s);
}


/* ==== section 3: the built-in scenes ====================================================== */

static void section3(void)
{
    uint32_t id;
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        fovsdf_builtin bi;
        size_t bytes = 0;
        unsigned char *mem;
        fov_result r1, r2, r3;
        char nm[128];
        const char *name = fovsdf_builtin_name(id);
        r1 = fovsdf_builtin_size(id, &bytes);
        mem = (unsigned char *)malloc(bytes + 1);
        r3 = fovsdf_builtin_init(id, &bi, mem + 1, bytes > 0 ? bytes - 1 : 0);
        r2 = fovsdf_builtin_init(id, &bi, mem + 1, bytes); /* an odd address: ASan checks the bounds */
        snprintf(nm, sizeof nm, "s3_%s_builds", name);
        check(r1 == FOV_OK && r2 == FOV_OK && r3 == FOV_ERR_TOO_SMALL && bi.program && bi.scene.dist_ex, nm,
              "size %s (%lu bytes), init %s, init with one byte less %s", fovsdf_result_string(r1), (unsigned long)bytes,
              fovsdf_result_string(r2), fovsdf_result_string(r3));
        if (r1 != FOV_OK || r2 != FOV_OK || !bi.program) { free(mem); continue; }
        {
            const fovsdf_program *pr = bi.program;
            float cp[3];
            double cd, ext, tgt[3], cam[3];
            int i, nonfinite = 0, above = 0, near_n = 0, near_bad = 0, acc_bad = 0, acc_n = 0;
            double worst_above = 0.0;
            fovsdf_ctx ctx;
            fovsdf_config cfg = fovsdf_config_default();
            fov_gaze gz;
            fov_result ri;
            Rng g;
            fovsdf_march_params mp;
            /* fractals are distance estimators, not exact: a bound may exceed them */
            int exact_scene = id != FOVSDF_SCENE_FRACTALS;
            snprintf(nm, sizeof nm, "s3_%s_has_bounds", name);
            check(pr->bounds > 0 && pr->prims >= 3, nm, "%u bounds, %u primitives", pr->bounds, pr->prims);
            cp[0] = bi.camera.pos[0]; cp[1] = bi.camera.pos[1]; cp[2] = bi.camera.pos[2];
            cd = (double)fovsdf_program_eval(cp, NULL, (void *)(uintptr_t)pr);
            gz.x = 0.5f * (float)bi.camera.width; gz.y = 0.5f * (float)bi.camera.height;
            ri = fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gz, NULL, 0);
            snprintf(nm, sizeof nm, "s3_%s_camera_outside", name);
            check(cd > 0.0 && finite_d(cd) && ri == FOV_OK && ctx.cam_dist > 0.0f, nm,
                  "distance at the camera %.6g, fovsdf_init %s, ctx.cam_dist %.6g", cd, fovsdf_result_string(ri),
                  ri == FOV_OK ? (double)ctx.cam_dist : 0.0);
            /* 200 random points in a box around the view */
            for (i = 0; i < 3; ++i) { tgt[i] = (double)bi.camera.target[i]; cam[i] = (double)bi.camera.pos[i]; }
            ext = 1.5 * len3d(cam[0] - tgt[0], cam[1] - tgt[1], cam[2] - tgt[2]);
            g.s = 100 + id;
            for (i = 0; i < 200; ++i) {
                double p[3];
                rand_point(&g, tgt, ext, p);
                if (!finite_d(prog_eval(pr, p, -1.0).d) || !finite_d(prog_eval(pr, p, 0.0).d)) nonfinite++;
            }
            snprintf(nm, sizeof nm, "s3_%s_values_finite", name);
            check(nonfinite == 0, nm, "%d of 200 random points with a NaN or infinite distance", nonfinite);
            /* bounds vs no bounds at points near the surfaces seen by the camera and at random
               points: with bounds never larger (exact scenes), equal near surfaces, and
               prims + prims_skipped = the primitive instructions of the program */
            mp = march_params(FOVSDF_METHOD_CLASSIC, 1024, 1e-4, 0.0, (double)bi.scene.t_max);
            for (i = 0; i < 600; ++i) {
                double p[3], un;
                PEval e1, e2;
                if (i < 300) {
                    float ro[3], rd[3];
                    fovsdf_hit h;
                    (void)fovsdf_camera_ray(&ctx, (float)urange(&g, 0.0, (double)bi.camera.width),
                                            (float)urange(&g, 0.0, (double)bi.camera.height), ro, rd);
                    if (fovsdf_march(&bi.scene, &mp, ro, rd, 0.0f, &h, NULL) != FOV_OK || h.kind == FOVSDF_MISS) continue;
                    un = (double)h.t + urange(&g, -0.06, 0.06);
                    p[0] = (double)ro[0] + (double)rd[0] * un; p[1] = (double)ro[1] + (double)rd[1] * un;
                    p[2] = (double)ro[2] + (double)rd[2] * un;
                    fpoint(p);
                } else {
                    rand_point(&g, tgt, ext, p);
                }
                un = prog_eval(pr, p, EPS_NO_BOUNDS).d;
                e1 = prog_eval(pr, p, 0.0);
                e2 = prog_eval(pr, p, EPS_NEAR);
                if (exact_scene && (e1.d > un + tol_of(un) || e2.d > un + tol_of(un))) {
                    above++;
                    worst_above = dmax(worst_above, dmax(e1.d, e2.d) - un);
                }
                if (un < NEAR_THR) {
                    near_n++;
                    if (fabs(e2.d - un) > tol_of(un)) near_bad++;
                }
                acc_n += 2;
                if (e1.prims + e1.skipped != pr->prims) acc_bad++;
                if (e2.prims + e2.skipped != pr->prims) acc_bad++;
            }
            if (exact_scene) {
                snprintf(nm, sizeof nm, "s3_%s_bounds_below_unbounded", name);
                check(above == 0, nm, "%d of 600 points where the bounded value exceeds the unbounded one (worst +%.3g)", above, worst_above);
            }
            snprintf(nm, sizeof nm, "s3_%s_bounds_exact_near_surface", name);
            check(near_n > 50 && near_bad == 0, nm, "%d of %d near-surface points where bounds change the value", near_bad, near_n);
            snprintf(nm, sizeof nm, "s3_%s_prims_accounting", name);
            check(acc_bad == 0, nm,
                  "%d of %d evaluations where prims + prims_skipped != program.prims (%u); prims_skipped is documented as "
                  "primitive evaluations skipped",
                  acc_bad, acc_n, pr->prims);
        }
        free(mem);
    }
}


/* ==== section 4: numerical stability ====================================================== */

#define FE ((double)FLT_EPSILON)

/* the documented hit threshold of fovsdf_march with eps_cone = 0 */
static double thr_doc(double eps, double cam_len, double t) { return dmax(eps, 8.0 * FE * (cam_len + t)); }

typedef struct RefRay {
    double ro[3], rd[3];
    double t;        /* fovsdf_trace_ref */
    uint32_t kind;
    double cos_inc;  /* |cos| of the angle between the ray and the normal at the reference hit */
    double min_ratio;/* min over the reference march of d / documented threshold */
} RefRay;

/* classic double march tracking the smallest d / threshold (how close a ray comes) */
static double ref_min_ratio(const Sc *s, int root, const double ro[3], const double rd[3], double t_max, double eps_ref,
                            double eps, double cone)
{
    double t = 0.0, mr = 1e300, cl = len3d(ro[0], ro[1], ro[2]);
    int i;
    for (i = 0; i < 200000 && t <= t_max; ++i) {
        double p[3], d;
        p[0] = ro[0] + rd[0] * t; p[1] = ro[1] + rd[1] * t; p[2] = ro[2] + rd[2] * t;
        d = ref_at(s, root, p, NULL, NULL);
        mr = dmin(mr, d / dmax(thr_doc(eps, cl, t), cone * t));
        if (d < eps_ref) break;
        t += d;
    }
    return mr;
}

static void ref_ray(const Sc *s, int root, const double ro[3], const double rd[3], double t_max, double eps_ref, double eps,
                    double cone, double scale, RefRay *rr)
{
    fovsdf_scene ds;
    RefCtx rc;
    fov_result r;
    memset(rr, 0, sizeof *rr);
    memcpy(rr->ro, ro, sizeof rr->ro);
    memcpy(rr->rd, rd, sizeof rr->rd);
    fovsdf_scene_init(&ds);
    rc.s = s; rc.root = root;
    ds.dist_d = ref_dist_d;
    ds.user = &rc;
    r = fovsdf_trace_ref(&ds, ro, rd, 0.0, t_max, eps_ref, 200000, &rr->t, &rr->kind);
    if (r != FOV_OK) { rr->kind = 99; return; }
    if (rr->kind == FOVSDF_HIT) {
        double p[3], gr[3], l, h = 1e-5 * scale;
        int k;
        for (k = 0; k < 3; ++k) p[k] = ro[k] + rd[k] * rr->t;
        for (k = 0; k < 3; ++k) {
            double a[3], b[3];
            memcpy(a, p, sizeof a); memcpy(b, p, sizeof b);
            a[k] += h; b[k] -= h;
            gr[k] = ref_at(s, root, a, NULL, NULL) - ref_at(s, root, b, NULL, NULL);
        }
        l = len3d(gr[0], gr[1], gr[2]);
        rr->cos_inc = l > 0.0 ? fabs(dot3d(gr, rd)) / l : 0.0;
        rr->min_ratio = 0.0;
    } else {
        rr->min_ratio = ref_min_ratio(s, root, ro, rd, t_max, eps_ref, eps, cone);
    }
}

/* accumulated comparison of one tracer against the reference */
typedef struct NAcc {
    int rays, bad_call, nonfinite, clear_hit, clear_hit_missed, clear_miss, clear_miss_hit, depth_n, depth_bad, exhausted;
    int clear_hit_exhausted; /* clear hits that ran out of steps (the threshold floor should prevent stalls) */
    double worst_rel, worst_ratio, worst_abs, wr_t, wr_tref, wr_env, wr_cos;
    int surf_bad;         /* hit points farther from the surface than the documented threshold */
    double worst_surf;    /* worst (exact distance at the hit point) / threshold */
} NAcc;

static void nacc_init(NAcc *a) { memset(a, 0, sizeof *a); }

/* trace rr with the program scene and method; compare with the reference */
static void nacc_ray(NAcc *a, const fovsdf_scene *fs, const Sc *s, int root, uint32_t method, const RefRay *rr, double eps,
                     double t_max, uint32_t max_steps)
{
    fovsdf_march_params mp = march_params(method, max_steps, eps, 0.0, t_max);
    fovsdf_hit h;
    fov_result r;
    double cl = len3d(rr->ro[0], rr->ro[1], rr->ro[2]);
    a->rays++;
    march_f(fs, &mp, rr->ro, rr->rd, 0.0, &h, &r);
    if (r != FOV_OK || h.kind > FOVSDF_EXHAUSTED || h.steps > max_steps) { a->bad_call++; return; }
    if (!finite_d((double)h.t) || !finite_d((double)h.dist)) { a->nonfinite++; return; }
    if (h.kind == FOVSDF_EXHAUSTED) a->exhausted++;
    if (rr->kind == FOVSDF_HIT && rr->cos_inc >= 0.3) {
        double rel, env;
        a->clear_hit++;
        if (h.kind == FOVSDF_MISS) { a->clear_hit_missed++; return; }
        if (h.kind == FOVSDF_EXHAUSTED) a->clear_hit_exhausted++;
        {   /* the exact distance at the reported hit point: within the documented threshold
               (plus the float rounding of the point, a few ulps of |p|) */
            double p[3], de, thr;
            int k;
            for (k = 0; k < 3; ++k) p[k] = rr->ro[k] + rr->rd[k] * (double)h.t;
            de = ref_at(s, root, p, NULL, NULL);
            thr = thr_doc(eps, cl, (double)h.t);
            if (fabs(de) / thr > a->worst_surf) a->worst_surf = fabs(de) / thr;
            if (!(de < thr + 4.0 * FE * len3d(p[0], p[1], p[2]) && de > -thr)) a->surf_bad++;
        }
        rel = fabs((double)h.t - rr->t) / rr->t;
        /* the header's NUMERICS: along the ray a hit is at most thr(t) / |cos(incidence)| off
           (plus the rounding of the point, a few ulps of |camera| + t) */
        env = (thr_doc(eps, cl, rr->t) + 4.0 * FE * (cl + rr->t)) / (fabs(rr->cos_inc) * rr->t);
        a->depth_n++;
        if (rel > env) a->depth_bad++;
        if (rel > a->worst_rel) a->worst_rel = rel;
        if (fabs((double)h.t - rr->t) > a->worst_abs) a->worst_abs = fabs((double)h.t - rr->t);
        if (rel / env > a->worst_ratio) {
            a->worst_ratio = rel / env; a->wr_t = (double)h.t; a->wr_tref = rr->t; a->wr_env = env; a->wr_cos = rr->cos_inc;
        }
    } else if (rr->kind == FOVSDF_HIT) {
        if (h.kind == FOVSDF_MISS) a->clear_hit_missed++; /* a real intersection is never skipped */
    } else if (rr->kind == FOVSDF_MISS && rr->min_ratio > 4.0) {
        a->clear_miss++;
        if (h.kind != FOVSDF_MISS) a->clear_miss_hit++;
    }
}

static void nacc_merge(NAcc *a, const NAcc *b)
{
    a->rays += b->rays; a->bad_call += b->bad_call; a->nonfinite += b->nonfinite; a->clear_hit += b->clear_hit;
    a->clear_hit_missed += b->clear_hit_missed; a->clear_miss += b->clear_miss; a->clear_miss_hit += b->clear_miss_hit;
    a->depth_n += b->depth_n; a->depth_bad += b->depth_bad; a->exhausted += b->exhausted; a->surf_bad += b->surf_bad;
    a->clear_hit_exhausted += b->clear_hit_exhausted;
    if (b->worst_surf > a->worst_surf) a->worst_surf = b->worst_surf;
    if (b->worst_rel > a->worst_rel) a->worst_rel = b->worst_rel;
    if (b->worst_abs > a->worst_abs) a->worst_abs = b->worst_abs;
    if (b->worst_ratio > a->worst_ratio) {
        a->worst_ratio = b->worst_ratio; a->wr_t = b->wr_t; a->wr_tref = b->wr_tref; a->wr_env = b->wr_env; a->wr_cos = b->wr_cos;
    }
}

/* one set of checks per setup, over the four tracers; a line of figures per tracer */
static void nacc_report(const NAcc acc[4], const char *setup)
{
    char nm[160];
    NAcc all;
    uint32_t m;
    nacc_init(&all);
    for (m = 0; m < 4; ++m) {
        const NAcc *a = &acc[m];
        nacc_merge(&all, a);
        fovcheck_info("s4_%s %s: worst relative depth error %.3g (abs %.3g) = %.3g x envelope (at |cos| %.2f); hit point at most %.3g "
             "thresholds from the surface; %d clear hits, %d clear misses, %d exhausted",
             setup, fovsdf_method_name(m), a->worst_rel, a->worst_abs, a->worst_ratio, a->wr_cos, a->worst_surf, a->clear_hit,
             a->clear_miss, a->exhausted);
    }
    snprintf(nm, sizeof nm, "s4_%s_hit_miss", setup);
    check(all.rays > 0 && all.bad_call == 0 && all.nonfinite == 0 && all.clear_hit > 0 && all.clear_hit_missed == 0 &&
              all.clear_miss_hit == 0 && all.clear_hit_exhausted == 0, nm,
          "%d rays (4 tracers): %d bad calls, %d non-finite, reference hits missed %d (clear hits %d, of them %d exhausted "
          "the 1024 steps), clear misses hit %d of %d",
          all.rays, all.bad_call, all.nonfinite, all.clear_hit_missed, all.clear_hit, all.clear_hit_exhausted, all.clear_miss_hit,
          all.clear_miss);
    snprintf(nm, sizeof nm, "s4_%s_hit_point_within_threshold", setup);
    check(all.depth_n > 0 && all.surf_bad == 0, nm,
          "%d of %d hit points farther from the surface than the documented threshold max(eps, 8 FLT_EPSILON (|camera| + t)); "
          "worst %.3g thresholds", all.surf_bad, all.depth_n, all.worst_surf);
    snprintf(nm, sizeof nm, "s4_%s_depth_envelope", setup);
    check(all.depth_n > 0 && all.depth_bad == 0, nm,
          "%d of %d hits (4 tracers, incidence |cos| >= 0.3) with a relative depth error above the documented envelope "
          "(thr(t) + 4 FLT_EPSILON (|camera| + t)) / (|cos| t); worst %.3g x envelope (t %.9g, t_ref %.9g, envelope %.3g, |cos| %.2f)",
          all.depth_bad, all.depth_n, all.worst_ratio, all.wr_t, all.wr_tref, all.wr_env, all.wr_cos);
}

/* A numerical setup: the program under root, a camera, a fan of rays. */
typedef struct NSetup {
    const char *name;
    Sc *s;
    int root;
    double cam[3], fwd[3], spread, eps, t_max, scale;
    int grid;
} NSetup;

static void basis(const double fwd[3], double r[3], double u[3])
{
    double l;
    r[0] = -fwd[2]; r[1] = 0.0; r[2] = fwd[0]; /* fwd x (0,1,0) */
    l = len3d(r[0], r[1], r[2]);
    r[0] /= l; r[1] /= l; r[2] /= l;
    u[0] = r[1] * fwd[2] - r[2] * fwd[1]; u[1] = r[2] * fwd[0] - r[0] * fwd[2]; u[2] = r[0] * fwd[1] - r[1] * fwd[0];
}

static RefRay *nsetup_refs(const NSetup *su, int *count)
{
    int n = su->grid * su->grid, i, j, k;
    RefRay *rr = (RefRay *)calloc((size_t)n, sizeof(RefRay));
    double r[3], u[3], ro[3];
    if (!rr) { printf("out of memory\n"); exit(2); }
    basis(su->fwd, r, u);
    for (k = 0; k < 3; ++k) ro[k] = rf(su->cam[k]);
    for (j = 0; j < su->grid; ++j)
        for (i = 0; i < su->grid; ++i) {
            double a = (2.0 * i / (su->grid - 1) - 1.0) * su->spread, b = (2.0 * j / (su->grid - 1) - 1.0) * su->spread, rd[3], l;
            for (k = 0; k < 3; ++k) rd[k] = su->fwd[k] + a * r[k] + b * u[k];
            l = len3d(rd[0], rd[1], rd[2]);
            for (k = 0; k < 3; ++k) rd[k] = rf(rd[k] / l);
            ref_ray(su->s, su->root, ro, rd, su->t_max, 1e-9 * su->scale + 1e-13 * len3d(ro[0], ro[1], ro[2]), su->eps, 0.0,
                    su->scale, &rr[j * su->grid + i]);
        }
    *count = n;
    return rr;
}

static void nsetup_run(const NSetup *su, NAcc acc[4])
{
    int n = 0, i, bad_ref = 0;
    uint32_t m;
    fovsdf_scene fs;
    RefRay *rr;
    if (sc_build(su->s, su->root) != FOV_OK) {
        check(0, su->name, "program build failed");
        return;
    }
    fovsdf_scene_init(&fs);
    fovsdf_scene_set_program(&fs, &su->s->prog);
    rr = nsetup_refs(su, &n);
    for (i = 0; i < n; ++i) if (rr[i].kind == 99) bad_ref++;
    if (bad_ref) check(0, su->name, "fovsdf_trace_ref failed on %d rays", bad_ref);
    for (m = 0; m <= (uint32_t)FOVSDF_METHOD_BV2018; ++m) { /* the four ray tracers */
        NAcc a;
        nacc_init(&a);
        for (i = 0; i < n; ++i) nacc_ray(&a, &fs, su->s, su->root, m, &rr[i], su->eps, su->t_max, 1024);
        nacc_merge(&acc[m], &a);
    }
    free(rr);
}

static void unit(double v[3])
{
    double l = len3d(v[0], v[1], v[2]);
    v[0] /= l; v[1] /= l; v[2] /= l;
}

/* exact ray-sphere intersection (double) */
static double ray_sphere(const double ro[3], const double rd[3], const double c[3], double r)
{
    double oc[3], b, cc, disc, dd = dot3d(rd, rd);
    oc[0] = ro[0] - c[0]; oc[1] = ro[1] - c[1]; oc[2] = ro[2] - c[2];
    b = dot3d(oc, rd) / dd;
    cc = (dot3d(oc, oc) - r * r) / dd;
    disc = b * b - cc;
    if (disc < 0.0) return -1.0;
    return -b - sqrt(disc);
}

static void section4_far(void)
{
    Sc *s = sc_new();
    const double dists[2] = { 1e4, 1e5 };
    int di;
    uint32_t m;
    for (di = 0; di < 2; ++di) {
        NSetup su;
        NAcc acc[4];
        double dir[3] = { 1.0, 0.7, -0.5 }, c[3];
        char nm[64];
        int k;
        /* a unit sphere 5 units in front of a camera far from the origin */
        unit(dir);
        memset(&su, 0, sizeof su);
        for (k = 0; k < 3; ++k) su.cam[k] = rf(dists[di] * dir[k]);
        su.fwd[0] = 0.3; su.fwd[1] = -0.2; su.fwd[2] = 1.0;
        unit(su.fwd);
        for (k = 0; k < 3; ++k) c[k] = su.cam[k] + 5.0 * su.fwd[k];
        sc_reset(s);
        su.root = sc_translate(s, sc_sphere(s, 1.0), c[0], c[1], c[2]);
        su.s = s; su.spread = 0.28; su.eps = 1e-4; su.t_max = 20.0; su.scale = 1.0; su.grid = 21;
        snprintf(nm, sizeof nm, "far%.0e_unit_sphere", dists[di]);
        su.name = nm;
        for (m = 0; m < 4; ++m) nacc_init(&acc[m]);
        nsetup_run(&su, acc);
        nacc_report(acc, nm);
        if (di == 1) { /* the reference tracer itself against the closed form */
            int n = 0, i, bad = 0;
            double worst = 0.0, cf[3];
            RefRay *rr = nsetup_refs(&su, &n);
            for (k = 0; k < 3; ++k) cf[k] = s->r[su.root].f[k];
            for (i = 0; i < n; ++i) {
                double ta = ray_sphere(rr[i].ro, rr[i].rd, cf, 1.0);
                if (rr[i].kind == FOVSDF_HIT && rr[i].cos_inc >= 0.3) {
                    double e = fabs(rr[i].t - ta) / ta;
                    worst = dmax(worst, e);
                    if (!(e < 1e-8)) bad++;
                }
            }
            free(rr);
            check(bad == 0, "s4_reference_tracer_vs_closed_form", "%d rays where fovsdf_trace_ref is off the ray-sphere intersection by > 1e-8 relative (worst %.3g)", bad, worst);
        }
        /* a big sphere at the origin seen from the same distance */
        memset(&su, 0, sizeof su);
        for (k = 0; k < 3; ++k) { su.cam[k] = rf(dists[di] * dir[k]); su.fwd[k] = -dir[k]; }
        sc_reset(s);
        su.root = sc_sphere(s, 1000.0);
        su.s = s; su.spread = 1.2 * 1000.0 / dists[di]; su.eps = 1e-4; su.t_max = 2.0 * dists[di]; su.scale = 1000.0; su.grid = 21;
        snprintf(nm, sizeof nm, "far%.0e_big_sphere", dists[di]);
        su.name = nm;
        for (m = 0; m < 4; ++m) nacc_init(&acc[m]);
        nsetup_run(&su, acc);
        nacc_report(acc, nm);
        /* a camera near the origin, a sphere of radius D/100 at distance D (the hit point, not
           the camera, is far from the origin) */
        memset(&su, 0, sizeof su);
        su.cam[0] = 1.0; su.cam[1] = 2.0; su.cam[2] = -3.0;
        for (k = 0; k < 3; ++k) { su.fwd[k] = dir[k]; c[k] = su.cam[k] + dists[di] * dir[k]; }
        sc_reset(s);
        su.root = sc_translate(s, sc_sphere(s, dists[di] / 100.0), c[0], c[1], c[2]);
        su.s = s; su.spread = 0.012; su.eps = 1e-4; su.t_max = 2.0 * dists[di]; su.scale = dists[di] / 100.0; su.grid = 21;
        snprintf(nm, sizeof nm, "origin_camera_far%.0e_sphere", dists[di]);
        su.name = nm;
        for (m = 0; m < 4; ++m) nacc_init(&acc[m]);
        nsetup_run(&su, acc);
        nacc_report(acc, nm);
    }
    sc_free(s);
}

static void section4_scaled(void)
{
    Sc *s = sc_new();
    static const double sizes[8] = { 1e-4, 1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1000.0 };
    int obj, si;
    uint32_t m;
    for (obj = 0; obj < 2; ++obj) {
        NAcc acc[4];
        const char *nm = obj == 0 ? "scaled_sphere" : "scaled_box";
        for (m = 0; m < 4; ++m) nacc_init(&acc[m]);
        for (si = 0; si < 8; ++si) {
            NSetup su;
            NAcc one[4];
            double r = sizes[si], dir[3] = { 0.3, 0.4, -1.0 };
            int k;
            unit(dir);
            memset(&su, 0, sizeof su);
            sc_reset(s);
            su.root = obj == 0 ? sc_sphere(s, r) : sc_rotate(s, sc_box(s, r, 0.6 * r, 0.8 * r), 1.0, 1.0, 1.0, 30.0);
            for (k = 0; k < 3; ++k) { su.cam[k] = rf(5.0 * r * dir[k]); su.fwd[k] = -dir[k]; }
            su.s = s; su.spread = 0.3; su.eps = 1e-4 * r; su.t_max = 20.0 * r; su.scale = r; su.grid = 21;
            su.name = nm;
            for (m = 0; m < 4; ++m) nacc_init(&one[m]);
            nsetup_run(&su, one);
            for (m = 0; m < 4; ++m) nacc_merge(&acc[m], &one[m]);
            fovcheck_info("s4_%s r=%g: worst relative depth error (classic, relaxed, autorelaxed, bv2018) %.3g %.3g %.3g %.3g", nm, r,
                 one[0].worst_rel, one[1].worst_rel, one[2].worst_rel, one[3].worst_rel);
        }
        nacc_report(acc, nm);
    }
    sc_free(s);
}


/* Rays grazing the plane y = 0 at 1e-2 .. 1e-6 rad: every tracer terminates (HIT, MISS or
   EXHAUSTED, within max_steps) with a finite t, never passes through the plane, and a HIT is
   within the documented threshold of the plane. */
static void section4_grazing(void)
{
    Sc *s = sc_new();
    static const double angles[5] = { 1e-2, 1e-3, 1e-4, 1e-5, 1e-6 };
    static const double origins[2][3] = { { 0.0, 1.0, 0.0 }, { 1e4, 1.0, -1e4 } };
    fovsdf_scene fs;
    int ai, oi, cone, bad = 0, tunnel = 0, hit_far = 0, n = 0;
    uint32_t m;
    double worst_hit = 0.0;
    clock_t t0 = clock();
    char first[256] = "";
    int root = sc_plane(s, 0.0, 1.0, 0.0, 0.0);
    if (sc_build(s, root) != FOV_OK) { check(0, "s4_grazing_build", "program build failed"); sc_free(s); return; }
    fovsdf_scene_init(&fs);
    fovsdf_scene_set_program(&fs, &s->prog);
    for (oi = 0; oi < 2; ++oi)
        for (ai = 0; ai < 5; ++ai)
            for (cone = 0; cone < 2; ++cone)
                for (m = 0; m < 4; ++m) {
                    double ro[3], rd[3], a = angles[ai], y, thr, cl, t_true;
                    fovsdf_march_params mp = march_params(m, FOVSDF_MAX_STEPS, 1e-4, cone ? 2.5e-4 : 0.0, 1e7);
                    fovsdf_hit h;
                    fov_result r;
                    int k;
                    for (k = 0; k < 3; ++k) ro[k] = origins[oi][k];
                    rd[0] = rf(cos(a)); rd[1] = rf(-sin(a)); rd[2] = 0.0;
                    march_f(&fs, &mp, ro, rd, 0.0, &h, &r);
                    n++;
                    cl = len3d(ro[0], ro[1], ro[2]);
                    t_true = -ro[1] / rd[1];
                    if (r != FOV_OK || h.kind > FOVSDF_EXHAUSTED || h.steps > FOVSDF_MAX_STEPS || !finite_d((double)h.t) ||
                        (double)h.t < 0.0 || (double)h.t > 1e7) {
                        if (bad++ == 0)
                            snprintf(first, sizeof first, "angle %g %s: result %s kind %u t %g steps %u", a, fovsdf_method_name(m),
                                     fovsdf_result_string(r), h.kind, (double)h.t, h.steps);
                        continue;
                    }
                    y = ro[1] + rd[1] * (double)h.t; /* exact distance to the plane at the reported t */
                    thr = dmax(dmax(1e-4, cone ? 2.5e-4 * (double)h.t : 0.0), 8.0 * FE * (cl + (double)h.t));
                    if (h.kind != FOVSDF_MISS && y < -thr) tunnel++;
                    if (h.kind == FOVSDF_HIT) {
                        double ratio = fabs(y) / thr;
                        worst_hit = dmax(worst_hit, ratio);
                        if (!(fabs(y) <= thr + 4.0 * FE * (cl + (double)h.t))) hit_far++;
                    }
                    if (oi == 0 && cone == 0)
                        fovcheck_info("s4_grazing %g rad %s: %s at t %.7g (plane at %.7g, relative %.2g), %u steps", a, fovsdf_method_name(m),
                             h.kind == FOVSDF_HIT ? "HIT" : (h.kind == FOVSDF_MISS ? "MISS" : "EXHAUSTED"), (double)h.t, t_true,
                             ((double)h.t - t_true) / t_true, h.steps);
                }
    check(bad == 0, "s4_grazing_terminates_finite", "%d of %d grazing rays with an error, an invalid kind, too many steps or a bad t; first: %s",
          bad, n, first);
    check(tunnel == 0, "s4_grazing_never_passes_the_plane", "%d of %d grazing rays reported past the plane", tunnel, n);
    check(hit_far == 0, "s4_grazing_hit_within_threshold", "%d grazing hits farther from the plane than the threshold (worst %.3g thresholds)",
          hit_far, worst_hit);
    check((double)(clock() - t0) / CLOCKS_PER_SEC < 20.0, "s4_grazing_time", "%.2f s for %d rays", (double)(clock() - t0) / CLOCKS_PER_SEC, n);
    sc_free(s);
}

/* Rays that start inside a surface report a hit at t_start (every tracer, the double
   reference, fovsdf_trace with a context), near the origin and 1e5 units away. */
static void section4_inside(void)
{
    Sc *s = sc_new();
    fovsdf_scene fs, ds;
    RefCtx rc;
    Rng g;
    int sc_i, i, bad = 0, n = 0, ref_bad = 0;
    uint32_t m;
    char first[256] = "";
    g.s = 4242;
    for (sc_i = 0; sc_i < 3; ++sc_i) {
        int root;
        double base[3] = { 0.0, 0.0, 0.0 }, reach;
        sc_reset(s);
        if (sc_i == 0) { root = sc_sphere(s, 1.0); reach = 0.5; }
        else if (sc_i == 1) { /* a union with a plane: start inside the box */
            root = sc_union(s, sc_union(s, sc_box(s, 1.0, 0.8, 0.9), sc_translate(s, sc_sphere(s, 0.5), 3.0, 0.0, 0.0)),
                            sc_plane(s, 0.0, 1.0, 0.0, 2.0));
            reach = 0.4;
        } else { /* a big sphere 1e5 units away */
            base[0] = rf(6e4); base[1] = rf(-5e4); base[2] = rf(5.5e4);
            root = sc_translate(s, sc_sphere(s, 1000.0), base[0], base[1], base[2]);
            reach = 500.0;
        }
        if (sc_build(s, root) != FOV_OK) { check(0, "s4_inside_build", "program build failed"); continue; }
        fovsdf_scene_init(&fs);
        fovsdf_scene_set_program(&fs, &s->prog);
        fovsdf_scene_init(&ds);
        rc.s = s; rc.root = root;
        ds.dist_d = ref_dist_d; ds.user = &rc;
        for (i = 0; i < 40; ++i) {
            double ro[3], rd[3], t0 = (i % 4) * 0.1 * reach, tr;
            uint32_t kr;
            int k;
            for (k = 0; k < 3; ++k) { ro[k] = rf(base[k] + urange(&g, -0.5, 0.5) * reach); rd[k] = urange(&g, -1.0, 1.0); }
            unit(rd);
            for (k = 0; k < 3; ++k) rd[k] = rf(rd[k]);
            t0 = rf(t0);
            for (m = 0; m < 4; ++m) {
                fovsdf_march_params mp = march_params(m, 256, 1e-4, 0.0, 100.0 + reach * 10.0);
                fovsdf_hit h;
                fov_result r;
                march_f(&fs, &mp, ro, rd, t0, &h, &r);
                n++;
                if (r != FOV_OK || h.kind != FOVSDF_HIT || (double)h.t != t0 || !((double)h.dist < 0.0)) {
                    if (bad++ == 0)
                        snprintf(first, sizeof first, "scene %d %s: result %s kind %u t %.9g (t_start %.9g) dist %g", sc_i,
                                 fovsdf_method_name(m), fovsdf_result_string(r), h.kind, (double)h.t, t0, (double)h.dist);
                }
            }
            if (fovsdf_trace_ref(&ds, ro, rd, t0, 100.0 + reach * 10.0, 1e-9, 1000, &tr, &kr) != FOV_OK || kr != FOVSDF_HIT || tr != t0)
                ref_bad++;
        }
    }
    check(n > 0 && bad == 0, "s4_inside_hit_at_t_start", "%d of %d rays starting inside did not report HIT at t_start; first: %s", bad, n, first);
    check(ref_bad == 0, "s4_inside_reference_hit_at_t_start", "%d rays where fovsdf_trace_ref did not report HIT at t_start", ref_bad);
    /* through a context: the camera inside a sphere */
    {
        fovsdf_ctx ctx;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fov_gaze gz;
        fov_result r1;
        fovsdf_hit h;
        float ro[3], rd[3];
        int root;
        uint32_t mm;
        int cbad = 0;
        sc_reset(s);
        root = sc_sphere(s, 2.0);
        (void)sc_build(s, root);
        fovsdf_scene_init(&fs);
        fovsdf_scene_set_program(&fs, &s->prog);
        fovsdf_camera_init(&cam, 16, 9);
        cam.pos[0] = 0.3f; cam.pos[1] = 0.2f; cam.pos[2] = -0.5f;
        gz.x = 8.0f; gz.y = 4.5f;
        for (mm = 0; mm < 4; ++mm) {
            cfg.method = mm;
            r1 = fovsdf_init(&ctx, &cfg, &fs, &cam, gz, NULL, 0);
            if (r1 != FOV_OK || !(ctx.cam_dist < 0.0f)) { cbad++; continue; }
            (void)fovsdf_camera_ray(&ctx, 3.5f, 6.5f, ro, rd);
            if (fovsdf_trace(&ctx, ro, rd, 0.0f, &h, NULL) != FOV_OK || h.kind != FOVSDF_HIT || h.t != 0.0f) cbad++;
            if (fovsdf_trace(&ctx, ro, rd, 0.75f, &h, NULL) != FOV_OK || h.kind != FOVSDF_HIT || h.t != 0.75f) cbad++;
        }
        check(cbad == 0, "s4_inside_context_trace", "%d failures (fovsdf_init, cam_dist < 0, fovsdf_trace HIT at t_start)", cbad);
    }
    sc_free(s);
}

/* Small renders of the setups: no NaN or infinity anywhere; where the reference is clear the
   hit mask agrees with it; a camera inside a surface gives hits at depth 0 everywhere. */
typedef struct RSetup {
    const char *name;
    int kind;             /* 0 sphere, 1 rotated box, 2 plane, 3 inside a sphere */
    double size, cam[3], target[3], fov, eps, t_max;
    uint32_t eps_mode;
} RSetup;

static void section4_render(void)
{
    enum { W = 48, H = 27 };
    RSetup rs[11];
    int n = 0, i;
    Sc *s = sc_new();
    double dir[3] = { 1.0, 0.7, -0.5 }, fwd[3] = { 0.3, -0.2, 1.0 };
    unit(dir);
    unit(fwd);
    memset(rs, 0, sizeof rs);
    for (i = 0; i < 2; ++i) { /* far cameras, unit sphere 5 units ahead */
        double D = i == 0 ? 1e4 : 1e5;
        int k;
        rs[n].name = i == 0 ? "far1e4_unit_sphere" : "far1e5_unit_sphere";
        rs[n].kind = 0; rs[n].size = 1.0; rs[n].fov = 40.0; rs[n].eps = 1e-4; rs[n].t_max = 20.0;
        for (k = 0; k < 3; ++k) { rs[n].cam[k] = rf(D * dir[k]); rs[n].target[k] = rs[n].cam[k] + 5.0 * fwd[k]; }
        n++;
    }
    {   /* far camera, big sphere at the origin */
        int k;
        rs[n].name = "far1e5_big_sphere"; rs[n].kind = 0; rs[n].size = 1000.0; rs[n].fov = 1.6; rs[n].eps = 1e-4; rs[n].t_max = 2e5;
        for (k = 0; k < 3; ++k) { rs[n].cam[k] = rf(1e5 * dir[k]); rs[n].target[k] = 0.0; }
        n++;
    }
    for (i = 0; i < 3; ++i) { /* scaled sphere and box */
        static const double sz[3] = { 1e-4, 1.0, 1e3 };
        static const char *const nms[3] = { "scaled_box_1e-4", "scaled_box_1", "scaled_box_1e3" };
        int k;
        double d[3] = { 0.3, 0.4, -1.0 };
        unit(d);
        rs[n].name = nms[i]; rs[n].kind = 1; rs[n].size = sz[i]; rs[n].fov = 35.0; rs[n].eps = 1e-4 * sz[i]; rs[n].t_max = 20.0 * sz[i];
        for (k = 0; k < 3; ++k) { rs[n].cam[k] = rf(5.0 * sz[i] * d[k]); rs[n].target[k] = 0.0; }
        n++;
        rs[n] = rs[n - 1];
        rs[n].kind = 0;
        rs[n].name = i == 0 ? "scaled_sphere_1e-4" : (i == 1 ? "scaled_sphere_1" : "scaled_sphere_1e3");
        n++;
    }
    {   /* a camera near the origin, a sphere of radius 1e3 at 1e5 */
        int k;
        rs[n].name = "origin_camera_far1e5_sphere"; rs[n].kind = 0; rs[n].size = 1000.0; rs[n].fov = 1.6; rs[n].eps = 1e-4;
        rs[n].t_max = 2e5;
        rs[n].eps_mode = FOVSDF_EPS_ABSOLUTE; /* no pixel cone: the ulp floor alone keeps the march going */
        rs[n].cam[0] = 1.0; rs[n].cam[1] = 2.0; rs[n].cam[2] = -3.0;
        for (k = 0; k < 3; ++k) rs[n].target[k] = rf(rs[n].cam[k] + 1e5 * dir[k]);
        n++;
    }
    /* the plane seen at grazing angles: fov 1 degree around 0.01 rad below the horizon */
    rs[n].name = "grazing_plane"; rs[n].kind = 2; rs[n].size = 1.0; rs[n].fov = 1.0; rs[n].eps = 1e-4; rs[n].t_max = 1e4;
    rs[n].cam[1] = 1.0; rs[n].target[0] = 100.0; rs[n].target[1] = 0.0;
    n++;
    for (i = 0; i < n + 1; ++i) {
        const RSetup *su;
        RSetup inside;
        fovsdf_ctx ctx;
        fovsdf_camera cam;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_scene fs;
        fov_gaze gz;
        fovsdf_output out;
        float rgb[W * H * 3], depth[W * H];
        uint8_t rgb8[W * H * 3], hit[W * H];
        uint32_t evals[W * H];
        int32_t mat[W * H];
        int root, k, x, y, nonfinite = 0, mask_bad = 0, clear = 0, hits = 0;
        fov_result r1, r2;
        fovsdf_stats st;
        char nm[128];
        if (i == n) { /* the camera inside a unit sphere */
            memset(&inside, 0, sizeof inside);
            inside.name = "inside_sphere"; inside.kind = 3; inside.size = 1.0; inside.fov = 60.0; inside.eps = 1e-4; inside.t_max = 10.0;
            inside.cam[0] = 0.2; inside.target[2] = 1.0;
            su = &inside;
        } else {
            su = &rs[i];
        }
        sc_reset(s);
        if (su->kind == 0 || su->kind == 3) root = sc_sphere(s, su->size);
        else if (su->kind == 1) root = sc_rotate(s, sc_box(s, su->size, 0.6 * su->size, 0.8 * su->size), 1.0, 1.0, 1.0, 30.0);
        else root = sc_plane(s, 0.0, 1.0, 0.0, 0.0);
        if (su->kind == 0 && (su->size == 1.0 || su->cam[0] == 1.0) && len3d(su->target[0], su->target[1], su->target[2]) > 100.0)
            root = sc_translate(s, root, su->target[0], su->target[1], su->target[2]); /* the sphere at the target */
        if (sc_build(s, root) != FOV_OK) { check(0, su->name, "program build failed"); continue; }
        fovsdf_scene_init(&fs);
        fovsdf_scene_set_program(&fs, &s->prog);
        fs.lights[0].shadow_k = 16.0f;
        fovsdf_camera_init(&cam, W, H);
        for (k = 0; k < 3; ++k) { cam.pos[k] = (float)su->cam[k]; cam.target[k] = (float)su->target[k]; }
        cam.fov_y_deg = (float)su->fov;
        cfg.eps = (float)su->eps;
        cfg.eps_mode = su->eps_mode;
        cfg.t_max = (float)su->t_max;
        gz.x = 0.5f * W; gz.y = 0.5f * H;
        r1 = fovsdf_init(&ctx, &cfg, &fs, &cam, gz, NULL, 0);
        fovsdf_output_init(&out);
        out.rgb = rgb; out.rgb8 = rgb8; out.depth = depth; out.hit = hit; out.evals = evals; out.material = mat;
        for (k = 0; k < W * H; ++k) { depth[k] = -1.0f; hit[k] = 7; }
        memset(&st, 0, sizeof st);
        r2 = r1 == FOV_OK ? fovsdf_render_rows(&ctx, 0, H, &out, &st) : r1;
        for (k = 0; k < W * H * 3; ++k) if (!finite_d((double)rgb[k]) || rgb[k] < 0.0f) nonfinite++;
        for (k = 0; k < W * H; ++k) {
            if (!finite_d((double)depth[k]) || depth[k] < 0.0f || (double)depth[k] > su->t_max * 1.000001 || hit[k] > 1) nonfinite++;
            hits += hit[k] == 1;
        }
        snprintf(nm, sizeof nm, "s4_render_%s_finite", su->name);
        check(r1 == FOV_OK && r2 == FOV_OK && nonfinite == 0, nm, "init %s, render %s, %d non-finite or out-of-range values",
              fovsdf_result_string(r1), fovsdf_result_string(r2), nonfinite);
        if (r1 != FOV_OK || r2 != FOV_OK) continue;
        if (su->kind == 3) {
            int bad = 0;
            for (k = 0; k < W * H; ++k) if (hit[k] != 1 || depth[k] != 0.0f) bad++;
            snprintf(nm, sizeof nm, "s4_render_%s_hits_at_zero", su->name);
            check(bad == 0, nm, "%d of %d pixels not a hit at depth 0 with the camera inside the sphere", bad, W * H);
            continue;
        }
        if (su->kind == 2) {
            fovcheck_info("s4_render_%s: %d of %d pixels hit or exhausted", su->name, hits, W * H);
            continue;
        }
        /* hit mask vs the double reference where the reference is clear */
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                float rof[3], rdf[3];
                double ro[3], rd[3];
                RefRay rr;
                int expect = -1;
                (void)fovsdf_camera_ray(&ctx, (float)x + 0.5f, (float)y + 0.5f, rof, rdf);
                for (k = 0; k < 3; ++k) { ro[k] = (double)rof[k]; rd[k] = (double)rdf[k]; }
                ref_ray(s, root, ro, rd, su->t_max, 1e-9 * su->size + 1e-13 * len3d(ro[0], ro[1], ro[2]), su->eps,
                        su->eps_mode == FOVSDF_EPS_ABSOLUTE ? 0.0 : 0.25 * (double)ctx.pixel_angle, su->size, &rr);
                if (rr.kind == FOVSDF_HIT && rr.cos_inc >= 0.3) expect = 1;
                else if (rr.kind == FOVSDF_MISS && rr.min_ratio > 4.0) expect = 0;
                if (expect < 0) continue;
                clear++;
                if (hit[y * W + x] != expect) mask_bad++;
            }
        snprintf(nm, sizeof nm, "s4_render_%s_hit_mask", su->name);
        check(clear > W * H / 2 && mask_bad == 0 && st.exhausted == 0, nm,
              "%d of %d clear pixels where the hit mask disagrees with the reference; %lu primary rays exhausted their steps",
              mask_bad, clear, (unsigned long)st.exhausted);
        fovcheck_info("s4_render_%s: %d of %d pixels hit, %d clear", su->name, hits, W * H, clear);
    }
    sc_free(s);
}

/* ==== main ================================================================================ */
/* fovsdf_program_compact: the compacted code renders the same bytes after the build memory
   is overwritten, and it is a small part of that memory. */
static void section5_compact(void)
{
    size_t sz, need;
    unsigned char *mem, *code;
    fovsdf_builtin bi;
    fovsdf_program p;
    fovsdf_config c = fovsdf_config_default();
    fovsdf_ctx k;
    fovsdf_output o;
    fov_gaze gz = { 32.0f, 18.0f };
    static float a[64 * 36 * 3], b[64 * 36 * 3];
    fov_result r1, r2, r3;
    fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &sz);
    mem = (unsigned char *)malloc(sz);
    fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &bi, mem, sz);
    bi.camera.width = 64; bi.camera.height = 36;
    c.method = FOVSDF_METHOD_CONE;
    fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
    fovsdf_output_init(&o); o.rgb = a;
    fovsdf_render_rows(&k, 0, 36, &o, NULL);
    p = *bi.program;
    need = fovsdf_program_code_bytes(&p);
    code = (unsigned char *)malloc(need + 1);
    r1 = fovsdf_program_compact(&p, code + 1, need - 1);   /* too small */
    r2 = fovsdf_program_compact(&p, NULL, need);
    r3 = fovsdf_program_compact(&p, code + 1, need);       /* unaligned start: aligned inside */
    memset(mem, 0xff, sz);                                  /* the build memory is gone */
    fovsdf_scene_set_program(&bi.scene, &p);
    fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
    o.rgb = b;
    fovsdf_render_rows(&k, 0, 36, &o, NULL);
    check(r1 == FOV_ERR_TOO_SMALL && r2 == FOV_ERR_NULL && r3 == FOV_OK && memcmp(a, b, sizeof a) == 0 && need * 4 < sz,
          "s5_compact_program_renders_the_same",
          "errors %d %d, compact %d, images %s, code %zu of %zu build bytes", (int)r1, (int)r2, (int)r3,
          memcmp(a, b, sizeof a) ? "differ" : "equal", need, sz);
    free(code);
    free(mem);
}

int main(void)
{
    clock_t t0 = clock();
    section1();
    section2_random("s2_random", 200, 0);
    section2_random("s2_random_grouped", 40, 1); /* groups under round, onion, smooth union */
    section2_graphs();
    section3();
    section4_far();
    section4_scaled();
    section4_grazing();
    section4_inside();
    section4_render();
    section5_compact();
    fovcheck_info("run time %.2f s", (double)(clock() - t0) / CLOCKS_PER_SEC);
    return fovcheck_summary();
}
