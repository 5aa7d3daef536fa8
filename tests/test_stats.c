/* test_stats.c - the counters of the three headers: the init functions clear every byte, and
   the counts accumulate across calls exactly as documented at fovpt_stats, fovsdf_stats and
   fovlp_taa_stats (added to, never reset).

   fovpt, for UNIFORM, LAYERS and SELECTIVE: one render into a cleared struct gives s1 (its
   sample count checked against the pixel count computed here); a second identical render
   into the same struct gives exactly 2 s1 in every field, whatever fovpt_resolve_rows,
   fovpt_reset and fovpt_init called in between (they must not touch the struct); trace and
   refine split over two "threads" and summed with fovpt_stats_add give s1;
   rays = camera_rays + bounce_rays + shadow_rays throughout, also for fovpt_radiance alone.
   fovsdf: two renders give twice one render (rays = pixels); fovsdf_stats_add sums.
   fovlp: two TAA resolves give pixels = 2 W H. Prints one line per check and
   "N passed, N failed". */
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOV_IMPL
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"
#include "fovcheck.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N fovcheck_name

static int all_zero(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i) if (b[i]) return 0;
    return 1;
}

static void test_inits(void)
{
    fovsdf_stats a;
    fovpt_stats b;
    fovlp_taa_stats c;
    fovlp_taa_io d;
    float f = 0.0f;
    uint8_t u = 0;
    memset(&a, 0xAB, sizeof a); fovsdf_stats_init(&a);
    memset(&b, 0xAB, sizeof b); fovpt_stats_init(&b);
    memset(&c, 0xAB, sizeof c); fovlp_taa_stats_init(&c);
    check(all_zero(&a, sizeof a), "fovsdf_stats_init_clears_every_byte", "not all zero");
    check(all_zero(&b, sizeof b), "fovpt_stats_init_clears_every_byte", "not all zero");
    check(all_zero(&c, sizeof c), "fovlp_taa_stats_init_clears_every_byte", "not all zero");
    d.cur_rgb = d.cur_depth = d.prev_rgb = d.prev_depth = &f;
    d.out_rgb = d.out_depth = &f;
    d.prev_age = d.out_age = &u;
    fovlp_taa_io_init(&d);
    check(!d.cur_rgb && !d.cur_depth && !d.prev_rgb && !d.prev_depth && !d.prev_age && !d.out_rgb &&
              !d.out_depth && !d.out_age,
          "fovlp_taa_io_init_sets_every_pointer_null", "a pointer is left set");
    fovsdf_stats_init(NULL); fovpt_stats_init(NULL); fovlp_taa_stats_init(NULL);
    fovlp_taa_io_init(NULL); fovpt_stats_add(NULL, &b); fovpt_stats_add(&b, NULL);
    fovsdf_stats_add(&a, NULL);
    check(all_zero(&a, sizeof a) && all_zero(&b, sizeof b), "inits_and_adds_accept_null",
          "a NULL argument changed a counter");
}

/* ---- fovpt -------------------------------------------------------------------------------- */
#define PW 40u
#define PH 30u

typedef struct pt_env {
    fovpt_material mat[2];
    fovpt_shape sh[3];
    fovpt_scene_desc d;
    fovpt_scene scene;
    fovpt_camera cam;
    void *smem;
} pt_env;

static int pt_scene(pt_env *e)
{
    size_t sb = 0;
    float p0[3] = { 0.0f, -1.0f, 0.0f }, n0[3] = { 0.0f, 1.0f, 0.0f };
    fovpt_material_init(&e->mat[0]);
    fovpt_material_init(&e->mat[1]);
    e->mat[1].emission[0] = e->mat[1].emission[1] = e->mat[1].emission[2] = 4.0f;
    fovpt_shape_sphere(&e->sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 0);
    fovpt_shape_sphere(&e->sh[1], 0.0f, 3.0f, 0.0f, 0.5f, 1);
    fovpt_shape_plane(&e->sh[2], p0, n0, 0);
    fovpt_scene_desc_init(&e->d);
    e->d.shapes = e->sh; e->d.num_shapes = 3; e->d.materials = e->mat; e->d.num_materials = 2;
    if (fovpt_scene_size(&e->d, &sb) != FOV_OK) return 0;
    e->smem = malloc(sb);
    if (fovpt_scene_build(&e->scene, &e->d, e->smem, sb) != FOV_OK) return 0;
    fovpt_camera_init(&e->cam, PW, PH);
    e->cam.pos[2] = -4.0f;
    return 1;
}

