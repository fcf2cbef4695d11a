/*
 * check_proc.c - the pieces `refray conform` stands on: running a shell
 * command in its own process group with a time limit (base/proc.h),
 * cleaning another program's bytes (base/text.h), and the atomic writer and
 * directory trees of base/fileio.h (spec/conformance.md [CONF-RUN-1],
 * [CONF-RUN-2], [CONF-REPORT-2]).
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "io/filewrite.h"
#include "io/proc.h"
#include "base/status.h"
#include "base/text.h"
#include "cli_testlib.h"

/* Valgrind runs the shell under it too: give commands more time there. */
static double slow(void)
{
    const char *v = getenv("REFRAY_TEST_VALGRIND");
    return v && strcmp(v, "1") == 0 ? 20 : 1;
}

static void read_text(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
}

/* Runs command in dir with out/err files there; returns the result. */
static proc_result run(const char *dir, const char *command, double timeout, const volatile sig_atomic_t *stop)
{
    char out[300], err[300], why[256];
    proc_result r;
    proc_opts o = {dir, cli_path(out, sizeof out, dir, "out.txt"), cli_path(err, sizeof err, dir, "err.txt"),
                   timeout, stop};
    ck_assert_int_eq(proc_run_shell(command, &o, &r, why, sizeof why), 0);
    return r;
}

/* [CONF-RUN-1] exit status, standard output and error in their files,
 * the working directory, standard input from /dev/null (cat ends). */
START_TEST(test_proc_run_shell_exit_and_files)
{
    char dir[64], path[300], text[512];
    cli_scratch(dir, sizeof dir, "proc");
    proc_result r = run(dir, "echo to-out; echo to-err >&2; pwd > where; cat; exit 7", 10 * slow(), NULL);
    ck_assert(r.exited && !r.signaled && !r.timed_out && !r.stopped);
    ck_assert_int_eq(r.exit_code, 7);
    read_text(cli_path(path, sizeof path, dir, "out.txt"), text, sizeof text);
    ck_assert_str_eq(text, "to-out\n");
    read_text(cli_path(path, sizeof path, dir, "err.txt"), text, sizeof text);
    ck_assert_str_eq(text, "to-err\n");
    read_text(cli_path(path, sizeof path, dir, "where"), text, sizeof text);
    ck_assert_msg(strncmp(text, dir, strlen(dir)) == 0, "pwd %s, expected %s", text, dir);
    cli_remove(dir);
}
END_TEST

START_TEST(test_proc_run_shell_signal)
{
    char dir[64], buf[32];
    cli_scratch(dir, sizeof dir, "proc");
    proc_result r = run(dir, "kill -TERM $$", 10 * slow(), NULL);
    ck_assert(r.signaled && !r.exited);
    ck_assert_int_eq(r.term_signal, SIGTERM);
    ck_assert_str_eq(proc_signal_name(SIGSEGV, buf, sizeof buf), "SIGSEGV");
    ck_assert_str_eq(proc_signal_name(77, buf, sizeof buf), "signal 77");
    cli_remove(dir);
}
END_TEST

/* A process is gone: no /proc entry, or a zombie waiting for its parent. */
static int gone(long pid)
{
    char path[64], stat[256];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 1;
    size_t n = fread(stat, 1, sizeof stat - 1, f);
    fclose(f);
    stat[n] = '\0';
    const char *close = strrchr(stat, ')');
    return close && close[1] == ' ' && (close[2] == 'Z' || close[2] == 'X');
}

/* Waits up to a second for pid to be gone; returns gone(pid). */
static int wait_gone(long pid)
{
    struct timespec ten_ms = {0, 10000000};
    for (int i = 0; i < 100 && !gone(pid); i++)
        nanosleep(&ten_ms, NULL);
    return gone(pid);
}

static long read_pid(const char *dir)
{
    char path[300], text[64];
    read_text(cli_path(path, sizeof path, dir, "pid"), text, sizeof text);
    return strtol(text, NULL, 10);
}

/* [CONF-RUN-2] Past the time limit the whole group dies, the shell's
 * background child too, well before the command would have ended. */
START_TEST(test_proc_run_shell_timeout_kills_the_group)
{
    char dir[64];
    cli_scratch(dir, sizeof dir, "proc");
    proc_result r = run(dir, "sleep 300 & echo $! > pid; sleep 300", 0.3 * slow(), NULL);
    ck_assert(r.timed_out && !r.exited && !r.signaled);
    ck_assert_msg(r.seconds >= 0.3 * slow() && r.seconds < 10 * slow(), "took %g s", r.seconds);
    long pid = read_pid(dir);
    ck_assert_msg(wait_gone(pid), "the background sleep %ld outlived its group", pid);
    cli_remove(dir);
}
END_TEST

/* What a command leaves running in its group when it exits is killed. */
START_TEST(test_proc_run_shell_kills_leftovers)
{
    char dir[64];
    cli_scratch(dir, sizeof dir, "proc");
    proc_result r = run(dir, "sleep 300 & echo $! > pid", 10 * slow(), NULL);
    ck_assert(r.exited && r.exit_code == 0);
    long pid = read_pid(dir);
    ck_assert_msg(wait_gone(pid), "the background sleep %ld outlived the command", pid);
    cli_remove(dir);
}
END_TEST

