/* tiny_scene.h - a tiny fovsdf render shared by the compile tests (include fovsdf.h first).
   Defines one static function, tiny_render(), so every includer must call it. */
#ifndef TINY_SCENE_H
#define TINY_SCENE_H

#define TINY_W 8
#define TINY_H 6

/* distance bound of the cube [-1, 1]^3 (max-norm minus 1: never above the true distance) */
static float tiny_cube(const float p[3], void *user)
{
    float ax = p[0] < 0.0f ? -p[0] : p[0];
    float ay = p[1] < 0.0f ? -p[1] : p[1];
    float az = p[2] < 0.0f ? -p[2] : p[2];
    float m = ax > ay ? ax : ay;
    (void)user;
    m = m > az ? m : az;
    return m - 1.0f;
}

/* Renders the cube from z = -3 into rgb (TINY_W * TINY_H * 3 bytes). Returns 0 on success,
   else a small positive code saying which step failed; *evals gets the evaluation count. */
static int tiny_render(uint8_t *rgb, uint64_t *evals)
{
    static uint64_t mem[256];
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_scene scene;
    fovsdf_camera cam;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats st;
    fov_gaze gaze;
    size_t bytes = 0;
    const char *s;

    {
        static fovsdf_stats zero_stats; /* zero: static storage */
        st = zero_stats;
    }
    *evals = 0;
    s = fovsdf_result_string(FOV_ERR_NULL);
    if (s == NULL) return 1;
    fovsdf_scene_init(&scene);
    scene.dist = tiny_cube;
    fovsdf_camera_init(&cam, TINY_W, TINY_H);
    cam.pos[2] = -3.0f;
    gaze.x = 0.5f * (float)TINY_W;
    gaze.y = 0.5f * (float)TINY_H;
    if (fovsdf_memory_size(&cfg, &cam, &bytes) != FOV_OK) return 2;
    if (bytes > sizeof mem) return 3;
    if (fovsdf_init(&ctx, &cfg, &scene, &cam, gaze, bytes > 0 ? (void *)mem : NULL, bytes) !=
        FOV_OK)
        return 4;
    fovsdf_output_init(&out);
    out.rgb8 = rgb;
    if (fovsdf_render_rows(&ctx, 0, TINY_H, &out, &st) != FOV_OK) return 5;
    if (st.evals == 0 || st.hits == 0 || st.hits == st.rays) return 6;
    *evals = st.evals;
    return 0;
}

#endif /* TINY_SCENE_H */
