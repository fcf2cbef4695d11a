/*
 * cli_testlib.h - running the refray program from a suite (check_kit.c,
 * check_conform.c): $REFRAY_BIN (set by `make test`), else build/refray,
 * from the repository root, with its standard output and error caught in
 * files (a full pipe could block it), and a scratch directory per test.
 * static inline, so a suite that uses only some of them gets no warning.
 */
#ifndef REFRAY_CLI_TESTLIB_H
#define REFRAY_CLI_TESTLIB_H

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "testlib.h"

#ifndef REFRAY_HAVE_JSON
#define REFRAY_HAVE_JSON 0
#endif

enum { CLI_OUT_MAX = 65536 };

typedef struct cli_run {
    int code;                 /* exit code, -1 when a signal ended it */
    char out[CLI_OUT_MAX];    /* standard output, cut at CLI_OUT_MAX - 1 */
    char err[CLI_OUT_MAX];    /* standard error */
} cli_run;

/* In a child about to exec refray: the signal dispositions a user's shell
 * gives a program.  A harness under nohup, or a background job of a
 * non-interactive shell, passes SIGHUP or SIGINT on ignored, and refray
 * rightly keeps an ignored signal ignored, so a test that sends one would
 * wait for a render to end by itself. */
static inline void cli_signals_default(void)
{
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
}

static inline const char *cli_refray_bin(void)
{
    const char *bin = getenv("REFRAY_BIN");
    if (!bin || !*bin)
        bin = "build/refray";
    ck_assert_msg(access(bin, X_OK) == 0, "no refray binary at %s (set REFRAY_BIN)", bin);
    return bin;
}

static inline void cli_slurp(FILE *f, char *buf, size_t size)
{
    rewind(f);
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
}

/* Runs refray with args (NULL-terminated, without the program's name). */
static inline void cli_refray(cli_run *r, const char *const *args)
{
    const char *bin = cli_refray_bin();
    char *argv[64];
    int n = 0;
    argv[n++] = (char *)bin;
    for (; args[n - 1] && n < 63; n++)
        argv[n] = (char *)args[n - 1];
    argv[n] = NULL;
    FILE *out = tmpfile(), *err = tmpfile();
    ck_assert(out && err);
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        dup2(fileno(out), 1);
        dup2(fileno(err), 2);
        execv(bin, argv);
        _exit(127);
    }
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    r->code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    cli_slurp(out, r->out, sizeof r->out);
    cli_slurp(err, r->err, sizeof r->err);
}

/* A fresh directory under /tmp, its path in dir (size bytes). */
static inline void cli_scratch(char *dir, size_t size, const char *tag)
{
    snprintf(dir, size, "/tmp/refray-%s-XXXXXX", tag);
    ck_assert_ptr_nonnull(mkdtemp(dir));
}

static inline void cli_remove(const char *dir)
{
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    ck_assert_int_eq(system(cmd), 0);
}

/* dir + "/" + name into out. */
static inline const char *cli_path(char *out, size_t size, const char *dir, const char *name)
{
    size_t n = strlen(dir), m = strlen(name);
    ck_assert_msg(n + 1 + m < size, "path too long: %s/%s", dir, name);
    memcpy(out, dir, n);
    out[n] = '/';
    memcpy(out + n + 1, name, m + 1);
    return out;
}

/* The entries of directory dir, "." and ".." left out; -1 if unreadable. */
static inline int cli_entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d)
        return -1;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static inline int cli_exists(const char *path)
{
    return access(path, F_OK) == 0;
}

/* The scenes of the small kit the kit and conform suites build: a
 * deterministic scene with one sample per pixel, a sampled one, and one
 * with a 2 x 2 pixel grid that the POV-Ray export refuses. */
static const char *const cli_kit_scenes[] = {
    "scenes/analytic/plane_point_linear.scene",
    "scenes/analytic/disk_light.scene",
    "scenes/analytic/sphere_shadow_two_lights.scene",
};
enum { CLI_KIT_SCENES = 3 };

/*
 * Builds that kit with `refray kit -q -o ROOT/kit SCENES` in a new
 * directory ROOT under /tmp (its path into root), for a suite's unchecked
 * fixture.  Returns refray's exit code, -1 when there is no directory or
 * the build has no JSON (no kit can be made; the suites check that).
 */
static inline int cli_kit_setup(char *root, size_t size)
{
    static cli_run r;
    char dir[300];
    snprintf(root, size, "/tmp/refray-kit-XXXXXX");
    if (!REFRAY_HAVE_JSON || !mkdtemp(root))
        return -1;
    snprintf(dir, sizeof dir, "%s/kit", root);
    const char *args[] = {"kit", "-q", "-o", dir, cli_kit_scenes[0], cli_kit_scenes[1], cli_kit_scenes[2], NULL};
    cli_refray(&r, args);
    if (r.code != 0)
        fprintf(stderr, "refray kit: %s", r.err);
    return r.code;
}

static inline void cli_kit_teardown(const char *root)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", root);
    if (strncmp(root, "/tmp/refray-kit-", 16) == 0 && !strstr(root, "XXXXXX") && system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", root);
}

#endif
