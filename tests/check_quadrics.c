/* Tests of the cylinder, cone and torus hit tests (src/render/intersect_quadric.c,
 * intersect_torus.c), their bounds, magnitudes and containment
 * (scene_prim_contains).  Every expected t, point and normal is worked out by
 * hand in the comment next to it, or checked by another route (the distance
 * to the surface computed from its definition). */
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "testlib.h"
#include "render/intersect.h"
#include "render/trace.h"
#include "render/render.h"
#include "image/image.h"
#include "scene/scene.h"
#include "io/scene_file.h"
#include "base/xform.h"

static ray make_ray(vec3 o, vec3 d)
{
    ray r;
    r.origin = o;
    r.dir = d;
    r.tmin = 0.0;
    r.tmax = HUGE_VAL;
    return r;
}

static scene_prim blank(scene_prim_kind kind)
{
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    p.mesh = -1;
    return p;
}

static scene_prim cylinder(vec3 from, vec3 to, double radius, int open)
{
    scene_prim p = blank(PRIM_CYLINDER);
    p.u.cylinder.from = from;
    p.u.cylinder.to = to;
    p.u.cylinder.radius = radius;
    p.u.cylinder.open = open;
    return p;
}

static scene_prim cone(vec3 from, double r0, vec3 to, double r1, int open)
{
    scene_prim p = blank(PRIM_CONE);
    p.u.cone.from = from;
    p.u.cone.to = to;
    p.u.cone.radius[0] = r0;
    p.u.cone.radius[1] = r1;
    p.u.cone.open = open;
    return p;
}

static scene_prim torus(vec3 c, vec3 axis, double major, double minor)
{
    scene_prim p = blank(PRIM_TORUS);
    p.u.torus.center = c;
    p.u.torus.axis = axis;
    p.u.torus.major = major;
    p.u.torus.minor = minor;
    return p;
}

/* The crossings of p along r, checked against the expected t, normals and
 * entering flags, in order. */
static void expect_crossings(const scene_prim *p, ray r, int count, const double *t, const vec3 *n, const int *entering,
                             double tol)
{
    hit out[ISECT_MAX_CROSSINGS];
    int got = isect_prim_all(p, &r, out);
    ck_assert_int_eq(got, count);
    for (int i = 0; i < count; i++) {
        ck_assert_near(out[i].t, t[i], tol);
        ck_assert_vec_near(out[i].normal, n[i], tol);
        ck_assert_vec_near(out[i].point, ray_at(&r, t[i]), tol * (1 + fabs(t[i])));
        ck_assert_int_eq(out[i].entering, entering[i]);
        ck_assert_int_eq(out[i].prim, -1);
    }
    hit h;
    ray rr = r;
    ck_assert_int_eq(isect_prim(p, &rr, &h), count > 0);
    if (count > 0) {
        ck_assert_near(h.t, t[0], tol);
        ck_assert_near(rr.tmax, h.t, 0);
    }
}

/* Unit cylinder on the z axis from 0 to 2: a ray along -x at height 1
 * enters the side at x = 1 (t = 2) and leaves at x = -1 (t = 4); one down
 * the axis 0.5 off it crosses the caps at z = 2 (t = 3) and z = 0 (t = 5).
 * Open, the first is a sheet crossed twice; the second misses. */
START_TEST(test_cylinder_by_hand)
{
    scene_prim c = cylinder(vec_make(0, 0, 0), vec_make(0, 0, 2), 1, 0), o = c;
    o.u.cylinder.open = 1;
    const double side_t[] = {2, 4}, cap_t[] = {3, 5};
    const vec3 side_n[] = {vec_make(1, 0, 0), vec_make(-1, 0, 0)};
    const vec3 cap_n[] = {vec_make(0, 0, 1), vec_make(0, 0, -1)};
    const int in_out[] = {1, 0};
    ray across = make_ray(vec_make(3, 0, 1), vec_make(-1, 0, 0)), down = make_ray(vec_make(0.5, 0, 5), vec_make(0, 0, -1));
    expect_crossings(&c, across, 2, side_t, side_n, in_out, 1e-15);
    expect_crossings(&c, down, 2, cap_t, cap_n, in_out, 1e-15);
    expect_crossings(&o, across, 2, side_t, side_n, in_out, 1e-15);
    expect_crossings(&o, down, 0, NULL, NULL, NULL, 0);
    /* From inside: only the exit (t = 1 to x = 1, normal +x, leaving). */
    const double exit_t[] = {1};
    const vec3 exit_n[] = {vec_make(1, 0, 0)};
    const int leaving[] = {0};
    expect_crossings(&c, make_ray(vec_make(0, 0, 1), vec_make(1, 0, 0)), 1, exit_t, exit_n, leaving, 1e-15);
    /* A non-unit direction: t scales, the point does not. */
    expect_crossings(&c, make_ray(vec_make(3, 0, 1), vec_make(-2, 0, 0)), 2, (const double[]){1, 2}, side_n, in_out,
                     1e-15);
}
END_TEST

/* A cone with radius 1 at z = 0 and its apex at z = 1: the side is
 * |p'| = 1 - z, slope k = -1, outward normal (rho^ + a)/sqrt(2).  Across at
 * z = 0.5: the side is at x = +-0.5 (t = 1.5, 2.5).  Up the axis 0.25 off
 * it: the base at t = 1, then the side where 1 - z = 0.25, z = 0.75
 * (t = 1.75).  Down the axis itself: the apex (t = 4, normal +z: away
 * from the cone), then the base (t = 5): the line is inside the double
 * cone throughout (a < 0) and the slab keeps one nappe. */
START_TEST(test_cone_by_hand)
{
    scene_prim c = cone(vec_make(0, 0, 0), 1, vec_make(0, 0, 1), 0, 0);
    double s = sqrt(0.5);
    const int in_out[] = {1, 0};
    expect_crossings(&c, make_ray(vec_make(2, 0, 0.5), vec_make(-1, 0, 0)), 2, (const double[]){1.5, 2.5},
                     (const vec3[]){vec_make(s, 0, s), vec_make(-s, 0, s)}, in_out, 1e-15);
    expect_crossings(&c, make_ray(vec_make(0.25, 0, -1), vec_make(0, 0, 1)), 2, (const double[]){1, 1.75},
                     (const vec3[]){vec_make(0, 0, -1), vec_make(s, 0, s)}, in_out, 1e-15);
    expect_crossings(&c, make_ray(vec_make(0, 0, 5), vec_make(0, 0, -1)), 2, (const double[]){4, 5},
                     (const vec3[]){vec_make(0, 0, 1), vec_make(0, 0, -1)}, in_out, 1e-15);
    /* Truncated, radii 1 and 0.5 over a length of 1 (k = -0.5): up the axis
     * 0.75 off it the side is met where 1 - 0.5 z = 0.75, z = 0.5. */
    scene_prim tr = cone(vec_make(0, 0, 0), 1, vec_make(0, 0, 1), 0.5, 0);
    double n = 1 / sqrt(1.25);
    expect_crossings(&tr, make_ray(vec_make(0.75, 0, -1), vec_make(0, 0, 1)), 2, (const double[]){1, 1.5},
                     (const vec3[]){vec_make(0, 0, -1), vec_make(n, 0, 0.5 * n)}, in_out, 1e-15);
    /* Open: the same ray meets the side only. */
    tr.u.cone.open = 1;
    expect_crossings(&tr, make_ray(vec_make(0.75, 0, -1), vec_make(0, 0, 1)), 1, (const double[]){1.5},
                     (const vec3[]){vec_make(n, 0, 0.5 * n)}, (const int[]){0}, 1e-15);
}
END_TEST

