/*
 * proc.c - see proc.h.
 *
 * The wait is a poll: waitid(WNOWAIT) says whether the child has ended
 * without reaping it, so its pid (and with it the process group id) cannot
 * be reused before the group is killed; between polls the parent sleeps a
 * few milliseconds.  No SIGCHLD or SIGALRM handler is needed, so the
 * library installs none.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "io/proc.h"
#include "base/status.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void nap(double seconds)
{
    struct timespec ts;
    ts.tv_sec = (time_t)seconds;
    ts.tv_nsec = (long)((seconds - (double)ts.tv_sec) * 1e9);
    nanosleep(&ts, NULL); /* an early wake-up (a signal) only polls sooner */
}

/* An output file for the child, or /dev/null; -1 with errno on failure. */
static int open_sink(const char *path)
{
    return open(path ? path : "/dev/null", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
}

/* In the child, between fork and exec: only async-signal-safe calls. */
static void child(const char *command, const char *dir, int in, int out, int err)
{
    static const char cd_failed[] = "refray: cannot enter the working directory\n";
    setpgid(0, 0);
    if (dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0)
        _exit(127);
    if (dir && chdir(dir) != 0) {
        ssize_t w = write(2, cd_failed, sizeof cd_failed - 1);
        (void)w;
        _exit(127);
    }
    execl("/bin/sh", "sh", "-c", command, (char *)NULL);
    _exit(127);
}

/* 1 when the child has ended (left unreaped), 0 while it runs, -1 on error. */
static int has_ended(pid_t pid)
{
    siginfo_t info;
    memset(&info, 0, sizeof info);
    if (waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT) != 0)
        return errno == EINTR ? 0 : -1;
    return info.si_pid == pid;
}

/* Polls until the child ends, the time is up or *stop is set. */
static void wait_for(pid_t pid, const proc_opts *o, double start, proc_result *r)
{
    double step = 0.001;
    for (;;) {
        int ended = has_ended(pid);
        if (ended != 0)
            return;
        if (o->stop && *o->stop) {
            r->stopped = 1;
            return;
        }
        double left = o->timeout > 0 ? start + o->timeout - now() : 1;
        if (left <= 0) {
            r->timed_out = 1;
            return;
        }
        nap(step < left ? step : left);
        step = step < 0.02 ? 2 * step : 0.02;
    }
}

static void reap(pid_t pid, proc_result *r)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        continue;
    if (r->timed_out || r->stopped)
        return;
    if (WIFEXITED(status)) {
        r->exited = 1;
        r->exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        r->signaled = 1;
        r->term_signal = WTERMSIG(status);
    }
}

int proc_run_shell(const char *command, const proc_opts *o, proc_result *r, char *why, size_t why_size)
{
    memset(r, 0, sizeof *r);
    int in = open("/dev/null", O_RDONLY | O_CLOEXEC);
    int out = open_sink(o->out_path), err = open_sink(o->err_path);
    if (in < 0 || out < 0 || err < 0) {
        snprintf(why, why_size, "cannot open the files for the command's output: %s", strerror(errno));
        if (in >= 0)
            close(in);
        if (out >= 0)
            close(out);
        if (err >= 0)
            close(err);
        return STATUS_IO;
    }
    double start = now();
    pid_t pid = fork();
    if (pid == 0)
        child(command, o->dir, in, out, err);
    int fork_errno = errno;
    close(in);
    close(out);
    close(err);
    if (pid < 0) {
        snprintf(why, why_size, "cannot start a process: %s", strerror(fork_errno));
        return STATUS_INTERNAL;
    }
    /* Also here, so the group exists before any kill below, whichever of
     * the two runs first; it fails harmlessly once the child has exec'd. */
    setpgid(pid, pid);
    wait_for(pid, o, start, r);
    kill(-pid, SIGKILL);
    reap(pid, r);
    r->seconds = now() - start;
    return STATUS_OK;
}

const char *proc_signal_name(int sig, char *buf, size_t size)
{
    static const struct { int sig; const char *name; } names[] = {
        {SIGHUP, "SIGHUP"},   {SIGINT, "SIGINT"},   {SIGQUIT, "SIGQUIT"}, {SIGILL, "SIGILL"},
        {SIGTRAP, "SIGTRAP"}, {SIGABRT, "SIGABRT"}, {SIGBUS, "SIGBUS"},   {SIGFPE, "SIGFPE"},
        {SIGKILL, "SIGKILL"}, {SIGUSR1, "SIGUSR1"}, {SIGSEGV, "SIGSEGV"}, {SIGUSR2, "SIGUSR2"},
        {SIGPIPE, "SIGPIPE"}, {SIGALRM, "SIGALRM"}, {SIGTERM, "SIGTERM"}, {SIGXCPU, "SIGXCPU"},
        {SIGXFSZ, "SIGXFSZ"}, {SIGSYS, "SIGSYS"},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (names[i].sig == sig)
            return names[i].name;
    snprintf(buf, size, "signal %d", sig);
    return buf;
}
