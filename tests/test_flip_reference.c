/*
 * test_flip_reference.c - compares fovm_flip (tests/common/fovmetrics.h)
 * with mean LDR-FLIP values produced by NVIDIA's reference FLIP tool
 * (see tests/flip_reference/reference_values.txt for how they were made).
 *
 * Run from the repository root:
 *   gcc -std=c99 -O2 -Itests/common tests/test_flip_reference.c -lm \
 *       -o /tmp/test_flip_reference && /tmp/test_flip_reference
 * or pass the data directory explicitly:
 *   /tmp/test_flip_reference path/to/tests/flip_reference
 *
 * Tolerance: a pair passes if |ours - ref| <= 1e-4 (absolute). This is
 * much stricter than the project's target (0.005 absolute or 2% relative)
 * because the achieved agreement is far better, and a loose tolerance
 * would not notice wrong details: e.g. weighting the two blue-yellow CSF
 * Gaussians by a*pi/b instead of a*sqrt(pi/b) moves the means by up to
 * 4.9e-4, and a CSF radius of 2 instead of 3 standard deviations by up
 * to 6.5e-4; dropping the Hunt adjustment by up to 0.087.
 * ACHIEVED (gcc 12.2, x86-64, -O2): max |diff| = 7.5e-6, max relative
 * diff = 2.4e-5 (shapes pairs ~1e-6; the reference prints only 6
 * decimals). The program prints the achieved maxima on its last check
 * line.
 *
 * Output: one "PASS name" / "FAIL name: detail" line per check, then
 * "N passed, M failed"; exit status 1 if any check failed.
 */
#define FOVIMG_IMPLEMENTATION
#include "fovimg.h"
#define FOVM_IMPLEMENTATION
#include "../examples/fovmetrics.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#define ABS_TOL 1e-4


int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "tests/flip_reference";
    char path[2048], line[1024];
    FILE *f;
    int npass = 0, nfail = 0, npairs = 0;
    double maxabs = 0.0, maxrel = 0.0;

    snprintf(path, sizeof path, "%s/reference_values.txt", dir);
    f = fopen(path, "r");
    if (!f) {
        printf("FAIL open_reference_values: cannot open %s\n", path);
        printf("0 passed, 1 failed\n");
        return 1;
    }
    while (fgets(line, sizeof line, f)) {
        char rname[256], tname[256], name[600];
        double ppd, refval, ours = 0.0, d, rel;
        fovimg a, b;
        int err;
        if (line[0] == '#' || line[0] == '\n' || line[0] == '\r') continue;
        if (sscanf(line, "%255s %255s %lf %lf", rname, tname, &ppd, &refval) != 4) {
            printf("FAIL parse: bad line: %s", line);
            nfail++;
            continue;
        }
        snprintf(name, sizeof name, "flip_%s_vs_%s_ppd%g", rname, tname, ppd);
        snprintf(path, sizeof path, "%s/%s", dir, rname);
        err = fovimg_read_any(path, &a);
        if (err) {
            printf("FAIL %s: reading %s: %s\n", name, path, fovimg_strerror(err));
            nfail++;
            continue;
        }
        snprintf(path, sizeof path, "%s/%s", dir, tname);
        err = fovimg_read_any(path, &b);
        if (err) {
            printf("FAIL %s: reading %s: %s\n", name, path, fovimg_strerror(err));
            fovimg_free(&a);
            nfail++;
            continue;
        }
        if (a.w != b.w || a.h != b.h || a.c != b.c) {
            printf("FAIL %s: size mismatch\n", name);
            nfail++;
        } else if ((err = fovm_flip(a.px, b.px, a.w, a.h, a.c, ppd, &ours, NULL)) != 0) {
            printf("FAIL %s: fovm_flip error %d\n", name, err);
            nfail++;
        } else {
            d = fabs(ours - refval);
            rel = refval > 0.0 ? d / refval : (d > 0.0 ? 1.0 : 0.0);
            if (d > maxabs) maxabs = d;
            if (rel > maxrel) maxrel = rel;
            npairs++;
            if (d <= ABS_TOL) {
                printf("PASS %s (ours %.6f, reference %.6f, diff %.2e)\n", name, ours, refval, d);
                npass++;
            } else {
                printf("FAIL %s: ours %.6f, reference %.6f, diff %.2e\n", name, ours, refval, d);
                nfail++;
            }
        }
        fovimg_free(&a);
        fovimg_free(&b);
    }
    fclose(f);
    if (npairs >= 10) {
        printf("PASS reference_pairs_loaded (%d pairs)\n", npairs);
        npass++;
    } else {
        printf("FAIL reference_pairs_loaded: only %d pairs compared\n", npairs);
        nfail++;
    }
    printf("%s max_difference: max |diff| = %.3g, max relative diff = %.3g (tolerance %.3g abs)\n",
           maxabs <= ABS_TOL ? "PASS" : "FAIL", maxabs, maxrel, ABS_TOL);
    if (maxabs <= ABS_TOL) npass++; else nfail++;
    printf("%d passed, %d failed\n", npass, nfail);
    return nfail ? 1 : 0;
}
