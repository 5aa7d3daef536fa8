/* fov_shared.h - the code fovsdf.h, fovlp.h and fovpt.h share, in one place.

   Not a header to include: tools/sync_shared.py copies each region below (from its
   BEGIN marker line to its END marker line) over the region of the same name in the
   three headers, so the headers stay single files. tests/shared.sh checks that the three
   copies are byte-identical and equal to this file. Names: public fov_ / FOV_, private
   fov__ / FOV__. */

/* ==== FOV_SHARED_BEGIN decl: shared by fovsdf.h, fovlp.h and fovpt.h ========================= */
/* Byte-identical in the three headers, compiled once per translation unit. Do not edit it in a
   header: edit tools/fov_shared.h and run `python3 tools/sync_shared.py` (tests/shared.sh
   checks the copies).

   CONFIGURATION shared by fovsdf.h, fovlp.h and fovpt.h (define before including the
   implementation; the same value for every header in a translation unit)
   FOV_DLL              export (in the translation unit with FOVxx_IMPLEMENTATION) or import
                        the API of a shared library
   FOV_ASSERT(c)        internal invariants only (default: assert.h, or nothing with NDEBUG)
   FOV_NO_LIBM          use the built-in float approximations of the math functions below
                        (relative error about 1e-6 or better on the ranges the libraries use)
   FOV_SQRTF FOV_FLOORF FOV_SINF FOV_COSF FOV_TANF FOV_ATAN2F FOV_EXPF FOV_LOGF FOV_POWF
                        math hooks: define all of them or none (an #error tells you)
   FOV_MEMSET FOV_MEMCPY   memory hooks (default: simple loops; compilers may still emit
                        calls to memset/memcpy for struct copies)
   FOV_NO_ERROR_STRINGS compile out the message texts: the logger gets "" and
                        *_result_string returns "" (for the smallest microcontroller builds)
   Error messages are on by default: set the logger in a config (cfg.logger.func) and every
   failure calls it with a code, a specific message and the header's source line. */
#ifndef FOV_SHARED_DECL_INCLUDED
#define FOV_SHARED_DECL_INCLUDED 1
#define FOV_SHARED_REVISION 5 /* the revision of this block; headers that differ must not mix */

#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__) || defined(__clang__)
#define FOV__UNUSED __attribute__((unused))
#else
#define FOV__UNUSED
#endif
/* Linkage of public functions (each header's FOVxx_API picks one): FOV_DLL builds a shared
   library (dllexport in the translation unit with the implementation, dllimport elsewhere on
   Windows; default visibility with gcc and clang). */
#if defined(FOV_DLL) && defined(_WIN32)
#define FOV__API_EXPORT __declspec(dllexport)
#define FOV__API_IMPORT __declspec(dllimport)
#elif defined(FOV_DLL) && (defined(__GNUC__) || defined(__clang__))
#define FOV__API_EXPORT __attribute__((visibility("default"))) extern
#define FOV__API_IMPORT __attribute__((visibility("default"))) extern
#else
#define FOV__API_EXPORT extern
#define FOV__API_IMPORT extern
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Result codes of every fallible function in the fov headers. */
typedef enum fov_result {
    FOV_OK = 0,
    FOV_ERR_INVALID_ARG = -1,  /* a parameter is out of its documented range */
    FOV_ERR_TOO_SMALL = -2,    /* the memory or buffer passed is smaller than required */
    FOV_ERR_LIMIT = -3,        /* a size is above a hard cap or overflows size_t */
    FOV_ERR_NULL = -4,         /* a required pointer is NULL */
    FOV_ERR_NOT_FINITE = -5,   /* NaN or infinity where a finite number is required */
    FOV_ERR_DEGENERATE = -6,   /* degenerate geometry: camera, display, scene */
    FOV_ERR_UNSUPPORTED = -7,  /* a valid request this build or version does not support */
    _FOV_RESULT_FORCE_I32 = 0x7FFFFFFF
} fov_result;

typedef enum fov_log_level {
    FOV_LOG_ERROR = 1,
    FOV_LOG_WARN = 2,
    FOV_LOG_INFO = 3,
    _FOV_LOG_LEVEL_FORCE_U32 = 0x7FFFFFFF
} fov_log_level;

/* Optional diagnostics: tag is the header ("fovsdf", "fovlp", "fovpt"), code a fov_result,
   msg a specific text naming what was wrong and what is allowed (never NULL; "" when the
   build defines FOV_NO_ERROR_STRINGS), line the header's source line that reported it. */
typedef void (*fov_log_func)(const char *tag, uint32_t level, int32_t code, const char *msg,
                             uint32_t line, void *user);
typedef struct fov_logger {
    fov_log_func func;
    void *user;
} fov_logger;

/* Gaze point in image pixels, continuous: pixel (i, j) covers [i, i+1) x [j, j+1), so its
   centre is (i + 0.5, j + 0.5); y grows downwards. Must be finite; it may lie off-screen. */
typedef struct fov_gaze {
    float x, y;
} fov_gaze;

/* The camera of all three headers: fovsdf_camera and fovpt_camera are this type, and fovlp's
   TAA takes it through fovlp_camera_from. A pinhole; lengths in world units (the scene's,
   whatever they are), angles in degrees, image points in pixels.
   Frame (right-handed, x the usual cross product):
       fwd = normalize(target - pos), right = normalize(fwd x up), up' = right x fwd.
   `right` points to the image's right (x, the column, grows that way) and up' to its top
   (y, the row, grows downwards: row 0 is the top). For the defaults below (pos (0, 0, 5)
   looking at the origin, up +y): fwd = -z, right = (-z) x (+y) = +x, up' = (+x) x (-z) = +y,
   so world +x appears on the image's right and world +y at its top (the textbook view of
   the xy plane, +z towards the viewer). Turned around (pos (0, 0, -5), or pos 0 and target
   (0, 0, 1): fwd = +z) the camera has world -x on the image's right.
   Image points: pixel (i, j) covers [i, i+1) x [j, j+1), its centre is (i + 0.5, j + 0.5),
   y down (as fov_gaze). The ray through image point (x, y) leaves the pinhole
   pos + eye_offset * right along
       fwd + sx right + sy up',  sx = -tl + (tl + tr) x / width,  sy = tt - (tt + tb) y / height
   with tl = tr = tan(fov_y_deg / 2) width / height and tt = tb = tan(fov_y_deg / 2) when the
   four tangents are 0 (a symmetric frustum), else tl, tr, tb, tt = tan_left .. tan_top
   (an off-axis frustum, e.g. an HMD eye's; fov_y_deg is then unused).
   Which header uses which field:
       pos, target, up, fov_y_deg, width, height   all three (fovlp_camera_from ignores the
                                                   size: the TAA uses the fovlp image's)
       eye_offset                                  all three
       tan_left, tan_right, tan_bottom, tan_top    fovsdf and fovpt (rays, eccentricity);
                                                   fovlp through config.display
                                                   (fovlp_camera_display) and config.taa.frustum
                                                   (its reprojection); a symmetric camera (all
                                                   0) gives the rays of earlier releases, bit
                                                   for bit
   The defaults ("the fov_camera defaults", set by fovsdf_camera_init and fovpt_camera_init,
   the same in both): pos (0, 0, 5), target (0, 0, 0), up (0, 1, 0), fov_y_deg 60, the given
   width and height, eye_offset 0, tangents 0. A zeroed fov_camera with a size, pos and
   target is valid too: up all zero means +y, fov_y_deg 0 means 60. Further limits (sizes,
   coordinate bounds) are each header's; invalid cameras return FOV_ERR_* from init. */
typedef struct fov_camera {
    float pos[3];           /* the camera's position, world units */
    float target[3];        /* a point it looks at; must differ from pos */
    float up[3];            /* up hint, any length, need not be orthogonal to the view; all
                               zero: +y. Must not be parallel to target - pos */
    float fov_y_deg;        /* vertical field of view in (0, 180) degrees; 0: 60 */
    uint32_t width, height; /* image size in pixels, >= 1 */
    float eye_offset;       /* stereo: the pinhole moves by this along `right`, world units
                               (-ipd/2 for the left eye, +ipd/2 for the right one); the view
                               axis keeps its direction */
    float tan_left, tan_right; /* off-axis frustum (an HMD eye): tangents of the angles from the */
    float tan_bottom, tan_top; /* view axis to the left, right, bottom and top image edges,
                               positive for an edge on that side of the axis (left + right
                               > 0, bottom + top > 0); all 0: symmetric, from fov_y_deg */
} fov_camera;

/* Display geometry, for eccentricity. The eye sits on the display's axis at a distance
   f (in pixels) from the image plane; the axis meets the image at its centre plus
   (axis_dx, axis_dy) pixels. f comes from, in this order:
     fov_y_deg > 0                      the image height subtends fov_y_deg at the eye
                                        (an HMD, or a window whose view matches the camera)
     pixel_pitch_mm > 0, distance_mm > 0   a monitor: f = distance_mm / pixel_pitch_mm
     all zero                           the rendering camera's vertical field of view.
   All zero assumes a symmetric frustum (the camera's axis through the image centre). For an
   off-axis frustum (an HMD eye with tangents l, r, b, t, as in OpenVR's GetProjectionRaw, the
   image W x H) give fov_y_deg = 2 atan((t + b) / 2), so f = H / (t + b), and
   axis_dx = f l - W / 2, axis_dy = f t - H / 2 (y down); fovsdf and fovpt derive these from
   the camera when the display is all zero, *_camera_display gives them (for fovlp). The model
   has square pixels: for tangents whose (l + r) / (t + b) differs from W / H, f follows the
   vertical.
   Eccentricity of a point q of the image = the angle, in degrees, between the eye's rays
   through q and through the gaze point. This is the one definition all fov headers use. */
typedef struct fov_display {
    float fov_y_deg;
    float pixel_pitch_mm;
    float distance_mm;
    float axis_dx, axis_dy;
} fov_display;

/* Precomputed eccentricity model (fill it with fovsdf_ecc_init / fovlp_ecc_init / ...). */
typedef struct fov_ecc_model {
    float cx, cy;    /* where the eye's axis meets the image, pixels */
    float f_px;      /* eye to image plane, pixels */
    float gx, gy;    /* the gaze point, pixels */
    float g[3];      /* unit direction of the gaze ray */
} fov_ecc_model;

/* The eye's resolution, for acuity-driven foveation. The minimum angle of resolution (MAR, the
   smallest gap the eye sees) grows linearly with the eccentricity e in degrees (Guenter, Finch,
   Drucker, Tan and Snyder, "Foveated 3D Graphics", 2012):  MAR(e) = mar0 + slope e. Their user
   study puts the slope at 1.32 (conservative: users judged the foveated image as good as or
   better than full resolution) to 1.65 arc minutes per degree (aggressive); 1 arc minute is
   the MAR of 20/20 vision at the gaze. A sampling that follows the eye places its samples at
   most quality * MAR(e) apart. A zero field takes its default.
   Quality 1 spaces the samples one MAR apart: the Nyquist rate of the finest grating the eye
   resolves (a period of 2 MAR). Point samples and the interpolating reconstructions the
   headers use lose contrast and alias at their Nyquist rate (bilinear keeps 41 % of a
   grating's contrast there, 81 % at half of it), so the default is 0.5, twice that rate:
   measured with bench/bench_perceptual.c, the rate at which the three headers' acuity-driven
   images are as good as full resolution on a 640x360 display (bench/README.md). */
