/*
 * intersect_quadric.c - cylinder and cone (intersect_shapes.h).
 *
 * Both are seen along their axis a = (to - from)/len from the end `from`:
 * a point o + t d has the axial coordinate z0 + t dz (z0 = (o - from).a,
 * dz = d.a) and the part across the axis fp + t dp.  The side is where
 * |fp + t dp| equals the radius at that height, rho(z) = r0 + k z with
 * k = (r1 - r0)/len (k = 0: a cylinder); the ends are the planes z = 0 and
 * z = len (the slab).  The cone's equation is formed scaled by a power of
 * two mu (quadric.mu, cone_slope): exact, so the same roots, but k mu and
 * the lengths times mu are small enough that no term overflows, where k
 * itself reaches 2^1001 (a cone 2^-500 long and 2^500 wide).
 *
 * A closed one is a convex solid: the points of the slab inside the side.
 * The line meets it in one interval (Kay and Kajiya's slabs, "Ray Tracing
 * Complex Scenes", SIGGRAPH 1986, with the side as one more constraint):
 * it enters at the later of the slab's and the side's entries and leaves
 * at the earlier of their exits.  Deciding both crossings from one interval
 * leaves no gap at the rim between side and cap.  An open one is the side
 * alone, cut by the slab: a sheet, like a plane.
 *
 * The side, |fp + t dp|^2 = (rho0 + s t)^2 with rho0 = r0 + k z0 and
 * s = k dz, is a t^2 + 2 b t + c = 0 with
 *     a = |dp|^2 - s^2,  b = fp.dp - rho0 s,  c = |fp|^2 - rho0^2.
 * For the cylinder (s = 0) it is the sphere's equation in the plane across
 * the axis, solved by isect_sphere_roots' perpendicular foot
 * (isect_common.c).  For the cone, a and c are formed as products of a
 * difference and a sum (exact to rounding near the surface), and the
 * discriminant b^2 - a c with both products' rounding errors recovered by
 * fma, so that a ray along a generator or just grazing the side is decided
 * from the exact sign of the rounded coefficients.  a may be negative (a ray steeper
 * than the side): then the line is inside the double cone outside its
 * roots, and the slab keeps the one nappe between the ends.
 *
 * A root of the side is refined like the sphere's: the equation is solved
 * again from o' = o + t d, where its root of least magnitude is a Newton
 * step onto the surface, so the hit point's error is relative to the
 * point itself and not to a far ray origin.  Cap points are projected onto
 * their plane.
 */
#include "render/intersect_shapes.h"
#include "render/isect_common.h"

/* The ray seen along the axis. */
typedef struct axial {
    vec3 a;          /* unit axis */
    real len;        /* |to - from| */
    real z0, dz;     /* axial coordinate of the origin, and its rate along d */
    vec3 fp, dp;     /* the parts of o - from and of d across the axis */
} axial;

/* Holds: bounds a value already keeps, stated for Eva (make prove), which
 * keeps no relation between a vector and its length.  UNIT_HELD bounds a
 * component of w (1/l) with l = vec_length(w) >= |w_i| (m sqrt(s) with
 * s >= 1): at most 1 + 2^-52. */
#define UNIT_HELD 0x1.00001p0

/*@ assigns \nothing; */
static real held(real c, real m) { return c > m ? m : c < -m ? -m : c; }

/*@ assigns \nothing; */
static vec3 vec_held(vec3 u, real m) { return vec_make(held(u.x, m), held(u.y, m), held(u.z, m)); }

/* The axis's length is at least 2^-500 ([LANG-EXTENT-1], check_extent.c:
 * the same vec_length of the same difference), so its hold never changes
 * it, nor does the unit axis's: 1/len and a are then bounded however
 * close `from` and `to` are in Eva's boxes. */
/*@ requires vfinite(from) && vfinite(to);
    assigns \nothing;
    ensures \is_finite(\result) && \result >= 0x1p-501; */
static real axis_length(vec3 from, vec3 to)
{
    real len = vec_length(vec_sub(to, from));
    return len < 0x1p-501 ? 0x1p-501 : len;
}

/*@ requires \valid(x);
    requires vfinite(from) && vfinite(to) && vfinite(o) && vfinite(d);
    assigns *x; */
