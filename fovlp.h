/* fovlp.h - v0.7.1 - kernel log-polar foveation with a gaze disc and temporal anti-aliasing
                      - MIT or public domain (see end of file)

   Do this:
      #define FOVLP_IMPLEMENTATION   (or #define FOV_IMPL for all fov headers)
   before you include this file in *one* C or C++ file to create the implementation.

QUICK START (the library never renders: you shade the positions it hands out)
      #define FOVLP_IMPLEMENTATION
      #include "fovlp.h"
      #include <stdlib.h>                                      // malloc

      fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, 1920, 1080);
      size_t bytes;  fovlp_memory_size(&cfg, &bytes);         // a few KiB of tables
      fovlp_ctx ctx; fovlp_init(&ctx, &cfg, malloc(bytes), bytes);
      fovlp_geometry g = ctx.geo;                              // g.samples = sample slots
      float *rgb = (float *)malloc(g.samples * 3 * sizeof(float));   // linear RGB per slot
      float *img = (float *)malloc(1920 * 1080 * 3 * sizeof(float)); // linear RGB per pixel
      uint8_t *rgba = (uint8_t *)malloc(1920 * 1080 * 4);           // what you display
      for (;;) {                                               // every frame
          fov_gaze gaze = { eye_x, eye_y };
          fovlp_camera lc;  fovlp_camera_from(&cam, &lc);       // cam: your fov_camera
          fovlp_begin_frame(&ctx, gaze, &lc);                  // (NULL: a still camera)
          fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), my_shade, my_user, rgb, NULL, NULL);
          fovlp_reconstruct_rows(&ctx, rgb, NULL, 0, 1080, img, 0, NULL);
          fovlp_srgb8_rows(&ctx, img, 0, 0, 1080, rgba, 0, 4);  // sRGB bytes, alpha 255
      }
   my_shade(x, y, rgb, depth, user) writes the linear RGB colour of the screen point (x, y)
   (continuous pixel coordinates, pixel centres at +0.5) from any renderer; depth is NULL
   unless you pass a depth buffer (TAA). Instead of the callback you can ask for the positions
   as an array (fovlp_samples) and write each sample's colour to rgb[3 * sample.slot]. Split
   the sample rows and the screen rows over threads as you like. fovlp_srgb8_rows gives 3
   (RGB, e.g. a PPM) or 4 bytes per pixel; keep img when you need float (HDR) output.
   With TAA (cfg.taa.enable = 1 before fovlp_init) pass a camera to fovlp_begin_frame, shade
   and reconstruct with depth, and resolve against a history that you swap every frame:
      float *sdep = (float *)malloc(g.samples * sizeof(float));      // depth per slot
      float *dep = (float *)malloc(1920 * 1080 * sizeof(float));      // depth per pixel
      // and two of each, screen-size: hist[2] (3 floats), hdep[2] (1 float), age[2] (1 byte)
          fovlp_shade_rows(&ctx, 0, fovlp_sample_rows(&ctx), my_shade, my_user, rgb, sdep, NULL);
          fovlp_reconstruct_rows(&ctx, rgb, sdep, 0, 1080, img, 0, dep);
          fovlp_taa_io io;  fovlp_taa_io_init(&io);
          io.cur_rgb = img;        io.cur_depth = dep;
          io.prev_rgb = hist[p];   io.prev_depth = hdep[p];   io.prev_age = age[p];
          io.out_rgb = hist[1-p];  io.out_depth = hdep[1-p];  io.out_age = age[1-p];
          fovlp_taa_rows(&ctx, &io, 0, 1080, NULL);            // the first frame needs no prev_*
          fovlp_srgb8_rows(&ctx, hist[1-p], 0, 0, 1080, rgba, 0, 4);   p = 1 - p;
   The depths are optional while the camera stands still (see fovlp_taa_io).
   examples/lp_sdf.c renders fovsdf.h's scenes through this library, with TAA.
   No eye tracker: fixed foveation, the gaze at the display's axis point and a larger disc
      fovlp_gaze_fixed(&cfg.display, 1920, 1080, &gaze);                 // the screen centre
      fovlp_config_gaze_margin(&base, FOV_GAZE_FIXED_MARGIN_DEG, &cfg);  // disc + 15 deg
   With one: filter its samples and grow the disc by the latency margin (GAZE INPUT): init
   with the largest margin, then per frame fovlp_set_gaze_margin (keeps the TAA history).
   A head-mounted display's eye (off-axis): fovlp_camera_from keeps its tangents for the
   reprojection; fovlp_camera_display(&cam, &cfg.display) for the eccentricity.

THE PIPELINE (in the order the data flows; Andersson & Hansson 2020, "Performance
Optimizations for Foveated Real-Time Raytracing", LU-CS-EX 2020-64, = "the thesis"; it builds
on Meng et al. 2018, "Kernel Foveated Rendering")
   1. Buffer size (thesis eq. 3.6): h = round(sqrt(W H / lp_aspect) / sigma),
      w = round(h lp_aspect); so w h = W H / sigma^2 log-polar (LP) texels before culling.
      lp_aspect 0 picks the aspect that makes the radial and angular sample spacings equal at
      match_deg eccentricity (thesis Sec. 5.2.1 tuning, closed form: spacing ratio
      radial/angular = L h t^(1/alpha - 1) / (2 pi alpha w_C), t = (log r / L)^alpha).
   2. Normaliser (eq. 3.10): L = log(screen diagonal) (thesis; the default), or
      L = log(distance from the gaze to the farthest corner) (Meng et al.), FOVLP_NORM_CORNER.
      Both in pixels; L >= log 2 (tiny screens).
   3. Gaze disc (composite foveation, eqs. 3.3-3.5): r_G = f tan(a_G) pixels with f the eye
      distance in pixels of the eccentricity model (a_G in radians), G = K(log r_G / L),
      u_G = w G / (1 - G), w_C = w + u_G. Pixels whose centre lies within r_G of the gaze are
      shaded 1:1 (one sample per pixel); the LP buffer covers r >= r_G.
   4. Kernel (eq. 3.2): K(x) = x^alpha. Screen -> LP (eq. 3.8/3.9):
         u = K(log(max(r, 1)) / L) w_C - u_G,   v = atan2(dy, dx) h / (2 pi), in [0, h)
      LP -> screen (eq. 3.7): rho = exp(L Kinv((u + u_G) / w_C)), x = gx + rho cos(2 pi v / h),
      y = gy + rho sin(2 pi v / h). K sits in the screen -> LP direction, as the thesis's ray
      counts require (Sec. 3.3.2, Table 5.3): alpha > 1 moves samples to the periphery.
   5. Culling: only the LP columns u < u_max = K(log r_max / L) w_C - u_G (r_max: the farthest
      corner from the gaze) are dispatched; an LP texel whose sample falls off-screen is never
      shaded; nor is a disc pixel outside the circle.
   6. Sampling: LP texel (u, v) is shaded at LP coordinate (u + ou, v + ov), disc pixel (i, j)
      at (i + ou, j + ov); (ou, ov) = (0.5, 0.5), or with TAA the scaled Halton (2, 3) point
      of the frame (eq. 3.11). One more sample sits on the gaze point itself (the centre).
   7. Reconstruction, per screen pixel (fovlp__pixel): the disc sample inside the disc;
      elsewhere bilinear interpolation of the LP samples at the pixel's (u, v) (eq. 3.8; the
      angle from a polynomial atan, fovlp__to_lp_fast, within 2e-6 h of atan2; the on-screen
      test of the four taps skipped when their ring lies inside the screen), at
      the positions actually shaded, with the angle wrapping (v = h is v = 0: no seam), taps
      whose sample was not shaded left out (weights renormalised; none left: the nearest
      shaded sample inwards). With cfg.recon = FOVLP_RECON_CUBIC (ours; what
      fovlp_config_acuity picks): Catmull-Rom over the 4 x 4 nearest LP samples instead,
      clamped per channel to the range of the 2 x 2 nearest (no ringing at edges), where all
      16 are shaded and inside the dispatched columns (else bilinear). Bilinear interpolation
      of samples spaced near the eye's MAR flattens detail the eye still sees (a sinusoid of
      8 texels: RMS error 0.020 bilinear, 0.003 cubic; tests/test_fovlp_acuity.c); averaged
      over TAA's jitter it acts as a tent filter as wide as two sample gaps, Catmull-Rom as
      a much flatter pass band. Between the disc edge and the innermost LP ring: linear along
      the radius from the nearest disc pixel to the ring (no step at the disc edge). Inside
      the innermost ring without a disc: a blend towards the centre sample (no singularity
      at the gaze). Optional 3x3 Gaussian blend in the periphery (eq. 3.13,
      fovlp_blend_rows).
   8. TAA in screen space (thesis Sec. 3.4): reprojection with the previous and current camera
      (the fov_camera you render with, through fovlp_camera_from) and the shaded depth,
      depth rejection, history blend 1/age with the age capped at 20 (eq. 3.12), optional
      neighbourhood clamp or variance clip in YCoCg (always on while the camera moves,
      ours), history reset on a gaze jump.
   9. Output: every image is linear RGB in floats (the colour space your shading writes);
      fovlp_srgb8_rows encodes it to 8-bit sRGB (the exact IEC 61966-2-1 curve, correctly
      rounded, the same bytes in every build) for a display texture or an image file.

CHOICES WHERE THE THESIS IS OPEN OR WRONG (each is tested in tests/test_fovlp.c)
   - atan vs atan2: eq. 3.9's arctan(y'/x') + [y' < 0] 2 pi is only right as atan2; we use
     atan2 wrapped to [0, 2 pi).
   - log(r_G + 1) vs log r_G: eq. 3.4 writes log(r_G + 1) but eq. 3.8 uses log r, so the LP
     buffer would start 1 px outside the disc. Default FOVLP_EDGE_LOG_R: log r_G in both
     places (u = 0 lands exactly on r_G). FOVLP_EDGE_THESIS keeps the thesis's formula.
   - The centre: log r < 0 inside 1 px; we clamp r >= 1 px in the mapping, and reconstruct
     the inside of the innermost sample ring by blending towards a sample at the gaze point.
   - The angle seam: the thesis's clamped bilinear sampler has a seam along the +x ray; we
     wrap v modulo h.
   - Texel positions: the thesis reconstructs as if every sample sat at its texel centre even
     when jittered (the image shifts with the jitter; its "twist" fix only corrects the
     mean). We interpolate at the positions actually shaded, so every frame is registered
     and the jitter only adds information. The eq. 3.11 scaling is kept so the offsets
     average to the texel centre.
   - Halton start index: 1 (Karis 2014; index 0 gives the point (0, 0) and a scaled y of
     1.04 texels). Scales with 16 phases: 1.062241 (x), 1.08 (y).
   - a_G in radians (the only reading that makes the thesis's presets consistent).
   - The viewing distance, when the display gives no geometry: the thesis's
     d = diagonal / tan 60 degrees (eq. 5.1 with max_view_angle 60 degrees).
   - Unused LP width (how much wider the buffer is): the thesis does not say; the buffer is
     w x h as eq. 3.6 gives, and the columns beyond u_max are not dispatched.
   - Gaussian blend: on screen pixels of the reconstruction; t rises linearly from 0 at
     blend_start (default diag / 6, the thesis) to 1 at blend_end (default diag / 2, ours).
   - TAA age order: age = min(age + 1, max_age) first, then out = lerp(history, current,
     1 / age); a rejection sets age = 1 before the blend (so the output is the current
     frame). Depth rejection: |d_prev - d_expected| > depth_tol * max(both) (default 2 %,
     the thesis gives no threshold). A still camera rejects nothing (thesis). Beyond
     periphery * diagonal from the gaze a moving camera's history that fails the depth test
     is kept (the thesis), blended with an age of at most 2 (history weight <= 1/2, ours),
     and the stored age is reset to 1 (the thesis's "update the age variable to 1").
   - Moving camera (ours): the thesis's depth test alone lets history through that does not
     belong to the pixel (the kept peripheral history, and bilinear history fetched across a
     depth edge), which ghosts: tests/test_fovlp_taa.c measures |out - truth| beyond diag/3
     at about 2x that of no TAA, and bench-lp's moving sequence ring RMSE up to 1.65x that
     of no TAA on the columns scene (1.02x with the clip; bench/results/lp_moving.csv). So
     while the camera moves (history reprojected) and taa.clamp is NONE, the history is
     variance-clipped in YCoCg (box mean +- clip_gamma standard deviations of the current
     3x3 neighbourhood); with a still camera nothing is clamped, since the history is
     registered exactly and clamping would undo the convergence of sub-pixel detail (thin
     wires: fovea 29.6 dB instead of 38.8 dB against 256 spp with clipping always on;
     bench_lp --fovea-study).
     taa.thesis_moving = 1 restores the thesis's behaviour.
   - A gaze jump larger than reset_deg (default 2 degrees) resets the history.
   - Jitter is off while the camera moves (thesis), unless taa.jitter_moving.
   - Off-screen gaze: clamped to the screen rectangle (a warning through the logger).

ACUITY-DRIVEN CONFIGURATION (fovlp_config_acuity: the parameters from the eye and the display)
      fovlp_config cfg = fovlp_config_default();
      cfg.width = 1920;  cfg.height = 1080;
      cfg.display.pixel_pitch_mm = 0.3113f;  cfg.display.distance_mm = 600.0f;  // 27", 60 cm
      fov_eye eye = { 0.0f, 0.0f, 0.5f };           // the defaults (quality 0.5, see fov_eye)
      fovlp_config_acuity(&cfg, NULL, &eye);        // sigma, alpha, gaze disc, lp_aspect
      // then fovlp_memory_size / fovlp_init as above (cfg.taa, cfg.blend are yours)
   It fills sigma, alpha, gaze_angle (no_disc 0), lp_aspect, norm (DIAGONAL), edge (LOG_R)
   and recon (CUBIC: Catmull-Rom over the LP samples, see step 7 of THE PIPELINE)
   and nothing else; cam (a fovlp_camera, may be NULL) gives the field of view only when
   cfg.display is all zero, and is then written to cfg.cam_fov_y_deg so that fovlp_init uses
   the same eccentricity model (with neither, the thesis's viewing distance). The fixed
   presets (fovlp_config_preset, Table 5.1 of the thesis) are unchanged.
   The rule (the shared fov_eye model, Guenter et al. 2012): with the gaze on the display's
   axis, a point r pixels away lies at e(r) = atan(r / f) (f the eye distance in pixels; the
   gaze disc uses the same r_G = f tan a_G), where the eye allows a sample spacing of
      s(r) = quality MAR(e(r)) ppd pixels,   MAR(e) = mar0 + slope e,   ppd = f pi / 180
   (fov_eye_plan's ppd: the coarsest on a flat display, so a pixel subtends at most 1 / ppd
   degrees anywhere). For every r from the disc edge r_G to R = the screen diagonal (the
   farthest corner from any gaze on the screen) the gap between neighbouring LP samples stays
   within s(r): radially r(u + 1) - r(u) <= s(r(u)) for every u >= 0 of the sample radii
   r(u) = exp(L ((u + u_G) / w_C)^(1 / alpha)) that fovlp_begin_frame tabulates (at any
   jitter offset), and angularly 2 pi r / h <= s(r). Inside the disc every pixel is shaded
   1:1: the disc covers at least e_full of fov_eye_plan (where the display's pixels are
   coarser than the eye, so no reduction is allowed), and more when that costs fewer samples.
   Among the disc radii and kernel exponents alpha in [1, 8] the call picks the pair with
   the fewest samples a gaze at the screen centre shades (disc pixels plus on-screen LP
   texels; the buffer still meets the rule for any gaze): h follows from the arcs at R (the
   angular rule binds at the far corner since r / s(r) grows with r), w_C from the radial
   rule, and alpha > 1 lets the radial spacing grow faster than r near the disc, as the
   eye's does (s(r) has the offset mar0). Then it builds the geometry fovlp_init will
   derive (fovlp_geometry_get's formulas), checks every gap on it (4 offsets per column) and
   grows the buffer until all meet the rule. Figures (quality 1, not the default 0.5; saving =
   screen pixels / samples shaded incl. the disc, gaze at the centre; tests/test_fovlp_acuity.c
   prints them):
      640x360, 45 degree camera  7.6 ppd  LP 142 x 460, disc 63 px   5.1x
      640x360, 65 degree camera  4.9 ppd  LP 152 x 611, disc 83 px   3.8x
      1920x1080, 27" at 60 cm   33.6 ppd  LP 180 x 378, disc 42 px  40.6x
      1600x1600 over 100 deg    11.7 ppd  LP 244 x 744, disc 98 px  18.5x
   Limits of the rule: it is exact for a gaze on the display's axis; for other gazes the
   angle between the eye's rays through neighbouring samples, against quality MAR of the true
   eccentricity, comes within 1.08 (640x360 at 65 degrees, next to the disc; 1.02 at 45
   degrees, 1.01 at the 100 degree display, 0.99 at the monitor). A display coarser than the
   eye nearly everywhere (the disc would reach beyond half the diagonal) gives
   FOV_ERR_UNSUPPORTED: trace every pixel instead.
   The rule is on the sample spacing; what the reconstruction makes of the samples is
   measured by bench/bench_perceptual.c (examples/fovmetrics.h: both images filtered to the
   eye, a Gaussian of 0.375 MAR(e), then FLIP at the display's ppd; against fovsdf's 4 spp
   ground truth; still camera, gaze at the centre; "full" = one sample per pixel centre, one
   frame; equal = perr at most 0.001 above full's). Three causes, separated by
   --lp-study (rows lp_acuity_pre: each LP sample the mean of 4 x 4 points over its texel):
   - aliasing of one frame of point samples. Where the pixels are much finer than the eye
     it is the worst: at the 27" monitor (33.6 ppd, primitives) quality 0.25 (4.2x) has perr
     0.0194 against full's 0.0180, prefiltered samples 0.0134 (the loss beyond 10 degrees
     gone), 16 frames of TAA (jitter: the same prefilter, free) 0.0118;
   - contrast loss of the interpolation once the samples are prefiltered: bilinear over
     samples near the eye's spacing flattens detail the eye still sees (the monitor at
     quality 0.5: prefiltered 0.0275, TAA 0.0228; columns at 640x360: prefiltered samples
     are no better than point samples). FOVLP_RECON_CUBIC (what this call picks) keeps it:
     the monitor at 0.5 with TAA 0.0202, columns at 640x360 with TAA equal at quality 0.7
     (2.5x; bilinear: 0.5);
   - the screen border and the far periphery of scenes with fine structure (columns at the
     monitor, beyond 20 degrees): LP samples that fall off the screen are not shaded, so a
     thin feature at the border is filled from inside; there every fovlp configuration
     (the C Fov and Fov presets too) stays above full.
   The gap rule is not what fails at the monitor's quality 0.25 (the same buffer with
   prefiltered samples beats full); from about 0.5 up the gaps themselves are too wide for the
   measure's eye. So use it with TAA and a quality below 1: still camera, 16 frames
   (one cycle of the jitter), cubic reconstruction, equal to full (saving, scenes primitives
   temple; columns where stated):
      640x360 (5-8 ppd)      one frame quality 0.5 (1.7-2.0x; atrium 0.35);
                             TAA quality 1 for primitives, temple (4.7-5.1x), 0.7 for
                             columns, atrium (2.4-2.5x)
      27" monitor (33.6 ppd) one frame: none at 0.25 (0.0192 / 0.0180); TAA: primitives
                             0.45 (10.3x), temple 0.35 (6.9x), atrium 0.25 (4.2x); columns
                             none (0.25: 0.0184 against 0.0148)
      100 degree headset     one frame 0.35 (3.7x; temple 0.5); TAA 0.7 (10.5x; temple
                             1, 18.5x)
   Full resolution gains from the same jitter and averaging too (the monitor, primitives:
   0.0093 after 16 frames; 640x360: 0.0191), so these are savings against one frame of
   full resolution, and only for a still view: while the camera moves there is no jitter
   (the thesis) and the one-frame figures apply. The rule and the figures at the top are
   for quality 1, the eye model's threshold.

DOES NOT
   - shade, trace or rasterise anything (you shade the positions), use a GPU API, start
     threads, allocate memory, or read or write files;
   - keep any global or thread-local state.

CONFIGURATION (define before including the implementation)
   FOVLP_STATIC         all functions static (use it when two libraries embed this header)
   FOVLP_API            override the linkage of every public function
   FOVLP_MAX_DIM        hard cap on the screen width and height          (default 65536)
   FOVLP_MAX_LP_DIM     hard cap on the LP buffer width and height       (default 65536)
   FOVLP_MAX_SAMPLES    hard cap on the sample slots (LP + disc + 1)     (default 2^28)
   Shared by the three headers (listed in the shared declarations block below):
   FOV_DLL, FOV_ASSERT, FOV_NO_LIBM, the math hooks FOV_SQRTF ... FOV_POWF, FOV_MEMSET,
   FOV_MEMCPY and FOV_NO_ERROR_STRINGS.

MEMORY
   The caller owns every byte. fovlp_memory_size() gives the context's working memory for a
   config (the per-frame tables: (w + 2 h) floats); fovlp_init() takes it. The sample buffer
   (ctx.geo.samples slots of 3 floats of linear RGB, optional depth: 1 float), every image
   (screen size, linear RGB floats or fovlp_srgb8_rows' bytes, explicit row stride) are
   caller buffers; TAA history (colour, depth, age) too, two copies that you swap every
   frame. Stack use: below 1 KiB in every entry point.

ERRORS AND LOGGING
   Every fallible function returns fov_result: FOV_OK (0) or a negative code.
   fovlp_result_string() never returns NULL. Bad input (NULL pointers, zero, over-cap or
   overflowing sizes, sigma or alpha <= 0, NaN or infinite gaze, camera or parameters, a
   gaze disc that covers the screen) is rejected with an error code before any work is done;
   nothing asserts on data. Messages are on by default (no FOV_DEBUG needed): cfg.logger
   receives each error once, with its code and a message naming the field or the call and
   the rule ("config.taa.phases must be 1 .. 256", "shade_rows: call fovlp_begin_frame
   first", "reconstruct: out_stride below 3 * width"), and a FOV_LOG_WARN when an off-screen
   gaze is clamped. Print them with
      static void log_err(const char *tag, uint32_t level, int32_t code, const char *msg,
                          uint32_t line, void *user)
      { (void)level; (void)user; fprintf(stderr, "%s %d (%s): %s [line %u]\n", tag, (int)code,
                fovlp_result_string((fov_result)code), msg, (unsigned)line); }
      cfg.logger.func = log_err;            // before fovlp_init: the context keeps a copy
   Every error return of a function given a valid context or config is logged with its code
   (tests/fuzz/fuzz_fovlp.c and tests/test_errors.c check it). Code only, nothing logged:
   a NULL context or config, fovlp_ecc_init, and fovlp_begin_frame on a context fovlp_init
   never filled (FOV_ERR_INVALID_ARG: it has no logger yet). FOV_NO_ERROR_STRINGS removes
   the texts (about 4.4 KB of a Cortex-M4 -Os build): the codes and lines still reach the
   logger with msg "" (never NULL), and fovlp_result_string returns "".
   A result that would not fit in a float is an error, never an infinity: fovlp_spacing
   and fovlp_lp_to_screen give FOV_ERR_LIMIT there. Bad data from the caller's shading
   does not spread: fovlp_taa_rows never writes a NaN or infinite colour into the history
   (a non-finite current colour keeps the history or gives 0, a non-finite fetched or
   clamped history is rejected, neighbours with NaN / inf are left out of the clamp box, a
   NaN or infinite depth fails the depth test); the reconstruction and the blend pass NaN
   and inf samples through as they are.

THREADING
   fovlp_begin_frame writes the context; between two begin_frame calls the context is
   read-only, so fovlp_samples / fovlp_shade_rows (sample rows) and fovlp_reconstruct_rows
   / fovlp_blend_rows / fovlp_taa_rows (screen rows) can run on disjoint rows from many
   threads. fovlp_blend_rows and fovlp_taa_rows read the rows above and below theirs from
   their input image: finish the input image first.

NUMERICS
   - Float only (no double anywhere); integers for frame counters and the Halton sequence.
   - The envelope: for finite inputs every FOV_OK output is finite, for any magnitude up to
     FLT_MAX (colours, depths, points, camera positions), and lies in the range below.
     Tested by tests/test_fovlp_numerics.c (libm, FOV_NO_LIBM, sanitizers) and fuzzed by
     tests/fuzz/fuzz_fovlp.c.
       reconstruction  each channel is a convex combination of the shaded samples it
                       uses (bilinear with renormalised weights, linear blends towards the
                       disc or centre sample): inside their [min, max] up to float
                       rounding (the fuzz check allows 1e-5 of the largest magnitude).
                       RECON_CUBIC: clamped to the [min, max] of the 2 x 2 nearest
                       samples (exactly; a sum that is not finite gives the bilinear
                       value).
                       Where the weighted sum of finite taps near FLT_MAX rounds past it,
                       the mean is recomputed with half weights (exact) and doubled back,
                       saturating at +-FLT_MAX; elsewhere the image is bit for bit the
                       plain formula's.
       blend           between the pixel and its 3x3 mean: inside the 3x3 range.
       TAA             always finite; each channel lies between the current colour and the
                       history used (a blend a + (b - a) t where b - a is finite, else
                       a (1 - t) + b t, clamped to [min(a, b), max(a, b)]). The history is
                       the previous output fetched bilinearly at the reprojected point,
                       clamped into the neighbourhood's YCoCg box, whose RGB corners lie up
                       to 3x outside its range (saturated at +-FLT_MAX): |out| <= 3 max
                       |current, previous|. With a still camera and no clamp the output
                       lies between the pixel's previous and current values exactly.
                       The clamp box is computed at the scale 2^-70 when a colour exceeds
                       2^60 (exact; 3e38^2 would overflow the variance sums), with moments
                       about the centre pixel (no cancellation for colours far from 0).
                       The depth test holds for depths up to FLT_MAX; a reprojected
                       distance beyond FLT_MAX rejects the history.
       mappings        screen_to_lp: any finite point, v in [0, lp_h); lp_to_screen:
                       FOV_ERR_LIMIT where the point would lie beyond the float range.
       density         finite and >= 0 at any finite point (0 for NaN / inf).
       spacing         finite (angular > 0, radial >= 0), or FOV_ERR_LIMIT where one
                       exceeds the float range (angular 2 pi r / h: r beyond about 5e37 h;
                       radial where du/dr underflows). At r <= 1 with alpha != 1 the kernel
                       is flat and the radial spacing is given as FLT_MAX.
       eccentricity    fovlp_ecc_deg in [0, 180] at any finite point (scaled first beyond
                       about 1e19 px); fovlp_ecc_ppd at most FLT_MAX.
   - Forward then inverse mapping round-trips within 1e-3 px relative to the radius (measured
     by the tests at 8K with libm and FOV_NO_LIBM).
   - Sample positions come from per-frame tables (exp along u, cos/sin along v), so shading
     and reconstruction agree bit for bit on which samples exist.

PLATFORM NOTES
   - Freestanding: with FOV_NO_LIBM (or all math hooks) and FOV_ASSERT defined the
     implementation includes only <stddef.h>, <stdint.h>, <float.h> and <limits.h> (plus
     <xmmintrin.h> with MSVC on x86, for the square root instruction; gcc and clang get it
     by inline assembly).
   - wasm32: clang --target=wasm32 -ffreestanding -nostdlib -DFOV_NO_LIBM works as is.
   - Cortex-M4F: arm-none-eabi-gcc -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard; the
     object file references no __aeabi_d* routine (checked by tests/compile/run.sh).

REFERENCES (cited by author and year, with the section, equation or table of that work;
"the thesis" is Andersson & Hansson 2020 throughout this file)
   Andersson & Hansson 2020  K. Andersson, T. Hansson, "Performance Optimizations for
                    Foveated Real-Time Raytracing", master's thesis, Lund University,
                    LU-CS-EX 2020-64, 2020.
   Meng et al. 2018 X. Meng, R. Du, M. Zwicker, A. Varshney, "Kernel Foveated Rendering",
                    Proceedings of the ACM on Computer Graphics and Interactive Techniques
                    1(1), article 5, 2018.
   Guenter et al. 2012  B. Guenter, M. Finch, S. Drucker, D. Tan, J. Snyder, "Foveated 3D
                    Graphics", ACM Transactions on Graphics 31(6), article 164 (SIGGRAPH
                    Asia), 2012: the linear MAR model and its slopes (the fov_eye defaults).
   Karis 2014       B. Karis, "High Quality Temporal Supersampling", SIGGRAPH 2014 course
                    Advances in Real-Time Rendering in Games.
   Salvi 2016       M. Salvi, "An Excursion in Temporal Supersampling", Game Developers
                    Conference (GDC), 2016.

LICENSE: see end of file.

RECENT REVISION HISTORY
   0.7.1 (2026-12-05) Documentation: PLATFORM NOTES name xmmintrin (MSVC only).
   0.7.0 (2026-12-05) fovlp_gaze_predict: the fovea led by the latency in pursuit (shared block
                      revision 5); FOV_NO_LIBM takes the CPU's exact square root where it has one
                      (SSE, Arm, wasm: as many instructions as with libm); FOVLP_MAX_* in the
                      declarations.
   0.6.0 (2026-12-05) gaze input from the shared block of revision 4: fovlp_gaze_filter_*,
                      fovlp_gaze_margin, fovlp_config_gaze_margin (widens the gaze disc),
                      fovlp_gaze_fixed; off-axis per-eye frusta: fovlp_camera_from accepts tan_left
                      .. tan_top, config.taa.frustum for the reprojection, fovlp_camera_display for
                      the eccentricity model.
   0.5.0 (2026-12-05) cfg.recon (fovlp_recon): FOVLP_RECON_CUBIC, Catmull-Rom over the 4 x 4
                      nearest LP samples clamped to the 2 x 2 nearest's range, which keeps
                      the contrast bilinear interpolation loses at the eye's scale;
                      fovlp_config_acuity selects it (its images change; the presets and a
                      zero recon stay bilinear, bit for bit as before). The shared block of
                      revision 3: fov_eye's default quality is 0.5 (was 1; fov_eye).
   0.4.0 (2026-12-02) fovlp_config_acuity: sigma, alpha, the gaze disc and lp_aspect from the
                      shared eye model (fov_eye, Guenter et al. 2012) and the display, the
                      fewest samples whose gaps meet quality * MAR(e) * ppd from the disc edge
                      to the diagonal (ACUITY-DRIVEN CONFIGURATION); the shared block of
                      revision 2 (fov_eye, fov_eye_plan, fovlp_eye_mar / _density / _ecc /
                      _plan). The presets are unchanged.
   0.3.0 (2026-12-02) one block shared with fovsdf.h and fovpt.h (tools/fov_shared.h); error
                      messages on by default, a specific one per failure (FOV_DEBUG no longer
                      needed); fovlp_camera_from (the TAA camera of a fov_camera);
                      fovlp_srgb8_rows and fovlp_linear_to_srgb8 (exact 8-bit sRGB, the same
                      bytes in every build); fovlp_taa_io_init, fovlp_taa_stats_init; the sample
                      buffer is called rgb (linear RGB; the docs said srgb); REFERENCES.
   0.2.1 (2026-12-01) finite outputs for finite inputs: the TAA blend, history fetch, variance
                      clip (scaled when the moments overflow; moments about the centre pixel),
                      depth test, reconstruction and fovlp_blend_rows no longer overflow for
                      colours near FLT_MAX (3e38 then -3e38 gave -inf in all of the history);
                      fovlp_spacing returns FOV_ERR_LIMIT instead of an infinite spacing;
                      fovlp_density and fovlp_ecc_deg finite at far points; screen_to_lp,
                      lp_to_screen and spacing log their errors.
   0.2.0 (2026-11-23) TAA: while the camera moves the history is variance-clipped in YCoCg
                      when taa.clamp is NONE (new field taa.thesis_moving = 1: the thesis's
                      unclamped history, which ghosts); a still camera is unchanged.
                      Review fixes: NaN / inf from the caller's shading never enters the TAA
                      history; jitter offsets in [0, 1) (disc samples stay on their pixel);
                      the disc buffer is min(S, W) x min(S, H) (geometry disc_cols /
                      disc_rows); finite mappings for huge inputs; aliased TAA buffers and
                      out_depth without sample_depth refused; any finite gaze accepted by
                      fovlp_ecc_init (shared model).
   0.1.0 (2026-11-23) first version: mappings, presets, gaze disc, sampling, reconstruction,
                      Gaussian blend, TAA.
*/

