/*
 * oracle_quadric.c - see oracle_quadric.h; the derivations are in
 * spec/analytic.md (sections `lambert_cylinder`, `lambert_cone`,
 * `lambert_torus`).
 */
#include <float.h>
#include <math.h>
#include "oracle/oracle_quadric.h"
#include "oracle/oracle_geom.h"

#define TWO_PI 6.283185307179586

static double sq(double x) { return x * x; }

/* Scaled first (oracle_tame): a tiny shape's p - V squares to 0. */
static vec3 unit(vec3 v)
{
    v = oracle_tame(v);
    return vec_scale(v, 1 / sqrt(vec_dot(v, v)));
}

/* The point of the line o + s d nearest c, in *near, and its parameter s:
 * the frustum's and the ring's tests start there, since their margins are
 * relative to terms that grow with the distance of the line's start
 * ([ORACLE-LAMBERT-CONE-2], [ORACLE-LAMBERT-TORUS-3]). */
static double restart_near(vec3 o, vec3 d, vec3 c, vec3 *near)
{
    double s = vec_dot(vec_sub(c, o), d) / vec_dot(d, d);
    *near = vec_add(o, vec_scale(d, s));
    return s;
}

/* ---- frustum ------------------------------------------------------------ */

oracle_frustum oracle_frustum_of(const scene_prim *p)
{
    oracle_frustum f;
    int cone = p->kind == PRIM_CONE;
    vec3 to = cone ? p->u.cone.to : p->u.cylinder.to;
    f.from = cone ? p->u.cone.from : p->u.cylinder.from;
    f.len = vec_length_fast(vec_sub(to, f.from));
    f.a = vec_scale(vec_sub(to, f.from), 1 / f.len);
    f.r0 = cone ? p->u.cone.radius[0] : p->u.cylinder.radius;
    f.r1 = cone ? p->u.cone.radius[1] : p->u.cylinder.radius;
    return f;
}

void oracle_frustum_ball(const oracle_frustum *f, vec3 *centre, double *radius)
{
    *centre = vec_add(f->from, vec_scale(f->a, f->len / 2));
    *radius = sqrt(sq(f->len / 2) + sq(fmax(f->r0, f->r1)));
}

/* The parameters where the line is inside the side, as up to two
 * intervals (lo may be -inf, hi +inf); *graze when it is within the margin
 * of touching the side. */
typedef struct side_set {
    int count;
    double lo[2], hi[2];
    int graze;
} side_set;

/* Cylinder: in the plane across the axis the line is w' + s d' (w = o -
 * from, primes the parts across a); with e = d'/|d'| its point nearest the
 * axis is w' + along e, along = -w'.e, at distance off, and it is inside
 * for |s |d'| - along| <= half = sqrt(r^2 - off^2). */
static void cylinder_side(const oracle_frustum *f, vec3 o, vec3 d, side_set *out)
{
    vec3 w = vec_sub(o, f->from);
    vec3 wp = vec_sub(w, vec_scale(f->a, vec_dot(w, f->a))), dp = vec_sub(d, vec_scale(f->a, vec_dot(d, f->a)));
    double r = f->r0, ld = sqrt(vec_dot(dp, dp)), off;
    out->count = 0;
    if (ld == 0) {
        off = sqrt(vec_dot(wp, wp));
        out->graze = fabs(off - r) <= ORACLE_EDGE_MARGIN * r;
        out->lo[0] = -INFINITY;
        out->hi[0] = INFINITY;
        out->count = off < r;
        return;
    }
    vec3 e = vec_scale(dp, 1 / ld);
    double along = -vec_dot(wp, e);
    off = sqrt(vec_dot(vec_add(wp, vec_scale(e, along)), vec_add(wp, vec_scale(e, along))));
    out->graze = fabs(off - r) <= ORACLE_EDGE_MARGIN * r;
    if (off >= r)
        return;
    double half = sqrt((r - off) * (r + off));
    out->lo[0] = (along - half) / ld;
    out->hi[0] = (along + half) / ld;
    out->count = 1;
}

/* The cone's radius grows by k along the axis: r0 + k z at height z. */
static double cone_slope(const oracle_frustum *f)
{
    return (f->r1 - f->r0) / f->len;
}

