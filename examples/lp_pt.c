/* lp_pt.c - path tracing in log-polar space with two fov headers: fovlp.h decides where to shade
   (kernel log-polar samples around the gaze, a gaze disc shaded 1:1, TAA over frames), fovpt.h
   path traces exactly those positions (fovpt_shade_points), fovlp reconstructs the image. The
   idea is Koskela et al. 2019 (M. Koskela, A. Lotvonen, M. Makitalo, P. Kivi, T. Viitanen,
   P. Jaaskelainen, "Foveated Real-Time Path Tracing in Visual-Polar Space", EGSR 2019), who
   path trace a grid in their Visual-Polar space on the GPU; the mapping here is fovlp.h's
   (Meng et al. 2018, "Kernel Foveated Rendering"; Andersson & Hansson 2020's gaze disc).
   Renders the Cornell box of examples/pt_scenes.h with a still camera and gaze for a few
   frames (TAA accumulates them; the jitter moves the samples) and writes the last one.

   usage: lp_pt [--width W] [--height H] [--frames N] [--spp S] [--acuity] [--no-taa]
                [--gaze X Y] [--out FILE]
     --frames  frames accumulated by fovlp's TAA (default 8; with --no-taa only the last counts)
     --spp     path samples per log-polar / disc position and frame (default 1)
     --acuity  fovlp_config_acuity (the eye model at the camera's field of view) instead of the
               C Fov preset of Andersson & Hansson 2020
     --out     the PPM written (default out/lp_pt.ppm; - writes none)
   Prints the samples shaded per frame (% of the pixels) and the time.

   Build: cc -std=c99 -O2 -I. examples/lp_pt.c -lm -o lp_pt */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#include "pt_scenes.h"
#include "lp_pt_shade.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void) { return (double)clock() * 1000.0 / (double)CLOCKS_PER_SEC; }

/* a linear float image as an 8-bit sRGB PPM (fovlp_srgb8_rows encodes) */
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

/* -h / --help prints this to stdout (exit 0); an unknown option prints it to stderr (exit 2) */
static void usage(FILE *f)
{
    fputs("usage: lp_pt [options]\n"
          "path traces the Cornell box (fovpt) at fovlp's log-polar positions, TAA over frames\n"
          "  --width W           image width (default 320)\n"
          "  --height H          image height (default 240)\n"
          "  --frames N          frames accumulated by the TAA (default 8)\n"
          "  --spp S             path samples per position and frame (default 1)\n"
          "  --acuity            fovlp_config_acuity instead of the C Fov preset\n"
          "  --no-taa            without temporal anti-aliasing (the last frame alone)\n"
          "  --gaze X Y          gaze in pixels (default the image centre)\n"
          "  --out FILE          PPM written (default out/lp_pt.ppm); - writes none\n"
          "  -h, --help          this text\n", f);
}

