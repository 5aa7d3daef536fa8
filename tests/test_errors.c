/* test_errors.c - errors say what went wrong, in the default build (no FOV_DEBUG).

   For each header, a list of different failures triggered through the public API (bad config
   fields, NULL callbacks, too many lights, call order, bad rows, strides, gaze, camera, ...).
   Each failure must return its documented code and call the logger exactly once with that
   code, level FOV_LOG_ERROR, the header's tag and a message that is not NULL, not empty and
   names the field (a substring written here, independently of the header); the messages of
   the different failures of one header must be pairwise different.
   Built a second time with -DFOV_NO_ERROR_STRINGS (tests/run_all.sh): then the logger still
   gets each code, once, with msg "" (never NULL), and *_result_string returns "". */
#ifdef FOV_DEBUG
#error "test_errors checks the default build: compile it without FOV_DEBUG"
#endif
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOVSDF_IMPLEMENTATION
#define FOVLP_IMPLEMENTATION
#define FOVPT_IMPLEMENTATION
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"

#include "fovcheck.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef FOV_NO_ERROR_STRINGS
#define STRINGS 0
#else
#define STRINGS 1
#endif
#define N fovcheck_name

/* ---- the recording logger --------------------------------------------------------------- */
typedef struct rec {
    int calls;    /* FOV_LOG_ERROR calls */
    int32_t code; /* the last error's code */
    int null_msg; /* a call passed msg == NULL */
    char tag[16];
    char msg[256];
} rec;
static void rec_fn(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                   void *user)
{
    rec *r = (rec *)user;
    (void)line;
    if (level != FOV_LOG_ERROR) return; /* fovlp warns about a clamped gaze: not an error */
    r->calls++;
    r->code = code;
    snprintf(r->tag, sizeof r->tag, "%s", tag ? tag : "(null)");
    if (!msg) r->null_msg = 1;
    snprintf(r->msg, sizeof r->msg, "%s", msg ? msg : "");
}

typedef struct fcase {
    const char *name;  /* what is wrong */
    fov_result want;   /* the documented code */
    const char *field; /* a text the message must contain */
} fcase;

#define MAXCASES 40
static char g_msgs[MAXCASES][256];

/* Runs case k of a header through run(k, lg) and checks the code and the logger call. */
static void check_case(const char *hdr, const fcase *c, int k,
                       fov_result (*run)(int, const fov_logger *))
{
    rec r;
    fov_logger lg;
    fov_result got;
    memset(&r, 0, sizeof r);
    lg.func = rec_fn;
    lg.user = &r;
    got = run(k, &lg);
    check(got == c->want, N("%s/%s: code", hdr, c->name), "returned %d (%s), documented %d (%s)",
          (int)got, fovsdf_result_string(got), (int)c->want, fovsdf_result_string(c->want));
    check(r.calls == 1 && r.code == (int32_t)got && strcmp(r.tag, hdr) == 0,
          N("%s/%s: logged once with the code and tag", hdr, c->name),
          "%d error calls, last code %d, tag \"%s\"", r.calls, (int)r.code, r.tag);
    check(!r.null_msg, N("%s/%s: msg not NULL", hdr, c->name), "the logger got NULL");
#if STRINGS
    check(r.msg[0] != 0 && strstr(r.msg, c->field) != NULL,
          N("%s/%s: message names %s", hdr, c->name, c->field), "message \"%s\"", r.msg);
#else
    check(r.msg[0] == 0, N("%s/%s: message empty (FOV_NO_ERROR_STRINGS)", hdr, c->name),
          "message \"%s\"", r.msg);
#endif
    snprintf(g_msgs[k], sizeof g_msgs[k], "%s", r.msg);
    printf("     %s %d \"%s\"\n", r.tag, (int)r.code, r.msg); /* what a user sees */
}

