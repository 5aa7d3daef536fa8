/* web_rt.h - the freestanding runtime of the browser demo's WebAssembly modules (web_sdf.c,
   web_lp.c, web_pt.c): what a wasm32 build without a libc needs besides the fov headers.
     memset / memcpy / memmove  the compiler may emit calls to them (the headers say so);
     a bump allocator           web_alloc / web_heap_reset over the module's linear memory,
                                grown with memory.grow; every setup call starts it afresh;
     WEB_EXPORT(name)           an explicit export (the link uses no --export-all).
   Built with clang --target=wasm32 -ffreestanding -nostdlib -Wl,--no-entry (examples/web/build.sh).
   Not part of the library. */
#ifndef WEB_RT_H
#define WEB_RT_H
#include <stddef.h>
#include <stdint.h>

#ifdef WEB_NATIVE
#define WEB_EXPORT(name)
#else
#define WEB_EXPORT(name) __attribute__((export_name(#name), visibility("default")))
#endif

#ifdef WEB_NATIVE
/* a native build of the same glue (examples/web/native_bench.c): libc's mem* functions and a
   fixed arena instead of the wasm linear memory */
#include <string.h>
#ifndef WEB_NATIVE_ARENA
#define WEB_NATIVE_ARENA (256u << 20)
#endif
static unsigned char *web__arena;
static size_t web__top;
void *malloc(size_t n);
static void web_heap_reset(void)
{
    if (!web__arena) web__arena = (unsigned char *)malloc(WEB_NATIVE_ARENA);
    web__top = 0;
}
static void *web_alloc(size_t n)
{
    size_t start;
    if (!web__arena) web_heap_reset();
    if (!web__arena) return NULL;
    start = (web__top + 15u) & ~(size_t)15u;
    if (n > WEB_NATIVE_ARENA - start) return NULL;
    web__top = start + n;
    memset(web__arena + start, 0, n);
    return web__arena + start;
}
#else
void *memset(void *d, int c, size_t n);
void *memcpy(void *d, const void *s, size_t n);
void *memmove(void *d, const void *s, size_t n);

/* volatile stores keep clang from turning the loops back into calls to themselves */
void *memset(void *d, int c, size_t n)
{
    volatile unsigned char *p = (volatile unsigned char *)d;
    while (n--) *p++ = (unsigned char)c;
    return d;
}
void *memcpy(void *d, const void *s, size_t n)
{
    volatile unsigned char *p = (volatile unsigned char *)d;
    const unsigned char *q = (const unsigned char *)s;
    while (n--) *p++ = *q++;
    return d;
}
void *memmove(void *d, const void *s, size_t n)
{
    volatile unsigned char *p = (volatile unsigned char *)d;
    const unsigned char *q = (const unsigned char *)s;
    if (p < q) { while (n--) *p++ = *q++; }
    else { p += n; q += n; while (n--) *--p = *--q; }
    return d;
}

extern unsigned char __heap_base;
static size_t web__top;

static void web_heap_reset(void) { web__top = (size_t)&__heap_base; }

/* n bytes aligned to 16 (zeroed: fresh pages are zero, reused ones are cleared), or NULL */
static void *web_alloc(size_t n)
{
    size_t start, end, have;
    if (web__top == 0) web_heap_reset();
    start = (web__top + 15u) & ~(size_t)15u;
    if (n > (size_t)0x7FFFFFFF - start) return NULL;
    end = start + n;
    have = __builtin_wasm_memory_size(0) * 65536u;
    if (end > have) {
        size_t pages = (end - have + 65535u) / 65536u;
        if (__builtin_wasm_memory_grow(0, pages) == (size_t)-1) return NULL;
    }
    web__top = end;
    memset((void *)start, 0, n);
    return (void *)start;
}
#endif

/* a float counter area the JS reads after each call (WEB_STAT_*) */
static double web_stats[16];
WEB_EXPORT(stats_ptr) double *stats_ptr(void);
double *stats_ptr(void) { return web_stats; }

/* linear RGB byte lookups for the overlay tints */
static uint8_t web__mix(uint8_t a, uint8_t b) { return (uint8_t)(((unsigned)a + (unsigned)b) / 2u); }

/* rows [y0, y1) of a packed RGB8 image into RGBA8 (alpha 255); tint (may be NULL): per pixel
   0 = none, 1..3 = a colour mixed in (overlay) */
static void web_rgba_rows(const uint8_t *rgb, uint8_t *rgba, const uint8_t *tint, uint32_t w,
                          uint32_t y0, uint32_t y1)
{
    static const uint8_t col[4][3] = { { 0, 0, 0 }, { 255, 64, 64 }, { 64, 255, 64 }, { 64, 128, 255 } };
    size_t i, i0 = (size_t)y0 * w, i1 = (size_t)y1 * w;
    for (i = i0; i < i1; ++i) {
        uint8_t r = rgb[3 * i], g = rgb[3 * i + 1], b = rgb[3 * i + 2];
        uint32_t t = tint ? tint[i] : 0u;
        if (t > 0u && t < 4u) { r = web__mix(r, col[t][0]); g = web__mix(g, col[t][1]); b = web__mix(b, col[t][2]); }
        rgba[4 * i] = r; rgba[4 * i + 1] = g; rgba[4 * i + 2] = b; rgba[4 * i + 3] = 255;
    }
}

/* the camera orbits its target about +y by `angle` radians (FOV_NO_LIBM: small polynomials;
   exactness does not matter, every worker computes the same bits). The angle comes from JS:
   web_orbit returns 0, or -1 (and leaves out[] alone) when it is not finite. */
static float web__floor(float x)   /* no libm: exact for every float */
{
    float t;
    if (!(x > -8388608.0f && x < 8388608.0f)) return x;   /* |x| >= 2^23: an integer already */
    t = (float)(int32_t)x;
    return t > x ? t - 1.0f : t;
}
static float web__sin(float x)
{
    const float pi = 3.14159265f, two_pi = 6.28318531f;
    float x2;
    x -= two_pi * web__floor(x / two_pi + 0.5f);   /* one step into [-pi, pi] (about) */
    if (x > 0.5f * pi) x = pi - x;
    if (x < -0.5f * pi) x = -pi - x;
    if (x > 0.5f * pi) x = 0.5f * pi;               /* rounding at the ends, and |x| >= 2^25 */
    if (x < -0.5f * pi) x = -0.5f * pi;
    x2 = x * x;
    return x * (1.0f - x2 / 6.0f * (1.0f - x2 / 20.0f * (1.0f - x2 / 42.0f * (1.0f - x2 / 72.0f))));
}
static int web_orbit(const float base_pos[3], const float target[3], float angle, float out[3])
{
    const float pi = 3.14159265f, two_pi = 6.28318531f;
    float dx = base_pos[0] - target[0], dz = base_pos[2] - target[2], s, c, a;
    if (!(angle >= -3.4e38f && angle <= 3.4e38f)) return -1;
    /* into [-pi, pi] first, so that a + pi/2 differs from a also for a huge angle (whose
       reduction is meaningless when floats are wider apart than 2 pi: clamped then) */
    a = angle - two_pi * web__floor(angle / two_pi + 0.5f);
    a = a > pi ? pi : a < -pi ? -pi : a;
    s = web__sin(a); c = web__sin(a + 1.57079633f);
    out[0] = target[0] + c * dx + s * dz;
    out[1] = base_pos[1];
    out[2] = target[2] - s * dx + c * dz;
    return 0;
}
#endif
