/*
 * Tests of src/render/shade.c, one TCase per function.  Statement IDs refer to
 * spec/shading.md.  Expected values are derived by hand (derivation in the
 * comment above each number) or by a route the code does not take: sines
 * from cross products of returned vectors, __float128 or exact rational
 * references for the critical angle.
 */
#include <float.h>
#include <math.h>
#include "testlib.h"
#include <quadmath.h>
#include "render/shade.h"


/* References are computed in __float128: software arithmetic, the same under
 * valgrind (which runs x87 long double at double precision). */
typedef __float128 quad;
static const double pi = 3.14159265358979323846;

static double rad(double deg) { return deg * (pi / 180.0); }

static int vec_same_bits(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* An orthonormal frame in general position, so that no product in the code
 * under test is exact by accident: f[2] = (0.36, -0.48, 0.8) is unit
 * (0.1296 + 0.2304 + 0.64 = 1); f[0], f[1] complete it right-handedly. */
static void general_frame(vec3 f[3])
{
    f[2] = vec_make(0.36, -0.48, 0.8);
    f[0] = vec_normalize(vec_cross(f[2], vec_make(1, 0, 0)));
    f[1] = vec_cross(f[2], f[0]);
}

/* a f0 + b f1 + c f2 */
static vec3 in_frame(const vec3 f[3], double a, double b, double c)
{
    return vec_madd(vec_madd(vec_scale(f[0], a), f[1], b), f[2], c);
}

/* A direction travelling into the surface of normal f[2] at angle deg from
 * the normal, in the f0-f2 plane. */
static vec3 incoming(const vec3 f[3], double deg)
{
    return in_frame(f, sin(rad(deg)), 0.0, -cos(rad(deg)));
}

/* ---- shade_ambient ------------------------------------------------------ */

/* [SHADE-AMBIENT-1] Dyadic values make the products exact:
 * 0.5*0.75 = 0.375, 0.25*2 = 0.5, 1*0.125 = 0.125. */
START_TEST(test_shade_ambient_is_kd_times_ia_per_channel)
{
    rgb got = shade_ambient(vec_make(0.5, 0.25, 1.0), vec_make(0.75, 2.0, 0.125));
    ck_assert(vec_same_bits(got, vec_make(0.375, 0.5, 0.125)));
    /* black reflects nothing, white reflects all (slide 11) */
    ck_assert(vec_same_bits(shade_ambient(vec_splat(0), vec_make(3, 4, 5)), vec_splat(0)));
    ck_assert(vec_same_bits(shade_ambient(vec_splat(1), vec_make(3, 4, 5)), vec_make(3, 4, 5)));
}
END_TEST

/* ---- shade_falloff ------------------------------------------------------ */

/* [SHADE-FALLOFF-1,2,3] E = (10,20,30), d = 3, d0 = 2: d + d0 = 5;
 * linear E/5 = (2,4,6); inverse square E/25 with E = (50,25,100) = (2,1,4);
 * none: E whatever d. */
START_TEST(test_shade_falloff_known_values)
{
    ck_assert_vec_near(shade_falloff(vec_make(10, 20, 30), 3, 2, FALLOFF_LINEAR),
                       vec_make(2, 4, 6), 0);
    ck_assert_vec_near(shade_falloff(vec_make(50, 25, 100), 3, 2, FALLOFF_INVERSE_SQUARE),
                       vec_make(2, 1, 4), 0);
    ck_assert(vec_same_bits(shade_falloff(vec_make(0.1, 0.2, 0.3), 1e9, 7, FALLOFF_NONE),
                            vec_make(0.1, 0.2, 0.3)));
    /* d0 = 0 is the plain 1/d and 1/d^2 of slide 16: 12/4 = 3, 12/16 = 0.75 */
    ck_assert_near(shade_falloff(vec_splat(12), 4, 0, FALLOFF_LINEAR).y, 3.0, 0);
    ck_assert_near(shade_falloff(vec_splat(12), 4, 0, FALLOFF_INVERSE_SQUARE).y, 0.75, 0);
}
END_TEST

/* [SHADE-FALLOFF-4] d -> 0: E/d0 and E/d0^2.  d = 1e-300 vanishes next to
 * d0 = 0.5 (1e-300 < ulp(0.5)/2), so the limits are reached exactly:
 * 3/0.5 = 6, 3/0.25 = 12. */
START_TEST(test_shade_falloff_limit_at_the_light)
{
    for (int i = 0; i < 2; i++) {
        double d = i == 0 ? 0.0 : 1e-300;
        ck_assert_near(shade_falloff(vec_splat(3), d, 0.5, FALLOFF_LINEAR).x, 6.0, 0);
        ck_assert_near(shade_falloff(vec_splat(3), d, 0.5, FALLOFF_INVERSE_SQUARE).x, 12.0, 0);
    }
}
END_TEST

/* [SHADE-FALLOFF-4] d -> infinity: I -> 0 with the right rate.
 * Linear: d I / E = d/(d + d0) = 1 - d0/(d + d0), so d I -> E and the
 * deficit is d0/(d + d0).  Inverse square: d^2 I / E = (d/(d + d0))^2
 * = 1 - 2 d0/d + O(1/d^2). */
START_TEST(test_shade_falloff_limit_far_away)
{
    static const double ds[] = {1e2, 1e4, 1e6, 1e9, 1e12};
    double d0 = 1.5, e = 7.0;
    for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++) {
        double d = ds[i];
        double lin = shade_falloff(vec_splat(e), d, d0, FALLOFF_LINEAR).x;
        double sq = shade_falloff(vec_splat(e), d, d0, FALLOFF_INVERSE_SQUARE).z;
        ck_assert_rel(1.0 - d * lin / e, d0 / (d + d0), 1e-4);
        ck_assert_rel(1.0 - d * d * sq / e, 2 * d0 / d, 2 * d0 / d + 1e-4);
        ck_assert(lin > 0 && sq > 0 && sq < lin);
    }
    ck_assert_near(shade_falloff(vec_splat(e), INFINITY, d0, FALLOFF_LINEAR).x, 0.0, 0);
}
END_TEST

/* [SHADE-FALLOFF-5] Defensive: d + d0 <= 0 or NaN returns E; an overflow is
 * clamped to DBL_MAX: 1/(1e-200)^2 = 1e400 > DBL_MAX. */
START_TEST(test_shade_falloff_defensive_cases)
{
    rgb e = vec_make(1, 2, 3);
    static const scene_falloff kinds[] = {FALLOFF_LINEAR, FALLOFF_INVERSE_SQUARE};
    for (int k = 0; k < 2; k++) {
        ck_assert(vec_same_bits(shade_falloff(e, 0, 0, kinds[k]), e));
        ck_assert(vec_same_bits(shade_falloff(e, -1, 0.5, kinds[k]), e));
        ck_assert(vec_same_bits(shade_falloff(e, NAN, 0.5, kinds[k]), e));
    }
    rgb huge = shade_falloff(vec_make(1, 0, 1), 1e-200, 0, FALLOFF_INVERSE_SQUARE);
    ck_assert(vec_is_finite(huge));
    ck_assert(huge.x == DBL_MAX && huge.y == 0.0);
    /* Finite means a black channel stays black: 0 * DBL_MAX = 0, not NaN. */
    ck_assert(vec_same_bits(vec_mul(vec_splat(0), huge), vec_splat(0)));
}
END_TEST

