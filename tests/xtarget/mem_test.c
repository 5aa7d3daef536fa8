/* mem_test.c - fixed-memory rendering on a microcontroller (tests/xtarget/run.sh).

   Renders FOVSDF_SCENE_PRIMITIVES at 160x128, 1 sample per pixel, the cone pyramid with full
   shading (soft shadows), band by band, and measures the working memory of the render:
     - the arena: everything the render reads or writes, bump-allocated from one static
       block: the compacted scene program (fovsdf_program_compact), the context, and the
       output buffers of one band (XT_BAND rows of sRGB bytes, hit mask and depth; the band
       buffers use fovsdf_output.origin_y, so they hold only their rows);
     - the stack: painted below the current stack pointer before rendering and scanned
       afterwards (the deepest word changed; on the Cortex-M4 only, XT_SEMIHOSTING).
   It prints "memory render arena <bytes> stack <bytes> total <bytes> limit <bytes>" and
   "memory build <bytes>": the scene is built once, at start-up, in a separate block that the
   render never touches (the test overwrites it before rendering; a device would reuse it,
   e.g. as the frame buffer). The image is streamed out in the dump format of render_test.c
   (rendered three times, once per section, since only one band is ever in memory) and
   compared with the same program built natively. */

#ifndef XT_EXTERNAL_IMPL
#define FOVSDF_IMPLEMENTATION
#endif
/* the least stack: 4 rays in flight (config.spp must not exceed it), programs evaluated point
   by point */
#ifndef FOVSDF_WAVE
#define FOVSDF_WAVE 4
#endif
#ifndef FOVSDF_BATCH
#define FOVSDF_BATCH 1
#endif
#if defined(XT_SEMIHOSTING) && !defined(FOV_ASSERT)
void xt_assert_fail(const char *expr, int line);
#define FOV_ASSERT(c) ((c) ? (void)0 : xt_assert_fail(#c, __LINE__))
#endif
#include "fovsdf.h"

#define XT_W 160
#define XT_H 128
#ifndef XT_BAND
#define XT_BAND 8       /* rows per band = cone_tile: no coarse work is repeated */
#endif
#ifndef XT_LIMIT
#define XT_LIMIT 32768u /* the budget for the render's working memory */
#endif
#define XT_ARENA 24576u
#define XT_STACK_PAINT 16384u

#define XT_NO_DUMP_IMAGE
#include "xt_out.h"

static uint64_t xt_build_mem[65536 / 8];  /* start-up only: the builtin's build memory */
static uint64_t xt_arena[XT_ARENA / 8];
static size_t xt_used;

static void *xt_alloc(size_t n)
{
    void *p;
    n = (n + 15u) & ~(size_t)15u;
    if (xt_used + n > sizeof xt_arena) return NULL;
    p = (unsigned char *)xt_arena + xt_used;
    xt_used += n;
    return p;
}

#ifdef XT_SEMIHOSTING
/* Paint XT_STACK_PAINT bytes below the caller's stack pointer, then find how deep the render
   wrote. noinline: the painting and scanning frames must not be part of the measured one. */
static uintptr_t xt_sp(void)
{
    uintptr_t sp;
    __asm volatile("mov %0, sp" : "=r"(sp));
    return sp;
}
static __attribute__((noinline)) void xt_paint(uintptr_t top)
{
    volatile uint32_t *p = (volatile uint32_t *)(top - XT_STACK_PAINT);
    while ((uintptr_t)p < top - 256u) *p++ = 0xdeadbeefu; /* spare this function's frame */
}
static uint32_t xt_scan(uintptr_t top)
{
    const volatile uint32_t *p = (const volatile uint32_t *)(top - XT_STACK_PAINT);
    while ((uintptr_t)p < top - 256u && *p == 0xdeadbeefu) ++p;
    return (uint32_t)(top - (uintptr_t)p);
}
#endif

typedef struct xt_state {
    fovsdf_ctx *ctx;
    uint8_t *rgb, *hit;
    float *depth;
} xt_state;

/* One pass over the frame, band by band; section 0: rgb, 1: hit, 2: depth (printed). */
static fov_result xt_pass(const xt_state *s, int section, fovsdf_stats *st)
{
    uint32_t y0, y;
    for (y0 = 0; y0 < XT_H; y0 += XT_BAND) {
        fovsdf_output o;
        uint32_t y1 = y0 + XT_BAND < XT_H ? y0 + XT_BAND : XT_H;
        fov_result r;
        fovsdf_output_init(&o);
        o.rgb8 = s->rgb; o.hit = s->hit; o.depth = s->depth;
        o.origin_y = y0;
        r = fovsdf_render_rows(s->ctx, y0, y1, &o, st);
        if (r != FOV_OK) return r;
        for (y = 0; y < y1 - y0; y++) {
            if (section == 0) xt_row_rgb(s->rgb + y * XT_W * 3, XT_W);
            else if (section == 1) xt_row_hit(s->hit + y * XT_W, XT_W);
            else xt_row_depth(s->depth + y * XT_W, XT_W);
        }
    }
    return FOV_OK;
}