/* The steepest valid cone ([LANG-EXTENT-1]): radius 2^500 at z = 0, its
 * apex 2^-500 above, slope k = -2^1000.  A ray down the line x = 2^499
 * from z = 2^30 meets the side where the radius is 2^499, at z = 2^-501:
 * t = 2^30 - 2^-501, which is 2^30 in doubles; the normal (x^ - k z^)
 * normalised is +z to 2^-1000, entering.  Unscaled, k z0 = -2^1030
 * overflowed and the cone was missed (spec/proofs.md, "Round 8d"). */
START_TEST(test_cone_steepest)
{
    for (int open = 0; open <= 1; open++) {
        scene_prim c = cone(vec_make(0, 0, 0), 0x1p500, vec_make(0, 0, 0x1p-500), 0, open);
        ray r = make_ray(vec_make(0x1p499, 0, 0x1p30), vec_make(0, 0, -1));
        hit h;
        ck_assert_int_eq(isect_prim(&c, &r, &h), 1);
        ck_assert_near(h.t, 0x1p30, 0);
        ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 1e-15);
        ck_assert_int_eq(h.entering, 1);
    }
}
END_TEST

/* Torus about z, major 2, minor 0.5.  Along -x in its plane: the tube is
 * crossed at x = 2.5, 1.5, -1.5, -2.5 (t = 2.5, 3.5, 6.5, 7.5) with outward
 * normals +x, -x, +x, -x.  Down through the tube at x = 2: z = +-0.5
 * (t = 4.5, 5.5).  Down the axis: through the hole, no hit.  From the
 * centre along +x: the inner wall at x = 1.5 (t = 1.5, normal -x, entering). */
START_TEST(test_torus_by_hand)
{
    scene_prim t = torus(vec_make(0, 0, 0), vec_make(0, 0, 1), 2, 0.5);
    const vec3 px = vec_make(1, 0, 0), nx = vec_make(-1, 0, 0);
    expect_crossings(&t, make_ray(vec_make(5, 0, 0), nx), 4, (const double[]){2.5, 3.5, 6.5, 7.5},
                     (const vec3[]){px, nx, px, nx}, (const int[]){1, 0, 1, 0}, 1e-14);
    expect_crossings(&t, make_ray(vec_make(2, 0, 5), vec_make(0, 0, -1)), 2, (const double[]){4.5, 5.5},
                     (const vec3[]){vec_make(0, 0, 1), vec_make(0, 0, -1)}, (const int[]){1, 0}, 1e-14);
    expect_crossings(&t, make_ray(vec_make(0, 0, 5), vec_make(0, 0, -1)), 0, NULL, NULL, NULL, 0);
    expect_crossings(&t, make_ray(vec_make(0, 0, 0), px), 2, (const double[]){1.5, 2.5}, (const vec3[]){nx, px},
                     (const int[]){1, 0}, 1e-14);
    /* tmin and tmax cut the crossings: only those in (3, 7) remain. */
    ray cut = make_ray(vec_make(5, 0, 0), nx);
    cut.tmin = 3;
    cut.tmax = 7;
    expect_crossings(&t, cut, 2, (const double[]){3.5, 6.5}, (const vec3[]){nx, px}, (const int[]){0, 1}, 1e-14);
}
END_TEST

/* [NUM-TORUS-1] A tube of radius 1e-3 at 1e6 from the origin, seen from
 * 100 above: the hit is 1e-3 above the plane of the ring (t = 100 - 1e-3),
 * within an ulp of 1e6 of the tube, with the normal +z. */
START_TEST(test_torus_thin_far)
{
    scene_prim t = torus(vec_make(1e6, 0, 0), vec_make(0, 0, 1), 1, 1e-3);
    ray r = make_ray(vec_make(1e6 + 1, 0, 100), vec_make(0, 0, -1));
    hit h;
    ck_assert(isect_prim(&t, &r, &h));
    ck_assert_near(h.t, 100 - 1e-3, 1e-12);
    ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 1e-9);
    ck_assert_near(h.point.x, 1e6 + 1, 2.4e-10);
    ck_assert_near(h.point.z, 1e-3, 1e-15);
}
END_TEST

/* A torus 2^-298 across seen from 2^100 (within the extent,
 * [LANG-EXTENT-1]) along a line 2 minor above its plane: no point of the
 * line is on it (every point of the torus has |z| <= minor).  The chord's
 * middle is formed with an error of about 2^48 (2^-52 of the distance),
 * 2^346 times the bounding radius: before round 9 the quartic's
 * coefficients, of that to the fourth power, overflowed (FE_OVERFLOW; the
 * infinities then gave no root).  Now that middle is no hit before any of
 * it is formed (spec/proofs.md, "Round 9").  From 2^-290 (a distance of
 * 2^8 radii) the same line in the plane hits the tube at x = major + minor. */
START_TEST(test_torus_far_tiny_forms_no_infinity)
{
    scene_prim t = torus(vec_make(0, 0, 0), vec_make(0, 0, 1), 0x1p-298, 0x1p-301);
    ray r = make_ray(vec_make(0x1.a200000000004p+100, 0, 0x1p-300), vec_make(-1, 0, 0));
    hit h;
    feclearexcept(FE_ALL_EXCEPT);
    int found = isect_prim(&t, &r, &h);
    ck_assert(!fetestexcept(FE_OVERFLOW | FE_INVALID | FE_DIVBYZERO));
    ck_assert_int_eq(found, 0);
    ray near = make_ray(vec_make(0x1.8p-290, 0, 0), vec_make(-1, 0, 0));
    ck_assert_int_eq(isect_prim(&t, &near, &h), 1);
    ck_assert(h.t == 0x1.8p-290 - (0x1p-298 + 0x1p-301));
    ck_assert_vec_near(h.normal, vec_make(1, 0, 0), 1e-15);
}
END_TEST

/* A torus scaled by 2 along its axis (kept in its local frame): the tube's
 * top seen from above at x = 2 is at z = 2 * 0.5 = 1 (t = 4). */
START_TEST(test_torus_transformed)
{
    scene_prim t = torus(vec_make(0, 0, 0), vec_make(0, 0, 1), 2, 0.5);
    xform w = xform_scale(vec_make(1, 1, 2));
    scene_frame f;
    f.to_world = w;
    ck_assert(xform_invert(&w, &f.to_local));
    t.frame = &f;
    ray r = make_ray(vec_make(2, 0, 5), vec_make(0, 0, -1));
    hit h;
    ck_assert(isect_prim(&t, &r, &h));
    ck_assert_near(h.t, 4, 1e-14);
    ck_assert_vec_near(h.point, vec_make(2, 0, 1), 1e-14);
    ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 1e-14);
}
END_TEST

/* The rim of a closed cylinder or cone leaves no gap: a ray aimed at a
 * point of the rim from any direction that enters the solid there (toward
 * both the side's and the cap's inside) hits, at about the distance to
 * the rim. */
