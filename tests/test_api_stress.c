/*
 * test_api_stress.c - a hostile but legal user of fovsdf.h, fovlp.h and fovpt.h, through the
 * public API only: odd, tiny and huge sizes; NaN, infinite and huge gazes, cameras and display
 * parameters; NULL in every pointer argument; out-of-range enums and values; memory one byte
 * short or misaligned; degenerate scenes and programs. Every output image is checked for
 * NaN/inf pixels, range, pixels left unwritten and writes past its end (canaries; ASan in the
 * sanitizer build). Each case runs in a child process under an alarm (no endless loop, no
 * crash takes the suite down): a hang or a crash is a FAIL of that case.
 *
 * Build (tests/run_all.sh builds it three ways: libm, -DFOV_NO_LIBM, sanitizers):
 *   gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion \
 *       -Werror -I. -Itests/common tests/test_api_stress.c -lm -o build/tests/test_api_stress
 * Output: "PASS name" / "FAIL name: detail" per check, then "N passed, N failed".
 */
#define _POSIX_C_SOURCE 200809L
/* FOV_TEST_LINK_IMPL: tests/run_all.sh links the implementations compiled once per build
   (tests/common/fov_impl_*.c) instead of compiling them in this file */
#ifndef FOV_TEST_LINK_IMPL
#define FOV_IMPL
#endif
#include "fovsdf.h"
#include "fovlp.h"
#include "fovpt.h"
#include "fovcheck.h"

#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* Inside a case the checks are quiet: a passing check is only counted (g_sub_pass), a failing
   one prints its FAIL line and counts as a failure; each case then closes with one PASS line
   giving its number of passing checks (so tens of thousands of fuzz checks do not flood the
   suite's count). */
static int g_quiet, g_sub_pass;
static int stress_check(int ok, const char *name, const char *fmt, ...) FOVCHECK_PRINTF(3, 4);
static int stress_check(int ok, const char *name, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    if (ok && g_quiet) { g_sub_pass++; return 1; }
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return check(ok, name, "%s", msg);
}
#define check stress_check

/* ---- helpers ----------------------------------------------------------------------------- */
#define N fovcheck_name /* tests/common/fovcheck.h */

static float f_nan(void) { volatile float z = 0.0f; return z / z; }
static float f_inf(void) { volatile float z = 0.0f; return 1.0f / z; }

static uint64_t g_rs = 0x243f6a8885a308d3ull;
static double urand(void)
{
    g_rs ^= g_rs << 13; g_rs ^= g_rs >> 7; g_rs ^= g_rs << 17;
    return (double)(g_rs >> 11) * (1.0 / 9007199254740992.0);
}
static float frand(float a, float b) { return a + (b - a) * (float)urand(); }

/* logger: remembers the last error it saw */
typedef struct tlog {
    int calls, errors, warnings;
    int32_t code;
    int msg_ok;
    char tag[16];
} tlog;
static void tlog_fn(const char *tag, uint32_t level, int32_t code, const char *msg, uint32_t line,
                    void *user)
{
    tlog *t = (tlog *)user;
    (void)line;
    t->calls++;
    if (level == FOV_LOG_ERROR) {
        t->errors++;
        t->code = code;
        t->msg_ok = msg != NULL && msg[0] != 0;
    } else {
        t->warnings++;
    }
    snprintf(t->tag, sizeof t->tag, "%s", tag ? tag : "(null)");
}
static fov_logger mk_logger(tlog *t)
{
    fov_logger l;
    memset(t, 0, sizeof *t);
    l.func = tlog_fn;
    l.user = t;
    return l;
}

/* expected code, and the logger saw that code with a message */
static void expect_logged(const char *name_in, fov_result got, fov_result want, const tlog *t)
{
    char name[200];
    snprintf(name, sizeof name, "%s", name_in);
    check(got == want, name, "got %d want %d", (int)got, (int)want);
    check(t->errors >= 1 && t->code == (int32_t)want && t->msg_ok, N("%s_logged", name),
          "logger errors %d code %d msg %d", t->errors, (int)t->code, t->msg_ok);
}
static void expect(const char *name, fov_result got, fov_result want)
{
    check(got == want, name, "got %d (%s) want %d", (int)got, fovsdf_result_string(got), (int)want);
}

/* float images with a canary tail: n floats, then CANARY floats of a bit pattern */
#define CANARY 16
static float *img_alloc(size_t n)
{
    float *p = (float *)malloc((n + CANARY) * sizeof(float));
    size_t i;
    if (!p) { fprintf(stderr, "out of memory\n"); exit(2); }
    for (i = 0; i < n; ++i) p[i] = f_nan();          /* unwritten pixels show as NaN */
    for (i = 0; i < CANARY; ++i) p[n + i] = -12345.0f;
    return p;
}
static int canary_ok(const float *p, size_t n)
{
    size_t i;
    for (i = 0; i < CANARY; ++i)
        if (!(p[n + i] == -12345.0f)) return 0;
    return 1;
}
/* number of entries outside [lo, hi] or not finite */
static size_t count_bad(const float *p, size_t n, float lo, float hi)
{
    size_t i, bad = 0;
    for (i = 0; i < n; ++i)
        if (!(p[i] >= lo && p[i] <= hi)) bad++;
    return bad;
}

/* ---- the case runner: every case in a child process under an alarm ---------------------- */
static int g_case_seconds = 120;
static void run_case(const char *name, void (*fn)(void))
{
    int fd[2], st = 0, got[2] = { 0, 0 };
    pid_t pid;
    fflush(stdout);
    fflush(stderr);
    if (pipe(fd) != 0) { check(0, name, "pipe failed"); return; }
    pid = fork();
    if (pid < 0) { check(0, name, "fork failed"); return; }
    if (pid == 0) {
        close(fd[0]);
        g_pass = g_fail = 0;
        alarm((unsigned)g_case_seconds);
        g_quiet = 1;
        g_sub_pass = 0;
        fn();
        g_quiet = 0;
        check(g_sub_pass > 0, N("%s_checks", name), "no check passed");
        printf("     (%s: %d checks passed, %d failed)\n", name, g_sub_pass, g_fail);
        got[0] = g_pass; got[1] = g_fail;
        fflush(stdout);
        if (write(fd[1], got, sizeof got) != (ssize_t)sizeof got) _exit(3);
        _exit(0);
    }
    close(fd[1]);
    {
        ssize_t rd = read(fd[0], got, sizeof got);
        close(fd[0]);
        waitpid(pid, &st, 0);
        if (rd == (ssize_t)sizeof got && WIFEXITED(st) && WEXITSTATUS(st) == 0) {
            g_pass += got[0];
            g_fail += got[1];
            check(1, N("%s_terminates", name), " ");
        } else if (WIFSIGNALED(st) && WTERMSIG(st) == SIGALRM) {
            check(0, N("%s_terminates", name), "no result after %d s (endless loop?)", g_case_seconds);
        } else {
            check(0, N("%s_terminates", name), "child crashed (status 0x%x, signal %d)", (unsigned)st,
                  WIFSIGNALED(st) ? WTERMSIG(st) : 0);
        }
    }
}

/* ======================================================================================== */
/* fovlp                                                                                     */
/* ======================================================================================== */

/* a smooth colour in [0.05, 0.95] and a depth in [1, 3] */
static void lp_shade(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)user;
    rgb[0] = 0.5f + 0.45f * sinf(0.37f * x);
    rgb[1] = 0.5f + 0.45f * cosf(0.23f * y);
    rgb[2] = 0.5f + 0.45f * sinf(0.11f * (x + y));
    if (depth) *depth = 2.0f + sinf(0.05f * x) * cosf(0.07f * y);
}

static void lp_shade_const(float x, float y, float rgb[3], float *depth, void *user)
{
    (void)x; (void)y; (void)user;
    rgb[0] = rgb[1] = rgb[2] = 0.8f;
    if (depth) *depth = 2.0f;
}

typedef struct lp_env {
    fovlp_ctx ctx;
    void *mem;
    float *rgb, *sdep;
    size_t nslots;
} lp_env;

static fov_result lp_open(lp_env *e, const fovlp_config *cfg)
{
    size_t bytes = 0;
    fov_result r = fovlp_memory_size(cfg, &bytes);
    memset(e, 0, sizeof *e);
    if (r != FOV_OK) return r;
    e->mem = malloc(bytes);
    r = fovlp_init(&e->ctx, cfg, e->mem, bytes);
    if (r != FOV_OK) return r;
    e->nslots = e->ctx.geo.samples;
    e->rgb = img_alloc(3u * e->nslots);
    e->sdep = img_alloc(e->nslots);
    return FOV_OK;
}
static void lp_close(lp_env *e)
{
    free(e->mem); free(e->rgb); free(e->sdep);
    memset(e, 0, sizeof *e);
}

/* every sample position handed out lies on the screen, and exactly the slots of the rows are
   written (sample buffer canaries) */
static void lp_frame_checks(lp_env *e, const char *tag_in, float *img, float *dep)
{
    const fovlp_ctx *c = &e->ctx;
    uint32_t W = c->geo.width, H = c->geo.height, rows = fovlp_sample_rows(c);
    size_t n = 0, n2 = 0, i, off = 0, badv = 0;
    fovlp_sample *s;
    fov_result r;
    uint64_t shaded = 0;
    char tag[160];
    snprintf(tag, sizeof tag, "%s", tag_in);
    r = fovlp_samples(c, 0, rows, NULL, 0, &n);
    check(r == FOV_OK && n >= 1 && n <= e->nslots, N("%s_count", tag), "r %d n %zu slots %zu", (int)r, n, e->nslots);
    s = (fovlp_sample *)malloc((n + 1) * sizeof *s);
    if (n > 0) {
        r = fovlp_samples(c, 0, rows, s, n - 1, &n2);
        check(r == FOV_ERR_TOO_SMALL, N("%s_samples_cap_short", tag), "r %d", (int)r);
    }
    r = fovlp_samples(c, 0, rows, s, n, &n2);
    check(r == FOV_OK && n2 == n, N("%s_samples", tag), "r %d n %zu/%zu", (int)r, n2, n);
    {
        fovlp_sample first;
        memset(&first, 0, sizeof first);
        for (i = 0; i < n2; ++i)
            if (!(s[i].x >= 0.0f && s[i].x < (float)W && s[i].y >= 0.0f && s[i].y < (float)H) ||
                s[i].slot >= e->nslots) {
                if (off == 0) first = s[i];
                off++;
            }
        check(off == 0, N("%s_samples_on_screen", tag),
              "%zu of %zu samples off the %ux%u screen or slot out of range, first (%.9g, %.9g) slot %u "
              "(lp_slots %u, centre %u), gaze (%.9g, %.9g), jitter (%g, %g), r_g %g, alpha %g sigma %g",
              off, n2, W, H, (double)first.x, (double)first.y, first.slot, c->geo.lp_slots, c->geo.centre_slot,
              (double)c->gaze.x, (double)c->gaze.y, (double)c->jit_u, (double)c->jit_v, (double)c->geo.r_g,
              (double)c->cfg.alpha, (double)c->cfg.sigma);
    }
    r = fovlp_shade_rows(c, 0, rows, lp_shade, NULL, e->rgb, e->sdep, &shaded);
    for (i = 0; i < n2; ++i)
        if (s[i].slot < e->nslots &&
            !(e->rgb[3u * s[i].slot] >= 0.05f && e->rgb[3u * s[i].slot] <= 0.95f)) badv++;
    check(r == FOV_OK && shaded == n && canary_ok(e->rgb, 3u * e->nslots) &&
              canary_ok(e->sdep, e->nslots) && badv == 0,
          N("%s_shade", tag), "r %d shaded %llu of %zu, %zu bad", (int)r, (unsigned long long)shaded, n, badv);
    free(s);
    r = fovlp_reconstruct_rows(c, e->rgb, e->sdep, 0, H, img, 0, dep);
    /* reconstruction interpolates shaded colours (convex weights): inside [0.05, 0.95] */
    check(r == FOV_OK && canary_ok(img, 3u * W * H) && canary_ok(dep, (size_t)W * H),
          N("%s_reconstruct", tag), "r %d", (int)r);
    check(count_bad(img, 3u * (size_t)W * H, 0.049f, 0.951f) == 0, N("%s_reconstruct_range", tag),
          "%zu of %u values NaN, unwritten or outside the shaded range", count_bad(img, 3u * (size_t)W * H, 0.049f, 0.951f), 3u * W * H);
    check(count_bad(dep, (size_t)W * H, 0.99f, 3.01f) == 0, N("%s_reconstruct_depth", tag),
          "%zu depths outside [1, 3]", count_bad(dep, (size_t)W * H, 0.99f, 3.01f));
    /* the same image from odd tiles in reverse order (threads may split it any way) */
    {
        float *img2 = img_alloc(3u * W * H), *dep2 = img_alloc((size_t)W * H);
        uint32_t tx, ty, tw = W / 3u + 1u, th = H / 2u + 1u, diff = 0;
        size_t q;
        r = FOV_OK;
        for (ty = H; ty-- > 0 && r == FOV_OK;)
            if (ty % th == 0)
                for (tx = W; tx-- > 0 && r == FOV_OK;)
                    if (tx % tw == 0)
                        r = fovlp_reconstruct_tile(c, e->rgb, e->sdep, tx, ty,
                                                   tx + tw < W ? tx + tw : W,
                                                   ty + th < H ? ty + th : H, img2, 0, dep2);
        for (q = 0; q < 3u * (size_t)W * H; ++q) diff += memcmp(&img[q], &img2[q], sizeof(float)) != 0;
        for (q = 0; q < (size_t)W * H; ++q) diff += memcmp(&dep[q], &dep2[q], sizeof(float)) != 0;
        check(r == FOV_OK && diff == 0 && canary_ok(img2, 3u * W * H), N("%s_tiles_equal_rows", tag), "r %d, %u values differ", (int)r, diff);
        free(img2); free(dep2);
    }
    /* a constant scene reconstructs to that constant everywhere (renormalised convex weights:
       an unshaded slot mixed in would pull a pixel down) */
    r = fovlp_shade_rows(c, 0, rows, lp_shade_const, NULL, e->rgb, e->sdep, NULL);
    if (r == FOV_OK) r = fovlp_reconstruct_rows(c, e->rgb, e->sdep, 0, H, img, 0, dep);
    check(r == FOV_OK && count_bad(img, 3u * (size_t)W * H, 0.8f - 1e-5f, 0.8f + 1e-5f) == 0 &&
              count_bad(dep, (size_t)W * H, 2.0f, 2.0f) == 0,
          N("%s_reconstruct_constant", tag), "r %d: %zu values differ from the constant 0.8, %zu depths from 2", (int)r,
          count_bad(img, 3u * (size_t)W * H, 0.8f - 1e-5f, 0.8f + 1e-5f), count_bad(dep, (size_t)W * H, 2.0f, 2.0f));
}

static const uint32_t g_sizes[][2] = { { 1, 1 }, { 2, 1 }, { 1, 3 }, { 7, 13 }, { 33, 31 }, { 97, 5 } };
#define NSIZES (sizeof g_sizes / sizeof g_sizes[0])

static void case_lp_sizes(void)
{
    uint32_t p, si, k;
    for (p = 0; p < 4; ++p)
        for (si = 0; si < NSIZES; ++si) {
            uint32_t W = g_sizes[si][0], H = g_sizes[si][1];
            fovlp_config cfg = fovlp_config_preset(p, W, H);
            lp_env e;
            fov_result r = lp_open(&e, &cfg);
            float *img, *dep;
            if (!check(r == FOV_OK, N("lp_init_%s_%ux%u", fovlp_preset_name(p), W, H), "r %d", (int)r)) {
                lp_close(&e);
                continue;
            }
            img = img_alloc(3u * W * H);
            dep = img_alloc((size_t)W * H);
            for (k = 0; k < 8; ++k) {
                fov_gaze g;
                switch (k) {
                case 0: g.x = 0.5f * (float)W; g.y = 0.5f * (float)H; break;
                case 1: g.x = 0.0f; g.y = 0.0f; break;
                case 2: g.x = (float)W; g.y = (float)H; break;                 /* the far corner */
                case 3: g.x = -1e30f; g.y = 1e30f; break;                        /* far off-screen */
                case 4: g.x = 3.0e38f; g.y = -3.0e38f; break;
                case 5: g.x = (float)W + 0.25f; g.y = -0.25f; break;
                default: g.x = frand(-2.0f * (float)W, 3.0f * (float)W); g.y = frand(-2.0f * (float)H, 3.0f * (float)H); break;
                }
                r = fovlp_begin_frame(&e.ctx, g, NULL);
                if (!check(r == FOV_OK, N("lp_begin_%s_%ux%u_g%u", fovlp_preset_name(p), W, H, k), "r %d", (int)r)) continue;
                lp_frame_checks(&e, N("lp_%s_%ux%u_g%u", fovlp_preset_name(p), W, H, k), img, dep);
            }
            free(img); free(dep);
            lp_close(&e);
        }
}

