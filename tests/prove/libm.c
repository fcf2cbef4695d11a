/*
 * libm.c - ACSL contracts of the C library functions the proved code calls
 * and Frama-C's own library leaves without one (or with one too weak to
 * use).  Declarations only: Frama-C merges these contracts with its
 * <math.h>.  They are assumptions, listed in spec/proofs.md ("What is
 * assumed"): each says what C99 Annex F (IEEE 754) defines the function to
 * return.  A bare clause holds of the doubles; EXACT(...) only in exact
 * arithmetic (the WP runs; the Eva runs define REFRAY_PROVE_EVA), DOUBLES(...) only of
 * the doubles (src/base/vec.h).
 */
#include <math.h>

#ifdef REFRAY_PROVE_EVA
#define EXACT(p) \true
#define DOUBLES(p) (p)
#else
#define EXACT(p) (p)
#define DOUBLES(p) \true
#endif

/*@ requires \is_finite(x) && \is_finite(y);
    assigns \result \from x, y;
    ensures \is_finite(\result);
    ensures \result == \max(x, y); */
extern double fmax(double x, double y);

/*@ requires \is_finite(x) && \is_finite(y);
    assigns \result \from x, y;
    ensures \is_finite(\result);
    ensures \result == \min(x, y); */
extern double fmin(double x, double y);

/*@ requires \is_finite(x) && \is_finite(y);
    assigns \result \from x, y;
    ensures \is_finite(\result);
    ensures \abs(\result) == \abs(x);
    ensures -\abs(x) <= \result <= \abs(x);   // the same, in a form Eva narrows by
    ensures y > 0 ==> \result == \abs(x);
    ensures y < 0 ==> \result == -\abs(x); */
extern double copysign(double x, double y);

/* x*y + z rounded once (its definition, so it holds of the doubles). */
/*@ requires \is_finite(x) && \is_finite(y) && \is_finite(z);
    requires -DBL_MAX <= x * y + z <= DBL_MAX;
    assigns \result \from x, y, z;
    ensures \is_finite(\result);
    ensures \result == (double)(x * y + z); */
extern double fma(double x, double y, double z);

/* Frama-C's own contract says "not zero" for a finite argument; glibc
 * returns 1, which an analysis of intervals can use. */
/*@ assigns \result \from d;
    behavior finite_is_one:
      assumes \is_finite(d);
      ensures \result == 1; */
extern int __finite(double d);

/* The neighbour of x toward y: between x and y, at most x's ulp away (an
 * ulp of a normal x is at most 2^-52 |x|, of a subnormal one 2^-1074),
 * at least the least subnormal's. */
/*@ requires \is_finite(x) && \is_finite(y);
    assigns \result \from x, y;
    ensures \is_finite(\result);
    ensures \min(x, y) <= \result <= \max(x, y);
    ensures x < y ==> x < \result <= y;
    ensures x > y ==> y <= \result < x;
    ensures x == y ==> \result == y;
    ensures EXACT(x != y ==> \abs(\result - x) <= 0x1p-52 * \abs(x) + 0x1p-1074);
    // and at least 2^-1074 away: every double is a multiple of 2^-1074 (so
    // a loop of steps toward y ends)
    ensures EXACT(x != y ==> \abs(\result - x) >= 0x1p-1074); */
extern double nextafter(double x, double y);

/*@ requires \is_finite(x) && \is_finite(y);
    requires \abs(x) <= 0x1p1022 && \abs(y) <= 0x1p1022;
    assigns \result \from x, y;
    ensures \is_finite(\result);
    ensures \max(\abs(x), \abs(y)) <= \result <= 2 * \max(\abs(x), \abs(y));
    ensures EXACT(\result == \sqrt(x * x + y * y)); */
extern double hypot(double x, double y);

/* tan on [0, pi/2): the double nearest pi/2 is below it, so tan stays
 * finite: at most 1.7e16.  tan(0) = 0 (F.9.1.7), positive on (0, pi/2);
 * in exact arithmetic the bound is pi/2 (the 36 digits of REAL_PI). */
/*@ requires 0 <= x && DOUBLES(x < 0x1.921fb54442d18p+0) && EXACT(x < 1.57079632679489661923132169163975144);
    assigns \result \from x;
    ensures \is_finite(\result) && 0 <= \result && DOUBLES(\result <= 0x1p54);
    ensures x > 0 ==> \result > 0;
    ensures EXACT(\result == \tan(x)); */
extern double tan(double x);

/* The largest integer not above x (F.9.6.2: exact).  Frama-C's own says
 * only "finite"; light_grid_for converts the result to int. */
/*@ requires \is_finite(x);
    assigns \result \from x;
    ensures \is_finite(\result);
    ensures \result <= x < \result + 1;
    ensures EXACT(\result == \floor(x)); */
extern double floor(double x);

/*@ requires \is_finite(x);
    assigns \result \from x;
    ensures \is_finite(\result) && -1 <= \result <= 1;
    ensures EXACT(\result == \cos(x)); */
extern double cos(double x);

/*@ requires \is_finite(x);
    assigns \result \from x;
    ensures \is_finite(\result) && -1 <= \result <= 1;
    ensures EXACT(\result == \sin(x)); */
extern double sin(double x);

/* pow(1, y) is 1 for every y, pow(x, y) in [0, 1] for x in [0, 1] and
 * y >= 0 (C99 F.9.4.4; monotony of x^y). Merged with Frama-C's contract.
 * In exact arithmetic it is x^y, the abstract real_pow of
 * src/render/shade.h (the same block: Frama-C merges the two). */
/*@ type mreal = real; */
/*@ axiomatic RealPow {
  logic mreal real_pow(mreal x, mreal y);
  } */
/*@ assigns errno, \result \from x, y;
    ensures x == 1 ==> \result == 1;
    ensures 0 <= x <= 1 && y >= 0 ==> 0 <= \result <= 1;
    ensures EXACT(0 < x <= 1 && y >= 0 ==> \result == real_pow(x, y)); */
extern double pow(double x, double y);
