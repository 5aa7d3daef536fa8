/* test_fovsdf_cells.c - FIPR / CONE_FOV with a small FOVSDF_FOV_CELLS (the header invites
   lowering it for small stacks): every config init accepts renders within the tile arrays
   (run under ASan with NDEBUG, so only the sizes protect the stack), and configs that need
   more cells are FOV_ERR_LIMIT. Built by tests/run_all.sh with -DFOVSDF_FOV_CELLS=100. */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h"
#include "fovcheck.h"
#include <stdlib.h>

int main(void)
{
    size_t sz;
    void *mem;
    fovsdf_builtin bi;
    uint32_t tiles[5] = { 4, 8, 12, 16, 20 }, t, m, ok_runs = 0, limits = 0, other = 0;
    int32_t r;
    fov_result first_bad = FOV_OK;
    static float rgb[37 * 23 * 3];
    fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &sz);
    mem = malloc(sz);
    fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &bi, mem, sz);
    bi.camera.width = 37;
    bi.camera.height = 23;
    for (m = 0; m < 2; ++m)
        for (t = 0; t < 5; ++t)
            for (r = 0; r <= 3; ++r) {
                fovsdf_config c = fovsdf_config_default();
                fovsdf_ctx k;
                fovsdf_output o;
                fov_gaze gz = { 10.0f, 7.0f };
                fov_result res;
                c.method = m ? FOVSDF_METHOD_CONE_FOV : FOVSDF_METHOD_FIPR;
                if (m) { if (tiles[t] & (tiles[t] - 1)) continue; c.cone_tile = tiles[t]; c.cone_levels = 0; }
                else c.ipr_tile = tiles[t];
                if (r == 0) c.ipr_no_filter = 1; else c.ipr_radius = r;
                c.acuity.fovea_deg = 3.0f;
                res = fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0);
                if (res == FOV_ERR_LIMIT) { ++limits; continue; }
                if (res != FOV_OK) { ++other; first_bad = res; printf("INFO %s tile %u r %d: %s\n", fovsdf_method_name(c.method), tiles[t], (int)r, fovsdf_result_string(res)); continue; }
                fovsdf_output_init(&o);
                o.rgb = rgb;
                if (fovsdf_render_rows(&k, 0, 23, &o, NULL) == FOV_OK) ++ok_runs;
            }
    check(limits >= 3 && ok_runs >= 10 && other == 0, "fov_cells_small_budget",
          "%u configs rendered, %u refused with FOV_ERR_LIMIT, %u other errors (first %d)", ok_runs, limits, other,
          (int)first_bad);
    free(mem);
    return fovcheck_summary();
}
