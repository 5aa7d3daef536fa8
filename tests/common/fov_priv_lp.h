/* fov_priv_lp.h - the test hook of fovlp.h: external wrappers (fovtest_lp_*) for exactly the
   private functions that the unit tests call, so those tests can be built with
   -DFOV_TEST_LINK_IMPL and linked with the implementation compiled once per build flavour
   (tests/common/fov_impl_lp.c, tests/run_all.sh) instead of compiling it themselves.

   Include it after fovlp.h. The declarations are always there; the definitions are compiled
   where the translation unit holds fovlp.h's implementation (FOVLP_IMPL_INCLUDED): in
   tests/common/fov_impl_lp.c (so the per-flavour archives export them), or in a test program
   compiled standalone with the implementation. Each wrapper calls the private function
   itself, so the compiler checks it against the real signature. Only public types appear
   here. The shared block's privates (fov__*) are wrapped in fov_priv_sdf.h. Test code only:
   nothing here is part of fovlp.h's API. */
#ifndef FOV_PRIV_LP_H
#define FOV_PRIV_LP_H

#ifndef FOVLP_H_INCLUDED
#error "fov_priv_lp.h: include fovlp.h first"
#endif

#ifdef __cplusplus
extern "C" {
#endif
/* fovlp__to_lp_fast: the reconstruction's screen -> log-polar mapping (polynomial atan) */
void fovtest_lp_to_lp_fast(const fovlp_ctx *ctx, float dx, float dy, float r2, float *u,
                           float *v);
#ifdef __cplusplus
}
#endif
#endif /* FOV_PRIV_LP_H */

#if defined(FOVLP_IMPL_INCLUDED) && !defined(FOV_PRIV_LP_IMPL)
#define FOV_PRIV_LP_IMPL
#ifdef __cplusplus
extern "C" {
#endif
void fovtest_lp_to_lp_fast(const fovlp_ctx *ctx, float dx, float dy, float r2, float *u,
                           float *v)
{
    fovlp__to_lp_fast(ctx, dx, dy, r2, u, v);
}
#ifdef __cplusplus
}
#endif
#endif /* FOVLP_IMPL_INCLUDED */
