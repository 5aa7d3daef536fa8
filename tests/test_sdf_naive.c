/*
 * test_sdf_naive.c - bench/sdf_naive.h (the built-in scenes written as plain C distance
 * functions, bench-sdf's naive and *_cb rows) agrees with the built-in programs.
 *
 * Build and run (from the repository root):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -ffp-contract=off -I. -Itests/common tests/test_sdf_naive.c -lm \
 *       -o build/tests/test_sdf_naive && ./build/tests/test_sdf_naive
 * Also built with -DFOV_NO_LIBM and with sanitizers. The naive functions call the library's
 * math (FOV__SQRT, FOV__FLOOR, and the mandelbulb's and terrain's own float kernels for sin,
 * cos, atan2, pow and log), so both sides use the same functions.
 *
 * For each of the six scenes, at 20000 random points in a box around the view (the camera
 * target +- 1.5 times the camera distance, camera included) and at every step and around
 * every hit of sphere-traced camera rays of the built-in view (64 x 36 rays):
 *   exact    the program evaluated with q.eps = 1e6, which makes every bounding sphere's skip
 *            margin (1.25 r + band + 4 eps) larger than the scene, so it evaluates the whole
 *            tree: |naive - program| <= TOL(p, d) at every point;
 *   bounded  the program as the tracers call it (q.eps = the default 1e-4): where it reports a
 *            material (>= 0) it equals the exact value within TOL; where it reports -1 (a
 *            bounding sphere stood in) its value is a lower bound: <= naive + TOL. In the
 *            fractals scene only at points within NEAR of a surface: the Menger sponge and
 *            the Mandelbulb are distance estimators, not distances, and the distance to a
 *            bounding sphere is no lower bound of an estimate (nor is the bounded program
 *            the full one far from the surfaces: 90 of 72367 points differ there);
 *   material where the point is within NEAR of a surface (|d| < NEAR) the naive material
 *            equals the program's (which is >= 0 there).
 * TOL(p, d) = 8 FLT_EPSILON (|d| + |p| + 1), relative to the size of the point (|p|, in scene
 * units) and to |d|: both sides run the same float formulas in the same order, so they can
 * differ only where the rounding of the point's coordinates differs, and a translation or
 * rotation of a point of size |p| rounds at ulp(|p|), an absolute error that the distance
 * computed from it inherits whatever |d| is (plus the same factor of |d| for the rounding of
 * the distance itself). Measured: bit-identical in the libm build (worst 0 TOL); in the
 * FOV_NO_LIBM build the library's rotation matrices come from its own cosf/sinf, an ulp off
 * the constants in sdf_naive.h, worst 0.1 TOL (temple). TOL is 9.5e-7 near the origin and
 * 4e-4 at the temple's horizon (400 units).
 * Each scene also checks that the checks saw enough: at least 2000 points with a material and
 * 500 near a surface. Changing any parameter of a naive scene (e.g. the primitives' sphere
 * radius 0.5 -> 0.5001) makes its exact check fail.
 */
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

/* sin, cos, atan2, pow and log appear only in the mandelbulb and the terrain, which use the
   library's own float kernels in every build: the naive scenes call them too */
#define NAIVE_SQRTF(x) fovtest_sqrt(x)
#define NAIVE_FLOORF(x) fovtest_floor(x)
#define NAIVE_SINF(x) fovtest_sdf_ksin1(x)
#define NAIVE_COSF(x) fovtest_sdf_kcos(x)
#define NAIVE_ATAN2F(y, x) fovtest_sdf_katan2(y, x)
#define NAIVE_POWF(x, y) fovtest_sdf_kpow(x, y)
#define NAIVE_LOGF(x) fovtest_sdf_klog(x)
#include "../bench/sdf_naive.h"

#include <stdlib.h>
#include <string.h>

#define NEAR 1e-3f
#define NRAND 20000
#define RAYS_X 64
#define RAYS_Y 36

