/* fovstress.h - the stress scenes of issue 10 for fovsdf.h, and their double-precision ground
   truth, shared by tests/test_fovsdf_props.c and bench/bench_stress.c (everything static).

   A scene is a union (min) of simple analytic primitives with float parameters. The library
   traces the float evaluation (fs_dist, a plain fovsdf_dist_fn); the reference evaluates the
   same formulas in double on the same (float) parameters (fs_dist_d), independent of the
   library's program evaluator, and marches in double along the library's own rays
   (fovsdf_camera_ray), so a difference is the tracer's, not the scene's.

   Six kinds (fs_make): FS_ONION nested thin shells cut open, FS_DUST many tiny spheres,
   FS_FAR a cluster of boxes, spheres, shells and Menger sponges 1e3 .. 1e6 units from the origin, FS_GRAZE
   a floor with low bumps seen at grazing angles, FS_ROOM a camera inside a closed room with
   thin pillars, FS_NEEDLE capsules of radius 0.002.

   Reference along a ray (fs_ref):
     t_in    the first t in [0, t_max] where the double distance is below -tol(t) (the ray is
             inside an object by more than the float noise), or +inf;
     near    1 when the ray comes within foot(t) of a surface before t_max (foot(t) =
             max(eps, foot_ang * t, tol(t))), so a reported hit there is legitimate;
   with tol(t) = 8 FLT_EPSILON (|camera| + t) + tol_frac * thr(t), thr the library's threshold
   for that ray. A reported hit (or a head start) at t "lies behind the first surface" when
   t > t_in. The reference marches f + tol (resp. f - foot) with steps no shorter than
   fs_dmin(t) = 0.002 tol(t); it may therefore find t_in up to that much late (never early). */
#ifndef FOVSTRESS_H
#define FOVSTRESS_H
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define FSTRESS_UNUSED __attribute__((unused))
#else
#define FSTRESS_UNUSED
#endif

enum { FS_ONION, FS_DUST, FS_FAR, FS_GRAZE, FS_ROOM, FS_NEEDLE, FS_KINDS };
static const char *const fs_kind_name[FS_KINDS] = { "onion", "dust", "far", "graze", "room", "needle" };

enum { FP_SPHERE, FP_SHELL_CUT, FP_BOX, FP_ROOM, FP_CAPSULE, FP_PLANE_Y, FP_VCYL, FP_MENGER };
typedef struct fs_prim {
    int type;
    float a[3], b[3]; /* centre / segment start; half extents / segment end / cut normal */
    float r, r2;      /* radius, thickness / cut offset / half height */
} fs_prim;

#define FS_MAXP 320
typedef struct fs_scene {
    int kind, n;
    fs_prim p[FS_MAXP];
    float cam[3], target[3], up[3], fov, t_max;
} fs_scene;

static uint32_t fs_rng(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}
static double fs_u(uint32_t *s) { return (double)fs_rng(s) / 16777216.0; }
static double fs_ur(uint32_t *s, double lo, double hi) { return lo + (hi - lo) * fs_u(s); }