#if defined(FOV_IMPL) && !defined(FOVLP_IMPLEMENTATION)
#define FOVLP_IMPLEMENTATION
#endif

#ifndef FOVLP_H_INCLUDED
#define FOVLP_H_INCLUDED

#include <stddef.h>
#include <stdint.h>

#define FOVLP_VERSION_MAJOR 0
#define FOVLP_VERSION_MINOR 7
#define FOVLP_VERSION_PATCH 1
#define FOVLP_VERSION_STRING "0.7.1"

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

#ifndef FOVLP_API
#if defined(FOVLP_STATIC)
#define FOVLP_API static FOV__UNUSED
#elif defined(FOVLP_IMPLEMENTATION)
#define FOVLP_API FOV__API_EXPORT
#else
#define FOVLP_API FOV__API_IMPORT
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ==== settings ============================================================================ */

typedef enum fovlp_norm {
    FOVLP_NORM_DIAGONAL = 0,  /* L = log(screen diagonal), fixed (thesis eq. 3.10) */
    FOVLP_NORM_CORNER = 1,    /* L = log(farthest corner from the gaze) (Meng et al. 2018) */
    _FOVLP_NORM_NUM,
    _FOVLP_NORM_FORCE_U32 = 0x7FFFFFFF
} fovlp_norm;

typedef enum fovlp_edge {
    FOVLP_EDGE_LOG_R = 0,     /* G = K(log r_G / L): the LP buffer starts exactly at r_G */
    FOVLP_EDGE_THESIS = 1,    /* G = K(log(r_G + 1) / L) as printed in eq. 3.4 */
    _FOVLP_EDGE_NUM,
    _FOVLP_EDGE_FORCE_U32 = 0x7FFFFFFF
} fovlp_edge;

typedef enum fovlp_recon {
    FOVLP_RECON_BILINEAR = 0, /* bilinear in (u, v) over the 2 x 2 nearest LP samples */
    FOVLP_RECON_CUBIC = 1,    /* Catmull-Rom in (u, v) over the 4 x 4 nearest, clamped to the
                                 range of the 2 x 2 nearest (no overshoot); bilinear where
                                 one of the 16 is not shaded */
    _FOVLP_RECON_NUM,
    _FOVLP_RECON_FORCE_U32 = 0x7FFFFFFF
} fovlp_recon;

typedef enum fovlp_clamp {
    FOVLP_CLAMP_NONE = 0,     /* depth rejection only (the thesis) */
    FOVLP_CLAMP_AABB = 1,     /* history clamped to the min/max box of the current 3x3
                                 neighbourhood in YCoCg (Karis 2014) */
    FOVLP_CLAMP_VARIANCE = 2, /* history clipped towards the neighbourhood mean, box
                                 mean +- clip_gamma * standard deviation, in YCoCg */
    _FOVLP_CLAMP_NUM,
    _FOVLP_CLAMP_FORCE_U32 = 0x7FFFFFFF
} fovlp_clamp;

typedef enum fovlp_preset {
    FOVLP_PRESET_FOV = 0,     /* sigma 0.75, alpha 1, no disc,   lp_aspect 1.2  (Table 5.1) */
    FOVLP_PRESET_K_FOV = 1,   /* sigma 1.0,  alpha 3, no disc,   lp_aspect 0.70 */
    FOVLP_PRESET_C_FOV = 2,   /* sigma 1.4,  alpha 1, a_G 0.20,  lp_aspect 0.33 */
    FOVLP_PRESET_C_K_FOV = 3, /* sigma 1.3,  alpha 2, a_G 0.15,  lp_aspect 0.35 */
    _FOVLP_PRESET_NUM,
    _FOVLP_PRESET_FORCE_U32 = 0x7FFFFFFF
} fovlp_preset;

/* Temporal anti-aliasing. All zero: TAA off. */
typedef struct fovlp_taa_config {
    uint32_t enable;        /* 1: jitter and history (fovlp_taa_rows)               0: off */
    uint32_t phases;        /* Halton (2, 3) points cycled, 1 .. 256                0: 16 */
    uint32_t halton_start;  /* index of the first Halton point                      0: 1 */
    uint32_t max_age;       /* age cap, 1 .. 255 (history weight 1 - 1/age)        0: 20 */
    uint32_t clamp;         /* fovlp_clamp                                   0: none */
    float clip_gamma;       /* VARIANCE: box half-size in standard deviations       0: 1.0 */
    float depth_tol;        /* relative depth difference that rejects history      0: 0.02 */
    float reset_deg;        /* gaze jump (degrees) that resets the history          0: 2.0 */
    float periphery;        /* beyond periphery * diagonal from the gaze a moving camera
                               keeps its history and resets the age (>= 1: never)  0: 1/3 */
    uint32_t jitter_moving; /* 1: keep jittering while the camera moves (thesis: off) */
    uint32_t thesis_moving; /* 1: a moving camera's history as the thesis uses it (clamped
                               only by taa.clamp; it ghosts); 0: while the camera moves,
                               history is variance-clipped in YCoCg (gamma clip_gamma)
                               wherever taa.clamp is NONE (ours) */
    float frustum[4];       /* an off-axis camera (an HMD eye): the fov_camera's tan_left,
                               tan_right, tan_bottom, tan_top; the reprojection then maps
                               screen point (x, y) to fwd + (-tl + (tl + tr) x / W) right +
                               (tt - (tt + tb) y / H) up (fovlp_camera's tan_half_y unused).
                               Finite, left + right and bottom + top > 1e-6, each <= 1e6.
                               All 0: the camera's own tan4 (fovlp_camera_from), else
                               symmetric from tan_half_y; set: must equal a non-zero
                               cam.tan4 (begin_frame: FOV_ERR_INVALID_ARG)          0: 0 */
} fovlp_taa_config;

/* A zero-filled config means "all defaults" (listed per field) apart from width and height,
   which are required. The defaults are the thesis's C Fov mode with the aspect matched.
   fovlp_config_default() gives the same settings filled in (without the g++ -Wextra warning
   of `= {0}`); then set width and height, or start from fovlp_config_preset(). */
typedef struct fovlp_config {
    uint32_t width, height; /* screen in pixels, 1 .. FOVLP_MAX_DIM (required) */
    float sigma;            /* buffer compression (> 0; < 1 gives more samples)     0: 1.4 */
    float alpha;            /* kernel exponent K(x) = x^alpha, (0, 16]              0: 1.0 */
    float gaze_angle;       /* a_G, radians, [0, 1.5) (0 after defaults: no disc)   0: 0.20 */
    uint32_t no_disc;       /* 1: no gaze disc (plain log-polar, the Fov / K Fov modes) */
    float lp_aspect;        /* LP buffer width / height (> 0); 0: matched spacing at match_deg */
    float match_deg;        /* eccentricity where lp_aspect 0 matches the radial and angular
                               sample spacing, (0, 89)                              0: 15 */
    uint32_t norm;          /* fovlp_norm                                         0: diagonal */
    uint32_t edge;          /* fovlp_edge                                         0: log r_G */
    uint32_t recon;         /* fovlp_recon, the LP samples' interpolation      0: bilinear */
    float cam_fov_y_deg;    /* used when display is all zero: the field of view of the image
                               height at the eye; 0: the thesis's viewing distance
                               d = diagonal / tan 60 degrees */
    fov_display display;    /* viewing geometry (eccentricity, r_G); see fov_display */
    uint32_t blend;         /* 1: Gaussian blend in the periphery (fovlp_blend_rows) */
    float blend_start;      /* fraction of the diagonal where the blend starts      0: 1/6 */
    float blend_end;        /* fraction of the diagonal where it is complete        0: 1/2 */
    fovlp_taa_config taa;
    fov_logger logger;      /* optional diagnostics */
} fovlp_config;

/* Derived geometry (eqs. 3.3-3.6, 3.10), for the config and the current gaze. */
typedef struct fovlp_geometry {
    uint32_t width, height; /* screen */
    uint32_t lp_w, lp_h;    /* LP buffer w x h (eq. 3.6) */
    float lp_aspect;        /* the aspect used (given or matched) */
    float L;                /* normaliser (eq. 3.10), for the current gaze */
    float f_px;             /* eye to image distance, pixels (the eccentricity model) */
    float r_g;              /* gaze disc radius, pixels (0: no disc) */
    float G, u_g, w_c;      /* eq. 3.4, 3.5 */
    float u_max;            /* LP columns the screen needs from the current gaze */
    uint32_t lp_cols;       /* columns dispatched: min(lp_w, ceil(u_max)), >= 1 */
    uint32_t disc_side;     /* S: side of the square around the disc, any gaze (0: no disc) */
    uint32_t disc_cols, disc_rows; /* the disc buffer: min(S, W) x min(S, H) slots (a strip
                               screen does not pay for a square of its long side) */
    uint32_t disc_x0, disc_y0, disc_w, disc_h; /* the current disc square on the screen */
    uint32_t lp_slots;      /* lp_w * lp_h: slot of texel (u, v) is v * lp_w + u */
    uint32_t disc_offset;   /* slot of disc pixel (x, y) = disc_offset + (y - disc_y0) *
                               disc_cols + (x - disc_x0) */
    uint32_t centre_slot;   /* slot of the sample on the gaze point */
    uint32_t samples;       /* slots in a sample buffer: lp_slots + disc_cols disc_rows + 1 */
} fovlp_geometry;

/* The camera for TAA reprojection: the shared fov_camera (see its declaration: frame,
   handedness, pixel convention) in basis form; fovlp_camera_from fills it from a fov_camera,
   with exactly the pinhole, frame and tan_half_y fovsdf_init derives from that camera (so it
   equals fovsdf_ctx's origin, right, up, fwd, tan_half_y bit for bit). Screen point (x, y)
   looks along fwd + ((x / W) 2 - 1) tan_half_y (W / H) right - ((y / H) 2 - 1) tan_half_y up
   (W x H the fovlp image); depth = distance along the unit ray. right, up, fwd: orthonormal. */
typedef struct fovlp_camera {
    float pos[3];
    float right[3], up[3], fwd[3];
    float tan_half_y;       /* tan(vertical field of view / 2), > 0 */
    float tan4[4];          /* an off-axis frustum's tan_left, tan_right, tan_bottom, tan_top
                               (fovlp_camera_from copies them; then the reprojection uses them
                               and tan_half_y is unused); all 0: symmetric. Zero them when
                               you fill the struct by hand (begin_frame rejects bad ones) */
} fovlp_camera;

/* The per-frame context (transparent, like fovsdf_ctx). fovlp_init fills it; fovlp_begin_frame
   updates it; read-only between begin_frame calls. */
typedef struct fovlp_ctx {
    fovlp_config cfg;       /* resolved: defaults filled in */
    fovlp_geometry geo;     /* for the current gaze */
    fov_ecc_model ecc;      /* the shared eccentricity model, for the current gaze */
    fov_gaze gaze;          /* current gaze (clamped to the screen) */
    fov_gaze prev_gaze;
    fovlp_camera cam, prev_cam;
    uint32_t have_cam;      /* bit 0: cam valid, bit 1: prev_cam valid */
    uint32_t frame;         /* frames begun since init or fovlp_reset_history */
    uint32_t in_frame;      /* 1 after the first begin_frame */
    uint32_t history_valid; /* TAA: 1 when the history passed to fovlp_taa_rows is usable */
    uint32_t moving;        /* 1 when cam differs from prev_cam */
    float jit_u, jit_v;     /* sample offset inside a texel / pixel this frame (0.5: centre) */
    float L_diag;           /* log(diagonal), the fixed normaliser of the sizes */
    float disc_angle;       /* the gaze disc used, radians: cfg.gaze_angle (which sizes the
                               buffers) after fovlp_init, smaller after fovlp_set_gaze_margin */
    float *rho;             /* lp_w radii of the columns' samples (this frame) */
    float *cs, *sn;         /* lp_h cos/sin of the rows' sample angles (this frame) */
    void *mem;
    size_t mem_size;
} fovlp_ctx;

/* A sample to shade: screen position and its slot in the sample buffer. */
typedef struct fovlp_sample {
    float x, y;
    uint32_t slot;
} fovlp_sample;

/* Shading callback: colour (linear RGB, 3 floats) and, when depth is not NULL, the depth
   (distance along the unit ray, for TAA) of the screen point (x, y). */
typedef void (*fovlp_shade_fn)(float x, float y, float rgb[3], float *depth, void *user);

/* Sample counts of the current frame (fovlp_count_samples). */
typedef struct fovlp_counts {
    uint64_t lp_dispatched;   /* lp_cols * lp_h */
    uint64_t lp_shaded;       /* LP texels whose sample is on the screen */
    uint64_t disc_dispatched; /* disc_w * disc_h */
    uint64_t disc_shaded;     /* disc pixels inside the circle */
    uint64_t shaded;          /* lp_shaded + disc_shaded + 1 (the centre sample) */
    float dispatched_pct;     /* (lp_dispatched + disc_dispatched) / (W H) * 100 */
    float shaded_pct;         /* shaded / (W H) * 100 */
} fovlp_counts;

/* TAA buffers of one frame. Screen-size, tightly packed: 3 floats per pixel for colour, one
   float per pixel for depth, one byte for age. Clear it with fovlp_taa_io_init (all NULL),
   then set what you have:
     cur_rgb      required: this frame's image (fovlp_reconstruct_rows, or fovlp_blend_rows)
     cur_depth    optional, NULL: no depth. This frame's depth (fovlp_reconstruct_rows'
                  out_depth); required while the camera moves (fovlp_begin_frame given a
                  camera that differs from the previous frame's), to reproject the history
     prev_rgb, prev_age   required once a history exists (ctx.history_valid: from the
                  second frame after fovlp_init, fovlp_reset_history or a gaze jump): what
                  the previous call wrote to out_rgb / out_age
     prev_depth   optional like cur_depth: the previous call's out_depth
     out_rgb, out_age     required: the result (show out_rgb) and the next frame's history
     out_depth    optional, NULL: not written; give it when the camera may move next frame
   Keep two sets of prev / out buffers and swap them every frame; out_* equal to cur_rgb or
   to prev_* is FOV_ERR_INVALID_ARG. */
typedef struct fovlp_taa_io {
    const float *cur_rgb;
    const float *cur_depth;
    const float *prev_rgb;
    const float *prev_depth;
    const uint8_t *prev_age;
    float *out_rgb;
    float *out_depth;
    uint8_t *out_age;
} fovlp_taa_io;

/* TAA counters: fovlp_taa_rows adds to them (never resets them); start with
   fovlp_taa_stats_init (all zero). One per thread, summed by you. */
typedef struct fovlp_taa_stats {
    uint64_t pixels;
    uint64_t rejected;      /* history rejected (off-screen or depth) */
    uint64_t kept_periphery;/* peripheral rule applied */
} fovlp_taa_stats;

/* ==== functions =========================================================================== */

FOVLP_API const char *fovlp_result_string(fov_result r);   /* never NULL */
FOVLP_API const char *fovlp_preset_name(uint32_t preset);  /* "Fov", ...; never NULL */

/* Config: defaults, presets (Table 5.1; an unknown preset gives the defaults) and the
   effective values with validation. */
FOVLP_API fovlp_config fovlp_config_default(void);   /* width = height = 0: set them */
FOVLP_API fovlp_config fovlp_config_preset(uint32_t preset, uint32_t width, uint32_t height);
FOVLP_API fov_result fovlp_config_resolve(const fovlp_config *in, fovlp_config *out);
/* Geometry of a config for a gaze point, without a context (sizes, u_G, used columns). */
FOVLP_API fov_result fovlp_geometry_get(const fovlp_config *cfg, fov_gaze gaze,
                                        fovlp_geometry *out);

