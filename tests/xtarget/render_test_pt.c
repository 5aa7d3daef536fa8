/* render_test_pt.c - the cross-target render test of fovpt.h (tests/xtarget/run.sh, targets
   named pt-*). Same dump format as render_test.c (compare.c reads both):

   Two scenes at XT_W x XT_H through the public API only, from static memory (the size
   queries are checked against it):
     scene 0 "box-path"      a Cornell-like box (quads, boxes, spheres, a 128-triangle mesh
                             behind a BVH), UNIFORM path tracing, 2 spp, NEE, Russian roulette
     scene 1 "box-selective" the same scene, SELECTIVE with the Whitted tracer (depth 3)
   rgb: the 8-bit sRGB image; hit / depth: the closest hit of the pixel-centre ray through
   fovpt_intersect (1 / the float bits of t; 0 / 0 for a miss); stats evals = all rays,
   primary = camera rays, rays = shadow rays, hits = bounce rays, exhausted = bad samples.

   XT_SEMIHOSTING / XT_EXTERNAL_IMPL: as in render_test.c. */
#ifndef XT_EXTERNAL_IMPL
#define FOVPT_IMPLEMENTATION
#endif
#if defined(XT_SEMIHOSTING) && !defined(FOV_ASSERT)
void xt_assert_fail(const char *expr, int line);
#define FOV_ASSERT(c) ((c) ? (void)0 : xt_assert_fail(#c, __LINE__))
#endif
#include "fovpt.h"

#ifndef XT_W
#define XT_W 64
#endif
#ifndef XT_H
#define XT_H 36
#endif
#ifndef XT_SCENE_MEM
#define XT_SCENE_MEM (64u * 1024u)
#endif
#ifndef XT_CTX_MEM
#define XT_CTX_MEM (XT_W * XT_H * 68u + 64u)
#endif

#include "xt_out.h"

/* ---- static memory ---- */
static uint64_t xt_scene_mem[XT_SCENE_MEM / 8u];
static uint64_t xt_ctx_mem[XT_CTX_MEM / 8u + 1u];
static uint8_t xt_rgb[XT_W * XT_H * 3];
static float xt_pos[3 * 3 * 128];

static fovpt_material xt_mat[6];
static fovpt_shape xt_sh[10];
static fovpt_mesh xt_mesh;

/* the scene: 5 quad walls, a quad light, a box, two spheres (Phong, glass), a mesh fan */
static fov_result xt_build(fovpt_scene *scene, size_t *bytes)
{
    fovpt_scene_desc d;
    uint32_t i;
    float c[3], u[3], v[3];
    for (i = 0; i < 6; i++) fovpt_material_init(&xt_mat[i]);
    xt_mat[1].albedo[1] = xt_mat[1].albedo[2] = 0.1f;
    xt_mat[2].albedo[0] = xt_mat[2].albedo[2] = 0.1f;
    xt_mat[3].emission[0] = xt_mat[3].emission[1] = xt_mat[3].emission[2] = 12.0f;
    xt_mat[4].type = FOVPT_MAT_PHONG;
    xt_mat[4].specular[0] = xt_mat[4].specular[1] = xt_mat[4].specular[2] = 0.15f;
    xt_mat[5].type = FOVPT_MAT_DIELECTRIC;
    xt_mat[5].albedo[0] = xt_mat[5].albedo[1] = xt_mat[5].albedo[2] = 1.0f;
#define XT_SET(a, x, y, z) (a[0] = (x), a[1] = (y), a[2] = (z))
    XT_SET(c, -1, 0, -1); XT_SET(u, 0, 0, 2); XT_SET(v, 2, 0, 0); fovpt_shape_quad(&xt_sh[0], c, u, v, 0);
    XT_SET(c, -1, 2, -1); XT_SET(u, 2, 0, 0); XT_SET(v, 0, 0, 2); fovpt_shape_quad(&xt_sh[1], c, u, v, 0);
    XT_SET(c, -1, 0, 1); XT_SET(u, 0, 2, 0); XT_SET(v, 2, 0, 0); fovpt_shape_quad(&xt_sh[2], c, u, v, 0);
    XT_SET(c, -1, 0, -1); XT_SET(u, 0, 2, 0); XT_SET(v, 0, 0, 2); fovpt_shape_quad(&xt_sh[3], c, u, v, 1);
    XT_SET(c, 1, 0, -1); XT_SET(u, 0, 0, 2); XT_SET(v, 0, 2, 0); fovpt_shape_quad(&xt_sh[4], c, u, v, 2);
    XT_SET(c, -0.25f, 1.999f, -0.25f); XT_SET(u, 0.5f, 0, 0); XT_SET(v, 0, 0, 0.5f); fovpt_shape_quad(&xt_sh[5], c, u, v, 3);
    XT_SET(c, 0.2f, 0, -0.5f); XT_SET(u, 0.7f, 0.6f, 0.0f); fovpt_shape_box(&xt_sh[6], c, u, 0);
    fovpt_shape_sphere(&xt_sh[7], -0.45f, 0.35f, 0.0f, 0.35f, 4);
    fovpt_shape_sphere(&xt_sh[8], 0.45f, 0.85f, -0.25f, 0.25f, 5);
    for (i = 0; i < 128; i++) { /* a grid of thin triangles on the back wall */
        float *p = xt_pos + 9u * i;
        p[0] = -0.4f; p[1] = 1.2f; p[2] = 0.99f;
        p[3] = -0.4f + 0.35f * (float)(i % 16u) / 16.0f; p[4] = 1.2f + 0.35f * (float)(i / 16u) / 8.0f; p[5] = 0.98f;
        p[6] = p[3] + 0.02f; p[7] = p[4] + 0.01f; p[8] = 0.97f;
    }
    xt_mesh.positions = xt_pos; xt_mesh.num_vertices = 3u * 128u; xt_mesh.indices = 0; xt_mesh.num_triangles = 128; xt_mesh.material = 2;
    fovpt_scene_desc_init(&d);
    d.shapes = xt_sh; d.num_shapes = 9; d.meshes = &xt_mesh; d.num_meshes = 1; d.materials = xt_mat; d.num_materials = 6;
    d.background[2] = 0.1f;
    if (fovpt_scene_size(&d, bytes) != FOV_OK) return FOV_ERR_INVALID_ARG;
    if (*bytes > sizeof xt_scene_mem) return FOV_ERR_TOO_SMALL;
    return fovpt_scene_build(scene, &d, xt_scene_mem, sizeof xt_scene_mem);
}