/* TAA on: the jittered sample positions stay on the screen too */
static void case_lp_taa_sizes(void)
{
    uint32_t p, si, k;
    for (p = 0; p < 4; ++p)
        for (si = 0; si < NSIZES; ++si) {
            uint32_t W = g_sizes[si][0], H = g_sizes[si][1];
            fovlp_config cfg = fovlp_config_preset(p, W, H);
            lp_env e;
            float *img, *dep;
            fov_result r;
            cfg.taa.enable = 1;
            r = lp_open(&e, &cfg);
            if (!check(r == FOV_OK, N("lp_taa_init_%u_%ux%u", p, W, H), "r %d", (int)r)) { lp_close(&e); continue; }
            img = img_alloc(3u * W * H);
            dep = img_alloc((size_t)W * H);
            for (k = 0; k < 16; ++k) {
                fov_gaze g;
                g.x = 0.5f * (float)W + 0.01f * (float)k;
                g.y = (float)H - 0.01f * (float)k;
                r = fovlp_begin_frame(&e.ctx, g, NULL);
                if (!check(r == FOV_OK, N("lp_taa_begin_%u_%ux%u_f%u", p, W, H, k), "r %d", (int)r)) continue;
                lp_frame_checks(&e, N("lp_taa_%s_%ux%u_f%u", fovlp_preset_name(p), W, H, k), img, dep);
            }
            free(img); free(dep);
            lp_close(&e);
        }
}

static void case_lp_bad_input(void)
{
    fovlp_config cfg, base = fovlp_config_preset(FOVLP_PRESET_C_FOV, 64, 48);
    tlog t;
    fovlp_ctx ctx;
    size_t bytes = 0, b2;
    unsigned char *mem;
    fov_result r;
    fov_gaze g = { 32.0f, 24.0f }, gn;
    fovlp_camera cam;
    fovlp_geometry geo;
    float u, v, f1[3] = { 0.0f, 0.0f, 0.0f };
    fovlp_counts cnt;
    memset(&cnt, 0, sizeof cnt);
    fovlp_taa_io io;

    /* sizes */
    cfg = base; cfg.width = 0; cfg.logger = mk_logger(&t);
    expect_logged("lp_width0", fovlp_memory_size(&cfg, &bytes), FOV_ERR_INVALID_ARG, &t);
    cfg = base; cfg.height = 0; cfg.logger = mk_logger(&t);
    expect_logged("lp_height0", fovlp_init(&ctx, &cfg, &t, 1), FOV_ERR_INVALID_ARG, &t);
    cfg = base; cfg.width = FOVLP_MAX_DIM + 1u; cfg.logger = mk_logger(&t);
    expect_logged("lp_width_over_cap", fovlp_memory_size(&cfg, &bytes), FOV_ERR_LIMIT, &t);
    cfg = base; cfg.width = 0xFFFFFFFFu; cfg.height = 0xFFFFFFFFu; cfg.logger = mk_logger(&t);
    expect_logged("lp_size_u32max", fovlp_memory_size(&cfg, &bytes), FOV_ERR_LIMIT, &t);
    /* the largest screens: a size or a clean LIMIT, and init agrees with the size query */
    {
        static const uint32_t big[][2] = { { 7680, 4320 }, { 65536, 65536 }, { 65536, 1 }, { 1, 65536 } };
        uint32_t i, p;
        for (i = 0; i < 4; ++i)
            for (p = 0; p < 4; ++p) {
                cfg = fovlp_config_preset(p, big[i][0], big[i][1]);
                r = fovlp_memory_size(&cfg, &bytes);
                check(r == FOV_OK || r == FOV_ERR_LIMIT, N("lp_big_%ux%u_%u_size", big[i][0], big[i][1], p), "r %d", (int)r);
                if (r != FOV_OK) continue;
                mem = (unsigned char *)malloc(bytes);
                r = fovlp_init(&ctx, &cfg, mem, bytes);
                check(r == FOV_OK && ctx.geo.samples >= 1 && ctx.geo.lp_w >= 1 && ctx.geo.lp_h >= 1 &&
                          (uint64_t)ctx.geo.lp_w * ctx.geo.lp_h < ctx.geo.samples + 1ull,
                      N("lp_big_%ux%u_%u_init", big[i][0], big[i][1], p), "r %d", (int)r);
                if (r == FOV_OK) {
                    g.x = -5.0f; g.y = 1e9f;
                    r = fovlp_begin_frame(&ctx, g, NULL);
                    check(r == FOV_OK && fovlp_sample_rows(&ctx) == ctx.geo.lp_h + ctx.geo.disc_h + 1u,
                          N("lp_big_%ux%u_%u_begin", big[i][0], big[i][1], p), "r %d", (int)r);
                }
                free(mem);
            }
    }
    /* memory: one byte short, NULL, misaligned */
    cfg = base;
    r = fovlp_memory_size(&cfg, &bytes);
    check(r == FOV_OK && bytes > 0, "lp_mem_size", "r %d", (int)r);
    mem = (unsigned char *)malloc(bytes + 8);
    cfg.logger = mk_logger(&t);
    expect_logged("lp_mem_one_short", fovlp_init(&ctx, &cfg, mem, bytes - 1), FOV_ERR_TOO_SMALL, &t);
    cfg.logger = mk_logger(&t);
    expect_logged("lp_mem_null", fovlp_init(&ctx, &cfg, NULL, bytes), FOV_ERR_NULL, &t);
    {
        int off, ok = 1;
        for (off = 1; off < 8; ++off) {
            float *img = img_alloc(3u * 64 * 48), *dep = img_alloc(64 * 48);
            lp_env e;
            unsigned char *m2 = (unsigned char *)malloc(bytes + (size_t)off);
            r = fovlp_init(&ctx, &base, m2 + off, bytes);
            g.x = 10.0f; g.y = 40.0f;
            if (r == FOV_OK) r = fovlp_begin_frame(&ctx, g, NULL);
            ok &= r == FOV_OK;
            if (r == FOV_OK) {
                memset(&e, 0, sizeof e);
                e.ctx = ctx;
                e.nslots = ctx.geo.samples;
                e.rgb = img_alloc(3u * e.nslots);
                e.sdep = img_alloc(e.nslots);
                lp_frame_checks(&e, N("lp_misaligned_%d", off), img, dep);
                free(e.rgb); free(e.sdep);
            }
            free(m2); free(img); free(dep);
        }
        check(ok, "lp_mem_misaligned", "init or begin_frame failed on a misaligned block");
    }
    r = fovlp_init(&ctx, &base, mem, bytes);
    check(r == FOV_OK, "lp_init_ok", "r %d", (int)r);
    /* calls before the first begin_frame */
    {
        size_t n = 0;
        check(fovlp_sample_rows(&ctx) == 0, "lp_rows_before_begin", "%u", fovlp_sample_rows(&ctx));
        expect("lp_samples_before_begin", fovlp_samples(&ctx, 0, 0, NULL, 0, &n), FOV_ERR_INVALID_ARG);
        expect("lp_screen_to_lp_before_begin", fovlp_screen_to_lp(&ctx, 1.0f, 1.0f, &u, &v), FOV_ERR_INVALID_ARG);
        expect("lp_reconstruct_before_begin", fovlp_reconstruct_rows(&ctx, f1, NULL, 0, 0, f1, 0, NULL), FOV_ERR_INVALID_ARG);
    }
    /* gaze */
    ctx.cfg.logger = mk_logger(&t);
    gn.x = f_nan(); gn.y = 1.0f;
    expect_logged("lp_gaze_nan", fovlp_begin_frame(&ctx, gn, NULL), FOV_ERR_NOT_FINITE, &t);
    gn.x = 1.0f; gn.y = -f_inf();
    ctx.cfg.logger = mk_logger(&t);
    expect_logged("lp_gaze_inf", fovlp_begin_frame(&ctx, gn, NULL), FOV_ERR_NOT_FINITE, &t);
    gn.x = 1e30f; gn.y = -1e30f;
    ctx.cfg.logger = mk_logger(&t);
    r = fovlp_begin_frame(&ctx, gn, NULL);
    check(r == FOV_OK && t.warnings == 1 && ctx.gaze.x == 64.0f && ctx.gaze.y == 0.0f, "lp_gaze_huge_clamped_warned",
          "r %d warnings %d gaze %g %g", (int)r, t.warnings, (double)ctx.gaze.x, (double)ctx.gaze.y);
    gn.x = f_nan();
    expect("lp_geometry_gaze_nan", fovlp_geometry_get(&base, gn, &geo), FOV_ERR_NOT_FINITE);
    /* camera */
    memset(&cam, 0, sizeof cam);
    cam.right[0] = 1.0f; cam.up[1] = 1.0f; cam.fwd[2] = 1.0f; cam.tan_half_y = 0.5f;
    {
        fovlp_camera c2;
        int i;
        for (i = 0; i < 6; ++i) {
            c2 = cam;
            switch (i) {
            case 0: c2.pos[1] = f_nan(); break;
            case 1: c2.fwd[0] = f_inf(); break;
            case 2: c2.tan_half_y = f_nan(); break;
            case 3: c2.right[0] = 0.0f; break;
            case 4: c2.tan_half_y = 0.0f; break;
            default: c2.tan_half_y = -1.0f; break;
            }
            ctx.cfg.logger = mk_logger(&t);
            g.x = 20.0f; g.y = 20.0f;
            expect_logged(N("lp_camera_bad_%d", i), fovlp_begin_frame(&ctx, g, &c2), i < 3 ? FOV_ERR_NOT_FINITE : FOV_ERR_DEGENERATE, &t);
        }
    }
    /* NULL pointers */
    g.x = 20.0f; g.y = 20.0f;
    r = fovlp_begin_frame(&ctx, g, &cam);
    check(r == FOV_OK, "lp_begin_cam", "r %d", (int)r);
    expect("lp_null_size_cfg", fovlp_memory_size(NULL, &b2), FOV_ERR_NULL);
    expect("lp_null_size_out", fovlp_memory_size(&base, NULL), FOV_ERR_NULL);
    expect("lp_null_init_ctx", fovlp_init(NULL, &base, mem, bytes), FOV_ERR_NULL);
    expect("lp_null_init_cfg", fovlp_init(&ctx, NULL, mem, bytes), FOV_ERR_NULL);
    expect("lp_null_begin", fovlp_begin_frame(NULL, g, NULL), FOV_ERR_NULL);
    expect("lp_null_resolve", fovlp_config_resolve(&base, NULL), FOV_ERR_NULL);
    expect("lp_null_geometry", fovlp_geometry_get(&base, g, NULL), FOV_ERR_NULL);
    expect("lp_null_ecc", fovlp_ecc_init(NULL, NULL, 60.0f, 4, 4, g), FOV_ERR_NULL);
    expect("lp_null_s2lp", fovlp_screen_to_lp(&ctx, 1.0f, 1.0f, NULL, &v), FOV_ERR_NULL);
    expect("lp_null_lp2s", fovlp_lp_to_screen(&ctx, 1.0f, 1.0f, &u, NULL), FOV_ERR_NULL);
    expect("lp_null_spacing", fovlp_spacing(&ctx, 3.0f, NULL, &v), FOV_ERR_NULL);
    expect("lp_null_samples_count", fovlp_samples(&ctx, 0, 1, NULL, 0, NULL), FOV_ERR_NULL);
    expect("lp_null_shade_fn", fovlp_shade_rows(&ctx, 0, 1, NULL, NULL, f1, NULL, NULL), FOV_ERR_NULL);
    expect("lp_null_shade_rgb", fovlp_shade_rows(&ctx, 0, 1, lp_shade, NULL, NULL, NULL, NULL), FOV_ERR_NULL);
    expect("lp_null_count", fovlp_count_samples(&ctx, NULL), FOV_ERR_NULL);
    expect("lp_null_recon_in", fovlp_reconstruct_rows(&ctx, NULL, NULL, 0, 1, f1, 0, NULL), FOV_ERR_NULL);
    expect("lp_null_recon_out", fovlp_reconstruct_rows(&ctx, f1, NULL, 0, 1, NULL, 0, NULL), FOV_ERR_NULL);
    expect("lp_null_recon_ctx", fovlp_reconstruct_rows(NULL, f1, NULL, 0, 1, f1, 0, NULL), FOV_ERR_NULL);
    expect("lp_null_blend", fovlp_blend_rows(&ctx, NULL, 0, 1, f1), FOV_ERR_NULL);
    expect("lp_null_taa_io", fovlp_taa_rows(&ctx, NULL, 0, 1, NULL), FOV_ERR_NULL);
    expect("lp_null_jitter", fovlp_jitter(&base, 0, NULL, &v), FOV_ERR_NULL);
    check(fovlp_sample_rows(NULL) == 0 && !(fovlp_density(NULL, 1.0f, 1.0f) != 0.0f) &&
              fovlp_ecc_deg(NULL, 1.0f, 1.0f) == 0.0f && fovlp_ecc_ppd(NULL) == 0.0f,
          "lp_null_value_functions", "nonzero");
    fovlp_reset_history(NULL);
    check(fovlp_result_string((fov_result)-99) != NULL && fovlp_preset_name(99) != NULL &&
              fovlp_result_string(FOV_ERR_LIMIT) != NULL, "lp_strings_never_null", "NULL");
    /* rows and tiles out of range */
    {
        uint32_t rows = fovlp_sample_rows(&ctx);
        size_t n = 0;
        float *img = img_alloc(3u * 64 * 48);
        expect("lp_rows_over", fovlp_samples(&ctx, 0, rows + 1u, NULL, 0, &n), FOV_ERR_INVALID_ARG);
        expect("lp_rows_reversed", fovlp_samples(&ctx, 2, 1, NULL, 0, &n), FOV_ERR_INVALID_ARG);
        expect("lp_recon_rows_over", fovlp_reconstruct_rows(&ctx, f1, NULL, 0, 49, img, 0, NULL), FOV_ERR_INVALID_ARG);
        expect("lp_recon_tile_x_over", fovlp_reconstruct_tile(&ctx, f1, NULL, 0, 0, 65, 1, img, 0, NULL), FOV_ERR_INVALID_ARG);
        expect("lp_recon_stride_short", fovlp_reconstruct_rows(&ctx, f1, NULL, 0, 1, img, 3u * 64 - 1u, NULL), FOV_ERR_INVALID_ARG);
        expect("lp_blend_alias", fovlp_blend_rows(&ctx, img, 0, 1, img), FOV_ERR_INVALID_ARG);
        expect("lp_blend_rows_over", fovlp_blend_rows(&ctx, img, 0, 49, f1), FOV_ERR_INVALID_ARG);
        memset(&io, 0, sizeof io);
        io.cur_rgb = img; io.out_rgb = img; io.out_age = (uint8_t *)img;
        expect("lp_taa_disabled", fovlp_taa_rows(&ctx, &io, 0, 1, NULL), FOV_ERR_INVALID_ARG);
        check(fovlp_count_samples(&ctx, &cnt) == FOV_OK && cnt.shaded >= 1, "lp_count_ok", "shaded %llu", (unsigned long long)cnt.shaded);
        free(img);
    }
    /* mapping functions with NaN / inf arguments */
    expect("lp_s2lp_nan", fovlp_screen_to_lp(&ctx, f_nan(), 1.0f, &u, &v), FOV_ERR_NOT_FINITE);
    expect("lp_lp2s_inf", fovlp_lp_to_screen(&ctx, 1.0f, f_inf(), &u, &v), FOV_ERR_NOT_FINITE);
    expect("lp_spacing_nan", fovlp_spacing(&ctx, f_nan(), &u, &v), FOV_ERR_NOT_FINITE);
    check(!(fovlp_density(&ctx, f_nan(), 0.0f) != 0.0f), "lp_density_nan_zero", "nonzero");
    r = fovlp_screen_to_lp(&ctx, 3e38f, -3e38f, &u, &v);
    check(r == FOV_OK && isfinite(u) && isfinite(v), "lp_s2lp_3e38_finite", "r %d u %g v %g", (int)r, (double)u, (double)v);
    r = fovlp_lp_to_screen(&ctx, 1e30f, 3.0f, &u, &v);
    check(r == FOV_ERR_LIMIT && isfinite(u) && isfinite(v), "lp_lp2s_huge_limit", "r %d x %g y %g", (int)r, (double)u, (double)v);
    r = fovlp_screen_to_lp(&ctx, 1e6f, -1e6f, &u, &v);
    check(r == FOV_OK && isfinite(u) && isfinite(v), "lp_s2lp_far_finite", "r %d u %g v %g", (int)r, (double)u, (double)v);
    free(mem);
}