int main(void)
{
    fovsdf_builtin b;
    fovsdf_config cfg;
    fovsdf_program *prog;
    fovsdf_stats st;
    fov_gaze gaze;
    xt_state s;
    size_t build = 0, i;
    fov_result r;
    const char *step = "ok";
    uint32_t stack = 0;
    static const char *const sections[3] = { "rgb", "hit", "depth" };
    int k;
    {
        static fovsdf_stats zero_stats;
        st = zero_stats;
    }
    xt_puts("fovxt 1 "); xt_putu(XT_W); xt_putc(' '); xt_putu(XT_H); xt_endl();
    xt_puts("scene 0 primitives"); xt_endl();

    /* start-up: build, then keep only the code */
    r = fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &build);
    if (r != FOV_OK || build > sizeof xt_build_mem) { step = "builtin_size"; goto fail; }
    xt_puts("memory scene "); xt_putu((uint64_t)build); xt_puts(" of "); xt_putu((uint64_t)sizeof xt_build_mem); xt_endl();
    r = fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &b, xt_build_mem, sizeof xt_build_mem);
    if (r != FOV_OK) { step = "builtin_init"; goto fail; }
    prog = (fovsdf_program *)xt_alloc(sizeof *prog);
    s.ctx = (fovsdf_ctx *)xt_alloc(sizeof *s.ctx);
    if (!prog || !s.ctx) { r = FOV_ERR_TOO_SMALL; step = "arena"; goto fail; }
    *prog = *b.program;
    {
        size_t n = fovsdf_program_code_bytes(prog);
        void *code = xt_alloc(n);
        if (!code) { r = FOV_ERR_TOO_SMALL; step = "arena_code"; goto fail; }
        r = fovsdf_program_compact(prog, code, n);
        if (r != FOV_OK) { step = "compact"; goto fail; }
    }
    fovsdf_scene_set_program(&b.scene, prog);
    for (i = 0; i < sizeof xt_build_mem / 8; i++) xt_build_mem[i] = ~(uint64_t)0; /* the build memory is gone */

    s.rgb = (uint8_t *)xt_alloc(XT_W * XT_BAND * 3);
    s.hit = (uint8_t *)xt_alloc(XT_W * XT_BAND);
    s.depth = (float *)xt_alloc(XT_W * XT_BAND * sizeof(float));
    if (!s.rgb || !s.hit || !s.depth) { r = FOV_ERR_TOO_SMALL; step = "arena_band"; goto fail; }

    b.camera.width = XT_W;
    b.camera.height = XT_H;
    cfg = fovsdf_config_default();
    cfg.method = FOVSDF_METHOD_CONE;
    cfg.cone_tile = XT_BAND;
    gaze.x = 0.5f * (float)XT_W;
    gaze.y = 0.5f * (float)XT_H;
    r = fovsdf_init(s.ctx, &cfg, &b.scene, &b.camera, gaze, NULL, 0);
    if (r != FOV_OK) { step = "init"; goto fail; }

    /* the measured render: the first pass (rgb); the two others repeat it for the dump */
    {
        fovsdf_stats none;
#ifdef XT_SEMIHOSTING
        uintptr_t top = xt_sp();
        xt_paint(top);
#endif
        xt_puts("status 0 ok"); xt_endl();
        for (k = 0; k < 3; k++) {
            none = st;
            xt_puts(sections[k]); xt_endl();
            r = xt_pass(&s, k, k == 0 ? &st : &none);
            if (r != FOV_OK) { step = "render"; break; }
#ifdef XT_SEMIHOSTING
            if (k == 0) stack = xt_scan(top);
#endif
        }
    }
    xt_puts("end"); xt_endl();
    xt_puts("stats evals "); xt_putu(st.evals); xt_puts(" primary "); xt_putu(st.evals_primary);
    xt_puts(" rays "); xt_putu(st.rays); xt_puts(" hits "); xt_putu(st.hits); xt_puts(" exhausted ");
    xt_putu(st.exhausted); xt_endl();
    xt_puts("memory render arena "); xt_putu((uint64_t)xt_used); xt_puts(" stack "); xt_putu(stack);
    xt_puts(" total "); xt_putu((uint64_t)xt_used + stack); xt_puts(" limit "); xt_putu(XT_LIMIT);
    xt_puts(" program "); xt_putu((uint64_t)fovsdf_program_code_bytes(prog)); xt_puts(" ctx ");
    xt_putu((uint64_t)sizeof(fovsdf_ctx)); xt_puts(" band "); xt_putu((uint64_t)(XT_W * XT_BAND * 8u)); xt_endl();
    xt_puts("memory build "); xt_putu((uint64_t)build); xt_endl();
    xt_puts("done "); xt_puti(r == FOV_OK ? 0 : 1); xt_endl();
#ifndef XT_SEMIHOSTING
    (void)fflush(stdout);
#endif
    return r == FOV_OK ? 0 : 1;
fail:
    xt_puts("status "); xt_puti((int32_t)r); xt_putc(' '); xt_puts(step); xt_endl();
    xt_puts("done 1"); xt_endl();
#ifndef XT_SEMIHOSTING
    (void)fflush(stdout);
#endif
    return 1;
}
