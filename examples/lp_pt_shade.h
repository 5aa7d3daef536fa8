/* lp_pt_shade.h - the glue between fovlp.h and fovpt.h used by examples/lp_pt.c,
   bench/bench_pt.c (the lp_ rows) and tests/test_fovpt_points.c: fovlp_samples hands out the
   log-polar and gaze-disc positions of a range of sample rows, fovpt_shade_points path traces
   them as one batch (the stream of the k-th position of the frame is first + k, so a split of
   the rows over threads gives the same image, bit for bit: tests/test_fovpt_points.c), and the colours (and first-hit distances, for
   the TAA) go to the samples' slots. Path tracing in a log-polar sample space is what Koskela
   et al. 2019 do on the GPU (M. Koskela, A. Lotvonen, M. Makitalo, P. Kivi, T. Viitanen,
   P. Jaaskelainen, "Foveated Real-Time Path Tracing in Visual-Polar Space", EGSR 2019); the
   mapping is fovlp.h's kernel log-polar one (X. Meng, R. Du, M. Zwicker, A. Varshney, "Kernel
   Foveated Rendering", PACMCGIT 1(1), 2018). Include after fovpt.h and fovlp.h; needs
   <stdlib.h>. */
#ifndef LP_PT_SHADE_H
#define LP_PT_SHADE_H

typedef struct lppt_user {
    const fovpt_scene *scene;
    const fovpt_config *cfg;   /* resolved (fovpt_config_resolve or fovpt_config_default) */
    const fovpt_camera *cam;   /* the same camera as fovlp_camera_from's (TAA) */
    uint32_t frame, spp;       /* the random streams' frame; samples per position */
    float jitter;              /* fovpt_shade_points' jitter: 0, the positions themselves (with
                                  fovlp's TAA, whose jitter moves them); 1 on the gaze disc's
                                  pixel centres, UNIFORM's box filter */
    fovpt_stats stats;         /* added to; one per thread */
} lppt_user;

/* The samples of rows [r0, r1) path traced into rgb (3 floats per slot) and depth (1 per
   slot, may be NULL); slots of other rows and unshaded slots keep their value. Returns
   FOV_OK or the first error (then nothing is written); FOV_ERR_LIMIT when the sample count's
   buffers exceed size_t, FOV_ERR_TOO_SMALL when malloc fails. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((unused))
#endif
static fov_result lppt_shade_samples(const fovlp_ctx *lp, uint32_t r0, uint32_t r1, lppt_user *u,
                                     float *rgb, float *depth)
{
    size_t n = 0, before = 0, i;
    fovlp_sample *smp;
    float *c, *t;
    fov_result r;
    if ((r = fovlp_samples(lp, r0, r1, NULL, 0, &n)) != FOV_OK) return r;
    if (r0 > 0 && (r = fovlp_samples(lp, 0, r0, NULL, 0, &before)) != FOV_OK) return r;
    if (n == 0) return FOV_OK;
    if (n > 0xFFFFFFFFu) return FOV_ERR_LIMIT;
    /* the byte counts below (n 3 floats, n samples) within size_t (a 32-bit size_t overflows) */
    if (n > SIZE_MAX / (3 * sizeof(float)) || n > SIZE_MAX / sizeof *smp) return FOV_ERR_LIMIT;
    smp = (fovlp_sample *)malloc(n * sizeof *smp);
    c = (float *)malloc(n * 3 * sizeof(float));
    t = (float *)malloc(n * sizeof(float));
    r = (smp && c && t) ? fovlp_samples(lp, r0, r1, smp, n, &n) : FOV_ERR_TOO_SMALL;
    if (r == FOV_OK)
        r = fovpt_shade_points(u->scene, u->cfg, u->cam, (uint32_t)n, &smp[0].x,
                               (uint32_t)(sizeof *smp / sizeof(float)), (uint32_t)before, u->frame,
                               u->spp, u->jitter, c, depth ? t : NULL, &u->stats);
    if (r == FOV_OK)
        for (i = 0; i < n; ++i) {
            size_t s = smp[i].slot;
            rgb[3 * s] = c[3 * i]; rgb[3 * s + 1] = c[3 * i + 1]; rgb[3 * s + 2] = c[3 * i + 2];
            if (depth) depth[s] = t[i];
        }
    free(smp); free(c); free(t);
    return r;
}

#endif
