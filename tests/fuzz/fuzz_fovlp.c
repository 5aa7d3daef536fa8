/* fuzz_fovlp.c - libFuzzer harness of fovlp.h (issue 10): configs as raw bytes, memory-size
   query then init in caller memory, sampling (array and callback), reconstruction with odd
   tile / row splits and strides, the Gaussian blend and TAA across frames, the mappings and
   the eccentricity model. Every buffer has a canary after it. Checks (FZ_CHECK aborts):
   - every FOV_OK output is finite and in its documented range (fovlp.h NUMERICS): geometry
     invariants, samples on the screen in their slots, mappings, density >= 0, spacings,
     eccentricity in [0, 180], jitter in [0, 1);
   - a result other than FOV_OK is a known code, and (with a context or config at hand) the
     logger got an error with that code;
   - the reconstruction with finite samples is finite and inside the range of the shaded
     values; tiles, row splits and strides never change it (bit for bit); the blend and TAA
     likewise do not depend on the row split;
   - TAA never writes a non-finite colour, ages stay in [1, max_age], |out| <= 3 max |input|,
     and with a still camera and no clamp each output lies between its history and current;
   - no canary is touched.
   Input layout (reading order; every reader gives a value past the end, see fuzz_common.h;
   tests/fuzz/gen_fovlp.py writes inputs in this layout):
     u8 preset (% 5; 4: zero config)  u8 width-1 (% 24)  u8 height-1 (% 24)
     u8 flags A, then per set bit: 0 sigma f(0.3, 4); 1 alpha f(0.25, 8); 2 gaze_angle
        f(0, 0.6); 3 no_disc u8 % 3; 4 lp_aspect f(0.1, 4); 5 match_deg f(1, 60);
        6 norm u8 % 3, edge u8 % 3; 7 display: u8 mode % 3 (fov_y f(10, 170) | pitch
        f(0.05, 1), distance f(100, 2000) | axis_dx f(-40, 40), axis_dy f(-40, 40))
     u8 flags B, then: 0 cam_fov_y_deg f(10, 170); 1 blend u8 % 3, blend_start f(0, 1),
        blend_end f(0, 1); 2 taa.enable = 1; 3 taa: phases u8, halton_start u8, max_age u8,
        clamp u8 % 4, clip_gamma f(0.5, 3), depth_tol f(0, 0.1), reset_deg f(0, 10),
        periphery f(0, 1), jitter_moving u8 % 3, thesis_moving u8 % 3; 4 fovlp_config_acuity
        (issue 13): eye mar0 f(0, 4), slope f(0, 4), quality f(0, 4), u8 cam % 2 (NULL |
        tan_half_y f(0.05, 3)); the harness then runs on the acuity config when it is FOV_OK
     u8 frames (% 5 + 1), then per frame:
        gaze f(-4, W + 4), f(-4, H + 4)
        u8 camera % 4 (NULL | still | moving: dpos f(-0.2, 0.2) x3, dfwd f(-0.05, 0.05) |
           hostile: pos f(-1e3, 1e3) x3, tan_half_y f(0.1, 2), then for k = 0..2 right[k],
           up[k], fwd[k] += f(-0.1, 0.1))
        u8 shade mode % 6 (smooth | +-3e38 | FLT_MAX | some NaN / inf | table: 4 raw floats |
           constant: 1 raw float)   u8 depth mode % 5 (4: constant f(0.1, 100))
        u8 sample-row split, u8 x cut, u8 y cut, u8 stride extra, u8 blend split, u8 taa split
        u8 history edits: bit 0 fovlp_reset_history; bit 1 u16 index, raw float into the
           history colour; bit 2 u16 index, raw float into the history depth; bit 3 u16
           index, u8 into the history age
        u8 queries % 4, each: x f(-2W, 3W), y f(-2H, 3H), r f(0, 4 diag), u f(-4, lp_w + 4),
           v f(-4, lp_h + 4), phase u8
   (f(lo, hi) = fz_float: in range 3 in 4, else raw bits or an edge value: NaN, inf, FLT_MAX) */
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"

#include "fuzz_common.h"
#include <math.h>

/* ---- logger: counts errors and remembers the last code ---------------------------------- */
typedef struct lg_state {
    int errors;
    int32_t last;
} lg_state;
static void lg_func(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    lg_state *s = (lg_state *)user;
    (void)msg; (void)line;
    FZ_CHECK(tag && !strcmp(tag, "fovlp"), "logger tag");
    FZ_CHECK(level == FOV_LOG_ERROR || level == FOV_LOG_WARN, "logger level %u", level);
    if (level == FOV_LOG_ERROR) {
        FZ_CHECK(code < 0 && code >= (int32_t)FOV_ERR_UNSUPPORTED, "error log with code %d", code);
        s->errors++;
        s->last = code;
    } else {
        FZ_CHECK(code == 0, "warning with code %d", code);
    }
}
static lg_state g_lg;
static int known(fov_result r) { return r == FOV_OK || (r < 0 && r >= FOV_ERR_UNSUPPORTED); }
/* a failed call with the logger set must have logged its code */
#define CALL(expr, what)                                                                      \
    do {                                                                                      \
        g_lg.errors = 0;                                                                      \
        res = (expr);                                                                         \
        FZ_CHECK(known(res) && fovlp_result_string(res) != NULL, "%s: unknown result %d", what, (int)res); \
        FZ_CHECK(res == FOV_OK || (g_lg.errors >= 1 && g_lg.last == (int32_t)res),            \
                 "%s: returned %d without logging it (%d errors logged, last %d)", what,     \
                 (int)res, g_lg.errors, (int)g_lg.last);                                      \
    } while (0)