typedef struct fov_eye {
    float mar0_arcmin;  /* MAR at the gaze, arc minutes, (0, 60]                      0: 1 */
    float slope_arcmin; /* MAR growth, arc minutes per degree, (0, 60]             0: 1.32 */
    float quality;      /* the one quality knob: allowed sample spacing as a multiple of the
                           MAR, (0, 100]; 1 = the eye's Nyquist rate, below 1 safer,
                           above 1 coarser than the eye resolves                   0: 0.5 */
} fov_eye;

/* What a display needs, from fov_eye and the display's pixels per degree (ppd). Each header's
   _eye_plan fills it from an eccentricity model: ppd is the coarsest on the image, f_px pi /
   180 at the eye's axis (a flat display's pixels subtend less away from the axis, so this errs
   on the safe side). e_X = the eccentricity in degrees from which a sample per X display pixels
   along each axis is as fine as the eye resolves; a display coarser than the eye out to E has
   e_full >= E, so a sampling that follows the plan keeps every pixel inside E. */
typedef struct fov_eye_plan {
    float ppd;       /* display pixels per degree used */
    float e_full;    /* inside: every pixel needs its own sample (no reduction)  */
    float e_half;    /* from here a sample per 2 x 2 pixels suffices */
    float e_quarter; /* from here a sample per 4 x 4 pixels suffices */
} fov_eye_plan;

/* ---- gaze input: filter, latency margin, fixed foveation (see each header's GAZE INPUT) --- */
/* Gaze angles: a gaze point (x, y) in pixels of an image with eccentricity model m (fov_ecc
   model: axis point (cx, cy), eye distance f) is, in degrees, h = atan2(x - cx, f) to the
   right and v = atan2(y - cy, sqrt((x - cx)^2 + f^2)) downwards (a longitude and latitude
   about the display's axis; the inverse is x = cx + f tan h, y = cy + f tan v / cos h). Near
   the axis a step of one degree in h or v is one degree of eccentricity; 20 degrees off the
   axis an h step is cos(v) of one. The filter works in these degrees.

   The filter (Casiez, Roussel and Vogel, "1 Euro Filter: A Simple Speed-based Low-pass
   Filter for Noisy Input in Interactive Systems", CHI 2012): per sample, with Te the time
   step, a(fc) = 1 / (1 + 1 / (2 pi fc Te)):
       velocity  dv = a(d_cutoff_hz) (x - x_prev) / Te + (1 - a(d_cutoff_hz)) dv_prev
       cutoff    fc = min_cutoff_hz + beta |dv|         (|dv| in degrees per second)
       position  x  = x_prev + max(a(fc), 1 / (n + 1)) (x_raw - x_prev)
   one cutoff for both axes (|dv| the 2-D speed). n counts the samples since the last reset
   or saccade landing: the first samples of a fixation are averaged (a running mean, the
   best estimate of a still target) until the One Euro weight takes over, so the filter
   settles in a few samples instead of its time constant 1 / (2 pi min_cutoff_hz).
   Saccades (velocity-threshold identification, I-VT: Salvucci and Goldberg, "Identifying
   Fixations and Saccades in Eye-Tracking Protocols", ETRA 2000): the speed of the raw gaze
   over the last window_ms (the newest sample against the one window_ms before it, so the
   tracker's noise is divided by the window, not by one sample step) above saccade_deg_s
   starts a saccade; the output is then the raw sample (no smoothing lag while the eye
   jumps). Below half of saccade_deg_s the saccade has landed: the filter restarts at the
   landing sample (n = 0, velocity 0) so the fovea jumps with the eye instead of sliding.
   100 deg/s: saccades of 2 degrees and more peak above 100 deg/s (the main sequence:
   Bahill, Clark and Stark, "The main sequence, a tool for studying human eye movements",
   Mathematical Biosciences 1975), smooth pursuit stays below about 30 to 50 deg/s, and a
   tracker noise of 0.5 degrees RMS over a 20 ms window gives about 35 deg/s RMS of speed.
   Error checks leave the filter unchanged: a timestamp not after the previous one
   (FOV_ERR_INVALID_ARG: out of order or a zero step; a tracker clock that went back, e.g.
   after a restart, needs _gaze_filter_reset too, or every later sample is rejected until the
   clock passes the old one), a step above max_dt_ms (FOV_ERR_LIMIT: the tracker lost the
   eye; call _gaze_filter_reset, then push again), a NaN or infinite
   sample (FOV_ERR_NOT_FINITE), an angle of +-90 degrees or beyond (FOV_ERR_INVALID_ARG; a
   pixel far enough off the axis rounds to 90 degrees and is rejected by _push_px and
   _gaze_to_deg as well; _push_px changes the filter and *out only when the whole call,
   the conversion back to pixels included, succeeds). A blink
   shorter than max_dt_ms needs nothing: push no samples while the tracker reports none.

   The margin (_gaze_margin), in degrees, which _config_gaze_margin adds to a config's
   full-quality radii so that the true gaze stays inside them:
       margin = accuracy_deg + 2.5 jitter + motion (latency_ms / 1000 + 1 / (2 pi fc))
   capped at max_margin_deg. accuracy_deg is the tracker's stated accuracy (its systematic
   error); jitter the RMS of the filtered gaze's noise, the filter's running estimate of the
   raw noise (noise_deg) scaled by the smoothing (sqrt(a / (2 - a)) for an exponential
   smoother of weight a): a 2-D Gaussian error exceeds 2.15 times its RMS in 1 % of samples,
   2.5 times in 0.2 %; motion the speed of the filtered gaze (out_speed_deg_s) less twice the
   speed the tracker's noise alone gives it (a n / te sqrt(ad / (2 - ad)), ad the velocity
   smoother's weight: a still eye's output jitters, it does not move), times the latency (how
   far the eye moves before the frame shows) and the smoothing's own lag 1 / (2 pi fc) behind
   a moving eye. During a saccade the output is the raw sample and the margin accuracy_deg +
   2.5 noise_deg: the eye sees next to nothing while it jumps (saccadic suppression), and the
   fovea lands with it. The margin grows with the latency and with the output's speed,
   except across a saccade onset: once the window speed passes saccade_deg_s the margin drops
   to accuracy_deg + 2.5 noise_deg, so there it falls as the speed rises (monotone in the
   speed only among non-saccade states, and in the latency always).
   bench/README.md (make bench-gaze) gives what it costs and buys on generated traces.

   Latency compensation (_gaze_predict): where the eye is when the frame is seen, latency_ms
   after the newest sample's timestamp, and a margin around that point (the margin above
   instead covers the eye's whole travel around the filtered gaze). A least-squares line
   x(t) = p + v t (both axes, t relative to the newest sample) is fitted to the raw samples
   since the last reset or saccade landing, at most predict_ms old and at most
   FOV_GAZE_HISTORY of them, and cut to its newer half while the motion changed within it:
   the mean of the newest quarter lies off the line through the older samples by more than
   3.03 times its standard error (the eye stopped or started), or one line per half fits
   better than one line for all (Chow's test, F(4, 2 (n - 4)) beyond about its 1 % point:
   a small saccade the speed threshold missed). n samples, times t_i with mean tm and
   S = sum (t_i - tm)^2; the residual s^2 = sum of both axes' squared residuals /
   (2 (n - 2)), the noise per axis the tracker's data show (fixational drift and any
   curvature included: the noise term is measured, not assumed; at least 1e-4 degrees, the
   float rounding of noiseless input). With
   h = latency_ms / 1000 - tm (seconds from the fitted samples' mean time to the frame):
     pursuit (mode FOV_GAZE_PURSUIT): the fitted speed |v| is above 3.03 times its standard
       error s / sqrt(S) per axis (a still eye exceeds it in 1 % of fits: chi-square, two
       degrees of freedom) and below saccade_deg_s: the gaze extrapolated along v,
           centre = mean + v h,
           margin = accuracy_deg + 2.5 sqrt(2) s sqrt(1 / n + h^2 / S)
       (the fit's prediction error: position noise, and velocity uncertainty times the
       lever h; 2.5 times the 2-D RMS is exceeded in 0.2 % of Gaussian errors).
     fixation (FOV_GAZE_FIXATION): not moving: no extrapolation, the mean of the fitted
       samples (a steadier point than the filtered gaze), and
           margin = accuracy_deg + 2.5 sqrt(2) s sqrt(1 / n) + max(0, |v| - 2 sqrt(2) s /
                    sqrt(S)) h
       (a speed too small to extrapolate still widens the margin by the travel it gives).
     settling (FOV_GAZE_SETTLING): fewer than FOV_GAZE_FIT_MIN samples since the reset or
       landing (or in the cut window), or spanning less than FOV_GAZE_FIT_MIN_MS: the
       filtered gaze and _gaze_margin's margin. Never extrapolated: a fresh landing does
       not overshoot (the fit sees only samples after it).
     saccade (FOV_GAZE_SACCADE): the raw sample and _gaze_margin's saccade margin
       (accuracy_deg + 2.5 noise_deg): the fovea lands with the eye.
   The margin is capped at max_margin_deg; the extrapolation is not bounded otherwise (|v| <
   saccade_deg_s, the lever at most latency_ms + predict_ms). A tracker above about
   FOV_GAZE_HISTORY / predict_ms samples per second fits a shorter span than predict_ms
   (32 samples: 160 Hz at the default 200 ms), a noisier velocity; above about 775 Hz the
   32 samples span less than FOV_GAZE_FIT_MIN_MS and it never extrapolates: decimate the
   samples to a lower rate (every k-th) to keep the span. Use the centre as the frame's gaze
   (_gaze_from_deg for pixels) and the margin as _config_gaze_margin's / _set_gaze_margin's.
   The filtered gaze (x_deg, y_deg) and _gaze_margin stay as they were. What the prediction
   cannot know: a pursuit that starts or stops within the latency (the samples that would
   show it arrive after the frame); there the error is up to the speed times the latency,
   outside the margin. bench/README.md gives the measured cost and coverage. */
#define FOV_GAZE_FIT_MIN 8           /* samples before _gaze_predict fits (else: settling) */
#define FOV_GAZE_FIT_MIN_MS 40.0f    /* and their span, milliseconds */
typedef enum fov_gaze_mode {
    FOV_GAZE_SETTLING = 0, /* too few samples since the reset or landing: the filtered gaze */
    FOV_GAZE_FIXATION = 1, /* not moving: the fitted mean */
    FOV_GAZE_PURSUIT = 2,  /* moving: extrapolated by the latency */
    FOV_GAZE_SACCADE = 3,  /* in a saccade: the raw sample */
    _FOV_GAZE_MODE_NUM = 4,
    _FOV_GAZE_MODE_FORCE_U32 = 0x7FFFFFFF
} fov_gaze_mode;
/* _gaze_predict's answer: where to centre the fovea for the frame and how much to grow it. */
typedef struct fov_gaze_prediction {
    float x_deg, y_deg;  /* the gaze predicted for latency_ms after the newest sample, degrees */
    float margin_deg;    /* the margin around it, degrees (capped at cfg.max_margin_deg) */
    float vx, vy;        /* the fitted velocity, deg/s (0 when settling or in a saccade) */
    float horizon_s;     /* the extrapolation's lever h, seconds (0 unless pursuit) */
    uint32_t n;          /* samples fitted (0 when settling or in a saccade) */
    fov_gaze_mode mode;  /* which case above */
} fov_gaze_prediction;
typedef struct fov_gaze_filter_config {
    float min_cutoff_hz; /* One Euro f_cmin: the cutoff of a still eye, Hz, (0, 100]   0: 0.5 */
    float beta;          /* One Euro beta: cutoff added per deg/s of speed, Hz s / deg,
                            (0, 10]; FOV_GAZE_BETA_NONE for none (a beta of 0)   0: 0.3 */
    float d_cutoff_hz;   /* cutoff of the velocity estimate, Hz, (0, 100]            0: 1 */
    float saccade_deg_s; /* saccade onset speed, deg/s, [20, 2000] (landing at half) 0: 100 */
    float window_ms;     /* the saccade detector's speed window, ms, [1, 100]        0: 20 */
    float max_dt_ms;     /* a larger step between samples is FOV_ERR_LIMIT, (0, 1e6]  0: 500 */
    float max_margin_deg; /* the margin's cap (and the margin during a saccade), (0, 90]
                                                                                  0: 15 */
    float predict_ms;    /* _gaze_predict's fit window, ms, [40, 2000]                0: 200 */
    fov_logger logger;   /* optional: every rejected call (_gaze_filter_init with this config,
                            _push, _push_px, _gaze_margin and _gaze_predict on the filter)
                            calls it once with FOV_LOG_ERROR, the code and the message, as the
                            configs do */
} fov_gaze_filter_config;
#define FOV_GAZE_BETA_NONE (-1.0f) /* beta: no speed adaptation (a plain low-pass) */
#define FOV_GAZE_HISTORY 32        /* raw samples kept for the saccade window: window_ms
   needs window_ms x rate + 1 of them, so 32 cover the default 20 ms up to a tracker rate of
   1.55 kHz; above it the window speed is taken over the oldest kept sample (31 sample steps,
   a shorter span: the noise is divided by less and the detector fires more easily). Trackers
   above about 1.5 kHz: lower the rate you push at (decimate) or shorten window_ms knowingly. */
