/* replay.c - runs a fuzz harness on files without libFuzzer: the committed corpus and the
   regression inputs, in `make test`. Each input runs in a child process (a contract failure
   aborts it, a hang is killed after 20 s), so one bad input fails one check and the rest
   still run.
   Usage: replay FILE_OR_DIR...   (prints PASS/FAIL per input and "N passed, N failed") */
#include <dirent.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int g_pass, g_fail;

static void run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf;
    long n;
    pid_t pid;
    int status = 0;
    if (!f) { printf("FAIL %s: cannot open\n", path); g_fail++; return; }
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (uint8_t *)malloc((size_t)(n > 0 ? n : 1));
    if (!buf || (n > 0 && fread(buf, 1, (size_t)n, f) != (size_t)n)) {
        printf("FAIL %s: cannot read\n", path); g_fail++; fclose(f); free(buf); return;
    }
    fclose(f);
    fflush(stdout);
    pid = fork();
    if (pid == 0) {
        alarm(20);
        LLVMFuzzerTestOneInput(buf, (size_t)n);
        _exit(0);
    }
    free(buf);
    if (pid < 0 || waitpid(pid, &status, 0) < 0) { printf("FAIL %s: fork\n", path); g_fail++; return; }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        printf("PASS %s\n", path);
        g_pass++;
    } else if (WIFSIGNALED(status)) {
        printf("FAIL %s: signal %d%s\n", path, WTERMSIG(status), WTERMSIG(status) == SIGALRM ? " (hang)" : "");
        g_fail++;
    } else {
        printf("FAIL %s: exit status %d\n", path, WEXITSTATUS(status));
        g_fail++;
    }
}

static int cmp(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void run_path(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) { printf("FAIL %s: no such file\n", path); g_fail++; return; }
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        struct dirent *e;
        char **names = 0;
        size_t count = 0, cap = 0, k;
        if (!d) { printf("FAIL %s: cannot open directory\n", path); g_fail++; return; }
        while ((e = readdir(d)) != 0) {
            size_t len;
            if (e->d_name[0] == '.') continue;
            if (count == cap) {
                cap = cap ? 2 * cap : 64;
                names = (char **)realloc(names, cap * sizeof *names);
                if (!names) abort();
            }
            len = strlen(path) + strlen(e->d_name) + 2;
            names[count] = (char *)malloc(len);
            if (!names[count]) abort();
            snprintf(names[count], len, "%s/%s", path, e->d_name);
            count++;
        }
        closedir(d);
        if (count) qsort(names, count, sizeof *names, cmp);
        for (k = 0; k < count; ++k) { run_path(names[k]); free(names[k]); }
        free(names);
    } else {
        run_file(path);
    }
}

int main(int argc, char **argv)
{
    int k;
    if (argc < 2 || !strcmp(argv[1], "--help")) {
        printf("usage: %s FILE_OR_DIR...  (runs the fuzz harness on each input)\n", argv[0]);
        return argc < 2 ? 2 : 0;
    }
    for (k = 1; k < argc; ++k) run_path(argv[k]);
    printf("%d passed, %d failed\n", g_pass, g_fail);
    return g_fail ? 1 : 0;
}
