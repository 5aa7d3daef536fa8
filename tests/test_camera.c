/* test_camera.c - the one camera model of fovsdf.h, fovlp.h and fovpt.h (fov_camera):
   the same type and defaults in every header, the documented frame and handedness (checked
   through the public ray, gaze and render functions against values worked out by hand from
   the pinhole geometry, not from the library), fovsdf's and fovpt's rays for the same camera
   and image point, fovlp_camera_from against the fovsdf context it must equal, eye_offset in
   fovpt, and the fields a header does not support. Prints "N passed, N failed". */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file; the shared camera
   defaults (fov__camera_init) are called through the test hook's wrapper
   (tests/common/fov_priv_sdf.h), which is compiled in this file when it holds the
   implementation */
#ifndef FOV_TEST_LINK_IMPL
#define FOV_IMPL
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"
#include "fov_priv_sdf.h"
#include "fovcheck.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

/* typedef compatibility: one type under three names (this must compile, as C and as C++) */
static const fovpt_camera *as_pt(const fovsdf_camera *c) { return c; }
static const fov_camera *as_fov(const fovpt_camera *c) { return c; }
typedef char size_check[sizeof(fovsdf_camera) == sizeof(fovpt_camera) ? 1 : -1];

static uint32_t g_rng = 0x2545f491u;
static float frand(float a, float b)
{
    g_rng = g_rng * 1664525u + 1013904223u;
    return a + (b - a) * ((float)(g_rng >> 8) / 16777216.0f);
}

/* a ball (centre c, radius r) for fovsdf */
typedef struct ball {
    float c[3], r;
} ball;
static float ball_sdf(const float p[3], void *user)
{
    const ball *b = (const ball *)user;
    float d[3];
    d[0] = p[0] - b->c[0];
    d[1] = p[1] - b->c[1];
    d[2] = p[2] - b->c[2];
    return sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - b->r;
}

typedef struct rec {
    int calls;
    int32_t code;
    char msg[256];
} rec;
static void rec_log(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                    void *user)
{
    rec *r = (rec *)user;
    (void)tag;
    (void)level;
    (void)line;
    r->calls++;
    r->code = code;
    snprintf(r->msg, sizeof r->msg, "%s", msg ? msg : "(null)");
}

static fov_result sdf_ctx(fovsdf_ctx *ctx, const fovsdf_camera *cam, ball *b, const fov_logger *lg)
{
    fovsdf_scene sc;
    fovsdf_config cfg = fovsdf_config_default();
    fov_gaze g;
    fovsdf_scene_init(&sc);
    sc.dist = ball_sdf;
    sc.user = b;
    if (lg) cfg.logger = *lg;
    g.x = 0.5f * (float)cam->width;
    g.y = 0.5f * (float)cam->height;
    return fovsdf_init(ctx, &cfg, &sc, cam, g, NULL, 0);
}

static double ulps_apart(float a, float b)
{
    double d = fabs((double)a - (double)b);
    return d / (double)FLT_EPSILON; /* in units of 2^-23, for values of magnitude <= 1 */
}

/* 1. the defaults: the same in both init functions, and the documented values */
static void test_defaults(void)
{
    fovsdf_camera a;
    fovpt_camera b;
    memset(&a, 0xAB, sizeof a);
    memset(&b, 0xCD, sizeof b);
    fovsdf_camera_init(&a, 320, 240);
    fovpt_camera_init(&b, 320, 240);
    check(memcmp(&a, &b, sizeof a) == 0, "defaults_fovsdf_equal_fovpt",
          "the two init functions differ");
    check(a.pos[0] == 0.0f && a.pos[1] == 0.0f && a.pos[2] == 5.0f && a.target[0] == 0.0f &&
              a.target[1] == 0.0f && a.target[2] == 0.0f && a.up[0] == 0.0f && a.up[1] == 1.0f &&
              a.up[2] == 0.0f && a.fov_y_deg == 60.0f && a.width == 320u && a.height == 240u &&
              a.eye_offset == 0.0f && a.tan_left == 0.0f && a.tan_right == 0.0f &&
              a.tan_bottom == 0.0f && a.tan_top == 0.0f,
          "defaults_documented_values", "pos %g %g %g target %g %g %g up %g %g %g fov %g",
          (double)a.pos[0], (double)a.pos[1], (double)a.pos[2], (double)a.target[0],
          (double)a.target[1], (double)a.target[2], (double)a.up[0], (double)a.up[1],
          (double)a.up[2], (double)a.fov_y_deg);
    check(as_fov(as_pt(&a)) == &a && sizeof(fov_camera) == sizeof(fovsdf_camera),
          "typedefs_one_type", " ");
}

/* 2. handedness of the default camera, worked out by hand: at (0, 0, 5) looking at the
   origin, fwd = -z, right = +x, up = +y. A point p = (X, Y, 0) lies at depth 5; its image
   point is x = W/2 + (H/2) (X / 5) / tan(30 deg), y = H/2 - (H/2) (Y / 5) / tan(30 deg). */