/* ---- shade_sample_power ------------------------------------------------- */

/* [SHADE-SAMPLE-1] E/samples: (3,6,9)/3 = (1,2,3); 1 sample keeps E; the samples add back
 * to E (to rounding: 7 is not a power of two). */
START_TEST(test_shade_sample_power_splits_evenly)
{
    ck_assert_vec_near(shade_sample_power(vec_make(3, 6, 9), 3), vec_make(1, 2, 3), 0);
    ck_assert(vec_same_bits(shade_sample_power(vec_make(0.3, 0.7, 1.1), 1), vec_make(0.3, 0.7, 1.1)));
    rgb sum = vec_splat(0), part = shade_sample_power(vec_make(0.3, 0.7, 1.1), 7);
    for (int i = 0; i < 7; i++)
        sum = vec_add(sum, part);
    ck_assert_vec_near(sum, vec_make(0.3, 0.7, 1.1), 4 * DBL_EPSILON);
}
END_TEST

/* ---- shade_face_forward ------------------------------------------------- */

/* [SHADE-FACE-1] */
START_TEST(test_shade_face_forward_turns_toward_viewer)
{
    vec3 n = vec_make(0.36, -0.48, 0.8);
    ck_assert(vec_same_bits(shade_face_forward(n, vec_make(0, 0, 1)), n));
    ck_assert(vec_same_bits(shade_face_forward(n, vec_make(0, 0, -1)), vec_neg(n)));
    /* edge-on, n.v = 0 exactly: n is kept */
    vec3 e = vec_make(0, 0, 1);
    ck_assert(vec_same_bits(shade_face_forward(e, vec_make(1, 0, 0)), e));
}
END_TEST

/* ---- shade_lambert ------------------------------------------------------ */

/* [SHADE-LAMBERT-2] N = z, L at 60 deg in the xz plane: N.L = 0*x + 0*0 +
 * 1*0.5 = 0.5 exactly (slide 13: cos 60 = 1/2).  Normal incidence: 1. */
START_TEST(test_shade_lambert_cosine_law_exact)
{
    vec3 n = vec_make(0, 0, 1);
    ck_assert(shade_lambert(n, vec_make(sin(rad(60)), 0, 0.5)) == 0.5);
    ck_assert(shade_lambert(n, n) == 1.0);
}
END_TEST

/* [SHADE-LAMBERT-2] In a general frame: cos of the angle used to build L. */
START_TEST(test_shade_lambert_cosine_law_sweep)
{
    vec3 f[3];
    general_frame(f);
    for (int deg = 0; deg < 90; deg += 5) {
        vec3 l = in_frame(f, sin(rad(deg)), 0, cos(rad(deg)));
        ck_assert_near(shade_lambert(f[2], l), cos(rad(deg)), 4 * DBL_EPSILON);
    }
}
END_TEST

/* [SHADE-LAMBERT-1] Exactly 0 at the horizon and below; clamped to 1. */
START_TEST(test_shade_lambert_zero_at_and_below_horizon)
{
    vec3 n = vec_make(0, 0, 1);
    ck_assert(shade_lambert(n, vec_make(1, 0, 0)) == 0.0);
    ck_assert(shade_lambert(n, vec_make(0.6, 0, -0.8)) == 0.0);
    ck_assert(shade_lambert(n, vec_make(0, 0, -1)) == 0.0);
    ck_assert(shade_lambert(n, vec_make(0, 0, 0)) == 0.0);
    ck_assert(shade_lambert(n, vec_make(NAN, 0, 1)) == 0.0);
    /* (1 + 2^-52)^2 rounds to 1 + 2^-51 > 1: a cosine above 1 is rounding */
    vec3 over = vec_make(0, 0, 1 + DBL_EPSILON);
    ck_assert(shade_lambert(over, over) == 1.0);
}
END_TEST

/* ---- shade_diffuse ------------------------------------------------------ */

/* [SHADE-DIFFUSE-1] Kd = (0.5, 0.25, 1), I = (2, 4, 8), 60 deg: Kd I =
 * (1, 1, 8), times cos 60 = 0.5: (0.5, 0.5, 4).  k_d, not slide 19's k_s. */
START_TEST(test_shade_diffuse_known_value)
{
    vec3 n = vec_make(0, 0, 1), l = vec_make(sin(rad(60)), 0, 0.5);
    rgb got = shade_diffuse(vec_make(0.5, 0.25, 1), vec_make(2, 4, 8), n, l);
    ck_assert(vec_same_bits(got, vec_make(0.5, 0.5, 4)));
    ck_assert(vec_same_bits(shade_diffuse(vec_splat(1), vec_splat(1), n, vec_make(0.6, 0, -0.8)),
                            vec_splat(0)));
}
END_TEST

/* ---- shade_reflect_about ------------------------------------------------ */

/* [SHADE-REFLECT-1] N = y, L = (0.6, 0.8, 0): N.L = 0.8, 2(N.L)N = (0, 1.6, 0),
 * minus L: (-0.6, 0.8, 0) (1.6 - 0.8 is exact).  L = N gives N. */
START_TEST(test_shade_reflect_about_known_value)
{
    vec3 n = vec_make(0, 1, 0);
    ck_assert(vec_same_bits(shade_reflect_about(vec_make(0.6, 0.8, 0), n), vec_make(-0.6, 0.8, 0)));
    ck_assert(vec_same_bits(shade_reflect_about(n, n), n));
}
END_TEST

/* [SHADE-REFLECT-1] Unit, angle in = angle out, coplanar with N and L, the
 * part along the surface negated; the mirror of -L (bit for bit). */
START_TEST(test_shade_reflect_about_identities)
{
    vec3 f[3];
    general_frame(f);
    vec3 n = f[2];
    for (int deg = 0; deg <= 90; deg += 3) {
        vec3 l = in_frame(f, sin(rad(deg)) * 0.6, sin(rad(deg)) * 0.8, cos(rad(deg)));
        vec3 r = shade_reflect_about(l, n);
        ck_assert_near(vec_length(r), 1.0, 8 * DBL_EPSILON);
        ck_assert_near(vec_dot(n, r), vec_dot(n, l), 4 * DBL_EPSILON);
        ck_assert_near(vec_dot(r, vec_cross(n, l)), 0.0, 8 * DBL_EPSILON);
        vec3 r_along = vec_madd(r, n, -vec_dot(n, r)), l_along = vec_madd(l, n, -vec_dot(n, l));
        ck_assert_vec_near(r_along, vec_neg(l_along), 8 * DBL_EPSILON);
        ck_assert(vec_same_bits(vec_neg(r), shade_mirror(l, n)));
    }
}
END_TEST

/* ---- shade_mirror ------------------------------------------------------- */