static int xt_scene(uint32_t id, const fovpt_scene *scene, size_t scene_bytes)
{
    fovpt_config cfg = fovpt_config_default();
    fovpt_camera cam;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    fov_gaze gaze;
    size_t ctx_bytes = 0;
    fov_result r = FOV_OK;
    const char *step = "ok";
    uint32_t x, y;
    {
        static fovpt_stats zero_stats;
        st = zero_stats;
    }
    for (y = 0; y < XT_W * XT_H * 3; y++) xt_rgb[y] = 0;
    xt_puts("scene "); xt_putu(id); xt_putc(' '); xt_puts(id ? "box-selective" : "box-path"); xt_endl();
    xt_puts("memory scene "); xt_putu((uint64_t)scene_bytes); xt_puts(" of "); xt_putu((uint64_t)sizeof xt_scene_mem); xt_endl();
    fovpt_camera_init(&cam, XT_W, XT_H);
    cam.pos[1] = 1.0f; cam.pos[2] = -3.2f; cam.target[1] = 1.0f; cam.target[2] = 0.0f; cam.fov_y_deg = 45.0f;
    gaze.x = 0.4f * (float)XT_W;
    gaze.y = 0.5f * (float)XT_H;
    if (id == 0) { cfg.spp = 2; cfg.sampler = FOVPT_SAMPLER_SOBOL; }
    else { cfg.method = FOVPT_METHOD_SELECTIVE; cfg.mode = FOVPT_MODE_WHITTED; cfg.sampler = FOVPT_SAMPLER_RANDOM; }
    r = fovpt_memory_size(&cfg, &cam, &ctx_bytes);
    if (r != FOV_OK) { step = "memory_size"; goto done; }
    if (ctx_bytes > sizeof xt_ctx_mem) { r = FOV_ERR_TOO_SMALL; step = "ctx_memory"; goto done; }
    r = fovpt_init(&ctx, &cfg, scene, &cam, gaze, xt_ctx_mem, sizeof xt_ctx_mem);
    if (r != FOV_OK) { step = "init"; goto done; }
    fovpt_output_init(&out);
    out.rgb8 = xt_rgb;
    r = fovpt_render(&ctx, 0, &out, &st);
    if (r != FOV_OK) { step = "render"; goto done; }
done:
    xt_puts("status "); xt_puti((int32_t)r); xt_putc(' '); xt_puts(step); xt_endl();
    xt_puts("stats evals "); xt_putu(st.rays);
    xt_puts(" primary "); xt_putu(st.camera_rays);
    xt_puts(" rays "); xt_putu(st.shadow_rays);
    xt_puts(" hits "); xt_putu(st.bounce_rays);
    xt_puts(" exhausted "); xt_putu(st.bad_samples);
    xt_endl();
    xt_dump_image(xt_rgb, NULL, NULL, XT_W, XT_H);
    /* the BVH on this target: the closest hit of every pixel-centre ray */
    xt_puts("hit"); xt_endl();
    for (y = 0; y < XT_H; y++) {
        for (x = 0; x < XT_W; x++) {
            float o[3], dir[3];
            fovpt_hit h;
            int hit = fovpt_camera_ray(&cam, (float)x + 0.5f, (float)y + 0.5f, o, dir) == FOV_OK &&
                      fovpt_intersect(scene, o, dir, 0.0f, 1e30f, &h);
            xt_putc(hit ? '1' : '0');
        }
        xt_endl();
    }
    xt_puts("depth"); xt_endl();
    for (y = 0; y < XT_H; y++) {
        for (x = 0; x < XT_W; x++) {
            float o[3], dir[3];
            fovpt_hit h;
            float t = 0.0f;
            if (fovpt_camera_ray(&cam, (float)x + 0.5f, (float)y + 0.5f, o, dir) == FOV_OK &&
                fovpt_intersect(scene, o, dir, 0.0f, 1e30f, &h))
                t = h.t;
            xt_puthex(xt_float_bits(t), 8);
        }
        xt_endl();
    }
    xt_puts("end"); xt_endl();
    return (int)r;
}

int main(void)
{
    static fovpt_scene scene;
    size_t bytes = 0;
    int status = 0;
    xt_puts("fovxt 1 "); xt_putu(XT_W); xt_putc(' '); xt_putu(XT_H); xt_endl();
    if (xt_build(&scene, &bytes) != FOV_OK) {
        xt_puts("error scene build"); xt_endl();
        status = 1;
    } else {
        if (xt_scene(0, &scene, bytes) != 0) status = 1;
        if (xt_scene(1, &scene, bytes) != 0) status = 1;
    }
    xt_puts("done "); xt_puti(status); xt_endl();
#ifndef XT_SEMIHOSTING
    (void)fflush(stdout);
#endif
    return status;
}
