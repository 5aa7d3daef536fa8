/*
 * test_fovpt_mirror.c - fovpt's next-event estimation through mirrors (cfg.mirror_nee, NEXT-EVENT
 * ESTIMATION THROUGH MIRRORS in fovpt.h).
 *
 * Build and run from the repository root (tests/run_all.sh builds it three ways):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovpt_mirror.c -lm -o build/tests/t
 *
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed".
 * Independent checks: the radiance a Lambert point receives through a mirror sphere and through
 * a mirror quad is integrated here in double over its hemisphere (4M cosine-weighted directions,
 * each traced against the sphere or quad and the light in closed form) and compared with the
 * mean of fovpt_radiance with cfg.mirror_nee on and off; the reflection points are checked
 * against the reflection law directly; a point inside a mirror sphere (which the estimator does
 * not cover) compares on against off.
 */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

typedef struct world {
    fovpt_shape shapes[4];
    fovpt_material mats[4];
    uint32_t ns;
    fovpt_scene sc;
    void *mem;
} world;

/* materials: 0 floor Lambert 0.5, 1 mirror (0.9, 0.8, 0.7), 2 light (10, 10, 10) */
static const double FLOOR_ALB = 0.5, MIR[3] = { 0.9, 0.8, 0.7 }, LE = 10.0;
static void mats(world *w)
{
    uint32_t k;
    for (k = 0; k < 3; ++k) fovpt_material_init(&w->mats[k]);
    w->mats[0].type = FOVPT_MAT_LAMBERT;
    w->mats[0].albedo[0] = w->mats[0].albedo[1] = w->mats[0].albedo[2] = (float)FLOOR_ALB;
    w->mats[1].type = FOVPT_MAT_MIRROR;
    for (k = 0; k < 3; ++k) w->mats[1].albedo[k] = (float)MIR[k];
    w->mats[2].type = FOVPT_MAT_LAMBERT;
    w->mats[2].albedo[0] = w->mats[2].albedo[1] = w->mats[2].albedo[2] = 0.0f;
    w->mats[2].emission[0] = w->mats[2].emission[1] = w->mats[2].emission[2] = (float)LE;
}
static int build(world *w)
{
    fovpt_scene_desc d;
    size_t n = 0;
    memset(&d, 0, sizeof d);
    d.shapes = w->shapes; d.num_shapes = w->ns;
    d.materials = w->mats; d.num_materials = 3;
    if (fovpt_scene_size(&d, &n) != FOV_OK) return 0;
    w->mem = malloc(n + 16u);
    return w->mem && fovpt_scene_build(&w->sc, &d, w->mem, n) == FOV_OK;
}

/* the light: the quad LC + a LU + b LV (two-sided); small: x = 2, y in [0.5, 1.5], z in [-0.5, 0.5];
   large (where the mirror bounce's own sampling competes: the weights of both matter): x = 1.6,
   y in [0, 4], z in [-3, 3] */
