/*
 * vec.h - 3-vectors of the tracer's floating type `real`, used for points,
 * directions and RGB colours alike.  Everything here is a pure static
 * inline function so that the hot paths of the tracer inline it; nothing
 * here allocates or touches global state.
 *
 * Colours reuse vec3 with x,y,z read as r,g,b (see rgb below) because the
 * shading formulas are the same channel-wise products and sums.
 *
 * `real` is double.  Built with -DREFRAY_LONG_DOUBLE (make LONG_DOUBLE=1,
 * spec/numerics.md "The stability tool") it is long double, so the same
 * source computes the same picture with a 64-bit significand, and
 * `refray stability` compares the two.  <tgmath.h> makes sqrt, fabs, pow,
 * fma, nextafter, ... follow the type of their arguments; a literal such as
 * 0.5 is a double and is promoted exactly.  Constants that must carry more
 * digits than a double in the long double build are written REAL_C(...).
 */
#ifndef REFRAY_VEC_H
#define REFRAY_VEC_H

#include <float.h>
/* Frama-C's C library has no <tgmath.h> (make prove, spec/proofs.md); it
 * analyses the double build only, where tgmath would pick the double
 * functions of <math.h> anyway. */
#if defined(__FRAMAC__) && !defined(REFRAY_LONG_DOUBLE)
#include <math.h>
#else
#include <tgmath.h>
#endif

/* ACSL's type of mathematical reals, named before the C `real` hides it. */
/*@ type mreal = real; */

#ifdef REFRAY_LONG_DOUBLE
typedef long double real;
#define REAL_C(x) x##L
#define REAL_EPSILON LDBL_EPSILON
#define REAL_MIN LDBL_MIN
#define REAL_MAX LDBL_MAX
#define REAL_MANT_DIG LDBL_MANT_DIG
#else
typedef double real;
#define REAL_C(x) x
#define REAL_EPSILON DBL_EPSILON
#define REAL_MIN DBL_MIN
#define REAL_MAX DBL_MAX
#define REAL_MANT_DIG DBL_MANT_DIG
#endif

/* pi to more digits than any real holds. */
#define REAL_PI REAL_C(3.14159265358979323846264338327950288)

typedef struct vec3 {
    real x, y, z;
} vec3;

/* An RGB triple of linear radiometric values; x=r, y=g, z=b. */
typedef vec3 rgb;

/*
 * The ACSL contracts of the core (make prove, spec/proofs.md).  A clause
 * holds of the doubles the code computes and of exact arithmetic alike,
 * and both Eva (the doubles) and WP (exact, real-number arithmetic) check
 * it, unless it is wrapped:
 *   EXACT(p)    holds in exact arithmetic: WP proves and uses it; the Eva
 *               runs (REFRAY_PROVE_EVA) read it as \true;
 *   DOUBLES(p)  a bound on magnitudes that holds of the doubles: Eva proves
 *               and uses it; WP reads it as \true.
 * (The clauses of a function other analyses use in place of its body are
 * written out, not through predicates: Eva narrows values by those only.)
 */
#ifdef __FRAMAC__
#ifdef REFRAY_PROVE_EVA
#define EXACT(p) \true
#define DOUBLES(p) (p)
#else
#define EXACT(p) (p)
#define DOUBLES(p) \true
#endif
#endif

