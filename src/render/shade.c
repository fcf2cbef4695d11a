/*
 * shade.c - the seed's shading formulas (spec/shading.md has the table of
 * slide -> formula -> function -> test).
 *
 * Invariants: every function is pure (no state, no allocation); inputs the
 * scene validator proves (0 <= Kd, Ks, t <= 1, shininess >= 0, ior > 0) are
 * asserted; conditions that can still happen in a stiff scene (a light at
 * the hit point, a dot product a hair outside [-1, 1]) are handled by
 * defensive checks named as such, never by NaN or Inf: no operation here
 * forms an infinity, not even one it would clamp afterwards.
 *
 * The ACSL contracts are checked by `make prove` (spec/proofs.md): Eva
 * shows every bare clause and the absence of run-time errors, infinities
 * and NaN for the doubles; WP proves every clause in exact arithmetic,
 * EXACT(...) ones included.  The requires name what establishes them:
 *   Kd, Ks in [0, 1], n >= 0, t in [0, 1], ior > 0, all finite:
 *     [LANG-MAT-1], [LANG-VALID-2] (material_props, src/scene/lower_blocks.c);
 *   powers, the ambient sum and d0 finite and >= 0: [LANG-POINT-1],
 *     [LANG-DIST-1], [LANG-AMBIENT-1] (light_common, lower_ambient);
 *   "unit" directions (vunit, src/base/vec.h): vec_normalize's result, which
 *     is what the tracer passes; each component is then at most 4 (vec.h).
 */
#include <assert.h>
#include <float.h>
#include <math.h>
#include "base/inline_hint.h"
#include "render/shade.h"

/*@ requires vin(kd, 0, 1);
    requires vcolour(ia);
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(\result.x == kd.x * ia.x && \result.y == kd.y * ia.y && \result.z == kd.z * ia.z);
    ensures EXACT(0 <= \result.x <= ia.x && 0 <= \result.y <= ia.y && 0 <= \result.z <= ia.z); */
rgb shade_ambient(rgb kd, rgb ia)
{
    return vec_mul(kd, ia);
}

/*
 * Defensive: e/s rounded, or DBL_MAX where that would pass DBL_MAX, so
 * that a zero Kd or shadow factor later gives 0, not Inf*0 = NaN.  The
 * overflow is decided before dividing, by products of s with powers of two
 * (exact for s < 1): e/s <= 2^1022 is divided at once; up to 2^1024 it is
 * divided a quarter at a time, 4 (e/4)/s being e/s with its one rounding.
 */
/*@ requires \is_finite(e) && e >= 0;
    requires \is_finite(s) && s > 0;
    assigns \nothing;
    ensures \is_finite(\result) && \result >= 0;
    ensures EXACT(\result <= e / s);
    ensures EXACT(e / s <= DBL_MAX ==> \result == e / s); */
static real saturating_div(real e, real s)
{
    if (s >= 1 || e <= s * 0x1p1022)
        return e / s;
    real quarter = 0.25 * e;
    if (quarter > s * 0x1p1022)
        return DBL_MAX;
    real q = quarter / s;
    return q <= 0.25 * DBL_MAX ? 4 * q : DBL_MAX;
}

/*@ requires vcolour(power);
    requires \is_finite(d) && d >= 0;    // a distance: vec_length's result (trace.c add_source)
    requires \is_finite(d0) && d0 >= 0;  // [LANG-POINT-1], [LANG-DIST-1]: d0 >= 0 (light_common)
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(falloff == FALLOFF_NONE || d + d0 == 0 ==> veq(\result, power));
    ensures EXACT(falloff != FALLOFF_NONE && d + d0 > 0 && d < 0x1p1023 && d0 < 0x1p1023 ==>
                  \result.x <= falloff_of(power.x, d + d0, falloff) &&
                  \result.y <= falloff_of(power.y, d + d0, falloff) &&
                  \result.z <= falloff_of(power.z, d + d0, falloff));
    ensures EXACT(falloff != FALLOFF_NONE && d + d0 > 0 && d < 0x1p1023 && d0 < 0x1p1023 &&
                  vbounded(power, DBL_MAX) ==>
                  (falloff_of(power.x, d + d0, falloff) <= DBL_MAX ==>
                   \result.x == falloff_of(power.x, d + d0, falloff)) &&
                  (falloff_of(power.y, d + d0, falloff) <= DBL_MAX ==>
                   \result.y == falloff_of(power.y, d + d0, falloff)) &&
                  (falloff_of(power.z, d + d0, falloff) <= DBL_MAX ==>
                   \result.z == falloff_of(power.z, d + d0, falloff))); */
