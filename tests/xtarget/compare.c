/* compare.c - compares two render_test.c dumps (tests/xtarget/run.sh). Hosted C99.

   usage: compare [--psnr DB] [--hit PERCENT] LABEL REFERENCE.txt TEST.txt
          compare --ppm DUMP.txt PREFIX      writes PREFIX<scene>.ppm (image) and
                                             PREFIX<scene>_hit.pgm per scene, for viewing

   For every scene of the reference dump it prints one line
     PASS LABEL SCENE: psnr=.. dB, hit mismatch ..%, max depth diff .. (..), evals ..
   or FAIL with the same figures and the reason, where
     psnr            PSNR of the 8-bit sRGB image over all channels (inf when identical),
     hit mismatch    pixels whose hit flag differs, in % of the pixels,
     max depth diff  largest |depth_ref - depth_test| over pixels both dumps mark as hit,
                     absolute in scene units and relative to depth_ref,
     evals           distance evaluations (fovsdf_stats.evals) of both, informative only.
   A scene passes when psnr >= DB (default 50) and hit mismatch <= PERCENT (default 0.1)
   and both renders reported success. Exit status: 0 all passed, 1 a failure, 2 usage or
   unreadable input. */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMP_MAX_SCENES 16

typedef struct cmp_scene {
    int id;
    char name[64];
    long status;
    char step[64];
    unsigned long long evals;
    unsigned char *rgb, *hit;
    float *depth;
} cmp_scene;

typedef struct cmp_dump {
    int w, h, nscenes, done, done_status;
    cmp_scene s[CMP_MAX_SCENES];
    char err[256];
} cmp_dump;

static int cmp_hexval(int c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* reads the next line (without the newline) into buf; 0 at end of file */
static int cmp_line(FILE *f, char *buf, size_t cap)
{
    size_t n;
    if (!fgets(buf, (int)cap, f)) return 0;
    n = strlen(buf);
    while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == '\r')) buf[--n] = 0;
    return 1;
}

static int cmp_load(const char *path, cmp_dump *d)
{
    FILE *f = fopen(path, "r");
    size_t cap;
    char *line;
    cmp_scene *s = NULL;
    memset(d, 0, sizeof *d);
    d->done_status = -1;
    if (!f) { snprintf(d->err, sizeof d->err, "cannot open %s", path); return 0; }
    cap = 1 << 16;
    line = (char *)malloc(cap);
    if (!line) { fclose(f); snprintf(d->err, sizeof d->err, "out of memory"); return 0; }
    if (!cmp_line(f, line, cap) || sscanf(line, "fovxt 1 %d %d", &d->w, &d->h) != 2 ||
        d->w <= 0 || d->h <= 0 || d->w > 4096 || d->h > 4096) {
        snprintf(d->err, sizeof d->err, "%s: no 'fovxt 1 W H' header line", path);
        goto fail;
    }
    while (cmp_line(f, line, cap)) {
        int x, y, n = d->w * d->h;
        if (strncmp(line, "scene ", 6) == 0) {
            if (d->nscenes == CMP_MAX_SCENES) { snprintf(d->err, sizeof d->err, "too many scenes"); goto fail; }
            s = &d->s[d->nscenes++];
            s->status = -999;
            if (sscanf(line, "scene %d %63s", &s->id, s->name) != 2) goto bad;
            s->rgb = (unsigned char *)calloc((size_t)n * 3, 1);
            s->hit = (unsigned char *)calloc((size_t)n, 1);
            s->depth = (float *)calloc((size_t)n, sizeof(float));
            if (!s->rgb || !s->hit || !s->depth) goto bad;
        } else if (strncmp(line, "done ", 5) == 0) {
            d->done = 1;
            d->done_status = atoi(line + 5);
        } else if (!s) {
            continue;   /* text before the first scene */
        } else if (strncmp(line, "status ", 7) == 0) {
            if (sscanf(line, "status %ld %63s", &s->status, s->step) != 2) goto bad;
        } else if (strncmp(line, "stats ", 6) == 0) {
            if (sscanf(line, "stats evals %llu", &s->evals) != 1) goto bad;
        } else if (strcmp(line, "rgb") == 0) {
            for (y = 0; y < d->h; y++) {
                if (!cmp_line(f, line, cap) || (int)strlen(line) != d->w * 6) goto bad;
                for (x = 0; x < d->w * 3; x++) {
                    int hi = cmp_hexval(line[2 * x]), lo = cmp_hexval(line[2 * x + 1]);
                    if (hi < 0 || lo < 0) goto bad;
                    s->rgb[(y * d->w) * 3 + x] = (unsigned char)(hi * 16 + lo);
                }
            }
        } else if (strcmp(line, "hit") == 0) {
            for (y = 0; y < d->h; y++) {
                if (!cmp_line(f, line, cap) || (int)strlen(line) != d->w) goto bad;
                for (x = 0; x < d->w; x++) {
                    if (line[x] != '0' && line[x] != '1') goto bad;
                    s->hit[y * d->w + x] = (unsigned char)(line[x] == '1');
                }
            }
        } else if (strcmp(line, "depth") == 0) {
            for (y = 0; y < d->h; y++) {
                if (!cmp_line(f, line, cap) || (int)strlen(line) != d->w * 8) goto bad;
                for (x = 0; x < d->w; x++) {
                    uint32_t u = 0;
                    float v;
                    int k;
                    for (k = 0; k < 8; k++) {
                        int h = cmp_hexval(line[8 * x + k]);
                        if (h < 0) goto bad;
                        u = (u << 4) | (uint32_t)h;
                    }
                    memcpy(&v, &u, sizeof v);
                    s->depth[y * d->w + x] = v;
                }
            }
        }
    }
    free(line);
    fclose(f);
    if (!d->done) { snprintf(d->err, sizeof d->err, "%s: truncated (no 'done' line)", path); return 0; }
    return 1;
bad:
    snprintf(d->err, sizeof d->err, "%s: malformed dump near '%.40s'", path, line);
fail:
    free(line);
    fclose(f);
    return 0;
}