static float tol_of(const float p[3], float d)
{
    float a = d < 0.0f ? -d : d;
    return 8.0f * FLT_EPSILON * (a + fovtest_len(p) + 1.0f);
}

static uint32_t rng_next(uint32_t *s)
{
    *s ^= *s << 13; *s ^= *s >> 17; *s ^= *s << 5;
    return *s;
}
static float rng_u01(uint32_t *s) { return (float)(rng_next(s) >> 8) * (1.0f / 16777216.0f); }

typedef struct acc_t {
    long n, n_mat, n_near, bad_exact, bad_bound, bad_lower, bad_mat;
    float worst_exact, worst_bound, worst_lower; /* in units of TOL */
    float wp[3], wd_naive, wd_prog;             /* the worst exact point */
    int32_t mat_naive, mat_prog;
    float mp[3];
} acc_t;

static float eval_prog(const fovsdf_program *prog, const float p[3], float eps, int32_t *mat)
{
    fovsdf_query q;
    float d;
    memset(&q, 0, sizeof q);
    q.inflate = 1.0f; q.eps = eps; q.want_material = 1;
    d = fovsdf_program_eval(p, &q, (void *)(uintptr_t)prog);
    *mat = q.material;
    return d;
}

static void point(acc_t *a, naive_fn fn, const fovsdf_program *prog, const float p[3], int de)
{
    int32_t mn = -7, mx, mb;
    float dn = fn(p, &mn), dx = eval_prog(prog, p, 1e6f, &mx), db, tol, r;
    db = eval_prog(prog, p, 1e-4f, &mb);
    tol = tol_of(p, dn);
    a->n++;
    r = fovtest_absf(dn - dx) / tol;
    if (!(r <= 1.0f)) a->bad_exact++;
    if (!(r <= a->worst_exact)) {
        a->worst_exact = r;
        a->wp[0] = p[0]; a->wp[1] = p[1]; a->wp[2] = p[2]; a->wd_naive = dn; a->wd_prog = dx;
    }
    if (de && !(fovtest_absf(dn) < NEAR)) {
        /* distance estimators: a bound is no lower bound of them (see the header) */
    } else if (mb >= 0) {
        a->n_mat++;
        r = fovtest_absf(dn - db) / tol;
        if (!(r <= 1.0f)) a->bad_bound++;
        if (r > a->worst_bound) a->worst_bound = r;
    } else {
        r = (db - dn) / tol;
        if (!(r <= 1.0f)) a->bad_lower++;
        if (r > a->worst_lower) a->worst_lower = r;
    }
    if (fovtest_absf(dn) < NEAR) {
        a->n_near++;
        if (mn != mb || mn != mx) {
            if (a->bad_mat == 0) {
                a->mat_naive = mn; a->mat_prog = mb;
                a->mp[0] = p[0]; a->mp[1] = p[1]; a->mp[2] = p[2];
            }
            a->bad_mat++;
        }
    }
}

/* sphere-trace camera rays with the exact program; every step, and points around each hit */
static void rays(acc_t *a, naive_fn fn, const fovsdf_builtin *bi, int de)
{
    fovsdf_ctx ctx;
    fovsdf_config cfg = fovsdf_config_default();
    fov_gaze g;
    int i, j, k, s;
    g.x = 0.5f * (float)bi->camera.width; g.y = 0.5f * (float)bi->camera.height;
    if (fovsdf_init(&ctx, &cfg, &bi->scene, &bi->camera, g, NULL, 0) != FOV_OK) return;
    for (j = 0; j < RAYS_Y; ++j)
        for (i = 0; i < RAYS_X; ++i) {
            float ro[3], rd[3], t = 0.0f, p[3];
            int32_t m;
            fovsdf_camera_ray(&ctx, ((float)i + 0.5f) * (float)bi->camera.width / RAYS_X,
                              ((float)j + 0.5f) * (float)bi->camera.height / RAYS_Y, ro, rd);
            for (s = 0; s < 512 && t < ctx.t_max; ++s) {
                float d;
                for (k = 0; k < 3; ++k) p[k] = ro[k] + rd[k] * t;
                point(a, fn, bi->program, p, de);
                d = eval_prog(bi->program, p, 1e6f, &m);
                if (d < 1e-4f * (1.0f + t)) {
                    static const float off[6] = { -3e-3f, -1e-3f, -3e-4f, 3e-4f, 1e-3f, 3e-3f };
                    int o;
                    for (o = 0; o < 6; ++o) {
                        for (k = 0; k < 3; ++k) p[k] = ro[k] + rd[k] * (t + off[o] * (1.0f + t));
                        point(a, fn, bi->program, p, de);
                    }
                    break;
                }
                t += d;
            }
        }
}

