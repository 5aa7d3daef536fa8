/*
 * test_fovpt_denoise.c - fovpt's guide buffers (fovpt_trace_rows_guide) and its foveated
 * denoiser (fovpt_denoise_*: temporal accumulation with reprojection, then the edge-avoiding
 * a-trous wavelet filter of Dammertz, Sewtz, Hanika, Lensch, "Edge-Avoiding A-Trous Wavelet
 * Transform for fast Global Illumination Filtering", HPG 2010, with the variance guidance of
 * Schied et al., "Spatiotemporal Variance-Guided Filtering", HPG 2017).
 *
 * Build and run from the repository root (tests/run_all.sh builds it three ways):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -I. -Itests/common tests/test_fovpt_denoise.c -lm -o build/tests/t
 *
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed".
 * Expected values are analytic: a closed box whose walls emit E and do not scatter shows E
 * everywhere; a furnace box (albedo 0.5, emission 0.5, closed) has radiance 0.5 / (1 - 0.5) = 1
 * up to the bounce limit (0.5^41 with max_depth 40); a two-region image keeps its two values
 * when a guide separates them; a static camera blends frame k with weight max(alpha, 1/k)
 * (the running mean for the first frames); a camera moved by exactly one pixel over a
 * fronto-parallel plane reads its history one pixel over.
 */
#define FOVPT_IMPLEMENTATION /* the implementation here: checks call fovpt__dn_nlog, fovpt__dn_atrous */
#include "fovpt.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

static int g_log_count;
static int32_t g_log_code;
static void logger(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                   void *user)
{
    (void)tag; (void)level; (void)line; (void)user; (void)msg;
    g_log_count++;
    g_log_code = code;
}

typedef struct img {
    uint32_t w, h;
    float *rgb, *alb, *nrm, *dep, *spp, *var;
    fovpt_guide g;
} img;
static void img_alloc(img *m, uint32_t w, uint32_t h)
{
    size_t n = (size_t)w * h;
    m->w = w; m->h = h;
    m->rgb = (float *)calloc(n * 3u, sizeof(float));
    m->alb = (float *)calloc(n * 3u, sizeof(float));
    m->nrm = (float *)calloc(n * 3u, sizeof(float));
    m->dep = (float *)calloc(n, sizeof(float));
    m->spp = (float *)calloc(n, sizeof(float));
    m->var = (float *)calloc(n, sizeof(float));
    fovpt_guide_init(&m->g);
    m->g.albedo = m->alb; m->g.normal = m->nrm; m->g.depth = m->dep;
    m->g.spp = m->spp; m->g.var = m->var;
}
static void img_free(img *m)
{
    free(m->rgb); free(m->alb); free(m->nrm); free(m->dep); free(m->spp); free(m->var);
}

/* a closed axis-aligned box [-1,1]^3 of six quads (camera inside), every wall one material */
static int box_scene(fovpt_scene *s, void **mem, const fovpt_material *m)
{
    static fovpt_shape sh[6];
    static const float c[6][3] = { { -1, -1, -1 }, { -1, -1, 1 }, { -1, -1, -1 },
                                   { -1, 1, -1 }, { -1, -1, -1 }, { 1, -1, -1 } };
    static const float u[6][3] = { { 2, 0, 0 }, { 0, 2, 0 }, { 0, 0, 2 },
                                   { 2, 0, 0 }, { 0, 2, 0 }, { 0, 0, 2 } };
    static const float v[6][3] = { { 0, 2, 0 }, { 2, 0, 0 }, { 2, 0, 0 },
                                   { 0, 0, 2 }, { 0, 0, 2 }, { 0, 2, 0 } };
    fovpt_scene_desc d;
    size_t b = 0;
    int i;
    for (i = 0; i < 6; ++i) fovpt_shape_quad(&sh[i], c[i], u[i], v[i], 0);
    fovpt_scene_desc_init(&d);
    d.shapes = sh; d.num_shapes = 6; d.materials = m; d.num_materials = 1;
    if (fovpt_scene_size(&d, &b) != FOV_OK) return 0;
    *mem = malloc(b + 16u);
    return fovpt_scene_build(s, &d, *mem, b) == FOV_OK;
}
static void box_cam(fovpt_camera *cam, uint32_t w, uint32_t h)
{
    fovpt_camera_init(cam, w, h);
    cam->pos[0] = 0.1f; cam->pos[1] = 0.2f; cam->pos[2] = 0.7f;
    cam->target[0] = -0.6f; cam->target[1] = -0.4f; cam->target[2] = -1.0f; /* a corner in view */
    cam->fov_y_deg = 90.0f;
}

/* renders frame f of the box with method / spp into m (image + guides) */
static int box_render(const fovpt_scene *s, const fovpt_camera *cam, uint32_t method, uint32_t spp,
                      uint32_t f, img *m, fovpt_stats *st)
{
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output o;
    size_t b = 0;
    void *mem;
    fov_gaze g;
    int ok;
    c.method = method; c.spp = spp; c.max_depth = 40;
    g.x = 0.5f * (float)cam->width; g.y = 0.5f * (float)cam->height;
    if (fovpt_memory_size(&c, cam, &b) != FOV_OK) return 0;
    mem = malloc(b + 16u);
    ok = fovpt_init(&ctx, &c, s, cam, g, mem, b) == FOV_OK;
    fovpt_output_init(&o);
    o.rgb = m->rgb;
    ok = ok && fovpt_render_guide(&ctx, f, &o, &m->g, st) == FOV_OK;
    free(mem);
    return ok;
}

static int dn_make(fovpt_denoise *dn, fovpt_denoise_cfg *c, void **mem)
{
    size_t b = 0;
    if (fovpt_denoise_size(c, &b) != FOV_OK) return 0;
    *mem = malloc(b);
    return fovpt_denoise_init(dn, c, *mem, b) == FOV_OK;
}

/* a constant-radiance scene (walls emit E, albedo 0) stays constant through the denoiser */
static void t_constant(void)
{
    fovpt_material m;
    fovpt_scene s;
    fovpt_camera cam;
    void *sm = NULL, *dm = NULL;
    img a;
    float *out;
    uint32_t meth, f;
    fovpt_material_init(&m);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.0f;
    m.emission[0] = 0.3f; m.emission[1] = 0.5f; m.emission[2] = 0.7f;
    if (!check(box_scene(&s, &sm, &m), "constant_scene", "build failed")) return;
    box_cam(&cam, 48, 36);
    img_alloc(&a, 48, 36);
    out = (float *)malloc(48u * 36u * 12u);
    for (meth = 0; meth < 2; ++meth) {
        fovpt_denoise dn;
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 24.0f, 18.0f };
        double worst = 0.0;
        int ok = 1;
        dc.width = 48; dc.height = 36;
        ok = dn_make(&dn, &dc, &dm);
        for (f = 0; f < 3 && ok; ++f) {
            fovpt_output o;
            size_t i;
            int k;
            ok = box_render(&s, &cam, meth ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_UNIFORM, 2, f, &a, NULL);
            fovpt_output_init(&o); o.rgb = out;
            ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK;
            ok = ok && fovpt_denoise_run(&dn, &o) == FOV_OK;
            for (i = 0; i < 48u * 36u; ++i)
                for (k = 0; k < 3; ++k) {
                    double d = fabs((double)out[3 * i + (size_t)k] - (double)m.emission[k]);
                    if (d > worst) worst = d;
                }
        }
        check(ok && worst <= 1e-5, N("constant_stays_constant_%s", meth ? "layers" : "uniform"),
              "worst deviation %g from E", worst);
        free(dm);
    }
    /* the guides of that scene: depth is the distance to a wall, normals unit and facing */
    {
        double dworst = 0.0, nworst = 0.0;
        uint32_t x, y;
        box_render(&s, &cam, FOVPT_METHOD_UNIFORM, 1, 0, &a, NULL);
        for (y = 0; y < 36; y += 5)
            for (x = 0; x < 48; x += 5) {
                size_t i = (size_t)y * 48u + x;
                float o[3], d[3], tmin = 1e30f, t;
                int k;
                double nl = 0.0;
                fovpt_camera_ray(&cam, (float)x + 0.5f, (float)y + 0.5f, o, d);
                for (k = 0; k < 3; ++k) { /* the nearest wall along the centre ray */
                    t = d[k] > 0.0f ? (1.0f - o[k]) / d[k] : (-1.0f - o[k]) / d[k];
                    if (t < tmin) tmin = t;
                }
                /* the samples jitter inside the pixel: within a pixel's spread of the centre's */
                if (fabs((double)a.dep[i] - (double)tmin) > 0.05 * (double)tmin)
                    dworst = fmax(dworst, fabs((double)a.dep[i] - (double)tmin) / (double)tmin);
                for (k = 0; k < 3; ++k) nl += (double)a.nrm[3 * i + (size_t)k] * (double)a.nrm[3 * i + (size_t)k];
                nworst = fmax(nworst, fabs(sqrt(nl) - 1.0));
            }
        check(dworst == 0.0, "guide_depth_is_ray_distance", "relative error %g", dworst);
        check(nworst < 1e-5, "guide_normal_unit", "|n| - 1 up to %g", nworst);
    }
    img_free(&a);
    free(out);
    free(sm);
}

/* furnace: a closed box of albedo 0.5 emitting 0.5: radiance 1; the denoiser keeps the mean.
   The stated tolerance: 2 % with the default luminance stop (phi_lum 8; the stop down-weights
   bright outliers of the heavy-tailed path-tracing noise, a known bias: 2.5 % at Schied et
   al. 2017's phi_lum 4), 1 % with phi_lum 16. */
static void t_furnace(void)
{
    fovpt_material m;
    fovpt_scene s;
    fovpt_camera cam;
    void *sm = NULL, *dm = NULL;
    img a;
    float *out;
    size_t n = 64u * 48u;
    int pass;
    fovpt_material_init(&m);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.5f;
    m.emission[0] = m.emission[1] = m.emission[2] = 0.5f;
    if (!check(box_scene(&s, &sm, &m), "furnace_scene", "build failed")) return;
    box_cam(&cam, 64, 48);
    img_alloc(&a, 64, 48);
    out = (float *)malloc(n * 12u);
    for (pass = 0; pass < 2; ++pass) {
        fovpt_denoise dn;
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 32.0f, 24.0f };
        fovpt_output o;
        double mi = 0.0, mo = 0.0, ei = 0.0, eo = 0.0, tol = pass ? 0.01 : 0.02;
        size_t i;
        int k, ok;
        dc.width = 64; dc.height = 48;
        if (pass) dc.phi_lum = 16.0f;
        ok = dn_make(&dn, &dc, &dm) && box_render(&s, &cam, FOVPT_METHOD_UNIFORM, 2, 0, &a, NULL);
        fovpt_output_init(&o); o.rgb = out;
        ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
        for (i = 0; i < n; ++i)
            for (k = 0; k < 3; ++k) {
                double vi = (double)a.rgb[3 * i + (size_t)k], vo = (double)out[3 * i + (size_t)k];
                mi += vi; mo += vo;
                ei += (vi - 1.0) * (vi - 1.0); eo += (vo - 1.0) * (vo - 1.0);
            }
        mi /= (double)(3u * n); mo /= (double)(3u * n);
        ei = sqrt(ei / (double)(3u * n)); eo = sqrt(eo / (double)(3u * n));
        if (!pass) check(ok && fabs(mi - 1.0) < 0.03, "furnace_input_mean_1", "input mean %.4f (rmse %.3f)", mi, ei);
        fovcheck_info("furnace phi_lum %d: mean %.4f -> %.4f, rmse %.4f -> %.4f", pass ? 16 : 8, mi, mo, ei, eo);
        check(ok && fabs(mo - mi) <= tol * mi, N("furnace_energy_phi_lum_%d", pass ? 16 : 8), "mean %.4f -> %.4f (tolerance %.0f %%)", mi, mo, 100.0 * tol);
        check(ok && eo < 0.5 * ei, N("furnace_noise_halved_phi_lum_%d", pass ? 16 : 8), "rmse against 1: %.4f -> %.4f", ei, eo);
        free(dm);
    }
    free(out); img_free(&a); free(sm);
}

