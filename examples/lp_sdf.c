/* lp_sdf.c - two fov headers together: fovlp.h decides where to shade (log-polar kernel
   foveation with a gaze disc and TAA), fovsdf.h shades (sphere tracing of a built-in scene).
   Renders a sequence with a moving gaze and a moving camera and writes numbered frames.

   usage: lp_sdf [--width W] [--height H] [--frames N] [--scene ID] [--preset P] [--no-taa]
                 [--out DIR] [--check]
     --scene   fovsdf built-in scene 0..5 (default 0, primitives)
     --preset  0 Fov, 1 K Fov, 2 C Fov (default), 3 C K Fov
     --out     directory for DIR/lp_<scene>_<NNN>.ppm (default out); "-" writes no files
     --check   compare frame 0 with a full-resolution render (fovsdf_render_rows, 1 spp; with
               TAA the same shading at every pixel at the frame's jitter offset): the gaze
               disc must be the same pixels (PSNR >= 90 dB; both shade with fovsdf_shade_point), the whole frame must be close (>= 18 dB);
               exit 1 otherwise
   Per frame it prints the samples shaded (% of the pixels) and the time.

   Build: cc -std=c99 -O2 -I. examples/lp_sdf.c -lm -o lp_sdf */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#include "lp_sdf_shade.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void) { return (double)clock() * 1000.0 / (double)CLOCKS_PER_SEC; }