/* every field of b equal to k times the same field of a */
static int pt_times(const fovpt_stats *a, const fovpt_stats *b, uint64_t k, char *why, size_t cap)
{
    const uint64_t *pa = (const uint64_t *)(const void *)a, *pb = (const uint64_t *)(const void *)b;
    size_t i, n = sizeof *a / sizeof(uint64_t);
    for (i = 0; i < n; ++i)
        if (pb[i] != k * pa[i]) {
            snprintf(why, cap, "field %zu: %llu, want %llu x %llu", i, (unsigned long long)pb[i],
                     (unsigned long long)k, (unsigned long long)pa[i]);
            return 0;
        }
    return 1;
}

static int pt_rays_sum(const fovpt_stats *s)
{
    return s->rays == s->camera_rays + s->bounce_rays + s->shadow_rays;
}

static void test_fovpt_method(pt_env *e, uint32_t method, const char *tag)
{
    fovpt_config cfg = fovpt_config_default();
    fovpt_ctx ctx;
    fovpt_output out;
    fovpt_stats s1, s2, ta, tb, sum, keep;
    fov_gaze g;
    size_t cb = 0;
    void *mem;
    uint8_t *px = (uint8_t *)malloc(PW * PH * 3u);
    fov_result r;
    char why[160] = "";
    uint64_t k;
    g.x = 0.5f * (float)PW; g.y = 0.5f * (float)PH;
    cfg.method = method;
    cfg.spp = 2;
    cfg.seed = 7;
    r = fovpt_memory_size(&cfg, &e->cam, &cb);
    mem = malloc(cb ? cb : 1u);
    if (r == FOV_OK) r = fovpt_init(&ctx, &cfg, &e->scene, &e->cam, g, mem, cb);
    check(r == FOV_OK, N("fovpt_%s_init", tag), "%s", fovpt_result_string(r));
    if (r != FOV_OK) { free(mem); free(px); return; }
    fovpt_output_init(&out);
    out.rgb8 = px;

    fovpt_stats_init(&s1);
    r = fovpt_render(&ctx, 3, &out, &s1);
    /* independent counts: UNIFORM spp samples per pixel; SELECTIVE one presample per pixel
       plus the extra samples it reports; LAYERS the samples of its lattice points */
    if (method == FOVPT_METHOD_UNIFORM) {
        k = (uint64_t)PW * PH * cfg.spp;
    } else if (method == FOVPT_METHOD_SELECTIVE) {
        k = (uint64_t)PW * PH + s1.extra_samples[0] + s1.extra_samples[1] + s1.extra_samples[2] +
            s1.extra_samples[3];
    } else {
        uint32_t n;
        for (n = 0, k = 0; n < FOVPT_MAX_LAYERS; ++n) k += s1.layer_samples[n];
    }
    check(r == FOV_OK && s1.samples == k && s1.camera_rays == k && pt_rays_sum(&s1) && s1.rays > k,
          N("fovpt_%s_one_render_counts", tag),
          "%s, samples %llu camera_rays %llu rays %llu, want samples %llu",
          fovpt_result_string(r), (unsigned long long)s1.samples,
          (unsigned long long)s1.camera_rays, (unsigned long long)s1.rays, (unsigned long long)k);

    /* two identical renders into one struct: exactly twice; the calls between leave it */
    fovpt_stats_init(&s2);
    r = fovpt_render(&ctx, 3, &out, &s2);
    keep = s2;
    if (r == FOV_OK) r = fovpt_resolve_rows(&ctx, 0, PH, &out);
    if (r == FOV_OK) r = fovpt_reset(&ctx);
    if (r == FOV_OK) r = fovpt_init(&ctx, &cfg, &e->scene, &e->cam, g, mem, cb);
    check(r == FOV_OK && memcmp(&keep, &s2, sizeof s2) == 0,
          N("fovpt_%s_other_calls_leave_stats", tag),
          "%s, %s", fovpt_result_string(r), memcmp(&keep, &s2, sizeof s2) ? "changed" : "same");
    if (r == FOV_OK) r = fovpt_render(&ctx, 3, &out, &s2);
    check(r == FOV_OK && pt_times(&s1, &s2, 2, why, sizeof why) && pt_rays_sum(&s2),
          N("fovpt_%s_two_renders_twice_one", tag), "%s, %s", fovpt_result_string(r), why);

    /* two threads' structs summed with fovpt_stats_add: the same as one render */
    fovpt_stats_init(&ta); fovpt_stats_init(&tb); fovpt_stats_init(&sum);
    r = fovpt_trace_rows(&ctx, 3, 0, PH / 2u, &ta);
    if (r == FOV_OK) r = fovpt_trace_rows(&ctx, 3, PH / 2u, PH, &tb);
    if (r == FOV_OK) r = fovpt_refine_rows(&ctx, 3, 0, 11u, &ta);
    if (r == FOV_OK) r = fovpt_refine_rows(&ctx, 3, 11u, PH, &tb);
    fovpt_stats_add(&sum, &ta);
    fovpt_stats_add(&sum, &tb);
    why[0] = '\0';
    check(r == FOV_OK && pt_times(&s1, &sum, 1, why, sizeof why),
          N("fovpt_%s_split_rows_summed_equal_one_render", tag), "%s, %s", fovpt_result_string(r),
          why);
    free(mem);
    free(px);
}

