/* fuzz_fovpt_dn.c - libFuzzer harness of fovpt.h's guide buffers, denoiser and
   fovpt_shade_points (conventions: tests/fuzz/fuzz_common.h; the geometry and the renderer
   are fuzz_fovpt.c's).

   From the bytes: a small scene of shapes (a floor, a wall, a sphere, a box, an area light,
   a mirror sphere; materials of every type, albedo in [0, 1], emission up to 1e30), then
   - fovpt_shade_points (sometimes): a resolved config, a camera (sometimes hostile), 0 .. 8
     points with strides 0 .. 4, hostile coordinates, jitter, spp, first, t or no t.
     FOV_OK: rgb finite and >= 0, t finite > 0 or FLT_MAX, and the same bits when the points
     are shaded in two calls (point i's streams are (seed, first + i, k, frame)). An error:
     a documented code, rgb, t and stats untouched ("everything is checked before any
     work"). Canaries after xy, rgb and t.
   - the denoiser over 1 .. 3 frames of 1x1 .. 16x16 pixels: a denoise config (the default,
     fields from the bytes, or the raw struct bytes) through fovpt_denoise_resolve (FOV_OK:
     every field in its documented range) and fovpt_denoise_size (>= 164 / 204 bytes per
     pixel), fovpt_denoise_init (misaligned and short memory rejected with the documented
     codes), then per frame the noisy image and guides from a render (two contexts: one
     by fovpt_trace_rows_guide / refine / resolve in odd row splits, the other by
     fovpt_render_guide or fovpt_render: the same image and guides bit for bit; the guides
     inside their documented ranges) or written here (a smooth synthetic frame), either
     sometimes with hostile pixels (NaN, inf, negative, huge radiance; NaN, zero or huge
     normals; zero, negative, NaN, inf depth; spp 0, negative or huge; var NaN, negative),
     the camera moved between frames (fovpt_set_view; reprojection), sometimes a hostile
     denoise camera or gaze. Two denoisers get the same frames: A by fovpt_denoise_run, B by
     the row-range entry points in random row splits per phase, with rejected calls mixed in
     (a failed fovpt_denoise_frame before the good one; phases out of order: the documented
     FOV_ERR_INVALID_ARG, the output untouched). FOV_OK: A's and B's images equal bit for
     bit (rgb and rgb8), finite and >= 0; stride padding and canaries after every caller
     buffer (images, guides, denoiser memory) intact. Last, sometimes: a frame whose temporal
     phase ran on some rows only is not history (A's next frame = B's after a reset).
   Every buffer has a stride with 0 .. 3 elements of padding (or 0: packed). Each input runs
   in a few ms (ASan). */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "fuzz_common.h"

#define FZ_PAD 0x5Au
#define FZ_MAXD 16u

static int fz_code_ok(fov_result r) { return r <= FOV_OK && r >= FOV_ERR_UNSUPPORTED; }

/* every error message: a documented code and a text (never NULL) */
static void fz_log(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    (void)tag; (void)level; (void)line; (void)user;
    FZ_CHECK(msg != NULL, "logger: msg NULL");
    FZ_CHECK(code < 0 && fz_code_ok((fov_result)code), "logger: code %d", (int)code);
}

/* ---- caller buffers with a row stride, padding and a canary --------------------------- */
typedef struct fz_buf {
    float *p;       /* NULL: not given */
    uint32_t ch;    /* floats per pixel */
    uint32_t stride; /* as passed (0: packed) */
    uint32_t rs;    /* the real row stride, floats */
    uint32_t W, H;
    size_t n;       /* payload bytes */
} fz_buf;

static void fz_buf_make(fz_buf *b, fz_in *in, uint32_t ch, uint32_t W, uint32_t H)
{
    uint32_t pad = fz_pick(in, 4);
    b->ch = ch; b->W = W; b->H = H;
    b->rs = ch * W + pad;
    b->stride = (pad == 0 && (fz_u8(in) & 1u)) ? 0u : b->rs;
    b->n = (size_t)b->rs * H * sizeof(float);
    b->p = (float *)fz_alloc(b->n, FZ_PAD);
}
static void fz_buf_free(fz_buf *b) { free(b->p); b->p = NULL; }
static float *fz_at(const fz_buf *b, uint32_t x, uint32_t y) { return b->p + (size_t)y * b->rs + (size_t)b->ch * x; }
/* padding and canary intact */
static void fz_buf_check(const fz_buf *b, const char *what)
{
    uint32_t y, x;
    if (!b->p) return;
    FZ_CHECK(fz_canary_ok(b->p, b->n), "%s: canary after the buffer overwritten", what);
    for (y = 0; y < b->H; ++y)
        for (x = b->ch * b->W; x < b->rs; ++x) {
            uint8_t q[4];
            memcpy(q, b->p + (size_t)y * b->rs + x, 4);
            FZ_CHECK(q[0] == FZ_PAD && q[1] == FZ_PAD && q[2] == FZ_PAD && q[3] == FZ_PAD,
                     "%s: stride padding written (row %u, element %u)", what, y, x);
        }
}
/* the payloads of two buffers of the same shape equal bit for bit */
static void fz_buf_same(const fz_buf *a, const fz_buf *b, const char *what)
{
    uint32_t y;
    if (!a->p || !b->p) return;
    for (y = 0; y < a->H; ++y)
        FZ_CHECK(memcmp(a->p + (size_t)y * a->rs, b->p + (size_t)y * b->rs, (size_t)a->ch * a->W * sizeof(float)) == 0,
                 "%s: differs in row %u", what, y);
}

/* 8-bit images alike */
typedef struct fz_buf8 {
    uint8_t *p;
    uint32_t stride, rs, W, H;
    size_t n;
} fz_buf8;
static void fz_buf8_make(fz_buf8 *b, fz_in *in, uint32_t W, uint32_t H)
{
    uint32_t pad = fz_pick(in, 5);
    b->W = W; b->H = H;
    b->rs = 3u * W + pad;
    b->stride = (pad == 0 && (fz_u8(in) & 1u)) ? 0u : b->rs;
    b->n = (size_t)b->rs * H;
    b->p = (uint8_t *)fz_alloc(b->n, FZ_PAD);
}
static void fz_buf8_check(const fz_buf8 *b, const char *what)
{
    uint32_t y, x;
    FZ_CHECK(fz_canary_ok(b->p, b->n), "%s: canary after the buffer overwritten", what);
    for (y = 0; y < b->H; ++y)
        for (x = 3u * b->W; x < b->rs; ++x)
            FZ_CHECK(b->p[(size_t)y * b->rs + x] == FZ_PAD, "%s: stride padding written (row %u)", what, y);
}

/* ---- the scene ---------------------------------------------------------------------------- */
#define FZ_NSH 6u
typedef struct fz_world {
    fovpt_material mat[5];
    fovpt_shape sh[FZ_NSH];
    fovpt_scene s;
    void *mem;
    size_t bytes;
} fz_world;