static void check_header(const char *hdr, const fcase *cs, int n,
                         fov_result (*run)(int, const fov_logger *))
{
    int k, j, dup = 0, d0 = 0, d1 = 0;
    if (n > MAXCASES) n = MAXCASES; /* g_msgs holds MAXCASES messages */
    for (k = 0; k < n; ++k)
        check_case(hdr, &cs[k], k, run);
#if STRINGS
    for (k = 0; k < n; ++k)
        for (j = k + 1; j < n; ++j)
            if (strcmp(g_msgs[k], g_msgs[j]) == 0) {
                if (!dup) {
                    d0 = k;
                    d1 = j;
                }
                ++dup;
            }
    check(n >= 10 && dup == 0, N("%s: the %d messages are pairwise different", hdr, n),
          "%d equal pairs; %s and %s both log \"%s\"", dup, cs[d0].name, cs[d1].name, g_msgs[d0]);
#else
    (void)j;
    (void)dup;
    (void)d0;
    (void)d1;
#endif
}

/* ==== fovsdf ================================================================================ */
static float sphere_sdf(const float p[3], void *user)
{
    (void)user;
    return sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0f;
}
static const fcase sdf_cases[] = {
    {"spp_3", FOV_ERR_INVALID_ARG, "spp"},
    {"omega_2.5", FOV_ERR_INVALID_ARG, "omega"},
    {"eps_nan", FOV_ERR_NOT_FINITE, "eps"},
    {"eps_px_negative", FOV_ERR_INVALID_ARG, "eps_px"},
    {"max_steps_over_cap", FOV_ERR_LIMIT, "max_steps"},
    {"ipr_levels_7", FOV_ERR_INVALID_ARG, "ipr_levels"},
    {"acuity_A_nan", FOV_ERR_NOT_FINITE, "acuity.A"},
    {"display_fov_200", FOV_ERR_INVALID_ARG, "display.fov_y_deg"},
    {"display_pitch_without_distance", FOV_ERR_INVALID_ARG, "distance_mm"},
    {"scene_no_callback", FOV_ERR_NULL, "dist"},
    {"scene_too_many_lights", FOV_ERR_LIMIT, "num_lights"},
    {"scene_lipschitz_negative", FOV_ERR_INVALID_ARG, "lipschitz"},
    {"scene_light_type_99", FOV_ERR_INVALID_ARG, "lights[].type"},
    {"cam_width_0", FOV_ERR_INVALID_ARG, "width"},
    {"cam_fov_190", FOV_ERR_INVALID_ARG, "fov_y_deg"},
    {"cam_target_is_pos", FOV_ERR_DEGENERATE, "target"},
    {"gaze_nan", FOV_ERR_NOT_FINITE, "gaze"},
    {"render_tile_y1_beyond", FOV_ERR_INVALID_ARG, "y1"},
    {"render_tile_x0_above_x1", FOV_ERR_INVALID_ARG, "x0"},
    {"render_tile_output_null", FOV_ERR_NULL, "output"},
    {"render_tile_rgb_stride", FOV_ERR_TOO_SMALL, "stride"},
    {"render_rows_y0_above_y1", FOV_ERR_INVALID_ARG, "y0"},
    {"trace_t_start_negative", FOV_ERR_INVALID_ARG, "t_start"},
    {"trace_rd_not_unit", FOV_ERR_INVALID_ARG, "rd"},
    {"trace_ro_nan", FOV_ERR_NOT_FINITE, "ro"},
    {"camera_ray_px_nan", FOV_ERR_NOT_FINITE, "px"},
    {"shade_point_rgb_null", FOV_ERR_NULL, "rgb"},
    {"program_check_nodes_null", FOV_ERR_NULL, "nodes"},
};
static fov_result sdf_run(int k, const fov_logger *lg)
{
    fovsdf_scene sc;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default(), out;
    fovsdf_ctx ctx;
    fovsdf_output o;
    fovsdf_hit hit;
    fov_gaze gz = {16.0f, 12.0f};
    float ro[3] = {0.0f, 0.0f, -3.0f}, rd[3] = {0.0f, 0.0f, 1.0f}, rgb[96 * 3];
    volatile float zero = 0.0f;
    float nan = zero / zero;
    fovsdf_scene_init(&sc);
    sc.dist = sphere_sdf;
    fovsdf_camera_init(&cam, 32, 24);
    cam.pos[2] = -3.0f;
    cfg.logger = *lg;
    fovsdf_output_init(&o);
    o.rgb = rgb;
    switch (k) {
    case 0: cfg.spp = 3; return fovsdf_config_resolve(&cfg, &out);
    case 1: cfg.omega = 2.5f; return fovsdf_config_resolve(&cfg, &out);
    case 2: cfg.eps = nan; return fovsdf_config_resolve(&cfg, &out);
    case 3: cfg.eps_px = -1.0f; return fovsdf_config_resolve(&cfg, &out);
    case 4: cfg.max_steps = FOVSDF_MAX_STEPS + 1u; return fovsdf_config_resolve(&cfg, &out);
    case 5: cfg.ipr_levels = 7; return fovsdf_config_resolve(&cfg, &out);
    case 6: cfg.acuity.A = nan; return fovsdf_config_resolve(&cfg, &out);
    case 7: cfg.display.fov_y_deg = 200.0f; return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 8:
        cfg.display.pixel_pitch_mm = 0.25f;
        return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 9:
        sc.dist = NULL;
        sc.dist_ex = NULL;
        return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 10:
        sc.num_lights = FOVSDF_MAX_LIGHTS + 1u;
        return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 11: sc.lipschitz = -1.0f; return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 12:
        sc.num_lights = 1;
        sc.lights[0].type = 99;
        return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 13: cam.width = 0; return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 14: cam.fov_y_deg = 190.0f; return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 15:
        cam.target[0] = cam.pos[0];
        cam.target[1] = cam.pos[1];
        cam.target[2] = cam.pos[2];
        return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    case 16: gz.x = nan; return fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
    default: break;
    }
    {
        /* a valid context (its config carries the logger), then a failing call */
        fov_logger none;
        fov_result r;
        none.func = NULL;
        none.user = NULL;
        cfg.logger = none;
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, gz, NULL, 0);
        if (r != FOV_OK) return FOV_OK; /* shows as a wrong code */
        ctx.cfg.logger = *lg;
    }
    switch (k) {
    case 17: return fovsdf_render_tile(&ctx, 0, 0, 4, 25, &o, NULL);
    case 18: return fovsdf_render_tile(&ctx, 5, 0, 4, 4, &o, NULL);
    case 19: return fovsdf_render_tile(&ctx, 0, 0, 4, 4, NULL, NULL);
    case 20: o.rgb_stride = 3; return fovsdf_render_tile(&ctx, 0, 0, 4, 4, &o, NULL);
    case 21: return fovsdf_render_rows(&ctx, 3, 2, &o, NULL);
    case 22: return fovsdf_trace(&ctx, ro, rd, -1.0f, &hit, NULL);
    case 23: rd[2] = 2.0f; return fovsdf_trace(&ctx, ro, rd, 0.0f, &hit, NULL);
    case 24: ro[1] = nan; return fovsdf_trace(&ctx, ro, rd, 0.0f, &hit, NULL);
    case 25: return fovsdf_camera_ray(&ctx, nan, 1.0f, ro, rd);
    case 26: return fovsdf_shade_point(&ctx, 1.0f, 1.0f, NULL, NULL, NULL, NULL);
    case 27: return fovsdf_program_check(NULL, 1, 0, lg);
    default: return FOV_OK;
    }
}

