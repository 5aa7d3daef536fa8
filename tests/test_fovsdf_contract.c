/*
 * test_fovsdf_contract.c - fovsdf.h's API contract at the edges of float (issue 10, findings
 * F1, F2, F6 and the version string): camera rays and pinholes at extreme values, builder and
 * program parameters at and beyond their bounds, the one node check shared by the builder and
 * fovsdf_program_build, primitive and operator evaluations with extreme valid parameters, and
 * the documented ranges of every FOV_OK render's rgb/rgb8/depth.
 *
 * Build and run from the repository root (tests/run_all.sh builds it three ways: libm,
 * -DFOV_NO_LIBM, sanitizers):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_fovsdf_contract.c -lm -o build/tests/t
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed". Expected
 * values come from double-precision arithmetic here (normalised vectors, analytic plane and
 * sphere distances and hits), never from the library.
 */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fovcheck.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name /* tests/common/fovcheck.h */

static float f_nan(void)
{
    volatile float z = 0.0f;
    return z / z;
}
static int finite_f(float x) { return x >= -FLT_MAX && x <= FLT_MAX; }
static double len3d(const float v[3])
{
    double x = (double)v[0], y = (double)v[1], z = (double)v[2];
    return sqrt(x * x + y * y + z * z);
}

/* ---- a logger that keeps the last message ------------------------------------------------ */
typedef struct logrec {
    int calls;
    int32_t code;
    char msg[256];
} logrec;
static void rec_log(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    logrec *r = (logrec *)user;
    (void)tag; (void)level; (void)line;
    r->calls++;
    r->code = code;
    snprintf(r->msg, sizeof r->msg, "%s", msg ? msg : "(null)");
}
static void rec_init(logrec *r) { memset(r, 0, sizeof *r); }

/* ---- scenes -------------------------------------------------------------------------------- */
typedef struct sph_scene { double c[3], r; } sph_scene;
static float sph_dist(const float p[3], void *user)
{
    const sph_scene *s = (const sph_scene *)user;
    double dx = (double)p[0] - s->c[0], dy = (double)p[1] - s->c[1], dz = (double)p[2] - s->c[2];
    return (float)(sqrt(dx * dx + dy * dy + dz * dz) - s->r);
}

/* Every output of a FOV_OK render within its documented range: rgb in [0, 65504] and finite,
   depth finite and >= 0, hit 0/1. Returns the number of violations (first one in *what). */
static int out_ok(const float *rgb, const float *depth, const uint8_t *hit, uint32_t n, char *what, size_t wn)
{
    uint32_t i;
    int bad = 0;
    for (i = 0; i < 3u * n; ++i)
        if (!(rgb[i] >= 0.0f && rgb[i] <= 65504.0f)) {
            if (!bad) snprintf(what, wn, "rgb[%u] = %g", i, (double)rgb[i]);
            ++bad;
        }
    for (i = 0; i < n; ++i) {
        if (!(depth[i] >= 0.0f && finite_f(depth[i]))) {
            if (!bad) snprintf(what, wn, "depth[%u] = %g", i, (double)depth[i]);
            ++bad;
        }
        if (hit[i] > 1u) {
            if (!bad) snprintf(what, wn, "hit[%u] = %u", i, hit[i]);
            ++bad;
        }
    }
    return bad;
}

#define IMG 8
/* Renders a program scene at IMG x IMG with a method and shading; checks the outputs. */
static void render_check(const char *name, const fovsdf_program *prog, const fovsdf_camera *cam, uint32_t method,
                         uint32_t shading, float t_max)
{
    fovsdf_scene sc;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fovsdf_output out;
    float rgb[IMG * IMG * 3], depth[IMG * IMG];
    uint8_t hit[IMG * IMG], rgb8[IMG * IMG * 3];
    fov_gaze g = { IMG * 0.5f, IMG * 0.5f };
    fov_result r;
    char what[128] = "";
    int bad;
    fovsdf_scene_init(&sc);
    fovsdf_scene_set_program(&sc, prog);
    sc.t_max = t_max;
    cfg.method = method;
    cfg.shading = shading;
    cfg.max_steps = 128;
    r = fovsdf_init(&ctx, &cfg, &sc, cam, g, NULL, 0);
    if (!check(r == FOV_OK, N("%s_init", name), "fovsdf_init: %s", fovsdf_result_string(r))) return;
    fovsdf_output_init(&out);
    out.rgb = rgb; out.depth = depth; out.hit = hit; out.rgb8 = rgb8;
    r = fovsdf_render_rows(&ctx, 0, IMG, &out, NULL);
    bad = r == FOV_OK ? out_ok(rgb, depth, hit, IMG * IMG, what, sizeof what) : 0;
    check(r == FOV_OK && bad == 0, name, "render %s, %d outputs out of range (first: %s)", fovsdf_result_string(r), bad,
          what);
}

static unsigned char g_mem[1 << 16];
/* Builds nodes[0 .. count) under root into a program in g_mem. */
static fov_result build(fovsdf_program *prog, const fovsdf_node *nodes, uint32_t count, int32_t root)
{
    size_t bytes = 0;
    fov_result r = fovsdf_program_size(nodes, count, root, &bytes);
    if (r != FOV_OK) return r;
    if (bytes > sizeof g_mem) return FOV_ERR_TOO_SMALL;
    return fovsdf_program_build(prog, nodes, count, root, g_mem, sizeof g_mem);
}

/* ==== version ================================================================================ */
static void test_version(void)
{
    char want[32], line[256];
    FILE *f;
    snprintf(want, sizeof want, "%d.%d.%d", FOVSDF_VERSION_MAJOR, FOVSDF_VERSION_MINOR, FOVSDF_VERSION_PATCH);
    check(strcmp(want, FOVSDF_VERSION_STRING) == 0, "version_string_matches_macros", "FOVSDF_VERSION_STRING \"%s\", macros %s",
          FOVSDF_VERSION_STRING, want);
    f = fopen("fovsdf.h", "r");
    if (f && fgets(line, sizeof line, f)) {
        char v[40];
        snprintf(v, sizeof v, " - v%s - ", FOVSDF_VERSION_STRING);
        check(strstr(line, v) != NULL, "version_string_matches_line_1", "line 1 \"%.60s\" lacks \"%s\"", line, v);
    } else {
        check(0, "version_string_matches_line_1", "cannot read fovsdf.h (run from the repository root)");
    }
    if (f) fclose(f);
}