/* every config field out of range: a documented code, logged with a message */
static void case_lp_config(void)
{
    fovlp_config c;
    fovlp_ctx ctx;
    size_t bytes;
    tlog t;
    int i;
    for (i = 0; i < 27; ++i) {
        fov_result want = FOV_ERR_INVALID_ARG, r;
        c = fovlp_config_preset(FOVLP_PRESET_C_K_FOV, 40, 30);
        switch (i) {
        case 0: c.sigma = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 1: c.sigma = -1.0f; break;
        case 2: c.sigma = 1e-6f; want = FOV_ERR_LIMIT; break;
        case 3: c.alpha = 17.0f; break;
        case 4: c.alpha = f_inf(); want = FOV_ERR_NOT_FINITE; break;
        case 5: c.gaze_angle = 1.5f; break;
        case 6: c.no_disc = 2; break;
        case 7: c.lp_aspect = 1e9f; break;
        case 8: c.match_deg = 90.0f; break;
        case 9: c.norm = 2; break;
        case 10: c.edge = 0x7FFFFFFFu; break;
        case 11: c.cam_fov_y_deg = 180.0f; break;
        case 12: c.display.fov_y_deg = -10.0f; break;
        case 13: c.display.fov_y_deg = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 14: c.display.pixel_pitch_mm = 0.25f; break;      /* distance missing */
        case 15: c.display.axis_dx = f_inf(); want = FOV_ERR_NOT_FINITE; break;
        case 16: c.blend = 3; break;
        case 17: c.blend_start = 0.6f; c.blend_end = 0.5f; break;
        case 18: c.taa.enable = 2; break;
        case 19: c.taa.phases = 257; break;
        case 20: c.taa.max_age = 256; break;
        case 21: c.taa.clamp = 3; break;
        case 22: c.taa.depth_tol = -1.0f; break;
        case 23: c.taa.periphery = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 24: c.display.fov_y_deg = 180.0f; break;
        case 25: c.display.pixel_pitch_mm = -0.2f; c.display.distance_mm = 500.0f; break;
        default: c.gaze_angle = 1.4f; c.display.fov_y_deg = 10.0f; break;   /* disc covers the screen */
        }
        c.logger = mk_logger(&t);
        r = fovlp_memory_size(&c, &bytes);
        expect_logged(N("lp_config_%d", i), r, want, &t);
        c.logger = mk_logger(&t);
        r = fovlp_init(&ctx, &c, &t, sizeof t);
        check(r == want, N("lp_config_%d_init", i), "got %d want %d", (int)r, (int)want);
    }
    /* an unknown preset gives the defaults */
    c = fovlp_config_preset(1234, 16, 16);
    {
        fovlp_config d = fovlp_config_default();
        d.width = d.height = 16;
        /* field by field (the struct has padding) */
        check(c.width == 16 && c.height == 16 && c.sigma == d.sigma && c.alpha == d.alpha && c.gaze_angle == d.gaze_angle &&
                  c.no_disc == d.no_disc && c.lp_aspect == d.lp_aspect && c.match_deg == d.match_deg && c.norm == d.norm &&
                  c.edge == d.edge && c.taa.phases == d.taa.phases && c.blend_end == d.blend_end,
              "lp_preset_unknown_defaults", "differs");
    }
}

/* TAA: NaN / inf / negative / huge depths, camera jumps and spins, degenerate bases */
static void case_lp_taa(void)
{
    const uint32_t W = 37, H = 23;
    uint32_t clamp, f;
    for (clamp = 0; clamp < 3; ++clamp) {
        fovlp_config cfg = fovlp_config_preset(FOVLP_PRESET_C_FOV, W, H);
        lp_env e;
        float *cur = img_alloc(3u * W * H), *cd = img_alloc((size_t)W * H);
        float *hr[2], *hd[2];
        uint8_t *ha[2];
        fovlp_camera cam;
        fovlp_taa_io io;
        fov_result r;
        size_t badn = 0, nanin = 0;
        int ok = 1;
        cfg.taa.enable = 1;
        cfg.taa.clamp = clamp;
        hr[0] = img_alloc(3u * W * H); hr[1] = img_alloc(3u * W * H);
        hd[0] = img_alloc((size_t)W * H); hd[1] = img_alloc((size_t)W * H);
        ha[0] = (uint8_t *)calloc((size_t)W * H + CANARY, 1); ha[1] = (uint8_t *)calloc((size_t)W * H + CANARY, 1);
        r = lp_open(&e, &cfg);
        if (!check(r == FOV_OK, N("lp_taa_open_%u", clamp), "r %d", (int)r)) continue;
        memset(&cam, 0, sizeof cam);
        cam.right[0] = 1.0f; cam.up[1] = 1.0f; cam.fwd[2] = 1.0f; cam.tan_half_y = 0.4f;
        for (f = 0; f < 24; ++f) {
            fov_gaze g;
            uint32_t i, rows, a = f & 1u, b = a ^ 1u;
            fovlp_taa_stats st;
            g.x = (f % 5u == 4u) ? 1e20f : frand(0.0f, (float)W);
            g.y = frand(-1.0f, (float)H + 1.0f);
            /* camera: small moves, jumps of 1e6, a spin of 180 degrees, parallel right/up */
            if (f % 4u == 1u) cam.pos[0] += 0.05f;
            if (f == 7u) cam.pos[2] += 1e6f;
            if (f == 11u) { cam.fwd[2] = -1.0f; cam.right[0] = -1.0f; }
            if (f == 15u) { cam.up[0] = 1.0f; cam.up[1] = 0.0f; }  /* up parallel to right */
            if (f == 19u) { cam.up[0] = 0.0f; cam.up[1] = 1.0f; cam.tan_half_y = 1e6f; }
            r = fovlp_begin_frame(&e.ctx, g, &cam);
            if (!(r == FOV_OK)) { ok = 0; continue; }
            rows = fovlp_sample_rows(&e.ctx);
            r = fovlp_shade_rows(&e.ctx, 0, rows, lp_shade, NULL, e.rgb, e.sdep, NULL);
            /* hostile depths in the sample buffer: NaN, inf, negative, zero, huge */
            for (i = 0; i < e.nslots; i += 7u) {
                static const float vals[5] = { 0.0f, -1.0f, 1e30f, 3.0e38f, 1e-30f };
                e.sdep[i] = (i / 7u) % 6u == 5u ? f_nan() : ((i / 7u) % 6u == 4u ? f_inf() : vals[(i / 7u) % 5u]);
            }
            if (r == FOV_OK) r = fovlp_reconstruct_rows(&e.ctx, e.rgb, e.sdep, 0, H, cur, 0, cd);
            /* and in the previous depth */
            for (i = 0; i < W * H; i += 5u) hd[b][i] = (i % 2u) ? f_nan() : -f_inf();
            memset(&io, 0, sizeof io);
            io.cur_rgb = cur; io.cur_depth = cd;
            io.prev_rgb = hr[b]; io.prev_depth = hd[b]; io.prev_age = ha[b];
            io.out_rgb = hr[a]; io.out_depth = hd[a]; io.out_age = ha[a];
            memset(&st, 0, sizeof st);
            if (r == FOV_OK) r = fovlp_taa_rows(&e.ctx, &io, 0, H, &st);
            if (r != FOV_OK) { ok = 0; continue; }
            nanin += count_bad(cur, 3u * W * H, 0.049f, 0.951f);
            badn += count_bad(hr[a], 3u * W * H, clamp == 0 ? 0.049f : -0.5f, clamp == 0 ? 0.951f : 1.5f);
            for (i = 0; i < W * H; ++i)
                if (ha[a][i] < 1u || ha[a][i] > 20u) badn++;
            if (!canary_ok(hr[a], 3u * W * H) || !canary_ok(hd[a], (size_t)W * H) || !canary_ok(cur, 3u * W * H)) badn++;
        }
        check(ok, N("lp_taa_hostile_%u_calls", clamp), "a call failed");
        check(nanin == 0, N("lp_taa_hostile_%u_reconstruct_range", clamp), "%zu bad values", nanin);
        check(badn == 0, N("lp_taa_hostile_%u_output", clamp), "%zu NaN / out-of-range values or ages", badn);
        lp_close(&e);
        free(cur); free(cd); free(hr[0]); free(hr[1]); free(hd[0]); free(hd[1]); free(ha[0]); free(ha[1]);
    }
}

/* ======================================================================================== */
/* fovpt                                                                                     */
/* ======================================================================================== */

typedef struct pt_env {
    fovpt_scene scene;
    void *smem, *cmem;
    fovpt_ctx ctx;
} pt_env;

static fov_result pt_build(pt_env *e, const fovpt_scene_desc *d)
{
    size_t sb = 0;
    fov_result r = fovpt_scene_size(d, &sb);
    memset(e, 0, sizeof *e);
    if (r != FOV_OK) return r;
    e->smem = malloc(sb ? sb : 1);
    return fovpt_scene_build(&e->scene, d, e->smem, sb);
}
static fov_result pt_init(pt_env *e, const fovpt_config *cfg, const fovpt_camera *cam, fov_gaze g)
{
    size_t cb = 0;
    fov_result r = fovpt_memory_size(cfg, cam, &cb);
    if (r != FOV_OK) return r;
    e->cmem = malloc(cb ? cb : 1);
    return fovpt_init(&e->ctx, cfg, &e->scene, cam, g, e->cmem, cb);
}
static void pt_free(pt_env *e) { free(e->smem); free(e->cmem); memset(e, 0, sizeof *e); }

/* renders a frame (or two, for the temporal options) and checks the image */
static void pt_render_check(pt_env *e, const char *tag_in, float lo, float hi)
{
    char tag[160];
    uint32_t W = e->ctx.cam.width, H = e->ctx.cam.height, f;
    float *img = img_alloc(3u * W * H);
    uint8_t *img8 = (uint8_t *)malloc(3u * W * H + CANARY);
    fovpt_output out;
    fovpt_stats st;
    fov_result r = FOV_OK;
    snprintf(tag, sizeof tag, "%s", tag_in);
    memset(img8 + 3u * W * H, 0xA5, CANARY);
    fovpt_output_init(&out);
    out.rgb = img;
    out.rgb8 = img8;
    memset(&st, 0, sizeof st);
    for (f = 0; f < 2 && r == FOV_OK; ++f) {
        if (f) r = fovpt_set_view(&e->ctx, &e->ctx.cam, e->ctx.gaze);
        if (r == FOV_OK) r = fovpt_render(&e->ctx, f, &out, &st);
    }
    check(r == FOV_OK && canary_ok(img, 3u * W * H), N("%s_render", tag), "r %d (%s)", (int)r, fovpt_result_string(r));
    {
        size_t k, bad8 = 0;
        for (k = 0; k < CANARY; ++k) bad8 += img8[3u * W * H + k] != 0xA5;
        check(bad8 == 0, N("%s_rgb8_canary", tag), "%zu bytes past the 8-bit image written", bad8);
    }
    check(count_bad(img, 3u * W * H, lo, hi) == 0, N("%s_pixels", tag), "%zu of %u values NaN, unwritten or outside [%g, %g]",
          count_bad(img, 3u * W * H, lo, hi), 3u * W * H, (double)lo, (double)hi);
    free(img); free(img8);
}

static fovpt_scene_desc pt_desc(fovpt_material *mats, uint32_t nm)
{
    fovpt_scene_desc d;
    fovpt_scene_desc_init(&d);
    d.materials = mats;
    d.num_materials = nm;
    return d;
}

/* every method at odd sizes with gazes on, at the corner and far off the screen */
static void case_pt_sizes(void)
{
    fovpt_material mats[2];
    fovpt_shape sh[3];
    fovpt_scene_desc d;
    pt_env e;
    uint32_t m, si, k, tmp;
    float lo[3] = { -50, -1, -50 }, hi[3] = { 50, 0, 50 };
    fovpt_material_init(&mats[0]);
    fovpt_material_init(&mats[1]);
    mats[1].emission[0] = mats[1].emission[1] = mats[1].emission[2] = 3.0f;
    fovpt_shape_sphere(&sh[0], 0.0f, 0.5f, 0.0f, 0.7f, 0);
    fovpt_shape_sphere(&sh[1], 1.0f, 3.0f, -1.0f, 0.5f, 1);
    fovpt_shape_box(&sh[2], lo, hi, 0);
    d = pt_desc(mats, 2);
    d.shapes = sh; d.num_shapes = 3;
    d.background[0] = d.background[1] = d.background[2] = 0.2f;
    if (!check(pt_build(&e, &d) == FOV_OK, "pt_sizes_scene", "build failed")) return;
    for (m = 0; m < (uint32_t)_FOVPT_METHOD_NUM; ++m)
        for (si = 0; si < NSIZES; ++si)
            for (k = 0; k < 4; ++k) {
                uint32_t W = g_sizes[si][0], H = g_sizes[si][1];
                fovpt_config cfg = fovpt_config_default();
                fovpt_camera cam;
                fov_gaze g;
                fov_result r;
                const char *tag;
                fovpt_camera_init(&cam, W, H);
                cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
                cam.pos[1] = 1.0f; cam.pos[2] = -4.0f; cam.target[1] = 0.5f;
                cfg.method = m;
                cfg.max_depth = 3;
                if (m >= FOVPT_METHOD_SELECTIVE && k == 3) { cfg.temporal.reuse = 1; cfg.temporal.smooth = 1; }
                switch (k) {
                case 0: g.x = 0.5f * (float)W; g.y = 0.5f * (float)H; break;
                case 1: g.x = (float)W; g.y = (float)H; break;
                case 2: g.x = -3e38f; g.y = 1e30f; break;   /* any finite gaze is valid */
                default: g.x = -3.0f * (float)W; g.y = 0.25f; break;
                }
                tag = N("pt_%s_%ux%u_g%u", fovpt_method_name(m), W, H, k);
                {
                    char t2[256];
                    snprintf(t2, sizeof t2, "%s", tag);
                    r = pt_init(&e, &cfg, &cam, g);
                    /* a finite gaze may lie off-screen (shared block): init succeeds */
                    if (check(r == FOV_OK, N("%s_init", t2), "r %d (%s)", (int)r, fovpt_result_string(r)))
                        pt_render_check(&e, t2, 0.0f, 1e4f);
                }
                free(e.cmem); e.cmem = NULL;
                tmp = 0; (void)tmp;
            }
    pt_free(&e);
}