/* [SHADE-MIRROR-1] D = (0.6, -0.8, 0) onto the floor N = y bounces to
 * (0.6, 0.8, 0): -2 N.D = 1.6, -0.8 + 1.6 = 0.8 exactly. */
START_TEST(test_shade_mirror_known_value)
{
    vec3 got = shade_mirror(vec_make(0.6, -0.8, 0), vec_make(0, 1, 0));
    ck_assert(vec_same_bits(got, vec_make(0.6, 0.8, 0)));
}
END_TEST

/* [SHADE-MIRROR-1] Length kept, angle in = angle out (N.M = -N.D), coplanar,
 * the part along the surface kept, either sign of N, twice = identity. */
START_TEST(test_shade_mirror_identities)
{
    vec3 f[3];
    general_frame(f);
    vec3 n = f[2];
    for (int deg = 0; deg <= 90; deg += 3) {
        vec3 d = in_frame(f, sin(rad(deg)) * 0.8, -sin(rad(deg)) * 0.6, -cos(rad(deg)));
        vec3 m = shade_mirror(d, n);
        ck_assert_near(vec_length(m), vec_length(d), 8 * DBL_EPSILON);
        ck_assert_near(vec_dot(n, m), -vec_dot(n, d), 4 * DBL_EPSILON);
        ck_assert_near(vec_dot(m, vec_cross(n, d)), 0.0, 8 * DBL_EPSILON);
        vec3 m_along = vec_madd(m, n, -vec_dot(n, m)), d_along = vec_madd(d, n, -vec_dot(n, d));
        ck_assert_vec_near(m_along, d_along, 8 * DBL_EPSILON);
        ck_assert(vec_same_bits(shade_mirror(d, vec_neg(n)), m));
        ck_assert_vec_near(shade_mirror(m, n), d, 8 * DBL_EPSILON);
    }
}
END_TEST

/* ---- shade_phong_lobe --------------------------------------------------- */

/* [SHADE-PHONG-1] Peak: V = R gives exactly 1 for any exponent. */
START_TEST(test_shade_phong_lobe_peak_is_one)
{
    static const double ns[] = {0, 1, 2.5, 150, 1e6, 1e300};
    vec3 r = vec_make(0, 0, 1);
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++)
        ck_assert(shade_phong_lobe(r, r, ns[i]) == 1.0);
}
END_TEST

/* [SHADE-PHONG-1] R = z, V at 60 deg: V.R = 0.5 exactly; 0.5^1 = 0.5,
 * 0.5^2 = 0.25, 0.5^10 = 1/1024, 0.5^0.5 = sqrt(1/2). */
START_TEST(test_shade_phong_lobe_known_values)
{
    vec3 r = vec_make(0, 0, 1), v = vec_make(sin(rad(60)), 0, 0.5);
    ck_assert(shade_phong_lobe(v, r, 1) == 0.5);
    ck_assert(shade_phong_lobe(v, r, 2) == 0.25);
    ck_assert(shade_phong_lobe(v, r, 10) == 1.0 / 1024);
    ck_assert_near(shade_phong_lobe(v, r, 0.5), sqrt(0.5), DBL_EPSILON);
}
END_TEST

/* [SHADE-PHONG-2] Symmetric about R: V at +phi and -phi, in two planes
 * through R, give identical bits (R = z makes V.R = cos phi in each case);
 * in a general frame V turned about R by any angle gives the same value. */
START_TEST(test_shade_phong_lobe_symmetric_about_r)
{
    vec3 r = vec_make(0, 0, 1);
    for (int deg = 1; deg < 90; deg += 7) {
        double s = sin(rad(deg)), c = cos(rad(deg));
        real ref = shade_phong_lobe(vec_make(s, 0, c), r, 7.5);   /* not rounded to double */
        ck_assert(shade_phong_lobe(vec_make(-s, 0, c), r, 7.5) == ref);
        ck_assert(shade_phong_lobe(vec_make(0, s, c), r, 7.5) == ref);
        ck_assert(shade_phong_lobe(vec_make(0, -s, c), r, 7.5) == ref);
    }
    vec3 f[3];
    general_frame(f);
    double s = sin(rad(20)), c = cos(rad(20));
    double ref = shade_phong_lobe(in_frame(f, s, 0, c), f[2], 40);
    for (int psi = 0; psi < 360; psi += 30) {
        vec3 v = in_frame(f, s * cos(rad(psi)), s * sin(rad(psi)), c);
        ck_assert_rel(shade_phong_lobe(v, f[2], 40), ref, 1e-13);
    }
}
END_TEST

/* [SHADE-PHONG-2] Decreasing in the angle phi between V and R; for n = 1 it
 * is cos phi itself (slide 26). */
START_TEST(test_shade_phong_lobe_decreasing_in_angle)
{
    static const double ns[] = {1, 10, 150};
    vec3 f[3];
    general_frame(f);
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++) {
        double prev = 2.0;
        for (int deg = 0; deg < 90; deg++) {
            double got = shade_phong_lobe(in_frame(f, sin(rad(deg)), 0, cos(rad(deg))), f[2], ns[i]);
            ck_assert_msg(got < prev || (got == 0 && prev == 0), "n=%g deg=%d", ns[i], deg);
            if (ns[i] == 1)
                ck_assert_near(got, cos(rad(deg)), 4 * DBL_EPSILON);
            prev = got;
        }
    }
}
END_TEST

/* [SHADE-PHONG-3] n = 0: 1 wherever V.R > 0, however small; 0 at and
 * behind 90 degrees (the seed's cos^0 = 1 would light the back too). */
START_TEST(test_shade_phong_lobe_exponent_zero)
{
    vec3 r = vec_make(0, 0, 1);
    ck_assert(shade_phong_lobe(vec_make(0.6, 0, 0.8), r, 0) == 1.0);
    ck_assert(shade_phong_lobe(vec_make(1, 0, 1e-300), r, 0) == 1.0);
    ck_assert(shade_phong_lobe(vec_make(1, 0, 0), r, 0) == 0.0);
    ck_assert(shade_phong_lobe(vec_make(0.6, 0, -0.8), r, 0) == 0.0);
    ck_assert(shade_phong_lobe(vec_make(0.6, 0, -0.8), r, 3) == 0.0);
    ck_assert(shade_phong_lobe(vec_make(NAN, 0, 1), r, 3) == 0.0);
}
END_TEST

/* [SHADE-PHONG-4] Large exponents: 0.999^1e6 = exp(1e6 ln 0.999) ~ e^-1000.5
 * underflows: exactly 0, no NaN, no subnormal; over a sweep every value is
 * 0 or a normal number in [0, 1].  Near the peak the value is accurate:
 * V.R = c = 1 - 1e-12 (to 5.6e-17, the ulp of 1/2 below 1), n = 1e6:
 * c^n = exp(n ln(1 - x)) = exp(-n x - n x^2/2 ...) = exp(-1e-6) to about
 * 6e-11 relative (the representation error of c times n). */
