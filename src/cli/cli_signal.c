/*
 * cli_signal.c - see cli_signal.h.
 *
 * Global state: the flag, a volatile sig_atomic_t, because a signal
 * handler can reach nothing else.
 */
#include <string.h>
#include "cli/cli_signal.h"

static volatile sig_atomic_t stop_flag;

static void on_stop(int sig)
{
    (void)sig;
    stop_flag = 1;
}

static const int stop_signals[] = {SIGINT, SIGTERM, SIGHUP};

/* stop for the stop signals, xfsz for SIGXFSZ. */
static void install(void (*stop)(int), void (*xfsz)(int))
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sigemptyset(&sa.sa_mask);
    sa.sa_handler = stop;
    for (size_t i = 0; i < sizeof stop_signals / sizeof stop_signals[0]; i++)
        sigaction(stop_signals[i], &sa, NULL);
    sa.sa_handler = xfsz;
    sigaction(SIGXFSZ, &sa, NULL);
}

void cli_signal_catch(void)
{
    install(on_stop, SIG_IGN);
}

void cli_signal_release(void)
{
    install(SIG_DFL, SIG_DFL);
}

int cli_signal_stopped(void)
{
    return stop_flag != 0;
}

const volatile sig_atomic_t *cli_signal_flag(void)
{
    return &stop_flag;
}