/* an analytic two-region image: a guide edge keeps both values, no guide edge blurs */
static void t_edges(void)
{
    const uint32_t W = 64, H = 32;
    static const char *const what[4] = { "albedo", "normal", "depth", "none" };
    img a;
    fovpt_camera cam;
    float *out = (float *)malloc((size_t)W * H * 12u);
    int e;
    img_alloc(&a, W, H);
    fovpt_camera_init(&cam, W, H);
    for (e = 0; e < 4; ++e) {
        fovpt_denoise dn;
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 32.0f, 16.0f };
        fovpt_output o;
        void *dm = NULL;
        uint32_t x, y;
        double worst = 0.0;
        int ok;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                size_t i = (size_t)y * W + x;
                int right = x >= W / 2;
                int k;
                for (k = 0; k < 3; ++k) {
                    a.rgb[3 * i + (size_t)k] = right ? 0.8f : 0.2f;
                    a.alb[3 * i + (size_t)k] = (e == 0 && right) ? 0.8f : 0.2f;
                    a.nrm[3 * i + (size_t)k] = 0.0f;
                }
                a.nrm[3 * i + ((e == 1 && right) ? 0u : 2u)] = 1.0f;
                a.dep[i] = (e == 2 && right) ? 2.0f : 1.0f;
                a.spp[i] = 1.0f;
                a.var[i] = 1.0f; /* a large variance: the luminance stop lets everything through */
            }
        dc.width = W; dc.height = H;
        dc.fovea_step = 65536.0f; /* every pass at every pixel */
        dc.no_temporal = 1;
        ok = dn_make(&dn, &dc, &dm);
        fovpt_output_init(&o); o.rgb = out;
        ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                double want = x >= W / 2 ? 0.8 : 0.2, d = fabs((double)out[3 * ((size_t)y * W + x)] - want);
                if (d > worst) worst = d;
            }
        if (e < 3) check(ok && worst <= 1e-3, N("edge_%s_preserved", what[e]), "worst %g from the analytic value", worst);
        else check(ok && worst > 0.05, "edge_without_guide_is_blurred", "worst %g (the filter must reach across)", worst);
        free(dm);
    }
    free(out);
    img_free(&a);
}

/* the ray distance to the plane z = -zp of a camera at the origin looking down -z */
static float plane_dist(const fovpt_camera *cam, uint32_t x, uint32_t y, float zp)
{
    float o[3], d[3];
    fovpt_camera_ray(cam, (float)x + 0.5f, (float)y + 0.5f, o, d);
    return (zp + o[2]) / -d[2];
}

/* reprojection: static camera exact (running mean), disocclusion rejected, one-pixel pan */
static void t_reproject(void)
{
    const uint32_t W = 40, H = 30;
    size_t n = (size_t)W * H, i;
    img a;
    fovpt_camera cam, cam2;
    fovpt_denoise dn;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    fov_gaze g = { 20.0f, 15.0f };
    fovpt_output o;
    float *A = (float *)malloc(n * 12u), *B = (float *)malloc(n * 12u), *C = (float *)malloc(n * 12u);
    float *out = (float *)malloc(n * 12u);
    void *dm = NULL;
    double w1 = 0.0, w2 = 0.0, w3 = 0.0, w4 = 0.0;
    uint32_t x, y, s = 12345u;
    int ok;
    img_alloc(&a, W, H);
    fovpt_camera_init(&cam, W, H);
    cam.pos[0] = cam.pos[1] = cam.pos[2] = 0.0f;
    cam.target[0] = cam.target[1] = 0.0f; cam.target[2] = -1.0f;
    for (i = 0; i < 3u * n; ++i) {
        s = s * 1664525u + 1013904223u; A[i] = (float)(s >> 8) / 16777216.0f;
        s = s * 1664525u + 1013904223u; B[i] = (float)(s >> 8) / 16777216.0f;
        s = s * 1664525u + 1013904223u; C[i] = (float)(s >> 8) / 16777216.0f;
    }
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            i = (size_t)y * W + x;
            a.dep[i] = plane_dist(&cam, x, y, 3.0f);
            a.nrm[3 * i + 2] = 1.0f;
        }
    a.g.var = NULL; a.g.spp = NULL; a.g.albedo = NULL;
    dc.width = W; dc.height = H; dc.no_filter = 1;
    ok = dn_make(&dn, &dc, &dm);
    fovpt_output_init(&o); o.rgb = out;
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, A, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, B, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    for (i = 0; i < 3u * n; ++i) w1 = fmax(w1, fabs((double)out[i] - 0.5 * ((double)A[i] + (double)B[i])));
    check(ok && w1 <= 1e-6, "static_history_maps_to_itself", "frame 2 differs from (A + B) / 2 by %g", w1);
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, C, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    for (i = 0; i < 3u * n; ++i) w2 = fmax(w2, fabs((double)out[i] - ((double)A[i] + (double)B[i] + (double)C[i]) / 3.0));
    check(ok && w2 <= 1e-6, "static_running_mean_frame3", "frame 3 differs from (A + B + C) / 3 by %g", w2);
    /* disocclusion: every depth doubled -> no history, the frame alone */
    for (i = 0; i < n; ++i) a.dep[i] *= 2.0f;
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, A, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    for (i = 0; i < 3u * n; ++i) w3 = fmax(w3, fabs((double)out[i] - (double)A[i]));
    check(ok && w3 <= 1e-6, "depth_mismatch_rejects_history", "differs from the frame by %g", w3);
    free(dm);
    /* a pan by exactly one pixel: the plane z = -3, the camera moves +x by one pixel's width */
    ok = dn_make(&dn, &dc, &dm);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) a.dep[(size_t)y * W + x] = plane_dist(&cam, x, y, 3.0f);
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, A, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    cam2 = cam;
    {
        float px = 3.0f * 2.0f * tanf(30.0f * 3.14159265f / 180.0f) / (float)H; /* one pixel at z = 3 */
        cam2.pos[0] += px; cam2.target[0] += px;
    }
    ok = ok && fovpt_denoise_frame(&dn, &cam2, g, B, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    for (y = 0; y < H; ++y)
        for (x = 0; x + 1u < W; ++x) {
            int k;
            for (k = 0; k < 3; ++k) {
                size_t p = 3 * ((size_t)y * W + x) + (size_t)k;
                w4 = fmax(w4, fabs((double)out[p] - 0.5 * ((double)A[p + 3] + (double)B[p])));
            }
        }
    check(ok && w4 <= 1e-3, "pan_one_pixel_reads_the_neighbour", "differs from (A[x+1] + B[x]) / 2 by %g", w4);
    free(dm);
    free(A); free(B); free(C); free(out);
    img_free(&a);
}

/* the foveation: the same noise is filtered less at the gaze than in the periphery */
static void t_foveation(void)
{
    const uint32_t W = 160, H = 120;
    size_t n = (size_t)W * H, i;
    img a;
    fovpt_camera cam;
    float *out = (float *)malloc(n * 12u);
    uint32_t x, y, s = 777u;
    int mode;
    img_alloc(&a, W, H);
    fovpt_camera_init(&cam, W, H);
    for (mode = 0; mode < 2; ++mode) {
        fovpt_denoise dn;
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 80.0f, 60.0f };
        fovpt_output o;
        void *dm = NULL;
        double sf = 0.0, sp = 0.0;
        size_t cf = 0, cp = 0;
        int ok;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                double r = hypot((double)x + 0.5 - 80.0, (double)y + 0.5 - 60.0);
                int k;
                i = (size_t)y * W + x;
                for (k = 0; k < 3; ++k) {
                    s = s * 1664525u + 1013904223u;
                    a.rgb[3 * i + (size_t)k] = 0.5f + 0.2f * ((float)(s >> 8) / 16777216.0f - 0.5f);
                    a.alb[3 * i + (size_t)k] = 0.5f;
                    a.nrm[3 * i + (size_t)k] = k == 2 ? 1.0f : 0.0f;
                }
                a.dep[i] = 1.0f;
                a.var[i] = -1.0f;
                /* mode 1: a layered density, 4 spp inside 20 px, 0.25 outside */
                a.spp[i] = (mode == 0 || r < 20.0) ? 4.0f : 0.25f;
            }
        dc.width = W; dc.height = H; dc.no_temporal = 1;
        if (mode == 0) dc.eye.quality = 8.0f; /* the eye's spacing passes a pixel at ~1 degree */
        ok = dn_make(&dn, &dc, &dm);
        fovpt_output_init(&o); o.rgb = out;
        ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                double r = hypot((double)x + 0.5 - 80.0, (double)y + 0.5 - 60.0), d;
                i = (size_t)y * W + x;
                if (x < 16 || y < 16 || x >= W - 16 || y >= H - 16) continue; /* no border */
                d = (double)out[3 * i] - 0.5;
                if (r < 8.0) { sf += d * d; cf++; }
                else if (r > 40.0) { sp += d * d; cp++; }
            }
        sf = sqrt(sf / (double)cf); sp = sqrt(sp / (double)cp);
        check(ok && sp < 0.6 * sf, N("fovea_filtered_least_%s", mode ? "density" : "eccentricity"),
              "residual noise fovea %.5f, periphery %.5f", sf, sp);
        free(dm);
    }
    free(out);
    img_free(&a);
}

