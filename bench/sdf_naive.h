/* sdf_naive.h - the six built-in scenes of fovsdf.h written as plain C distance functions,
   what a user would write without the library (bench-sdf's `naive` and `*_cb` rows, and
   tests/test_sdf_naive.c, which checks them against the built-in programs).

     float naive_<scene>(const float p[3], int32_t *material);  material may be NULL

   for <scene> = primitives, columns, temple, atrium, thin, fractals; naive_scene(id) gives the
   function of fovsdf_builtin id. Each one is compiled code: the same primitives, operators and
   parameters as the scene builders in fovsdf.h (fovsdf__scene_primitives and the others), in
   the builders' order, with the same material ids; no interpreter, no bounding spheres. The
   primitives are copies of the canonical exact forms after Quilez (I. Quilez, "distance
   functions", iquilezles.org), written as in fovsdf.h so that the float arithmetic is the
   same; the rotation matrices are the float values of the builders' Rodrigues formula
   (cosf/sinf of the angle). The libm calls go through NAIVE_SQRTF, NAIVE_FLOORF, NAIVE_SINF,
   NAIVE_COSF, NAIVE_ATAN2F, NAIVE_POWF and NAIVE_LOGF (default: <math.h>), which the test
   maps to the library's math (the mandelbulb's and the terrain's own float kernels among it),
   so that both sides compute the same values.

   Differences from the built-in programs: these are the exact trees, so far from every
   surface they return the exact distance where a program returns the (smaller) distance to a
   bounding sphere and material -1; and the program's union clusters are rebalanced into
   bounding hierarchies, which changes which material wins an exact tie (never which distance
   comes out). C99; include after <stdint.h>. */
#ifndef SDF_NAIVE_H
#define SDF_NAIVE_H
#include <stdint.h>

#ifndef NAIVE_SQRTF
#include <math.h>
#define NAIVE_SQRTF(x) sqrtf(x)
#define NAIVE_FLOORF(x) floorf(x)
#define NAIVE_SINF(x) sinf(x)
#define NAIVE_COSF(x) cosf(x)
#define NAIVE_ATAN2F(y, x) atan2f(y, x)
#define NAIVE_POWF(x, y) powf(x, y)
#define NAIVE_LOGF(x) logf(x)
#endif

typedef float (*naive_fn)(const float p[3], int32_t *material);

/* ---- primitives (in the primitive's own frame) ------------------------------------------ */
static float nv_minf(float a, float b) { return a < b ? a : b; }
static float nv_maxf(float a, float b) { return a > b ? a : b; }
static float nv_absf(float a) { return a < 0.0f ? -a : a; }
static float nv_clampf(float x, float a, float b) { return x >= a ? (x > b ? b : x) : a; }
static float nv_len2(float x, float y) { return NAIVE_SQRTF(x * x + y * y); }
static float nv_len3(float x, float y, float z) { return NAIVE_SQRTF(x * x + y * y + z * z); }

