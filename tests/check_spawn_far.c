/*
 * check_spawn_far.c - secondary rays from points near the largest double
 * (src/render/intersect.c, spawn_offset and offset_coord; spec/proofs.md,
 * "Rays and lights"): Eva showed that the spawn offset and the moved origin
 * became infinite there.  Now the origin is held at DBL_MAX and the offset
 * of a primitive whose magnitude passes DBL_MAX is that of DBL_MAX.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "testlib.h"
#include "render/intersect.h"
#include "base/xform.h"

/* A hit at x = DBL_MAX pushed outward: p + offset passes DBL_MAX, which
 * the origin is held at; the other coordinates do not move (n has no
 * part along them), the direction and interval are as for any ray. */
START_TEST(test_spawn_far_origin_held_at_dbl_max)
{
    vec3 p = vec_make(DBL_MAX, 1, -2), n = vec_make(1, 0, 0);
    ray out = ray_spawn(p, n, n);
    ck_assert(out.origin.x == DBL_MAX);
    ck_assert(out.origin.y == 1 && out.origin.z == -2);
    ck_assert(out.dir.x == 1 && out.dir.y == 0 && out.dir.z == 0);
    ck_assert(out.tmin == 0 && out.tmax == HUGE_VAL);
    ray back = ray_spawn(vec_make(-DBL_MAX, 0, 0), n, vec_make(-1, 0, 0));
    ck_assert(back.origin.x == -DBL_MAX);
    /* Inward from DBL_MAX: p - offset, a finite value below DBL_MAX. */
    ray in = ray_spawn(p, n, vec_make(-1, 0, 0));
    ck_assert(isfinite(in.origin.x) && in.origin.x < DBL_MAX);
    ck_assert(in.origin.x == DBL_MAX - (SPAWN_REL * DBL_MAX + SPAWN_ABS));
}
END_TEST

/* Past 2^1023 but not past DBL_MAX: the origin is p + offset as it would
 * be rounded anywhere else (the halves are exact). */
START_TEST(test_spawn_far_origin_rounds_as_the_sum)
{
    double x = 0x1.8p1023;   /* 1.3e308 */
    vec3 n = vec_make(0, 0, 1);
    ray r = ray_spawn(vec_make(0, 0, x), n, n);
    double offset = SPAWN_REL * x + SPAWN_ABS;
    ck_assert(r.origin.z == x + offset);
    ck_assert(r.origin.z > x);
    ray s = ray_spawn(vec_make(0, 0, -x), n, vec_make(0, 0, -1));
    ck_assert(s.origin.z == -x - offset);
}
END_TEST

/* A sphere at 1e308 of radius 1e308: its magnitude passes DBL_MAX (+Inf);
 * the shadow rays' offset is that of DBL_MAX, not infinite. */
START_TEST(test_spawn_far_infinite_magnitude)
{
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_SPHERE;
    p.mesh = -1;
    p.u.sphere.center = vec_make(1e308, 0, 0);
    p.u.sphere.radius = 1e308;
    ck_assert(isinf(isect_prim_magnitude(&p)));
    hit h;
    memset(&h, 0, sizeof h);
    h.point = vec_make(0, 0, 0);
    h.normal = h.shading_normal = vec_make(-1, 0, 0);
    shadow_start st = ray_shadow_start(&p, &h);
    ck_assert(st.offset == SPAWN_REL * DBL_MAX + SPAWN_ABS);
    ray r = ray_shadow_along(&st, vec_make(-1, 0, 0));
    ck_assert(isfinite(r.origin.x) && r.origin.x == -st.offset);
    ck_assert(r.tmin == st.offset);
}
END_TEST

/* A shadow ray toward a light less than 2^-1024 from its spawned origin
 * (issue 17; spec/proofs.md, "Rays and lights"): 1/dist is +Inf there and
 * to * (1/dist) made 0 * Inf = NaN components.  The hit is the origin on
 * the plane y = 0 (normal +y), so the origin is pushed to (0, SPAWN_ABS, 0)
 * (magnitude 0: the offset is SPAWN_ABS); the light one double above it
 * lies straight up, the other one on the least double along +x: the
 * direction is exactly the axis, the length of the step the distance. */
START_TEST(test_spawn_near_target_direction_is_unit)
{
    vec3 n = vec_make(0, 1, 0);
    double above = nextafter(SPAWN_ABS, 1);
    ray r = ray_spawn_to(vec_make(0, 0, 0), n, vec_make(0, above, 0));
    ck_assert(r.origin.x == 0 && r.origin.y == SPAWN_ABS && r.origin.z == 0);
    ck_assert_msg(r.dir.x == 0 && r.dir.y == 1 && r.dir.z == 0, "dir (%g, %g, %g)", (double)r.dir.x, (double)r.dir.y,
                  (double)r.dir.z);
    ck_assert(r.tmin == SPAWN_ABS);
    ck_assert(r.tmax > 0 && r.tmax <= above - SPAWN_ABS);
    shadow_start st;
    st.point = vec_make(0, 0, 0);
    st.normal = n;
    st.offset = SPAWN_ABS;
    ray s = ray_shadow_to(&st, vec_make(0x1p-1074, SPAWN_ABS, 0));
    ck_assert(s.origin.y == SPAWN_ABS);
    ck_assert_msg(s.dir.x == 1 && s.dir.y == 0 && s.dir.z == 0, "dir (%g, %g, %g)", (double)s.dir.x, (double)s.dir.y,
                  (double)s.dir.z);
    ck_assert(s.tmax > 0 && s.tmax <= 0x1p-1074);
    /* Both unit (and finite: NaN fails every comparison). */
    ck_assert(r.dir.x * r.dir.x + r.dir.y * r.dir.y + r.dir.z * r.dir.z == 1);
    ck_assert(s.dir.x * s.dir.x + s.dir.y * s.dir.y + s.dir.z * s.dir.z == 1);
}
END_TEST

Suite *suite_spawn_far(void)
{
    Suite *s = suite_create("spawn_far");
    TCase *tc = tcase_create("far");
    tcase_add_test(tc, test_spawn_far_origin_held_at_dbl_max);
    tcase_add_test(tc, test_spawn_far_origin_rounds_as_the_sum);
    tcase_add_test(tc, test_spawn_far_infinite_magnitude);
    tcase_add_test(tc, test_spawn_near_target_direction_is_unit);
    suite_add_tcase(s, tc);
    return s;
}
