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
 * Lines right after it of the form `# then: LINE:COL: error|note: ...` are
 * later diagnostics the run must print too, in that order (each a whole
 * line of the output; source and caret lines in between are skipped).
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
#include "io/scene_file.h"
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

enum { MAX_EXPECT = 8 };

typedef struct expectation {
    char lines[MAX_EXPECT][LINE_MAX_LEN + PATH_MAX_LEN];
    int count;
} expectation;

/* A header line's expectation as a whole line of output: FILE:LINE:COL: ... */
static void expected_text(const char *path, const char *expect, char *want, size_t size)
{
    if (expect[0] >= '0' && expect[0] <= '9')
        snprintf(want, size, "%s:%s", path, expect);
    else
        snprintf(want, size, "%s/%s", BAD_DIR, expect);
}

/* The `# expect:` line and the `# then:` lines after it. */
static void expected_lines(const char *path, expectation *e)
{
    char header[LINE_MAX_LEN], sidecar[LINE_MAX_LEN];
    static const char tag[] = "# expect: ", then[] = "# then: ";
    const char *from = path;
    if (ends_with(path, ".json")) {
        snprintf(sidecar, sizeof sidecar, "%.*s.expect", (int)(strlen(path) - 5), path);
        from = sidecar;
    }
    FILE *f = fopen(from, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", from);
    e->count = 0;
    while (e->count < MAX_EXPECT && fgets(header, sizeof header, f)) {
        header[strcspn(header, "\r\n")] = '\0';
        const char *want = e->count == 0 ? tag : then;
        size_t n = strlen(want);
        if (strncmp(header, want, n) != 0)
            break;
        expected_text(path, header + n, e->lines[e->count++], sizeof e->lines[0]);
    }
    fclose(f);
    ck_assert_msg(e->count > 0, "%s: first line is not '# expect: ...'", path);
}

static void first_line_of(const char *text, char *line, size_t size)
{
    size_t n = strcspn(text, "\n");
    if (n >= size)
        n = size - 1;
    memcpy(line, text, n);
    line[n] = '\0';
}

/* The first line of text is e's first line, and e's later lines follow
 * in order, each a whole line. */
static void check_output(const char *who, const char *text, const expectation *e)
{
    char line[LINE_MAX_LEN];
    first_line_of(text, line, sizeof line);
    ck_assert_msg(strcmp(line, e->lines[0]) == 0, "%s:\n  got  %s\n  want %s", who, line, e->lines[0]);
    const char *at = text + strcspn(text, "\n");
    for (int k = 1; k < e->count; k++) {
        for (;;) {
            ck_assert_msg(*at, "%s: no line\n  %s\nafter the ones before; the output is\n%s", who, e->lines[k], text);
            at++;
            first_line_of(at, line, sizeof line);
            at += strcspn(at, "\n");
            if (strcmp(line, e->lines[k]) == 0)
                break;
        }
    }
}

/* (a) through the library. */
static void check_library(const char *path, const expectation *e)
{
    char *out = NULL;
    size_t size;
    int status;
    FILE *f = open_memstream(&out, &size);
    ck_assert_ptr_nonnull(f);
    scene_model *s = scene_file_load(path, NULL, f, 1, &status);
    fclose(f);
    scene_free(s);
    ck_assert_msg(s == NULL, "%s loaded", path);
    ck_assert_msg(status == STATUS_DATA, "%s: status %d, expected STATUS_DATA", path, status);
    check_output(path, out, e);
    free(out);
}

/* Runs `refray check path` with stderr into a pipe; returns the exit code
 * (-1 when it did not exit normally) and stderr (its first size - 1 bytes). */
static int run_cli(const char *path, char *buf, size_t size)
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
    size_t used = 0;
    ssize_t got;
    while (used < size - 1 && (got = read(fds[0], buf + used, size - 1 - used)) > 0)
        used += (size_t)got;
    /* Drain the rest so the child never blocks on a full pipe. */
    char sink[4096];
    while (used == size - 1 && read(fds[0], sink, sizeof sink) > 0)
        ;
    close(fds[0]);
    buf[used] = '\0';
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* (b) through the command line. */
static void check_cli(const char *path, const expectation *e)
{
    static char out[LINE_MAX_LEN * 16];
    char who[PATH_MAX_LEN + 32];
    int code = run_cli(path, out, sizeof out);
    snprintf(who, sizeof who, "refray check %s", path);
    ck_assert_msg(code == 65, "%s: exit %d, expected 65", who, code);
    check_output(who, out, e);
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
    char path[PATH_MAX_LEN];
    static expectation e;
    corpus_read(&c);
    ck_assert_msg(_i < c.count, "no bad scene number %d (%d files)", _i, c.count);
    snprintf(path, sizeof path, "%s/%s", BAD_DIR, c.names[_i]);
    expected_lines(path, &e);
    check_library(path, &e);
    check_cli(path, &e);
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
