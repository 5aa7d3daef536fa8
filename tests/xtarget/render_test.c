/* render_test.c - the cross-target render test of fovsdf.h (tests/xtarget/run.sh).

   Renders two built-in scenes (FOVSDF_SCENE_PRIMITIVES and FOVSDF_SCENE_THIN) at XT_W x XT_H,
   1 sample per pixel, classic sphere tracing with fovsdf_config_default(), through the
   public API only, and writes for each scene the sRGB 8-bit image, the hit mask, the depth
   (float bits in hex, so no printf or double is involved) and the evaluation counts to
   stdout as text. tests/xtarget/compare.c compares the dumps of two targets.

   All memory is static (no malloc): the scene memory is XT_SCENE_MEM bytes and the program
   checks fovsdf_builtin_size() against it. Output goes through xt_out():
     default          stdio (hosted and wasm32-wasi)
     XT_SEMIHOSTING   xt_write() from m4_startup.c (ARM semihosting, QEMU mps2-an386)
   XT_EXTERNAL_IMPL   do not compile the implementation here (link it from another file).
   XT_FOVLP           also render fovlp.h's scenes (lp_render_test.h; run.sh sets it when
                      fovlp.h exists).
   Under XT_SEMIHOSTING, FOV_ASSERT reports through xt_assert_fail() (m4_startup.c).

   Dump format (one item per line):
     fovxt 1 <width> <height>
     scene <id> <name>
     memory scene <fovsdf_builtin_size bytes> of <static buffer bytes>
     status <fov_result of the first failing call, 0 if none> <step that failed or "ok">
     stats evals <n> primary <n> rays <n> hits <n> exhausted <n>
     rgb      then <height> lines of width*3 bytes as hex
     hit      then <height> lines of width characters 0/1
     depth    then <height> lines of width 8-digit hex words (IEEE-754 bits of the float)
     end
     (next scene)
     done <exit status> */

#ifndef XT_EXTERNAL_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
#if defined(XT_SEMIHOSTING) && !defined(FOV_ASSERT)
/* bare metal: the library's internal assertions stay on and report through semihosting */
void xt_assert_fail(const char *expr, int line);
#define FOV_ASSERT(c) ((c) ? (void)0 : xt_assert_fail(#c, __LINE__))
#endif
#include "fovsdf.h"

#ifndef XT_W
#define XT_W 96
#endif
#ifndef XT_H
#define XT_H 54
#endif
#ifndef XT_SCENE_MEM
#define XT_SCENE_MEM (512u * 1024u)
#endif
#ifndef XT_CTX_MEM
#define XT_CTX_MEM (64u * 1024u)
#endif

#include "xt_out.h"

/* ---- static memory ---- */
static uint64_t xt_scene_mem[XT_SCENE_MEM / 8u];   /* uint64_t: 8-byte aligned */
static uint64_t xt_ctx_mem[XT_CTX_MEM / 8u];
static uint8_t xt_rgb[XT_W * XT_H * 3];
static uint8_t xt_hit[XT_W * XT_H];
static float xt_depth[XT_W * XT_H];

/* Renders one built-in scene and dumps it. Returns 0 or a fov_result. */
static int xt_scene(uint32_t id)
{
    fovsdf_builtin b;
    fovsdf_config cfg;
    fovsdf_ctx ctx;
    fovsdf_output out;
    fovsdf_stats st;
    fov_gaze gaze;
    size_t bytes = 0, ctx_bytes = 0;
    fov_result r = FOV_OK;
    const char *step = "ok";
    uint32_t y;

    for (y = 0; y < XT_W * XT_H; y++) { xt_hit[y] = 0; xt_depth[y] = 0.0f; }
    for (y = 0; y < XT_W * XT_H * 3; y++) xt_rgb[y] = 0;
    {
        static fovsdf_stats zero_stats; /* zero: static storage */
        st = zero_stats;
    }

    xt_puts("scene "); xt_putu(id); xt_putc(' '); xt_puts(fovsdf_builtin_name(id)); xt_endl();

    r = fovsdf_builtin_size(id, &bytes);
    if (r != FOV_OK) { step = "builtin_size"; goto done; }
    if (bytes > sizeof xt_scene_mem) {
        xt_puts("error scene memory: need "); xt_putu((uint64_t)bytes); xt_puts(", have ");
        xt_putu((uint64_t)sizeof xt_scene_mem); xt_endl();
        r = FOV_ERR_TOO_SMALL; step = "scene_memory"; goto done;
    }
    xt_puts("memory scene "); xt_putu((uint64_t)bytes); xt_puts(" of ");
    xt_putu((uint64_t)sizeof xt_scene_mem); xt_endl();
    r = fovsdf_builtin_init(id, &b, xt_scene_mem, sizeof xt_scene_mem);
    if (r != FOV_OK) { step = "builtin_init"; goto done; }

    b.camera.width = XT_W;
    b.camera.height = XT_H;
    cfg = fovsdf_config_default();
    gaze.x = 0.5f * (float)XT_W;
    gaze.y = 0.5f * (float)XT_H;

    r = fovsdf_memory_size(&cfg, &b.camera, &ctx_bytes);
    if (r != FOV_OK) { step = "memory_size"; goto done; }
    if (ctx_bytes > sizeof xt_ctx_mem) {
        xt_puts("error context memory: need "); xt_putu((uint64_t)ctx_bytes); xt_endl();
        r = FOV_ERR_TOO_SMALL; step = "ctx_memory"; goto done;
    }
    r = fovsdf_init(&ctx, &cfg, &b.scene, &b.camera, gaze,
                    ctx_bytes > 0 ? (void *)xt_ctx_mem : NULL, ctx_bytes);
    if (r != FOV_OK) { step = "init"; goto done; }

    fovsdf_output_init(&out);
    out.rgb8 = xt_rgb;
    out.hit = xt_hit;
    out.depth = xt_depth;
    r = fovsdf_render_rows(&ctx, 0, XT_H, &out, &st);
    if (r != FOV_OK) { step = "render_rows"; goto done; }

done:
    xt_puts("status "); xt_puti((int32_t)r); xt_putc(' '); xt_puts(step); xt_endl();
    xt_puts("stats evals "); xt_putu(st.evals);
    xt_puts(" primary "); xt_putu(st.evals_primary);
    xt_puts(" rays "); xt_putu(st.rays);
    xt_puts(" hits "); xt_putu(st.hits);
    xt_puts(" exhausted "); xt_putu(st.exhausted);
    xt_endl();
    xt_dump_image(xt_rgb, xt_hit, xt_depth, XT_W, XT_H);
    xt_puts("end"); xt_endl();
    return (int)r;
}

#ifdef XT_FOVLP
#include "lp_render_test.h" /* fovlp.h: scenes 20-22 in the same dump format */
#endif

int main(void)
{
    int status = 0;
    xt_puts("fovxt 1 "); xt_putu(XT_W); xt_putc(' '); xt_putu(XT_H); xt_endl();
    if (xt_scene(FOVSDF_SCENE_PRIMITIVES) != 0) status = 1;
    if (xt_scene(FOVSDF_SCENE_THIN) != 0) status = 1;
#ifdef XT_FOVLP
    if (xt_lp_scenes() != 0) status = 1;
#endif
    xt_puts("done "); xt_puti(status); xt_endl();
#ifndef XT_SEMIHOSTING
    (void)fflush(stdout);
#endif
    return status;
}
