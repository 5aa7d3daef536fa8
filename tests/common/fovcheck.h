/* fovcheck.h - the check harness of the fov test programs: one line per check, "PASS name"
   or "FAIL name: detail", and a closing "N passed, N failed" line (fovcheck_summary), which
   tests/run_all.sh adds up. Include it in one test program (everything is static). */
#ifndef FOVCHECK_H
#define FOVCHECK_H
#include <stdarg.h>
#include <stdio.h>

#if defined(__GNUC__) || defined(__clang__)
#define FOVCHECK_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define FOVCHECK_PRINTF(a, b)
#endif

static int g_pass, g_fail;

/* Records one check; returns ok so callers can chain diagnostics. */
static int check(int ok, const char *name, const char *fmt, ...) FOVCHECK_PRINTF(3, 4);
static int check(int ok, const char *name, const char *fmt, ...)
{
    if (ok) {
        printf("PASS %s\n", name);
        g_pass++;
    } else {
        va_list ap;
        printf("FAIL %s: ", name);
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        printf("\n");
        g_fail++;
    }
    fflush(stdout);
    return ok;
}

/* Formats a check name into one static buffer (one name per check call):
   check(ok, fovcheck_name("case_%d", i), ...). Test programs may #define N fovcheck_name. */
static char fovcheck__name[256];
static inline const char *fovcheck_name(const char *fmt, ...) FOVCHECK_PRINTF(1, 2);
static inline const char *fovcheck_name(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(fovcheck__name, sizeof fovcheck__name, fmt, ap);
    va_end(ap);
    return fovcheck__name;
}

/* Prints an "INFO ..." line: a figure the run reports, no check. */
static inline void fovcheck_info(const char *fmt, ...) FOVCHECK_PRINTF(1, 2);
static inline void fovcheck_info(const char *fmt, ...)
{
    va_list ap;
    printf("INFO ");
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
}

/* Prints the closing line; returns the process exit status. */
static int fovcheck_summary(void)
{
    printf("%d passed, %d failed\n", g_pass, g_fail);
    return g_fail ? 1 : 0;
}
#endif