START_TEST(test_shade_phong_lobe_large_exponents)
{
    vec3 r = vec_make(0, 0, 1);
    double c = 0.999;
    ck_assert(shade_phong_lobe(vec_make(sqrt(1 - c * c), 0, c), r, 1e6) == 0.0);
    static const double ns[] = {1e3, 7e4, 1e6, 1e9, 1e300};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++)
        for (double cc = 0.5; cc < 1.0; cc = 0.5 * (cc + 1.0)) {
            double got = shade_phong_lobe(vec_make(sqrt(1 - cc * cc), 0, cc), r, ns[i]);
            int cls = fpclassify(got);
            ck_assert_msg(cls == FP_ZERO || (cls == FP_NORMAL && got <= 1.0), "n=%g c=%.17g: %g",
                          ns[i], cc, got);
        }
    c = 1 - 1e-12;
    ck_assert_rel(shade_phong_lobe(vec_make(sqrt(1 - c * c), 0, c), r, 1e6), exp(-1e-6), 1e-9);
    /* V.R = 0.5 exactly (60 deg): 0.5^1000 = 2^-1000 is normal and exact;
     * 0.5^1050 = 2^-1050 is subnormal (DBL_MIN = 2^-1022): flushed to 0. */
    vec3 v60 = vec_make(sin(rad(60)), 0, 0.5);
    ck_assert(shade_phong_lobe(v60, r, 1000) == ldexp(1.0, -1000));
    ck_assert(shade_phong_lobe(v60, r, 1050) == 0.0);
}
END_TEST

/* [SHADE-PHONG-4] V.R slightly > 1 from rounding is clamped: with
 * V = R = (1 + 2^-52) x, V.R = 1 + 2^-51 (the 2^-104 rounds off), and
 * (1 + 2^-51)^1e6 would be 1 + 4.4e-10; the lobe is exactly 1. */
START_TEST(test_shade_phong_lobe_clamps_rounding_above_one)
{
    vec3 v = vec_make(1 + DBL_EPSILON, 0, 0);
    ck_assert(vec_dot(v, v) > 1.0);
    ck_assert(shade_phong_lobe(v, v, 1e6) == 1.0);
    ck_assert(shade_phong_lobe(v, v, 1) == 1.0);
}
END_TEST

/* ---- shade_specular ----------------------------------------------------- */

/* [SHADE-PHONG-1] [SHADE-SPEC-1] N = y, L = (0.6, 0.8, 0): R = (-0.6, 0.8, 0)
 * (hand-derived above).  Viewed along R the highlight is Ks*I exactly:
 * 0.6^2 + 0.8^2 rounds to 1 in double (checked here), the lobe is 1. */
START_TEST(test_shade_specular_peak_is_ks_times_i)
{
    vec3 n = vec_make(0, 1, 0), l = vec_make(0.6, 0.8, 0), v = vec_make(-0.6, 0.8, 0);
    ck_assert(vec_dot(v, v) >= 1.0);
    rgb ks = vec_make(0.3, 0.7, 0.9), in = vec_make(1.7, 0.2, 5.0);
    static const double ns[] = {0, 1, 20, 1e6};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++)
        ck_assert(vec_same_bits(shade_specular(ks, in, v, n, l, ns[i]), vec_mul(ks, in)));
    /* normal incidence, viewed head on */
    ck_assert(vec_same_bits(shade_specular(ks, in, n, n, n, 150), vec_mul(ks, in)));
}
END_TEST

/* [SHADE-SPEC-1] Ks = (0.5, 1, 0.25), I = (2, 2, 4), N = L = z, so R = z;
 * V at 60 deg: V.R = 0.5, n = 3: 0.125; Ks I = (1, 2, 1) -> (0.125, 0.25, 0.125). */
START_TEST(test_shade_specular_known_value)
{
    vec3 z = vec_make(0, 0, 1), v = vec_make(sin(rad(60)), 0, 0.5);
    rgb got = shade_specular(vec_make(0.5, 1, 0.25), vec_make(2, 2, 4), v, z, z, 3);
    ck_assert(vec_same_bits(got, vec_make(0.125, 0.25, 0.125)));
}
END_TEST

/* [SHADE-SPEC-1] Light at or below the horizon: no highlight, even where
 * V = R would give the full lobe (L = (0.6, -0.8, 0), N = y:
 * R = 2(-0.8)y - L = (-0.6, -0.8, 0)). */
START_TEST(test_shade_specular_zero_unless_light_in_front)
{
    vec3 n = vec_make(0, 1, 0);
    rgb one = vec_splat(1);
    vec3 l = vec_make(0.6, -0.8, 0), v = vec_make(-0.6, -0.8, 0);
    ck_assert(shade_phong_lobe(v, shade_reflect_about(l, n), 5) == 1.0);
    ck_assert(vec_same_bits(shade_specular(one, one, v, n, l, 5), vec_splat(0)));
    l = vec_make(1, 0, 0);
    ck_assert(vec_same_bits(shade_specular(one, one, vec_make(-1, 0, 0), n, l, 0), vec_splat(0)));
}
END_TEST

/* ---- shade_direct ------------------------------------------------------- */

/* [SHADE-DIRECT-1] Kd = 0.5, Ks = 0.25, I = 4, N = z, L at 60 deg in xz,
 * V = z.  Body: 0.5 * 4 * cos 60 = 1.  R = 2 (0.5) z - L = (-sin 60, 0, 0.5),
 * V.R = 0.5, n = 2: 0.25; highlight 0.25 * 4 * 0.25 = 0.25. */
START_TEST(test_shade_direct_known_value)
{
    vec3 z = vec_make(0, 0, 1), l = vec_make(sin(rad(60)), 0, 0.5);
    shade_terms s = shade_direct(vec_splat(0.5), vec_splat(0.25), 2, vec_splat(4), z, l, z);
    ck_assert(vec_same_bits(s.body, vec_splat(1)));
    ck_assert(vec_same_bits(s.highlight, vec_splat(0.25)));
}
END_TEST

/* [SHADE-DIRECT-1] The parts are shade_diffuse and shade_specular; both 0
 * for a light behind; a shadow factor S in the intensity scales both
 * (0.25 is a power of two: exactly). */
START_TEST(test_shade_direct_parts_and_shadow_scaling)
{
    vec3 f[3];
    general_frame(f);
    vec3 n = f[2], l = in_frame(f, 0.6, 0, 0.8), v = in_frame(f, -0.28, 0.48, 0.83);
    rgb kd = vec_make(0.9, 0.5, 0.1), ks = vec_make(0.2, 0.4, 0.6), in = vec_make(3, 2, 1);
    shade_terms s = shade_direct(kd, ks, 12, in, n, l, v);
    ck_assert(vec_same_bits(s.body, shade_diffuse(kd, in, n, l)));
    ck_assert(vec_same_bits(s.highlight, shade_specular(ks, in, v, n, l, 12)));
    ck_assert(s.highlight.x > 0);
    shade_terms q = shade_direct(kd, ks, 12, vec_scale(in, 0.25), n, l, v);
    ck_assert(vec_same_bits(q.body, vec_scale(s.body, 0.25)));
    ck_assert(vec_same_bits(q.highlight, vec_scale(s.highlight, 0.25)));
    shade_terms b = shade_direct(kd, ks, 12, in, n, vec_neg(l), v);
    ck_assert(vec_same_bits(b.body, vec_splat(0)) && vec_same_bits(b.highlight, vec_splat(0)));
}
END_TEST