START_TEST(test_rim_is_closed)
{
    scene_prim shapes[2] = {cylinder(vec_make(0.3, -0.2, 0.1), vec_make(1.3, 0.8, -0.4), 0.7, 0),
                         cone(vec_make(0.3, -0.2, 0.1), 0.9, vec_make(1.3, 0.8, -0.4), 0.2, 0)};
    uint64_t state = 12345;
    for (int k = 0; k < 2; k++) {
        const scene_prim *p = &shapes[k];
        vec3 from = p->kind == PRIM_CONE ? p->u.cone.from : p->u.cylinder.from;
        vec3 to = p->kind == PRIM_CONE ? p->u.cone.to : p->u.cylinder.to;
        vec3 a = vec_normalize(vec_sub(to, from)), u = vec_normalize(vec_cross(a, vec_make(0, 0, 1)));
        vec3 v = vec_cross(a, u);
        for (int i = 0; i < 2000; i++) {
            state = state * 6364136223846793005u + 1442695040888963407u;
            double phi = (double)(state >> 11) * 0x1p-53 * 6.283185307179586;
            int top = i & 1;
            double radius = p->kind == PRIM_CONE ? p->u.cone.radius[top] : p->u.cylinder.radius;
            vec3 radial = vec_add(vec_scale(u, cos(phi)), vec_scale(v, sin(phi)));
            vec3 rim = vec_madd(top ? to : from, radial, radius);
            /* come from outside, diagonally across the edge */
            vec3 out = vec_normalize(vec_add(radial, vec_scale(a, top ? 1.0 : -1.0)));
            ray r = make_ray(vec_madd(rim, out, 2.0), vec_neg(out));
            hit h;
            ck_assert_msg(isect_prim(p, &r, &h), "shape %d rim point %d missed", k, i);
            ck_assert_near(h.t, 2.0, 1e-12);
        }
    }
}
END_TEST

/* Bounds: the box of the end disks, or of the ring plus the tube. */
START_TEST(test_quadric_bounds_and_magnitude)
{
    vec3 lo, hi;
    scene_prim c = cylinder(vec_make(0, 0, 0), vec_make(3, 0, 0), 1, 0);
    ck_assert(isect_prim_bounds(&c, &lo, &hi));
    ck_assert_vec_near(lo, vec_make(0, -1, -1), 0);
    ck_assert_vec_near(hi, vec_make(3, 1, 1), 0);
    scene_prim k = cone(vec_make(0, 0, 0), 1, vec_make(0, 0, 2), 0.5, 0);
    ck_assert(isect_prim_bounds(&k, &lo, &hi));
    ck_assert_vec_near(lo, vec_make(-1, -1, 0), 0);
    ck_assert_vec_near(hi, vec_make(1, 1, 2), 0);
    scene_prim t = torus(vec_make(1, -7, 3), vec_make(0, 0, 1), 2, 0.5);
    ck_assert(isect_prim_bounds(&t, &lo, &hi));
    ck_assert_vec_near(lo, vec_make(-1.5, -9.5, 2.5), 0);
    ck_assert_vec_near(hi, vec_make(3.5, -4.5, 3.5), 0);
    /* |centre|max 7 + major 2 + minor 0.5; the cylinder's ends 3 + radius 1 */
    ck_assert_near(isect_prim_magnitude(&t), 9.5, 0);
    ck_assert_near(isect_prim_magnitude(&c), 4, 0);
    ck_assert_near(isect_prim_magnitude(&k), 3, 0);
    /* A tilted axis: a unit cylinder along (1,1,0)/sqrt2 spans
     * sqrt(1 - 1/2) across x and y about each end, 1 along z. */
    scene_prim d = cylinder(vec_make(0, 0, 0), vec_make(1, 1, 0), 1, 1);
    ck_assert(isect_prim_bounds(&d, &lo, &hi));
    ck_assert_vec_near(lo, vec_make(-sqrt(0.5), -sqrt(0.5), -1), 1e-15);
    ck_assert_vec_near(hi, vec_make(1 + sqrt(0.5), 1 + sqrt(0.5), 1), 1e-15);
}
END_TEST

/* Containment (the medium stack's probe, the buried-light warning): a
 * closed cylinder and cone, and the torus's tube; an open one holds
 * nothing. */
START_TEST(test_quadric_contains)
{
    scene_prim c = cylinder(vec_make(0, 0, 0), vec_make(0, 0, 2), 1, 0);
    ck_assert(scene_prim_contains(&c, vec_make(0.5, 0.5, 1)));
    ck_assert(!scene_prim_contains(&c, vec_make(0.8, 0.8, 1)));
    ck_assert(!scene_prim_contains(&c, vec_make(0, 0, 2.5)));
    c.u.cylinder.open = 1;
    ck_assert(!scene_prim_contains(&c, vec_make(0.5, 0.5, 1)));
    ck_assert(!scene_prim_is_solid(&c) && scene_prim_self_shadows(&c));
    scene_prim k = cone(vec_make(0, 0, 0), 1, vec_make(0, 0, 1), 0, 0);
    ck_assert(scene_prim_contains(&k, vec_make(0.3, 0, 0.6)));   /* radius there 0.4 */
    ck_assert(!scene_prim_contains(&k, vec_make(0.5, 0, 0.6)));
    ck_assert(scene_prim_is_solid(&k) && scene_prim_self_shadows(&k));  /* seen from inside */
    scene_prim t = torus(vec_make(0, 0, 0), vec_make(0, 0, 1), 2, 0.5);
    ck_assert(scene_prim_contains(&t, vec_make(0, 2.2, 0.3)));    /* distance sqrt(0.13) < 0.5 */
    ck_assert(!scene_prim_contains(&t, vec_make(0, 0, 0)));       /* the hole */
    ck_assert(scene_prim_is_solid(&t) && scene_prim_self_shadows(&t));
}
END_TEST

/* A ray leaving a hit by ray_spawn_hit, outward or inward, never meets the
 * surface it leaves at about t = 0 (it may meet it again further on). */
START_TEST(test_quadric_spawn_no_self_hit)
{
    scene_prim shapes[3] = {cylinder(vec_make(1e4, 2, 3), vec_make(1e4 + 2, 4, 3), 0.5, 1),
                         cone(vec_make(-3, 1e3, 0), 0.8, vec_make(-3, 1e3 + 2, 1), 0.1, 0),
                         torus(vec_make(5, 5, -1e5), vec_normalize(vec_make(1, 2, 3)), 1, 0.1)};
    uint64_t state = 99;
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3000; i++) {
            vec3 lo, hi;
            ck_assert(isect_prim_bounds(&shapes[k], &lo, &hi));
            double u[6];
            for (int j = 0; j < 6; j++) {
                state = state * 6364136223846793005u + 1442695040888963407u;
                u[j] = (double)(state >> 11) * 0x1p-53;
            }
            vec3 target = vec_make(lo.x + u[0] * (hi.x - lo.x), lo.y + u[1] * (hi.y - lo.y), lo.z + u[2] * (hi.z - lo.z));
            vec3 dir = vec_normalize(vec_make(u[3] - 0.5, u[4] - 0.5, u[5] - 0.5));
            ray r = make_ray(vec_madd(target, dir, -10), dir);
            hit h;
            if (!isect_prim(&shapes[k], &r, &h))
                continue;
            vec3 out = vec_normalize(vec_add(h.normal, vec_scale(dir, 0.3)));
            for (int side = 0; side < 2; side++) {
                vec3 d = side ? vec_neg(out) : out;
                ray s = ray_spawn_hit(&shapes[k], &h, d);
                hit h2;
                if (isect_prim(&shapes[k], &s, &h2))
                    ck_assert_msg(h2.t > 1e-6, "shape %d: a spawned ray met its own surface at t = %g", k,
                                  (double)h2.t);
            }
        }
}
END_TEST

