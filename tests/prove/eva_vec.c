/*
 * eva_vec.c - Eva's driver for vec_length, vec_normalize and vec_length_fast
 * (src/base/vec.h).
 *
 * Their bodies divide each component by the largest one, M: a ratio of at
 * most 1, which an analysis of intervals cannot see when M ranges over
 * every double.  So the domain is split: M in one binade [2^k, 2^(k+1)),
 * taken by one component of one sign, the other two anywhere in
 * [-2^(k+1), 2^(k+1)].  Over k = -1074 .. 1021, M = 2^1022 itself, and
 * the six choices of component and sign these boxes cover every finite
 * vector with 0 < M <= 2^1022 (the precondition); the zero vector is the
 * last case.
 * In each box the ratios lie in [-2, 2] and Eva checks the bare clauses of
 * the two contracts; the other drivers use the contracts instead of the
 * bodies (-eva-use-spec).  The boxes are straight-line code, one
 * BOX(2^k, 2^(k+1)) a binade, listed in boxes.h, which tests/prove/prove.sh
 * writes (a loop would keep every iteration's state apart: quadratic).
 */
#include "eva.h"

volatile vec3 eva_sink;

static void binade(real lo, real hi)
{
    if (lo > 0x1p1022)
        return;   /* past the precondition */
    /* The binade of 2^1022 is in the precondition by its least element
     * alone (M <= 2^1022): the box [2^1022, 2^1022]. */
    hi = lo == 0x1p1022 ? lo : binade_top(hi);
    for (int axis = 0; axis < 3; axis++) {
        eva_sink = vec_normalize(largest_at(axis, 1, lo, hi));
        eva_sink = vec_normalize(largest_at(axis, -1, lo, hi));
        eva_sink.x = vec_length_fast(largest_at(axis, 1, lo, hi));
        eva_sink.x = vec_length_fast(largest_at(axis, -1, lo, hi));
    }
}

void eva_vec(void)
{
    eva_sink = vec_normalize(vec_make(0, 0, 0));
    eva_sink.x = vec_length_fast(vec_make(0, 0, 0));
#define BOX(lo, hi) binade(lo, hi);
#include "boxes.h"
#undef BOX
}