static void case_pt_scenes(void)
{
    fovpt_material mats[3];
    fovpt_scene_desc d;
    fovpt_shape sh[4];
    pt_env e;
    fov_result r;
    tlog t;
    fovpt_camera cam;
    fovpt_config cfg = fovpt_config_default();
    fov_gaze g = { 8.0f, 6.0f };
    fovpt_material_init(&mats[0]);
    fovpt_material_init(&mats[1]);
    mats[1].emission[0] = 2.0f; mats[1].emission[1] = 1.0f; mats[1].emission[2] = 0.5f;
    fovpt_material_init(&mats[2]);
    mats[2].type = FOVPT_MAT_DIELECTRIC;
    fovpt_camera_init(&cam, 16, 12);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -5.0f;

    /* zero primitives: the background everywhere (an independent expectation), for every
       method (the Catmull-Rom, Lanczos and bilinear fills of a constant are that constant),
       mode, odd sizes and gazes off the screen */
    d = pt_desc(mats, 1);
    d.background[0] = 0.25f; d.background[1] = 0.5f; d.background[2] = 0.75f;
    r = pt_build(&e, &d);
    check(r == FOV_OK && e.scene.num_prims == 0, "pt_empty_scene", "r %d", (int)r);
    {
        uint32_t m, si, k;
        for (m = 0; m < (uint32_t)_FOVPT_METHOD_NUM && r == FOV_OK; ++m)
            for (si = 0; si < NSIZES; ++si)
                for (k = 0; k < 3; ++k) {
                    uint32_t W = g_sizes[si][0], H = g_sizes[si][1];
                    fovpt_config c2 = fovpt_config_default();
                    fovpt_camera cm;
                    fov_gaze gz;
                    float *img = img_alloc(3u * W * H);
                    fovpt_output out;
                    size_t i, bad = 0;
                    fov_result r2;
                    c2.method = m;
                    c2.mode = k == 1 ? 1u : 0u;
                    /* no occlusion mask: every pixel belongs to some layer */
                    if (m == FOVPT_METHOD_LAYERS) { fovpt_layers_preset(&c2.layers, FOVPT_LAYERS_KTH_RADIUS); c2.layers.layer[0].radius_deg = 0.0f; }
                    fovpt_camera_init(&cm, W, H);
                    cm.target[2] = 1.0f; /* fovpt_camera_init's former default target */
                    cm.pos[2] = -5.0f;
                    gz.x = k == 0 ? 0.5f * (float)W : -1e4f;
                    gz.y = k == 2 ? 1e6f : 0.5f * (float)H;
                    free(e.cmem); e.cmem = NULL;
                    r2 = pt_init(&e, &c2, &cm, gz);
                    fovpt_output_init(&out);
                    out.rgb = img;
                    if (r2 == FOV_OK) r2 = fovpt_render(&e.ctx, 0, &out, NULL);
                    for (i = 0; i < (size_t)W * H; ++i)
                        bad += fabsf(img[3 * i] - 0.25f) > 1e-5f || fabsf(img[3 * i + 1] - 0.5f) > 1e-5f ||
                               fabsf(img[3 * i + 2] - 0.75f) > 1e-5f || img[3 * i] != img[3 * i];
                    check(r2 == FOV_OK && bad == 0 && canary_ok(img, 3u * W * H),
                          N("pt_empty_scene_background_%s_%ux%u_%u", fovpt_method_name(m), W, H, k),
                          "r %d, %zu of %u pixels differ from the background", (int)r2, bad, W * H);
                    free(img);
                }
    }
    pt_free(&e);

    /* only emitters, every mode and method */
    {
        uint32_t mode, m;
        fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 1);
        fovpt_shape_sphere(&sh[1], 0.0f, 0.0f, 0.0f, 0.5f, 1);       /* nested, same centre */
        {
            float p0[3] = { -1, -1, 2 }, u0[3] = { 2, 0, 0 }, v0[3] = { 0, 2, 0 };
            fovpt_shape_quad(&sh[2], p0, u0, v0, 1);
        }
        d = pt_desc(mats, 2);
        d.shapes = sh; d.num_shapes = 3;
        r = pt_build(&e, &d);
        check(r == FOV_OK && e.scene.num_lights == 3, "pt_only_emitters_build", "r %d lights %u", (int)r, e.scene.num_lights);
        for (mode = 0; mode < 2 && r == FOV_OK; ++mode)
            for (m = 0; m < (uint32_t)_FOVPT_METHOD_NUM; ++m) {
                fovpt_config c2 = fovpt_config_default();
                c2.mode = mode; c2.method = m;
                free(e.cmem); e.cmem = NULL;
                if (check(pt_init(&e, &c2, &cam, g) == FOV_OK, N("pt_only_emitters_%u_%u_init", mode, m), "init"))
                    pt_render_check(&e, N("pt_only_emitters_%u_%s", mode, fovpt_method_name(m)), 0.0f, 1e4f);
            }
        pt_free(&e);
    }

    /* degenerate triangles */
    {
        float v[18] = { 0, 0, 0, 1, 1, 1, 2, 2, 2,            /* collinear */
                        5, 5, 5, 5, 5, 5, 5, 5, 5 };          /* a point */
        fovpt_mesh mesh;
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = v; mesh.num_vertices = 6; mesh.num_triangles = 2;
        d = pt_desc(mats, 2);
        d.meshes = &mesh; d.num_meshes = 1;
        d.logger = mk_logger(&t);
        r = pt_build(&e, &d);
        expect_logged("pt_degenerate_tris", r, FOV_ERR_DEGENERATE, &t);
        pt_free(&e);
        d.skip_degenerate = 1;
        r = pt_build(&e, &d);
        check(r == FOV_OK && e.scene.num_skipped == 2 && e.scene.num_prims == 0, "pt_degenerate_tris_skipped",
              "r %d skipped %u prims %u", (int)r, e.scene.num_skipped, e.scene.num_prims);
        if (r == FOV_OK && check(pt_init(&e, &cfg, &cam, g) == FOV_OK, "pt_degenerate_skipped_init", "init"))
            pt_render_check(&e, "pt_degenerate_skipped", 0.0f, 0.0f);
        pt_free(&e);
        /* emissive degenerate: a zero-area light */
        mesh.material = 1;
        d.skip_degenerate = 0;
        d.logger = mk_logger(&t);
        expect_logged("pt_degenerate_light", pt_build(&e, &d), FOV_ERR_DEGENERATE, &t);
        pt_free(&e);
        /* NaN vertex, index out of range, NULL positions, material out of range */
        v[4] = f_nan();
        mesh.material = 0;
        d.logger = mk_logger(&t);
        expect_logged("pt_nan_vertex", pt_build(&e, &d), FOV_ERR_NOT_FINITE, &t);
        pt_free(&e);
        v[4] = 1.0f;
        {
            uint32_t idx[3] = { 0, 1, 6 };
            mesh.indices = idx; mesh.num_triangles = 1;
            d.logger = mk_logger(&t);
            expect_logged("pt_index_out_of_range", pt_build(&e, &d), FOV_ERR_INVALID_ARG, &t);
            pt_free(&e);
            mesh.indices = NULL;
        }
        mesh.positions = NULL;
        d.logger = mk_logger(&t);
        expect_logged("pt_mesh_null_positions", pt_build(&e, &d), FOV_ERR_NULL, &t);
        pt_free(&e);
        mesh.positions = v; mesh.material = 7;
        d.logger = mk_logger(&t);
        expect_logged("pt_mesh_material_range", pt_build(&e, &d), FOV_ERR_INVALID_ARG, &t);
        pt_free(&e);
        mesh.material = 0; mesh.num_triangles = 3;     /* 9 vertices needed, 6 given */
        d.logger = mk_logger(&t);
        expect_logged("pt_mesh_too_few_vertices", pt_build(&e, &d), FOV_ERR_INVALID_ARG, &t);
        pt_free(&e);
    }

    /* shapes: bad types and values */
    {
        int i;
        for (i = 0; i < 9; ++i) {
            fov_result want = FOV_ERR_DEGENERATE;
            fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 0);
            switch (i) {
            case 0: sh[0].r = 0.0f; break;
            case 1: sh[0].r = -1.0f; break;
            case 2: sh[0].p[1] = f_nan(); want = FOV_ERR_NOT_FINITE; break;
            case 3: sh[0].type = 77; want = FOV_ERR_INVALID_ARG; break;
            case 4: sh[0].material = 3; want = FOV_ERR_INVALID_ARG; break;
            case 5: { float p0[3] = { 0, 0, 0 }, n0[3] = { 0, 0, 0 }; fovpt_shape_plane(&sh[0], p0, n0, 0); break; }
            case 6: { float p0[3] = { 0, 0, 0 }, u0[3] = { 1, 0, 0 }; fovpt_shape_quad(&sh[0], p0, u0, u0, 0); break; }
            case 7: { float a0[3] = { 1, 1, 1 }, b0[3] = { 0, 2, 2 }; fovpt_shape_box(&sh[0], a0, b0, 0); break; }
            default: { float a0[3] = { 1, 1, 1 }, b0[3] = { 1, 1, 2 }; fovpt_shape_box(&sh[0], a0, b0, 0); break; }
            }
            d = pt_desc(mats, 3);
            d.shapes = sh; d.num_shapes = 1;
            d.logger = mk_logger(&t);
            expect_logged(N("pt_shape_bad_%d", i), pt_build(&e, &d), want, &t);
            pt_free(&e);
        }
    }
    /* materials out of range */
    {
        int i;
        for (i = 0; i < 6; ++i) {
            fovpt_material mb = mats[0];
            fov_result want = FOV_ERR_INVALID_ARG;
            switch (i) {
            case 0: mb.type = 9; break;
            case 1: mb.albedo[1] = 1.5f; break;
            case 2: mb.emission[2] = -1.0f; break;
            case 3: mb.exponent = f_nan(); want = FOV_ERR_NOT_FINITE; break;
            case 4: mb.type = FOVPT_MAT_DIELECTRIC; mb.ior = 0.0f; break;
            default: mb.emission[0] = f_inf(); want = FOV_ERR_NOT_FINITE; break;
            }
            d = pt_desc(&mb, 1);
            d.logger = mk_logger(&t);
            expect_logged(N("pt_material_bad_%d", i), pt_build(&e, &d), want, &t);
            pt_free(&e);
        }
        d = pt_desc(NULL, 1);
        expect("pt_materials_null", pt_build(&e, &d), FOV_ERR_NULL);
        pt_free(&e);
        d = pt_desc(mats, 0);
        expect("pt_materials_zero", pt_build(&e, &d), FOV_ERR_NULL);
        pt_free(&e);
        d = pt_desc(mats, 1);
        d.num_shapes = 2;
        expect("pt_shapes_null", pt_build(&e, &d), FOV_ERR_NULL);
        pt_free(&e);
        d = pt_desc(mats, 1);
        d.background[1] = f_nan();
        expect("pt_background_nan", pt_build(&e, &d), FOV_ERR_NOT_FINITE);
        pt_free(&e);
        d = pt_desc(mats, 1);
        d.bvh_bins = 1;
        expect("pt_bvh_bins_1", pt_build(&e, &d), FOV_ERR_INVALID_ARG);
        pt_free(&e);
    }
    /* scene memory: one byte short, NULL; build needs no alignment slack beyond 8 bytes */
    {
        size_t sb = 0;
        void *m;
        fovpt_scene s;
        fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 0);
        d = pt_desc(mats, 1);
        d.shapes = sh; d.num_shapes = 1;
        r = fovpt_scene_size(&d, &sb);
        m = malloc(sb + 16);
        d.logger = mk_logger(&t);
        expect_logged("pt_scene_mem_one_short", fovpt_scene_build(&s, &d, m, sb - 1), FOV_ERR_TOO_SMALL, &t);
        expect("pt_scene_mem_null", fovpt_scene_build(&s, &d, NULL, sb), FOV_ERR_NULL);
        expect("pt_scene_null", fovpt_scene_build(NULL, &d, m, sb), FOV_ERR_NULL);
        expect("pt_scene_size_null", fovpt_scene_size(&d, NULL), FOV_ERR_NULL);
        expect("pt_scene_desc_null", fovpt_scene_size(NULL, &sb), FOV_ERR_NULL);
        free(m);
    }
}

/* big coordinates and 100k identical triangles */
static void case_pt_huge(void)
{
    fovpt_material mats[2];
    fovpt_scene_desc d;
    fovpt_shape sh[3];
    pt_env e;
    fov_result r;
    fovpt_camera cam;
    fovpt_config cfg = fovpt_config_default();
    fov_gaze g = { 6.0f, 5.0f };
    fovpt_material_init(&mats[0]);
    fovpt_material_init(&mats[1]);
    mats[1].emission[0] = mats[1].emission[1] = mats[1].emission[2] = 1.0f;
    /* a scene of size 1e15 (well beyond the documented 1e-2 .. 1e3, still finite): no NaN */
    fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 3e15f, 1e15f, 0);
    fovpt_shape_sphere(&sh[1], 2e15f, 2e15f, 2e15f, 5e14f, 1);
    {
        float lo[3] = { -1e15f, -2e15f, -1e15f }, hi[3] = { 1e15f, -1e15f, 8e15f };
        fovpt_shape_box(&sh[2], lo, hi, 0);
    }
    d = pt_desc(mats, 2);
    d.shapes = sh; d.num_shapes = 3;
    r = pt_build(&e, &d);
    check(r == FOV_OK, "pt_big_coords_build", "r %d", (int)r);
    fovpt_camera_init(&cam, 12, 10);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -1e15f;
    if (r == FOV_OK && check(pt_init(&e, &cfg, &cam, g) == FOV_OK, "pt_big_coords_init", "init"))
        pt_render_check(&e, "pt_big_coords", 0.0f, 1e4f);
    pt_free(&e);

    /* 100k identical triangles: a bounded BVH, the same hits as brute force */
    {
        const uint32_t NT = 100000;
        float tri[9] = { -1, -1, 0, 1, -1, 0, 0, 1, 0 };
        float *pos = (float *)malloc(sizeof(float) * 9u * NT);
        fovpt_mesh mesh;
        uint32_t i, agree = 0;
        for (i = 0; i < NT; ++i) memcpy(pos + 9u * i, tri, sizeof tri);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = pos; mesh.num_vertices = 3u * NT; mesh.num_triangles = NT;
        d = pt_desc(mats, 2);
        d.meshes = &mesh; d.num_meshes = 1;
        r = pt_build(&e, &d);
        check(r == FOV_OK && e.scene.bvh_depth <= FOVPT_MAX_BVH_DEPTH && e.scene.num_prims == NT, "pt_100k_identical_build",
              "r %d depth %u prims %u", (int)r, e.scene.bvh_depth, e.scene.num_prims);
        if (r == FOV_OK) {
            for (i = 0; i < 64; ++i) {
                float o[3], dir[3];
                fovpt_hit h1, h2;
                int a, b;
                o[0] = frand(-1.5f, 1.5f); o[1] = frand(-1.5f, 1.5f); o[2] = -3.0f;
                dir[0] = frand(-0.1f, 0.1f); dir[1] = frand(-0.1f, 0.1f); dir[2] = 1.0f;
                a = fovpt_intersect(&e.scene, o, dir, 0.0f, 1e30f, &h1);
                b = fovpt_intersect_brute(&e.scene, o, dir, 0.0f, 1e30f, &h2);
                agree += a == b && (!a || fabsf(h1.t - h2.t) <= 1e-5f * h2.t);
            }
            check(agree == 64, "pt_100k_identical_hits", "%u of 64 rays agree with brute force", agree);
            fovpt_camera_init(&cam, 12, 10);
            cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
            cam.pos[2] = -3.0f;
            if (check(pt_init(&e, &cfg, &cam, g) == FOV_OK, "pt_100k_init", "init"))
                pt_render_check(&e, "pt_100k", 0.0f, 1e4f);
        }
        pt_free(&e);
        /* a depth cap that cannot hold them: a clean LIMIT */
        d.bvh_max_depth = 4;
        r = pt_build(&e, &d);
        expect("pt_100k_depth_cap", r, FOV_ERR_LIMIT);
        pt_free(&e);
        free(pos);
    }
}