rgb shade_falloff(rgb power, real d, real d0, scene_falloff falloff)
{
    if (falloff == FALLOFF_NONE)
        return power;
    /* Defensive: d + d0 past DBL_MAX (a light 9e307 away): halve both, and
     * the power, which leaves E/s unchanged and forms no infinity. */
    real s, e_scale = 1;
    if (d >= 0x1p1023 || d0 >= 0x1p1023) {
        s = 0.5 * d + 0.5 * d0;
        e_scale = 0.5;
    } else {
        s = d + d0;
    }
    /* Defensive: the validator (d0 >= 0) and the tracer (hits leave the
     * light) keep s > 0; a light exactly on the surface with d0 = 0 gives
     * s = 0, where L is undefined anyway: return E rather than Inf. */
    if (!(s > 0.0))
        return power;
    /* E/s/s, not E/(s*s): s*s underflows to 0 for s < 1e-162. */
    rgb linear = vec_make(saturating_div(e_scale * power.x, s), saturating_div(e_scale * power.y, s),
                          saturating_div(e_scale * power.z, s));
    if (falloff == FALLOFF_LINEAR)
        return linear;
    return vec_make(saturating_div(e_scale * linear.x, s), saturating_div(e_scale * linear.y, s),
                    saturating_div(e_scale * linear.z, s));
}

/*@ requires vcolour(power);
    requires samples >= 1;               // [LANG-DIST-1]: samples in 1 .. 4096 (distributed_shape)
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(\result.x == power.x / samples && \result.y == power.y / samples &&
                  \result.z == power.z / samples); */
rgb shade_sample_power(rgb power, int samples)
{
    assert(samples >= 1);
    return vec_make(power.x / samples, power.y / samples, power.z / samples);
}

/*@ requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires vfinite(v) && DOUBLES(vbounded(v, 4));
    assigns \nothing;
    ensures vfinite(\result) && DOUBLES(vbounded(\result, 4));
    ensures EXACT(vdot(n, v) >= 0 ==> veq(\result, n));
    ensures EXACT(vdot(n, v) < 0 ==> \result.x == -n.x && \result.y == -n.y && \result.z == -n.z); */
vec3 shade_face_forward(vec3 n, vec3 v)
{
    return vec_dot(n, v) < 0.0 ? vec_neg(n) : n;
}

/* `c > 0` is false for NaN too, so a degenerate L (the zero vector that
 * vec_normalize returns for a light at the point) contributes nothing. */
/*@ requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires vfinite(l) && DOUBLES(vbounded(l, 4));
    assigns \nothing;
    ensures 0 <= \result <= 1;
    ensures EXACT(vdot(n, l) <= 0 ==> \result == 0);
    ensures EXACT(0 < vdot(n, l) <= 1 ==> \result == vdot(n, l)); */
real shade_lambert(vec3 n, vec3 l)
{
    real c = vec_dot(n, l);
    if (!(c > 0.0))
        return 0.0;
    return c < 1.0 ? c : 1.0;
}

/*@ requires vin(kd, 0, 1);
    requires vcolour(intensity);
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires vfinite(l) && DOUBLES(vbounded(l, 4));
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(0 <= \result.x <= kd.x * intensity.x && 0 <= \result.y <= kd.y * intensity.y &&
                  0 <= \result.z <= kd.z * intensity.z);
    ensures EXACT(vdot(n, l) <= 0 ==> vzero(\result));
    // [SHADE-DIFFUSE-1] in the code's order of products (CVC4's strings mode closes it)
    ensures EXACT(0 < vdot(n, l) <= 1 ==> \result.x == kd.x * intensity.x * vdot(n, l) &&
                  \result.y == kd.y * intensity.y * vdot(n, l) && \result.z == kd.z * intensity.z * vdot(n, l)); */
rgb shade_diffuse(rgb kd, rgb intensity, vec3 n, vec3 l)
{
    return vec_scale(vec_mul(kd, intensity), shade_lambert(n, l));
}

/* R = 2(N.L)N - L: the component of L along N is kept, the rest negated. */
/*@ requires vfinite(l) && DOUBLES(vbounded(l, 4));
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    assigns \nothing;
    ensures vfinite(\result) && DOUBLES(vbounded(\result, 512));
    ensures EXACT(\result.x == 2 * vdot(n, l) * n.x - l.x && \result.y == 2 * vdot(n, l) * n.y - l.y &&
                  \result.z == 2 * vdot(n, l) * n.z - l.z); */
vec3 shade_reflect_about(vec3 l, vec3 n)
{
    return vec_sub(vec_scale(n, 2.0 * vec_dot(n, l)), l);
}

/* D - 2(N.D)N: the component of D along N is negated, the rest kept.  The
 * sign of n cancels ((-N.D)(-N) = (N.D)N), so either orientation works. */
/*@ requires vfinite(d) && DOUBLES(vbounded(d, 4));
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    assigns \nothing;
    ensures vfinite(\result) && DOUBLES(vbounded(\result, 512));
    ensures EXACT(is_mirror(\result, d, n)); */
vec3 shade_mirror(vec3 d, vec3 n)
{
    return vec_madd(d, n, -2.0 * vec_dot(n, d));
}