/* ==== fovlp ================================================================================= */
static void lp_shade(float x, float y, float c[3], float *depth, void *user)
{
    (void)user;
    c[0] = x;
    c[1] = y;
    c[2] = 0.0f;
    if (depth) *depth = 1.0f;
}
static const fcase lp_cases[] = {
    {"width_0", FOV_ERR_INVALID_ARG, "width"},
    {"sigma_nan", FOV_ERR_NOT_FINITE, "sigma"},
    {"alpha_20", FOV_ERR_INVALID_ARG, "alpha"},
    {"norm_99", FOV_ERR_INVALID_ARG, "norm"},
    {"blend_end_below_start", FOV_ERR_INVALID_ARG, "blend_end"},
    {"taa_phases_300", FOV_ERR_INVALID_ARG, "taa.phases"},
    {"taa_jitter_moving_2", FOV_ERR_INVALID_ARG, "jitter_moving"},
    {"taa_reset_deg_negative", FOV_ERR_INVALID_ARG, "reset_deg"},
    {"display_pitch_without_distance", FOV_ERR_INVALID_ARG, "distance_mm"},
    {"init_mem_null", FOV_ERR_NULL, "mem"},
    {"init_mem_size_small", FOV_ERR_TOO_SMALL, "mem_size"},
    {"jitter_ou_null", FOV_ERR_NULL, "ou"},
    {"screen_to_lp_before_begin_frame", FOV_ERR_INVALID_ARG, "screen_to_lp"},
    {"shade_rows_before_begin_frame", FOV_ERR_INVALID_ARG, "shade_rows"},
    {"reconstruct_before_begin_frame", FOV_ERR_INVALID_ARG, "reconstruct"},
    {"taa_rows_before_begin_frame", FOV_ERR_INVALID_ARG, "taa_rows"},
    {"begin_frame_gaze_nan", FOV_ERR_NOT_FINITE, "gaze"},
    {"shade_rows_r1_beyond", FOV_ERR_INVALID_ARG, "r1"},
    {"shade_rows_fn_null", FOV_ERR_NULL, "fn"},
    {"reconstruct_stride_small", FOV_ERR_INVALID_ARG, "stride"},
    {"reconstruct_y1_beyond", FOV_ERR_INVALID_ARG, "y1"},
    {"blend_in_is_out", FOV_ERR_INVALID_ARG, "alias"},
    {"taa_rows_taa_disabled", FOV_ERR_INVALID_ARG, "taa.enable"},
    {"samples_cap_small", FOV_ERR_TOO_SMALL, "cap"},
};
static fov_result lp_run(int k, const fov_logger *lg)
{
    static float smp_rgb[40000 * 3], img[64 * 48 * 3];
    static unsigned char mem[1 << 16];
    static fovlp_sample smp[4];
    fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 64, 48), out;
    fovlp_ctx ctx;
    fovlp_taa_io io;
    fov_gaze gz = {32.0f, 24.0f};
    size_t bytes = 0, cnt;
    float u, v;
    volatile float zero = 0.0f;
    float nan = zero / zero;
    fov_result r;
    cfg.logger = *lg;
    memset(&io, 0, sizeof io);
    switch (k) {
    case 0: cfg.width = 0; return fovlp_config_resolve(&cfg, &out);
    case 1: cfg.sigma = nan; return fovlp_config_resolve(&cfg, &out);
    case 2: cfg.alpha = 20.0f; return fovlp_config_resolve(&cfg, &out);
    case 3: cfg.norm = 99; return fovlp_config_resolve(&cfg, &out);
    case 4:
        cfg.blend_start = 0.6f;
        cfg.blend_end = 0.5f;
        return fovlp_config_resolve(&cfg, &out);
    case 5: cfg.taa.phases = 300; return fovlp_config_resolve(&cfg, &out);
    case 6: cfg.taa.jitter_moving = 2; return fovlp_config_resolve(&cfg, &out);
    case 7: cfg.taa.reset_deg = -1.0f; return fovlp_config_resolve(&cfg, &out);
    case 8: cfg.display.pixel_pitch_mm = 0.25f; return fovlp_config_resolve(&cfg, &out);
    case 9: return fovlp_init(&ctx, &cfg, NULL, 0);
    case 10: return fovlp_init(&ctx, &cfg, mem, 8);
    case 11: return fovlp_jitter(&cfg, 0, NULL, &v);
    default: break;
    }
    {
        fov_logger none;
        none.func = NULL;
        none.user = NULL;
        cfg.logger = none;
        if (k == 15 || k == 22) cfg.taa.enable = k == 15 ? 1u : 0u;
        if (fovlp_memory_size(&cfg, &bytes) != FOV_OK || bytes > sizeof mem) return FOV_OK;
        if (fovlp_init(&ctx, &cfg, mem, sizeof mem) != FOV_OK) return FOV_OK;
        if (ctx.geo.samples > 40000) return FOV_OK;
        ctx.cfg.logger = *lg;
    }
    switch (k) {
    case 12: return fovlp_screen_to_lp(&ctx, 1.0f, 1.0f, &u, &v);
    case 13: return fovlp_shade_rows(&ctx, 0, 1, lp_shade, NULL, smp_rgb, NULL, NULL);
    case 14: return fovlp_reconstruct_rows(&ctx, smp_rgb, NULL, 0, 48, img, 0, NULL);
    case 15: return fovlp_taa_rows(&ctx, &io, 0, 48, NULL);
    case 16: gz.x = nan; return fovlp_begin_frame(&ctx, gz, NULL);
    default: break;
    }
    ctx.cfg.logger.func = NULL;
    r = fovlp_begin_frame(&ctx, gz, NULL);
    ctx.cfg.logger = *lg;
    if (r != FOV_OK) return FOV_OK;
    switch (k) {
    case 17:
        return fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx) + 1u, lp_shade, NULL, smp_rgb, NULL,
                                NULL);
    case 18: return fovlp_shade_rows(&ctx, 0, 1, NULL, NULL, smp_rgb, NULL, NULL);
    case 19: return fovlp_reconstruct_rows(&ctx, smp_rgb, NULL, 0, 48, img, 10, NULL);
    case 20: return fovlp_reconstruct_rows(&ctx, smp_rgb, NULL, 0, 49, img, 0, NULL);
    case 21: return fovlp_blend_rows(&ctx, img, 0, 48, img);
    case 22:
        io.cur_rgb = img;
        io.out_rgb = smp_rgb;
        io.out_age = mem;
        return fovlp_taa_rows(&ctx, &io, 0, 48, NULL);
    case 23: return fovlp_samples(&ctx, 0, fovlp_sample_rows(&ctx), smp, 4, &cnt);
    default: return FOV_OK;
    }
}

