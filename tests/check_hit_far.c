/*
 * check_hit_far.c - hit tests whose ray parameter passes the largest double
 * (src/render/isect_common.c isect_quotient, isect_sphere_roots;
 * src/render/intersect.c plane_t, box_slabs; spec/proofs.md, "Hit tests"):
 * Eva showed that a direction nearly along a plane, a slab or a cylinder's
 * axis divided a finite distance into an infinity.  Each case here raised
 * the overflow flag before; now the quotient is decided before dividing and
 * held at 2^1020, and the answer is the one the infinity gave.
 */
#include <fenv.h>
#include <float.h>
#include <math.h>
#include "testlib.h"
#include "render/intersect.h"

#define FE_BAD (FE_OVERFLOW | FE_INVALID | FE_DIVBYZERO)

static ray ray_of(vec3 o, vec3 d)
{
    ray r;
    r.origin = o;
    r.dir = d;
    r.tmin = 0;
    r.tmax = HUGE_VAL;
    return r;
}

/* n.(p0 - o) = 2^500 over n.d = 2^-600: t = 2^1100, past DBL_MAX.  A miss,
 * as the infinity was (t < tmax fails). */
START_TEST(test_hit_far_plane_nearly_parallel)
{
    ray r = ray_of(vec_make(0, 0, 0), vec_make(1, 0, 0x1p-600));
    hit h;
    feclearexcept(FE_ALL_EXCEPT);
    int found = isect_plane(vec_make(0, 0, 0x1p500), vec_make(0, 0, 1), &r, &h);
    ck_assert(!fetestexcept(FE_BAD));
    ck_assert_int_eq(found, 0);
    ck_assert(r.tmax == HUGE_VAL);
    /* Not parallel: hit as ever (t = 2^500 / 2^-1 = 2^501). */
    ray s = ray_of(vec_make(0, 0, 0), vec_make(1, 0, 0.5));
    ck_assert_int_eq(isect_plane(vec_make(0, 0, 0x1p500), vec_make(0, 0, 1), &s, &h), 1);
    ck_assert(h.t == 0x1p501);
}
END_TEST

/* The unit box seen from inside its y and z slabs, the ray along x with a
 * y part of 2^-1074: the y slab's (lo - o)/d was -Inf and +Inf.  The hit is
 * the x face at 0, entered at t = 5, as before. */
START_TEST(test_hit_far_box_nearly_along_a_slab)
{
    ray r = ray_of(vec_make(-5, 0.5, 0.5), vec_make(1, 0x1p-1074, 0));
    hit h;
    feclearexcept(FE_ALL_EXCEPT);
    int found = isect_box(vec_make(0, 0, 0), vec_make(1, 1, 1), &r, &h);
    ck_assert(!fetestexcept(FE_BAD));
    ck_assert_int_eq(found, 1);
    ck_assert(h.t == 5);
    ck_assert(h.normal.x == -1 && h.normal.y == 0 && h.normal.z == 0);
    /* Outside the y slab by 2^30: both y crossings past DBL_MAX, a miss. */
    ray s = ray_of(vec_make(-5, -0x1p30, 0.5), vec_make(1, 0x1p-1000, 0));
    feclearexcept(FE_ALL_EXCEPT);
    found = isect_box(vec_make(0, 0, 0), vec_make(1, 1, 1), &s, &h);
    ck_assert(!fetestexcept(FE_BAD));
    ck_assert_int_eq(found, 0);
}
END_TEST

/* A sphere 2^500 away along a direction of 2^-530: the foot -b/a is at
 * 2^1030.  A miss (the roots are past DBL_MAX), as the NaNs gave. */
START_TEST(test_hit_far_sphere_tiny_direction)
{
    ray r = ray_of(vec_make(0x1p500, 0, 0), vec_make(-0x1p-530, 0, 0));
    hit h;
    feclearexcept(FE_ALL_EXCEPT);
    int found = isect_sphere(vec_make(0, 0, 0), 1, &r, &h);
    ck_assert(!fetestexcept(FE_BAD));
    ck_assert_int_eq(found, 0);
}
END_TEST

/* Inside a cylinder of radius 2^500, 2^499 off its axis, the ray within
 * 2^-530 of the axis direction: the side's roots c/q and q/a are at about
 * -+2^1030 (they were -Inf and +Inf).  The ray leaves through the cap at
 * z = 1, at t = 0.5. */
START_TEST(test_hit_far_cylinder_along_its_axis)
{
    ray r = ray_of(vec_make(0, 0x1p499, 0.5), vec_make(0x1p-530, 0, 1));
    hit h;
    feclearexcept(FE_ALL_EXCEPT);
    int found = isect_cylinder(vec_make(0, 0, 0), vec_make(0, 0, 1), 0x1p500, 0, &r, &h);
    ck_assert(!fetestexcept(FE_BAD));
    ck_assert_int_eq(found, 1);
    ck_assert(h.t == 0.5);
    ck_assert(h.normal.x == 0 && h.normal.y == 0 && h.normal.z == 1);
}
END_TEST

Suite *suite_hit_far(void)
{
    Suite *s = suite_create("hit_far");
    TCase *tc = tcase_create("far");
    tcase_add_test(tc, test_hit_far_plane_nearly_parallel);
    tcase_add_test(tc, test_hit_far_box_nearly_along_a_slab);
    tcase_add_test(tc, test_hit_far_sphere_tiny_direction);
    tcase_add_test(tc, test_hit_far_cylinder_along_its_axis);
    suite_add_tcase(s, tc);
    return s;
}
