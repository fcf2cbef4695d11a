/*
 * cli_progress.h - the progress bar of refray render on standard error:
 * rows done of all, elapsed time and an estimate of what is left.
 */
#ifndef REFRAY_CLI_PROGRESS_H
#define REFRAY_CLI_PROGRESS_H

typedef struct cli_progress {
    int show;          /* 0: draw nothing (-q, or stderr is not a terminal) */
    double start;      /* render_clock() when the bar started */
    long base;         /* rows already done when it started (a resumed render) */
    int last;          /* the last permille drawn, -1: none yet */
} cli_progress;

/* A bar that starts now with base of its rows done; shown when show is
 * non-zero and standard error is a terminal. */
void cli_progress_init(cli_progress *p, int show, long base);

/* Draws done of total rows (a new line once done == total). */
void cli_progress_show(cli_progress *p, long done, long total);

/* Ends a bar cut short, so that a message starts on a line of its own;
 * returns "\n" when the bar was shown, else "". */
const char *cli_progress_break(const cli_progress *p);

#endif