static void axial_of(vec3 from, vec3 to, vec3 o, vec3 d, axial *x)
{
    vec3 w = vec_sub(to, from), f = vec_sub(o, from);
    x->len = axis_length(from, to);
    x->a = vec_scale(w, 1.0 / x->len);
    x->a = vec_held(x->a, UNIT_HELD);
    x->z0 = vec_dot(f, x->a);
    x->dz = vec_dot(d, x->a);
    x->fp = vec_madd(f, x->a, -x->z0);
    x->dp = vec_madd(d, x->a, -x->dz);
}

/* The shape: radius r0 at from, r1 at to. */
typedef struct quadric {
    vec3 from, to;
    real r0, r1;
    real k;          /* (r1 - r0)/len times mu */
    int cone;        /* 0: the cylinder's perpendicular-foot solve */
    real mu;         /* the cone's scale, a power of two (1: the cylinder) */
} quadric;

/* The cone's scale mu: a power of two with |k mu| <= 1/4 and mu <= 1/4,
 * k mu returned.  Then rho0 mu = r0 mu + (k mu) z0 is within 2^502 and
 * the terms of a, b, c (times mu^2) and of the discriminant within
 * 2^1019 (make prove: Eva's cone run).  Every step is by a power of two,
 * so the roots are the unscaled equation's, bit for bit, unless a scaled
 * term falls below 2^-1022 (spec/proofs.md, "Round 8d"). */
/*@ requires \valid(k) && \valid(mu) && \separated(k, mu);
    requires \is_finite(*k) && \is_finite(*mu) && 0 <= *mu <= 1;
    requires 2 <= e <= 0x1p512;
    assigns *k, *mu;
    ensures \is_finite(*k) && \is_finite(*mu) && 0 <= *mu <= 1; */
static void slope_step(real *k, real *mu, real e)
{
    /* two comparisons on k: Eva narrows k by them (not by fabs) */
    if (*k > 0.5 * e || *k < -0.5 * e) {
        *k /= e;
        *mu /= e;
    }
}

/*@ requires \valid(mu) && \is_finite(k);
    assigns *mu;
    ensures \is_finite(\result) && \is_finite(*mu) && 0 <= *mu <= 1; */
static real cone_slope(real k, real *mu)
{
    *mu = 1;
    slope_step(&k, mu, 0x1p512);
    slope_step(&k, mu, 0x1p256);
    slope_step(&k, mu, 0x1p128);
    slope_step(&k, mu, 0x1p64);
    slope_step(&k, mu, 0x1p32);
    slope_step(&k, mu, 0x1p16);
    slope_step(&k, mu, 0x1p8);
    slope_step(&k, mu, 0x1p4);
    slope_step(&k, mu, 0x1p2);
    slope_step(&k, mu, 0x1p1);
    *mu *= 0x1p-2;
    return k * 0x1p-2;
}

/* An unbounded end of an interval: finite (make prove: Eva takes every
 * non-finite double for an alarm), beyond every t a solve returns
 * (isect_quotient's and isect_sphere_roots' are at most CROSSING_MAX), and
 * such that the difference of two ends is finite.  A crossing past
 * CROSSING_MAX (a cone's root) is none, as an infinite one was: o + t d
 * stays finite for |d| <= 4. */
#define SPAN_FAR 0x1p1022
#define CROSSING_MAX 0x1p1021

/* Up to two closed intervals of t; lo may be -SPAN_FAR and hi SPAN_FAR. */
typedef struct tspan {
    int count;
    real lo[2], hi[2];
} tspan;

/* num/den, or +-SPAN_FAR where isect_quotient holds it (past 2^1020: no
 * crossing, an unbounded end, as the infinity or the huge quotient was; a
 * step that long leaves near_shape's box).  A slab's end, a cone's root. */
/*@ requires \is_finite(num) && \is_finite(den) && DOUBLES(\abs(num) <= 0x1p1017);
    assigns \nothing;
    ensures \is_finite(\result) && DOUBLES(-SPAN_FAR <= \result <= SPAN_FAR); */
static real far_quotient(real num, real den)
{
    real q;
    if (!isect_quotient(num, den, &q))
        q = copysign(SPAN_FAR, q);
    return q;
}