static void t_errors(void)
{
    fovpt_denoise dn;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default(), r;
    fovpt_camera cam;
    fovpt_output o;
    fov_gaze g = { 4.0f, 4.0f }, bad = { NAN, 0.0f };
    img a;
    size_t b = 0;
    uint64_t *mem;
    img_alloc(&a, 8, 8);
    fovpt_camera_init(&cam, 8, 8);
    fovpt_output_init(&o);
    o.rgb = a.rgb;
    dc.logger.func = logger;
    check(fovpt_denoise_size(&dc, &b) == FOV_ERR_INVALID_ARG, "size_zero", "width 0 accepted");
    dc.width = 8; dc.height = 8;
    check(fovpt_denoise_size(NULL, &b) == FOV_ERR_NULL && fovpt_denoise_size(&dc, NULL) == FOV_ERR_NULL, "size_null", "NULL accepted");
    r = dc; r.width = FOVPT_MAX_DIM + 1u;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_LIMIT, "size_limit", "over FOVPT_MAX_DIM accepted");
    r = dc; r.levels = FOVPT_DN_MAX_LEVELS + 1u;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "levels_cap", "levels above the cap accepted");
    r = dc; r.phi_lum = NAN;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_NOT_FINITE, "nan_field", "NaN accepted");
    r = dc; r.skip_noise = -1.0f;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "dn_cfg_skip_noise_negative", "skip_noise -1 accepted");
    r = dc; r.r_small = 0.5f;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "dn_cfg_r_small_below_1", "r_small 0.5 accepted");
    r = dc; r.spp_full = NAN;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_NOT_FINITE, "dn_cfg_spp_full_nan", "spp_full NaN accepted");
    r = dc; r.spp_full = -2.0f;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "dn_cfg_spp_full_negative", "spp_full -2 accepted");
    r = dc; r.no_sure = 2;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "dn_cfg_no_sure_2", "no_sure 2 accepted");
    r = dc; r.sure_radius = 9;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "dn_cfg_sure_radius_9", "sure_radius 9 accepted");
    r = dc; r.sure_min_spp = 1.5f;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG, "dn_cfg_sure_min_spp_below_2", "sure_min_spp 1.5 accepted");
    r = dc; r.sure_min_spp = NAN;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_NOT_FINITE, "dn_cfg_sure_min_spp_nan", "sure_min_spp NaN accepted");
    {   /* the selection's memory: FOVPT__DN_SEL floats per pixel more than without */
        size_t b0 = 0, b1 = 0;
        r = dc; r.width = 10; r.height = 10;
        fovpt_denoise_size(&r, &b0);
        r.no_sure = 1;
        fovpt_denoise_size(&r, &b1);
        check(b0 == b1 + 100u * 4u * FOVPT__DN_SEL, "dn_size_sure", "%zu bytes with, %zu without", b0, b1);
    }
    r = dc; r.alpha_fovea = 0.1f; r.alpha_periphery = 0.5f;
    g_log_count = 0;
    check(fovpt_denoise_size(&r, &b) == FOV_ERR_INVALID_ARG && g_log_count == 1 && g_log_code == FOV_ERR_INVALID_ARG,
          "alpha_order_logged", "alpha_periphery > alpha_fovea accepted or not logged");
    check(fovpt_denoise_size(&dc, &b) == FOV_OK && b >= 8u * 8u * 132u, "size_ok", "%zu bytes", b);
    mem = (uint64_t *)malloc(b + 8u);
    check(fovpt_denoise_init(&dn, &dc, mem, b - 1u) == FOV_ERR_TOO_SMALL, "init_too_small", "accepted");
    check(fovpt_denoise_init(&dn, &dc, (char *)mem + 4, b) == FOV_ERR_INVALID_ARG, "init_misaligned", "accepted");
    check(fovpt_denoise_init(&dn, &dc, NULL, b) == FOV_ERR_NULL, "init_null_mem", "accepted");
    check(fovpt_denoise_init(&dn, &dc, mem, b) == FOV_OK, "init_ok", "failed");
    check(fovpt_denoise_temporal_rows(&dn, 0, 8) == FOV_ERR_INVALID_ARG, "rows_before_frame", "accepted");
    check(fovpt_denoise_frame(&dn, &cam, g, NULL, 0, &a.g) == FOV_ERR_NULL, "frame_null_rgb", "accepted");
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, NULL) == FOV_ERR_NULL, "frame_null_guide", "accepted");
    a.g.depth = NULL;
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_ERR_NULL, "frame_no_depth", "accepted");
    a.g.depth = a.dep;
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 23, &a.g) == FOV_ERR_INVALID_ARG, "frame_rgb_stride", "stride 23 < 24 accepted");
    a.g.normal_stride = 5;
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_ERR_INVALID_ARG, "frame_normal_stride", "accepted");
    a.g.normal_stride = 0;
    check(fovpt_denoise_frame(&dn, &cam, bad, a.rgb, 0, &a.g) == FOV_ERR_NOT_FINITE, "frame_nan_gaze", "accepted");
    cam.width = 9;
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_ERR_INVALID_ARG, "frame_size_mismatch", "accepted");
    cam.width = 8;
    cam.target[0] = cam.pos[0]; cam.target[1] = cam.pos[1]; cam.target[2] = cam.pos[2];
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_ERR_DEGENERATE, "frame_bad_camera", "accepted");
    fovpt_camera_init(&cam, 8, 8);
    check(fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK, "frame_ok", "failed");
    check(fovpt_denoise_temporal_rows(&dn, 5, 9) == FOV_ERR_INVALID_ARG, "temporal_rows_range", "accepted");
    check(fovpt_denoise_atrous_rows(&dn, fovpt_denoise_passes(&dn), 0, 8) == FOV_ERR_INVALID_ARG, "atrous_pass_range", "accepted");
    check(fovpt_denoise_atrous_rows(&dn, 0, 3, 2) == FOV_ERR_INVALID_ARG, "atrous_rows_range", "accepted");
    o.rgb_stride = 10;
    check(fovpt_denoise_resolve_rows(&dn, 0, 8, &o) == FOV_ERR_INVALID_ARG, "resolve_stride", "accepted");
    check(fovpt_denoise_resolve_rows(&dn, 0, 8, NULL) == FOV_ERR_NULL, "resolve_null", "accepted");
    o.rgb_stride = 0;
    check(fovpt_denoise_run(&dn, &o) == FOV_OK, "run_ok", "failed");
    check(fovpt_denoise_run(NULL, &o) == FOV_ERR_NULL && fovpt_denoise_reset(NULL) == FOV_ERR_NULL, "null_ctx", "accepted");
    /* the guide trace rejects a short stride */
    {
        fovpt_material m;
        fovpt_scene s;
        void *sm = NULL, *cm;
        fovpt_config c = fovpt_config_default();
        fovpt_ctx ctx;
        size_t cb = 0;
        fovpt_material_init(&m);
        if (box_scene(&s, &sm, &m)) {
            box_cam(&cam, 8, 8);
            fovpt_memory_size(&c, &cam, &cb);
            cm = malloc(cb + 16u);
            fovpt_init(&ctx, &c, &s, &cam, g, cm, cb);
            a.g.depth_stride = 7;
            check(fovpt_trace_rows_guide(&ctx, 0, 0, 8, &a.g, NULL) == FOV_ERR_INVALID_ARG, "guide_stride", "accepted");
            a.g.depth_stride = 0;
            check(fovpt_trace_rows_guide(&ctx, 0, 4, 2, &a.g, NULL) == FOV_ERR_INVALID_ARG, "guide_rows", "accepted");
            check(fovpt_trace_rows_guide(NULL, 0, 0, 8, &a.g, NULL) == FOV_ERR_NULL, "guide_null_ctx", "accepted");
            free(cm);
        }
        free(sm);
    }
    free(mem);
    img_free(&a);
}

/* the guided trace traces the same samples as fovpt_trace_rows: the same image */
static void t_same_image(void)
{
    fovpt_material m;
    fovpt_scene s;
    fovpt_camera cam;
    void *sm = NULL;
    uint32_t meth;
    fovpt_material_init(&m);
    m.albedo[0] = 0.6f; m.albedo[1] = 0.5f; m.albedo[2] = 0.4f;
    m.emission[0] = m.emission[1] = m.emission[2] = 0.3f;
    if (!box_scene(&s, &sm, &m)) return;
    box_cam(&cam, 40, 30);
    for (meth = 0; meth < 3; ++meth) {
        fovpt_config c = fovpt_config_default();
        fovpt_ctx ctx;
        fovpt_output o;
        fovpt_stats s1, s2;
        size_t b = 0;
        void *mem;
        fov_gaze g = { 20.0f, 15.0f };
        img a;
        float *ref = (float *)malloc(40u * 30u * 12u);
        c.method = meth == 0 ? FOVPT_METHOD_UNIFORM : meth == 1 ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_ZONES;
        c.spp = 2;
        img_alloc(&a, 40, 30);
        fovpt_memory_size(&c, &cam, &b);
        mem = malloc(b + 16u);
        fovpt_init(&ctx, &c, &s, &cam, g, mem, b);
        fovpt_output_init(&o);
        o.rgb = ref;
        fovpt_stats_init(&s1); fovpt_stats_init(&s2);
        fovpt_render(&ctx, 3, &o, &s1);
        o.rgb = a.rgb;
        fovpt_render_guide(&ctx, 3, &o, &a.g, &s2);
        check(memcmp(ref, a.rgb, 40u * 30u * 12u) == 0 && s1.samples == s2.samples,
              N("guided_trace_same_image_%u", meth), "images or sample counts differ");
        check(s2.rays == s2.camera_rays + s2.bounce_rays + s2.shadow_rays, N("guided_stats_sum_%u", meth), "rays not the sum");
        if (meth == 0) {
            size_t i, bad = 0;
            for (i = 0; i < 40u * 30u; ++i) bad += a.spp[i] != 2.0f || !(a.var[i] >= 0.0f) || fabsf(a.alb[3 * i] - 0.6f) > 1e-6f;
            check(bad == 0, "guide_uniform_spp_var_albedo", "%zu pixels with spp != 2, var < 0 or albedo != 0.6", bad);
        } else {
            /* the gaze pixel has the innermost layer's density, the corner a coarser one;
               a var only where one stride-1 layer alone gives the value (its own spp, 2: no
               blend band), -1 elsewhere */
            size_t i, own = 0, bad = 0;
            float sp1 = (float)ctx.lay.layer[ctx.lay.count - 1u].spp; /* the innermost layer's */
            for (i = 0; i < 40u * 30u; ++i) {
                own += a.var[i] >= 0.0f;
                bad += a.var[i] >= 0.0f ? a.spp[i] != sp1 : a.var[i] != -1.0f;
            }
            /* (ZONES at 40 x 30: every fovea pixel is in a blend band) */
            check((meth == 2 || own > 0u) && bad == 0u, N("guide_layers_var_own_only_%u", meth),
                  "%zu pixels with a var, %zu with a var but a blended spp or another negative var", own, bad);
            check(a.spp[15 * 40 + 20] > a.spp[0] && (meth == 2 || a.var[15 * 40 + 20] >= 0.0f) && fabsf(a.var[0] + 1.0f) < 1e-6f,
                  N("guide_layers_density_%u", meth), "gaze spp %g var %g, corner spp %g var %g", (double)a.spp[15 * 40 + 20],
                  (double)a.var[15 * 40 + 20], (double)a.spp[0], (double)a.var[0]);
        }
        free(mem); free(ref);
        img_free(&a);
    }
    free(sm);
}

/* var with accumulate: the variance of the accumulated mean (second call's sample variance /
   4 accumulated samples, about half the first call's / 2) */
/* the box of t_var_accum and t_two_stride1 (walls albedo 0.6 / 0.5 / 0.4, emission 0.3), w x h,
   rendered with c and its guides into r->a (frame 0); -1: the scene did not build */
typedef struct box_run {
    fovpt_material m; /* the scene keeps a pointer to it */
    fovpt_scene s;
    fovpt_camera cam;
    fovpt_ctx ctx;
    fovpt_output o;
    void *sm, *mem;
    img a;
} box_run;
static int box_run_start(box_run *r, const fovpt_config *c, uint32_t w, uint32_t h, fov_gaze g)
{
    size_t b = 0;
    int ok;
    fovpt_material_init(&r->m);
    r->m.albedo[0] = 0.6f; r->m.albedo[1] = 0.5f; r->m.albedo[2] = 0.4f;
    r->m.emission[0] = r->m.emission[1] = r->m.emission[2] = 0.3f;
    r->sm = r->mem = NULL;
    if (!box_scene(&r->s, &r->sm, &r->m)) return -1;
    box_cam(&r->cam, w, h);
    img_alloc(&r->a, w, h);
    ok = fovpt_memory_size(c, &r->cam, &b) == FOV_OK;
    r->mem = malloc(b + 16u);
    ok = ok && fovpt_init(&r->ctx, c, &r->s, &r->cam, g, r->mem, b) == FOV_OK;
    fovpt_output_init(&r->o);
    r->o.rgb = r->a.rgb;
    return ok && fovpt_render_guide(&r->ctx, 0, &r->o, &r->a.g, NULL) == FOV_OK;
}
static void box_run_end(box_run *r)
{
    free(r->mem); free(r->sm);
    img_free(&r->a);
}

static void t_var_accum(void)
{
    fovpt_config c = fovpt_config_default();
    fov_gaze g = { 20.0f, 15.0f };
    box_run r;
    size_t i;
    double v0 = 0.0, v1 = 0.0;
    int ok;
    c.method = FOVPT_METHOD_UNIFORM; c.spp = 2; c.accumulate = 1;
    ok = box_run_start(&r, &c, 40, 30, g);
    if (ok < 0) return;
    for (i = 0; i < 40u * 30u; ++i) v0 += (double)r.a.var[i];
    ok = ok && fovpt_render_guide(&r.ctx, 1, &r.o, &r.a.g, NULL) == FOV_OK;
    for (i = 0; i < 40u * 30u; ++i) v1 += (double)r.a.var[i];
    check(ok && r.a.spp[0] == 4.0f && v0 > 0.0 && v1 / v0 > 0.35 && v1 / v0 < 0.65, "guide_var_accumulate",
          "ok %d spp %g, mean var %g -> %g (ratio %.3f, want ~0.5)", ok, (double)r.a.spp[0], v0 / 1200.0, v1 / 1200.0, v1 / v0);
    box_run_end(&r);
}

