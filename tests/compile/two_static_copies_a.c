/* Compile test (stb#1429): two translation units each embed a private (FOVxx_STATIC) copy of
   every present header and expose one non-static wrapper; two_static_copies_main.c links
   both into one program. Any public symbol that escapes the STATIC switch (a function or a
   constant table) gives a duplicate-symbol link error; run.sh also checks with nm that no
   fovsdf_/fovlp_/fovpt_ symbol is global in the object. Unused static functions must not
   warn under -Wall -Werror (the unused attribute). two_static_copies_b.c is this file with
   TWO_STATIC_COPY set to two_static_copy_b. */
#ifndef TWO_STATIC_COPY
#define TWO_STATIC_COPY two_static_copy_a
#endif
#ifdef FOV_HAVE_FOVSDF
#define FOVSDF_STATIC
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "tiny_scene.h"
#endif
#ifdef FOV_HAVE_FOVLP
#define FOVLP_STATIC
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#endif
#ifdef FOV_HAVE_FOVPT
#define FOVPT_STATIC
#define FOVPT_IMPLEMENTATION
#include "fovpt.h"
#include "tiny_pt.h"
#endif

#ifdef __cplusplus
extern "C" {
#endif
int TWO_STATIC_COPY(unsigned char *rgb, unsigned long *evals);
#ifdef __cplusplus
}
#endif

/* renders the tiny scene with this copy; 0 on success */
int TWO_STATIC_COPY(unsigned char *rgb, unsigned long *evals)
{
    *evals = 0;
#ifdef FOV_HAVE_FOVSDF
    {
        uint64_t e = 0;
        int r = tiny_render(rgb, &e);
        *evals = (unsigned long)e;
        if (r != 0) return r;
    }
#endif
#ifdef FOV_HAVE_FOVPT
    {   /* the same 8x6 image size: both copies must agree on this one too */
        static uint8_t img[TINY_PT_W * TINY_PT_H * 3];
        uint64_t rays = 0;
        unsigned i;
        int r = tiny_pt_render(img, &rays);
        if (r != 0) return 100 + r;
        *evals += (unsigned long)rays;
        for (i = 0; i < sizeof img; i++) rgb[i] = (unsigned char)(rgb[i] ^ img[i]);
    }
#endif
    (void)rgb;
    return 0;
}