/* Acuity-driven configuration (see ACUITY-DRIVEN CONFIGURATION in the doc block): fills
   sigma, alpha, gaze_angle, no_disc, lp_aspect, norm, edge and recon (FOVLP_RECON_CUBIC) of
   *cfg so that the LP sample spacing meets the eye (eye NULL = the fov_eye defaults) for
   cfg's display, with the fewest samples; cam (may be NULL) gives the field of view when
   cfg->display is all zero (then cfg->cam_fov_y_deg is set to it). Every other field is
   left as it was; *cfg is written only on success. FOV_ERR_NULL, _NOT_FINITE, _INVALID_ARG
   (eye, cam, config), _UNSUPPORTED (the eye needs every pixel of the screen), _LIMIT,
   _DEGENERATE (no buffer meets the eye); each logged through cfg->logger. */
FOVLP_API fov_result fovlp_config_acuity(fovlp_config *cfg, const fovlp_camera *cam,
                                         const fov_eye *eye);

/* Eccentricity (the shared model; the same semantics as fovsdf_ecc_*). */
FOVLP_API fov_result fovlp_ecc_init(fov_ecc_model *m, const fov_display *display,
                                    float cam_fov_y_deg, uint32_t width, uint32_t height,
                                    fov_gaze gaze);
FOVLP_API float fovlp_ecc_deg(const fov_ecc_model *m, float x, float y); /* degrees */
FOVLP_API float fovlp_ecc_ppd(const fov_ecc_model *m);
/* The eye's resolution (the shared model; see fov_eye; eye NULL = the defaults). _eye_mar: the
   allowed sample spacing at ecc_deg, quality * MAR, degrees (0 for bad input). _eye_density:
   the linear samples per display pixel the eye needs there for a display of ppd pixels per
   degree, (0, 1] (1 for bad input). _eye_ecc: the eccentricity, [0, 180] degrees, from which a
   linear density suffices (its inverse; bad input: 0 for density >= 1, else 180). _eye_plan:
   fov_eye_plan for an eccentricity model (FOV_ERR_NULL, _NOT_FINITE, _INVALID_ARG). */
FOVLP_API float fovlp_eye_mar(const fov_eye *eye, float ecc_deg);
FOVLP_API float fovlp_eye_density(const fov_eye *eye, float ppd, float ecc_deg);
FOVLP_API float fovlp_eye_ecc(const fov_eye *eye, float ppd, float density);
FOVLP_API fov_result fovlp_eye_plan(const fov_eye *eye, const fov_ecc_model *m,
                                    fov_eye_plan *plan);

/* GAZE INPUT (the shared model: see fov_gaze_filter_config; the same functions in fovsdf.h,
   fovlp.h and fovpt.h). A filter in your memory conditions the tracker's raw samples; its
   state, the tracker's accuracy and the system's latency give a margin that
   fovlp_config_gaze_margin adds to the config's full-quality radii. No eye tracker: fixed
   foveation, fovlp_gaze_fixed (the display's axis point) with FOV_GAZE_FIXED_MARGIN_DEG.
      fov_gaze_filter gf;  fovlp_gaze_filter_init(&gf, NULL);           // once (NULL: defaults)
      // per tracker sample (timestamps in microseconds, strictly increasing):
      fovlp_gaze_filter_push_px(&gf, &ecc, t_us, raw_px, &gaze);        // or _push in degrees
      // per frame:
      float m;  fovlp_gaze_margin(&gf, 0.5f, 50.0f, &m);     // accuracy 0.5 deg, latency 50 ms
      // or latency-compensated (the fovea where the eye is when the frame is seen):
      //   fov_gaze_prediction pr;  fovlp_gaze_predict(&gf, 0.5f, 50.0f, &pr);
      //   float d[2] = { pr.x_deg, pr.y_deg };  fovlp_gaze_from_deg(&ecc, d, &gaze);
      //   m = pr.margin_deg;
      fovlp_set_gaze_margin(&ctx, &base_cfg, m);           // then fovlp_begin_frame, render
   where ctx was initialised once with fovlp_config_gaze_margin(&base_cfg, gf.cfg.max_margin_deg,
   &cfg) (the room for the largest margin; a per-frame fovlp_init would reset the TAA history).
   _gaze_filter_config_default: the defaults filled in. _gaze_filter_init: FOV_ERR_NULL, or
   FOV_ERR_NOT_FINITE / FOV_ERR_INVALID_ARG for a bad config field (f left as it was).
   _gaze_filter_reset: forget every sample (after tracking was lost), keep the config.
   _gaze_filter_push: one raw sample (t_us, x_deg right, y_deg down; the gaze angles of
   fov_gaze_filter_config); the filtered gaze is then f->x_deg, f->y_deg. Errors leave f as
   it was (see fov_gaze_filter_config). _gaze_filter_push_px: the same for a sample in pixels
   of the image of eccentricity model m (only m's axis point and f_px are used), the filtered
   gaze in pixels in *out (may be NULL). _gaze_to_deg / _gaze_from_deg: pixels to gaze angles
   and back (FOV_ERR_INVALID_ARG beyond +-90 degrees or off the float range).
   _gaze_margin: the margin in degrees for the filter's last state (FOV_ERR_INVALID_ARG for a
   negative accuracy or latency, *margin_deg then the cap). _gaze_predict: latency compensation, the
   gaze latency_ms after the newest sample (extrapolated along the fitted velocity during
   pursuit, not in fixations, never across a saccade or right after its landing) and its
   margin (see fov_gaze_filter_config); render with out->x_deg, out->y_deg as the gaze
   (_gaze_from_deg for pixels) and out->margin_deg as the margin; errors as _gaze_margin's
   (*out then the filtered gaze and the cap); f is only read. _gaze_fixed: the gaze at the
   display's axis point (width / 2 + axis_dx, height / 2 + axis_dy; display may be NULL).
   _camera_display: the fov_display of a camera's own frustum, off-axis or not (fov_y_deg,
   axis_dx, axis_dy as fov_display describes; the eccentricity model every header derives
   from a camera when config.display is all zero). */
FOVLP_API fov_gaze_filter_config fovlp_gaze_filter_config_default(void);
FOVLP_API fov_result fovlp_gaze_filter_init(fov_gaze_filter *f,
                                            const fov_gaze_filter_config *cfg);
FOVLP_API void fovlp_gaze_filter_reset(fov_gaze_filter *f);
FOVLP_API fov_result fovlp_gaze_filter_push(fov_gaze_filter *f, uint64_t t_us, float x_deg,
                                            float y_deg);
FOVLP_API fov_result fovlp_gaze_filter_push_px(fov_gaze_filter *f, const fov_ecc_model *m,
                                               uint64_t t_us, fov_gaze raw, fov_gaze *out);
FOVLP_API fov_result fovlp_gaze_to_deg(const fov_ecc_model *m, fov_gaze px, float deg[2]);
FOVLP_API fov_result fovlp_gaze_from_deg(const fov_ecc_model *m, const float deg[2],
                                         fov_gaze *px);
FOVLP_API fov_result fovlp_gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                       float latency_ms, float *margin_deg);
FOVLP_API fov_result fovlp_gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                        float latency_ms, fov_gaze_prediction *out);
FOVLP_API fov_result fovlp_gaze_fixed(const fov_display *display, uint32_t width,
                                      uint32_t height, fov_gaze *out);
FOVLP_API fov_result fovlp_camera_display(const fov_camera *cam, fov_display *out);
/* The margin applied: *out = base resolved (fovlp_config_resolve) with the gaze disc's
   gaze_angle (radians) grown by margin_deg (>= 0) degrees. The disc's size sets the context's
   sizes: fovlp_init with *out for the largest margin you allow, then per frame
   fovlp_set_gaze_margin (a per-frame fovlp_init resets the TAA history). FOV_ERR_NULL,
   FOV_ERR_NOT_FINITE, FOV_ERR_INVALID_ARG (margin < 0),
   FOV_ERR_UNSUPPORTED (no_disc = 1: there is no full-quality disc to widen), FOV_ERR_LIMIT
   (gaze_angle reaching 1.5 radians), or the base's resolve error; *out written only on
   success. */
FOVLP_API fov_result fovlp_config_gaze_margin(const fovlp_config *base, float margin_deg,
                                              fovlp_config *out);
/* The margin applied per frame to a context, keeping its TAA history: the gaze disc becomes
   base's gaze_angle (resolved) grown by margin_deg rounded up to a multiple of 0.25 degrees
   (a wobbling margin does not move the LP samples every frame), from the next
   fovlp_begin_frame on. The context's sizes (LP buffer, disc buffer, sample slots, memory)
   never change: they are those of the config fovlp_init took, so init with
   fovlp_config_gaze_margin(&base, largest margin, &cfg) (FOV_GAZE_FIXED_MARGIN_DEG or the
   filter's max_margin_deg); the LP columns then start at the smaller disc's edge (u_G, w_C of
   fovlp_geometry follow it). A margin beyond that room is clamped to the context's disc (a
   FOV_LOG_WARN through cfg.logger; ctx->disc_angle says what is used) and returns FOV_OK.
   FOV_ERR_NULL, FOV_ERR_INVALID_ARG (ctx not initialised, margin < 0, base.gaze_angle above
   the context's), FOV_ERR_NOT_FINITE, FOV_ERR_UNSUPPORTED (no_disc), base's resolve error;
   the context is unchanged on error. */
FOVLP_API fov_result fovlp_set_gaze_margin(fovlp_ctx *ctx, const fovlp_config *base,
                                           float margin_deg);

/* Context: memory size query, init, and per frame begin_frame. cam may be NULL (no
   reprojection: TAA treats the camera as still). Resets the history on a gaze jump. */
FOVLP_API fov_result fovlp_memory_size(const fovlp_config *cfg, size_t *bytes);
FOVLP_API fov_result fovlp_init(fovlp_ctx *ctx, const fovlp_config *cfg, void *mem,
                                size_t mem_size);
FOVLP_API fov_result fovlp_begin_frame(fovlp_ctx *ctx, fov_gaze gaze, const fovlp_camera *cam);
/* The TAA camera of a fov_camera (the one you render with): pos = the pinhole pos +
   eye_offset * right, the frame of fov_camera, tan_half_y = tan(fov_y_deg / 2) (fov_y_deg 0:
   60). The size is not used (the TAA uses the fovlp image's). An off-axis camera (non-zero
   tan_left .. tan_top) gives tan_half_y = (tan_bottom + tan_top) / 2 and its tangents in
   tan4, which the reprojection uses (config.taa.frustum may stay 0; when set it must equal
   them: fovlp_begin_frame returns FOV_ERR_INVALID_ARG otherwise, and FOV_ERR_UNSUPPORTED
   when their ratio is not the fovlp image's aspect within 1e-3: non-square pixels, as in
   every header); set config.display with
   fovlp_camera_display (the eccentricity). FOV_ERR_NULL, FOV_ERR_NOT_FINITE,
   FOV_ERR_INVALID_ARG (field of view outside
   (0, 180), tangents as fovsdf_init rejects them, a pinhole beyond float) or
   FOV_ERR_DEGENERATE (target == pos, up parallel to the view).
   out is written only on success. */
FOVLP_API fov_result fovlp_camera_from(const fov_camera *cam, fovlp_camera *out);
FOVLP_API void fovlp_reset_history(fovlp_ctx *ctx);   /* the next frame starts TAA afresh */
/* Clear a fovlp_taa_io (every pointer NULL) or fovlp_taa_stats (every counter 0): the same as
   `= {0}` in C, without the missing-initializer warning of g++ -Wextra. */
FOVLP_API void fovlp_taa_io_init(fovlp_taa_io *io);
FOVLP_API void fovlp_taa_stats_init(fovlp_taa_stats *stats);

/* Mappings (continuous LP coordinates: texel (u, v) covers [u, u+1) x [v, v+1)). Any finite
   screen point maps; lp_to_screen gives FOV_ERR_LIMIT for a u so large that the point lies
   beyond the float range. */
FOVLP_API fov_result fovlp_screen_to_lp(const fovlp_ctx *ctx, float x, float y, float *u,
                                        float *v);
FOVLP_API fov_result fovlp_lp_to_screen(const fovlp_ctx *ctx, float u, float v, float *x,
                                        float *y);
/* LP texels per screen pixel area at a screen point (the Jacobian of the mapping; 1 inside
   the disc; finite and >= 0 for any finite point, 0 for NaN / inf), and the sample spacings
   in pixels, radial and angular, at radius r (r <= 1 counts as 1; with alpha != 1 the
   radial spacing there is FLT_MAX: the kernel is flat). FOV_ERR_LIMIT (logged, both set to
   0) where a spacing would exceed the float range, e.g. fovlp_spacing(FLT_MAX). */
FOVLP_API float fovlp_density(const fovlp_ctx *ctx, float x, float y);
FOVLP_API fov_result fovlp_spacing(const fovlp_ctx *ctx, float r, float *radial_px,
                                   float *angular_px);

/* Sampling. Sample rows: lp_h LP rows, then disc_h disc rows, then one row holding the
   centre sample; split them over threads freely. */
FOVLP_API uint32_t fovlp_sample_rows(const fovlp_ctx *ctx);
/* Array form: the samples of rows [r0, r1) into out (cap entries); *count = the number of
   samples (also when out is NULL, a count-only query; FOV_ERR_TOO_SMALL when cap is short). */
FOVLP_API fov_result fovlp_samples(const fovlp_ctx *ctx, uint32_t r0, uint32_t r1,
                                   fovlp_sample *out, size_t cap, size_t *count);
/* Callback form: shades rows [r0, r1) into rgb (3 floats per slot) and depth (1 per slot;
   may be NULL); slots that are not shaded are set to 0. shaded (may be NULL) is added to. */
FOVLP_API fov_result fovlp_shade_rows(const fovlp_ctx *ctx, uint32_t r0, uint32_t r1,
                                      fovlp_shade_fn fn, void *user, float *rgb, float *depth,
                                      uint64_t *shaded);
FOVLP_API fov_result fovlp_count_samples(const fovlp_ctx *ctx, fovlp_counts *out);

/* Reconstruction of screen rows [y0, y1) from the shaded samples (sample_rgb, linear RGB)
   into out_rgb (row stride in floats, 0: 3 W). sample_depth is optional (NULL: no depth);
   out_depth (W floats per row, optional, NULL: not written) gets the depth of the nearest
   sample and needs sample_depth (FOV_ERR_NULL without). */
FOVLP_API fov_result fovlp_reconstruct_rows(const fovlp_ctx *ctx, const float *sample_rgb,
                                            const float *sample_depth, uint32_t y0,
                                            uint32_t y1, float *out_rgb, uint32_t out_stride,
                                            float *out_depth);
/* Tile form: the tile [x0, x1) x [y0, y1). */
FOVLP_API fov_result fovlp_reconstruct_tile(const fovlp_ctx *ctx, const float *sample_rgb,
                                            const float *sample_depth, uint32_t x0,
                                            uint32_t y0, uint32_t x1, uint32_t y1,
                                            float *out_rgb, uint32_t out_stride,
                                            float *out_depth);
/* Gaussian blend in the periphery (eq. 3.13) of a reconstructed image (tightly packed),
   rows [y0, y1) into out (must not alias in). Copies when cfg.blend is 0. */
FOVLP_API fov_result fovlp_blend_rows(const fovlp_ctx *ctx, const float *in_rgb, uint32_t y0,
                                      uint32_t y1, float *out_rgb);
/* TAA resolve of screen rows [y0, y1) (see fovlp_taa_io). stats (may be NULL) is added to. */
FOVLP_API fov_result fovlp_taa_rows(const fovlp_ctx *ctx, const fovlp_taa_io *io, uint32_t y0,
                                    uint32_t y1, fovlp_taa_stats *stats);
/* 8-bit sRGB output, for an RGBA8 texture or an image file. fovlp_linear_to_srgb8 encodes one
   linear value: round(255 srgb(x)) with srgb the exact IEC 61966-2-1 curve (12.92 x up to
   x = 0.0031308, else 1.055 x^(1/2.4) - 0.055; not gamma 2.2), rounded to nearest, the input
   clamped to [0, 1]: x <= 0, -inf and NaN give 0, x >= 1 and +inf give 255. It uses no math
   function (a 255-entry table of the code boundaries and a 416-entry start table, integer
   compares only: 1.4 KiB), so every build (libm, FOV_NO_LIBM, any target) gives the same
   byte for the same float, and every byte is the correctly rounded one.
   fovlp_srgb8_rows encodes screen rows [y0, y1) of a linear float image (3 floats per pixel,
   as fovlp_reconstruct_rows, fovlp_blend_rows and fovlp_taa_rows write it; rgb_stride in
   floats, 0: 3 W) into out with `channels` bytes per pixel: 3 (RGB, e.g. a PPM) or 4 (RGBA,
   alpha 255); out_stride in bytes, 0: channels W. Row y is read at rgb + y rgb_stride and
   written at out + y out_stride (whole-image buffers, as in the other row functions); rows
   may be split over threads. Needs only an initialised ctx (no begin_frame). */
FOVLP_API uint8_t fovlp_linear_to_srgb8(float x);
FOVLP_API fov_result fovlp_srgb8_rows(const fovlp_ctx *ctx, const float *rgb, uint32_t rgb_stride,
                                      uint32_t y0, uint32_t y1, uint8_t *out, uint32_t out_stride,
                                      uint32_t channels);
/* The scaled Halton (2, 3) offset of a phase (eq. 3.11), in texels; for tests and tools. */
FOVLP_API fov_result fovlp_jitter(const fovlp_config *cfg, uint32_t phase, float *ou,
                                  float *ov);

/* The documented limits (see the configuration macros above), defined here so that a
   translation unit with the declarations alone can use them; give them the same value in
   every translation unit. */
#ifndef FOVLP_MAX_DIM
#define FOVLP_MAX_DIM 65536u
#endif
#ifndef FOVLP_MAX_LP_DIM
#define FOVLP_MAX_LP_DIM 65536u
#endif
#ifndef FOVLP_MAX_SAMPLES
#define FOVLP_MAX_SAMPLES 268435456u
#endif

#ifdef __cplusplus
}
#endif

#endif /* FOVLP_H_INCLUDED */

/* ---- end of API; implementation below ---- */
#ifdef __INTELLISENSE__
#define FOVLP_IMPLEMENTATION
#endif

#if defined(FOVLP_IMPLEMENTATION) && !defined(FOVLP_IMPL_INCLUDED)
#define FOVLP_IMPL_INCLUDED

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

#define FOVLP__PRIV FOV__PRIV
#define FOVLP__FAIL(lg, r, msg) FOV__FAIL(lg, "fovlp", r, msg)



#define FOVLP__TWO_PI 6.28318530717959f
#define FOVLP__GAZE_STEP_DEG 0.25f /* fovlp_set_gaze_margin rounds the margin up to this */
#define FOVLP__LOG2 0.693147181f
#define FOVLP__MAX_PHASES 256u

FOVLP__PRIV int fovlp__neq(float a, float b) { return a < b || a > b; }
/* |a| for any finite a: scaled by the largest component when the squared length overflows or
   underflows (inf only when |a| itself exceeds FLT_MAX); the plain formula otherwise */
FOVLP__PRIV float fovlp__len_safe(const float a[3])
{
    float d = fov__dot(a, a), m, s[3];
    if (d >= FLT_MIN && d <= FLT_MAX) return FOV__SQRT(d);
    m = fov__maxf(fov__maxf(fov__absf(a[0]), fov__absf(a[1])), fov__absf(a[2]));
    if (!(m > 0.0f) || !fov__finite(m)) return m;   /* 0, NaN or inf */
    s[0] = a[0] / m; s[1] = a[1] / m; s[2] = a[2] / m;
    return m * FOV__SQRT(fov__dot(s, s));
}
/* 2 x for a finite x, saturated at +-FLT_MAX; NaN and inf pass through */
FOVLP__PRIV float fovlp__twice_sat(float x)
{
    float t = x + x;
    if (fov__finite(x) && !fov__finite(t)) return x > 0.0f ? 3.4028235e38f : -3.4028235e38f;
    return t;
}
/* a + (b - a) t for t in [0, 1], never outside [min(a, b), max(a, b)] and finite for finite
   a, b: where b - a overflows (a and b of opposite signs beyond FLT_MAX / 2) it blends as
   a (1 - t) + b t, which cannot overflow; the clamp catches the rounding of either form.
   The usual case is bit for bit the plain formula. NaN in a or b passes through. */
FOVLP__PRIV float fovlp__lerp(float a, float b, float t)
{
    float d = b - a, r, lo = a < b ? a : b, hi = a < b ? b : a;
    r = fov__finite(d) ? a + d * t : a * (1.0f - t) + b * t;
    return r < lo ? lo : (r > hi ? hi : r);
}
FOVLP__PRIV float fovlp__normalize(float v[3])
{
    float d = fov__dot(v, v), l;
    if (!(d >= FLT_MIN && d <= FLT_MAX)) {
        /* the squared length overflows or underflows: scale by the largest component first,
           so any finite non-zero vector comes out unit length */
        float m = fov__maxf(fov__maxf(fov__absf(v[0]), fov__absf(v[1])), fov__absf(v[2]));
        if (!(m > 0.0f) || !fov__finite(m)) return m;
        v[0] /= m; v[1] /= m; v[2] /= m;
        l = fov__len(v);
        v[0] /= l; v[1] /= l; v[2] /= l;
        return l * m;
    }
    l = FOV__SQRT(d);
    v[0] /= l; v[1] /= l; v[2] /= l;
    return l;
}
/* uint64 -> float without the compiler runtime's 64-bit conversion helper */
FOVLP__PRIV float fovlp__u64f(uint64_t x)
{
    return (float)(uint32_t)(x >> 32) * 4294967296.0f + (float)(uint32_t)(x & 0xFFFFFFFFu);
}
/* K(x) = x^alpha for x >= 0 (eq. 3.2); alpha 1 exactly without a pow. */
FOVLP__PRIV float fovlp__pow(float x, float a)
{
    if (!(x > 0.0f)) return 0.0f;
    if (!fovlp__neq(a, 1.0f)) return x;
    return FOV__POW(x, a);
}
FOVLP__PRIV uint32_t fovlp__ceil_u(float x, uint32_t cap)
{
    float c;
    if (!(x > 0.0f)) return 0;
    if (x >= (float)cap) return cap;
    c = FOV__FLOOR(x);
    return (uint32_t)c + (c < x ? 1u : 0u);
}


/* ---- results, configs, presets ---------------------------------------------------------- */
FOVLP_API const char *fovlp_result_string(fov_result r) { return fov__result_string(r); }

FOVLP_API const char *fovlp_preset_name(uint32_t preset)
{
    static const char *const names[] = { "Fov", "K Fov", "C Fov", "C K Fov" };
    return preset < (uint32_t)_FOVLP_PRESET_NUM ? names[preset] : "unknown";
}

