/*
 * cli_signal.c - see cli_signal.h.
 *
 * Global state, the program's only: the number of the signal that came
 * and whether the command cooperates, both volatile sig_atomic_t, because
 * a signal handler can reach nothing else.  The library never sees them:
 * it is asked through cancel callbacks.
 */
#include <string.h>
#include "base/status.h"
#include "cli/cli_signal.h"

static volatile sig_atomic_t caught;       /* the signal's number; 0: none yet */
static volatile sig_atomic_t cooperating;  /* 1: the command polls the flag */

static const int handled[] = {SIGINT, SIGTERM, SIGHUP};

static void on_signal(int sig)
{
    int again = caught != 0;
    caught = sig;
    if (cooperating && !again)
        return;
    /* Nobody is listening, or this is the second signal: die by it now,
     * as if it had never been caught. */
    signal(sig, SIG_DFL);
    raise(sig);
}

void cli_signal_install(void)
{
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    /* Interrupted system calls restart: the flag is polled, not an EINTR. */
    sa.sa_flags = SA_RESTART;
    for (size_t i = 0; i < sizeof handled / sizeof handled[0]; i++)
        if (sigaction(handled[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            sigaction(handled[i], &sa, NULL);
    signal(SIGXFSZ, SIG_IGN);
}

void cli_signal_cooperate(int on)
{
    cooperating = on != 0;
    /* A signal that came while nobody listened killed the process; one
     * that comes from now on is seen at the next poll. */
}

int cli_signal_cancel(void *unused)
{
    (void)unused;
    return caught != 0;
}

const volatile sig_atomic_t *cli_signal_flag(void)
{
    return &caught;
}

int cli_signal_exit_code(int status)
{
    if (status == STATUS_CANCELLED && caught != 0)
        return 128 + caught;
    return status_exit_code(status);
}
