/*
 * status.h - the exit statuses of sysexits(3) that the library returns and
 * the CLI exits with.
 */
#ifndef REFRAY_STATUS_H
#define REFRAY_STATUS_H

/* Exit codes of sysexits.h, shared by the library and the CLI. */
enum {
    REFRAY_EXIT_OK = 0,
    REFRAY_EXIT_FAIL = 1,      /* a check (verify) did not pass */
    REFRAY_EXIT_USAGE = 64,
    REFRAY_EXIT_DATAERR = 65,  /* bad scene */
    REFRAY_EXIT_NOINPUT = 66,  /* missing input file */
    REFRAY_EXIT_SOFTWARE = 70, /* internal error, out of memory */
    REFRAY_EXIT_IOERR = 74,
    REFRAY_EXIT_INTERRUPTED = 130
};

#endif