/* b^2 - a c with the rounding of both products recovered by fma. */
/*@ assigns \nothing; */
static real discriminant(real a, real b, real c)
{
    real p = b * b, q = a * c;
    return (p - q) + (fma(b, b, -p) - fma(a, c, -q));
}

typedef struct side_eq {
    real a, b, c;
} side_eq;

/*@ requires \valid_read(s) && \valid_read(x);
    assigns \nothing; */
static side_eq cone_equation(const quadric *s, const axial *x)
{
    side_eq e;
    real rho0 = s->r0 * s->mu + s->k * x->z0, sig = s->k * x->dz;
    real lf = vec_length(x->fp), ld = vec_length(x->dp);
    /* Both >= 0 already (vec_length's exact clause), stated for Eva,
     * whose bounds on vec_length hold of magnitudes only. */
    lf = (lf > 0 ? lf : 0) * s->mu;
    ld = (ld > 0 ? ld : 0) * s->mu;
    e.a = (ld - fabs(sig)) * (ld + fabs(sig));
    e.b = vec_dot(x->fp, x->dp) * s->mu * s->mu - rho0 * sig;
    e.c = (lf - fabs(rho0)) * (lf + fabs(rho0));
    return e;
}

/* [NUM-FRAME-4] The cylinder's side across its axis: isect_sphere_roots on
 * dp, scaled by 2^300 while it is below 2^-300 in every coordinate (at
 * most three times: from 2^-1074 to 2^-174; exact, a power of two; held
 * first only for Eva, which keeps no bound between a vector and its
 * coordinates' comparisons).  A line within 2^-300 of the axis's direction
 * (a kept frame squashing the cylinder along its axis: the local
 * direction's part along it 1/s times its part across) has a = |dp|^2
 * below 2^-600, subnormal from 2^-511 on: its bits are lost, and a (R -
 * |l|) under the square root rounds to 0, a "graze" at the foot 2^530
 * away, so the cylinder squashed to 1e-160 .. 5e-162 and seen obliquely
 * had holes (tests/attack13, finding 3; at 1e-170 a was 0 and the line
 * decided as the axis's direction, inside by c, rightly).  Scaled, the
 * roots are the same line's in t 2^-300k: scaled back, and held to the
 * unbounded end SPAN_FAR past 2^1020 (a crossing past CROSSING_MAX is
 * none).  Any other line is solved as before; dp = 0 too (a = 0). */
/*@ requires \valid(dp);
    assigns *dp;
    ensures \result == 0 || \result == 1; */
static int across_step(vec3 *dp)
{
    if (!(fabs(dp->x) < 0x1p-300 && fabs(dp->y) < 0x1p-300 && fabs(dp->z) < 0x1p-300))
        return 0;
    *dp = vec_scale(vec_held(*dp, 0x1p-300), 0x1p300);
    return 1;
}

/* One across_step undone on a root: t 2^300, held to SPAN_FAR past 2^1020
 * (after k steps t 2^300k past 2^1020 at the last: the product grows). */
/*@ requires \is_finite(t);
    assigns \nothing;
    ensures \is_finite(\result); */
static real root_unscaled(real t)
{
    return t > 0x1p720 ? SPAN_FAR : t < -0x1p720 ? -SPAN_FAR : t * 0x1p300;
}

/*@ requires \valid(t + (0 .. 1)) && \valid(a) && \separated(t + (0 .. 1), a);
    requires vfinite(fp) && vfinite(dp) && \is_finite(r) && r > 0;
    assigns t[0 .. 1], *a;
    ensures 0 <= \result <= 2; */
static int cylinder_roots(vec3 fp, vec3 dp, real r, real t[2], real *a)
{
    int k = across_step(&dp);
    k += k ? across_step(&dp) : 0;
    k += k > 1 ? across_step(&dp) : 0;
    *a = vec_length2(dp);
    t[0] = t[1] = 0;
    if (!(*a > 0))
        return 0;
    int n = isect_sphere_roots(fp, dp, r, t);
    /* unrolled for Eva (k <= 3) */
    if (k > 0) {
        t[0] = root_unscaled(t[0]);
        t[1] = root_unscaled(t[1]);
    }
    if (k > 1) {
        t[0] = root_unscaled(t[0]);
        t[1] = root_unscaled(t[1]);
    }
    if (k > 2) {
        t[0] = root_unscaled(t[0]);
        t[1] = root_unscaled(t[1]);
    }
    return n;
}

