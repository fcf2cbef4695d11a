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

/* Lemma functions of isect_sphere_roots' roots on the sphere (ghost code,
 * make prove only: see the block in base/vec.h).  The derivation of the
 * comment above, one nonlinear step a lemma: with F = |f|^2, the foot
 * l = f + s d (s = -b/a) has a |l|^2 = a F - b^2; root^2 = a (R - |l|)
 * (R + |l|) = a R^2 - a |l|^2; c = F - R^2; (q + b)^2 = root^2; hence
 * q^2 + 2 b q + a c = 0, and |f + t d|^2 - R^2 = c + 2 t b + t^2 a is 0 at
 * t = q/a and at t = c/q. */
/*@ ghost
  /@ requires EXACT(a == vnorm2(d) && b == vdot(f, d));
     assigns \nothing;
     ensures EXACT(vdist2(f, d, t) == vnorm2(f) + 2 * t * b + t * t * a); @/
  static void lemma_dist_expand(vec3 f, vec3 d, real t, real a, real b) { }

  /@ requires EXACT(u == x + y * s);
     assigns \nothing;
     ensures EXACT((x + s * y) * (x + s * y) == u * u); @/
  static void lemma_square_line(real u, real x, real y, real s) { }

  /@ requires EXACT(l.x == f.x + d.x * s && l.y == f.y + d.y * s && l.z == f.z + d.z * s);
     assigns \nothing;
     ensures EXACT(vdist2(f, d, s) == vnorm2(l)); @/
  static void lemma_dist_line(vec3 f, vec3 d, vec3 l, real s)
  {
      lemma_square_line(l.x, f.x, d.x, s);
      lemma_square_line(l.y, f.y, d.y, s);
      lemma_square_line(l.z, f.z, d.z, s);
  }

  /@ requires EXACT(a > 0 && s == -b / a);
     assigns \nothing;
     ensures EXACT(a * (vnorm2(f) + 2 * s * b + s * s * a) == a * vnorm2(f) - b * b); @/
  static void lemma_foot_scalar(vec3 f, real a, real b, real s) { }

  /@ requires EXACT(a > 0 && a == vnorm2(d) && b == vdot(f, d) && s == -b / a);
     requires EXACT(l.x == f.x + d.x * s && l.y == f.y + d.y * s && l.z == f.z + d.z * s);
     assigns \nothing;
     ensures EXACT(a * vnorm2(l) == a * vnorm2(f) - b * b); @/
  static void lemma_foot_norm(vec3 f, vec3 d, vec3 l, real s, real a, real b)
  {
      lemma_dist_line(f, d, l, s);
      lemma_dist_expand(f, d, s, a, b);
      lemma_foot_scalar(f, a, b, s);
  }

  /@ requires EXACT(sa * sa == x && sb * sb == y && root == sa * sb);
     assigns \nothing;
     ensures EXACT(root * root == x * y); @/
  static void lemma_product_square(real root, real sa, real sb, real x, real y) { }

  /@ requires EXACT(\abs(x) == \abs(y));
     assigns \nothing;
     ensures EXACT(x * x == y * y); @/
  static void lemma_abs_square(real x, real y) { }

  /@ requires EXACT(lf * lf == vnorm2(f) && c == (lf - r) * (lf + r));
     assigns \nothing;
     ensures EXACT(c == vnorm2(f) - r * r); @/
  static void lemma_c_norm(vec3 f, real lf, real r, real c) { }

  /@ requires EXACT(a * vnorm2(l) == a * vnorm2(f) - b * b && ll * ll == vnorm2(l) && lf * lf == vnorm2(f));
     assigns \nothing;
     ensures EXACT(a * (ll * ll) == a * (lf * lf) - b * b); @/
  static void lemma_norms_scalar(vec3 f, vec3 l, real a, real b, real ll, real lf) { }

  /@ requires EXACT(a * (ll * ll) == a * (lf * lf) - b * b && ag == a * (r - ll) && rl == r + ll);
     requires EXACT(root * root == ag * rl && c == (lf - r) * (lf + r) && cs * cs == root * root && q == -(b + cs));
     assigns \nothing;
     ensures EXACT(q * q + 2 * b * q + a * c == 0); @/
  static void lemma_quadratic_scalar(real a, real b, real r, real ll, real lf, real ag, real rl, real root,
                                     real c, real cs, real q) { }

  /@ requires EXACT(den != 0 && t == num / den);
     assigns \nothing;
     ensures EXACT(t * den == num); @/
  static void lemma_quotient_times(real num, real den, real t) { }

  /@ requires EXACT(a > 0 && t == q / a && q * q + 2 * b * q + a * c == 0);
     assigns \nothing;
     ensures EXACT(c + 2 * t * b + t * t * a == 0); @/
  static void lemma_root_qa(real a, real b, real c, real q, real t)
  {
      lemma_quotient_times(q, a, t);
  }

  /@ requires EXACT(t * q == c);
     assigns \nothing;
     ensures EXACT(q * q * (c + 2 * t * b + t * t * a) == c * (q * q + 2 * b * q + a * c)); @/
  static void lemma_root_cq_ring(real a, real b, real c, real q, real t) { }

  /@ requires EXACT(q != 0 && q * q * (c + 2 * t * b + t * t * a) == c * (q * q + 2 * b * q + a * c));
     requires EXACT(q * q + 2 * b * q + a * c == 0);
     assigns \nothing;
     ensures EXACT(c + 2 * t * b + t * t * a == 0); @/
  static void lemma_root_cq_cancel(real a, real b, real c, real q, real t) { }

  /@ requires EXACT(q != 0 && t == c / q && q * q + 2 * b * q + a * c == 0);
     assigns \nothing;
     ensures EXACT(c + 2 * t * b + t * t * a == 0); @/
  static void lemma_root_cq(real a, real b, real c, real q, real t)
  {
      lemma_quotient_times(c, q, t);
      lemma_root_cq_ring(a, b, c, q, t);
      lemma_root_cq_cancel(a, b, c, q, t);
  }

  /@ requires EXACT(a == vnorm2(d) && b == vdot(f, d) && c == vnorm2(f) - r * r && c + 2 * t * b + t * t * a == 0);
     assigns \nothing;
     ensures EXACT(vdist2(f, d, t) == r * r); @/
  static void lemma_on_sphere(vec3 f, vec3 d, real r, real a, real b, real c, real t)
  {
      lemma_dist_expand(f, d, t, a, b);
  }

  // held_root's two cases: a root below 2^1020 in magnitude is the quotient
  /@ requires EXACT(a > 0 && a == vnorm2(d) && b == vdot(f, d) && c == vnorm2(f) - r * r);
     requires EXACT(q * q + 2 * b * q + a * c == 0);
     requires EXACT(\abs(q) < \abs(a) * 0x1p1020 ==> t == q / a);
     requires EXACT(\abs(q) >= \abs(a) * 0x1p1020 ==> \abs(t) >= 0x1p1020);
     assigns \nothing;
     ensures EXACT(\abs(t) < 0x1p1020 ==> vdist2(f, d, t) == r * r); @/
  static void lemma_held_qa(vec3 f, vec3 d, real r, real a, real b, real c, real q, real t)
  {
      if (t < 0x1p1020 && t > -0x1p1020) {
          lemma_root_qa(a, b, c, q, t);
          lemma_on_sphere(f, d, r, a, b, c, t);
      }
  }

  /@ requires EXACT(a == vnorm2(d) && b == vdot(f, d) && c == vnorm2(f) - r * r);
     requires EXACT(q * q + 2 * b * q + a * c == 0);
     requires EXACT(\abs(c) < \abs(q) * 0x1p1020 ==> t == c / q);
     requires EXACT(\abs(c) >= \abs(q) * 0x1p1020 ==> \abs(t) >= 0x1p1020);
     assigns \nothing;
     ensures EXACT(\abs(t) < 0x1p1020 ==> vdist2(f, d, t) == r * r); @/
  static void lemma_held_cq(vec3 f, vec3 d, real r, real a, real b, real c, real q, real t)
  {
      if (t < 0x1p1020 && t > -0x1p1020) {
          lemma_root_cq(a, b, c, q, t);
          lemma_on_sphere(f, d, r, a, b, c, t);
      }
  }

  // the two roots (root > 0)
  /@ requires EXACT(a > 0 && a == vnorm2(d) && b == vdot(f, d) && s == -b / a);
     requires EXACT(l.x == f.x + d.x * s && l.y == f.y + d.y * s && l.z == f.z + d.z * s);
     requires EXACT(ll * ll == vnorm2(l) && gap == r - ll && ag == a * gap && rl == r + ll);
     requires EXACT(ag >= 0 && rl >= 0 && sa == \sqrt(ag) && sb == \sqrt(rl) && root == sa * sb);
     requires EXACT(lf * lf == vnorm2(f) && c == (lf - r) * (lf + r) && \abs(cs) == \abs(root) && q == -(b + cs));
     requires EXACT(\abs(c) < \abs(q) * 0x1p1020 ==> t0 == c / q);
     requires EXACT(\abs(c) >= \abs(q) * 0x1p1020 ==> \abs(t0) >= 0x1p1020);
     requires EXACT(\abs(q) < \abs(a) * 0x1p1020 ==> t1 == q / a);
     requires EXACT(\abs(q) >= \abs(a) * 0x1p1020 ==> \abs(t1) >= 0x1p1020);
     assigns \nothing;
     ensures EXACT(\abs(t0) < 0x1p1020 ==> vdist2(f, d, t0) == r * r);
     ensures EXACT(\abs(t1) < 0x1p1020 ==> vdist2(f, d, t1) == r * r); @/
  static void lemma_sphere_roots(vec3 f, vec3 d, vec3 l, real r, real a, real b, real s, real ll, real gap,
                                 real ag, real rl, real sa, real sb, real root, real lf, real c, real cs,
                                 real q, real t0, real t1)
  {
      lemma_foot_norm(f, d, l, s, a, b);
      lemma_norms_scalar(f, l, a, b, ll, lf);
      lemma_sqrt_square(sa, ag);
      lemma_sqrt_square(sb, rl);
      lemma_product_square(root, sa, sb, ag, rl);
      lemma_abs_square(cs, root);
      lemma_quadratic_scalar(a, b, r, ll, lf, ag, rl, root, c, cs, q);
      lemma_c_norm(f, lf, r, c);
      lemma_held_cq(f, d, r, a, b, c, q, t0);
      lemma_held_qa(f, d, r, a, b, c, q, t1);
  }

  // a graze (root = 0): |l| = R, and the foot is on the sphere
  /@ requires EXACT(p == x * y && p == 0 && y * y > 0);
     assigns \nothing;
     ensures EXACT(x == 0); @/
  static void lemma_product_zero(real x, real y, real p) { }

  /@ requires EXACT(a > 0 && ag == a * gap && sa * sa == ag && sa == 0);
     assigns \nothing;
     ensures EXACT(gap == 0); @/
  static void lemma_zero_gap(real a, real gap, real ag, real sa) { }

  /@ requires EXACT(x == y);
     assigns \nothing;
     ensures EXACT(x * x == y * y); @/
  static void lemma_equal_square(real x, real y) { }

  /@ requires EXACT(a > 0 && r > 0 && ll >= 0);
     requires EXACT(gap == r - ll && ag == a * gap && rl == r + ll && sa * sa == ag && sb * sb == rl);
     requires EXACT(root == sa * sb && root == 0);
     assigns \nothing;
     ensures EXACT(ll == r); @/
  static void lemma_graze_scalar(real r, real a, real ll, real gap, real ag, real rl, real sa, real sb, real root)
  {
      lemma_product_zero(sa, sb, root);
      lemma_zero_gap(a, gap, ag, sa);
  }

  /@ requires EXACT(a > 0 && r > 0 && ll >= 0 && ll * ll == vnorm2(l));
     requires EXACT(l.x == f.x + d.x * s && l.y == f.y + d.y * s && l.z == f.z + d.z * s);
     requires EXACT(gap == r - ll && ag == a * gap && rl == r + ll);
     requires EXACT(ag >= 0 && rl >= 0 && sa == \sqrt(ag) && sb == \sqrt(rl) && root == sa * sb && root == 0);
     assigns \nothing;
     ensures EXACT(vdist2(f, d, s) == r * r); @/
  static void lemma_sphere_graze(vec3 f, vec3 d, vec3 l, real s, real r, real a, real ll, real gap, real ag,
                                 real rl, real sa, real sb, real root)
  {
      lemma_sqrt_square(sa, ag);
      lemma_sqrt_square(sb, rl);
      lemma_graze_scalar(r, a, ll, gap, ag, rl, sa, sb, root);
      lemma_equal_square(ll, r);
      lemma_dist_line(f, d, l, s);
  }
*/
int isect_sphere_roots(vec3 f, vec3 d, real radius, real t[2])
{
    /* vec_length2, not vec_dot(d, d): the same roundings, but Eva sees
     * squares, so a keeps the largest component's square as its lower
     * bound (vec_dot's two copies of d give products of either sign). */
    real a = vec_length2(d);
    t[0] = t[1] = 0;
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
    /* Each value a name, for the lemma calls (the same operations). */
    real ag = a * gap, rl = radius + ll, sa = sqrt(ag), sb = sqrt(rl);
    real root = sa * sb;
    if (root == 0.0) {
        /*@ ghost lemma_sphere_graze(f, d, l, foot, radius, a, ll, gap, ag, rl, sa, sb, root); */
        t[0] = foot;
        return 1;
    }
    real lf = vec_length_fast(f);
    real c = (lf - radius) * (lf + radius);
    real cs = copysign(root, b), q = -(b + cs);
    real t0 = held_root(c, q), t1 = held_root(q, a);
    /*@ ghost lemma_sphere_roots(f, d, l, radius, a, b, foot, ll, gap, ag, rl, sa, sb, root, lf, c, cs, q, t0, t1); */
    t[0] = t0 < t1 ? t0 : t1;
    t[1] = t0 < t1 ? t1 : t0;
    return 2;
}