static void case_pt_bad_input(void)
{
    fovpt_material mat;
    fovpt_shape sh;
    fovpt_scene_desc d;
    pt_env e;
    fovpt_camera cam, c2;
    fovpt_config cfg = fovpt_config_default(), c;
    fov_gaze g = { 8.0f, 6.0f }, gb;
    size_t bytes = 0;
    fov_result r;
    tlog t;
    int i;
    fovpt_material_init(&mat);
    fovpt_shape_sphere(&sh, 0.0f, 0.0f, 0.0f, 1.0f, 0);
    d = pt_desc(&mat, 1);
    d.shapes = &sh; d.num_shapes = 1;
    if (!check(pt_build(&e, &d) == FOV_OK, "pt_bad_scene", "build")) return;
    fovpt_camera_init(&cam, 16, 12);
    cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
    cam.pos[2] = -4.0f;
    /* cameras */
    for (i = 0; i < 12; ++i) {
        fov_result want = FOV_ERR_INVALID_ARG;
        c2 = cam;
        switch (i) {
        case 0: c2.width = 0; break;
        case 1: c2.height = FOVPT_MAX_DIM + 1u; want = FOV_ERR_LIMIT; break;
        case 2: c2.pos[0] = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 3: c2.fov_y_deg = 180.0f; break;
        case 4: c2.fov_y_deg = -5.0f; break;
        case 5: c2.fov_y_deg = f_inf(); want = FOV_ERR_NOT_FINITE; break;
        case 6: c2.target[0] = c2.pos[0]; c2.target[1] = c2.pos[1]; c2.target[2] = c2.pos[2]; want = FOV_ERR_DEGENERATE; break;
        case 7: c2.up[0] = 0.0f; c2.up[1] = 0.0f; c2.up[2] = 5.0f; want = FOV_ERR_DEGENERATE; break;   /* parallel */
        case 8: c2.target[0] = 0.0f; c2.target[1] = 10.0f; c2.target[2] = -4.0f;
                c2.up[0] = c2.up[1] = c2.up[2] = 0.0f; want = FOV_ERR_DEGENERATE; break;  /* looks up, default up */
        case 9: c2.tan_left = 1.0f; c2.tan_right = -1.0f; c2.tan_top = 1.0f; c2.tan_bottom = 1.0f; break;
        case 10: c2.tan_top = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        default: c2.pos[0] = 3e38f; c2.target[0] = -3e38f; want = FOV_ERR_DEGENERATE; break;   /* fwd overflows */
        }
        c = cfg;
        c.logger = mk_logger(&t);
        r = fovpt_memory_size(&c, &c2, &bytes);
        if (r == FOV_OK) {
            void *m = malloc(bytes ? bytes : 1);
            c.logger = mk_logger(&t);
            r = fovpt_init(&e.ctx, &c, &e.scene, &c2, g, m, bytes);
            free(m);
        }
        expect_logged(N("pt_camera_bad_%d", i), r, want, &t);
    }
    /* camera fov 0 means 60 (documented) */
    c2 = cam; c2.fov_y_deg = 0.0f;
    {
        float o[3], dr[3], o2[3], d2[3];
        r = fovpt_camera_ray(&c2, 3.0f, 2.0f, o, dr);
        c2.fov_y_deg = 60.0f;
        fovpt_camera_ray(&c2, 3.0f, 2.0f, o2, d2);
        check(r == FOV_OK && dr[0] == d2[0] && dr[1] == d2[1] && dr[2] == d2[2], "pt_camera_fov0_is_60", "r %d", (int)r);
        expect("pt_camera_ray_nan", fovpt_camera_ray(&cam, f_nan(), 1.0f, o, dr), FOV_ERR_NOT_FINITE);
        expect("pt_camera_ray_null", fovpt_camera_ray(&cam, 1.0f, 1.0f, NULL, dr), FOV_ERR_NULL);
    }
    /* gazes */
    r = fovpt_memory_size(&cfg, &cam, &bytes);
    e.cmem = malloc(bytes + 16);
    for (i = 0; i < 3; ++i) {
        gb.x = i == 0 ? f_nan() : 1.0f;
        gb.y = i == 1 ? f_inf() : 1.0f;
        if (i == 2) { gb.x = 3.0e38f; gb.y = -3.0e38f; }
        c = cfg;
        c.logger = mk_logger(&t);
        r = fovpt_init(&e.ctx, &c, &e.scene, &cam, gb, e.cmem, bytes);
        if (i < 2) expect_logged(N("pt_gaze_bad_%d", i), r, FOV_ERR_NOT_FINITE, &t);
        else check(r == FOV_OK || r == FOV_ERR_INVALID_ARG || r == FOV_ERR_NOT_FINITE, "pt_gaze_3e38", "r %d", (int)r);
    }
    /* display parameters */
    for (i = 0; i < 5; ++i) {
        fov_result want = FOV_ERR_INVALID_ARG;
        c = cfg;
        switch (i) {
        case 0: c.display.fov_y_deg = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 1: c.display.fov_y_deg = -20.0f; break;
        case 2: c.display.pixel_pitch_mm = -0.3f; c.display.distance_mm = 600.0f; break;
        case 3: c.display.distance_mm = 600.0f; break;
        default: c.display.fov_y_deg = 180.0f; break;
        }
        c.logger = mk_logger(&t);
        r = fovpt_memory_size(&c, &cam, &bytes);
        if (r == FOV_OK) {
            c.logger = mk_logger(&t);
            r = fovpt_init(&e.ctx, &c, &e.scene, &cam, g, e.cmem, bytes);
        }
        expect_logged(N("pt_display_bad_%d", i), r, want, &t);
    }
    /* configs: enums and values */
    for (i = 0; i < 20; ++i) {
        fov_result want = FOV_ERR_INVALID_ARG;
        c = cfg;
        switch (i) {
        case 0: c.method = 5; break;
        case 1: c.mode = 2; break;
        case 2: c.spp = FOVPT_MAX_SPP + 1u; want = FOV_ERR_LIMIT; break;
        case 3: c.max_depth = FOVPT_MAX_BOUNCES + 1u; want = FOV_ERR_LIMIT; break;
        case 4: c.no_nee = 2; break;
        case 5: c.layers.count = 1; break;
        case 6: c.layers.count = FOVPT_MAX_LAYERS + 1u; break;
        case 7: c.layers.layer[1].stride = 0; break;
        case 8: c.layers.layer[2].radius_deg = 50.0f; break;          /* increasing */
        case 9: c.layers.layer[1].radius_deg = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 10: c.layers.layer[0].radius_deg = 1.0f; break;          /* mask inside layer 1 */
        case 11: c.layers.layer[1].spp = 0; break;
        case 12: c.layers.blend_deg = -1.0f; break;
        case 13: c.zones.inner_deg = 40.0f; break;                     /* above middle */
        case 14: c.zones.lanczos_a = 4; break;
        case 15: c.selective.e_deg[2] = 1.0f; break;                  /* not increasing */
        case 16: c.selective.tau[3] = -0.5f; break;
        case 17: c.temporal.n_tpi = 5; break;
        case 18: c.temporal.alpha[2] = 1.5f; break;
        default: c.selective.n_sd[0] = 65; want = FOV_ERR_LIMIT; break;
        }
        c.logger = mk_logger(&t);
        r = fovpt_memory_size(&c, &cam, &bytes);
        expect_logged(N("pt_config_bad_%d", i), r, want, &t);
    }
    /* layer presets */
    {
        fovpt_layers_cfg lc;
        expect("pt_layers_preset_unknown", fovpt_layers_preset(&lc, 7), FOV_ERR_INVALID_ARG);
        expect("pt_layers_preset_null", fovpt_layers_preset(NULL, 0), FOV_ERR_NULL);
    }
    /* memory: one byte short; the largest images give a size or a clean LIMIT */
    {
        uint32_t m;
        for (m = 0; m < (uint32_t)_FOVPT_METHOD_NUM; ++m) {
            void *mem;
            c = cfg;
            c.method = m;
            if (m >= FOVPT_METHOD_SELECTIVE) { c.temporal.reuse = 1; c.temporal.smooth = 1; }
            r = fovpt_memory_size(&c, &cam, &bytes);
            mem = malloc(bytes);
            c.logger = mk_logger(&t);
            expect_logged(N("pt_mem_one_short_%u", m), fovpt_init(&e.ctx, &c, &e.scene, &cam, g, mem, bytes - 1), FOV_ERR_TOO_SMALL, &t);
            free(mem);
            c2 = cam; c2.width = 65536; c2.height = 65536;
            r = fovpt_memory_size(&c, &c2, &bytes);
            check(r == FOV_ERR_LIMIT || (r == FOV_OK && bytes / 65536u / 65536u >= 16u), N("pt_mem_65536sq_%u", m),
                  "r %d bytes %zu", (int)r, bytes);
        }
    }
    /* NULL pointers */
    r = fovpt_memory_size(&cfg, &cam, &bytes);
    expect("pt_null_memsize_cfg", fovpt_memory_size(NULL, &cam, &bytes), FOV_ERR_NULL);
    expect("pt_null_memsize_cam", fovpt_memory_size(&cfg, NULL, &bytes), FOV_ERR_NULL);
    expect("pt_null_memsize_out", fovpt_memory_size(&cfg, &cam, NULL), FOV_ERR_NULL);
    expect("pt_null_init_ctx", fovpt_init(NULL, &cfg, &e.scene, &cam, g, e.cmem, bytes), FOV_ERR_NULL);
    expect("pt_null_init_cfg", fovpt_init(&e.ctx, NULL, &e.scene, &cam, g, e.cmem, bytes), FOV_ERR_NULL);
    expect("pt_null_init_scene", fovpt_init(&e.ctx, &cfg, NULL, &cam, g, e.cmem, bytes), FOV_ERR_NULL);
    expect("pt_null_init_cam", fovpt_init(&e.ctx, &cfg, &e.scene, NULL, g, e.cmem, bytes), FOV_ERR_NULL);
    expect("pt_null_init_mem", fovpt_init(&e.ctx, &cfg, &e.scene, &cam, g, NULL, bytes), FOV_ERR_NULL);
    expect("pt_null_set_view", fovpt_set_view(NULL, &cam, g), FOV_ERR_NULL);
    expect("pt_null_reset", fovpt_reset(NULL), FOV_ERR_NULL);
    expect("pt_null_trace", fovpt_trace_rows(NULL, 0, 0, 1, NULL), FOV_ERR_NULL);
    expect("pt_null_refine", fovpt_refine_rows(NULL, 0, 0, 1, NULL), FOV_ERR_NULL);
    expect("pt_null_resolve_ctx", fovpt_resolve_rows(NULL, 0, 1, NULL), FOV_ERR_NULL);
    expect("pt_null_render", fovpt_render(NULL, 0, NULL, NULL), FOV_ERR_NULL);
    expect("pt_null_resolve_cfg", fovpt_config_resolve(NULL, &c), FOV_ERR_NULL);
    expect("pt_null_ecc", fovpt_ecc_init(NULL, NULL, 60.0f, 4, 4, g), FOV_ERR_NULL);
    expect("pt_null_tau", fovpt_tau_fov(NULL, 1.0f, NULL), FOV_ERR_NULL);
    {
        float o[3] = { 0, 0, -5 }, dr[3] = { 0, 0, 1 }, rgb[3];
        fovpt_hit h;
        fovpt_rng rng;
        fovpt_config rc;
        fovpt_config_resolve(&cfg, &rc);
        fovpt_rng_init(&rng, 1, 2, 3, 4);
        check(fovpt_intersect(NULL, o, dr, 0.0f, 1e30f, &h) == 0 && fovpt_intersect(&e.scene, NULL, dr, 0.0f, 1e30f, &h) == 0 &&
                  fovpt_intersect(&e.scene, o, dr, 0.0f, 1e30f, NULL) == 0 && fovpt_occluded(NULL, o, dr, 0.0f, 1.0f) == 0,
              "pt_null_intersect", "returned a hit");
        dr[0] = f_nan();
        check(fovpt_intersect(&e.scene, o, dr, 0.0f, 1e30f, &h) == 0, "pt_intersect_nan_dir", "hit");
        dr[0] = 0.0f; dr[2] = 0.0f;
        check(fovpt_intersect(&e.scene, o, dr, 0.0f, 1e30f, &h) == 0, "pt_intersect_zero_dir", "hit");
        dr[2] = 1.0f;
        expect("pt_null_radiance_rgb", fovpt_radiance(&e.scene, &rc, o, dr, &rng, NULL, NULL), FOV_ERR_NULL);
        dr[1] = f_inf();
        r = fovpt_radiance(&e.scene, &rc, o, dr, &rng, rgb, NULL);
        check(r == FOV_ERR_NOT_FINITE || (r == FOV_OK && isfinite(rgb[0]) && isfinite(rgb[1]) && isfinite(rgb[2])),
              "pt_radiance_inf_dir", "r %d rgb %g", (int)r, (double)rgb[0]);
    }
    check(fovpt_result_string((fov_result)12345) != NULL && fovpt_method_name(99) != NULL, "pt_strings_never_null", "NULL");
    /* rows out of range, set_view with another size, a render before init */
    r = fovpt_init(&e.ctx, &cfg, &e.scene, &cam, g, e.cmem, bytes);
    check(r == FOV_OK, "pt_init_ok", "r %d", (int)r);
    expect("pt_trace_rows_over", fovpt_trace_rows(&e.ctx, 0, 0, 13, NULL), FOV_ERR_INVALID_ARG);
    expect("pt_trace_rows_reversed", fovpt_trace_rows(&e.ctx, 0, 5, 4, NULL), FOV_ERR_INVALID_ARG);
    c2 = cam; c2.width = 17;
    expect("pt_set_view_size_changed", fovpt_set_view(&e.ctx, &c2, g), FOV_ERR_INVALID_ARG);
    gb.x = f_nan(); gb.y = 0.0f;
    expect("pt_set_view_gaze_nan", fovpt_set_view(&e.ctx, &cam, gb), FOV_ERR_NOT_FINITE);
    c2 = cam; c2.pos[1] = f_nan();
    expect("pt_set_view_cam_nan", fovpt_set_view(&e.ctx, &c2, g), FOV_ERR_NOT_FINITE);
    /* misaligned context memory: a documented error or a correct frame, never UB */
    {
        unsigned char *m = (unsigned char *)malloc(bytes + 8);
        r = fovpt_init(&e.ctx, &cfg, &e.scene, &cam, g, m + 4, bytes);
        check(r == FOV_ERR_INVALID_ARG || r == FOV_OK, "pt_mem_misaligned_init", "r %d", (int)r);
        if (r == FOV_OK) pt_render_check(&e, "pt_mem_misaligned", 0.0f, 1e4f);
        free(m);
    }
    pt_free(&e);
}

/* random but valid configs, odd sizes, random gazes: a documented error or a clean frame */
static void case_pt_fuzz(void)
{
    fovpt_material mats[3];
    fovpt_shape sh[4];
    fovpt_scene_desc d;
    pt_env e;
    int it, fails_init = 0, errs_undoc = 0;
    float lo[3] = { -20, -1.5f, -20 }, hi[3] = { 20, -1, 20 };
    fovpt_material_init(&mats[0]);
    fovpt_material_init(&mats[1]);
    mats[1].emission[0] = mats[1].emission[1] = mats[1].emission[2] = 5.0f;
    fovpt_material_init(&mats[2]);
    mats[2].type = FOVPT_MAT_MIRROR;
    fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 2);
    fovpt_shape_sphere(&sh[1], 2.0f, 2.0f, 1.0f, 0.4f, 1);
    fovpt_shape_box(&sh[2], lo, hi, 0);
    fovpt_shape_sphere(&sh[3], -1.5f, 0.0f, 0.5f, 0.6f, 0);
    d = pt_desc(mats, 3);
    d.shapes = sh; d.num_shapes = 4;
    if (!check(pt_build(&e, &d) == FOV_OK, "pt_fuzz_scene", "build")) return;
    for (it = 0; it < 300; ++it) {
        fovpt_config cfg = fovpt_config_default();
        fovpt_camera cam;
        fov_gaze g;
        fov_result r;
        uint32_t W = 1u + (uint32_t)(urand() * 40.0), H = 1u + (uint32_t)(urand() * 30.0), n;
        char tag[64];
        snprintf(tag, sizeof tag, "pt_fuzz_%d", it);
        fovpt_camera_init(&cam, W, H);
        cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
        cam.pos[0] = frand(-1, 1); cam.pos[1] = frand(0, 2); cam.pos[2] = -5.0f;
        cam.fov_y_deg = frand(1.0f, 179.0f);
        if (it % 5 == 1) {   /* asymmetric frustum, off-axis, some extreme */
            cam.tan_left = frand(-0.5f, 2.0f);
            cam.tan_top = frand(-0.5f, 2.0f); cam.tan_bottom = frand(0.6f, 2.0f);
            /* square pixels: (left + right) / (bottom + top) = W / H (else UNSUPPORTED) */
            cam.tan_right = (cam.tan_bottom + cam.tan_top) * (float)W / (float)H - cam.tan_left;
            if (it % 25 == 1) {
                float big = 1e5f;
                cam.tan_left = cam.tan_right = W >= H ? big : big * (float)W / (float)H;
                cam.tan_top = cam.tan_bottom = W >= H ? big * (float)H / (float)W : big;
            }
        }
        cfg.method = (uint32_t)(urand() * 5.0);
        cfg.mode = it % 7 == 3 ? 1u : 0u;
        cfg.spp = 1u + (uint32_t)(urand() * 2.0);
        cfg.max_depth = 1u + (uint32_t)(urand() * 3.0);
        cfg.seed = (uint32_t)it;
        if (urand() < 0.5) {   /* a random layer table, strides up to 64 */
            uint32_t cnt = 2u + (uint32_t)(urand() * (FOVPT_MAX_LAYERS - 1));
            float rad = frand(40.0f, 170.0f);
            cfg.layers.count = cnt;
            cfg.layers.layer[0].radius_deg = urand() < 0.5 ? 0.0f : rad + 5.0f;
            for (n = 0; n < cnt; ++n) {
                cfg.layers.layer[n].stride = 1u + (uint32_t)(urand() * 64.0);
                cfg.layers.layer[n].spp = 1u + (uint32_t)(urand() * 2.0);
                if (n > 0) { cfg.layers.layer[n].radius_deg = rad; rad *= frand(0.2f, 0.9f); }
            }
            cfg.layers.blend_deg = frand(0.0f, 10.0f);
            cfg.layers.snap = urand() < 0.5 ? 1u : 0u;
            cfg.layers.blend_linear = urand() < 0.5 ? 1u : 0u;
        }
        if (urand() < 0.3) {
            cfg.zones.inner_deg = frand(0.1f, 20.0f);
            cfg.zones.middle_deg = cfg.zones.inner_deg + frand(0.1f, 60.0f);
            cfg.zones.overlap_px = frand(0.0f, 64.0f);
            cfg.zones.lanczos_a = urand() < 0.5 ? 2u : 3u;
        }
        if (cfg.method >= FOVPT_METHOD_SELECTIVE && urand() < 0.5) {
            cfg.temporal.reuse = 1; cfg.temporal.smooth = urand() < 0.5 ? 1u : 0u;
            cfg.temporal.n_tpi = 1u + (uint32_t)(urand() * 4.0);
        }
        if (urand() < 0.3) { cfg.display.fov_y_deg = frand(1.0f, 179.0f); cfg.display.axis_dx = frand(-100, 100); }
        switch (it % 4) {
        case 0: g.x = frand(0.0f, (float)W); g.y = frand(0.0f, (float)H); break;
        case 1: g.x = frand(-1e4f, 1e4f); g.y = frand(-1e4f, 1e4f); break;
        case 2: g.x = (float)W; g.y = 0.0f; break;
        default: g.x = frand(-3.0f * (float)W, 4.0f * (float)W); g.y = frand(-3.0f * (float)H, 4.0f * (float)H); break;
        }
        r = pt_init(&e, &cfg, &cam, g);
        if (r != FOV_OK) {
            fails_init++;
            if (r != FOV_ERR_INVALID_ARG && r != FOV_ERR_LIMIT) errs_undoc++;
            check(0, N("%s_init", tag), "r %d (%s) method %u %ux%u gaze %g %g", (int)r, fovpt_result_string(r), cfg.method, W, H,
                  (double)g.x, (double)g.y);
        } else {
            /* phases row by row, rows in reverse order, against fovpt_render (the frame of a
               fresh context each) */
            {
                float *a = img_alloc(3u * W * H), *b = img_alloc(3u * W * H);
                fovpt_output oa, ob;
                uint32_t y, diff = 0;
                size_t q;
                fovpt_output_init(&oa); oa.rgb = a;
                fovpt_output_init(&ob); ob.rgb = b;
                r = fovpt_render(&e.ctx, 0, &oa, NULL);
                if (r == FOV_OK) r = fovpt_reset(&e.ctx);
                for (y = H; y-- > 0 && r == FOV_OK;) r = fovpt_trace_rows(&e.ctx, 0, y, y + 1u, NULL);
                for (y = H; y-- > 0 && r == FOV_OK;) r = fovpt_refine_rows(&e.ctx, 0, y, y + 1u, NULL);
                for (y = H; y-- > 0 && r == FOV_OK;) r = fovpt_resolve_rows(&e.ctx, y, y + 1u, &ob);
                for (q = 0; q < 3u * (size_t)W * H; ++q) diff += memcmp(&a[q], &b[q], sizeof(float)) != 0;
                check(r == FOV_OK && diff == 0, N("%s_rows_reversed_equal", tag), "r %d, %u values differ", (int)r, diff);
                free(a); free(b);
                r = fovpt_reset(&e.ctx);
            }
            pt_render_check(&e, tag, 0.0f, 1e4f);
            /* the next frame: a moved camera and gaze */
            cam.pos[0] += 0.1f;
            g.x += frand(-5.0f, 5.0f);
            r = fovpt_set_view(&e.ctx, &cam, g);
            if (check(r == FOV_OK, N("%s_set_view", tag), "r %d", (int)r)) pt_render_check(&e, N("%s_f2", tag), 0.0f, 1e4f);
        }
        free(e.cmem); e.cmem = NULL;
    }
    (void)errs_undoc;
    pt_free(&e);
}

