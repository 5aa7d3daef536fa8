/* fuzz_fovpt.c - libFuzzer harness of fovpt.h (conventions: tests/fuzz/fuzz_common.h).

   From the bytes: a small mesh (1 .. 64 triangles: hostile floats, NaN vertices, degenerate
   triangles, coordinates from 1e-3 to 1e5 scale, grid-snapped and axis-aligned flat
   geometry, shared edges) plus a few shapes, built into caller memory with canaries after
   every buffer. Then:
   - rays from the bytes (aimed at triangle points, edges and vertices, along axes, in
     planes, with a component of 2^-100 .. 2^-145, raw): fovpt_intersect / fovpt_occluded against the library's brute force
     (exact: the BVH runs the same per-primitive tests, so its hits are a subset of brute
     force's: a BVH hit implies a brute-force hit no farther away) and against an
     independent double-precision Moller-Trumbore over the input triangles (a hit clearly
     inside a triangle, barycentric margin 1e-4, not grazing, must be found by the BVH, by
     fovpt_occluded and by brute force, no farther than it);
   - every hit: t in (tmin, tmax), finite point, unit normal;
   - camera rays (fovpt_camera_ray) from hostile cameras and image points: FOV_OK means a
     finite unit direction from the camera position;
   - a small render (<= 12 x 12, UNIFORM / LAYERS / ZONES / SELECTIVE / JIN, path or
     Whitted, temporal reuse and smoothing from the bytes) over 1 .. 3 frames with
     fovpt_set_view between them, odd row splits and strides: FOV_OK or a documented error
     code, finite outputs, canaries and stride padding intact.
   Each input runs in well under 5 ms. */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "fuzz_common.h"
#include <math.h>

#define FZ_MAX_TRIS 64u
#define FZ_PAD 0x5Au

static int fz_code_ok(fov_result r) { return r <= FOV_OK && r >= FOV_ERR_UNSUPPORTED; }

/* a coordinate: hostile (fz_float), or a grid value (multiples of scale / 4) */
static float fz_coord(fz_in *in, float scale, float off)
{
    uint8_t s = fz_u8(in);
    if (s < 96) return off + scale * 0.25f * (float)((int)fz_pick(in, 33) - 16);
    if (s < 224) return off + fz_float(in, -4.0f * scale, 4.0f * scale);
    return fz_raw_float(in);
}

/* ---- independent reference: Moller-Trumbore in double over the input triangles -------- */
typedef struct fz_ref {
    int clear;      /* a hit with barycentric margin >= 1e-4, |cos| >= 1e-3, t well inside */
    double t_clear; /* the closest such hit */
} fz_ref;