/* ==== F1: camera rays, pinholes, shade_point ================================================= */
static void test_f1(void)
{
    static sph_scene unit = { { 0.0, 0.0, 0.0 }, 1.0 };
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fov_gaze g = { 0.5f, 0.5f };
    fov_result r;
    logrec lr;
    float ro[3], rd[3], rgb[3], t;
    int32_t mat;

    fovsdf_scene_init(&sc);
    sc.dist = sph_dist;
    sc.user = &unit;
    sc.t_max = 60.0f;
    rec_init(&lr);
    cfg.logger.func = rec_log;
    cfg.logger.user = &lr;

    /* the camera: 1x1, eye_offset 3e38, up (3e38, 3e38, 3e38): the pinhole lies 3e38
       from the origin, where float cannot resolve positions (its square is inf) */
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    cam.eye_offset = 3e38f;
    cam.up[0] = cam.up[1] = cam.up[2] = 3e38f;
    r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
    check(r == FOV_ERR_INVALID_ARG && lr.calls == 1 && strstr(lr.msg, "eye_offset") != NULL, "f1_eye_offset_3e38_rejected",
          "fovsdf_init %s, %d log calls, message \"%s\"", fovsdf_result_string(r), lr.calls, lr.msg);
    /* a position beyond the bound */
    rec_init(&lr);
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    cam.pos[0] = 2e18f; cam.target[0] = 2e18f; cam.target[2] = 1.0f;
    r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
    check(r == FOV_ERR_INVALID_ARG && lr.calls == 1 && strstr(lr.msg, "cam.pos") != NULL, "f1_pos_2e18_rejected",
          "fovsdf_init %s, message \"%s\"", fovsdf_result_string(r), lr.msg);
    /* both within the bound, the pinhole beyond it (1e18 + 0.9e18 along right = -x) */
    rec_init(&lr);
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    cam.pos[0] = -1e18f; cam.target[0] = -1e18f; cam.target[2] = 1.0f; cam.eye_offset = 9e17f;
    r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
    check(r == FOV_ERR_INVALID_ARG && strstr(lr.msg, "pinhole") != NULL, "f1_pinhole_beyond_1e18_rejected",
          "fovsdf_init %s, message \"%s\"", fovsdf_result_string(r), lr.msg);

    /* at the bound it works: camera 9e17 from the origin, a sphere of radius 1e16 whose
       centre lies 1e17 ahead: the hit at t = 9e16 (float resolves ~1e11 there) */
    {
        static sph_scene far_s = { { 9e17, 0.0, 1e17 }, 1e16 };
        fovsdf_scene fs = sc;
        fs.user = &far_s;
        fs.t_max = 1e18f;
        fovsdf_camera_init(&cam, 1, 1);
        cam.pos[0] = 9e17f; cam.pos[2] = 0.0f; cam.target[0] = 9e17f; cam.target[2] = 1.0f;
        r = fovsdf_init(&ctx, NULL, &fs, &cam, g, NULL, 0);
        check(r == FOV_OK, "f1_camera_9e17_valid", "fovsdf_init %s", fovsdf_result_string(r));
        if (r == FOV_OK) {
            r = fovsdf_shade_point(&ctx, 0.5f, 0.5f, rgb, &t, &mat, NULL);
            check(r == FOV_OK && fabs((double)t - 9e16) <= 1e13 && finite_f(rgb[0]) && rgb[0] >= 0.0f,
                  "f1_camera_9e17_hit", "%s, t %.9g (want 9e16 within 1e13), rgb %g", fovsdf_result_string(r), (double)t,
                  (double)rgb[0]);
        }
    }

    /* fovsdf_trace and fovsdf_march: a ray origin beyond the bound (the old code: the floor
       8 FLT_EPSILON |ro| overflowed to inf and every ray hit at t_start) */
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
    if (r == FOV_OK) {
        fovsdf_hit h;
        fovsdf_march_params mp;
        float o3[3] = { 3e38f, 0.0f, 0.0f }, d3[3] = { -1.0f, 0.0f, 0.0f };
        memset(&h, 0, sizeof h);
        rec_init(&lr);
        r = fovsdf_trace(&ctx, o3, d3, 0.0f, &h, NULL);
        check(r == FOV_ERR_INVALID_ARG && lr.calls == 1 && strstr(lr.msg, "ro") != NULL, "f1_trace_ro_3e38_rejected",
              "%s (kind %u, t %g), message \"%s\"", fovsdf_result_string(r), h.kind, (double)h.t, lr.msg);
        memset(&mp, 0, sizeof mp);
        mp.method = FOVSDF_METHOD_CLASSIC; mp.max_steps = 64; mp.eps = 1e-4f; mp.t_max = 100.0f;
        r = fovsdf_march(&sc, &mp, o3, d3, 0.0f, &h, NULL);
        check(r == FOV_ERR_INVALID_ARG, "f1_march_ro_3e38_rejected", "%s (kind %u, t %g)", fovsdf_result_string(r), h.kind,
              (double)h.t);
        /* at the bound: from (1e18, 0, 0) towards the unit sphere, a miss within t_max 100 */
        o3[0] = 1e18f;
        r = fovsdf_trace(&ctx, o3, d3, 0.0f, &h, NULL);
        check(r == FOV_OK && h.kind == FOVSDF_MISS, "f1_trace_ro_1e18_miss", "%s, kind %u, t %g", fovsdf_result_string(r),
              h.kind, (double)h.t);
    }

    /* an image point far off the image: a unit ray along the right direction */
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
    if (check(r == FOV_OK, "f1_base_camera", "%s", fovsdf_result_string(r))) {
        double u = (1e30 * 2.0 - 1.0) * tan(30.0 * 3.14159265358979 / 180.0), e[3], l, err = 0.0, len;
        int k;
        r = fovsdf_camera_ray(&ctx, 1e30f, 0.5f, ro, rd);
        for (k = 0; k < 3; ++k) e[k] = (double)ctx.fwd[k] + u * (double)ctx.right[k];
        l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        for (k = 0; k < 3; ++k) err = fmax(err, fabs((double)rd[k] - e[k] / l));
        len = len3d(rd);
        check(r == FOV_OK && fabs(len - 1.0) < 1e-6 && err < 1e-6, "f1_camera_ray_1e30_unit",
              "%s, rd (%g %g %g) length %.9g, error %.3g", fovsdf_result_string(r), (double)rd[0], (double)rd[1],
              (double)rd[2], len, err);
        r = fovsdf_shade_point(&ctx, 1e30f, 0.5f, rgb, &t, &mat, NULL);
        check(r == FOV_OK && t >= 0.0f && t <= 60.0f && finite_f(rgb[0]) && finite_f(rgb[1]) && finite_f(rgb[2]),
              "f1_shade_point_1e30", "%s, t %g, rgb %g %g %g", fovsdf_result_string(r), (double)t, (double)rgb[0],
              (double)rgb[1], (double)rgb[2]);
        /* tiny and large image points near the image: still unit */
        r = fovsdf_camera_ray(&ctx, -3e20f, 7e19f, ro, rd);
        len = len3d(rd);
        check(r == FOV_OK && fabs(len - 1.0) < 1e-6, "f1_camera_ray_3e20_unit", "%s, length %.9g", fovsdf_result_string(r),
              len);
        /* a direction beyond float: px 3e38 on a 1-pixel-wide image gives u = inf; the ray is
           rescaled, and points along +right (u -> +inf), py -3e38 along +up (v -> +inf) */
        rec_init(&lr);
        r = fovsdf_camera_ray(&ctx, 3e38f, 0.5f, ro, rd);
        len = len3d(rd);
        err = 0.0;
        for (k = 0; k < 3; ++k) err = fmax(err, fabs((double)rd[k] - (double)ctx.right[k]));
        check(r == FOV_OK && lr.calls == 0 && fabs(len - 1.0) < 1e-6 && err < 1e-6, "f1_camera_ray_3e38_unit",
              "%s, message \"%s\", rd length %g, distance from +right %.3g", fovsdf_result_string(r), lr.msg, len, err);
        rec_init(&lr);
        r = fovsdf_camera_ray(&ctx, 0.5f, -3e38f, ro, rd);
        err = 0.0;
        for (k = 0; k < 3; ++k) err = fmax(err, fabs((double)rd[k] - (double)ctx.up[k]));
        check(r == FOV_OK && fabs(len3d(rd) - 1.0) < 1e-6 && err < 1e-6, "f1_camera_ray_py_m3e38_up",
              "%s, distance from +up %.3g", fovsdf_result_string(r), err);
        rec_init(&lr);
        r = fovsdf_shade_point(&ctx, 0.5f, -3e38f, rgb, &t, &mat, NULL);
        check(r == FOV_OK && t >= 0.0f && t <= 60.0f && finite_f(rgb[0]) && finite_f(rgb[1]) && finite_f(rgb[2]),
              "f1_shade_point_3e38", "%s, t %g, rgb %g %g %g", fovsdf_result_string(r), (double)t, (double)rgb[0],
              (double)rgb[1], (double)rgb[2]);
    }
}