/* ---- shade_refract ------------------------------------------------------ */

typedef struct ior_pair {
    double n1, n2;
} ior_pair;

static const ior_pair snell_pairs[] = {
    {1.0, 1.5}, {1.5, 1.0}, {1.0, 1.333}, {1.333, 1.0}, {1.0, 2.42}, {2.42, 1.0},
    {1.5, 1.7}, {1.7, 1.5}, {1.0, 1.0001}, {1.0001, 1.0}, {1.33, 1.5}, {1.25, 1.0},
};

/* [SHADE-SNELL-1] Over angles 0..90 and the pairs above, in a general frame:
 * n1 sin th1 = n2 sin th2 with both sines measured as |x X n| of the vectors
 * (d as given, t as returned); t is unit, coplanar with d and n, goes
 * through (t.n < 0) and keeps d's side along the surface.  TIR exactly when
 * (n1/n2) sin th1 > 1 (angles within 1e-9 of critical are left to the
 * critical-angle test). */
START_TEST(test_shade_refract_snell_sweep)
{
    vec3 f[3];
    general_frame(f);
    vec3 n = f[2];
    for (size_t p = 0; p < sizeof snell_pairs / sizeof snell_pairs[0]; p++) {
        double n1 = snell_pairs[p].n1, n2 = snell_pairs[p].n2;
        for (double deg = 0; deg <= 90.0; deg += 0.5) {
            vec3 d = incoming(f, deg), t = vec_make(0, 0, 0);
            double s1 = vec_length(vec_cross(d, n)), x = n1 / n2 * sin(rad(deg));
            int ok = shade_refract(d, n, n1, n2, &t);
            if (fabs(x - 1.0) < 1e-9)
                continue;
            ck_assert_msg(ok == (x < 1.0), "n1=%g n2=%g deg=%g ok=%d", n1, n2, deg, ok);
            if (!ok)
                continue;
            double s2 = vec_length(vec_cross(t, n));
            ck_assert_near(n1 * s1, n2 * s2, 1e-14 * n1);
            ck_assert_near(vec_length(t), 1.0, 4 * DBL_EPSILON);
            ck_assert_near(vec_dot(t, vec_cross(d, n)), 0.0, 4 * DBL_EPSILON);
            ck_assert(vec_dot(t, n) < 0.0);
            ck_assert(vec_dot(vec_cross(t, n), vec_cross(d, n)) >= 0.0);
        }
    }
}
END_TEST

/* [SHADE-SNELL-1] Hand-derived: N = y, D = (0.8, -0.6, 0) (sin 0.8, cos 0.6).
 * Air into n2 = 1.6: sin th2 = 0.8/1.6 = 0.5, cos th2 = sqrt(3)/2:
 * T = (0.5, -sqrt(3)/2, 0).  Out of n1 = 1.25 into air with D = (0.6, -0.8, 0):
 * sin th2 = 1.25 * 0.6 = 0.75, cos th2 = sqrt(1 - 9/16) = sqrt(7)/4. */
START_TEST(test_shade_refract_known_values)
{
    vec3 n = vec_make(0, 1, 0), t;
    ck_assert_int_eq(shade_refract(vec_make(0.8, -0.6, 0), n, 1.0, 1.6, &t), 1);
    ck_assert_vec_near(t, vec_make(0.5, -sqrt(3.0) / 2, 0), 2 * DBL_EPSILON);
    ck_assert_int_eq(shade_refract(vec_make(0.6, -0.8, 0), n, 1.25, 1.0, &t), 1);
    ck_assert_vec_near(t, vec_make(0.75, -sqrt(7.0) / 4, 0), 2 * DBL_EPSILON);
    /* normal incidence goes straight through, either way */
    ck_assert_int_eq(shade_refract(vec_make(0, -1, 0), n, 1.5, 1.0, &t), 1);
    ck_assert_vec_near(t, vec_make(0, -1, 0), 0);
    ck_assert_int_eq(shade_refract(vec_make(0, -1, 0), n, 1.0, 2.42, &t), 1);
    ck_assert_vec_near(t, vec_make(0, -1, 0), 0);
}
END_TEST

/* [SHADE-SNELL-3] n1 == n2: d comes back bit for bit, even at angles where
 * the general formula would round. */
START_TEST(test_shade_refract_equal_indices_keep_bits)
{
    vec3 f[3];
    general_frame(f);
    static const double iors[] = {1.0, 1.5, 2.42, 1e-3, 1e3};
    for (size_t i = 0; i < sizeof iors / sizeof iors[0]; i++)
        for (double deg = 0; deg <= 90.0; deg += 7.5) {
            vec3 d = incoming(f, deg), t = vec_make(0, 0, 0);
            ck_assert_int_eq(shade_refract(d, f[2], iors[i], iors[i], &t), 1);
            ck_assert(vec_same_bits(t, d));
        }
}
END_TEST

/* [SHADE-SNELL-2] On TIR the function returns 0 and gives the mirror
 * direction.  Grazing out of glass (n1 = 1.5) into air always reflects. */
START_TEST(test_shade_refract_tir_reports_and_mirrors)
{
    vec3 f[3];
    general_frame(f);
    for (double deg = 45; deg <= 90.0; deg += 5) {
        vec3 d = incoming(f, deg), t = vec_make(0, 0, 0);
        ck_assert_int_eq(shade_refract(d, f[2], 1.5, 1.0, &t), 0);
        ck_assert(vec_same_bits(t, shade_mirror(d, f[2])));
    }
    vec3 t;
    ck_assert_int_eq(shade_refract(vec_make(1, 0, 0), vec_make(0, 1, 0), 1.0001, 1.0, &t), 0);
}
END_TEST

/* d in the xy plane with cos th1 = c exactly against N = y: N.D = -c with
 * no rounding (the other products are by 0). */
static vec3 incoming_with_cos(double c)
{
    return vec_make(sqrt(1.0 - c * c), -c, 0);
}

/* Sign of the discriminant (n1 c)^2 - (n1 - n2)(n1 + n2), in __float128.
 * n1 - n2 and n1 + n2 are exact there (54 bits at most), each product of
 * doubles is rounded once to 113 bits: both sides carry a relative error of
 * about 2^-112, far below the relative margin 2 * 2^-54 that one double ulp
 * of c gives.  (Not n1^2 - n2^2: for n1 = 1 + 1e-12 that difference loses
 * everything to the rounding of n1^2.) */
static int ld_refracts(double n1, double n2, double c)
{
    /* Both sides are of degree 2 in (n1, n2): scaling them by the same power
     * of two is exact and keeps the __float128 arithmetic near 1 (valgrind
     * mishandles its extreme exponents). */
    int e = ilogb(n1);
    n1 = ldexp(n1, -e);
    n2 = ldexp(n2, -e);
    quad a = (quad)n1 * c;
    quad b = ((quad)n1 - n2) * ((quad)n1 + n2);
    return a * a > b;
}

