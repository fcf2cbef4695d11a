/* Tests of src/render/intersect.c.  Every expected t, point and normal is worked
 * out by hand in the comment next to it, or checked by a different route
 * (distance to the surface, a known chord length). */
#include <float.h>
#include <stdint.h>
#include <string.h>
#include "testlib.h"
#include "render/intersect.h"
#include "render/isect_common.h"
#include "base/xform.h"

/* Counter-based generator: the value is a hash (splitmix64's finaliser) of
 * seed and counter, so a test draws the same numbers however it runs. */
typedef struct rng {
    uint64_t seed, counter;
} rng;

static double rng_uniform(rng *g)
{
    uint64_t z = g->seed * 0x9E3779B97F4A7C15u + (g->counter++ + 1) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}

static vec3 rng_unit(rng *g)
{
    for (;;) {
        vec3 v = vec_make(2 * rng_uniform(g) - 1, 2 * rng_uniform(g) - 1, 2 * rng_uniform(g) - 1);
        double l2 = vec_length2(v);
        if (l2 > 0.01 && l2 <= 1.0)
            return vec_normalize(v);
    }
}

static ray make_ray(vec3 o, vec3 d)
{
    ray r;
    r.origin = o;
    r.dir = d;
    r.tmin = 0.0;
    r.tmax = HUGE_VAL;
    return r;
}

static scene_prim prim_blank(scene_prim_kind kind)
{
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    p.mesh = -1;
    return p;
}

static scene_prim prim_sphere(vec3 c, double radius)
{
    scene_prim p = prim_blank(PRIM_SPHERE);
    p.u.sphere.center = c;
    p.u.sphere.radius = radius;
    return p;
}

static scene_prim prim_plane(vec3 point, vec3 n)
{
    scene_prim p = prim_blank(PRIM_PLANE);
    p.u.plane.point = point;
    p.u.plane.normal = n;
    return p;
}

static scene_prim prim_triangle(vec3 a, vec3 b, vec3 c)
{
    scene_prim p = prim_blank(PRIM_TRIANGLE);
    p.u.triangle.p[0] = a;
    p.u.triangle.p[1] = b;
    p.u.triangle.p[2] = c;
    return p;
}

static scene_prim prim_box(vec3 lo, vec3 hi)
{
    scene_prim p = prim_blank(PRIM_BOX);
    p.u.box.lo = lo;
    p.u.box.hi = hi;
    return p;
}

/* Gives p the local frame to_world, kept in *f (which must outlive p). */
static void prim_set_xform(scene_prim *p, scene_frame *f, xform to_world)
{
    f->to_world = to_world;
    ck_assert(xform_invert(&to_world, &f->to_local));
    p->frame = f;
}

/* ---- sphere ---- */

START_TEST(test_isect_sphere_hit_by_hand)
{
    /* Centre (1,2,3), R 2, ray up z from z = -7 on the axis: enters at
     * z = 1, t = 8, normal (0,0,-1). */
    ray r = make_ray(vec_make(1, 2, -7), vec_make(0, 0, 1));
    hit h;
    ck_assert(isect_sphere(vec_make(1, 2, 3), 2, &r, &h));
    ck_assert_near(h.t, 8.0, 1e-15);
    ck_assert_near(r.tmax, 8.0, 1e-15);
    ck_assert_vec_near(h.point, vec_make(1, 2, 1), 1e-15);
    ck_assert_vec_near(h.normal, vec_make(0, 0, -1), 1e-15);
    ck_assert_vec_near(h.shading_normal, h.normal, 0.0);
    ck_assert_int_eq(h.entering, 1);
    ck_assert_int_eq(h.prim, -1);
    /* One unit off the axis in x: z = 3 - sqrt(4 - 1), t = 10 - sqrt(3),
     * normal (1, 0, -sqrt 3)/2. */
    r = make_ray(vec_make(2, 2, -7), vec_make(0, 0, 1));
    ck_assert(isect_sphere(vec_make(1, 2, 3), 2, &r, &h));
    ck_assert_near(h.t, 10 - sqrt(3.0), 1e-14);
    ck_assert_vec_near(h.normal, vec_make(0.5, 0, -sqrt(3.0) / 2), 1e-15);
}
END_TEST

START_TEST(test_isect_sphere_non_unit_direction)
{
    /* Direction (0,0,2): the same line as before at half the t. */
    ray r = make_ray(vec_make(1, 2, -7), vec_make(0, 0, 2));
    hit h;
    ck_assert(isect_sphere(vec_make(1, 2, 3), 2, &r, &h));
    ck_assert_near(h.t, 4.0, 1e-15);
    ck_assert_vec_near(h.point, vec_make(1, 2, 1), 1e-15);
}
END_TEST

START_TEST(test_isect_sphere_miss_leaves_ray_and_hit)
{
    ray r = make_ray(vec_make(3.5, 2, -7), vec_make(0, 0, 1)), before = r;
    hit h, keep;
    memset(&h, 0x5a, sizeof h);
    keep = h;
    ck_assert(!isect_sphere(vec_make(1, 2, 3), 2, &r, &h));
    ck_assert(memcmp(&r, &before, sizeof r) == 0);
    ck_assert(memcmp(&h, &keep, sizeof h) == 0);
    /* Pointing away from the sphere: both roots negative. */
    r = make_ray(vec_make(1, 2, -7), vec_make(0, 0, -1));
    ck_assert(!isect_sphere(vec_make(1, 2, 3), 2, &r, &h));
}
END_TEST