/*
 * The lobe is cos^n of the angle between v and r.  For a large n every ulp
 * of the cosine is n ulps of the lobe, and the plain dot product V.R carries
 * the rounding of the unit vectors' lengths (|V| = 1 +- eps moves V.R by
 * eps), which has nothing to do with the angle: with n = 1e6 that alone is
 * a relative error of 1e-10.  So for angles below 41 degrees (h < 1/4) the
 * cosine is formed from h = 1 - cos = |V - R|^2 / (2 |V| |R|), in which the lengths
 * cancel to second order and V - R is exact (Sterbenz) for nearby vectors,
 * and kept as a sum c_hi + c_lo = 1 - h held exactly; then
 *   (c_hi + c_lo)^n = c_hi^n (1 + c_lo/c_hi)^n = pow(c_hi, n) exp(n c_lo/c_hi)
 * to first order in c_lo/c_hi < 2^-52.  pow of a double that is exactly the
 * cosine (V = R: c_hi = 1, c_lo = 0) stays exact.  Measured in
 * spec/numerics.md ("Phong lobe").
 */
/* Returns c_hi and stores c_lo / c_hi in *rel.  Defensive: vectors far
 * from unit length (2 |V| |R| below 1/2) take the plain cosine, and that
 * is clamped to 1 as a unit pair's is. */
/*@ requires vfinite(v) && DOUBLES(vbounded(v, 1024));
    requires vfinite(r) && DOUBLES(vbounded(r, 1024));
    requires \is_finite(c) && 0 < c;
    requires \valid(rel);
    requires EXACT(c == vdot(v, r));
    assigns *rel \from v, r, c;
    ensures \is_finite(\result) && 0 < \result <= 1;
    ensures \is_finite(*rel) && DOUBLES(-0.5 <= *rel <= 0.5);
    ensures EXACT(*rel == 0);
    // for unit V, R (h = 1 - V.R) both branches give the cosine
    ensures EXACT(vnorm2(v) == 1 && vnorm2(r) == 1 ==> \result == \min(c, 1)); */
static real lobe_cosine(vec3 v, vec3 r, real c, real *rel)
{
    vec3 d = vec_sub(v, r);
    real den = 2 * sqrt(vec_length2(v) * vec_length2(r));
    real h = den >= 0.5 ? vec_length2(d) / den : 1;
    /* For the last clause: unit V, R give den = 2 and h = 1 - V.R. */
    /*@ assert lobe_den: EXACT(vnorm2(v) == 1 && vnorm2(r) == 1 ==> den == 2); */
    /*@ assert lobe_d: EXACT(unit_pair(v, r) ==> vnorm2(d) == 2 - 2 * c); */
    /*@ assert lobe_h: EXACT(vnorm2(v) == 1 && vnorm2(r) == 1 ==> h == 1 - c); */
    if (h < 0.25) {
        real c_hi = 1 - h;
        *rel = ((1 - c_hi) - h) / c_hi;   /* c_lo: exact, 1 - c_hi is (Sterbenz) */
        return c_hi;
    }
    *rel = 0;
    return c < 1 ? c : 1;                 /* far from the peak V.R is as good */
}

/*
 * The exponent of the correction exp(n c_lo / c_hi) is at most 372 where
 * pow(c_hi, n) has not underflowed to 0 (n <= 745 / h there and
 * |c_lo| <= 2^-53 h); where it has, the product is 0 whatever the
 * correction, so capping the exponent at 709 changes nothing and keeps
 * exp finite: 0 * Inf would be NaN.  The cap is a comparison, not fmin (a
 * libm call per lobe on x86-64): x < 709 ? x : 709 is fmin(x, 709) for
 * every double x, as a NaN fails the test and gets 709, fmin's answer, and
 * 709 is no zero, so no -0/+0 tie arises (here x is finite anyway: n
 * finite, |rel| <= 1/2).  Rounding never puts the lobe above
 * 1, and the final comparison says so to the analyser (again a comparison,
 * not fmin; p >= DBL_MIN is no NaN, where the two agree).
 */
/*@ requires vfinite(v) && DOUBLES(vbounded(v, 1024));
    requires vfinite(r) && DOUBLES(vbounded(r, 1024));
    requires \is_finite(shininess) && shininess >= 0;  // [LANG-MAT-1]: n >= 0 (material_props)
    assigns errno;   // pow and exp may set ERANGE on underflow
    ensures 0 <= \result <= 1;
    ensures EXACT(vdot(v, r) <= 0 ==> \result == 0);
    ensures EXACT(vdot(v, r) > 0 && shininess == 0 ==> \result == 1);
    // the value (V.R)^n for unit V, R ([SHADE-PHONG-1]), x^y abstract
    ensures EXACT(vdot(v, r) > 0 && shininess > 0 && vnorm2(v) == 1 && vnorm2(r) == 1 ==>
                  \result == phong_of(vdot(v, r), shininess)); */
