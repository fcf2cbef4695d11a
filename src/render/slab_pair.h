/*
 * slab_pair.h - slab_box_meets_neg (slab.h) for the two children of an
 * inner node at once, one in each lane of an SSE2 register: the BVH's
 * walks (bvh.c) test both children of every inner node they enter.
 *
 * Each lane makes the scalar test's operations in its order: the entry and
 * exit of a slab as ((near or far) - o) * inv, the entry's running maximum
 * from tmin as `t > tn ? t : tn` (MAXPD returns its second operand unless
 * the first is greater: the ternary itself, NaN and zeros included), the
 * least exit from +inf as `t < least ? t : least` (MINPD), the pad
 * least * (1 + copysign(pad, least)) (copysign of a positive constant is
 * its OR with the sign bit), the cap by tmax and the comparison `<=`.
 * SSE2's packed double operations round each lane as the scalar ones do
 * (the scalar code is SSE2 too on x86-64), so every entry and answer is
 * the scalar test's to the bit.  Only on x86-64 with real a double: its
 * ABI aligns the stack for the pair form's 16-byte lanes, which an i386
 * caller of the library need not do (M32 keeps the scalar test); not the
 * long double build, not Frama-C (which never parses bvh.c, kept off all
 * the same).  Elsewhere the scalar test of each child, as before.
 */
#ifndef REFRAY_SLAB_PAIR_H
#define REFRAY_SLAB_PAIR_H

#include <stddef.h>
#include "render/bvh.h"
#include "render/slab.h"

#if defined(__SSE2__) && defined(__x86_64__) && !defined(REFRAY_LONG_DOUBLE) && !defined(__FRAMAC__)
#define SLAB_PAIR_SSE2 1
#include <emmintrin.h>
#include "base/inline_hint.h"

/* HINT_IN_LINE: inlined at every call, so that a walk's constant offsets
 * fold. */

/* A ray prepared for pair tests: origin and 1/d in both lanes. */
typedef struct slab_pair_ray {
    __m128d o[3], inv[3];
} slab_pair_ray;

/* +inf, the sign bit, the pad and 1 in both lanes, each an aligned load
 * (_mm_set1_pd of a constant was a load and a shuffle at every node). */
static const double slab_pair_k[4][2] __attribute__((aligned(16))) = {
    {INFINITY, INFINITY}, {-0.0, -0.0}, {SLAB_EXIT_PAD, SLAB_EXIT_PAD}, {1.0, 1.0}};

/* The byte offsets in a bvh_node of an axis's lower and upper bound. */
static inline HINT_IN_LINE size_t slab_pair_lo_at(int axis)
{
    return offsetof(bvh_node, lo) + (size_t)axis * sizeof(real);
}

static inline HINT_IN_LINE size_t slab_pair_hi_at(int axis)
{
    return offsetof(bvh_node, hi) + (size_t)axis * sizeof(real);
}

/* The offset of an axis's near bound for a ray whose neg flag is neg (hi
 * for a negative direction, as slab_ends chooses), or of its far one. */
static inline HINT_IN_LINE size_t slab_pair_near_at(int axis, int neg)
{
    return neg ? slab_pair_hi_at(axis) : slab_pair_lo_at(axis);
}

static inline HINT_IN_LINE size_t slab_pair_far_at(int axis, int neg)
{
    return neg ? slab_pair_lo_at(axis) : slab_pair_hi_at(axis);
}

static inline void slab_pair_make(const slab_ray *s, slab_pair_ray *p)
{
    const real o[3] = {s->o.x, s->o.y, s->o.z}, inv[3] = {s->inv.x, s->inv.y, s->inv.z};
    for (int k = 0; k < 3; k++) {
        p->o[k] = _mm_set1_pd(o[k]);
        p->inv[k] = _mm_set1_pd(inv[k]);
    }
}

/* The bound at byte offset `at` of node a in the low lane, of a + 1 in the
 * high one. */
static inline HINT_IN_LINE __m128d slab_pair_load(const bvh_node *a, size_t at)
{
    const char *p = (const char *)(const void *)a + at;
    return _mm_loadh_pd(_mm_load_sd((const double *)(const void *)p),
                        (const double *)(const void *)(p + sizeof(bvh_node)));
}