START_TEST(test_isect_sphere_tangent_is_one_hit)
{
    /* Unit sphere, ray along x at y = 1: the discriminant is exactly 0 and
     * the graze at (0,1,0), t = 5, counts once. */
    scene_prim s = prim_sphere(vec_make(0, 0, 0), 1);
    ray r = make_ray(vec_make(-5, 1, 0), vec_make(1, 0, 0));
    hit out[ISECT_MAX_CROSSINGS];
    ck_assert_int_eq(isect_prim_all(&s, &r, out), 1);
    ck_assert_near(out[0].t, 5.0, 0.0);
    ck_assert_vec_near(out[0].point, vec_make(0, 1, 0), 0.0);
    ck_assert_vec_near(out[0].normal, vec_make(0, 1, 0), 0.0);
    hit h;
    ck_assert(isect_prim(&s, &r, &h));
    ck_assert_near(h.t, 5.0, 0.0);
    /* Just outside misses, just inside is two hits. */
    r = make_ray(vec_make(-5, 1 + 1e-15, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(isect_prim_all(&s, &r, out), 0);
    r = make_ray(vec_make(-5, 1 - 1e-15, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(isect_prim_all(&s, &r, out), 2);
}
END_TEST

START_TEST(test_isect_sphere_tiny_radius_miss)
{
    /* R = 2^-540 at (2^-538, 0, 0); a ray down the y axis passes 4 R from
     * the centre.  The quarter discriminant (R - 4R)(R + 4R) = -15 R^2 is
     * below the smallest denormal: computed as one product it is -0, which
     * would read as a graze.  At ordinary scale the same geometry misses
     * too, and a ray through the centre hits at t = 1.5 - R. */
    double rad = ldexp(1.0, -540);
    ray r = make_ray(vec_make(0, 1.5, 0), vec_make(0, -1, 0));
    hit h;
    ck_assert(!isect_sphere(vec_make(4 * rad, 0, 0), rad, &r, &h));
    r = make_ray(vec_make(0, 1.5, 0), vec_make(0, -1, 0));
    ck_assert(!isect_sphere(vec_make(1, 0, 0), 0.25, &r, &h));
    r = make_ray(vec_make(4 * rad, 1.5, 0), vec_make(0, -1, 0));
    ck_assert(isect_sphere(vec_make(4 * rad, 0, 0), rad, &r, &h));
    ck_assert_near(h.t, 1.5, 0.0); /* 1.5 - 2^-540 rounds to 1.5 */
}
END_TEST

START_TEST(test_isect_sphere_from_inside_hits_far_side)
{
    /* From the centre of R = 3 along -y: t = 3, outward normal = dir. */
    ray r = make_ray(vec_make(1, 1, 1), vec_make(0, -1, 0));
    hit h;
    ck_assert(isect_sphere(vec_make(1, 1, 1), 3, &r, &h));
    ck_assert_near(h.t, 3.0, 1e-15);
    ck_assert_vec_near(h.normal, vec_make(0, -1, 0), 1e-15);
    ck_assert_int_eq(h.entering, 0);
    scene_prim s = prim_sphere(vec_make(1, 1, 1), 3);
    hit out[ISECT_MAX_CROSSINGS];
    r = make_ray(vec_make(1, 1, 1), vec_make(0, -1, 0));
    ck_assert_int_eq(isect_prim_all(&s, &r, out), 1);
}
END_TEST

START_TEST(test_isect_sphere_ray_starting_on_surface)
{
    /* Origin (0,0,1) on the unit sphere.  Inward: the root at t = 0 is not
     * in (0, inf); the far side at t = 2 is, leaving.  Outward: nothing. */
    ray r = make_ray(vec_make(0, 0, 1), vec_make(0, 0, -1));
    hit h;
    ck_assert(isect_sphere(vec_make(0, 0, 0), 1, &r, &h));
    ck_assert_near(h.t, 2.0, 0.0);
    ck_assert_int_eq(h.entering, 0);
    r = make_ray(vec_make(0, 0, 1), vec_make(0, 0, 1));
    ck_assert(!isect_sphere(vec_make(0, 0, 0), 1, &r, &h));
    /* Tangentially along the surface: the graze at t = 0 is excluded. */
    r = make_ray(vec_make(0, 0, 1), vec_make(1, 0, 0));
    ck_assert(!isect_sphere(vec_make(0, 0, 0), 1, &r, &h));
}
END_TEST

START_TEST(test_isect_sphere_respects_tmin_tmax)
{
    /* Unit sphere at the origin, ray from z = -9 up: roots t = 8 and 10. */
    scene_prim s = prim_sphere(vec_make(0, 0, 0), 1);
    ray r = make_ray(vec_make(0, 0, -9), vec_make(0, 0, 1));
    hit h;
    r.tmax = 8.0; /* open interval: 8 itself is out */
    ck_assert(!isect_prim(&s, &r, &h));
    r.tmax = 8.5;
    ck_assert(isect_prim(&s, &r, &h));
    ck_assert_near(h.t, 8.0, 0.0);
    r = make_ray(vec_make(0, 0, -9), vec_make(0, 0, 1));
    r.tmin = 8.0; /* skips the entry, keeps the exit */
    ck_assert(isect_prim(&s, &r, &h));
    ck_assert_near(h.t, 10.0, 0.0);
    ck_assert_int_eq(h.entering, 0);
    r = make_ray(vec_make(0, 0, -9), vec_make(0, 0, 1));
    r.tmin = 8.5;
    r.tmax = 10.0;
    ck_assert(!isect_prim(&s, &r, &h));
    hit out[ISECT_MAX_CROSSINGS];
    r = make_ray(vec_make(0, 0, -9), vec_make(0, 0, 1));
    ck_assert_int_eq(isect_prim_all(&s, &r, out), 2);
    ck_assert_near(out[0].t, 8.0, 0.0);
    ck_assert_near(out[1].t, 10.0, 0.0);
    ck_assert_int_eq(out[0].entering, 1);
    ck_assert_int_eq(out[1].entering, 0);
    ck_assert(r.tmax == HUGE_VAL); /* the all-hits query leaves r alone */
}
END_TEST

/* | |p - c| - R | for the hit of a ray from o aimed at target. */
static double sphere_hit_error(vec3 c, double radius, vec3 o, vec3 target)
{
    ray r = make_ray(o, vec_normalize(vec_sub(target, o)));
    hit h;
    ck_assert(isect_sphere(c, radius, &r, &h));
    return fabs(vec_length(vec_sub(h.point, c)) - radius);
}

START_TEST(test_isect_sphere_small_sphere_far_away)
{
    /* R = 1e-4 at the origin seen from 1e4 away (RTG I ch. 7's case): the
     * hit must lie on the sphere to a few ulps of R, not of 1e4. */
    rng g = {11, 0};
    double radius = 1e-4, worst = 0.0;
    for (int i = 0; i < 200; i++) {
        vec3 eye_dir = rng_unit(&g), u = rng_unit(&g);
        if (vec_dot(u, eye_dir) < 0.3)
            u = vec_neg(u);
        if (vec_dot(u, eye_dir) < 0.3)
            continue;
        worst = fmax(worst, sphere_hit_error(vec_make(0, 0, 0), radius, vec_scale(eye_dir, 1e4),
                                             vec_scale(u, radius)));
    }
    ck_assert_msg(worst <= 8 * DBL_EPSILON * radius, "worst error %g", worst);
}
END_TEST

START_TEST(test_isect_sphere_huge_sphere_close_up)
{
    /* R = 1e6 at the origin, eye 1 unit above its surface. */
    rng g = {12, 0};
    double radius = 1e6, worst = 0.0;
    for (int i = 0; i < 200; i++) {
        vec3 up = rng_unit(&g), side = vec_normalize(vec_cross(up, rng_unit(&g)));
        vec3 eye = vec_scale(up, radius + 1);
        /* Aim at surface points up to about 100 units away. */
        vec3 u = vec_normalize(vec_madd(up, side, 1e-4 * rng_uniform(&g)));
        worst = fmax(worst, sphere_hit_error(vec_make(0, 0, 0), radius, eye, vec_scale(u, radius)));
    }
    ck_assert_msg(worst <= 8 * DBL_EPSILON * radius, "worst error %g", worst);
}
END_TEST

/* Whether the hot record of sphere s answers as s's own test (isect_part,
 * the roots with no shortcut) on r: the count, and the nearest hit's bits. */
static void assert_hot_sphere_matches(const scene_prim *s, const ray *r)
{
    real g[ISECT_HOT_REALS];
    int reals, code = isect_hot_make(s, 0, g, &reals);
    ck_assert_int_eq(ISECT_HOT_KIND(code), ISECT_HOT_SPHERE);
    ck_assert_int_eq(isect_hot_crossings(code, g, r, NULL), isect_part_crossings(s, 0, r));
    /* [NUM-SPHERE-ANY-1] */
    ck_assert_int_eq(isect_hot_crossed(code, g, r, NULL), isect_part_crossings(s, 0, r) > 0);
    ck_assert_int_eq(isect_part_crossed(s, 0, r), isect_part_crossings(s, 0, r) > 0);
    ray a = *r, b = *r;
    hit ha, hb;
    int na = isect_hot_hit(code, g, &a, &ha), nb = isect_part(s, 0, &b, &hb);
    ck_assert_int_eq(na, nb);
    if (na)
        ck_assert(same_real_bits(ha.t, hb.t) && same_real_bits(a.tmax, b.tmax));
}

/* Checks isect_sphere_moving_away on r against s's full test; returns 1
 * when it told a miss. */
static int moving_away_case(const scene_prim *s, const ray *r)
{
    vec3 c = s->u.sphere.center;
    real radius = s->u.sphere.radius;
    int away = isect_sphere_moving_away(vec_sub(r->origin, c), radius, r);
    if (away) {
        real t[2];
        int n = isect_sphere_roots(vec_sub(r->origin, c), r->dir, radius, t);
        for (int i = 0; i < n; i++)
            ck_assert_msg(!(t[i] > 0.0), "root %a of a ray told moving away", (double)t[i]);
        ck_assert_int_eq(isect_part_crossings(s, 0, r), 0);
    }
    assert_hot_sphere_matches(s, r);
    return away;
}

/* [NUM-SPHERE-2]: a miss told without the roots is a miss of the roots. */
START_TEST(test_isect_sphere_moving_away_matches_the_roots)
{
    /* By hand, the unit sphere: from (2,0,0) along +x it is behind; along
     * -x ahead; along y (f.d = 0), on the surface, an ulp outside or inside
     * it, or with tmin < 0 (the crossings behind count) left to the roots. */
    scene_prim s = prim_sphere(vec_make(0, 0, 0), 1);
    ray r = make_ray(vec_make(2, 0, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(moving_away_case(&s, &r), 1);
    r.dir = vec_make(-1, 0, 0);
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    r.dir = vec_make(0, 1, 0);
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    r = make_ray(vec_make(1, 0, 0), vec_make(1, 0.5, 0));
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    r.origin.x = nextafter((real)1, (real)2);   /* the ulp of real, not of double */
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    r.origin.x = nextafter((real)1, (real)0);
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    r.origin.x = 1 + 1e-9;
    ck_assert_int_eq(moving_away_case(&s, &r), 1);
    r = make_ray(vec_make(2, 0, 0), vec_make(1, 0, 0));
    r.tmin = -4;
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    ck_assert_int_eq(isect_part_crossings(&s, 0, &r), 2);
    /* Inside, moving away from the centre: the exit is ahead. */
    r = make_ray(vec_make(0.5, 0, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    ck_assert_int_eq(isect_part_crossings(&s, 0, &r), 1);
    /* Far from the world's origin: |o| past 2^23 |f| is left to the roots
     * (the refinement's slack reaches 1e-9 |o|). */
    s = prim_sphere(vec_make(1e12, 0, 0), 1e-3);
    r = make_ray(vec_make(1e12 + 0.5, 0, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(moving_away_case(&s, &r), 0);
    s = prim_sphere(vec_make(1e3, 0, 0), 1);
    r = make_ray(vec_make(1e3 + 3, 0, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(moving_away_case(&s, &r), 1);

    rng g = {1607, 0};
    int told = 0, told_far = 0, told_near = 0;
    for (int i = 0; i < 60000; i++) {
        double scale = pow(10.0, 8 * rng_uniform(&g) - 4);
        double spread = rng_uniform(&g) < 0.2 ? pow(10.0, 12 * rng_uniform(&g)) : 3.0;
        vec3 c = vec_scale(vec_make(2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1),
                           spread * scale);
        double radius = scale * (0.05 + rng_uniform(&g));
        s = prim_sphere(c, radius);
        vec3 n = rng_unit(&g), o;
        double where = rng_uniform(&g);
        int kind = i % 5;
        /* On the surface (rounded), an ulp or a spawn offset off it, or
         * out to a million radii. */
        if (kind == 0)
            o = vec_madd(c, n, radius);
        else if (kind == 1) {
            o = vec_madd(c, n, radius);
            o = vec_make(nextafter(o.x, o.x + n.x), nextafter(o.y, o.y + n.y), nextafter(o.z, o.z + n.z));
        } else if (kind == 2)
            o = vec_madd(c, n, radius * (1 + 1e-9 * (where - 0.5)));
        else
            o = vec_madd(c, n, radius * (1 + pow(10.0, 6 * where)));
        /* Away along the normal, tangent, or tangent tipped by a little. */
        vec3 t = vec_normalize(vec_cross(n, rng_unit(&g)));
        double tip = rng_uniform(&g), lean = pow(10.0, -12 * rng_uniform(&g));
        vec3 d = tip < 0.2 ? n : tip < 0.4 ? t : tip < 0.7 ? vec_madd(t, n, lean) : tip < 0.85 ? vec_madd(t, n, -lean)
               : rng_unit(&g);
        d = vec_scale(d, 0.25 + 3.75 * rng_uniform(&g));
        r = make_ray(o, d);
        double w = rng_uniform(&g);
        r.tmin = w < 0.4 ? 0.0 : w < 0.5 ? -0.0 : w < 0.9 ? 1e-9 * scale * rng_uniform(&g) : -scale * rng_uniform(&g);
        if (rng_uniform(&g) < 0.3)
            r.tmax = r.tmin + 4 * scale * rng_uniform(&g);
        int away = moving_away_case(&s, &r);
        told += away;
        if (away && vec_length2(vec_sub(o, c)) > 4 * radius * radius)
            told_far++;
        else if (away)
            told_near++;
    }
    /* The rays reach every branch. */
    ck_assert_msg(told > 10000 && told_far > 3000 && told_near > 3000, "told %d: %d far, %d near", told, told_far,
                  told_near);
}
END_TEST

/* [NUM-SPHERE-3]: a sphere's count (isect_part_crossings, a hot record's
 * isect_hot_crossings), which takes a far origin's root clear of the
 * interval's ends unrefined, against the full hits (isect_part_all: every
 * root refined), on intervals whose ends fall between a root and its
 * refinement, at a refined root, or far from both. */
START_TEST(test_isect_sphere_count_matches_the_refined_roots)
{
    rng g = {1919, 0};
    int between = 0, clear = 0, second_only = 0;
    for (int i = 0; i < 40000; i++) {
        double scale = pow(10.0, 8 * rng_uniform(&g) - 4);
        double spread = pow(10.0, 12 * rng_uniform(&g));
        vec3 c = vec_scale(rng_unit(&g), spread * scale);
        double radius = scale * (0.05 + rng_uniform(&g));
        scene_prim s = prim_sphere(c, radius);
        /* A far origin (|f| > 2R), aimed at a point of the sphere's
         * silhouette disk: anywhere on it, or a graze to 1e-12 of R. */
        vec3 n = rng_unit(&g), side = vec_normalize(vec_cross(n, rng_unit(&g)));
        double away = radius * (2.5 + pow(10.0, 6 * rng_uniform(&g)));
        double w = rng_uniform(&g);
        double off = w < 0.5 ? sqrt(rng_uniform(&g)) : 1 - pow(10.0, -12 * rng_uniform(&g));
        vec3 o = vec_madd(c, n, away), aim = vec_madd(c, side, radius * off);
        vec3 d = vec_scale(vec_normalize(vec_sub(aim, o)), 0.25 + 3.75 * rng_uniform(&g));
        ray r = make_ray(o, d);
        hit full[ISECT_MAX_CROSSINGS];
        real u[2];
        int nu = isect_sphere_roots(vec_sub(o, c), d, radius, u);
        int nf = isect_part_all(&s, 0, &r, full);
        if (nu != 2 || nf != 2)
            continue;
        /* Where the ends go: past both roots, at a root's refined t or its
         * unrefined one (whichever is larger, so that exactly one of the two
         * is inside where they differ), or anywhere near the sphere. */
        int k = i % 6;
        real t0 = full[0].t, t1 = full[1].t;
        if (k == 1)
            r.tmax = u[1] > t1 ? u[1] : t1;
        else if (k == 2)
            r.tmin = u[0] < t0 ? u[0] : t0;
        else if (k == 3)
            r.tmax = t1;
        else if (k == 4)
            r.tmin = t0;
        else if (k == 5) {
            r.tmin = t0 * rng_uniform(&g);
            r.tmax = t0 + (t1 - t0) * 3 * rng_uniform(&g);
        }
        int expect = isect_part_all(&s, 0, &r, full);
        int unrefined = (u[0] > r.tmin && u[0] < r.tmax) + (u[1] > r.tmin && u[1] < r.tmax);
        between += unrefined != expect;
        clear += k == 0;
        ck_assert_int_eq(isect_part_crossings(&s, 0, &r), expect);
        real gr[ISECT_HOT_REALS];
        int reals, code = isect_hot_make(&s, 0, gr, &reals);
        ck_assert_int_eq(isect_hot_crossings(code, gr, &r, NULL), expect);
        /* [NUM-SPHERE-ANY-1] The first root taken, or none. */
        ck_assert_int_eq(isect_part_crossed(&s, 0, &r), expect > 0);
        ck_assert_int_eq(isect_hot_crossed(code, gr, &r, NULL), expect > 0);
        int first_out = !(u[0] > r.tmin && u[0] < r.tmax) && !(t0 > r.tmin && t0 < r.tmax);
        second_only += expect == 1 && first_out;
    }
    ck_assert_msg(second_only > 1000, "%d rays cross the second root alone", second_only);
    /* Enough rays on which counting the unrefined roots would be wrong,
     * and enough with both roots clear of the ends. */
    ck_assert_msg(between > 1000 && clear > 5000, "between %d, clear %d", between, clear);
}
END_TEST

/* Attack 21's two directions far from unit length ([NUM-SPHERE-3]'s range
 * of |d|_max): with |d| = 2^-401 a gap went subnormal, with |d| about 2^455
 * it overflowed, and the count took 2 where the refined roots give 1.  The
 * expected count is the refined roots' (isect_part_all); that it is 1 is
 * asserted so that each case still tells the two counts apart. */
START_TEST(test_isect_sphere_count_far_from_unit_directions)
{
    static const struct { double c[3], radius, o[3], d[3], tmin, tmax; } cases[] = {
        {{0x1.949dfee56af26p-212, 0x1.05f824ef4fbcdp-212, 0x1.0feca4124e21bp-210}, 0x1.835201fe39a9ap-267,
         {0x1.949dfee56af26p-212, 0x1.05f824ef4fbcep-212, 0x1.0feca4124e21bp-210},
         {0, -0x1.4b408044980edp-401, 0}, 0x1.ec127f4a9c4bap+135, 0x1.10aa02af846bp+137},
        {{-0x1.3c5c4f6186a6ap+164, -0x1.f9f3e7ccbc9a7p+169, -0x1.42a530dce2811p+168}, 0x1.1abe55e61fb61p+116,
         {-0x1.3c5c4f6534876p+164, -0x1.f9f3e7cc6bd57p+169, -0x1.42a530dd063d2p+168},
         {0x1.44ee5cafaf5edp+453, -0x1.bdd39e366f833p+454, 0x1.8a7dcff56142p+452}, -HUGE_VAL, HUGE_VAL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        scene_prim s = prim_sphere(vec_make(cases[i].c[0], cases[i].c[1], cases[i].c[2]), cases[i].radius);
        ray r = make_ray(vec_make(cases[i].o[0], cases[i].o[1], cases[i].o[2]),
                         vec_make(cases[i].d[0], cases[i].d[1], cases[i].d[2]));
        r.tmin = cases[i].tmin;
        r.tmax = cases[i].tmax;
        hit full[ISECT_MAX_CROSSINGS];
        int expect = isect_part_all(&s, 0, &r, full);
        ck_assert_int_eq(expect, 1);
        ck_assert_int_eq(isect_part_crossings(&s, 0, &r), expect);
        real gr[ISECT_HOT_REALS];
        int reals, code = isect_hot_make(&s, 0, gr, &reals);
        if (r.tmin >= 0)   /* a hot record's walk never has a negative tmin */
            ck_assert_int_eq(isect_hot_crossings(code, gr, &r, NULL), expect);
    }
}
END_TEST

/* ---- plane ---- */

START_TEST(test_isect_plane_hit_by_hand)
{
    /* Plane y = -1, normal +y.  From (0,4,0) down: t = 5, front side. */
    ray r = make_ray(vec_make(0, 4, 0), vec_make(0, -1, 0));
    hit h;
    ck_assert(isect_plane(vec_make(3, -1, 7), vec_make(0, 1, 0), &r, &h));
    ck_assert_near(h.t, 5.0, 0.0);
    ck_assert_vec_near(h.point, vec_make(0, -1, 0), 0.0);
    ck_assert_vec_near(h.normal, vec_make(0, 1, 0), 0.0);
    ck_assert_int_eq(h.entering, 1);
    /* From below: the same declared normal, entering 0 (two-sided sheet). */
    r = make_ray(vec_make(0, -3, 0), vec_make(0, 1, 0));
    ck_assert(isect_plane(vec_make(3, -1, 7), vec_make(0, 1, 0), &r, &h));
    ck_assert_near(h.t, 2.0, 0.0);
    ck_assert_vec_near(h.normal, vec_make(0, 1, 0), 0.0);
    ck_assert_int_eq(h.entering, 0);
    /* At 45 degrees from (0,1,0): drops 2 in y after 2 sqrt 2, at (2,-1,0). */
    r = make_ray(vec_make(0, 1, 0), vec_normalize(vec_make(1, -1, 0)));
    ck_assert(isect_plane(vec_make(3, -1, 7), vec_make(0, 1, 0), &r, &h));
    ck_assert_near(h.t, 2 * sqrt(2.0), 1e-15);
    ck_assert_vec_near(h.point, vec_make(2, -1, 0), 1e-15);
}
END_TEST

START_TEST(test_isect_plane_parallel_and_behind_miss)
{
    hit h;
    ray r = make_ray(vec_make(0, 4, 0), vec_make(1, 0, 0));
    ck_assert(!isect_plane(vec_make(0, -1, 0), vec_make(0, 1, 0), &r, &h));
    r = make_ray(vec_make(0, -1, 0), vec_make(0, 0, 1)); /* in the plane */
    ck_assert(!isect_plane(vec_make(0, -1, 0), vec_make(0, 1, 0), &r, &h));
    r = make_ray(vec_make(0, 4, 0), vec_make(0, 1, 0)); /* going away */
    ck_assert(!isect_plane(vec_make(0, -1, 0), vec_make(0, 1, 0), &r, &h));
    r = make_ray(vec_make(0, 4, 0), vec_make(0, -1, 0));
    r.tmax = 5.0;
    ck_assert(!isect_plane(vec_make(0, -1, 0), vec_make(0, 1, 0), &r, &h));
    r.tmin = 4.0;
    r.tmax = 5.5;
    ck_assert(isect_plane(vec_make(0, -1, 0), vec_make(0, 1, 0), &r, &h));
}
END_TEST

START_TEST(test_isect_plane_point_on_plane_from_far)
{
    /* A tilted plane through (1,2,3) seen from 1e6 away: the hit point's
     * distance to the plane is rounding of |p|, not of the eye's 1e6. */
    vec3 n = vec_normalize(vec_make(1, 2, 2)), p0 = vec_make(1, 2, 3);
    rng g = {21, 0};
    for (int i = 0; i < 100; i++) {
        vec3 eye = vec_scale(rng_unit(&g), 1e6);
        vec3 target = vec_add(p0, vec_cross(n, rng_unit(&g)));
        ray r = make_ray(eye, vec_normalize(vec_sub(target, eye)));
        hit h;
        if (!isect_plane(p0, n, &r, &h))
            continue;
        ck_assert_near(vec_dot(n, vec_sub(h.point, p0)), 0.0, 16 * DBL_EPSILON * 5);
    }
}
END_TEST

/* ---- disk ---- */

START_TEST(test_isect_disk_radius_inclusive)
{
    /* Unit disk in z = 0.  A ray down through (1,0): exactly on the rim,
     * included; through (1+1e-12,0): outside.  Through the centre: t = 5. */
    hit h;
    vec3 c = vec_make(0, 0, 0), n = vec_make(0, 0, 1);
    ray r = make_ray(vec_make(1, 0, 5), vec_make(0, 0, -1));
    ck_assert(isect_disk(c, n, 1, &r, &h));
    ck_assert_near(h.t, 5.0, 0.0);
    ck_assert_vec_near(h.point, vec_make(1, 0, 0), 0.0);
    ck_assert_vec_near(h.normal, n, 0.0);
    ck_assert_int_eq(h.entering, 1);
    r = make_ray(vec_make(1 + 1e-12, 0, 5), vec_make(0, 0, -1));
    ck_assert(!isect_disk(c, n, 1, &r, &h));
    r = make_ray(vec_make(0.5, 0.5, -2), vec_make(0, 0, 1));
    ck_assert(isect_disk(c, n, 1, &r, &h));
    ck_assert_near(h.t, 2.0, 0.0);
    ck_assert_int_eq(h.entering, 0);
    r = make_ray(vec_make(0.5, 0.5, 0), vec_make(1, 0, 0)); /* parallel, in plane */
    ck_assert(!isect_disk(c, n, 1, &r, &h));
}
END_TEST

START_TEST(test_isect_disk_tilted)
{
    /* Disk centred (0,0,4) facing -z... tilted: normal (0,1,1)/sqrt 2, R 1.
     * A ray along +z on the axis hits the centre at t = 4 + 5 = 9 from
     * z = -5; at y = 0.6 the plane is z = 4 - 0.6, t = 8.4, and the hit
     * (0, 0.6, 3.4) is 0.6 sqrt 2 = 0.85 from the centre: inside.  At
     * y = 0.75 the distance is 1.06: outside. */
    vec3 c = vec_make(0, 0, 4), n = vec_normalize(vec_make(0, 1, 1));
    hit h;
    ray r = make_ray(vec_make(0, 0, -5), vec_make(0, 0, 1));
    ck_assert(isect_disk(c, n, 1, &r, &h));
    ck_assert_near(h.t, 9.0, 1e-14);
    r = make_ray(vec_make(0, 0.6, -5), vec_make(0, 0, 1));
    ck_assert(isect_disk(c, n, 1, &r, &h));
    ck_assert_near(h.t, 8.4, 1e-14);
    ck_assert_vec_near(h.normal, n, 1e-15);
    r = make_ray(vec_make(0, 0.75, -5), vec_make(0, 0, 1));
    ck_assert(!isect_disk(c, n, 1, &r, &h));
}
END_TEST

/* ---- triangle ---- */

START_TEST(test_isect_triangle_hit_by_hand)
{
    /* (0,0,0),(1,0,0),(0,1,0): normal x cross y = +z.  Down through
     * (0.25,0.25) from z = 2: t = 2, front. */
    vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    hit h;
    ray r = make_ray(vec_make(0.25, 0.25, 2), vec_make(0, 0, -1));
    ck_assert(isect_triangle(v, NULL, &r, &h));
    ck_assert_near(h.t, 2.0, 0.0);
    ck_assert_near(r.tmax, 2.0, 0.0);
    ck_assert_vec_near(h.point, vec_make(0.25, 0.25, 0), 1e-16);
    ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 0.0);
    ck_assert_vec_near(h.shading_normal, vec_make(0, 0, 1), 0.0);
    ck_assert_int_eq(h.entering, 1);
    /* From below: same normal, back side. */
    r = make_ray(vec_make(0.25, 0.25, -3), vec_make(0, 0, 1));
    ck_assert(isect_triangle(v, NULL, &r, &h));
    ck_assert_near(h.t, 3.0, 0.0);
    ck_assert_int_eq(h.entering, 0);
    /* Outside the hypotenuse x + y = 1. */
    r = make_ray(vec_make(0.6, 0.6, 2), vec_make(0, 0, -1));
    ck_assert(!isect_triangle(v, NULL, &r, &h));
    r = make_ray(vec_make(-0.01, 0.5, 2), vec_make(0, 0, -1));
    ck_assert(!isect_triangle(v, NULL, &r, &h));
    /* tmax below 2: miss. */
    r = make_ray(vec_make(0.25, 0.25, 2), vec_make(0, 0, -1));
    r.tmax = 1.5;
    ck_assert(!isect_triangle(v, NULL, &r, &h));
    /* Parallel to the plane: miss. */
    r = make_ray(vec_make(0.25, 0.25, 0), vec_make(1, 0, 0));
    ck_assert(!isect_triangle(v, NULL, &r, &h));
}
END_TEST

START_TEST(test_isect_triangle_oblique)
{
    /* The triangle x + y + z = 1 on the axes, seen from the origin along
     * (1,1,1)/sqrt 3: t = 1/sqrt 3 at (1/3,1/3,1/3); the normal
     * (-1,1,0) x (-1,0,1) = (1,1,1) points away from the origin, so the
     * ray meets the back (entering 0). */
    vec3 v[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    hit h;
    ray r = make_ray(vec_make(0, 0, 0), vec_normalize(vec_make(1, 1, 1)));
    ck_assert(isect_triangle(v, NULL, &r, &h));
    ck_assert_near(h.t, 1 / sqrt(3.0), 1e-15);
    ck_assert_vec_near(h.point, vec_make(1 / 3.0, 1 / 3.0, 1 / 3.0), 1e-15);
    ck_assert_vec_near(h.normal, vec_normalize(vec_make(1, 1, 1)), 1e-15);
    ck_assert_int_eq(h.entering, 0);
    /* With a negative dominant direction component (winding swap path). */
    r = make_ray(vec_make(1, 1, 1), vec_normalize(vec_make(-1, -1, -1.5)));
    ck_assert(isect_triangle(v, NULL, &r, &h));
    ck_assert_near(vec_dot(h.point, vec_make(1, 1, 1)), 1.0, 1e-15);
    ck_assert_int_eq(h.entering, 1);
}
END_TEST

START_TEST(test_isect_triangle_shading_normal_interpolated)
{
    /* Vertex normals z, x, y at (0,0,0),(1,0,0),(0,1,0).  At (0.25,0.25)
     * the weights are 0.5, 0.25, 0.25: (0.25,0.25,0.5), unit (1,1,2)/sqrt 6. */
    vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    vec3 n[3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    hit h;
    ray r = make_ray(vec_make(0.25, 0.25, 2), vec_make(0, 0, -1));
    ck_assert(isect_triangle(v, n, &r, &h));
    ck_assert_vec_near(h.shading_normal, vec_scale(vec_make(1, 1, 2), 1 / sqrt(6.0)), 1e-15);
    ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 0.0);
    scene_prim p = prim_triangle(v[0], v[1], v[2]);
    p.u.triangle.n = n;
    r = make_ray(vec_make(0.25, 0.25, 2), vec_make(0, 0, -1));
    ck_assert(isect_prim(&p, &r, &h));
    ck_assert_vec_near(h.shading_normal, vec_scale(vec_make(1, 1, 2), 1 / sqrt(6.0)), 1e-15);
}
END_TEST

/* Hits over a set of triangles (as a mesh would be tested). */
static int mesh_hits(const vec3 (*tri)[3], int count, vec3 o, vec3 target)
{
    int hits = 0;
    for (int i = 0; i < count; i++) {
        ray r = make_ray(o, vec_sub(target, o));
        hit h;
        hits += isect_triangle(tri[i], NULL, &r, &h);
    }
    return hits;
}

START_TEST(test_isect_triangle_watertight_shared_edge)
{
    /* A non-planar quad A B C D split along A-C.  Rays aimed at points of
     * the shared edge (rounded, so they pass within an ulp of it, on either
     * side) from many origins must hit at least one triangle. */
    vec3 a = {0.1, -0.2, 0.03}, b = {1.3, 0.1, 0.3}, c = {1.1, 1.7, -0.2}, d = {-0.15, 1.05, 0.11};
    vec3 tri[2][3] = {{a, b, c}, {a, c, d}};
    vec3 n1 = vec_normalize(vec_cross(vec_sub(b, a), vec_sub(c, a)));
    vec3 n2 = vec_normalize(vec_cross(vec_sub(c, a), vec_sub(d, a)));
    rng g = {31, 0};
    int zero = 0, two = 0, rays = 0;
    while (rays < 20000) {
        vec3 o = vec_add(vec_make(0.5, 0.5, 0), vec_scale(rng_unit(&g), 3 + 1e3 * rng_uniform(&g)));
        double s = rays % 2 ? rng_uniform(&g) : (double)(rays % 997 + 1) / 998.0;
        vec3 target = vec_madd(a, vec_sub(c, a), s);
        /* Where the two faces are seen from opposite sides the edge is a
         * silhouette and a miss by an ulp is right: only other views count. */
        vec3 dir = vec_normalize(vec_sub(target, o));
        if (vec_dot(dir, n1) * vec_dot(dir, n2) < 0.01)
            continue;
        rays++;
        int n = mesh_hits((const vec3 (*)[3])tri, 2, o, target);
        zero += n == 0;
        two += n == 2;
    }
    ck_assert_int_eq(zero, 0);
    ck_assert_msg(two < 20000, "every ray hit both: the edge test is too loose");
}
END_TEST

START_TEST(test_isect_triangle_watertight_fan_vertex)
{
    /* Seven triangles around a shared vertex v (a closed fan, slightly
     * bumpy).  Rays aimed exactly at v, and at points of the spokes, from
     * all around: never zero hits. */
    vec3 v = vec_make(0.3, -0.7, 0.2), ring[7];
    vec3 tri[7][3];
    for (int k = 0; k < 7; k++) {
        double ang = 2 * 3.14159265358979 * k / 7;
        ring[k] = vec_add(v, vec_make(cos(ang), sin(ang), 0.1 * (k % 3) - 0.1));
    }
    for (int k = 0; k < 7; k++) {
        tri[k][0] = v;
        tri[k][1] = ring[k];
        tri[k][2] = ring[(k + 1) % 7];
    }
    rng g = {32, 0};
    for (int i = 0; i < 20000; i++) {
        vec3 u = rng_unit(&g);
        if (fabs(u.z) < 0.5)
            continue; /* too grazing: the bumpy fan has silhouettes there */
        vec3 o = vec_add(v, vec_scale(u, 0.5 + 100 * rng_uniform(&g)));
        vec3 target = i % 2 ? v : vec_madd(v, vec_sub(ring[i % 7], v), 0.5 * rng_uniform(&g));
        if (fabs(vec_normalize(vec_sub(target, o)).z) < 0.4)
            continue;
        ck_assert_int_ge(mesh_hits((const vec3 (*)[3])tri, 7, o, target), 1);
    }
}
END_TEST

START_TEST(test_isect_triangle_watertight_sweep)
{
    /* A dense sweep of parallel rays across a two-triangle square: every
     * ray inside the square hits exactly one or (on the diagonal) two. */
    vec3 tri[2][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
    vec3 dir = vec_normalize(vec_make(0.3, -0.2, -1));
    for (int i = 1; i < 400; i++) {
        for (int j = 1; j < 400; j++) {
            vec3 target = vec_make(i / 400.0, j / 400.0, 0);
            vec3 o = vec_madd(target, dir, -7.0);
            int n = mesh_hits((const vec3 (*)[3])tri, 2, o, vec_add(o, dir));
            /* ck_abort_msg on a miss, not a ck_assert per ray: a passed
             * assertion is a message to Check's parent, 300 000 of them. */
            if (n < 1)
                ck_abort_msg("ray at (%d,%d) slipped through", i, j);
            if (i != j && n != 1)
                ck_abort_msg("ray at (%d,%d) hit %d", i, j, n);
        }
    }
}
END_TEST

/* ---- box ---- */

START_TEST(test_isect_box_hit_by_hand)
{
    /* Box [-1,1]x[-2,2]x[-3,3]; from (-5,.5,.5) along +x: enters x = -1 at
     * t = 4 (normal -x), leaves x = 1 at t = 6 (normal +x). */
    scene_prim bx = prim_box(vec_make(-1, -2, -3), vec_make(1, 2, 3));
    ray r = make_ray(vec_make(-5, 0.5, 0.5), vec_make(1, 0, 0));
    hit h, out[ISECT_MAX_CROSSINGS];
    ck_assert(isect_box(bx.u.box.lo, bx.u.box.hi, &r, &h));
    ck_assert_near(h.t, 4.0, 0.0);
    ck_assert_vec_near(h.point, vec_make(-1, 0.5, 0.5), 0.0);
    ck_assert_vec_near(h.normal, vec_make(-1, 0, 0), 0.0);
    ck_assert_int_eq(h.entering, 1);
    r = make_ray(vec_make(-5, 0.5, 0.5), vec_make(1, 0, 0));
    ck_assert_int_eq(isect_prim_all(&bx, &r, out), 2);
    ck_assert_near(out[1].t, 6.0, 0.0);
    ck_assert_vec_near(out[1].normal, vec_make(1, 0, 0), 0.0);
    ck_assert_int_eq(out[1].entering, 0);
    /* Oblique, from above the top face z = 3: from (0,0,7) along
     * (0.6,0,-0.8): z = 3 at t = 5 (x = 3 > 1: misses the top), x = 1 at
     * t = 5/3 with z = 7 - 4/3 > 3: still above.  It misses. */
    r = make_ray(vec_make(0, 0, 7), vec_make(0.6, 0, -0.8));
    ck_assert(!isect_box(bx.u.box.lo, bx.u.box.hi, &r, &h));
    /* From (0,0,7) along (0.1,0,-0.5)/|.|: z = 3 at s = 8 (x = 0.8): top. */
    r = make_ray(vec_make(0, 0, 7), vec_normalize(vec_make(0.1, 0, -0.5)));
    ck_assert(isect_box(bx.u.box.lo, bx.u.box.hi, &r, &h));
    ck_assert_near(h.t, 4 * sqrt(0.26) / 0.5, 1e-14);
    ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 0.0);
    ck_assert_near(h.point.z, 3.0, 0.0);
}
END_TEST

START_TEST(test_isect_box_from_inside_and_on_surface)
{
    vec3 lo = vec_make(-1, -2, -3), hi = vec_make(1, 2, 3);
    hit h;
    ray r = make_ray(vec_make(0, 0, 0), vec_make(0, 0, -1));
    ck_assert(isect_box(lo, hi, &r, &h));
    ck_assert_near(h.t, 3.0, 0.0);
    ck_assert_vec_near(h.normal, vec_make(0, 0, -1), 0.0);
    ck_assert_int_eq(h.entering, 0);
    /* On the face x = -1 going in: the t = 0 entry is excluded, exit at 2. */
    r = make_ray(vec_make(-1, 0, 0), vec_make(1, 0, 0));
    ck_assert(isect_box(lo, hi, &r, &h));
    ck_assert_near(h.t, 2.0, 0.0);
    ck_assert_int_eq(h.entering, 0);
    /* On the face going out: nothing. */
    r = make_ray(vec_make(-1, 0, 0), vec_make(-1, 0, 0));
    ck_assert(!isect_box(lo, hi, &r, &h));
}
END_TEST

START_TEST(test_isect_box_axis_parallel_on_slab_plane)
{
    /* Along +x with y exactly on the face plane y = 2 (and y = -2): 0 * inf
     * would be NaN in a naive slab test; the closed faces make it a hit at
     * x = -1, t = 4.  A hair above the face: a miss.  -0.0 components too. */
    vec3 lo = vec_make(-1, -2, -3), hi = vec_make(1, 2, 3);
    hit h;
    ray r = make_ray(vec_make(-5, 2, 0), vec_make(1, 0, 0));
    ck_assert(isect_box(lo, hi, &r, &h));
    ck_assert_near(h.t, 4.0, 0.0);
    ck_assert_vec_near(h.normal, vec_make(-1, 0, 0), 0.0);
    r = make_ray(vec_make(-5, -2, 3), vec_make(1, -0.0, -0.0));
    ck_assert(isect_box(lo, hi, &r, &h));
    ck_assert_near(h.t, 4.0, 0.0);
    r = make_ray(vec_make(-5, nextafter(2.0, 3.0), 0), vec_make(1, 0, 0));
    ck_assert(!isect_box(lo, hi, &r, &h));
    /* Down the y axis with x and z on edges: enters y = 2 at t = 3. */
    r = make_ray(vec_make(1, 5, -3), vec_make(0, -1, 0));
    ck_assert(isect_box(lo, hi, &r, &h));
    ck_assert_near(h.t, 3.0, 0.0);
    ck_assert_vec_near(h.normal, vec_make(0, 1, 0), 0.0);
}
END_TEST

START_TEST(test_isect_box_edge_touch_is_one_hit)
{
    /* Unit cube; from (-1,0,.5) along (1,1,0)/sqrt 2 the ray only touches
     * the edge x = 0, y = 1 at t = sqrt 2: one crossing.  From (-1,-1,.5)
     * it goes in through the edge x = y = 0 (t = sqrt 2, the tie goes to
     * the x face) and out through x = y = 1 (t = 2 sqrt 2). */
    scene_prim bx = prim_box(vec_make(0, 0, 0), vec_make(1, 1, 1));
    vec3 dir = vec_normalize(vec_make(1, 1, 0));
    hit out[ISECT_MAX_CROSSINGS];
    ray r = make_ray(vec_make(-1, 0, 0.5), dir);
    ck_assert_int_eq(isect_prim_all(&bx, &r, out), 1);
    ck_assert_near(out[0].t, sqrt(2.0), 1e-15);
    r = make_ray(vec_make(-1, -1, 0.5), dir);
    ck_assert_int_eq(isect_prim_all(&bx, &r, out), 2);
    ck_assert_near(out[0].t, sqrt(2.0), 1e-15);
    ck_assert_vec_near(out[0].normal, vec_make(-1, 0, 0), 0.0);
    ck_assert_near(out[1].t, 2 * sqrt(2.0), 1e-15);
    ck_assert_vec_near(out[1].normal, vec_make(1, 0, 0), 0.0);
}
END_TEST

START_TEST(test_isect_box_tmin_tmax)
{
    scene_prim bx = prim_box(vec_make(-1, -1, -1), vec_make(1, 1, 1));
    hit h;
    ray r = make_ray(vec_make(-5, 0, 0), vec_make(1, 0, 0)); /* t 4 and 6 */
    r.tmax = 4.0;
    ck_assert(!isect_prim(&bx, &r, &h));
    r.tmin = 4.0;
    r.tmax = 7.0;
    ck_assert(isect_prim(&bx, &r, &h));
    ck_assert_near(h.t, 6.0, 0.0);
    ck_assert_near(r.tmax, 6.0, 0.0);
}
END_TEST

/* The hot record's nearest hit (isect_hot_hit, the nearest walk's) is
 * isect_box's: whether it hits, its t and the ray's tmax after. */
static void assert_hot_box_hit_matches(int code, const real *g, const scene_prim *bx, const ray *r)
{
    ray r1 = *r, r2 = *r;
    hit h1, h2;
    int met = isect_hot_hit(code, g, &r1, &h1);
    ck_assert_int_eq(met, isect_box(bx->u.box.lo, bx->u.box.hi, &r2, &h2));
    ck_assert(r1.tmax == r2.tmax);
    if (met)
        ck_assert(h1.t == h2.t);
}

/* A box's hot record counts what the box itself counts (isect_part_crossings,
 * through box_hits), also where hot_box_crossings finds the segment apart
 * from one of the box's slabs without box_slabs.  By hand on [0, 1]^3: from
 * the top face's middle going up, nothing (the start, t = 0, is outside
 * (0, inf)); going down, the bottom at t = 1; from y = 2 down, t = 1 and
 * 2; from y = 1.5 up with tmin = -2, t = -1.5 and -0.5 (the quick answer
 * holds only for tmin >= 0); from y = -2 up, tmax at the entry t = 2
 * (open: nothing) and an ulp past it (the entry); a ray along y at 2^-1021
 * whose crossings are held at 2^1020, inside tmax = 1.5 2^1020.  Then 20000 rays from
 * below a box (or above it, going down) with tmax an ulp either side of the rounded entry (where
 * tmax d_y rounded can equal lo_y - o_y though the entry is inside), and
 * 20000 rays whose origins sit on a box's planes, an ulp off them or
 * anywhere, with direction components 0, -0 or random, and intervals
 * starting at 0, -0, past 0 or below; for the random ones the nearest hit
 * (isect_hot_hit) too. */
START_TEST(test_isect_hot_box_crossings_match_the_box)
{
    real g[ISECT_HOT_REALS];
    int reals;
    scene_prim bx = prim_box(vec_make(0, 0, 0), vec_make(1, 1, 1));
    int code = isect_hot_make(&bx, 0, g, &reals);
    ck_assert_int_eq(ISECT_HOT_KIND(code), ISECT_HOT_BOX);
    ray r = make_ray(vec_make(0.5, 1, 0.5), vec_make(0, 1, 0));
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 0);
    r.dir = vec_make(0, -1, 0);
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 1);
    r.origin.y = 2;
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 2);
    r = make_ray(vec_make(0.5, 1.5, 0.5), vec_make(0, 1, 0));
    r.tmin = -2;
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 2);
    r = make_ray(vec_make(0.5, -2, 0.5), vec_make(0, 1, 0));
    r.tmax = 2;
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 0);
    r.tmax = nextafter(2.0, 3.0);
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 1);
    /* Along y at 2^-1021 from y = -1: both crossings (2^1021, 2^1022) are
     * held at 2^1020 (isect_quotient), one crossing inside tmax = 1.5 2^1020,
     * though tmax d_y rounded (0.75) lies short of the box. */
    r = make_ray(vec_make(0.5, -1, 0.5), vec_make(0, 0x1p-1021, 0));
    r.tmax = 0x1.8p1020;
    ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), 1);
    ck_assert_int_eq(isect_part_crossings(&bx, 0, &r), 1);
    rng s = {91, 0};
    for (int i = 0; i < 20000; i++) {
        double l = 4 * rng_uniform(&s) - 2, dy = 0.01 + rng_uniform(&s);
        bx = prim_box(vec_make(-1, l, -1), vec_make(1, l + 1, 1));
        code = isect_hot_make(&bx, 0, g, &reals);
        /* Half of them from above, down. */
        double face = i % 2 ? l + 1 : l, away = (i % 2 ? 1 : -1) * (3 * rng_uniform(&s) + 1e-3);
        r = make_ray(vec_make(0.5, face + away, 0.5), vec_make(0, i % 2 ? -dy : dy, 0));
        double entry = (face - r.origin.y) / r.dir.y;
        double ends[3] = {nextafter(entry, -HUGE_VAL), entry, nextafter(entry, HUGE_VAL)};
        for (int k = 0; k < 3; k++) {
            r.tmax = ends[k];
            ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), isect_part_crossings(&bx, 0, &r));
            assert_hot_box_hit_matches(code, g, &bx, &r);
        }
    }
    for (int i = 0; i < 20000; i++) {
        double lo[3], hi[3], o[3], d[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = 4 * rng_uniform(&s) - 2;
            hi[k] = lo[k] + 0.01 + 2 * rng_uniform(&s);
            double pick = rng_uniform(&s), c = pick < 0.5 ? (pick < 0.25 ? lo[k] : hi[k]) : 6 * rng_uniform(&s) - 3;
            double side = rng_uniform(&s);
            o[k] = side < 0.2 ? nextafter(c, -HUGE_VAL) : side < 0.4 ? nextafter(c, HUGE_VAL) : c;
            double w = rng_uniform(&s);
            d[k] = w < 0.15 ? 0.0 : w < 0.25 ? -0.0 : 2 * rng_uniform(&s) - 1;
        }
        if (d[0] == 0 && d[1] == 0 && d[2] == 0)
            d[i % 3] = 1;
        bx = prim_box(vec_make(lo[0], lo[1], lo[2]), vec_make(hi[0], hi[1], hi[2]));
        code = isect_hot_make(&bx, 0, g, &reals);
        r = make_ray(vec_make(o[0], o[1], o[2]), vec_make(d[0], d[1], d[2]));
        double w = rng_uniform(&s);
        r.tmin = w < 0.3 ? 0.0 : w < 0.4 ? -0.0 : w < 0.8 ? 1e-3 * rng_uniform(&s) : -rng_uniform(&s);
        r.tmax = rng_uniform(&s) < 0.5 ? HUGE_VAL : r.tmin + 4 * rng_uniform(&s);
        ck_assert_int_eq(isect_hot_crossings(code, g, &r, NULL), isect_part_crossings(&bx, 0, &r));
        assert_hot_box_hit_matches(code, g, &bx, &r);
    }
}
END_TEST

/* ---- transformed primitives ---- */

START_TEST(test_isect_prim_ellipsoid)
{
    /* Unit sphere scaled by (2,1,1): x^2/4 + y^2 + z^2 = 1.  Along +x from
     * (-10,0,0): x = -2, t = 8, normal -x.  From (-10,0.5,0): x = -sqrt 3,
     * t = 10 - sqrt 3, normal along the gradient (x/4, y, 0) =
     * (-sqrt3/4, 1/2, 0). */
    scene_prim e = prim_sphere(vec_make(0, 0, 0), 1);
    scene_frame e_frame;
    prim_set_xform(&e, &e_frame, xform_scale(vec_make(2, 1, 1)));
    hit h, out[ISECT_MAX_CROSSINGS];
    ray r = make_ray(vec_make(-10, 0, 0), vec_make(1, 0, 0));
    ck_assert(isect_prim(&e, &r, &h));
    ck_assert_near(h.t, 8.0, 1e-14);
    ck_assert_vec_near(h.point, vec_make(-2, 0, 0), 1e-14);
    ck_assert_vec_near(h.normal, vec_make(-1, 0, 0), 1e-15);
    ck_assert_int_eq(h.entering, 1);
    r = make_ray(vec_make(-10, 0.5, 0), vec_make(1, 0, 0));
    ck_assert(isect_prim(&e, &r, &h));
    ck_assert_near(h.t, 10 - sqrt(3.0), 1e-14);
    ck_assert_vec_near(h.point, vec_make(-sqrt(3.0), 0.5, 0), 1e-14);
    ck_assert_vec_near(h.normal, vec_normalize(vec_make(-sqrt(3.0) / 4, 0.5, 0)), 1e-15);
    ck_assert_vec_near(h.shading_normal, h.normal, 0.0);
    /* Both crossings, the exit at x = +sqrt 3 with normal (sqrt3/4, 1/2, 0). */
    r = make_ray(vec_make(-10, 0.5, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(isect_prim_all(&e, &r, out), 2);
    ck_assert_near(out[1].t, 10 + sqrt(3.0), 1e-14);
    ck_assert_vec_near(out[1].normal, vec_normalize(vec_make(sqrt(3.0) / 4, 0.5, 0)), 1e-15);
    ck_assert_int_eq(out[1].entering, 0);
    /* Along y the ellipsoid is as thin as the sphere: y = 1 misses... just. */
    r = make_ray(vec_make(-10, 1.0000001, 0), vec_make(1, 0, 0));
    ck_assert(!isect_prim(&e, &r, &h));
}
END_TEST

START_TEST(test_isect_prim_rotated_box)
{
    /* Box [-1,1]x[-.5,.5]x[-.5,.5] turned 90 degrees about z spans
     * [-.5,.5]x[-1,1]: up +y from (0,-5,0) it is met at y = -1, t = 4. */
    scene_prim bx = prim_box(vec_make(-1, -0.5, -0.5), vec_make(1, 0.5, 0.5));
    scene_frame bx_frame;
    prim_set_xform(&bx, &bx_frame, xform_rotate_xyz(vec_make(0, 0, 90)));
    hit h;
    ray r = make_ray(vec_make(0, -5, 0), vec_make(0, 1, 0));
    ck_assert(isect_prim(&bx, &r, &h));
    ck_assert_near(h.t, 4.0, 1e-15);
    ck_assert_vec_near(h.normal, vec_make(0, -1, 0), 1e-15);
    r = make_ray(vec_make(0.7, -5, 0), vec_make(0, 1, 0));
    ck_assert(!isect_prim(&bx, &r, &h));
    /* The cube [-1,1]^3 turned 45 degrees about z: local x' = (x+y)/sqrt2,
     * y' = (y-x)/sqrt2.  Along +x at y = 0.2 the ray enters where
     * y' = 1, x = 0.2 - sqrt 2, so t = 5.2 - sqrt 2 from x = -5; the face
     * y' = 1 has world normal (-1,1,0)/sqrt 2. */
    scene_prim cube = prim_box(vec_make(-1, -1, -1), vec_make(1, 1, 1));
    scene_frame cube_frame;
    prim_set_xform(&cube, &cube_frame, xform_rotate_xyz(vec_make(0, 0, 45)));
    r = make_ray(vec_make(-5, 0.2, 0), vec_make(1, 0, 0));
    ck_assert(isect_prim(&cube, &r, &h));
    ck_assert_near(h.t, 5.2 - sqrt(2.0), 1e-14);
    ck_assert_vec_near(h.normal, vec_make(-sqrt(0.5), sqrt(0.5), 0), 1e-15);
    ck_assert_int_eq(h.entering, 1);
}
END_TEST

START_TEST(test_isect_prim_translated_scaled_disk)
{
    /* A unit disk (normal +z) scaled by 3 and moved to (0,0,2) is a radius
     * 3 disk in z = 2: from (2.9,0,10) down, t = 8; at x = 3.1, a miss. */
    scene_prim d = prim_blank(PRIM_DISK);
    d.u.disk.normal = vec_make(0, 0, 1);
    d.u.disk.radius = 1;
    xform s = xform_scale(vec_make(3, 3, 3)), t = xform_translate(vec_make(0, 0, 2));
    scene_frame d_frame;
    prim_set_xform(&d, &d_frame, xform_compose(&t, &s));
    hit h;
    ray r = make_ray(vec_make(2.9, 0, 10), vec_make(0, 0, -1));
    ck_assert(isect_prim(&d, &r, &h));
    ck_assert_near(h.t, 8.0, 1e-14);
    ck_assert_vec_near(h.normal, vec_make(0, 0, 1), 1e-15);
    r = make_ray(vec_make(3.1, 0, 10), vec_make(0, 0, -1));
    ck_assert(!isect_prim(&d, &r, &h));
}
END_TEST

START_TEST(test_isect_prim_bounds)
{
    vec3 lo, hi;
    scene_prim s = prim_sphere(vec_make(1, 2, 3), 2);
    ck_assert(isect_prim_bounds(&s, &lo, &hi));
    ck_assert_vec_near(lo, vec_make(-1, 0, 1), 0.0);
    ck_assert_vec_near(hi, vec_make(3, 4, 5), 0.0);
    scene_prim pl = prim_plane(vec_make(0, 0, 0), vec_make(0, 1, 0));
    ck_assert(!isect_prim_bounds(&pl, &lo, &hi));
    /* Disk facing +z, radius 2: flat in z, +-2 in x and y. */
    scene_prim d = prim_blank(PRIM_DISK);
    d.u.disk.normal = vec_make(0, 0, 1);
    d.u.disk.radius = 2;
    ck_assert(isect_prim_bounds(&d, &lo, &hi));
    ck_assert_vec_near(lo, vec_make(-2, -2, 0), 0.0);
    ck_assert_vec_near(hi, vec_make(2, 2, 0), 0.0);
    /* The 45-degree cube: corners reach sqrt 2 in x and y. */
    scene_prim cube = prim_box(vec_make(-1, -1, -1), vec_make(1, 1, 1));
    scene_frame cube_frame;
    prim_set_xform(&cube, &cube_frame, xform_rotate_xyz(vec_make(0, 0, 45)));
    ck_assert(isect_prim_bounds(&cube, &lo, &hi));
    ck_assert_vec_near(hi, vec_make(sqrt(2.0), sqrt(2.0), 1), 1e-15);
}
END_TEST

/* ---- secondary rays ---- */

START_TEST(test_ray_spawn_offsets_to_the_side_of_dir)
{
    vec3 p = vec_make(1e3, -2, 5), n = vec_make(0, 1, 0);
    ray out = ray_spawn(p, n, vec_make(0.6, 0.8, 0));
    ray in = ray_spawn(p, n, vec_make(0.6, -0.8, 0));
    ck_assert(out.origin.y > p.y);
    ck_assert(in.origin.y < p.y);
    /* By SPAWN_REL * 1e3 (+ the negligible floor): well under 1e-9. */
    ck_assert_near(out.origin.y - p.y, SPAWN_REL * 1e3, 1e-3 * SPAWN_REL * 1e3);
    ck_assert(out.tmin == 0.0 && out.tmax == HUGE_VAL);
    ck_assert_vec_near(out.dir, vec_make(0.6, 0.8, 0), 0.0);
    /* At the origin only the absolute floor is left. */
    ray zero = ray_spawn(vec_make(0, 0, 0), n, n);
    ck_assert(zero.origin.y > 0.0 && zero.origin.y < 1e-290);
}
END_TEST

START_TEST(test_ray_spawn_to_stops_short_of_target)
{
    /* From (0,0,0) on the plane y = 0 toward (3,4,0): unit dir (0.6,0.8,0),
     * tmax just below the distance 5. */
    vec3 n = vec_make(0, 1, 0);
    ray r = ray_spawn_to(vec_make(0, 0, 0), n, vec_make(3, 4, 0));
    ck_assert_near(vec_length(r.dir), 1.0, 2 * DBL_EPSILON);
    ck_assert_vec_near(r.dir, vec_make(0.6, 0.8, 0), 1e-15);
    ck_assert(r.tmax < 5.0 && r.tmax > 5.0 * (1 - 2 * SPAWN_SHADOW_SHRINK));
    /* A light exactly on a wall x = 3 (normal -x): the wall does not
     * shadow it. */
    hit h;
    ray s = ray_spawn_to(vec_make(0, 0, 0), n, vec_make(3, 4, 0));
    ck_assert(!isect_plane(vec_make(3, 0, 0), vec_make(-1, 0, 0), &s, &h));
    /* A wall at x = 2.9 does. */
    ck_assert(isect_plane(vec_make(2.9, 0, 0), vec_make(-1, 0, 0), &s, &h));
    /* Target behind the surface: the origin moves to that side. */
    ray b = ray_spawn_to(vec_make(0, 0, 0), n, vec_make(0, -2, 0));
    ck_assert(b.origin.y < 0.0);
}
END_TEST

/* Reflection of d about n. */
static vec3 reflect(vec3 d, vec3 n) { return vec_madd(d, n, -2 * vec_dot(d, n)); }

/* A direction into the surface (against the outward n), bent but not
 * grazing: a stand-in for refraction. */
static vec3 transmit(vec3 n, rng *g)
{
    vec3 t = vec_normalize(vec_madd(vec_neg(n), rng_unit(g), 0.8));
    return vec_dot(t, n) < -0.05 ? t : vec_neg(n);
}

START_TEST(test_ray_spawn_sphere_no_self_hit)
{
    /* For scales 1e-6 .. 1e6: reflected rays leave the sphere for good;
     * transmitted rays hit the far side at the chord length -2 R (n . u),
     * never the near side at t ~ 0. */
    rng g = {41, 0};
    for (int e = -6; e <= 6; e++) {
        double s = pow(10.0, e);
        scene_prim sp = prim_sphere(vec_scale(vec_make(0.3, -0.2, 0.1), s), s);
        for (int i = 0; i < 300; i++) {
            vec3 eye = vec_add(sp.u.sphere.center, vec_scale(rng_unit(&g), 5 * s));
            vec3 aim = vec_add(sp.u.sphere.center, vec_scale(rng_unit(&g), 0.9 * s));
            ray r = make_ray(eye, vec_normalize(vec_sub(aim, eye)));
            hit h;
            ck_assert(isect_prim(&sp, &r, &h));
            ray refl = ray_spawn_hit(&sp, &h, reflect(r.dir, h.normal));
            hit h2;
            ck_assert_msg(!isect_prim(&sp, &refl, &h2), "scale %g: reflected ray re-hit at t=%g",
                          s, (double)h2.t);
            vec3 u = transmit(h.normal, &g);
            ray in = ray_spawn_hit(&sp, &h, u);
            ck_assert(isect_prim(&sp, &in, &h2));
            ck_assert_rel(h2.t, -2 * s * vec_dot(h.normal, u), 1e-9);
            ck_assert_int_eq(h2.entering, 0);
            /* The simple point-based spawn also works here: geometry at the
             * scale of its position. */
            ray in2 = ray_spawn(h.point, h.normal, u);
            ck_assert(isect_prim(&sp, &in2, &h2));
            ck_assert_rel(h2.t, -2 * s * vec_dot(h.normal, u), 1e-9);
        }
    }
}
END_TEST

START_TEST(test_ray_spawn_sheets_no_self_hit)
{
    /* A tilted plane and a triangle at each scale: neither the reflected
     * nor the transmitted ray meets the same sheet again. */
    rng g = {42, 0};
    for (int e = -6; e <= 6; e++) {
        double s = pow(10.0, e);
        vec3 n = vec_normalize(vec_make(0.2, 1, -0.3));
        scene_prim pl = prim_plane(vec_scale(vec_make(0.1, -0.4, 0.2), s), n);
        scene_prim tr = prim_triangle(vec_scale(vec_make(-1, -0.5, -1), s),
                                   vec_scale(vec_make(1.2, 0.1, -0.9), s),
                                   vec_scale(vec_make(0.1, 0.3, 1.3), s));
        const scene_prim *sheets[2] = {&pl, &tr};
        for (int k = 0; k < 2; k++) {
            for (int i = 0; i < 300; i++) {
                vec3 eye = vec_scale(rng_unit(&g), 4 * s);
                vec3 aim = vec_scale(vec_make(rng_uniform(&g) - 0.5, 0, rng_uniform(&g) - 0.5), s);
                ray r = make_ray(eye, vec_normalize(vec_sub(aim, eye)));
                hit h, h2;
                if (!isect_prim(sheets[k], &r, &h))
                    continue;
                ray refl = ray_spawn_hit(sheets[k], &h, reflect(r.dir, h.normal));
                ck_assert_msg(!isect_prim(sheets[k], &refl, &h2), "scale %g kind %d: t=%g", s, k,
                              (double)h2.t);
                ray through = ray_spawn_hit(sheets[k], &h, r.dir);
                ck_assert_msg(!isect_prim(sheets[k], &through, &h2), "scale %g kind %d: t=%g", s,
                              k, (double)h2.t);
            }
        }
    }
}
END_TEST

START_TEST(test_ray_spawn_hit_large_geometry_near_origin)
{
    /* A 2e3-wide floor triangle and a 1e3-radius ground sphere hit near the
     * world origin: the hit point's error is relative to the vertices or
     * the centre (1e3), so ray_spawn_hit must offset by that, not by |p|. */
    scene_prim floor = prim_triangle(vec_make(-1e3, 0, -1e3), vec_make(1e3, 0, -1e3),
                                  vec_make(0.37, 0, 1.3e3));
    floor.u.triangle.p[0].y = 1e-3; /* tilt it so y is not exact */
    scene_prim ground = prim_sphere(vec_make(0.2, -1e3, 0.1), 1e3);
    const scene_prim *prims[2] = {&floor, &ground};
    rng g = {43, 0};
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < 500; i++) {
            vec3 eye = vec_make(rng_uniform(&g) - 0.5, 1 + rng_uniform(&g), 5 + rng_uniform(&g));
            vec3 aim = vec_make(1e-3 * (rng_uniform(&g) - 0.5), 0, 1e-3 * (rng_uniform(&g) - 0.5));
            ray r = make_ray(eye, vec_normalize(vec_sub(aim, eye)));
            hit h, h2;
            ck_assert(isect_prim(prims[k], &r, &h));
            ray refl = ray_spawn_hit(prims[k], &h, reflect(r.dir, h.normal));
            ck_assert_msg(!isect_prim(prims[k], &refl, &h2), "kind %d: t=%g", k, (double)h2.t);
        }
    }
}
END_TEST

START_TEST(test_ray_spawn_ellipsoid_and_box)
{
    /* Transformed primitives: an ellipsoid and a rotated box at scale 1e3. */
    scene_prim e = prim_sphere(vec_make(0, 0, 0), 1);
    xform sc = xform_scale(vec_make(2e3, 1e3, 0.5e3)), mv = xform_translate(vec_make(5e3, 0, 0));
    scene_frame e_frame;
    prim_set_xform(&e, &e_frame, xform_compose(&mv, &sc));
    scene_prim bx = prim_box(vec_make(-1, -2, -3), vec_make(1, 2, 3));
    xform rot = xform_rotate_xyz(vec_make(10, 20, 30)), big = xform_scale(vec_make(1e3, 1e3, 1e3));
    xform rb = xform_compose(&rot, &big);
    scene_frame bx_frame;
    prim_set_xform(&bx, &bx_frame, xform_compose(&mv, &rb));
    const scene_prim *prims[2] = {&e, &bx};
    rng g = {44, 0};
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < 500; i++) {
            vec3 eye = vec_add(vec_make(5e3, 0, 0), vec_scale(rng_unit(&g), 2e4));
            vec3 aim = vec_add(vec_make(5e3, 0, 0), vec_scale(rng_unit(&g), 400));
            ray r = make_ray(eye, vec_normalize(vec_sub(aim, eye)));
            hit h, h2;
            ck_assert(isect_prim(prims[k], &r, &h));
            ck_assert_int_eq(h.entering, 1);
            ray refl = ray_spawn_hit(prims[k], &h, reflect(r.dir, h.normal));
            ck_assert_msg(!isect_prim(prims[k], &refl, &h2), "kind %d: t=%g", k, (double)h2.t);
            ray in = ray_spawn_hit(prims[k], &h, transmit(h.normal, &g));
            ck_assert(isect_prim(prims[k], &in, &h2));
            ck_assert_int_eq(h2.entering, 0);
            /* It leaves through another part of the surface: the ellipsoid
             * is far thicker than 1 at any inward angle used, and a box ray
             * cannot leave through the face it came in by. */
            if (k == 0)
                ck_assert_msg(h2.t > 1.0, "inner ray stopped at t=%g", (double)h2.t);
            else
                ck_assert(vec_dot(h2.normal, h.normal) < 0.999);
        }
    }
}
END_TEST

/* Shadow rays start at tmin = the offset (a surface within it, such as the
 * other side of a concave edge, does not shadow); mirror rays at 0.  A ray
 * spawned into an axis-aligned box from a hit next to its edge starts
 * strictly inside on every axis (by the offset). */
START_TEST(test_ray_spawn_hit_shadow_and_box_edges)
{
    scene_prim bx = prim_box(vec_make(-1, -1, -1), vec_make(1, 1, 1));
    hit h;
    /* From inside, straight at the edge x = -1, y = 1: the slab tie goes to
     * x (the lower axis), so the hit is on the face x = -1 with y = 1. */
    ray r = make_ray(vec_make(0, 0, 0.25), vec_normalize(vec_make(-1, 1, 0)));
    ck_assert(isect_prim(&bx, &r, &h));
    ck_assert(h.point.x == -1 && h.point.y == 1);
    vec3 m = reflect(r.dir, h.normal);
    ray mr = ray_spawn_hit(&bx, &h, m), sr = ray_spawn_hit_shadow(&bx, &h, m);
    real off = SPAWN_REL * 1 + SPAWN_ABS;   /* magnitude 1 */
    ck_assert(mr.tmin == 0.0);
    ck_assert_near(sr.tmin, off, 1e-3 * off);
    /* Inside by the offset on x (the hit face) and on y (the edge). */
    ck_assert_near(mr.origin.x, -1 + off, 4 * DBL_EPSILON);
    ck_assert_near(mr.origin.y, 1 - off, 4 * DBL_EPSILON);
    /* So the mirror ray, heading out through y = 1, still meets it. */
    hit h2;
    ck_assert(isect_prim(&bx, &mr, &h2));
    ck_assert(h2.normal.y == 1);
}
END_TEST

START_TEST(test_isect_prim_magnitude)
{
    scene_prim s = prim_sphere(vec_make(1, -7, 3), 2);
    ck_assert_near(isect_prim_magnitude(&s), 9.0, 0.0);
    scene_prim t = prim_triangle(vec_make(0, 0, 0), vec_make(-40, 1, 0), vec_make(3, 3, 3));
    ck_assert_near(isect_prim_magnitude(&t), 40.0, 0.0);
    /* Scaled by 10 and moved by (0,0,-100): |L|inf 10, so 10 * 9 + 100. */
    xform sc = xform_scale(vec_make(10, 10, 10)), mv = xform_translate(vec_make(0, 0, -100));
    scene_frame s_frame;
    prim_set_xform(&s, &s_frame, xform_compose(&mv, &sc));
    ck_assert_near(isect_prim_magnitude(&s), 190.0, 0.0);
}
END_TEST

/* A random plane through [-2, 2]^3 and a ray from there, tmin 0 or a
 * little above (the plane tests' random cases). */
static void random_plane_ray(rng *g, scene_prim *p, ray *r)
{
    *p = prim_plane(vec_make(4 * rng_uniform(g) - 2, 4 * rng_uniform(g) - 2, 4 * rng_uniform(g) - 2), rng_unit(g));
    *r = make_ray(vec_make(4 * rng_uniform(g) - 2, 4 * rng_uniform(g) - 2, 4 * rng_uniform(g) - 2), rng_unit(g));
    r->tmin = rng_uniform(g) < 0.5 ? 0 : 1e-3 * rng_uniform(g);
}

/* The count of a plane's crossings (isect_part_crossings: the shadow
 * walk's, which goes to plane_t at once for a plane in the world frame)
 * is the number of full hits (isect_prim_all: through plane_point): by
 * hand on y = 0 from (0, 1, 0) straight down (t = 1, open at both ends of
 * (tmin, tmax)), then for 2000 random planes and rays, each also with its
 * interval closed onto the hit's t from either side. */
START_TEST(test_isect_plane_crossings_match_full_hits)
{
    hit out[ISECT_MAX_CROSSINGS];
    scene_prim p = prim_plane(vec_make(0, 0, 0), vec_make(0, 1, 0));
    ray r = make_ray(vec_make(0, 1, 0), vec_make(0, -1, 0));
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 1);
    r.tmax = 1;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r.tmax = nextafter(1.0, 2.0);
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 1);
    r.tmin = 1;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r = make_ray(vec_make(0, 1, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    /* Moving away from the plane: the crossing is behind the origin, at
     * t = -1 from y = 1 going up, and t = -0 from the plane itself going
     * down: no crossing for tmin = 0, one where tmin < 0 lets t in. */
    r = make_ray(vec_make(0, 1, 0), vec_make(0, 1, 0));
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r.tmin = -2;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 1);
    r.tmin = -0.5;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r = make_ray(vec_make(0, 0, 0), vec_make(0, -1, 0));
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r.tmin = -1;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 1);
    /* From the plane upward: t = +0, no crossing for tmin = 0 either. */
    r = make_ray(vec_make(0, 0, 0), vec_make(0, 1, 0));
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r.tmin = -1;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 1);
    /* Moved up to y = 5 by its transform: above the ray going down from
     * y = 1, met by the one going up at t = 4. */
    scene_frame p_frame;
    prim_set_xform(&p, &p_frame, xform_translate(vec_make(0, 5, 0)));
    r = make_ray(vec_make(0, 1, 0), vec_make(0, -1, 0));
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r = make_ray(vec_make(0, 1, 0), vec_make(0, 1, 0));
    r.tmax = 4;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 0);
    r.tmax = 4.5;
    ck_assert_int_eq(isect_part_crossings(&p, 0, &r), 1);
    rng g = {77, 0};
    for (int i = 0; i < 2000; i++) {
        random_plane_ray(&g, &p, &r);
        int full = isect_prim_all(&p, &r, out);
        ck_assert_int_eq(isect_part_crossings(&p, 0, &r), full);
        if (!full)
            continue;
        /* In real: the long double build's t rounded to double may fall
         * either side of the hit. */
        real t = out[0].t;
        real ends[4][2] = {{r.tmin, t}, {r.tmin, nextafter(t, (real)HUGE_VAL)}, {t, HUGE_VAL},
                           {nextafter(t, -(real)HUGE_VAL), HUGE_VAL}};
        for (int k = 0; k < 4; k++) {
            r.tmin = ends[k][0];
            r.tmax = ends[k][1];
            int n = isect_prim_all(&p, &r, out);
            ck_assert_int_eq(n, k % 2);
            ck_assert_int_eq(isect_part_crossings(&p, 0, &r), n);
        }
    }
}
END_TEST


