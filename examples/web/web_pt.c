/* web_pt.c - glue of the browser demo's fovpt module (examples/web): a Cornell box (the scene
   of examples/pt_scenes.h, built here without malloc) path traced with LAYERS (Axblad 2020;
   hollow lattices, so the stride-1 layer's pixels take UNIFORM's samples) or SELECTIVE
   supersampling (Kim et al. 2021, Whitted mode as in their paper), progressively accumulated,
   and a full-resolution UNIFORM reference (LAYERS: path tracing at the layers' 4 spp;
   SELECTIVE: Whitted at 16 spp, supersampling everywhere). A worker renders rows [y0, y1):
   it traces (and refines) a halo of rows around them, which the resolve reads (the lattice
   taps above and below, the neighbours' presamples), so the image does not depend on the
   split. Accumulation restarts when the camera or the gaze moves (fovpt_set_view), or on
   pt_restart. Not part of the library. It calls fovpt.h's public API, with one exception:
   the layers overlay (pt_render with overlay 1) reads fields of fovpt_ctx that have no getter
   (ecc, lay, layer_trace_deg: which layer traces each pixel); the share of pixels traced comes
   from fovpt_stats and the fovea radius from fovpt_config_resolve. */
#ifndef WEB_NATIVE_LIBM /* native_bench.c may use libm instead */
#define FOV_NO_LIBM
#endif
#define FOV_ASSERT(c) ((void)0)
#include "web_rt.h"
#define FOVPT_IMPLEMENTATION
#include "../../fovpt.h"

#define PT_MAX_SHAPES 24
#define PT_HALO_LAYERS 16u  /* > 3 lattice steps of the coarsest layer (stride 4) */
#define PT_HALO_SEL 4u
#define PT_MAX_MARGIN 15.0f  /* the gaze filter's default margin cap (max_margin_deg) */

typedef struct pt_view_state {
    fovpt_ctx ctx;
    uint32_t frame;          /* frames accumulated since the last reset */
    float last[5];           /* gaze x, y, camera angle of the last frame; [3] valid */
} pt_view_state;

static struct {
    fovpt_shape shapes[PT_MAX_SHAPES];
    uint32_t num_shapes;
    fovpt_material mats[8];
    uint32_t num_mats;
    fovpt_scene scene;
    fovpt_camera cam;
    float base_pos[3];
    uint32_t w, h, ignore_gaze, method;
    float fovea_deg;         /* stride-1 layer's radius (LAYERS) or e_f (SELECTIVE), resolved */
    float margin_deg;        /* the gaze margin the foveated view's context has */
    float fovea_now;         /* fovea_deg of that context's config (with the margin) */
    fovpt_config cfg;        /* the foveated view's config without the margin */
    void *mem0;              /* its memory (sized for any margin up to PT_MAX_MARGIN) */
    size_t mem0_size;
    pt_view_state v[2];      /* 0 foveated, 1 reference */
    uint8_t *rgb8, *rgba, *tint;
} S;

WEB_EXPORT(rgba_ptr) uint8_t *rgba_ptr(void);
uint8_t *rgba_ptr(void) { return S.rgba; }

static uint32_t pt_mat(uint32_t type, float r, float g, float b)
{
    fovpt_material *m = &S.mats[S.num_mats];
    fovpt_material_init(m);
    m->type = type;
    m->albedo[0] = r; m->albedo[1] = g; m->albedo[2] = b;
    return S.num_mats++;
}
static void pt_quad(float x, float y, float z, float ux, float uy, float uz, float vx, float vy,
                    float vz, uint32_t m)
{
    float c[3], u[3], v[3];
    c[0] = x; c[1] = y; c[2] = z; u[0] = ux; u[1] = uy; u[2] = uz; v[0] = vx; v[1] = vy; v[2] = vz;
    fovpt_shape_quad(&S.shapes[S.num_shapes++], c, u, v, m);
}
static void pt_box(float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m)
{
    float lo[3], hi[3];
    lo[0] = x0; lo[1] = y0; lo[2] = z0; hi[0] = x1; hi[1] = y1; hi[2] = z1;
    fovpt_shape_box(&S.shapes[S.num_shapes++], lo, hi, m);
}

