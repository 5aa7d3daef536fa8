/* lp_sdf_shade.h - the glue between fovlp.h and fovsdf.h used by examples/lp_sdf.c and
   bench/bench_lp.c: a fovlp_shade_fn that shades a screen point with fovsdf_shade_point
   (the same sample fovsdf_render_rows takes). (The TAA camera comes from the same
   fov_camera through fovlp_camera_from.) Include after fovsdf.h and fovlp.h. */
#ifndef LP_SDF_SHADE_H
#define LP_SDF_SHADE_H

typedef struct lpsdf_user {
    const fovsdf_ctx *sdf;
    fovsdf_stats stats;   /* one per thread */
} lpsdf_user;

/* Linear RGB and the hit distance (t_max for a miss) of screen point (x, y): one fovsdf
   sample, shaded exactly as fovsdf_render_rows shades one (fovsdf_shade_point). */
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

#endif