static double LC[3], LU[3], LV[3];
static void set_light(int large, float lc[3], float lu[3], float lv[3])
{
    static const double sc[3] = { 2.0, 0.5, -0.5 }, su[3] = { 0.0, 1.0, 0.0 }, sv[3] = { 0.0, 0.0, 1.0 };
    static const double bc[3] = { 1.6, 0.0, -3.0 }, bu[3] = { 0.0, 4.0, 0.0 }, bv[3] = { 0.0, 0.0, 6.0 };
    int k;
    for (k = 0; k < 3; ++k) {
        LC[k] = large ? bc[k] : sc[k]; LU[k] = large ? bu[k] : su[k]; LV[k] = large ? bv[k] : sv[k];
        lc[k] = (float)LC[k]; lu[k] = (float)LU[k]; lv[k] = (float)LV[k];
    }
}
static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
/* t of ray o + t d through the parallelogram c + a u + b v (a, b in [0, 1]), or -1 */
static double hit_quad(const double o[3], const double d[3], const double c[3], const double u[3], const double v[3])
{
    double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] }, dn = dot3(d, n), t, q[3],
           a, b, uu = dot3(u, u), vv = dot3(v, v), uv = dot3(u, v), det;
    double oc[3] = { c[0] - o[0], c[1] - o[1], c[2] - o[2] };
    if (fabs(dn) < 1e-15) return -1.0;
    t = dot3(oc, n) / dn;
    if (!(t > 1e-9)) return -1.0;
    q[0] = o[0] + t * d[0] - c[0]; q[1] = o[1] + t * d[1] - c[1]; q[2] = o[2] + t * d[2] - c[2];
    det = uu * vv - uv * uv;
    a = (dot3(q, u) * vv - dot3(q, v) * uv) / det;
    b = (dot3(q, v) * uu - dot3(q, u) * uv) / det;
    return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0 ? t : -1.0;
}
static double hit_sphere(const double o[3], const double d[3], const double c[3], double r)
{
    double oc[3] = { o[0] - c[0], o[1] - c[1], o[2] - c[2] }, b = dot3(oc, d), cc = dot3(oc, oc) - r * r, disc = b * b - cc, t;
    if (disc < 0.0) return -1.0;
    t = -b - sqrt(disc);
    return t > 1e-9 ? t : -1.0; /* from outside only: the cases here start outside */
}
/* irradiance weight per channel at x (normal +y) in double: direct light and light through the
   mirror (sphere: c, r > 0; quad: mc, mu, mv with r = 0), cosine-weighted over n x n directions;
   returns E (per channel) and the part through the mirror in Em */
static void brute(const double x[3], const double c[3], double r, const double mc[3], const double mu[3], const double mv[3],
                  int n, double E[3], double Em[3])
{
    int i, j, k;
    double sd = 0.0, sm[3] = { 0, 0, 0 };
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            double u1 = (i + 0.5) / n, u2 = (j + 0.5) / n, s = sqrt(u1), ph = 2.0 * 3.14159265358979323846 * u2;
            double d[3] = { s * cos(ph), sqrt(1.0 - u1), s * sin(ph) }, tl = hit_quad(x, d, LC, LU, LV), tm, p[3], nn[3], rd[3],
                   dn, tl2;
            tm = r > 0.0 ? hit_sphere(x, d, c, r) : hit_quad(x, d, mc, mu, mv);
            if (tl > 0.0 && (tm < 0.0 || tl < tm)) { sd += 1.0; continue; }
            if (tm < 0.0) continue;
            for (k = 0; k < 3; ++k) p[k] = x[k] + tm * d[k];
            if (r > 0.0) for (k = 0; k < 3; ++k) nn[k] = (p[k] - c[k]) / r;
            else {
                nn[0] = mu[1] * mv[2] - mu[2] * mv[1]; nn[1] = mu[2] * mv[0] - mu[0] * mv[2]; nn[2] = mu[0] * mv[1] - mu[1] * mv[0];
                dn = sqrt(dot3(nn, nn));
                for (k = 0; k < 3; ++k) nn[k] /= dn;
            }
            dn = dot3(d, nn);
            for (k = 0; k < 3; ++k) rd[k] = d[k] - 2.0 * dn * nn[k];
            tl2 = hit_quad(p, rd, LC, LU, LV);
            if (tl2 > 0.0)
                for (k = 0; k < 3; ++k) sm[k] += MIR[k];
        }
    for (k = 0; k < 3; ++k) {
        Em[k] = 3.14159265358979323846 * LE * sm[k] / ((double)n * n);
        E[k] = 3.14159265358979323846 * LE * sd / ((double)n * n) + Em[k];
    }
}