/* long frame sequences with the temporal options: teleports, spins, gazes jumping off-screen,
   and extreme but valid materials (Phong exponent 1e6, ior 1e-3 and 99, kd + ks = 2, emission
   1e20) */
static void case_pt_temporal(void)
{
    fovpt_material mats[6];
    fovpt_shape sh[6];
    fovpt_scene_desc d;
    pt_env e;
    uint32_t it;
    float lo[3] = { -10, -2, -10 }, hi[3] = { 10, -1.5f, 10 };
    int i;
    for (i = 0; i < 6; ++i) fovpt_material_init(&mats[i]);
    mats[1].type = FOVPT_MAT_PHONG; mats[1].exponent = 1e6f; mats[1].specular[0] = mats[1].specular[1] = mats[1].specular[2] = 1.0f;
    mats[1].albedo[0] = mats[1].albedo[1] = mats[1].albedo[2] = 1.0f;
    mats[2].type = FOVPT_MAT_DIELECTRIC; mats[2].ior = 1e-3f;
    mats[3].type = FOVPT_MAT_DIELECTRIC; mats[3].ior = 99.0f;
    mats[4].emission[0] = mats[4].emission[1] = mats[4].emission[2] = 1e20f;
    mats[5].type = FOVPT_MAT_MIRROR; mats[5].albedo[0] = mats[5].albedo[1] = mats[5].albedo[2] = 1.0f;
    fovpt_shape_sphere(&sh[0], 0.0f, 0.0f, 0.0f, 1.0f, 1);
    fovpt_shape_sphere(&sh[1], 2.0f, 0.0f, 0.0f, 0.7f, 2);
    fovpt_shape_sphere(&sh[2], -2.0f, 0.0f, 0.0f, 0.7f, 3);
    fovpt_shape_sphere(&sh[3], 0.0f, 3.0f, 0.0f, 1e-3f, 4);
    fovpt_shape_box(&sh[4], lo, hi, 5);
    fovpt_shape_sphere(&sh[5], 0.0f, 0.0f, 3.0f, 1.0f, 0);
    d = pt_desc(mats, 6);
    d.shapes = sh; d.num_shapes = 6;
    if (!check(pt_build(&e, &d) == FOV_OK, "pt_temporal_scene", "build")) return;
    for (it = 0; it < 24; ++it) {
        static const uint32_t sz[4][2] = { { 1, 1 }, { 7, 13 }, { 33, 31 }, { 2, 1 } };
        uint32_t W = sz[it % 4][0], H = sz[it % 4][1], f;
        fovpt_config cfg = fovpt_config_default();
        fovpt_camera cam;
        fov_gaze g;
        fov_result r;
        float *img = img_alloc(3u * W * H);
        fovpt_output out;
        size_t bad = 0;
        int ok = 1;
        char tag[64];
        snprintf(tag, sizeof tag, "pt_temporal_%u", it);
        cfg.method = (it / 4u) % 5u;
        cfg.mode = (it % 3u == 2u) ? 1u : 0u;
        cfg.max_depth = cfg.mode ? 3u : 6u;
        cfg.accumulate = (it % 2u);
        if (cfg.method >= FOVPT_METHOD_SELECTIVE) {
            cfg.temporal.reuse = 1; cfg.temporal.smooth = 1;
            cfg.temporal.n_tpi = 1u + it % 4u;
            cfg.temporal.n_reuse_max = 1u + it % 5u;
        }
        fovpt_camera_init(&cam, W, H);
        cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
        cam.pos[2] = -5.0f;
        g.x = 0.5f * (float)W; g.y = 0.5f * (float)H;
        r = pt_init(&e, &cfg, &cam, g);
        if (!check(r == FOV_OK, N("%s_init", tag), "r %d", (int)r)) { free(img); free(e.cmem); e.cmem = NULL; continue; }
        fovpt_output_init(&out);
        out.rgb = img;
        for (f = 0; f < 12 && ok; ++f) {
            r = fovpt_render(&e.ctx, f, &out, NULL);
            if (r != FOV_OK) { ok = 0; break; }
            bad += count_bad(img, 3u * W * H, 0.0f, 3.0e38f);
            if (!canary_ok(img, 3u * W * H)) bad++;
            /* the next view */
            switch (f % 6u) {
            case 0: cam.pos[0] += 0.05f; break;
            case 1: cam.pos[2] = -1e4f; break;                                   /* teleport */
            case 2: cam.pos[2] = -5.0f; cam.target[2] = -10.0f; break;           /* spin 180 */
            case 3: cam.target[2] = 1.0f; g.x = -1e6f; break;                    /* gaze far off */
            case 4: g.x = (float)W; g.y = (float)H; break;
            default: break;                                                      /* still */
            }
            r = fovpt_set_view(&e.ctx, &cam, g);
            if (r != FOV_OK) ok = 0;
        }
        check(ok, N("%s_calls", tag), "r %d at frame %u", (int)r, f);
        check(bad == 0, N("%s_pixels", tag), "%zu NaN, negative or unwritten values", bad);
        free(img);
        free(e.cmem); e.cmem = NULL;
    }
    pt_free(&e);
}

/* random layer tables and zone settings over an empty scene: every pixel is the background
   (no hole where a layer's lattice is sparse, stride up to 64 on tiny images, gaze anywhere) */
static void case_pt_fill_fuzz(void)
{
    fovpt_material mat;
    fovpt_scene_desc d;
    pt_env e;
    int it;
    fovpt_material_init(&mat);
    d = pt_desc(&mat, 1);
    d.background[0] = 0.25f; d.background[1] = 0.5f; d.background[2] = 0.75f;
    if (!check(pt_build(&e, &d) == FOV_OK, "pt_fill_scene", "build")) return;
    for (it = 0; it < 300; ++it) {
        uint32_t W = 1u + (uint32_t)(urand() * 60.0), H = 1u + (uint32_t)(urand() * 40.0), n;
        fovpt_config cfg = fovpt_config_default();
        fovpt_camera cam;
        fov_gaze g;
        fov_result r;
        float *img = img_alloc(3u * W * H);
        fovpt_output out;
        size_t i, bad = 0, first = 0;
        cfg.method = it % 2 ? FOVPT_METHOD_LAYERS : FOVPT_METHOD_ZONES;
        if (cfg.method == FOVPT_METHOD_LAYERS) {
            uint32_t cnt = 2u + (uint32_t)(urand() * (FOVPT_MAX_LAYERS - 1));
            float rad = frand(5.0f, 170.0f);
            cfg.layers.count = cnt;
            cfg.layers.layer[0].radius_deg = 0.0f;       /* no occlusion mask */
            for (n = 0; n < cnt; ++n) {
                cfg.layers.layer[n].stride = 1u + (uint32_t)(urand() * (urand() < 0.5 ? 64.0 : 6.0));
                /* strides above the image's shorter side with an off-screen gaze once left a
                   layer without lattice points (review finding 1): uncapped */
                cfg.layers.layer[n].spp = 1;
                if (n > 0) { cfg.layers.layer[n].radius_deg = rad; rad *= frand(0.1f, 0.9f); }
            }
            cfg.layers.blend_deg = frand(0.0f, 20.0f);
            cfg.layers.snap = urand() < 0.5 ? 1u : 0u;
            cfg.layers.blend_linear = urand() < 0.5 ? 1u : 0u;
        } else {
            cfg.zones.inner_deg = frand(0.01f, 30.0f);
            cfg.zones.middle_deg = cfg.zones.inner_deg + frand(0.01f, 60.0f);
            cfg.zones.overlap_px = frand(0.0f, 64.0f);
            cfg.zones.lanczos_a = urand() < 0.5 ? 2u : 3u;
        }
        if (urand() < 0.3) cfg.display.fov_y_deg = frand(1.0f, 179.0f);
        fovpt_camera_init(&cam, W, H);
        cam.pos[2] = 0.0f; cam.target[2] = 1.0f; /* fovpt_camera_init's former default view */
        cam.fov_y_deg = frand(1.0f, 179.0f);
        g.x = frand(-2.0f * (float)W, 3.0f * (float)W);
        g.y = frand(-2.0f * (float)H, 3.0f * (float)H);
        r = pt_init(&e, &cfg, &cam, g);
        fovpt_output_init(&out);
        out.rgb = img;
        if (r == FOV_OK) r = fovpt_render(&e.ctx, 0, &out, NULL);
        for (i = 0; i < (size_t)W * H; ++i)
            if (fabsf(img[3 * i] - 0.25f) > 1e-5f || fabsf(img[3 * i + 1] - 0.5f) > 1e-5f || fabsf(img[3 * i + 2] - 0.75f) > 1e-5f ||
                img[3 * i] != img[3 * i]) {
                if (bad == 0) first = i;
                bad++;
            }
        {
            char lay[400];
            size_t o = 0;
            lay[0] = 0;
            if (cfg.method == FOVPT_METHOD_LAYERS)
                for (n = 0; n < cfg.layers.count && o < sizeof lay - 40; ++n)
                    o += (size_t)snprintf(lay + o, sizeof lay - o, " [r %.3g d %u]", (double)cfg.layers.layer[n].radius_deg,
                                          cfg.layers.layer[n].stride);
            check(r == FOV_OK && bad == 0 && canary_ok(img, 3u * W * H), N("pt_fill_fuzz_%d_%s", it, fovpt_method_name(cfg.method)),
                  "r %d, %zu of %u pixels differ from the background, first (%zu, %zu) = %g %g %g; %ux%u gaze %g %g, cam fov %g, "
                  "display fov %g, blend %g snap %u linear %u, layers%s",
                  (int)r, bad, W * H, first % W, first / W, (double)img[3 * first], (double)img[3 * first + 1], (double)img[3 * first + 2],
                  W, H, (double)g.x, (double)g.y, (double)cam.fov_y_deg, (double)cfg.display.fov_y_deg, (double)cfg.layers.blend_deg,
                  cfg.layers.snap, cfg.layers.blend_linear, lay);
        }
        free(img);
        free(e.cmem); e.cmem = NULL;
    }
    /* SELECTIVE / JIN with temporal reuse and smoothing over moving frames: still the
       background everywhere */
    for (it = 0; it < 40; ++it) {
        uint32_t W = 1u + (uint32_t)(urand() * 40.0), H = 1u + (uint32_t)(urand() * 30.0), f;
        fovpt_config cfg = fovpt_config_default();
        fovpt_camera cam;
        fov_gaze g;
        fov_result r;
        float *img = img_alloc(3u * W * H);
        fovpt_output out;
        size_t i, bad = 0;
        cfg.method = it % 2 ? FOVPT_METHOD_SELECTIVE : FOVPT_METHOD_JIN;
        cfg.temporal.reuse = 1; cfg.temporal.smooth = 1;
        cfg.temporal.n_tpi = 1u + (uint32_t)(urand() * 4.0);
        cfg.accumulate = it % 3 == 0 ? 1u : 0u;
        fovpt_camera_init(&cam, W, H);
        cam.pos[2] = 0.0f; cam.target[2] = 1.0f; /* fovpt_camera_init's former default view */
        g.x = frand(-1.0f * (float)W, 2.0f * (float)W);
        g.y = frand(-1.0f * (float)H, 2.0f * (float)H);
        r = pt_init(&e, &cfg, &cam, g);
        fovpt_output_init(&out);
        out.rgb = img;
        for (f = 0; f < 6 && r == FOV_OK; ++f) {
            r = fovpt_render(&e.ctx, f, &out, NULL);
            for (i = 0; i < (size_t)W * H && r == FOV_OK; ++i)
                bad += fabsf(img[3 * i] - 0.25f) > 1e-5f || fabsf(img[3 * i + 1] - 0.5f) > 1e-5f ||
                       fabsf(img[3 * i + 2] - 0.75f) > 1e-5f || img[3 * i] != img[3 * i];
            cam.pos[0] += f == 2 ? 1e3f : 0.1f;
            g.x += frand(-3.0f, 3.0f);
            if (r == FOV_OK) r = fovpt_set_view(&e.ctx, &cam, g);
        }
        check(r == FOV_OK && bad == 0 && canary_ok(img, 3u * W * H), N("pt_fill_temporal_%d", it), "r %d, %zu pixel-frames differ", (int)r, bad);
        free(img);
        free(e.cmem); e.cmem = NULL;
    }
    pt_free(&e);
}