/* The camera on the Primitives scene (a checkerboard floor): no NaN hit, nothing past
   t_max, no float-to-int conversion of a NaN in the checkerboard (UBSan aborts on that). */
static void test_f1_primitives(void)
{
    fovsdf_builtin bi;
    static unsigned char mem[1 << 17];
    size_t bytes;
    fov_result r;
    fovsdf_ctx ctx;
    fov_gaze g = { 0.5f, 0.5f };
    float rgb[3], t, n[3] = { 0.0f, 1.0f, 0.0f }, rd[3] = { 0.0f, 0.0f, 1.0f }, p[3];
    int32_t mat;
    if (fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &bytes) != FOV_OK || bytes > sizeof mem ||
        fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &bi, mem, sizeof mem) != FOV_OK) {
        check(0, "f1_primitives_scene", "cannot build");
        return;
    }
    bi.camera.width = bi.camera.height = 1;
    r = fovsdf_init(&ctx, NULL, &bi.scene, &bi.camera, g, NULL, 0);
    if (!check(r == FOV_OK, "f1_primitives_init", "%s", fovsdf_result_string(r))) return;
    r = fovsdf_shade_point(&ctx, 1e30f, 0.5f, rgb, &t, &mat, NULL);
    check(r == FOV_OK && t >= 0.0f && t <= 60.0f && rgb[0] >= 0.0f && rgb[0] <= 65504.0f, "f1_primitives_shade_1e30",
          "%s, t %g, rgb %g", fovsdf_result_string(r), (double)t, (double)rgb[0]);
    bi.camera.eye_offset = 3e38f;
    bi.camera.up[0] = bi.camera.up[1] = bi.camera.up[2] = 3e38f;
    r = fovsdf_init(&ctx, NULL, &bi.scene, &bi.camera, g, NULL, 0);
    if (r == FOV_OK) { /* the old behaviour: a hit at t 1.87e38 past t_max 60, or a NaN point */
        r = fovsdf_shade_point(&ctx, 0.5f, 0.5f, rgb, &t, &mat, NULL);
        check(0, "f1_primitives_eye_offset_3e38", "accepted: shade_point %s, t %g (t_max 60), rgb %g",
              fovsdf_result_string(r), (double)t, (double)rgb[0]);
    } else {
        check(r == FOV_ERR_INVALID_ARG, "f1_primitives_eye_offset_3e38", "%s", fovsdf_result_string(r));
    }
    /* fovsdf_shade at a NaN point on the checkerboard (material 1): a defined colour */
    bi.camera.eye_offset = 0.0f;
    bi.camera.up[0] = 0.0f; bi.camera.up[1] = 1.0f; bi.camera.up[2] = 0.0f;
    r = fovsdf_init(&ctx, NULL, &bi.scene, &bi.camera, g, NULL, 0);
    if (r == FOV_OK) {
        p[0] = f_nan(); p[1] = 0.0f; p[2] = 3e38f;
        fovsdf_shade(&ctx, p, n, rd, 1, rgb, NULL);
        check(rgb[0] >= 0.0f && rgb[0] <= 65504.0f && rgb[1] >= 0.0f && rgb[2] >= 0.0f, "f1_checkerboard_nan_point",
              "rgb %g %g %g", (double)rgb[0], (double)rgb[1], (double)rgb[2]);
    }
}

/* ==== F2: builder parameters, lights, rendered ranges ======================================== */
static void test_f2_plane(void)
{
    fovsdf_node nodes[4];
    fovsdf_builder b;
    fovsdf_program prog;
    int32_t root;
    fov_result r;
    double e[3] = { 0.89, 1e6, 1e30 }, l;
    float p[3];
    int k, okn = 1;
    /* the plane: the offset 1e30 lies beyond the 1e18 bound of scene lengths */
    fovsdf_builder_init(&b, nodes, 4);
    root = fovsdf_plane(&b, 0.89f, 1e6f, 1e30f, 1e30f);
    check(root < 0 && b.err == FOV_ERR_LIMIT, "f2_plane_offset_1e30_limit", "index %d, err %s", (int)root,
          fovsdf_result_string(b.err));
    /* the same normal with a small offset: stored unit, distances as in double */
    fovsdf_builder_init(&b, nodes, 4);
    root = fovsdf_plane(&b, 0.89f, 1e6f, 1e30f, 1.5f);
    l = sqrt(e[0] / 1e30 * e[0] / 1e30 + e[1] / 1e30 * e[1] / 1e30 + 1.0);
    for (k = 0; k < 3; ++k) okn = okn && root == 0 && fabs((double)nodes[0].f[k] - e[k] / 1e30 / l) < 1e-7;
    check(okn, "f2_plane_normal_1e30_unit", "index %d, stored normal %g %g %g", (int)root, (double)nodes[0].f[0],
          (double)nodes[0].f[1], (double)nodes[0].f[2]);
    r = build(&prog, nodes, b.count, root);
    if (check(r == FOV_OK, "f2_plane_build", "%s", fovsdf_result_string(r))) {
        double maxerr = 0.0;
        for (k = 0; k < 5; ++k) {
            double want;
            float d;
            p[0] = (float)(k * 3 - 5); p[1] = (float)(k - 2) * 0.5f; p[2] = (float)(4 - k) * 2.0f;
            want = ((double)p[0] * (e[0] / 1e30) + (double)p[1] * (e[1] / 1e30) + (double)p[2]) / l + 1.5;
            d = fovsdf_program_eval(p, NULL, &prog);
            maxerr = fmax(maxerr, fabs((double)d - want));
        }
        check(maxerr < 1e-5, "f2_plane_1e30_distance", "max |d - double| %.3g", maxerr);
    }
    /* a zero normal is degenerate; a hand-made node with a 1e30-long normal is normalised by
       the build as the builder does */
    fovsdf_builder_init(&b, nodes, 4);
    root = fovsdf_plane(&b, 0.0f, 0.0f, 0.0f, 1.0f);
    check(root < 0 && b.err == FOV_ERR_DEGENERATE, "f2_plane_zero_normal_degenerate", "err %s", fovsdf_result_string(b.err));
    memset(nodes, 0, sizeof nodes);
    nodes[0].type = FOVSDF_NODE_PLANE;
    nodes[0].a = nodes[0].b = -1;
    nodes[0].f[0] = 0.0f; nodes[0].f[1] = 1e30f; nodes[0].f[2] = 0.0f; nodes[0].f[3] = 0.25f;
    r = build(&prog, nodes, 1, 0);
    if (check(r == FOV_OK, "f2_plane_handmade_build", "%s", fovsdf_result_string(r))) {
        float d;
        p[0] = 3.0f; p[1] = 2.0f; p[2] = -1.0f;
        d = fovsdf_program_eval(p, NULL, &prog);
        check(fabs((double)d - 2.25) < 1e-6, "f2_plane_handmade_1e30_normal", "distance %g, want 2.25", (double)d);
    }
}