/* Fills the defaults of the zero fields and validates everything except width/height. */
FOVLP__PRIV fov_result fovlp__resolve(const fovlp_config *in, fovlp_config *out)
{
    static const fov__field fl[12] = { /* NaN or infinite: pass 0; negative (1s): pass 1 */
        FOV__FIELD(fovlp_config, sigma, 1), FOV__FIELD(fovlp_config, alpha, 1),
        FOV__FIELD(fovlp_config, gaze_angle, 1), FOV__FIELD(fovlp_config, lp_aspect, 1),
        FOV__FIELD(fovlp_config, match_deg, 1), FOV__FIELD(fovlp_config, cam_fov_y_deg, 1),
        FOV__FIELD(fovlp_config, blend_start, 1), FOV__FIELD(fovlp_config, blend_end, 1),
        FOV__FIELD(fovlp_config, taa.clip_gamma, 1), FOV__FIELD(fovlp_config, taa.depth_tol, 1),
        FOV__FIELD(fovlp_config, taa.reset_deg, 1), FOV__FIELD(fovlp_config, taa.periphery, 1) };
    fovlp_config c = *in;
    const fov_logger *lg = &in->logger;
    fov_result r = fov__fields_check(lg, "fovlp", "config.", &c, fl, 12u, 0, (uint32_t)__LINE__);
    if (r == FOV_OK) r = fov__display_check(lg, "fovlp", &c.display, 1, (uint32_t)__LINE__);
    if (r == FOV_OK) r = fov__fields_check(lg, "fovlp", "config.", &c, fl, 12u, 1, __LINE__);
    if (r != FOV_OK) return r;
    if (fov__is0(c.sigma)) c.sigma = 1.4f;
    if (c.sigma < 1e-3f)
        FOVLP__FAIL(lg, FOV_ERR_LIMIT, "config.sigma below 1e-3 (buffer too large)");
    if (fov__is0(c.alpha)) c.alpha = 1.0f;
    if (c.alpha > 16.0f) FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.alpha must be in (0, 16]");
    if (c.no_disc > 1) FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.no_disc must be 0 or 1");
    if (c.no_disc) c.gaze_angle = 0.0f;
    else if (fov__is0(c.gaze_angle)) c.gaze_angle = 0.20f;
    if (c.gaze_angle >= 1.5f)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.gaze_angle must be below 1.5 rad");
    if (fov__is0(c.match_deg)) c.match_deg = 15.0f;
    if (c.match_deg >= 89.0f)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.match_deg must be in (0, 89)");
    if (c.lp_aspect > 65536.0f || (c.lp_aspect > 0.0f && c.lp_aspect < 1.0f / 65536.0f))
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.lp_aspect must be 0 or in [2^-16, 2^16]");
    if (c.norm >= (uint32_t)_FOVLP_NORM_NUM)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.norm: unknown (see fovlp_norm)");
    if (c.edge >= (uint32_t)_FOVLP_EDGE_NUM)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.edge: unknown (see fovlp_edge)");
    if (c.recon >= (uint32_t)_FOVLP_RECON_NUM)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.recon: unknown (see fovlp_recon)");
    if (c.cam_fov_y_deg >= 180.0f)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.cam_fov_y_deg must be in (0, 180)");
    r = fov__display_check(lg, "fovlp", &c.display, 2, (uint32_t)__LINE__);
    if (r != FOV_OK) return r;
    if (c.blend > 1) FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.blend must be 0 or 1");
    if (fov__is0(c.blend_start)) c.blend_start = 1.0f / 6.0f;
    if (fov__is0(c.blend_end)) c.blend_end = 0.5f;
    if (!(c.blend_end > c.blend_start))
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.blend_end must exceed blend_start");
    if (c.taa.enable > 1) FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.enable must be 0 or 1");
    if (c.taa.jitter_moving > 1)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.jitter_moving must be 0 or 1");
    if (c.taa.thesis_moving > 1)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.thesis_moving must be 0 or 1");
    if (c.taa.phases == 0) c.taa.phases = 16;
    if (c.taa.phases > FOVLP__MAX_PHASES)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.phases must be 1 .. 256");
    if (c.taa.halton_start == 0) c.taa.halton_start = 1;
    if (c.taa.halton_start > 0x00FFFFFFu)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.halton_start above 2^24");
    if (c.taa.max_age == 0) c.taa.max_age = 20;
    if (c.taa.max_age > 255)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.max_age must be 1 .. 255");
    if (c.taa.clamp >= (uint32_t)_FOVLP_CLAMP_NUM)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.clamp: unknown (see fovlp_clamp)");
    if (fov__is0(c.taa.clip_gamma)) c.taa.clip_gamma = 1.0f;
    if (fov__is0(c.taa.depth_tol)) c.taa.depth_tol = 0.02f;
    if (fov__is0(c.taa.reset_deg)) c.taa.reset_deg = 2.0f;
    {
        const float *t = c.taa.frustum;
        int any = !fov__is0(t[0]) || !fov__is0(t[1]) || !fov__is0(t[2]) || !fov__is0(t[3]);
        if (!fov__finite(t[0]) || !fov__finite(t[1]) || !fov__finite(t[2]) || !fov__finite(t[3]))
            FOVLP__FAIL(lg, FOV_ERR_NOT_FINITE, "config.taa.frustum[] NaN or infinite");
        if (any && (!(t[0] + t[1] > 1e-6f) || !(t[2] + t[3] > 1e-6f) || t[0] > 1e6f ||
                    t[1] > 1e6f || t[2] > 1e6f || t[3] > 1e6f))
            FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config.taa.frustum: left + right and bottom + "
                        "top must exceed 1e-6, each at most 1e6");
        if (any && c.width > 0 && c.height > 0 &&
            !fov__tan_aspect_ok(t[0], t[1], t[2], t[3], c.width, c.height))
            FOVLP__FAIL(lg, FOV_ERR_UNSUPPORTED,
                        "config.taa.frustum: (left + right) / (bottom + top) must be width / "
                        "height within 1e-3 (non-square pixels are not supported)");
    }
    if (fov__is0(c.taa.periphery)) c.taa.periphery = 1.0f / 3.0f;
    *out = c;
    return FOV_OK;
}

FOVLP_API fovlp_config fovlp_config_preset(uint32_t preset, uint32_t width, uint32_t height)
{
    /* Table 5.1 of the thesis */
    static const float tab[4][4] = {
        { 0.75f, 1.0f, 0.0f, 1.2f }, { 1.0f, 3.0f, 0.0f, 0.70f },
        { 1.4f, 1.0f, 0.20f, 0.33f }, { 1.3f, 2.0f, 0.15f, 0.35f } };
    fovlp_config c = fovlp_config_default();
    c.width = width;
    c.height = height;
    if (preset < (uint32_t)_FOVLP_PRESET_NUM) {
        c.sigma = tab[preset][0];
        c.alpha = tab[preset][1];
        c.gaze_angle = tab[preset][2];
        c.no_disc = c.gaze_angle > 0.0f ? 0u : 1u;
        c.lp_aspect = tab[preset][3];
    }
    return c;
}

FOVLP_API fovlp_config fovlp_config_default(void)
{
    fovlp_config c;
    fov_result r;
    FOV_MEMSET(&c, 0, sizeof c);
    r = fovlp__resolve(&c, &c); /* all zero resolves: the defaults */
    FOV_ASSERT(r == FOV_OK);
    (void)r;
    return c;
}

FOVLP_API fov_result fovlp_config_resolve(const fovlp_config *in, fovlp_config *out)
{
    fovlp_config c;
    fov_result r = FOV_OK;
    if (!in) return FOV_ERR_NULL;
    if (!out) FOVLP__FAIL(&in->logger, FOV_ERR_NULL, "config_resolve: out is NULL");
    if (in->width == 0 || in->height == 0)
        FOVLP__FAIL(&in->logger, FOV_ERR_INVALID_ARG, "config.width and height must be >= 1");
    if (in->width > FOVLP_MAX_DIM || in->height > FOVLP_MAX_DIM)
        FOVLP__FAIL(&in->logger, FOV_ERR_LIMIT, "config.width or height above FOVLP_MAX_DIM");
    r = fovlp__resolve(in, &c);
    if (r != FOV_OK) return r;
    *out = c;
    return FOV_OK;
}

/* ---- eccentricity (the shared model; identical to fovsdf_ecc_*) --------------------------- */
FOVLP_API fov_result fovlp_ecc_init(fov_ecc_model *m, const fov_display *d, float fov_y_deg,
                                    uint32_t w, uint32_t h, fov_gaze g)
{ return fov__ecc_init(m, d, fov_y_deg, w, h, g, FOVLP_MAX_DIM); }
FOVLP_API float fovlp_ecc_deg(const fov_ecc_model *m, float x, float y)
{ return fov__ecc_deg(m, x, y); }
FOVLP_API float fovlp_ecc_ppd(const fov_ecc_model *m)
{ return fov__ecc_ppd(m); }
FOVLP_API float fovlp_eye_mar(const fov_eye *eye, float ecc_deg)
{ return fov__eye_mar(eye, ecc_deg); }
FOVLP_API float fovlp_eye_density(const fov_eye *eye, float ppd, float ecc_deg)
{ return fov__eye_density(eye, ppd, ecc_deg); }
FOVLP_API float fovlp_eye_ecc(const fov_eye *eye, float ppd, float density)
{ return fov__eye_ecc(eye, ppd, density); }
FOVLP_API fov_result fovlp_eye_plan(const fov_eye *eye, const fov_ecc_model *m,
                                    fov_eye_plan *plan)
{ return fov__eye_plan(eye, m, plan); }

/* ---- gaze input (GAZE INPUT; the shared fov__gaze_*) ------------------------------------- */
FOVLP_API fov_gaze_filter_config fovlp_gaze_filter_config_default(void)
{
    fov_gaze_filter_config c;
    const char *bad;
    FOV_MEMSET(&c, 0, sizeof c);
    (void)fov__gaze_cfg(0, &c, &bad);
    return c;
}
FOVLP_API fov_result fovlp_gaze_filter_init(fov_gaze_filter *f, const fov_gaze_filter_config *cfg)
{
    fov_gaze_filter_config c;
    const char *bad;
    fov_result r;
    if (!f) {
        if (cfg)
            return fov__err(&cfg->logger, "fovlp", FOV_ERR_NULL,
                            FOV__MSG("gaze_filter_init: f is NULL"), (uint32_t)__LINE__);
        return FOV_ERR_NULL;
    }
    r = fov__gaze_cfg(cfg, &c, &bad);
    if (r != FOV_OK) return cfg ? fov__err(&cfg->logger, "fovlp", r, bad, (uint32_t)__LINE__) : r;
    FOV_MEMSET(f, 0, sizeof *f);
    f->cfg = c;
    return FOV_OK;
}
FOVLP_API void fovlp_gaze_filter_reset(fov_gaze_filter *f)
{
    if (f) fov__gaze_reset(f);
}
FOVLP_API fov_result fovlp_gaze_filter_push(fov_gaze_filter *f, uint64_t t_us, float x_deg,
                                            float y_deg)
{
    const char *bad;
    fov_result r;
    if (!f) return FOV_ERR_NULL;
    r = fov__gaze_push(f, t_us, x_deg, y_deg, &bad);
    return r == FOV_OK ? r : fov__err(&f->cfg.logger, "fovlp", r, bad, (uint32_t)__LINE__);
}
FOVLP_API fov_result fovlp_gaze_filter_push_px(fov_gaze_filter *f, const fov_ecc_model *m,
                                               uint64_t t_us, fov_gaze raw, fov_gaze *out)
{
    const char *bad;
    fov_result r;
    if (!f) return FOV_ERR_NULL;
    if (!m)
        return fov__err(&f->cfg.logger, "fovlp", FOV_ERR_NULL,
                        FOV__MSG("gaze_filter_push_px: m is NULL"), (uint32_t)__LINE__);
    r = fov__gaze_push_px(f, m, t_us, raw, out, &bad);
    return r == FOV_OK ? r : fov__err(&f->cfg.logger, "fovlp", r, bad, (uint32_t)__LINE__);
}
FOVLP_API fov_result fovlp_gaze_to_deg(const fov_ecc_model *m, fov_gaze px, float deg[2])
{
    if (!m || !deg) return FOV_ERR_NULL;
    if (!fov__finite(px.x) || !fov__finite(px.y)) return FOV_ERR_NOT_FINITE;
    return fov__gaze_to_deg(m, px.x, px.y, deg) ? FOV_OK : FOV_ERR_INVALID_ARG;
}
FOVLP_API fov_result fovlp_gaze_from_deg(const fov_ecc_model *m, const float deg[2], fov_gaze *px)
{
    fov_gaze g;
    if (!m || !deg || !px) return FOV_ERR_NULL;
    if (!fov__finite(deg[0]) || !fov__finite(deg[1])) return FOV_ERR_NOT_FINITE;
    if (!fov__gaze_from_deg(m, deg, &g.x, &g.y)) return FOV_ERR_INVALID_ARG;
    *px = g;
    return FOV_OK;
}
FOVLP_API fov_result fovlp_gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                       float latency_ms, float *margin_deg)
{
    fov_result r = fov__gaze_margin(f, accuracy_deg, latency_ms, margin_deg);
    if (r == FOV_OK || !f) return r;
    return fov__err(&f->cfg.logger, "fovlp", r,
                    margin_deg ? FOV__MSG("gaze_margin: accuracy_deg must be in [0, 90] and "
                                          "latency_ms in [0, 1e6], finite (*margin_deg: the cap)")
                               : FOV__MSG("gaze_margin: margin_deg is NULL"),
                    (uint32_t)__LINE__);
}
FOVLP_API fov_result fovlp_gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                        float latency_ms, fov_gaze_prediction *out)
{
    fov_result r = fov__gaze_predict(f, accuracy_deg, latency_ms, out);
    if (r == FOV_OK || !f) return r;
    return fov__err(&f->cfg.logger, "fovlp", r,
                    out ? FOV__MSG("gaze_predict: accuracy_deg must be in [0, 90] and "
                                   "latency_ms in [0, 1e6], finite (*out: the filtered gaze "
                                   "and the cap)")
                        : FOV__MSG("gaze_predict: out is NULL"),
                    (uint32_t)__LINE__);
}
FOVLP_API fov_result fovlp_gaze_fixed(const fov_display *display, uint32_t width,
                                      uint32_t height, fov_gaze *out)
{
    float dx = display ? display->axis_dx : 0.0f, dy = display ? display->axis_dy : 0.0f;
    if (!out) return FOV_ERR_NULL;
    if (width == 0 || height == 0) return FOV_ERR_INVALID_ARG;
    if (!fov__finite(dx) || !fov__finite(dy)) return FOV_ERR_NOT_FINITE;
    out->x = 0.5f * (float)width + dx;
    out->y = 0.5f * (float)height + dy;
    return FOV_OK;
}
FOVLP_API fov_result fovlp_camera_display(const fov_camera *cam, fov_display *out)
{
    fov_display d;
    fov_result r = fov__camera_display(cam, &d);
    if (r == FOV_OK && out) *out = d;
    return out ? r : FOV_ERR_NULL;
}
FOVLP_API fov_result fovlp_config_gaze_margin(const fovlp_config *base, float margin_deg,
                                              fovlp_config *out)
{
    fovlp_config c;
    fov_result r;
    if (!base || !out) return FOV_ERR_NULL;
    if (!fov__finite(margin_deg))
        FOVLP__FAIL(&base->logger, FOV_ERR_NOT_FINITE,
                    "config_gaze_margin: margin NaN or infinite");
    if (margin_deg < 0.0f)
        FOVLP__FAIL(&base->logger, FOV_ERR_INVALID_ARG,
                    "config_gaze_margin: margin must be >= 0");
    r = fovlp_config_resolve(base, &c);
    if (r != FOV_OK) return r;
    if (c.no_disc)
        FOVLP__FAIL(&base->logger, FOV_ERR_UNSUPPORTED,
                    "config_gaze_margin: no_disc = 1, no full-quality disc to widen");
    c.gaze_angle += margin_deg * FOV__DEG;
    if (!(c.gaze_angle < 1.5f))
        FOVLP__FAIL(&base->logger, FOV_ERR_LIMIT,
                    "config_gaze_margin: gaze_angle plus the margin reaches 1.5 radians");
    *out = c;
    return FOV_OK;
}

/* ---- geometry (eqs. 3.3-3.6, 3.10) -------------------------------------------------------- */
/* The camera field of view handed to the eccentricity model when the display is all zero:
   cfg.cam_fov_y_deg, else the thesis's viewing distance d = diagonal / tan 60 degrees. */
FOVLP__PRIV float fovlp__view_fov(const fovlp_config *c)
{
    float diag, d;
    if (c->cam_fov_y_deg > 0.0f) return c->cam_fov_y_deg;
    diag = FOV__SQRT((float)c->width * (float)c->width + (float)c->height * (float)c->height);
    d = diag / 1.73205081f;
    return 2.0f * FOV__ATAN2(0.5f * (float)c->height, d) / FOV__DEG;
}

FOVLP__PRIV fov_gaze fovlp__clamp_gaze(const fovlp_config *c, fov_gaze g, int *clamped)
{
    fov_gaze o;
    o.x = fov__clampf(g.x, 0.0f, (float)c->width);
    o.y = fov__clampf(g.y, 0.0f, (float)c->height);
    *clamped = fovlp__neq(o.x, g.x) || fovlp__neq(o.y, g.y);
    return o;
}

FOVLP__PRIV float fovlp__far_corner(const fovlp_config *c, fov_gaze g)
{
    float dx = fov__maxf(g.x, (float)c->width - g.x), dy = fov__maxf(g.y, (float)c->height - g.y);
    return FOV__SQRT(dx * dx + dy * dy);
}

/* Sizes (fixed for a config) and the gaze-dependent part. c must be resolved with valid
   width/height; ecc must be initialised for gaze (gives f_px). */
FOVLP__PRIV fov_result fovlp__geometry2(const fovlp_config *c, fov_gaze gaze, float f_px,
                                        float disc_angle, fovlp_geometry *g)
{
    const fov_logger *lg = &c->logger;
    float W = (float)c->width, H = (float)c->height;
    float diag = FOV__SQRT(W * W + H * H);
    float L_diag = FOV__LOG(fov__maxf(diag, 2.0f));
    float L, r_g, G, G_diag, asp, hf, wf, rmax, xm;
    uint32_t S;
    size_t slots, lp;
    FOV_MEMSET(g, 0, sizeof *g);
    g->width = c->width;
    g->height = c->height;
    g->f_px = f_px;
    /* eq. 3.3: the gaze disc radius */
    r_g = c->gaze_angle > 0.0f ? f_px * FOV__TAN(c->gaze_angle) : 0.0f;
    if (!fov__finite(r_g))
        FOVLP__FAIL(lg, FOV_ERR_DEGENERATE, "geometry: gaze disc radius overflows");
    /* eq. 3.4 with the diagonal normaliser, for the sizes */
    xm = c->edge == FOVLP_EDGE_THESIS ? r_g + 1.0f : r_g;
    G_diag = r_g > 0.0f ? fovlp__pow(FOV__LOG(fov__maxf(xm, 1.0f)) / L_diag, c->alpha) : 0.0f;
    if (G_diag >= 0.999f)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG,
                    "geometry: gaze disc covers the screen (gaze_angle too large)");
    /* eq. 3.6, or the aspect that matches the spacings at match_deg (section 5.1 tuning) */
    asp = c->lp_aspect;
    if (!(asp > 0.0f)) {
        float r_ref = f_px * FOV__TAN(c->match_deg * FOV__DEG);
        float x = FOV__LOG(fov__maxf(r_ref, 2.0f)) / L_diag;
        float t = fov__clampf(fovlp__pow(fov__minf(x, 1.0f), c->alpha), 1e-3f, 1.0f);
        float k = L_diag * fovlp__pow(t, 1.0f / c->alpha - 1.0f) / (FOVLP__TWO_PI * c->alpha);
        asp = fov__clampf(k * (1.0f - G_diag), 1.0f / 65536.0f, 65536.0f);
    }
    g->lp_aspect = asp;
    hf = FOV__FLOOR(FOV__SQRT(W * H / asp) / c->sigma + 0.5f);
    if (!(hf <= (float)FOVLP_MAX_LP_DIM))
        FOVLP__FAIL(lg, FOV_ERR_LIMIT, "geometry: LP buffer height above FOVLP_MAX_LP_DIM");
    if (hf < 1.0f) hf = 1.0f;
    wf = FOV__FLOOR(hf * asp + 0.5f);
    if (!(wf <= (float)FOVLP_MAX_LP_DIM))
        FOVLP__FAIL(lg, FOV_ERR_LIMIT, "geometry: LP buffer width above FOVLP_MAX_LP_DIM");
    if (wf < 1.0f) wf = 1.0f;
    g->lp_w = (uint32_t)wf;
    g->lp_h = (uint32_t)hf;
    /* disc buffer: covers the square of any gaze position */
    S = 0;
    if (r_g > 0.0f) {
        float s = 2.0f * r_g + 2.0f, m = fov__maxf(W, H);
        S = s >= m ? (uint32_t)m : fovlp__ceil_u(s, FOVLP_MAX_DIM);
    }
    g->disc_side = S;
    /* the disc actually used (fovlp_set_gaze_margin): at most the sized one, same buffers */
    if (disc_angle >= 0.0f && disc_angle < c->gaze_angle && r_g > 0.0f) {
        r_g = disc_angle > 0.0f ? f_px * FOV__TAN(disc_angle) : 0.0f;
        xm = c->edge == FOVLP_EDGE_THESIS ? r_g + 1.0f : r_g;
    }
    g->disc_cols = S < c->width ? S : c->width;
    g->disc_rows = S < c->height ? S : c->height;
    lp = (size_t)g->lp_w * (size_t)g->lp_h;
    slots = lp + (size_t)g->disc_cols * (size_t)g->disc_rows + 1u;
    if (lp / g->lp_w != g->lp_h || slots > (size_t)FOVLP_MAX_SAMPLES || slots < lp)
        FOVLP__FAIL(lg, FOV_ERR_LIMIT, "geometry: sample slots above FOVLP_MAX_SAMPLES");
    g->lp_slots = (uint32_t)lp;
    g->disc_offset = (uint32_t)lp;
    g->centre_slot = (uint32_t)(lp + (size_t)g->disc_cols * (size_t)g->disc_rows);
    g->samples = (uint32_t)slots;
    /* the gaze-dependent part */
    rmax = fovlp__far_corner(c, gaze);
    L = c->norm == FOVLP_NORM_CORNER ? FOV__LOG(fov__maxf(rmax, 2.0f)) : L_diag;
    g->L = L;
    g->r_g = r_g;
    G = r_g > 0.0f ? fovlp__pow(FOV__LOG(fov__maxf(xm, 1.0f)) / L, c->alpha) : 0.0f;
    if (G >= 0.999f)
        FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "geometry: gaze disc covers the screen at this gaze");
    g->G = G;
    g->u_g = (float)g->lp_w * G / (1.0f - G);
    g->w_c = (float)g->lp_w + g->u_g;
    g->u_max = fovlp__pow(FOV__LOG(fov__maxf(rmax, 1.0f)) / L, c->alpha) * g->w_c - g->u_g;
    g->lp_cols = fovlp__ceil_u(g->u_max, g->lp_w);
    if (g->lp_cols < 1) g->lp_cols = 1;
    if (S > 0) {
        float x0 = fov__maxf(0.0f, FOV__FLOOR(gaze.x - r_g));
        float y0 = fov__maxf(0.0f, FOV__FLOOR(gaze.y - r_g));
        uint32_t x1 = fovlp__ceil_u(gaze.x + r_g, c->width),
            y1 = fovlp__ceil_u(gaze.y + r_g, c->height);
        g->disc_x0 = (uint32_t)x0;
        g->disc_y0 = (uint32_t)y0;
        g->disc_w = x1 > g->disc_x0 ? x1 - g->disc_x0 : 0;
        g->disc_h = y1 > g->disc_y0 ? y1 - g->disc_y0 : 0;
        if (g->disc_w > g->disc_cols) g->disc_w = g->disc_cols;
        if (g->disc_h > g->disc_rows) g->disc_h = g->disc_rows;
    }
    return FOV_OK;
}

FOVLP__PRIV fov_result fovlp__geometry(const fovlp_config *c, fov_gaze gaze, float f_px,
                                       fovlp_geometry *g)
{
    return fovlp__geometry2(c, gaze, f_px, -1.0f, g);
}

/* disc_angle: the disc used (<= the config's gaze_angle, which sizes the buffers); < 0: the
   config's */
FOVLP__PRIV fov_result fovlp__setup2(const fovlp_config *cfg, fov_gaze gaze, float disc_angle,
                                     fovlp_config *c, fov_ecc_model *ecc, fov_gaze *gz,
                                     fovlp_geometry *g)
{
    fov_result r;
    int clamped;
    if (!cfg) return FOV_ERR_NULL;
    r = fovlp_config_resolve(cfg, c);
    if (r != FOV_OK) return r;
    if (!fov__finite(gaze.x) || !fov__finite(gaze.y))
        FOVLP__FAIL(&c->logger, FOV_ERR_NOT_FINITE, "gaze.x or gaze.y NaN or infinite");
    *gz = fovlp__clamp_gaze(c, gaze, &clamped);
    if (clamped && c->logger.func)
        c->logger.func("fovlp", FOV_LOG_WARN, (int32_t)FOV_OK, FOV__MSG("gaze off-screen: clamped"),
                       (uint32_t)__LINE__, c->logger.user);
    r = fovlp_ecc_init(ecc, &c->display, fovlp__view_fov(c), c->width, c->height, *gz);
    if (r != FOV_OK)
        FOVLP__FAIL(&c->logger, r, "gaze or config.display: the eye direction overflows");
    return fovlp__geometry2(c, *gz, ecc->f_px, disc_angle, g);
}
FOVLP__PRIV fov_result fovlp__setup(const fovlp_config *cfg, fov_gaze gaze, fovlp_config *c,
                                    fov_ecc_model *ecc, fov_gaze *gz, fovlp_geometry *g)
{
    return fovlp__setup2(cfg, gaze, -1.0f, c, ecc, gz, g);
}

