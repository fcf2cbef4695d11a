/*
 * slab.h - the slab test of a ray against an axis-aligned box, shared by
 * the BVH's traversal (bvh.c) and the kept-frame hit's box (intersect.c),
 * which must cull by the same arithmetic ([NUM-FRAME-1]).
 *
 * It is the robust test of Ize ("Robust BVH Ray Traversal", JCGT 2(2),
 * 2013): the exit distance is enlarged by 1 + 4 eps (> 1 + 2 gamma_3) so
 * rounding never culls a box the ray touches, and a NaN from 0 * inf
 * (origin on a slab plane, direction parallel to it) never narrows the
 * interval because the comparisons that update it are false for NaN.
 * Every step is monotone in the box's bounds, so a box that holds another
 * gives an interval that holds the other's.
 */
#ifndef REFRAY_SLAB_H
#define REFRAY_SLAB_H

#include <float.h>
#include "render/ray.h"

#define SLAB_EXIT_PAD (4.0 * DBL_EPSILON)

/* A ray prepared for slab tests: 1/d with signed infinities for d = +-0. */
typedef struct slab_ray {
    vec3 o, inv;
    int neg[3];
} slab_ray;

static inline real slab_inverse(real d) { return d != 0.0 ? 1.0 / d : copysign(INFINITY, d); }

static inline slab_ray slab_make(const ray *r)
{
    slab_ray s;
    s.o = r->origin;
    s.inv = vec_make(slab_inverse(r->dir.x), slab_inverse(r->dir.y), slab_inverse(r->dir.z));
    /* inv is never 0 or NaN (d is finite), so < 0 is its sign bit; and
     * Frama-C, which parses this through intersect.c, has no signbit. */
    s.neg[0] = s.inv.x < 0;
    s.neg[1] = s.inv.y < 0;
    s.neg[2] = s.inv.z < 0;
    return s;
}

/* One slab's entry and unscaled exit. */
static inline void slab_ends(real lo, real hi, real o, real inv, int neg, real *t0, real *t1)
{
    *t0 = ((neg ? hi : lo) - o) * inv;
    *t1 = ((neg ? lo : hi) - o) * inv;
}

/* Narrows [*tn, *tf] by one slab; NaN leaves it unchanged (see the top). */
static inline void slab(real lo, real hi, real o, real inv, int neg, real *tn, real *tf)
{
    real t0, t1;
    slab_ends(lo, hi, o, inv, neg, &t0, &t1);
    /* Enlarge the exit by scaling, not by adding |t1| * pad: for t1 = -inf
     * (a box wholly to one side of a parallel ray) that would be NaN and
     * the box would never be culled. */
    t1 *= 1.0 + copysign(SLAB_EXIT_PAD, t1);   /* 1 + pad for t1 >= 0, 1 - pad below: no branch */
    if (t0 > *tn)
        *tn = t0;
    if (t1 < *tf)
        *tf = t1;
}

/* Narrows [*tn, *tf] to where the ray is within the box [lo, hi]. */
static inline void slab_box(vec3 lo, vec3 hi, const slab_ray *s, real *tn, real *tf)
{
    slab(lo.x, hi.x, s->o.x, s->inv.x, s->neg[0], tn, tf);
    slab(lo.y, hi.y, s->o.y, s->inv.y, s->neg[1], tn, tf);
    slab(lo.z, hi.z, s->o.z, s->inv.z, s->neg[2], tn, tf);
}


/*
 * Whether slab_box narrows [tmin, tmax] to a nonempty interval, and its
 * entry in *enter: the same answer and the same entry to the bit, with
 * the exit's pad applied once, to the least unscaled exit, not to each.
 * The pad, pad(t) = t (1 + copysign(SLAB_EXIT_PAD, t)) rounded, is
 * non-decreasing in t (a rounded product by a positive constant on either
 * side of 0, at most -0 below it and at least +0 above), so the least of
 * the padded exits is the pad of the least exit (equal as values; a zero's
 * sign does not change a comparison).  A NaN exit narrows nothing in
 * either form: it never passes `<`, and the least starts at +inf, whose
 * pad is +inf.  The BVH's walks read only the entry and the answer, and
 * so save the pad's four operations on two of the three axes.
 * slab_box_meets_neg takes the neg flags as arguments: the same
 * selections, so the same bits; a walk that passes them as constants
 * (bvh.c, one copy of the nearest walk per octant) has no choice left to
 * make per node.
 */
static inline int slab_box_meets_neg(vec3 lo, vec3 hi, const slab_ray *s, int nx, int ny, int nz, real tmin,
                                     real tmax, real *enter)
{
    real x0, x1, y0, y1, z0, z1;
    slab_ends(lo.x, hi.x, s->o.x, s->inv.x, nx, &x0, &x1);
    slab_ends(lo.y, hi.y, s->o.y, s->inv.y, ny, &y0, &y1);
    slab_ends(lo.z, hi.z, s->o.z, s->inv.z, nz, &z0, &z1);
    real tn = tmin, least = INFINITY;
    tn = x0 > tn ? x0 : tn;
    tn = y0 > tn ? y0 : tn;
    tn = z0 > tn ? z0 : tn;
    least = x1 < least ? x1 : least;
    least = y1 < least ? y1 : least;
    least = z1 < least ? z1 : least;
    least *= 1.0 + copysign(SLAB_EXIT_PAD, least);
    *enter = tn;
    return tn <= (least < tmax ? least : tmax);
}

/* The ray's octant: bit k is neg[k]. */
static inline int slab_octant(const slab_ray *s)
{
    return s->neg[0] | s->neg[1] << 1 | s->neg[2] << 2;
}

static inline int slab_box_meets(vec3 lo, vec3 hi, const slab_ray *s, real tmin, real tmax, real *enter)
{
    return slab_box_meets_neg(lo, hi, s, s->neg[0], s->neg[1], s->neg[2], tmin, tmax, enter);
}

#endif
