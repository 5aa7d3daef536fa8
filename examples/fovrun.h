/* fovrun.h - render a fovsdf context on several threads (row bands through
   fovsdf_render_rows, one fovsdf_stats per thread, summed) and time it. For the demo and the
   benchmark; the library itself never starts threads. Include after fovsdf.h; POSIX. */
#ifndef FOVRUN_H
#define FOVRUN_H
#include <pthread.h>
#include <string.h>
#include <time.h>

typedef struct fovrun_job {
    const fovsdf_ctx *ctx;
    const fovsdf_output *out;
    uint32_t band, first, step, height;
    fovsdf_stats stats;
} fovrun_job;

static void *fovrun_worker(void *arg)
{
    fovrun_job *j = (fovrun_job *)arg;
    uint32_t y;
    for (y = j->first * j->band; y < j->height; y += j->step * j->band) {
        uint32_t y1 = y + j->band < j->height ? y + j->band : j->height;
        fovsdf_render_rows(j->ctx, y, y1, j->out, &j->stats);
    }
    return NULL;
}

static double fovrun_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* Renders the whole image with nthreads threads in bands of fovsdf_band_rows rows (at least 4)
   handed out round robin; returns the wall time in ms and the summed stats in *st. */
static double fovrun_render(const fovsdf_ctx *ctx, const fovsdf_output *out, int nthreads, fovsdf_stats *st)
{
    pthread_t th[64];
    fovrun_job jobs[64];
    int i;
    uint32_t band;
    double t0 = fovrun_now_ms();
    if (nthreads < 1) nthreads = 1;
    if (nthreads > 64) nthreads = 64;
    band = fovsdf_band_rows(ctx);
    if (band < 4) band = 4;
    for (i = 0; i < nthreads; ++i) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].ctx = ctx; jobs[i].out = out; jobs[i].band = band; jobs[i].first = (uint32_t)i;
        jobs[i].step = (uint32_t)nthreads; jobs[i].height = ctx->cam.height;
        pthread_create(&th[i], NULL, fovrun_worker, &jobs[i]);
    }
    memset(st, 0, sizeof *st);
    for (i = 0; i < nthreads; ++i) {
        pthread_join(th[i], NULL);
        fovsdf_stats_add(st, &jobs[i].stats);
    }
    return fovrun_now_ms() - t0;
}
#endif