static fov_result pt_cornell(void)
{
    fovpt_scene_desc d;
    size_t bytes = 0;
    void *mem;
    fov_result r;
    uint32_t white = pt_mat(FOVPT_MAT_LAMBERT, 0.73f, 0.73f, 0.73f);
    uint32_t red = pt_mat(FOVPT_MAT_LAMBERT, 0.65f, 0.05f, 0.05f);
    uint32_t green = pt_mat(FOVPT_MAT_LAMBERT, 0.12f, 0.45f, 0.15f);
    uint32_t light = pt_mat(FOVPT_MAT_LAMBERT, 0.0f, 0.0f, 0.0f);
    uint32_t phong = pt_mat(FOVPT_MAT_PHONG, 0.2f, 0.3f, 0.6f);
    uint32_t mirror = pt_mat(FOVPT_MAT_MIRROR, 0.9f, 0.9f, 0.9f);
    S.mats[light].emission[0] = S.mats[light].emission[1] = S.mats[light].emission[2] = 15.0f;
    S.mats[phong].specular[0] = S.mats[phong].specular[1] = S.mats[phong].specular[2] = 0.3f;
    S.mats[phong].exponent = 40.0f;
    pt_quad(-1, 0, -1, 0, 0, 2, 2, 0, 0, white);   /* floor */
    pt_quad(-1, 2, -1, 2, 0, 0, 0, 0, 2, white);   /* ceiling */
    pt_quad(-1, 0, 1, 0, 2, 0, 2, 0, 0, white);    /* back */
    pt_quad(-1, 0, -1, 0, 2, 0, 0, 0, 2, red);     /* left */
    pt_quad(1, 0, -1, 0, 0, 2, 0, 2, 0, green);    /* right */
    pt_quad(-0.25f, 1.999f, -0.25f, 0.5f, 0, 0, 0, 0, 0.5f, light);
    pt_box(-0.7f, 0.0f, -0.1f, -0.15f, 1.2f, 0.5f, white);
    pt_box(0.15f, 0.0f, -0.6f, 0.7f, 0.6f, -0.05f, white);
    fovpt_shape_sphere(&S.shapes[S.num_shapes++], 0.42f, 0.85f, -0.32f, 0.25f, phong);
    fovpt_shape_sphere(&S.shapes[S.num_shapes++], -0.45f, 1.45f, 0.2f, 0.25f, mirror);
    fovpt_scene_desc_init(&d);
    d.shapes = S.shapes; d.num_shapes = S.num_shapes;
    d.materials = S.mats; d.num_materials = S.num_mats;
    if ((r = fovpt_scene_size(&d, &bytes)) != FOV_OK) return r;
    if (!(mem = web_alloc(bytes))) return FOV_ERR_TOO_SMALL;
    return fovpt_scene_build(&S.scene, &d, mem, bytes);
}

static fov_result pt_view_init(pt_view_state *v, const fovpt_config *cfg)
{
    size_t bytes = 0;
    void *mem;
    fov_result r;
    fov_gaze g;
    fovpt_config wide;
    size_t b2 = 0;
    g.x = 0.5f * (float)S.w; g.y = 0.5f * (float)S.h;
    if ((r = fovpt_memory_size(cfg, &S.cam, &bytes)) != FOV_OK) return r;
    /* room for the widest margin too (pt_render re-initialises with the margin's config) */
    if ((r = fovpt_config_gaze_margin(cfg, PT_MAX_MARGIN, &wide)) != FOV_OK) return r;
    if ((r = fovpt_memory_size(&wide, &S.cam, &b2)) != FOV_OK) return r;
    if (b2 > bytes) bytes = b2;
    if (!(mem = web_alloc(bytes ? bytes : 16))) return FOV_ERR_TOO_SMALL;
    if (v == &S.v[0]) { S.cfg = *cfg; S.mem0 = mem; S.mem0_size = bytes; S.margin_deg = 0.0f; }
    v->frame = 0;
    v->last[3] = 0.0f;
    return fovpt_init(&v->ctx, cfg, &S.scene, &S.cam, g, mem, bytes);
}

