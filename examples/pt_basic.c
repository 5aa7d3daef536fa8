/* pt_basic.c - the smallest fovpt program: a grey ball and a glass ball under a lamp, path
   traced with the foveation layers of Axblad 2020, Sec. 3.1.3 (gaze at the image centre),
   written as a PPM image. Axblad 2020: T. Axblad, "Impact of Foveated Rendering on Path
   Tracing Frame Rate in Head-Mounted VR Displays", master's thesis, KTH, 2020.
   Build: cc -O2 examples/pt_basic.c -I. -lm -o pt_basic && ./pt_basic > pt_basic.ppm
   (stderr: the rays traced per layer and in total) */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    static uint8_t pixels[320 * 240 * 3];
    fovpt_material mat[4];
    fovpt_shape shapes[4];
    fovpt_scene_desc desc;
    fovpt_scene scene;
    fovpt_camera cam;
    fovpt_config cfg = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats stats;
    fov_gaze gaze = { 160.0f, 120.0f };
    float floor_pt[3] = { 0.0f, 0.0f, 0.0f }, up[3] = { 0.0f, 1.0f, 0.0f };
    size_t scene_bytes = 0, ctx_bytes = 0;
    void *scene_mem, *ctx_mem;
    fov_result r;
    uint32_t n;
    if (argc > 1) { /* no options: -h / --help prints the usage (exit 0), anything else exits 2 */
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        fputs("usage: pt_basic > pt_basic.ppm\n  writes a 320x240 PPM to stdout, the rays per layer to stderr; no options\n"
              "  -h, --help  this text\n", help ? stdout : stderr);
        return help ? 0 : 2;
    }

    fovpt_material_init(&mat[0]);                       /* grey Lambert */
    fovpt_material_init(&mat[1]);                       /* the lamp */
    mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 20.0f;
    fovpt_material_init(&mat[2]);                       /* glass */
    mat[2].type = FOVPT_MAT_DIELECTRIC;
    mat[2].albedo[0] = mat[2].albedo[1] = mat[2].albedo[2] = 1.0f;
    fovpt_material_init(&mat[3]);                       /* a shiny floor (Axblad's Phong) */
    mat[3].type = FOVPT_MAT_PHONG;
    mat[3].albedo[0] = 0.5f; mat[3].albedo[1] = 0.45f; mat[3].albedo[2] = 0.4f;
    mat[3].specular[0] = mat[3].specular[1] = mat[3].specular[2] = 0.3f;
    fovpt_shape_plane(&shapes[0], floor_pt, up, 3);
    fovpt_shape_sphere(&shapes[1], -0.6f, 0.5f, 0.0f, 0.5f, 0);
    fovpt_shape_sphere(&shapes[2], 0.6f, 0.5f, 0.0f, 0.5f, 2);
    fovpt_shape_sphere(&shapes[3], 0.0f, 3.0f, 0.5f, 0.4f, 1);

    fovpt_scene_desc_init(&desc);
    desc.shapes = shapes; desc.num_shapes = 4;
    desc.materials = mat; desc.num_materials = 4;
    desc.background[0] = 0.1f; desc.background[1] = 0.12f; desc.background[2] = 0.18f;
    if ((r = fovpt_scene_size(&desc, &scene_bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
    scene_mem = malloc(scene_bytes + 16u);
    if ((r = fovpt_scene_build(&scene, &desc, scene_mem, scene_bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }

    fovpt_camera_init(&cam, 320, 240);
    cam.pos[0] = 0.0f; cam.pos[1] = 1.0f; cam.pos[2] = -3.0f;
    cam.target[0] = 0.0f; cam.target[1] = 0.5f; cam.target[2] = 0.0f;
    cfg.method = FOVPT_METHOD_LAYERS;                   /* 6/10/20 degree layers, d = 1..4, 4 spp */
    if ((r = fovpt_memory_size(&cfg, &cam, &ctx_bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
    ctx_mem = malloc(ctx_bytes + 16u);
    if ((r = fovpt_init(&ctx, &cfg, &scene, &cam, gaze, ctx_mem, ctx_bytes)) != FOV_OK) {
        fprintf(stderr, "%s\n", fovpt_result_string(r));
        return 1;
    }
    fovpt_output_init(&out);
    out.rgb8 = pixels;
    fovpt_stats_init(&stats);                           /* counters; every call adds to them */
    fovpt_render(&ctx, 0, &out, &stats);                /* or trace/resolve rows on threads */

    for (n = 0; n < ctx.lay.count; ++n)
        fprintf(stderr, "layer %u: %llu target pixels, %llu samples\n", n, (unsigned long long)stats.layer_targets[n],
                (unsigned long long)stats.layer_samples[n]);
    fprintf(stderr, "%llu rays in total (UNIFORM at 4 spp: %u camera rays)\n", (unsigned long long)stats.rays, 320u * 240u * 4u);
    printf("P6\n320 240\n255\n");
    fwrite(pixels, 1, sizeof pixels, stdout);
    free(ctx_mem);
    free(scene_mem);
    return 0;
}