real shade_phong_lobe(vec3 v, vec3 r, real shininess)
{
    assert(shininess >= 0.0);
    real c = vec_dot(v, r), rel;
    if (!(c > 0.0))
        return 0.0;
    if (shininess == 0)
        return 1.0;
    real c_hi = lobe_cosine(v, r, c, &rel);
    /* Subnormal results (below 2.2e-308) are invisible and slow: flush. */
    real p = pow(c_hi, shininess);
    if (rel != 0) {
        real x = shininess * rel;
        p *= exp(x < 709 ? x : 709);
    }
    return p >= DBL_MIN ? (p < 1.0 ? p : 1.0) : 0.0;
}

/*@ requires vin(ks, 0, 1);
    requires vcolour(intensity);
    requires vfinite(v) && DOUBLES(vbounded(v, 4));
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires vfinite(l) && DOUBLES(vbounded(l, 4));
    requires \is_finite(shininess) && shininess >= 0;
    assigns errno;
    ensures vcolour(\result);
    ensures EXACT(vdot(n, l) <= 0 ==> vzero(\result));
    ensures EXACT(0 <= \result.x <= ks.x * intensity.x && 0 <= \result.y <= ks.y * intensity.y &&
                  0 <= \result.z <= ks.z * intensity.z);
    // the lobe is taken about R = 2(N.L)N - L ([SHADE-SPEC-1], [SHADE-PHONG-3]):
    // nothing where V.R <= 0, Ks I in full for n = 0 where V.R > 0
    ensures EXACT(vdot(n, l) > 0 && vdot(v, reflected(l, n)) <= 0 ==> vzero(\result));
    ensures EXACT(vdot(n, l) > 0 && vdot(v, reflected(l, n)) > 0 && shininess == 0 ==>
                  \result.x == ks.x * intensity.x && \result.y == ks.y * intensity.y &&
                  \result.z == ks.z * intensity.z);
    // the highlight's value Ks I (V.R)^n for unit V and R (R is unit when N, L are)
    ensures EXACT(vdot(n, l) > 0 && vdot(v, reflected(l, n)) > 0 && shininess > 0 &&
                  vnorm2(v) == 1 && vnorm2(reflected(l, n)) == 1 ==>
                  \result.x == ks.x * intensity.x * phong_of(vdot(v, reflected(l, n)), shininess) &&
                  \result.y == ks.y * intensity.y * phong_of(vdot(v, reflected(l, n)), shininess) &&
                  \result.z == ks.z * intensity.z * phong_of(vdot(v, reflected(l, n)), shininess)); */
rgb shade_specular(rgb ks, rgb intensity, vec3 v, vec3 n, vec3 l, real shininess)
{
    if (!(vec_dot(n, l) > 0.0))
        return vec_splat(0.0);
    vec3 r = shade_reflect_about(l, n);
    /* For the last clause: the lobe's arguments are those of the clause. */
    /*@ assert spec_unit: EXACT(vnorm2(reflected(l, n)) == 1 ==> vnorm2(r) == 1); */
    /*@ assert spec_dot: EXACT(vdot(v, r) == vdot(v, reflected(l, n))); */
    real lobe = shade_phong_lobe(v, r, shininess);
    /*@ assert spec_lobe: EXACT(vdot(n, l) > 0 && vdot(v, reflected(l, n)) > 0 && shininess > 0 &&
                                vnorm2(v) == 1 && vnorm2(reflected(l, n)) == 1 ==>
                                lobe == phong_of(vdot(v, reflected(l, n)), shininess)); */
    return vec_scale(vec_mul(ks, intensity), lobe);
}

/*@ requires vin(kd, 0, 1) && vin(ks, 0, 1);
    requires \is_finite(shininess) && shininess >= 0;
    requires vcolour(intensity);
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires vfinite(l) && DOUBLES(vbounded(l, 4));
    requires vfinite(v) && DOUBLES(vbounded(v, 4));
    assigns errno;
    ensures vcolour(\result.body) && vcolour(\result.highlight);
    ensures EXACT(vdot(n, l) <= 0 ==> vzero(\result.body) && vzero(\result.highlight));
    ensures EXACT(0 <= \result.body.x <= kd.x * intensity.x && 0 <= \result.body.y <= kd.y * intensity.y &&
                  0 <= \result.body.z <= kd.z * intensity.z);
    ensures EXACT(0 <= \result.highlight.x <= ks.x * intensity.x &&
                  0 <= \result.highlight.y <= ks.y * intensity.y &&
                  0 <= \result.highlight.z <= ks.z * intensity.z); */
shade_terms shade_direct(rgb kd, rgb ks, real shininess, rgb intensity, vec3 n, vec3 l,
                         vec3 v)
{
    shade_terms s;
    s.body = shade_diffuse(kd, intensity, n, l);
    s.highlight = shade_specular(ks, intensity, v, n, l, shininess);
    return s;
}

/* Error-free product (fma rounds once): a*b == result + *err exactly. */
/*@ requires \is_finite(a) && \is_finite(b) && DOUBLES(\abs(a) <= 0x1p500 && \abs(b) <= 0x1p500);
    requires \valid(err);
    assigns *err \from a, b;
    ensures \is_finite(\result) && \is_finite(*err);
    ensures EXACT(\result == a * b && *err == 0); */