static float nv_sphere(float x, float y, float z, float r) { return nv_len3(x, y, z) - r; }
static float nv_box(float x, float y, float z, float bx, float by, float bz)
{
    float qx = nv_absf(x) - bx, qy = nv_absf(y) - by, qz = nv_absf(z) - bz;
    float o = nv_len3(nv_maxf(qx, 0.0f), nv_maxf(qy, 0.0f), nv_maxf(qz, 0.0f));
    return o + nv_minf(nv_maxf(qx, nv_maxf(qy, qz)), 0.0f);
}
static float nv_round_box(float x, float y, float z, float bx, float by, float bz, float r)
{
    return nv_box(x, y, z, bx - r, by - r, bz - r) - r;
}
static float nv_frame3(float ax, float ay, float az)
{
    return nv_len3(nv_maxf(ax, 0.0f), nv_maxf(ay, 0.0f), nv_maxf(az, 0.0f)) +
           nv_minf(nv_maxf(ax, nv_maxf(ay, az)), 0.0f);
}
static float nv_box_frame(float x, float y, float z, float bx, float by, float bz, float e)
{
    float px = nv_absf(x) - bx, py = nv_absf(y) - by, pz = nv_absf(z) - bz;
    float qx = nv_absf(px + e) - e, qy = nv_absf(py + e) - e, qz = nv_absf(pz + e) - e;
    return nv_minf(nv_minf(nv_frame3(px, qy, qz), nv_frame3(qx, py, qz)), nv_frame3(qx, qy, pz));
}
static float nv_torus(float x, float y, float z, float major, float minor)
{
    return nv_len2(nv_len2(x, z) - major, y) - minor;
}
static float nv_capsule(float x, float y, float z, float ax, float ay, float az, float cx,
                        float cy, float cz, float r)
{
    float pax = x - ax, pay = y - ay, paz = z - az, bax = cx - ax, bay = cy - ay, baz = cz - az;
    float bb = bax * bax + bay * bay + baz * baz;
    float h = bb > 0.0f ? nv_clampf((pax * bax + pay * bay + paz * baz) / bb, 0.0f, 1.0f) : 0.0f;
    return nv_len3(pax - bax * h, pay - bay * h, paz - baz * h) - r;
}
static float nv_cylinder(float x, float y, float z, float half_height, float r)
{
    float dx = nv_len2(x, z) - r, dy = nv_absf(y) - half_height;
    return nv_minf(nv_maxf(dx, dy), 0.0f) + nv_len2(nv_maxf(dx, 0.0f), nv_maxf(dy, 0.0f));
}
static float nv_cone(float x, float y, float z, float h, float r1, float r2)
{
    float qx = nv_len2(x, z), qy = y;
    float k2x = r2 - r1, k2y = 2.0f * h;
    float cax = qx - nv_minf(qx, qy < 0.0f ? r1 : r2), cay = nv_absf(qy) - h;
    float tt = nv_clampf(((r2 - qx) * k2x + (h - qy) * k2y) / (k2x * k2x + k2y * k2y), 0.0f, 1.0f);
    float cbx = qx - r2 + k2x * tt, cby = qy - h + k2y * tt;
    float s = (cbx < 0.0f && cay < 0.0f) ? -1.0f : 1.0f;
    return s * NAIVE_SQRTF(nv_minf(cax * cax + cay * cay, cbx * cbx + cby * cby));
}
/* Menger sponge of half size 1, `iters` levels of crosses */
static float nv_menger(float x, float y, float z, int iters)
{
    float d = nv_box(x, y, z, 1.0f, 1.0f, 1.0f), s = 1.0f, p[3];
    int m, k;
    if (!(d <= 1.0f)) return d;
    p[0] = x; p[1] = y; p[2] = z;
    for (m = 0; m < iters; ++m) {
        float r[3], da, db, dc, c;
        for (k = 0; k < 3; ++k) {
            float v = p[k] * s, a;
            v = v - 2.0f * NAIVE_FLOORF(v * 0.5f);
            a = v - 1.0f;
            r[k] = nv_absf(1.0f - 3.0f * nv_absf(a));
        }
        s *= 3.0f;
        da = nv_maxf(r[0], r[1]);
        db = nv_maxf(r[1], r[2]);
        dc = nv_maxf(r[2], r[0]);
        c = (nv_minf(da, nv_minf(db, dc)) - 1.0f) / s;
        d = nv_maxf(d, c);
    }
    return d;
}
static float nv_mandelbulb(float x, float y, float z, float power, int iters)
{
    float zx = x, zy = y, zz = z, dr = 1.0f, r = nv_len3(x, y, z);
    int i;
    for (i = 0; i < iters && r <= 2.0f; ++i) {
        float th, ph, zr, st;
        if (r < 1e-20f) { dr = 1.0f; break; }
        th = NAIVE_ATAN2F(nv_len2(zx, zy), zz) * power;
        ph = NAIVE_ATAN2F(zy, zx) * power;
        zr = NAIVE_POWF(r, power - 1.0f);
        dr = power * zr * dr + 1.0f;
        zr *= r;
        st = NAIVE_SINF(th);
        zx = zr * st * NAIVE_COSF(ph) + x;
        zy = zr * st * NAIVE_SINF(ph) + y;
        zz = zr * NAIVE_COSF(th) + z;
        r = nv_len3(zx, zy, zz);
    }
    if (r < 1e-20f) return 0.0f;
    return 0.5f * NAIVE_LOGF(r) * r / dr;
}
/* height field y = amp * sum_o 0.5^o sin(fx) sin(fz), each octave rotated and scaled 2.03x;
   lip = 1 / sqrt(1 + (bound on |grad h|)^2) makes (y - h) lip a distance bound */