/* The primitives, once in float (what the library traces) and once in double. */
#define FS_DEFINE_EVAL(NAME, T, SQRT, FABS, FLOOR)                                                           \
    static T NAME(const fs_scene *sc, const T q[3])                                                   \
    {                                                                                                 \
        T best = (T)1e30;                                                                             \
        int i;                                                                                        \
        for (i = 0; i < sc->n; ++i) {                                                                 \
            const fs_prim *pr = &sc->p[i];                                                            \
            T x = q[0] - (T)pr->a[0], y = q[1] - (T)pr->a[1], z = q[2] - (T)pr->a[2], d;              \
            switch (pr->type) {                                                                       \
            case FP_SPHERE: d = SQRT(x * x + y * y + z * z) - (T)pr->r; break;                        \
            case FP_SHELL_CUT: {                                                                      \
                T s = FABS(SQRT(x * x + y * y + z * z) - (T)pr->r) - (T)pr->r2;                       \
                T c = x * (T)pr->b[0] + y * (T)pr->b[1] + z * (T)pr->b[2] - (T)pr->r * (T)0.3;         \
                d = s > c ? s : c;                                                                    \
                break;                                                                                \
            }                                                                                         \
            case FP_BOX:                                                                              \
            case FP_ROOM: {                                                                           \
                T ex = FABS(x) - (T)pr->b[0], ey = FABS(y) - (T)pr->b[1], ez = FABS(z) - (T)pr->b[2];   \
                T mx = ex > ey ? (ex > ez ? ex : ez) : (ey > ez ? ey : ez);                           \
                T ox = ex > 0 ? ex : 0, oy = ey > 0 ? ey : 0, oz = ez > 0 ? ez : 0;                   \
                d = SQRT(ox * ox + oy * oy + oz * oz) + (mx < 0 ? mx : 0);                            \
                if (pr->type == FP_ROOM) d = -d;                                                      \
                break;                                                                                \
            }                                                                                         \
            case FP_CAPSULE: {                                                                        \
                T bx = (T)pr->b[0] - (T)pr->a[0], by = (T)pr->b[1] - (T)pr->a[1],                      \
                  bz = (T)pr->b[2] - (T)pr->a[2];                                                     \
                T h = (x * bx + y * by + z * bz) / (bx * bx + by * by + bz * bz);                     \
                h = h < 0 ? 0 : (h > 1 ? 1 : h);                                                      \
                x -= bx * h; y -= by * h; z -= bz * h;                                                \
                d = SQRT(x * x + y * y + z * z) - (T)pr->r;                                           \
                break;                                                                                \
            }                                                                                         \
            case FP_PLANE_Y: d = y; break;                                                            \
            case FP_MENGER: { /* Menger sponge of half size r, 3 iterations (Quilez's bound) */         \
                T hs = (T)pr->r, scl = 1, ex, ey, ez, mx, ox, oy, oz;                                  \
                int it;                                                                               \
                x /= hs; y /= hs; z /= hs;                                                            \
                ex = FABS(x) - 1; ey = FABS(y) - 1; ez = FABS(z) - 1;                                 \
                mx = ex > ey ? (ex > ez ? ex : ez) : (ey > ez ? ey : ez);                             \
                ox = ex > 0 ? ex : 0; oy = ey > 0 ? ey : 0; oz = ez > 0 ? ez : 0;                     \
                d = SQRT(ox * ox + oy * oy + oz * oz) + (mx < 0 ? mx : 0);                            \
                for (it = 0; it < 3; ++it) {                                                          \
                    T ax = x * scl, ay = y * scl, az = z * scl, rx, ry, rz, da, db, dc, cc;              \
                    ax = ax - 2 * FLOOR(ax / 2) - 1; ay = ay - 2 * FLOOR(ay / 2) - 1;                   \
                    az = az - 2 * FLOOR(az / 2) - 1;                                                  \
                    scl *= 3;                                                                         \
                    rx = FABS(1 - 3 * FABS(ax)); ry = FABS(1 - 3 * FABS(ay)); rz = FABS(1 - 3 * FABS(az)); \
                    da = rx > ry ? rx : ry; db = ry > rz ? ry : rz; dc = rz > rx ? rz : rx;           \
                    cc = ((da < db ? (da < dc ? da : dc) : (db < dc ? db : dc)) - 1) / scl;            \
                    d = d > cc ? d : cc;                                                              \
                }                                                                                     \
                d *= hs;                                                                              \
                break;                                                                                \
            }                                                            \
            default: { /* vertical cylinder, radius r, half height r2 */                               \
                T dr = SQRT(x * x + z * z) - (T)pr->r, dy = FABS(y) - (T)pr->r2;                      \
                T ox = dr > 0 ? dr : 0, oy = dy > 0 ? dy : 0;                                         \
                d = SQRT(ox * ox + oy * oy) + ((dr > dy ? dr : dy) < 0 ? (dr > dy ? dr : dy) : 0);     \
                break;                                                                                \
            }                                                                                         \
            }                                                                                         \
            if (d < best) best = d;                                                                   \
        }                                                                                             \
        return best;                                                                                  \
    }
FS_DEFINE_EVAL(fs_eval_f, float, sqrtf, fabsf, floorf)
FS_DEFINE_EVAL(fs_eval_d, double, sqrt, fabs, floor)

static float fs_dist(const float p[3], void *user) { return fs_eval_f((const fs_scene *)user, p); }

static void fs_add(fs_scene *s, int type, double ax, double ay, double az, double bx, double by, double bz, double r,
                   double r2)
{
    fs_prim *p;
    if (s->n >= FS_MAXP) return;
    p = &s->p[s->n++];
    p->type = type;
    p->a[0] = (float)ax; p->a[1] = (float)ay; p->a[2] = (float)az;
    p->b[0] = (float)bx; p->b[1] = (float)by; p->b[2] = (float)bz;
    p->r = (float)r; p->r2 = (float)r2;
}

/* Random scene of a kind; n_obj scales the object count (dust, needles, pillars); far_d is
   the distance of FS_FAR's cluster from the origin (0: random in 1e3 .. 1e6). */