static real two_prod(real a, real b, real *err)
{
    real p = a * b;
    *err = fma(a, b, -p);
    return p;
}

/* Error-free sum (Knuth's TwoSum, no ordering needed): a+b == result + *err. */
/*@ requires \is_finite(a) && \is_finite(b) && DOUBLES(\abs(a) <= 0x1p1000 && \abs(b) <= 0x1p1000);
    requires \valid(err);
    assigns *err \from a, b;
    ensures \is_finite(\result) && \is_finite(*err);
    ensures EXACT(\result == a + b && *err == 0); */
static real two_sum(real a, real b, real *err)
{
    real s = a + b;
    real bb = s - a;
    *err = (a - (s - bb)) + (b - bb);
    return s;
}

/*
 * Scales n1, n2 by one power of two so that the larger lies in [0.5, 1)
 * (the fraction frexp gives) and returns it: exact, so it changes no sign
 * or ratio, and the squares below can neither overflow nor underflow for
 * the larger index.  The power is found by halving steps, each a product
 * with a power of two: exact, save for a smaller index pushed below
 * DBL_MIN (a ratio of indices past 2^1021), which is rounded.
 */
/*@ requires \is_finite(n1) && n1 > 0 && \is_finite(n2) && n2 > 0;   // [LANG-MAT-1]: ior > 0, or 1 (air)
    requires \valid(s1) && \valid(s2) && \separated(s1, s2);
    assigns *s1 \from n1, n2;
    assigns *s2 \from n1, n2;
    assigns \result \from n1, n2;
    ensures \initialized(s1) && \initialized(s2);
    ensures \is_finite(\result) && DOUBLES(0.5 <= \result < 1);
    ensures \is_finite(*s1) && \is_finite(*s2) && DOUBLES(0 <= *s1 <= 1 && 0 <= *s2 <= 1);
    ensures EXACT(*s1 > 0 && *s2 > 0 && \result > 0);
    ensures EXACT(*s1 * n2 == *s2 * n1 && \result * n1 == *s1 * \max(n1, n2) && \result * n2 == *s2 * \max(n1, n2)); */
static real scale_indices(real n1, real n2, real *s1, real *s2)
{
    static const real step[10] = {0x1p512, 0x1p256, 0x1p128, 0x1p64, 0x1p32, 0x1p16, 0x1p8, 0x1p4, 0x1p2, 0x1p1};
    /* Products with the reciprocals: the same roundings as quotients by
     * powers of two, and cheaper. */
    static const real down[10] = {0x1p-512, 0x1p-256, 0x1p-128, 0x1p-64, 0x1p-32, 0x1p-16, 0x1p-8, 0x1p-4,
                                  0x1p-2, 0x1p-1};
    /* The larger by a comparison, not fmax (a call into libm): both are
     * positive and finite, so the same double. */
    real m = n1 > n2 ? n1 : n2, a = n1, b = n2;
    /* The larger index in [1, 2) (air 1, water 1.33, glass 1.5, a dense
     * flint 1.9: most pairs of a scene): no step below applies but the one
     * halving, so these are its three products, without the loops. */
    if (m >= 1 && m < 2) {
        *s1 = a * 0.5;
        *s2 = b * 0.5;
        return m * 0.5;
    }
    /*@ loop unroll 10;
        loop invariant 0 <= i <= 10;
        loop invariant EXACT(m > 0 && a > 0 && b > 0);
        loop invariant EXACT(a * n2 == b * n1 && m * n1 == a * \max(n1, n2) && m * n2 == b * \max(n1, n2));
        loop assigns i, m, a, b;
        loop variant 10 - i; */
    for (int i = 0; i < 10; i++) {
        if (m >= step[i]) {   /* m < 2 step[i] here: m / step[i] in [1, 2) */
            m *= down[i];
            a *= down[i];
            b *= down[i];
        }
    }
    if (m >= 1) {
        m *= 0.5;
        a *= 0.5;
        b *= 0.5;
    }
    /* Up, 2^512 first and twice: from the least subnormal 2^-1074. */
    /*@ loop unroll 11;
        loop invariant -1 <= i <= 10;
        loop invariant EXACT(m > 0 && a > 0 && b > 0);
        loop invariant EXACT(a * n2 == b * n1 && m * n1 == a * \max(n1, n2) && m * n2 == b * \max(n1, n2));
        loop assigns i, m, a, b;
        loop variant 10 - i; */
    for (int i = -1; i < 10; i++) {
        real up = step[i < 0 ? 0 : i];
        if (m * up < 1) {
            m *= up;
            a *= up;
            b *= up;
        }
    }
    *s1 = a;
    *s2 = b;
    return m;
}

