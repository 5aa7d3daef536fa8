/* lp_sdf_shade.h - the glue between fovlp.h and fovsdf.h used by examples/lp_sdf.c and
   bench/bench_lp.c: a fovlp_shade_fn that shades a screen point with fovsdf's public API
   (fovsdf_camera_ray, fovsdf_trace, fovsdf_distance for the material, fovsdf_normal,
   fovsdf_shade or fovsdf_sky), the same steps fovsdf_render_rows takes for one sample, and
   the conversion of a fovsdf context's camera into a fovlp_camera for TAA reprojection.
   Include after fovsdf.h and fovlp.h. */
#ifndef LP_SDF_SHADE_H
#define LP_SDF_SHADE_H

typedef struct lpsdf_user {
    const fovsdf_ctx *sdf;
    fovsdf_stats stats;   /* one per thread */
} lpsdf_user;

/* Linear RGB and the hit distance (t_max for a miss) of screen point (x, y). */
static void lpsdf_shade(float x, float y, float rgb[3], float *depth, void *user)
{
    lpsdf_user *u = (lpsdf_user *)user;
    const fovsdf_ctx *c = u->sdf;
    float ro[3], rd[3];
    fovsdf_hit h;
    if (fovsdf_camera_ray(c, x, y, ro, rd) != FOV_OK || fovsdf_trace(c, ro, rd, 0.0f, &h, &u->stats) != FOV_OK) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        if (depth) *depth = c->t_max;
        return;
    }
    if (h.kind != FOVSDF_MISS) {
        float p[3], n[3], hn = 0.5f * c->pixel_angle * h.t;
        int32_t mat = 0;
        p[0] = ro[0] + rd[0] * h.t; p[1] = ro[1] + rd[1] * h.t; p[2] = ro[2] + rd[2] * h.t;
        (void)fovsdf_distance(c, p, &mat, &u->stats);
        fovsdf_normal(c, p, hn > 1e-4f ? hn : 1e-4f, n, &u->stats);
        fovsdf_shade(c, p, n, rd, mat, rgb, &u->stats);
    } else {
        fovsdf_sky(c, rd, rgb);
    }
    if (depth) *depth = h.t;
}

static fovlp_camera lpsdf_camera(const fovsdf_ctx *c)
{
    fovlp_camera k;
    int i;
    for (i = 0; i < 3; ++i) {
        k.pos[i] = c->origin[i];
        k.right[i] = c->right[i];
        k.up[i] = c->up[i];
        k.fwd[i] = c->fwd[i];
    }
    k.tan_half_y = c->tan_half_y;
    return k;
}
#endif