/* mean and variance (per channel) of ns fovpt_radiance samples of the ray o, d */
static void sample(const world *w, int mnee, const float o[3], const float d[3], uint32_t ns, double mean[3], double var[3])
{
    fovpt_config c = fovpt_config_default();
    fovpt_stats st;
    double s1[3] = { 0, 0, 0 }, s2[3] = { 0, 0, 0 };
    uint32_t i, k;
    c.max_depth = 2; c.mirror_nee = (uint32_t)mnee; c.rr_start = FOVPT_RR_OFF;
    memset(&st, 0, sizeof st);
    for (i = 0; i < ns; ++i) {
        fovpt_rng r;
        float L[3];
        fovpt_rng_init(&r, 7u + (uint32_t)mnee, i, 0u, 0u);
        if (fovpt_radiance(&w->sc, &c, o, d, &r, L, &st) != FOV_OK) L[0] = L[1] = L[2] = -1e9f;
        for (k = 0; k < 3; ++k) { s1[k] += (double)L[k]; s2[k] += (double)L[k] * (double)L[k]; }
    }
    for (k = 0; k < 3; ++k) {
        mean[k] = s1[k] / ns;
        var[k] = s2[k] / ns - mean[k] * mean[k];
    }
}

/* x on the floor seen by the ray o, d: on and off against the double-precision integral */
static void mirror_case(const char *name, world *w, const double x[3], const float o[3], const float d[3], const double c[3],
                        double r, const double mc[3], const double mu[3], const double mv[3], int large)
{
    double E[3], Em[3], mon[3], von[3], moff[3], voff[3];
    int k, ok_on = 1, ok_off = 1;
    const uint32_t ns = 200000u;
    brute(x, c, r, mc, mu, mv, 2048, E, Em);
    check(Em[1] > 0.05 * E[1], N("mirror_%s_case_is_lit_through_the_mirror", name), "through the mirror %.4g of %.4g", Em[1], E[1]);
    sample(w, 1, o, d, ns, mon, von);
    sample(w, 0, o, d, ns, moff, voff);
    for (k = 0; k < 3; ++k) {
        double want = FLOOR_ALB / 3.14159265358979323846 * E[k];
        if (!(fabs(mon[k] - want) <= 4.0 * sqrt(von[k] / ns) + 3e-3 * want)) ok_on = 0;
        if (!(fabs(moff[k] - want) <= 4.0 * sqrt(voff[k] / ns) + 3e-3 * want)) ok_off = 0;
    }
    check(ok_on, N("mirror_%s_on_equals_the_integral", name), "on %.5f %.5f %.5f, integral %.5f %.5f %.5f (sd of mean %.2g)", mon[0],
          mon[1], mon[2], FLOOR_ALB / 3.14159265358979323846 * E[0], FLOOR_ALB / 3.14159265358979323846 * E[1],
          FLOOR_ALB / 3.14159265358979323846 * E[2], sqrt(von[1] / ns));
    check(ok_off, N("mirror_%s_off_equals_the_integral", name), "off %.5f %.5f %.5f, integral %.5f (sd of mean %.2g)", moff[0],
          moff[1], moff[2], FLOOR_ALB / 3.14159265358979323846 * E[1], sqrt(voff[1] / ns));
    if (!large) /* a small light: the connection is the better estimator by far */
        check(von[1] < 0.25 * voff[1], N("mirror_%s_on_has_a_quarter_of_the_variance_or_less", name), "variance on %.4g off %.4g",
              von[1], voff[1]);
    else /* a large one: the weights keep the better of the two; no worse than without */
        check(von[1] < voff[1], N("mirror_%s_on_has_no_more_variance", name), "variance on %.4g off %.4g", von[1], voff[1]);
    fovcheck_info("mirror %s: E %.4f (through the mirror %.4f); variance on %.4g off %.4g", name, E[1], Em[1], von[1], voff[1]);
}

/* a floor point lit through a mirror sphere (quad 0) or a mirror quad (quad 1), by the small or
   the large light */
