/*
 * testrun.h - running the refray binary from a test: $REFRAY_BIN (set by
 * `make test`), else build/refray, from the repository root.
 */
#ifndef REFRAY_TESTRUN_H
#define REFRAY_TESTRUN_H

#include <stddef.h>

/* Runs the binary with argv (NULL-terminated; argv[0] is the name the
 * child sees) and returns its exit code, -1 when it did not exit normally.
 * The start of stdout and stderr go to out and err (NUL-terminated, cut
 * at their sizes; either may be NULL). */
int testrun_refray(const char *const argv[], char *out, size_t out_size, char *err, size_t err_size);

#endif