/* the fovea radius of a config, resolved: the stride-1 layer's (LAYERS) or e_f (SELECTIVE) */
static fov_result pt_fovea_of(const fovpt_config *cfg, float *deg)
{
    fovpt_config res;
    fov_result r;
    if ((r = fovpt_config_resolve(cfg, &res)) != FOV_OK) return r;
    *deg = res.method == FOVPT_METHOD_LAYERS ? res.layers.layer[res.layers.count - 1u].radius_deg
                                             : res.selective.e_deg[0];
    return FOV_OK;
}

/* w x h; method 1 LAYERS or 3 SELECTIVE; ignore_gaze as in web_sdf.c */
WEB_EXPORT(pt_setup) int pt_setup(uint32_t w, uint32_t h, uint32_t method, uint32_t ignore_gaze);
int pt_setup(uint32_t w, uint32_t h, uint32_t method, uint32_t ignore_gaze)
{
    fovpt_config cfg = fovpt_config_default(), ref;
    fov_result r;
    size_t npx;
    web_heap_reset();
    memset(&S, 0, sizeof S);
    if (w == 0 || h == 0 || w > 4096 || h > 4096) return FOV_ERR_INVALID_ARG;
    if (method != FOVPT_METHOD_LAYERS && method != FOVPT_METHOD_SELECTIVE) return FOV_ERR_INVALID_ARG;
    S.w = w; S.h = h; S.ignore_gaze = ignore_gaze; S.method = method;
    if ((r = pt_cornell()) != FOV_OK) return r;
    fovpt_camera_init(&S.cam, w, h);
    S.cam.pos[0] = 0.0f; S.cam.pos[1] = 1.0f; S.cam.pos[2] = -3.4f;
    S.cam.target[0] = 0.0f; S.cam.target[1] = 1.0f; S.cam.target[2] = 0.0f;
    S.cam.fov_y_deg = 40.0f;
    memcpy(S.base_pos, S.cam.pos, sizeof S.base_pos);
    cfg.method = method;
    cfg.accumulate = 1;
    ref = cfg;
    ref.method = FOVPT_METHOD_UNIFORM;
    if (method == FOVPT_METHOD_LAYERS) {
        if ((r = fovpt_layers_preset(&cfg.layers, FOVPT_LAYERS_KTH_RADIUS)) != FOV_OK) return r;
        cfg.layers.hollow = 1;
        ref.spp = cfg.layers.layer[cfg.layers.count - 1].spp;
    } else {
        cfg.mode = FOVPT_MODE_WHITTED;
        ref.mode = FOVPT_MODE_WHITTED;
        ref.spp = 16;
    }
    if ((r = pt_fovea_of(&cfg, &S.fovea_deg)) != FOV_OK) return r;
    S.fovea_now = S.fovea_deg;
    if ((r = pt_view_init(&S.v[0], &cfg)) != FOV_OK) return r;
    if ((r = pt_view_init(&S.v[1], &ref)) != FOV_OK) return r;
    npx = (size_t)w * h;
    S.rgb8 = (uint8_t *)web_alloc(npx * 3);
    S.rgba = (uint8_t *)web_alloc(npx * 4);
    S.tint = (uint8_t *)web_alloc(npx);
    if (!S.rgb8 || !S.rgba || !S.tint) return FOV_ERR_TOO_SMALL;
    return FOV_OK;
}

/* the fovea radius of the layers (the stride-1 layer), degrees; selective: e_f */
WEB_EXPORT(pt_fovea_deg) float pt_fovea_deg(void);
float pt_fovea_deg(void) { return S.fovea_deg; }
WEB_EXPORT(pt_fov_y) float pt_fov_y(void);
float pt_fov_y(void) { return S.cam.fov_y_deg; }