static float srgb(float v)
{
    v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

/* a linear float image (3 floats per pixel) as an 8-bit sRGB PPM: fovlp_srgb8_rows encodes */
static int write_ppm(const char *path, const fovlp_ctx *lp, const float *rgb, uint32_t w, uint32_t h)
{
    uint8_t *px = (uint8_t *)malloc((size_t)w * h * 3);
    FILE *f = px ? fopen(path, "wb") : NULL;
    int ok = f != NULL && fovlp_srgb8_rows(lp, rgb, 0, 0, h, px, 0, 3) == FOV_OK;
    if (ok) {
        fprintf(f, "P6\n%u %u\n255\n", w, h);
        ok = fwrite(px, 1, (size_t)w * h * 3, f) == (size_t)w * h * 3;
    }
    if (f && fclose(f) != 0) ok = 0;
    free(px);
    return ok ? 0 : -1;
}

/* PSNR of the sRGB encodings over the pixels with mask[i] == want (mask NULL: all) */
static double psnr(const float *a, const float *b, const uint8_t *mask, uint8_t want, size_t npx)
{
    double se = 0.0;
    size_t i, n = 0;
    int c;
    for (i = 0; i < npx; ++i) {
        if (mask && mask[i] != want) continue;
        for (c = 0; c < 3; ++c) {
            double d = (double)(srgb(a[3 * i + (size_t)c]) - srgb(b[3 * i + (size_t)c]));
            se += d * d;
        }
        n += 3;
    }
    if (n == 0) return 0.0;
    if (se <= 0.0) return 99.0;
    return 10.0 * log10((double)n / se);
}

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: lp_sdf [options]\n"
          "renders a fovsdf scene through fovlp (log-polar foveation, TAA) with a moving gaze and camera\n"
          "  --width W           image width (default 640)\n"
          "  --height H          image height (default 360)\n"
          "  --frames N          frames (default 24)\n"
          "  --scene ID          fovsdf built-in scene 0..5 (default 0, primitives)\n"
          "  --preset P          0 Fov, 1 K Fov, 2 C Fov (default), 3 C K Fov\n"
          "  --no-taa            without temporal anti-aliasing\n"
          "  --out DIR           writes DIR/lp_<scene>_<NNN>.ppm (default out); - writes no files\n"
          "  --check             frame 0 against a full-resolution render; exit 1 on failure\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 640, H = 360, frames = 24, scene = 0, preset = FOVLP_PRESET_C_FOV, f, rows;
    int taa = 1, check = 0, a, fails = 0;
    const char *out = "out";
    fovlp_config cfg;
    fovlp_ctx lp;
    void *lpmem;
    size_t bytes = 0, npx;
    float *samples, *sdepth, *cur, *cdep, *hist[2], *hdep[2];
    uint8_t *age[2];
    void *scene_mem;
    fovsdf_builtin bi;
    fovsdf_config scfg = fovsdf_config_default();
    fov_result r;
    int ping = 0;
    float base_pos[3], base_target[3];

    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--width") && a + 1 < argc) W = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--height") && a + 1 < argc) H = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--frames") && a + 1 < argc) frames = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--scene") && a + 1 < argc) scene = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--preset") && a + 1 < argc) preset = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) out = argv[++a];
        else if (!strcmp(argv[a], "--no-taa")) taa = 0;
        else if (!strcmp(argv[a], "--check")) check = 1;
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }

    /* the scene (fovsdf) */
    if ((r = fovsdf_builtin_size(scene, &bytes)) != FOV_OK) { fprintf(stderr, "scene %u: %s\n", scene, fovsdf_result_string(r)); return 1; }
    scene_mem = malloc(bytes);
    if ((r = fovsdf_builtin_init(scene, &bi, scene_mem, bytes)) != FOV_OK) { fprintf(stderr, "scene: %s\n", fovsdf_result_string(r)); return 1; }
    bi.camera.width = W;
    bi.camera.height = H;
    memcpy(base_pos, bi.camera.pos, sizeof base_pos);
    memcpy(base_target, bi.camera.target, sizeof base_target);

    /* the foveation (fovlp): the camera's field of view is the display's */
    cfg = fovlp_config_preset(preset, W, H);
    cfg.cam_fov_y_deg = bi.camera.fov_y_deg;
    cfg.taa.enable = (uint32_t)taa;
    if ((r = fovlp_memory_size(&cfg, &bytes)) != FOV_OK) { fprintf(stderr, "fovlp: %s\n", fovlp_result_string(r)); return 1; }
    lpmem = malloc(bytes);
    if ((r = fovlp_init(&lp, &cfg, lpmem, bytes)) != FOV_OK) { fprintf(stderr, "fovlp_init: %s\n", fovlp_result_string(r)); return 1; }
    npx = (size_t)W * H;
    samples = (float *)malloc((size_t)lp.geo.samples * 3 * sizeof(float));
    sdepth = (float *)malloc((size_t)lp.geo.samples * sizeof(float));
    cur = (float *)malloc(npx * 3 * sizeof(float));
    cdep = (float *)malloc(npx * sizeof(float));
    for (a = 0; a < 2; ++a) {
        hist[a] = (float *)calloc(npx * 3, sizeof(float));
        hdep[a] = (float *)calloc(npx, sizeof(float));
        age[a] = (uint8_t *)calloc(npx, 1);
    }
    printf("lp_sdf: %s, %ux%u, %s, LP buffer %ux%u, gaze disc r_G %.1f px, TAA %s\n", fovsdf_builtin_name(scene), W, H,
           fovlp_preset_name(preset), lp.geo.lp_w, lp.geo.lp_h, (double)lp.geo.r_g, taa ? "on" : "off");

    for (f = 0; f < frames; ++f) {
        float ph = 6.2831853f * (float)f / (float)(frames > 1 ? frames : 1);
        fov_gaze gaze;
        fovsdf_ctx sdf;
        fovlp_camera cam;
        fovlp_counts cnt;
        lpsdf_user user;
        const float *img = cur;
        double t0 = now_ms(), t1;
        /* a gaze on a slow Lissajous path and a camera moving sideways */
        gaze.x = (float)W * (0.5f + 0.25f * sinf(ph));
        gaze.y = (float)H * (0.5f + 0.2f * sinf(2.0f * ph));
        bi.camera.pos[0] = base_pos[0] + 0.02f * (float)f;
        bi.camera.target[0] = base_target[0] + 0.02f * (float)f;
        if ((r = fovsdf_init(&sdf, &scfg, &bi.scene, &bi.camera, gaze, NULL, 0)) != FOV_OK) {
            fprintf(stderr, "fovsdf_init: %s\n", fovsdf_result_string(r));
            return 1;
        }
        /* TAA reprojects with the same camera: its basis form, equal to the fovsdf context's */
        if ((r = fovlp_camera_from(&bi.camera, &cam)) != FOV_OK) {
            fprintf(stderr, "fovlp_camera_from: %s\n", fovlp_result_string(r));
            return 1;
        }
        if ((r = fovlp_begin_frame(&lp, gaze, &cam)) != FOV_OK) { fprintf(stderr, "begin_frame: %s\n", fovlp_result_string(r)); return 1; }
        memset(&user, 0, sizeof user);
        user.sdf = &sdf;
        rows = fovlp_sample_rows(&lp);
        fovlp_shade_rows(&lp, 0, rows, lpsdf_shade, &user, samples, sdepth, NULL);  /* split rows over threads if you like */
        fovlp_reconstruct_rows(&lp, samples, sdepth, 0, H, cur, 0, cdep);
        if (taa) {
            fovlp_taa_io io;
            fovlp_taa_io_init(&io);
            io.cur_rgb = cur; io.cur_depth = cdep;
            io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
            io.out_rgb = hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
            fovlp_taa_rows(&lp, &io, 0, H, NULL);
            ping = 1 - ping;
            img = hist[ping];
        }
        t1 = now_ms();
        fovlp_count_samples(&lp, &cnt);
        printf("frame %3u: gaze (%5.1f, %5.1f), %5.1f %% of the pixels shaded, %.1f ms\n", f, (double)gaze.x,
               (double)gaze.y, (double)cnt.shaded_pct, t1 - t0);
        if (strcmp(out, "-") != 0) {
            char path[512];
            snprintf(path, sizeof path, "%s/lp_%s_%03u.ppm", out, fovsdf_builtin_name(scene), f);
            if (write_ppm(path, &lp, img, W, H) != 0) { fprintf(stderr, "cannot write %s (does the directory exist?)\n", path); return 1; }
        }
        if (check && f == 0) {
            /* fovsdf's own full-resolution render of the same frame */
            float *ref = (float *)malloc(npx * 3 * sizeof(float));
            uint8_t *mask = (uint8_t *)malloc(npx);
            fovsdf_output o;
            fovsdf_stats st;
            size_t i;
            double p_disc, p_all;
            fovsdf_stats_init(&st);
            fovsdf_output_init(&o);
            o.rgb = ref;
            if (!taa) {
                fovsdf_render_rows(&sdf, 0, H, &o, &st);
            } else { /* the same shading at every pixel, at this frame's jittered offset */
                lpsdf_user u2;
                uint32_t x, y;
                memset(&u2, 0, sizeof u2);
                u2.sdf = &sdf;
                for (y = 0; y < H; ++y)
                    for (x = 0; x < W; ++x)
                        lpsdf_shade((float)x + lp.jit_u, (float)y + lp.jit_v, ref + 3 * ((size_t)y * W + x), NULL, &u2);
            }
            for (i = 0; i < npx; ++i) {
                float dx = (float)(i % W) + 0.5f - lp.gaze.x, dy = (float)(i / W) + 0.5f - lp.gaze.y;
                mask[i] = (uint8_t)(dx * dx + dy * dy < lp.geo.r_g * lp.geo.r_g ? 1 : 0);
            }
            p_disc = psnr(ref, cur, mask, 1, npx);
            p_all = psnr(ref, cur, NULL, 0, npx);
            printf("check: frame 0 against the full-resolution render: gaze disc %.1f dB, whole frame %.1f dB\n", p_disc, p_all);
            if (!(p_disc >= 90.0 && p_all >= 18.0)) { printf("FAIL lp_sdf check\n"); fails++; }
            else printf("PASS lp_sdf check: disc >= 90 dB, frame >= 18 dB\n");
            free(ref);
            free(mask);
        }
    }
    free(scene_mem); free(lpmem); free(samples); free(sdepth); free(cur); free(cdep);
    for (a = 0; a < 2; ++a) { free(hist[a]); free(hdep[a]); free(age[a]); }
    return fails ? 1 : 0;
}
