/*
 * oracle.c - the registry of analytic families and the image loop.  Each
 * family lives in its own file src/oracle/<family>.c and exports one
 * `const oracle_family oracle_<name>`; the build lists them in the
 * generated oracle_list.h (one ORACLE_FAMILY(name) each), so adding a
 * family needs no edit here.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "oracle/oracle.h"

#define ORACLE_FAMILY(name) extern const oracle_family oracle_##name;
#include "oracle_list.h"
#undef ORACLE_FAMILY

static const oracle_family *const families[] = {
#define ORACLE_FAMILY(name) &oracle_##name,
#include "oracle_list.h"
#undef ORACLE_FAMILY
    NULL
};

const oracle_family *const *oracle_families(int *count)
{
    *count = (int)(sizeof families / sizeof families[0]) - 1;
    return families;
}

const oracle_family *oracle_find(const char *name)
{
    for (int i = 0; families[i]; i++)
        if (strcmp(families[i]->name, name) == 0)
            return families[i];
    return NULL;
}

/* A radiance is finite with no negative channel: anything else is a
 * formula that lost its accuracy (attack 9, finding 4: a disk of radius
 * 1e-12 gave +-1e10), never an image to bet on. */
static int admissible(rgb c)
{
    return vec_is_finite(c) && c.x >= 0 && c.y >= 0 && c.z >= 0;
}

/* The mean of the k x k cell centres of pixel (i, j); 0 if any is
 * ambiguous, -1 if any is not admissible. */
static int exact_pixel(const oracle_family *f, const oracle_view *v, int i, int j, rgb *out)
{
    rgb sum = vec_splat(0);
    int k = v->samples;
    for (int b = 0; b < k; b++) {
        for (int a = 0; a < k; a++) {
            rgb c;
            if (f->radiance(v, i + (a + 0.5) / k, j + (b + 0.5) / k, &c) != ORACLE_EXACT)
                return 0;
            if (!admissible(c))
                return -1;
            sum = vec_add(sum, c);
        }
    }
    *out = vec_scale(sum, 1.0 / ((double)k * k));
    return 1;
}

int oracle_image(const oracle_family *f, const oracle_view *v, img_buf *out, unsigned char *excluded,
                 long *excluded_count)
{
    if (img_create(out, v->width, v->height) != 0)
        return STATUS_NO_MEMORY;
    long count = 0;
    for (int j = 0; j < v->height; j++) {
        for (int i = 0; i < v->width; i++) {
            rgb c = vec_splat(0);
            int ok = exact_pixel(f, v, i, j, &c);
            if (ok < 0) {
                img_free(out);
                return STATUS_FAIL;
            }
            double *px = img_pixel(out, i, j);
            px[0] = ok ? c.x : 0;
            px[1] = ok ? c.y : 0;
            px[2] = ok ? c.z : 0;
            if (excluded)
                excluded[(size_t)j * (size_t)v->width + (size_t)i] = (unsigned char)!ok;
            count += !ok;
        }
    }
    if (excluded_count)
        *excluded_count = count;
    return STATUS_OK;
}

int oracle_refuse(char *why, size_t why_size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, why_size, fmt, ap);
    va_end(ap);
    return 0;
}
