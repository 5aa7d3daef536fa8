/* heads_hashes.c - prints the want[][][] table of tests/test_fovsdf_heads.c
   (thesis_variant_images_unchanged): FNV-1a hashes of IPR, SKIP and FIPR renders of the
   built-in scenes at 96x64. The committed table was printed by this program built against
   fovsdf.h of commit dcdc067 (before heuristic_start existed):
      git show dcdc067:fovsdf.h > build/old/fovsdf.h
      gcc -std=c99 -O2 -ffp-contract=off [-DFOV_NO_LIBM] -Ibuild/old tests/heads_hashes.c -lm
   With -DNEWHDR it sets heuristic_start 1 for a header that has the field: use that only to
   refresh the table after a deliberate change of the tracers shared by every method (check
   first that the change is the tracers', e.g. that CLASSIC's images changed too). */
#define FOVSDF_IMPLEMENTATION
#include "fovsdf.h" /* the header under -I */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
static uint64_t fnv(uint64_t h, const void *p, size_t n){const unsigned char*c=(const unsigned char*)p;while(n--){h^=*c++;h*=1099511628211ull;}return h;}
int main(int argc, char **argv){
  if (argc > 1) { /* no options: -h / --help prints the usage (exit 0), anything else exits 2 */
    int help = !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h");
    fputs("usage: heads_hashes\n  prints the want[][][] table of tests/test_fovsdf_heads.c for the fovsdf.h under -I;"
          " no options\n  -h, --help  this text\n", help ? stdout : stderr);
    return help ? 0 : 2;
  }
  const uint32_t methods[3] = { FOVSDF_METHOD_IPR, FOVSDF_METHOD_SKIP, FOVSDF_METHOD_FIPR };
  static float rgb[96 * 64 * 3], dep[96 * 64], st[96 * 64];
  uint32_t id, mi, s;
  for (id = 0; id < 6; ++id) { size_t sz; void *mem; fovsdf_builtin bi;
    fovsdf_builtin_size(id, &sz); mem = malloc(sz); fovsdf_builtin_init(id, &bi, mem, sz);
    bi.camera.width = 96; bi.camera.height = 64; printf("        {");
    for (mi = 0; mi < 3; ++mi) { printf(" {");
      for (s = 0; s < 2; ++s) { fovsdf_config c = fovsdf_config_default(); fovsdf_ctx k; fovsdf_output o; fov_gaze gz = { 28.8f, 38.4f };
        uint64_t h = 1469598103934665603ull;
        c.method = methods[mi]; c.spp = s ? 4u : 1u; c.shading = (id & 1) ? FOVSDF_SHADE_FULL : FOVSDF_SHADE_NO_SHADOWS;
#ifdef NEWHDR
        c.heuristic_start = 1;
#endif
        fovsdf_init(&k, &c, &bi.scene, &bi.camera, gz, NULL, 0); fovsdf_output_init(&o);
        o.rgb = rgb; o.depth = dep; o.start = st;
        memset(rgb, 0, sizeof rgb); memset(dep, 0, sizeof dep); memset(st, 0, sizeof st);
        fovsdf_render_rows(&k, 0, 64, &o, NULL);
        h = fnv(h, rgb, sizeof rgb); h = fnv(h, dep, sizeof dep); h = fnv(h, st, sizeof st);
        printf(" 0x%016llxull%s", (unsigned long long)h, s ? "" : ","); }
      printf(" }%s", mi < 2 ? "," : ""); }
    printf(" },\n"); free(mem); }
  return 0; }
