/* main.c - the tiny consumer project of tests/cmake/run.sh: all three fov headers with their
   implementations (FOV_IMPL), found only through the build system's include flags (the
   project lives outside the repository). Each header's config resolves (fovsdf, fovlp with
   the C-FoV preset at 640x360, fovpt) and FOVSDF_VERSION_STRING equals FOV_EXPECT_VERSION,
   the version the build system reports (find_package's fov_VERSION, pkg-config
   --modversion). Exit status 0 when all hold; otherwise a line per failure on stderr. */
#define FOV_IMPL
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"

#include <stdio.h>
#include <string.h>

#ifndef FOV_EXPECT_VERSION
#error "build with -DFOV_EXPECT_VERSION=\"X.Y.Z\" (the version the build system reports)"
#endif

int main(void)
{
    int bad = 0;
    fovsdf_config sdf_in = fovsdf_config_default(), sdf;
    fovlp_config lp_in = fovlp_config_preset(FOVLP_PRESET_C_FOV, 640, 360), lp;
    fovpt_config pt_in = fovpt_config_default(), pt;
    size_t lp_bytes = 0;
    if (fovsdf_config_resolve(&sdf_in, &sdf) != FOV_OK) {
        fprintf(stderr, "fovsdf_config_resolve failed\n");
        bad = 1;
    }
    if (fovlp_config_resolve(&lp_in, &lp) != FOV_OK || fovlp_memory_size(&lp, &lp_bytes) != FOV_OK
        || lp_bytes == 0) {
        fprintf(stderr, "fovlp_config_resolve / fovlp_memory_size failed\n");
        bad = 1;
    }
    if (fovpt_config_resolve(&pt_in, &pt) != FOV_OK) {
        fprintf(stderr, "fovpt_config_resolve failed\n");
        bad = 1;
    }
    if (strcmp(FOVSDF_VERSION_STRING, FOV_EXPECT_VERSION) != 0) {
        fprintf(stderr, "FOVSDF_VERSION_STRING \"%s\" != build system version \"%s\"\n",
                FOVSDF_VERSION_STRING, FOV_EXPECT_VERSION);
        bad = 1;
    }
    if (!bad) printf("consumer: fov %s, fovlp %s, fovpt %s\n", FOVSDF_VERSION_STRING,
                     FOVLP_VERSION_STRING, FOVPT_VERSION_STRING);
    return bad;
}