static scene_model *load(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text("test.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d):\n%s", status, text);
    return s;
}

/* The radiance along one ray through the scene, as the renderer traces a
 * camera ray (starting in air). */
static rgb trace_one(const scene_model *s, vec3 o, vec3 d, trace_stats *st)
{
    tracer t;
    medium_stack air;
    memset(&air, 0, sizeof air);
    memset(st, 0, sizeof *st);
    ck_assert(tracer_init(&t, s, 0, 0));
    ray r = make_ray(o, d);
    rgb c = trace_ray(&t, &r, 1, &air, 0, st);
    tracer_free(&t);
    return c;
}

/* [SHADE-SHADOW-1] Shadows through a clear torus (t = 0.5, ior 1): a
 * plane point under the tube sees the light through 2 surfaces (0.5^2 of
 * Kd E = 0.5: 0.125), one under the hole or beyond the ring all of it
 * (0.5); a wall point behind the ring seen along its plane, through 4
 * (0.5^4 of 0.5). */
START_TEST(test_torus_transparent_shadow)
{
    scene_model *s = load("material clear { Kd 0 t 0.5 ior 1 }\n"
                       "torus { center [0, 1, 0] axis [0, 1, 0] major 1 minor 0.25 material clear }\n"
                       "plane { normal [0, 1, 0] material { Kd 0.5 } }\n"
                       "distant_light { direction [0, -1, 0] }\n");
    trace_stats st;
    static const double x[] = {1, 1.24, 0, 1.3, -0.8};
    static const double want[] = {0.125, 0.125, 0.5, 0.5, 0.125};
    for (int i = 0; i < 5; i++) {
        rgb c = trace_one(s, vec_make(x[i], 0.1, 0.01), vec_make(0, -1, 0), &st);
        ck_assert_msg(fabs(c.x - want[i]) < 1e-12, "x = %g: %.17g, expected %g", x[i], (double)c.x, want[i]);
    }
    scene_free(s);
    s = load("material clear { Kd 0 t 0.5 ior 1 }\n"
             "torus { axis [0, 1, 0] major 1 minor 0.25 material clear }\n"
             "plane { point [-5, 0, 0] normal [1, 0, 0] material { Kd 0.5 } }\n"
             "point_light { position [5, 0, 0] falloff none }\n");
    rgb c = trace_one(s, vec_make(-4.9, 0, 0), vec_make(-1, 0, 0), &st);
    ck_assert_msg(fabs(c.x - 0.5 * 0.0625) < 1e-12, "%.17g", (double)c.x);
    scene_free(s);
}
END_TEST

/* [LANG-FEATURES-1] A torus shadows itself: from the centre, the inner
 * wall at x = 1.5 faces a light coming from -x (N.L = 1), but the far side
 * of the ring stands in the way: only the ambient Kd Ia = 0.5 * 0.2 is
 * left.  Lit from above, the top of the tube is not shadowed. */
START_TEST(test_torus_shadows_itself)
{
    scene_model *s = load("ambient { color 0.2 }\n"
                       "torus { axis [0, 1, 0] major 2 minor 0.5 material { Kd 0.5 } }\n"
                       "distant_light { direction [1, 0, 0] }\n");
    ck_assert(s->features.shadows);
    trace_stats st;
    rgb c = trace_one(s, vec_make(0, 0, 0), vec_make(1, 0, 0), &st);
    ck_assert_msg(fabs(c.x - 0.1) < 1e-15, "%.17g", (double)c.x);
    ck_assert_int_eq(st.shadow_rays, 1);
    scene_free(s);
    /* Lit from above, a point on the tube's top (N = +y): Kd (Ia + E). */
    s = load("ambient { color 0.2 }\n"
             "torus { axis [0, 1, 0] major 2 minor 0.5 material { Kd 0.5 } }\n"
             "distant_light { direction [0, -1, 0] }\n");
    c = trace_one(s, vec_make(2, 5, 0), vec_make(0, -1, 0), &st);
    ck_assert_msg(fabs(c.x - 0.6) < 1e-15, "%.17g", (double)c.x);
    scene_free(s);
}
END_TEST

/* [NUM-GLASS-2] [SHADE-SNELL-1] Glass cylinders and tori are solids: a ray down the
 * axis of a glass cylinder meets both caps at normal incidence and passes
 * straight through (two refracted rays, the background times t^2); a point
 * inside the cylinder or inside the torus's tube starts in its glass; one
 * in the torus's hole or inside an open cylinder does not. */