/* A primitive under a translation, built with the builder; returns the root or -1. */
static void test_f2_huge_sizes(void)
{
    fovsdf_node nodes[8];
    fovsdf_builder b;
    fovsdf_program prog;
    fovsdf_camera cam;
    int32_t root;
    fov_result r;
    float p[3];
    /* sphere radius 3e38: beyond the bound */
    fovsdf_builder_init(&b, nodes, 8);
    root = fovsdf_sphere(&b, 3e38f);
    check(root < 0 && b.err == FOV_ERR_LIMIT, "f2_sphere_3e38_limit", "index %d, err %s", (int)root, fovsdf_result_string(b.err));
    /* at the bound: radius 1e18, the camera inside (every pixel a hit at t 0), and a sphere
       of radius 1e17 1.1e17 ahead (the hit at 1e16), with BV2018 */
    fovsdf_builder_init(&b, nodes, 8);
    root = fovsdf_sphere(&b, 1e18f);
    r = build(&prog, nodes, b.count, root);
    if (check(r == FOV_OK, "f2_sphere_1e18_build", "%s", fovsdf_result_string(r))) {
        fovsdf_camera_init(&cam, IMG, IMG);
        cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
        render_check("f2_sphere_1e18_inside_bv2018", &prog, &cam, FOVSDF_METHOD_BV2018, FOVSDF_SHADE_FULL, 60.0f);
        render_check("f2_sphere_1e18_inside_depth", &prog, &cam, FOVSDF_METHOD_BV2018, FOVSDF_SHADE_DEPTH, 60.0f);
    }
    fovsdf_builder_init(&b, nodes, 8);
    root = fovsdf_translate(&b, fovsdf_sphere(&b, 1e17f), 0.0f, 0.0f, 1.1e17f);
    r = build(&prog, nodes, b.count, root);
    if (check(r == FOV_OK, "f2_sphere_1e17_build", "%s", fovsdf_result_string(r))) {
        fovsdf_scene sc;
        fovsdf_config cfg = fovsdf_config_default();
        fovsdf_ctx ctx;
        fov_gaze g = { 0.5f, 0.5f };
        float rgb[3] = { 0.0f, 0.0f, 0.0f }, t = 0.0f;
        int32_t mat;
        fovsdf_camera_init(&cam, 1, 1);
        cam.pos[2] = 0.0f; cam.target[2] = 1.0f;
        fovsdf_scene_init(&sc);
        fovsdf_scene_set_program(&sc, &prog);
        sc.t_max = 1e18f;
        cfg.method = FOVSDF_METHOD_BV2018;
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
        if (r == FOV_OK) r = fovsdf_shade_point(&ctx, 0.5f, 0.5f, rgb, &t, &mat, NULL);
        check(r == FOV_OK && fabs((double)t - 1e16) < 1e16 * 1e-4 && rgb[0] >= 0.0f && rgb[0] <= 65504.0f,
              "f2_sphere_1e17_bv2018_hit", "%s, t %.8g (want 1e16), rgb %g", fovsdf_result_string(r), (double)t,
              (double)rgb[0]);
    }
    /* cone top radius 1e30: beyond the bound; at the bound, finite everywhere */
    fovsdf_builder_init(&b, nodes, 8);
    root = fovsdf_cone(&b, 1.0f, 1.0f, 1e30f);
    check(root < 0 && b.err == FOV_ERR_LIMIT, "f2_cone_top_1e30_limit", "index %d, err %s", (int)root,
          fovsdf_result_string(b.err));
    {
        /* a hand-made cone node with top radius 1e30 fails program_build the same way */
        fovsdf_node cn;
        memset(&cn, 0, sizeof cn);
        cn.type = FOVSDF_NODE_CONE; cn.a = cn.b = -1; cn.f[0] = 1.0f; cn.f[1] = 1.0f; cn.f[2] = 1e30f;
        r = build(&prog, &cn, 1, 0);
        check(r == FOV_ERR_LIMIT, "f2_cone_top_1e30_program_build_limit", "%s", fovsdf_result_string(r));
    }
    fovsdf_builder_init(&b, nodes, 8);
    root = fovsdf_cone(&b, 1.0f, 1.0f, 1e18f);
    r = build(&prog, nodes, b.count, root);
    if (check(r == FOV_OK, "f2_cone_top_1e18_build", "%s", fovsdf_result_string(r))) {
        int i, bad = 0;
        float first = 0.0f;
        for (i = 0; i < 64; ++i) {
            float d;
            p[0] = (float)(i % 4 - 2) * 0.7f; p[1] = (float)(i / 4 % 4 - 2) * 0.6f; p[2] = (float)(i / 16 - 2) * 0.9f;
            d = fovsdf_program_eval(p, NULL, &prog);
            if (!finite_f(d)) { if (!bad) first = d; ++bad; }
        }
        check(bad == 0, "f2_cone_top_1e18_finite", "%d of 64 points not finite (first %g)", bad, (double)first);
    }
}

/* A callback whose distances lie near -FLT_MAX (finite): the tetrahedron normal's sums
   overflowed to inf in the old code (a normal (0, inf, 0), inf/NaN shading). */
static float near_max_dist(const float p[3], void *user)
{
    (void)user;
    return p[1] * 1e36f - 3e38f;
}
static void test_f2_normal_overflow(void)
{
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fov_gaze g = { 0.5f, 0.5f };
    float p[3] = { 0.25f, 0.5f, -0.75f }, n[3] = { 0.0f, 0.0f, 0.0f }, rd[3] = { 0.0f, 0.0f, 1.0f }, rgb[3];
    fov_result r;
    fovsdf_scene_init(&sc);
    sc.dist = near_max_dist;
    fovsdf_camera_init(&cam, 1, 1);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    r = fovsdf_init(&ctx, NULL, &sc, &cam, g, NULL, 0);
    if (!check(r == FOV_OK, "f2_normal_near_flt_max_init", "%s", fovsdf_result_string(r))) return;
    fovsdf_normal(&ctx, p, 1e-2f, n, NULL);
    /* the field grows along +y only: the normal is (0, 1, 0) (the differences, 2e34 at
       h = 1e-2, lie well above the 2e31 ulp of 3e38, so they resolve the direction) */
    check(fabs((double)n[0]) < 1e-6 && fabs((double)n[1] - 1.0) < 1e-6 && fabs((double)n[2]) < 1e-6,
          "f2_normal_near_flt_max_unit", "normal %g %g %g", (double)n[0], (double)n[1], (double)n[2]);
    fovsdf_shade(&ctx, p, n, rd, 0, rgb, NULL);
    check(rgb[0] >= 0.0f && rgb[0] <= 65504.0f && rgb[1] >= 0.0f && rgb[1] <= 65504.0f && rgb[2] >= 0.0f &&
              rgb[2] <= 65504.0f,
          "f2_shade_near_flt_max_in_range", "rgb %g %g %g", (double)rgb[0], (double)rgb[1], (double)rgb[2]);
}