/* The roots of the side's equation, increasing; their number (0 to 2).
 * *all: the equation holds nowhere or everywhere without roots (a = 0, a
 * cylinder's axis direction): set to 1 when the line is inside throughout. */
/*@ requires \valid_read(s) && \valid_read(x) && \valid(t + (0 .. 1)) && \valid(eq);
    requires \separated(t + (0 .. 1), eq, s, x) && \separated(eq, s, x);
    requires !s->cone ==> s->r0 > 0;   // check_radius: a cylinder's radius > 0
    assigns t[0 .. 1], *eq;
    ensures 0 <= \result <= 2; */
static int side_roots(const quadric *s, const axial *x, real t[2], side_eq *eq)
{
    if (!s->cone) {
        eq->b = 0;
        eq->c = vec_length(x->fp) - s->r0;
        return cylinder_roots(x->fp, x->dp, s->r0, t, &eq->a);
    }
    *eq = cone_equation(s, x);
    if (eq->a == 0) {
        if (eq->b == 0)
            return 0;
        t[0] = far_quotient(-eq->c, 2 * eq->b);
        return 1;
    }
    real disc = discriminant(eq->a, eq->b, eq->c);
    if (disc < 0)
        return 0;
    real q = -(eq->b + copysign(sqrt(disc), eq->b));
    if (q == 0) {
        t[0] = 0;
        return 1;
    }
    real t0 = far_quotient(q, eq->a), t1 = far_quotient(eq->c, q);
    t[0] = t0 < t1 ? t0 : t1;
    t[1] = t0 < t1 ? t1 : t0;
    return 2;
}

/* The t where the line is inside the side: for the cylinder and a cone
 * with a > 0 between the roots; a cone with a < 0 outside them; a = 0
 * on one side of the single root; no roots: nowhere or everywhere by the
 * sign of the equation (c for the cylinder's axis direction). */
/*@ requires \valid_read(s) && \valid_read(x) && \valid(out) && \separated(out, s, x);
    requires !s->cone ==> s->r0 > 0;
    assigns *out;
    ensures 0 <= out->count <= 2; */
static void side_span(const quadric *s, const axial *x, tspan *out)
{
    real t[2] = {0, 0};
    side_eq eq;
    int n = side_roots(s, x, t, &eq);
    out->count = 0;
    if (n == 0) {
        int inside = s->cone ? eq.a < 0 || (eq.a == 0 && eq.b == 0 && eq.c <= 0) : eq.a == 0 && eq.c <= 0;
        if (inside) {
            out->lo[0] = -SPAN_FAR;
            out->hi[0] = SPAN_FAR;
            out->count = 1;
        }
        return;
    }
    if (n == 1 && s->cone && eq.a == 0) {
        out->lo[0] = eq.b > 0 ? -SPAN_FAR : t[0];
        out->hi[0] = eq.b > 0 ? t[0] : SPAN_FAR;
        out->count = 1;
        return;
    }
    if (n == 1)
        t[1] = t[0];
    if (!s->cone || eq.a > 0) {
        out->lo[0] = t[0];
        out->hi[0] = t[1];
        out->count = 1;
        return;
    }
    out->lo[0] = -SPAN_FAR;
    out->hi[0] = t[0];
    out->lo[1] = t[1];
    out->hi[1] = SPAN_FAR;
    out->count = 2;
}

/* The t between the end planes, [*lo, *hi]; 0 when never (parallel and
 * outside).  *lo_end: the end plane crossed at *lo (0: from, 1: to).  A
 * crossing past 2^1020 (isect_quotient holds it: a direction nearly across
 * the axis) is no crossing, an unbounded end, as its infinity was. */
/*@ requires \valid_read(x) && \valid(lo) && \valid(hi) && \valid(lo_end);
    requires \separated(lo, hi, lo_end, x);
    assigns *lo, *hi, *lo_end;
    ensures *lo_end == 0 || *lo_end == 1; */