/* isect_plane_nearest (the nearest walk's deferred plane: its t alone) is
 * isect_part's test: by hand on y = 0 from (0, 1, 0) straight down, t = 1,
 * refused with the interval closed onto it; a ray moving away, from tmin 0
 * (no hit) and from tmin -2 (t = -1); then for 2000 random planes
 * and rays the same answer and the same t, to the bit, as isect_part's
 * full hit on a copy of the ray, also with tmax at that t (no hit) and
 * just past it (the hit). */
START_TEST(test_isect_plane_nearest_is_isect_part)
{
    scene_prim p = prim_plane(vec_make(0, 0, 0), vec_make(0, 1, 0));
    ray r = make_ray(vec_make(0, 1, 0), vec_make(0, -1, 0));
    real t = -1;
    ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), 1);
    ck_assert(t == 1);
    r.tmax = 1;
    ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), 0);
    r = make_ray(vec_make(0, 1, 0), vec_make(1, 0, 0));
    ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), 0);
    /* Moving away (its quick miss), and the same ray from tmin -2, which
     * meets the plane behind its origin, at t = -1. */
    r = make_ray(vec_make(0, 1, 0), vec_make(0, 1, 0));
    ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), 0);
    r.tmin = -2;
    ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), 1);
    ck_assert(t == -1);
    /* A tmin in (-1, 0) too (attack 25g, mutant away_tmin_gt_m1: the quick
     * miss taken for tmin > -1): from y = 0.25 away from the plane with
     * tmin -0.5, the plane at t = -0.25, inside (tmin, tmax). */
    r = make_ray(vec_make(0, 0.25, 0), vec_make(0, 1, 0));
    r.tmin = -0.5;
    ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), 1);
    ck_assert(t == -0.25);
    rng g = {78, 0};
    int met = 0;
    for (int i = 0; i < 2000; i++) {
        random_plane_ray(&g, &p, &r);
        ray full = r;
        hit h;
        int want = isect_part(&p, 0, &full, &h);
        ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), want);
        if (!want)
            continue;
        met++;
        ck_assert(memcmp(&t, &h.t, sizeof t) == 0);
        real ends[2] = {h.t, nextafter(h.t, (real)HUGE_VAL)};
        for (int k = 0; k < 2; k++) {
            r.tmax = ends[k];
            full = r;
            want = isect_part(&p, 0, &full, &h);
            ck_assert_int_eq(want, k);
            ck_assert_int_eq(isect_plane_nearest(p.u.plane.point, p.u.plane.normal, &r, &t), want);
            ck_assert(!want || memcmp(&t, &h.t, sizeof t) == 0);
        }
    }
    ck_assert_msg(met > 500, "only %d rays met their plane", met);
}
END_TEST
Suite *suite_intersect(void)
{
    Suite *s = suite_create("intersect");
    TCase *sphere = tcase_create("sphere");
    tcase_add_test(sphere, test_isect_sphere_hit_by_hand);
    tcase_add_test(sphere, test_isect_sphere_non_unit_direction);
    tcase_add_test(sphere, test_isect_sphere_miss_leaves_ray_and_hit);
    tcase_add_test(sphere, test_isect_sphere_tangent_is_one_hit);
    tcase_add_test(sphere, test_isect_sphere_tiny_radius_miss);
    tcase_add_test(sphere, test_isect_sphere_from_inside_hits_far_side);
    tcase_add_test(sphere, test_isect_sphere_ray_starting_on_surface);
    tcase_add_test(sphere, test_isect_sphere_respects_tmin_tmax);
    tcase_add_test(sphere, test_isect_sphere_small_sphere_far_away);
    tcase_add_test(sphere, test_isect_sphere_huge_sphere_close_up);
    tcase_add_test(sphere, test_isect_sphere_moving_away_matches_the_roots);
    tcase_add_test(sphere, test_isect_sphere_count_matches_the_refined_roots);
    tcase_add_test(sphere, test_isect_sphere_count_far_from_unit_directions);
    suite_add_tcase(s, sphere);
    TCase *sheet = tcase_create("plane_disk");
    tcase_add_test(sheet, test_isect_plane_hit_by_hand);
    tcase_add_test(sheet, test_isect_plane_crossings_match_full_hits);
    tcase_add_test(sheet, test_isect_plane_nearest_is_isect_part);
    tcase_add_test(sheet, test_isect_plane_parallel_and_behind_miss);
    tcase_add_test(sheet, test_isect_plane_point_on_plane_from_far);
    tcase_add_test(sheet, test_isect_disk_radius_inclusive);
    tcase_add_test(sheet, test_isect_disk_tilted);
    suite_add_tcase(s, sheet);
    TCase *tri = tcase_create("triangle");
    tcase_add_test(tri, test_isect_triangle_hit_by_hand);
    tcase_add_test(tri, test_isect_triangle_oblique);
    tcase_add_test(tri, test_isect_triangle_shading_normal_interpolated);
    tcase_add_test(tri, test_isect_triangle_watertight_shared_edge);
    tcase_add_test(tri, test_isect_triangle_watertight_fan_vertex);
    tcase_add_test(tri, test_isect_triangle_watertight_sweep);
    suite_add_tcase(s, tri);
    TCase *box = tcase_create("box");
    tcase_add_test(box, test_isect_box_hit_by_hand);
    tcase_add_test(box, test_isect_box_from_inside_and_on_surface);
    tcase_add_test(box, test_isect_box_axis_parallel_on_slab_plane);
    tcase_add_test(box, test_isect_box_edge_touch_is_one_hit);
    tcase_add_test(box, test_isect_box_tmin_tmax);
    tcase_add_test(box, test_isect_hot_box_crossings_match_the_box);
    suite_add_tcase(s, box);
    TCase *xf = tcase_create("transformed");
    tcase_add_test(xf, test_isect_prim_ellipsoid);
    tcase_add_test(xf, test_isect_prim_rotated_box);
    tcase_add_test(xf, test_isect_prim_translated_scaled_disk);
    tcase_add_test(xf, test_isect_prim_bounds);
    tcase_add_test(xf, test_isect_prim_magnitude);
    suite_add_tcase(s, xf);
    TCase *spawn = tcase_create("spawn");
    tcase_add_test(spawn, test_ray_spawn_offsets_to_the_side_of_dir);
    tcase_add_test(spawn, test_ray_spawn_to_stops_short_of_target);
    tcase_add_test(spawn, test_ray_spawn_sphere_no_self_hit);
    tcase_add_test(spawn, test_ray_spawn_sheets_no_self_hit);
    tcase_add_test(spawn, test_ray_spawn_hit_large_geometry_near_origin);
    tcase_add_test(spawn, test_ray_spawn_ellipsoid_and_box);
    tcase_add_test(spawn, test_ray_spawn_hit_shadow_and_box_edges);
    suite_add_tcase(s, spawn);
    return s;
}