static void test_fovpt_radiance(pt_env *e)
{
    fovpt_config cfg = fovpt_config_default(), rc;
    fovpt_stats s1, s2;
    float org[3] = { 0.0f, 0.0f, -4.0f }, dir[3] = { 0.1f, 0.05f, 1.0f }, rgb[3];
    fovpt_rng rng;
    fov_result r = fovpt_config_resolve(&cfg, &rc);
    int i, ok = r == FOV_OK;
    char why[160] = "";
    fovpt_stats_init(&s1);
    fovpt_stats_init(&s2);
    for (i = 0; i < 64 && ok; ++i) {
        fovpt_rng_init(&rng, 1, (uint32_t)i, 0, 0);
        ok = fovpt_radiance(&e->scene, &rc, org, dir, &rng, rgb, &s1) == FOV_OK;
    }
    for (i = 0; i < 128 && ok; ++i) {
        fovpt_rng_init(&rng, 1, (uint32_t)(i % 64), 0, 0);
        ok = fovpt_radiance(&e->scene, &rc, org, dir, &rng, rgb, &s2) == FOV_OK;
    }
    check(ok && pt_rays_sum(&s1) && s1.camera_rays == 0 && s1.samples == 0 && s1.shadow_rays > 0,
          "fovpt_radiance_counts_its_rays",
          "rays %llu camera %llu bounce %llu shadow %llu samples %llu", (unsigned long long)s1.rays,
          (unsigned long long)s1.camera_rays, (unsigned long long)s1.bounce_rays,
          (unsigned long long)s1.shadow_rays, (unsigned long long)s1.samples);
    check(ok && pt_times(&s1, &s2, 2, why, sizeof why), "fovpt_radiance_twice_the_paths_twice",
          "%s", why);
}

/* ---- fovsdf ------------------------------------------------------------------------------- */
static float sdf_sphere(const float p[3], void *user)
{
    (void)user;
    return sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0f;
}

static void test_fovsdf(void)
{
    const uint32_t W = 48, H = 32;
    fovsdf_scene scene;
    fovsdf_camera cam;
    fovsdf_config cfg = fovsdf_config_default();
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats s1, s2, a, b, sum;
    fov_gaze g;
    fov_result r;
    uint64_t *p1 = (uint64_t *)(void *)&s1, *p2 = (uint64_t *)(void *)&s2;
    size_t i, bad = 0;
    g.x = 24.0f; g.y = 16.0f;
    fovsdf_scene_init(&scene);
    scene.dist = sdf_sphere;
    fovsdf_camera_init(&cam, W, H);
    cam.pos[2] = -3.0f;
    r = fovsdf_init(&ctx, &cfg, &scene, &cam, g, NULL, 0);
    fovsdf_output_init(&out);
    fovsdf_stats_init(&s1);
    fovsdf_stats_init(&s2);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, H, &out, &s1);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, H, &out, &s2);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, H, &out, &s2);
    for (i = 0; i < sizeof s1 / sizeof(uint64_t); ++i) bad += p2[i] != 2u * p1[i];
    check(r == FOV_OK && s1.rays == (uint64_t)W * H && bad == 0 && s1.evals > 0,
          "fovsdf_two_renders_twice_one", "%s, rays %llu (want %u), %zu fields not doubled",
          fovsdf_result_string(r), (unsigned long long)s1.rays, W * H, bad);
    fovsdf_stats_init(&a); fovsdf_stats_init(&b); fovsdf_stats_init(&sum);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, 13, &out, &a);
    if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 13, H, &out, &b);
    fovsdf_stats_add(&sum, &a);
    fovsdf_stats_add(&sum, &b);
    check(r == FOV_OK && memcmp(&sum, &s1, sizeof sum) == 0, "fovsdf_split_rows_summed_equal_one",
          "%s, %s", fovsdf_result_string(r), memcmp(&sum, &s1, sizeof sum) ? "differ" : "same");
}