/* [SHADE-SNELL-2] [SHADE-CRIT-1] The critical cosine splits refraction from
 * TIR to the last bit.  The reference c* = sqrt((n1 - n2)(n1 + n2))/n1 is
 * computed in __float128 and rounded to the nearest double; the doubles
 * one ulp on either side are checked to lie strictly on either side of the
 * true critical cosine (ld_refracts), then cos th1 one ulp above c* must
 * refract (angle just below critical) and one ulp below must reflect. */
START_TEST(test_shade_refract_critical_split_is_exact)
{
    static const ior_pair pairs[] = {
        {1.5, 1.0}, {1.333, 1.0}, {2.42, 1.0}, {1.0001, 1.0}, {1.7, 1.5},
        {1.5, 1.33}, {1.0 + 1e-12, 1.0}, {4.0, 1.0}, {1e6, 1.0}, {1.25, 1.0},
        {1.09398, 1.0}, {1.12839, 1.0}, {1e200, 3e199}, {1e-200, 3e-201},
    };
    vec3 n = vec_make(0, 1, 0), t;
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++) {
        double n1 = pairs[p].n1, n2 = pairs[p].n2;
        quad ln1 = ldexp(n1, -ilogb(n1)), ln2 = ldexp(n2, -ilogb(n1));
        double cc = (double)(sqrtq((ln1 - ln2) * (ln1 + ln2)) / ln1);
        double above = nextafter(cc, 2.0), below = nextafter(cc, 0.0);
        ck_assert(ld_refracts(n1, n2, above) && !ld_refracts(n1, n2, below));
        ck_assert_msg(shade_refract(incoming_with_cos(above), n, n1, n2, &t) == 1,
                      "n1=%.17g n2=%.17g c=%.17g should refract", n1, n2, above);
        ck_assert_msg(shade_refract(incoming_with_cos(below), n, n1, n2, &t) == 0,
                      "n1=%.17g n2=%.17g c=%.17g should reflect", n1, n2, below);
        ck_assert(vec_dot(t, n) > 0);
    }
}
END_TEST

/* [SHADE-SNELL-4] Accuracy of cos th2 near the critical angle, where the
 * textbook sqrt(1 - eta^2 (1 - c^2)) has an absolute error of ~1e-16 under
 * the root, i.e. ~1e-8 in a cos th2 of ~1e-8.  Pairs with a rational
 * critical cosine p/q give an exact reference:
 *   n2^2 cos^2 th2 = n1^2 (c^2 - (p/q)^2) = (n1/q)^2 (q c - p)(q c + p),
 * where q c has at most 57 bits, so q c - p is exact in __float128.
 *   n1 = 1.25, n2 = 1: sin th_c = 0.8, cos th_c = 3/5;
 *   n1 = 5, n2 = 3: cos th_c = 4/5;  n1 = 13, n2 = 12: cos th_c = 5/13. */
START_TEST(test_shade_refract_accurate_near_critical)
{
    static const struct { double n1, n2, p, q; } cases[] = {
        {1.25, 1.0, 3, 5}, {5.0, 3.0, 4, 5}, {13.0, 12.0, 5, 13}, {1.625, 1.5, 5, 13},
    };
    static const int ulps[] = {1, 2, 5, 100, 100000};
    vec3 n = vec_make(0, 1, 0);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double c = nextafter(cases[i].p / cases[i].q, 0.0);
        while ((quad)cases[i].q * c - cases[i].p <= 0)
            c = nextafter(c, 2.0);
        for (int step = 0, k = 0; k < (int)(sizeof ulps / sizeof ulps[0]); k++) {
            for (; step < ulps[k] - 1; step++)
                c = nextafter(c, 2.0);
            quad qc = (quad)cases[i].q * c;
            quad k2 = (qc - cases[i].p) * (qc + cases[i].p);
            double want = (double)(sqrtq(k2) * cases[i].n1 / cases[i].q / cases[i].n2);
            vec3 t;
            ck_assert_int_eq(shade_refract(incoming_with_cos(c), n, cases[i].n1, cases[i].n2, &t), 1);
            ck_assert_rel(-t.y, want, 1e-13);
        }
    }
}
END_TEST

/* [SHADE-SNELL-4] Near and at grazing incidence into a denser medium:
 * n1 = 1, n2 = 1.25, th1 -> 90 deg: sin th2 -> 0.8, cos th2 -> 0.6; in
 * general sin th2 = 0.8 sin th1 (Snell, measured from the vectors). */
START_TEST(test_shade_refract_accurate_near_grazing)
{
    vec3 n = vec_make(0, 1, 0), t;
    ck_assert_int_eq(shade_refract(vec_make(1, 0, 0), n, 1.0, 1.25, &t), 1);
    ck_assert_vec_near(t, vec_make(0.8, -0.6, 0), 2 * DBL_EPSILON);
    static const double cs[] = {1e-300, 1e-200, 1e-16, 1e-12, 1e-8, 1e-4};
    for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        vec3 d = incoming_with_cos(cs[i]);
        ck_assert_int_eq(shade_refract(d, n, 1.0, 1.25, &t), 1);
        ck_assert_rel(vec_length(vec_cross(t, n)), 0.8 * vec_length(vec_cross(d, n)), 4 * DBL_EPSILON);
        ck_assert_near(vec_length(t), 1.0, 4 * DBL_EPSILON);
    }
    /* a hair of positive N.D (rounding) is treated as grazing, not an error */
    ck_assert_int_eq(shade_refract(vec_make(1, 1e-17, 0), n, 1.0, 1.25, &t), 1);
    ck_assert_vec_near(t, vec_make(0.8, -0.6, 0), 2 * DBL_EPSILON);
}
END_TEST

/* [SHADE-SNELL-4] Extreme but finite indices give finite unit results, never NaN. */
START_TEST(test_shade_refract_extreme_indices_stay_finite)
{
    /* 1e200^2 overflows and 1e-200^2 underflows: only a scaled evaluation
     * of the discriminant survives these. */
    static const ior_pair pairs[] = {{1e-3, 1e3}, {1e3, 1e-3},   {1e200, 3e200},
                                     {3e200, 1e200}, {1e-200, 3e-200}, {3e-200, 1e-200}};
    vec3 f[3];
    general_frame(f);
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++)
        for (double deg = 0; deg <= 90; deg += 10) {
            vec3 t = vec_make(NAN, NAN, NAN);
            int ok = shade_refract(incoming(f, deg), f[2], pairs[p].n1, pairs[p].n2, &t);
            ck_assert(vec_is_finite(t));
            ck_assert_near(vec_length(t), 1.0, 8 * DBL_EPSILON);
            ck_assert(ok == 0 || ok == 1);
        }
}
END_TEST

/* ---- shade_critical_angle_cos ------------------------------------------- */

