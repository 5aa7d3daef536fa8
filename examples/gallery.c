/* gallery.c - the README's pictures: for a few fovsdf built-in scenes the full-resolution
   image beside the foveated one (CONE_FOV) with the gaze marked and the mask of the pixels
   that traced their own rays; one fovlp frame (full resolution, the log-polar sample buffer,
   the reconstruction after TAA); one fovpt image (UNIFORM beside LAYERS and the layers).
   Deterministic: one thread, no clock; the same build writes the same bytes.

   usage: gallery [--out DIR] [--width W] [--height H] [--help]
     --out     directory for the PPM files (default build/gallery_ppm; it must exist)
     --width, --height  size of one panel (default 480 x 270)
   Writes DIR/sdf_<scene>.ppm, DIR/lp_primitives.ppm, DIR/pt_cornell.ppm: each a row of three
   panels, 8-bit sRGB. `make gallery` converts them to PNG under docs/img/ with
   examples/gallery_png.py (python3, standard library only).

   Build: cc -std=c99 -O2 -I. examples/gallery.c -lm -o gallery */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "lp_sdf_shade.h"
#include "pt_scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NPANEL 3
#define GUTTER 4

typedef struct sheet {   /* a row of NPANEL panels of linear RGB floats (sRGB on output) */
    uint32_t pw, ph, w, h;
    float *px;
} sheet;

static int sheet_init(sheet *s, uint32_t pw, uint32_t ph)
{
    size_t i, n;
    s->pw = pw; s->ph = ph;
    s->w = NPANEL * pw + (NPANEL - 1) * GUTTER; s->h = ph;
    n = (size_t)s->w * s->h * 3;
    s->px = (float *)malloc(n * sizeof(float));
    if (!s->px) return -1;
    for (i = 0; i < n; ++i) s->px[i] = 1.0f; /* white gutters */
    return 0;
}

static float *panel_px(sheet *s, uint32_t panel, uint32_t x, uint32_t y)
{
    return s->px + 3 * ((size_t)y * s->w + (size_t)panel * (s->pw + GUTTER) + x);
}

static void panel_put(sheet *s, uint32_t panel, const float *rgb)
{
    uint32_t x, y;
    for (y = 0; y < s->ph; ++y)
        for (x = 0; x < s->pw; ++x) memcpy(panel_px(s, panel, x, y), rgb + 3 * ((size_t)y * s->pw + x), 3 * sizeof(float));
}

static void dot(sheet *s, uint32_t panel, long x, long y, float r, float g, float b)
{
    float *p;
    if (x < 0 || y < 0 || x >= (long)s->pw || y >= (long)s->ph) return;
    p = panel_px(s, panel, (uint32_t)x, (uint32_t)y);
    p[0] = r; p[1] = g; p[2] = b;
}

/* the gaze: a ring of radius 7 px and a centre dot, white on a black outline */
static void mark_gaze(sheet *s, uint32_t panel, float gx, float gy)
{
    int pass;
    long dx, dy;
    for (pass = 0; pass < 2; ++pass) {
        float c = pass ? 1.0f : 0.0f;
        for (dy = -9; dy <= 9; ++dy)
            for (dx = -9; dx <= 9; ++dx) {
                float d = sqrtf((float)(dx * dx + dy * dy));
                int on = pass ? (fabsf(d - 7.0f) < 0.75f || d < 1.3f) : (fabsf(d - 7.0f) < 1.6f || d < 2.2f);
                if (on) dot(s, panel, (long)floorf(gx) + dx, (long)floorf(gy) + dy, c, c, c);
            }
    }
}

/* a thin circle of radius r px (eccentricity borders, the gaze disc) */
static void circle(sheet *s, uint32_t panel, float gx, float gy, float r, float c)
{
    int k, n = (int)(6.3f * r) + 8;
    for (k = 0; k < n; ++k) {
        float a = 6.2831853f * (float)k / (float)n;
        dot(s, panel, (long)floorf(gx + r * cosf(a)), (long)floorf(gy + r * sinf(a)), c, c, c);
    }
}

