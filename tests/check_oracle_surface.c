/*
 * check_oracle_surface.c - oracle_surface.h: the distance from a point to
 * each kind of primitive's surface ([ORACLE-VIEW-ROUNDING-3], spec/verify.md),
 * checked against another route: points laid on the surface from its own
 * parametrisation (angles, heights, barycentric weights, mapped through the
 * frame for a kept frame), the nearest of a grid refined around its best
 * cell.  Every such point lies on the surface, so their nearest is at least
 * the true distance: the answer must never exceed it (a lower bound), and
 * for the kinds measured exactly must come within the sampling's reach of
 * it.  A few values are worked by hand.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "testlib.h"
#include "oracle/oracle_surface.h"

/* A point of the surface at (u, v) in [0, 1]^2, in the shape's own frame. */
typedef vec3 (*surface_fn)(const scene_prim *p, int part, double u, double v);

/* An orthonormal pair across the unit axis a. */
static void across(vec3 a, vec3 *e1, vec3 *e2)
{
    vec3 t = fabs(a.x) < 0.6 ? vec_make(1, 0, 0) : vec_make(0, 1, 0);
    *e1 = vec_normalize(vec_cross(a, t));
    *e2 = vec_cross(a, *e1);
}

/* The point at angle 2 pi w, radius rho, height h about the axis from o along the unit a. */
static vec3 around(vec3 o, vec3 a, double h, double rho, double w)
{
    vec3 e1, e2;
    across(a, &e1, &e2);
    double phi = 2 * REAL_PI * w;
    return vec_add(vec_add(o, vec_scale(a, h)), vec_add(vec_scale(e1, rho * cos(phi)), vec_scale(e2, rho * sin(phi))));
}

static vec3 sphere_at(const scene_prim *p, int part, double u, double v)
{
    (void)part;
    double th = REAL_PI * u, ph = 2 * REAL_PI * v, r = p->u.sphere.radius;
    return vec_add(p->u.sphere.center, vec_make(r * sin(th) * cos(ph), r * sin(th) * sin(ph), r * cos(th)));
}

static vec3 disk_at(const scene_prim *p, int part, double u, double v)
{
    (void)part;
    return around(p->u.disk.center, vec_normalize(p->u.disk.normal), 0, p->u.disk.radius * u, v);
}

/* Barycentric (u, v u') folded into the triangle. */
static vec3 corner_mix(vec3 a, vec3 b, vec3 c, double u, double v)
{
    double s = u, t = v * (1 - u);
    return vec_add(a, vec_add(vec_scale(vec_sub(b, a), s), vec_scale(vec_sub(c, a), t)));
}

static vec3 triangle_at(const scene_prim *p, int part, double u, double v)
{
    (void)part;
    return corner_mix(p->u.triangle.p[0], p->u.triangle.p[1], p->u.triangle.p[2], u, v);
}

static vec3 box_at(const scene_prim *p, int part, double u, double v)
{
    vec3 lo = p->u.box.lo, hi = p->u.box.hi, d = vec_sub(hi, lo);
    int axis = part / 2;
    double w[3];
    w[axis] = part % 2;
    w[(axis + 1) % 3] = u;
    w[(axis + 2) % 3] = v;
    return vec_make(lo.x + w[0] * d.x, lo.y + w[1] * d.y, lo.z + w[2] * d.z);
}

/* part 0: the side; 1 and 2: the caps at from and to. */
static vec3 tube_at(vec3 from, vec3 to, double r0, double r1, int part, double u, double v)
{
    vec3 axis = vec_sub(to, from);
    double h = vec_length(axis);
    vec3 a = vec_scale(axis, 1 / h);
    if (part == 0)
        return around(from, a, h * u, r0 + (r1 - r0) * u, v);
    return around(from, a, part == 1 ? 0 : h, (part == 1 ? r0 : r1) * u, v);
}

static vec3 cylinder_at(const scene_prim *p, int part, double u, double v)
{
    return tube_at(p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.radius, part, u, v);
}

static vec3 cone_at(const scene_prim *p, int part, double u, double v)
{
    return tube_at(p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1], part, u, v);
}