/* [SHADE-CRIT-1] Rational critical cosines, rounded up by hand:
 *   1.25 -> 1: cos th_c = 3/5; double(0.6) = 0.599999999999999977796 < 3/5,
 *     so the least double >= 3/5 is the next one up;
 *   5 -> 3: 4/5; double(0.8) = 0.800000000000000044409 > 4/5: itself;
 *   13 -> 12 and 1.625 -> 1.5 (the same ratio scaled by 1/8): 5/13 lies
 *     below double(5/13) (13 * double(5/13) - 5 > 0, checked exactly);
 *   13 -> 5: 12/13 below double(12/13), likewise. */
START_TEST(test_shade_critical_angle_cos_rational_cases)
{
    ck_assert((quad)5 * 0.6 - 3 < 0 && (quad)5 * 0.8 - 4 > 0);
    ck_assert((quad)13 * (5.0 / 13) - 5 > 0 && (quad)13 * (12.0 / 13) - 12 > 0);
    ck_assert(shade_critical_angle_cos(1.25, 1.0) == nextafter(0.6, 1.0));
    ck_assert(shade_critical_angle_cos(5.0, 3.0) == 0.8);
    ck_assert(shade_critical_angle_cos(13.0, 12.0) == 5.0 / 13);
    ck_assert(shade_critical_angle_cos(1.625, 1.5) == 5.0 / 13);
    ck_assert(shade_critical_angle_cos(13.0, 5.0) == 12.0 / 13);
}
END_TEST

/* [SHADE-CRIT-1] No TIR into a denser (or equal) medium: 0. */
START_TEST(test_shade_critical_angle_cos_zero_without_tir)
{
    ck_assert(shade_critical_angle_cos(1.0, 1.5) == 0.0);
    ck_assert(shade_critical_angle_cos(1.5, 1.5) == 0.0);
    vec3 t;
    ck_assert_int_eq(shade_refract(vec_make(1, 0, 0), vec_make(0, 1, 0), 1.0, 1.5, &t), 1);
}
END_TEST

/* [SHADE-CRIT-1] Against the __float128 reference (rounded to nearest, so
 * the function's rounded-up value is it or the next double), and agreeing
 * with shade_refract at the returned value and one ulp below; the
 * textbook sin th_c = n2/n1 is reproduced from the returned cosine. */
START_TEST(test_shade_critical_angle_cos_matches_refract)
{
    static const ior_pair pairs[] = {
        {1.5, 1.0}, {1.333, 1.0}, {2.42, 1.0}, {1.0001, 1.0}, {1.7, 1.5}, {1.5, 1.33},
        {1.0 + 1e-12, 1.0}, {4.0, 1.0}, {1e6, 1.0}, {3.0, 2.9999999}, {1e3, 1e-3},
        /* for these two the first estimate sqrt((n1-n2)(n1+n2))/n1 in double
         * lands above the answer (found by a search): the downward step */
        {1.09398, 1.0}, {1.12839, 1.0},
    };
    vec3 n = vec_make(0, 1, 0), t;
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++) {
        double n1 = pairs[p].n1, n2 = pairs[p].n2;
        quad ln1 = ldexp(n1, -ilogb(n1)), ln2 = ldexp(n2, -ilogb(n1));
        double ref = (double)(sqrtq((ln1 - ln2) * (ln1 + ln2)) / ln1);
        double cc = shade_critical_angle_cos(n1, n2);
        ck_assert_msg(cc == ref || cc == nextafter(ref, 2.0), "n1=%g n2=%g: %.17g vs %.17g", n1,
                      n2, cc, ref);
        ck_assert_int_eq(shade_refract(incoming_with_cos(cc), n, n1, n2, &t), 1);
        ck_assert_int_eq(shade_refract(incoming_with_cos(nextafter(cc, 0.0)), n, n1, n2, &t), 0);
        /* sin = sqrt((1 - c)(1 + c)) (1 - c is exact near 1, 1 - c*c is not);
         * one ulp u of c moves it by u c / sin: allow two of those. */
        double sin_c = n2 / n1, u = nextafter(cc, 2.0) - cc;
        ck_assert_near(sqrt((1.0 - cc) * (1.0 + cc)), sin_c, 2 * u * cc / sin_c + 4 * DBL_EPSILON);
    }
}
END_TEST

/* ---- shade_transmit_blend ----------------------------------------------- */

/* [SHADE-BLEND-1] Endpoints exact; t = 1/4 with front (1,2,4), back (5,6,0):
 * 0.75 (1,2,4) + 0.25 (5,6,0) = (0.75 + 1.25, 1.5 + 1.5, 3 + 0) = (2, 3, 3). */
START_TEST(test_shade_transmit_blend_endpoints_and_value)
{
    rgb front = vec_make(0.3, 0.7, 1.9), back = vec_make(0.1, 5.0, 0.2);
    ck_assert(vec_same_bits(shade_transmit_blend(front, back, 0.0), front));
    ck_assert(vec_same_bits(shade_transmit_blend(front, back, 1.0), back));
    ck_assert(vec_same_bits(shade_transmit_blend(vec_make(1, 2, 4), vec_make(5, 6, 0), 0.25),
                            vec_make(2, 3, 3)));
}
END_TEST

/* [SHADE-BLEND-1] Affine in t: blend(t) - front = t (back - front), and the
 * blend at the midpoint of two t is the midpoint of the blends. */
START_TEST(test_shade_transmit_blend_is_linear)
{
    rgb front = vec_make(0.3, 0.7, 1.9), back = vec_make(0.1, 5.0, 0.2);
    for (int i = 0; i <= 20; i++) {
        double t = i / 20.0;
        rgb got = shade_transmit_blend(front, back, t);
        ck_assert_vec_near(vec_sub(got, front), vec_scale(vec_sub(back, front), t), 1e-15);
        double a = t * 0.5, b = 1.0 - t * 0.3;
        rgb mid = vec_scale(vec_add(shade_transmit_blend(front, back, a),
                                    shade_transmit_blend(front, back, b)), 0.5);
        ck_assert_vec_near(shade_transmit_blend(front, back, 0.5 * (a + b)), mid, 1e-15);
    }
}
END_TEST

/* ---- shade_local and shade_combine -------------------------------------- */

/* [SHADE-LOCAL-1] Highlights are not scaled by (1 - t): at t = 1 only the
 * highlight is left; at t = 0 body + highlight; t = 0.5 with B = (2,4,6),
 * H = (1,1,1): (2, 3, 4). */
START_TEST(test_shade_local_keeps_highlight_whole)
{
    rgb b = vec_make(2, 4, 6), h = vec_make(1, 1, 1);
    ck_assert(vec_same_bits(shade_local(b, h, 1.0), h));
    ck_assert(vec_same_bits(shade_local(b, h, 0.0), vec_add(b, h)));
    ck_assert(vec_same_bits(shade_local(b, h, 0.5), vec_make(2, 3, 4)));
}
END_TEST