static void test_handedness(void)
{
    const double t30 = tan(30.0 * 3.14159265358979323846 / 180.0);
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    ball b;
    float r[3], u[3], f[3], ro[3], rd[3];
    fov_gaze g;
    double ex = 160.0 + 120.0 * 0.2 / t30, ey = 120.0 - 120.0 * 0.2 / t30; /* X = 1, Y = 1 */
    fov_result e;
    int k;
    fovsdf_camera_init(&cam, 320, 240);
    e = fovsdf_camera_basis(&cam, r, u, f);
    check(e == FOV_OK && r[0] == 1.0f && r[1] == 0.0f && r[2] == 0.0f && u[0] == 0.0f &&
              u[1] == 1.0f && u[2] == 0.0f && f[0] == 0.0f && f[1] == 0.0f && f[2] == -1.0f,
          "handed_default_basis_right_+x_up_+y_fwd_-z", "right %g %g %g up %g %g %g fwd %g %g %g",
          (double)r[0], (double)r[1], (double)r[2], (double)u[0], (double)u[1], (double)u[2],
          (double)f[0], (double)f[1], (double)f[2]);
    /* world +x on the image's right, +y at its top (fovpt's projection of world points) */
    {
        float p[3] = {1.0f, 0.0f, 0.0f};
        e = fovpt_gaze_from_point(&cam, p, &g);
        check(e == FOV_OK && fabs((double)g.x - ex) < 1e-3 && fabs((double)g.y - 120.0) < 1e-3,
              "handed_+x_projects_right_of_centre", "(%g, %g), want (%g, 120)", (double)g.x,
              (double)g.y, ex);
        p[0] = 0.0f;
        p[1] = 1.0f;
        e = fovpt_gaze_from_point(&cam, p, &g);
        check(e == FOV_OK && fabs((double)g.x - 160.0) < 1e-3 && fabs((double)g.y - ey) < 1e-3,
              "handed_+y_projects_above_centre", "(%g, %g), want (160, %g)", (double)g.x,
              (double)g.y, ey);
    }
    /* the rays through those image points head for (1, 0, 0) and (0, 1, 0): fovsdf and fovpt */
    b.c[0] = 0.0f;
    b.c[1] = 0.0f;
    b.c[2] = -100.0f;
    b.r = 1.0f;
    e = sdf_ctx(&ctx, &cam, &b, NULL);
    if (check(e == FOV_OK, "handed_sdf_init", "%s", fovsdf_result_string(e))) {
        static const double want[2][3] = {{1.0, 0.0, -5.0}, {0.0, 1.0, -5.0}};
        int i, lib;
        for (i = 0; i < 2; ++i)
            for (lib = 0; lib < 2; ++lib) {
                double err = 0.0, l = sqrt(26.0);
                float px = (float)(i == 0 ? ex : 160.0), py = (float)(i == 0 ? 120.0 : ey);
                e = lib == 0 ? fovsdf_camera_ray(&ctx, px, py, ro, rd)
                             : fovpt_camera_ray(&cam, px, py, ro, rd);
                for (k = 0; k < 3; ++k)
                    err = fmax(err, fabs((double)rd[k] - want[i][k] / l));
                check(e == FOV_OK && err < 1e-5 && ro[0] == 0.0f && ro[1] == 0.0f && ro[2] == 5.0f,
                      N("handed_%s_ray_to_%s", lib ? "fovpt" : "fovsdf", i ? "+y" : "+x"),
                      "rd %g %g %g, err %g", (double)rd[0], (double)rd[1], (double)rd[2], err);
            }
    }
    /* turned around (pos (0, 0, -5), as documented): world +x on the image's left */
    {
        fovsdf_camera c2 = cam;
        float p[3] = {1.0f, 0.0f, 0.0f};
        c2.pos[2] = -5.0f;
        e = fovpt_gaze_from_point(&c2, p, &g);
        check(e == FOV_OK && fabs((double)g.x - (320.0 - ex)) < 1e-3,
              "handed_turned_around_+x_on_the_left", "x %g, want %g", (double)g.x, 320.0 - ex);
    }
}

/* 3. a rendered image: a ball at world +x appears in the image's right half, one at +y in
   its top half (fovsdf's hit mask and fovpt's radiance; 32x24, default camera) */
static void count_halves(const uint8_t *m, uint32_t W, uint32_t H, long n[4])
{
    uint32_t x, y;
    n[0] = n[1] = n[2] = n[3] = 0; /* left, right, top, bottom */
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x)
            if (m[y * W + x]) {
                n[x < W / 2 ? 0 : 1]++;
                n[y < H / 2 ? 2 : 3]++;
            }
}
static void test_render_sides(void)
{
    enum { W = 32, H = 24 };
    static const float where[2][3] = {{1.5f, 0.0f, 0.0f}, {0.0f, 1.2f, 0.0f}};
    uint8_t mask[W * H];
    int i, k;
    for (i = 0; i < 2; ++i) {
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        fovsdf_output out;
        ball b;
        long n[4];
        fov_result e;
        fovsdf_camera_init(&cam, W, H);
        for (k = 0; k < 3; ++k)
            b.c[k] = where[i][k];
        b.r = 0.5f;
        memset(mask, 0, sizeof mask);
        e = sdf_ctx(&ctx, &cam, &b, NULL);
        fovsdf_output_init(&out);
        out.hit = mask;
        if (e == FOV_OK) e = fovsdf_render_rows(&ctx, 0, H, &out, NULL);
        count_halves(mask, W, H, n);
        if (i == 0)
            check(e == FOV_OK && n[1] > 10 && n[0] == 0, "render_sdf_ball_at_+x_in_right_half",
                  "%s: %ld pixels left, %ld right", fovsdf_result_string(e), n[0], n[1]);
        else
            check(e == FOV_OK && n[2] > 10 && n[3] == 0, "render_sdf_ball_at_+y_in_top_half",
                  "%s: %ld pixels top, %ld bottom", fovsdf_result_string(e), n[2], n[3]);
    }
    for (i = 0; i < 2; ++i) {
        fovpt_material mat;
        fovpt_shape sh;
        fovpt_scene_desc d;
        fovpt_scene scene;
        fovpt_camera cam;
        fovpt_config cfg = fovpt_config_default();
        fovpt_ctx ctx;
        fovpt_output out;
        fov_gaze g = {16.0f, 12.0f};
        static float rgb[W * H * 3];
        size_t sb = 0, cb = 0;
        void *smem = NULL, *cmem = NULL;
        long n[4];
        fov_result e;
        fovpt_material_init(&mat);
        mat.emission[0] = mat.emission[1] = mat.emission[2] = 1.0f;
        fovpt_shape_sphere(&sh, where[i][0], where[i][1], where[i][2], 0.5f, 0);
        fovpt_scene_desc_init(&d);
        d.shapes = &sh;
        d.num_shapes = 1;
        d.materials = &mat;
        d.num_materials = 1;
        fovpt_camera_init(&cam, W, H);
        e = fovpt_scene_size(&d, &sb);
        if (e == FOV_OK) {
            smem = malloc(sb);
            e = fovpt_scene_build(&scene, &d, smem, sb);
        }
        if (e == FOV_OK) e = fovpt_memory_size(&cfg, &cam, &cb);
        if (e == FOV_OK) {
            cmem = malloc(cb ? cb : 1);
            e = fovpt_init(&ctx, &cfg, &scene, &cam, g, cmem, cb);
        }
        memset(rgb, 0, sizeof rgb);
        fovpt_output_init(&out);
        out.rgb = rgb;
        if (e == FOV_OK) e = fovpt_render(&ctx, 0, &out, NULL);
        for (k = 0; k < W * H; ++k)
            mask[k] = (uint8_t)(rgb[3 * k] > 0.5f);
        count_halves(mask, W, H, n);
        if (i == 0)
            check(e == FOV_OK && n[1] > 10 && n[0] == 0, "render_pt_ball_at_+x_in_right_half",
                  "%s: %ld pixels left, %ld right", fovpt_result_string(e), n[0], n[1]);
        else
            check(e == FOV_OK && n[2] > 10 && n[3] == 0, "render_pt_ball_at_+y_in_top_half",
                  "%s: %ld pixels top, %ld bottom", fovpt_result_string(e), n[2], n[3]);
        free(smem);
        free(cmem);
    }
}