START_TEST(test_proc_run_shell_stop_flag)
{
    char dir[64];
    static volatile sig_atomic_t stop = 1;
    cli_scratch(dir, sizeof dir, "proc");
    proc_result r = run(dir, "sleep 300", 0, &stop);
    ck_assert(r.stopped && !r.exited);
    ck_assert_msg(r.seconds < 5 * slow(), "took %g s", r.seconds);
    cli_remove(dir);
}
END_TEST

/* [CONF-REPORT-2] Bytes that are not UTF-8 or are control characters
 * become '?', CR LF a line feed, whole UTF-8 sequences are kept. */
START_TEST(test_text_clean)
{
    char out[64];
    static const char in[] = "a\x01" "b\xff" "c\r\nd\te\xc3\xa9" "f\xc0\x80" "g\xed\xa0\x80" "h\rz\xe2\x82";
    text_clean(in, sizeof in - 1, out, sizeof out);
    ck_assert_str_eq(out, "a?b?c\nd\te\xc3\xa9" "f??g???h\nz??");
    /* A sequence that does not fit whole is left out. */
    ck_assert_int_eq((int)text_clean("ab\xc3\xa9", 4, out, 4), 2);
    ck_assert_str_eq(out, "ab");
}
END_TEST

START_TEST(test_text_tail)
{
    static const char t[] = "one\ntwo\nthree\nfour\n\n";
    size_t n = sizeof t - 1;
    ck_assert_str_eq(t + text_tail(t, n, 2, 100), "three\nfour\n\n");
    ck_assert_str_eq(t + text_tail(t, n, 10, 100), t);
    /* 8 bytes reach into "three": the tail begins at the next line. */
    ck_assert_str_eq(t + text_tail(t, n, 10, 8), "four\n\n");
    ck_assert_int_eq((int)text_tail("", 0, 3, 10), 0);
}
END_TEST

static int fill_fails(FILE *fp, void *ctx)
{
    (void)ctx;
    fputs("half", fp);
    return STATUS_IO;
}

/* The atomic writer leaves nothing when its filler fails; it replaces a
 * file whole; it refuses a directory in the way. */
START_TEST(test_file_write_atomic)
{
    char dir[64], path[300], text[64], why[512];
    cli_scratch(dir, sizeof dir, "fileio");
    cli_path(path, sizeof path, dir, "f.txt");
    ck_assert_int_eq(file_write_bytes(path, "first", 5, why, sizeof why), 0);
    ck_assert_int_eq(file_write_atomic(path, fill_fails, NULL, why, sizeof why), STATUS_IO);
    read_text(path, text, sizeof text);
    ck_assert_str_eq(text, "first");
    ck_assert_int_eq(file_write_bytes(path, "second", 6, why, sizeof why), 0);
    read_text(path, text, sizeof text);
    ck_assert_str_eq(text, "second");
    ck_assert_msg(cli_entries(dir) == 1, "a temporary file was left in %s", dir);
    ck_assert_int_eq(file_write_bytes(dir, "x", 1, why, sizeof why), STATUS_IO);
    ck_assert_msg(strstr(why, "not a regular file") != NULL, "why: %s", why);
    cli_remove(dir);
}
END_TEST

/* make_dirs makes the missing parents; remove_tree removes a tree with a
 * symbolic link in it without following it. */
START_TEST(test_file_dirs_and_remove_tree)
{
    char dir[64], path[300], outside[300], link[300], why[512];
    cli_scratch(dir, sizeof dir, "fileio");
    cli_path(path, sizeof path, dir, "tree/a/b/c");
    ck_assert_int_eq(file_make_dirs(path, why, sizeof why), 0);
    ck_assert_int_eq(file_make_dirs(path, why, sizeof why), 0);
    ck_assert_int_eq(file_write_bytes(cli_path(outside, sizeof outside, dir, "keep.txt"), "k", 1, why, sizeof why),
                     0);
    cli_path(link, sizeof link, dir, "tree/a/link");
    ck_assert_int_eq(symlink(dir, link), 0);
    cli_path(path, sizeof path, dir, "tree/a/b/file");
    ck_assert_int_eq(file_write_bytes(path, "x", 1, why, sizeof why), 0);
    ck_assert_int_eq(file_make_dirs(cli_path(path, sizeof path, dir, "keep.txt/x"), why, sizeof why),
                     STATUS_IO);
    ck_assert_int_eq(file_remove_tree(cli_path(path, sizeof path, dir, "tree"), why, sizeof why), 0);
    ck_assert(!cli_exists(path));
    ck_assert(cli_exists(outside));
    ck_assert_int_eq(file_remove_tree(path, why, sizeof why), 0); /* already gone */
    cli_remove(dir);
}
END_TEST

Suite *suite_proc(void)
{
    Suite *s = suite_create("proc");
    TCase *tc = tcase_create("proc");
    tcase_add_test(tc, test_proc_run_shell_exit_and_files);
    tcase_add_test(tc, test_proc_run_shell_signal);
    tcase_add_test(tc, test_proc_run_shell_timeout_kills_the_group);
    tcase_add_test(tc, test_proc_run_shell_kills_leftovers);
    tcase_add_test(tc, test_proc_run_shell_stop_flag);
    tcase_add_test(tc, test_text_clean);
    tcase_add_test(tc, test_text_tail);
    tcase_add_test(tc, test_file_write_atomic);
    tcase_add_test(tc, test_file_dirs_and_remove_tree);
    suite_add_tcase(s, tc);
    return s;
}