/* Directional lights of any finite length, colours up to FLT_MAX: rgb in [0, 65504]. */
static void test_f2_lights(void)
{
    fovsdf_node nodes[4];
    fovsdf_builder b;
    fovsdf_program prog;
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fov_gaze g = { IMG * 0.5f, IMG * 0.5f };
    float img_a[IMG * IMG * 3], img_b[IMG * IMG * 3], depth[IMG * IMG];
    uint8_t hit[IMG * IMG];
    int32_t root;
    fov_result r;
    uint32_t i, k;
    double maxd = 0.0;
    char what[128] = "";
    int bad;
    fovsdf_builder_init(&b, nodes, 4);
    root = fovsdf_sphere(&b, 1.0f);
    if (build(&prog, nodes, b.count, root) != FOV_OK) { check(0, "f2_lights_build", "failed"); return; }
    fovsdf_camera_init(&cam, IMG, IMG);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    fovsdf_scene_init(&sc);
    fovsdf_scene_set_program(&sc, &prog);
    sc.lights[0].v[0] = -0.06f; sc.lights[0].v[1] = -0.06f; sc.lights[0].v[2] = -1e30f;
    fovsdf_output_init(&out);
    out.rgb = img_a; out.depth = depth; out.hit = hit;
    r = fovsdf_init(&ctx, NULL, &sc, &cam, g, NULL, 0);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, IMG, &out, NULL);
    /* the same light as a unit vector (in double: (-6e-32, -6e-32, -1) is (0, 0, -1) in float) */
    sc.lights[0].v[0] = 0.0f; sc.lights[0].v[1] = 0.0f; sc.lights[0].v[2] = -1.0f;
    out.rgb = img_b;
    if (r == FOV_OK) r = fovsdf_init(&ctx, NULL, &sc, &cam, g, NULL, 0);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, IMG, &out, NULL);
    for (i = 0; i < IMG * IMG * 3; ++i) maxd = fmax(maxd, fabs((double)img_a[i] - (double)img_b[i]));
    check(r == FOV_OK && maxd < 1e-5, "f2_light_dir_1e30_as_unit", "%s, max |difference| %.3g (the old code: ~6e29)",
          fovsdf_result_string(r), maxd);
    /* every light FLT_MAX bright, ambient and sky FLT_MAX: rgb stays in [0, 65504] */
    sc.num_lights = FOVSDF_MAX_LIGHTS;
    for (i = 0; i < FOVSDF_MAX_LIGHTS; ++i) {
        sc.lights[i] = sc.lights[0];
        sc.lights[i].v[0] = (float)i - 3.0f;
        for (k = 0; k < 3; ++k) sc.lights[i].color[k] = FLT_MAX;
    }
    for (k = 0; k < 3; ++k) { sc.ambient[k] = FLT_MAX; sc.sky_zenith[k] = FLT_MAX; sc.sky_horizon[k] = -FLT_MAX; }
    out.rgb = img_a;
    r = fovsdf_init(&ctx, NULL, &sc, &cam, g, NULL, 0);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, IMG, &out, NULL);
    bad = r == FOV_OK ? out_ok(img_a, depth, hit, IMG * IMG, what, sizeof what) : 0;
    check(r == FOV_OK && bad == 0, "f2_lights_flt_max_rgb_in_range", "%s, %d values out of range (first: %s)",
          fovsdf_result_string(r), bad, what);
}

/* Every primitive and operator with extreme valid parameters: finite at finite points, and a
   render of each gives outputs within their ranges. */
static void test_f2_audit(void)
{
    static const float sizes[] = { 1e-30f, 1e-6f, 1.0f, 1e6f, 1e18f };
    static const float pts[] = { 0.0f, 1e-30f, 0.5f, -1.0f, 3.0f, -1e6f, 1e12f, -1e18f, 1e30f, -3e38f, FLT_MAX };
    const uint32_t npts = (uint32_t)(sizeof pts / sizeof pts[0]);
    fovsdf_node nodes[16];
    fovsdf_builder b;
    fovsdf_program prog;
    fovsdf_camera cam;
    int kind, si, bad_total = 0, built = 0, nan_total = 0;
    char first[160] = "", first_nan[160] = "";
    fovsdf_camera_init(&cam, IMG, IMG);
    cam.pos[2] = -5.0f; /* fovsdf_camera_init's former default view */
    for (kind = 0; kind < 22; ++kind)
        for (si = 0; si < 5; ++si) {
            float s = sizes[si], a3[3], c3[3];
            int32_t x = -1, y, root = -1;
            uint32_t i, j, k;
            fovsdf_builder_init(&b, nodes, 16);
            a3[0] = -s; a3[1] = 0.0f; a3[2] = s * 0.5f; c3[0] = s; c3[1] = s; c3[2] = 0.0f;
            switch (kind) {
            case 0: root = fovsdf_sphere(&b, s); break;
            case 1: root = fovsdf_box(&b, s, 1.0f, s); break;
            case 2: root = fovsdf_round_box(&b, s, s, s, s * 0.5f); break;
            case 3: root = fovsdf_box_frame(&b, s, s, 1.0f, s * 0.1f); break;
            case 4: root = fovsdf_torus(&b, s, s * 0.25f); break;
            case 5: root = fovsdf_capsule(&b, a3, c3, s); break;
            case 6: root = fovsdf_cylinder(&b, s, 1.0f); break;
            case 7: root = fovsdf_cone(&b, s, 1.0f, s); break;
            case 8: root = fovsdf_cone(&b, 1.0f, s, 0.0f); break;
            case 9: root = fovsdf_menger(&b, s, 8); break;
            case 10: root = fovsdf_mandelbulb(&b, si == 0 ? 2.0f : 16.0f, 32); break;
            case 11: root = fovsdf_terrain(&b, s, s, 12); break;
            case 12: x = fovsdf_sphere(&b, 1.0f); y = fovsdf_box(&b, 2.0f, 0.5f, 0.5f);
                     root = fovsdf_smooth_union(&b, x, y, s); break;
            case 13: x = fovsdf_sphere(&b, 1.0f); y = fovsdf_box(&b, 2.0f, 0.5f, 0.5f);
                     root = fovsdf_smooth_subtract(&b, x, y, s); break;
            case 14: x = fovsdf_sphere(&b, 1.0f); y = fovsdf_box(&b, 2.0f, 0.5f, 0.5f);
                     root = fovsdf_smooth_intersect(&b, x, y, s); break;
            case 15: root = fovsdf_scale(&b, fovsdf_sphere(&b, 1.0f), s); break;
            case 16: root = fovsdf_repeat(&b, fovsdf_sphere(&b, 0.25f), s, s, 0.0f, 0, 3, 0); break;
            case 17: root = fovsdf_onion(&b, fovsdf_sphere(&b, 1.0f), s); break;
            case 18: root = fovsdf_round(&b, fovsdf_box(&b, 0.5f, 0.5f, 0.5f), s); break;
            case 19: root = fovsdf_translate(&b, fovsdf_sphere(&b, 0.5f), s, -s, s); break;
            case 20: x = fovsdf_plane(&b, s, 1.0f, -s, s);
                     root = fovsdf_smooth_union(&b, x, fovsdf_repeat(&b, fovsdf_menger(&b, s, 3), s, 0.0f, s, 2, 0, 0), 1.0f);
                     break;
            default: x = fovsdf_terrain(&b, 1.0f, s, 6);
                     root = fovsdf_smooth_subtract(&b, x, fovsdf_scale(&b, fovsdf_torus(&b, s, s), 1e-3f), s); break;
            }
            if (root < 0) { /* every case lies within the documented ranges */
                ++bad_total;
                if (!first[0]) snprintf(first, sizeof first, "kind %d size %g: builder %s", kind, (double)s, fovsdf_result_string(b.err));
                continue;
            }
            if (build(&prog, nodes, b.count, root) != FOV_OK) {
                ++bad_total;
                if (!first[0]) snprintf(first, sizeof first, "kind %d size %g: program_build failed", kind, (double)s);
                continue;
            }
            ++built;
            for (i = 0; i < npts; ++i)
                for (j = 0; j < npts; ++j)
                    for (k = 0; k < npts; k += 2) {
                        float p[3], d;
                        p[0] = pts[i]; p[1] = pts[j]; p[2] = pts[(k + i) % npts];
                        d = fovsdf_program_eval(p, NULL, &prog);
                        if (d != d) {
                            if (!first_nan[0])
                                snprintf(first_nan, sizeof first_nan, "kind %d size %g at (%g %g %g)", kind, (double)s,
                                         (double)p[0], (double)p[1], (double)p[2]);
                            ++nan_total;
                        }
                        if (!finite_f(d)) {
                            if (!first[0])
                                snprintf(first, sizeof first, "kind %d size %g at (%g %g %g): %g", kind, (double)s,
                                         (double)p[0], (double)p[1], (double)p[2], (double)d);
                            ++bad_total;
                        }
                    }
            if (si == 0 || si == 4) {
                render_check(N("f2_audit_render_kind%d_size%g_full", kind, (double)s), &prog, &cam, FOVSDF_METHOD_BV2018,
                             FOVSDF_SHADE_FULL, 60.0f);
                render_check(N("f2_audit_render_kind%d_size%g_cone_normals", kind, (double)s), &prog, &cam,
                             FOVSDF_METHOD_CONE, FOVSDF_SHADE_NORMALS, 60.0f);
            }
        }
    check(nan_total == 0, "f2_audit_eval_no_nan", "%d NaN distances (first: %s)", nan_total, first_nan);
    check(bad_total == 0 && built == 22 * 5, "f2_audit_eval_finite", "%d failures over %d programs (first: %s)", bad_total,
          built, first);
}