static int inr(float x, float lo, float hi) { return x >= lo && x <= hi; }

/* ---- the "renderer" ----------------------------------------------------------------------- */
typedef struct shade_ctx {
    uint32_t mode, dmode, calls;
    float table[4], konst, dconst;
    float W, H;
} shade_ctx;
static uint32_t hash2(float x, float y)
{
    uint32_t a, b, h;
    memcpy(&a, &x, 4); memcpy(&b, &y, 4);
    h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 15; h *= 0x2C1B3C6Du; h ^= h >> 12; h *= 0x297A2D39u; h ^= h >> 15;
    return h;
}
static void shade(float x, float y, float rgb[3], float *depth, void *user)
{
    shade_ctx *s = (shade_ctx *)user;
    uint32_t h = hash2(x, y), ch;
    volatile float zero = 0.0f;
    FZ_CHECK(fz_finite(x) && fz_finite(y) && x >= 0.0f && x < s->W && y >= 0.0f && y < s->H,
             "shade callback at (%g, %g) outside the %gx%g screen", (double)x, (double)y, (double)s->W, (double)s->H);
    s->calls++;
    for (ch = 0; ch < 3; ++ch) {
        uint32_t k = (h >> (8 * ch)) & 0xFFu;
        switch (s->mode) {
        case 0: rgb[ch] = (float)k / 255.0f; break;
        case 1: rgb[ch] = (k & 1u) ? 3e38f : -3e38f; break;
        case 2: rgb[ch] = FLT_MAX; break;
        case 3: rgb[ch] = k == 7u ? zero / zero : (k == 9u ? 1.0f / zero : (float)k); break;
        case 4: rgb[ch] = s->table[k & 3u]; break;
        default: rgb[ch] = s->konst; break;
        }
    }
    if (depth) {
        switch (s->dmode) {
        case 0: *depth = 1.0f + (float)(h & 1023u) / 64.0f; break;
        case 1: *depth = 1e38f; break;
        case 2: *depth = (h & 15u) == 3u ? zero / zero : 4.0f; break;
        case 3: *depth = -2.0f; break;
        default: *depth = s->dconst; break;
        }
    }
}

/* ---- geometry invariants ------------------------------------------------------------------ */
static void check_geo(const fovlp_geometry *g, const fovlp_config *c)
{
    uint64_t slots;
    FZ_CHECK(g->width == c->width && g->height == c->height, "geometry: screen");
    FZ_CHECK(g->lp_w >= 1 && g->lp_h >= 1 && g->lp_w <= 65536u && g->lp_h <= 65536u, "geometry: lp %ux%u", g->lp_w, g->lp_h);
    FZ_CHECK(fz_finite(g->lp_aspect) && g->lp_aspect > 0.0f, "geometry: aspect %g", (double)g->lp_aspect);
    FZ_CHECK(fz_finite(g->L) && g->L >= 0.69f, "geometry: L %g", (double)g->L);
    FZ_CHECK(fz_finite(g->f_px) && g->f_px > 0.0f, "geometry: f_px %g", (double)g->f_px);
    FZ_CHECK(fz_finite(g->r_g) && g->r_g >= 0.0f, "geometry: r_g %g", (double)g->r_g);
    FZ_CHECK(inr(g->G, 0.0f, 0.999f) && fz_finite(g->u_g) && g->u_g >= 0.0f && fz_finite(g->w_c) && g->w_c >= (float)g->lp_w,
             "geometry: G %g u_g %g w_c %g", (double)g->G, (double)g->u_g, (double)g->w_c);
    FZ_CHECK(fz_finite(g->u_max), "geometry: u_max %g", (double)g->u_max);
    FZ_CHECK(g->lp_cols >= 1 && g->lp_cols <= g->lp_w, "geometry: lp_cols %u of %u", g->lp_cols, g->lp_w);
    FZ_CHECK(g->disc_cols <= g->width && g->disc_rows <= g->height && g->disc_w <= g->disc_cols && g->disc_h <= g->disc_rows,
             "geometry: disc buffer");
    FZ_CHECK(g->disc_w == 0 || (g->disc_x0 + g->disc_w <= g->width), "geometry: disc x range");
    FZ_CHECK(g->disc_h == 0 || (g->disc_y0 + g->disc_h <= g->height), "geometry: disc y range");
    FZ_CHECK((g->r_g > 0.0f) == (g->disc_side > 0), "geometry: disc side %u with r_g %g", g->disc_side, (double)g->r_g);
    slots = (uint64_t)g->lp_w * g->lp_h;
    FZ_CHECK(g->lp_slots == slots && g->disc_offset == slots &&
             g->centre_slot == slots + (uint64_t)g->disc_cols * g->disc_rows && g->samples == g->centre_slot + 1u,
             "geometry: slot layout");
}