static void test_through_mirror(int quad, int large)
{
    world w;
    const double x[3] = { 0.8, 0.0, 0.2 }, c[3] = { 0.0, 1.2, 0.0 }, mc[3] = { -1.0, 0.0, -1.0 }, mu[3] = { 3.5, 0.0, 0.0 },
                 mv[3] = { 0.0, 2.0, 0.0 };
    const float o[3] = { 0.8f, 2.0f, 2.2f }, d[3] = { 0.0f, -1.0f, -1.0f }, pt[3] = { 0, 0, 0 }, up[3] = { 0, 1, 0 },
                fc[3] = { -1.0f, 0.0f, -1.0f }, fu[3] = { 3.5f, 0.0f, 0.0f }, fv[3] = { 0.0f, 2.0f, 0.0f };
    const char *nm = quad ? (large ? "quad_large_light" : "quad") : (large ? "sphere_large_light" : "sphere");
    float lc[3], lu[3], lv[3];
    set_light(large, lc, lu, lv);
    memset(&w, 0, sizeof w);
    mats(&w);
    fovpt_shape_plane(&w.shapes[0], pt, up, 0);
    if (quad) fovpt_shape_quad(&w.shapes[1], fc, fu, fv, 1);
    else fovpt_shape_sphere(&w.shapes[1], 0.0f, 1.2f, 0.0f, 1.0f, 1);
    fovpt_shape_quad(&w.shapes[2], lc, lu, lv, 2);
    w.ns = 3;
    if (!check(build(&w), N("mirror_%s_scene_builds", nm), "fovpt_scene_build failed")) return;
    check(w.sc.num_mirrors == 1u &&
              ((const fovpt__prim *)w.sc.prims)[w.sc.mirrors[0]].type == (quad ? FOVPT_SHAPE_QUAD : FOVPT_SHAPE_SPHERE),
          N("mirror_%s_scene_lists_the_mirror", nm), "num_mirrors %u", w.sc.num_mirrors);
    if (quad) mirror_case(nm, &w, x, o, d, NULL, 0.0, mc, mu, mv, large);
    else mirror_case(nm, &w, x, o, d, c, 1.0, NULL, NULL, NULL, large);
    free(w.mem);
}

/* a point inside a mirror sphere: the estimator does not cover it; on and off agree */
static void test_inside_sphere(void)
{
    world w;
    const float o[3] = { 0.3f, 1.0f, 0.9f }, d[3] = { 0.0f, -1.0f, -0.5f }, fc[3] = { -1.0f, -1.0f, -1.0f },
                fu[3] = { 2.0f, 0.0f, 0.0f }, fv[3] = { 0.0f, 0.0f, 2.0f }, lc[3] = { -0.25f, 2.0f, -0.25f },
                lu[3] = { 0.5f, 0, 0 }, lv[3] = { 0, 0, 0.5f };
    double mon[3], von[3], moff[3], voff[3], z;
    memset(&w, 0, sizeof w);
    mats(&w);
    fovpt_shape_sphere(&w.shapes[0], 0.0f, 0.0f, 0.0f, 3.0f, 1);
    fovpt_shape_quad(&w.shapes[1], fc, fu, fv, 0);
    fovpt_shape_quad(&w.shapes[2], lc, lu, lv, 2);
    w.ns = 3;
    if (!check(build(&w), "mirror_inside_scene_builds", "fovpt_scene_build failed")) return;
    sample(&w, 1, o, d, 200000u, mon, von);
    sample(&w, 0, o, d, 200000u, moff, voff);
    z = fabs(mon[1] - moff[1]) / sqrt((von[1] + voff[1]) / 200000.0);
    check(z < 4.5 && moff[1] > 0.0, "mirror_inside_a_sphere_on_equals_off",
          "on %.5f off %.5f (%.1f standard errors apart)", mon[1], moff[1], z);
    free(w.mem);
}

