/* pt_basic.c - the smallest fovpt program: a grey ball and a glass ball under a lamp, path
   traced with the foveation layers of Axblad 2020, Sec. 3.1.3 (gaze at the image centre),
   denoised by fovpt's foveated filter (guide buffers, temporal accumulation over a few frames
   of a still camera, the edge-avoiding a-trous wavelet filter of Dammertz et al. 2010 with
   the variance guidance of Schied et al. 2017), written as a 640x360 PPM image with the
   gaze marked (a ring of 6 degrees, the innermost layer's radius).
   Axblad 2020: T. Axblad, "Impact of Foveated Rendering on Path Tracing Frame Rate in
   Head-Mounted VR Displays", master's thesis, KTH, 2020. Dammertz et al. 2010: H. Dammertz,
   D. Sewtz, J. Hanika, H. Lensch, "Edge-Avoiding A-Trous Wavelet Transform for fast Global
   Illumination Filtering", High Performance Graphics 2010. Schied et al. 2017: C. Schied et
   al., "Spatiotemporal Variance-Guided Filtering: Real-Time Reconstruction for Path-Traced
   Global Illumination", High Performance Graphics 2017.
   Build: cc -O2 examples/pt_basic.c -I. -lm -o pt_basic && ./pt_basic > pt_basic.ppm
   (stderr: the rays traced per layer and in total)
   ./pt_basic --pair > pair.ppm: the denoised image (no ring) beside a 256 spp UNIFORM
   reference (1284x360; `make gallery` turns it into docs/img/pt_denoise.png; about a minute) */
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 640u
#define H 360u
#define FRAMES 8u

/* a ring around the gaze, radius r pixels: dark outline, light core */
static void mark_gaze(uint8_t *px, float gx, float gy, float r)
{
    uint32_t x, y;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            float dx = (float)x + 0.5f - gx, dy = (float)y + 0.5f - gy, d2 = dx * dx + dy * dy;
            uint8_t *p = px + 3u * ((size_t)y * W + x);
            if (d2 >= (r - 2.5f) * (r - 2.5f) && d2 <= (r + 2.5f) * (r + 2.5f)) p[0] = p[1] = p[2] = 20;
            if (d2 >= (r - 1.0f) * (r - 1.0f) && d2 <= (r + 1.0f) * (r + 1.0f)) { p[0] = 255; p[1] = 220; p[2] = 60; }
            if (d2 <= 4.0f) { p[0] = 255; p[1] = 220; p[2] = 60; }
        }
}