FOVLP_API fov_result fovlp_geometry_get(const fovlp_config *cfg, fov_gaze gaze, fovlp_geometry *out)
{
    fovlp_config c;
    fov_ecc_model e;
    fov_gaze gz;
    if (!cfg) return FOV_ERR_NULL;
    if (!out) FOVLP__FAIL(&cfg->logger, FOV_ERR_NULL, "geometry_get: out is NULL");
    return fovlp__setup(cfg, gaze, &c, &e, &gz, out);
}

/* ---- acuity-driven configuration (fovlp_config_acuity) ------------------------------------ */
/* The design model (see the doc block, ACUITY-DRIVEN CONFIGURATION): the gaze on the display's
   axis, a point r pixels from it at the eccentricity e(r) = atan(r / f), the eye's allowed
   sample spacing there s(r) = quality MAR(e(r)) ppd pixels (ppd the plan's, the coarsest),
   for r from the disc edge r_G to R = the screen diagonal (the farthest corner from any gaze
   on the screen), with the normaliser L = log(diagonal). */
#define FOVLP__AC_N 64            /* radius nodes of the search */
typedef struct fovlp__acm {
    const fov_eye *eye;
    float f, ppd, L, R, W, H;
} fovlp__acm;
/* s(r): the eye's allowed spacing in pixels at radius r */
FOVLP__PRIV float fovlp__ac_s(const fovlp__acm *a, float r)
{
    float e = FOV__ATAN2(r, a->f) * (180.0f / FOV__PI);
    return fov__eye_mar(a->eye, e) * a->ppd;
}
/* fraction of the circle of radius rho about the screen centre that lies on the screen */
FOVLP__PRIV float fovlp__ac_frac(const fovlp__acm *a, float rho)
{
    float hw = 0.5f * a->W, hh = 0.5f * a->H, out = 0.0f;
    if (rho * rho >= hw * hw + hh * hh) return 0.0f;
    if (rho > hh) out += FOV__ATAN2(FOV__SQRT(rho * rho - hh * hh), hh);
    if (rho > hw) out += FOV__ATAN2(FOV__SQRT(rho * rho - hw * hw), hw);
    return fov__maxf(0.0f, 1.0f - out * (2.0f / FOV__PI));
}
/* the screen pixels within rho of the screen centre (the disc of a centred gaze) */
FOVLP__PRIV float fovlp__ac_disc_area(const fovlp__acm *a, float rho)
{
    float hw = 0.5f * a->W, hh = 0.5f * a->H, c = FOV__PI * rho * rho, sa = c, sb = c;
    if (rho * rho >= hw * hw + hh * hh) return a->W * a->H;
    if (rho > hh) /* the circle inside the strip |y| <= hh */
        sb = 2.0f * (hh * FOV__SQRT(rho * rho - hh * hh) +
                     rho * rho * FOV__ATAN2(hh, FOV__SQRT(rho * rho - hh * hh)));
    if (rho > hw)
        sa = 2.0f * (hw * FOV__SQRT(rho * rho - hw * hw) +
                     rho * rho * FOV__ATAN2(hw, FOV__SQRT(rho * rho - hw * hw)));
    return fov__maxf(0.0f, sa + sb - c);
}
/* The largest step in t = u_C / w_C that keeps the radial gap from a sample at radius r to
   the next within s(r): (log(r + s(r)) / L)^alpha - (log r / L)^alpha. */
FOVLP__PRIV float fovlp__ac_dt(const fovlp__acm *a, float r, float alpha)
{
    float s = fovlp__ac_s(a, r);
    return fovlp__pow(FOV__LOG(r + s) / a->L, alpha) - fovlp__pow(FOV__LOG(r) / a->L, alpha);
}
/* w_C (radial) and h (angular) that meet the eye from r_g to R, on n log-spaced radii */
FOVLP__PRIV void fovlp__ac_need(const fovlp__acm *a, float r_g, float alpha, uint32_t n,
                                float *w_c, float *h)
{
    float dmin = FLT_MAX, hmax = 0.0f, lr = FOV__LOG(a->R / r_g);
    uint32_t k;
    for (k = 0; k <= n; ++k) {
        float r = k == n ? a->R : r_g * FOV__EXP(lr * (float)k / (float)n);
        float d = fovlp__ac_dt(a, r, alpha), q = FOVLP__TWO_PI * r / fovlp__ac_s(a, r);
        if (d < dmin) dmin = d;
        if (q > hmax) hmax = q;
    }
    *w_c = dmin > 0.0f ? 1.0f / dmin : FLT_MAX;
    *h = hmax;
}

/* The worst ratio of a gap between neighbouring samples to the eye's allowed spacing, for the
   geometry g of the config c (the sample radii of begin_frame's table, exp(L ((i + o + u_G) /
   w_C)^(1 / alpha)), at offsets o = 0, 1/4, .. 1 of every column, and the arcs 2 pi r / h).
   *rad and *ang get the radial and angular worst ratios. */
FOVLP__PRIV void fovlp__ac_check(const fovlp__acm *a, const fovlp_config *c,
                                 const fovlp_geometry *g, float *rad, float *ang)
{
    uint32_t i, j;
    float ia = 1.0f / c->alpha;
    *rad = *ang = 0.0f;
    for (i = 0; i < g->lp_w; ++i) {
        for (j = 0; j < 4u; ++j) {
            float u = (float)i + 0.25f * (float)j;
            float r0 = FOV__EXP(g->L * fovlp__pow((u + g->u_g) / g->w_c, ia));
            float r1 = FOV__EXP(g->L * fovlp__pow((u + 1.0f + g->u_g) / g->w_c, ia));
            float s0;
            if (r0 > a->R) break;
            s0 = fovlp__ac_s(a, fov__maxf(r0, g->r_g));
            *rad = fov__maxf(*rad, (r1 - r0) / s0);
            *ang = fov__maxf(*ang, FOVLP__TWO_PI * r0 / ((float)g->lp_h * s0));
        }
        if (j < 4u) break;
    }
    *ang = fov__maxf(*ang, FOVLP__TWO_PI * a->R / ((float)g->lp_h * fovlp__ac_s(a, a->R)));
}


FOVLP_API fov_result fovlp_config_acuity(fovlp_config *cfg, const fovlp_camera *cam,
                                         const fov_eye *eye)
{
    fovlp_config c, t;
    fov_ecc_model m;
    fov_eye_plan plan;
    fovlp__acm a;
    fovlp_geometry g;
    fov_gaze gz;
    fov_result r;
    const fov_logger *lg;
    float lq[FOVLP__AC_N], lqs[FOVLP__AC_N], fr[FOVLP__AC_N];
    float r_lo, r_cap, best = FLT_MAX, b_alpha = 1.0f, b_rg = 0.0f, w_c, hf, rad, ang;
    uint32_t k, k0, w, h, it;
    int disp0;
    if (!cfg) return FOV_ERR_NULL;
    lg = &cfg->logger;
    r = fov__eye_check(lg, "fovlp", "config_acuity: ", eye);
    if (r != FOV_OK) return r;
    t = *cfg;
    disp0 = fov__is0(t.display.fov_y_deg) && fov__is0(t.display.pixel_pitch_mm) &&
            fov__is0(t.display.distance_mm);
    if (cam) {
        if (!fov__finite(cam->tan_half_y))
            FOVLP__FAIL(lg, FOV_ERR_NOT_FINITE, "config_acuity: cam.tan_half_y NaN or infinite");
        if (!(cam->tan_half_y > 0.0f) || cam->tan_half_y > 1e6f)
            FOVLP__FAIL(lg, FOV_ERR_INVALID_ARG, "config_acuity: cam.tan_half_y must be in "
                                                 "(0, 1e6] (a field of view in (0, 180))");
        if (disp0) t.cam_fov_y_deg = 2.0f * FOV__ATAN2(cam->tan_half_y, 1.0f) / FOV__DEG;
    }
    t.norm = FOVLP_NORM_DIAGONAL;
    t.edge = FOVLP_EDGE_LOG_R;
    r = fovlp_config_resolve(&t, &c);
    if (r != FOV_OK) return r;
    gz.x = 0.5f * (float)c.width + c.display.axis_dx; /* the gaze on the display's axis */
    gz.y = 0.5f * (float)c.height + c.display.axis_dy;
    r = fovlp_ecc_init(&m, &c.display, fovlp__view_fov(&c), c.width, c.height, gz);
    if (r == FOV_OK) r = fovlp_eye_plan(eye, &m, &plan);
    if (r != FOV_OK)
        FOVLP__FAIL(lg, r, "config_acuity: config.display or cam gives no eccentricity model");
    a.eye = eye;
    a.f = m.f_px;
    a.ppd = plan.ppd;
    a.W = (float)c.width;
    a.H = (float)c.height;
    a.R = FOV__SQRT(a.W * a.W + a.H * a.H);
    a.L = FOV__LOG(fov__maxf(a.R, 2.0f));
    /* the disc: at least where the eye needs every pixel (e_full), at most q = 0.98 */
    r_lo = plan.e_full < 89.0f ? a.f * FOV__TAN(plan.e_full * FOV__DEG) * 1.0001f + 0.01f
                               : FLT_MAX;
    r_lo = fov__maxf(r_lo, 1.5f);
    r_cap = fov__minf(FOV__EXP(0.98f * a.L), fov__minf(0.5f * a.R, a.f * 14.0f));
    if (!(r_lo < r_cap))
        FOVLP__FAIL(lg, FOV_ERR_UNSUPPORTED,
                    "config_acuity: the eye needs every pixel of the screen (no log-polar "
                    "reduction: trace every pixel)");
    /* the search: nodes r_k log-spaced on [r_lo, R]; candidates r_G = r_k up to r_cap and
       alpha in [1, 8] by 1/4, then alpha refined by 1/32. Per candidate: w_C from the radial
       rule at the nodes, h from the arcs (the same for every candidate), and the samples a
       centred gaze shades: the disc's pixels plus h w_C times the on-screen part of d(q^alpha). */
    for (k = 0; k < FOVLP__AC_N; ++k) {
        float rk = r_lo * FOV__EXP(FOV__LOG(a.R / r_lo) * (float)k / (float)(FOVLP__AC_N - 1));
        float sk = fovlp__ac_s(&a, rk);
        lq[k] = FOV__LOG(FOV__LOG(rk) / a.L);
        lqs[k] = FOV__LOG(FOV__LOG(rk + sk) / a.L);
        fr[k] = fovlp__ac_frac(&a, rk);
    }
    fovlp__ac_need(&a, r_lo, 1.0f, 256u, &w_c, &hf);
    for (it = 0; it < 2u; ++it) {
        float a0 = it == 0 ? 1.0f : fov__maxf(1.0f, b_alpha - 0.25f);
        float a1 = it == 0 ? 8.0f : fov__minf(8.0f, b_alpha + 0.25f);
        float da = it == 0 ? 0.25f : 0.03125f, al;
        for (al = a0; al <= a1 + 1e-4f; al += da) {
            for (k0 = 0; k0 < FOVLP__AC_N - 1u; ++k0) {
                float rg = r_lo * FOV__EXP(FOV__LOG(a.R / r_lo) * (float)k0 /
                                           (float)(FOVLP__AC_N - 1));
                float dmin = FLT_MAX, acc = 0.0f, prev, cost;
                if (rg > r_cap) break;
                if (it == 1 && fovlp__neq(rg, b_rg)) continue;
                prev = FOV__EXP(al * lq[k0]);
                for (k = k0; k < FOVLP__AC_N; ++k) {
                    float pk = FOV__EXP(al * lq[k]), d = FOV__EXP(al * lqs[k]) - pk;
                    if (d < dmin) dmin = d;
                    if (k > k0) acc += (pk - prev) * 0.5f * (fr[k] + fr[k - 1]);
                    prev = pk;
                }
                if (!(dmin > 0.0f)) continue;
                cost = fovlp__ac_disc_area(&a, rg) + hf * acc / dmin;
                if (cost < best) { best = cost; b_alpha = al; b_rg = rg; }
            }
        }
    }
    if (!(b_rg > 0.0f))
        FOVLP__FAIL(lg, FOV_ERR_DEGENERATE, "config_acuity: no log-polar buffer meets the eye");
    /* the buffer for the choice, checked on the geometry fovlp_init derives from the config
       (the sample radii begin_frame tabulates); grown until every gap meets the eye */
    fovlp__ac_need(&a, b_rg, b_alpha, 1024u, &w_c, &hf);
    {
        float G = fovlp__pow(FOV__LOG(b_rg) / a.L, b_alpha);
        w = fovlp__ceil_u(w_c * (1.0f - G), FOVLP_MAX_LP_DIM);
        h = fovlp__ceil_u(hf, FOVLP_MAX_LP_DIM);
    }
    for (it = 0; it < 16u; ++it) {
        float asp;
        if (w < 1u) w = 1u;
        if (h < 1u) h = 1u;
        if (w >= FOVLP_MAX_LP_DIM || h >= FOVLP_MAX_LP_DIM)
            FOVLP__FAIL(lg, FOV_ERR_LIMIT,
                        "config_acuity: the buffer the eye needs is above FOVLP_MAX_LP_DIM");
        asp = (float)w / (float)h;
        t = c;
        t.lp_aspect = asp;
        t.sigma = FOV__SQRT(a.W * a.H / asp) / (float)h;
        t.alpha = b_alpha;
        t.gaze_angle = FOV__ATAN2(b_rg, a.f);
        t.no_disc = 0;
        r = fovlp__geometry(&t, gz, a.f, &g);
        if (r != FOV_OK) return r;
        fovlp__ac_check(&a, &t, &g, &rad, &ang);
        if (g.lp_h >= h && g.lp_w >= w && rad <= 1.0f && ang <= 1.0f && g.r_g >= r_lo - 0.01f)
            break;
        if (g.r_g < r_lo - 0.01f) b_rg *= 1.0001f;
        if (g.lp_w < w || rad > 1.0f)
            w = fovlp__ceil_u((float)w * fov__maxf(rad, 1.0f), FOVLP_MAX_LP_DIM) + 1u;
        if (g.lp_h < h || ang > 1.0f)
            h = fovlp__ceil_u((float)h * fov__maxf(ang, 1.0f), FOVLP_MAX_LP_DIM) + 1u;
    }
    if (it == 16u)
        FOVLP__FAIL(lg, FOV_ERR_DEGENERATE, "config_acuity: the buffer did not meet the eye");
    cfg->sigma = t.sigma;
    cfg->alpha = t.alpha;
    cfg->gaze_angle = t.gaze_angle;
    cfg->no_disc = 0;
    cfg->lp_aspect = t.lp_aspect;
    cfg->norm = FOVLP_NORM_DIAGONAL;
    cfg->edge = FOVLP_EDGE_LOG_R;
    cfg->recon = FOVLP_RECON_CUBIC;
    if (cam && disp0) cfg->cam_fov_y_deg = t.cam_fov_y_deg;
    return FOV_OK;
}

/* ---- context ------------------------------------------------------------------------------ */
FOVLP__PRIV size_t fovlp__mem_bytes(const fovlp_geometry *g)
{
    return fov__align(sizeof(float) * (size_t)g->lp_w) +
           2u * fov__align(sizeof(float) * (size_t)g->lp_h);
}

FOVLP_API fov_result fovlp_memory_size(const fovlp_config *cfg, size_t *bytes)
{
    fovlp_geometry g;
    fov_gaze gz;
    fov_result r;
    if (!cfg) return FOV_ERR_NULL;
    if (!bytes) FOVLP__FAIL(&cfg->logger, FOV_ERR_NULL, "memory_size: bytes is NULL");
    gz.x = 0.5f * (float)cfg->width;
    gz.y = 0.5f * (float)cfg->height;
    r = fovlp_geometry_get(cfg, gz, &g);
    if (r != FOV_OK) return r;
    *bytes = fovlp__mem_bytes(&g) + 16u; /* + alignment slack */
    return FOV_OK;
}

FOVLP_API fov_result fovlp_init(fovlp_ctx *ctx, const fovlp_config *cfg, void *mem, size_t mem_size)
{
    fovlp_config c;
    fov_ecc_model e;
    fov_gaze gz;
    fovlp_geometry g;
    fov_result r;
    size_t need;
    unsigned char *p;
    if (!cfg) return FOV_ERR_NULL;
    if (!ctx) FOVLP__FAIL(&cfg->logger, FOV_ERR_NULL, "init: ctx is NULL");
    gz.x = 0.5f * (float)cfg->width;
    gz.y = 0.5f * (float)cfg->height;
    r = fovlp__setup(cfg, gz, &c, &e, &gz, &g);
    if (r != FOV_OK) return r;
    need = fovlp__mem_bytes(&g) + 16u;
    if (!mem)
        FOVLP__FAIL(&c.logger, FOV_ERR_NULL, "init: mem is NULL (size it with fovlp_memory_size)");
    if (mem_size < need)
        FOVLP__FAIL(&c.logger, FOV_ERR_TOO_SMALL, "init: mem_size below fovlp_memory_size");
    FOV_MEMSET(ctx, 0, sizeof *ctx);
    ctx->cfg = c;
    ctx->geo = g;
    ctx->ecc = e;
    ctx->gaze = gz;
    ctx->prev_gaze = gz;
    ctx->L_diag = FOV__LOG(fov__maxf(FOV__SQRT((float)c.width * (float)c.width +
                                                     (float)c.height * (float)c.height), 2.0f));
    p = (unsigned char *)mem;
    p += (16u - (size_t)((uintptr_t)p & 15u)) & 15u;
    ctx->rho = (float *)(void *)p;
    p += fov__align(sizeof(float) * (size_t)g.lp_w);
    ctx->cs = (float *)(void *)p;
    p += fov__align(sizeof(float) * (size_t)g.lp_h);
    ctx->sn = (float *)(void *)p;
    ctx->mem = mem;
    ctx->mem_size = mem_size;
    ctx->jit_u = ctx->jit_v = 0.5f;
    ctx->disc_angle = c.gaze_angle;
    return FOV_OK;
}

FOVLP_API fov_result fovlp_set_gaze_margin(fovlp_ctx *ctx, const fovlp_config *base,
                                           float margin_deg)
{
    fovlp_config b, c;
    fov_ecc_model e;
    fov_gaze gz;
    fovlp_geometry g;
    fov_result r;
    float q, a;
    if (!ctx || !base) return FOV_ERR_NULL;
    if (!ctx->rho || !ctx->cs || !ctx->sn) return FOV_ERR_INVALID_ARG; /* not initialised */
    if (!fov__finite(margin_deg))
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NOT_FINITE,
                    "set_gaze_margin: margin NaN or infinite");
    if (margin_deg < 0.0f)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "set_gaze_margin: margin must be >= 0");
    r = fovlp_config_resolve(base, &b);
    if (r != FOV_OK) return r;
    if (b.no_disc || ctx->cfg.no_disc)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_UNSUPPORTED,
                    "set_gaze_margin: no_disc = 1, no full-quality disc to widen");
    if (b.gaze_angle > ctx->cfg.gaze_angle)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "set_gaze_margin: base.gaze_angle above the context's (init with "
                    "fovlp_config_gaze_margin(base, largest margin))");
    /* up to the next FOVLP__GAZE_STEP_DEG: a margin that wobbles does not move the
       LP samples every frame */
    q = FOV__FLOOR(margin_deg / FOVLP__GAZE_STEP_DEG);
    if (q * FOVLP__GAZE_STEP_DEG < margin_deg) q += 1.0f;
    a = b.gaze_angle + q * FOVLP__GAZE_STEP_DEG * FOV__DEG;
    if (!(a <= ctx->cfg.gaze_angle)) {
        a = ctx->cfg.gaze_angle;
        if (ctx->cfg.logger.func)
            ctx->cfg.logger.func("fovlp", FOV_LOG_WARN, (int32_t)FOV_OK,
                                 FOV__MSG("set_gaze_margin: margin above the context's room: "
                                          "clamped to its disc"),
                                 (uint32_t)__LINE__, ctx->cfg.logger.user);
    }
    /* the geometry at the current gaze must exist (it does: a smaller disc than the sized one) */
    {
        fov_result r2 = fovlp__setup2(&ctx->cfg, ctx->gaze, a, &c, &e, &gz, &g);
        if (r2 != FOV_OK) return r2;
    }
    ctx->disc_angle = a; /* the next begin_frame uses it; the sizes and the history stay */
    return FOV_OK;
}

FOVLP_API void fovlp_reset_history(fovlp_ctx *ctx)
{
    if (!ctx) return;
    ctx->frame = 0;
    ctx->history_valid = 0;
}

/* Radical inverse of n in base b (Halton), from integers. */
FOVLP__PRIV float fovlp__halton(uint32_t n, uint32_t b)
{
    float f = 1.0f, r = 0.0f, inv = 1.0f / (float)b;
    while (n > 0) {
        f *= inv;
        r += f * (float)(n % b);
        n /= b;
    }
    return r;
}

FOVLP_API fov_result fovlp_jitter(const fovlp_config *cfg, uint32_t phase, float *ou, float *ov)
{
    fovlp_config c;
    fov_result r;
    uint32_t k, n;
    float m2 = 0.0f, m3 = 0.0f;
    if (!cfg) return FOV_ERR_NULL;
    if (!ou || !ov) FOVLP__FAIL(&cfg->logger, FOV_ERR_NULL, "jitter: ou and ov are required");
    r = fovlp__resolve(cfg, &c);
    if (r != FOV_OK) return r;
    n = c.taa.phases;
    /* eq. 3.11: scale so the offsets of one cycle average to the texel centre */
    for (k = 0; k < n; ++k) {
        m2 += fovlp__halton(c.taa.halton_start + k, 2);
        m3 += fovlp__halton(c.taa.halton_start + k, 3);
    }
    m2 /= (float)n;
    m3 /= (float)n;
    k = c.taa.halton_start + phase % n;
    *ou = m2 > 0.0f ? fovlp__halton(k, 2) * (0.5f / m2) : 0.5f;
    *ov = m3 > 0.0f ? fovlp__halton(k, 3) * (0.5f / m3) : 0.5f;
    /* the scaling can push an offset to 1 or beyond for some (phases, halton_start), e.g.
       3 phases from index 2: a sample must stay inside its texel / pixel (a disc sample at
       x = W would be off the screen), so offsets are clamped to [0, 1) (the cycle's mean is
       then slightly below 0.5 for those configurations; the defaults never clamp) */
    if (*ou > 0.99999994f) *ou = 0.99999994f;
    if (*ov > 0.99999994f) *ov = 0.99999994f;
    return FOV_OK;
}

FOVLP__PRIV int fovlp__cam_ok(const fovlp_camera *c)
{
    return fov__finite3(c->pos) && fov__finite3(c->right) && fov__finite3(c->up) &&
           fov__finite3(c->fwd) && fov__finite(c->tan_half_y) && fov__finite(c->tan4[0]) &&
           fov__finite(c->tan4[1]) && fov__finite(c->tan4[2]) && fov__finite(c->tan4[3]);
}
FOVLP__PRIV int fovlp__off4(const float t[4])
{
    return !fov__is0(t[0]) || !fov__is0(t[1]) || !fov__is0(t[2]) || !fov__is0(t[3]);
}
/* the tangents the reprojection uses for camera cam: its own (fovlp_camera_from of an
   off-axis fov_camera), else config.taa.frustum; 0 when symmetric */
FOVLP__PRIV int fovlp__cam_tan(const fovlp_camera *cam, const fovlp_config *c, float t[4])
{
    const float *s = fovlp__off4(cam->tan4) ? cam->tan4
                     : fovlp__off4(c->taa.frustum) ? c->taa.frustum : NULL;
    if (!s) return 0;
    t[0] = s[0]; t[1] = s[1]; t[2] = s[2]; t[3] = s[3];
    return 1;
}
FOVLP__PRIV int fovlp__cam_differs(const fovlp_camera *a, const fovlp_camera *b)
{
    int i;
    for (i = 0; i < 3; ++i)
        if (fovlp__neq(a->pos[i], b->pos[i]) || fovlp__neq(a->right[i], b->right[i]) ||
            fovlp__neq(a->up[i], b->up[i]) || fovlp__neq(a->fwd[i], b->fwd[i]))
            return 1;
    for (i = 0; i < 4; ++i)
        if (fovlp__neq(a->tan4[i], b->tan4[i])) return 1;
    return fovlp__neq(a->tan_half_y, b->tan_half_y);
}