static void fs_make(fs_scene *s, int kind, uint32_t seed, int n_obj, double far_d)
{
    uint32_t r = seed * 2654435761u + 12345u;
    double off[3] = { 0.0, 0.0, 0.0 }, cd[3];
    int i;
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->up[1] = 1.0f;
    s->fov = 60.0f;
    s->t_max = 40.0f;
    (void)fs_rng(&r);
    switch (kind) {
    case FS_ONION: {
        int k, nk = 3 + (int)(fs_u(&r) * 3.0);
        double n[3] = { fs_ur(&r, -1, 1), fs_ur(&r, -1, 1), -1.5 }, l;
        l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (k = 0; k < nk; ++k)
            fs_add(s, FP_SHELL_CUT, 0, 0, 0, n[0] / l, n[1] / l, n[2] / l, 0.6 + 0.5 * k, fs_ur(&r, 0.0005, 0.005));
        fs_add(s, FP_SPHERE, 0, 0, 0, 0, 0, 0, 0.3, 0);
        cd[0] = fs_ur(&r, -2, 2); cd[1] = fs_ur(&r, -1, 2); cd[2] = -6.0;
        break;
    }
    case FS_DUST:
        for (i = 0; i < n_obj; ++i)
            fs_add(s, FP_SPHERE, fs_ur(&r, -1, 1), fs_ur(&r, -0.6, 0.6), fs_ur(&r, -1, 1), 0, 0, 0, fs_ur(&r, 0.002, 0.03), 0);
        cd[0] = fs_ur(&r, -0.5, 0.5); cd[1] = fs_ur(&r, -0.3, 0.3); cd[2] = -2.6;
        s->t_max = 10.0f;
        break;
    case FS_FAR: {
        double D = far_d > 0.0 ? far_d : pow(10.0, fs_ur(&r, 3.0, 6.0));
        double dir[3] = { 0.6, 0.48, -0.64 };
        for (i = 0; i < 3; ++i) off[i] = D * dir[i];
        for (i = 0; i < 10; ++i) {
            double x = fs_ur(&r, -9, 9), y = fs_ur(&r, -4, 4), z = fs_ur(&r, -9, 9);
            if (i % 3 == 0) fs_add(s, FP_BOX, off[0] + x, off[1] + y, off[2] + z, fs_ur(&r, 0.5, 2.5), fs_ur(&r, 0.1, 2.5), fs_ur(&r, 0.5, 2.5), 0, 0);
            else if (i % 3 == 1) fs_add(s, FP_SPHERE, off[0] + x, off[1] + y, off[2] + z, 0, 0, 0, fs_ur(&r, 0.5, 2.5), 0);
            else if (i % 6 == 2) fs_add(s, FP_SHELL_CUT, off[0] + x, off[1] + y, off[2] + z, 0, 0.6, -0.8, fs_ur(&r, 1.0, 2.5), fs_ur(&r, 0.02, 0.1));
            else fs_add(s, FP_MENGER, off[0] + x, off[1] + y, off[2] + z, 0, 0, 0, fs_ur(&r, 1.5, 4.0), 0);
        }
        cd[0] = fs_ur(&r, -2, 2); cd[1] = fs_ur(&r, -1, 1); cd[2] = -22.0;
        s->t_max = 60.0f;
        break;
    }
    case FS_GRAZE:
        fs_add(s, FP_PLANE_Y, 0, 0, 0, 0, 0, 0, 0, 0);
        for (i = 0; i < 40 && s->n < FS_MAXP; ++i) {
            double rr = fs_ur(&r, 0.05, 0.4), h = fs_ur(&r, 0.0005, 0.02);
            fs_add(s, FP_SPHERE, fs_ur(&r, -6, 6), h - rr, fs_ur(&r, 0.5, 30), 0, 0, 0, rr, 0);
        }
        s->cam[0] = 0.0f; s->cam[1] = (float)fs_ur(&r, 0.02, 0.2); s->cam[2] = 0.0f;
        s->target[0] = (float)fs_ur(&r, -1, 1); s->target[1] = 0.0f; s->target[2] = 30.0f;
        s->fov = 30.0f;
        s->t_max = 60.0f;
        return;
    case FS_ROOM:
        fs_add(s, FP_ROOM, 0, 1.5, 0, 5, 1.5, 5, 0, 0);
        for (i = 0; i < n_obj; ++i)
            fs_add(s, FP_VCYL, fs_ur(&r, -4.5, 4.5), 1.5, fs_ur(&r, -4.5, 4.5), 0, 0, 0, fs_ur(&r, 0.004, 0.05), 1.5);
        fs_add(s, FP_BOX, fs_ur(&r, -3, 3), 0.3, fs_ur(&r, -3, 3), 0.4, 0.3, 0.6, 0, 0);
        s->cam[0] = (float)fs_ur(&r, -1, 1); s->cam[1] = (float)fs_ur(&r, 0.5, 2.5); s->cam[2] = (float)fs_ur(&r, -1, 1);
        s->target[0] = (float)fs_ur(&r, -5, 5); s->target[1] = (float)fs_ur(&r, 0, 3); s->target[2] = 5.0f;
        s->fov = 90.0f;
        s->t_max = 30.0f;
        return;
    default: /* FS_NEEDLE */
        for (i = 0; i < n_obj; ++i) {
            double x = fs_ur(&r, -1.5, 1.5), y = fs_ur(&r, -1, 1), z = fs_ur(&r, -1, 1);
            fs_add(s, FP_CAPSULE, x, y, z, x + fs_ur(&r, -1, 1), y + fs_ur(&r, -1, 1), z + fs_ur(&r, -1, 1), 0.002, 0);
        }
        fs_add(s, FP_SPHERE, 0, 0, 6, 0, 0, 0, 2.0, 0);
        cd[0] = fs_ur(&r, -0.5, 0.5); cd[1] = fs_ur(&r, -0.5, 0.5); cd[2] = -4.0;
        s->t_max = 20.0f;
        break;
    }
    for (i = 0; i < 3; ++i) {
        s->cam[i] = (float)(off[i] + cd[i]);
        s->target[i] = (float)off[i];
    }
}