/* Fixed foveation for users without an eye tracker: the gaze at the display's axis point
   (the lens centre of an HMD, the screen centre of a monitor: _gaze_fixed) and the foveae
   grown by this many degrees (_config_gaze_margin): most natural saccades are 15 degrees or
   smaller and larger gaze shifts come with a head movement (Bahill, Adler and Stark, "Most
   naturally occurring human saccades have magnitudes of 15 degrees or less", Investigative
   Ophthalmology 1975), so a still head mostly looks within 15 degrees of straight ahead. */
#define FOV_GAZE_FIXED_MARGIN_DEG 15.0f

/* The filter's state, in caller memory (a few hundred bytes, no pointers: copy it freely).
   Fill it with _gaze_filter_init; read x_deg, y_deg (the filtered gaze) and the rest after
   each push; write nothing. */
typedef struct fov_gaze_filter {
    fov_gaze_filter_config cfg; /* resolved (defaults filled in) */
    float x_deg, y_deg;   /* the filtered gaze, degrees (valid once samples > 0) */
    float vx, vy;         /* its filtered velocity, deg/s */
    float speed_deg_s;    /* |(vx, vy)| (during a saccade: the raw window speed) */
    float ox, oy;         /* velocity of the filtered gaze itself (its steps over time,
                             smoothed at d_cutoff_hz), deg/s: what the margin uses */
    float out_speed_deg_s; /* |(ox, oy)| */
    float te_s;           /* the last time step, seconds */
    float cutoff_hz;      /* the position cutoff fc of the last sample */
    float alpha;          /* the position weight of the last sample (1 in a saccade) */
    float noise_deg;      /* running RMS of raw - filtered (2-D), the raw noise estimate */
    float raw_x, raw_y;   /* the last raw sample, degrees */
    uint32_t saccade;     /* 1 while a saccade is in flight (output = raw) */
    uint32_t saccades;    /* saccades detected since init */
    uint32_t samples;     /* samples since init or reset */
    uint32_t settled;     /* samples since the last reset or landing (n above) */
    uint64_t t_us;        /* the last sample's timestamp, microseconds */
    uint32_t head, count; /* ring of the last raw samples (saccade window) */
    uint64_t hist_t[FOV_GAZE_HISTORY];
    float hist_x[FOV_GAZE_HISTORY], hist_y[FOV_GAZE_HISTORY];
} fov_gaze_filter;

#ifdef __cplusplus
}
#endif
#elif FOV_SHARED_REVISION != 5
#error "fov: fovsdf.h, fovlp.h and fovpt.h of different releases in one translation unit"
#endif /* FOV_SHARED_DECL_INCLUDED */
/* ==== FOV_SHARED_END decl ==================================================================== */

/* ==== FOV_SHARED_BEGIN impl: shared by fovsdf.h, fovlp.h and fovpt.h ========================= */
/* Byte-identical in the three headers, compiled once per translation unit (edit
   tools/fov_shared.h, then run `python3 tools/sync_shared.py`). Private: every name starts
   with fov__ / FOV__ and has internal linkage. */
#ifndef FOV__SHARED_IMPL_INCLUDED
#define FOV__SHARED_IMPL_INCLUDED 1

#include <float.h>
#include <limits.h>

/* ---- hooks ------------------------------------------------------------------------------ */
#ifndef FOV_ASSERT
#include <assert.h>
#define FOV_ASSERT(c) assert(c)
#endif

#if defined(FOV_SQRTF) || defined(FOV_FLOORF) || defined(FOV_SINF) || defined(FOV_COSF) ||    \
    defined(FOV_TANF) || defined(FOV_ATAN2F) || defined(FOV_EXPF) || defined(FOV_LOGF) ||      \
    defined(FOV_POWF)
#if !defined(FOV_SQRTF) || !defined(FOV_FLOORF) || !defined(FOV_SINF) || !defined(FOV_COSF) || \
    !defined(FOV_TANF) || !defined(FOV_ATAN2F) || !defined(FOV_EXPF) || !defined(FOV_LOGF) ||  \
    !defined(FOV_POWF)
#error "fov: define all nine math hooks (FOV_SQRTF ... FOV_POWF, see the doc block) or none"
#endif
#define FOV__HOOKED_MATH 1
#endif

#define FOV__PRIV static FOV__UNUSED

/* Float tests without == (the library builds clean with -Wfloat-equal). */
FOV__PRIV int fov__is0(float x) { return x <= 0.0f && x >= 0.0f; }       /* +-0, not NaN */
FOV__PRIV int fov__isnan(float x) { return !(x <= 0.0f) && !(x > 0.0f); }

#if !defined(FOV__HOOKED_MATH) && !defined(FOV_NO_LIBM)
#include <math.h>
#define FOV__SQRT(x) sqrtf(x)
#define FOV__FLOOR(x) floorf(x)
#define FOV__SIN(x) sinf(x)
#define FOV__COS(x) cosf(x)
#define FOV__TAN(x) tanf(x)
#define FOV__ATAN2(y, x) atan2f(y, x)
#define FOV__EXP(x) expf(x)
#define FOV__LOG(x) logf(x)
#define FOV__POW(x, y) powf(x, y)
#elif defined(FOV__HOOKED_MATH)
#define FOV__SQRT(x) FOV_SQRTF(x)
#define FOV__FLOOR(x) FOV_FLOORF(x)
#define FOV__SIN(x) FOV_SINF(x)
#define FOV__COS(x) FOV_COSF(x)
#define FOV__TAN(x) FOV_TANF(x)
#define FOV__ATAN2(y, x) FOV_ATAN2F(y, x)
#define FOV__EXP(x) FOV_EXPF(x)
#define FOV__LOG(x) FOV_LOGF(x)
#define FOV__POW(x, y) FOV_POWF(x, y)
#else
/* FOV_NO_LIBM: small float approximations (relative error about 1e-6 or better on the
   ranges the library uses; tests/test_fovsdf.c checks them against libm). The square root
   is the target's own instruction where it has one for certain, which needs no libm
   (FOV__SQRT_HW: 1 x86 SSE sqrtss (inline assembly with gcc and clang, so a freestanding
   build includes no intrinsics header, which may pull in <stdlib.h>; <xmmintrin.h> with
   MSVC), 2 AArch64 fsqrt, 3 32-bit Arm VFP vsqrt.f32, 4 wasm f32.sqrt): correctly rounded,
   the value libm's sqrtf gives, -0 for -0. Elsewhere (x87-only x86,
   Cortex-M0/M3, RISC-V, MSVC on Arm...) the software versions below. __builtin_sqrtf is
   not used outside wasm: gcc keeps a call to sqrtf for negative inputs (errno) unless
   -fno-math-errno, and a target without the instruction always calls sqrtf. */
#define FOV__SQRT(x) fov__sqrtf(x)
#define FOV__FLOOR(x) fov__floorf(x)
#define FOV__SIN(x) fov__sinf(x)
#define FOV__COS(x) fov__cosf(x)
#define FOV__TAN(x) (fov__sinf(x) / fov__cosf(x))
#define FOV__ATAN2(y, x) fov__atan2f(y, x)
#define FOV__EXP(x) fov__expf(x)
#define FOV__LOG(x) fov__logf(x)
#define FOV__POW(x, y) fov__powf(x, y)

#if defined(__wasm__) && defined(__clang__)
#define FOV__SQRT_HW 4
#elif defined(__SSE__) && defined(__GNUC__)
#define FOV__SQRT_HW 1
#elif defined(_MSC_VER) && (defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 1))
#define FOV__SQRT_HW 1
#include <xmmintrin.h>
#elif defined(__aarch64__) && defined(__GNUC__)
#define FOV__SQRT_HW 2
#elif defined(__ARM_FP) && (__ARM_FP & 4) && defined(__GNUC__) && !defined(__aarch64__)
#define FOV__SQRT_HW 3
#endif

typedef union fov__bits { float f; uint32_t u; } fov__bits;

FOV__PRIV float fov__sqrtf(float x)
{
#if defined(FOV__SQRT_HW) && FOV__SQRT_HW == 4
    return __builtin_sqrtf(x); /* one f32.sqrt instruction (clang's wasm32 has no errno) */
#elif defined(FOV__SQRT_HW) && FOV__SQRT_HW == 1 && defined(__GNUC__)
    float r;
    __asm__("sqrtss {%1, %0|%0, %1}" : "=x"(r) : "x"(x)); /* AT&T | Intel syntax */
    return r;
#elif defined(FOV__SQRT_HW) && FOV__SQRT_HW == 1
    return _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x))); /* sqrtss */
#elif defined(FOV__SQRT_HW) && FOV__SQRT_HW == 2
    float r;
    __asm__("fsqrt %s0, %s1" : "=w"(r) : "w"(x));
    return r;
#elif defined(FOV__SQRT_HW) && FOV__SQRT_HW == 3
    float r;
    __asm__("vsqrt.f32 %0, %1" : "=t"(r) : "t"(x));
    return r;
#else
    fov__bits b;
    float y;
    if (!(x > 0.0f)) return fov__is0(x) ? x : (x - x) / (x - x); /* +-0, or NaN for x < 0 */
    if (x > FLT_MAX) return x;
    b.f = x;
    b.u = 0x5f3759dfu - (b.u >> 1); /* 1/sqrt(x) estimate, then Newton */
    y = b.f;
    y = y * (1.5f - 0.5f * x * y * y);
    y = y * (1.5f - 0.5f * x * y * y);
    y = y * (1.5f - 0.5f * x * y * y);
    y = x * y;                          /* sqrt estimate; one Newton step on sqrt */
    return 0.5f * (y + x / y);
#endif
}

FOV__PRIV float fov__floorf(float x)
{
    float r;
    if (!(x > -8388608.0f && x < 8388608.0f)) return x; /* integral already, or NaN */
    r = (float)(int32_t)x;
    return r > x ? r - 1.0f : r;
}

