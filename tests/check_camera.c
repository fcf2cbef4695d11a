/*
 * Tests of camera_ray: directions and origins derived from the camera's
 * definition (spec/language.md, camera block) by hand.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "testlib.h"
#include "render/camera.h"
#include "scene/scene.h"

static scene_camera camera(scene_camera_kind kind, double fov, double width)
{
    /* Eye at +z looking at the origin with y up: forward -z, right +x. */
    scene_camera c;
    memset(&c, 0, sizeof c);
    c.kind = kind;
    c.eye = vec_make(0, 0, 5);
    c.look_at = vec_make(0, 0, 0);
    c.up = vec_make(0, 1, 0);
    c.fov = fov;
    c.width = width;
    c.forward = vec_make(0, 0, -1);
    c.right = vec_make(1, 0, 0);
    c.true_up = vec_make(0, 1, 0);
    return c;
}

START_TEST(test_camera_ray_centre_is_forward)
{
    scene_camera c = camera(CAMERA_PERSPECTIVE, 60, 2);
    ray r = camera_ray(&c, camera_half(&c), 100, 50, 50, 25);
    ck_assert_vec_near(r.dir, vec_make(0, 0, -1), 1e-16);
    ck_assert_vec_near(r.origin, c.eye, 0);
}
END_TEST

START_TEST(test_camera_ray_edges_span_the_horizontal_fov)
{
    /* fov 90: the right edge's ray is at 45 degrees, (1, 0, -1)/sqrt2; the
     * top edge of a 2:1 image is at half that slope, (0, 0.5, -1)/|...|. */
    scene_camera c = camera(CAMERA_PERSPECTIVE, 90, 2);
    ray right = camera_ray(&c, camera_half(&c), 200, 100, 200, 50);
    ck_assert_vec_near(right.dir, vec_make(1 / sqrt(2.0), 0, -1 / sqrt(2.0)), 1e-15);
    ray top = camera_ray(&c, camera_half(&c), 200, 100, 100, 0);
    double len = sqrt(1.25);
    ck_assert_vec_near(top.dir, vec_make(0, 0.5 / len, -1 / len), 1e-15);
}
END_TEST

/* The screen's half-width tan(fov/2), by hand: fov 90 gives tan 45 = 1,
 * fov 60 tan 30 = 1/sqrt(3) (each within the rounding of pi/180 and of
 * tan); an orthographic camera 0 (its rays take width/2 instead). */
START_TEST(test_camera_half_is_the_tangent_of_half_the_fov)
{
    scene_camera c = camera(CAMERA_PERSPECTIVE, 90, 2);
    ck_assert(fabs(camera_half(&c) - 1.0) <= 2 * DBL_EPSILON);
    c.fov = 60;
    ck_assert(fabs(camera_half(&c) - 1.0 / sqrt(3.0)) <= 2 * DBL_EPSILON);
    c = camera(CAMERA_ORTHOGRAPHIC, 90, 2);
    ck_assert(camera_half(&c) == 0.0);
}
END_TEST

START_TEST(test_camera_ray_orthographic_offsets_the_origin)
{
    /* width 4 on a 4x2 image: x spans [-2, 2], y spans [-1, 1]; the centre
     * of pixel (3, 0) is at x = 3.5 -> 1.5, y = 0.5 -> 0.5. */
    scene_camera c = camera(CAMERA_ORTHOGRAPHIC, 60, 4);
    ray r = camera_ray(&c, camera_half(&c), 4, 2, 3.5, 0.5);
    ck_assert_vec_near(r.origin, vec_make(1.5, 0.5, 5), 1e-15);
    ck_assert_vec_near(r.dir, vec_make(0, 0, -1), 0);
}
END_TEST

Suite *suite_camera(void)
{
    Suite *s = suite_create("camera");
    TCase *tc = tcase_create("camera_ray");
    tcase_add_test(tc, test_camera_ray_centre_is_forward);
    tcase_add_test(tc, test_camera_ray_edges_span_the_horizontal_fov);
    tcase_add_test(tc, test_camera_ray_orthographic_offsets_the_origin);
    tcase_add_test(tc, test_camera_half_is_the_tangent_of_half_the_fov);
    suite_add_tcase(s, tc);
    return s;
}
