/* web_gaze.c - the browser demo's gaze module (examples/web), loaded by the page itself (not
   by the workers): the shared gaze filter and latency margin of the fov headers (GAZE INPUT
   in fovsdf.h; the same functions in fovlp.h and fovpt.h) over the eccentricity model of the
   current camera. The page pushes every raw gaze sample (pixels, a timestamp) and reads the
   filtered gaze and the margin; the workers get the margin and apply it with their header's
   *_config_gaze_margin.
   Exports: gaze_setup, gaze_reset, gaze_push, gaze_x, gaze_y, gaze_margin, gaze_noise_deg,
   gaze_saccade, gaze_resets. Not part of the library; the public API only. */
#define FOV_NO_LIBM
#define FOV_ASSERT(c) ((void)0)
/* the runtime's allocator and image helpers are not used here */
#pragma clang diagnostic ignored "-Wunused-function"
#include "web_rt.h"
#define FOVSDF_IMPLEMENTATION
#include "../../fovsdf.h"

static struct {
    fov_ecc_model ecc;
    fov_gaze_filter f;
    fov_gaze out;          /* the filtered gaze, pixels */
    uint32_t ready, resets;
} G;

/* the eccentricity model of a w x h image of vertical field of view fov_y_deg (the camera's;
   a symmetric frustum, display all zero as the glue's cameras) and a filter with the header's
   defaults; forgets every sample. Returns a fov_result. */
WEB_EXPORT(gaze_setup) int gaze_setup(float fov_y_deg, uint32_t w, uint32_t h);
int gaze_setup(float fov_y_deg, uint32_t w, uint32_t h)
{
    fov_gaze c;
    fov_result r;
    G.ready = 0;
    if (w == 0 || h == 0) return FOV_ERR_INVALID_ARG;
    c.x = 0.5f * (float)w;
    c.y = 0.5f * (float)h;
    if ((r = fovsdf_ecc_init(&G.ecc, NULL, fov_y_deg, w, h, c)) != FOV_OK) return r;
    if ((r = fovsdf_gaze_filter_init(&G.f, NULL)) != FOV_OK) return r;
    G.out = c;
    G.ready = 1;
    G.resets = 0;
    return FOV_OK;
}

WEB_EXPORT(gaze_reset) void gaze_reset(void);
void gaze_reset(void) { fovsdf_gaze_filter_reset(&G.f); }

/* one raw sample at t_ms milliseconds (the page's clock), (x, y) in pixels. A timestamp not
   after the previous one or a gap above the filter's max_dt_ms (the page was paused, the
   test stepped the clock back) restarts the filter there (what the header asks for when
   tracking was lost), counted by gaze_resets. Returns a fov_result. */
WEB_EXPORT(gaze_push) int gaze_push(double t_ms, float x, float y);
int gaze_push(double t_ms, float x, float y)
{
    fov_gaze raw, out;
    fov_result r;
    uint64_t t_us;
    if (!G.ready) return FOV_ERR_NULL;
    if (!(t_ms >= 0.0 && t_ms < 1e15)) return FOV_ERR_INVALID_ARG;
    t_us = (uint64_t)(t_ms * 1000.0);
    raw.x = x; raw.y = y;
    r = fovsdf_gaze_filter_push_px(&G.f, &G.ecc, t_us, raw, &out);
    if (r == FOV_ERR_LIMIT || (r == FOV_ERR_INVALID_ARG && G.f.samples > 0 && t_us <= G.f.t_us)) {
        fovsdf_gaze_filter_reset(&G.f);
        G.resets++;
        r = fovsdf_gaze_filter_push_px(&G.f, &G.ecc, t_us, raw, &out);
    }
    if (r != FOV_OK) return r;
    G.out = out;
    return FOV_OK;
}

WEB_EXPORT(gaze_x) float gaze_x(void);
float gaze_x(void) { return G.out.x; }
WEB_EXPORT(gaze_y) float gaze_y(void);
float gaze_y(void) { return G.out.y; }
/* the margin in degrees for the tracker's accuracy and the system's latency (the filter's
   last state), or a negative fov_result */
WEB_EXPORT(gaze_margin) float gaze_margin(float accuracy_deg, float latency_ms);
float gaze_margin(float accuracy_deg, float latency_ms)
{
    float m = 0.0f;
    fov_result r;
    if (!G.ready) return (float)FOV_ERR_NULL;
    r = fovsdf_gaze_margin(&G.f, accuracy_deg, latency_ms, &m);
    return r == FOV_OK ? m : (float)r;
}
WEB_EXPORT(gaze_noise_deg) float gaze_noise_deg(void);
float gaze_noise_deg(void) { return G.f.noise_deg; }
WEB_EXPORT(gaze_saccade) uint32_t gaze_saccade(void);
uint32_t gaze_saccade(void) { return G.f.saccade; }
WEB_EXPORT(gaze_resets) uint32_t gaze_resets(void);
uint32_t gaze_resets(void) { return G.resets; }