/* One axis: its entry into the running maximum *tn, its exit into the
 * running least *least. */
static inline HINT_IN_LINE void slab_pair_axis(const bvh_node *a, size_t near_at, size_t far_at, __m128d o, __m128d inv,
                                  __m128d *tn, __m128d *least)
{
    __m128d t0 = _mm_mul_pd(_mm_sub_pd(slab_pair_load(a, near_at), o), inv);
    __m128d t1 = _mm_mul_pd(_mm_sub_pd(slab_pair_load(a, far_at), o), inv);
    *tn = _mm_max_pd(t0, *tn);
    *least = _mm_min_pd(t1, *least);
}

/* The pad of the least exits, the cap by tmax and the answer (the scalar
 * test's last lines, slab_box_meets_neg); the entries to *ta and *tc. */
static inline HINT_IN_LINE int slab_pair_end(__m128d tn, __m128d least, real tmax, real *ta, real *tc)
{
    __m128d pad = _mm_or_pd(_mm_and_pd(least, _mm_load_pd(slab_pair_k[1])), _mm_load_pd(slab_pair_k[2]));
    least = _mm_mul_pd(least, _mm_add_pd(_mm_load_pd(slab_pair_k[3]), pad));
    __m128d met = _mm_cmple_pd(tn, _mm_min_pd(least, _mm_set1_pd(tmax)));
    _mm_storel_pd(ta, tn);
    _mm_storeh_pd(tc, tn);
    return _mm_movemask_pd(met);
}

/*
 * Whether the ray meets node a (bit 0) and node a + 1 (bit 1) within
 * [tmin, tmax], with their entries in *ta and *tc: slab_box_meets_neg of
 * each.  The offsets are slab_pair_near_at's and slab_pair_far_at's for
 * the ray's neg flags: constants where the walk is made once per octant.  Written out axis by axis (a
 * loop over the axes was kept as one, its offsets in memory).
 */
static inline HINT_IN_LINE int slab_pair_meets(const bvh_node *a, const slab_pair_ray *s, size_t nx, size_t fx, size_t ny,
                                  size_t fy, size_t nz, size_t fz, real tmin, real tmax, real *ta, real *tc)
{
    __m128d tn = _mm_set1_pd(tmin), least = _mm_load_pd(slab_pair_k[0]);
    slab_pair_axis(a, nx, fx, s->o[0], s->inv[0], &tn, &least);
    slab_pair_axis(a, ny, fy, s->o[1], s->inv[1], &tn, &least);
    slab_pair_axis(a, nz, fz, s->o[2], s->inv[2], &tn, &least);
    return slab_pair_end(tn, least, tmax, ta, tc);
}

/* slab_pair_meets from the slab ray itself, its lanes and offsets formed
 * at the call: no pair form made per ray (a shadow walk that tests few
 * inner nodes). */
static inline HINT_IN_LINE int slab_pair_meets_slab(const bvh_node *a, const slab_ray *s, real tmin, real tmax,
                                                        real *ta, real *tc)
{
    __m128d tn = _mm_set1_pd(tmin), least = _mm_load_pd(slab_pair_k[0]);
    slab_pair_axis(a, slab_pair_near_at(0, s->neg[0]), slab_pair_far_at(0, s->neg[0]), _mm_set1_pd(s->o.x),
                   _mm_set1_pd(s->inv.x), &tn, &least);
    slab_pair_axis(a, slab_pair_near_at(1, s->neg[1]), slab_pair_far_at(1, s->neg[1]), _mm_set1_pd(s->o.y),
                   _mm_set1_pd(s->inv.y), &tn, &least);
    slab_pair_axis(a, slab_pair_near_at(2, s->neg[2]), slab_pair_far_at(2, s->neg[2]), _mm_set1_pd(s->o.z),
                   _mm_set1_pd(s->inv.z), &tn, &least);
    return slab_pair_end(tn, least, tmax, ta, tc);
}
#endif

#endif