static int slab(const axial *x, real *lo, real *hi, int *lo_end)
{
    if (x->dz == 0) {
        *lo = -SPAN_FAR;
        *hi = SPAN_FAR;
        *lo_end = 0;
        return x->z0 >= 0 && x->z0 <= x->len;
    }
    real t0 = far_quotient(-x->z0, x->dz), t1 = far_quotient(x->len - x->z0, x->dz);
    *lo_end = x->dz > 0 ? 0 : 1;
    *lo = x->dz > 0 ? t0 : t1;
    *hi = x->dz > 0 ? t1 : t0;
    return 1;
}

/* One crossing before refinement: t and the surface (0, 1: the end caps at
 * from and to, 2: the side). */
typedef struct crossing {
    real t;
    int surface;
} crossing;

enum { SURFACE_SIDE = 2 };

/* The closed solid: the slab's interval met with the side's (by
 * convexity at most one of the side's pieces meets the slab in more than a
 * point; near the apex, where both may touch it, the longer one is kept). */
/*@ requires \valid_read(s) && \valid_read(x) && \valid(c + (0 .. 1)) && \separated(c + (0 .. 1), s, x);
    requires !s->cone ==> s->r0 > 0;
    assigns c[0 .. 1];
    ensures 0 <= \result <= 2; */
static int solid_crossings(const quadric *s, const axial *x, crossing c[2])
{
    real slo, shi;
    int end;
    tspan side = {0, {0, 0}, {0, 0}};
    if (!slab(x, &slo, &shi, &end))
        return 0;
    side_span(s, x, &side);
    int best = -1;
    real best_len = -1;
    /*@ loop invariant 0 <= i <= side.count && -1 <= best < i;
        loop assigns i, best, best_len;
        loop variant side.count - i; */
    for (int i = 0; i < side.count; i++) {
        real lo = side.lo[i] > slo ? side.lo[i] : slo, hi = side.hi[i] < shi ? side.hi[i] : shi;
        if (lo <= hi && hi - lo > best_len) {
            best = i;
            best_len = hi - lo;
        }
    }
    if (best < 0)
        return 0;
    real t0 = side.lo[best] >= slo ? side.lo[best] : slo, t1 = side.hi[best] <= shi ? side.hi[best] : shi;
    /* Two comparisons each, and c written only past them: Eva narrows by
     * them (not by fabs), and a caller's state then holds no other t. */
    if (!(t0 >= -CROSSING_MAX && t0 <= CROSSING_MAX && t1 >= -CROSSING_MAX && t1 <= CROSSING_MAX))
        return 0;
    c[0].surface = side.lo[best] >= slo ? SURFACE_SIDE : end;
    c[0].t = t0;
    c[1].surface = side.hi[best] <= shi ? SURFACE_SIDE : 1 - end;
    c[1].t = t1;
    return t0 == t1 ? 1 : 2;
}

/* The open side: its finite crossings whose height is between the ends. */
/*@ requires \valid_read(s) && \valid_read(x) && \valid(c + (0 .. 1)) && \separated(c + (0 .. 1), s, x);
    requires !s->cone ==> s->r0 > 0;
    assigns c[0 .. 1];
    ensures 0 <= \result <= 2; */
static int open_crossings(const quadric *s, const axial *x, crossing c[2])
{
    tspan side = {0, {0, 0}, {0, 0}};
    real t[4] = {0, 0, 0, 0};
    int n = 0, found = 0;
    side_span(s, x, &side);
    /*@ loop invariant 0 <= i <= side.count && 0 <= n <= 2 * i;
        loop assigns i, n, t[0 .. 3];
        loop variant side.count - i; */
    for (int i = 0; i < side.count; i++) {
        t[n++] = side.lo[i];
        if (side.hi[i] != side.lo[i])
            t[n++] = side.hi[i];
    }
    /* Unrolled for Eva (n <= 4), which otherwise widens i past n. */
    /*@ loop unroll 4;
        loop invariant 0 <= i <= n && 0 <= found <= 2;
        loop assigns i, found, c[0 .. 1];
        loop variant n - i; */
    for (int i = 0; i < n && found < 2; i++) {
        real ti = t[i];
        if (!(ti >= -CROSSING_MAX && ti <= CROSSING_MAX))
            continue;
        /* |t dz| past 2^1019 puts z far beyond both ends (|z0| and len
         * are within 2^505): decided before the product, which could
         * overflow. */
        if ((x->dz < -1 || x->dz > 1) && (ti < -0x1p1019 || ti > 0x1p1019))
            continue;
        real z = x->z0 + ti * x->dz;
        if (z >= 0 && z <= x->len) {
            c[found].t = ti;
            c[found++].surface = SURFACE_SIDE;
        }
    }
    return found;
}