/* Cone, in the radius form about the frustum's start rather than about its
 * apex ([ORACLE-LAMBERT-CONE-3]): a nearly cylindrical cone has its apex far
 * away, and the apex form's C = (q.w)^2 - c2 |q|^2 subtracted two terms of
 * order |o - V|^2 to get one of order r^2 (tests/attack11, finding 1: radii
 * 1 and 0.9999999, the apex 2e7 away).  With w = o - from, z0 = w.a, dz =
 * d.a and w', d' their parts across the axis, the line is inside the double
 * cone where the radius covers the distance from the axis:
 *   Q(s) = (rho + k dz s)^2 - |w' + s d'|^2 >= 0,  rho = r0 + k z0,
 *   A = k^2 dz^2 - |d'|^2,  B = k dz rho - w'.d',  C = (rho - |w'|)(rho + |w'|).
 * The roots by q' = -(B + sign(B) sqrt(B^2 - AC)): q'/A and C/q'. */
static void cone_side(const oracle_frustum *f, vec3 o, vec3 d, side_set *out)
{
    double k = cone_slope(f);
    vec3 w = vec_sub(o, f->from);
    double z0 = vec_dot(w, f->a), dz = vec_dot(d, f->a);
    vec3 wp = vec_sub(w, vec_scale(f->a, z0)), dp = vec_sub(d, vec_scale(f->a, dz));
    double rho = f->r0 + k * z0, lw = sqrt(vec_dot(wp, wp));
    double A = k * k * dz * dz - vec_dot(dp, dp), B = k * dz * rho - vec_dot(wp, dp), C = (rho - lw) * (rho + lw);
    double disc = B * B - A * C;
    out->count = 0;
    out->graze = fabs(disc) <= ORACLE_EDGE_MARGIN * (B * B + fabs(A * C));
    if (disc < 0) {
        if (A > 0) {
            out->lo[0] = -INFINITY;
            out->hi[0] = INFINITY;
            out->count = 1;
        }
        return;
    }
    double qq = -(B + copysign(sqrt(disc), B)), t0 = qq / A, t1 = C / qq;
    double lo = fmin(t0, t1), hi = fmax(t0, t1);
    if (A < 0) {
        out->lo[0] = lo;
        out->hi[0] = hi;
        out->count = 1;
        return;
    }
    out->lo[0] = -INFINITY;
    out->hi[0] = lo;
    out->lo[1] = hi;
    out->hi[1] = INFINITY;
    out->count = 2;
}

/* The outward normal of the cone at p: the gradient of |p'| - (r0 + k z),
 * negative inside (p' the part of p - from across the axis). */
static vec3 cone_normal(const oracle_frustum *f, vec3 p)
{
    vec3 w = vec_sub(p, f->from);
    vec3 across = vec_sub(w, vec_scale(f->a, vec_dot(w, f->a)));
    return unit(vec_sub(unit(across), vec_scale(f->a, cone_slope(f))));
}

/* Whether p on the side lies within the margin of the apex: its distance
 * from the apex along the side is rho sqrt(1 + k^2) / |k|, rho the radius
 * at p (no division: k may be tiny). */
static int near_apex(const oracle_frustum *f, vec3 p)
{
    double k = cone_slope(f), rho = f->r0 + k * vec_dot(vec_sub(p, f->from), f->a);
    return rho * sqrt(1 + k * k) <= ORACLE_EDGE_MARGIN * fmax(f->r0, f->r1) * fabs(k);
}

/* The line is first restarted at its point nearest the frustum's centre:
 * the graze tests are relative to the quadric's coefficients, which grow
 * with |o|, so from a far origin (an orthographic eye 1e3 sizes away) every
 * line tested as grazing (attack 10, finding 6); s is shifted back. */
