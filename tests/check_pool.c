/*
 * check_pool.c - the worker pool (io/pool.h) behind render --jobs and
 * verify --jobs ([SCALE-JOBS-2..4], spec/scaling.md): every job runs
 * exactly once and its messages arrive whole and in order, on workers or
 * in this process alike; a failing job, a worker killed by a signal or
 * exiting on its own, and the stop flag each end the run with their status
 * and leave no worker behind.
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "base/status.h"
#include "io/pool.h"
#include "testlib.h"

enum { JOBS = 40, PARTS = 3, BIG = 100000 };

/* What the parent saw. */
typedef struct seen {
    int parts[JOBS];          /* messages of each job so far */
    int done[JOBS];           /* done callbacks of each job */
    int finishes;             /* messages from finish */
    int fail_job;             /* the job that fails, -1: none */
    int how;                  /* 0 status DATA, 1 SIGKILL, 2 _exit(3), 3 set stop */
    volatile sig_atomic_t stop;
} seen;

/* Job j sends PARTS messages: part p is BIG bytes, all (j * 7 + p) & 255,
 * so that a message cut or mixed with another shows. */
static int work(void *ctx, int job, pool_link *link)
{
    seen *s = ctx;
    static unsigned char buf[BIG];
    if (job == s->fail_job) {
        if (s->how == 1)
            raise(SIGKILL);
        if (s->how == 2)
            _exit(3);
        if (s->how == 0)
            return STATUS_DATA;
    }
    for (int p = 0; p < PARTS; p++) {
        memset(buf, (job * 7 + p) & 255, sizeof buf);
        if (pool_send(link, buf, sizeof buf) != 0)
            return STATUS_CANCELLED;
    }
    return STATUS_OK;
}

static void finish(void *ctx, pool_link *link)
{
    (void)ctx;
    pool_send(link, "end", 3);
}

static int message(void *ctx, int job, const void *data, size_t len)
{
    seen *s = ctx;
    const unsigned char *b = data;
    if (job < 0) {
        ck_assert(len == 3 && memcmp(data, "end", 3) == 0);
        s->finishes++;
        return STATUS_OK;
    }
    ck_assert_int_lt(job, JOBS);
    ck_assert_uint_eq(len, BIG);
    int want = (job * 7 + s->parts[job]) & 255;
    size_t i = 0;
    while (i < len && b[i] == want)
        i++;
    ck_assert_msg(i == len, "job %d part %d: byte %zu is %d, not %d", job, s->parts[job], i, b[i], want);
    s->parts[job]++;
    if (s->how == 3 && job == s->fail_job)
        s->stop = 1;
    return STATUS_OK;
}

static int done(void *ctx, int job)
{
    seen *s = ctx;
    ck_assert_int_eq(s->parts[job], PARTS);
    s->done[job]++;
    return STATUS_OK;
}

/* 1 when this process has no child left (no worker outlived the run). */
static int no_children(void)
{
    return waitpid(-1, NULL, WNOHANG) < 0 && errno == ECHILD;
}

static int run(seen *s, int workers, pool_failure *f, char *why, size_t size)
{
    pool_ops ops = {work, finish, message, done, s};
    return pool_run(workers, JOBS, &ops, &s->stop, f, why, size);
}

/* [SCALE-JOBS-2] 40 jobs of 3 messages of 100 kB (larger than a socket's
 * buffer) on 0 (here), 1, 3 and 8 workers. */
START_TEST(test_pool_every_job_once_in_order)
{
    static const int workers[] = {0, 1, 3, 8};
    for (size_t k = 0; k < sizeof workers / sizeof workers[0]; k++) {
        seen s;
        pool_failure f;
        char why[200];
        memset(&s, 0, sizeof s);
        s.fail_job = -1;
        ck_assert_int_eq(run(&s, workers[k], &f, why, sizeof why), STATUS_OK);
        for (int j = 0; j < JOBS; j++) {
            ck_assert_int_eq(s.parts[j], PARTS);
            ck_assert_int_eq(s.done[j], 1);
        }
        ck_assert_int_eq(s.finishes, workers[k] ? workers[k] : 1);
        ck_assert(no_children());
    }
}
END_TEST

/* [SCALE-JOBS-3] A failing job, a worker killed by SIGKILL, a worker that
 * exits: the run stops with the status, names the job and how, and no
 * worker is left. */
START_TEST(test_pool_failures)
{
    static const struct {
        int how, workers, status, term_signal, exit_code;
        const char *words;
    } cases[] = {
        {0, 3, STATUS_DATA, 0, -1, ""},
        {0, 0, STATUS_DATA, 0, -1, ""},
        {1, 3, STATUS_INTERNAL, SIGKILL, -1, "was killed by SIGKILL"},
        {2, 2, STATUS_INTERNAL, 0, 3, "exited with code 3"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        seen s;
        pool_failure f;
        char why[200];
        memset(&s, 0, sizeof s);
        s.fail_job = 17;
        s.how = cases[k].how;
        ck_assert_int_eq(run(&s, cases[k].workers, &f, why, sizeof why), cases[k].status);
        ck_assert_int_eq(f.job, 17);
        ck_assert_int_eq(f.term_signal, cases[k].term_signal);
        ck_assert_int_eq(f.exit_code, cases[k].exit_code);
        ck_assert_msg(strstr(why, cases[k].words) != NULL, "'%s'", why);
        ck_assert_int_eq(s.done[17], 0);
        ck_assert(no_children());
    }
}
END_TEST

/* [SCALE-JOBS-4] The stop flag, set while job 5 runs, ends the run with
 * STATUS_CANCELLED on workers and here, before every job ran. */
START_TEST(test_pool_stop)
{
    for (int workers = 0; workers <= 2; workers += 2) {
        seen s;
        pool_failure f;
        char why[200];
        int all = 1;
        memset(&s, 0, sizeof s);
        s.fail_job = 5;
        s.how = 3;
        ck_assert_int_eq(run(&s, workers, &f, why, sizeof why), STATUS_CANCELLED);
        for (int j = 0; j < JOBS; j++)
            all &= s.done[j];
        ck_assert(!all);
        ck_assert(no_children());
    }
}
END_TEST

Suite *suite_pool(void)
{
    Suite *s = suite_create("pool");
    TCase *tc = tcase_create("pool");
    tcase_set_timeout(tc, 20);
    tcase_add_test(tc, test_pool_every_job_once_in_order);
    tcase_add_test(tc, test_pool_failures);
    tcase_add_test(tc, test_pool_stop);
    suite_add_tcase(s, tc);
    return s;
}