static int cmp_write_ppm(const char *dump_path, const char *prefix)
{
    static cmp_dump d;
    int i, p;
    if (!cmp_load(dump_path, &d)) { fprintf(stderr, "compare: %s\n", d.err); return 2; }
    for (i = 0; i < d.nscenes; i++) {
        char path[1024];
        FILE *f;
        int n = d.w * d.h;
        snprintf(path, sizeof path, "%s%s.ppm", prefix, d.s[i].name);
        f = fopen(path, "wb");
        if (!f) { fprintf(stderr, "compare: cannot write %s\n", path); return 2; }
        fprintf(f, "P6\n%d %d\n255\n", d.w, d.h);
        fwrite(d.s[i].rgb, 1, (size_t)n * 3, f);
        fclose(f);
        snprintf(path, sizeof path, "%s%s_hit.pgm", prefix, d.s[i].name);
        f = fopen(path, "wb");
        if (!f) { fprintf(stderr, "compare: cannot write %s\n", path); return 2; }
        fprintf(f, "P5\n%d %d\n255\n", d.w, d.h);
        for (p = 0; p < n; p++) fputc(d.s[i].hit[p] ? 255 : 0, f);
        fclose(f);
    }
    return 0;
}

/* -h / --help prints this to stdout (exit 0); wrong arguments print it to stderr (exit 2) */
static void cmp_usage(FILE *f)
{
    fputs("usage: compare [--psnr DB] [--hit PERCENT] LABEL REFERENCE.txt TEST.txt\n"
          "       compare --ppm DUMP.txt PREFIX\n"
          "  compares two render_test.c dumps scene by scene (tests/xtarget/run.sh)\n"
          "  --psnr DB        least PSNR of the 8-bit sRGB image (default 50)\n"
          "  --hit PERCENT    most pixels whose hit flag differs (default 0.1)\n"
          "  --ppm            writes PREFIX<scene>.ppm and PREFIX<scene>_hit.pgm per scene\n"
          "  -h, --help       this text\n", f);
}