static vec3 torus_at(const scene_prim *p, int part, double u, double v)
{
    (void)part;
    vec3 a = p->u.torus.axis, e1, e2;
    across(a, &e1, &e2);
    double phi = 2 * REAL_PI * u, psi = 2 * REAL_PI * v;
    vec3 ring = vec_add(vec_scale(e1, cos(phi)), vec_scale(e2, sin(phi)));
    double rho = p->u.torus.major + p->u.torus.minor * cos(psi);
    return vec_add(p->u.torus.center, vec_add(vec_scale(ring, rho), vec_scale(a, p->u.torus.minor * sin(psi))));
}

static vec3 mesh_at(const scene_prim *p, int part, double u, double v)
{
    const int *t = p->u.mesh.tri[part];
    const vec3 *x = p->u.mesh.positions;
    return corner_mix(x[t[0]], x[t[1]], x[t[2]], u, v);
}

static int parts_of(const scene_prim *p)
{
    switch (p->kind) {
    case PRIM_BOX:
        return 6;
    case PRIM_CYLINDER:
        return p->u.cylinder.open ? 1 : 3;
    case PRIM_CONE:
        return p->u.cone.open ? 1 : 3;
    case PRIM_MESH:
        return p->u.mesh.tri_count;
    default:
        return 1;
    }
}

static surface_fn surface_of(const scene_prim *p)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        return sphere_at;
    case PRIM_DISK:
        return disk_at;
    case PRIM_TRIANGLE:
        return triangle_at;
    case PRIM_BOX:
        return box_at;
    case PRIM_CYLINDER:
        return cylinder_at;
    case PRIM_CONE:
        return cone_at;
    case PRIM_TORUS:
        return torus_at;
    default:
        return mesh_at;
    }
}

/* Whether u (0) or v (1) goes round the shape: its samples wrap past 0
 * and 1 (a nearest point just across the seam is reached from either
 * side); the others stop at the edges. */
static int wraps(const scene_prim *p, int which)
{
    switch (p->kind) {
    case PRIM_TORUS:
        return 1;
    case PRIM_SPHERE:
    case PRIM_DISK:
    case PRIM_CYLINDER:
    case PRIM_CONE:
        return which == 1;
    default:
        return 0;
    }
}

static double keep_in(const scene_prim *p, int which, double w)
{
    return wraps(p, which) ? w - floor(w) : fmin(1, fmax(0, w));
}

static double sample_distance(const scene_prim *p, int part, double u, double v, vec3 q)
{
    vec3 x = surface_of(p)(p, part, u, v);
    if (p->frame)
        x = xform_point(&p->frame->to_world, x);
    return vec_length(vec_sub(x, q));
}

/* The nearest of a 48 x 48 grid on each part, then 8 rounds of a 9 x 9
 * grid a quarter as wide around the best so far: at least the true
 * distance, and within a small part of the shape's size of it. */
static double sampled_distance(const scene_prim *p, vec3 q)
{
    double best = HUGE_VAL;
    for (int part = 0; part < parts_of(p); part++) {
        double bu = 0, bv = 0, part_best = HUGE_VAL, step = 1.0 / 47;
        for (int i = 0; i < 48; i++)
            for (int j = 0; j < 48; j++) {
                double d = sample_distance(p, part, i * step, j * step, q);
                if (d < part_best) {
                    part_best = d;
                    bu = i * step;
                    bv = j * step;
                }
            }
        for (int round = 0; round < 8; round++) {
            double cu = bu, cv = bv;
            for (int i = -4; i <= 4; i++)
                for (int j = -4; j <= 4; j++) {
                    double u = keep_in(p, 0, cu + i * step / 4), v = keep_in(p, 1, cv + j * step / 4);
                    double d = sample_distance(p, part, u, v, q);
                    if (d < part_best) {
                        part_best = d;
                        bu = u;
                        bv = v;
                    }
                }
            step /= 4;
        }
        best = fmin(best, part_best);
    }
    return best;
}

/* The shapes checked, each of size about 1 to 3 about the origin; what a
 * shape keeps out of line is kept in the caller's store. */
enum { SHAPES = 13 };

typedef struct shape_store {
    scene_frame frame;
    vec3 corners[4];
    int tri[4][3];
} shape_store;