/* a scene of nothing but a user hook, hostile hooks */
typedef struct hook_state { int mode; } hook_state;
static int hostile_hook(const float org[3], const float dir[3], float tmin, float tmax, float *t, float n[3],
                        uint32_t *material, void *user)
{
    const hook_state *hs = (const hook_state *)user;
    /* a unit sphere at the origin */
    float b = org[0] * dir[0] + org[1] * dir[1] + org[2] * dir[2];
    float dd = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
    float c = org[0] * org[0] + org[1] * org[1] + org[2] * org[2] - 1.0f;
    float disc = b * b - dd * c, tt;
    if (disc < 0.0f) return 0;
    tt = (-b - sqrtf(disc)) / dd;
    if (!(tt > tmin && tt < tmax)) tt = (-b + sqrtf(disc)) / dd;
    if (!(tt > tmin && tt < tmax)) return 0;
    *t = tt;
    n[0] = org[0] + tt * dir[0]; n[1] = org[1] + tt * dir[1]; n[2] = org[2] + tt * dir[2];
    *material = 0;
    switch (hs->mode) {
    case 1: *t = f_nan(); break;
    case 2: n[0] = n[1] = n[2] = 0.0f; break;
    case 3: *material = 999; break;
    case 4: n[1] = f_inf(); break;
    case 5: *t = tmin; break;
    case 6: *t = -f_inf(); break;
    default: break;
    }
    return 1;
}
static void case_pt_user_hook(void)
{
    fovpt_material mats[2];
    fovpt_scene_desc d;
    pt_env e;
    int mode;
    uint32_t m;
    fovpt_material_init(&mats[0]);
    fovpt_material_init(&mats[1]);
    mats[1].emission[0] = mats[1].emission[1] = mats[1].emission[2] = 1.0f;
    for (mode = 0; mode < 7; ++mode) {
        hook_state hs;
        fovpt_camera cam;
        fov_gaze g = { 6.0f, 5.0f };
        fov_result r;
        hs.mode = mode;
        d = pt_desc(mats, 2);
        d.user_hit = hostile_hook; d.user = &hs;
        d.background[0] = d.background[1] = d.background[2] = 0.5f;
        r = pt_build(&e, &d);
        if (!check(r == FOV_OK, N("pt_hook_%d_build", mode), "r %d", (int)r)) { pt_free(&e); continue; }
        fovpt_camera_init(&cam, 12, 10);
        cam.target[2] = 1.0f; /* fovpt_camera_init's former default target */
        cam.pos[2] = -3.0f;
        for (m = 0; m < (uint32_t)_FOVPT_METHOD_NUM; ++m) {
            fovpt_config cfg = fovpt_config_default();
            char tag[64];
            cfg.method = m;
            snprintf(tag, sizeof tag, "pt_hook_%d_%s", mode, fovpt_method_name(m));
            free(e.cmem); e.cmem = NULL;
            r = pt_init(&e, &cfg, &cam, g);
            if (check(r == FOV_OK, N("%s_init", tag), "r %d", (int)r)) pt_render_check(&e, tag, 0.0f, 1e4f);
        }
        /* mode 0: the hook's sphere is seen (the centre pixel is not the background) */
        if (mode == 0) {
            fovpt_config cfg = fovpt_config_default();
            float img[3 * 120] = { 0.0f };
            fovpt_output out;
            free(e.cmem); e.cmem = NULL;
            r = pt_init(&e, &cfg, &cam, g);
            fovpt_output_init(&out);
            out.rgb = img;
            if (r == FOV_OK) r = fovpt_render(&e.ctx, 0, &out, NULL);
            check(r == FOV_OK && fabsf(img[3 * (5 * 12 + 6)] - 0.5f) > 1e-3f, "pt_hook_only_scene_visible",
                  "r %d centre %g (the background is 0.5)", (int)r, (double)img[3 * (5 * 12 + 6)]);
        }
        pt_free(&e);
    }
}

/* random but valid fovlp configs at odd sizes: a documented error or a clean frame */
static void case_lp_fuzz(void)
{
    int it;
    for (it = 0; it < 400; ++it) {
        uint32_t W = 1u + (uint32_t)(urand() * (it % 3 == 0 ? 400.0 : 40.0)), H = 1u + (uint32_t)(urand() * 40.0), k;
        fovlp_config cfg = fovlp_config_preset((uint32_t)(urand() * 4.0), W, H);
        lp_env e;
        fov_result r;
        tlog t;
        char tag[64];
        snprintf(tag, sizeof tag, "lp_fuzz_%d", it);
        if (urand() < 0.5) cfg.sigma = (float)pow(10.0, -1.0 + 2.5 * urand());   /* <= 100 samples per pixel */
        if (urand() < 0.5) cfg.alpha = (float)pow(10.0, -2.0 + 3.2 * urand());
        if (urand() < 0.5) { cfg.no_disc = urand() < 0.5 ? 1u : 0u; cfg.gaze_angle = frand(0.0f, 1.49f); }
        if (urand() < 0.5) cfg.lp_aspect = urand() < 0.3 ? 0.0f : (float)pow(10.0, -3.0 + 6.0 * urand());
        if (urand() < 0.3) cfg.match_deg = frand(0.01f, 88.9f);
        cfg.norm = urand() < 0.5 ? 1u : 0u;
        cfg.edge = urand() < 0.5 ? 1u : 0u;
        if (urand() < 0.3) cfg.cam_fov_y_deg = frand(0.01f, 179.9f);
        if (urand() < 0.3) { cfg.display.fov_y_deg = frand(0.01f, 179.9f); cfg.display.axis_dx = frand(-1e3f, 1e3f); }
        else if (urand() < 0.3) { cfg.display.pixel_pitch_mm = frand(0.01f, 1.0f); cfg.display.distance_mm = frand(1.0f, 5000.0f); }
        cfg.blend = urand() < 0.5 ? 1u : 0u;
        cfg.taa.enable = urand() < 0.5 ? 1u : 0u;
        if (urand() < 0.5) {   /* any valid Halton cycle (review finding 3: offsets >= 1 texel) */
            cfg.taa.phases = 1u + (uint32_t)(urand() * 255.0);
            cfg.taa.halton_start = (uint32_t)(urand() * 999.0);
        }
        cfg.logger = mk_logger(&t);
        r = lp_open(&e, &cfg);
        if (r != FOV_OK) {
            /* a rejected config: a documented code, logged with a message */
            check((r == FOV_ERR_INVALID_ARG || r == FOV_ERR_LIMIT || r == FOV_ERR_DEGENERATE) && t.errors >= 1 && t.code == (int32_t)r && t.msg_ok,
                  N("%s_rejected_logged", tag), "r %d logged %d code %d", (int)r, t.errors, (int)t.code);
        } else {
            float *img = img_alloc(3u * W * H), *dep = img_alloc((size_t)W * H), *bl = img_alloc(3u * W * H);
            for (k = 0; k < 3; ++k) {
                fov_gaze g;
                g.x = k == 0 ? frand(0.0f, (float)W) : frand(-2.0f * (float)W, 3.0f * (float)W);
                g.y = k == 2 ? 1e25f : frand(-2.0f * (float)H, 3.0f * (float)H);
                r = fovlp_begin_frame(&e.ctx, g, NULL);
                if (!check(r == FOV_OK, N("%s_begin_%u", tag, k), "r %d", (int)r)) continue;
                lp_frame_checks(&e, N("%s_g%u", tag, k), img, dep);
                r = fovlp_blend_rows(&e.ctx, img, 0, H, bl);
                check(r == FOV_OK && count_bad(bl, 3u * W * H, 0.049f, 0.951f) == 0 && canary_ok(bl, 3u * W * H),
                      N("%s_g%u_blend", tag, k), "r %d", (int)r);
            }
            free(img); free(dep); free(bl);
        }
        lp_close(&e);
    }
}

/* ======================================================================================== */
/* fovsdf                                                                                    */
/* ======================================================================================== */

/* every method at odd sizes with gazes far off the screen, every output enabled */
static void case_sdf_offscreen(void)
{
    size_t bytes = 0;
    void *mem;
    fovsdf_builtin bi;
    uint32_t m, si, k;
    fov_result r = fovsdf_builtin_size(FOVSDF_SCENE_PRIMITIVES, &bytes);
    mem = malloc(bytes);
    if (r == FOV_OK) r = fovsdf_builtin_init(FOVSDF_SCENE_PRIMITIVES, &bi, mem, bytes);
    if (!check(r == FOV_OK, "sdf_builtin", "r %d", (int)r)) { free(mem); return; }
    for (m = 0; m < (uint32_t)_FOVSDF_METHOD_NUM; ++m)
        for (si = 0; si < NSIZES; ++si)
            for (k = 0; k < 3; ++k) {
                uint32_t W = g_sizes[si][0], H = g_sizes[si][1];
                fovsdf_config cfg = fovsdf_config_default();
                fovsdf_camera cam = bi.camera;
                fovsdf_ctx ctx;
                fov_gaze g;
                fovsdf_output out;
                float *rgb = img_alloc(3u * W * H), *dep = img_alloc((size_t)W * H);
                uint8_t *mask = (uint8_t *)malloc((size_t)W * H + CANARY);
                char tag[96];
                cfg.method = m;
                cam.width = W; cam.height = H;
                /* far off-screen: any finite gaze is valid (review finding 6) */
                g.x = k == 0 ? -3e38f : (k == 1 ? 1e30f : (float)W + 5000.0f);
                g.y = k == 0 ? 3e38f : (k == 1 ? 1e30f : -7.0f);
                memset(mask, 7, (size_t)W * H + CANARY);
                snprintf(tag, sizeof tag, "sdf_%s_%ux%u_g%u", fovsdf_method_name(m), W, H, k);
                r = fovsdf_init(&ctx, &cfg, &bi.scene, &cam, g, NULL, 0);
                if (check(r == FOV_OK, N("%s_init", tag), "r %d (%s)", (int)r, fovsdf_result_string(r))) {
                    size_t i, badm = 0;
                    fovsdf_output_init(&out);
                    out.rgb = rgb; out.depth = dep; out.mask = mask;
                    r = fovsdf_render_rows(&ctx, 0, H, &out, NULL);
                    check(r == FOV_OK && canary_ok(rgb, 3u * W * H) && canary_ok(dep, (size_t)W * H),
                          N("%s_render", tag), "r %d", (int)r);
                    check(count_bad(rgb, 3u * W * H, 0.0f, 1e3f) == 0 && count_bad(dep, (size_t)W * H, 0.0f, 1e6f) == 0,
                          N("%s_pixels", tag), "%zu colour, %zu depth values NaN or unwritten",
                          count_bad(rgb, 3u * W * H, 0.0f, 1e3f), count_bad(dep, (size_t)W * H, 0.0f, 1e6f));
                    for (i = 0; i < (size_t)W * H; ++i) badm += mask[i] > 1u;
                    for (i = 0; i < CANARY; ++i) badm += mask[(size_t)W * H + i] != 7u;
                    check(badm == 0, N("%s_mask", tag), "%zu mask bytes unwritten, out of range or past the end", badm);
                }
                free(rgb); free(dep); free(mask);
            }
    free(mem);
}

static void case_sdf_bad_input(void)
{
    size_t bytes = 0;
    void *mem;
    fovsdf_builtin bi;
    fovsdf_ctx ctx;
    fovsdf_camera cam, c2;
    fovsdf_config cfg = fovsdf_config_default(), c;
    fov_gaze g = { 4.0f, 3.0f }, gb;
    tlog t;
    int i;
    fov_result r = fovsdf_builtin_size(FOVSDF_SCENE_COLUMNS, &bytes);
    mem = malloc(bytes);
    if (r == FOV_OK) r = fovsdf_builtin_init(FOVSDF_SCENE_COLUMNS, &bi, mem, bytes);
    if (!check(r == FOV_OK, "sdf_bad_builtin", "r %d", (int)r)) { free(mem); return; }
    expect("sdf_builtin_one_short", fovsdf_builtin_init(FOVSDF_SCENE_COLUMNS, &bi, mem, bytes - 1), FOV_ERR_TOO_SMALL);
    r = fovsdf_builtin_init(FOVSDF_SCENE_COLUMNS, &bi, mem, bytes);
    expect("sdf_builtin_unknown", fovsdf_builtin_size(77, &bytes), FOV_ERR_INVALID_ARG);
    cam = bi.camera;
    cam.width = 9; cam.height = 7;
    for (i = 0; i < 15; ++i) {
        fov_result want = FOV_ERR_INVALID_ARG;
        c2 = cam;
        switch (i) {
        case 12: c2.target[0] = c2.pos[0]; c2.target[1] = c2.pos[1]; c2.target[2] = c2.pos[2];
                 c2.pos[0] = 0.0f; c2.pos[1] = 1.0f; c2.pos[2] = -3.0f;
                 c2.target[0] = 0.0f; c2.target[1] = 1.0f; c2.target[2] = -3.0f + 1e-6f; want = FOV_OK; break;
        case 13: c2.up[0] = 0.0f; c2.up[1] = 1e30f; c2.up[2] = 0.0f; want = FOV_OK; break;
        case 14: c2.up[0] = 0.0f; c2.up[1] = 0.0f; c2.up[2] = 1e-25f; want = FOV_OK; break;
        case 0: c2.width = 0; break;
        case 1: c2.width = FOVSDF_MAX_DIM + 1u; want = FOV_ERR_LIMIT; break;
        case 2: c2.pos[2] = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 3: c2.fov_y_deg = 180.0f; break;
        case 4: c2.fov_y_deg = -1.0f; break;
        case 5: memcpy(c2.target, c2.pos, sizeof c2.pos); want = FOV_ERR_DEGENERATE; break;
        case 6: c2.up[0] = c2.target[0] - c2.pos[0]; c2.up[1] = c2.target[1] - c2.pos[1];
                c2.up[2] = c2.target[2] - c2.pos[2]; want = FOV_ERR_DEGENERATE; break;
        case 7: c2.eye_offset = f_inf(); want = FOV_ERR_NOT_FINITE; break;
        case 8: c2.fov_y_deg = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 9: c2.pos[0] = 3e38f; c2.target[0] = -3e38f; want = FOV_ERR_DEGENERATE; break;   /* fwd overflows */
        case 10: c2.up[0] = 1e-30f; c2.up[1] = 0.0f; c2.up[2] = 0.0f; want = FOV_OK; break;  /* tiny but valid */
        default: c2.fov_y_deg = 1e-3f; want = FOV_OK; break;
        }
        c = cfg;
        c.logger = mk_logger(&t);
        r = fovsdf_init(&ctx, &c, &bi.scene, &c2, g, NULL, 0);
        if (want == FOV_OK) {
            check(r == FOV_OK, N("sdf_camera_%d", i), "r %d", (int)r);
            if (r == FOV_OK) {
                float rgb[3 * 63 + CANARY];
                fovsdf_output out;
                size_t k;
                for (k = 0; k < 3u * 63u; ++k) rgb[k] = f_nan();
                fovsdf_output_init(&out);
                out.rgb = rgb;
                r = fovsdf_render_rows(&ctx, 0, 7, &out, NULL);
                check(r == FOV_OK && count_bad(rgb, 3u * 63u, 0.0f, 1e3f) == 0, N("sdf_camera_%d_render", i), "r %d", (int)r);
            }
        } else {
            expect_logged(N("sdf_camera_bad_%d", i), r, want, &t);
        }
    }
    for (i = 0; i < 2; ++i) {
        gb.x = i == 0 ? f_nan() : 1.0f;
        gb.y = i == 1 ? -f_inf() : 1.0f;
        c = cfg;
        c.logger = mk_logger(&t);
        r = fovsdf_init(&ctx, &c, &bi.scene, &cam, gb, NULL, 0);
        expect_logged(N("sdf_gaze_bad_%d", i), r, FOV_ERR_NOT_FINITE, &t);
    }
    /* a failed re-initialisation leaves a working context exactly as it was */
    {
        float *a = img_alloc(3u * 9 * 7), *b = img_alloc(3u * 9 * 7);
        fovsdf_output out;
        uint32_t diff = 0;
        size_t q;
        int ok = 1;
        fovsdf_output_init(&out);
        c = cfg;
        c.method = FOVSDF_METHOD_FIPR;
        r = fovsdf_init(&ctx, &c, &bi.scene, &cam, g, NULL, 0);
        out.rgb = a;
        if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, 7, &out, NULL);
        ok &= r == FOV_OK;
        for (i = 0; i < 4; ++i) {
            fovsdf_config c3 = fovsdf_config_default();
            fov_gaze g3 = g;
            c2 = cam;
            switch (i) {
            case 0: g3.x = f_nan(); break;                             /* rejected: NaN gaze */
            case 1: c2.pos[0] = c2.target[0]; c2.pos[1] = c2.target[1]; c2.pos[2] = c2.target[2]; break;
            case 2: c3.display.fov_y_deg = 200.0f; break;              /* rejected through the display */
            default: c2.width = 0; break;
            }
            r = fovsdf_init(&ctx, &c3, &bi.scene, &c2, g3, NULL, 0);
            ok &= r != FOV_OK;
        }
        out.rgb = b;
        r = fovsdf_render_rows(&ctx, 0, 7, &out, NULL);
        for (q = 0; q < 3u * 9u * 7u; ++q) diff += memcmp(&a[q], &b[q], sizeof(float)) != 0;
        check(ok && r == FOV_OK && diff == 0, "sdf_failed_init_keeps_ctx", "ok %d r %d, %u values differ after failed re-inits", ok, (int)r, diff);
        free(a); free(b);
    }
    /* method-specific values and enums */
    for (i = 0; i < 14; ++i) {
        fov_result want = FOV_ERR_INVALID_ARG;
        c = cfg;
        switch (i) {
        case 0: c.method = 9; break;
        case 1: c.spp = 3; break;
        case 2: c.eps_mode = 3; break;
        case 3: c.eps = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        case 4: c.omega = 2.0f; break;
        case 5: c.cone_tile = 24; break;
        case 6: c.ipr_levels = 7; break;
        case 7: c.ipr_radius = -1; break;
        case 8: c.skip_block = 17; break;
        case 9: c.finish = 5; break;
        case 10: c.fov_mask = 3; break;
        case 11: c.refresh = 3; break;
        case 12: c.display.pixel_pitch_mm = 0.3f; break;   /* distance missing */
        default: c.display.axis_dy = f_nan(); want = FOV_ERR_NOT_FINITE; break;
        }
        c.logger = mk_logger(&t);
        r = fovsdf_init(&ctx, &c, &bi.scene, &cam, g, NULL, 0);
        if (r == FOV_ERR_LIMIT && (i == 1 || i == 5 || i == 6 || i == 8)) want = FOV_ERR_LIMIT;
        expect_logged(N("sdf_config_bad_%d", i), r, want, &t);
    }
    free(mem);
}