static float nv_terrain(float x, float y, float z, float amp, float freq, int oct, float lip)
{
    float h = 0.0f, w = 1.0f, fx = x * freq, fz = z * freq;
    int o;
    for (o = 0; o < oct; ++o) {
        float nx;
        h += w * NAIVE_SINF(fx) * NAIVE_SINF(fz);
        nx = (0.8f * fx - 0.6f * fz) * 2.03f;
        fz = (0.6f * fx + 0.8f * fz) * 2.03f;
        fx = nx;
        w *= 0.5f;
    }
    return (y - h * amp) * lip;
}

/* ---- operators -------------------------------------------------------------------------- */
/* union, subtract, intersect of (d, m) with (e, me), in place; a tie keeps the second */
static void nv_union(float *d, int32_t *m, float e, int32_t me)
{
    if (!(*d < e)) { *d = e; *m = me; }
}
static void nv_subtract(float *d, int32_t *m, float e, int32_t me)
{
    if (!(*d > -e)) { *d = -e; *m = me; }
}
static void nv_intersect(float *d, int32_t *m, float e, int32_t me)
{
    if (!(*d > e)) { *d = e; *m = me; }
}
static void nv_smooth_union(float *d, int32_t *m, float e, int32_t me, float k)
{
    float a = *d, b = e, h = nv_clampf(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
    *d = b + (a - b) * h - k * h * (1.0f - h);
    if (!(h > 0.5f)) *m = me;
}
static void nv_smooth_subtract(float *d, int32_t *m, float e, int32_t me, float k)
{
    float a = *d, b = e, h = nv_clampf(0.5f - 0.5f * (a + b) / k, 0.0f, 1.0f);
    *d = a + (-b - a) * h + k * h * (1.0f - h);
    if (h > 0.5f) *m = me;
}
static void nv_smooth_intersect(float *d, int32_t *m, float e, int32_t me, float k)
{
    float a = *d, b = e, h = nv_clampf(0.5f - 0.5f * (b - a) / k, 0.0f, 1.0f);
    *d = b + (a - b) * h + k * h * (1.0f - h);
    if (!(h > 0.5f)) *m = me;
}
/* limited repetition: the nearest of the copies at period * c, c in [-n, n] (n 0: unlimited) */
static float nv_rep(float v, float period, float n)
{
    float c = NAIVE_FLOORF(v / period + 0.5f);
    if (n > 0.0f) c = nv_clampf(c, -n, n);
    return v - period * c;
}
/* world -> object: R^T p for the row-major rotation R (object -> world) */
static void nv_rot(const float r[9], float x, float y, float z, float o[3])
{
    o[0] = r[0] * x + r[3] * y + r[6] * z;
    o[1] = r[1] * x + r[4] * y + r[7] * z;
    o[2] = r[2] * x + r[5] * y + r[8] * z;
}
/* rotations of the builders: about y by 30 and 25 degrees, x by 90 and -90, z by 45 and 90 */
static const float nv_rot_y30[9] = { 0.866025388f, 0.0f, 0.5f, 0.0f, 1.0f, 0.0f, -0.5f, 0.0f,
                                     0.866025388f };
static const float nv_rot_y25[9] = { 0.906307757f, 0.0f, 0.42261827f, 0.0f, 1.0f, 0.0f,
                                     -0.42261827f, 0.0f, 0.906307757f };
static const float nv_rot_x90[9] = { 0.99999994f, 0.0f, 0.0f, 0.0f, -4.37113883e-08f, -1.0f,
                                     0.0f, 1.0f, -4.37113883e-08f };
static const float nv_rot_xm90[9] = { 0.99999994f, 0.0f, 0.0f, 0.0f, -4.37113883e-08f, 1.0f,
                                      0.0f, -1.0f, -4.37113883e-08f };
static const float nv_rot_z45[9] = { 0.707106769f, -0.707106769f, 0.0f, 0.707106769f,
                                     0.707106769f, 0.0f, 0.0f, 0.0f, 1.0f };
static const float nv_rot_z90[9] = { -4.37113883e-08f, -1.0f, 0.0f, 1.0f, -4.37113883e-08f, 0.0f,
                                     0.0f, 0.0f, 0.99999994f };

/* ---- the scenes -------------------------------------------------------------------------- */
/* Primitives: every primitive and operator on a checkerboard plane */
static float naive_primitives(const float p[3], int32_t *material)
{
    float x = p[0], y = p[1], z = p[2], d = y, e, f, q[3];
    int32_t m = 1, me;
    nv_union(&d, &m, nv_sphere(x + 4.0f, y - 0.5f, z, 0.5f), 2);
    nv_rot(nv_rot_y30, x + 2.0f, y - 0.4f, z, q);
    nv_union(&d, &m, nv_box(q[0], q[1], q[2], 0.4f, 0.4f, 0.4f), 3);
    nv_union(&d, &m, nv_round_box(x, y - 0.35f, z, 0.45f, 0.35f, 0.45f, 0.12f), 4);
    nv_rot(nv_rot_x90, x - 2.0f, y - 0.55f, z, q);
    nv_union(&d, &m, nv_torus(q[0], q[1], q[2], 0.4f, 0.12f), 5);
    nv_union(&d, &m, nv_capsule(x - 4.0f, y, z, -0.3f, 0.2f, 0.0f, 0.3f, 0.9f, 0.1f, 0.18f), 6);
    nv_union(&d, &m, nv_cylinder(x + 4.0f, y - 0.5f, z - 2.5f, 0.5f, 0.35f), 7);
    nv_union(&d, &m, nv_cone(x + 2.0f, y - 0.5f, z - 2.5f, 0.5f, 0.45f, 0.1f), 2);
    nv_union(&d, &m, nv_box_frame(x, y - 0.45f, z - 2.5f, 0.45f, 0.45f, 0.45f, 0.04f), 3);
    /* smooth union of a sphere (4) and a box (6) */
    e = nv_sphere(x - 2.0f + 0.25f, y - 0.4f, z - 2.5f, 0.35f); me = 4;
    nv_smooth_union(&e, &me, nv_box(x - 2.0f - 0.3f, y - 0.4f, z - 2.5f, 0.25f, 0.25f, 0.25f), 6,
                    0.25f);
    nv_union(&d, &m, e, me);
    /* an onion shell cut open by a box */
    e = nv_absf(nv_sphere(x - 4.0f, y - 0.5f, z - 2.5f, 0.45f)) - 0.04f; me = 5;
    nv_subtract(&e, &me, nv_box(x - 4.0f, y - 0.5f - 0.45f, z - 2.5f + 0.3f, 0.6f, 0.3f, 0.6f), 5);
    nv_union(&d, &m, e, me);
    e = nv_sphere(x + 3.0f, y - 0.4f, z - 5.0f, 0.5f); me = 7;
    nv_intersect(&e, &me, nv_box(x + 3.0f, y - 0.4f, z - 5.0f, 0.4f, 0.4f, 0.4f), 7);
    nv_union(&d, &m, e, me);
    e = nv_box(x, y - 0.45f, z - 5.0f, 0.45f, 0.45f, 0.45f); me = 2;
    nv_smooth_subtract(&e, &me, nv_sphere(x, y - 0.45f, z - 5.0f, 0.55f), 2, 0.1f);
    nv_union(&d, &m, e, me);
    e = nv_sphere(x - 3.0f, y - 0.5f, z - 5.0f, 0.55f); me = 3;
    nv_smooth_intersect(&e, &me, nv_cylinder(x - 3.0f, y - 0.5f, z - 5.0f, 0.6f, 0.4f), 3, 0.1f);
    nv_union(&d, &m, e, me);
    /* a mirrored pair of rounded boxes, scaled by 1.2 */
    q[0] = x / 1.2f; q[1] = (y - 0.42f) / 1.2f; q[2] = (z - 7.5f) / 1.2f;
    f = (nv_box(nv_absf(q[0]) - 0.5f, q[1], q[2], 0.1f, 0.3f, 0.1f) - 0.05f) * 1.2f;
    nv_union(&d, &m, f, 4);
    /* a row of 13 small spheres, 0.5 apart */
    nv_union(&d, &m, nv_sphere(nv_rep(x, 0.5f, 6.0f), y - 0.12f, z + 1.5f, 0.12f), 6);
    if (material) *material = m;
    return d;
}

/* Columns and Lights: a closed hall, 9 x 9 columns, 5 x 5 spheres */
static float naive_columns(const float p[3], int32_t *material)
{
    float x = p[0], y = p[1], z = p[2], d = y, e, cx, cz;
    int32_t m = 1, me;
    e = nv_box(x, y - 2.0f, z, 20.5f, 2.5f, 20.5f); me = 7;
    nv_subtract(&e, &me, nv_box(x, y - 1.75f, z, 19.5f, 2.25f, 19.5f), 7);
    nv_union(&d, &m, e, me);
    cx = nv_rep(x, 4.0f, 4.0f);
    cz = nv_rep(z, 4.0f, 4.0f);
    e = nv_cylinder(cx, y - 2.0f, cz, 1.8f, 0.35f); me = 4;
    nv_union(&e, &me, nv_box(cx, y - 0.1f, cz, 0.5f, 0.1f, 0.5f), 0);
    nv_union(&e, &me, nv_box(cx, y - 3.9f, cz, 0.5f, 0.1f, 0.5f), 0);
    nv_union(&e, &me, nv_torus(cx, y - 3.6f, cz, 0.36f, 0.05f), 3);
    nv_union(&d, &m, e, me);
    cx = nv_rep(x - 2.0f, 8.0f, 2.0f);
    cz = nv_rep(z - 2.0f, 8.0f, 2.0f);
    nv_union(&d, &m, nv_sphere(cx, y - 0.3f, cz, 0.3f), 2);
    if (material) *material = m;
    return d;
}

/* Temple on a terrain */
static float naive_temple(const float p[3], int32_t *material)
{
    float x = p[0], y = p[1], z = p[2], d, e, q[3];
    int32_t m = 5, me = 7;
    d = nv_terrain(x, y, z, 6.0f, 0.035f, 6, 0.607299685f);
    e = nv_box(x, y - 0.1f, z, 4.6f, 0.6f, 6.6f);
    nv_union(&e, &me, nv_box(x, y - 0.85f, z, 4.2f, 0.15f, 6.2f), 7);
    nv_union(&e, &me, nv_cylinder(nv_rep(x, 1.6f, 2.0f), y - 2.5f, nv_rep(z, 2.0f, 3.0f), 1.5f,
                                  0.25f), 7);
    nv_union(&e, &me, nv_box(x, y - 4.25f, z, 4.0f, 0.25f, 6.0f), 7);
    {   /* the roof: a box turned 45 degrees about z, cut by the plane y = 4.5 */
        float r;
        int32_t mr = 2;
        nv_rot(nv_rot_z45, x, y - 2.45f, z, q);
        r = nv_box(q[0], q[1], q[2], 2.9f, 2.9f, 6.1f);
        nv_intersect(&r, &mr, -y + 4.5f, 2);
        nv_union(&e, &me, r, mr);
    }
    nv_union(&d, &m, e, me);
    if (material) *material = m;
    return d;
}

/* Atrium: two storeys of arcades, 11 bays on each side */
static float naive_atrium(const float p[3], int32_t *material)
{
    float x = p[0], y = p[1], z = p[2], d = y, e, ax = nv_absf(p[0]), bx, bz, q[3];
    int32_t m = 1, me;
    nv_union(&d, &m, nv_box(ax - 7.0f, y - 5.0f, z, 0.5f, 5.0f, 16.0f), 7);
    nv_union(&d, &m, nv_box(x, y - 5.0f, nv_absf(z) - 15.5f, 7.5f, 5.0f, 0.5f), 7);
    /* one bay, repeated along z and mirrored in x */
    bx = ax - 4.0f;
    bz = nv_rep(z + 1.25f, 2.5f, 5.0f);
    e = nv_cylinder(bx, y - 1.6f, bz, 1.6f, 0.28f); me = 4;
    nv_union(&e, &me, nv_box(bx, y - 0.12f, bz, 0.4f, 0.12f, 0.4f), 0);
    nv_union(&e, &me, nv_box(bx, y - 3.2f, bz, 0.4f, 0.12f, 0.4f), 0);
    {   /* the arch: a box with a cylindrical cut */
        float a;
        int32_t ma = 7;
        a = nv_box(bx, y - 4.1f, bz - 1.25f, 0.35f, 0.8f, 1.25f);
        nv_rot(nv_rot_z90, bx, y - 3.4f, bz - 1.25f, q);
        nv_subtract(&a, &ma, nv_cylinder(q[0], q[1], q[2], 0.5f, 0.95f), 7);
        nv_union(&e, &me, a, ma);
    }
    {   /* the upper storey */
        float u;
        int32_t mu = 4;
        u = nv_cylinder(bx, y - 6.0f, bz, 1.1f, 0.18f);
        nv_union(&u, &mu, nv_box(bx + 0.1f, y - 5.4f, bz - 1.25f, 0.25f, 0.5f, 1.25f), 2);
        nv_union(&u, &mu, nv_box(bx, y - 7.3f, bz - 1.25f, 0.35f, 0.2f, 1.25f), 2);
        nv_union(&e, &me, u, mu);
    }
    nv_rot(nv_rot_z90, bx, y - 2.3f, bz - 1.25f, q);
    nv_union(&e, &me, nv_torus(q[0], q[1], q[2], 0.3f, 0.04f), 6);
    nv_union(&d, &m, e, me);
    /* gallery floors */
    nv_union(&d, &m, nv_box(ax - 5.5f, y - 4.75f, z, 1.5f, 0.15f, 15.0f), 0);
    /* the fountain */
    e = nv_cylinder(x, y - 0.3f, z - 2.0f, 0.3f, 1.2f); me = 3;
    nv_subtract(&e, &me, nv_cylinder(x, y - 0.3f - 0.2f, z - 2.0f, 0.3f, 1.05f), 3);
    nv_union(&d, &m, e, me);
    /* statues: spheres on plinths, 5 along z on each side */
    bx = ax - 2.2f;
    bz = nv_rep(z, 5.0f, 2.0f);
    e = nv_sphere(bx, y - 1.25f, bz, 0.35f); me = 2;
    nv_union(&e, &me, nv_box(bx, y - 0.45f, bz, 0.25f, 0.45f, 0.25f), 2);
    nv_union(&d, &m, e, me);
    if (material) *material = m;
    return d;
}

/* Thin features: wires, small spheres, a plate with holes, thin box frames */
static float naive_thin(const float p[3], int32_t *material)
{
    float x = p[0], y = p[1], z = p[2], d = y, e, q[3];
    int32_t m = 1, me;
    nv_union(&d, &m, nv_capsule(nv_rep(x + 0.4f, 0.12f, 12.0f), y, z - 0.6f, 0.0f, 0.0f, 0.0f,
                                0.0f, 1.2f, 0.0f, 0.008f), 3);
    nv_union(&d, &m, nv_capsule(x, nv_rep(y - 1.5f, 0.15f, 3.0f), z - 1.4f, -2.5f, 0.0f, 0.0f,
                                2.5f, 0.0f, 0.0f, 0.005f), 6);
    nv_union(&d, &m, nv_cylinder(nv_absf(x) - 2.5f, y - 1.0f, z - 1.4f, 1.0f, 0.04f), 0);
    nv_union(&d, &m, nv_sphere(nv_rep(x + 1.7f, 0.1f, 7.0f), nv_rep(y - 0.6f, 0.1f, 4.0f), z,
                               0.018f), 2);
    e = nv_box(x - 1.6f, y - 0.6f, z, 0.6f, 0.5f, 0.02f); me = 7;
    nv_rot(nv_rot_x90, nv_rep(x - 1.6f, 0.1f, 5.0f), nv_rep(y - 0.6f, 0.1f, 4.0f), z, q);
    nv_subtract(&e, &me, nv_cylinder(q[0], q[1], q[2], 0.1f, 0.03f), 7);
    nv_union(&d, &m, e, me);
    nv_union(&d, &m, nv_box_frame(nv_rep(x, 0.4f, 2.0f), y - 0.16f, z + 0.6f, 0.15f, 0.15f, 0.15f,
                                  0.006f), 4);
    if (material) *material = m;
    return d;
}

/* Fractals: a Menger sponge (4 levels) and a Mandelbulb (power 8, 8 iterations) */
static float naive_fractals(const float p[3], int32_t *material)
{
    float x = p[0], y = p[1], z = p[2], d = y, q[3];
    int32_t m = 1;
    nv_rot(nv_rot_y25, x + 1.7f, y - 1.0f, z - 0.3f, q);
    nv_union(&d, &m, nv_menger(q[0], q[1], q[2], 4), 3);
    nv_rot(nv_rot_xm90, x - 1.5f, y - 1.15f, z, q);
    nv_union(&d, &m, nv_mandelbulb(q[0], q[1], q[2], 8.0f, 8), 4);
    if (material) *material = m;
    return d;
}

/* the function of built-in scene id (fovsdf_builtin_init's order), NULL for other ids */
static naive_fn naive_scene(uint32_t id)
{
    static const naive_fn fns[6] = { naive_primitives, naive_columns, naive_temple,
                                     naive_atrium, naive_thin, naive_fractals };
    return id < 6u ? fns[id] : (naive_fn)0;
}
#endif