/* Whether *p is within 2^502 of the shape's end `from` in each coordinate:
 * every point of a valid cylinder or cone is ([LANG-EXTENT-1]: |to - from|
 * within 2^501 a coordinate, the radii within 2^500), so a crossing whose
 * point o + t d is not lies off the shape by more than 2^500, which the
 * rounding of o + t d reaches only from an origin past about 2^550 (no
 * origin Eva's boxes hold, make prove).  *p is held to that box: the same
 * point where the result is 1, and a bound Eva sees (it keeps none
 * between o, t and d). */
/*@ assigns \nothing; */
static real box_held(real v, real c) { return v < c - 0x1p502 ? c - 0x1p502 : v > c + 0x1p502 ? c + 0x1p502 : v; }

/*@ requires \valid_read(s) && \valid(p) && \separated(s, p);
    assigns *p; */
static int near_shape(const quadric *s, vec3 *p)
{
    vec3 q = vec_make(box_held(p->x, s->from.x), box_held(p->y, s->from.y), box_held(p->z, s->from.z));
    int in = q.x == p->x && q.y == p->y && q.z == p->z;
    *p = q;
    return in;
}

/* t moved onto the side: the equation solved again from o2 = o + t d
 * (near_shape); its root of least magnitude is the step.  Returns the
 * refined t, *p the point; a step that would leave the shape's box
 * (near_shape: never one onto the side) is not taken. */
/*@ requires \valid_read(s) && \valid_read(r) && \valid(p) && \separated(p, s, r);
    requires !s->cone ==> s->r0 > 0;
    assigns *p; */
static real side_refine(const quadric *s, const ray *r, real t, vec3 o2, vec3 *p)
{
    axial x;
    side_eq eq;
    real roots[2] = {0, 0};
    axial_of(s->from, s->to, o2, r->dir, &x);
    int n = side_roots(s, &x, roots, &eq);
    *p = o2;
    if (n == 0)
        return t;
    real step = n == 2 && fabs(roots[1]) < fabs(roots[0]) ? roots[1] : roots[0];
    if (!(step >= -CROSSING_MAX && step <= CROSSING_MAX))
        return t;   /* a held root: no crossing, and far off the shape's box */
    vec3 moved = vec_madd(o2, r->dir, step);
    if (!near_shape(s, &moved))
        return t;
    *p = moved;
    return t + step;
}

/* The outward normal of the side at p (a cone's apex: along the axis,
 * away from the cone). */
/*@ requires \valid_read(s);
    assigns \nothing; */
static vec3 side_normal(const quadric *s, vec3 a, vec3 p)
{
    vec3 q = vec_sub(p, s->from);
    vec3 across = vec_madd(q, a, -vec_dot(q, a));
    real l = vec_length(across);
    if (!(l > 0))
        return s->k > 0 ? vec_neg(a) : a;
    /* |across_i| <= l, so the holds at 2l and UNIT_HELD never bind; below
     * a length of 2^-500 both are scaled by 2^600 (exact: the same
     * quotients wherever 1/l is finite, and no +Inf for a subnormal l).
     * They bound across (1/l) for Eva. */
    if (l < 0x1p-500) {
        across = vec_scale(vec_held(across, 2 * l), 0x1p600);
        l *= 0x1p600;
    } else {
        across = vec_held(across, 2 * l);
    }
    /* u - k a scaled by the cone's mu (its k is k mu): the same direction */
    return vec_normalize(vec_madd(vec_scale(vec_held(vec_scale(across, 1.0 / l), UNIT_HELD), s->mu), a, -s->k));
}

/*@ requires \valid_read(s) && \valid_read(x) && \valid_read(r) && \valid(h) && \separated(h, s, x, r);
    requires !s->cone ==> s->r0 > 0;
    assigns *h; */