static float to_srgb(float v)
{
    v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

static int sheet_write(const sheet *s, const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    size_t i, n = (size_t)s->w * s->h * 3;
    snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
    f = fopen(path, "wb");
    if (!f) { fprintf(stderr, "gallery: cannot write %s (does the directory exist?)\n", path); return -1; }
    fprintf(f, "P6\n%u %u\n255\n", s->w, s->h);
    for (i = 0; i < n; ++i) fputc((int)(to_srgb(s->px[i]) * 255.0f + 0.5f), f);
    if (fclose(f) != 0) return -1;
    printf("wrote %s (%ux%u)\n", path, s->w, s->h);
    return 0;
}

/* mix a linear colour towards a tint: the overlays keep the image's luminance visible */
static void tint(float *rgb, float r, float g, float b, float k)
{
    float l = 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
    l = 0.15f + 0.85f * (l > 1.0f ? 1.0f : l);
    rgb[0] = (1.0f - k) * l + k * r * l * 1.6f;
    rgb[1] = (1.0f - k) * l + k * g * l * 1.6f;
    rgb[2] = (1.0f - k) * l + k * b * l * 1.6f;
}

static void log_msg(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line, void *user)
{
    (void)level; (void)line; (void)user;
    fprintf(stderr, "gallery: %s: %s (%d)\n", tag, msg ? msg : "(no message)", (int)code);
}

/* fovsdf: CONE (full resolution, every pixel traced) | CONE_FOV + gaze | its mask */
static int gallery_sdf(uint32_t id, float gxf, float gyf, uint32_t W, uint32_t H, const char *dir)
{
    fovsdf_builtin bi;
    fovsdf_config cfg;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats st;
    fov_gaze gaze;
    size_t bytes = 0, i, npx = (size_t)W * H;
    void *mem;
    float *rgb = (float *)malloc(npx * 3 * sizeof(float));
    uint8_t *mask = (uint8_t *)malloc(npx);
    sheet s;
    char name[64];
    fov_result r;
    uint32_t x;
    float fovea_px = 0.0f;

    if (!rgb || !mask || sheet_init(&s, W, H) != 0) return -1;
    if (fovsdf_builtin_size(id, &bytes) != FOV_OK || !(mem = malloc(bytes))) return -1;
    if ((r = fovsdf_builtin_init(id, &bi, mem, bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovsdf_result_string(r)); return -1; }
    bi.camera.width = W;
    bi.camera.height = H;
    gaze.x = gxf * (float)W; gaze.y = gyf * (float)H;

    cfg = fovsdf_config_default();
    cfg.method = FOVSDF_METHOD_CONE;
    cfg.logger.func = log_msg;
    if ((r = fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0)) != FOV_OK) return -1;
    fovsdf_output_init(&out);
    out.rgb = rgb;
    memset(&st, 0, sizeof st);
    if (fovsdf_render_rows(&ctx, 0, H, &out, &st) != FOV_OK) return -1;
    panel_put(&s, 0, rgb);
    printf("%s: cone %.1f evaluations per pixel", fovsdf_builtin_name(id), (double)st.evals / (double)npx);

    cfg.method = FOVSDF_METHOD_CONE_FOV;
    if ((r = fovsdf_init(&ctx, &cfg, &bi.scene, &bi.camera, gaze, NULL, 0)) != FOV_OK) return -1;
    out.mask = mask;
    memset(&st, 0, sizeof st);
    if (fovsdf_render_rows(&ctx, 0, H, &out, &st) != FOV_OK) return -1;
    panel_put(&s, 1, rgb);
    printf(", cone_fov %.1f\n", (double)st.evals / (double)npx);
    for (i = 0; i < npx; ++i) { /* traced: warm; interpolated: cool */
        if (mask[i] == 1) tint(rgb + 3 * i, 1.0f, 0.45f, 0.1f, 0.85f);
        else tint(rgb + 3 * i, 0.25f, 0.45f, 1.0f, 0.5f);
    }
    panel_put(&s, 2, rgb);
    /* the fovea's border: the first pixel right of the gaze beyond fovea_deg */
    for (x = (uint32_t)gaze.x; x < 4 * W; ++x)
        if (fovsdf_ecc_deg(&ctx.ecc, (float)x + 0.5f, gaze.y) > 7.5f) { fovea_px = (float)x + 0.5f - gaze.x; break; }
    mark_gaze(&s, 1, gaze.x, gaze.y);
    mark_gaze(&s, 2, gaze.x, gaze.y);
    if (fovea_px > 0.0f) circle(&s, 2, gaze.x, gaze.y, fovea_px, 1.0f);
    snprintf(name, sizeof name, "sdf_%s", fovsdf_builtin_name(id));
    r = sheet_write(&s, dir, name) == 0 ? FOV_OK : FOV_ERR_INVALID_ARG;
    free(mem); free(rgb); free(mask); free(s.px);
    return r == FOV_OK ? 0 : -1;
}

/* fovlp (C Fov) shading fovsdf's primitives: full resolution | the log-polar sample buffer
   (what was shaded) | the reconstruction after 16 still TAA frames, gaze and disc marked */
static int gallery_lp(uint32_t W, uint32_t H, const char *dir)
{
    fovsdf_builtin bi;
    fovsdf_config scfg = fovsdf_config_default();
    fovsdf_ctx sdf;
    fovlp_config cfg;
    fovlp_ctx lp;
    fovlp_camera cam;
    lpsdf_user user;
    fov_gaze gaze;
    size_t bytes = 0, npx = (size_t)W * H;
    void *smem, *lpmem;
    float *samples, *sdepth, *cur, *cdep, *hist[2], *hdep[2], *full;
    uint8_t *age[2];
    int ping = 0, f, k;
    uint32_t x, y, rows;
    sheet s;
    fov_result r;

    if (sheet_init(&s, W, H) != 0) return -1;
    if (fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &bytes) != FOV_OK || !(smem = malloc(bytes))) return -1;
    if (fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &bi, smem, bytes) != FOV_OK) return -1;
    bi.camera.width = W;
    bi.camera.height = H;
    gaze.x = 0.42f * (float)W; gaze.y = 0.55f * (float)H;
    if (fovsdf_init(&sdf, &scfg, &bi.scene, &bi.camera, gaze, NULL, 0) != FOV_OK) return -1;

    cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    cfg.cam_fov_y_deg = bi.camera.fov_y_deg;
    cfg.taa.enable = 1;
    cfg.logger.func = log_msg;
    if ((r = fovlp_memory_size(&cfg, &bytes)) != FOV_OK || !(lpmem = malloc(bytes))) return -1;
    if ((r = fovlp_init(&lp, &cfg, lpmem, bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovlp_result_string(r)); return -1; }
    samples = (float *)calloc((size_t)lp.geo.samples * 3, sizeof(float));
    sdepth = (float *)calloc((size_t)lp.geo.samples, sizeof(float));
    cur = (float *)malloc(npx * 3 * sizeof(float));
    cdep = (float *)malloc(npx * sizeof(float));
    full = (float *)malloc(npx * 3 * sizeof(float));
    for (k = 0; k < 2; ++k) {
        hist[k] = (float *)calloc(npx * 3, sizeof(float));
        hdep[k] = (float *)calloc(npx, sizeof(float));
        age[k] = (uint8_t *)calloc(npx, 1);
    }
    memset(&user, 0, sizeof user);
    user.sdf = &sdf;
    for (y = 0; y < H; ++y) /* the full-resolution frame: one sample per pixel centre */
        for (x = 0; x < W; ++x) lpsdf_shade((float)x + 0.5f, (float)y + 0.5f, full + 3 * ((size_t)y * W + x), NULL, &user);
    panel_put(&s, 0, full);

    if (fovlp_camera_from(&bi.camera, &cam) != FOV_OK) return -1; /* the camera fovsdf renders */
    for (f = 0; f < 16; ++f) {
        fovlp_taa_io io;
        if ((r = fovlp_begin_frame(&lp, gaze, &cam)) != FOV_OK) return -1;
        rows = fovlp_sample_rows(&lp);
        fovlp_shade_rows(&lp, 0, rows, lpsdf_shade, &user, samples, sdepth, NULL);
        fovlp_reconstruct_rows(&lp, samples, sdepth, 0, H, cur, 0, cdep);
        io.cur_rgb = cur; io.cur_depth = cdep;
        io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
        io.out_rgb = hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
        fovlp_taa_rows(&lp, &io, 0, H, NULL);
        ping = 1 - ping;
    }
    /* the log-polar buffer (lp_w x lp_h texels: u, the log of the distance to the gaze, to
       the right; v, the angle around it, down), stretched to the panel; columns not
       dispatched for this gaze (beyond the farthest screen corner) stay grey */
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            uint32_t u = (uint32_t)((size_t)x * lp.geo.lp_w / W), v = (uint32_t)((size_t)y * lp.geo.lp_h / H);
            float *d = full + 3 * ((size_t)y * W + x);
            if (u >= lp.geo.lp_cols) { d[0] = d[1] = d[2] = 0.18f; continue; }
            memcpy(d, samples + 3 * ((size_t)v * lp.geo.lp_w + u), 3 * sizeof(float));
        }
    printf("lp: C Fov, LP buffer %ux%u (%u columns dispatched), gaze disc r_G %.1f px, %u sample slots for %ux%u pixels\n",
           lp.geo.lp_w, lp.geo.lp_h, lp.geo.lp_cols, (double)lp.geo.r_g, lp.geo.samples, W, H);
    panel_put(&s, 1, full);
    panel_put(&s, 2, hist[ping]);
    mark_gaze(&s, 0, gaze.x, gaze.y);
    mark_gaze(&s, 2, gaze.x, gaze.y);
    if (lp.geo.r_g > 0.0f) circle(&s, 2, gaze.x, gaze.y, lp.geo.r_g, 1.0f);
    k = sheet_write(&s, dir, "lp_primitives");
    free(smem); free(lpmem); free(samples); free(sdepth); free(cur); free(cdep); free(full); free(s.px);
    for (f = 0; f < 2; ++f) { free(hist[f]); free(hdep[f]); free(age[f]); }
    return k;
}