static int fz_world_build(fz_world *w, fz_in *in)
{
    fovpt_scene_desc d;
    uint32_t i, k, ns = 0;
    float p[3], u[3], v[3];
    fov_result e;
    for (i = 0; i < 5; ++i) {
        fovpt_material_init(&w->mat[i]);
        w->mat[i].type = i == 4 ? (uint32_t)FOVPT_MAT_MIRROR : fz_pick(in, 4);
        for (k = 0; k < 3; ++k) {
            w->mat[i].albedo[k] = fz_unit_range(in, 0.0f, 1.0f);
            w->mat[i].specular[k] = 0.5f * fz_unit_range(in, 0.0f, 1.0f) * (1.0f - w->mat[i].albedo[k]);
        }
        w->mat[i].exponent = fz_unit_range(in, 0.0f, 200.0f);
        w->mat[i].ior = fz_unit_range(in, 1.0f, 2.5f);
    }
    w->mat[2].type = FOVPT_MAT_LAMBERT;
    {   /* the light: usual, dim, or huge (clamped at FOVPT_MAX_RADIANCE by the tracer) */
        uint32_t m = fz_pick(in, 8);
        float em = m == 7 ? 1e30f : (m == 6 ? 1e20f : fz_unit_range(in, 0.0f, 30.0f));
        for (k = 0; k < 3; ++k) w->mat[2].emission[k] = em * (k == 2 ? 0.8f : 1.0f);
    }
    p[0] = 0.0f; p[1] = fz_unit_range(in, -0.2f, 0.0f); p[2] = 0.0f;
    u[0] = 0.0f; u[1] = 1.0f; u[2] = 0.0f;
    fovpt_shape_plane(&w->sh[ns++], p, u, 0);
    p[0] = -2.0f; p[1] = 0.0f; p[2] = fz_unit_range(in, -2.5f, -1.0f);
    u[0] = 4.0f; u[1] = 0.0f; u[2] = 0.0f;
    v[0] = 0.0f; v[1] = 3.0f; v[2] = 0.0f;
    fovpt_shape_quad(&w->sh[ns++], p, u, v, 1);
    fovpt_shape_sphere(&w->sh[ns++], fz_unit_range(in, -1.0f, 1.0f), 0.5f, fz_unit_range(in, -1.0f, 1.0f),
                       fz_unit_range(in, 0.1f, 0.8f), 3);
    p[0] = fz_unit_range(in, -1.5f, 0.5f); p[1] = 0.0f; p[2] = fz_unit_range(in, -1.5f, 0.5f);
    u[0] = p[0] + fz_unit_range(in, 0.1f, 1.0f); u[1] = fz_unit_range(in, 0.1f, 1.5f); u[2] = p[2] + fz_unit_range(in, 0.1f, 1.0f);
    fovpt_shape_box(&w->sh[ns++], p, u, fz_pick(in, 2));
    p[0] = -0.5f; p[1] = fz_unit_range(in, 1.5f, 3.0f); p[2] = -0.5f;
    u[0] = fz_unit_range(in, 0.2f, 1.5f); u[1] = 0.0f; u[2] = 0.0f;
    v[0] = 0.0f; v[1] = 0.0f; v[2] = fz_unit_range(in, 0.2f, 1.5f);
    fovpt_shape_quad(&w->sh[ns++], p, u, v, 2);
    if (fz_u8(in) & 1u)
        fovpt_shape_sphere(&w->sh[ns++], fz_unit_range(in, -1.0f, 1.0f), fz_unit_range(in, 0.2f, 1.0f),
                           fz_unit_range(in, -1.0f, 1.0f), fz_unit_range(in, 0.1f, 0.5f), 4);
    fovpt_scene_desc_init(&d);
    d.shapes = w->sh; d.num_shapes = ns;
    d.materials = w->mat; d.num_materials = 5;
    e = fovpt_scene_size(&d, &w->bytes);
    FZ_CHECK(e == FOV_OK, "scene_size of a valid scene: %d", (int)e);
    w->mem = fz_alloc(w->bytes, 0xCD);
    e = fovpt_scene_build(&w->s, &d, w->mem, w->bytes);
    FZ_CHECK(e == FOV_OK, "scene_build of a valid scene: %d", (int)e);
    FZ_CHECK(fz_canary_ok(w->mem, w->bytes), "scene memory canary");
    return 1;
}

/* a camera looking at the scene; hostile 1 in 16 */
static void fz_cam(fz_in *in, fovpt_camera *cam, uint32_t W, uint32_t H)
{
    uint32_t k;
    fovpt_camera_init(cam, W, H);
    cam->pos[0] = fz_unit_range(in, -2.0f, 2.0f);
    cam->pos[1] = fz_unit_range(in, 0.2f, 3.0f);
    cam->pos[2] = fz_unit_range(in, 2.0f, 5.0f);
    cam->target[0] = fz_unit_range(in, -0.5f, 0.5f);
    cam->target[1] = fz_unit_range(in, 0.0f, 1.0f);
    cam->target[2] = fz_unit_range(in, -1.0f, 0.5f);
    cam->fov_y_deg = fz_unit_range(in, 20.0f, 100.0f);
    if (fz_u8(in) >= 232) { /* off-axis frustum */
        cam->tan_left = fz_unit_range(in, 0.05f, 1.5f); cam->tan_right = fz_unit_range(in, 0.05f, 1.5f);
        /* the same aspect as the image (else FOV_ERR_UNSUPPORTED, below) */
        cam->tan_bottom = (cam->tan_left + cam->tan_right) * (float)H / (float)W * fz_unit_range(in, 0.1f, 0.9f);
        cam->tan_top = (cam->tan_left + cam->tan_right) * (float)H / (float)W - cam->tan_bottom;
    }
    if (fz_u8(in) >= 240) {
        for (k = 0; k < 3; ++k) { cam->pos[k] = fz_float(in, -5.0f, 5.0f); cam->up[k] = fz_float(in, -1.0f, 1.0f); }
        cam->fov_y_deg = fz_float(in, 0.0f, 180.0f);
        cam->eye_offset = fz_float(in, -0.1f, 0.1f);
    }
}

/* ---- fovpt_shade_points ------------------------------------------------------------------ */
static int fz_is_shade_err(fov_result e)
{
    /* the camera's errors add _DEGENERATE and _UNSUPPORTED (an off-axis frustum whose aspect
       is not the image's) */
    return e == FOV_ERR_NULL || e == FOV_ERR_NOT_FINITE || e == FOV_ERR_INVALID_ARG || e == FOV_ERR_LIMIT ||
           e == FOV_ERR_DEGENERATE || e == FOV_ERR_UNSUPPORTED;
}

