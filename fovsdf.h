/* fovsdf.h - v0.10.1 - sphere tracing of signed distance functions, built for foveation
                       - MIT or public domain (see end of file)

   Do this:
      #define FOVSDF_IMPLEMENTATION   (or #define FOV_IMPL for all fov headers)
   before you include this file in *one* C or C++ file to create the implementation.

QUICK START
      #define FOVSDF_IMPLEMENTATION
      #include "fovsdf.h"
      #include <math.h>                                      // sqrtf (also with FOV_NO_LIBM)

      static float my_sdf(const float p[3], void *user)      // a unit sphere
      { (void)user; return sqrtf(p[0]*p[0] + p[1]*p[1] + p[2]*p[2]) - 1.0f; }

      fovsdf_scene scene;  fovsdf_scene_init(&scene);  scene.dist = my_sdf;
      fovsdf_camera cam;   fovsdf_camera_init(&cam, 320, 240);  // = fov_camera, shared
      cam.pos[2] = 3.0f;     // from (0,0,3) at the origin: world +x right, +y up in the image
      fovsdf_config cfg = fovsdf_config_default();           // classic sphere tracing
      fovsdf_ctx ctx;
      fov_gaze gaze = { 160.0f, 120.0f };
      if (fovsdf_init(&ctx, &cfg, &scene, &cam, gaze, NULL, 0) != FOV_OK) ...
      fovsdf_output out;   fovsdf_output_init(&out);  out.rgb8 = pixels;  // 320*240*3 bytes
      fovsdf_stats st;     fovsdf_stats_init(&st);    // counters, optional (NULL: none)
      fovsdf_render_rows(&ctx, 0, 240, &out, &st);           // split rows over threads if you like

   See examples/sdf_basic.c (a complete program) and examples/sdf_scenes.c (the built-in
   scenes, all tracers, written to image files).

   No eye tracker: fixed foveation, the gaze at the display's axis point and a larger fovea
      fovsdf_gaze_fixed(&cfg.display, 320, 240, &gaze);                 // the screen centre
      fovsdf_config_gaze_margin(&base, FOV_GAZE_FIXED_MARGIN_DEG, &cfg); // fovea + 15 deg
   With one: filter its samples and grow the fovea by the latency margin per frame, then
   fovsdf_init as every frame (GAZE INPUT; keep counting cfg.frame).
   A head-mounted display: per eye tan_left .. tan_top, eye_offset and its own gaze (see
   fovsdf_camera, examples/sdf_stereo.c: both eyes side by side).

WHAT IT DOES
   - Sphere tracing (Hart 1996) of a signed distance function (SDF) given as a C callback, or
     as a tree of built-in primitives and operators compiled into a small program that skips
     far-away objects with bounding spheres.
   - Tracers: classic (absolute and pixel-cone epsilon), over-relaxed (Keinert et al. 2014),
     the Balint & Valasek 2018 step, auto-relaxed (Ban & Valasek 2023). Every distance
     evaluation is counted.
   - Shading helpers: tetrahedron normals (4 evaluations), Lambert plus ambient, soft shadows
     (Algorithm 2, Sec. 2.3.3, of the thesis, Polychronakis 2025 = Quilez's penumbra estimate)
     with a head start, material ids, a sky gradient; 1, 4 or 16 samples per pixel.
   - One eccentricity model (degrees between the gaze ray and a pixel's ray, from the display
     geometry), shared with fovlp.h and fovpt.h.
   - Accelerated head starts: the conservative cone pyramid (FOVSDF_METHOD_CONE), the thesis's
     inverted pyramid (FOVSDF_METHOD_IPR) and Skipping Spheres (FOVSDF_METHOD_SKIP), below.

ACCELERATED METHODS
   CONE (beyond the thesis): the image is cut into grid-aligned tiles of cone_tile pixels. Each
   tile marches one cone from the pinhole that contains every sample ray of the tile; where it
   touches a surface the tile splits in four and each quarter continues from there, for
   cone_levels levels (default: down to 2x2 pixels); then every sample ray starts from its
   cell's distance and finishes with cfg.finish (default the Balint-Valasek step). Guarantee:
   for a distance function that never overestimates (Lipschitz <= 1 after scene.lipschitz), no
   ray starts past its first hit (tests/test_fovsdf_accel.c checks it over 300 random scenes and
   cameras against analytic intersections; the float envelope, tested to 1e6 units from the
   origin, is in NUMERICS), and a tile whose cone reaches t_max is empty: its
   pixels are not marched at all. Results do not depend on how the caller splits the image
   into rows or tiles. Working memory: none beyond a 40-cell stack (about 1 KiB) per call;
   fovsdf_memory_size stays 0. Distance estimators that can overestimate (Mandelbulb, smooth
   operators, large repetition with overlapping copies) lose the guarantee, not the image.
   SAFE AND THESIS HEAD STARTS (heuristic_start). IPR, SKIP and FIPR default to a safe
   variant (heuristic_start 0): the start a cell hands its pixels is certified by a cone, as in
   CONE. The cone from the pinhole that contains every sample ray of the cell (its pixel
   rectangle, so every spp offset) marches with the free-cone step from its parent cell's
   certified start (the camera for the top level); the pixels start at the larger of the
   parent's start and where the cone stopped. Guarantee, and where it ends: CONE's. For a
   distance function that never overestimates (and within the float envelope of NUMERICS) no
   sample ray starts past its first hit, and a cell whose cone reaches t_max is empty (its pixels
   are not marched; start = t_max). tests/test_fovsdf_heads.c checks it on 100 random stress
   scenes: thin shells 0.002 thick, needles of radius 0.002, dust of tiny spheres, thin pillars
   in a room with the camera inside, a grazing floor; 1 and 4 spp; several tile and block sizes.
   The reference is a double-precision SDF of the test's own. 0 of 1.2 million sample rays start
   past their first hit. With heuristic_start 1 the same rays give IPR 0.38 %, SKIP 16.7 % and
   FIPR 0.27 %. A certified start needs no start check (the thesis variant spends one evaluation
   per sample ray on it). The thesis variant (heuristic_start 1) is the one each method's
   paragraph below describes, unchanged: the same images as 0.2.1 (tested). What the safe
   variants cost, and what the thesis variant risks, is measured by bench/bench_heads.c. The
   run covers the six built-in scenes plus thin shells and needles, at 320x180 and 1 spp.
   - Cost. Safe IPR and SKIP need fewer evaluations than the thesis's: IPR 6.1-11.0 per pixel
     against 10.6-16.6, SKIP 6.2-12.1 against 11.5-25.3. Their time is 0.68-0.85 (IPR) and
     0.47-0.92 (SKIP) of the thesis variant's. The cones stop where the coarse rays would
     crawl along silhouettes, and no start needs checking. Safe FIPR needs 4-14 % more
     evaluations (5.0-9.7 per pixel against 4.4-8.4), because it marches cones besides the
     level-0 rays; its time is about the same (0.88-1.21 on a loaded machine).
   - Risk. With heuristic_start 1, pixels start past their first hit: IPR 0-1552 per scene
     (2.7 % on thin), FIPR up to 200 traced pixels, and SKIP 12-39 % of the pixels. SKIP's
     start check restarts most of those from the camera, at a full march each; the rest skip
     a surface and reach the image. Safe: 0 everywhere.
   - Quality. Safe IPR and SKIP come within 0.1 dB of CLASSIC's PSNR against the ground truth
     on every scene, and safe FIPR within 0.25 dB of the thesis FIPR.
     The thesis variant's differs from it by -4.4 dB (SKIP on thin shells) to +3.9 dB (IPR on
     needles). The gain there is a fault: missing the sub-pixel needles, which the default
     0.25-pixel threshold widens, looks more like the 0.01-pixel ground truth.
   IPR (thesis ch. 5): ipr_levels levels (default 3: 1/16, 1/4 and all of the pixels); each
   level traces the rays through its cells' centres from the minimum t of the parent cell and
   its neighbours within ipr_radius (default 1: the 3x3 filter, applied before each level;
   fovsdf_min_filter is the same filter on an image); every sample ray of a pixel starts from
   the filtered value of the last level. Misses are stored as t_max. Choices where the thesis
   is silent: the child of cell (u, v) is (u/2, v/2); no extra safety margin; nearest parent;
   every level uses cfg.finish. The filter is a heuristic, no guarantee: sub-pixel features the
   coarse rays miss can be skipped (measured on the thin scene: 2 % of the pixels at 320x180).
   Safe variant (the default): the same levels and tiles; each cell's value is its certified
   start (above) instead of its centre ray's hit. No filter is needed (each cone contains all
   of its cell's rays), so ipr_radius and ipr_no_filter apply to the thesis variant only. No
   apron either: only the cells over the requested pixels are marched.
   Working memory per tile of ipr_tile pixels (default 32): the level arrays with aprons,
   (8 + 2*2)^2 + (16 + 2*1)^2 = 468 floats = 1872 bytes for the defaults, on the stack, at most
   FOVSDF_TILE_SCRATCH floats (default 1024; a config that needs more is FOV_ERR_LIMIT). The
   aprons are recomputed by each tile: 0.46 coarse rays per pixel against the 0.31 of a
   whole-image pyramid.
   SKIP (thesis ch. 6): one low-resolution ray per cell of skip_block x skip_block pixels
   (default 4) marches the scene scaled by skip_scale (default 1.005; deflated when the camera
   is inside; subtracted holes shrink) and stops early at skip_eps (default 0.05); with shadows
   it also leaves one shadow-ray head start per light. The full-resolution rays start from the
   cell's t (see fovsdf__skip_cell for the choices). A heuristic without filter: a cell whose
   centre ray hits something far can start its edge pixels past a nearer object. Working
   memory: one cell (a few floats per light); no apron. Scaling needs a dist_ex callback that
   honours fovsdf_query.inflate (the built-in programs do). The low-resolution ray goes through
   the centre of the block clipped to the image (a 1x1 image, or a border block). Safe variant
   (the default): one certified cone per block, from the camera. It has no scaled scene, no
   early termination and no shadow head starts (skip_scale, skip_eps and skip_no_shadow_start
   apply to the thesis variant). The cone needs neither heuristic, since scaling would only
   stop it earlier. A shadow head start has no certificate: a pixel's shadow ray can meet a
   needle that the cell's ray passed.
   FIPR (thesis Sec. 5.2.1) and CONE_FOV (beyond the thesis): foveated head starts. A pixel is
   traced (all its sample rays, from IPR's or CONE's head start) when it lies in the fovea
   (acuity.fovea_deg of eccentricity, default 7.5), or, with probability p(w) = A exp(-rate w)
   + C (fovsdf_acuity), when it lies on an edge of a low-resolution depth map (Sobel, relative
   threshold edge_threshold, default 0.1; fov_mask chooses other policies). Every other pixel
   is the bilinear interpolation of a mid level (one shaded ray per 2x2 pixels), refreshed
   every refresh-th frame (1, 2, 4; the tiles take turns, so frames cost the same; pixels
   not refreshed are not written, so keep the previous frame in the buffers). The mask output
   says which pixel was made how. Super-sampling (spp) applies to traced pixels only: the
   thesis's selective anti-aliasing. A static scene and gaze reach the refresh-1 image after
   `refresh` frames (tested), and with a fovea covering the image FIPR is IPR (3 levels, the
   same heuristic_start) and CONE_FOV is CONE bit for bit when the image's sides are multiples
   of the tile (CONE_FOV keeps its border tiles' cells unclipped, CONE clips them). FIPR always has
   the thesis's three levels (ipr_levels is IPR's alone); ipr_tile, ipr_radius and ipr_no_filter
   apply. The pipeline and the choices are at fovsdf__fov_tile.
   Safe FIPR (the default): the mid ray and the traced pixels of a 2x2 cell start from the
   cell's certified start (its cone from its 4x4 parent's), so no traced ray and no mid ray
   starts past its first hit. Level 0 still traces thin rays from the camera for the edge map.
   FIPR and CONE_FOV: an interpolated pixel reports its mid ray's depth, always in [0, t_max]
   (a mid-level hit the tracer reports beyond t_max, or a non-finite one, counts as a miss).
   The thesis's mask-guided blur (pass 5) is fovsdf_mask_blur, a post-process nobody calls by
   default: its own study found it made the foveation more visible.
   Working memory per tile: FOVSDF_FOV_CELLS (default 324) mid-level cells of 48 bytes and
   twice as many floats (level 0: hits and certified starts), on the stack (17.7 KiB), enough
   for ipr_tile 32 with radius 1 (FIPR) and cone_tile 32 (CONE_FOV); configs that need more
   are FOV_ERR_LIMIT. acuity.fovea_deg 0 means the default 7.5: for no fovea at all pass a
   tiny angle such as 1e-3.
   Quarter level (config.quarter_deg > 0; beyond the thesis): from that eccentricity on, the
   pixels outside the mask take the bilinear interpolation of a quarter level instead, one
   shaded ray per 4x4 pixels through the cell's centre (weights 5/8, 7/8, 1/8, 3/8 of the
   nearer cell per axis), blended linearly with the mid level over FOVSDF_QUARTER_BAND
   pixels (default 8, the pixel size at the eye's axis) past quarter_deg: both levels
   reconstruct continuously and the weight changes gradually, so there is no seam (a smooth
   image is reconstructed within 15 % of one pixel's change, tested). The quarter ray starts
   from a certified start: CONE_FOV, the least of its four 2x2 cells' (their cones contain it,
   on their common corner; one proven empty proves it a miss); safe FIPR, its level-0 cell's
   cone; thesis FIPR, the minimum of level 0 over its cell and neighbours (ipr_radius).
   Where every pixel of a 4x4 cell takes the quarter level alone, CONE_FOV's pyramid stops
   at that cell. The mask output says 3 for a pixel that took the quarter level (alone or
   blended). quarter_deg 0 (the default) gives the images and counts of 0.5.0 bit for bit.
   Level filter (config.level_filter 1; beyond the thesis): a mid or quarter sample takes the
   mean albedo of its cell (2S x 2S points of the S x S cell, where their rays meet the hit's
   tangent plane; the hit's material and lighting), a box prefilter of the texture, at no
   distance evaluation. What it fixes: the sparse rays point-sample textures finer than their
   spacing, and the aliases are coarse enough to see (ACUITY-DRIVEN FOVEATION). Costs
   4 S^2 albedo calls per level sample: cheap for the built-in checkerboard and palette, to be
   weighed for an expensive scene.albedo callback.
   Per-pixel texture (config.level_filter 2; beyond the thesis): a mid or quarter sample keeps
   its lighting (the shaded colour over the albedo: ambient plus lights, with shadows) and its
   normal instead of its colour, and each interpolated pixel takes, per interpolation tap, the
   albedo where the pixel's own ray meets the tap's tangent plane (the tap's material; the
   tap's own point where the ray meets the plane behind the camera, from its other side or
   more grazing than a quarter of the tap ray's incidence), times the tap's lighting, clamped
   as a shaded colour, weighted as the bilinear. Lighting is smooth and shared; texture edges
   come out where a full-resolution ray puts them (on a plane: the classic pixel's albedo),
   with no blur from the level's spacing, at no distance evaluation: 4 albedo calls per
   interpolated pixel (8 in the quarter blend band). What it fixes: the level filter's box and
   the bilinear blur every texture edge over 2-4 pixels, which the eye resolves near the
   fovea of a dense display (ACUITY-DRIVEN FOVEATION). Only the lit shadings
   (FOVSDF_SHADE_FULL, NO_SHADOWS) have a lighting to keep; other shadings and misses (the
   sky) interpolate colours as level_filter 0.
   Contrast refinement (config.refine_contrast C > 0; beyond the thesis): a pixel outside the
   mask whose interpolation taps (mid and quarter cells) have luminances (Rec. 709 weights,
   linear) whose Michelson contrast (max - min) / (max + min + 1e-3) exceeds C traces its own
   rays instead (mask output 1): silhouettes and shadow edges, which the sparse rays alias,
   and which the level filter cannot prefilter. Its cost follows the edges in the image.
   With level_filter 2 the taps' values are their lighting, so it compares lighting (shadow
   edges; the texture is per pixel already).
   Geometric refinement (config.refine_depth, refine_normal_deg, refine_material; beyond the
   thesis): a pixel outside the mask whose interpolation taps (mid and quarter cells) disagree
   on hit and miss or whose hits' depths differ by more than refine_depth of the nearest (a
   silhouette), whose hits' normals differ by more than refine_normal_deg from the first
   hit's (a crease; the lit shadings, where the levels have normals), or whose hits lie on
   different materials (refine_material 1: another object touching or crossing this one)
   traces its own rays instead (mask output 1), from its 2x2 cell's certified start, so a
   refined pixel is the pixel of the same method with a fovea over the whole image bit for
   bit (tested; without a quarter level, whose pyramid may stop at 4x4 cells). The levels
   point-sample geometry: a silhouette between two level rays steps in stairs of 2 or 4 pixels
   that the eye sees just outside the fovea of a dense display, and interpolated lighting
   across a crease or a contact darkens a band of pixels. The cost follows the silhouettes,
   creases and object boundaries in the image, not the texture: a scene without them in view
   costs no evaluation more (tested), and it is monotone in each threshold (tested). 0 (the
   default) turns each test off; all three 0 give the images and counts of 0.7.0.
   - Six built-in scenes modelled on the thesis's test scenes (Primitives, Columns and Lights,
     Temple on a terrain, Atrium, Thin features, Fractals).

ACUITY-DRIVEN FOVEATION
   fovsdf_config_acuity(&cfg, &cam, &eye) fills the foveation fields of FIPR and CONE_FOV from
   the display (cfg.display; all zero: cam's field of view) and the eye (fov_eye: the minimum
   angle of resolution MAR(e) = mar0 + slope e of Guenter et al. 2012, and the quality knob,
   the allowed sample spacing as a multiple of the MAR; NULL: 1 arc minute, 1.32 arc minutes
   per degree, quality 0.5, twice the Nyquist rate of the finest grating the eye resolves; see
   fov_eye) through fovsdf_eye_plan (the pixels per degree at the eye's axis;
   the plan does not depend on the gaze):
   - acuity.fovea_deg = plan.e_half: every pixel traces its own rays wherever one sample per
     2x2 pixels would be coarser than the eye resolves. A display coarser than the eye out to
     E has e_half > e_full >= E, so it gets no reduction inside E (tested at 4 pixels per
     degree: E = 10.6 degrees). Below 1e-3 degrees: 1e-3 (no fovea; 0 would mean 7.5).
   - quarter_deg = plan.e_quarter, from where one sample per 4x4 pixels suffices (0 when that
     lies at 180 degrees: never).
   - fov_mask FOVSDF_MASK_FOVEA: the thesis's edge and acuity (Bernoulli) pixels are not needed
     where the level's density already matches the eye. Measured with the edge mask on the
     acuity levels (primitives, 640x360): 3 % more evaluations, eye-filtered PSNR within
     0.05 dB; randomly placed full-resolution pixels among interpolated ones are noise.
   - refresh 1: the periphery is the part of the visual field most sensitive to flicker, and
     tiles that refresh on alternate frames flicker wherever the image changes.
   - acuity.outer_deg 0 (A, rate and C stay; the fovea mask ignores them).
   - level_filter 2 (texture per pixel) and geometric refinement: refine_depth 0.05,
     refine_normal_deg 25, refine_material 1 (silhouettes, creases and object boundaries
     trace their own pixels). Measured at equal perceived quality (bench/bench_perceptual.c:
     eye-filtered FLIP against a 4-spp ground truth at most 0.001 above classic's), these
     turned the loss at quality 1 into a tie on most scenes: the level filter's box and the
     bilinear blur of texture edges, and the levels' stairs along silhouettes and contacts,
     were what the eye filter saw (see What the eye notices, below). For 0.7.0's
     configuration pass an eye with quality 1 and set level_filter 1 and the three refine
     fields 0 after the call.
   - refine_contrast stays as the caller set it (default 0, off): at 640x360 the quality knob
     buys the same perceived quality for fewer evaluations (primitives: as good as classic
     with refine_contrast 0.1 at a saving of 2.1x, with quality 0.7 at 2.9x).
   The method and every other field stay as the caller set them (for a method other than FIPR
   and CONE_FOV the fields have no effect). Errors, with a message through cfg->logger and
   *cfg unchanged: FOV_ERR_NULL; the eccentricity model's code for a bad camera or display;
   FOV_ERR_INVALID_ARG or FOV_ERR_NOT_FINITE for a bad eye.
   What the eye notices near the fovea of a dense display (bench_perceptual, eye-filtered FLIP
   at 33.6 px/degree, primitives, quality 1 of 0.7.0's configuration: 0.0282 against classic's
   0.0180, the loss at 2-10 degrees): the checkerboard's edges blurred over 2-4 pixels by the
   level filter and the bilinear (level_filter 2 alone: 0.0227), stairs of 2 and 4 pixels
   along silhouettes and where objects touch the floor (adding refine_depth and
   refine_material: 0.0192), and lighting interpolated across creases (adding
   refine_normal_deg: 0.0185, a tie, at 10.5x instead of 13.0x). Left: lighting interpolated
   over fast-varying lighting (columns and atrium, many point lights, curved columns: 0.0170
   against 0.0148 at desktop27; neither refine_contrast on the lighting, 0.1, nor a normal
   threshold of 15 degrees closes it; the quarter level is where it lies: with quarter_deg 0
   columns ties at quality 1, 0.0155, saving 4.3x instead of 7.9x); textured curved surfaces,
   whose texture the tangent planes misplace by the curvature over a tap's spacing.
   As good as classic (eye-filtered FLIP at most 0.001 above classic's against the 4-spp
   ground truth, gaze at the centre, no shadows; CONE_FOV; the saving in distance evaluations
   at the highest quality knob of 0.25 .. 1 that ties; make bench-perceptual and
   bench_perceptual --scenes-sdf atrium,fractals --qualities 0.7,1):
     640x360 (5-8 px/degree)  primitives 1 (3.5x), temple 0.7 (3.7x), thin 1 (2.5x),
                              columns 0.5 (2.2x), atrium 0.7 (2.9x), fractals 1 (2.7x)
     desktop27 (33.6)         primitives 1 (10.4x), temple 1 (9.4x), thin 1 (4.8x),
                              fractals 1 (2.9x), atrium 0.35 (6.3x), columns 0.25 (4.3x)
     hmd (11.7)               primitives 1 (7.7x), temple 1 (9.0x), thin 1 (5.4x),
                              atrium 1 (7.3x), fractals 1 (6.1x), columns 0.5 (5.2x)
   (0.7.0's configuration: primitives and temple tied at 0.25-0.5 only, 3.3x / 5.4x / 5.9x.)
   Above quality 1 the saving grows little (most scenes still tie at 3: primitives 10.9x at
   desktop27): the refinement traces what the coarser levels would have missed.
   What the eye notices in the periphery (bench/bench_sdf_acuity.c: both images filtered to the
   eye's resolution, a Gaussian of standard deviation MAR(e) / 2 per pixel, then PSNR per
   eccentricity band against a 16-spp ground truth; primitives 640x360, 6.7 px/degree):
   point-sampled texture comes first. The checkerboard floors (5 of the 6 built-in scenes)
   alias into coarse patterns the eye resolves: beyond 20 degrees classic scores 39.5 dB, the
   mid level 35.8, the quarter level 31.0; with the level filter 43.6 and 38.9 (the mid level
   then beats classic's aliased 1-spp pixels). Geometry comes second (normal shading, no
   texture: classic 53.0, quarter level 45.9): silhouettes of rays 4 pixels apart.
   Blockiness does not show: bilinear from 2x2 or 4x4 cells is smooth. Contrast: the level
   filter averages a cell, with the bilinear a filter about 1.5 cells wide, within the eye's
   MAR by construction.
   Savings (classic's distance evaluations, all passes and shading, over the method's; gaze
   at the centre, soft shadows, 1 spp) and the eye-filtered PSNR against classic's
   (make bench-sdf-acuity ARGS="--quality 1,0.7,0.5 --methods cone_fov,cone_fov_acuity"):
   - 640x360 on the built-in cameras (45-65 degrees, 4.9-7.6 px/degree): quality 1 saves
     2.8-4.5x (cone_fov with the fixed 7.5-degree fovea: 2.6-3.5x) and loses 0.7-8 dB
     beyond its fovea; as good as classic (within 0.5 dB in every band, or at least 45 dB)
     at quality 0.7 on primitives (2.9x), temple (3.1x) and fractals (2.7x), 0.5 on thin
     (2.2x); columns and atrium lose 1-3 dB even at 0.5 (1.4x, 1.7x): their silhouettes and
     shadow edges.
   - 1920x1080 on a 27-inch monitor at 60 cm (33.6 px/degree, camera fov_y 31 degrees):
     quality 1 saves 10.0x on primitives, 7.4x on columns and 10.3x on temple but loses 3.6,
     6 and 6.7 dB just outside its 1.9-degree fovea; quality 0.5 saves 7.2x, 5.4x and 8.2x,
     and primitives is then as good as classic (within 0.5 dB below 45 dB, at least 45 dB
     above); columns still loses 1.3 dB at 5-10 degrees (silhouettes of the columns against
     the walls behind, which the mid level's rays 2 pixels apart alias), temple 2.1 dB at
     0-5 degrees (the terrain's detail where the mid level starts); thin (8.9x at 1, 6.6x at
     0.5) loses 2-9 dB beyond 5 degrees: needles and shells far thinner than the levels'
     spacing. Atrium and fractals were not measured at 1080p. refine_contrast buys
     quality dearly: at 0.05 (quality 1) columns is as good as classic at a saving of 2.6x;
     at 0.1 it traces 27 % of primitives' pixels (the floor's tile edges too) for 3.5x, still
     2.2 dB short at 5-10 degrees.

CHEAPER SHADOWS BEYOND THE FOVEA
   Opt-in (config.shadow_fov_deg > 0; off by default, and off every image and counter is as
   without the fields): the samples whose image point lies beyond shadow_fov_deg of the gaze
   (the eccentricity model above; a cosine test per shaded sample ray, in float: samples at
   the threshold may fall either side of fovsdf_ecc_deg's value; no atan2) start their shadow
   rays at least shadow_fov_t0_px (default 4) pixel footprints from the surface instead of
   shadow_t0. Near the surface Algorithm 2's steps
   are small (h grows about as t sin(angle to the surface)), so this skips the costliest part
   of most rays; what goes is a contact shadow thinner than those pixels, which the periphery
   does not resolve. The pixels within the threshold are bit for bit today's. Measured
   (640x360, gaze at the centre, 1 spp, shadow_fov_deg 7.5; shadow evaluations per pixel off
   -> on; PSNR change against the ground truth in the worst eccentricity band of 5-10, 10-20,
   20+ degrees, and of both images filtered to the eye's resolution, fovm_eye_filter):
     cone_fov  primitives 5.5 -> 4.4 (0.0 dB, 0.0), columns 52.4 -> 40.2 (0.0, +0.2),
               temple 9.7 -> 7.7 (0.0, 0.0), atrium 20.3 -> 15.2 (-0.1, 0.0),
               thin 4.4 -> 3.7 (-0.1, -0.1), fractals 5.4 -> 4.5 (-0.2, -0.4)
     cone      primitives 12.8 -> 10.0 (0.0, 0.0), columns 129.5 -> 98.7 (0.0, +0.4),
               temple 23.4 -> 18.4 (0.0, 0.0), atrium 49.9 -> 37.1 (-1.3, -1.0: contact
               shadows at its pillars), thin 10.2 -> 8.6 (-0.8, -0.4), fractals 12.8 -> 10.6
               (-0.5, -0.7)
   For cone_fov, shadow_fov_t0_px 2 keeps every band within 0.1 dB and saves about 60 % as
   much; 8 saves another 10 % (fractals: -0.8 dB at 10-20 degrees). The issue's alternative,
   a step budget shadow_fov_steps below shadow_steps, is far worse per evaluation saved: a ray
   that runs out where its penumbra is not yet known leaks light (its running minimum) or,
   dark when still in a penumbra (as here, slightly better), shadows where there are none.
   cone_fov at 16 steps alone halves the shadow work of columns, temple and atrium but loses
   3-12 dB in their worst band; 32 steps on top of the default start saves another 7-16 %
   for 0.1-0.5 dB. A minimum step of a fraction of t (0.05-0.2) saved 1-24 % for up to 2 dB;
   a start offset in world units (0.05-0.2) saves like the footprint one but loses up to
   1.4 dB on fractals (cone), whose details are small in world units.
   fovsdf_config_acuity leaves the shadow_fov fields as the caller set them (default off):
   from its fovea on (plan.e_half, 11-18 degrees here) the default start costs fractals 0.4 dB
   of eye-filtered PSNR (a missing shadow is contrast, not detail the eye filter removes), and
   2 pixel footprints, within 0.02 dB everywhere, save only 4-11 % of the shadow work.

DOES NOT
   - use a GPU API, start threads, allocate memory, or read or write files;
   - keep any global or thread-local state.

CONFIGURATION (define before including the implementation)
   FOVSDF_STATIC        all functions static (use it when two libraries embed this header)
   FOVSDF_API           override the linkage of every public function
   FOVSDF_MAX_STEPS     hard cap on march steps per ray               (default 65536)
   FOVSDF_MAX_DIM       hard cap on image width and height            (default 65536)
   FOVSDF_MAX_STACK     value stack depth of the scene program        (default 32)
   FOVSDF_BATCH         points per batch callback and lanes of the batch evaluator
                        (default 32 on 64-bit CPUs, 16 elsewhere; 1: point by point)
   FOVSDF_WAVE          sample rays in flight per render call (default 128 on 64-bit CPUs,
                        32 elsewhere; at least config.spp)
   FOVSDF_SHADOW_GROUP  shadow rays per shadow proof (default 0: none; 16 saves 15-30 % of
                        the shadow evaluations of directional lights, the images unchanged,
                        but per-pixel evaluation counts then depend on the split)
   FOVSDF_NO_SIMD       no intrinsics (the batch evaluator's square root); the loops stay
                        plain C either way (what the compiler vectorises; FOVSDF_SIMD_NAME
                        names the instruction set the build targets: "avx2", "sse2", "neon",
                        "simd128" or "scalar")
   FOVSDF_DOUBLE        also compile the double-precision reference tracer (hosted builds;
                        it references software-double routines on a single-precision FPU)
   FOVSDF_QUARTER_BAND  pixels over which FIPR's and CONE_FOV's quarter level blends in past
                        config.quarter_deg (default 8; 0: a hard switch)
   FOVSDF_PRUNE_CODE    instructions of the per-tile pruned program of a built-in program
                        scene that CONE and CONE_FOV keep on their stack (64 bytes each, on
                        the stack of the thread that renders the tile: mind small thread
                        stacks; default 0: no pruning). Each tile prunes the program for its cone
                        (bounds its rays never enter become their bound's value, bound tests
                        they always pass go, unions such a value can never win go) and marches
                        every batch inside the cone with it: the same images, depths,
                        materials and counts (tests/test_fovsdf_prune.c). On the built-in
                        scenes it saves nothing: the cone reaches t_max, so almost only the
                        first kind applies, which costs what the bound's skip costs; shadow
                        rays, most of the evaluations, lie outside the cone (issue 12)
   FOVSDF_PRUNE_MIN     bound tests and unions a tile's pruning must remove before the tile
                        uses its pruned program (default 1; 0: always)
   Shared by the three headers (listed in the shared declarations block below):
   FOV_DLL, FOV_ASSERT, FOV_NO_LIBM, the math hooks FOV_SQRTF ... FOV_POWF, FOV_MEMSET,
   FOV_MEMCPY and FOV_NO_ERROR_STRINGS.

MEMORY
   The caller owns every byte. fovsdf_memory_size() says how much working memory a
   configuration needs (0 for the tracers of this version); fovsdf_init() takes it as a
   pointer and size. Images are caller buffers with an explicit row stride. The scene program
   and the built-in scenes are built into caller memory after a size query
   (fovsdf_program_size, fovsdf_builtin_size). Stack use (gcc -fstack-usage, x86-64 -O2): the
   tracers and CONE need less than 4 KiB plus the scene program's value stack
   (FOVSDF_MAX_STACK * 8 bytes); IPR adds FOVSDF_TILE_SCRATCH floats (4 KiB), FIPR and
   CONE_FOV add FOVSDF_FOV_CELLS * 56 bytes (17.7 KiB) and (FOVSDF_FOV_CELLS / 2 + 8) * 52
   bytes for the quarter level's cells (8.6 KiB; fovsdf__fov_tile measured 34.5 KiB in 0.5.0,
   40.2 KiB in 0.7.0, 47.3 KiB now that a level cell keeps its normal, with the passes
   inlined). Lower the two macros for small
   stacks (configs that need more are then FOV_ERR_LIMIT). The wavefront adds about
   FOVSDF_WAVE * 0.6 KiB (77 KiB at 128, 19 KiB at 32) and the batch evaluator about
   FOVSDF_BATCH * 1.4 KiB (45 KiB at 32; nothing at 1); tests/xtarget/mem_test.c renders
   Primitives on a Cortex-M4 with FOVSDF_WAVE 4 and FOVSDF_BATCH 1 in 5.4 KiB of stack.

ERRORS AND LOGGING
   Every fallible function returns fov_result: FOV_OK (0) or a negative code.
   fovsdf_result_string() never returns NULL. Bad input (NULL pointers, zero, negative,
   overflowing or over-cap sizes, NaN or infinite camera, gaze or parameters, a field of view
   outside (0, 180) degrees, a camera looking along its up vector, a zero step budget) is
   rejected with an error code before any work is done (an off-axis camera with
   tan_left + tan_right or tan_bottom + tan_top <= 1e-6, or a tangent above 1e6, with
   FOV_ERR_INVALID_ARG; one whose (tan_left + tan_right) / (tan_bottom + tan_top) is not
   width / height within 1e-3, i.e. non-square pixels, with FOV_ERR_UNSUPPORTED, the same in
   fovlp.h and fovpt.h); nothing asserts on data.
   Messages are on by default (no FOV_DEBUG needed): set cfg.logger and every failure calls it
   once, with the code and a message naming the field and the rule, e.g.
   "config.spp must be 1, 4 or 16 (0: 1)", "init: scene.num_lights above FOVSDF_MAX_LIGHTS",
   "render_tile/rows: x1 or y1 beyond the image". To see them:
      static void log_err(const char *tag, uint32_t level, int32_t code, const char *msg,
                          uint32_t line, void *user)
      { (void)level; (void)user; fprintf(stderr, "%s %d (%s): %s [line %u]\n", tag, (int)code,
                fovsdf_result_string((fov_result)code), msg, (unsigned)line); }
      cfg.logger.func = log_err;            // the context keeps it: fovsdf_render_* log too
   The loggers: cfg.logger (fovsdf_config_resolve, fovsdf_memory_size, fovsdf_init and every
   call on the context), fovsdf_builder.logger, fovsdf_program_check's argument. Functions
   without one return the code only: fovsdf_camera_basis, fovsdf_ecc_init, fovsdf_march,
   fovsdf_min_filter, fovsdf_mask_blur, fovsdf_program_size / _build / _compact,
   fovsdf_builtin_size / _init, fovsdf_trace_ref, and any call given a NULL context or
   config. FOV_NO_ERROR_STRINGS removes the texts (about 7.5 KB of a Cortex-M4 -Os build):
   the logger still gets every code and line, with msg "" (never NULL), and
   fovsdf_result_string returns "".
   Non-finite values from your callbacks never reach the image: a NaN or infinite distance
   ends the ray as a miss (every tracer; no evaluation beyond t_max or at a non-finite point,
   hits always at a finite t in [t_start, t_max]), a NaN or infinite albedo channel is taken
   as 0.
   Bounds of the float envelope (NUMERICS): a camera position, eye_offset or pinhole beyond
   1e18 from the origin is FOV_ERR_INVALID_ARG at fovsdf_init ("init: cam.pos ...",
   "init: cam.eye_offset ...", "init: pinhole ..."); an image point whose ray direction
   overflows float is rescaled (fovsdf_camera_ray and fovsdf_shade_point give a unit ray for any
   finite image point).
   Scene nodes: the builder functions and fovsdf_program_build share one check (the ranges at
   fovsdf_node_type: FOV_ERR_NOT_FINITE, FOV_ERR_LIMIT for lengths beyond 1e18,
   FOV_ERR_INVALID_ARG, FOV_ERR_DEGENERATE); fovsdf_builder.logger and fovsdf_program_check
   log the first failure as "<builder|program_build>: node <index> (<type>): f<k> <rule>",
   e.g. "program_build: node 2 (menger): i0 iterations must be 1 .. 8" (such a composed text
   lives on the stack: copy it in the logger if you keep it).

THREADING
   No function keeps state between calls except in the objects you pass. fovsdf_init fills a
   context that is read-only afterwards: call fovsdf_render_rows / fovsdf_render_tile on
   disjoint rows or tiles from as many threads as you like, each with its own fovsdf_stats
   (fovsdf_stats_init, then fovsdf_stats_add them up).
   The head-start methods work on grid-aligned tiles: split the rows at multiples of
   fovsdf_band_rows(ctx) or a tile's coarse work is repeated by every call that cuts it (the
   image is the same either way). Threads stay with you (examples/fovrun.h runs them on
   pthreads). A worker-friendly split: work items of band_rows rows by a multiple of band_rows
   columns (whole grid tiles, fovsdf_render_tile), each of at least 16 FOVSDF_WAVE / spp pixels
   (one call's pixels form the wavefront and every call ends with a partial one, so calls of
   at least FOVSDF_WAVE / spp pixels keep the batches full; a call of one pixel works, with
   batches of its own samples only), taken in row-major order from a shared counter: the
   fovea's tiles cost several times the periphery's, and many small items let the workers
   end together (fixed bands handed out round robin leave one idle for up to a few per cent
   of the frame). At 640x360 that is 115 items of 128x16 for the cone methods (fovrun.h's
   FOVRUN_ITEM_PX 2048 at 1 spp: their partial wavefronts cost 0.4 % more instructions on one
   thread than whole-width bands, 1024 0.6 %, atrium CONE_FOV 320x180, callgrind).

BATCHED EVALUATION
   Every tracer, normal and shadow ray of a render call evaluates the scene in batches of up
   to FOVSDF_BATCH points (structure of arrays, fovsdf_batch): through scene.dist_batch when
   it is set, else point by point through dist_ex / dist (the library batches around them).
   A batch callback must give each point what the per-point callback would (the library uses
   either: fovsdf_distance and fovsdf_shade_point go point by point); its values are taken as
   they are (NaN, infinite or unwritten: FLT_MAX, a miss). Built-in programs have both
   (fovsdf_scene_set_program). Each ray runs the same state machine either way, so images do
   not depend on the batch size, on FOVSDF_WAVE, on the split into rows and tiles, or on
   which callback form evaluated them (tests/test_fovsdf_wave.c, tests/wave_variants.sh).
   Shadow proofs: for a group of up to FOVSDF_SHADOW_GROUP shadow rays of one light, one
   march along a tube (parallel rays) or a cone (rays converging on a point light) that
   contains them proves k h / t >= 1 (no attenuation) for all samples beyond a split; the rays
   stop there and keep the same light fraction (Algorithm 2 takes a minimum). It needs a
   distance that never overestimates (Lipschitz 1 after scene.lipschitz, as every head start
   here does); for the built-in programs the proof's own evaluations use a threshold lowered
   so that their bounding spheres are skipped wherever a ray point's could be. Which rays form
   a group depends on the call, so per-pixel evaluation counts do (the image does not): that is
   why the proofs are off by default (FOVSDF_SHADOW_GROUP 0), keeping every count independent
   of the split as well.

NUMERICS (the float envelope; tests/test_fovsdf_scene.c and _contract.c establish it)
   - The library computes in float only (no double anywhere unless FOVSDF_DOUBLE).
   - The hit threshold of a ray at distance t is
         thr(t) = max(eps, eps_px * pixel_angle * cos^2(theta) * t,
                      8 * FLT_EPSILON * (|camera| + t)),
     theta the ray's angle to the camera's axis: the pixel-cone term is the ray's own pixel
     footprint (a pinhole pixel subtends pixel_angle cos^2(theta) radially and pixel_angle
     cos(theta) tangentially; the smaller one), so wide fields of view and extreme aspect
     ratios do not turn near misses into hits (measured on 64x36 images of spheres all around
     the camera, hits whose ray never comes within one pixel footprint of a surface: 4.4 % of
     the pixels at 150 degrees, 64 % at 179.9 and 98 % of a 4096x1 image with the centre
     pixel's angle; none now, tests/test_fovsdf_props.c). Never below a few float ulps of the
     position, so a march always makes progress and ends within max_steps. fovsdf_march takes
     eps_cone as given (no footprint scaling). The normals' default step follows the same
     footprint.
   - A hit point lies within thr(t) of the surface; along the ray that is at most
     thr(t) / |cos(incidence)|. A secant step then refines it, but only where that is safe
     (see the next point): near normal incidence the sphere at its end point verifies it; at
     grazing angles one empty ball does: a ball off the ray, tangent to the surface at the
     secant's end point F and through the last verified point A, whose radius the distance at
     its centre c confirms (Lipschitz 1: the ball around c of radius f(c) holds no surface),
     holds the segment A F (4 evaluations; refused when f(c) is too small, or when the
     rounding of the test would take more than the margin: a plane below about 0.4 degrees
     with the hit near the threshold). Otherwise the hit moves by the last distance. Planes
     are exact again from normal incidence down to about 0.4 degrees: within 3e-6 relative
     at 0.5 .. 60 degrees with eps 1e-4 and with a pixel cone of 2.4e-3 (it was up to 1.1e-4
     and 0.21 with the plain step alone;
     tests/test_fovsdf_props.c, ball_grazing_floor_exact_*), and textures no longer slide:
     the built-in Primitives at 160x90 against the ground truth, 29.8 dB for CLASSIC (19.8
     with the plain step, 29.6 with the unverified secant). Cost: up to 5 evaluations per
     hit instead of 1 (about 2 more evaluations per pixel on the built-in scenes, 5-10 % of
     all). Measured (tests/test_fovsdf_scene.c): objects 1e-4 .. 1e3 in size with the camera
     at 5 sizes, |cos(incidence)| >= 0.3: relative depth error below 4.4e-5; a plane seen at
     0.01 rad: -2.1e-6 relative (-9.8e-5 with the plain step), at 1e-3 rad +2.3e-5 (2.3e-5
     below the plane, within the float noise of a position 1000 away), at 1e-4 rad -9.4e-3
     (beyond the ball's range); camera 1e5 units from the origin, unit sphere 5 units away:
     about 1e-2 relative (the ulp floor, 8 * FLT_EPSILON * 1e5 = 0.095 units, dominates).
   - No hit behind the first surface (every tracer; CONE and CONE_FOV's traced pixels too; for
     a distance function that never overestimates): let t_in be the first t where the ray is
     inside an object by more than tol(t) = 8 FLT_EPSILON (|camera| + t) + 0.02 thr(t) (the
     float noise of the position plus 2 % of the threshold); no reported hit has t > t_in. The
     march itself never steps past its unbounding spheres, and the hit refinement moves a hit
     beyond the last sample's sphere only when the sphere at the new point overlaps it or one
     empty ball, confirmed by the distance at its centre, holds the segment it jumps (both
     up to 1 % of the threshold plus 4 ulps of |camera| + t). tests/test_fovsdf_props.c checks
     it for every method and eps mode at 1 and 4 spp on thin shells, dust, grazing floors,
     rooms with thin pillars, needles of radius 0.002 and clusters 1e3 .. 1e6 units from the
     origin, against a double-precision reference along the library's own rays. IPR, SKIP and
     FIPR are heuristics (ACCELERATED METHODS): their head starts can still lie past a
     surface.
   - The range: no tracer evaluates beyond t_max or at a non-finite point (an overflowing
     position counts as a miss), and every hit has a finite t in [t_start, t_max]; a NaN,
     infinite or huge distance ends the ray as a miss (the relaxed steps end at t_max, and a
     plain step past t_max is a miss).
   - CONE's guarantee in float: the cone march takes f - 8 FLT_EPSILON (|camera| + t) as its
     safe radius, so it holds while the float evaluation of the distance at a point of
     magnitude up to |camera| + t errs by at most that much (the position rounded once, about
     half an ulp, plus a few operations: true of the built-in primitives and of camera- or
     origin-relative callbacks; a callback whose own float error is larger, such as a deep
     fractal iteration on absolute coordinates, is in effect an overestimating one there and
     loses the guarantee, not the image).
     Tested with single-pixel cones (the tightest) facing a box and a Menger sponge 1e4, 1e5
     and 1e6 units from the origin: no pixel starts past its first hit (without the margin:
     474, 520 and 3215 of 4096 pixels, by up to 2e-4, 0.36 and 3.8 units).
   - Keep scenes camera-relative where you can: float positions 1e5 from the origin resolve
     only about 0.01 units.
   - Hard bounds: the camera's position and pinhole (pos + eye_offset * right) lie within
     1e18 of the origin per component, and every scene length of the built-in programs
     (fovsdf_node_type) is at most 1e18: the squares of a few such lengths then stay finite in
     float (FLT_MAX is 3.4e38), so distances, thresholds (8 * FLT_EPSILON * |camera| is 1e12
     there) and normals are finite. Measured (tests/test_fovsdf_contract.c): a camera 9e17
     from the origin hits a sphere of radius 1e16 1e17 ahead at t = 9e16 within 1e13; a
     sphere of radius 1e18 (the camera inside) and one of radius 1e17 1.1e17 ahead (hit at
     1e16 within 1e-4 relative) render with BV2018.
   - The built-in programs evaluate to a finite distance at every finite point, for every
     node within its ranges (checked: each primitive and operator with sizes 1e-30 .. 1e18 at
     points from 0 to FLT_MAX per component): a point whose distance is beyond float gets
     +-FLT_MAX, smooth operators with an infinite operand take the plain operator, a repeat
     whose |p| / period exceeds float leaves p unfolded, terrain octaves stop where x * f1
     passes 1e30. Folds more than 2^23 periods from the origin carry float rounding of the
     point (up to an ulp of it), as every position does.
   - Colours: fovsdf_output.rgb, fovsdf_shade_point, fovsdf_shade and fovsdf_sky give linear
     RGB in [0, 65504] (the largest half float) whatever the scene's colours: values are
     clamped there, NaN (0 * inf with FLT_MAX lights) is 0; rgb8 is its sRGB encoding.
     The tetrahedron normal stays unit where the scene's distances come near FLT_MAX (its
     sums would overflow: it then sums differences from the first sample, the same normal).
     Directional lights and plane normals of any finite non-zero length are normalised
     exactly (scaled to a largest component of 1 first), so a light (-0.06, -0.06, -1e30) is
     the light (0, 0, -1).
   - Rays that start inside a surface (negative distance) report a hit at t_start.
   - Rays that graze a surface can exhaust max_steps (below about 1e-5 rad on a plane with
     the default 256 steps): they are reported as FOVSDF_EXHAUSTED with the t reached, and
     shaded as hits there. They never pass through the surface.
   - The mandelbulb and the terrain use the library's own sin, cos, atan2, pow and log (see
     fovsdf_node_type), never libm's or the math hooks' (the square root is still FOV__SQRT,
     so a FOV_SQRTF hook changes them): their values are the same with libm and FOV_NO_LIBM,
     and within 4 ulp of the exact functions (sin and cos: 2^-32 absolute where the result is
     below 2^-10; pow: for |y| <= 16 and a normal result).
   - Floating-point contraction: the tests build with -ffp-contract=off; results across
     targets agree within the tolerances stated in tests/xtarget (measured: the same images
     of its two scenes on x86-64, wasm32 and Cortex-M4, with libm and with FOV_NO_LIBM).

PLATFORM NOTES
   - Freestanding: the implementation includes only <stddef.h>, <stdint.h>, <float.h> and
     <limits.h> when FOV_NO_LIBM (or all math hooks) and FOV_ASSERT are defined (plus
     <xmmintrin.h> with MSVC on x86, for the square root instruction; gcc and clang get it
     by inline assembly); otherwise it also includes <math.h> and <assert.h>. The batch
     square root adds a compiler SIMD header: <emmintrin.h> (<immintrin.h> with AVX) on x86
     except in a freestanding FOV_NO_LIBM build, <wasm_simd128.h> with -msimd128,
     <arm_neon.h> on AArch64; FOVSDF_NO_SIMD removes them.
   - wasm32: clang --target=wasm32 -ffreestanding -nostdlib -DFOV_NO_LIBM works as is.
   - Cortex-M4F: arm-none-eabi-gcc -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard; the
     library's object file references no __aeabi_d* routine (checked by the tests).

REFERENCES (cited by author and year, with the section, equation, algorithm or figure of that
work; "the thesis" is Polychronakis 2025 throughout this file)
   Polychronakis 2025  A. Polychronakis, "Implicit and Foveated Techniques for Real-Time
                    Computer Graphics Rendering", doctoral dissertation, Technical University
                    of Crete, 2025. Its ch. 5 (IPR, FIPR) appeared as Polychronakis et al. 2023
                    and its ch. 6 (SKIP) as Polychronakis et al. 2024.
   Polychronakis et al. 2023  A. Polychronakis, G. A. Koulieris, K. Mania, "An Inverted
                    Pyramid Acceleration Structure Guiding Foveated Sphere Tracing for Implicit
                    Surfaces in VR", Eurographics Symposium on Rendering (EGSR), 2023.
   Polychronakis et al. 2024  A. Polychronakis, G. A. Koulieris, K. Mania, "Skipping Spheres:
                    SDF Scaling & Early Ray Termination for Fast Sphere Tracing", Computer
                    Graphics and Visual Computing (CGVC), 2024.
   Hart 1996        J. C. Hart, "Sphere Tracing: A Geometric Method for the Antialiased Ray
                    Tracing of Implicit Surfaces", The Visual Computer 12(10), 1996.
   Keinert et al. 2014  B. Keinert, H. Schafer, J. Korndorfer, U. Ganse, M. Stamminger,
                    "Enhanced Sphere Tracing", Smart Tools and Apps for Graphics (STAG), 2014.
   Balint & Valasek 2018  C. Balint, G. Valasek, "Accelerating Sphere Tracing", Eurographics
                    2018 Short Papers.
   Ban & Valasek 2023  R. Ban, G. Valasek, "Automatic Step Size Relaxation in Sphere
                    Tracing", Eurographics 2023 Short Papers.
   Guenter et al. 2012  B. Guenter, M. Finch, S. Drucker, D. Tan, J. Snyder, "Foveated 3D
                    Graphics", ACM Transactions on Graphics 31(6) (SIGGRAPH Asia), 2012.
   Quilez           I. Quilez, "Distance functions" (the primitives and operators) and "Soft
                    shadows in raymarched SDFs" (the penumbra estimate), iquilezles.org.
   Cody & Waite 1980  W. J. Cody, W. Waite, "Software Manual for the Elementary Functions",
                    Prentice-Hall, 1980 (the argument reduction of sin and cos, ch. 8).
   Payne & Hanek 1983  M. H. Payne, R. N. Hanek, "Radian Reduction for Trigonometric
                    Functions", ACM SIGNUM Newsletter 18(1), 1983.
   Dekker 1971      T. J. Dekker, "A Floating-Point Technique for Extending the Available
                    Precision", Numerische Mathematik 18, 1971 (the split and the exact
                    product).
   Moshier 1989     S. L. Moshier, "Methods and Programs for Mathematical Functions", Ellis
                    Horwood, 1989 (the Cephes library: the sinf, cosf and atanf polynomials).
   Sun Microsystems 1993  fdlibm, the freely distributable libm (logf and log2f: the
                    reduction to [sqrt(1/2), sqrt(2)) and the log1p polynomial).

LICENSE: see end of file.

RECENT REVISION HISTORY
   0.10.1 (2026-12-05) Documentation: PLATFORM NOTES name the headers each build includes
                      (xmmintrin only with MSVC); NUMERICS states the cross-target figures of
                      the current tests (the same images with FOV_NO_LIBM).
   0.10.0 (2026-12-05) fovsdf_gaze_predict: the fovea led by the latency in pursuit (shared block
                      revision 5); FOV_NO_LIBM takes the CPU's exact square root where it has one
                      (SSE, Arm, wasm), also in the batch evaluator: as many instructions as with
                      libm (was 1.6x); FOVSDF_MAX_* in the declarations.
   0.9.0 (2026-12-05) gaze input from the shared block of revision 4: fovsdf_gaze_filter_* (One Euro
                      filter with saccade restart), fovsdf_gaze_margin and fovsdf_config_gaze_margin
                      (a latency-safe fovea), fovsdf_gaze_fixed and FOV_GAZE_FIXED_MARGIN_DEG for
                      users without an eye tracker; off-axis per-eye frusta: fovsdf_init takes
                      cam.tan_left .. tan_top (was FOV_ERR_UNSUPPORTED); a symmetric frustum renders
                      as before, bit for bit.
   0.8.0 (2026-12-05) foveation the eye does not notice near the fovea: config.level_filter 2
                      (the levels keep their lighting and normal; each interpolated pixel
                      takes the albedo at its own ray's point on the taps' tangent planes) and
                      geometric refinement (config.refine_depth, refine_normal_deg,
                      refine_material: pixels whose taps straddle a silhouette, a crease or
                      two materials trace their own rays, bit for bit the full-resolution
                      pixel). fovsdf_config_acuity sets level_filter 2, refine_depth 0.05,
                      refine_normal_deg 25 and refine_material 1 (its images and counts
                      change: as good as classic by the eye-filtered measure at quality 1 on
                      most scenes and displays, see ACUITY-DRIVEN FOVEATION). With the three
                      new fields 0 and level_filter 0 or 1 every image and count is 0.7.0's.
                      A level cell is 48 bytes (was 32): fovsdf__fov_tile 47.3 KiB of stack.
                      The shared block of revision 3: fov_eye's default quality is 0.5 (was
                      1), twice the Nyquist rate of the eye's finest grating (fov_eye).
   0.7.0 (2026-12-02) the mandelbulb and the terrain use the library's own branch-free float
                      kernels (sin, cos, atan2, log, pow; within 4 ulp) with libm,
                      FOV_NO_LIBM and the math hooks alike, and run vectorised in the batch
                      evaluator: temple and fractals 1.7x and 1.25x fewer instructions, their
                      images within a few 8-bit channels of 0.6.0's (the other scenes bit for
                      bit); fovsdf_shade_points_grouped (a certified cone head start per group
                      of nearby points, for fovlp's samples); opt-in cheaper shadow rays
                      beyond an eccentricity (config.shadow_fov_deg, shadow_fov_t0_px,
                      shadow_fov_steps; off by default); per-tile pruning of the built-in
                      program against the tile's cone (FOVSDF_PRUNE_CODE, off by default: exact
                      and measured without gain here), fovsdf_batch.cone set for CONE and
                      CONE_FOV batches; SKIP's certified cones as wavefronts; the eccentricity's
                      atan2 only where a decision needs it; FOVSDF_WAVE_MIN 7 of 32 lanes.
                      Images and counters of every other scene unchanged.
   0.6.0 (2026-12-02) acuity-driven foveation: fovsdf_config_acuity fills FIPR's and CONE_FOV's
                      foveation fields from the display and the shared eye model (fovea to
                      the plan's e_half, quarter level from e_quarter, fovea-only mask,
                      refresh 1, level filter); a quarter level (config.quarter_deg: one ray
                      per 4x4 pixels, blended in over FOVSDF_QUARTER_BAND pixels, mask
                      output 3); config.level_filter (the levels' samples take their cell's
                      mean albedo); config.refine_contrast (interpolated pixels at a contrast
                      edge of their taps trace their own rays). fovsdf_config gained
                      quarter_deg, refine_contrast and level_filter; with all three 0 (the
                      defaults) images and counts are those of 0.5.0.
   0.5.0 (2026-12-02) wavefront rendering: a render call's pixels march, get their normals and
                      their shadow rays as batches (FOVSDF_WAVE rays in flight); a batch
                      distance interface (fovsdf_batch, scene.dist_batch, fovsdf_ray_cone,
                      fovsdf_distance_batch) with a vectorised evaluator for built-in programs
                      (fovsdf_program_eval_batch, the same value as fovsdf_program_eval for every
                      point); fovsdf_shade_points (n points at once, for fovlp.h); shadow
                      proofs for groups of shadow rays (FOVSDF_SHADOW_GROUP, off by default)
                      skip the samples that cannot change a light fraction. Images and
                      counts are unchanged (bit for bit). config.spp above FOVSDF_WAVE is
                      FOV_ERR_LIMIT.
   0.4.0 (2026-12-02) one block shared with fovlp.h and fovpt.h (tools/fov_shared.h, marked
                      regions; private names fov__); error messages on by default,
                      a specific one per failure (FOV_DEBUG no longer needed; msg "" under
                      FOV_NO_ERROR_STRINGS, never NULL); fovsdf_render_tile logs bad rows;
                      fov_camera shared: fovsdf_camera is a typedef of it (the same fields in
                      order, then tan_left .. tan_top; non-zero tangents: FOV_ERR_UNSUPPORTED);
                      fovsdf_camera_init now stands at (0, 0, 5) looking at the origin (+x right,
                      +y up; it was (0, 0, -5)); fovsdf_stats_init; one function per tracer
                      (images unchanged); REFERENCES cite every paper.
   0.3.0 (2026-12-01) accuracy and contract fixes found from outside: the hit refinement never
                      moves a hit past an unverified point (it jumped through thin surfaces);
                      no tracer evaluates or reports a hit beyond t_max or at a non-finite
                      point; the pixel-cone threshold uses each ray's own footprint (wide
                      fields of view and 4096x1 images reported misses as hits); the cone
                      march keeps its guarantee far from the origin (float margin) and an
                      exhausted cone past t_max is empty; IPR, SKIP and FIPR default to a safe,
                      cone-certified head start (new field heuristic_start = 1: the thesis's);
                      a 1x1 image keeps SKIP's ray in the image; interpolated FIPR/CONE_FOV
                      depths stay in [0, t_max]; fovsdf_trace no longer restarts caller rays;
                      normalisation of any finite vector; origins beyond 1e18 rejected;
                      fovsdf_program_build checks node parameters as the builder does (one
                      check; new fovsdf_program_check, fovsdf_builder.logger); finite,
                      NaN-free evaluation of every node in its ranges; rgb outputs clamped to
                      [0, 65504]; FOVSDF_VERSION_STRING matches the version (said 0.2.0).
   0.2.1 (2026-11-23) a camera whose up hint or view vector is tiny (1e-30) or huge (1e30) is
                      valid (was FOV_ERR_DEGENERATE: the squared length under/overflowed);
                      a NaN or infinite albedo from the callback is taken as 0 (was a NaN
                      pixel); a failed fovsdf_init leaves an existing context unchanged;
                      any finite gaze is valid (the shared eccentricity model scales a gaze
                      beyond ~1e19 px before normalising; ecc_ppd FLT_MAX, not inf);
                      fovsdf_min_filter radius above 64 is FOV_ERR_LIMIT.
   0.2.0 (2026-11-23) FIPR and CONE_FOV (foveated head starts, periphery refresh, mask output,
                      fovsdf_mask_blur), tile output buffers (fovsdf_output.origin_x/y),
                      fovsdf_program_compact; fovsdf_output gained fields (zero them with
                      fovsdf_output_init), fovsdf_config gained the foveation fields.
   0.1.0 (2026-11-22) first release: tracers, built-in scenes, shading, eccentricity model.
*/

#if defined(FOV_IMPL) && !defined(FOVSDF_IMPLEMENTATION)
#define FOVSDF_IMPLEMENTATION
#endif

#ifndef FOVSDF_H_INCLUDED
#define FOVSDF_H_INCLUDED

#include <stddef.h>
#include <stdint.h>

#define FOVSDF_VERSION_MAJOR 0
#define FOVSDF_VERSION_MINOR 10
#define FOVSDF_VERSION_PATCH 1
#define FOVSDF_VERSION_STRING "0.10.1"

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

#ifndef FOVSDF_API
#if defined(FOVSDF_STATIC)
#define FOVSDF_API static FOV__UNUSED
#elif defined(FOVSDF_IMPLEMENTATION)
#define FOVSDF_API FOV__API_EXPORT
#else
#define FOVSDF_API FOV__API_IMPORT
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ==== tracers and settings ================================================================ */

typedef enum fovsdf_method {
    FOVSDF_METHOD_CLASSIC = 0,     /* Hart 1996; the ground truth with a tight epsilon */
    FOVSDF_METHOD_RELAXED = 1,     /* over-relaxation with back-step, Keinert et al. 2014 */
    FOVSDF_METHOD_AUTORELAXED = 2, /* slope-driven relaxation, Ban & Valasek 2023 */
    FOVSDF_METHOD_BV2018 = 3,      /* linear-approximation step, Balint & Valasek 2018 */
    FOVSDF_METHOD_CONE = 4,        /* conservative cone pyramid head start (beyond the thesis) */
    FOVSDF_METHOD_IPR = 5,         /* inverted pyramid with minimum filter (thesis ch. 5) */
    FOVSDF_METHOD_SKIP = 6,        /* Skipping Spheres: scaled SDF, early termination (ch. 6) */
    FOVSDF_METHOD_FIPR = 7,        /* foveated IPR: acuity and edge mask, mid level elsewhere */
    FOVSDF_METHOD_CONE_FOV = 8,    /* the FIPR mask and refresh on the cone pyramid */
    _FOVSDF_METHOD_NUM,
    _FOVSDF_METHOD_FORCE_U32 = 0x7FFFFFFF
} fovsdf_method;

typedef enum fovsdf_eps_mode {
    FOVSDF_EPS_BOTH = 0,      /* hit when d < max(eps, eps_px * footprint * t)  (default) */
    FOVSDF_EPS_ABSOLUTE = 1,  /* hit when d < eps */
    FOVSDF_EPS_CONE = 2,      /* hit when d < eps_px * footprint * t (footprint: the ray's pixel
                                 angle, pixel_angle cos^2(theta), NUMERICS) */
    _FOVSDF_EPS_NUM,
    _FOVSDF_EPS_FORCE_U32 = 0x7FFFFFFF
} fovsdf_eps_mode;
/* Whatever the mode, the threshold never drops below 8 float ulps of |camera| + t. */

typedef enum fovsdf_shading {
    FOVSDF_SHADE_FULL = 0,       /* albedo * (ambient + sum of lights * Lambert * soft shadow) */
    FOVSDF_SHADE_NO_SHADOWS = 1, /* as FULL without shadow rays */
    FOVSDF_SHADE_NORMALS = 2,    /* 0.5 + 0.5 * normal */
    FOVSDF_SHADE_DEPTH = 3,      /* grey 1 - t / t_max */
    FOVSDF_SHADE_STEPS = 4,      /* heat map of the evaluations per pixel (blue 1, red 256) */
    _FOVSDF_SHADE_NUM,
    _FOVSDF_SHADE_FORCE_U32 = 0x7FFFFFFF
} fovsdf_shading;

/* Acuity model of the thesis (Eq. 4.1, 4.2, 5.1): the probability that a pixel at eccentricity
   w (degrees) is traced at full resolution, p(w) = A exp(-rate w) + C, with p = 1 inside the
   fovea and 0 beyond the outer periphery (outer_deg 0: no outer zone). The OCR of the thesis
   garbles the exponent; we read it as a rate of 0.20651 per degree (tau = 4.842 degrees), the
   one reading that matches the thesis's own "75 % lower at 6 degrees" (p(6) = 0.271 against
   p(0) = 0.918) and the hyperbola-like fall-off it cites (both in its Sec. 2.1.2). */
typedef struct fovsdf_acuity {
    float A;          /* 0.90964 */
    float rate;       /* per degree, 1 / tau: 0.20651 */
    float C;          /* 0.00792 */
    float fovea_deg;  /* p = 1 below: 7.5 (the thesis's imperceptible fovea) */
    float outer_deg;  /* p = 0 beyond (0: never) */
} fovsdf_acuity;

/* Rendering settings. A zero-filled config means "all defaults" (listed per field);
   fovsdf_config_default() gives the same settings filled in (and no g++ -Wextra warning). */
typedef struct fovsdf_config {
    uint32_t method;        /* fovsdf_method                                       0: classic */
    uint32_t spp;           /* samples per pixel: 1, 4 or 16 (patterns below)      0: 1 */
    uint32_t eps_mode;      /* fovsdf_eps_mode                                     0: both */
    float eps;              /* absolute hit threshold, world units                 0: 1e-4 */
    float eps_px;           /* pixel-cone hit threshold, in pixels                 0: 0.25 */
    uint32_t max_steps;     /* march steps per ray, <= FOVSDF_MAX_STEPS            0: 256 */
    float t_max;            /* rays beyond it miss; 0: the scene's t_max, else      100 */
    float omega;            /* RELAXED: step factor in [1, 2)                      0: 1.6 */
    float ar_beta;          /* AUTORELAXED: slope smoothing in (0, 1]              0: 0.3 */
    float bv_relax;         /* BV2018: weight of the linear extrapolation in (0,1]  0: 0.9 */
    uint32_t shading;       /* fovsdf_shading                                      0: full */
    uint32_t shadow_steps;  /* max steps per shadow ray                            0: 64 */
    float shadow_eps;       /* shadow ray: stop when the penumbra factor < it      0: 1e-3 */
    float shadow_t0;        /* shadow ray start offset along the light, world units 0: 1e-2 */
    float shadow_fov_deg;   /* cheaper shadow rays for the samples beyond this eccentricity,
                               degrees (each sample ray's, fov_display; the pixels within,
                               up to float rounding at the threshold, keep today's shadows
                               bit for bit): the two fields below; [0, 180]
                                                                  0: off (every ray as above) */
    float shadow_fov_t0_px; /* beyond shadow_fov_deg: the shadow ray starts at least this many
                               pixel footprints at the hit (pixel_angle * distance from the
                               pinhole) along the light, skipping the small steps next to the
                               surface: contact shadows thinner than that go (CHEAPER
                               SHADOWS BEYOND THE FOVEA); 0 .. 1e6                    0: 4 */
    uint32_t shadow_fov_steps; /* beyond shadow_fov_deg: max steps per shadow ray, 1 ..
                               shadow_steps; below shadow_steps, a ray that runs out still in
                               a penumbra (its last k h / t < 1) is dark (0), else it keeps its
                               running minimum (measured: costly in error, see CHEAPER
                               SHADOWS BEYOND THE FOVEA)  0 (kept 0): shadow_steps, no cut */
    float normal_eps;       /* tetrahedron half-size; 0: 0.5 pixel cone at the hit (>= 1e-4) */
    uint32_t cone_tile;     /* CONE: side of the top-level tiles, pixels, power of 2 <= 256;
                                                                                   0: 16 */
    uint32_t cone_levels;   /* CONE: cone levels, each halving the cell side, at most
                               log2(cone_tile) + 1 (down to single pixels); 0: log2(cone_tile),
                               i.e. down to 2x2-pixel cells (measured cheapest) */
    uint32_t ipr_levels;    /* IPR: pyramid levels including the full-resolution one, 1 .. 6
                               (1 = no head start); each lower level has 1/4 of the pixels
                                                                          0: 3 (1/16, 1/4, 1) */
    int32_t ipr_radius;     /* IPR: radius of the neighbour minimum filter applied before each
                               level, 1 .. 3 (negative: an error)           0: 1 (3x3 filter) */
    uint32_t ipr_no_filter; /* IPR: 1 = no minimum filter (the thesis's ablation; may miss) */
    uint32_t ipr_tile;      /* IPR: tile side in pixels (multiple of 2^(levels-1), <= 64;
                               working memory is per tile)                              0: 32 */
    uint32_t skip_block;    /* SKIP: pixels per axis of a low-resolution cell, 1 .. 16   0: 4 */
    float skip_scale;       /* SKIP: SDF scale s of the low-resolution pass (> 0; 1 = no
                               scaling, the ablation "without SC")                   0: 1.005 */
    float skip_eps;         /* SKIP: early-termination threshold of the low-resolution pass,
                               world units (the ablation "without ET": set it to eps) 0: 0.05 */
    uint32_t skip_no_shadow_start; /* SKIP: 1 = shadow rays get no head start            */
    uint32_t finish;        /* head-start methods: tracer of the sample rays from their head
                               start, fovsdf_finish                                 0: bv2018 */
    uint32_t heuristic_start; /* IPR, SKIP, FIPR: 0 = safe head starts, certified by a cone over
                               each cell (no sample ray starts past its first hit, see
                               ACCELERATED METHODS); 1 = the thesis's unverified head starts
                               (minimum filter, scaled scene, early termination)      0: safe */
    /* FIPR and CONE_FOV: which pixels trace their own sample rays (see ACCELERATED METHODS) */
    fovsdf_acuity acuity;   /* p(w); a zero field takes its default (fovsdf_acuity_default:
                               fovea 7.5 degrees of eccentricity, no outer zone) */
    uint32_t fov_mask;      /* fovsdf_fov_mask: how fovea, acuity and edges combine  0: edges */
    float edge_threshold;   /* relative depth change per low-resolution cell (Sobel) that
                               makes an edge, > 0                                    0: 0.1 */
    float quarter_deg;      /* FIPR and CONE_FOV: beyond this eccentricity, degrees, the
                               pixels outside the mask take a quarter level (one ray per 4x4
                               pixels) instead of the mid level, blended over a band of
                               FOVSDF_QUARTER_BAND pixels; >= acuity.fovea_deg, <= 180
                                                                           0: none (mid level) */
    float refine_contrast;  /* FIPR and CONE_FOV: a pixel outside the mask whose interpolation
                               taps' luminances differ by more than this Michelson contrast,
                               (max - min) / (max + min + 1e-3), traces its own rays; >= 0
                                                                                   0: never */
    uint32_t level_filter;  /* FIPR and CONE_FOV: 1 = the mid and quarter levels' samples take
                               their cell's mean albedo (a prefiltered texture: no aliasing of
                               textures the sparse rays would point-sample; no extra distance
                               evaluations); 2 = the levels' samples give their lighting only,
                               and each interpolated pixel takes the albedo at its own ray's
                               point on each tap's tangent plane (the texture at full
                               resolution; no extra distance evaluations); 0: point samples */
    float refine_depth;     /* FIPR and CONE_FOV: a pixel outside the mask whose interpolation
                               taps disagree on hit and miss, or whose hits' depths differ by
                               more than this fraction of the nearest, traces its own rays (a
                               silhouette); >= 0                                    0: never */
    float refine_normal_deg; /* FIPR and CONE_FOV: ... whose hits' normals differ by more than
                               this angle, degrees (a crease); in [0, 180]          0: never */
    uint32_t refine_material; /* FIPR and CONE_FOV: 1 = ... whose hits lie on different
                               materials (another object); 0 or 1                   0: never */
    uint32_t refresh;       /* pixels outside the mask are refreshed every refresh-th frame:
                               1, 2 or 4 (the thesis's 1/1, 1/2, 1/4 rates)          0: 1 */
    uint32_t frame;         /* frame number: which quarter or half of the periphery refreshes */
    uint32_t seed;          /* seed of the mask's random numbers (fovsdf_u01) */
    fov_display display;    /* for eccentricity; all zero: the camera's field of view */
    fov_logger logger;      /* optional diagnostics */
} fovsdf_config;

/* How FIPR and CONE_FOV choose the pixels that trace their own sample rays (the rest take the
   mid level, interpolated). u = fovsdf_u01(seed, x, y, 0), p = fovsdf_acuity_p(acuity, w). */
typedef enum fovsdf_fov_mask {
    FOVSDF_MASK_EDGES = 0,  /* fovea OR (edge AND u < p): the thesis's edges-in-the-periphery
                               reading (default) */
    FOVSDF_MASK_ACUITY = 1, /* fovea OR u < p: acuity alone (the chapter 4 sampling) */
    FOVSDF_MASK_FOVEA = 2,  /* fovea only */
    _FOVSDF_MASK_NUM,
    _FOVSDF_MASK_FORCE_U32 = 0x7FFFFFFF
} fovsdf_fov_mask;

/* Tracer of the sample rays after a head start (CONE). Measured over the built-in scenes at
   320x180: the Balint-Valasek step needs 15 % fewer evaluations than classic from a head start. */
typedef enum fovsdf_finish {
    FOVSDF_FINISH_DEFAULT = 0,     /* = FOVSDF_FINISH_BV2018 */
    FOVSDF_FINISH_CLASSIC = 1,
    FOVSDF_FINISH_RELAXED = 2,
    FOVSDF_FINISH_AUTORELAXED = 3,
    FOVSDF_FINISH_BV2018 = 4,
    _FOVSDF_FINISH_NUM,
    _FOVSDF_FINISH_FORCE_U32 = 0x7FFFFFFF
} fovsdf_finish;

/* Sample patterns (offsets from the pixel centre, in pixels):
     1 spp: (0, 0).
     4 spp: rotated grid, (+-1/8, +-3/8) and (+-3/8, -+1/8): (-1/8,-3/8) (3/8,-1/8) (1/8,3/8)
            (-3/8,1/8).
     16 spp: a 4x4 grid of strata of size 1/4, each sample jittered inside its stratum by a
            fixed n-rooks pattern so no two samples share a row or a column of a 16x16 grid.
   The pixel's colour is the box-filtered mean of its samples. */

/* ==== camera ============================================================================== */

/* The shared camera, fov_camera (its declaration documents the frame, handedness, pixel
   convention and defaults). fovsdf uses every field. Off-axis tangents (an HMD eye's, e.g.
   OpenVR's GetProjectionRaw or OpenXR's XrFovf, as positive tangents) give every tracer the
   frustum's rays and, when config.display is all zero, the frustum's eccentricity model
   (fov_display); all 0 keeps the symmetric camera of fov_y_deg, bit for bit. Limits: width
   and height 1 .. FOVSDF_MAX_DIM; pos, eye_offset and the pinhole pos + eye_offset * right
   lie within 1e18 of the origin (per component; fovsdf_init rejects more with
   FOV_ERR_INVALID_ARG, see NUMERICS). Stereo: eye_offset -ipd/2 for the left eye, +ipd/2 for
   the right one, each eye's tangents and gaze; render each eye with its own context
   (examples/sdf_stereo.c). */
typedef fov_camera fovsdf_camera;

/* ==== scenes ============================================================================== */

/* What the tracer tells an extended distance callback, and what the callback may report. */
typedef struct fovsdf_query {
    float inflate;          /* SDF scaling s (Skipping Spheres): 1 = the exact scene. A
                               callback that honours it returns f(p/s)*s per object, with
                               subtracted operands scaled by 1/s (holes shrink when objects
                               grow). Callbacks that ignore it stay correct, only slower. */
    float eps;              /* the current hit threshold, for bounding-volume margins */
    uint32_t want_material; /* 1: set material */
    int32_t material;       /* out: material id of the nearest surface; the built-in program
                               reports -1 far from every surface, where a bounding sphere
                               stood in for the nearest subtree (never within a quarter of
                               the bound's radius of it, so never at a hit) */
    uint32_t prims;         /* out, accumulated: primitive evaluations */
    uint32_t prims_skipped; /* out, accumulated: primitive evaluations skipped by bounds
                               (prims + prims_skipped = the program's primitive count) */
} fovsdf_query;

typedef float (*fovsdf_dist_fn)(const float p[3], void *user);
typedef float (*fovsdf_dist_ex_fn)(const float p[3], fovsdf_query *q, void *user);

/* A cone that contains a set of points: every point p of the set has p = apex + t u with u a
   unit vector within the half-angle atan(tan_half) of axis and t in [t0, t1] (the distance
   from the apex along the ray). CONE and CONE_FOV hand one to batch callbacks (fovsdf_batch.
   cone): the cone of the top-level tile (CONE_FOV: with its apron of 2 pixels) from the
   pinhole out to t_max (t0 0, t1 1.001 t_max), with every batch of the tile's cone pyramid and
   sample rays whose points all lie in it (as computed in float; normals, shadow rays and
   everything else: NULL). A callback may prune its scene for it (the cone changes once per
   tile: compare its fields, not its address, to reuse a pruning), but whatever it drops must
   not change the value, material or counts at any point of the cone: the images must not
   depend on whether a point came with a cone. The built-in program can prune itself the same
   way (FOVSDF_PRUNE_CODE, off by default: on the built-in scenes it saves nothing). */
typedef struct fovsdf_ray_cone {
    float apex[3];
    float axis[3];          /* unit */
    float tan_half;         /* >= 0 */
    float t0, t1;           /* 0 <= t0 <= t1 */
} fovsdf_ray_cone;

/* A batch of points for a batch distance callback, as arrays (structure of arrays). The
   library fills n, x, y, z, eps, inflate, d (with NaN: a distance the callback leaves
   unwritten is a miss, FLT_MAX) and material, and reads d and material back; the callback
   adds its primitive counts to prims and prims_skipped. Each point must get exactly the value
   the per-point callbacks (if the scene has them too) would give it with the same inflate and
   eps: the library uses either, and the images then do not depend on which. */
typedef struct fovsdf_batch {
    uint32_t n;              /* points, 1 .. FOVSDF_BATCH */
    const float *x, *y, *z;  /* the points */
    const float *eps;        /* per point: the hit threshold there (as fovsdf_query.eps) */
    float inflate;           /* as fovsdf_query.inflate, one value for the batch */
    float *d;                /* out: n distances */
    int32_t *material;       /* NULL (not wanted) or out: n material ids (fovsdf_query) */
    uint32_t prims;          /* out, accumulated: primitive evaluations */
    uint32_t prims_skipped;  /* out, accumulated: primitive evaluations skipped by bounds */
    const fovsdf_ray_cone *cone; /* NULL or a cone that contains every point of the batch
                                    (fovsdf_ray_cone: CONE and CONE_FOV tiles set it) */
} fovsdf_batch;
typedef void (*fovsdf_dist_batch_fn)(fovsdf_batch *b, void *user);
typedef void (*fovsdf_albedo_fn)(const float p[3], int32_t material, float rgb[3], void *user);
#ifdef FOVSDF_DOUBLE
typedef double (*fovsdf_dist_d_fn)(const double p[3], void *user);
#endif

typedef enum fovsdf_light_type {
    FOVSDF_LIGHT_DIRECTIONAL = 0, /* v = direction towards the light (need not be unit) */
    FOVSDF_LIGHT_POINT = 1,       /* v = position; falloff 1 / (1 + d^2 / range^2) */
    _FOVSDF_LIGHT_NUM,
    _FOVSDF_LIGHT_FORCE_U32 = 0x7FFFFFFF
} fovsdf_light_type;

typedef struct fovsdf_light {
    uint32_t type;          /* fovsdf_light_type */
    float v[3];             /* direction or position */
    float color[3];         /* linear RGB intensity */
    float range;            /* point light: falloff radius, and no light (no shadow ray)
                               beyond 8 * range; 0: infinite, no falloff */
    float shadow_k;         /* penumbra hardness k of Algorithm 2 (8 soft .. 128 hard);
                               0: 16; negative: this light casts no shadows */
} fovsdf_light;

#ifndef FOVSDF_MAX_LIGHTS
#define FOVSDF_MAX_LIGHTS 8
#endif

/* A scene: a distance function plus how to light and colour it. Not a config: zero fields
   are literal (no lights, black sky) except lipschitz (0 = 1). fovsdf_scene_init sets a
   useful default (one white sun, grey sky gradient, ambient 0.15). */
typedef struct fovsdf_scene {
    fovsdf_dist_fn dist;        /* plain distance callback; or */
    fovsdf_dist_ex_fn dist_ex;  /* extended callback, used when not NULL */
    void *user;                 /* passed to every callback */
    fovsdf_albedo_fn albedo;    /* NULL: a built-in palette indexed by material id, with
                                   material 1 a checkerboard on x/z */
    float lipschitz;            /* bound on |grad f|; steps are divided by it; 0: 1 */
    float t_max;                /* scene extent along rays; 0: use the config's */
    uint32_t num_lights;        /* <= FOVSDF_MAX_LIGHTS */
    fovsdf_light lights[FOVSDF_MAX_LIGHTS];
    float ambient[3];           /* added to every hit's light */
    float sky_zenith[3];        /* sky colour straight up */
    float sky_horizon[3];       /* sky colour at the horizon and below */
    fovsdf_dist_batch_fn dist_batch; /* optional batch callback (fovsdf_batch): every tracer,
                                   normal and shadow ray evaluates through it when it is set
                                   (with per-point callbacks too: single points use those) */
#ifdef FOVSDF_DOUBLE
    fovsdf_dist_d_fn dist_d;    /* optional double distance for the reference tracer */
#endif
} fovsdf_scene;

/* ==== built-in scene description (a tree of nodes compiled into a program) =============== */

/* Node parameters and their ranges. The builder functions and fovsdf_program_build apply one
   check (fovsdf_program_check): every parameter a node reads is finite (else
   FOV_ERR_NOT_FINITE); every length (sizes, radii, offsets, periods, blend radii, capsule end
   points, the plane's offset, the terrain's amplitude and frequency) is at most 1e18 in
   magnitude (else FOV_ERR_LIMIT: squares of scene lengths must stay finite in float, see
   NUMERICS); the ranges below hold (else FOV_ERR_INVALID_ARG; a zero plane normal is
   FOV_ERR_DEGENERATE). Sizes have no lower bound but > 0. */
typedef enum fovsdf_node_type {
    FOVSDF_NODE_NONE = 0,
    /* primitives (centred at the origin) */
    FOVSDF_NODE_SPHERE,       /* f0 radius > 0 */
    FOVSDF_NODE_BOX,          /* f0..f2 half extents > 0 */
    FOVSDF_NODE_ROUND_BOX,    /* f0..f2 half extents > 0, f3 rounding radius in [0, min f0..f2] */
    FOVSDF_NODE_BOX_FRAME,    /* f0..f2 half extents > 0, f3 frame thickness > 0 */
    FOVSDF_NODE_TORUS,        /* f0 major radius >= 0, f1 minor radius > 0; in the x/z plane */
    FOVSDF_NODE_CAPSULE,      /* segment f0..f2 -> f3..f5, f6 radius > 0 */
    FOVSDF_NODE_CYLINDER,     /* along y: f0 half height > 0, f1 radius > 0 */
    FOVSDF_NODE_CONE,         /* capped cone along y: f0 half height > 0, f1 bottom, f2 top
                                 radius >= 0, not both 0 */
    FOVSDF_NODE_PLANE,        /* f0..f2 normal (non-zero; the builder and the build normalise
                                 it), f3 offset: dot(p, n) + f3 */
    FOVSDF_NODE_MENGER,       /* Menger sponge: f0 half size > 0, i0 iterations (1..8) */
    FOVSDF_NODE_MANDELBULB,   /* f0 power in [2, 16], i0 iterations (1..32); radius about 1.2 */
    FOVSDF_NODE_TERRAIN,      /* height field y = f0 * fbm(x * f1, z * f1), i0 octaves (1..12),
                                 f0 >= 0, f1 > 0; a distance bound (y - h) * f2 with f2 in
                                 (0, 1] (fovsdf_terrain sets f2 = 1 / sqrt(1 + G^2), G its bound
                                 on the slope, which makes it Lipschitz 1) */
    /* The mandelbulb's atan2, pow, sin, cos, log and the terrain's sin are the library's own
       float kernels (within 4 ulp of the exact functions; the implementation's "own float
       kernels" comment has the bounds and their conditions), whatever the math configuration
       (libm, FOV_NO_LIBM, the math hooks but FOV_SQRTF, which their square roots use): these
       two primitives give the same values on every target, and the batch evaluator runs them
       vectorised. */
    /* binary operators: a, b children */
    FOVSDF_NODE_UNION,
    FOVSDF_NODE_SUBTRACT,     /* a minus b */
    FOVSDF_NODE_INTERSECT,
    FOVSDF_NODE_SMOOTH_UNION,     /* f0 = k > 0, blend radius */
    FOVSDF_NODE_SMOOTH_SUBTRACT,  /* f0 = k > 0 */
    FOVSDF_NODE_SMOOTH_INTERSECT, /* f0 = k > 0 */
    /* unary: a child */
    FOVSDF_NODE_TRANSLATE,    /* f0..f2 offset */
    FOVSDF_NODE_ROTATE,       /* f0..f8 rotation matrix (row-major, object -> world; rows
                                 orthonormal within 1e-3) */
    FOVSDF_NODE_SCALE,        /* f0 uniform scale > 0 */
    FOVSDF_NODE_REPEAT,       /* f0..f2 period per axis >= 0 (0: no repetition on that axis),
                                 i0..i2 copies each side, 0 .. 1000000 (0: infinite) */
    FOVSDF_NODE_MIRROR,       /* i0 bit mask of mirrored axes (1 x, 2 y, 4 z), 1 .. 7: p -> |p| */
    FOVSDF_NODE_ROUND,        /* f0 radius >= 0: f - r */
    FOVSDF_NODE_ONION,        /* f0 thickness > 0: |f| - th (the canonical onion) */
    _FOVSDF_NODE_NUM,
    _FOVSDF_NODE_FORCE_U32 = 0x7FFFFFFF
} fovsdf_node_type;

typedef struct fovsdf_node {
    uint32_t type;          /* fovsdf_node_type */
    int32_t a, b;           /* child node indices (operators), -1 when unused */
    int32_t material;       /* primitives: material id */
    int32_t i[3];           /* integer parameters */
    float f[9];             /* float parameters */
} fovsdf_node;

/* Builds nodes into a caller array; every function returns the new node's index, or -1
   after an error (then err says why, and later calls keep returning -1). Each node is checked
   exactly as fovsdf_program_build checks it (fovsdf_program_check): the ranges given at
   fovsdf_node_type, finite parameters, lengths at most 1e18 in magnitude. */
typedef struct fovsdf_builder {
    fovsdf_node *nodes;
    uint32_t cap, count;
    int32_t material;       /* material given to the primitives created next */
    fov_result err;
    fov_logger logger;      /* optional: receives a message with the first error (the node,
                               the field and its allowed range); fovsdf_builder_init clears it */
} fovsdf_builder;

/* A compiled scene program (opaque data in caller memory; evaluate it with
   fovsdf_program_eval, or hand it to a scene with fovsdf_scene_set_program). */
typedef struct fovsdf_program {
    const void *code;       /* instructions */
    uint32_t count;         /* number of instructions */
    uint32_t prims;         /* number of primitive instructions */
    uint32_t bounds;        /* number of bounding volumes */
    float bound_center[3];  /* bounding sphere of the whole scene (radius < 0: unbounded) */
    float bound_radius;
} fovsdf_program;

/* ==== built-in scenes ===================================================================== */

typedef enum fovsdf_builtin_id {
    FOVSDF_SCENE_PRIMITIVES = 0, /* open: primitives on a checkerboard plane */
    FOVSDF_SCENE_COLUMNS = 1,    /* closed: repeated columns, several point lights */
    FOVSDF_SCENE_TEMPLE = 2,     /* a temple on a cliff terrain, large depth range */
    FOVSDF_SCENE_ATRIUM = 3,     /* an interior with arcades, many objects */
    FOVSDF_SCENE_THIN = 4,       /* wires, small spheres, subtraction holes */
    FOVSDF_SCENE_FRACTALS = 5,   /* Menger sponge and Mandelbulb */
    _FOVSDF_SCENE_NUM,
    _FOVSDF_SCENE_FORCE_U32 = 0x7FFFFFFF
} fovsdf_builtin_id;

typedef struct fovsdf_builtin {
    fovsdf_scene scene;     /* ready to trace; scene.user points into the caller memory */
    fovsdf_camera camera;   /* a suggested view (640x360; change width/height freely) */
    const fovsdf_program *program;
    const char *name;
} fovsdf_builtin;

/* ==== per-frame context and outputs ======================================================= */

typedef struct fovsdf_ctx {  /* filled by fovsdf_init; read-only afterwards */
    fovsdf_config cfg;       /* resolved: defaults filled in */
    fovsdf_scene scene;
    fovsdf_camera cam;
    fov_gaze gaze;
    fov_ecc_model ecc;
    float origin[3];         /* pinhole after the stereo offset */
    float right[3], up[3], fwd[3];
    float tan_half_y, aspect;
    float pixel_angle;       /* angle of one pixel at the image centre, radians (2 tan(fov_y/2)
                                / height); a ray at angle theta off the axis uses
                                pixel_angle cos^2(theta), its own footprint (NUMERICS) */
    float t_max;
    float cam_dist;          /* the scene's distance at the camera (sign: inside < 0) */
    float shadow_fov_cos;    /* cos(cfg.shadow_fov_deg): eccentricity test of the shaded rays */
    void *mem;
    size_t mem_size;
    uint32_t off_axis;       /* 1: cam.tan_left .. tan_top give the frustum (tan4) */
    float tan4[4];           /* off-axis: tan_left, tan_right, tan_bottom, tan_top */
} fovsdf_ctx;

/* Per-pixel outputs; every pointer may be NULL (not written). Strides are in elements
   (floats, bytes or integers) per row; 0 means tightly packed. The buffers describe the
   whole image: fovsdf_render_rows writes only its rows. */
typedef struct fovsdf_output {
    float *rgb;            uint32_t rgb_stride;      /* linear RGB, 3 floats per pixel, each
                                                        in [0, 65504] (NUMERICS) */
    uint8_t *rgb8;         uint32_t rgb8_stride;     /* sRGB-encoded 8-bit RGB */
    float *depth;          uint32_t depth_stride;    /* ray t of the nearest hitting sample;
                                                        t_max when no sample hit */
    uint8_t *hit;          uint32_t hit_stride;      /* 1 when at least half the samples hit */
    uint32_t *evals;       uint32_t evals_stride;    /* distance evaluations of the pixel
                                                        (primary rays, normals, shadows) */
    uint32_t *steps;       uint32_t steps_stride;    /* march steps of its primary rays */
    float *start;          uint32_t start_stride;    /* t its sample rays started from (head
                                                        start; 0 without one; t_max when a
                                                        conservative pass proved it empty) */
    int32_t *material;     uint32_t material_stride;  /* of the nearest hit, -1 for a miss */
    uint8_t *mask;         uint32_t mask_stride;     /* how the pixel was made: 1 its own sample
                                                        rays (every method but FIPR/CONE_FOV);
                                                        0 interpolated from the mid level; 2 kept
                                                        from an earlier frame (not written); 3
                                                        from the quarter level (quarter_deg) */
    uint32_t origin_x, origin_y; /* the buffers' first element is pixel (origin_x, origin_y):
                                    0, 0 for whole-image buffers; a tile's corner for tile
                                    buffers (set the strides to the tile's width). Rendering
                                    pixels left of or above the origin is FOV_ERR_INVALID_ARG.
                                    A zero stride means rows of width - origin_x pixels. */
} fovsdf_output;

/* Deterministic counters. Every function that takes a fovsdf_stats * (render_rows / _tile,
   trace, shade_point, march, distance, normal, soft_shadow, shade; NULL: not counted) adds
   to it and none resets it, so one struct can sum a frame's calls, or many frames. Start a
   count with fovsdf_stats_init (all zero; `fovsdf_stats s = {0};` is the same in C, but
   warns under g++ -Wextra). With threads give each its own and sum them with
   fovsdf_stats_add. */
typedef struct fovsdf_stats {
    uint64_t evals;          /* every distance evaluation */
    uint64_t evals_primary;  /* of primary (camera) rays */
    uint64_t evals_normal;   /* of normals */
    uint64_t evals_shadow;   /* of shadow rays */
    uint64_t evals_lowres;   /* of head-start passes (accelerated methods) */
    uint64_t rays;           /* primary rays */
    uint64_t shadow_rays;
    uint64_t hits;           /* primary rays that hit */
    uint64_t exhausted;      /* primary rays that ran out of steps */
    uint64_t prims;          /* built-in programs: primitive evaluations */
    uint64_t prims_skipped;  /* built-in programs: primitive evaluations saved by bounds */
} fovsdf_stats;

typedef enum fovsdf_hit_kind {
    FOVSDF_MISS = 0,
    FOVSDF_HIT = 1,
    FOVSDF_EXHAUSTED = 2,    /* ran out of steps before t_max: treated as a hit */
    _FOVSDF_HIT_FORCE_U32 = 0x7FFFFFFF
} fovsdf_hit_kind;

typedef struct fovsdf_hit {
    uint32_t kind;           /* fovsdf_hit_kind */
    float t;                 /* ray parameter reached (t_max on a miss) */
    float dist;              /* the distance value at t */
    uint32_t steps;          /* march steps taken */
    uint32_t evals;          /* distance evaluations (steps plus back-steps) */
} fovsdf_hit;

/* Explicit parameters for fovsdf_march (no defaults: every field is taken as given). */
typedef struct fovsdf_march_params {
    uint32_t method;        /* fovsdf_method */
    uint32_t max_steps;     /* 1 .. FOVSDF_MAX_STEPS (0 is an error here) */
    float eps;              /* absolute hit threshold (>= 0) */
    float eps_cone;         /* threshold growth per unit t, radians (>= 0); eps or eps_cone > 0 */
    float t_max;            /* > 0 */
    float omega;            /* RELAXED: [1, 2) */
    float ar_beta;          /* AUTORELAXED: (0, 1] */
    float bv_relax;         /* BV2018: (0, 1] */
} fovsdf_march_params;

/* ==== functions =========================================================================== */

/* Versions and results */
FOVSDF_API const char *fovsdf_result_string(fov_result r);   /* never NULL */
FOVSDF_API const char *fovsdf_method_name(uint32_t method);  /* "classic", ...; never NULL */

/* Config: defaults, and the effective values (defaults filled in) with validation. */
FOVSDF_API fovsdf_config fovsdf_config_default(void);
FOVSDF_API fovsdf_config fovsdf_config_ground_truth(void);  /* classic, eps 1e-5, eps_px 0.01,
                                                              4096 steps */
FOVSDF_API fov_result fovsdf_config_resolve(const fovsdf_config *in, fovsdf_config *out);
/* Acuity-driven foveation (ACCELERATED METHODS, ACUITY-DRIVEN FOVEATION): fills only the
   foveation fields of *cfg (acuity.fovea_deg, acuity.outer_deg, quarter_deg, refresh, fov_mask,
   level_filter, refine_depth, refine_normal_deg, refine_material) from the display in
   cfg->display (all zero: cam's fov_y_deg), cam's size (cam must not be NULL) and the eye
   (NULL: the defaults, fov_eye); every other field, method included, stays as the caller set
   it. FOV_ERR_NULL, the eccentricity model's or the eye's error code, or
   fovsdf_config_resolve's for the config it would give, with a message through cfg->logger;
   *cfg is unchanged on error. */
FOVSDF_API fov_result fovsdf_config_acuity(fovsdf_config *cfg, const fovsdf_camera *cam,
                                           const fov_eye *eye);

/* Camera and scene helpers. fovsdf_camera_init sets the fov_camera defaults (the same as
   fovpt_camera_init's: pos (0, 0, 5) looking at the origin, up +y, 60 degrees; world +x on
   the image's right, +y at its top). fovsdf_camera_basis gives the camera's frame (see
   fov_camera; the one fovsdf_init uses): right, up, fwd unit and orthogonal. */
FOVSDF_API void fovsdf_camera_init(fovsdf_camera *cam, uint32_t width, uint32_t height);
FOVSDF_API fov_result fovsdf_camera_basis(const fovsdf_camera *cam, float right[3],
                                          float up[3], float fwd[3]);
FOVSDF_API void fovsdf_scene_init(fovsdf_scene *scene);
FOVSDF_API void fovsdf_scene_set_program(fovsdf_scene *scene, const fovsdf_program *prog);

/* Eccentricity (the shared model; see fov_display). cam_fov_y_deg is used when the display
   gives no geometry. Returns FOV_ERR_* for bad sizes, NaN gaze or degenerate displays. */
FOVSDF_API fov_result fovsdf_ecc_init(fov_ecc_model *m, const fov_display *display,
                                      float cam_fov_y_deg, uint32_t width, uint32_t height,
                                      fov_gaze gaze);
FOVSDF_API float fovsdf_ecc_deg(const fov_ecc_model *m, float x, float y); /* degrees */
/* Pixels per degree at the gaze point (radial direction), e.g. for FLIP. */
FOVSDF_API float fovsdf_ecc_ppd(const fov_ecc_model *m);
/* The eye's resolution (the shared model; see fov_eye; eye NULL = the defaults). _eye_mar: the
   allowed sample spacing at ecc_deg, quality * MAR, degrees (0 for bad input). _eye_density:
   the linear samples per display pixel the eye needs there for a display of ppd pixels per
   degree, (0, 1] (1 for bad input). _eye_ecc: the eccentricity, [0, 180] degrees, from which a
   linear density suffices (its inverse; bad input: 0 for density >= 1, else 180). _eye_plan:
   fov_eye_plan for an eccentricity model (FOV_ERR_NULL, _NOT_FINITE, _INVALID_ARG). */
FOVSDF_API float fovsdf_eye_mar(const fov_eye *eye, float ecc_deg);
FOVSDF_API float fovsdf_eye_density(const fov_eye *eye, float ppd, float ecc_deg);
FOVSDF_API float fovsdf_eye_ecc(const fov_eye *eye, float ppd, float density);
FOVSDF_API fov_result fovsdf_eye_plan(const fov_eye *eye, const fov_ecc_model *m,
                                      fov_eye_plan *plan);

/* GAZE INPUT (the shared model: see fov_gaze_filter_config; the same functions in fovsdf.h,
   fovlp.h and fovpt.h). A filter in your memory conditions the tracker's raw samples; its
   state, the tracker's accuracy and the system's latency give a margin that
   fovsdf_config_gaze_margin adds to the config's full-quality radii. No eye tracker: fixed
   foveation, fovsdf_gaze_fixed (the display's axis point) with FOV_GAZE_FIXED_MARGIN_DEG.
      fov_gaze_filter gf;  fovsdf_gaze_filter_init(&gf, NULL);           // once (NULL: defaults)
      // per tracker sample (timestamps in microseconds, strictly increasing):
      fovsdf_gaze_filter_push_px(&gf, &ecc, t_us, raw_px, &gaze);        // or _push in degrees
      // per frame:
      float m;  fovsdf_gaze_margin(&gf, 0.5f, 50.0f, &m);     // accuracy 0.5 deg, latency 50 ms
      // or latency-compensated (the fovea where the eye is when the frame is seen):
      //   fov_gaze_prediction pr;  fovsdf_gaze_predict(&gf, 0.5f, 50.0f, &pr);
      //   float d[2] = { pr.x_deg, pr.y_deg };  fovsdf_gaze_from_deg(&ecc, d, &gaze);
      //   m = pr.margin_deg;
      fovsdf_config_gaze_margin(&base_cfg, m, &cfg);  cfg.frame = frame;    // every frame:
      fovsdf_init(&ctx, &cfg, &scene, &cam, gaze, mem, bytes);           // then render with cfg
   fovsdf keeps no state between frames in its context (fovsdf_init is the per-frame call
   anyway: camera and gaze): FIPR / CONE_FOV's refresh state is cfg.frame (keep counting it
   across the re-inits) and the previous frame in your output buffers, so a per-frame
   margin loses nothing.
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
FOVSDF_API fov_gaze_filter_config fovsdf_gaze_filter_config_default(void);
FOVSDF_API fov_result fovsdf_gaze_filter_init(fov_gaze_filter *f,
                                              const fov_gaze_filter_config *cfg);
FOVSDF_API void fovsdf_gaze_filter_reset(fov_gaze_filter *f);
FOVSDF_API fov_result fovsdf_gaze_filter_push(fov_gaze_filter *f, uint64_t t_us, float x_deg,
                                              float y_deg);
FOVSDF_API fov_result fovsdf_gaze_filter_push_px(fov_gaze_filter *f, const fov_ecc_model *m,
                                                 uint64_t t_us, fov_gaze raw, fov_gaze *out);
FOVSDF_API fov_result fovsdf_gaze_to_deg(const fov_ecc_model *m, fov_gaze px, float deg[2]);
FOVSDF_API fov_result fovsdf_gaze_from_deg(const fov_ecc_model *m, const float deg[2],
                                           fov_gaze *px);
FOVSDF_API fov_result fovsdf_gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                         float latency_ms, float *margin_deg);
FOVSDF_API fov_result fovsdf_gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                          float latency_ms, fov_gaze_prediction *out);
FOVSDF_API fov_result fovsdf_gaze_fixed(const fov_display *display, uint32_t width,
                                        uint32_t height, fov_gaze *out);
FOVSDF_API fov_result fovsdf_camera_display(const fov_camera *cam, fov_display *out);
/* The margin applied: *out = base resolved (fovsdf_config_resolve) with acuity.fovea_deg,
   acuity.outer_deg (when > 0) and quarter_deg (when > 0) grown by margin_deg (>= 0). Call it
   per frame from the same base. FOV_ERR_NULL, FOV_ERR_NOT_FINITE, FOV_ERR_INVALID_ARG
   (margin < 0), FOV_ERR_LIMIT (a radius beyond 180 degrees), or the base's resolve error;
   *out written only on success. */
FOVSDF_API fov_result fovsdf_config_gaze_margin(const fovsdf_config *base, float margin_deg,
                                                fovsdf_config *out);

FOVSDF_API fovsdf_acuity fovsdf_acuity_default(void);
FOVSDF_API float fovsdf_acuity_p(const fovsdf_acuity *a, float ecc_deg); /* 0 for bad input */
/* A deterministic uniform number in [0, 1) per (seed, x, y, frame): a 32-bit integer hash, the
   same on every target, for Bernoulli masks (mask = u < p) that repeat for a seed. */
FOVSDF_API float fovsdf_u01(uint32_t seed, uint32_t x, uint32_t y, uint32_t frame);

/* Working memory for a config and camera (0 for the tracers of this version). */
FOVSDF_API fov_result fovsdf_memory_size(const fovsdf_config *cfg, const fovsdf_camera *cam,
                                         size_t *bytes);
/* Validates everything and fills ctx (a failed call leaves ctx unchanged, so a context can
   be re-initialised in place and kept when that fails). mem may be NULL when the size is 0. */
FOVSDF_API fov_result fovsdf_init(fovsdf_ctx *ctx, const fovsdf_config *cfg,
                                  const fovsdf_scene *scene, const fovsdf_camera *cam,
                                  fov_gaze gaze, void *mem, size_t mem_size);
FOVSDF_API void fovsdf_output_init(fovsdf_output *out); /* pointers NULL, strides, origin 0 */
FOVSDF_API void fovsdf_stats_init(fovsdf_stats *stats);   /* every counter 0 */
FOVSDF_API void fovsdf_stats_add(fovsdf_stats *acc, const fovsdf_stats *s); /* acc += s */

/* Rows per band for threading: the head-start methods work on grid-aligned tiles, and a call
   whose rows or columns cut a tile repeats that tile's coarse work. Split the image into row
   ranges (and column ranges, fovsdf_render_tile) that start at multiples of this (cone_tile,
   ipr_tile, skip_block; 1 for the plain tracers); THREADING gives a worker-friendly split.
   Results never depend on the split, only the cost. */
FOVSDF_API uint32_t fovsdf_band_rows(const fovsdf_ctx *ctx);
/* Render rows [y0, y1) or the tile [x0, x1) x [y0, y1); stats (may be NULL) is added to. */
FOVSDF_API fov_result fovsdf_render_rows(const fovsdf_ctx *ctx, uint32_t y0, uint32_t y1,
                                         const fovsdf_output *out, fovsdf_stats *stats);
FOVSDF_API fov_result fovsdf_render_tile(const fovsdf_ctx *ctx, uint32_t x0, uint32_t y0,
                                         uint32_t x1, uint32_t y1, const fovsdf_output *out,
                                         fovsdf_stats *stats);

/* Single rays. fovsdf_camera_ray gives the ray through image point (px, py) (continuous
   pixel coordinates; pixel centres at +0.5; any finite point off the image too, up to
   +-FLT_MAX): rd is unit length; NaN or inf is FOV_ERR_NOT_FINITE.
   fovsdf_trace marches with the context's method from t_start (the pixel cone of the ray's
   own footprint, as a pixel's; no head-start check: a hit has t in [t_start, t_max]). rd
   must be unit length; ro (also fovsdf_march's) within 1e18 of the origin per component
   (else FOV_ERR_INVALID_ARG). */
FOVSDF_API fov_result fovsdf_camera_ray(const fovsdf_ctx *ctx, float px, float py,
                                        float ro[3], float rd[3]);
FOVSDF_API fov_result fovsdf_trace(const fovsdf_ctx *ctx, const float ro[3], const float rd[3],
                                   float t_start, fovsdf_hit *hit, fovsdf_stats *stats);
/* One sample, exactly as a pixel's: the camera ray through image point (px, py) marched from
   the camera with the context's tracer (head-start methods: their finishing tracer), shaded as
   fovsdf_render_rows shades a sample (hit refinement, normal, lights, shadows or sky). For
   renderers that choose their own sample positions (fovlp.h's log-polar samples). t gets the
   hit distance (t_max for a miss), material the hit's id (-1 for a miss); both may be NULL. */
FOVSDF_API fov_result fovsdf_shade_point(const fovsdf_ctx *ctx, float px, float py, float rgb[3],
                                         float *t, int32_t *material, fovsdf_stats *stats);
/* n samples at once, each exactly fovsdf_shade_point's (bit for bit), marched and shaded as one
   wavefront: the positions another header hands out (fovlp_samples: its fovlp_sample array is
   x, y, slot, so pass &samples[0].x with stride 3). Point i is (xy[i stride], xy[i stride + 1])
   (stride in floats; 0: 2); rgb gets 3 floats per point, t and material (both may be NULL) one
   each. Every point is checked before any work (NaN: FOV_ERR_NOT_FINITE; a ray that overflows:
   FOV_ERR_INVALID_ARG). */
FOVSDF_API fov_result fovsdf_shade_points(const fovsdf_ctx *ctx, uint32_t n, const float *xy,
                                          uint32_t stride, float *rgb, float *t,
                                          int32_t *material, fovsdf_stats *stats);
/* fovsdf_shade_points with a head start for groups of nearby points: points [g group,
   (g + 1) group) form group g (the last may be shorter); the group's cone (apex at the camera,
   around every ray through the group's bounding rectangle, as CONE's cells) is marched first,
   as one wavefront with the other groups' cones, and the group's rays start where it stopped
   (a cone that reaches t_max: every ray of the group misses). The guarantee is CONE's: no ray
   starts past its first hit. So each point is fovsdf_shade_point's up to where its march stops
   inside the hit threshold (as CONE's pixels are CLASSIC's), not bit for bit. group 0 or 1 is
   fovsdf_shade_points; at most FOVSDF_MAX_GROUP (default 256), else FOV_ERR_INVALID_ARG. The
   points of a group should lie close together (fovlp_samples' order: a log-polar row around
   the gaze); a group spread wide only costs its cone's first evaluation. fovlp's C Fov samples of
   primitives at 640x360, group 8: 25 % fewer evaluations with soft shadows (48.0 -> 36.2 per
   sample), 35 % without; 13 % fewer instructions (bench_lp --group). */
#ifndef FOVSDF_MAX_GROUP
#define FOVSDF_MAX_GROUP 256u
#endif
#if (FOVSDF_MAX_GROUP) < 1 || (FOVSDF_MAX_GROUP) > 65536
#error "fovsdf: FOVSDF_MAX_GROUP must be in 1 .. 65536"
#endif
FOVSDF_API fov_result fovsdf_shade_points_grouped(const fovsdf_ctx *ctx, uint32_t n,
                                                  const float *xy, uint32_t stride,
                                                  uint32_t group, float *rgb, float *t,
                                                  int32_t *material, fovsdf_stats *stats);
/* March one ray through a scene without a context, with explicit parameters (a ray tracer:
   classic, relaxed, autorelaxed or bv2018; per-image methods such as CONE are rejected). */
FOVSDF_API fov_result fovsdf_march(const fovsdf_scene *scene, const fovsdf_march_params *params,
                                   const float ro[3], const float rd[3], float t_start,
                                   fovsdf_hit *hit, fovsdf_stats *stats);
/* Distance at p (counts one evaluation); material may be NULL. */
FOVSDF_API float fovsdf_distance(const fovsdf_ctx *ctx, const float p[3], int32_t *material,
                                 fovsdf_stats *stats);
/* Distances at n points given as arrays (structure of arrays; material may be NULL): one
   evaluation each, through the scene's batch callback when it has one. n 0: nothing. */
FOVSDF_API fov_result fovsdf_distance_batch(const fovsdf_ctx *ctx, uint32_t n, const float *x,
                                            const float *y, const float *z, float *d,
                                            int32_t *material, fovsdf_stats *stats);
/* Unit normal by the tetrahedron technique: 4 evaluations at +-h. */
FOVSDF_API void fovsdf_normal(const fovsdf_ctx *ctx, const float p[3], float h, float n[3],
                              fovsdf_stats *stats);
/* Soft shadow (Algorithm 2): march from p towards the unit direction l for t in
   [t_start, t_end]; returns the light fraction in [0, 1] (0 = full shadow). */
FOVSDF_API float fovsdf_soft_shadow(const fovsdf_ctx *ctx, const float p[3], const float l[3],
                                    float t_start, float t_end, float k, fovsdf_stats *stats);
/* The IPR neighbour minimum filter on a caller image: out(x, y) = the minimum of in over the
   (2 radius + 1)^2 window around (x, y), clamped at the borders (radius 0 copies; radius above
   64: FOV_ERR_LIMIT, the cost grows with its square). out must not alias in. */
FOVSDF_API fov_result fovsdf_min_filter(const float *in, uint32_t w, uint32_t h, int32_t radius,
                                        float *out);
/* FIPR's pass 5, optional (the thesis's study, Sec. 5.4.1, found it made the foveation more
   visible, so nothing calls it by default): a Gaussian blur of sigma pixels, in (0, 8], applied
   only where traced and interpolated pixels meet (sigma in [0.05, 8]): a pixel is blurred when
   its 3x3 neighbourhood holds both mask value 1 and another value (the mask output of FIPR /
   CONE_FOV); every other pixel is copied. Kernel radius ceil(3 sigma), renormalised at the
   image borders. rgb and out are 3 floats per pixel with row strides in floats (0: 3 w), mask a
   byte per pixel (stride 0: w); out must not alias rgb. */
FOVSDF_API fov_result fovsdf_mask_blur(const float *rgb, uint32_t rgb_stride, const uint8_t *mask,
                                       uint32_t mask_stride, uint32_t w, uint32_t h, float sigma,
                                       float *out, uint32_t out_stride);
/* Shades one hit: linear RGB of the surface at p with normal n seen along rd (a direction
   from the camera's pinhole: with config.shadow_fov_deg, its eccentricity chooses the shadow
   rays, as in the images). */
FOVSDF_API void fovsdf_shade(const fovsdf_ctx *ctx, const float p[3], const float n[3],
                             const float rd[3], int32_t material, float rgb[3],
                             fovsdf_stats *stats);
FOVSDF_API void fovsdf_sky(const fovsdf_ctx *ctx, const float rd[3], float rgb[3]);

/* Scene builder */
FOVSDF_API void fovsdf_builder_init(fovsdf_builder *b, fovsdf_node *nodes, uint32_t cap);
FOVSDF_API int32_t fovsdf_sphere(fovsdf_builder *b, float r);
FOVSDF_API int32_t fovsdf_box(fovsdf_builder *b, float hx, float hy, float hz);
FOVSDF_API int32_t fovsdf_round_box(fovsdf_builder *b, float hx, float hy, float hz, float r);
FOVSDF_API int32_t fovsdf_box_frame(fovsdf_builder *b, float hx, float hy, float hz, float e);
FOVSDF_API int32_t fovsdf_torus(fovsdf_builder *b, float major, float minor);
FOVSDF_API int32_t fovsdf_capsule(fovsdf_builder *b, const float a[3], const float c[3],
                                  float r);
FOVSDF_API int32_t fovsdf_cylinder(fovsdf_builder *b, float half_height, float r);
FOVSDF_API int32_t fovsdf_cone(fovsdf_builder *b, float half_height, float r_bottom,
                               float r_top);
FOVSDF_API int32_t fovsdf_plane(fovsdf_builder *b, float nx, float ny, float nz, float offset);
FOVSDF_API int32_t fovsdf_menger(fovsdf_builder *b, float half_size, int32_t iterations);
FOVSDF_API int32_t fovsdf_mandelbulb(fovsdf_builder *b, float power, int32_t iterations);
FOVSDF_API int32_t fovsdf_terrain(fovsdf_builder *b, float amplitude, float frequency,
                                  int32_t octaves);
FOVSDF_API int32_t fovsdf_union(fovsdf_builder *b, int32_t x, int32_t y);
FOVSDF_API int32_t fovsdf_subtract(fovsdf_builder *b, int32_t x, int32_t y);
FOVSDF_API int32_t fovsdf_intersect(fovsdf_builder *b, int32_t x, int32_t y);
FOVSDF_API int32_t fovsdf_smooth_union(fovsdf_builder *b, int32_t x, int32_t y, float k);
FOVSDF_API int32_t fovsdf_smooth_subtract(fovsdf_builder *b, int32_t x, int32_t y, float k);
FOVSDF_API int32_t fovsdf_smooth_intersect(fovsdf_builder *b, int32_t x, int32_t y, float k);
FOVSDF_API int32_t fovsdf_translate(fovsdf_builder *b, int32_t x, float tx, float ty, float tz);
FOVSDF_API int32_t fovsdf_rotate(fovsdf_builder *b, int32_t x, float ax, float ay, float az,
                                 float angle_deg);
FOVSDF_API int32_t fovsdf_scale(fovsdf_builder *b, int32_t x, float s);
FOVSDF_API int32_t fovsdf_repeat(fovsdf_builder *b, int32_t x, float px, float py, float pz,
                                 int32_t nx, int32_t ny, int32_t nz);
FOVSDF_API int32_t fovsdf_mirror(fovsdf_builder *b, int32_t x, int32_t axes);
FOVSDF_API int32_t fovsdf_round(fovsdf_builder *b, int32_t x, float r);
FOVSDF_API int32_t fovsdf_onion(fovsdf_builder *b, int32_t x, float thickness);

/* Compile the tree under root into a program: size query, then build into caller memory.
   Union clusters are rebalanced into a bounding-sphere hierarchy and bounding spheres are
   placed around subtrees worth skipping (see fovsdf_program_eval). */
FOVSDF_API fov_result fovsdf_program_size(const fovsdf_node *nodes, uint32_t count,
                                          int32_t root, size_t *bytes);
FOVSDF_API fov_result fovsdf_program_build(fovsdf_program *prog, const fovsdf_node *nodes,
                                           uint32_t count, int32_t root, void *mem,
                                           size_t bytes);
/* The node check of fovsdf_program_build (and of every builder function), with a logger:
   count and root, then every node's type, children (indices below count) and parameters (the
   ranges at fovsdf_node_type: finite, lengths at most 1e18 in magnitude, iteration counts
   within their caps). Returns the first failure's code, the one fovsdf_program_build returns
   for these nodes, and logs it (the node index, the field and the allowed range). logger
   may be NULL. */
FOVSDF_API fov_result fovsdf_program_check(const fovsdf_node *nodes, uint32_t count, int32_t root,
                                           const fov_logger *logger);
/* Keep only the code: fovsdf_program_compact copies the instructions (code_bytes of them,
   64 bytes each, plus up to 15 for alignment) to dst and points prog there, so the build
   memory (nodes, bounds, scratch: several times larger) can be reused. For a built-in scene:
      fovsdf_program p = *bi.program;                    // keep p alive while tracing
      fovsdf_program_compact(&p, code, sizeof code);
      fovsdf_scene_set_program(&bi.scene, &p);
   (tests/xtarget/mem_test.c renders Primitives this way in 32 KiB on a Cortex-M4). */
FOVSDF_API size_t fovsdf_program_code_bytes(const fovsdf_program *prog);
FOVSDF_API fov_result fovsdf_program_compact(fovsdf_program *prog, void *dst, size_t bytes);
/* Evaluate (the signature of fovsdf_dist_ex_fn; user = const fovsdf_program *). q may be
   NULL. */
FOVSDF_API float fovsdf_program_eval(const float p[3], fovsdf_query *q, void *user);
/* Evaluate a batch (the signature of fovsdf_dist_batch_fn): each point gets exactly
   fovsdf_program_eval's value, material and counts (bit for bit), whatever the batch. Each
   instruction runs over the batch in plain loops the compiler vectorises; a bounding sphere
   skips its subtree when no point of the batch needs it, and the points that could skip get
   the bound's value. Any n (it works in chunks of FOVSDF_BATCH); NULL arrays: nothing. */
FOVSDF_API void fovsdf_program_eval_batch(fovsdf_batch *b, void *user);

/* Built-in scenes: size query, then build into caller memory (which must outlive use). */
FOVSDF_API const char *fovsdf_builtin_name(uint32_t id);   /* never NULL */
FOVSDF_API fov_result fovsdf_builtin_size(uint32_t id, size_t *bytes);
FOVSDF_API fov_result fovsdf_builtin_init(uint32_t id, fovsdf_builtin *out, void *mem,
                                          size_t bytes);

#ifdef FOVSDF_DOUBLE
/* Reference tracer in double precision: classic sphere tracing of scene->dist_d with the
   absolute threshold eps (FOV_ERR_UNSUPPORTED when the scene has no dist_d). */
FOVSDF_API fov_result fovsdf_trace_ref(const fovsdf_scene *scene, const double ro[3],
                                       const double rd[3], double t_start, double t_max,
                                       double eps, uint32_t max_steps, double *t_hit,
                                       uint32_t *kind);
#endif

/* The documented limits (see the configuration macros above), defined here so that a
   translation unit with the declarations alone can use them; give them the same value in
   every translation unit. */
#ifndef FOVSDF_MAX_STEPS
#define FOVSDF_MAX_STEPS 65536u
#endif
#ifndef FOVSDF_MAX_DIM
#define FOVSDF_MAX_DIM 65536u
#endif
#ifndef FOVSDF_MAX_STACK
#define FOVSDF_MAX_STACK 32
#endif

#ifdef __cplusplus
}
#endif

#endif /* FOVSDF_H_INCLUDED */

/* ---- end of API; implementation below ---- */
#ifdef __INTELLISENSE__
#define FOVSDF_IMPLEMENTATION
#endif

#if defined(FOVSDF_IMPLEMENTATION) && !defined(FOVSDF_IMPL_INCLUDED)
#define FOVSDF_IMPL_INCLUDED

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

#define FOVSDF__PRIV FOV__PRIV
#if defined(_MSC_VER) && !defined(__cplusplus)
#define FOVSDF__INL static __inline
#else
#define FOVSDF__INL static inline
#endif
/* gcc's -O2 cost model ("very cheap") does not vectorise loops with selects, and under its
   default -ftrapping-math it keeps "a > b ? a : b" a branch: the batch evaluator and its
   inline helpers ask for the dynamic model and no-trapping-math (the same IEEE operations and
   values; only floating-point exception flags, which the library never reads, may differ),
   so min and max become maxps / minps. clang vectorises them at -O2 as they are. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(FOVSDF_NO_SIMD) && __GNUC__ >= 8
#define FOVSDF__VEC __attribute__((optimize("vect-cost-model=dynamic", "no-trapping-math")))
#else
#define FOVSDF__VEC
#endif
/* the tile functions keep their own frames (inlined into fovsdf_render_tile, FIPR's 13 KiB of
   cells would be on every method's stack) */
#if defined(__GNUC__) || defined(__clang__)
#define FOVSDF__NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define FOVSDF__NOINLINE __declspec(noinline)
#else
#define FOVSDF__NOINLINE
#endif
#if defined(__cplusplus) || defined(_MSC_VER)
#define FOVSDF__RESTRICT __restrict
#else
#define FOVSDF__RESTRICT restrict
#endif
#define FOVSDF__FAIL(lg, r, msg) FOV__FAIL(lg, "fovsdf", r, msg)

/* Points per batch callback and lanes of the batch evaluator; and rays in flight per render
   call (the wavefront). Both only set speed and stack (see MEMORY), never a value: 32 and 128
   on 64-bit CPUs, 16 and 32 elsewhere (wasm32, 32-bit ARM); FOVSDF_BATCH 1 evaluates a built-in
   program point by point (the least stack). */
#if defined(__x86_64__) || defined(_M_X64) || defined(__aarch64__) || defined(_M_ARM64)
#define FOVSDF__BIG_STACK 1
#endif
#ifndef FOVSDF_BATCH
#ifdef FOVSDF__BIG_STACK
#define FOVSDF_BATCH 32
#else
#define FOVSDF_BATCH 16
#endif
#endif
#if FOVSDF_BATCH < 1
#error "fovsdf: FOVSDF_BATCH must be at least 1"
#endif
#ifndef FOVSDF_WAVE
#ifdef FOVSDF__BIG_STACK
#define FOVSDF_WAVE 128
#else
#define FOVSDF_WAVE 32
#endif
#endif
#if FOVSDF_WAVE < 1
#error "fovsdf: FOVSDF_WAVE must be at least 1 (and at least config.spp)"
#endif
/* The batch evaluator's loops are plain C over FOVSDF__L lanes (FOVSDF_BATCH rounded up to a
   multiple of 8), which compilers vectorise; the one hand-written part is the square root
   (compilers keep sqrtf scalar while errno may be set), for libm's sqrtf and for FOV_NO_LIBM
   where fov__sqrtf is the target's instruction (FOV__SQRT_HW: both correctly rounded, so the
   vector square root gives their values); a math hook or FOV_NO_LIBM's software square root
   runs lane by lane, and so does a freestanding x86 build with FOV_NO_LIBM (gcc's intrinsics
   headers include <stdlib.h>). FOVSDF_NO_SIMD: no intrinsics. */
#define FOVSDF__L ((((FOVSDF_BATCH) + 7) / 8) * 8)
#if !defined(FOVSDF_NO_SIMD) && !defined(FOV__HOOKED_MATH) && \
    (!defined(FOV_NO_LIBM) || (defined(FOV__SQRT_HW) && \
                               (FOV__SQRT_HW != 1 || !defined(__GNUC__) || __STDC_HOSTED__)))
#if defined(__AVX__)
#include <immintrin.h>
#define FOVSDF__SQRT_AVX 1
#elif defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#define FOVSDF__SQRT_SSE 1
#elif defined(__wasm_simd128__)
#include <wasm_simd128.h>
#define FOVSDF__SQRT_WASM 1
#elif defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>
#define FOVSDF__SQRT_NEON 1
#endif
#endif
#if defined(FOVSDF_NO_SIMD)
#define FOVSDF_SIMD_NAME "scalar"
#elif defined(__AVX2__)
#define FOVSDF_SIMD_NAME "avx2"
#elif defined(__SSE2__) || defined(_M_X64)
#define FOVSDF_SIMD_NAME "sse2"
#elif defined(__ARM_NEON)
#define FOVSDF_SIMD_NAME "neon"
#elif defined(__wasm_simd128__)
#define FOVSDF_SIMD_NAME "simd128"
#else
#define FOVSDF_SIMD_NAME "scalar"
#endif
#ifndef FOVSDF_TILE_SCRATCH /* floats of per-call working memory on the stack (IPR tiles) */
#define FOVSDF_TILE_SCRATCH 1024
#endif
/* IPR: the apron of stored level l (cells beyond the tile its filters reach) and the floats a
   tile needs: level levels-2 needs r (the pixels' filter), each level below ceil(a/2) + r. */
FOVSDF__PRIV uint32_t fovsdf__ipr_apron(uint32_t levels, uint32_t l, uint32_t r)
{
    uint32_t a = r, k;
    for (k = levels - 2u; k > l; --k) a = (a + 1u) / 2u + r;
    return a;
}
FOVSDF__PRIV size_t fovsdf__ipr_floats(uint32_t tile, uint32_t levels, int32_t r)
{
    size_t n = 0;
    uint32_t l;
    for (l = 0; l + 1u < levels; ++l) {
        size_t side =
            (size_t)(tile >> (levels - 1u - l)) + 2u * fovsdf__ipr_apron(levels, l, (uint32_t)r);
        n += side * side;
    }
    return n;
}
#ifndef FOVSDF_FOV_CELLS /* cells per FIPR / CONE_FOV tile: mid level (32 bytes each) and
                            FIPR's level 0 (8 bytes each: hit, certified start), on the stack */
#define FOVSDF_FOV_CELLS 324
#endif
/* FIPR / CONE_FOV: the larger of a tile's two arrays, apron included: the mid level (at least
   one cell for the bilinear reconstruction, r for the minimum filter) and FIPR's level 0 (the
   parents of those cells and their filter, at least one for Sobel). */
FOVSDF__PRIV size_t fovsdf__fov_cells(uint32_t tile, int32_t r, int cone)
{
    size_t am = (size_t)(r > 1 ? r : 1), ms = (size_t)(tile / 2u) + 2u * am;
    size_t ls = (size_t)(tile / 4u) + 2u * ((am + 1u) / 2u + (size_t)r);
    return cone || ms >= ls ? ms * ms : ls * ls;
}
/* quarter cells per FIPR / CONE_FOV tile: (T / 4 + 2)^2 <= FOVSDF_FOV_CELLS / 2 + 8 whenever
   the mid level's (T / 2 + 2)^2 fits FOVSDF_FOV_CELLS */
#define FOVSDF__FOV_QCELLS (FOVSDF_FOV_CELLS / 2 + 8)
#ifndef FOVSDF_QUARTER_BAND /* pixels (at the eye's axis) over which the quarter level blends in */
#define FOVSDF_QUARTER_BAND 8
#endif
#ifndef FOVSDF_CONE_SLACK /* a cone stops when f <= t k (1 + slack): earlier is always safe */
#define FOVSDF_CONE_SLACK 0.5f
#endif


/* NaN gives a: a NaN never survives a clamp (bit for bit the plain clamp otherwise) */
FOVSDF__PRIV float fovsdf__nan(void)
{
    uint32_t u = 0x7fc00000u;
    float f;
    FOV_MEMCPY(&f, &u, sizeof f);
    return f;
}
FOVSDF__INL float fovsdf__clampf(float x, float a, float b)
{
    return x >= a ? (x > b ? b : x) : a;
}
FOVSDF__INL float fovsdf__len2f(float x, float y) { return FOV__SQRT(x * x + y * y); }
FOVSDF__INL float fovsdf__len3f(float x, float y, float z)
{
    return FOV__SQRT(x * x + y * y + z * z);
}
/* Scales v to unit length and returns its length before (FLT_MAX when that is beyond float).
   Any finite non-zero v works: one whose squares would under- or overflow (largest component
   below 1e-15 or above 1e15) is brought to a largest component of 1 first; every other vector
   takes the plain path, bit for bit. A zero, NaN or infinite v is left as it is and gives 0. */
FOVSDF__PRIV float fovsdf__normalize(float v[3])
{
    float m, l, s = 1.0f;
    if (!fov__finite3(v)) return 0.0f;
    m = fov__maxf(fov__absf(v[0]), fov__maxf(fov__absf(v[1]), fov__absf(v[2])));
    if (!(m > 0.0f)) return 0.0f;
    if (m < 1e-15f || m > 1e15f) { v[0] /= m; v[1] /= m; v[2] /= m; s = m; }
    l = fov__len(v);
    v[0] /= l; v[1] /= l; v[2] /= l;
    l *= s;
    return l <= FLT_MAX ? l : FLT_MAX;
}


/* ---- results, names, configs ------------------------------------------------------------ */
FOVSDF_API const char *fovsdf_result_string(fov_result r) { return fov__result_string(r); }

FOVSDF_API const char *fovsdf_method_name(uint32_t method)
{
    static const char *const names[] = { "classic", "relaxed", "autorelaxed", "bv2018", "cone",
                                         "ipr", "skip", "fipr", "cone_fov" };
    return method < (uint32_t)_FOVSDF_METHOD_NUM ? names[method] : "unknown";
}

FOVSDF_API fovsdf_config fovsdf_config_default(void)
{
    fovsdf_config c;
    FOV_MEMSET(&c, 0, sizeof c);
    (void)fovsdf_config_resolve(&c, &c);
    return c;
}

FOVSDF_API fovsdf_config fovsdf_config_ground_truth(void)
{
    fovsdf_config c = fovsdf_config_default();
    c.method = FOVSDF_METHOD_CLASSIC;
    c.eps = 1e-5f;
    c.eps_px = 0.01f;
    c.max_steps = 4096;
    c.shadow_steps = 256;
    return c;
}

/* Acuity-driven foveation: the fovea out to plan.e_half, the quarter level from plan.e_quarter
   (the plan does not depend on the gaze: its ppd is the one at the eye's axis). */
FOVSDF_API fov_result fovsdf_config_acuity(fovsdf_config *cfg, const fovsdf_camera *cam,
                                           const fov_eye *eye)
{
    fov_ecc_model m;
    fov_eye_plan pl;
    fov_gaze g;
    fov_result r;
    const fov_logger *lg;
    float fovea;
    fovsdf_config c, res;
    if (!cfg) return FOV_ERR_NULL;
    lg = &cfg->logger;
    if (!cam) FOVSDF__FAIL(lg, FOV_ERR_NULL, "config_acuity: cam is NULL");
    r = fov__display_check(lg, "fovsdf", &cfg->display, 3, (uint32_t)__LINE__);
    if (r != FOV_OK) return r;
    g.x = 0.5f * (float)cam->width; g.y = 0.5f * (float)cam->height;
    r = fovsdf_ecc_init(&m, &cfg->display, cam->fov_y_deg, cam->width, cam->height, g);
    if (r != FOV_OK)
        FOVSDF__FAIL(lg, r, "config_acuity: no eccentricity model (cam width, height, fov_y_deg "
                            "or config.display)");
    r = fov__eye_check(lg, "fovsdf", "config_acuity: ", eye);
    if (r != FOV_OK) return r;
    r = fovsdf_eye_plan(eye, &m, &pl);
    if (r != FOV_OK) FOVSDF__FAIL(lg, r, "config_acuity: no eye plan for this display");
    /* full resolution wherever half the linear density is not yet enough; 1e-3: no fovea (0
       would mean the 7.5-degree default) */
    fovea = fovsdf__clampf(pl.e_half, 1e-3f, 180.0f);
    c = *cfg;
    c.acuity.fovea_deg = fovea;
    c.acuity.outer_deg = 0.0f;
    c.quarter_deg = pl.e_quarter < 180.0f ? fov__maxf(pl.e_quarter, fovea) : 0.0f;
    c.refresh = 1u; /* the periphery is the part of the visual field most sensitive to flicker */
    c.fov_mask = (uint32_t)FOVSDF_MASK_FOVEA;
    c.level_filter = 2u;     /* texture per pixel: no blur of its edges near the fovea */
    c.refine_depth = 0.05f;  /* silhouettes, */
    c.refine_normal_deg = 25.0f; /* creases */
    c.refine_material = 1u;  /* and object boundaries trace their own pixels */
    /* the whole config must be valid, as fovlp's and fovpt's config_acuity check (resolve logs
       its own message) */
    r = fovsdf_config_resolve(&c, &res);
    if (r != FOV_OK) return r;
    *cfg = c;
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_config_resolve(const fovsdf_config *in, fovsdf_config *out)
{
    /* the float fields: NaN or infinite (pass 0), negative (pass 1) */
    static const fov__field fl[9] = {
        FOV__FIELD(fovsdf_config, eps, 1),
        FOV__FIELD(fovsdf_config, eps_px, 1), FOV__FIELD(fovsdf_config, t_max, 1),
        FOV__FIELD(fovsdf_config, omega, 1), FOV__FIELD(fovsdf_config, ar_beta, 1),
        FOV__FIELD(fovsdf_config, bv_relax, 1), FOV__FIELD(fovsdf_config, shadow_eps, 1),
        FOV__FIELD(fovsdf_config, shadow_t0, 1), FOV__FIELD(fovsdf_config, normal_eps, 1) };
    static const fov__field fa[10] = {
        FOV__FIELD(fovsdf_config, acuity.A, 1), FOV__FIELD(fovsdf_config, acuity.rate, 1),
        FOV__FIELD(fovsdf_config, acuity.C, 1), FOV__FIELD(fovsdf_config, acuity.fovea_deg, 1),
        FOV__FIELD(fovsdf_config, acuity.outer_deg, 1),
        FOV__FIELD(fovsdf_config, edge_threshold, 1), FOV__FIELD(fovsdf_config, quarter_deg, 1),
        FOV__FIELD(fovsdf_config, refine_contrast, 1), FOV__FIELD(fovsdf_config, refine_depth, 1),
        FOV__FIELD(fovsdf_config, refine_normal_deg, 1) };
    fovsdf_config c;
    const fov_logger *lg;
    fov_result r;
    if (!in) return FOV_ERR_NULL;
    lg = &in->logger;
    if (!out) FOVSDF__FAIL(lg, FOV_ERR_NULL, "config_resolve: out is NULL");
    c = *in;
    r = fov__fields_check(lg, "fovsdf", "config.", &c, fl, 9u, 0, (uint32_t)__LINE__);
    if (r == FOV_OK) r = fov__display_check(lg, "fovsdf", &c.display, 1, (uint32_t)__LINE__);
    if (r != FOV_OK) return r;
    if (c.method >= (uint32_t)_FOVSDF_METHOD_NUM)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.method: unknown (see fovsdf_method)");
    if (c.spp == 0) c.spp = 1;
    if (c.spp != 1 && c.spp != 4 && c.spp != 16)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.spp must be 1, 4 or 16 (0: 1)");
    if (c.spp > FOVSDF_WAVE)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT, "config.spp above FOVSDF_WAVE (rays in flight)");
    if (c.eps_mode >= (uint32_t)_FOVSDF_EPS_NUM)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.eps_mode: unknown (see fovsdf_eps_mode)");
    r = fov__fields_check(lg, "fovsdf", "config.", &c, fl, 9u, 1, (uint32_t)__LINE__);
    if (r != FOV_OK) return r;
    if (fov__is0(c.eps)) c.eps = 1e-4f;
    if (fov__is0(c.eps_px)) c.eps_px = 0.25f;
    if (c.max_steps == 0) c.max_steps = 256;
    if (c.max_steps > FOVSDF_MAX_STEPS)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT, "config.max_steps above FOVSDF_MAX_STEPS");
    if (fov__is0(c.omega)) c.omega = 1.6f;
    if (c.omega < 1.0f || c.omega >= 2.0f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.omega must be in [1, 2) (0: 1.6)");
    if (fov__is0(c.ar_beta)) c.ar_beta = 0.3f;
    if (c.ar_beta > 1.0f) FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.ar_beta must be in (0, 1]");
    if (fov__is0(c.bv_relax)) c.bv_relax = 0.9f;
    if (c.bv_relax > 1.0f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.bv_relax must be in (0, 1]");
    if (c.shading >= (uint32_t)_FOVSDF_SHADE_NUM)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.shading: unknown (see fovsdf_shading)");
    if (c.shadow_steps == 0) c.shadow_steps = 64;
    if (c.shadow_steps > FOVSDF_MAX_STEPS)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT, "config.shadow_steps above FOVSDF_MAX_STEPS");
    if (fov__is0(c.shadow_eps)) c.shadow_eps = 1e-3f;
    if (c.finish == 0) c.finish = FOVSDF_FINISH_BV2018;
    if (c.finish >= (uint32_t)_FOVSDF_FINISH_NUM)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.finish: unknown (see fovsdf_finish)");
    if (c.heuristic_start > 1)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "config.heuristic_start must be 0 (safe) or 1 (thesis)");
    if (c.ipr_levels == 0) c.ipr_levels = 3;
    if (c.ipr_levels > 6) FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.ipr_levels must be 1 .. 6");
    if (c.ipr_radius < 0 || c.ipr_radius > 3)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.ipr_radius must be 0 .. 3");
    if (c.ipr_radius == 0) c.ipr_radius = 1;
    if (c.ipr_no_filter > 1)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.ipr_no_filter must be 0 or 1");
    if (c.ipr_tile == 0) c.ipr_tile = 32;
    if (c.ipr_tile > 64 || c.ipr_tile % (1u << (c.ipr_levels - 1u)) != 0)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "config.ipr_tile must be a multiple of 2^(ipr_levels-1), at most 64");
    if (c.method == FOVSDF_METHOD_IPR &&
        fovsdf__ipr_floats(c.ipr_tile, c.ipr_levels,
                           (c.ipr_no_filter || !c.heuristic_start) ? 0 : c.ipr_radius) >
            FOVSDF_TILE_SCRATCH)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT,
                     "config.ipr_tile: working memory above FOVSDF_TILE_SCRATCH");
    if (!fov__finite(c.skip_scale))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "config.skip_scale is NaN or infinite");
    if (!fov__finite(c.skip_eps))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "config.skip_eps is NaN or infinite");
    if (c.skip_scale < 0.0f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.skip_scale must be >= 0");
    if (c.skip_eps < 0.0f) FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.skip_eps must be >= 0");
    if (fov__is0(c.skip_scale)) c.skip_scale = 1.005f;
    if (fov__is0(c.skip_eps)) c.skip_eps = 0.05f;
    if (c.skip_scale > 2.0f || c.skip_scale < 0.5f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.skip_scale must be in [0.5, 2] (0: 1.005)");
    if (c.skip_block == 0) c.skip_block = 4;
    if (c.skip_block > 16)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.skip_block must be 1 .. 16");
    if (c.skip_no_shadow_start > 1)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.skip_no_shadow_start must be 0 or 1");
    if (c.cone_tile == 0) c.cone_tile = 16;
    if (c.cone_tile > 256 || (c.cone_tile & (c.cone_tile - 1)) != 0)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.cone_tile must be a power of two <= 256");
    {
        uint32_t lv = 1, tt = c.cone_tile;
        while (tt > 1) { tt >>= 1; ++lv; }
        if (c.cone_levels == 0) c.cone_levels = lv > 1 ? lv - 1 : 1;
        if (c.cone_levels > lv)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.cone_levels above log2(cone_tile) + 1");
    }
    if (fov__is0(c.shadow_t0)) c.shadow_t0 = 1e-2f;
    if (!fov__finite(c.shadow_fov_deg))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "config.shadow_fov_deg is NaN or infinite");
    if (!fov__finite(c.shadow_fov_t0_px))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "config.shadow_fov_t0_px is NaN or infinite");
    if (c.shadow_fov_deg < 0.0f || c.shadow_fov_deg > 180.0f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.shadow_fov_deg must be in [0, 180] (0: off)");
    if (c.shadow_fov_t0_px < 0.0f || c.shadow_fov_t0_px > 1e6f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.shadow_fov_t0_px must be in [0, 1e6] (0: 4)");
    if (fov__is0(c.shadow_fov_t0_px)) c.shadow_fov_t0_px = 4.0f;
    /* shadow_fov_steps 0 stays 0 (shadow_steps): a default config takes any shadow_steps */
    if (c.shadow_fov_steps > c.shadow_steps)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "config.shadow_fov_steps must be <= shadow_steps (0: shadow_steps)");
    {
        fovsdf_acuity d = fovsdf_acuity_default();
        r = fov__fields_check(lg, "fovsdf", "config.", &c, fa, 10u, 0, (uint32_t)__LINE__);
        if (r == FOV_OK) r = fov__fields_check(lg, "fovsdf", "config.", &c, fa, 10u, 1, __LINE__);
        if (r != FOV_OK) return r;
        if (fov__is0(c.acuity.A)) c.acuity.A = d.A;
        if (fov__is0(c.acuity.rate)) c.acuity.rate = d.rate;
        if (fov__is0(c.acuity.C)) c.acuity.C = d.C;
        if (fov__is0(c.acuity.fovea_deg)) c.acuity.fovea_deg = d.fovea_deg;
        if (c.acuity.A + c.acuity.C > 1.0f)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.acuity: A + C above 1");
        if (c.acuity.fovea_deg > 180.0f)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.acuity.fovea_deg must be <= 180");
        if (c.acuity.outer_deg > 0.0f && c.acuity.outer_deg <= c.acuity.fovea_deg)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                         "config.acuity.outer_deg must exceed fovea_deg (0: 7.5)");
        if (fov__is0(c.edge_threshold)) c.edge_threshold = 0.1f;
        if (c.level_filter > 2u)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.level_filter must be 0, 1 or 2");
        if (c.refine_normal_deg > 180.0f)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.refine_normal_deg must be in [0, 180]");
        if (c.refine_material > 1u)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.refine_material must be 0 or 1");
        if (c.quarter_deg > 180.0f)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.quarter_deg must be <= 180 (0: none)");
        if (c.quarter_deg > 0.0f && c.quarter_deg < c.acuity.fovea_deg)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                         "config.quarter_deg must be 0 (none) or >= acuity.fovea_deg");
        if (c.fov_mask >= (uint32_t)_FOVSDF_MASK_NUM)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.fov_mask: unknown (see fovsdf_fov_mask)");
        if (c.refresh == 0) c.refresh = 1;
        if (c.refresh != 1 && c.refresh != 2 && c.refresh != 4)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.refresh must be 1, 2 or 4 (0: 1)");
        if (c.method == FOVSDF_METHOD_FIPR &&
            (c.ipr_tile % 4u != 0 ||
             fovsdf__fov_cells(c.ipr_tile, c.ipr_no_filter ? 0 : c.ipr_radius, 0) >
                 FOVSDF_FOV_CELLS))
            FOVSDF__FAIL(lg, FOV_ERR_LIMIT,
                         "config.ipr_tile: FIPR needs a multiple of 4, cells in FOVSDF_FOV_CELLS");
        if (c.method == FOVSDF_METHOD_CONE_FOV && c.cone_tile < 4)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "config.cone_tile: CONE_FOV needs >= 4");
        if (c.method == FOVSDF_METHOD_CONE_FOV &&
            fovsdf__fov_cells(c.cone_tile, 1, 1) > FOVSDF_FOV_CELLS)
            FOVSDF__FAIL(lg, FOV_ERR_LIMIT,
                         "config.cone_tile: CONE_FOV cells above FOVSDF_FOV_CELLS");
    }
    r = fov__display_check(lg, "fovsdf", &c.display, 2, (uint32_t)__LINE__);
    if (r != FOV_OK) return r;
    *out = c;
    return FOV_OK;
}

/* ---- camera, scene defaults, eccentricity -------------------------------------------------- */
FOVSDF_API void fovsdf_camera_init(fovsdf_camera *cam, uint32_t width, uint32_t height)
{
    fov__camera_init(cam, width, height);
}

FOVSDF_API fov_result fovsdf_camera_basis(const fovsdf_camera *cam, float right[3], float up[3],
                                          float fwd[3])
{
    if (!cam || !right || !up || !fwd) return FOV_ERR_NULL;
    return fov__camera_basis(cam, right, up, fwd);
}

FOVSDF_API void fovsdf_scene_init(fovsdf_scene *s)
{
    if (!s) return;
    FOV_MEMSET(s, 0, sizeof *s);
    s->lipschitz = 1.0f;
    s->num_lights = 1;
    s->lights[0].type = FOVSDF_LIGHT_DIRECTIONAL;
    s->lights[0].v[0] = -0.5f; s->lights[0].v[1] = 0.8f; s->lights[0].v[2] = -0.3f;
    s->lights[0].color[0] = s->lights[0].color[1] = s->lights[0].color[2] = 1.0f;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.15f;
    s->sky_zenith[0] = 0.30f; s->sky_zenith[1] = 0.45f; s->sky_zenith[2] = 0.75f;
    s->sky_horizon[0] = 0.75f; s->sky_horizon[1] = 0.80f; s->sky_horizon[2] = 0.85f;
}

FOVSDF_API void fovsdf_scene_set_program(fovsdf_scene *s, const fovsdf_program *prog)
{
    if (!s) return;
    s->dist = 0;
    s->dist_ex = fovsdf_program_eval;
    s->dist_batch = fovsdf_program_eval_batch;
    s->user = (void *)(uintptr_t)prog; /* the evaluator only reads through it */
}

/* The shared eccentricity model (see fov_display). */
FOVSDF_API fov_result fovsdf_ecc_init(fov_ecc_model *m, const fov_display *d, float fov_y_deg,
                                      uint32_t w, uint32_t h, fov_gaze g)
{ return fov__ecc_init(m, d, fov_y_deg, w, h, g, FOVSDF_MAX_DIM); }
FOVSDF_API float fovsdf_ecc_deg(const fov_ecc_model *m, float x, float y)
{ return fov__ecc_deg(m, x, y); }
FOVSDF_API float fovsdf_ecc_ppd(const fov_ecc_model *m) { return fov__ecc_ppd(m); }
FOVSDF_API float fovsdf_eye_mar(const fov_eye *eye, float ecc_deg)
{ return fov__eye_mar(eye, ecc_deg); }
FOVSDF_API float fovsdf_eye_density(const fov_eye *eye, float ppd, float ecc_deg)
{ return fov__eye_density(eye, ppd, ecc_deg); }
FOVSDF_API float fovsdf_eye_ecc(const fov_eye *eye, float ppd, float density)
{ return fov__eye_ecc(eye, ppd, density); }
FOVSDF_API fov_result fovsdf_eye_plan(const fov_eye *eye, const fov_ecc_model *m,
                                      fov_eye_plan *plan)
{ return fov__eye_plan(eye, m, plan); }

/* ---- gaze input (GAZE INPUT; the shared fov__gaze_*) ------------------------------------- */
FOVSDF_API fov_gaze_filter_config fovsdf_gaze_filter_config_default(void)
{
    fov_gaze_filter_config c;
    const char *bad;
    FOV_MEMSET(&c, 0, sizeof c);
    (void)fov__gaze_cfg(0, &c, &bad);
    return c;
}
FOVSDF_API fov_result fovsdf_gaze_filter_init(fov_gaze_filter *f, const fov_gaze_filter_config *cfg)
{
    fov_gaze_filter_config c;
    const char *bad;
    fov_result r;
    if (!f) {
        if (cfg)
            return fov__err(&cfg->logger, "fovsdf", FOV_ERR_NULL,
                            FOV__MSG("gaze_filter_init: f is NULL"), (uint32_t)__LINE__);
        return FOV_ERR_NULL;
    }
    r = fov__gaze_cfg(cfg, &c, &bad);
    if (r != FOV_OK) return cfg ? fov__err(&cfg->logger, "fovsdf", r, bad, (uint32_t)__LINE__) : r;
    FOV_MEMSET(f, 0, sizeof *f);
    f->cfg = c;
    return FOV_OK;
}
FOVSDF_API void fovsdf_gaze_filter_reset(fov_gaze_filter *f)
{
    if (f) fov__gaze_reset(f);
}
FOVSDF_API fov_result fovsdf_gaze_filter_push(fov_gaze_filter *f, uint64_t t_us, float x_deg,
                                              float y_deg)
{
    const char *bad;
    fov_result r;
    if (!f) return FOV_ERR_NULL;
    r = fov__gaze_push(f, t_us, x_deg, y_deg, &bad);
    return r == FOV_OK ? r : fov__err(&f->cfg.logger, "fovsdf", r, bad, (uint32_t)__LINE__);
}
FOVSDF_API fov_result fovsdf_gaze_filter_push_px(fov_gaze_filter *f, const fov_ecc_model *m,
                                                 uint64_t t_us, fov_gaze raw, fov_gaze *out)
{
    const char *bad;
    fov_result r;
    if (!f) return FOV_ERR_NULL;
    if (!m)
        return fov__err(&f->cfg.logger, "fovsdf", FOV_ERR_NULL,
                        FOV__MSG("gaze_filter_push_px: m is NULL"), (uint32_t)__LINE__);
    r = fov__gaze_push_px(f, m, t_us, raw, out, &bad);
    return r == FOV_OK ? r : fov__err(&f->cfg.logger, "fovsdf", r, bad, (uint32_t)__LINE__);
}
FOVSDF_API fov_result fovsdf_gaze_to_deg(const fov_ecc_model *m, fov_gaze px, float deg[2])
{
    if (!m || !deg) return FOV_ERR_NULL;
    if (!fov__finite(px.x) || !fov__finite(px.y)) return FOV_ERR_NOT_FINITE;
    return fov__gaze_to_deg(m, px.x, px.y, deg) ? FOV_OK : FOV_ERR_INVALID_ARG;
}
FOVSDF_API fov_result fovsdf_gaze_from_deg(const fov_ecc_model *m, const float deg[2], fov_gaze *px)
{
    fov_gaze g;
    if (!m || !deg || !px) return FOV_ERR_NULL;
    if (!fov__finite(deg[0]) || !fov__finite(deg[1])) return FOV_ERR_NOT_FINITE;
    if (!fov__gaze_from_deg(m, deg, &g.x, &g.y)) return FOV_ERR_INVALID_ARG;
    *px = g;
    return FOV_OK;
}
FOVSDF_API fov_result fovsdf_gaze_margin(const fov_gaze_filter *f, float accuracy_deg,
                                         float latency_ms, float *margin_deg)
{
    fov_result r = fov__gaze_margin(f, accuracy_deg, latency_ms, margin_deg);
    if (r == FOV_OK || !f) return r;
    return fov__err(&f->cfg.logger, "fovsdf", r,
                    margin_deg ? FOV__MSG("gaze_margin: accuracy_deg must be in [0, 90] and "
                                          "latency_ms in [0, 1e6], finite (*margin_deg: the cap)")
                               : FOV__MSG("gaze_margin: margin_deg is NULL"),
                    (uint32_t)__LINE__);
}
FOVSDF_API fov_result fovsdf_gaze_predict(const fov_gaze_filter *f, float accuracy_deg,
                                          float latency_ms, fov_gaze_prediction *out)
{
    fov_result r = fov__gaze_predict(f, accuracy_deg, latency_ms, out);
    if (r == FOV_OK || !f) return r;
    return fov__err(&f->cfg.logger, "fovsdf", r,
                    out ? FOV__MSG("gaze_predict: accuracy_deg must be in [0, 90] and "
                                   "latency_ms in [0, 1e6], finite (*out: the filtered gaze "
                                   "and the cap)")
                        : FOV__MSG("gaze_predict: out is NULL"),
                    (uint32_t)__LINE__);
}
FOVSDF_API fov_result fovsdf_gaze_fixed(const fov_display *display, uint32_t width,
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
FOVSDF_API fov_result fovsdf_camera_display(const fov_camera *cam, fov_display *out)
{
    fov_display d;
    fov_result r = fov__camera_display(cam, &d);
    if (r == FOV_OK && out) *out = d;
    return out ? r : FOV_ERR_NULL;
}
FOVSDF_API fov_result fovsdf_config_gaze_margin(const fovsdf_config *base, float margin_deg,
                                                fovsdf_config *out)
{
    fovsdf_config c;
    fov_result r;
    if (!base || !out) return FOV_ERR_NULL;
    if (!fov__finite(margin_deg))
        FOVSDF__FAIL(&base->logger, FOV_ERR_NOT_FINITE,
                    "config_gaze_margin: margin NaN or infinite");
    if (margin_deg < 0.0f)
        FOVSDF__FAIL(&base->logger, FOV_ERR_INVALID_ARG,
                    "config_gaze_margin: margin must be >= 0");
    r = fovsdf_config_resolve(base, &c);
    if (r != FOV_OK) return r;
    c.acuity.fovea_deg += margin_deg;
    if (c.acuity.outer_deg > 0.0f) c.acuity.outer_deg += margin_deg;
    if (c.quarter_deg > 0.0f) c.quarter_deg += margin_deg;
    if (!(c.acuity.fovea_deg <= 180.0f) || !(c.acuity.outer_deg <= 180.0f) ||
        !(c.quarter_deg <= 180.0f))
        FOVSDF__FAIL(&base->logger, FOV_ERR_LIMIT,
                     "config_gaze_margin: fovea_deg, outer_deg or quarter_deg beyond 180");
    *out = c;
    return FOV_OK;
}

/* ---- node validation: the one check of the builder and of fovsdf_program_build ------------ */
/* Lengths of the scene (sizes, radii, offsets, periods, blend radii) are at most this in
   magnitude: squared lengths of a few of them stay finite in float (NUMERICS). */
#define FOVSDF__MAX_LEN 1e18f
/* A position every component of which lies within FOVSDF__MAX_LEN of the origin. */
FOVSDF__PRIV int fovsdf__coord_ok(const float v[3])
{
    return fov__absf(v[0]) <= FOVSDF__MAX_LEN && fov__absf(v[1]) <= FOVSDF__MAX_LEN &&
           fov__absf(v[2]) <= FOVSDF__MAX_LEN;
}
/* Every linear RGB value the library returns lies in [0, this] (the largest half float). */
#define FOVSDF__RGB_MAX 65504.0f

FOVSDF__PRIV int fovsdf__node_arity(uint32_t t)
{
    if (t >= FOVSDF_NODE_SPHERE && t <= FOVSDF_NODE_TERRAIN) return 0;
    if (t >= FOVSDF_NODE_UNION && t <= FOVSDF_NODE_SMOOTH_INTERSECT) return 2;
    if (t >= FOVSDF_NODE_TRANSLATE && t <= FOVSDF_NODE_ONION) return 1;
    return -1;
}

FOVSDF__PRIV const char *fovsdf__node_name(uint32_t t)
{
    static const char *const names[] = { "none", "sphere", "box", "round_box", "box_frame",
                                         "torus", "capsule", "cylinder", "cone", "plane",
                                         "menger", "mandelbulb", "terrain", "union", "subtract",
                                         "intersect", "smooth_union", "smooth_subtract",
                                         "smooth_intersect", "translate", "rotate", "scale",
                                         "repeat", "mirror", "round", "onion" };
    return t < (uint32_t)_FOVSDF_NODE_NUM ? names[t] : "unknown";
}

/* Logs "<who>: node <index> (<type>): [f<field> ]<rule>" and returns r. */
FOVSDF__PRIV fov_result fovsdf__node_fail(const fov_logger *lg, fov_result r, const char *who,
                                          uint32_t index, uint32_t type, int field,
                                          const char *rule, uint32_t line)
{
#ifndef FOV_NO_ERROR_STRINGS
    char buf[192];
    uint32_t n = 0;
    n = fov__app(buf, n, sizeof buf, who);
    n = fov__app(buf, n, sizeof buf, ": node ");
    n = fov__appu(buf, n, sizeof buf, index);
    n = fov__app(buf, n, sizeof buf, " (");
    n = fov__app(buf, n, sizeof buf, fovsdf__node_name(type));
    n = fov__app(buf, n, sizeof buf, "): ");
    if (field >= 0) {
        n = fov__app(buf, n, sizeof buf, "f");
        n = fov__appu(buf, n, sizeof buf, (uint32_t)field);
        n = fov__app(buf, n, sizeof buf, " ");
    }
    (void)fov__app(buf, n, sizeof buf, rule);
    return fov__err(lg, "fovsdf", r, buf, line);
#else
    (void)who; (void)index; (void)type; (void)field; (void)rule;
    return fov__err(lg, "fovsdf", r, "", line);
#endif
}

/* Float parameters each node type reads (f0 .. f(n-1)). */
FOVSDF__PRIV uint32_t fovsdf__node_nf(uint32_t t)
{
    static const uint8_t nf[_FOVSDF_NODE_NUM] = { 0, 1, 3, 4, 4, 2, 7, 2, 3, 4, 1, 1, 3, 0, 0, 0, 1,
                                                  1, 1, 3, 9, 1, 3, 0, 1, 1 };
    return t < (uint32_t)_FOVSDF_NODE_NUM ? nf[t] : 0u;
}

#define FOVSDF__NCK(cond, code, field, rule)                                                     \
    do {                                                                                         \
        if (!(cond))                                                                             \
            return fovsdf__node_fail(lg, code, who, index, n->type, field, FOV__MSG(rule),       \
                                     (uint32_t)__LINE__);                                        \
    } while (0)

/* Validates node n (the node at index `index`): its type, its children (indices in
   [0, limit)) and every parameter it reads, with the ranges the builder functions document.
   The first failure is logged (with the node, the field and the allowed range) and returned. */
FOVSDF__PRIV fov_result fovsdf__node_check(const fovsdf_node *n, uint32_t index, uint32_t limit,
                                           const fov_logger *lg, const char *who)
{
    const float *f = n->f;
    uint32_t t = n->type, nf, k;
    int ar = fovsdf__node_arity(t);
    FOVSDF__NCK(ar >= 0, FOV_ERR_INVALID_ARG, -1, "unknown node type");
    FOVSDF__NCK(ar < 1 || (n->a >= 0 && (uint32_t)n->a < limit), FOV_ERR_INVALID_ARG, -1,
                "child a must be an existing node index (builder: an earlier node)");
    FOVSDF__NCK(ar < 2 || (n->b >= 0 && (uint32_t)n->b < limit), FOV_ERR_INVALID_ARG, -1,
                "child b must be an existing node index (builder: an earlier node)");
    nf = fovsdf__node_nf(t);
    for (k = 0; k < nf; ++k)
        FOVSDF__NCK(fov__finite(f[k]), FOV_ERR_NOT_FINITE, (int)k, "is NaN or infinite");
    /* lengths: everything but the plane normal, the rotation matrix, the bulb's power and the
       terrain's distance scale */
    for (k = 0; k < nf; ++k) {
        if ((t == FOVSDF_NODE_PLANE && k < 3u) || t == FOVSDF_NODE_ROTATE ||
            t == FOVSDF_NODE_MANDELBULB || (t == FOVSDF_NODE_TERRAIN && k == 2u))
            continue;
        FOVSDF__NCK(fov__absf(f[k]) <= FOVSDF__MAX_LEN, FOV_ERR_LIMIT, (int)k,
                    "beyond 1e18 in magnitude (the float envelope of scene lengths)");
    }
    switch (t) {
    case FOVSDF_NODE_SPHERE:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "radius must be > 0");
        break;
    case FOVSDF_NODE_BOX: case FOVSDF_NODE_ROUND_BOX: case FOVSDF_NODE_BOX_FRAME:
        for (k = 0; k < 3u; ++k)
            FOVSDF__NCK(f[k] > 0.0f, FOV_ERR_INVALID_ARG, (int)k, "half extent must be > 0");
        if (t == FOVSDF_NODE_ROUND_BOX)
            FOVSDF__NCK(f[3] >= 0.0f && f[3] <= f[0] && f[3] <= f[1] && f[3] <= f[2],
                        FOV_ERR_INVALID_ARG, 3,
                        "rounding radius must be in [0, the smallest half extent]");
        if (t == FOVSDF_NODE_BOX_FRAME)
            FOVSDF__NCK(f[3] > 0.0f, FOV_ERR_INVALID_ARG, 3, "frame thickness must be > 0");
        break;
    case FOVSDF_NODE_TORUS:
        FOVSDF__NCK(f[0] >= 0.0f, FOV_ERR_INVALID_ARG, 0, "major radius must be >= 0");
        FOVSDF__NCK(f[1] > 0.0f, FOV_ERR_INVALID_ARG, 1, "minor radius must be > 0");
        break;
    case FOVSDF_NODE_CAPSULE:
        FOVSDF__NCK(f[6] > 0.0f, FOV_ERR_INVALID_ARG, 6, "radius must be > 0");
        break;
    case FOVSDF_NODE_CYLINDER:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "half height must be > 0");
        FOVSDF__NCK(f[1] > 0.0f, FOV_ERR_INVALID_ARG, 1, "radius must be > 0");
        break;
    case FOVSDF_NODE_CONE:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "half height must be > 0");
        FOVSDF__NCK(f[1] >= 0.0f, FOV_ERR_INVALID_ARG, 1, "bottom radius must be >= 0");
        FOVSDF__NCK(f[2] >= 0.0f, FOV_ERR_INVALID_ARG, 2, "top radius must be >= 0");
        FOVSDF__NCK(f[1] > 0.0f || f[2] > 0.0f, FOV_ERR_INVALID_ARG, 1,
                    "bottom or top radius must be > 0");
        break;
    case FOVSDF_NODE_PLANE:
        FOVSDF__NCK(!(fov__is0(f[0]) && fov__is0(f[1]) && fov__is0(f[2])), FOV_ERR_DEGENERATE, 0,
                    "normal (f0..f2) must not be zero");
        break;
    case FOVSDF_NODE_MENGER:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "half size must be > 0");
        FOVSDF__NCK(n->i[0] >= 1 && n->i[0] <= 8, FOV_ERR_INVALID_ARG, -1,
                    "i0 iterations must be 1 .. 8");
        break;
    case FOVSDF_NODE_MANDELBULB:
        FOVSDF__NCK(f[0] >= 2.0f && f[0] <= 16.0f, FOV_ERR_INVALID_ARG, 0,
                    "power must be in [2, 16]");
        FOVSDF__NCK(n->i[0] >= 1 && n->i[0] <= 32, FOV_ERR_INVALID_ARG, -1,
                    "i0 iterations must be 1 .. 32");
        break;
    case FOVSDF_NODE_TERRAIN:
        FOVSDF__NCK(f[0] >= 0.0f, FOV_ERR_INVALID_ARG, 0, "amplitude must be >= 0");
        FOVSDF__NCK(f[1] > 0.0f, FOV_ERR_INVALID_ARG, 1, "frequency must be > 0");
        FOVSDF__NCK(f[2] > 0.0f && f[2] <= 1.0f, FOV_ERR_INVALID_ARG, 2,
            "distance scale must be in (0, 1] (fovsdf_terrain sets it from the slope bound)");
        FOVSDF__NCK(n->i[0] >= 1 && n->i[0] <= 12, FOV_ERR_INVALID_ARG, -1,
                    "i0 octaves must be 1 .. 12");
        break;
    case FOVSDF_NODE_SMOOTH_UNION: case FOVSDF_NODE_SMOOTH_SUBTRACT:
    case FOVSDF_NODE_SMOOTH_INTERSECT:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "blend radius k must be > 0");
        break;
    case FOVSDF_NODE_ROTATE: {
        uint32_t i, j;
        for (i = 0; i < 3u; ++i)
            for (j = 0; j < 3u; ++j) {
                float d = f[3u * i] * f[3u * j] + f[3u * i + 1u] * f[3u * j + 1u] +
                          f[3u * i + 2u] * f[3u * j + 2u];
                FOVSDF__NCK(fov__absf(d - (i == j ? 1.0f : 0.0f)) <= 1e-3f, FOV_ERR_INVALID_ARG, -1,
                            "f0..f8 must be a rotation matrix (rows orthonormal within 1e-3)");
            }
        break;
    }
    case FOVSDF_NODE_SCALE:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "scale must be > 0");
        break;
    case FOVSDF_NODE_REPEAT:
        for (k = 0; k < 3u; ++k) {
            FOVSDF__NCK(f[k] >= 0.0f, FOV_ERR_INVALID_ARG, (int)k,
                        "period must be >= 0 (0: no repetition)");
            FOVSDF__NCK(n->i[k] >= 0 && n->i[k] <= 1000000, FOV_ERR_INVALID_ARG, -1,
                        "i0..i2 copies each side must be 0 .. 1000000 (0: infinite)");
        }
        break;
    case FOVSDF_NODE_MIRROR:
        FOVSDF__NCK(n->i[0] >= 1 && n->i[0] <= 7, FOV_ERR_INVALID_ARG, -1,
                    "i0 axis mask must be 1 .. 7");
        break;
    case FOVSDF_NODE_ROUND:
        FOVSDF__NCK(f[0] >= 0.0f, FOV_ERR_INVALID_ARG, 0, "radius must be >= 0");
        break;
    case FOVSDF_NODE_ONION:
        FOVSDF__NCK(f[0] > 0.0f, FOV_ERR_INVALID_ARG, 0, "thickness must be > 0");
        break;
    default: break; /* union, subtract, intersect, translate: children and lengths only */
    }
    return FOV_OK;
}
#undef FOVSDF__NCK

/* ---- scene builder ------------------------------------------------------------------------ */
FOVSDF_API void fovsdf_builder_init(fovsdf_builder *b, fovsdf_node *nodes, uint32_t cap)
{
    if (!b) return;
    b->nodes = nodes;
    b->cap = nodes ? cap : 0;
    b->count = 0;
    b->material = 0;
    b->err = nodes ? FOV_OK : FOV_ERR_NULL;
    b->logger.func = 0;
    b->logger.user = 0;
}

/* Appends a node after fovsdf__node_check (the check fovsdf_program_build applies). */
FOVSDF__PRIV int32_t fovsdf__add(fovsdf_builder *b, uint32_t type, int32_t x, int32_t y,
                                 const float *f, uint32_t nf, const int32_t *iv, uint32_t ni)
{
    fovsdf_node *n;
    uint32_t k;
    fov_result r;
    if (!b) return -1;
    if (b->err != FOV_OK) return -1;
    if (b->count >= b->cap || b->count >= 0x7fffffffu) {
        b->err = fov__err(&b->logger, "fovsdf", FOV_ERR_TOO_SMALL,
                          FOV__MSG("builder: node array full (cap)"), (uint32_t)__LINE__);
        return -1;
    }
    n = &b->nodes[b->count]; /* written, but counted only when valid */
    FOV_MEMSET(n, 0, sizeof *n);
    n->type = type;
    n->a = x;
    n->b = y;
    n->material = b->material;
    for (k = 0; k < nf && k < 9; ++k) n->f[k] = f[k];
    for (k = 0; k < ni && k < 3; ++k) n->i[k] = iv[k];
    r = fovsdf__node_check(n, b->count, b->count, &b->logger, "builder");
    if (r != FOV_OK) { b->err = r; return -1; }
    return (int32_t)b->count++;
}
FOVSDF__PRIV int32_t fovsdf__bad(fovsdf_builder *b, fov_result r, const char *msg, uint32_t line)
{
    if (b && b->err == FOV_OK) b->err = fov__err(&b->logger, "fovsdf", r, msg, line);
    return -1;
}
#define FOVSDF__BAD(b, r, msg) fovsdf__bad(b, r, FOV__MSG(msg), (uint32_t)__LINE__)

FOVSDF_API int32_t fovsdf_sphere(fovsdf_builder *b, float r)
{
    return fovsdf__add(b, FOVSDF_NODE_SPHERE, -1, -1, &r, 1, 0, 0);
}
FOVSDF_API int32_t fovsdf_box(fovsdf_builder *b, float hx, float hy, float hz)
{
    float f[3];
    f[0] = hx; f[1] = hy; f[2] = hz;
    return fovsdf__add(b, FOVSDF_NODE_BOX, -1, -1, f, 3, 0, 0);
}
FOVSDF_API int32_t fovsdf_round_box(fovsdf_builder *b, float hx, float hy, float hz, float r)
{
    float f[4];
    f[0] = hx; f[1] = hy; f[2] = hz; f[3] = r;
    return fovsdf__add(b, FOVSDF_NODE_ROUND_BOX, -1, -1, f, 4, 0, 0);
}
FOVSDF_API int32_t fovsdf_box_frame(fovsdf_builder *b, float hx, float hy, float hz, float e)
{
    float f[4];
    f[0] = hx; f[1] = hy; f[2] = hz; f[3] = e;
    return fovsdf__add(b, FOVSDF_NODE_BOX_FRAME, -1, -1, f, 4, 0, 0);
}
FOVSDF_API int32_t fovsdf_torus(fovsdf_builder *b, float major, float minor)
{
    float f[2];
    f[0] = major; f[1] = minor;
    return fovsdf__add(b, FOVSDF_NODE_TORUS, -1, -1, f, 2, 0, 0);
}
FOVSDF_API int32_t fovsdf_capsule(fovsdf_builder *b, const float a[3], const float c[3], float r)
{
    float f[7];
    if (!a || !c) return FOVSDF__BAD(b, FOV_ERR_NULL, "builder: capsule end points are NULL");
    f[0] = a[0]; f[1] = a[1]; f[2] = a[2]; f[3] = c[0]; f[4] = c[1]; f[5] = c[2]; f[6] = r;
    return fovsdf__add(b, FOVSDF_NODE_CAPSULE, -1, -1, f, 7, 0, 0);
}
FOVSDF_API int32_t fovsdf_cylinder(fovsdf_builder *b, float half_height, float r)
{
    float f[2];
    f[0] = half_height; f[1] = r;
    return fovsdf__add(b, FOVSDF_NODE_CYLINDER, -1, -1, f, 2, 0, 0);
}
FOVSDF_API int32_t fovsdf_cone(fovsdf_builder *b, float half_height, float r_bottom, float r_top)
{
    float f[3];
    f[0] = half_height; f[1] = r_bottom; f[2] = r_top;
    return fovsdf__add(b, FOVSDF_NODE_CONE, -1, -1, f, 3, 0, 0);
}
FOVSDF_API int32_t fovsdf_plane(fovsdf_builder *b, float nx, float ny, float nz, float offset)
{
    float f[4];
    f[0] = nx; f[1] = ny; f[2] = nz; f[3] = offset;
    /* any finite non-zero normal (1e-30 or 1e30 long too); zero stays zero */
    (void)fovsdf__normalize(f);
    return fovsdf__add(b, FOVSDF_NODE_PLANE, -1, -1, f, 4, 0, 0);
}
FOVSDF_API int32_t fovsdf_menger(fovsdf_builder *b, float half_size, int32_t iterations)
{
    return fovsdf__add(b, FOVSDF_NODE_MENGER, -1, -1, &half_size, 1, &iterations, 1);
}
FOVSDF_API int32_t fovsdf_mandelbulb(fovsdf_builder *b, float power, int32_t iterations)
{
    return fovsdf__add(b, FOVSDF_NODE_MANDELBULB, -1, -1, &power, 1, &iterations, 1);
}
FOVSDF_API int32_t fovsdf_terrain(fovsdf_builder *b, float amplitude, float frequency,
                                  int32_t octaves)
{
    float f[3], g = 0.0f, w = 1.0f;
    int32_t o, no = octaves < 1 ? 1 : (octaves > 12 ? 12 : octaves);
    /* |grad h| <= amplitude * frequency * sum_o (0.5 * 2.03)^o; the distance bound divides
       (y - h) by sqrt(1 + |grad h|^2), which makes it Lipschitz 1 (conservative). */
    for (o = 0; o < no; ++o) { g += w; w *= 0.5f * 2.03f; }
    g *= amplitude * frequency;
    f[0] = amplitude; f[1] = frequency;
    /* 1 / sqrt(1 + g^2), or 1 / g where g^2 would overflow (a slope bound above 1e15) */
    f[2] = fov__absf(g) > 1e15f ? 1.0f / fov__absf(g) : 1.0f / FOV__SQRT(1.0f + g * g);
    if (!fov__finite(f[2])) f[2] = 0.0f; /* NaN inputs: node_check reports them first */
    return fovsdf__add(b, FOVSDF_NODE_TERRAIN, -1, -1, f, 3, &octaves, 1);
}
FOVSDF__PRIV int32_t fovsdf__binop(fovsdf_builder *b, uint32_t type, int32_t x, int32_t y, float k,
                                   int smooth)
{
    return fovsdf__add(b, type, x, y, &k, smooth ? 1u : 0u, 0, 0);
}
FOVSDF_API int32_t fovsdf_union(fovsdf_builder *b, int32_t x, int32_t y)
{
    return fovsdf__binop(b, FOVSDF_NODE_UNION, x, y, 0.0f, 0);
}
FOVSDF_API int32_t fovsdf_subtract(fovsdf_builder *b, int32_t x, int32_t y)
{
    return fovsdf__binop(b, FOVSDF_NODE_SUBTRACT, x, y, 0.0f, 0);
}
FOVSDF_API int32_t fovsdf_intersect(fovsdf_builder *b, int32_t x, int32_t y)
{
    return fovsdf__binop(b, FOVSDF_NODE_INTERSECT, x, y, 0.0f, 0);
}
FOVSDF_API int32_t fovsdf_smooth_union(fovsdf_builder *b, int32_t x, int32_t y, float k)
{
    return fovsdf__binop(b, FOVSDF_NODE_SMOOTH_UNION, x, y, k, 1);
}
FOVSDF_API int32_t fovsdf_smooth_subtract(fovsdf_builder *b, int32_t x, int32_t y, float k)
{
    return fovsdf__binop(b, FOVSDF_NODE_SMOOTH_SUBTRACT, x, y, k, 1);
}
FOVSDF_API int32_t fovsdf_smooth_intersect(fovsdf_builder *b, int32_t x, int32_t y, float k)
{
    return fovsdf__binop(b, FOVSDF_NODE_SMOOTH_INTERSECT, x, y, k, 1);
}
FOVSDF_API int32_t fovsdf_translate(fovsdf_builder *b, int32_t x, float tx, float ty, float tz)
{
    float f[3];
    f[0] = tx; f[1] = ty; f[2] = tz;
    return fovsdf__add(b, FOVSDF_NODE_TRANSLATE, x, -1, f, 3, 0, 0);
}
FOVSDF_API int32_t fovsdf_rotate(fovsdf_builder *b, int32_t x, float ax, float ay, float az,
                                 float angle_deg)
{
    float a[3], f[9], c, s, t;
    a[0] = ax; a[1] = ay; a[2] = az;
    if (!fov__finite3(a) || !fov__finite(angle_deg))
        return FOVSDF__BAD(b, FOV_ERR_NOT_FINITE,
                           "builder: rotate axis or angle is NaN or infinite");
    if (!(fovsdf__normalize(a) > 0.0f))
        return FOVSDF__BAD(b, FOV_ERR_DEGENERATE, "builder: rotate axis is zero");
    c = FOV__COS(angle_deg * FOV__DEG);
    s = FOV__SIN(angle_deg * FOV__DEG);
    t = 1.0f - c;
    /* Rodrigues: rotation matrix R (object -> world), row-major */
    f[0] = c + a[0] * a[0] * t;        f[1] = a[0] * a[1] * t - a[2] * s;
    f[2] = a[0] * a[2] * t + a[1] * s;
    f[3] = a[1] * a[0] * t + a[2] * s; f[4] = c + a[1] * a[1] * t;
    f[5] = a[1] * a[2] * t - a[0] * s;
    f[6] = a[2] * a[0] * t - a[1] * s; f[7] = a[2] * a[1] * t + a[0] * s;
    f[8] = c + a[2] * a[2] * t;
    return fovsdf__add(b, FOVSDF_NODE_ROTATE, x, -1, f, 9, 0, 0);
}
FOVSDF_API int32_t fovsdf_scale(fovsdf_builder *b, int32_t x, float s)
{
    return fovsdf__add(b, FOVSDF_NODE_SCALE, x, -1, &s, 1, 0, 0);
}
FOVSDF_API int32_t fovsdf_repeat(fovsdf_builder *b, int32_t x, float px, float py, float pz,
                                 int32_t nx, int32_t ny, int32_t nz)
{
    float f[3];
    int32_t n[3];
    f[0] = px; f[1] = py; f[2] = pz; n[0] = nx; n[1] = ny; n[2] = nz;
    return fovsdf__add(b, FOVSDF_NODE_REPEAT, x, -1, f, 3, n, 3);
}
FOVSDF_API int32_t fovsdf_mirror(fovsdf_builder *b, int32_t x, int32_t axes)
{
    return fovsdf__add(b, FOVSDF_NODE_MIRROR, x, -1, 0, 0, &axes, 1);
}
FOVSDF_API int32_t fovsdf_round(fovsdf_builder *b, int32_t x, float r)
{
    return fovsdf__add(b, FOVSDF_NODE_ROUND, x, -1, &r, 1, 0, 0);
}
FOVSDF_API int32_t fovsdf_onion(fovsdf_builder *b, int32_t x, float thickness)
{
    return fovsdf__add(b, FOVSDF_NODE_ONION, x, -1, &thickness, 1, 0, 0);
}

/* ---- compiled program -------------------------------------------------------------------- */
/* The program is postfix code for a small stack machine: primitives push a (distance,
   material) pair, operators pop two and push one, point ops (translate, rotate, scale, repeat,
   mirror) save the evaluation point, transform it, and a POP restores it (and rescales the
   distance for SCALE). BOUND instructions guard a subtree: when the point is farther than a
   margin from the subtree's bounding sphere, the distance to the sphere (a lower bound of the
   subtree's distance) is pushed instead and the subtree is skipped. */
enum {
    FOVSDF__OP_PRIM = 1,  /* node type in sub */
    FOVSDF__OP_BIN,       /* binary operator, node type in sub */
    FOVSDF__OP_UNARY,     /* ROUND / ONION, node type in sub */
    FOVSDF__OP_PUSHP,     /* point op, node type in sub */
    FOVSDF__OP_POPP,      /* restore point; multiply distance by f[0] */
    FOVSDF__OP_BOUND      /* f[0..2] centre, f[3] radius, jump = index after the subtree */
};
#define FOVSDF__FLAG_DEFLATE 1u
/* Pruned programs only (fovsdf__prune), in the existing instructions (the evaluators'
   dispatch stays as it is): BDIST, a BOUND that every point of the region skips with its
   subtree dropped: flags BDIST, jump the next index and band -FLT_MAX (margin 0: it skips at
   every point off its centre, which the region never contains), so it pushes the bound's
   value and material -1 and counts i[0] skipped; CNT, a UNARY of sub FOVSDF__SUB_CNT: counts
   i[0] skipped (a BDIST that can never be its union's minimum, dropped with the union). */
#define FOVSDF__FLAG_BDIST 2u
#define FOVSDF__SUB_CNT 0xffffu

typedef struct fovsdf__ins {
    uint16_t op, sub;
    uint32_t flags;
    int32_t material;
    uint32_t jump;        /* BOUND: next instruction after the guarded subtree */
    int32_t i[3];         /* BOUND: i[0] = primitives inside */
    float f[9];
} fovsdf__ins;

typedef struct fovsdf__bsph {   /* per-node bounds and cost */
    float c[3], r;              /* r < 0: unbounded */
    uint32_t prims;             /* cost in primitive-evaluation units (fractals cost more) */
    uint32_t count;             /* primitive instructions in the subtree */
    uint32_t done;              /* 0 unvisited, 1 in progress, 2 done */
} fovsdf__bsph;

#define FOVSDF__MAX_DEPTH 64


/* Bounding sphere of a primitive in its own frame. */
FOVSDF__PRIV void fovsdf__prim_bound(const fovsdf_node *n, fovsdf__bsph *o)
{
    const float *f = n->f;
    o->c[0] = o->c[1] = o->c[2] = 0.0f;
    switch (n->type) {
    case FOVSDF_NODE_SPHERE: o->r = f[0]; break;
    case FOVSDF_NODE_BOX: case FOVSDF_NODE_ROUND_BOX: case FOVSDF_NODE_BOX_FRAME:
        o->r = fovsdf__len3f(f[0], f[1], f[2]);
        break;
    case FOVSDF_NODE_TORUS: o->r = f[0] + f[1]; break;
    case FOVSDF_NODE_CAPSULE:
        o->c[0] = 0.5f * (f[0] + f[3]); o->c[1] = 0.5f * (f[1] + f[4]);
        o->c[2] = 0.5f * (f[2] + f[5]);
        o->r = 0.5f * fovsdf__len3f(f[3] - f[0], f[4] - f[1], f[5] - f[2]) + f[6];
        break;
    case FOVSDF_NODE_CYLINDER: o->r = fovsdf__len2f(f[0], f[1]); break;
    case FOVSDF_NODE_CONE: o->r = fovsdf__len2f(f[0], fov__maxf(f[1], f[2])); break;
    case FOVSDF_NODE_MENGER: o->r = f[0] * 1.7320508f; break;
    case FOVSDF_NODE_MANDELBULB: o->r = f[0] < 4.0f ? 1.5f : 1.25f; break;
    default: o->r = -1.0f; break; /* plane, terrain */
    }
    o->r *= 1.0001f; /* absorb rounding */
}

FOVSDF__PRIV void fovsdf__merge_bound(const fovsdf__bsph *a, const fovsdf__bsph *b, fovsdf__bsph *o)
{
    float d[3], l, r;
    if (a->r < 0.0f || b->r < 0.0f) { o->r = -1.0f; return; }
    d[0] = b->c[0] - a->c[0]; d[1] = b->c[1] - a->c[1]; d[2] = b->c[2] - a->c[2];
    l = fov__len(d);
    if (l + b->r <= a->r) {
        o->c[0] = a->c[0]; o->c[1] = a->c[1]; o->c[2] = a->c[2]; o->r = a->r;
        return;
    }
    if (l + a->r <= b->r) {
        o->c[0] = b->c[0]; o->c[1] = b->c[1]; o->c[2] = b->c[2]; o->r = b->r;
        return;
    }
    r = 0.5f * (l + a->r + b->r);
    o->c[0] = a->c[0] + d[0] * ((r - a->r) / l);
    o->c[1] = a->c[1] + d[1] * ((r - a->r) / l);
    o->c[2] = a->c[2] + d[2] * ((r - a->r) / l);
    o->r = r * 1.0001f; /* absorb rounding */
}

/* Bounds of node n from its children's (already computed) bounds. */
FOVSDF__PRIV void fovsdf__node_bound(const fovsdf_node *n, fovsdf__bsph *bs, fovsdf__bsph *o)
{
    const fovsdf__bsph *a = n->a >= 0 ? &bs[n->a] : 0, *b = n->b >= 0 ? &bs[n->b] : 0;
    const float *f = n->f;
    uint32_t prims = (a ? a->prims : 0) + (b ? b->prims : 0);
    uint32_t count = (a ? a->count : 0) + (b ? b->count : 0);
    switch (n->type) {
    case FOVSDF_NODE_UNION: fovsdf__merge_bound(a, b, o); break;
    case FOVSDF_NODE_SMOOTH_UNION:
        fovsdf__merge_bound(a, b, o);
        if (o->r >= 0.0f) o->r += 0.25f * f[0];
        break;
    case FOVSDF_NODE_SUBTRACT: *o = *a; break;
    case FOVSDF_NODE_SMOOTH_SUBTRACT: *o = *a; if (o->r >= 0.0f) o->r += 0.25f * f[0]; break;
    case FOVSDF_NODE_INTERSECT: case FOVSDF_NODE_SMOOTH_INTERSECT:
        if (a->r < 0.0f) *o = *b; else if (b->r < 0.0f) *o = *a; else *o = a->r < b->r ? *a : *b;
        if (n->type == FOVSDF_NODE_SMOOTH_INTERSECT && o->r >= 0.0f) o->r += 0.25f * f[0];
        break;
    case FOVSDF_NODE_TRANSLATE: *o = *a; o->c[0] += f[0]; o->c[1] += f[1]; o->c[2] += f[2]; break;
    case FOVSDF_NODE_ROTATE:
        *o = *a;
        o->c[0] = f[0] * a->c[0] + f[1] * a->c[1] + f[2] * a->c[2];
        o->c[1] = f[3] * a->c[0] + f[4] * a->c[1] + f[5] * a->c[2];
        o->c[2] = f[6] * a->c[0] + f[7] * a->c[1] + f[8] * a->c[2];
        o->r = a->r < 0.0f ? -1.0f : a->r * 1.0001f;
        break;
    case FOVSDF_NODE_SCALE:
        *o = *a; o->c[0] *= f[0]; o->c[1] *= f[0]; o->c[2] *= f[0];
        if (o->r >= 0.0f) o->r *= f[0];
        break;
    case FOVSDF_NODE_REPEAT: {
        int k;
        float ext = 0.0f;
        *o = *a;
        for (k = 0; k < 3; ++k) {
            if (f[k] > 0.0f) {
                if (n->i[k] == 0) { o->r = -1.0f; break; }
                ext += ((float)n->i[k] * f[k]) * ((float)n->i[k] * f[k]);
            }
        }
        if (o->r >= 0.0f) o->r += FOV__SQRT(ext);
        break;
    }
    case FOVSDF_NODE_MIRROR: {
        int k;
        float m = 0.0f;
        *o = *a;
        for (k = 0; k < 3; ++k) if (n->i[0] & (1 << k)) { m += o->c[k] * o->c[k]; o->c[k] = 0.0f; }
        if (o->r >= 0.0f) o->r += FOV__SQRT(m);
        break;
    }
    case FOVSDF_NODE_ROUND: case FOVSDF_NODE_ONION: *o = *a; if (o->r >= 0.0f) o->r += f[0]; break;
    default: fovsdf__prim_bound(n, o); prims = 1; count = 1; break;
    }
    /* cost in primitive-evaluation units: fractals and terrain cost several */
    if (n->type == FOVSDF_NODE_MENGER) prims = 1u + (uint32_t)n->i[0];
    if (n->type == FOVSDF_NODE_MANDELBULB) prims = 2u + (uint32_t)n->i[0] / 2u;
    if (n->type == FOVSDF_NODE_TERRAIN) prims = 1u + (uint32_t)n->i[0];
    /* extents beyond float (1e6 copies of a 1e18 period): unbounded, never a NaN centre */
    if (!fov__finite(o->r) || !fov__finite3(o->c)) {
        o->r = -1.0f;
        o->c[0] = o->c[1] = o->c[2] = 0.0f;
    }
    o->prims = prims > 0xffffffu ? 0xffffffu : prims;
    o->count = count > 0xffffffu ? 0xffffffu : count;
    o->done = 2;
}

typedef struct fovsdf__frame {
    int32_t node;
    uint32_t stage;
    uint32_t flags;    /* inflation parity */
    uint32_t bound_at; /* index of this node's BOUND instruction, or ~0 */
    int32_t parent_r_valid;
    float parent_r;
    float band;        /* how far operators above (round, onion, smooth) may move surfaces out */
} fovsdf__frame;

/* Bounds of every node reachable from root, post-order with an explicit stack of up to
   `count` entries in program memory (each node is on it at most once); a child that is still
   in progress closes a cycle: FOV_ERR_INVALID_ARG. */
FOVSDF__PRIV fov_result fovsdf__bounds(const fovsdf_node *nodes, uint32_t count, int32_t root,
                                       fovsdf__bsph *bs, int32_t *stk, uint8_t *stage)
{
    uint32_t k, sp;
    for (k = 0; k < count; ++k) { bs[k].done = 0; stage[k] = 0; }
    stk[0] = root; sp = 1;
    bs[root].done = 1;
    while (sp > 0) {
        int32_t x = stk[sp - 1];
        const fovsdf_node *nd = &nodes[x];
        int ar = fovsdf__node_arity(nd->type);
        if (ar < 0) return FOV_ERR_INVALID_ARG;
        if (stage[x] < (uint32_t)ar) {
            int32_t ch = stage[x] == 0 ? nd->a : nd->b;
            stage[x]++;
            if (ch < 0 || (uint32_t)ch >= count) return FOV_ERR_INVALID_ARG;
            if (bs[ch].done == 1) return FOV_ERR_INVALID_ARG; /* cycle */
            if (bs[ch].done == 0) {
                if (sp >= count) return FOV_ERR_LIMIT;
                bs[ch].done = 1;
                stk[sp++] = ch;
            }
            continue;
        }
        fovsdf__node_bound(nd, bs, &bs[x]);
        --sp;
    }
    return FOV_OK;
}

/* Rebalance every union cluster (a maximal tree of plain unions) into a bounding-sphere
   hierarchy: unbounded operands (planes, terrain, infinite repetition) stay at the top, the
   bounded ones are split recursively at the median of their centres along the widest axis.
   The cluster's root node keeps its index; new union nodes are appended after *n. */
FOVSDF__PRIV fov_result fovsdf__rebalance(fovsdf_node *nd, uint32_t *n, uint32_t cap,
                                          const fovsdf__bsph *bs, int32_t *leaves,
                                          uint32_t leaf_cap, uint8_t *is_child, int32_t *stk,
                                          uint32_t stk_cap)
{
    uint32_t count = *n, u, k;
    for (k = 0; k < count; ++k) is_child[k] = 0;
    for (k = 0; k < count; ++k)
        if (nd[k].type == FOVSDF_NODE_UNION) {
            if (nd[nd[k].a].type == FOVSDF_NODE_UNION) is_child[nd[k].a] = 1;
            if (nd[nd[k].b].type == FOVSDF_NODE_UNION) is_child[nd[k].b] = 1;
        }
    for (u = 0; u < count; ++u) {
        uint32_t sp = 0;
        int32_t top = -1;
        uint32_t nl = 0, nb = 0, i, j;
        int32_t rlo[FOVSDF__MAX_DEPTH], rhi[FOVSDF__MAX_DEPTH], *rslot[FOVSDF__MAX_DEPTH];
        int32_t rsp = 0;
        if (nd[u].type != FOVSDF_NODE_UNION || is_child[u] || bs[u].done != 2) continue;
        /* gather the cluster's operands */
        stk[sp++] = nd[u].b;
        stk[sp++] = nd[u].a;
        while (sp > 0) {
            int32_t x = stk[--sp];
            if (nd[x].type == FOVSDF_NODE_UNION) {
                if (sp + 2 > stk_cap) return FOV_ERR_LIMIT; /* a union DAG that unfolds too far */
                stk[sp++] = nd[x].b;
                stk[sp++] = nd[x].a;
            } else {
                if (nl >= leaf_cap) return FOV_ERR_LIMIT;
                leaves[nl++] = x;
            }
        }
        if (nl < 3) continue;
        /* bounded operands first (keeping their order), unbounded ones after */
        for (i = 0; i < nl; ++i)
            if (bs[leaves[i]].r >= 0.0f) {
                int32_t t = leaves[i];
                for (j = i; j > nb; --j) leaves[j] = leaves[j - 1];
                leaves[nb++] = t;
            }
        if (nb >= 2) {
            rlo[0] = 0; rhi[0] = (int32_t)nb; rslot[0] = &top; rsp = 1;
            while (rsp > 0) {
                int32_t lo, hi, *slot, mid, g;
                int ax = 0;
                float mn[3], mx[3];
                --rsp;
                lo = rlo[rsp]; hi = rhi[rsp]; slot = rslot[rsp];
                if (hi - lo == 1) { *slot = leaves[lo]; continue; }
                mn[0] = mn[1] = mn[2] = FLT_MAX;
                mx[0] = mx[1] = mx[2] = -FLT_MAX;
                for (i = (uint32_t)lo; i < (uint32_t)hi; ++i)
                    for (k = 0; k < 3; ++k) {
                        mn[k] = fov__minf(mn[k], bs[leaves[i]].c[k]);
                        mx[k] = fov__maxf(mx[k], bs[leaves[i]].c[k]);
                    }
                if (mx[1] - mn[1] > mx[ax] - mn[ax]) ax = 1;
                if (mx[2] - mn[2] > mx[ax] - mn[ax]) ax = 2;
                for (g = (hi - lo) / 2; g > 0; g /= 2) /* shell sort by centre along ax */
                    for (i = (uint32_t)(lo + g); i < (uint32_t)hi; ++i) {
                        int32_t t = leaves[i];
                        for (j = i; j >= (uint32_t)(lo + g) &&
                             bs[leaves[j - (uint32_t)g]].c[ax] > bs[t].c[ax]; j -= (uint32_t)g)
                            leaves[j] = leaves[j - (uint32_t)g];
                        leaves[j] = t;
                    }
                mid = (lo + hi) / 2;
                if (*n >= cap || rsp + 2 > FOVSDF__MAX_DEPTH) return FOV_ERR_LIMIT;
                nd[*n] = nd[u];
                nd[*n].a = -1;
                nd[*n].b = -1;
                *slot = (int32_t)*n;
                rlo[rsp] = lo; rhi[rsp] = mid; rslot[rsp] = &nd[*n].a; ++rsp;
                rlo[rsp] = mid; rhi[rsp] = hi; rslot[rsp] = &nd[*n].b; ++rsp;
                ++*n;
            }
        } else if (nb == 1) {
            top = leaves[0];
        }
        for (i = nb; i < nl; ++i) {
            if (top < 0) { top = leaves[i]; continue; }
            if (*n >= cap) return FOV_ERR_LIMIT;
            nd[*n] = nd[u];
            nd[*n].a = top;
            nd[*n].b = leaves[i];
            top = (int32_t)(*n)++;
        }
        /* the cluster root keeps its index: move the top union into it */
        FOV_ASSERT(top >= 0 && nd[top].type == FOVSDF_NODE_UNION);
        nd[u].a = nd[top].a;
        nd[u].b = nd[top].b;
    }
    return FOV_OK;
}

/* Emit the postfix code for the tree under root (bounds in bs). code == NULL counts only. */
FOVSDF__PRIV fov_result fovsdf__compile(const fovsdf_node *nodes, int32_t root,
                                        const fovsdf__bsph *bs, fovsdf__ins *code, uint32_t *n_out)
{
    fovsdf__frame st[FOVSDF__MAX_DEPTH];
    int32_t sp = 0;
    uint32_t n = 0, k;
    int32_t vdepth = 0, pdepth = 0, vmax = 0, pmax = 0;
    st[0].node = root; st[0].stage = 0; st[0].flags = 0; st[0].bound_at = 0xffffffffu;
    st[0].parent_r_valid = 0; st[0].parent_r = 0.0f; st[0].band = 0.0f;
    sp = 1;
    while (sp > 0) {
        fovsdf__frame *fr = &st[sp - 1];
        const fovsdf_node *nd = &nodes[fr->node];
        const fovsdf__bsph *b = &bs[fr->node];
        int ar = fovsdf__node_arity(nd->type);
        if (fr->stage == 0) {
            /* a bound pays off around subtrees of two or more primitives that are clearly
               smaller than the enclosing bound */
            if (b->r >= 0.0f && b->prims >= 2u &&
                (!fr->parent_r_valid || fr->parent_r > 1.2f * b->r)) {
                if (code) {
                    fovsdf__ins *in = &code[n];
                    FOV_MEMSET(in, 0, sizeof *in);
                    in->op = FOVSDF__OP_BOUND;
                    in->f[0] = b->c[0]; in->f[1] = b->c[1]; in->f[2] = b->c[2]; in->f[3] = b->r;
                    in->f[4] = fr->band;
                    in->i[0] = (int32_t)b->count;
                }
                fr->bound_at = n++;
            } else {
                fr->bound_at = 0xffffffffu;
            }
            if (ar == 0) {
                if (code) {
                    fovsdf__ins *in = &code[n];
                    FOV_MEMSET(in, 0, sizeof *in);
                    in->op = FOVSDF__OP_PRIM;
                    in->sub = (uint16_t)nd->type;
                    in->flags = fr->flags;
                    in->material = nd->material;
                    for (k = 0; k < 9; ++k) in->f[k] = nd->f[k];
                    for (k = 0; k < 3; ++k) in->i[k] = nd->i[k];
                }
                ++n;
                if (++vdepth > vmax) vmax = vdepth;
                fr->stage = 99;
            } else {
                if (nd->type >= FOVSDF_NODE_TRANSLATE && nd->type <= FOVSDF_NODE_MIRROR) {
                    if (code) {
                        fovsdf__ins *in = &code[n];
                        FOV_MEMSET(in, 0, sizeof *in);
                        in->op = FOVSDF__OP_PUSHP;
                        in->sub = (uint16_t)nd->type;
                        for (k = 0; k < 9; ++k) in->f[k] = nd->f[k];
                        for (k = 0; k < 3; ++k) in->i[k] = nd->i[k];
                    }
                    ++n;
                    if (++pdepth > pmax) pmax = pdepth;
                }
                fr->stage = 1;
            }
        }
        if (fr->stage >= 1 && fr->stage <= (uint32_t)ar) {
            int32_t ch = fr->stage == 1 ? nd->a : nd->b;
            uint32_t fl = fr->flags;
            float pr = b->r >= 0.0f ? b->r : (fr->parent_r_valid ? fr->parent_r : 0.0f);
            int32_t pv = (b->r >= 0.0f || fr->parent_r_valid) ? 1 : 0;
            /* inside a transform the child's bound is in another frame: compare radii only
               when the frames agree in scale (rotate/translate/mirror/repeat keep it) */
            float band = fr->band;
            if (nd->type == FOVSDF_NODE_SCALE) { pv = 0; band /= nd->f[0]; }
            /* operators that move the surface outwards or blend operands: a skipped subtree's
               lower bound minus this band must stay above the hit threshold */
            if (nd->type == FOVSDF_NODE_ROUND || nd->type == FOVSDF_NODE_ONION ||
                nd->type == FOVSDF_NODE_SMOOTH_UNION || nd->type == FOVSDF_NODE_SMOOTH_SUBTRACT ||
                nd->type == FOVSDF_NODE_SMOOTH_INTERSECT)
                band += nd->f[0];
            if (fr->stage == 2 &&
                (nd->type == FOVSDF_NODE_SUBTRACT || nd->type == FOVSDF_NODE_SMOOTH_SUBTRACT))
                fl ^= FOVSDF__FLAG_DEFLATE; /* holes shrink when solids grow */
            fr->stage++;
            if (sp >= FOVSDF__MAX_DEPTH) return FOV_ERR_LIMIT;
            st[sp].node = ch; st[sp].stage = 0; st[sp].flags = fl; st[sp].bound_at = 0xffffffffu;
            st[sp].parent_r_valid = pv; st[sp].parent_r = pr; st[sp].band = band;
            ++sp;
            continue;
        }
        /* all children done: emit the operator */
        if (ar == 2 || nd->type == FOVSDF_NODE_ROUND || nd->type == FOVSDF_NODE_ONION ||
            (nd->type >= FOVSDF_NODE_TRANSLATE && nd->type <= FOVSDF_NODE_MIRROR)) {
            if (code) {
                fovsdf__ins *in = &code[n];
                FOV_MEMSET(in, 0, sizeof *in);
                if (ar == 2) in->op = FOVSDF__OP_BIN;
                else if (nd->type == FOVSDF_NODE_ROUND || nd->type == FOVSDF_NODE_ONION)
                    in->op = FOVSDF__OP_UNARY;
                else in->op = FOVSDF__OP_POPP;
                in->sub = (uint16_t)nd->type;
                in->f[0] = nd->f[0];
                if (in->op == FOVSDF__OP_POPP && nd->type != FOVSDF_NODE_SCALE) in->f[0] = 1.0f;
            }
            ++n;
            if (ar == 2) --vdepth;
            if (nd->type >= FOVSDF_NODE_TRANSLATE && nd->type <= FOVSDF_NODE_MIRROR) --pdepth;
        }
        if (fr->bound_at != 0xffffffffu && code) code[fr->bound_at].jump = n;
        --sp;
        if (n > 0x00ffffffu) return FOV_ERR_LIMIT;
    }
    if (vmax > FOVSDF_MAX_STACK || pmax > FOVSDF_MAX_STACK) return FOV_ERR_LIMIT;
    *n_out = n;
    return FOV_OK;
}

/* Program memory: [bounds 2n][nodes 2n][leaves n][child marks n][stack 2n][stages 2n]
   [code 6n]. The node copy is rebalanced (union clusters become bounding hierarchies, at most
   n - 1 new nodes) and then compiled; every node visit emits at most 3 instructions (BOUND,
   the op or PUSHP, POP). Limits: after rebalancing, a tree deeper than 64 nodes or needing more
   than FOVSDF_MAX_STACK values or points at once gives FOV_ERR_LIMIT. */
FOVSDF_API fov_result fovsdf_program_size(const fovsdf_node *nodes, uint32_t count, int32_t root,
                                          size_t *bytes)
{
    size_t n2;
    if (!nodes || !bytes) return FOV_ERR_NULL;
    if (count == 0 || root < 0 || (uint32_t)root >= count) return FOV_ERR_INVALID_ARG;
    if (count > 0x00ffffffu) return FOV_ERR_LIMIT;
    n2 = 2u * (size_t)count;
    *bytes = 16u + fov__align(sizeof(fovsdf__bsph) * n2) + fov__align(sizeof(fovsdf_node) * n2) +
             fov__align(sizeof(int32_t) * (size_t)count) + fov__align((size_t)count) +
             fov__align(sizeof(int32_t) * n2) + fov__align(n2) +
             fov__align(sizeof(fovsdf__ins) * n2 * 3u);
    return FOV_OK;
}

FOVSDF_API size_t fovsdf_program_code_bytes(const fovsdf_program *prog)
{
    if (!prog || !prog->code) return 0;
    return 15u + sizeof(fovsdf__ins) * (size_t)prog->count;
}

FOVSDF_API fov_result fovsdf_program_compact(fovsdf_program *prog, void *dst, size_t bytes)
{
    unsigned char *base;
    const unsigned char *src;
    size_t n, i;
    if (!prog || !dst || !prog->code) return FOV_ERR_NULL;
    if (bytes < fovsdf_program_code_bytes(prog)) return FOV_ERR_TOO_SMALL;
    base = (unsigned char *)dst;
    base += (16u - ((uintptr_t)base & 15u)) & 15u;
    src = (const unsigned char *)prog->code;
    n = sizeof(fovsdf__ins) * (size_t)prog->count;
    if (src < base + n && base < src + n) return FOV_ERR_INVALID_ARG; /* overlapping */
    for (i = 0; i < n; ++i) base[i] = src[i];
    prog->code = base;
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_program_check(const fovsdf_node *nodes, uint32_t count, int32_t root,
                                           const fov_logger *lg)
{
    uint32_t k;
    if (!nodes) FOVSDF__FAIL(lg, FOV_ERR_NULL, "program_check: nodes is NULL");
    if (count == 0 || root < 0 || (uint32_t)root >= count)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "program_check: count must be > 0 and root in [0, count)");
    if (count > 0x00ffffffu)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT, "program_check: more than 2^24 - 1 nodes");
    for (k = 0; k < count; ++k) {
        fov_result r = fovsdf__node_check(&nodes[k], k, count, lg, "program_build");
        if (r != FOV_OK) return r;
    }
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_program_build(fovsdf_program *prog, const fovsdf_node *nodes,
                                           uint32_t count, int32_t root, void *mem, size_t bytes)
{
    size_t need, n2;
    uint32_t n = 0, k, prims = 0, bounds = 0, nn = count;
    fovsdf__bsph *bs;
    fovsdf_node *nd;
    int32_t *leaves, *stk;
    uint8_t *marks, *stage;
    fovsdf__ins *code;
    fov_result r;
    unsigned char *base;
    if (!prog || !nodes || !mem) return FOV_ERR_NULL;
    r = fovsdf_program_size(nodes, count, root, &need);
    if (r != FOV_OK) return r;
    if (bytes < need) return FOV_ERR_TOO_SMALL;
    r = fovsdf_program_check(nodes, count, root, 0);
    if (r != FOV_OK) return r;
    n2 = 2u * (size_t)count;
    base = (unsigned char *)mem;
    base += (16u - ((uintptr_t)base & 15u)) & 15u; /* 16-byte align */
    bs = (fovsdf__bsph *)(void *)base;
    base += fov__align(sizeof(fovsdf__bsph) * n2);
    nd = (fovsdf_node *)(void *)base;
    base += fov__align(sizeof(fovsdf_node) * n2);
    leaves = (int32_t *)(void *)base;
    base += fov__align(sizeof(int32_t) * (size_t)count);
    marks = (uint8_t *)base;
    base += fov__align((size_t)count);
    stk = (int32_t *)(void *)base;
    base += fov__align(sizeof(int32_t) * n2);
    stage = (uint8_t *)base;
    base += fov__align(n2);
    code = (fovsdf__ins *)(void *)base;
    for (k = 0; k < count; ++k) {
        nd[k] = nodes[k];
        /* a hand-made normal of any non-zero length, as the builder's */
        if (nd[k].type == FOVSDF_NODE_PLANE) {
            float l2 = fov__dot(nd[k].f, nd[k].f);
            if (!(l2 > 0.999999f && l2 < 1.000001f)) (void)fovsdf__normalize(nd[k].f);
        }
    }
    r = fovsdf__bounds(nd, count, root, bs, stk, stage);
    if (r != FOV_OK) return r;
    r = fovsdf__rebalance(nd, &nn, (uint32_t)n2, bs, leaves, count, marks, stk, (uint32_t)n2);
    if (r != FOV_OK) return r;
    r = fovsdf__bounds(nd, nn, root, bs, stk, stage);
    if (r != FOV_OK) return r;
    r = fovsdf__compile(nd, root, bs, 0, &n); /* count first */
    if (r != FOV_OK) return r;
    if ((size_t)n > n2 * 3u) return FOV_ERR_TOO_SMALL; /* shared subtrees: more memory */
    r = fovsdf__compile(nd, root, bs, code, &n);
    if (r != FOV_OK) return r;
    for (k = 0; k < n; ++k) {
        if (code[k].op == FOVSDF__OP_PRIM) ++prims;
        if (code[k].op == FOVSDF__OP_BOUND) ++bounds;
    }
    prog->code = code;
    prog->count = n;
    prog->prims = prims;
    prog->bounds = bounds;
    prog->bound_center[0] = bs[root].c[0];
    prog->bound_center[1] = bs[root].c[1];
    prog->bound_center[2] = bs[root].c[2];
    prog->bound_radius = bs[root].r;
    return FOV_OK;
}

/* ---- primitive distance functions (canonical exact forms after Quilez; the thesis's
        Sec. 2.2.1 lists the same set) ------------------------------------------------------ */
FOVSDF__INL float fovsdf__sd_box(float x, float y, float z, float bx, float by, float bz)
{
    float qx = fov__absf(x) - bx, qy = fov__absf(y) - by, qz = fov__absf(z) - bz;
    float o = fovsdf__len3f(fov__maxf(qx, 0.0f), fov__maxf(qy, 0.0f), fov__maxf(qz, 0.0f));
    return o + fov__minf(fov__maxf(qx, fov__maxf(qy, qz)), 0.0f);
}
FOVSDF__INL float fovsdf__sd_frame3(float ax, float ay, float az)
{
    return fovsdf__len3f(fov__maxf(ax, 0.0f), fov__maxf(ay, 0.0f), fov__maxf(az, 0.0f)) +
           fov__minf(fov__maxf(ax, fov__maxf(ay, az)), 0.0f);
}
FOVSDF__PRIV float fovsdf__sd_box_frame(const float p[3], const float *f)
{
    float px = fov__absf(p[0]) - f[0], py = fov__absf(p[1]) - f[1], pz = fov__absf(p[2]) - f[2];
    float e = f[3];
    float qx = fov__absf(px + e) - e, qy = fov__absf(py + e) - e, qz = fov__absf(pz + e) - e;
    return fov__minf(fov__minf(fovsdf__sd_frame3(px, qy, qz), fovsdf__sd_frame3(qx, py, qz)),
                        fovsdf__sd_frame3(qx, qy, pz));
}
FOVSDF__PRIV float fovsdf__sd_capsule(const float p[3], const float *f)
{
    float pa[3], ba[3], h, bb;
    pa[0] = p[0] - f[0]; pa[1] = p[1] - f[1]; pa[2] = p[2] - f[2];
    ba[0] = f[3] - f[0]; ba[1] = f[4] - f[1]; ba[2] = f[5] - f[2];
    bb = fov__dot(ba, ba);
    h = bb > 0.0f ? fovsdf__clampf(fov__dot(pa, ba) / bb, 0.0f, 1.0f) : 0.0f;
    return fovsdf__len3f(pa[0] - ba[0] * h, pa[1] - ba[1] * h, pa[2] - ba[2] * h) - f[6];
}
FOVSDF__PRIV float fovsdf__sd_cone(const float p[3], const float *f)
{
    float h = f[0], r1 = f[1], r2 = f[2];
    float qx = fovsdf__len2f(p[0], p[2]), qy = p[1];
    float k2x = r2 - r1, k2y = 2.0f * h;
    float cax = qx - fov__minf(qx, qy < 0.0f ? r1 : r2), cay = fov__absf(qy) - h;
    float tt =
        fovsdf__clampf(((r2 - qx) * k2x + (h - qy) * k2y) / (k2x * k2x + k2y * k2y), 0.0f, 1.0f);
    float cbx = qx - r2 + k2x * tt, cby = qy - h + k2y * tt;
    float s = (cbx < 0.0f && cay < 0.0f) ? -1.0f : 1.0f;
    return s * FOV__SQRT(fov__minf(cax * cax + cay * cay, cbx * cbx + cby * cby));
}
FOVSDF__PRIV float fovsdf__sd_menger(const float p[3], int32_t iters)
{
    float d = fovsdf__sd_box(p[0], p[1], p[2], 1.0f, 1.0f, 1.0f), s = 1.0f;
    int32_t m;
    /* the crosses are at most 1/3 deep (c <= 1/3 below), so beyond 1 the box alone is the
       result, bit for bit, and p * 3^iters cannot overflow into inf - inf */
    if (!(d <= 1.0f)) return d;
    for (m = 0; m < iters; ++m) {
        float a[3], r[3], da, db, dc, c;
        int k;
        for (k = 0; k < 3; ++k) {
            float v = p[k] * s;
            v = v - 2.0f * FOV__FLOOR(v * 0.5f); /* mod 2 */
            a[k] = v - 1.0f;
            r[k] = fov__absf(1.0f - 3.0f * fov__absf(a[k]));
        }
        s *= 3.0f;
        da = fov__maxf(r[0], r[1]);
        db = fov__maxf(r[1], r[2]);
        dc = fov__maxf(r[2], r[0]);
        c = (fov__minf(da, fov__minf(db, dc)) - 1.0f) / s;
        d = fov__maxf(d, c);
    }
    return d;
}
/* Branch-free selects for the lane loops; the same values as the ternaries, NaN and signed
   zeros included. vmax and vmin are the ternaries themselves (maxps / minps compute exactly
   a > b ? a : b and a < b ? a : b); every helper the lane loops call carries FOVSDF__VEC, or
   gcc would not inline it into them (fovsdf__vabs is fov__absf). */
typedef union fovsdf__fu { float f; uint32_t u; } fovsdf__fu;
FOVSDF__INL FOVSDF__VEC float fovsdf__sel(int c, float a, float b) /* c ? a : b */
{
    fovsdf__fu x, y;
    uint32_t m = 0u - (uint32_t)(c != 0);
    x.f = a; y.f = b;
    x.u = (x.u & m) | (y.u & ~m);
    return x.f;
}
FOVSDF__INL FOVSDF__VEC int32_t fovsdf__seli(int c, int32_t a, int32_t b)
{
    int32_t m = -(int32_t)(c != 0);
    return (a & m) | (b & ~m);
}
FOVSDF__INL FOVSDF__VEC float fovsdf__vmax(float a, float b) { return a > b ? a : b; }
FOVSDF__INL FOVSDF__VEC float fovsdf__vmin(float a, float b) { return a < b ? a : b; }
FOVSDF__INL FOVSDF__VEC float fovsdf__vclamp(float x, float a, float b) /* = fovsdf__clampf */
{
    return fovsdf__sel(x >= a, fovsdf__sel(x > b, b, x), a);
}
FOVSDF__INL FOVSDF__VEC int fovsdf__vfinite(float x) { return (x >= -FLT_MAX) & (x <= FLT_MAX); }
FOVSDF__INL FOVSDF__VEC float fovsdf__vabs(float a) { return a < 0.0f ? -a : a; } /* fov__absf */
/* A primitive's value v at SDF scale sc with fovsdf_program_eval's last resort: NaN becomes
   FLT_MAX (v * 1 is v for every v that is not NaN). */
FOVSDF__INL FOVSDF__VEC float fovsdf__pfin(float v, float sc)
{
    float r = v * sc;
    return fovsdf__sel((r <= 0.0f) | (r > 0.0f), r, FLT_MAX);
}
/* 1 when x is +0 (x - x0 is then x for every x, -0 included) */
FOVSDF__INL FOVSDF__VEC int fovsdf__is_p0(float x)
{
    fovsdf__fu u;
    u.f = x;
    return u.u == 0u;
}
/* FOV__FLOOR(x) without a branch, so the loops vectorise (SSE2 has no floor instruction and
   gcc keeps floorf a call or a branch): |x| < 2^23 is truncated by an integer conversion and
   moved down by one when that rounded up (x < 0 not integral); any larger |x| is integral
   already (as are inf and NaN), and floorf returns it unchanged, so it passes through. libm's
   floorf keeps the sign of x (floor(-0) = -0); FOV_NO_LIBM's fov__floorf gives +0 there, and so
   does this without libm. Math hooks: the hook, lane by lane. */
FOVSDF__INL FOVSDF__VEC float fovsdf__vfloor(float x)
{
#if defined(FOV__HOOKED_MATH)
    return FOV__FLOOR(x);
#else
    fovsdf__fu r;
    int in = (x > -8388608.0f) & (x < 8388608.0f);
    float xi = fovsdf__sel(in, x, 0.0f), c = (float)(int32_t)xi;
#if !defined(FOV_NO_LIBM)
    fovsdf__fu sx;
    sx.f = x;
#endif
    c = fovsdf__sel(c > xi, c - 1.0f, c);
    r.f = fovsdf__sel(in, c, x);
#if !defined(FOV_NO_LIBM)
    r.u |= sx.u & 0x80000000u; /* the result's sign is x's (0 and -1 < x < 0 included) */
#endif
    return r.f;
#endif
}

/* ---- the mandelbulb's and the terrain's math: the library's own float kernels -------------
   sin and cos (fovsdf__ksin, fovsdf__kcos; fovsdf__ksin1: sin for any x), atan2
   (fovsdf__katan2), log (fovsdf__klog) and pow for x > 0 (fovsdf__kpow), without branches
   (selects, integer operations on the bits, no float-to-int conversion of an unbounded value)
   so that the lane loops vectorise. The two primitives use them in fovsdf_program_eval and in
   the batch evaluator alike and with every math configuration (libm, FOV_NO_LIBM, the math
   hooks): their values are the same on every IEEE float target without contraction. Errors
   against double-precision libm (tests/test_fovsdf.c samples them densely; "ulp" is the ulp
   of the exact result):
   - sin, cos: the reduction by multiples of pi/2 (Cody & Waite 1980) in three pieces for
     |x| < 8192 (FOVSDF__KMID), one polynomial for sin on [-pi/2, pi/2]; sin up to 1e6
     (FOVSDF__KBIG) with k and pi/2 in 12-bit pieces (the products exact) and Moshier's
     (1989) polynomials on [-pi/4, pi/4]: at most 4 ulp where the result is at least 2^-10 in
     magnitude, an absolute error below 2^-32 elsewhere. fovsdf__ksin1 reduces any larger
     finite |x| with 96 bits of 2/pi (Payne & Hanek 1983): the same bounds up to FLT_MAX (the
     terrain's octaves, 2.03 times larger each, up to its 1e30 cutoff). inf, NaN: NaN.
   - atan2: at most 3 ulp (the reduction to [0, tan(pi/8)] and Moshier's polynomial); zeros'
     signs and the quadrants as C99's atan2f, atan2(+-inf, +-inf) = +-pi/4 or +-3pi/4, NaN in,
     NaN out.
   - log: at most 1 ulp (fdlibm's logf, Sun Microsystems 1993); log 0 = -inf, log of x < 0 or
     NaN is NaN, log inf = inf.
   - pow(x, y) = 2^(y log2 x) for x > 0 and |y| <= 16: at most 3 ulp where the result is a
     normal float (log2 x as fdlibm's log2f's two parts, y log2 x with Dekker's (1971) exact
     product); 0 or inf beyond float's range.
   The mandelbulb's angles are within 16 pi and its radii in [1e-20, 2] (pow) or positive
   (log); the terrain's arguments are any finite float below its cutoff. */
#define FOVSDF__KMID 8192.0f
#define FOVSDF__KBIG 1e6f
#if defined(__GNUC__) || defined(__clang__) /* too long for gcc's inlining limits otherwise */
#define FOVSDF__KINL FOVSDF__INL __attribute__((always_inline)) FOVSDF__VEC
#else
#define FOVSDF__KINL FOVSDF__INL FOVSDF__VEC
#endif
#define FOVSDF__KRND 12582912.0f /* 1.5 * 2^23: (v + it) - it rounds |v| < 2^22 to an integer */
/* sin r and cos r on [-pi/4, pi/4] (Moshier 1989), then the quadrant q's signs and swap */
FOVSDF__KINL void fovsdf__ksc(float r, uint32_t q, float *s, float *c)
{
    float z = r * r, ps, pc, ss, cc;
    ps = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
    pc = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) *
         z * z - 0.5f * z + 1.0f;
    ss = fovsdf__sel((int)(q & 1u), pc, ps);
    cc = fovsdf__sel((int)(q & 1u), ps, pc);
    *s = fovsdf__sel((int)(q & 2u), -ss, ss);
    *c = fovsdf__sel((int)((q + 1u) & 2u), -cc, cc);
}
/* the same for |x| < FOVSDF__KBIG: x - k pi/2 with k = kh + kl (kh a multiple of 4096,
   |kl| <= 2048) and pi/2 = c1 + c2 + c3 + c4 (12 bits each) + c5: every product k? c? is
   exact */
FOVSDF__KINL void fovsdf__ksincos_w(float x, float *s, float *c)
{
    fovsdf__fu kb;
    int in = fovsdf__vabs(x) < FOVSDF__KBIG, fin = fovsdf__vfinite(x);
    float xs = fovsdf__sel(in, x, 0.0f), k, kh, kl, r, ss, cc, adj;
    kb.f = xs * 0.636619747f + FOVSDF__KRND; /* its low bits: k mod 4 */
    k = kb.f - FOVSDF__KRND;
    kh = ((k * 2.44140625e-4f + FOVSDF__KRND) - FOVSDF__KRND) * 4096.0f;
    kl = k - kh;
    r = xs - kh * 1.57080078f;
    r = r - kl * 1.57080078f;
    r = r - kh * -4.45358455e-6f;
    r = r - kl * -4.45358455e-6f;
    r = r - kh * -8.70613803e-10f;
    r = r - kl * -8.70613803e-10f;
    r = r - kh * 6.22280005e-14f;
    r = r - kl * 6.22280005e-14f;
    r = r - k * 5.72118892e-18f;
    /* k from the rounded x 2/pi can be one off (|x| beyond 2^20): move r back into
       [-pi/4, pi/4] (the products are exact) */
    adj = fovsdf__sel(r > 0.785398185f, 1.0f, fovsdf__sel(r < -0.785398185f, -1.0f, 0.0f));
    r = ((((r - adj * 1.57080078f) - adj * -4.45358455e-6f) - adj * -8.70613803e-10f) -
         adj * 6.22280005e-14f) - adj * 5.72118892e-18f;
    fovsdf__ksc(r, kb.u + (uint32_t)(int32_t)adj, &ss, &cc);
    *s = fovsdf__sel(fin, ss, x - x);
    *c = fovsdf__sel(fin, cc, x - x);
}
/* sin r on [-pi/2, pi/2] (a little beyond): an odd polynomial of degree 11, the Chebyshev
   interpolant of (sin r / r - 1) / r^2 in r^2 (relative error 1.9e-8) */
FOVSDF__KINL float fovsdf__ksinp(float r)
{
    float z = r * r;
    return r + r * z * (-1.666666716e-1f + z * (8.333332837e-3f + z * (-1.984108385e-4f +
                        z * (2.753629815e-6f - z * 2.407637645e-8f))));
}
/* sin x and cos x for |x| < FOVSDF__KMID (beyond: not sin and cos, but finite; inf and NaN
   give NaN): sin x = (-1)^k sin(x - k pi), cos x = (-1)^(k+1) sin(x - (k + 1/2) pi), the
   multiples of pi/2 (2k or 2k + 1, below 2^13) subtracted in three pieces c1 (8 bits) + c2
   (11 bits) + c3 (the products by c1 and c2 exact) */
FOVSDF__KINL float fovsdf__ksin(float x)
{
    fovsdf__fu kb, sb;
    int in = fovsdf__vabs(x) < FOVSDF__KMID, fin = fovsdf__vfinite(x);
    float xs = fovsdf__sel(in, x, 0.0f), m;
    kb.f = xs * 0.318309873f + FOVSDF__KRND; /* k = round(x / pi); its low bit: k's parity */
    m = 2.0f * (kb.f - FOVSDF__KRND);
    sb.f = fovsdf__ksinp(((xs - m * 1.5703125f) - m * 4.83751297e-4f) - m * 7.54979013e-8f);
    sb.u ^= kb.u << 31;
    return fovsdf__sel(fin, sb.f, x - x);
}
FOVSDF__KINL float fovsdf__kcos(float x)
{
    fovsdf__fu kb, sb;
    int in = fovsdf__vabs(x) < FOVSDF__KMID, fin = fovsdf__vfinite(x);
    float xs = fovsdf__sel(in, x, 0.0f), m;
    kb.f = (xs * 0.318309873f - 0.5f) + FOVSDF__KRND; /* k = round(x / pi - 1/2) */
    m = 2.0f * (kb.f - FOVSDF__KRND) + 1.0f;
    sb.f = fovsdf__ksinp(((xs - m * 1.5703125f) - m * 4.83751297e-4f) - m * 7.54979013e-8f);
    sb.u ^= ~kb.u << 31;
    return fovsdf__sel(fin, sb.f, x - x);
}
FOVSDF__KINL float fovsdf__ksin_w(float x) /* |x| < FOVSDF__KBIG */
{
    float s, c;
    fovsdf__ksincos_w(x, &s, &c);
    return s;
}
/* sin x for finite |x| >= FOVSDF__KBIG: |x| = m 2^e (m an integer < 2^24, e >= -4), and
   x 2/pi mod 4 is m times the 96 bits of 2/pi from 2^(1-e) on, mod 2^96 (Payne & Hanek
   1983); the lane loops call it only for such lanes. */
FOVSDF__PRIV float fovsdf__ksin_big(float x)
{
    /* the bits of 2/pi after 32 zero bits (bit t of the table is 2/pi's bit 2^(31 - t)) */
    static const uint32_t tp[9] = { 0x00000000u, 0x517cc1b7u, 0x27220a94u, 0xfe13abe8u,
                                    0xfa9a6ee0u, 0x6db14accu, 0x9e21c820u, 0xff28b1d5u,
                                    0xef5de2b0u };
    fovsdf__fu b, sc;
    uint32_t m, t0, w, sh, wd[3], j, q, t32;
    uint64_t lo, mid, hi, qq, mag;
    int64_t fr;
    float s, c, r;
    b.f = x;
    m = (b.u & 0x007fffffu) | 0x00800000u;
    t0 = ((b.u >> 23) & 0xffu) - 150u + 31u; /* the window's first bit, 2^(1-e) */
    w = t0 >> 5;
    sh = t0 & 31u;
    for (j = 0; j < 3; ++j)
        wd[j] = sh ? (tp[w + j] << sh) | (tp[w + j + 1u] >> (32u - sh)) : tp[w + j];
    lo = (uint64_t)m * wd[2];
    mid = (uint64_t)m * wd[1] + (lo >> 32);
    hi = (uint64_t)m * wd[0] + (mid >> 32);
    qq = (hi << 32) | (mid & 0xffffffffu); /* x 2/pi mod 4 in units of 2^-62 */
    qq += (uint64_t)1 << 61;               /* round to the nearest quadrant */
    q = (uint32_t)(qq >> 62);
    fr = (int64_t)(qq & ((((uint64_t)1) << 62) - 1u)) - ((int64_t)1 << 61);
    /* (float)fr rounded as a conversion would, without a 64-bit conversion (a runtime call
       on 32-bit targets): 32 leading bits with the rest as a sticky bit */
    mag = fr < 0 ? (uint64_t)(-fr) : (uint64_t)fr;
    for (sh = 0; (mag >> sh) > 0xffffffffu; ++sh) {}
    lo = mag >> sh;
    t32 = (uint32_t)lo | (uint32_t)((lo << sh) != mag);
    sc.u = (127u + sh) << 23;
    r = (float)t32 * sc.f;
    fovsdf__ksc((fr < 0 ? -r : r) * 3.40612167e-19f, q, &s, &c); /* 2^-62 pi/2 */
    return x < 0.0f ? -s : s;
}
FOVSDF__PRIV FOVSDF__VEC float fovsdf__ksin1(float x) /* sin x for every x */
{
    float a = fovsdf__vabs(x);
    if (a < FOVSDF__KMID || !fovsdf__vfinite(x)) return fovsdf__ksin(x);
    return a < FOVSDF__KBIG ? fovsdf__ksin_w(x) : fovsdf__ksin_big(x);
}
FOVSDF__KINL float fovsdf__katan2(float y, float x)
{
    fovsdf__fu bx, by;
    float ax = fovsdf__vabs(x), ay = fovsdf__vabs(y), mx, mn, t, u, z, a;
    int sw = ay > ax, hi;
    bx.f = x; by.f = y;
    mx = fovsdf__sel(sw, ay, ax);
    mn = fovsdf__sel(sw, ax, ay);
    t = mn / fovsdf__sel(mx > 0.0f, mx, 1.0f);      /* atan2(0, 0): t = 0 */
    t = fovsdf__sel(mn > FLT_MAX, 1.0f, t);          /* both infinite */
    hi = t > 0.414213562f;                           /* tan(pi/8) */
    u = fovsdf__sel(hi, (t - 1.0f) / (t + 1.0f), t); /* atan t = pi/4 + atan u */
    z = u * u;
    a = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
         3.33329491539e-1f) * z * u + u;
    a = fovsdf__sel(hi, (a + -2.18556950e-8f) + 7.85398185e-1f, a);
    a = fovsdf__sel(sw, (1.57079637f - a) + -4.37113883e-8f, a);
    a = fovsdf__sel((int)(bx.u >> 31), (3.14159274f - a) + -8.74227766e-8f, a);
    return fovsdf__sel((int)(by.u >> 31), -a, a);
}
/* x > 0 finite: x = m 2^e with m in [sqrt(1/2), sqrt(2)) (subnormals too); *e = e */
FOVSDF__KINL float fovsdf__kfrexp(float x, float *e)
{
    fovsdf__fu b;
    int sub = x < 1.17549435e-38f, hi;
    int32_t ei;
    b.f = fovsdf__sel(sub, x * 16777216.0f, x);
    ei = (int32_t)((b.u >> 23) & 0xffu) - fovsdf__seli(sub, 151, 127);
    b.u = (b.u & 0x007fffffu) | 0x3f800000u;
    hi = b.f > 1.41421356f;
    *e = (float)(ei + hi);
    return fovsdf__sel(hi, 0.5f * b.f, b.f);
}
/* log(1 + f) = f - (*h - the return value), *h = f^2 / 2, for f = m - 1 (fdlibm's logf) */
FOVSDF__KINL float fovsdf__klogt(float f, float *h)
{
    float s = f / (2.0f + f), z = s * s, w = z * z;
    float r = z * (6.6666668653e-1f + w * (2.8571429849e-1f + w * (1.8183572590e-1f +
                                                                      w * 1.4798198640e-1f))) +
              w * (4.0000000596e-1f + w * (2.2222198546e-1f + w * 1.5313838422e-1f));
    *h = 0.5f * f * f;
    return s * (*h + r);
}
FOVSDF__KINL float fovsdf__knan(void)
{
    fovsdf__fu b;
    b.u = 0x7fc00000u;
    return b.f;
}
FOVSDF__KINL float fovsdf__klog(float x)
{
    float e, h, f = fovsdf__kfrexp(x, &e) - 1.0f, t = fovsdf__klogt(f, &h), r;
    r = e * 6.9313812256e-1f - ((h - (t + e * 9.0580006145e-6f)) - f); /* ln 2 = hi + lo */
    r = fovsdf__sel(x <= FLT_MAX, r, x);                                /* inf, NaN */
    return fovsdf__sel(x > 0.0f, r,
                       fovsdf__sel((x <= 0.0f) & (x >= 0.0f), -FLT_MAX * 2.0f, fovsdf__knan()));
}
/* a = ah + al with ah of 12 bits (Veltkamp's split, Dekker 1971) */
FOVSDF__KINL float fovsdf__ksplit(float a, float *al)
{
    float c = 4097.0f * a, ah = c - (c - a);
    *al = a - ah;
    return ah;
}
FOVSDF__KINL float fovsdf__kpow(float x, float y) /* x > 0, |y| <= 16 */
{
    fovsdf__fu s1, s2, hb;
    float e, h, f = fovsdf__kfrexp(x, &e) - 1.0f, t = fovsdf__klogt(f, &h), hi, lo, vh, vl;
    float yh, yl, a, n, p, pe, n2, g, n3, q, k, k1, y1, y2, v1, v2;
    /* log2 m = vh + vl (fdlibm's log2f): hi keeps f - h's top 12 bits, vh = hi * 12 bits */
    hb.f = f - h;
    hb.u &= 0xfffff000u;
    hi = hb.f;
    lo = (f - hi) - h + t;
    vh = hi * 1.4428710938f;
    vl = (lo + hi) * -1.7605285393e-4f + lo * 1.4428710938f;
    /* y log2 x = e yh + e yl + y vh + y vl: e yh exact (yh: y to 12 fractional bits), y vh
       as p + pe (Dekker's product); the integer parts n, n2 come off exactly */
    yh = ((y * 4096.0f + FOVSDF__KRND) - FOVSDF__KRND) * 2.44140625e-4f;
    yl = y - yh;
    a = e * yh;
    n = (a + FOVSDF__KRND) - FOVSDF__KRND;
    p = y * vh;
    y1 = fovsdf__ksplit(y, &y2);
    v1 = fovsdf__ksplit(vh, &v2);
    pe = (((y1 * v1 - p) + y1 * v2) + y2 * v1) + y2 * v2;
    n2 = (p + FOVSDF__KRND) - FOVSDF__KRND;
    g = ((a - n) + (p - n2)) + ((pe + e * yl) + y * vl);
    n3 = (g + FOVSDF__KRND) - FOVSDF__KRND;
    g = g - n3; /* |g| <= 1/2: 2^g (Taylor to degree 7) */
    q = 1.0f + g * (6.931471806e-1f + g * (2.402265070e-1f + g * (5.550410866e-2f +
        g * (9.618129108e-3f + g * (1.333355815e-3f + g * (1.540353039e-4f +
        g * 1.525273380e-5f))))));
    k = fovsdf__vclamp((n + n2) + n3, -252.0f, 252.0f);
    k1 = (k * 0.5f + FOVSDF__KRND) - FOVSDF__KRND;
    s1.u = (uint32_t)((int32_t)k1 + 127) << 23;
    s2.u = (uint32_t)((int32_t)(k - k1) + 127) << 23;
    return q * s1.f * s2.f;
}
/* The mandelbulb and the terrain with the kernels above; fovsdf__prim_lanes computes the
   same values over the lanes. */
FOVSDF__PRIV FOVSDF__VEC float fovsdf__sd_mandelbulb(const float p[3], float power,
                                                     int32_t iters)
{
    float z[3], dr = 1.0f, r;
    int32_t i;
    z[0] = p[0]; z[1] = p[1]; z[2] = p[2];
    r = fov__len(z);
    for (i = 0; i < iters && r <= 2.0f; ++i) {
        float th, ph, zr, st, ct, sp, cp;
        if (r < 1e-20f) { dr = 1.0f; break; }
        th = fovsdf__katan2(fovsdf__len2f(z[0], z[1]), z[2]) * power;
        ph = fovsdf__katan2(z[1], z[0]) * power;
        zr = fovsdf__kpow(r, power - 1.0f);
        dr = power * zr * dr + 1.0f;
        zr *= r;
        st = fovsdf__ksin(th); ct = fovsdf__kcos(th);
        sp = fovsdf__ksin(ph); cp = fovsdf__kcos(ph);
        z[0] = zr * st * cp + p[0];
        z[1] = zr * st * sp + p[1];
        z[2] = zr * ct + p[2];
        r = fov__len(z);
    }
    if (r < 1e-20f) return 0.0f;
    return 0.5f * fovsdf__klog(r) * r / dr;
}
FOVSDF__PRIV FOVSDF__VEC float fovsdf__terrain_h(float x, float z, const float *f, int32_t oct)
{
    float h = 0.0f, w = 1.0f, fx = x * f[1], fz = z * f[1];
    int32_t o;
    for (o = 0; o < oct; ++o) {
        float nx;
        /* beyond 1e30 (not finite soon after) the octaves are float noise: stop, never NaN */
        if (!(fov__absf(fx) < 1e30f && fov__absf(fz) < 1e30f)) break;
        h += w * fovsdf__ksin1(fx) * fovsdf__ksin1(fz);
        nx = (0.8f * fx - 0.6f * fz) * 2.03f; /* rotate and scale each octave */
        fz = (0.6f * fx + 0.8f * fz) * 2.03f;
        fx = nx;
        w *= 0.5f;
    }
    return h * f[0];
}

FOVSDF__PRIV float fovsdf__prim(const fovsdf__ins *in, const float p[3])
{
    const float *f = in->f;
    switch (in->sub) {
    case FOVSDF_NODE_SPHERE: return fov__len(p) - f[0];
    case FOVSDF_NODE_BOX: return fovsdf__sd_box(p[0], p[1], p[2], f[0], f[1], f[2]);
    case FOVSDF_NODE_ROUND_BOX:
        return fovsdf__sd_box(p[0], p[1], p[2], f[0] - f[3], f[1] - f[3], f[2] - f[3]) - f[3];
    case FOVSDF_NODE_BOX_FRAME: return fovsdf__sd_box_frame(p, f);
    case FOVSDF_NODE_TORUS: return fovsdf__len2f(fovsdf__len2f(p[0], p[2]) - f[0], p[1]) - f[1];
    case FOVSDF_NODE_CAPSULE: return fovsdf__sd_capsule(p, f);
    case FOVSDF_NODE_CYLINDER: {
        float dx = fovsdf__len2f(p[0], p[2]) - f[1], dy = fov__absf(p[1]) - f[0];
        return fov__minf(fov__maxf(dx, dy), 0.0f) +
            fovsdf__len2f(fov__maxf(dx, 0.0f), fov__maxf(dy, 0.0f));
    }
    case FOVSDF_NODE_CONE: return fovsdf__sd_cone(p, f);
    case FOVSDF_NODE_PLANE: return fov__dot(p, f) + f[3];
    case FOVSDF_NODE_MENGER: {
        float q[3];
        q[0] = p[0] / f[0]; q[1] = p[1] / f[0]; q[2] = p[2] / f[0];
        return fovsdf__sd_menger(q, in->i[0]) * f[0];
    }
    case FOVSDF_NODE_MANDELBULB: return fovsdf__sd_mandelbulb(p, f[0], in->i[0]);
    case FOVSDF_NODE_TERRAIN: return (p[1] - fovsdf__terrain_h(p[0], p[2], f, in->i[0])) * f[2];
    default: return FLT_MAX;
    }
}

FOVSDF_API float fovsdf_program_eval(const float p_in[3], fovsdf_query *q, void *user)
{
    const fovsdf_program *prog = (const fovsdf_program *)user;
    const fovsdf__ins *code;
    float vs[FOVSDF_MAX_STACK];
    int32_t ms[FOVSDF_MAX_STACK];
    float ps[FOVSDF_MAX_STACK][3];
    float p[3], inflate = 1.0f, eps = 0.0f;
    int32_t vsp = 0, psp = 0;
    uint32_t pc = 0, n, prims = 0, skipped = 0;
    if (!prog || !prog->code || prog->count == 0 || !p_in) return FLT_MAX;
    code = (const fovsdf__ins *)prog->code;
    n = prog->count;
    p[0] = p_in[0]; p[1] = p_in[1]; p[2] = p_in[2];
    if (q) {
        inflate = (q->inflate > 0.0f && fov__finite(q->inflate)) ? q->inflate : 1.0f;
        eps = q->eps;
    }
    while (pc < n) {
        const fovsdf__ins *in = &code[pc];
        switch (in->op) {
        case FOVSDF__OP_PRIM: {
            float d;
            /* Skipping Spheres: Scale(p) = f(p / s) * s about the primitive's origin */
            if (inflate < 1.0f || inflate > 1.0f) {
                float s = (in->flags & FOVSDF__FLAG_DEFLATE) ? 1.0f / inflate : inflate, qp[3];
                qp[0] = p[0] / s; qp[1] = p[1] / s; qp[2] = p[2] / s;
                d = fovsdf__prim(in, qp) * s;
            } else {
                d = fovsdf__prim(in, p);
            }
            /* last resort (no finite point reaches it in the envelope) */
            if (fov__isnan(d)) d = FLT_MAX;
            vs[vsp] = d;
            ms[vsp] = in->material;
            ++vsp;
            ++prims;
            ++pc;
            break;
        }
        case FOVSDF__OP_BIN: {
            float b = vs[--vsp], a = vs[vsp - 1], k = in->f[0], h, r;
            int32_t mb = ms[vsp], ma = ms[vsp - 1], m = ma;
            uint32_t sub = in->sub;
            /* an infinite operand (a point far beyond float's range of a subtree) makes the
               blend inf - inf: take the plain operator, its limit */
            if (!fov__finite(a) || !fov__finite(b)) {
                if (sub == FOVSDF_NODE_SMOOTH_UNION) sub = FOVSDF_NODE_UNION;
                else if (sub == FOVSDF_NODE_SMOOTH_SUBTRACT) sub = FOVSDF_NODE_SUBTRACT;
                else if (sub == FOVSDF_NODE_SMOOTH_INTERSECT) sub = FOVSDF_NODE_INTERSECT;
            }
            switch (sub) {
            case FOVSDF_NODE_UNION: r = a < b ? a : b; m = a < b ? ma : mb; break;
            case FOVSDF_NODE_SUBTRACT: r = a > -b ? a : -b; m = a > -b ? ma : mb; break;
            case FOVSDF_NODE_INTERSECT: r = a > b ? a : b; m = a > b ? ma : mb; break;
            case FOVSDF_NODE_SMOOTH_UNION:
                h = fovsdf__clampf(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
                r = b + (a - b) * h - k * h * (1.0f - h); m = h > 0.5f ? ma : mb; break;
            case FOVSDF_NODE_SMOOTH_SUBTRACT:
                h = fovsdf__clampf(0.5f - 0.5f * (a + b) / k, 0.0f, 1.0f);
                r = a + (-b - a) * h + k * h * (1.0f - h); m = h > 0.5f ? mb : ma; break;
            default: /* smooth intersection */
                h = fovsdf__clampf(0.5f - 0.5f * (b - a) / k, 0.0f, 1.0f);
                r = b + (a - b) * h + k * h * (1.0f - h); m = h > 0.5f ? ma : mb; break;
            }
            vs[vsp - 1] = r;
            ms[vsp - 1] = m;
            ++pc;
            break;
        }
        case FOVSDF__OP_UNARY:
            if (in->sub == FOVSDF_NODE_ROUND) vs[vsp - 1] -= in->f[0];
            else if (in->sub == FOVSDF_NODE_ONION) vs[vsp - 1] = fov__absf(vs[vsp - 1]) - in->f[0];
            else skipped += (uint32_t)in->i[0]; /* CNT (pruned programs) */
            ++pc;
            break;
        case FOVSDF__OP_PUSHP: {
            const float *f = in->f;
            int k;
            ps[psp][0] = p[0]; ps[psp][1] = p[1]; ps[psp][2] = p[2];
            ++psp;
            switch (in->sub) {
            case FOVSDF_NODE_TRANSLATE: p[0] -= f[0]; p[1] -= f[1]; p[2] -= f[2]; break;
            case FOVSDF_NODE_ROTATE: {
                float x = p[0], y = p[1], z = p[2]; /* world -> object: R^T p */
                p[0] = f[0] * x + f[3] * y + f[6] * z;
                p[1] = f[1] * x + f[4] * y + f[7] * z;
                p[2] = f[2] * x + f[5] * y + f[8] * z;
                break;
            }
            case FOVSDF_NODE_SCALE: p[0] /= f[0]; p[1] /= f[0]; p[2] /= f[0]; break;
            case FOVSDF_NODE_REPEAT:
                for (k = 0; k < 3; ++k) {
                    if (f[k] > 0.0f) {
                        float c = FOV__FLOOR(p[k] / f[k] + 0.5f);
                        /* |p| / period beyond float: no fold, never inf - inf */
                        if (!fov__finite(c)) c = 0.0f;
                        if (in->i[k] > 0) c = fovsdf__clampf(c, -(float)in->i[k], (float)in->i[k]);
                        p[k] -= f[k] * c;
                    }
                }
                break;
            default: /* mirror */
                for (k = 0; k < 3; ++k) if (in->i[0] & (1 << k)) p[k] = fov__absf(p[k]);
                break;
            }
            ++pc;
            break;
        }
        case FOVSDF__OP_POPP:
            --psp;
            p[0] = ps[psp][0]; p[1] = ps[psp][1]; p[2] = ps[psp][2];
            vs[vsp - 1] *= in->f[0];
            ++pc;
            break;
        default: { /* BOUND */
            const float *f = in->f;
            float dx = p[0] - f[0], dy = p[1] - f[1], dz = p[2] - f[2],
                d2 = dx * dx + dy * dy + dz * dz;
            /* margin r/4 + band + 4 eps (a negative eps, from the shadow proofs, shrinks it to
               at most 0: the bound's value wherever the point is off its centre) */
            float lim = fov__maxf(1.25f * f[3] + f[4] + 4.0f * eps, 0.0f);
            /* With inflation each primitive grows about its own origin, which a bound of the
               exact scene does not cover: evaluate everything then. */
            if (!(inflate < 1.0f || inflate > 1.0f) && d2 > lim * lim) {
                vs[vsp] = FOV__SQRT(d2) - f[3];
                ms[vsp] = -1;
                ++vsp;
                skipped += (uint32_t)in->i[0];
                pc = in->jump;
            } else {
                ++pc;
            }
            break;
        }
        }
    }
    if (q) {
        q->prims += prims;
        q->prims_skipped += skipped;
        q->material = vsp > 0 ? ms[0] : -1;
    }
    /* finite always: +-inf (a point whose distance is beyond float) becomes +-FLT_MAX */
    return vsp > 0 ? (fov__isnan(vs[0]) ? FLT_MAX : fovsdf__clampf(vs[0], -FLT_MAX, FLT_MAX))
        : FLT_MAX;
}

/* ---- the batch evaluator: fovsdf_program_eval over a batch, instruction by instruction ------
   Every lane computes exactly what fovsdf_program_eval computes for its point (the same float
   operations in the same order), so a batch never changes a value. Bounds: a lane whose test
   says "skip" takes the bound's value; the subtree runs when at least one active lane needs
   it, and at its end the skipping lanes get the bound's value back (a pending record); lanes
   that an outer record already decided are inactive and do not count. */
#define FOVSDF__BREC 16 /* pending bounds at once; a batch that needs more goes point by point */
typedef struct fovsdf__bscr {
    float vs[FOVSDF_MAX_STACK][FOVSDF__L];
    int32_t ms[FOVSDF_MAX_STACK][FOVSDF__L];
    /* the point stack: a transform writes the axes it changes into the next level's storage
       and points the others at its parent's (no copies; popping just drops the level);
       level 0 is the batch's own arrays when the batch fills every lane */
    float ps[FOVSDF_MAX_STACK + 1][3][FOVSDF__L];
    const float *pp[FOVSDF_MAX_STACK + 1][3];
    float q[3][FOVSDF__L], w[5][FOVSDF__L]; /* scaled points, primitive scratch */
    float e4[FOVSDF__L];                         /* 4 eps per lane (the bound's margin) */
    float bv[FOVSDF__BREC][FOVSDF__L];       /* pending bounds: the bound's value */
    int32_t bm[FOVSDF__BREC][FOVSDF__L];     /* 1: the lane takes it */
    int32_t act[FOVSDF__BREC + 1][FOVSDF__L]; /* active lanes (1) per nesting level */
    uint32_t bj[FOVSDF__BREC], bslot[FOVSDF__BREC], nact[FOVSDF__BREC + 1];
} fovsdf__bscr;

/* v[i] = sqrt(v[i]) over the lanes, exactly FOV__SQRT's value. */
FOVSDF__INL FOVSDF__VEC void fovsdf__sqrt_lanes(float *v)
{
    uint32_t i;
#if defined(FOVSDF__SQRT_AVX)
    for (i = 0; i < FOVSDF__L; i += 8)
        _mm256_storeu_ps(v + i, _mm256_sqrt_ps(_mm256_loadu_ps(v + i)));
#elif defined(FOVSDF__SQRT_SSE)
    for (i = 0; i < FOVSDF__L; i += 4)
        _mm_storeu_ps(v + i, _mm_sqrt_ps(_mm_loadu_ps(v + i)));
#elif defined(FOVSDF__SQRT_WASM)
    for (i = 0; i < FOVSDF__L; i += 4)
        wasm_v128_store(v + i, wasm_f32x4_sqrt(wasm_v128_load(v + i)));
#elif defined(FOVSDF__SQRT_NEON)
    for (i = 0; i < FOVSDF__L; i += 4) vst1q_f32(v + i, vsqrtq_f32(vld1q_f32(v + i)));
#else
    for (i = 0; i < FOVSDF__L; ++i) v[i] = FOV__SQRT(v[i]);
#endif
}

/* One primitive over the lanes at (x, y, z) into d, times sc, NaN made FLT_MAX (fovsdf__pfin),
   with the float operations of fovsdf__prim in its order; w: five scratch lanes. Every
   primitive runs vectorised (the mandelbulb and the terrain with the library's own kernels;
   a terrain lane whose argument is beyond FOVSDF__KBIG takes fovsdf__ksin1 one by one). */
FOVSDF__PRIV FOVSDF__VEC void
fovsdf__prim_lanes(const fovsdf__ins *in, const float *FOVSDF__RESTRICT x,
                   const float *FOVSDF__RESTRICT y, const float *FOVSDF__RESTRICT z,
                   float *FOVSDF__RESTRICT d, float sc, float (*w)[FOVSDF__L])
{
    const float *f = in->f;
    const uint32_t n = FOVSDF__L; /* a constant trip count: the loops vectorise at -O2 */
    float *FOVSDF__RESTRICT t = w[0], *FOVSDF__RESTRICT u = w[1];
    uint32_t i;
    switch (in->sub) {
    case FOVSDF_NODE_SPHERE: {
        float r = f[0];
        for (i = 0; i < n; ++i) t[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin(t[i] - r, sc);
        break;
    }
    case FOVSDF_NODE_BOX:
    case FOVSDF_NODE_ROUND_BOX: {
        int rb = in->sub == FOVSDF_NODE_ROUND_BOX;
        float r = rb ? f[3] : 0.0f;
        float bx = rb ? f[0] - f[3] : f[0], by = rb ? f[1] - f[3] : f[1],
              bz = rb ? f[2] - f[3] : f[2];
        for (i = 0; i < n; ++i) {
            float qx = fovsdf__vmax(fovsdf__vabs(x[i]) - bx, 0.0f);
            float qy = fovsdf__vmax(fovsdf__vabs(y[i]) - by, 0.0f);
            float qz = fovsdf__vmax(fovsdf__vabs(z[i]) - bz, 0.0f);
            t[i] = qx * qx + qy * qy + qz * qz;
        }
        fovsdf__sqrt_lanes(t);
        if (rb) {
            for (i = 0; i < n; ++i) {
                float qx = fovsdf__vabs(x[i]) - bx, qy = fovsdf__vabs(y[i]) - by,
                      qz = fovsdf__vabs(z[i]) - bz;
                float o = t[i] + fovsdf__vmin(fovsdf__vmax(qx, fovsdf__vmax(qy, qz)), 0.0f);
                d[i] = fovsdf__pfin(o - r, sc);
            }
        } else {
            for (i = 0; i < n; ++i) {
                float qx = fovsdf__vabs(x[i]) - bx, qy = fovsdf__vabs(y[i]) - by,
                      qz = fovsdf__vabs(z[i]) - bz;
                float o = t[i] + fovsdf__vmin(fovsdf__vmax(qx, fovsdf__vmax(qy, qz)), 0.0f);
                d[i] = fovsdf__pfin(o, sc);
            }
        }
        break;
    }
    case FOVSDF_NODE_BOX_FRAME: { /* fovsdf__sd_box_frame: three frame3 terms */
        float *FOVSDF__RESTRICT t2 = w[2], *FOVSDF__RESTRICT t3 = w[3];
        float ax = f[0], ay = f[1], az = f[2], e = f[3];
        for (i = 0; i < n; ++i) {
            float px = fovsdf__vabs(x[i]) - ax, py = fovsdf__vabs(y[i]) - ay,
                  pz = fovsdf__vabs(z[i]) - az;
            float qx = fovsdf__vabs(px + e) - e, qy = fovsdf__vabs(py + e) - e,
                  qz = fovsdf__vabs(pz + e) - e;
            float mpx = fovsdf__vmax(px, 0.0f), mpy = fovsdf__vmax(py, 0.0f),
                  mpz = fovsdf__vmax(pz, 0.0f);
            float mqx = fovsdf__vmax(qx, 0.0f), mqy = fovsdf__vmax(qy, 0.0f),
                  mqz = fovsdf__vmax(qz, 0.0f);
            t[i] = mpx * mpx + mqy * mqy + mqz * mqz;
            t2[i] = mqx * mqx + mpy * mpy + mqz * mqz;
            t3[i] = mqx * mqx + mqy * mqy + mpz * mpz;
        }
        fovsdf__sqrt_lanes(t);
        fovsdf__sqrt_lanes(t2);
        fovsdf__sqrt_lanes(t3);
        for (i = 0; i < n; ++i) {
            float px = fovsdf__vabs(x[i]) - ax, py = fovsdf__vabs(y[i]) - ay,
                  pz = fovsdf__vabs(z[i]) - az;
            float qx = fovsdf__vabs(px + e) - e, qy = fovsdf__vabs(py + e) - e,
                  qz = fovsdf__vabs(pz + e) - e;
            float r1 = t[i] + fovsdf__vmin(fovsdf__vmax(px, fovsdf__vmax(qy, qz)), 0.0f);
            float r2 = t2[i] + fovsdf__vmin(fovsdf__vmax(qx, fovsdf__vmax(py, qz)), 0.0f);
            float r3 = t3[i] + fovsdf__vmin(fovsdf__vmax(qx, fovsdf__vmax(qy, pz)), 0.0f);
            d[i] = fovsdf__pfin(fovsdf__vmin(fovsdf__vmin(r1, r2), r3), sc);
        }
        break;
    }
    case FOVSDF_NODE_TORUS: {
        float r0 = f[0], r1 = f[1];
        for (i = 0; i < n; ++i) t[i] = x[i] * x[i] + z[i] * z[i];
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) {
            float a = t[i] - r0;
            t[i] = a * a + y[i] * y[i];
        }
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin(t[i] - r1, sc);
        break;
    }
    case FOVSDF_NODE_CYLINDER: {
        float h = f[0], r = f[1];
        for (i = 0; i < n; ++i) t[i] = x[i] * x[i] + z[i] * z[i];
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) {
            float dx = t[i] - r, dy = fovsdf__vabs(y[i]) - h;
            float mx = fovsdf__vmax(dx, 0.0f), my = fovsdf__vmax(dy, 0.0f);
            u[i] = fovsdf__vmin(fovsdf__vmax(dx, dy), 0.0f);
            t[i] = mx * mx + my * my;
        }
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin(u[i] + t[i], sc);
        break;
    }
    case FOVSDF_NODE_CAPSULE: {
        float bax = f[3] - f[0], bay = f[4] - f[1], baz = f[5] - f[2];
        float bb = bax * bax + bay * bay + baz * baz, ox = f[0], oy = f[1], oz = f[2];
        float r = f[6];
        for (i = 0; i < n; ++i) {
            float pax = x[i] - ox, pay = y[i] - oy, paz = z[i] - oz, h, ex, ey, ez;
            h = fovsdf__sel(bb > 0.0f,
                            fovsdf__vclamp((pax * bax + pay * bay + paz * baz) / bb, 0.0f, 1.0f),
                            0.0f);
            ex = pax - bax * h; ey = pay - bay * h; ez = paz - baz * h;
            t[i] = ex * ex + ey * ey + ez * ez;
        }
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin(t[i] - r, sc);
        break;
    }
    case FOVSDF_NODE_CONE: { /* fovsdf__sd_cone */
        float h = f[0], r1 = f[1], r2 = f[2];
        float k2x = r2 - r1, k2y = 2.0f * h;
        float kk = k2x * k2x + k2y * k2y;
        for (i = 0; i < n; ++i) t[i] = x[i] * x[i] + z[i] * z[i];
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) {
            float qx = t[i], qy = y[i];
            float cax = qx - fovsdf__vmin(qx, fovsdf__sel(qy < 0.0f, r1, r2)),
                  cay = fovsdf__vabs(qy) - h;
            float tt = fovsdf__vclamp(((r2 - qx) * k2x + (h - qy) * k2y) / kk, 0.0f, 1.0f);
            float cbx = qx - r2 + k2x * tt, cby = qy - h + k2y * tt;
            u[i] = fovsdf__sel((cbx < 0.0f) & (cay < 0.0f), -1.0f, 1.0f);
            t[i] = fovsdf__vmin(cax * cax + cay * cay, cbx * cbx + cby * cby);
        }
        fovsdf__sqrt_lanes(t);
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin(u[i] * t[i], sc);
        break;
    }
    case FOVSDF_NODE_PLANE: {
        float a = f[0], b = f[1], c = f[2], e = f[3];
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin(x[i] * a + y[i] * b + z[i] * c + e, sc);
        break;
    }
    case FOVSDF_NODE_MENGER: { /* fovsdf__sd_menger at p / f[0], times f[0] */
        float *FOVSDF__RESTRICT qx = w[0], *FOVSDF__RESTRICT qy = w[1],
              *FOVSDF__RESTRICT qz = w[2], *FOVSDF__RESTRICT d0 = w[3],
              *FOVSDF__RESTRICT dm = w[4];
        float s0 = f[0], s = 1.0f;
        int32_t m, it = in->i[0];
        for (i = 0; i < n; ++i) {
            float ax, ay, az;
            qx[i] = x[i] / s0; qy[i] = y[i] / s0; qz[i] = z[i] / s0;
            ax = fovsdf__vmax(fovsdf__vabs(qx[i]) - 1.0f, 0.0f);
            ay = fovsdf__vmax(fovsdf__vabs(qy[i]) - 1.0f, 0.0f);
            az = fovsdf__vmax(fovsdf__vabs(qz[i]) - 1.0f, 0.0f);
            d0[i] = ax * ax + ay * ay + az * az;
        }
        fovsdf__sqrt_lanes(d0);
        for (i = 0; i < n; ++i) {
            float ax = fovsdf__vabs(qx[i]) - 1.0f, ay = fovsdf__vabs(qy[i]) - 1.0f,
                  az = fovsdf__vabs(qz[i]) - 1.0f;
            d0[i] = d0[i] + fovsdf__vmin(fovsdf__vmax(ax, fovsdf__vmax(ay, az)), 0.0f);
            dm[i] = d0[i];
        }
        /* every lane runs the iterations; those whose box distance is beyond 1 (the scalar
           returns the box there) take d0 below */
        for (m = 0; m < it; ++m) {
            float s3 = s * 3.0f;
            for (i = 0; i < n; ++i) {
                float vx = qx[i] * s, vy = qy[i] * s, vz = qz[i] * s, rx, ry, rz, c;
                vx = vx - 2.0f * fovsdf__vfloor(vx * 0.5f);
                vy = vy - 2.0f * fovsdf__vfloor(vy * 0.5f);
                vz = vz - 2.0f * fovsdf__vfloor(vz * 0.5f);
                rx = fovsdf__vabs(1.0f - 3.0f * fovsdf__vabs(vx - 1.0f));
                ry = fovsdf__vabs(1.0f - 3.0f * fovsdf__vabs(vy - 1.0f));
                rz = fovsdf__vabs(1.0f - 3.0f * fovsdf__vabs(vz - 1.0f));
                c = (fovsdf__vmin(fovsdf__vmax(rx, ry),
                                  fovsdf__vmin(fovsdf__vmax(ry, rz), fovsdf__vmax(rz, rx))) -
                     1.0f) / s3;
                dm[i] = fovsdf__vmax(dm[i], c);
            }
            s = s3;
        }
        for (i = 0; i < n; ++i)
            d[i] = fovsdf__pfin(fovsdf__sel(d0[i] <= 1.0f, dm[i], d0[i]) * s0, sc);
        break;
    }
    case FOVSDF_NODE_MANDELBULB: { /* fovsdf__sd_mandelbulb, lane by lane the same values */
        /* The lanes still iterating (r <= 2, r >= 1e-20) are packed into the first cnt slots
           of c* (lane ix[k]); each iteration runs over them alone (rounded up to 4: the
           slots past cnt compute values nobody reads) and drops the lanes that stopped. A
           lane's R and DR are its r and dr. */
        float *FOVSDF__RESTRICT R = t, *FOVSDF__RESTRICT DR = u;
        float cx[FOVSDF__L], cy[FOVSDF__L], cz[FOVSDF__L], zx[FOVSDF__L], zy[FOVSDF__L];
        float zz[FOVSDF__L], cdr[FOVSDF__L], cr[FOVSDF__L], cq[FOVSDF__L];
        uint32_t ix[FOVSDF__L], cnt = 0, k, j, cn4;
        float pw = f[0], pm = f[0] - 1.0f;
        int32_t m, it = in->i[0];
        for (i = 0; i < n; ++i) {
            R[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
            DR[i] = 1.0f;
            cx[i] = cy[i] = cz[i] = zx[i] = zy[i] = zz[i] = cr[i] = cq[i] = 0.0f;
            cdr[i] = 1.0f; /* (fovsdf__sqrt_lanes(cq) reads every lane) */
        }
        fovsdf__sqrt_lanes(R);
        for (i = 0; i < n; ++i) {
            if (R[i] <= 2.0f && !(R[i] < 1e-20f)) {
                cx[cnt] = zx[cnt] = x[i]; cy[cnt] = zy[cnt] = y[i]; cz[cnt] = zz[cnt] = z[i];
                cr[cnt] = R[i]; ix[cnt++] = i;
            }
        }
        for (m = 0; m < it && cnt > 0; ++m) {
            cn4 = (cnt + 3u) & ~3u;
            for (k = 0; k < cn4; ++k) cq[k] = zx[k] * zx[k] + zy[k] * zy[k];
            fovsdf__sqrt_lanes(cq);
            for (k = 0; k < cn4; ++k) {
                float th = fovsdf__katan2(cq[k], zz[k]) * pw;
                float ph = fovsdf__katan2(zy[k], zx[k]) * pw;
                float zr = fovsdf__kpow(cr[k], pm), st, ct, sp, cp;
                cdr[k] = pw * zr * cdr[k] + 1.0f;
                zr *= cr[k];
                st = fovsdf__ksin(th); ct = fovsdf__kcos(th);
                sp = fovsdf__ksin(ph); cp = fovsdf__kcos(ph);
                zx[k] = zr * st * cp + cx[k];
                zy[k] = zr * st * sp + cy[k];
                zz[k] = zr * ct + cz[k];
                cq[k] = zx[k] * zx[k] + zy[k] * zy[k] + zz[k] * zz[k];
            }
            fovsdf__sqrt_lanes(cq);
            for (k = 0, j = 0; k < cnt; ++k) {
                float rk = cq[k];
                R[ix[k]] = rk;
                DR[ix[k]] = cdr[k]; /* (at r < 1e-20 the distance is 0, whatever dr) */
                if (rk <= 2.0f && !(rk < 1e-20f)) { /* iterates on: to slot j */
                    cx[j] = cx[k]; cy[j] = cy[k]; cz[j] = cz[k];
                    zx[j] = zx[k]; zy[j] = zy[k]; zz[j] = zz[k];
                    cdr[j] = cdr[k]; cr[j] = rk; ix[j++] = ix[k];
                }
            }
            cnt = j;
        }
        for (i = 0; i < n; ++i)
            d[i] = fovsdf__pfin(fovsdf__sel(R[i] < 1e-20f, 0.0f,
                                            0.5f * fovsdf__klog(R[i]) * R[i] / DR[i]), sc);
        break;
    }
    case FOVSDF_NODE_TERRAIN: { /* fovsdf__terrain_h: a lane past the 1e30 cutoff stops */
        float *FOVSDF__RESTRICT fx = w[2], *FOVSDF__RESTRICT fz = w[3], *FOVSDF__RESTRICT h = w[4];
        float *FOVSDF__RESTRICT s2 = d; /* scratch until the end */
        float fr = f[1], wo = 1.0f;
        int32_t o, oct = in->i[0], big;
        for (i = 0; i < n; ++i) {
            fx[i] = x[i] * fr; fz[i] = z[i] * fr; h[i] = 0.0f;
            u[i] = 1.0f; /* 1: the lane still adds octaves */
        }
        for (o = 0; o < oct; ++o) {
            big = 0;
            for (i = 0; i < n; ++i) {
                float ax = fovsdf__vabs(fx[i]), az = fovsdf__vabs(fz[i]);
                int live = (u[i] > 0.0f) & (ax < 1e30f) & (az < 1e30f);
                t[i] = fovsdf__ksin(fx[i]);
                s2[i] = fovsdf__ksin(fz[i]);
                big |= live & ((ax >= FOVSDF__KMID) | (az >= FOVSDF__KMID));
                u[i] = fovsdf__sel(live, 1.0f, 0.0f);
            }
            if (big) { /* fovsdf__ksin1's choice per lane: the wide reduction, then beyond it
                          Payne-Hanek one by one */
                big = 0;
                for (i = 0; i < n; ++i) {
                    float ax = fovsdf__vabs(fx[i]), az = fovsdf__vabs(fz[i]);
                    t[i] = fovsdf__sel(ax >= FOVSDF__KMID, fovsdf__ksin_w(fx[i]), t[i]);
                    s2[i] = fovsdf__sel(az >= FOVSDF__KMID, fovsdf__ksin_w(fz[i]), s2[i]);
                    big |= (u[i] > 0.0f) & ((ax >= FOVSDF__KBIG) | (az >= FOVSDF__KBIG));
                }
            }
            if (big) {
                for (i = 0; i < n; ++i) {
                    if (u[i] > 0.0f) {
                        t[i] = fovsdf__ksin1(fx[i]);
                        s2[i] = fovsdf__ksin1(fz[i]);
                    }
                }
            }
            for (i = 0; i < n; ++i) {
                float nx = (0.8f * fx[i] - 0.6f * fz[i]) * 2.03f;
                h[i] = fovsdf__sel(u[i] > 0.0f, h[i] + wo * t[i] * s2[i], h[i]);
                fz[i] = (0.6f * fx[i] + 0.8f * fz[i]) * 2.03f;
                fx[i] = nx;
            }
            wo *= 0.5f;
        }
        for (i = 0; i < n; ++i) d[i] = fovsdf__pfin((y[i] - h[i] * f[0]) * f[2], sc);
        break;
    }
    default:
        for (i = 0; i < n; ++i) {
            float p[3];
            p[0] = x[i]; p[1] = y[i]; p[2] = z[i];
            d[i] = fovsdf__pfin(fovsdf__prim(in, p), sc);
        }
        break;
    }
}

/* One blend over the lanes A = A op B (materials MA, MB when wm): BODY sets r, the value, and
   ta, 1 when A's material wins, from the operands a and c (no top-level commas in BODY). */
#define FOVSDF__BLEND(BODY)                                                                   \
    do {                                                                                       \
        if (wm) {                                                                              \
            for (i = 0; i < n; ++i) {                                                          \
                float a = A[i], c = B[i], r;                                                   \
                int ta;                                                                        \
                BODY                                                                           \
                A[i] = r;                                                                      \
                MA[i] = fovsdf__seli(ta, MA[i], MB[i]);                                        \
            }                                                                                  \
        } else {                                                                               \
            for (i = 0; i < n; ++i) {                                                          \
                float a = A[i], c = B[i], r;                                                   \
                int ta;                                                                        \
                BODY                                                                           \
                A[i] = r;                                                                      \
                (void)ta;                                                                      \
            }                                                                                  \
        }                                                                                      \
    } while (0)

/* nb <= FOVSDF_BATCH points starting at point k0 of b. Every loop runs over all FOVSDF__L
   lanes through restrict pointers (a constant trip count and no aliasing: compilers vectorise
   them at -O2); lanes past nb repeat the last point and are inactive. Materials are tracked
   only when b->material asks for them. */
FOVSDF__PRIV FOVSDF__VEC int fovsdf__eval_lanes(const fovsdf_program *prog, fovsdf_batch *b,
                                                uint32_t k0, uint32_t nb, fovsdf__bscr *s)
{
    const fovsdf__ins *code = (const fovsdf__ins *)prog->code;
    const uint32_t n = FOVSDF__L;
    float inflate = (b->inflate > 0.0f && fovsdf__vfinite(b->inflate)) ? b->inflate : 1.0f;
    int scaled = inflate < 1.0f || inflate > 1.0f, wm = b->material != 0;
    uint32_t pc = 0, cnt = prog->count, i, prims = 0, skipped = 0, lv = 0, bsp = 0;
    uint32_t nj = cnt; /* where the innermost pending subtree (or the program) ends */
    int32_t vsp = 0, psp = 0;
    {
        float *FOVSDF__RESTRICT E4 = s->e4;
        int32_t *FOVSDF__RESTRICT A0 = s->act[0];
        if (nb == n) { /* a full batch: level 0 is the batch's arrays */
            s->pp[0][0] = b->x + k0; s->pp[0][1] = b->y + k0; s->pp[0][2] = b->z + k0;
            if (b->eps) {
                const float *FOVSDF__RESTRICT EP = b->eps + k0;
                for (i = 0; i < n; ++i) E4[i] = 4.0f * EP[i];
            } else {
                for (i = 0; i < n; ++i) E4[i] = 0.0f;
            }
            for (i = 0; i < n; ++i) A0[i] = 1;
        } else {
            float *FOVSDF__RESTRICT X = s->ps[0][0], *FOVSDF__RESTRICT Y = s->ps[0][1],
                  *FOVSDF__RESTRICT Z = s->ps[0][2];
            for (i = 0; i < n; ++i) {
                uint32_t k = k0 + (i < nb ? i : nb - 1u);
                X[i] = b->x[k]; Y[i] = b->y[k]; Z[i] = b->z[k];
                E4[i] = b->eps ? 4.0f * b->eps[k] : 0.0f;
                A0[i] = i < nb ? 1 : 0;
            }
            s->pp[0][0] = X; s->pp[0][1] = Y; s->pp[0][2] = Z;
        }
    }
    s->nact[0] = nb;
    for (;;) {
        const fovsdf__ins *in;
        /* a subtree that ended: the lanes that skipped it take the bound's value */
        if (pc == nj) {
            float *FOVSDF__RESTRICT V;
            const float *FOVSDF__RESTRICT BV;
            const int32_t *FOVSDF__RESTRICT BM;
            if (bsp == 0) break; /* the program's end */
            V = s->vs[s->bslot[bsp - 1]];
            BV = s->bv[bsp - 1];
            BM = s->bm[bsp - 1];
            for (i = 0; i < n; ++i) V[i] = fovsdf__sel(BM[i], BV[i], V[i]);
            if (wm) {
                int32_t *FOVSDF__RESTRICT M = s->ms[s->bslot[bsp - 1]];
                for (i = 0; i < n; ++i) M[i] = fovsdf__seli(BM[i], -1, M[i]);
            }
            --bsp;
            --lv;
            nj = bsp > 0 ? s->bj[bsp - 1] : cnt;
            continue;
        }
        in = &code[pc];
        switch (in->op) {
        case FOVSDF__OP_PRIM: {
            float *FOVSDF__RESTRICT d = s->vs[vsp];
            const float *X = s->pp[psp][0], *Y = s->pp[psp][1], *Z = s->pp[psp][2];
            if (scaled) {
                float sc = (in->flags & FOVSDF__FLAG_DEFLATE) ? 1.0f / inflate : inflate;
                float *FOVSDF__RESTRICT QX = s->q[0], *FOVSDF__RESTRICT QY = s->q[1],
                      *FOVSDF__RESTRICT QZ = s->q[2];
                for (i = 0; i < n; ++i) {
                    QX[i] = X[i] / sc; QY[i] = Y[i] / sc; QZ[i] = Z[i] / sc;
                }
                fovsdf__prim_lanes(in, QX, QY, QZ, d, sc, s->w);
            } else {
                fovsdf__prim_lanes(in, X, Y, Z, d, 1.0f, s->w);
            }
            if (wm) {
                int32_t *FOVSDF__RESTRICT M = s->ms[vsp], mat = in->material;
                for (i = 0; i < n; ++i) M[i] = mat;
            }
            ++vsp;
            prims += s->nact[lv];
            ++pc;
            break;
        }
        case FOVSDF__OP_BIN: {
            float *FOVSDF__RESTRICT A = s->vs[vsp - 2];
            const float *FOVSDF__RESTRICT B = s->vs[vsp - 1];
            int32_t *FOVSDF__RESTRICT MA = s->ms[vsp - 2];
            const int32_t *FOVSDF__RESTRICT MB = s->ms[vsp - 1];
            float k = in->f[0];
            --vsp;
            switch (in->sub) {
            case FOVSDF_NODE_UNION:
                FOVSDF__BLEND(ta = a < c; r = fovsdf__sel(ta, a, c););
                break;
            case FOVSDF_NODE_SUBTRACT:
                FOVSDF__BLEND(c = -c; ta = a > c; r = fovsdf__sel(ta, a, c););
                break;
            case FOVSDF_NODE_INTERSECT:
                FOVSDF__BLEND(ta = a > c; r = fovsdf__sel(ta, a, c););
                break;
            case FOVSDF_NODE_SMOOTH_UNION:
                FOVSDF__BLEND({
                    int fin = fovsdf__vfinite(a) & fovsdf__vfinite(c);
                    float h = fovsdf__vclamp(0.5f + 0.5f * (c - a) / k, 0.0f, 1.0f);
                    float v = c + (a - c) * h - k * h * (1.0f - h);
                    ta = fovsdf__seli(fin, h > 0.5f, a < c);
                    r = fovsdf__sel(fin, v, fovsdf__vmin(a, c));
                });
                break;
            case FOVSDF_NODE_SMOOTH_SUBTRACT:
                FOVSDF__BLEND({
                    int fin = fovsdf__vfinite(a) & fovsdf__vfinite(c);
                    float h = fovsdf__vclamp(0.5f - 0.5f * (a + c) / k, 0.0f, 1.0f);
                    float v = a + (-c - a) * h + k * h * (1.0f - h);
                    ta = fovsdf__seli(fin, !(h > 0.5f), a > -c);
                    r = fovsdf__sel(fin, v, fovsdf__vmax(a, -c));
                });
                break;
            default: /* smooth intersection */
                FOVSDF__BLEND({
                    int fin = fovsdf__vfinite(a) & fovsdf__vfinite(c);
                    float h = fovsdf__vclamp(0.5f - 0.5f * (c - a) / k, 0.0f, 1.0f);
                    float v = c + (a - c) * h + k * h * (1.0f - h);
                    ta = fovsdf__seli(fin, h > 0.5f, a > c);
                    r = fovsdf__sel(fin, v, fovsdf__vmax(a, c));
                });
                break;
            }
            ++pc;
            break;
        }
        case FOVSDF__OP_UNARY: {
            float r = in->f[0];
            if (in->sub == FOVSDF__SUB_CNT) { /* pruned programs (the stack may be empty) */
                skipped += s->nact[lv] * (uint32_t)in->i[0];
                ++pc;
                break;
            }
            {
                float *FOVSDF__RESTRICT V = s->vs[vsp - 1];
                if (in->sub == FOVSDF_NODE_ROUND) for (i = 0; i < n; ++i) V[i] -= r;
                else for (i = 0; i < n; ++i) V[i] = fovsdf__vabs(V[i]) - r;
            }
            ++pc;
            break;
        }
        case FOVSDF__OP_PUSHP: {
            const float *f = in->f;
            const float *FOVSDF__RESTRICT X = s->pp[psp][0], *FOVSDF__RESTRICT Y = s->pp[psp][1],
                        *FOVSDF__RESTRICT Z = s->pp[psp][2];
            float *FOVSDF__RESTRICT OX = s->ps[psp + 1][0],
                  *FOVSDF__RESTRICT OY = s->ps[psp + 1][1],
                  *FOVSDF__RESTRICT OZ = s->ps[psp + 1][2];
            const float **O = s->pp[psp + 1];
            int k;
            O[0] = X; O[1] = Y; O[2] = Z; /* axes the transform leaves alone */
            ++psp;
            switch (in->sub) {
            case FOVSDF_NODE_TRANSLATE: {
                float a = f[0], c = f[1], e = f[2];
                if (!fovsdf__is_p0(a)) { for (i = 0; i < n; ++i) OX[i] = X[i] - a; O[0] = OX; }
                if (!fovsdf__is_p0(c)) { for (i = 0; i < n; ++i) OY[i] = Y[i] - c; O[1] = OY; }
                if (!fovsdf__is_p0(e)) { for (i = 0; i < n; ++i) OZ[i] = Z[i] - e; O[2] = OZ; }
                break;
            }
            case FOVSDF_NODE_ROTATE: { /* world -> object: R^T p */
                float r0 = f[0], r1 = f[1], r2 = f[2], r3 = f[3], r4 = f[4], r5 = f[5],
                      r6 = f[6], r7 = f[7], r8 = f[8];
                for (i = 0; i < n; ++i) {
                    float px = X[i], py = Y[i], pz = Z[i];
                    OX[i] = r0 * px + r3 * py + r6 * pz;
                    OY[i] = r1 * px + r4 * py + r7 * pz;
                    OZ[i] = r2 * px + r5 * py + r8 * pz;
                }
                O[0] = OX; O[1] = OY; O[2] = OZ;
                break;
            }
            case FOVSDF_NODE_SCALE: {
                float sc = f[0];
                for (i = 0; i < n; ++i) { OX[i] = X[i] / sc; OY[i] = Y[i] / sc; OZ[i] = Z[i] / sc; }
                O[0] = OX; O[1] = OY; O[2] = OZ;
                break;
            }
            case FOVSDF_NODE_REPEAT:
                for (k = 0; k < 3; ++k) {
                    const float *FOVSDF__RESTRICT P = s->pp[psp - 1][k];
                    float *FOVSDF__RESTRICT Q = s->ps[psp][k], per = f[k], lim = (float)in->i[k];
                    if (!(per > 0.0f)) continue;
                    if (in->i[k] > 0) {
                        for (i = 0; i < n; ++i) {
                            float c = fovsdf__vfloor(P[i] / per + 0.5f);
                            c = fovsdf__sel(fovsdf__vfinite(c), c, 0.0f);
                            c = fovsdf__vclamp(c, -lim, lim);
                            Q[i] = P[i] - per * c;
                        }
                    } else {
                        for (i = 0; i < n; ++i) {
                            float c = fovsdf__vfloor(P[i] / per + 0.5f);
                            c = fovsdf__sel(fovsdf__vfinite(c), c, 0.0f);
                            Q[i] = P[i] - per * c;
                        }
                    }
                    O[k] = Q;
                }
                break;
            default: /* mirror */
                for (k = 0; k < 3; ++k)
                    if (in->i[0] & (1 << k)) {
                        const float *FOVSDF__RESTRICT P = s->pp[psp - 1][k];
                        float *FOVSDF__RESTRICT Q = s->ps[psp][k];
                        for (i = 0; i < n; ++i) Q[i] = fovsdf__vabs(P[i]);
                        O[k] = Q;
                    }
                break;
            }
            ++pc;
            break;
        }
        case FOVSDF__OP_POPP: {
            float *FOVSDF__RESTRICT V = s->vs[vsp - 1], sc = in->f[0];
            --psp; /* the parent's point is still there */
            if (sc < 1.0f || sc > 1.0f) for (i = 0; i < n; ++i) V[i] *= sc;
            ++pc;
            break;
        }
        default: { /* BOUND */
            const float *f = in->f;
            const float *FOVSDF__RESTRICT X = s->pp[psp][0], *FOVSDF__RESTRICT Y = s->pp[psp][1],
                        *FOVSDF__RESTRICT Z = s->pp[psp][2], *FOVSDF__RESTRICT E4 = s->e4;
            const int32_t *FOVSDF__RESTRICT ACT = s->act[lv];
            int32_t *FOVSDF__RESTRICT BM = s->bm[bsp];
            float *FOVSDF__RESTRICT T = s->w[0];
            float cx = f[0], cy = f[1], cz = f[2], lim0 = 1.25f * f[3] + f[4];
            uint32_t nskip = 0, na = s->nact[lv];
            if (scaled) { ++pc; break; } /* inflation: evaluate everything (as the scalar) */
            for (i = 0; i < n; ++i) {
                float dx = X[i] - cx, dy = Y[i] - cy, dz = Z[i] - cz,
                      d2 = dx * dx + dy * dy + dz * dz;
                float lim = fovsdf__vmax(lim0 + E4[i], 0.0f);
                int32_t sk = (d2 > lim * lim) & ACT[i];
                T[i] = d2;
                BM[i] = sk;
                nskip += (uint32_t)sk;
            }
            skipped += nskip * (uint32_t)in->i[0];
            if (nskip == 0) { ++pc; break; }
            fovsdf__sqrt_lanes(T);
            if (nskip == na) { /* every lane that counts skips: jump */
                float *FOVSDF__RESTRICT V = s->vs[vsp], r = f[3];
                for (i = 0; i < n; ++i) V[i] = T[i] - r;
                if (wm) {
                    int32_t *FOVSDF__RESTRICT M = s->ms[vsp];
                    for (i = 0; i < n; ++i) M[i] = -1;
                }
                ++vsp;
                pc = in->jump;
                break;
            }
            if (bsp >= FOVSDF__BREC) return 0; /* too deep: the caller goes point by point */
            {
                float *FOVSDF__RESTRICT BV = s->bv[bsp], r = f[3];
                int32_t *FOVSDF__RESTRICT A2 = s->act[lv + 1];
                for (i = 0; i < n; ++i) {
                    BV[i] = T[i] - r;
                    A2[i] = ACT[i] & (BM[i] ^ 1);
                }
            }
            s->nact[lv + 1] = na - nskip;
            s->bj[bsp] = in->jump;
            s->bslot[bsp] = (uint32_t)vsp;
            nj = in->jump;
            ++bsp;
            ++lv;
            ++pc;
            break;
        }
        }
    }
    b->prims += prims;
    b->prims_skipped += skipped;
    {
        float *FOVSDF__RESTRICT D = b->d + k0;
        const float *FOVSDF__RESTRICT V = s->vs[0];
        /* finite always: NaN and +-inf become FLT_MAX and +-FLT_MAX (fovsdf_program_eval) */
        if (vsp > 0) {
            for (i = 0; i < nb; ++i) {
                float v = V[i];
                D[i] = fovsdf__sel((v <= 0.0f) | (v > 0.0f), fovsdf__vclamp(v, -FLT_MAX, FLT_MAX),
                                   FLT_MAX);
            }
        } else {
            for (i = 0; i < nb; ++i) D[i] = FLT_MAX;
        }
        if (wm) {
            int32_t *FOVSDF__RESTRICT M = b->material + k0;
            const int32_t *FOVSDF__RESTRICT MS = s->ms[0];
            if (vsp > 0) for (i = 0; i < nb; ++i) M[i] = MS[i];
            else for (i = 0; i < nb; ++i) M[i] = -1;
        }
    }
    return 1;
}

/* Points k0 .. k0 + n of b through fovsdf_program_eval, one by one. */
FOVSDF__PRIV void fovsdf__eval_points(const fovsdf_program *prog, fovsdf_batch *b, uint32_t k0,
                                      uint32_t n)
{
    uint32_t i;
    for (i = k0; i < k0 + n; ++i) {
        fovsdf_query q;
        float p[3];
        q.inflate = b->inflate; q.eps = b->eps ? b->eps[i] : 0.0f; q.want_material = 1;
        q.material = 0; q.prims = 0; q.prims_skipped = 0;
        p[0] = b->x[i]; p[1] = b->y[i]; p[2] = b->z[i];
        b->d[i] = fovsdf_program_eval(p, &q, (void *)(uintptr_t)prog);
        if (b->material) b->material[i] = q.material;
        b->prims += q.prims; b->prims_skipped += q.prims_skipped;
    }
}
#undef FOVSDF__BLEND

FOVSDF_API void fovsdf_program_eval_batch(fovsdf_batch *b, void *user)
{
    const fovsdf_program *prog = (const fovsdf_program *)user;
    uint32_t k;
    if (!b || !b->x || !b->y || !b->z || !b->d) return;
    if (!prog || !prog->code || prog->count == 0) {
        for (k = 0; k < b->n; ++k) b->d[k] = FLT_MAX;
        return;
    }
#if FOVSDF_BATCH == 1
    fovsdf__eval_points(prog, b, 0, b->n); /* the least stack */
#else
    {
        fovsdf__bscr s;
        for (k = 0; k < b->n; k += FOVSDF__L) {
            uint32_t n = b->n - k < FOVSDF__L ? b->n - k : FOVSDF__L;
            if (!fovsdf__eval_lanes(prog, b, k, n, &s)) fovsdf__eval_points(prog, b, k, n);
        }
    }
#endif
}

/* ---- per-tile pruning of a built-in program (beyond the thesis; issue 12) -------------------
   A region is a set of evaluation points in one frame of the program: a cone segment (points
   apex + t u, u unit within atan(k) of the unit axis, t in [t0, t1]) or a box [lo, hi],
   widened by pad (every point lies within pad of the set). fovsdf__prune walks the code with
   the region of each frame (a point op maps the region into its child's frame: translate and
   scale keep the cone, rotate, mirror and repeat go through its bounding box) and
   (a) replaces a BOUND whose test skips at every point of the region (every eps in [e_lo,
       e_hi], inflate 1) by BDIST, the bound's value, and drops its subtree;
   (b) drops a BOUND whose test never skips there (its margin sphere contains the region);
   (c) drops a union with a BDIST operand that can never be its minimum (fovsdf__prune).
   Wherever the region holds, the pruned program then gives exactly the full program's
   distance, material, prims and prims_skipped: the values are the same float operations,
   BDIST counts what the skip counted, and a dropped test never skipped. The distances from a
   bound's centre to the region are taken 1e-4 relative plus pad beyond the float noise of the
   test (pad starts at 1e-5 of the region's extent and grows by 1e-6 of the magnitudes at each
   point op), so a point that fovsdf__in_cone admits is decided the same way. With inflate != 1
   the full program tests no bound: a pruned program must then not be used (fovsdf__in_cone's
   callers check). */
#ifndef FOVSDF_PRUNE_CODE /* pruned program instructions per tile on the stack (64 bytes each);
                             0: no pruning; a longer program is not pruned (CONFIGURATION) */
#define FOVSDF_PRUNE_CODE 0
#endif
#ifndef FOVSDF_PRUNE_MIN /* rules (b) and (c) applications that make a tile use its pruned
                            program (0: every tile that could be pruned) */
#define FOVSDF_PRUNE_MIN 1
#endif
#if (FOVSDF_PRUNE_CODE) < 0 || (FOVSDF_PRUNE_MIN) < 0
#error "fovsdf: FOVSDF_PRUNE_CODE and FOVSDF_PRUNE_MIN must be >= 0"
#endif
typedef struct fovsdf__preg {
    int kind;                      /* 0 unknown (nothing is pruned), 1 cone, 2 box */
    float apex[3], axis[3], k, t0, t1;
    float lo[3], hi[3];
    float pad;
} fovsdf__preg;

typedef struct fovsdf__pruned {  /* a tile's cone and pruned program (fovsdf__marcher.pv) */
    fovsdf_ray_cone cone;         /* the points that may use it (fovsdf__in_cone) */
    float e_lo, e_hi;             /* and their thresholds */
    uint32_t rules[3];            /* bounds turned into BDIST, tests dropped, unions dropped */
    int pruned;                   /* 0: the cone only (for a batch callback) */
#if FOVSDF_PRUNE_CODE > 0
    fovsdf_program prog;
    fovsdf_scene sc;              /* the scene with user = &prog */
    fovsdf__ins code[FOVSDF_PRUNE_CODE];
#endif
} fovsdf__pruned;

FOVSDF__PRIV float fovsdf__preg_mag(const fovsdf__preg *g)
{
    if (g->kind == 1) return fov__len(g->apex) + g->t1;
    return fovsdf__len3f(fov__maxf(fov__absf(g->lo[0]), fov__absf(g->hi[0])),
                         fov__maxf(fov__absf(g->lo[1]), fov__absf(g->hi[1])),
                         fov__maxf(fov__absf(g->lo[2]), fov__absf(g->hi[2])));
}

/* The cone segment's bounding box (the region becomes a box). */
FOVSDF__PRIV void fovsdf__preg_box(fovsdf__preg *g)
{
    int j;
    float ca, sa;
    if (g->kind != 1) return;
    ca = 1.0f / FOV__SQRT(1.0f + g->k * g->k);
    sa = g->k * ca;
    for (j = 0; j < 3; ++j) {
        /* the largest and least u_j over the cap: cos of (angle to +-e_j minus alpha), or +-1
           when the cap contains +-e_j */
        float aj = g->axis[j], sj = FOV__SQRT(fov__maxf(1.0f - aj * aj, 0.0f));
        float umax = aj >= ca ? 1.0f : aj * ca + sj * sa;
        float umin = -aj >= ca ? -1.0f : aj * ca - sj * sa;
        umax = fovsdf__clampf(umax * 1.0001f + 1e-6f, -1.0f, 1.0f);
        umin = fovsdf__clampf(umin * 1.0001f - 1e-6f, -1.0f, 1.0f);
        g->hi[j] = g->apex[j] + (umax >= 0.0f ? g->t1 : g->t0) * umax;
        g->lo[j] = g->apex[j] + (umin >= 0.0f ? g->t0 : g->t1) * umin;
    }
    g->pad += 1e-6f * fovsdf__preg_mag(g);
    g->kind = 2;
}

/* The region of a point op's child frame (the op's transform applied to g). */
FOVSDF__PRIV void fovsdf__preg_map(const fovsdf__preg *g, const fovsdf__ins *in, fovsdf__preg *o)
{
    const float *f = in->f;
    float mag = fovsdf__preg_mag(g);
    int k;
    *o = *g;
    if (g->kind == 0) return;
    switch (in->sub) {
    case FOVSDF_NODE_TRANSLATE:
        for (k = 0; k < 3; ++k) {
            if (o->kind == 1) o->apex[k] -= f[k];
            else { o->lo[k] -= f[k]; o->hi[k] -= f[k]; }
        }
        o->pad += 1e-6f * (mag + fovsdf__len3f(f[0], f[1], f[2]));
        break;
    case FOVSDF_NODE_SCALE:
        for (k = 0; k < 3; ++k) {
            if (o->kind == 1) o->apex[k] /= f[0];
            else { o->lo[k] /= f[0]; o->hi[k] /= f[0]; }
        }
        o->t0 /= f[0]; o->t1 /= f[0];
        o->pad = o->pad / f[0] + 1e-6f * (mag / f[0]);
        break;
    case FOVSDF_NODE_ROTATE: { /* p' = R^T p: the box's centre and |R^T| of its half sides */
        float c[3], h[3];
        fovsdf__preg_box(o);
        for (k = 0; k < 3; ++k) {
            c[k] = 0.5f * (o->lo[k] + o->hi[k]);
            h[k] = 0.5f * (o->hi[k] - o->lo[k]);
        }
        for (k = 0; k < 3; ++k) {
            float cc = f[k] * c[0] + f[3 + k] * c[1] + f[6 + k] * c[2];
            float hh = fov__absf(f[k]) * h[0] + fov__absf(f[3 + k]) * h[1] +
                fov__absf(f[6 + k]) * h[2];
            o->lo[k] = cc - hh; o->hi[k] = cc + hh;
        }
        /* rows orthonormal within 1e-3: the pad grows with the matrix */
        o->pad = o->pad * 1.01f + 1e-6f * mag;
        break;
    }
    case FOVSDF_NODE_MIRROR:
        fovsdf__preg_box(o);
        for (k = 0; k < 3; ++k)
            if (in->i[0] & (1 << k)) {
                float l = o->lo[k], hv = o->hi[k];
                if (hv <= 0.0f) { o->lo[k] = -hv; o->hi[k] = -l; }
                else if (l < 0.0f) { o->lo[k] = 0.0f; o->hi[k] = fov__maxf(-l, hv); }
            }
        o->pad += 1e-6f * mag;
        break;
    case FOVSDF_NODE_REPEAT:
        fovsdf__preg_box(o);
        for (k = 0; k < 3; ++k) {
            float per = f[k], cl, ch, lim = (float)in->i[k];
            if (!(per > 0.0f)) continue;
            cl = FOV__FLOOR((o->lo[k] - o->pad) / per + 0.5f);
            ch = FOV__FLOOR((o->hi[k] + o->pad) / per + 0.5f);
            if (!fov__finite(cl) || !fov__finite(ch) || fov__absf(cl) > 1e6f ||
                fov__absf(ch) > 1e6f) { o->kind = 0; return; }
            if (in->i[k] > 0) {
                cl = fovsdf__clampf(cl, -lim, lim);
                ch = fovsdf__clampf(ch, -lim, lim);
            }
            if (fov__is0(cl - ch)) { /* one cell: a shift */
                o->lo[k] -= per * cl; o->hi[k] -= per * cl;
            } else { /* the hull of the folded pieces */
                o->lo[k] = fov__minf(o->lo[k] - per * cl, -0.5f * per);
                o->hi[k] = fov__maxf(o->hi[k] - per * ch, 0.5f * per);
            }
        }
        o->pad += 1e-6f * (mag + fovsdf__len3f(f[0], f[1], f[2]));
        break;
    default: break;
    }
    if (o->kind == 2 && !(fov__finite3(o->lo) && fov__finite3(o->hi))) o->kind = 0;
    if (o->kind == 1 && !(fov__finite3(o->apex) && fov__finite(o->t1))) o->kind = 0;
    if (!fov__finite(o->pad)) o->kind = 0;
}

/* The least and largest distance from c to the region (pad and 1e-4 included). */
FOVSDF__PRIV void fovsdf__preg_dist(const fovsdf__preg *g, const float c[3], float *dmin,
                                    float *dmax)
{
    float lo, hi;
    int k;
    if (g->kind == 1) {
        float v[3], w[3], al, pe, rho, ca, sa, s, x, y, x2, y2;
        for (k = 0; k < 3; ++k) v[k] = c[k] - g->apex[k];
        al = fov__dot(v, g->axis);
        for (k = 0; k < 3; ++k) w[k] = v[k] - al * g->axis[k];
        pe = fov__len(w);
        rho = fov__len(v);
        ca = 1.0f / FOV__SQRT(1.0f + g->k * g->k);
        sa = g->k * ca;
        if (pe <= g->k * al) { /* within the half-angle: radially */
            lo = fov__maxf(fov__maxf(g->t0 - rho, rho - g->t1), 0.0f);
        } else { /* to the boundary ray at alpha, s clamped to [t0, t1] */
            s = fovsdf__clampf(al * ca + pe * sa, g->t0, g->t1);
            x = al - s * ca; y = pe - s * sa;
            lo = FOV__SQRT(x * x + y * y);
        }
        if (pe * ca + al * sa < 0.0f) { /* the far side passes the opposite direction */
            hi = rho + g->t1;
        } else {
            x = al - g->t0 * ca; y = pe + g->t0 * sa;
            x2 = al - g->t1 * ca; y2 = pe + g->t1 * sa;
            hi = FOV__SQRT(fov__maxf(x * x + y * y, x2 * x2 + y2 * y2));
        }
    } else {
        float a[3], b[3];
        for (k = 0; k < 3; ++k) {
            a[k] = fov__maxf(fov__maxf(g->lo[k] - c[k], c[k] - g->hi[k]), 0.0f);
            b[k] = fov__maxf(fov__absf(c[k] - g->lo[k]), fov__absf(c[k] - g->hi[k]));
        }
        lo = fov__len(a);
        hi = fov__len(b);
    }
    *dmin = lo * (1.0f - 1e-4f) - g->pad;
    *dmax = hi * (1.0f + 1e-4f) + g->pad;
}

/* Bounds [lo, hi] of a primitive's value over the region g of its frame (an exact distance of a
   solid inside the ball (c, R) lies in [|p - c| - R, |p - q|] for any point q inside the solid,
   Lipschitz 1; a plane's from its support; the fractals and the terrain are not bounded). */
FOVSDF__PRIV void fovsdf__prim_range(const fovsdf__ins *in, const fovsdf__preg *g, float *lo,
                                     float *hi)
{
    const float *f = in->f;
    float c[3] = { 0.0f, 0.0f, 0.0f }, q[3] = { 0.0f, 0.0f, 0.0f }, R, qoff = 0.0f, a, b, d0, d1;
    *lo = -FLT_MAX; *hi = FLT_MAX;
    switch (in->sub) {
    case FOVSDF_NODE_SPHERE: R = f[0]; qoff = -f[0]; break;
    case FOVSDF_NODE_BOX: case FOVSDF_NODE_ROUND_BOX: R = fovsdf__len3f(f[0], f[1], f[2]); break;
    case FOVSDF_NODE_BOX_FRAME:
        R = fovsdf__len3f(f[0], f[1], f[2]); q[0] = f[0]; q[1] = f[1]; q[2] = f[2];
        break;
    case FOVSDF_NODE_TORUS: R = f[0] + f[1]; qoff = f[0] - f[1]; break;
    case FOVSDF_NODE_CAPSULE:
        c[0] = 0.5f * (f[0] + f[3]); c[1] = 0.5f * (f[1] + f[4]); c[2] = 0.5f * (f[2] + f[5]);
        R = 0.5f * fovsdf__len3f(f[3] - f[0], f[4] - f[1], f[5] - f[2]) + f[6];
        q[0] = f[0]; q[1] = f[1]; q[2] = f[2]; qoff = -f[6];
        break;
    case FOVSDF_NODE_CYLINDER: R = fovsdf__len2f(f[0], f[1]); break;
    case FOVSDF_NODE_CONE: R = fovsdf__len2f(f[0], fov__maxf(f[1], f[2])); break;
    case FOVSDF_NODE_PLANE: {
        fovsdf__preg b2 = *g;
        int k;
        fovsdf__preg_box(&b2);
        if (b2.kind != 2) return;
        a = f[3]; b = f[3];
        for (k = 0; k < 3; ++k) {
            a += fov__minf(f[k] * b2.lo[k], f[k] * b2.hi[k]);
            b += fov__maxf(f[k] * b2.lo[k], f[k] * b2.hi[k]);
        }
        d0 = b2.pad * 1.001f + 1e-5f * (fovsdf__preg_mag(&b2) + fov__absf(f[3]));
        *lo = a - d0; *hi = b + d0;
        return;
    }
    default: return; /* fractals, terrain */
    }
    fovsdf__preg_dist(g, c, &d0, &a);
    fovsdf__preg_dist(g, q, &b, &d1);
    a = 1e-5f * (fovsdf__preg_mag(g) + R); /* the float noise of the value */
    *lo = d0 - R * 1.0001f - a;
    *hi = d1 + qoff + a;
}

/* Prune prog for the points of g (region in the program's world frame) with thresholds in
   [e_lo, e_hi] and inflate 1 into code[0 .. cap) (see above); 0 when it does not fit. Rule
   (c): each value on the stack carries bounds over the region; a plain union whose operand is
   a bare BDIST that stays above the other operand's upper bound (strictly: the evaluator
   keeps a on a < b) can never be the minimum: the BDIST becomes CNT (its count) and the union
   goes. */
typedef struct fovsdf__pval { float lo, hi; uint32_t at, np; int bare; } fovsdf__pval;
FOVSDF__PRIV int fovsdf__prune(const fovsdf_program *prog, const fovsdf__preg *g, float e_lo,
                               float e_hi, int rule_c, fovsdf__ins *code, uint32_t cap,
                               fovsdf_program *out, uint32_t *rules)
{
    const fovsdf__ins *src = (const fovsdf__ins *)prog->code;
    fovsdf__preg reg[FOVSDF_MAX_STACK + 1];
    fovsdf__pval vs[FOVSDF_MAX_STACK];
    uint32_t ob_out[FOVSDF__MAX_DEPTH], ob_end[FOVSDF__MAX_DEPTH];
    float ob_lo[FOVSDF__MAX_DEPTH], ob_hi[FOVSDF__MAX_DEPTH];
    uint32_t pc = 0, no = 0, nob = 0, n = prog->count, ra = 0, rb = 0, rc = 0, nbo = 0;
    uint32_t lead = 0xffffffffu; /* the first BOUND or PUSHP of the value being started */
    int32_t rsp = 0, vsp = 0;
    reg[0] = *g;
    if (!(g->kind == 1 || g->kind == 2) || !(e_lo <= e_hi) || !fov__finite(e_hi)) return 0;
    for (;;) {
        const fovsdf__ins *in;
        while (nob > 0 && ob_end[nob - 1] == pc) { /* a kept bound's end: either value */
            --nob;
            code[ob_out[nob]].jump = no;
            if (vsp > 0) {
                vs[vsp - 1].lo = fov__minf(vs[vsp - 1].lo, ob_lo[nob]);
                vs[vsp - 1].hi = fov__maxf(vs[vsp - 1].hi, ob_hi[nob]);
                vs[vsp - 1].bare = 0;
            }
        }
        if (pc >= n) break;
        in = &src[pc];
        if (no >= cap) return 0;
        if (in->op == FOVSDF__OP_BOUND) {
            const float *f = in->f;
            if (in->flags) return 0; /* a program pruned already */
            /* the evaluator's margins at the extreme thresholds (the same operations: lim
               grows with eps) */
            float l_hi = fov__maxf(1.25f * f[3] + f[4] + 4.0f * e_hi, 0.0f);
            float l_lo = fov__maxf(1.25f * f[3] + f[4] + 4.0f * e_lo, 0.0f);
            float dmin = 0.0f, dmax = FLT_MAX;
            if (reg[rsp].kind != 0) fovsdf__preg_dist(&reg[rsp], f, &dmin, &dmax);
            if (reg[rsp].kind != 0 && dmin > l_hi * (1.0f + 1e-4f)) { /* (a) every point skips */
                if (vsp >= FOVSDF_MAX_STACK) return 0;
                code[no] = *in;
                code[no].flags = FOVSDF__FLAG_BDIST;
                code[no].jump = no + 1u;
                code[no].f[4] = -FLT_MAX;
                vs[vsp].lo = dmin - f[3] * 1.0001f; vs[vsp].hi = dmax - f[3] * 0.9999f;
                vs[vsp].at = lead != 0xffffffffu ? lead : no;
                vs[vsp].bare = vs[vsp].at == no; /* nothing before it */
                vs[vsp].np = (uint32_t)in->i[0]; ++vsp;
                lead = 0xffffffffu;
                ++no; ++ra;
                pc = in->jump;
                continue;
            }
            if (reg[rsp].kind != 0 && dmax * (1.0f + 1e-4f) < l_lo) { /* (b) no point skips */
                ++pc; ++rb;
                continue;
            }
            if (nob >= FOVSDF__MAX_DEPTH) return 0;
            code[no] = *in;
            ob_out[nob] = no; ob_end[nob] = in->jump;
            ob_lo[nob] = reg[rsp].kind != 0 ? dmin - f[3] * 1.0001f : -FLT_MAX;
            ob_hi[nob] = reg[rsp].kind != 0 ? dmax - f[3] * 0.9999f : FLT_MAX;
            if (lead == 0xffffffffu) lead = no;
            ++nob; ++nbo; ++no; ++pc;
            continue;
        }
        code[no] = *in;
        switch (in->op) {
        case FOVSDF__OP_PRIM:
            if (vsp >= FOVSDF_MAX_STACK) return 0;
            if (reg[rsp].kind != 0) fovsdf__prim_range(in, &reg[rsp], &vs[vsp].lo, &vs[vsp].hi);
            else { vs[vsp].lo = -FLT_MAX; vs[vsp].hi = FLT_MAX; }
            vs[vsp].at = lead != 0xffffffffu ? lead : no;
            vs[vsp].bare = 0; vs[vsp].np = 1; ++vsp;
            lead = 0xffffffffu;
            break;
        case FOVSDF__OP_BIN: {
            fovsdf__pval a, b;
            float k = in->f[0] * 0.2501f, sl;
            if (vsp < 2) return 0;
            b = vs[--vsp]; a = vs[vsp - 1];
            sl = 1e-4f * (fov__absf(a.hi) + fov__absf(b.lo) + fov__absf(a.lo) + fov__absf(b.hi)) +
                1e-30f;
            if (rule_c && in->sub == FOVSDF_NODE_UNION && b.bare && a.hi + sl < b.lo &&
                a.hi < FLT_MAX) { /* b is never the minimum */
                /* b's code (a BDIST and CNTs) goes, one CNT of what it counted in its place */
                FOV_MEMSET(&code[b.at], 0, sizeof code[b.at]);
                code[b.at].op = FOVSDF__OP_UNARY;
                code[b.at].sub = FOVSDF__SUB_CNT;
                code[b.at].i[0] = (int32_t)b.np;
                no = b.at + 1u;
                vs[vsp - 1].np = a.np + b.np;
                ++rc; ++pc;
                continue; /* a stays, as it was */
            }
            if (rule_c && in->sub == FOVSDF_NODE_UNION && a.bare && b.hi + sl < a.lo &&
                b.hi < FLT_MAX) { /* a is never the minimum (a tie takes b) */
                uint32_t sh = b.at - a.at - 1u, j;
                FOV_MEMSET(&code[a.at], 0, sizeof code[a.at]);
                code[a.at].op = FOVSDF__OP_UNARY;
                code[a.at].sub = FOVSDF__SUB_CNT;
                code[a.at].i[0] = (int32_t)a.np;
                for (j = b.at; j < no; ++j) { /* b's code moves down over a's */
                    code[j - sh] = code[j];
                    if (code[j - sh].op == FOVSDF__OP_BOUND) code[j - sh].jump -= sh;
                }
                no -= sh;
                b.at = a.at; b.bare = 0; b.np += a.np;
                vs[vsp - 1] = b;
                ++rc; ++pc;
                continue;
            }
            switch (in->sub) {
            case FOVSDF_NODE_UNION:
                a.lo = fov__minf(a.lo, b.lo); a.hi = fov__minf(a.hi, b.hi); break;
            case FOVSDF_NODE_SMOOTH_UNION:
                a.lo = fov__minf(a.lo, b.lo) - k; a.hi = fov__minf(a.hi, b.hi); break;
            case FOVSDF_NODE_SUBTRACT: case FOVSDF_NODE_SMOOTH_SUBTRACT:
                a.lo = fov__maxf(a.lo, -b.hi); a.hi = fov__maxf(a.hi, -b.lo);
                if (in->sub == FOVSDF_NODE_SMOOTH_SUBTRACT) a.hi += k;
                break;
            default: /* intersections */
                a.lo = fov__maxf(a.lo, b.lo); a.hi = fov__maxf(a.hi, b.hi);
                if (in->sub == FOVSDF_NODE_SMOOTH_INTERSECT) a.hi += k;
                break;
            }
            a.lo -= sl; a.hi += sl; a.bare = 0; a.np += b.np;
            vs[vsp - 1] = a;
            break;
        }
        case FOVSDF__OP_UNARY: {
            fovsdf__pval *v;
            if (vsp < 1 || in->sub == FOVSDF__SUB_CNT) return 0; /* a program pruned already */
            v = &vs[vsp - 1];
            if (in->sub == FOVSDF_NODE_ROUND) { v->lo -= in->f[0]; v->hi -= in->f[0]; }
            else {
                float l = v->lo, h = v->hi;
                v->lo = (l <= 0.0f && h >= 0.0f ? 0.0f : fov__minf(fov__absf(l), fov__absf(h))) -
                    in->f[0];
                v->hi = fov__maxf(fov__absf(l), fov__absf(h)) - in->f[0];
            }
            v->bare = 0;
            break;
        }
        case FOVSDF__OP_PUSHP:
            if (rsp >= FOVSDF_MAX_STACK) return 0;
            if (lead == 0xffffffffu) lead = no;
            fovsdf__preg_map(&reg[rsp], in, &reg[rsp + 1]);
            ++rsp;
            break;
        case FOVSDF__OP_POPP:
            if (rsp > 0) --rsp;
            if (vsp < 1) return 0;
            vs[vsp - 1].lo *= in->f[0]; vs[vsp - 1].hi *= in->f[0]; vs[vsp - 1].bare = 0;
            break;
        default: return 0; /* a program pruned already */
        }
        /* unbounded values stay unbounded (no inf - inf later) */
        if (vsp > 0) {
            fovsdf__pval *v = &vs[vsp - 1];
            if (!(v->lo > -FLT_MAX)) v->lo = -FLT_MAX;
            if (!(v->hi < FLT_MAX)) v->hi = FLT_MAX;
        }
        ++no; ++pc;
    }
    out->code = code;
    out->count = no;
    out->prims = prog->prims; /* what prims + prims_skipped still add up to */
    out->bounds = nbo;
    out->bound_center[0] = prog->bound_center[0]; out->bound_center[1] = prog->bound_center[1];
    out->bound_center[2] = prog->bound_center[2]; out->bound_radius = prog->bound_radius;
    if (rules) { rules[0] = ra; rules[1] = rb; rules[2] = rc; }
    return 1;
}

/* 1 when point p lies in cone q (fovsdf_ray_cone; t the distance from the apex), as computed
   in float (fovsdf__prune's pad covers the rounding). */
FOVSDF__INL int fovsdf__in_cone(const fovsdf_ray_cone *q, float x, float y, float z)
{
    float v0 = x - q->apex[0], v1 = y - q->apex[1], v2 = z - q->apex[2];
    float t2 = v0 * v0 + v1 * v1 + v2 * v2;
    float al = v0 * q->axis[0] + v1 * q->axis[1] + v2 * q->axis[2];
    float w0 = v0 - al * q->axis[0], w1 = v1 - al * q->axis[1], w2 = v2 - al * q->axis[2];
    float k = q->tan_half;
    return al > 0.0f && t2 >= q->t0 * q->t0 && t2 <= q->t1 * q->t1 &&
        w0 * w0 + w1 * w1 + w2 * w2 <= (k * al) * (k * al);
}

/* Prune sc's program (a built-in program scene only) for the cone q with thresholds in
   [e_lo, e_hi] into pv. Returns 1 when pv holds a pruned program. */
FOVSDF__PRIV int fovsdf__prune_cone(const fovsdf_scene *sc, const fovsdf_ray_cone *q, float e_lo,
                                    float e_hi, fovsdf__pruned *pv)
{
#if FOVSDF_PRUNE_CODE > 0
    const fovsdf_program *pg = (const fovsdf_program *)sc->user;
    fovsdf__preg g;
    int k;
    if (sc->dist_ex != fovsdf_program_eval ||
        (sc->dist_batch && sc->dist_batch != fovsdf_program_eval_batch) || !pg || !pg->code ||
        pg->count == 0 || pg->count > FOVSDF_PRUNE_CODE)
        return 0;
    if (!(q->tan_half >= 0.0f) || !(q->t0 >= 0.0f) || !(q->t1 >= q->t0) || !fov__finite(q->t1) ||
        !fov__finite(q->tan_half) || !fov__finite3(q->apex))
        return 0;
    g.kind = 1;
    for (k = 0; k < 3; ++k) { g.apex[k] = q->apex[k]; g.axis[k] = q->axis[k]; }
    g.k = q->tan_half; g.t0 = q->t0; g.t1 = q->t1;
    g.pad = 1e-5f * (fov__len(q->apex) + q->t1) + 1e-30f;
    for (k = 0; k < 3; ++k) g.lo[k] = g.hi[k] = 0.0f;
    if (!fovsdf__prune(pg, &g, e_lo, e_hi, 1, pv->code, FOVSDF_PRUNE_CODE, &pv->prog, pv->rules))
        return 0;
    pv->sc = *sc;
    pv->sc.user = &pv->prog;
    pv->cone = *q;
    pv->e_lo = e_lo; pv->e_hi = e_hi;
    pv->pruned = 1;
    return 1;
#else
    (void)sc; (void)q; (void)e_lo; (void)e_hi; (void)pv;
    return 0;
#endif
}

/* ---- distance evaluation and the four tracers --------------------------------------------- */
typedef struct fovsdf__marcher {
    const fovsdf_scene *sc;
    float inv_lip;
    uint32_t method, max_steps;
    float eps, eps_cone, ulp0, ulp1, t_max;
    float omega, beta, relax;
    float inflate;     /* SDF scale of the evaluations (1: the exact scene) */
    int verify_start;  /* heuristic head starts: restart from 0 when t0 is inside a surface */
    int per_ray;       /* 1: eps_cone is the centre pixel's; each ray scales it by its own
                          footprint, cos^2 of its angle to fwd (camera rays, fovsdf_trace) */
    float fwd[3];      /* the camera's forward axis (per_ray) */
    const struct fovsdf__pruned *pv; /* NULL, or the tile's cone and pruned program: the
                                        wavefront's evaluations inside the cone use them */
} fovsdf__marcher;

/* One counted evaluation. A non-finite value from a user callback becomes FLT_MAX, which ends
   the ray as a miss instead of spreading NaN. */
FOVSDF__PRIV float fovsdf__eval_in(const fovsdf_scene *sc, float inv_lip, const float p[3],
                                   float eps, float inflate, int32_t *mat, fovsdf_stats *st)
{
    float d;
    if (sc->dist_ex) {
        fovsdf_query q;
        q.inflate = inflate; q.eps = eps; q.want_material = 1; q.material = 0; q.prims = 0;
        q.prims_skipped = 0;
        d = sc->dist_ex(p, &q, sc->user);
        if (mat) *mat = q.material;
        if (st) { st->prims += q.prims; st->prims_skipped += q.prims_skipped; }
    } else if (sc->dist) {
        d = sc->dist(p, sc->user);
        if (mat) *mat = 0;
    } else { /* a batch callback alone: a batch of one */
        fovsdf_batch b;
        int32_t m = 0;
        d = fovsdf__nan();
        b.n = 1; b.x = &p[0]; b.y = &p[1]; b.z = &p[2]; b.eps = &eps; b.inflate = inflate;
        b.d = &d; b.material = &m; b.prims = 0; b.prims_skipped = 0; b.cone = 0;
        sc->dist_batch(&b, sc->user);
        if (mat) *mat = m;
        if (st) { st->prims += b.prims; st->prims_skipped += b.prims_skipped; }
    }
    if (st) st->evals++;
    d *= inv_lip;
    return fov__finite(d) ? d : FLT_MAX;
}

/* n <= FOVSDF_BATCH counted evaluations at (x, y, z)[i] with thresholds eps[i] (as
   fovsdf__eval_in for each point: the same values, materials and counts), through the batch
   callback when the scene has one, else point by point. mat may be NULL. */
FOVSDF__PRIV void
fovsdf__eval_batch(const fovsdf_scene *sc, float inv_lip, uint32_t n, const float *x,
                   const float *y, const float *z, const float *eps, float inflate,
                   const fovsdf_ray_cone *cone, float *d, int32_t *mat, fovsdf_stats *st)
{
    uint32_t i;
    if (sc->dist_batch) {
        fovsdf_batch b;
        const fovsdf_program *pg = (const fovsdf_program *)sc->user;
        /* a built-in program writes every distance and material, finite: no defaults, and
           at Lipschitz 1 nothing to scale */
        int own = sc->dist_batch == fovsdf_program_eval_batch && pg && pg->code && pg->count > 0;
        if (!own) {
            float nan = fovsdf__nan();
            for (i = 0; i < n; ++i) d[i] = nan;
            if (mat) for (i = 0; i < n; ++i) mat[i] = 0;
        }
        b.n = n; b.x = x; b.y = y; b.z = z; b.eps = eps; b.inflate = inflate; b.d = d;
        b.material = mat; b.prims = 0; b.prims_skipped = 0; b.cone = cone;
        sc->dist_batch(&b, sc->user);
        if (st) { st->prims += b.prims; st->prims_skipped += b.prims_skipped; st->evals += n; }
        if (!own || inv_lip < 1.0f || inv_lip > 1.0f) {
            for (i = 0; i < n; ++i) {
                float v = d[i] * inv_lip;
                d[i] = fov__finite(v) ? v : FLT_MAX;
            }
        }
        return;
    }
    for (i = 0; i < n; ++i) {
        float p[3];
        p[0] = x[i]; p[1] = y[i]; p[2] = z[i];
        d[i] = fovsdf__eval_in(sc, inv_lip, p, eps[i], inflate, mat ? &mat[i] : 0, st);
    }
}
FOVSDF__PRIV float fovsdf__eval_sc(const fovsdf_scene *sc, float inv_lip, const float p[3],
                                   float eps, int32_t *mat, fovsdf_stats *st)
{
    return fovsdf__eval_in(sc, inv_lip, p, eps, 1.0f, mat, st);
}

/* The ulp floor's constant part, 8 FLT_EPSILON |ro|, without overflowing for |ro| beyond
   1.8e19 (the squared length would be inf and make every ray hit at its start). */
FOVSDF__PRIV float fovsdf__ulp0(const float ro[3])
{
    float l = fov__maxf(fov__absf(ro[0]), fov__maxf(fov__absf(ro[1]), fov__absf(ro[2]))), q[3];
    if (!(l > 0.0f)) return 0.0f;
    if (l < 1e18f) return 8.0f * FLT_EPSILON * fov__len(ro);
    q[0] = ro[0] / l; q[1] = ro[1] / l; q[2] = ro[2] / l;
    return 8.0f * FLT_EPSILON * l * fov__len(q);
}

FOVSDF__PRIV float fovsdf__thr(const fovsdf__marcher *m, float t)
{
    float a = m->eps, b = m->eps_cone * t, c = m->ulp0 + m->ulp1 * t;
    return fov__maxf(a, fov__maxf(b, c));
}

/* The refinement's margin at t: 1 % of the threshold plus 4 ulps of |camera| + t (the float
   noise of a position); see the hit refinement, fovsdf__refine. */
FOVSDF__PRIV float fovsdf__mg(const fovsdf__marcher *m, float t)
{
    return 0.01f * fovsdf__thr(m, t) + 0.5f * (m->ulp0 + m->ulp1 * t);
}

/* Hit refinement (every tracer): the threshold stops a ray up to eps (or a fraction of a pixel
   cone) short of the surface along the ray, which at grazing angles slides the hit point, and
   every texture on it, by that fraction of a pixel. One secant step through the last two
   samples is exact for planes; it is kept only when it lowers |d|, stays outside (up to
   the margin mg below), stays in [t0, t_max] and never passes a point the march has not
   verified: the loop's last sample proves [t, t + d] empty (its unbounding sphere), and a
   move beyond t + d is kept only when
   - the sphere at its end point (radius d2) overlaps that one, d + d2 + 2 mg >= dt (then
     no point of the segment is inside by more than mg): roughly normal incidence, a
     plane at |cos(incidence)| = c while d (1/c - 1) <= 2 mg; or else
   - one empty ball off the ray holds the segment it jumps (below): with
     A = p(t + d) and F = p(t + dt) the secant's end point, n the outward normal at F
     (the secant's slope along the ray and two forward differences across it), the ball
     around c = F + H n through A tangent to the plane at F (H = |A - F|^2 / (2 h_A),
     h_A = (A - F) . n the height of A above that plane: for a plane the smallest such
     ball) contains no surface point when its radius is at most f(c) (Lipschitz 1), so
     when A and F both lie within f(c) + mg of c (less 4 ulps of H for the rounding of
     the test), so does the whole segment (a ball is convex) and no point of it is
     inside by more than mg. Refused when |f(F)| > d / 4 (the secant found no surface
     there: a ray running along a curved surface keeps its hit where the threshold
     stopped it, as a plain tracer would), when h_A <= 0, when 8 ulps of H exceed mg
     (a plane below about 0.4 degrees with d near the threshold), or when anything is
     not finite; a surface inside the ball (a thin wall before the plane, a concave corner)
     makes f(c) smaller than H and refuses it. 4 evaluations (F, two differences, c),
     tried up to 1024 |d| ahead.
   Otherwise the hit moves by d, inside the sample's sphere (the plain step; the secant
   step is clamped to 64 |d|). Backward moves (d < 0) stay within the part the loop
   verified. A plane is then refined exactly from normal incidence down to about 0.4
   degrees (the unverified secant before issue 10, clamped to 64 |d|, was exact down to
   about 0.9 degrees, and jumped thin surfaces: a ray stopped 0.06 before a shell and the
   secant put the hit 0.94 behind it); below that the hit stays up to thr (1/c - 1)
   before the plane. Cost per hit: one evaluation, up to 5 when the ball is tried (a hit
   at the first evaluation takes one more for the second sample: 6 at most). mg = 1 % of
   the threshold plus the float noise of the position (4 ulps of |camera| + t), which
   the shading offsets cover; it is also the
   depth the contract allows inside (NUMERICS: tol is 2 % of the threshold plus 8 ulps):
   a wall thinner than 2 mg is below what the refinement can see. */

/* Empty-ball certificate of a forward secant move from a hit at t (distance d > 0) to t2 >
   t + d (see the hit refinement): a ball around c = F + H n, F = p(t2), n the
   outward normal at F, H the radius of the ball tangent at F through A = p(t + d), is empty
   when its radius is at most f(c) (Lipschitz 1); when A and F lie within f(c) + mg of c (less
   the test's rounding), so does the segment between them (convexity), and no point of it is
   inside by more than mg. 4 evaluations: F, two forward differences, c (1 when F is
   already no better than the plain refinement would be). */

/* ---- the march as a resumable state machine -------------------------------------------------
   Every tracer and the hit refinement are written once, as a coroutine over fovsdf__mco: it
   runs until it needs a distance, leaves the point in q (threshold qe, SDF scale qi) and
   returns 1; whoever evaluates puts the distance and material in res, resm and calls it again.
   fovsdf__march evaluates point by point; the wavefront (fovsdf__wave) evaluates the requests
   of many rays in one batch. Both run the same code on the same values, so an image does not
   depend on which one marched it, nor on how rays were grouped into batches. A point that
   overflows (a camera near FLT_MAX) is never evaluated: it reads FLT_MAX, a miss, and leaves
   the material alone. */
/* fovsdf__thr and fovsdf__mg with the ray's own eps_cone ec (the same operations) */
FOVSDF__INL float fovsdf__thr_ec(const fovsdf__marcher *m, float ec, float t)
{
    float a = m->eps, b = ec * t, c = m->ulp0 + m->ulp1 * t;
    return fov__maxf(a, fov__maxf(b, c));
}
FOVSDF__INL float fovsdf__mg_ec(const fovsdf__marcher *m, float ec, float t)
{
    return 0.01f * fovsdf__thr_ec(m, ec, t) + 0.5f * (m->ulp0 + m->ulp1 * t);
}

typedef struct fovsdf__mco {
    float ro[3], rd[3], t0;    /* the ray and its start */
    float ec;                  /* the ray's own eps_cone (per_ray: scaled by its footprint) */
    float q[3], qe, qi;        /* the pending evaluation: point, threshold, SDF scale */
    float res;                 /* its result */
    int32_t resm;
    uint32_t pc;               /* where to resume (0: start) */
    int got;                   /* 1: the last request was evaluated (a finite point) */
    uint32_t evals;            /* evaluations so far */
    /* tracer state (the result is t, d, steps, kind, mat) */
    float t, d, pt, pd, om, tp, rp, z, sl, dp, T, R;
    int hp, have;
    uint32_t steps, kind;
    int32_t mat, m2, mb;
    /* refinement and ball certificate */
    float t1, d1, dt, mg, tt, dd, slope, lim, tb, db, t2, fb, e, g1, a[3], f[3], b1[3], b2[3];
    int ok;
} fovsdf__mco;

/* Yield a request at point w->q (already set), resume point k. */
#define FOVSDF__YIELD_P(k, thr_, infl_)                                                            \
    do {                                                                                           \
        w->qe = (thr_); w->qi = (infl_); w->got = 1; w->pc = (k);                                  \
        return 1;                                                                                  \
    case (k):;                                                                                     \
    } while (0)
/* Request ro + tt rd (FLT_MAX without an evaluation when that overflows). */
#define FOVSDF__YIELD_T(k, tt_, infl_)                                                             \
    do {                                                                                           \
        w->q[0] = w->ro[0] + w->rd[0] * (tt_); w->q[1] = w->ro[1] + w->rd[1] * (tt_);              \
        w->q[2] = w->ro[2] + w->rd[2] * (tt_);                                                     \
        if (!fov__finite3(w->q)) { w->res = FLT_MAX; w->got = 0; break; }                          \
        w->qe = fovsdf__thr_ec(m, w->ec, (tt_)); w->qi = (infl_); w->got = 1; w->pc = (k);         \
        return 1;                                                                                  \
    case (k):;                                                                                     \
    } while (0)

FOVSDF__PRIV void fovsdf__mco_init(const fovsdf__marcher *m, fovsdf__mco *w, const float ro[3],
                                   const float rd[3], float t0)
{
    w->ro[0] = ro[0]; w->ro[1] = ro[1]; w->ro[2] = ro[2];
    w->rd[0] = rd[0]; w->rd[1] = rd[1]; w->rd[2] = rd[2];
    w->t0 = t0;
    w->pc = 0;
    w->evals = 0;
    w->mat = 0;
    w->ec = m->eps_cone;
    if (m->per_ray && m->eps_cone > 0.0f) {
        /* the ray's own pixel footprint: a pixel at angle theta off the axis of a pinhole camera
           subtends pixel_angle cos^2(theta) radially and pixel_angle cos(theta) tangentially;
           the smaller one, so wide fields of view do not turn near misses into hits */
        float cz = fovsdf__clampf(fov__dot(rd, m->fwd), 0.0f, 1.0f);
        w->ec = m->eps_cone * cz * cz;
    }
}

/* March ro + t rd from t0 with the marcher's method (see the method enum for the papers):
   one tracer, then the hit refinement. Contract (every method): evaluations only at finite
   points with t <= t_max; a hit has a finite t in [t0, t_max] (t0 after the head-start
   check); a refinement never moves a hit past a point of the ray it has not verified (see
   the refinement below). Returns 1 with a request, 0 when done (kind, t, d, steps, mat). */
FOVSDF__PRIV int fovsdf__mco_run(const fovsdf__marcher *m, fovsdf__mco *w)
{
    float v, den, fac, M, om, u, s, q[3], n[3], c[3], ha, h2, hr, rr, g2;
    int i, k;
    switch (w->pc) {
    case 0:
        w->kind = FOVSDF_MISS;
        if (!(w->t0 <= m->t_max)) { /* nothing to march: a miss for every method */
            w->t = m->t_max; w->d = 0.0f; w->steps = 0;
            w->pc = 9999u;
            return 0;
        }
        if (m->verify_start && w->t0 > 0.0f) {
            /* a heuristic head start (IPR, SKIP) can lie past the surface, inside it: one
               evaluation tells, and such a ray starts over from the camera */
            FOVSDF__YIELD_T(1u, w->t0, m->inflate);
            if (w->res < 0.0f) w->t0 = 0.0f;
        }
        w->t = w->t0; w->d = 0.0f; w->pt = w->t0; w->pd = 0.0f; w->hp = 0; w->have = 0;
        w->steps = 0; w->kind = FOVSDF_MISS;
        if (m->method == FOVSDF_METHOD_RELAXED) {
            /* Keinert et al. 2014, over-relaxed sphere tracing: step omega * d; when the
               unbounding sphere at the new point does not overlap the previous one the step may
               have jumped a surface: go back to the safe point tp + rp and continue with
               omega = 1. */
            w->om = m->omega; w->tp = w->t0; w->rp = 0.0f;
            for (;;) {
                if (w->t > m->t_max) break;
                if (w->steps >= m->max_steps) { /* the last relaxed step is unverified */
                    w->kind = FOVSDF_EXHAUSTED;
                    if (w->have && w->t > w->tp + w->rp) { w->t = w->tp + w->rp; w->d = w->rp; }
                    break;
                }
                FOVSDF__YIELD_T(10u, w->t, m->inflate);
                w->d = w->res;
                if (w->got) w->mat = w->resm;
                ++w->steps;
                if (w->have && w->om > 1.0f && w->d + w->rp < w->t - w->tp) {
                    w->t = w->tp + w->rp; w->om = 1.0f; w->have = 0;
                    continue;
                }
                if (w->d < fovsdf__thr_ec(m, w->ec, w->t)) { w->kind = FOVSDF_HIT; break; }
                w->tp = w->t; w->rp = w->d; w->have = 1;
                w->pt = w->t; w->pd = w->d; w->hp = 1;
                /* an over-relaxed step may only leave the range after the overlap test has
                   seen its end point: stop it at t_max (a plain step past t_max is a safe
                   miss) */
                w->t = (w->t + w->d > m->t_max) ? w->t + w->d
                                                : fov__minf(w->t + w->om * w->d, m->t_max);
            }
        } else if (m->method == FOVSDF_METHOD_AUTORELAXED) {
            /* Ban & Valasek 2023: smooth the slope m of d along the ray (exponential average,
               weight beta) and step omega * d with omega = 2 / (1 - m), the step that reaches
               the surface predicted by the line; back-step to a plain step when the spheres at
               t and t + z do not overlap. A step never ends past t_max; when a plain step
               would, the sphere at t already proves the rest of the range empty: a miss.
               (d is the distance r at t.) */
            w->sl = -1.0f;
            FOVSDF__YIELD_T(20u, w->t, m->inflate);
            w->d = w->res;
            if (w->got) w->mat = w->resm;
            ++w->steps;
            if (w->d < fovsdf__thr_ec(m, w->ec, w->t)) w->kind = FOVSDF_HIT;
            w->z = w->d;
            while (w->kind == FOVSDF_MISS) {
                if (!(w->t + w->d <= m->t_max)) break;
                if (w->steps >= m->max_steps) { w->kind = FOVSDF_EXHAUSTED; break; }
                w->T = fov__minf(w->t + w->z, m->t_max);
                FOVSDF__YIELD_T(21u, w->T, m->inflate);
                w->R = w->res;
                if (w->got) w->mat = w->resm;
                ++w->steps;
                /* (a plain step, z = r, needs no test: T - t may exceed r by the rounding of
                   T) */
                if (w->z > w->d && w->T - w->t > fov__absf(w->R) + w->d) {
                    w->sl = -1.0f; w->z = w->d;
                    continue;
                }
                M = (w->R - w->d) / fov__maxf(w->T - w->t, 1e-20f);
                w->sl += m->beta * (M - w->sl);
                w->pt = w->t; w->pd = w->d; w->hp = 1;
                w->t = w->T; w->d = w->R;
                if (w->d < fovsdf__thr_ec(m, w->ec, w->t)) { w->kind = FOVSDF_HIT; break; }
                om = 2.0f / (1.0f - fovsdf__clampf(w->sl, -1.0f, 0.9f));
                w->z = w->d * fov__maxf(1.0f, om);
            }
        } else if (m->method == FOVSDF_METHOD_BV2018) {
            /* Balint & Valasek 2018: fit a line through the last two distance samples and step
               d * (1 + relax * (dp - rp + d) / (dp + rp - d)), falling back to a plain step
               when the spheres do not overlap. Steps end at t_max at the latest (as
               AUTORELAXED). */
            w->dp = 0.0f; w->rp = 0.0f;
            FOVSDF__YIELD_T(30u, w->t, m->inflate);
            w->d = w->res;
            if (w->got) w->mat = w->resm;
            ++w->steps;
            if (w->d < fovsdf__thr_ec(m, w->ec, w->t)) w->kind = FOVSDF_HIT;
            while (w->kind == FOVSDF_MISS) {
                if (!(w->t + w->d <= m->t_max)) break;
                if (w->steps >= m->max_steps) { w->kind = FOVSDF_EXHAUSTED; break; }
                w->z = w->d;
                if (w->have) {
                    den = w->dp + w->rp - w->d;
                    fac = den > 1e-20f ? (w->dp - w->rp + w->d) / den : 16.0f;
                    w->z = w->d * (1.0f + m->relax * fovsdf__clampf(fac, 0.0f, 16.0f));
                }
                w->T = fov__minf(w->t + w->z, m->t_max);
                FOVSDF__YIELD_T(31u, w->T, m->inflate);
                w->R = w->res;
                if (w->got) w->mat = w->resm;
                ++w->steps;
                if (w->have && w->z > w->d && w->T - w->t > w->d + fov__absf(w->R)) {
                    w->have = 0;
                    continue;
                }
                w->dp = w->T - w->t; w->rp = w->d; w->have = 1;
                w->pt = w->t; w->pd = w->d; w->hp = 1;
                w->t = w->T; w->d = w->R;
                if (w->d < fovsdf__thr_ec(m, w->ec, w->t)) { w->kind = FOVSDF_HIT; break; }
            }
        } else {
            /* Hart 1996, Algorithm 1 of the thesis: t += d until d < threshold or t > t_max. */
            for (;;) {
                if (w->t > m->t_max) break;
                if (w->steps >= m->max_steps) { w->kind = FOVSDF_EXHAUSTED; break; }
                FOVSDF__YIELD_T(40u, w->t, m->inflate);
                w->d = w->res;
                if (w->got) w->mat = w->resm;
                ++w->steps;
                if (w->d < fovsdf__thr_ec(m, w->ec, w->t)) { w->kind = FOVSDF_HIT; break; }
                w->pt = w->t; w->pd = w->d; w->hp = 1;
                w->t += w->d;
            }
        }
        /* the hit refinement (see the comment above) */
        if (w->kind != FOVSDF_HIT) goto done;
        if (!w->hp && w->d > 0.0f && fov__finite(w->d)) {
            /* hit at the first evaluation (a head start next to the surface): one plain step
               (inside the sample's sphere) gives the second sample the secant needs (kept only
               when it gets closer) */
            w->t1 = w->t; w->d1 = w->d;
            w->dt = w->d; w->mg = 0.0f;
            w->t2 = w->t + w->dt;
            if (w->t2 <= m->t_max && w->t2 >= w->t0) {
                FOVSDF__YIELD_T(50u, w->t2, 1.0f);
                w->m2 = w->got ? w->resm : 0;
                v = w->res;
                if (fov__absf(v) < fov__absf(w->d) && v > -fovsdf__mg_ec(m, w->ec, w->t2) &&
                    (w->dt <= fov__maxf(w->d, 0.0f) || w->dt <= w->d + v + 2.0f * w->mg)) {
                    w->t = w->t2; w->d = v; w->mat = w->m2;
                    w->pt = w->t1; w->pd = w->d1; w->hp = 1;
                }
            }
        }
        if (!(w->hp && w->pt < w->t && w->pd > w->d)) goto done;
        w->tt = w->t; w->dd = w->d;
        w->slope = (w->dd - w->pd) / (w->tt - w->pt);
        w->dt = -w->dd / w->slope;
        w->lim = 64.0f * fov__absf(w->dd);
        w->mg = fovsdf__mg_ec(m, w->ec, w->tt);
        w->tb = w->tt; w->db = w->dd; w->mb = 0;
        w->ok = 0;
        /* the secant's end point has d2 ~ 0, so a forward move longer than d + 2 mg cannot be
           verified by the spheres: try the empty ball (up to 1024 |d| ahead), else move by d
           (within the sphere; one evaluation) */
        if (w->dd > 0.0f && fov__finite(w->dt) && w->dt > w->dd + 2.0f * w->mg) {
            /* the empty-ball certificate (see its comment above) */
            w->t2 = w->tt + fov__minf(w->dt, 1024.0f * w->dd);
            if (!(w->t2 <= m->t_max) || !(w->t2 > w->tt + w->dd)) goto ball_end;
            for (i = 0; i < 3; ++i) {
                w->a[i] = w->ro[i] + w->rd[i] * (w->tt + w->dd);
                w->f[i] = w->ro[i] + w->rd[i] * w->t2;
            }
            if (!fov__finite3(w->a) || !fov__finite3(w->f)) goto ball_end;
            w->q[0] = w->f[0]; w->q[1] = w->f[1]; w->q[2] = w->f[2];
            FOVSDF__YIELD_P(60u, fovsdf__thr_ec(m, w->ec, w->t2), 1.0f);
            w->fb = w->res; w->m2 = w->resm;
            /* the secant found the surface (F at least 4 times closer than the hit; a ray
               running along a curved surface keeps the hit where the threshold stopped it),
               and F is not inside by more than the margin */
            if (!(fov__absf(w->fb) <= 0.25f * w->dd && w->fb > -fovsdf__mg_ec(m, w->ec, w->t2)))
                goto ball_end;
            /* the normal: the secant's slope is the derivative along the ray; two forward
               differences from F across it give the rest. The step: at least the threshold,
               and large enough that the float noise of the differences (u, 8 ulps of the
               position) tilts n by less than sqrt(mg / H) (a tilt theta lowers f(c) by
               H theta^2 / 2); H is about (t2 - t)^2 / (2 d) for a plane (sin(incidence) =
               d / (t2 - t)) */
            u = m->ulp0 + m->ulp1 * w->t2;
            s = w->t2 - w->tt;
            w->e = fov__maxf(fovsdf__thr_ec(m, w->ec, w->t2),
                             FOV__SQRT(u * (s * s / (2.0f * w->dd))));
            {
                float ax[3] = { 0.0f, 0.0f, 0.0f };
                k = fov__absf(w->rd[0]) <= fov__absf(w->rd[1])
                        ? (fov__absf(w->rd[0]) <= fov__absf(w->rd[2]) ? 0 : 2)
                        : (fov__absf(w->rd[1]) <= fov__absf(w->rd[2]) ? 1 : 2);
                ax[k] = 1.0f;
                fov__cross(w->rd, ax, w->b1);
            }
            if (!(fovsdf__normalize(w->b1) > 0.0f)) goto ball_end;
            fov__cross(w->rd, w->b1, w->b2);
            for (i = 0; i < 3; ++i) w->q[i] = w->f[i] + w->e * w->b1[i];
            if (!fov__finite3(w->q)) goto ball_end;
            FOVSDF__YIELD_P(61u, fovsdf__thr_ec(m, w->ec, w->t2), 1.0f);
            w->g1 = w->res - w->fb;
            for (i = 0; i < 3; ++i) w->q[i] = w->f[i] + w->e * w->b2[i];
            if (!fov__finite3(w->q)) goto ball_end;
            FOVSDF__YIELD_P(62u, fovsdf__thr_ec(m, w->ec, w->t2), 1.0f);
            g2 = w->res - w->fb;
            for (i = 0; i < 3; ++i)
                n[i] = w->slope * w->e * w->rd[i] + w->g1 * w->b1[i] + g2 * w->b2[i];
            if (!(fovsdf__normalize(n) > 0.0f)) goto ball_end;
            for (i = 0; i < 3; ++i) q[i] = w->a[i] - w->f[i];
            ha = fov__dot(q, n); /* A's height above the tangent plane at F */
            h2 = fov__dot(q, q);
            if (!(ha > 0.0f)) goto ball_end;
            hr = h2 / (2.0f * ha); /* the ball through A tangent at F */
            /* |A - c|, |F - c| and f(c) round by a few ulps of H: that must leave most of the
               margin */
            if (!(hr <= FLT_MAX) || !(8.0f * FLT_EPSILON * hr < w->mg)) goto ball_end;
            for (i = 0; i < 3; ++i) c[i] = w->f[i] + hr * n[i];
            if (!fov__finite3(c)) goto ball_end;
            /* keep what the test needs after the evaluation: c in a, hr in b2[0] */
            for (i = 0; i < 3; ++i) { w->a[i] -= c[i]; w->f[i] -= c[i]; w->q[i] = c[i]; }
            w->b2[0] = hr;
            FOVSDF__YIELD_P(63u, fovsdf__thr_ec(m, w->ec, w->t2), 1.0f);
            v = w->res; /* f(c) */
            if (!(v > 0.0f) || !(v < FLT_MAX)) goto ball_end;
            rr = v + w->mg - 4.0f * FLT_EPSILON * w->b2[0];
            if (!(fov__len(w->a) <= rr && fov__len(w->f) <= rr)) goto ball_end;
            w->tb = w->t2; w->db = w->fb; w->mb = w->m2;
            w->ok = 1;
        ball_end:;
        }
        if (w->ok) {
            w->t = w->tb; w->d = w->db; w->mat = w->mb;
            w->dt = 0.0f;
        } else {
            w->dt = fovsdf__clampf(w->dt, -w->lim, w->lim);
            if (w->dd > 0.0f && w->dt > w->dd + 2.0f * w->mg) w->dt = w->dd;
        }
        if (!fov__is0(w->dt) && fov__finite(w->dt)) {
            /* one refinement move of the hit (t, d) by dt, evaluated at the exact scene
               (inflate 1): kept when t + dt is in [t0, t_max], lowers |d|, is not inside by
               more than the margin, and passes no point the march has not verified: a backward
               move or one of at most d (inside the last sample's sphere), or a forward one
               whose end sphere (radius d2) overlaps that sphere, d + d2 + 2 mg >= dt */
            w->t2 = w->t + w->dt;
            if (w->t2 <= m->t_max && w->t2 >= w->t0) {
                FOVSDF__YIELD_T(51u, w->t2, 1.0f);
                w->m2 = w->got ? w->resm : 0;
                v = w->res;
                if (fov__absf(v) < fov__absf(w->d) && v > -fovsdf__mg_ec(m, w->ec, w->t2) &&
                    (w->dt <= fov__maxf(w->d, 0.0f) || w->dt <= w->d + v + 2.0f * w->mg)) {
                    w->t = w->t2; w->d = v; w->mat = w->m2;
                }
            }
        }
    done:
        w->pc = 9999u;
        return 0;
    default:
        return 0;
    }
}
#undef FOVSDF__YIELD_P
#undef FOVSDF__YIELD_T

/* The march point by point (a coroutine fed one evaluation at a time). */
FOVSDF__PRIV void fovsdf__march(const fovsdf__marcher *m, const float ro[3], const float rd[3],
                                float t0, fovsdf_hit *h, int32_t *mat, fovsdf_stats *st)
{
    fovsdf__mco w;
    fovsdf__mco_init(m, &w, ro, rd, t0);
    if (mat) w.mat = *mat; /* untouched unless an evaluation reports one */
    while (fovsdf__mco_run(m, &w)) {
        w.res = fovsdf__eval_in(m->sc, m->inv_lip, w.q, w.qe, w.qi, &w.resm, st);
        ++w.evals;
    }
    h->kind = w.kind;
    h->t = w.kind == FOVSDF_MISS ? m->t_max : w.t;
    h->dist = w.d;
    h->steps = w.steps;
    h->evals = w.evals;
    if (mat) *mat = w.mat;
}

FOVSDF__PRIV void fovsdf__marcher_from_ctx(const fovsdf_ctx *c, fovsdf__marcher *m,
                                           const float ro[3])
{
    m->sc = &c->scene;
    m->pv = 0;
    m->inv_lip = 1.0f / c->scene.lipschitz;
    /* per-image methods (CONE) trace single rays with their finishing tracer */
    m->method =
        c->cfg.method <= (uint32_t)FOVSDF_METHOD_BV2018 ? c->cfg.method : c->cfg.finish - 1u;
    m->max_steps = c->cfg.max_steps;
    m->eps = c->cfg.eps_mode == FOVSDF_EPS_CONE ? 0.0f : c->cfg.eps;
    m->eps_cone = c->cfg.eps_mode == FOVSDF_EPS_ABSOLUTE ? 0.0f : c->cfg.eps_px * c->pixel_angle;
    m->ulp0 = fovsdf__ulp0(ro);
    m->ulp1 = 8.0f * FLT_EPSILON;
    m->t_max = c->t_max;
    m->omega = c->cfg.omega;
    m->beta = c->cfg.ar_beta;
    m->relax = c->cfg.bv_relax;
    m->inflate = 1.0f;
    m->verify_start = c->cfg.method == FOVSDF_METHOD_IPR || c->cfg.method == FOVSDF_METHOD_SKIP ||
                      c->cfg.method == FOVSDF_METHOD_FIPR;
    m->per_ray = 1;
    m->fwd[0] = c->fwd[0]; m->fwd[1] = c->fwd[1]; m->fwd[2] = c->fwd[2];
}

FOVSDF_API fov_result fovsdf_march(const fovsdf_scene *scene, const fovsdf_march_params *mp,
                                   const float ro[3], const float rd[3], float t_start,
                                   fovsdf_hit *hit, fovsdf_stats *stats)
{
    fovsdf__marcher m;
    float l;
    if (!scene || !mp || !ro || !rd || !hit) return FOV_ERR_NULL;
    if (!scene->dist && !scene->dist_ex && !scene->dist_batch) return FOV_ERR_NULL;
    if (!fov__finite3(ro) || !fov__finite3(rd) || !fov__finite(t_start) || !fov__finite(mp->eps) ||
        !fov__finite(mp->eps_cone) || !fov__finite(mp->t_max) || !fov__finite(mp->omega) ||
        !fov__finite(mp->ar_beta) || !fov__finite(mp->bv_relax) || !fov__finite(scene->lipschitz))
        return FOV_ERR_NOT_FINITE;
    if (mp->method > (uint32_t)FOVSDF_METHOD_BV2018 || mp->max_steps == 0 || mp->eps < 0.0f ||
        mp->eps_cone < 0.0f || !(mp->eps > 0.0f || mp->eps_cone > 0.0f) || !(mp->t_max > 0.0f) ||
        t_start < 0.0f || scene->lipschitz < 0.0f)
        return FOV_ERR_INVALID_ARG;
    /* beyond 1e18: float cannot resolve it (NUMERICS) */
    if (!fovsdf__coord_ok(ro)) return FOV_ERR_INVALID_ARG;
    if (mp->max_steps > FOVSDF_MAX_STEPS) return FOV_ERR_LIMIT;
    if (mp->method == FOVSDF_METHOD_RELAXED && !(mp->omega >= 1.0f && mp->omega < 2.0f))
        return FOV_ERR_INVALID_ARG;
    if (mp->method == FOVSDF_METHOD_AUTORELAXED && !(mp->ar_beta > 0.0f && mp->ar_beta <= 1.0f))
        return FOV_ERR_INVALID_ARG;
    if (mp->method == FOVSDF_METHOD_BV2018 && !(mp->bv_relax > 0.0f && mp->bv_relax <= 1.0f))
        return FOV_ERR_INVALID_ARG;
    l = fov__len(rd);
    if (!(l > 0.999f && l < 1.001f)) return FOV_ERR_INVALID_ARG;
    m.sc = scene;
    m.inv_lip = scene->lipschitz > 0.0f ? 1.0f / scene->lipschitz : 1.0f;
    m.method = mp->method;
    m.max_steps = mp->max_steps;
    m.eps = mp->eps;
    m.eps_cone = mp->eps_cone;
    m.ulp0 = fovsdf__ulp0(ro);
    m.ulp1 = 8.0f * FLT_EPSILON;
    m.t_max = mp->t_max;
    m.omega = mp->omega;
    m.beta = mp->ar_beta;
    m.relax = mp->bv_relax;
    m.inflate = 1.0f;
    m.verify_start = 0;
    m.per_ray = 0; /* eps_cone is the caller's, per ray */
    m.pv = 0;
    m.fwd[0] = 0.0f; m.fwd[1] = 0.0f; m.fwd[2] = 1.0f;
    fovsdf__march(&m, ro, rd, t_start, hit, 0, stats);
    return FOV_OK;
}

/* ---- shading helpers ------------------------------------------------------------------------ */
FOVSDF_API float fovsdf_distance(const fovsdf_ctx *c, const float p[3], int32_t *material,
                                 fovsdf_stats *st)
{
    if (!c || !p) return FLT_MAX;
    return fovsdf__eval_sc(&c->scene, 1.0f / c->scene.lipschitz, p, c->cfg.eps, material, st);
}

FOVSDF_API fov_result fovsdf_distance_batch(const fovsdf_ctx *c, uint32_t n, const float *x,
                                            const float *y, const float *z, float *d,
                                            int32_t *material, fovsdf_stats *st)
{
    float eps[FOVSDF_BATCH];
    uint32_t k, i;
    if (!c) return FOV_ERR_NULL;
    if (n == 0) return FOV_OK;
    if (!x || !y || !z || !d)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NULL, "distance_batch: x, y, z or d is NULL");
    for (i = 0; i < FOVSDF_BATCH; ++i) eps[i] = c->cfg.eps;
    for (k = 0; k < n; k += FOVSDF_BATCH) {
        uint32_t m = n - k < FOVSDF_BATCH ? n - k : FOVSDF_BATCH;
        fovsdf__eval_batch(&c->scene, 1.0f / c->scene.lipschitz, m, x + k, y + k, z + k, eps,
                           1.0f, 0, d + k, material ? material + k : 0, st);
    }
    return FOV_OK;
}

/* The tetrahedron technique: n = sum_i k_i f(p + h k_i), k_i = (+-1, +-1, +-1) with an even
   number of minus signs; 4 evaluations. */
static const float fovsdf__tet[4][3] = { { 1.0f, -1.0f, -1.0f }, { -1.0f, -1.0f, 1.0f },
                                         { -1.0f, 1.0f, -1.0f }, { 1.0f, 1.0f, 1.0f } };

/* The normal from the 4 distances (FLT_MAX already mapped to 0). */
FOVSDF__PRIV void fovsdf__normal_from(const float dv[4], float n[3])
{
    int i;
    n[0] = n[1] = n[2] = 0.0f;
    for (i = 0; i < 4; ++i) {
        n[0] += fovsdf__tet[i][0] * dv[i]; n[1] += fovsdf__tet[i][1] * dv[i];
        n[2] += fovsdf__tet[i][2] * dv[i];
    }
    if (!fov__finite3(n)) { /* distances near FLT_MAX overflowed the sums: each k column sums
                               to 0, so differences from the first give the same normal */
        n[0] = n[1] = n[2] = 0.0f;
        for (i = 1; i < 4; ++i) {
            float d = dv[i] - dv[0];
            n[0] += fovsdf__tet[i][0] * d; n[1] += fovsdf__tet[i][1] * d;
            n[2] += fovsdf__tet[i][2] * d;
        }
    }
    if (!(fovsdf__normalize(n) > 0.0f)) { n[0] = 0.0f; n[1] = 1.0f; n[2] = 0.0f; }
}

FOVSDF_API void fovsdf_normal(const fovsdf_ctx *c, const float p[3], float h, float n[3],
                              fovsdf_stats *st)
{
    fovsdf_stats local;
    int i;
    float inv, dv[4];
    if (!c || !p || !n) return;
    if (!st) { FOV_MEMSET(&local, 0, sizeof local); st = &local; }
    inv = 1.0f / c->scene.lipschitz;
    for (i = 0; i < 4; ++i) {
        float q[3], d;
        q[0] = p[0] + h * fovsdf__tet[i][0]; q[1] = p[1] + h * fovsdf__tet[i][1];
        q[2] = p[2] + h * fovsdf__tet[i][2];
        d = fovsdf__eval_sc(&c->scene, inv, q, 0.0f, 0, st);
        dv[i] = d >= FLT_MAX ? 0.0f : d;
    }
    st->evals_normal += 4;
    fovsdf__normal_from(dv, n);
}

/* Algorithm 2 as a stepper (the shadow rays of the wavefront and of fovsdf__shadow): evaluates
   the scene at p + t l, and ends with res (the light fraction) and t_att, where the penumbra
   began (the first t with k h / t < 1; t when the light was never attenuated). */
typedef struct fovsdf__sco {
    float p[3], l[3], t, t_end, t_stop, k, res, floor0, t_att; /* t_stop <= t_end: see the
                                                                 wavefront's shadow proof */
    uint32_t i, evals, steps;       /* steps: the budget */
    int peri;                        /* beyond shadow_fov_deg */
} fovsdf__sco;

/* Starts a shadow ray; returns 1 when it needs an evaluation (at p + t l). */
FOVSDF__PRIV int fovsdf__sco_init(const fovsdf_ctx *c, fovsdf__sco *s, const float p[3],
                                  const float l[3], float t_start, float t_end, float k, int peri,
                                  fovsdf_stats *st)
{
    s->peri = peri;
    s->steps = peri && c->cfg.shadow_fov_steps ? c->cfg.shadow_fov_steps : c->cfg.shadow_steps;
    s->p[0] = p[0]; s->p[1] = p[1]; s->p[2] = p[2];
    s->l[0] = l[0]; s->l[1] = l[1]; s->l[2] = l[2];
    s->res = 1.0f; s->t = t_start; s->t_end = t_end; s->t_stop = t_end; s->k = k;
    s->t_att = -1.0f;
    s->i = 0; s->evals = 0;
    if (!(s->t > 0.0f)) s->t = 1e-6f;
    s->floor0 = 8.0f * FLT_EPSILON * fov__len(p);
    st->shadow_rays++;
    return s->i < s->steps && s->t < s->t_stop;
}
/* Feeds the distance h at p + t l; returns 1 when the ray needs another one. */
FOVSDF__PRIV int fovsdf__sco_next(const fovsdf_ctx *c, fovsdf__sco *s, float h)
{
    ++s->evals;
    if (s->t_att < 0.0f && s->k * h < s->t) s->t_att = s->t;
    s->res = fov__minf(s->res, s->k * h / s->t);
    if (s->res < c->cfg.shadow_eps) { s->res = 0.0f; return 0; }
    {
        float tp = s->t;
        s->t += fov__maxf(h, s->floor0 + 8.0f * FLT_EPSILON * s->t);
        ++s->i;
        if (s->peri && s->i >= s->steps && s->steps < c->cfg.shadow_steps && s->t < s->t_stop &&
            s->k * h < tp)
            s->res = 0.0f; /* beyond shadow_fov_deg, out of its cut budget in a penumbra: dark */
    }
    return s->i < s->steps && s->t < s->t_stop;
}

/* Algorithm 2 core, point by point, on the scene scaled by inflate (Skipping Spheres'
   low-resolution shadow rays); *t_out: where the penumbra began, or the distance reached. */
FOVSDF__PRIV float fovsdf__shadow(const fovsdf_ctx *c, const float p[3], const float l[3],
                                  float t_start, float t_end, float k, float inflate, int peri,
                                  float *t_out, fovsdf_stats *st)
{
    fovsdf__sco s;
    float inv = 1.0f / c->scene.lipschitz;
    int more = fovsdf__sco_init(c, &s, p, l, t_start, t_end, k, peri, st);
    while (more) {
        float q[3], h;
        q[0] = s.p[0] + s.l[0] * s.t; q[1] = s.p[1] + s.l[1] * s.t; q[2] = s.p[2] + s.l[2] * s.t;
        h = fovsdf__eval_in(&c->scene, inv, q, c->cfg.eps, inflate, 0, st);
        more = fovsdf__sco_next(c, &s, h);
    }
    st->evals_shadow += s.evals;
    *t_out = s.t_att >= 0.0f ? s.t_att : s.t;
    return fovsdf__clampf(s.res, 0.0f, 1.0f);
}

FOVSDF_API float fovsdf_soft_shadow(const fovsdf_ctx *c, const float p[3], const float l[3],
                                    float t_start, float t_end, float k, fovsdf_stats *st)
{
    /* Algorithm 2 of the thesis (Quilez's penumbra estimate): res = min(res, k h / t); full
       shadow as soon as res < eps (the algorithm's strict comparison); t_start is the head
       start. */
    fovsdf_stats local;
    float tr;
    if (!c || !p || !l) return 1.0f;
    if (!st) { FOV_MEMSET(&local, 0, sizeof local); st = &local; }
    return fovsdf__shadow(c, p, l, t_start, t_end, k, 1.0f, 0, &tr, st);
}

FOVSDF__PRIV void fovsdf__albedo(const fovsdf_ctx *c, const float p[3], int32_t mat, float rgb[3])
{
    static const float pal[8][3] = {
        { 0.80f, 0.80f, 0.80f }, { 0.0f, 0.0f, 0.0f }, { 0.85f, 0.30f, 0.25f },
        { 0.30f, 0.55f, 0.85f }, { 0.90f, 0.75f, 0.30f }, { 0.35f, 0.75f, 0.40f },
        { 0.70f, 0.45f, 0.80f }, { 0.92f, 0.90f, 0.85f }
    };
    if (c->scene.albedo) {
        int i;
        c->scene.albedo(p, mat, rgb, c->scene.user);
        for (i = 0; i < 3; ++i)
            if (!fov__finite(rgb[i])) rgb[i] = 0.0f; /* a user's NaN never reaches the image */
        return;
    }
    /* checkerboard on x/z, unit squares (the clamp maps NaN to -1e6: a defined int) */
    if (mat == 1) {
        int32_t ix = (int32_t)FOV__FLOOR(fovsdf__clampf(p[0], -1e6f, 1e6f));
        int32_t iz = (int32_t)FOV__FLOOR(fovsdf__clampf(p[2], -1e6f, 1e6f));
        float v = ((ix + iz) & 1) ? 0.85f : 0.30f;
        rgb[0] = rgb[1] = rgb[2] = v;
        return;
    }
    if (mat < 0) mat = 0;
    rgb[0] = pal[mat & 7][0]; rgb[1] = pal[mat & 7][1]; rgb[2] = pal[mat & 7][2];
}

FOVSDF_API void fovsdf_sky(const fovsdf_ctx *c, const float rd[3], float rgb[3])
{
    float s;
    int i;
    if (!c || !rd || !rgb) return;
    s = fovsdf__clampf(rd[1], 0.0f, 1.0f);
    for (i = 0; i < 3; ++i)
        rgb[i] = fovsdf__clampf(c->scene.sky_horizon[i] +
                                (c->scene.sky_zenith[i] - c->scene.sky_horizon[i]) * s, 0.0f,
                                FOVSDF__RGB_MAX);
}

/* Direction to light i from p (unit), its distance, attenuation; 0 when it cannot light p. */
FOVSDF__PRIV int fovsdf__light_dir(const fovsdf_ctx *c, uint32_t i, const float p[3], float l[3],
                                   float *dist, float *att)
{
    const fovsdf_light *L = &c->scene.lights[i];
    *att = 1.0f;
    if (L->type == FOVSDF_LIGHT_POINT) {
        l[0] = L->v[0] - p[0]; l[1] = L->v[1] - p[1]; l[2] = L->v[2] - p[2];
        *dist = fovsdf__normalize(l);
        if (!(*dist > 0.0f)) return 0;
        if (L->range > 0.0f) {
            if (*dist > 8.0f * L->range) return 0; /* no light reaches: no shadow ray */
            *att = 1.0f / (1.0f + *dist * *dist / (L->range * L->range));
        }
    } else {
        l[0] = L->v[0]; l[1] = L->v[1]; l[2] = L->v[2];
        if (!(fovsdf__normalize(l) > 0.0f)) return 0;
        *dist = c->t_max;
    }
    return 1;
}

/* Light i at a hit p with normal n: 0 when it adds nothing (no light reaches p, or p faces
   away: no shadow ray either); else its direction l, ndl, att and, when it casts a shadow
   here, shadow 1 with the shadow ray's start q (p off the surface by off), t0, dist and k. */
typedef struct fovsdf__lit { float l[3], ndl, att, q[3], t0, dist, k; int shadow; } fovsdf__lit;
FOVSDF__PRIV int fovsdf__light_prep(const fovsdf_ctx *c, uint32_t i, const float p[3],
                                    const float n[3], float off, const float *sh_start, int peri,
                                    fovsdf__lit *o)
{
    const fovsdf_light *L = &c->scene.lights[i];
    if (!fovsdf__light_dir(c, i, p, o->l, &o->dist, &o->att)) return 0;
    o->ndl = fov__dot(n, o->l);
    if (o->ndl <= 0.0f) return 0; /* facing away: no light, no shadow ray */
    o->shadow = 0;
    if (c->cfg.shading == FOVSDF_SHADE_FULL && L->shadow_k >= 0.0f) {
        o->k = L->shadow_k > 0.0f ? L->shadow_k : 16.0f;
        o->t0 = c->cfg.shadow_t0;
        if (peri) { /* beyond shadow_fov_deg: shadow_fov_t0_px pixel footprints at p */
            float dv[3], t0f;
            dv[0] = p[0] - c->origin[0]; dv[1] = p[1] - c->origin[1]; dv[2] = p[2] - c->origin[2];
            t0f = c->cfg.shadow_fov_t0_px * c->pixel_angle * fov__len(dv);
            if (t0f > o->t0) o->t0 = t0f;
        }
        if (sh_start && sh_start[i] > o->t0) o->t0 = sh_start[i];
        o->q[0] = p[0] + n[0] * off; o->q[1] = p[1] + n[1] * off; o->q[2] = p[2] + n[2] * off;
        o->shadow = o->t0 < o->dist; /* else fully lit */
    }
    return 1;
}
/* 1 when the shaded ray rd (from the camera's pinhole) is beyond shadow_fov_deg of the gaze
   (eccentricity of its image point, fov_display): cheaper shadow rays. The image point
   (x, y) with u = rd.right / rd.fwd, v = rd.up / rd.fwd is x = W/2 + a u, y = H/2 - a v,
   a = H / (2 tan(fov_y / 2)); the eye's ray through it, (x - cx, y - cy, f) scaled by rd.fwd,
   against the gaze ray g by cosines (no atan2). */
FOVSDF__PRIV int fovsdf__shadow_far(const fovsdf_ctx *c, const float rd[3])
{
    float rf, a, e[3];
    if (!(c->cfg.shadow_fov_deg > 0.0f)) return 0;
    rf = fov__dot(rd, c->fwd);
    if (!(rf > 0.0f)) return 1; /* behind the image plane: far from any gaze on it */
    a = 0.5f * (float)c->cam.height / c->tan_half_y;
    if (c->off_axis) { /* the axis's image point is (a tl, a tt), not the centre */
        e[0] = a * fov__dot(rd, c->right) - (c->ecc.cx - a * c->tan4[0]) * rf;
        e[1] = (c->ecc.cy - a * c->tan4[3]) * -rf - a * fov__dot(rd, c->up);
    } else {
        e[0] = a * fov__dot(rd, c->right) - (c->ecc.cx - 0.5f * (float)c->cam.width) * rf;
        e[1] = (c->ecc.cy - 0.5f * (float)c->cam.height) * -rf - a * fov__dot(rd, c->up);
    }
    e[2] = c->ecc.f_px * rf;
    return fov__dot(e, c->ecc.g) < c->shadow_fov_cos * fov__len(e);
}

/* The offset of shadow rays from the surface at p. */
FOVSDF__PRIV float fovsdf__shadow_off(const fovsdf_ctx *c, const float p[3])
{
    return fov__maxf(2.0f * c->cfg.eps, 16.0f * FLT_EPSILON * fov__len(p));
}

FOVSDF__PRIV void fovsdf__shade(const fovsdf_ctx *c, const float p[3], const float n[3],
                                int32_t material, float rgb[3], const float *sh_start, int peri,
                                fovsdf_stats *st)
{
    float alb[3], acc[3], off;
    uint32_t i;
    fovsdf__albedo(c, p, material, alb);
    acc[0] = c->scene.ambient[0]; acc[1] = c->scene.ambient[1]; acc[2] = c->scene.ambient[2];
    off = fovsdf__shadow_off(c, p);
    for (i = 0; i < c->scene.num_lights; ++i) {
        const fovsdf_light *L = &c->scene.lights[i];
        fovsdf__lit lt;
        float sh = 1.0f, tr;
        if (!fovsdf__light_prep(c, i, p, n, off, sh_start, peri, &lt)) continue;
        if (lt.shadow)
            sh = fovsdf__shadow(c, lt.q, lt.l, lt.t0, lt.dist, lt.k, 1.0f, peri, &tr, st);
        acc[0] += L->color[0] * lt.ndl * lt.att * sh;
        acc[1] += L->color[1] * lt.ndl * lt.att * sh;
        acc[2] += L->color[2] * lt.ndl * lt.att * sh;
    }
    /* NaN (0 * inf): 0 */
    for (i = 0; i < 3u; ++i) rgb[i] = fovsdf__clampf(alb[i] * acc[i], 0.0f, FOVSDF__RGB_MAX);
}

FOVSDF_API void fovsdf_shade(const fovsdf_ctx *c, const float p[3], const float n[3],
                             const float rd[3], int32_t material, float rgb[3], fovsdf_stats *st)
{
    fovsdf_stats local;
    if (!c || !p || !n || !rd || !rgb) return;
    if (!st) { FOV_MEMSET(&local, 0, sizeof local); st = &local; }
    fovsdf__shade(c, p, n, material, rgb, NULL, fovsdf__shadow_far(c, rd), st);
}

/* ---- context ------------------------------------------------------------------------------- */
FOVSDF_API fovsdf_acuity fovsdf_acuity_default(void)
{
    fovsdf_acuity a;
    a.A = 0.90964f;
    a.rate = 0.20651f;
    a.C = 0.00792f;
    a.fovea_deg = 7.5f;
    a.outer_deg = 0.0f;
    return a;
}

FOVSDF_API float fovsdf_acuity_p(const fovsdf_acuity *a, float w)
{
    float p;
    if (!a || !fov__finite(w) || !fov__finite(a->A) || !fov__finite(a->rate) || !fov__finite(a->C))
        return 0.0f;
    if (w <= a->fovea_deg) return 1.0f;
    if (a->outer_deg > 0.0f && w > a->outer_deg) return 0.0f;
    p = a->A * FOV__EXP(-a->rate * w) + a->C;
    return fovsdf__clampf(p, 0.0f, 1.0f);
}

FOVSDF_API float fovsdf_u01(uint32_t seed, uint32_t x, uint32_t y, uint32_t frame)
{
    /* integer mixing (murmur3-style finaliser over the combined key) */
    uint32_t h = seed ^ 0x9e3779b9u;
    h ^= x * 0x85ebca6bu; h = (h << 13) | (h >> 19); h = h * 5u + 0xe6546b64u;
    h ^= y * 0xc2b2ae35u; h = (h << 13) | (h >> 19); h = h * 5u + 0xe6546b64u;
    h ^= frame * 0x27d4eb2fu; h = (h << 13) | (h >> 19); h = h * 5u + 0xe6546b64u;
    h ^= h >> 16; h *= 0x85ebca6bu; h ^= h >> 13; h *= 0xc2b2ae35u; h ^= h >> 16;
    return (float)(h >> 8) * (1.0f / 16777216.0f); /* 24 bits: exact in float */
}

FOVSDF_API fov_result fovsdf_memory_size(const fovsdf_config *cfg, const fovsdf_camera *cam,
                                         size_t *bytes)
{
    fovsdf_config c;
    fov_result r;
    const fov_logger *lg = cfg ? &cfg->logger : 0;
    if (!bytes) FOVSDF__FAIL(lg, FOV_ERR_NULL, "memory_size: bytes is NULL");
    *bytes = 0;
    if (cfg) {
        r = fovsdf_config_resolve(cfg, &c);
        if (r != FOV_OK) return r;
    }
    if (cam && (cam->width == 0 || cam->height == 0))
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "memory_size: cam.width and cam.height must be >= 1");
    if (cam && (cam->width > FOVSDF_MAX_DIM || cam->height > FOVSDF_MAX_DIM))
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT,
                     "memory_size: cam.width or cam.height above FOVSDF_MAX_DIM");
    return FOV_OK;
}

FOVSDF_API void fovsdf_output_init(fovsdf_output *o)
{
    if (o) FOV_MEMSET(o, 0, sizeof *o);
}

FOVSDF_API void fovsdf_stats_init(fovsdf_stats *st)
{
    if (st) FOV_MEMSET(st, 0, sizeof *st);
}

FOVSDF_API void fovsdf_stats_add(fovsdf_stats *a, const fovsdf_stats *s)
{
    if (!a || !s) return;
    a->evals += s->evals; a->evals_primary += s->evals_primary; a->evals_normal += s->evals_normal;
    a->evals_shadow += s->evals_shadow; a->evals_lowres += s->evals_lowres; a->rays += s->rays;
    a->shadow_rays += s->shadow_rays; a->hits += s->hits; a->exhausted += s->exhausted;
    a->prims += s->prims; a->prims_skipped += s->prims_skipped;
}

FOVSDF__PRIV fov_result fovsdf__scene_check(const fovsdf_scene *s, const fov_logger *lg)
{
    uint32_t i;
    if (!s->dist && !s->dist_ex && !s->dist_batch)
        FOVSDF__FAIL(lg, FOV_ERR_NULL,
                     "init: scene.dist, scene.dist_ex and scene.dist_batch are all NULL");
    if (!fov__finite(s->lipschitz))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "init: scene.lipschitz is NaN or infinite");
    if (!fov__finite(s->t_max))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "init: scene.t_max is NaN or infinite");
    if (!fov__finite3(s->ambient))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "init: scene.ambient is NaN or infinite");
    if (!fov__finite3(s->sky_zenith) || !fov__finite3(s->sky_horizon))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE,
                     "init: scene.sky_zenith or sky_horizon NaN or infinite");
    if (s->lipschitz < 0.0f)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: scene.lipschitz must be >= 0");
    if (s->t_max < 0.0f) FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: scene.t_max must be >= 0");
    if (s->num_lights > FOVSDF_MAX_LIGHTS)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT, "init: scene.num_lights above FOVSDF_MAX_LIGHTS");
    for (i = 0; i < s->num_lights; ++i) {
        const fovsdf_light *L = &s->lights[i];
        if (!fov__finite3(L->v) || !fov__finite3(L->color) || !fov__finite(L->range) ||
            !fov__finite(L->shadow_k))
            FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE,
                         "init: scene.lights[]: v, color, range or shadow_k not finite");
        if (L->type >= (uint32_t)_FOVSDF_LIGHT_NUM)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                         "init: scene.lights[].type unknown (see fovsdf_light_type)");
        if (L->range < 0.0f)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: scene.lights[].range must be >= 0");
    }
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_init(fovsdf_ctx *ctx, const fovsdf_config *cfg,
                                  const fovsdf_scene *scene, const fovsdf_camera *cam,
                                  fov_gaze gaze, void *mem, size_t mem_size)
{
    fovsdf_config c;
    const fov_logger *lg = cfg ? &cfg->logger : 0;
    fov_result r;
    size_t need;
    float tanh, fov, rt[3], up[3], fw[3], rt_o[3];
    uint32_t i;
    int off;
    fov_ecc_model em;
    if (!ctx) FOVSDF__FAIL(lg, FOV_ERR_NULL, "init: ctx is NULL");
    if (!scene) FOVSDF__FAIL(lg, FOV_ERR_NULL, "init: scene is NULL");
    if (!cam) FOVSDF__FAIL(lg, FOV_ERR_NULL, "init: cam is NULL");
    if (cfg) {
        r = fovsdf_config_resolve(cfg, &c);
        if (r != FOV_OK) return r;
    } else {
        c = fovsdf_config_default();
    }
    r = fovsdf__scene_check(scene, lg);
    if (r != FOV_OK) return r;
    if (cam->width == 0 || cam->height == 0)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: cam.width and cam.height must be >= 1");
    if (cam->width > FOVSDF_MAX_DIM || cam->height > FOVSDF_MAX_DIM)
        FOVSDF__FAIL(lg, FOV_ERR_LIMIT, "init: cam.width or cam.height above FOVSDF_MAX_DIM");
    if (!fov__finite(cam->fov_y_deg) || !fov__finite(cam->eye_offset) || !fov__finite(gaze.x) ||
        !fov__finite(gaze.y))
        FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE,
                     "init: cam.fov_y_deg, cam.eye_offset or gaze NaN or infinite");
    off = !fov__is0(cam->tan_left) || !fov__is0(cam->tan_right) || !fov__is0(cam->tan_bottom) ||
          !fov__is0(cam->tan_top);
    if (off) {
        if (!fov__finite(cam->tan_left) || !fov__finite(cam->tan_right) ||
            !fov__finite(cam->tan_bottom) || !fov__finite(cam->tan_top))
            FOVSDF__FAIL(lg, FOV_ERR_NOT_FINITE, "init: cam.tan_left .. tan_top NaN or infinite");
        if (!(cam->tan_left + cam->tan_right > 1e-6f) ||
            !(cam->tan_bottom + cam->tan_top > 1e-6f) ||
            cam->tan_left > 1e6f || cam->tan_right > 1e6f || cam->tan_bottom > 1e6f ||
            cam->tan_top > 1e6f)
            FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                         "init: cam.tan_*: left + right and bottom + top must exceed 1e-6, each "
                         "at most 1e6");
        if (!fov__tan_aspect_ok(cam->tan_left, cam->tan_right, cam->tan_bottom, cam->tan_top,
                                cam->width, cam->height))
            FOVSDF__FAIL(lg, FOV_ERR_UNSUPPORTED,
                         "init: cam.tan_*: (tan_left + tan_right) / (tan_bottom + tan_top) must "
                         "be width / height within 1e-3 (non-square pixels are not supported)");
    }
    fov = fov__is0(cam->fov_y_deg) ? 60.0f : cam->fov_y_deg;
    if (!(fov > 0.0f && fov < 180.0f))
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: cam.fov_y_deg must be in (0, 180) (0: 60)");
    r = fovsdf_camera_basis(cam, rt, up, fw);
    if (r == FOV_ERR_NOT_FINITE) FOVSDF__FAIL(lg, r, "init: cam.pos, target or up NaN or infinite");
    if (r != FOV_OK)
        FOVSDF__FAIL(lg, r, "init: cam.target == cam.pos, or cam.up zero or along the view");
    /* positions beyond 1e18 cannot be resolved (NUMERICS): their squares overflow float */
    if (!fovsdf__coord_ok(cam->pos))
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: cam.pos beyond 1e18 units from the origin");
    if (fov__absf(cam->eye_offset) > FOVSDF__MAX_LEN)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG, "init: cam.eye_offset beyond 1e18 units");
    for (i = 0; i < 3; ++i) rt_o[i] = cam->pos[i] + rt[i] * cam->eye_offset;
    if (!fovsdf__coord_ok(rt_o))
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "init: pinhole (cam.pos + eye_offset * right) beyond 1e18 units");
    r = fovsdf_memory_size(&c, cam, &need);
    if (r != FOV_OK) return r;
    if (mem_size < need || (need > 0 && !mem))
        FOVSDF__FAIL(lg, FOV_ERR_TOO_SMALL, "init: mem NULL or mem_size below fovsdf_memory_size");
    if (off && fov__is0(c.display.fov_y_deg) && fov__is0(c.display.pixel_pitch_mm) &&
        fov__is0(c.display.distance_mm)) {
        /* an off-axis frustum without a display: the camera's own (fov_display) */
        fov_display dd;
        r = fov__camera_display(cam, &dd);
        if (r == FOV_OK) {
            dd.axis_dx += c.display.axis_dx;
            dd.axis_dy += c.display.axis_dy;
            r = fovsdf_ecc_init(&em, &dd, fov, cam->width, cam->height, gaze);
        }
    } else {
        r = fovsdf_ecc_init(&em, &c.display, fov, cam->width, cam->height, gaze);
    }
    if (r != FOV_OK)
        FOVSDF__FAIL(lg, r, "init: gaze or config.display: the eye direction overflows");
    /* everything is valid: only now is ctx written (a failed call leaves it as it was) */
    ctx->right[0] = rt[0]; ctx->right[1] = rt[1]; ctx->right[2] = rt[2];
    ctx->up[0] = up[0]; ctx->up[1] = up[1]; ctx->up[2] = up[2];
    ctx->fwd[0] = fw[0]; ctx->fwd[1] = fw[1]; ctx->fwd[2] = fw[2];
    ctx->ecc = em;
    ctx->cfg = c;
    ctx->scene = *scene;
    if (fov__is0(ctx->scene.lipschitz)) ctx->scene.lipschitz = 1.0f;
    ctx->cam = *cam;
    ctx->cam.fov_y_deg = fov;
    ctx->gaze = gaze;
    ctx->origin[0] = cam->pos[0] + ctx->right[0] * cam->eye_offset;
    ctx->origin[1] = cam->pos[1] + ctx->right[1] * cam->eye_offset;
    ctx->origin[2] = cam->pos[2] + ctx->right[2] * cam->eye_offset;
    tanh = FOV__TAN(0.5f * fov * FOV__DEG);
    ctx->off_axis = off ? 1u : 0u;
    ctx->tan4[0] = cam->tan_left; ctx->tan4[1] = cam->tan_right;
    ctx->tan4[2] = cam->tan_bottom; ctx->tan4[3] = cam->tan_top;
    if (off) tanh = 0.5f * (cam->tan_bottom + cam->tan_top);
    ctx->tan_half_y = tanh;
    ctx->aspect = (float)cam->width / (float)cam->height;
    ctx->pixel_angle = 2.0f * tanh / (float)cam->height;
    if (off) /* the larger of a pixel's two extents at the axis */
        ctx->pixel_angle = fov__maxf(ctx->pixel_angle,
                                     (cam->tan_left + cam->tan_right) / (float)cam->width);
    ctx->t_max = c.t_max > 0.0f ? c.t_max : (scene->t_max > 0.0f ? scene->t_max : 100.0f);
    ctx->mem = mem;
    ctx->mem_size = mem_size;
    ctx->shadow_fov_cos = FOV__COS(c.shadow_fov_deg * FOV__DEG);
    ctx->cam_dist =
        fovsdf__eval_sc(&ctx->scene, 1.0f / ctx->scene.lipschitz, ctx->origin, c.eps, 0, 0);
    return FOV_OK;
}

/* The ray of an off-axis frustum (fov_camera): fwd + sx right + sy up, sx = -tl + (tl + tr)
   px / W, sy = tt - (tt + tb) py / H; a point so far off the image that sx or sy overflow is
   scaled down first (only the direction counts). */
FOVSDF__PRIV int fovsdf__ray_off(const fovsdf_ctx *c, float px, float py, float ro[3],
                                float rd[3])
{
    const float *t = c->tan4;
    float a = px / (float)c->cam.width, b = py / (float)c->cam.height, k, f = 1.0f, u, v;
    int i;
    ro[0] = c->origin[0]; ro[1] = c->origin[1]; ro[2] = c->origin[2];
    k = fov__maxf(fov__absf(a), fov__absf(b));
    if (k > 1e6f && fov__finite(k)) f = 1.0f / k;
    u = -t[0] * f + (t[0] + t[1]) * (a * f);
    v = t[3] * f - (t[2] + t[3]) * (b * f);
    for (i = 0; i < 3; ++i) rd[i] = c->fwd[i] * f + u * c->right[i] + v * c->up[i];
    if (fovsdf__normalize(rd) > 0.0f) return 1;
    rd[0] = c->fwd[0]; rd[1] = c->fwd[1]; rd[2] = c->fwd[2];
    return 0;
}

/* The ray through image point (px, py); no argument checks (internal use). Returns 0 when
   the direction is not finite (an image point ~1e38 / tan(fov_y / 2) pixels off the image):
   never for points within a few image sizes of the image. */
FOVSDF__PRIV int fovsdf__ray(const fovsdf_ctx *c, float px, float py, float ro[3], float rd[3])
{
    float u, v;
    if (c->off_axis) return fovsdf__ray_off(c, px, py, ro, rd);
    u = (px / (float)c->cam.width * 2.0f - 1.0f) * c->tan_half_y * c->aspect;
    v = (1.0f - py / (float)c->cam.height * 2.0f) * c->tan_half_y;
    rd[0] = c->fwd[0] + u * c->right[0] + v * c->up[0];
    rd[1] = c->fwd[1] + u * c->right[1] + v * c->up[1];
    rd[2] = c->fwd[2] + u * c->right[2] + v * c->up[2];
    ro[0] = c->origin[0]; ro[1] = c->origin[1]; ro[2] = c->origin[2];
    if (fovsdf__normalize(rd) > 0.0f) return 1;
    {
        /* a point so far off the image that u or v overflowed: the same direction from the
           offset scaled down by its largest component (px / width cannot overflow) */
        float a = px / (float)c->cam.width - 0.5f, b = 0.5f - py / (float)c->cam.height, k,
            f = 1.0f;
        k = fov__maxf(fov__absf(a), fov__absf(b));
        if (k > 1.0f && fov__finite(k)) { a /= k; b /= k; f = 1.0f / k; }
        u = a * 2.0f * c->tan_half_y * c->aspect;
        v = b * 2.0f * c->tan_half_y;
        rd[0] = c->fwd[0] * f + u * c->right[0] + v * c->up[0];
        rd[1] = c->fwd[1] * f + u * c->right[1] + v * c->up[1];
        rd[2] = c->fwd[2] * f + u * c->right[2] + v * c->up[2];
        if (fovsdf__normalize(rd) > 0.0f) return 1;
    }
    rd[0] = c->fwd[0]; rd[1] = c->fwd[1]; rd[2] = c->fwd[2]; /* a unit vector all the same */
    return 0;
}

FOVSDF_API fov_result fovsdf_camera_ray(const fovsdf_ctx *c, float px, float py, float ro[3],
                                        float rd[3])
{
    if (!c) return FOV_ERR_NULL;
    if (!ro || !rd)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NULL, "camera_ray: ro and rd are required");
    if (!fov__finite(px) || !fov__finite(py))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NOT_FINITE, "camera_ray: px or py NaN or infinite");
    if (!fovsdf__ray(c, px, py, ro, rd))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG,
                     "camera_ray: (px, py) so far off the image that its ray overflows float");
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_trace(const fovsdf_ctx *c, const float ro[3], const float rd[3],
                                   float t_start, fovsdf_hit *hit, fovsdf_stats *st)
{
    fovsdf__marcher m;
    float l;
    if (!c) return FOV_ERR_NULL;
    if (!ro || !rd || !hit)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NULL, "trace: ro, rd and hit are required");
    if (!fov__finite3(ro))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NOT_FINITE, "trace: ro NaN or infinite");
    if (!fov__finite3(rd))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NOT_FINITE, "trace: rd NaN or infinite");
    if (!fov__finite(t_start))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NOT_FINITE, "trace: t_start NaN or infinite");
    if (t_start < 0.0f)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG, "trace: t_start must be >= 0");
    if (!fovsdf__coord_ok(ro))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG,
                     "trace: ro beyond 1e18 units from the origin");
    l = fov__len(rd);
    if (!(l > 0.999f && l < 1.001f))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG, "trace: rd must have length 1 (+-0.001)");
    fovsdf__marcher_from_ctx(c, &m, ro);
    m.verify_start = 0; /* a user's ray from t_start: hits lie in [t_start, t_max] */
    fovsdf__march(&m, ro, rd, t_start, hit, 0, st);
    return FOV_OK;
}

/* ---- rendering ------------------------------------------------------------------------------ */
/* Sample offsets from the pixel centre (see the config's documentation). */
static const float fovsdf__pat4[4][2] =
    { { -0.125f, -0.375f }, { 0.375f, -0.125f }, { 0.125f, 0.375f }, { -0.375f, 0.125f } };
static const int fovsdf__rook_a[4] = { 1, 3, 0, 2 };
static const int fovsdf__rook_b[4] = { 2, 0, 3, 1 };

FOVSDF__PRIV void fovsdf__sample_offset(uint32_t spp, uint32_t s, float *ox, float *oy)
{
    if (spp == 4) { *ox = fovsdf__pat4[s][0]; *oy = fovsdf__pat4[s][1]; return; }
    if (spp == 16) {
        uint32_t i = s & 3u, j = s >> 2;
        *ox = ((float)(4 * (int)i + fovsdf__rook_a[j]) + 0.5f) / 16.0f - 0.5f;
        *oy = ((float)(4 * (int)j + fovsdf__rook_b[i]) + 0.5f) / 16.0f - 0.5f;
        return;
    }
    *ox = 0.0f; *oy = 0.0f;
}

FOVSDF__PRIV float fovsdf__srgb(float x)
{
    if (!(x > 0.0f)) return 0.0f;
    if (x >= 1.0f) return 1.0f;
    return x <= 0.0031308f ? 12.92f * x : 1.055f * FOV__POW(x, 1.0f / 2.4f) - 0.055f;
}

FOVSDF__PRIV void fovsdf__heat(float evals, float rgb[3])
{
    /* blue (1 evaluation) -> green -> red (256 or more), log scale */
    float s = fovsdf__clampf(FOV__LOG(fov__maxf(evals, 1.0f)) / FOV__LOG(256.0f), 0.0f, 1.0f);
    rgb[0] = fovsdf__clampf(2.0f * s - 1.0f, 0.0f, 1.0f);
    rgb[1] = 1.0f - fov__absf(2.0f * s - 1.0f);
    rgb[2] = fovsdf__clampf(1.0f - 2.0f * s, 0.0f, 1.0f);
}

/* Writes one pixel's outputs. */
FOVSDF__PRIV void fovsdf__put(const fovsdf_ctx *c, const fovsdf_output *o, uint32_t x, uint32_t y,
                              const float acc[3], float depth, uint8_t hit, uint32_t evals,
                              float start, uint32_t steps, int32_t mat, uint8_t mask)
{
    uint32_t w = c->cam.width - o->origin_x;
    x -= o->origin_x;
    y -= o->origin_y;
    if (o->rgb) { /* the documented range, whatever the scene's colours (NaN: 0) */
        float *q = o->rgb + (size_t)y * (o->rgb_stride ? o->rgb_stride : 3u * w) + 3u * (size_t)x;
        q[0] = fovsdf__clampf(acc[0], 0.0f, FOVSDF__RGB_MAX);
        q[1] = fovsdf__clampf(acc[1], 0.0f, FOVSDF__RGB_MAX);
        q[2] = fovsdf__clampf(acc[2], 0.0f, FOVSDF__RGB_MAX);
    }
    if (o->rgb8) {
        uint8_t *q =
            o->rgb8 + (size_t)y * (o->rgb8_stride ? o->rgb8_stride : 3u * w) + 3u * (size_t)x;
        int i;
        for (i = 0; i < 3; ++i) q[i] = (uint8_t)(fovsdf__srgb(acc[i]) * 255.0f + 0.5f);
    }
    if (o->depth) o->depth[(size_t)y * (o->depth_stride ? o->depth_stride : w) + x] = depth;
    if (o->hit) o->hit[(size_t)y * (o->hit_stride ? o->hit_stride : w) + x] = hit;
    if (o->evals) o->evals[(size_t)y * (o->evals_stride ? o->evals_stride : w) + x] = evals;
    if (o->start) o->start[(size_t)y * (o->start_stride ? o->start_stride : w) + x] = start;
    if (o->steps) o->steps[(size_t)y * (o->steps_stride ? o->steps_stride : w) + x] = steps;
    if (o->material)
        o->material[(size_t)y * (o->material_stride ? o->material_stride : w) + x] = mat;
    if (o->mask) o->mask[(size_t)y * (o->mask_stride ? o->mask_stride : w) + x] = mask;
}

/* One sample ray through image point (px, py): march from t_start (or a proven miss), shade.
   sh_start: per-light head starts of the shadow rays (SKIP), used when the sample's hit lies
   within sh_tol of sh_ref_t (the low-resolution hit), else none (a different surface). */
typedef struct fovsdf__smp { float col[3], t; int32_t mat; uint32_t steps; int hit; } fovsdf__smp;
/* Colour of a marched ray (hit or miss) into col. */
FOVSDF__PRIV void fovsdf__shade_ray(const fovsdf_ctx *c, const fovsdf__marcher *m0,
                                    const float ro[3], const float rd[3], const fovsdf_hit *h,
                                    int32_t mat, const float *sh_start, float sh_ref_t,
                                    float sh_tol, float col[3], fovsdf_stats *st)
{
    uint64_t es = st->evals;
    if (h->kind != FOVSDF_MISS) {
        float p[3], n[3], hn;
        p[0] = ro[0] + rd[0] * h->t; p[1] = ro[1] + rd[1] * h->t; p[2] = ro[2] + rd[2] * h->t;
        if (c->cfg.shading == FOVSDF_SHADE_DEPTH) {
            col[0] = col[1] = col[2] = 1.0f - h->t / c->t_max;
        } else if (c->cfg.shading == FOVSDF_SHADE_STEPS) {
            col[0] = col[1] = col[2] = 0.0f;
        } else {
            /* half the ray's own pixel footprint (as the hit threshold: pixel_angle cos^2) */
            float cz = fovsdf__clampf(fov__dot(rd, c->fwd), 0.0f, 1.0f);
            hn = c->cfg.normal_eps > 0.0f
                     ? c->cfg.normal_eps
                     : fov__maxf(fov__maxf(1e-4f, 0.5f * c->pixel_angle * cz * cz * h->t),
                                 4.0f * (m0->ulp0 + m0->ulp1 * h->t));
            fovsdf_normal(c, p, hn, n, st);
            if (fov__dot(n, rd) > 0.0f && h->dist < 0.0f) {
                n[0] = -n[0]; n[1] = -n[1]; n[2] = -n[2];
            }
            if (c->cfg.shading == FOVSDF_SHADE_NORMALS) {
                col[0] = 0.5f + 0.5f * n[0]; col[1] = 0.5f + 0.5f * n[1];
                col[2] = 0.5f + 0.5f * n[2];
            } else {
                fovsdf__shade(c, p, n, mat, col,
                              (sh_start && fov__absf(h->t - sh_ref_t) <= sh_tol) ? sh_start : NULL,
                              fovsdf__shadow_far(c, rd), st);
            }
        }
    } else {
        if (c->cfg.shading == FOVSDF_SHADE_DEPTH || c->cfg.shading == FOVSDF_SHADE_STEPS)
            col[0] = col[1] = col[2] = 0.0f;
        else fovsdf_sky(c, rd, col);
    }
    /* via uint32: no 64-bit int-to-float helper on 32-bit CPUs */
    if (c->cfg.shading == FOVSDF_SHADE_STEPS) {
        uint64_t ne = st->evals - es + h->evals;
        fovsdf__heat((float)(uint32_t)(ne > 0xffffffu ? 0xffffffu : ne), col);
    }
}

/* One sample ray through image point (px, py): march from t_start (or a proven miss), shade.
   sh_start: per-light head starts of the shadow rays (SKIP), used when the sample's hit lies
   within sh_tol of sh_ref_t (the low-resolution hit), else none (a different surface). */
FOVSDF__PRIV void fovsdf__sample(const fovsdf_ctx *c, const fovsdf__marcher *m0, float px, float py,
                                 float t_start, int known_miss, const float *sh_start,
                                 float sh_ref_t, float sh_tol, fovsdf__smp *r, fovsdf_stats *st)
{
    float ro[3], rd[3];
    fovsdf_hit h;
    int32_t mat = 0;
    fovsdf__ray(c, px, py, ro, rd);
    if (known_miss) { /* a conservative pass proved this ray empty up to t_max */
        h.kind = FOVSDF_MISS; h.t = c->t_max; h.dist = 0.0f; h.steps = 0; h.evals = 0;
    } else {
        fovsdf__march(m0, ro, rd, t_start, &h, &mat, st);
    }
    st->rays++;
    st->evals_primary += h.evals;
    r->steps = h.steps;
    r->t = h.t;
    r->mat = h.kind != FOVSDF_MISS ? mat : -1;
    r->hit = h.kind != FOVSDF_MISS;
    if (h.kind == FOVSDF_EXHAUSTED) st->exhausted++;
    if (r->hit) st->hits++;
    fovsdf__shade_ray(c, m0, ro, rd, &h, mat, sh_start, sh_ref_t, sh_tol, r->col, st);
}


/* ---- the wavefront ---------------------------------------------------------------------------
   The pixels a tile renders are queued (fovsdf__wave_pixel) and rendered together
   (fovsdf__wave_flush): their sample rays march as one batch, each step evaluating up to
   FOVSDF_BATCH pending requests in one call (rays that finish leave, the others keep the batch
   full); then the normals of all hits (4 points each), then each light's shadow rays, the same
   way. Each ray runs the same coroutine as a single march and every value is exactly the
   per-point one, so images and counts do not depend on FOVSDF_WAVE, FOVSDF_BATCH or the
   caller's split into rows and tiles. Stack: about FOVSDF_WAVE * 0.4 KiB (50 KiB at 128). */

typedef struct fovsdf__wjob {
    uint32_t x, y;             /* the pixel; for fovsdf_shade_points: the point's index */
    float px, py;              /* fovsdf_shade_points: the image point */
    float t_start, sh_ref_t, sh_tol;
    int known_miss, has_sh;
    float sh[FOVSDF_MAX_LIGHTS];
} fovsdf__wjob;

typedef struct fovsdf__wray {
    fovsdf__mco mc;                 /* the march */
    float p[3], n[3], col[3], alb[3], acc[3], dv[4], off, ndl, att;
    uint32_t sev;                   /* shading evaluations */
    int hit, lit, prep, shadow;     /* lit: Lambert with lights; prep, shadow: the current light */
    int peri;                        /* beyond shadow_fov_deg: cheaper shadow rays */
} fovsdf__wray;

/* The shadow proof of a group of shadow rays (fovsdf__wave_flush, step 4): rays q_i + t l_i,
   t in [t0_i, dist_i], all within R of the axis point c + t a (R: the origins' spread
   around c; a directional light's rays are parallel). Lipschitz 1 along the axis: if
   F = f(c + s a), every ray point with t in [s, s + d] has f >= F - d - R, so
   k f >= t there while d <= (k (F - R) - s) / (k + 1). The axis march extends
   a run of such steps; a step that fails starts the run again further on. A run that reaches
   T = max dist_i proves that from its start (split) on every sample of every ray has
   k h / t >= 1: Algorithm 2's minimum cannot drop there, so each ray marches only up to
   split and its light fraction is the same value, without the far samples. A point light:
   the rays converge on it, so the march runs over the fraction u of the way from c to the
   light at distance D instead: ray i is at (1 - u) q_i + u L, within (1 - u) R of the axis
   point c + u D a, at t = u dist_i <= u T, and a step d in u is safe while
   d <= (k (F - (1 - u) R) - u T) / (k D + T); the split is u * dist_i per ray. */
typedef struct fovsdf__gco {
    float c[3], a[3], R, T, k, s, start, eps, split, mg, D; /* D > 0: point light at c + D a,
                                                                   s is the fraction u */
    uint32_t evals, n0, n;          /* axis evaluations; members gm[n0 .. n0 + n) */
    int done;
} fovsdf__gco;
#ifndef FOVSDF_SHADOW_GROUP /* shadow rays per proof; 0 (the default): no proofs */
#define FOVSDF_SHADOW_GROUP 0
#endif

typedef struct fovsdf__wave {
    const fovsdf_ctx *c;
    const fovsdf__marcher *m;
    const fovsdf_output *o;
    fovsdf_stats *st;
    uint32_t nj, cap, spp;
    float *prgb, *pt;          /* fovsdf_shade_points: the outputs (points mode when prgb) */
    int32_t *pmat;
    fovsdf__wjob job[FOVSDF_WAVE];
    fovsdf__wray ray[FOVSDF_WAVE];
    fovsdf__sco sco[FOVSDF_WAVE];
    uint32_t q[FOVSDF_WAVE];        /* ring of rays waiting for an evaluation */
    fovsdf__gco grp[FOVSDF_WAVE];   /* shadow proofs of groups of rays (one per ray at most) */
    uint32_t gm[FOVSDF_WAVE];       /* the rays of each group, group after group */
    float bx[FOVSDF__L + 4], by[FOVSDF__L + 4], bz[FOVSDF__L + 4], be[FOVSDF__L + 4],
        bd[FOVSDF__L + 4];
    int32_t bm[FOVSDF__L + 4];
    uint32_t bk[FOVSDF__L + 4];
    uint32_t afoot;                 /* level_filter: the shaded rays are level samples of cells
                                       of afoot x afoot pixels (0: point samples) */
} fovsdf__wave;

FOVSDF__PRIV void fovsdf__wave_init(fovsdf__wave *w, const fovsdf_ctx *c, const fovsdf_output *o,
                                    fovsdf_stats *st)
{
    w->c = c; w->m = 0; w->o = o; w->st = st; w->nj = 0;
    w->spp = c->cfg.spp;
    w->cap = FOVSDF_WAVE / c->cfg.spp;
    w->prgb = 0; w->pt = 0; w->pmat = 0;
    w->afoot = 0;
}

/* The wavefront's evaluations: n <= FOVSDF_BATCH points as fovsdf__eval_batch, or point by point
   when they fill less than FOVSDF_WAVE_MIN lanes of a batch (the same values, materials and
   counts either way): the batch evaluator of a built-in program always runs FOVSDF__L lanes,
   which costs about as much as 6 to 7 single evaluations (callgrind, 320x180: 5.9e3 against
   821 instructions on primitives, 1.8e4 against 3.0e3 on atrium). 7 of 32 lanes: against 11,
   -1.1 % (CONE) and -1.7 % (CONE_FOV) instructions on atrium at 160x90, primitives within
   +-0.2 %. A scene with a batch callback only is always evaluated in batches. */
#ifndef FOVSDF_WAVE_MIN
#define FOVSDF_WAVE_MIN ((FOVSDF_BATCH + 4) / 5)
#endif
FOVSDF__PRIV void fovsdf__wave_eval_c(const fovsdf_scene *sc, float inv_lip, uint32_t n,
                                      const float *x, const float *y, const float *z,
                                      const float *eps, float inflate,
                                      const fovsdf_ray_cone *cone, float *d, int32_t *mat,
                                      fovsdf_stats *st)
{
    uint32_t i;
    if (n >= (uint32_t)(FOVSDF_WAVE_MIN) || (!sc->dist_ex && !sc->dist)) {
        fovsdf__eval_batch(sc, inv_lip, n, x, y, z, eps, inflate, cone, d, mat, st);
        return;
    }
    for (i = 0; i < n; ++i) {
        float p[3];
        p[0] = x[i]; p[1] = y[i]; p[2] = z[i];
        d[i] = fovsdf__eval_in(sc, inv_lip, p, eps[i], inflate, mat ? &mat[i] : 0, st);
    }
}

FOVSDF__INL void fovsdf__wave_eval(const fovsdf_scene *sc, float inv_lip, uint32_t n,
                                   const float *x, const float *y, const float *z,
                                   const float *eps, float inflate, float *d, int32_t *mat,
                                   fovsdf_stats *st)
{
    fovsdf__wave_eval_c(sc, inv_lip, n, x, y, z, eps, inflate, 0, d, mat, st);
}

/* The marcher's evaluations (fovsdf__wave_eval with m->sc): a batch whose points all lie in
   the tile's cone m->pv->cone goes with that cone (fovsdf_batch.cone), and, when its
   thresholds are in the range the program was pruned for and inflate is 1, through the
   pruned program (the same values, materials and counts: fovsdf__prune). */
FOVSDF__PRIV void fovsdf__wave_eval_pv(const fovsdf__marcher *m, uint32_t n, const float *x,
                                       const float *y, const float *z, const float *eps,
                                       float inflate, float *d, int32_t *mat, fovsdf_stats *st)
{
    const fovsdf__pruned *pv = m->pv;
    {
        uint32_t i;
        const fovsdf_scene *sc = m->sc;
        int ok = !(inflate < 1.0f || inflate > 1.0f) && pv->pruned;
        for (i = 0; i < n; ++i) {
            if (!fovsdf__in_cone(&pv->cone, x[i], y[i], z[i])) break;
            if (!(eps[i] >= pv->e_lo && eps[i] <= pv->e_hi)) ok = 0;
        }
        if (i == n) {
#if FOVSDF_PRUNE_CODE > 0
            if (ok) sc = &pv->sc;
#else
            (void)ok;
#endif
            fovsdf__wave_eval_c(sc, m->inv_lip, n, x, y, z, eps, inflate, &pv->cone, d, mat, st);
            return;
        }
    }
    fovsdf__wave_eval_c(m->sc, m->inv_lip, n, x, y, z, eps, inflate, 0, d, mat, st);
}
FOVSDF__INL void fovsdf__wave_eval_m(const fovsdf__marcher *m, uint32_t n, const float *x,
                                     const float *y, const float *z, const float *eps,
                                     float inflate, float *d, int32_t *mat, fovsdf_stats *st)
{
    if (m->pv) fovsdf__wave_eval_pv(m, n, x, y, z, eps, inflate, d, mat, st);
    else fovsdf__wave_eval_c(m->sc, m->inv_lip, n, x, y, z, eps, inflate, 0, d, mat, st);
}

/* March every queued request of the ring (head 0, cnt entries) to the end. */
FOVSDF__PRIV void fovsdf__wave_march(fovsdf__wave *w, const fovsdf__marcher *m, uint32_t cnt)
{
    uint32_t head = 0, nb, i;
    while (cnt > 0) {
        float qi = w->ray[w->q[head]].mc.qi;
        for (nb = 0; nb < FOVSDF_BATCH && nb < cnt; ++nb) { /* one SDF scale per batch */
            const fovsdf__mco *mc = &w->ray[w->q[(head + nb) % FOVSDF_WAVE]].mc;
            if (mc->qi < qi || mc->qi > qi) break;
            w->bx[nb] = mc->q[0]; w->by[nb] = mc->q[1]; w->bz[nb] = mc->q[2];
            w->be[nb] = mc->qe;
        }
        fovsdf__wave_eval_m(m, nb, w->bx, w->by, w->bz, w->be, qi, w->bd, w->bm, w->st);
        for (i = 0; i < nb; ++i) {
            uint32_t k = w->q[head];
            fovsdf__mco *mc = &w->ray[k].mc;
            head = (head + 1u) % FOVSDF_WAVE;
            --cnt;
            mc->res = w->bd[i]; mc->resm = w->bm[i]; ++mc->evals;
            if (fovsdf__mco_run(m, mc)) { w->q[(head + cnt) % FOVSDF_WAVE] = k; ++cnt; }
        }
    }
}

/* The shadow rays w->sco[k] of the rays in w->q[0 .. cnt) to the end. */
FOVSDF__PRIV void fovsdf__wave_shadows(fovsdf__wave *w, uint32_t cnt)
{
    const fovsdf_ctx *c = w->c;
    uint32_t head = 0, nb, i;
    float inv = 1.0f / c->scene.lipschitz;
    for (i = 0; i < FOVSDF_BATCH; ++i) w->be[i] = c->cfg.eps;
    while (cnt > 0) {
        for (nb = 0; nb < FOVSDF_BATCH && nb < cnt; ++nb) {
            const fovsdf__sco *s = &w->sco[w->q[(head + nb) % FOVSDF_WAVE]];
            w->bx[nb] = s->p[0] + s->l[0] * s->t; w->by[nb] = s->p[1] + s->l[1] * s->t;
            w->bz[nb] = s->p[2] + s->l[2] * s->t;
        }
        fovsdf__wave_eval(&c->scene, inv, nb, w->bx, w->by, w->bz, w->be, 1.0f, w->bd, 0, w->st);
        for (i = 0; i < nb; ++i) {
            uint32_t k = w->q[head];
            head = (head + 1u) % FOVSDF_WAVE;
            --cnt;
            if (fovsdf__sco_next(c, &w->sco[k], w->bd[i])) {
                w->q[(head + cnt) % FOVSDF_WAVE] = k;
                ++cnt;
            }
        }
    }
}

/* Consumes the axis distance F at c + s a; 1 while the proof needs another evaluation. */
FOVSDF__PRIV int fovsdf__gco_next(fovsdf__gco *g, float F)
{
    float kk = g->k * (1.0f / 1.001f); /* 0.1 % margin on k h / t >= 1 against rounding */
    float room, d, end = g->D > 0.0f ? 1.0f : g->T;
    ++g->evals;
    if (g->D > 0.0f) {
        room = F - g->mg - (1.0f - g->s) * g->R;
        d = (kk * room - g->s * g->T) / (kk * g->D + g->T);
    } else {
        room = F - g->mg - g->R;
        d = (kk * room - g->s) / (kk + 1.0f);
    }
    if (d > 1e-3f * g->s + 1e-6f && fov__finite(d)) {
        g->s += d;
    } else { /* not provable here: a new run starts further on */
        float adv = g->D > 0.0f ? fov__maxf(room, 0.0f) / g->D
                                : fov__maxf(room, 0.0f);
        g->s = fov__maxf(g->s + adv, 2.0f * g->s + (g->D > 0.0f ? 1e-3f / g->D : 1e-3f));
        g->start = g->s;
    }
    if (g->s >= end) { g->split = g->start; g->done = 1; return 0; }
    if (g->evals >= 16u || !fov__finite(g->s)) { g->split = FLT_MAX; g->done = 1; return 0; }
    return 1;
}

/* Shadow proofs for the shadow rays w->gm[0 .. nm) of light li, in groups of
   FOVSDF_SHADOW_GROUP consecutive rays; lowers each ray's t_stop to its group's split. */
FOVSDF__PRIV void fovsdf__wave_proofs(fovsdf__wave *w, uint32_t li, uint32_t nm)
{
    const fovsdf_ctx *c = w->c;
    const fovsdf_light *L = &c->scene.lights[li];
    float inv = 1.0f / c->scene.lipschitz;
    int program = c->scene.dist_batch == fovsdf_program_eval_batch ||
                  (!c->scene.dist_batch && c->scene.dist_ex == fovsdf_program_eval);
    uint32_t ng = 0, g, i, j, nb, pend;
#if FOVSDF_SHADOW_GROUP < 2
    (void)L; (void)inv; (void)program; (void)ng; (void)g; (void)i; (void)j; (void)nb; (void)pend;
    (void)nm;
    return;
#else
    if (nm < FOVSDF_SHADOW_GROUP / 2u) return; /* small groups cost more than they save */
    for (g = 0; g * FOVSDF_SHADOW_GROUP < nm; ++g) {
        fovsdf__gco *G = &w->grp[ng];
        float lo[3], hi[3], r2 = 0.0f, off = 0.0f, s0 = FLT_MAX;
        G->n0 = g * FOVSDF_SHADOW_GROUP;
        G->n = nm - G->n0 < FOVSDF_SHADOW_GROUP ? nm - G->n0 : FOVSDF_SHADOW_GROUP;
        if (G->n < FOVSDF_SHADOW_GROUP / 2u) continue;
        G->T = 0.0f; G->k = w->sco[w->gm[G->n0]].k;
        for (j = 0; j < 3; ++j) lo[j] = hi[j] = w->sco[w->gm[G->n0]].p[j];
        for (i = 0; i < G->n; ++i) {
            const fovsdf__sco *sc = &w->sco[w->gm[G->n0 + i]];
            for (j = 0; j < 3; ++j) {
                lo[j] = fov__minf(lo[j], sc->p[j]); hi[j] = fov__maxf(hi[j], sc->p[j]);
            }
            G->T = fov__maxf(G->T, sc->t_end);
            s0 = fov__minf(s0, sc->t);
        }
        for (j = 0; j < 3; ++j) G->c[j] = 0.5f * (lo[j] + hi[j]);
        G->D = 0.0f;
        if (L->type == FOVSDF_LIGHT_POINT) {
            for (j = 0; j < 3; ++j) G->a[j] = L->v[j] - G->c[j];
            G->D = fovsdf__normalize(G->a);
            if (!(G->D > 0.0f)) continue;
        } else {
            for (j = 0; j < 3; ++j) G->a[j] = w->sco[w->gm[G->n0]].l[j];
        }
        for (i = 0; i < G->n; ++i) {
            const fovsdf__sco *sc = &w->sco[w->gm[G->n0 + i]];
            float d[3];
            for (j = 0; j < 3; ++j) d[j] = sc->p[j] - G->c[j];
            r2 = fov__maxf(r2, fov__dot(d, d));
            off = fov__maxf(off, w->ray[w->gm[G->n0 + i]].off);
        }
        /* widened by a few ulps of the sums (and of the positions: mg) */
        G->R = FOV__SQRT(r2) * 1.0001f + 1e-6f;
        /* a point light's ray leaves q = p + off n towards L from p: off more from the axis */
        G->mg = 16.0f * FLT_EPSILON * (fov__len(G->c) + G->T) + 1e-6f + (G->D > 0.0f ? off : 0.0f);
        /* the built-in program decides its bounds with the threshold: for the axis point, a
           threshold lowered by the largest ray-axis distance / 4 makes it skip a bound
           whenever any ray point could (so its value is never above theirs minus the
           distance); other callbacks are taken as Lipschitz 1 as they are */
        G->eps = program ? c->cfg.eps - 0.25f * (G->R + G->mg) : c->cfg.eps;
        G->s = fov__maxf(s0, 2.0f * G->R);
        if (G->D > 0.0f) G->s = fov__minf(G->s / G->T, 1.0f); /* as a fraction (t <= u T) */
        G->start = G->s;
        G->evals = 0; G->done = 0; G->split = FLT_MAX;
        /* a group spread over more than a tenth of its range proves nothing worth the cost */
        if (!fov__finite(G->R) || !fov__finite(G->T) || !(G->R < 0.1f * G->T) ||
            !(G->s < (G->D > 0.0f ? 1.0f : G->T)))
            continue;
        ++ng;
    }
    /* the axis marches as one wavefront */
    for (pend = ng; pend > 0;) {
        uint32_t idx[FOVSDF_BATCH];
        for (g = 0, nb = 0; g < ng && nb < FOVSDF_BATCH; ++g) {
            const fovsdf__gco *G = &w->grp[g];
            if (G->done) continue;
            float sa = G->D > 0.0f ? G->s * G->D : G->s;
            w->bx[nb] = G->c[0] + G->a[0] * sa; w->by[nb] = G->c[1] + G->a[1] * sa;
            w->bz[nb] = G->c[2] + G->a[2] * sa; w->be[nb] = G->eps;
            idx[nb++] = g;
        }
        if (nb == 0) break;
        fovsdf__eval_batch(&c->scene, inv, nb, w->bx, w->by, w->bz, w->be, 1.0f, 0, w->bd, 0,
                           w->st);
        for (i = 0; i < nb; ++i)
            if (!fovsdf__gco_next(&w->grp[idx[i]], w->bd[i])) --pend;
    }
    for (g = 0; g < ng; ++g) {
        const fovsdf__gco *G = &w->grp[g];
        w->st->evals_shadow += G->evals;
        w->ray[w->gm[G->n0]].sev += G->evals; /* the group's first ray carries its cost */
        if (G->split < FLT_MAX)
            for (i = 0; i < G->n; ++i) {
                fovsdf__sco *sc = &w->sco[w->gm[G->n0 + i]];
                sc->t_stop = fov__minf(sc->t_end, G->D > 0.0f ? G->split * sc->t_end : G->split);
            }
    }
#endif
}

/* Normals of the rays k with ray[k].lit or NORMALS shading: 4 points each, in batches. */
FOVSDF__PRIV void fovsdf__wave_normals(fovsdf__wave *w, uint32_t nr, const float *hn)
{
    const fovsdf_ctx *c = w->c;
    float inv = 1.0f / c->scene.lipschitz;
    uint32_t k, i, nb = 0, j;
    for (i = 0; i < FOVSDF__L + 4u; ++i) w->be[i] = 0.0f;
    for (k = 0; k <= nr; ++k) {
        if (k < nr && w->ray[k].lit) {
            const fovsdf__wray *r = &w->ray[k];
            for (i = 0; i < 4; ++i) {
                w->bx[nb] = r->p[0] + hn[k] * fovsdf__tet[i][0];
                w->by[nb] = r->p[1] + hn[k] * fovsdf__tet[i][1];
                w->bz[nb] = r->p[2] + hn[k] * fovsdf__tet[i][2];
                w->bk[nb] = 4u * k + i;
                ++nb;
            }
        }
        if (nb + 4u > FOVSDF__L || (k == nr && nb > 0)) {
            for (j = 0; j < nb; j += FOVSDF_BATCH)
                fovsdf__wave_eval(&c->scene, inv, nb - j < FOVSDF_BATCH ? nb - j : FOVSDF_BATCH,
                                  w->bx + j, w->by + j, w->bz + j, w->be + j, 1.0f, w->bd + j, 0,
                                  w->st);
            for (j = 0; j < nb; ++j)
                w->ray[w->bk[j] / 4u].dv[w->bk[j] % 4u] = w->bd[j] >= FLT_MAX ? 0.0f : w->bd[j];
            nb = 0;
        }
    }
}

/* Steps 2 to 4 of a flush: the colour of each marched ray w->ray[0 .. nr) into ray[k].col,
   as fovsdf__shade_ray (per: rays per job, whose SKIP shadow head starts they use; 0: none);
   ray[k].sev: its shading evaluations. */
/* level_filter: the albedo of a level sample (a ray through the centre of a cell of S x S
   pixels) averaged over its cell, a box prefilter of the texture: 2S x 2S points on a regular
   grid over the cell (4 per pixel, at the 4-spp grid's spacing), each where its ray meets the
   tangent plane of the hit (p, normal n), with the hit's material; a ray that would meet the
   plane behind the camera, from its other side or more grazing than a quarter of the centre
   ray's incidence keeps the centre's point. No distance evaluations. */
FOVSDF__PRIV void fovsdf__albedo_cell(const fovsdf_ctx *c, const float p[3], const float n[3],
                                      const fovsdf__mco *mc, uint32_t S, float rgb[3])
{
    float d0[3], du[3], dv[3], q[3], a[3], dn0, rf, pn, sx, sy, inv;
    uint32_t i, j, N = 2u * S;
    int k;
    rf = fov__dot(mc->rd, c->fwd);
    if (!(rf > 1e-6f)) { fovsdf__albedo(c, p, mc->mat, rgb); return; }
    sx = 2.0f * c->tan_half_y * c->aspect / (float)c->cam.width;
    sy = -2.0f * c->tan_half_y / (float)c->cam.height;
    if (c->off_axis) sx = (c->tan4[0] + c->tan4[1]) / (float)c->cam.width;
    for (k = 0; k < 3; ++k) {
        d0[k] = mc->rd[k] / rf; /* the centre ray's direction with unit depth along fwd */
        du[k] = sx * c->right[k]; dv[k] = sy * c->up[k];
        q[k] = p[k] - mc->ro[k];
    }
    dn0 = fov__dot(d0, n);
    pn = fov__dot(q, n);
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    inv = 1.0f / (float)(N * N);
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            float ox = ((float)i + 0.5f) * 0.5f - 0.5f * (float)S,
                  oy = ((float)j + 0.5f) * 0.5f - 0.5f * (float)S, d[3], dn, t, x[3];
            for (k = 0; k < 3; ++k) d[k] = d0[k] + ox * du[k] + oy * dv[k];
            dn = fov__dot(d, n);
            t = dn * dn0 > 0.0f && fov__absf(dn) >= 0.25f * fov__absf(dn0) ? pn / dn : -1.0f;
            if (t > 0.0f && fov__finite(t))
                for (k = 0; k < 3; ++k) x[k] = mc->ro[k] + d[k] * t;
            else
                for (k = 0; k < 3; ++k) x[k] = p[k];
            fovsdf__albedo(c, x, mc->mat, a);
            rgb[0] += a[0] * inv; rgb[1] += a[1] * inv; rgb[2] += a[2] * inv;
        }
}

FOVSDF__PRIV void fovsdf__wave_shade(fovsdf__wave *w, const fovsdf__marcher *m, uint32_t nr,
                                     uint32_t per)
{
    const fovsdf_ctx *c = w->c;
    fovsdf_stats *st = w->st;
    uint32_t k, j, cnt, li;
    float hn[FOVSDF_WAVE];
    int shading = c->cfg.shading == FOVSDF_SHADE_FULL || c->cfg.shading == FOVSDF_SHADE_NO_SHADOWS;
    /* 2. what each ray needs for its colour (as fovsdf__sample and fovsdf__shade_ray) */
    for (k = 0; k < nr; ++k) {
        fovsdf__wray *r = &w->ray[k];
        const fovsdf__mco *mc = &r->mc;
        r->hit = mc->kind != FOVSDF_MISS;
        r->sev = 0; r->lit = 0;
        if (!r->hit) {
            if (c->cfg.shading == FOVSDF_SHADE_DEPTH || c->cfg.shading == FOVSDF_SHADE_STEPS)
                r->col[0] = r->col[1] = r->col[2] = 0.0f;
            else fovsdf_sky(c, mc->rd, r->col);
            continue;
        }
        r->p[0] = mc->ro[0] + mc->rd[0] * mc->t; r->p[1] = mc->ro[1] + mc->rd[1] * mc->t;
        r->p[2] = mc->ro[2] + mc->rd[2] * mc->t;
        if (c->cfg.shading == FOVSDF_SHADE_DEPTH) {
            r->col[0] = r->col[1] = r->col[2] = 1.0f - mc->t / c->t_max;
        } else if (c->cfg.shading == FOVSDF_SHADE_STEPS) {
            r->col[0] = r->col[1] = r->col[2] = 0.0f;
        } else {
            /* half the ray's own pixel footprint (as the hit threshold: pixel_angle cos^2) */
            float cz = fovsdf__clampf(fov__dot(mc->rd, c->fwd), 0.0f, 1.0f);
            hn[k] = c->cfg.normal_eps > 0.0f
                        ? c->cfg.normal_eps
                        : fov__maxf(fov__maxf(1e-4f, 0.5f * c->pixel_angle * cz * cz * mc->t),
                                    4.0f * (m->ulp0 + m->ulp1 * mc->t));
            r->lit = 1;
        }
    }
    /* 3. normals */
    fovsdf__wave_normals(w, nr, hn);
    for (k = 0; k < nr; ++k) {
        fovsdf__wray *r = &w->ray[k];
        if (!r->lit) continue;
        st->evals_normal += 4;
        r->sev += 4;
        fovsdf__normal_from(r->dv, r->n);
        if (fov__dot(r->n, r->mc.rd) > 0.0f && r->mc.d < 0.0f) {
            r->n[0] = -r->n[0]; r->n[1] = -r->n[1]; r->n[2] = -r->n[2];
        }
        if (!shading) {
            r->col[0] = 0.5f + 0.5f * r->n[0]; r->col[1] = 0.5f + 0.5f * r->n[1];
            r->col[2] = 0.5f + 0.5f * r->n[2];
            r->lit = 0;
            continue;
        }
        if (w->afoot) fovsdf__albedo_cell(c, r->p, r->n, &r->mc, w->afoot, r->alb);
        else fovsdf__albedo(c, r->p, r->mc.mat, r->alb);
        r->acc[0] = c->scene.ambient[0]; r->acc[1] = c->scene.ambient[1];
        r->acc[2] = c->scene.ambient[2];
        r->off = fovsdf__shadow_off(c, r->p);
        r->peri = fovsdf__shadow_far(c, r->mc.rd);
    }
    /* 4. lights in order, each with its shadow rays as one wavefront (as fovsdf__shade) */
    for (li = 0; li < c->scene.num_lights; ++li) {
        const fovsdf_light *L = &c->scene.lights[li];
        cnt = 0;
        for (k = 0; k < nr; ++k) {
            fovsdf__wray *r = &w->ray[k];
            const fovsdf__wjob *jb = per ? &w->job[k / per] : 0;
            fovsdf__lit lt;
            r->prep = 0;
            if (!r->lit) continue;
            if (jb && !(jb->has_sh && fov__absf(r->mc.t - jb->sh_ref_t) <= jb->sh_tol)) jb = 0;
            if (!fovsdf__light_prep(c, li, r->p, r->n, r->off, jb ? jb->sh : NULL, r->peri, &lt))
                continue;
            r->prep = 1; r->ndl = lt.ndl; r->att = lt.att; r->shadow = lt.shadow;
            if (lt.shadow && fovsdf__sco_init(c, &w->sco[k], lt.q, lt.l, lt.t0, lt.dist, lt.k,
                                              r->peri, st))
                w->gm[cnt++] = k;
        }
        fovsdf__wave_proofs(w, li, cnt);
        for (k = 0, j = 0; k < cnt; ++k) { /* the rays with samples left before their split */
            const fovsdf__sco *sc = &w->sco[w->gm[k]];
            if (sc->t < sc->t_stop) w->q[j++] = w->gm[k];
        }
        fovsdf__wave_shadows(w, j);
        for (k = 0; k < nr; ++k) {
            fovsdf__wray *r = &w->ray[k];
            float sh = 1.0f;
            if (!r->prep) continue;
            if (r->shadow) {
                sh = fovsdf__clampf(w->sco[k].res, 0.0f, 1.0f);
                st->evals_shadow += w->sco[k].evals;
                r->sev += w->sco[k].evals;
            }
            r->acc[0] += L->color[0] * r->ndl * r->att * sh;
            r->acc[1] += L->color[1] * r->ndl * r->att * sh;
            r->acc[2] += L->color[2] * r->ndl * r->att * sh;
        }
    }
    for (k = 0; k < nr; ++k) {
        fovsdf__wray *r = &w->ray[k];
        if (r->lit) {
            int i;
            /* NaN (0 * inf): 0 */
            for (i = 0; i < 3; ++i)
                r->col[i] = fovsdf__clampf(r->alb[i] * r->acc[i], 0.0f, FOVSDF__RGB_MAX);
        }
        if (c->cfg.shading == FOVSDF_SHADE_STEPS) {
            uint32_t ne = r->mc.evals + r->sev;
            fovsdf__heat((float)(ne > 0xffffffu ? 0xffffffu : ne), r->col);
        }
    }
}

/* Render the queued pixels (see above). */
FOVSDF__PRIV void fovsdf__wave_flush(fovsdf__wave *w)
{
    const fovsdf_ctx *c = w->c;
    const fovsdf__marcher *m = w->m;
    fovsdf_stats *st = w->st;
    uint32_t spp = w->spp, nr = w->nj * spp, k, j, s, cnt = 0;
    if (w->nj == 0) return;
    /* 1. the sample rays, marched as one wavefront */
    for (k = 0; k < nr; ++k) {
        const fovsdf__wjob *jb = &w->job[k / spp];
        fovsdf__mco *mc = &w->ray[k].mc;
        float ox, oy, ro[3], rd[3];
        if (w->prgb) {
            fovsdf__ray(c, jb->px, jb->py, ro, rd);
        } else {
            fovsdf__sample_offset(spp, k % spp, &ox, &oy);
            fovsdf__ray(c, (float)jb->x + 0.5f + ox, (float)jb->y + 0.5f + oy, ro, rd);
        }
        fovsdf__mco_init(m, mc, ro, rd, jb->t_start);
        if (jb->known_miss) { /* a conservative pass proved this ray empty up to t_max */
            mc->kind = FOVSDF_MISS; mc->d = 0.0f; mc->steps = 0; mc->pc = 9999u;
        } else if (fovsdf__mco_run(m, mc)) {
            w->q[cnt++] = k;
        }
    }
    fovsdf__wave_march(w, m, cnt);
    for (k = 0; k < nr; ++k) { /* as fovsdf__sample */
        const fovsdf__mco *mc = &w->ray[k].mc;
        st->rays++;
        st->evals_primary += mc->evals;
        if (mc->kind == FOVSDF_EXHAUSTED) st->exhausted++;
        if (mc->kind != FOVSDF_MISS) st->hits++;
    }
    fovsdf__wave_shade(w, m, nr, spp);
    /* 5. colours and pixels */
    for (j = 0; j < w->nj; ++j) {
        const fovsdf__wjob *jb = &w->job[j];
        float acc[3] = { 0.0f, 0.0f, 0.0f }, tnear = c->t_max;
        uint32_t nhit = 0, nsteps = 0, ev = 0;
        int32_t mnear = -1;
        for (s = 0; s < spp; ++s) {
            const fovsdf__wray *r = &w->ray[j * spp + s];
            if (w->prgb) { /* as fovsdf_shade_point */
                float *o3 = w->prgb + 3u * (size_t)jb->x;
                o3[0] = fovsdf__clampf(r->col[0], 0.0f, FOVSDF__RGB_MAX);
                o3[1] = fovsdf__clampf(r->col[1], 0.0f, FOVSDF__RGB_MAX);
                o3[2] = fovsdf__clampf(r->col[2], 0.0f, FOVSDF__RGB_MAX);
                if (w->pt) w->pt[jb->x] = r->hit ? r->mc.t : c->t_max;
                if (w->pmat) w->pmat[jb->x] = r->hit ? r->mc.mat : -1;
                continue;
            }
            nsteps += r->mc.steps;
            ev += r->mc.evals + r->sev;
            if (r->hit) {
                ++nhit;
                if (r->mc.t < tnear) { tnear = r->mc.t; mnear = r->mc.mat; }
            }
            acc[0] += r->col[0]; acc[1] += r->col[1]; acc[2] += r->col[2];
        }
        if (w->prgb) continue;
        acc[0] /= (float)spp; acc[1] /= (float)spp; acc[2] /= (float)spp;
        fovsdf__put(c, w->o, jb->x, jb->y, acc, tnear, (uint8_t)(2u * nhit >= spp ? 1u : 0u), ev,
                    jb->known_miss ? c->t_max : jb->t_start, nsteps, mnear, 1u);
    }
    w->nj = 0;
}

/* Queue pixel (x, y): its sample rays march from t_start (known_miss: proven empty); sh_start
   as fovsdf__sample's. */
FOVSDF__PRIV void fovsdf__wave_pixel(fovsdf__wave *w, const fovsdf__marcher *m, uint32_t x,
                                     uint32_t y, float t_start, int known_miss,
                                     const float *sh_start, float sh_ref_t, float sh_tol)
{
    fovsdf__wjob *jb;
    uint32_t i;
    if (w->nj > 0 && w->m != m) fovsdf__wave_flush(w);
    w->m = m;
    jb = &w->job[w->nj];
    jb->x = x; jb->y = y; jb->t_start = t_start; jb->known_miss = known_miss;
    jb->has_sh = sh_start != NULL; jb->sh_ref_t = sh_ref_t; jb->sh_tol = sh_tol;
    if (sh_start)
        for (i = 0; i < w->c->scene.num_lights; ++i) jb->sh[i] = sh_start[i];
    if (++w->nj >= w->cap) fovsdf__wave_flush(w);
}

/* The head-start passes' rays as one wavefront, in the ray slots only (the queued pixels wait:
   their rays are set up when they are flushed): n <= FOVSDF_WAVE rays through image points
   (px[k], py[k]) marched from t0[k] with m, each exactly as fovsdf__march (into h[k] and, when
   mat is not NULL, mat[k]). The evaluations count into st->evals, nowhere else. */
FOVSDF__PRIV void fovsdf__wave_rays(fovsdf__wave *w, const fovsdf__marcher *m, uint32_t n,
                                    const float *px, const float *py, const float *t0,
                                    fovsdf_hit *h, int32_t *mat)
{
    uint32_t k, cnt = 0;
    FOV_ASSERT(n <= FOVSDF_WAVE);
    for (k = 0; k < n; ++k) {
        fovsdf__mco *mc = &w->ray[k].mc;
        float ro[3], rd[3];
        fovsdf__ray(w->c, px[k], py[k], ro, rd);
        fovsdf__mco_init(m, mc, ro, rd, t0[k]);
        if (fovsdf__mco_run(m, mc)) w->q[cnt++] = k;
    }
    fovsdf__wave_march(w, m, cnt);
    for (k = 0; k < n; ++k) {
        const fovsdf__mco *mc = &w->ray[k].mc;
        h[k].kind = mc->kind;
        h[k].t = mc->kind == FOVSDF_MISS ? m->t_max : mc->t;
        h[k].dist = mc->d;
        h[k].steps = mc->steps;
        h[k].evals = mc->evals;
        if (mat) mat[k] = mc->mat;
    }
}

/* Colours of n <= FOVSDF_WAVE rays already marched (h[k], material mat[k]) through image points
   (px[k], py[k]), each exactly as fovsdf__shade_ray without shadow head starts, into
   rgb[3 k .. 3 k + 2], as one wavefront in the ray slots only (as fovsdf__wave_rays). */
FOVSDF__PRIV void fovsdf__wave_shade_rays(fovsdf__wave *w, const fovsdf__marcher *m, uint32_t n,
                                          const float *px, const float *py, const fovsdf_hit *h,
                                          const int32_t *mat, float *rgb)
{
    uint32_t k;
    FOV_ASSERT(n <= FOVSDF_WAVE);
    for (k = 0; k < n; ++k) {
        fovsdf__mco *mc = &w->ray[k].mc;
        float ro[3], rd[3];
        fovsdf__ray(w->c, px[k], py[k], ro, rd);
        fovsdf__mco_init(m, mc, ro, rd, 0.0f);
        mc->kind = h[k].kind; mc->t = h[k].t; mc->d = h[k].dist; mc->mat = mat[k];
        mc->steps = 0; mc->evals = 0; /* a STEPS heat map counts the shading only */
        mc->pc = 9999u;
    }
    fovsdf__wave_shade(w, m, n, 0);
    for (k = 0; k < n; ++k) {
        rgb[3u * k] = w->ray[k].col[0]; rgb[3u * k + 1u] = w->ray[k].col[1];
        rgb[3u * k + 2u] = w->ray[k].col[2];
    }
}

FOVSDF_API fov_result fovsdf_shade_point(const fovsdf_ctx *c, float px, float py, float rgb[3],
                                         float *t, int32_t *material, fovsdf_stats *stats)
{
    fovsdf__marcher m;
    fovsdf__smp r;
    fovsdf_stats local;
    float ro[3], rd[3];
    if (!c) return FOV_ERR_NULL;
    if (!rgb) FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NULL, "shade_point: rgb is NULL");
    if (!fov__finite(px) || !fov__finite(py))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NOT_FINITE, "shade_point: px or py NaN or infinite");
    if (!fovsdf__ray(c, px, py, ro, rd))
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG,
                     "shade_point: (px, py) so far off the image that its ray overflows float");
    FOV_MEMSET(&local, 0, sizeof local);
    fovsdf__marcher_from_ctx(c, &m, c->origin);
    m.verify_start = 0; /* from the camera */
    fovsdf__sample(c, &m, px, py, 0.0f, 0, NULL, 0.0f, 0.0f, &r, &local);
    rgb[0] = fovsdf__clampf(r.col[0], 0.0f, FOVSDF__RGB_MAX); /* as fovsdf_output.rgb */
    rgb[1] = fovsdf__clampf(r.col[1], 0.0f, FOVSDF__RGB_MAX);
    rgb[2] = fovsdf__clampf(r.col[2], 0.0f, FOVSDF__RGB_MAX);
    if (t) *t = r.hit ? r.t : c->t_max;
    if (material) *material = r.mat;
    if (stats) fovsdf_stats_add(stats, &local);
    return FOV_OK;
}

/* The checks of fovsdf_shade_points and fovsdf_shade_points_grouped (c not NULL, n > 0). */
FOVSDF__PRIV fov_result fovsdf__points_check(const fovsdf_ctx *c, uint32_t n, const float *xy,
                                             uint32_t *stride, const float *rgb)
{
    uint32_t i;
    if (!xy || !rgb) FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NULL, "shade_points: xy or rgb is NULL");
    if (*stride == 0) *stride = 2;
    if (*stride < 2)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG, "shade_points: stride must be 0 or >= 2");
    for (i = 0; i < n; ++i) { /* every point is checked before any work */
        float ro[3], rd[3], px = xy[(size_t)i * *stride], py = xy[(size_t)i * *stride + 1u];
        if (!fov__finite(px) || !fov__finite(py))
            FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NOT_FINITE,
                         "shade_points: a point's x or y is NaN or infinite");
        if (!fovsdf__ray(c, px, py, ro, rd))
            FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG,
                         "shade_points: a point so far off the image that its ray overflows");
    }
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_shade_points(const fovsdf_ctx *c, uint32_t n, const float *xy,
                                          uint32_t stride, float *rgb, float *t,
                                          int32_t *material, fovsdf_stats *stats)
{
    return fovsdf_shade_points_grouped(c, n, xy, stride, 0, rgb, t, material, stats);
}

FOVSDF__PRIV fov_result fovsdf__check_output(const fovsdf_ctx *c, const fovsdf_output *o,
                                             uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1)
{
    uint32_t w;
    const fov_logger *lg = &c->cfg.logger;
    if (x0 >= x1 || y0 >= y1) return FOV_OK; /* nothing is written */
    if (x0 < o->origin_x || y0 < o->origin_y)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "render_tile: x0 or y0 below output.origin_x or origin_y");
    if (o->origin_x >= c->cam.width || o->origin_y >= c->cam.height)
        FOVSDF__FAIL(lg, FOV_ERR_INVALID_ARG,
                     "render_tile: output.origin_x or origin_y outside the image");
    w = x1 - o->origin_x; /* the widest row written */
    if ((o->rgb && o->rgb_stride && o->rgb_stride < 3u * w) ||
        (o->rgb8 && o->rgb8_stride && o->rgb8_stride < 3u * w) ||
        (o->depth && o->depth_stride && o->depth_stride < w) ||
        (o->hit && o->hit_stride && o->hit_stride < w) ||
        (o->evals && o->evals_stride && o->evals_stride < w) ||
        (o->material && o->material_stride && o->material_stride < w) ||
        (o->steps && o->steps_stride && o->steps_stride < w) ||
        (o->start && o->start_stride && o->start_stride < w) ||
        (o->mask && o->mask_stride && o->mask_stride < w))
        FOVSDF__FAIL(lg, FOV_ERR_TOO_SMALL,
                     "render_tile: an output *_stride below the tile's width");
    return FOV_OK;
}

/* ---- conservative cone pyramid (beyond the thesis; the cone-marching bound, derived here) ----
   A cell is a rectangle of pixels; its cone has its apex at the pinhole, its axis a through the
   cell's centre and half-angle alpha, the largest angle between a and the rays through the
   cell's corners (every sample of every pixel of the cell lies inside), k = tan(alpha).
   March along the axis with the free-cone step: at axial distance t with distance f = f(o+ta),
   every cone point of axial distance in [t, (f + t) / (1 + k)] is inside the empty ball, so
       t <- t + (f - t k) / (1 + k)        while f > t k + eps.
   When the cone touches a surface the cell splits in four and each child continues from the
   parent's t, shortened to t cos(alpha_child) so that the child's cone starts inside the region
   its parent proved empty; single pixels then march their sample rays from their cell's t.
   A cell that reaches t_max is empty: its pixels are not marched at all. For any distance
   function that never overestimates (Lipschitz <= 1, after scene.lipschitz), no ray starts past
   its first hit. */
FOVSDF__PRIV float fovsdf__cone_march(const fovsdf_ctx *c, const fovsdf__marcher *m,
                                      const float a[3], float k, float t, fovsdf_stats *st)
{
    uint32_t i;
    uint64_t e0 = st->evals;
    for (i = 0; i < m->max_steps; ++i) {
        float p[3], f;
        if (t > m->t_max) { t = -1.0f; break; }
        p[0] = c->origin[0] + a[0] * t; p[1] = c->origin[1] + a[1] * t;
        p[2] = c->origin[2] + a[2] * t;
        /* the float evaluation at a position of magnitude up to |camera| + t errs by a few
           ulps of it: take the distance minus the library's ulp floor, 8 FLT_EPSILON
           (|camera| + t), as the safe radius (NUMERICS: where the guarantee holds) */
        f = fovsdf__eval_sc(m->sc, m->inv_lip, p, m->eps, 0, st) - (m->ulp0 + m->ulp1 * t);
        if (f <= t * k * (1.0f + FOVSDF_CONE_SLACK) + m->eps) break;
        t += (f - t * k) / (1.0f + k);
    }
    /* the step budget can run out right after a verified step past t_max: the cone is empty */
    if (t > m->t_max) t = -1.0f;
    st->evals_lowres += st->evals - e0;
    return t;
}

#ifndef FOVSDF_CONE_SLACK
#define FOVSDF_CONE_SLACK 0.0f
#endif

/* fovsdf__cone_march for n cones as one wavefront: cone j (unit axis a, k = tan(half-angle))
   marches from its t to where it stops (-1: it reached t_max), each exactly as
   fovsdf__cone_march (the same values, evaluations and counts), the evaluations of all the
   cones still marching in batches of FOVSDF_BATCH. act: scratch for n indices. */
typedef struct fovsdf__wcone { float a[3], k, t; uint32_t i; } fovsdf__wcone;
FOVSDF__PRIV int fovsdf__wcone_go(const fovsdf__marcher *m, fovsdf__wcone *q)
{
    if (q->i >= m->max_steps || q->t > m->t_max) { /* as the loop's end and its first test */
        if (q->t > m->t_max) q->t = -1.0f;
        return 0;
    }
    return 1;
}
FOVSDF__PRIV void fovsdf__wave_cones(fovsdf__wave *w, const fovsdf__marcher *m, uint32_t n,
                                     fovsdf__wcone *cn, uint32_t *act)
{
    const fovsdf_ctx *c = w->c;
    uint32_t na = 0, j, i, nb, keep;
    uint64_t e = 0;
    for (j = 0; j < n; ++j) {
        cn[j].i = 0;
        if (fovsdf__wcone_go(m, &cn[j])) act[na++] = j;
    }
    for (i = 0; i < FOVSDF_BATCH; ++i) w->be[i] = m->eps;
    while (na > 0) {
        keep = 0;
        for (j = 0; j < na; j += nb) {
            nb = na - j < FOVSDF_BATCH ? na - j : FOVSDF_BATCH;
            for (i = 0; i < nb; ++i) {
                const fovsdf__wcone *q = &cn[act[j + i]];
                w->bx[i] = c->origin[0] + q->a[0] * q->t; w->by[i] = c->origin[1] + q->a[1] * q->t;
                w->bz[i] = c->origin[2] + q->a[2] * q->t;
            }
            fovsdf__wave_eval_m(m, nb, w->bx, w->by, w->bz, w->be, 1.0f, w->bd, 0, w->st);
            e += nb;
            for (i = 0; i < nb; ++i) {
                uint32_t id = act[j + i];
                fovsdf__wcone *q = &cn[id];
                /* as fovsdf__cone_march */
                float f = w->bd[i] - (m->ulp0 + m->ulp1 * q->t);
                if (f <= q->t * q->k * (1.0f + FOVSDF_CONE_SLACK) + m->eps) continue;
                q->t += (f - q->t * q->k) / (1.0f + q->k);
                ++q->i;
                if (fovsdf__wcone_go(m, q)) act[keep++] = id;
            }
        }
        na = keep;
    }
    w->st->evals_lowres += e;
}
/* Cone of the pixel rectangle [x0, x1) x [y0, y1): unit axis a and k = tan(half-angle). */
FOVSDF__PRIV float fovsdf__cell_cone(const fovsdf_ctx *c, float x0, float y0, float x1, float y1,
                                     float a[3])
{
    float ro[3], d[3], cmin = 1.0f;
    int i;
    /* fovsdf_camera_ray's ray without its argument checks (finite points, as every caller's) */
    (void)fovsdf__ray(c, 0.5f * (x0 + x1), 0.5f * (y0 + y1), ro, a);
    for (i = 0; i < 4; ++i) {
        float cs;
        (void)fovsdf__ray(c, (i & 1) ? x1 : x0, (i & 2) ? y1 : y0, ro, d);
        cs = fov__dot(a, d);
        if (cs < cmin) cmin = cs;
    }
    cmin = fovsdf__clampf(cmin, 1e-6f, 1.0f);
    /* tan(acos(cmin)), widened by a few ulps of the dot products */
    return FOV__SQRT(fov__maxf(1.0f - cmin * cmin, 0.0f)) / cmin * 1.0001f + 1e-6f;
}

/* The points as one wavefront from the camera (group <= 1) or, group by group, from where the
   group's cone stopped: the cones of up to FOVSDF_WAVE groups march together (each exactly as
   fovsdf__cone_march, as fovsdf__safe_start from the camera), then their points queue. */
FOVSDF_API fov_result fovsdf_shade_points_grouped(const fovsdf_ctx *c, uint32_t n,
                                                  const float *xy, uint32_t stride,
                                                  uint32_t group, float *rgb, float *t,
                                                  int32_t *material, fovsdf_stats *stats)
{
    fovsdf__marcher m;
    fovsdf__wave wv;
    fovsdf_stats local;
    fovsdf__wcone cn[FOVSDF_WAVE];
    uint32_t act[FOVSDF_WAVE], i, g, ng, first;
    fov_result r;
    if (!c) return FOV_ERR_NULL;
    if (group > FOVSDF_MAX_GROUP)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG,
                     "shade_points_grouped: group above FOVSDF_MAX_GROUP");
    if (n == 0) return FOV_OK;
    r = fovsdf__points_check(c, n, xy, &stride, rgb);
    if (r != FOV_OK) return r;
    if (group < 2u) group = 1u;
    FOV_MEMSET(&local, 0, sizeof local);
    fovsdf__marcher_from_ctx(c, &m, c->origin);
    m.verify_start = 0; /* from the camera, or from a certified start */
    fovsdf__wave_init(&wv, c, 0, &local);
    wv.spp = 1; wv.cap = FOVSDF_WAVE; wv.prgb = rgb; wv.pt = t; wv.pmat = material;
    for (first = 0; first < n; first += n - first < ng * group ? n - first : ng * group) {
        /* the cones of the next groups (none for group 1: every ray from the camera) */
        ng = (n - first) / group + ((n - first) % group != 0u ? 1u : 0u);
        if (ng > FOVSDF_WAVE) ng = FOVSDF_WAVE;
        if (group > 1u) {
            for (g = 0; g < ng; ++g) {
                uint32_t j0 = first + g * group, j1 = n - j0 > group ? j0 + group : n, j;
                float x0 = FLT_MAX, y0 = FLT_MAX, x1 = -FLT_MAX, y1 = -FLT_MAX;
                for (j = j0; j < j1; ++j) {
                    float px = xy[(size_t)j * stride], py = xy[(size_t)j * stride + 1u];
                    x0 = fov__minf(x0, px); x1 = fov__maxf(x1, px);
                    y0 = fov__minf(y0, py); y1 = fov__maxf(y1, py);
                }
                cn[g].k = fovsdf__cell_cone(c, x0, y0, x1, y1, cn[g].a);
                cn[g].t = 0.0f;
            }
            fovsdf__wave_cones(&wv, &m, ng, cn, act);
        }
        for (g = 0; g < ng; ++g) {
            uint32_t j0 = first + g * group, j1 = n - j0 > group ? j0 + group : n;
            /* as fovsdf__safe_start from the camera: -1 is a proven miss */
            float ts = group > 1u ? cn[g].t : 0.0f;
            ts = ts < 0.0f ? -1.0f : fov__minf(fov__maxf(ts, 0.0f), m.t_max);
            for (i = j0; i < j1; ++i) {
                fovsdf__wjob *jb = &wv.job[wv.nj];
                wv.m = &m;
                jb->x = i; jb->y = 0;
                jb->px = xy[(size_t)i * stride]; jb->py = xy[(size_t)i * stride + 1u];
                jb->t_start = ts < 0.0f ? 0.0f : ts; jb->known_miss = ts < 0.0f;
                jb->has_sh = 0; jb->sh_ref_t = 0.0f; jb->sh_tol = 0.0f;
                if (++wv.nj >= wv.cap) fovsdf__wave_flush(&wv);
            }
        }
    }
    fovsdf__wave_flush(&wv);
    if (stats) fovsdf_stats_add(stats, &local);
    return FOV_OK;
}

/* The cone of the pixel rectangle [x0, x1) x [y0, y1) from the camera out to t_max, for the
   marchers mc (cones) and mp (sample rays) of a tile: pv gets it, with the scene's program
   pruned for it when the scene is a built-in program (fovsdf__prune_cone; thresholds from mc's
   eps to mp's at t_max), or the cone alone for a batch callback. Returns 0 when neither
   applies (the tile marches with the marchers as they are). */
FOVSDF__PRIV int fovsdf__tile_cone(const fovsdf_ctx *c, const fovsdf__marcher *mc,
                                   const fovsdf__marcher *mp, float x0, float y0, float x1,
                                   float y1, fovsdf__pruned *pv)
{
    fovsdf_ray_cone q;
    float e_lo, e_hi;
    if (mc->sc != mp->sc || mc->inflate < 1.0f || mc->inflate > 1.0f) return 0;
    /* nothing to do: no pruning (FOVSDF_PRUNE_CODE 0) and no batch callback of the user's */
    if (FOVSDF_PRUNE_CODE == 0 &&
        (!mc->sc->dist_batch || mc->sc->dist_batch == fovsdf_program_eval_batch))
        return 0;
    q.tan_half = fovsdf__cell_cone(c, x0, y0, x1, y1, q.axis);
    q.apex[0] = c->origin[0]; q.apex[1] = c->origin[1]; q.apex[2] = c->origin[2];
    q.t0 = 0.0f;
    q.t1 = fov__maxf(mc->t_max, mp->t_max) * 1.001f;
    e_lo = fov__minf(mc->eps, mp->eps);
    e_hi = fov__maxf(fovsdf__thr_ec(mp, mp->eps_cone, q.t1),
                     fovsdf__thr_ec(mc, mc->eps_cone, q.t1));
    /* rule (a) alone saves nothing per evaluation (BDIST costs what the skip costs): the
       pruned program is used when at least FOVSDF_PRUNE_MIN tests or unions went */
    if (fovsdf__prune_cone(mc->sc, &q, e_lo, e_hi, pv))
        return pv->rules[1] + pv->rules[2] + 1u > (uint32_t)(FOVSDF_PRUNE_MIN) ? 1 : 0;
    if (!mc->sc->dist_batch || mc->sc->dist_batch == fovsdf_program_eval_batch) return 0;
    pv->cone = q;
    pv->pruned = 0;
    pv->e_lo = e_lo; pv->e_hi = e_hi;
    return 1;
}

/* A cell of the cone pyramid: its pixel rectangle relative to the tile's corner, its level and
   its parent's t. */
typedef struct fovsdf__cell { uint16_t x0, y0, x1, y1, level; float t; } fovsdf__cell;

/* Cones in flight per CONE tile (each slot keeps a 40-cell stack, 640 bytes). 1 by default: with
   the built-in programs' batch evaluator (a bounded subtree runs when any lane needs it, and
   the cones of a tile are spread over it) 32 slots cost 3 % more instructions than one
   (callgrind, primitives 640x360: 2.95e9 against 2.86e9, 1 slot the same as marching each
   cone alone); a batch callback that gains from width may want more. */
#ifndef FOVSDF_CONE_SLOTS
#define FOVSDF_CONE_SLOTS 1
#endif
#if FOVSDF_CONE_SLOTS < 1
#error "fovsdf: FOVSDF_CONE_SLOTS must be at least 1"
#endif

/* The cone pyramid over one grid-aligned top-level tile [x0,x1) x [y0,y1) (clipped to the image
   only, so the cells and results do not depend on how the caller splits the image), writing the
   pixels inside the requested region [rx0,rx1) x [ry0,ry1). The cones march as one wavefront:
   FOVSDF_CONE_SLOTS slots, each walking its part of the tree depth first on its own stack (a
   cell's children wait there for it; at most 3 per level), an idle slot taking the oldest cell
   of the fullest stack; every cone exactly as fovsdf__cone_march, so the cells, their t and the
   counts are those of a single depth-first walk; only the order of the queued pixels differs. */
FOVSDF__PRIV FOVSDF__NOINLINE void
fovsdf__cone_tile(const fovsdf_ctx *c, const fovsdf__marcher *mc, const fovsdf__marcher *mp,
                  uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1, uint32_t rx0, uint32_t ry0,
                  uint32_t rx1, uint32_t ry1, fovsdf_stats *st, fovsdf__wave *wv)
{
    fovsdf__cell stk[FOVSDF_CONE_SLOTS][4 * 10], cur[FOVSDF_CONE_SLOTS];
    fovsdf__wcone cn[FOVSDF_CONE_SLOTS];
    uint32_t sp[FOVSDF_CONE_SLOTS], s, i, nb, act[FOVSDF_CONE_SLOTS];
    int busy[FOVSDF_CONE_SLOTS];
    uint64_t e = 0;
    fovsdf__pruned pv;
    fovsdf__marcher mc2, mp2;
    if (fovsdf__tile_cone(c, mc, mp, (float)x0, (float)y0, (float)x1, (float)y1, &pv)) {
        mc2 = *mc; mc2.pv = &pv; mc = &mc2;
        mp2 = *mp; mp2.pv = &pv; mp = &mp2;
    }
    for (s = 0; s < FOVSDF_CONE_SLOTS; ++s) { sp[s] = 0; busy[s] = 0; }
    stk[0][0].x0 = 0; stk[0][0].y0 = 0; stk[0][0].x1 = (uint16_t)(x1 - x0);
    stk[0][0].y1 = (uint16_t)(y1 - y0); stk[0][0].level = 1; stk[0][0].t = 0.0f;
    sp[0] = 1;
    (void)st; /* the cones count into wv's, the same */
    for (;;) {
        uint32_t na = 0;
        for (s = 0; s < FOVSDF_CONE_SLOTS; ++s) {
            for (;;) {
                fovsdf__cell *cl = &cur[s];
                uint32_t px0, py0, px1, py1, x, y;
                float t;
                if (!busy[s]) { /* the next cell: its own stack's top, or the oldest elsewhere */
                    uint32_t v = s, k;
                    if (sp[s] == 0) {
                        for (k = 0; k < FOVSDF_CONE_SLOTS; ++k)
                            if (sp[k] > sp[v]) v = k;
                        if (sp[v] == 0) break; /* no cell left anywhere */
                        *cl = stk[v][0];
                        for (k = 1; k < sp[v]; ++k) stk[v][k - 1] = stk[v][k];
                        --sp[v];
                    } else {
                        *cl = stk[s][--sp[s]];
                    }
                    px0 = x0 + cl->x0 > rx0 ? x0 + cl->x0 : rx0;
                    px1 = x0 + cl->x1 < rx1 ? x0 + cl->x1 : rx1;
                    py0 = y0 + cl->y0 > ry0 ? y0 + cl->y0 : ry0;
                    py1 = y0 + cl->y1 < ry1 ? y0 + cl->y1 : ry1;
                    if (px0 >= px1 || py0 >= py1) continue; /* not requested */
                    cn[s].k = fovsdf__cell_cone(c, (float)(x0 + cl->x0), (float)(y0 + cl->y0),
                                                (float)(x0 + cl->x1), (float)(y0 + cl->y1),
                                                cn[s].a);
                    /* from the parent's t shortened by cos(alpha) */
                    cn[s].t = cl->t * (1.0f / FOV__SQRT(1.0f + cn[s].k * cn[s].k));
                    cn[s].i = 0;
                    busy[s] = 1;
                }
                if (fovsdf__wcone_go(mc, &cn[s])) { act[na++] = s; break; }
                /* the cone stopped */
                busy[s] = 0;
                t = cn[s].t;
                px0 = x0 + cl->x0 > rx0 ? x0 + cl->x0 : rx0;
                px1 = x0 + cl->x1 < rx1 ? x0 + cl->x1 : rx1;
                py0 = y0 + cl->y0 > ry0 ? y0 + cl->y0 : ry0;
                py1 = y0 + cl->y1 < ry1 ? y0 + cl->y1 : ry1;
                if (t < 0.0f) { /* proven empty: no full-resolution marching */
                    for (y = py0; y < py1; ++y)
                        for (x = px0; x < px1; ++x)
                            fovsdf__wave_pixel(wv, mp, x, y, 0.0f, 1, NULL, 0.0f, 0.0f);
                    continue;
                }
                if ((cl->x1 - cl->x0 <= 1 && cl->y1 - cl->y0 <= 1) ||
                    cl->level >= c->cfg.cone_levels) {
                    for (y = py0; y < py1; ++y)
                        for (x = px0; x < px1; ++x)
                            fovsdf__wave_pixel(wv, mp, x, y, t, 0, NULL, 0.0f, 0.0f);
                    continue;
                }
                {
                    uint32_t xm = cl->x0 + (uint32_t)(cl->x1 - cl->x0 + 1) / 2u,
                        ym = cl->y0 + (uint32_t)(cl->y1 - cl->y0 + 1) / 2u, q;
                    for (q = 4; q-- > 0;) { /* pushed in reverse: taken in scan order */
                        fovsdf__cell ch;
                        ch.x0 = (uint16_t)((q & 1) ? xm : cl->x0);
                        ch.x1 = (q & 1) ? cl->x1 : (uint16_t)xm;
                        ch.y0 = (uint16_t)((q & 2) ? ym : cl->y0);
                        ch.y1 = (q & 2) ? cl->y1 : (uint16_t)ym;
                        if (ch.x0 >= ch.x1 || ch.y0 >= ch.y1) continue;
                        ch.level = (uint16_t)(cl->level + 1u);
                        ch.t = t;
                        FOV_ASSERT(sp[s] < 4u * 10u);
                        stk[s][sp[s]++] = ch;
                    }
                }
            }
        }
        if (na == 0) break; /* nothing in flight and no cell left */
        /* one step of every cone in flight (as fovsdf__cone_march) */
        for (i = 0; i < FOVSDF_BATCH; ++i) wv->be[i] = mc->eps;
        for (s = 0; s < na; s += nb) {
            nb = na - s < FOVSDF_BATCH ? na - s : FOVSDF_BATCH;
            for (i = 0; i < nb; ++i) {
                const fovsdf__wcone *p = &cn[act[s + i]];
                wv->bx[i] = c->origin[0] + p->a[0] * p->t;
                wv->by[i] = c->origin[1] + p->a[1] * p->t;
                wv->bz[i] = c->origin[2] + p->a[2] * p->t;
            }
            fovsdf__wave_eval_m(mc, nb, wv->bx, wv->by, wv->bz, wv->be, 1.0f, wv->bd, 0,
                                wv->st);
            e += nb;
            for (i = 0; i < nb; ++i) {
                fovsdf__wcone *p = &cn[act[s + i]];
                float d = wv->bd[i] - (mc->ulp0 + mc->ulp1 * p->t);
                if (d <= p->t * p->k * (1.0f + FOVSDF_CONE_SLACK) + mc->eps) {
                    p->i = 0xffffffffu; /* stopped (t <= t_max stays) */
                } else {
                    p->t += (d - p->t * p->k) / (1.0f + p->k);
                    ++p->i;
                }
            }
        }
    }
    wv->st->evals_lowres += e;
    if (mp == &mp2 && wv->nj > 0) fovsdf__wave_flush(wv); /* pv ends with the tile */
}

FOVSDF_API fov_result fovsdf_min_filter(const float *in, uint32_t w, uint32_t h, int32_t radius,
                                        float *out)
{
    uint32_t x, y;
    if (!in || !out) return FOV_ERR_NULL;
    if (w == 0 || h == 0 || radius < 0) return FOV_ERR_INVALID_ARG;
    if (w > FOVSDF_MAX_DIM || h > FOVSDF_MAX_DIM || radius > 64) return FOV_ERR_LIMIT;
    if (in == out) return FOV_ERR_INVALID_ARG;
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            uint32_t u0 = x > (uint32_t)radius ? x - (uint32_t)radius : 0,
                u1 = x + (uint32_t)radius < w ? x + (uint32_t)radius : w - 1;
            uint32_t v0 = y > (uint32_t)radius ? y - (uint32_t)radius : 0,
                v1 = y + (uint32_t)radius < h ? y + (uint32_t)radius : h - 1;
            uint32_t u, v;
            float t = in[(size_t)y * w + x];
            for (v = v0; v <= v1; ++v)
                for (u = u0; u <= u1; ++u)
                    t = in[(size_t)v * w + u] < t ? in[(size_t)v * w + u] : t;
            out[(size_t)y * w + x] = t;
        }
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_mask_blur(const float *rgb, uint32_t rgb_stride, const uint8_t *mask,
                                       uint32_t mask_stride, uint32_t w, uint32_t h, float sigma,
                                       float *out, uint32_t out_stride)
{
    float wt[25];
    int32_t R, i, j, x, y;
    if (!rgb || !mask || !out) return FOV_ERR_NULL;
    if (!fov__finite(sigma)) return FOV_ERR_NOT_FINITE;
    if (w == 0 || h == 0 || !(sigma >= 0.05f) || sigma > 8.0f || rgb == out)
        return FOV_ERR_INVALID_ARG;
    if (w > FOVSDF_MAX_DIM || h > FOVSDF_MAX_DIM) return FOV_ERR_LIMIT;
    if (rgb_stride == 0) rgb_stride = 3u * w;
    if (out_stride == 0) out_stride = 3u * w;
    if (mask_stride == 0) mask_stride = w;
    if (rgb_stride < 3u * w || out_stride < 3u * w || mask_stride < w) return FOV_ERR_TOO_SMALL;
    R = (int32_t)(3.0f * sigma);
    if ((float)R < 3.0f * sigma) ++R; /* ceil(3 sigma), at most 24 */
    for (i = 0; i <= R; ++i) wt[i] = FOV__EXP(-0.5f * (float)(i * i) / (sigma * sigma));
    for (y = 0; y < (int32_t)h; ++y)
        for (x = 0; x < (int32_t)w; ++x) {
            const float *s = rgb + (size_t)y * rgb_stride + 3u * (size_t)x;
            float *d = out + (size_t)y * out_stride + 3u * (size_t)x;
            int has1 = 0, has0 = 0;
            for (j = y - 1; j <= y + 1; ++j)
                for (i = x - 1; i <= x + 1; ++i)
                    if (i >= 0 && j >= 0 && i < (int32_t)w && j < (int32_t)h) {
                        if (mask[(size_t)j * mask_stride + (size_t)i] == 1u) has1 = 1;
                        else has0 = 1;
                    }
            if (!(has1 && has0)) { d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; continue; }
            {
                float acc[3] = { 0.0f, 0.0f, 0.0f }, sum = 0.0f;
                for (j = y - R; j <= y + R; ++j) {
                    if (j < 0 || j >= (int32_t)h) continue;
                    for (i = x - R; i <= x + R; ++i) {
                        const float *q;
                        float k;
                        if (i < 0 || i >= (int32_t)w) continue;
                        q = rgb + (size_t)j * rgb_stride + 3u * (size_t)i;
                        k = wt[i > x ? i - x : x - i] * wt[j > y ? j - y : y - j];
                        acc[0] += k * q[0]; acc[1] += k * q[1]; acc[2] += k * q[2];
                        sum += k;
                    }
                }
                d[0] = acc[0] / sum; d[1] = acc[1] / sum; d[2] = acc[2] / sum;
            }
        }
    return FOV_OK;
}

/* ---- inverted pyramid rendering, IPR (thesis Sec. 5.2; Polychronakis et al. 2023) ----------
   Level 0 traces one ray per cell of 2^(levels-1) x 2^(levels-1) pixels through the cell's
   centre from the camera; every higher level traces the rays of cells half as wide, each from
   the minimum t of its parent and the parent's neighbours within ipr_radius (the neighbour
   minimum filter, "applied before each level"); at the top every sample ray of a pixel starts
   from that filtered value. A miss is stored as t_max (explicit, so the filter takes the
   neighbours' hits). The filter is a heuristic: unlike the cone, a child may start past a
   surface the coarser rays did not see. Tiles are grid aligned with an apron of cells around
   them, so results do not depend on how the image is split. This is the thesis variant
   (heuristic_start 1); the default is fovsdf__ipr_tile_safe. */
FOVSDF__PRIV float fovsdf__ipr_min(const float *lv, uint32_t side, int32_t u, int32_t v, int32_t r)
{
    float t = lv[(size_t)v * side + (size_t)u];
    int32_t i, j;
    for (j = -r; j <= r; ++j)
        for (i = -r; i <= r; ++i) {
            float q = lv[(size_t)(v + j) * side + (size_t)(u + i)];
            t = q < t ? q : t;
        }
    return t;
}

FOVSDF__PRIV FOVSDF__NOINLINE void
fovsdf__ipr_tile(const fovsdf_ctx *c, const fovsdf__marcher *m, uint32_t tx, uint32_t ty,
                 uint32_t rx0, uint32_t ry0, uint32_t rx1, uint32_t ry1, fovsdf_stats *st,
                 fovsdf__wave *wv)
{
    float scratch[FOVSDF_TILE_SCRATCH], px[FOVSDF_WAVE], py[FOVSDF_WAVE], ts[FOVSDF_WAVE];
    float *lv[6];
    fovsdf_hit h[FOVSDF_WAVE];
    uint32_t side[6], apr[6], L = c->cfg.ipr_levels, T = c->cfg.ipr_tile, l, x, y;
    int32_t r = c->cfg.ipr_no_filter ? 0 : c->cfg.ipr_radius;
    size_t off = 0;
    uint64_t e0 = st->evals;
    for (l = 0; l + 1u < L; ++l) {
        apr[l] = fovsdf__ipr_apron(L, l, (uint32_t)r);
        side[l] = (T >> (L - 1u - l)) + 2u * apr[l];
        lv[l] = scratch + off;
        off += (size_t)side[l] * side[l];
    }
    FOV_ASSERT(off <= FOVSDF_TILE_SCRATCH);
    for (l = 0; l + 1u < L; ++l) {
        uint32_t S = 1u << (L - 1u - l), u, v;
        int32_t c0x = (int32_t)(tx / S) - (int32_t)apr[l],
            c0y = (int32_t)(ty / S) - (int32_t)apr[l];
        uint32_t n = side[l] * side[l], i, j, nb;
        for (i = 0; i < n; i += nb) { /* the level's rays as one wavefront, FOVSDF_WAVE at once */
            nb = n - i < FOVSDF_WAVE ? n - i : FOVSDF_WAVE;
            for (j = 0; j < nb; ++j) {
                int32_t cx, cy;
                u = (i + j) % side[l]; v = (i + j) / side[l];
                cx = c0x + (int32_t)u; cy = c0y + (int32_t)v;
                ts[j] = 0.0f;
                if (l > 0) { /* parent cell and its neighbours, in the parent's array */
                    int32_t pu = ((cx >= 0 ? cx : cx - 1) / 2) -
                        ((int32_t)(tx / (S * 2u)) - (int32_t)apr[l - 1]);
                    int32_t pv = ((cy >= 0 ? cy : cy - 1) / 2) -
                        ((int32_t)(ty / (S * 2u)) - (int32_t)apr[l - 1]);
                    ts[j] = fovsdf__ipr_min(lv[l - 1], side[l - 1], pu, pv, r);
                }
                px[j] = ((float)cx + 0.5f) * (float)S; py[j] = ((float)cy + 0.5f) * (float)S;
            }
            fovsdf__wave_rays(wv, m, nb, px, py, ts, h, 0);
            for (j = 0; j < nb; ++j)
                lv[l][i + j] = h[j].kind == FOVSDF_MISS ? c->t_max : h[j].t;
        }
    }
    st->evals_lowres += st->evals - e0;
    for (y = ry0; y < ry1; ++y)
        for (x = rx0; x < rx1; ++x) {
            float t0 = 0.0f;
            if (L > 1u) {
                int32_t pu = (int32_t)(x / 2u) - ((int32_t)(tx / 2u) - (int32_t)apr[L - 2u]);
                int32_t pv = (int32_t)(y / 2u) - ((int32_t)(ty / 2u) - (int32_t)apr[L - 2u]);
                t0 = fovsdf__ipr_min(lv[L - 2u], side[L - 2u], pu, pv, r);
            }
            fovsdf__wave_pixel(wv, m, x, y, t0 < c->t_max ? t0 : c->t_max, 0, NULL, 0.0f, 0.0f);
        }
}

/* A cell's certified head start (the safe variants of IPR, SKIP and FIPR): the cone of the pixel
   rectangle [x0, x1) x [y0, y1) marched from its parent's certified t_par (0: the camera), as
   CONE marches its cells. Every sample ray of the rectangle is empty up to t_par (its parent's
   cone contains it) and, along the cone, up to where the cone stopped: so it may start at the
   larger of the two. Returns -1 when the cone reached t_max (every ray of the cell misses). */
FOVSDF__PRIV float fovsdf__safe_start(const fovsdf_ctx *c, const fovsdf__marcher *m, float x0,
                                      float y0, float x1, float y1, float t_par, fovsdf_stats *st)
{
    float a[3], k, t;
    if (t_par < 0.0f) return -1.0f; /* the parent's cone is empty up to t_max: so is this one */
    k = fovsdf__cell_cone(c, x0, y0, x1, y1, a);
    t = fovsdf__cone_march(c, m, a, k, t_par * (1.0f / FOV__SQRT(1.0f + k * k)), st);
    if (t < 0.0f) return -1.0f;
    return fov__minf(fov__maxf(t, t_par), m->t_max);
}

/* IPR, safe variant (heuristic_start 0): the same levels and tiles, but each cell's value is
   the certified start of fovsdf__safe_start over its own pixels, from its parent's, in place of
   the thin ray's hit; no minimum filter is needed (each cone contains every sample ray that
   starts from it) and no apron: only the cells over the requested pixels are marched. */
FOVSDF__PRIV FOVSDF__NOINLINE void
fovsdf__ipr_tile_safe(const fovsdf_ctx *c, const fovsdf__marcher *m, uint32_t tx, uint32_t ty,
                      uint32_t rx0, uint32_t ry0, uint32_t rx1, uint32_t ry1, fovsdf_stats *st,
                      fovsdf__wave *wv)
{
    float scratch[FOVSDF_TILE_SCRATCH], ts[FOVSDF_WAVE];
    float *lv[6];
    fovsdf__wcone cn[FOVSDF_WAVE];
    uint32_t side[6], L = c->cfg.ipr_levels, T = c->cfg.ipr_tile, W = c->cam.width,
        H = c->cam.height, l, x, y, id[FOVSDF_WAVE], act[FOVSDF_WAVE];
    size_t off = 0;
    (void)st; /* the cones count into wv's, the same */
    for (l = 0; l + 1u < L; ++l) {
        side[l] = T >> (L - 1u - l);
        lv[l] = scratch + off;
        off += (size_t)side[l] * side[l];
    }
    FOV_ASSERT(off <= FOVSDF_TILE_SCRATCH);
    for (l = 0; l + 1u < L; ++l) {
        uint32_t S = 1u << (L - 1u - l), u, v;
        /* the cells over the requested pixels (their parents lie over them too), their cones
           (fovsdf__safe_start's) as one wavefront, FOVSDF_WAVE at once */
        uint32_t u0 = (rx0 - tx) / S, v0 = (ry0 - ty) / S, nu = (rx1 - 1u - tx) / S - u0 + 1u,
            n = nu * ((ry1 - 1u - ty) / S - v0 + 1u), i, j, nb, k;
        for (i = 0; i < n; i += nb) {
            nb = n - i < FOVSDF_WAVE ? n - i : FOVSDF_WAVE;
            for (j = k = 0; j < nb; ++j) {
                uint32_t x0, y0;
                float tp;
                u = u0 + (i + j) % nu; v = v0 + (i + j) / nu;
                x0 = tx + u * S; y0 = ty + v * S;
                tp = l > 0 ? lv[l - 1][(size_t)(v / 2u) * side[l - 1] + u / 2u] : 0.0f;
                if (tp < 0.0f) { /* the parent's cone is empty up to t_max: so is this one */
                    lv[l][(size_t)v * side[l] + u] = -1.0f;
                    continue;
                }
                cn[k].k = fovsdf__cell_cone(c, (float)x0, (float)y0,
                                            (float)(x0 + S < W ? x0 + S : W),
                                            (float)(y0 + S < H ? y0 + S : H), cn[k].a);
                cn[k].t = tp * (1.0f / FOV__SQRT(1.0f + cn[k].k * cn[k].k));
                ts[k] = tp;
                id[k++] = v * side[l] + u;
            }
            fovsdf__wave_cones(wv, m, k, cn, act);
            for (j = 0; j < k; ++j)
                lv[l][id[j]] =
                    cn[j].t < 0.0f ? -1.0f : fov__minf(fov__maxf(cn[j].t, ts[j]), m->t_max);
        }
    }
    for (y = ry0; y < ry1; ++y)
        for (x = rx0; x < rx1; ++x) {
            float t0 =
                L > 1u ? lv[L - 2u][(size_t)((y - ty) / 2u) * side[L - 2u] + (x - tx) / 2u] : 0.0f;
            if (t0 < 0.0f) fovsdf__wave_pixel(wv, m, x, y, 0.0f, 1, NULL, 0.0f, 0.0f);
            else fovsdf__wave_pixel(wv, m, x, y, t0, 0, NULL, 0.0f, 0.0f);
        }
}

/* ---- Skipping Spheres, SKIP (thesis Sec. 6.2; Polychronakis et al. 2024) -------------------
   Pass 1, per grid-aligned cell of skip_block x skip_block pixels: one ray through the cell's
   centre marches the scene scaled by s (Scale(p) = f(p/s) s per primitive, subtracted operands
   by 1/s so holes shrink; s becomes 1/s when the camera is inside, so the scene deflates)
   and stops early at skip_eps. With shadows, it also marches one shadow ray per light from its
   hit, scaled too, stopping when the penumbra factor drops below shadow_eps. Pass 2: every
   sample ray of the cell's pixels starts at the cell's t; a shadow ray whose low-resolution
   ray was never attenuated is not marched at all, the others start at half the distance where
   the low-resolution penumbra began. (Our choice: the thesis stores where the low-resolution
   shadow ray ended, which drops every penumbra it did not fully enter: about 10 dB PSNR on the
   columns scene at 160x90.)
   Choices where the thesis is silent: a low-resolution miss gives its pixels no head start
   (they march from the camera: treating them as misses lost 0.7 % of the pixels of the
   primitives scene at silhouettes); a pixel whose hit is farther than max(4 skip_eps, 2 % of t)
   from the cell's hit (another surface) gets no shadow head start; scaling is about each
   primitive's origin (built-in programs; plain distance callbacks cannot scale and get early
   termination only); one evaluation verifies each head start and a ray whose start lies inside a
   surface (a grazing floor seen by the cell's lower rows) starts over from the camera.
   Like IPR this is a heuristic: neither scaling nor early termination guarantees that small
   objects are seen. That is the thesis variant (heuristic_start 1); the default marches one
   certified cone per block instead (fovsdf__safe_start) and keeps none of the above. */
FOVSDF__PRIV FOVSDF__NOINLINE void
fovsdf__skip_cell(const fovsdf_ctx *c, const fovsdf__marcher *m, uint32_t cx, uint32_t cy,
                  uint32_t rx0, uint32_t ry0, uint32_t rx1, uint32_t ry1, fovsdf_stats *st,
                  fovsdf__wave *wv)
{
    uint32_t B = c->cfg.skip_block, x, y, i;
    uint32_t bx0 = cx * B, by0 = cy * B, bx1 = bx0 + B < c->cam.width ? bx0 + B : c->cam.width;
    uint32_t by1 = by0 + B < c->cam.height ? by0 + B : c->cam.height;
    float ro[3], rd[3], sh[FOVSDF_MAX_LIGHTS], t_low, s_eff = c->cfg.skip_scale, tol;
    fovsdf__marcher ml = *m;
    fovsdf_hit h;
    uint64_t e0 = st->evals, es0 = st->evals_shadow;
    int has_sh = 0;
    if (!c->cfg.heuristic_start) { /* safe: the block's cone, its pixels start where it stopped */
        float t0 =
            fovsdf__safe_start(c, m, (float)bx0, (float)by0, (float)bx1, (float)by1, 0.0f, st);
        for (y = (by0 > ry0 ? by0 : ry0); y < (by1 < ry1 ? by1 : ry1); ++y)
            for (x = (bx0 > rx0 ? bx0 : rx0); x < (bx1 < rx1 ? bx1 : rx1); ++x)
                fovsdf__wave_pixel(wv, m, x, y, t0 < 0.0f ? 0.0f : t0, t0 < 0.0f, NULL, 0.0f, 0.0f);
        return;
    }
    if (c->cam_dist < 0.0f) s_eff = 1.0f / s_eff; /* camera inside: deflate */
    ml.method = FOVSDF_METHOD_CLASSIC;
    ml.verify_start = 0;
    ml.eps = c->cfg.skip_eps;
    ml.eps_cone = 0.0f;
    ml.inflate = s_eff;
    /* through the centre of the block clipped to the image (a 1x1 image, or a border block of
       an image whose sides are not multiples of skip_block, has its ray inside the image) */
    fovsdf__ray(c, 0.5f * (float)(bx0 + bx1), 0.5f * (float)(by0 + by1), ro, rd);
    fovsdf__march(&ml, ro, rd, 0.0f, &h, 0, st);
    t_low = h.kind == FOVSDF_MISS ? c->t_max : h.t;
    if (h.kind != FOVSDF_MISS && c->cfg.shading == FOVSDF_SHADE_FULL &&
        !c->cfg.skip_no_shadow_start) {
        float p[3];
        p[0] = ro[0] + rd[0] * t_low; p[1] = ro[1] + rd[1] * t_low; p[2] = ro[2] + rd[2] * t_low;
        for (i = 0; i < c->scene.num_lights; ++i) {
            float l[3], dist, att, tr,
                k = c->scene.lights[i].shadow_k > 0.0f ? c->scene.lights[i].shadow_k : 16.0f;
            sh[i] = 0.0f;
            if (c->scene.lights[i].shadow_k < 0.0f || !fovsdf__light_dir(c, i, p, l, &dist, &att))
                continue;
            fovsdf__shadow(c, p, l, c->cfg.shadow_t0, dist, k, s_eff, 0, &tr, st);
            /* a ray never attenuated needs no full-resolution march; otherwise start at half the
               distance where its penumbra began, so the full-resolution ray (from a point up to
               a cell away) still integrates the penumbra */
            sh[i] = tr >= dist ? dist : 0.5f * tr;
        }
        has_sh = 1;
    }
    st->evals_lowres += st->evals - e0;
    st->evals_shadow = es0; /* the low-resolution shadow rays count as the low-resolution pass */
    tol = fov__maxf(4.0f * c->cfg.skip_eps, 0.02f * t_low);
    for (y = (by0 > ry0 ? by0 : ry0); y < (by1 < ry1 ? by1 : ry1); ++y)
        for (x = (bx0 > rx0 ? bx0 : rx0); x < (bx1 < rx1 ? bx1 : rx1); ++x)
            fovsdf__wave_pixel(wv, m, x, y, h.kind == FOVSDF_MISS ? 0.0f : t_low, 0,
                               has_sh ? sh : NULL, t_low, tol);
}

/* SKIP's default (heuristic_start 0) over the blocks of [x0, x1) x [y0, y1) (the blocks
   fovsdf__skip_cell would take, in its order): their certified starts (fovsdf__safe_start from
   the camera) marched as wavefronts of up to FOVSDF_WAVE cones (fovsdf__wave_cones), then each
   block's pixels queued as fovsdf__skip_cell queues them: the same starts, counts and pixels
   in the same order. */
FOVSDF__PRIV FOVSDF__NOINLINE void
fovsdf__skip_safe(const fovsdf_ctx *c, const fovsdf__marcher *m, uint32_t x0, uint32_t y0,
                  uint32_t x1, uint32_t y1, fovsdf__wave *wv)
{
    fovsdf__wcone cn[FOVSDF_WAVE];
    uint32_t act[FOVSDF_WAVE], B = c->cfg.skip_block, W = c->cam.width, H = c->cam.height;
    uint32_t cx, cy, nu = 0, nv = 0, j, nb, x, y, u = 0, v = 0, u0, v0;
    for (cx = x0 / B; cx * B < x1; ++cx) ++nu;
    for (cy = y0 / B; cy * B < y1; ++cy) ++nv;
    /* the blocks in row-major order, FOVSDF_WAVE at a time; (u, v) walks them without an
       index (nu nv reaches 2^32 at 65536 x 65536 with skip_block 1) */
    while (nu > 0 && v < nv) {
        u0 = u; v0 = v;
        for (nb = 0; nb < FOVSDF_WAVE && v < nv; ++nb) {
            uint32_t bx0 = (x0 / B + u) * B, by0 = (y0 / B + v) * B;
            float k = fovsdf__cell_cone(c, (float)bx0, (float)by0,
                                        (float)(bx0 + B < W ? bx0 + B : W),
                                        (float)(by0 + B < H ? by0 + B : H), cn[nb].a);
            cn[nb].k = k;
            cn[nb].t = 0.0f; /* from the camera: safe_start with t_par 0 */
            if (++u == nu) { u = 0; ++v; }
        }
        fovsdf__wave_cones(wv, m, nb, cn, act);
        u = u0; v = v0;
        for (j = 0; j < nb; ++j) {
            uint32_t bx0 = (x0 / B + u) * B, by0 = (y0 / B + v) * B;
            uint32_t bx1 = bx0 + B < W ? bx0 + B : W, by1 = by0 + B < H ? by0 + B : H;
            float t0 = cn[j].t < 0.0f ? -1.0f : fov__minf(fov__maxf(cn[j].t, 0.0f), m->t_max);
            for (y = (by0 > y0 ? by0 : y0); y < (by1 < y1 ? by1 : y1); ++y)
                for (x = (bx0 > x0 ? bx0 : x0); x < (bx1 < x1 ? bx1 : x1); ++x)
                    fovsdf__wave_pixel(wv, m, x, y, t0 < 0.0f ? 0.0f : t0, t0 < 0.0f, NULL, 0.0f,
                                       0.0f);
            if (++u == nu) { u = 0; ++v; }
        }
    }
}

/* ---- foveated methods: FIPR (thesis Sec. 5.2.1, Fig. 5.3; Polychronakis et al. 2023) and
   CONE_FOV (the same mask and refresh on the cone pyramid) -----------------------------------
   Per grid-aligned tile (ipr_tile pixels for FIPR, cone_tile for CONE_FOV), in the order the
   data flows (the thesis's five passes):
   1. low-resolution depth. FIPR: one ray per 4x4-pixel cell (level 0, 1/16 of the pixels)
      from the camera. CONE_FOV: the cone pyramid down to 2x2-pixel cells (their cones' t).
   2. edges: Sobel on a depth map, |G| > 8 edge_threshold tmin, tmin the least t of the 3x3
      neighbourhood: a relative change of depth per cell (scale-free; 8 is the Sobel response
      to a unit slope). FIPR: on level 0, nearest upscaling (the thesis); CONE_FOV: on the mid
      level, which it traces anyway.
   3. the mask (Eq. 5.1 and the combination policy, fov_mask): with w the pixel's eccentricity,
      p = fovsdf_acuity_p(acuity, w) (1 in the fovea, 0 beyond outer_deg) and
      u = fovsdf_u01(seed, x, y, 0), a pixel is in the mask when w <= fovea_deg, or when
      u < p and it lies on an edge (FOVSDF_MASK_EDGES). The thesis's literal product p * edge
      would drop the fovea's non-edge pixels, against its own text; we read "salient edges are
      traced even in the periphery" as this OR. The mask does not depend on the frame: pass
      another seed for another pattern.
   4. rendering. The mid level is one ray per 2x2-pixel cell through the cell's centre. FIPR:
      it starts from the minimum of level 0 over the parent and its neighbours within
      ipr_radius (the 3x3 min filter), and pixels in the mask march every sample ray from the
      same filter over the mid level (the thesis variant, heuristic_start 1); by default both
      start from the 2x2 cell's certified start instead (fovsdf__fov_tc). CONE_FOV: the mid
      ray and the pixels' sample rays start from their 2x2 cell's cone (the guarantee of CONE
      holds for every traced ray). Pixels
      outside the mask take the bilinear interpolation of the shaded mid-level rays around
      them (weights 3/4, 1/4 per axis) and are refreshed every refresh-th frame: the tiles
      take turns (refresh 2: a checkerboard of tiles; refresh 4: tile (i, j) refreshes when
      frame % 4 equals the Bayer rank [[0, 2], [3, 1]] at row j & 1, column i & 1), so every
      frame costs about the same. (Turns per 2x2 cell, tried first, saved 2 % and 14 % of the
      evaluations at refresh 2 and 4: the bilinear taps of a refreshed cell need its
      neighbours anyway.) A pixel that is
      not refreshed is not written at all (the caller's buffers hold the earlier frame; the
      mask output says 2). A static scene and gaze therefore reach the image of refresh 1
      after `refresh` consecutive frames.
      With quarter_deg > 0 (beyond the thesis) a pixel outside the mask whose eccentricity w
      exceeds quarter_deg takes, with weight s = min(1, (w - quarter_deg) / band), the
      bilinear interpolation of the quarter level (one ray per 4x4 cell through its centre,
      fovsdf__fov_q), and 1 - s of the mid level's (not fetched at all when s = 1); band =
      FOVSDF_QUARTER_BAND pixels at the axis's pixel size. With level_filter the level
      samples' albedo is their cell's mean (fovsdf__albedo_cell).
   5. the thesis's mask-guided blur is not applied here: its study found it made the
      foveation more visible (thesis Sec. 5.4.1, Fig. 5.8); fovsdf_mask_blur does it on request.
   Everything is lazy: a cell is traced, or shaded, the first time a pixel of the tile needs
   it, so the fovea never shades mid-level rays and the periphery never traces its pixels.
   The tile's arrays hold its cells and a one-cell (FIPR: max(1, r)) apron; the apron cells
   are traced by the tile that needs them (CONE_FOV: from the camera), so results depend on the
   tile grid only, never on the caller's split. */
typedef struct fovsdf__mid {
    float tc;              /* CONE_FOV: the cell cone's t; -1 proven empty; -2 unknown (apron) */
    float th, dist;        /* the centre ray: hit t (t_max: miss) and the distance there; while
                              its march is requested, th holds its start */
    float rgb[3];          /* its colour, once shaded (level_filter 2 and lit: its lighting,
                              the colour over the albedo) */
    float n[3];            /* level_filter 2 and lit: its normal */
    int32_t mat;
    uint8_t kind, state;   /* fovsdf_hit_kind; 0 untouched, 1 traced, 2 shaded */
    uint8_t lit;           /* level_filter 2: rgb and n are its lighting and normal */
    uint8_t nok;           /* n is its normal */
    uint8_t req;           /* requested this round: 1 its march, 2 its shading, 4 its cone
                              (safe FIPR; tc is -3 meanwhile) */
} fovsdf__mid;

typedef struct fovsdf__fovt {
    const fovsdf_ctx *c;
    const fovsdf__marcher *mp; /* mid rays and sample rays */
    fovsdf__mid *mid;          /* mid cells (u, v), u in [mu0, mu0 + ms) */
    float *l0;                 /* FIPR level 0: t, or -1 before it is traced (-3: requested) */
    float *l0s;                /* safe FIPR level 0: the cells' certified starts; -2 unknown,
                                  -3 requested */
    int32_t mu0, mv0, lu0, lv0, r;
    uint32_t ms, ls;
    float t_ring;              /* CONE_FOV: start of the apron cells (a cone over tile + apron) */
    int cone, safe;            /* CONE_FOV; FIPR with heuristic_start 0 */
    fovsdf_stats *st;
    fovsdf__wave *wv;          /* the wavefront the requests run in */
    int miss;                  /* a value the current pixel needs is not there yet */
    uint32_t nrm, nrl, nrs;    /* requests of this round: mid cells, level-0 rays and cones */
    uint32_t *rqm, *rql, *rqs; /* their indices in mid, l0 and l0s */
    fovsdf__mid dummy;         /* what a missing mid cell reads as */
    /* the quarter level (quarter_deg > 0): cells (i, j) of 4x4 pixels, i in [qu0, qu0 + qs) */
    int quarter;
    fovsdf__mid *qc;
    int32_t qu0, qv0;
    uint32_t qs, nrq;
    uint32_t *rqq;             /* its requests of this round */
    float qdeg, qband;         /* quarter_deg and the blend band, degrees (0: a hard switch) */
    /* eccentricity without the atan2 where a threshold decides (fovsdf__ecc_side): squared
       tangents around fovea_deg (ft2) and around the quarter band (qt2), an upper bound of
       fovsdf_acuity_p beyond the fovea (p_hi); ecc_fast 0: always the atan2 */
    int ecc_fast;
    float ft2lo, ft2hi, qt2lo, qt2hi, p_hi;
    int refine;                /* refine_depth, refine_normal_deg or refine_material set */
    float rncos;               /* cos refine_normal_deg (-2: never) */
} fovsdf__fovt;

/* Which side of two eccentricities pixel point (x, y) surely lies on, from the squared tangent
   of its angle to the gaze (|v x g|^2 / (v . g)^2, the terms fov__ecc_deg takes the atan2 of):
   -1 below the angle whose squared tangent is t2lo, 1 above t2hi's (t2hi < 0: never), 0
   undecided (take fovsdf_ecc_deg). fovsdf__ecc_t2 widens both by a relative 1e-3 on the
   tangent (at least 4e-4 of the angle below 60 degrees, a hundred times the float error of the
   atan2, the tangent and these products), so a decided side is always the side of
   fovsdf_ecc_deg's value: the same mask and weights as with the atan2 at every pixel. */
FOVSDF__PRIV int fovsdf__ecc_side(const fov_ecc_model *m, float x, float y, float t2lo,
                                  float t2hi)
{
    float v[3], c[3], s2, co;
    v[0] = x - m->cx; v[1] = y - m->cy; v[2] = m->f_px;
    if (!fov__finite(fov__dot(v, v))) return 0;
    fov__cross(v, m->g, c);
    s2 = fov__dot(c, c);
    co = fov__dot(v, m->g);
    if (!(co > 0.0f) || !fov__finite(s2)) return 0;
    co *= co;
    if (!fov__finite(co)) return 0;
    if (s2 < t2lo * co) return -1;
    if (t2hi >= 0.0f && s2 > t2hi * co) return 1;
    return 0;
}

/* The squared tangents of deg (degrees) widened by the relative margin of fovsdf__ecc_side:
   *lo just below, *hi just above; -1 for both (no side decided) and 0 when deg is outside
   (0, 60). */
FOVSDF__PRIV int fovsdf__ecc_t2(float deg, float *lo, float *hi)
{
    float t;
    if (!(deg > 0.0f && deg < 60.0f)) { *lo = -1.0f; *hi = -1.0f; return 0; }
    t = FOV__TAN(deg * (FOV__PI / 180.0f));
    *lo = (t * 0.999f) * (t * 0.999f);
    *hi = (t * 1.001f) * (t * 1.001f);
    return 1;
}

FOVSDF__PRIV uint32_t fovsdf__bayer(int32_t u, int32_t v, uint32_t k) /* refresh rank of a tile */
{
    static const uint8_t b4[4] = { 0, 2, 3, 1 };
    if (k == 2u) return (uint32_t)((u + v) & 1);
    return k == 4u ? b4[(u & 1) + 2 * (v & 1)] : 0u;
}
FOVSDF__PRIV int32_t fovsdf__fdiv2(int32_t a) /* floor(a / 2) */
{
    return (a - (a < 0 ? 1 : 0)) / 2;
}

/* FIPR level-0 cell (i, j): one ray through its centre from the camera, requested on first use
   (f->miss until the round's wavefront has traced it; see fovsdf__fov_tile). */
FOVSDF__PRIV float fovsdf__fov_l0(fovsdf__fovt *f, int32_t i, int32_t j)
{
    float *q;
    FOV_ASSERT(i >= f->lu0 && j >= f->lv0 && i < f->lu0 + (int32_t)f->ls &&
               j < f->lv0 + (int32_t)f->ls);
    q = f->l0 + (size_t)(j - f->lv0) * f->ls + (size_t)(i - f->lu0);
    if (*q < 0.0f) {
        if (*q > -2.0f) { /* untouched: request it */
            *q = -3.0f;
            f->rql[f->nrl++] = (uint32_t)(q - f->l0);
        }
        f->miss = 1;
        return 0.0f;
    }
    return *q;
}

/* Safe FIPR: the certified start of level-0 cell (i, j) (4x4 pixels, from the camera) and of
   mid cell (u, v) (2x2 pixels, from its level-0 parent's), in tc; -1 when proven empty. The
   cells are not clipped to the image (apron cells may lie outside it). */
FOVSDF__PRIV float fovsdf__fov_l0s(fovsdf__fovt *f, int32_t i, int32_t j)
{
    float *q;
    FOV_ASSERT(i >= f->lu0 && j >= f->lv0 && i < f->lu0 + (int32_t)f->ls &&
               j < f->lv0 + (int32_t)f->ls);
    q = f->l0s + (size_t)(j - f->lv0) * f->ls + (size_t)(i - f->lu0);
    if (*q > -1.5f) return *q;
    if (*q > -2.5f) { /* unknown: request its cone (-3) */
        *q = -3.0f;
        f->rqs[f->nrs++] = (uint32_t)(q - f->l0s);
    }
    f->miss = 1;
    return -1.0f;
}
FOVSDF__PRIV float fovsdf__fov_tc(fovsdf__fovt *f, int32_t u, int32_t v)
{
    fovsdf__mid *m;
    FOV_ASSERT(u >= f->mu0 && v >= f->mv0 && u < f->mu0 + (int32_t)f->ms &&
               v < f->mv0 + (int32_t)f->ms);
    m = f->mid + (size_t)(v - f->mv0) * f->ms + (size_t)(u - f->mu0);
    if (m->tc > -1.5f) return m->tc;
    if (m->tc > -2.5f) {
        int miss = f->miss;
        float tp;
        f->miss = 0;
        tp = fovsdf__fov_l0s(f, fovsdf__fdiv2(u), fovsdf__fdiv2(v));
        if (f->miss) return -1.0f; /* the parent's cone first */
        f->miss = miss;
        /* as fovsdf__safe_start: the parent's cone is empty up to t_max, so is this one */
        if (tp < 0.0f) { m->tc = -1.0f; return -1.0f; }
        if (!m->req) f->rqm[f->nrm++] = (uint32_t)(m - f->mid);
        m->req |= 4u; /* its cone */
        m->tc = -3.0f;
    }
    f->miss = 1;
    return -1.0f;
}

/* Mid cell (u, v): its march requested on first use, its shading when `shade` (f->miss and a
   dummy cell until the round's wavefront has run them, fovsdf__fov_run). fovsdf__fov_mid
   returns a cell that is there at once (inlined: the bilinear taps read 4 or 5 cells per
   pixel), fovsdf__fov_mid_req does the rest. */
FOVSDF__PRIV FOVSDF__NOINLINE const fovsdf__mid *
fovsdf__fov_mid_req(fovsdf__fovt *f, fovsdf__mid *m, int32_t u, int32_t v, int shade)
{
    const fovsdf_ctx *c = f->c;
    if (m->state == 0 && !(m->req & 1u)) {
        float t0 = 0.0f;
        if (f->cone) {
            t0 = m->tc >= 0.0f ? m->tc : f->t_ring;
        } else if (f->safe) {
            int miss = f->miss;
            f->miss = 0;
            t0 = fovsdf__fov_tc(f, u, v); /* -1: proven empty, below */
            if (f->miss) return &f->dummy; /* its cone first */
            f->miss = miss;
        } else {
            int32_t i = fovsdf__fdiv2(u), j = fovsdf__fdiv2(v), a, b;
            int miss = f->miss;
            f->miss = 0;
            t0 = c->t_max;
            for (b = -f->r; b <= f->r; ++b)
                for (a = -f->r; a <= f->r; ++a) t0 = fov__minf(t0, fovsdf__fov_l0(f, i + a, j + b));
            if (f->miss) return &f->dummy; /* its start needs level-0 rays first */
            f->miss = miss;
        }
        if ((f->cone || f->safe) && fov__is0(m->tc + 1.0f)) { /* the cone proved the cell empty */
            m->th = c->t_max; m->dist = 0.0f; m->kind = (uint8_t)FOVSDF_MISS; m->mat = -1;
            m->state = 1;
            if (!shade) return m;
        } else {
            if (!m->req) f->rqm[f->nrm++] = (uint32_t)(m - f->mid);
            m->req |= 1u;
            m->th = t0;
        }
    }
    if (shade && !(m->req & 2u)) {
        if (!m->req) f->rqm[f->nrm++] = (uint32_t)(m - f->mid);
        m->req |= 2u;
    }
    f->miss = 1;
    return &f->dummy;
}

FOVSDF__INL const fovsdf__mid *fovsdf__fov_mid(fovsdf__fovt *f, int32_t u, int32_t v, int shade)
{
    fovsdf__mid *m;
    FOV_ASSERT(u >= f->mu0 && v >= f->mv0 && u < f->mu0 + (int32_t)f->ms &&
               v < f->mv0 + (int32_t)f->ms);
    m = f->mid + (size_t)(v - f->mv0) * f->ms + (size_t)(u - f->mu0);
    if (m->state == 2 || (m->state == 1 && !shade)) return m;
    return fovsdf__fov_mid_req(f, m, u, v, shade);
}

/* Quarter cell (i, j) (4x4 pixels, its ray through the cell's centre, the corner its four 2x2
   cells share), as fovsdf__fov_mid. Its start: CONE_FOV, the least certified start of those 2x2
   cells that the tile holds (the apron's: f->t_ring), each of whose cones contains the ray (on
   its boundary; fovsdf__cell_cone includes the corners), a proven miss when one of them is
   empty; safe FIPR, the certified start of its level-0 cell (the same 4x4 pixels); thesis FIPR,
   the least level-0 hit over the cell and its neighbours within ipr_radius (as the mid level). */
FOVSDF__PRIV const fovsdf__mid *fovsdf__fov_q(fovsdf__fovt *f, int32_t i, int32_t j, int shade)
{
    const fovsdf_ctx *c = f->c;
    fovsdf__mid *m;
    FOV_ASSERT(i >= f->qu0 && j >= f->qv0 && i < f->qu0 + (int32_t)f->qs &&
               j < f->qv0 + (int32_t)f->qs);
    m = f->qc + (size_t)(j - f->qv0) * f->qs + (size_t)(i - f->qu0);
    if (m->state == 2 || (m->state == 1 && !shade)) return m;
    if (m->state == 0 && !(m->req & 1u)) {
        float t0 = c->t_max;
        int empty = 0, miss = f->miss;
        int32_t a, b;
        f->miss = 0;
        if (f->cone) {
            for (b = 0; b < 2; ++b)
                for (a = 0; a < 2; ++a) {
                    int32_t u = 2 * i + a, v = 2 * j + b;
                    float tc;
                    if (u < f->mu0 || v < f->mv0 || u >= f->mu0 + (int32_t)f->ms ||
                        v >= f->mv0 + (int32_t)f->ms)
                        continue;
                    tc = f->mid[(size_t)(v - f->mv0) * f->ms + (size_t)(u - f->mu0)].tc;
                    if (fov__is0(tc + 1.0f)) empty = 1;
                    else t0 = fov__minf(t0, tc >= 0.0f ? tc : f->t_ring);
                }
        } else if (f->safe) {
            t0 = fovsdf__fov_l0s(f, i, j); /* -1: proven empty */
            if (f->miss) return &f->dummy;
            empty = t0 < 0.0f;
        } else {
            for (b = -f->r; b <= f->r; ++b)
                for (a = -f->r; a <= f->r; ++a) t0 = fov__minf(t0, fovsdf__fov_l0(f, i + a, j + b));
            if (f->miss) return &f->dummy; /* its start needs level-0 rays first */
        }
        f->miss = miss;
        if (empty) {
            m->th = c->t_max; m->dist = 0.0f; m->kind = (uint8_t)FOVSDF_MISS; m->mat = -1;
            m->state = 1;
            if (!shade) return m;
        } else {
            if (!m->req) f->rqq[f->nrq++] = (uint32_t)(m - f->qc);
            m->req |= 1u;
            m->th = t0;
        }
    }
    if (shade && !(m->req & 2u)) {
        if (!m->req) f->rqq[f->nrq++] = (uint32_t)(m - f->qc);
        m->req |= 2u;
    }
    f->miss = 1;
    return &f->dummy;
}

/* The weight of the quarter level at pixel (x, y): 0 before quarter_deg (or without the level),
   rising linearly to 1 over the band. */
FOVSDF__PRIV float fovsdf__fov_qw(const fovsdf__fovt *f, uint32_t x, uint32_t y)
{
    float w;
    if (!f->quarter) return 0.0f;
    if (f->ecc_fast) { /* beyond the band's ends the weight is 0 or 1 without the value */
        int side = fovsdf__ecc_side(&f->c->ecc, (float)x + 0.5f, (float)y + 0.5f, f->qt2lo,
                                    f->qt2hi);
        if (side) return side < 0 ? 0.0f : 1.0f;
    }
    w = fovsdf_ecc_deg(&f->c->ecc, (float)x + 0.5f, (float)y + 0.5f) - f->qdeg;
    if (!(f->qband > 0.0f)) return w >= 0.0f ? 1.0f : 0.0f;
    return fovsdf__clampf(w / f->qband, 0.0f, 1.0f);
}

/* The marches (pass 1) and shadings (pass 2) requested for cells of side S pixels (the mid
   level's 2, the quarter level's 4), rays through the cells' centres, as wavefronts. */
FOVSDF__PRIV void fovsdf__fov_cells_run(fovsdf__fovt *f, fovsdf__mid *cells, const uint32_t *rq,
                                        uint32_t nr, int32_t u0, int32_t v0, uint32_t side,
                                        float S)
{
    const fovsdf_ctx *c = f->c;
    float px[FOVSDF_WAVE], py[FOVSDF_WAVE], t0[FOVSDF_WAVE], rgb[3 * FOVSDF_WAVE];
    fovsdf_hit h[FOVSDF_WAVE];
    int32_t mat[FOVSDF_WAVE];
    uint32_t id[FOVSDF_WAVE], i, k, n, pass;
    for (pass = 1; pass <= 2; ++pass) /* 1: marches, 2: shading */
        for (i = 0; i < nr;) {
            for (n = 0; n < FOVSDF_WAVE && i < nr; ++i) {
                fovsdf__mid *m = &cells[rq[i]];
                int32_t u = u0 + (int32_t)(rq[i] % side),
                    v = v0 + (int32_t)(rq[i] / side);
                if (!(m->req & pass)) continue;
                px[n] = ((float)u + 0.5f) * S; py[n] = ((float)v + 0.5f) * S;
                t0[n] = m->th;
                if (pass == 2u) {
                    h[n].kind = m->kind; h[n].t = m->th; h[n].dist = m->dist; h[n].steps = 0;
                    h[n].evals = 0;
                    mat[n] = m->mat;
                }
                id[n++] = rq[i];
            }
            if (n == 0) continue;
            if (pass == 1u) {
                fovsdf__wave_rays(f->wv, f->mp, n, px, py, t0, h, mat);
                for (k = 0; k < n; ++k) {
                    fovsdf__mid *m = &cells[id[k]];
                    fovsdf_hit *hk = &h[k];
                    /* the interpolated pixels report this ray's depth: a hit must lie in
                       [0, t_max] (a tracer's hit beyond t_max, or a non-finite one, is a miss) */
                    if (hk->kind != FOVSDF_MISS && !(hk->t >= 0.0f && hk->t <= c->t_max)) {
                        hk->kind = FOVSDF_MISS; hk->t = c->t_max; hk->dist = 0.0f;
                    }
                    m->th = hk->kind == FOVSDF_MISS ? c->t_max : hk->t;
                    m->dist = hk->dist;
                    m->kind = (uint8_t)hk->kind;
                    m->mat = hk->kind == FOVSDF_MISS ? -1 : mat[k];
                    m->state = 1;
                    f->st->evals_lowres += hk->evals;
                }
            } else {
                f->wv->afoot = c->cfg.level_filter == 1u ? (uint32_t)S : 0u;
                fovsdf__wave_shade_rays(f->wv, f->mp, n, px, py, h, mat, rgb);
                f->wv->afoot = 0;
                for (k = 0; k < n; ++k) {
                    fovsdf__mid *m = &cells[id[k]];
                    const fovsdf__wray *r = &f->wv->ray[k]; /* its slot, as shaded */
                    m->lit = (uint8_t)(c->cfg.level_filter == 2u && r->lit);
                    m->nok = (uint8_t)r->lit;
                    m->n[0] = m->n[1] = m->n[2] = 0.0f;
                    if (r->lit) { m->n[0] = r->n[0]; m->n[1] = r->n[1]; m->n[2] = r->n[2]; }
                    if (m->lit) { /* the pixels take the albedo at their own points */
                        m->rgb[0] = r->acc[0]; m->rgb[1] = r->acc[1]; m->rgb[2] = r->acc[2];
                    } else {
                        m->rgb[0] = rgb[3u * k]; m->rgb[1] = rgb[3u * k + 1u];
                        m->rgb[2] = rgb[3u * k + 2u];
                    }
                    m->state = 2;
                }
            }
        }
    for (i = 0; i < nr; ++i) cells[rq[i]].req = 0;
}

/* The requests of one round as wavefronts: the level-0 rays, then the mid rays (their starts
   need the level-0 ones), then the shading of mid rays; every value exactly as the cell's own
   march and fovsdf__shade_ray. */
FOVSDF__PRIV void fovsdf__fov_run(fovsdf__fovt *f)
{
    const fovsdf_ctx *c = f->c;
    float px[FOVSDF_WAVE], py[FOVSDF_WAVE], t0[FOVSDF_WAVE];
    fovsdf_hit h[FOVSDF_WAVE];
    uint32_t id[FOVSDF_WAVE], act[FOVSDF_WAVE], i, j, k, n;
    for (i = 0; i < f->nrl; i += n) {
        n = f->nrl - i < FOVSDF_WAVE ? f->nrl - i : FOVSDF_WAVE;
        for (k = 0; k < n; ++k) {
            uint32_t q = f->rql[i + k];
            px[k] = ((float)(f->lu0 + (int32_t)(q % f->ls)) + 0.5f) * 4.0f;
            py[k] = ((float)(f->lv0 + (int32_t)(q / f->ls)) + 0.5f) * 4.0f;
            t0[k] = 0.0f;
        }
        fovsdf__wave_rays(f->wv, f->mp, n, px, py, t0, h, 0);
        for (k = 0; k < n; ++k) {
            f->l0[f->rql[i + k]] = h[k].kind == FOVSDF_MISS ? c->t_max : h[k].t;
            f->st->evals_lowres += h[k].evals;
        }
    }
    f->nrl = 0;
    /* safe FIPR's cones (fovsdf__safe_start): level 0's from the camera and the mid cells'
       from their parents', which the request found already marched: one wavefront */
    for (i = 0, j = 0; i < f->nrs || j < f->nrm;) {
        fovsdf__wcone cn[FOVSDF_WAVE];
        for (n = 0; n < FOVSDF_WAVE && (i < f->nrs || j < f->nrm);) {
            float x0, y0, s = 4.0f, tp = 0.0f;
            if (i < f->nrs) {
                uint32_t q = f->rqs[i++];
                x0 = 4.0f * (float)(f->lu0 + (int32_t)(q % f->ls));
                y0 = 4.0f * (float)(f->lv0 + (int32_t)(q / f->ls));
                id[n] = q;
            } else {
                uint32_t q = f->rqm[j++];
                int32_t u = f->mu0 + (int32_t)(q % f->ms), v = f->mv0 + (int32_t)(q / f->ms);
                if (!(f->mid[q].req & 4u)) continue;
                x0 = 2.0f * (float)u; y0 = 2.0f * (float)v; s = 2.0f;
                tp = fovsdf__fov_l0s(f, fovsdf__fdiv2(u), fovsdf__fdiv2(v));
                id[n] = q | 0x80000000u;
            }
            cn[n].k = fovsdf__cell_cone(c, x0, y0, x0 + s, y0 + s, cn[n].a);
            cn[n].t = tp * (1.0f / FOV__SQRT(1.0f + cn[n].k * cn[n].k));
            t0[n] = tp;
            ++n;
        }
        fovsdf__wave_cones(f->wv, f->mp, n, cn, act);
        for (k = 0; k < n; ++k) {
            float t = cn[k].t < 0.0f ? -1.0f : fov__minf(fov__maxf(cn[k].t, t0[k]), f->mp->t_max);
            if (id[k] & 0x80000000u) f->mid[id[k] & 0x7fffffffu].tc = t;
            else f->l0s[id[k]] = t;
        }
    }
    f->nrs = 0;
    fovsdf__fov_cells_run(f, f->mid, f->rqm, f->nrm, f->mu0, f->mv0, f->ms, 2.0f);
    f->nrm = 0;
    if (f->nrq) fovsdf__fov_cells_run(f, f->qc, f->rqq, f->nrq, f->qu0, f->qv0, f->qs, 4.0f);
    f->nrq = 0;
}

/* Step 2: Sobel on level 0 (FIPR) or the mid level (CONE_FOV) around cell (i, j). */
FOVSDF__PRIV int fovsdf__fov_edge(fovsdf__fovt *f, int32_t i, int32_t j)
{
    float t[9], tmin, gx, gy, s;
    int32_t a, b;
    for (b = -1; b <= 1; ++b)
        for (a = -1; a <= 1; ++a)
            t[(b + 1) * 3 + (a + 1)] =
                f->cone ? fovsdf__fov_mid(f, i + a, j + b, 0)->th : fovsdf__fov_l0(f, i + a, j + b);
    tmin = t[0];
    for (a = 1; a < 9; ++a) tmin = fov__minf(tmin, t[a]);
    gx = (t[2] + 2.0f * t[5] + t[8]) - (t[0] + 2.0f * t[3] + t[6]);
    gy = (t[6] + 2.0f * t[7] + t[8]) - (t[0] + 2.0f * t[1] + t[2]);
    s = 8.0f * f->c->cfg.edge_threshold * fov__maxf(tmin, 1e-6f);
    return gx * gx + gy * gy > s * s;
}

/* Whether every pixel of the S x S cell at (x0, y0) takes the quarter level alone (weight 1):
   its 2x2 cells then need no cones of their own (the quarter ray starts from this cell's). */
FOVSDF__PRIV int fovsdf__fov_qonly(const fovsdf__fovt *f, uint32_t x0, uint32_t y0, uint32_t S)
{
    uint32_t x, y;
    for (y = y0; y < y0 + S; ++y)
        for (x = x0; x < x0 + S; ++x)
            if (fovsdf__fov_qw(f, x, y) < 1.0f) return 0;
    return 1;
}

/* Step 1 of CONE_FOV: the cone pyramid over the tile, down to 2x2-pixel cells (cone_levels
   permitting), storing each cell's t in the mid cells it covers. The cells are the tile's own
   grid, not clipped to the image, so 2x2 cells stay aligned. The cones march as one wavefront
   (as fovsdf__wave_cones: each exactly as fovsdf__cone_march), a cell's children joining as
   soon as it stops; the first, besides the tile's, is the apron's cone (f->t_ring: one cone over
   the tile widened by the apron's 2x2 cells, which lie in the neighbouring tiles, gives their
   rays a safe start). A cell marches only after its parent, so the cells in flight never
   outnumber the tile's 2x2 cells. */
FOVSDF__PRIV void fovsdf__fov_cones(fovsdf__fovt *f, const fovsdf__marcher *mc, uint32_t tx,
                                    uint32_t ty, uint32_t T)
{
    const fovsdf_ctx *c = f->c;
    fovsdf__wave *w = f->wv;
    fovsdf__wcone cn[FOVSDF_FOV_CELLS + 4];
    /* a slot's cell: its offset in the tile (x | y << 16) and width; slot 1 is the apron's */
    uint32_t pos[FOVSDF_FOV_CELLS + 4], wid[FOVSDF_FOV_CELLS + 4], act[FOVSDF_FOV_CELLS + 4],
        fr[FOVSDF_FOV_CELLS + 4], lev[FOVSDF_FOV_CELLS + 4];
    uint32_t na = 2, nf = 0, j, i, nb, q, keep;
    uint64_t e = 0;
    for (j = FOVSDF_FOV_CELLS + 4u; j-- > 2u;) fr[nf++] = j; /* free slots */
    pos[0] = 0; wid[0] = T; lev[0] = 1;
    cn[0].k = fovsdf__cell_cone(c, (float)tx, (float)ty, (float)(tx + T), (float)(ty + T), cn[0].a);
    cn[0].t = 0.0f;
    cn[1].k = fovsdf__cell_cone(c, (float)tx - 2.0f, (float)ty - 2.0f, (float)(tx + T) + 2.0f,
                                (float)(ty + T) + 2.0f, cn[1].a);
    cn[1].t = 0.0f;
    act[0] = 0; act[1] = 1; cn[0].i = 0; cn[1].i = 0;
    for (i = 0; i < FOVSDF_BATCH; ++i) w->be[i] = mc->eps;
    while (na > 0) {
        /* the cones that stopped leave (fovsdf__wcone_go), their children join */
        keep = 0;
        for (j = 0; j < na; ++j) {
            uint32_t id = act[j], x0, y0, S, L;
            float t;
            if (fovsdf__wcone_go(mc, &cn[id])) { act[keep++] = id; continue; }
            if (id == 1u) { f->t_ring = cn[1].t < 0.0f ? c->t_max : cn[1].t; continue; }
            x0 = tx + (pos[id] & 0xffffu); y0 = ty + (pos[id] >> 16); S = wid[id]; L = lev[id];
            t = cn[id].t;
            fr[nf++] = id;
            if (t < 0.0f || S <= 2u || L >= c->cfg.cone_levels ||
                (S <= 4u && f->quarter && fovsdf__fov_qonly(f, x0, y0, S))) {
                uint32_t u, v;
                for (v = y0 / 2u; v < (y0 + S) / 2u; ++v)
                    for (u = x0 / 2u; u < (x0 + S) / 2u; ++u)
                        f->mid[(size_t)((int32_t)v - f->mv0) * f->ms +
                               (size_t)((int32_t)u - f->mu0)].tc = t < 0.0f ? -1.0f : t;
                continue;
            }
            for (q = 0; q < 4u; ++q) {
                uint32_t h = S / 2u, cx = x0 + ((q & 1u) ? h : 0u), cy = y0 + ((q & 2u) ? h : 0u);
                uint32_t k;
                fovsdf__wcone *ch;
                if (cx >= c->cam.width || cy >= c->cam.height) continue; /* off the image */
                FOV_ASSERT(nf > 0);
                k = fr[--nf];
                ch = &cn[k];
                pos[k] = (cx - tx) | (cy - ty) << 16; wid[k] = h; lev[k] = L + 1u;
                ch->k = fovsdf__cell_cone(c, (float)cx, (float)cy, (float)(cx + h),
                                          (float)(cy + h), ch->a);
                ch->t = t * (1.0f / FOV__SQRT(1.0f + ch->k * ch->k)); /* as CONE */
                ch->i = 0;
                act[na++] = k; /* examined later in this pass */
            }
        }
        na = keep;
        /* one step of every cone in flight */
        for (j = 0; j < na; j += nb) {
            nb = na - j < FOVSDF_BATCH ? na - j : FOVSDF_BATCH;
            for (i = 0; i < nb; ++i) {
                const fovsdf__wcone *p = &cn[act[j + i]];
                w->bx[i] = c->origin[0] + p->a[0] * p->t; w->by[i] = c->origin[1] + p->a[1] * p->t;
                w->bz[i] = c->origin[2] + p->a[2] * p->t;
            }
            fovsdf__wave_eval_m(mc, nb, w->bx, w->by, w->bz, w->be, 1.0f, w->bd, 0, w->st);
            e += nb;
            for (i = 0; i < nb; ++i) {
                fovsdf__wcone *p = &cn[act[j + i]];
                /* as fovsdf__cone_march */
                float d = w->bd[i] - (mc->ulp0 + mc->ulp1 * p->t);
                if (d <= p->t * p->k * (1.0f + FOVSDF_CONE_SLACK) + mc->eps) {
                    p->i = 0xffffffffu; /* stopped: no more steps (t <= t_max stays) */
                } else {
                    p->t += (d - p->t * p->k) / (1.0f + p->k);
                    ++p->i;
                }
            }
        }
    }
    w->st->evals_lowres += e;
}

/* The least and largest luminance (Rec. 709 weights, linear) of the colours seen so far. */
FOVSDF__PRIV void fovsdf__lum_range(const float rgb[3], float *lo, float *hi)
{
    float Y = 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
    *lo = fov__minf(*lo, Y);
    *hi = fov__maxf(*hi, Y);
}

/* level_filter 2: the colour level sample m (lit; its ray through image point (cx, cy)) gives
   the pixel whose ray has the unit direction pd: its lighting times the albedo where pd meets
   the sample's tangent plane, with its material (the sample's own point when pd meets the
   plane behind the camera, from its other side, or more grazing than a quarter of the sample
   ray's incidence, as fovsdf__albedo_cell), clamped as a shaded ray's colour. Into out. */
FOVSDF__PRIV const float *fovsdf__tap_rgb(const fovsdf_ctx *c, const fovsdf__mid *m, float cx,
                                          float cy, const float pd[3], float out[3])
{
    float ro[3], r0[3], q[3], x[3], alb[3], dn, dn0, t;
    int k;
    (void)fovsdf__ray(c, cx, cy, ro, r0);
    for (k = 0; k < 3; ++k) q[k] = r0[k] * m->th;
    dn = fov__dot(pd, m->n);
    dn0 = fov__dot(r0, m->n);
    t = dn * dn0 > 0.0f && fov__absf(dn) >= 0.25f * fov__absf(dn0) ? fov__dot(q, m->n) / dn
                                                                     : -1.0f;
    if (t > 0.0f && fov__finite(t))
        for (k = 0; k < 3; ++k) x[k] = ro[k] + pd[k] * t;
    else
        for (k = 0; k < 3; ++k) x[k] = ro[k] + q[k];
    fovsdf__albedo(c, x, m->mat, alb);
    for (k = 0; k < 3; ++k) out[k] = fovsdf__clampf(alb[k] * m->rgb[k], 0.0f, FOVSDF__RGB_MAX);
    return out;
}

/* What the interpolation taps seen so far say of the geometry (refine_depth, refine_normal_deg,
   refine_material): the nearest and farthest hit, the hits' and the taps' counts, the hits'
   material (-2: two or more), the first normal nf and the least cosine between it and the
   others' (2: no normal yet). The cosine to the first normal, not every pair: at most twice
   the angle. */
FOVSDF__PRIV void fovsdf__depth_range(const fovsdf__mid *m, float *lo, float *hi, uint32_t *nhit,
                                      uint32_t *ntap, int32_t *mat, int *mixed, float nf[3],
                                      float *ncos)
{
    ++*ntap;
    if (m->kind == FOVSDF_MISS) return;
    if (*nhit == 0u) *mat = m->mat;
    else if (*mat != m->mat) *mixed = 1; /* two materials (any int32_t is a material id) */
    if (m->nok && *ncos > 1.5f) { /* the first normal */
        nf[0] = m->n[0]; nf[1] = m->n[1]; nf[2] = m->n[2];
        *ncos = 1.0f;
    } else if (m->nok) {
        *ncos = fov__minf(*ncos, fov__dot(nf, m->n));
    }
    ++*nhit;
    *lo = fov__minf(*lo, m->th);
    *hi = fov__maxf(*hi, m->th);
}

/* Steps 3 and 4 for pixel (x, y) of a FIPR / CONE_FOV tile, as far as the cells it needs allow:
   0 when one is missing (requested: f->miss), else 1 (the pixel is queued or written). *ps
   keeps its mask decision between rounds. */
FOVSDF__PRIV int fovsdf__fov_pixel(fovsdf__fovt *f, uint32_t x, uint32_t y, uint8_t *ps, int due,
                                   const fovsdf_output *o)
{
    const fovsdf_ctx *c = f->c;
    int32_t u = (int32_t)(x / 2u), v = (int32_t)(y / 2u);
    f->miss = 0;
    if (*ps == 0u) {
        /* step 3: the mask (the eccentricity's value only where the threshold or p needs it:
           fovsdf__ecc_side; u >= p_hi >= p outside the fovea) */
        float w = 0.0f, p;
        int in, side = f->ecc_fast ? fovsdf__ecc_side(&c->ecc, (float)x + 0.5f, (float)y + 0.5f,
                                                      f->ft2lo, f->ft2hi)
                                   : 0;
        if (side > 0 && c->cfg.fov_mask != FOVSDF_MASK_FOVEA &&
            !(fovsdf_u01(c->cfg.seed, x, y, 0) < f->p_hi))
            side = 2; /* u >= p: outside the mask */
        if (side == 0 || (side == 1 && c->cfg.fov_mask != FOVSDF_MASK_FOVEA))
            w = fovsdf_ecc_deg(&c->ecc, (float)x + 0.5f, (float)y + 0.5f); /* p needs it */
        if (side < 0) in = 1;
        else if (side == 2) in = 0;
        else if (side == 0 && w <= c->cfg.acuity.fovea_deg) in = 1;
        else if (c->cfg.fov_mask == FOVSDF_MASK_FOVEA) in = 0;
        else {
            p = fovsdf_acuity_p(&c->cfg.acuity, w);
            in = fovsdf_u01(c->cfg.seed, x, y, 0) < p &&
                 (c->cfg.fov_mask == FOVSDF_MASK_ACUITY ||
                  fovsdf__fov_edge(f, f->cone ? u : (int32_t)(x / 4u),
                                   f->cone ? v : (int32_t)(y / 4u)));
        }
        if (f->miss) return 0;
        *ps = in ? 2u : 1u;
    }
    /* step 4: render */
    if (*ps == 2u) {
        float t0;
        int miss = 0;
        if (f->cone || f->safe) {
            t0 = f->cone ? f->mid[(size_t)(v - f->mv0) * f->ms + (size_t)(u - f->mu0)].tc
                         : fovsdf__fov_tc(f, u, v);
            if (f->miss) return 0;
            miss = t0 < 0.0f;
            if (miss) t0 = 0.0f;
        } else {
            int32_t a, b;
            t0 = c->t_max;
            for (b = -f->r; b <= f->r; ++b)
                for (a = -f->r; a <= f->r; ++a)
                    t0 = fov__minf(t0, fovsdf__fov_mid(f, u + a, v + b, 0)->th);
            if (f->miss) return 0;
        }
        fovsdf__wave_pixel(f->wv, f->mp, x, y, t0, miss, NULL, 0.0f, 0.0f);
    } else if (!due) {
        if (o->mask)
            o->mask[(size_t)(y - o->origin_y) *
                    (o->mask_stride ? o->mask_stride : c->cam.width - o->origin_x) +
                    (x - o->origin_x)] = 2u;
    } else {
        int32_t a, b;
        float col[3] = { 0.0f, 0.0f, 0.0f }, s = fovsdf__fov_qw(f, x, y), ylo = 3.4e38f,
              yhi = -3.4e38f, tlo = 3.4e38f, thi = 0.0f;
        uint32_t nhit = 0, ntap = 0;
        int32_t tmat = -1;
        int tmix = 0;
        float tnf[3] = { 0.0f, 0.0f, 0.0f }, tncos = 2.0f; /* 2: no normal yet */
        const int rd = f->refine;
        const int rmat = c->cfg.refine_material != 0u;
        const float rncos = f->rncos;
        const fovsdf__mid *own = &f->dummy;
        float pd[3] = { 0.0f, 0.0f, 0.0f }, tc[3];
        if (c->cfg.level_filter == 2u) {
            float ro[3];
            (void)fovsdf__ray(c, (float)x + 0.5f, (float)y + 0.5f, ro, pd); /* the pixel's ray */
        }
        if (s < 1.0f) { /* the mid level, bilinear */
            int32_t ua = (x & 1u) ? u : u - 1, va = (y & 1u) ? v : v - 1;
            float wx = (x & 1u) ? 0.25f : 0.75f, wy = (y & 1u) ? 0.25f : 0.75f;
            own = fovsdf__fov_mid(f, u, v, 1);
            for (b = 0; b < 2; ++b)
                for (a = 0; a < 2; ++a) {
                    const fovsdf__mid *m = fovsdf__fov_mid(f, ua + a, va + b, 1);
                    float wt = (a ? wx : 1.0f - wx) * (b ? wy : 1.0f - wy);
                    const float *mc = m->lit && !f->miss
                                          ? fovsdf__tap_rgb(c, m, 2.0f * (float)(ua + a) + 1.0f,
                                                            2.0f * (float)(va + b) + 1.0f, pd, tc)
                                          : m->rgb;
                    col[0] += wt * mc[0]; col[1] += wt * mc[1];
                    col[2] += wt * mc[2];
                    if (c->cfg.refine_contrast > 0.0f) fovsdf__lum_range(m->rgb, &ylo, &yhi);
                    if (rd) fovsdf__depth_range(m, &tlo, &thi, &nhit, &ntap, &tmat, &tmix, tnf,
                                                &tncos);
                }
        }
        if (s > 0.0f) { /* the quarter level, bilinear (weights 5/8 .. 3/8 per axis), blended */
            static const float qw[4] = { 0.625f, 0.875f, 0.125f, 0.375f };
            int32_t i = (int32_t)(x / 4u), j = (int32_t)(y / 4u);
            int32_t ia = (x & 2u) ? i : i - 1, ja = (y & 2u) ? j : j - 1;
            float wx = qw[x & 3u], wy = qw[y & 3u], cq[3] = { 0.0f, 0.0f, 0.0f };
            const fovsdf__mid *oq = fovsdf__fov_q(f, i, j, 1);
            for (b = 0; b < 2; ++b)
                for (a = 0; a < 2; ++a) {
                    const fovsdf__mid *m = fovsdf__fov_q(f, ia + a, ja + b, 1);
                    float wt = (a ? wx : 1.0f - wx) * (b ? wy : 1.0f - wy);
                    const float *mc = m->lit && !f->miss
                                          ? fovsdf__tap_rgb(c, m, 4.0f * (float)(ia + a) + 2.0f,
                                                            4.0f * (float)(ja + b) + 2.0f, pd, tc)
                                          : m->rgb;
                    cq[0] += wt * mc[0]; cq[1] += wt * mc[1];
                    cq[2] += wt * mc[2];
                    if (c->cfg.refine_contrast > 0.0f) fovsdf__lum_range(m->rgb, &ylo, &yhi);
                    if (rd) fovsdf__depth_range(m, &tlo, &thi, &nhit, &ntap, &tmat, &tmix, tnf,
                                                &tncos);
                }
            for (a = 0; a < 3; ++a) col[a] = (1.0f - s) * col[a] + s * cq[a];
            if (s >= 0.5f) own = oq;
        }
        if (f->miss) return 0;
        if (c->cfg.refine_contrast > 0.0f &&
            yhi - ylo > c->cfg.refine_contrast * (yhi + ylo + 1e-3f)) {
            *ps = 2u; /* refined: the taps' contrast says an edge; trace the pixel */
            return fovsdf__fov_pixel(f, x, y, ps, due, o);
        }
        if (rd && nhit > 0u &&
            ((nhit < ntap && c->cfg.refine_depth > 0.0f) || (tmix && rmat) ||
             tncos < rncos ||
             (c->cfg.refine_depth > 0.0f && thi - tlo > c->cfg.refine_depth * tlo))) {
            /* refined: the taps say a silhouette, another object or a crease; trace the pixel */
            *ps = 2u;
            return fovsdf__fov_pixel(f, x, y, ps, due, o);
        }
        fovsdf__put(c, o, x, y, col, own->th, (uint8_t)(own->kind != FOVSDF_MISS), 0u, 0.0f, 0u,
                    own->mat, s > 0.0f ? 3u : 0u);
    }
    *ps = 3u;
    return 1;
}

FOVSDF__PRIV FOVSDF__NOINLINE void
fovsdf__fov_tile(const fovsdf_ctx *c, const fovsdf__marcher *mc, const fovsdf__marcher *mp,
                 uint32_t tx, uint32_t ty, uint32_t rx0, uint32_t ry0, uint32_t rx1, uint32_t ry1,
                 const fovsdf_output *o, fovsdf_stats *st, fovsdf__wave *wv)
{
    fovsdf__mid mid[FOVSDF_FOV_CELLS], qc[FOVSDF__FOV_QCELLS];
    float l0[2 * FOVSDF_FOV_CELLS];
    uint32_t rqm[FOVSDF_FOV_CELLS], rql[FOVSDF_FOV_CELLS], rqs[FOVSDF_FOV_CELLS],
        rqq[FOVSDF__FOV_QCELLS];
    uint8_t ps[4u * FOVSDF_FOV_CELLS]; /* per pixel: 0 unknown, 1 outside the mask, 2 inside,
                                          3 done (a tile has at most 4 pixels per mid cell) */
    fovsdf__fovt f;
    uint32_t T, x, y, i, ph = c->cfg.frame % c->cfg.refresh, left;
    int32_t am;
    int due;
    fovsdf__pruned pv;
    fovsdf__marcher mc2, mp2;
    f.c = c; f.mp = mp; f.mid = mid; f.l0 = l0; f.l0s = l0 + FOVSDF_FOV_CELLS; f.st = st;
    f.wv = wv; f.rqm = rqm; f.rql = rql; f.rqs = rqs; f.nrm = 0; f.nrl = 0; f.nrs = 0;
    f.miss = 0;
    FOV_MEMSET(&f.dummy, 0, sizeof f.dummy);
    f.cone = c->cfg.method == FOVSDF_METHOD_CONE_FOV;
    f.safe = !f.cone && !c->cfg.heuristic_start;
    f.r = f.cone ? 1 : (c->cfg.ipr_no_filter ? 0 : c->cfg.ipr_radius);
    T = f.cone ? c->cfg.cone_tile : c->cfg.ipr_tile;
    /* step 4's refresh: whole tiles take turns (a finer pattern would still need every mid cell
       for the bilinear taps of its neighbours and save almost nothing) */
    due = c->cfg.refresh == 1u ||
        fovsdf__bayer((int32_t)(tx / T), (int32_t)(ty / T), c->cfg.refresh) == ph;
    am = f.r > 1 ? f.r : 1;
    f.ms = T / 2u + 2u * (uint32_t)am;
    f.mu0 = (int32_t)(tx / 2u) - am; f.mv0 = (int32_t)(ty / 2u) - am;
    f.ls = T / 4u + 2u * (uint32_t)((am + 1) / 2 + f.r);
    f.lu0 = (int32_t)(tx / 4u) - (am + 1) / 2 - f.r;
    f.lv0 = (int32_t)(ty / 4u) - (am + 1) / 2 - f.r;
    FOV_ASSERT((size_t)f.ms * f.ms <= FOVSDF_FOV_CELLS &&
               (f.cone || (size_t)f.ls * f.ls <= FOVSDF_FOV_CELLS));
    for (i = 0; i < f.ms * f.ms; ++i) { mid[i].tc = -2.0f; mid[i].state = 0; mid[i].req = 0; }
    if (!f.cone)
        for (i = 0; i < f.ls * f.ls; ++i) { l0[i] = -1.0f; f.l0s[i] = -2.0f; }
    f.t_ring = 0.0f;
    /* the quarter level: the tile's 4x4 cells and a one-cell apron (T is a multiple of 4) */
    f.refine = c->cfg.refine_depth > 0.0f || c->cfg.refine_normal_deg > 0.0f ||
               c->cfg.refine_material != 0u;
    f.rncos = c->cfg.refine_normal_deg > 0.0f
                  ? FOV__COS(c->cfg.refine_normal_deg * (FOV__PI / 180.0f)) : -2.0f;
    f.quarter = c->cfg.quarter_deg > 0.0f;
    f.qc = qc; f.rqq = rqq; f.nrq = 0;
    f.qs = T / 4u + 2u; f.qu0 = (int32_t)(tx / 4u) - 1; f.qv0 = (int32_t)(ty / 4u) - 1;
    f.qdeg = c->cfg.quarter_deg;
    f.qband = (float)FOVSDF_QUARTER_BAND / (c->ecc.f_px * 0.017453292f);
    /* the eccentricity's shortcuts (fovsdf__ecc_side), not with math hooks of unknown accuracy */
#if defined(FOV__HOOKED_MATH)
    f.ecc_fast = 0;
#else
    f.ecc_fast = 1;
#endif
    (void)fovsdf__ecc_t2(c->cfg.acuity.fovea_deg, &f.ft2lo, &f.ft2hi);
    (void)fovsdf__ecc_t2(f.qdeg, &f.qt2lo, &f.qt2hi);
    if (f.qband > 0.0f) { /* the upper end: where the weight reaches 1 */
        float lo;
        (void)fovsdf__ecc_t2(f.qdeg + f.qband, &lo, &f.qt2hi);
    }
    {
        const fovsdf_acuity *a = &c->cfg.acuity;
        f.p_hi = 2.0f; /* no bound */
        if (!fov__finite(a->A) || !fov__finite(a->rate) || !fov__finite(a->C))
            f.p_hi = 0.0f; /* fovsdf_acuity_p is 0 */
        else if (a->A >= 0.0f && a->rate >= 0.0f && a->fovea_deg > 0.0f && a->fovea_deg < 60.0f)
            f.p_hi = (a->A * FOV__EXP(-a->rate * a->fovea_deg) + a->C) * 1.001f + 1e-6f;
    }
    if (f.quarter) {
        FOV_ASSERT(T % 4u == 0 && (size_t)f.qs * f.qs <= FOVSDF__FOV_QCELLS);
        for (i = 0; i < f.qs * f.qs; ++i) { qc[i].state = 0; qc[i].req = 0; }
    }
    /* the cone of the tile and its apron's 2x2 cells (as the apron's cone in fovsdf__fov_cones) */
    if (f.cone && fovsdf__tile_cone(c, mc, mp, (float)tx - 2.0f, (float)ty - 2.0f,
                                    (float)(tx + T) + 2.0f, (float)(ty + T) + 2.0f, &pv)) {
        mc2 = *mc; mc2.pv = &pv; mc = &mc2;
        mp2 = *mp; mp2.pv = &pv; f.mp = &mp2;
    }
    if (f.cone) fovsdf__fov_cones(&f, mc, tx, ty, T);
    /* rounds: each pixel goes as far as the cells it needs allow; the cells it misses are
       requested and marched (or shaded) as one wavefront (fovsdf__fov_run) before the next
       round. A pixel requests a cell only on the path the lazy pass took (every value it read
       before was final), so the tile traces and shades exactly the cells that pass did, with
       the same values; only the order of the queued pixels differs. */
    FOV_ASSERT((rx1 - rx0) * (ry1 - ry0) <= 4u * FOVSDF_FOV_CELLS);
    for (i = 0; i < (rx1 - rx0) * (ry1 - ry0); ++i) ps[i] = 0;
    for (;;) {
        left = 0;
        for (y = ry0; y < ry1; ++y)
            for (x = rx0; x < rx1; ++x) {
                uint8_t *q = &ps[(y - ry0) * (rx1 - rx0) + (x - rx0)];
                if (*q != 3u && !fovsdf__fov_pixel(&f, x, y, q, due, o)) ++left;
            }
        if (left == 0) break;
        FOV_ASSERT(f.nrm > 0 || f.nrl > 0 || f.nrs > 0 || f.nrq > 0);
        fovsdf__fov_run(&f);
    }
    if (f.mp == &mp2 && wv->nj > 0) fovsdf__wave_flush(wv); /* pv ends with the tile */
}

FOVSDF_API fov_result fovsdf_render_tile(const fovsdf_ctx *c, uint32_t x0, uint32_t y0, uint32_t x1,
                                         uint32_t y1, const fovsdf_output *o, fovsdf_stats *stats)
{
    fovsdf_stats local;
    fovsdf__marcher m, mp; /* mp: the pixels' marcher, alive until the last flush */
    fovsdf__wave wv;
    uint32_t x, y;
    fov_result r;
    if (!c) return FOV_ERR_NULL;
    if (!o) FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_NULL, "render_tile: output o is NULL");
    if (x0 > x1) FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG, "render_tile: needs x0 <= x1");
    if (y0 > y1)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG, "render_tile/rows: needs y0 <= y1");
    if (x1 > c->cam.width || y1 > c->cam.height)
        FOVSDF__FAIL(&c->cfg.logger, FOV_ERR_INVALID_ARG,
                     "render_tile/rows: x1 or y1 beyond the image");
    r = fovsdf__check_output(c, o, x0, y0, x1, y1);
    if (r != FOV_OK) return r;
    FOV_MEMSET(&local, 0, sizeof local);
    fovsdf__marcher_from_ctx(c, &m, c->origin);
    fovsdf__wave_init(&wv, c, o, &local);
    if (c->cfg.method == FOVSDF_METHOD_SKIP) {
        mp = m;
        uint32_t B = c->cfg.skip_block, cx, cy;
        mp.method = c->cfg.finish - 1u;
        mp.verify_start = (int)c->cfg.heuristic_start; /* a certified start needs no check */
        if (!c->cfg.heuristic_start) fovsdf__skip_safe(c, &mp, x0, y0, x1, y1, &wv);
        else
            for (cy = y0 / B; cy * B < y1; ++cy)
                for (cx = x0 / B; cx * B < x1; ++cx)
                    fovsdf__skip_cell(c, &mp, cx, cy, x0, y0, x1, y1, &local, &wv);
    } else if (c->cfg.method == FOVSDF_METHOD_IPR) {
        mp = m;
        uint32_t T = c->cfg.ipr_tile, tx, ty;
        mp.method = c->cfg.finish - 1u; /* every level traces with the finishing tracer */
        mp.verify_start = (int)c->cfg.heuristic_start;
        for (ty = y0 - y0 % T; ty < y1; ty += T)
            for (tx = x0 - x0 % T; tx < x1; tx += T)
                (c->cfg.heuristic_start ? fovsdf__ipr_tile : fovsdf__ipr_tile_safe)(
                    c, &mp, tx, ty, tx > x0 ? tx : x0, ty > y0 ? ty : y0, tx + T < x1 ? tx + T : x1,
                    ty + T < y1 ? ty + T : y1, &local, &wv);
    } else if (c->cfg.method == FOVSDF_METHOD_FIPR || c->cfg.method == FOVSDF_METHOD_CONE_FOV) {
        mp = m;
        uint32_t T = c->cfg.method == FOVSDF_METHOD_FIPR ? c->cfg.ipr_tile : c->cfg.cone_tile, tx,
            ty;
        mp.method = c->cfg.finish - 1u;
        if (c->cfg.method == FOVSDF_METHOD_FIPR) mp.verify_start = (int)c->cfg.heuristic_start;
        for (ty = y0 - y0 % T; ty < y1; ty += T)
            for (tx = x0 - x0 % T; tx < x1; tx += T)
                fovsdf__fov_tile(c, &m, &mp, tx, ty, tx > x0 ? tx : x0, ty > y0 ? ty : y0,
                                 tx + T < x1 ? tx + T : x1, ty + T < y1 ? ty + T : y1, o, &local,
                                 &wv);
    } else if (c->cfg.method == FOVSDF_METHOD_CONE) {
        mp = m;
        uint32_t T = c->cfg.cone_tile, tx, ty;
        mp.method = c->cfg.finish - 1u; /* fovsdf_finish -> fovsdf_method */
        for (ty = y0 - y0 % T; ty < y1; ty += T)
            for (tx = x0 - x0 % T; tx < x1; tx += T)
                fovsdf__cone_tile(c, &m, &mp, tx, ty, tx + T < c->cam.width ? tx + T : c->cam.width,
                                  ty + T < c->cam.height ? ty + T : c->cam.height, x0, y0, x1, y1,
                                  &local, &wv);
    } else {
        for (y = y0; y < y1; ++y)
            for (x = x0; x < x1; ++x)
                fovsdf__wave_pixel(&wv, &m, x, y, 0.0f, 0, NULL, 0.0f, 0.0f);
    }
    fovsdf__wave_flush(&wv); /* the pixels still queued */
    if (stats) fovsdf_stats_add(stats, &local);
    return FOV_OK;
}

FOVSDF_API uint32_t fovsdf_band_rows(const fovsdf_ctx *c)
{
    if (!c) return 1;
    switch (c->cfg.method) {
    case FOVSDF_METHOD_CONE: return c->cfg.cone_tile;
    case FOVSDF_METHOD_IPR: return c->cfg.ipr_tile;
    case FOVSDF_METHOD_SKIP: return c->cfg.skip_block;
    case FOVSDF_METHOD_FIPR: return c->cfg.ipr_tile;
    case FOVSDF_METHOD_CONE_FOV: return c->cfg.cone_tile;
    default: return 1;
    }
}

FOVSDF_API fov_result fovsdf_render_rows(const fovsdf_ctx *c, uint32_t y0, uint32_t y1,
                                         const fovsdf_output *o, fovsdf_stats *stats)
{
    if (!c) return FOV_ERR_NULL;
    return fovsdf_render_tile(c, 0, y0, c->cam.width, y1, o, stats);
}

/* ---- built-in scenes (modelled on the thesis's test scenes, Fig. 5.5 and 6.4) ------------- */
/* Node capacity of each built-in scene (exactly what its builder creates: a scene that grows
   without updating this fails fovsdf_builtin_init with FOV_ERR_TOO_SMALL, which the tests see). */
static const uint32_t fovsdf__scene_nodes[_FOVSDF_SCENE_NUM] = { 67u, 25u, 20u, 61u, 28u, 9u };

FOVSDF__PRIV int32_t fovsdf__at(fovsdf_builder *b, int32_t x, float tx, float ty, float tz)
{
    return fovsdf_translate(b, x, tx, ty, tz);
}
FOVSDF__PRIV int32_t fovsdf__mat(fovsdf_builder *b, int32_t m) { b->material = m; return m; }

FOVSDF__PRIV void fovsdf__light(fovsdf_scene *s, uint32_t type, float x, float y, float z, float r,
                                float g, float bl, float range, float k)
{
    fovsdf_light *L;
    if (s->num_lights >= FOVSDF_MAX_LIGHTS) return;
    L = &s->lights[s->num_lights++];
    L->type = type;
    L->v[0] = x; L->v[1] = y; L->v[2] = z;
    L->color[0] = r; L->color[1] = g; L->color[2] = bl;
    L->range = range;
    L->shadow_k = k;
}

FOVSDF__PRIV void fovsdf__view(fovsdf_builtin *o, float px, float py, float pz, float tx, float ty,
                               float tz, float fov, float t_max)
{
    fovsdf_camera_init(&o->camera, 640, 360);
    o->camera.pos[0] = px; o->camera.pos[1] = py; o->camera.pos[2] = pz;
    o->camera.target[0] = tx; o->camera.target[1] = ty; o->camera.target[2] = tz;
    o->camera.fov_y_deg = fov;
    o->scene.t_max = t_max;
}

/* Primitives: the open scene, every primitive and operator on a checkerboard plane. */
FOVSDF__PRIV int32_t fovsdf__scene_primitives(fovsdf_builder *b, fovsdf_builtin *o)
{
    int32_t r, x, y;
    float a[3], c[3];
    fovsdf__mat(b, 1);
    r = fovsdf_plane(b, 0.0f, 1.0f, 0.0f, 0.0f);
    fovsdf__mat(b, 2);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_sphere(b, 0.5f), -4.0f, 0.5f, 0.0f));
    fovsdf__mat(b, 3);
    r = fovsdf_union(b, r,
                     fovsdf__at(b,
                                fovsdf_rotate(b, fovsdf_box(b, 0.4f, 0.4f, 0.4f), 0.0f, 1.0f, 0.0f,
                                              30.0f), -2.0f, 0.4f, 0.0f));
    fovsdf__mat(b, 4);
    r = fovsdf_union(b, r,
                     fovsdf__at(b, fovsdf_round_box(b, 0.45f, 0.35f, 0.45f, 0.12f), 0.0f, 0.35f,
                                0.0f));
    fovsdf__mat(b, 5);
    r = fovsdf_union(b, r,
                     fovsdf__at(b,
                                fovsdf_rotate(b, fovsdf_torus(b, 0.4f, 0.12f), 1.0f, 0.0f, 0.0f,
                                              90.0f), 2.0f, 0.55f, 0.0f));
    fovsdf__mat(b, 6);
    a[0] = -0.3f; a[1] = 0.2f; a[2] = 0.0f; c[0] = 0.3f; c[1] = 0.9f; c[2] = 0.1f;
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_capsule(b, a, c, 0.18f), 4.0f, 0.0f, 0.0f));
    fovsdf__mat(b, 7);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_cylinder(b, 0.5f, 0.35f), -4.0f, 0.5f, 2.5f));
    fovsdf__mat(b, 2);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_cone(b, 0.5f, 0.45f, 0.1f), -2.0f, 0.5f, 2.5f));
    fovsdf__mat(b, 3);
    r = fovsdf_union(b, r,
                     fovsdf__at(b, fovsdf_box_frame(b, 0.45f, 0.45f, 0.45f, 0.04f), 0.0f, 0.45f,
                                2.5f));
    fovsdf__mat(b, 4);
    x = fovsdf__at(b, fovsdf_sphere(b, 0.35f), -0.25f, 0.0f, 0.0f);
    fovsdf__mat(b, 6);
    y = fovsdf__at(b, fovsdf_box(b, 0.25f, 0.25f, 0.25f), 0.3f, 0.0f, 0.0f);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_smooth_union(b, x, y, 0.25f), 2.0f, 0.4f, 2.5f));
    fovsdf__mat(b, 5);
    x = fovsdf_onion(b, fovsdf_sphere(b, 0.45f), 0.04f);
    y = fovsdf__at(b, fovsdf_box(b, 0.6f, 0.3f, 0.6f), 0.0f, 0.45f, -0.3f);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_subtract(b, x, y), 4.0f, 0.5f, 2.5f));
    fovsdf__mat(b, 7);
    x = fovsdf_intersect(b, fovsdf_sphere(b, 0.5f), fovsdf_box(b, 0.4f, 0.4f, 0.4f));
    r = fovsdf_union(b, r, fovsdf__at(b, x, -3.0f, 0.4f, 5.0f));
    fovsdf__mat(b, 2);
    x = fovsdf_smooth_subtract(b, fovsdf_box(b, 0.45f, 0.45f, 0.45f), fovsdf_sphere(b, 0.55f),
                               0.1f);
    r = fovsdf_union(b, r, fovsdf__at(b, x, 0.0f, 0.45f, 5.0f));
    fovsdf__mat(b, 3);
    x = fovsdf_smooth_intersect(b, fovsdf_sphere(b, 0.55f), fovsdf_cylinder(b, 0.6f, 0.4f), 0.1f);
    r = fovsdf_union(b, r, fovsdf__at(b, x, 3.0f, 0.5f, 5.0f));
    fovsdf__mat(b, 4); /* a mirrored pair of rounded boxes, scaled */
    x = fovsdf_mirror(b,
                      fovsdf__at(b, fovsdf_round(b, fovsdf_box(b, 0.1f, 0.3f, 0.1f), 0.05f), 0.5f,
                                 0.0f, 0.0f), 1);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_scale(b, x, 1.2f), 0.0f, 0.42f, 7.5f));
    fovsdf__mat(b, 6); /* a short row of repeated small spheres */
    x = fovsdf_repeat(b, fovsdf_sphere(b, 0.12f), 0.5f, 0.0f, 0.0f, 6, 0, 0);
    r = fovsdf_union(b, r, fovsdf__at(b, x, 0.0f, 0.12f, -1.5f));
    fovsdf_scene_init(&o->scene);
    o->scene.num_lights = 0;
    fovsdf__light(&o->scene, FOVSDF_LIGHT_DIRECTIONAL, -0.6f, 0.8f, -0.4f, 1.0f, 0.95f, 0.85f, 0.0f,
                  16.0f);
    o->scene.ambient[0] = 0.18f; o->scene.ambient[1] = 0.2f; o->scene.ambient[2] = 0.25f;
    fovsdf__view(o, 0.0f, 2.6f, -7.0f, 0.0f, 0.4f, 2.5f, 50.0f, 60.0f);
    return r;
}

/* Columns and Lights: a closed hall of repeated columns lit by five point lights. */
FOVSDF__PRIV int32_t fovsdf__scene_columns(fovsdf_builder *b, fovsdf_builtin *o)
{
    int32_t r, col, x;
    fovsdf__mat(b, 1);
    r = fovsdf_plane(b, 0.0f, 1.0f, 0.0f, 0.0f);
    fovsdf__mat(b, 7);
    x = fovsdf_subtract(b, fovsdf__at(b, fovsdf_box(b, 20.5f, 2.5f, 20.5f), 0.0f, 2.0f, 0.0f),
                        fovsdf__at(b, fovsdf_box(b, 19.5f, 2.25f, 19.5f), 0.0f, 1.75f, 0.0f));
    r = fovsdf_union(b, r, x);
    fovsdf__mat(b, 4);
    col = fovsdf__at(b, fovsdf_cylinder(b, 1.8f, 0.35f), 0.0f, 2.0f, 0.0f);
    fovsdf__mat(b, 0);
    col = fovsdf_union(b, col, fovsdf__at(b, fovsdf_box(b, 0.5f, 0.1f, 0.5f), 0.0f, 0.1f, 0.0f));
    col = fovsdf_union(b, col, fovsdf__at(b, fovsdf_box(b, 0.5f, 0.1f, 0.5f), 0.0f, 3.9f, 0.0f));
    fovsdf__mat(b, 3);
    col = fovsdf_union(b, col, fovsdf__at(b, fovsdf_torus(b, 0.36f, 0.05f), 0.0f, 3.6f, 0.0f));
    col = fovsdf_repeat(b, col, 4.0f, 0.0f, 4.0f, 4, 0, 4);
    r = fovsdf_union(b, r, col);
    fovsdf__mat(b, 2);
    x = fovsdf_repeat(b, fovsdf__at(b, fovsdf_sphere(b, 0.3f), 0.0f, 0.3f, 0.0f), 8.0f, 0.0f, 8.0f,
                      2, 0, 2);
    r = fovsdf_union(b, r, fovsdf__at(b, x, 2.0f, 0.0f, 2.0f));
    fovsdf_scene_init(&o->scene);
    o->scene.num_lights = 0;
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, 2.0f, 3.0f, -6.0f, 3.0f, 2.2f, 1.2f, 5.0f, 12.0f);
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, -6.0f, 2.5f, 2.0f, 1.2f, 1.8f, 3.0f, 5.0f, 12.0f);
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, 6.0f, 2.5f, 6.0f, 2.6f, 1.2f, 2.4f, 5.0f, 12.0f);
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, -2.0f, 3.2f, 10.0f, 1.5f, 3.0f, 1.5f, 5.0f, 12.0f);
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, 10.0f, 3.0f, -2.0f, 3.0f, 3.0f, 2.0f, 5.0f, 12.0f);
    o->scene.ambient[0] = o->scene.ambient[1] = o->scene.ambient[2] = 0.06f;
    fovsdf__view(o, 1.7f, 1.6f, -10.0f, 3.5f, 1.5f, 4.0f, 60.0f, 60.0f);
    return r;
}

/* Temple on a terrain: hills to the horizon (large depth range), a columned temple. */
FOVSDF__PRIV int32_t fovsdf__scene_temple(fovsdf_builder *b, fovsdf_builtin *o)
{
    int32_t r, t, x, y;
    fovsdf__mat(b, 5);
    r = fovsdf_terrain(b, 6.0f, 0.035f, 6);
    fovsdf__mat(b, 7);
    t = fovsdf__at(b, fovsdf_box(b, 4.6f, 0.6f, 6.6f), 0.0f, 0.1f, 0.0f);
    t = fovsdf_union(b, t, fovsdf__at(b, fovsdf_box(b, 4.2f, 0.15f, 6.2f), 0.0f, 0.85f, 0.0f));
    x = fovsdf_repeat(b, fovsdf_cylinder(b, 1.5f, 0.25f), 1.6f, 0.0f, 2.0f, 2, 0, 3);
    t = fovsdf_union(b, t, fovsdf__at(b, x, 0.0f, 2.5f, 0.0f));
    t = fovsdf_union(b, t, fovsdf__at(b, fovsdf_box(b, 4.0f, 0.25f, 6.0f), 0.0f, 4.25f, 0.0f));
    fovsdf__mat(b, 2);
    x = fovsdf_rotate(b, fovsdf_box(b, 2.9f, 2.9f, 6.1f), 0.0f, 0.0f, 1.0f, 45.0f);
    y = fovsdf_plane(b, 0.0f, -1.0f, 0.0f, 4.5f);
    t = fovsdf_union(b, t, fovsdf_intersect(b, fovsdf__at(b, x, 0.0f, 2.45f, 0.0f), y));
    r = fovsdf_union(b, r, t);
    fovsdf_scene_init(&o->scene);
    o->scene.num_lights = 0;
    fovsdf__light(&o->scene, FOVSDF_LIGHT_DIRECTIONAL, -0.5f, 0.45f, 0.35f, 1.2f, 1.05f, 0.85f,
                  0.0f, 12.0f);
    o->scene.ambient[0] = 0.2f; o->scene.ambient[1] = 0.22f; o->scene.ambient[2] = 0.28f;
    fovsdf__view(o, -14.0f, 6.0f, -22.0f, 0.0f, 2.0f, 0.0f, 45.0f, 400.0f);
    return r;
}

/* Atrium: an interior court with two storeys of arcades (many objects, open roof). */
FOVSDF__PRIV int32_t fovsdf__scene_atrium(fovsdf_builder *b, fovsdf_builtin *o)
{
    int32_t r, x, arch, up, bay;
    fovsdf__mat(b, 1);
    r = fovsdf_plane(b, 0.0f, 1.0f, 0.0f, 0.0f);
    fovsdf__mat(b, 7); /* side walls and end walls */
    x = fovsdf_mirror(b, fovsdf__at(b, fovsdf_box(b, 0.5f, 5.0f, 16.0f), 7.0f, 5.0f, 0.0f), 1);
    r = fovsdf_union(b, r, x);
    x = fovsdf_mirror(b, fovsdf__at(b, fovsdf_box(b, 7.5f, 5.0f, 0.5f), 0.0f, 5.0f, 15.5f), 4);
    r = fovsdf_union(b, r, x);
    /* one bay of the arcade: column, arch with a cylindrical cut, upper column, balustrade */
    fovsdf__mat(b, 4);
    bay = fovsdf__at(b, fovsdf_cylinder(b, 1.6f, 0.28f), 0.0f, 1.6f, 0.0f);
    fovsdf__mat(b, 0);
    bay = fovsdf_union(b, bay, fovsdf__at(b, fovsdf_box(b, 0.4f, 0.12f, 0.4f), 0.0f, 0.12f, 0.0f));
    bay = fovsdf_union(b, bay, fovsdf__at(b, fovsdf_box(b, 0.4f, 0.12f, 0.4f), 0.0f, 3.2f, 0.0f));
    fovsdf__mat(b, 7);
    arch = fovsdf__at(b, fovsdf_box(b, 0.35f, 0.8f, 1.25f), 0.0f, 4.1f, 1.25f);
    x = fovsdf__at(b, fovsdf_rotate(b, fovsdf_cylinder(b, 0.5f, 0.95f), 0.0f, 0.0f, 1.0f, 90.0f),
                   0.0f, 3.4f, 1.25f);
    arch = fovsdf_subtract(b, arch, x);
    bay = fovsdf_union(b, bay, arch);
    fovsdf__mat(b, 4);
    up = fovsdf__at(b, fovsdf_cylinder(b, 1.1f, 0.18f), 0.0f, 6.0f, 0.0f);
    fovsdf__mat(b, 2);
    up = fovsdf_union(b, up, fovsdf__at(b, fovsdf_box(b, 0.25f, 0.5f, 1.25f), -0.1f, 5.4f, 1.25f));
    up = fovsdf_union(b, up, fovsdf__at(b, fovsdf_box(b, 0.35f, 0.2f, 1.25f), 0.0f, 7.3f, 1.25f));
    bay = fovsdf_union(b, bay, up);
    fovsdf__mat(b, 6); /* hanging rings in each bay */
    bay = fovsdf_union(b, bay,
                       fovsdf__at(b,
                                  fovsdf_rotate(b, fovsdf_torus(b, 0.3f, 0.04f), 0.0f, 0.0f, 1.0f,
                                                90.0f), 0.0f, 2.3f, 1.25f));
    bay = fovsdf_repeat(b, bay, 0.0f, 0.0f, 2.5f, 0, 0, 5);
    r = fovsdf_union(b, r, fovsdf_mirror(b, fovsdf__at(b, bay, 4.0f, 0.0f, -1.25f), 1));
    /* the gallery floor between arcade and wall */
    fovsdf__mat(b, 0);
    r = fovsdf_union(b, r,
                     fovsdf_mirror(b,
                                   fovsdf__at(b, fovsdf_box(b, 1.5f, 0.15f, 15.0f), 5.5f, 4.75f,
                                              0.0f), 1));
    /* fountain and statues in the court */
    fovsdf__mat(b, 3);
    x = fovsdf_subtract(b, fovsdf_cylinder(b, 0.3f, 1.2f),
                        fovsdf__at(b, fovsdf_cylinder(b, 0.3f, 1.05f), 0.0f, 0.2f, 0.0f));
    r = fovsdf_union(b, r, fovsdf__at(b, x, 0.0f, 0.3f, 2.0f));
    fovsdf__mat(b, 2);
    x = fovsdf_repeat(b, fovsdf__at(b, fovsdf_sphere(b, 0.35f), 0.0f, 1.25f, 0.0f), 0.0f, 0.0f,
                      5.0f, 0, 0, 2);
    x = fovsdf_union(b, x,
                     fovsdf_repeat(b,
                                   fovsdf__at(b, fovsdf_box(b, 0.25f, 0.45f, 0.25f), 0.0f, 0.45f,
                                              0.0f), 0.0f, 0.0f, 5.0f, 0, 0, 2));
    r = fovsdf_union(b, r, fovsdf_mirror(b, fovsdf__at(b, x, 2.2f, 0.0f, 0.0f), 1));
    fovsdf_scene_init(&o->scene);
    o->scene.num_lights = 0;
    fovsdf__light(&o->scene, FOVSDF_LIGHT_DIRECTIONAL, 0.35f, 0.9f, 0.25f, 1.1f, 1.0f, 0.85f, 0.0f,
                  16.0f);
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, 0.0f, 2.5f, -8.0f, 1.5f, 1.2f, 0.8f, 4.0f, 16.0f);
    fovsdf__light(&o->scene, FOVSDF_LIGHT_POINT, 0.0f, 2.5f, 9.0f, 0.8f, 1.0f, 1.5f, 4.0f, 16.0f);
    o->scene.ambient[0] = o->scene.ambient[1] = o->scene.ambient[2] = 0.12f;
    fovsdf__view(o, -1.0f, 1.7f, -13.0f, 0.5f, 3.2f, 8.0f, 65.0f, 80.0f);
    return r;
}

/* Thin features: wires, small spheres and a plate with small holes. */
FOVSDF__PRIV int32_t fovsdf__scene_thin(fovsdf_builder *b, fovsdf_builtin *o)
{
    int32_t r, x, y;
    float a[3], c[3];
    fovsdf__mat(b, 1);
    r = fovsdf_plane(b, 0.0f, 1.0f, 0.0f, 0.0f);
    fovsdf__mat(b, 3); /* a fence of thin vertical wires */
    a[0] = 0.0f; a[1] = 0.0f; a[2] = 0.0f; c[0] = 0.0f; c[1] = 1.2f; c[2] = 0.0f;
    x = fovsdf_repeat(b, fovsdf_capsule(b, a, c, 0.008f), 0.12f, 0.0f, 0.0f, 12, 0, 0);
    r = fovsdf_union(b, r, fovsdf__at(b, x, -0.4f, 0.0f, 0.6f));
    fovsdf__mat(b, 6); /* horizontal wires strung between two poles */
    a[0] = -2.5f; a[1] = 0.0f; a[2] = 0.0f; c[0] = 2.5f; c[1] = 0.0f; c[2] = 0.0f;
    x = fovsdf_repeat(b, fovsdf_capsule(b, a, c, 0.005f), 0.0f, 0.15f, 0.0f, 0, 3, 0);
    r = fovsdf_union(b, r, fovsdf__at(b, x, 0.0f, 1.5f, 1.4f));
    fovsdf__mat(b, 0);
    x = fovsdf_mirror(b, fovsdf__at(b, fovsdf_cylinder(b, 1.0f, 0.04f), 2.5f, 1.0f, 1.4f), 1);
    r = fovsdf_union(b, r, x);
    fovsdf__mat(b, 2); /* a grid of small spheres */
    x = fovsdf_repeat(b, fovsdf_sphere(b, 0.018f), 0.1f, 0.1f, 0.0f, 7, 4, 0);
    r = fovsdf_union(b, r, fovsdf__at(b, x, -1.7f, 0.6f, 0.0f));
    fovsdf__mat(b, 7); /* a plate with a grid of holes (subtraction) */
    x = fovsdf_box(b, 0.6f, 0.5f, 0.02f);
    y = fovsdf_repeat(b, fovsdf_rotate(b, fovsdf_cylinder(b, 0.1f, 0.03f), 1.0f, 0.0f, 0.0f, 90.0f),
                      0.1f, 0.1f, 0.0f, 5, 4, 0);
    r = fovsdf_union(b, r, fovsdf__at(b, fovsdf_subtract(b, x, y), 1.6f, 0.6f, 0.0f));
    fovsdf__mat(b, 4); /* thin box frames */
    x = fovsdf_repeat(b, fovsdf_box_frame(b, 0.15f, 0.15f, 0.15f, 0.006f), 0.4f, 0.0f, 0.0f, 2, 0,
                      0);
    r = fovsdf_union(b, r, fovsdf__at(b, x, 0.0f, 0.16f, -0.6f));
    fovsdf_scene_init(&o->scene);
    o->scene.num_lights = 0;
    fovsdf__light(&o->scene, FOVSDF_LIGHT_DIRECTIONAL, -0.4f, 0.8f, -0.5f, 1.0f, 1.0f, 0.95f, 0.0f,
                  24.0f);
    o->scene.ambient[0] = o->scene.ambient[1] = o->scene.ambient[2] = 0.2f;
    fovsdf__view(o, 0.2f, 1.1f, -3.2f, 0.0f, 0.7f, 0.6f, 55.0f, 40.0f);
    return r;
}

/* Fractals: a Menger sponge and a Mandelbulb (distance estimators, not exact SDFs). */
FOVSDF__PRIV int32_t fovsdf__scene_fractals(fovsdf_builder *b, fovsdf_builtin *o)
{
    int32_t r;
    fovsdf__mat(b, 1);
    r = fovsdf_plane(b, 0.0f, 1.0f, 0.0f, 0.0f);
    fovsdf__mat(b, 3);
    r = fovsdf_union(b, r,
                     fovsdf__at(b,
                                fovsdf_rotate(b, fovsdf_menger(b, 1.0f, 4), 0.0f, 1.0f, 0.0f,
                                              25.0f), -1.7f, 1.0f, 0.3f));
    fovsdf__mat(b, 4);
    r = fovsdf_union(b, r,
                     fovsdf__at(b,
                                fovsdf_rotate(b, fovsdf_mandelbulb(b, 8.0f, 8), 1.0f, 0.0f, 0.0f,
                                              -90.0f), 1.5f, 1.15f, 0.0f));
    fovsdf_scene_init(&o->scene);
    o->scene.num_lights = 0;
    fovsdf__light(&o->scene, FOVSDF_LIGHT_DIRECTIONAL, -0.5f, 0.7f, -0.6f, 1.0f, 0.95f, 0.9f, 0.0f,
                  16.0f);
    o->scene.ambient[0] = 0.2f; o->scene.ambient[1] = 0.2f; o->scene.ambient[2] = 0.24f;
    fovsdf__view(o, 0.0f, 1.9f, -5.0f, 0.0f, 1.0f, 0.0f, 50.0f, 40.0f);
    return r;
}

FOVSDF_API const char *fovsdf_builtin_name(uint32_t id)
{
    static const char *const names[] =
        { "primitives", "columns", "temple", "atrium", "thin", "fractals" };
    return id < (uint32_t)_FOVSDF_SCENE_NUM ? names[id] : "unknown";
}

FOVSDF_API fov_result fovsdf_builtin_size(uint32_t id, size_t *bytes)
{
    size_t prog;
    fovsdf_node dummy;
    fov_result r;
    if (!bytes) return FOV_ERR_NULL;
    if (id >= (uint32_t)_FOVSDF_SCENE_NUM) return FOV_ERR_INVALID_ARG;
    FOV_MEMSET(&dummy, 0, sizeof dummy);
    r = fovsdf_program_size(&dummy, fovsdf__scene_nodes[id], 0, &prog);
    if (r != FOV_OK) return r;
    *bytes = 16u + fov__align(sizeof(fovsdf_program)) +
        fov__align(sizeof(fovsdf_node) * fovsdf__scene_nodes[id]) + prog;
    return FOV_OK;
}

FOVSDF_API fov_result fovsdf_builtin_init(uint32_t id, fovsdf_builtin *o, void *mem, size_t bytes)
{
    size_t need;
    unsigned char *base;
    fovsdf_program *prog;
    fovsdf_node *nodes;
    fovsdf_builder b;
    int32_t root;
    fov_result r;
    if (!o || !mem) return FOV_ERR_NULL;
    r = fovsdf_builtin_size(id, &need);
    if (r != FOV_OK) return r;
    if (bytes < need) return FOV_ERR_TOO_SMALL;
    base = (unsigned char *)mem;
    base += (16u - ((uintptr_t)base & 15u)) & 15u;
    prog = (fovsdf_program *)(void *)base;
    nodes = (fovsdf_node *)(void *)(base + fov__align(sizeof(fovsdf_program)));
    FOV_MEMSET(o, 0, sizeof *o);
    fovsdf_builder_init(&b, nodes, fovsdf__scene_nodes[id]);
    switch (id) {
    case FOVSDF_SCENE_PRIMITIVES: root = fovsdf__scene_primitives(&b, o); break;
    case FOVSDF_SCENE_COLUMNS: root = fovsdf__scene_columns(&b, o); break;
    case FOVSDF_SCENE_TEMPLE: root = fovsdf__scene_temple(&b, o); break;
    case FOVSDF_SCENE_ATRIUM: root = fovsdf__scene_atrium(&b, o); break;
    case FOVSDF_SCENE_THIN: root = fovsdf__scene_thin(&b, o); break;
    default: root = fovsdf__scene_fractals(&b, o); break;
    }
    if (b.err != FOV_OK) return b.err;
    if (root < 0) return FOV_ERR_INVALID_ARG;
    r = fovsdf_program_build(prog, nodes, b.count, root,
                             base + fov__align(sizeof(fovsdf_program)) +
                             fov__align(sizeof(fovsdf_node) * fovsdf__scene_nodes[id]),
                             bytes - (size_t)(base - (unsigned char *)mem) -
                             fov__align(sizeof(fovsdf_program)) -
                                 fov__align(sizeof(fovsdf_node) * fovsdf__scene_nodes[id]));
    if (r != FOV_OK) return r;
    fovsdf_scene_set_program(&o->scene, prog);
    o->program = prog;
    o->name = fovsdf_builtin_name(id);
    return FOV_OK;
}

#ifdef FOVSDF_DOUBLE
/* Double-precision classic sphere tracing of a double distance callback (the reference for
   the numerical-stability tests). */
FOVSDF_API fov_result fovsdf_trace_ref(const fovsdf_scene *scene, const double ro[3],
                                       const double rd[3], double t_start, double t_max, double eps,
                                       uint32_t max_steps, double *t_hit, uint32_t *kind)
{
    double t = t_start;
    uint32_t i;
    if (!scene || !ro || !rd || !t_hit || !kind) return FOV_ERR_NULL;
    if (!scene->dist_d) return FOV_ERR_UNSUPPORTED;
    if (max_steps == 0 || !(eps > 0.0) || !(t_max > 0.0) || !(t_start >= 0.0))
        return FOV_ERR_INVALID_ARG;
    *kind = FOVSDF_EXHAUSTED;
    for (i = 0; i < max_steps; ++i) {
        double p[3], d;
        if (t > t_max) { *kind = FOVSDF_MISS; t = t_max; break; }
        p[0] = ro[0] + rd[0] * t; p[1] = ro[1] + rd[1] * t; p[2] = ro[2] + rd[2] * t;
        d = scene->dist_d(p, scene->user);
        if (!(d >= -DBL_MAX && d <= DBL_MAX)) { *kind = FOVSDF_MISS; t = t_max; break; }
        if (d < eps) { *kind = FOVSDF_HIT; break; }
        t += d;
    }
    *t_hit = t;
    return FOV_OK;
}
#endif

#endif /* FOVSDF_IMPLEMENTATION */

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