/* sin and cos on [-pi/4, pi/4] (Taylor to order 11 / 10). */
FOV__PRIV float fov__sin_k(float x)
{
    float x2 = x * x;
    return x * (1.0f + x2 * (-1.6666667e-1f + x2 * (8.3333333e-3f + x2 * (-1.9841270e-4f +
                x2 * (2.7557319e-6f - x2 * 2.5052108e-8f)))));
}
FOV__PRIV float fov__cos_k(float x)
{
    float x2 = x * x;
    return 1.0f + x2 * (-0.5f + x2 * (4.1666667e-2f + x2 * (-1.3888889e-3f +
                x2 * (2.4801587e-5f - x2 * 2.7557319e-7f))));
}
/* Reduce x by multiples of pi/2 (Cody-Waite, 3-part pi/2); quadrant in *q. */
FOV__PRIV float fov__reduce(float x, int32_t *q)
{
    float k;
    if (!(x > -1e6f && x < 1e6f)) { *q = 0; return (x > -FLT_MAX && x < FLT_MAX) ? 0.0f : x - x; }
    k = fov__floorf(x * 0.63661977236758134f + 0.5f);
    *q = (int32_t)k;
    /* pi/2 = 1.5703125 + 4.837512969970703e-4 + 7.549789954891882e-8; k * 1.5703125 is exact */
    return ((x - k * 1.5703125f) - k * 4.837512969970703e-4f) - k * 7.549789954891882e-8f;
}
FOV__PRIV float fov__sinf(float x)
{
    int32_t q;
    float r = fov__reduce(x, &q);
    switch (q & 3) {
    case 0: return fov__sin_k(r);
    case 1: return fov__cos_k(r);
    case 2: return -fov__sin_k(r);
    default: return -fov__cos_k(r);
    }
}
FOV__PRIV float fov__cosf(float x)
{
    int32_t q;
    float r = fov__reduce(x, &q);
    switch (q & 3) {
    case 0: return fov__cos_k(r);
    case 1: return -fov__sin_k(r);
    case 2: return -fov__cos_k(r);
    default: return fov__sin_k(r);
    }
}
/* atan on [0, 1] via the reduction atan(x) = pi/4 + atan((x-1)/(x+1)) for x > tan(pi/8). */
FOV__PRIV float fov__atan01(float x)
{
    float off = 0.0f, z, z2;
    if (x > 0.41421356f) { off = 0.78539816f; x = (x - 1.0f) / (x + 1.0f); }
    z = x;
    z2 = z * z;
    return off + z * (1.0f + z2 * (-3.3333333e-1f + z2 * (2.0e-1f + z2 * (-1.4285714e-1f +
                 z2 * (1.1111111e-1f + z2 * (-9.0909091e-2f + z2 * 7.6923077e-2f))))));
}
FOV__PRIV float fov__atan2f(float y, float x)
{
    float ax = x < 0.0f ? -x : x, ay = y < 0.0f ? -y : y, a;
    if (fov__isnan(x) || fov__isnan(y)) return x + y;
    if (fov__is0(ax) && fov__is0(ay)) return 0.0f;
    a = ay <= ax ? fov__atan01(ay / ax) : 1.57079633f - fov__atan01(ax / ay);
    if (x < 0.0f) a = 3.14159265f - a;
    return y < 0.0f ? -a : a;
}
FOV__PRIV float fov__expf(float x)
{
    float k, r, p;
    fov__bits b;
    if (fov__isnan(x)) return x;
    if (x > 88.7f) return FLT_MAX * 2.0f;
    if (x < -103.0f) return 0.0f;
    k = fov__floorf(x * 1.44269504f + 0.5f);
    r = (x - k * 0.693145752f) - k * 1.42860677e-6f;
    p = 1.0f + r * (1.0f + r * (0.5f + r * (1.6666667e-1f + r * (4.1666667e-2f +
        r * (8.3333333e-3f + r * 1.3888889e-3f)))));
    if (k < -126.0f) {
        b.u = (uint32_t)(k + 126.0f + 127.0f) << 23;
        return p * b.f * 1.17549435e-38f;
    }
    b.u = (uint32_t)((int32_t)k + 127) << 23;
    return p * b.f;
}
FOV__PRIV float fov__logf(float x)
{
    fov__bits b;
    int32_t e;
    float m, s, s2;
    if (fov__isnan(x) || x < 0.0f) return (x - x) / (x - x);
    if (fov__is0(x)) return -FLT_MAX * 2.0f;
    if (x > FLT_MAX) return x;
    b.f = x;
    e = 0;
    if (b.u < 0x00800000u) { b.f = x * 8388608.0f; e = -23; } /* subnormal */
    e += (int32_t)((b.u >> 23) & 0xffu) - 127;
    b.u = (b.u & 0x007fffffu) | 0x3f800000u; /* m in [1, 2) */
    m = b.f;
    if (m > 1.41421356f) { m *= 0.5f; e += 1; }
    s = (m - 1.0f) / (m + 1.0f); /* log(m) = 2 atanh(s) */
    s2 = s * s;
    return (float)e * 0.693147181f +
           2.0f * s * (1.0f + s2 * (3.3333333e-1f + s2 * (2.0e-1f + s2 * (1.4285714e-1f +
                                                                   s2 * 1.1111111e-1f))));
}
FOV__PRIV float fov__powf(float x, float y)
{
    if (fov__is0(y)) return 1.0f;
    if (fov__is0(x)) return y > 0.0f ? 0.0f : FLT_MAX * 2.0f;
    if (x < 0.0f) {
        float fy = fov__floorf(y);
        float r;
        if (fy < y || fy > y) return (x - x) / (x - x);
        r = fov__expf(y * fov__logf(-x));
        return ((int32_t)fov__floorf(y * 0.5f) * 2 == (int32_t)fy) ? r : -r;
    }
    return fov__expf(y * fov__logf(x));
}
#endif

#ifndef FOV_MEMSET
#define FOV_MEMSET(p, v, n) fov__memset(p, v, n)
FOV__PRIV void fov__memset(void *p, int v, size_t n)
{
    unsigned char *c = (unsigned char *)p;
    while (n--) *c++ = (unsigned char)v;
}
#endif
#ifndef FOV_MEMCPY
#define FOV_MEMCPY(d, s, n) fov__memcpy(d, s, n)
FOV__PRIV void fov__memcpy(void *d, const void *s, size_t n)
{
    unsigned char *a = (unsigned char *)d;
    const unsigned char *b = (const unsigned char *)s;
    while (n--) *a++ = *b++;
}
#endif

#define FOV__PI 3.14159265358979f
#define FOV__DEG 0.0174532925199433f

/* ---- small helpers ---------------------------------------------------------------------- */
FOV__PRIV int fov__finite(float x) { return x >= -FLT_MAX && x <= FLT_MAX; }
FOV__PRIV int fov__finite3(const float v[3])
{
    return fov__finite(v[0]) && fov__finite(v[1]) && fov__finite(v[2]);
}
FOV__PRIV float fov__minf(float a, float b) { return a < b ? a : b; }
FOV__PRIV float fov__maxf(float a, float b) { return a > b ? a : b; }
FOV__PRIV float fov__absf(float a) { return a < 0.0f ? -a : a; }
FOV__PRIV float fov__clampf(float x, float a, float b) { return x < a ? a : (x > b ? b : x); }
FOV__PRIV float fov__dot(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
FOV__PRIV float fov__len(const float a[3]) { return FOV__SQRT(fov__dot(a, a)); }
FOV__PRIV void fov__cross(const float a[3], const float b[3], float r[3])
{
    float x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2];
    float z = a[0] * b[1] - a[1] * b[0];
    r[0] = x; r[1] = y; r[2] = z;
}
/* Brings a vector whose squared length would underflow or overflow (largest component
   below 1e-15 or above 1e15) to a largest component of 1; other vectors are untouched, bit
   for bit. Leaves zero and non-finite vectors as they are. */
FOV__PRIV void fov__prescale(float v[3])
{
    float m = fov__maxf(fov__absf(v[0]), fov__maxf(fov__absf(v[1]), fov__absf(v[2])));
    if (m > 0.0f && fov__finite(m) && (m < 1e-15f || m > 1e15f)) {
        v[0] /= m; v[1] /= m; v[2] /= m;
    }
}
/* Normalises v in place and returns its length, or 0 when v is zero or has a NaN or
   infinite component (v is then left as it is): a return > 0 means v is now unit. Every
   normalisation in the library goes through here. A squared length in [1e-30, 1e30] takes
   the plain path (sqrt of the dot product, three divisions); any other finite vector is
   first prescaled to a largest component m = 1 (fov__prescale), so vectors of any finite
   length come out unit (|v| - 1 within 2 ulps) instead of unnormalised; the length returned
   is then m * |v / m| (+inf when it exceeds FLT_MAX: still > 0, v still unit). */
FOV__PRIV float fov__normalize(float v[3])
{
    float l2 = fov__dot(v, v), l, m;
    if (l2 >= 1e-30f && l2 <= 1e30f) {
        l = FOV__SQRT(l2);
        v[0] /= l; v[1] /= l; v[2] /= l;
        return l;
    }
    if (!fov__finite(v[0]) || !fov__finite(v[1]) || !fov__finite(v[2])) return 0.0f;
    m = fov__maxf(fov__absf(v[0]), fov__maxf(fov__absf(v[1]), fov__absf(v[2])));
    if (!(m > 0.0f)) return 0.0f;
    v[0] /= m; v[1] /= m; v[2] /= m;
    l = fov__len(v); /* in [1, sqrt 3] */
    v[0] /= l; v[1] /= l; v[2] /= l;
    return m * l;
}
FOV__PRIV size_t fov__align(size_t x) { return (x + 15u) & ~(size_t)15u; }

/* ---- errors ----------------------------------------------------------------------------- */
/* Messages are on by default; FOV_NO_ERROR_STRINGS compiles them out (the logger then gets
   ""). FOV__FAIL reports through the optional logger and returns the code. */
