/*
 * isect_common.h - the pieces the hit tests share (intersect.c,
 * intersect_quadric.c, intersect_torus.c): below all three, so that each
 * includes it and none includes another's.  Internal to the render layer.
 */
#ifndef REFRAY_ISECT_COMMON_H
#define REFRAY_ISECT_COMMON_H

#include "render/ray.h"

/*@
  // |f + t d|^2: the squared distance from the centre of the point at t,
  // for f = o - c (make prove, spec/proofs.md "Hit tests")
  logic mreal vdist2(vec3 f, vec3 d, mreal t) =
    (f.x + t * d.x) * (f.x + t * d.x) + (f.y + t * d.y) * (f.y + t * d.y) +
    (f.z + t * d.z) * (f.z + t * d.z);
*/

/* The ray parameters the hit tests return are at most 2^1020 in magnitude
 * (spec/proofs.md, "Hit tests"): num/den, or 2^1020 with the sign of
 * num/den where that passes it, decided before dividing so that no
 * infinity is formed (a direction nearly along a plane, a slab or a
 * cylinder's axis); returns 1 when *q is num/den (never for den = 0).  The bound on num holds
 * within the scene's extent ([LANG-EXTENT-1]: differences of coordinates
 * and their dot products with unit vectors). */
/*@ requires \valid(q);
    requires \is_finite(num) && \is_finite(den);
    requires DOUBLES(\abs(num) <= 0x1p1017);
    assigns *q \from num, den;
    assigns \result \from num, den;
    ensures \result == 0 || \result == 1;
    // the bound as two comparisons: Eva narrows a caller's value by them, not by \abs
    ensures \initialized(q) && \is_finite(*q) && DOUBLES(-0x1p1021 <= *q <= 0x1p1021);
    ensures EXACT(\result == 1 ==> den != 0 && *q == num / den && *q * den == num);
    ensures EXACT(\result == 0 ==> \abs(num) >= \abs(den) * 0x1p1020 && \abs(*q) == 0x1p1020);
    ensures EXACT(\result == 0 ==> (*q > 0 <==> (num < 0 <==> den < 0))); */
int isect_quotient(real num, real den, real *q);

/* The roots of |f + t d| = radius, in increasing order; their number (0, 1
 * for a graze, or 2).  Used by the sphere, the cylinder (across its axis)
 * and the torus (its bounding sphere).  A line whose nearest point to the
 * centre is past t = 2^1020 has no roots; a root past 2^1020 is returned as
 * 2^1020 with its sign (isect_quotient): |d| far below |f| (a line nearly
 * along a cylinder's axis).  t[0] and t[1] beyond the roots are 0. */
/*@ requires \valid(t + (0 .. 1));
    // finite centre and radius > 0: check_radius, in_range (scene/check.c);
    // f = o - c, d the ray's (or a part of it): finite (spec/proofs.md, "Hit tests")
    requires vfinite(f) && vfinite(d) && \is_finite(radius) && radius > 0;
    // within the scene's extent ([LANG-EXTENT-1]): a sphere's |f| <= 2^501,
    // R <= 2^500, |d| <= 4; wider for the callers Eva bounds less closely:
    // the torus's bounding sphere (R = major + minor <= 2^501), the
    // cylinder's parts across its axis (|f| <= 2^505, |d| <= 64 to Eva,
    // spec/proofs.md "Hit tests: cylinder, cone, torus")
    requires DOUBLES(vbounded(f, 0x1p505) && radius <= 0x1p501 && vbounded(d, 64));
    assigns t[0 .. 1];
    ensures 0 <= \result <= 2;
    // both written, 0 where no root: Eva does not split a caller's state
    // by the result, so the bounds hold whatever it is
    ensures \is_finite(t[0]) && DOUBLES(-0x1p1021 <= t[0] <= 0x1p1021);
    ensures \is_finite(t[1]) && DOUBLES(-0x1p1021 <= t[1] <= 0x1p1021);
    ensures EXACT(\result == 2 ==> t[0] <= t[1]);   // doubles too: ordered by a comparison
    ensures EXACT(\result == 1 ==> t[0] == -vdot(f, d) / vnorm2(d));
    // the roots of the quadratic, unless held at 2^1020: a (R^2 - |l|^2) =
    // b^2 - a c and (q + b)^2 = b^2 - a c give it (lemma_sphere_roots,
    // lemma_sphere_graze in isect_common.c; admitted before 2026-12-02)
    ensures EXACT(\result >= 1 && \abs(t[0]) < 0x1p1020 ==> vdist2(f, d, t[0]) == radius * radius);
    ensures EXACT(\result == 2 && \abs(t[1]) < 0x1p1020 ==> vdist2(f, d, t[1]) == radius * radius); */
int isect_sphere_roots(vec3 f, vec3 d, real radius, real t[2]);

/* Whether sphere_hits (intersect.c) would keep no crossing of the sphere
 * of centre o - f for r, told without the roots ([NUM-SPHERE-2],
 * spec/numerics.md 2.1a): tmin >= 0, the origin outside by a margin that
 * survives isect_sphere_roots' rounding (|f| rounded > R, so c >= 0) and
 * f.d > 0 (so q < 0): both roots are then <= 0.  When the origin is far
 * (sphere_hits refines, |f|^2 > 4 R^2 as it rounds it), both roots are
 * below -|f|/(4|d|), and with |o| <= 2^23 |f| sphere_root_possible's
 * slack cannot lift them to tmin.  R^2 >= 2^-1000 keeps |f| in
 * vec_length_fast's range of sqrt(f.f), the f2 computed here.  A ray
 * leaving a sphere, or a shadow ray leaving a neighbour, meets many
 * spheres' boxes while moving away from them. */
static inline int isect_sphere_moving_away(vec3 f, real radius, const ray *r)
{
    if (!(vec_dot(f, r->dir) > 0.0 && r->tmin >= 0.0))
        return 0;
    real rr = radius * radius, f2 = vec_length2(f);
    if (!(rr >= 0x1p-1000 && f2 > rr * (1.0 + 4.0 * REAL_EPSILON)))
        return 0;
    if (!(f2 > 4.0 * radius * radius))
        return 1;
    real m = vec_max_abs(r->origin);
    return m * m <= 0x1p46 * f2;
}
/* Fills a hit: prim -1, part 0, no barycentrics, shading normal = n,
 * entering = dir . n < 0. */
/*@ requires \valid(h);
    requires vfinite(n) && vfinite(dir);
    assigns *h;
    // a copy (doubles too; Eva does not compare the ranges it keeps)
    ensures EXACT(h->t == t && veq(h->point, p) && veq(h->normal, n) && veq(h->shading_normal, n));
    ensures h->prim == -1 && h->part == 0 && h->b1 == 0 && h->b2 == 0;
    ensures EXACT(h->entering == (vdot(dir, n) < 0 ? 1 : 0)); */
void isect_hit_set(hit *h, real t, vec3 p, vec3 n, vec3 dir);

#endif
