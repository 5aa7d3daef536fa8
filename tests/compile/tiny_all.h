/* tiny_render_all: renders the tiny scene of every header present (tiny_scene.h, tiny_pt.h,
   tiny_lp.h, included before this file); 0 on success, else the fovsdf error, 100 + the fovpt
   error or fovlp's. For all_three_one_tu.c and hooks_stub.c. */
#ifndef TINY_ALL_H
#define TINY_ALL_H
static int tiny_render_all(void)
{
#ifdef FOV_HAVE_FOVSDF
    {
        static uint8_t rgb[TINY_W * TINY_H * 3];
        uint64_t evals = 0;
        int e = tiny_render(rgb, &evals);
        if (e != 0) return e;
    }
#endif
#ifdef FOV_HAVE_FOVPT
    {
        static uint8_t rgb2[TINY_PT_W * TINY_PT_H * 3];
        uint64_t rays = 0;
        int e = tiny_pt_render(rgb2, &rays);
        if (e != 0) return 100 + e;
    }
#endif
#ifdef FOV_HAVE_FOVLP
    if (tiny_lp() != 0) return tiny_lp();
#endif
    return 0;
}
#endif