/* two stride-1 layers overlapping in their blend band (7 .. 13 degrees): inside it the
   inner layer alone (4 spp: var >= 0); in the band the value mixes the two layers, so the
   var of one layer's samples is not the value's: -1 (earlier versions: the var of the
   layer with the larger weight); outside, the outer layer's 1 spp: -1 */
static void t_two_stride1(void)
{
    fovpt_config c = fovpt_config_default();
    fov_gaze g = { 80.0f, 60.0f };
    box_run r;
    uint32_t x, y, in_n = 0, in_bad = 0, out_n = 0, out_bad = 0;
    int ok;
    c.method = FOVPT_METHOD_LAYERS; c.spp = 1;
    c.layers.count = 2; c.layers.blend_deg = 6.0f;
    c.layers.layer[0].stride = 1; c.layers.layer[0].spp = 1; c.layers.layer[0].radius_deg = 0.0f;
    c.layers.layer[1].stride = 1; c.layers.layer[1].spp = 4; c.layers.layer[1].radius_deg = 10.0f;
    ok = box_run_start(&r, &c, 160, 120, g);
    if (ok < 0) return;
    for (y = 0; ok && y < 120; ++y)
        for (x = 0; x < 160; ++x) {
            float e = fovpt_ecc_deg(&r.ctx.ecc, (float)x + 0.5f, (float)y + 0.5f), v = r.a.var[y * 160u + x];
            if (e < 6.7f) { in_n++; in_bad += !(v >= 0.0f); }
            if (e > 7.3f && e < 12.7f && e <= r.ctx.layer_trace_deg[1]) { out_n++; out_bad += v != -1.0f; }
        }
    check(ok && in_n > 20u && out_n > 20u && in_bad == 0u && out_bad == 0u, "guide_two_stride1_band_var_unknown",
          "ok %d: inside the band %u px (%u without var), in the band %u px (%u with var; trace %g deg)", ok, in_n, in_bad,
          out_n, out_bad, ok ? (double)r.ctx.layer_trace_deg[1] : 0.0);
    box_run_end(&r);
}

/* a synthetic frame: left third sky (depth 0), the rest a wall at depth 2 facing the camera,
   noisy colours from a hash of (x, y, f) */
static void synth_frame(img *a, uint32_t f)
{
    uint32_t x, y, k;
    for (y = 0; y < a->h; ++y)
        for (x = 0; x < a->w; ++x) {
            size_t i = (size_t)y * a->w + x;
            uint32_t h = (x * 73856093u) ^ (y * 19349663u) ^ ((f + 1u) * 83492791u);
            for (k = 0; k < 3; ++k) {
                h = h * 1664525u + 1013904223u;
                a->rgb[3 * i + k] = 0.5f + (float)(h >> 8) * (1.0f / 16777216.0f);
                a->alb[3 * i + k] = 0.5f;
            }
            a->dep[i] = x < a->w / 3u ? 0.0f : 2.0f;
            a->nrm[3 * i] = 0.0f; a->nrm[3 * i + 1] = 0.0f; a->nrm[3 * i + 2] = 1.0f;
            a->spp[i] = 2.0f;
            a->var[i] = -1.0f;
        }
}

/* runs every phase with row ranges of `rows` rows */
static int dn_split(fovpt_denoise *dn, uint32_t rows, float *out)
{
    uint32_t y, i, H = dn->cfg.height;
    fovpt_output o;
    fovpt_output_init(&o); o.rgb = out;
    for (y = 0; y < H; y += rows)
        if (fovpt_denoise_temporal_rows(dn, y, y + rows < H ? y + rows : H) != FOV_OK) return 0;
    for (i = 0; i < fovpt_denoise_passes(dn); ++i)
        for (y = 0; y < H; y += rows)
            if (fovpt_denoise_atrous_rows(dn, i, y, y + rows < H ? y + rows : H) != FOV_OK) return 0;
    for (y = 0; y < H; y += rows)
        if (fovpt_denoise_resolve_rows(dn, y, y + rows < H ? y + rows : H, &o) != FOV_OK) return 0;
    return 1;
}