static fz_ref fz_reference(const float *pos, uint32_t nt, const float o[3], const float d[3], float tmin, float tmax)
{
    fz_ref r;
    uint32_t i;
    double dl = 0.0, dd[3];
    int k;
    r.clear = 0; r.t_clear = 0.0;
    for (k = 0; k < 3; ++k) { dd[k] = (double)d[k]; dl += dd[k] * dd[k]; }
    /* the float envelope of the triangle test: coordinates and origins up to 1e12 (its
       products are cubes of the coordinates) */
    for (k = 0; k < 3; ++k) if (!(fabs((double)o[k]) <= 1e12)) return r;
    dl = dl > 0.0 ? dl : 1.0;
    for (i = 0; i < nt; ++i) {
        const float *v = pos + 9u * i;
        double e1[3], e2[3], s[3], pv[3], q[3], n[3], det, u, w, t, nl, cs, tol;
        int fin = 1;
        for (k = 0; k < 9; ++k) if (!fz_finite(v[k]) || !(fabs((double)v[k]) <= 1e12)) fin = 0;
        if (!fin) continue;
        for (k = 0; k < 3; ++k) {
            e1[k] = (double)v[3 + k] - (double)v[k];
            e2[k] = (double)v[6 + k] - (double)v[k];
            s[k] = (double)o[k] - (double)v[k];
        }
        pv[0] = dd[1] * e2[2] - dd[2] * e2[1]; pv[1] = dd[2] * e2[0] - dd[0] * e2[2]; pv[2] = dd[0] * e2[1] - dd[1] * e2[0];
        det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
        n[0] = e1[1] * e2[2] - e1[2] * e2[1]; n[1] = e1[2] * e2[0] - e1[0] * e2[2]; n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        nl = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (!(nl > 0.0) || !(nl < 1e300)) continue;
        cs = det * det / (nl * dl); /* cos^2 between the ray and the normal */
        if (!(cs > 1e-6)) continue; /* grazing (or degenerate): no claim */
        u = (s[0] * pv[0] + s[1] * pv[1] + s[2] * pv[2]) / det;
        q[0] = s[1] * e1[2] - s[2] * e1[1]; q[1] = s[2] * e1[0] - s[0] * e1[2]; q[2] = s[0] * e1[1] - s[1] * e1[0];
        w = (dd[0] * q[0] + dd[1] * q[1] + dd[2] * q[2]) / det;
        t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
        {   /* margin: 1e-4 plus a bound on the float test's rounding of u and w (products of
               |o| + |v0|, |d|, |e1| + |e2| over |det|) */
            double sa = 0.0, ea = 0.0, err;
            for (k = 0; k < 3; ++k) {
                sa += fabs((double)o[k]) + fabs((double)v[k]);
                ea += fabs(e1[k]) + fabs(e2[k]);
            }
            err = 64.0 * 6e-8 * sqrt(dl) * (sa + ea) * ea / fabs(det);
            if (!(u >= 1e-4 + err && w >= 1e-4 + err && u + w <= 1.0 - 1e-4 - err)) continue;
        }
        tol = 1e-4 * (t < 0.0 ? -t : t) + 1e-30;
        if (!(t > (double)tmin + tol + 1e-4 * (tmin < 0.0f ? -(double)tmin : (double)tmin) && t < (double)tmax - tol)) continue;
        /* nor closer to tmin or tmax than the float ray's own rounding (1e-5 |o| / |d|, the tolerance
           the caller's check allows): a float test cannot tell such a t from tmin (found:
           o = (-175000, -375000, -175000) on a triangle's plane to 0.001, its products of
           1e10 round the t to exactly 0, no hit after tmin 0) */
        {
            double om = 0.0;
            for (k = 0; k < 3; ++k) om = fabs((double)o[k]) > om ? fabs((double)o[k]) : om;
            if (!(t > (double)tmin + 1e-5 * om / sqrt(dl))) continue;
            if (!(t < (double)tmax - 1e-5 * om / sqrt(dl))) continue; /* the same at tmax */
        }
        /* far beyond float range of the geometry: the float test cannot resolve it */
        if (!(t < 1e30)) continue;
        if (!r.clear || t < r.t_clear) { r.clear = 1; r.t_clear = t; }
    }
    return r;
}

static void fz_check_hit(const fovpt_hit *h, float tmin, float tmax, const char *what)
{
    double nl = (double)h->n[0] * (double)h->n[0] + (double)h->n[1] * (double)h->n[1] + (double)h->n[2] * (double)h->n[2];
    FZ_CHECK(h->t > tmin && h->t < tmax, "%s: hit t %g outside (%g, %g)", what, (double)h->t, (double)tmin, (double)tmax);
    FZ_CHECK(fz_finite_n(h->n, 3) && nl > 0.999 && nl < 1.001, "%s: normal not unit (|n|^2 = %g)", what, nl);
}

