/*
 * check_fit.c - least-squares lines (fit.h) against values worked out by
 * hand from the definitions: slope = Sxy/Sxx on centred sums, se =
 * sqrt(SSE/(n-2)/Sxx), r2 = 1 - SSE/Syy ([VERIFY-FIT-1]).
 */
#include "testlib.h"
#include "verify/fit.h"

/* x = 0,1,2,3; y = 0,-1.1,-1.9,-3: xbar 1.5, ybar -1.5, dx = -1.5,-.5,.5,1.5,
 * dy = 1.5,.4,-.4,-1.5; Sxx = 5, Sxy = -4.9, Syy = 4.82; slope -0.98,
 * intercept -1.5 + 0.98*1.5 = -0.03; predictions -0.03,-1.01,-1.99,-2.97,
 * residuals .03,-.09,.09,-.03, SSE = .018; se = sqrt(.018/2/5) = sqrt(.0018). */
START_TEST(test_fit_linear_hand_example)
{
    const double x[] = {0, 1, 2, 3}, y[] = {0, -1.1, -1.9, -3.0};
    fit_line f;
    ck_assert_int_eq(fit_linear(x, y, 4, &f), 1);
    ck_assert_int_eq(f.points, 4);
    ck_assert_near(f.slope, -0.98, 1e-14);
    ck_assert_near(f.intercept, -0.03, 1e-14);
    ck_assert_near(f.slope_se, 0.042426406871192851, 1e-14);
    ck_assert_near(f.r2, 1 - 0.018 / 4.82, 1e-14);
}
END_TEST

/* y = 3/x at x = 1, 2, 4, ..., 1024: ln y = ln 3 - ln x, a perfect line. */
START_TEST(test_fit_loglog_exact_power_law)
{
    double x[11], y[11];
    for (int i = 0; i < 11; i++) {
        x[i] = (double)(1 << i);
        y[i] = 3.0 / x[i];
    }
    fit_line f;
    ck_assert_int_eq(fit_loglog(x, y, 11, &f), 1);
    ck_assert_int_eq(f.points, 11);
    ck_assert_near(f.slope, -1.0, 1e-13);
    ck_assert_near(f.intercept, 1.0986122886681098, 1e-13); /* ln 3 */
    ck_assert_near(f.slope_se, 0, 1e-13);
    ck_assert_near(f.r2, 1, 1e-13);
}
END_TEST

/* y = 2 x^-1/2 at x = 1, 4, 16, 64: 2, 1, 0.5, 0.25. */
START_TEST(test_fit_loglog_half_order)
{
    const double x[] = {1, 4, 16, 64}, y[] = {2, 1, 0.5, 0.25};
    fit_line f;
    ck_assert_int_eq(fit_loglog(x, y, 4, &f), 1);
    ck_assert_near(f.slope, -0.5, 1e-14);
    ck_assert_near(f.intercept, 0.69314718055994531, 1e-14); /* ln 2 */
}
END_TEST

/* Noise that cancels: ln y_i = -ln x_i + e_i with ln x = 0,1,2,3 and
 * e = (+d, -d, -d, +d).  sum dx*e = (-1.5 + .5 - .5 + 1.5) d = 0 and
 * sum e = 0, so the slope stays -1 and the intercept 0; the residuals are
 * e itself: SSE = 4 d^2, se = sqrt(4 d^2 / 2 / 5) = d sqrt(0.4). */
START_TEST(test_fit_loglog_noisy_points)
{
    const double d = 0.1, e[] = {d, -d, -d, d};
    double x[4], y[4];
    for (int i = 0; i < 4; i++) {
        x[i] = exp((double)i);
        y[i] = exp(-(double)i + e[i]);
    }
    fit_line f;
    ck_assert_int_eq(fit_loglog(x, y, 4, &f), 1);
    ck_assert_near(f.slope, -1.0, 1e-13);
    ck_assert_near(f.intercept, 0.0, 1e-13);
    ck_assert_near(f.slope_se, 0.063245553203367588, 1e-13); /* 0.1 * sqrt(0.4) */
    /* Syy = sum (-dx + e)^2 = 5 + 4 d^2 - 2 sum dx*e = 5.04: r2 = 1 - .04/5.04 */
    ck_assert_near(f.r2, 1 - 0.04 / 5.04, 1e-13);
}
END_TEST

/* Zero, negative and non-finite values cannot lie on a power law. */
START_TEST(test_fit_loglog_skips_unusable_points)
{
    const double x[] = {1, 2, -1, 4, NAN, 8, 16}, y[] = {1, 0.5, 7, 0.25, 1, 0, 0.0625};
    fit_line f;
    ck_assert_int_eq(fit_loglog(x, y, 7, &f), 1);
    ck_assert_int_eq(f.points, 4); /* x = 1, 2, 4, 16 */
    ck_assert_near(f.slope, -1.0, 1e-14);
}
END_TEST

START_TEST(test_fit_linear_needs_two_distinct_x)
{
    const double x[] = {2, 2, 2}, y[] = {1, 2, 3};
    fit_line f;
    ck_assert_int_eq(fit_linear(x, y, 1, &f), 0);
    ck_assert(isnan(f.slope));
    ck_assert_int_eq(fit_linear(x, y, 3, &f), 0);
    ck_assert(isnan(f.slope) && isnan(f.slope_se));
    ck_assert_int_eq(fit_loglog(x, y, 0, &f), 0);
    ck_assert_int_eq(f.points, 0);
}
END_TEST

/* Two points fix the line but leave no degree of freedom for an error. */
START_TEST(test_fit_linear_two_points_have_no_standard_error)
{
    const double x[] = {1, 3}, y[] = {5, 1};
    fit_line f;
    ck_assert_int_eq(fit_linear(x, y, 2, &f), 1);
    ck_assert_near(f.slope, -2.0, 1e-15);
    ck_assert_near(f.intercept, 7.0, 1e-15);
    ck_assert(isnan(f.slope_se));
}
END_TEST

Suite *suite_fit(void)
{
    Suite *s = suite_create("fit");
    TCase *tc = tcase_create("fit");
    tcase_add_test(tc, test_fit_linear_hand_example);
    tcase_add_test(tc, test_fit_loglog_exact_power_law);
    tcase_add_test(tc, test_fit_loglog_half_order);
    tcase_add_test(tc, test_fit_loglog_noisy_points);
    tcase_add_test(tc, test_fit_loglog_skips_unusable_points);
    tcase_add_test(tc, test_fit_linear_needs_two_distinct_x);
    tcase_add_test(tc, test_fit_linear_two_points_have_no_standard_error);
    suite_add_tcase(s, tc);
    return s;
}
