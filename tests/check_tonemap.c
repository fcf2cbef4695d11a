/* Tests of src/image/tonemap.c: the scalar display mapping.  Expected values are
 * derived by hand or by a different formula (exp2/log instead of pow). */
#include <float.h>
#include "testlib.h"
#include "image/tonemap.h"

START_TEST(test_tonemap_exposure)
{
    ck_assert_near(tonemap_exposure(0.3, 0.0), 0.3, 0.0);
    ck_assert_near(tonemap_exposure(0.3, 1.0), 0.6, 0.0);
    ck_assert_near(tonemap_exposure(0.3, -2.0), 0.075, 1e-17);
    /* half a stop is a factor sqrt(2) */
    ck_assert_rel(tonemap_exposure(1.0, 0.5), sqrt(2.0), 4 * DBL_EPSILON);
}
END_TEST

START_TEST(test_tonemap_clamp)
{
    ck_assert_near(tonemap_clamp(-0.5), 0.0, 0.0);
    ck_assert_near(tonemap_clamp(0.25), 0.25, 0.0);
    ck_assert_near(tonemap_clamp(1.0), 1.0, 0.0);
    ck_assert_near(tonemap_clamp(7.0), 1.0, 0.0);
    ck_assert_near(tonemap_clamp(INFINITY), 1.0, 0.0);
    ck_assert_near(tonemap_clamp(NAN), 0.0, 0.0);
}
END_TEST

START_TEST(test_tonemap_reinhard_limits)
{
    ck_assert_near(tonemap_reinhard(0.0), 0.0, 0.0);
    ck_assert_near(tonemap_reinhard(1.0), 0.5, 0.0);
    ck_assert_near(tonemap_reinhard(3.0), 0.75, 0.0);
    ck_assert_near(tonemap_reinhard(-2.0), 0.0, 0.0);
    ck_assert_near(tonemap_reinhard(NAN), 0.0, 0.0);
    ck_assert_near(tonemap_reinhard(INFINITY), 1.0, 0.0);
    /* 1 - v/(1+v) = 1/(1+v): the curve approaches 1 from below */
    double big = 1e6;
    ck_assert(tonemap_reinhard(big) < 1.0);
    ck_assert_near(1.0 - tonemap_reinhard(big), 1.0 / (1.0 + big), 1e-15);
    /* near 0 it is v - v^2 + ...: slope 1 */
    ck_assert_near(tonemap_reinhard(1e-9) / 1e-9, 1.0, 1e-8);
}
END_TEST

/* 1.055 * 2^(-1/2.4) - 0.055 by exp2, not pow: 0.7353569830524495. */
START_TEST(test_tonemap_srgb_encode_known_values)
{
    double half = 1.055 * exp2(-1.0 / 2.4) - 0.055;
    ck_assert_near(half, 0.7353569830524495, 2e-16);
    ck_assert_near(tonemap_srgb_encode(0.5), half, 2e-16);
    ck_assert_near(tonemap_srgb_encode(0.0), 0.0, 0.0);
    ck_assert_near(tonemap_srgb_encode(1.0), 1.0, 2e-16);
    ck_assert_near(tonemap_srgb_encode(0.001), 0.01292, 1e-17); /* linear branch */
    /* 0.18 (mid grey) by exp/log: 1.055 exp(ln 0.18 / 2.4) - 0.055 */
    ck_assert_near(tonemap_srgb_encode(0.18), 1.055 * exp(log(0.18) / 2.4) - 0.055, 1e-15);
}
END_TEST

START_TEST(test_tonemap_srgb_decode_known_values)
{
    ck_assert_near(tonemap_srgb_decode(0.0), 0.0, 0.0);
    ck_assert_near(tonemap_srgb_decode(1.0), 1.0, 2e-16);
    ck_assert_near(tonemap_srgb_decode(0.01292), 0.001, 1e-18);
    /* ((0.5 + 0.055) / 1.055)^2.4 by exp/log */
    ck_assert_near(tonemap_srgb_decode(0.5), exp(2.4 * log(0.555 / 1.055)), 1e-15);
    ck_assert_near(tonemap_srgb_decode(0.7353569830524495), 0.5, 1e-15);
}
END_TEST

