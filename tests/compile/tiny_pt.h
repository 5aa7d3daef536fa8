/* tiny_pt.h - a tiny fovpt render shared by the compile tests (include fovpt.h first).
   Defines one static function, tiny_pt_render(), so every includer must call it. No malloc:
   static buffers sized by the size queries (checked). */
#ifndef TINY_PT_H_INCLUDED
#define TINY_PT_H_INCLUDED

#define TINY_PT_W 8
#define TINY_PT_H 6

/* Renders a grey sphere lit by a quad light, UNIFORM (path, 2 spp) and LAYERS (Whitted),
   into rgb (TINY_PT_W * TINY_PT_H * 3 bytes: the byte-wise sum of both images). Returns 0
   on success, else a small positive code saying which step failed; *rays gets the ray count. */
static int tiny_pt_render(uint8_t *rgb, uint64_t *rays)
{
    static uint64_t scene_mem[256], ctx_mem[512];
    static uint8_t img2[TINY_PT_W * TINY_PT_H * 3];
    fovpt_material mat[2];
    fovpt_shape sh[2];
    fovpt_scene_desc desc;
    fovpt_scene scene;
    fovpt_camera cam;
    fovpt_config cfg;
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats st;
    fov_gaze gaze;
    size_t bytes = 0;
    uint32_t i;
    float corner[3] = { -0.5f, 2.0f, -0.5f }, u[3] = { 1.0f, 0.0f, 0.0f }, v[3] = { 0.0f, 0.0f, 1.0f };
    {
        static fovpt_stats zero_stats;
        st = zero_stats;
    }
    *rays = 0;
    if (fovpt_result_string(FOV_ERR_NULL) == NULL) return 1;
    fovpt_material_init(&mat[0]);
    fovpt_material_init(&mat[1]);
    mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 5.0f;
    fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 0);
    fovpt_shape_quad(&sh[1], corner, u, v, 1);
    fovpt_scene_desc_init(&desc);
    desc.shapes = sh; desc.num_shapes = 2; desc.materials = mat; desc.num_materials = 2;
    desc.background[2] = 0.2f;
    if (fovpt_scene_size(&desc, &bytes) != FOV_OK) return 2;
    if (bytes > sizeof scene_mem) return 3;
    if (fovpt_scene_build(&scene, &desc, scene_mem, sizeof scene_mem) != FOV_OK) return 4;
    fovpt_camera_init(&cam, TINY_PT_W, TINY_PT_H);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -3.0f;
    gaze.x = 0.5f * (float)TINY_PT_W;
    gaze.y = 0.5f * (float)TINY_PT_H;
    cfg = fovpt_config_default();
    cfg.spp = 2;
    if (fovpt_memory_size(&cfg, &cam, &bytes) != FOV_OK) return 5;
    if (bytes > sizeof ctx_mem) return 6;
    if (fovpt_init(&ctx, &cfg, &scene, &cam, gaze, ctx_mem, sizeof ctx_mem) != FOV_OK) return 7;
    fovpt_output_init(&out);
    out.rgb8 = rgb;
    if (fovpt_render(&ctx, 0, &out, &st) != FOV_OK) return 8;
    cfg.method = FOVPT_METHOD_LAYERS;
    cfg.mode = FOVPT_MODE_WHITTED;
    cfg.max_depth = 0;
    if (fovpt_memory_size(&cfg, &cam, &bytes) != FOV_OK) return 9;
    if (bytes > sizeof ctx_mem) return 10;
    if (fovpt_init(&ctx, &cfg, &scene, &cam, gaze, ctx_mem, sizeof ctx_mem) != FOV_OK) return 11;
    out.rgb8 = img2;
    if (fovpt_render(&ctx, 0, &out, &st) != FOV_OK) return 12;
    for (i = 0; i < TINY_PT_W * TINY_PT_H * 3; ++i) rgb[i] = (uint8_t)(rgb[i] + img2[i]);
    if (st.rays == 0 || st.camera_rays == 0) return 13;
    *rays = st.rays;
    return 0;
}
#endif