oracle_chord_kind oracle_line_frustum(const oracle_frustum *f, vec3 o_far, vec3 d, double *s, vec3 *n)
{
    vec3 centre = vec_add(f->from, vec_scale(f->a, 0.5 * f->len));
    vec3 o;
    double restart = restart_near(o_far, d, centre, &o);
    double scale = fmax(f->len, fmax(f->r0, f->r1)), margin = ORACLE_EDGE_MARGIN * scale;
    int cylinder = f->r0 == f->r1;
    side_set side;
    if (cylinder)
        cylinder_side(f, o, d, &side);
    else
        cone_side(f, o, d, &side);
    /* the slab between the end planes z = 0 and z = len */
    double z0 = vec_dot(vec_sub(o, f->from), f->a), dz = vec_dot(d, f->a), slo, shi;
    int end;
    if (dz == 0) {
        if (fabs(z0) <= margin || fabs(z0 - f->len) <= margin)
            return ORACLE_CHORD_GRAZE;
        if (z0 < 0 || z0 > f->len)
            return side.graze ? ORACLE_CHORD_GRAZE : ORACLE_CHORD_MISS;
        slo = -INFINITY;
        shi = INFINITY;
        end = 0;
    } else {
        double a = -z0 / dz, b = (f->len - z0) / dz;
        slo = fmin(a, b);
        shi = fmax(a, b);
        end = dz > 0 ? 0 : 1;
    }
    int best = -1;
    double lo = 0, hi = 0;
    for (int i = 0; i < side.count; i++) {
        double l = fmax(side.lo[i], slo), h = fmin(side.hi[i], shi);
        if (l <= h && (best < 0 || h - l > hi - lo)) {
            best = i;
            lo = l;
            hi = h;
        }
    }
    if (side.graze)
        return ORACLE_CHORD_GRAZE;
    if (best < 0)
        return ORACLE_CHORD_MISS;
    /* the rim (side and cap entered together), a corner grazed (entry and
     * exit together) */
    if (fabs(side.lo[best] - slo) <= margin || hi - lo <= margin)
        return ORACLE_CHORD_GRAZE;
    *s = lo + restart;
    vec3 p = vec_add(o, vec_scale(d, lo));
    if (side.lo[best] < slo) {
        *n = end == 0 ? vec_neg(f->a) : f->a;
        return ORACLE_CHORD_HIT;
    }
    if (cylinder) {
        vec3 w = vec_sub(p, f->from);
        *n = unit(vec_sub(w, vec_scale(f->a, vec_dot(w, f->a))));
        return ORACLE_CHORD_HIT;
    }
    if (near_apex(f, p))
        return ORACLE_CHORD_GRAZE;
    *n = cone_normal(f, p);
    return ORACLE_CHORD_HIT;
}

/* ---- ring torus ---------------------------------------------------------- */

oracle_ring oracle_ring_of(const scene_prim *p)
{
    oracle_ring t;
    t.c = p->u.torus.center;
    t.a = unit(p->u.torus.axis);
    vec3 least = fabs(t.a.x) <= fabs(t.a.y) && fabs(t.a.x) <= fabs(t.a.z) ? vec_make(1, 0, 0)
                 : fabs(t.a.y) <= fabs(t.a.z)                          ? vec_make(0, 1, 0)
                                                                        : vec_make(0, 0, 1);
    t.u = unit(vec_cross(t.a, least));
    t.v = vec_cross(t.a, t.u);
    t.major = p->u.torus.major;
    t.minor = p->u.torus.minor;
    return t;
}

static vec3 ring_point(const oracle_ring *t, double theta)
{
    return vec_add(t->c, vec_add(vec_scale(t->u, t->major * cos(theta)), vec_scale(t->v, t->major * sin(theta))));
}

/* Along the line o + s d: where the core circle's point at theta projects
 * (along) and its squared distance from the line (dist2). */
typedef struct ring_line {
    const oracle_ring *t;
    vec3 o, d;
} ring_line;

static void ring_line_at(const ring_line *rl, double theta, double *along, double *dist2)
{
    vec3 w = vec_sub(ring_point(rl->t, theta), rl->o);
    *along = vec_dot(w, rl->d);
    /* |w|^2 - along^2 cancels to a rounding error of |w|^2 where the line
     * passes through the core circle: below 0 there (-1e-15 for the line
     * through the far tube's core from the inner wall), and its NaN root
     * made oracle_ring_blocks call such a line clear.  0 is within that
     * error of the true value. */
    *dist2 = fmax(vec_dot(w, w) - *along * *along, 0);
}

static double ring_dist2(const ring_line *rl, double theta)
{
    double along, d2;
    ring_line_at(rl, theta, &along, &d2);
    return d2;
}

/* Golden-section search for a minimum of f in [a, b], to 1e-10 of the
 * angle: an error d in the angle moves a minimum's value by about
 * f'' d^2 / 2, far below rounding. */