/*
 * k = (n1 c)^2 - (n1^2 - n2^2) = n2^2 cos^2(th2), from Snell:
 *   cos^2 th2 = 1 - (n1/n2)^2 (1 - c^2)   => multiply by n2^2.
 * k < 0 is total internal reflection.  Near the critical angle k is the
 * difference of two nearly equal numbers, so each product is split exactly
 * (two_prod) and the three heads summed exactly (two_sum); only the small
 * tails are rounded: absolute error about 2^-104 * max(n1, n2)^2, against
 * 2^-52 for the textbook 1 - eta^2 (1 - c^2).  This makes the sign exact
 * for every c a whole ulp away from the critical cosine.
 */
/*@ requires \is_finite(n1) && \is_finite(n2) && DOUBLES(0 <= n1 <= 1 && 0 <= n2 <= 1);
    requires \is_finite(c) && \is_finite(c_lo) && DOUBLES(0 <= c <= 1 && \abs(c_lo) <= 1024);
    assigns \nothing;
    ensures \is_finite(\result);
    ensures EXACT(\result == snell_k(n1, n2, c + c_lo)); */
static real refract_discriminant(real n1, real n2, real c, real c_lo)
{
    real e_p, e_pp, e_a, e_b, e_1, e_2;
    real p = two_prod(n1, c, &e_p);      /* n1 c  = p + e_p */
    e_p += n1 * c_lo;                    /* n1 (c + c_lo) = p + e_p, to 2^-104 */
    real pp = two_prod(p, p, &e_pp);     /* p^2   = pp + e_pp */
    real a = two_prod(n1, n1, &e_a);     /* n1^2  = a + e_a */
    real b = two_prod(n2, n2, &e_b);     /* n2^2  = b + e_b */
    real h = two_sum(pp, -a, &e_1);
    h = two_sum(h, b, &e_2);
    /* (p + e_p)^2 = p^2 + 2 p e_p + e_p^2 */
    real tail = e_pp + 2.0 * p * e_p + e_p * e_p - e_a + e_b + e_1 + e_2;
    return h + tail;
}

/*
 * cos th1 = -N.D as an unevaluated sum c + *lo, exact to about 2^-104:
 * near the critical angle cos th2 = sqrt(k)/n2 has the slope
 * n1^2 c / sqrt(k) in c, so the one rounding of a plain dot product
 * (2^-53) would be amplified without bound, and would flip the decision
 * for angles within about 1e-16 rad of the critical one (spec/numerics.md,
 * "Refraction").  Products split exactly by two_prod, summed by two_sum.
 * Clamped: a hair outside [0, 1] from rounding is grazing or normal
 * incidence, not an error.
 */
/*@ requires vfinite(d) && DOUBLES(vbounded(d, 4));
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires \valid(lo);
    assigns *lo \from d, n;
    ensures \is_finite(\result) && 0 <= \result <= 1;
    ensures \is_finite(*lo) && DOUBLES(\abs(*lo) <= 1024);
    ensures EXACT(\result == incidence(d, n) && *lo == 0); */
static real incidence_cos(vec3 d, vec3 n, real *lo)
{
    real e0, e1, e2, s0, s1;
    real p0 = two_prod(n.x, d.x, &e0), p1 = two_prod(n.y, d.y, &e1), p2 = two_prod(n.z, d.z, &e2);
    real h = two_sum(p0, p1, &s0);
    h = two_sum(h, p2, &s1);
    real c = -h, c_lo = -(e0 + e1 + e2 + s0 + s1);
    real sum = c + c_lo;
    *lo = 0;
    if (!(sum > 0.0))
        return 0.0;
    if (!(sum < 1.0))
        return 1.0;
    (void)two_sum(c, c_lo, lo);   /* renormalised: sum + *lo == c + c_lo, |lo| <= ulp(sum)/2 */
    return sum;
}

/*
 * With c = cos th1, the part of d along the surface is d + c n (length
 * sin th1).  Snell keeps its direction and scales it by eta = n1/n2; the
 * part along -n has length cos th2 = sqrt(k)/n2 (see refract_discriminant):
 *   t = eta (d + c n) - cos th2 n.
 * Written this way the normal component of t is computed from k alone,
 * which stays accurate near the critical angle (cos th2 -> 0) and near
 * grazing incidence (sin th1 -> 1), where eta d + (eta c - cos th2) n
 * cancels.  It is computed times n2, as n1 (d + c n) - sqrt(k) n with the
 * scaled indices, which normalising undoes: no division, so no index ratio
 * (up to 1e600 between valid iors) can overflow.
 */
/*@ requires vfinite(d) && DOUBLES(vbounded(d, 4));
    requires vfinite(n) && DOUBLES(vbounded(n, 4));
    requires \is_finite(n1) && n1 > 0 && \is_finite(n2) && n2 > 0;  // [LANG-MAT-1]: ior > 0, or 1 (air)
    requires EXACT(vunit(d));
    requires \valid(t);
    assigns *t \from d, n, n1, n2;
    ensures \result == 0 || \result == 1;
    ensures vfinite(*t) && DOUBLES(vbounded(*t, 512));
    ensures EXACT(\result == 0 <==> snell_k(n1, n2, incidence(d, n)) < 0);
    ensures EXACT(\result == 0 ==> is_mirror(*t, d, n));
    ensures EXACT(n1 == n2 ==> \result == 1 && veq(*t, d));
    ensures EXACT(\result == 1 ==> \abs(vnorm2(*t) - 1) <= 0x1p-20); */