/* ==== fovpt ================================================================================= */
static const fcase pt_cases[] = {
    {"method_99", FOV_ERR_INVALID_ARG, "method"},
    {"spp_over_cap", FOV_ERR_LIMIT, "spp"},
    {"layers_count_1", FOV_ERR_INVALID_ARG, "layers.count"},
    {"layer_2_stride_0", FOV_ERR_INVALID_ARG, "layer[2].stride"},
    {"zones_lanczos_5", FOV_ERR_INVALID_ARG, "lanczos_a"},
    {"temporal_n_tpi_9", FOV_ERR_INVALID_ARG, "n_tpi"},
    {"selective_tau_negative", FOV_ERR_INVALID_ARG, "selective.tau"},
    {"display_fov_nan", FOV_ERR_NOT_FINITE, "display.fov_y_deg"},
    {"temporal_reuse_with_layers", FOV_ERR_UNSUPPORTED, "temporal"},
    {"scene_no_materials", FOV_ERR_NULL, "materials"},
    {"scene_sphere_radius_negative", FOV_ERR_DEGENERATE, "sphere"},
    {"scene_albedo_2", FOV_ERR_INVALID_ARG, "albedo"},
    {"scene_build_mem_null", FOV_ERR_NULL, "mem"},
    {"init_cam_width_0", FOV_ERR_INVALID_ARG, "width"},
    {"init_gaze_nan", FOV_ERR_NOT_FINITE, "gaze"},
    {"init_scene_not_built", FOV_ERR_INVALID_ARG, "fovpt_scene_build"},
    {"trace_rows_y1_beyond", FOV_ERR_INVALID_ARG, "y1"},
    {"resolve_rows_stride_small", FOV_ERR_INVALID_ARG, "stride"},
    {"set_view_size_differs", FOV_ERR_INVALID_ARG, "differs"},
    {"radiance_dir_zero", FOV_ERR_DEGENERATE, "dir"},
    {"render_out_null", FOV_ERR_NULL, "out"},
    {"robust_2", FOV_ERR_INVALID_ARG, "config.robust"},
    {"robust_over_cap", FOV_ERR_LIMIT, "config.robust"},
    {"shade_points_robust_1", FOV_ERR_INVALID_ARG, "c.robust"},
    {"mirror_nee_2", FOV_ERR_INVALID_ARG, "config.mirror_nee"},
    {"shade_points_mirror_nee_3", FOV_ERR_INVALID_ARG, "c.mirror_nee"},
};
static fov_result pt_run(int k, const fov_logger *lg)
{
    static unsigned char smem[1 << 16], cmem[1 << 20];
    fovpt_material mat[1];
    fovpt_shape sh[1];
    fovpt_scene_desc d;
    fovpt_scene scene;
    fovpt_camera cam;
    fovpt_config cfg = fovpt_config_default(), out;
    fovpt_ctx ctx;
    fovpt_output o;
    fov_gaze gz = {8.0f, 6.0f};
    size_t sb = 0, cb = 0;
    float org[3] = {0.0f, 0.0f, -4.0f}, dir[3] = {0.0f, 0.0f, 0.0f}, rgb[3], img[16 * 12 * 3];
    fovpt_rng rng;
    volatile float zero = 0.0f;
    float nan = zero / zero;
    fov_logger none;
    none.func = NULL;
    none.user = NULL;
    rng.key = 1;
    rng.ctr = 0;
    fovpt_material_init(&mat[0]);
    fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 0);
    fovpt_scene_desc_init(&d);
    d.shapes = sh;
    d.num_shapes = 1;
    d.materials = mat;
    d.num_materials = 1;
    fovpt_camera_init(&cam, 16, 12);
    cam.pos[2] = -4.0f;
    cfg.logger = *lg;
    d.logger = *lg;
    fovpt_output_init(&o);
    o.rgb = img;
    switch (k) {
    case 0: cfg.method = 99; return fovpt_config_resolve(&cfg, &out);
    case 1: cfg.spp = FOVPT_MAX_SPP + 1u; return fovpt_config_resolve(&cfg, &out);
    case 2: cfg.layers.count = 1; return fovpt_config_resolve(&cfg, &out);
    case 3: cfg.layers.layer[2].stride = 0; return fovpt_config_resolve(&cfg, &out);
    case 4: cfg.zones.lanczos_a = 5; return fovpt_config_resolve(&cfg, &out);
    case 5: cfg.temporal.n_tpi = 9; return fovpt_config_resolve(&cfg, &out);
    case 6: cfg.selective.tau[0] = -1.0f; return fovpt_config_resolve(&cfg, &out);
    case 7: cfg.display.fov_y_deg = nan; return fovpt_config_resolve(&cfg, &out);
    case 8:
        cfg.method = FOVPT_METHOD_LAYERS;
        cfg.temporal.reuse = 1;
        return fovpt_memory_size(&cfg, &cam, &cb);
    case 9: d.num_materials = 0; return fovpt_scene_size(&d, &sb);
    case 10: sh[0].r = -1.0f; return fovpt_scene_size(&d, &sb);
    case 11: mat[0].albedo[1] = 2.0f; return fovpt_scene_size(&d, &sb);
    case 12: return fovpt_scene_build(&scene, &d, NULL, 4096);
    case 21: cfg.robust = 2; return fovpt_config_resolve(&cfg, &out);
    case 22: cfg.robust = FOVPT_ROBUST_MAX + 1u; return fovpt_config_resolve(&cfg, &out);
    case 24: cfg.mirror_nee = 2; return fovpt_config_resolve(&cfg, &out);
    default: break;
    }
    d.logger = none;
    if (fovpt_scene_size(&d, &sb) != FOV_OK || sb > sizeof smem) return FOV_OK;
    if (fovpt_scene_build(&scene, &d, smem, sizeof smem) != FOV_OK) return FOV_OK;
    switch (k) {
    case 13: cam.width = 0; return fovpt_init(&ctx, &cfg, &scene, &cam, gz, cmem, sizeof cmem);
    case 14: gz.y = nan; return fovpt_init(&ctx, &cfg, &scene, &cam, gz, cmem, sizeof cmem);
    case 15:
        scene.materials = NULL;
        return fovpt_init(&ctx, &cfg, &scene, &cam, gz, cmem, sizeof cmem);
    case 19: return fovpt_radiance(&scene, &cfg, org, dir, &rng, rgb, NULL);
    case 23: {
        float xy[2] = {4.0f, 4.0f};
        cfg.robust = 1;
        return fovpt_shade_points(&scene, &cfg, &cam, 1, xy, 0, 0, 0, 1, 0.0f, rgb, NULL, NULL);
    }
    case 25: {
        float xy[2] = {4.0f, 4.0f};
        cfg.mirror_nee = 3;
        return fovpt_shade_points(&scene, &cfg, &cam, 1, xy, 0, 0, 0, 1, 0.0f, rgb, NULL, NULL);
    }
    default: break;
    }
    cfg.logger = none;
    if (fovpt_memory_size(&cfg, &cam, &cb) != FOV_OK || cb > sizeof cmem) return FOV_OK;
    if (fovpt_init(&ctx, &cfg, &scene, &cam, gz, cmem, sizeof cmem) != FOV_OK) return FOV_OK;
    ctx.cfg.logger = *lg;
    switch (k) {
    case 16: return fovpt_trace_rows(&ctx, 0, 0, 13, NULL);
    case 17: o.rgb_stride = 5; return fovpt_resolve_rows(&ctx, 0, 12, &o);
    case 18: cam.width = 17; return fovpt_set_view(&ctx, &cam, gz);
    case 20: return fovpt_render(&ctx, 0, NULL, NULL);
    default: return FOV_OK;
    }
}