/* 4. the same camera, the same image point: fovsdf's and fovpt's rays agree (origin bit for
   bit; directions within a few ulps: fovpt does not renormalise up = right x fwd, and the
   two headers evaluate the image-plane offset in a different order), and fovlp_camera_from
   equals the fovsdf context bit for bit */
static void test_rays_agree(void)
{
    int it, bad_init = 0, n = 0, lp_bad = 0;
    double worst = 0.0, ratio = 0.0;
    long org_bad = 0;
    for (it = 0; it < 3000; ++it) {
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        fovlp_camera lc;
        ball b = {{0.0f, 0.0f, 0.0f}, 0.1f};
        int k, j;
        if (it % 10 == 9) /* any size, up to 1999:1 */
            fovsdf_camera_init(&cam, 1u + (uint32_t)frand(0.0f, 1999.0f),
                               1u + (uint32_t)frand(0.0f, 1999.0f));
        else { /* displays: aspect 1:4 .. 4:1 */
            uint32_t h = 1u + (uint32_t)frand(0.0f, 1999.0f);
            fovsdf_camera_init(&cam, 1u + (uint32_t)((float)h * frand(0.25f, 4.0f)), h);
        }
        for (k = 0; k < 3; ++k) {
            cam.pos[k] = frand(-50.0f, 50.0f);
            cam.target[k] = frand(-50.0f, 50.0f);
            cam.up[k] = frand(-1.0f, 1.0f);
        }
        cam.fov_y_deg = frand(1.0f, 170.0f);
        if (it % 3 == 0) cam.eye_offset = frand(-0.1f, 0.1f);
        if (it % 7 == 0) { cam.up[0] = cam.up[1] = cam.up[2] = 0.0f; }
        b.c[0] = cam.target[0];
        b.c[1] = cam.target[1];
        b.c[2] = cam.target[2];
        if (sdf_ctx(&ctx, &cam, &b, NULL) != FOV_OK) {
            bad_init++;
            continue;
        }
        if (fovlp_camera_from(&cam, &lc) != FOV_OK || memcmp(lc.pos, ctx.origin, sizeof lc.pos) ||
            memcmp(lc.right, ctx.right, sizeof lc.right) || memcmp(lc.up, ctx.up, sizeof lc.up) ||
            memcmp(lc.fwd, ctx.fwd, sizeof lc.fwd) ||
            memcmp(&lc.tan_half_y, &ctx.tan_half_y, sizeof(float)))
            lp_bad++;
        for (j = 0; j < 8; ++j) {
            float x = frand(-0.5f, 1.5f) * (float)cam.width,
                  y = frand(-0.5f, 1.5f) * (float)cam.height;
            float o1[3], d1[3], o2[3], d2[3];
            double tol;
            if (fovsdf_camera_ray(&ctx, x, y, o1, d1) != FOV_OK ||
                fovpt_camera_ray(&cam, x, y, o2, d2) != FOV_OK) {
                bad_init++;
                continue;
            }
            n++;
            if (memcmp(o1, o2, sizeof o1)) org_bad++;
            /* the tolerance, 8 ulps, grows with the image plane's half-width tan(fov_y/2) W/H
               beyond 8: an image point is known to an ulp of x / W, so an error of eps tan W/H
               in the offset is inherent in either formula (18 ulps at 1527x3 pixels, 57 deg) */
            tol = 8.0 * fmax(1.0, tan(0.5 * (double)cam.fov_y_deg * 3.14159265358979 / 180.0) *
                                      fmax(1.0, (double)cam.width / (double)cam.height) / 8.0);
            for (k = 0; k < 3; ++k) {
                worst = fmax(worst, ulps_apart(d1[k], d2[k]));
                ratio = fmax(ratio, ulps_apart(d1[k], d2[k]) / tol);
            }
        }
    }
    check(bad_init == 0 && n == 24000, "rays_agree_all_valid", "%d failures, %d rays", bad_init, n);
    check(org_bad == 0, "rays_agree_origin_bit_for_bit", "%ld origins differ", org_bad);
    check(ratio <= 1.0, "rays_agree_direction_within_8_ulps",
          "worst %.2f of the tolerance (%.2f ulps) over %d rays", ratio, worst, n);
    printf("     (fovsdf vs fovpt ray directions: worst %.2f ulps of 1, %.2f of the tolerance, %d "
           "rays)\n",
           worst, ratio, n);
    check(lp_bad == 0, "fovlp_camera_from_equals_fovsdf_ctx", "%d cameras differ", lp_bad);
}

/* 5. eye_offset: fovpt's pinhole is pos + eye_offset * right, in every ray it traces: a
   render with eye_offset 0.25 equals, bit for bit, the render of the camera moved by 0.25
   along right (for the default camera, right = +x exactly). fovsdf the same. */