static void fz_rays(fz_in *in, const fovpt_scene *s, const float *pos, uint32_t nt, uint32_t ns, float scale, float off, int shapes)
{
    uint32_t nr = 8u + fz_pick(in, 40), r;
    for (r = 0; r < nr && fz_left(in) > 0; ++r) {
        float o[3], d[3], tmin = 0.0f, tmax = FLT_MAX;
        uint32_t mode = fz_pick(in, 6), k;
        fovpt_hit h1, h2;
        int a1, a2, oc, in_box;
        fz_ref ref;
        for (k = 0; k < 3; ++k) o[k] = fz_coord(in, scale, off);
        if (mode <= 2 && nt > 0) { /* at a point of a triangle: barycentrics from bytes (edges, vertices) */
            const float *v = pos + 9u * fz_pick(in, nt);
            float b1 = (float)fz_pick(in, 5) * 0.25f, b2 = (float)fz_pick(in, 5) * 0.25f, tp[3];
            if (mode == 2) { b1 = fz_unit_range(in, 0.0f, 1.0f); b2 = fz_unit_range(in, 0.0f, 1.0f - b1); }
            if (b1 + b2 > 1.0f) b2 = 1.0f - b1;
            for (k = 0; k < 3; ++k) tp[k] = v[k] + b1 * (v[3 + k] - v[k]) + b2 * (v[6 + k] - v[k]);
            if (fz_u8(in) < 64) o[fz_pick(in, 3)] = tp[0]; /* sometimes in an axis plane of the point */
            for (k = 0; k < 3; ++k) d[k] = tp[k] - o[k];
        } else if (mode == 3) { /* along an axis */
            uint32_t ax = fz_pick(in, 3); /* read in this order (an assignment's operands are unsequenced) */
            d[0] = d[1] = d[2] = 0.0f;
            d[ax] = (fz_u8(in) & 1) ? -1.0f : 1.0f;
        } else if (mode == 4) { /* in an axis plane, grazing, or a tiny component */
            uint32_t ax, g;
            for (k = 0; k < 3; ++k) d[k] = fz_unit_range(in, -1.0f, 1.0f);
            ax = fz_pick(in, 3);
            g = fz_u8(in);
            /* 1 in 8: +-2^-100 .. 2^-145, around FLT_MIN (2^-126) and subnormal, whose
               reciprocal or margin product overflows (the brute-force route, NUMERICS) */
            if ((g & 7u) == 6u) {
                d[ax] = ldexpf((g & 128u) ? -1.0f : 1.0f, -100 - 3 * (int)((g >> 3) & 15u));
                /* and sometimes an origin as close to the plane ax = 0 (where grid and flat
                   triangles lie): the hit is then at a moderate t */
                if (fz_u8(in) < 128) o[ax] = ldexpf((fz_u8(in) & 1u) ? -1.0f : 1.0f, -100 - (int)fz_pick(in, 40));
            } else {
                d[ax] = (g & 1u) ? 0.0f : 1e-7f;
            }
        } else {
            for (k = 0; k < 3; ++k) d[k] = fz_float(in, -1.0f, 1.0f);
        }
        if (fz_u8(in) < 40) tmin = fz_float(in, -2.0f * scale, 2.0f * scale);
        if (fz_u8(in) < 60) tmax = fz_float(in, 0.0f, 8.0f * scale);
        a1 = fovpt_intersect(s, o, d, tmin, tmax, &h1);
        a2 = fovpt_intersect_brute(s, o, d, tmin, tmax, &h2);
        oc = fovpt_occluded(s, o, d, tmin, tmax);
        if (a1) fz_check_hit(&h1, tmin, tmax, "fovpt_intersect");
        if (a2) fz_check_hit(&h2, tmin, tmax, "fovpt_intersect_brute");
        /* the BVH tests a subset of brute force's primitives with the same arithmetic */
        FZ_CHECK(!a1 || (a2 && h1.t >= h2.t), "BVH hit (t %.9g) closer than brute force (%d, t %.9g)", (double)h1.t, a2,
                 a2 ? (double)h2.t : 0.0);
        FZ_CHECK(!oc || a2, "fovpt_occluded without a brute-force hit");
        FZ_CHECK(!a1 || oc, "fovpt_intersect hit (t %.9g, prim %u) but fovpt_occluded says free: o (%.9g %.9g %.9g) d (%.9g %.9g %.9g) tmin %.9g tmax %.9g",
                 (double)h1.t, h1.prim, (double)o[0], (double)o[1], (double)o[2], (double)d[0], (double)d[1], (double)d[2],
                 (double)tmin, (double)tmax);
        if (!fz_finite_n(o, 3) || !fz_finite_n(d, 3) || !fz_finite(tmin) || !fz_finite(tmax)) continue;
        /* brute force's triangle hit lies outside that triangle's bounding box (in double,
           1e-7 tolerance): a ray in the triangle's plane, whose t the float test cannot
           resolve (det near 0 but above its cut); the BVH's box test rightly culls it */
        in_box = 1;
        if (a2 && h2.prim >= ns && h2.prim - ns < nt) {
            const float *v = pos + 9u * (h2.prim - ns);
            for (k = 0; k < 3; ++k) {
                double lo = (double)v[k], hi = lo, P = (double)o[k] + (double)h2.t * (double)d[k], tol;
                lo = (double)v[3 + k] < lo ? (double)v[3 + k] : lo; lo = (double)v[6 + k] < lo ? (double)v[6 + k] : lo;
                hi = (double)v[3 + k] > hi ? (double)v[3 + k] : hi; hi = (double)v[6 + k] > hi ? (double)v[6 + k] : hi;
                tol = 1e-7 * ((lo < 0.0 ? -lo : lo) + (hi < 0.0 ? -hi : hi) + (P < 0.0 ? -P : P) + (hi - lo));
                if (P < lo - tol || P > hi + tol) in_box = 0;
            }
        }
        if (a2 && (!a1 || h1.t > h2.t) && h2.prim >= ns && h2.prim - ns < nt) {
            /* the BVH missed a brute-force triangle hit: a failure unless the hit point lies
               outside the triangle's bounding box (above) */
            FZ_CHECK(!in_box,
                     "BVH misses brute force's hit inside the triangle's box: o (%.9g %.9g %.9g) d (%.9g %.9g %.9g) tmin %g tmax %g: brute t %.9g (triangle %u), BVH %d t %.9g",
                     (double)o[0], (double)o[1], (double)o[2], (double)d[0], (double)d[1], (double)d[2], (double)tmin, (double)tmax,
                     (double)h2.t, h2.prim - ns, a1, a1 ? (double)h1.t : 0.0);
        }
        ref = fz_reference(pos, nt, o, d, tmin, tmax);
        if (ref.clear) {
            double om = 0.0, dl = 0.0, tol;
            for (k = 0; k < 3; ++k) {
                om = (o[k] < 0.0f ? -(double)o[k] : (double)o[k]) > om ? (o[k] < 0.0f ? -(double)o[k] : (double)o[k]) : om;
                dl += (double)d[k] * (double)d[k];
            }
            /* t rounds relative to itself and to |o| / |d| (the float ray's own rounding) */
            tol = 1e-3 * (ref.t_clear < 0.0 ? -ref.t_clear : ref.t_clear) + 1e-5 * (om + (double)scale) / (dl > 0.0 ? sqrt(dl) : 1.0);
            FZ_CHECK(a2 && (double)h2.t <= ref.t_clear + tol, "brute force misses a clear hit at t %.9g (got %d, %.9g): o (%.9g %.9g %.9g) d (%.9g %.9g %.9g) tmin %g tmax %g nt %u", ref.t_clear,
                     a2, a2 ? (double)h2.t : 0.0, (double)o[0], (double)o[1], (double)o[2], (double)d[0], (double)d[1], (double)d[2], (double)tmin, (double)tmax, nt);
            FZ_CHECK(a1 && (double)h1.t <= ref.t_clear + tol,
                     "BVH misses a clear hit: o (%.9g %.9g %.9g) d (%.9g %.9g %.9g) tmin %g tmax %g: reference t %.9g, BVH %d t %.9g, brute %.9g",
                     (double)o[0], (double)o[1], (double)o[2], (double)d[0], (double)d[1], (double)d[2], (double)tmin, (double)tmax,
                     ref.t_clear, a1, a1 ? (double)h1.t : 0.0, a2 ? (double)h2.t : 0.0);
            FZ_CHECK(oc, "fovpt_occluded misses a clear hit at t %.9g", ref.t_clear);
            /* with no shapes, the closest hit is a triangle: BVH = brute force exactly, unless
               brute force's hit is an in-plane one outside its triangle's box (above; its t
               comes before the clear hit: session 15's fuzz finding T15_inplane_hit.bin) */
            if (!shapes && in_box) FZ_CHECK(h1.t <= h2.t, "BVH t %.9g, brute force t %.9g", (double)h1.t, (double)h2.t);
        }
    }
}