static int crossing_hit(const quadric *s, const axial *x, const ray *r, vec3 o2, real tm, crossing c, hit *h)
{
    vec3 p = vec_madd(o2, r->dir, c.t), n;
    real t = c.t + tm;
    h->t = t;   /* written on every path (Eva: the caller reads it after a 0 too) */
    if (!near_shape(s, &p))
        return 0;
    if (c.surface == SURFACE_SIDE) {
        t = side_refine(s, r, t, p, &p);
        n = side_normal(s, x->a, p);
    } else {
        vec3 plane = c.surface == 0 ? s->from : s->to;
        p = vec_madd(p, x->a, -vec_dot(vec_sub(p, plane), x->a));
        n = c.surface == 0 ? vec_neg(x->a) : x->a;
    }
    isect_hit_set(h, t, p, n, r->dir);
    return 1;
}

/* [NUM-QUADRIC-2] A flat cone's point of the line nearest the middle of its axis, when
 * heights count |k| times as much as lengths across the axis (|k| > 1: the
 * radius changes faster than the height): tm minimises |fp + t dp|^2 +
 * k^2 (z0 + t dz - len/2)^2, both terms times mu^2 (k is k mu here; |k| and
 * mu <= 1/4, so nothing overflows).  The Euclidean nearest point of a line
 * passing h from the middle can be h off it in height, where the double
 * cone's radius rho0 is about |k| h: the equation's b^2 and a c there are of
 * order (k dz rho0)^2 and their difference, the discriminant, of order
 * (k dz fp)^2, lost to rounding once (fp / (k h))^2 falls below eps: from
 * |k| of about 1e8 for a line passing the rim (a cone 1e8 wide and 1 high,
 * tests/attack11, finding 3).  The weighted point is within h_k of the axis
 * and h_k / |k| of the middle's height, h_k the line's weighted distance
 * from the middle, which for a line meeting the shape is at most
 * max(r0, r1) + |k| len / 2 <= 1.5 max(r0, r1): rho0 and every term are then
 * of the shape's size.  0 where the quotient is held (den 0: no direction). */
/*@ requires \valid_read(s) && \valid_read(r) && \valid(tm) && \separated(tm, s, r);
    requires vfinite(s->from) && vfinite(s->to) && vfinite(r->origin) && vfinite(r->dir);
    assigns *tm; */
static int flat_cone_middle(const quadric *s, const ray *r, real *tm)
{
    axial x;
    axial_of(s->from, s->to, r->origin, r->dir, &x);
    real m2 = s->mu * s->mu, k2 = s->k * s->k;
    real num = k2 * ((0.5 * x.len - x.z0) * x.dz) - m2 * vec_dot(x.fp, x.dp);
    real den = k2 * (x.dz * x.dz) + m2 * vec_length2(x.dp);
    *tm = 0;
    return isect_quotient(num, den, tm);
}

/* The cone's side equation is formed about o2 = o + tm d, the line's point
 * nearest the middle of the axis (a flat cone's: flat_cone_middle); returns
 * tm, *o2 that point (tm = 0 and o2 = o for the cylinder, or where the point
 * is not near_shape's).
 *
 * Why: formed about a far origin, c = |fp|^2 - rho0^2 subtracts two
 * squares of the distance, and |fp| = sqrt(D^2 + h^2) (D the distance along
 * the ray, h the offset across it) has lost h once h^2/2D is below half an
 * ulp of D: at D = 1e7 for |h| < 0.136, at D = 1e8 for |h| < 1.22, the
 * whole of a unit cone.  The discriminant b^2 - a c then no longer depends
 * on where the ray passes the axis (tests/attack10, cone_ortho_far: 66 of
 * 192 pixels wrong at 1e8, a ray missing by 0.01 hit at 1e7;
 * cone_false_shadow: rays 0.35 off the side blocked).  The cylinder's
 * perpendicular foot (isect_sphere_roots) forms that offset directly; the
 * cone's radius changes along the ray, so it has no such foot, and the
 * origin is moved instead: about o2 every term is of
 * the shape's size, and the roots are the same line's, shifted by tm.
 * The point o2 carries the rounding of o + tm d, eps |o| (the sphere's
 * foot carries the same).  near_shape's hold keeps o2 - from within
 * 2^502 a coordinate for Eva (make prove), which sees no relation
 * between o2 and the shape; a line whose nearest point is outside that
 * box (2^502 off `from`) misses the shape (within 1.4 2^501 of the
 * middle) by more than 2^497, and is solved from o as before. */
