/*
 * testrun.c - see testrun.h.  stdout and stderr go to temporary files, so
 * a child that writes much cannot block on a full pipe.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "testlib.h"
#include "testrun.h"

static void read_start(FILE *f, char *buf, size_t size)
{
    if (!buf || !size)
        return;
    rewind(f);
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
}

int testrun_refray(const char *const argv[], char *out, size_t out_size, char *err, size_t err_size)
{
    const char *bin = getenv("REFRAY_BIN");
    if (!bin || !*bin)
        bin = "build/refray";
    ck_assert_msg(access(bin, X_OK) == 0, "no refray binary at %s (set REFRAY_BIN)", bin);
    FILE *o = tmpfile(), *e = tmpfile();
    ck_assert_ptr_nonnull(o);
    ck_assert_ptr_nonnull(e);
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        dup2(fileno(o), 1);
        dup2(fileno(e), 2);
        execv(bin, (char *const *)argv);
        _exit(127);
    }
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    read_start(o, out, out_size);
    read_start(e, err, err_size);
    fclose(o);
    fclose(e);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