#ifndef FOV_NO_ERROR_STRINGS
#define FOV__MSG(s) s
#else
#define FOV__MSG(s) ""
#endif
FOV__PRIV fov_result fov__err(const fov_logger *lg, const char *tag, fov_result r, const char *msg,
                              uint32_t line)
{
    if (lg && lg->func) lg->func(tag, FOV_LOG_ERROR, (int32_t)r, msg, line, lg->user);
    return r;
}
#define FOV__FAIL(lg, tag, r, msg) return fov__err(lg, tag, r, FOV__MSG(msg), (uint32_t)__LINE__)
#ifndef FOV_NO_ERROR_STRINGS
/* Append s (or v in decimal) to the message buf of capacity cap holding n characters. */
FOV__PRIV uint32_t fov__app(char *buf, uint32_t n, uint32_t cap, const char *s)
{
    while (*s && n + 1u < cap) buf[n++] = *s++;
    buf[n] = 0;
    return n;
}
FOV__PRIV uint32_t fov__appu(char *buf, uint32_t n, uint32_t cap, uint32_t v)
{
    char d[12];
    uint32_t k = 0;
    do { d[k++] = (char)('0' + (int)(v % 10u)); v /= 10u; } while (v > 0u && k < 11u);
    while (k > 0u && n + 1u < cap) buf[n++] = d[--k];
    buf[n] = 0;
    return n;
}
#endif
/* Logs the message a b c (composed on the stack; "" under FOV_NO_ERROR_STRINGS), returns r. */
FOV__PRIV fov_result fov__err3(const fov_logger *lg, const char *tag, fov_result r, const char *a,
                               const char *b, const char *c, uint32_t line)
{
#ifndef FOV_NO_ERROR_STRINGS
    char buf[112];
    uint32_t n = fov__app(buf, 0, sizeof buf, a);
    n = fov__app(buf, n, sizeof buf, b);
    (void)fov__app(buf, n, sizeof buf, c);
    return fov__err(lg, tag, r, buf, line);
#else
    (void)a; (void)b; (void)c;
    return fov__err(lg, tag, r, "", line);
#endif
}
/* A float field of a struct for fov__fields_check: byte offset, 1 if it must be >= 0, name. */
typedef struct fov__field {
    uint16_t off, nonneg;
    const char *name;
} fov__field;
#define FOV__FIELD(type, member, nonneg) { (uint16_t)offsetof(type, member), nonneg, \
                                           FOV__MSG(#member) }
/* Pass 0: the first of the n fields of the struct at base that is NaN or infinite fails with
   FOV_ERR_NOT_FINITE, "<who><name> is NaN or infinite"; pass 1: the first negative one among
   those marked nonneg fails with FOV_ERR_INVALID_ARG, "<who><name> must be >= 0". */
FOV__PRIV fov_result fov__fields_check(const fov_logger *lg, const char *tag, const char *who,
                                       const void *base, const fov__field *f, uint32_t n,
                                       int pass, uint32_t line)
{
    uint32_t i;
    for (i = 0; i < n; ++i) {
        float x;
        FOV_MEMCPY(&x, (const unsigned char *)base + f[i].off, sizeof x);
        if (pass == 0 && !fov__finite(x))
            return fov__err3(lg, tag, FOV_ERR_NOT_FINITE, who, f[i].name, " is NaN or infinite",
                             line);
        if (pass == 1 && f[i].nonneg && x < 0.0f)
            return fov__err3(lg, tag, FOV_ERR_INVALID_ARG, who, f[i].name, " must be >= 0", line);
    }
    return FOV_OK;
}

/* The rules of config.display (fov_display): what & 1, every field finite; what & 2,
   fov_y_deg in [0, 180), pixel_pitch_mm and distance_mm >= 0 and given together. */
FOV__PRIV fov_result fov__display_check(const fov_logger *lg, const char *tag, const fov_display *d,
                                        int what, uint32_t line)
{
    static const fov__field f[5] = {
        FOV__FIELD(fov_display, fov_y_deg, 0), FOV__FIELD(fov_display, pixel_pitch_mm, 0),
        FOV__FIELD(fov_display, distance_mm, 0), FOV__FIELD(fov_display, axis_dx, 0),
        FOV__FIELD(fov_display, axis_dy, 0) };
    fov_result r = FOV_OK;
    if (what & 1) r = fov__fields_check(lg, tag, "config.display.", d, f, 5u, 0, line);
    if (r != FOV_OK || !(what & 2)) return r;
    if (d->fov_y_deg < 0.0f || d->fov_y_deg >= 180.0f)
        return fov__err(lg, tag, FOV_ERR_INVALID_ARG,
                        FOV__MSG("config.display.fov_y_deg must be in [0, 180)"), line);
    if (d->pixel_pitch_mm < 0.0f || d->distance_mm < 0.0f)
        return fov__err(lg, tag, FOV_ERR_INVALID_ARG,
                        FOV__MSG("config.display: pixel_pitch_mm, distance_mm must be >= 0"), line);
    if (fov__is0(d->pixel_pitch_mm) != fov__is0(d->distance_mm))
        return fov__err(lg, tag, FOV_ERR_INVALID_ARG,
                        FOV__MSG("config.display: give pixel_pitch_mm and distance_mm, or neither"),
                        line);
    return FOV_OK;
}

FOV__PRIV const char *fov__result_string(fov_result r)
{
#ifdef FOV_NO_ERROR_STRINGS
    (void)r;
    return "";
#else
    switch (r) {
    case FOV_OK: return "ok";
    case FOV_ERR_INVALID_ARG: return "invalid argument: a parameter is out of range";
    case FOV_ERR_TOO_SMALL: return "buffer or memory too small";
    case FOV_ERR_LIMIT: return "size above a hard limit or overflowing";
    case FOV_ERR_NULL: return "a required pointer is NULL";
    case FOV_ERR_NOT_FINITE: return "NaN or infinite value where a finite one is required";
    case FOV_ERR_DEGENERATE: return "degenerate camera, display or scene";
    case FOV_ERR_UNSUPPORTED: return "not supported by this build";
    default: return "unknown result code";
    }
#endif
}

/* ---- the camera (see fov_camera) -------------------------------------------------------- */
/* The fov_camera defaults (fovsdf_camera_init, fovpt_camera_init). */
FOV__PRIV void fov__camera_init(fov_camera *cam, uint32_t width, uint32_t height)
{
    if (!cam) return;
    FOV_MEMSET(cam, 0, sizeof *cam);
    cam->pos[2] = 5.0f;
    cam->up[1] = 1.0f;
    cam->fov_y_deg = 60.0f;
    cam->width = width;
    cam->height = height;
}

/* The camera's frame (fovsdf_camera_basis, fovlp_camera_from): fwd, right, up = right x fwd,
   unit and orthogonal. A tiny (1e-30) or huge (1e30) up hint or view vector is valid (it is
   prescaled). FOV_ERR_NOT_FINITE for NaN or infinite vectors, FOV_ERR_DEGENERATE for a zero
   or overflowing view vector or an up hint parallel to it. (fovpt keeps its own version of
   this, see fovpt__camera_setup.) */
FOV__PRIV fov_result fov__camera_basis(const fov_camera *cam, float right[3], float up[3],
                                       float fwd[3])
{
    float f[3], u[3], r[3], l;
    int k;
    if (!fov__finite3(cam->pos) || !fov__finite3(cam->target) || !fov__finite3(cam->up))
        return FOV_ERR_NOT_FINITE;
    for (k = 0; k < 3; ++k) {
        f[k] = cam->target[k] - cam->pos[k];
        u[k] = cam->up[k];
    }
    if (fov__is0(u[0]) && fov__is0(u[1]) && fov__is0(u[2])) u[1] = 1.0f;
    fov__prescale(f);
    fov__prescale(u);
    l = fov__len(f); /* after the prescale: 0, infinite (target - pos overflowed) or plain */
    if (!(l > 0.0f) || !fov__finite(l)) return FOV_ERR_DEGENERATE;
    f[0] /= l; f[1] /= l; f[2] /= l;
    l = fov__len(u);
    u[0] /= l; u[1] /= l; u[2] /= l;
    fov__cross(f, u, r);
    l = fov__len(r);
    if (!(l > 1e-6f)) return FOV_ERR_DEGENERATE; /* looking along the up vector */
    r[0] /= l; r[1] /= l; r[2] /= l;
    fov__cross(r, f, u);
    l = fov__len(u);
    u[0] /= l; u[1] /= l; u[2] /= l;
    for (k = 0; k < 3; ++k) {
        right[k] = r[k];
        up[k] = u[k];
        fwd[k] = f[k];
    }
    return FOV_OK;
}

/* ---- the eccentricity model (see fov_display) ------------------------------------------- */
FOV__PRIV fov_result fov__ecc_init(fov_ecc_model *m, const fov_display *d, float cam_fov_y_deg,
                                   uint32_t width, uint32_t height, fov_gaze gaze, uint32_t max_dim)
{
    float f, v[3];
    fov_display z;
    if (!m) return FOV_ERR_NULL;
    if (!d) { FOV_MEMSET(&z, 0, sizeof z); d = &z; }
    if (width == 0 || height == 0) return FOV_ERR_INVALID_ARG;
    if (width > max_dim || height > max_dim) return FOV_ERR_LIMIT;
    if (!fov__finite(gaze.x) || !fov__finite(gaze.y) || !fov__finite(cam_fov_y_deg) ||
        !fov__finite(d->fov_y_deg) || !fov__finite(d->pixel_pitch_mm) ||
        !fov__finite(d->distance_mm) || !fov__finite(d->axis_dx) || !fov__finite(d->axis_dy))
        return FOV_ERR_NOT_FINITE;
    if (d->fov_y_deg > 0.0f) {
        if (d->fov_y_deg >= 180.0f) return FOV_ERR_INVALID_ARG;
        f = 0.5f * (float)height / FOV__TAN(0.5f * d->fov_y_deg * FOV__DEG);
    } else if (d->pixel_pitch_mm > 0.0f && d->distance_mm > 0.0f) {
        f = d->distance_mm / d->pixel_pitch_mm;
    } else if (d->fov_y_deg < 0.0f || !fov__is0(d->pixel_pitch_mm) || !fov__is0(d->distance_mm)) {
        return FOV_ERR_INVALID_ARG; /* negative, or a monitor given by pitch or distance only */
    } else {
        if (!(cam_fov_y_deg > 0.0f && cam_fov_y_deg < 180.0f)) return FOV_ERR_INVALID_ARG;
        f = 0.5f * (float)height / FOV__TAN(0.5f * cam_fov_y_deg * FOV__DEG);
    }
    if (!(f > 0.0f) || !fov__finite(f)) return FOV_ERR_DEGENERATE;
    m->cx = 0.5f * (float)width + d->axis_dx;
    m->cy = 0.5f * (float)height + d->axis_dy;
    m->f_px = f;
    m->gx = gaze.x;
    m->gy = gaze.y;
    v[0] = gaze.x - m->cx; v[1] = gaze.y - m->cy; v[2] = f;
    if (!fov__finite3(v)) return FOV_ERR_INVALID_ARG;
    if (!fov__finite(fov__dot(v, v))) {
        /* a gaze far off-screen (|v| > ~1e19 px): only the direction counts, so scale by the
           largest component first (any finite gaze works; the usual range is untouched) */
        float s = fov__maxf(fov__maxf(fov__absf(v[0]), fov__absf(v[1])), v[2]);
        v[0] /= s; v[1] /= s; v[2] /= s;
    }
    fov__normalize(v);
    m->g[0] = v[0]; m->g[1] = v[1]; m->g[2] = v[2];
    return FOV_OK;
}

/* The angle in degrees between the eye's rays through (x, y) and through the gaze point. */
FOV__PRIV float fov__ecc_deg(const fov_ecc_model *m, float x, float y)
{
    float v[3], c[3], s, co;
    if (!m) return 0.0f;
    v[0] = x - m->cx; v[1] = y - m->cy; v[2] = m->f_px;
    if (!fov__finite(fov__dot(v, v)) && fov__finite(x) && fov__finite(y)) {
        /* a point beyond ~1e19 px (or x - cx overflows): only the direction counts, so halve
           (no overflow) and scale by the largest component; the usual range is untouched */
        float k;
        v[0] = 0.5f * x - 0.5f * m->cx; v[1] = 0.5f * y - 0.5f * m->cy; v[2] = 0.5f * m->f_px;
        k = fov__maxf(fov__maxf(fov__absf(v[0]), fov__absf(v[1])), v[2]);
        v[0] /= k; v[1] /= k; v[2] /= k;
    }
    fov__cross(v, m->g, c);
    s = fov__len(c);
    co = fov__dot(v, m->g);
    return FOV__ATAN2(s, co) * (180.0f / FOV__PI); /* atan2 keeps small angles exact */
}

/* Pixels per degree at the gaze. d(angle)/d(pixels) along the radial direction at the gaze is
   f / (f^2 + r^2) radians per pixel, with r the gaze's distance from the axis. */
FOV__PRIV float fov__ecc_ppd(const fov_ecc_model *m)
{
    float rx, ry, r2, ppd;
    if (!m) return 0.0f;
    rx = m->gx - m->cx; ry = m->gy - m->cy; r2 = rx * rx + ry * ry;
    ppd = (m->f_px * m->f_px + r2) / m->f_px * FOV__DEG;
    return ppd <= 3.4028235e38f ? ppd : 3.4028235e38f; /* gaze beyond ~1e19 px: FLT_MAX */
}

/* ---- the eye's resolution (see fov_eye) ------------------------------------------------- */
/* The eye's fields with defaults, in degrees: mar0, slope and quality; 0 on bad fields. */
FOV__PRIV int fov__eye_get(const fov_eye *e, float *mar0, float *slope, float *q)
{
    float a = e ? e->mar0_arcmin : 0.0f, b = e ? e->slope_arcmin : 0.0f;
    float c = e ? e->quality : 0.0f;
    if (fov__is0(a)) a = 1.0f;
    if (fov__is0(b)) b = 1.32f;
    if (fov__is0(c)) c = 0.5f;
    if (!(a > 0.0f && a <= 60.0f) || !(b > 0.0f && b <= 60.0f) || !(c > 0.0f && c <= 100.0f))
        return 0;
    *mar0 = a / 60.0f; *slope = b / 60.0f; *q = c;
    return 1;
}

/* The allowed sample spacing at eccentricity ecc, degrees: quality * MAR(ecc); 0 on bad input. */
FOV__PRIV float fov__eye_mar(const fov_eye *e, float ecc)
{
    float w0, m, q;
    if (!fov__eye_get(e, &w0, &m, &q) || !(ecc >= 0.0f && ecc <= 180.0f)) return 0.0f;
    return q * (w0 + m * ecc);
}

/* The linear sample density the eye needs at ecc, in samples per display pixel along each axis,
   in (0, 1]: min(1, 1 / (ppd spacing)). Bad input: 1 (every pixel, the safe answer). */
FOV__PRIV float fov__eye_density(const fov_eye *e, float ppd, float ecc)
{
    float s = fov__eye_mar(e, ecc), d;
    if (!(s > 0.0f) || !(ppd > 0.0f) || !fov__finite(ppd)) return 1.0f;
    d = 1.0f / (ppd * s);
    return d < 1.0f ? d : 1.0f;
}

/* The eccentricity in degrees, [0, 180], from which a linear density `density` (0, 1] is as
   fine as the eye resolves: the inverse of fov__eye_density. Bad input: 0 for a density of 1
   or more, 180 (never) otherwise: the safe answers. */
FOV__PRIV float fov__eye_ecc(const fov_eye *e, float ppd, float density)
{
    float w0, m, q, x;
    if (!fov__eye_get(e, &w0, &m, &q) || !(ppd > 0.0f) || !fov__finite(ppd) ||
        !(density > 0.0f) || !fov__finite(density))
        return density >= 1.0f ? 0.0f : 180.0f;
    if (density >= 1.0f) density = 1.0f;
    x = (1.0f / (ppd * density * q) - w0) / m;
    if (!(x > 0.0f)) return 0.0f;
    return x < 180.0f ? x : 180.0f;
}

/* Checks a fov_eye field by field (NULL: the defaults), logging which field breaks which rule
   ("<who>eye.slope_arcmin must be in (0, 60] (0: 1.32)"): what each header's config_acuity
   calls before fov__eye_plan. */
FOV__PRIV fov_result fov__eye_check(const fov_logger *lg, const char *tag, const char *who,
                                    const fov_eye *eye)
{
    static const char *const nm[3] = { FOV__MSG("eye.mar0_arcmin"), FOV__MSG("eye.slope_arcmin"),
                                       FOV__MSG("eye.quality") };
    static const char *const rule[3] = { FOV__MSG(" must be in (0, 60] (0: 1)"),
                                         FOV__MSG(" must be in (0, 60] (0: 1.32)"),
                                         FOV__MSG(" must be in (0, 100] (0: 1)") };
    static const float hi[3] = { 60.0f, 60.0f, 100.0f };
    float v[3];
    uint32_t i;
    if (!eye) return FOV_OK;
    v[0] = eye->mar0_arcmin; v[1] = eye->slope_arcmin; v[2] = eye->quality;
    for (i = 0; i < 3; ++i) {
        if (!fov__finite(v[i]))
            return fov__err3(lg, tag, FOV_ERR_NOT_FINITE, who, nm[i],
                             FOV__MSG(" is NaN or infinite"), (uint32_t)__LINE__);
        if (v[i] < 0.0f || v[i] > hi[i])
            return fov__err3(lg, tag, FOV_ERR_INVALID_ARG, who, nm[i], rule[i],
                             (uint32_t)__LINE__);
    }
    return FOV_OK;
}

FOV__PRIV fov_result fov__eye_plan(const fov_eye *e, const fov_ecc_model *m, fov_eye_plan *out)
{
    float w0, sl, q, ppd;
    if (!m || !out) return FOV_ERR_NULL;
    if (!fov__eye_get(e, &w0, &sl, &q)) {
        if (e && (!fov__finite(e->mar0_arcmin) || !fov__finite(e->slope_arcmin) ||
                  !fov__finite(e->quality)))
            return FOV_ERR_NOT_FINITE;
        return FOV_ERR_INVALID_ARG;
    }
    ppd = m->f_px * FOV__DEG;
    if (!(ppd > 0.0f) || !fov__finite(ppd)) return FOV_ERR_INVALID_ARG;
    out->ppd = ppd;
    out->e_full = fov__eye_ecc(e, ppd, 1.0f);
    out->e_half = fov__eye_ecc(e, ppd, 0.5f);
    out->e_quarter = fov__eye_ecc(e, ppd, 0.25f);
    return FOV_OK;
}
/* ---- gaze input (see fov_gaze_filter_config) -------------------------------------------- */
/* The config with defaults; FOV_ERR_* (and which field) for bad fields. */
FOV__PRIV fov_result fov__gaze_cfg(const fov_gaze_filter_config *in, fov_gaze_filter_config *o,
                                   const char **bad)
{
    fov_gaze_filter_config c;
    if (in) c = *in; else FOV_MEMSET(&c, 0, sizeof c);
    *bad = FOV__MSG("");
    if (!fov__finite(c.min_cutoff_hz) || !fov__finite(c.beta) || !fov__finite(c.d_cutoff_hz) ||
        !fov__finite(c.saccade_deg_s) || !fov__finite(c.window_ms) ||
        !fov__finite(c.max_dt_ms) || !fov__finite(c.max_margin_deg) ||
        !fov__finite(c.predict_ms)) {
        *bad = FOV__MSG("gaze filter config: a field is NaN or infinite");
        return FOV_ERR_NOT_FINITE;
    }
    if (fov__is0(c.min_cutoff_hz)) c.min_cutoff_hz = 0.5f;
    if (fov__is0(c.beta)) c.beta = 0.3f;
    else if (c.beta < 0.0f && c.beta >= FOV_GAZE_BETA_NONE && c.beta <= FOV_GAZE_BETA_NONE)
        c.beta = 0.0f;
    if (fov__is0(c.d_cutoff_hz)) c.d_cutoff_hz = 1.0f;
    if (fov__is0(c.saccade_deg_s)) c.saccade_deg_s = 100.0f;
    if (fov__is0(c.window_ms)) c.window_ms = 20.0f;
    if (fov__is0(c.max_dt_ms)) c.max_dt_ms = 500.0f;
    if (fov__is0(c.max_margin_deg)) c.max_margin_deg = 15.0f;
    if (fov__is0(c.predict_ms)) c.predict_ms = 200.0f;
    if (!(c.min_cutoff_hz > 0.0f && c.min_cutoff_hz <= 100.0f))
        *bad = FOV__MSG("gaze filter config: min_cutoff_hz must be in (0, 100] (0: 0.5)");
    else if (!(c.beta >= 0.0f && c.beta <= 10.0f))
        *bad = FOV__MSG("gaze filter config: beta must be in (0, 10] (0: 0.3) or "
                        "FOV_GAZE_BETA_NONE (no speed adaptation)");
    else if (!(c.d_cutoff_hz > 0.0f && c.d_cutoff_hz <= 100.0f))
        *bad = FOV__MSG("gaze filter config: d_cutoff_hz must be in (0, 100] (0: 1)");
    else if (!(c.saccade_deg_s >= 20.0f && c.saccade_deg_s <= 2000.0f))
        *bad = FOV__MSG("gaze filter config: saccade_deg_s must be in [20, 2000] (0: 100)");
    else if (!(c.window_ms >= 1.0f && c.window_ms <= 100.0f))
        *bad = FOV__MSG("gaze filter config: window_ms must be in [1, 100] (0: 20)");
    else if (!(c.max_dt_ms > 0.0f && c.max_dt_ms <= 1e6f))
        *bad = FOV__MSG("gaze filter config: max_dt_ms must be in (0, 1e6] (0: 500)");
    else if (!(c.max_margin_deg > 0.0f && c.max_margin_deg <= 90.0f))
        *bad = FOV__MSG("gaze filter config: max_margin_deg must be in (0, 90] (0: 15)");
    else if (!(c.predict_ms >= FOV_GAZE_FIT_MIN_MS && c.predict_ms <= 2000.0f))
        *bad = FOV__MSG("gaze filter config: predict_ms must be in [40, 2000] (0: 200)");
    else {
        *o = c;
        return FOV_OK;
    }
    return FOV_ERR_INVALID_ARG;
}

FOV__PRIV void fov__gaze_reset(fov_gaze_filter *f)
{
    fov_gaze_filter_config c = f->cfg;
    uint32_t k = f->saccades;
    FOV_MEMSET(f, 0, sizeof *f);
    f->cfg = c;
    f->saccades = k;
}

/* A microsecond difference as 32 bits, saturated (about 71 minutes): 32-bit targets convert
   it to float without a 64-bit runtime helper. */
FOV__PRIV uint32_t fov__us32(uint64_t d) { return d > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)d; }

