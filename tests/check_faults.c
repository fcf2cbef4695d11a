/*
 * Faults from the outside world, through the refray program itself: missing
 * and unreadable inputs, an include of a directory, output directories that
 * do not exist or cannot be written, a full disk, SIGINT during a render,
 * NUL bytes, invalid UTF-8, CRLF, a 1 MB line, 1e400 and -0.  Each must give
 * a clear message, its documented exit code, no crash, and no file left
 * behind.  The program is REFRAY_BIN (set by `make test`), else build/refray.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "testlib.h"

enum { ERR_MAX = 8192 };

typedef struct run_result {
    int status;            /* exit code, or 128 + signal */
    char err[ERR_MAX];     /* the start of stderr */
} run_result;

static const char *refray_bin(void)
{
    const char *bin = getenv("REFRAY_BIN");
    return bin && *bin ? bin : "build/refray";
}

static char work_dir[256];

/* A fresh directory for one test's files. */
static void make_work_dir(void)
{
    snprintf(work_dir, sizeof work_dir, "/tmp/refray-faults-XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(work_dir));
}

static void path_in(char *out, size_t size, const char *name)
{
    snprintf(out, size, "%s/%s", work_dir, name);
}

static void write_file(const char *name, const char *data, size_t len)
{
    char path[512];
    path_in(path, sizeof path, name);
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    ck_assert_uint_eq(fwrite(data, 1, len, f), len);
    ck_assert_int_eq(fclose(f), 0);
}

/* Runs refray with args (NULL-terminated), stdout to out_path or /dev/null. */
static run_result run(const char *out_path, const char *const *args)
{
    run_result r;
    int pipefd[2];
    memset(&r, 0, sizeof r);
    ck_assert_int_eq(pipe(pipefd), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        const char *argv[32];
        int n = 0;
        argv[n++] = refray_bin();
        for (int i = 0; args[i] && n < 31; i++)
            argv[n++] = args[i];
        argv[n] = NULL;
        int out = open(out_path ? out_path : "/dev/null", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(out, 1);
        dup2(pipefd[1], 2);
        close(pipefd[0]);
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    close(pipefd[1]);
    size_t got = 0;
    ssize_t k;
    char sink[4096];
    while ((k = read(pipefd[0], got < ERR_MAX - 1 ? r.err + got : sink,
                     got < ERR_MAX - 1 ? ERR_MAX - 1 - got : sizeof sink)) > 0)
        got += got < ERR_MAX - 1 ? (size_t)k : 0;
    close(pipefd[0]);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

/* Files in the work directory whose name starts with prefix. */
static int count_files(const char *prefix)
{
    DIR *d = opendir(work_dir);
    int n = 0;
    struct dirent *e;
    ck_assert_ptr_nonnull(d);
    while ((e = readdir(d)))
        n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    closedir(d);
    return n;
}

#define ASSERT_ERR_HAS(r, text) \
    ck_assert_msg(strstr((r).err, (text)) != NULL, "stderr lacks \"%s\":\n%s", (text), (r).err)

static const char tiny_scene[] = "image { width 4 height 3 }\nsphere { }\n";

START_TEST(test_faults_missing_scene_is_66)
{
    const char *args[] = {"check", "/nonexistent/nothing.scene", NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 66);
    ASSERT_ERR_HAS(r, "cannot open '/nonexistent/nothing.scene': No such file or directory");
}
END_TEST

START_TEST(test_faults_scene_that_is_a_directory_is_66)
{
    make_work_dir();
    const char *args[] = {"check", work_dir, NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 66);
    ASSERT_ERR_HAS(r, "is a directory");
}
END_TEST

START_TEST(test_faults_include_of_a_directory_is_65)
{
    char path[512], sub[512];
    make_work_dir();
    path_in(sub, sizeof sub, "sub");
    ck_assert_int_eq(mkdir(sub, 0755), 0);
    static const char scene[] = "include \"sub\"\nsphere { }\n";
    write_file("a.scene", scene, sizeof scene - 1);
    path_in(path, sizeof path, "a.scene");
    const char *args[] = {"check", path, NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 65);
    ASSERT_ERR_HAS(r, "a.scene:1:9: error: '");
    ASSERT_ERR_HAS(r, "/sub' is a directory, not a file");
}
END_TEST

START_TEST(test_faults_output_directory_missing_is_74_and_nothing_is_written)
{
    char scene[512];
    make_work_dir();
    write_file("s.scene", tiny_scene, sizeof tiny_scene - 1);
    path_in(scene, sizeof scene, "s.scene");
    const char *args[] = {"render", scene, "-o", "/nonexistent-dir/out.pfm", "-q", NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 74);
    ASSERT_ERR_HAS(r, "cannot write into '/nonexistent-dir'");
}
END_TEST

START_TEST(test_faults_output_onto_a_non_file_is_refused)
{
    /* A directory named like the output must not be replaced. */
    char scene[512], target[512];
    make_work_dir();
    write_file("s.scene", tiny_scene, sizeof tiny_scene - 1);
    path_in(scene, sizeof scene, "s.scene");
    path_in(target, sizeof target, "out.pfm");
    ck_assert_int_eq(mkdir(target, 0755), 0);
    const char *args[] = {"render", scene, "-o", target, "-q", NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 74);
    ASSERT_ERR_HAS(r, "exists and is not a regular file");
    struct stat sb;
    ck_assert_int_eq(stat(target, &sb), 0);
    ck_assert(S_ISDIR(sb.st_mode));
    ck_assert_int_eq(count_files("out.pfm.tmp"), 0);
}
END_TEST

START_TEST(test_faults_full_disk_is_74)
{
    /* Standard output on /dev/full: every write fails with ENOSPC. */
    char scene[512];
    make_work_dir();
    write_file("s.scene", tiny_scene, sizeof tiny_scene - 1);
    path_in(scene, sizeof scene, "s.scene");
    const char *args[] = {"render", scene, "-o", "-", "--format", "pfm", "-q", NULL};
    run_result r = run("/dev/full", args);
    ck_assert_int_eq(r.status, 74);
    ASSERT_ERR_HAS(r, "No space left on device");
}
END_TEST

START_TEST(test_faults_sigint_leaves_no_file_and_exits_130)
{
    /* A render long enough to be interrupted: SIGINT after it started.  PFM,
     * so the case also runs in a build without libpng. */
    static const char slow[] = "image { width 400 height 400 samples 4 }\n"
                               "distributed_light { rectangle [-1, 5, -1] [2, 0, 0] [0, 0, 2] samples 256 }\n"
                               "plane { point [0, -1, 0] }\nsphere { }\n";
    char scene[512], out[512];
    make_work_dir();
    write_file("s.scene", slow, sizeof slow - 1);
    path_in(scene, sizeof scene, "s.scene");
    path_in(out, sizeof out, "out.pfm");
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execl(refray_bin(), refray_bin(), "render", scene, "-o", out, "-q", (char *)NULL);
        _exit(127);
    }
    /* Under valgrind the program needs seconds to reach main. */
    const char *vg = getenv("REFRAY_TEST_VALGRIND");
    struct timespec pause = {vg && strcmp(vg, "1") == 0 ? 5 : 0, 300 * 1000 * 1000};
    nanosleep(&pause, NULL);
    ck_assert_int_eq(kill(pid, SIGINT), 0);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 130, "status %d", status);
    ck_assert_int_eq(count_files("out.pfm"), 0);
}
END_TEST

/* Scene text with awkward bytes, each a clear error with its location. */
START_TEST(test_faults_awkward_bytes_are_located_errors)
{
    static const struct {
        const char *name;
        const char *text;
        size_t len;
        const char *message;
    } cases[] = {
        {"nul.scene", "sphere { radius 1 }\n\0\n", 22, "nul.scene:2:1: error: NUL byte in the scene text"},
        {"utf8.scene", "sphere { \xc3\x28 }\n", 14, "utf8.scene:1:10: error: non-ASCII byte"},
        {"crlf.scene", "sphere {\r\n radius -1 }\r\n", 24, "crlf.scene:2:9: error: radius must be > 0, got -1"},
        {"huge.scene", "sphere { radius 1e400 }\n", 24, "huge.scene:1:17: error: number out of range"},
    };
    make_work_dir();
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char path[512];
        write_file(cases[i].name, cases[i].text, cases[i].len);
        path_in(path, sizeof path, cases[i].name);
        const char *args[] = {"check", path, NULL};
        run_result r = run(NULL, args);
        ck_assert_int_eq(r.status, 65);
        ASSERT_ERR_HAS(r, cases[i].message);
    }
}
END_TEST

START_TEST(test_faults_negative_zero_is_a_number)
{
    char path[512];
    static const char scene[] = "sphere { center [-0, -0.0, 0] radius 1 }\n";
    make_work_dir();
    write_file("z.scene", scene, sizeof scene - 1);
    path_in(path, sizeof path, "z.scene");
    const char *args[] = {"check", path, NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 0);
}
END_TEST

START_TEST(test_faults_megabyte_line_is_shown_as_a_window)
{
    /* A 1 MB line with the error at its end: the message must come fast
     * and the excerpt must stay one screen wide. */
    enum { LINE = 1 << 20 };
    char *text = malloc(LINE + 64), path[512];
    ck_assert_ptr_nonnull(text);
    memcpy(text, "sphere { ", 9);
    memset(text + 9, ' ', LINE);
    memcpy(text + 9 + LINE, "radius -1 }\n", 12);
    make_work_dir();
    write_file("long.scene", text, 9 + LINE + 12);
    free(text);
    path_in(path, sizeof path, "long.scene");
    const char *args[] = {"check", path, NULL};
    run_result r = run(NULL, args);
    ck_assert_int_eq(r.status, 65);
    ASSERT_ERR_HAS(r, "long.scene:1:1048593: error: radius must be > 0, got -1");
    ck_assert_msg(strlen(r.err) < 1000, "the excerpt is %zu bytes", strlen(r.err));
}
END_TEST

Suite *suite_faults(void)
{
    Suite *s = suite_create("faults");
    TCase *inputs = tcase_create("inputs");
    tcase_add_test(inputs, test_faults_missing_scene_is_66);
    tcase_add_test(inputs, test_faults_scene_that_is_a_directory_is_66);
    tcase_add_test(inputs, test_faults_include_of_a_directory_is_65);
    tcase_add_test(inputs, test_faults_awkward_bytes_are_located_errors);
    tcase_add_test(inputs, test_faults_negative_zero_is_a_number);
    tcase_add_test(inputs, test_faults_megabyte_line_is_shown_as_a_window);
    suite_add_tcase(s, inputs);
    TCase *outputs = tcase_create("outputs");
    tcase_set_timeout(outputs, 30);
    tcase_add_test(outputs, test_faults_output_directory_missing_is_74_and_nothing_is_written);
    tcase_add_test(outputs, test_faults_output_onto_a_non_file_is_refused);
    tcase_add_test(outputs, test_faults_full_disk_is_74);
    tcase_add_test(outputs, test_faults_sigint_leaves_no_file_and_exits_130);
    suite_add_tcase(s, outputs);
    return s;
}
