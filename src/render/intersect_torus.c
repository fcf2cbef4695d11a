/*
 * intersect_torus.c - the ring torus (intersect_shapes.h): the points at
 * distance `minor` (r) from the circle of radius `major` (R) about `center`
 * across the unit `axis` a.  With q = p - center, z = q.a and
 * rho = |q - z a| (the distance from the axis), the distance from the
 * circle is D = sqrt((rho - R)^2 + z^2) and the surface is D = r.
 *
 * Squaring twice gives the quartic of the literature (P. Hanrahan in
 * Glassner, ed., "An Introduction to Ray Tracing", 1989; J. M. Cychosz,
 * "Intersecting a Ray with an Elliptical Torus", Graphics Gems II, 1991):
 *     (|q|^2 + R^2 - r^2)^2 - 4 R^2 rho^2 = (D^2 - r^2)((rho + R)^2 + z^2 - r^2),
 * whose second factor is positive for a ring torus (r < R), so the quartic
 * and D - r have the same sign.  Along the line q(s) = p0 + s e (e unit)
 * it is s^4 + c3 s^3 + c2 s^2 + c1 s + c0 with alpha = p0.e,
 * beta = |p0|^2 + R^2 - r^2 and the parts p0', e' of p0 and e across the
 * axis:
 *     c3 = 4 alpha,                c2 = 4 alpha^2 + 2 beta - 4 R^2 |e'|^2,
 *     c1 = 4 alpha beta - 8 R^2 p0'.e',
 *     c0 = (D0 - r)(D0 + r) ((rho0 + R)^2 + z0^2 - r^2)    (D0, rho0, z0 at p0).
 *
 * Three steps keep it robust at the scales of scenes/stress:
 *   1. the line is met with the bounding sphere (radius R + r, by
 *      isect_sphere_roots' perpendicular foot); p0 is the middle of that chord,
 *      the point of the line nearest the centre, and lengths are divided by
 *      R + r: the coefficients are of order 1 and the roots lie in
 *      [-h, h], h <= 1, however far the ray starts;
 *   2. the real roots in [-h, h] are isolated by the derivative cascade:
 *      the roots of P''' split [-h, h] where P'' is monotone, the roots of
 *      P'' where P' is, the roots of P' where P is; in each monotone piece
 *      a sign change brackets exactly one root, found by Newton's method
 *      safeguarded by bisection.  No closed form (Ferrari's cancels
 *      badly for thin tori), no root is lost to a near-double root
 *      elsewhere, and a graze (a double root) is a sign change only when
 *      the rounded quartic changes sign;
 *   3. each root is polished by Newton's method on the distance itself,
 *      g(t) = D(o + t d) - r, whose gradient is the unit normal n, so
 *      t <- t - g / (n.d), restarted from the point each time (as the
 *      sphere's refinement): the hit point ends within a few ulps of its
 *      own magnitude of the surface, however far the origin.  A polish
 *      that would move the root farther than the quartic could have been
 *      wrong (a grazing pair) is not taken.
 * spec/numerics.md ("The torus") has the measured errors.
 */
#include "render/intersect_shapes.h"
#include "render/isect_common.h"

enum { DEGREE = 4, ROOTS_MAX = 4 };

/*
 * Bounds for make prove's Eva run (spec/proofs.md, "Round 9"): values the
 * code keeps already, stated where Eva, which keeps no relation between two
 * values, can use them, or cases that are no hit.
 *   T_FAR: a ray parameter (the chord's middle and half length, a root, a
 *     polish step).  A hit within the extent ([LANG-EXTENT-1]) is at
 *     |t| <= 2^506 (a world ray's direction has a component >= 1/8, a
 *     transform keeps t): past 2^1012 none is.
 *   P_FAR: the chord's middle o + tm d - c, within R (1 + 2^-50) of the
 *     centre and the rounding of tm d (2^-52 |f| <= 2^450).
 *   MIDDLE_FAR: the chord's middle p0 and its half length, in units of the
 *     bounding radius R: 1 at most for the exact chord; past 2 only where
 *     the rounding of tm d (2^-52 |f|) exceeds R, an origin more than 2^50
 *     times the torus's size from it, whose rays the doubles do not place
 *     on the torus (its hits were rounding noise).
 *   UNIT_MAX: a component of a unit vector formed as d (1/|d|).
 *   X_FAR: a point the polish visits, within 7.5 R (p0 and u within 2 R,
 *     a move within limit, 2 R) of a centre within 2^500.
 *   R_FAR: such a point's distance from the axis.
 */
