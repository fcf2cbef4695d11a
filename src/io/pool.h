/*
 * pool.h - jobs spread over worker processes (refray render --jobs,
 * refray verify --jobs).  A worker is a copy of this process made by
 * fork(2), single-threaded, with everything the parent had loaded; it
 * takes one job at a time from the parent and sends messages back on its
 * own socket.  The parent hands out the jobs in order as workers come
 * free, passes every message to the caller, and, when a job fails, a
 * worker dies or *stop is set, kills every worker (SIGKILL) and waits for
 * it, so that no worker outlives pool_run.
 *
 * With workers = 0 the jobs run one after another in this process,
 * through the same callbacks, without fork.
 *
 * In a worker, SIGINT is ignored (the terminal sends it to the parent
 * too, which decides) and SIGTERM, SIGHUP and SIGPIPE are back to their
 * defaults, so a worker whose parent has gone dies at its next message.
 * The parent's own signal dispositions are not touched: it polls *stop,
 * which the caller's handler sets.
 */
#ifndef REFRAY_POOL_H
#define REFRAY_POOL_H

#include <signal.h>
#include <stddef.h>

/* A job's way to the parent. */
typedef struct pool_link pool_link;

/* Sends len bytes from a job to the parent's message callback, which sees
 * them whole and in order.  Returns 0, or -1 when the run is over (the
 * parent has gone, or in this process message refused them): the job
 * should then return at once. */
int pool_send(pool_link *link, const void *data, size_t len);

typedef struct pool_ops {
    /* In a worker: runs job, sending what it makes through link; returns
     * STATUS_OK, or the status that stops the run. */
    int (*work)(void *ctx, int job, pool_link *link);
    /* In a worker after its last job (NULL: nothing): its messages
     * arrive with job -1. */
    void (*finish)(void *ctx, pool_link *link);
    /* In the parent: one message of job; another status than STATUS_OK
     * stops the run with it. */
    int (*message)(void *ctx, int job, const void *data, size_t len);
    /* In the parent when job has succeeded, after its messages (NULL:
     * nothing); another status than STATUS_OK stops the run with it. */
    int (*done)(void *ctx, int job);
    void *ctx;
} pool_ops;

/* How a run failed when a worker was to blame. */
typedef struct pool_failure {
    int job;             /* the job it was on, -1: none */
    int worker;          /* 1-based; 0: none */
    long pid;
    int term_signal;     /* it was killed by this signal (0: it was not) */
    int exit_code;       /* it exited by itself with this code (-1: it did not) */
} pool_failure;

/*
 * Runs the jobs 0 .. jobs - 1 on at most `workers` processes (0: here).
 * Returns STATUS_OK when every job succeeded; STATUS_CANCELLED when *stop
 * (may be NULL) became non-zero; the status a callback returned; or
 * STATUS_INTERNAL when a worker died or exited unasked (*fail says how,
 * why says it in words) or no socket or process could be made.  fail is
 * filled whenever the run fails (job -1 and worker 0 when no worker was to
 * blame).
 */
int pool_run(int workers, int jobs, const pool_ops *ops, const volatile sig_atomic_t *stop, pool_failure *fail,
             char *why, size_t why_size);

/* The processors online, at least 1 (what --jobs 0 means). */
int pool_cpu_count(void);

#endif
