/* The user's hook functions of hooks_stub.c (defined in hooks_stub_fns.c) and the render
   entry point main() calls; C linkage. */
#ifndef HOOKS_STUB_H
#define HOOKS_STUB_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif
float hook_sqrtf(float x);
float hook_floorf(float x);
float hook_sinf(float x);
float hook_cosf(float x);
float hook_tanf(float x);
float hook_atan2f(float y, float x);
float hook_expf(float x);
float hook_logf(float x);
float hook_powf(float x, float y);
void *hook_memset(void *p, int v, size_t n);
void *hook_memcpy(void *d, const void *s, size_t n);
void hook_assert(int ok, const char *what, int line);
int hooks_stub_render(void);
#ifdef __cplusplus
}
#endif
#endif