static double golden_min(double (*f)(const void *, double), const void *ctx, double a, double b)
{
    const double g = 0.6180339887498949;
    double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = f(ctx, x1), f2 = f(ctx, x2);
    while (b - a > 1e-10) {
        if (f1 <= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(ctx, x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(ctx, x2);
        }
    }
    return f1 <= f2 ? x1 : x2;
}

static double dist2_of(const void *ctx, double theta)
{
    return ring_dist2(ctx, theta);
}

/*
 * dist2 (the squared distance of the circle's point from the line) at
 * RING_SAMPLES angles h apart, and its local minima that matter: one per
 * stretch of samples below the threshold (1 + 2 margin)^2 minor^2, found by
 * golden section about the least sample of the stretch (its neighbours are
 * larger, so it brackets a minimum), and any minimum hidden between two
 * samples above the threshold.  Such a dip is at most M2 h^2 / 8 below the
 * lower of its two samples, where M2 = 2R|w| + 2R|w.d| + 4R^2 (w = c - o)
 * bounds |dist2''|, so only intervals within that of the threshold are
 * searched, and none is lost however narrow.
 */
enum { RING_SAMPLES = 1024, RING_MINIMA = 8 };

typedef struct ring_scan {
    double h, f[RING_SAMPLES + 1];
    double theta[RING_MINIMA];
    int count;
} ring_scan;

static void ring_samples(const ring_line *rl, ring_scan *sc)
{
    const oracle_ring *t = rl->t;
    vec3 w = vec_sub(t->c, rl->o);
    double wu = vec_dot(w, t->u), wv = vec_dot(w, t->v), du = vec_dot(rl->d, t->u), dv = vec_dot(rl->d, t->v);
    double ww = vec_dot(w, w), wd = vec_dot(w, rl->d), c = 1, sn = 0;
    double ch = cos(sc->h), shh = sin(sc->h);
    /* The samples only bracket: the angle is stepped by rotation (an
     * error of about k ulps), the refinement evaluates exactly. */
    for (int k = 0; k <= RING_SAMPLES; k++) {
        double along = wd + t->major * (c * du + sn * dv);
        sc->f[k] = ww + 2 * t->major * (c * wu + sn * wv) + sq(t->major) - along * along;
        double next = c * ch - sn * shh;
        sn = sn * ch + c * shh;
        c = next;
    }
}

static void ring_minima(const ring_line *rl, ring_scan *sc)
{
    const oracle_ring *t = rl->t;
    vec3 w = vec_sub(t->c, rl->o);
    double h = sc->h = TWO_PI / RING_SAMPLES, *f = sc->f;
    double m2 = 2 * t->major * sqrt(vec_dot(w, w)) + 2 * t->major * fabs(vec_dot(w, rl->d)) + 4 * sq(t->major);
    double limit = sq(t->minor * (1 + 2 * ORACLE_EDGE_MARGIN)), dip = m2 * h * h / 8;
    ring_samples(rl, sc);
    sc->count = 0;
    for (int k = 0; k < RING_SAMPLES && sc->count < RING_MINIMA; k++) {
        double before = f[k == 0 ? RING_SAMPLES - 1 : k - 1], after = f[k + 1];
        if (f[k] <= limit && f[k] <= before && f[k] <= after) {
            sc->theta[sc->count++] = golden_min(dist2_of, rl, (k - 1) * h, (k + 1) * h);
        } else if (fmin(f[k], after) > limit && fmin(f[k], after) - dip <= limit) {
            double m = golden_min(dist2_of, rl, k * h, (k + 1) * h);
            if (m > k * h + 1e-9 && m < (k + 1) * h - 1e-9)
                sc->theta[sc->count++] = m;
        }
    }
}

/* The entry parameter into the ball at theta; +inf where the line misses it. */
static double entry_of(const void *ctx, double theta)
{
    double along, d2;
    const ring_line *rl = ctx;
    ring_line_at(rl, theta, &along, &d2);
    double r2 = sq(rl->t->minor);
    return d2 < r2 ? along - sqrt(r2 - d2) : INFINITY;
}

/* One end of the stretch of {dist2 < minor^2} around the minimum m, toward
 * dir: the samples bracket it, bisection finds it. */
static double stretch_end(const ring_line *rl, const ring_scan *sc, double m, int dir)
{
    double r2 = sq(rl->t->minor), in = m, out = m;
    for (int i = 1; i <= RING_SAMPLES; i++) {
        out = (floor(m / sc->h) + (dir > 0 ? i : 1 - i)) * sc->h;
        int k = ((int)floor(out / sc->h + 0.5) % RING_SAMPLES + RING_SAMPLES) % RING_SAMPLES;
        if (sc->f[k] >= r2 && ring_dist2(rl, out) >= r2)
            break;
        in = out;
    }
    while (fabs(out - in) > 1e-12) {
        double mid = (in + out) / 2;
        if (ring_dist2(rl, mid) < r2)
            in = mid;
        else
            out = mid;
    }
    return in;
}

/* The least entry over the stretch around the minimum m: the entry is
 * sampled across it and refined by golden section. */
static double least_entry(const ring_line *rl, const ring_scan *sc, double m)
{
    double lo = stretch_end(rl, sc, m, -1), hi = stretch_end(rl, sc, m, 1);
    double best = m, best_s = entry_of(rl, m);
    for (int i = 0; i <= 32; i++) {
        double th = lo + (hi - lo) * i / 32, s = entry_of(rl, th);
        if (s < best_s) {
            best_s = s;
            best = th;
        }
    }
    double span = (hi - lo) / 32;
    double th = golden_min(entry_of, rl, fmax(lo, best - span), fmin(hi, best + span));
    return fmin(entry_of(rl, th), best_s);
}

/* The outward normal at p: from the nearest point of the core circle. */
static vec3 ring_normal(const oracle_ring *t, vec3 p)
{
    vec3 q = vec_sub(p, t->c);
    vec3 across = vec_sub(q, vec_scale(t->a, vec_dot(q, t->a)));
    vec3 core = vec_add(t->c, vec_scale(unit(across), t->major));
    return unit(vec_sub(p, core));
}

/* [ORACLE-LAMBERT-TORUS-3] As for the frustum, the line is restarted at its
 * point nearest the ring's centre: the scan's dip margin grows with |c - o|,
 * so from an orthographic eye 50 times the usual distance it took misses
 * for hits (tests/attack11, finding 2); s is shifted back. */
oracle_chord_kind oracle_line_ring(const oracle_ring *t, vec3 o_far, vec3 d, double *s, vec3 *n)
{
    vec3 o;
    double restart = restart_near(o_far, d, t->c, &o);
    ring_line rl = {t, o, d};
    ring_scan sc;
    /* The outline's margin widens by the view's rounding: a render's ray
     * from an origin of size |o_far| lies a few u |o_far| aside, and its hit
     * test rounds at that size too; the floor of [ORACLE-VIEW-ROUNDING-1]
     * admits K u of it (from an eye 1e11 away the render lost samples 8 to
     * 128 u |o_far| inside the outline: tests/attack15/torus_far.sh). */
    double r = t->minor, best = INFINITY, graze_along = INFINITY,
           margin = ORACLE_EDGE_MARGIN * r + ORACLE_VIEW_ROUNDING_K * DBL_EPSILON / 2 * vec_length(o_far);
    int graze = 0;
    ring_minima(&rl, &sc);
    for (int i = 0; i < sc.count; i++) {
        double along, d2;
        ring_line_at(&rl, sc.theta[i], &along, &d2);
        if (fabs(sqrt(d2) - r) <= margin) {
            graze = 1;
            graze_along = fmin(graze_along, along);
        } else if (d2 < r * r) {
            best = fmin(best, least_entry(&rl, &sc, sc.theta[i]));
        }
    }
    /* a touch in front of the hit (or with nothing hit) could be seen */
    if (graze && graze_along <= best + 2 * r)
        return ORACLE_CHORD_GRAZE;
    if (!isfinite(best))
        return ORACLE_CHORD_MISS;
    *s = best + restart;
    *n = ring_normal(t, vec_add(o, vec_scale(d, best)));
    return ORACLE_CHORD_HIT;
}

int oracle_ring_blocks(const oracle_ring *t, vec3 p, vec3 l)
{
    ring_line rl = {t, p, l};
    ring_scan sc;
    double r = t->minor;
    int ambiguous = 0;
    ring_minima(&rl, &sc);
    for (int i = 0; i < sc.count; i++) {
        double along, d2;
        ring_line_at(&rl, sc.theta[i], &along, &d2);
        /* The balls around p's own part of the tube meet the line behind p
         * (along < 0): p is on the surface, inside none of them. */
        if (along <= 0)
            continue;
        if (sqrt(d2) < r * (1 - ORACLE_EDGE_MARGIN))
            return 1;
        if (sqrt(d2) <= r * (1 + ORACLE_EDGE_MARGIN))
            ambiguous = 1;
    }
    return ambiguous ? -1 : 0;
}