/* camera rays: FOV_OK means a finite unit direction from the camera position */
static void fz_camera(fz_in *in, float scale)
{
    fovpt_camera cam;
    uint32_t i, k;
    uint32_t cw = fz_range_u32(in, 1u, 32u), ch = 1u + fz_pick(in, 32); /* sequenced reads */
    fovpt_camera_init(&cam, cw, ch);
    for (k = 0; k < 3; ++k) {
        cam.pos[k] = fz_float(in, -scale, scale);
        cam.target[k] = fz_float(in, -scale, scale);
        cam.up[k] = fz_float(in, -1.0f, 1.0f);
    }
    cam.fov_y_deg = fz_float(in, 0.0f, 180.0f);
    if (fz_u8(in) < 48) {
        cam.tan_left = fz_float(in, 0.0f, 4.0f); cam.tan_right = fz_float(in, 0.0f, 4.0f);
        cam.tan_bottom = fz_float(in, 0.0f, 4.0f); cam.tan_top = fz_float(in, 0.0f, 4.0f);
    }
    for (i = 0; i < 4; ++i) {
        float x = fz_float(in, -2.0f, 34.0f), y = fz_float(in, -2.0f, 34.0f), o[3], d[3];
        fov_result e = fovpt_camera_ray(&cam, x, y, o, d);
        FZ_CHECK(fz_code_ok(e), "fovpt_camera_ray: unknown code %d", (int)e);
        if (e == FOV_OK) {
            double l = (double)d[0] * (double)d[0] + (double)d[1] * (double)d[1] + (double)d[2] * (double)d[2];
            FZ_CHECK(fz_finite_n(d, 3) && l > 1.0 - 1e-5 && l < 1.0 + 1e-5,
                     "fovpt_camera_ray FOV_OK with |dir|^2 = %g (point %g %g)", l, (double)x, (double)y);
            FZ_CHECK(o[0] == cam.pos[0] && o[1] == cam.pos[1] && o[2] == cam.pos[2], "fovpt_camera_ray: origin is not the camera");
        }
    }
}

