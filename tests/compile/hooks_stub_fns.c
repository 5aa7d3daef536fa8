/* The user's hook functions for hooks_stub.c: count the calls, forward to the C library.
   main() renders through hooks_stub.c and checks that the math and memory hooks were used
   and that no assertion hook reported a failure. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hooks_stub.h"

static unsigned long math_calls, mem_calls, assert_calls, assert_failures;

float hook_sqrtf(float x) { math_calls++; return sqrtf(x); }
float hook_floorf(float x) { math_calls++; return floorf(x); }
float hook_sinf(float x) { math_calls++; return sinf(x); }
float hook_cosf(float x) { math_calls++; return cosf(x); }
float hook_tanf(float x) { math_calls++; return tanf(x); }
float hook_atan2f(float y, float x) { math_calls++; return atan2f(y, x); }
float hook_expf(float x) { math_calls++; return expf(x); }
float hook_logf(float x) { math_calls++; return logf(x); }
float hook_powf(float x, float y) { math_calls++; return powf(x, y); }
void *hook_memset(void *p, int v, size_t n) { mem_calls++; return memset(p, v, n); }
void *hook_memcpy(void *d, const void *s, size_t n) { mem_calls++; return memcpy(d, s, n); }
void hook_assert(int ok, const char *what, int line)
{
    assert_calls++;
    if (!ok) {
        assert_failures++;
        fprintf(stderr, "hooks_stub: FOV_ASSERT(%s) failed at line %d\n", what, line);
    }
}

int main(void)
{
    int r = hooks_stub_render();
    printf("hooks: math %lu, memory %lu, assert %lu (failed %lu)\n", math_calls, mem_calls,
           assert_calls, assert_failures);
    if (r != 0) return r;
    if (math_calls == 0) return 30;
    if (mem_calls == 0) return 31;
    if (assert_failures != 0) return 32;
    return 0;
}