#define T_FAR 0x1p1012
#define P_FAR 0x1p510
#define MIDDLE_FAR 2.0
#define UNIT_MAX 0x1.00001p0
#define X_FAR 0x1p505
#define R_FAR 0x1p506

/* Two comparisons in the caller's test: Eva narrows v by them (not by a
 * function's result, nor by fabs). */
#define WITHIN(v, m) ((v) <= (m) && (v) >= -(m))
/* v, or the end of [lo, hi] it passes (two comparisons: Eva narrows by
 * them).  Its clauses are comparisons and copies of the doubles: WP's
 * proof holds of them (EXACT: Eva's intervals keep no relation to show
 * them by, and it narrows by the code itself). */
/*@ assigns \nothing;
    ensures EXACT(lo <= hi ==> lo <= \result <= hi);
    ensures EXACT(lo <= v <= hi ==> \result == v); */
static real in_range(real v, real lo, real hi) { return v > hi ? hi : v < lo ? lo : v; }

/* p[0] + p[1] u + ... + p[deg] u^deg by Horner's rule. */
/*@ requires 0 <= deg && \valid_read(p + (0 .. deg));
    assigns \nothing; */
static real poly_eval(const real *p, int deg, real u)
{
    real v = p[deg];
    /*@ loop invariant -1 <= i < deg;
        loop assigns i, v;
        loop variant i + 1; */
    for (int i = deg - 1; i >= 0; i--)
        v = v * u + p[i];
    return v;
}

/*@ requires 1 <= deg <= DEGREE && \valid_read(p + (0 .. deg)) && \valid(dp + (0 .. deg - 1));
    requires \separated(dp + (0 .. deg - 1), p + (0 .. deg));
    assigns dp[0 .. deg - 1]; */
static void poly_derive(const real *p, int deg, real *dp)
{
    /*@ loop invariant 1 <= i <= deg + 1;
        loop assigns i, dp[0 .. deg - 1];
        loop variant deg + 1 - i; */
    for (int i = 1; i <= deg; i++)
        dp[i - 1] = (real)i * p[i];
}

/* The one root of p in [a, b], where p is monotone and changes sign
 * (fa = p(a)): Newton from the middle, falling back to bisection whenever
 * a step would leave the bracket; stops when the bracket or the step is
 * below 2^-50 (lengths here are of order 1). */
/*@ requires 1 <= deg && \valid_read(p + (0 .. deg)) && \valid_read(dp + (0 .. deg - 1));
    assigns \nothing; */
static real monotone_root(const real *p, const real *dp, int deg, real a, real b, real fa)
{
    real x = 0.5 * (a + b);
    /*@ loop invariant 0 <= i <= 200;
        loop assigns i, x, a, b;
        loop variant 200 - i; */
    for (int i = 0; i < 200; i++) {
        real fx = poly_eval(p, deg, x);
        if (fx == 0)
            return x;
        if ((fx < 0) == (fa < 0))
            a = x;
        else
            b = x;
        /* A quotient isect_quotient holds (past 2^1020, or slope 0) puts
         * next far outside [a, b], as the huge or infinite one did. */
        real slope = poly_eval(dp, deg - 1, x), step;
        isect_quotient(fx, slope, &step);
        real next = x - step;
        if (!(next > a && next < b))
            next = 0.5 * (a + b);
        if (fabs(next - x) <= 0x1p-50 || b - a <= 0x1p-50)
            return next;
        x = next;
    }
    return x;
}

/* The real roots of p (degree deg >= 1) in [lo, hi], increasing; their number. */
/*@ requires 1 <= deg <= DEGREE && \valid_read(p + (0 .. deg)) && \valid(roots + (0 .. deg - 1));
    requires \separated(roots + (0 .. deg - 1), p + (0 .. deg));
    decreases deg;
    assigns roots[0 .. deg - 1];
    ensures 0 <= \result <= deg; */