int main(int argc, char **argv)
{
    uint32_t W = 320, H = 240, frames = 8, spp = 1, f;
    int taa = 1, acuity = 0, a, ping = 0, have_gaze = 0;
    float gx = 0.0f, gy = 0.0f;
    const char *out = "out/lp_pt.ppm";
    pt_scene S;
    fovpt_config pcfg = fovpt_config_default();
    fovlp_config cfg;
    fovlp_camera lcam;
    fovlp_ctx lp;
    fov_gaze gaze;
    void *lpmem;
    size_t bytes = 0, npx;
    float *samples, *sdepth, *cur, *cdep, *hist[2], *hdep[2];
    const float *img;
    uint8_t *age[2];
    fov_result r;
    double t_all = 0.0;

    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) { usage(stdout); return 0; }
        else if (!strcmp(argv[a], "--width") && a + 1 < argc) W = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--height") && a + 1 < argc) H = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--frames") && a + 1 < argc) frames = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--spp") && a + 1 < argc) spp = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--acuity")) acuity = 1;
        else if (!strcmp(argv[a], "--no-taa")) taa = 0;
        else if (!strcmp(argv[a], "--gaze") && a + 2 < argc) {
            gx = (float)atof(argv[++a]);
            gy = (float)atof(argv[++a]);
            have_gaze = 1;
        }
        else if (!strcmp(argv[a], "--out") && a + 1 < argc) out = argv[++a];
        else { fprintf(stderr, "unknown option %s\n", argv[a]); usage(stderr); return 2; }
    }
    if (W < 1 || H < 1 || frames < 1 || spp < 1) { fprintf(stderr, "lp_pt: sizes, frames and spp must be >= 1\n"); return 2; }

    /* the scene and camera (fovpt) */
    if (pt_scene_make(&S, PT_SCENE_CORNELL) != 0) { fprintf(stderr, "lp_pt: scene build failed\n"); return 1; }
    S.cam.width = W;
    S.cam.height = H;
    gaze.x = have_gaze ? gx : 0.5f * (float)W;
    gaze.y = have_gaze ? gy : 0.5f * (float)H;

    /* the foveation (fovlp): the camera's field of view is the display's, as fovpt assumes */
    if ((r = fovlp_camera_from(&S.cam, &lcam)) != FOV_OK) { fprintf(stderr, "fovlp_camera_from: %s\n", fovlp_result_string(r)); return 1; }
    cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    cfg.cam_fov_y_deg = S.cam.fov_y_deg;
    if (acuity && (r = fovlp_config_acuity(&cfg, &lcam, NULL)) != FOV_OK) {
        fprintf(stderr, "fovlp_config_acuity: %s\n", fovlp_result_string(r));
        return 1;
    }
    cfg.taa.enable = (uint32_t)taa;
    if ((r = fovlp_memory_size(&cfg, &bytes)) != FOV_OK) { fprintf(stderr, "fovlp: %s\n", fovlp_result_string(r)); return 1; }
    lpmem = malloc(bytes ? bytes : 1);
    if (!lpmem) { fprintf(stderr, "lp_pt: out of memory (fovlp's working memory)\n"); return 1; }
    if ((r = fovlp_init(&lp, &cfg, lpmem, bytes)) != FOV_OK) { fprintf(stderr, "fovlp_init: %s\n", fovlp_result_string(r)); return 1; }
    if ((uint64_t)W * H > (uint64_t)(SIZE_MAX / (3 * sizeof(float)))) { fprintf(stderr, "lp_pt: %ux%u too large\n", W, H); return 1; }
    npx = (size_t)W * H;
    samples = (float *)calloc((size_t)lp.geo.samples * 3, sizeof(float));
    sdepth = (float *)calloc((size_t)lp.geo.samples, sizeof(float));
    cur = (float *)malloc(npx * 3 * sizeof(float));
    cdep = (float *)malloc(npx * sizeof(float));
    for (a = 0; a < 2; ++a) {
        hist[a] = (float *)calloc(npx * 3, sizeof(float));
        hdep[a] = (float *)calloc(npx, sizeof(float));
        age[a] = (uint8_t *)calloc(npx, 1);
    }
    if (!samples || !sdepth || !cur || !cdep || !hist[0] || !hist[1] || !hdep[0] || !hdep[1] || !age[0] || !age[1]) {
        fprintf(stderr, "lp_pt: out of memory (image buffers for %ux%u)\n", W, H);
        return 1;
    }
    printf("lp_pt: cornell, %ux%u, %s, LP buffer %ux%u, gaze disc r_G %.1f px, %u spp per position, TAA %s\n", W, H,
           acuity ? "fovlp_config_acuity" : "C Fov", lp.geo.lp_w, lp.geo.lp_h, (double)lp.geo.r_g, spp, taa ? "on" : "off");

    img = cur;
    for (f = 0; f < frames; ++f) {
        lppt_user u;
        fovlp_counts cnt;
        double t0 = now_ms(), t1;
        if ((r = fovlp_begin_frame(&lp, gaze, &lcam)) != FOV_OK) { fprintf(stderr, "begin_frame: %s\n", fovlp_result_string(r)); return 1; }
        memset(&u, 0, sizeof u);
        u.scene = &S.scene; u.cfg = &pcfg; u.cam = &S.cam; u.frame = f; u.spp = spp;
        /* fovlp's positions, fovpt's paths (split the sample rows over threads if you like) */
        if ((r = lppt_shade_samples(&lp, 0, fovlp_sample_rows(&lp), &u, samples, sdepth)) != FOV_OK) {
            fprintf(stderr, "shade: %s\n", fovpt_result_string(r));
            return 1;
        }
        if ((r = fovlp_reconstruct_rows(&lp, samples, sdepth, 0, H, cur, 0, cdep)) != FOV_OK) {
            fprintf(stderr, "fovlp_reconstruct_rows: %s\n", fovlp_result_string(r));
            return 1;
        }
        if (taa) {
            fovlp_taa_io io;
            fovlp_taa_io_init(&io);
            io.cur_rgb = cur; io.cur_depth = cdep;
            io.prev_rgb = hist[ping]; io.prev_depth = hdep[ping]; io.prev_age = age[ping];
            io.out_rgb = hist[1 - ping]; io.out_depth = hdep[1 - ping]; io.out_age = age[1 - ping];
            if ((r = fovlp_taa_rows(&lp, &io, 0, H, NULL)) != FOV_OK) {
                fprintf(stderr, "fovlp_taa_rows: %s\n", fovlp_result_string(r));
                return 1;
            }
            ping = 1 - ping;
            img = hist[ping];
        }
        t1 = now_ms();
        t_all += t1 - t0;
        fovlp_count_samples(&lp, &cnt);
        printf("frame %3u: %5.1f %% of the pixels shaded, %llu rays, %.1f ms\n", f, (double)cnt.shaded_pct,
               (unsigned long long)u.stats.rays, t1 - t0);
    }
    printf("%u frames in %.0f ms\n", frames, t_all);
    if (strcmp(out, "-") != 0) {
        if (write_ppm(out, &lp, img, W, H) != 0) { fprintf(stderr, "cannot write %s (does the directory exist?)\n", out); return 1; }
        printf("wrote %s\n", out);
    }
    pt_scene_free(&S);
    free(lpmem); free(samples); free(sdepth); free(cur); free(cdep);
    for (a = 0; a < 2; ++a) { free(hist[a]); free(hdep[a]); free(age[a]); }
    return 0;
}