int main(int argc, char **argv)
{
    double psnr_min = 50.0, hit_max = 0.1;
    const char *label, *ref_path, *test_path;
    static cmp_dump ref, tst;
    int a = 1, i, failed = 0;

    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) { cmp_usage(stdout); return 0; }
    if (argc == 4 && strcmp(argv[1], "--ppm") == 0) return cmp_write_ppm(argv[2], argv[3]);

    while (a + 1 < argc && argv[a][0] == '-' && argv[a][1] == '-') {
        if (strcmp(argv[a], "--psnr") == 0) psnr_min = atof(argv[a + 1]);
        else if (strcmp(argv[a], "--hit") == 0) hit_max = atof(argv[a + 1]);
        else break;
        a += 2;
    }
    if (argc - a != 3) {
        cmp_usage(stderr);
        return 2;
    }
    label = argv[a]; ref_path = argv[a + 1]; test_path = argv[a + 2];
    if (!cmp_load(ref_path, &ref)) {
        printf("FAIL %s: reference unreadable: %s\n", label, ref.err);
        return 1;
    }
    if (!cmp_load(test_path, &tst)) {
        printf("FAIL %s: %s\n", label, tst.err);
        return 1;
    }
    if (ref.w != tst.w || ref.h != tst.h) {
        printf("FAIL %s: image size %dx%d, reference %dx%d\n", label, tst.w, tst.h, ref.w, ref.h);
        return 1;
    }
    if (ref.nscenes == 0) {
        printf("FAIL %s: the reference has no scene\n", label);
        return 1;
    }
    for (i = 0; i < ref.nscenes; i++) {
        const cmp_scene *r = &ref.s[i], *t = NULL;
        int j, n = ref.w * ref.h, p, mism = 0, both = 0, worst = -1;
        double se = 0.0, mse, psnr, mis_pct, dmax = 0.0, drel = 0.0, edelta;
        char psnr_txt[32];
        for (j = 0; j < tst.nscenes; j++)
            if (tst.s[j].id == r->id) t = &tst.s[j];
        if (!t) { printf("FAIL %s %s: scene missing from the dump\n", label, r->name); failed = 1; continue; }
        for (p = 0; p < 3 * n; p++) {
            double e = (double)r->rgb[p] - (double)t->rgb[p];
            se += e * e;
        }
        for (p = 0; p < n; p++) {
            if (r->hit[p] != t->hit[p]) mism++;
            else if (r->hit[p]) {
                double dz = fabs((double)r->depth[p] - (double)t->depth[p]);
                both++;
                if (!(dz <= dmax)) { dmax = dz; worst = p; }   /* NaN counts as worst */
            }
        }
        if (worst >= 0 && r->depth[worst] != 0.0f) drel = dmax / fabs((double)r->depth[worst]);
        mse = se / (3.0 * n);
        psnr = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : (double)INFINITY;
        if (mse > 0.0) snprintf(psnr_txt, sizeof psnr_txt, "%.2f", psnr);
        else snprintf(psnr_txt, sizeof psnr_txt, "inf");
        mis_pct = 100.0 * mism / n;
        edelta = r->evals ? 100.0 * ((double)t->evals - (double)r->evals) / (double)r->evals : 0.0;
        {
            char fig[512], why[256];
            int ok = 1;
            why[0] = 0;
            snprintf(fig, sizeof fig,
                     "psnr=%s dB, hit mismatch %.3f%% (%d px), max depth diff %.3g (rel %.2g, %d px both hit), evals %llu vs ref %llu (%+.3f%%)",
                     psnr_txt, mis_pct, mism, dmax, drel, both, t->evals, r->evals, edelta);
            if (r->status != 0 || t->status != 0) {
                ok = 0;
                snprintf(why, sizeof why, "; render failed: ref status %ld (%s), test status %ld (%s)",
                         r->status, r->step, t->status, t->step);
            } else {
                if (!(psnr >= psnr_min)) {
                    ok = 0;
                    snprintf(why + strlen(why), sizeof why - strlen(why), "; psnr below %.1f dB", psnr_min);
                }
                if (!(mis_pct <= hit_max)) {
                    ok = 0;
                    snprintf(why + strlen(why), sizeof why - strlen(why), "; hit mismatch above %.3f%%", hit_max);
                }
            }
            if (ok) printf("PASS %s %s: %s\n", label, r->name, fig);
            else { printf("FAIL %s %s: %s%s\n", label, r->name, fig, why); failed = 1; }
        }
    }
    if (tst.done_status != 0 && !failed) {
        printf("FAIL %s: program reported done %d\n", label, tst.done_status);
        failed = 1;
    }
    return failed;
}