FOVLP_API fov_result fovlp_camera_from(const fov_camera *cam, fovlp_camera *out)
{
    float r[3], u[3], f[3], o[3], fov;
    fov_result e;
    int k, off;
    if (!cam || !out) return FOV_ERR_NULL;
    if (!fov__finite(cam->fov_y_deg) || !fov__finite(cam->eye_offset) ||
        !fov__finite(cam->tan_left) || !fov__finite(cam->tan_right) ||
        !fov__finite(cam->tan_bottom) || !fov__finite(cam->tan_top))
        return FOV_ERR_NOT_FINITE;
    off = !fov__is0(cam->tan_left) || !fov__is0(cam->tan_right) ||
          !fov__is0(cam->tan_bottom) || !fov__is0(cam->tan_top);
    if (off && (!(cam->tan_left + cam->tan_right > 1e-6f) ||
                !(cam->tan_bottom + cam->tan_top > 1e-6f) || cam->tan_left > 1e6f ||
                cam->tan_right > 1e6f || cam->tan_bottom > 1e6f || cam->tan_top > 1e6f))
        return FOV_ERR_INVALID_ARG;
    fov = fov__is0(cam->fov_y_deg) ? 60.0f : cam->fov_y_deg;
    if (!off && !(fov > 0.0f && fov < 180.0f)) return FOV_ERR_INVALID_ARG;
    e = fov__camera_basis(cam, r, u, f);
    if (e != FOV_OK) return e;
    for (k = 0; k < 3; ++k) o[k] = cam->pos[k] + r[k] * cam->eye_offset; /* as fovsdf_init */
    if (!fov__finite3(o)) return FOV_ERR_INVALID_ARG;
    for (k = 0; k < 3; ++k) {
        out->pos[k] = o[k];
        out->right[k] = r[k];
        out->up[k] = u[k];
        out->fwd[k] = f[k];
    }
    out->tan_half_y = off ? 0.5f * (cam->tan_bottom + cam->tan_top)
                          : FOV__TAN(0.5f * fov * FOV__DEG);
    out->tan4[0] = off ? cam->tan_left : 0.0f;
    out->tan4[1] = off ? cam->tan_right : 0.0f;
    out->tan4[2] = off ? cam->tan_bottom : 0.0f;
    out->tan4[3] = off ? cam->tan_top : 0.0f;
    return FOV_OK;
}

FOVLP_API fov_result fovlp_begin_frame(fovlp_ctx *ctx, fov_gaze gaze, const fovlp_camera *cam)
{
    fovlp_config c;
    fov_ecc_model e;
    fov_gaze gz;
    fovlp_geometry g;
    fov_result r;
    uint32_t i, moving = 0, jump = 0;
    float ou = 0.5f, ov = 0.5f;
    if (!ctx) return FOV_ERR_NULL;
    if (!ctx->rho || !ctx->cs || !ctx->sn) return FOV_ERR_INVALID_ARG; /* not initialised */
    if (cam) {
        if (!fovlp__cam_ok(cam))
            FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NOT_FINITE,
                        "begin_frame: a cam field NaN or infinite");
        if (!(cam->tan_half_y > 0.0f) || fov__len(cam->fwd) < 0.5f || fov__len(cam->right) < 0.5f ||
            fov__len(cam->up) < 0.5f)
            FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_DEGENERATE,
                        "begin_frame: cam.tan_half_y <= 0 or fwd, right or up not unit");
        if (fovlp__off4(cam->tan4)) {
            const float *t = cam->tan4, *ft = ctx->cfg.taa.frustum;
            if (!(t[0] + t[1] > 1e-6f) || !(t[2] + t[3] > 1e-6f) || t[0] > 1e6f ||
                t[1] > 1e6f || t[2] > 1e6f || t[3] > 1e6f)
                FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                            "begin_frame: cam.tan4 (off-axis tangents): left + right and "
                            "bottom + top must exceed 1e-6, each <= 1e6 (zero them for a "
                            "symmetric camera)");
            if (fovlp__off4(ft) && (fovlp__neq(t[0], ft[0]) || fovlp__neq(t[1], ft[1]) ||
                                    fovlp__neq(t[2], ft[2]) || fovlp__neq(t[3], ft[3])))
                FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                            "begin_frame: cam.tan4 differs from config.taa.frustum (the "
                            "camera's frustum is not the one the config describes)");
            if (!fov__tan_aspect_ok(t[0], t[1], t[2], t[3], ctx->cfg.width, ctx->cfg.height))
                FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_UNSUPPORTED,
                            "begin_frame: cam.tan4: (left + right) / (bottom + top) must be "
                            "width / height within 1e-3 (non-square pixels are not supported)");
        }
    }
    r = fovlp__setup2(&ctx->cfg, gaze, ctx->disc_angle, &c, &e, &gz, &g);
    if (r != FOV_OK) return r;
    if (g.lp_w != ctx->geo.lp_w || g.lp_h != ctx->geo.lp_h || g.samples != ctx->geo.samples)
        FOVLP__FAIL(&c.logger, FOV_ERR_DEGENERATE,
                    "begin_frame: LP sizes changed (ctx->cfg modified?)");
    /* gaze jump: reset the history */
    if (ctx->in_frame) {
        float a = fovlp_ecc_deg(&e, ctx->gaze.x, ctx->gaze.y);
        if (!(a <= c.taa.reset_deg)) jump = 1;
    }
    ctx->prev_gaze = ctx->in_frame ? ctx->gaze : gz;
    ctx->prev_cam = ctx->cam;
    ctx->have_cam = (ctx->have_cam & 1u) ? 2u : 0u;
    if (cam) { ctx->cam = *cam; ctx->have_cam |= 1u; }
    if ((ctx->have_cam & 3u) == 3u)
        moving = (uint32_t)fovlp__cam_differs(&ctx->cam, &ctx->prev_cam);
    if (jump) ctx->frame = 0;
    ctx->history_valid = (ctx->frame > 0 && c.taa.enable) ? 1u : 0u;
    ctx->moving = moving;
    ctx->gaze = gz;
    ctx->ecc = e;
    ctx->geo = g;
    /* jitter (eq. 3.11), off while moving unless asked for */
    if (c.taa.enable && (!moving || c.taa.jitter_moving)) {
        r = fovlp_jitter(&c, ctx->frame, &ou, &ov);
        if (r != FOV_OK) return r;
    }
    ctx->jit_u = ou;
    ctx->jit_v = ov;
    /* per-frame tables: eq. 3.7 split into its u part (radius) and v part (angle) */
    for (i = 0; i < g.lp_w; ++i) {
        float t = ((float)i + ou + g.u_g) / g.w_c;
        ctx->rho[i] = FOV__EXP(g.L * fovlp__pow(t, 1.0f / c.alpha));
    }
    for (i = 0; i < g.lp_h; ++i) {
        float a = FOVLP__TWO_PI * ((float)i + ov) / (float)g.lp_h;
        ctx->cs[i] = FOV__COS(a);
        ctx->sn[i] = FOV__SIN(a);
    }
    ctx->in_frame = 1;
    ctx->frame = ctx->frame + 1u < 0x7FFFFFFFu ? ctx->frame + 1u : 1u;
    return FOV_OK;
}

/* ---- mappings ----------------------------------------------------------------------------- */
/* Screen -> continuous LP coordinates (eqs. 3.8, 3.9 with atan2 and the r >= 1 clamp). */
FOVLP__PRIV void fovlp__to_lp(const fovlp_ctx *ctx, float dx, float dy, float *u, float *v)
{
    const fovlp_geometry *g = &ctx->geo;
    float r2 = dx * dx + dy * dy, r;
    float a = FOV__ATAN2(dy, dx);
    if (fov__finite(r2)) {
        r = FOV__SQRT(r2);
    } else { /* beyond ~1.8e19 px: scale first (fovlp_screen_to_lp takes any finite point) */
        float m = fov__maxf(fov__absf(dx), fov__absf(dy)), sx = dx / m, sy = dy / m;
        r = m * FOV__SQRT(sx * sx + sy * sy);
        if (!fov__finite(r)) r = 3.4028235e38f;
    }
    if (a < 0.0f) a += FOVLP__TWO_PI;
    *u = fovlp__pow(FOV__LOG(fov__maxf(r, 1.0f)) / g->L, ctx->cfg.alpha) * g->w_c - g->u_g;
    *v = a * ((float)g->lp_h / FOVLP__TWO_PI);
    if (*v >= (float)g->lp_h) *v -= (float)g->lp_h;
}

/* The reconstruction's mapping (step 7; fovlp__to_lp stays the reference): the same u, with
   the angle from a polynomial atan instead of the libm / hook atan2: reduced to |z| <= tan(pi/8)
   by the octant and atan z = z - z^3/3 + ... + z^13/13, truncation error below 2e-7 rad
   (z^15/15), about 4 float ulps of 2 pi. On x86-64 glibc this costs about a quarter of atan2f.
   With alpha = 1 there is no pow; dx, dy are finite (the gaze is). Tolerance (tested in
   tests/test_fovlp.c against fovlp_screen_to_lp): |du| <= 1e-4 (u + 1), |dv| <= 2e-6 h (v
   texels, wrapped). */
FOVLP__PRIV void fovlp__to_lp_fast(const fovlp_ctx *ctx, float dx, float dy, float r2, float *u,
                                   float *v)
{
    const fovlp_geometry *g = &ctx->geo;
    float ax = dx < 0.0f ? -dx : dx, ay = dy < 0.0f ? -dy : dy, z, z2, off = 0.0f, a, q;
    int swap = ay > ax;
    z = swap ? (ax > 0.0f ? ax / ay : 0.0f) : (ay > 0.0f ? ay / ax : 0.0f);   /* in [0, 1] */
    if (z > 0.41421356f) { off = 0.78539816f; z = (z - 1.0f) / (z + 1.0f); }
    z2 = z * z;
    a = off + z * (1.0f + z2 * (-3.3333333e-1f + z2 * (2.0e-1f + z2 * (-1.4285714e-1f +
              z2 * (1.1111111e-1f + z2 * (-9.0909091e-2f + z2 * 7.6923077e-2f))))));
    if (swap) a = 1.57079633f - a;
    if (dx < 0.0f) a = 3.14159265f - a;
    if (dy < 0.0f) a = FOVLP__TWO_PI - a;                  /* [0, 2 pi) */
    q = FOV__LOG(fov__maxf(FOV__SQRT(r2), 1.0f)) / g->L;
    *u = fovlp__pow(q, ctx->cfg.alpha) * g->w_c - g->u_g;
    *v = a * ((float)g->lp_h / FOVLP__TWO_PI);
    if (*v >= (float)g->lp_h) *v -= (float)g->lp_h;
    if (*v < 0.0f) *v = 0.0f;
}

FOVLP_API fov_result fovlp_screen_to_lp(const fovlp_ctx *ctx, float x, float y, float *u, float *v)
{
    if (!ctx) return FOV_ERR_NULL;
    if (!u || !v) FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "screen_to_lp: u and v are required");
    if (!ctx->in_frame)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "screen_to_lp: call fovlp_begin_frame first");
    if (!fov__finite(x) || !fov__finite(y))
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NOT_FINITE, "screen_to_lp: x or y NaN or infinite");
    fovlp__to_lp(ctx, x - ctx->gaze.x, y - ctx->gaze.y, u, v);
    return FOV_OK;
}

FOVLP_API fov_result fovlp_lp_to_screen(const fovlp_ctx *ctx, float u, float v, float *x, float *y)
{
    const fovlp_geometry *g;
    float t, rho, a;
    if (!ctx) return FOV_ERR_NULL;
    if (!x || !y) FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "lp_to_screen: x and y are required");
    if (!ctx->in_frame)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "lp_to_screen: call fovlp_begin_frame first");
    if (!fov__finite(u) || !fov__finite(v))
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NOT_FINITE, "lp_to_screen: u or v NaN or infinite");
    g = &ctx->geo;
    t = (u + g->u_g) / g->w_c;                  /* eq. 3.5: u_C / w_C */
    if (t < 0.0f)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "lp_to_screen: u inside the gaze disc (u < -u_G)");
    rho = FOV__EXP(g->L * fovlp__pow(t, 1.0f / ctx->cfg.alpha));   /* eq. 3.7 */
    a = FOVLP__TWO_PI * v / (float)g->lp_h;
    *x = ctx->gaze.x + rho * FOV__COS(a);
    *y = ctx->gaze.y + rho * FOV__SIN(a);
    if (!fov__finite(*x) || !fov__finite(*y)) {   /* u far beyond the buffer */
        *x = ctx->gaze.x; *y = ctx->gaze.y;
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_LIMIT,
                    "lp_to_screen: the point lies beyond the float range");
    }
    return FOV_OK;
}

/* Distance of (dx, dy) from the origin for any finite dx, dy (scaled where the squares
   overflow; FLT_MAX where the distance itself is beyond the float range). */
FOVLP__PRIV float fovlp__hypot(float dx, float dy)
{
    float r2 = dx * dx + dy * dy, m, sx, sy, r;
    if (fov__finite(r2)) return FOV__SQRT(r2);
    m = fov__maxf(fov__absf(dx), fov__absf(dy));
    sx = dx / m; sy = dy / m;
    r = m * FOV__SQRT(sx * sx + sy * sy);
    return fov__finite(r) ? r : 3.4028235e38f;
}
/* du/dr = alpha q^(alpha-1) w_C / (L r), q = log r / L, for a finite r >= 1; evaluated as
   (alpha q^(alpha-1)) ((w_C / L) / r) so no partial product overflows for any r up to
   FLT_MAX (the first factor is below 2^110, the second below w_C / L); 0 at r = 1 for
   alpha != 1 (q = 0: the kernel is flat there; K(x) = x^alpha). */
FOVLP__PRIV float fovlp__dudr(const fovlp_ctx *ctx, float r)
{
    const fovlp_geometry *g = &ctx->geo;
    float k = (g->w_c / g->L) / r;
    if (!fovlp__neq(ctx->cfg.alpha, 1.0f)) return k;
    return ctx->cfg.alpha * fovlp__pow(FOV__LOG(r) / g->L, ctx->cfg.alpha - 1.0f) * k;
}

FOVLP_API float fovlp_density(const fovlp_ctx *ctx, float x, float y)
{
    const fovlp_geometry *g;
    float r, d;
    if (!ctx || !ctx->in_frame || !fov__finite(x) || !fov__finite(y)) return 0.0f;
    g = &ctx->geo;
    r = fovlp__hypot(x - ctx->gaze.x, y - ctx->gaze.y);
    if (g->r_g > 0.0f && r < g->r_g) return 1.0f;
    r = fov__maxf(r, 1.0f);
    /* du/dr dv/ds with dv/ds = h / (2 pi r): both finite for any r in [1, FLT_MAX] */
    d = fovlp__dudr(ctx, r) * (((float)g->lp_h / FOVLP__TWO_PI) / r);
    return fov__finite(d) ? d : 0.0f;
}

FOVLP_API fov_result fovlp_spacing(const fovlp_ctx *ctx, float r, float *radial_px,
                                   float *angular_px)
{
    const fovlp_geometry *g;
    float dudr, rad, ang;
    if (!ctx) return FOV_ERR_NULL;
    if (!radial_px || !angular_px)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL,
                    "spacing: radial_px and angular_px are required");
    if (!ctx->in_frame)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG, "spacing: call fovlp_begin_frame first");
    if (!fov__finite(r))
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NOT_FINITE, "spacing: r NaN or infinite");
    g = &ctx->geo;
    if (g->r_g > 0.0f && r < g->r_g) { *radial_px = *angular_px = 1.0f; return FOV_OK; }
    r = fov__maxf(r, 1.0f);
    dudr = fovlp__dudr(ctx, r);
    /* the kernel is flat at r = 1 (alpha != 1): an unbounded radial spacing, given as FLT_MAX;
       elsewhere a derivative that underflows means a spacing beyond the float range */
    rad = dudr > 0.0f ? 1.0f / dudr : 3.4028235e38f;
    ang = r * (FOVLP__TWO_PI / (float)g->lp_h);
    if (!fov__finite(rad) || !fov__finite(ang) || (!(dudr > 0.0f) && r > 1.0f)) {
        *radial_px = *angular_px = 0.0f;
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_LIMIT,
                    "spacing: r so large that a spacing overflows float");
    }
    *radial_px = rad;
    *angular_px = ang;
    return FOV_OK;
}

/* ---- sampling ----------------------------------------------------------------------------- */
/* Position of LP texel (u, v)'s sample this frame; 1 when it is shaded (dispatched column and
   on the screen). Shading and reconstruction both call this, so they agree bit for bit. */
FOVLP__PRIV int fovlp__lp_pos(const fovlp_ctx *ctx, uint32_t u, uint32_t v, float *x, float *y)
{
    float r = ctx->rho[u];
    *x = ctx->gaze.x + r * ctx->cs[v];
    *y = ctx->gaze.y + r * ctx->sn[v];
    return u < ctx->geo.lp_cols && *x >= 0.0f && *x < (float)ctx->geo.width && *y >= 0.0f &&
           *y < (float)ctx->geo.height;
}
/* Disc pixel (i, j) (screen pixel) is shaded when its centre lies inside the circle. */
FOVLP__PRIV int fovlp__in_disc(const fovlp_ctx *ctx, uint32_t i, uint32_t j)
{
    float dx = (float)i + 0.5f - ctx->gaze.x, dy = (float)j + 0.5f - ctx->gaze.y;
    return ctx->geo.r_g > 0.0f && dx * dx + dy * dy < ctx->geo.r_g * ctx->geo.r_g;
}
FOVLP__PRIV void fovlp__centre_pos(const fovlp_ctx *ctx, float *x, float *y)
{
    float W = (float)ctx->geo.width, H = (float)ctx->geo.height;
    *x = ctx->gaze.x < W ? ctx->gaze.x : W - 0.5f;
    *y = ctx->gaze.y < H ? ctx->gaze.y : H - 0.5f;
}

FOVLP_API uint32_t fovlp_sample_rows(const fovlp_ctx *ctx)
{
    if (!ctx || !ctx->in_frame) return 0;
    return ctx->geo.lp_h + ctx->geo.disc_h + 1u;
}

/* Visits the samples of rows [r0, r1); emit(slot, x, y, shaded) for every slot of the rows. */
typedef struct fovlp__visit {
    fovlp_sample *out;
    size_t cap, n;
    fovlp_shade_fn fn;
    void *user;
    float *rgb, *depth;
    uint64_t shaded;
    int overflow;
} fovlp__visit;

FOVLP__PRIV void fovlp__emit(fovlp__visit *vi, uint32_t slot, float x, float y, int on)
{
    if (vi->fn) {
        float *c = vi->rgb + (size_t)slot * 3u;
        if (on) {
            float d = 0.0f;
            c[0] = c[1] = c[2] = 0.0f;
            vi->fn(x, y, c, vi->depth ? &d : (float *)0, vi->user);
            if (vi->depth) vi->depth[slot] = d;
            vi->shaded++;
        } else {
            c[0] = c[1] = c[2] = 0.0f;
            if (vi->depth) vi->depth[slot] = 0.0f;
        }
        return;
    }
    if (!on) return;
    if (vi->out) {
        if (vi->n < vi->cap) {
            vi->out[vi->n].x = x;
            vi->out[vi->n].y = y;
            vi->out[vi->n].slot = slot;
        } else {
            vi->overflow = 1;
        }
    }
    vi->n++;
}

FOVLP__PRIV void fovlp__visit_rows(const fovlp_ctx *ctx, uint32_t r0, uint32_t r1, fovlp__visit *vi)
{
    const fovlp_geometry *g = &ctx->geo;
    uint32_t r, u;
    for (r = r0; r < r1; ++r) {
        if (r < g->lp_h) {
            uint32_t base = r * g->lp_w;
            for (u = 0; u < g->lp_w; ++u) {
                float x, y;
                int on = fovlp__lp_pos(ctx, u, r, &x, &y);
                if (u >= g->lp_cols && !vi->fn) break;
                fovlp__emit(vi, base + u, x, y, on);
            }
        } else if (r < g->lp_h + g->disc_h) {
            uint32_t k = r - g->lp_h, j = g->disc_y0 + k, i;
            uint32_t base = g->disc_offset + k * g->disc_cols;
            for (i = 0; i < g->disc_cols; ++i) {
                uint32_t px = g->disc_x0 + i;
                int on = i < g->disc_w && fovlp__in_disc(ctx, px, j);
                float sx = (float)px + ctx->jit_u, sy = (float)j + ctx->jit_v;
                if (i >= g->disc_w && !vi->fn) break;
                /* inside its pixel even where px + offset rounds up to px + 1 in float */
                if (sx >= (float)px + 1.0f) sx = ((float)px + 1.0f) * (1.0f - 1.1920929e-7f);
                if (sy >= (float)j + 1.0f) sy = ((float)j + 1.0f) * (1.0f - 1.1920929e-7f);
                fovlp__emit(vi, base + i, sx, sy, on);
            }
        } else {
            float x, y;
            fovlp__centre_pos(ctx, &x, &y);
            fovlp__emit(vi, g->centre_slot, x, y, 1);
        }
    }
}

/* who: "samples" or "shade_rows" (the function named in the message) */
FOVLP__PRIV fov_result fovlp__rows_ok(const fovlp_ctx *ctx, uint32_t r0, uint32_t r1,
                                      const char *who)
{
    if (!ctx->in_frame)
        return fov__err3(&ctx->cfg.logger, "fovlp", FOV_ERR_INVALID_ARG, who,
                         FOV__MSG(": call fovlp_begin_frame first"), "", (uint32_t)__LINE__);
    if (r0 > r1 || r1 > fovlp_sample_rows(ctx))
        return fov__err3(&ctx->cfg.logger, "fovlp", FOV_ERR_INVALID_ARG, who,
                         FOV__MSG(": needs r0 <= r1 <= fovlp_sample_rows"), "", (uint32_t)__LINE__);
    return FOV_OK;
}

FOVLP_API fov_result fovlp_samples(const fovlp_ctx *ctx, uint32_t r0, uint32_t r1,
                                   fovlp_sample *out, size_t cap, size_t *count)
{
    fovlp__visit vi;
    fov_result r;
    if (!ctx) return FOV_ERR_NULL;
    if (!count) FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "samples: count is NULL");
    r = fovlp__rows_ok(ctx, r0, r1, FOV__MSG("samples"));
    if (r != FOV_OK) return r;
    FOV_MEMSET(&vi, 0, sizeof vi);
    vi.out = out;
    vi.cap = out ? cap : 0;
    fovlp__visit_rows(ctx, r0, r1, &vi);
    *count = vi.n;
    if (vi.overflow)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_TOO_SMALL, "samples: cap below the count");
    return FOV_OK;
}

FOVLP_API fov_result fovlp_shade_rows(const fovlp_ctx *ctx, uint32_t r0, uint32_t r1,
                                      fovlp_shade_fn fn, void *user, float *rgb, float *depth,
                                      uint64_t *shaded)
{
    fovlp__visit vi;
    fov_result r;
    if (!ctx) return FOV_ERR_NULL;
    if (!fn || !rgb)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "shade_rows: fn and rgb are required");
    r = fovlp__rows_ok(ctx, r0, r1, FOV__MSG("shade_rows"));
    if (r != FOV_OK) return r;
    FOV_MEMSET(&vi, 0, sizeof vi);
    vi.fn = fn;
    vi.user = user;
    vi.rgb = rgb;
    vi.depth = depth;
    fovlp__visit_rows(ctx, r0, r1, &vi);
    if (shaded) *shaded += vi.shaded;
    return FOV_OK;
}

