/*
 * gen.h - what the generators of committed test fixtures share (tests/gen/,
 * `make fixtures`; tests/check_fixtures.c checks that they give the bytes
 * that are committed): files written under a root directory, and doubles
 * written as the shortest decimal that reads back as the same double.
 *
 * Each generator is a program: `gen_NAME [ROOT]` writes its files under
 * ROOT (default "."), creating directories as needed, and exits 0, or 74
 * with a message when a file cannot be written.
 */
#ifndef REFRAY_TESTS_GEN_H
#define REFRAY_TESTS_GEN_H

#include <stdio.h>

/* The double nearest pi (what every generator's angles start from). */
#define GEN_PI 3.141592653589793

enum { GEN_REPR_MAX = 48 };

/*
 * x as the shortest decimal string that reads back as x (of those, the
 * nearest to x), laid out as Python's repr lays out a float: positional
 * with at least one digit after the point ("1.5", "100.0", "0.0001")
 * while the decimal exponent is from -4 to 15, else "d.ddde+XX" with a
 * sign and at least two exponent digits ("1e-05", "-1e+300"); "-0.0" for
 * negative zero.  Writes into buf and returns it.
 */
char *gen_repr(double x, char buf[GEN_REPR_MAX]);

/* Writes gen_repr(x) to f. */
void gen_put(FILE *f, double x);

/* Opens root/path for writing in binary mode, creating root and the
 * directories of path; exits 74 with a message when it cannot. */
FILE *gen_open(const char *root, const char *path);

/* Closes f (opened for path); exits 74 with a message on a write error. */
void gen_close(FILE *f, const char *path);

/* ROOT from the command line ("." when absent); exits 64 on more. */
const char *gen_root(int argc, char **argv, const char *usage);

#endif