int main(void)
{
    uint32_t id;
    for (id = 0; id < (uint32_t)_FOVSDF_SCENE_NUM; ++id) {
        fovsdf_builtin bi;
        size_t sz = 0;
        void *mem = NULL;
        naive_fn fn = naive_scene(id);
        acc_t a;
        uint32_t seed = 0x9e3779b9u ^ (id * 7919u + 1u);
        float c[3], r;
        int i, k;
        const char *nm = fovsdf_builtin_name(id);
        int de = id == FOVSDF_SCENE_FRACTALS;
        memset(&a, 0, sizeof a);
        if (!check(fovsdf_builtin_size(id, &sz) == FOV_OK && (mem = malloc(sz)) != NULL &&
                       fovsdf_builtin_init(id, &bi, mem, sz) == FOV_OK && fn != NULL,
                   fovcheck_name("%s: built-in scene and naive function", nm), "init failed"))
            continue;
        {
            float v[3];
            for (k = 0; k < 3; ++k) {
                c[k] = bi.camera.target[k];
                v[k] = bi.camera.pos[k] - bi.camera.target[k];
            }
            r = 1.5f * fovtest_len(v);
        }
        for (i = 0; i < NRAND; ++i) {
            float p[3];
            for (k = 0; k < 3; ++k) p[k] = c[k] + r * (2.0f * rng_u01(&seed) - 1.0f);
            point(&a, fn, bi.program, p, de);
        }
        rays(&a, fn, &bi, de);
        check(a.bad_exact == 0, fovcheck_name("%s: naive = full program within TOL", nm),
              "%ld of %ld points differ; worst %.3g TOL at (%.6g, %.6g, %.6g): naive %.9g, "
              "program %.9g", a.bad_exact, a.n, (double)a.worst_exact, (double)a.wp[0],
              (double)a.wp[1], (double)a.wp[2], (double)a.wd_naive, (double)a.wd_prog);
        check(a.bad_bound == 0,
              fovcheck_name("%s: bounded program = naive where it reports a material", nm),
              "%ld of %ld differ, worst %.3g TOL", a.bad_bound, a.n_mat, (double)a.worst_bound);
        check(a.bad_lower == 0,
              fovcheck_name("%s: bounded program <= naive where a bound stood in", nm),
              "%ld of %ld above, worst %.3g TOL", a.bad_lower, a.n - a.n_mat,
              (double)a.worst_lower);
        check(a.bad_mat == 0, fovcheck_name("%s: materials agree near surfaces", nm),
              "%ld of %ld differ; first at (%.6g, %.6g, %.6g): naive %d, program %d", a.bad_mat,
              a.n_near, (double)a.mp[0], (double)a.mp[1], (double)a.mp[2], (int)a.mat_naive,
              (int)a.mat_prog);
        check(a.n_mat >= 2000 && a.n_near >= 500, fovcheck_name("%s: coverage", nm),
              "%ld points with a material, %ld near a surface", a.n_mat, a.n_near);
        fovcheck_info("%s: %ld points, %ld with a material, %ld within %g of a surface; worst "
                      "|naive - program| %.3g TOL (full), %.3g TOL (bounded)", nm, a.n, a.n_mat,
                      a.n_near, (double)NEAR, (double)a.worst_exact, (double)a.worst_bound);
        free(mem);
    }
    return fovcheck_summary();
}