/* never-written memory, phases out of order, a failed frame, the row split */
static void t_robust(void)
{
    const uint32_t W = 32, H = 24;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    fovpt_denoise dn;
    fovpt_camera cam;
    fovpt_output o;
    fov_gaze g = { 16.0f, 12.0f }, gnan;
    img a, b;
    size_t bytes = 0, i, bad;
    void *mem;
    float *out = (float *)malloc((size_t)W * H * 12u), *ref = (float *)malloc((size_t)W * H * 12u);
    uint32_t split, f;
    int ok;
    gnan.x = (float)nan(""); gnan.y = 12.0f;
    box_cam(&cam, W, H);
    img_alloc(&a, W, H); img_alloc(&b, W, H);
    synth_frame(&a, 0); synth_frame(&b, 1);
    dc.width = W; dc.height = H;
    fovpt_denoise_size(&dc, &bytes);
    mem = malloc(bytes);
    fovpt_output_init(&o); o.rgb = out;
    /* 1. memory full of 0xFF (NaN floats), two frames without a phase between, then run */
    memset(mem, 0xFF, bytes);
    ok = fovpt_denoise_init(&dn, &dc, mem, bytes) == FOV_OK &&
         fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
         fovpt_denoise_frame(&dn, &cam, g, b.rgb, 0, &b.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    for (bad = 0, i = 0; i < 3u * W * H; ++i) bad += !(out[i] >= 0.0f && out[i] < 2.0f);
    check(ok && bad == 0, "dn_ff_memory_finite", "ok %d, %zu values not finite in [0, 2)", ok, bad);
    /* the same, one frame run in between: frame 2 takes frame 1 as history (finite, in range) */
    memset(mem, 0xFF, bytes);
    ok = fovpt_denoise_init(&dn, &dc, mem, bytes) == FOV_OK &&
         fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK &&
         fovpt_denoise_frame(&dn, &cam, g, b.rgb, 0, &b.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    for (bad = 0, i = 0; i < 3u * W * H; ++i) bad += !(out[i] >= 0.0f && out[i] < 2.0f);
    check(ok && bad == 0 && dn.has_prev, "dn_ff_memory_history", "ok %d has_prev %u, %zu bad values", ok, dn.has_prev, bad);
    /* 4. phases out of order */
    ok = fovpt_denoise_init(&dn, &dc, mem, bytes) == FOV_OK && fovpt_denoise_passes(&dn) >= 2u &&
         fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK;
    check(ok && fovpt_denoise_resolve_rows(&dn, 0, H, &o) == FOV_ERR_INVALID_ARG, "dn_order_resolve_first",
          "resolve right after frame accepted");
    check(fovpt_denoise_atrous_rows(&dn, 0, 0, H) == FOV_ERR_INVALID_ARG, "dn_order_atrous_first",
          "a-trous before temporal accepted");
    check(fovpt_denoise_temporal_rows(&dn, 0, 10) == FOV_OK &&
          fovpt_denoise_atrous_rows(&dn, 0, 0, H) == FOV_ERR_INVALID_ARG, "dn_order_partial_temporal",
          "a-trous on rows whose temporal phase did not run accepted");
    check(fovpt_denoise_temporal_rows(&dn, 10, H) == FOV_OK && fovpt_denoise_atrous_rows(&dn, 1, 0, H) == FOV_ERR_INVALID_ARG,
          "dn_order_skip_pass", "pass 1 before pass 0 accepted");
    check(fovpt_denoise_atrous_rows(&dn, 0, 0, H) == FOV_OK && fovpt_denoise_resolve_rows(&dn, 0, H, &o) == FOV_ERR_INVALID_ARG &&
          fovpt_denoise_temporal_rows(&dn, 0, H) == FOV_ERR_INVALID_ARG, "dn_order_resolve_early",
          "resolve before the last pass or temporal after a pass accepted");
    for (i = 1, ok = 1; i < fovpt_denoise_passes(&dn); ++i) ok = ok && fovpt_denoise_atrous_rows(&dn, (uint32_t)i, 0, H) == FOV_OK;
    check(ok && fovpt_denoise_resolve_rows(&dn, 0, H, &o) == FOV_OK && fovpt_denoise_resolve_rows(&dn, 0, H, &o) == FOV_OK,
          "dn_order_complete", "the phases in order rejected");
    /* 5. a failed frame leaves no frame: every row call fails until the next good frame */
    check(fovpt_denoise_frame(&dn, &cam, gnan, b.rgb, 0, &b.g) == FOV_ERR_NOT_FINITE &&
          fovpt_denoise_temporal_rows(&dn, 0, H) == FOV_ERR_INVALID_ARG && fovpt_denoise_atrous_rows(&dn, 0, 0, H) == FOV_ERR_INVALID_ARG &&
          fovpt_denoise_resolve_rows(&dn, 0, H, &o) == FOV_ERR_INVALID_ARG && fovpt_denoise_run(&dn, &o) == FOV_ERR_INVALID_ARG,
          "dn_failed_frame_rows_fail", "row calls after a failed frame accepted");
    check(fovpt_denoise_frame(&dn, &cam, g, b.rgb, 0, &b.g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK && dn.has_prev,
          "dn_failed_frame_recovers", "the next good frame failed or lost the history");
    /* 9. row split: rows of 1, 3 and all give bit-identical output (two frames, history on) */
    for (split = 0; split < 3; ++split) {
        uint32_t rows = split == 0 ? H : split == 1 ? 1u : 3u;
        ok = fovpt_denoise_init(&dn, &dc, mem, bytes) == FOV_OK;
        for (f = 0; f < 2; ++f)
            ok = ok && fovpt_denoise_frame(&dn, &cam, g, f ? b.rgb : a.rgb, 0, f ? &b.g : &a.g) == FOV_OK &&
                 dn_split(&dn, rows, split ? out : ref);
        if (split)
            check(ok && memcmp(out, ref, (size_t)W * H * 12u) == 0, N("dn_row_split_identical_%u", rows),
                  "rows of %u differ from the whole image (ok %d)", rows, ok);
    }
    free(mem); free(out); free(ref);
    img_free(&a); img_free(&b);
}

/* the normal stop's -ln c series (folded into the tap's exponential) against logf / powf */
static void t_nlog(void)
{
    double worst = 0.0, worst_w = 0.0, worst_a32 = 0.0;
    int below = 1, i;
    for (i = 0; i <= 2500; ++i) {
        float c = 0.75f + 0.25f * (float)i / 2500.0f;
        double t = -log((double)c), a = (double)fovpt__dn_nlog(c), w, we;
        if (a > t + 1e-7) below = 0;
        if (fabs(a - t) > worst) worst = fabs(a - t);
        w = exp(-128.0 * a);
        we = pow((double)c, 128.0);
        if (we > exp(-10.0) && fabs(w / we - 1.0) > worst_w) worst_w = fabs(w / we - 1.0);
        w = exp(-32.0 * a); /* the default phi_normal: the weight's absolute error */
        we = pow((double)c, 32.0);
        if (fabs(w - we) > worst_a32) worst_a32 = fabs(w - we);
    }
    check(worst <= 2.7e-4 && below, "nlog_series_bound", "worst |series + ln c| %g (bound 2.7e-4), never above: %d", worst, below);
    check(worst_w <= 1e-4, "nlog_weight_128", "c^128 relative error %g where above e^-10 (want <= 1e-4)", worst_w);
    check(worst_a32 <= 3.2e-6, "nlog_weight_32", "c^32 absolute error %g on [0.75, 1] (want <= 3.2e-6, the documented bound)", worst_a32);
}

/* one frame of a through a denoiser made for dc (no history); *info (may be NULL): its state
   after the run (its passes and resolved cfg; the memory is freed) */
static int dn_once(fovpt_denoise_cfg *dc, img *a, fov_gaze g, float *out, fovpt_denoise *info)
{
    fovpt_denoise dn;
    fovpt_camera cam;
    fovpt_output o;
    void *dm = NULL;
    int ok;
    fovpt_camera_init(&cam, a->w, a->h);
    ok = dn_make(&dn, dc, &dm);
    fovpt_output_init(&o);
    o.rgb = out;
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, a->rgb, 0, &a->g) == FOV_OK && fovpt_denoise_run(&dn, &o) == FOV_OK;
    if (info) *info = dn;
    free(dm);
    return ok;
}

/* An independent a-trous in double (the documented filter: B3 5 x 5 or linear 3 x 3 taps,
   Schied et al.'s stops with exp and pow) for one pass over rgb/var (W x H), in place. */
static void ref_atrous(const img *a, float *rgb, float *var, uint32_t W, uint32_t H, int step, int rad,
                       const fovpt_denoise_cfg *c)
{
    static const double h5[5] = { 0.0625, 0.25, 0.375, 0.25, 0.0625 }, h3[3] = { 0.25, 0.5, 0.25 };
    const double *hk = rad == 1 ? h3 : h5;
    size_t n = (size_t)W * H;
    float *o = (float *)malloc(n * 12u), *ov = (float *)malloc(n * 4u);
    int x, y, dx, dy, k, w_ = (int)W, h_ = (int)H;
    for (y = 0; y < h_; ++y)
        for (x = 0; x < w_; ++x) {
            size_t i = (size_t)y * W + (size_t)x;
            double v3 = 0.0, lp, sig, zp = (double)a->dep[i] > 0.0 ? (double)a->dep[i] : 0.0, s0 = 1e30, s1 = 1e30, acc[3] = { 0, 0, 0 }, ws = 0, wv = 0;
            for (dy = -1; dy <= 1; ++dy)
                for (dx = -1; dx <= 1; ++dx) {
                    int qx = x + dx < 0 ? 0 : x + dx >= w_ ? w_ - 1 : x + dx, qy = y + dy < 0 ? 0 : y + dy >= h_ ? h_ - 1 : y + dy;
                    v3 += h3[dx + 1] * h3[dy + 1] * (double)var[(size_t)qy * W + (size_t)qx];
                }
            lp = 0.2126 * (double)rgb[3 * i] + 0.7152 * (double)rgb[3 * i + 1] + 0.0722 * (double)rgb[3 * i + 2];
            sig = 1.0 / ((double)c->phi_lum * sqrt(v3) + 1e-6);
            if (x > 0) s0 = fabs(zp - (double)a->dep[i - 1]);
            if (x + 1 < w_ && fabs(zp - (double)a->dep[i + 1]) < s0) s0 = fabs(zp - (double)a->dep[i + 1]);
            if (y > 0) s1 = fabs(zp - (double)a->dep[i - W]);
            if (y + 1 < h_ && fabs(zp - (double)a->dep[i + W]) < s1) s1 = fabs(zp - (double)a->dep[i + W]);
            if (s0 > 1e29) s0 = 0.0;
            if (s1 > 1e29) s1 = 0.0;
            for (dy = -rad; dy <= rad; ++dy)
                for (dx = -rad; dx <= rad; ++dx) {
                    int qx = x + dx * step, qy = y + dy * step;
                    size_t j;
                    double w, ex, lq, zq, cn, da;
                    if (qx < 0 || qy < 0 || qx >= w_ || qy >= h_) continue;
                    j = (size_t)qy * W + (size_t)qx;
                    w = hk[dx + rad] * hk[dy + rad];
                    if (dx || dy) {
                        zq = (double)a->dep[j] > 0.0 ? (double)a->dep[j] : 0.0;
                        if ((zp > 0.0) != (zq > 0.0)) continue;
                        lq = 0.2126 * (double)rgb[3 * j] + 0.7152 * (double)rgb[3 * j + 1] + 0.0722 * (double)rgb[3 * j + 2];
                        ex = fabs(lp - lq) * sig;
                        if (zp > 0.0) {
                            ex += fabs(zp - zq) / ((double)c->phi_depth * step * (s0 * abs(dx) + s1 * abs(dy)) + 1e-3 * zp);
                            cn = (double)a->nrm[3 * i] * (double)a->nrm[3 * j] + (double)a->nrm[3 * i + 1] * (double)a->nrm[3 * j + 1] +
                                 (double)a->nrm[3 * i + 2] * (double)a->nrm[3 * j + 2];
                            if (!(cn > 0.0)) continue;
                            w *= pow(cn, (double)c->phi_normal);
                        }
                        for (k = 0; k < 3; ++k) {
                            da = (double)a->alb[3 * i + (size_t)k] - (double)a->alb[3 * j + (size_t)k];
                            ex += da * da / ((double)c->phi_albedo * (double)c->phi_albedo);
                        }
                        w *= exp(-ex);
                    }
                    for (k = 0; k < 3; ++k) acc[k] += w * (double)rgb[3 * j + (size_t)k];
                    ws += w;
                    wv += w * w * (double)var[j];
                }
            for (k = 0; k < 3; ++k) o[3 * i + (size_t)k] = (float)(acc[k] / ws);
            ov[i] = (float)(wv / (ws * ws));
        }
    memcpy(rgb, o, n * 12u);
    memcpy(var, ov, n * 4u);
    free(o); free(ov);
}

/* the library's a-trous (5 x 5 and the 3 x 3 taps of r_small) equals the reference above on an
   image with normal, depth, albedo and luminance structure (every pass at every pixel) */
static void t_kernel_ref(void)
{
    const uint32_t W = 48, H = 36;
    size_t n = (size_t)W * H, i;
    img a;
    float *out = (float *)malloc(n * 12u), *rr = (float *)malloc(n * 12u), *rv = (float *)malloc(n * 4u);
    uint32_t x, y, s = 4242u;
    int rad;
    img_alloc(&a, W, H);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            int k, reg = (x * 3u < W ? 0 : x * 3u < 2u * W ? 1 : 2) + (y > H / 2 ? 3 : 0);
            double tilt = (reg % 3) * 0.5236 * ((y & 8u) ? 1.0 : 0.3); /* 0, ~9..30, ~18..60 degrees */
            i = (size_t)y * W + x;
            for (k = 0; k < 3; ++k) {
                s = s * 1664525u + 1013904223u;
                a.rgb[3 * i + (size_t)k] = 0.3f + 0.1f * (float)reg + 0.3f * ((float)(s >> 8) / 16777216.0f);
                a.alb[3 * i + (size_t)k] = reg >= 3 ? 0.5f : 0.45f + 0.02f * (float)k;
            }
            a.nrm[3 * i] = (float)sin(tilt); a.nrm[3 * i + 1] = 0.0f; a.nrm[3 * i + 2] = (float)cos(tilt);
            a.dep[i] = (x > 40u && y < 6u) ? 0.0f : 1.0f + 0.02f * (float)x + (reg == 4 ? 0.5f : 0.0f); /* a miss corner */
            a.spp[i] = 8.0f; /* a trusted var: the a-trous input is the guide's var */
            s = s * 1664525u + 1013904223u;
            a.var[i] = 0.002f + 0.004f * ((float)(s >> 8) / 16777216.0f);
        }
    for (rad = 4; rad >= 1; --rad) { /* 4, 3: phi_normal 128, 2, 1: the default 32 (both take the series) */
        fovpt_denoise dn;
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 24.0f, 18.0f };
        double worst = 0.0;
        uint32_t p;
        int ok, pn128 = rad > 2;
        if (pn128) rad -= 2;
        dc.width = W; dc.height = H; dc.no_temporal = 1;
        dc.fovea_step = 65536.0f; dc.skip_noise = 1e-9f; dc.spp_full = 1e30f;
        dc.r_small = rad == 2 ? 65536.0f : 1.0f;
        if (pn128) dc.phi_normal = 128.0f;
        ok = dn_once(&dc, &a, g, out, &dn);
        memcpy(rr, a.rgb, n * 12u);
        memcpy(rv, a.var, n * 4u);
        for (p = 0; p < dn.passes; ++p) ref_atrous(&a, rr, rv, W, H, 1 << p, rad, &dn.cfg);
        for (i = 0; i < n * 3u; ++i)
            if (fabs((double)out[i] - (double)rr[i]) > worst) worst = fabs((double)out[i] - (double)rr[i]);
        check(ok && worst <= 2e-5, N("atrous_equals_reference_%dx%d%s", 2 * rad + 1, 2 * rad + 1, pn128 ? "_pn128" : ""),
              "worst |library - double reference| %g over %u passes (ok %d)", worst, dn.passes, ok);
        if (pn128) rad += 2;
    }
    free(out); free(rr); free(rv);
    img_free(&a);
}

/* the flat guides of t_adaptive and t_skip_evidence: albedo 0.5, normal +z, depth 1, the
   given spp and var at every pixel */
static void flat_guides(img *a, float spp, float var)
{
    size_t i, k, n = (size_t)a->w * a->h;
    for (i = 0; i < n; ++i) {
        for (k = 0; k < 3; ++k) {
            a->alb[3 * i + k] = 0.5f;
            a->nrm[3 * i + k] = k == 2 ? 1.0f : 0.0f;
        }
        a->dep[i] = 1.0f;
        a->spp[i] = spp;
        a->var[i] = var;
    }
}

/* the adaptive policy: a converged pixel (spp far above spp_full, or noise below skip_noise
   display codes) is left as it is; below, the same image is filtered */
static void t_adaptive(void)
{
    const uint32_t W = 40, H = 30;
    size_t n = (size_t)W * H, i;
    img a;
    float *out = (float *)malloc(n * 12u);
    uint32_t s = 99u;
    int mode;
    img_alloc(&a, W, H);
    for (mode = 0; mode < 4; ++mode) {
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 20.0f, 15.0f };
        double diff = 0.0;
        int ok, k;
        for (i = 0; i < n; ++i)
            for (k = 0; k < 3; ++k) {
                s = s * 1664525u + 1013904223u;
                a.rgb[3 * i + (size_t)k] = 0.4f + 0.2f * ((float)(s >> 8) / 16777216.0f);
            }
        /* 0: 1024 spp (k = 1/8: widest step 1/2, no pass); 1: 16 spp (every pass);
           2: var 0 from 8 spp (noise 0 codes: skipped); 3: var 1e-4 (~1.3 codes: filtered) */
        flat_guides(&a, mode == 0 ? 1024.0f : mode == 1 ? 16.0f : 8.0f,
                    mode == 2 ? 0.0f : mode == 3 ? 1e-4f : 0.003f);
        dc.width = W; dc.height = H; dc.no_temporal = 1; dc.spp_ref = 16.0f;
        ok = dn_once(&dc, &a, g, out, NULL);
        for (i = 0; i < n * 3u; ++i) diff += fabs((double)out[i] - (double)a.rgb[i]);
        diff /= (double)(n * 3u);
        if (mode == 0 || mode == 2)
            check(ok && diff == 0.0, N("adaptive_converged_untouched_%s", mode ? "noise" : "spp"), "mean |out - in| %g (ok %d)", diff, ok);
        else
            check(ok && diff > 0.01, N("adaptive_noisy_filtered_%s", mode == 3 ? "noise" : "spp"), "mean |out - in| %g (ok %d)", diff, ok);
    }
    free(out);
    img_free(&a);
}

/* the default normal stop (phi_normal 32), one 5 x 5 pass: a surface whose normals tilt at
   random by up to 6 degrees about two axes (a faceted terrain) is smoothed as one surface:
   noise std times 0.36 or less (measured 0.32; with 0.7.0's default 128 it is 0.40, 16: 0.31:
   the bound needs phi_normal below ~100); a noise-free 45 degree crease between radiance 0.3
   and 0.7 with a loose luminance stop (var 0.0075: 0.4 is 0.58 phi_lum sigmas) stays an edge:
   the columns beside it within 0.002 of their side's value on average (phi_normal 16:
   0.0004, 8: 0.006, 4: 0.024); so does a 30 degree crease, whose normal weight falls in the
   series' range (c = 0.866): cos 30 degrees ^ 32 = 0.0101, and in the 5 x 5 kernel the two
   columns across the crease carry 5/16 of the 1-D weight against 11/16 on the pixel's side,
   so even with a luminance weight of 1 the column beside it moves at most
   0.4 * 0.0101 * 5/16 / (11/16 + 0.0101 * 5/16) = 0.0018 towards the other side. The
   smoothing has a floor that does not depend on the code: the unweighted 5 x 5 kernel leaves
   sqrt(sum w^2) = 0.273 of white noise's std, no weighting goes below it (0.25 with the
   estimate's scatter). */
