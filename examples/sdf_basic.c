/* sdf_basic.c - the smallest fovsdf program: a sphere on a plane, written as a PPM image.
   Build: cc -O2 examples/sdf_basic.c -I. -lm -o sdf_basic && ./sdf_basic > basic.ppm */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static float scene_sdf(const float p[3], void *user)
{
    float sphere = sqrtf(p[0] * p[0] + (p[1] - 1.0f) * (p[1] - 1.0f) + p[2] * p[2]) - 1.0f;
    float ground = p[1];
    (void)user;
    return sphere < ground ? sphere : ground;
}

int main(int argc, char **argv)
{
    static uint8_t pixels[320 * 240 * 3];
    fovsdf_scene scene;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats stats;
    fov_gaze gaze = { 160.0f, 120.0f };
    fov_result r;
    if (argc > 1) { /* no options: -h / --help prints the usage (exit 0), anything else exits 2 */
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        fputs("usage: sdf_basic > basic.ppm\n  writes a 320x240 PPM to stdout; no options\n  -h, --help  this text\n",
              help ? stdout : stderr);
        return help ? 0 : 2;
    }

    fovsdf_scene_init(&scene);            /* one sun, a sky gradient */
    scene.dist = scene_sdf;
    fovsdf_camera_init(&cam, 320, 240);
    cam.pos[0] = 0.0f; cam.pos[1] = 2.0f; cam.pos[2] = -5.0f;
    cam.target[1] = 0.8f;
    r = fovsdf_init(&ctx, &cfg, &scene, &cam, gaze, NULL, 0);
    if (r != FOV_OK) { fprintf(stderr, "fovsdf_init: %s\n", fovsdf_result_string(r)); return 1; }
    fovsdf_output_init(&out);
    out.rgb8 = pixels;
    fovsdf_stats_init(&stats);            /* counters; render calls add to them */
    fovsdf_render_rows(&ctx, 0, 240, &out, &stats);  /* or split rows across threads */
    printf("P6\n320 240\n255\n");
    fwrite(pixels, 1, sizeof pixels, stdout);
    fprintf(stderr, "%.1f distance evaluations per pixel\n", (double)stats.evals / (320.0 * 240.0));
    return 0;
}
