/*
 * proc.h - running a shell command as a child process, in its own process
 * group and directory, with its output in files and a time limit: what
 * `refray conform` needs to run another program without trusting it.
 *
 * Nothing here touches signal dispositions or other process-wide state:
 * the caller that wants Ctrl-C to stop a run passes the flag its own
 * handler sets, and the run polls it.
 */
#ifndef REFRAY_PROC_H
#define REFRAY_PROC_H

#include <signal.h>
#include <stddef.h>

typedef struct proc_opts {
    const char *dir;       /* the working directory, or NULL for ours */
    const char *out_path;  /* standard output into this file (truncated), or NULL: /dev/null */
    const char *err_path;  /* standard error likewise */
    double timeout;        /* seconds of wall time; <= 0: none */
    const volatile sig_atomic_t *stop;  /* polled; non-zero stops the run; may be NULL */
} proc_opts;

typedef struct proc_result {
    int exited;            /* 1: it exited by itself, with exit_code */
    int exit_code;
    int signaled;          /* 1: a signal ended it (not one of ours), term_signal */
    int term_signal;
    int timed_out;         /* 1: the time limit passed and the group was killed */
    int stopped;           /* 1: *stop became non-zero and the group was killed */
    double seconds;        /* wall time from start to end */
} proc_result;

/*
 * Runs `/bin/sh -c command` with standard input from /dev/null, as the
 * leader of a new process group, so that the whole group (the shell and
 * everything it started) can be killed with one kill(2).  Waits until it
 * ends, the timeout passes or *stop is set; in the last two cases sends
 * SIGKILL to the group.  When it ends by itself, whatever it left running
 * in its group is killed too.  Returns STATUS_OK with r filled (whatever
 * the command did), or STATUS_IO (its output files cannot be opened) /
 * STATUS_INTERNAL (no process can be started) with the reason in why.
 */
int proc_run_shell(const char *command, const proc_opts *o, proc_result *r, char *why, size_t why_size);

/* "SIGSEGV" and the like for the common signals, else "signal N" in buf. */
const char *proc_signal_name(int sig, char *buf, size_t size);

#endif