/*@ requires \valid_read(s) && \valid_read(r) && \valid(o2) && \separated(o2, s, r);
    requires vfinite(s->from) && vfinite(s->to) && vfinite(r->origin) && vfinite(r->dir);
    assigns *o2; */
static real cone_origin(const quadric *s, const ray *r, vec3 *o2)
{
    real tm;
    *o2 = r->origin;
    if (!s->cone)
        return 0;
    if (s->k > s->mu || s->k < -s->mu) {
        if (!flat_cone_middle(s, r, &tm))
            return 0;
    } else {
        vec3 mid = vec_madd(s->from, vec_sub(s->to, s->from), 0.5);
        if (!isect_quotient(vec_dot(vec_sub(mid, r->origin), r->dir), vec_length2(r->dir), &tm))
            return 0;
    }
    /* a line of a tiny direction: kept from o, so that a crossing's t plus tm
     * stays within 2^1021 + 2^1019 and o + t d finite (|d| <= 4) */
    if (!(tm >= -0x1p1019 && tm <= 0x1p1019))
        return 0;
    vec3 p = ray_at(r, tm);
    if (!near_shape(s, &p))
        return 0;
    *o2 = p;
    return tm;
}

/*@ requires \valid_read(s) && \valid_read(r) && max >= 0 && \valid(out + (0 .. max - 1));
    requires \separated(out + (0 .. max - 1), s, r);
    requires !s->cone ==> s->r0 > 0;   // check_radius
    requires vfinite(s->from) && vfinite(s->to) && vfinite(r->origin) && vfinite(r->dir);
    assigns out[0 .. max - 1];
    ensures 0 <= \result <= max;
    // doubles too (comparisons of the returned t): tmin >= 0 and t < tmax <= +Inf, so t is finite;
    // EXACT: WP's (relations between two doubles, which Eva's intervals do not keep)
    ensures EXACT(\forall integer i; 0 <= i < \result ==> \old(r->tmin) < out[i].t < \old(r->tmax));
    ensures EXACT(\result == 2 ==> out[0].t <= out[1].t); */
static int quadric_hits(const quadric *s, int open, const ray *r, hit *out, int max)
{
    axial x;
    crossing c[2] = {{0, 0}, {0, 0}};
    hit h[2];
    vec3 o2;
    real tm = cone_origin(s, r, &o2);
    axial_of(s->from, s->to, o2, r->dir, &x);
    int n = open ? open_crossings(s, &x, c) : solid_crossings(s, &x, c), kept = 0;
    /*@ loop invariant 0 <= i <= n && 0 <= kept <= i;
        loop invariant EXACT(\forall integer j; 0 <= j < kept ==> r->tmin < h[j].t < r->tmax);
        loop assigns i, kept, h[0 .. 1];
        loop variant n - i; */
    for (int i = 0; i < n; i++) {
        kept += crossing_hit(s, &x, r, o2, tm, c[i], &h[kept]) && h[kept].t > r->tmin && h[kept].t < r->tmax;
    }
    if (kept == 2 && h[1].t < h[0].t) {
        hit swap = h[0];
        h[0] = h[1];
        h[1] = swap;
    }
    /*@ loop invariant 0 <= i <= kept && i <= max;
        loop invariant EXACT(\forall integer j; 0 <= j < i ==> out[j].t == h[j].t);
        loop assigns i, out[0 .. max - 1];
        loop variant kept - i; */
    for (int i = 0; i < kept && i < max; i++)
        out[i] = h[i];
    return kept < max ? kept : max;
}

int isect_cylinder_hits(vec3 from, vec3 to, real radius, int open, const ray *r, hit *out, int max)
{
    quadric s = {from, to, radius, radius, 0, 0, 1};
    return quadric_hits(&s, open, r, out, max);
}

int isect_cone_hits(vec3 from, vec3 to, real r0, real r1, int open, const ray *r, hit *out, int max)
{
    quadric s = {from, to, r0, r1, 0, 1, 1};
    s.k = cone_slope((r1 - r0) / axis_length(from, to), &s.mu);
    return quadric_hits(&s, open, r, out, max);
}