/* the reflection points against the reflection law (random spheres, points and quads) */
static void test_reflection_law(void)
{
    uint32_t i, k, found = 0, bad = 0, nq = 0, badq = 0;
    fovpt_rng r;
    fovpt_rng_init(&r, 3u, 0u, 0u, 0u);
    for (i = 0; i < 20000u; ++i) {
        fovpt__prim p;
        float x[3], y[3], q[3], n[3], g, wx[3], wy[3], a, b, cr[3];
        memset(&p, 0, sizeof p);
        p.type = FOVPT_SHAPE_SPHERE;
        for (k = 0; k < 3; ++k) {
            p.a[k] = 10.0f * fovpt_rng_next(&r) - 5.0f;
            x[k] = 20.0f * fovpt_rng_next(&r) - 10.0f;
            y[k] = 20.0f * fovpt_rng_next(&r) - 10.0f;
        }
        p.r = 0.05f + 3.0f * fovpt_rng_next(&r);
        if (!fovpt__mirror_point(&p, x, y, q, n, &g)) continue;
        ++found;
        fovpt__sub3(wx, x, q); fovpt__sub3(wy, y, q);
        fov__normalize(wx); fov__normalize(wy);
        a = fov__dot(wx, n); b = fov__dot(wy, n);
        fov__cross(wx, wy, cr);
        if (a < 0.01f && b < 0.01f) continue; /* grazing (above 89.4 degrees): float cannot tell */
        { /* on the sphere, equal angles, n in the plane of wx and wy, g positive */
            float dq[3];
            fovpt__sub3(dq, q, p.a);
            if (!(fabsf(fov__len(dq) - p.r) <= 1e-5f * (p.r + fov__len(p.a))) || !(fabsf(a - b) <= 2e-5f) ||
                !(fabsf(fov__dot(cr, n)) <= 2e-5f) || !(g > 0.0f)) {
                if (bad < 5u)
                    fovcheck_info("sphere r %g at %g %g %g, x %g %g %g, y %g %g %g: |q - c| - r %g, cos %g %g, coplanar %g",
                                  (double)p.r, (double)p.a[0], (double)p.a[1], (double)p.a[2], (double)x[0], (double)x[1],
                                  (double)x[2], (double)y[0], (double)y[1], (double)y[2], (double)(fov__len(dq) - p.r), (double)a,
                                  (double)b, (double)fov__dot(cr, n));
                ++bad;
            }
        }
    }
    check(found > 2000u && bad == 0, "mirror_sphere_points_obey_the_reflection_law", "%u of %u wrong", bad, found);
    for (i = 0; i < 20000u; ++i) { /* quads: against the mirrored point */
        fovpt__prim p;
        float x[3], y[3], q[3], n[3], g, u[3], v[3], c[3], yr[3], sy, d2[3], e;
        memset(&p, 0, sizeof p);
        p.type = FOVPT_SHAPE_QUAD;
        for (k = 0; k < 3; ++k) {
            c[k] = 4.0f * fovpt_rng_next(&r) - 2.0f;
            u[k] = 4.0f * fovpt_rng_next(&r) - 2.0f;
            v[k] = 4.0f * fovpt_rng_next(&r) - 2.0f;
            x[k] = 8.0f * fovpt_rng_next(&r) - 4.0f;
            y[k] = 8.0f * fovpt_rng_next(&r) - 4.0f;
        }
        fovpt__copy3(p.a, c); fovpt__copy3(p.b, u); fovpt__copy3(p.c, v);
        fovpt__unit_normal(u, v, p.n);
        if (!fovpt__mirror_point(&p, x, y, q, n, &g)) continue;
        ++nq;
        sy = fov__dot(y, p.n) - fov__dot(c, p.n);
        fovpt__madd3(yr, y, -2.0f * sy, p.n);
        fovpt__sub3(d2, yr, x);
        e = fabsf(g * fov__dot(d2, d2) - 1.0f);
        { /* q on the segment x y' and in the plane */
            float t1[3], t2[3], cr[3];
            fovpt__sub3(t1, q, x); fovpt__sub3(t2, yr, x);
            fov__cross(t1, t2, cr);
            if (!(e <= 1e-5f) || !(fov__len(cr) <= 1e-4f * fov__dot(t2, t2)) ||
                !(fabsf(fov__dot(q, p.n) - fov__dot(c, p.n)) <= 1e-4f))
                ++badq;
        }
    }
    check(nq > 500u && badq == 0, "mirror_quad_points_on_the_mirrored_segment_g_1_over_d2", "%u of %u wrong", badq, nq);
}