/* The smoothing weight of cutoff fc (Hz) for a time step of te seconds. */
FOV__PRIV float fov__gaze_alpha(float fc, float te)
{
    float r = 2.0f * FOV__PI * fc * te;
    return r / (r + 1.0f);
}

/* One sample; on any error *f is left as it was and *bad names the rule. */
FOV__PRIV fov_result fov__gaze_push(fov_gaze_filter *f, uint64_t t_us, float x, float y,
                                    const char **bad)
{
    fov_gaze_filter s;
    float te, wx, wy, wt, spd, a, ad, dvx, dvy, ex, ey, sp;
    uint32_t i, k;
    *bad = FOV__MSG("");
    if (!fov__finite(x) || !fov__finite(y)) {
        *bad = FOV__MSG("gaze_filter_push: sample NaN or infinite (skip the tracker's invalid "
                        "samples)");
        return FOV_ERR_NOT_FINITE;
    }
    if (!(fov__absf(x) < 90.0f && fov__absf(y) < 90.0f)) {
        *bad = FOV__MSG("gaze_filter_push: sample at or beyond +-90 degrees (must be in "
                        "(-90, 90))");
        return FOV_ERR_INVALID_ARG;
    }
    if (f->samples > 0u) {
        if (t_us < f->t_us) {
            *bad = FOV__MSG("gaze_filter_push: timestamp before the previous sample's");
            return FOV_ERR_INVALID_ARG;
        }
        if (t_us == f->t_us) {
            *bad = FOV__MSG("gaze_filter_push: zero time step (the same timestamp twice)");
            return FOV_ERR_INVALID_ARG;
        }
        if ((float)fov__us32(t_us - f->t_us) > f->cfg.max_dt_ms * 1000.0f) {
            *bad = FOV__MSG("gaze_filter_push: time step above cfg.max_dt_ms (tracking lost: "
                            "call _gaze_filter_reset)");
            return FOV_ERR_LIMIT;
        }
    }
    s = *f;
    /* the ring of raw samples */
    s.head = (s.head + 1u) % FOV_GAZE_HISTORY;
    s.hist_t[s.head] = t_us; s.hist_x[s.head] = x; s.hist_y[s.head] = y;
    if (s.count < FOV_GAZE_HISTORY) s.count++;
    s.raw_x = x; s.raw_y = y;
    if (s.samples == 0u) {
        s.x_deg = x; s.y_deg = y;
        s.vx = s.vy = s.speed_deg_s = 0.0f;
        s.ox = s.oy = s.out_speed_deg_s = 0.0f;
        s.cutoff_hz = s.cfg.min_cutoff_hz;
        s.alpha = 1.0f;
        s.samples = 1u; s.settled = 1u; s.saccade = 0u;
        s.t_us = t_us;
        *f = s;
        return FOV_OK;
    }
    te = (float)fov__us32(t_us - s.t_us) * 1e-6f;
    s.t_us = t_us;
    s.te_s = te;
    s.samples = s.samples < 0xFFFFFFFFu ? s.samples + 1u : s.samples;
    /* the window speed: the newest sample against the newest one at least window_ms older
       (or the oldest kept) */
    k = s.head;
    for (i = 1u; i < s.count; ++i) {
        k = (s.head + FOV_GAZE_HISTORY - i) % FOV_GAZE_HISTORY;
        if ((float)fov__us32(t_us - s.hist_t[k]) >= s.cfg.window_ms * 1000.0f) break;
    }
    wx = x - s.hist_x[k]; wy = y - s.hist_y[k];
    wt = (float)fov__us32(t_us - s.hist_t[k]) * 1e-6f;
    spd = wt > 0.0f ? FOV__SQRT(wx * wx + wy * wy) / wt : 0.0f;
    if (!s.saccade && spd > s.cfg.saccade_deg_s) {
        s.saccade = 1u;
        s.saccades++;
    } else if (s.saccade && spd < 0.5f * s.cfg.saccade_deg_s) {
        /* landing: restart at the landing sample */
        s.saccade = 0u;
        s.x_deg = x; s.y_deg = y;
        s.vx = s.vy = s.speed_deg_s = 0.0f;
        s.ox = s.oy = s.out_speed_deg_s = 0.0f;
        s.cutoff_hz = s.cfg.min_cutoff_hz;
        s.alpha = 1.0f;
        s.settled = 1u;
        *f = s;
        return FOV_OK;
    }
    if (s.saccade) {
        s.x_deg = x; s.y_deg = y;
        s.vx = wt > 0.0f ? wx / wt : 0.0f; s.vy = wt > 0.0f ? wy / wt : 0.0f;
        s.speed_deg_s = s.out_speed_deg_s = spd;
        s.ox = s.vx; s.oy = s.vy;
        s.alpha = 1.0f;
        *f = s;
        return FOV_OK;
    }
    /* One Euro */
    ad = fov__gaze_alpha(s.cfg.d_cutoff_hz, te);
    ex = x - s.x_deg; ey = y - s.y_deg;
    dvx = ex / te; dvy = ey / te;
    s.vx += ad * (dvx - s.vx);
    s.vy += ad * (dvy - s.vy);
    sp = FOV__SQRT(s.vx * s.vx + s.vy * s.vy);
    s.speed_deg_s = sp;
    s.cutoff_hz = s.cfg.min_cutoff_hz + s.cfg.beta * sp;
    a = fov__gaze_alpha(s.cutoff_hz, te);
    if (a < 1.0f / (float)(s.settled + 1u)) a = 1.0f / (float)(s.settled + 1u);
    s.alpha = a;
    s.x_deg += a * ex;
    s.y_deg += a * ey;
    s.ox += ad * (a * ex / te - s.ox);
    s.oy += ad * (a * ey / te - s.oy);
    s.out_speed_deg_s = FOV__SQRT(s.ox * s.ox + s.oy * s.oy);
    s.settled = s.settled < 0xFFFFFFFFu ? s.settled + 1u : s.settled;
    /* the raw noise: a running mean square of the innovation over about a second (a
       running mean for the first samples) */
    {
        float an = fov__gaze_alpha(0.16f, te), e2 = ex * ex + ey * ey, n2;
        if (an < 1.0f / (float)s.samples) an = 1.0f / (float)s.samples;
        n2 = s.noise_deg * s.noise_deg;
        n2 += an * (e2 - n2);
        s.noise_deg = FOV__SQRT(n2);
    }
    if (!fov__finite(s.x_deg) || !fov__finite(s.y_deg) || !fov__finite(s.vx) ||
        !fov__finite(s.vy) || !fov__finite(s.noise_deg)) {
        *bad = FOV__MSG("gaze_filter_push: the state overflows (time step too small)");
        return FOV_ERR_INVALID_ARG;
    }
    *f = s;
    return FOV_OK;
}