/* a small render over 1 .. 3 frames */
static void fz_render(fz_in *in, const fovpt_scene *s, float scale)
{
    fovpt_config cfg;
    fovpt_camera cam;
    fov_gaze gaze;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    size_t need = 0, rgb_n, rgb8_n;
    void *mem;
    float *rgb;
    uint8_t *rgb8;
    uint32_t W = 1u + fz_pick(in, 12), H = 1u + fz_pick(in, 12), frames = 1u + fz_pick(in, 3), f, k, rs, r8s;
    fov_result e;
    cfg = fovpt_config_default();
    cfg.method = fz_pick(in, 5);
    cfg.mode = fz_pick(in, 2);
    cfg.spp = 1u + fz_pick(in, 2);
    cfg.max_depth = fz_pick(in, 4);
    cfg.seed = fz_u32(in);
    cfg.accumulate = fz_pick(in, 2);
    cfg.no_nee = fz_pick(in, 2);
    cfg.temporal.reuse = fz_pick(in, 2);
    cfg.temporal.smooth = fz_pick(in, 2);
    if (fz_u8(in) < 16) cfg.spp = fz_u32(in); /* out of range sometimes */
    /* a valid but large spp (up to FOVPT_MAX_SPP) renders millions of samples: keep each input
       fast (libFuzzer's -timeout); the range check above FOVPT_MAX_SPP is still exercised */
    if (cfg.spp > 16u && cfg.spp <= FOVPT_MAX_SPP) cfg.spp = 16u;
    /* cfg.robust (ROBUST PIXEL ESTIMATE) from the seed, so the inputs' bytes keep their
       meaning: one seed in 8 takes 3 .. 17 groups (17: above FOVPT_ROBUST_MAX, an error),
       with 24 .. 55 spp so that it groups (at most 13 x 13 pixels, 3 frames: fast) */
    if ((cfg.seed & 7u) == 5u) {
        cfg.robust = 3u + (cfg.seed >> 3) % 15u;
        if (cfg.spp <= 16u) cfg.spp = 24u + (cfg.seed >> 8) % 32u;
    }
    /* cfg.mirror_nee from the seed too: one seed in 4 on (the scenes' mirror spheres and quads),
       one in 64 the invalid 2 (an error) */
    if ((cfg.seed & 0x30u) == 0x10u) cfg.mirror_nee = 1u;
    else if ((cfg.seed & 0x3F0u) == 0x220u) cfg.mirror_nee = 2u;
    fovpt_camera_init(&cam, W, H);
    for (k = 0; k < 3; ++k) { cam.pos[k] = fz_float(in, -3.0f * scale, 3.0f * scale); cam.target[k] = fz_float(in, -scale, scale); }
    cam.fov_y_deg = fz_unit_range(in, 10.0f, 120.0f);
    gaze.x = fz_float(in, -4.0f, (float)W + 4.0f);
    gaze.y = fz_float(in, -4.0f, (float)H + 4.0f);
    e = fovpt_memory_size(&cfg, &cam, &need);
    FZ_CHECK(fz_code_ok(e), "fovpt_memory_size: unknown code %d", (int)e);
    if (e != FOV_OK || need > ((size_t)64 << 20)) return;
    mem = fz_alloc(need, 0xCD);
    e = fovpt_init(&ctx, &cfg, s, &cam, gaze, mem, need);
    FZ_CHECK(fz_code_ok(e), "fovpt_init: unknown code %d", (int)e);
    if (e != FOV_OK) { FZ_CHECK(fz_canary_ok(mem, need), "fovpt_init wrote past its memory"); free(mem); return; }
    rs = 3u * W + fz_pick(in, 4);
    r8s = 3u * W + fz_pick(in, 5);
    rgb_n = (size_t)rs * H * sizeof(float);
    rgb8_n = (size_t)r8s * H;
    rgb = (float *)fz_alloc(rgb_n, FZ_PAD);
    rgb8 = (uint8_t *)fz_alloc(rgb8_n, FZ_PAD);
    fovpt_output_init(&out);
    out.rgb = rgb; out.rgb_stride = rs;
    out.rgb8 = rgb8; out.rgb8_stride = r8s;
    for (f = 0; f < frames; ++f) {
        uint32_t y0 = 0, split = 1u + fz_pick(in, H);
        memset(&st, 0, sizeof st);
        if (f > 0) {
            fovpt_camera c2 = cam;
            if (fz_u8(in) & 1) for (k = 0; k < 3; ++k) c2.pos[k] += fz_unit_range(in, -0.1f, 0.1f) * scale;
            gaze.x = fz_float(in, -4.0f, (float)W + 4.0f);
            e = fovpt_set_view(&ctx, &c2, gaze);
            FZ_CHECK(fz_code_ok(e), "fovpt_set_view: unknown code %d", (int)e);
        }
        /* odd row splits: trace, then refine, then resolve, each in chunks of `split` rows */
        for (y0 = 0; y0 < H; y0 += split) {
            e = fovpt_trace_rows(&ctx, f, y0, y0 + split < H ? y0 + split : H, &st);
            FZ_CHECK(e == FOV_OK, "fovpt_trace_rows: %d", (int)e);
        }
        for (y0 = 0; y0 < H; y0 += split) {
            e = fovpt_refine_rows(&ctx, f, y0, y0 + split < H ? y0 + split : H, &st);
            FZ_CHECK(e == FOV_OK, "fovpt_refine_rows: %d", (int)e);
        }
        for (y0 = 0; y0 < H; y0 += split) {
            e = fovpt_resolve_rows(&ctx, y0, y0 + split < H ? y0 + split : H, &out);
            FZ_CHECK(e == FOV_OK, "fovpt_resolve_rows: %d", (int)e);
        }
        {
            uint32_t x, y;
            for (y = 0; y < H; ++y) {
                for (x = 0; x < 3u * W; ++x)
                    FZ_CHECK(fz_finite(rgb[(size_t)y * rs + x]), "rgb not finite at row %u element %u: %g", y, x,
                             (double)rgb[(size_t)y * rs + x]);
                for (x = 3u * W; x < rs; ++x) {
                    uint8_t b[4];
                    memcpy(b, &rgb[(size_t)y * rs + x], 4);
                    FZ_CHECK(b[0] == FZ_PAD && b[1] == FZ_PAD && b[2] == FZ_PAD && b[3] == FZ_PAD, "rgb stride padding written");
                }
                for (x = 3u * W; x < r8s; ++x) FZ_CHECK(rgb8[(size_t)y * r8s + x] == FZ_PAD, "rgb8 stride padding written");
            }
        }
        FZ_CHECK(st.bad_samples <= st.samples + st.rays, "bad_samples above the sample count");
    }
    FZ_CHECK(fz_canary_ok(mem, need), "context memory canary");
    FZ_CHECK(fz_canary_ok(rgb, rgb_n), "rgb canary");
    FZ_CHECK(fz_canary_ok(rgb8, rgb8_n), "rgb8 canary");
    free(rgb); free(rgb8); free(mem);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const float scales[4] = { 1e-3f, 1.0f, 1e3f, 1e5f };
    fz_in in = fz_begin(data, size);
    uint32_t nt = 1u + fz_pick(&in, FZ_MAX_TRIS), ns = fz_pick(&in, 4), i, k;
    float scale = scales[fz_pick(&in, 4)], off = (fz_u8(&in) < 32) ? 37.0f * scale : 0.0f;
    size_t pos_n = 9u * sizeof(float) * nt, sh_n = sizeof(fovpt_shape) * 4u, bytes = 0;
    float *pos = (float *)fz_alloc(pos_n, 0);
    fovpt_shape *sh = (fovpt_shape *)fz_alloc(sh_n, 0);
    fovpt_material mat[3];
    fovpt_mesh mesh;
    fovpt_scene_desc d;
    fovpt_scene s;
    fov_result e;
    void *mem;
    for (i = 0; i < nt; ++i) {
        float *v = pos + 9u * i;
        uint32_t mode = fz_pick(&in, 5);
        for (k = 0; k < 9; ++k) v[k] = fz_coord(&in, scale, off);
        if (mode == 1) { /* axis-aligned flat */
            uint32_t ax = fz_pick(&in, 3);
            v[3 + ax] = v[6 + ax] = v[ax];
        } else if (mode == 2 && i > 0) { /* shares an edge with the previous triangle */
            memcpy(v, v - 9, 3 * sizeof(float));
            memcpy(v + 3, v - 3, 3 * sizeof(float));
        } else if (mode == 3) { /* degenerate: two equal vertices */
            memcpy(v + 3, v, 3 * sizeof(float));
        }
    }
    for (i = 0; i < 3; ++i) {
        fovpt_material_init(&mat[i]);
        mat[i].type = fz_pick(&in, 5);
        if (fz_u8(&in) < 64) mat[i].emission[0] = mat[i].emission[1] = mat[i].emission[2] = fz_float(&in, 0.0f, 8.0f);
    }
    for (i = 0; i < ns; ++i) {
        float p[3], u[3], v[3];
        for (k = 0; k < 3; ++k) { p[k] = fz_coord(&in, scale, off); u[k] = fz_coord(&in, scale, 0.0f); v[k] = fz_coord(&in, scale, 0.0f); }
        switch (fz_pick(&in, 4)) {
        case 0: {
            float rad = fz_float(&in, 0.0f, scale);
            fovpt_shape_sphere(&sh[i], p[0], p[1], p[2], rad, fz_pick(&in, 3));
            break;
        }
        case 1: fovpt_shape_quad(&sh[i], p, u, v, fz_pick(&in, 3)); break;
        case 2:
            for (k = 0; k < 3; ++k) u[k] = p[k] + (u[k] < 0.0f ? -u[k] : u[k]);
            fovpt_shape_box(&sh[i], p, u, fz_pick(&in, 3));
            break;
        default: fovpt_shape_plane(&sh[i], p, u, fz_pick(&in, 3)); break;
        }
    }
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos; mesh.num_vertices = 3u * nt; mesh.num_triangles = nt; mesh.material = fz_pick(&in, 3);
    fovpt_scene_desc_init(&d);
    d.meshes = &mesh; d.num_meshes = 1;
    d.shapes = ns ? sh : NULL; d.num_shapes = ns;
    d.materials = mat; d.num_materials = 3;
    d.bvh_min_prims = 1u + fz_pick(&in, 4);
    d.bvh_leaf = fz_pick(&in, 5);
    d.bvh_bins = fz_pick(&in, 3) == 0 ? 2u + fz_pick(&in, 31) : 0u;
    d.skip_degenerate = 1u - (fz_u8(&in) < 32 ? 1u : 0u);
    e = fovpt_scene_size(&d, &bytes);
    FZ_CHECK(fz_code_ok(e), "fovpt_scene_size: unknown code %d", (int)e);
    if (e == FOV_OK) {
        mem = fz_alloc(bytes, 0xCD);
        e = fovpt_scene_build(&s, &d, mem, bytes);
        FZ_CHECK(fz_code_ok(e), "fovpt_scene_build: unknown code %d", (int)e);
        FZ_CHECK(fz_canary_ok(mem, bytes), "scene memory canary");
        FZ_CHECK(fz_canary_ok(pos, pos_n) && fz_canary_ok(sh, sh_n), "input canaries");
        if (e == FOV_OK) {
            int shapes = 0;
            for (i = 0; i < ns; ++i) shapes = 1;
            fz_rays(&in, &s, pos, nt, ns, scale, off, shapes);
            fz_camera(&in, scale);
            fz_render(&in, &s, scale);
            FZ_CHECK(fz_canary_ok(mem, bytes), "scene memory canary after use");
        } else {
            fz_camera(&in, scale);
        }
        free(mem);
    } else {
        fz_camera(&in, scale);
    }
    free(pos); free(sh);
    return 0;
}
