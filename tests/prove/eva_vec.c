/*
 * eva_vec.c - Eva's driver for vec_length and vec_normalize (src/base/vec.h).
 *
 * Their bodies divide each component by the largest one, M: a ratio of at
 * most 1, which an analysis of intervals cannot see when M ranges over
 * every double.  So the domain is split: M in one binade [2^k, 2^(k+1)],
 * taken by one component of one sign, the other two anywhere in
 * [-2^(k+1), 2^(k+1)].  Over k = -1074 .. 1021 and the six choices of
 * component and sign these boxes cover every finite vector with
 * 0 < M <= 2^1022 (the precondition); the zero vector is the last case.
 * In each box the ratios lie in [-2, 2] and Eva checks the bare clauses of
 * the two contracts; the other drivers use the contracts instead of the
 * bodies (-eva-use-spec).
 */
#include "__fc_builtin.h"
#include "base/vec.h"

volatile vec3 eva_sink;

static real any(real lo, real hi) { return Frama_C_double_interval(lo, hi); }

/* Component axis in sign * [lo, hi], the others in [-hi, hi]. */
static vec3 largest_at(int axis, real sign, real lo, real hi)
{
    vec3 v = vec_make(any(-hi, hi), any(-hi, hi), any(-hi, hi));
    real m = sign > 0 ? any(lo, hi) : any(-hi, -lo);
    if (axis == 0)
        v.x = m;
    else if (axis == 1)
        v.y = m;
    else
        v.z = m;
    return v;
}

void eva_vec(void)
{
    eva_sink = vec_normalize(vec_make(0, 0, 0));
    real lo = 0x1p-1074;
    /*@ loop unroll 2100; */
    for (int k = -1074; k <= 1021; k++) {
        real hi = 2 * lo;
        eva_sink = vec_normalize(largest_at(0, 1, lo, hi));
        eva_sink = vec_normalize(largest_at(0, -1, lo, hi));
        eva_sink = vec_normalize(largest_at(1, 1, lo, hi));
        eva_sink = vec_normalize(largest_at(1, -1, lo, hi));
        eva_sink = vec_normalize(largest_at(2, 1, lo, hi));
        eva_sink = vec_normalize(largest_at(2, -1, lo, hi));
        lo = hi;
    }
}
