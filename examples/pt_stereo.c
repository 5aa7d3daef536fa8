/* pt_stereo.c - stereo with fovpt: a head camera split into two eyes (fovpt_camera_eyes),
   each given an off-axis frustum (tangents as OpenVR's GetProjectionRaw or OpenXR's XrFovf
   give them, each eye seeing more outwards) and its own gaze (both eyes fixate one point:
   fovpt_gaze_from_point per eye), path traced with the foveation layers of Axblad 2020
   (grown by a gaze filter's latency margin) and written side by side as one PPM. Without an
   eye tracker use fovpt_gaze_fixed and FOV_GAZE_FIXED_MARGIN_DEG instead (GAZE INPUT).
   Build: cc -O2 examples/pt_stereo.c -I. -lm -o pt_stereo && ./pt_stereo > pt_stereo.ppm */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EW 128 /* one eye's image */
#define EH 144

int main(int argc, char **argv)
{
    static uint8_t pixels[2 * EW * EH * 3];
    static const float fixate[3] = { 0.6f, 0.5f, 0.0f }; /* the glass ball */
    fovpt_material mat[4];
    fovpt_shape shapes[4];
    fovpt_scene_desc desc;
    fovpt_scene scene;
    fovpt_camera head, eyes[2];
    fovpt_config base = fovpt_config_default(), cfg;
    fov_gaze_filter gf;
    float floor_pt[3] = { 0.0f, 0.0f, 0.0f }, up[3] = { 0.0f, 1.0f, 0.0f }, margin = 0.0f;
    size_t scene_bytes = 0;
    void *scene_mem;
    fov_result r;
    int eye;
    if (argc > 1) { /* no options: -h / --help prints the usage (exit 0), anything else exits 2 */
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        fputs("usage: pt_stereo > pt_stereo.ppm\n  writes the two eyes side by side, a 256x144 "
              "PPM, to stdout; no options\n  -h, --help  this text\n", help ? stdout : stderr);
        return help ? 0 : 2;
    }
    fovpt_material_init(&mat[0]);
    fovpt_material_init(&mat[1]);
    mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 20.0f;
    fovpt_material_init(&mat[2]);
    mat[2].type = FOVPT_MAT_DIELECTRIC;
    mat[2].albedo[0] = mat[2].albedo[1] = mat[2].albedo[2] = 1.0f;
    fovpt_material_init(&mat[3]);
    mat[3].albedo[0] = 0.5f; mat[3].albedo[1] = 0.45f; mat[3].albedo[2] = 0.4f;
    fovpt_shape_plane(&shapes[0], floor_pt, up, 3);
    fovpt_shape_sphere(&shapes[1], -0.6f, 0.5f, 0.0f, 0.5f, 0);
    fovpt_shape_sphere(&shapes[2], 0.6f, 0.5f, 0.0f, 0.5f, 2);
    fovpt_shape_sphere(&shapes[3], 0.0f, 3.0f, 0.5f, 0.4f, 1);
    fovpt_scene_desc_init(&desc);
    desc.shapes = shapes; desc.num_shapes = 4;
    desc.materials = mat; desc.num_materials = 4;
    desc.background[0] = 0.1f; desc.background[1] = 0.12f; desc.background[2] = 0.18f;
    if ((r = fovpt_scene_size(&desc, &scene_bytes)) != FOV_OK) return 1;
    scene_mem = malloc(scene_bytes + 16u);
    if (!scene_mem || (r = fovpt_scene_build(&scene, &desc, scene_mem, scene_bytes)) != FOV_OK)
        return 1;
    /* the filter's margin for a still eye, 50 ms of latency, 0.5 degrees of accuracy */
    fovpt_gaze_filter_init(&gf, NULL);
    {
        uint32_t i;
        for (i = 0; i < 60; ++i)
            fovpt_gaze_filter_push(&gf, 8333u * i, -3.0f + 0.1f * (float)(i % 3), 1.0f);
    }
    fovpt_gaze_margin(&gf, 0.5f, 50.0f, &margin);
    base.method = FOVPT_METHOD_LAYERS;
    base.spp = 1;
    if ((r = fovpt_config_gaze_margin(&base, margin, &cfg)) != FOV_OK) return 1;
    fovpt_camera_init(&head, EW, EH);
    head.pos[0] = 0.0f; head.pos[1] = 1.0f; head.pos[2] = -3.0f;
    head.target[0] = 0.0f; head.target[1] = 0.5f; head.target[2] = 0.0f;
    if ((r = fovpt_camera_eyes(&head, 0.064f, eyes)) != FOV_OK) return 1;
    for (eye = 0; eye < 2; ++eye) {
        fovpt_camera *cam = &eyes[eye];
        fovpt_ctx ctx;
        fovpt_output out;
        fovpt_stats st;
        fov_gaze g;
        size_t bytes = 0;
        void *mem;
        cam->tan_left = eye == 0 ? 0.9f : 0.7f; /* each eye sees more outwards */
        cam->tan_right = eye == 0 ? 0.7f : 0.9f;
        cam->tan_bottom = 0.9f; cam->tan_top = 0.9f;
        if ((r = fovpt_gaze_from_point(cam, fixate, &g)) != FOV_OK ||
            (r = fovpt_memory_size(&cfg, cam, &bytes)) != FOV_OK) {
            fprintf(stderr, "%s\n", fovpt_result_string(r));
            return 1;
        }
        mem = malloc(bytes + 16u);
        if (!mem || (r = fovpt_init(&ctx, &cfg, &scene, cam, g, mem, bytes)) != FOV_OK) {
            fprintf(stderr, "fovpt_init: %s\n", fovpt_result_string(r));
            return 1;
        }
        fovpt_output_init(&out);
        out.rgb8 = pixels + (size_t)eye * EW * 3;    /* the left or right half */
        out.rgb8_stride = 2 * EW * 3;                /* a row of the side-by-side image */
        fovpt_stats_init(&st);
        fovpt_render(&ctx, 0, &out, &st);
        fprintf(stderr, "%s eye: gaze (%.1f, %.1f), margin %.2f deg, %llu rays\n",
                eye ? "right" : "left", (double)g.x, (double)g.y, (double)margin,
                (unsigned long long)st.rays);
        free(mem);
    }
    printf("P6\n%d %d\n255\n", 2 * EW, EH);
    fwrite(pixels, 1, sizeof pixels, stdout);
    free(scene_mem);
    return 0;
}