static void test_eye_offset(void)
{
    enum { W = 24, H = 16 };
    static float img[2][W * H * 3];
    uint32_t m;
    float ro[3], rd[3];
    fovpt_camera cam;
    fov_result e;
    fovpt_camera_init(&cam, W, H);
    cam.eye_offset = 0.25f;
    e = fovpt_camera_ray(&cam, 3.5f, 2.5f, ro, rd);
    check(e == FOV_OK && ro[0] == 0.25f && ro[1] == 0.0f && ro[2] == 5.0f,
          "eye_offset_pt_ray_origin", "origin %g %g %g", (double)ro[0], (double)ro[1],
          (double)ro[2]);
    for (m = 0; m < (uint32_t)_FOVPT_METHOD_NUM; ++m) {
        fovpt_material mat[2];
        fovpt_shape sh[3];
        fovpt_scene_desc d;
        fovpt_scene scene;
        fovpt_config cfg = fovpt_config_default();
        fov_gaze g = {10.0f, 7.0f};
        void *smem = NULL;
        size_t sb = 0;
        int v, same = 1;
        uint32_t f;
        float pl[3] = {0.0f, -1.0f, 0.0f}, nz[3] = {0.0f, 1.0f, 0.0f};
        fovpt_material_init(&mat[0]);
        fovpt_material_init(&mat[1]);
        mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 3.0f;
        fovpt_shape_sphere(&sh[0], 0.3f, 0.0f, 0.0f, 1.0f, 0);
        fovpt_shape_sphere(&sh[1], -1.0f, 2.5f, 1.0f, 0.5f, 1);
        fovpt_shape_plane(&sh[2], pl, nz, 0);
        fovpt_scene_desc_init(&d);
        d.shapes = sh;
        d.num_shapes = 3;
        d.materials = mat;
        d.num_materials = 2;
        fovpt_scene_size(&d, &sb);
        smem = malloc(sb);
        e = fovpt_scene_build(&scene, &d, smem, sb);
        cfg.method = m;
        for (v = 0; v < 2 && e == FOV_OK; ++v) {
            fovpt_camera c = cam;
            fovpt_ctx ctx;
            fovpt_output out;
            size_t cb = 0;
            void *cmem;
            if (v == 1) {
                c.eye_offset = 0.0f;
                c.pos[0] = 0.25f;
                c.target[0] = 0.25f;
            }
            e = fovpt_memory_size(&cfg, &c, &cb);
            if (e != FOV_OK) break;
            cmem = malloc(cb ? cb : 1);
            e = fovpt_init(&ctx, &cfg, &scene, &c, g, cmem, cb);
            fovpt_output_init(&out);
            out.rgb = img[v];
            for (f = 0; f < 3 && e == FOV_OK; ++f) {
                if (f > 0) e = fovpt_set_view(&ctx, &c, g);
                if (e == FOV_OK) e = fovpt_render(&ctx, f, &out, NULL);
            }
            free(cmem);
        }
        if (e == FOV_OK) same = memcmp(img[0], img[1], sizeof img[0]) == 0;
        check(e == FOV_OK && same,
              N("eye_offset_pt_render_%s_equals_moved_camera", fovpt_method_name(m)), "%s%s",
              fovpt_result_string(e), same ? "" : ", images differ");
        free(smem);
    }
    {
        fovsdf_camera c0, c1;
        fovsdf_ctx k0, k1;
        ball b = {{0.3f, 0.0f, 0.0f}, 1.0f};
        static float im0[W * H * 3], im1[W * H * 3];
        fovsdf_output o0, o1;
        fovsdf_camera_init(&c0, W, H);
        c0.eye_offset = 0.25f;
        c1 = c0;
        c1.eye_offset = 0.0f;
        c1.pos[0] = 0.25f;
        c1.target[0] = 0.25f;
        fovsdf_output_init(&o0);
        o0.rgb = im0;
        fovsdf_output_init(&o1);
        o1.rgb = im1;
        e = sdf_ctx(&k0, &c0, &b, NULL);
        if (e == FOV_OK) e = sdf_ctx(&k1, &c1, &b, NULL);
        if (e == FOV_OK) e = fovsdf_render_rows(&k0, 0, H, &o0, NULL);
        if (e == FOV_OK) e = fovsdf_render_rows(&k1, 0, H, &o1, NULL);
        check(e == FOV_OK && memcmp(im0, im1, sizeof im0) == 0,
              "eye_offset_sdf_render_equals_moved_camera", "%s", fovsdf_result_string(e));
    }
    /* fovpt_gaze_from_point sees from the pinhole: the point straight ahead of it is the
       image centre */
    {
        float p[3] = {0.25f, 0.0f, 0.0f};
        fov_gaze g;
        e = fovpt_gaze_from_point(&cam, p, &g);
        check(e == FOV_OK && fabsf(g.x - 12.0f) < 1e-4f && fabsf(g.y - 8.0f) < 1e-4f,
              "eye_offset_pt_gaze_from_pinhole", "(%g, %g), want (12, 8)", (double)g.x,
              (double)g.y);
    }
}

/* 6. off-axis tangents (an HMD eye): accepted by every header; bad tangents rejected and
   logged with the field's name */