static void fz_shade(fz_in *in, const fovpt_scene *s)
{
    fovpt_config cfg = fovpt_config_default(), rc;
    fovpt_camera cam;
    fovpt_stats st, st0;
    uint32_t n = fz_pick(in, 9), stride = fz_pick(in, 5), first = fz_u32(in), frame = fz_u32(in), spp, i, es;
    float jitter, *xy, *rgb, *t, *rgb2, *t2;
    size_t xy_n, rgb_n, t_n;
    int use_t = fz_pick(in, 4) != 0, null_xy = n == 0 && (fz_u8(in) & 1u);
    fov_result e;
    cfg.mode = fz_pick(in, 2);
    cfg.spp = 1u + fz_pick(in, 4);
    cfg.max_depth = 1u + fz_pick(in, 3);
    cfg.no_nee = fz_pick(in, 2);
    cfg.seed = fz_u32(in);
    cfg.sampler = fz_pick(in, 3);
    cfg.mirror_nee = cfg.mode == FOVPT_MODE_PATH ? fz_pick(in, 2) : 0u;
    if (fz_u8(in) >= 224) cfg.robust = 3u + fz_pick(in, 6);
    cfg.logger.func = fz_log;
    if (fovpt_config_resolve(&cfg, &rc) != FOV_OK) return;
    fz_cam(in, &cam, 1u + fz_pick(in, 32), 1u + fz_pick(in, 32));
    spp = fz_pick(in, 8); /* 0: the config's */
    if (fz_u8(in) >= 248) spp = FOVPT_MAX_SPP + 1u + fz_pick(in, 3); /* FOV_ERR_LIMIT */
    else if (rc.robust && fz_u8(in) < 128) spp = rc.robust * (1u + fz_pick(in, 3)); /* groups */
    jitter = fz_u8(in) < 128 ? 0.0f : fz_float(in, 0.0f, 3.0f);
    es = stride == 0 ? 2u : stride;
    xy_n = (size_t)(n ? (n - 1u) * (es < 2u ? 2u : es) + 2u : 1u) * sizeof(float);
    rgb_n = (size_t)(3u * n + 1u) * sizeof(float);
    t_n = (size_t)(n + 1u) * sizeof(float);
    xy = (float *)fz_alloc(xy_n, 0);
    rgb = (float *)fz_alloc(rgb_n, FZ_PAD); rgb2 = (float *)fz_alloc(rgb_n, FZ_PAD);
    t = (float *)fz_alloc(t_n, FZ_PAD); t2 = (float *)fz_alloc(t_n, FZ_PAD);
    for (i = 0; i < n; ++i) {
        float *q = xy + (size_t)i * es;
        if (fz_u8(in) < 224) {
            q[0] = fz_unit_range(in, -2.0f, (float)cam.width + 2.0f);
            q[1] = fz_unit_range(in, -2.0f, (float)cam.height + 2.0f);
        } else {
            q[0] = fz_float(in, -1e4f, 1e4f);
            q[1] = fz_float(in, -1e4f, 1e4f);
        }
    }
    memset(&st, 0x11, sizeof st);
    st0 = st;
    e = fovpt_shade_points(s, &rc, &cam, n, null_xy ? NULL : xy, stride, first, frame, spp, jitter,
                           null_xy ? NULL : rgb, use_t ? t : NULL, &st);
    FZ_CHECK(fz_code_ok(e), "shade_points: unknown code %d", (int)e);
    FZ_CHECK(fz_canary_ok(xy, xy_n) && fz_canary_ok(rgb, rgb_n) && fz_canary_ok(t, t_n), "shade_points: canary");
    if (e != FOV_OK) {
        uint8_t b[4];
        FZ_CHECK(fz_is_shade_err(e), "shade_points: undocumented code %d", (int)e);
        /* checked before any work: nothing written */
        for (i = 0; i < 3u * n; ++i) { memcpy(b, rgb + i, 4); FZ_CHECK(b[0] == FZ_PAD && b[3] == FZ_PAD, "shade_points: rgb written on error %d", (int)e); }
        for (i = 0; i < n; ++i) { memcpy(b, t + i, 4); FZ_CHECK(b[0] == FZ_PAD && b[3] == FZ_PAD, "shade_points: t written on error %d", (int)e); }
        FZ_CHECK(memcmp(&st, &st0, sizeof st) == 0, "shade_points: stats changed on error %d", (int)e);
        FZ_CHECK(stride != 1u || e == FOV_ERR_INVALID_ARG, "shade_points: stride 1 gave %d", (int)e);
    } else {
        FZ_CHECK(stride != 1u || n == 0u, "shade_points: stride 1 accepted");
        for (i = 0; i < 3u * n; ++i)
            FZ_CHECK(fz_finite(rgb[i]) && rgb[i] >= 0.0f, "shade_points: rgb[%u] = %g", i, (double)rgb[i]);
        for (i = 0; use_t && i < n; ++i)
            FZ_CHECK((fz_finite(t[i]) && t[i] > 0.0f), "shade_points: t[%u] = %g", i, (double)t[i]);
        if (n >= 2u) { /* the same points in two calls: the same bits */
            uint32_t m = 1u + fz_pick(in, n - 1u);
            fov_result e1 = fovpt_shade_points(s, &rc, &cam, m, xy, stride, first, frame, spp, jitter, rgb2,
                                               use_t ? t2 : NULL, NULL);
            fov_result e2 = fovpt_shade_points(s, &rc, &cam, n - m, xy + (size_t)m * es, stride, first + m, frame, spp,
                                               jitter, rgb2 + 3u * m, use_t ? t2 + m : NULL, NULL);
            FZ_CHECK(e1 == FOV_OK && e2 == FOV_OK, "shade_points split: %d %d", (int)e1, (int)e2);
            FZ_CHECK(memcmp(rgb, rgb2, 3u * n * sizeof(float)) == 0, "shade_points: split at %u changes rgb", m);
            FZ_CHECK(!use_t || memcmp(t, t2, n * sizeof(float)) == 0, "shade_points: split at %u changes t", m);
            FZ_CHECK(fz_canary_ok(rgb2, rgb_n) && fz_canary_ok(t2, t_n), "shade_points split: canary");
        }
    }
    free(xy);
    free(rgb); free(rgb2); free(t); free(t2);
}