/* fovpt: UNIFORM 4 spp | LAYERS (6/10/20-degree radii, 4 spp in the fovea) | the layers */
static int gallery_pt(uint32_t W, uint32_t H, const char *dir)
{
    pt_scene ps;
    fovpt_config cfg;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    fov_gaze gaze;
    size_t bytes = 0, npx = (size_t)W * H, i;
    void *mem = NULL;
    float *rgb = (float *)malloc(npx * 3 * sizeof(float));
    sheet s;
    uint32_t m, x, y, n;
    static const float col[FOVPT_MAX_LAYERS][3] = { { 0.25f, 0.45f, 1.0f }, { 0.3f, 0.9f, 0.4f }, { 1.0f, 0.85f, 0.2f },
                                                    { 1.0f, 0.4f, 0.1f } };
    int rc;

    if (!rgb || sheet_init(&s, W, H) != 0) return -1;
    if (pt_scene_make(&ps, PT_SCENE_CORNELL) != 0) return -1;
    ps.cam.width = W;
    ps.cam.height = H;
    gaze.x = 0.62f * (float)W; gaze.y = 0.52f * (float)H;
    for (m = 0; m < 2; ++m) {
        cfg = fovpt_config_default();
        cfg.method = m ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_UNIFORM;
        cfg.spp = 4;
        cfg.logger.func = log_msg;
        if (fovpt_memory_size(&cfg, &ps.cam, &bytes) != FOV_OK) return -1;
        free(mem);
        if (!(mem = malloc(bytes + 16u))) return -1;
        if (fovpt_init(&ctx, &cfg, &ps.scene, &ps.cam, gaze, mem, bytes) != FOV_OK) return -1;
        fovpt_output_init(&out);
        out.rgb = rgb;
        memset(&st, 0, sizeof st);
        if (fovpt_render(&ctx, 0, &out, &st) != FOV_OK) return -1;
        panel_put(&s, m, rgb);
        printf("pt: cornell %s, %llu camera rays (%.2f per pixel)\n", fovpt_method_name(cfg.method),
               (unsigned long long)st.camera_rays, (double)st.camera_rays / (double)npx);
    }
    /* the layer of each pixel: the innermost layer whose radius holds its eccentricity */
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            float e = fovpt_ecc_deg(&ctx.ecc, (float)x + 0.5f, (float)y + 0.5f);
            uint32_t layer = 0;
            i = (size_t)y * W + x;
            for (n = 1; n < ctx.lay.count; ++n)
                if (e <= ctx.lay.layer[n].radius_deg) layer = n;
            if (ctx.lay.layer[0].radius_deg > 0.0f && e > ctx.lay.layer[0].radius_deg) {
                rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = 0.0f; /* occlusion mask: not traced */
                continue;
            }
            tint(rgb + 3 * i, col[layer][0], col[layer][1], col[layer][2], 0.7f);
        }
    panel_put(&s, 2, rgb);
    mark_gaze(&s, 1, gaze.x, gaze.y);
    mark_gaze(&s, 2, gaze.x, gaze.y);
    rc = sheet_write(&s, dir, "pt_cornell");
    free(mem); free(rgb); free(s.px);
    pt_scene_free(&ps);
    return rc;
}

