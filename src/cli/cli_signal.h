/*
 * cli_signal.h - the program's stop flag: what SIGINT, SIGTERM and SIGHUP
 * do while a command that writes files runs (render, merge).  The flag is
 * the one piece of state a signal handler can reach; the commands poll it
 * (the library through its cancel callback, the worker pool directly).
 */
#ifndef REFRAY_CLI_SIGNAL_H
#define REFRAY_CLI_SIGNAL_H

#include <signal.h>

/*
 * From now on SIGINT, SIGTERM and SIGHUP set the flag instead of ending
 * the process, without SA_RESTART (a blocked read or poll returns EINTR,
 * so the flag is seen at once), and SIGXFSZ is ignored, so that a file
 * size limit (ulimit -f) is a write error with a message, EFBIG, rather
 * than a silent death.
 */
void cli_signal_catch(void);

/* The four signals back to their default actions. */
void cli_signal_release(void);

/* Non-zero once one of the signals came. */
int cli_signal_stopped(void);

/* The flag itself, for code that polls it (io/pool.h). */
const volatile sig_atomic_t *cli_signal_flag(void);

#endif
