/* test_versions.c - the version macros of each header agree with its version line.

   For fovsdf.h, fovlp.h and fovpt.h: <NAME>_VERSION_STRING must equal "MAJOR.MINOR.PATCH"
   formatted from the compiled <NAME>_VERSION_MAJOR/MINOR/PATCH macros, and the "vX.Y.Z" of
   the header's first line (the file is read as text, so the check is independent of the
   preprocessor), and the first entry under "RECENT REVISION HISTORY" must name the same
   version. Run from the repository root (or pass the directory that holds the headers).
   Prints one line per check and "N passed, N failed". */
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"
#include "fovcheck.h"

#include <stdio.h>
#include <string.h>

#define VT_STR2(x) #x
#define VT_STR(x) VT_STR2(x)

/* reads up to cap - 1 bytes of path into buf; returns the length, or -1 */
static long read_text(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n;
    if (!f) return -1;
    n = fread(buf, 1, cap - 1, f);
    fclose(f);
    buf[n] = '\0';
    return (long)n;
}

/* copies the first "vX.Y.Z" token of the text's first line (without the v) into out */
static int first_line_version(const char *text, char *out, size_t cap)
{
    const char *eol = strchr(text, '\n');
    const char *p;
    size_t len = eol ? (size_t)(eol - text) : strlen(text);
    for (p = text; p + 1 < text + len; ++p) {
        if (p[0] == 'v' && p[1] >= '0' && p[1] <= '9' && (p == text || p[-1] == ' ')) {
            size_t k = 0;
            ++p;
            while (p < text + len && ((*p >= '0' && *p <= '9') || *p == '.') && k + 1 < cap)
                out[k++] = *p++;
            out[k] = '\0';
            return k > 0;
        }
    }
    return 0;
}

/* the version that starts the first non-empty line after "RECENT REVISION HISTORY" */
static int history_version(const char *text, char *out, size_t cap)
{
    const char *p = strstr(text, "RECENT REVISION HISTORY");
    size_t k = 0;
    if (!p) return 0;
    p = strchr(p, '\n');
    if (!p) return 0;
    while (*p == '\n' || *p == ' ') ++p;
    while (((*p >= '0' && *p <= '9') || *p == '.') && k + 1 < cap) out[k++] = *p++;
    out[k] = '\0';
    return k > 0;
}

static char g_text[1 << 20];

static void check_header(const char *dir, const char *file, const char *macro_string,
                         int major, int minor, int patch)
{
    char path[512], name[128], from_macros[64], line_ver[64], hist_ver[64];
    long n;
    snprintf(path, sizeof path, "%s/%s", dir, file);
    snprintf(from_macros, sizeof from_macros, "%d.%d.%d", major, minor, patch);

    snprintf(name, sizeof name, "%s: VERSION_STRING matches MAJOR.MINOR.PATCH", file);
    check(strcmp(macro_string, from_macros) == 0, name, "VERSION_STRING \"%s\", macros %s",
          macro_string, from_macros);

    n = read_text(path, g_text, sizeof g_text);
    snprintf(name, sizeof name, "%s: header readable", file);
    if (!check(n > 0, name, "cannot read %s (run from the repository root)", path)) return;

    snprintf(name, sizeof name, "%s: first line has vX.Y.Z", file);
    if (check(first_line_version(g_text, line_ver, sizeof line_ver), name,
              "no vX.Y.Z on the first line of %s", path)) {
        snprintf(name, sizeof name, "%s: first line's vX.Y.Z matches VERSION_STRING", file);
        check(strcmp(line_ver, macro_string) == 0, name, "first line v%s, VERSION_STRING \"%s\"",
              line_ver, macro_string);
    } else {
        line_ver[0] = '\0';
    }

    snprintf(name, sizeof name, "%s: has a RECENT REVISION HISTORY entry", file);
    if (check(history_version(g_text, hist_ver, sizeof hist_ver), name,
              "no version after RECENT REVISION HISTORY in %s", path)) {
        snprintf(name, sizeof name, "%s: newest RECENT REVISION HISTORY entry is the version", file);
        check(strcmp(hist_ver, line_ver) == 0, name, "history starts with %s, first line v%s",
              hist_ver, line_ver);
    }

    /* the text of the macros agrees with the compiled values (the header read is the one
       compiled) */
    snprintf(name, sizeof name, "%s: the file read is the header compiled", file);
    {
        char needle[128];
        snprintf(needle, sizeof needle, "_VERSION_STRING \"%s\"", macro_string);
        check(strstr(g_text, needle) != NULL, name, "%s does not contain %s", path, needle);
    }
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    /* the checker itself: a mismatch must be seen */
    {
        char v[64];
        check(first_line_version("/* x.h - v1.22.3 - y\nv9.9.9", v, sizeof v) && !strcmp(v, "1.22.3"),
              "self-test: first-line parser", "got %s", v);
        check(history_version("RECENT REVISION HISTORY\n   0.3.1 (2026) z", v, sizeof v) &&
                  !strcmp(v, "0.3.1"), "self-test: history parser", "got %s", v);
        check(strcmp(VT_STR(FOVSDF_VERSION_MAJOR), "") != 0, "self-test: macros expand", "empty");
    }
    check_header(dir, "fovsdf.h", FOVSDF_VERSION_STRING, FOVSDF_VERSION_MAJOR,
                 FOVSDF_VERSION_MINOR, FOVSDF_VERSION_PATCH);
    check_header(dir, "fovlp.h", FOVLP_VERSION_STRING, FOVLP_VERSION_MAJOR, FOVLP_VERSION_MINOR,
                 FOVLP_VERSION_PATCH);
    check_header(dir, "fovpt.h", FOVPT_VERSION_STRING, FOVPT_VERSION_MAJOR, FOVPT_VERSION_MINOR,
                 FOVPT_VERSION_PATCH);
    return fovcheck_summary();
}