/* Random trees of every node type with parameters drawn log-uniformly over their whole
   ranges (1e-30 .. 1e18), evaluated at points of every magnitude up to FLT_MAX: never NaN,
   never inf (a 32-bit LCG: the same trees every run). */
static uint32_t g_rng = 12345u;
static uint32_t rnd(void) { g_rng = g_rng * 1664525u + 1013904223u; return g_rng >> 8; }
static float rnd01(void) { return (float)rnd() * (1.0f / 16777216.0f); }
static float rnd_len(void) { return powf(10.0f, -30.0f + 48.0f * rnd01()); }
static float rnd_sgn(float x) { return (rnd() & 1u) ? -x : x; }
static int32_t rnd_tree(fovsdf_builder *b, int depth)
{
    uint32_t t = depth <= 0 ? 1u + rnd() % 12u : 1u + rnd() % 25u;
    float a3[3], c3[3], s = rnd_len();
    int32_t x, y;
    a3[0] = rnd_sgn(rnd_len()); a3[1] = rnd_sgn(rnd_len()); a3[2] = rnd_sgn(rnd_len());
    c3[0] = rnd_sgn(rnd_len()); c3[1] = rnd_sgn(rnd_len()); c3[2] = rnd_sgn(rnd_len());
    switch (t) {
    case FOVSDF_NODE_SPHERE: return fovsdf_sphere(b, s);
    case FOVSDF_NODE_BOX: return fovsdf_box(b, s, rnd_len(), rnd_len());
    case FOVSDF_NODE_ROUND_BOX: return fovsdf_round_box(b, s, s * 2.0f, s * 0.5f, s * 0.5f * rnd01());
    case FOVSDF_NODE_BOX_FRAME: return fovsdf_box_frame(b, s, rnd_len(), rnd_len(), rnd_len());
    case FOVSDF_NODE_TORUS: return fovsdf_torus(b, s, rnd_len());
    case FOVSDF_NODE_CAPSULE: return fovsdf_capsule(b, a3, c3, s);
    case FOVSDF_NODE_CYLINDER: return fovsdf_cylinder(b, s, rnd_len());
    case FOVSDF_NODE_CONE: return fovsdf_cone(b, s, rnd_len(), (rnd() & 1u) ? 0.0f : rnd_len());
    case FOVSDF_NODE_PLANE: return fovsdf_plane(b, a3[0], a3[1], a3[2], rnd_sgn(s));
    case FOVSDF_NODE_MENGER: return fovsdf_menger(b, s, 1 + (int32_t)(rnd() % 8u));
    case FOVSDF_NODE_MANDELBULB: return fovsdf_mandelbulb(b, 2.0f + 14.0f * rnd01(), 1 + (int32_t)(rnd() % 32u));
    case FOVSDF_NODE_TERRAIN: return fovsdf_terrain(b, s, rnd_len(), 1 + (int32_t)(rnd() % 12u));
    case FOVSDF_NODE_UNION: case FOVSDF_NODE_SUBTRACT: case FOVSDF_NODE_INTERSECT: case FOVSDF_NODE_SMOOTH_UNION:
    case FOVSDF_NODE_SMOOTH_SUBTRACT: case FOVSDF_NODE_SMOOTH_INTERSECT:
        x = rnd_tree(b, depth - 1);
        y = rnd_tree(b, depth - 1);
        if (t == FOVSDF_NODE_UNION) return fovsdf_union(b, x, y);
        if (t == FOVSDF_NODE_SUBTRACT) return fovsdf_subtract(b, x, y);
        if (t == FOVSDF_NODE_INTERSECT) return fovsdf_intersect(b, x, y);
        if (t == FOVSDF_NODE_SMOOTH_UNION) return fovsdf_smooth_union(b, x, y, s);
        if (t == FOVSDF_NODE_SMOOTH_SUBTRACT) return fovsdf_smooth_subtract(b, x, y, s);
        return fovsdf_smooth_intersect(b, x, y, s);
    default:
        x = rnd_tree(b, depth - 1);
        switch (t) {
        case FOVSDF_NODE_TRANSLATE: return fovsdf_translate(b, x, a3[0], a3[1], a3[2]);
        case FOVSDF_NODE_ROTATE: return fovsdf_rotate(b, x, c3[0], c3[1], c3[2], 360.0f * rnd01());
        case FOVSDF_NODE_SCALE: return fovsdf_scale(b, x, s);
        case FOVSDF_NODE_REPEAT:
            return fovsdf_repeat(b, x, (rnd() & 1u) ? 0.0f : s, rnd_len(), (rnd() & 1u) ? 0.0f : rnd_len(),
                                 (int32_t)(rnd() % 3u) * 500000, (int32_t)(rnd() % 4u), 0);
        case FOVSDF_NODE_MIRROR: return fovsdf_mirror(b, x, 1 + (int32_t)(rnd() % 7u));
        case FOVSDF_NODE_ROUND: return fovsdf_round(b, x, s);
        default: return fovsdf_onion(b, x, s);
        }
    }
}
static void test_f2_random_trees(void)
{
    fovsdf_node nodes[64];
    fovsdf_builder b;
    fovsdf_program prog;
    int tree, built = 0, bad = 0, k;
    char first[200] = "";
    for (tree = 0; tree < 400; ++tree) {
        int32_t root;
        fovsdf_builder_init(&b, nodes, 64);
        root = rnd_tree(&b, 3);
        if (root < 0 || build(&prog, nodes, b.count, root) != FOV_OK) {
            if (!first[0]) snprintf(first, sizeof first, "tree %d not built: %s", tree, fovsdf_result_string(b.err));
            ++bad;
            continue;
        }
        ++built;
        for (k = 0; k < 200; ++k) {
            float p[3], d;
            p[0] = rnd_sgn(k < 20 ? FLT_MAX * rnd01() : powf(10.0f, -38.0f + 76.0f * rnd01()));
            p[1] = rnd_sgn(powf(10.0f, -38.0f + 76.0f * rnd01()));
            p[2] = rnd_sgn(powf(10.0f, -10.0f + 20.0f * rnd01()));
            d = fovsdf_program_eval(p, NULL, &prog);
            if (!finite_f(d)) {
                if (!first[0])
                    snprintf(first, sizeof first, "tree %d (%u nodes, root type %u) at (%g %g %g): %g", tree, b.count,
                             nodes[root].type, (double)p[0], (double)p[1], (double)p[2], (double)d);
                ++bad;
            }
        }
    }
    check(bad == 0 && built == 400, "f2_random_trees_eval_finite", "%d failures, %d of 400 trees built (first: %s)", bad,
          built, first);
}