static void check_cfg(const fovlp_config *c)
{
    FZ_CHECK(fz_finite(c->sigma) && c->sigma >= 1e-3f && fz_finite(c->alpha) && c->alpha > 0.0f && c->alpha <= 16.0f,
             "resolved sigma %g alpha %g", (double)c->sigma, (double)c->alpha);
    FZ_CHECK(inr(c->gaze_angle, 0.0f, 1.5f) && c->no_disc <= 1 && inr(c->match_deg, 0.0f, 89.0f) &&
             c->norm < 2 && c->edge < 2 && c->blend <= 1 && c->blend_end > c->blend_start, "resolved config fields");
    FZ_CHECK(c->taa.phases >= 1 && c->taa.phases <= 256 && c->taa.max_age >= 1 && c->taa.max_age <= 255 &&
             c->taa.clamp < 3 && c->taa.clip_gamma > 0.0f && fz_finite(c->taa.clip_gamma) && c->taa.depth_tol > 0.0f &&
             c->taa.reset_deg > 0.0f && c->taa.periphery > 0.0f, "resolved taa fields");
}

/* ---- reading the config -------------------------------------------------------------------- */
typedef struct acu_in {
    int on, cam;
    fov_eye eye;
    float tan_half_y;
} acu_in;
static void read_config(fz_in *in, fovlp_config *c, acu_in *acu)
{
    uint32_t preset = fz_pick(in, 5), W = fz_u8(in) % 24u + 1u, H = fz_u8(in) % 24u + 1u;
    uint8_t a, b;
    if (preset < 4) {
        *c = fovlp_config_preset(preset, W, H);
    } else {
        memset(c, 0, sizeof *c);
        c->width = W; c->height = H;
    }
    a = fz_u8(in);
    if (a & 1u) c->sigma = fz_float(in, 0.3f, 4.0f);
    if (a & 2u) c->alpha = fz_float(in, 0.25f, 8.0f);
    if (a & 4u) c->gaze_angle = fz_float(in, 0.0f, 0.6f);
    if (a & 8u) c->no_disc = fz_u8(in) % 3u;
    if (a & 16u) c->lp_aspect = fz_float(in, 0.1f, 4.0f);
    if (a & 32u) c->match_deg = fz_float(in, 1.0f, 60.0f);
    if (a & 64u) { c->norm = fz_u8(in) % 3u; c->edge = fz_u8(in) % 3u; }
    if (a & 128u) {
        uint32_t m = fz_pick(in, 3);
        if (m == 0) c->display.fov_y_deg = fz_float(in, 10.0f, 170.0f);
        else if (m == 1) { c->display.pixel_pitch_mm = fz_float(in, 0.05f, 1.0f); c->display.distance_mm = fz_float(in, 100.0f, 2000.0f); }
        else { c->display.axis_dx = fz_float(in, -40.0f, 40.0f); c->display.axis_dy = fz_float(in, -40.0f, 40.0f); }
    }
    b = fz_u8(in);
    if (b & 1u) c->cam_fov_y_deg = fz_float(in, 10.0f, 170.0f);
    if (b & 2u) { c->blend = fz_u8(in) % 3u; c->blend_start = fz_float(in, 0.0f, 1.0f); c->blend_end = fz_float(in, 0.0f, 1.0f); }
    if (b & 4u) c->taa.enable = 1;
    if (b & 8u) {
        c->taa.phases = fz_u8(in);
        c->taa.halton_start = fz_u8(in);
        c->taa.max_age = fz_u8(in);
        c->taa.clamp = fz_u8(in) % 4u;
        c->taa.clip_gamma = fz_float(in, 0.5f, 3.0f);
        c->taa.depth_tol = fz_float(in, 0.0f, 0.1f);
        c->taa.reset_deg = fz_float(in, 0.0f, 10.0f);
        c->taa.periphery = fz_float(in, 0.0f, 1.0f);
        c->taa.jitter_moving = fz_u8(in) % 3u;
        c->taa.thesis_moving = fz_u8(in) % 3u;
    }
    memset(acu, 0, sizeof *acu);
    if (b & 16u) {
        acu->on = 1;
        acu->eye.mar0_arcmin = fz_float(in, 0.0f, 4.0f);
        acu->eye.slope_arcmin = fz_float(in, 0.0f, 4.0f);
        acu->eye.quality = fz_float(in, 0.0f, 4.0f);
        acu->cam = (int)(fz_u8(in) % 2u);
        if (acu->cam) acu->tan_half_y = fz_float(in, 0.05f, 3.0f);
    }
    c->logger.func = lg_func;
    c->logger.user = &g_lg;
}

/* range of the finite values of a channel set; *all_finite = 0 when any is NaN / inf */
typedef struct vrange {
    float lo[3], hi[3], amax;
    int all_finite, any;
} vrange;
static void vr_init(vrange *r)
{
    int c;
    for (c = 0; c < 3; ++c) { r->lo[c] = FLT_MAX; r->hi[c] = -FLT_MAX; }
    r->amax = 0.0f; r->all_finite = 1; r->any = 0;
}
static void vr_add(vrange *r, const float *v)
{
    int c;
    for (c = 0; c < 3; ++c) {
        if (!fz_finite(v[c])) { r->all_finite = 0; continue; }
        if (v[c] < r->lo[c]) r->lo[c] = v[c];
        if (v[c] > r->hi[c]) r->hi[c] = v[c];
        if (v[c] > r->amax) r->amax = v[c];
        if (-v[c] > r->amax) r->amax = -v[c];
        r->any = 1;
    }
}
/* v inside [lo, hi] up to the rounding of a convex combination */
static int vr_inside(const vrange *r, const float *v)
{
    int c;
    for (c = 0; c < 3; ++c) {
        float slack = 1e-5f * r->amax + 1e-30f;
        if (!(v[c] >= r->lo[c] - slack && v[c] <= r->hi[c] + slack)) return 0;
    }
    return 1;
}