static void t_faceted(void)
{
    const uint32_t W = 48, H = 36;
    size_t n = (size_t)W * H, i;
    img a;
    float *out = (float *)malloc(n * 12u);
    uint32_t x, y, s = 7u;
    int mode;
    img_alloc(&a, W, H);
    for (mode = 0; mode < 3; ++mode) {
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 24.0f, 18.0f };
        double si = 0.0, so = 0.0, worst = 0.0, col[2] = { 0.0, 0.0 };
        size_t cnt = 0;
        int ok, k;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                double t = x >= W / 2 ? (mode == 2 ? 0.5236 : 0.7854) : 0.0, u = 0.0;
                float v = mode == 0 ? 0.5f : (x >= W / 2 ? 0.7f : 0.3f);
                i = (size_t)y * W + x;
                s = s * 1664525u + 1013904223u;
                for (k = 0; k < 3; ++k) {
                    a.rgb[3 * i + (size_t)k] = v + (mode ? 0.0f : 0.3f) * ((float)(s >> 8) / 16777216.0f - 0.5f);
                    a.alb[3 * i + (size_t)k] = 0.5f;
                }
                if (mode == 0) { /* tilts uniform in +-6 degrees about two axes */
                    s = s * 1664525u + 1013904223u;
                    t = 0.2094 * ((double)(s >> 8) / 16777216.0 - 0.5);
                    s = s * 1664525u + 1013904223u;
                    u = 0.2094 * ((double)(s >> 8) / 16777216.0 - 0.5);
                }
                a.nrm[3 * i] = (float)(sin(t) * cos(u)); a.nrm[3 * i + 1] = (float)sin(u);
                a.nrm[3 * i + 2] = (float)(cos(t) * cos(u));
                a.dep[i] = 2.0f;
                a.spp[i] = 16.0f;
                a.var[i] = 0.0075f; /* the uniform noise's: 0.3^2 / 12 */
            }
        dc.width = W; dc.height = H; dc.no_temporal = 1; dc.spp_ref = 16.0f; dc.levels = 1;
        ok = dn_once(&dc, &a, g, out, NULL);
        for (y = 4; y < H - 4u; ++y)
            for (x = 4; x < W - 4u; ++x) {
                i = (size_t)y * W + x;
                if (mode == 0) {
                    double d0 = (double)a.rgb[3 * i] - 0.5, d1 = (double)out[3 * i] - 0.5;
                    si += d0 * d0; so += d1 * d1; cnt++;
                } else if (x == W / 2 - 1u || x == W / 2) {
                    col[x == W / 2] += (double)out[3 * i] / (double)(H - 8u);
                }
            }
        worst = fabs(col[0] - 0.3) > fabs(col[1] - 0.7) ? fabs(col[0] - 0.3) : fabs(col[1] - 0.7);
        if (mode == 0)
            check(ok && so <= 0.36 * 0.36 * si && so >= 0.25 * 0.25 * si, "dn_default_faceted_smoothed",
                  "output noise std / input %g (want in [0.25, 0.36]; ok %d)", sqrt(so / si), ok);
        else
            check(ok && worst <= 0.002, mode == 1 ? "dn_default_crease45_kept" : "dn_default_crease30_kept",
                  "|mean of a column beside the crease - its side's value| %g (want <= 0.002; ok %d)", worst, ok);
    }
    free(out);
    img_free(&a);
}

/* skip_noise needs evidence: one sample per pixel on sparse light (every 4th pixel of every 4th
   row lit, the rest black, a variance guide of 0) leaves black 3 x 3 windows whose variance
   estimate is 0 though the pixel may just have missed the light; from 1 sample that is no
   reason to skip the pixel (it is filtered towards the lit ones), from 16 it is (untouched) */
static void t_skip_evidence(void)
{
    const uint32_t W = 32, H = 32;
    size_t n = (size_t)W * H, i;
    img a;
    float *out = (float *)malloc(n * 12u);
    int spp16;
    img_alloc(&a, W, H);
    for (spp16 = 0; spp16 < 2; ++spp16) {
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 16.0f, 16.0f };
        double sum = 0.0;
        uint32_t x, y, cnt = 0;
        int ok, k;
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                i = (size_t)y * W + x;
                for (k = 0; k < 3; ++k)
                    a.rgb[3 * i + (size_t)k] = (x % 4u == 0u && y % 4u == 0u) ? 1.0f : 0.0f;
            }
        flat_guides(&a, spp16 ? 16.0f : 1.0f, 0.0f);
        dc.width = W; dc.height = H; dc.no_temporal = 1; dc.spp_ref = a.spp[0];
        dc.phi_lum = 1000.0f; /* a weak luminance stop: black pixels blend with lit ones */
        ok = dn_once(&dc, &a, g, out, NULL);
        for (y = 8; y < 24; ++y)
            for (x = 8; x < 24; ++x)
                if (x % 4u == 2u && y % 4u == 2u) { /* black, its 3 x 3 window black */
                    i = (size_t)y * W + x;
                    sum += (double)out[3 * i] + (double)out[3 * i + 1] + (double)out[3 * i + 2];
                    cnt++;
                }
        sum /= (double)(3u * cnt);
        if (spp16)
            check(ok && sum == 0.0, "skip_noise_var0_from_16_samples_untouched", "mean %g (ok %d)", sum, ok);
        else
            check(ok && sum > 1e-3, "skip_noise_var0_from_1_sample_filtered", "mean %g (ok %d)", sum, ok);
    }
    free(out);
    img_free(&a);
}

/* The SSE2 a-trous pass (4 pixels of a row at once, fovpt__dn_px4) against the scalar pass
   (fovpt__dn_px, the reference): the same float operations in the same order lane by lane,
   so every output float must be bit-identical (the bound: 0; the builds here do not contract
   to FMA). Every pass of a 5-level frame, for phi_normal 32 (the -ln c series, c < 3/4 by
   the integer power), 128 and 200.5 (series, far taps dropped), 8 (integer power alone) and
   3.5 (powf: the scalar pass alone, trivially equal), with and without the albedo guide, on
   random images (normals up to 90 degrees apart, misses, spp and var mixed so lanes of a
   group differ in radius, in being filtered and in hitting) and on the images the other
   checks use (the kernel reference's regions, the faceted terrain, the sky/wall frame).
   Elsewhere (no SSE2, FOVPT_NO_SIMD) both calls take the scalar pass. Checked to fail when
   one lane is wrong: a tap read one pixel over in one lane or at one offset, one lane's
   kernel weight at one offset times 1.0001, one lane's luminance, series, integer power,
   albedo or depth slope perturbed, a passed-through lane not copied, the far drop left out. */
static void simd_img(img *a, int kind, uint32_t seed)
{
    uint32_t x, y, k, s = seed, W = a->w, H = a->h;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            double t, u;
            s = s * 1664525u + 1013904223u;
            for (k = 0; k < 3; ++k) {
                s = s * 1664525u + 1013904223u;
                a->rgb[3 * i + k] = (kind == 1 ? (x * 3u < W ? 0.3f : 0.6f) : 0.0f) + ((float)(s >> 8) / 16777216.0f) * (kind == 0 ? 2.0f : 0.3f);
                a->alb[3 * i + k] = kind == 0 ? (float)(s >> 20) / 4096.0f : 0.5f;
            }
            s = s * 1664525u + 1013904223u;
            t = kind == 0 ? 1.5708 * ((double)(s >> 8) / 16777216.0) : kind == 2 ? 0.2094 * ((double)(s >> 8) / 16777216.0 - 0.5) : (x * 3u < 2u * W ? 0.0 : 0.5236);
            s = s * 1664525u + 1013904223u;
            u = kind == 0 ? 0.8 * ((double)(s >> 8) / 16777216.0 - 0.5) : kind == 2 ? 0.2094 * ((double)(s >> 8) / 16777216.0 - 0.5) : 0.0;
            a->nrm[3 * i] = (float)(sin(t) * cos(u)); a->nrm[3 * i + 1] = (float)sin(u);
            a->nrm[3 * i + 2] = (float)(cos(t) * cos(u));
            s = s * 1664525u + 1013904223u;
            if (kind == 0) a->dep[i] = (s >> 28) == 0u ? 0.0f : 1.0f + (float)(s >> 8) / 16777216.0f * ((s & 1u) ? 3.0f : 0.01f);
            else a->dep[i] = (kind == 1 && x * 3u < W) ? 0.0f : 2.0f + 0.01f * (float)x;
            s = s * 1664525u + 1013904223u;
            a->spp[i] = kind == 0 ? (float)(1u + (s >> 27)) : 2.0f;
            a->var[i] = kind == 0 ? ((s & 3u) ? 0.02f * (float)(s >> 8) / 16777216.0f : -1.0f) : -1.0f;
        }
}
/* Every a-trous pass of dn's frame, scalar (the reference) then SSE2 into the same buffer:
   the floats whose bits differ; *passes, the largest |simd - scalar| (NaN counts) and the
   NaNs of the SSE2 output added up. */
static uint32_t simd_vs_scalar(fovpt_denoise *dn, float *ref, size_t n, uint32_t H, uint32_t *passes,
                               double *worst, uint32_t *nan)
{
    uint32_t p, nd = 0;
    size_t i;
    for (p = 0; p < dn->passes; ++p) {
        float *dst = dn->buf[(p & 1u) ^ 1u];
        fovpt__dn_atrous(dn, p, 0, H, 0);
        memcpy(ref, dst, n * 16u);
        if (dn->sel) /* the SURE selection's centre derivatives too */
            for (i = 0; i < n; ++i) ref[4u * n + i] = dn->sel[FOVPT__DN_SEL * i + 9u];
        fovpt__dn_atrous(dn, p, 0, H, 1);
        for (i = 0; i < n * 4u; ++i) {
            double d = fabs((double)dst[i] - (double)ref[i]);
            if (!(d <= *worst)) *worst = d; /* NaN too */
            nd += memcmp(&dst[i], &ref[i], sizeof(float)) != 0;
            *nan += dst[i] != dst[i];
        }
        for (i = 0; dn->sel && i < n; ++i) {
            const float *f = dn->sel + FOVPT__DN_SEL * i + 9u;
            double d = fabs((double)*f - (double)ref[4u * n + i]);
            if (!(d <= *worst)) *worst = d;
            nd += memcmp(f, &ref[4u * n + i], sizeof(float)) != 0;
        }
        ++*passes;
    }
    return nd;
}
static void t_simd_scalar(void)
{
    const uint32_t W = 101, H = 45;
    static const float pns[5] = { 32.0f, 128.0f, 200.5f, 8.0f, 3.5f };
    size_t n = (size_t)W * H;
    img a;
    float *ref = (float *)malloc(n * 20u); /* 4 floats per pixel, then the derivatives */
    int kind, ip, alb;
    if (!check(ref != NULL, "atrous_simd_equals_scalar: memory", "malloc")) return;
    img_alloc(&a, W, H);
    for (kind = 0; kind < 3; ++kind)
        for (ip = 0; ip < 5; ++ip)
            for (alb = 0; alb < 2; ++alb) {
                fovpt_denoise dn;
                fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
                fovpt_camera cam;
                fov_gaze g = { 30.0f, 20.0f };
                void *dm = NULL;
                uint32_t nd = 0, passes = 0, nnan = 0;
                double worst = 0.0;
                int ok;
                simd_img(&a, kind, 1234u + (uint32_t)(kind * 10 + ip));
                a.g.albedo = alb ? a.alb : NULL;
                dc.width = W; dc.height = H; dc.phi_normal = pns[ip];
                if (kind == 0) dc.spp_ref = 8.0f; /* lanes mixed: 3 x 3 and 5 x 5, some passed through */
                else { dc.fovea_step = 65536.0f; dc.skip_noise = 1e-9f; dc.spp_full = 1e30f; }
                fovpt_camera_init(&cam, W, H);
                ok = dn_make(&dn, &dc, &dm);
                ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
                     fovpt_denoise_temporal_rows(&dn, 0, H) == FOV_OK;
                if (ok) nd = simd_vs_scalar(&dn, ref, n, H, &passes, &worst, &nnan);
                check(ok && passes == 5u && nd == 0u && worst == 0.0,
                      N("atrous_simd_equals_scalar_%s_pn%g%s", kind == 0 ? "random" : kind == 1 ? "regions" : "faceted", (double)pns[ip], alb ? "" : "_noalbedo"),
                      "%u of %u floats differ in bits over %u passes, max |simd - scalar| %g (want 0; ok %d)", nd, (unsigned)(n * 4u) * passes, passes, worst, ok);
                free(dm);
            }
    a.g.albedo = a.alb;
    free(ref);
    img_free(&a);
}