static int poly_roots(const real *p, int deg, real lo, real hi, real *roots)
{
    if (deg == 1) {
        real u = -p[0] / p[1];
        roots[0] = u;
        return p[1] != 0 && u >= lo && u <= hi;
    }
    real dp[DEGREE], ends[ROOTS_MAX + 2] = {0, 0, 0, 0, 0, 0};
    poly_derive(p, deg, dp);
    int ncut = poly_roots(dp, deg - 1, lo, hi, ends + 1), found = 0;
    ends[0] = lo;
    ends[ncut + 1] = hi;
    /*@ loop invariant 0 <= i <= ncut + 1 && 0 <= found <= i;
        loop assigns i, found, roots[0 .. deg - 1];
        loop variant ncut + 1 - i; */
    for (int i = 0; i <= ncut; i++) {
        real a = ends[i], b = ends[i + 1], fa = poly_eval(p, deg, a), fb = poly_eval(p, deg, b);
        if (fa == 0) {
            if (found == 0 || roots[found - 1] != a)
                roots[found++] = a;
        } else if (fb == 0 && i == ncut) {
            roots[found++] = b;
        } else if ((fa < 0) != (fb < 0) && fb != 0) {
            roots[found++] = monotone_root(p, dp, deg, a, b, fa);
        }
    }
    return found;
}

typedef struct torus {
    vec3 c, a;
    real major, minor;
} torus;

/* The distance from the core circle at p and its gradient, the outward
 * unit normal; 0 on the axis or the circle itself, where neither exists
 * (*n is then the axis). */
/*@ requires \valid_read(tr) && \valid(d) && \valid(n) && \separated(d, n, tr);
    assigns *d, *n; */
static int torus_distance(const torus *tr, vec3 p, real *d, vec3 *n)
{
    vec3 q = vec_sub(p, tr->c);
    /* For p within X_FAR, a centre within 2^500 and |a_i| <= 1 + 2^-29
     * (check.c): |z| <= 3 (2^505 + 2^500) (1 + 2^-29) < 2^508; |across| <=
     * |q| (|a|^2 <= 2), so rho within R_FAR; major <= 2^500, so |dr| <
     * 2^507.  Never held, stated for WP (hypot's bounds) and Eva. */
    real z = in_range(vec_dot(q, tr->a), -0x1p508, 0x1p508);
    vec3 across = vec_madd(q, tr->a, -z);
    real rho = in_range(vec_length(across), 0, R_FAR), dr = in_range(rho - tr->major, -0x1p507, 0x1p507), k, zd;
    *d = hypot(dr, z);
    *n = tr->a;
    /* k = dr / (d rho), held only within 2^-1020 of the axis (|dr| <= d,
     * hypot): taken as the axis itself.  z / d is a zero's own sign. */
    if (!(rho > 0) || !(*d > 0) || !isect_quotient(dr, *d * rho, &k))
        return 0;
    if (z == 0)
        zd = z;
    else
        isect_quotient(z, *d, &zd);
    /* |across_i| <= rho (vec_length is m sqrt(s), s >= 1) and |dr| <= d,
     * |z| <= d: |k| <= 1/rho, |across_i k| <= 1 and |z / d| <= 1 to a few
     * ulps.  The holds state that for Eva, apart for rho < 1 and >= 1. */
    if (rho >= 1)
        k = in_range(k, -2, 2);
    across = vec_make(in_range(across.x, -2 * rho, 2 * rho), in_range(across.y, -2 * rho, 2 * rho),
                      in_range(across.z, -2 * rho, 2 * rho));
    vec3 side = vec_scale(across, k);
    side = vec_make(in_range(side.x, -UNIT_MAX, UNIT_MAX), in_range(side.y, -UNIT_MAX, UNIT_MAX),
                    in_range(side.z, -UNIT_MAX, UNIT_MAX));
    *n = vec_madd(side, tr->a, in_range(zd, -1, 1));
    return 1;
}

/* Polishes the root t (step 3) from x, its point ray_at(r, t); *p and *n
 * are the point and the normal.  dl: |r->dir|; limit: the largest move in
 * t that is still the same root. */
/*@ requires \valid_read(tr) && \valid_read(r) && \valid(p) && \valid(n) && \separated(p, n, tr, r);
    assigns *p, *n; */
