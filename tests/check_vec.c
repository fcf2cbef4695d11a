/* Tests of src/base/vec.h: the identities every other module leans on. */
#include <float.h>
#include "testlib.h"
#include "base/vec.h"

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

Suite *suite_vec(void)
{
    Suite *s = suite_create("vec");
    TCase *tc = tcase_create("identities");
    tcase_add_test(tc, test_vec_cross_is_orthogonal_and_right_handed);
    tcase_add_test(tc, test_vec_length_survives_huge_and_tiny_components);
    tcase_add_test(tc, test_vec_length_fast_exact_and_falls_back_at_the_ends);
    tcase_add_test(tc, test_vec_normalize_gives_unit_length_or_zero);
    tcase_add_test(tc, test_vec_madd_and_mul);
    suite_add_tcase(s, tc);
    return s;
}