START_TEST(test_tonemap_srgb_round_trip)
{
    for (int i = 0; i <= 1000; i++) {
        double v = i / 1000.0;
        ck_assert_near(tonemap_srgb_decode(tonemap_srgb_encode(v)), v, 1e-12);
        ck_assert_near(tonemap_srgb_encode(tonemap_srgb_decode(v)), v, 1e-12);
    }
}
END_TEST

/* The standard's constants make the branches meet only to 2.9e-8 (encode)
 * and 2.4e-9 (decode); a typo in any constant would break this by far
 * more (e.g. 12.92 -> 12.9 moves the linear branch by 6e-5). */
START_TEST(test_tonemap_srgb_branches_meet)
{
    double t = 0.0031308;
    double below = tonemap_srgb_encode(nextafter(t, 0.0));
    double at = tonemap_srgb_encode(t);
    ck_assert_near(below, 12.92 * t, 1e-15);
    ck_assert_near(at, below, 3e-8);
    double d = 0.04045;
    ck_assert_near(tonemap_srgb_decode(nextafter(d, 0.0)), tonemap_srgb_decode(d), 3e-9);
    /* and the encode curve is increasing across the knee */
    ck_assert(tonemap_srgb_encode(t * 1.001) > tonemap_srgb_encode(t * 0.999));
}
END_TEST

START_TEST(test_tonemap_quantize_endpoints)
{
    ck_assert_uint_eq(tonemap_quantize(0.0, 255), 0);
    ck_assert_uint_eq(tonemap_quantize(1.0, 255), 255);
    ck_assert_uint_eq(tonemap_quantize(-3.0, 255), 0);
    ck_assert_uint_eq(tonemap_quantize(2.0, 255), 255);
    ck_assert_uint_eq(tonemap_quantize(NAN, 255), 0);
    ck_assert_uint_eq(tonemap_quantize(INFINITY, 65535), 65535);
    ck_assert_uint_eq(tonemap_quantize(1.0, 65535), 65535);
}
END_TEST

START_TEST(test_tonemap_quantize_rounds_half_up)
{
    /* Products that are exact binary fractions make the halves exact:
     * maxcode 4, v = 0.375 -> 1.5 -> 2. */
    ck_assert_uint_eq(tonemap_quantize(0.375, 4), 2);
    ck_assert_uint_eq(tonemap_quantize(0.125, 4), 1);   /* 0.5 -> 1 */
    ck_assert_uint_eq(tonemap_quantize(0.124, 4), 0);
    ck_assert_uint_eq(tonemap_quantize(0.5, 255), 128); /* 127.5 -> 128 */
    ck_assert_uint_eq(tonemap_quantize(0.5, 65535), 32768);
    ck_assert_uint_eq(tonemap_quantize(100.4 / 255.0, 255), 100);
}
END_TEST

Suite *suite_tonemap(void)
{
    Suite *s = suite_create("tonemap");
    TCase *tc = tcase_create("scalar");
    tcase_add_test(tc, test_tonemap_exposure);
    tcase_add_test(tc, test_tonemap_clamp);
    tcase_add_test(tc, test_tonemap_reinhard_limits);
    tcase_add_test(tc, test_tonemap_srgb_encode_known_values);
    tcase_add_test(tc, test_tonemap_srgb_decode_known_values);
    tcase_add_test(tc, test_tonemap_srgb_round_trip);
    tcase_add_test(tc, test_tonemap_srgb_branches_meet);
    tcase_add_test(tc, test_tonemap_quantize_endpoints);
    tcase_add_test(tc, test_tonemap_quantize_rounds_half_up);
    suite_add_tcase(s, tc);
    return s;
}