/* ---- the denoiser ------------------------------------------------------------------------ */
/* the resolved config inside its documented ranges */
static void fz_dn_cfg_check(const fovpt_denoise_cfg *c)
{
    FZ_CHECK(c->levels >= 1u && c->levels <= FOVPT_DN_MAX_LEVELS, "resolved levels %u", c->levels);
    FZ_CHECK(c->no_filter <= 1u && c->no_temporal <= 1u && c->no_sure <= 1u, "resolved flags");
    FZ_CHECK(c->fovea_step >= 1.0f && c->fovea_step <= 65536.0f, "resolved fovea_step %g", (double)c->fovea_step);
    FZ_CHECK(fz_finite(c->spp_ref) && c->spp_ref >= 0.0f, "resolved spp_ref %g", (double)c->spp_ref);
    FZ_CHECK(c->phi_lum > 0.0f && c->phi_lum <= 1e6f && c->phi_normal > 0.0f && c->phi_normal <= 1e6f &&
             c->phi_depth > 0.0f && c->phi_depth <= 1e6f && c->phi_albedo > 0.0f && c->phi_albedo <= 1e6f,
             "resolved phi_*");
    FZ_CHECK(c->alpha_fovea > 0.0f && c->alpha_fovea <= 1.0f && c->alpha_periphery > 0.0f &&
             c->alpha_periphery <= c->alpha_fovea, "resolved alpha %g %g", (double)c->alpha_fovea, (double)c->alpha_periphery);
    FZ_CHECK(c->depth_tol > 0.0f && c->depth_tol <= 1.0f, "resolved depth_tol %g", (double)c->depth_tol);
    FZ_CHECK(c->normal_cos >= -1.0f && c->normal_cos < 1.0f, "resolved normal_cos %g", (double)c->normal_cos);
    FZ_CHECK(c->skip_noise > 0.0f && c->skip_noise <= 255.0f, "resolved skip_noise %g", (double)c->skip_noise);
    FZ_CHECK(c->spp_full > 0.0f && c->spp_full <= 1e30f, "resolved spp_full %g", (double)c->spp_full);
    FZ_CHECK(c->r_small >= 1.0f && c->r_small <= 65536.0f, "resolved r_small %g", (double)c->r_small);
    FZ_CHECK(c->sure_radius >= 1u && c->sure_radius <= 8u, "resolved sure_radius %u", c->sure_radius);
    FZ_CHECK(c->sure_min_spp >= 2.0f && c->sure_min_spp <= 1e30f, "resolved sure_min_spp %g", (double)c->sure_min_spp);
}

static void fz_dn_cfg(fz_in *in, fovpt_denoise_cfg *dc, uint32_t W, uint32_t H)
{
    uint32_t mode = fz_pick(in, 8);
    *dc = fovpt_denoise_cfg_default();
    if (mode >= 3u && mode <= 6u) { /* some fields from the bytes, mostly in range */
#define FZ_F(field, lo, hi) if (fz_u8(in) >= 160) dc->field = fz_float(in, lo, hi)
#define FZ_U(field, n) if (fz_u8(in) >= 160) dc->field = fz_pick(in, n)
        FZ_U(levels, 10u);
        FZ_U(no_filter, 3u);
        FZ_U(no_temporal, 2u);
        FZ_F(fovea_step, 0.0f, 16.0f);
        FZ_F(spp_ref, 0.0f, 64.0f);
        FZ_F(phi_lum, 0.0f, 64.0f);
        FZ_F(phi_normal, 0.0f, 256.0f);
        FZ_F(phi_depth, 0.0f, 8.0f);
        FZ_F(phi_albedo, 0.0f, 1.0f);
        FZ_F(alpha_fovea, 0.0f, 1.0f);
        FZ_F(alpha_periphery, 0.0f, 0.3f);
        FZ_F(depth_tol, 0.0f, 1.0f);
        FZ_F(normal_cos, -1.0f, 1.0f);
        FZ_F(skip_noise, 0.0f, 8.0f);
        FZ_F(spp_full, 0.0f, 64.0f);
        FZ_F(r_small, 0.0f, 8.0f);
        FZ_U(no_sure, 3u);
        FZ_U(sure_radius, 10u);
        FZ_F(sure_min_spp, 0.0f, 32.0f);
        FZ_F(eye.mar0_arcmin, 0.0f, 10.0f);
        FZ_F(eye.slope_arcmin, 0.0f, 10.0f);
        FZ_F(eye.quality, 0.0f, 10.0f);
        if (fz_u8(in) >= 224) {
            dc->display.fov_y_deg = fz_float(in, 0.0f, 180.0f);
            dc->display.pixel_pitch_mm = fz_float(in, 0.0f, 1.0f);
            dc->display.distance_mm = fz_float(in, 0.0f, 1000.0f);
            dc->display.axis_dx = fz_float(in, -10.0f, 10.0f);
            dc->display.axis_dy = fz_float(in, -10.0f, 10.0f);
        }
#undef FZ_F
#undef FZ_U
    } else if (mode == 7u) { /* the raw struct bytes (all but the logger) */
        size_t k;
        uint8_t *b = (uint8_t *)dc;
        for (k = 0; k < offsetof(fovpt_denoise_cfg, logger); ++k) b[k] = fz_u8(in);
    }
    dc->logger.func = fz_log;
    dc->logger.user = NULL;
    dc->width = W; dc->height = H;
    if (fz_u8(in) >= 248) { dc->width = fz_pick(in, W + 2u); dc->height = 1u + fz_pick(in, H + 1u); }
}

/* the guides' documented content (fovpt_trace_rows_guide) */
static void fz_guide_check(const fz_buf *gb, const fovpt_config *rc, uint32_t W, uint32_t H)
{
    uint32_t x, y, k;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            const float *al = gb[0].p ? fz_at(&gb[0], x, y) : NULL, *nr = fz_at(&gb[1], x, y), *dp = fz_at(&gb[2], x, y);
            const float *sp = gb[3].p ? fz_at(&gb[3], x, y) : NULL, *vr = gb[4].p ? fz_at(&gb[4], x, y) : NULL;
            double nl = 0.0;
            int nz = nr[0] == 0.0f && nr[1] == 0.0f && nr[2] == 0.0f;
            for (k = 0; al && k < 3; ++k)
                FZ_CHECK(al[k] >= 0.0f && al[k] <= 1.0f, "guide albedo (%u, %u)[%u] = %g outside [0, 1]", x, y, k, (double)al[k]);
            for (k = 0; k < 3; ++k) { FZ_CHECK(fz_finite(nr[k]), "guide normal (%u, %u) not finite", x, y); nl += (double)nr[k] * (double)nr[k]; }
            FZ_CHECK(nz || (nl > 0.998 && nl < 1.002), "guide normal (%u, %u) neither 0 nor unit: |n|^2 = %g", x, y, nl);
            FZ_CHECK(fz_finite(dp[0]) && dp[0] >= 0.0f, "guide depth (%u, %u) = %g", x, y, (double)dp[0]);
            /* depth 0: no sample hit, so the normal is (0, 0, 0) too. Not the converse: hits whose
               normals cancel (a pixel across the floor's horizon, seen from above, and a light
               quad's underside, seen from below) give a zero mean normal with a depth > 0 */
            FZ_CHECK(dp[0] > 0.0f || nz, "guide (%u, %u): depth 0 (no hit) but normal (%g %g %g)", x, y,
                     (double)nr[0], (double)nr[1], (double)nr[2]);
            if (sp) {
                FZ_CHECK(fz_finite(sp[0]) && sp[0] >= 0.0f, "guide spp (%u, %u) = %g", x, y, (double)sp[0]);
                if (rc->method == FOVPT_METHOD_SELECTIVE || rc->method == FOVPT_METHOD_JIN)
                    FZ_CHECK(sp[0] == 1.0f, "guide spp (%u, %u) = %g, SELECTIVE / JIN: 1", x, y, (double)sp[0]);
                if (rc->method == FOVPT_METHOD_UNIFORM && !rc->accumulate)
                    FZ_CHECK(sp[0] == (float)rc->spp, "guide spp (%u, %u) = %g, UNIFORM: %u", x, y, (double)sp[0], rc->spp);
            }
            if (vr) {
                FZ_CHECK(fz_finite(vr[0]) && (vr[0] >= 0.0f || vr[0] == -1.0f), "guide var (%u, %u) = %g", x, y, (double)vr[0]);
                if (rc->method == FOVPT_METHOD_SELECTIVE || rc->method == FOVPT_METHOD_JIN ||
                    (rc->method == FOVPT_METHOD_UNIFORM && !rc->accumulate && rc->spp < 2u))
                    FZ_CHECK(vr[0] == -1.0f, "guide var (%u, %u) = %g, expected -1 (fewer than 2 own samples)", x, y, (double)vr[0]);
            }
        }
}