/* both views start accumulating afresh */
WEB_EXPORT(pt_restart) int pt_restart(void);
int pt_restart(void)
{
    int k;
    fov_result r;
    if (!S.rgba) return FOV_ERR_NULL;
    for (k = 0; k < 2; ++k) {
        if ((r = fovpt_reset(&S.v[k].ctx)) != FOV_OK) return r;
        S.v[k].frame = 0;
    }
    return FOV_OK;
}

/* Rows [y0, y1) of the next frame of view `which` (0 foveated, 1 reference): gaze (gx, gy),
   camera orbited by cam_angle. overlay 1 tints the layers (LAYERS) by the finest layer that
   traces each pixel's lattice point. web_stats: [0] samples, [1] rays, [2] pixels whose own
   samples were traced (layer stride 1 or UNIFORM; SELECTIVE: every pixel's presample), [3]
   pixels, [4] frames accumulated (after this one), [5] extra samples (SELECTIVE), [6] the
   fovea radius rendered with (as pt_fovea_deg, of the config with the margin), degrees. margin_deg (>= 0,
   at most PT_MAX_MARGIN; the foveated view only): the gaze margin (web_gaze.c), added to the
   layers' radii / selective's e_deg by fovpt_config_gaze_margin; a new margin re-initialises
   the foveated context (its accumulation restarts, as on a gaze move). */
WEB_EXPORT(pt_render) int pt_render(uint32_t which, float gx, float gy, float cam_angle,
                                    uint32_t y0, uint32_t y1, uint32_t overlay, float margin_deg);