/* [SHADE-HIT-1] B = (2,4,8), H = 0.5, Ks = (0.5, 0.25, 0), t = 0.25,
 * mirrored M = 4, transmitted T = (8, 0, 16):
 *   r: 0.75*2 + 0.5 + 0.5*4  + 0.25*8  = 1.5 + 0.5 + 2 + 2 = 6
 *   g: 0.75*4 + 0.5 + 0.25*4 + 0       = 3 + 0.5 + 1      = 4.5
 *   b: 0.75*8 + 0.5 + 0      + 0.25*16 = 6 + 0.5 + 4      = 10.5 */
START_TEST(test_shade_combine_known_value)
{
    rgb b = vec_make(2, 4, 8), h = vec_splat(0.5), ks = vec_make(0.5, 0.25, 0);
    rgb m = vec_splat(4), tr = vec_make(8, 0, 16);
    ck_assert(vec_same_bits(shade_combine(b, h, ks, 0.25, m, tr), vec_make(6, 4.5, 10.5)));
}
END_TEST

/* [SHADE-HIT-1] Without secondary rays the combination is the local colour
 * bit for bit; otherwise it equals the slide-37 blend of body and the
 * transmitted colour, plus highlight and Ks * mirrored (a second route). */
START_TEST(test_shade_combine_routes_agree)
{
    rgb b = vec_make(0.31, 0.62, 0.17), h = vec_make(0.05, 0.9, 0.33), ks = vec_make(0.2, 0.7, 0.4);
    rgb m = vec_make(0.8, 0.1, 1.3), tr = vec_make(0.45, 0.6, 0.01);
    for (int i = 0; i <= 10; i++) {
        double t = i / 10.0;
        ck_assert(vec_same_bits(shade_combine(b, h, ks, t, vec_splat(0), vec_splat(0)),
                                shade_local(b, h, t)));
        rgb want = vec_add(vec_add(shade_transmit_blend(b, tr, t), h), vec_mul(ks, m));
        ck_assert_vec_near(shade_combine(b, h, ks, t, m, tr), want, 4 * DBL_EPSILON);
    }
}
END_TEST

/* ---- shade_shadow_transmission ------------------------------------------ */

/* [SHADE-SHADOW-1] A stack 0.5, 0.25, 1, 0.75 lets through the product
 * 0.5 * 0.25 * 0.75 = 0.09375 (dyadic: exact), in any order; an opaque
 * surface anywhere gives 0; a glass sphere of t = 0.8 is crossed twice:
 * 0.64. */
START_TEST(test_shade_shadow_transmission_is_a_product)
{
    static const double stack[4] = {0.5, 0.25, 1.0, 0.75};
    static const int orders[3][4] = {{0, 1, 2, 3}, {3, 2, 1, 0}, {2, 0, 3, 1}};
    for (int o = 0; o < 3; o++) {
        double s = 1.0;
        for (int i = 0; i < 4; i++)
            s = shade_shadow_transmission(s, stack[orders[o][i]]);
        ck_assert(s == 0.09375);
    }
    double s = 1.0;
    for (int i = 0; i < 4; i++)
        s = shade_shadow_transmission(s, i == 1 ? 0.0 : 0.9);
    ck_assert(s == 0.0);
    s = shade_shadow_transmission(shade_shadow_transmission(1.0, 0.8), 0.8);
    ck_assert_near(s, 0.64, 2 * DBL_EPSILON);
    ck_assert(shade_shadow_transmission(1.0, 1.0) == 1.0);
}
END_TEST

/* [SHADE-SAT-1] A channel that overflowed to +Inf comes back as DBL_MAX;
 * finite values pass unchanged, bit for bit; NaN stays NaN so the tracer's
 * non-finite counter still sees it. */
START_TEST(test_shade_saturate_caps_infinity_keeps_nan)
{
    double big = DBL_MAX;
    rgb c = shade_saturate(vec_make(big + big, 0.25, -3.0));
    ck_assert(c.x == DBL_MAX);
    ck_assert(c.y == 0.25 && c.z == -3.0);
    c = shade_saturate(vec_make(NAN, 1.0, DBL_MAX));
    ck_assert(isnan(c.x));
    ck_assert(c.z == DBL_MAX);
}
END_TEST

Suite *suite_shade(void)
{
    Suite *s = suite_create("shade");
    struct { const char *name; const TTest *tests[8]; } cases[] = {
        {"shade_ambient", {test_shade_ambient_is_kd_times_ia_per_channel}},
        {"shade_falloff", {test_shade_falloff_known_values, test_shade_falloff_limit_at_the_light,
                           test_shade_falloff_limit_far_away, test_shade_falloff_defensive_cases}},
        {"shade_sample_power", {test_shade_sample_power_splits_evenly}},
        {"shade_face_forward", {test_shade_face_forward_turns_toward_viewer}},
        {"shade_lambert", {test_shade_lambert_cosine_law_exact, test_shade_lambert_cosine_law_sweep,
                           test_shade_lambert_zero_at_and_below_horizon}},
        {"shade_diffuse", {test_shade_diffuse_known_value}},
        {"shade_reflect_about", {test_shade_reflect_about_known_value,
                                 test_shade_reflect_about_identities}},
        {"shade_mirror", {test_shade_mirror_known_value, test_shade_mirror_identities}},
        {"shade_phong_lobe", {test_shade_phong_lobe_peak_is_one, test_shade_phong_lobe_known_values,
                              test_shade_phong_lobe_symmetric_about_r,
                              test_shade_phong_lobe_decreasing_in_angle,
                              test_shade_phong_lobe_exponent_zero,
                              test_shade_phong_lobe_large_exponents,
                              test_shade_phong_lobe_clamps_rounding_above_one}},
        {"shade_specular", {test_shade_specular_peak_is_ks_times_i, test_shade_specular_known_value,
                            test_shade_specular_zero_unless_light_in_front}},
        {"shade_direct", {test_shade_direct_known_value, test_shade_direct_parts_and_shadow_scaling}},
        {"shade_refract", {test_shade_refract_snell_sweep, test_shade_refract_known_values,
                           test_shade_refract_equal_indices_keep_bits,
                           test_shade_refract_tir_reports_and_mirrors,
                           test_shade_refract_critical_split_is_exact,
                           test_shade_refract_accurate_near_critical,
                           test_shade_refract_accurate_near_grazing,
                           test_shade_refract_extreme_indices_stay_finite}},
        {"shade_critical_angle_cos", {test_shade_critical_angle_cos_rational_cases,
                                      test_shade_critical_angle_cos_zero_without_tir,
                                      test_shade_critical_angle_cos_matches_refract}},
        {"shade_transmit_blend", {test_shade_transmit_blend_endpoints_and_value,
                                  test_shade_transmit_blend_is_linear}},
        {"shade_local", {test_shade_local_keeps_highlight_whole}},
        {"shade_combine", {test_shade_combine_known_value, test_shade_combine_routes_agree}},
        {"shade_shadow_transmission", {test_shade_shadow_transmission_is_a_product}},
        {"shade_saturate", {test_shade_saturate_caps_infinity_keeps_nan}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        TCase *tc = tcase_create(cases[i].name);
        for (int j = 0; j < 8 && cases[i].tests[j]; j++)
            tcase_add_test(tc, cases[i].tests[j]);
        suite_add_tcase(s, tc);
    }
    return s;
}