/*@
  logic mreal vdot(vec3 a, vec3 b) = a.x * b.x + a.y * b.y + a.z * b.z;
  logic mreal vnorm2(vec3 a) = vdot(a, a);
  logic mreal vmaxabs(vec3 a) = \max(\abs(a.x), \max(\abs(a.y), \abs(a.z)));

  predicate vfinite(vec3 a) = \is_finite(a.x) && \is_finite(a.y) && \is_finite(a.z);
  predicate vbounded(vec3 a, mreal b) = \abs(a.x) <= b && \abs(a.y) <= b && \abs(a.z) <= b;
  predicate vin(vec3 a, mreal lo, mreal hi) = lo <= a.x <= hi && lo <= a.y <= hi && lo <= a.z <= hi;
  predicate vzero(vec3 a) = a.x == 0 && a.y == 0 && a.z == 0;
  predicate veq(vec3 a, vec3 b) = a.x == b.x && a.y == b.y && a.z == b.z;
  // "unit": |a|^2 within 2^-20 of 1 (what vec_normalize and the loader
  // deliver is within a few ulps; spec/proofs.md, "Unit vectors")
  predicate vunit(vec3 a) = \abs(vnorm2(a) - 1) <= 0x1p-20;
  // a finite colour with no negative channel (a finite double is at most
  // DBL_MAX: no bound is written, a 309-digit literal stalls the provers)
  predicate vcolour(vec3 c) = vfinite(c) && c.x >= 0 && c.y >= 0 && c.z >= 0;

*/

/*
 * Lemma functions (ghost code: make prove only, the compiler sees a
 * comment; spec/proofs.md, "Admitted", round 6).  Each states one nonlinear
 * step of exact arithmetic; WP proves it alone, from its own requires, and
 * a ghost call puts its instance into the proof that needs it.  The
 * provers, given the whole goal, neither find such an instance of a lemma
 * nor take two such steps in one goal (a substitution into a product, a
 * quotient by a positive divisor).  Eva reads every clause as \true; a
 * ghost call passes variables only, so Eva finds no arithmetic in it.
 */
/*@ ghost
  /@ requires EXACT(m > 0 && s == x / m);
     assigns \nothing;
     ensures EXACT(m * m * (s * s) == x * x); @/
  static void lemma_square_quotient(real x, real m, real s) { }

  /@ requires EXACT(m != 0 && s == x / m && t == y / m);
     assigns \nothing;
     ensures EXACT(s * y == t * x); @/
  static void lemma_quotient_cross(real x, real y, real m, real s, real t) { }

  /@ requires EXACT(m > 0 && s.x == a.x / m && s.y == a.y / m && s.z == a.z / m);
     assigns \nothing;
     ensures EXACT(m * m * vnorm2(s) == vnorm2(a)); @/
  static void lemma_norm_quotient(vec3 a, real m, vec3 s)
  {
      lemma_square_quotient(a.x, m, s.x);
      lemma_square_quotient(a.y, m, s.y);
      lemma_square_quotient(a.z, m, s.z);
  }

  /@ requires EXACT(s2 >= 0 && r == \sqrt(s2));
     assigns \nothing;
     ensures EXACT(r >= 0 && r * r == s2); @/
  static void lemma_sqrt_square(real r, real s2) { }

  /@ requires EXACT(r >= 0 && r * r == s2 && m > 0 && m * m * s2 == vnorm2(a));
     assigns \nothing;
     ensures EXACT(m * r >= 0 && (m * r) * (m * r) == vnorm2(a)); @/
  static void lemma_scaled_root(vec3 a, real m, real r, real s2) { }

  /@ requires EXACT(i * d == 1);
     assigns \nothing;
     ensures EXACT((x * i) * d == x); @/
  static void lemma_inverse_back(real x, real i, real d) { }

  /@ requires EXACT(l > 0 && l * l * vnorm2(u) == l * l);
     assigns \nothing;
     ensures EXACT(vnorm2(u) == 1); @/
  static void lemma_cancel_square(real l, vec3 u) { }

  /@ requires EXACT(l > 0 && l * l == vnorm2(a) && u.x == a.x / l && u.y == a.y / l && u.z == a.z / l);
     assigns \nothing;
     ensures EXACT(vnorm2(u) == 1);
     ensures EXACT(u.x * a.y == u.y * a.x && u.y * a.z == u.z * a.y && u.z * a.x == u.x * a.z); @/
  static void lemma_unit_quotient(vec3 a, real l, vec3 u)
  {
      lemma_norm_quotient(a, l, u);
      lemma_cancel_square(l, u);
      lemma_quotient_cross(a.x, a.y, l, u.x, u.y);
      lemma_quotient_cross(a.y, a.z, l, u.y, u.z);
      lemma_quotient_cross(a.z, a.x, l, u.z, u.x);
  }
*/

