/*
 * cancel.h - asking a caller, now and then, whether to stop.
 *
 * Long work (a load, a BVH build, a pixel of many rays, an image encoded)
 * counts its steps into a cancel_poll and calls the caller's function once
 * every CANCEL_STEPS steps.  A step is a small bounded piece of work (one
 * statement lowered, one ray traced, one light sample, one row encoded):
 * at most some microseconds, so the caller is asked every few
 * milliseconds and a stop takes effect well within the 0.2 s of
 * [REL-CANCEL-1] (spec/reliability.md).  Once the function has said stop,
 * the poll stays stopped.  A zeroed cancel_poll never asks and never stops.
 */
#ifndef REFRAY_CANCEL_H
#define REFRAY_CANCEL_H

enum { CANCEL_STEPS = 256 };

typedef struct cancel_poll {
    int (*fn)(void *user);     /* non-zero: stop; NULL: never */
    void *user;
    int countdown;             /* steps until fn is asked again */
    int stopped;               /* fn said stop (sticky) */
} cancel_poll;

static inline cancel_poll cancel_poll_make(int (*fn)(void *user), void *user)
{
    cancel_poll c = {fn, user, 0, 0};
    return c;
}

/* Counts n steps; 1 when the work must stop (fn said so, now or before).
 * The first call asks at once.  NULL never stops. */
static inline int cancel_steps(cancel_poll *c, long n)
{
    if (!c || !c->fn)
        return 0;
    if (c->stopped)
        return 1;
    if (n < c->countdown) {
        c->countdown -= (int)n;
        return 0;
    }
    c->countdown = CANCEL_STEPS;
    c->stopped = c->fn(c->user) != 0;
    return c->stopped;
}

static inline int cancel_step(cancel_poll *c)
{
    return cancel_steps(c, 1);
}

/* Asks fn now, whatever the count (before a step that cannot be undone,
 * such as renaming a written file into place); 1: stop. */
static inline int cancel_now(cancel_poll *c)
{
    if (!c || !c->fn)
        return 0;
    if (!c->stopped)
        c->stopped = c->fn(c->user) != 0;
    return c->stopped;
}

/* Whether the work was stopped, without counting a step. */
static inline int cancel_stopped(const cancel_poll *c)
{
    return c && c->stopped;
}

#endif
