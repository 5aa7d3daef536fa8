/* fovpt.h - v0.14.0 - foveated path tracing: layers, zones, selective supersampling
                     - MIT or public domain (see end of file)

   In *one* C or C++ file, #define FOVPT_IMPLEMENTATION (or FOV_IMPL, for every fov header)
   before you include this file: that file holds the implementation.

QUICK START
      #define FOVPT_IMPLEMENTATION
      #include "fovpt.h"
      #include <stdlib.h>                             // malloc

      fovpt_material mat[2];  fovpt_material_init(&mat[0]);  fovpt_material_init(&mat[1]);
      mat[1].emission[0] = mat[1].emission[1] = mat[1].emission[2] = 4.0f;   // a lamp
      fovpt_shape sh[2];      fovpt_shape_sphere(&sh[0], 0,0,0, 1.0f, 0);    // grey ball
                              fovpt_shape_sphere(&sh[1], 0,3,0, 0.5f, 1);    // the lamp
      fovpt_scene_desc d;     fovpt_scene_desc_init(&d);
      d.shapes = sh; d.num_shapes = 2; d.materials = mat; d.num_materials = 2;
      size_t sb;  fovpt_scene_size(&d, &sb);          // caller memory for the scene + BVH
      fovpt_scene scene;  fovpt_scene_build(&scene, &d, malloc(sb), sb);
      fovpt_camera cam;   fovpt_camera_init(&cam, 320, 240);  // = fov_camera, shared
      cam.pos[2] = 4.0f;  // from (0,0,4) at the origin: world +x right, +y up in the image
      fovpt_config cfg = fovpt_config_default();      // path tracing, 1 spp, NEE, RR
      size_t cb;  fovpt_memory_size(&cfg, &cam, &cb);
      fovpt_ctx ctx;  fov_gaze gaze = { 160.0f, 120.0f };
      if (fovpt_init(&ctx, &cfg, &scene, &cam, gaze, malloc(cb), cb) != FOV_OK) ...
      fovpt_output out;  fovpt_output_init(&out);  out.rgb8 = pixels;   // 320*240*3 bytes
      fovpt_stats st;    fovpt_stats_init(&st);       // counters, optional (NULL: none)
      fovpt_render(&ctx, 0, &out, &st);               // frame 0; or trace/resolve by rows
   st adds up over calls (every frame's rays, until fovpt_stats_init clears it).

   See examples/pt_basic.c for a complete program.

   No eye tracker: fixed foveation, the gaze at the display's axis point and larger foveae
      fovpt_gaze_fixed(&cfg.display, 320, 240, &gaze);                 // the screen centre
      fovpt_config_gaze_margin(&base, FOV_GAZE_FIXED_MARGIN_DEG, &cfg); // radii + 15 deg
   With one: filter its samples and grow the radii by the latency margin per frame with
   fovpt_set_gaze_margin (keeps the accumulation; GAZE INPUT).

   Stereo, per-eye gaze: one context per eye (Axblad 2020, Sec. 3.2.1, and Kim et al. 2021,
   Fig. 4, render the eyes independently).
      fovpt_camera eye[2];  fovpt_camera_eyes(&head, 0.064f, eye);   // ipd in scene units
      fov_gaze g[2];        fovpt_gaze_from_point(&eye[0], gaze_target, &g[0]);   // the 3D
                            fovpt_gaze_from_point(&eye[1], gaze_target, &g[1]);   // vergence point
      fovpt_init(&ctx[0], &cfg, &scene, &eye[0], g[0], mem0, cb);   // and eye[1], g[1]
   Each eye's eccentricity is then measured from its own gaze point with its own camera.
   (The same eyes from one camera: eye_offset = -ipd/2 and +ipd/2, see fov_camera.)

WHAT IT DOES (the pipeline, in the order the data flows)
   1. Scene (fovpt_scene_build): spheres, infinite planes, quads (parallelograms), axis-aligned
      boxes and triangle meshes, validated, copied into caller memory, with a binned-SAH BVH
      (Wald 2007) over the bounded primitives, collapsed to 8 children per node (4 with
      FOVPT_NO_SIMD; FOVPT_BVH_WIDTH) for the traversal (each node opens its largest
      inner children until it has that many; with SIMD a subtree of at most 4 primitives,
      one leaf block, is never a node of its own: opened by its parent, or one leaf child;
      leaves lie in whole blocks, padded where one would straddle two; a node's boxes are
      tested in SIMD passes of 4 (SSE on x86, NEON on AArch64, SIMD128 on wasm32 with
      -msimd128) or one of 8 (AVX), one after another elsewhere), nearest child first; leaf
      triangles are stored in SoA blocks of four and tested four at a time the same way; a
      bounded shape is a leaf of its own, culled by its box; planes and the user hook are
      tested apart. Fewer than bvh_min_prims bounded
      primitives: no BVH, a plain loop. The box test is conservative (NUMERICS): the BVH
      never misses a hit that the brute-force loop finds.
   2. Camera rays, one deterministic random stream per (pixel, sample, frame) (fovpt_rng: a
      counter-based integer hash, no state outside the stream); with cfg.sampler SOBOL (the
      default) the pixel's samples are stratified (SAMPLERS).
   3. Radiance (fovpt_radiance): Kajiya's rendering equation (Kajiya 1986; Axblad 2020, Eq.
      2.1) estimated by an iterative path tracer: BSDF sampling (Lambert, the two-lobe Phong
      of Axblad 2020, Sec. 3.2.2, mirror, dielectric with Fresnel), next-event estimation
      towards sampleable emitters combined with BSDF hits by the power heuristic (Veach
      1997), Russian roulette, a bounce limit. Or a Whitted-style tracer (Kim et al. 2021,
      Sec. 5: depth 3, hard shadows, reflection, refraction).
   4. Sampling pattern per method: UNIFORM (every pixel, spp samples: the non-foveated
      renderer); LAYERS (Axblad 2020, ch. 3: gaze-centred lattices of stride d per layer);
      ZONES (Polychronakis 2025, ch. 4: 1, 1/4, 1/16 ray density); SELECTIVE (Kim et al.
      2021: presample, 2x2-subpixel disparity test scaled by tau_fov(e), 9/4/2/1 extra
      samples); JIN (Jin et al. 2009: 4 per problematic subpixel everywhere).
   5. Resolve (fovpt_resolve_rows): progressive mean; LAYERS: Catmull-Rom fill of untraced
      pixels (Axblad 2020, Eq. 3.17, with its coefficient error fixed) and border blending
      (Eq. 3.18); ZONES: Lanczos upsampling and linear overlap blending; temporal reuse and
      smoothing (Kim et al. 2021, steps 2 and 4, Sec. 4.4 and 4.7); 8-bit sRGB or float
      output.
   6. Denoising (optional; fovpt_trace_rows_guide, fovpt_denoise_*): first-hit guide buffers
      (albedo, normal, depth, samples per pixel, variance) from the traced samples, then
      temporal accumulation with reprojection and the edge-avoiding a-trous wavelet filter
      (Dammertz et al. 2010) with variance guidance (Schied et al. 2017), foveated: fewer
      passes and a shorter history where the eye resolves the pixels and the samples are dense;
      where a pixel's own samples are many, the input or a pass's output by least Stein's
      unbiased risk estimate (Li et al. 2012) (the declarations' DENOISING comment has the
      details).

STATUS (v0.5.0)
   Implemented and tested: geometry, BVH, intersection (BVH, brute force, user hook), the
   path tracer (all materials, NEE + MIS, Russian roulette, bounce limit), the Whitted tracer,
   the random streams, progressive accumulation, every method (UNIFORM, LAYERS, ZONES,
   SELECTIVE, JIN) by rows, eccentricity, tau_fov and alpha(e), per-eye cameras and gaze,
   temporal reuse and smoothing (SELECTIVE and JIN only, as in Kim et al. 2021;
   FOV_ERR_UNSUPPORTED with the others).
   The acuity-driven configuration (fovpt_config_acuity) and the B-spline layer
   reconstruction (layers.bspline). Path tracing at arbitrary image points
   (fovpt_shade_points: fovlp.h's log-polar samples, examples/lp_pt.c).

CHOICES WHERE THE SOURCES ARE OPEN (each one is tested)
   - Phong (Axblad 2020, Eq. 3.7-3.15): the thesis mixes a uniform-hemisphere weight (3.13)
     with lobe-sampling energy updates and a clamp (Eq. 3.15-3.16): biased. Here one
     estimator: the BRDF kd/pi + ks (a+2)/(2 pi) max(0, wr.wi)^a (wr = mirror of wo), sampled
     from the mixture pD * cos/pi + pS * (a+1)/(2 pi) cos^a about wr with pS, pD from Eq.
     3.9-3.12 (mean of ks, kd), weight f cos / mixture pdf (unbiased; no clamp).
   - Emitters are two-sided (emission = material.emission on both faces) and add to the
     surface's scattering. Sampleable by NEE: spheres (uniform on their area), quads and
     triangles; emissive planes and boxes are found by BSDF sampling only (full weight).
     A light is picked with probability proportional to area * mean(emission).
   - Bounces: max_depth counts scattering events; emission seen after at most max_depth
     bounces is counted (max_depth 0: emitters and background only). Default 8 (Axblad
     2020, Sec. 3.1.1).
   - Russian roulette from bounce rr_start (default 3): survival probability = max channel of
     the path throughput, clamped to [0.05, 1]; survivors are divided by it (unbiased).
   - Whitted mode: emitters are treated as point lights at their centre (sphere: the point
     nearest the shading point), intensity emission * area * |cos| / d^2, hard shadows; an
     ambient term background * kd; mirrors and dielectrics branch deterministically (both
     Fresnel branches, explicit stack); no random numbers except the pixel jitter.
   - Degenerate triangles (zero area) are an error unless desc.skip_degenerate = 1.
   - Pixel jitter: uniform in the pixel (box filter), from the pixel's stream.
   - LAYERS (Axblad 2020, Sec. 3.2.1-3.2.4). Lattice of layer n >= 1: pixels
     (gx + k d, gy + l d), (gx, gy) = floor(gaze) (snap: floor(gaze / d) * d), the first one
     on the image taken as the origin, clamped to column W - 1 / row H - 1 so that a stride
     wider than the image with the gaze off it still leaves one point; layer 0: (k d, l d),
     static. A lattice point (pixel centre eccentricity e) is traced when
        e <= min(r_n + blend/2 + a_n, r_0 + a_n)  (layer n >= 1; the r_0 term with a mask)
        e <= r_0 + a_0                             (layer 0 with a mask; all points without)
     with the apron a_n = (2 sqrt(2) d_n + 1) / f_px radians in degrees (f_px: the eye's
     distance to the image in pixels), so every Catmull-Rom neighbour of a pixel that needs
     the layer is traced (an angle between two pixels' rays is at most their distance / f).
     Like Axblad 2020, every layer covers its whole disk, including the finer layers' area.
     Samples of a target pixel are jittered uniformly inside it. Untraced pixels: separable
     Catmull-Rom over the 4 x 4 lattice neighbours (Eq. 3.17 fixed), neighbour indices
     clamped at the image border; where a neighbour is not traced (mask border), the
     bilinear weights of the 2 x 2 inner neighbours that are; results clamped to >= 0
     (Catmull-Rom overshoots). Blending (Eq. 3.18) from the outside in: C = F_0, then for
     n = 1 .. N-1: C = (1 - vb_n) C + vb_n F_n with vb_n = 1 at e <= r_n - blend/2, 0 at
     e >= r_n + blend/2, smoothstep (or linear) between; continuous across every border.
     Pixels beyond the mask radius are black (not traced, as in Axblad 2020). Where the
     innermost full-weight layer has no traced neighbour, the next layer outwards that has
     one gives C (the outermost layer is traced wherever the mask lets it).
     layers.bspline = 1 (and zones.bspline for ZONES) replaces Catmull-Rom (Lanczos) on the
     layers of stride >= 2 by the uniform cubic B-spline over the same 4 x 4 neighbours
     (weights >= 0, no clamp): an approximating filter that averages the lattice's
     path-tracing noise (per-pixel variance of independent lattice noise x 0.35 against
     Catmull-Rom, x 0.29 against Lanczos-3, at stride 4) and blurs by about 0.58 stride
     (standard deviation), near the eye's own blur where the stride follows the acuity.
   - ZONES (Polychronakis 2025, Sec. 4.2): it renders full frames and keeps every 2nd / 4th
     pixel (nearest neighbour); here only the kept pixels are traced: static lattices of
     stride 4 (everywhere), 2 (e <= middle_deg + overlap/2 + apron) and 1 (e <= inner_deg +
     overlap/2 + apron), cfg.spp samples each, apron a_n = (sqrt(2) a d_n + 1) / f_px. The
     coarse lattices are Lanczos-upsampled (a = 3 lobes, normalised weights) and the zones
     blended linearly over overlap_px pixels (converted to degrees at the gaze) centred on
     each border. Zone radii: inner 7.5 and middle 32.5 degrees (the conservative 15 and 65
     degree fields of Polychronakis 2025, Sec. 4.4.2, read as diameters).
   - SELECTIVE / JIN (Kim et al. 2021, Sec. 3 and 4.6; Jin et al. 2009). Presample: one ray
     through each pixel centre (no jitter) gives the colour reference and the Table 1
     attributes: object ids (primitive ids), normals, shadow counts (occluded shadow rays:
     Whitted's light tests, the path tracer's first NEE test) at the primary hit and, when it is
     a mirror or glass, at the secondary hit; no textures, so the texture flags never differ.
     Subpixel NW, NE, SW, SE is compared with the 3 neighbours on its side (image border: the
     pixel itself). Discordance: ids or shadow counts differ, normals more than normal_tol_deg
     (10) apart; tau_sel = min tau of the discordant attributes, else tau_col. Problematic when
     (max - min) / (max + min) of a channel over the 4 linear colours exceeds tau_fov(e) tau_sel
     (1.36, 1.02, 2.04) (JIN: tau_fov = 1). Problematic subpixels get n_sd[zone] (JIN: 4, in
     every zone) stratified jittered samples: an m x m grid when n_sd is a square, else n_sd
     columns; the subpixel is their mean. Other subpixels: bilinear from the 4 pixel centres
     around the subpixel centre (9/16, 3/16, 3/16, 1/16; Kim et al. 2021, Fig. 2), or the
     pixel's presample (JIN, fill_centre). The pixel is the mean of its 4 subpixels. Beyond
     e_np: the presample only. Colours are linear radiance (the contrast is a ratio).
   - Temporal (Kim et al. 2021, steps 2 and 4, Sec. 4.4-4.7), SELECTIVE and JIN.
     fovpt_set_view ends a frame. History per frame and pixel: the raw colour (before
     smoothing, as in Kim et al. 2021), the first-hit distance, the colour reference, the
     reuse count. Reuse (central region): the pixel's
     first hit v (centre ray) projects into the previous view at pixel q (nearest); reused
     when 1. q's reuse count < n_reuse_max, 2./3. both rays hit, 4. |dist(v, previous
     camera) - q's stored distance| <= eps_depth x that distance (our reading of condition 4
     of Kim et al. 2021, Sec. 4.4, as a disocclusion test, not its literal wording), 5. the
     two colour references pass the
     contrast test with tau_reuse x tau_col (the previous frame's attributes are not kept,
     so step 1 of the disparity test is skipped). A reused pixel copies q's colour and
     gets count + 1. Smoothing: C* = sum_i a (1-a)^i C_i / sum of the weights used, i = 0 ..
     n_tpi, a = fovpt_alpha(e), C_i = the raw colour at v's pixel in frame t-i when the
     depths agree within eps_depth; rejected frames leave the normalisation; pixels whose
     centre ray misses are not smoothed.

ACUITY-DRIVEN CONFIGURATION (fovpt_config_acuity)
      fovpt_config cfg = fovpt_config_default();
      cfg.method = FOVPT_METHOD_LAYERS;                // or ZONES, SELECTIVE
      cfg.display.pixel_pitch_mm = 0.3113f; cfg.display.distance_mm = 600.0f;  // or all zero
      fov_eye eye = { 0 };  eye.quality = 0.5f;        // NULL: the same defaults (fov_eye)
      if (fovpt_config_acuity(&cfg, &cam, &eye) != FOV_OK) ...   // then fovpt_memory_size, init
   fills the three foveation families from the display (cfg.display; all zero: the camera's
   frustum, off-axis ones included, as fovpt_init derives it) and the eye model (fov_eye, the
   shared MAR(e) = mar0 + slope e of Guenter et al. 2012, one quality knob): cfg.layers (count,
   radius_deg, stride, spp, bspline = hollow = cell_jitter = 1, clamp_white =
   FOVPT_ACUITY_CLAMP_WHITE), cfg.zones (inner_deg, middle_deg, spp[3], bspline = hollow =
   cell_jitter = 1, clamp_white = FOVPT_ACUITY_CLAMP_WHITE), cfg.selective.e_deg[5] and
   tau_shape; whichever method cfg.method picks then uses its own family. Every other field
   (method, spp, acuity_budget, blend_deg, overlap_px, n_sd, tau, temporal, display, logger,
   ...) stays as the caller set it; on an error cfg is unchanged and the
   logger gets the reason (a bad eye field: FOV_ERR_NOT_FINITE or FOV_ERR_INVALID_ARG naming
   it; a bad config, camera or display: the code fovpt_config_resolve or fovpt_init would
   give). A second call changes nothing.
   The fixed tables stay available: fovpt_layers_preset by name, zero fields for the defaults.
   The pixels per degree are fovpt_eye_plan's (at the eye's axis, the coarsest on a flat
   display: the safe side), so the result does not depend on the gaze. Choices:
   - Layers. The stride-s layer starts (the inner edge of its blend band) at e(s), where the
     eye's allowed spacing quality * MAR(e) * ppd reaches s pixels (fovpt_eye_ecc(eye, ppd,
     1/s)): there s is the largest stride within the allowed spacing. The finer layer's
     radius_deg is then e(s) + blend_deg / 2 (+ 0.001), the innermost layer has stride 1 and
     full weight out to e(2) >= e_full. Strides from the ladder 1, 2, 3, 4, 6, 8, 12, 16, 24,
     32, 48, 64 (Axblad 2020's 1-4, then steps of at most 1.5: a layer costs about its disk
     over its stride squared, and every layer covers its whole disk), the first
     FOVPT_MAX_LAYERS entries up to the spacing allowed at the largest eccentricity an
     on-screen gaze sees (the angle between opposite image corners); of entries the eye allows
     already at the gaze (e(s) = 0) only the coarsest is kept, next to the stride-1 layer of
     radius blend_deg / 2. A fixed ladder keeps the stride at each eccentricity monotone in ppd
     and quality. No occlusion mask (layer[0] radius 0). A display coarser than the eye
     across the image: two layers, stride 1 out to 179.5 degrees and a background of the
     spacing allowed there; with hollow = 1 the background is then never traced on screen, so
     the table costs UNIFORM's samples and gives UNIFORM's image (at cfg.spp, bit for bit).
     hollow = 1: no layer traced under a finer one's full-weight disk (Axblad 2020's layers
     overlap: at 640 x 360 and quality 0.25 the background alone added 36 % to UNIFORM's
     samples). cell_jitter = 1: a lattice point's samples cover its d x d cell, so detail
     finer than the lattice becomes noise (averaged by spp and the eye) instead of aliasing.
   - Zones. inner_deg = e_half and middle_deg = e_quarter of the plan (densities 1/4 and 1/16
     are exactly what the eye allows from there), each plus half the overlap band
     (overlap_px / ppd / 2 degrees), since the coarser zone's weight starts that far inside;
     hollow and cell_jitter as for the layers; spp[3] as below.
   - Samples (layers' spp, zones.spp; the path tracer's noise is what the periphery shows).
     After the eye's blur (a Gaussian of s = 0.375 MAR(e), the measure of examples/fovmetrics.h,
     s in pixels) independent noise of variance v per sample (RANDOM's; SOBOL's, the default,
     falls faster with spp where the error is direct light and edges, so there the plan errs
     towards more samples) keeps v / spp_u x cu of it in UNIFORM's image,
     cu = 1 / (1 + 4 pi s^2) (the Gaussian's sum of squared weights: exact
     for s -> 0 and s >> 1, an approximation between), and v / spp_n x cl on a stride-d
     lattice, cl = 1 / (1 + 4 pi (b^2 + s^2 / d^2)), b^2 = 1/3 (the B-spline) + 1/12 (the cell
     box) in cells^2; cu and cl averaged over each layer's band (a 48 x 48 grid of image
     points, the gaze at the centre). acuity_budget 0: spp_n = the least integer above
     0.99 spp cl / cu (spp = cfg.spp, UNIFORM's): each band's mean filtered noise at most
     UNIFORM's; the stride-1 layer takes spp, a coarser one between 1 and spp d^2 (UNIFORM's
     density). acuity_budget B > 0: spp_n = k (d^2 cl^g)^(1 / (1 + g)), g = FOVPT_ACUITY_GAMMA
     (0.5), which minimises the mean of (filtered variance)^g (g 1/2: the mean filtered
     standard deviation) for the total B W H spp (k fitted to the lattice points the table
     traces and to the rounded spp; within a few % of the budget): B = 1 is equal time with
     UNIFORM, the fovea then gets more than spp, the periphery less. clamp_white = 1: the
     lattice estimates what the display shows; PT noise is heavy-tailed and a displayed
     UNIFORM pixel clips its fireflies at white, which the lattice's mean of many samples
     (before this clamp) did not: its filtered error was 4-6 dB above the model's.
     The bound. Equal filtered noise at a pixel needs spp_n / d^2 >= spp cl / (d^2 cu): the
     saving there is at most d^2 cu / cl = (d^2 + 4 pi (b^2 d^2 + s^2)) / (1 + 4 pi s^2),
     which for the eye's stride d = q MAR ppd (s = 0.375 d / q, s >> 1) tends to
     1 + q^2 (1 + 4 pi b^2) / 1.77 = 1 + 3.5 q^2 (b^2 = 5/12): 4.5x at quality 1, 1.9x at 0.5,
     and none inside e_full; over an image, 1 / (f + (1 - f) / S) with f the share of pixels
     inside e_full. Every saving an unbiased estimator gets at equal noise comes from the
     reconstruction's blur b d (0.65 d against the eye's 0.375 d / q: a bias the measure
     sees from about quality 0.7) and from the lattice point covering several pixels. 5x at
     equal perceived quality would need q^2 (1 + 4 pi b^2) >= 7, a blur near twice the eye's:
     not for an unbiased path tracer under this measure. A denoiser (edge-aware, a footprint
     far wider than b without the bias at edges; issue 14), temporal accumulation or noise the
     eye's filter removes better (blue-noise / low-discrepancy samples) lifts it.
     Measured (bench/bench_perceptual.c, Cornell box, equal: perr <= perr_ref + 0.001): the
     largest saving at equal perceived quality 1.4x (layers) / 3.4x (zones, 1 spp) at
     640 x 360 (8.6 px/degree), 1.0x / 1.4x on the 27-inch monitor (33.6), 2.0x / 2.1x on the
     headset (11.7); at equal time (acuity_budget 1) perr 5-13 % below UNIFORM's except the
     layers on the monitor (7 % above: its far periphery, strides 12-16). An edge-rich scene
     (441 cubes) is equal nowhere (quality 0.5: 1.04x, perr +5 % at 640 x 360; 1.17x, +55 %
     on the monitor): there the lattice's blur of detail near the MAR, a bias no spp removes,
     dominates, and the quality knob would have to go well below 0.5.
   - Reconstruction: the smoothing B-spline (layers.bspline, zones.bspline; see LAYERS below)
     on the coarse lattices. What makes the periphery visible, measured after filtering both
     images to the eye's resolution (bench/pt_acuity.c --recon, Cornell box, 4 spp, at 33.6
     and 5.4 px/degree): the path-tracing noise of the sparse lattice (upsampled into blobs of
     the stride's size that the eye's blur does not average away), not the reconstruction
     (with 64 times the samples per lattice point the error beyond e_half falls by 7-13 dB).
     The B-spline lowers FLIP there by 7-19 % (PSNR -0.5 .. +1.6 dB); its own blur costs no
     measurable error at 33.6 px/degree, 2 dB PSNR (no FLIP) at 5.4 px/degree.
   - Selective. Kim et al. 2021's borders (or the caller's) scaled by one factor k so that
     e_np, beyond which only the presample (one sample per pixel) is traced, falls at e_full,
     beyond which one sample per pixel is as fine as the eye resolves; the zones keep their
     proportions and tau_fov its shape as a function of e / k (tau'_f divided by k, so the
     shape stays valid). e_np is at least 0.01 degrees and e_max below 180.
   bench/pt_acuity.c prints the samples per pixel and savings at three displays (and the
   error by cause after an eye-resolution filter).

SHADING IMAGE POINTS (fovpt_shade_points; path tracing in log-polar space with fovlp.h)
   Another header decides where to shade, fovpt shades those image points, the other header
   reconstructs: fovlp.h's kernel log-polar samples (Meng et al. 2018), as Koskela et al. 2019
   path trace a regular grid in their Visual-Polar space on the GPU and map it to the screen.
      fovlp_begin_frame(&lp, gaze, &lcam);                      // fovlp picks the positions
      fovlp_samples(&lp, 0, fovlp_sample_rows(&lp), smp, cap, &n);
      fovpt_shade_points(&scene, &cfg, &cam, (uint32_t)n, &smp[0].x, 3, 0, frame, spp, 0.0f,
                         col, dep, &st);                        // x, y, slot: stride 3 floats
      for (i = 0; i < n; ++i) copy col[3 i ..] (and dep[i]) to slot smp[i].slot;
      fovlp_reconstruct_rows(&lp, rgb, sdep, 0, H, img, 0, idep);   // then fovlp_taa_rows
   examples/lp_pt.c is the whole program (Cornell box, TAA over frames). Point i is
   (xy[i stride], xy[i stride + 1]) in the camera's image (pixels, continuous, centres at
   +0.5; off-image points work as in fovpt_camera_ray). Its sample k (k < spp) is exactly
      fovpt_rng_init_sobol(&rng, cfg->seed, first + i, k, frame);   // stream (first + i)
                                       // mod 2^32 (fovpt_rng_init with cfg->sampler RANDOM)
      if (jitter > 0) { x += (fovpt_rng_next(&rng) - 0.5f) * jitter;    // in this order
                        y += (fovpt_rng_next(&rng) - 0.5f) * jitter; }
      else if (rng.sobol) { fovpt_rng_next(&rng); fovpt_rng_next(&rng); } // pair dropped
      fovpt_camera_ray(cam, x, y, org, dir);
      fovpt_radiance(scene, cfg, org, dir, &rng, c_k, stats);
   and rgb[3 i ..] = (c_0 + ... + c_(spp-1)) / spp, the sum in k order (bit for bit; tested
   against these calls; with cfg->robust the ROBUST PIXEL ESTIMATE of c_0 .. c_(spp-1)).
   The stream is the point's index, not its pixel: two points in one pixel get independent
   noise; give `first` the index of a batch's first point when you split
   a list over threads or calls, and a new `frame` each frame (the same frame repeats the
   noise). jitter 0: the point is the sample (fovlp's TAA jitter moves the points over
   frames, which anti-aliases); jitter 1 at pixel centres, first = y W + x0 for the pixels
   x0, x0 + 1, ... of row y, is the UNIFORM method's pixel (its box filter and streams:
   fovpt_render's image bit for bit, tested with and without clamp_white set, as UNIFORM
   never clamps). clamp_white is not read here: rgb is the plain mean, not a LAYERS or ZONES
   stride >= 2 lattice point's mean of sample groups clamped at clamp_white; a texel's size
   prefilters a coarser sample. t (may be NULL) gets the distance along sample 0's unit
   camera ray to the first surface (FLT_MAX when it leaves the scene): the depth fovlp's TAA
   reprojects with. The config's method, foveation tables (layers, zones, with their
   clamp_white), temporal and display fields are not read (mode, max_depth, rr_start,
   no_nee, seed, sampler, robust and logger are); spp 0 takes cfg->spp.
   Every pointer, the config, the camera and every point are checked before any work (NULL:
   FOV_ERR_NULL; a NaN or infinite x, y or jitter: FOV_ERR_NOT_FINITE; a negative jitter, a
   point whose ray or the ray of any of its jitter square's 4 corners overflows (then no
   sample's ray can): FOV_ERR_INVALID_ARG; spp above FOVPT_MAX_SPP or 3 n floats beyond
   SIZE_MAX: FOV_ERR_LIMIT);
   on an error nothing is written. stats: samples and camera_rays n spp, plus the paths' rays.

SAMPLERS (cfg.sampler, fovpt_rng_init_sobol)
   FOVPT_SAMPLER_RANDOM gives every (pixel, sample, frame) its own independent numbers.
   FOVPT_SAMPLER_SOBOL (the default since 0.14.0: cfg.sampler 0, FOVPT_SAMPLER_DEFAULT,
   resolves to it) stratifies the samples of a pixel: sample k takes the first
   dimensions of a scrambled Sobol sequence (Sobol 1967) at index k, as Burley 2020 builds
   it: each group of dimensions shuffles k by its own nested uniform (Owen 1995) scramble of
   the Laine-Karras 2011 hash and then scrambles the point (two rounds of the hash, keyed by
   seed, pixel, frame and group). The groups follow the path's order of use: the pixel
   position (dimensions 0, 1: a 2-D Sobol pair), then triples, each a 1-D group (the light or
   BSDF lobe pick) and a 2-D pair (the point on the light, the BSDF direction): the light and
   BSDF samples of the first four bounces (26 dimensions; Russian roulette, from bounce
   rr_start, shifts the triples after it, which stay uniform but lose their pairing).
   Numbers past the 26th are the random stream's. So samples 0 .. 2^m - 1 of a pixel put
   exactly one point into each of the 2^m elementary intervals of every pair, and one into
   each 1/2^m of every 1-D group, while two groups (a pick and its pair included) pair their
   points like independent ones (tested); every number stays uniform in [0, 1), so the
   estimate stays unbiased and its mean is RANDOM's. Each frame (and seed) scrambles anew:
   frames are independent, like RANDOM's. The methods number a pixel's samples from 0
   (LAYERS' layer n from n 2^16, SELECTIVE's and JIN's subpixel q from (q + 1) 2^12: blocks
   that stratify the same way); a lone sample (index 0 only) is as random as RANDOM's. A
   camera ray without jitter (fovpt_shade_points with jitter 0, the SELECTIVE and JIN
   presample through the pixel centre) draws the pixel pair and drops it, so the path's
   dimensions keep their places (RANDOM's streams are unchanged by this).
   Measured (`make bench-pt-sampler`, bench/results/pt_sampler.csv: 160 x 120, 4 seeds, MSE of
   the clamped image against 2048 RANDOM spp), the same samples, SOBOL over RANDOM: UNIFORM
   at 16 spp the terrain +6.4 dB, the mirrors +5.2 dB, the 441 cubes +3.8 dB; at 4 spp +2.6
   to +3.8 dB in these three; the Cornell box -0.2 to +0.5 dB (its clamped error is the
   fireflies of its mirror and Phong spheres: RANDOM's PSNR falls from 4 to 16 spp) and the
   interior +0.1 to +1.2 dB. Cost: 12-20 % more instructions per frame (callgrind, UNIFORM
   8 spp: the hashes of a path's 26 numbers); at equal time the terrain, mirrors and cubes
   gain, the Cornell box and the interior lose a little. Hence the default (0.14.0; RANDOM
   before, now cfg.sampler = FOVPT_SAMPLER_RANDOM, whose value moved from 0 to 2).

ROBUST PIXEL ESTIMATE (cfg.robust)
   Path tracing noise is heavy-tailed: a rare path that next-event estimation cannot sample
   (light reaching a diffuse wall through a mirror: a caustic) carries a radiance many times
   the pixel's, and a pixel that catches one shows a bright speck, most visible where the eye
   looks, where the foveated methods put their many samples. cfg.robust = k (3 ..
   FOVPT_ROBUST_MAX) replaces the mean of a pixel's samples in one call by an adaptive median
   of means after Buisine, Delepoulle and Renaud 2021, "Firefly Removal in Monte Carlo
   Rendering with Adaptive Median of meaNs". It applies to the spp samples of one call for a
   UNIFORM pixel, a LAYERS / ZONES lattice point (stride 1, or without clamp_white) and a
   fovpt_shade_points point, in path mode:
     - each sample is split into the radiance its camera ray's specular chain reaches
       (emission and background before the first bounce that is not a mirror or glass one:
       what the eye sees directly or through mirrors and glass, so a light's or a mirrored
       light's partly covered edge is coverage, not noise; glass's random pick of reflection
       or refraction and Russian roulette make these terms vary too, and they stay in the
       plain mean, specks included) and the rest; Whitted mode: all of it (no random
       numbers along its rays);
     - the rest is summed in g = min(k, spp / FOVPT_ROBUST_MIN_GROUP) groups of consecutive
       samples (sizes within one); with g >= 3, the groups' mean luminances l_1 <= .. <= l_g
       (0.2126 R + 0.7152 G + 0.0722 B) give the Gini coefficient G = sum_i (2 i - g - 1) l_i
       / (g sum_i l_i) (0: all equal; (g - 1) / g: one group holds everything);
     - the pixel is the chains' mean plus, where G > FOVPT_ROBUST_GINI, the median group's
       mean of the rest (the mean of the two middle ones for even g), else its plain mean.
   Biased where a rare path carries much of a pixel's true value: a caustic's own pixels
   (the Cornell box's ceiling, lit through its mirror sphere, comes out darker at 64 spp)
   lose it with their specks. Consistent as the samples of one call grow: every group mean
   tends to the pixel's and G to 0 (tested: its squared difference from the plain mean of
   the same samples falls 6x from 64 to 256 spp on that Cornell box). Not across calls: with
   cfg.accumulate, a temporal filter or fovlp's TAA at a fixed spp per call the running
   mean keeps the per-call bias (Cornell box, 64 x 48, 32 spp x 64 frames: the image's mean
   luminance 3.9 % below the plain one's; 2048 spp in one call: equal). Fewer than 3 groups (spp < 3
   FOVPT_ROBUST_MIN_GROUP), Whitted mode (deterministic along each ray), SELECTIVE's and
   JIN's samples and lattice points that group their samples for clamp_white: the plain
   mean, as with robust 0 (the default: unbiased, every image as before). The guides' var
   stays the plain samples' variance. Measured: bench/README.md (`bench_pt --robust`, the
   rows <method>_rb). Light through a mirror sphere or quad is better served unbiased by
   cfg.mirror_nee (below).

NEXT-EVENT ESTIMATION THROUGH MIRRORS (cfg.mirror_nee)
   Next-event estimation samples a point on a light and connects to it; light that reaches a
   diffuse point only by way of a mirror (a caustic: the Cornell box's wall lit through its
   mirror sphere) is found only when a sampled bounce happens to hit the light's small image
   in the mirror, rarely and with a large value: specks. cfg.mirror_nee = 1 (path mode)
   connects through the mirrors as well, after Mitchell and Hanrahan 1992, "Illumination from
   Curved Reflectors" (the reflection point by Fermat's principle, the irradiance from the
   reflected wavefront's curvature), the one-mirror case of the manifold next-event
   estimation of Hanika, Droske and Fascione 2015:
     - at each Lambert or Phong vertex (where next-event estimation runs, below max_depth - 1
       bounces), one of the scene's mirror spheres and quads (shapes of material
       FOVPT_MAT_MIRROR; fovpt_scene.mirrors, uniformly) and one light point y (as next-event
       estimation picks it) give the reflection point p on the mirror (a quad: y mirrored in
       its plane; a sphere: the one point on the side that x and y see, by the Illinois
       method); the segments x p and p y are tested for occlusion (two shadow rays) and the
       sample adds f cos albedo_mirror L_e / p_c, p_c = pdf_mirror pdf_y / (g cos_y) its
       solid-angle pdf at x, with g the solid angle at x per area at y through the mirror (a
       plane: 1 / |x - y'|^2; a sphere of radius R at incidence t: 1 / (w_t w_s), w = d1 + d2
       + 2 d1 d2 / (R cos t) and d1 + d2 + 2 d1 d2 cos t / R, the Coddington equations);
     - the same path found by the vertex's sampled bounce (off one of these mirrors, a sphere
       from outside, then a sampleable light) and the connection are weighed by the power
       heuristic of their pdfs at x (Veach 1997), as next-event estimation and the bounce
       are for a light seen directly: a small light's image takes the connection, a large
       one the bounce (every other path as before).
   Unbiased: the mean of a Lambert point's radiance through a mirror sphere and through a
   mirror quad, lit by a small and by a large light, equals its irradiance integrated in
   double over the hemisphere; with the small light at a hundredth to a fiftieth of the plain
   estimator's variance, with the large one below it (tests/test_fovpt_mirror.c).
   Not covered (plain sampling as before): glass, mirror boxes, planes and mesh triangles,
   two or more mirror bounces in a row, the inside of a mirror sphere, Whitted mode.
   Cost: a root solve and up to two shadow rays per diffuse vertex where the scene has a
   mirror sphere or quad (no cost and every image bit for bit as before where it has none, and
   with mirror_nee 0, the default). Measured: bench/README.md (`bench_pt --mirror-nee`, the
   rows <method>_mn).

DOES NOT
   - use a GPU API, start threads, allocate memory, or read or write files;
   - keep any global or thread-local state;
   - texture, instance or animate geometry (build a new scene instead).

CONFIGURATION (define before including the implementation)
   FOVPT_STATIC         all functions static (use it when two libraries embed this header)
   FOVPT_API            override the linkage of every public function
   FOVPT_MAX_DIM        hard cap on image width and height                (default 65536)
   FOVPT_MAX_PRIMS      hard cap on primitives (shapes + triangles)       (default and maximum 2^26)
   FOVPT_MAX_BVH_DEPTH  BVH depth cap; traversal stack W - 1 entries per level (default 64)
   FOVPT_NO_SIMD        no SSE / AVX / NEON / SIMD128 in the BVH traversal and no SSE2 in
                        the denoiser's a-trous pass (the scalar twins: same hits, the same
                        denoised image bit for bit, slower)
   FOVPT_BVH_WIDTH      children per traversal node, 4 or 8  (default 8; 4 with FOVPT_NO_SIMD)
   FOVPT_MAX_BOUNCES    hard cap on max_depth                             (default 1024)
   FOVPT_MAX_SPP        hard cap on samples per pixel per frame           (default 65536)
   FOVPT_MAX_RADIANCE   a sample's radiance is clamped per channel to this (at most FLT_MAX),
                        so sums and squares over FOVPT_MAX_SPP samples stay finite
                                                                          (default 1e16)
   FOVPT_MAX_LAYERS     entries of the layer table                         (default 8)
   FOVPT_ROBUST_MAX     cfg.robust's largest group count                  (default 16)
   FOVPT_ROBUST_MIN_GROUP  samples per group at least (cfg.robust)        (default 8)
   FOVPT_ROBUST_GINI    the group means' Gini coefficient above which cfg.robust takes the
                        median group                                      (default 0.25)
   FOVPT_ACUITY_GAMMA   fovpt_config_acuity with acuity_budget > 0 minimises the mean of
                        (eye-filtered variance)^gamma                     (default 0.5)
   FOVPT_ACUITY_CELL_JITTER  cell_jitter fovpt_config_acuity sets, 0 or 1  (default 1)
   FOVPT_ACUITY_NOISE_MARGIN fovpt_config_acuity, acuity_budget 0: the coarse layers' spp
                        times this over the equal-noise rule              (default 1)
   FOVPT_ACUITY_CLAMP_WHITE  clamp_white fovpt_config_acuity sets          (default 1)
   FOVPT_MAX_WHITTED    hard cap on the Whitted depth (branch stack)      (default 16)
   FOVPT_RAY_EPS        relative offset of secondary ray origins          (default 1e-4)
   FOVPT_DN_MAX_LEVELS  hard cap on the denoiser's a-trous passes         (default 8)
   Shared by the three headers (listed in the shared declarations block below):
   FOV_DLL, FOV_ASSERT, FOV_NO_LIBM, the math hooks FOV_SQRTF ... FOV_POWF, FOV_MEMSET,
   FOV_MEMCPY and FOV_NO_ERROR_STRINGS.

MEMORY
   The caller owns every byte; blocks must be 8-byte aligned (malloc's and uint64_t arrays
   are). fovpt_scene_size() gives the bytes for a scene description
   (primitives, binary BVH nodes (32 bytes each, up to 2n - 1 for n bounded primitives),
   traversal nodes (256 bytes each, 128 with FOVPT_BVH_WIDTH 4; up to n/5 + n/(W - 1) + 1,
   n/2 + n/(W - 1) + 1 with FOVPT_NO_SIMD), build data reused for the leaf triangles (60
   bytes per leaf slot: n rounded up to a multiple of 4, plus 4 ceil(n/16) slots for the
   padding that keeps a leaf of up to 4 in one block of 4; at most 2^26 slots), the leaf
   order (4 bytes per slot), light table);
   fovpt_scene_build() builds into them.
   fovpt_memory_size() gives the working memory of a context (UNIFORM: 16 bytes per pixel,
   the progressive accumulator; LAYERS, ZONES: 16 bytes per lattice point of every layer,
   (W/d + 2)(H/d + 2) each; SELECTIVE, JIN: 68 bytes per pixel, plus 32 per pixel and frame
   of history with temporal options: 2 frames for reuse, n_tpi + 1 for smoothing). Images are
   caller buffers with an explicit row stride. Stack use per entry point: about 7 KiB at
   most with 8-wide nodes, 4.5 KiB with 4 (gcc -O2, x86-64, -fstack-usage, frames along the
   deepest chain: trace_rows 0.8 KiB, radiance 2.1 KiB with the Whitted branch stack of
   2 * FOVPT_MAX_WHITTED entries, traversal 4.1 KiB: W - 1 entries of 8 bytes (node, entry
   distance) per depth level, 3.6 KiB with 8-wide nodes, 1.5 KiB with 4; the BVH build 2.5
   KiB (the work stack of FOVPT_MAX_BVH_DEPTH entries and 32 bins), its collapse 3.7 KiB;
   resolve_rows 2 KiB). Lower FOVPT_MAX_BVH_DEPTH to save stack.
   The denoiser: fovpt_denoise_size (204 bytes per pixel, 164 with cfg.no_sure) into caller
   memory (fovpt_denoise_init); its input image and guide buffers are caller buffers with
   strides.

ERRORS AND LOGGING
   Every fallible function returns fov_result: FOV_OK (0) or a negative code;
   fovpt_result_string() never returns NULL. Rejected before any work is done: NULL
   pointers; zero, overflowing or over-cap sizes and counts; NaN or infinite vertices,
   camera, gaze or parameters; degenerate triangles, spheres of radius <= 0, inverted boxes,
   zero normals, quads of zero area (lights or not); indices out of range; a BVH deeper than
   the cap (FOV_ERR_LIMIT); bad layer tables (radii not decreasing with the layer index,
   stride < 1), and every out-of-range config field. Non-finite radiance (from a user hook,
   say) is replaced by black and counted in fovpt_stats.bad_samples, and finite radiance is
   clamped at FOVPT_MAX_RADIANCE (an emission near FLT_MAX summed to infinity before 0.10.0):
   images never hold NaN or infinity.
   Messages are on by default (no FOV_DEBUG needed). desc.logger (fovpt_scene_size,
   fovpt_scene_build) and cfg.logger (fovpt_config_resolve, fovpt_memory_size, fovpt_init,
   fovpt_radiance and the calls on the context, which keeps a copy) receive each error once:
   its code, the source line and a message naming the field and the rule, such as
   "config.layers.layer[2].stride must be >= 1" or "scene: meshes[].indices >= num_vertices".
   A logger that prints them:
      static void log_err(const char *tag, uint32_t level, int32_t code, const char *msg,
                          uint32_t line, void *user)
      { (void)level; (void)user; fprintf(stderr, "%s %d (%s): %s [line %u]\n", tag, (int)code,
                fovpt_result_string((fov_result)code), msg, (unsigned)line); }
      cfg.logger.func = log_err;            // and desc.logger.func = log_err for the scene
   No logger, the code only: fovpt_camera_ray, fovpt_gaze_from_point, fovpt_camera_eyes,
   fovpt_layers_preset, fovpt_tau_fov, fovpt_ecc_init, and a NULL config, description or
   context. FOV_NO_ERROR_STRINGS drops the texts (about 7 KB of a Cortex-M4 -Os build): the
   logger still gets each code and line, with msg "" (never NULL); fovpt_result_string "".

THREADING
   No state outside the objects you pass. A built scene is read-only. fovpt_init fills a
   context whose settings are read-only; fovpt_trace_rows on disjoint row ranges may run on
   as many threads as you like (each with its own fovpt_stats, summed by fovpt_stats_add),
   then, after all of them, fovpt_refine_rows (SELECTIVE, JIN) and after that
   fovpt_resolve_rows, each on disjoint rows. Results do not depend on the split.
   The denoiser likewise: fovpt_denoise_frame, then fovpt_denoise_temporal_rows on every row,
   then each a-trous pass (fovpt_denoise_atrous_rows, pass 0, 1, ...) on every row before the
   next pass starts, then fovpt_denoise_resolve_rows (a barrier between phases).

NUMERICS
   - float only. Secondary rays start at the hit point moved along the normal by
     FOVPT_RAY_EPS * (1 + max |coordinate|) (default 1e-4): keep scenes of size 1e-2 .. 1e3
     around the origin.
   - BVH = brute force: the box test is conservative, so fovpt_intersect and fovpt_occluded
     find every hit fovpt_intersect_brute finds (same t: both run the same primitive tests;
     the four-lane triangle test performs the same float operations in the same order on
     every SIMD path, FMA contraction off: the implementation turns it off itself, for gcc
     in every mode and for clang, whose -ffp-contract=fast and -ffast-math override that).
     The closest hit is canonical: the smallest t, and among equal t the lowest primitive
     slot (the brute-force loop's order), whatever order the traversal visits the leaves in,
     so the BVH returns the same primitive too.
     Slabs (Kay-Kajiya) with 1 / d = +inf for a zero direction component; a ray lying in a
     slab's face plane gives 0 * inf = NaN, which the max/min operand order drops (the slab
     does not constrain it), on every SIMD path and the scalar one (FOVPT_NO_SIMD,
     Cortex-M; the BVH = brute force test runs on each: tests/xtarget); boxes of zero
     thickness and rays starting on a face are inside. Each box's exit distance is widened
     to exit * (1 + 2^-21) (+ 2^-19 |tmin| when tmin < 0) before the comparison (Ize 2013,
     "Robust BVH Ray Traversal": a slab distance is within gamma(3) of its exact value), and
     the boxes of triangles, quads and spheres are padded by 2^-21 of their largest coordinate
     magnitude (the triangle records hold v0 and rounded edges; the float tests accept points a
     few ulps outside). Checked against
     brute force on adversarial scenes (flat axis-aligned quads, rays in faces and along
     axes, grazing rays, zero-thickness boxes, 1e-3 .. 1e5 scales, bvh_min_prims 1 .. 4:
     1.5 million rays, no miss). The only brute-force hits the BVH may skip lie outside
     their primitive's box: rays (almost) in a triangle's plane whose t the float test
     cannot resolve (about 1 in 10^5 of those adversarial rays). A ray with a direction
     component that is not 0 but below FLT_MIN in magnitude (its reciprocal, or that times
     the margin, overflows, and a box 2^-100 thin beside the origin was culled: every such
     hit lost before 0.9.0) is traced by the brute-force loop (tested).
   - The triangle test (Moller-Trumbore) is not watertight: a ray aimed exactly at a shared
     edge (to float precision) hits neither triangle in about 10 % of the cases; random
     rays from inside a closed 3072-triangle mesh: none of 200000 leaked.
   - Vectors of any finite length are normalised (prescaled when their squared length
     would under- or overflow): camera vectors, plane and hook normals, triangle and quad
     normals, ray directions (the ray tests scale a direction outside [2^-32, 2^32] by a
     power of two, exactly). fovpt_camera_ray returns FOV_ERR_INVALID_ARG for an image
     point whose image-plane offset overflows (|x| or |y| near FLT_MAX / the tangent);
     every FOV_OK ray is finite and unit. Triangle tests multiply three coordinates:
     coordinates and ray origins up to about 1e12 (beyond, the products overflow and rays
     miss); triangles with edges up to 1e19 build.
   - Random streams are 32-bit integer hashes: identical on every target. Images are
     identical across targets up to libm differences (tests/xtarget states the tolerance).

PLATFORM NOTES
   - Freestanding: the implementation includes only <stddef.h>, <stdint.h>, <float.h> and
     <limits.h> when FOV_NO_LIBM (or all math hooks) and FOV_ASSERT are defined, plus
     <xmmintrin.h> on x86 with SSE (and <emmintrin.h> with SSE2, <immintrin.h> with AVX),
     <arm_neon.h> on AArch64, <wasm_simd128.h> on wasm32 with -msimd128 (define
     FOVPT_NO_SIMD to leave them out).
   - wasm32: clang --target=wasm32 -ffreestanding -nostdlib -DFOV_NO_LIBM works as is.
   - Cortex-M4F: arm-none-eabi-gcc -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard; no
     __aeabi_d* routine is referenced (checked by tests/compile).

REFERENCES (cited above and below by author and year, with the section, equation, figure or
table of that work; "the thesis" in a Phong or Catmull-Rom comment is Axblad 2020)
   Axblad 2020      T. Axblad, "Impact of Foveated Rendering on Path Tracing Frame Rate in
                    Head-Mounted VR Displays", master's thesis, KTH Royal Institute of
                    Technology, Stockholm, 2020. (LAYERS, the Phong BRDF, the path tracer)
   Kim et al. 2021  Y. Kim, Y. Ko, I. Ihm, "Selective Foveated Ray Tracing for Head-Mounted
                    Displays", IEEE International Symposium on Mixed and Augmented Reality
                    (ISMAR), 2021, pp. 413-421. (SELECTIVE, the Whitted tracer, temporal)
   Polychronakis 2025  A. Polychronakis, "Implicit and Foveated Techniques for Real-Time
                    Computer Graphics Rendering", doctoral dissertation, Technical University
                    of Crete, 2025; ch. 4 is Polychronakis, Koulieris, Mania, "Emulating
                    Foveated Path Tracing", ACM SIGGRAPH Motion, Interaction and Games (MIG),
                    2021. (ZONES)
   Jin et al. 2009  B. Jin, I. Ihm, B. Chang, C. Park, W. Lee, S. Jung, "Selective and Adaptive
                    Supersampling for Real-Time Ray Tracing", High Performance Graphics 2009.
   Kajiya 1986      J. T. Kajiya, "The Rendering Equation", SIGGRAPH 1986.
   Guenter et al. 2012  B. Guenter, M. Finch, S. Drucker, D. Tan, J. Snyder, "Foveated 3D
                    Graphics", ACM Transactions on Graphics 31(6) (SIGGRAPH Asia), 2012. (the
                    eye model of fovpt_config_acuity)
   Veach 1997       E. Veach, "Robust Monte Carlo Methods for Light Transport Simulation",
                    PhD thesis, Stanford University, 1997 (multiple importance sampling).
   Wald 2007        I. Wald, "On Fast Construction of SAH-based Bounding Volume Hierarchies",
                    IEEE Symposium on Interactive Ray Tracing, 2007.
   Ize 2013         T. Ize, "Robust BVH Ray Traversal", Journal of Computer Graphics
                    Techniques 2(2), 2013.
   Kay & Kajiya 1986  T. L. Kay, J. T. Kajiya, "Ray Tracing Complex Scenes", SIGGRAPH 1986.
   Moller & Trumbore 1997  T. Moller, B. Trumbore, "Fast, Minimum Storage Ray-Triangle
                    Intersection", Journal of Graphics Tools 2(1), 1997.
   Dammertz et al. 2010  H. Dammertz, D. Sewtz, J. Hanika, H. P. A. Lensch, "Edge-Avoiding
                    A-Trous Wavelet Transform for fast Global Illumination Filtering", High
                    Performance Graphics 2010. (the denoiser's spatial filter)
   Schied et al. 2017  C. Schied, A. Kaplanyan, C. Wyman, A. Patney, C. R. A. Chaitanya,
                    J. Burgess, S. Liu, C. Dachsbacher, A. Lefohn, M. Salvi, "Spatiotemporal
                    Variance-Guided Filtering: Real-Time Reconstruction for Path-Traced Global
                    Illumination", High Performance Graphics 2017. (variance guidance, the
                    edge-stopping functions, temporal accumulation)
   Koskela et al. 2019  M. Koskela, A. Lotvonen, M. Makitalo, P. Kivi, T. Viitanen,
                    P. Jaaskelainen, "Foveated Real-Time Path Tracing in Visual-Polar Space",
                    Eurographics Symposium on Rendering (EGSR, DL-only and Industry Track),
                    2019. (path tracing in a polar sample space, fovpt_shade_points)
   Meng et al. 2018 X. Meng, R. Du, M. Zwicker, A. Varshney, "Kernel Foveated Rendering",
                    Proceedings of the ACM on Computer Graphics and Interactive Techniques
                    1(1), article 5, 2018. (the kernel log-polar mapping of fovlp.h)
   Sobol 1967       I. M. Sobol', "On the distribution of points in a cube and the approximate
                    evaluation of integrals", USSR Computational Mathematics and Mathematical
                    Physics 7(4), 1967. (SAMPLERS)
   Owen 1995        A. B. Owen, "Randomly Permuted (t,m,s)-Nets and (t,s)-Sequences", Monte
                    Carlo and Quasi-Monte Carlo Methods in Scientific Computing, Lecture Notes
                    in Statistics 106, Springer, 1995. (nested uniform scrambling)
   Laine & Karras 2011  S. Laine, T. Karras, "Stratified Sampling for Stochastic
                    Transparency", Computer Graphics Forum 30(4) (EGSR), 2011. (the hash)
   Burley 2020      B. Burley, "Practical Hash-based Owen Scrambling", Journal of Computer
                    Graphics Techniques 9(4), 2020. (shuffled, scrambled Sobol; its constants)
   Duff et al. 2017 T. Duff, J. Burgess, P. Christensen, C. Hery, A. Kensler, M. Liani,
                    R. Villemin, "Building an Orthonormal Basis, Revisited", Journal of
                    Computer Graphics Techniques 6(1), 2017.
   Mitchell & Hanrahan 1992  D. Mitchell, P. Hanrahan, "Illumination from Curved
                    Reflectors", SIGGRAPH 1992. (NEXT-EVENT ESTIMATION THROUGH MIRRORS)
   Hanika et al. 2015  J. Hanika, M. Droske, L. Fascione, "Manifold Next Event Estimation",
                    Computer Graphics Forum 34(4) (EGSR), 2015.
   Li et al. 2012   T.-M. Li, Y.-T. Wu, Y.-Y. Chuang, "SURE-based Optimization for Adaptive
                    Sampling and Reconstruction", ACM Transactions on Graphics 31(6) (SIGGRAPH
                    Asia), 2012. (the denoiser's per-pixel selection)

LICENSE: see end of file.

RECENT REVISION HISTORY
   0.14.0 (2026-12-06) The default sampler is SOBOL (SAMPLERS): cfg.sampler 0 is now
                      FOVPT_SAMPLER_DEFAULT, which fovpt_config_resolve turns into
                      FOVPT_SAMPLER_SOBOL (1, unchanged) and fovpt_shade_points reads as
                      SOBOL; FOVPT_SAMPLER_RANDOM moved from 0 to 2 (code that names it keeps
                      RANDOM; code that leaves the field 0 now gets stratified samples: at
                      equal samples +2.6 to +6.4 dB on the terrain, the cubes and the mirrors,
                      for 12-20 % more instructions per frame). Images of a default config
                      change; their mean does not. FOVPT_SAMPLER_RANDOM renders 0.13.0's
                      images bit for bit; a sampler value of 0 that was stored, computed or
                      passed as a number now means SOBOL, and 2 is no longer rejected
                      (_FOVPT_SAMPLER_NUM is 3). Found by a new fuzzing target of the guides
                      and the denoiser (tests/fuzz/fuzz_fovpt_dn.c): the depth guide is the
                      mean hit distance where the distances sum beyond FLT_MAX (was inf);
                      the denoiser normalises a normal guide longer than unit and reads a
                      non-finite one as (0, 0, 0) (with phi_normal below 32 such a normal
                      gave NaN pixels).
   0.13.0 (2026-12-06) A bounded shape (sphere, quad, box) is a BVH leaf of its own, never in a
                      combined leaf block, so the W-wide node's box test culls it: Cornell
                      box frames 1.6-1.7x fewer instructions, the mirror room and the
                      interior 1.4-1.5x, the same images; the scene memory reserves up to
                      (n + 3 shapes) / 5 more W-wide nodes with SIMD. The implementation
                      turns FMA contraction off itself (gcc in every mode, clang but for
                      -ffp-contract=fast / -ffast-math): built with -mfma in gnu mode, the
                      BVH had missed hits that brute force finds. AVX node test: slab
                      distances as (o - plane) * -inv, the same floats (3-4 % fewer
                      instructions per terrain ray). The denoiser runs 10-22 % fewer
                      instructions: the SSE2 pass takes only 3 x 3 taps where all 4 lanes do
                      and runs at the image borders too (bit-identical), and a pass after the
                      first leaves a pixel whose running variance is below (skip_noise / 8)^2
                      (PSNR per field within 0.001 dB on the bench's scenes).
   0.12.0 (2026-12-05) cfg.mirror_nee (NEXT-EVENT ESTIMATION THROUGH MIRRORS): next-event
                      estimation through mirror spheres and quads (Mitchell and Hanrahan 1992),
                      unbiased, opt-in; fovpt_scene.mirrors / num_mirrors list them (the scene
                      memory grows by 4 bytes per mirror). The field follows robust in
                      fovpt_config (positional initialisers of the later fields move).
                      The denoiser keeps per pixel (>= sure_min_spp own samples) its input or
                      one a-trous pass's output by Stein's unbiased risk estimate (Li et al.
                      2012; cfg.no_sure, sure_radius, sure_min_spp; fovpt_denoise_size 204
                      bytes per pixel, was 164): fovea +1.5 .. +2.2 dB on the cubes and the
                      mirrors on the same frames; the guide's var is -1 in LAYERS / ZONES blend
                      bands (two layers' mix).
                      Traversal: the SIMD leaf runs the whole triangle test (no early exit
                      on u), three hit children are ordered by a branch-free sorting
                      network, AVX leaves broadcast the ray from its record: 3-5 % fewer
                      instructions per terrain ray (AVX2), same hits, images identical.
   0.11.0 (2026-12-05) cfg.robust (ROBUST PIXEL ESTIMATE): an opt-in adaptive median of means
                      against caustic specks (Buisine et al. 2021), the camera's specular
                      chains kept as a plain mean; off by default (every image as before); at
                      equal time the Cornell box's fovea +3.7 / +4.1 dB (layers_fovea, centre /
                      corner gaze); the field follows sampler in fovpt_config (positional
                      initialisers of the later fields move). Traversal: one SIMD pass at the
                      ray entry of fovpt_intersect and fovpt_occluded (finiteness, routing and
                      1/d by one 4-lane division; the scalar entry is its twin), the ray's
                      octant instead of six plane indices, the leaf's lanes from one mask and
                      no not-a-triangle lanes in triangle-only scenes: 13-20 % fewer
                      instructions per ray with SIMD, 1.05-1.21x side by side against 0.10.0;
                      same hits. fovpt__lanczos_value (dead since 0.10.0) removed.
   0.10.0 (2026-12-05) BVH: with SIMD a binary subtree of <= 4 primitives is opened by its
                      W-wide parent while it has room, else it is one leaf child laid out in
                      one block of 4 lanes (padding slots: fovpt_scene gains num_slots); the
                      SAH prices a leaf in whole blocks. 8-wide nodes hold 6.6 children (3.5
                      before) and are the default with any SIMD (FOVPT_BVH_WIDTH 8: two 4-lane
                      passes per node without AVX; 4 with FOVPT_NO_SIMD); scene memory about
                      300 bytes per triangle (303 SSE2, 361 AVX2); same hits. Side by side
                      against 0.9.0: terrain AVX2 1.14 / 1.17x (camera / bounce), Cornell box
                      up to 1.41x; SSE2 8-wide against 4-wide 1.08 / 1.11x on the terrain,
                      1.14-1.27x camera on the small scenes. A sample's radiance
                      is clamped per channel at FOVPT_MAX_RADIANCE (1e16): an emission near
                      FLT_MAX summed to +inf in the image (a fuzzer finding). LAYERS / ZONES:
                      the resolve sums each lattice column once per row, ZONES' Lanczos weights
                      take three sines per axis (4a before), eccentricity thresholds are tested
                      without atan2 where they decide (resolve and trace): 7 % (LAYERS) and 17 %
                      (ZONES) fewer instructions per 4 spp frame, images within rounding.
   0.9.0 (2026-12-05) A stratified sampler (SAMPLERS): cfg.sampler = FOVPT_SAMPLER_SOBOL,
                      fovpt_rng_init_sobol, enum fovpt_sampler; fovpt_config gains `sampler`
                      after `accumulate` (positional initialisers of the later fields move),
                      fovpt_rng grows to 32 bytes. Default RANDOM: images unchanged.
                      BVH: the box test's margin folded into the far planes' reciprocals
                      (Ize 2013), leaf blocks carry slot, id, material and normal so a hit
                      does not read the primitive record (scene memory 303 bytes per
                      triangle, was 279; same hits): terrain 1.10 / 1.20x (SSE2, camera /
                      bounce), 1.15 / 1.17x (AVX2) side by side. Rays with a direction
                      component in (0, FLT_MIN) take the brute-force loop (their boxes could
                      be culled: a hit the BVH lost, 0.8.0 too). Denoiser: an SSE2 a-trous
                      pass, bit-identical to the scalar one, 1.7-1.85x faster filter.
   0.8.0 (2026-12-05) Denoiser: phi_normal 32 by default (was 128): faceted and bumpy surfaces
                      are filtered as one surface, creases of 30 degrees or more stay edges; the
                      fast -ln c series serves every phi_normal >= 32 (absolute weight error
                      below 3.2e-6).
   0.7.0 (2026-12-05) BVH traversal: hit children by the lowest set bit of the hit mask, three
                      or more sorted on the stack, no separate root box test, per-ray broadcasts out
                      of the leaves (6-18 % fewer instructions per ray, same hits); an empty
                      child of a wide node returns at once (a tmin rescaled to -inf reached it
                      and read past the leaves: a fuzzer finding).
                      Denoiser about 3x cheaper: 3x3 taps where the pixel is coarse (r_small), fewer
                      passes above spp_full samples, none where the noise is below skip_noise (new
                      fields). One trace loop with an optional guide sink. fovpt_gaze_predict
                      (shared block revision 5); the FOVPT_MAX_* limits in the declarations.
   0.6.0 (2026-12-05) BVH: leaf triangles in SoA groups of four tested four at a time; one 4-lane
                      SIMD layer for SSE, NEON (AArch64) and wasm SIMD128 with a scalar twin
                      (FOVPT_NO_SIMD); FOVPT_BVH_WIDTH 4 or 8 (8 with AVX2); the closest hit is
                      canonical (smallest t, then the lowest primitive slot: brute force's rule),
                      images unchanged; a smaller scene memory reserve (279 bytes per triangle, was
                      300). Guide buffers (fovpt_guide, fovpt_trace_rows_guide, fovpt_render_guide)
                      and a foveated denoiser (fovpt_denoise_*: temporal reprojection and an edge-
                      avoiding a-trous filter after Dammertz et al. 2010 and Schied et al. 2017,
                      strength and history weight by eccentricity and sample density; caller memory,
                      row phases). fovpt_shade_points: path or Whitted radiance at arbitrary image
                      points (fovlp.h's log-polar samples; Koskela et al. 2019). Gaze input from the
                      shared block of revision 4 (fovpt_gaze_filter_*, fovpt_gaze_margin,
                      fovpt_config_gaze_margin, fovpt_gaze_fixed).
   0.5.0 (2026-12-05) fovpt_config_acuity sets the samples from the eye model: spp per layer /
                      zone for equal eye-filtered noise (acuity_budget 0, new field) or
                      spread for the least mean noise at a budget (acuity_budget > 0); new
                      fields layers.hollow / zones.hollow (no layer traced under a finer one;
                      UNIFORM's streams: a display coarser than the eye costs and shows exactly
                      UNIFORM), layers.cell_jitter / zones.cell_jitter (samples over the
                      lattice cell: prefiltered), layers.clamp_white / zones.clamp_white,
                      zones.spp[3]; all zero by default (presets'
                      images unchanged). fovpt_config_acuity no longer keeps the caller's layer
                      spp (set them after the call to override). The shared block of
                      revision 3: fov_eye's default quality is 0.5 (was 1; fov_eye). Fix: a
                      second fovpt_config_acuity call no longer moves the selective borders
                      by float rounding.
   0.4.0 (2026-12-02) fovpt_config_acuity: the layer table (radii, strides from a ladder), the
                      zone radii and the selective borders from the display and the shared eye
                      model (fov_eye, fovpt_eye_plan; Guenter et al. 2012), presets kept by
                      name; layers.bspline (new field): a smoothing cubic B-spline reconstruction
                      of the coarse layers; bench/pt_acuity.c. Fix: a hit whose t along a huge
                      or tiny direction (rescaled by 2^k) rounds onto tmin or tmax is reported
                      at the nearest float inside the interval by fovpt_intersect, brute force
                      and fovpt_occluded alike (before, intersect could miss what occluded hit).
   0.3.0 (2026-12-02) one block shared with fovsdf.h and fovlp.h (tools/fov_shared.h); error
                      messages on by default, a specific one per failure naming the field;
                      fov_camera shared: fovpt_camera is a typedef of it, new field eye_offset
                      (honoured: the pinhole moves along right); fovpt_camera_init now stands at
                      (0, 0, 5) looking at the origin (it was at the origin looking along +z);
                      fovpt_stats_init, fovpt_stats_add, what adds to fovpt_stats documented;
                      fovpt_radiance adds its rays to stats.rays; fovpt_config_resolve checks
                      the display; fovpt_ecc_deg finite beyond 1e19 px (the shared model);
                      REFERENCES cite every paper.
   0.2.1 (2026-12-01) the BVH finds every hit brute force finds: a conservative box test on the
                      SSE and scalar paths (rays lying in a box face, zero direction
                      components, a rounding margin after Ize 2013, padded primitive boxes);
                      fovpt_camera_ray always unit or FOV_ERR_INVALID_ARG; vectors of any
                      length normalised; directions of length ~1e30, huge triangles and
                      degenerate sphere normals handled; skip_degenerate keeps the
                      documented primitive ids; FOVPT_VERSION_STRING matches (said 0.1.0).
   0.2.0 (2026-11-23) review fixes: a LAYERS layer whose stride exceeds the image with the
                      gaze off it keeps one lattice point (it read before its buffer); hook
                      and plane normals and camera vectors of any length; a failed
                      fovpt_set_view leaves the view unchanged; fovpt_radiance logs; any
                      finite gaze accepted (shared eccentricity model);
                      4-wide BVH for the traversal (collapsed from the binary SAH tree; SSE
                      four-box test on x86): callgrind 64.5M -> 40.3M instructions on the
                      throughput loop, 0.49 -> 0.59-0.62x of Embree's single thread, same hits;
                      per-eye gaze: fovpt_gaze_from_point (a 3D gaze target or direction
                      to an eye's gaze point), fovpt_camera_eyes (two eye cameras from a
                      head camera and the interpupillary distance);
                      faster BVH traversal (sign-picked slabs, siblings tested together, far
                      child pushed with its entry distance, leaf-ordered triangles, deferred
                      division; SAH defaults 16 bins, leaf 2, traversal cost 1.5):
                      0.38x -> 0.49x of Embree's single-thread rays/s; same hits. Tried
                      and not kept: an SSE test of both children's boxes in one 4-lane pass
                      (a 64-byte node with the child boxes side by side; same hits): callgrind
                      instructions -19 %, CPU time unchanged in interleaved runs against Embree.
   0.1.0 (2026-11-23) first release: geometry, BVH, path and Whitted tracers, UNIFORM method.
*/

#if defined(FOV_IMPL) && !defined(FOVPT_IMPLEMENTATION)
#define FOVPT_IMPLEMENTATION
#endif

#ifndef FOVPT_H_INCLUDED
#define FOVPT_H_INCLUDED

#include <stddef.h>
#include <stdint.h>

#define FOVPT_VERSION_MAJOR 0
#define FOVPT_VERSION_MINOR 14
#define FOVPT_VERSION_PATCH 0
#define FOVPT_VERSION_STRING "0.14.0"

#ifndef FOVPT_MAX_LAYERS
#define FOVPT_MAX_LAYERS 8
#endif
#ifndef FOVPT_ACUITY_GAMMA
#define FOVPT_ACUITY_GAMMA 0.5f
#endif
#ifndef FOVPT_ACUITY_CELL_JITTER
#define FOVPT_ACUITY_CELL_JITTER 1u
#endif
#ifndef FOVPT_ACUITY_CLAMP_WHITE
#define FOVPT_ACUITY_CLAMP_WHITE 1.0f
#endif
#ifndef FOVPT_ACUITY_NOISE_MARGIN
#define FOVPT_ACUITY_NOISE_MARGIN 1.0f
#endif

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

#ifndef FOVPT_API
#if defined(FOVPT_STATIC)
#define FOVPT_API static FOV__UNUSED
#elif defined(FOVPT_IMPLEMENTATION)
#define FOVPT_API FOV__API_EXPORT
#else
#define FOVPT_API FOV__API_IMPORT
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ==== geometry and materials =============================================================== */

typedef enum fovpt_shape_type {
    FOVPT_SHAPE_SPHERE = 0, /* p = centre, r = radius (> 0) */
    FOVPT_SHAPE_PLANE = 1,  /* p = a point on it, u = normal (non-zero; front side) */
    FOVPT_SHAPE_QUAD = 2,   /* parallelogram p + s u + t v, s, t in [0, 1]; normal u x v */
    FOVPT_SHAPE_BOX = 3,    /* axis-aligned, p = min corner, u = max corner (u >= p, not flat
                               in more than one axis) */
    _FOVPT_SHAPE_NUM,
    _FOVPT_SHAPE_FORCE_U32 = 0x7FFFFFFF
} fovpt_shape_type;

typedef struct fovpt_shape {
    uint32_t type;      /* fovpt_shape_type */
    uint32_t material;  /* index into the scene's materials */
    float p[3], u[3], v[3];
    float r;
} fovpt_shape;

/* A triangle mesh: num_triangles triples of vertex indices (or, when indices is NULL,
   consecutive vertex triples). Triangle k of the mesh reports the primitive id
   num_shapes + (triangles of the meshes before it) + k. */
typedef struct fovpt_mesh {
    const float *positions;    /* 3 floats per vertex */
    uint32_t num_vertices;
    const uint32_t *indices;   /* 3 per triangle, or NULL */
    uint32_t num_triangles;
    uint32_t material;
} fovpt_mesh;

typedef enum fovpt_material_type {
    FOVPT_MAT_LAMBERT = 0,    /* albedo kd: f = kd / pi */
    FOVPT_MAT_PHONG = 1,      /* Axblad 2020 Eq. 3.7-3.8: kd/pi + ks (a+2)/(2pi) max(0,wr.wi)^a */
    FOVPT_MAT_MIRROR = 2,     /* perfect reflection tinted by albedo */
    FOVPT_MAT_DIELECTRIC = 3, /* smooth glass of index ior, Fresnel-weighted, tinted by albedo */
    _FOVPT_MAT_NUM,
    _FOVPT_MAT_FORCE_U32 = 0x7FFFFFFF
} fovpt_material_type;

typedef struct fovpt_material {
    uint32_t type;        /* fovpt_material_type */
    float albedo[3];      /* kd (Lambert, Phong) or tint (mirror, dielectric), each in [0, 1] */
    float specular[3];    /* ks (Phong), each in [0, 1]; kd + ks <= 1 conserves energy */
    float exponent;       /* Phong a >= 0 */
    float ior;            /* dielectric index of refraction > 0 (1.5 glass) */
    float emission[3];    /* emitted radiance, >= 0, on both faces */
} fovpt_material;

/* User geometry (an SDF traced by fovsdf, for example). Called for every ray with the
   current closest t as tmax; returns 1 and fills *t in (tmin, tmax), n (any length, facing
   anywhere) and *material when it hits, else 0. Reported as primitive FOVPT_PRIM_USER. */
typedef int (*fovpt_user_hit_fn)(const float org[3], const float dir[3], float tmin, float tmax,
                                 float *t, float n[3], uint32_t *material, void *user);
#define FOVPT_PRIM_USER 0xFFFFFFFEu
#define FOVPT_PRIM_NONE 0xFFFFFFFFu

typedef struct fovpt_scene_desc {
    const fovpt_shape *shapes;       uint32_t num_shapes;
    const fovpt_mesh *meshes;        uint32_t num_meshes;
    const fovpt_material *materials; uint32_t num_materials;   /* at least 1 */
    float background[3];       /* radiance of rays that leave the scene (>= 0) */
    fovpt_user_hit_fn user_hit;      void *user;
    uint32_t bvh_min_prims;    /* no BVH below this many bounded primitives       0: 8 */
    uint32_t bvh_bins;         /* SAH bins per axis, 2 .. 32                      0: 16 */
    uint32_t bvh_leaf;         /* triangles per leaf when SAH finds no better     0: 2
                                  (1 .. 16; larger leaves only when SAH prefers them, up to 16;
                                  with SIMD the SAH counts a leaf's whole blocks of 4, and a
                                  subtree of <= 4 may be one leaf child of the W-wide tree);
                                  a bounded shape is always a leaf of its own (shapes with one
                                  centroid excepted) */
    uint32_t bvh_max_depth;    /* depth cap, 2 .. FOVPT_MAX_BVH_DEPTH; deeper is an error
                                                                       0: FOVPT_MAX_BVH_DEPTH */
    uint32_t skip_degenerate;  /* 1: drop zero-area triangles instead of failing */
    fov_logger logger;
} fovpt_scene_desc;

/* A built scene: everything lives in the caller's memory. Read-only after the build. */
typedef struct fovpt_scene {
    const void *prims;         /* internal primitive records */
    const void *nodes;         /* BVH nodes (NULL: no BVH) */
    const uint32_t *order;     /* primitive order of the BVH leaves */
    const float *leaf_tris;    /* per leaf slot: v0, e1, e2 of a triangle (zeros otherwise), in
                                  SoA blocks of 4 slots: float[12][4] per block (v0, e1, e2,
                                  normal), then the 4 slots' primitive slot, id and material
                                  (uint32_t[3][4]) */
    const void *nodes4;        /* the BVH collapsed to 4 children per node (traversal) */
    uint32_t num_nodes4;
    uint32_t num_slots;        /* leaf slots in leaf_tris and order (a multiple of 4, at least
                                  num_bounded: a leaf of <= 4 starts a new block where it
                                  would straddle two; unused slots hold FOVPT_PRIM_NONE);
                                  0 without a BVH (order then has num_bounded entries) */
    const uint32_t *lights;    /* sampleable emitters (primitive slots) */
    const float *light_cdf;    /* cumulative selection probability */
    const float *light_area;
    const fovpt_material *materials;
    uint32_t num_prims, num_bounded, num_nodes, num_lights, num_materials, bvh_depth;
    uint32_t num_skipped;      /* degenerate triangles dropped (skip_degenerate) */
    float background[3];
    fovpt_user_hit_fn user_hit;
    void *user;
    float bounds_lo[3], bounds_hi[3];  /* of the bounded primitives */
    const uint32_t *mirrors;   /* primitive slots of the mirror spheres and quads (shapes of
                                  material FOVPT_MAT_MIRROR): cfg.mirror_nee's targets */
    uint32_t num_mirrors;
} fovpt_scene;

typedef struct fovpt_hit {
    float t;
    float p[3];        /* hit point */
    float n[3];        /* unit geometric normal as defined by the shape (not flipped) */
    uint32_t prim;     /* primitive id (see fovpt_mesh), FOVPT_PRIM_USER, or FOVPT_PRIM_NONE */
    uint32_t material;
    uint32_t slot;     /* internal primitive slot */
} fovpt_hit;

/* ==== camera ============================================================================== */

/* The shared camera, fov_camera (its declaration documents the frame, handedness, pixel
   convention and defaults). fovpt uses every field: the off-axis tangents tan_left ..
   tan_top (an HMD eye's frustum; each within 1e6, left + right and bottom + top > 1e-6) and
   eye_offset (the pinhole pos + eye_offset * right; fovpt_camera_eyes gives the two eyes of
   a head camera instead by moving pos and target). Size 1 .. FOVPT_MAX_DIM. */
typedef fov_camera fovpt_camera;

/* ==== rendering settings =================================================================== */

typedef enum fovpt_method {
    FOVPT_METHOD_UNIFORM = 0,   /* every pixel, spp samples per frame (non-foveated) */
    FOVPT_METHOD_LAYERS = 1,    /* Axblad 2020: gaze-centred lattice layers */
    FOVPT_METHOD_ZONES = 2,     /* Polychronakis 2025, ch. 4: zones at 1, 1/4, 1/16 density */
    FOVPT_METHOD_SELECTIVE = 3, /* Kim et al. 2021: selective foveated supersampling */
    FOVPT_METHOD_JIN = 4,       /* Jin et al. 2009: 4 samples per problematic subpixel */
    _FOVPT_METHOD_NUM,
    _FOVPT_METHOD_FORCE_U32 = 0x7FFFFFFF
} fovpt_method;

typedef enum fovpt_mode {
    FOVPT_MODE_PATH = 0,        /* Monte Carlo path tracing */
    FOVPT_MODE_WHITTED = 1,     /* Whitted-style ray tracing (Kim et al. 2021) */
    _FOVPT_MODE_NUM,
    _FOVPT_MODE_FORCE_U32 = 0x7FFFFFFF
} fovpt_mode;

typedef enum fovpt_sampler {    /* SAMPLERS */
    FOVPT_SAMPLER_DEFAULT = 0,  /* the library's choice: SOBOL (before 0.14.0: RANDOM) */
    FOVPT_SAMPLER_SOBOL = 1,    /* a pixel's samples stratified: scrambled Sobol (Burley 2020) */
    FOVPT_SAMPLER_RANDOM = 2,   /* independent numbers per (pixel, sample, frame) (was 0) */
    _FOVPT_SAMPLER_NUM,
    _FOVPT_SAMPLER_FORCE_U32 = 0x7FFFFFFF
} fovpt_sampler;

#define FOVPT_RR_OFF 0xFFFFFFFFu

/* Layers of Axblad 2020. layer[0] is the background layer, the highest index the innermost
   one (the indexing of its Eq. 3.2). Radii are eccentricities (degrees from the gaze, the
   shared model)
   and must decrease with the index; layer[0].radius_deg is the occlusion mask (rays beyond
   it are not traced; 0 = no mask). Lattice points of layer n: pixels (gx + k d, gy + l d)
   with (gx, gy) the gaze pixel (snapped to multiples of d when snap = 1; layer 0 does not
   move with the gaze) whose eccentricity is <= radius_deg + blend_deg / 2 (the blend band
   needs both layers). */
typedef struct fovpt_layer {
    float radius_deg;
    uint32_t stride;        /* d >= 1 */
    uint32_t spp;           /* samples per target pixel >= 1 */
} fovpt_layer;
typedef struct fovpt_layers_cfg {
    uint32_t count;         /* 2 .. FOVPT_MAX_LAYERS; 0: preset FOVPT_LAYERS_KTH_RADIUS */
    fovpt_layer layer[FOVPT_MAX_LAYERS];
    float blend_deg;        /* blend band width around each layer border; 0: 1 degree */
    uint32_t blend_linear;  /* 1: linear vb profile; 0: smoothstep */
    uint32_t snap;          /* 1: lattice origin snapped to multiples of d (no crawling) */
    uint32_t bspline;       /* 1: layers of stride >= 2 reconstructed by the cubic B-spline
                               (smoothing: averages the lattice's path-tracing noise) instead
                               of Catmull-Rom; 0: Catmull-Rom (Axblad 2020) */
    uint32_t hollow;        /* 1: a layer is traced only where the resolve reads it, outside
                               the next finer layer's full-weight disk less the filter's reach
                               (see LAYERS), and a pixel's k-th sample is the same stream in
                               every layer, as in UNIFORM: a table whose stride-1 layer covers
                               the image gives UNIFORM's samples and image; 0: every layer
                               covers its whole disk, streams per layer (Axblad 2020) */
    uint32_t cell_jitter;   /* 1: a stride-d layer's samples jitter over the d x d pixels
                               centred on its lattice point (a box prefilter: edges and detail
                               finer than the lattice turn into noise, which spp averages,
                               instead of aliasing); 0: inside the lattice point's pixel */
    float clamp_white;      /* > 0: a stride >= 2 lattice point averages its samples in groups
                               of cfg.spp (one UNIFORM pixel's), each group's mean clamped per
                               channel at clamp_white (the display's white: 1 for rgb8) first.
                               A displayed UNIFORM pixel clips its mean there, so the layer
                               estimates the mean of what UNIFORM shows: a firefly keeps one
                               pixel's weight instead of lighting the whole cell. Biased in
                               linear radiance (as the display is); 0: off */
} fovpt_layers_cfg;

typedef enum fovpt_layers_preset_id {
    FOVPT_LAYERS_KTH_RADIUS = 0,    /* 6/10/20 degrees read as radii, d = 1,2,3 + 4, 4 spp */
    FOVPT_LAYERS_KTH_DIAMETER = 1,  /* 6/10/20 read as diameters: radii 3/5/10 */
    _FOVPT_LAYERS_PRESET_NUM,
    _FOVPT_LAYERS_PRESET_FORCE_U32 = 0x7FFFFFFF
} fovpt_layers_preset_id;

/* Zones of Polychronakis 2025, ch. 4: inner (full density), middle (1/4: one ray per 2x2
   pixels), outer (1/16), Lanczos-upsampled, blended over an overlap. */
typedef struct fovpt_zones_cfg {
    float inner_deg;        /* 0: 7.5 (Polychronakis 2025's 15 degrees read as a diameter) */
    float middle_deg;       /* > inner_deg; 0: 32.5 (65 degrees as a diameter) */
    float overlap_px;       /* linear blend width at each border, pixels; 0: 4 */
    uint32_t lanczos_a;     /* Lanczos lobes, 2 or 3; 0: 3 */
    uint32_t bspline;       /* 1: the 1/4 and 1/16 zones reconstructed by the cubic B-spline
                               (smoothing, as layers.bspline) instead of Lanczos; 0: Lanczos */
    uint32_t hollow;        /* 1: each zone's lattice traced only where the resolve reads it
                               (as layers.hollow); 0: full-frame lattices (Polychronakis 2025) */
    uint32_t spp[3];        /* samples per traced pixel of the inner (1), middle (1/4) and
                               outer (1/16) zone, <= FOVPT_MAX_SPP;             0: cfg.spp */
    uint32_t cell_jitter;   /* 1: the middle and outer zones' samples jitter over their 2 x 2
                               and 4 x 4 cells (as layers.cell_jitter); 0: in the pixel */
    float clamp_white;      /* the middle and outer zones' group clamp (as layers.clamp_white,
                               groups of cfg.spp); 0: off */
} fovpt_zones_cfg;

/* Selective foveated supersampling of Kim et al. 2021 (also the JIN baseline). */
typedef struct fovpt_selective_cfg {
    float e_deg[5];         /* e_f, e_p, e_m, e_np, e_max; 0: 3.3, 5.5, 12.1, 30, 45 */
    uint32_t n_sd[4];       /* samples per problematic subpixel by zone; 0: 9, 4, 2, 1 */
    float tau_shape[4];     /* tau_fov shape (tau0, tau_f, tau'_f, tau_np); 0: 1, 2, 0.5, 12 */
    float tau[9];           /* colour thresholds: col, poid, psn, psc, pte, soid, ssn, ssc,
                               ste; 0: Fig. 6: 0.02, 0.05, 0.06, 0.06, 0.02, 0.02, 0.02, 0.06,
                               0.02 */
    float normal_tol_deg;   /* normals differing more are discordant; 0: 10 */
    uint32_t fill_centre;   /* 1: non-problematic subpixels take the pixel colour (Jin);
                               0: bilinear from the neighbours (Kim et al. 2021) */
} fovpt_selective_cfg;

/* Temporal reuse (step 2) and smoothing (step 4) of Kim et al. 2021, Sec. 4.4-4.7; both off
   by default. */
typedef struct fovpt_temporal_cfg {
    uint32_t reuse;         /* 1: reuse pixels of the previous frame in the central region */
    uint32_t n_reuse_max;   /* 1 .. 5; 0: 5 */
    float tau_reuse;        /* > 0; 0: 1 */
    float eps_depth;        /* relative first-hit distance tolerance; 0: 0.01 */
    uint32_t smooth;        /* 1: eccentricity-dependent exponential smoothing */
    uint32_t n_tpi;         /* previous frames blended, 1 .. 4; 0: 4 */
    float alpha[6];         /* alpha at 0, e_f, e_p, e_m, e_np, e_max;
                               0: 0.9, 0.8, 0.7, 0.5, 0.2, 0.1 */
} fovpt_temporal_cfg;

/* Rendering settings. A zero-filled config means "all defaults" (listed per field);
   fovpt_config_default() gives the same settings filled in (and no g++ -Wextra warning). */
typedef struct fovpt_config {
    uint32_t method;        /* fovpt_method                                      0: uniform */
    uint32_t mode;          /* fovpt_mode                                        0: path */
    uint32_t spp;           /* UNIFORM samples per pixel per frame               0: 1 */
    uint32_t max_depth;     /* bounces, <= FOVPT_MAX_BOUNCES      0: 8 (path), 3 (Whitted) */
    uint32_t rr_start;      /* Russian roulette from this bounce; FOVPT_RR_OFF   0: 3 */
    uint32_t no_nee;        /* 1: no next-event estimation (BSDF sampling only) */
    uint32_t seed;          /* random stream seed (any value) */
    uint32_t accumulate;    /* 1: trace_rows adds to the running mean (progressive) */
    uint32_t sampler;       /* fovpt_sampler (SAMPLERS)                           0: SOBOL */
    uint32_t robust;        /* ROBUST PIXEL ESTIMATE: group count k, 3 .. FOVPT_ROBUST_MAX;
                               0: the plain mean (unbiased)                       0: off */
    uint32_t mirror_nee;    /* 1: NEXT-EVENT ESTIMATION THROUGH MIRRORS (path mode)  0: off */
    float acuity_budget;    /* read by fovpt_config_acuity only (ACUITY-DRIVEN CONFIGURATION,
                               samples): 0: each layer's / zone's spp the fewest that keep its
                               eye-filtered noise at UNIFORM's at spp; > 0: the total samples
                               about acuity_budget x UNIFORM's (W H spp), spread to minimise the
                               mean eye-filtered noise (1: equal time). [0, 64]         0: 0 */
    fovpt_layers_cfg layers;
    fovpt_zones_cfg zones;
    fovpt_selective_cfg selective;
    fovpt_temporal_cfg temporal;
    fov_display display;    /* for eccentricity; all zero: the camera's field of view */
    fov_logger logger;
} fovpt_config;

/* ==== context, output, statistics ========================================================== */

/* A camera's view for reprojection (temporal options). */
typedef struct fovpt_view {
    float pos[3], right[3], up[3], fwd[3];
    float tan4[4];            /* x from tan4[0] to tan4[1], y from tan4[2] (top) to tan4[3] */
} fovpt_view;

typedef struct fovpt_ctx {    /* filled by fovpt_init */
    fovpt_config cfg;         /* resolved */
    const fovpt_scene *scene;
    fovpt_camera cam;
    fov_gaze gaze;
    fov_ecc_model ecc;
    float right[3], up[3], fwd[3];
    float origin[3];          /* the pinhole: cam.pos + cam.eye_offset * right */
    float tx0, tx1, ty0, ty1; /* image-plane tangents: x from tx0 to tx1, y from ty0 (top) */
    float *accum;             /* UNIFORM: 4 floats per pixel: rgb sum, weight */
    /* LAYERS: per layer a lattice grid of 4 floats per point (rgb sum, weight; weight 0 =
       not traced): point (k, l) is pixel (ox + k d, oy + l d), k < nx, l < ny */
    float *layer_buf[FOVPT_MAX_LAYERS];
    uint32_t layer_ox[FOVPT_MAX_LAYERS], layer_oy[FOVPT_MAX_LAYERS];
    uint32_t layer_nx[FOVPT_MAX_LAYERS], layer_ny[FOVPT_MAX_LAYERS];
    float layer_trace_deg[FOVPT_MAX_LAYERS]; /* lattice points up to this eccentricity are traced */
    float layer_inner_deg[FOVPT_MAX_LAYERS]; /* hollow: and from this one (else -1) */
    fovpt_layers_cfg lay;     /* LAYERS: cfg.layers; ZONES: the three zones as static layers */
    /* ZONES: Lanczos lobes a of the upsampling (LAYERS: 0, Catmull-Rom) */
    uint32_t lanczos;
    void *pre;                /* SELECTIVE, JIN: presample records, 52 bytes per pixel */
    /* SELECTIVE, JIN with temporal options: a ring of frames, 8 floats per pixel (raw rgb,
       first-hit distance or -1, colour reference rgb, reuse count), and their views */
    float *hist[5];
    fovpt_view hist_view[5];
    uint32_t hist_slots, hist_cur, hist_valid;
    void *mem;
    size_t mem_size;
} fovpt_ctx;

/* Per-pixel outputs; every pointer may be NULL. Strides in elements per row; 0: packed. */
typedef struct fovpt_output {
    float *rgb;     uint32_t rgb_stride;    /* linear RGB, 3 floats per pixel */
    uint8_t *rgb8;  uint32_t rgb8_stride;   /* sRGB-encoded 8-bit RGB, clamped */
} fovpt_output;

/* Counters. No function resets them: every function that takes a fovpt_stats * (NULL: not
   counted) adds its own counts to what the struct holds, so they accumulate across calls,
   rows and frames until you clear them with fovpt_stats_init (all zero; `= {0}` is the same
   in C but warns under g++ -Wextra). fovpt_init, fovpt_set_view and fovpt_reset (which may
   reset the image's accumulation, never the counters) and fovpt_resolve_rows leave them.
     fovpt_trace_rows   samples and camera_rays of its rows, the bounce and shadow rays of
                        their paths, rays, bad_samples; LAYERS, ZONES: layer_targets and
                        layer_samples; SELECTIVE, JIN: the presamples (one per pixel).
     fovpt_refine_rows  SELECTIVE, JIN: the extra samples with their rays (samples,
                        camera_rays, ...), problematic, extra_samples, reused; other
                        methods: nothing.
     fovpt_render       both, for the whole image: the same as the two calls.
     fovpt_radiance     bounce_rays, shadow_rays, rays (their sum) and bad_samples of the one
                        path; the ray you pass is yours: not in samples, camera_rays or rays.
   After any sequence of these calls rays = camera_rays + bounce_rays + shadow_rays.
   Rendering the same frame twice into one struct (the same frame index, no fovpt_set_view
   between) doubles every count. With threads give each its own struct and sum them with
   fovpt_stats_add. */
typedef struct fovpt_stats {
    uint64_t samples;         /* camera samples */
    uint64_t rays;            /* every ray: camera + bounce + shadow */
    uint64_t camera_rays, bounce_rays, shadow_rays;
    uint64_t bad_samples;     /* non-finite radiance replaced by black */
    uint64_t layer_targets[FOVPT_MAX_LAYERS]; /* LAYERS: lattice points traced per layer */
    uint64_t layer_samples[FOVPT_MAX_LAYERS]; /* LAYERS: their samples (targets x spp) */
    /* SELECTIVE, JIN: problematic subpixels and their extra samples, per zone (fovea,
       parafovea, perifovea, near periphery; JIN counts everything in zone 0) */
    uint64_t problematic[4], extra_samples[4];
    uint64_t reused;          /* temporal reuse: pixels copied from the previous frame */
} fovpt_stats;

/* A random stream: counter-based, deterministic per (seed, pixel, sample, frame); with
   fovpt_rng_init_sobol its first dimensions are a scrambled Sobol sequence over the samples
   (SAMPLERS). Fill it with fovpt_rng_init or fovpt_rng_init_sobol only. */
typedef struct fovpt_rng {
    uint32_t key, ctr;
    uint32_t scramble, index, sobol; /* sobol 1: (scramble, index) drive the first dimensions;
                                        index is kept bit-reversed */
    uint32_t group, gkey, gidx;      /* the current group's key and shuffled index (a cache) */
} fovpt_rng;

/* ==== functions =========================================================================== */

FOVPT_API const char *fovpt_result_string(fov_result r);    /* never NULL */
FOVPT_API const char *fovpt_method_name(uint32_t method);   /* "uniform", ...; never NULL */

FOVPT_API fovpt_config fovpt_config_default(void);
/* Defaults filled in and every field validated (also the tables of the methods not used). */
FOVPT_API fov_result fovpt_config_resolve(const fovpt_config *in, fovpt_config *out);
FOVPT_API fov_result fovpt_layers_preset(fovpt_layers_cfg *out, uint32_t preset);
/* Acuity-driven foveation (see ACUITY-DRIVEN CONFIGURATION): fills cfg's layer table (with its
   spp), zone radii and spp, hollow, cell_jitter and clamp_white, and the selective borders
   (with the tau_fov slope) from cfg->display (all zero: cam's frustum), the eye (NULL: the
   defaults), fovpt_eye_plan, cfg->spp (UNIFORM's, the reference) and cfg->acuity_budget;
   every other field stays as set. Errors through cfg->logger; on error cfg is unchanged. */
FOVPT_API fov_result fovpt_config_acuity(fovpt_config *cfg, const fovpt_camera *cam,
                                         const fov_eye *eye);

/* The fov_camera defaults (the same as fovsdf_camera_init's: pos (0, 0, 5) looking at the
   origin, up +y, 60 degrees; world +x on the image's right, +y at its top). */
FOVPT_API void fovpt_camera_init(fovpt_camera *cam, uint32_t width, uint32_t height);
/* The ray through image point (x, y) (pixels, continuous; pixel centres at i + 0.5) from the
   pinhole pos + eye_offset * right (see fov_camera): dir
   unit and finite. Any finite (x, y) off the image works (x = 1e30 gives the ray along the
   image's right axis) until the image-plane offset overflows: then FOV_ERR_INVALID_ARG
   (this function has no logger; fovpt_init and fovpt_set_view log camera errors). */
FOVPT_API fov_result fovpt_camera_ray(const fovpt_camera *cam, float x, float y, float org[3],
                                      float dir[3]);
/* Per-eye gaze. The image point of world point p seen by this camera (pixels, continuous;
   it may lie off-screen): the gaze to pass to fovpt_init / fovpt_set_view when an eye
   tracker gives a 3D gaze target (the vergence point). For a gaze direction d of this eye,
   pass p = pinhole + d (the pinhole: cam->pos + cam->eye_offset * right, see fov_camera).
   FOV_ERR_INVALID_ARG when p is not in front of the camera (its depth along the view axis
   <= 1e-6 of its distance) or projects beyond +-2^24 pixels. */
FOVPT_API fov_result fovpt_gaze_from_point(const fovpt_camera *cam, const float p[3],
                                           fov_gaze *gaze);
/* Stereo: the two eye cameras of a head camera, eyes[0] left and eyes[1] right: positions
   head->pos -/+ ipd/2 along the head's image-right axis, view axes parallel (targets moved
   alike), the same up, size, field of view, eye_offset and tangents (set each eye's tangents
   afterwards if the headset gives them, e.g. OpenVR GetProjectionRaw). ipd in scene units,
   finite, >= 0. Axblad 2020 and Kim et al. 2021 render the eyes independently: one context
   per eye, each with
   its own gaze (fovpt_gaze_from_point of the same 3D target). */
FOVPT_API fov_result fovpt_camera_eyes(const fovpt_camera *head, float ipd, fovpt_camera eyes[2]);

FOVPT_API void fovpt_material_init(fovpt_material *m);   /* Lambert, albedo 0.8, ior 1.5 */
FOVPT_API void fovpt_shape_sphere(fovpt_shape *s, float cx, float cy, float cz, float r,
                                  uint32_t material);
FOVPT_API void fovpt_shape_plane(fovpt_shape *s, const float point[3], const float normal[3],
                                 uint32_t material);
FOVPT_API void fovpt_shape_quad(fovpt_shape *s, const float corner[3], const float u[3],
                                const float v[3], uint32_t material);
FOVPT_API void fovpt_shape_box(fovpt_shape *s, const float lo[3], const float hi[3],
                               uint32_t material);
FOVPT_API void fovpt_scene_desc_init(fovpt_scene_desc *d);

/* Scene memory for a description (validates it completely), then the build. */
FOVPT_API fov_result fovpt_scene_size(const fovpt_scene_desc *desc, size_t *bytes);
FOVPT_API fov_result fovpt_scene_build(fovpt_scene *scene, const fovpt_scene_desc *desc,
                                       void *mem, size_t bytes);

/* Closest hit in (tmin, tmax): 1 and *hit filled, or 0 (also for bad input). dir need not be
   unit length (t is in units of dir; any finite non-zero length). _brute tests every
   primitive (the reference); the BVH finds the same closest t and primitive (among equal
   t the lowest primitive slot, as brute force; NUMERICS). */
FOVPT_API int fovpt_intersect(const fovpt_scene *s, const float org[3], const float dir[3],
                              float tmin, float tmax, fovpt_hit *hit);
FOVPT_API int fovpt_intersect_brute(const fovpt_scene *s, const float org[3],
                                    const float dir[3], float tmin, float tmax, fovpt_hit *hit);
FOVPT_API int fovpt_occluded(const fovpt_scene *s, const float org[3], const float dir[3],
                             float tmin, float tmax);

FOVPT_API void fovpt_rng_init(fovpt_rng *r, uint32_t seed, uint32_t pixel, uint32_t sample,
                              uint32_t frame);
FOVPT_API void fovpt_rng_init_sobol(fovpt_rng *r, uint32_t seed, uint32_t pixel,
                                    uint32_t sample, uint32_t frame);      /* SAMPLERS */
FOVPT_API float fovpt_rng_next(fovpt_rng *r);              /* uniform in [0, 1) */

/* BSDF of a material at a surface with unit normal n (either side), unit wo (towards the
   viewer). sample: draws wi; *weight = f cos / pdf (the throughput factor), *pdf (0 for a
   delta lobe), returns 0 when the path ends (no valid direction). eval: f * cos(wi) and the
   sampling pdf of wi (both 0 for delta materials). */
FOVPT_API int fovpt_bsdf_sample(const fovpt_material *m, const float n[3], const float wo[3],
                                fovpt_rng *rng, float wi[3], float weight[3], float *pdf);
FOVPT_API void fovpt_bsdf_eval(const fovpt_material *m, const float n[3], const float wo[3],
                               const float wi[3], float fcos[3], float *pdf);

/* Radiance arriving at org from direction dir (the estimator of the path or Whitted mode of
   a resolved config). Non-finite results are replaced by 0 (counted in stats, which is
   added to: see fovpt_stats). */
FOVPT_API fov_result fovpt_radiance(const fovpt_scene *s, const fovpt_config *resolved,
                                    const float org[3], const float dir[3], fovpt_rng *rng,
                                    float rgb[3], fovpt_stats *stats);

/* Path tracing at arbitrary image points, for a sampler outside fovpt (fovlp.h's log-polar samples;
   see SHADING IMAGE POINTS): n points, point i at (xy[i stride], xy[i stride + 1]) (stride in
   floats, 0: 2; fovlp_sample arrays: &samples[0].x, stride 3), spp samples each (0: resolved->spp),
   sample k of point i on the stream (resolved->seed, first + i, k, frame) (fovpt_rng_init_sobol,
   or fovpt_rng_init with resolved->sampler RANDOM), its ray through the point (jitter 0) or
   through a point uniform in the jitter x jitter pixels centred on it (the stream's first two
   numbers; jitter 1 at pixel centres is UNIFORM's box filter, bit for bit), fovpt_radiance's
   estimator; rgb gets the plain mean (3 floats per point; clamp_white is not read), t (may be NULL)
   the first-hit distance along sample 0's unit camera ray (FLT_MAX: a miss). Everything is checked
   before any work (FOV_ERR_NULL, _NOT_FINITE, _INVALID_ARG incl. a jitter square corner's ray
   overflowing, _LIMIT, the camera's errors). stats is added to. */
FOVPT_API fov_result fovpt_shade_points(const fovpt_scene *scene, const fovpt_config *resolved,
                                        const fovpt_camera *cam, uint32_t n, const float *xy,
                                        uint32_t stride, uint32_t first, uint32_t frame,
                                        uint32_t spp, float jitter, float *rgb, float *t,
                                        fovpt_stats *stats);

/* Eccentricity (the shared model; see fov_display): the same semantics as fovsdf_ecc_*. */
FOVPT_API fov_result fovpt_ecc_init(fov_ecc_model *m, const fov_display *display,
                                    float cam_fov_y_deg, uint32_t width, uint32_t height,
                                    fov_gaze gaze);
FOVPT_API float fovpt_ecc_deg(const fov_ecc_model *m, float x, float y); /* degrees */
FOVPT_API float fovpt_ecc_ppd(const fov_ecc_model *m);
/* The eye's resolution (the shared model; see fov_eye; eye NULL = the defaults). _eye_mar: the
   allowed sample spacing at ecc_deg, quality * MAR, degrees (0 for bad input). _eye_density:
   the linear samples per display pixel the eye needs there for a display of ppd pixels per
   degree, (0, 1] (1 for bad input). _eye_ecc: the eccentricity, [0, 180] degrees, from which a
   linear density suffices (its inverse; bad input: 0 for density >= 1, else 180). _eye_plan:
   fov_eye_plan for an eccentricity model (FOV_ERR_NULL, _NOT_FINITE, _INVALID_ARG). */
FOVPT_API float fovpt_eye_mar(const fov_eye *eye, float ecc_deg);
FOVPT_API float fovpt_eye_density(const fov_eye *eye, float ppd, float ecc_deg);
FOVPT_API float fovpt_eye_ecc(const fov_eye *eye, float ppd, float density);
FOVPT_API fov_result fovpt_eye_plan(const fov_eye *eye, const fov_ecc_model *m,
                                    fov_eye_plan *plan);

/* GAZE INPUT (the shared model: see fov_gaze_filter_config; the same functions in fovsdf.h,
   fovlp.h and fovpt.h). A filter in your memory conditions the tracker's raw samples; its
   state, the tracker's accuracy and the system's latency give a margin that
   fovpt_config_gaze_margin adds to the config's full-quality radii. No eye tracker: fixed
   foveation, fovpt_gaze_fixed (the display's axis point) with FOV_GAZE_FIXED_MARGIN_DEG.
      fov_gaze_filter gf;  fovpt_gaze_filter_init(&gf, NULL);           // once (NULL: defaults)
      // per tracker sample (timestamps in microseconds, strictly increasing):
      fovpt_gaze_filter_push_px(&gf, &ecc, t_us, raw_px, &gaze);        // or _push in degrees
      // per frame:
      float m;  fovpt_gaze_margin(&gf, 0.5f, 50.0f, &m);     // accuracy 0.5 deg, latency 50 ms
      // or latency-compensated (the fovea where the eye is when the frame is seen):
      //   fov_gaze_prediction pr;  fovpt_gaze_predict(&gf, 0.5f, 50.0f, &pr);
      //   float d[2] = { pr.x_deg, pr.y_deg };  fovpt_gaze_from_deg(&ecc, d, &gaze);
      //   m = pr.margin_deg;
      fovpt_set_gaze_margin(&ctx, &base_cfg, m);          // then fovpt_render as usual
   (fovpt_init once with base_cfg; a per-frame fovpt_init with fovpt_config_gaze_margin's
   config would reset the accumulation and the temporal ring every frame).
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
FOVPT_API fov_gaze_filter_config fovpt_gaze_filter_config_default(void);
FOVPT_API fov_result fovpt_gaze_filter_init(fov_gaze_filter *f,
                                            const fov_gaze_filter_config *cfg);
FOVPT_API void fovpt_gaze_filter_reset(fov_gaze_filter *f);
FOVPT_API fov_result fovpt_gaze_filter_push(fov_gaze_filter *f, uint64_t t_us, float x_deg,
                                            float y_deg);
FOVPT_API fov_result fovpt_gaze_filter_push_px(fov_gaze_filter *f, const fov_ecc_model *m,
                                               uint64_t t_us, fov_gaze raw, fov_gaze *out);
FOVPT_API fov_result fovpt_gaze_to_deg(const fov_ecc_model *m, fov_gaze px, float deg[2]);
FOVPT_API fov_result fovpt_gaze_from_deg(const fov_ecc_model *m, const float deg[2],
                                         fov_gaze *px);
FOVPT_API fov_result fovpt_gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                       float latency_ms, float *margin_deg);
FOVPT_API fov_result fovpt_gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                        float latency_ms, fov_gaze_prediction *out);
FOVPT_API fov_result fovpt_gaze_fixed(const fov_display *display, uint32_t width,
                                      uint32_t height, fov_gaze *out);
FOVPT_API fov_result fovpt_camera_display(const fov_camera *cam, fov_display *out);
/* The margin applied: *out = base resolved (fovpt_config_resolve) with every full-quality
   and visual-field radius grown by margin_deg (>= 0): the layers' radius_deg (layer[0]'s
   only when it is a mask, > 0), zones.inner_deg and middle_deg, selective.e_deg[0..4] (the
   order of each set kept). FOV_ERR_NULL, FOV_ERR_NOT_FINITE, FOV_ERR_INVALID_ARG (margin <
   0), FOV_ERR_LIMIT (a radius reaching 180 degrees), or the base's resolve error; *out
   written only on success. */
FOVPT_API fov_result fovpt_config_gaze_margin(const fovpt_config *base, float margin_deg,
                                              fovpt_config *out);
/* The margin applied per frame to a context, keeping its accumulation (UNIFORM, the LAYERS
   and ZONES lattices) and its temporal ring (SELECTIVE, JIN): ctx->cfg becomes
   fovpt_config_gaze_margin(base, margin_deg) and the layers' trace radii follow, from the next
   render on; nothing is reset (a per-frame fovpt_init would reset all of it). base must differ
   from the context's config only in the radii the margin grows (the same method, layer
   strides and temporal slots: the memory layout): else FOV_ERR_INVALID_ARG, use fovpt_init.
   FOV_ERR_NULL, FOV_ERR_NOT_FINITE, FOV_ERR_INVALID_ARG (margin < 0), FOV_ERR_LIMIT, base's
   resolve error; the context is unchanged on error. */
FOVPT_API fov_result fovpt_set_gaze_margin(fovpt_ctx *ctx, const fovpt_config *base,
                                           float margin_deg);

/* Context: working memory for a config and camera, then init (validates everything). */
FOVPT_API fov_result fovpt_memory_size(const fovpt_config *cfg, const fovpt_camera *cam,
                                       size_t *bytes);
FOVPT_API fov_result fovpt_init(fovpt_ctx *ctx, const fovpt_config *cfg,
                                const fovpt_scene *scene, const fovpt_camera *cam,
                                fov_gaze gaze, void *mem, size_t bytes);
/* A new camera pose (same size) and gaze for the next frame; resets the accumulation when
   the camera changed. With temporal options (SELECTIVE, JIN) it also ends the frame just
   rendered: call it once between frames (even when nothing moved), it makes that frame
   history for reuse and smoothing. */
FOVPT_API fov_result fovpt_set_view(fovpt_ctx *ctx, const fovpt_camera *cam, fov_gaze gaze);
FOVPT_API fov_result fovpt_reset(fovpt_ctx *ctx);          /* clears accumulation, history */
/* Phase 1: trace the samples of rows [y0, y1) for frame `frame` (any rows, any thread).
   stats (may be NULL) is added to, never reset (see fovpt_stats), here and in the calls
   below. */
FOVPT_API fov_result fovpt_trace_rows(fovpt_ctx *ctx, uint32_t frame, uint32_t y0,
                                      uint32_t y1, fovpt_stats *stats);
/* Phase 2 (SELECTIVE, JIN; nothing for the other methods), after every row of the frame is
   traced: the subpixel tests and the extra samples of rows [y0, y1) (reads the presamples
   of the rows above and below). */
FOVPT_API fov_result fovpt_refine_rows(fovpt_ctx *ctx, uint32_t frame, uint32_t y0,
                                       uint32_t y1, fovpt_stats *stats);
/* Phase 3, after every row of the frame is refined: reconstruct rows [y0, y1) into out. */
FOVPT_API fov_result fovpt_resolve_rows(const fovpt_ctx *ctx, uint32_t y0, uint32_t y1,
                                        const fovpt_output *out);
/* All phases for the whole image. frame (here and in trace / refine) picks the random streams:
   the same frame index renders the same noise, so give each new frame a new index (the
   progressive mean of cfg.accumulate converges only over distinct frames). */
FOVPT_API fov_result fovpt_render(fovpt_ctx *ctx, uint32_t frame, const fovpt_output *out,
                                  fovpt_stats *stats);
FOVPT_API void fovpt_output_init(fovpt_output *out);   /* every pointer NULL, stride 0 */
FOVPT_API void fovpt_stats_init(fovpt_stats *stats);    /* every counter 0 (see fovpt_stats) */
FOVPT_API void fovpt_stats_add(fovpt_stats *acc, const fovpt_stats *s);   /* acc += s */

/* Foveation building blocks (exposed for tests and for callers with their own pipeline). */
/* Catmull-Rom weights of v0..v3 at t in [0, 1] (Axblad 2020, Eq. 3.17, with the t^3
   coefficient of v2 corrected to -3/2): they sum to 1, give v1 at t = 0 and v2 at t = 1. */
FOVPT_API void fovpt_catmull_rom(float t, float w[4]);
/* tau_fov(e) of Kim et al. 2021, Sec. 4.6.1: two quadratic Bezier curves (C1 spline) through
   (0, tau0), (e_f, tau_f), (e_np, tau_np) with slope tau'_f at e_f and zero slope at both ends;
   tau_np beyond e_np. FOV_ERR_INVALID_ARG (via *out = 0 and the return) when the shape makes
   x(t) non-monotone. */
FOVPT_API fov_result fovpt_tau_fov(const fovpt_selective_cfg *resolved, float e_deg, float *out);
/* alpha(e) of Kim et al. 2021, Sec. 4.7: piecewise linear through the six nodes, clamped
   beyond e_max. */
FOVPT_API float fovpt_alpha(const fovpt_temporal_cfg *resolved_t,
                            const fovpt_selective_cfg *resolved_s, float e_deg);

/* ==== denoising: guide buffers and a foveated edge-avoiding a-trous filter ================== */
/* DENOISING (see also the DENOISING section of the doc block)
   Guide buffers. fovpt_trace_rows_guide traces rows [y0, y1) exactly as fovpt_trace_rows
   (the same samples, streams and image) and also writes per-pixel first-hit guides of those
   rows into the caller's buffers (every pointer may be NULL: not written; strides in
   elements per row, 0: packed; a stride below the packed one is FOV_ERR_INVALID_ARG):
     albedo  3 floats: the mean over the pixel's samples of the first hit's material albedo
             (kd, or the mirror / glass tint); 0 where a sample leaves the scene
     normal  3 floats: the normalised mean of the first hits' unit normals, turned towards
             the camera; (0, 0, 0) when no sample hits or the normals cancel
     depth   1 float: the mean distance from the pinhole to the first hit along the unit
             ray (ray distance, not view-plane depth), over the samples that hit; 0: none hit
     spp     1 float: samples per pixel behind the pixel's value: UNIFORM its samples (with
             accumulate: the running total); LAYERS, ZONES the layers' densities spp_n / d_n^2
             blended as the resolve blends the layers (fovea: the stride-1 layer's spp);
             SELECTIVE, JIN 1 (the presample)
     var     1 float: the variance of the pixel's mean luminance (0.2126 R + 0.7152 G +
             0.0722 B, linear) from its own samples: the sample variance of this call's n
             >= 2 samples / the number of samples the pixel's value is the mean of (n; with
             accumulate the running total); -1 where unknown (fewer than 2 own samples, or
             a LAYERS / ZONES blend band, where the value mixes two layers: the variance of
             one layer's samples is not the value's; the denoiser then estimates it
             spatially. Measured as below, fovea, layers_diam_fovea at its equal-time
             density, against the former var of the larger-weight layer: cornell +1.8 dB
             (corner +3.2), cubes441 corner +8.0, mesh100k +0.3, interior +0.2 (+1.2),
             mirrors -1.6 (+0.4); the other methods' fovea lies outside the bands)
   Which samples: UNIFORM and the pixels a stride-1 layer or zone traces: the pixel's own
   samples (the guides are their means; where two stride-1 layers trace a pixel, in their
   blend band, those of the layer with the larger weight in the resolve's blend, the inner
   one where vb >= 1/2). Pixels filled by a coarser layer or zone (and
   every pixel of SELECTIVE and JIN): one extra ray through the pixel centre, first hit only
   (counted in stats.camera_rays and rays; no shading), var -1.
   The denoiser (fovpt_denoise_*). Temporal accumulation with reprojection, then an
   edge-avoiding a-trous wavelet filter (Dammertz et al. 2010) with variance guidance (Schied
   et al. 2017), foveated. Per frame:
      fovpt_denoise_frame(&dn, &cam, gaze, rgb, rgb_stride, &guide);   // the noisy frame
      fovpt_denoise_temporal_rows(&dn, y0, y1);                  // all rows, then (barrier)
      for (i = 0; i < fovpt_denoise_passes(&dn); ++i)
          fovpt_denoise_atrous_rows(&dn, i, y0, y1);             // all rows of pass i, barrier
      fovpt_denoise_resolve_rows(&dn, y0, y1, &out);             // after the last pass
   (fovpt_denoise_run does all of it for the whole image.) Every row-range call may run on
   disjoint rows on as many threads as you like, but each phase must have finished on every
   row before any row of the next phase starts (a pass reads neighbours up to 2^(i+1) rows
   away). The buffers given to fovpt_denoise_frame must stay unchanged until the frame's
   resolve is done. Results do not depend on the row split. Each row remembers the last phase
   it finished: a row call is rejected (FOV_ERR_INVALID_ARG) when one of its rows has not
   finished the previous phase (temporal before pass 0, pass i - 1 before pass i, the last
   pass before the resolve) or already ran a later one; rows outside the call's range are not
   checked (they may be running on other threads; the barrier is the caller's). A failed
   fovpt_denoise_frame leaves the denoiser without a frame (row calls fail until the next
   good one; the history is kept). A frame whose temporal phase did not run on every row is
   not used as history. fovpt_denoise_init clears the memory (no frame, no history).
   Temporal: each pixel's first hit (pinhole + depth * the unit ray through the pixel centre;
   depth 0: the direction, at infinity) is projected into the previous frame's camera and the
   history read bilinearly from the 4 pixels around it, each tap kept only when its stored
   depth agrees (|d_prev - distance to the previous pinhole| <= depth_tol d + 2 |local depth
   slope|) and its normal too (dot >= normal_cos; a miss only matches a miss); a point that
   lands within 1e-3 px of a pixel centre takes that pixel alone (a static camera maps every
   pixel onto itself exactly). Colour = (1 - a) history + a input with
   a = max(alpha(p), 1 / n), n the history length (<= 32); the luminance moments and the
   variance (propagated: (1 - a)^2 var_history + a^2 var_input) alike.
   Spatial: pass i (0 .. passes - 1) takes the 5 x 5 B3-spline taps at step 2^i with the
   edge-stopping weights of Schied et al. 2017: normals max(0, n.n')^phi_normal, depth
   exp(-|z - z'| / (phi_depth |grad z| |offset| + 1e-3 z)), albedo
   exp(-|a - a'|^2 / phi_albedo^2) and luminance exp(-|l - l'| / (phi_lum sqrt(var3x3))),
   var3x3 the 3 x 3 Gaussian of the variance; the variance is filtered with the squared
   weights. Input variance: the guide's var where >= 0, else the temporal moments (n >= 4),
   propagated with the history as above; where neither is known, the luminance variance over
   the 3 x 3 pixels at the lattice spacing; while the history is short (n < 4) the mean of
   the two (measured: Cornell 160 x 120 fovea PSNR -0.1 .. +0.5 dB over the guide's var
   alone, bench_pt --denoise).
   Foveation: a pixel's coarseness r = max(s(e), sqrt(spp_ref / spp)) >= 1, s(e) the eye's
   allowed sample spacing in pixels at its eccentricity e (fov_eye: quality * MAR(e) * ppd,
   the shared model) and spp the guide's density (spp_ref 0: the density at the gaze);
   pass i filters the pixel only while 2^i <= fovea_step * r * k (else the pixel is passed
   through), k = min(1, sqrt(spp_full / spp)), and the history weight is 1 - alpha,
   alpha(p) = max(alpha_periphery, alpha_fovea / r): the fovea keeps the fewest passes and
   the shortest history. Pixels whose reach r k >= r_small take the 3 x 3 linear B-spline
   taps (1/4, 1/2, 1/4) instead of the 5 x 5 B3 ones (a third of the work; measured cubes441
   320 x 240 LAYERS: periphery -0.55 dB, fovea unchanged).
   Adaptive cost: where the frame's samples already suffice the filter stays away. A pixel
   with more than spp_full samples gets fewer passes (k < 1; above (fovea_step r)^2 spp_full
   none: measured on cubes441 at 64 fovea spp, 5 passes lose 0.8 dB to the noisy input, one
   gains 1.7), and a pixel whose input noise (the temporal phase's variance, as 8-bit sRGB
   codes with the slope min(12.92, 0.5 / sqrt(l))) is below skip_noise gets none when that
   variance rests on at least 8 samples (the spp guide times the history frames; fewer may
   all have missed the light): it costs one compare per pass. A guide var from at least 8
   samples is trusted alone (the spatial estimate, which counts shading as noise, is mixed in
   only below). Passes after the first also leave a pixel as it is where the running
   estimate's variance (the one the passes propagate, as display codes the same way) is below
   (skip_noise / 8)^2 (FOVPT__DN_QUIET 64: the propagated variance leaves out the correlation
   the passes build, so it underestimates the noise left, by about 3x on a flat noisy grey
   (tests/test_fovpt_denoise.c fovea_filtered_least_*); with the factor 1 those tests fail).
   Pass 0 has pooled the 3 x 3 (or 5 x 5) neighbourhood by then, so the estimate is not one
   pixel's few samples. It catches sky, black and converged regions of the periphery, where
   the wide passes cost the most: one 320 x 240 LAYERS frame (bench_pt's scenes, fovea 53 /
   30 spp, callgrind, fovpt_denoise_run) cubes441 401 -> 386 M instructions, mesh100k 382 ->
   346 M; PSNR per field unchanged to 0.001 dB, bench_pt's periphery flicker within 1 %.
   SURE selection (on unless cfg.no_sure; Li, Wu, Chuang 2012, "SURE-based optimization for
   adaptive sampling and reconstruction", ACM TOG 31(6)): where a pixel's guide var rests on
   at least sure_min_spp samples (the spp guide; 16: the sample variance of fewer is too
   noisy, measured below), its output is the candidate of least estimated error among the
   temporal phase's output y (no pass) and the output F_k after each pass k. The estimate is
   Stein's unbiased risk estimate of the luminance: (F - y)^2 - s2 + 2 s2 dF/dy (s2 = the
   variance of y: the guide's var, propagated with the history; y itself: s2), weighted by
   the squared slope of the display curve at y (min(12.92, 0.5 / sqrt(l)), as skip_noise:
   the error is judged in display codes, so a bright outlier does not decide for its dark
   neighbours), then averaged over the (2 sure_radius + 1)^2 pixels around (those with a
   selection; per pixel SURE is too noisy to choose by) and compared by strict <: a tie
   keeps the earlier candidate. dF/dy, the approximation: each pass is a normalised weighted
   mean, its derivative by the pixel's own input the centre weight / the weight sum plus the
   luminance stop's slope (sig sum_j w_j sgn(l - l_j) (F - l_j) / sum w; the other stops and
   the variance guide do not depend on y), exact for one pass (tests/test_fovpt_denoise.c:
   sure_derivative_vs_difference, against a central difference); over passes the product
   of these along the centre path (the paths through neighbours that return to the pixel
   are left out: a small underestimate where the kernel is wide, when the candidates' own
   SURE is small anyway). The cost: one more pass over the selected pixels per pass (the
   window mean) and 40 bytes per pixel (fovpt_denoise_size; none with no_sure); the SSE2
   pass computes the same derivative lane by lane (bit-identical to the scalar one).
   Measured (a harness outside the repository over this API: 320 x 240, four seeds each,
   centre / corner gaze, the fovea (f1) against eight 512-spp fovea references, LAYERS and
   ZONES at the equal-time fovea densities of bench_pt; selection minus none, dB, the same
   noisy frames): cubes441 +0.2 (17 spp) +1.5 (53) +0.0 (171), corner +0.7 (53); mirrors
   +2.2 (16) +1.7 (63) +0.0 (192), corner +2.2 +1.9; cornell, mesh100k, interior and every
   ZONES case -0.12 .. +0.07, except interior at 21 spp -0.1 (centre) / -0.5 (corner); the
   whole image within 0.02. With sure_min_spp 2 the low counts lose
   (cornell 11 spp -0.3, 7 spp -2.7; mesh100k 5 and 15 spp -0.1); without the luminance
   stop's slope in dF/dy the 21-spp interior lost 0.9 dB (corner). bench/README.md has the
   equal-time rows.
   Weights: one exponential per tap (fovpt__exp_neg) for the depth, albedo, luminance and
   normal stops; with phi_normal >= 32, c^phi_normal = exp(-phi_normal (-ln c)) with -ln c
   from a 4-term series for c >= 3/4 (absolute weight error below 3.2e-6 of the centre
   tap's for every phi_normal >= 32, the default; from 128 also a relative error below 1e-4
   where the weight is above e^-10);
   c < 3/4 with phi_normal >= 104.3 drops the tap (weight below e^-30); else c^phi_normal
   exactly (by squaring for an integer phi_normal).
   phi_normal 32 (0.7.0: 128): a faceted or bumpy surface whose normals turn a few degrees
   per pixel is filtered as one surface (cos 8 degrees ^ 32 = 0.73, ^ 128 = 0.29), a crease of
   30 degrees or more is still an edge (cos 30 degrees ^ 32 = 0.01). Measured (LAYERS 320 x
   240, fovea 16 spp, 3 seeds, fovea PSNR against 512 spp): mesh100k 38.1 -> 39.6 dB,
   interior 27.6 -> 29.1, mirrors 34.4 -> 34.6, cornell 33.2 -> 33.3, cubes441 29.72 ->
   29.67; periphery mesh100k +1.4 dB, the others within 0.3 dB. Cost (callgrind, one LAYERS
   frame): cubes441 +0.5 %, mesh100k +4 % instructions.
   SIMD: on x86 with SSE2 the a-trous pass filters 4 pixels of a row at once (the same tap
   offsets; each lane its own radius, stops and pass-through), where all their 5 x 5 taps
   lie inside the image columns and the normal stop needs no powf (phi_normal an integer or
   >= 104.3); the border columns (2 * 2^pass wide), a row's last width % 4 pixels and other
   phi_normal take the scalar pass. Each lane performs the scalar pass's float operations in
   its order (a tap the scalar pass skips adds +0), so the image is bit-identical to
   FOVPT_NO_SIMD's (tests/test_fovpt_denoise.c: atrous_simd_equals_scalar_*, widths 13,
   30, 101, an input that overflows the variance) as the implementation keeps the compiler
   from contracting the scalar a * b + c into FMA (NUMERICS; clang's -ffp-contract=fast and
   -ffast-math override it, and such a build rounds a few values differently). Measured (a
   harness outside the repository: callgrind, one LAYERS KTH-radius frame 320 x 240,
   instructions per pixel, temporal / a-trous passes): cubes441 1204 / 6631 -> 1204 / 4016,
   mesh100k 1204 / 7192 -> 1204 / 3817; time of fovpt_denoise_run, old and new interleaved
   in one program: 1.73x (cubes441), 1.85x (mesh100k) faster (medians of 21).
   Memory: fovpt_denoise_size, 204 bytes per pixel (two history frames of 12 floats, two
   filter buffers of 4, the coarseness, the guides packed, the SURE selection's 10 floats;
   164 with no_sure); no threads, no allocation. */
#ifndef FOVPT_DN_MAX_LEVELS
#define FOVPT_DN_MAX_LEVELS 8
#endif
typedef struct fovpt_guide {
    float *albedo;  uint32_t albedo_stride;  /* 3 floats per pixel */
    float *normal;  uint32_t normal_stride;  /* 3 floats per pixel */
    float *depth;   uint32_t depth_stride;   /* 1 float per pixel */
    float *spp;     uint32_t spp_stride;     /* 1 float per pixel */
    float *var;     uint32_t var_stride;     /* 1 float per pixel */
} fovpt_guide;

typedef struct fovpt_denoise_cfg {
    uint32_t width, height;   /* image size, 1 .. FOVPT_MAX_DIM (the frames' camera size) */
    uint32_t levels;          /* a-trous passes at most (steps 1 .. 2^(levels-1)), 1 ..
                                 FOVPT_DN_MAX_LEVELS                                  0: 5 */
    uint32_t no_filter;       /* 1: no a-trous pass (temporal accumulation only) */
    uint32_t no_temporal;     /* 1: no history (each frame filtered alone) */
    float fovea_step;         /* widest step where r = 1, pixels, [1, 2^16]           0: 4 */
    float spp_ref;            /* density of r = 1 (>= 0); 0: the guide's at the gaze pixel */
    float phi_lum;            /* luminance stop, (0, 1e6]                             0: 8 */
    float phi_normal;         /* normal exponent, (0, 1e6]                           0: 32 */
    float phi_depth;          /* depth-slope multiplier, (0, 1e6]                     0: 1 */
    float phi_albedo;         /* albedo difference scale, (0, 1e6]                  0: 0.1 */
    float alpha_fovea;        /* input weight where r = 1, (0, 1]                   0: 0.2 */
    float alpha_periphery;    /* the least input weight, (0, alpha_fovea]          0: 0.05 */
    float depth_tol;          /* relative depth tolerance of reprojection, (0, 1]  0: 0.02 */
    float normal_cos;         /* least normal dot of reprojection, [-1, 1)          0: 0.9 */
    float skip_noise;         /* a pass leaves a pixel as it is where its noise is below
                                 this many 8-bit display codes (a variance from >= 8
                                 samples; after pass 0 also where the running estimate's
                                 is below skip_noise / 8), (0, 255]; 1e-9: only where
                                 it is 0                                          0: 0.5 */
    float spp_full;           /* samples per pixel (the spp guide) up to which a pixel gets
                                 every pass of its coarseness; above, the widest step shrinks
                                 by sqrt(spp_full / spp): a converged fovea is left as it is,
                                 (0, 1e30]                                            0: 16 */
    float r_small;            /* reach r k from which the passes take 3 x 3 taps instead
                                 of 5 x 5, [1, 65536]                                0: 2 */
    uint32_t no_sure;         /* 1: no SURE selection (the last pass's output everywhere);
                                 0: per pixel with a guide var from >= sure_min_spp
                                 samples, the input or the output of a pass, whichever
                                 has the least smoothed SURE (see DENOISING)            */
    uint32_t sure_radius;     /* the SURE smoothing window's radius, 1 .. 8          0: 4 */
    float sure_min_spp;       /* the least samples (spp guide) behind a pixel's var for
                                 the selection, [2, 1e30]                            0: 16 */
    fov_display display;      /* eccentricity (fov_display); all zero: the camera's frustum */
    fov_eye eye;              /* the eye model (fov_eye), zero fields: the defaults */
    fov_logger logger;
} fovpt_denoise_cfg;

typedef struct fovpt_denoise {  /* filled by fovpt_denoise_init; read-only for the caller */
    fovpt_denoise_cfg cfg;      /* resolved */
    fovpt_view view, prev_view; /* this frame's and the previous frame's cameras */
    fov_ecc_model ecc;
    float spp_ref;              /* this frame's */
    const float *in;  uint32_t in_stride;
    fovpt_guide guide;
    float *hist[2];             /* 12 floats per pixel: rgb, m1, m2, n, var, depth, normal */
    float *buf[2];              /* 4 floats per pixel: rgb, var */
    float *coarse;              /* 1 float per pixel: r */
    float *pack;                /* 8 floats per pixel: depth, normal, albedo, luminance */
    float *sel;                 /* SURE: 10 floats per pixel (NULL without): the best
                                   candidate's rgb and smoothed SURE, two raw SURE slots,
                                   the input luminance, its variance, the output's centre
                                   derivative, the last pass's centre weight fraction */
    uint32_t cur, frames, has_prev, passes, in_frame;
    void *mem;
    size_t mem_size;
} fovpt_denoise;

FOVPT_API void fovpt_guide_init(fovpt_guide *g);   /* every pointer NULL, strides 0 */
/* fovpt_trace_rows plus the guide buffers of rows [y0, y1) (g NULL: fovpt_trace_rows). */
FOVPT_API fov_result fovpt_trace_rows_guide(fovpt_ctx *ctx, uint32_t frame, uint32_t y0,
                                            uint32_t y1, const fovpt_guide *g,
                                            fovpt_stats *stats);
/* fovpt_render with the guides of the whole image. */
FOVPT_API fov_result fovpt_render_guide(fovpt_ctx *ctx, uint32_t frame, const fovpt_output *out,
                                        const fovpt_guide *g, fovpt_stats *stats);
FOVPT_API fovpt_denoise_cfg fovpt_denoise_cfg_default(void);
/* Defaults filled in, every field checked (FOV_ERR_INVALID_ARG, _LIMIT, _NOT_FINITE). */
FOVPT_API fov_result fovpt_denoise_resolve(const fovpt_denoise_cfg *in, fovpt_denoise_cfg *out);
FOVPT_API fov_result fovpt_denoise_size(const fovpt_denoise_cfg *cfg, size_t *bytes);
/* mem: at least fovpt_denoise_size bytes, 8-byte aligned (FOV_ERR_TOO_SMALL, _INVALID_ARG). */
FOVPT_API fov_result fovpt_denoise_init(fovpt_denoise *dn, const fovpt_denoise_cfg *cfg,
                                        void *mem, size_t bytes);
FOVPT_API fov_result fovpt_denoise_reset(fovpt_denoise *dn);   /* forgets the history */
/* Starts a frame: its camera (the size of the config), gaze, the noisy linear image (3 floats
   per pixel, stride in floats, 0: packed) and its guides (depth and normal required; albedo,
   spp, var optional). The previous frame (if any) becomes the history. The buffers' values are
   not checked: radiance NaN, infinite or negative reads as 0, a depth <= 0 or not finite as a
   miss, a normal longer than unit (|n|^2 > 1.0001) is normalised, one with a NaN or infinite
   component reads as (0, 0, 0). */
FOVPT_API fov_result fovpt_denoise_frame(fovpt_denoise *dn, const fovpt_camera *cam,
                                         fov_gaze gaze, const float *rgb, uint32_t rgb_stride,
                                         const fovpt_guide *g);
FOVPT_API uint32_t fovpt_denoise_passes(const fovpt_denoise *dn);  /* a-trous passes (0: none) */
FOVPT_API fov_result fovpt_denoise_temporal_rows(fovpt_denoise *dn, uint32_t y0, uint32_t y1);
FOVPT_API fov_result fovpt_denoise_atrous_rows(fovpt_denoise *dn, uint32_t pass, uint32_t y0,
                                               uint32_t y1);
FOVPT_API fov_result fovpt_denoise_resolve_rows(const fovpt_denoise *dn, uint32_t y0,
                                                uint32_t y1, const fovpt_output *out);
/* Every phase on the whole image (after fovpt_denoise_frame). The denoised image is finite and
   >= 0 whatever the buffers hold (a fuzzing target checks it: tests/fuzz/fuzz_fovpt_dn.c). */
FOVPT_API fov_result fovpt_denoise_run(fovpt_denoise *dn, const fovpt_output *out);

/* The documented limits (see the configuration macros above), defined here so that a
   translation unit with the declarations alone can use them; give them the same value in
   every translation unit. */
#ifndef FOVPT_MAX_DIM
#define FOVPT_MAX_DIM 65536u
#endif
#ifndef FOVPT_MAX_PRIMS
#define FOVPT_MAX_PRIMS (1u << 26)
#endif
#if FOVPT_MAX_PRIMS > (1u << 26)
#error \
"fovpt: FOVPT_MAX_PRIMS above 2^26 (the wide BVH packs a leaf's first primitive in 26 bits)"
#endif
#ifndef FOVPT_MAX_BVH_DEPTH
#define FOVPT_MAX_BVH_DEPTH 64
#endif
#ifndef FOVPT_MAX_BOUNCES
#define FOVPT_MAX_BOUNCES 1024u
#endif
#ifndef FOVPT_MAX_SPP
#define FOVPT_MAX_SPP 65536u
#endif
#ifndef FOVPT_ROBUST_MAX
#define FOVPT_ROBUST_MAX 16
#endif
#ifndef FOVPT_ROBUST_MIN_GROUP
#define FOVPT_ROBUST_MIN_GROUP 8
#endif
#ifndef FOVPT_ROBUST_GINI
#define FOVPT_ROBUST_GINI 0.25f
#endif
#if FOVPT_ROBUST_MAX < 3 || FOVPT_ROBUST_MIN_GROUP < 1
#error "fovpt.h: FOVPT_ROBUST_MAX must be at least 3 and FOVPT_ROBUST_MIN_GROUP at least 1"
#endif
#ifndef FOVPT_MAX_RADIANCE
#define FOVPT_MAX_RADIANCE 1e16
#endif

#ifdef __cplusplus
}
#endif

#endif /* FOVPT_H_INCLUDED */

/* ---- end of API; implementation below ---- */
#ifdef __INTELLISENSE__
#define FOVPT_IMPLEMENTATION
#endif

#if defined(FOVPT_IMPLEMENTATION) && !defined(FOVPT_IMPL_INCLUDED)
#define FOVPT_IMPL_INCLUDED
/* No FMA contraction in the implementation, whatever the build's flags (gcc's gnu modes and
   clang contract a * b + c into one rounding where the target has FMA): the SIMD paths and
   their scalar twins, and the BVH and brute force, then round alike (NUMERICS). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif
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

#define FOVPT__PRIV FOV__PRIV
#define FOVPT__FAIL(lg, r, msg) FOV__FAIL(lg, "fovpt", r, msg)

/* SIMD: the wide BVH tests a node's boxes four at a time (eight with AVX) and a leaf's
   triangles four at a time (SoA blocks): SSE on x86 (FOVPT__SIMD 1), NEON on AArch64 (2),
   SIMD128 on wasm32 built with -msimd128 (3); FOVPT_NO_SIMD or any other target: the scalar
   twin, the same arithmetic one lane at a time (0). Every path gives the same hits (the same float
   operations in the same order, no FMA contraction: the comparisons are exact). */
#if !defined(FOVPT_NO_SIMD) && (defined(__SSE__) || defined(_M_X64) || \
                                (defined(_M_IX86_FP) && _M_IX86_FP >= 1))
#define FOVPT__SIMD 1
#include <xmmintrin.h>
#if defined(__AVX__)
#include <immintrin.h>
#endif
typedef __m128 fovpt__v4;
typedef __m128 fovpt__m4;
#define FOVPT__V_SET1(x) _mm_set1_ps(x)
#define FOVPT__V_LD(p) _mm_loadu_ps(p)
#define FOVPT__V_ST(p, a) _mm_storeu_ps(p, a)
#define FOVPT__V_ADD(a, b) _mm_add_ps(a, b)
#define FOVPT__V_SUB(a, b) _mm_sub_ps(a, b)
#define FOVPT__V_MUL(a, b) _mm_mul_ps(a, b)
#define FOVPT__V_DIV(a, b) _mm_div_ps(a, b)
#define FOVPT__V_MAXT(a, t) _mm_max_ps(a, t) /* a > t ? a : t (NaN a: t) */
#define FOVPT__V_MINT(a, t) _mm_min_ps(a, t) /* a < t ? a : t (NaN a: t) */
#define FOVPT__V_LE(a, b) _mm_cmple_ps(a, b)
#define FOVPT__V_LT(a, b) _mm_cmplt_ps(a, b)
#define FOVPT__V_GE(a, b) _mm_cmpge_ps(a, b)
#define FOVPT__V_GT(a, b) _mm_cmpgt_ps(a, b)
#define FOVPT__M_AND(a, b) _mm_and_ps(a, b)
#define FOVPT__V_SIGN(a) _mm_and_ps(a, _mm_set1_ps(-0.0f))
#define FOVPT__V_ABS(a) _mm_andnot_ps(_mm_set1_ps(-0.0f), a)
#define FOVPT__V_XOR(a, m) _mm_xor_ps(a, m)
#define FOVPT__M_BITS(m) ((uint32_t)_mm_movemask_ps(m))
/* p[0], p[1], p[2], w: three floats of a caller's float[3] (no load past it) and a constant */
#define FOVPT__V_LD3(p, w)                                                                 \
    _mm_movelh_ps(_mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)(p)),        \
                  _mm_unpacklo_ps(_mm_load_ss((p) + 2), _mm_set_ss(w)))
#elif !defined(FOVPT_NO_SIMD) && defined(__aarch64__) && (defined(__ARM_NEON) || defined(_M_ARM64))
#define FOVPT__SIMD 2
#include <arm_neon.h>
typedef float32x4_t fovpt__v4;
typedef uint32x4_t fovpt__m4;
#define FOVPT__V_SET1(x) vdupq_n_f32(x)
#define FOVPT__V_LD(p) vld1q_f32(p)
#define FOVPT__V_ST(p, a) vst1q_f32(p, a)
#define FOVPT__V_ADD(a, b) vaddq_f32(a, b)
#define FOVPT__V_SUB(a, b) vsubq_f32(a, b)
#define FOVPT__V_MUL(a, b) vmulq_f32(a, b)
#define FOVPT__V_DIV(a, b) vdivq_f32(a, b)
#define FOVPT__V_MAXT(a, t) vbslq_f32(vcgtq_f32(a, t), a, t)
#define FOVPT__V_MINT(a, t) vbslq_f32(vcltq_f32(a, t), a, t)
#define FOVPT__V_LE(a, b) vcleq_f32(a, b)
#define FOVPT__V_LT(a, b) vcltq_f32(a, b)
#define FOVPT__V_GE(a, b) vcgeq_f32(a, b)
#define FOVPT__V_GT(a, b) vcgtq_f32(a, b)
#define FOVPT__M_AND(a, b) vandq_u32(a, b)
#define FOVPT__V_SIGN(a) vandq_u32(vreinterpretq_u32_f32(a), vdupq_n_u32(0x80000000u))
#define FOVPT__V_ABS(a) vabsq_f32(a)
#define FOVPT__V_XOR(a, m) vreinterpretq_f32_u32(veorq_u32(vreinterpretq_u32_f32(a), m))
FOV__PRIV uint32_t fovpt__neon_bits(uint32x4_t m)
{
    static const uint32_t w[4] = { 1u, 2u, 4u, 8u };
    return vaddvq_u32(vandq_u32(m, vld1q_u32(w)));
}
#define FOVPT__M_BITS(m) fovpt__neon_bits(m)
#define FOVPT__V_LD3(p, w) vcombine_f32(vld1_f32(p), vset_lane_f32((p)[2], vdup_n_f32(w), 0))
#elif !defined(FOVPT_NO_SIMD) && defined(__wasm_simd128__)
#define FOVPT__SIMD 3
#include <wasm_simd128.h>
typedef v128_t fovpt__v4;
typedef v128_t fovpt__m4;
#define FOVPT__V_SET1(x) wasm_f32x4_splat(x)
#define FOVPT__V_LD(p) wasm_v128_load(p)
#define FOVPT__V_ST(p, a) wasm_v128_store(p, a)
#define FOVPT__V_ADD(a, b) wasm_f32x4_add(a, b)
#define FOVPT__V_SUB(a, b) wasm_f32x4_sub(a, b)
#define FOVPT__V_MUL(a, b) wasm_f32x4_mul(a, b)
#define FOVPT__V_DIV(a, b) wasm_f32x4_div(a, b)
#define FOVPT__V_MAXT(a, t) wasm_f32x4_pmax(t, a) /* t < a ? a : t */
#define FOVPT__V_MINT(a, t) wasm_f32x4_pmin(t, a) /* a < t ? a : t */
#define FOVPT__V_LE(a, b) wasm_f32x4_le(a, b)
#define FOVPT__V_LT(a, b) wasm_f32x4_lt(a, b)
#define FOVPT__V_GE(a, b) wasm_f32x4_ge(a, b)
#define FOVPT__V_GT(a, b) wasm_f32x4_gt(a, b)
#define FOVPT__M_AND(a, b) wasm_v128_and(a, b)
#define FOVPT__V_SIGN(a) wasm_v128_and(a, wasm_i32x4_splat((int32_t)0x80000000u))
#define FOVPT__V_ABS(a) wasm_f32x4_abs(a)
#define FOVPT__V_XOR(a, m) wasm_v128_xor(a, m)
#define FOVPT__M_BITS(m) ((uint32_t)wasm_i32x4_bitmask(m))
#define FOVPT__V_LD3(p, w) wasm_f32x4_make((p)[0], (p)[1], (p)[2], w)
#else
#define FOVPT__SIMD 0
#endif
#define FOVPT__SSE (FOVPT__SIMD == 1)
/* the denoiser's a-trous pass 4 pixels at once: SSE2 (x86-64, or x86 with SSE2 float maths:
   a 32-bit gcc build with -msse2 alone keeps x87 maths for the scalar reference) */
#if FOVPT__SIMD == 1 && ((defined(__SSE2__) && defined(__SSE2_MATH__)) || defined(_M_X64) || \
                         (defined(_M_IX86_FP) && _M_IX86_FP >= 2))
#define FOVPT__DN_SSE2 1
#include <emmintrin.h>
#else
#define FOVPT__DN_SSE2 0
#endif


#ifndef FOVPT_MAX_WHITTED /* Whitted depth cap (the branch stack has 2x this many entries) */
#define FOVPT_MAX_WHITTED 16u
#endif
#ifndef FOVPT_RAY_EPS
#define FOVPT_RAY_EPS 1e-4f
#endif
#define FOVPT__BINS_MAX 32u
#define FOVPT__LEAF_MAX 16u


FOVPT__PRIV void fovpt__set3(float d[3], float x, float y, float z)
{ d[0] = x; d[1] = y; d[2] = z; }
FOVPT__PRIV void fovpt__copy3(float d[3], const float s[3])
{ d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; }
FOVPT__PRIV void fovpt__sub3(float d[3], const float a[3], const float b[3])
{
    d[0] = a[0] - b[0]; d[1] = a[1] - b[1]; d[2] = a[2] - b[2];
}
FOVPT__PRIV void fovpt__madd3(float d[3], const float a[3], float s, const float b[3])
{
    d[0] = a[0] + s * b[0]; d[1] = a[1] + s * b[1]; d[2] = a[2] + s * b[2];
}
FOVPT__PRIV float fovpt__max3(const float v[3]) { return fov__maxf(v[0], fov__maxf(v[1], v[2])); }
FOVPT__PRIV float fovpt__mean3(const float v[3]) { return (v[0] + v[1] + v[2]) * (1.0f / 3.0f); }
FOVPT__PRIV int fovpt__nonzero3(const float v[3])
{ return v[0] > 0.0f || v[1] > 0.0f || v[2] > 0.0f; }
/* The unit normal a x b / |a x b| of edges of any finite length: when the cross product
   under- or overflows, each edge is first scaled to a largest component of 1 (the
   direction does not change). n = 0 when the edges are parallel or zero. */
FOVPT__PRIV void fovpt__unit_normal(const float a[3], const float b[3], float n[3])
{
    float x[3], y[3], mx, my;
    fov__cross(a, b, n);
    if (fov__normalize(n) > 0.0f) return;
    mx = fov__maxf(fov__absf(a[0]), fov__maxf(fov__absf(a[1]), fov__absf(a[2])));
    my = fov__maxf(fov__absf(b[0]), fov__maxf(fov__absf(b[1]), fov__absf(b[2])));
    fovpt__set3(n, 0.0f, 0.0f, 0.0f);
    if (!(mx > 0.0f && my > 0.0f) || !fov__finite(mx) || !fov__finite(my)) return;
    fovpt__set3(x, a[0] / mx, a[1] / mx, a[2] / mx);
    fovpt__set3(y, b[0] / my, b[1] / my, b[2] / my);
    fov__cross(x, y, n);
    if (!(fov__normalize(n) > 0.0f)) fovpt__set3(n, 0.0f, 0.0f, 0.0f);
}
/* An orthonormal basis around unit n (Duff et al. 2017, branchless up to the sign). */
FOVPT__PRIV void fovpt__basis(const float n[3], float t[3], float b[3])
{
    float sg = n[2] >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sg + n[2]);
    float c = n[0] * n[1] * a;
    fovpt__set3(t, 1.0f + sg * n[0] * n[0] * a, sg * c, -sg * n[0]);
    fovpt__set3(b, c, sg + n[1] * n[1] * a, -n[1]);
}


/* ---- results, names, configs ------------------------------------------------------------ */
FOVPT_API const char *fovpt_result_string(fov_result r) { return fov__result_string(r); }
/* The shared eccentricity model (see fov_display). */
FOVPT_API fov_result fovpt_ecc_init(fov_ecc_model *m, const fov_display *d, float fov_y_deg,
                                    uint32_t w, uint32_t h, fov_gaze g)
{ return fov__ecc_init(m, d, fov_y_deg, w, h, g, FOVPT_MAX_DIM); }
FOVPT_API float fovpt_ecc_deg(const fov_ecc_model *m, float x, float y)
{
    return fov__ecc_deg(m, x, y);
}
FOVPT_API float fovpt_ecc_ppd(const fov_ecc_model *m) { return fov__ecc_ppd(m); }
FOVPT_API float fovpt_eye_mar(const fov_eye *eye, float ecc_deg)
{ return fov__eye_mar(eye, ecc_deg); }
FOVPT_API float fovpt_eye_density(const fov_eye *eye, float ppd, float ecc_deg)
{ return fov__eye_density(eye, ppd, ecc_deg); }
FOVPT_API float fovpt_eye_ecc(const fov_eye *eye, float ppd, float density)
{ return fov__eye_ecc(eye, ppd, density); }
FOVPT_API fov_result fovpt_eye_plan(const fov_eye *eye, const fov_ecc_model *m,
                                    fov_eye_plan *plan)
{ return fov__eye_plan(eye, m, plan); }

/* ---- gaze input (GAZE INPUT; the shared fov__gaze_*) ------------------------------------- */
FOVPT_API fov_gaze_filter_config fovpt_gaze_filter_config_default(void)
{
    fov_gaze_filter_config c;
    const char *bad;
    FOV_MEMSET(&c, 0, sizeof c);
    (void)fov__gaze_cfg(0, &c, &bad);
    return c;
}
FOVPT_API fov_result fovpt_gaze_filter_init(fov_gaze_filter *f, const fov_gaze_filter_config *cfg)
{
    fov_gaze_filter_config c;
    const char *bad;
    fov_result r;
    if (!f) {
        if (cfg)
            return fov__err(&cfg->logger, "fovpt", FOV_ERR_NULL,
                            FOV__MSG("gaze_filter_init: f is NULL"), (uint32_t)__LINE__);
        return FOV_ERR_NULL;
    }
    r = fov__gaze_cfg(cfg, &c, &bad);
    if (r != FOV_OK) return cfg ? fov__err(&cfg->logger, "fovpt", r, bad, (uint32_t)__LINE__) : r;
    FOV_MEMSET(f, 0, sizeof *f);
    f->cfg = c;
    return FOV_OK;
}
FOVPT_API void fovpt_gaze_filter_reset(fov_gaze_filter *f)
{
    if (f) fov__gaze_reset(f);
}
FOVPT_API fov_result fovpt_gaze_filter_push(fov_gaze_filter *f, uint64_t t_us, float x_deg,
                                            float y_deg)
{
    const char *bad;
    fov_result r;
    if (!f) return FOV_ERR_NULL;
    r = fov__gaze_push(f, t_us, x_deg, y_deg, &bad);
    return r == FOV_OK ? r : fov__err(&f->cfg.logger, "fovpt", r, bad, (uint32_t)__LINE__);
}
FOVPT_API fov_result fovpt_gaze_filter_push_px(fov_gaze_filter *f, const fov_ecc_model *m,
                                               uint64_t t_us, fov_gaze raw, fov_gaze *out)
{
    const char *bad;
    fov_result r;
    if (!f) return FOV_ERR_NULL;
    if (!m)
        return fov__err(&f->cfg.logger, "fovpt", FOV_ERR_NULL,
                        FOV__MSG("gaze_filter_push_px: m is NULL"), (uint32_t)__LINE__);
    r = fov__gaze_push_px(f, m, t_us, raw, out, &bad);
    return r == FOV_OK ? r : fov__err(&f->cfg.logger, "fovpt", r, bad, (uint32_t)__LINE__);
}
FOVPT_API fov_result fovpt_gaze_to_deg(const fov_ecc_model *m, fov_gaze px, float deg[2])
{
    if (!m || !deg) return FOV_ERR_NULL;
    if (!fov__finite(px.x) || !fov__finite(px.y)) return FOV_ERR_NOT_FINITE;
    return fov__gaze_to_deg(m, px.x, px.y, deg) ? FOV_OK : FOV_ERR_INVALID_ARG;
}
FOVPT_API fov_result fovpt_gaze_from_deg(const fov_ecc_model *m, const float deg[2], fov_gaze *px)
{
    fov_gaze g;
    if (!m || !deg || !px) return FOV_ERR_NULL;
    if (!fov__finite(deg[0]) || !fov__finite(deg[1])) return FOV_ERR_NOT_FINITE;
    if (!fov__gaze_from_deg(m, deg, &g.x, &g.y)) return FOV_ERR_INVALID_ARG;
    *px = g;
    return FOV_OK;
}
FOVPT_API fov_result fovpt_gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                       float latency_ms, float *margin_deg)
{
    fov_result r = fov__gaze_margin(f, accuracy_deg, latency_ms, margin_deg);
    if (r == FOV_OK || !f) return r;
    return fov__err(&f->cfg.logger, "fovpt", r,
                    margin_deg ? FOV__MSG("gaze_margin: accuracy_deg must be in [0, 90] and "
                                          "latency_ms in [0, 1e6], finite (*margin_deg: the cap)")
                               : FOV__MSG("gaze_margin: margin_deg is NULL"),
                    (uint32_t)__LINE__);
}
FOVPT_API fov_result fovpt_gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                        float latency_ms, fov_gaze_prediction *out)
{
    fov_result r = fov__gaze_predict(f, accuracy_deg, latency_ms, out);
    if (r == FOV_OK || !f) return r;
    return fov__err(&f->cfg.logger, "fovpt", r,
                    out ? FOV__MSG("gaze_predict: accuracy_deg must be in [0, 90] and "
                                   "latency_ms in [0, 1e6], finite (*out: the filtered gaze "
                                   "and the cap)")
                        : FOV__MSG("gaze_predict: out is NULL"),
                    (uint32_t)__LINE__);
}
FOVPT_API fov_result fovpt_gaze_fixed(const fov_display *display, uint32_t width,
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
FOVPT_API fov_result fovpt_camera_display(const fov_camera *cam, fov_display *out)
{
    fov_display d;
    fov_result r = fov__camera_display(cam, &d);
    if (r == FOV_OK && out) *out = d;
    return out ? r : FOV_ERR_NULL;
}
FOVPT_API fov_result fovpt_config_gaze_margin(const fovpt_config *base, float margin_deg,
                                              fovpt_config *out)
{
    fovpt_config c;
    fov_result r;
    uint32_t i;
    int over = 0;
    if (!base || !out) return FOV_ERR_NULL;
    if (!fov__finite(margin_deg))
        FOVPT__FAIL(&base->logger, FOV_ERR_NOT_FINITE,
                    "config_gaze_margin: margin NaN or infinite");
    if (margin_deg < 0.0f)
        FOVPT__FAIL(&base->logger, FOV_ERR_INVALID_ARG,
                    "config_gaze_margin: margin must be >= 0");
    r = fovpt_config_resolve(base, &c);
    if (r != FOV_OK) return r;
    for (i = 0; i < c.layers.count && i < FOVPT_MAX_LAYERS; ++i)
        if (c.layers.layer[i].radius_deg > 0.0f) {
            c.layers.layer[i].radius_deg += margin_deg;
            over |= !(c.layers.layer[i].radius_deg < 180.0f);
        }
    c.zones.inner_deg += margin_deg;
    c.zones.middle_deg += margin_deg;
    over |= !(c.zones.middle_deg < 180.0f) || !(c.zones.inner_deg < 180.0f);
    for (i = 0; i < 5u; ++i) {
        c.selective.e_deg[i] += margin_deg;
        over |= !(c.selective.e_deg[i] < 180.0f);
    }
    if (over)
        FOVPT__FAIL(&base->logger, FOV_ERR_LIMIT,
                    "config_gaze_margin: a layer, zone or selective radius reaches 180");
    *out = c;
    return FOV_OK;
}

FOVPT_API const char *fovpt_method_name(uint32_t method)
{
    static const char *const names[] = { "uniform", "layers", "zones", "selective", "jin" };
    return method < (uint32_t)_FOVPT_METHOD_NUM ? names[method] : "unknown";
}

FOVPT_API fov_result fovpt_layers_preset(fovpt_layers_cfg *o, uint32_t preset)
{
    /* Axblad 2020, Sec. 3.1.3: 6, 10, 20 degrees; d = 4 (background), 3, 2, 1; 4 spp */
    static const float rad[3] = { 20.0f, 10.0f, 6.0f };
    uint32_t i;
    if (!o) return FOV_ERR_NULL;
    if (preset >= (uint32_t)_FOVPT_LAYERS_PRESET_NUM) return FOV_ERR_INVALID_ARG;
    FOV_MEMSET(o, 0, sizeof *o);
    o->count = 4;
    o->layer[0].radius_deg = 0.0f; /* no occlusion mask */
    o->layer[0].stride = 4;
    o->layer[0].spp = 4;
    for (i = 1; i < 4; ++i) {
        o->layer[i].radius_deg =
            preset == FOVPT_LAYERS_KTH_DIAMETER ? 0.5f * rad[i - 1] : rad[i - 1];
        o->layer[i].stride = 4u - i;
        o->layer[i].spp = 4;
    }
    o->blend_deg = 1.0f;
    return FOV_OK;
}

FOVPT__PRIV int fovpt__pos(float v) { return v > 0.0f && fov__finite(v); }
FOVPT__PRIV int fovpt__bad_f(float v) { return !fov__finite(v); }

/* Logs "config.layers.layer[<i>].<rule>" and returns r. */
FOVPT__PRIV fov_result fovpt__layer_fail(const fov_logger *lg, fov_result r, uint32_t i,
                                         const char *rule, uint32_t line)
{
#ifndef FOV_NO_ERROR_STRINGS
    char b[16];
    uint32_t n = fov__app(b, 0, sizeof b, "[");
    n = fov__appu(b, n, sizeof b, i);
    (void)fov__app(b, n, sizeof b, "].");
    return fov__err3(lg, "fovpt", r, "config.layers.layer", b, rule, line);
#else
    (void)i; (void)rule;
    return fov__err(lg, "fovpt", r, "", line);
#endif
}

FOVPT_API fov_result fovpt_config_resolve(const fovpt_config *in, fovpt_config *out)
{
    fovpt_config c;
    const fov_logger *lg;
    uint32_t i;
    if (!in) return FOV_ERR_NULL;
    if (!out) FOVPT__FAIL(&in->logger, FOV_ERR_NULL, "config_resolve: out is NULL");
    c = *in;
    lg = &c.logger;
    if (c.method >= (uint32_t)_FOVPT_METHOD_NUM)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.method: unknown (see fovpt_method)");
    if (c.mode >= (uint32_t)_FOVPT_MODE_NUM)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.mode: unknown (see fovpt_mode)");
    if (c.spp == 0) c.spp = 1;
    if (c.spp > FOVPT_MAX_SPP) FOVPT__FAIL(lg, FOV_ERR_LIMIT, "config.spp above FOVPT_MAX_SPP");
    if (c.max_depth == 0) c.max_depth = c.mode == FOVPT_MODE_WHITTED ? 3u : 8u;
    if (c.max_depth > FOVPT_MAX_BOUNCES)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "config.max_depth above FOVPT_MAX_BOUNCES");
    if (c.mode == FOVPT_MODE_WHITTED && c.max_depth > FOVPT_MAX_WHITTED)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "config.max_depth above FOVPT_MAX_WHITTED (Whitted)");
    if (c.rr_start == 0) c.rr_start = 3;
    if (c.no_nee > 1) FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.no_nee must be 0 or 1");
    if (c.accumulate > 1) FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.accumulate must be 0 or 1");
    if (c.sampler >= (uint32_t)_FOVPT_SAMPLER_NUM)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.sampler: unknown (see fovpt_sampler)");
    if (c.sampler == (uint32_t)FOVPT_SAMPLER_DEFAULT) c.sampler = (uint32_t)FOVPT_SAMPLER_SOBOL;
    if (c.robust == 1u || c.robust == 2u)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                    "config.robust must be 0 (off) or 3 .. FOVPT_ROBUST_MAX groups");
    if (c.robust > (uint32_t)FOVPT_ROBUST_MAX)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "config.robust above FOVPT_ROBUST_MAX");
    if (c.mirror_nee > 1u)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.mirror_nee must be 0 or 1");
    /* layers (Axblad 2020) */
    if (c.layers.count == 0) {
        float bd = c.layers.blend_deg;
        uint32_t lin = c.layers.blend_linear, snap = c.layers.snap, bs = c.layers.bspline;
        uint32_t ho = c.layers.hollow, cj = c.layers.cell_jitter;
        float cw = c.layers.clamp_white;
        fovpt_layers_preset(&c.layers, FOVPT_LAYERS_KTH_RADIUS);
        if (!(bd <= 0.0f && bd >= 0.0f)) c.layers.blend_deg = bd;
        c.layers.blend_linear = lin;
        c.layers.snap = snap;
        c.layers.bspline = bs;
        c.layers.hollow = ho;
        c.layers.cell_jitter = cj;
        c.layers.clamp_white = cw;
    }
    if (c.layers.count < 2 || c.layers.count > FOVPT_MAX_LAYERS)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.count must be 2 .. FOVPT_MAX_LAYERS");
    if (fovpt__bad_f(c.layers.blend_deg))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.layers.blend_deg is NaN or infinite");
    if (c.layers.blend_deg < 0.0f)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.blend_deg must be >= 0");
    if (c.layers.blend_deg <= 0.0f) c.layers.blend_deg = 1.0f;
    if (c.layers.blend_linear > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.blend_linear must be 0 or 1");
    if (c.layers.snap > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.snap must be 0 or 1");
    if (c.layers.bspline > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.bspline must be 0 or 1");
    if (c.layers.hollow > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.hollow must be 0 or 1");
    if (c.layers.cell_jitter > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers.cell_jitter must be 0 or 1");
    if (fovpt__bad_f(c.layers.clamp_white) || fovpt__bad_f(c.zones.clamp_white))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.layers/zones.clamp_white is NaN or infinite");
    if (c.layers.clamp_white < 0.0f || c.zones.clamp_white < 0.0f)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.layers/zones.clamp_white must be >= 0");
    if (fovpt__bad_f(c.acuity_budget))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.acuity_budget is NaN or infinite");
    if (!(c.acuity_budget >= 0.0f && c.acuity_budget <= 64.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.acuity_budget must be in [0, 64]");
    for (i = 0; i < c.layers.count; ++i) {
        const fovpt_layer *L = &c.layers.layer[i];
        const char *bad = 0; /* the broken rule, logged as "config.layers.layer[i].<rule>" */
        fov_result e = FOV_ERR_INVALID_ARG;
        if (fovpt__bad_f(L->radius_deg)) {
            bad = FOV__MSG("radius_deg is NaN or infinite");
            e = FOV_ERR_NOT_FINITE;
        }
        else if (L->stride < 1) bad = FOV__MSG("stride must be >= 1");
        else if (L->stride > 64) { bad = FOV__MSG("stride above 64"); e = FOV_ERR_LIMIT; }
        else if (L->spp < 1) bad = FOV__MSG("spp must be >= 1");
        else if (L->spp > FOVPT_MAX_SPP) {
            bad = FOV__MSG("spp above FOVPT_MAX_SPP");
            e = FOV_ERR_LIMIT;
        }
        else if (i == 0 && L->radius_deg < 0.0f) bad = FOV__MSG("radius_deg (mask) must be >= 0");
        else if (i > 0 && !(L->radius_deg > 0.0f && L->radius_deg < 180.0f))
            bad = FOV__MSG("radius_deg must be in (0, 180)");
        else if (i > 1 && !(L->radius_deg < c.layers.layer[i - 1].radius_deg))
            bad = FOV__MSG("radius_deg must be below the previous layer's");
        if (bad) return fovpt__layer_fail(lg, e, i, bad, (uint32_t)__LINE__);
    }
    if (c.layers.layer[0].radius_deg > 0.0f &&
        !(c.layers.layer[1].radius_deg < c.layers.layer[0].radius_deg))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                    "config.layers.layer[1].radius_deg must be below layer[0]'s (the mask)");
    /* zones (Polychronakis 2025) */
    if (fovpt__bad_f(c.zones.inner_deg))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.zones.inner_deg is NaN or infinite");
    if (fovpt__bad_f(c.zones.middle_deg))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.zones.middle_deg is NaN or infinite");
    if (fovpt__bad_f(c.zones.overlap_px))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.zones.overlap_px is NaN or infinite");
    if (c.zones.inner_deg <= 0.0f) c.zones.inner_deg = 7.5f;
    if (c.zones.middle_deg <= 0.0f) c.zones.middle_deg = 32.5f;
    if (c.zones.overlap_px <= 0.0f) c.zones.overlap_px = 4.0f;
    if (c.zones.lanczos_a == 0) c.zones.lanczos_a = 3;
    if (!(c.zones.middle_deg > c.zones.inner_deg) || c.zones.middle_deg >= 180.0f)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.zones: needs inner_deg < middle_deg < 180");
    if (c.zones.overlap_px > 64.0f)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.zones.overlap_px above 64");
    if (c.zones.lanczos_a != 2 && c.zones.lanczos_a != 3)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.zones.lanczos_a must be 2 or 3 (0: 3)");
    if (c.zones.bspline > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.zones.bspline must be 0 or 1");
    if (c.zones.hollow > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.zones.hollow must be 0 or 1");
    if (c.zones.cell_jitter > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.zones.cell_jitter must be 0 or 1");
    for (i = 0; i < 3; ++i) {
        /* 0 stays 0 (cfg.spp at use: a config resolved before spp is set keeps following it) */
        if (c.zones.spp[i] > FOVPT_MAX_SPP)
            FOVPT__FAIL(lg, FOV_ERR_LIMIT, "config.zones.spp[] above FOVPT_MAX_SPP");
    }
    /* selective (Kim et al. 2021) */
    {
        static const float e_def[5] = { 3.3f, 5.5f, 12.1f, 30.0f, 45.0f };
        static const uint32_t n_def[4] = { 9, 4, 2, 1 };
        static const float ts_def[4] = { 1.0f, 2.0f, 0.5f, 12.0f };
        static const float tau_def[9] =
            { 0.02f, 0.05f, 0.06f, 0.06f, 0.02f, 0.02f, 0.02f, 0.06f, 0.02f };
        fovpt_selective_cfg *s = &c.selective;
        int all0 = 1;
        for (i = 0; i < 5; ++i) {
            if (fovpt__bad_f(s->e_deg[i]))
                FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.selective.e_deg[] NaN or infinite");
            if (s->e_deg[i] > 0.0f || s->e_deg[i] < 0.0f) all0 = 0;
        }
        if (all0) for (i = 0; i < 5; ++i) s->e_deg[i] = e_def[i];
        for (i = 0; i < 5; ++i)
            if (!(s->e_deg[i] > (i ? s->e_deg[i - 1] : 0.0f)) || s->e_deg[i] >= 180.0f)
                FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                            "config.selective.e_deg must increase, within (0, 180)");
        if ((s->n_sd[0] | s->n_sd[1] | s->n_sd[2] | s->n_sd[3]) == 0)
            for (i = 0; i < 4; ++i) s->n_sd[i] = n_def[i];
        for (i = 0; i < 4; ++i)
            if (s->n_sd[i] > 64) FOVPT__FAIL(lg, FOV_ERR_LIMIT, "config.selective.n_sd[] above 64");
        all0 = 1;
        for (i = 0; i < 4; ++i) {
            if (fovpt__bad_f(s->tau_shape[i]))
                FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.selective.tau_shape[] NaN or infinite");
            if (s->tau_shape[i] > 0.0f || s->tau_shape[i] < 0.0f) all0 = 0;
        }
        if (all0) for (i = 0; i < 4; ++i) s->tau_shape[i] = ts_def[i];
        for (i = 0; i < 9; ++i) {
            if (fovpt__bad_f(s->tau[i]))
                FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.selective.tau[] NaN or infinite");
            if (s->tau[i] < 0.0f)
                FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.selective.tau[] must be >= 0");
            if (s->tau[i] <= 0.0f) s->tau[i] = tau_def[i];
        }
        if (fovpt__bad_f(s->normal_tol_deg))
            FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE,
                        "config.selective.normal_tol_deg is NaN or infinite");
        if (s->normal_tol_deg <= 0.0f) s->normal_tol_deg = 10.0f;
        if (s->normal_tol_deg > 180.0f)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.selective.normal_tol_deg above 180");
        if (s->fill_centre > 1)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.selective.fill_centre must be 0 or 1");
        {
            /* tau_fov shape: positive, and x(t) monotone on both Bezier segments */
            float t0 = s->tau_shape[0], tf = s->tau_shape[1], tp = s->tau_shape[2],
                tn = s->tau_shape[3];
            float ef = s->e_deg[0], enp = s->e_deg[3];
            if (!(t0 > 0.0f && tf > 0.0f && tn > 0.0f && tp > 0.0f) ||
                tp < (tf - t0) / ef || tp < (tn - tf) / (enp - ef))
                FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                            "config.selective.tau_shape: needs all > 0 and x(t) monotone");
        }
    }
    /* temporal (Kim et al. 2021) */
    {
        static const float a_def[6] = { 0.9f, 0.8f, 0.7f, 0.5f, 0.2f, 0.1f };
        fovpt_temporal_cfg *t = &c.temporal;
        int all0 = 1;
        if (t->reuse > 1)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.reuse must be 0 or 1");
        if (t->smooth > 1)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.smooth must be 0 or 1");
        if (t->n_reuse_max == 0) t->n_reuse_max = 5;
        if (t->n_reuse_max > 5)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.n_reuse_max must be 1 .. 5");
        if (fovpt__bad_f(t->tau_reuse))
            FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.temporal.tau_reuse is NaN or infinite");
        if (fovpt__bad_f(t->eps_depth))
            FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.temporal.eps_depth is NaN or infinite");
        if (t->tau_reuse < 0.0f)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.tau_reuse must be >= 0");
        if (t->eps_depth < 0.0f)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.eps_depth must be >= 0");
        if (t->tau_reuse <= 0.0f) t->tau_reuse = 1.0f;
        if (t->eps_depth <= 0.0f) t->eps_depth = 0.01f;
        if (t->n_tpi == 0) t->n_tpi = 4;
        if (t->n_tpi > 4)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.n_tpi must be 1 .. 4");
        for (i = 0; i < 6; ++i) {
            if (fovpt__bad_f(t->alpha[i]))
                FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "config.temporal.alpha[] NaN or infinite");
            if (t->alpha[i] > 0.0f || t->alpha[i] < 0.0f) all0 = 0;
        }
        if (all0) for (i = 0; i < 6; ++i) t->alpha[i] = a_def[i];
        for (i = 0; i < 6; ++i)
            if (!(t->alpha[i] > 0.0f && t->alpha[i] <= 1.0f))
                FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "config.temporal.alpha[] must be in (0, 1]");
    }
    /* display */
    {
        fov_result e = fov__display_check(lg, "fovpt", &c.display, 3, (uint32_t)__LINE__);
        if (e != FOV_OK) return e;
    }
    *out = c;
    return FOV_OK;
}

FOVPT_API fovpt_config fovpt_config_default(void)
{
    fovpt_config c;
    FOV_MEMSET(&c, 0, sizeof c);
    (void)fovpt_config_resolve(&c, &c);
    return c;
}

/* ---- camera ------------------------------------------------------------------------------- */
FOVPT_API void fovpt_camera_init(fovpt_camera *cam, uint32_t width, uint32_t height)
{
    fov__camera_init(cam, width, height);
}

/* Basis, image-plane tangents and the pinhole (pos itself when eye_offset is 0, bit for
   bit); validates the camera. */
FOVPT__PRIV fov_result fovpt__camera_setup(const fovpt_camera *cam, float r[3], float u[3],
                                           float f[3], float tan4[4], float org[3])
{
    float lf, lr, fy;
    int asym, k;
    if (!cam) return FOV_ERR_NULL;
    if (cam->width == 0 || cam->height == 0) return FOV_ERR_INVALID_ARG;
    if (cam->width > FOVPT_MAX_DIM || cam->height > FOVPT_MAX_DIM) return FOV_ERR_LIMIT;
    if (!fov__finite3(cam->pos) || !fov__finite3(cam->target) || !fov__finite3(cam->up) ||
        !fov__finite(cam->fov_y_deg) || !fov__finite(cam->tan_left) ||
        !fov__finite(cam->tan_right) || !fov__finite(cam->tan_bottom) ||
        !fov__finite(cam->tan_top) || !fov__finite(cam->eye_offset))
        return FOV_ERR_NOT_FINITE;
    /* fovpt's own frame, not fov__camera_basis: it normalises without prescaling first and
       does not renormalise up = r x f, so on ordinary cameras up differs from the shared
       frame in the last bit (and r, f too for vectors near 1e-15 or 1e15 long); the shared
       one would change fovpt's images */
    fovpt__sub3(f, cam->target, cam->pos);
    fovpt__copy3(u, cam->up);
    if (!fovpt__nonzero3(u) && !(u[0] < 0.0f || u[1] < 0.0f || u[2] < 0.0f))
        fovpt__set3(u, 0.0f, 1.0f, 0.0f);
    /* a view vector of 1e-25 or 3e38 and an up hint of 1e-30 or 3e38 are valid: the
       normalisation prescales; a view vector that overflows (target - pos beyond FLT_MAX)
       or is zero is degenerate */
    lf = fov__normalize(f);
    if (!(lf > 0.0f)) return FOV_ERR_DEGENERATE;
    fov__normalize(u);
    fov__cross(f, u, r);
    lr = fov__normalize(r);
    if (!(lr > 1e-6f)) return FOV_ERR_DEGENERATE;
    fov__cross(r, f, u);
    fovpt__copy3(org, cam->pos);
    if (!fov__is0(cam->eye_offset)) {
        for (k = 0; k < 3; ++k) org[k] = cam->pos[k] + cam->eye_offset * r[k];
        if (!fov__finite3(org)) return FOV_ERR_INVALID_ARG; /* a pinhole beyond FLT_MAX */
    }
    asym = fov__absf(cam->tan_left) > 0.0f || fov__absf(cam->tan_right) > 0.0f ||
           fov__absf(cam->tan_bottom) > 0.0f || fov__absf(cam->tan_top) > 0.0f;
    if (asym) {
        if (!(cam->tan_left + cam->tan_right > 1e-6f) ||
            !(cam->tan_bottom + cam->tan_top > 1e-6f) || cam->tan_left > 1e6f ||
            cam->tan_right > 1e6f || cam->tan_top > 1e6f || cam->tan_bottom > 1e6f)
            return FOV_ERR_INVALID_ARG;
        if (!fov__tan_aspect_ok(cam->tan_left, cam->tan_right, cam->tan_bottom, cam->tan_top,
                                cam->width, cam->height))
            return FOV_ERR_UNSUPPORTED;
        tan4[0] = -cam->tan_left; tan4[1] = cam->tan_right;
        tan4[2] = cam->tan_top; tan4[3] = -cam->tan_bottom;
    } else {
        float ty, tx;
        fy = cam->fov_y_deg > 0.0f || cam->fov_y_deg < 0.0f ? cam->fov_y_deg : 60.0f;
        if (!(fy > 0.0f && fy < 180.0f)) return FOV_ERR_INVALID_ARG;
        ty = FOV__TAN(0.5f * fy * FOV__DEG);
        tx = ty * (float)cam->width / (float)cam->height;
        tan4[0] = -tx; tan4[1] = tx; tan4[2] = ty; tan4[3] = -ty;
    }
    return FOV_OK;
}

/* The unit direction through image point (x, y); returns its length before normalising,
   0 when it is not finite (x or y so far off the image that the image-plane offset
   overflows: only fovpt_camera_ray can ask for such points). */
FOVPT__PRIV float fovpt__primary(const float r[3], const float u[3], const float f[3],
                                 const float tan4[4], uint32_t w, uint32_t h, float x, float y,
                                 float dir[3])
{
    float sx = tan4[0] + (tan4[1] - tan4[0]) * (x / (float)w);
    float sy = tan4[2] + (tan4[3] - tan4[2]) * (y / (float)h);
    dir[0] = f[0] + sx * r[0] + sy * u[0];
    dir[1] = f[1] + sx * r[1] + sy * u[1];
    dir[2] = f[2] + sx * r[2] + sy * u[2];
    return fov__normalize(dir);
}

FOVPT_API fov_result fovpt_camera_ray(const fovpt_camera *cam, float x, float y, float org[3],
                                      float dir[3])
{
    float r[3], u[3], f[3], t4[4], o[3];
    fov_result e;
    if (!cam || !org || !dir) return FOV_ERR_NULL;
    if (!fov__finite(x) || !fov__finite(y)) return FOV_ERR_NOT_FINITE;
    e = fovpt__camera_setup(cam, r, u, f, t4, o);
    if (e != FOV_OK) return e;
    if (!(fovpt__primary(r, u, f, t4, cam->width, cam->height, x, y, dir) > 0.0f))
        return FOV_ERR_INVALID_ARG;
    fovpt__copy3(org, o);
    return FOV_OK;
}

FOVPT_API fov_result fovpt_gaze_from_point(const fovpt_camera *cam, const float p[3],
                                           fov_gaze *gaze)
{
    float r[3], u[3], f[3], t4[4], o[3], d[3], z, sx, sy, x, y;
    fov_result e;
    if (!cam || !p || !gaze) return FOV_ERR_NULL;
    if (!fov__finite3(p)) return FOV_ERR_NOT_FINITE;
    e = fovpt__camera_setup(cam, r, u, f, t4, o);
    if (e != FOV_OK) return e;
    /* invert fovpt__primary: direction f + sx r + sy u through (x, y), from the pinhole */
    fovpt__sub3(d, p, o);
    fov__prescale(d); /* a point 1e30 away: the ratios below do not depend on |d| */
    z = fov__dot(d, f);
    if (!(z > 1e-6f * fov__len(d))) return FOV_ERR_INVALID_ARG;
    sx = fov__dot(d, r) / z;
    sy = fov__dot(d, u) / z;
    x = (float)cam->width * ((sx - t4[0]) / (t4[1] - t4[0]));
    y = (float)cam->height * ((sy - t4[2]) / (t4[3] - t4[2]));
    if (!(fov__absf(x) <= 16777216.0f) || !(fov__absf(y) <= 16777216.0f))
        return FOV_ERR_INVALID_ARG;
    gaze->x = x;
    gaze->y = y;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_camera_eyes(const fovpt_camera *head, float ipd, fovpt_camera eyes[2])
{
    float r[3], u[3], f[3], t4[4], o[3];
    fov_result e;
    int k, i;
    if (!head || !eyes) return FOV_ERR_NULL;
    if (!fov__finite(ipd)) return FOV_ERR_NOT_FINITE;
    if (!(ipd >= 0.0f)) return FOV_ERR_INVALID_ARG;
    e = fovpt__camera_setup(head, r, u, f, t4, o);
    if (e != FOV_OK) return e;
    for (i = 0; i < 2; ++i) {
        float s = (i == 0 ? -0.5f : 0.5f) * ipd;
        eyes[i] = *head;
        for (k = 0; k < 3; ++k) {
            eyes[i].pos[k] = head->pos[k] + s * r[k];
            eyes[i].target[k] = head->target[k] + s * r[k];
        }
        if (!fov__finite3(eyes[i].pos) || !fov__finite3(eyes[i].target)) return FOV_ERR_NOT_FINITE;
    }
    return FOV_OK;
}

/* ---- materials, shapes, descriptions ------------------------------------------------------ */
FOVPT_API void fovpt_material_init(fovpt_material *m)
{
    if (!m) return;
    FOV_MEMSET(m, 0, sizeof *m);
    m->albedo[0] = m->albedo[1] = m->albedo[2] = 0.8f;
    m->exponent = 20.0f;
    m->ior = 1.5f;
}
FOVPT_API void fovpt_shape_sphere(fovpt_shape *s, float cx, float cy, float cz, float r,
                                  uint32_t material)
{
    if (!s) return;
    FOV_MEMSET(s, 0, sizeof *s);
    s->type = FOVPT_SHAPE_SPHERE;
    fovpt__set3(s->p, cx, cy, cz);
    s->r = r;
    s->material = material;
}
FOVPT_API void fovpt_shape_plane(fovpt_shape *s, const float point[3], const float normal[3],
                                 uint32_t material)
{
    if (!s || !point || !normal) return;
    FOV_MEMSET(s, 0, sizeof *s);
    s->type = FOVPT_SHAPE_PLANE;
    fovpt__copy3(s->p, point);
    fovpt__copy3(s->u, normal);
    s->material = material;
}
FOVPT_API void fovpt_shape_quad(fovpt_shape *s, const float corner[3], const float u[3],
                                const float v[3], uint32_t material)
{
    if (!s || !corner || !u || !v) return;
    FOV_MEMSET(s, 0, sizeof *s);
    s->type = FOVPT_SHAPE_QUAD;
    fovpt__copy3(s->p, corner);
    fovpt__copy3(s->u, u);
    fovpt__copy3(s->v, v);
    s->material = material;
}
FOVPT_API void fovpt_shape_box(fovpt_shape *s, const float lo[3], const float hi[3],
                               uint32_t material)
{
    if (!s || !lo || !hi) return;
    FOV_MEMSET(s, 0, sizeof *s);
    s->type = FOVPT_SHAPE_BOX;
    fovpt__copy3(s->p, lo);
    fovpt__copy3(s->u, hi);
    s->material = material;
}
FOVPT_API void fovpt_scene_desc_init(fovpt_scene_desc *d)
{
    if (d) FOV_MEMSET(d, 0, sizeof *d);
}

/* ---- scene: internal records -------------------------------------------------------------- */
/* One primitive. Triangle: a = v0, b = e1, c = e2. Sphere: a = centre, r. Quad: a = corner,
   b = u, c = v, n = u x v / |u x v|. Box: a = lo, b = hi. Plane: a = point, n = unit normal. */
typedef struct fovpt__prim {
    uint32_t type, material, id, light; /* light: emitter slot + 1, 0 = not sampled */
    float a[3], b[3], c[3], n[3];
    float r;
} fovpt__prim;
#define FOVPT__TRI 7u

typedef struct fovpt__node {
    float b[6];     /* box: lo x, y, z then hi x, y, z (a ray picks its slab planes by index) */
    uint32_t a;     /* leaf: first index into order; inner: left child (right = a + 1) */
    uint32_t n;     /* leaf: primitive count (>= 1); inner: 0 */
} fovpt__node;

/* The traversal's BVH: the binary tree collapsed to up to FOVPT__W (FOVPT_BVH_WIDTH: 8 with
   SIMD, 4 with FOVPT_NO_SIMD) children per node (each node opens its largest inner children
   until it has W). b[row][child], rows as in fovpt__node.b (lo x, y, z, hi x, y, z), so a
   ray's near and far rows are b[nb[k]] and b[fb[k]], the W children side by side; empty
   slots have an empty box (lo FLT_MAX, hi -FLT_MAX), which every ray misses. child: a node
   index, or FOVPT__LEAF4 | first << 5 | count for a leaf (count <= 16). 128 bytes (W = 4) or
   256 (W = 8). */
#ifndef FOVPT_BVH_WIDTH
#if FOVPT__SIMD /* 8-wide: fewer, fuller nodes; without AVX two 4-lane passes per node (0.10.0:
                   SSE2 1.08 / 1.11x on the terrain, 1.14-1.27x on the small scenes, wasm
                   SIMD128 1.07-1.11x against 4-wide, side by side) */
#define FOVPT_BVH_WIDTH 8
#else
#define FOVPT_BVH_WIDTH 4
#endif
#endif
#if FOVPT_BVH_WIDTH != 4 && FOVPT_BVH_WIDTH != 8
#error "fovpt: FOVPT_BVH_WIDTH must be 4 or 8"
#endif
#define FOVPT__W ((uint32_t)FOVPT_BVH_WIDTH)
typedef struct fovpt__node4 {
    float b[6][FOVPT_BVH_WIDTH];
    uint32_t child[FOVPT_BVH_WIDTH];
    uint32_t pad[FOVPT_BVH_WIDTH];
} fovpt__node4;
#define FOVPT__LEAF4 0x80000000u
/* A block of 4 leaf slots in fovpt_scene.leaf_tris: 48 floats (v0, e1, e2 and the unit
   normal as 12 rows of 4 lanes), then 3 rows of 4 uint32_t: the slots' primitive slot (index
   into the primitive records, as the leaf order), id and material, so a hit found in the
   block is reported without reading the primitive record (a cache miss per ray on a large
   mesh). 240 bytes. */
#define FOVPT__LBLK 60u
/* traversal stack: at most W - 1 entries pushed per node on the path, plus the root */
#define FOVPT__STACK ((FOVPT__W - 1u) * FOVPT_MAX_BVH_DEPTH + 2u)

typedef struct fovpt__layout {
    size_t prims, nodes, nodes4, order, lights, cdf, area, mirrors, pbox, total;
    uint32_t n_prims, n_bounded, n_tris, n_lights, n_mirrors, n_nodes_max, n_slots;
} fovpt__layout;
/* Leaf slots reserved for n bounded primitives: n rounded up to whole blocks of 4, plus
   FOVPT__SLACK(n) blocks for the padding that keeps leaves of <= 4 inside one block. */
#define FOVPT__SLACK(n) (((n) + 15u) / 16u)
#if FOVPT__SIMD
#define FOVPT__COMBINE 4u
#else
#define FOVPT__COMBINE 1u
#endif

/* |v| without the squares' under- or overflow (prescaled to a largest component of 1 when
   the squared length would leave [1e-30, 1e30]); +inf only when |v| > FLT_MAX. */
FOVPT__PRIV float fovpt__len_robust(const float v[3])
{
    float l2 = fov__dot(v, v), m, w[3];
    if (l2 >= 1e-30f && l2 <= 1e30f) return FOV__SQRT(l2);
    m = fov__maxf(fov__absf(v[0]), fov__maxf(fov__absf(v[1]), fov__absf(v[2])));
    if (!(m > 0.0f) || !fov__finite(m)) return m > 0.0f ? m : 0.0f;
    fovpt__set3(w, v[0] / m, v[1] / m, v[2] / m);
    return m * fov__len(w);
}
FOVPT__PRIV int fovpt__tri_area2(const float *v0, const float *v1, const float *v2, float *area2)
{
    float e1[3], e2[3], c[3], l1, l2, L;
    fovpt__sub3(e1, v1, v0);
    fovpt__sub3(e2, v2, v0);
    fov__cross(e1, e2, c);
    *area2 = fovpt__len_robust(c);
    if (!(*area2 > 0.0f) || !fov__finite(*area2) || !fov__finite3(c)) return 0;
    /* zero area, or below float resolution of the edge lengths: |e1 x e2| > 1e-12 (|e1|^2 +
       |e2|^2), compared in units of the longer edge so that no square under- or overflows */
    l1 = fovpt__len_robust(e1); l2 = fovpt__len_robust(e2); L = fov__maxf(l1, l2);
    if (!fov__finite(L)) return 0;
    return (*area2 / L) / L > 1e-12f * ((l1 / L) * (l1 / L) + (l2 / L) * (l2 / L));
}

FOVPT__PRIV int fovpt__emissive(const fovpt_material *m) { return fovpt__nonzero3(m->emission); }
/* a shape or primitive of this type and material is one of cfg.mirror_nee's targets
   (fovpt_scene.mirrors): a mirror sphere or quad */
FOVPT__PRIV int fovpt__mirror_kind(uint32_t type, const fovpt_material *m)
{
    return (type == FOVPT_SHAPE_SPHERE || type == FOVPT_SHAPE_QUAD) && m->type == FOVPT_MAT_MIRROR;
}

/* Validates a description and computes the memory layout. */
FOVPT__PRIV fov_result fovpt__plan(const fovpt_scene_desc *d, fovpt__layout *L)
{
    const fov_logger *lg;
    uint32_t i, k;
    uint64_t n_tris = 0, n_prims, n_bounded = 0, n_lights = 0, n_mirrors = 0, skipped = 0;
    uint64_t sz;
    if (!d) return FOV_ERR_NULL;
    lg = &d->logger;
    FOV_MEMSET(L, 0, sizeof *L);
    if (!d->materials || d->num_materials == 0)
        FOVPT__FAIL(lg, FOV_ERR_NULL, "scene: desc.materials NULL or num_materials 0");
    if (d->num_materials > 65536u)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "scene: desc.num_materials above 65536");
    if (d->num_shapes && !d->shapes)
        FOVPT__FAIL(lg, FOV_ERR_NULL, "scene: desc.shapes NULL with num_shapes > 0");
    if (d->num_meshes && !d->meshes)
        FOVPT__FAIL(lg, FOV_ERR_NULL, "scene: desc.meshes NULL with num_meshes > 0");
    if (d->num_shapes > FOVPT_MAX_PRIMS || d->num_meshes > FOVPT_MAX_PRIMS)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT,
                    "scene: desc.num_shapes or num_meshes above FOVPT_MAX_PRIMS");
    if (!fov__finite3(d->background))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "scene: desc.background NaN or infinite");
    if (d->background[0] < 0.0f || d->background[1] < 0.0f || d->background[2] < 0.0f)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: desc.background must be >= 0");
    if (d->bvh_bins == 1 || d->bvh_bins > FOVPT__BINS_MAX)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: desc.bvh_bins must be 0 or 2 .. 32");
    if (d->bvh_leaf > FOVPT__LEAF_MAX)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: desc.bvh_leaf must be 0 .. 16");
    if (d->bvh_max_depth == 1 || d->bvh_max_depth > FOVPT_MAX_BVH_DEPTH)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                    "scene: desc.bvh_max_depth must be 0 or 2 .. FOVPT_MAX_BVH_DEPTH");
    if (d->skip_degenerate > 1)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: desc.skip_degenerate must be 0 or 1");
    for (i = 0; i < d->num_materials; ++i) {
        const fovpt_material *m = &d->materials[i];
        if (m->type >= (uint32_t)_FOVPT_MAT_NUM)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                        "scene: materials[].type unknown (see fovpt_material_type)");
        if (!fov__finite3(m->albedo) || !fov__finite3(m->specular) || !fov__finite3(m->emission) ||
            !fov__finite(m->exponent) || !fov__finite(m->ior))
            FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "scene: a materials[] value NaN or infinite");
        for (k = 0; k < 3; ++k) {
            if (!(m->albedo[k] >= 0.0f && m->albedo[k] <= 1.0f) ||
                !(m->specular[k] >= 0.0f && m->specular[k] <= 1.0f))
                FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                            "scene: materials[].albedo and specular must be in [0, 1]");
            if (m->emission[k] < 0.0f)
                FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: materials[].emission must be >= 0");
        }
        if (m->exponent < 0.0f || m->exponent > 1e6f)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: materials[].exponent must be in [0, 1e6]");
        if (m->type == FOVPT_MAT_DIELECTRIC && !(m->ior > 0.0f && m->ior < 100.0f))
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                        "scene: materials[].ior must be in (0, 100) (dielectric)");
    }
    for (i = 0; i < d->num_shapes; ++i) {
        const fovpt_shape *s = &d->shapes[i];
        int em;
        if (s->material >= d->num_materials)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: shapes[].material >= num_materials");
        em = fovpt__emissive(&d->materials[s->material]);
        n_mirrors += (uint64_t)fovpt__mirror_kind(s->type, &d->materials[s->material]);
        if (!fov__finite3(s->p) || !fov__finite3(s->u) || !fov__finite3(s->v) || !fov__finite(s->r))
            FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "scene: a shapes[] value NaN or infinite");
        switch (s->type) {
        case FOVPT_SHAPE_SPHERE:
            if (!(s->r > 0.0f))
                FOVPT__FAIL(lg, FOV_ERR_DEGENERATE, "scene: shapes[].r of a sphere must be > 0");
            if (!fov__finite(s->r * s->r * 16.0f))
                FOVPT__FAIL(lg, FOV_ERR_LIMIT,
                            "scene: shapes[].r of a sphere too large (r^2 overflows)");
            ++n_bounded; n_lights += em ? 1u : 0u;
            break;
        case FOVPT_SHAPE_PLANE:
            if (!(fov__absf(s->u[0]) > 0.0f || fov__absf(s->u[1]) > 0.0f ||
                  fov__absf(s->u[2]) > 0.0f))
                FOVPT__FAIL(lg, FOV_ERR_DEGENERATE, "scene: shapes[].u (plane normal) is zero");
            break;
        case FOVPT_SHAPE_QUAD: {
            float c[3];
            fov__cross(s->u, s->v, c);
            if (!(fov__len(c) > 1e-12f * (fov__dot(s->u, s->u) + fov__dot(s->v, s->v))) ||
                !fov__finite(fov__len(c)))
                FOVPT__FAIL(lg, FOV_ERR_DEGENERATE,
                            em ? "scene: shapes[]: quad light of zero area"
                               : "scene: shapes[]: quad of zero area");
            ++n_bounded; n_lights += em ? 1u : 0u;
            break;
        }
        case FOVPT_SHAPE_BOX: {
            int flat = 0;
            for (k = 0; k < 3; ++k) {
                if (s->u[k] < s->p[k])
                    FOVPT__FAIL(lg, FOV_ERR_DEGENERATE,
                                "scene: shapes[]: box u (max) below p (min)");
                if (!(s->u[k] > s->p[k])) ++flat;
            }
            if (flat > 1)
                FOVPT__FAIL(lg, FOV_ERR_DEGENERATE, "scene: shapes[]: box flat in two axes");
            ++n_bounded;
            break;
        }
        default: FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: shapes[].type unknown");
        }
    }
    for (i = 0; i < d->num_meshes; ++i) {
        const fovpt_mesh *m = &d->meshes[i];
        uint64_t nv3 = (uint64_t)m->num_triangles * 3u;
        int em;
        if (m->num_triangles == 0) continue;
        if (!m->positions) FOVPT__FAIL(lg, FOV_ERR_NULL, "scene: meshes[].positions is NULL");
        if (m->material >= d->num_materials)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: meshes[].material >= num_materials");
        if (m->num_triangles > FOVPT_MAX_PRIMS || m->num_vertices > 3u * FOVPT_MAX_PRIMS)
            FOVPT__FAIL(lg, FOV_ERR_LIMIT,
                        "scene: meshes[] triangle or vertex count above FOVPT_MAX_PRIMS");
        if (!m->indices && nv3 > m->num_vertices)
            FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                        "scene: meshes[] without indices: below 3 vertices a triangle");
        for (k = 0; k < m->num_vertices; ++k)
            if (!fov__finite3(m->positions + 3u * (size_t)k))
                FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "scene: meshes[].positions NaN or infinite");
        em = fovpt__emissive(&d->materials[m->material]);
        for (k = 0; k < m->num_triangles; ++k) {
            uint32_t i0, i1, i2;
            float a2;
            if (m->indices) {
                i0 = m->indices[3u * (size_t)k]; i1 = m->indices[3u * (size_t)k + 1u];
                i2 = m->indices[3u * (size_t)k + 2u];
                if (i0 >= m->num_vertices || i1 >= m->num_vertices || i2 >= m->num_vertices)
                    FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "scene: meshes[].indices >= num_vertices");
            } else {
                i0 = 3u * k; i1 = i0 + 1u; i2 = i0 + 2u;
            }
            if (!fovpt__tri_area2(m->positions + 3u * (size_t)i0, m->positions + 3u * (size_t)i1,
                                  m->positions + 3u * (size_t)i2, &a2)) {
                if (!d->skip_degenerate)
                    FOVPT__FAIL(lg, FOV_ERR_DEGENERATE,
                                em ? "scene: meshes[]: triangle light of zero area"
                                   : "scene: meshes[]: triangle of zero area");
                ++skipped;
                continue;
            }
            ++n_tris;
            n_lights += em ? 1u : 0u;
        }
    }
    n_bounded += n_tris;
    n_prims = (uint64_t)d->num_shapes + n_tris;
    if (n_prims > FOVPT_MAX_PRIMS)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "scene: primitives in total above FOVPT_MAX_PRIMS");
    (void)skipped;
    L->n_prims = (uint32_t)n_prims;
    L->n_bounded = (uint32_t)n_bounded;
    L->n_tris = (uint32_t)n_tris;
    L->n_lights = (uint32_t)n_lights;
    L->n_mirrors = (uint32_t)n_mirrors;
    L->n_nodes_max = L->n_bounded ? 2u * L->n_bounded - 1u : 0u;
    L->n_slots = 4u * ((L->n_bounded + 3u) / 4u + FOVPT__SLACK(L->n_bounded));
    if (L->n_slots > (1u << 26)) L->n_slots = 1u << 26; /* a leaf's first slot: 26 bits */
    /* sizes in uint64_t, checked against SIZE_MAX */
    sz = 0;
    L->prims = 0;
    sz += (uint64_t)fov__align(sizeof(fovpt__prim)) * 0u + (uint64_t)sizeof(fovpt__prim) * n_prims;
    sz = (sz + 15u) & ~(uint64_t)15u;
    L->nodes = (size_t)sz;
    sz += (uint64_t)sizeof(fovpt__node) * L->n_nodes_max;
    sz = (sz + 15u) & ~(uint64_t)15u;
    /* W-wide nodes: one with fewer than W children holds a whole binary subtree (these are
       disjoint) of more than FOVPT__COMBINE primitives, or of two or more with a bounded
       shape (fovpt__mark_small: a smaller subtree is opened by its parent or is one leaf
       child): with a triangle weighing 1 and a shape FOVPT__COMBINE, each such subtree
       weighs more than FOVPT__COMBINE, so there are at most (n + (FOVPT__COMBINE - 1) shapes) /
       (FOVPT__COMBINE + 1) of them besides the root; one with W children opened W - 1 of
       the at most n - 1 binary inner nodes; or the root */
    L->nodes4 = (size_t)sz;
    sz += (uint64_t)sizeof(fovpt__node4) *
          (((uint64_t)L->n_bounded + (FOVPT__COMBINE - 1u) * (uint64_t)(L->n_bounded - L->n_tris)) /
               (FOVPT__COMBINE + 1u) +
           (uint64_t)L->n_bounded / (FOVPT__W - 1u) + 1u);
    L->order = (size_t)sz;
    sz += 4u * (uint64_t)L->n_slots;
    sz = (sz + 15u) & ~(uint64_t)15u;
    L->lights = (size_t)sz;
    sz += 4u * n_lights;
    sz = (sz + 15u) & ~(uint64_t)15u;
    L->cdf = (size_t)sz;
    sz += 4u * n_lights;
    sz = (sz + 15u) & ~(uint64_t)15u;
    L->area = (size_t)sz;
    sz += 4u * n_lights;
    sz = (sz + 15u) & ~(uint64_t)15u;
    L->mirrors = (size_t)sz;
    sz += 4u * n_mirrors;
    sz = (sz + 15u) & ~(uint64_t)15u;
    L->pbox = (size_t)sz;   /* build data: 9 floats per bounded primitive (box, centroid);
                               after the build: the leaf-ordered triangles (v0, e1, e2) in
                               SoA blocks of 4 slots (fovpt_scene.leaf_tris), 60 bytes
                               per slot (FOVPT__LBLK floats per block of 4) */
    sz += FOVPT__LBLK * (uint64_t)L->n_slots; /* whole blocks of 4 */
    sz = (sz + 15u) & ~(uint64_t)15u;
    if (sz > (uint64_t)(SIZE_MAX / 2u))
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "scene: memory size overflows size_t");
    L->total = (size_t)sz;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_scene_size(const fovpt_scene_desc *desc, size_t *bytes)
{
    fovpt__layout L;
    fov_result e;
    if (!desc) return FOV_ERR_NULL;
    if (!bytes) FOVPT__FAIL(&desc->logger, FOV_ERR_NULL, "scene_size: bytes is NULL");
    e = fovpt__plan(desc, &L);
    if (e != FOV_OK) return e;
    *bytes = L.total;
    return FOV_OK;
}

/* A primitive's bounding box. Triangle and quad corners are a + e (rounded: a triangle's
   records hold v0 and the edges, so v0 + e1 need not be v1) and their ray tests round too;
   their boxes and spheres' are widened by FOVPT__BOX_PAD of the largest coordinate
   magnitude per axis (a few ulps), so no hit the primitive test reports lies outside its
   box (the BVH property test against brute force). Boxes are their own slabs. */
#define FOVPT__BOX_PAD 4.76837158203125e-07f /* 2^-21 */
FOVPT__PRIV void fovpt__prim_box(const fovpt__prim *p, float lo[3], float hi[3], int padded)
{
    uint32_t k;
    for (k = 0; k < 3; ++k) {
        float pad;
        switch (p->type) {
        case FOVPT_SHAPE_SPHERE: lo[k] = p->a[k] - p->r; hi[k] = p->a[k] + p->r; break;
        case FOVPT_SHAPE_QUAD: {
            float x0 = p->a[k], x1 = p->a[k] + p->b[k], x2 = p->a[k] + p->c[k], x3 = x1 + p->c[k];
            lo[k] = fov__minf(fov__minf(x0, x1), fov__minf(x2, x3));
            hi[k] = fov__maxf(fov__maxf(x0, x1), fov__maxf(x2, x3));
            break;
        }
        case FOVPT_SHAPE_BOX: lo[k] = p->a[k]; hi[k] = p->b[k]; break;
        default: { /* triangle */
            float x0 = p->a[k], x1 = p->a[k] + p->b[k], x2 = p->a[k] + p->c[k];
            lo[k] = fov__minf(x0, fov__minf(x1, x2));
            hi[k] = fov__maxf(x0, fov__maxf(x1, x2));
            break;
        }
        }
        if (p->type == FOVPT_SHAPE_BOX || !padded) continue;
        pad = fov__maxf(fov__absf(lo[k]), fov__absf(hi[k])) * FOVPT__BOX_PAD;
        lo[k] -= pad;
        hi[k] += pad;
    }
}

FOVPT__PRIV float fovpt__half_area(const float lo[3], const float hi[3])
{
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    if (!(dx >= 0.0f) || !(dy >= 0.0f) || !(dz >= 0.0f)) return 0.0f;
    return dx * dy + dy * dz + dz * dx;
}

typedef struct fovpt__bin {
    float lo[3], hi[3];
    uint32_t n;
} fovpt__bin;

/* Leaves sized to the leaf test's blocks. A small subtree is one of at most FOVPT__COMBINE
   primitives (4, one block of 4 lanes; 1 without SIMD, where every triangle is a test of its
   own and the binary leaves' boxes pay: +4 / +6 % instructions per terrain ray with leaves
   of 4) and no bounded shape (its leaf keeps its own box: see fovpt__build_bvh): its
   primitives are contiguous in order. Each inner small subtree is marked (n =
   FOVPT__LEAF4 | count), laid out in one block (fovpt__leaf_layout) and never made a W-wide
   node of its own (fovpt__collapse4: a node opens it while it has room, else it is one leaf
   child), so every W-wide node but the root holds more than FOVPT__COMBINE primitives or a
   bounded shape (the node bound of fovpt__plan). Combining sibling leaves outright, even
   only where the parent's box is no larger than theirs together, tested more leaves
   (interior: 1.14 -> 1.50 per camera ray, +8 % instructions); the marks keep the leaves' own
   boxes where a node has room for them. Children follow their parent in the node array, so
   one backward pass sees them first. */
FOVPT__PRIV int fovpt__leaf_has_shape(const fovpt__node *l, const uint32_t *order,
                                      const fovpt__prim *prims)
{
    uint32_t k;
    if (l->n & FOVPT__LEAF4) return 0; /* a marked subtree: triangles only */
    for (k = 0; k < l->n; ++k)
        if (prims[order[l->a + k]].type != FOVPT__TRI) return 1;
    return 0;
}
FOVPT__PRIV void fovpt__mark_small(fovpt__node *nodes, uint32_t used, const uint32_t *order,
                                   const fovpt__prim *prims)
{
    uint32_t i = used;
    while (i-- > 0) {
        fovpt__node *nd = &nodes[i];
        const fovpt__node *l, *r;
        uint32_t c;
        if (nd->n) continue;
        l = &nodes[nd->a]; r = l + 1;
        c = (l->n & ~FOVPT__LEAF4) + (r->n & ~FOVPT__LEAF4);
        if (l->n && r->n && c <= FOVPT__COMBINE && !fovpt__leaf_has_shape(l, order, prims) &&
            !fovpt__leaf_has_shape(r, order, prims))
            nd->n = FOVPT__LEAF4 | c; /* else large: 0 */
    }
}
/* The first slot of a node's subtree (its leftmost leaf). */
FOVPT__PRIV uint32_t fovpt__first_slot(const fovpt__node *nodes, uint32_t i)
{
    while (nodes[i].n == 0 || (nodes[i].n & FOVPT__LEAF4)) i = nodes[i].a;
    return nodes[i].a;
}

/* Assigns the leaves their slots, depth first and left to right (the build's order, src, nb
   entries, into dst by slot), so that a leaf, or a marked small subtree (fovpt__mark_small) as
   a whole, lies in as few blocks of 4 slots as its count needs: where it would straddle one
   more, it starts the next block and the slots skipped are padding (FOVPT_PRIM_NONE), while
   the reserve of nslots slots allows it (otherwise it straddles, which the leaf test
   handles). Returns the slots used, a multiple of 4. */
FOVPT__PRIV uint32_t fovpt__leaf_layout(fovpt__node *nodes, const uint32_t *src, uint32_t *dst,
                                        uint32_t nb, uint32_t nslots)
{
    uint32_t stack[FOVPT_MAX_BVH_DEPTH + 2u], sub[FOVPT__COMBINE + 2u];
    uint32_t sp = 0, cur = 0, left = nb, j;
    stack[sp++] = 0;
    while (sp > 0) {
        const uint32_t ni = stack[--sp];
        fovpt__node *nd = &nodes[ni];
        uint32_t n = nd->n & ~FOVPT__LEAF4, al = (cur + 3u) & ~3u, f, ss = 0;
        if (!nd->n) {
            FOV_ASSERT(sp + 2u <= FOVPT_MAX_BVH_DEPTH + 2u);
            stack[sp++] = nd->a + 1u;
            stack[sp++] = nd->a;
            continue;
        }
        if (((cur + n - 1u) >> 2) - (cur >> 2) > (n - 1u) >> 2 && al + left <= nslots)
            while (cur < al) dst[cur++] = FOVPT_PRIM_NONE;
        f = fovpt__first_slot(nodes, ni);
        for (j = 0; j < n; ++j) dst[cur + j] = src[f + j];
        sub[ss++] = ni; /* the subtree's leaves keep their offsets from its first slot */
        while (ss > 0) {
            fovpt__node *q = &nodes[sub[--ss]];
            if (q->n & FOVPT__LEAF4) {
                FOV_ASSERT(ss + 2u <= FOVPT__COMBINE + 2u);
                sub[ss++] = q->a; sub[ss++] = q->a + 1u;
            } else {
                q->a = cur + (q->a - f);
            }
        }
        cur += n;
        left -= n;
    }
    while (cur & 3u) dst[cur++] = FOVPT_PRIM_NONE;
    return cur;
}

/* Collapses the binary BVH into W-wide nodes (iterative, explicit stack); returns the count.
   A node opens its largest inner children (a marked small subtree too) until it has W; a
   small subtree left unopened is one leaf child (its slots are in one block), not a node. */
FOVPT__PRIV uint32_t fovpt__collapse4(const fovpt__node *nodes, fovpt__node4 *n4)
{
    typedef struct { uint32_t bin, slot; } work;
    work stack[(FOVPT__W - 1u) * FOVPT_MAX_BVH_DEPTH + 4u];
    uint32_t sp = 0, used = 1, c[FOVPT_BVH_WIDTH], m, j, k;
    stack[sp].bin = 0; stack[sp].slot = 0; ++sp;
    while (sp > 0) {
        work w = stack[--sp];
        fovpt__node4 *q = &n4[w.slot];
        const uint32_t rn = nodes[w.bin].n;
        if (rn && !(rn & FOVPT__LEAF4)) { c[0] = w.bin; m = 1; } /* a root that is a leaf */
        else { c[0] = nodes[w.bin].a; c[1] = nodes[w.bin].a + 1u; m = 2; }
        while (m < FOVPT__W) { /* open the inner child of largest area */
            uint32_t best = FOVPT__W;
            float ba = -1.0f;
            for (j = 0; j < m; ++j) {
                float a = fovpt__half_area(nodes[c[j]].b, nodes[c[j]].b + 3);
                const uint32_t cn = nodes[c[j]].n; /* inner, or a small subtree */
                if ((!cn || (cn & FOVPT__LEAF4)) && a > ba) { ba = a; best = j; }
            }
            if (best == FOVPT__W) break;
            k = c[best];
            c[best] = nodes[k].a;
            c[m++] = nodes[k].a + 1u;
        }
        for (j = 0; j < FOVPT__W; ++j) {
            if (j >= m) {
                for (k = 0; k < 3; ++k) { q->b[k][j] = FLT_MAX; q->b[3 + k][j] = -FLT_MAX; }
                q->child[j] = FOVPT__LEAF4; /* an empty leaf (fovpt__leaf returns at once) */
                continue;
            }
            for (k = 0; k < 6; ++k) q->b[k][j] = nodes[c[j]].b[k];
            if (nodes[c[j]].n & FOVPT__LEAF4) { /* a small subtree */
                q->child[j] = FOVPT__LEAF4 | (fovpt__first_slot(nodes, c[j]) << 5) |
                              (nodes[c[j]].n & ~FOVPT__LEAF4);
            } else if (nodes[c[j]].n) {
                q->child[j] = FOVPT__LEAF4 | (nodes[c[j]].a << 5) | nodes[c[j]].n;
            } else {
                FOV_ASSERT(sp < (FOVPT__W - 1u) * FOVPT_MAX_BVH_DEPTH + 4u);
                q->child[j] = used;
                stack[sp].bin = c[j]; stack[sp].slot = used; ++sp;
                ++used;
            }
        }
        for (k = 0; k < FOVPT__W; ++k) q->pad[k] = 0u;
    }
    return used;
}

/* Binned SAH build (Wald 2007), iterative with an explicit work stack. */
FOVPT__PRIV fov_result fovpt__build_bvh(fovpt_scene *s, fovpt__node *nodes, uint32_t *order,
                                        float *pb, const fovpt_scene_desc *d)
{
    typedef struct { uint32_t node, start, count, depth; } work;
    work stack[FOVPT_MAX_BVH_DEPTH + 1];
    const fov_logger *lg = &d->logger;
    const fovpt__prim *prims = (const fovpt__prim *)s->prims;
    uint32_t sp = 0, used = 1, max_depth = 0, i, k;
    uint32_t bins = d->bvh_bins ? d->bvh_bins : 16u;
    uint32_t leaf = d->bvh_leaf ? d->bvh_leaf : 2u;
    uint32_t cap = d->bvh_max_depth ? d->bvh_max_depth : (uint32_t)FOVPT_MAX_BVH_DEPTH;
    uint32_t nb = s->num_bounded;
    for (i = 0; i < nb; ++i) {
        float *q = pb + 9u * (size_t)i;
        order[i] = i;
        fovpt__prim_box(&prims[i], q, q + 3, 1);
        for (k = 0; k < 3; ++k) q[6 + k] = 0.5f * (q[k] + q[3 + k]);
    }
    stack[sp].node = 0; stack[sp].start = 0; stack[sp].count = nb; stack[sp].depth = 1; ++sp;
    while (sp > 0) {
        work w = stack[--sp];
        fovpt__node *nd = &nodes[w.node];
        float clo[3], chi[3], best_cost, leaf_cost, area;
        uint32_t best_axis = 3, best_split = 0, mid, ns = 0;
        for (k = 0; k < 3; ++k) { nd->b[k] = clo[k] = FLT_MAX; nd->b[3 + k] = chi[k] = -FLT_MAX; }
        for (i = w.start; i < w.start + w.count; ++i) {
            const float *q = pb + 9u * (size_t)order[i];
            ns += prims[order[i]].type != FOVPT__TRI;
            for (k = 0; k < 3; ++k) {
                nd->b[k] = fov__minf(nd->b[k], q[k]);
                nd->b[3 + k] = fov__maxf(nd->b[3 + k], q[3 + k]);
                clo[k] = fov__minf(clo[k], q[6 + k]); chi[k] = fov__maxf(chi[k], q[6 + k]);
            }
        }
        if (w.depth > max_depth) max_depth = w.depth;
        area = fovpt__half_area(nd->b, nd->b + 3);
        /* whole blocks of 4 with SIMD (see below) */
        leaf_cost = FOVPT__COMBINE > 1u ? 4.0f * (float)((w.count + 3u) >> 2) : (float)w.count;
        best_cost = FLT_MAX;
        if (w.count > leaf || (ns > 0u && w.count > 1u)) {
            uint32_t axis;
            for (axis = 0; axis < 3; ++axis) {
                fovpt__bin bin[FOVPT__BINS_MAX];
                float ext = chi[axis] - clo[axis], scale, rlo[3], rhi[3], ra[FOVPT__BINS_MAX];
                uint32_t rn[FOVPT__BINS_MAX], b, cnt;
                if (!(ext > 0.0f)) continue;
                scale = (float)bins / ext;
                for (b = 0; b < bins; ++b) {
                    bin[b].n = 0;
                    for (k = 0; k < 3; ++k) { bin[b].lo[k] = FLT_MAX; bin[b].hi[k] = -FLT_MAX; }
                }
                for (i = w.start; i < w.start + w.count; ++i) {
                    const float *q = pb + 9u * (size_t)order[i];
                    float fb = (q[6 + axis] - clo[axis]) * scale;
                    b = fb >= (float)bins ? bins - 1u : (fb > 0.0f ? (uint32_t)fb : 0u);
                    if (b >= bins) b = bins - 1u;
                    bin[b].n++;
                    for (k = 0; k < 3; ++k) {
                        bin[b].lo[k] = fov__minf(bin[b].lo[k], q[k]);
                        bin[b].hi[k] = fov__maxf(bin[b].hi[k], q[3 + k]);
                    }
                }
                /* right sweep: areas and counts of bins b .. bins-1 */
                for (k = 0; k < 3; ++k) { rlo[k] = FLT_MAX; rhi[k] = -FLT_MAX; }
                cnt = 0;
                for (b = bins - 1u; b > 0; --b) {
                    for (k = 0; k < 3; ++k) {
                        rlo[k] = fov__minf(rlo[k], bin[b].lo[k]);
                        rhi[k] = fov__maxf(rhi[k], bin[b].hi[k]);
                    }
                    cnt += bin[b].n;
                    rn[b] = cnt;
                    ra[b] = fovpt__half_area(rlo, rhi);
                }
                for (k = 0; k < 3; ++k) { rlo[k] = FLT_MAX; rhi[k] = -FLT_MAX; }
                cnt = 0;
                for (b = 0; b + 1u < bins; ++b) { /* split after bin b */
                    float cost;
                    for (k = 0; k < 3; ++k) {
                        rlo[k] = fov__minf(rlo[k], bin[b].lo[k]);
                        rhi[k] = fov__maxf(rhi[k], bin[b].hi[k]);
                    }
                    cnt += bin[b].n;
                    if (cnt == 0 || rn[b + 1u] == 0) continue;
                    cost = fovpt__half_area(rlo, rhi) * (float)cnt + ra[b + 1u] * (float)rn[b + 1u];
                    if (cost < best_cost) { best_cost = cost; best_axis = axis; best_split = b; }
                }
            }
        }
        /* SAH: intersection cost 1 per primitive, traversal cost 1.5 (an inner step tests two
           boxes: about 80 instructions against about 50 for a triangle, under callgrind).
           Defaults 16 bins, leaf 2, cost 1.5 against 12, 4, 1.0 before: 3.0 -> 3.4 Mrays/s on
           bench-pt's 100k-triangle terrain, 0.45x -> 0.49x of Embree's single thread. With
           SIMD a leaf costs its whole blocks of 4 (the leaf test's lanes: 5 cost 8), so a leaf
           just over a block splits where that pays (the children's costs stay per primitive:
           rounded there, the binned sweep loses its gradient; cubes441: 2.6 -> 2.5 block
           tests per camera ray, rounded sweep 4.6). */
        /* A bounded shape (sphere, quad, box, ...) is a leaf of its own: the leaf test hands
           it to fovpt__isect alone, 40-100 instructions, where the W children's boxes cost
           one SIMD pass, so only identical centroids (no split) keep it with others (up to
           FOVPT__LEAF_MAX; more are split in the middle, as triangles are). Cornell
           box, UNIFORM 2 spp at 160 x 120 (callgrind, the same image): 379M -> 221M
           instructions, the mirrors 448M -> 329M, the interior 549M -> 383M (fovpt__isect per
           ray 8 -> 2-3 on the Cornell box). */
        if (ns > 0u ? w.count <= 1u || (best_axis == 3u && w.count <= FOVPT__LEAF_MAX) :
            (w.count <= leaf ||
             (w.count <= FOVPT__LEAF_MAX &&
              (best_axis == 3u || !(area > 0.0f) || 1.5f + best_cost / area >= leaf_cost)))) {
            nd->a = w.start; nd->n = w.count;
            continue;
        }
        if (best_axis < 3u) {
            float scale = (float)bins / (chi[best_axis] - clo[best_axis]);
            uint32_t lo_i = w.start, hi_i = w.start + w.count;
            while (lo_i < hi_i) {
                const float *q = pb + 9u * (size_t)order[lo_i];
                float fb = (q[6 + best_axis] - clo[best_axis]) * scale;
                uint32_t b = fb >= (float)bins ? bins - 1u : (fb > 0.0f ? (uint32_t)fb : 0u);
                if (b >= bins) b = bins - 1u;
                if (b <= best_split) ++lo_i;
                else { uint32_t t = order[lo_i]; order[lo_i] = order[--hi_i]; order[hi_i] = t; }
            }
            mid = lo_i - w.start;
            if (mid == 0 || mid == w.count) mid = w.count / 2u; /* cannot happen; be safe */
        } else {
            mid = w.count / 2u; /* identical centroids: any split is as good */
        }
        if (w.depth + 1u > cap)
            FOVPT__FAIL(lg, FOV_ERR_LIMIT,
                        "scene: BVH deeper than bvh_max_depth (FOVPT_MAX_BVH_DEPTH)");
        FOV_ASSERT(used + 2u <= s->num_nodes);
        nd->a = used; nd->n = 0;
        stack[sp].node = used; stack[sp].start = w.start; stack[sp].count = mid;
        stack[sp].depth = w.depth + 1u; ++sp;
        stack[sp].node = used + 1u; stack[sp].start = w.start + mid;
        stack[sp].count = w.count - mid; stack[sp].depth = w.depth + 1u; ++sp;
        used += 2u;
    }
    s->num_nodes = used;
    s->bvh_depth = max_depth;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_scene_build(fovpt_scene *s, const fovpt_scene_desc *d, void *mem,
                                       size_t bytes)
{
    fovpt__layout L;
    fov_result e;
    fovpt__prim *prims;
    uint32_t i, k, np = 0, nl = 0, nb, skipped = 0;
    unsigned char *base = (unsigned char *)mem;
    uint32_t *lights, *mirrors, nm = 0;
    float *cdf, *area, total = 0.0f;
    if (!d) return FOV_ERR_NULL;
    if (!s) FOVPT__FAIL(&d->logger, FOV_ERR_NULL, "scene_build: s is NULL");
    e = fovpt__plan(d, &L);
    if (e != FOV_OK) return e;
    if (L.total > 0 && !mem) FOVPT__FAIL(&d->logger, FOV_ERR_NULL, "scene_build: mem is NULL");
    if (bytes < L.total)
        FOVPT__FAIL(&d->logger, FOV_ERR_TOO_SMALL, "scene_build: bytes below fovpt_scene_size");
    if (((uintptr_t)mem & 7u) != 0)
        FOVPT__FAIL(&d->logger, FOV_ERR_INVALID_ARG, "scene_build: mem not 8-byte aligned");
    FOV_MEMSET(s, 0, sizeof *s);
    prims = (fovpt__prim *)(void *)(base + L.prims);
    lights = (uint32_t *)(void *)(base + L.lights);
    cdf = (float *)(void *)(base + L.cdf);
    area = (float *)(void *)(base + L.area);
    mirrors = (uint32_t *)(void *)(base + L.mirrors);
    /* bounded primitives first (shapes, then triangles), planes last */
    for (i = 0; i < d->num_shapes; ++i) {
        const fovpt_shape *sh = &d->shapes[i];
        fovpt__prim *p;
        if (sh->type == FOVPT_SHAPE_PLANE) continue;
        p = &prims[np++];
        FOV_MEMSET(p, 0, sizeof *p);
        p->type = sh->type; p->material = sh->material; p->id = i;
        fovpt__copy3(p->a, sh->p); p->r = sh->r;
        if (sh->type == FOVPT_SHAPE_QUAD) {
            fovpt__copy3(p->b, sh->u); fovpt__copy3(p->c, sh->v);
            fovpt__unit_normal(sh->u, sh->v, p->n);
        } else if (sh->type == FOVPT_SHAPE_BOX) {
            fovpt__copy3(p->b, sh->u);
        }
    }
    {
        uint32_t id = d->num_shapes;
        for (i = 0; i < d->num_meshes; ++i) {
            const fovpt_mesh *m = &d->meshes[i];
            for (k = 0; k < m->num_triangles; ++k) {
                uint32_t i0, i1, i2;
                const float *v0, *v1, *v2;
                float a2;
                fovpt__prim *p;
                if (m->indices) {
                    i0 = m->indices[3u * (size_t)k]; i1 = m->indices[3u * (size_t)k + 1u];
                    i2 = m->indices[3u * (size_t)k + 2u];
                } else {
                    i0 = 3u * k; i1 = i0 + 1u; i2 = i0 + 2u;
                }
                v0 = m->positions + 3u * (size_t)i0; v1 = m->positions + 3u * (size_t)i1;
                v2 = m->positions + 3u * (size_t)i2;
                if (!fovpt__tri_area2(v0, v1, v2, &a2)) { /* ids stay k */
                    ++skipped; ++id; continue;
                }
                p = &prims[np++];
                FOV_MEMSET(p, 0, sizeof *p);
                p->type = FOVPT__TRI; p->material = m->material; p->id = id++;
                fovpt__copy3(p->a, v0); fovpt__sub3(p->b, v1, v0); fovpt__sub3(p->c, v2, v0);
                fovpt__unit_normal(p->b, p->c, p->n);
                p->r = 0.5f * a2; /* area */
            }
        }
    }
    nb = np;
    for (i = 0; i < d->num_shapes; ++i) {
        const fovpt_shape *sh = &d->shapes[i];
        fovpt__prim *p;
        if (sh->type != FOVPT_SHAPE_PLANE) continue;
        p = &prims[np++];
        FOV_MEMSET(p, 0, sizeof *p);
        p->type = FOVPT_SHAPE_PLANE; p->material = sh->material; p->id = i;
        fovpt__copy3(p->a, sh->p); fovpt__copy3(p->n, sh->u); fov__normalize(p->n);
    }
    FOV_ASSERT(np == L.n_prims && nb == L.n_bounded);
    /* lights: sampleable emitters, picked by area * mean emission */
    for (i = 0; i < nb; ++i) {
        fovpt__prim *p = &prims[i];
        const fovpt_material *m = &d->materials[p->material];
        float a;
        if (!fovpt__emissive(m) || p->type == FOVPT_SHAPE_BOX) continue;
        if (p->type == FOVPT_SHAPE_SPHERE) a = 4.0f * FOV__PI * p->r * p->r;
        else if (p->type == FOVPT_SHAPE_QUAD) {
            float c[3]; fov__cross(p->b, p->c, c); a = fov__len(c);
        }
        else a = p->r;
        lights[nl] = i;
        area[nl] = a;
        total += a * fovpt__mean3(m->emission);
        cdf[nl] = total;
        p->light = ++nl;
    }
    if (nl > 0) {
        if (!(total > 0.0f) || !fov__finite(total))
            FOVPT__FAIL(&d->logger, FOV_ERR_LIMIT, "scene_build: total emitted power overflows");
        for (i = 0; i < nl; ++i) cdf[i] /= total;
        cdf[nl - 1u] = 1.0f;
    }
    for (i = 0; i < nb; ++i)
        if (fovpt__mirror_kind(prims[i].type, &d->materials[prims[i].material])) mirrors[nm++] = i;
    FOV_ASSERT(nm == L.n_mirrors);
    s->mirrors = mirrors;
    s->num_mirrors = nm;
    s->prims = prims;
    s->order = (const uint32_t *)(void *)(base + L.order);
    s->lights = lights;
    s->light_cdf = cdf;
    s->light_area = area;
    s->materials = d->materials;
    s->num_prims = np;
    s->num_bounded = nb;
    s->num_lights = nl;
    s->num_materials = d->num_materials;
    s->num_skipped = skipped;
    fovpt__copy3(s->background, d->background);
    s->user_hit = d->user_hit;
    s->user = d->user;
    for (k = 0; k < 3; ++k) { s->bounds_lo[k] = FLT_MAX; s->bounds_hi[k] = -FLT_MAX; }
    for (i = 0; i < nb; ++i) {
        float lo[3], hi[3];
        fovpt__prim_box(&prims[i], lo, hi, 0); /* the public bounds: exact */
        for (k = 0; k < 3; ++k) {
            s->bounds_lo[k] = fov__minf(s->bounds_lo[k], lo[k]);
            s->bounds_hi[k] = fov__maxf(s->bounds_hi[k], hi[k]);
        }
    }
    {
        uint32_t minp = d->bvh_min_prims ? d->bvh_min_prims : 8u;
        uint32_t *order = (uint32_t *)(void *)(base + L.order);
        if (nb >= minp && nb > 0) {
            s->num_nodes = L.n_nodes_max;
            e = fovpt__build_bvh(s, (fovpt__node *)(void *)(base + L.nodes), order,
                                 (float *)(void *)(base + L.pbox), d);
            if (e != FOV_OK) { FOV_MEMSET(s, 0, sizeof *s); return e; }
            s->nodes = base + L.nodes;
            {   /* the build data is spent: a copy of the build's order, then the leaves */
                uint32_t *tmp = (uint32_t *)(void *)(base + L.pbox);
                fovpt__mark_small((fovpt__node *)(void *)(base + L.nodes), s->num_nodes, order,
                                  (const fovpt__prim *)s->prims);
                for (i = 0; i < nb; ++i) tmp[i] = order[i];
                s->num_slots = fovpt__leaf_layout((fovpt__node *)(void *)(base + L.nodes), tmp,
                                                  order, nb, L.n_slots);
            }
            {   /* the build data is spent: reuse it for the triangles in leaf order, in SoA
                   blocks of 4 slots (block i / 4: 9 rows v0 x y z, e1 x y z, e2 x y z of 4
                   lanes each, the normal's 3 rows, then the rows slot, id, material:
                   FOVPT__LBLK), so a leaf tests 4 triangles per pass */
                float *lt = (float *)(void *)(base + L.pbox);
                for (i = 0; i < s->num_slots; ++i) {
                    float *q = lt + FOVPT__LBLK * (size_t)(i >> 2) + (i & 3u);
                    uint32_t *qi = (uint32_t *)(void *)(q + 48);
                    const fovpt__prim *p = order[i] != FOVPT_PRIM_NONE ? &prims[order[i]] : NULL;
                    qi[0] = p ? order[i] : 0u;
                    qi[4] = p ? p->id : 0u;
                    qi[8] = p ? p->material : 0u;
                    if (p && p->type == FOVPT__TRI) {
                        for (k = 0; k < 3; ++k) {
                            q[4u * k] = p->a[k]; q[4u * (3u + k)] = p->b[k];
                            q[4u * (6u + k)] = p->c[k]; q[4u * (9u + k)] = p->n[k];
                        }
                    } else {
                        /* e1 = e2 = 0: det = 0, see fovpt__closest */
                        for (k = 0; k < 12; ++k) q[4u * k] = 0.0f;
                    }
                }
                s->leaf_tris = lt;
            }
            s->nodes4 = base + L.nodes4;
            s->num_nodes4 = fovpt__collapse4((const fovpt__node *)s->nodes,
                                             (fovpt__node4 *)(void *)(base + L.nodes4));
            {   /* the small subtrees' marks (fovpt__mark_small) cleared: inner nodes n = 0 */
                fovpt__node *n2 = (fovpt__node *)(void *)(base + L.nodes);
                for (i = 0; i < s->num_nodes; ++i)
                    if (n2[i].n & FOVPT__LEAF4) n2[i].n = 0;
            }
        } else {
            for (i = 0; i < nb; ++i) order[i] = i;
            s->nodes = NULL;
            s->leaf_tris = NULL;
            s->nodes4 = NULL;
            s->num_nodes4 = 0;
            s->num_nodes = 0;
        }
    }
    return FOV_OK;
}

/* ---- intersection ------------------------------------------------------------------------- */
typedef struct fovpt__ray {
    float o[4], d[4], inv[4]; /* inv: 1 / d, +inf where d is +-0; [3]: padding, so the SIMD
                                 entry (fovpt__ray_fast) stores each as 4 lanes */
    float ig[4];              /* inv * FOVPT__BOX_GROW (the far planes' factor) */
    uint32_t oct;             /* bit k set where inv[k] < 0 (d[k] < 0): the slabs' near and
                                 far planes in fovpt__node.b, lo (k) and hi (3 + k), swapped
                                 there (fovpt__closest) */
} fovpt__ray;

/* The BVH box test's rounding margin (Ize 2013, "Robust BVH Ray Traversal"): the far
   planes' distances are (plane - o) * fl(inv * FOVPT__BOX_GROW), the bound tmax enters as
   fl(tmax * FOVPT__BOX_GROW), and k = FOVPT__BOX_NEG * |tmin| is added to the exit for a
   negative tmin (0 otherwise), before it is compared with the entry distance. A near
   distance (plane - o) * inv is at most (1 + eps)^3 times its exact value (eps = 2^-24: the
   difference, the reciprocal, the product), a far one at least (1 - eps)^4 GROW times
   (one rounding more: inv * GROW); GROW = 1 + 2^-21 = 1 + 8 eps > (1 + eps)^3 / (1 - eps)^4,
   so a ray that meets the exact box (faces included) is never culled, and the widening
   costs no operation per node (it was u * GROW + k on every exit). The additive k covers
   exits behind the origin (u < 0, the widening then shrinks |u|'s margin), reachable only
   with tmin < 0. */
#define FOVPT__BOX_GROW 1.000000476837158203125f /* 1 + 2^-21 */
#define FOVPT__BOX_NEG 1.9073486328125e-06f      /* 2^-19 = 4 (GROW - 1) */
FOVPT__PRIV float fovpt__inf(void)
{
    union { uint32_t u; float f; } b;
    b.u = 0x7f800000u;
    return b.f;
}

/* Nearest t in (tmin, tmax) of one primitive, or a value >= tmax. */
FOVPT__PRIV float fovpt__isect(const fovpt__prim *p, const fovpt__ray *r, float tmin, float tmax)
{
    switch (p->type) {
    case FOVPT__TRI: {
        /* Moller-Trumbore with the division deferred: u and v scaled by |det| are tested
           against |det| (sign flips are exact), t = dot(e2, q) / det only for a hit inside */
        float pv[3], s[3], q[3], det, ad, sg, u, v, t;
        fov__cross(r->d, p->c, pv);
        det = fov__dot(p->b, pv);
        if (!(fov__absf(det) > 1e-30f)) return tmax;
        sg = det < 0.0f ? -1.0f : 1.0f;
        ad = det * sg;
        fovpt__sub3(s, r->o, p->a);
        u = fov__dot(s, pv) * sg;
        if (!(u >= 0.0f && u <= ad)) return tmax;
        fov__cross(s, p->b, q);
        v = fov__dot(r->d, q) * sg;
        if (!(v >= 0.0f && u + v <= ad)) return tmax;
        t = fov__dot(p->c, q) / det;
        return (t > tmin && t < tmax) ? t : tmax;
    }
    case FOVPT_SHAPE_SPHERE: {
        /* |o + t d - c|^2 = r^2 with the numerically stable form of the roots */
        float oc[3], a, b, c, disc, sq, t0, t1, qq;
        fovpt__sub3(oc, r->o, p->a);
        a = fov__dot(r->d, r->d);
        b = fov__dot(oc, r->d);
        /* discriminant via the closest-approach distance (Hearn-Baker, Ray Tracing Gems ch. 7) */
        {
            float l[3];
            fovpt__madd3(l, oc, -b / a, r->d);
            disc = a * (p->r * p->r - fov__dot(l, l));
        }
        if (!(disc >= 0.0f)) return tmax;
        c = fov__dot(oc, oc) - p->r * p->r;
        sq = FOV__SQRT(disc);
        qq = b > 0.0f ? -(b + sq) : -(b - sq);
        t0 = c / qq;
        t1 = qq / a;
        if (t0 > t1) { float tt = t0; t0 = t1; t1 = tt; }
        if (t0 > tmin && t0 < tmax) return t0;
        if (t1 > tmin && t1 < tmax) return t1;
        return tmax;
    }
    case FOVPT_SHAPE_QUAD: {
        float dn = fov__dot(r->d, p->n), t, x[3], w[3], uu, uv, vv, wu, wv, det, s, tt;
        if (!(fov__absf(dn) > 1e-30f)) return tmax;
        fovpt__sub3(x, p->a, r->o);
        t = fov__dot(x, p->n) / dn;
        if (!(t > tmin && t < tmax)) return tmax;
        fovpt__madd3(w, r->o, t, r->d);
        fovpt__sub3(w, w, p->a);
        uu = fov__dot(p->b, p->b); uv = fov__dot(p->b, p->c); vv = fov__dot(p->c, p->c);
        wu = fov__dot(w, p->b); wv = fov__dot(w, p->c);
        det = uu * vv - uv * uv;
        s = (wu * vv - wv * uv) / det;
        tt = (wv * uu - wu * uv) / det;
        return (s >= 0.0f && s <= 1.0f && tt >= 0.0f && tt <= 1.0f) ? t : tmax;
    }
    case FOVPT_SHAPE_BOX: {
        /* slabs; a direction component of 0 gives inv = inf, so a slab the ray lies in (o
           on a face: 0 * inf = NaN) is ignored by the NaN-dropping max/min below, and a
           slab it misses gives +-inf */
        float t0 = tmin, t1 = tmax, tn = -FLT_MAX, tf = FLT_MAX;
        uint32_t k;
        for (k = 0; k < 3; ++k) {
            float a = (p->a[k] - r->o[k]) * r->inv[k], b = (p->b[k] - r->o[k]) * r->inv[k];
            if (a > b) { float tt = a; a = b; b = tt; }
            tn = a > tn ? a : tn; tf = b < tf ? b : tf;
        }
        if (!(tn <= tf)) return tmax;
        if (tn > t0 && tn < t1) return tn;
        if (tf > t0 && tf < t1) return tf;
        return tmax;
    }
    case FOVPT_SHAPE_PLANE: {
        float dn = fov__dot(r->d, p->n), x[3], t;
        if (!(fov__absf(dn) > 1e-30f)) return tmax;
        fovpt__sub3(x, p->a, r->o);
        t = fov__dot(x, p->n) / dn;
        return (t > tmin && t < tmax) ? t : tmax;
    }
    default: return tmax;
    }
}

/* A direction of any finite length: the ray tests multiply |dir| by edge lengths twice, so
   a direction whose largest component lies outside [2^-32, 2^32] is scaled by a power of
   two (exact) to one in [2^-16, 2^16); tmin, tmax and the hit t are rescaled alike.
   Returns the factor applied to t (1 for ordinary directions, bit for bit as before). */
/* One pass over a direction's components (every ray): bit 1 when the largest magnitude lies
   outside [2^-32, 2^32] or is NaN (the direction is rescaled), bit 2 when a component is not
   0 but below FLT_MIN in magnitude: its reciprocal overflows (|d| <= 2^-128) or the box
   test's margin on it does, so the slab test could cull a box the ray enters; such rays take
   the brute-force loop (NUMERICS). Also called on a rescaled direction (bit 2 alone). */
FOVPT__PRIV int fovpt__dir_class(const float d[3])
{
    uint32_t k, tiny = 0;
    float m;
    for (k = 0; k < 3; ++k) {
        union { float f; uint32_t u; } v;
        v.f = d[k];
        tiny |= (uint32_t)((v.u & 0x7fffffffu) - 1u < 0x007fffffu);
    }
    m = fov__maxf(fov__absf(d[0]), fov__maxf(fov__absf(d[1]), fov__absf(d[2])));
    return (!(m >= 2.3283064365386963e-10f && m <= 4294967296.0f) ? 1 : 0) | (tiny ? 2 : 0);
}
/* The floats next to finite x, up and down (for the rescaled t below). */
FOVPT__PRIV float fovpt__next_up(float x)
{
    uint32_t u;
    if (fov__is0(x)) u = 1u; /* the smallest positive subnormal */
    else {
        FOV_MEMCPY(&u, &x, sizeof u);
        if (x > 0.0f) u += 1u; else u -= 1u;
    }
    FOV_MEMCPY(&x, &u, sizeof x);
    return x;
}
FOVPT__PRIV float fovpt__next_down(float x) { return -fovpt__next_up(-x); }

/* t along dir from t along dir / sc (sc a power of 2, so the division is exact unless it under-
   or overflows): a hit found inside the scaled (tmin, tmax) lies inside (tmin, tmax); when the
   quotient rounds onto a bound, the nearest float inside. Returns 0 if there is none. */
FOVPT__PRIV int fovpt__unscale_t(float ts, float sc, float tmin, float tmax, float *t)
{
    float u = ts / sc;
    if (!(u > tmin)) u = fovpt__next_up(tmin);
    if (!(u < tmax)) u = fovpt__next_down(tmax);
    *t = u;
    return u > tmin && u < tmax;
}

FOVPT__PRIV float fovpt__dir_scale(const float dir[3], float d[3])
{
    float m = fov__maxf(fov__absf(dir[0]), fov__maxf(fov__absf(dir[1]), fov__absf(dir[2]))),
        sc = 1.0f;
    int i;
    fovpt__copy3(d, dir);
    if (!(m > 0.0f) || !fov__finite(m) || (m >= 2.3283064365386963e-10f && m <= 4294967296.0f))
        return 1.0f;
    for (i = 0; i < 16 && m >= 65536.0f; ++i) { /* 2^-16 */
        m *= 1.52587890625e-05f; sc *= 65536.0f;
    }
    for (i = 0; i < 16 && m < 1.52587890625e-05f; ++i) { m *= 65536.0f; sc *= 1.52587890625e-05f; }
    d[0] = dir[0] / sc; d[1] = dir[1] / sc; d[2] = dir[2] / sc;
    return sc; /* d = dir / sc: t along dir = t along d * (1 / sc) */
}

/* The ray record of a direction that is finite and nonzero (fovpt__ray_init checks it). */
FOVPT__PRIV void fovpt__ray_set(fovpt__ray *r, const float org[3], const float dir[3])
{
    uint32_t k;
    for (k = 0; k < 3; ++k) {
        const float d = dir[k];
        /* |d| <= 2^-128: +-inf; 0 < |d| < 2^-126 rays go to brute force (fovpt__dir_class) */
        const float inv = d < 0.0f || d > 0.0f ? 1.0f / d : fovpt__inf();
        r->o[k] = org[k];
        r->d[k] = d;
        r->inv[k] = inv;
        r->ig[k] = inv * FOVPT__BOX_GROW;
    }
    r->oct = (r->inv[0] < 0.0f ? 1u : 0u) | (r->inv[1] < 0.0f ? 2u : 0u) |
             (r->inv[2] < 0.0f ? 4u : 0u);
}
FOVPT__PRIV int fovpt__ray_init(fovpt__ray *r, const float org[3], const float dir[3])
{
    if (!fov__finite3(org) || !fov__finite3(dir) || !(fov__dot(dir, dir) > 0.0f)) return 0;
    fovpt__ray_set(r, org, dir);
    return 1;
}
#if FOVPT__SIMD
/* The entry of fovpt_intersect and fovpt_occluded for the common ray, one 4-lane pass instead
   of fovpt__dir_class, fov__finite3 twice and fovpt__ray_set: the origin finite and every
   direction component's magnitude in [FLT_MIN, 2^32], the largest >= 2^-32. Then
   fovpt__dir_class gives 0 (no rescale: the largest lies in [2^-32, 2^32]; nothing tiny: no
   component below FLT_MIN) and no component is 0, so the record is fovpt__ray_set's with
   inv = 1 / d in every lane: one 4-lane IEEE division, correctly rounded per lane, the same
   floats as three scalar ones; oct from d < 0 (= inv < 0). Lane 3 of
   the direction is 1 (no division by 0). A subnormal or zero component (or one flushed to
   zero in the compare), a non-finite value or a direction to rescale returns 0: the caller
   takes the scalar entry, which is this function's twin (and the only path without SIMD). */
FOVPT__PRIV int fovpt__ray_fast(fovpt__ray *r, const float org[3], const float dir[3])
{
    const fovpt__v4 o = FOVPT__V_LD3(org, 0.0f), d = FOVPT__V_LD3(dir, 1.0f);
    const fovpt__v4 ad = FOVPT__V_ABS(d);
    const uint32_t ok =
        FOVPT__M_BITS(FOVPT__V_LE(FOVPT__V_ABS(o), FOVPT__V_SET1(FLT_MAX))) &
        FOVPT__M_BITS(FOVPT__M_AND(FOVPT__V_GE(ad, FOVPT__V_SET1(1.17549435e-38f)),
                                   FOVPT__V_LE(ad, FOVPT__V_SET1(4294967296.0f))));
    if (ok != 15u || !(FOVPT__M_BITS(FOVPT__V_GE(ad, FOVPT__V_SET1(2.3283064365386963e-10f))) &
                       7u))
        return 0;
    FOVPT__V_ST(r->o, o);
    FOVPT__V_ST(r->d, d);
    {
        const fovpt__v4 inv = FOVPT__V_DIV(FOVPT__V_SET1(1.0f), d);
        FOVPT__V_ST(r->inv, inv);
        FOVPT__V_ST(r->ig, FOVPT__V_MUL(inv, FOVPT__V_SET1(FOVPT__BOX_GROW)));
    }
    r->oct = FOVPT__M_BITS(FOVPT__V_LT(d, FOVPT__V_SET1(0.0f))); /* lane 3: 1, never set */
    return 1;
}
#endif

/* The slab test (Kay-Kajiya) of fovpt__closest, W boxes at once, with the near and far
   planes picked by the direction's sign, so no swap: the same products as (lo - o) * inv and
   (hi - o) * inv, only never compared. Conservative: max(a, t) = a > t ? a : t and
   min(b, t) = b < t ? b : t drop a NaN slab distance (0 * inf: the ray lies in a slab's face
   plane, parallel to it), and the exit is widened by the rounding margin (far planes times
   inv * FOVPT__BOX_GROW, tmax * FOVPT__BOX_GROW, + FOVPT__BOX_NEG * max(0, -tmin)). */

/* A BVH leaf: slots [first, end) of the leaf order, tested in the SoA blocks of
   s->leaf_tris four lanes at a time (Moller-Trumbore with the division deferred, the same
   operations on the same floats as fovpt__isect, so the same t as brute force; SIMD, or the
   scalar twin lane by lane). Slots that are not triangles (stored as zeros: det = 0) go
   through fovpt__isect. The closest hit is canonical, as in brute force: the smallest t, and
   among equal t the lowest primitive slot, whatever order the traversal visits leaves in
   (a t equal to the closest so far replaces it when its slot is lower; a t equal to the
   caller's tmax never counts). Returns 1 when any is set and a hit was found. */
FOVPT__PRIV int fovpt__leaf_take(float t, uint32_t slot, float *tmax, uint32_t *best)
{
    if (t < *tmax || (t <= *tmax && *best != FOVPT_PRIM_NONE && slot < *best)) {
        *tmax = t; *best = slot;
        return 1;
    }
    return 0;
}
/* The lowest set bit of a nonzero x. */
FOVPT__PRIV uint32_t fovpt__ctz(uint32_t x)
{
#if defined(__GNUC__) || defined(__clang__)
    return (uint32_t)__builtin_ctz(x);
#else
    uint32_t n = 0;
    while (!(x & 1u)) { x >>= 1; ++n; }
    return n;
#endif
}
/* A ray's per-traversal constants for the leaf tests: origin, direction and tmin broadcast
   to the four lanes once per ray (the scalar twin reads them from fovpt__ray). With AVX the
   leaf broadcasts them from the ray record instead (vbroadcastss costs what a load costs, and
   the per-ray copies were 14 instructions of the entry: 1.2-1.8 % of a terrain ray's). */
#if FOVPT__SIMD == 1 && defined(__AVX__)
#define FOVPT__RAYV 0 /* vbroadcastss from the ray record: as cheap as a load */
#else
#define FOVPT__RAYV FOVPT__SIMD
#endif
typedef struct fovpt__rayv {
#if FOVPT__RAYV
    fovpt__v4 ox, oy, oz, dx, dy, dz, tmin;
#else
    int unused;
#endif
} fovpt__rayv;
FOVPT__PRIV int fovpt__leaf(const fovpt_scene *s, const fovpt__ray *r, const fovpt__rayv *rv,
                            uint32_t first, uint32_t count, float tmin, float *tmax,
                            uint32_t *best, uint32_t *pos, int any, int shapes)
{
    const fovpt__prim *prims = (const fovpt__prim *)s->prims;
    uint32_t blk = first >> 2, lm;
    const float *q = s->leaf_tris + FOVPT__LBLK * (size_t)blk;
    /* the leaf's slots [first, first + count) as a bit mask from lane 0 of its first block
       (count <= FOVPT__LEAF_MAX = 16: at most 19 bits), 4 bits per block; an empty child of
       a W-wide node (count 0, box inverted: reached only when the box test is widened to
       everything, a tmin of -inf after the direction's rescale) has none */
    for (lm = ((1u << count) - 1u) << (first & 3u); lm; lm >>= 4, ++blk, q += FOVPT__LBLK) {
        const uint32_t b0 = blk << 2, lanes = lm & 15u;
        uint32_t hm, dm, j;
        float tv[4];
#if FOVPT__SIMD
        {
#if FOVPT__RAYV
            const fovpt__v4 dx = rv->dx, dy = rv->dy, dz = rv->dz, ox = rv->ox, oy = rv->oy,
                oz = rv->oz, vtmin = rv->tmin;
#else
            const fovpt__v4 dx = FOVPT__V_SET1(r->d[0]), dy = FOVPT__V_SET1(r->d[1]),
                dz = FOVPT__V_SET1(r->d[2]), ox = FOVPT__V_SET1(r->o[0]),
                oy = FOVPT__V_SET1(r->o[1]), oz = FOVPT__V_SET1(r->o[2]),
                vtmin = FOVPT__V_SET1(tmin);
            (void)rv;
#endif
            const fovpt__v4 e1x = FOVPT__V_LD(q + 12), e1y = FOVPT__V_LD(q + 16),
                e1z = FOVPT__V_LD(q + 20), e2x = FOVPT__V_LD(q + 24), e2y = FOVPT__V_LD(q + 28),
                e2z = FOVPT__V_LD(q + 32);
            const fovpt__v4 sx = FOVPT__V_SUB(ox, FOVPT__V_LD(q)),
                sy = FOVPT__V_SUB(oy, FOVPT__V_LD(q + 4)),
                sz = FOVPT__V_SUB(oz, FOVPT__V_LD(q + 8));
            const fovpt__v4 pvx = FOVPT__V_SUB(FOVPT__V_MUL(dy, e2z), FOVPT__V_MUL(dz, e2y)),
                pvy = FOVPT__V_SUB(FOVPT__V_MUL(dz, e2x), FOVPT__V_MUL(dx, e2z)),
                pvz = FOVPT__V_SUB(FOVPT__V_MUL(dx, e2y), FOVPT__V_MUL(dy, e2x));
            const fovpt__v4 det = FOVPT__V_ADD(FOVPT__V_ADD(FOVPT__V_MUL(e1x, pvx),
                                                            FOVPT__V_MUL(e1y, pvy)),
                                               FOVPT__V_MUL(e1z, pvz));
            const fovpt__v4 ad = FOVPT__V_ABS(det);
            const fovpt__m4 okd = FOVPT__V_GT(ad, FOVPT__V_SET1(1e-30f));
            const fovpt__v4 zero = FOVPT__V_SET1(0.0f);
            fovpt__v4 u, v, t, qx, qy, qz;
            fovpt__m4 m;
            u = FOVPT__V_ADD(FOVPT__V_ADD(FOVPT__V_MUL(sx, pvx), FOVPT__V_MUL(sy, pvy)),
                             FOVPT__V_MUL(sz, pvz));
            u = FOVPT__V_XOR(u, FOVPT__V_SIGN(det)); /* u * sg: the sign flipped where det < 0 */
            m = FOVPT__M_AND(okd, FOVPT__M_AND(FOVPT__V_GE(u, zero), FOVPT__V_LE(u, ad)));
            hm = FOVPT__M_BITS(m) & lanes;
            /* det = 0 (a slot that is not a triangle) or tiny: the loop below passes the
               shapes to fovpt__isect and drops the triangles, so a scene whose bounded
               primitives are all triangles needs no such lanes */
            dm = shapes ? ~FOVPT__M_BITS(okd) & lanes : 0u;
            {   /* the rest of the test whatever hm is: u passes in most blocks a ray reaches
                   (87 % on the terrain's bounce rays), and the branch it would take is the
                   hard one to predict (without it: terrain 1.00-1.04x camera, 1.03-1.05x
                   bounce rays, side by side) */
                qx = FOVPT__V_SUB(FOVPT__V_MUL(sy, e1z), FOVPT__V_MUL(sz, e1y));
                qy = FOVPT__V_SUB(FOVPT__V_MUL(sz, e1x), FOVPT__V_MUL(sx, e1z));
                qz = FOVPT__V_SUB(FOVPT__V_MUL(sx, e1y), FOVPT__V_MUL(sy, e1x));
                v = FOVPT__V_ADD(FOVPT__V_ADD(FOVPT__V_MUL(dx, qx), FOVPT__V_MUL(dy, qy)),
                                 FOVPT__V_MUL(dz, qz));
                v = FOVPT__V_XOR(v, FOVPT__V_SIGN(det));
                t = FOVPT__V_DIV(FOVPT__V_ADD(FOVPT__V_ADD(FOVPT__V_MUL(e2x, qx),
                                                           FOVPT__V_MUL(e2y, qy)),
                                              FOVPT__V_MUL(e2z, qz)), det);
                m = FOVPT__M_AND(m, FOVPT__M_AND(FOVPT__V_GE(v, zero),
                                                 FOVPT__V_LE(FOVPT__V_ADD(u, v), ad)));
                m = FOVPT__M_AND(m, FOVPT__M_AND(FOVPT__V_GT(t, vtmin),
                                                 FOVPT__V_LE(t, FOVPT__V_SET1(*tmax))));
                hm &= FOVPT__M_BITS(m);
                FOVPT__V_ST(tv, t);
            }
        }
#else
        uint32_t lb;
        (void)rv;
        hm = dm = 0;
        for (lb = lanes; lb; lb &= lb - 1u) { /* the leaf's lanes, lowest first */
            float v0[3], e1[3], e2[3], pv[3], sv[3], qv[3], det, ad, sg, u, v, t;
            uint32_t k;
            j = fovpt__ctz(lb);
            for (k = 0; k < 3; ++k) {
                v0[k] = q[4u * k + j]; e1[k] = q[4u * (3u + k) + j]; e2[k] = q[4u * (6u + k) + j];
            }
            fov__cross(r->d, e2, pv);
            det = fov__dot(e1, pv);
            if (!(fov__absf(det) > 1e-30f)) { dm |= shapes ? 1u << j : 0u; continue; }
            sg = det < 0.0f ? -1.0f : 1.0f;
            ad = det * sg;
            fovpt__sub3(sv, r->o, v0);
            u = fov__dot(sv, pv) * sg;
            if (!(u >= 0.0f && u <= ad)) continue;
            fov__cross(sv, e1, qv);
            v = fov__dot(r->d, qv) * sg;
            if (!(v >= 0.0f && u + v <= ad)) continue;
            t = fov__dot(e2, qv) / det;
            if (!(t > tmin && t <= *tmax)) continue;
            tv[j] = t;
            hm |= 1u << j;
        }
#endif
        for (dm |= hm; dm; dm &= dm - 1u) { /* the lanes hit (hm) or left to fovpt__isect */
            const uint32_t slot = ((const uint32_t *)(const void *)(q + 48))[j = fovpt__ctz(dm)];
            if (hm & (1u << j)) {
                if (fovpt__leaf_take(tv[j], slot, tmax, best)) {
                    if (any) return 1;
                    *pos = b0 + j; /* the hit record from this block (fovpt__hit) */
                }
            } else if (prims[slot].type != FOVPT__TRI) {
                /* another shape: its own test, over (tmin, tmax] when a tie may count */
                float tm = *tmax, t;
                if (*best != FOVPT_PRIM_NONE && tm < FLT_MAX) tm = fovpt__next_up(tm);
                t = fovpt__isect(&prims[slot], r, tmin, tm);
                if (t < tm && fovpt__leaf_take(t, slot, tmax, best)) {
                    if (any) return 1;
                    *pos = FOVPT_PRIM_NONE;
                }
            }
        }
    }
    return 0;
}

/* Closest hit over the bounded primitives and the planes: returns the slot (and lowers *tmax
   to its t) or FOVPT_PRIM_NONE; any: returns the first hit found instead (occlusion); brute:
   a loop over every bounded primitive instead of the BVH. BVH traversal, from the root of
   the W-wide nodes (fovpt__node4; no separate box test for the whole tree: the root's
   children's boxes bound it): the W children's slab tests at once (SSE / AVX / NEON /
   SIMD128, or the same arithmetic per child), then a single hit child is visited directly
   (the lowest set bit of the hit mask), of two the nearer (by entry distance) is visited and
   the other pushed, of three the two farther are pushed (farthest first, by a sorting
   network) and the nearest visited, of four or more all are pushed, sorted in place farthest
   first, and the nearest is popped and visited; every stack entry keeps its entry distance.
   A pop skips entries that start beyond the closest hit found meanwhile (no second box test:
   tn <= min(box exit, tmax) widened by the rounding margin at the push, so tn <= new tmax,
   widened alike, is the same test). Leaf triangles are intersected inline from a
   leaf-ordered copy (v0, e1, e2), the other shapes through fovpt__isect; the planes
   (unbounded) are tested after the bounded primitives. */
FOVPT__PRIV uint32_t fovpt__closest(const fovpt_scene *s, const fovpt__ray *r, float tmin,
                                    float *tmax, int brute, int any, uint32_t *pos)
{
    const fovpt__prim *prims = (const fovpt__prim *)s->prims;
    uint32_t best = FOVPT_PRIM_NONE, i;
    float t;
    *pos = FOVPT_PRIM_NONE;
    if (s->nodes && !brute) {
        const fovpt__node4 *n4 = (const fovpt__node4 *)s->nodes4;
        /* the bounded shapes come first in the primitive records, then the triangles: the
           first record tells whether any leaf slot holds a shape */
        const int shapes = prims[0].type != FOVPT__TRI;
        uint32_t stack[FOVPT__STACK], sp = 0, ref = 0;
        float stack_t[FOVPT__STACK], lim;
        fovpt__rayv rv;
        const float gk = tmin < 0.0f ? -tmin * FOVPT__BOX_NEG : 0.0f;
        /* per octant: the near planes' rows in fovpt__node.b (lo x, y, z = 0, 1, 2; hi = 3, 4,
           5, swapped on a negative axis), then the far planes' */
        static const uint32_t rows[8][6] = {
            { 0, 1, 2, 3, 4, 5 }, { 3, 1, 2, 0, 4, 5 }, { 0, 4, 2, 3, 1, 5 }, { 3, 4, 2, 0, 1, 5 },
            { 0, 1, 5, 3, 4, 2 }, { 3, 1, 5, 0, 4, 2 }, { 0, 4, 5, 3, 1, 2 }, { 3, 4, 5, 0, 1, 2 }
        };
        const uint32_t *rw = rows[r->oct];
        const uint32_t nx = rw[0], ny = rw[1], nz = rw[2], fx = rw[3], fy = rw[4], fz = rw[5];
#if FOVPT__SIMD
        const float ifx = r->ig[0], ify = r->ig[1], ifz = r->ig[2];
        const fovpt__v4 vox = FOVPT__V_SET1(r->o[0]), voy = FOVPT__V_SET1(r->o[1]),
            voz = FOVPT__V_SET1(r->o[2]);
        const fovpt__v4 vix = FOVPT__V_SET1(r->inv[0]), viy = FOVPT__V_SET1(r->inv[1]),
            viz = FOVPT__V_SET1(r->inv[2]);
        const fovpt__v4 vfx = FOVPT__V_SET1(ifx), vfy = FOVPT__V_SET1(ify),
            vfz = FOVPT__V_SET1(ifz);
        const fovpt__v4 vtmin = FOVPT__V_SET1(tmin), vgk = FOVPT__V_SET1(gk);
        fovpt__v4 vtmax = FOVPT__V_SET1(*tmax * FOVPT__BOX_GROW);
#if FOVPT__RAYV
        rv.ox = vox; rv.oy = voy; rv.oz = voz; rv.tmin = vtmin;
        rv.dx = FOVPT__V_SET1(r->d[0]); rv.dy = FOVPT__V_SET1(r->d[1]);
        rv.dz = FOVPT__V_SET1(r->d[2]);
#else
        rv.unused = 0;
        (void)vtmin;
#endif
#if FOVPT__SIMD == 1 && FOVPT_BVH_WIDTH == 8 && defined(__AVX__)
        /* the slab distances as (o - plane) * -inv: -(plane - o) and -inv exactly, so the
           same floats as (plane - o) * inv (NaN where that is NaN), and the plane's load
           folds into the subtraction (vsubps o, [mem]); SSE without VEX gains nothing (the
           load cannot fold, o needs a copy), so the 4-lane passes keep (plane - o) * inv */
        const __m256 wox = _mm256_set1_ps(r->o[0]), woy = _mm256_set1_ps(r->o[1]),
            woz = _mm256_set1_ps(r->o[2]), wix = _mm256_set1_ps(-r->inv[0]),
            wiy = _mm256_set1_ps(-r->inv[1]), wiz = _mm256_set1_ps(-r->inv[2]),
            wfx = _mm256_set1_ps(-ifx), wfy = _mm256_set1_ps(-ify), wfz = _mm256_set1_ps(-ifz);
        __m256 wtmax = _mm256_set1_ps(*tmax * FOVPT__BOX_GROW);
        (void)vix; (void)viy; (void)viz; (void)vfx; (void)vfy; (void)vfz; (void)vgk; (void)vtmax;
        (void)vox; (void)voy; (void)voz;
#endif
#else
        const float ox = r->o[0], oy = r->o[1], oz = r->o[2], ix = r->inv[0], iy = r->inv[1],
            iz = r->inv[2], ifx = ix * FOVPT__BOX_GROW, ify = iy * FOVPT__BOX_GROW,
            ifz = iz * FOVPT__BOX_GROW;
        rv.unused = 0;
#endif
        {   /* no separate root box test: the root node's children's boxes are its box */
            lim = *tmax * FOVPT__BOX_GROW + gk; /* a pushed entry distance beyond: culled */
            for (;;) {
                if (ref & FOVPT__LEAF4) {
                    if (fovpt__leaf(s, r, &rv, (ref & ~FOVPT__LEAF4) >> 5, ref & 31u, tmin, tmax,
                                    &best, pos, any, shapes))
                        return best;
                    lim = *tmax * FOVPT__BOX_GROW + gk;
#if FOVPT__SIMD
                    vtmax = FOVPT__V_SET1(*tmax * FOVPT__BOX_GROW);
#if FOVPT__SIMD == 1 && FOVPT_BVH_WIDTH == 8 && defined(__AVX__)
                    wtmax = _mm256_set1_ps(*tmax * FOVPT__BOX_GROW);
#endif
#endif
                } else {
                    /* the W children's slab tests (the slab test's arithmetic, the same
                       operand order: max(a, t) = a > t ? a : t), then the hit children
                       nearest first: one is visited; of two the nearer is visited and the
                       other pushed; of three the two farther are pushed, farthest first,
                       and the nearest visited; four or more are all pushed with their
                       entry distances, sorted farthest first, and the nearest popped */
                    const fovpt__node4 *nd = &n4[ref];
                    float tv[FOVPT_BVH_WIDTH];
                    uint32_t hm, j;
#if FOVPT__SIMD == 1 && FOVPT_BVH_WIDTH == 8 && defined(__AVX__)
                    __m256 t0 = _mm256_set1_ps(tmin), u0 = wtmax;
#define FOVPT__SLAB8(row, o, i) _mm256_mul_ps(_mm256_sub_ps(o, _mm256_loadu_ps(nd->b[row])), i)
                    t0 = _mm256_max_ps(FOVPT__SLAB8(nx, wox, wix), t0);
                    u0 = _mm256_min_ps(FOVPT__SLAB8(fx, wox, wfx), u0);
                    t0 = _mm256_max_ps(FOVPT__SLAB8(ny, woy, wiy), t0);
                    u0 = _mm256_min_ps(FOVPT__SLAB8(fy, woy, wfy), u0);
                    t0 = _mm256_max_ps(FOVPT__SLAB8(nz, woz, wiz), t0);
                    u0 = _mm256_min_ps(FOVPT__SLAB8(fz, woz, wfz), u0);
#undef FOVPT__SLAB8
                    if (gk > 0.0f) u0 = _mm256_add_ps(u0, _mm256_set1_ps(gk));
                    hm = (uint32_t)_mm256_movemask_ps(_mm256_cmp_ps(t0, u0, _CMP_LE_OQ));
                    _mm256_storeu_ps(tv, t0);
#elif FOVPT__SIMD
                    /* four children per pass, the passes written out (W / 4 of them) */
#define FOVPT__SLAB4(row, o, i, j) FOVPT__V_MUL(FOVPT__V_SUB(FOVPT__V_LD(nd->b[row] + j), o), i)
#define FOVPT__PASS4(j, bits)                                                              \
    do {                                                                                   \
        fovpt__v4 t0 = vtmin, u0 = vtmax;                                                  \
        t0 = FOVPT__V_MAXT(FOVPT__SLAB4(nx, vox, vix, j), t0);                             \
        u0 = FOVPT__V_MINT(FOVPT__SLAB4(fx, vox, vfx, j), u0);                             \
        t0 = FOVPT__V_MAXT(FOVPT__SLAB4(ny, voy, viy, j), t0);                             \
        u0 = FOVPT__V_MINT(FOVPT__SLAB4(fy, voy, vfy, j), u0);                             \
        t0 = FOVPT__V_MAXT(FOVPT__SLAB4(nz, voz, viz, j), t0);                             \
        u0 = FOVPT__V_MINT(FOVPT__SLAB4(fz, voz, vfz, j), u0);                             \
        if (gk > 0.0f) u0 = FOVPT__V_ADD(u0, vgk);                                         \
        bits = FOVPT__M_BITS(FOVPT__V_LE(t0, u0)) << j;                                    \
        FOVPT__V_ST(tv + j, t0);                                                           \
    } while (0)
                    FOVPT__PASS4(0u, hm);
#if FOVPT_BVH_WIDTH == 8
                    {
                        uint32_t hm1;
                        FOVPT__PASS4(4u, hm1);
                        hm |= hm1;
                    }
#endif
#undef FOVPT__PASS4
#undef FOVPT__SLAB4
#else
                    hm = 0;
                    for (j = 0; j < FOVPT__W; ++j) {
                        const float tm = *tmax * FOVPT__BOX_GROW;
                        float t0 = tmin, u0 = tm, a, c;
                        a = (nd->b[nx][j] - ox) * ix; c = (nd->b[fx][j] - ox) * ifx;
                        t0 = a > t0 ? a : t0; u0 = c < u0 ? c : u0;
                        a = (nd->b[ny][j] - oy) * iy; c = (nd->b[fy][j] - oy) * ify;
                        t0 = a > t0 ? a : t0; u0 = c < u0 ? c : u0;
                        a = (nd->b[nz][j] - oz) * iz; c = (nd->b[fz][j] - oz) * ifz;
                        t0 = a > t0 ? a : t0; u0 = c < u0 ? c : u0;
                        tv[j] = t0;
                        if (t0 <= u0 + gk) hm |= 1u << j;
                    }
#endif
                    if (hm) {
                        uint32_t j0 = fovpt__ctz(hm), j1, base;
                        hm &= hm - 1u;
                        if (!hm) { /* the common cases first: one or two children hit */
                            ref = nd->child[j0];
                            continue;
                        }
                        j1 = fovpt__ctz(hm);
                        hm &= hm - 1u;
                        FOV_ASSERT(sp + FOVPT__W <= FOVPT__STACK);
                        if (!hm) {
                            if (tv[j1] < tv[j0]) { j = j0; j0 = j1; j1 = j; }
                            stack[sp] = nd->child[j1]; stack_t[sp++] = tv[j1];
                            ref = nd->child[j0];
                            continue;
                        }
                        if (!(hm & (hm - 1u))) {
                            /* three: a sorting network on the lane numbers (compare and
                               swap by a mask, no branch: the order of three entry
                               distances is what a branch predictor misses), farthest first */
                            uint32_t j2 = fovpt__ctz(hm), x;
                            x = (j0 ^ j1) & (0u - (uint32_t)(tv[j0] < tv[j1])); j0 ^= x; j1 ^= x;
                            x = (j1 ^ j2) & (0u - (uint32_t)(tv[j1] < tv[j2])); j1 ^= x; j2 ^= x;
                            x = (j0 ^ j1) & (0u - (uint32_t)(tv[j0] < tv[j1])); j0 ^= x; j1 ^= x;
                            stack[sp] = nd->child[j0]; stack_t[sp++] = tv[j0];
                            stack[sp] = nd->child[j1]; stack_t[sp++] = tv[j1];
                            ref = nd->child[j2];
                            continue;
                        }
                        /* four or more: all pushed, sorted farthest first (insertion by
                           entry distance), the nearest popped and visited */
                        base = sp;
                        stack[sp] = nd->child[j0]; stack_t[sp++] = tv[j0];
                        stack[sp] = nd->child[j1]; stack_t[sp++] = tv[j1];
                        for (; hm; hm &= hm - 1u) {
                            j = fovpt__ctz(hm);
                            stack[sp] = nd->child[j]; stack_t[sp++] = tv[j];
                        }
                        for (j = base + 1u; j < sp; ++j) {
                            const float tk = stack_t[j];
                            const uint32_t ck = stack[j];
                            uint32_t k = j;
                            while (k > base && stack_t[k - 1u] < tk) {
                                stack_t[k] = stack_t[k - 1u]; stack[k] = stack[k - 1u]; --k;
                            }
                            stack_t[k] = tk; stack[k] = ck;
                        }
                        ref = stack[--sp];
                        continue;
                    }
                }
                /* pop, skipping nodes now beyond the closest hit */
                for (;;) {
                    if (sp == 0) { ref = FOVPT_PRIM_NONE; break; }
                    --sp;
                    if (stack_t[sp] <= lim) { ref = stack[sp]; break; }
                }
                if (ref == FOVPT_PRIM_NONE) break;
            }
        }
    } else {
        for (i = 0; i < s->num_bounded; ++i) {
            t = fovpt__isect(&prims[i], r, tmin, *tmax);
            if (t < *tmax) { *tmax = t; best = i; if (any) return best; }
        }
    }
    for (i = s->num_bounded; i < s->num_prims; ++i) {
        t = fovpt__isect(&prims[i], r, tmin, *tmax);
        if (t < *tmax) { *tmax = t; best = i; *pos = FOVPT_PRIM_NONE; if (any) return best; }
    }
    return best;
}

FOVPT__PRIV int fovpt__hit(const fovpt_scene *s, const float org[3], const float dir[3], float tmin,
                           float tmax, fovpt_hit *h, int brute)
{
    fovpt__ray r;
    float t = tmax, un[3];
    uint32_t slot, pos, umat = 0;
    int user = 0, dc;
    if (!s || !h || !org || !dir || !s->prims) { if (h) h->prim = FOVPT_PRIM_NONE; return 0; }
    h->prim = FOVPT_PRIM_NONE;
    if (!fov__finite(tmin) || !(tmax > tmin)) return 0;
#if FOVPT__SIMD
    if (fovpt__ray_fast(&r, org, dir)) {
        slot = fovpt__closest(s, &r, tmin, &t, brute, 0, &pos);
    } else
#endif
    if (!((dc = fovpt__dir_class(dir)) & 1)) {
        /* largest component in [2^-32, 2^32]: dot(dir, dir) >= 2^-64 > 0 when finite */
        if (!fov__finite3(org) || !fov__finite3(dir)) return 0;
        fovpt__ray_set(&r, org, dir);
        slot = fovpt__closest(s, &r, tmin, &t, brute || (dc & 2), 0, &pos);
    } else {
        float ds[3], sc = fovpt__dir_scale(dir, ds), ts;
        if (!fovpt__ray_init(&r, org, ds)) return 0;
        ts = tmax * sc; /* t along ds */
        slot = fovpt__closest(s, &r, tmin * sc, &ts, brute || (fovpt__dir_class(ds) & 2), 0, &pos);
        if (slot != FOVPT_PRIM_NONE && !fovpt__unscale_t(ts, sc, tmin, tmax, &t)) {
            slot = FOVPT_PRIM_NONE; /* no float strictly inside (tmin, tmax) */
            t = tmax;
        }
    }
    if (s->user_hit) {
        float tu = t;
        un[0] = un[1] = un[2] = 0.0f;
        if (s->user_hit(org, dir, tmin, t, &tu, un, &umat, s->user) && tu > tmin && tu < t &&
            umat < s->num_materials && fov__normalize(un) > 0.0f) {
            t = tu;
            user = 1;
        }
    }
    if (!user && slot == FOVPT_PRIM_NONE) return 0;
    h->t = t;
    fovpt__madd3(h->p, org, t, dir);
    if (user) {
        fovpt__copy3(h->n, un);
        h->prim = FOVPT_PRIM_USER;
        h->material = umat;
        h->slot = FOVPT_PRIM_USER;
        return 1;
    } else if (pos != FOVPT_PRIM_NONE) {
        /* a triangle found in a leaf block: id, material and normal from the block, which
           the traversal has just read */
        const float *q = s->leaf_tris + FOVPT__LBLK * (size_t)(pos >> 2) + (pos & 3u);
        const uint32_t *qi = (const uint32_t *)(const void *)(q + 48);
        h->prim = qi[4];
        h->material = qi[8];
        h->slot = slot;
        fovpt__set3(h->n, q[36], q[40], q[44]);
    } else {
        const fovpt__prim *p = (const fovpt__prim *)s->prims + slot;
        h->prim = p->id;
        h->material = p->material;
        h->slot = slot;
        if (p->type == FOVPT_SHAPE_SPHERE) {
            fovpt__sub3(h->n, h->p, p->a);
            if (!(fov__normalize(h->n) > 0.0f)) {
                /* the hit point rounded onto the centre (a radius below the coordinates'
                   resolution): the normal facing the ray */
                fovpt__set3(h->n, -dir[0], -dir[1], -dir[2]);
                fov__normalize(h->n);
            }
        } else if (p->type == FOVPT_SHAPE_BOX) {
            /* the face: the axis where the hit is relatively closest to a slab */
            float best = FLT_MAX;
            uint32_t k, ax = 0;
            float sg = 1.0f;
            for (k = 0; k < 3; ++k) {
                float ext = fov__maxf(p->b[k] - p->a[k], 1e-30f);
                float d0 = fov__absf(h->p[k] - p->a[k]) / ext,
                    d1 = fov__absf(h->p[k] - p->b[k]) / ext;
                if (d0 < best) { best = d0; ax = k; sg = -1.0f; }
                if (d1 < best) { best = d1; ax = k; sg = 1.0f; }
            }
            h->n[0] = h->n[1] = h->n[2] = 0.0f;
            h->n[ax] = sg;
        } else {
            fovpt__copy3(h->n, p->n);
        }
    }
    return 1;
}

FOVPT_API int fovpt_intersect(const fovpt_scene *s, const float org[3], const float dir[3],
                              float tmin, float tmax, fovpt_hit *hit)
{
    return fovpt__hit(s, org, dir, tmin, tmax, hit, 0);
}
FOVPT_API int fovpt_intersect_brute(const fovpt_scene *s, const float org[3], const float dir[3],
                                    float tmin, float tmax, fovpt_hit *hit)
{
    return fovpt__hit(s, org, dir, tmin, tmax, hit, 1);
}
FOVPT_API int fovpt_occluded(const fovpt_scene *s, const float org[3], const float dir[3],
                             float tmin, float tmax)
{
    fovpt__ray r;
    uint32_t pos;
    float t = tmax;
    int dc;
    if (!s || !org || !dir || !s->prims) return 0;
    if (!fov__finite(tmin) || !(tmax > tmin)) return 0;
#if FOVPT__SIMD
    if (fovpt__ray_fast(&r, org, dir)) {
        if (fovpt__closest(s, &r, tmin, &t, 0, 1, &pos) != FOVPT_PRIM_NONE) return 1;
    } else
#endif
    if (!((dc = fovpt__dir_class(dir)) & 1)) {
        if (!fov__finite3(org) || !fov__finite3(dir)) return 0; /* as in fovpt__hit */
        fovpt__ray_set(&r, org, dir);
        if (fovpt__closest(s, &r, tmin, &t, dc & 2, 1, &pos) != FOVPT_PRIM_NONE)
            return 1;
    } else {
        float ds[3], sc = fovpt__dir_scale(dir, ds);
        if (!fovpt__ray_init(&r, org, ds)) return 0;
        t = tmax * sc;
        /* any hit inside the scaled interval is one inside (tmin, tmax), t rounded onto the
           nearest float inside as fovpt_intersect reports it (fovpt__unscale_t) */
        if (fovpt__closest(s, &r, tmin * sc, &t, fovpt__dir_class(ds) & 2, 1, &pos) !=
            FOVPT_PRIM_NONE) {
            float tt;
            if (fovpt__unscale_t(t, sc, tmin, tmax, &tt)) return 1;
        }
    }
    if (s->user_hit) {
        float tu = tmax, un[3] = { 0.0f, 0.0f, 0.0f };
        uint32_t um = 0;
        if (s->user_hit(org, dir, tmin, tmax, &tu, un, &um, s->user) && tu > tmin && tu < tmax)
            return 1;
    }
    return 0;
}

/* ---- random streams ------------------------------------------------------------------------ */
/* A 32-bit integer finaliser (lowbias32, C. Wellons' hash prospector): full avalanche. */
FOVPT__PRIV uint32_t fovpt__mix(uint32_t x)
{
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
FOVPT_API void fovpt_rng_init(fovpt_rng *r, uint32_t seed, uint32_t pixel, uint32_t sample,
                              uint32_t frame)
{
    uint32_t k;
    if (!r) return;
    k = fovpt__mix(seed ^ 0x9e3779b9u);
    k = fovpt__mix(k ^ pixel);
    k = fovpt__mix(k + 0x85ebca6bu * sample);
    k = fovpt__mix(k ^ (0xc2b2ae35u * (frame + 1u)));
    r->key = k;
    r->ctr = 0;
    r->scramble = r->index = r->sobol = 0;
    r->group = 0xFFFFFFFFu;
    r->gkey = r->gidx = 0;
}
#define FOVPT__SOBOL_DIMS 26u /* the pixel pair and 8 triples: 4 bounces' light and BSDF */
#ifndef FOVPT__BITREV /* tests define it 0 to run the portable path */
#if defined(__clang__) && defined(__has_builtin)
#if __has_builtin(__builtin_bitreverse32)
#define FOVPT__BITREV 2 /* one instruction where the target has it (rbit on ARM) */
#endif
#endif
#if !defined(FOVPT__BITREV) && (defined(__GNUC__) || defined(__clang__))
#define FOVPT__BITREV 1 /* byte swap, then the bits of each byte */
#endif
#ifndef FOVPT__BITREV
#define FOVPT__BITREV 0
#endif
#endif
/* The bits of x in reverse order (the same value on every path: test_fovpt.c compares it with
   a loop, the FOVPT_NO_SIMD build with FOVPT__BITREV 0). */
FOVPT__PRIV uint32_t fovpt__rev32(uint32_t x)
{
#if FOVPT__BITREV == 2
    return __builtin_bitreverse32(x);
#else
#if FOVPT__BITREV == 1
    x = __builtin_bswap32(x);
#else
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    x = (x >> 16) | (x << 16);
#endif
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
#endif
}
/* The hash of Laine and Karras 2011 with the constants of Burley 2020: on a bit-reversed
   fraction (bit 0 = the 1/2 digit) a nested uniform scramble (Owen 1995): output bit j
   depends only on input bits 0..j, so every elementary interval maps onto one. */
FOVPT__PRIV uint32_t fovpt__lk(uint32_t x, uint32_t seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu; x ^= x * 0xb82f1e52u; x ^= x * 0xc7afe638u; x ^= x * 0x8d22f6e6u;
    return x;
}
/* Sobol's dimension 1 (Sobol 1967) of index i, bit-reversed (bit j = the 2^-(j+1) digit):
   its generator is Pascal's triangle mod 2, so digit j is the xor of the index bits k that
   contain j (k & j = j, Lucas' theorem), a superset transform in five steps. Dimension 0
   (van der Corput), bit-reversed, is i itself. */
FOVPT__PRIV uint32_t fovpt__sobol1r(uint32_t i)
{
    i ^= (i >> 1) & 0x55555555u;
    i ^= (i >> 2) & 0x33333333u;
    i ^= (i >> 4) & 0x0f0f0f0fu;
    i ^= (i >> 8) & 0x00ff00ffu;
    i ^= (i >> 16) & 0x0000ffffu;
    return i;
}
FOVPT_API void fovpt_rng_init_sobol(fovpt_rng *r, uint32_t seed, uint32_t pixel,
                                    uint32_t sample, uint32_t frame)
{
    uint32_t k;
    if (!r) return;
    fovpt_rng_init(r, seed, pixel, sample, frame);
    k = fovpt__mix(seed ^ 0x3c6ef372u); /* the stream of (seed, pixel, frame), not the sample */
    k = fovpt__mix(k ^ pixel);
    r->scramble = fovpt__mix(k ^ (0xc2b2ae35u * (frame + 1u)));
    r->index = fovpt__rev32(sample);
    r->sobol = 1;
}
FOVPT_API float fovpt_rng_next(fovpt_rng *r)
{
    uint32_t x, c;
    if (!r) return 0.0f;
    c = r->ctr++;
    if (r->sobol == 1u && c < FOVPT__SOBOL_DIMS) {
        /* SAMPLERS: dimensions 0, 1 one pair, then triples (a 1-D dimension, a pair): each
           group (a pair, or a 1-D dimension alone) shuffles the sample index by its own
           nested uniform scramble (Burley 2020),
           so the groups are independent of each other while each is stratified over the
           samples; the index, bit-reversed, scrambled and reversed back, keeps a prefix of
           2^m indices' low m bits a permutation */
        /* dimension c's group (0: the pixel pair; triple t: the 1-D 1 + 2t, the pair 2 + 2t)
           and role (1: Sobol's dimension 0, the 1-D's or a pair's x; 2: dimension 1, y) */
        static const unsigned char grp[FOVPT__SOBOL_DIMS] = { 0, 0, 1, 2, 2, 3, 4, 4, 5, 6, 6,
            7, 8, 8, 9, 10, 10, 11, 12, 12, 13, 14, 14, 15, 16, 16 };
        static const unsigned char role[FOVPT__SOBOL_DIMS] = { 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2,
            1, 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2, 1, 1, 2 };
        uint32_t g = grp[c], j = role[c];
        if (g != r->group) {
            r->group = g;
            r->gkey = fovpt__mix(r->scramble + 0x68bc21ebu * (g + 1u));
            r->gidx = fovpt__rev32(fovpt__lk(r->index, r->gkey));
        }
        x = j == 2u ? fovpt__sobol1r(r->gidx) : r->gidx; /* bit-reversed */
        {   /* two rounds: one leaves the low digits' histogram measurably uneven (a chi-square
               over 32 bins at p ~ 1e-6 in the test's streams); a composition of nested
               uniform scrambles is one */
            uint32_t sd = fovpt__mix(r->gkey ^ (0x02e5be93u * (j + 1u)));
            x = fovpt__rev32(fovpt__lk(fovpt__lk(x, sd), fovpt__mix(sd)));
        }
        return (float)(x >> 8) * (1.0f / 16777216.0f);
    }
    x = fovpt__mix(fovpt__mix(r->key + 0x9e3779b9u * c) ^ r->key);
    return (float)(x >> 8) * (1.0f / 16777216.0f);
}
/* The stream of a sample under the config's sampler (DEFAULT, which a config handed to
   fovpt_shade_points without fovpt_config_resolve may still hold, is SOBOL). */
FOVPT__PRIV int fovpt__sobol(const fovpt_config *c)
{
    return c->sampler != (uint32_t)FOVPT_SAMPLER_RANDOM;
}
FOVPT__PRIV void fovpt__rng_start(fovpt_rng *r, const fovpt_config *c, uint32_t pixel,
                                  uint32_t sample, uint32_t frame)
{
    if (fovpt__sobol(c))
        fovpt_rng_init_sobol(r, c->seed, pixel, sample, frame);
    else
        fovpt_rng_init(r, c->seed, pixel, sample, frame);
}

/* ---- BSDFs -------------------------------------------------------------------------------- */
FOVPT__PRIV void fovpt__local(const float n[3], float x, float y, float z, float out[3])
{
    float t[3], b[3];
    fovpt__basis(n, t, b);
    out[0] = x * t[0] + y * b[0] + z * n[0];
    out[1] = x * t[1] + y * b[1] + z * n[1];
    out[2] = x * t[2] + y * b[2] + z * n[2];
}
FOVPT__PRIV void fovpt__cosine(const float n[3], float u1, float u2, float wi[3])
{
    float r = FOV__SQRT(u1), ph = 2.0f * FOV__PI * u2;
    fovpt__local(n, r * FOV__COS(ph), r * FOV__SIN(ph), FOV__SQRT(fov__maxf(0.0f, 1.0f - u1)), wi);
}
FOVPT__PRIV void fovpt__reflect(const float n[3], const float wo[3], float wi[3])
{
    float c = 2.0f * fov__dot(n, wo);
    wi[0] = c * n[0] - wo[0]; wi[1] = c * n[1] - wo[1]; wi[2] = c * n[2] - wo[2];
}
/* Phong lobe probabilities (Axblad 2020, Eq. 3.9-3.12): pS = mean(ks) / (mean(ks) + mean(kd)). */
FOVPT__PRIV float fovpt__phong_ps(const fovpt_material *m)
{
    float as = fovpt__mean3(m->specular), ad = fovpt__mean3(m->albedo);
    return as + ad > 0.0f ? as / (as + ad) : 0.0f;
}
/* f cos and the mixture pdf of a Lambert or Phong material; ns faces wo. */
FOVPT__PRIV void fovpt__eval_smooth(const fovpt_material *m, const float ns[3], const float wo[3],
                                    const float wi[3], float fcos[3], float *pdf)
{
    float ci = fov__dot(ns, wi);
    uint32_t k;
    fcos[0] = fcos[1] = fcos[2] = 0.0f;
    *pdf = 0.0f;
    if (!(ci > 0.0f)) return;
    if (m->type == FOVPT_MAT_LAMBERT) {
        for (k = 0; k < 3; ++k) fcos[k] = m->albedo[k] * (ci / FOV__PI);
        *pdf = ci / FOV__PI;
    } else {
        float wr[3], c, lobe = 0.0f, ps = fovpt__phong_ps(m), a = m->exponent;
        fovpt__reflect(ns, wo, wr);
        c = fov__dot(wr, wi);
        if (c > 0.0f) lobe = FOV__POW(c, a) * (1.0f / (2.0f * FOV__PI));
        for (k = 0; k < 3; ++k)
            fcos[k] = (m->albedo[k] / FOV__PI + m->specular[k] * (a + 2.0f) * lobe) * ci;
        *pdf = (1.0f - ps) * ci / FOV__PI + ps * (a + 1.0f) * lobe;
    }
}
FOVPT__PRIV float fovpt__fresnel(float cosi, float n1, float n2, float *cost)
{
    float eta = n1 / n2, s2 = eta * eta * (1.0f - cosi * cosi), ct, rs, rp;
    if (s2 >= 1.0f) { *cost = 0.0f; return 1.0f; } /* total internal reflection */
    ct = FOV__SQRT(1.0f - s2);
    *cost = ct;
    rs = (n1 * cosi - n2 * ct) / (n1 * cosi + n2 * ct);
    rp = (n2 * cosi - n1 * ct) / (n2 * cosi + n1 * ct);
    return 0.5f * (rs * rs + rp * rp);
}

FOVPT_API int fovpt_bsdf_sample(const fovpt_material *m, const float n[3], const float wo[3],
                                fovpt_rng *rng, float wi[3], float weight[3], float *pdf)
{
    float ns[3], u0, u1, u2;
    uint32_t k;
    if (!m || !n || !wo || !rng || !wi || !weight || !pdf) return 0;
    weight[0] = weight[1] = weight[2] = 0.0f;
    *pdf = 0.0f;
    u0 = fovpt_rng_next(rng); u1 = fovpt_rng_next(rng); u2 = fovpt_rng_next(rng);
    fovpt__copy3(ns, n);
    if (fov__dot(ns, wo) < 0.0f) { ns[0] = -ns[0]; ns[1] = -ns[1]; ns[2] = -ns[2]; }
    switch (m->type) {
    case FOVPT_MAT_LAMBERT:
        fovpt__cosine(ns, u1, u2, wi);
        *pdf = fov__dot(ns, wi) / FOV__PI;
        if (!(*pdf > 0.0f)) return 0;
        fovpt__copy3(weight, m->albedo);
        return 1;
    case FOVPT_MAT_PHONG: {
        float ps = fovpt__phong_ps(m), fcos[3];
        if (!(fovpt__mean3(m->specular) + fovpt__mean3(m->albedo) > 0.0f)) return 0;
        if (u0 < ps) { /* Phong lobe about the mirror direction: pdf (a+1)/(2 pi) cos^a */
            float wr[3], ct = FOV__POW(u1, 1.0f / (m->exponent + 1.0f)), st,
                ph = 2.0f * FOV__PI * u2;
            st = FOV__SQRT(fov__maxf(0.0f, 1.0f - ct * ct));
            fovpt__reflect(ns, wo, wr);
            fovpt__local(wr, st * FOV__COS(ph), st * FOV__SIN(ph), ct, wi);
        } else {
            fovpt__cosine(ns, u1, u2, wi);
        }
        fovpt__eval_smooth(m, ns, wo, wi, fcos, pdf);
        if (!(*pdf > 0.0f)) return 0;
        for (k = 0; k < 3; ++k) weight[k] = fcos[k] / *pdf;
        return 1;
    }
    case FOVPT_MAT_MIRROR:
        fovpt__reflect(ns, wo, wi);
        fovpt__copy3(weight, m->albedo);
        return 1;
    case FOVPT_MAT_DIELECTRIC: {
        float ci = fov__dot(n, wo), nn[3], n1, n2, cost, F;
        int entering = ci > 0.0f;
        if (entering) { fovpt__copy3(nn, n); n1 = 1.0f; n2 = m->ior; }
        else { nn[0] = -n[0]; nn[1] = -n[1]; nn[2] = -n[2]; n1 = m->ior; n2 = 1.0f; ci = -ci; }
        F = fovpt__fresnel(ci, n1, n2, &cost);
        if (u0 < F) {
            fovpt__reflect(nn, wo, wi);
        } else {
            float eta = n1 / n2;
            for (k = 0; k < 3; ++k) wi[k] = -eta * wo[k] + (eta * ci - cost) * nn[k];
            fov__normalize(wi);
        }
        fovpt__copy3(weight, m->albedo);
        return 1;
    }
    default: return 0;
    }
}

FOVPT_API void fovpt_bsdf_eval(const fovpt_material *m, const float n[3], const float wo[3],
                               const float wi[3], float fcos[3], float *pdf)
{
    float ns[3];
    if (!fcos || !pdf) return;
    fcos[0] = fcos[1] = fcos[2] = 0.0f;
    *pdf = 0.0f;
    if (!m || !n || !wo || !wi) return;
    if (m->type != FOVPT_MAT_LAMBERT && m->type != FOVPT_MAT_PHONG) return;
    fovpt__copy3(ns, n);
    if (fov__dot(ns, wo) < 0.0f) { ns[0] = -ns[0]; ns[1] = -ns[1]; ns[2] = -ns[2]; }
    fovpt__eval_smooth(m, ns, wo, wi, fcos, pdf);
}

/* ---- lights -------------------------------------------------------------------------------- */
FOVPT__PRIV float fovpt__light_pick_pdf(const fovpt_scene *s, uint32_t k)
{
    return k == 0 ? s->light_cdf[0] : s->light_cdf[k] - s->light_cdf[k - 1u];
}
/* Samples a point y (normal ny) on a light; returns the light index. */
FOVPT__PRIV uint32_t fovpt__light_sample(const fovpt_scene *s, fovpt_rng *rng, float y[3],
                                         float ny[3])
{
    float u0 = fovpt_rng_next(rng), u1 = fovpt_rng_next(rng), u2 = fovpt_rng_next(rng);
    uint32_t lo = 0, hi = s->num_lights - 1u;
    const fovpt__prim *p;
    while (lo < hi) { /* first k with cdf[k] > u0 */
        uint32_t mid = (lo + hi) / 2u;
        if (s->light_cdf[mid] > u0) hi = mid; else lo = mid + 1u;
    }
    p = (const fovpt__prim *)s->prims + s->lights[lo];
    if (p->type == FOVPT_SHAPE_SPHERE) {
        float z = 1.0f - 2.0f * u1, r = FOV__SQRT(fov__maxf(0.0f, 1.0f - z * z)),
            ph = 2.0f * FOV__PI * u2;
        fovpt__set3(ny, r * FOV__COS(ph), r * FOV__SIN(ph), z);
        fovpt__madd3(y, p->a, p->r, ny);
    } else if (p->type == FOVPT_SHAPE_QUAD) {
        fovpt__madd3(y, p->a, u1, p->b);
        fovpt__madd3(y, y, u2, p->c);
        fovpt__copy3(ny, p->n);
    } else {
        float su = FOV__SQRT(u1);
        fovpt__madd3(y, p->a, su * (1.0f - u2), p->b);
        fovpt__madd3(y, y, su * u2, p->c);
        fovpt__copy3(ny, p->n);
    }
    return lo;
}
FOVPT__PRIV float fovpt__eps_at(const float p[3])
{
    return FOVPT_RAY_EPS *
        (1.0f + fov__maxf(fov__absf(p[0]), fov__maxf(fov__absf(p[1]), fov__absf(p[2]))));
}
/* p moved off the surface (normal n) to the side of direction d */
FOVPT__PRIV void fovpt__offset(const float p[3], const float n[3], const float d[3], float o[3])
{
    float e = fovpt__eps_at(p);
    if (fov__dot(n, d) < 0.0f) e = -e;
    fovpt__madd3(o, p, e, n);
}

/* NEXT-EVENT ESTIMATION THROUGH MIRRORS: the point p on the mirror sphere or quad mp where
   light from y reflects to x, the mirror's unit normal n there (on x's and y's side) and
   g = dw_x / (cos_y dA_y), the solid angle at x per projected area at y through the mirror.
   0: no such point (x or y behind the mirror or inside the sphere, p off the quad, grazing).
   Quad: y mirrored in the plane (y'), p where x y' crosses it, g = 1 / |x - y'|^2. Sphere
   (centre c, radius R): p = c + R n with n between (x - c) and (y - c), found by the
   Illinois method on the tangential part of the unit directions to x and y (0 at the
   reflection point; positive at n = (x - c) / |x - c|, negative at the other end); g from
   the reflected pencil's two principal widths per unit angle at x (the Coddington equations
   of a convex mirror, focal lengths R cos t / 2 and R / (2 cos t), t the angle of
   incidence): w = d1 + d2 + 2 d1 d2 / (R cos t) and d1 + d2 + 2 d1 d2 cos t / R, g =
   1 / (w w') (a plane mirror, R -> infinity: 1 / (d1 + d2)^2). */
FOVPT__PRIV float fovpt__mirror_g(float R, float d1, float d2, float ct)
{
    float wt, ws;
    if (!(R > 0.0f)) return 1.0f / ((d1 + d2) * (d1 + d2)); /* a plane */
    wt = d1 + d2 + 2.0f * d1 * d2 / (R * ct);
    ws = d1 + d2 + 2.0f * d1 * d2 * ct / R;
    return 1.0f / (wt * ws);
}
FOVPT__PRIV int fovpt__mirror_point(const fovpt__prim *mp, const float x[3], const float y[3],
                                    float p[3], float n[3], float *g)
{
    float vx[3], vy[3], d1, d2, ct;
    uint32_t k, it;
    if (mp->type == FOVPT_SHAPE_QUAD) {
        float sx, sy, yr[3], t, q[3], bc[3], c1[3], den, al, be;
        fovpt__sub3(vx, x, mp->a);
        fovpt__sub3(vy, y, mp->a);
        sx = fov__dot(vx, mp->n);
        sy = fov__dot(vy, mp->n);
        if (!(sx * sy > 0.0f)) return 0; /* not on one side */
        fovpt__madd3(yr, y, -2.0f * sy, mp->n);
        t = sx / (sx + sy);
        for (k = 0; k < 3; ++k) p[k] = x[k] + t * (yr[k] - x[k]);
        fovpt__sub3(q, p, mp->a);
        fov__cross(mp->b, mp->c, bc);
        den = fov__dot(bc, bc);
        fov__cross(q, mp->c, c1);
        al = fov__dot(c1, bc) / den;
        fov__cross(mp->b, q, c1);
        be = fov__dot(c1, bc) / den;
        if (!(al >= 0.0f && al <= 1.0f && be >= 0.0f && be <= 1.0f)) return 0;
        for (k = 0; k < 3; ++k) n[k] = sx > 0.0f ? mp->n[k] : -mp->n[k];
        fovpt__sub3(vx, yr, x);
        d1 = fov__dot(vx, vx);
        if (!(d1 > 0.0f) || !fov__finite(d1)) return 0;
        *g = 1.0f / d1;
        return 1;
    } else {
        const float R = mp->r;
        float ux[3], uy[3], t0[3], dx, dy, s0 = 0.0f, s1 = 1.0f, f0, f1, sm = 0.0f, fm = 1.0f;
        int side = 0;
        fovpt__sub3(ux, x, mp->a);
        fovpt__sub3(uy, y, mp->a);
        dx = fov__normalize(ux);
        dy = fov__normalize(uy);
        if (!(dx > R && dy > R) || fov__dot(ux, uy) < -0.9999f) return 0;
        fovpt__sub3(t0, uy, ux);
        f0 = 1.0f; f1 = -1.0f; /* signs at the ends (values: any of these signs) */
        for (it = 0; it < 48u && s1 - s0 > 1e-7f; ++it) {
            float wx[3], wy[3], tn, nn;
            /* regula falsi with the Illinois halving (first step: the midpoint) */
            sm = it ? (s0 * f1 - s1 * f0) / (f1 - f0) : 0.5f;
            if (!(sm > s0 && sm < s1)) sm = 0.5f * (s0 + s1);
            for (k = 0; k < 3; ++k) n[k] = (1.0f - sm) * ux[k] + sm * uy[k];
            nn = fov__normalize(n);
            if (!(nn > 0.0f)) return 0;
            fovpt__madd3(p, mp->a, R, n);
            fovpt__sub3(wx, x, p);
            fovpt__sub3(wy, y, p);
            if (!(fov__normalize(wx) > 0.0f) || !(fov__normalize(wy) > 0.0f)) return 0;
            tn = fov__dot(t0, n);
            ct = fov__dot(wx, n);
            fm = fov__dot(wx, t0) + fov__dot(wy, t0) - tn * (ct + fov__dot(wy, n));
            if (!fov__finite(fm)) return 0;
            /* the sines' residual: about 1e-6 rad where the incidence is steep, less than
               that near grazing, where the sine's slope is cos t */
            if (fov__absf(fm) <= 1e-6f * fov__len(t0) * fov__maxf(fov__absf(ct), 1e-3f)) break;
            if (fm > 0.0f) { s0 = sm; f0 = fm; if (side > 0) f1 *= 0.5f; side = 1; }
                else { s1 = sm; f1 = fm; if (side < 0) f0 *= 0.5f; side = -1; }
        }
        fovpt__sub3(vx, x, p);
        fovpt__sub3(vy, y, p);
        d1 = fov__normalize(vx);
        d2 = fov__normalize(vy);
        ct = fov__dot(vx, n);
        if (!(ct > 1e-6f && fov__dot(vy, n) > 1e-6f && d1 > 0.0f && d2 > 0.0f)) return 0;
        *g = fovpt__mirror_g(R, d1, d2, ct);
        return fov__finite(*g) && *g > 0.0f;
    }
}
/* whether hit h is one that fovpt__mirror_point finds: a mirror quad, or a
   mirror sphere reached from outside (ray direction d) */
FOVPT__PRIV int fovpt__mirror_target(const fovpt_scene *s, const fovpt_hit *h, const float d[3])
{
    const fovpt__prim *p = (const fovpt__prim *)s->prims + h->slot;
    return fovpt__mirror_kind(p->type, &s->materials[h->material]) &&
           (p->type == FOVPT_SHAPE_QUAD || fov__dot(h->n, d) < 0.0f);
}
/* cfg.mirror_nee at a Lambert or Phong vertex x (normal nx, outgoing wo): one light point
   seen through one mirror (picked uniformly), both segments tested for occlusion; adds
   beta f cos albedo_mirror emission g cos_y / (pdf_mirror pdf_area) to L */
FOVPT__PRIV void fovpt__mirror_nee(const fovpt_scene *s, const fovpt_material *m, const float x[3],
                                   const float nx[3], const float wo[3], const float beta[3],
                                   fovpt_rng *rng, float L[3], fovpt_stats *st)
{
    const fovpt__prim *pr = (const fovpt__prim *)s->prims, *mp, *lp;
    float u = fovpt_rng_next(rng), y[3], ny[3], p[3], n[3], g, wx[3], v[3], fcos[3], pb, d1, dv,
        cl, w, xo[3], po[3], sv[3];
    uint32_t j = (uint32_t)(u * (float)s->num_mirrors), li, k;
    if (j >= s->num_mirrors) j = s->num_mirrors - 1u;
    mp = pr + s->mirrors[j];
    li = fovpt__light_sample(s, rng, y, ny);
    lp = pr + s->lights[li];
    if (lp == mp || !fovpt__mirror_point(mp, x, y, p, n, &g)) return;
    fovpt__sub3(wx, p, x);
    d1 = fov__normalize(wx);
    fovpt__sub3(v, y, p);
    dv = fov__len(v);
    if (!(d1 > 0.0f) || !(dv > 0.0f)) return;
    cl = fov__absf(fov__dot(ny, v)) / dv;
    fovpt_bsdf_eval(m, nx, wo, wx, fcos, &pb);
    if (!(cl > 0.0f) || !(fcos[0] > 0.0f || fcos[1] > 0.0f || fcos[2] > 0.0f)) return;
    /* 1 / the solid-angle pdf at x, times the power heuristic against the BSDF's pdf pb */
    w = g * cl * s->light_area[li] * (float)s->num_mirrors / fovpt__light_pick_pdf(s, li);
    if (!fov__finite(w) || !(w > 0.0f)) return;
    w = w / (1.0f + pb * pb * w * w);
    fovpt__offset(x, nx, wx, xo);
    fovpt__sub3(sv, p, xo);
    st->shadow_rays++;
    if (fovpt_occluded(s, xo, sv, 0.0f, 1.0f - 1e-4f)) return;
    fovpt__offset(p, n, v, po);
    fovpt__sub3(sv, y, po);
    st->shadow_rays++;
    if (fovpt_occluded(s, po, sv, 0.0f, 1.0f - 1e-4f)) return;
    for (k = 0; k < 3; ++k)
        L[k] += beta[k] * fcos[k] * s->materials[mp->material].albedo[k] *
                s->materials[lp->material].emission[k] * w;
}

/* ---- the path tracer (Axblad 2020, Eq. 2.1, 3.4; one consistent estimator, see doc block) */
/* Kim et al. 2021, Table 1: attributes of a presample (this library has no textures: the
   texture flags never differ). */
typedef struct fovpt__attr {
    uint32_t poid, soid;    /* primitive ids; FOVPT_PRIM_NONE: no hit, no secondary ray */
    float pn[3], sn[3];     /* unit normals facing the incoming ray */
    uint32_t psc, ssc;      /* shadow rays found occluded at the hit */
    float pt;               /* distance of the primary hit (unit ray), -1: no hit */
    uint32_t pmat;          /* material of the primary hit (guide buffers) */
    float lc[3];            /* the part of the radiance the camera ray's specular chain
                               reaches (emission and background before the first bounce
                               that is not a delta; Whitted: all): ROBUST PIXEL ESTIMATE */
} fovpt__attr;
FOVPT__PRIV void fovpt__attr_hit(const fovpt_hit *h, const float d[3], uint32_t *oid, float n[3])
{
    float sg = fov__dot(h->n, d) > 0.0f ? -1.0f : 1.0f;
    *oid = h->prim;
    n[0] = sg * h->n[0]; n[1] = sg * h->n[1]; n[2] = sg * h->n[2];
}

FOVPT__PRIV void fovpt__path(const fovpt_scene *s, const fovpt_config *c, const float org[3],
                             const float dir[3], fovpt_rng *rng, float L[3], fovpt_stats *st,
                             fovpt__attr *at)
{
    float o[3], d[3], beta[3] = { 1.0f, 1.0f, 1.0f }, prev_pdf = 0.0f,
        prev_p[3] = { 0.0f, 0.0f, 0.0f };
    int prev_delta = 1, nee = !c->no_nee && s->num_lights > 0, sec = 0, chain = 1;
    /* cfg.mirror_nee: ms 1 after a vertex that sampled the lights through the mirrors, 2 when
       the path then reflected off one of them (the light it reaches next is counted there) */
    int mnee = nee && c->mirror_nee && s->num_mirrors > 0, ms = 0, drop;
    float m_pdf = 0.0f, m_d1 = 0.0f, m_ct = 0.0f, m_r = 0.0f; /* that bounce: pdf, mirror hit */
    uint32_t bounce, k;
    fovpt_hit h;
    fovpt__copy3(o, org);
    fovpt__copy3(d, dir);
    fov__normalize(d);
    L[0] = L[1] = L[2] = 0.0f;
    for (bounce = 0;; ++bounce) {
        const fovpt_material *m;
        float wo[3], wi[3], wgt[3], pdf;
        if (bounce) st->bounce_rays++;
        if (!fovpt__hit(s, o, d, 0.0f, FLT_MAX, &h, 0)) {
            for (k = 0; k < 3; ++k) L[k] += beta[k] * s->background[k];
            if (at && chain)
                for (k = 0; k < 3; ++k) at->lc[k] += beta[k] * s->background[k];
            break;
        }
        m = &s->materials[h.material];
        drop = ms == 2;
        ms = ms == 1 && h.slot != FOVPT_PRIM_USER && fovpt__mirror_target(s, &h, d)
                 ? 2
                 : 0;
        if (ms == 2) { /* what the light's weight needs (the sampled bounce's pdf is still x's) */
            const fovpt__prim *p = (const fovpt__prim *)s->prims + h.slot;
            m_pdf = prev_pdf;
            m_d1 = h.t;
            m_ct = fov__absf(fov__dot(d, h.n));
            m_r = p->type == FOVPT_SHAPE_SPHERE ? p->r : 0.0f;
        }
        if (at && bounce == 0) {
            fovpt__attr_hit(&h, d, &at->poid, at->pn);
            at->pt = h.t;
            at->pmat = h.material;
            sec = m->type == FOVPT_MAT_MIRROR || m->type == FOVPT_MAT_DIELECTRIC;
        } else if (at && bounce == 1 && sec) {
            fovpt__attr_hit(&h, d, &at->soid, at->sn);
        }
        if (fovpt__emissive(m)) {
            float w = 1.0f;
            if (drop && h.slot != FOVPT_PRIM_USER &&
                ((const fovpt__prim *)s->prims + h.slot)->light) {
                /* x -> mirror -> this light, which cfg.mirror_nee samples too: the power
                   heuristic against its pdf at x, (1 / M) pick / (area g cos_y) */
                const fovpt__prim *p = (const fovpt__prim *)s->prims + h.slot;
                float cy = fov__absf(fov__dot(d, h.n)),
                      pm = fovpt__light_pick_pdf(s, p->light - 1u) /
                           ((float)s->num_mirrors * s->light_area[p->light - 1u] *
                            fovpt__mirror_g(m_r, m_d1, h.t, m_ct) * cy);
                w = fov__finite(pm) ? m_pdf * m_pdf / (m_pdf * m_pdf + pm * pm) : 0.0f;
                if (!fov__finite(w)) w = 0.0f;
            } else if (nee && !prev_delta && h.slot != FOVPT_PRIM_USER) {
                const fovpt__prim *p = (const fovpt__prim *)s->prims + h.slot;
                if (p->light) { /* power heuristic against the light-sampling pdf */
                    float v[3], d2, cl, pl;
                    fovpt__sub3(v, h.p, prev_p);
                    d2 = fov__dot(v, v);
                    cl = fov__absf(fov__dot(h.n, v)) / FOV__SQRT(d2);
                    pl = cl > 0.0f
                             ? fovpt__light_pick_pdf(s, p->light - 1u) * d2 /
                                   (s->light_area[p->light - 1u] * cl)
                             : FLT_MAX;
                    w = fov__finite(pl)
                            ? prev_pdf * prev_pdf / (prev_pdf * prev_pdf + pl * pl)
                            : 0.0f;
                }
            }
            for (k = 0; k < 3; ++k) L[k] += beta[k] * m->emission[k] * w;
            if (at && chain)
                for (k = 0; k < 3; ++k) at->lc[k] += beta[k] * m->emission[k] * w;
        }
        if (bounce >= c->max_depth) break;
        wo[0] = -d[0]; wo[1] = -d[1]; wo[2] = -d[2];
        if (nee && (m->type == FOVPT_MAT_LAMBERT || m->type == FOVPT_MAT_PHONG)) {
            float y[3], ny[3], v[3], d2, dist, cl, fcos[3], pb, xo[3];
            uint32_t li = fovpt__light_sample(s, rng, y, ny);
            const fovpt__prim *lp = (const fovpt__prim *)s->prims + s->lights[li];
            fovpt__sub3(v, y, h.p);
            d2 = fov__dot(v, v);
            dist = FOV__SQRT(d2);
            if (dist > 0.0f) {
                float vu[3];
                vu[0] = v[0] / dist; vu[1] = v[1] / dist; vu[2] = v[2] / dist;
                cl = fov__absf(fov__dot(ny, vu));
                fovpt_bsdf_eval(m, h.n, wo, vu, fcos, &pb);
                if (cl > 0.0f && (fcos[0] > 0.0f || fcos[1] > 0.0f || fcos[2] > 0.0f)) {
                    float sv[3];
                    fovpt__offset(h.p, h.n, vu, xo);
                    fovpt__sub3(sv, y, xo);
                    st->shadow_rays++;
                    if (!fovpt_occluded(s, xo, sv, 0.0f, 1.0f - 1e-4f)) {
                        const fovpt_material *lm = &s->materials[lp->material];
                        float pl = fovpt__light_pick_pdf(s, li) * d2 / (s->light_area[li] * cl);
                        float w = pl * pl / (pl * pl + pb * pb);
                        if (fov__finite(pl) && pl > 0.0f)
                            for (k = 0; k < 3; ++k)
                                L[k] += beta[k] * fcos[k] * lm->emission[k] * w / pl;
                    } else if (at) {
                        if (bounce == 0) at->psc++;
                        else if (bounce == 1 && sec) at->ssc++;
                    }
                }
            }
            if (mnee && bounce + 1u < c->max_depth) {
                fovpt__mirror_nee(s, m, h.p, h.n, wo, beta, rng, L, st);
                ms = 1;
            }
        }
        if (!fovpt_bsdf_sample(m, h.n, wo, rng, wi, wgt, &pdf)) break;
        for (k = 0; k < 3; ++k) beta[k] *= wgt[k];
        prev_pdf = pdf;
        prev_delta = !(pdf > 0.0f);
        if (!prev_delta) chain = 0;
        fovpt__copy3(prev_p, h.p);
        if (!(fovpt__max3(beta) > 0.0f)) break; /* zero throughput (Axblad 2020) */
        if (c->rr_start != FOVPT_RR_OFF && bounce + 1u >= c->rr_start) {
            float q = fov__clampf(fovpt__max3(beta), 0.05f, 1.0f);
            if (fovpt_rng_next(rng) >= q) break;
            for (k = 0; k < 3; ++k) beta[k] /= q;
        }
        fovpt__offset(h.p, h.n, wi, o);
        fovpt__copy3(d, wi);
    }
}

/* ---- the Whitted-style tracer (Kim et al. 2021; choices in the doc block) --------------- */
FOVPT__PRIV void fovpt__whitted(const fovpt_scene *s, const fovpt_config *c, const float org[3],
                                const float dir[3], float L[3], fovpt_stats *st, fovpt__attr *at)
{
    int sec_done = 0;
    typedef struct { float o[3], d[3], w[3]; uint32_t depth; } branch;
    branch stack[2u * FOVPT_MAX_WHITTED + 2u];
    uint32_t sp = 0, k, li;
    fovpt_hit h;
    L[0] = L[1] = L[2] = 0.0f;
    fovpt__copy3(stack[0].o, org);
    fovpt__copy3(stack[0].d, dir);
    fov__normalize(stack[0].d);
    stack[0].w[0] = stack[0].w[1] = stack[0].w[2] = 1.0f;
    stack[0].depth = 0;
    sp = 1;
    while (sp > 0) {
        branch b = stack[--sp];
        const fovpt_material *m;
        float wo[3];
        if (b.depth) st->bounce_rays++;
        if (!fovpt__hit(s, b.o, b.d, 0.0f, FLT_MAX, &h, 0)) {
            for (k = 0; k < 3; ++k) L[k] += b.w[k] * s->background[k];
            if (b.depth == 1) sec_done = 1;
            continue;
        }
        m = &s->materials[h.material];
        if (at && b.depth == 0) {
            fovpt__attr_hit(&h, b.d, &at->poid, at->pn);
            at->pt = h.t;
            at->pmat = h.material;
        }
        if (at && b.depth == 1 && !sec_done) fovpt__attr_hit(&h, b.d, &at->soid, at->sn);
        for (k = 0; k < 3; ++k) L[k] += b.w[k] * m->emission[k];
        wo[0] = -b.d[0]; wo[1] = -b.d[1]; wo[2] = -b.d[2];
        if (m->type == FOVPT_MAT_LAMBERT || m->type == FOVPT_MAT_PHONG) {
            for (k = 0; k < 3; ++k) L[k] += b.w[k] * m->albedo[k] * s->background[k]; /* ambient */
            for (li = 0; li < s->num_lights; ++li) {
                const fovpt__prim *lp = (const fovpt__prim *)s->prims + s->lights[li];
                const fovpt_material *lm = &s->materials[lp->material];
                float y[3], v[3], d2, dist, vu[3], g, fcos[3], pb, xo[3], sv[3];
                if (lp->type == FOVPT_SHAPE_SPHERE) {
                    float cx[3], dc;
                    fovpt__sub3(cx, h.p, lp->a);
                    dc = fov__normalize(cx);
                    if (!(dc > lp->r)) continue; /* inside the light */
                    fovpt__madd3(y, lp->a, lp->r, cx);
                    g = FOV__PI * lp->r * lp->r / (dc * dc);
                } else {
                    if (lp->type == FOVPT_SHAPE_QUAD) {
                        fovpt__madd3(y, lp->a, 0.5f, lp->b); fovpt__madd3(y, y, 0.5f, lp->c);
                    } else {
                        fovpt__madd3(y, lp->a, 1.0f / 3.0f, lp->b);
                        fovpt__madd3(y, y, 1.0f / 3.0f, lp->c);
                    }
                    g = -1.0f;
                }
                fovpt__sub3(v, y, h.p);
                d2 = fov__dot(v, v);
                dist = FOV__SQRT(d2);
                if (!(dist > 0.0f)) continue;
                vu[0] = v[0] / dist; vu[1] = v[1] / dist; vu[2] = v[2] / dist;
                if (g < 0.0f) g = s->light_area[li] * fov__absf(fov__dot(lp->n, vu)) / d2;
                fovpt_bsdf_eval(m, h.n, wo, vu, fcos, &pb);
                if (!(fcos[0] > 0.0f || fcos[1] > 0.0f || fcos[2] > 0.0f) || !(g > 0.0f)) continue;
                fovpt__offset(h.p, h.n, vu, xo);
                fovpt__sub3(sv, y, xo);
                st->shadow_rays++;
                if (fovpt_occluded(s, xo, sv, 0.0f, 1.0f - 1e-4f)) {
                    if (at && b.depth == 0) at->psc++;
                    if (at && b.depth == 1 && !sec_done) at->ssc++;
                    continue;
                }
                for (k = 0; k < 3; ++k) L[k] += b.w[k] * fcos[k] * lm->emission[k] * g;
            }
            if (b.depth == 1) sec_done = 1;
            continue;
        }
        if (b.depth == 1) sec_done = 1;
        if (b.depth >= c->max_depth) continue;
        if (m->type == FOVPT_MAT_MIRROR) {
            branch *nb = &stack[sp++];
            fovpt__reflect(h.n, wo, nb->d);
            fovpt__offset(h.p, h.n, nb->d, nb->o);
            for (k = 0; k < 3; ++k) nb->w[k] = b.w[k] * m->albedo[k];
            nb->depth = b.depth + 1u;
        } else if (m->type == FOVPT_MAT_DIELECTRIC) {
            float ci = fov__dot(h.n, wo), nn[3], n1, n2, cost, F;
            branch *nb;
            if (ci > 0.0f) { fovpt__copy3(nn, h.n); n1 = 1.0f; n2 = m->ior; }
            else {
                nn[0] = -h.n[0]; nn[1] = -h.n[1]; nn[2] = -h.n[2]; n1 = m->ior; n2 = 1.0f; ci = -ci;
            }
            F = fovpt__fresnel(ci, n1, n2, &cost);
            nb = &stack[sp++];
            fovpt__reflect(nn, wo, nb->d);
            fovpt__offset(h.p, h.n, nb->d, nb->o);
            for (k = 0; k < 3; ++k) nb->w[k] = b.w[k] * m->albedo[k] * F;
            nb->depth = b.depth + 1u;
            if (F < 1.0f) {
                float eta = n1 / n2;
                nb = &stack[sp++];
                for (k = 0; k < 3; ++k) nb->d[k] = -eta * wo[k] + (eta * ci - cost) * nn[k];
                fov__normalize(nb->d);
                fovpt__offset(h.p, h.n, nb->d, nb->o);
                for (k = 0; k < 3; ++k) nb->w[k] = b.w[k] * m->albedo[k] * (1.0f - F);
                nb->depth = b.depth + 1u;
            }
        }
        FOV_ASSERT(sp <= 2u * FOVPT_MAX_WHITTED + 2u);
    }
}

FOVPT__PRIV fov_result fovpt__radiance(const fovpt_scene *s, const fovpt_config *c,
                                       const float org[3], const float dir[3], fovpt_rng *rng,
                                       float rgb[3], fovpt_stats *stats, fovpt__attr *at);
FOVPT_API fov_result fovpt_radiance(const fovpt_scene *s, const fovpt_config *c, const float org[3],
                                    const float dir[3], fovpt_rng *rng, float rgb[3],
                                    fovpt_stats *stats)
{
    uint64_t before = stats ? stats->bounce_rays + stats->shadow_rays : 0u;
    fov_result r = fovpt__radiance(s, c, org, dir, rng, rgb, stats, NULL);
    if (stats) stats->rays += stats->bounce_rays + stats->shadow_rays - before;
    return r;
}
FOVPT__PRIV fov_result fovpt__radiance(const fovpt_scene *s, const fovpt_config *c,
                                       const float org[3], const float dir[3], fovpt_rng *rng,
                                       float rgb[3], fovpt_stats *stats, fovpt__attr *at)
{
    fovpt_stats local;
    fovpt_stats *st = stats ? stats : &local;
    if (at) {
        FOV_MEMSET(at, 0, sizeof *at);
        at->poid = at->soid = FOVPT_PRIM_NONE;
        at->pt = -1.0f;
    }
    if (!c) return FOV_ERR_NULL;
    if (!s || !org || !dir || !rng || !rgb)
        FOVPT__FAIL(&c->logger, FOV_ERR_NULL, "radiance: s, org, dir, rng and rgb are required");
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    if (!s->prims && !s->user_hit && s->num_prims)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "radiance: scene not built (call fovpt_scene_build)");
    if (!fov__finite3(org))
        FOVPT__FAIL(&c->logger, FOV_ERR_NOT_FINITE, "radiance: org NaN or infinite");
    if (!fov__finite3(dir))
        FOVPT__FAIL(&c->logger, FOV_ERR_NOT_FINITE, "radiance: dir NaN or infinite");
    if (!(fov__dot(dir, dir) > 0.0f))
        FOVPT__FAIL(&c->logger, FOV_ERR_DEGENERATE, "radiance: dir is zero");
    if (c->mode >= (uint32_t)_FOVPT_MODE_NUM)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "radiance: c.mode unknown (see fovpt_mode)");
    if (c->max_depth > FOVPT_MAX_BOUNCES)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "radiance: c.max_depth above FOVPT_MAX_BOUNCES");
    if (c->mode == FOVPT_MODE_WHITTED && c->max_depth > FOVPT_MAX_WHITTED)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "radiance: c.max_depth above FOVPT_MAX_WHITTED");
    if (c->mode == FOVPT_MODE_WHITTED) fovpt__whitted(s, c, org, dir, rgb, st, at);
    else fovpt__path(s, c, org, dir, rng, rgb, st, at);
    if (!fov__finite3(rgb)) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        st->bad_samples++;
    } else { /* finite but huge (an emission near FLT_MAX): sums of samples stay finite */
        uint32_t k;
        for (k = 0; k < 3; ++k) rgb[k] = fov__minf(rgb[k], (float)FOVPT_MAX_RADIANCE);
    }
    if (at) { /* the chain's part, within the sample's final value: Whitted all of it (no
                 random numbers along the ray), a path its chain's terms, 0 where NaN and at
                 most the value (0 where a non-finite sample was dropped, the cap above) */
        uint32_t k;
        for (k = 0; k < 3; ++k)
            at->lc[k] = c->mode == FOVPT_MODE_WHITTED ? rgb[k]
                      : at->lc[k] > 0.0f ? fov__minf(at->lc[k], rgb[k]) : 0.0f;
    }
    return FOV_OK;
}

/* ROBUST PIXEL ESTIMATE: the group count for spp samples (0: the plain mean), the group of
   sample s, and the estimate as a sum over the spp samples: the specular chains' sum lc
   (what the eye sees directly or through mirrors and glass: a light's or a mirrored light's
   anti-aliased edge is coverage, not a firefly) plus, from the groups' sums gs[0 .. g-1] of
   the rest, the median group's mean times spp where the group means' Gini coefficient is
   above FOVPT_ROBUST_GINI, else the sum of the groups' sums. fovpt__robust_add splits a
   sample. 32-bit integers only (no compiler helpers on 32-bit targets): (g + 1) spp stays
   below 2^32 because a count of spp above (2^32 - 1) / (FOVPT_ROBUST_MAX + 1) takes the plain
   mean (a sample count no frame reaches: FOVPT_MAX_SPP is 65536). */
FOVPT__PRIV uint32_t fovpt__robust_groups(uint32_t robust, uint32_t spp)
{
    uint32_t g = spp / (uint32_t)FOVPT_ROBUST_MIN_GROUP;
    if (robust < 3u || spp > 0xFFFFFFFFu / ((uint32_t)FOVPT_ROBUST_MAX + 1u)) return 0u;
    if (g > robust) g = robust;
    return g >= 3u ? g : 0u;
}
FOVPT__PRIV uint32_t fovpt__robust_group_of(uint32_t s, uint32_t g, uint32_t spp)
{
    return s * g / spp;
}
FOVPT__PRIV void fovpt__robust_add(float gs[][3], float lc[3], uint32_t g, uint32_t spp,
                                   uint32_t s, const float rgb[3], const float c[3])
{
    float *q = gs[fovpt__robust_group_of(s, g, spp)];
    uint32_t k;
    for (k = 0; k < 3; ++k) {
        lc[k] += c[k];
        q[k] += fov__maxf(rgb[k] - c[k], 0.0f);
    }
}
FOVPT__PRIV void fovpt__robust_sum(float gs[][3], const float lc[3], uint32_t g, uint32_t spp,
                                   float sum[3])
{
    float l[FOVPT_ROBUST_MAX], n[FOVPT_ROBUST_MAX], tot = 0.0f, gini = 0.0f;
    uint32_t ord[FOVPT_ROBUST_MAX], i, j, k, a, b;
    sum[0] = lc[0]; sum[1] = lc[1]; sum[2] = lc[2];
    for (i = 0; i < g; ++i) {
        /* group i: the samples s with floor(s g / spp) = i, from ceil(i spp / g) on */
        n[i] = (float)(((i + 1u) * spp + g - 1u) / g - (i * spp + g - 1u) / g);
        for (k = 0; k < 3; ++k) sum[k] += gs[i][k];
        l[i] = (0.2126f * gs[i][0] + 0.7152f * gs[i][1] + 0.0722f * gs[i][2]) / n[i];
        tot += l[i];
        for (j = i; j > 0 && l[ord[j - 1u]] > l[i]; --j) ord[j] = ord[j - 1u];
        ord[j] = i; /* ord: the groups by luminance, ascending (insertion) */
    }
    if (!(tot > 0.0f) || !(tot < FLT_MAX)) return;
    for (i = 0; i < g; ++i) gini += (float)(2 * (int32_t)i + 1 - (int32_t)g) * l[ord[i]];
    if (!(gini > FOVPT_ROBUST_GINI * (float)g * tot)) return;
    a = ord[(g - 1u) / 2u]; b = ord[g / 2u]; /* the median group (a = b for odd g) */
    for (k = 0; k < 3; ++k)
        sum[k] = lc[k] + 0.5f * (gs[a][k] / n[a] + gs[b][k] / n[b]) * (float)spp;
}

/* ---- shading image points (fovpt_shade_points: fovlp's log-polar samples) ------------------ */
FOVPT__PRIV fov_result fovpt__cam_fail(const fov_logger *lg, fov_result e, const char *who,
                                       uint32_t line);
FOVPT_API fov_result fovpt_shade_points(const fovpt_scene *s, const fovpt_config *c,
                                        const fovpt_camera *cam, uint32_t n, const float *xy,
                                        uint32_t stride, uint32_t first, uint32_t frame,
                                        uint32_t spp, float jitter, float *rgb, float *t,
                                        fovpt_stats *stats)
{
    float r[3], u[3], f[3], t4[4], o[3], hj;
    uint32_t i, k, W, H, rg;
    int bad;
    fovpt_stats st;
    fov_result e;
    if (!c) return FOV_ERR_NULL;
    if (!s || !cam || (n && (!xy || !rgb)))
        FOVPT__FAIL(&c->logger, FOV_ERR_NULL, "shade_points: scene, cam, xy and rgb are required");
    if (!s->prims && !s->user_hit && s->num_prims)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "shade_points: scene not built (call fovpt_scene_build)");
    if (c->mode >= (uint32_t)_FOVPT_MODE_NUM)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "shade_points: c.mode unknown (see fovpt_mode)");
    if (c->sampler >= (uint32_t)_FOVPT_SAMPLER_NUM)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "shade_points: c.sampler unknown (see fovpt_sampler)");
    if (c->robust == 1u || c->robust == 2u)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "shade_points: c.robust must be 0 or 3 .. FOVPT_ROBUST_MAX");
    if (c->robust > (uint32_t)FOVPT_ROBUST_MAX)
        FOVPT__FAIL(&c->logger, FOV_ERR_LIMIT, "shade_points: c.robust above FOVPT_ROBUST_MAX");
    if (c->mirror_nee > 1u)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "shade_points: c.mirror_nee must be 0 or 1");
    if (c->max_depth > FOVPT_MAX_BOUNCES ||
        (c->mode == FOVPT_MODE_WHITTED && c->max_depth > FOVPT_MAX_WHITTED))
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                    "shade_points: c.max_depth above FOVPT_MAX_BOUNCES (Whitted: "
                    "FOVPT_MAX_WHITTED)");
    if (stride == 0) stride = 2;
    if (stride < 2)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "shade_points: stride must be 0 or >= 2");
    if (!fov__finite(jitter))
        FOVPT__FAIL(&c->logger, FOV_ERR_NOT_FINITE, "shade_points: jitter NaN or infinite");
    if (jitter < 0.0f)
        FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG, "shade_points: jitter must be >= 0");
    hj = 0.5f * jitter;
    if (spp == 0) spp = c->spp ? c->spp : 1u;
    if (spp > FOVPT_MAX_SPP)
        FOVPT__FAIL(&c->logger, FOV_ERR_LIMIT, "shade_points: spp above FOVPT_MAX_SPP");
    /* the largest index read or written, (n - 1) max(stride, 3) + 2 floats, within size_t */
    if (n && (uint64_t)n * (stride > 3u ? stride : 3u) > (uint64_t)(SIZE_MAX / sizeof(float)))
        FOVPT__FAIL(&c->logger, FOV_ERR_LIMIT, "shade_points: n points overflow size_t");
    e = fovpt__camera_setup(cam, r, u, f, t4, o);
    if (e != FOV_OK) return fovpt__cam_fail(&c->logger, e, FOV__MSG("shade_points"), __LINE__);
    W = cam->width; H = cam->height;
    for (i = 0; i < n; ++i) { /* every point is checked before any work */
        float d[3], x = xy[(size_t)i * stride], y = xy[(size_t)i * stride + 1u];
        if (!fov__finite(x) || !fov__finite(y))
            FOVPT__FAIL(&c->logger, FOV_ERR_NOT_FINITE,
                        "shade_points: a point's x or y is NaN or infinite");
        /* a ray component f + sx r + sy u is monotone in x (through sx) and in y (through sy),
           rounding included, and a jittered x lies in [x - hj, x + hj] (y alike): over the
           square its extremes sit at corners, but which two depends on the signs of r and u
           (a rolled camera mixes sx and sy), so all four corners are checked */
        bad = !(fovpt__primary(r, u, f, t4, W, H, x, y, d) > 0.0f);
        for (k = 0; k < 4u && jitter > 0.0f && !bad; ++k)
            bad = !(fovpt__primary(r, u, f, t4, W, H, (k & 1u) ? x + hj : x - hj,
                                   (k & 2u) ? y + hj : y - hj, d) > 0.0f);
        if (bad)
            FOVPT__FAIL(&c->logger, FOV_ERR_INVALID_ARG,
                        "shade_points: a point so far off the image that its ray overflows");
    }
    FOV_MEMSET(&st, 0, sizeof st);
    rg = fovpt__robust_groups(c->robust, spp); /* ROBUST PIXEL ESTIMATE */
    for (i = 0; i < n; ++i) {
        float d[3], sum[3] = { 0.0f, 0.0f, 0.0f }, rs[FOVPT_ROBUST_MAX][3],
            rl[3] = { 0.0f, 0.0f, 0.0f };
        float x = xy[(size_t)i * stride], y = xy[(size_t)i * stride + 1u];
        if (!(jitter > 0.0f)) (void)fovpt__primary(r, u, f, t4, W, H, x, y, d);
        for (k = 0; k < rg; ++k) rs[k][0] = rs[k][1] = rs[k][2] = 0.0f;
        for (k = 0; k < spp; ++k) {
            fovpt_rng rng;
            fovpt__attr at;
            float c3[3];
            at.pt = -1.0f;
            fovpt__rng_start(&rng, c, first + i, k, frame);
            if (jitter > 0.0f) { /* a box filter of jitter pixels (UNIFORM's at 1) */
                float jx = fovpt_rng_next(&rng), jy = fovpt_rng_next(&rng);
                (void)fovpt__primary(r, u, f, t4, W, H, x + (jx - 0.5f) * jitter,
                                     y + (jy - 0.5f) * jitter, d);
            } else if (rng.sobol) { /* SAMPLERS: the pixel pair drawn and dropped */
                (void)fovpt_rng_next(&rng); (void)fovpt_rng_next(&rng);
            }
            (void)fovpt__radiance(s, c, o, d, &rng, c3, &st, (rg || (k == 0u && t)) ? &at : NULL);
            if (k == 0u && t) t[i] = at.pt >= 0.0f ? at.pt : FLT_MAX;
            if (rg) {
                fovpt__robust_add(rs, rl, rg, spp, k, c3, at.lc);
            } else {
                sum[0] += c3[0]; sum[1] += c3[1]; sum[2] += c3[2];
            }
        }
        if (rg) fovpt__robust_sum(rs, rl, rg, spp, sum);
        rgb[3u * (size_t)i] = sum[0] / (float)spp;
        rgb[3u * (size_t)i + 1u] = sum[1] / (float)spp;
        rgb[3u * (size_t)i + 2u] = sum[2] / (float)spp;
    }
    st.samples = (uint64_t)n * spp;
    st.camera_rays = st.samples;
    st.rays = st.camera_rays + st.bounce_rays + st.shadow_rays;
    if (stats) {
        stats->samples += st.samples; stats->camera_rays += st.camera_rays;
        stats->bounce_rays += st.bounce_rays; stats->shadow_rays += st.shadow_rays;
        stats->rays += st.rays; stats->bad_samples += st.bad_samples;
    }
    return FOV_OK;
}

/* ---- context and rendering ------------------------------------------------------------------- */
/* LAYERS: lattice grid size of layer n (covers the image for any gaze). */
FOVPT__PRIV uint64_t fovpt__grid_cells(uint32_t w, uint32_t h, uint32_t d)
{
    return (uint64_t)(w / d + 2u) * (uint64_t)(h / d + 2u);
}

/* The layer table a method uses: LAYERS its own; ZONES (Polychronakis 2025, ch. 4) three
   static full-frame lattices of stride 4, 2, 1 (1/16, 1/4, all of the pixels) with the zone radii
   (the blend width is set from the gaze's pixels per degree, fovpt__ctx_view). */
FOVPT__PRIV void fovpt__lay(const fovpt_config *c, fovpt_layers_cfg *o)
{
    if (c->method != FOVPT_METHOD_ZONES) { *o = c->layers; return; }
    FOV_MEMSET(o, 0, sizeof *o);
    o->count = 3;
    o->layer[0].stride = 4; o->layer[0].spp = c->zones.spp[2] ? c->zones.spp[2] : c->spp;
    o->layer[1].stride = 2; o->layer[1].spp = c->zones.spp[1] ? c->zones.spp[1] : c->spp;
    o->layer[1].radius_deg = c->zones.middle_deg;
    o->layer[2].stride = 1; o->layer[2].spp = c->zones.spp[0] ? c->zones.spp[0] : c->spp;
    o->layer[2].radius_deg = c->zones.inner_deg;
    o->blend_deg = 1.0f;
    o->blend_linear = 1; /* "we linearly interpolate a short overlapping boundary" */
    o->snap = 1;         /* full-frame buffers: lattices do not move with the gaze */
    o->bspline = c->zones.bspline; /* B-spline instead of Lanczos (reach 2 <= a cells) */
    o->hollow = c->zones.hollow;
    o->cell_jitter = c->zones.cell_jitter;
    o->clamp_white = c->zones.clamp_white;
}

/* temporal ring: the current frame plus n_tpi (smoothing) or 1 (reuse only) previous ones */
FOVPT__PRIV uint32_t fovpt__hist_slots(const fovpt_config *c)
{
    if (!c->temporal.reuse && !c->temporal.smooth) return 0;
    return (c->temporal.smooth ? c->temporal.n_tpi : 1u) + 1u;
}

FOVPT__PRIV fov_result fovpt__ctx_bytes(const fovpt_config *c, const fovpt_camera *cam,
                                        size_t *bytes)
{
    uint64_t px, total = 0;
    uint32_t n;
    const fov_logger *lg = &c->logger;
    if (c->method >= (uint32_t)_FOVPT_METHOD_NUM)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "memory_size: config.method unknown");
    if ((c->temporal.reuse || c->temporal.smooth) && c->method != FOVPT_METHOD_SELECTIVE &&
        c->method != FOVPT_METHOD_JIN)
        FOVPT__FAIL(lg, FOV_ERR_UNSUPPORTED,
                    "config.temporal: reuse and smooth need method SELECTIVE or JIN");
    px = (uint64_t)cam->width * cam->height;
    if (c->method == FOVPT_METHOD_UNIFORM) {
        total = (px * 16u + 15u) & ~(uint64_t)15u;
    } else if (c->method == FOVPT_METHOD_SELECTIVE || c->method == FOVPT_METHOD_JIN) {
        total = ((px * 16u + 15u) & ~(uint64_t)15u) + ((px * 52u + 15u) & ~(uint64_t)15u);
        total += (uint64_t)fovpt__hist_slots(c) * ((px * 32u + 15u) & ~(uint64_t)15u);
    } else {
        fovpt_layers_cfg lay;
        fovpt__lay(c, &lay);
        for (n = 0; n < lay.count; ++n)
            total += (fovpt__grid_cells(cam->width, cam->height, lay.layer[n].stride) * 16u + 15u) &
                     ~(uint64_t)15u;
    }
    if (total > (uint64_t)(SIZE_MAX / 2u))
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "memory_size: context memory overflows size_t");
    *bytes = (size_t)total;
    return FOV_OK;
}

/* Logs a fovpt__camera_setup failure as "<who>: <the rule its code stands for>". */
FOVPT__PRIV fov_result fovpt__cam_fail(const fov_logger *lg, fov_result e, const char *who,
                                       uint32_t line)
{
    const char *m = FOV__MSG(": cam.width or height 0, fov_y_deg not in (0, 180) or bad tan_*");
    if (e == FOV_ERR_LIMIT) m = FOV__MSG(": cam.width or height above FOVPT_MAX_DIM");
    if (e == FOV_ERR_NOT_FINITE) m = FOV__MSG(": a cam field NaN or infinite");
    if (e == FOV_ERR_UNSUPPORTED)
        m = FOV__MSG(": cam.tan_*: (tan_left + tan_right) / (tan_bottom + tan_top) must be "
                     "width / height within 1e-3 (non-square pixels are not supported)");
    if (e == FOV_ERR_DEGENERATE) m = FOV__MSG(": cam.target == pos, or up zero or along the view");
    return fov__err3(lg, "fovpt", e, who, m, "", line);
}

FOVPT_API fov_result fovpt_memory_size(const fovpt_config *cfg, const fovpt_camera *cam,
                                       size_t *bytes)
{
    fovpt_config c;
    float r[3], u[3], f[3], t4[4], o[3];
    fov_result e;
    if (!cfg) return FOV_ERR_NULL;
    if (!cam || !bytes)
        FOVPT__FAIL(&cfg->logger, FOV_ERR_NULL, "memory_size: cam and bytes are required");
    e = fovpt_config_resolve(cfg, &c);
    if (e != FOV_OK) return e;
    e = fovpt__camera_setup(cam, r, u, f, t4, o);
    if (e != FOV_OK) return fovpt__cam_fail(&c.logger, e, FOV__MSG("memory_size"), __LINE__);
    return fovpt__ctx_bytes(&c, cam, bytes);
}

FOVPT__PRIV void fovpt__make_view(const fovpt_ctx *ctx, fovpt_view *v)
{
    fovpt__copy3(v->pos, ctx->origin);
    fovpt__copy3(v->right, ctx->right); fovpt__copy3(v->up, ctx->up);
    fovpt__copy3(v->fwd, ctx->fwd);
    v->tan4[0] = ctx->tx0; v->tan4[1] = ctx->tx1; v->tan4[2] = ctx->ty0; v->tan4[3] = ctx->ty1;
}
/* The pixel of a view that sees world point p (0 when behind or off the image); its
   distance from the view's pinhole in *dist. */
FOVPT__PRIV int fovpt__project(const fovpt_view *v, uint32_t W, uint32_t H, const float p[3],
                               uint32_t *px, uint32_t *py, float *dist)
{
    float d[3], z, sx, sy, x, y;
    fovpt__sub3(d, p, v->pos);
    z = fov__dot(d, v->fwd);
    if (!(z > 0.0f)) return 0;
    sx = fov__dot(d, v->right) / z;
    sy = fov__dot(d, v->up) / z;
    x = (sx - v->tan4[0]) / (v->tan4[1] - v->tan4[0]) * (float)W;
    y = (sy - v->tan4[2]) / (v->tan4[3] - v->tan4[2]) * (float)H;
    if (!(x >= 0.0f && x < (float)W && y >= 0.0f && y < (float)H)) return 0;
    *px = (uint32_t)x;
    *py = (uint32_t)y;
    *dist = fov__len(d);
    return 1;
}

/* The eccentricity model of a camera: the display's, or the camera's own frustum; then the
   per-layer lattice origins and traced radii (LAYERS). */
/* The eccentricity model of a camera whose image-plane tangents t4 (x from t4[0] to t4[1], y
   from t4[2] at the top to t4[3]) fovpt__camera_setup gave: the display's when one is given,
   else the camera's own frustum, off-axis or not (fov_display: f = H / (t + b), the axis at
   the image point of tangent 0). */
FOVPT__PRIV fov_result fovpt__ecc_of(const fov_display *disp, const fovpt_camera *cam,
                                     const float t4[4], fov_gaze gaze, fov_ecc_model *m)
{
    fov_display d = *disp;
    int given = d.fov_y_deg > 0.0f || d.fov_y_deg < 0.0f || d.pixel_pitch_mm > 0.0f ||
                d.pixel_pitch_mm < 0.0f || d.distance_mm > 0.0f || d.distance_mm < 0.0f;
    if (!given) {
        /* the camera frustum: f = H / (ty0 - ty1); the axis at the image point of tangent 0 */
        float fpx = (float)cam->height / (t4[2] - t4[3]);
        d.fov_y_deg = 2.0f * FOV__ATAN2(0.5f * (float)cam->height, fpx) / FOV__DEG;
        d.axis_dx += -t4[0] * fpx - 0.5f * (float)cam->width;
        d.axis_dy += t4[2] * fpx - 0.5f * (float)cam->height;
    }
    return fovpt_ecc_init(m, &d, 60.0f, cam->width, cam->height, gaze);
}

FOVPT__PRIV fov_result fovpt__ctx_view(fovpt_ctx *ctx)
{
    const fovpt_camera *cam = &ctx->cam;
    fovpt_layers_cfg *L = &ctx->lay;
    fov_result e;
    uint32_t n;
    float t4[4];
    t4[0] = ctx->tx0; t4[1] = ctx->tx1; t4[2] = ctx->ty0; t4[3] = ctx->ty1;
    e = fovpt__ecc_of(&ctx->cfg.display, cam, t4, ctx->gaze, &ctx->ecc);
    if (e != FOV_OK) return e;
    if (ctx->cfg.method != FOVPT_METHOD_UNIFORM) {
        float gxf = fov__clampf(FOV__FLOOR(ctx->gaze.x), -1e9f, 1e9f),
            gyf = fov__clampf(FOV__FLOOR(ctx->gaze.y), -1e9f, 1e9f);
        /* 32-bit: no 64-bit division helpers on MCUs */
        int32_t gx = (int32_t)gxf, gy = (int32_t)gyf;
        float r0 = L->layer[0].radius_deg, to_deg = 1.0f / (ctx->ecc.f_px * FOV__DEG);
        if (ctx->cfg.method == FOVPT_METHOD_ZONES) /* overlap_px at the gaze, in degrees */
            L->blend_deg = ctx->cfg.zones.overlap_px / fov__maxf(fovpt_ecc_ppd(&ctx->ecc), 1e-6f);
        for (n = 0; n < L->count; ++n) {
            int32_t d_ = (int32_t)L->layer[n].stride, ox = 0, oy = 0;
            /* the filter's reach: 2 lattice cells (Catmull-Rom) or a (Lanczos), diagonally */
            float reach = ctx->lanczos ? (float)ctx->lanczos : 2.0f;
            float apron = (1.4142136f * reach * (float)L->layer[n].stride + 1.0f) * to_deg, tr;
            if (n > 0) {
                ox = ((gx % d_) + d_) % d_;
                oy = ((gy % d_) + d_) % d_;
                if (L->snap) ox = oy = 0;
                /* a stride wider than the image with the gaze off it could leave the layer
                   without a lattice point: keep at least one (column W - 1 / row H - 1) */
                if (ox > (int32_t)cam->width - 1) ox = (int32_t)cam->width - 1;
                if (oy > (int32_t)cam->height - 1) oy = (int32_t)cam->height - 1;
            }
            ctx->layer_ox[n] = (uint32_t)ox;
            ctx->layer_oy[n] = (uint32_t)oy;
            ctx->layer_nx[n] = (uint32_t)(((int32_t)cam->width - ox + d_ - 1) / d_);
            ctx->layer_ny[n] = (uint32_t)(((int32_t)cam->height - oy + d_ - 1) / d_);
            if (n == 0) tr = r0 > 0.0f ? r0 + apron : FLT_MAX;
            else {
                tr = L->layer[n].radius_deg + 0.5f * L->blend_deg + apron;
                if (r0 > 0.0f) tr = fov__minf(tr, r0 + apron);
            }
            ctx->layer_trace_deg[n] = tr;
            /* hollow: inside r_{n+1} - blend / 2 the finer layer n + 1 has full weight and
               layer n is never read; its filter reaches `apron` further in */
            ctx->layer_inner_deg[n] = -1.0f;
            if (L->hollow && n + 1u < L->count)
                ctx->layer_inner_deg[n] = L->layer[n + 1u].radius_deg - 0.5f * L->blend_deg - apron;
        }
    }
    return FOV_OK;
}

/* ---- acuity-driven configuration (fovpt_config_acuity) ---------------------------------- */

/* The eye's allowed sample spacing at ecc, in pixels of a display of ppd pixels per degree. */
FOVPT__PRIV float fovpt__allowed_px(const fov_eye *eye, float ppd, float ecc)
{
    return fovpt_eye_mar(eye, fov__clampf(ecc, 0.0f, 180.0f)) * ppd;
}

/* The share of an independent per-sample noise's variance that a normalised Gaussian of
   variance t2 (in units of the sample spacing squared) keeps: the sum of its squared weights
   over the lattice, 1 / (1 + 4 pi t2) (1 at t2 = 0; 1 / (4 pi t2), the continuous limit, for
   t2 >> 1; within 15 % of the discrete sums in between). */
FOVPT__PRIV float fovpt__keep(float t2) { return 1.0f / (1.0f + 12.566371f * t2); }

/* Lattice points a hollow table traces (fovpt__ctx_view's conditions, the gaze of m), counted
   on every u-th point of each axis (u = 1 up to 128 x 128 points) and scaled. */
FOVPT__PRIV float fovpt__traced(const fov_ecc_model *m, uint32_t W, uint32_t H, uint32_t d,
                                float lo, float hi)
{
    uint32_t u = 1, i, j, cnt = 0, ox, oy;
    int32_t gx = (int32_t)fov__clampf(FOV__FLOOR(m->gx), 0.0f, 1e9f),
        gy = (int32_t)fov__clampf(FOV__FLOOR(m->gy), 0.0f, 1e9f);
    while ((W / d) / u > 128u || (H / d) / u > 128u) ++u;
    ox = (uint32_t)(gx % (int32_t)d); oy = (uint32_t)(gy % (int32_t)d);
    for (j = oy; j < H; j += d * u)
        for (i = ox; i < W; i += d * u) {
            float e = fovpt_ecc_deg(m, (float)i + 0.5f, (float)j + 0.5f);
            if (e >= lo && e <= hi) ++cnt;
        }
    return (float)cnt * (float)u * (float)u;
}

/* Samples per traced pixel of a hollow foveated table (nl lattices, index 0 the outermost,
   stride d[n], full weight where r[n + 1] <= e < r[n], r[0] = FLT_MAX, r[nl] = 0; blend band
   blend degrees, filter reach `reach` lattice cells) for the eye-filtered noise (see
   ACUITY-DRIVEN CONFIGURATION, samples). m: the eccentricity model with the gaze at the image
   centre; mar1: the eye with quality 1 (its own blur); budget as cfg.acuity_budget. */
FOVPT__PRIV void fovpt__acuity_spp(const fov_ecc_model *m, uint32_t W, uint32_t H, float ppd,
                                   const fov_eye *mar1, uint32_t spp_u, float budget, uint32_t nl,
                                   const uint32_t *d, const float *r, float blend, float reach,
                                   uint32_t *spp)
{
    enum { G = 48 }; /* G x G image points for the bands' noise */
    float cu[FOVPT_MAX_LAYERS], cl[FOVPT_MAX_LAYERS], np[FOVPT_MAX_LAYERS], tp[FOVPT_MAX_LAYERS];
    float target, k, to_deg = 1.0f / (m->f_px * FOV__DEG);
    uint32_t i, j, n, it;
    for (n = 0; n < nl; ++n) cu[n] = cl[n] = np[n] = 0.0f;
    for (j = 0; j < G; ++j)
        for (i = 0; i < G; ++i) {
            float e = fovpt_ecc_deg(m, ((float)i + 0.5f) * (float)W / (float)G,
                                    ((float)j + 0.5f) * (float)H / (float)G), sg, dn, b2;
            for (n = nl - 1u; n > 0 && !(e < r[n]); --n) {}
            /* the eye filter's sigma (fovm_eye_filter: 0.3748 MAR), display pixels */
            sg = 0.3748f * fovpt_eye_mar(mar1, e) * ppd;
            dn = (float)d[n];
            /* the B-spline's variance 1/3 (+ the cell box's 1/12), cells^2 */
            b2 = d[n] >= 2u ? 1.0f / 3.0f : 0.0f;
            if (d[n] >= 2u && FOVPT_ACUITY_CELL_JITTER) b2 += 1.0f / 12.0f;
            cu[n] += fovpt__keep(sg * sg);
            cl[n] += fovpt__keep(b2 + sg * sg / (dn * dn));
            np[n] += 1.0f;
        }
    for (n = 0; n < nl; ++n) {
        float apron = (1.4142136f * reach * (float)d[n] + 1.0f) * to_deg;
        float hi = n ? r[n] + 0.5f * blend + apron : FLT_MAX;
        float lo = n + 1u < nl ? r[n + 1u] - 0.5f * blend - apron : -1.0f;
        tp[n] = fovpt__traced(m, W, H, d[n], lo, hi);
        if (np[n] > 0.0f) { cu[n] /= np[n]; cl[n] /= np[n]; }
        else { /* off the image (centred gaze): its inner edge stands for it */
            float e = n + 1u < nl ? r[n + 1u] : 0.0f, sg = 0.3748f * fovpt_eye_mar(mar1, e) * ppd;
            float dn = (float)d[n];
            float b2 = d[n] >= 2u ? 1.0f / 3.0f : 0.0f;
            if (d[n] >= 2u && FOVPT_ACUITY_CELL_JITTER) b2 += 1.0f / 12.0f;
            cu[n] = fovpt__keep(sg * sg);
            cl[n] = fovpt__keep(b2 + sg * sg / (dn * dn));
        }
    }
    if (!(budget > 0.0f)) {
        /* the band's mean filtered variance sigma^2 cl / spp_n at most UNIFORM's sigma^2 cu /
           spp_u: spp_n = spp_u cl / cu, times FOVPT_ACUITY_NOISE_MARGIN, rounded up with a
           slack of 0.01 sample (a ratio of 1 in float rounding stays spp_u, at any spp_u) */
        for (n = 0; n < nl; ++n) {
            float v = (float)spp_u * cl[n] / cu[n];
            if (d[n] >= 2u) v *= FOVPT_ACUITY_NOISE_MARGIN;
            v = -FOV__FLOOR(0.01f - v); /* ceil(v - 0.01) */
            spp[n] = (uint32_t)fov__clampf(v, 1.0f, (float)FOVPT_MAX_SPP);
        }
        return;
    }
    /* minimise the mean of (filtered variance)^FOVPT_ACUITY_GAMMA, sum_n N_n (cl_n / spp_n)^g,
       subject to sum_n T_n spp_n = budget W H spp_u (N_n: the band's pixels, T_n its traced
       points, about N_n / d_n^2): spp_n = k (d_n^2 cl_n^g)^(1 / (1 + g)); k from the counts,
       then refitted to the rounded spp (g = 1: the mean variance, spp ~ d sqrt(cl); g = 1/2:
       the mean standard deviation) */
    target = budget * (float)W * (float)H * (float)spp_u;
    {
        float w[FOVPT_MAX_LAYERS], tot = 0.0f, g = FOVPT_ACUITY_GAMMA;
        for (n = 0; n < nl; ++n) {
            w[n] = FOV__POW((float)(d[n] * d[n]) * FOV__POW(cl[n], g), 1.0f / (1.0f + g));
            tot += tp[n] * w[n];
        }
        k = tot > 0.0f ? target / tot : (float)spp_u;
        for (it = 0; it < 6; ++it) {
            float cost = 0.0f;
            for (n = 0; n < nl; ++n) {
                float v = FOV__FLOOR(k * w[n] + 0.5f);
                spp[n] = (uint32_t)fov__clampf(v, 1.0f, (float)FOVPT_MAX_SPP);
                cost += tp[n] * (float)spp[n];
            }
            if (!(cost > 0.0f)) break;
            k *= target / cost;
        }
    }
}

FOVPT_API fov_result fovpt_config_acuity(fovpt_config *cfg, const fovpt_camera *cam,
                                         const fov_eye *eye)
{
    /* The layer strides the table may use, finest first: Axblad 2020's 1, 2, 3, 4, then steps
       of at most 1.5 (a layer costs about its disk over its stride squared, and the disk grows
       with the next stride: small steps keep the sampling near the eye's allowed spacing).
       The first FOVPT_MAX_LAYERS entries at most. */
    static const uint8_t ladder[12] = { 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64 };
    uint32_t sel[FOVPT_MAX_LAYERS];
    float esel[FOVPT_MAX_LAYERS];
    fovpt_config c, out;
    const fov_logger *lg;
    fov_ecc_model m, mc;
    fov_eye_plan plan;
    fov_eye eye1;
    fov_gaze g;
    float r[3], u[3], f[3], t4[4], o[3], span, ppd, b, eps = 1e-3f;
    fov_result e;
    uint32_t i, n, nl, dmax;
    if (!cfg) return FOV_ERR_NULL;
    lg = &cfg->logger;
    if (!cam) FOVPT__FAIL(lg, FOV_ERR_NULL, "config_acuity: cam is NULL");
    e = fov__eye_check(lg, "fovpt", "config_acuity: ", eye);
    if (e != FOV_OK) return e;
    e = fovpt_config_resolve(cfg, &c); /* the defaults the computation starts from */
    if (e != FOV_OK) return e;
    e = fovpt__camera_setup(cam, r, u, f, t4, o);
    if (e != FOV_OK) return fovpt__cam_fail(lg, e, FOV__MSG("config_acuity"), __LINE__);
    /* the plan does not depend on the gaze (ppd at the eye's axis); the span is the largest
       eccentricity an on-screen gaze sees: the angle between opposite image corners */
    g.x = 0.0f; g.y = 0.0f;
    e = fovpt__ecc_of(&c.display, cam, t4, g, &m);
    if (e == FOV_OK) e = fovpt_eye_plan(eye, &m, &plan);
    if (e != FOV_OK)
        FOVPT__FAIL(lg, e, "config_acuity: config.display or the camera gives no eye distance");
    span = fovpt_ecc_deg(&m, (float)cam->width, (float)cam->height);
    g.x = (float)cam->width;
    e = fovpt__ecc_of(&c.display, cam, t4, g, &m);
    if (e != FOV_OK)
        FOVPT__FAIL(lg, e, "config_acuity: config.display or the camera gives no eye distance");
    span = fov__maxf(span, fovpt_ecc_deg(&m, 0.0f, (float)cam->height));
    ppd = plan.ppd;
    out = *cfg;

    /* LAYERS. The stride-s layer starts (its blend band's inner edge) where the eye's allowed
       spacing reaches s pixels, e(s) = fovpt_eye_ecc(eye, ppd, 1 / s): there s is the largest
       stride within the allowed spacing. The finer layer's radius is e(s) + blend / 2. Ladder
       strides up to the allowed spacing at the span (dmax). */
    b = c.layers.blend_deg;
    dmax = (uint32_t)fov__clampf(FOV__FLOOR(fovpt__allowed_px(eye, ppd, span)), 1.0f, 64.0f);
    /* sel: the strides used, finest first; a stride whose e(s) is that of the one before (0:
       the eye allows both at the gaze) replaces it, so the radii strictly decrease */
    sel[0] = 1; esel[0] = 0.0f;
    nl = 1;
    for (i = 1; i < 12u && ladder[i] <= dmax; ++i) {
        float es = fovpt_eye_ecc(eye, ppd, 1.0f / (float)ladder[i]);
        if (!(es + 0.5f * b + eps < 179.5f)) break;
        if (nl >= 2 && !(es > esel[nl - 1])) { sel[nl - 1] = ladder[i]; continue; }
        if (nl >= FOVPT_MAX_LAYERS) break;
        sel[nl] = ladder[i]; esel[nl] = es;
        ++nl;
    }
    FOV_MEMSET(out.layers.layer, 0, sizeof out.layers.layer);
    if (nl >= 2) {
        out.layers.count = nl;
        for (n = 0; n < nl; ++n) { /* layer n has sel[nl - 1 - n] (layer 0: the coarsest) */
            out.layers.layer[n].stride = sel[nl - 1u - n];
            if (n > 0) out.layers.layer[n].radius_deg = esel[nl - n] + 0.5f * b + eps;
        }
    } else {
        /* the display is coarser than the eye across the image: the stride-1 layer covers
           everything up to 179.5 degrees; the background (never on screen unless the blend
           band reaches it) takes the spacing allowed at its inner border */
        float ein = 179.5f - 0.5f * b;
        out.layers.count = 2;
        out.layers.layer[1].stride = 1;
        out.layers.layer[1].radius_deg = 179.5f;
        out.layers.layer[0].stride =
            (uint32_t)fov__clampf(FOV__FLOOR(fovpt__allowed_px(eye, ppd, ein)), 1.0f, 64.0f);
    }
    out.layers.layer[0].radius_deg = 0.0f; /* no occlusion mask */
    out.layers.bspline = 1u; /* the coarse layers' noise averaged (see LAYERS, bspline) */
    out.layers.hollow = 1u;  /* no layer traced under a finer one */
    out.layers.cell_jitter = FOVPT_ACUITY_CELL_JITTER; /* prefiltered lattice samples */
    out.layers.clamp_white = FOVPT_ACUITY_CLAMP_WHITE;  /* what the display shows */
    /* spp per layer from the eye-filtered noise (fovpt__acuity_spp), the gaze at the centre */
    g.x = 0.5f * (float)cam->width; g.y = 0.5f * (float)cam->height;
    e = fovpt__ecc_of(&c.display, cam, t4, g, &mc);
    if (e != FOV_OK)
        FOVPT__FAIL(lg, e, "config_acuity: config.display or the camera gives no eye distance");
    if (eye) eye1 = *eye;
    else FOV_MEMSET(&eye1, 0, sizeof eye1);
    eye1.quality = 1.0f;
    {
        uint32_t dd[FOVPT_MAX_LAYERS] = { 0 }, sp[FOVPT_MAX_LAYERS] = { 0 };
        float rr[FOVPT_MAX_LAYERS + 1];
        for (n = 0; n < out.layers.count; ++n) {
            dd[n] = out.layers.layer[n].stride;
            rr[n] = n ? out.layers.layer[n].radius_deg : FLT_MAX;
        }
        rr[out.layers.count] = 0.0f;
        fovpt__acuity_spp(&mc, cam->width, cam->height, ppd, &eye1, c.spp, c.acuity_budget,
                          out.layers.count, dd, rr, c.layers.blend_deg, 2.0f, sp);
        for (n = 0; n < out.layers.count; ++n) out.layers.layer[n].spp = sp[n];
    }

    /* ZONES. Density 1/4 (stride 2) is allowed from e_half, 1/16 (stride 4) from e_quarter;
       the coarser zone's weight starts half an overlap inside the border (overlap_px at the
       gaze, whose pixels per degree are at least the plan's: plan.ppd gives the wider band) */
    {
        float mz = 0.5f * c.zones.overlap_px / ppd + eps;
        float mid = fov__minf(plan.e_quarter + mz, 179.9f);
        uint32_t dd[3] = { 4u, 2u, 1u }, sp[3];
        float rr[4];
        out.zones.inner_deg = fov__minf(plan.e_half + mz, 0.999f * mid);
        out.zones.middle_deg = mid;
        out.zones.bspline = 1u;
        out.zones.hollow = 1u;
        out.zones.cell_jitter = FOVPT_ACUITY_CELL_JITTER;
        out.zones.clamp_white = FOVPT_ACUITY_CLAMP_WHITE;
        rr[0] = FLT_MAX; rr[1] = mid; rr[2] = out.zones.inner_deg; rr[3] = 0.0f;
        fovpt__acuity_spp(&mc, cam->width, cam->height, ppd, &eye1, c.spp, c.acuity_budget, 3u,
                          dd, rr, c.zones.overlap_px / fov__maxf(fovpt_ecc_ppd(&mc), 1e-6f),
                          (float)c.zones.lanczos_a, sp);
        out.zones.spp[0] = sp[2]; out.zones.spp[1] = sp[1]; out.zones.spp[2] = sp[0];
    }

    /* SELECTIVE. Kim et al. 2021's borders scaled by one factor k so that e_np (beyond it the
       presample only, one sample per pixel) falls at e_full (from there one sample per pixel is
       as fine as the eye resolves); the zones keep their proportions and tau_fov its shape
       (its slope tau'_f divided by k: the same curve of e / k) */
    {
        fovpt_selective_cfg *s = &out.selective;
        float k = fov__maxf(plan.e_full, 0.01f) / c.selective.e_deg[3];
        k = fov__minf(k, 179.0f / c.selective.e_deg[4]);
        /* a config this call filled scales by 1 up to float rounding: keep it as it is, so a
           second call changes nothing */
        if (k > 0.99999f && k < 1.00001f) k = 1.0f;
        for (i = 0; i < 5; ++i) s->e_deg[i] = c.selective.e_deg[i] * k;
        for (i = 0; i < 4; ++i) s->tau_shape[i] = c.selective.tau_shape[i];
        s->tau_shape[2] = c.selective.tau_shape[2] / k;
    }
    e = fovpt_config_resolve(&out, &c);
    if (e != FOV_OK)
        FOVPT__FAIL(lg, e, "config_acuity: the derived layers, zones or fields do not validate");
    cfg->layers = out.layers;
    cfg->zones.inner_deg = out.zones.inner_deg;
    cfg->zones.middle_deg = out.zones.middle_deg;
    cfg->zones.bspline = out.zones.bspline;
    cfg->zones.hollow = out.zones.hollow;
    cfg->zones.cell_jitter = out.zones.cell_jitter;
    cfg->zones.clamp_white = out.zones.clamp_white;
    for (i = 0; i < 3; ++i) cfg->zones.spp[i] = out.zones.spp[i];
    for (i = 0; i < 5; ++i) cfg->selective.e_deg[i] = out.selective.e_deg[i];
    for (i = 0; i < 4; ++i) cfg->selective.tau_shape[i] = out.selective.tau_shape[i];
    return FOV_OK;
}

FOVPT_API fov_result fovpt_init(fovpt_ctx *ctx, const fovpt_config *cfg, const fovpt_scene *scene,
                                const fovpt_camera *cam, fov_gaze gaze, void *mem, size_t bytes)
{
    fovpt_config c;
    float t4[4];
    size_t need;
    fov_result e;
    if (!cfg) return FOV_ERR_NULL;
    if (!ctx) FOVPT__FAIL(&cfg->logger, FOV_ERR_NULL, "init: ctx is NULL");
    if (!scene) FOVPT__FAIL(&cfg->logger, FOV_ERR_NULL, "init: scene is NULL");
    if (!cam) FOVPT__FAIL(&cfg->logger, FOV_ERR_NULL, "init: cam is NULL");
    e = fovpt_config_resolve(cfg, &c);
    if (e != FOV_OK) return e;
    if (!scene->prims && scene->num_prims)
        FOVPT__FAIL(&c.logger, FOV_ERR_INVALID_ARG,
                    "init: scene.prims NULL (call fovpt_scene_build)");
    if (!scene->materials)
        FOVPT__FAIL(&c.logger, FOV_ERR_INVALID_ARG,
                    "init: scene.materials NULL (call fovpt_scene_build)");
    FOV_MEMSET(ctx, 0, sizeof *ctx);
    e = fovpt__camera_setup(cam, ctx->right, ctx->up, ctx->fwd, t4, ctx->origin);
    if (e != FOV_OK) return fovpt__cam_fail(&c.logger, e, FOV__MSG("init"), __LINE__);
    if (!fov__finite(gaze.x) || !fov__finite(gaze.y))
        FOVPT__FAIL(&c.logger, FOV_ERR_NOT_FINITE, "init: gaze.x or gaze.y NaN or infinite");
    e = fovpt__ctx_bytes(&c, cam, &need);
    if (e != FOV_OK) return e;
    if (need > 0 && !mem) FOVPT__FAIL(&c.logger, FOV_ERR_NULL, "init: mem is NULL");
    if (bytes < need)
        FOVPT__FAIL(&c.logger, FOV_ERR_TOO_SMALL, "init: bytes below fovpt_memory_size");
    if (((uintptr_t)mem & 7u) != 0)
        FOVPT__FAIL(&c.logger, FOV_ERR_INVALID_ARG, "init: mem not 8-byte aligned");
    ctx->cfg = c;
    ctx->scene = scene;
    ctx->cam = *cam;
    ctx->gaze = gaze;
    ctx->tx0 = t4[0]; ctx->tx1 = t4[1]; ctx->ty0 = t4[2]; ctx->ty1 = t4[3];
    fovpt__lay(&c, &ctx->lay);
    ctx->lanczos = c.method == FOVPT_METHOD_ZONES ? c.zones.lanczos_a : 0u;
    e = fovpt__ctx_view(ctx);
    if (e != FOV_OK)
        FOVPT__FAIL(&c.logger, e, "init: gaze or config.display: the eye direction overflows");
    ctx->mem = mem;
    ctx->mem_size = bytes;
    if (c.method == FOVPT_METHOD_UNIFORM) {
        ctx->accum = (float *)mem;
    } else if (c.method == FOVPT_METHOD_SELECTIVE || c.method == FOVPT_METHOD_JIN) {
        size_t px = (size_t)cam->width * cam->height, off;
        uint32_t k;
        ctx->accum = (float *)mem;
        ctx->pre = (unsigned char *)mem + fov__align(px * 16u);
        off = fov__align(px * 16u) + fov__align(px * 52u);
        ctx->hist_slots = fovpt__hist_slots(&c);
        for (k = 0; k < ctx->hist_slots; ++k) {
            ctx->hist[k] = (float *)(void *)((unsigned char *)mem + off);
            off += fov__align(px * 32u);
        }
        fovpt__make_view(ctx, &ctx->hist_view[0]);
    } else {
        unsigned char *p = (unsigned char *)mem;
        uint32_t n;
        for (n = 0; n < ctx->lay.count; ++n) {
            ctx->layer_buf[n] = (float *)(void *)p;
            p += fov__align((size_t)fovpt__grid_cells(cam->width, cam->height,
                                                      ctx->lay.layer[n].stride) * 16u);
        }
    }
    return fovpt_reset(ctx);
}

FOVPT_API fov_result fovpt_set_gaze_margin(fovpt_ctx *ctx, const fovpt_config *base,
                                           float margin_deg)
{
    fovpt_config c;
    fovpt_layers_cfg lay;
    fov_result e;
    size_t need_old, need_new;
    uint32_t n;
    if (!ctx || !base) return FOV_ERR_NULL;
    e = fovpt_config_gaze_margin(base, margin_deg, &c);
    if (e != FOV_OK) return e;
    fovpt__lay(&c, &lay);
    if (fovpt__ctx_bytes(&ctx->cfg, &ctx->cam, &need_old) != FOV_OK ||
        fovpt__ctx_bytes(&c, &ctx->cam, &need_new) != FOV_OK || need_old != need_new ||
        c.method != ctx->cfg.method || lay.count != ctx->lay.count ||
        fovpt__hist_slots(&c) != ctx->hist_slots)
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "set_gaze_margin: base differs from the context's config beyond the radii "
                    "(method, layers, temporal slots): use fovpt_init");
    for (n = 0; n < lay.count; ++n)
        if (lay.layer[n].stride != ctx->lay.layer[n].stride)
            FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                        "set_gaze_margin: a layer stride differs from the context's: use "
                        "fovpt_init");
    {
        fovpt_config c0 = ctx->cfg;
        fovpt_layers_cfg l0 = ctx->lay;
        fov_ecc_model e0 = ctx->ecc;
        ctx->cfg = c;
        ctx->lay = lay;
        e = fovpt__ctx_view(ctx);
        if (e != FOV_OK) {
            ctx->cfg = c0; ctx->lay = l0; ctx->ecc = e0;
            fovpt__ctx_view(ctx); /* the old view again (it succeeded before) */
            FOVPT__FAIL(&ctx->cfg.logger, e, "set_gaze_margin: the view fails (unchanged)");
        }
    }
    return FOV_OK;
}

FOVPT_API fov_result fovpt_reset(fovpt_ctx *ctx)
{
    uint32_t n;
    if (!ctx) return FOV_ERR_NULL;
    ctx->hist_valid = 0;
    if (ctx->accum) FOV_MEMSET(ctx->accum, 0, (size_t)ctx->cam.width * ctx->cam.height * 16u);
    for (n = 0; n < FOVPT_MAX_LAYERS; ++n)
        if (ctx->layer_buf[n])
            FOV_MEMSET(ctx->layer_buf[n], 0,
                       (size_t)fovpt__grid_cells(ctx->cam.width, ctx->cam.height,
                                                 ctx->lay.layer[n].stride) * 16u);
    return FOV_OK;
}

FOVPT_API fov_result fovpt_set_view(fovpt_ctx *ctx, const fovpt_camera *cam, fov_gaze gaze)
{
    float r[3], u[3], f[3], t4[4], o[3];
    fov_result e;
    fovpt_camera old;
    int moved;
    if (!ctx) return FOV_ERR_NULL;
    if (!cam) FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "set_view: cam is NULL");
    e = fovpt__camera_setup(cam, r, u, f, t4, o);
    if (e != FOV_OK) return fovpt__cam_fail(&ctx->cfg.logger, e, FOV__MSG("set_view"), __LINE__);
    if (cam->width != ctx->cam.width || cam->height != ctx->cam.height)
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "set_view: cam.width or height differs from init's");
    if (!fov__finite(gaze.x) || !fov__finite(gaze.y))
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NOT_FINITE,
                    "set_view: gaze.x or gaze.y NaN or infinite");
    old = ctx->cam;
    moved = 0;
    {
        uint32_t k;
        for (k = 0; k < 3; ++k)
            if (old.pos[k] < cam->pos[k] || old.pos[k] > cam->pos[k] ||
                old.target[k] < cam->target[k] || old.target[k] > cam->target[k] ||
                old.up[k] < cam->up[k] || old.up[k] > cam->up[k])
                moved = 1;
        if (old.eye_offset < cam->eye_offset || old.eye_offset > cam->eye_offset) moved = 1;
        if (t4[0] < ctx->tx0 || t4[0] > ctx->tx0 || t4[2] < ctx->ty0 || t4[2] > ctx->ty0 ||
            t4[1] < ctx->tx1 || t4[1] > ctx->tx1 || t4[3] < ctx->ty1 || t4[3] > ctx->ty1)
            moved = 1;
        /* LAYERS: the lattices move with the gaze */
        if (ctx->cfg.method != FOVPT_METHOD_UNIFORM &&
            (gaze.x < ctx->gaze.x || gaze.x > ctx->gaze.x || gaze.y < ctx->gaze.y ||
             gaze.y > ctx->gaze.y))
            moved = 1;
    }
    {
        /* a failed call leaves the view as it was (fovpt__ctx_view fails, if at all, in
           fovpt_ecc_init, before it touches the layer tables) */
        fov_gaze g0 = ctx->gaze;
        fov_ecc_model ecc0 = ctx->ecc;
        float r0[3], u0[3], f0[3], o0[3], tt[4];
        fovpt__copy3(r0, ctx->right); fovpt__copy3(u0, ctx->up); fovpt__copy3(f0, ctx->fwd);
        fovpt__copy3(o0, ctx->origin);
        tt[0] = ctx->tx0; tt[1] = ctx->tx1; tt[2] = ctx->ty0; tt[3] = ctx->ty1;
        ctx->cam = *cam;
        ctx->gaze = gaze;
        fovpt__copy3(ctx->right, r); fovpt__copy3(ctx->up, u); fovpt__copy3(ctx->fwd, f);
        fovpt__copy3(ctx->origin, o);
        ctx->tx0 = t4[0]; ctx->tx1 = t4[1]; ctx->ty0 = t4[2]; ctx->ty1 = t4[3];
        e = fovpt__ctx_view(ctx);
        if (e != FOV_OK) {
            ctx->cam = old; ctx->gaze = g0; ctx->ecc = ecc0;
            fovpt__copy3(ctx->right, r0); fovpt__copy3(ctx->up, u0); fovpt__copy3(ctx->fwd, f0);
            fovpt__copy3(ctx->origin, o0);
            ctx->tx0 = tt[0]; ctx->tx1 = tt[1]; ctx->ty0 = tt[2]; ctx->ty1 = tt[3];
            FOVPT__FAIL(&ctx->cfg.logger, e,
                        "set_view: gaze or display geometry (the view is unchanged)");
        }
    }
    if (ctx->hist_slots) { /* the frame just rendered becomes history; nothing is reset */
        ctx->hist_cur = (ctx->hist_cur + 1u) % ctx->hist_slots;
        if (ctx->hist_valid + 1u < ctx->hist_slots) ctx->hist_valid++;
        fovpt__make_view(ctx, &ctx->hist_view[ctx->hist_cur]);
        return FOV_OK;
    }
    if (moved) return fovpt_reset(ctx);
    return FOV_OK;
}

/* SELECTIVE, JIN: a presample (48 bytes): colour reference, Kim et al. 2021 Table 1 attributes */
typedef struct fovpt__pre {
    float col[3];
    uint32_t poid, soid;
    float pn[3], sn[3];
    uint32_t sc;              /* primary shadow count | secondary << 16 */
    float t;                  /* primary hit distance, -1: no hit */
} fovpt__pre;

FOVPT__PRIV void fovpt__add_stats(fovpt_stats *d, fovpt_stats *s)
{
    uint32_t n;
    s->rays = s->camera_rays + s->bounce_rays + s->shadow_rays;
    if (!d) return;
    d->samples += s->samples; d->rays += s->rays; d->camera_rays += s->camera_rays;
    d->bounce_rays += s->bounce_rays; d->shadow_rays += s->shadow_rays;
    d->bad_samples += s->bad_samples;
    for (n = 0; n < FOVPT_MAX_LAYERS; ++n) {
        d->layer_targets[n] += s->layer_targets[n];
        d->layer_samples[n] += s->layer_samples[n];
    }
    for (n = 0; n < 4; ++n) {
        d->problematic[n] += s->problematic[n];
        d->extra_samples[n] += s->extra_samples[n];
    }
    d->reused += s->reused;
}

/* per-pixel first-hit guide sums (fovpt_trace_rows_guide) */
FOVPT__PRIV float fovpt__lum(const float c[3])
{
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

/* per-pixel guide sums over its samples */
typedef struct fovpt__gsum {
    float alb[3], nrm[3], dep, l1, l2;
    uint32_t n, hits;
    uint32_t dep_lo; /* 1: dep holds the distances times 2^-32 (their sum overflowed) */
} fovpt__gsum;

FOVPT__PRIV void fovpt__gsum_add(fovpt__gsum *G, const fovpt_scene *s, const fovpt__attr *at,
                                 const float rgb[3])
{
    float l = fovpt__lum(rgb);
    G->n++;
    G->l1 += l;
    G->l2 += l * l;
    if (at->poid == FOVPT_PRIM_NONE || !(at->pt > 0.0f)) return;
    G->hits++;
    if (G->dep_lo) {
        G->dep += at->pt * 2.3283064365386963e-10f;
    } else if (fov__finite(G->dep + at->pt)) {
        G->dep += at->pt;
    } else { /* distances near FLT_MAX (a camera 1e38 from a plane): their sum overflows, so
                from here on it is kept scaled by 2^-32 (exact for such sums); fovpt__gwrite
                scales the mean back */
        G->dep = G->dep * 2.3283064365386963e-10f + at->pt * 2.3283064365386963e-10f;
        G->dep_lo = 1u;
    }
    fovpt__madd3(G->nrm, G->nrm, 1.0f, at->pn);
    if (at->pmat < s->num_materials)
        fovpt__madd3(G->alb, G->alb, 1.0f, s->materials[at->pmat].albedo);
}

/* spp samples of pixel (x, y), jittered in the pixel (cell 1) or in the cell x cell pixels
   centred on it (cell > 1); returns their sum in sum[3]. white > 0: the samples in groups of
   `group`, each group's mean clamped per channel at white (clamp_white). G (may be NULL):
   the first-hit guide sums of the samples are added to it. */
FOVPT__PRIV void fovpt__pixel(fovpt_ctx *ctx, uint32_t frame, uint32_t x, uint32_t y, uint32_t spp,
                              uint32_t sample0, uint32_t cell, uint32_t group, float white,
                              float sum[3], fovpt__gsum *G, fovpt_stats *st)
{
    uint32_t s, k, W = ctx->cam.width, H = ctx->cam.height, ng = 0, rg;
    float t4[4], gs[3] = { 0.0f, 0.0f, 0.0f }, rs[FOVPT_ROBUST_MAX][3],
        rl[3] = { 0.0f, 0.0f, 0.0f };
    t4[0] = ctx->tx0; t4[1] = ctx->tx1; t4[2] = ctx->ty0; t4[3] = ctx->ty1;
    sum[0] = sum[1] = sum[2] = 0.0f;
    if (!(white > 0.0f) || group < 1u) group = 0;
    /* ROBUST PIXEL ESTIMATE: the samples' sums by group (not with clamp_white's groups) */
    rg = group ? 0u : fovpt__robust_groups(ctx->cfg.robust, spp);
    for (k = 0; k < rg; ++k) rs[k][0] = rs[k][1] = rs[k][2] = 0.0f;
    for (s = 0; s < spp; ++s) {
        fovpt_rng rng;
        float dir[3], rgb[3] = { 0.0f, 0.0f, 0.0f }, jx, jy;
        fovpt__rng_start(&rng, &ctx->cfg, y * W + x, sample0 + s, frame);
        jx = fovpt_rng_next(&rng); jy = fovpt_rng_next(&rng);
        if (cell > 1u) { /* the box of the lattice cell: a prefilter against aliasing */
            jx = 0.5f + (jx - 0.5f) * (float)cell;
            jy = 0.5f + (jy - 0.5f) * (float)cell;
        }
        fovpt__primary(ctx->right, ctx->up, ctx->fwd, t4, W, H, (float)x + jx, (float)y + jy, dir);
        st->camera_rays++;
        if (G || rg) { /* the guides' sums too (the same estimator and stream) */
            fovpt__attr at;
            (void)fovpt__radiance(ctx->scene, &ctx->cfg, ctx->origin, dir, &rng, rgb, st, &at);
            if (G) fovpt__gsum_add(G, ctx->scene, &at, rgb);
            if (rg) {
                fovpt__robust_add(rs, rl, rg, spp, s, rgb, at.lc);
                continue;
            }
        } else {
            (void)fovpt__radiance(ctx->scene, &ctx->cfg, ctx->origin, dir, &rng, rgb, st, NULL);
        }
        if (!group) { sum[0] += rgb[0]; sum[1] += rgb[1]; sum[2] += rgb[2]; continue; }
        gs[0] += rgb[0]; gs[1] += rgb[1]; gs[2] += rgb[2];
        if (++ng == group || s + 1u == spp) { /* a group's mean clamped at white, weight ng */
            float cap = white * (float)ng;
            for (k = 0; k < 3; ++k) sum[k] += fov__minf(gs[k], cap);
            gs[0] = gs[1] = gs[2] = 0.0f;
            ng = 0;
        }
    }
    if (rg) fovpt__robust_sum(rs, rl, rg, spp, sum);
    st->samples += spp;
}

FOVPT__PRIV void fovpt__store(float *acc, const float sum[3], uint32_t spp, uint32_t accumulate)
{
    if (accumulate) {
        acc[0] += sum[0]; acc[1] += sum[1]; acc[2] += sum[2]; acc[3] += (float)spp;
    } else {
        acc[0] = sum[0]; acc[1] = sum[1]; acc[2] = sum[2]; acc[3] = (float)spp;
    }
}

/* ---- SELECTIVE and JIN: subpixel inspection and multisampling (Kim et al. 2021, Sec. 4.6) */
/* Step 1 of the two-step test: the threshold of the most sensitive discordant attribute
   (Table 1), else tau_col. tau[]: col, poid, psn, psc, pte, soid, ssn, ssc, ste. */
FOVPT__PRIV float fovpt__tau_sel(const fovpt_selective_cfg *sc, const fovpt__pre *P,
                                 const fovpt__pre *const Q[3], float cos_tol)
{
    float m = FLT_MAX;
    uint32_t k;
    for (k = 0; k < 3; ++k) {
        const fovpt__pre *q = Q[k];
        if (P->poid != q->poid) m = fov__minf(m, sc->tau[1]);
        else if (P->poid != FOVPT_PRIM_NONE && fov__dot(P->pn, q->pn) < cos_tol)
            m = fov__minf(m, sc->tau[2]);
        if ((P->sc & 0xFFFFu) != (q->sc & 0xFFFFu)) m = fov__minf(m, sc->tau[3]);
        if (P->soid != q->soid) m = fov__minf(m, sc->tau[5]);
        else if (P->soid != FOVPT_PRIM_NONE && fov__dot(P->sn, q->sn) < cos_tol)
            m = fov__minf(m, sc->tau[6]);
        if ((P->sc >> 16) != (q->sc >> 16)) m = fov__minf(m, sc->tau[7]);
        /* texture flags (pte, ste): no textures, never discordant */
    }
    return m < FLT_MAX ? m : sc->tau[0];
}
/* Step 2: Mitchell's contrast (Imax - Imin) / (Imax + Imin) per channel over the pixel and
   its three neighbours against tau * (1.36, 1.02, 2.04) (= 3.4 x Mitchell's 0.4, 0.3, 0.6). */
FOVPT__PRIV int fovpt__contrast(const fovpt__pre *P, const fovpt__pre *const Q[3], float tau)
{
    static const float kc[3] = { 1.36f, 1.02f, 2.04f };
    uint32_t c, k;
    for (c = 0; c < 3; ++c) {
        float mx = P->col[c], mn = P->col[c];
        for (k = 0; k < 3; ++k) {
            mx = fov__maxf(mx, Q[k]->col[c]); mn = fov__minf(mn, Q[k]->col[c]);
        }
        if (mx + mn > 0.0f && (mx - mn) > tau * kc[c] * (mx + mn)) return 1;
    }
    return 0;
}

/* Kim et al. 2021, step 2 (Sec. 4.4): temporal pixel reuse test (conditions 1-5, see the doc
   block); on success the previous frame's colour in rgb and the reuse count in cur[7]. */
FOVPT__PRIV int fovpt__reuse(const fovpt_ctx *ctx, uint32_t x, uint32_t y, const fovpt__pre *P,
                             float rgb[3], float *cur)
{
    uint32_t W = ctx->cam.width, H = ctx->cam.height,
        prev = (ctx->hist_cur + ctx->hist_slots - 1u) % ctx->hist_slots, qx, qy;
    float dir[3], v[3], dist, t4[4], con;
    const float *q;
    const fovpt_temporal_cfg *tc = &ctx->cfg.temporal;
    uint32_t c;
    if (!(P->t > 0.0f)) return 0;                                         /* 2. p_cur hits */
    t4[0] = ctx->tx0; t4[1] = ctx->tx1; t4[2] = ctx->ty0; t4[3] = ctx->ty1;
    fovpt__primary(ctx->right, ctx->up, ctx->fwd, t4, W, H, (float)x + 0.5f, (float)y + 0.5f, dir);
    fovpt__madd3(v, ctx->origin, P->t, dir);
    if (!fovpt__project(&ctx->hist_view[prev], W, H, v, &qx, &qy, &dist)) return 0;
    q = ctx->hist[prev] + 8u * ((size_t)qy * W + qx);
    if (!(q[7] < (float)tc->n_reuse_max)) return 0;                        /* 1. reuse count */
    if (!(q[3] > 0.0f)) return 0;                                         /* 3. p_reuse hits */
    if (!(fov__absf(dist - q[3]) <= tc->eps_depth * q[3])) return 0;      /* 4. depth */
    for (c = 0; c < 3; ++c) {                                             /* 5. colour test */
        static const float kc[3] = { 1.36f, 1.02f, 2.04f };
        float mx = fov__maxf(P->col[c], q[4 + c]), mn = fov__minf(P->col[c], q[4 + c]);
        con = mx + mn > 0.0f ? (mx - mn) / (mx + mn) : 0.0f;
        if (con > tc->tau_reuse * ctx->cfg.selective.tau[0] * kc[c]) return 0;
    }
    fovpt__copy3(rgb, q);
    cur[7] = q[7] + 1.0f;
    return 1;
}

FOVPT_API fov_result fovpt_refine_rows(fovpt_ctx *ctx, uint32_t frame, uint32_t y0, uint32_t y1,
                                       fovpt_stats *stats)
{
    fovpt_stats st;
    uint32_t x, y, W, H, q;
    const fovpt_selective_cfg *sc;
    const fovpt__pre *pre;
    float cos_tol, t4[4];
    int jin;
    if (!ctx) return FOV_ERR_NULL;
    W = ctx->cam.width; H = ctx->cam.height;
    if (y0 > y1 || y1 > H)
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG, "refine_rows: needs y0 <= y1 <= height");
    if (!ctx->pre) return FOV_OK; /* nothing to refine for this method */
    FOV_MEMSET(&st, 0, sizeof st);
    sc = &ctx->cfg.selective;
    pre = (const fovpt__pre *)ctx->pre;
    jin = ctx->cfg.method == FOVPT_METHOD_JIN;
    cos_tol = FOV__COS(sc->normal_tol_deg * FOV__DEG);
    t4[0] = ctx->tx0; t4[1] = ctx->tx1; t4[2] = ctx->ty0; t4[3] = ctx->ty1;
    for (y = y0; y < y1; ++y) {
        for (x = 0; x < W; ++x) {
            const fovpt__pre *P = pre + ((size_t)y * W + x);
            float e = fovpt_ecc_deg(&ctx->ecc, (float)x + 0.5f, (float)y + 0.5f), tf = 1.0f,
                pix[3] = { 0.0f, 0.0f, 0.0f };
            uint32_t zone = 0, nsd = 4, mx, my;
            float *cur =
                ctx->hist_slots ? ctx->hist[ctx->hist_cur] + 8u * ((size_t)y * W + x) : NULL;
            if (cur) { /* the current frame's history record */
                fovpt__copy3(cur + 4, P->col);
                cur[3] = P->t;
                cur[7] = 0.0f;
            }
            if (!jin) {
                zone = e <= sc->e_deg[0] ? 0u : e <= sc->e_deg[1] ? 1u
                     : e <= sc->e_deg[2] ? 2u : e <= sc->e_deg[3] ? 3u : 4u;
                if (zone == 4u) { /* peripheral pixel region: the presample alone */
                    fovpt__store(ctx->accum + 4u * ((size_t)y * W + x), P->col, 1u,
                                 ctx->cfg.accumulate);
                    if (cur) fovpt__copy3(cur, P->col);
                    continue;
                }
            }
            if (cur && ctx->cfg.temporal.reuse && ctx->hist_valid > 0 &&
                fovpt__reuse(ctx, x, y, P, pix, cur)) {
                fovpt__store(ctx->accum + 4u * ((size_t)y * W + x), pix, 1u, ctx->cfg.accumulate);
                fovpt__copy3(cur, pix);
                st.reused++;
                continue;
            }
            if (!jin) {
                nsd = sc->n_sd[zone];
                (void)fovpt_tau_fov(sc, e, &tf);
            }
            /* stratum layout: m x m for a square count, else n columns x 1 row */
            mx = 1; while ((mx + 1u) * (mx + 1u) <= nsd) ++mx;
            if (mx * mx == nsd) my = mx; else { mx = nsd; my = 1; }
            for (q = 0; q < 4; ++q) { /* NW, NE, SW, SE */
                int32_t sx = (q & 1u) ? 1 : -1, sy = (q & 2u) ? 1 : -1;
                int32_t nxp = (int32_t)x + sx, nyp = (int32_t)y + sy;
                const fovpt__pre *Q[3];
                float sub[3] = { 0.0f, 0.0f, 0.0f };
                uint32_t k;
                if (nxp < 0 || nxp >= (int32_t)W) nxp = (int32_t)x;
                if (nyp < 0 || nyp >= (int32_t)H) nyp = (int32_t)y;
                Q[0] = pre + ((size_t)y * W + (uint32_t)nxp);
                Q[1] = pre + ((size_t)(uint32_t)nyp * W + x);
                Q[2] = pre + ((size_t)(uint32_t)nyp * W + (uint32_t)nxp);
                if (nsd > 0 && fovpt__contrast(P, Q, tf * fovpt__tau_sel(sc, P, Q, cos_tol))) {
                    uint32_t s2;
                    for (s2 = 0; s2 < nsd; ++s2) { /* stratified jittered samples in the subpixel */
                        fovpt_rng rng;
                        float dir[3], rgb[3] = { 0.0f, 0.0f, 0.0f }, u, v;
                        /* SOBOL: blocks aligned to 2^12 (SAMPLERS); RANDOM as before */
                        fovpt__rng_start(&rng, &ctx->cfg, y * W + x, fovpt__sobol(&ctx->cfg) ?
                                         ((q + 1u) << 12) + s2 : 1u + q * 4096u + s2, frame);
                        u = ((float)(s2 % mx) + fovpt_rng_next(&rng)) / (float)mx;
                        v = ((float)(s2 / mx) + fovpt_rng_next(&rng)) / (float)my;
                        fovpt__primary(ctx->right, ctx->up, ctx->fwd, t4, W, H,
                                       (float)x + 0.5f * (float)(q & 1u) + 0.5f * u,
                                       (float)y + 0.5f * (float)(q >> 1) + 0.5f * v, dir);
                        st.camera_rays++;
                        (void)fovpt__radiance(ctx->scene, &ctx->cfg, ctx->origin, dir, &rng, rgb,
                                              &st, NULL);
                        for (k = 0; k < 3; ++k) sub[k] += rgb[k];
                    }
                    for (k = 0; k < 3; ++k) sub[k] /= (float)nsd;
                    st.samples += nsd;
                    st.problematic[zone]++;
                    st.extra_samples[zone] += nsd;
                } else if (jin || sc->fill_centre) {
                    fovpt__copy3(sub, P->col); /* Jin et al.: the pixel-centre colour */
                } else { /* Kim et al. 2021, Fig. 2: bilinear from the 4 pixel centres */
                    for (k = 0; k < 3; ++k)
                        sub[k] = 0.5625f * P->col[k] + 0.1875f * (Q[0]->col[k] + Q[1]->col[k]) +
                            0.0625f * Q[2]->col[k];
                }
                for (k = 0; k < 3; ++k) pix[k] += 0.25f * sub[k];
            }
            fovpt__store(ctx->accum + 4u * ((size_t)y * W + x), pix, 1u, ctx->cfg.accumulate);
            if (cur) fovpt__copy3(cur, pix);
        }
    }
    fovpt__add_stats(stats, &st);
    return FOV_OK;
}

FOVPT__PRIV uint8_t fovpt__srgb8(float v)
{
    float e;
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    e = v <= 0.0031308f ? 12.92f * v : 1.055f * FOV__POW(v, 1.0f / 2.4f) - 0.055f;
    return (uint8_t)(e * 255.0f + 0.5f);
}

/* The Lanczos kernel L(x) = sinc(x) sinc(x / a) for |x| < a, else 0 (1 at |x| < 1e-6).
   The 2a weights of one axis at fraction f in [0, 1): w[i] = L(x), x = f + a - 1 - i, from
   three sines instead of 4a: sin(pi x) = (-1)^(a-1-i) sin(pi f), and sin(pi x / a) by the
   angle sum from sin and cos of pi f / a and the constants sin, cos(pi k / a). */
FOVPT__PRIV void fovpt__lanczos_axis(float f, int32_t a, float w[6])
{
    /* cos, sin of pi k / a for k = a - 1 - i, i = 0 .. 2a - 1 (a = 2: k = 1 .. -2;
       a = 3: k = 2 .. -3) */
    static const float c2[4] = { 0.0f, 1.0f, 0.0f, -1.0f }, s2[4] = { 1.0f, 0.0f, -1.0f, 0.0f };
    static const float c3[6] = { -0.5f, 0.5f, 1.0f, 0.5f, -0.5f, -1.0f },
                       s3[6] = { 0.8660254f, 0.8660254f, 0.0f, -0.8660254f, -0.8660254f, 0.0f };
    const float *ck = a == 2 ? c2 : c3, *sk = a == 2 ? s2 : s3, fa = (float)a;
    float sp = FOV__SIN(FOV__PI * f), u = FOV__PI * f / fa, su = FOV__SIN(u), cu = FOV__COS(u);
    int32_t i;
    for (i = 0; i < 2 * a; ++i) {
        float x = f + (float)(a - 1 - i), px = FOV__PI * x;
        if (fov__absf(x) < 1e-6f) { w[i] = 1.0f; continue; }
        if (fov__absf(x) >= fa) { w[i] = 0.0f; continue; }
        w[i] = fa * (((a - 1 - i) & 1) ? -sp : sp) * (su * ck[i] + cu * sk[i]) / (px * px);
    }
}
/* Uniform cubic B-spline weights of v0..v3 at t in [0, 1]: non-negative, sum 1; at t = 0
   (1, 4, 1) / 6 (an approximating, smoothing filter: the variance of independent noise on the
   lattice falls to 0.48 of it in one dimension, averaged over t, against 0.81 for Catmull-Rom). */
FOVPT__PRIV void fovpt__bspline(float t, float w[4])
{
    float u = 1.0f - t, t2 = t * t, t3 = t2 * t;
    w[0] = u * u * u / 6.0f;
    w[1] = (3.0f * t3 - 6.0f * t2 + 4.0f) / 6.0f;
    w[2] = (-3.0f * t3 + 3.0f * t2 + 3.0f * t + 1.0f) / 6.0f;
    w[3] = t3 / 6.0f;
}

/* LAYERS: layer n's value at pixel (x, y) by Catmull-Rom over its lattice (Axblad 2020,
   Eq. 3.17, Fig. 3.10: four horizontal interpolations, then one vertical), or the B-spline;
   0 when unavailable. The resolve sums through the column cache (fovpt__layer_value_cc) and
   calls this only for its bilinear fallback where a tap is not traced; ZONES' Lanczos taps
   (Polychronakis 2025, Sec. 4.2) are summed by the cache alone. */
FOVPT__PRIV int fovpt__layer_value(const fovpt_ctx *ctx, uint32_t n, uint32_t x, uint32_t y,
                                   float c[3])
{
    const float *buf = ctx->layer_buf[n];
    uint32_t d = ctx->lay.layer[n].stride, nx = ctx->layer_nx[n], ny = ctx->layer_ny[n];
    int32_t kx, ky, i, j, ok = 1;
    float fx, fy, wx[4], wy[4], acc[3] = { 0.0f, 0.0f, 0.0f };
    int32_t rx = (int32_t)x - (int32_t)ctx->layer_ox[n],
        ry = (int32_t)y - (int32_t)ctx->layer_oy[n];
    if (nx == 0 || ny == 0) return 0;   /* no lattice point (never, see fovpt__ctx_view) */
    kx = rx >= 0 ? rx / (int32_t)d : -(((-rx) + (int32_t)d - 1) / (int32_t)d);
    ky = ry >= 0 ? ry / (int32_t)d : -(((-ry) + (int32_t)d - 1) / (int32_t)d);
    fx = (float)(rx - kx * (int32_t)d) / (float)d;
    fy = (float)(ry - ky * (int32_t)d) / (float)d;
    if (ctx->lay.bspline && d >= 2) {
        fovpt__bspline(fx, wx);
        fovpt__bspline(fy, wy);
    } else {
        fovpt_catmull_rom(fx, wx);
        fovpt_catmull_rom(fy, wy);
    }
    for (j = 0; j < 4 && ok; ++j) {
        int32_t lj = ky - 1 + j;
        lj = lj < 0 ? 0 : (lj >= (int32_t)ny ? (int32_t)ny - 1 : lj);
        for (i = 0; i < 4; ++i) {
            int32_t ki = kx - 1 + i;
            const float *a;
            float w = wx[i] * wy[j];
            ki = ki < 0 ? 0 : (ki >= (int32_t)nx ? (int32_t)nx - 1 : ki);
            if (!(w > 0.0f || w < 0.0f)) continue; /* adds nothing (a lattice-aligned row) */
            a = buf + 4u * ((size_t)lj * nx + (size_t)ki);
            if (!(a[3] > 0.0f)) { ok = 0; break; }
            w /= a[3];
            acc[0] += w * a[0]; acc[1] += w * a[1]; acc[2] += w * a[2];
        }
    }
    if (!ok) { /* a neighbour is not traced: bilinear over the inner 2 x 2 that are */
        float ws = 0.0f;
        acc[0] = acc[1] = acc[2] = 0.0f;
        for (j = 0; j < 2; ++j)
            for (i = 0; i < 2; ++i) {
                int32_t ki = kx + i, lj = ky + j;
                const float *a;
                float w = (i ? fx : 1.0f - fx) * (j ? fy : 1.0f - fy);
                ki = ki < 0 ? 0 : (ki >= (int32_t)nx ? (int32_t)nx - 1 : ki);
                lj = lj < 0 ? 0 : (lj >= (int32_t)ny ? (int32_t)ny - 1 : lj);
                a = buf + 4u * ((size_t)lj * nx + (size_t)ki);
                if (!(a[3] > 0.0f) || !(w > 0.0f)) continue;
                ws += w;
                w /= a[3];
                acc[0] += w * a[0]; acc[1] += w * a[1]; acc[2] += w * a[2];
            }
        if (!(ws > 0.0f)) return 0;
        acc[0] /= ws; acc[1] /= ws; acc[2] /= ws;
    }
    c[0] = fov__maxf(acc[0], 0.0f); c[1] = fov__maxf(acc[1], 0.0f); c[2] = fov__maxf(acc[2], 0.0f);
    return 1;
}

/* The resolve's per-row cache of lattice columns. Both filters are separable: a pixel's value
   is sum_i wx[i] col(kx - 1 + i) with col(k) = sum_j wy[j] v(k, ky - 1 + j) (Lanczos: 2a
   taps, and the weights of the traced taps summed alike), so the stride d pixels between two
   lattice columns share the columns' vertical sums. Per layer: the row's vertical weights
   and FOVPT__CC columns (direct-mapped by index); v[3] is the column's weight sum (Lanczos)
   or 1 / 0 (Catmull-Rom, B-spline: every tap of non-zero weight traced, or not). */
#define FOVPT__CC 8
typedef struct fovpt__cc {
    uint32_t row;                 /* the pixel row the entries belong to; UINT32_MAX: none */
    int32_t ky;
    float wy[6];
    int32_t tag[FOVPT__CC];       /* the column index held, or INT32_MIN */
    float v[FOVPT__CC][4];
} fovpt__cc;

/* Layer n's value at pixel (x, y) through the cache cc: Catmull-Rom or B-spline (LAYERS,
   fovpt__layer_value's filter, summed column by column: equal up to rounding; where a tap
   is not traced, fovpt__layer_value's answer, its bilinear fallback), or for ZONES the
   Lanczos upsampling of Polychronakis 2025, Sec. 4.2: separable, 2a taps per axis,
   normalised, lattice points reproduced exactly, untraced taps dropped (weights
   renormalised), 0 when their weights sum to at most 0.05. */
FOVPT__PRIV int fovpt__layer_value_cc(const fovpt_ctx *ctx, uint32_t n, uint32_t x, uint32_t y,
                                      float c[3], fovpt__cc *cc)
{
    const float *buf = ctx->layer_buf[n];
    uint32_t d = ctx->lay.layer[n].stride, nx = ctx->layer_nx[n], ny = ctx->layer_ny[n], k;
    int lz = ctx->lanczos && !(ctx->lay.bspline && d >= 2), bs = ctx->lay.bspline && d >= 2;
    int32_t a = lz ? (int32_t)ctx->lanczos : 2, T = 2 * a, rx, kx, base, i, j;
    float fx, wx[6], acc[3] = { 0.0f, 0.0f, 0.0f }, ws = 0.0f;
    if (nx == 0 || ny == 0) return 0;
    if (cc->row != y) { /* a new row: its vertical weights, no column held */
        int32_t ry = (int32_t)y - (int32_t)ctx->layer_oy[n];
        float fy;
        cc->ky = ry >= 0 ? ry / (int32_t)d : -(((-ry) + (int32_t)d - 1) / (int32_t)d);
        fy = (float)(ry - cc->ky * (int32_t)d) / (float)d;
        if (lz) fovpt__lanczos_axis(fy, a, cc->wy);
        else if (bs) fovpt__bspline(fy, cc->wy);
        else fovpt_catmull_rom(fy, cc->wy);
        for (i = 0; i < FOVPT__CC; ++i) cc->tag[i] = INT32_MIN;
        cc->row = y;
    }
    rx = (int32_t)x - (int32_t)ctx->layer_ox[n];
    kx = rx >= 0 ? rx / (int32_t)d : -(((-rx) + (int32_t)d - 1) / (int32_t)d);
    fx = (float)(rx - kx * (int32_t)d) / (float)d;
    if (lz) fovpt__lanczos_axis(fx, a, wx);
    else if (bs) fovpt__bspline(fx, wx);
    else fovpt_catmull_rom(fx, wx);
    base = kx - a + 1;
    for (i = 0; i < T; ++i) {
        int32_t kk = base + i, slot = (int32_t)((uint32_t)kk & (FOVPT__CC - 1u));
        float *col = cc->v[slot];
        if (!(wx[i] > 0.0f || wx[i] < 0.0f)) continue;
        if (cc->tag[slot] != kk) { /* the column's vertical sum */
            int32_t ki = kk < 0 ? 0 : (kk >= (int32_t)nx ? (int32_t)nx - 1 : kk);
            int32_t jb = cc->ky - a + 1;
            col[0] = col[1] = col[2] = col[3] = 0.0f;
            for (j = 0; j < T; ++j) {
                int32_t lj = jb + j;
                const float *p;
                float w = cc->wy[j];
                if (!(w > 0.0f || w < 0.0f)) continue;
                lj = lj < 0 ? 0 : (lj >= (int32_t)ny ? (int32_t)ny - 1 : lj);
                p = buf + 4u * ((size_t)lj * nx + (size_t)ki);
                if (!(p[3] > 0.0f)) {
                    if (lz) continue;
                    col[3] = -1.0f; /* not traced */
                    break;
                }
                if (lz) col[3] += w;
                w /= p[3];
                col[0] += w * p[0]; col[1] += w * p[1]; col[2] += w * p[2];
            }
            if (!lz) col[3] = col[3] < 0.0f ? 0.0f : 1.0f;
            cc->tag[slot] = kk;
        }
        if (!lz && !(col[3] > 0.0f)) return fovpt__layer_value(ctx, n, x, y, c);
        for (k = 0; k < 3; ++k) acc[k] += wx[i] * col[k];
        ws += wx[i] * col[3];
    }
    if (lz) {
        if (!(ws > 0.05f)) return 0;
        for (k = 0; k < 3; ++k) acc[k] /= ws;
    }
    for (k = 0; k < 3; ++k) c[k] = fov__maxf(acc[k], 0.0f);
    return 1;
}

/* Axblad 2020, Eq. 3.18: blend weight of layer n at eccentricity e */
FOVPT__PRIV float fovpt__vb(const fovpt_layers_cfg *L, uint32_t n, float e)
{
    float t = (L->layer[n].radius_deg + 0.5f * L->blend_deg - e) / L->blend_deg;
    t = fov__clampf(t, 0.0f, 1.0f);
    return L->blend_linear ? t : t * t * (3.0f - 2.0f * t);
}

/* Kim et al. 2021, step 4 (Sec. 4.7): truncated exponential smoothing over the frames that
   see the same first hit (within eps_depth), weights alpha (1 - alpha)^i, alpha = fovpt_alpha(e);
   rejected frames drop out of the normalisation. */
FOVPT__PRIV void fovpt__smooth(const fovpt_ctx *ctx, uint32_t x, uint32_t y, float c[3])
{
    uint32_t W = ctx->cam.width, H = ctx->cam.height, i, k;
    const float *cur = ctx->hist[ctx->hist_cur] + 8u * ((size_t)y * W + x);
    float a, w, ws, acc[3], dir[3], v[3], t4[4];
    if (!(cur[3] > 0.0f) || ctx->hist_valid == 0) return; /* no first hit: nothing to follow */
    a = fovpt_alpha(&ctx->cfg.temporal, &ctx->cfg.selective,
                    fovpt_ecc_deg(&ctx->ecc, (float)x + 0.5f, (float)y + 0.5f));
    t4[0] = ctx->tx0; t4[1] = ctx->tx1; t4[2] = ctx->ty0; t4[3] = ctx->ty1;
    fovpt__primary(ctx->right, ctx->up, ctx->fwd, t4, W, H, (float)x + 0.5f, (float)y + 0.5f, dir);
    fovpt__madd3(v, ctx->origin, cur[3], dir);
    w = a;
    ws = a;
    for (k = 0; k < 3; ++k) acc[k] = a * c[k];
    for (i = 1; i <= ctx->hist_valid && i <= ctx->cfg.temporal.n_tpi; ++i) {
        uint32_t slot = (ctx->hist_cur + ctx->hist_slots - i) % ctx->hist_slots, qx, qy;
        float dist;
        const float *q;
        w *= 1.0f - a;
        if (!fovpt__project(&ctx->hist_view[slot], W, H, v, &qx, &qy, &dist)) continue;
        q = ctx->hist[slot] + 8u * ((size_t)qy * W + qx);
        if (!(q[3] > 0.0f) || !(fov__absf(dist - q[3]) <= ctx->cfg.temporal.eps_depth * q[3]))
            continue;
        for (k = 0; k < 3; ++k) acc[k] += w * q[k];
        ws += w;
    }
    for (k = 0; k < 3; ++k) c[k] = acc[k] / ws;
}

/* LAYERS resolve: where pixel v lies against eccentricity thresholds without the atan2 of
   fov__ecc_deg. tan2[i] = tan^2 of threshold i (degrees), or -1 where it is outside
   [2, 60]: that one is always decided exactly. The comparison s^2 < co^2 tan^2 (s =
   |v x g|, co = v . g, e = atan2(s, co)) decides e < T when it holds with a relative margin
   of 1e-5; otherwise 0: undecided, the caller computes e exactly. Returns -1 (e < T), +1
   (e > T) or 0. One ulp of e moves tan^2 e by 4 e eps / sin 2e relative: below 1e-6 up to
   60 degrees, but 1e-5 at 89 degrees, where a pixel at e = T was decided outside (a
   reviewer's case). Below 2 degrees the cross product's rounding (eps / sin e relative)
   differs between this copy and fov__ecc_deg's where a compiler contracts them into FMA
   differently (gnu99, -mfma: decisions contradicted at e < 0.2 degrees, a second review;
   the implementation now turns contraction off, NUMERICS). */
FOVPT__PRIV int fovpt__ecc_side(float s2, float co, float tan2)
{
    float r;
    if (!(tan2 >= 0.0f) || !fov__finite(s2) || !fov__finite(co)) return 0;
    if (co <= 0.0f) return 1; /* e >= 90 degrees */
    r = co * co * tan2;
    if (!fov__finite(r) || !(r >= 1e-30f)) return 0;
    if (s2 < r * (1.0f - 1e-5f)) return -1;
    if (s2 > r * (1.0f + 1e-5f)) return 1;
    return 0;
}
/* s^2 = |v x g|^2 and co = v . g of pixel position (x, y) (fov__ecc_deg's vector), for
   fovpt__ecc_side */
FOVPT__PRIV void fovpt__ecc_s2co(const fov_ecc_model *m, float x, float y, float *s2, float *co)
{
    float v[3], cr[3];
    v[0] = x - m->cx; v[1] = y - m->cy; v[2] = m->f_px;
    fov__cross(v, m->g, cr);
    *s2 = fov__dot(cr, cr);
    *co = fov__dot(v, m->g);
}
FOVPT__PRIV float fovpt__tan2_deg(float t)
{
    float tn;
    if (!(t >= 2.0f && t <= 60.0f)) return -1.0f;
    tn = FOV__TAN(t * (FOV__PI / 180.0f));
    return tn * tn;
}

FOVPT_API fov_result fovpt_resolve_rows(const fovpt_ctx *ctx, uint32_t y0, uint32_t y1,
                                        const fovpt_output *out)
{
    /* LAYERS: tan^2 of radius_deg of layer 0 and of radius_deg -+ blend_deg / 2 (full weight
       inside, none outside) of each layer; e exactly only where a comparison is undecided */
    float t2r0 = -1.0f, t2in[FOVPT_MAX_LAYERS], t2out[FOVPT_MAX_LAYERS];
    fovpt__cc cc[FOVPT_MAX_LAYERS];
    uint32_t x, y, k, W;
    if (!ctx) return FOV_ERR_NULL;
    if (!out) FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "resolve_rows: out is NULL");
    if (!ctx->accum && !ctx->layer_buf[0])
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NULL,
                    "resolve_rows: ctx not initialised (fovpt_init)");
    W = ctx->cam.width;
    if (y0 > y1 || y1 > ctx->cam.height)
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "resolve_rows: needs y0 <= y1 <= height");
    if ((out->rgb_stride && out->rgb_stride < 3u * W) ||
        (out->rgb8_stride && out->rgb8_stride < 3u * W))
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "resolve_rows: out.rgb_stride or rgb8_stride below 3 * width");
    if (!ctx->accum) {
        const fovpt_layers_cfg *L = &ctx->lay;
        t2r0 = fovpt__tan2_deg(L->layer[0].radius_deg);
        for (k = 0; k < L->count && k < FOVPT_MAX_LAYERS; ++k) {
            t2in[k] = fovpt__tan2_deg(L->layer[k].radius_deg - 0.5f * L->blend_deg);
            t2out[k] = fovpt__tan2_deg(L->layer[k].radius_deg + 0.5f * L->blend_deg);
        }
    }
    for (y = y0; y < y1; ++y) {
        for (k = 0; k < FOVPT_MAX_LAYERS; ++k) cc[k].row = UINT32_MAX;
        for (x = 0; x < W; ++x) {
            float c[3] = { 0.0f, 0.0f, 0.0f };
            if (ctx->accum) { /* UNIFORM, SELECTIVE, JIN */
                const float *acc = ctx->accum + 4u * ((size_t)y * W + x);
                for (k = 0; k < 3; ++k) c[k] = acc[3] > 0.0f ? acc[k] / acc[3] : 0.0f;
                if (ctx->hist_slots && ctx->cfg.temporal.smooth) fovpt__smooth(ctx, x, y, c);
            } else {
                const fovpt_layers_cfg *L = &ctx->lay;
                const fov_ecc_model *em = &ctx->ecc;
                float f[3], s2, co, e = -1.0f; /* e < 0: not computed yet */
                uint32_t n, top = 0;
                int side = -1; /* layer 0 radius 0 (the default): the whole image */
#define FOVPT__E() (e >= 0.0f ? e : (e = fovpt_ecc_deg(em, (float)x + 0.5f, (float)y + 0.5f)))
                fovpt__ecc_s2co(em, (float)x + 0.5f, (float)y + 0.5f, &s2, &co);
                if (L->layer[0].radius_deg > 0.0f) side = fovpt__ecc_side(s2, co, t2r0);
                if (side < 0 || (side == 0 && FOVPT__E() <= L->layer[0].radius_deg)) {
                    /* the innermost layer with full weight: nothing below it is needed */
                    for (n = L->count - 1u; n > 0; --n) {
                        side = fovpt__ecc_side(s2, co, t2in[n]);
                        if (side > 0) continue;
                        if (side < 0 || fovpt__vb(L, n, FOVPT__E()) >= 1.0f) { top = n; break; }
                    }
                    if (!fovpt__layer_value_cc(ctx, top, x, y, c, &cc[top])) {
                        /* not available (untraced neighbours): the next layer outwards that
                           has a value (the background layer covers every pixel) */
                        uint32_t m;
                        int got = 0;
                        for (m = top + 1u; m < L->count && !got; ++m)
                            got = fovpt__layer_value_cc(ctx, m, x, y, c, &cc[m]);
                        if (!got) c[0] = c[1] = c[2] = 0.0f;
                    }
                    for (n = top + 1u; n < L->count; ++n) {
                        float vb;
                        if (fovpt__ecc_side(s2, co, t2out[n]) > 0) continue; /* weight 0 */
                        vb = fovpt__vb(L, n, FOVPT__E());
                        if (!(vb > 0.0f) || !fovpt__layer_value_cc(ctx, n, x, y, f, &cc[n]))
                            continue;
                        for (k = 0; k < 3; ++k) c[k] = (1.0f - vb) * c[k] + vb * f[k];
                    }
                }
#undef FOVPT__E
            }
            if (out->rgb) {
                float *o =
                    out->rgb + (size_t)y * (out->rgb_stride ? out->rgb_stride : 3u * W) + 3u * x;
                o[0] = c[0]; o[1] = c[1]; o[2] = c[2];
            }
            if (out->rgb8) {
                uint8_t *o =
                    out->rgb8 + (size_t)y * (out->rgb8_stride ? out->rgb8_stride : 3u * W) + 3u * x;
                o[0] = fovpt__srgb8(c[0]); o[1] = fovpt__srgb8(c[1]); o[2] = fovpt__srgb8(c[2]);
            }
        }
    }
    return FOV_OK;
}

FOVPT_API fov_result fovpt_render(fovpt_ctx *ctx, uint32_t frame, const fovpt_output *out,
                                  fovpt_stats *stats)
{
    fov_result e;
    if (!ctx) return FOV_ERR_NULL;
    if (!out) FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "render: out is NULL");
    e = fovpt_trace_rows(ctx, frame, 0, ctx->cam.height, stats);
    if (e != FOV_OK) return e;
    e = fovpt_refine_rows(ctx, frame, 0, ctx->cam.height, stats);
    if (e != FOV_OK) return e;
    return fovpt_resolve_rows(ctx, 0, ctx->cam.height, out);
}

FOVPT_API void fovpt_output_init(fovpt_output *out)
{
    if (out) FOV_MEMSET(out, 0, sizeof *out);
}

FOVPT_API void fovpt_stats_init(fovpt_stats *stats)
{
    if (stats) FOV_MEMSET(stats, 0, sizeof *stats);
}

FOVPT_API void fovpt_stats_add(fovpt_stats *acc, const fovpt_stats *s)
{
    fovpt_stats t;
    if (!acc || !s) return;
    t = *s; /* fovpt__add_stats recomputes t.rays (camera + bounce + shadow) */
    fovpt__add_stats(acc, &t);
}

/* ---- foveation building blocks --------------------------------------------------------------- */
FOVPT_API void fovpt_catmull_rom(float t, float w[4])
{
    /* Axblad 2020, Eq. 3.17, t^3 coefficient of v2 = -3/2 (the thesis prints -1/2) */
    float t2 = t * t, t3 = t2 * t;
    if (!w) return;
    w[0] = -0.5f * t3 + t2 - 0.5f * t;
    w[1] = 1.5f * t3 - 2.5f * t2 + 1.0f;
    w[2] = -1.5f * t3 + 2.0f * t2 + 0.5f * t;
    w[3] = 0.5f * t3 - 0.5f * t2;
}

/* y of a quadratic Bezier (x0,y0) (x1,y1) (x2,y2) at x = e, x monotone on [0, 1]. */
FOVPT__PRIV float fovpt__bezier_y(float x0, float y0, float x1, float y1, float x2, float y2,
                                  float e)
{
    float A = x0 - 2.0f * x1 + x2, B = 2.0f * (x1 - x0), C = x0 - e, t, u;
    if (fov__absf(A) <= 1e-6f * (fov__absf(B) + 1e-30f)) {
        t = B > 0.0f || B < 0.0f ? -C / B : 0.0f;
    } else {
        float disc = fov__maxf(0.0f, B * B - 4.0f * A * C), sq = FOV__SQRT(disc);
        float q = -0.5f * (B + (B < 0.0f ? -sq : sq));
        float r0 = q / A, r1 = (q > 0.0f || q < 0.0f) ? C / q : r0;
        t = (r0 >= -1e-4f && r0 <= 1.0001f) ? r0 : r1;
    }
    t = fov__clampf(t, 0.0f, 1.0f);
    u = 1.0f - t;
    return u * u * y0 + 2.0f * t * u * y1 + t * t * y2;
}

FOVPT_API fov_result fovpt_tau_fov(const fovpt_selective_cfg *s, float e, float *out)
{
    float t0, tf, tp, tn, ef, enp;
    if (!s || !out) return FOV_ERR_NULL;
    *out = 0.0f;
    t0 = s->tau_shape[0]; tf = s->tau_shape[1]; tp = s->tau_shape[2]; tn = s->tau_shape[3];
    ef = s->e_deg[0]; enp = s->e_deg[3];
    if (!fov__finite(e) || !fov__finite(t0) || !fov__finite(tf) || !fov__finite(tp) ||
        !fov__finite(tn) || !fov__finite(ef) || !fov__finite(enp))
        return FOV_ERR_NOT_FINITE;
    if (!(ef > 0.0f && enp > ef && t0 > 0.0f && tf > 0.0f && tn > 0.0f && tp > 0.0f) ||
        tp < (tf - t0) / ef || tp < (tn - tf) / (enp - ef))
        return FOV_ERR_INVALID_ARG;
    if (e <= 0.0f) *out = t0;
    else if (e <= ef) *out = fovpt__bezier_y(0.0f, t0, ef - (tf - t0) / tp, t0, ef, tf, e);
    else if (e < enp) *out = fovpt__bezier_y(ef, tf, ef + (tn - tf) / tp, tn, enp, tn, e);
    else *out = tn;
    return FOV_OK;
}

FOVPT_API float fovpt_alpha(const fovpt_temporal_cfg *t, const fovpt_selective_cfg *s, float e)
{
    float x[6];
    uint32_t i;
    if (!t || !s || !fov__finite(e)) return 0.0f;
    x[0] = 0.0f;
    for (i = 0; i < 5; ++i) x[i + 1u] = s->e_deg[i];
    if (e <= 0.0f) return t->alpha[0];
    for (i = 0; i < 5; ++i)
        if (e <= x[i + 1u]) {
            float w = (e - x[i]) / (x[i + 1u] - x[i]);
            return t->alpha[i] + w * (t->alpha[i + 1u] - t->alpha[i]);
        }
    return t->alpha[5];
}


/* ---- denoising: guide buffers (fovpt_trace_rows_guide) --------------------------------- */
FOVPT__PRIV float *fovpt__gptr(float *p, uint32_t stride, uint32_t ch, uint32_t W, uint32_t x,
                               uint32_t y)
{
    return p + (size_t)y * (stride ? stride : ch * W) + (size_t)ch * x;
}

/* writes the guides of pixel (x, y) from G; spp < 0: G->n; vn: the number of samples the
   pixel's image value is the mean of (with accumulate more than G's), 0: var -1 */
FOVPT__PRIV void fovpt__gwrite(const fovpt_guide *g, uint32_t W, uint32_t x, uint32_t y,
                               const fovpt__gsum *G, float spp, float vn)
{
    uint32_t k;
    float inv = G->n ? 1.0f / (float)G->n : 0.0f;
    if (g->albedo) {
        float *o = fovpt__gptr(g->albedo, g->albedo_stride, 3u, W, x, y);
        for (k = 0; k < 3; ++k) o[k] = G->alb[k] * inv;
    }
    if (g->normal) {
        float *o = fovpt__gptr(g->normal, g->normal_stride, 3u, W, x, y), n[3];
        fovpt__copy3(n, G->nrm);
        if (G->hits && fov__normalize(n) > 0.0f) fovpt__copy3(o, n);
        else o[0] = o[1] = o[2] = 0.0f;
    }
    if (g->depth)
        *fovpt__gptr(g->depth, g->depth_stride, 1u, W, x, y) =
            !G->hits ? 0.0f
                     : (G->dep_lo ? fov__minf(G->dep / (float)G->hits * 4294967296.0f, FLT_MAX)
                                  : G->dep / (float)G->hits);
    if (g->spp) *fovpt__gptr(g->spp, g->spp_stride, 1u, W, x, y) = spp < 0.0f ? (float)G->n : spp;
    if (g->var) {
        float v = -1.0f;
        if (vn > 0.0f && G->n >= 2u) { /* one sample's variance / the samples averaged */
            float m = G->l1 * inv;
            v = fov__maxf(0.0f, (G->l2 - G->l1 * m) / (float)(G->n - 1u)) /
                fov__maxf(vn, (float)G->n);
        }
        *fovpt__gptr(g->var, g->var_stride, 1u, W, x, y) = v;
    }
}

/* LAYERS, ZONES: is pixel (x, y) a traced point of a stride-1 layer (traced with its guides)? */
FOVPT__PRIV int fovpt__own_pixel(const fovpt_ctx *ctx, uint32_t x, uint32_t y, float e)
{
    uint32_t n;
    for (n = 0; n < ctx->lay.count; ++n)
        if (ctx->lay.layer[n].stride == 1u && x >= ctx->layer_ox[n] && y >= ctx->layer_oy[n] &&
            !(e > ctx->layer_trace_deg[n] || e < ctx->layer_inner_deg[n]))
            return 1;
    return 0;
}

/* LAYERS, ZONES: the samples per pixel behind pixel (x, y), blended as the resolve does */
FOVPT__PRIV float fovpt__density(const fovpt_ctx *ctx, float e)
{
    const fovpt_layers_cfg *L = &ctx->lay;
    uint32_t n, top = 0;
    float D;
    for (n = L->count - 1u; n > 0; --n)
        if (fovpt__vb(L, n, e) >= 1.0f) { top = n; break; }
    D = (float)L->layer[top].spp / (float)(L->layer[top].stride * L->layer[top].stride);
    for (n = top + 1u; n < L->count; ++n) {
        float vb = fovpt__vb(L, n, e);
        D = (1.0f - vb) * D + vb * (float)L->layer[n].spp /
                                  (float)(L->layer[n].stride * L->layer[n].stride);
    }
    return D;
}

/* LAYERS, ZONES: the stride-1 layer whose samples give pixel (x, y)'s guides when more than
   one traces it (their blend band): the largest weight in the resolve's blend (layer n's
   weight: vb_n, or 1 for the full-weight layer, times (1 - vb_m) of every layer m > n; 0
   below the full-weight layer), ties to the later layer */
FOVPT__PRIV uint32_t fovpt__gwin(const fovpt_ctx *ctx, uint32_t x, uint32_t y, float e)
{
    const fovpt_layers_cfg *L = &ctx->lay;
    uint32_t n, m, top = 0, win = 0;
    float best = -1.0f;
    for (n = L->count - 1u; n > 0; --n)
        if (fovpt__vb(L, n, e) >= 1.0f) { top = n; break; }
    for (n = 0; n < L->count; ++n) {
        float w;
        if (L->layer[n].stride != 1u || x < ctx->layer_ox[n] || y < ctx->layer_oy[n] ||
            e > ctx->layer_trace_deg[n] || e < ctx->layer_inner_deg[n])
            continue;
        w = n < top ? 0.0f : n == top ? 1.0f : fovpt__vb(L, n, e);
        for (m = n + 1u; m < L->count; ++m) w *= 1.0f - fovpt__vb(L, m, e);
        if (w >= best) { best = w; win = n; }
    }
    return win;
}

/* LAYERS, ZONES: 1 when layer win alone gives the pixel's value at eccentricity e (its
   weight in the resolve's blend, as in fovpt__gwin, is 1), 0 in a blend band (the value
   mixes layers: the variance of its own samples' mean is not the value's) */
FOVPT__PRIV int fovpt__gsole(const fovpt_ctx *ctx, float e, uint32_t win)
{
    const fovpt_layers_cfg *L = &ctx->lay;
    uint32_t n, m, top = 0;
    float w;
    for (n = L->count - 1u; n > 0; --n)
        if (fovpt__vb(L, n, e) >= 1.0f) { top = n; break; }
    w = win == top ? 1.0f : win < top ? 0.0f : fovpt__vb(L, win, e);
    for (m = win + 1u; m < L->count; ++m) w *= 1.0f - fovpt__vb(L, m, e);
    return w >= 1.0f;
}

FOVPT__PRIV int fovpt__gstride_bad(uint32_t stride, uint32_t ch, uint32_t W)
{
    return stride != 0u && stride < ch * W;
}

FOVPT_API void fovpt_guide_init(fovpt_guide *g)
{
    if (g) FOV_MEMSET(g, 0, sizeof *g);
}

/* The sample loop of fovpt_trace_rows and fovpt_trace_rows_guide on rows [y0, y1) (checked
   by the caller): g NULL, the samples alone; else the same samples and streams plus the
   guides of the rows (stride-1 points keep their own samples' guides; every other pixel
   gets the first hit of one more ray through its centre). */
FOVPT__PRIV void fovpt__trace(fovpt_ctx *ctx, uint32_t frame, uint32_t y0, uint32_t y1,
                              const fovpt_guide *g, fovpt_stats *st)
{
    uint32_t x, y, n, W = ctx->cam.width, H = ctx->cam.height;
    float t4[4];
    t4[0] = ctx->tx0; t4[1] = ctx->tx1; t4[2] = ctx->ty0; t4[3] = ctx->ty1;
    if (ctx->cfg.method == FOVPT_METHOD_UNIFORM) {
        for (y = y0; y < y1; ++y)
            for (x = 0; x < W; ++x) {
                float sum[3], *acc = ctx->accum + 4u * ((size_t)y * W + x);
                fovpt__gsum G;
                FOV_MEMSET(&G, 0, sizeof G);
                fovpt__pixel(ctx, frame, x, y, ctx->cfg.spp, 0, 1u, 0u, 0.0f, sum, g ? &G : NULL,
                             st);
                fovpt__store(acc, sum, ctx->cfg.spp, ctx->cfg.accumulate);
                if (g) fovpt__gwrite(g, W, x, y, &G, acc[3], acc[3]);
            }
    } else if (ctx->pre) {
        /* SELECTIVE, JIN step 1 (Kim et al. 2021, Fig. 4 A-3): one ray through each pixel centre,
           colour reference and attributes */
        for (y = y0; y < y1; ++y)
            for (x = 0; x < W; ++x) {
                fovpt__pre *P = (fovpt__pre *)ctx->pre + ((size_t)y * W + x);
                fovpt__attr at;
                fovpt_rng rng;
                float dir[3];
                fovpt__rng_start(&rng, &ctx->cfg, y * W + x, 0, frame);
                if (rng.sobol) { (void)fovpt_rng_next(&rng); (void)fovpt_rng_next(&rng); }
                fovpt__primary(ctx->right, ctx->up, ctx->fwd, t4, W, H, (float)x + 0.5f,
                               (float)y + 0.5f, dir);
                st->camera_rays++;
                st->samples++;
                (void)fovpt__radiance(ctx->scene, &ctx->cfg, ctx->origin, dir, &rng, P->col, st,
                                      &at);
                P->poid = at.poid; P->soid = at.soid;
                fovpt__copy3(P->pn, at.pn); fovpt__copy3(P->sn, at.sn);
                P->sc = (at.psc > 65535u ? 65535u : at.psc) |
                        ((at.ssc > 65535u ? 65535u : at.ssc) << 16);
                P->t = at.pt;
            }
    } else {
        /* LAYERS (Axblad 2020, Fig. 3.6: ray buffer with gaze offset -> path tracing), ZONES */
        for (n = 0; n < ctx->lay.count; ++n) {
            uint32_t d = ctx->lay.layer[n].stride, spp = ctx->lay.layer[n].spp, k, l;
            uint32_t nx = ctx->layer_nx[n], ox = ctx->layer_ox[n], oy = ctx->layer_oy[n];
            float tr = ctx->layer_trace_deg[n], ti = ctx->layer_inner_deg[n];
            /* the disk test by fovpt__ecc_side (no atan2) where it decides; nothing to test
               where every eccentricity passes (the background: tr FLT_MAX, no inner edge) */
            float t2tr = fovpt__tan2_deg(tr), t2ti = fovpt__tan2_deg(ti);
            int all_in = !(tr < 180.0f) && !(ti > 0.0f);
            const fov_ecc_model *em = &ctx->ecc;
            /* hollow: sample k of a pixel is UNIFORM's stream k in every layer */
            uint32_t s0 = ctx->lay.hollow ? 0u : n << 16;
            /* lattice rows whose pixel row lies in [y0, y1) */
            uint32_t l0 = y0 > oy ? (y0 - oy + d - 1u) / d : 0u;
            int own = g && d == 1u; /* stride-1 points: their own samples' guides */
            for (l = l0; l < ctx->layer_ny[n]; ++l) {
                uint32_t py = oy + l * d;
                if (py >= y1) break;
                for (k = 0; k < nx; ++k) {
                    uint32_t px = ox + k * d;
                    float *acc = ctx->layer_buf[n] + 4u * ((size_t)l * nx + k), sum[3];
                    float ep = -1.0f; /* < 0: not computed */
                    fovpt__gsum G;
                    if (!all_in) {
                        float s2, co;
                        int sa, sb;
                        fovpt__ecc_s2co(em, (float)px + 0.5f, (float)py + 0.5f, &s2, &co);
                        sa = fovpt__ecc_side(s2, co, t2tr);
                        sb = ti > 0.0f ? fovpt__ecc_side(s2, co, t2ti) : 1;
                        if (sa == 0 || sb == 0) {
                            ep = fovpt_ecc_deg(em, (float)px + 0.5f, (float)py + 0.5f);
                            sa = ep > tr ? 1 : -1;
                            sb = ep < ti ? -1 : 1;
                        }
                        if (sa > 0 || sb < 0) {
                            acc[0] = acc[1] = acc[2] = acc[3] = 0.0f; /* not traced */
                            continue;
                        }
                    }
                    if (own && ep < 0.0f)
                        ep = fovpt_ecc_deg(em, (float)px + 0.5f, (float)py + 0.5f);
                    FOV_MEMSET(&G, 0, sizeof G);
                    fovpt__pixel(ctx, frame, px, py, spp, s0, ctx->lay.cell_jitter ? d : 1u,
                                 ctx->cfg.spp, d >= 2u ? ctx->lay.clamp_white : 0.0f, sum,
                                 own ? &G : NULL, st);
                    fovpt__store(acc, sum, spp, ctx->cfg.accumulate);
                    if (own && fovpt__gwin(ctx, px, py, ep) == n) /* one layer's guides */
                        fovpt__gwrite(g, W, px, py, &G, fovpt__density(ctx, ep),
                                      fovpt__gsole(ctx, ep, n) ? acc[3] : 0.0f);
                    st->layer_targets[n]++;
                    st->layer_samples[n] += spp;
                }
            }
        }
    }
    if (!g || ctx->cfg.method == FOVPT_METHOD_UNIFORM) return;
    /* pixels without their own samples: the first hit of the ray through the centre */
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            float e = fovpt_ecc_deg(&ctx->ecc, (float)x + 0.5f, (float)y + 0.5f), dir[3];
            float zero[3] = { 0.0f, 0.0f, 0.0f };
            fovpt__gsum G;
            fovpt__attr at;
            fovpt_hit h;
            if (!ctx->pre && fovpt__own_pixel(ctx, x, y, e)) continue;
            FOV_MEMSET(&G, 0, sizeof G);
            FOV_MEMSET(&at, 0, sizeof at);
            at.poid = FOVPT_PRIM_NONE;
            fovpt__primary(ctx->right, ctx->up, ctx->fwd, t4, W, H, (float)x + 0.5f,
                           (float)y + 0.5f, dir);
            st->camera_rays++;
            if (fovpt__hit(ctx->scene, ctx->origin, dir, 0.0f, FLT_MAX, &h, 0)) {
                fovpt__attr_hit(&h, dir, &at.poid, at.pn);
                at.pt = h.t;
                at.pmat = h.material;
            }
            fovpt__gsum_add(&G, ctx->scene, &at, zero);
            fovpt__gwrite(g, W, x, y, &G, ctx->pre ? 1.0f : fovpt__density(ctx, e), 0.0f);
        }
}

/* fovpt_trace_rows (g NULL) and fovpt_trace_rows_guide: the checks, then fovpt__trace */
FOVPT__PRIV fov_result fovpt__trace_rows(fovpt_ctx *ctx, uint32_t frame, uint32_t y0, uint32_t y1,
                                         const fovpt_guide *g, fovpt_stats *stats)
{
    fovpt_stats st;
    uint32_t W;
    if (!ctx) return FOV_ERR_NULL;
    W = ctx->cam.width;
    if (!ctx->scene || (!ctx->accum && !ctx->layer_buf[0]))
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NULL,
                    "trace_rows(_guide): ctx not initialised (fovpt_init)");
    if (y0 > y1 || y1 > ctx->cam.height)
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "trace_rows(_guide): needs y0 <= y1 <= height");
    if (g && (fovpt__gstride_bad(g->albedo_stride, 3u, W) ||
              fovpt__gstride_bad(g->normal_stride, 3u, W) ||
              fovpt__gstride_bad(g->depth_stride, 1u, W) ||
              fovpt__gstride_bad(g->spp_stride, 1u, W) || fovpt__gstride_bad(g->var_stride, 1u, W)))
        FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_INVALID_ARG,
                    "trace_rows_guide: a guide stride below the packed one (3 * width for "
                    "albedo and normal, width for depth, spp, var)");
    FOV_MEMSET(&st, 0, sizeof st);
    fovpt__trace(ctx, frame, y0, y1, g, &st);
    fovpt__add_stats(stats, &st);
    return FOV_OK;
}

FOVPT_API fov_result fovpt_trace_rows(fovpt_ctx *ctx, uint32_t frame, uint32_t y0, uint32_t y1,
                                      fovpt_stats *stats)
{
    return fovpt__trace_rows(ctx, frame, y0, y1, NULL, stats);
}

FOVPT_API fov_result fovpt_trace_rows_guide(fovpt_ctx *ctx, uint32_t frame, uint32_t y0,
                                            uint32_t y1, const fovpt_guide *g,
                                            fovpt_stats *stats)
{
    return fovpt__trace_rows(ctx, frame, y0, y1, g, stats);
}

FOVPT_API fov_result fovpt_render_guide(fovpt_ctx *ctx, uint32_t frame, const fovpt_output *out,
                                        const fovpt_guide *g, fovpt_stats *stats)
{
    fov_result e;
    if (!ctx) return FOV_ERR_NULL;
    if (!out) FOVPT__FAIL(&ctx->cfg.logger, FOV_ERR_NULL, "render_guide: out is NULL");
    e = fovpt_trace_rows_guide(ctx, frame, 0, ctx->cam.height, g, stats);
    if (e != FOV_OK) return e;
    e = fovpt_refine_rows(ctx, frame, 0, ctx->cam.height, stats);
    if (e != FOV_OK) return e;
    return fovpt_resolve_rows(ctx, 0, ctx->cam.height, out);
}

/* ---- denoising: the foveated a-trous filter (Dammertz et al. 2010; Schied et al. 2017) -- */
/* exp(-x) for x in [0, 30] (edge-stopping weights): 2^(-x log2 e) as 2^-i by the exponent
   bits times a degree-6 Taylor polynomial of 2^-f, f in [0, 1) (relative error below 5e-5) */
FOVPT__PRIV float fovpt__exp_neg(float x)
{
    float t = x * 1.44269504f, f, p;
    int32_t i;
    union { float f; uint32_t u; } b;
    if (!(t < 126.0f)) return 0.0f;
    if (!(t > 0.0f)) return 1.0f;
    i = (int32_t)t;
    f = t - (float)i;
    /* 2^-f on [0, 1): Taylor in (-f ln 2), Horner */
    f *= -0.693147181f;
    p = 0.00833333333f + f * 0.00138888889f;
    p = 1.0f + f * (1.0f + f * (0.5f + f * (0.166666667f + f * (0.0416666667f + f * p))));
    b.u = (uint32_t)(127 - i) << 23;
    return p * b.f;
}
#define FOVPT__DN_HIST 12u
#define FOVPT__DN_MAXN 32.0f
#define FOVPT__DN_SEL 10u /* floats per pixel of SURE (see fovpt_denoise.sel) */
/* a guide var from at least this many samples is trusted alone (no spatial estimate mixed in) */
#ifndef FOVPT__DN_QUIET /* the quiet test's factor on the running variance (see fovpt__dn_quiet) */
#define FOVPT__DN_QUIET 64.0f
#endif
#ifndef FOVPT__DN_VAR_SPP
#define FOVPT__DN_VAR_SPP 8.0f
#endif

FOVPT_API fovpt_denoise_cfg fovpt_denoise_cfg_default(void)
{
    fovpt_denoise_cfg c;
    FOV_MEMSET(&c, 0, sizeof c);
    c.levels = 5;
    c.fovea_step = 4.0f;
    c.phi_lum = 8.0f;
    c.phi_normal = 32.0f;
    c.phi_depth = 1.0f;
    c.phi_albedo = 0.1f;
    c.alpha_fovea = 0.2f;
    c.alpha_periphery = 0.05f;
    c.depth_tol = 0.02f;
    c.normal_cos = 0.9f;
    c.skip_noise = 0.5f;
    c.r_small = 2.0f;
    c.spp_full = 16.0f;
    c.sure_radius = 4;
    c.sure_min_spp = 16.0f;
    return c;
}

/* exact float equality without == (the library builds clean with -Wfloat-equal) */
FOVPT__PRIV int fovpt__dn_feq(float a, float b) { return a <= b && a >= b; }

FOVPT__PRIV int fovpt__dn_in(float v, float lo, float hi)
{
    return fov__finite(v) && v > lo && v <= hi;
}

FOVPT_API fov_result fovpt_denoise_resolve(const fovpt_denoise_cfg *in, fovpt_denoise_cfg *out)
{
    fovpt_denoise_cfg c, d = fovpt_denoise_cfg_default();
    const fov_logger *lg;
    if (!in || !out) return FOV_ERR_NULL;
    c = *in;
    lg = &in->logger;
    if (c.width == 0 || c.height == 0)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.width and cfg.height must be >= 1");
    if (c.width > FOVPT_MAX_DIM || c.height > FOVPT_MAX_DIM)
        FOVPT__FAIL(lg, FOV_ERR_LIMIT, "denoise: cfg.width or cfg.height above FOVPT_MAX_DIM");
    if (!c.levels) c.levels = d.levels;
    if (c.levels > FOVPT_DN_MAX_LEVELS)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.levels above FOVPT_DN_MAX_LEVELS");
    if (c.no_filter > 1u || c.no_temporal > 1u)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.no_filter and no_temporal are 0 or 1");
    if (!fov__finite(c.fovea_step) || !fov__finite(c.spp_ref) || !fov__finite(c.phi_lum) ||
        !fov__finite(c.phi_normal) || !fov__finite(c.phi_depth) || !fov__finite(c.phi_albedo) ||
        !fov__finite(c.alpha_fovea) || !fov__finite(c.alpha_periphery) ||
        !fov__finite(c.depth_tol) || !fov__finite(c.normal_cos) || !fov__finite(c.skip_noise) ||
        !fov__finite(c.r_small) || !fov__finite(c.spp_full))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "denoise: a cfg field is NaN or infinite");
    if (fov__is0(c.fovea_step)) c.fovea_step = d.fovea_step;
    if (fov__is0(c.phi_lum)) c.phi_lum = d.phi_lum;
    if (fov__is0(c.phi_normal)) c.phi_normal = d.phi_normal;
    if (fov__is0(c.phi_depth)) c.phi_depth = d.phi_depth;
    if (fov__is0(c.phi_albedo)) c.phi_albedo = d.phi_albedo;
    if (fov__is0(c.alpha_fovea)) c.alpha_fovea = d.alpha_fovea;
    if (fov__is0(c.alpha_periphery))
        c.alpha_periphery = fov__minf(d.alpha_periphery, c.alpha_fovea);
    if (fov__is0(c.depth_tol)) c.depth_tol = d.depth_tol;
    if (fov__is0(c.normal_cos)) c.normal_cos = d.normal_cos;
    if (fov__is0(c.skip_noise)) c.skip_noise = d.skip_noise;
    if (fov__is0(c.r_small)) c.r_small = d.r_small;
    if (fov__is0(c.spp_full)) c.spp_full = d.spp_full;
    if (!(c.fovea_step >= 1.0f && c.fovea_step <= 65536.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.fovea_step must be in [1, 65536]");
    if (!(c.spp_ref >= 0.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.spp_ref must be >= 0");
    if (!fovpt__dn_in(c.phi_lum, 0.0f, 1e6f) || !fovpt__dn_in(c.phi_normal, 0.0f, 1e6f) ||
        !fovpt__dn_in(c.phi_depth, 0.0f, 1e6f) || !fovpt__dn_in(c.phi_albedo, 0.0f, 1e6f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.phi_* must be in (0, 1e6]");
    if (!fovpt__dn_in(c.alpha_fovea, 0.0f, 1.0f) || !fovpt__dn_in(c.alpha_periphery, 0.0f, 1.0f) ||
        c.alpha_periphery > c.alpha_fovea)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                    "denoise: cfg.alpha_fovea in (0, 1], alpha_periphery in (0, alpha_fovea]");
    if (!fovpt__dn_in(c.depth_tol, 0.0f, 1.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.depth_tol must be in (0, 1]");
    if (!(c.normal_cos >= -1.0f && c.normal_cos < 1.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.normal_cos must be in [-1, 1)");
    if (!(c.skip_noise > 0.0f && c.skip_noise <= 255.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.skip_noise must be in (0, 255]");
    if (!(c.r_small >= 1.0f && c.r_small <= 65536.0f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.r_small must be in [1, 65536]");
    if (c.no_sure > 1u)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.no_sure is 0 or 1");
    if (!c.sure_radius) c.sure_radius = d.sure_radius;
    if (c.sure_radius > 8u)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.sure_radius must be in [1, 8]");
    if (!fov__finite(c.sure_min_spp))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "denoise: a cfg field is NaN or infinite");
    if (fov__is0(c.sure_min_spp)) c.sure_min_spp = d.sure_min_spp;
    if (!(c.sure_min_spp >= 2.0f && c.sure_min_spp <= 1e30f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.sure_min_spp must be in [2, 1e30]");
    if (!(c.spp_full > 0.0f && c.spp_full <= 1e30f))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.spp_full must be in (0, 1e30]");
    if (!fov__finite(c.eye.mar0_arcmin) || !fov__finite(c.eye.slope_arcmin) ||
        !fov__finite(c.eye.quality) || c.eye.mar0_arcmin < 0.0f || c.eye.slope_arcmin < 0.0f ||
        c.eye.quality < 0.0f)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise: cfg.eye fields must be finite and >= 0");
    *out = c;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_denoise_size(const fovpt_denoise_cfg *cfg, size_t *bytes)
{
    fovpt_denoise_cfg c;
    fov_result e;
    uint64_t px;
    if (!cfg || !bytes) return FOV_ERR_NULL;
    e = fovpt_denoise_resolve(cfg, &c);
    if (e != FOV_OK) return e;
    px = (uint64_t)c.width * c.height;
    px = px * 4u * (2u * FOVPT__DN_HIST + 2u * 4u + 1u + 8u + (c.no_sure ? 0u : FOVPT__DN_SEL)) +
         64u;
    if (px > (uint64_t)(SIZE_MAX / 2u))
        FOVPT__FAIL(&cfg->logger, FOV_ERR_LIMIT, "denoise_size: memory overflows size_t");
    *bytes = (size_t)px;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_denoise_init(fovpt_denoise *dn, const fovpt_denoise_cfg *cfg,
                                        void *mem, size_t bytes)
{
    size_t need = 0, px;
    fov_result e;
    float *p;
    if (!dn || !cfg) return FOV_ERR_NULL;
    e = fovpt_denoise_size(cfg, &need);
    if (e != FOV_OK) return e;
    if (!mem) FOVPT__FAIL(&cfg->logger, FOV_ERR_NULL, "denoise_init: mem is NULL");
    if (((uintptr_t)mem & 7u) != 0u)
        FOVPT__FAIL(&cfg->logger, FOV_ERR_INVALID_ARG, "denoise_init: mem not 8-byte aligned");
    if (bytes < need)
        FOVPT__FAIL(&cfg->logger, FOV_ERR_TOO_SMALL,
                    "denoise_init: bytes below fovpt_denoise_size");
    FOV_MEMSET(dn, 0, sizeof *dn);
    FOV_MEMSET(mem, 0, need); /* history, buffers and row phases start defined (zero) */
    (void)fovpt_denoise_resolve(cfg, &dn->cfg);
    px = (size_t)dn->cfg.width * dn->cfg.height;
    p = (float *)mem;
    dn->hist[0] = p; p += FOVPT__DN_HIST * px;
    dn->hist[1] = p; p += FOVPT__DN_HIST * px;
    dn->buf[0] = p; p += 4u * px;
    dn->buf[1] = p; p += 4u * px;
    dn->coarse = p; p += px;
    dn->pack = p; p += 8u * px;
    dn->sel = dn->cfg.no_sure ? NULL : p;
    dn->mem = mem;
    dn->mem_size = bytes;
    dn->passes = dn->cfg.no_filter ? 0u : dn->cfg.levels;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_denoise_reset(fovpt_denoise *dn)
{
    if (!dn) return FOV_ERR_NULL;
    if (!dn->mem) FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_NULL, "denoise_reset: not initialised");
    dn->frames = 0;
    dn->has_prev = 0;
    dn->in_frame = 0;
    return FOV_OK;
}

FOVPT_API uint32_t fovpt_denoise_passes(const fovpt_denoise *dn) { return dn ? dn->passes : 0u; }

FOVPT__PRIV const float *fovpt__gin(const float *p, uint32_t stride, uint32_t ch, uint32_t W,
                                    uint32_t x, uint32_t y)
{
    return p + (size_t)y * (stride ? stride : ch * W) + (size_t)ch * x;
}

/* Row y's phase mark (the 8th packed float of its first pixel): 0 after fovpt_denoise_frame,
   1 after the temporal phase, 2 + i after a-trous pass i. Each row call reads and writes only
   the marks of its own rows (no race between threads on disjoint rows). */
FOVPT__PRIV float *fovpt__dn_rowmark(const fovpt_denoise *dn, uint32_t y)
{
    return dn->pack + 8u * (size_t)y * dn->cfg.width + 7u;
}

/* 1 when every row of [y0, y1) has finished phase ph - 1 (or already phase ph) */
FOVPT__PRIV int fovpt__dn_phase_ok(const fovpt_denoise *dn, uint32_t y0, uint32_t y1, float ph)
{
    uint32_t y;
    for (y = y0; y < y1; ++y) {
        float m = *fovpt__dn_rowmark(dn, y);
        if (!(fovpt__dn_feq(m, ph - 1.0f) || fovpt__dn_feq(m, ph))) return 0;
    }
    return 1;
}

FOVPT_API fov_result fovpt_denoise_frame(fovpt_denoise *dn, const fovpt_camera *cam,
                                         fov_gaze gaze, const float *rgb, uint32_t rgb_stride,
                                         const fovpt_guide *g)
{
    const fov_logger *lg;
    fovpt_view v;
    fov_ecc_model ecc;
    fov_result e;
    uint32_t W, H, y, done;
    if (!dn) return FOV_ERR_NULL;
    lg = &dn->cfg.logger;
    if (!dn->mem) FOVPT__FAIL(lg, FOV_ERR_NULL, "denoise_frame: not initialised (denoise_init)");
    dn->in_frame = 0; /* a failed frame leaves no frame to run the phases on */
    if (!cam || !rgb || !g)
        FOVPT__FAIL(lg, FOV_ERR_NULL, "denoise_frame: cam, rgb and g are required");
    if (!g->depth || !g->normal)
        FOVPT__FAIL(lg, FOV_ERR_NULL, "denoise_frame: g.depth and g.normal are required");
    W = dn->cfg.width; H = dn->cfg.height;
    if (cam->width != W || cam->height != H)
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG, "denoise_frame: camera size differs from cfg's");
    if (fovpt__gstride_bad(rgb_stride, 3u, W) || fovpt__gstride_bad(g->albedo_stride, 3u, W) ||
        fovpt__gstride_bad(g->normal_stride, 3u, W) || fovpt__gstride_bad(g->depth_stride, 1u, W) ||
        fovpt__gstride_bad(g->spp_stride, 1u, W) || fovpt__gstride_bad(g->var_stride, 1u, W))
        FOVPT__FAIL(lg, FOV_ERR_INVALID_ARG,
                    "denoise_frame: a stride below the packed one (3 * width for rgb, albedo "
                    "and normal, width for depth, spp, var)");
    if (!fov__finite(gaze.x) || !fov__finite(gaze.y))
        FOVPT__FAIL(lg, FOV_ERR_NOT_FINITE, "denoise_frame: gaze NaN or infinite");
    e = fovpt__camera_setup(cam, v.right, v.up, v.fwd, v.tan4, v.pos);
    if (e != FOV_OK) FOVPT__FAIL(lg, e, "denoise_frame: invalid camera (see fov_camera)");
    e = fovpt__ecc_of(&dn->cfg.display, cam, v.tan4, gaze, &ecc);
    if (e != FOV_OK) FOVPT__FAIL(lg, e, "denoise_frame: invalid cfg.display (see fov_display)");
    /* committed from here on; the previous frame is history only if its temporal phase ran
       on every row (else its history slot holds an older or never-written frame) */
    for (done = 1u, y = 0; y < H; ++y) {
        float *m = fovpt__dn_rowmark(dn, y);
        if (!(*m >= 1.0f)) done = 0u;
        *m = 0.0f;
    }
    if (dn->frames > 0u) {
        dn->cur ^= 1u;
        dn->prev_view = dn->view;
        dn->has_prev = !dn->cfg.no_temporal && done;
    }
    dn->ecc = ecc;
    dn->view = v;
    dn->frames++;
    dn->in = rgb;
    dn->in_stride = rgb_stride;
    dn->guide = *g;
    dn->spp_ref = dn->cfg.spp_ref;
    if (!(dn->spp_ref > 0.0f)) {
        dn->spp_ref = 1.0f;
        if (g->spp) {
            float gx = fov__clampf(gaze.x, 0.0f, (float)W - 1.0f);
            float gy = fov__clampf(gaze.y, 0.0f, (float)H - 1.0f);
            float s = *fovpt__gin(g->spp, g->spp_stride, 1u, W, (uint32_t)gx, (uint32_t)gy);
            if (s > 0.0f && fov__finite(s)) dn->spp_ref = s;
        }
    }
    dn->in_frame = 1;
    return FOV_OK;
}

/* the 4-neighbour depth slope at (x, y) (the smaller one-sided difference per axis) */
FOVPT__PRIV void fovpt__dn_slope(const fovpt_denoise *dn, uint32_t x, uint32_t y, float s[2])
{
    const fovpt_guide *g = &dn->guide;
    uint32_t W = dn->cfg.width, H = dn->cfg.height;
    float z = *fovpt__gin(g->depth, g->depth_stride, 1u, W, x, y), a = FLT_MAX, b = FLT_MAX;
    if (x > 0) a = fov__absf(z - *fovpt__gin(g->depth, g->depth_stride, 1u, W, x - 1u, y));
    if (x + 1u < W) b = fov__absf(z - *fovpt__gin(g->depth, g->depth_stride, 1u, W, x + 1u, y));
    s[0] = fov__minf(a, b) < FLT_MAX ? fov__minf(a, b) : 0.0f;
    a = b = FLT_MAX;
    if (y > 0) a = fov__absf(z - *fovpt__gin(g->depth, g->depth_stride, 1u, W, x, y - 1u));
    if (y + 1u < H) b = fov__absf(z - *fovpt__gin(g->depth, g->depth_stride, 1u, W, x, y + 1u));
    s[1] = fov__minf(a, b) < FLT_MAX ? fov__minf(a, b) : 0.0f;
}

/* the coarseness r >= 1 of pixel (x, y); *k: the reach factor min(1, sqrt(spp_full / spp))
   (1 without an spp guide) */
FOVPT__PRIV float fovpt__dn_coarse(const fovpt_denoise *dn, uint32_t x, uint32_t y, float *k)
{
    const fovpt_guide *g = &dn->guide;
    float e = fovpt_ecc_deg(&dn->ecc, (float)x + 0.5f, (float)y + 0.5f);
    float r = fovpt_eye_mar(&dn->cfg.eye, e) * fovpt_ecc_ppd(&dn->ecc);
    *k = 1.0f;
    if (g->spp) {
        float s = *fovpt__gin(g->spp, g->spp_stride, 1u, dn->cfg.width, x, y);
        if (s > 0.0f && fov__finite(s)) {
            r = fov__maxf(r, FOV__SQRT(dn->spp_ref / s));
            if (s > dn->cfg.spp_full) *k = FOV__SQRT(dn->cfg.spp_full / s);
        }
    }
    return fov__clampf(r, 1.0f, 65536.0f);
}

/* SURE: a pixel's weight of its luminance SURE, the squared slope of the display
   curve at its input luminance l, min(12.92, 0.5 / sqrt(l))^2 (the gamma-2 curve's, as
   skip_noise): the error is judged on the display codes */
FOVPT__PRIV float fovpt__dn_sure_w(float l)
{
    return fov__minf(166.9264f, 0.25f / fov__maxf(l, 1e-30f));
}
/* a variance var (linear, at luminance l) times factor below skip_noise^2 in 8-bit display
   codes (the slope as fovpt__dn_sure_w's) */
FOVPT__PRIV int fovpt__dn_below_skip(const fovpt_denoise *dn, float var, float l, float factor)
{
    return fov__maxf(var, 0.0f) * fovpt__dn_sure_w(l) * 65025.0f * factor <
           dn->cfg.skip_noise * dn->cfg.skip_noise;
}

/* the normal guide as the denoiser reads it: a unit normal (|n|^2 <= 1.0001) bit for bit; a
   longer one (a caller's unnormalised normal) normalised by the shared fov__normalize (which
   prescales what would overflow); one with a NaN or infinite component (0, 0, 0) (no normal
   stop passes it). Longer normals gave dots c >> 1 and c^phi_normal = inf weights: NaN pixels
   (fuzz finding, session 18) */
FOVPT__PRIV void fovpt__dn_nrm(const float *g, float n[3])
{
    fovpt__copy3(n, g);
    if (fov__dot(n, n) <= 1.0001f) return;
    if (!(fov__normalize(n) > 0.0f)) n[0] = n[1] = n[2] = 0.0f;
}

FOVPT_API fov_result fovpt_denoise_temporal_rows(fovpt_denoise *dn, uint32_t y0, uint32_t y1)
{
    uint32_t x, y, k, W, H;
    const fovpt_guide *g;
    if (!dn) return FOV_ERR_NULL;
    if (!dn->in_frame)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_temporal_rows: call fovpt_denoise_frame first");
    W = dn->cfg.width; H = dn->cfg.height;
    if (y0 > y1 || y1 > H)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_temporal_rows: needs y0 <= y1 <= height");
    if (!fovpt__dn_phase_ok(dn, y0, y1, 1.0f))
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_temporal_rows: a row already ran a later phase of this frame");
    g = &dn->guide;
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            const float *c = fovpt__gin(dn->in, dn->in_stride, 3u, W, x, y);
            float nrm[3], z = *fovpt__gin(g->depth, g->depth_stride, 1u, W, x, y);
            float *o = dn->hist[dn->cur] + FOVPT__DN_HIST * i, *b = dn->buf[0] + 4u * i;
            float kr, in[3], l, var_in = -1.0f, r = fovpt__dn_coarse(dn, x, y, &kr), hs[8];
            float hw = 0.0f;
            float a = fov__maxf(dn->cfg.alpha_periphery, dn->cfg.alpha_fovea / r), n = 1.0f;
            float var_own = 0.0f; /* the samples behind the guide's var */
            int hit = z > 0.0f && fov__finite(z), gv = 0;
            fovpt__dn_nrm(fovpt__gin(g->normal, g->normal_stride, 3u, W, x, y), nrm);
            for (k = 0; k < 3; ++k) in[k] = fov__finite(c[k]) ? fov__maxf(c[k], 0.0f) : 0.0f;
            if (!hit) z = 0.0f;
            l = fovpt__lum(in);
            dn->coarse[i] = r * kr; /* the passes' reach: fovea_step r k */
            for (k = 0; k < 8; ++k) hs[k] = 0.0f;
            if (g->var) {
                float v = *fovpt__gin(g->var, g->var_stride, 1u, W, x, y);
                if (v >= 0.0f && fov__finite(v)) {
                    var_in = v;
                    gv = 1;
                    if (g->spp) var_own = *fovpt__gin(g->spp, g->spp_stride, 1u, W, x, y);
                }
            }
            if (dn->has_prev) { /* reproject the first hit into the previous view */
                const fovpt_view *pv = &dn->prev_view, *cv = &dn->view;
                float dir[3], X[3], d[3], zz, sx, sy, px, py, fx, fy, dist, sl[2], tol;
                int ix, iy, tx, ty;
                fovpt__primary(cv->right, cv->up, cv->fwd, cv->tan4, W, H, (float)x + 0.5f,
                               (float)y + 0.5f, dir);
                if (hit) fovpt__madd3(X, cv->pos, z, dir);
                else fovpt__madd3(X, pv->pos, 1.0f, dir);
                fovpt__sub3(d, X, pv->pos);
                zz = fov__dot(d, pv->fwd);
                dist = fov__len(d);
                fovpt__dn_slope(dn, x, y, sl);
                tol = dn->cfg.depth_tol * z + 2.0f * fov__maxf(sl[0], sl[1]);
                if (zz > 0.0f) {
                    sx = fov__dot(d, pv->right) / zz;
                    sy = fov__dot(d, pv->up) / zz;
                    px = (sx - pv->tan4[0]) / (pv->tan4[1] - pv->tan4[0]) * (float)W - 0.5f;
                    py = (sy - pv->tan4[2]) / (pv->tan4[3] - pv->tan4[2]) * (float)H - 0.5f;
                    if (px > -1.0f && py > -1.0f && px < (float)W && py < (float)H) {
                        float rx = FOV__FLOOR(px + 0.5f), ry = FOV__FLOOR(py + 0.5f);
                        if (fov__absf(px - rx) < 1e-3f) px = rx; /* on a pixel centre */
                        if (fov__absf(py - ry) < 1e-3f) py = ry;
                        ix = (int)FOV__FLOOR(px); iy = (int)FOV__FLOOR(py);
                        fx = px - (float)ix; fy = py - (float)iy;
                        for (ty = 0; ty < 2; ++ty)
                            for (tx = 0; tx < 2; ++tx) {
                                int qx = ix + tx, qy = iy + ty;
                                float w = (tx ? fx : 1.0f - fx) * (ty ? fy : 1.0f - fy);
                                const float *q;
                                if (!(w > 0.0f) || qx < 0 || qy < 0 || qx >= (int)W ||
                                    qy >= (int)H)
                                    continue;
                                q = dn->hist[dn->cur ^ 1u] + FOVPT__DN_HIST *
                                        ((size_t)qy * W + (size_t)qx);
                                if (hit) {
                                    if (!(q[8] > 0.0f) || !(fov__absf(q[8] - dist) <= tol) ||
                                        !(fov__dot(q + 9, nrm) >= dn->cfg.normal_cos))
                                        continue;
                                } else if (!fov__is0(q[8])) {
                                    continue;
                                }
                                for (k = 0; k < 7; ++k)
                                    if (!fov__finite(q[k])) break;
                                if (k < 7) continue; /* never a non-finite history */
                                for (k = 0; k < 8; ++k) hs[k] += w * q[k];
                                hw += w;
                            }
                    }
                }
            }
            if (hw > 0.01f) {
                float m1, m2, inv = 1.0f / hw, vh;
                n = fov__minf(hs[5] * inv + 1.0f, FOVPT__DN_MAXN);
                a = fov__maxf(a, 1.0f / n);
                for (k = 0; k < 3; ++k) o[k] = (1.0f - a) * hs[k] * inv + a * in[k];
                m1 = (1.0f - a) * hs[3] * inv + a * l;
                m2 = (1.0f - a) * hs[4] * inv + a * l * l;
                o[3] = m1; o[4] = m2;
                if (var_in < 0.0f && n >= 4.0f) var_in = fov__maxf(0.0f, m2 - m1 * m1);
                vh = hs[6] * inv;
                o[6] = -1.0f;
                if (var_in >= 0.0f)
                    o[6] = (1.0f - a) * (1.0f - a) * fov__maxf(vh, 0.0f) + a * a * var_in;
            } else {
                for (k = 0; k < 3; ++k) o[k] = in[k];
                o[3] = l; o[4] = l * l;
                o[6] = var_in;
            }
            o[5] = n;
            if (dn->sel) { /* SURE: the candidate "no pass" (S = var) and the input */
                float *sp = dn->sel + FOVPT__DN_SEL * i;
                float v = gv && var_own >= dn->cfg.sure_min_spp ? fov__minf(o[6], FLT_MAX)
                                                                 : -1.0f;
                sp[0] = o[0]; sp[1] = o[1]; sp[2] = o[2];
                sp[3] = FLT_MAX;
                sp[6] = fovpt__lum(o);
                sp[4] = sp[5] = v * fovpt__dn_sure_w(sp[6]);
                sp[7] = v;
                sp[8] = 1.0f;
                sp[9] = 1.0f;
            }
            if (o[6] < 0.0f || (n < 4.0f && !(var_own >= FOVPT__DN_VAR_SPP))) {
                /* spatial: 3 x 3 pixels at the lattice spacing */
                int st = (int)fov__clampf(FOV__FLOOR(r + 0.5f), 1.0f, 4.0f), dx, dy, cnt = 0;
                float s1 = 0.0f, s2 = 0.0f;
                for (dy = -1; dy <= 1; ++dy)
                    for (dx = -1; dx <= 1; ++dx) {
                        int qx = (int)x + dx * st, qy = (int)y + dy * st;
                        const float *q;
                        float lq, cq[3];
                        if (qx < 0 || qy < 0 || qx >= (int)W || qy >= (int)H) continue;
                        q = fovpt__gin(dn->in, dn->in_stride, 3u, W, (uint32_t)qx, (uint32_t)qy);
                        for (k = 0; k < 3; ++k)
                            cq[k] = fov__finite(q[k]) ? fov__maxf(q[k], 0.0f) : 0.0f;
                        lq = fovpt__lum(cq);
                        s1 += lq; s2 += lq * lq; cnt++;
                    }
                s1 /= (float)cnt;
                s1 = fov__maxf(0.0f, s2 / (float)cnt - s1 * s1);
                o[6] = o[6] < 0.0f ? s1 : 0.5f * (o[6] + s1);
            }
            /* input noise below skip_noise display codes (the sRGB slope taken as
               min(12.92, 0.5 / sqrt(l)), the gamma-2 curve's), estimated from at least
               FOVPT__DN_VAR_SPP samples (the guide's spp, at least 1, times the history
               frames): no pass filters the pixel */
            if (fov__maxf(var_own, 1.0f) * n >= FOVPT__DN_VAR_SPP &&
                fovpt__dn_below_skip(dn, o[6], o[3], 1.0f))
                dn->coarse[i] = 0.0f;
            o[7] = 0.0f;
            o[8] = z;
            fovpt__copy3(o + 9, nrm);
            {
                float *pk = dn->pack + 8u * i;
                pk[0] = z;
                fovpt__copy3(pk + 1, nrm);
                if (g->albedo)
                    fovpt__copy3(pk + 4, fovpt__gin(g->albedo, g->albedo_stride, 3u, W, x, y));
                else pk[4] = pk[5] = pk[6] = 0.0f;
                pk[7] = 0.0f;
            }
            b[0] = o[0]; b[1] = o[1]; b[2] = o[2]; b[3] = o[6];
        }
    for (y = y0; y < y1; ++y) *fovpt__dn_rowmark(dn, y) = 1.0f;
    return FOV_OK;
}

/* the packed depth's slope at (x, y) (the smaller one-sided difference per axis) */
FOVPT__PRIV void fovpt__dn_pslope(const float *pk, uint32_t W, uint32_t H, uint32_t x, uint32_t y,
                                  float s[2])
{
    const float *p = pk + 8u * ((size_t)y * W + x);
    float z = p[0], a = FLT_MAX, b = FLT_MAX;
    if (x > 0) a = fov__absf(z - p[-8]);
    if (x + 1u < W) b = fov__absf(z - p[8]);
    s[0] = fov__minf(a, b) < FLT_MAX ? fov__minf(a, b) : 0.0f;
    a = b = FLT_MAX;
    if (y > 0) a = fov__absf(z - p[-(ptrdiff_t)(8u * W)]);
    if (y + 1u < H) b = fov__absf(z - p[8u * W]);
    s[1] = fov__minf(a, b) < FLT_MAX ? fov__minf(a, b) : 0.0f;
}

/* -ln(c) for c in [0.75, 1] (the normal stop c^phi_normal = exp(-phi_normal (-ln c)), folded
   into the tap's one exponential): u + u^2/2 + u^3/3 + u^4/4, u = 1 - c, below the true
   value by less than u^5 / (5 (1 - u)) <= 2.7e-4 (u = 1/4; with phi_normal 128 the weight's
   relative error is below 3.5 % at weights below e^-37 and below 1e-4 where the weight is
   above e^-10; with phi_normal 32 its absolute error is below 3.2e-6;
   tests/test_fovpt_denoise.c checks both against pow) */
FOVPT__PRIV float fovpt__dn_nlog(float c)
{
    float u = fov__maxf(1.0f - c, 0.0f);
    return u * (1.0f + u * (0.5f + u * (0.333333333f + u * 0.25f)));
}

FOVPT__PRIV int fovpt__dn_mini(int a, int b) { return a < b ? a : b; }

/* c^e for an integer e >= 1, by squaring */
FOVPT__PRIV float fovpt__dn_ipow(float c, uint32_t e)
{
    float r = 1.0f;
    while (e) {
        if (e & 1u) r *= c;
        c *= c;
        e >>= 1;
    }
    return r;
}

/* one a-trous pass's per-pass constants */
typedef struct fovpt__dnp {
    const float *src, *pk;
    float *dst, *dfr; /* dfr: SURE's centre weight fractions (stride FOVPT__DN_SEL) */
    float ia2, pn, fstep;
    uint32_t W, H, ipn;
    int step, alb, nfar, nser;
} fovpt__dnp;

/* a pixel's own terms of a pass: whether the pass filters it, the luminance stop's scale,
   the kernel radius and the depth stop's denominators per |offset| */
typedef struct fovpt__dnl {
    float lp, sig, zp, idz[3][3];
    int on, rad, hitp;
} fovpt__dnl;

/* after the first pass: the running estimate's noise (its variance, as display codes like
   skip_noise) is already below skip_noise: the pass leaves the pixel as it is */
FOVPT__PRIV int fovpt__dn_quiet(const fovpt_denoise *dn, const fovpt__dnp *P, const float *p)
{
    return P->step > 1 && fovpt__dn_below_skip(dn, p[3], fovpt__lum(p), FOVPT__DN_QUIET);
}

FOVPT__PRIV void fovpt__dn_lane(const fovpt_denoise *dn, const fovpt__dnp *P, uint32_t x,
                                uint32_t y, fovpt__dnl *L)
{
    uint32_t W = P->W, H = P->H;
    size_t i = (size_t)y * W + x;
    const float *src = P->src, *p = src + 4u * i;
    const float *r0 = src + 4u * (size_t)(y > 0 ? y - 1u : 0u) * W;
    const float *r1 = src + 4u * (size_t)y * W;
    const float *r2 = src + 4u * (size_t)(y + 1u < H ? y + 1u : y) * W;
    uint32_t xm = x > 0 ? x - 1u : 0u, xp = x + 1u < W ? x + 1u : x;
    float v3, sl[2];
    int a, b;
    L->on = !(P->fstep > dn->cfg.fovea_step * dn->coarse[i]) && !fovpt__dn_quiet(dn, P, p);
    if (!L->on) return; /* passed through: nothing else needed */
    L->zp = P->pk[8u * i];
    L->hitp = L->zp > 0.0f;
    /* the variance's 3 x 3 Gaussian (edge pixels repeated) */
    v3 = 0.25f * (0.25f * r0[4u * xm + 3u] + 0.5f * r0[4u * x + 3u] + 0.25f * r0[4u * xp + 3u]) +
         0.5f * (0.25f * r1[4u * xm + 3u] + 0.5f * r1[4u * x + 3u] + 0.25f * r1[4u * xp + 3u]) +
         0.25f * (0.25f * r2[4u * xm + 3u] + 0.5f * r2[4u * x + 3u] + 0.25f * r2[4u * xp + 3u]);
    v3 = fov__maxf(v3, 0.0f);
    L->lp = fovpt__lum(p);
    L->sig = 1.0f / (dn->cfg.phi_lum * FOV__SQRT(v3) + 1e-6f);
    L->rad = dn->coarse[i] >= dn->cfg.r_small ? 1 : 2;
    for (b = 0; b < 3; ++b)
        for (a = 0; a < 3; ++a) L->idz[b][a] = 0.0f;
    if (L->hitp) {
        fovpt__dn_pslope(P->pk, W, H, x, y, sl);
        sl[0] *= dn->cfg.phi_depth * P->fstep; sl[1] *= dn->cfg.phi_depth * P->fstep;
        for (b = 0; b <= L->rad; ++b)
            for (a = 0; a <= L->rad; ++a)
                L->idz[b][a] = 1.0f / (sl[0] * (float)a + sl[1] * (float)b + 1e-3f * L->zp);
    }
}

/* the scalar pass at one pixel (the reference of the SIMD path) */
FOVPT__PRIV void fovpt__dn_px(const fovpt_denoise *dn, const fovpt__dnp *P, uint32_t x,
                              uint32_t y)
{
    static const float h5[5] = { 0.0625f, 0.25f, 0.375f, 0.25f, 0.0625f };
    static const float h3[3] = { 0.25f, 0.5f, 0.25f };
    uint32_t W = P->W, H = P->H, k;
    size_t i = (size_t)y * W + x;
    const float *src = P->src, *pk = P->pk, *p = src + 4u * i, *gp = pk + 8u * i, *hk;
    float *o = P->dst + 4u * i, ws = 0.0f, wv = 0.0f, acc[3] = { 0.0f, 0.0f, 0.0f };
    float sa = 0.0f, sb = 0.0f; /* SURE: sum w sgn(lp - lq), sum w sgn(lp - lq) lq */
    int dx, dy, dx0, dx1, dy0, dy1, rad, step = P->step;
    fovpt__dnl L;
    fovpt__dn_lane(dn, P, x, y, &L);
    if (!L.on) { /* not at this pixel */
        o[0] = p[0]; o[1] = p[1]; o[2] = p[2]; o[3] = p[3];
        if (P->dfr) P->dfr[FOVPT__DN_SEL * i] = 1.0f;
        return;
    }
    rad = L.rad;
    hk = rad == 1 ? h3 : h5;
    /* the taps inside the image */
    dx0 = -fovpt__dn_mini(rad, (int)x / step);
    dx1 = fovpt__dn_mini(rad, (int)(W - 1u - x) / step);
    dy0 = -fovpt__dn_mini(rad, (int)y / step);
    dy1 = fovpt__dn_mini(rad, (int)(H - 1u - y) / step);
    for (dy = dy0; dy <= dy1; ++dy) {
        size_t row = (size_t)((int)y + dy * step) * W;
        float hy = hk[dy + rad];
        int ady = dy < 0 ? -dy : dy;
        for (dx = dx0; dx <= dx1; ++dx) {
            size_t j = row + (size_t)((int)x + dx * step);
            const float *q = src + 4u * j, *gq = pk + 8u * j;
            float w = hk[dx + rad] * hy, ex, lq;
            if (dx || dy) {
                if (L.hitp != (gq[0] > 0.0f)) continue;
                lq = fovpt__lum(q);
                ex = fov__absf(L.lp - lq) * L.sig;
                if (L.hitp) {
                    float c = gp[1] * gq[1] + gp[2] * gq[2] + gp[3] * gq[3];
                    ex += fov__absf(L.zp - gq[0]) * L.idz[ady][dx < 0 ? -dx : dx];
                    if (P->nser && c >= 0.75f) {
                        ex += P->pn * fovpt__dn_nlog(c);
                    } else {
                        if ((P->nfar && c < 0.75f) || !(c > 0.0f)) continue;
                        w *= P->ipn ? fovpt__dn_ipow(c, P->ipn) : FOV__POW(c, P->pn);
                    }
                }
                if (P->alb) {
                    float a0 = gp[4] - gq[4], a1 = gp[5] - gq[5], a2 = gp[6] - gq[6];
                    ex += (a0 * a0 + a1 * a1 + a2 * a2) * P->ia2;
                }
                if (!(ex < 30.0f)) continue; /* weight below 1e-13 */
                w *= fovpt__exp_neg(ex);
                if (!(w > 1e-13f)) continue;
                if (P->dfr) {
                    float t = w * (L.lp > lq ? 1.0f : L.lp < lq ? -1.0f : 0.0f);
                    sa += t;
                    sb += t * lq;
                }
            }
            for (k = 0; k < 3; ++k) acc[k] += w * q[k];
            ws += w;
            wv += w * w * fov__maxf(q[3], 0.0f);
        }
    }
    for (k = 0; k < 3; ++k) o[k] = acc[k] / ws;
    o[3] = wv / (ws * ws);
    if (P->dfr) { /* d out / d centre: the centre weight and the luminance stop's slope */
        float fl = 0.2126f * o[0] + 0.7152f * o[1] + 0.0722f * o[2];
        float d = (hk[rad] * hk[rad] + L.sig * (fl * sa - sb)) / ws;
        d = d > 0.0f ? d : 0.0f;
        P->dfr[FOVPT__DN_SEL * i] = d < 1.0f ? d : 1.0f;
    }
}

#if FOVPT__DN_SSE2
/* fovpt__exp_neg on 4 lanes for x in [0, 30) (the same operations: bit-identical there) */
FOVPT__PRIV __m128 fovpt__dn_exp4(__m128 x)
{
    __m128 t = _mm_mul_ps(x, _mm_set1_ps(1.44269504f)), f, p;
    __m128i i = _mm_cvttps_epi32(t);
    f = _mm_mul_ps(_mm_sub_ps(t, _mm_cvtepi32_ps(i)), _mm_set1_ps(-0.693147181f));
    p = _mm_add_ps(_mm_set1_ps(0.00833333333f), _mm_mul_ps(f, _mm_set1_ps(0.00138888889f)));
    p = _mm_add_ps(_mm_set1_ps(0.0416666667f), _mm_mul_ps(f, p));
    p = _mm_add_ps(_mm_set1_ps(0.166666667f), _mm_mul_ps(f, p));
    p = _mm_add_ps(_mm_set1_ps(0.5f), _mm_mul_ps(f, p));
    p = _mm_add_ps(_mm_set1_ps(1.0f), _mm_mul_ps(f, p));
    p = _mm_add_ps(_mm_set1_ps(1.0f), _mm_mul_ps(f, p));
    i = _mm_slli_epi32(_mm_sub_epi32(_mm_set1_epi32(127), i), 23); /* 2^-i */
    return _mm_mul_ps(p, _mm_castsi128_ps(i));
}

FOVPT__PRIV __m128 fovpt__dn_sel4(__m128 m, __m128 a, __m128 b)
{
    return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b));
}

/* the pass at pixels x .. x + 3 of row y, all of whose taps (5 x 5, or 3 x 3 where all 4 take
   those) lie inside the image columns (rows clipped as in fovpt__dn_px): the scalar
   operations lane by lane, in the same order, so the result is bit-identical to fovpt__dn_px
   as long as the compiler does not contract the scalar code into FMA (the implementation
   turns that off: NUMERICS) */
FOVPT__PRIV void fovpt__dn_px4(const fovpt_denoise *dn, const fovpt__dnp *P, uint32_t x,
                               uint32_t y)
{
    static const float h5[5] = { 0.0625f, 0.25f, 0.375f, 0.25f, 0.0625f };
    static const float h3[5] = { 0.0f, 0.25f, 0.5f, 0.25f, 0.0f };
    uint32_t W = P->W, H = P->H, l, b;
    size_t i = (size_t)y * W + x;
    const float *src = P->src, *pk = P->pk;
    float *o = P->dst + 4u * i;
    __m128 hv[5], idz[3][3], lp, sig, zp, hitp, n1, n2, n3, a0, a1, a2, r, g, bl, v;
    __m128 acc0, acc1, acc2, ws, wv, q0, q1, q2, q3, zero = _mm_setzero_ps(), sa, sb;
    __m128 c75 = _mm_set1_ps(0.75f), pn = _mm_set1_ps(P->pn), ia2 = _mm_set1_ps(P->ia2);
    __m128 cr = _mm_loadu_ps(dn->coarse + i), rad1, sl0, sl1, v3;
    float t[4];
    int dx, dy, dy0, dy1, step = P->step, on, any_hit, rd;
    /* fovpt__dn_lane's terms, 4 lanes at once */
    on = _mm_movemask_ps(_mm_cmpngt_ps(_mm_set1_ps(P->fstep),
                                       _mm_mul_ps(_mm_set1_ps(dn->cfg.fovea_step), cr)));
    for (l = 0; l < 4u; ++l)
        if ((on >> l & 1) && fovpt__dn_quiet(dn, P, src + 4u * (i + l))) on &= ~(1 << l);
    if (!on) {
        for (l = 0; l < 16u; ++l) o[l] = src[4u * i + l];
        if (P->dfr)
            for (l = 0; l < 4u; ++l) P->dfr[FOVPT__DN_SEL * (i + l)] = 1.0f;
        return;
    }
    rad1 = _mm_cmpge_ps(cr, _mm_set1_ps(dn->cfg.r_small));
    for (dx = 0; dx < 5; ++dx)
        hv[dx] = fovpt__dn_sel4(rad1, _mm_set1_ps(h3[dx]), _mm_set1_ps(h5[dx]));
    { /* the variance's 3 x 3 Gaussian (x - 1 and x + 4 inside the image) */
        const float *rw[3];
        __m128 vr[3];
        rw[0] = src + 4u * (size_t)(y > 0 ? y - 1u : 0u) * W;
        rw[1] = src + 4u * (size_t)y * W;
        rw[2] = src + 4u * (size_t)(y + 1u < H ? y + 1u : y) * W;
        for (b = 0; b < 3; ++b) {
            float e[6];
            for (l = 0; l < 6; ++l) e[l] = rw[b][4u * (x + l - 1u) + 3u];
            vr[b] = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(0.25f), _mm_loadu_ps(e)),
                                          _mm_mul_ps(_mm_set1_ps(0.5f), _mm_loadu_ps(e + 1))),
                               _mm_mul_ps(_mm_set1_ps(0.25f), _mm_loadu_ps(e + 2)));
        }
        v3 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(0.25f), vr[0]),
                                   _mm_mul_ps(_mm_set1_ps(0.5f), vr[1])),
                        _mm_mul_ps(_mm_set1_ps(0.25f), vr[2]));
        _mm_storeu_ps(t, _mm_max_ps(v3, zero));
        for (l = 0; l < 4; ++l) t[l] = FOV__SQRT(t[l]); /* the scalar square root (a hook) */
        sig = _mm_div_ps(_mm_set1_ps(1.0f),
                         _mm_add_ps(_mm_mul_ps(_mm_set1_ps(dn->cfg.phi_lum), _mm_loadu_ps(t)),
                                    _mm_set1_ps(1e-6f)));
    }
    q0 = _mm_loadu_ps(src + 4u * i);
    q1 = _mm_loadu_ps(src + 4u * i + 4u);
    q2 = _mm_loadu_ps(src + 4u * i + 8u);
    q3 = _mm_loadu_ps(src + 4u * i + 12u);
    _MM_TRANSPOSE4_PS(q0, q1, q2, q3);
    lp = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(0.2126f), q0),
                               _mm_mul_ps(_mm_set1_ps(0.7152f), q1)),
                    _mm_mul_ps(_mm_set1_ps(0.0722f), q2));
    q0 = _mm_loadu_ps(pk + 8u * i);
    q1 = _mm_loadu_ps(pk + 8u * i + 8u);
    q2 = _mm_loadu_ps(pk + 8u * i + 16u);
    q3 = _mm_loadu_ps(pk + 8u * i + 24u);
    _MM_TRANSPOSE4_PS(q0, q1, q2, q3);
    zp = q0; n1 = q1; n2 = q2; n3 = q3;
    hitp = _mm_cmpgt_ps(zp, zero);
    any_hit = _mm_movemask_ps(hitp);
    a0 = a1 = a2 = zero;
    if (P->alb) {
        q0 = _mm_loadu_ps(pk + 8u * i + 4u);
        q1 = _mm_loadu_ps(pk + 8u * i + 12u);
        q2 = _mm_loadu_ps(pk + 8u * i + 20u);
        q3 = _mm_loadu_ps(pk + 8u * i + 28u);
        _MM_TRANSPOSE4_PS(q0, q1, q2, q3);
        a0 = q0; a1 = q1; a2 = q2;
    }
    if (any_hit) { /* fovpt__dn_pslope and the depth stop's denominators */
        __m128 fm = _mm_set1_ps(FLT_MAX), d0, d1, mn;
        __m128 sc = _mm_set1_ps(dn->cfg.phi_depth * P->fstep);
        float e[6];
        for (l = 0; l < 6; ++l) e[l] = pk[8u * (i + l - 1u)];
        d0 = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_sub_ps(zp, _mm_loadu_ps(e)));
        d1 = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_sub_ps(zp, _mm_loadu_ps(e + 2)));
        mn = _mm_min_ps(d0, d1);
        sl0 = _mm_and_ps(_mm_cmplt_ps(mn, fm), mn);
        d0 = d1 = fm;
        if (y > 0) {
            for (l = 0; l < 4; ++l) e[l] = pk[8u * (i + l - W)];
            d0 = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_sub_ps(zp, _mm_loadu_ps(e)));
        }
        if (y + 1u < H) {
            for (l = 0; l < 4; ++l) e[l] = pk[8u * (i + l + W)];
            d1 = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_sub_ps(zp, _mm_loadu_ps(e)));
        }
        mn = _mm_min_ps(d0, d1);
        sl1 = _mm_and_ps(_mm_cmplt_ps(mn, fm), mn);
        sl0 = _mm_mul_ps(sl0, sc);
        sl1 = _mm_mul_ps(sl1, sc);
        for (b = 0; b < 3; ++b)
            for (l = 0; l < 3; ++l)
                idz[b][l] = _mm_div_ps(
                    _mm_set1_ps(1.0f),
                    _mm_add_ps(_mm_add_ps(_mm_mul_ps(sl0, _mm_set1_ps((float)l)),
                                          _mm_mul_ps(sl1, _mm_set1_ps((float)b))),
                               _mm_mul_ps(_mm_set1_ps(1e-3f), zp)));
    }
    acc0 = acc1 = acc2 = ws = wv = sa = sb = zero;
    /* every lane 3 x 3: only those taps (the 5 x 5 ring's weights are 0 in every lane) */
    rd = _mm_movemask_ps(rad1) == 15 ? 1 : 2;
    dy0 = -fovpt__dn_mini(rd, (int)y / step);
    dy1 = fovpt__dn_mini(rd, (int)(H - 1u - y) / step);
    for (dy = dy0; dy <= dy1; ++dy) {
        size_t row = (size_t)((int)y + dy * step) * W;
        __m128 hy = hv[dy + 2];
        int ady = dy < 0 ? -dy : dy;
        for (dx = -rd; dx <= rd; ++dx) {
            size_t j = row + (size_t)((int)x + dx * step);
            const float *q = src + 4u * j, *gq = pk + 8u * j;
            __m128 w = _mm_mul_ps(hv[dx + 2], hy), ex, z, c, live, d, e;
            if ((dx || dy) && !_mm_movemask_ps(_mm_cmpgt_ps(w, zero))) continue;
            q0 = _mm_loadu_ps(q);
            q1 = _mm_loadu_ps(q + 4);
            q2 = _mm_loadu_ps(q + 8);
            q3 = _mm_loadu_ps(q + 12);
            _MM_TRANSPOSE4_PS(q0, q1, q2, q3); /* r, g, b, var of the 4 taps */
            if (dx || dy) {
                r = _mm_loadu_ps(gq);
                g = _mm_loadu_ps(gq + 8);
                bl = _mm_loadu_ps(gq + 16);
                v = _mm_loadu_ps(gq + 24);
                _MM_TRANSPOSE4_PS(r, g, bl, v); /* depth, normal */
                z = r;
                live = _mm_xor_ps(hitp, _mm_cmpgt_ps(z, zero)); /* hit differs: dropped */
                live = _mm_andnot_ps(live, _mm_cmpgt_ps(w, zero));
                d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(0.2126f), q0),
                                          _mm_mul_ps(_mm_set1_ps(0.7152f), q1)),
                               _mm_mul_ps(_mm_set1_ps(0.0722f), q2));
                ex = _mm_mul_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_sub_ps(lp, d)), sig);
                if (any_hit) {
                    __m128 exh, pw;
                    int adx = dx < 0 ? -dx : dx;
                    c = _mm_add_ps(_mm_add_ps(_mm_mul_ps(n1, g), _mm_mul_ps(n2, bl)),
                                   _mm_mul_ps(n3, v));
                    exh = _mm_add_ps(ex, _mm_mul_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f),
                                                                  _mm_sub_ps(zp, z)),
                                                    idz[ady][adx]));
                    pw = hitp; /* the lanes taking the exact power */
                    if (P->nser) {
                        __m128 ser = _mm_cmpge_ps(c, c75);
                        __m128 u = _mm_max_ps(_mm_sub_ps(_mm_set1_ps(1.0f), c), zero), s;
                        s = _mm_mul_ps(u, _mm_set1_ps(0.25f));
                        s = _mm_add_ps(_mm_set1_ps(0.333333333f), s);
                        s = _mm_add_ps(_mm_set1_ps(0.5f), _mm_mul_ps(u, s));
                        s = _mm_add_ps(_mm_set1_ps(1.0f), _mm_mul_ps(u, s));
                        s = _mm_mul_ps(u, s);
                        exh = fovpt__dn_sel4(ser, _mm_add_ps(exh, _mm_mul_ps(pn, s)), exh);
                        pw = _mm_andnot_ps(ser, pw);
                    }
                    if (_mm_movemask_ps(pw)) {
                        __m128 drop = _mm_cmpngt_ps(c, zero), cc = c, rr = _mm_set1_ps(1.0f);
                        uint32_t e2 = P->ipn;
                        if (P->nfar) drop = _mm_or_ps(drop, _mm_cmplt_ps(c, c75));
                        live = _mm_andnot_ps(_mm_and_ps(pw, drop), live);
                        if (e2) { /* fovpt__dn_ipow */
                            while (e2) {
                                if (e2 & 1u) rr = _mm_mul_ps(rr, cc);
                                cc = _mm_mul_ps(cc, cc);
                                e2 >>= 1;
                            }
                            w = fovpt__dn_sel4(pw, _mm_mul_ps(w, rr), w);
                        }
                        /* else nfar: every power lane was dropped */
                    }
                    ex = fovpt__dn_sel4(hitp, exh, ex);
                }
                if (P->alb) {
                    __m128 e0, e1, e3;
                    r = _mm_loadu_ps(gq + 4);
                    g = _mm_loadu_ps(gq + 12);
                    bl = _mm_loadu_ps(gq + 20);
                    v = _mm_loadu_ps(gq + 28);
                    _MM_TRANSPOSE4_PS(r, g, bl, v);
                    e0 = _mm_sub_ps(a0, r); e1 = _mm_sub_ps(a1, g); e3 = _mm_sub_ps(a2, bl);
                    e0 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(e0, e0), _mm_mul_ps(e1, e1)),
                                    _mm_mul_ps(e3, e3));
                    ex = _mm_add_ps(ex, _mm_mul_ps(e0, ia2));
                }
                live = _mm_and_ps(live, _mm_cmplt_ps(ex, _mm_set1_ps(30.0f)));
                if (!_mm_movemask_ps(live)) continue;
                e = fovpt__dn_exp4(_mm_and_ps(live, ex));
                w = _mm_mul_ps(w, e);
                live = _mm_and_ps(live, _mm_cmpgt_ps(w, _mm_set1_ps(1e-13f)));
                w = _mm_and_ps(live, w);
                if (P->dfr) { /* fovpt__dn_px's sa, sb (a skipped lane adds +-0) */
                    __m128 sg = _mm_or_ps(_mm_and_ps(_mm_cmpgt_ps(lp, d), _mm_set1_ps(1.0f)),
                                          _mm_and_ps(_mm_cmplt_ps(lp, d), _mm_set1_ps(-1.0f)));
                    __m128 tt = _mm_mul_ps(w, sg);
                    sa = _mm_add_ps(sa, tt);
                    sb = _mm_add_ps(sb, _mm_and_ps(live, _mm_mul_ps(tt, d)));
                }
            }
            /* a lane whose tap the scalar pass skips adds an exact +0, not +0 times its
               value (an infinite value would make NaN); the centre tap is every lane's */
            if (!(dx || dy)) live = _mm_cmpeq_ps(zero, zero);
            acc0 = _mm_add_ps(acc0, _mm_and_ps(live, _mm_mul_ps(w, q0)));
            acc1 = _mm_add_ps(acc1, _mm_and_ps(live, _mm_mul_ps(w, q1)));
            acc2 = _mm_add_ps(acc2, _mm_and_ps(live, _mm_mul_ps(w, q2)));
            ws = _mm_add_ps(ws, w);
            wv = _mm_add_ps(wv, _mm_and_ps(live, _mm_mul_ps(_mm_mul_ps(w, w),
                                                              _mm_max_ps(q3, zero))));
        }
    }
    q0 = _mm_div_ps(acc0, ws);
    q1 = _mm_div_ps(acc1, ws);
    q2 = _mm_div_ps(acc2, ws);
    q3 = _mm_div_ps(wv, _mm_mul_ps(ws, ws));
    if (P->dfr) { /* fovpt__dn_px's centre derivative, lane by lane */
        __m128 fl = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(0.2126f), q0),
                                          _mm_mul_ps(_mm_set1_ps(0.7152f), q1)),
                               _mm_mul_ps(_mm_set1_ps(0.0722f), q2));
        __m128 dd = _mm_div_ps(_mm_add_ps(_mm_mul_ps(hv[2], hv[2]),
                                          _mm_mul_ps(sig, _mm_sub_ps(_mm_mul_ps(fl, sa), sb))),
                               ws);
        _mm_storeu_ps(t, _mm_min_ps(_mm_max_ps(dd, zero), _mm_set1_ps(1.0f)));
    }
    _MM_TRANSPOSE4_PS(q0, q1, q2, q3);
    _mm_storeu_ps(o, q0);
    _mm_storeu_ps(o + 4, q1);
    _mm_storeu_ps(o + 8, q2);
    _mm_storeu_ps(o + 12, q3);
    for (l = 0; l < 4; ++l) {
        if (P->dfr) P->dfr[FOVPT__DN_SEL * (i + l)] = t[l];
        if (!(on >> l & 1)) {
            for (b = 0; b < 4; ++b) o[4u * l + b] = src[4u * (i + l) + b];
            if (P->dfr) P->dfr[FOVPT__DN_SEL * (i + l)] = 1.0f;
        }
    }
}
#endif

/* the pass over rows [y0, y1); simd 0: the scalar reference alone */
FOVPT__PRIV void fovpt__dn_atrous(fovpt_denoise *dn, uint32_t pass, uint32_t y0, uint32_t y1,
                                  int simd)
{
    fovpt__dnp P;
    uint32_t x, y;
    P.W = dn->cfg.width; P.H = dn->cfg.height;
    P.alb = dn->guide.albedo != NULL;
    P.pk = dn->pack;
    P.src = dn->buf[pass & 1u];
    P.dst = dn->buf[(pass & 1u) ^ 1u];
    P.dfr = dn->sel ? dn->sel + 9 : NULL;
    P.step = 1 << pass;
    P.fstep = (float)P.step;
    P.ia2 = 1.0f / (dn->cfg.phi_albedo * dn->cfg.phi_albedo);
    P.pn = dn->cfg.phi_normal;
    P.nfar = P.pn * 0.287682072f >= 30.0f; /* c < 3/4: c^phi_normal below e^-30, dropped */
    P.nser = P.pn >= 32.0f; /* the series (weight error below 3.2e-6; smaller pn: exact power) */
    P.ipn = 0;
    if (P.pn <= 4096.0f && fov__is0(P.pn - FOV__FLOOR(P.pn))) P.ipn = (uint32_t)P.pn;
#if FOVPT__DN_SSE2
    /* 4 pixels at once where their taps lie inside the columns (5 x 5, or 3 x 3 where all 4
       take those) and the normal stop needs no powf (an integer phi_normal or one whose far
       taps are dropped) */
    if (!(P.ipn || P.nfar)) simd = 0;
#else
    (void)simd;
#endif
    for (y = y0; y < y1; ++y) {
        x = 0;
#if FOVPT__DN_SSE2
        if (simd) {
            /* 4 at once where their 5 x 5 taps lie inside the columns, or their 3 x 3 taps
               where all 4 take those (the periphery's image borders) */
            uint32_t m = 2u * (uint32_t)P.step, s1 = (uint32_t)P.step;
            const float *cr = dn->coarse + (size_t)y * P.W;
            float rs = dn->cfg.r_small;
            while (x + 3u + s1 < P.W) {
                if ((x >= m && x + 3u + m < P.W) ||
                    (x >= s1 && cr[x] >= rs && cr[x + 1u] >= rs && cr[x + 2u] >= rs &&
                     cr[x + 3u] >= rs)) {
                    fovpt__dn_px4(dn, &P, x, y);
                    x += 4u;
                } else {
                    fovpt__dn_px(dn, &P, x++, y);
                }
            }
        }
#endif
        for (; x < P.W; ++x) fovpt__dn_px(dn, &P, x, y);
    }
}

/* SURE: the mean of the raw SURE in slot (4 or 5) over the window around (x, y) (the
   pixels with a guide var) */
FOVPT__PRIV float fovpt__dn_sure_mean(const fovpt_denoise *dn, uint32_t x, uint32_t y,
                                      uint32_t slot)
{
    int R = (int)dn->cfg.sure_radius, W = (int)dn->cfg.width, H = (int)dn->cfg.height;
    int qx, qy, x0 = (int)x - R, x1 = (int)x + R, ya = (int)y - R, yb = (int)y + R, n = 0;
    float s = 0.0f;
    if (x0 < 0) x0 = 0;
    if (ya < 0) ya = 0;
    if (x1 > W - 1) x1 = W - 1;
    if (yb > H - 1) yb = H - 1;
    for (qy = ya; qy <= yb; ++qy)
        for (qx = x0; qx <= x1; ++qx) {
            const float *q = dn->sel + FOVPT__DN_SEL * ((size_t)qy * (size_t)W + (size_t)qx);
            if (!(q[7] >= 0.0f)) continue;
            s += q[slot];
            n++;
        }
    if (!n) return FLT_MAX;
    s /= (float)n;
    return s;
}

/* SURE, rows [y0, y1): the candidate in buf[pass & 1] (the output of pass - 1, or the
   input for pass 0) replaces the best so far where its smoothed SURE is lower */
FOVPT__PRIV void fovpt__dn_sure_pick(fovpt_denoise *dn, uint32_t pass, uint32_t y0, uint32_t y1)
{
    uint32_t x, y, W = dn->cfg.width;
    const float *src = dn->buf[pass & 1u];
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            float *sp = dn->sel + FOVPT__DN_SEL * i, m;
            if (!(sp[7] >= 0.0f)) continue;
            m = fovpt__dn_sure_mean(dn, x, y, 4u + (pass & 1u));
            if (m < sp[3]) {
                sp[0] = src[4u * i]; sp[1] = src[4u * i + 1u]; sp[2] = src[4u * i + 2u];
                sp[3] = m;
            }
        }
}

/* SURE, rows [y0, y1) after pass `pass`: the output's derivative by its input at the
   pixel (the product of the passes' centre weight fractions) and its raw SURE
   (F - y)^2 - var + 2 var dF/dy into slot 4 + ((pass + 1) & 1) */
FOVPT__PRIV void fovpt__dn_sure_raw(fovpt_denoise *dn, uint32_t pass, uint32_t y0, uint32_t y1)
{
    uint32_t x, y, W = dn->cfg.width, slot = 4u + ((pass + 1u) & 1u);
    const float *dst = dn->buf[(pass & 1u) ^ 1u];
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            float *sp = dn->sel + FOVPT__DN_SEL * i, d, v = sp[7], e;
            if (!(v >= 0.0f)) continue;
            sp[8] *= sp[9];
            d = fovpt__lum(dst + 4u * i) - sp[6];
            e = (d * d - v + 2.0f * v * sp[8]) * fovpt__dn_sure_w(sp[6]);
            sp[slot] = fov__finite(e) ? e : FLT_MAX;
        }
}

FOVPT_API fov_result fovpt_denoise_atrous_rows(fovpt_denoise *dn, uint32_t pass, uint32_t y0,
                                               uint32_t y1)
{
    if (!dn) return FOV_ERR_NULL;
    if (!dn->in_frame)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_atrous_rows: call fovpt_denoise_frame first");
    if (pass >= dn->passes)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_atrous_rows: pass must be below fovpt_denoise_passes");
    if (y0 > y1 || y1 > dn->cfg.height)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_atrous_rows: needs y0 <= y1 <= height");
    if (!fovpt__dn_phase_ok(dn, y0, y1, 2.0f + (float)pass))
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_atrous_rows: a row has not finished the previous phase (temporal "
                    "or pass - 1) or already ran a later pass");
    if (dn->sel) fovpt__dn_sure_pick(dn, pass, y0, y1);
    fovpt__dn_atrous(dn, pass, y0, y1, 1);
    if (dn->sel) fovpt__dn_sure_raw(dn, pass, y0, y1);
    for (; y0 < y1; ++y0) *fovpt__dn_rowmark(dn, y0) = 2.0f + (float)pass;
    return FOV_OK;
}

FOVPT_API fov_result fovpt_denoise_resolve_rows(const fovpt_denoise *dn, uint32_t y0,
                                                uint32_t y1, const fovpt_output *out)
{
    uint32_t x, y, W;
    const float *src;
    if (!dn) return FOV_ERR_NULL;
    if (!out) FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_NULL, "denoise_resolve_rows: out is NULL");
    if (!dn->in_frame)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_resolve_rows: call fovpt_denoise_frame first");
    W = dn->cfg.width;
    if (y0 > y1 || y1 > dn->cfg.height)
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_resolve_rows: needs y0 <= y1 <= height");
    if (fovpt__gstride_bad(out->rgb_stride, 3u, W) || fovpt__gstride_bad(out->rgb8_stride, 3u, W))
        FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                    "denoise_resolve_rows: out.rgb_stride or rgb8_stride below 3 * width");
    for (y = y0; y < y1; ++y)
        if (!fovpt__dn_feq(*fovpt__dn_rowmark(dn, y), 1.0f + (float)dn->passes))
            FOVPT__FAIL(&dn->cfg.logger, FOV_ERR_INVALID_ARG,
                        "denoise_resolve_rows: a row has not finished the temporal phase and "
                        "every a-trous pass");
    src = dn->buf[dn->passes & 1u];
    for (y = y0; y < y1; ++y)
        for (x = 0; x < W; ++x) {
            const float *c = src + 4u * ((size_t)y * W + x);
            if (dn->sel && dn->passes) { /* SURE: the last pass's output or the best */
                const float *sp = dn->sel + FOVPT__DN_SEL * ((size_t)y * W + x);
                if (sp[7] >= 0.0f &&
                    !(fovpt__dn_sure_mean(dn, x, y, 4u + (dn->passes & 1u)) < sp[3]))
                    c = sp;
            }
            if (out->rgb) {
                float *o =
                    out->rgb + (size_t)y * (out->rgb_stride ? out->rgb_stride : 3u * W) + 3u * x;
                o[0] = c[0]; o[1] = c[1]; o[2] = c[2];
            }
            if (out->rgb8) {
                uint8_t *o =
                    out->rgb8 + (size_t)y * (out->rgb8_stride ? out->rgb8_stride : 3u * W) + 3u * x;
                o[0] = fovpt__srgb8(c[0]); o[1] = fovpt__srgb8(c[1]); o[2] = fovpt__srgb8(c[2]);
            }
        }
    return FOV_OK;
}

FOVPT_API fov_result fovpt_denoise_run(fovpt_denoise *dn, const fovpt_output *out)
{
    fov_result e;
    uint32_t i;
    if (!dn) return FOV_ERR_NULL;
    e = fovpt_denoise_temporal_rows(dn, 0, dn->cfg.height);
    for (i = 0; e == FOV_OK && i < dn->passes; ++i)
        e = fovpt_denoise_atrous_rows(dn, i, 0, dn->cfg.height);
    if (e != FOV_OK) return e;
    return fovpt_denoise_resolve_rows(dn, 0, dn->cfg.height, out);
}

#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif
#endif /* FOVPT_IMPLEMENTATION */

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