FOVLP_API fov_result fovlp_count_samples(const fovlp_ctx *ctx, fovlp_counts *out)
{
    const fovlp_geometry *g;
    uint32_t u, v;
    float area;
    if (!ctx) return FOV_ERR_NULL;
    if (!out) FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "count_samples: out is NULL");
    if (!ctx->in_frame)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "count_samples: call fovlp_begin_frame first");
    g = &ctx->geo;
    FOV_MEMSET(out, 0, sizeof *out);
    out->lp_dispatched = (uint64_t)g->lp_cols * g->lp_h;
    for (v = 0; v < g->lp_h; ++v)
        for (u = 0; u < g->lp_cols; ++u) {
            float x, y;
            out->lp_shaded += (uint64_t)fovlp__lp_pos(ctx, u, v, &x, &y);
        }
    out->disc_dispatched = (uint64_t)g->disc_w * g->disc_h;
    for (v = 0; v < g->disc_h; ++v)
        for (u = 0; u < g->disc_w; ++u)
            out->disc_shaded += (uint64_t)fovlp__in_disc(ctx, g->disc_x0 + u, g->disc_y0 + v);
    out->shaded = out->lp_shaded + out->disc_shaded + 1u;
    area = (float)g->width * (float)g->height;
    out->dispatched_pct = fovlp__u64f(out->lp_dispatched + out->disc_dispatched) / area * 100.0f;
    out->shaded_pct = fovlp__u64f(out->shaded) / area * 100.0f;
    return FOV_OK;
}

/* ---- reconstruction ----------------------------------------------------------------------- */
/* FOVLP_RECON_CUBIC: Catmull-Rom over the 4 x 4 LP samples around (i0 + fu, j0 + fv) (columns
   i0 - 1 .. i0 + 2, rows j0 - 1 .. j0 + 2 wrapped), the result clamped per channel to the
   range of the inner 2 x 2 (so it stays inside the samples it uses: no ringing, no new
   extremes). Leaves rgb (the bilinear value) as it is when a column is missing, a tap is not
   shaded or the sum is not finite. */
FOVLP__PRIV void fovlp__lp_cubic(const fovlp_ctx *ctx, const float *smp_rgb, int32_t i0,
                                 int32_t j0, float fu, float fv, float in_r, float edge,
                                 float rgb[3])
{
    const fovlp_geometry *g = &ctx->geo;
    float wu[4], wv[4], a[3] = { 0.0f, 0.0f, 0.0f }, lo[3], hi[3], t;
    int32_t di, dj, c;
    int all_on;
    if (i0 < 1 || i0 + 2 >= (int32_t)g->lp_cols) return;
    /* all 16 taps on the screen for sure (no test each) when their rings lie inside it, or
       when the pixel is farther from the border than a tap can be from it: radially within
       rho[i0 + 2] - rho[i0 - 1], along the arc within two angle steps at rho[i0 + 2] (with
       1 % and 0.01 px to spare) */
    all_on = ctx->rho[i0 + 2] < in_r ||
             ((ctx->rho[i0 + 2] - ctx->rho[i0 - 1]) +
              ctx->rho[i0 + 2] * (2.0f * FOVLP__TWO_PI / (float)g->lp_h)) * 1.01f + 0.01f < edge;
    /* Catmull-Rom weights (sum 1) */
    wu[0] = 0.5f * fu * (fu * (2.0f - fu) - 1.0f);
    wu[1] = 0.5f * (fu * fu * (3.0f * fu - 5.0f) + 2.0f);
    wu[2] = 0.5f * fu * (fu * (4.0f - 3.0f * fu) + 1.0f);
    wu[3] = 0.5f * fu * fu * (fu - 1.0f);
    wv[0] = 0.5f * fv * (fv * (2.0f - fv) - 1.0f);
    wv[1] = 0.5f * (fv * fv * (3.0f * fv - 5.0f) + 2.0f);
    wv[2] = 0.5f * fv * (fv * (4.0f - 3.0f * fv) + 1.0f);
    wv[3] = 0.5f * fv * fv * (fv - 1.0f);
    lo[0] = lo[1] = lo[2] = FLT_MAX;
    hi[0] = hi[1] = hi[2] = -FLT_MAX;
    for (dj = 0; dj < 4; ++dj) {
        int32_t j = j0 - 1 + dj;
        while (j < 0) j += (int32_t)g->lp_h;
        while (j >= (int32_t)g->lp_h) j -= (int32_t)g->lp_h;
        for (di = 0; di < 4; ++di) {
            int32_t i = i0 - 1 + di;
            float x, y, w = wu[di] * wv[dj];
            const float *p;
            if (!all_on && !fovlp__lp_pos(ctx, (uint32_t)i, (uint32_t)j, &x, &y)) return;
            p = smp_rgb + 3u * ((size_t)(uint32_t)j * g->lp_w + (uint32_t)i);
            for (c = 0; c < 3; ++c) {
                a[c] += w * p[c];
                if (di == 1 || di == 2) {
                    if (dj == 1 || dj == 2) {
                        lo[c] = fov__minf(lo[c], p[c]);
                        hi[c] = fov__maxf(hi[c], p[c]);
                    }
                }
            }
        }
    }
    t = (a[0] - a[0]) + (a[1] - a[1]) + (a[2] - a[2]);   /* NaN unless finite */
    if (!(t >= 0.0f && t <= 0.0f)) return;
    for (c = 0; c < 3; ++c) rgb[c] = fov__clampf(a[c], lo[c], hi[c]);
}

/* Bilinear lookup of the LP samples at continuous (uc, vc), angle wrapped, unshaded taps left
   out; edge: the distance of the pixel (at (uc, vc)) to the nearest screen border. Returns the
   weight found (0: none); rgb and the depth of the heaviest tap. */
FOVLP__PRIV float fovlp__lp_lookup(const fovlp_ctx *ctx, const float *smp_rgb, const float *sdep,
                                   float uc, float vc, float edge, float rgb[3], float *depth)
{
    const fovlp_geometry *g = &ctx->geo;
    float su = uc - ctx->jit_u, sv = vc - ctx->jit_v, fu, fv, wsum = 0.0f, wbest = -1.0f;
    float fl_u, fl_v;
    /* radius of the largest circle around the gaze inside the screen, less a margin for the
       rounding of gaze + rho cos (the exact test would accept every tap inside it) */
    float in_r = fov__minf(fov__minf(ctx->gaze.x, (float)g->width - ctx->gaze.x),
                           fov__minf(ctx->gaze.y, (float)g->height - ctx->gaze.y)) * 0.999f - 0.01f;
    int32_t i0, j0, di, dj;
    int all_on, clamped = 0, pass;
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    *depth = 0.0f;
    if (su < 0.0f) { su = 0.0f; clamped = 1; }         /* inside the first column */
    if (su > (float)g->lp_w - 1.0f) { su = (float)g->lp_w - 1.0f; clamped = 1; }
    /* floor by truncation: su in [0, lp_w - 1], sv in (-1, lp_h) */
    i0 = (int32_t)su;
    j0 = (int32_t)sv;
    if ((float)j0 > sv) --j0;
    fl_u = (float)i0;
    fl_v = (float)j0;
    fu = su - fl_u;
    fv = sv - fl_v;
    /* all four taps shaded for sure (skip their tests) when their ring lies inside the screen
       (the circle of radius rho[i0 + 1] around the gaze within it, with a margin), or when
       the pixel is farther from the screen border than the taps can be from the pixel: their
       radii bracket the pixel's (su not clamped), so a tap is within the ring step plus one
       angle step at radius rho[i0 + 1] of it (with 1 % and 0.01 px to spare) */
    all_on = i0 + 1 < (int32_t)g->lp_cols &&
             (ctx->rho[i0 + 1] < in_r ||
              (clamped == 0 && ((ctx->rho[i0 + 1] - ctx->rho[i0]) +
                                ctx->rho[i0 + 1] * (FOVLP__TWO_PI / (float)g->lp_h)) * 1.01f +
                               0.01f < edge));
    /* pass 0: the weighted mean; where it is not finite, pass 1 sums with half weights
       (exact: the same bits halved), which cannot overflow for finite taps, and doubles the
       mean back saturating at +-FLT_MAX where the weights' rounding pushes it past (taps
       near FLT_MAX summed to inf in pass 0); NaN / inf from the shading pass through */
    for (pass = 0; pass < 2; ++pass) {
        float k = pass ? 0.5f : 1.0f, a0 = 0.0f, a1 = 0.0f, a2 = 0.0f, t;
        wsum = 0.0f;
        wbest = -1.0f;
        for (dj = 0; dj < 2; ++dj) {
            int32_t j = j0 + dj;
            float wv = dj ? fv : 1.0f - fv;
            /* the angle wraps: row -1 is row h-1, row h is row 0 */
            while (j < 0) j += (int32_t)g->lp_h;
            while (j >= (int32_t)g->lp_h) j -= (int32_t)g->lp_h;
            for (di = 0; di < 2; ++di) {
                int32_t i = i0 + di;
                float wu = di ? fu : 1.0f - fu, w = wu * wv, x, y, kw;
                size_t slot;
                if (!(w > 0.0f) || i >= (int32_t)g->lp_w) continue;
                if (!all_on && !fovlp__lp_pos(ctx, (uint32_t)i, (uint32_t)j, &x, &y)) continue;
                slot = (size_t)(uint32_t)j * g->lp_w + (uint32_t)i;
                kw = k * w;   /* local sums: rgb may alias the samples */
                a0 += kw * smp_rgb[3 * slot];
                a1 += kw * smp_rgb[3 * slot + 1];
                a2 += kw * smp_rgb[3 * slot + 2];
                wsum += w;
                if (w > wbest) { wbest = w; *depth = sdep ? sdep[slot] : 0.0f; }
            }
        }
        if (!(wsum > 1e-6f)) break;
        rgb[0] = a0 / wsum; rgb[1] = a1 / wsum; rgb[2] = a2 / wsum;
        t = (rgb[0] - rgb[0]) + (rgb[1] - rgb[1]) + (rgb[2] - rgb[2]);   /* NaN unless finite */
        if (pass == 0 && t >= 0.0f && t <= 0.0f) {
            if (ctx->cfg.recon == (uint32_t)FOVLP_RECON_CUBIC && !clamped && wsum > 0.999f)
                fovlp__lp_cubic(ctx, smp_rgb, i0, j0, fu, fv, in_r, edge, rgb);
            return wsum;
        }
        if (pass == 1) {
            rgb[0] = fovlp__twice_sat(rgb[0]);
            rgb[1] = fovlp__twice_sat(rgb[1]);
            rgb[2] = fovlp__twice_sat(rgb[2]);
            return wsum;
        }
    }
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    *depth = 0.0f;
    /* no shaded tap (near the screen border or the last column): the nearest shaded sample
       inwards along the two rows */
    for (i0 = i0 < (int32_t)g->lp_w ? i0 : (int32_t)g->lp_w - 1; i0 >= 0; --i0) {
        for (dj = 0; dj < 2; ++dj) {
            int32_t j = j0 + (fv >= 0.5f ? 1 - dj : dj);
            float x, y;
            size_t slot;
            while (j < 0) j += (int32_t)g->lp_h;
            while (j >= (int32_t)g->lp_h) j -= (int32_t)g->lp_h;
            if (!fovlp__lp_pos(ctx, (uint32_t)i0, (uint32_t)j, &x, &y)) continue;
            slot = (size_t)(uint32_t)j * g->lp_w + (uint32_t)i0;
            rgb[0] = smp_rgb[3 * slot]; rgb[1] = smp_rgb[3 * slot + 1];
            rgb[2] = smp_rgb[3 * slot + 2];
            *depth = sdep ? sdep[slot] : 0.0f;
            return 1.0f;
        }
    }
    return 0.0f;
}

/* One screen pixel (the pipeline's step 7). */
FOVLP__PRIV void fovlp__pixel(const fovlp_ctx *ctx, const float *smp_rgb, const float *sdep,
                              uint32_t px, uint32_t py, float rgb[3], float *depth)
{
    const fovlp_geometry *g = &ctx->geo;
    const float *cen = smp_rgb + 3u * (size_t)g->centre_slot;
    float cdep = sdep ? sdep[g->centre_slot] : 0.0f;
    float dx = (float)px + 0.5f - ctx->gaze.x, dy = (float)py + 0.5f - ctx->gaze.y;
    float uc, vc, r, r2, edge;
    /* the gaze disc: its own sample, 1:1 */
    if (g->r_g > 0.0f && dx * dx + dy * dy < g->r_g * g->r_g) {
        size_t slot =
            (size_t)g->disc_offset + (size_t)(py - g->disc_y0) * g->disc_cols + (px - g->disc_x0);
        rgb[0] = smp_rgb[3 * slot]; rgb[1] = smp_rgb[3 * slot + 1]; rgb[2] = smp_rgb[3 * slot + 2];
        *depth = sdep ? sdep[slot] : 0.0f;
        return;
    }
    r2 = dx * dx + dy * dy;
    fovlp__to_lp_fast(ctx, dx, dy, r2, &uc, &vc);
    edge = fov__minf(fov__minf((float)px + 0.5f, (float)g->width - (float)px - 0.5f),
                       fov__minf((float)py + 0.5f, (float)g->height - (float)py - 0.5f));
    if (!(fovlp__lp_lookup(ctx, smp_rgb, sdep, uc, vc, edge, rgb, depth) > 0.0f)) {
        rgb[0] = cen[0]; rgb[1] = cen[1]; rgb[2] = cen[2];
        *depth = cdep;
        return;
    }
    if (!(r2 < ctx->rho[0] * ctx->rho[0] * 1.0001f)) return;  /* beyond the innermost ring */
    r = FOV__SQRT(r2);
    /* between the disc and the innermost LP ring: interpolate along the radius between the
       nearest disc pixel inwards and the ring (no step at the disc edge) */
    if (g->r_g > 0.0f && r < ctx->rho[0] && r > 0.0f) {
        float qx = ctx->gaze.x + dx / r * fov__maxf(g->r_g - 0.75f, 0.0f);
        float qy = ctx->gaze.y + dy / r * fov__maxf(g->r_g - 0.75f, 0.0f);
        if (qx >= 0.0f && qy >= 0.0f && qx < (float)g->width && qy < (float)g->height) {
            uint32_t ix = (uint32_t)qx, iy = (uint32_t)qy;
            if (fovlp__in_disc(ctx, ix, iy) && ix >= g->disc_x0 && iy >= g->disc_y0 &&
                ix - g->disc_x0 < g->disc_w && iy - g->disc_y0 < g->disc_h) {
                size_t slot = (size_t)g->disc_offset + (size_t)(iy - g->disc_y0) * g->disc_cols +
                    (ix - g->disc_x0);
                float ex = (float)ix + 0.5f - ctx->gaze.x, ey = (float)iy + 0.5f - ctx->gaze.y;
                float rin = FOV__SQRT(ex * ex + ey * ey);
                float t = ctx->rho[0] > rin
                              ? fov__clampf((r - rin) / (ctx->rho[0] - rin), 0.0f, 1.0f)
                              : 1.0f;
                const float *q = smp_rgb + 3u * slot;
                rgb[0] = fovlp__lerp(q[0], rgb[0], t);
                rgb[1] = fovlp__lerp(q[1], rgb[1], t);
                rgb[2] = fovlp__lerp(q[2], rgb[2], t);
                if (t < 0.5f) *depth = sdep ? sdep[slot] : 0.0f;
            }
        }
        return;
    }
    /* inside the innermost sample ring (plain log-polar): blend towards the centre sample */
    if (!(g->r_g > 0.0f) && r < ctx->rho[0]) {
        float t = r / ctx->rho[0];
        rgb[0] = fovlp__lerp(cen[0], rgb[0], t);
        rgb[1] = fovlp__lerp(cen[1], rgb[1], t);
        rgb[2] = fovlp__lerp(cen[2], rgb[2], t);
        if (t < 0.5f) *depth = cdep;
    }
}

FOVLP_API fov_result fovlp_reconstruct_tile(const fovlp_ctx *ctx, const float *sample_rgb,
                                            const float *sample_depth, uint32_t x0, uint32_t y0,
                                            uint32_t x1, uint32_t y1, float *out_rgb,
                                            uint32_t out_stride, float *out_depth)
{
    uint32_t x, y, stride;
    if (!ctx) return FOV_ERR_NULL;
    if (!sample_rgb || !out_rgb)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL,
                    "reconstruct: sample_rgb and out_rgb are required");
    if (!ctx->in_frame)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "reconstruct: call fovlp_begin_frame first");
    if (out_depth && !sample_depth)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "reconstruct: out_depth needs sample_depth");
    if (x0 > x1 || y0 > y1)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "reconstruct: needs x0 <= x1 and y0 <= y1");
    if (x1 > ctx->geo.width || y1 > ctx->geo.height)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "reconstruct: x1 or y1 beyond the image");
    stride = out_stride ? out_stride : 3u * ctx->geo.width;
    if (stride < 3u * ctx->geo.width)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "reconstruct: out_stride below 3 * width");
    for (y = y0; y < y1; ++y)
        for (x = x0; x < x1; ++x) {
            float c[3], d;
            float *o = out_rgb + (size_t)y * stride + 3u * (size_t)x;
            fovlp__pixel(ctx, sample_rgb, sample_depth, x, y, c, &d);
            o[0] = c[0]; o[1] = c[1]; o[2] = c[2];
            if (out_depth) out_depth[(size_t)y * ctx->geo.width + x] = d;
        }
    return FOV_OK;
}

FOVLP_API fov_result fovlp_reconstruct_rows(const fovlp_ctx *ctx, const float *sample_rgb,
                                            const float *sample_depth, uint32_t y0, uint32_t y1,
                                            float *out_rgb, uint32_t out_stride, float *out_depth)
{
    if (!ctx) return FOV_ERR_NULL;
    return fovlp_reconstruct_tile(ctx, sample_rgb, sample_depth, 0, y0, ctx->geo.width, y1,
                                  out_rgb, out_stride, out_depth);
}

/* ---- Gaussian blend in the periphery (eq. 3.13) --------------------------------------------- */
FOVLP_API fov_result fovlp_blend_rows(const fovlp_ctx *ctx, const float *in, uint32_t y0,
                                      uint32_t y1, float *out)
{
    /* separable 1/16 [1 2 1; 2 4 2; 1 2 1], halved: k[a] k[b] sums to 1/2 (exact powers of
       two), so the sum of finite values cannot overflow; doubled back with saturation */
    static const float k[3] = { 0.25f, 0.5f, 0.25f };
    uint32_t W, H, x, y;
    float diag, s, e;
    if (!ctx) return FOV_ERR_NULL;
    if (!in || !out) FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "blend: in and out are required");
    if (!ctx->in_frame)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG, "blend: call fovlp_begin_frame first");
    W = ctx->geo.width; H = ctx->geo.height;
    if (y0 > y1 || y1 > H)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG, "blend: needs y0 <= y1 <= height");
    if (in == out)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG, "blend: out must not alias in");
    diag = FOV__SQRT((float)W * (float)W + (float)H * (float)H);
    s = ctx->cfg.blend_start * diag;
    e = ctx->cfg.blend_end * diag;
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            size_t o = 3u * ((size_t)y * W + x);
            float dx = (float)x + 0.5f - ctx->gaze.x, dy = (float)y + 0.5f - ctx->gaze.y;
            float t = ctx->cfg.blend
                          ? fov__clampf((FOV__SQRT(dx * dx + dy * dy) - s) / (e - s), 0.0f, 1.0f)
                          : 0.0f;
            float gsum[3] = { 0.0f, 0.0f, 0.0f };
            int32_t a, b, ch;
            if (!(t > 0.0f)) {
                out[o] = in[o]; out[o + 1] = in[o + 1]; out[o + 2] = in[o + 2]; continue;
            }
            for (b = -1; b <= 1; ++b)
                for (a = -1; a <= 1; ++a) {
                    int32_t xx = (int32_t)x + a, yy = (int32_t)y + b;
                    size_t q;
                    /* clamp at borders */
                    xx = xx < 0 ? 0 : (xx >= (int32_t)W ? (int32_t)W - 1 : xx);
                    yy = yy < 0 ? 0 : (yy >= (int32_t)H ? (int32_t)H - 1 : yy);
                    q = 3u * ((size_t)(uint32_t)yy * W + (uint32_t)xx);
                    for (ch = 0; ch < 3; ++ch)
                        gsum[ch] += 0.5f * k[a + 1] * k[b + 1] * in[q + (size_t)ch];
                }
            /* the lerp cannot overflow: inside [min, max] of the pixel and the 3x3 mean */
            for (a = 0; a < 3; ++a)
                out[o + (size_t)a] = fovlp__lerp(in[o + (size_t)a], fovlp__twice_sat(gsum[a]), t);
        }
    return FOV_OK;
}

/* ---- temporal anti-aliasing (thesis section 3.4, eq. 3.12) ---------------------------------- */
FOVLP__PRIV void fovlp__to_ycocg(const float c[3], float o[3])
{
    o[0] = 0.25f * c[0] + 0.5f * c[1] + 0.25f * c[2];
    o[1] = 0.5f * c[0] - 0.5f * c[2];
    o[2] = -0.25f * c[0] + 0.5f * c[1] - 0.25f * c[2];
}
FOVLP__PRIV void fovlp__from_ycocg(const float c[3], float o[3])
{
    o[0] = c[0] + c[1] - c[2];
    o[1] = c[0] + c[2];
    o[2] = c[0] - c[1] - c[2];
}

/* The clamp / clip of h at the scale k (YCoCg of k * colour) into r; 0 when the pass at
   k = 1 was not finite (a sum of squares, a YCoCg value or the result: colours beyond about
   1e19, or a NaN / inf neighbour when not careful). careful: neighbours with a NaN / inf
   channel are left out (the fast pass, careful = 0, takes every neighbour). */
FOVLP__PRIV int fovlp__clip_at(const fovlp_ctx *ctx, const float *cur, uint32_t x, uint32_t y,
                               uint32_t mode, const float h[3], float k, int careful, float r[3])
{
    uint32_t W = ctx->geo.width, H = ctx->geo.height;
    const float *p = cur + 3u * ((size_t)y * W + x);
    float mn[3], mx[3], m1[3], m2[3], c0[3] = { 0.0f, 0.0f, 0.0f }, hy[3], s[3], n = 0.0f, t;
    int32_t a, b, ch, have_c = 0;
    t = (p[0] - p[0]) + (p[1] - p[1]) + (p[2] - p[2]);   /* 0, or NaN for a NaN / inf channel */
    if (!careful || (t >= 0.0f && t <= 0.0f)) {
        s[0] = p[0] * k; s[1] = p[1] * k; s[2] = p[2] * k;
        fovlp__to_ycocg(k < 1.0f ? s : p, c0);
        have_c = 1;
    }
    for (ch = 0; ch < 3; ++ch) { mn[ch] = FLT_MAX; mx[ch] = -FLT_MAX; m1[ch] = m2[ch] = 0.0f; }
    for (b = -1; b <= 1; ++b)
        for (a = -1; a <= 1; ++a) {
            int32_t xx = (int32_t)x + a, yy = (int32_t)y + b;
            float q[3];
            if (xx < 0 || yy < 0 || xx >= (int32_t)W || yy >= (int32_t)H) continue;
            p = cur + 3u * ((size_t)(uint32_t)yy * W + (uint32_t)xx);
            if (careful) {
                t = (p[0] - p[0]) + (p[1] - p[1]) + (p[2] - p[2]);
                if (!(t >= 0.0f && t <= 0.0f)) continue;   /* the caller's bad samples: left out */
            }
            if (k < 1.0f) {
                s[0] = p[0] * k; s[1] = p[1] * k; s[2] = p[2] * k;
                fovlp__to_ycocg(s, q);
            } else {
                fovlp__to_ycocg(p, q);
            }
            if (!have_c) { c0[0] = q[0]; c0[1] = q[1]; c0[2] = q[2]; have_c = 1; }
            for (ch = 0; ch < 3; ++ch) {
                float e = q[ch] - c0[ch];
                mn[ch] = fov__minf(mn[ch], q[ch]);
                mx[ch] = fov__maxf(mx[ch], q[ch]);
                m1[ch] += e;
                m2[ch] += e * e;
            }
            n += 1.0f;
        }
    r[0] = h[0]; r[1] = h[1]; r[2] = h[2];
    if (!(n > 0.0f)) return 1;
    s[0] = h[0] * k; s[1] = h[1] * k; s[2] = h[2] * k;
    fovlp__to_ycocg(s, hy);
    if (mode == FOVLP_CLAMP_AABB) {
        for (ch = 0; ch < 3; ++ch) hy[ch] = fov__clampf(hy[ch], mn[ch], mx[ch]);
    } else {
        float scale = 0.0f, d[3], eps = k < 1.0f ? 1e-6f * k : 1e-6f;
        for (ch = 0; ch < 3; ++ch) {
            float mc = m1[ch] / n, var = fov__maxf(m2[ch] / n - mc * mc, 0.0f), mu = c0[ch] + mc;
            float ext = ctx->cfg.taa.clip_gamma * FOV__SQRT(var) + eps;
            d[ch] = hy[ch] - mu;
            scale = fov__maxf(scale, fov__absf(d[ch]) / ext);
            m1[ch] = mu;
        }
        if (scale > 1.0f)
            for (ch = 0; ch < 3; ++ch) hy[ch] = m1[ch] + d[ch] / scale;
    }
    fovlp__from_ycocg(hy, r);
    if (k < 1.0f) {
        for (ch = 0; ch < 3; ++ch)
            r[ch] = fov__clampf(r[ch] * 1.18059162e21f, -3.4028235e38f, 3.4028235e38f); /* 2^70 */
        return 1;
    }
    t = (m1[0] + m1[1] + m1[2]) + (m2[0] + m2[1] + m2[2]) + (mn[0] + mn[1] + mn[2]) +
        (mx[0] + mx[1] + mx[2]);
    return fov__finite(t) && fov__finite3(r);
}

