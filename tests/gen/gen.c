/*
 * gen.c - the shared part of the fixture generators (gen.h).
 *
 * The shortest decimal of a double: for p = 1, 2, ... 17 digits, printf's
 * correctly rounded p-digit decimal is the nearest one to x; the first p
 * for which it reads back as x gives the answer.  Where the interval of
 * decimals that read back as x is lopsided (x a power of two: the double
 * below is half as far as the one above), the nearest p-digit decimal may
 * fall outside it while its neighbour one unit in the last digit away is
 * inside; that neighbour is then the answer for p digits.  Both can not be
 * inside without the nearest one being inside too, so the result is the
 * shortest, and among the shortest the nearest, as Gay's dtoa gives it.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "gen.h"

enum { DIGITS_MAX = 20 }; /* 17 significant digits at most, and room */

/* digits[0..n) (no point) times 10^(exp10 - n + 1), with sign, as text
 * strtod reads; whether it reads back as x. */
static int reads_back(int negative, const char *digits, int n, int exp10, double x)
{
    char text[64];
    snprintf(text, sizeof text, "%s%.*se%d", negative ? "-" : "", n, digits, exp10 - n + 1);
    return strtod(text, NULL) == x;
}

/* Adds step (+1 or -1) to the last digit of digits[0..n) with carry or
 * borrow; 0 when the number of digits would change (that length was tried
 * already, or a carry past the first digit). */
static int nudge(char *digits, int n, int step)
{
    int i = n - 1;
    while (i >= 0) {
        int d = digits[i] - '0' + step;
        if (d >= 0 && d <= 9) {
            digits[i] = (char)('0' + d);
            return !(digits[0] == '0');
        }
        digits[i--] = step > 0 ? '0' : '9';
    }
    return 0;
}

/* The shortest digits of |x| > 0 into digits (NUL-terminated, no trailing
 * zero), and the decimal exponent of the first one. */
static void shortest(double x, char *digits, int *exp10)
{
    int negative = x < 0;
    for (int p = 1; p <= 17; p++) {
        char text[32];
        snprintf(text, sizeof text, "%.*e", p - 1, fabs(x));
        int n = 0;
        for (const char *c = text; *c && *c != 'e'; c++)
            if (*c != '.')
                digits[n++] = *c;
        digits[n] = '\0';
        *exp10 = atoi(strchr(text, 'e') + 1);
        if (reads_back(negative, digits, n, *exp10, x))
            break;
        char other[DIGITS_MAX];
        int found = 0;
        for (int step = -1; step <= 1 && !found; step += 2) {
            memcpy(other, digits, (size_t)n + 1);
            found = nudge(other, n, step) && reads_back(negative, other, n, *exp10, x);
        }
        if (found) {
            memcpy(digits, other, (size_t)n + 1);
            break;
        }
    }
    size_t n = strlen(digits);
    while (n > 1 && digits[n - 1] == '0')
        digits[--n] = '\0';
}

char *gen_repr(double x, char buf[GEN_REPR_MAX])
{
    char digits[DIGITS_MAX], *out = buf;
    int exp10;
    if (isnan(x) || isinf(x)) {
        strcpy(buf, isnan(x) ? "nan" : x < 0 ? "-inf" : "inf");
        return buf;
    }
    if (signbit(x))
        *out++ = '-';
    if (x == 0) {
        strcpy(out, "0.0");
        return buf;
    }
    shortest(x, digits, &exp10);
    int n = (int)strlen(digits), point = exp10 + 1;
    if (point > -4 && point <= 16) {
        if (point <= 0) {
            *out++ = '0';
            *out++ = '.';
            for (int i = 0; i < -point; i++)
                *out++ = '0';
            strcpy(out, digits);
        } else if (point >= n) {
            strcpy(out, digits);
            out += n;
            for (int i = n; i < point; i++)
                *out++ = '0';
            strcpy(out, ".0");
        } else {
            snprintf(out, GEN_REPR_MAX - 1, "%.*s.%s", point, digits, digits + point);
        }
    } else {
        snprintf(out, GEN_REPR_MAX - 1, "%c%s%se%c%02d", digits[0], n > 1 ? "." : "", digits + 1,
                 exp10 < 0 ? '-' : '+', abs(exp10));
    }
    return buf;
}

void gen_put(FILE *f, double x)
{
    char buf[GEN_REPR_MAX];
    fputs(gen_repr(x, buf), f);
}

static void fail(const char *what, const char *path)
{
    fprintf(stderr, "gen: cannot %s '%s': %s\n", what, path, strerror(errno));
    exit(74);
}

FILE *gen_open(const char *root, const char *path)
{
    char full[4096];
    snprintf(full, sizeof full, "%s/%s", root, path);
    for (char *slash = strchr(full + 1, '/'); slash; slash = strchr(slash + 1, '/')) {
        *slash = '\0';
        if (mkdir(full, 0777) != 0 && errno != EEXIST)
            fail("make the directory", full);
        *slash = '/';
    }
    FILE *f = fopen(full, "wb");
    if (!f)
        fail("write", full);
    return f;
}

void gen_close(FILE *f, const char *path)
{
    if (ferror(f) | fclose(f))
        fail("write", path);
}

const char *gen_root(int argc, char **argv, const char *usage)
{
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: %s\n", usage);
        exit(64);
    }
    return argc == 2 ? argv[1] : ".";
}