/* ==== F6: one node check for the builder and fovsdf_program_build =========================== */
typedef struct bad_case {
    const char *name;
    uint32_t type;
    float f[9];
    int32_t i[3];
    fov_result want;
    const char *field;   /* expected in the message */
} bad_case;

/* Calls the builder function of the node's type with the node's parameters (children: two
   spheres built first). */
static int32_t build_like(fovsdf_builder *b, const fovsdf_node *n)
{
    const float *f = n->f;
    int32_t s0 = -1, s1 = -1;
    if (n->type >= FOVSDF_NODE_UNION) { s0 = fovsdf_sphere(b, 1.0f); s1 = fovsdf_sphere(b, 0.5f); }
    switch (n->type) {
    case FOVSDF_NODE_SPHERE: return fovsdf_sphere(b, f[0]);
    case FOVSDF_NODE_BOX: return fovsdf_box(b, f[0], f[1], f[2]);
    case FOVSDF_NODE_ROUND_BOX: return fovsdf_round_box(b, f[0], f[1], f[2], f[3]);
    case FOVSDF_NODE_BOX_FRAME: return fovsdf_box_frame(b, f[0], f[1], f[2], f[3]);
    case FOVSDF_NODE_TORUS: return fovsdf_torus(b, f[0], f[1]);
    case FOVSDF_NODE_CAPSULE: return fovsdf_capsule(b, f, f + 3, f[6]);
    case FOVSDF_NODE_CYLINDER: return fovsdf_cylinder(b, f[0], f[1]);
    case FOVSDF_NODE_CONE: return fovsdf_cone(b, f[0], f[1], f[2]);
    case FOVSDF_NODE_PLANE: return fovsdf_plane(b, f[0], f[1], f[2], f[3]);
    case FOVSDF_NODE_MENGER: return fovsdf_menger(b, f[0], n->i[0]);
    case FOVSDF_NODE_MANDELBULB: return fovsdf_mandelbulb(b, f[0], n->i[0]);
    case FOVSDF_NODE_TERRAIN: return fovsdf_terrain(b, f[0], f[1], n->i[0]);
    case FOVSDF_NODE_SMOOTH_UNION: return fovsdf_smooth_union(b, s0, s1, f[0]);
    case FOVSDF_NODE_SMOOTH_SUBTRACT: return fovsdf_smooth_subtract(b, s0, s1, f[0]);
    case FOVSDF_NODE_SMOOTH_INTERSECT: return fovsdf_smooth_intersect(b, s0, s1, f[0]);
    case FOVSDF_NODE_TRANSLATE: return fovsdf_translate(b, s0, f[0], f[1], f[2]);
    case FOVSDF_NODE_SCALE: return fovsdf_scale(b, s0, f[0]);
    case FOVSDF_NODE_REPEAT: return fovsdf_repeat(b, s0, f[0], f[1], f[2], n->i[0], n->i[1], n->i[2]);
    case FOVSDF_NODE_MIRROR: return fovsdf_mirror(b, s0, n->i[0]);
    case FOVSDF_NODE_ROUND: return fovsdf_round(b, s0, f[0]);
    case FOVSDF_NODE_ONION: return fovsdf_onion(b, s0, f[0]);
    default: return -1;
    }
}

