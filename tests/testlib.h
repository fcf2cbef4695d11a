/*
 * testlib.h - helpers shared by the Check suites.
 */
#ifndef REFRAY_TESTLIB_H
#define REFRAY_TESTLIB_H

#include <check.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "base/vec.h"

/* |got - want| <= tol, with the values in the failure message. */
#define ck_assert_near(got, want, tol)                                                      \
    do {                                                                                    \
        double ck_got_ = (got), ck_want_ = (want), ck_tol_ = (tol);                         \
        ck_assert_msg(fabs(ck_got_ - ck_want_) <= ck_tol_,                                   \
                      "%s = %.17g, expected %.17g (tolerance %.3g)", #got, ck_got_, ck_want_, \
                      ck_tol_);                                                             \
    } while (0)

/* Relative closeness: |got - want| <= rel * max(|want|, tiny). */
#define ck_assert_rel(got, want, rel)                                                       \
    do {                                                                                    \
        double ck_g_ = (got), ck_w_ = (want), ck_r_ = (rel);                                \
        double ck_s_ = fabs(ck_w_) > 1e-300 ? fabs(ck_w_) : 1e-300;                         \
        ck_assert_msg(fabs(ck_g_ - ck_w_) <= ck_r_ * ck_s_,                                   \
                      "%s = %.17g, expected %.17g (relative tolerance %.3g)", #got, ck_g_,   \
                      ck_w_, ck_r_);                                                        \
    } while (0)

#define ck_assert_vec_near(got, want, tol)                                                  \
    do {                                                                                    \
        vec3 ck_gv_ = (got), ck_wv_ = (want);                                               \
        ck_assert_near(ck_gv_.x, ck_wv_.x, tol);                                            \
        ck_assert_near(ck_gv_.y, ck_wv_.y, tol);                                            \
        ck_assert_near(ck_gv_.z, ck_wv_.z, tol);                                            \
    } while (0)

/* a and b the same real to the bit.  The long double build's x87 real
 * holds 10 bytes of value in a slot of 16, and a store leaves the other 6 as
 * they were, so memcmp there compares garbage: its value and sign are
 * compared instead (NaN payloads alike). */
static inline int same_real_bits(real a, real b)
{
#ifdef REFRAY_LONG_DOUBLE
    return (a != a && b != b) || (a == b && signbit(a) == signbit(b));
#else
    return memcmp(&a, &b, sizeof a) == 0;
#endif
}

static inline int same_vec_bits(vec3 a, vec3 b)
{
    return same_real_bits(a.x, b.x) && same_real_bits(a.y, b.y) && same_real_bits(a.z, b.z);
}

static inline int same_vecs_bits(const vec3 *a, const vec3 *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!same_vec_bits(a[i], b[i]))
            return 0;
    return 1;
}

/* splitmix64 of a counter: a reproducible stream without hidden state. */
static inline uint64_t test_mix(uint64_t x)
{
    x += 0x9e3779b97f4a7c15u;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9u;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebu;
    return x ^ (x >> 31);
}

#endif