/* ---- fovlp -------------------------------------------------------------------------------- */
static void lp_shade(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)user;
    rgb[0] = 0.5f + 0.4f * sinf(0.3f * x);
    rgb[1] = 0.5f + 0.4f * cosf(0.2f * y);
    rgb[2] = 0.5f;
    if (depth) *depth = 2.0f;
}

static void test_fovlp(void)
{
    const uint32_t W = 64, H = 40;
    fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
    fovlp_ctx ctx;
    fovlp_taa_io io;
    fovlp_taa_stats st;
    fov_gaze g;
    size_t bytes = 0;
    void *mem;
    float *smp, *img, *hist[2];
    uint8_t *age[2];
    fov_result r;
    int f, ping = 0;
    g.x = 30.0f; g.y = 20.0f;
    cfg.taa.enable = 1;
    r = fovlp_memory_size(&cfg, &bytes);
    mem = malloc(bytes ? bytes : 1u);
    if (r == FOV_OK) r = fovlp_init(&ctx, &cfg, mem, bytes);
    if (r != FOV_OK) {
        check(0, "fovlp_taa_init", "%s", fovlp_result_string(r));
        free(mem);
        return;
    }
    smp = (float *)malloc(sizeof(float) * 3u * ctx.geo.samples);
    img = (float *)malloc(sizeof(float) * 3u * W * H);
    hist[0] = (float *)malloc(sizeof(float) * 3u * W * H);
    hist[1] = (float *)malloc(sizeof(float) * 3u * W * H);
    age[0] = (uint8_t *)malloc(W * H);
    age[1] = (uint8_t *)malloc(W * H);
    fovlp_taa_stats_init(&st);
    for (f = 0; f < 2 && r == FOV_OK; ++f) {
        r = fovlp_begin_frame(&ctx, g, NULL);
        if (r == FOV_OK)
            r = fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), lp_shade, NULL, smp, NULL, NULL);
        if (r == FOV_OK) r = fovlp_reconstruct_rows(&ctx, smp, NULL, 0, H, img, 0, NULL);
        fovlp_taa_io_init(&io); /* no depth anywhere: the camera is still */
        io.cur_rgb = img;
        io.prev_rgb = hist[ping]; io.prev_age = age[ping];
        io.out_rgb = hist[1 - ping]; io.out_age = age[1 - ping];
        if (r == FOV_OK) r = fovlp_taa_rows(&ctx, &io, 0, 17, &st);
        if (r == FOV_OK) r = fovlp_taa_rows(&ctx, &io, 17, H, &st);
        ping = 1 - ping;
    }
    check(r == FOV_OK && st.pixels == 2u * W * H, "fovlp_taa_stats_two_frames_added",
          "%s, pixels %llu, want %u", fovlp_result_string(r), (unsigned long long)st.pixels,
          2u * W * H);
    free(mem); free(smp); free(img); free(hist[0]); free(hist[1]); free(age[0]); free(age[1]);
}

int main(void)
{
    pt_env e;
    test_inits();
    memset(&e, 0, sizeof e);
    if (check(pt_scene(&e), "fovpt_scene_build", "scene rejected")) {
        test_fovpt_method(&e, FOVPT_METHOD_UNIFORM, "uniform");
        test_fovpt_method(&e, FOVPT_METHOD_LAYERS, "layers");
        test_fovpt_method(&e, FOVPT_METHOD_SELECTIVE, "selective");
        test_fovpt_radiance(&e);
    }
    free(e.smem);
    test_fovsdf();
    test_fovlp();
    return fovcheck_summary();
}
