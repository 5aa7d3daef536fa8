/* sdf_stereo.c - stereo with fovsdf: a head-mounted display's two eyes, each an off-axis
   frustum (tangents as OpenVR's GetProjectionRaw or OpenXR's XrFovf give them, the left eye
   seeing more to its left) moved by half the interpupillary distance, each with its own gaze
   (both eyes fixate one point, so the gazes differ), written side by side as one PPM.
   The fovea is grown by the latency margin of a gaze filter (GAZE INPUT); without an eye
   tracker use fovsdf_gaze_fixed and FOV_GAZE_FIXED_MARGIN_DEG instead.
   Build: cc -O2 examples/sdf_stereo.c -I. -lm -o sdf_stereo && ./sdf_stereo > stereo.ppm */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define EW 160 /* one eye's image */
#define EH 176

static float scene_sdf(const float p[3], void *user)
{
    float sphere = sqrtf(p[0] * p[0] + (p[1] - 1.0f) * (p[1] - 1.0f) + p[2] * p[2]) - 1.0f;
    float box = fmaxf(fabsf(p[0] - 1.8f), fmaxf(fabsf(p[1] - 0.5f), fabsf(p[2] - 1.0f))) - 0.5f;
    float ground = p[1];
    (void)user;
    return fminf(fminf(sphere, box), ground);
}

/* the pixel of eye camera c that sees world point q (the frustum's rays inverted) */
static fov_gaze gaze_of(const fovsdf_camera *c, const float q[3])
{
    float r[3], u[3], f[3], d[3], z;
    fov_gaze g = { 0.5f * EW, 0.5f * EH };
    int k;
    if (fovsdf_camera_basis(c, r, u, f) != FOV_OK) return g;
    for (k = 0; k < 3; ++k) d[k] = q[k] - (c->pos[k] + c->eye_offset * r[k]);
    z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    if (z <= 0.0f) return g;
    g.x = ((d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) / z + c->tan_left) /
          (c->tan_left + c->tan_right) * (float)EW;
    g.y = (c->tan_top - (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / z) /
          (c->tan_bottom + c->tan_top) * (float)EH;
    return g;
}

int main(int argc, char **argv)
{
    static uint8_t pixels[2 * EW * EH * 3];
    static const float fixate[3] = { 0.4f, 1.0f, 0.0f }; /* the point both eyes look at */
    fovsdf_scene scene;
    fovsdf_config base = fovsdf_config_default(), cfg;
    fov_gaze_filter gf;
    float margin = 0.0f;
    int eye;
    if (argc > 1) { /* no options: -h / --help prints the usage (exit 0), anything else exits 2 */
        int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
        fputs("usage: sdf_stereo > stereo.ppm\n  writes the two eyes side by side, a 320x176 PPM, "
              "to stdout; no options\n  -h, --help  this text\n", help ? stdout : stderr);
        return help ? 0 : 2;
    }
    fovsdf_scene_init(&scene);
    scene.dist = scene_sdf;
    /* a still eye seen by a 120 Hz tracker: the filter's margin for 50 ms of latency and a
       stated accuracy of 0.5 degrees (the raw samples would come from the tracker) */
    fovsdf_gaze_filter_init(&gf, NULL);
    {
        uint32_t i;
        for (i = 0; i < 60; ++i)
            fovsdf_gaze_filter_push(&gf, 8333u * i, 2.0f + 0.1f * (float)(i % 3), -1.0f);
    }
    fovsdf_gaze_margin(&gf, 0.5f, 50.0f, &margin);
    if (fovsdf_config_gaze_margin(&base, margin, &cfg) != FOV_OK) return 1;
    cfg.method = FOVSDF_METHOD_FIPR; /* the foveated tracer */
    for (eye = 0; eye < 2; ++eye) {
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        fovsdf_output out;
        fovsdf_stats st;
        fov_gaze g;
        fov_result r;
        fovsdf_camera_init(&cam, EW, EH);
        cam.pos[0] = 0.0f; cam.pos[1] = 1.6f; cam.pos[2] = -4.0f;
        cam.target[0] = 0.0f; cam.target[1] = 1.0f; cam.target[2] = 0.0f;
        cam.eye_offset = eye == 0 ? -0.032f : 0.032f;     /* ipd 64 mm in metres */
        cam.tan_left = eye == 0 ? 1.0f : 0.8f;             /* each eye sees more outwards */
        cam.tan_right = eye == 0 ? 0.8f : 1.0f;
        cam.tan_bottom = 0.99f; cam.tan_top = 0.99f;        /* 1.8 / 1.98 = 160 / 176 */
        g = gaze_of(&cam, fixate);
        r = fovsdf_init(&ctx, &cfg, &scene, &cam, g, NULL, 0);
        if (r != FOV_OK) {
            fprintf(stderr, "fovsdf_init: %s\n", fovsdf_result_string(r));
            return 1;
        }
        fovsdf_output_init(&out);
        out.rgb8 = pixels + (size_t)eye * EW * 3;          /* the left or right half */
        out.rgb8_stride = 2 * EW * 3;                      /* a row of the side-by-side image */
        fovsdf_stats_init(&st);
        r = fovsdf_render_rows(&ctx, 0, EH, &out, &st);
        if (r != FOV_OK) { fprintf(stderr, "render: %s\n", fovsdf_result_string(r)); return 1; }
        fprintf(stderr, "%s eye: gaze (%.1f, %.1f), fovea %.2f deg (margin %.2f), "
                "%.1f evaluations per pixel\n",
                eye ? "right" : "left", (double)g.x, (double)g.y, (double)cfg.acuity.fovea_deg,
                (double)margin, (double)st.evals / (EW * EH));
    }
    printf("P6\n%d %d\n255\n", 2 * EW, EH);
    fwrite(pixels, 1, sizeof pixels, stdout);
    return 0;
}
