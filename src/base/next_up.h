/*
 * next_up.h - the next real toward +infinity: nextafter(x, +INFINITY) for
 * every x but NaN, without the call into libm (the nearest-hit walk's
 * window, src/render/bvh.c, takes one per hit it keeps).
 */
#ifndef REFRAY_NEXT_UP_H
#define REFRAY_NEXT_UP_H

#include <stdint.h>
#include <string.h>
#include "base/vec.h"

/* For doubles, a double's bits ordered as an integer follow its magnitude:
 * one more moves a positive x (subnormals and the largest double, which
 * becomes +inf, included) up, one less moves a negative x toward zero
 * (-2^-1074 becomes -0, as nextafter gives; -inf becomes -DBL_MAX).  +-0
 * become 2^-1074, +inf stays.  A NaN is returned as it is (nextafter returns
 * a NaN too, not necessarily these bits).  The long double build (and
 * Frama-C, which has no model of the bits) takes nextafter itself. */
static inline real real_next_up(real x)
{
#if defined(REFRAY_LONG_DOUBLE) || defined(__FRAMAC__)
    return nextafter(x, (real)INFINITY);
#else
    uint64_t u;
    if (x != x || x == (real)INFINITY)
        return x;
    if (x == 0.0)
        return 0x1p-1074;
    memcpy(&u, &x, sizeof u);
    u = x > 0.0 ? u + 1 : u - 1;
    memcpy(&x, &u, sizeof x);
    return x;
#endif
}

#endif
