/* The bad-input corpus: every file tests/bad/NAME.scene holds, on its first line,
 *
 *   # expect: LINE:COL: error: MESSAGE
 *
 * the exact first diagnostic the file must produce, without the file name
 * (LINE counts the header itself).  A JSON scene, tests/bad/NAME.json
 * (spec/json.md, "Diagnostics"), cannot hold a comment: its expectation is
 * the first line of tests/bad/NAME.expect, in the same form (LINE counts
 * the lines of the .json); they are checked only in builds with JSON
 * (spec/json.md [JSON-DIAG-1] malformed JSON, [JSON-DIAG-2] a document
 * that breaks the format).  When the first error is in a file the
 * scene reads (an include, an OBJ mesh), the expectation names that file
 * relative to tests/bad/: `# expect: inc/cycle_b.scene:2:9: error: ...`.
 *
 * Each file is checked twice: through scene_load (status 65, first line of
 * the diagnostics) and through the command line, `refray check FILE`, run
 * as a child process (exit code 65, first line of stderr).  The binary is
 * $REFRAY_BIN (set by `make test`), else build/refray.  Tests run from the
 * repository root.  The corpus covers every error path of the scanner,
 * the parser and the validator; spec/language.md lists the messages. */
#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "testlib.h"
#include "scene/scene.h"

#define BAD_DIR "tests/bad"

enum { MIN_FILES = 45, MAX_FILES = 512, PATH_MAX_LEN = 512, LINE_MAX_LEN = 2048 };

typedef struct corpus {
    char names[MAX_FILES][64];
    int count;
} corpus;

static int by_name(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

static int ends_with(const char *name, const char *ext)
{
    size_t n = strlen(name), k = strlen(ext);
    return n > k && strcmp(name + n - k, ext) == 0;
}

static int is_scene(const char *name)
{
#ifdef REFRAY_HAVE_JSON
    if (ends_with(name, ".json") && name[0] != '.')
        return 1;
#endif
    return ends_with(name, ".scene") && name[0] != '.';
}

/* The *.scene (and *.json) files of tests/bad, sorted; count -1 when the directory
 * cannot be read. */
static void corpus_read(corpus *c)
{
    c->count = 0;
    DIR *dir = opendir(BAD_DIR);
    if (!dir) {
        c->count = -1;
        return;
    }
    for (struct dirent *e = readdir(dir); e; e = readdir(dir)) {
        if (!is_scene(e->d_name) || strlen(e->d_name) >= sizeof c->names[0] || c->count == MAX_FILES)
            continue;
        strcpy(c->names[c->count++], e->d_name);
    }
    closedir(dir);
    qsort(c->names, (size_t)c->count, sizeof c->names[0], by_name);
}

/* The header's expectation as a whole first line: FILE:LINE:COL: ... */
static void expected_line(const char *path, char *want, size_t size)
{
    char header[LINE_MAX_LEN], sidecar[LINE_MAX_LEN];
    static const char tag[] = "# expect: ";
    const char *from = path;
    if (ends_with(path, ".json")) {
        snprintf(sidecar, sizeof sidecar, "%.*s.expect", (int)(strlen(path) - 5), path);
        from = sidecar;
    }
    FILE *f = fopen(from, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", from);
    ck_assert_msg(fgets(header, sizeof header, f) != NULL, "%s is empty", path);
    fclose(f);
    header[strcspn(header, "\r\n")] = '\0';
    ck_assert_msg(strncmp(header, tag, sizeof tag - 1) == 0, "%s: first line is not '# expect: ...'", path);
    const char *expect = header + sizeof tag - 1;
    if (expect[0] >= '0' && expect[0] <= '9')
        snprintf(want, size, "%s:%s", path, expect);
    else
        snprintf(want, size, "%s/%s", BAD_DIR, expect);
}

static void first_line_of(const char *text, char *line, size_t size)
{
    size_t n = strcspn(text, "\n");
    if (n >= size)
        n = size - 1;
    memcpy(line, text, n);
    line[n] = '\0';
}

/* (a) through the library. */
static void check_library(const char *path, const char *want)
{
    char *out = NULL, line[LINE_MAX_LEN];
    size_t size;
    int status;
    FILE *f = open_memstream(&out, &size);
    ck_assert_ptr_nonnull(f);
    rf_scene *s = scene_load(path, NULL, f, 1, &status);
    fclose(f);
    first_line_of(out, line, sizeof line);
    free(out);
    scene_free(s);
    ck_assert_msg(s == NULL, "%s loaded", path);
    ck_assert_msg(status == REFRAY_EXIT_DATAERR, "%s: status %d, expected 65", path, status);
    ck_assert_msg(strcmp(line, want) == 0, "%s:\n  got  %s\n  want %s", path, line, want);
}

/* Runs `refray check path` with stderr into a pipe; returns the exit code
 * (-1 when it did not exit normally) and the first line of stderr. */
static int run_cli(const char *path, char *line, size_t size)
{
    const char *bin = getenv("REFRAY_BIN");
    if (!bin || !*bin)
        bin = "build/refray";
    ck_assert_msg(access(bin, X_OK) == 0, "no refray binary at %s (set REFRAY_BIN)", bin);
    int fds[2];
    ck_assert_int_eq(pipe(fds), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(fds[1], 2);
        if (null >= 0)
            dup2(null, 1);
        close(fds[0]);
        close(fds[1]);
        execl(bin, bin, "check", path, (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    char buf[LINE_MAX_LEN * 4];
    size_t used = 0;
    ssize_t got;
    while ((got = read(fds[0], buf + used, sizeof buf - 1 - used)) > 0)
        used += (size_t)got;
    /* Drain the rest so the child never blocks on a full pipe. */
    char sink[4096];
    while (used == sizeof buf - 1 && read(fds[0], sink, sizeof sink) > 0)
        ;
    close(fds[0]);
    buf[used] = '\0';
    first_line_of(buf, line, size);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* (b) through the command line. */
static void check_cli(const char *path, const char *want)
{
    char line[LINE_MAX_LEN];
    int code = run_cli(path, line, sizeof line);
    ck_assert_msg(code == REFRAY_EXIT_DATAERR, "refray check %s: exit %d, expected 65", path, code);
    ck_assert_msg(strcmp(line, want) == 0, "refray check %s:\n  got  %s\n  want %s", path, line, want);
}

/* A broken glob must not pass by checking nothing. */
START_TEST(test_bad_corpus_size)
{
    corpus c;
    corpus_read(&c);
    ck_assert_msg(c.count >= MIN_FILES, "%s holds %d .scene files, expected at least %d", BAD_DIR, c.count,
                  MIN_FILES);
}
END_TEST

/* File number _i of the sorted corpus (one loop test per file). */
START_TEST(test_bad_scene_file)
{
    corpus c;
    char path[PATH_MAX_LEN], want[LINE_MAX_LEN + PATH_MAX_LEN];
    corpus_read(&c);
    ck_assert_msg(_i < c.count, "no bad scene number %d (%d files)", _i, c.count);
    snprintf(path, sizeof path, "%s/%s", BAD_DIR, c.names[_i]);
    expected_line(path, want, sizeof want);
    check_library(path, want);
    check_cli(path, want);
}
END_TEST

Suite *suite_badscenes(void)
{
    Suite *s = suite_create("badscenes");
    TCase *tc = tcase_create("badscenes");
    corpus c;
    corpus_read(&c);
    tcase_add_test(tc, test_bad_corpus_size);
    tcase_add_loop_test(tc, test_bad_scene_file, 0, c.count > 0 ? c.count : 1);
    suite_add_tcase(s, tc);
    return s;
}