static scene_prim shape(int i, shape_store *st)
{
    static const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.mesh = -1;
    switch (i) {
    case 0:
        p.kind = PRIM_SPHERE;
        p.u.sphere.center = vec_make(0.3, -0.2, 0.1);
        p.u.sphere.radius = 1.1;
        break;
    case 1:
        p.kind = PRIM_DISK;
        p.u.disk.center = vec_make(0.1, 0.2, -0.3);
        p.u.disk.normal = vec_make(1, 2, 2);
        p.u.disk.radius = 1.3;
        break;
    case 2:
        p.kind = PRIM_TRIANGLE;
        p.u.triangle.p[0] = vec_make(-1, -0.5, 0.2);
        p.u.triangle.p[1] = vec_make(1.2, -0.7, -0.1);
        p.u.triangle.p[2] = vec_make(0.1, 1.1, 0.4);
        break;
    case 3:
        p.kind = PRIM_BOX;
        p.u.box.lo = vec_make(-1, -0.6, -0.8);
        p.u.box.hi = vec_make(0.9, 0.7, 1.2);
        break;
    case 4:
    case 5:
        p.kind = PRIM_CYLINDER;
        p.u.cylinder.from = vec_make(-0.5, -1, 0.2);
        p.u.cylinder.to = vec_make(0.7, 1.1, -0.3);
        p.u.cylinder.radius = 0.6;
        p.u.cylinder.open = i == 5;
        break;
    case 6:
    case 7:
        p.kind = PRIM_CONE;
        p.u.cone.from = vec_make(0.2, -1.2, -0.1);
        p.u.cone.to = vec_make(-0.3, 0.9, 0.4);
        p.u.cone.radius[0] = 0.9;
        p.u.cone.radius[1] = i == 6 ? 0.3 : 0;
        p.u.cone.open = i == 7;
        break;
    case 8:
        p.kind = PRIM_TORUS;
        p.u.torus.center = vec_make(0.1, -0.1, 0.2);
        p.u.torus.axis = vec_normalize(vec_make(0.3, 1, -0.2));
        p.u.torus.major = 1.2;
        p.u.torus.minor = 0.35;
        break;
    case 9:
        st->corners[0] = vec_make(-1, -0.8, -0.7);
        st->corners[1] = vec_make(1.1, -0.6, -0.5);
        st->corners[2] = vec_make(0, 1.2, -0.4);
        st->corners[3] = vec_make(0.1, 0, 1.3);
        memcpy(st->tri, faces, sizeof faces);
        p.kind = PRIM_MESH;
        p.u.mesh.positions = st->corners;
        p.u.mesh.position_count = 4;
        p.u.mesh.tri = st->tri;
        p.u.mesh.tri_count = 4;
        p.u.mesh.closed = 1;
        break;
    default: { /* kept frames: an ellipsoid, a turned box, a squashed cylinder */
        xform scale = xform_scale(i == 10 ? vec_make(2, 0.7, 1) : i == 11 ? vec_make(1, 1, 1) : vec_make(1.5, 1, 0.8));
        xform turn = xform_rotate_xyz(vec_make(30, -20, 45)), lin = xform_compose(&turn, &scale);
        xform move = xform_translate(vec_make(0.2, -0.1, 0.3));
        st->frame.to_world = xform_compose(&move, &lin);
        ck_assert(xform_invert(&st->frame.to_world, &st->frame.to_local));
        p = shape(i == 10 ? 0 : i == 11 ? 3 : 4, st);
        p.frame = &st->frame;
        break;
    }
    }
    return p;
}

static vec3 random_point(uint64_t k, double reach)
{
    double c[3];
    for (int i = 0; i < 3; i++)
        c[i] = reach * (2 * ((test_mix(k * 3 + (uint64_t)i) >> 11) * 0x1p-53) - 1);
    return vec_make(c[0], c[1], c[2]);
}

/* Each kind without a frame is measured exactly: the answer is no larger
 * than the nearest surface point found, and within 1e-6 of it, for points
 * inside, near and outside the shape. */
START_TEST(test_surface_distance_agrees_with_sampling)
{
    for (int i = 0; i < 10; i++) {
        shape_store st;
        scene_prim p = shape(i, &st);
        for (uint64_t k = 0; k < 40; k++) {
            vec3 q = random_point(1000 * (uint64_t)i + k, k < 20 ? 1.5 : 4);
            double got = oracle_surface_distance(&p, q), want = sampled_distance(&p, q);
            ck_assert_msg(got <= want + 1e-12 && got >= want - 1e-6, "shape %d, point %llu: %.17g, sampled %.17g", i,
                          (unsigned long long)k, got, want);
        }
    }
}
END_TEST