static real torus_polish(const torus *tr, const ray *r, real dl, real t, real limit, vec3 x, vec3 *p, vec3 *n)
{
    real tt = t, d;
    vec3 nn = tr->a;
    /*@ loop unroll 8;
        loop invariant 0 <= i <= 8;
        loop assigns i, x, tt, d, nn;
        loop variant 8 - i; */
    for (int i = 0; i < 8 && torus_distance(tr, x, &d, &nn); i++) {
        real slope = vec_dot(nn, r->dir), step;
        if (slope == 0)
            break;
        /* A step held (past 2^1020) or past 2 T_FAR is farther than limit
         * (<= T_FAR, as |tt - t|): the test below refused it. */
        if (!isect_quotient(-(d - tr->minor), slope, &step) || !WITHIN(step, 2 * T_FAR))
            break;
        if (!(fabs(tt + step - t) <= limit))
            break;
        vec3 next = vec_madd(x, r->dir, step);
        if (!(WITHIN(next.x, X_FAR) && WITHIN(next.y, X_FAR) && WITHIN(next.z, X_FAR)))
            break;
        x = next;
        tt += step;
        /* Done when the move is below the rounding of the point itself. */
        vec3 ax = vec_make(fabs(x.x), fabs(x.y), fabs(x.z));
        if (fabs(step) * dl <= REAL_EPSILON * (vec_max_component(ax) + tr->major))
            break;
    }
    torus_distance(tr, x, &d, n);
    *p = x;
    return tt;
}

/* The quartic's coefficients about p0 (lengths divided by the bounding
 * radius; e unit), leading coefficient 1 in c[4]. */
/*@ requires \valid_read(tr) && \valid(c + (0 .. DEGREE)) && \separated(c + (0 .. DEGREE), tr);
    assigns c[0 .. DEGREE]; */
static void torus_quartic(const torus *tr, real scale, vec3 p0, vec3 e, real c[DEGREE + 1])
{
    /* major <= scale (minor > 0, a monotone rounding) and 2 minor < scale
     * (minor < major): the holds never change big or small. */
    real big = in_range(tr->major / scale, 0, 1), small = in_range(tr->minor / scale, 0, 0.5);
    /* |p0_i| <= 2, |a_i| <= 1 + 2^-29 (check.c): never held; for WP. */
    real z0 = in_range(vec_dot(p0, tr->a), -8, 8), ez = vec_dot(e, tr->a);
    vec3 p0x = vec_madd(p0, tr->a, -z0), ex = vec_madd(e, tr->a, -ez);
    real alpha = vec_dot(p0, e), m = vec_length2(p0), beta = m + (big - small) * (big + small);
    /* |p0x| <= |p0| (1 + 2^-29) <= 2 sqrt(3) (1 + 2^-29): never held. */
    real rho0 = in_range(vec_length(p0x), 0, 4), d0 = hypot(rho0 - big, z0);
    c[4] = 1;
    c[3] = 4 * alpha;
    c[2] = 4 * alpha * alpha + 2 * beta - 4 * big * big * vec_length2(ex);
    c[1] = 4 * alpha * beta - 8 * big * big * vec_dot(p0x, ex);
    c[0] = (d0 - small) * (d0 + small) * ((rho0 + big) * (rho0 + big) + z0 * z0 - small * small);
}

