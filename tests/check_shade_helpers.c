/*
 * Tests of the static helpers of src/render/shade.c that make prove reasons
 * about (spec/proofs.md): saturating_div, saturating_add, scale_indices.
 *
 * They are static, so this file compiles shade.c itself, with the exported
 * shade_* names renamed so that they do not clash with the library's copy
 * the runner links.  No code of the library changes for the tests; a new
 * exported name in shade.c that is missing below fails the link (two
 * definitions), loudly.
 *
 * Expected values come from exact binary arithmetic worked by hand (powers
 * of two, sums that fit 53 bits) or from the C library's frexp and ldexp,
 * a route scale_indices does not take.
 */
#define shade_ambient helpers_shade_ambient
#define shade_falloff helpers_shade_falloff
#define shade_sample_power helpers_shade_sample_power
#define shade_face_forward helpers_shade_face_forward
#define shade_lambert helpers_shade_lambert
#define shade_diffuse helpers_shade_diffuse
#define shade_reflect_about helpers_shade_reflect_about
#define shade_mirror helpers_shade_mirror
#define shade_phong_lobe helpers_shade_phong_lobe
#define shade_specular helpers_shade_specular
#define shade_direct helpers_shade_direct
#define shade_refract helpers_shade_refract
#define shade_critical_angle_cos helpers_shade_critical_angle_cos
#define shade_transmit_blend helpers_shade_transmit_blend
#define shade_saturate helpers_shade_saturate
#define shade_local helpers_shade_local
#define shade_combine helpers_shade_combine
#define shade_shadow_transmission helpers_shade_shadow_transmission
#include "render/shade.c"

#include "testlib.h"

/* saturating_div: e/s rounded once, DBL_MAX past it ([SHADE-FALLOFF-5]). */
START_TEST(test_saturating_div)
{
    static const struct {
        double e, s, want;
    } cases[] = {
        {6.0, 3.0, 2.0},                   /* exact */
        {1.0, 4.0, 0.25},                  /* exact: a power of two */
        {0.0, 0x1p-1074, 0.0},             /* nothing over the least subnormal */
        {0x1p-1074, 0x1p-1074, 1.0},
        {1.0, 0x1p-1074, DBL_MAX},         /* 2^1074: past DBL_MAX */
        {DBL_MAX, 1.0, DBL_MAX},           /* s >= 1: divided at once */
        {DBL_MAX, 0.5, DBL_MAX},           /* 2 DBL_MAX */
        {0x1p1023, 0.5, DBL_MAX},          /* 2^1024, just past */
        {0x1.8p1022, 0x1.8p-1, 0x1p1023},  /* 1.5 2^1022 / 0.75: the quarter path, exact */
        {0x1p1022, 0x1p-1, 0x1p1023},      /* 2^1023 exactly, e > s 2^1022 */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        ck_assert_msg(saturating_div(cases[i].e, cases[i].s) == cases[i].want, "case %zu: %a / %a gave %La, want %a",
                      i, cases[i].e, cases[i].s, (long double)saturating_div(cases[i].e, cases[i].s), cases[i].want);
    /* Not exact: the correctly rounded third, 0x1.5555555555555p-2; in the
     * long double build's 64-bit significand 1010...10 (64 bits) then 1010...
     * past half an ulp: up to 0xAAAAAAAAAAAAAAABp-65. */
#ifdef REFRAY_LONG_DOUBLE
    ck_assert(saturating_div(1.0, 3.0) == 0xAAAAAAAAAAAAAAABp-65L);
#else
    ck_assert(saturating_div(1.0, 3.0) == 0x1.5555555555555p-2);
#endif
}
END_TEST

/* saturating_add: a + b rounded once, DBL_MAX past it, never Inf
 * ([SHADE-SAT-1]). */
START_TEST(test_saturating_add)
{
    static const struct {
        double a, b, want;
    } cases[] = {
        {1.0, 2.0, 3.0},
        {0.0, 0.0, 0.0},
        {0x1p1023, 0x1p1022, 0x1.8p1023},   /* the halved path, exact */
        {0x1p1023, 1.0, 0x1p1023},          /* 1 is far below half an ulp of 2^1023 */
        {0x1p1023, 0x1p-1074, 0x1p1023},    /* the subnormal's half is lost: no harm */
        {0x1.fffffffffffffp1022, 0x1.fffffffffffffp1022, DBL_MAX}, /* exactly DBL_MAX */
        {0x1p1023, 0x1p1023, DBL_MAX},      /* 2^1024 */
        {DBL_MAX, 0.0, DBL_MAX},
        {DBL_MAX, DBL_MAX, DBL_MAX},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ck_assert_msg(saturating_add(cases[i].a, cases[i].b) == cases[i].want, "case %zu: %a + %a gave %La, want %a",
                      i, cases[i].a, cases[i].b, (long double)saturating_add(cases[i].a, cases[i].b), cases[i].want);
        ck_assert(saturating_add(cases[i].b, cases[i].a) == cases[i].want);   /* symmetric */
    }
}
END_TEST

/* scale_indices: both indices times one power of two, the larger into
 * [0.5, 1): frexp's fraction of the larger, and ldexp of the other by the
 * same exponent (both correctly rounded; only an index ratio past 2^1021
 * rounds the smaller). */
START_TEST(test_scale_indices)
{
    static const double pairs[][2] = {
        {1.0, 1.0}, {1.5, 1.0}, {1.0, 1.33}, {2.417, 1.0}, {0x1p-1074, 0x1p-1074}, {0x1p-1070, 1.0},
        {DBL_MAX, 1.0}, {3e-300, 1e-300}, {1e300, 1e-300}, {1.0, DBL_MAX}, {0x1p-1022, 0x1.8p-1022},
    };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        /* In real, not double: the long double build's scale_indices
         * scales in long double, where 1e-300 / 2^997 does not underflow. */
        real n1 = pairs[i][0], n2 = pairs[i][1], s1 = -1, s2 = -1;
        int e;
        real frac = frexp(n1 > n2 ? n1 : n2, &e);
        real m = scale_indices(n1, n2, &s1, &s2);
        ck_assert_msg(m == frac && s1 == ldexp(n1, -e) && s2 == ldexp(n2, -e),
                      "case %zu (%La, %La): got %La, %La, %La; want %La, %La, %La", i, (long double)n1,
                      (long double)n2, (long double)m, (long double)s1, (long double)s2, (long double)frac,
                      (long double)ldexp(n1, -e), (long double)ldexp(n2, -e));
        ck_assert(m >= 0.5 && m < 1.0);
    }
    /* Hand-worked: 1.5 and 1 scaled by 2^-1. */
    real s1, s2;
    ck_assert(scale_indices(1.5, 1.0, &s1, &s2) == 0.75 && s1 == 0.75 && s2 == 0.5);
}
END_TEST

Suite *suite_shade_helpers(void)
{
    Suite *s = suite_create("shade_helpers");
    TCase *tc = tcase_create("helpers");
    tcase_add_test(tc, test_saturating_div);
    tcase_add_test(tc, test_saturating_add);
    tcase_add_test(tc, test_scale_indices);
    suite_add_tcase(s, tc);
    return s;
}