#define MAX_SAMPLES_FUZZ 20000u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = fz_begin(data, size);
    fovlp_config cfg, rc;
    fovlp_geometry geo;
    fovlp_ctx ctx;
    fov_result res;
    size_t bytes = 0, k;
    void *mem;
    uint32_t W, H, frames, f, R, x, y;
    float *rgb = 0, *sdep = 0, *img = 0, *dep = 0, *img2 = 0, *dep2 = 0, *bl = 0, *bl2 = 0;
    float *hist[2], *hdep[2], *tout2, *tdep2;
    uint8_t *age[2], *tage2;
    fovlp_sample *smp = 0, *smp2 = 0;
    int ping = 0, big;
    size_t npix, img2_len = 0;
    uint32_t stride2 = 0;
    fovlp_camera base;
    shade_ctx sc;
    acu_in acu;

    memset(&g_lg, 0, sizeof g_lg);
    FZ_CHECK(fovlp_preset_name(data && size ? data[0] : 0u) != NULL, "preset_name");
    read_config(&in, &cfg, &acu);
    if (acu.on) { /* fovlp_config_acuity: writes *cfg only on success, finite parameters */
        fovlp_config before = cfg;
        fovlp_camera ac;
        memset(&ac, 0, sizeof ac);
        ac.tan_half_y = acu.tan_half_y;
        CALL(fovlp_config_acuity(&cfg, acu.cam ? &ac : NULL, &acu.eye), "config_acuity");
        if (res != FOV_OK)
            FZ_CHECK(memcmp(&before, &cfg, sizeof cfg) == 0, "config_acuity wrote *cfg and failed");
        else
            FZ_CHECK(inr(cfg.sigma, 1e-3f, 1e30f) && inr(cfg.alpha, 1.0f, 8.0f) &&
                     inr(cfg.gaze_angle, 0.0f, 1.5f) && inr(cfg.lp_aspect, 1.0f / 65536.0f, 65536.0f) &&
                     cfg.no_disc == 0 && cfg.norm == FOVLP_NORM_DIAGONAL && cfg.edge == FOVLP_EDGE_LOG_R,
                     "config_acuity: sigma %g alpha %g gaze_angle %g lp_aspect %g", (double)cfg.sigma,
                     (double)cfg.alpha, (double)cfg.gaze_angle, (double)cfg.lp_aspect);
    }
    W = cfg.width; H = cfg.height; npix = (size_t)W * H;

    CALL(fovlp_config_resolve(&cfg, &rc), "config_resolve");
    if (res == FOV_OK) check_cfg(&rc);
    CALL(fovlp_memory_size(&cfg, &bytes), "memory_size");
    if (res != FOV_OK) {
        /* init must refuse the same config */
        fovlp_ctx c2;
        uint8_t m2[64];
        CALL(fovlp_init(&c2, &cfg, m2, sizeof m2), "init of a rejected config");
        FZ_CHECK(res != FOV_OK, "memory_size failed but init accepted the config");
        return 0;
    }
    FZ_CHECK(bytes > 0 && bytes < ((size_t)1 << 31), "memory_size %zu", bytes);
    if (bytes > ((size_t)8 << 20)) return 0;   /* a huge LP table (sigma near 1e-3): skip */
    mem = fz_alloc(bytes, 0x5A);
    if (bytes > 16) {
        CALL(fovlp_init(&ctx, &cfg, mem, bytes - 1), "init with one byte short");
        FZ_CHECK(res == FOV_ERR_TOO_SMALL, "init accepted memory_size - 1 bytes (%d)", (int)res);
    }
    CALL(fovlp_init(&ctx, &cfg, mem, bytes), "init");
    FZ_CHECK(res == FOV_OK, "init refused what memory_size accepted (%d)", (int)res);
    FZ_CHECK(fz_canary_ok(mem, bytes), "init wrote past its memory");
    check_geo(&ctx.geo, &ctx.cfg);
    check_cfg(&ctx.cfg);
    big = ctx.geo.samples > MAX_SAMPLES_FUZZ;
    if (!big) {
        rgb = (float *)fz_alloc(sizeof(float) * 3u * ctx.geo.samples, 0);
        sdep = (float *)fz_alloc(sizeof(float) * ctx.geo.samples, 0);
        smp = (fovlp_sample *)fz_alloc(sizeof(fovlp_sample) * ctx.geo.samples, 0);
        smp2 = (fovlp_sample *)fz_alloc(sizeof(fovlp_sample) * ctx.geo.samples, 0);
    }
    img = (float *)fz_alloc(sizeof(float) * 3u * npix, 0);
    dep = (float *)fz_alloc(sizeof(float) * npix, 0);
    dep2 = (float *)fz_alloc(sizeof(float) * npix, 0);
    bl = (float *)fz_alloc(sizeof(float) * 3u * npix, 0);
    bl2 = (float *)fz_alloc(sizeof(float) * 3u * npix, 0);
    for (k = 0; k < 2; ++k) {
        hist[k] = (float *)fz_alloc(sizeof(float) * 3u * npix, 0);
        hdep[k] = (float *)fz_alloc(sizeof(float) * npix, 0);
        age[k] = (uint8_t *)fz_alloc(npix, 0);
    }
    tout2 = (float *)fz_alloc(sizeof(float) * 3u * npix, 0);
    tdep2 = (float *)fz_alloc(sizeof(float) * npix, 0);
    tage2 = (uint8_t *)fz_alloc(npix, 0);
    memset(&base, 0, sizeof base);
    base.right[0] = 1.0f; base.up[1] = 1.0f; base.fwd[2] = 1.0f; base.tan_half_y = 0.5f;
    memset(&sc, 0, sizeof sc);
    sc.W = (float)W; sc.H = (float)H;

    frames = fz_u8(&in) % 5u + 1u;
    for (f = 0; f < frames; ++f) {
        fov_gaze gz;
        fovlp_camera cam = base, *camp = 0;
        uint32_t cm, split, xc, yc, extra, bsplit, tsplit, nq, q, ex;
        float diag = sqrtf((float)W * (float)W + (float)H * (float)H);
        size_t cnt = 0, cnt2 = 0;
        vrange sr;
        gz.x = fz_float(&in, -4.0f, (float)W + 4.0f);
        gz.y = fz_float(&in, -4.0f, (float)H + 4.0f);
        cm = fz_pick(&in, 4);
        if (cm == 1) camp = &cam;
        else if (cm == 2) {
            for (k = 0; k < 3; ++k) base.pos[k] += fz_float(&in, -0.2f, 0.2f);
            base.fwd[0] += fz_float(&in, -0.05f, 0.05f);
            cam = base; camp = &cam;
        } else if (cm == 3) {
            for (k = 0; k < 3; ++k) cam.pos[k] = fz_float(&in, -1e3f, 1e3f);
            cam.tan_half_y = fz_float(&in, 0.1f, 2.0f);
            for (k = 0; k < 3; ++k) {
                cam.right[k] += fz_float(&in, -0.1f, 0.1f);
                cam.up[k] += fz_float(&in, -0.1f, 0.1f);
                cam.fwd[k] += fz_float(&in, -0.1f, 0.1f);
            }
            camp = &cam;
        }
        sc.mode = fz_pick(&in, 6);
        if (sc.mode == 4) for (k = 0; k < 4; ++k) sc.table[k] = fz_raw_float(&in);
        if (sc.mode == 5) sc.konst = fz_raw_float(&in);
        sc.dmode = fz_pick(&in, 5);
        if (sc.dmode == 4) sc.dconst = fz_float(&in, 0.1f, 100.0f);
        split = fz_u8(&in); xc = fz_u8(&in); yc = fz_u8(&in); extra = fz_u8(&in) % 8u;
        bsplit = fz_u8(&in); tsplit = fz_u8(&in);
        /* the caller's side of the history: a reset, or bad values in the history buffers */
        ex = fz_u8(&in);
        if (ex & 1u) fovlp_reset_history(&ctx);
        if (ex & 2u) { size_t i = fz_u16(&in) % (3u * npix); hist[ping][i] = fz_raw_float(&in); }
        if (ex & 4u) { size_t i = fz_u16(&in) % npix; hdep[ping][i] = fz_raw_float(&in); }
        if (ex & 8u) { size_t i = fz_u16(&in) % npix; age[ping][i] = fz_u8(&in); }

        CALL(fovlp_begin_frame(&ctx, gz, camp), "begin_frame");
        if (res != FOV_OK) {
            FZ_CHECK(res == FOV_ERR_NOT_FINITE || res == FOV_ERR_DEGENERATE || res == FOV_ERR_INVALID_ARG,
                     "begin_frame: unexpected error %d", (int)res);
            continue;
        }
        FZ_CHECK(fz_canary_ok(mem, bytes), "begin_frame wrote past the context memory");
        check_geo(&ctx.geo, &ctx.cfg);
        FZ_CHECK(inr(ctx.gaze.x, 0.0f, (float)W) && inr(ctx.gaze.y, 0.0f, (float)H), "gaze not clamped to the screen");
        FZ_CHECK(ctx.jit_u >= 0.0f && ctx.jit_u < 1.0f && ctx.jit_v >= 0.0f && ctx.jit_v < 1.0f, "jitter %g %g",
                 (double)ctx.jit_u, (double)ctx.jit_v);
        for (k = 0; k < ctx.geo.lp_w; ++k)
            FZ_CHECK(fz_finite(ctx.rho[k]) && ctx.rho[k] >= 1.0f && (k == 0 || ctx.rho[k] >= ctx.rho[k - 1]),
                     "rho[%zu] = %g", k, (double)ctx.rho[k]);
        R = fovlp_sample_rows(&ctx);
        FZ_CHECK(R == ctx.geo.lp_h + ctx.geo.disc_h + 1u, "sample rows %u", R);

        /* queries: mappings, density, spacing, eccentricity, jitter */
        nq = fz_u8(&in) % 4u;
        for (q = 0; q < nq; ++q) {
            float qx = fz_float(&in, -2.0f * (float)W, 3.0f * (float)W), qy = fz_float(&in, -2.0f * (float)H, 3.0f * (float)H);
            float qr = fz_float(&in, 0.0f, 4.0f * diag);
            float qu = fz_float(&in, -4.0f, (float)ctx.geo.lp_w + 4.0f), qv = fz_float(&in, -4.0f, (float)ctx.geo.lp_h + 4.0f);
            uint32_t ph = fz_u8(&in);
            float u, v, sx, sy, d, rad, ang, e, ou, ov;
            int fin = fz_finite(qx) && fz_finite(qy);
            CALL(fovlp_screen_to_lp(&ctx, qx, qy, &u, &v), "screen_to_lp");
            FZ_CHECK(res == FOV_OK || (!fin && res == FOV_ERR_NOT_FINITE), "screen_to_lp(%g, %g): %d", (double)qx, (double)qy, (int)res);
            if (res == FOV_OK) {
                FZ_CHECK(fz_finite(u) && fz_finite(v) && v >= 0.0f && v < (float)ctx.geo.lp_h,
                         "screen_to_lp(%g, %g) = (%g, %g)", (double)qx, (double)qy, (double)u, (double)v);
                if (ctx.cfg.alpha >= 1.0f && ctx.cfg.alpha <= 3.0f) {
                    float dx = qx - ctx.gaze.x, dy = qy - ctx.gaze.y, r = sqrtf(dx * dx + dy * dy);
                    if (r >= 2.0f && r <= 2.0f * diag && u + ctx.geo.u_g >= 0.0f) {
                        CALL(fovlp_lp_to_screen(&ctx, u, v, &sx, &sy), "lp_to_screen (round trip)");
                        FZ_CHECK(res == FOV_OK && fabsf(sx - qx) <= 1e-3f * r + 1e-3f && fabsf(sy - qy) <= 1e-3f * r + 1e-3f,
                                 "round trip (%g, %g) -> (%g, %g) -> (%g, %g)", (double)qx, (double)qy, (double)u, (double)v,
                                 (double)sx, (double)sy);
                    }
                }
            }
            CALL(fovlp_lp_to_screen(&ctx, qu, qv, &sx, &sy), "lp_to_screen");
            if (res == FOV_OK) FZ_CHECK(fz_finite(sx) && fz_finite(sy), "lp_to_screen(%g, %g) = (%g, %g)", (double)qu, (double)qv, (double)sx, (double)sy);
            else FZ_CHECK(res == FOV_ERR_LIMIT || res == FOV_ERR_INVALID_ARG || res == FOV_ERR_NOT_FINITE, "lp_to_screen: %d", (int)res);
            d = fovlp_density(&ctx, qx, qy);
            FZ_CHECK(fz_finite(d) && d >= 0.0f, "density(%g, %g) = %g", (double)qx, (double)qy, (double)d);
            CALL(fovlp_spacing(&ctx, qr, &rad, &ang), "spacing");
            if (res == FOV_OK) FZ_CHECK(fz_finite(rad) && fz_finite(ang) && rad >= 0.0f && ang > 0.0f,
                                        "spacing(%g) = %g, %g", (double)qr, (double)rad, (double)ang);
            else FZ_CHECK(res == FOV_ERR_LIMIT || (res == FOV_ERR_NOT_FINITE && !fz_finite(qr)), "spacing(%g): %d", (double)qr, (int)res);
            if (fin) {
                e = fovlp_ecc_deg(&ctx.ecc, qx, qy);
                FZ_CHECK(fz_finite(e) && e >= 0.0f && e <= 180.0f, "ecc_deg(%g, %g) = %g", (double)qx, (double)qy, (double)e);
            }
            e = fovlp_ecc_ppd(&ctx.ecc);
            FZ_CHECK(fz_finite(e) && e >= 0.0f, "ecc_ppd %g", (double)e);
            CALL(fovlp_jitter(&ctx.cfg, ph, &ou, &ov), "jitter");
            FZ_CHECK(res == FOV_OK && ou >= 0.0f && ou < 1.0f && ov >= 0.0f && ov < 1.0f, "jitter(%u) = %g, %g", ph,
                     (double)ou, (double)ov);
            CALL(fovlp_geometry_get(&ctx.cfg, gz, &geo), "geometry_get");
            FZ_CHECK(res == FOV_OK, "geometry_get refused a gaze begin_frame took: %d", (int)res);
            check_geo(&geo, &ctx.cfg);
        }
        if (big) continue;

        /* sampling: count query, array (whole and split), callback (split) */
        CALL(fovlp_samples(&ctx, 0, R, NULL, 0, &cnt), "samples count");
        FZ_CHECK(res == FOV_OK && cnt >= 1 && cnt <= ctx.geo.samples, "sample count %zu of %u slots", cnt, ctx.geo.samples);
        if (cnt > 1) {
            CALL(fovlp_samples(&ctx, 0, R, smp, cnt - 1, &cnt2), "samples, cap one short");
            FZ_CHECK(res == FOV_ERR_TOO_SMALL, "samples accepted a short array (%d)", (int)res);
        }
        CALL(fovlp_samples(&ctx, 0, R, smp, cnt, &cnt2), "samples");
        FZ_CHECK(res == FOV_OK && cnt2 == cnt, "samples: %zu then %zu", cnt, cnt2);
        FZ_CHECK(fz_canary_ok(smp, sizeof(fovlp_sample) * ctx.geo.samples), "samples wrote past the array");
        for (k = 0; k < cnt; ++k) {
            FZ_CHECK(fz_finite(smp[k].x) && fz_finite(smp[k].y) && smp[k].x >= 0.0f && smp[k].x < (float)W &&
                     smp[k].y >= 0.0f && smp[k].y < (float)H && smp[k].slot < ctx.geo.samples,
                     "sample %zu at (%g, %g) slot %u", k, (double)smp[k].x, (double)smp[k].y, smp[k].slot);
            FZ_CHECK(k == 0 || smp[k].slot != smp[k - 1].slot, "sample slot repeated");
        }
        {
            uint32_t s = split % (R + 1u);
            size_t c1 = 0, c2 = 0;
            CALL(fovlp_samples(&ctx, 0, s, smp2, ctx.geo.samples, &c1), "samples [0, s)");
            FZ_CHECK(res == FOV_OK, "samples [0, s): %d", (int)res);
            CALL(fovlp_samples(&ctx, s, R, smp2 + c1, ctx.geo.samples - c1, &c2), "samples [s, R)");
            FZ_CHECK(res == FOV_OK && c1 + c2 == cnt, "split samples %zu + %zu != %zu", c1, c2, cnt);
            FZ_CHECK(!memcmp(smp, smp2, sizeof(fovlp_sample) * cnt), "samples differ with a row split at %u", s);
            CALL(fovlp_samples(&ctx, s + 1u, s, smp2, 0, &c1), "samples r0 > r1");
            FZ_CHECK(res == FOV_ERR_INVALID_ARG, "samples accepted r0 > r1");
            /* callback form, split the same way */
            {
                uint64_t shaded = 0;
                sc.calls = 0;
                CALL(fovlp_shade_rows(&ctx, 0, s, shade, &sc, rgb, sdep, &shaded),
                     "shade_rows [0, s)");
                FZ_CHECK(res == FOV_OK, "shade_rows: %d", (int)res);
                CALL(fovlp_shade_rows(&ctx, s, R, shade, &sc, rgb, sdep, &shaded),
                     "shade_rows [s, R)");
                FZ_CHECK(res == FOV_OK && shaded == cnt && sc.calls == cnt, "shade_rows: %llu shaded, %u calls, %zu samples",
                         (unsigned long long)shaded, sc.calls, cnt);
            }
        }
        FZ_CHECK(fz_canary_ok(rgb, sizeof(float) * 3u * ctx.geo.samples) &&
                     fz_canary_ok(sdep, sizeof(float) * ctx.geo.samples),
                 "shade_rows wrote past the sample buffers");
        vr_init(&sr);
        for (k = 0; k < cnt; ++k) vr_add(&sr, rgb + 3u * smp[k].slot);
        {
            fovlp_counts cn;
            CALL(fovlp_count_samples(&ctx, &cn), "count_samples");
            FZ_CHECK(res == FOV_OK && cn.shaded == cnt && cn.lp_shaded <= cn.lp_dispatched && cn.disc_shaded <= cn.disc_dispatched &&
                     fz_finite(cn.dispatched_pct) && fz_finite(cn.shaded_pct) && cn.shaded_pct >= 0.0f,
                     "count_samples: shaded %llu of %zu", (unsigned long long)cn.shaded, cnt);
        }

        /* reconstruction: rows (reference), then tiles with an odd stride, every other frame
       without depth (the colours must not change) */
        {
            int with_depth = (f & 1u) == 0u;
            uint32_t cx = xc % (W + 1u), cy = yc % (H + 1u), t;
            CALL(fovlp_reconstruct_rows(&ctx, rgb, sdep, 0, H, img, 0, dep), "reconstruct_rows");
            FZ_CHECK(res == FOV_OK, "reconstruct_rows: %d", (int)res);
            FZ_CHECK(fz_canary_ok(img, sizeof(float) * 3u * npix) && fz_canary_ok(dep, sizeof(float) * npix),
                     "reconstruct_rows wrote past the image");
            if (sr.all_finite)
                for (k = 0; k < npix; ++k)
                    FZ_CHECK(fz_finite_n(img + 3u * k, 3) && vr_inside(&sr, img + 3u * k),
                             "pixel %zu = (%g, %g, %g) outside the shaded range [%g, %g]", k, (double)img[3 * k],
                             (double)img[3 * k + 1], (double)img[3 * k + 2], (double)sr.lo[0], (double)sr.hi[0]);
            stride2 = 3u * W + extra;
            img2_len = (size_t)(H - 1u) * stride2 + 3u * W;
            img2 = (float *)fz_alloc(sizeof(float) * img2_len, 0x77);
            memset(dep2, 0x77, sizeof(float) * npix);
            for (t = 0; t < 4; ++t) {
                uint32_t x0 = (t & 1u) ? cx : 0u, x1 = (t & 1u) ? W : cx, y0 = (t & 2u) ? cy : 0u, y1 = (t & 2u) ? H : cy;
                CALL(fovlp_reconstruct_tile(&ctx, rgb, with_depth ? sdep : NULL, x0, y0, x1, y1,
                                            img2, stride2, with_depth ? dep2 : NULL),
                     "reconstruct_tile");
                FZ_CHECK(res == FOV_OK, "reconstruct_tile: %d", (int)res);
            }
            FZ_CHECK(fz_canary_ok(img2, sizeof(float) * img2_len) && fz_canary_ok(dep2, sizeof(float) * npix),
                     "reconstruct_tile wrote past the image (stride %u)", stride2);
            for (y = 0; y < H; ++y)
                for (x = 0; x < W; ++x) {
                    FZ_CHECK(!memcmp(img + 3u * ((size_t)y * W + x), img2 + (size_t)y * stride2 + 3u * x, 3 * sizeof(float)),
                             "tile split (%u, %u) stride %u changed pixel (%u, %u)", cx, cy, stride2, x, y);
                    if (with_depth)
                        FZ_CHECK(!memcmp(dep + (size_t)y * W + x, dep2 + (size_t)y * W + x, sizeof(float)),
                                 "tile split changed the depth of pixel (%u, %u)", x, y);
                }
            free(img2); img2 = 0;
            CALL(fovlp_reconstruct_tile(&ctx, rgb, sdep, 0, 0, W + 1u, H, img, 0, NULL),
                 "reconstruct_tile out of range");
            FZ_CHECK(res == FOV_ERR_INVALID_ARG, "reconstruct_tile accepted x1 = W + 1");
        }

        /* blend: whole and split at a row */
        {
            uint32_t s = bsplit % (H + 1u);
            vrange ir;
            CALL(fovlp_blend_rows(&ctx, img, 0, H, bl), "blend_rows");
            FZ_CHECK(res == FOV_OK, "blend_rows: %d", (int)res);
            CALL(fovlp_blend_rows(&ctx, img, 0, s, bl2), "blend_rows [0, s)");
            CALL(fovlp_blend_rows(&ctx, img, s, H, bl2), "blend_rows [s, H)");
            FZ_CHECK(!memcmp(bl, bl2, sizeof(float) * 3u * npix), "blend depends on the row split at %u", s);
            FZ_CHECK(fz_canary_ok(bl, sizeof(float) * 3u * npix) && fz_canary_ok(bl2, sizeof(float) * 3u * npix),
                     "blend wrote past its image");
            vr_init(&ir);
            for (k = 0; k < npix; ++k) vr_add(&ir, img + 3u * k);
            if (ir.all_finite)
                for (k = 0; k < npix; ++k)
                    FZ_CHECK(fz_finite_n(bl + 3u * k, 3) && vr_inside(&ir, bl + 3u * k), "blend pixel %zu outside the image's range", k);
        }

        /* TAA: whole (ping-pong history) and split into a second output */
        if (ctx.cfg.taa.enable) {
            fovlp_taa_io io;
            fovlp_taa_stats st;
            uint32_t s = tsplit % (H + 1u), hv = ctx.history_valid, still = !ctx.moving;
            vrange tr;
            const float *cur = (f & 2u) ? bl : img;
            memset(&st, 0, sizeof st);
            io.cur_rgb = cur; io.cur_depth = dep;
            io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
            io.out_rgb = hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
            CALL(fovlp_taa_rows(&ctx, &io, 0, H, &st), "taa_rows");
            FZ_CHECK(res == FOV_OK && st.pixels == npix && st.rejected <= npix, "taa_rows: %d", (int)res);
            io.out_rgb = tout2; io.out_depth = tdep2; io.out_age = tage2;
            CALL(fovlp_taa_rows(&ctx, &io, 0, s, NULL), "taa_rows [0, s)");
            CALL(fovlp_taa_rows(&ctx, &io, s, H, NULL), "taa_rows [s, H)");
            FZ_CHECK(!memcmp(tout2, hist[1 - ping], sizeof(float) * 3u * npix) && !memcmp(tage2, age[1 - ping], npix),
                     "TAA depends on the row split at %u", s);
            io.out_rgb = (float *)(void *)(size_t)cur;   /* aliasing the input: refused */
            CALL(fovlp_taa_rows(&ctx, &io, 0, H, NULL), "taa_rows aliased");
            FZ_CHECK(res == FOV_ERR_INVALID_ARG, "taa_rows accepted out_rgb == cur_rgb");
            for (k = 0; k < 2; ++k)
                FZ_CHECK(fz_canary_ok(hist[k], sizeof(float) * 3u * npix) && fz_canary_ok(hdep[k], sizeof(float) * npix) &&
                         fz_canary_ok(age[k], npix), "TAA wrote past its buffers");
            FZ_CHECK(fz_canary_ok(tout2, sizeof(float) * 3u * npix) && fz_canary_ok(tage2, npix), "TAA wrote past its buffers");
            vr_init(&tr);
            for (k = 0; k < npix; ++k) { vr_add(&tr, cur + 3u * k); if (hv) vr_add(&tr, hist[ping] + 3u * k); }
            for (k = 0; k < npix; ++k) {
                const float *o = hist[1 - ping] + 3u * k, *cc = cur + 3u * k, *pp = hist[ping] + 3u * k;
                uint32_t ch, a = age[1 - ping][k];
                FZ_CHECK(fz_finite_n(o, 3), "TAA wrote a non-finite colour at pixel %zu: (%g, %g, %g)", k, (double)o[0],
                         (double)o[1], (double)o[2]);
                FZ_CHECK(a >= 1 && a <= ctx.cfg.taa.max_age, "TAA age %u (max %u)", a, ctx.cfg.taa.max_age);
                for (ch = 0; ch < 3; ++ch) {
                    FZ_CHECK(fabsf(o[ch]) <= 3.0f * tr.amax * (1.0f + 1e-5f) + 1e-30f || fabsf(o[ch]) <= tr.amax,
                             "TAA output %g beyond 3 max |input| = 3 * %g", (double)o[ch], (double)tr.amax);
                    if (hv && still && ctx.cfg.taa.clamp == FOVLP_CLAMP_NONE && fz_finite(cc[ch]) && fz_finite(pp[ch])) {
                        float lo = fminf(cc[ch], pp[ch]), hi = fmaxf(cc[ch], pp[ch]);
                        FZ_CHECK(o[ch] >= lo && o[ch] <= hi, "TAA still: output %g outside [history %g, current %g] at pixel %zu",
                                 (double)o[ch], (double)pp[ch], (double)cc[ch], k);
                    }
                }
            }
            ping = 1 - ping;
        }
        FZ_CHECK(fz_canary_ok(mem, bytes), "context memory overwritten");
    }

    free(mem); free(rgb); free(sdep); free(smp); free(smp2); free(img); free(dep); free(dep2);
    free(bl); free(bl2);
    for (k = 0; k < 2; ++k) { free(hist[k]); free(hdep[k]); free(age[k]); }
    free(tout2); free(tdep2); free(tage2);
    return 0;
}