/* The speed of the filtered gaze beyond what the tracker's noise alone gives it: a still eye
   seen through noise of RMS n (2-D) moves the output by a n per sample, whose velocity,
   smoothed with weight ad, has an RMS of a n / te sqrt(ad / (2 - ad)); twice that is
   subtracted (a still eye's output speed exceeds it in 2 % of samples). */
FOV__PRIV float fov__gaze_motion(const fov_gaze_filter *f)
{
    float te = f->te_s > 0.0f ? f->te_s : 1.0f, ad = fov__gaze_alpha(f->cfg.d_cutoff_hz, te);
    float sn = fov__clampf(f->alpha, 0.0f, 1.0f) * f->noise_deg / te * FOV__SQRT(ad / (2.0f - ad));
    float v = f->out_speed_deg_s - 2.0f * sn;
    return v > 0.0f ? v : 0.0f;
}

/* The margin in degrees (see fov_gaze_filter_config); speed, cutoff and alpha from the
   filter. Bad input: the cap (the safe answer) and FOV_ERR_*. */
FOV__PRIV fov_result fov__gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                      float latency_ms, float *out)
{
    float cap, m, jit, a, fc;
    if (!f || !out) return FOV_ERR_NULL;
    cap = f->cfg.max_margin_deg > 0.0f && f->cfg.max_margin_deg <= 90.0f ? f->cfg.max_margin_deg
                                                                          : 15.0f;
    *out = cap;
    if (!fov__finite(accuracy_deg) || !fov__finite(latency_ms)) return FOV_ERR_NOT_FINITE;
    if (accuracy_deg < 0.0f || latency_ms < 0.0f || latency_ms > 1e6f || accuracy_deg > 90.0f)
        return FOV_ERR_INVALID_ARG;
    if (f->samples == 0u) return FOV_OK;
    if (f->saccade) {
        /* the output is the raw sample; the eye sees next to nothing while it jumps */
        m = accuracy_deg + 2.5f * f->noise_deg;
        *out = m < cap ? m : cap;
        return FOV_OK;
    }
    a = fov__clampf(f->alpha, 0.0f, 1.0f);
    fc = f->cutoff_hz > 0.0f ? f->cutoff_hz : 1e-3f;
    jit = f->noise_deg * FOV__SQRT(a / (2.0f - a));
    m = accuracy_deg + 2.5f * jit +
        fov__gaze_motion(f) * (latency_ms * 1e-3f + 1.0f / (2.0f * FOV__PI * fc));
    if (!(m < cap)) m = cap; /* NaN too */
    *out = m;
    return FOV_OK;
}

/* The least-squares line through ring samples off .. off + n - 1 counted back from the newest
   (t relative to the newest sample, seconds): the means, S, the velocity and the sum of both
   axes' squared residuals. */
/* The least residual variance the fit assumes, deg^2 per axis (1e-4 degrees RMS: float
   rounding of noiseless input is not a change of motion) */
#define FOV__GAZE_S2_MIN 1e-8f
typedef struct fov__gaze_line {
    float tm, xm, ym, sxx, vx, vy, ssr;
} fov__gaze_line;
FOV__PRIV void fov__gaze_fit(const fov_gaze_filter *f, uint32_t off, uint32_t n, fov__gaze_line *l)
{
    uint64_t t0 = f->hist_t[f->head % FOV_GAZE_HISTORY];
    float sxy = 0.0f, syy = 0.0f;
    uint32_t i, k;
    l->tm = l->xm = l->ym = l->sxx = l->ssr = 0.0f;
    for (i = off; i < off + n; ++i) {
        k = (f->head + FOV_GAZE_HISTORY - i) % FOV_GAZE_HISTORY;
        l->tm -= (float)fov__us32(t0 - f->hist_t[k]) * 1e-6f;
        l->xm += f->hist_x[k]; l->ym += f->hist_y[k];
    }
    l->tm /= (float)n; l->xm /= (float)n; l->ym /= (float)n;
    for (i = off; i < off + n; ++i) {
        float dt;
        k = (f->head + FOV_GAZE_HISTORY - i) % FOV_GAZE_HISTORY;
        dt = -(float)fov__us32(t0 - f->hist_t[k]) * 1e-6f - l->tm;
        l->sxx += dt * dt;
        sxy += dt * (f->hist_x[k] - l->xm);
        syy += dt * (f->hist_y[k] - l->ym);
    }
    l->vx = l->sxx > 0.0f ? sxy / l->sxx : 0.0f;
    l->vy = l->sxx > 0.0f ? syy / l->sxx : 0.0f;
    for (i = off; i < off + n; ++i) {
        float dt, ex, ey;
        k = (f->head + FOV_GAZE_HISTORY - i) % FOV_GAZE_HISTORY;
        dt = -(float)fov__us32(t0 - f->hist_t[k]) * 1e-6f - l->tm;
        ex = f->hist_x[k] - l->xm - l->vx * dt;
        ey = f->hist_y[k] - l->ym - l->vy * dt;
        l->ssr += ex * ex + ey * ey;
    }
}

/* Latency compensation (see fov_gaze_filter_config): a line fitted to the raw samples since
   the last reset or landing, shortened while its newest samples leave it, extrapolated by the
   latency when its speed is significant. Bad input: FOV_ERR_* with *out the filtered gaze
   and the cap (the safe answer). */
