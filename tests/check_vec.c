/* Tests of src/base/vec.h: the identities every other module leans on;
 * and of base/next_up.h. */
#include <float.h>
#include <stdint.h>
#include <string.h>
#include "testlib.h"
#include "base/vec.h"
#include "base/next_up.h"

START_TEST(test_vec_cross_is_orthogonal_and_right_handed)
{
    vec3 x = vec_make(1, 0, 0), y = vec_make(0, 1, 0);
    ck_assert_vec_near(vec_cross(x, y), vec_make(0, 0, 1), 0.0);
    vec3 a = vec_make(0.3, -2.0, 5.0), b = vec_make(-1.5, 0.25, 4.0);
    vec3 c = vec_cross(a, b);
    ck_assert_near(vec_dot(c, a), 0.0, 1e-13);
    ck_assert_near(vec_dot(c, b), 0.0, 1e-13);
}
END_TEST

START_TEST(test_vec_length_survives_huge_and_tiny_components)
{
    /* sqrt(dot) would overflow to Inf here and underflow to 0 below. */
    ck_assert_rel(vec_length(vec_make(3e200, 4e200, 0)), 5e200, 1e-15);
    ck_assert_rel(vec_length(vec_make(3e-320, 4e-320, 0)), 5e-320, 1e-3);
    ck_assert_near(vec_length(vec_make(0, 0, 0)), 0.0, 0.0);
}
END_TEST

START_TEST(test_vec_length_fast_exact_and_falls_back_at_the_ends)
{
    /* 3-4-12 is a Pythagorean quadruple: the length is 13 exactly. */
    ck_assert(vec_length_fast(vec_make(3, 4, 12)) == 13);
    ck_assert(vec_length_fast(vec_make(0, 0, 0)) == 0);
    /* a.a overflows and underflows here; the scaled form still gives 13 * 2^k. */
    ck_assert(vec_length_fast(vec_make(3e200, 4e200, 12e200)) == vec_length(vec_make(3e200, 4e200, 12e200)));
    ck_assert(vec_length_fast(vec_make(3e200, 4e200, 12e200)) < INFINITY);
    ck_assert(vec_length_fast(vec_make(3e-200, 4e-200, 12e-200)) > 0);
}
END_TEST

START_TEST(test_vec_normalize_gives_unit_length_or_zero)
{
    vec3 n = vec_normalize(vec_make(1e-300, 2e-300, -2e-300));
    ck_assert_near(vec_length(n), 1.0, 4 * DBL_EPSILON);
    ck_assert_near(n.y, 2.0 / 3.0, 4 * DBL_EPSILON);
    vec3 z = vec_normalize(vec_make(0, 0, 0));
    ck_assert(z.x == 0 && z.y == 0 && z.z == 0);
}
END_TEST

START_TEST(test_vec_madd_and_mul)
{
    ck_assert_vec_near(vec_madd(vec_make(1, 2, 3), vec_make(1, 1, 2), 0.5), vec_make(1.5, 2.5, 4), 0);
    ck_assert_vec_near(vec_mul(vec_make(1, 2, 3), vec_make(4, 5, 6)), vec_make(4, 10, 18), 0);
}
END_TEST

/* a and b the same real: equal with the same sign, or both NaN. */
static int same_real(real a, real b)
{
    return (a != a && b != b) || (a == b && signbit(a) == signbit(b));
}

static void assert_next_up(real x)
{
    real got = real_next_up(x), want = nextafter(x, (real)INFINITY);
    ck_assert_msg(same_real(got, want), "real_next_up(%La) = %La, nextafter %La", (long double)x, (long double)got,
                  (long double)want);
}

START_TEST(test_real_next_up_is_nextafter_toward_infinity)
{
    /* The ends of each range, either sign: zeros, the least subnormal and
     * the largest, the least normal, 1, the largest double, infinities;
     * every power of two and the doubles either side of it. */
    const double edges[] = {0.0, 0x1p-1074, 0x1.ffffffffffffep-1023, 0x1.fffffffffffffp-1023, DBL_MIN, 1.0, DBL_MAX,
                            HUGE_VAL};
    for (int i = 0; i < (int)(sizeof edges / sizeof edges[0]); i++) {
        assert_next_up(edges[i]);
        assert_next_up(-edges[i]);
    }
    ck_assert(real_next_up(DBL_MAX) == HUGE_VAL || sizeof(real) > sizeof(double));
    ck_assert(same_real(real_next_up(-0x1p-1074), -0.0) || sizeof(real) > sizeof(double));
    ck_assert(same_real(real_next_up(-0.0), 0x1p-1074) || sizeof(real) > sizeof(double));
    for (int e = -1074; e <= 1023; e++) {
        double p = ldexp(1.0, e);
        double around[3] = {nextafter(p, 0.0), p, nextafter(p, HUGE_VAL)};
        for (int k = 0; k < 3; k++) {
            assert_next_up(around[k]);
            assert_next_up(-around[k]);
        }
    }
    /* A NaN stays a NaN. */
    ck_assert(isnan(real_next_up((real)NAN)));
    /* Random bit patterns: every exponent, subnormals and NaNs among them. */
    uint64_t z = 0x243f6a8885a308d3u;
    for (int i = 0; i < 1000000; i++) {
        z = z * 6364136223846793005u + 1442695040888963407u;
        uint64_t bits = z ^ (z >> 29);
        double x;
        memcpy(&x, &bits, sizeof x);
        assert_next_up(x);
    }
}
END_TEST

Suite *suite_vec(void)
{
    Suite *s = suite_create("vec");
    TCase *tc = tcase_create("identities");
    /* The next-up test's million random doubles take 0.4 s of CPU; Check's
     * default of 4 s ran out in CI's clang build at load 14. */
    tcase_set_timeout(tc, 20);
    tcase_add_test(tc, test_vec_cross_is_orthogonal_and_right_handed);
    tcase_add_test(tc, test_vec_length_survives_huge_and_tiny_components);
    tcase_add_test(tc, test_vec_length_fast_exact_and_falls_back_at_the_ends);
    tcase_add_test(tc, test_vec_normalize_gives_unit_length_or_zero);
    tcase_add_test(tc, test_vec_madd_and_mul);
    tcase_add_test(tc, test_real_next_up_is_nextafter_toward_infinity);
    suite_add_tcase(s, tc);
    return s;
}
