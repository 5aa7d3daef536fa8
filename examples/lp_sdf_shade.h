/* lp_sdf_shade.h - the glue between fovlp.h and fovsdf.h used by examples/lp_sdf.c and
   bench/bench_lp.c: a fovlp_shade_fn that shades a screen point with fovsdf_shade_point
   (the same sample fovsdf_render_rows takes), and lpsdf_shade_samples, which shades all the
   samples of a range of rows in one fovsdf_shade_points call (a wavefront: the same values,
   faster), or with a cone head start per group of samples (lpsdf_user.group). (The TAA camera comes from the same fov_camera through fovlp_camera_from.)
   Include after fovsdf.h and fovlp.h; lpsdf_shade_samples needs <stdlib.h>. */
#ifndef LP_SDF_SHADE_H
#define LP_SDF_SHADE_H

typedef struct lpsdf_user {
    const fovsdf_ctx *sdf;
    fovsdf_stats stats;   /* one per thread */
    uint32_t group;       /* lpsdf_shade_samples: 0, each sample's ray from the camera
                             (fovsdf_shade_point's values bit for bit); G > 1, groups of G
                             consecutive samples of a log-polar row share a certified cone head
                             start (fovsdf_shade_points_grouped; 8 is a good choice) */
} lpsdf_user;

/* Linear RGB and the hit distance (t_max for a miss) of screen point (x, y): one fovsdf
   sample, shaded exactly as fovsdf_render_rows shades one (fovsdf_shade_point). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((unused))
#endif
static void lpsdf_shade(float x, float y, float rgb[3], float *depth, void *user)
{
    lpsdf_user *u = (lpsdf_user *)user;
    float t;
    if (fovsdf_shade_point(u->sdf, x, y, rgb, &t, NULL, &u->stats) != FOV_OK) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        t = u->sdf->t_max;
    }
    if (depth) *depth = t;
}

/* The samples of rows [r0, r1) shaded into rgb / depth (slots, as fovlp_shade_rows; depth may
   be NULL; slots that are not shaded keep their value): fovlp_samples hands out the
   positions, fovsdf_shade_points shades them as one batch. Returns 0, or -1 when memory or a
   call fails (then nothing is written). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((unused))
#endif
static int lpsdf_shade_samples(const fovlp_ctx *lp, uint32_t r0, uint32_t r1, lpsdf_user *u,
                               float *rgb, float *depth)
{
    size_t n = 0, i;
    fovlp_sample *smp;
    float *c, *t;
    int ok;
    if (fovlp_samples(lp, r0, r1, NULL, 0, &n) != FOV_OK) return -1;
    if (n == 0) return 0;
    smp = (fovlp_sample *)malloc(n * sizeof *smp);
    c = (float *)malloc(n * 3 * sizeof(float));
    t = (float *)malloc(n * sizeof(float));
    ok = smp && c && t && fovlp_samples(lp, r0, r1, smp, n, &n) == FOV_OK &&
         fovsdf_shade_points_grouped(u->sdf, (uint32_t)n, &smp[0].x,
                                     (uint32_t)(sizeof *smp / sizeof(float)), u->group, c, t,
                                     NULL, &u->stats) == FOV_OK;
    if (ok)
        for (i = 0; i < n; ++i) {
            size_t s = smp[i].slot;
            rgb[3 * s] = c[3 * i]; rgb[3 * s + 1] = c[3 * i + 1]; rgb[3 * s + 2] = c[3 * i + 2];
            if (depth) depth[s] = t[i];
        }
    free(smp); free(c); free(t);
    return ok ? 0 : -1;
}

#endif
