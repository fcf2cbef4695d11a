/*
 * status.h - the one status family of the library and the program.
 *
 * Every function of the library that can fail returns one of these (or
 * reports one through an out-parameter); out of memory is STATUS_NO_MEMORY
 * everywhere.  The public API's rf_status has the same values in the same
 * order (src/api checks that at compile time).  The program turns a status
 * into its exit code in one place, status_exit_code.
 */
#ifndef REFRAY_STATUS_H
#define REFRAY_STATUS_H

typedef enum status_code {
    STATUS_OK = 0,
    STATUS_USAGE,       /* a bad argument or option, a format this build lacks */
    STATUS_DATA,        /* a bad scene, a malformed file, a limit passed */
    STATUS_NO_INPUT,    /* an input that cannot be opened */
    STATUS_NO_MEMORY,   /* an allocation failed */
    STATUS_IO,          /* the operating system refused a read or write */
    STATUS_CANCELLED,   /* the caller asked to stop (the CLI: SIGINT) */
    STATUS_INTERNAL,    /* a broken invariant or a failed helper process */
    STATUS_FAIL,        /* a check (verify, compare) did not pass */
    STATUS_COUNT
} status_code;

/* The exit code of sysexits(3) for s: 0, 1 (FAIL), 64 (USAGE), 65 (DATA),
 * 66 (NO_INPUT), 70 (NO_MEMORY, INTERNAL), 74 (IO), 130 (CANCELLED). */
int status_exit_code(int s);

/* The status whose exit code is code (70 and unknown codes: INTERNAL), for
 * a helper process's exit. */
int status_from_exit_code(int code);

/* Of two statuses, the one with the larger exit code (the worse of two
 * files' results). */
int status_worse(int a, int b);

/* A short lower-case description ("out of memory"). */
const char *status_string(int s);

#endif