int shade_refract(vec3 d, vec3 n, real n1, real n2, vec3 *t)
{
    assert(n1 > 0.0 && n2 > 0.0 && isfinite(n1) && isfinite(n2));
    /* Equal indices: no boundary at all.  The general formula would return
     * d only up to rounding, and an index-matched interface (touching
     * glass, a medium left into the same medium) must not move a ray. */
    if (n1 == n2) {
        *t = d;
        return 1;
    }
    real s1, s2;
    (void)scale_indices(n1, n2, &s1, &s2);
    real c_lo, c = incidence_cos(d, n, &c_lo);
    real k = refract_discriminant(s1, s2, c, c_lo);
    if (!(k >= 0.0)) {
        *t = shade_mirror(d, n);
        return 0;
    }
    vec3 along = vec_madd(d, n, c);
    vec3 u = vec_normalize(vec_madd(vec_scale(along, s1), n, -fmin(sqrt(k), s2)));
    /* Defensive: a zero vector only when s2 underflowed (n1/n2 past 2^1074)
     * at normal incidence, the one direction that passes: straight on. */
    *t = u.x == 0 && u.y == 0 && u.z == 0 ? d : u;
    return 1;
}

/*
 * sqrt((n1 - n2)(n1 + n2)) / n1 is within a few ulps of the critical cosine
 * (each factor has one rounding; n1 - n2 is exact when n2 >= n1/2); the two
 * loops then step to the least value whose discriminant is >= 0, using the
 * same test as shade_refract, so the two agree to the bit.  The discriminant
 * increases with c, and the estimate is a few ulps off: the loops run a few
 * times.
 */
/*@ requires \is_finite(n1) && n1 > 0 && \is_finite(n2) && n2 > 0;  // [LANG-MAT-1]: ior > 0, or 1 (air)
    assigns \nothing;
    ensures \is_finite(\result) && 0 <= \result <= 1;
    ensures EXACT(n1 <= n2 ==> \result == 0);
    ensures EXACT(snell_k(n1, n2, \result) >= 0);
    // the least such cosine, to one step of nextafter (libm.c): a cosine
    // that much below the result is total internal reflection
    ensures EXACT(n1 > n2 ==> snell_k(n1, n2, step_below(\result)) < 0); */
real shade_critical_angle_cos(real n1, real n2)
{
    assert(n1 > 0.0 && n2 > 0.0 && isfinite(n1) && isfinite(n2));
    if (n1 <= n2)
        return 0.0;
    real s1, s2;
    real m = scale_indices(n1, n2, &s1, &s2);   /* s1 here */
    /* For the last clause: the cosine 0 reflects (s1 > s2 as n1 > n2). */
    /*@ assert crit_s2: EXACT(s2 * n1 > s2 * n2); */
    /*@ assert crit_s: EXACT(s1 > s2); */
    /*@ assert crit_sq: EXACT(s1 * s1 > s1 * s2 && s1 * s2 > s2 * s2); */
    /*@ assert crit_k0: EXACT(snell_k(s1, s2, 0) < 0); */
    real c = fmin(sqrt(fmax((s1 - s2) * (s1 + s2), 0)) / m, 1.0);   /* fmax: s1 >= s2, so never taken */
    /* The variants count steps of the least subnormal, the least a
     * nextafter step moves (libm.c). */
    /*@ loop invariant 0 <= c <= 1;
        loop assigns c;
        loop variant \floor((1 - c) / 0x1p-1074); */
    while (c < 1.0 && !(refract_discriminant(s1, s2, c, 0) >= 0.0))
        c = nextafter(c, 1.0);
    real below = nextafter(c, 0.0);
    /*@ loop invariant 0 <= below <= 1 && 0 <= c <= 1;
        loop invariant EXACT(snell_k(s1, s2, c) >= 0);
        loop invariant EXACT(below >= c - 0x1p-52 * c - 0x1p-1074);
        loop invariant EXACT(c > 0 ==> below <= c - 0x1p-1074);
        loop assigns c, below;
        loop variant \floor(c / 0x1p-1074); */
    while (c > 0.0 && refract_discriminant(s1, s2, below, 0) >= 0.0) {
        c = below;
        below = nextafter(c, 0.0);
    }
    /* The loop stopped at a c > 0 (c = 0 reflects) whose next cosine
     * down reflects. */
    /*@ assert crit_c: EXACT(c > 0); */
    /*@ assert crit_below: EXACT(snell_k(n1, n2, below) < 0); */
    /*@ assert crit_step: EXACT(0 <= step_below(c) <= below); */
    return c;
}

/* Two products rather than front + t (back - front): the endpoints are then
 * exact (1 * front + 0 * back, 0 * front + 1 * back). */