START_TEST(test_quadric_glass)
{
    scene_model *s = load("image { background 1 max_depth 5 }\n"
                       "cylinder { from [0, 0, 0] to [0, 0, -2] radius 1 material { Kd 0 t 0.8 ior 1.5 } }\n"
                       "torus { center [5, 0, 0] axis [0, 0, 1] major 2 minor 0.5 material { Kd 0 t 1 ior 1.3 } }\n"
                       "cylinder { from [20, 0, 0] to [20, 0, 5] open material { Kd 0 t 1 ior 1.7 } }\n");
    trace_stats st;
    rgb c = trace_one(s, vec_make(0.3, 0.2, 5), vec_make(0, 0, -1), &st);
    ck_assert_msg(fabs(c.x - 0.64) < 1e-12, "%.17g", (double)c.x);
    ck_assert_int_eq(st.refraction_rays, 2);
    tracer t;
    medium_stack m;
    ck_assert(tracer_init(&t, s, 0, 0));
    trace_media_at(&t, vec_make(0.2, 0.1, -1), &m, &st);
    ck_assert_int_eq(m.count, 1);
    ck_assert_near(m.ior[0], 1.5, 0);
    trace_media_at(&t, vec_make(5 + 2.1, 0, 0.2), &m, &st);
    ck_assert_int_eq(m.count, 1);
    ck_assert_near(m.ior[0], 1.3, 0);
    trace_media_at(&t, vec_make(5, 0, 0), &m, &st);
    ck_assert_int_eq(m.count, 0);
    trace_media_at(&t, vec_make(20, 0.5, 1), &m, &st);
    ck_assert_int_eq(m.count, 0);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/* The apex of a cone seen head-on by an orthographic camera 1e-310 wide:
 * every hit point is a subnormal distance from the axis, and the side's
 * normal depends on the azimuth alone, so each pixel is the pixel of the
 * same camera 1e-300 wide, to the rounding of the subnormal hit points'
 * azimuths (1e-14 apart here; 1e-9 asked) (an outside attack's finding: before round 8,
 * side_normal's 1/l was +Inf below l = 2^-1024 and every pixel kept only
 * the ambient 0.08). */
static void render_apex(double width, img_buf *img)
{
    char text[512];
    snprintf(text, sizeof text,
             "image { width 8 height 6 background 0.25 }\n"
             "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width %.17g }\n"
             "ambient { color 0.1 }\ndistant_light { direction [1, -1, 0.5] power 1 }\n"
             "cone { from [0, 0, 0] to [0, 2, 0] radii 1 0 material { Kd 0.8 } }\n",
             width);
    int status;
    scene_model *s = scene_file_load_text("apex.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_ptr_nonnull(s);
    render_opts o;
    memset(&o, 0, sizeof o);
    render_stats st;
    ck_assert_int_eq(render_image(s, &o, img, &st), STATUS_OK);
    scene_free(s);
}

START_TEST(test_cone_apex_subnormal_width)
{
    img_buf tiny, small;
    render_apex(1e-310, &tiny);
    render_apex(1e-300, &small);
    ck_assert_int_eq(tiny.width, small.width);
    int lit = 0;
    for (int i = 0; i < 3 * tiny.width * tiny.height; i++) {
        ck_assert_msg(fabs(tiny.rgb[i] - small.rgb[i]) <= 1e-9, "value %d: %.17g at width 1e-310, %.17g at 1e-300", i,
                      tiny.rgb[i], small.rgb[i]);
        lit += small.rgb[i] > 0.1;
    }
    ck_assert_int_gt(lit, 0);
    img_free(&tiny);
    img_free(&small);
}
END_TEST

/* [NUM-QUADRIC-1] A cone of radius 1 at y = -1 and 0.5 at y = 1 (rho(y) =
 * 0.75 - y/4) seen from D along -x: the line (D, y, z) - t x^ meets the side
 * where x^2 + z^2 = rho^2, first at x = sqrt(rho^2 - z^2), t = D - x, and
 * misses it for |z| > rho.  At y = 0.8 (rho = 0.55): z = 0.5 hits at
 * x = sqrt(0.0525); z = +-0.56 and 0.9 miss by 0.01 and 0.35.  Before the
 * origin was moved near the cone (cone_origin), |fp| = sqrt(D^2 + z^2)
 * rounded to D from D = 1e8 on (z^2/2D below half an ulp of D): c and the
 * discriminant lost z, and all four rays hit (tests/attack10, finding 1). */
START_TEST(test_cone_far_origin)
{
    static const double dist[] = {10, 1e7, 1e8, 1e10, 1e12};
    static const double miss_z[] = {0.56, -0.56, 0.9};
    const double x = sqrt(0.55 * 0.55 - 0.25);
    for (int open = 0; open <= 1; open++)
        for (int i = 0; i < 5; i++) {
            scene_prim c = cone(vec_make(0, -1, 0), 1, vec_make(0, 1, 0), 0.5, open);
            double d = dist[i];
            hit h;
            ray r = make_ray(vec_make(d, 0.8, 0.5), vec_make(-1, 0, 0));
            ck_assert_msg(isect_prim(&c, &r, &h), "open %d, D = %g: missed", open, d);
            ck_assert_msg(fabs(h.t - (d - x)) <= 2 * DBL_EPSILON * d, "open %d, D = %g: t = %.17g, expected %.17g",
                          open, d, (double)h.t, d - x);
            ck_assert_msg(fabs(h.point.x - x) <= 1e-15 && h.point.y == 0.8 && h.point.z == 0.5,
                          "open %d, D = %g: point (%.17g, %.17g, %.17g)", open, d, (double)h.point.x, (double)h.point.y,
                              (double)h.point.z);
            for (int j = 0; j < 3; j++) {
                r = make_ray(vec_make(d, 0.8, miss_z[j]), vec_make(-1, 0, 0));
                ck_assert_msg(!isect_prim(&c, &r, &h), "open %d, D = %g, z = %g: hit at t = %.17g", open, d,
                              miss_z[j], (double)h.t);
            }
        }
}
END_TEST

/* Renders text with the shortcuts on (no_shortcuts 0) or off (1). */
static void render_text(const char *text, int no_shortcuts, img_buf *img)
{
    scene_model *s = load(text);
    render_opts o;
    memset(&o, 0, sizeof o);
    o.no_shortcuts = no_shortcuts;
    render_stats st;
    ck_assert_int_eq(render_image(s, &o, img, &st), STATUS_OK);
    scene_free(s);
}

/* Whether got and want hold the same values: bit for bit, or (as_float)
 * to the float an image file stores. */
static void expect_same_image(const img_buf *got, const img_buf *want, int as_float, const char *what)
{
    ck_assert_int_eq(got->width, want->width);
    ck_assert_int_eq(got->height, want->height);
    int differ = 0, first = -1;
    for (int i = 0; i < 3 * want->width * want->height; i++) {
        float fg = (float)got->rgb[i], fw = (float)want->rgb[i];
        int same = as_float ? memcmp(&fg, &fw, sizeof fg) == 0
                            : memcmp(&got->rgb[i], &want->rgb[i], sizeof got->rgb[i]) == 0;
        if (!same) {
            first = first < 0 ? i : first;
            differ++;
        }
    }
    ck_assert_msg(differ == 0, "%s: %d of %d values differ, the first (%d) %.17g, expected %.17g", what, differ,
                  3 * want->width * want->height, first, got->rgb[first], want->rgb[first]);
}

/* [NUM-QUADRIC-1] [SHADE-SHORTCUT-OFF-1] An orthographic image does not
 * depend on the eye's distance along the view (the rays are the same
 * lines, their origins exact on the x axis): the cone seen from 1e8 and
 * 1e12 is the image seen from 10 to the float an image file holds (the
 * doubles differ in their last bits: the hit point o + t d, before its
 * refinement, carries the rounding of the far origin, eps 1e8), and the
 * shortcuts change no bit.  Before, 66 of 192 pixels differed at 1e8
 * (holes and hits outside the trapezoid) and the shortcuts changed 48
 * (tests/attack10, cone_ortho_far.scene). */
START_TEST(test_cone_far_orthographic_view)
{
    static const char *const eyes[] = {"1e8", "1e12"};
    const char *form = "image { width 16 height 12 }\n"
                       "camera { orthographic eye [%s, 0, 0] look_at [0, 0, 0] up [0, 1, 0] width 2.6 }\n"
                       "ambient { color 0.2 }\npoint_light { position [3, 10, 2] power 40 falloff none }\n"
                       "cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5 %s material { Kd 0.8 } }\n";
    char text[512];
    for (int open = 0; open <= 1; open++) {
        img_buf ref;
        snprintf(text, sizeof text, form, "10", open ? "open" : "");
        render_text(text, 0, &ref);
        for (int e = 0; e < 2; e++) {
            img_buf on, off;
            char what[64];
            snprintf(text, sizeof text, form, eyes[e], open ? "open" : "");
            render_text(text, 0, &on);
            render_text(text, 1, &off);
            snprintf(what, sizeof what, "open %d, eye %s", open, eyes[e]);
            expect_same_image(&on, &ref, 1, what);
            snprintf(what, sizeof what, "open %d, eye %s, shortcuts off", open, eyes[e]);
            expect_same_image(&off, &on, 0, what);
            img_free(&on);
            img_free(&off);
        }
        img_free(&ref);
    }
}

END_TEST

/* A floor 1e8 from the cone, the light 10 beyond it: every shadow ray
 * passes the axis 0.9 from it at height 0.8, where the radius is 0.55,
 * missing by 0.35; the floor is lit as without the cone.  Before, 189 of
 * 192 pixels were in a false shadow (tests/attack10, cone_false_shadow). */
START_TEST(test_cone_far_no_false_shadow)
{
    const char *form = "image { width 16 height 12 }\n"
                       "camera { orthographic eye [1e8, 10, 0] look_at [1e8, -1.5, 0] up [0, 0, -1] width 4 }\n"
                       "ambient { color 0.1 }\npoint_light { position [-10, 0.8, 0.9] power 1e8 falloff none }\n"
                       "plane { point [0, -1.5, 0] normal [0, 1, 0] material { Kd 0.8 } }\n%s";
    char text[640];
    img_buf bare;
    snprintf(text, sizeof text, form, "");
    render_text(text, 0, &bare);
    for (int off = 0; off <= 1; off++) {
        img_buf with;
        snprintf(text, sizeof text, form, "cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5 material { Kd 0.8 } }\n");
        render_text(text, off, &with);
        expect_same_image(&with, &bare, 0, off ? "shortcuts off" : "shortcuts on");
        img_free(&with);
    }
    img_free(&bare);
}
END_TEST

/* Whether every value of got is within rel |want| of want's. */
static void expect_close_image(const img_buf *got, const img_buf *want, double rel, const char *what)
{
    ck_assert_int_eq(got->width, want->width);
    ck_assert_int_eq(got->height, want->height);
    int over = 0, first = -1;
    for (int i = 0; i < 3 * want->width * want->height; i++)
        if (!(fabs(got->rgb[i] - want->rgb[i]) <= rel * fabs(want->rgb[i]))) {
            first = first < 0 ? i : first;
            over++;
        }
    ck_assert_msg(over == 0, "%s: %d of %d values over %g, the first (%d) %.17g, expected %.17g", what, over,
                  3 * want->width * want->height, rel, first, got->rgb[first], want->rgb[first]);
}

/* [NUM-QUADRIC-1] tests/attack11, finding 3: a closed and an open cone of
 * height 1 and radius R, seen from above by an orthographic eye 10 R away,
 * cover what their base disk covers (the apex projects inside it) with a
 * normal within atan(1/R) of the disk's: each channel is within Kd power
 * atan(1/R) <= 2.1/R of the disk's image, under 2.5/R of its value (a lit
 * channel is at least 0.85), so 4/R relative holds it; and the shortcuts
 * change no bit.  Before (main aebfd84), R = 1e8: 36 pixels differed from
 * the disk, up to 1.89 (the sky drawn lit), 38 with the shortcuts off; R =
 * 5e7 the shortcuts-off image alone (40 pixels). */
START_TEST(test_cone_flat_wide)
{
    static const double radii[] = {5e7, 1e8, 1e10, 1e12};
    const char *form = "image { width 16 height 12 max_depth 2 background [0.1, 0.1, 0.2] }\n"
                       "camera { orthographic eye [%.17g, %.17g, 0] look_at [0, 0, 0] up [0, 1, 0] width %.17g }\n"
                       "ambient { color 0.2 }\ndistant_light { direction [-0.5, -1, 0.2] power 3 }\n"
                       "%s { %s [0, -0.5, 0] %s %.17g %s material { Kd [0.7, 0.5, 0.3] } }\n";
    char text[640], what[64];
    for (size_t i = 0; i < sizeof radii / sizeof radii[0]; i++) {
        double r = radii[i];
        img_buf disk;
        snprintf(text, sizeof text, form, 6 * r, 8 * r, 3 * r, "disk", "center", "normal [0, 1, 0] radius", r, "");
        render_text(text, 0, &disk);
        for (int open = 0; open <= 1; open++) {
            img_buf on, off;
            snprintf(text, sizeof text, form, 6 * r, 8 * r, 3 * r, "cone", "from", "to [0, 0.5, 0] radii", r,
                     open ? "0 open" : "0");
            render_text(text, 0, &on);
            render_text(text, 1, &off);
            snprintf(what, sizeof what, "R %g, open %d", r, open);
            expect_close_image(&on, &disk, 4 / r, what);
            snprintf(what, sizeof what, "R %g, open %d, shortcuts off", r, open);
            expect_same_image(&off, &on, 0, what);
            img_free(&on);
            img_free(&off);
        }
        img_free(&disk);
    }
}
END_TEST

/* A shape squashed by a kept frame (scale [1, s, 1] rotate [0, 30, 0]) at
 * the origin, seen from 10 above: "%s" the shape, "%.17g" s. */
static const char squashed[] = "image { width 16 height 12 }\n"
                               "camera { eye [0, 10, 0.001] look_at [0, 0, 0] fov 20 }\n"
                               "ambient { color 0.2 }\npoint_light { position [3, 10, 2] power 40 falloff none }\n"
                               "%s scale [1, %.17g, 1] rotate [0, 30, 0] material { Kd 0.8 } }\n";

/* [NUM-FRAME-2] [NUM-FRAME-3] tests/attack10, finding 2.  At s = 1e-10 a
 * squashed sphere, cylinder and cone (radius 1 at the bottom) and the disk
 * of radius 1 (whose frame leaves it as it is) are the flat disk of radius 1
 * seen from above: the same silhouette, normals vertical to 1e-10, the
 * image the disk without a frame gives (to the float an image file holds).
 * Squashed further, to 1e-20, 1e-160 and 1e-300, every shape (these, a box
 * and a torus) gives its image at 1e-10, with the shortcuts on and off.
 * Before (main aebfd84): the disk at 1e-10 drawn with holes (its box has
 * no thickness: the frame's gate culled its hits), the sphere at 1e-20
 * with 58 of 68 pixels wrong, at 1e-160 and past nothing drawn; the torus
 * at 1e-20 nothing. */
START_TEST(test_frame_squashed_shapes)
{
    static const char *const shapes[] = {
        "sphere { center [0, 0, 0] radius 1",
        "cylinder { from [0, -1, 0] to [0, 1, 0] radius 1",
        "cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5",
        "disk { center [0, 0, 0] normal [0, 1, 0] radius 1",
        "box { from [-0.7, -1, -0.7] to [0.7, 1, 0.7]",
        "torus { center [0, 0, 0] axis [0, 1, 0] major 0.8 minor 0.4",
    };
    static const double squash[] = {1e-20, 1e-160, 1e-300};
    char text[640], what[96];
    img_buf flat;
    render_text("image { width 16 height 12 }\ncamera { eye [0, 10, 0.001] look_at [0, 0, 0] fov 20 }\n"
                "ambient { color 0.2 }\npoint_light { position [3, 10, 2] power 40 falloff none }\n"
                "disk { center [0, 0, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }\n",
                0, &flat);
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++) {
        img_buf ref;
        snprintf(text, sizeof text, squashed, shapes[i], 1e-10);
        render_text(text, 0, &ref);
        if (i < 4)
            expect_same_image(&ref, &flat, 1, shapes[i]);
        for (size_t j = 0; j < sizeof squash / sizeof squash[0]; j++) {
            img_buf on, off;
            snprintf(text, sizeof text, squashed, shapes[i], squash[j]);
            render_text(text, 0, &on);
            render_text(text, 1, &off);
            snprintf(what, sizeof what, "%.40s, s %g", shapes[i], squash[j]);
            expect_same_image(&on, &ref, 1, what);
            snprintf(what, sizeof what, "%.40s, s %g, shortcuts off", shapes[i], squash[j]);
            expect_same_image(&off, &on, 0, what);
            img_free(&on);
            img_free(&off);
        }
        img_free(&ref);
    }
    img_free(&flat);
}
END_TEST

/* text rendered with the shortcuts on and off: its image is want's to rel
 * relative (0: to the float an image file holds), and the two the same to
 * the bit. */
static void expect_flat_image(const char *text, const img_buf *want, double rel, const char *what)
{
    img_buf on, off;
    render_text(text, 0, &on);
    render_text(text, 1, &off);
    if (rel > 0)
        expect_close_image(&on, want, rel, what);
    else
        expect_same_image(&on, want, 1, what);
    expect_same_image(&off, &on, 0, what);
    img_free(&on);
    img_free(&off);
}

/* [NUM-FRAME-4] tests/attack13, finding 3.  A closed cylinder squashed
 * along its axis to s = 1.5e-162 .. 5e-162 and seen obliquely (eye [2.5,
 * 3.2, -4]) is, to s, the unit disk in y = 0: its silhouette from any
 * direction, every visible point lit Kd Ia (ambient only), so its image is
 * the disk's without a frame, bit for bit as a float (geometry, not a
 * render of the cylinder); the same for the cones (the side slanting and
 * nearly upright) and the sphere, from 1e-150 to 1e-170.  With a light and
 * a shiny floor under the shape lifted to y = 1 and turned, the floor's
 * shadow and mirror rays cross it: the image is the lifted disk's to 1e-6
 * (the world points come back through the frame).
 * And without a frame: a cylinder whose axis leans 2e-162 off the vertical,
 * seen straight down, is the disk of its top cap.  Before (main 5100e81):
 * the cylinder at 1.5e-162 .. 5e-162 had 6 to 13 of 68 pixels background
 * (|dp|^2 subnormal made every crossing of the side a graze), its shadow
 * missed on 3 floor pixels at 1e-160 and 12 at 1e-161, and the leaning one
 * had 28 holes at 2e-162. */
START_TEST(test_frame_squashed_oblique)
{
    static const char *const shapes[] = {
        "cylinder { from [0, -1, 0] to [0, 1, 0] radius 1",
        "cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5",
        "cone { from [0, -1, 0] to [0, 1, 0] radii 1 1.0000001",
        "sphere { center [0, 0, 0] radius 1",
    };
    static const double squash[] = {1e-150, 1e-160, 1e-161, 1.5e-162, 2e-162, 3e-162, 5e-162, 1e-170};
    const char *view = "image { width 32 height 24 }\ncamera { eye [2.5, 3.2, -4] look_at [0, 0.6, 0] fov 50 }\n"
                       "ambient { color 0.2 }\n";
    const char *lit = "image { width 32 height 24 max_depth 3 }\n"
                      "camera { eye [2.5, 3.2, -4] look_at [0, 0.6, 0] fov 50 }\nambient { color 0.2 }\n"
                      "point_light { position [0.8, 6, 0.5] power 40 falloff none }\n"
                      "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.4 n 20 } }\n";
    char text[1024], what[96];
    img_buf flat, flat_lit, flat_down, on;
    snprintf(text, sizeof text, "%sdisk { center [0, 0, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }\n",
             view);
    render_text(text, 0, &flat);
    snprintf(text, sizeof text, "%sdisk { center [0, 1, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }\n", lit);
    render_text(text, 0, &flat_lit);
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        for (size_t j = 0; j < sizeof squash / sizeof squash[0]; j++) {
            snprintf(text, sizeof text, "%s%s scale [1, %.17g, 1] material { Kd 0.8 } }\n", view, shapes[i],
                     squash[j]);
            snprintf(what, sizeof what, "%.40s, s %g", shapes[i], squash[j]);
            expect_flat_image(text, &flat, 0, what);
            snprintf(text, sizeof text, "%s%s scale [1, %.17g, 1] rotate [0, 30, 0] translate [0, 1, 0] "
                     "material { Kd 0.8 } }\n", lit, shapes[i], squash[j]);
            snprintf(what, sizeof what, "%.40s, s %g, lit over a floor", shapes[i], squash[j]);
            expect_flat_image(text, &flat_lit, 1e-6, what);
        }
    const char *down = "image { width 16 height 12 }\n"
                       "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, 1] width 3 }\n"
                       "ambient { color 0.2 }\n";
    snprintf(text, sizeof text, "%sdisk { center [0, 1, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }\n",
             down);
    render_text(text, 0, &flat_down);
    snprintf(text, sizeof text, "%scylinder { from [0, -1, 0] to [4e-162, 1, 0] radius 1 material { Kd 0.8 } }\n",
             down);
    render_text(text, 0, &on);
    expect_same_image(&on, &flat_down, 1, "a cylinder leaning 2e-162");
    img_free(&on);
    img_free(&flat);
    img_free(&flat_lit);
    img_free(&flat_down);
}
END_TEST

/* [NUM-FRAME-5] A shape turned and then squashed (`rotate R scale [1, s,
 * 1]`: along no axis of its own frame), over a shiny floor, lit, seen
 * obliquely: to s it is its outline seen along y, flat in y = 0 with
 * vertical normals (geometry): the sphere turned two ways the unit disk,
 * the box [-0.7, 0.7] x [-1, 1] x [-0.7, 0.7] turned 30 degrees about z
 * the rectangle |x| <= 0.7 cos 30 + sin 30, |z| <= 0.7 (two triangles).
 * The image is the flat shape's to 1e-6 (the world points come back
 * through the frame), the same with the shortcuts off.  Before (main
 * 5100e81): from s = 1e-12 on, 48 to 198 of 768 pixels off, at 1e-20 and
 * past the shape drawn nowhere (tests/frame_squash/turned.sh). */
START_TEST(test_frame_squashed_turned)
{
    static const char *const shapes[] = {
        "sphere { center [0, 0, 0] radius 1 rotate [0, 0, 30]",
        "sphere { center [0, 0, 0] radius 1 rotate [40, 0, 25]",
        "box { from [-0.7, -1, -0.7] to [0.7, 1, 0.7] rotate [0, 0, 30]",
    };
    static const double squash[] = {1e-12, 1e-20, 1e-160, 1e-300};
    const char *lit = "image { width 32 height 24 max_depth 3 }\n"
                      "camera { eye [2.5, 3.2, -4] look_at [0, 0, 0] fov 45 }\nambient { color 0.2 }\n"
                      "point_light { position [0.8, 6, 0.5] power 40 falloff none }\n"
                      "plane { point [0, -1.5, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.4 n 20 } }\n";
    const double hx = 0.7 * sqrt(0.75) + 0.5; /* cos 30 = sqrt(3) / 2, sin 30 = 1/2 */
    char text[1024], what[96];
    img_buf disk, rect;
    snprintf(text, sizeof text, "%sdisk { center [0, 0, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }\n", lit);
    render_text(text, 0, &disk);
    snprintf(text, sizeof text,
             "%striangle { vertices [%.17g, 0, -0.7] [%.17g, 0, -0.7] [%.17g, 0, 0.7] material { Kd 0.8 } }\n"
             "triangle { vertices [%.17g, 0, -0.7] [%.17g, 0, 0.7] [%.17g, 0, 0.7] material { Kd 0.8 } }\n",
             lit, -hx, hx, hx, -hx, hx, -hx);
    render_text(text, 0, &rect);
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        for (size_t j = 0; j < sizeof squash / sizeof squash[0]; j++) {
            snprintf(text, sizeof text, "%s%s scale [1, %.17g, 1] material { Kd 0.8 } }\n", lit, shapes[i],
                     squash[j]);
            snprintf(what, sizeof what, "%.60s, s %g", shapes[i], squash[j]);
            expect_flat_image(text, i < 2 ? &disk : &rect, 1e-6, what);
        }
    img_free(&disk);
    img_free(&rect);
}
END_TEST

/* [NUM-FRAME-6] Shapes turned and then stretched 1e12 (`rotate R scale
 * [S, 1, 1]`: along no axis of their own frame, spread about S), hit by
 * rays from eyes 5 and 5e4 away aimed at points of their surface where the
 * views see them.  Geometry, not refray's solve: the unit sphere so turned
 * and stretched along x is x^2 / S^2 + y^2 + z^2 = 1, within |x| <= 3 the
 * unit cylinder about x to 5e-24; the cylinder |x| <= 1 of radius 1 about x,
 * turned about x and stretched along z, is y^2 + z^2 / S^2 <= 1, |x| <= 1,
 * within |z| <= 3 the plank |x| <= 1, |y| <= 1.  Each crossing's point P
 * (with its o, t, d; T = 0) must be on the world line to 7 u (|o| + |t d| +
 * |P|) (max norms, u = 2^-53: the rounding of (o - T) + t d, the pull's
 * step and + T, spec/numerics.md 2.17c) and on the surface to 16 eps |P|
 * (the pull's local solve from a point of the line near P: its local
 * origin rounds by 3 u |L^-1| |P - T|, under 4 u here, and L^-T of the
 * local normal is within 1e-11 of unit length).  Before (23aaeed) the point
 * came through L: up to about 2e-5 |o| off the line (eps S |o - T|). */
START_TEST(test_frame_stretched_turned)
{
    static const char *const shapes[] = {
        "sphere { center [0, 0, 0] radius 1 rotate [40, 0, 25] scale [1e12, 1, 1] }\n",
        "sphere { center [0, 0, 0] radius 1 rotate [0, 0, 30] scale [1e12, 1, 1] }\n",
        "cylinder { from [-1, 0, 0] to [1, 0, 0] radius 1 rotate [30, 0, 0] scale [1, 1, 1e12] }\n",
    };
    static const double eyes[][3] = {{2.5, 3.2, -4}, {-3, 1.2, 2.5}, {0.6, 7, -1.5}, {0, 3e4, -4e4}};
    const long double S = 1e12L, u = 0x1p-53L;
    for (int k = 0; k < 3; k++) {
        scene_model *s = load(shapes[k]);
        const scene_prim *p = &s->prims[0];
        ck_assert(p->frame != NULL);
        int crossings = 0;
        for (int e = 0; e < 4; e++)
            for (int a = 0; a < 7; a++)
                for (int b = 0; b < 16; b++) {
                    /* the target: on the ellipsoid x = -3 .. 3 round the axis; on
                     * the plank z = -3 .. 3 across its faces x = +-1 and y = +-1,
                     * 0.1 in from their edges */
                    double v = -3 + a, ang = b * (2 * 3.14159265358979 / 16), c = cos(ang), sn = sin(ang);
                    double w = -0.9 + 0.6 * (b / 4), side = b % 2 ? 1 : -1;
                    vec3 target = k < 2 ? vec_make(v, c, sn) : b % 4 < 2 ? vec_make(side, w, v) : vec_make(w, side, v);
                    vec3 o = vec_make(eyes[e][0], eyes[e][1], eyes[e][2]);
                    ray r = make_ray(o, vec_sub(target, o));
                    hit out[ISECT_MAX_CROSSINGS];
                    int n = isect_prim_all(p, &r, out);
                    ck_assert_msg(n > 0, "shape %d, eye %d: no hit aimed at (%g, %g, %g)", k, e, (double)target.x,
                                  (double)target.y, (double)target.z);
                    for (int i = 0; i < n; i++, crossings++) {
                        long double P[3] = {out[i].point.x, out[i].point.y, out[i].point.z};
                        long double O[3] = {o.x, o.y, o.z}, D[3] = {r.dir.x, r.dir.y, r.dir.z}, t = out[i].t;
                        long double v3[3], mo = 0, md = 0, mp = 0;
                        for (int j = 0; j < 3; j++) {
                            v3[j] = P[j] - O[j];
                            mo = fmaxl(mo, fabsl(O[j]));
                            md = fmaxl(md, fabsl(D[j]));
                            mp = fmaxl(mp, fabsl(P[j]));
                        }
                        long double cx = v3[1] * D[2] - v3[2] * D[1], cy = v3[2] * D[0] - v3[0] * D[2],
                                    cz = v3[0] * D[1] - v3[1] * D[0];
                        long double off = sqrtl(cx * cx + cy * cy + cz * cz) / sqrtl(D[0] * D[0] + D[1] * D[1] + D[2] * D[2]);
                        long double line = 7 * u * (mo + fabsl(t) * md + mp) * sqrtl(3);
                        ck_assert_msg(off <= line, "shape %d, eye %d, crossing %d: %Lg off the line, over %Lg", k, e,
                                      i, off, line);
                        long double dist;
                        if (k < 2)
                            dist = fabsl(sqrtl(P[0] * P[0] / (S * S) + P[1] * P[1] + P[2] * P[2]) - 1);
                        else
                            dist = fminl(fabsl(fabsl(P[1]) - sqrtl(1 - P[2] * P[2] / (S * S))), fabsl(fabsl(P[0]) - 1));
                        ck_assert_msg(dist <= 32 * u * mp, "shape %d, eye %d, crossing %d: %Lg off the surface, over %Lg",
                                      k, e, i, dist, 32 * u * mp);
                        if (k == 2)
                            ck_assert(fabsl(P[0]) <= 1 + 32 * u && fabsl(P[1]) <= 1 + 32 * u);
                    }
                }
        ck_assert_int_gt(crossings, 4 * 7 * 16);
        scene_free(s);
    }
}
END_TEST

Suite *suite_quadrics(void)
{
    Suite *s = suite_create("quadrics");
    TCase *tc = tcase_create("quadrics");
    tcase_add_test(tc, test_cylinder_by_hand);
    tcase_add_test(tc, test_cone_by_hand);
    tcase_add_test(tc, test_cone_steepest);
    tcase_add_test(tc, test_cone_apex_subnormal_width);
    tcase_add_test(tc, test_cone_far_origin);
    tcase_add_test(tc, test_cone_far_orthographic_view);
    tcase_add_test(tc, test_cone_far_no_false_shadow);
    tcase_add_test(tc, test_cone_flat_wide);
    tcase_add_test(tc, test_frame_squashed_shapes);
    tcase_add_test(tc, test_frame_squashed_oblique);
    tcase_add_test(tc, test_frame_squashed_turned);
    tcase_add_test(tc, test_frame_stretched_turned);
    tcase_add_test(tc, test_torus_by_hand);
    tcase_add_test(tc, test_torus_thin_far);
    tcase_add_test(tc, test_torus_far_tiny_forms_no_infinity);
    tcase_add_test(tc, test_torus_transformed);
    tcase_add_test(tc, test_rim_is_closed);
    tcase_add_test(tc, test_quadric_bounds_and_magnitude);
    tcase_add_test(tc, test_quadric_contains);
    tcase_add_test(tc, test_quadric_spawn_no_self_hit);
    tcase_add_test(tc, test_torus_transparent_shadow);
    tcase_add_test(tc, test_torus_shadows_itself);
    tcase_add_test(tc, test_quadric_glass);
    suite_add_tcase(s, tc);
    return s;
}
