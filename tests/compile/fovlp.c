/* Compile test: the fovlp.h implementation plus a small program using it (C; fovlp.cc
   compiles this file as C++). Built by tests/compile/run.sh over the compiler x standard x
   optimisation matrix with -Werror; one build per compiler is linked and run. */
#define FOVLP_IMPLEMENTATION
#include "fovlp.h"
#include "tiny_lp.h"

int main(void)
{
    fovlp_config cfg = fovlp_config_default(), r;
    int e = tiny_lp();
    if (e != 0) return e;
    cfg.width = 64; cfg.height = 48;
    if (fovlp_config_resolve(&cfg, &r) != FOV_OK) return 20;
    cfg.sigma = -1.0f;
    if (fovlp_config_resolve(&cfg, &r) != FOV_ERR_INVALID_ARG) return 21;
    if (fovlp_result_string(FOV_ERR_LIMIT) == 0 || fovlp_preset_name(2) == 0) return 22;
    return 0;
}