/* hostile scene fields and callbacks: NaN lights, sky, ambient, Lipschitz bound, t_max are
   rejected; a NaN albedo or distance from the user's callbacks never reaches the image */
static float unit_sphere(const float p[3], void *u) { (void)u; return sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0f; }
static float nan_sphere(const float p[3], void *u) { (void)u; return p[0] > 0.3f ? f_nan() : unit_sphere(p, u); }
static void nan_albedo(const float p[3], int32_t m, float rgb[3], void *u)
{
    (void)m; (void)u;
    rgb[0] = p[1] > 0.0f ? f_nan() : 0.5f;
    rgb[1] = p[1] > 0.0f ? 0.5f : f_inf();
    rgb[2] = -f_inf();
}
static void case_sdf_scene(void)
{
    int i;
    for (i = 0; i < 15; ++i) {
        fovsdf_scene sc;
        fovsdf_camera cam;
        fovsdf_ctx ctx;
        fovsdf_config cfg = fovsdf_config_default();
        fov_gaze g = { 8.0f, 6.0f };
        float *rgb = img_alloc(3u * 16 * 12);
        fovsdf_output out;
        fov_result r, want = FOV_ERR_NOT_FINITE;
        tlog t;
        fovsdf_scene_init(&sc);
        sc.dist = unit_sphere;
        fovsdf_camera_init(&cam, 16, 12);
        cam.pos[2] = -4.0f;
        switch (i) {
        case 0: want = FOV_OK; break;
        case 1: sc.ambient[1] = f_nan(); break;
        case 2: sc.lights[0].color[0] = f_inf(); break;
        case 3: sc.lights[0].v[0] = sc.lights[0].v[1] = sc.lights[0].v[2] = 0.0f; want = FOV_OK; break;  /* no light */
        case 4: sc.lights[0].v[1] = f_nan(); break;
        case 5: sc.num_lights = FOVSDF_MAX_LIGHTS + 1u; want = FOV_ERR_LIMIT; break;
        case 6: sc.lights[0].type = 7; want = FOV_ERR_INVALID_ARG; break;
        case 7: sc.lipschitz = f_nan(); break;
        case 8: sc.lipschitz = -2.0f; want = FOV_ERR_INVALID_ARG; break;
        case 9: sc.t_max = f_nan(); break;
        case 10: sc.sky_zenith[2] = f_inf(); break;
        case 11: sc.lights[0].type = FOVSDF_LIGHT_POINT; sc.lights[0].range = f_nan(); break;
        case 12: sc.lights[0].shadow_k = f_nan(); break;
        case 13: sc.albedo = nan_albedo; want = FOV_OK; break;
        default: sc.dist = nan_sphere; sc.albedo = nan_albedo; want = FOV_OK; break;
        }
        cfg.logger = mk_logger(&t);
        r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
        if (want != FOV_OK) {
            expect_logged(N("sdf_scene_bad_%d", i), r, want, &t);
        } else {
            fovsdf_output_init(&out);
            out.rgb = rgb;
            if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, 12, &out, NULL);
            check(r == FOV_OK && count_bad(rgb, 3u * 16 * 12, 0.0f, 1e3f) == 0 && canary_ok(rgb, 3u * 16 * 12),
                  N("sdf_scene_ok_%d_finite", i), "r %d, %zu values NaN, infinite or negative", (int)r,
                  count_bad(rgb, 3u * 16 * 12, 0.0f, 1e3f));
        }
        free(rgb);
    }
}

/* programs with degenerate nodes: cycles, self references, zero sizes, NaN parameters */
static float sdf_eval_range(const fovsdf_program *p, float *out_min)
{
    int i, bad = 0;
    float mn = 1e30f;
    for (i = 0; i < 200; ++i) {
        float q[3], d;
        q[0] = frand(-4, 4); q[1] = frand(-4, 4); q[2] = frand(-4, 4);
        d = fovsdf_program_eval(q, NULL, (void *)p);
        if (d != d) bad++;
        if (d < mn) mn = d;
    }
    *out_min = mn;
    return (float)bad;
}

static void case_sdf_programs(void)
{
    fovsdf_node nodes[16];
    fovsdf_program prog;
    size_t bytes = 0;
    unsigned char *mem;
    fov_result r;
    int i;
    float mn;
    /* hand-made node arrays (the struct is public) */
    for (i = 0; i < 6; ++i) {
        memset(nodes, 0, sizeof nodes);
        nodes[0].type = FOVSDF_NODE_SPHERE; nodes[0].a = nodes[0].b = -1; nodes[0].f[0] = 1.0f;
        nodes[1].type = FOVSDF_NODE_UNION; nodes[1].a = 0; nodes[1].b = 2;
        nodes[2].type = FOVSDF_NODE_TRANSLATE; nodes[2].a = 0; nodes[2].b = -1; nodes[2].f[0] = 2.0f;
        switch (i) {
        case 0: nodes[1].b = 1; break;                 /* a union that contains itself */
        case 1: nodes[2].a = 1; break;                 /* a cycle through two nodes */
        case 2: nodes[1].a = 3; break;                 /* a child beyond count */
        case 3: nodes[1].a = -5; break;
        case 4: nodes[2].type = 999; break;
        default: nodes[1].a = 2; nodes[1].b = 2; break; /* the same child twice: valid */
        }
        r = fovsdf_program_size(nodes, 3, 1, &bytes);
        if (r != FOV_OK) { check(i < 5, N("sdf_prog_hand_%d", i), "size r %d", (int)r); continue; }
        mem = (unsigned char *)malloc(bytes + 3);
        r = fovsdf_program_build(&prog, nodes, 3, 1, mem + 3, bytes);   /* misaligned too */
        if (i < 5) {
            check(r == FOV_ERR_INVALID_ARG, N("sdf_prog_hand_%d", i), "r %d, want INVALID_ARG", (int)r);
        } else {
            check(r == FOV_OK && sdf_eval_range(&prog, &mn) == 0.0f, N("sdf_prog_hand_%d", i), "r %d", (int)r);
        }
        free(mem);
    }
    /* deep trees: a chain of transforms deeper than the program's point stack is a clean
       FOV_ERR_LIMIT (documented: FOVSDF_MAX_STACK), a shallow one builds; a builder that runs
       out of nodes stops with FOV_ERR_TOO_SMALL */
    {
        static fovsdf_node deep[4100];
        uint32_t depth;
        for (depth = 8; depth <= 4096; depth *= 8) {
            fovsdf_builder b;
            int32_t root;
            uint32_t k;
            fovsdf_builder_init(&b, deep, 4100);
            root = fovsdf_sphere(&b, 1.0f);
            for (k = 0; k < depth; ++k) root = fovsdf_translate(&b, root, 1e-3f, 0.0f, 0.0f);
            r = fovsdf_program_size(deep, b.count, root, &bytes);
            mem = (unsigned char *)malloc(bytes);
            if (r == FOV_OK) r = fovsdf_program_build(&prog, deep, b.count, root, mem, bytes);
            if (depth <= FOVSDF_MAX_STACK / 2u)
                check(r == FOV_OK && sdf_eval_range(&prog, &mn) == 0.0f, N("sdf_prog_chain_%u", depth), "r %d", (int)r);
            else
                check(r == FOV_ERR_LIMIT, N("sdf_prog_chain_%u", depth), "r %d, want FOV_ERR_LIMIT", (int)r);
            free(mem);
        }
        {
            fovsdf_builder b;
            int32_t root, k;
            fovsdf_builder_init(&b, deep, 100);
            root = fovsdf_sphere(&b, 1.0f);
            for (k = 0; k < 200 && root >= 0; ++k) root = fovsdf_union(&b, root, fovsdf_sphere(&b, 0.5f));
            check(root < 0 && b.err == FOV_ERR_TOO_SMALL && b.count <= 100u, "sdf_builder_full", "root %d err %d count %u",
                  (int)root, (int)b.err, b.count);
        }
    }
    r = fovsdf_program_size(nodes, 0, 0, &bytes);
    expect("sdf_prog_count0", r, FOV_ERR_INVALID_ARG);
    expect("sdf_prog_root_neg", fovsdf_program_size(nodes, 3, -1, &bytes), FOV_ERR_INVALID_ARG);
    expect("sdf_prog_null", fovsdf_program_size(NULL, 3, 0, &bytes), FOV_ERR_NULL);
    /* builder: degenerate primitives and operators */
    for (i = 0; i < 14; ++i) {
        fovsdf_builder b;
        int32_t root = -1, s;
        float a0[3] = { 1, 1, 1 };
        fovsdf_builder_init(&b, nodes, 16);
        switch (i) {
        case 0: root = fovsdf_sphere(&b, 0.0f); break;
        case 1: root = fovsdf_sphere(&b, -1.0f); break;
        case 2: root = fovsdf_box(&b, 0.0f, 0.0f, 0.0f); break;
        case 3: root = fovsdf_torus(&b, 1.0f, 0.0f); break;
        case 4: root = fovsdf_capsule(&b, a0, a0, 0.5f); break;      /* a == b */
        case 5: root = fovsdf_cone(&b, 1.0f, 0.0f, 0.0f); break;
        case 6: root = fovsdf_plane(&b, 0.0f, 0.0f, 0.0f, 1.0f); break;
        case 7: s = fovsdf_sphere(&b, 1.0f); root = fovsdf_scale(&b, s, 0.0f); break;
        case 8: s = fovsdf_sphere(&b, 1.0f); root = fovsdf_repeat(&b, s, 0.0f, 0.0f, 0.0f, 3, 3, 3); break;
        case 9: s = fovsdf_sphere(&b, f_nan()); root = s; break;
        case 10: s = fovsdf_sphere(&b, 1.0f); root = fovsdf_rotate(&b, s, 0.0f, 0.0f, 0.0f, 45.0f); break;
        case 11: s = fovsdf_sphere(&b, 1.0f); root = fovsdf_smooth_union(&b, s, s, 0.0f); break;
        case 12: root = fovsdf_menger(&b, 1.0f, 0); break;
        default: s = fovsdf_sphere(&b, 1.0f); root = fovsdf_union(&b, s, 5); break;   /* dangling */
        }
        if (root < 0) {
            check(b.err != FOV_OK, N("sdf_builder_%d_error", i), "index -1 without an error code");
            continue;
        }
        r = fovsdf_program_size(nodes, b.count, root, &bytes);
        if (r != FOV_OK) { check(1, N("sdf_builder_%d_rejected", i), " "); continue; }
        mem = (unsigned char *)malloc(bytes);
        r = fovsdf_program_build(&prog, nodes, b.count, root, mem, bytes);
        if (r == FOV_OK) {
            /* accepted: evaluations are never NaN, and a scene traced with it renders finite */
            float bad = sdf_eval_range(&prog, &mn);
            fovsdf_scene sc;
            fovsdf_camera cam;
            fovsdf_ctx ctx;
            fovsdf_config cfg = fovsdf_config_default();
            fov_gaze g = { 3.0f, 3.0f };
            float rgb[3 * 35];
            fovsdf_output out;
            check(bad == 0.0f, N("sdf_builder_%d_eval_finite", i), "%g NaN distances of 200", (double)bad);
            fovsdf_scene_init(&sc);
            fovsdf_scene_set_program(&sc, &prog);
            fovsdf_camera_init(&cam, 7, 5);
            cam.pos[2] = -5.0f;
            fovsdf_output_init(&out);
            out.rgb = rgb;
            memset(rgb, 0xFF, sizeof rgb);
            r = fovsdf_init(&ctx, &cfg, &sc, &cam, g, NULL, 0);
            if (r == FOV_OK) r = fovsdf_render_rows(&ctx, 0, 5, &out, NULL);
            check(r == FOV_OK && count_bad(rgb, 3u * 35u, 0.0f, 1e3f) == 0, N("sdf_builder_%d_render", i), "r %d", (int)r);
        } else {
            check(r == FOV_ERR_INVALID_ARG || r == FOV_ERR_NOT_FINITE || r == FOV_ERR_DEGENERATE,
                  N("sdf_builder_%d_build_code", i), "r %d", (int)r);
        }
        free(mem);
    }
}

/* ======================================================================================== */
/* across the headers: one eccentricity model, one set of result strings                    */
/* ======================================================================================== */
static void case_cross(void)
{
    int i, agree = 0, codes = 0;
    for (i = 0; i < 300; ++i) {
        fov_display d;
        fov_ecc_model a, b, c;
        fov_gaze g;
        uint32_t W = 1u + (uint32_t)(urand() * 3000.0), H = 1u + (uint32_t)(urand() * 3000.0);
        float fov = frand(-10.0f, 200.0f), x = frand(-5000, 5000), y = frand(-5000, 5000);
        fov_result ra, rb, rc;
        memset(&d, 0, sizeof d);
        switch (i % 5) {
        case 0: d.fov_y_deg = frand(-5.0f, 190.0f); break;
        case 1: d.pixel_pitch_mm = frand(-0.1f, 0.4f); d.distance_mm = frand(-10.0f, 900.0f); break;
        case 2: d.axis_dx = i % 10 == 2 ? f_nan() : frand(-100, 100); break;
        case 3: d.pixel_pitch_mm = 0.25f; break;
        default: break;
        }
        g.x = i % 7 == 0 ? 3e38f : frand(-1e4f, 1e4f);
        g.y = i % 11 == 0 ? f_nan() : frand(-1e4f, 1e4f);
        ra = fovsdf_ecc_init(&a, &d, fov, W, H, g);
        rb = fovlp_ecc_init(&b, &d, fov, W, H, g);
        rc = fovpt_ecc_init(&c, &d, fov, W, H, g);
        codes += ra == rb && rb == rc;
        if (ra == FOV_OK && rb == FOV_OK && rc == FOV_OK) {
            float ea = fovsdf_ecc_deg(&a, x, y), eb = fovlp_ecc_deg(&b, x, y), ec = fovpt_ecc_deg(&c, x, y);
            agree += fabsf(ea - eb) <= 1e-3f && fabsf(ea - ec) <= 1e-3f &&
                     fabsf(fovsdf_ecc_ppd(&a) - fovlp_ecc_ppd(&b)) <= 1e-3f * fovsdf_ecc_ppd(&a) &&
                     fabsf(fovsdf_ecc_ppd(&a) - fovpt_ecc_ppd(&c)) <= 1e-3f * fovsdf_ecc_ppd(&a) && isfinite(ea);
        } else {
            agree++;
        }
    }
    check(codes == 300, "cross_ecc_init_same_codes", "%d of 300 inputs give the same result code in all three headers", codes);
    check(agree == 300, "cross_ecc_same_values", "%d of 300 agree", agree);
    for (i = -8; i <= 0; ++i) {
        const char *a = fovsdf_result_string((fov_result)i), *b = fovlp_result_string((fov_result)i),
                   *c = fovpt_result_string((fov_result)i);
        check(a && b && c && strcmp(a, b) == 0 && strcmp(a, c) == 0, N("cross_result_string_%d", i),
              "'%s' / '%s' / '%s'", a ? a : "(null)", b ? b : "(null)", c ? c : "(null)");
    }
}

int main(int argc, char **argv)
{
    static const struct { const char *name; void (*fn)(void); } cases[] = {
        { "lp_sizes", case_lp_sizes },       { "lp_taa_sizes", case_lp_taa_sizes },
        { "lp_bad_input", case_lp_bad_input }, { "lp_config", case_lp_config },
        { "lp_taa", case_lp_taa },           { "pt_sizes", case_pt_sizes },
        { "pt_scenes", case_pt_scenes },     { "pt_huge", case_pt_huge },
        { "pt_bad_input", case_pt_bad_input }, { "sdf_offscreen", case_sdf_offscreen },
        { "sdf_bad_input", case_sdf_bad_input }, { "sdf_programs", case_sdf_programs },
        { "cross", case_cross },             { "pt_fuzz", case_pt_fuzz },
        { "pt_user_hook", case_pt_user_hook }, { "lp_fuzz", case_lp_fuzz },
        { "pt_temporal", case_pt_temporal }, { "sdf_scene", case_sdf_scene },
        { "pt_fill_fuzz", case_pt_fill_fuzz },
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        if (argc > 1 && strcmp(argv[1], cases[i].name) != 0) continue;
        run_case(cases[i].name, cases[i].fn);
    }
    return fovcheck_summary();
}