int pt_render(uint32_t which, float gx, float gy, float cam_angle, uint32_t y0, uint32_t y1,
              uint32_t overlay, float margin_deg)
{
    pt_view_state *v;
    fovpt_camera cam;
    fovpt_stats st, st_band;
    fovpt_output out;
    fov_gaze g;
    fov_result r;
    uint32_t halo, t0, t1, q0, q1, y, x, n;
    double traced = 0.0;
    if (!S.rgba) return FOV_ERR_NULL;
    if (which > 1u || y0 > y1 || y1 > S.h) return FOV_ERR_INVALID_ARG;
    if (!(margin_deg >= 0.0f && margin_deg <= PT_MAX_MARGIN)) return FOV_ERR_INVALID_ARG;
    v = &S.v[which];
    if (which == 0 && (margin_deg < S.margin_deg || margin_deg > S.margin_deg)) {
        fovpt_config c = S.cfg;
        fov_gaze g0;
        size_t need = 0;
        g0.x = 0.5f * (float)S.w; g0.y = 0.5f * (float)S.h;
        if (margin_deg > 0.0f && (r = fovpt_config_gaze_margin(&S.cfg, margin_deg, &c)) != FOV_OK)
            return r;
        if ((r = fovpt_memory_size(&c, &S.cam, &need)) != FOV_OK) return r;
        if ((r = pt_fovea_of(&c, &S.fovea_now)) != FOV_OK) return r;
        if (need > S.mem0_size) return FOV_ERR_TOO_SMALL;
        if ((r = fovpt_init(&v->ctx, &c, &S.scene, &S.cam, g0, S.mem0, S.mem0_size)) != FOV_OK)
            return r;
        S.margin_deg = margin_deg;
        v->frame = 0;
        v->last[3] = 0.0f;
    }
    cam = S.cam;
    if (web_orbit(S.base_pos, cam.target, cam_angle, cam.pos) != 0) return FOV_ERR_INVALID_ARG;
    g.x = S.ignore_gaze ? 0.5f * (float)S.w : gx;
    g.y = S.ignore_gaze ? 0.5f * (float)S.h : gy;
    /* fovpt_set_view restarts the accumulation when the camera (or, foveated, the gaze) moved */
    if (!(v->last[3] > 0.0f) || v->last[2] < cam_angle || v->last[2] > cam_angle ||
        (which == 0 && (v->last[0] < g.x || v->last[0] > g.x || v->last[1] < g.y || v->last[1] > g.y)))
        v->frame = 0;
    v->last[0] = g.x; v->last[1] = g.y; v->last[2] = cam_angle; v->last[3] = 1.0f;
    if ((r = fovpt_set_view(&v->ctx, &cam, g)) != FOV_OK) return r;
    if (v->frame == 0 && (r = fovpt_reset(&v->ctx)) != FOV_OK) return r;
    halo = which == 1 ? 0u : S.method == FOVPT_METHOD_LAYERS ? PT_HALO_LAYERS : PT_HALO_SEL;
    t0 = y0 > halo ? y0 - halo : 0u;
    t1 = y1 + halo < S.h ? y1 + halo : S.h;
    q0 = y0 > halo / 2u ? y0 - halo / 2u : 0u;
    q1 = y1 + halo / 2u < S.h ? y1 + halo / 2u : S.h;
    fovpt_stats_init(&st);
    fovpt_stats_init(&st_band);
    /* the halo rows are traced too (their counts are left out of the band's figures) */
    if (t0 < y0 && (r = fovpt_trace_rows(&v->ctx, v->frame, t0, y0, &st)) != FOV_OK) return r;
    if ((r = fovpt_trace_rows(&v->ctx, v->frame, y0, y1, &st_band)) != FOV_OK) return r;
    if (y1 < t1 && (r = fovpt_trace_rows(&v->ctx, v->frame, y1, t1, &st)) != FOV_OK) return r;
    if (q0 < y0 && (r = fovpt_refine_rows(&v->ctx, v->frame, q0, y0, &st)) != FOV_OK) return r;
    if ((r = fovpt_refine_rows(&v->ctx, v->frame, y0, y1, &st_band)) != FOV_OK) return r;
    if (y1 < q1 && (r = fovpt_refine_rows(&v->ctx, v->frame, y1, q1, &st)) != FOV_OK) return r;
    fovpt_output_init(&out);
    out.rgb8 = S.rgb8;
    if ((r = fovpt_resolve_rows(&v->ctx, y0, y1, &out)) != FOV_OK) return r;
    v->frame++;
    /* the share of pixels traced at full density: LAYERS, the stride-1 layer's lattice points
       traced in the band (every pixel of the fovea); the others trace every pixel's own samples */
    if (which == 0 && S.method == FOVPT_METHOD_LAYERS) {
        const fovpt_ctx *c = &v->ctx;
        uint32_t fin = c->lay.count - 1u;
        traced = (double)st_band.layer_targets[fin];
        /* overlay only (the tint is not needed otherwise): the finest layer that traces each
           pixel's lattice point (ctx fields, no public getter), red the stride-1 fovea */
        if (overlay)
            for (y = y0; y < y1; ++y)
                for (x = 0; x < S.w; ++x) {
                    float e = fovpt_ecc_deg(&c->ecc, (float)x + 0.5f, (float)y + 0.5f);
                    uint32_t lay = c->lay.count, k;
                    for (k = c->lay.count; k-- > 0;)
                        if (e <= c->layer_trace_deg[k]) { lay = k; break; }
                    S.tint[(size_t)y * S.w + x] =
                        (uint8_t)(lay == fin ? 1 : lay + 1u == fin ? 2 : lay + 2u == fin ? 3 : 0);
                }
    } else {
        traced = (double)(y1 - y0) * (double)S.w;
    }
    web_rgba_rows(S.rgb8, S.rgba, which == 0 && S.method == FOVPT_METHOD_LAYERS && overlay ? S.tint : NULL,
                  S.w, y0, y1);
    n = y1 - y0;
    web_stats[0] = (double)st_band.samples;
    web_stats[1] = (double)st_band.rays;
    web_stats[2] = traced;
    web_stats[3] = (double)n * (double)S.w;
    web_stats[4] = (double)v->frame;
    web_stats[5] = (double)(st_band.extra_samples[0] + st_band.extra_samples[1] +
                            st_band.extra_samples[2] + st_band.extra_samples[3]);
    web_stats[6] = which == 0 ? (double)S.fovea_now : 0.0;
    return FOV_OK;
}
