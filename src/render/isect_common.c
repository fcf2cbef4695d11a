/*
 * isect_common.c - what the hit tests share (isect_common.h).
 */
#include "render/isect_common.h"

void isect_hit_set(hit *h, real t, vec3 p, vec3 n, vec3 dir)
{
    h->t = t;
    h->point = p;
    h->normal = n;
    h->shading_normal = n;
    h->prim = -1;
    h->part = 0;
    h->entering = vec_dot(dir, n) < 0.0;
    h->b1 = h->b2 = 0.0;
}

/*
 * Sphere.  With f = o - c, |f + t d|^2 = R^2 is a t^2 + 2 b t + c = 0 with
 * a = d.d, b = f.d, c = f.f - R^2.  Following Haines, Guenther and
 * Akenine-Moller, "Precision Improvements for Ray/Sphere Intersection"
 * (Ray Tracing Gems I, ch. 7):
 *   - the quarter discriminant b^2 - a c equals a (R^2 - |l|^2) with
 *     l = f - (b/a) d the vector from the centre to the line's nearest
 *     point; |l| is computed directly, so the small difference is not lost
 *     between two huge squares (a small sphere seen from far away);
 *   - c is formed as (|f| - R)(|f| + R), exact to rounding near the surface;
 *   - q = -(b + sign(b) sqrt(disc)) has no cancellation, and the roots are
 *     c/q and q/a (the product of the roots is c/a).
 * Writes the roots in increasing order; returns their number (1 when the
 * discriminant is exactly 0, |l| = R: a graze).
 */
/* |num| < |den| 2^1020 is decided by a product of den with a power of
 * two, exact below |den| = 2^-3; from there on the quotient is within the
 * bound whenever |num| <= 2^1017.  The strict test keeps 0/0 out.  The
 * quotient is formed from the magnitudes, where Eva sees the test's bound:
 * the same double as num/den (the rounding is symmetric) but for the sign
 * of a zero, which no open interval (tmin >= 0, t) tells apart. */
int isect_quotient(real num, real den, real *q)
{
    real an = fabs(num), ad = fabs(den);
    if (ad >= 0x1p-3 || an < ad * 0x1p1020) {
        real m = an / ad;
        /* Below 2^-3 the test bounds m by 2^1020 (an exact product, a
         * monotone rounding), so this never changes m; it is written out
         * for Eva, which keeps no relation between an and ad and would
         * bound m only by 2^1020 times the spread of ad in a box. */
        if (ad < 0x1p-3 && m > 0x1p1020)
            m = 0x1p1020;
        *q = (num < 0) != (den < 0) ? -m : m;
        return 1;
    }
    *q = (num < 0) == (den < 0) ? 0x1p1020 : -0x1p1020;
    return 0;
}

/* A root of the quadratic, c/q or q/a: held at 2^1020 with its sign past
 * it (the half chord over a tiny |d|). */
/*@ requires \is_finite(num) && \is_finite(den) && DOUBLES(\abs(num) <= 0x1p1017);
    assigns \nothing;
    // the bound as two comparisons: Eva narrows a caller's value by them, not by \abs
    ensures \is_finite(\result) && DOUBLES(-0x1p1021 <= \result <= 0x1p1021);
    ensures EXACT(\abs(num) < \abs(den) * 0x1p1020 ==> \result == num / den);
    ensures EXACT(\abs(num) >= \abs(den) * 0x1p1020 ==> \abs(\result) >= 0x1p1020); */
static real held_root(real num, real den)
{
    real q;
    isect_quotient(num, den, &q);
    return q;
}

int isect_sphere_roots(vec3 f, vec3 d, real radius, real t[2])
{
    /* vec_length2, not vec_dot(d, d): the same roundings, but Eva sees
     * squares, so a keeps the largest component's square as its lower
     * bound (vec_dot's two copies of d give products of either sign). */
    real a = vec_length2(d);
    if (!(a > 0.0))
        return 0;
    real b = vec_dot(f, d), foot;
    /* -b/a past 2^1020: |d| is below 2^-519 beside |f| (2^501 at most). */
    if (!isect_quotient(-b, a, &foot))
        return 0;
    vec3 l = vec_madd(f, d, foot);
    /* A quick miss without the square root: with R^2 normal, |l|^2 > R^2
     * (1 + 4 eps) (each side rounded) gives sqrt(|l|^2) > R (1 + 2u) even
     * after its rounding, so the test below would fail too. */
    real rr = radius * radius, l2 = vec_length2(l);
    if (rr >= REAL_MIN && l2 > rr * (1.0 + 4.0 * REAL_EPSILON))
        return 0;
    real ll = vec_length_fast(l);
    /* Decide hit or miss on ll <= R itself (R - ll >= 0 is the same test
     * for doubles): the product (R - ll)(R + ll) underflows to -0 for a
     * sphere below about 1e-154 and would pass for a graze.  The square
     * root is taken factor by factor for the same reason. */
    real gap = radius - ll;
    if (!(gap >= 0.0))
        return 0;
    real root = sqrt(a * gap) * sqrt(radius + ll);
    if (root == 0.0) {
        t[0] = foot;
        return 1;
    }
    real lf = vec_length_fast(f);
    real c = (lf - radius) * (lf + radius);
    real q = -(b + copysign(root, b));
    real t0 = held_root(c, q), t1 = held_root(q, a);
    t[0] = t0 < t1 ? t0 : t1;
    t[1] = t0 < t1 ? t1 : t0;
    return 2;
}

/* A disk of radius R across the unit axis a spans R sqrt(1 - a_k^2) about
 * its centre along axis k. */
void isect_disk_extent(vec3 a, real radius, vec3 *e)
{
    *e = vec_make(radius * sqrt(fmax(0.0, 1.0 - a.x * a.x)), radius * sqrt(fmax(0.0, 1.0 - a.y * a.y)),
                  radius * sqrt(fmax(0.0, 1.0 - a.z * a.z)));
}
