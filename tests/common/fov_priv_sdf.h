/* fov_priv_sdf.h - the test hook of fovsdf.h: external wrappers (fovtest_*) for exactly the
   private functions and macros that the unit tests call, so those tests can be built with
   -DFOV_TEST_LINK_IMPL and linked with the implementation compiled once per build flavour
   (tests/common/fov_impl_sdf.c, tests/run_all.sh) instead of compiling it themselves.

   Include it after fovsdf.h. The declarations are always there; the definitions are compiled
   where the translation unit holds fovsdf.h's implementation (FOVSDF_IMPL_INCLUDED): in
   tests/common/fov_impl_sdf.c (so the per-flavour archives export them), or in a test program
   compiled standalone with the implementation. Each wrapper calls the private function
   itself, so the compiler checks the wrapper against its real signature, and a wrapper gives
   the same value as the private function called inline (the same code, compiled with the
   same flags: -ffp-contract=off, the flavour's -O level and defines).

   The shared block's privates (fov__*: the FOV_NO_LIBM math, FOV__SQRT / FOV__FLOOR,
   fov__absf, fov__len, fov__camera_init) are byte-identical in the three headers; they are
   wrapped from fovsdf.h's translation unit only, so the archive holds each symbol once.
   Only public types appear here (fovsdf_ctx, fov_camera); a private that takes a private type
   (fovsdf__marcher...) gets no wrapper and its test stays non-link. Test code only: nothing
   here is part of fovsdf.h's API. */
#ifndef FOV_PRIV_SDF_H
#define FOV_PRIV_SDF_H

#ifndef FOVSDF_H_INCLUDED
#error "fov_priv_sdf.h: include fovsdf.h first"
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* the shared block (fov__*) */
float fovtest_sqrt(float x);  /* FOV__SQRT: libm's sqrtf, the math hook, or fov__sqrtf */
float fovtest_floor(float x); /* FOV__FLOOR: floorf, the hook, or fov__floorf */
float fovtest_absf(float a);
float fovtest_len(const float a[3]);
void fovtest_camera_init(fov_camera *cam, uint32_t width, uint32_t height);
/* FOV__SQRT_HW: the FOV_NO_LIBM square root instruction (1 SSE, 2 AArch64, 3 Arm VFP,
   4 wasm), 0 when the build has none (or uses libm or the math hooks) */
int fovtest_sqrt_hw(void);
#if defined(FOV_NO_LIBM) && !defined(FOV_SQRTF)
/* FOV_NO_LIBM's own approximations (without math hooks, which are all-or-none) */
float fovtest_sqrtf(float x);
float fovtest_floorf(float x);
float fovtest_sinf(float x);
float fovtest_cosf(float x);
float fovtest_atan2f(float y, float x);
float fovtest_expf(float x);
float fovtest_logf(float x);
float fovtest_powf(float x, float y);
#endif

/* fovsdf__*: the float kernels of the built-in programs, the lane floor, the primary ray,
   the shadow cut-off and the sample offsets */
float fovtest_sdf_ksin(float x);
float fovtest_sdf_kcos(float x);
void fovtest_sdf_ksincos_w(float x, float *s, float *c);
float fovtest_sdf_ksin1(float x);
float fovtest_sdf_katan2(float y, float x);
float fovtest_sdf_klog(float x);
float fovtest_sdf_kpow(float x, float y);
float fovtest_sdf_vfloor(float x);
int fovtest_sdf_ray(const fovsdf_ctx *c, float px, float py, float ro[3], float rd[3]);
int fovtest_sdf_shadow_far(const fovsdf_ctx *c, const float rd[3]);
void fovtest_sdf_sample_offset(uint32_t spp, uint32_t s, float *ox, float *oy);

#ifdef __cplusplus
}
#endif
#endif /* FOV_PRIV_SDF_H */

#if defined(FOVSDF_IMPL_INCLUDED) && !defined(FOV_PRIV_SDF_IMPL)
#define FOV_PRIV_SDF_IMPL
#ifdef __cplusplus
extern "C" {
#endif
float fovtest_sqrt(float x) { return FOV__SQRT(x); }
float fovtest_floor(float x) { return FOV__FLOOR(x); }
float fovtest_absf(float a) { return fov__absf(a); }
float fovtest_len(const float a[3]) { return fov__len(a); }
void fovtest_camera_init(fov_camera *cam, uint32_t width, uint32_t height)
{
    fov__camera_init(cam, width, height);
}
int fovtest_sqrt_hw(void)
{
#ifdef FOV__SQRT_HW
    return FOV__SQRT_HW;
#else
    return 0;
#endif
}
#if defined(FOV_NO_LIBM) && !defined(FOV__HOOKED_MATH)
float fovtest_sqrtf(float x) { return fov__sqrtf(x); }
float fovtest_floorf(float x) { return fov__floorf(x); }
float fovtest_sinf(float x) { return fov__sinf(x); }
float fovtest_cosf(float x) { return fov__cosf(x); }
float fovtest_atan2f(float y, float x) { return fov__atan2f(y, x); }
float fovtest_expf(float x) { return fov__expf(x); }
float fovtest_logf(float x) { return fov__logf(x); }
float fovtest_powf(float x, float y) { return fov__powf(x, y); }
#endif

float fovtest_sdf_ksin(float x) { return fovsdf__ksin(x); }
float fovtest_sdf_kcos(float x) { return fovsdf__kcos(x); }
void fovtest_sdf_ksincos_w(float x, float *s, float *c) { fovsdf__ksincos_w(x, s, c); }
float fovtest_sdf_ksin1(float x) { return fovsdf__ksin1(x); }
float fovtest_sdf_katan2(float y, float x) { return fovsdf__katan2(y, x); }
float fovtest_sdf_klog(float x) { return fovsdf__klog(x); }
float fovtest_sdf_kpow(float x, float y) { return fovsdf__kpow(x, y); }
float fovtest_sdf_vfloor(float x) { return fovsdf__vfloor(x); }
int fovtest_sdf_ray(const fovsdf_ctx *c, float px, float py, float ro[3], float rd[3])
{
    return fovsdf__ray(c, px, py, ro, rd);
}
int fovtest_sdf_shadow_far(const fovsdf_ctx *c, const float rd[3])
{
    return fovsdf__shadow_far(c, rd);
}
void fovtest_sdf_sample_offset(uint32_t spp, uint32_t s, float *ox, float *oy)
{
    fovsdf__sample_offset(spp, s, ox, oy);
}
#ifdef __cplusplus
}
#endif
#endif /* FOVSDF_IMPL_INCLUDED */