/* a scene without mirror spheres or quads (a mirror box, a Lambert sphere): on == off bit for
   bit (no random numbers drawn), and a bad value is an error */
static void test_no_targets(void)
{
    world w;
    const float lo[3] = { -0.5f, 0.0f, -0.5f }, hi[3] = { 0.5f, 1.0f, 0.5f }, lc[3] = { 2.0f, 0.5f, -0.5f },
                lu[3] = { 0, 1, 0 }, lv[3] = { 0, 0, 1 }, pt[3] = { 0, 0, 0 }, up[3] = { 0, 1, 0 };
    fovpt_camera cam;
    fov_gaze gz;
    fovpt_config c = fovpt_config_default(), r;
    float *a, *b;
    int same = 1, t;
    memset(&w, 0, sizeof w);
    mats(&w);
    fovpt_shape_box(&w.shapes[0], lo, hi, 1);
    fovpt_shape_sphere(&w.shapes[1], -1.5f, 0.5f, 0.0f, 0.5f, 0);
    fovpt_shape_quad(&w.shapes[2], lc, lu, lv, 2);
    fovpt_shape_plane(&w.shapes[3], pt, up, 0);
    w.ns = 4;
    if (!check(build(&w), "mirror_no_targets_scene_builds", "fovpt_scene_build failed")) return;
    check(w.sc.num_mirrors == 0u, "mirror_box_is_not_a_target", "num_mirrors %u", w.sc.num_mirrors);
    fovpt_camera_init(&cam, 24, 16);
    cam.pos[0] = 0.0f; cam.pos[1] = 2.0f; cam.pos[2] = 5.0f;
    cam.target[0] = 0.0f; cam.target[1] = 0.5f; cam.target[2] = 0.0f;
    gz.x = 12.0f; gz.y = 8.0f;
    a = (float *)calloc(24u * 16u * 3u, 4u);
    b = (float *)calloc(24u * 16u * 3u, 4u);
    for (t = 0; t < 2; ++t) {
        fovpt_ctx ctx;
        fovpt_output out;
        size_t n = 0;
        void *mem;
        c.spp = 8; c.mirror_nee = (uint32_t)t;
        if (fovpt_memory_size(&c, &cam, &n) != FOV_OK) { same = 0; break; }
        mem = malloc(n + 16u);
        fovpt_output_init(&out);
        out.rgb = t ? b : a;
        if (fovpt_init(&ctx, &c, &w.sc, &cam, gz, mem, n) != FOV_OK || fovpt_render(&ctx, 0, &out, NULL) != FOV_OK) same = 0;
        free(mem);
    }
    check(same && memcmp(a, b, 24u * 16u * 12u) == 0, "mirror_nee_without_targets_is_bit_identical", "images differ");
    c.mirror_nee = 2;
    check(fovpt_config_resolve(&c, &r) == FOV_ERR_INVALID_ARG, "mirror_nee_2_is_an_error", "accepted");
    free(a); free(b);
    free(w.mem);
}

int main(void)
{
    test_reflection_law();
    test_through_mirror(0, 0);
    test_through_mirror(0, 1);
    test_through_mirror(1, 0);
    test_through_mirror(1, 1);
    test_inside_sphere();
    test_no_targets();
    return fovcheck_summary();
}