/* The same comparison at widths that are not multiples of 4 (13, 30: the border columns and
   a row's last width % 4 pixels) and on an image whose every 7th pixel is 1e20 (the temporal
   variance overflows to inf: a lane whose tap the scalar pass skips must add nothing, not
   0 times inf). Bit-identical again, NaNs included (both paths use the same SSE arithmetic). */
static void t_simd_scalar_edge(void)
{
    static const uint32_t ws[2] = { 13u, 30u };
    static const float pns[2] = { 32.0f, 8.0f };
    uint32_t iw;
    int big, ip;
    for (iw = 0; iw < 2; ++iw)
        for (big = 0; big < 2; ++big)
            for (ip = 0; ip < 2; ++ip) {
                const uint32_t W = ws[iw], H = 11;
                size_t n = (size_t)W * H, i;
                img a;
                float *ref = (float *)malloc(n * 20u);
                fovpt_denoise dn;
                fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
                fovpt_camera cam;
                fov_gaze g = { 6.0f, 5.0f };
                void *dm = NULL;
                uint32_t nd = 0, passes = 0, nan = 0;
                int ok = ref != NULL;
                img_alloc(&a, W, H);
                simd_img(&a, 0, 77u + iw * 5u + (uint32_t)(big * 2 + ip));
                if (big)
                    for (i = 0; i < n; i += 7u) a.rgb[3 * i] = a.rgb[3 * i + 1] = 1e20f;
                a.g.albedo = a.alb;
                dc.width = W; dc.height = H; dc.phi_normal = pns[ip]; dc.spp_ref = 8.0f;
                fovpt_camera_init(&cam, W, H);
                ok = ok && dn_make(&dn, &dc, &dm);
                ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
                     fovpt_denoise_temporal_rows(&dn, 0, H) == FOV_OK;
                double worst = 0.0;
                if (ok) nd = simd_vs_scalar(&dn, ref, n, H, &passes, &worst, &nan);
                check(ok && passes > 0u && nd == 0u,
                      N("atrous_simd_equals_scalar_w%u%s_pn%g", W, big ? "_1e20" : "", (double)pns[ip]),
                      "%u floats differ in bits over %u passes (%u NaN in the SIMD output; ok %d)", nd, passes, nan, ok);
                if (big) { /* the public run on the same input: a finite image (no NaN, no inf) */
                    float *o3 = (float *)malloc(n * 3u * sizeof(float));
                    fovpt_output out;
                    uint32_t badv = 0;
                    fovpt_output_init(&out);
                    out.rgb = o3;
                    ok = o3 && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
                         fovpt_denoise_run(&dn, &out) == FOV_OK;
                    for (i = 0; ok && i < n * 3u; ++i) badv += !(o3[i] >= 0.0f && o3[i] <= FLT_MAX);
                    check(ok && badv == 0u, N("denoise_run_1e20_finite_w%u_pn%g", W, (double)pns[ip]),
                          "%u of %u values NaN, infinite or negative (ok %d)", badv, (unsigned)(n * 3u), ok);
                    free(o3);
                }
                free(dm);
                free(ref);
                img_free(&a);
            }
}

/* a pass after the first leaves a pixel as it is where the running estimate's noise (its
   variance, as display codes) is below skip_noise / 8: a grey image whose input noise is
   0.5 / 64 codes^2 (above (skip_noise / 8)^2, from 1 sample: the temporal skip does not
   apply) is quiet after pass 0, so 5 levels give the image of 1 level; with 100x the variance
   pass 1 and on filter */
static void t_quiet(void)
{
    const uint32_t W = 40, H = 30;
    size_t n = (size_t)W * H, i;
    img a;
    float *o1 = (float *)malloc(n * 12u), *o5 = (float *)malloc(n * 12u);
    int loud;
    img_alloc(&a, W, H);
    for (loud = 0; loud < 2; ++loud) {
        fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
        fov_gaze g = { 20.0f, 15.0f };
        float amp = loud ? 0.0085f : 0.00085f; /* uniform: var amp^2 / 3 */
        uint32_t x, y, s = 99u, diff = 0, cnt = 0;
        int ok;
        flat_guides(&a, 1.0f, amp * amp / 3.0f);
        for (i = 0; i < n; ++i) {
            float v;
            s = s * 1664525u + 1013904223u;
            v = 0.5f + amp * (2.0f * (float)(s >> 8) / 16777216.0f - 1.0f);
            a.rgb[3 * i] = a.rgb[3 * i + 1] = a.rgb[3 * i + 2] = v;
        }
        dc.width = W; dc.height = H; dc.no_temporal = 1;
        dc.fovea_step = 65536.0f; dc.spp_full = 1e30f; /* every pass on at every pixel */
        dc.levels = 1;
        ok = dn_once(&dc, &a, g, o1, NULL);
        dc.levels = 5;
        ok = ok && dn_once(&dc, &a, g, o5, NULL);
        for (y = 2; y + 2u < H; ++y) /* the border's fewer taps may leave it louder */
            for (x = 2; x + 2u < W; ++x) {
                i = (size_t)y * W + x;
                diff += memcmp(o1 + 3 * i, o5 + 3 * i, 12u) != 0;
                cnt++;
            }
        if (loud)
            check(ok && diff > cnt / 2u, "quiet_loud_filtered_by_later_passes",
                  "%u of %u pixels differ between 1 and 5 levels (ok %d)", diff, cnt, ok);
        else
            check(ok && diff == 0u, "quiet_after_pass0_later_passes_leave_it",
                  "%u of %u pixels differ between 1 and 5 levels (want 0; ok %d)", diff, cnt, ok);
    }
    free(o1);
    free(o5);
    img_free(&a);
}

/* ---- the SURE selection (Li, Wu, Chuang 2012) ---------------------------------------------- */
/* a flat wall (depth 1, normal +z, albedo 0.5), every pixel with spp 32 */
static void sure_img(img *a, uint32_t seed, float amp)
{
    uint32_t x, y, k, s = seed;
    flat_guides(a, 32.0f, amp * amp / 3.0f);
    for (y = 0; y < a->h; ++y)
        for (x = 0; x < a->w; ++x) {
            size_t i = (size_t)y * a->w + x;
            float n;
            s = s * 1664525u + 1013904223u;
            n = amp * (2.0f * (float)(s >> 8) / 16777216.0f - 1.0f); /* uniform: var amp^2 / 3 */
            for (k = 0; k < 3; ++k) a->rgb[3 * i + k] = 0.5f + n;
        }
}

/* A constant image with a known (nonzero) variance and 32 spp stays constant with the
   selection on (every candidate is the constant). */
static void t_sure_constant(void)
{
    const uint32_t W = 40, H = 30;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    fov_gaze g = { 20.0f, 15.0f };
    img a;
    float *out = (float *)malloc((size_t)W * H * 12u);
    size_t i;
    double worst = 0.0;
    int ok;
    img_alloc(&a, W, H);
    flat_guides(&a, 32.0f, 0.01f);
    for (i = 0; i < (size_t)W * H * 3u; ++i) a.rgb[i] = 0.25f;
    dc.width = W; dc.height = H;
    ok = out && dn_once(&dc, &a, g, out, NULL);
    for (i = 0; ok && i < (size_t)W * H * 3u; ++i) worst = fmax(worst, fabs((double)out[i] - 0.25));
    check(ok && worst <= 1e-6, "sure_constant_stays_constant", "worst deviation %g (ok %d)", worst, ok);
    free(out);
    img_free(&a);
}

/* The analytic two-region image: the left half an exact texture (stripes 0.2 / 0.4 two
   pixels wide, var 1e-8 from 32 samples: exact to 1e-4), the right half 0.6 plus uniform
   noise of known variance (the guide's var). With phi_lum 1e6 (the luminance stop nearly
   off) the a-trous passes blur the stripes (checked with cfg.no_sure); the selection must keep
   the exact input there (its SURE is the var, every pass's about the squared change) and take
   a filtered value on the noisy half (>= 90 % of its pixels changed, the error against the
   truth below 0.1x the input's). Pixels within two windows of the boundary are not counted. */
static void t_sure_two_region(void)
{
    const uint32_t W = 64, H = 32;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    fov_gaze g = { 32.0f, 16.0f };
    img a;
    float *out = (float *)malloc((size_t)W * H * 12u), *off = (float *)malloc((size_t)W * H * 12u);
    uint32_t x, y, k, s = 99u, nl = 0, keep = 0, blur_off = 0, nr = 0, same = 0;
    double ein = 0.0, eout = 0.0;
    int ok, m = 2 * 4 + 2; /* two windows (sure_radius 4) and a pixel */
    img_alloc(&a, W, H);
    flat_guides(&a, 32.0f, 0.0f);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            float n;
            s = s * 1664525u + 1013904223u;
            n = 0.2f * (2.0f * (float)(s >> 8) / 16777216.0f - 1.0f);
            for (k = 0; k < 3; ++k) a.rgb[3 * i + k] = x < W / 2u ? ((x / 2u) % 2u ? 0.4f : 0.2f) : 0.6f + n;
            a.var[i] = x < W / 2u ? 1e-8f : 0.04f / 3.0f;
        }
    dc.width = W; dc.height = H; dc.phi_lum = 1e6f; dc.skip_noise = 1e-9f;
    dc.fovea_step = 64.0f;
    ok = out && off && dn_once(&dc, &a, g, out, NULL);
    dc.no_sure = 1;
    ok = ok && dn_once(&dc, &a, g, off, NULL);
    for (y = 0; ok && y < H; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            if ((int)x < (int)(W / 2u) - m) {
                nl++;
                keep += memcmp(out + 3 * i, a.rgb + 3 * i, 12u) == 0;
                blur_off += fabsf(off[3 * i] - a.rgb[3 * i]) > 0.01f;
            } else if ((int)x >= (int)(W / 2u) + m) {
                double d;
                nr++;
                same += memcmp(out + 3 * i, a.rgb + 3 * i, 12u) != 0;
                d = (double)a.rgb[3 * i] - 0.6; ein += d * d;
                d = (double)out[3 * i] - 0.6; eout += d * d;
            }
        }
    check(ok && nl > 100u && keep == nl, "sure_keeps_exact_input",
          "%u of %u exact pixels kept bit for bit (ok %d)", keep, nl, ok);
    check(ok && blur_off * 2u > nl, "sure_two_region_filter_blurs_without",
          "without the selection %u of %u exact pixels moved by > 0.01 (want most: else the "
          "test shows nothing)", blur_off, nl);
    check(ok && nr > 100u && same * 10u >= nr * 9u && eout < 0.1 * ein, "sure_filters_noisy_region",
          "%u of %u noisy pixels take a filtered value; MSE %g -> %g (want < 0.1x)", same, nr,
          ein / (nr ? nr : 1u), eout / (nr ? nr : 1u));
    free(out); free(off);
    img_free(&a);
}