static void usage(FILE *f)
{
    fputs("usage: gallery [--out DIR] [--width W] [--height H]\n"
          "  renders the README's gallery as PPM files into DIR (default build/gallery_ppm):\n"
          "  sdf_<scene>.ppm (full | CONE_FOV | mask), lp_primitives.ppm, pt_cornell.ppm\n"
          "  --width W, --height H   panel size in pixels (default 480 x 270, 16 .. 4096)\n",
          f);
}

int main(int argc, char **argv)
{
    const char *dir = "build/gallery_ppm";
    uint32_t W = 480, H = 270;
    int a, fails = 0;
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--out") && a + 1 < argc) dir = argv[++a];
        else if (!strcmp(argv[a], "--width") && a + 1 < argc) W = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--height") && a + 1 < argc) H = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (W < 16 || H < 16 || W > 4096 || H > 4096) { fprintf(stderr, "panel size 16 .. 4096\n"); return 2; }
    fails += gallery_sdf(FOVSDF_SCENE_PRIMITIVES, 0.38f, 0.62f, W, H, dir) != 0;
    fails += gallery_sdf(FOVSDF_SCENE_TEMPLE, 0.55f, 0.45f, W, H, dir) != 0;
    fails += gallery_sdf(FOVSDF_SCENE_COLUMNS, 0.5f, 0.5f, W, H, dir) != 0;
    fails += gallery_lp(W, H, dir) != 0;
    fails += gallery_pt(W, H, dir) != 0;
    if (fails) fprintf(stderr, "gallery: %d image(s) failed\n", fails);
    return fails ? 1 : 0;
}
