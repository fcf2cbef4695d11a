/*
 * Tests of the distributed-light sample layout (lightsample.c).
 */
#include <math.h>
#include "testlib.h"
#include "render/lightsample.h"
#include "base/sampler.h"
#include "base/sampler_counters.h"

START_TEST(test_light_grid_for_is_the_squarest_factorisation)
{
    int samples[] = {1, 2, 4, 7, 12, 16, 18, 64};
    int rows[] = {1, 1, 2, 1, 3, 4, 3, 8};
    for (int i = 0; i < 8; i++) {
        light_grid g = light_grid_for(samples[i]);
        ck_assert_int_eq(g.rows, rows[i]);
        ck_assert_int_eq(g.rows * g.cols, samples[i]);
    }
}
END_TEST

START_TEST(test_light_cell_point_stays_in_its_cell)
{
    light_grid g = light_grid_for(12); /* 3 rows x 4 cols */
    for (int j = 0; j < 12; j++) {
        double s, t;
        light_cell_point(g, j, 0.999999, 0.0, &s, &t);
        ck_assert(s >= (j % 4) / 4.0 && s < (j % 4 + 1) / 4.0);
        ck_assert(t >= (j / 4) / 3.0 && t < (j / 4 + 1) / 3.0);
    }
}
END_TEST

START_TEST(test_light_concentric_maps_onto_the_disk)
{
    double x, y;
    light_concentric(0.5, 0.5, &x, &y);
    ck_assert_near(x, 0, 0);
    ck_assert_near(y, 0, 0);
    /* The square's edge midpoints go to the circle: (1, 0.5) -> (1, 0). */
    light_concentric(1.0, 0.5, &x, &y);
    ck_assert_near(x, 1, 1e-15);
    ck_assert_near(y, 0, 1e-15);
    /* Area preservation: the inner square [0.25, 0.75]^2 (a quarter of the
     * area) maps inside radius 1/2 (a quarter of the disk's area). */
    for (int i = 0; i <= 20; i++) {
        double s = 0.25 + 0.5 * i / 20.0;
        light_concentric(s, 0.25, &x, &y);
        ck_assert_near(hypot(x, y), 0.5, 1e-15);
    }
}
END_TEST

START_TEST(test_light_frame_is_orthonormal_and_right_handed)
{
    vec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0.6, 0, -0.8}, {0.36, 0.48, 0.8}};
    for (int i = 0; i < 6; i++) {
        vec3 t1, t2, n = normals[i];
        light_frame(n, &t1, &t2);
        ck_assert_near(vec_length(t1), 1, 1e-15);
        ck_assert_near(vec_length(t2), 1, 1e-15);
        ck_assert_near(vec_dot(t1, t2), 0, 1e-15);
        ck_assert_vec_near(vec_cross(t1, t2), n, 1e-15);
    }
}
END_TEST

/* The constant table of mixed counters is sampler_mix at each counter; its
 * first entry is also SplitMix64's published first output for the seed 0
 * (Steele, Lea, Flood 2014; the reference generator's next() from state 0),
 * a value from outside this code. */
START_TEST(test_sampler_mixed_counter_table_is_sampler_mix)
{
    ck_assert(sampler_mixed_counter[0] == 0xe220a8397b1dcdafULL);
    int wrong = 0;
    for (int c = 0; c < SAMPLER_MIXED_COUNTERS; c++)
        wrong += sampler_mixed_counter[c] != sampler_mix((uint64_t)c);
    ck_assert_int_eq(wrong, 0);
}
END_TEST

Suite *suite_lightsample(void)
{
    Suite *s = suite_create("lightsample");
    TCase *tc = tcase_create("layout");
    tcase_add_test(tc, test_light_grid_for_is_the_squarest_factorisation);
    tcase_add_test(tc, test_light_cell_point_stays_in_its_cell);
    tcase_add_test(tc, test_light_concentric_maps_onto_the_disk);
    tcase_add_test(tc, test_light_frame_is_orthonormal_and_right_handed);
    tcase_add_test(tc, test_sampler_mixed_counter_table_is_sampler_mix);
    suite_add_tcase(s, tc);
    return s;
}