/* Reference of one ray (ro, rd: the library's float ray, taken exactly as doubles). thr0 +
   thr1 t is the library's threshold growth without its ulp floor (max(eps, eps_cone t)): pass
   eps and the ray's eps_cone; foot_ang the pixel's angular footprint for `near`. */
typedef struct fs_ref {
    double t_in;   /* first t with f < -tol(t), or INFINITY */
    double t_hit;  /* first t with f <= 0 (to fs_dmin), or INFINITY */
    int near;      /* comes within foot(t) of a surface before t_max */
    int capped;    /* the reference ran out of steps (result unknown) */
} fs_ref;


/* march g(t) = f(t) - lvl(t), lvl(t) = u0 + u1 t + w max(eps, ec t) (Lipschitz bound
   1 + |u1| + |w| ec), to its first root below t_max; returns the root or INFINITY; sets
   *capped on running out of steps. Steps are at least dmin(t) = 0.002 (8 FLT_EPSILON (cl + t)
   + 0.02 max(eps, ec t)). */
static double fs_root(const fs_scene *sc, const double ro[3], const double rd[3], double cl, double t_max, double u0,
                      double u1, double w, double eps, double ec, int *capped)
{
    double t = 0.0, L = 1.0 + fabs(u1) + fabs(w) * ec;
    long k;
    for (k = 0; k < 400000; ++k) {
        double p[3], g, m = eps > ec * t ? eps : ec * t, dmin;
        p[0] = ro[0] + rd[0] * t; p[1] = ro[1] + rd[1] * t; p[2] = ro[2] + rd[2] * t;
        g = fs_eval_d(sc, p) - (u0 + u1 * t + w * m);
        if (g <= 0.0) return t;
        if (t > t_max) return (double)INFINITY;
        g /= L;
        dmin = 0.002 * (8.0 * (double)FLT_EPSILON * (cl + t) + 0.02 * m) + 1e-12;
        t += g > dmin ? g : dmin;
    }
    *capped = 1;
    return (double)INFINITY;
}

/* tol(t) of the header comment */
FSTRESS_UNUSED static double fs_tol(double cl, double t, double eps, double ec, double tol_frac)
{
    return 8.0 * (double)FLT_EPSILON * (cl + t) + tol_frac * (eps > ec * t ? eps : ec * t);
}

static fs_ref fs_reference(const fs_scene *sc, const float rof[3], const float rdf[3], double t_max, double eps,
                           double eps_cone, double tol_frac, double foot_ang)
{
    fs_ref r;
    double ro[3], rd[3], cl, e8 = 8.0 * (double)FLT_EPSILON;
    int i;
    for (i = 0; i < 3; ++i) { ro[i] = (double)rof[i]; rd[i] = (double)rdf[i]; }
    cl = sqrt(ro[0] * ro[0] + ro[1] * ro[1] + ro[2] * ro[2]);
    r.capped = 0;
    r.t_in = fs_root(sc, ro, rd, cl, t_max, -e8 * cl, -e8, -tol_frac, eps, eps_cone, &r.capped);
    r.t_hit = fs_root(sc, ro, rd, cl, t_max, 0.0, 0.0, 0.0, eps, eps_cone, &r.capped);
    /* near: f < max(eps, foot t, 8 FLT_EPSILON (cl + t)) <= eps + foot t + 8 FLT_EPSILON (cl + t) */
    r.near = fs_root(sc, ro, rd, cl, t_max, eps + e8 * cl, e8 + foot_ang, 0.0, eps, eps_cone, &r.capped) <= t_max;
    return r;
}
#endif