int main(int argc, char **argv)
{
    static uint8_t pixels[W * H * 3], refpix[W * H * 3];
    static float noisy[W * H * 3], albedo[W * H * 3], normal[W * H * 3], depth[W * H], spp[W * H], var[W * H];
    fovpt_material mat[4];
    fovpt_shape shapes[4];
    fovpt_scene_desc desc;
    fovpt_scene scene;
    fovpt_camera cam;
    fovpt_config cfg = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats stats;
    fovpt_guide guide;
    fovpt_denoise dn;
    fovpt_denoise_cfg dcfg = fovpt_denoise_cfg_default();
    fov_gaze gaze = { 320.0f, 180.0f };
    fov_ecc_model ecc;
    float floor_pt[3] = { 0.0f, 0.0f, 0.0f }, up[3] = { 0.0f, 1.0f, 0.0f }, r6;
    size_t scene_bytes = 0, ctx_bytes = 0, dn_bytes = 0;
    void *scene_mem, *ctx_mem, *dn_mem;
    fov_result r;
    uint32_t n, f, x, y;
    int pair = 0;
    if (argc > 1) { /* --pair, -h / --help (exit 0); anything else exits 2 */
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        pair = !strcmp(argv[1], "--pair");
        if (!pair || argc > 2) {
            fputs("usage: pt_basic [--pair] > pt_basic.ppm\n  writes a 640x360 PPM to stdout (denoised, gaze marked), the rays per layer to stderr\n"
                  "  --pair      the denoised image beside a 256 spp reference (1284x360)\n"
                  "  -h, --help  this text\n", help ? stdout : stderr);
            return help ? 0 : 2;
        }
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

    fovpt_camera_init(&cam, W, H);
    cam.pos[0] = 0.0f; cam.pos[1] = 1.0f; cam.pos[2] = -3.0f;
    cam.target[0] = 0.0f; cam.target[1] = 0.5f; cam.target[2] = 0.0f;
    cfg.method = FOVPT_METHOD_LAYERS;                   /* 6/10/20 degree layers, d = 1..4, 4 spp */
    cfg.layers.count = 0;                               /* the preset's table (KTH radius) ... */
    cfg.layers.bspline = 1;                             /* ... smoothing B-spline for the coarse layers */
    cfg.layers.cell_jitter = 1;                         /* samples over the lattice cell */
    cfg.sampler = FOVPT_SAMPLER_SOBOL;                  /* stratified samples (the default; fovpt.h SAMPLERS) */

    if ((r = fovpt_memory_size(&cfg, &cam, &ctx_bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
    ctx_mem = malloc(ctx_bytes + 16u);
    if ((r = fovpt_init(&ctx, &cfg, &scene, &cam, gaze, ctx_mem, ctx_bytes)) != FOV_OK) {
        fprintf(stderr, "%s\n", fovpt_result_string(r));
        return 1;
    }
    /* the denoiser: caller memory, the guides the trace writes */
    dcfg.width = W; dcfg.height = H;
    if ((r = fovpt_denoise_size(&dcfg, &dn_bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
    dn_mem = malloc(dn_bytes);
    if ((r = fovpt_denoise_init(&dn, &dcfg, dn_mem, dn_bytes)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
    fovpt_guide_init(&guide);
    guide.albedo = albedo; guide.normal = normal; guide.depth = depth; guide.spp = spp; guide.var = var;
    fovpt_stats_init(&stats);                           /* counters; every call adds to them */
    for (f = 0; f < FRAMES; ++f) {                      /* a still camera: the history adds up */
        fovpt_output_init(&out);
        out.rgb = noisy;
        /* or fovpt_trace_rows_guide / resolve rows on threads */
        if ((r = fovpt_render_guide(&ctx, f, &out, &guide, &stats)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
        if ((r = fovpt_denoise_frame(&dn, &cam, gaze, noisy, 0, &guide)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
        fovpt_output_init(&out);
        out.rgb8 = pixels;
        /* or fovpt_denoise_temporal_rows, _atrous_rows, _resolve_rows by rows */
        if ((r = fovpt_denoise_run(&dn, &out)) != FOV_OK) { fprintf(stderr, "%s\n", fovpt_result_string(r)); return 1; }
    }
    for (n = 0; n < ctx.lay.count; ++n)
        fprintf(stderr, "layer %u: %llu target pixels, %llu samples\n", n, (unsigned long long)stats.layer_targets[n],
                (unsigned long long)stats.layer_samples[n]);
    fprintf(stderr, "%llu rays in total over %u frames (UNIFORM at 4 spp: %u camera rays per frame)\n", (unsigned long long)stats.rays,
            FRAMES, W * H * 4u);
    if (!pair) {
        /* the ring: 6 degrees from the gaze, along the image's x axis */
        fovpt_ecc_init(&ecc, NULL, cam.fov_y_deg, W, H, gaze);
        for (r6 = 0.0f; r6 < (float)W && fovpt_ecc_deg(&ecc, gaze.x + r6, gaze.y) < 6.0f; r6 += 0.5f) {}
        mark_gaze(pixels, gaze.x, gaze.y, r6);
        printf("P6\n%u %u\n255\n", W, H);
        fwrite(pixels, 1, sizeof pixels, stdout);
    } else {
        fovpt_config rc = fovpt_config_default();
        void *rm;
        rc.spp = 256; rc.seed = 777;
        fovpt_memory_size(&rc, &cam, &ctx_bytes);
        rm = malloc(ctx_bytes + 16u);
        fovpt_init(&ctx, &rc, &scene, &cam, gaze, rm, ctx_bytes);
        fovpt_output_init(&out);
        out.rgb8 = refpix;
        fovpt_render(&ctx, 0, &out, NULL);
        free(rm);
        printf("P6\n%u %u\n255\n", 2u * W + 4u, H);
        for (y = 0; y < H; ++y) {
            static const uint8_t gut[12] = { 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255 };
            fwrite(pixels + 3u * W * y, 1, 3u * W, stdout);
            fwrite(gut, 1, sizeof gut, stdout);
            fwrite(refpix + 3u * W * y, 1, 3u * W, stdout);
        }
        (void)x;
    }
    free(dn_mem);
    free(ctx_mem);
    free(scene_mem);
    return 0;
}