/* Clamp (AABB) or clip (variance) the history colour h against the current 3x3
   neighbourhood of (x, y), in YCoCg (Karis 2014; Salvi 2016 for the variance box).
   Where the pass at full scale overflows (colours beyond about 1e19: 3e38^2 overflowed the
   sums of squares and silently disabled the clip, or gave NaN) it is redone at the scale
   2^-70 (exact, a power of two), and the result, scaled back, saturates at +-FLT_MAX (the
   YCoCg box's corners can lie up to 3x outside the RGB range of the neighbourhood). The
   moments are taken about the centre pixel's colour c: var = E[(q - c)^2] - E[q - c]^2 does
   not cancel catastrophically the way E[q^2] - E[q]^2 does for a neighbourhood far from 0
   (a uniform 1234.567 left a box wide enough to keep a history 0.12 away; now the box is
   the colour). Neighbours with a NaN or infinite channel (the caller's shading) are left
   out of the box; with none left h is kept as it is; a non-finite h stays non-finite (the
   caller rejects it). */
FOVLP__PRIV void fovlp__clamp_history(const fovlp_ctx *ctx, const float *cur, uint32_t x,
                                      uint32_t y, uint32_t mode, float h[3])
{
    float r[3];
    /* the fast pass; if not finite: without the NaN / inf neighbours; then at 2^-70 */
    if (!fovlp__clip_at(ctx, cur, x, y, mode, h, 1.0f, 0, r) && fov__finite3(h) &&
        !fovlp__clip_at(ctx, cur, x, y, mode, h, 1.0f, 1, r))
        (void)fovlp__clip_at(ctx, cur, x, y, mode, h, 8.47032947e-22f, 1, r);   /* 2^-70 */
    h[0] = r[0]; h[1] = r[1]; h[2] = r[2];
}

/* Bilinear fetch of the previous colour at continuous (hx, hy), borders clamped. */
FOVLP__PRIV void fovlp__fetch(const float *img, uint32_t W, uint32_t H, float hx, float hy,
                              float o[3])
{
    float sx = fov__clampf(hx - 0.5f, 0.0f, (float)W - 1.0f),
        sy = fov__clampf(hy - 0.5f, 0.0f, (float)H - 1.0f);
    float fx = FOV__FLOOR(sx), fy = FOV__FLOOR(sy), ax = sx - fx, ay = sy - fy;
    uint32_t x0 = (uint32_t)fx, y0 = (uint32_t)fy;
    uint32_t x1 = x0 + 1u < W ? x0 + 1u : x0, y1 = y0 + 1u < H ? y0 + 1u : y0;
    const float *p00 = img + 3u * ((size_t)y0 * W + x0), *p10 = img + 3u * ((size_t)y0 * W + x1);
    const float *p01 = img + 3u * ((size_t)y1 * W + x0), *p11 = img + 3u * ((size_t)y1 * W + x1);
    int ch;
    for (ch = 0; ch < 3; ++ch) {
        float t0 = p00[ch] + (p10[ch] - p00[ch]) * ax, t1 = p01[ch] + (p11[ch] - p01[ch]) * ax;
        o[ch] = t0 + (t1 - t0) * ay;
        if (!fov__finite(o[ch])) {
            /* a difference overflowed (neighbours of opposite signs beyond FLT_MAX / 2; a
               +-3e38 checkerboard gave NaN * 0), or a tap is NaN / inf: blend without
               differences (NaN / inf taps still give a non-finite result, rejected) */
            t0 = fovlp__lerp(p00[ch], p10[ch], ax);
            t1 = fovlp__lerp(p01[ch], p11[ch], ax);
            o[ch] = fovlp__lerp(t0, t1, ay);
        }
    }
}

FOVLP_API void fovlp_taa_io_init(fovlp_taa_io *io)
{
    if (!io) return;
    io->cur_rgb = NULL; io->cur_depth = NULL; io->prev_rgb = NULL; io->prev_depth = NULL;
    io->prev_age = NULL; io->out_rgb = NULL; io->out_depth = NULL; io->out_age = NULL;
}

FOVLP_API void fovlp_taa_stats_init(fovlp_taa_stats *stats)
{
    if (stats) FOV_MEMSET(stats, 0, sizeof *stats);
}

FOVLP_API fov_result fovlp_taa_rows(const fovlp_ctx *ctx, const fovlp_taa_io *io, uint32_t y0,
                                    uint32_t y1, fovlp_taa_stats *stats)
{
    const fovlp_config *c;
    uint32_t W, H, x, y, reproject;
    float diag, asp, per;
    int offc, offp;
    float fta[4] = { 0.0f, 0.0f, 0.0f, 0.0f }, ftp[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    if (!ctx) return FOV_ERR_NULL;
    c = &ctx->cfg;
    if (!io) FOVLP__FAIL(&c->logger, FOV_ERR_NULL, "taa_rows: io is NULL");
    if (!ctx->in_frame)
        FOVLP__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "taa_rows: call fovlp_begin_frame first");
    if (!c->taa.enable)
        FOVLP__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "taa_rows: cfg.taa.enable is 0");
    if (!io->cur_rgb || !io->out_rgb || !io->out_age)
        FOVLP__FAIL(&c->logger, FOV_ERR_NULL,
                    "taa_rows: io.cur_rgb, out_rgb and out_age are required");
    if (ctx->history_valid && (!io->prev_rgb || !io->prev_age))
        FOVLP__FAIL(&c->logger, FOV_ERR_NULL,
                    "taa_rows: io.prev_rgb and prev_age needed after frame 1");
    if ((const float *)io->out_rgb == io->cur_rgb || (const float *)io->out_rgb == io->prev_rgb ||
        (io->out_depth && (const float *)io->out_depth == io->prev_depth) ||
        (const uint8_t *)io->out_age == io->prev_age) /* neighbourhoods and reprojection
                                                         read them */
        FOVLP__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "taa_rows: io.out_* must not alias cur_rgb or prev_*");
    W = ctx->geo.width; H = ctx->geo.height;
    if (y0 > y1 || y1 > H)
        FOVLP__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "taa_rows: needs y0 <= y1 <= height");
    reproject = ctx->history_valid && ctx->moving;
    if (reproject && (!io->cur_depth || !io->prev_depth))
        FOVLP__FAIL(&c->logger, FOV_ERR_NULL,
                    "taa_rows: a moving camera needs io.cur_depth and prev_depth");
    diag = FOV__SQRT((float)W * (float)W + (float)H * (float)H);
    per = c->taa.periphery * diag;
    asp = (float)W / (float)H;
    offc = fovlp__cam_tan(&ctx->cam, c, fta);
    offp = fovlp__cam_tan(&ctx->prev_cam, c, ftp);
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            const float *cur = io->cur_rgb + 3u * i;
            float dc = io->cur_depth ? io->cur_depth[i] : 0.0f;
            float hist[3], hx = (float)x + 0.5f, hy = (float)y + 0.5f, w;
            uint32_t age, reject = 0, periph = 0, ch;
            if (stats) stats->pixels++;
            if (io->out_depth) io->out_depth[i] = dc;
            if (!ctx->history_valid) {
                /* a non-finite colour from the caller's shading never enters the history */
                for (ch = 0; ch < 3; ++ch)
                    io->out_rgb[3 * i + ch] = fov__finite(cur[ch]) ? cur[ch] : 0.0f;
                io->out_age[i] = 1;
                continue;
            }
            if (reproject) {
                /* world point of this pixel, then its place in the previous frame */
                const fovlp_camera *a = &ctx->cam, *p = &ctx->prev_cam;
                const float *ft = fta;
                float sxn = (hx / (float)W * 2.0f - 1.0f) * a->tan_half_y * asp;
                float syn = (hy / (float)H * 2.0f - 1.0f) * a->tan_half_y;
                float d[3], wp[3], rel[3], z;
                if (offc) { /* off-axis (taa.frustum); syn points down as above */
                    sxn = -ft[0] + (ft[0] + ft[1]) * (hx / (float)W);
                    syn = -ft[3] + (ft[2] + ft[3]) * (hy / (float)H);
                }
                for (ch = 0; ch < 3; ++ch)
                    d[ch] = a->fwd[ch] + sxn * a->right[ch] - syn * a->up[ch];
                fovlp__normalize(d);
                for (ch = 0; ch < 3; ++ch) {
                    wp[ch] = a->pos[ch] + dc * d[ch]; rel[ch] = wp[ch] - p->pos[ch];
                }
                z = fov__dot(rel, p->fwd);
                if (!(z > 1e-6f) || !fov__finite(dc)) {
                    reject = 1;
                } else {
                    float px = fov__dot(rel, p->right) / (z * p->tan_half_y * asp);
                    float py = fov__dot(rel, p->up) / (z * p->tan_half_y);
                    hx = (px + 1.0f) * 0.5f * (float)W;
                    hy = (1.0f - py) * 0.5f * (float)H;
                    if (offp) {
                        float qx = fov__dot(rel, p->right) / z, qy = fov__dot(rel, p->up) / z;
                        hx = (qx + ftp[0]) / (ftp[0] + ftp[1]) * (float)W;
                        hy = (ftp[3] - qy) / (ftp[2] + ftp[3]) * (float)H;
                    }
                    if (!(hx >= 0.0f && hx < (float)W && hy >= 0.0f && hy < (float)H)) {
                        reject = 1;
                    } else {
                        float expect = fovlp__len_safe(rel);
                        float hd = io->prev_depth[(size_t)(uint32_t)hy * W + (uint32_t)hx];
                        /* NaN, or a distance beyond FLT_MAX: differs (inf <= tol * inf would
                           pass) */
                        if (!fov__finite(expect) || !fov__finite(hd) ||
                            !(fov__absf(hd - expect) <= c->taa.depth_tol * fov__maxf(hd, expect))) {
                            float gx = (float)x + 0.5f - ctx->gaze.x,
                                gy = (float)y + 0.5f - ctx->gaze.y;
                            /* keep, age reset after */
                            if (gx * gx + gy * gy > per * per) periph = 1;
                            else reject = 1;
                        }
                    }
                }
            }
            if (reject) {
                age = 1;
                hist[0] = hist[1] = hist[2] = 0.0f;
                if (stats) stats->rejected++;
            } else {
                uint32_t pa = io->prev_age[(size_t)(uint32_t)hy * W + (uint32_t)hx];
                age = pa + 1u < c->taa.max_age ? pa + 1u : c->taa.max_age;
                if (age < 1) age = 1;
                if (periph && age > 2) age = 2; /* the kept history weighs at most 1/2 */
                fovlp__fetch(io->prev_rgb, W, H, hx, hy, hist);
                if (c->taa.clamp != FOVLP_CLAMP_NONE)
                    fovlp__clamp_history(ctx, io->cur_rgb, x, y, c->taa.clamp, hist);
                else if (reproject && !c->taa.thesis_moving) /* moving: no ghost (ours) */
                    fovlp__clamp_history(ctx, io->cur_rgb, x, y, FOVLP_CLAMP_VARIANCE, hist);
                if (!fov__finite(hist[0]) || !fov__finite(hist[1]) || !fov__finite(hist[2])) {
                    /* a NaN / inf neighbour in this frame's colours (the caller's shading) */
                    age = 1; periph = 0;
                    hist[0] = hist[1] = hist[2] = 0.0f;
                    if (stats) stats->rejected++;
                } else if (periph && stats) {
                    stats->kept_periphery++;
                }
            }
            w = 1.0f / (float)age;
            for (ch = 0; ch < 3; ++ch) {
                /* a non-finite current colour: keep the history (or 0 without one), so one bad
                   sample cannot spread through the bilinear fetch and the clamp frame by frame */
                float cc = fov__finite(cur[ch]) ? cur[ch] : (age > 1 ? hist[ch] : 0.0f);
                /* within [min, max] of history and current, finite (issue 10 F8: 3e38 then
                   -3e38 overflowed hist + (cur - hist) / age to -inf) */
                io->out_rgb[3 * i + ch] = fovlp__lerp(hist[ch], cc, w);
            }
            io->out_age[i] = (uint8_t)(periph ? 1u : age);
        }
    return FOV_OK;
}

/* ---- 8-bit sRGB output ----------------------------------------------------------------------- */
/* The exact encoding without math functions. t[k] (k = 0 .. 254) is the bit pattern of the
   smallest float x with round(255 srgb(x)) >= k + 1, srgb the IEC 61966-2-1 curve in exact
   arithmetic (computed offline with 60-digit decimals; tests/test_fovlp_srgb8.c recomputes
   every boundary in double). For x >= 0 the bit patterns of floats are ordered like the
   floats, so the code of x is the number of t[k] <= bits(x). s[b] starts the count for the
   bucket b of bits(x) in [2^-13, 1) (exponent and 5 mantissa bits: 13 x 32 buckets, the code
   at the bucket's lower end); at most 3 boundaries lie inside a bucket. */
FOVLP_API uint8_t fovlp_linear_to_srgb8(float x)
{
    static const uint32_t t[255] = {
        0x391f22b4, 0x39eeb40e, 0x3a46eb61, 0x3a8b3e5e, 0x3ab3070b, 0x3adacfb8, 0x3b014c33,
        0x3b153089, 0x3b2914df, 0x3b3cf936, 0x3b50f2d1, 0x3b65fb9b, 0x3b7c3403, 0x3b89d060,
        0x3b962333, 0x3ba314bd, 0x3bb0a731, 0x3bbedcb7, 0x3bcdb76d, 0x3bdd3967, 0x3bed64af,
        0x3bfe3b46, 0x3c07df91, 0x3c10f91b, 0x3c1a6b32, 0x3c2436c8, 0x3c2e5cc7, 0x3c38de1a,
        0x3c43bba4, 0x3c4ef648, 0x3c5a8ee4, 0x3c668654, 0x3c72dd71, 0x3c7f950f, 0x3c865702,
        0x3c8d148f, 0x3c940396, 0x3c9b247c, 0x3ca277a6, 0x3ca9fd78, 0x3cb1b653, 0x3cb9a298,
        0x3cc1c2a9, 0x3cca16e3, 0x3cd29fa4, 0x3cdb5d4b, 0x3ce45032, 0x3ced78b5, 0x3cf6d72e,
        0x3d0035fc, 0x3d051bb4, 0x3d0a1cec, 0x3d0f39d0, 0x3d14728a, 0x3d19c745, 0x3d1f382c,
        0x3d24c567, 0x3d2a6f22, 0x3d303584, 0x3d3618b7, 0x3d3c18e4, 0x3d423632, 0x3d4870ca,
        0x3d4ec8d2, 0x3d553e73, 0x3d5bd1d3, 0x3d628318, 0x3d69526a, 0x3d703fee, 0x3d774bca,
        0x3d7e7624, 0x3d82df90, 0x3d869372, 0x3d8a56cb, 0x3d8e29ab, 0x3d920c27, 0x3d95fe4f,
        0x3d9a0035, 0x3d9e11ec, 0x3da23384, 0x3da66510, 0x3daaa6a0, 0x3daef847, 0x3db35a15,
        0x3db7cc1b, 0x3dbc4e6b, 0x3dc0e114, 0x3dc58429, 0x3dca37b9, 0x3dcefbd6, 0x3dd3d08f,
        0x3dd8b5f5, 0x3dddac19, 0x3de2b30a, 0x3de7cad9, 0x3decf395, 0x3df22d50, 0x3df77817,
        0x3dfcd3fc, 0x3e012087, 0x3e03dfae, 0x3e06a77b, 0x3e0977f6, 0x3e0c5126, 0x3e0f3314,
        0x3e121dc5, 0x3e151143, 0x3e180d95, 0x3e1b12c2, 0x3e1e20d1, 0x3e2137cb, 0x3e2457b6,
        0x3e278099, 0x3e2ab27d, 0x3e2ded68, 0x3e313161, 0x3e347e70, 0x3e37d49c, 0x3e3b33ec,
        0x3e3e9c67, 0x3e420e15, 0x3e4588fb, 0x3e490d22, 0x3e4c9a90, 0x3e50314c, 0x3e53d15d,
        0x3e577aca, 0x3e5b2d9a, 0x3e5ee9d4, 0x3e62af7e, 0x3e667e9f, 0x3e6a573e, 0x3e6e3962,
        0x3e722511, 0x3e761a52, 0x3e7a192c, 0x3e7e21a5, 0x3e8119e2, 0x3e8327c7, 0x3e853a86,
        0x3e875222, 0x3e896e9d, 0x3e8b8ffc, 0x3e8db641, 0x3e8fe170, 0x3e92118b, 0x3e944696,
        0x3e968095, 0x3e98bf89, 0x3e9b0377, 0x3e9d4c62, 0x3e9f9a4c, 0x3ea1ed38, 0x3ea4452b,
        0x3ea6a226, 0x3ea9042e, 0x3eab6b44, 0x3eadd76d, 0x3eb048aa, 0x3eb2bf00, 0x3eb53a71,
        0x3eb7bb00, 0x3eba40b1, 0x3ebccb85, 0x3ebf5b81, 0x3ec1f0a7, 0x3ec48af9, 0x3ec72a7c,
        0x3ec9cf32, 0x3ecc791e, 0x3ecf2842, 0x3ed1dca2, 0x3ed49641, 0x3ed75521, 0x3eda1946,
        0x3edce2b2, 0x3edfb168, 0x3ee2856a, 0x3ee55ebd, 0x3ee83d63, 0x3eeb215d, 0x3eee0ab1,
        0x3ef0f95f, 0x3ef3ed6b, 0x3ef6e6d8, 0x3ef9e5a8, 0x3efce9de, 0x3efff37e, 0x3f018145,
        0x3f030b82, 0x3f049877, 0x3f062827, 0x3f07ba92, 0x3f094fb9, 0x3f0ae79f, 0x3f0c8244,
        0x3f0e1faa, 0x3f0fbfd2, 0x3f1162be, 0x3f13086e, 0x3f14b0e4, 0x3f165c22, 0x3f180a29,
        0x3f19bafa, 0x3f1b6e96, 0x3f1d24ff, 0x3f1ede36, 0x3f209a3c, 0x3f225913, 0x3f241abc,
        0x3f25df38, 0x3f27a689, 0x3f2970af, 0x3f2b3dad, 0x3f2d0d83, 0x3f2ee032, 0x3f30b5bd,
        0x3f328e24, 0x3f346968, 0x3f36478b, 0x3f38288f, 0x3f3a0c73, 0x3f3bf33a, 0x3f3ddce5,
        0x3f3fc975, 0x3f41b8eb, 0x3f43ab48, 0x3f45a08f, 0x3f4798bf, 0x3f4993db, 0x3f4b91e3,
        0x3f4d92d8, 0x3f4f96bd, 0x3f519d92, 0x3f53a758, 0x3f55b411, 0x3f57c3be, 0x3f59d65f,
        0x3f5bebf7, 0x3f5e0486, 0x3f60200e, 0x3f623e90, 0x3f64600c, 0x3f668485, 0x3f68abfb,
        0x3f6ad670, 0x3f6d03e5, 0x3f6f345a, 0x3f7167d2, 0x3f739e4d, 0x3f75d7cc, 0x3f781451,
        0x3f7a53dd, 0x3f7c9671, 0x3f7edc0e
    };
    static const uint8_t s[416] = {
        0,0,0,0,0,0,0,0,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,
        1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,
        1,1,1,1,1,1,1,1,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,
        2,2,2,2,3,3,3,3,3,3,3,3,3,3,3,3,3,3,3,3,3,4,4,4,4,4,
        4,4,4,4,4,5,5,5,5,5,5,5,5,5,5,6,6,6,6,6,6,6,6,6,6,7,
        7,7,7,7,8,8,8,8,8,9,9,9,9,9,10,10,10,10,10,11,11,11,11,11,12,12,
        12,12,12,12,13,13,13,14,14,14,15,15,15,16,16,16,16,17,17,17,18,18,18,18,19,19,
        19,19,20,20,20,20,21,21,21,21,22,22,23,23,23,24,24,25,25,25,26,26,27,27,27,28,
        28,29,29,29,30,30,30,31,31,31,32,32,32,33,33,33,34,34,35,35,36,36,37,38,38,39,
        39,40,40,41,41,42,42,43,43,44,44,45,45,46,46,46,47,47,48,48,49,49,49,50,51,52,
        53,53,54,55,56,56,57,58,58,59,60,60,61,62,62,63,64,64,65,66,66,67,67,68,68,69,
        70,70,71,72,73,74,75,76,77,78,79,80,81,82,83,84,85,85,86,87,88,89,90,91,91,92,
        93,94,95,95,96,97,98,98,99,101,102,103,105,
        106,107,109,110,111,113,114,115,116,118,119,120,121,
        122,123,124,126,127,128,129,130,131,132,133,134,135,
        136,137,139,141,143,145,146,148,150,152,153,155,157,
        158,160,162,163,165,166,168,169,171,172,174,175,177,
        178,179,181,182,184,185,186,188,190,193,195,198,200,
        202,205,207,209,212,214,216,218,220,223,225,227,229,
        231,233,235,237,239,240,242,244,246,248,250,251,253
    };
    union { float f; uint32_t u; } b;
    uint32_t c;
    b.f = x;
    if (b.u >= 0x3f800000u) return b.u <= 0x7f800000u ? 255u : 0u; /* >= 1, +inf; NaN, < 0 */
    if (b.u < t[0]) return 0u;                               /* below the first boundary, +0 */
    c = s[(b.u - 0x39000000u) >> 18];                          /* t[0] > 2^-13 = 0x39000000 */
    while (c < 255u && b.u >= t[c]) ++c;
    return (uint8_t)c;
}

FOVLP_API fov_result fovlp_srgb8_rows(const fovlp_ctx *ctx, const float *rgb, uint32_t rgb_stride,
                                      uint32_t y0, uint32_t y1, uint8_t *out, uint32_t out_stride,
                                      uint32_t channels)
{
    uint32_t W, H, x, y, is, os;
    if (!ctx || !rgb || !out) return FOV_ERR_NULL;
    W = ctx->geo.width; H = ctx->geo.height;
    if (!W || !H)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "srgb8_rows: ctx has no screen size (call fovlp_init first)");
    if (channels != 3u && channels != 4u)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "srgb8_rows: channels must be 3 (RGB) or 4 (RGBA, alpha 255)");
    if (y0 > y1 || y1 > H)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "srgb8_rows: rows [y0, y1) must satisfy y0 <= y1 <= height");
    is = rgb_stride ? rgb_stride : 3u * W;
    os = out_stride ? out_stride : channels * W;
    if (is < 3u * W)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "srgb8_rows: rgb_stride must be 0 or at least 3 * width floats");
    if (os < channels * W)
        FOVLP__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "srgb8_rows: out_stride must be 0 or at least channels * width bytes");
    for (y = y0; y < y1; ++y) {
        const float *p = rgb + (size_t)y * is;
        uint8_t *q = out + (size_t)y * os;
        for (x = 0; x < W; ++x, p += 3, q += channels) {
            q[0] = fovlp_linear_to_srgb8(p[0]);
            q[1] = fovlp_linear_to_srgb8(p[1]);
            q[2] = fovlp_linear_to_srgb8(p[2]);
            if (channels == 4u) q[3] = 255u;
        }
    }
    return FOV_OK;
}

#endif /* FOVLP_IMPLEMENTATION */

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