int isect_torus_hits(vec3 center, vec3 axis, real major, real minor, const ray *r, hit *out, int max)
{
    torus tr = {center, axis, major, minor};
    /* Every array written before it is read (Eva reads them on paths it
     * cannot tell are dead). */
    real scale = major + minor, tb[2] = {0, 0}, c[DEGREE + 1], u[ROOTS_MAX] = {0, 0, 0, 0};
    vec3 f = vec_sub(r->origin, center);
    /* A line that only touches the bounding sphere touches the torus at
     * most on its outer equator: a graze, counted as a miss. */
    if (isect_sphere_roots(f, r->dir, scale, tb) < 2)
        return 0;
    /* Two roots: some d_i^2 > 0, so |d_i| >= 2^-538 and vec_length (m
     * sqrt(s), s >= 1) at least that: the hold never changes dl. */
    real dl = vec_length(r->dir), tm = 0.5 * (tb[0] + tb[1]), w = 0.5 * (tb[1] - tb[0]), half;
    dl = dl < 0x1p-540 ? 0x1p-540 : dl;
    if (!(WITHIN(tm, T_FAR) && WITHIN(w, T_FAR)))
        return 0;
    vec3 e = vec_scale(r->dir, 1.0 / dl), mid = vec_madd(f, r->dir, tm);
    if (!(WITHIN(mid.x, P_FAR) && WITHIN(mid.y, P_FAR) && WITHIN(mid.z, P_FAR)))
        return 0;
    vec3 p0 = vec_scale(mid, 1.0 / scale);
    if (!isect_quotient(w * dl, scale, &half) || !WITHIN(half, MIDDLE_FAR) || !WITHIN(p0.x, MIDDLE_FAR) ||
        !WITHIN(p0.y, MIDDLE_FAR) || !WITHIN(p0.z, MIDDLE_FAR))
        return 0;
    /* |e_i| = |d_i| (1/dl) with dl >= |d_i|: never held. */
    e = vec_make(in_range(e.x, -UNIT_MAX, UNIT_MAX), in_range(e.y, -UNIT_MAX, UNIT_MAX),
                 in_range(e.z, -UNIT_MAX, UNIT_MAX));
    torus_quartic(&tr, scale, p0, e, c);
    /* The torus touches its bounding sphere along the outer equator: a ray
     * entering there has a root at the chord's very end, which rounding may
     * put just outside.  Outside the sphere the quartic is positive (no
     * point of the torus is there), so a margin adds no root.
     * [NUM-TORUS-2] From a far origin the chord's ends carry the rounding
     * of t, a few eps |t|: the margin is 2^-44 |tm| dl / scale (256 eps |tm|
     * in the chord's units) where that is past 2^-20 (a torus seen from
     * 2^24 sizes away; nearer, 2^-20 as before), and at most 1. */
    real far;
    isect_quotient(fabs(tm) * dl, 0x1p44 * scale, &far);
    half += far > 1 ? 1 : far > 0x1p-20 ? far : 0x1p-20;
    int n = poly_roots(c, DEGREE, -half, half, u), found = 0;
    hit h[ROOTS_MAX] = {0};
    /*@ loop invariant 0 <= i <= n && 0 <= found <= i;
        loop invariant EXACT(\forall integer j; 0 <= j < found ==> r->tmin < h[j].t < r->tmax);
        loop assigns i, found, h[0 .. ROOTS_MAX - 1];
        loop variant n - i; */
    for (int i = 0; i < n; i++) {
        /* The same root until halfway to its neighbours (or 1e-3 of the
         * chord past the outer ones). */
        real below = i > 0 ? 0.5 * (u[i] - u[i - 1]) : 1e-3 * half;
        real above = i + 1 < n ? 0.5 * (u[i + 1] - u[i]) : 1e-3 * half;
        /* u scale / dl and limit past 2^1020 (isect_quotient holds them),
         * or t past T_FAR: no hit. */
        real du, limit;
        if (!isect_quotient(u[i] * scale, dl, &du) || !isect_quotient((below < above ? below : above) * scale, dl, &limit))
            continue;
        real t = tm + du;
        if (!(WITHIN(t, T_FAR) && WITHIN(limit, T_FAR)))
            continue;
        vec3 x = ray_at(r, t), p, nn;
        if (!(WITHIN(x.x, X_FAR) && WITHIN(x.y, X_FAR) && WITHIN(x.z, X_FAR)))
            continue;
        t = torus_polish(&tr, r, dl, t, limit, x, &p, &nn);
        /* Set in a local, copied: Eva shows isect_hit_set's clauses of
         * one hit, not of h[found], an index it does not pin. */
        if (t > r->tmin && t < r->tmax) {
            hit one;
            isect_hit_set(&one, t, p, nn, r->dir);
            h[found++] = one;
        }
    }
    /*@ loop invariant 1 <= i <= found || (found == 0 && i == 1);
        loop invariant EXACT(\forall integer k; 0 <= k < found ==> r->tmin < h[k].t < r->tmax);
        loop assigns i, h[0 .. ROOTS_MAX - 1];
        loop variant found - i; */
    for (int i = 1; i < found; i++)
        /*@ loop invariant 0 <= j <= i;
            loop invariant EXACT(\forall integer k; 0 <= k < found ==> r->tmin < h[k].t < r->tmax);
            loop assigns j, h[0 .. ROOTS_MAX - 1];
            loop variant j; */
        for (int j = i; j > 0 && h[j].t < h[j - 1].t; j--) {
            hit s = h[j];
            h[j] = h[j - 1];
            h[j - 1] = s;
        }
    /*@ loop invariant 0 <= i <= found && i <= max;
        loop invariant EXACT(\forall integer j; 0 <= j < i ==> out[j].t == h[j].t);
        loop assigns i, out[0 .. max - 1];
        loop variant found - i; */
    for (int i = 0; i < found && i < max; i++)
        out[i] = h[i];
    return found < max ? found : max;
}