/* a synthetic frame: planes with edges, a few normals and albedos, noisy radiance */
static void fz_synth(fz_in *in, fz_buf *rgb, fz_buf *gb, uint32_t W, uint32_t H)
{
    uint32_t st = fz_u32(in) | 1u, x, y, k, edge = fz_pick(in, W + 1u);
    float d0 = fz_unit_range(in, 0.5f, 20.0f), dx = fz_unit_range(in, -0.3f, 0.3f), bright = fz_unit_range(in, 0.0f, 4.0f);
    float spp = (float)fz_pick(in, 40), var = fz_unit_range(in, -1.0f, 0.5f);
    static const float nrm[3][3] = { { 0.0f, 0.0f, 1.0f }, { 0.0f, 1.0f, 0.0f }, { 0.6f, 0.0f, 0.8f } };
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            uint32_t reg = x < edge ? 0u : (y & 1u) + 1u;
            float noise;
            st ^= st << 13; st ^= st >> 17; st ^= st << 5;
            noise = (float)(st >> 8) / 16777216.0f;
            for (k = 0; k < 3; ++k) fz_at(rgb, x, y)[k] = bright * (0.2f + 0.3f * (float)reg + noise);
            if (gb[0].p) for (k = 0; k < 3; ++k) fz_at(&gb[0], x, y)[k] = 0.25f * (float)(reg + 1u);
            for (k = 0; k < 3; ++k) fz_at(&gb[1], x, y)[k] = nrm[reg][k];
            fz_at(&gb[2], x, y)[0] = reg == 2u && (st & 8u) ? 0.0f : d0 + dx * (float)x + 3.0f * (float)reg;
            if (fz_at(&gb[2], x, y)[0] <= 0.0f) for (k = 0; k < 3; ++k) fz_at(&gb[1], x, y)[k] = 0.0f;
            if (gb[3].p) fz_at(&gb[3], x, y)[0] = spp;
            if (gb[4].p) fz_at(&gb[4], x, y)[0] = var < 0.0f ? -1.0f : var * noise;
        }
}

/* hostile pixels in the noisy image and the guides */
static void fz_hostile(fz_in *in, fz_buf *rgb, fz_buf *gb, uint32_t W, uint32_t H)
{
    uint32_t np = 1u + fz_pick(in, 8), i, k;
    for (i = 0; i < np && fz_left(in) > 0; ++i) {
        uint32_t x = fz_pick(in, W), y = fz_pick(in, H), what = fz_pick(in, 6);
        float *p;
        switch (what) {
        case 0: p = fz_at(rgb, x, y); for (k = 0; k < 3; ++k) p[k] = fz_float(in, -1.0f, 1e6f); break;
        case 1: if (gb[0].p) { p = fz_at(&gb[0], x, y); for (k = 0; k < 3; ++k) p[k] = fz_float(in, -1.0f, 2.0f); } break;
        case 2: if (gb[1].p) { p = fz_at(&gb[1], x, y); for (k = 0; k < 3; ++k) p[k] = fz_float(in, -2.0f, 2.0f); } break;
        case 3: if (gb[2].p) fz_at(&gb[2], x, y)[0] = fz_float(in, -1.0f, 100.0f); break;
        case 4: if (gb[3].p) fz_at(&gb[3], x, y)[0] = fz_float(in, -1.0f, 1e9f); break;
        default: if (gb[4].p) fz_at(&gb[4], x, y)[0] = fz_float(in, -2.0f, 1e3f); break;
        }
    }
}

static void fz_guide_of(fovpt_guide *g, const fz_buf *gb)
{
    fovpt_guide_init(g);
    g->albedo = gb[0].p; g->albedo_stride = gb[0].stride;
    g->normal = gb[1].p; g->normal_stride = gb[1].stride;
    g->depth = gb[2].p; g->depth_stride = gb[2].stride;
    g->spp = gb[3].p; g->spp_stride = gb[3].stride;
    g->var = gb[4].p; g->var_stride = gb[4].stride;
}

/* row ranges [y0, y1) of one phase in random chunks */
static uint32_t fz_split(fz_in *in, uint32_t H) { return 1u + fz_pick(in, H); }

/* the output of a denoiser: finite, >= 0 */
static void fz_dn_out_check(const fz_buf *o, const char *what)
{
    uint32_t x, y, k;
    for (y = 0; y < o->H; ++y)
        for (x = 0; x < o->W; ++x)
            for (k = 0; k < 3; ++k) {
                float v = fz_at(o, x, y)[k];
                FZ_CHECK(fz_finite(v) && v >= 0.0f, "%s: (%u, %u)[%u] = %g", what, x, y, k, (double)v);
            }
    fz_buf_check(o, what);
}

