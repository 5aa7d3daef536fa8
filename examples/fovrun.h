/* fovrun.h - render a fovsdf context on several threads and time it. The image is cut into
   work items of fovsdf_band_rows rows by a multiple of band_rows columns (whole grid tiles of
   the head-start methods, so no call repeats a tile's coarse work) of at least
   FOVRUN_ITEM_PX / spp pixels (so each fovsdf_render_tile call's wavefront keeps its batches
   full); the workers take the items in row-major order from a shared counter (a mutex), so a
   worker that drew the costly fovea simply takes fewer items. One fovsdf_stats per thread,
   summed. For the demo and the benchmark; the library itself never starts threads. Include
   after fovsdf.h; POSIX. */
#ifndef FOVRUN_H
#define FOVRUN_H
#include <pthread.h>
#include <string.h>
#include <time.h>

#ifndef FOVRUN_ITEM_PX
#define FOVRUN_ITEM_PX 2048u /* pixels per work item at 1 spp: 16 wavefronts of 128 */
#endif

typedef struct fovrun_queue {
    pthread_mutex_t lock;
    uint32_t next, count;          /* items handed out so far, items in all */
    uint32_t band, cols, nx, w, h; /* item size band x cols pixels, nx items per item row */
} fovrun_queue;

typedef struct fovrun_job {
    const fovsdf_ctx *ctx;
    const fovsdf_output *out;
    fovrun_queue *q;
    fovsdf_stats stats;
} fovrun_job;

static void *fovrun_worker(void *arg)
{
    fovrun_job *j = (fovrun_job *)arg;
    fovrun_queue *q = j->q;
    for (;;) {
        uint32_t k, x0, y0, x1, y1;
        pthread_mutex_lock(&q->lock);
        k = q->next < q->count ? q->next++ : q->count;
        pthread_mutex_unlock(&q->lock);
        if (k == q->count) break;
        x0 = (k % q->nx) * q->cols; y0 = (k / q->nx) * q->band;
        x1 = x0 + q->cols < q->w ? x0 + q->cols : q->w;
        y1 = y0 + q->band < q->h ? y0 + q->band : q->h;
        fovsdf_render_tile(j->ctx, x0, y0, x1, y1, j->out, &j->stats);
    }
    return NULL;
}

static double fovrun_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* Renders the whole image with nthreads threads (1 .. 64: the calling thread and nthreads - 1
   started ones; 1 renders on the calling thread, with the same items) taking work items from
   a shared counter; returns the wall time in ms
   and the summed stats in *st. The image and every counter are the same for any nthreads. */
static double fovrun_render(const fovsdf_ctx *ctx, const fovsdf_output *out, int nthreads,
                            fovsdf_stats *st)
{
    pthread_t th[64];
    fovrun_job jobs[64];
    fovrun_queue q;
    int i, started[64];
    uint32_t spp = ctx->cfg.spp ? ctx->cfg.spp : 1u, px = FOVRUN_ITEM_PX / spp, tiles;
    double t0 = fovrun_now_ms();
    if (nthreads < 1) nthreads = 1;
    if (nthreads > 64) nthreads = 64;
    q.band = fovsdf_band_rows(ctx);
    if (q.band < 1) q.band = 1;
    q.w = ctx->cam.width; q.h = ctx->cam.height;
    if (px < 1) px = 1;
    tiles = (px + q.band * q.band - 1) / (q.band * q.band); /* band x band tiles per item */
    q.cols = tiles * q.band < q.w ? tiles * q.band : q.w;
    if (q.cols < 1) q.cols = 1;
    q.nx = (q.w + q.cols - 1) / q.cols;
    q.count = q.nx * ((q.h + q.band - 1) / q.band);
    q.next = 0;
    pthread_mutex_init(&q.lock, NULL);
    for (i = 0; i < nthreads; ++i) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].ctx = ctx; jobs[i].out = out; jobs[i].q = &q;
        /* job 0 is the caller's; a thread that cannot start leaves its items to the others */
        started[i] = i > 0 && pthread_create(&th[i], NULL, fovrun_worker, &jobs[i]) == 0;
    }
    fovrun_worker(&jobs[0]); /* the caller works too (1 thread: all of it) */
    memset(st, 0, sizeof *st);
    for (i = 0; i < nthreads; ++i) {
        if (started[i]) pthread_join(th[i], NULL);
        fovsdf_stats_add(st, &jobs[i].stats);
    }
    pthread_mutex_destroy(&q.lock);
    return fovrun_now_ms() - t0;
}
#endif