int main(void)
{
    int nsdf = (int)(sizeof sdf_cases / sizeof sdf_cases[0]);
    int nlp = (int)(sizeof lp_cases / sizeof lp_cases[0]);
    int npt = (int)(sizeof pt_cases / sizeof pt_cases[0]);
    check_header("fovsdf", sdf_cases, nsdf, sdf_run);
    check_header("fovlp", lp_cases, nlp, lp_run);
    check_header("fovpt", pt_cases, npt, pt_run);
    {
        /* every code's string: a text by default, "" under FOV_NO_ERROR_STRINGS, never NULL */
        int r, ok = 1;
        for (r = (int)FOV_ERR_UNSUPPORTED; r <= 0; ++r) {
            const char *a = fovsdf_result_string((fov_result)r),
                       *b = fovlp_result_string((fov_result)r);
            const char *c = fovpt_result_string((fov_result)r);
            if (!a || !b || !c ||
                (STRINGS ? (a[0] == 0 || b[0] == 0 || c[0] == 0) : (a[0] || b[0] || c[0])))
                ok = 0;
        }
        check(ok,
              STRINGS ? "result strings non-empty for every code"
                      : "result strings \"\" (FOV_NO_ERROR_STRINGS)",
              "a result string is NULL or %s", STRINGS ? "empty" : "not empty");
    }
    return fovcheck_summary();
}