/* The centre derivative after pass 0 (the centre weight / the sum plus the luminance
   stop's slope; the other weights fixed) against a central difference of the pass's output
   luminance in the pixel's own luminance (double), on a noisy wall: within 2 % + 1e-3. And
   the mean raw SURE of each candidate (the input, each pass) against the mean true squared
   error of its luminance, both weighted by the display slope as the selection weighs them
   (double), 96 x 64 pixels: within 0.06 of the mean weighted input variance s2 (SURE is
   unbiased for a weighted mean with fixed weights; its own spread over 6144 pixels is about
   0.02 s2, plus the derivative's centre-path approximation; a derivative of 0 would miss
   the one-pass candidate by about 0.3 s2, of 1 every filtered one by about 2 s2). */
static void t_sure_vs_truth(void)
{
    const uint32_t W = 96, H = 64;
    fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
    fovpt_camera cam;
    fov_gaze g = { 48.0f, 32.0f };
    fovpt_denoise dn;
    void *dm = NULL;
    img a;
    float *o1 = (float *)malloc((size_t)W * H * 12u), *o2 = (float *)malloc((size_t)W * H * 12u);
    size_t n = (size_t)W * H, i, probe[4];
    double dworst = 0.0, rworst = 0.0, ratio[8] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }, s2 = 0.0;
    uint32_t p, np = 0, j;
    int ok;
    img_alloc(&a, W, H);
    sure_img(&a, 4242u, 0.15f);
    fovpt_camera_init(&cam, W, H);
    dc.width = W; dc.height = H; dc.skip_noise = 1e-9f; dc.spp_full = 1e30f; dc.fovea_step = 16.0f;
    ok = o1 && o2 && dn_make(&dn, &dc, &dm);
    ok = ok && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
         fovpt_denoise_temporal_rows(&dn, 0, H) == FOV_OK;
    for (p = 0; ok && p <= dn.passes; ++p) { /* candidate p: the output of p passes */
        const float *src = dn.buf[p & 1u];
        double sr = 0.0, st = 0.0;
        if (p == 0u)
            for (i = 0; i < n; ++i) s2 += (double)dn.sel[FOVPT__DN_SEL * i + 4u] / (double)n;
        for (i = 0; i < n; ++i) {
            const float *sp = dn.sel + FOVPT__DN_SEL * i;
            double l = 0.2126 * (double)src[4 * i] + 0.7152 * (double)src[4 * i + 1] + 0.0722 * (double)src[4 * i + 2];
            double w = fmin(166.9264, 0.25 / fmax((double)sp[6], 1e-30));
            sr += (double)sp[4 + (p & 1u)];
            st += (l - 0.5) * (l - 0.5) * w;
        }
        ratio[np++] = (sr - st) / (double)n / s2;
        if (!(fabs(ratio[np - 1u]) <= rworst)) rworst = fabs(ratio[np - 1u]);
        if (p < dn.passes) ok = fovpt_denoise_atrous_rows(&dn, p, 0, H) == FOV_OK;
    }
    check(ok && np == 6u && s2 > 0.0 && rworst < 0.06, "sure_mean_vs_true_mse",
          "(SURE - true error) / s2 per candidate %.3f %.3f %.3f %.3f %.3f %.3f (want within 0.06; ok %d, %u)",
          ratio[0], ratio[1], ratio[2], ratio[3], ratio[4], ratio[5], ok, np);
    free(dm);
    /* the derivative of one pass */
    dc.levels = 1;
    probe[0] = 5u * W + 7u; probe[1] = 20u * W + 24u; probe[2] = 53u * W + 80u; probe[3] = 11u * W + 60u;
    for (j = 0; ok && j < 4u; ++j) {
        size_t q = probe[j];
        double dfr, fd, l1, l2;
        float save[3];
        int k;
        fovpt_denoise_cfg d0 = dc;
        ok = dn_make(&dn, &d0, &dm) && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
             fovpt_denoise_temporal_rows(&dn, 0, H) == FOV_OK && fovpt_denoise_atrous_rows(&dn, 0, 0, H) == FOV_OK;
        dfr = ok ? (double)dn.sel[FOVPT__DN_SEL * q + 9u] : 0.0;
        free(dm);
        d0.no_sure = 1;
        for (k = 0; k < 3; ++k) save[k] = a.rgb[3 * q + (size_t)k];
        for (k = 0; k < 3; ++k) a.rgb[3 * q + (size_t)k] = save[k] + 1e-3f;
        ok = ok && dn_once(&d0, &a, g, o1, NULL);
        for (k = 0; k < 3; ++k) a.rgb[3 * q + (size_t)k] = save[k] - 1e-3f;
        ok = ok && dn_once(&d0, &a, g, o2, NULL);
        for (k = 0; k < 3; ++k) a.rgb[3 * q + (size_t)k] = save[k];
        l1 = 0.2126 * (double)o1[3 * q] + 0.7152 * (double)o1[3 * q + 1] + 0.0722 * (double)o1[3 * q + 2];
        l2 = 0.2126 * (double)o2[3 * q] + 0.7152 * (double)o2[3 * q + 1] + 0.0722 * (double)o2[3 * q + 2];
        fd = (l1 - l2) / ((double)(save[0] + 1e-3f) - (double)(save[0] - 1e-3f));
        if (!(fabs(fd - dfr) <= 0.02 * fabs(fd) + 1e-3)) dworst = fmax(dworst, fabs(fd - dfr) + 1.0);
        if (j == 0u && !(dfr > 0.0 && dfr < 1.0)) dworst = 99.0;
    }
    check(ok && dworst == 0.0, "sure_derivative_vs_difference",
          "the pass's centre derivative differs from the central difference (worst flag %g; ok %d)", dworst, ok);
    free(o1); free(o2);
    img_free(&a);
}

/* The depth guide is the mean hit distance even where the distances sum beyond FLT_MAX: a
   camera 2.5e38 below a floor plane, looking up, hits it at t in [2.5e38, 2.9e38]; four
   samples per pixel summed to inf before the fix (fuzz finding F1 of session 18,
   tests/fuzz/regress/fovpt_dn/F1_depth_sum_overflow.bin) */
static void t_depth_far(void)
{
    fovpt_material m;
    fovpt_shape sh;
    fovpt_scene_desc d;
    fovpt_scene s;
    fovpt_camera cam;
    fovpt_config c = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output o;
    fov_gaze g = { 2.0f, 2.0f };
    const float p0[3] = { 0.0f, 0.0f, 0.0f }, n0[3] = { 0.0f, 1.0f, 0.0f };
    size_t sb = 0, cb = 0, i, bad = 0, badn = 0;
    void *sm = NULL, *cm = NULL;
    img a;
    int ok;
    fovpt_material_init(&m);
    fovpt_shape_plane(&sh, p0, n0, 0);
    fovpt_scene_desc_init(&d);
    d.shapes = &sh; d.num_shapes = 1; d.materials = &m; d.num_materials = 1;
    fovpt_camera_init(&cam, 4, 4);
    cam.pos[1] = -2.5e38f;
    cam.up[0] = 0.0f; cam.up[1] = 0.0f; cam.up[2] = 1.0f;
    cam.fov_y_deg = 40.0f;
    c.spp = 4;
    img_alloc(&a, 4, 4);
    ok = fovpt_scene_size(&d, &sb) == FOV_OK && (sm = malloc(sb)) != NULL &&
         fovpt_scene_build(&s, &d, sm, sb) == FOV_OK && fovpt_memory_size(&c, &cam, &cb) == FOV_OK &&
         (cm = malloc(cb)) != NULL && fovpt_init(&ctx, &c, &s, &cam, g, cm, cb) == FOV_OK;
    fovpt_output_init(&o);
    o.rgb = a.rgb;
    ok = ok && fovpt_render_guide(&ctx, 0, &o, &a.g, NULL) == FOV_OK;
    for (i = 0; ok && i < 16u; ++i) {
        bad += !(a.dep[i] >= 2.5e38f && a.dep[i] <= 3.0e38f);
        badn += !(a.nrm[3 * i] == 0.0f && a.nrm[3 * i + 1] == -1.0f && a.nrm[3 * i + 2] == 0.0f);
    }
    check(ok && bad == 0 && badn == 0, "guide_depth_mean_near_flt_max",
          "ok %d, %zu of 16 depths outside [2.5e38, 3e38] (pixel 0: %g), %zu normals not (0, -1, 0)", ok, bad,
          (double)a.dep[0], badn);
    img_free(&a);
    free(cm);
    free(sm);
}

/* A caller's normal guide that is not unit: one pixel's normal (0, 0, 1e20) or (0, 0, inf)
   among (0.6, 0, 0.8) gives dots c of 8e19 or inf, and with phi_normal below 32 (the exact
   power: 16 by squaring, 31.13 by powf) c^phi_normal = inf weights made NaN pixels before the
   fix (fuzz finding F2 of session 18, tests/fuzz/regress/fovpt_dn/F2_normal_inf_nan.bin). Now
   a normal longer than unit is normalised, a non-finite one reads as (0, 0, 0): the image is
   finite and >= 0 */
static void t_normal_hostile(void)
{
    static const float pns[2] = { 16.0f, 31.13f };
    const uint32_t W = 12, H = 9;
    size_t n = (size_t)W * H, i;
    int ip, kind;
    for (ip = 0; ip < 2; ++ip)
        for (kind = 0; kind < 2; ++kind) {
            fovpt_denoise dn;
            fovpt_denoise_cfg dc = fovpt_denoise_cfg_default();
            fovpt_camera cam;
            fovpt_output out;
            fov_gaze g = { 6.0f, 4.0f };
            void *dm = NULL;
            img a;
            float *o3 = (float *)malloc(n * 3u * sizeof(float));
            uint32_t bad = 0, st = 12345u;
            int ok;
            img_alloc(&a, W, H);
            for (i = 0; i < n; ++i) {
                st = st * 1664525u + 1013904223u;
                a.rgb[3 * i] = a.rgb[3 * i + 1] = a.rgb[3 * i + 2] = 0.2f + (float)(st >> 8) / 16777216.0f;
                a.alb[3 * i] = a.alb[3 * i + 1] = a.alb[3 * i + 2] = 0.5f;
                a.nrm[3 * i] = 0.6f; a.nrm[3 * i + 1] = 0.0f; a.nrm[3 * i + 2] = 0.8f;
                a.dep[i] = 5.0f; a.spp[i] = 4.0f; a.var[i] = 0.01f;
            }
            a.nrm[3 * (4 * W + 4) + 0] = 0.0f;
            a.nrm[3 * (4 * W + 4) + 2] = kind ? (float)HUGE_VAL : 1e20f;
            dc.width = W; dc.height = H; dc.phi_normal = pns[ip];
            fovpt_camera_init(&cam, W, H);
            fovpt_output_init(&out);
            out.rgb = o3;
            ok = o3 && dn_make(&dn, &dc, &dm) && fovpt_denoise_frame(&dn, &cam, g, a.rgb, 0, &a.g) == FOV_OK &&
                 fovpt_denoise_run(&dn, &out) == FOV_OK;
            for (i = 0; ok && i < n * 3u; ++i) bad += !(o3[i] >= 0.0f && o3[i] <= FLT_MAX);
            check(ok && bad == 0u, N("denoise_normal_%s_finite_pn%g", kind ? "inf" : "1e20", (double)pns[ip]),
                  "%u of %u values NaN, infinite or negative (ok %d)", bad, (unsigned)(n * 3u), ok);
            free(dm);
            free(o3);
            img_free(&a);
        }
}

int main(void)
{
    t_constant();
    t_furnace();
    t_edges();
    t_reproject();
    t_foveation();
    t_errors();
    t_same_image();
    t_depth_far();
    t_normal_hostile();
    t_robust();
    t_var_accum();
    t_two_stride1();
    t_nlog();
    t_kernel_ref();
    t_adaptive();
    t_faceted();
    t_skip_evidence();
    t_quiet();
    t_simd_scalar();
    t_simd_scalar_edge();
    t_sure_constant();
    t_sure_two_region();
    t_sure_vs_truth();
    return fovcheck_summary();
}