static void test_off_axis_errors(void)
{
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovlp_camera lc;
    ball b = {{0.0f, 0.0f, 0.0f}, 1.0f};
    rec r;
    fov_logger lg;
    fov_result e;
    memset(&r, 0, sizeof r);
    lg.func = rec_log;
    lg.user = &r;
    fovsdf_camera_init(&cam, 16, 16);
    cam.tan_left = 0.5f;
    cam.tan_right = 0.7f;
    cam.tan_bottom = 0.5f;
    cam.tan_top = 0.7f; /* (0.5 + 0.7) / (0.5 + 0.7): the 16 x 16 image's aspect */
    e = sdf_ctx(&ctx, &cam, &b, &lg);
    check(e == FOV_OK && r.calls == 0 && ctx.off_axis == 1u, "off_axis_sdf_accepted", "%s",
          fovsdf_result_string(e));
    e = fovlp_camera_from(&cam, &lc);
    check(e == FOV_OK && fabsf(lc.tan_half_y - 0.6f) < 1e-6f, "off_axis_lp_camera_from",
          "%s %g", fovlp_result_string(e), (double)lc.tan_half_y);
    /* review item: tangents whose ratio is not the image's aspect (non-square pixels) are
       FOV_ERR_UNSUPPORTED with a message in every header; within 1e-3 they are accepted */
    {
        fovpt_config pc = fovpt_config_default();
        fovlp_config lcfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 16, 16), lo;
        fovlp_ctx lctx;
        fov_display dsp;
        fov_gaze g = { 8.0f, 8.0f };
        size_t nb = 0;
        void *lmem;
        rec r2;
        fov_logger lg2;
        memset(&r2, 0, sizeof r2);
        lg2.func = rec_log;
        lg2.user = &r2;
        cam.tan_top = 0.6f; /* (0.5 + 0.7) / (0.5 + 0.6) = 1.09, the image 1 */
        e = sdf_ctx(&ctx, &cam, &b, &lg2);
        check(e == FOV_ERR_UNSUPPORTED && r2.calls == 1 &&
              r2.code == (int32_t)FOV_ERR_UNSUPPORTED, "off_axis_aspect_sdf_unsupported",
              "%s, %d calls", fovsdf_result_string(e), r2.calls);
#ifndef FOV_NO_ERROR_STRINGS
        check(strstr(r2.msg, "width / height") != NULL, "off_axis_aspect_sdf_message", "\"%s\"",
              r2.msg);
#endif
        pc.logger = lg2;
        r2.calls = 0;
        e = fovpt_memory_size(&pc, &cam, &nb);
        check(e == FOV_ERR_UNSUPPORTED && r2.calls == 1, "off_axis_aspect_pt_unsupported",
              "%s, %d calls", fovpt_result_string(e), r2.calls);
#ifndef FOV_NO_ERROR_STRINGS
        check(strstr(r2.msg, "width / height") != NULL, "off_axis_aspect_pt_message", "\"%s\"",
              r2.msg);
#endif
        check(fovsdf_camera_display(&cam, &dsp) == FOV_ERR_UNSUPPORTED &&
              fovlp_camera_display(&cam, &dsp) == FOV_ERR_UNSUPPORTED &&
              fovpt_camera_display(&cam, &dsp) == FOV_ERR_UNSUPPORTED,
              "off_axis_aspect_camera_display_unsupported", "-");
        lcfg.taa.frustum[0] = 0.5f; lcfg.taa.frustum[1] = 0.7f;
        lcfg.taa.frustum[2] = 0.5f; lcfg.taa.frustum[3] = 0.6f;
        lcfg.logger = lg2;
        r2.calls = 0;
        e = fovlp_config_resolve(&lcfg, &lo);
        check(e == FOV_ERR_UNSUPPORTED && r2.calls == 1, "off_axis_aspect_lp_frustum_unsupported",
              "%s", fovlp_result_string(e));
#ifndef FOV_NO_ERROR_STRINGS
        check(strstr(r2.msg, "width / height") != NULL, "off_axis_aspect_lp_message", "\"%s\"",
              r2.msg);
#endif
        /* fovlp_camera_from keeps them (the fovlp image may differ from the camera's); the
           context checks them against its image */
        memset(lcfg.taa.frustum, 0, sizeof lcfg.taa.frustum);
        fovlp_memory_size(&lcfg, &nb);
        lmem = malloc(nb);
        check(fovlp_init(&lctx, &lcfg, lmem, nb) == FOV_OK &&
                  fovlp_camera_from(&cam, &lc) == FOV_OK &&
                  fovlp_begin_frame(&lctx, g, &lc) == FOV_ERR_UNSUPPORTED,
              "off_axis_aspect_lp_begin_frame_unsupported", "-");
        cam.tan_top = 0.7f * (1.0f + 5e-4f); /* within 1e-3: accepted */
        check(sdf_ctx(&ctx, &cam, &b, NULL) == FOV_OK &&
                  fovpt_memory_size(&pc, &cam, &nb) == FOV_OK &&
                  fovlp_camera_display(&cam, &dsp) == FOV_OK &&
                  fovlp_camera_from(&cam, &lc) == FOV_OK &&
                  fovlp_begin_frame(&lctx, g, &lc) == FOV_OK,
              "off_axis_aspect_within_1e-3_accepted", "-");
        cam.tan_top = 0.7f;
        free(lmem);
    }
    cam.tan_left = -0.7f; /* left + right <= 0 */
    e = sdf_ctx(&ctx, &cam, &b, &lg);
    check(e == FOV_ERR_INVALID_ARG && r.calls == 1 && r.code == (int32_t)FOV_ERR_INVALID_ARG,
          "off_axis_sdf_bad_tangents_rejected_and_logged", "%s, %d log calls",
          fovsdf_result_string(e), r.calls);
#ifndef FOV_NO_ERROR_STRINGS
    check(strstr(r.msg, "tan_") != NULL, "off_axis_sdf_message_names_field", "message \"%s\"",
          r.msg);
#endif
    check(fovlp_camera_from(&cam, &lc) == FOV_ERR_INVALID_ARG, "off_axis_lp_bad_tangents", "-");
    cam.tan_left = (float)NAN;
    check(sdf_ctx(&ctx, &cam, &b, NULL) == FOV_ERR_NOT_FINITE, "off_axis_sdf_nan_tangent", "-");
    cam.tan_left = cam.tan_right = cam.tan_bottom = 0.0f;
    cam.tan_top = -0.0f; /* -0 is 0: symmetric */
    e = sdf_ctx(&ctx, &cam, &b, &lg);
    check(e == FOV_OK && ctx.off_axis == 0u && fovlp_camera_from(&cam, &lc) == FOV_OK,
          "zero_tangents_symmetric", "%s", fovsdf_result_string(e));
    {
        fovlp_config lcfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 64, 48), out;
        lcfg.taa.frustum[0] = 0.5f;
        lcfg.taa.frustum[1] = -0.6f;
        check(fovlp_config_resolve(&lcfg, &out) == FOV_ERR_INVALID_ARG, "lp_bad_frustum", "-");
        lcfg.taa.frustum[1] = (float)INFINITY;
        check(fovlp_config_resolve(&lcfg, &out) == FOV_ERR_NOT_FINITE, "lp_inf_frustum", "-");
    }
}

/* 7. symmetric frusta are today's camera, bit for bit: with the tangents 0, fovsdf's rays are
   the formula of fov_camera worked out here in the same float operations (u = (x / W 2 - 1)
   tan(fov / 2) W / H, v = (1 - y / H 2) tan(fov / 2), fwd + u right + v up, normalised the
   library's way: the three divisions by the length) from fovsdf_camera_basis's frame; the
   context's eccentricity model is the one fovsdf_ecc_init gives for the camera's field of
   view */