FOV__PRIV fov_result fov__gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                       float latency_ms, fov_gaze_prediction *out)
{
    fov_gaze_prediction p;
    fov__gaze_line l;
    fov_result r;
    float m, win, s2, se2, v2, h, cap;
    uint32_t k, n, avail;
    uint64_t t0;
    if (!f || !out) return FOV_ERR_NULL;
    FOV_MEMSET(&p, 0, sizeof p);
    p.x_deg = f->x_deg; p.y_deg = f->y_deg;
    p.mode = f->saccade ? FOV_GAZE_SACCADE : FOV_GAZE_SETTLING;
    r = fov__gaze_margin(f, accuracy_deg, latency_ms, &m);
    p.margin_deg = m;
    *out = p;
    if (r != FOV_OK || f->samples == 0u || f->saccade) return r;
    cap = f->cfg.max_margin_deg > 0.0f && f->cfg.max_margin_deg <= 90.0f ? f->cfg.max_margin_deg
                                                                          : 15.0f;
    win = f->cfg.predict_ms >= FOV_GAZE_FIT_MIN_MS && f->cfg.predict_ms <= 2000.0f
              ? f->cfg.predict_ms * 1000.0f : 200000.0f;
    avail = f->count < f->settled ? f->count : f->settled;
    if (avail > FOV_GAZE_HISTORY) avail = FOV_GAZE_HISTORY;
    t0 = f->hist_t[f->head % FOV_GAZE_HISTORY];
    /* the samples in the window */
    for (n = 0u; n < avail; ++n) {
        k = (f->head + FOV_GAZE_HISTORY - n) % FOV_GAZE_HISTORY;
        if (f->hist_t[k] > t0 || (float)fov__us32(t0 - f->hist_t[k]) > win) break;
    }
    for (;;) {
        fov__gaze_line a, b;
        float pooled, dof, q, ex, ey, vq;
        uint32_t m4;
        if (n < FOV_GAZE_FIT_MIN) return FOV_OK;
        k = (f->head + FOV_GAZE_HISTORY - (n - 1u)) % FOV_GAZE_HISTORY;
        if ((float)fov__us32(t0 - f->hist_t[k]) < FOV_GAZE_FIT_MIN_MS * 1000.0f) return FOV_OK;
        fov__gaze_fit(f, 0u, n, &l);
        if (!(l.sxx > 0.0f)) return FOV_OK;
        /* a change of motion within the window keeps the newer half: (1) the newest quarter
           off the line through the older samples (their mean, against its standard error
           from the older samples' residual, beyond the 1 % of a 2-D Gaussian: the eye stopped
           or started); (2) Chow's test, one line against one line per half, F(4, 2 (n - 4))
           beyond about its 1 % point */
        m4 = n / 4u > 2u ? n / 4u : 2u;
        fov__gaze_fit(f, m4, n - m4, &b);
        fov__gaze_fit(f, 0u, m4, &a);
        q = a.tm - b.tm;
        ex = a.xm - b.xm - b.vx * q;
        ey = a.ym - b.ym - b.vy * q;
        vq = b.ssr / (2.0f * (float)(n - m4 - 2u));
        vq = (vq > FOV__GAZE_S2_MIN ? vq : FOV__GAZE_S2_MIN) *
             (1.0f / (float)m4 + 1.0f / (float)(n - m4) + (b.sxx > 0.0f ? q * q / b.sxx : 0.0f));
        if (ex * ex + ey * ey > 9.21f * vq) { n /= 2u; continue; }
        fov__gaze_fit(f, 0u, n / 2u, &a);
        fov__gaze_fit(f, n / 2u, n - n / 2u, &b);
        dof = 2.0f * (float)(n - 4u);
        pooled = (a.ssr + b.ssr) / dof;
        if (pooled < FOV__GAZE_S2_MIN) pooled = FOV__GAZE_S2_MIN;
        if (!(l.ssr - a.ssr - b.ssr > (3.32f + 30.0f / dof) * 4.0f * pooled)) break;
        n /= 2u;
    }
    s2 = l.ssr / (2.0f * (float)(n - 2u));
    if (s2 < FOV__GAZE_S2_MIN) s2 = FOV__GAZE_S2_MIN;
    se2 = s2 / l.sxx; /* the velocity's variance per axis */
    v2 = l.vx * l.vx + l.vy * l.vy;
    h = latency_ms * 1e-3f - l.tm;
    p.vx = l.vx; p.vy = l.vy; p.n = n;
    if (v2 > 9.21f * se2 && v2 < f->cfg.saccade_deg_s * f->cfg.saccade_deg_s) {
        p.mode = FOV_GAZE_PURSUIT;
        p.horizon_s = h;
        p.x_deg = l.xm + l.vx * h;
        p.y_deg = l.ym + l.vy * h;
        m = accuracy_deg + 2.5f * FOV__SQRT(2.0f * s2 * (1.0f / (float)n + h * h / l.sxx));
    } else {
        float ve = FOV__SQRT(v2) - 2.0f * FOV__SQRT(2.0f * se2);
        p.mode = FOV_GAZE_FIXATION;
        p.x_deg = l.xm; p.y_deg = l.ym;
        m = accuracy_deg + 2.5f * FOV__SQRT(2.0f * s2 / (float)n) + (ve > 0.0f ? ve * h : 0.0f);
    }
    if (!fov__finite(p.x_deg) || !fov__finite(p.y_deg) || !(fov__absf(p.x_deg) < 90.0f) ||
        !(fov__absf(p.y_deg) < 90.0f)) {
        /* an extrapolation off the gaze angles' range: the filtered gaze and the cap */
        p.x_deg = f->x_deg; p.y_deg = f->y_deg;
        p.mode = FOV_GAZE_SETTLING; p.horizon_s = 0.0f;
        p.vx = p.vy = 0.0f; p.n = 0u;
        m = cap;
    }
    p.margin_deg = m < cap ? m : cap; /* NaN: the cap */
    *out = p;
    return FOV_OK;
}

/* Pixels to gaze degrees and back (see fov_gaze_filter_config); 0 when not finite. */
FOV__PRIV int fov__gaze_to_deg(const fov_ecc_model *m, float x, float y, float d[2])
{
    float dx = x - m->cx, dy = y - m->cy;
    if (!fov__finite(dx) || !fov__finite(dy) || !(m->f_px > 0.0f)) return 0;
    d[0] = FOV__ATAN2(dx, m->f_px) / FOV__DEG;
    d[1] = FOV__ATAN2(dy, FOV__SQRT(dx * dx + m->f_px * m->f_px)) / FOV__DEG;
    /* a pixel far enough out rounds to exactly 90 degrees, which fov__gaze_from_deg (and the
       filter) cannot take: the open interval (-90, 90) only */
    return fov__finite(d[0]) && fov__finite(d[1]) && fov__absf(d[0]) < 90.0f &&
           fov__absf(d[1]) < 90.0f;
}
FOV__PRIV int fov__gaze_from_deg(const fov_ecc_model *m, const float d[2], float *x, float *y)
{
    float h = d[0] * FOV__DEG, v = d[1] * FOV__DEG, ch;
    if (!(fov__absf(d[0]) < 90.0f && fov__absf(d[1]) < 90.0f) || !(m->f_px > 0.0f)) return 0;
    ch = FOV__COS(h);
    *x = m->cx + m->f_px * FOV__TAN(h);
    *y = m->cy + m->f_px * FOV__TAN(v) / ch;
    return fov__finite(*x) && fov__finite(*y);
}
/* A pixel sample: converted, pushed into a copy of the filter and the filtered gaze turned
   back into pixels; the filter (and *out) change only when all three succeed. */
FOV__PRIV fov_result fov__gaze_push_px(fov_gaze_filter *f, const fov_ecc_model *m, uint64_t t_us,
                                       fov_gaze raw, fov_gaze *out, const char **bad)
{
    fov_gaze_filter s;
    fov_gaze g;
    float d[2];
    fov_result r;
    *bad = FOV__MSG("");
    if (!fov__finite(raw.x) || !fov__finite(raw.y)) {
        *bad = FOV__MSG("gaze_filter_push_px: sample NaN or infinite (skip the tracker's "
                        "invalid samples)");
        return FOV_ERR_NOT_FINITE;
    }
    if (!fov__gaze_to_deg(m, raw.x, raw.y, d)) {
        *bad = FOV__MSG("gaze_filter_push_px: sample at or beyond 90 degrees off the axis, or "
                        "the eccentricity model is not initialised");
        return FOV_ERR_INVALID_ARG;
    }
    s = *f;
    r = fov__gaze_push(&s, t_us, d[0], d[1], bad);
    if (r != FOV_OK) return r;
    g.x = g.y = 0.0f;
    if (out) {
        d[0] = s.x_deg; d[1] = s.y_deg;
        if (!fov__gaze_from_deg(m, d, &g.x, &g.y)) {
            *bad = FOV__MSG("gaze_filter_push_px: the filtered gaze has no pixel (beyond 90 "
                            "degrees)");
            return FOV_ERR_INVALID_ARG;
        }
    }
    *f = s;
    if (out) *out = g;
    return FOV_OK;
}

/* An off-axis frustum's tangents against the image: (l + r) / (b + t) = w / h within 1e-3
   relative (square pixels: the headers use one scale for both axes); 0 when not. */
FOV__PRIV int fov__tan_aspect_ok(float tl, float tr, float tb, float tt, uint32_t w, uint32_t h)
{
    float a = (tl + tr) * (float)h, b = (tb + tt) * (float)w;
    return fov__absf(a - b) <= 1e-3f * b;
}

/* The display of a camera's own frustum (fov_display: f = H / (t + b), the axis at the image
   point of tangent 0); the camera's tangents, or the symmetric ones of fov_y_deg (0: 60).
   FOV_ERR_* for bad fields; FOV_ERR_UNSUPPORTED for tangents whose ratio is not the image's
   aspect (fov__tan_aspect_ok). */
FOV__PRIV fov_result fov__camera_display(const fov_camera *cam, fov_display *d)
{
    float tl, tr, tb, tt, f, fy;
    if (!cam || !d) return FOV_ERR_NULL;
    if (cam->width == 0 || cam->height == 0) return FOV_ERR_INVALID_ARG;
    if (!fov__finite(cam->fov_y_deg) || !fov__finite(cam->tan_left) ||
        !fov__finite(cam->tan_right) || !fov__finite(cam->tan_bottom) ||
        !fov__finite(cam->tan_top))
        return FOV_ERR_NOT_FINITE;
    FOV_MEMSET(d, 0, sizeof *d);
    if (fov__is0(cam->tan_left) && fov__is0(cam->tan_right) && fov__is0(cam->tan_bottom) &&
        fov__is0(cam->tan_top)) {
        fy = fov__is0(cam->fov_y_deg) ? 60.0f : cam->fov_y_deg;
        if (!(fy > 0.0f && fy < 180.0f)) return FOV_ERR_INVALID_ARG;
        d->fov_y_deg = fy;
        return FOV_OK;
    }
    tl = cam->tan_left; tr = cam->tan_right; tb = cam->tan_bottom; tt = cam->tan_top;
    if (!(tl + tr > 1e-6f) || !(tb + tt > 1e-6f) || tl > 1e6f || tr > 1e6f || tb > 1e6f ||
        tt > 1e6f)
        return FOV_ERR_INVALID_ARG;
    if (!fov__tan_aspect_ok(tl, tr, tb, tt, cam->width, cam->height)) return FOV_ERR_UNSUPPORTED;
    f = (float)cam->height / (tt + tb);
    d->fov_y_deg = 2.0f * FOV__ATAN2(0.5f * (float)cam->height, f) / FOV__DEG;
    d->axis_dx = tl * f - 0.5f * (float)cam->width;
    d->axis_dy = tt * f - 0.5f * (float)cam->height;
    return FOV_OK;
}
#endif /* FOV__SHARED_IMPL_INCLUDED */
/* ==== FOV_SHARED_END impl ==================================================================== */

/* ==== FOV_SHARED_BEGIN license ============================================================== */
/*
------------------------------------------------------------------------------
This software is available under 2 licenses -- choose whichever you prefer.
------------------------------------------------------------------------------
ALTERNATIVE A - MIT License
Copyright (c) 2026 the fov authors
Permission is hereby granted, free of charge, to any person obtaining a copy of
this software and associated documentation files (the "Software"), to deal in
the Software without restriction, including without limitation the rights to
use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies
of the Software, and to permit persons to whom the Software is furnished to do
so, subject to the following conditions:
The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
------------------------------------------------------------------------------
ALTERNATIVE B - Public Domain (www.unlicense.org)
This is free and unencumbered software released into the public domain.
Anyone is free to copy, modify, publish, use, compile, sell, or distribute this
software, either in source code form or as a compiled binary, for any purpose,
commercial or non-commercial, and by any means.
In jurisdictions that recognize copyright laws, the author or authors of this
software dedicate any and all copyright interest in the software to the public
domain. We make this dedication for the benefit of the public at large and to
the detriment of our heirs and successors. We intend this dedication to be an
overt act of relinquishment in perpetuity of all present and future rights to
this software under copyright law.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER IN AN
ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN CONNECTION
WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
------------------------------------------------------------------------------
*/
/* ==== FOV_SHARED_END license ================================================================ */