/*@ assigns \nothing;
    ensures EXACT(\result.x == x && \result.y == y && \result.z == z); */
static inline vec3 vec_make(real x, real y, real z)
{
    vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

/*@ assigns \nothing;
    ensures EXACT(\result.x == s && \result.y == s && \result.z == s); */
static inline vec3 vec_splat(real s) { return vec_make(s, s, s); }
/*@ assigns \nothing;
    ensures EXACT(\result.x == a.x + b.x && \result.y == a.y + b.y && \result.z == a.z + b.z); */
static inline vec3 vec_add(vec3 a, vec3 b) { return vec_make(a.x + b.x, a.y + b.y, a.z + b.z); }
/*@ assigns \nothing;
    ensures EXACT(\result.x == a.x - b.x && \result.y == a.y - b.y && \result.z == a.z - b.z); */
static inline vec3 vec_sub(vec3 a, vec3 b) { return vec_make(a.x - b.x, a.y - b.y, a.z - b.z); }
/*@ assigns \nothing;
    ensures EXACT(\result.x == -a.x && \result.y == -a.y && \result.z == -a.z); */
static inline vec3 vec_neg(vec3 a) { return vec_make(-a.x, -a.y, -a.z); }
/*@ assigns \nothing;
    ensures EXACT(\result.x == a.x * s && \result.y == a.y * s && \result.z == a.z * s); */
static inline vec3 vec_scale(vec3 a, real s) { return vec_make(a.x * s, a.y * s, a.z * s); }

/* Channel-wise product: a colour filtered by a coefficient. */
/*@ assigns \nothing;
    ensures EXACT(\result.x == a.x * b.x && \result.y == a.y * b.y && \result.z == a.z * b.z); */
static inline vec3 vec_mul(vec3 a, vec3 b) { return vec_make(a.x * b.x, a.y * b.y, a.z * b.z); }

/* a + b*s, the accumulation step of every shading sum. */
/*@ assigns \nothing;
    ensures EXACT(\result.x == a.x + b.x * s && \result.y == a.y + b.y * s && \result.z == a.z + b.z * s); */
static inline vec3 vec_madd(vec3 a, vec3 b, real s)
{
    return vec_make(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}

/*@ assigns \nothing;
    ensures EXACT(\result == vdot(a, b)); */
static inline real vec_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/*@ assigns \nothing;
    ensures EXACT(\result.x == a.y * b.z - a.z * b.y && \result.y == a.z * b.x - a.x * b.z &&
                  \result.z == a.x * b.y - a.y * b.x); */
static inline vec3 vec_cross(vec3 a, vec3 b)
{
    return vec_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* a.x * a.x rather than vec_dot(a, a): the same roundings, and an analyser
 * that sees one operand twice knows the square is not negative. */
/*@ assigns \nothing;
    ensures \result >= 0;
    ensures EXACT(\result == vnorm2(a)); */
static inline real vec_length2(vec3 a) { return a.x * a.x + a.y * a.y + a.z * a.z; }

/*
 * hypot-style length: no overflow for components near DBL_MAX/2 and no
 * underflow to 0 for denormal components, which plain sqrt(dot) suffers.
 * The bounds by the largest component M hold of the doubles (Eva, M split
 * binade by binade: tests/prove/eva_vec.c); the exact length of the real
 * model is what WP proves.
 */
/*@ requires vfinite(a) && DOUBLES(vbounded(a, 0x1p1022));
    assigns \nothing;
    ensures \is_finite(\result);
    ensures DOUBLES(\max(\abs(a.x), \max(\abs(a.y), \abs(a.z))) >= 0x1p-1072 ==>
                    \max(\abs(a.x), \max(\abs(a.y), \abs(a.z))) / 4 <= \result);
    ensures DOUBLES(\result <= 7 * \max(\abs(a.x), \max(\abs(a.y), \abs(a.z))));
    // m sqrt(sum (a/m)^2) is |a|: the lemma functions above (proved 2026-12-02)
    ensures EXACT(\result >= 0 && \result * \result == vnorm2(a)); */
static inline real vec_length(vec3 a)
{
    real m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0 || !isfinite(m))
        return m;
    /* Divide rather than multiply by 1/m: 1/m overflows for denormal m. */
    vec3 s = vec_make(a.x / m, a.y / m, a.z / m);
    real s2 = vec_length2(s), r = sqrt(s2);
    /*@ ghost lemma_norm_quotient(a, m, s); lemma_sqrt_square(r, s2); lemma_scaled_root(a, m, r, s2); */
    return m * r;
}

/* |a| as sqrt(a.a) when a.a can neither overflow nor lose precision to
 * underflow (one square root, no divisions), else vec_length's scaled form;
 * the two may differ in the last bit.  The tracer's light distance
 * (trace.c add_source), so it carries vec_length's bounds: Eva checks them
 * on the same boxes (tests/prove/eva_vec.c). */
/*@ requires vfinite(a) && DOUBLES(vbounded(a, 0x1p1022));
    assigns \nothing;
    ensures \is_finite(\result) && \result >= 0;
    ensures DOUBLES(\max(\abs(a.x), \max(\abs(a.y), \abs(a.z))) >= 0x1p-1072 ==>
                    \max(\abs(a.x), \max(\abs(a.y), \abs(a.z))) / 4 <= \result);
    ensures DOUBLES(\result <= 7 * \max(\abs(a.x), \max(\abs(a.y), \abs(a.z))));
    ensures EXACT(\result * \result == vnorm2(a));   // either way |a| (2026-12-02) */
static inline real vec_length_fast(vec3 a)
{
    /* Decided on the largest component, before squaring: a.a formed an
     * infinity past 2^512 (not returned, but an infinity all the same, and
     * an alarm of make prove).  Within these powers of two a.a is in
     * [REAL_MIN, REAL_MAX].  The largest by comparisons, not fmax: the
     * components are finite (no NaN for fmax to skip) and |.| >= +0, so the
     * same double, without fmax's two calls into libm a light sample. */
    real ax = fabs(a.x), ay = fabs(a.y), az = fabs(a.z);
    real m = ax > ay ? ax : ay;
    m = m > az ? m : az;
    if (!(m >= 0x1p-511 && m < 0x1p511))
        return vec_length(a);
    real s2 = vec_length2(a), r = sqrt(s2);
    /*@ ghost lemma_sqrt_square(r, s2); */
    return r;
}

/* Unit vector along a; returns the zero vector for a zero input so that a
 * caller that validated its input never sees NaN from here. */
/*@ requires vfinite(a) && DOUBLES(vbounded(a, 0x1p1022));
    assigns \nothing;
    ensures \is_finite(\result.x) && \is_finite(\result.y) && \is_finite(\result.z);
    ensures DOUBLES(-4 <= \result.x <= 4 && -4 <= \result.y <= 4 && -4 <= \result.z <= 4);
    ensures a.x == 0 && a.y == 0 && a.z == 0 ==> \result.x == 0 && \result.y == 0 && \result.z == 0;
    ensures DOUBLES(a.x != 0 || a.y != 0 || a.z != 0 ==>
                    \max(\abs(\result.x), \max(\abs(\result.y), \abs(\result.z))) >= 0.125);
    ensures EXACT(!vzero(a) ==> vdot(\result, a) > 0);   // not turned round
    // |a / |a|| = 1 (lemma_unit_quotient; admitted before 2026-12-02)
    ensures EXACT(!vzero(a) ==> vnorm2(\result) == 1);
    // along a: every 2x2 minor of (result, a) is 0 (lemma_unit_quotient)
    ensures EXACT(\result.x * a.y == \result.y * a.x && \result.y * a.z == \result.z * a.y &&
                  \result.z * a.x == \result.x * a.z); */
static inline vec3 vec_normalize(vec3 a)
{
    real len = vec_length(a);
    if (!(len > 0))
        return vec_make(0, 0, 0);
    vec3 u = vec_make(a.x / len, a.y / len, a.z / len);
    /*@ ghost lemma_unit_quotient(a, len, u); */
    return u;
}

/* The max norm, max |v_i|: the scale of a point's rounding (spawn
 * offsets, the BVH's tie slack, the tracer's light and crossing bounds).
 * By comparisons, not fmax: it runs per ray and per hit, and fmax is a
 * call into libm on x86-64.  The two give the same double here: fabs is
 * never -0 and, for the operands the contract admits, never NaN, and where
 * two magnitudes are equal they are the same bits.  (A NaN, outside the
 * contract, fmax would skip and this would not; the copies in intersect.c,
 * trace.c and bvh.c it replaces were this expression, so every image is
 * the same either way.) */
/*@ requires !\is_NaN(v.x) && !\is_NaN(v.y) && !\is_NaN(v.z);
    assigns \nothing;
    ensures \result >= 0;
    ensures EXACT(\result == vmaxabs(v)); */
static inline real vec_max_abs(vec3 v)
{
    real x = fabs(v.x), y = fabs(v.y), z = fabs(v.z);
    real m = x > y ? x : y;
    return m > z ? m : z;
}

/* The 1-norm, |v_x| + |v_y| + |v_z| (summed in that order): a bound on
 * every coordinate involved in a rounding argument (the bundles' margins,
 * a light's side of a normal, a plane's pad). */
/*@ assigns \nothing; */
static inline real vec_sum_abs(vec3 v) { return fabs(v.x) + fabs(v.y) + fabs(v.z); }

/*@ requires !\is_NaN(a.x) && !\is_NaN(a.y) && !\is_NaN(a.z);
    assigns \nothing;
    ensures EXACT(\result == \max(a.x, \max(a.y, a.z))); */
static inline real vec_max_component(vec3 a) { return fmax(a.x, fmax(a.y, a.z)); }
/*@ requires !\is_NaN(a.x) && !\is_NaN(a.y) && !\is_NaN(a.z);
    assigns \nothing;
    ensures EXACT(\result == \min(a.x, \min(a.y, a.z))); */
static inline real vec_min_component(vec3 a) { return fmin(a.x, fmin(a.y, a.z)); }

/*@ requires !\is_NaN(a.x) && !\is_NaN(a.y) && !\is_NaN(a.z) && !\is_NaN(b.x) && !\is_NaN(b.y) && !\is_NaN(b.z);
    assigns \nothing;
    ensures EXACT(\result.x == \min(a.x, b.x) && \result.y == \min(a.y, b.y) && \result.z == \min(a.z, b.z)); */
static inline vec3 vec_min(vec3 a, vec3 b) { return vec_make(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
/*@ requires !\is_NaN(a.x) && !\is_NaN(a.y) && !\is_NaN(a.z) && !\is_NaN(b.x) && !\is_NaN(b.y) && !\is_NaN(b.z);
    assigns \nothing;
    ensures EXACT(\result.x == \max(a.x, b.x) && \result.y == \max(a.y, b.y) && \result.z == \max(a.z, b.z)); */
static inline vec3 vec_max(vec3 a, vec3 b) { return vec_make(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }

/*@ assigns \nothing;
    ensures EXACT(\result != 0 <==> vfinite(a)); */
static inline int vec_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/*@ assigns \nothing;
    ensures EXACT(\result == (axis == 0 ? a.x : axis == 1 ? a.y : a.z)); */
static inline real vec_component(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

#endif
