/*
 * shrink.c - delta debugging over a scene's statements (Zeller's ddmin,
 * reduced to what a scene of a few dozen statements needs): remove chunks
 * of the removable statements, halving the chunk size down to one, and
 * keep every removal after which the scene still has an interior
 * disagreement with POV-Ray; repeat single removals until none is
 * possible.  The image and camera statements stay.
 */
#include <string.h>
#include "dt.h"

/* Whether the statements of keep still disagree in the interior. */
static int still_fails(const dt_config *c, const char *name, const dtgen_scene *g, const unsigned char *keep,
                       int *tries)
{
    static char text[DTGEN_TEXT_MAX];
    dt_result r;
    (*tries)++;
    if (dtgen_subset(g, keep, text, sizeof text) == 0)
        return 0;
    return dt_run(c, name, text, &r) == DT_INTERIOR;
}

/* Tries to drop statements idx[0..n) from keep; 1 when they went. */
static int drop(const dt_config *c, const char *name, const dtgen_scene *g, unsigned char *keep, const int *idx,
                int n, int *tries)
{
    unsigned char trial[DTGEN_STMT_MAX];
    memcpy(trial, keep, sizeof trial);
    for (int i = 0; i < n; i++)
        trial[idx[i]] = 0;
    if (!still_fails(c, name, g, trial, tries))
        return 0;
    memcpy(keep, trial, sizeof trial);
    return 1;
}

/* One pass with chunks of size kept statements; 1 when any went. */
static int pass(const dt_config *c, const char *name, const dtgen_scene *g, unsigned char *keep, int size,
                int *tries)
{
    int idx[DTGEN_STMT_MAX], n = 0, any = 0;
    for (int i = 2; i < g->count; i++)
        if (keep[i])
            idx[n++] = i;
    for (int first = 0; first < n; first += size) {
        int m = n - first < size ? n - first : size;
        any |= drop(c, name, g, keep, idx + first, m, tries);
    }
    return any;
}

int dt_shrink(const dt_config *c, const char *name, const dtgen_scene *g, unsigned char *keep)
{
    int tries = 0;
    for (int i = 0; i < DTGEN_STMT_MAX; i++)
        keep[i] = 1;
    for (int size = (g->count - 2) / 2; size > 1; size /= 2)
        pass(c, name, g, keep, size, &tries);
    while (pass(c, name, g, keep, 1, &tries))
        ;
    return tries;
}
