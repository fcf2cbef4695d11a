/*
 * Tests of screen_offset, the static helper of src/render/camera.c whose
 * contract make prove checks (spec/proofs.md, "Rays and lights": the screen
 * point right*(sx*half) + true_up*(sy*half*aspect) of the pinhole formula,
 * camera.h).  It is static, so this file compiles camera.c itself with the
 * exported camera_ray and camera_half renamed; a new exported name in
 * camera.c that is not renamed here fails the link (two definitions),
 * loudly.
 *
 * Expected values are worked by hand with a basis of short binary
 * fractions (0.6 and 0.8 times powers of two round as 0.6 and 0.8 do), so
 * each product and sum below is the one the formula gives.
 */
#define camera_ray helpers_camera_ray
#define camera_half helpers_camera_half
#include "render/camera.c"
#undef camera_ray
#undef camera_half

#include <string.h>
#include "testlib.h"

static scene_camera basis(vec3 right, vec3 true_up)
{
    scene_camera c;
    memset(&c, 0, sizeof c);
    c.right = right;
    c.true_up = true_up;
    return c;
}

START_TEST(test_screen_offset_centre_is_zero)
{
    scene_camera c = basis(vec_make(0.6, 0.8, 0), vec_make(0, 0, 1));
    vec3 p = screen_offset(&c, 3, 0.75, 0, 0);
    ck_assert_vec_near(p, vec_make(0, 0, 0), 0);
}
END_TEST

START_TEST(test_screen_offset_scales_right_by_half_and_up_by_half_aspect)
{
    /* right (0.6, 0.8, 0) * (0.5 * 4) = (1.2, 1.6, 0);
     * up (0, 0, 1) * (0.25 * 4 * 0.5) = (0, 0, 0.5). */
    scene_camera c = basis(vec_make(0.6, 0.8, 0), vec_make(0, 0, 1));
    vec3 p = screen_offset(&c, 4, 0.5, 0.5, 0.25);
    ck_assert_vec_near(p, vec_make(1.2, 1.6, 0.5), 1e-15);
}
END_TEST

START_TEST(test_screen_offset_corners_take_the_signs_of_sx_sy)
{
    /* The top-left corner (sx = -1, sy = +1) of a 2:1 image (aspect 0.5)
     * with half = 1: -right + 0.5 up. */
    scene_camera c = basis(vec_make(1, 0, 0), vec_make(0, 1, 0));
    ck_assert_vec_near(screen_offset(&c, 1, 0.5, -1, 1), vec_make(-1, 0.5, 0), 0);
    ck_assert_vec_near(screen_offset(&c, 1, 0.5, 1, -1), vec_make(1, -0.5, 0), 0);
}
END_TEST

START_TEST(test_screen_offset_large_half_stays_finite)
{
    /* The contract's bound: half up to 2^54 (tan near 90 degrees), |sx|,
     * |sy| up to 2^32, aspect up to 2^31: at most 2^122 a component. */
    scene_camera c = basis(vec_make(1, 0, 0), vec_make(0, 1, 0));
    vec3 p = screen_offset(&c, 0x1p54, 0x1p31, 0x1p32, 0x1p32);
    ck_assert(isfinite(p.x) && isfinite(p.y) && isfinite(p.z));
    ck_assert(p.x == 0x1p86 && p.y == 0x1p117 && p.z == 0);
}
END_TEST

Suite *suite_camera_helpers(void)
{
    Suite *s = suite_create("camera_helpers");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_screen_offset_centre_is_zero);
    tcase_add_test(tc, test_screen_offset_scales_right_by_half_and_up_by_half_aspect);
    tcase_add_test(tc, test_screen_offset_corners_take_the_signs_of_sx_sy);
    tcase_add_test(tc, test_screen_offset_large_half_stays_finite);
    suite_add_tcase(s, tc);
    return s;
}