/* A kept frame gives a lower bound: never above the sampled distance, and
 * (the frame's stretch bounded by Gershgorin's rows) at least the sampled
 * distance over the frame's condition, 2 / 0.7 for the ellipsoid; a turn
 * alone loses nothing. */
START_TEST(test_surface_distance_bounds_a_kept_frame)
{
    static const double condition[] = {2 / 0.7, 1, 1.5 / 0.8};
    for (int i = 10; i < SHAPES; i++) {
        shape_store st;
        scene_prim p = shape(i, &st);
        for (uint64_t k = 0; k < 40; k++) {
            vec3 q = random_point(1000 * (uint64_t)i + k, k < 20 ? 2 : 5);
            double got = oracle_surface_distance(&p, q), want = sampled_distance(&p, q);
            double least = want / condition[i - 10] - 1e-6;
            if (i == 11)
                least = want - 1e-6;
            ck_assert_msg(got <= want + 1e-12 && got >= least, "shape %d, point %llu: %.17g, sampled %.17g", i,
                          (unsigned long long)k, got, want);
        }
    }
}
END_TEST

/* p and what it keeps moved by shift. */
static void move(scene_prim *p, shape_store *st, vec3 shift)
{
    if (p->frame) {
        st->frame.to_world.m[0][3] += shift.x;
        st->frame.to_world.m[1][3] += shift.y;
        st->frame.to_world.m[2][3] += shift.z;
        ck_assert(xform_invert(&st->frame.to_world, &st->frame.to_local));
        return;
    }
    vec3 *at[4];
    int n = 0;
    switch (p->kind) {
    case PRIM_SPHERE:
        at[n++] = &p->u.sphere.center;
        break;
    case PRIM_DISK:
        at[n++] = &p->u.disk.center;
        break;
    case PRIM_TRIANGLE:
        for (int k = 0; k < 3; k++)
            at[n++] = &p->u.triangle.p[k];
        break;
    case PRIM_BOX:
        at[n++] = &p->u.box.lo;
        at[n++] = &p->u.box.hi;
        break;
    case PRIM_CYLINDER:
        at[n++] = &p->u.cylinder.from;
        at[n++] = &p->u.cylinder.to;
        break;
    case PRIM_CONE:
        at[n++] = &p->u.cone.from;
        at[n++] = &p->u.cone.to;
        break;
    case PRIM_TORUS:
        at[n++] = &p->u.torus.center;
        break;
    default:
        for (int k = 0; k < 4; k++)
            at[n++] = &st->corners[k];
        break;
    }
    for (int k = 0; k < n; k++)
        *at[k] = vec_add(*at[k], shift);
}

/* The property the tolerance rests on, for every shape above from 300
 * points drawn at random about it, a third of them with the shape moved by
 * [1e5, -3e4, 1e5] (where the samples' own rounding, allowed for, is
 * 1e-11): never above any surface point's distance.  A point inside the box but near the surface is where the box's
 * own distance broke it (spec/verify.md [ORACLE-VIEW-ROUNDING-3]). */
START_TEST(test_surface_distance_is_a_lower_bound)
{
    for (uint64_t k = 0; k < 300; k++) {
        shape_store st;
        int i = (int)(test_mix(k) % SHAPES);
        scene_prim p = shape(i, &st);
        vec3 shift = k % 3 == 0 ? vec_make(1e5, -3e4, 1e5) : vec_splat(0);
        move(&p, &st, shift);
        vec3 q = vec_add(shift, random_point(k + 77, 1.8));
        double got = oracle_surface_distance(&p, q), want = sampled_distance(&p, q);
        double allowed = want + 8 * DBL_EPSILON * vec_max_abs(q);
        ck_assert_msg(got <= allowed, "shape %d, point %llu: %.17g above the sampled %.17g", i, (unsigned long long)k,
                      got, want);
    }
}
END_TEST

/* By hand.  The answers are lessened by the bound of their rounding,
 * 256 u (|q| + C): 5.7e-10 at 1e4. */
