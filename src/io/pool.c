/*
 * pool.c - see pool.h.
 *
 * Each worker has one socket pair (AF_UNIX, SOCK_STREAM): the parent
 * writes a job number (int32; -1: no more jobs), the worker answers with
 * frames, a header then len bytes: MESSAGE frames from pool_send, then one
 * DONE frame with the job's status.  Only the worker writes its end and
 * only the parent reads it, so frames never interleave.  The parent sends
 * with MSG_NOSIGNAL: a worker that died makes a send fail, not the parent.
 * A worker that dies shows as end of file on its socket; waitpid then says
 * how.
 */
#include <errno.h>
#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include "base/status.h"
#include "io/pool.h"
#include "io/proc.h"

enum { FRAME_MESSAGE = 1, FRAME_DONE = 2 };

typedef struct frame {
    int32_t kind;
    int32_t job;
    int32_t status;   /* DONE: the job's status */
    uint32_t len;     /* MESSAGE: bytes that follow */
} frame;

struct pool_link {
    int fd;              /* the worker's socket; -1: jobs run in this process */
    int job;
    const pool_ops *ops;
    int status;          /* in this process: the first status message refused with */
};

/* ---- Both sides ---- */

/* Writes n bytes; 0, or -1 (the other side has gone). */
static int write_all(int fd, const void *p, size_t n, int flags)
{
    const char *b = p;
    while (n > 0) {
        ssize_t k = flags ? send(fd, b, n, flags) : write(fd, b, n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return -1;
        b += k;
        n -= (size_t)k;
    }
    return 0;
}

/* Reads n bytes: 1, 0 at end of file before the first byte, -1 on an
 * error or an end in the middle, -2 when *stop was set during the wait. */
static int read_all(int fd, void *p, size_t n, const volatile sig_atomic_t *stop)
{
    char *b = p;
    size_t got = 0;
    while (got < n) {
        ssize_t k = read(fd, b + got, n - got);
        if (k < 0 && errno == EINTR) {
            if (stop && *stop)
                return -2;
            continue;
        }
        if (k <= 0)
            return k == 0 && got == 0 ? 0 : -1;
        got += (size_t)k;
    }
    return 1;
}

int pool_send(pool_link *link, const void *data, size_t len)
{
    if (link->fd < 0) {
        int rc = link->ops->message(link->ops->ctx, link->job, data, len);
        if (rc != STATUS_OK && link->status == STATUS_OK)
            link->status = rc;
        return rc == STATUS_OK ? 0 : -1;
    }
    frame f = {FRAME_MESSAGE, link->job, 0, (uint32_t)len};
    return write_all(link->fd, &f, sizeof f, 0) == 0 && write_all(link->fd, data, len, 0) == 0 ? 0 : -1;
}

/* ---- The worker ---- */

/* Never returns: jobs until the parent says -1 or goes. */
static void worker_main(int fd, const pool_ops *ops)
{
    pool_link link = {fd, -1, ops, STATUS_OK};
    int32_t job = -1;
    signal(SIGINT, SIG_IGN);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    while (read_all(fd, &job, sizeof job, NULL) == 1 && job >= 0) {
        link.job = job;
        frame f = {FRAME_DONE, job, ops->work(ops->ctx, job, &link), 0};
        if (write_all(fd, &f, sizeof f, 0) != 0 || f.status != STATUS_OK)
            _exit(0);
    }
    if (job < 0 && ops->finish) {
        link.job = -1;
        ops->finish(ops->ctx, &link);
    }
    _exit(0);
}

/* ---- The parent ---- */

enum { W_BUSY, W_STOPPING, W_GONE };

typedef struct worker {
    pid_t pid;
    int fd;
    int job;
    int state;
} worker;

typedef struct pool_run_state {
    worker *w;
    int count;           /* workers started */
    int next, jobs;      /* the next job to hand out */
    const pool_ops *ops;
    const volatile sig_atomic_t *stop;
    char *buf;           /* a message's bytes */
    size_t cap;
    pool_failure *fail;
    char *why;
    size_t why_size;
} pool_run_state;

static void blame(pool_run_state *p, int i, const char *fmt, const char *detail)
{
    p->fail->job = p->w[i].job;
    p->fail->worker = i + 1;
    p->fail->pid = (long)p->w[i].pid;
    snprintf(p->why, p->why_size, fmt, i + 1, (long)p->w[i].pid, detail);
}

/* Reaps worker i; STATUS_OK when it exited 0 after it was told to stop. */
static int reap(pool_run_state *p, int i)
{
    int status = 0;
    char name[32], code[32];
    while (waitpid(p->w[i].pid, &status, 0) < 0 && errno == EINTR)
        continue;
    close(p->w[i].fd);
    int asked = p->w[i].state == W_STOPPING;
    p->w[i].state = W_GONE;
    if (asked && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return STATUS_OK;
    if (WIFSIGNALED(status)) {
        p->fail->term_signal = WTERMSIG(status);
        blame(p, i, "worker %d (pid %ld) was killed by %s", proc_signal_name(WTERMSIG(status), name, sizeof name));
    } else {
        p->fail->exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        snprintf(code, sizeof code, "%d", p->fail->exit_code);
        blame(p, i, "worker %d (pid %ld) exited with code %s before its work was done", code);
    }
    return STATUS_INTERNAL;
}

/* Gives worker i its next job, or tells it to stop. */
static void hand_out(pool_run_state *p, int i)
{
    int32_t job = p->next < p->jobs ? p->next++ : -1;
    if (job >= 0)
        p->w[i].job = job;
    else
        p->w[i].state = W_STOPPING;
    /* A send to a worker that died fails here and shows as its end of
     * file at the next poll. */
    (void)write_all(p->w[i].fd, &job, sizeof job, MSG_NOSIGNAL);
}

static int take_message(pool_run_state *p, int i, const frame *f)
{
    if (f->len > p->cap) {
        char *b = realloc(p->buf, f->len);
        if (!b) {
            snprintf(p->why, p->why_size, "out of memory");
            return STATUS_NO_MEMORY;
        }
        p->buf = b;
        p->cap = f->len;
    }
    int r = f->len ? read_all(p->w[i].fd, p->buf, f->len, p->stop) : 1;
    if (r == -2)
        return STATUS_CANCELLED;
    if (r != 1)
        return reap(p, i);
    return p->ops->message(p->ops->ctx, f->job, p->buf, f->len);
}

/* Reads one frame of worker i and acts on it. */
static int serve(pool_run_state *p, int i)
{
    frame f;
    int r = read_all(p->w[i].fd, &f, sizeof f, p->stop);
    if (r == -2)
        return STATUS_CANCELLED;
    if (r != 1)
        return reap(p, i);
    if (f.kind == FRAME_MESSAGE)
        return take_message(p, i, &f);
    if (f.status != STATUS_OK) {
        p->fail->job = f.job;
        p->fail->worker = i + 1;
        p->fail->pid = (long)p->w[i].pid;
        return f.status;
    }
    int rc = p->ops->done ? p->ops->done(p->ops->ctx, f.job) : STATUS_OK;
    if (rc == STATUS_OK)
        hand_out(p, i);
    return rc;
}

/* Starts worker i: its socket pair and process. */
static int start(pool_run_state *p, int i)
{
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0) {
        snprintf(p->why, p->why_size, "cannot make a socket for worker %d: %s", i + 1, strerror(errno));
        return STATUS_INTERNAL;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        for (int k = 0; k < i; k++)
            close(p->w[k].fd);
        close(sv[0]);
        worker_main(sv[1], p->ops);
    }
    int e = errno;
    close(sv[1]);
    if (pid < 0) {
        close(sv[0]);
        snprintf(p->why, p->why_size, "cannot start worker %d: %s", i + 1, strerror(e));
        return STATUS_INTERNAL;
    }
    p->w[i].pid = pid;
    p->w[i].fd = sv[0];
    p->w[i].state = W_BUSY;
    p->count = i + 1;
    hand_out(p, i);
    return STATUS_OK;
}

/* Kills and reaps every worker still there. */
static void stop_all(pool_run_state *p)
{
    for (int i = 0; i < p->count; i++)
        if (p->w[i].state != W_GONE)
            kill(p->w[i].pid, SIGKILL);
    for (int i = 0; i < p->count; i++)
        if (p->w[i].state != W_GONE) {
            while (waitpid(p->w[i].pid, NULL, 0) < 0 && errno == EINTR)
                continue;
            close(p->w[i].fd);
            p->w[i].state = W_GONE;
        }
}

/* Serves the workers until all have stopped or something failed. */
static int serve_all(pool_run_state *p)
{
    struct pollfd fds[256];
    int who[256];
    for (;;) {
        if (p->stop && *p->stop)
            return STATUS_CANCELLED;
        int n = 0;
        for (int i = 0; i < p->count; i++)
            if (p->w[i].state != W_GONE) {
                fds[n].fd = p->w[i].fd;
                fds[n].events = POLLIN;
                fds[n].revents = 0;
                who[n++] = i;
            }
        if (n == 0)
            return STATUS_OK;
        /* A stop that comes between the check above and poll is seen
         * within the timeout. */
        int ready = poll(fds, (nfds_t)n, 100);
        if (ready < 0 && errno != EINTR) {
            snprintf(p->why, p->why_size, "cannot wait for the workers: %s", strerror(errno));
            return STATUS_INTERNAL;
        }
        for (int k = 0; ready > 0 && k < n; k++) {
            if (!fds[k].revents)
                continue;
            int rc = serve(p, who[k]);
            if (rc != STATUS_OK)
                return rc;
        }
    }
}

/* The jobs one after another, here. */
static int run_here(int jobs, const pool_ops *ops, const volatile sig_atomic_t *stop, pool_failure *fail)
{
    pool_link link = {-1, -1, ops, STATUS_OK};
    for (int job = 0; job < jobs; job++) {
        if (stop && *stop)
            return STATUS_CANCELLED;
        link.job = job;
        int rc = ops->work(ops->ctx, job, &link);
        if (rc == STATUS_OK && link.status != STATUS_OK)
            rc = link.status;
        if (rc == STATUS_OK && ops->done)
            rc = ops->done(ops->ctx, job);
        if (rc != STATUS_OK) {
            fail->job = job;
            return rc;
        }
    }
    if (ops->finish) {
        link.job = -1;
        ops->finish(ops->ctx, &link);
    }
    return link.status;
}

int pool_run(int workers, int jobs, const pool_ops *ops, const volatile sig_atomic_t *stop, pool_failure *fail,
             char *why, size_t why_size)
{
    worker w[256];
    pool_run_state p = {w, 0, 0, jobs, ops, stop, NULL, 0, fail, why, why_size};
    memset(fail, 0, sizeof *fail);
    fail->job = -1;
    fail->exit_code = -1;
    why[0] = '\0';
    if (workers < 1)
        return run_here(jobs, ops, stop, fail);
    if (workers > jobs)
        workers = jobs;
    if (workers > (int)(sizeof w / sizeof w[0]))
        workers = (int)(sizeof w / sizeof w[0]);
    int rc = STATUS_OK;
    for (int i = 0; i < workers && rc == STATUS_OK; i++)
        rc = start(&p, i);
    if (rc == STATUS_OK)
        rc = serve_all(&p);
    stop_all(&p);
    free(p.buf);
    return rc;
}

int pool_cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > 256 ? 256 : (int)n;
}
