/*
 * cli_signal.h - SIGINT, SIGTERM and SIGHUP for every command, in one place
 * (spec/reliability.md, "Signals").
 *
 * cli_main installs the handler once.  While a command cooperates (it
 * passes cli_signal_cancel as the cancel callback of whatever runs long:
 * a load, a render, an image or report being written), a signal only sets
 * a flag: the work stops at its next poll, the temporary of a file being
 * written is removed, and the command returns STATUS_CANCELLED, which
 * becomes exit code 128 + the signal (130 SIGINT, 143 SIGTERM, 129 SIGHUP).
 * Outside those stretches, and at a second signal, the signal takes its
 * default action at once (the process dies by it: the shell reports
 * 128 + the signal too); no output file is half written then, and a
 * temporary a killed writer leaves behind is removed by the next write
 * into that directory (io/atomic.h).  A signal ignored when refray started
 * (nohup) stays ignored.
 *
 * Worker processes (render --jobs, io/pool.h) inherit the handler and the
 * cooperation: a signal to the whole process group stops every worker at
 * its next poll, and the parent polls the same flag while it waits for
 * them (its poll() returns at least every 0.1 s), stops them and writes
 * nothing.  SIGXFSZ is ignored, so that a file size limit (ulimit -f) is a
 * write error with a message (EFBIG, 74) rather than a silent death.
 */
#ifndef REFRAY_CLI_SIGNAL_H
#define REFRAY_CLI_SIGNAL_H

#include <signal.h>

/* Installs the handler for SIGINT, SIGTERM and SIGHUP (not cooperating);
 * ignores SIGXFSZ. */
void cli_signal_install(void);

/* From now on (on != 0) the command polls cli_signal_cancel; 0: no longer. */
void cli_signal_cooperate(int on);

/* A cancel callback (base/cancel.h): non-zero once a signal came. */
int cli_signal_cancel(void *unused);

/* The flag itself, for code that polls a sig_atomic_t (io/proc.h,
 * io/pool.h). */
const volatile sig_atomic_t *cli_signal_flag(void);

/* The exit code of status: 128 + the signal for STATUS_CANCELLED after a
 * signal, else status_exit_code(status). */
int cli_signal_exit_code(int status);

#endif