START_TEST(test_surface_distance_by_hand)
{
    shape_store st;
    scene_prim p = shape(0, &st);
    p.u.sphere.center = vec_make(1e4, 0, 1e4);
    p.u.sphere.radius = 1;
    /* Inside the unit sphere's box, 0.6 from each face, just outside the
     * sphere: sqrt(3 0.4^2 + ...) = sqrt(1.08) - 1 = 0.03923; the box's
     * nearest face is 0.4 away. */
    ck_assert_near(oracle_surface_distance(&p, vec_make(1e4 + 0.6, 0.6, 1e4 + 0.6)), sqrt(1.08) - 1, 1e-9);
    /* Just inside: 1 - sqrt(0.75) = 0.1340. */
    ck_assert_near(oracle_surface_distance(&p, vec_make(1e4 + 0.5, 0.5, 1e4 + 0.5)), 1 - sqrt(0.75), 1e-9);
    /* On the surface: 0 (held at 0 by the rounding margin). */
    ck_assert(oracle_surface_distance(&p, vec_make(1e4 + 1, 0, 1e4)) == 0);
    /* The plane y = 2 (its normal unnormalised): 3 from y = 5. */
    p.kind = PRIM_PLANE;
    p.u.plane.point = vec_make(0, 2, 0);
    p.u.plane.normal = vec_make(0, 4, 0);
    ck_assert_near(oracle_surface_distance(&p, vec_make(7, 5, -3)), 3, 1e-12);
    /* A torus seen from its centre's axis, 2 above the centre: the tube's
     * circle is sqrt(R^2 + 4) away, so sqrt(1.44 + 4) - 0.35. */
    p = shape(8, &st);
    ck_assert_near(oracle_surface_distance(&p, vec_add(p.u.torus.center, vec_scale(p.u.torus.axis, 2))),
                   sqrt(1.44 + 4) - 0.35, 1e-12);
    /* A closed cylinder along z from 0 to 4, radius 1: from (0.5, 0, 3.8)
     * the cap is 0.2 away, the side 0.5; the open one has the side only. */
    p = shape(4, &st);
    p.u.cylinder.from = vec_make(0, 0, 0);
    p.u.cylinder.to = vec_make(0, 0, 4);
    p.u.cylinder.radius = 1;
    ck_assert_near(oracle_surface_distance(&p, vec_make(0.5, 0, 3.8)), 0.2, 1e-12);
    p.u.cylinder.open = 1;
    ck_assert_near(oracle_surface_distance(&p, vec_make(0.5, 0, 3.8)), 0.5, 1e-12);
    /* Past the open end, along the axis: to the rim, sqrt(1 + 1). */
    ck_assert_near(oracle_surface_distance(&p, vec_make(0, 0, 5)), sqrt(2), 1e-12);
    /* A box from inside: its nearest face. */
    p = shape(3, &st);
    ck_assert_near(oracle_surface_distance(&p, vec_make(0.8, 0, 0)), 0.1, 1e-12);
    /* A triangle in z = 0 seen from above its inside and past an edge; a
     * sliver (three points on a line) is its longest edge. */
    vec3 a = vec_make(0, 0, 0), b = vec_make(2, 0, 0), c = vec_make(0, 2, 0);
    ck_assert_near(oracle_triangle_distance(vec_make(0.5, 0.5, 3), a, b, c), 3, 1e-12);
    ck_assert_near(oracle_triangle_distance(vec_make(2, 2, 1), a, b, c), sqrt(2 + 1), 1e-12);
    ck_assert_near(oracle_triangle_distance(vec_make(1, 1, 0), a, b, vec_make(4, 0, 0)), 1, 1e-12);
    /* An empty mesh has nothing to meet. */
    p = shape(9, &st);
    p.u.mesh.position_count = p.u.mesh.tri_count = 0;
    ck_assert(oracle_surface_distance(&p, vec_make(0, 0, 0)) == HUGE_VAL);
}
END_TEST

Suite *suite_oracle_surface(void)
{
    Suite *s = suite_create("oracle_surface");
    TCase *tc = tcase_create("distance");
    tcase_add_test(tc, test_surface_distance_agrees_with_sampling);
    tcase_add_test(tc, test_surface_distance_bounds_a_kept_frame);
    tcase_add_test(tc, test_surface_distance_is_a_lower_bound);
    tcase_add_test(tc, test_surface_distance_by_hand);
    suite_add_tcase(s, tc);
    return s;
}