/*
 * a + b for colour channels a, b in [0, DBL_MAX], DBL_MAX where the sum
 * would pass it: [SHADE-SAT-1] without forming the infinity first.  Below
 * 2^1023 each, the sum cannot overflow; otherwise the halves are added
 * (exactly halved, as one of them is at least 2^1023 and the other's lost
 * bit is absorbed) and doubled back unless that passes DBL_MAX.
 */
/*@ requires \is_finite(a) && a >= 0 && \is_finite(b) && b >= 0;
    assigns \nothing;
    ensures \is_finite(\result) && \result >= 0;
    ensures EXACT(\result <= a + b);
    ensures EXACT(a + b <= DBL_MAX ==> \result == a + b); */
static real saturating_add(real a, real b)
{
    if (a < 0x1p1023 && b < 0x1p1023)
        return a + b;
    real h = 0.5 * a + 0.5 * b;
    return h <= 0.5 * DBL_MAX ? 2 * h : DBL_MAX;
}

/*@ requires vcolour(a) && vcolour(b);
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(\result.x <= a.x + b.x && \result.y <= a.y + b.y && \result.z <= a.z + b.z);
    ensures EXACT((a.x + b.x <= DBL_MAX ==> \result.x == a.x + b.x) && (a.y + b.y <= DBL_MAX ==> \result.y == a.y + b.y) &&
                  (a.z + b.z <= DBL_MAX ==> \result.z == a.z + b.z)); */
static rgb saturating_sum(rgb a, rgb b)
{
    return vec_make(saturating_add(a.x, b.x), saturating_add(a.y, b.y), saturating_add(a.z, b.z));
}

/*@ requires vcolour(front) && vcolour(back);
    requires \is_finite(t) && 0 <= t <= 1;   // [LANG-MAT-1]: t in [0, 1] (material_props)
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(blended(\result, front, back, t)); */
rgb shade_transmit_blend(rgb front, rgb back, real t)
{
    assert(t >= 0.0 && t <= 1.0);
    return saturating_sum(vec_scale(front, 1.0 - t), vec_scale(back, t));
}

/* Comparisons, not fmin: fmin(NaN, x) is x, and a NaN must stay visible. */
/*@ requires !\is_NaN(x);
    assigns \nothing;
    ensures \result <= DBL_MAX;
    ensures EXACT(\result == \min(x, DBL_MAX)); */
static real saturate1(real x) { return x > DBL_MAX ? DBL_MAX : x; }

/* The tracer passes sums that may have overflowed: defined for +Inf (and
 * for NaN, which it keeps); what is proved is the finite case. */
/*@ requires !\is_NaN(c.x) && !\is_NaN(c.y) && !\is_NaN(c.z);
    assigns \nothing;
    ensures \result.x <= DBL_MAX && \result.y <= DBL_MAX && \result.z <= DBL_MAX;
    ensures EXACT(vfinite(c) && c.x <= DBL_MAX && c.y <= DBL_MAX && c.z <= DBL_MAX ==> veq(\result, c)); */
rgb shade_saturate(rgb c)
{
    return vec_make(saturate1(c.x), saturate1(c.y), saturate1(c.z));
}

/*@ requires vcolour(body) && vcolour(highlight);
    requires \is_finite(t) && 0 <= t <= 1;
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(is_local(\result, body, highlight, t)); */
rgb shade_local(rgb body, rgb highlight, real t)
{
    assert(t >= 0.0 && t <= 1.0);
    return saturating_sum(highlight, vec_scale(body, 1.0 - t));
}

/* In line (HINT_IN_LINE_EXTERN; LTO carries it into trace.c): called out of line
 * its six colours went through the stack, three calls a glass point
 * (spec/performance.md, twenty-third round). */
/*@ requires vcolour(body) && vcolour(highlight) && vcolour(mirrored) && vcolour(transmitted);
    requires vin(ks, 0, 1);
    requires \is_finite(t) && 0 <= t <= 1;
    assigns \nothing;
    ensures vcolour(\result);
    ensures EXACT(is_combined(\result, body, highlight, ks, t, mirrored, transmitted)); */
HINT_IN_LINE_EXTERN rgb shade_combine(rgb body, rgb highlight, rgb ks, real t, rgb mirrored, rgb transmitted)
{
    rgb c = shade_local(body, highlight, t);
    c = saturating_sum(c, vec_mul(ks, mirrored));
    return saturating_sum(c, vec_scale(transmitted, t));
}

/*@ requires \is_finite(carried) && 0 <= carried <= 1;
    requires \is_finite(t_occluder) && 0 <= t_occluder <= 1;  // [LANG-MAT-1]: t in [0, 1]
    assigns \nothing;
    ensures 0 <= \result <= 1;
    ensures EXACT(\result == carried * t_occluder);
    ensures EXACT(t_occluder == 0 ==> \result == 0); */
real shade_shadow_transmission(real carried, real t_occluder)
{
    assert(carried >= 0.0 && carried <= 1.0);
    assert(t_occluder >= 0.0 && t_occluder <= 1.0);
    return carried * t_occluder;
}