static void fz_denoise(fz_in *in, const fovpt_scene *s)
{
    uint32_t W = 1u + fz_pick(in, FZ_MAXD), H = 1u + fz_pick(in, FZ_MAXD), frames = 1u + fz_pick(in, 3), f, k, y0, sp;
    uint32_t gmask = fz_u8(in), src_mode = fz_pick(in, 4), compare = fz_pick(in, 3);
    fovpt_config cfg = fovpt_config_default(), rc;
    fovpt_camera cam;
    fov_gaze gaze;
    fovpt_ctx ctxA, ctxB;
    fovpt_denoise_cfg dc, dcr;
    fovpt_denoise dnA, dnB;
    fovpt_output outA, outB, nout;
    fovpt_guide gA, gB;
    fz_buf nA, nB, gbA[5], gbB[5], dA, dB;
    fz_buf8 dA8, dB8, nA8;
    void *memA = NULL, *memB = NULL, *dmA = NULL, *dmB = NULL;
    size_t needA = 0, dbytes = 0, dalloc = 0;
    int have_ctx = 0, have_dn = 0;
    fov_result e, e2;
    /* render config */
    cfg.method = fz_pick(in, 5);
    cfg.mode = fz_pick(in, 2);
    cfg.spp = 1u + fz_pick(in, 4);
    if (fz_u8(in) >= 208 && W * H <= 64u) cfg.spp = 8u + fz_pick(in, 20); /* a var from >= 16 samples: SURE */
    cfg.max_depth = 1u + fz_pick(in, 3);
    cfg.no_nee = fz_pick(in, 2);
    cfg.seed = fz_u32(in);
    cfg.accumulate = fz_pick(in, 2);
    cfg.sampler = fz_pick(in, 3);
    if (cfg.method >= FOVPT_METHOD_SELECTIVE) { cfg.temporal.reuse = fz_pick(in, 2); cfg.temporal.smooth = fz_pick(in, 2); }
    cfg.logger.func = fz_log;
    fz_cam(in, &cam, W, H);
    gaze.x = fz_unit_range(in, -2.0f, (float)W + 2.0f);
    gaze.y = fz_unit_range(in, -2.0f, (float)H + 2.0f);
    /* the buffers: the noisy images, the guides (albedo, spp, var sometimes absent; depth
       and normal absent 1 in 32: fovpt_denoise_frame's FOV_ERR_NULL), the denoised images */
    fz_buf_make(&nA, in, 3u, W, H); fz_buf_make(&nB, in, 3u, W, H);
    fz_buf8_make(&nA8, in, W, H);
    for (k = 0; k < 5; ++k) {
        static const uint32_t ch[5] = { 3u, 3u, 1u, 1u, 1u };
        fz_buf_make(&gbA[k], in, ch[k], W, H);
        gbB[k] = gbA[k];
        gbB[k].p = (float *)fz_alloc(gbA[k].n, FZ_PAD);
    }
    for (k = 0; k < 5; ++k) {
        int drop = (k == 0 || k >= 3) ? ((gmask >> k) & 1u) && (gmask & 0x40u) : (gmask == 0xFFu);
        if (drop) { fz_buf_free(&gbA[k]); fz_buf_free(&gbB[k]); }
    }
    fz_buf_make(&dA, in, 3u, W, H); fz_buf_make(&dB, in, 3u, W, H);
    fz_buf8_make(&dA8, in, W, H); fz_buf8_make(&dB8, in, W, H);
    fz_guide_of(&gA, gbA); fz_guide_of(&gB, gbB);
    fovpt_output_init(&nout); nout.rgb = nA.p; nout.rgb_stride = nA.stride; nout.rgb8 = nA8.p; nout.rgb8_stride = nA8.stride;
    fovpt_output_init(&outA); outA.rgb = dA.p; outA.rgb_stride = dA.stride; outA.rgb8 = dA8.p; outA.rgb8_stride = dA8.stride;
    fovpt_output_init(&outB); outB.rgb = dB.p; outB.rgb_stride = dB.stride; outB.rgb8 = dB8.p; outB.rgb8_stride = dB8.stride;
    /* two render contexts */
    if (src_mode != 3u && fovpt_config_resolve(&cfg, &rc) == FOV_OK && fovpt_memory_size(&cfg, &cam, &needA) == FOV_OK &&
        needA < ((size_t)16 << 20)) {
        memA = fz_alloc(needA, 0xCD); memB = fz_alloc(needA, 0xCD);
        e = fovpt_init(&ctxA, &cfg, s, &cam, gaze, memA, needA);
        e2 = fovpt_init(&ctxB, &cfg, s, &cam, gaze, memB, needA);
        FZ_CHECK(e == e2 && fz_code_ok(e), "fovpt_init: %d %d", (int)e, (int)e2);
        have_ctx = e == FOV_OK;
    }
    /* the denoise config and two denoisers */
    fz_dn_cfg(in, &dc, W, H);
    e = fovpt_denoise_resolve(&dc, &dcr);
    FZ_CHECK(fz_code_ok(e), "denoise_resolve: unknown code %d", (int)e);
    if (e == FOV_OK) fz_dn_cfg_check(&dcr);
    e2 = fovpt_denoise_size(&dc, &dbytes);
    FZ_CHECK(e2 == e, "denoise_size %d, resolve %d", (int)e2, (int)e);
    if (e == FOV_OK) {
        uint64_t px = (uint64_t)dcr.width * dcr.height;
        FZ_CHECK(dbytes >= px * (dcr.no_sure ? 164u : 204u), "denoise_size %zu below %u bytes per pixel", dbytes,
                 dcr.no_sure ? 164u : 204u);
        dalloc = dbytes + 8u * fz_pick(in, 3);
        dmA = fz_alloc(dalloc + 8u, 0xEE); dmB = fz_alloc(dalloc + 8u, 0xEE);
        if (fz_u8(in) >= 224) { /* documented rejections: misaligned, too small */
            e = fovpt_denoise_init(&dnA, &dc, (uint8_t *)dmA + 4, dalloc);
            FZ_CHECK(e == FOV_ERR_INVALID_ARG, "denoise_init: misaligned memory gave %d", (int)e);
            e = fovpt_denoise_init(&dnA, &dc, dmA, dbytes - 8u);
            FZ_CHECK(e == FOV_ERR_TOO_SMALL, "denoise_init: bytes below denoise_size gave %d", (int)e);
            FZ_CHECK(fz_canary_ok(dmA, dalloc + 8u), "denoise_init on error: canary");
        }
        e = fovpt_denoise_init(&dnA, &dc, dmA, dalloc);
        e2 = fovpt_denoise_init(&dnB, &dc, dmB, dalloc);
        FZ_CHECK(e == FOV_OK && e2 == FOV_OK, "denoise_init of a resolved config: %d %d", (int)e, (int)e2);
        FZ_CHECK(fovpt_denoise_passes(&dnA) <= dcr.levels && (!dcr.no_filter || fovpt_denoise_passes(&dnA) == 0u),
                 "denoise_passes %u with levels %u no_filter %u", fovpt_denoise_passes(&dnA), dcr.levels, dcr.no_filter);
        have_dn = 1;
    }
    for (f = 0; f < frames; ++f) {
        fovpt_camera dcam = cam;
        fov_gaze dgaze = gaze;
        int rendered = 0;
        if (f > 0) { /* move: camera and gaze (reprojection) */
            fovpt_camera c2 = cam;
            uint32_t mv = fz_pick(in, 4);
            if (mv == 1u) for (k = 0; k < 3; ++k) c2.pos[k] += fz_unit_range(in, -0.2f, 0.2f);
            if (mv == 2u) for (k = 0; k < 3; ++k) c2.target[k] += fz_unit_range(in, -0.3f, 0.3f);
            if (mv == 3u) fz_cam(in, &c2, W, H);
            gaze.x = fz_float(in, -2.0f, (float)W + 2.0f);
            gaze.y = fz_unit_range(in, -2.0f, (float)H + 2.0f);
            if (have_ctx) {
                e = fovpt_set_view(&ctxA, &c2, gaze);
                e2 = fovpt_set_view(&ctxB, &c2, gaze);
                FZ_CHECK(e == e2 && fz_code_ok(e), "set_view: %d %d", (int)e, (int)e2);
                if (e == FOV_OK) cam = c2;
                else gaze = ctxA.gaze;
            } else {
                cam = c2;
            }
            dcam = cam; dgaze = gaze;
            if (have_dn && fz_u8(in) >= 240) {
                FZ_CHECK(fovpt_denoise_reset(&dnA) == FOV_OK && fovpt_denoise_reset(&dnB) == FOV_OK, "denoise_reset");
            }
        }
        /* the noisy frame */
        if (have_ctx && src_mode != 3u) {
            fovpt_stats st;
            fovpt_stats_init(&st);
            sp = fz_split(in, H);
            for (y0 = 0; y0 < H; y0 += sp) {
                e = fovpt_trace_rows_guide(&ctxA, f, y0, y0 + sp < H ? y0 + sp : H, &gA, &st);
                FZ_CHECK(e == FOV_OK, "trace_rows_guide: %d", (int)e);
            }
            sp = fz_split(in, H);
            for (y0 = 0; y0 < H; y0 += sp) {
                e = fovpt_refine_rows(&ctxA, f, y0, y0 + sp < H ? y0 + sp : H, &st);
                FZ_CHECK(e == FOV_OK, "refine_rows: %d", (int)e);
            }
            sp = fz_split(in, H);
            for (y0 = 0; y0 < H; y0 += sp) {
                e = fovpt_resolve_rows(&ctxA, y0, y0 + sp < H ? y0 + sp : H, &nout);
                FZ_CHECK(e == FOV_OK, "resolve_rows: %d", (int)e);
            }
            if (compare) { /* the other context, whole: the same image (and guides) */
                fovpt_output o2;
                fovpt_output_init(&o2); o2.rgb = nB.p; o2.rgb_stride = nB.stride;
                e = compare == 1u ? fovpt_render_guide(&ctxB, f, &o2, &gB, NULL) : fovpt_render(&ctxB, f, &o2, NULL);
                FZ_CHECK(e == FOV_OK, "render%s: %d", compare == 1u ? "_guide" : "", (int)e);
                fz_buf_same(&nA, &nB, compare == 1u ? "render_guide vs trace_rows_guide in rows: image"
                                                    : "render vs trace_rows_guide in rows: image");
                if (compare == 1u)
                    for (k = 0; k < 5; ++k) fz_buf_same(&gbA[k], &gbB[k], "render_guide vs trace_rows_guide in rows: a guide");
            }
            if (gbA[1].p && gbA[2].p) fz_guide_check(gbA, &rc, W, H);
            for (k = 0; k < 5; ++k) { fz_buf_check(&gbA[k], "guide"); fz_buf_check(&gbB[k], "guide B"); }
            fz_buf_check(&nA, "noisy rgb"); fz_buf_check(&nB, "noisy rgb B"); fz_buf8_check(&nA8, "noisy rgb8");
            for (y0 = 0; y0 < H; ++y0)
                for (k = 0; k < 3u * W; ++k) FZ_CHECK(fz_finite(nA.p[(size_t)y0 * nA.rs + k]), "noisy rgb not finite");
            rendered = 1;
        } else if (gbA[1].p && gbA[2].p) {
            fz_synth(in, &nA, gbA, W, H);
        }
        if (!have_dn) continue;
        if (src_mode == 2u || (src_mode == 3u && fz_u8(in) >= 128) || (!rendered && fz_u8(in) >= 224))
            fz_hostile(in, &nA, gbA, W, H);
        if (fz_u8(in) >= 240) { /* a hostile denoise camera or gaze */
            if (fz_u8(in) & 1u) fz_cam(in, &dcam, W, H);
            else dgaze.x = fz_float(in, -1e3f, 1e3f);
        }
        /* B: sometimes a failed frame first (the history is kept, no frame to run) */
        if (fz_u8(in) >= 208) {
            uint32_t how = fz_pick(in, 4);
            fov_gaze bad = dgaze;
            fovpt_guide gbad = gA;
            volatile float z = 0.0f;
            fov_result want = FOV_ERR_NOT_FINITE;
            if (how == 0u) bad.y = z / z;
            if (how == 1u) { gbad.depth = NULL; want = FOV_ERR_NULL; }
            if (how == 2u) { gbad.normal_stride = 3u * W - 1u; want = W * 3u > 1u ? FOV_ERR_INVALID_ARG : FOV_OK; }
            if (how == 3u) { gbad.normal = NULL; want = FOV_ERR_NULL; }
            if (want != FOV_OK) {
                e = fovpt_denoise_frame(&dnB, &dcam, bad, nA.p, nA.stride, &gbad);
                FZ_CHECK(e != FOV_OK && fz_code_ok(e), "denoise_frame with a bad argument (%u) gave %d", how, (int)e);
                FZ_CHECK(e == want || dcr.width != W || dcr.height != H || !gA.depth || !gA.normal,
                         "denoise_frame with a bad argument (%u): %d, documented %d", how, (int)e, (int)want);
                e = fovpt_denoise_temporal_rows(&dnB, 0, dcr.height);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "temporal_rows after a failed frame: %d", (int)e);
                e = fovpt_denoise_resolve_rows(&dnB, 0, dcr.height, &outB);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "resolve_rows after a failed frame: %d", (int)e);
            }
        }
        e = fovpt_denoise_frame(&dnA, &dcam, dgaze, nA.p, nA.stride, &gA);
        e2 = fovpt_denoise_frame(&dnB, &dcam, dgaze, nA.p, nA.stride, &gA);
        FZ_CHECK(e == e2 && fz_code_ok(e), "denoise_frame: %d %d", (int)e, (int)e2);
        if ((!gA.depth || !gA.normal)) FZ_CHECK(e == FOV_ERR_NULL, "denoise_frame without depth or normal: %d", (int)e);
        else if (dcr.width != W || dcr.height != H) FZ_CHECK(e == FOV_ERR_INVALID_ARG, "denoise_frame of another size: %d", (int)e);
        if (e != FOV_OK) {
            e = fovpt_denoise_run(&dnA, &outA);
            FZ_CHECK(e == FOV_ERR_INVALID_ARG, "denoise_run after a failed frame: %d", (int)e);
            continue;
        }
        {
            uint32_t passes = fovpt_denoise_passes(&dnA), p, inj = fz_pick(in, 8);
            /* A: everything */
            e = fovpt_denoise_run(&dnA, &outA);
            FZ_CHECK(e == FOV_OK, "denoise_run: %d", (int)e);
            /* B: the phases in row chunks, rejected calls mixed in */
            if (inj == 1u) {
                e = fovpt_denoise_resolve_rows(&dnB, 0, H, &outB);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "resolve_rows before temporal: %d", (int)e);
            }
            if (inj == 2u && passes) {
                e = fovpt_denoise_atrous_rows(&dnB, 0, fz_pick(in, H), H);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "atrous_rows before temporal: %d", (int)e);
            }
            sp = fz_split(in, H);
            for (y0 = 0; y0 < H; y0 += sp) {
                e = fovpt_denoise_temporal_rows(&dnB, y0, y0 + sp < H ? y0 + sp : H);
                FZ_CHECK(e == FOV_OK, "temporal_rows: %d", (int)e);
            }
            if (inj == 3u && passes >= 2u) {
                e = fovpt_denoise_atrous_rows(&dnB, 1u + fz_pick(in, passes - 1u), 0, H);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "atrous_rows pass >= 1 before pass 0: %d", (int)e);
            }
            if (inj == 4u) {
                e = fovpt_denoise_atrous_rows(&dnB, passes + fz_pick(in, 3), 0, H);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "atrous_rows pass >= passes: %d", (int)e);
            }
            if (inj == 5u && passes) {
                e = fovpt_denoise_resolve_rows(&dnB, 0, H, &outB);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "resolve_rows before the passes: %d", (int)e);
            }
            for (p = 0; p < passes; ++p) {
                sp = fz_split(in, H);
                for (y0 = 0; y0 < H; y0 += sp) {
                    e = fovpt_denoise_atrous_rows(&dnB, p, y0, y0 + sp < H ? y0 + sp : H);
                    FZ_CHECK(e == FOV_OK, "atrous_rows pass %u rows %u..: %d", p, y0, (int)e);
                }
            }
            if (inj == 6u && passes) {
                e = fovpt_denoise_temporal_rows(&dnB, 0, H);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "temporal_rows after the passes: %d", (int)e);
            }
            if (inj == 7u) {
                e = fovpt_denoise_resolve_rows(&dnB, 1u, 0u, &outB);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "resolve_rows y0 > y1: %d", (int)e);
                e = fovpt_denoise_temporal_rows(&dnB, 0, H + 1u);
                FZ_CHECK(e == FOV_ERR_INVALID_ARG, "temporal_rows y1 > height: %d", (int)e);
                {   /* an output stride below 3 * width */
                    fovpt_output ob = outB;
                    ob.rgb_stride = 3u * W - 1u;
                    e = fovpt_denoise_resolve_rows(&dnB, 0, H, &ob);
                    FZ_CHECK(e == FOV_ERR_INVALID_ARG, "resolve_rows with rgb_stride 3 W - 1: %d", (int)e);
                }
            }
            /* nothing of B's output written so far (every call above was rejected) */
            for (y0 = 0; y0 < H; ++y0)
                for (k = 0; k < 3u * W; ++k) {
                    uint8_t q[4];
                    memcpy(q, dB.p + (size_t)y0 * dB.rs + k, 4);
                    FZ_CHECK(f > 0u || (q[0] == FZ_PAD && q[3] == FZ_PAD), "a rejected resolve_rows wrote the output");
                }
            sp = fz_split(in, H);
            for (y0 = 0; y0 < H; y0 += sp) {
                e = fovpt_denoise_resolve_rows(&dnB, y0, y0 + sp < H ? y0 + sp : H, &outB);
                FZ_CHECK(e == FOV_OK, "resolve_rows: %d", (int)e);
            }
            fz_dn_out_check(&dA, "denoise_run output");
            fz_dn_out_check(&dB, "denoise rows output");
            fz_buf8_check(&dA8, "denoise_run rgb8"); fz_buf8_check(&dB8, "denoise rows rgb8");
            fz_buf_same(&dA, &dB, "denoise_run vs the row-range calls: rgb");
            for (y0 = 0; y0 < H; ++y0)
                FZ_CHECK(memcmp(dA8.p + (size_t)y0 * dA8.rs, dB8.p + (size_t)y0 * dB8.rs, 3u * W) == 0,
                         "denoise_run vs the row-range calls: rgb8 row %u", y0);
            FZ_CHECK(fz_canary_ok(dmA, dalloc + 8u) && fz_canary_ok(dmB, dalloc + 8u), "denoiser memory canary");
            /* the frame's buffers unchanged by the denoiser */
            fz_buf_check(&nA, "noisy rgb (denoiser input)");
            for (k = 0; k < 5; ++k) fz_buf_check(&gbA[k], "guide (denoiser input)");
        }
    }
    /* "A frame whose temporal phase did not run on every row is not used as history": A runs
       the temporal phase of one more frame on rows [0, k) only, then a frame in full; B
       forgets its history (fovpt_denoise_reset) before that frame: the same image. (The last
       reads of an input, so the seeds before this check keep their meaning.) */
    if (have_dn && fz_u8(in) >= 192) {
        uint32_t kk = fz_pick(in, H);
        e = fovpt_denoise_frame(&dnA, &cam, gaze, nA.p, nA.stride, &gA);
        if (e == FOV_OK) {
            if (kk) {
                e = fovpt_denoise_temporal_rows(&dnA, 0, kk);
                FZ_CHECK(e == FOV_OK, "temporal_rows on rows [0, %u): %d", kk, (int)e);
            }
            e = fovpt_denoise_frame(&dnA, &cam, gaze, nA.p, nA.stride, &gA);
            FZ_CHECK(e == FOV_OK, "denoise_frame after a partial frame: %d", (int)e);
            FZ_CHECK(fovpt_denoise_reset(&dnB) == FOV_OK, "denoise_reset");
            e = fovpt_denoise_frame(&dnB, &cam, gaze, nA.p, nA.stride, &gA);
            FZ_CHECK(e == FOV_OK, "denoise_frame after reset: %d", (int)e);
            e = fovpt_denoise_run(&dnA, &outA);
            e2 = fovpt_denoise_run(&dnB, &outB);
            FZ_CHECK(e == FOV_OK && e2 == FOV_OK, "denoise_run: %d %d", (int)e, (int)e2);
            fz_dn_out_check(&dA, "denoise_run after a partial frame");
            fz_buf_same(&dA, &dB, "a partial frame used as history (vs. no history after reset): rgb");
        }
    }
    if (have_ctx) {
        FZ_CHECK(fz_canary_ok(memA, needA) && fz_canary_ok(memB, needA), "context memory canary");
    }
    free(memA); free(memB); free(dmA); free(dmB);
    fz_buf_free(&nA); fz_buf_free(&nB); free(nA8.p);
    for (k = 0; k < 5; ++k) { fz_buf_free(&gbA[k]); fz_buf_free(&gbB[k]); }
    fz_buf_free(&dA); fz_buf_free(&dB); free(dA8.p); free(dB8.p);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_begin(data, size);
    fz_world w;
    uint32_t what = fz_pick(&in, 4); /* 0: shade_points, 1: denoiser, else both */
    fz_world_build(&w, &in);
    if (what != 1u) fz_shade(&in, &w.s);
    if (what != 0u) fz_denoise(&in, &w.s);
    FZ_CHECK(fz_canary_ok(w.mem, w.bytes), "scene memory canary after use");
    free(w.mem);
    return 0;
}