static void test_symmetric_bitwise(void)
{
    int it, bad = 0, n = 0;
    for (it = 0; it < 200; ++it) {
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        fov_ecc_model em;
        float rt[3], up[3], fw[3], tanh, asp;
        ball b = {{0.0f, 0.0f, 0.0f}, 0.1f};
        int k, j;
        fovsdf_camera_init(&cam, 8u + (uint32_t)frand(0.0f, 900.0f),
                           8u + (uint32_t)frand(0.0f, 900.0f));
        for (k = 0; k < 3; ++k) {
            cam.pos[k] = frand(-20.0f, 20.0f);
            cam.target[k] = frand(-20.0f, 20.0f);
        }
        cam.fov_y_deg = frand(10.0f, 150.0f);
        if (it % 2) cam.eye_offset = frand(-0.05f, 0.05f);
        if (sdf_ctx(&ctx, &cam, &b, NULL) != FOV_OK ||
            fovsdf_camera_basis(&cam, rt, up, fw) != FOV_OK) {
            bad++;
            continue;
        }
        tanh = tanf(0.5f * cam.fov_y_deg * 0.0174532925199433f);
        asp = (float)cam.width / (float)cam.height;
        {
            fov_gaze g;
            g.x = 0.5f * (float)cam.width;
            g.y = 0.5f * (float)cam.height;
            fovsdf_ecc_init(&em, NULL, cam.fov_y_deg, cam.width, cam.height, g);
            if (memcmp(&em, &ctx.ecc, sizeof em)) bad++; /* the same call as before */
        }
        for (j = 0; j < 10; ++j) {
            float x = frand(0.0f, 1.0f) * (float)cam.width;
            float y = frand(0.0f, 1.0f) * (float)cam.height;
            float u = (x / (float)cam.width * 2.0f - 1.0f) * tanh * asp;
            float v = (1.0f - y / (float)cam.height * 2.0f) * tanh, d[3], l, ro[3], rd[3];
            for (k = 0; k < 3; ++k) d[k] = fw[k] + u * rt[k] + v * up[k];
            l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (k = 0; k < 3; ++k) d[k] /= l;
#ifndef FOV_NO_LIBM
            if (fovsdf_camera_ray(&ctx, x, y, ro, rd) != FOV_OK || memcmp(rd, d, sizeof d)) bad++;
#else /* the library's own tan and sqrt approximations: within a few ulps of libm's */
            if (fovsdf_camera_ray(&ctx, x, y, ro, rd) != FOV_OK ||
                ulps_apart(rd[0], d[0]) > 8.0 || ulps_apart(rd[1], d[1]) > 8.0 ||
                ulps_apart(rd[2], d[2]) > 8.0)
                bad++;
#endif
            n++;
        }
    }
    check(bad == 0 && n == 2000, "symmetric_sdf_rays_bit_for_bit", "%d of %d differ", bad, n);
}

/* 9. every fovsdf method renders an off-axis frustum whose tangents are the symmetric ones
   (l = r = tan(30 deg) W / H, b = t = tan 30 deg) as the symmetric camera: the rays differ in
   the last bits only, so the images agree to 1e-3 in 99 % of the pixel values */
static void test_off_axis_render(void)
{
    enum { W = 48, H = 32 };
    static float im0[W * H * 3], im1[W * H * 3];
    uint32_t m;
    for (m = 0; m <= (uint32_t)FOVSDF_METHOD_CONE_FOV; ++m) {
        fovsdf_camera c0, c1;
        fovsdf_ctx k0, k1;
        fovsdf_scene sc;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_output o0, o1;
        ball b = {{0.3f, 0.0f, 0.0f}, 1.0f};
        fov_gaze g = {20.0f, 14.0f};
        fov_result e;
        int i, close = 0;
        float t = tanf(30.0f * 0.0174532925199433f);
        fovsdf_scene_init(&sc);
        sc.dist = ball_sdf;
        sc.user = &b;
        cfg.method = m;
        fovsdf_camera_init(&c0, W, H);
        c1 = c0;
        c1.tan_left = c1.tan_right = t * (float)W / (float)H;
        c1.tan_bottom = c1.tan_top = t;
        fovsdf_output_init(&o0);
        o0.rgb = im0;
        fovsdf_output_init(&o1);
        o1.rgb = im1;
        e = fovsdf_init(&k0, &cfg, &sc, &c0, g, NULL, 0);
        if (e == FOV_OK) e = fovsdf_init(&k1, &cfg, &sc, &c1, g, NULL, 0);
        if (e == FOV_OK) e = fovsdf_render_rows(&k0, 0, H, &o0, NULL);
        if (e == FOV_OK) e = fovsdf_render_rows(&k1, 0, H, &o1, NULL);
        for (i = 0; i < W * H * 3; ++i) close += fabsf(im0[i] - im1[i]) <= 1e-3f;
        check(e == FOV_OK && close >= (W * H * 3) * 99 / 100,
              N("off_axis_render_method%u_equals_symmetric", m), "%s, %d of %d close",
              fovsdf_result_string(e), close, W * H * 3);
    }
}

/* 10. fovlp's reprojection with taa.frustum: given the symmetric camera's own tangents
   (l = r = tan(fov / 2) W / H, b = t = tan(fov / 2)) it finds the same history pixels as
   without (frustum 0): a camera moving towards a plane at a known depth, the TAA outputs
   agree to 1e-4 in 99 % of the values; a frustum whose axis is the image's left edge (l 0,
   r 2 tan W / H) scales the image about that edge instead of the centre: different history
   pixels (the off-axis path is used) */
