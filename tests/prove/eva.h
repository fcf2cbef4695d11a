/*
 * eva.h - inputs for Eva's drivers (tests/prove/eva_*.c): each returns any
 * double, vector or colour of a box, so that a driver's call covers a
 * whole domain at once.  Analysis only: never compiled into refray.
 */
#ifndef REFRAY_PROVE_EVA_H
#define REFRAY_PROVE_EVA_H

#include "__fc_builtin.h"
#include "base/vec.h"

static real any(real lo, real hi) { return Frama_C_double_interval(lo, hi); }
static vec3 any_vec(real lo, real hi) { return vec_make(any(lo, hi), any(lo, hi), any(lo, hi)); }
/* What a unit vector is to Eva: vec_normalize's bound. */
static vec3 any_dir(void) { return any_vec(-4, 4); }
static rgb any_colour(void) { return any_vec(0, DBL_MAX); }
static rgb any_coefficient(void) { return any_vec(0, 1); }

/* Component axis in sign * [lo, hi], the others in [-hi, hi]: the vectors
 * whose largest component is in [lo, hi] (eva_vec.c, eva_isect.c). */
static vec3 largest_at(int axis, real sign, real lo, real hi)
{
    vec3 v = any_vec(-hi, hi);
    real m = sign > 0 ? any(lo, hi) : any(-hi, -lo);
    if (axis == 0)
        v.x = m;
    else if (axis == 1)
        v.y = m;
    else
        v.z = m;
    return v;
}

/* The largest double below hi = 2^j (a binade [2^(j-1), 2^j) ends there),
 * and DBL_MAX itself, which ends the last one. */
static real binade_top(real hi)
{
    if (hi == DBL_MAX)
        return hi;
    return hi > 0x1p-1022 ? hi - hi * 0x1p-53 : hi - 0x1p-1074;
}

#endif
