/* fuzz_common.h - shared helpers of the fov fuzz harnesses (tests/fuzz/fuzz_*.c).

   A harness defines   int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
   and reads its input through an fz_in cursor: every reader returns a value for any input
   (zero bytes past the end), so each byte string is a valid test case. A broken contract
   (an FOV_OK call whose outputs are not finite or outside the documented range, a canary
   overwritten, a BVH that disagrees with brute force) calls FZ_FAIL, which prints the
   reason and aborts: libFuzzer records the input, tests/fuzz/replay.c counts a failure.

   Built two ways (see tests/fuzz/run.sh): with clang -fsanitize=fuzzer,address,undefined
   for `make fuzz`, and with tests/fuzz/replay.c (any C compiler, no libFuzzer) to replay the
   committed corpus and regression inputs in `make test`. Everything here is static. */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FZ_FAIL(...)                                                        \
    do {                                                                    \
        fprintf(stderr, "FUZZ CONTRACT %s:%d: ", __FILE__, __LINE__);       \
        fprintf(stderr, __VA_ARGS__);                                       \
        fprintf(stderr, "\n");                                              \
        abort();                                                            \
    } while (0)
#define FZ_CHECK(cond, ...) do { if (!(cond)) FZ_FAIL(__VA_ARGS__); } while (0)

typedef struct fz_in {
    const uint8_t *p;
    size_t n, i;
} fz_in;

static fz_in fz_begin(const uint8_t *data, size_t size)
{
    fz_in in;
    in.p = data; in.n = size; in.i = 0;
    return in;
}
static size_t fz_left(const fz_in *in) { return in->i < in->n ? in->n - in->i : 0; }
static uint8_t fz_u8(fz_in *in) { return in->i < in->n ? in->p[in->i++] : (uint8_t)0; }
static uint16_t fz_u16(fz_in *in)
{
    uint16_t a = fz_u8(in);
    return (uint16_t)(a | (uint16_t)(fz_u8(in) << 8));
}
static uint32_t fz_u32(fz_in *in)
{
    uint32_t a = fz_u16(in);
    return a | ((uint32_t)fz_u16(in) << 16);
}
/* an integer in [lo, hi] (hi >= lo) */
static uint32_t fz_range_u32(fz_in *in, uint32_t lo, uint32_t hi)
{
    uint32_t span = hi - lo;
    if (span == 0xffffffffu) return fz_u32(in);
    return lo + fz_u32(in) % (span + 1u);
}
/* a choice among n (n >= 1) from one byte */
static uint32_t fz_pick(fz_in *in, uint32_t n) { return n ? (uint32_t)fz_u8(in) % n : 0u; }
/* any float bit pattern: NaN, inf, denormals, -0 included */
static float fz_raw_float(fz_in *in)
{
    uint32_t u = fz_u32(in);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}
/* a float in [lo, hi] from 16 bits */
static float fz_unit_range(fz_in *in, float lo, float hi)
{
    float u = (float)fz_u16(in) / 65535.0f;
    return lo + (hi - lo) * u;
}
/* mostly sensible, sometimes hostile: one selector byte chooses a value in [lo, hi]
   (3 in 4), a raw bit pattern (1 in 8), or an edge value (0, -0, +-FLT_MAX, +-inf, NaN,
   FLT_MIN, 1e-30, 1e30) */
static float fz_float(fz_in *in, float lo, float hi)
{
    uint8_t s = fz_u8(in);
    static const float edge[] = { 0.0f, -0.0f, FLT_MAX, -FLT_MAX, FLT_MIN, 1e-30f, 1e30f, -1e30f };
    if (s < 192) return fz_unit_range(in, lo, hi);
    if (s < 224) return fz_raw_float(in);
    if (s < 248) return edge[(s - 224) % 8];
    {
        volatile float z = 0.0f;
        return (s & 1) ? 1.0f / z : z / z; /* inf or NaN */
    }
}

static int fz_finite(float x) { return x >= -FLT_MAX && x <= FLT_MAX; }
static int fz_finite_n(const float *v, size_t n)
{
    size_t k;
    for (k = 0; k < n; ++k) if (!fz_finite(v[k])) return 0;
    return 1;
}

/* canaries: a buffer of n payload bytes followed by FZ_CANARY guard bytes */
#define FZ_CANARY 64
static void fz_canary_set(void *buf, size_t payload)
{
    memset((uint8_t *)buf + payload, 0xA5, FZ_CANARY);
}
static int fz_canary_ok(const void *buf, size_t payload)
{
    const uint8_t *g = (const uint8_t *)buf + payload;
    size_t k;
    for (k = 0; k < FZ_CANARY; ++k) if (g[k] != 0xA5) return 0;
    return 1;
}
/* malloc with room for the canary; the payload is filled with fill */
static void *fz_alloc(size_t payload, int fill)
{
    void *b = malloc(payload + FZ_CANARY);
    if (!b) { fprintf(stderr, "fuzz: out of memory\n"); abort(); }
    memset(b, fill, payload);
    fz_canary_set(b, payload);
    return b;
}
#endif