static void lp_taa_run(const float frustum[4], float *out, fovlp_taa_stats *st)
{
    enum { W = 64, H = 48 };
    static float cur[W * H * 3], dep[W * H], prev[W * H * 3], pdep[W * H], hdep[W * H];
    static uint8_t age[W * H], oage[W * H];
    fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    fovlp_ctx ctx;
    fov_camera c;
    fovlp_camera lc;
    fovlp_taa_io io;
    fov_gaze g = {32.0f, 24.0f};
    size_t bytes = 0;
    void *mem;
    int i, f;
    cfg.taa.enable = 1;
    for (i = 0; i < 4; ++i) cfg.taa.frustum[i] = frustum[i];
    fovlp_memory_size(&cfg, &bytes);
    mem = malloc(bytes ? bytes : 1);
    if (fovlp_init(&ctx, &cfg, mem, bytes) != FOV_OK) { free(mem); return; }
    for (i = 0; i < W * H; ++i) {
        prev[3 * i] = (float)(i % 7) * 0.1f; prev[3 * i + 1] = (float)(i % 5) * 0.2f;
        prev[3 * i + 2] = 0.5f;
        cur[3 * i] = (float)(i % 3) * 0.3f; cur[3 * i + 1] = (float)(i % 11) * 0.05f;
        cur[3 * i + 2] = 0.3f;
        age[i] = 5;
    }
    for (f = 0; f < 2; ++f) {
        fovtest_camera_init(&c, W, H);
        c.pos[2] = 5.0f - 0.5f * (float)f; /* a dolly towards the plane z = 0 */
        fovlp_camera_from(&c, &lc);
        fovlp_begin_frame(&ctx, g, &lc);
        for (i = 0; i < W * H; ++i) { /* the plane z = 0 seen from z = 5: depth along the ray */
            float x = ((float)(i % W) + 0.5f) / W * 2.0f - 1.0f;
            float y = ((float)(i / W) + 0.5f) / H * 2.0f - 1.0f;
            float t = tanf(30.0f * 0.0174532925199433f), sx = x * t * W / H, sy = y * t;
            dep[i] = c.pos[2] * sqrtf(1.0f + sx * sx + sy * sy);
            pdep[i] = 5.0f * sqrtf(1.0f + sx * sx + sy * sy);
        }
        fovlp_taa_io_init(&io);
        io.cur_rgb = cur; io.cur_depth = dep;
        io.prev_rgb = prev; io.prev_depth = pdep; io.prev_age = age;
        io.out_rgb = out; io.out_depth = hdep; io.out_age = oage;
        fovlp_taa_stats_init(st);
        fovlp_taa_rows(&ctx, &io, 0, H, st);
    }
    free(mem);
}
static void test_lp_frustum(void)
{
    static float a[64 * 48 * 3], b[64 * 48 * 3], c[64 * 48 * 3];
    float t = tanf(30.0f * 0.0174532925199433f), z[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    float sym[4], shift[4];
    int i, same = 0, diff = 0;
    fovlp_taa_stats sa, sb, sc;
    sym[0] = sym[1] = t * 64.0f / 48.0f; sym[2] = sym[3] = t;
    shift[0] = 0.0f; shift[1] = 2.0f * t * 64.0f / 48.0f; shift[2] = shift[3] = t;
    lp_taa_run(z, a, &sa);
    lp_taa_run(sym, b, &sb);
    lp_taa_run(shift, c, &sc);
    for (i = 0; i < 64 * 48 * 3; ++i) {
        same += fabsf(a[i] - b[i]) <= 1e-4f;
        diff += fabsf(a[i] - c[i]) > 1e-4f;
    }
    check(same >= 64 * 48 * 3 * 99 / 100 && sa.rejected == sb.rejected &&
          sa.kept_periphery == sb.kept_periphery, "lp_taa_frustum_symmetric_equals_plain",
          "%d of %d values, rejected %llu / %llu", same, 64 * 48 * 3,
          (unsigned long long)sa.rejected, (unsigned long long)sb.rejected);
    check(diff > 0 && sc.rejected > sa.rejected, "lp_taa_frustum_shifted_differs",
          "%d values differ, rejected %llu / %llu", diff, (unsigned long long)sc.rejected,
          (unsigned long long)sa.rejected);
}

/* an independent reference of an off-axis eye, in double: the frame of fov_camera from pos,
   target, up; the ray through (x, y) is fwd + (-l + (l + r) x / W) right + (t - (t + b) y / H)
   up from pos + eye_offset right */
static void ref_ray(const fov_camera *c, double x, double y, double o[3], double d[3])
{
    double f[3], u[3], r[3], l;
    int k;
    for (k = 0; k < 3; ++k) { f[k] = (double)c->target[k] - (double)c->pos[k]; u[k] = c->up[k]; }
    l = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (k = 0; k < 3; ++k) f[k] /= l;
    r[0] = f[1] * u[2] - f[2] * u[1];
    r[1] = f[2] * u[0] - f[0] * u[2];
    r[2] = f[0] * u[1] - f[1] * u[0];
    l = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (k = 0; k < 3; ++k) r[k] /= l;
    u[0] = r[1] * f[2] - r[2] * f[1];
    u[1] = r[2] * f[0] - r[0] * f[2];
    u[2] = r[0] * f[1] - r[1] * f[0];
    {
        double tl = c->tan_left, tr = c->tan_right, tb = c->tan_bottom, tt = c->tan_top;
        double sx = -tl + (tl + tr) * x / c->width, sy = tt - (tt + tb) * y / c->height;
        for (k = 0; k < 3; ++k) {
            d[k] = f[k] + sx * r[k] + sy * u[k];
            o[k] = (double)c->pos[k] + (double)c->eye_offset * r[k];
        }
    }
    l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (k = 0; k < 3; ++k) d[k] /= l;
}

/* 8. per-eye off-axis rays (OpenVR-like tangents of a left and a right eye, each with its own
   gaze) from fovsdf and fovpt against the reference; the eccentricity of the same pixel in
   fovsdf's, fovpt's and fovlp's context (fovlp given fovlp_camera_display) against the angle
   between the reference rays through the pixel and through the gaze */
static void test_off_axis_eyes(void)
{
    /* tangents as OpenVR's GetProjectionRaw gives them for a left eye (left, right, top,
       bottom = -1.39, 1.24, -1.47, 1.46), made positive; the right eye mirrored */
    static const float tl[2] = { 1.39f, 1.24f }, tr[2] = { 1.24f, 1.39f };
    enum { W = 263, H = 293 }; /* square pixels: (l + r) / W = (t + b) / H */
    int eye, worst_ok = 1, ecc_ok = 1, three_ok = 1;
    double worst = 0.0, worst_e = 0.0, worst_3 = 0.0;
    for (eye = 0; eye < 2; ++eye) {
        fovsdf_camera cam;
        fovsdf_ctx sctx;
        fovpt_ctx pctx;
        fovlp_ctx lctx;
        fovlp_config lcfg;
        fovpt_config pcfg = fovpt_config_default();
        fovpt_material mat;
        fovpt_shape sh;
        fovpt_scene_desc d;
        fovpt_scene scene;
        fov_gaze g;
        ball b = {{0.0f, 0.0f, 0.0f}, 0.5f};
        void *smem, *pmem, *lmem;
        size_t sb = 0, pb = 0, lb = 0;
        fov_result e1, e2, e3;
        int x, y;
        fovsdf_camera_init(&cam, W, H);
        cam.pos[0] = 0.3f; cam.pos[1] = 0.2f; cam.pos[2] = 4.0f;
        cam.target[0] = -0.1f; cam.target[1] = 0.1f;
        cam.eye_offset = eye ? 0.032f : -0.032f;
        cam.tan_left = tl[eye]; cam.tan_right = tr[eye];
        cam.tan_top = 1.47f; cam.tan_bottom = 1.46f;
        g.x = eye ? 150.0f : 110.0f; /* a per-eye gaze: the eyes converge */
        g.y = 140.0f;
        {
            fovsdf_scene sc;
            fovsdf_scene_init(&sc);
            sc.dist = ball_sdf;
            sc.user = &b;
            e1 = fovsdf_init(&sctx, NULL, &sc, &cam, g, NULL, 0);
        }
        fovpt_material_init(&mat);
        fovpt_shape_sphere(&sh, 0.0f, 0.0f, 0.0f, 0.5f, 0);
        fovpt_scene_desc_init(&d);
        d.shapes = &sh; d.num_shapes = 1; d.materials = &mat; d.num_materials = 1;
        fovpt_scene_size(&d, &sb);
        smem = malloc(sb);
        e2 = fovpt_scene_build(&scene, &d, smem, sb);
        if (e2 == FOV_OK) e2 = fovpt_memory_size(&pcfg, &cam, &pb);
        pmem = malloc(pb ? pb : 1);
        if (e2 == FOV_OK) e2 = fovpt_init(&pctx, &pcfg, &scene, &cam, g, pmem, pb);
        lcfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
        e3 = fovlp_camera_display(&cam, &lcfg.display);
        lcfg.taa.frustum[0] = cam.tan_left; lcfg.taa.frustum[1] = cam.tan_right;
        lcfg.taa.frustum[2] = cam.tan_bottom; lcfg.taa.frustum[3] = cam.tan_top;
        if (e3 == FOV_OK) e3 = fovlp_memory_size(&lcfg, &lb);
        lmem = malloc(lb ? lb : 1);
        if (e3 == FOV_OK) e3 = fovlp_init(&lctx, &lcfg, lmem, lb);
        if (e3 == FOV_OK) e3 = fovlp_begin_frame(&lctx, g, NULL);
        check(e1 == FOV_OK && e2 == FOV_OK && e3 == FOV_OK, N("off_axis_eye%d_contexts", eye),
              "%d %d %d", (int)e1, (int)e2, (int)e3);
        if (e1 == FOV_OK && e2 == FOV_OK && e3 == FOV_OK)
            for (y = 0; y <= H; y += 21)
                for (x = 0; x <= W; x += 19) {
                    double o[3], dr[3], og[3], dg[3], c, ang;
                    float ro[3], rd[3], po[3], pd[3], es, ep, el;
                    int k;
                    ref_ray(&cam, x + 0.5, y + 0.5, o, dr);
                    fovsdf_camera_ray(&sctx, (float)x + 0.5f, (float)y + 0.5f, ro, rd);
                    fovpt_camera_ray(&cam, (float)x + 0.5f, (float)y + 0.5f, po, pd);
                    for (k = 0; k < 3; ++k) {
                        worst = fmax(worst, fabs((double)rd[k] - dr[k]));
                        worst = fmax(worst, fabs((double)pd[k] - dr[k]));
                        worst = fmax(worst, fabs((double)ro[k] - o[k]));
                    }
                    ref_ray(&cam, (double)g.x, (double)g.y, og, dg);
                    c = dr[0] * dg[0] + dr[1] * dg[1] + dr[2] * dg[2];
                    ang = acos(fmin(1.0, c)) * 180.0 / 3.14159265358979;
                    es = fovsdf_ecc_deg(&sctx.ecc, (float)x + 0.5f, (float)y + 0.5f);
                    ep = fovpt_ecc_deg(&pctx.ecc, (float)x + 0.5f, (float)y + 0.5f);
                    el = fovlp_ecc_deg(&lctx.ecc, (float)x + 0.5f, (float)y + 0.5f);
                    worst_e = fmax(worst_e, fabs((double)es - ang));
                    worst_3 = fmax(worst_3, fmax(fabs((double)es - (double)ep),
                                                 fabs((double)es - (double)el)));
                }
        free(smem); free(pmem); free(lmem);
    }
    printf("     (off-axis eyes: rays within %.3g of the reference, eccentricity within %.3g deg, "
           "headers within %.3g deg)\n", worst, worst_e, worst_3);
    worst_ok = worst <= 2e-6;
    ecc_ok = worst_e <= 2e-3;
    three_ok = worst_3 <= 2e-3;
    check(worst_ok, "off_axis_eye_rays_match_reference", "worst component error %.3g", worst);
    check(ecc_ok, "off_axis_ecc_matches_reference_angle", "worst %.3g deg", worst_e);
    check(three_ok, "off_axis_three_headers_same_ecc", "worst %.3g deg", worst_3);
}

int main(int argc, char **argv)
{
    if (argc > 1 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        printf("usage: %s\n  checks fov_camera: one type and the same defaults in fovsdf.h, "
               "fovlp.h and fovpt.h,\n"
               "  the documented handedness, fovsdf and fovpt rays agree, fovlp_camera_from, "
               "eye_offset\n",
               argv[0]);
        return 0;
    }
    test_defaults();
    test_handedness();
    test_render_sides();
    test_rays_agree();
    test_eye_offset();
    test_off_axis_errors();
    test_symmetric_bitwise();
    test_off_axis_eyes();
    test_off_axis_render();
    test_lp_frustum();
    return fovcheck_summary();
}