static void test_f6(void)
{
    const float nan = f_nan();
    bad_case cases[] = {
        { "menger_iter_2e31", FOVSDF_NODE_MENGER, { 1.0f }, { 2147483647 }, FOV_ERR_INVALID_ARG, "i0 iterations must be 1 .. 8" },
        { "menger_iter_0", FOVSDF_NODE_MENGER, { 1.0f }, { 0 }, FOV_ERR_INVALID_ARG, "i0 iterations" },
        { "mandelbulb_iter_33", FOVSDF_NODE_MANDELBULB, { 8.0f }, { 33 }, FOV_ERR_INVALID_ARG, "i0 iterations must be 1 .. 32" },
        { "mandelbulb_power_1", FOVSDF_NODE_MANDELBULB, { 1.0f }, { 8 }, FOV_ERR_INVALID_ARG, "f0 power" },
        { "terrain_octaves_13", FOVSDF_NODE_TERRAIN, { 1.0f, 1.0f, 0.5f }, { 13 }, FOV_ERR_INVALID_ARG, "i0 octaves" },
        { "terrain_freq_0", FOVSDF_NODE_TERRAIN, { 1.0f, 0.0f, 0.5f }, { 3 }, FOV_ERR_INVALID_ARG, "f1 frequency" },
        { "sphere_nan", FOVSDF_NODE_SPHERE, { nan }, { 0 }, FOV_ERR_NOT_FINITE, "f0 is NaN" },
        { "sphere_neg", FOVSDF_NODE_SPHERE, { -1.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f0 radius" },
        { "sphere_3e38", FOVSDF_NODE_SPHERE, { 3e38f }, { 0 }, FOV_ERR_LIMIT, "f0 beyond 1e18" },
        { "box_negative", FOVSDF_NODE_BOX, { 1.0f, -0.5f, 1.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f1 half extent" },
        { "round_box_r_too_big", FOVSDF_NODE_ROUND_BOX, { 1.0f, 0.5f, 1.0f, 0.6f }, { 0 }, FOV_ERR_INVALID_ARG, "f3 rounding" },
        { "box_frame_e_0", FOVSDF_NODE_BOX_FRAME, { 1.0f, 1.0f, 1.0f, 0.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f3 frame" },
        { "torus_minor_0", FOVSDF_NODE_TORUS, { 1.0f, 0.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f1 minor" },
        { "capsule_r_neg", FOVSDF_NODE_CAPSULE, { 0, 0, 0, 1, 1, 1, -0.1f }, { 0 }, FOV_ERR_INVALID_ARG, "f6 radius" },
        { "capsule_end_2e18", FOVSDF_NODE_CAPSULE, { 0, 0, 0, 2e18f, 1, 1, 0.1f }, { 0 }, FOV_ERR_LIMIT, "f3 beyond" },
        { "cylinder_h_0", FOVSDF_NODE_CYLINDER, { 0.0f, 1.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f0 half height" },
        { "cone_radii_0", FOVSDF_NODE_CONE, { 1.0f, 0.0f, 0.0f }, { 0 }, FOV_ERR_INVALID_ARG, "bottom or top" },
        { "plane_zero", FOVSDF_NODE_PLANE, { 0.0f, 0.0f, 0.0f, 1.0f }, { 0 }, FOV_ERR_DEGENERATE, "normal" },
        { "plane_offset_inf", FOVSDF_NODE_PLANE, { 0.0f, 1.0f, 0.0f, 1e30f * 1e30f }, { 0 }, FOV_ERR_NOT_FINITE, "f3 is NaN" },
        { "smooth_union_k_0", FOVSDF_NODE_SMOOTH_UNION, { 0.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f0 blend radius" },
        { "smooth_subtract_k_nan", FOVSDF_NODE_SMOOTH_SUBTRACT, { nan }, { 0 }, FOV_ERR_NOT_FINITE, "f0 is NaN" },
        { "smooth_intersect_k_2e18", FOVSDF_NODE_SMOOTH_INTERSECT, { 2e18f }, { 0 }, FOV_ERR_LIMIT, "f0 beyond" },
        { "translate_3e38", FOVSDF_NODE_TRANSLATE, { 0.0f, 3e38f, 0.0f }, { 0 }, FOV_ERR_LIMIT, "f1 beyond" },
        { "scale_0", FOVSDF_NODE_SCALE, { 0.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f0 scale" },
        { "repeat_period_neg", FOVSDF_NODE_REPEAT, { 1.0f, -1.0f, 0.0f }, { 0, 0, 0 }, FOV_ERR_INVALID_ARG, "f1 period" },
        { "repeat_copies_2e6", FOVSDF_NODE_REPEAT, { 1.0f, 0.0f, 0.0f }, { 2000000, 0, 0 }, FOV_ERR_INVALID_ARG, "copies" },
        { "mirror_axes_8", FOVSDF_NODE_MIRROR, { 0.0f }, { 8 }, FOV_ERR_INVALID_ARG, "axis mask" },
        { "round_neg", FOVSDF_NODE_ROUND, { -0.1f }, { 0 }, FOV_ERR_INVALID_ARG, "f0 radius" },
        { "onion_0", FOVSDF_NODE_ONION, { 0.0f }, { 0 }, FOV_ERR_INVALID_ARG, "f0 thickness" },
    };
    const uint32_t nc = (uint32_t)(sizeof cases / sizeof cases[0]);
    uint32_t c;
    for (c = 0; c < nc; ++c) {
        const bad_case *bc = &cases[c];
        fovsdf_node nodes[4], bn[8];
        fovsdf_program prog;
        fovsdf_builder b;
        logrec lr, lb;
        fov_result r, rc;
        int32_t root, k, first = 0;
        /* hand-made: node 2 is the bad one (children 0 and 1 are spheres) */
        memset(nodes, 0, sizeof nodes);
        for (k = 0; k < 2; ++k) {
            nodes[k].type = FOVSDF_NODE_SPHERE; nodes[k].a = nodes[k].b = -1; nodes[k].f[0] = 1.0f;
        }
        nodes[2].type = bc->type;
        nodes[2].a = bc->type >= FOVSDF_NODE_UNION ? 0 : -1;
        nodes[2].b = bc->type >= FOVSDF_NODE_UNION && bc->type <= FOVSDF_NODE_SMOOTH_INTERSECT ? 1 : -1;
        memcpy(nodes[2].f, bc->f, sizeof bc->f);
        memcpy(nodes[2].i, bc->i, sizeof bc->i);
        r = build(&prog, nodes, 3, 2);
        rec_init(&lr);
        {
            fov_logger lg;
            lg.func = rec_log;
            lg.user = &lr;
            rc = fovsdf_program_check(nodes, 3, 2, &lg);
        }
        check(r == bc->want && rc == bc->want && lr.calls == 1 && strstr(lr.msg, "node 2 (") != NULL &&
                  strstr(lr.msg, bc->field) != NULL,
              N("f6_program_build_%s", bc->name), "program_build %s, program_check %s (want %s), message \"%s\" (want \"%s\")",
              fovsdf_result_string(r), fovsdf_result_string(rc), fovsdf_result_string(bc->want), lr.msg, bc->field);
        /* the builder function with the same parameters: the same code, logged */
        fovsdf_builder_init(&b, bn, 8);
        rec_init(&lb);
        b.logger.func = rec_log;
        b.logger.user = &lb;
        root = build_like(&b, &nodes[2]);
        if (bc->type == FOVSDF_NODE_TERRAIN || bc->type == FOVSDF_NODE_PLANE) first = 1; /* f2 / the normal are derived */
        check(root < 0 && b.err == bc->want && lb.calls == 1 && (first || strstr(lb.msg, bc->field) != NULL),
              N("f6_builder_%s", bc->name), "index %d, err %s (want %s), message \"%s\"", (int)root,
              fovsdf_result_string(b.err), fovsdf_result_string(bc->want), lb.msg);
    }
    /* the valid form of each case builds through both routes */
    {
        fovsdf_node nodes[4];
        fovsdf_program prog;
        fov_result r;
        memset(nodes, 0, sizeof nodes);
        nodes[0].type = FOVSDF_NODE_MENGER; nodes[0].a = nodes[0].b = -1; nodes[0].f[0] = 1.0f; nodes[0].i[0] = 8;
        r = build(&prog, nodes, 1, 0);
        check(r == FOV_OK, "f6_menger_8_iterations_ok", "%s", fovsdf_result_string(r));
        nodes[0].type = FOVSDF_NODE_ROTATE; nodes[0].a = 1; nodes[0].b = -1;
        memset(nodes[0].f, 0, sizeof nodes[0].f);
        nodes[0].f[1] = 1.0f; nodes[0].f[3] = -1.0f; nodes[0].f[8] = 1.0f; /* 90 degrees about z */
        nodes[1].type = FOVSDF_NODE_SPHERE; nodes[1].a = nodes[1].b = -1; nodes[1].f[0] = 1.0f;
        r = build(&prog, nodes, 2, 0);
        check(r == FOV_OK, "f6_rotate_matrix_ok", "%s", fovsdf_result_string(r));
        nodes[0].f[0] = 2.0f; /* no longer a rotation */
        r = build(&prog, nodes, 2, 0);
        check(r == FOV_ERR_INVALID_ARG, "f6_rotate_not_orthonormal", "%s", fovsdf_result_string(r));
        /* a child index that does not exist */
        nodes[0].f[0] = 0.0f; nodes[0].a = 7;
        r = build(&prog, nodes, 2, 0);
        check(r == FOV_ERR_INVALID_ARG, "f6_child_out_of_range", "%s", fovsdf_result_string(r));
    }
}

int main(void)
{
    test_version();
    test_f6();
    test_f2_plane();
    test_f2_huge_sizes();
    test_f2_lights();
    test_f2_normal_overflow();
    test_f1();
    test_f2_audit();
    test_f2_random_trees();
    test_f1_primitives();
    return fovcheck_summary();
}
