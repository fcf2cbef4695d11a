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

void cli_signal_catch(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < sizeof stop_signals / sizeof stop_signals[0]; i++)
        sigaction(stop_signals[i], &sa, NULL);
    sa.sa_handler = SIG_IGN;
    sigaction(SIGXFSZ, &sa, NULL);
}

void cli_signal_release(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < sizeof stop_signals / sizeof stop_signals[0]; i++)
        sigaction(stop_signals[i], &sa, NULL);
    sigaction(SIGXFSZ, &sa, NULL);
}

int cli_signal_stopped(void)
{
    return stop_flag != 0;
}

const volatile sig_atomic_t *cli_signal_flag(void)
{
    return &stop_flag;
}
