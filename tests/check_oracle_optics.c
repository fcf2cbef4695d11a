/*
 * Tests of the mirror and refraction families of the analytic oracle
 * (src/oracle/{parallel_mirrors, glass_slab, snell_window, ball_lens}.c and
 * optics_util.c; spec/analytic.md, one section per family):
 *   1. the helpers against numbers worked out by hand in the comments
 *      (3-4-5 triangles, angles of 30 and 60 degrees) and against a second
 *      route (plain summation, step-by-step reflection, a 2-D vector trace
 *      of the ball lens with Snell's law in vector form);
 *   2. each family's radiance at chosen pixels of small inline scenes, by
 *      hand, and the depth cuts and ambiguous margins;
 *   3. every scene of these families rendered by the tracer and compared
 *      with its exact image at 1e-9 relative, with a bound on the pixels
 *      excluded (ORACLE_REPORT=1 prints the measured errors), and scenes
 *      where the tracer's self-intersection offsets matter: the sensitive
 *      pixels are excluded and the rest still pass;
 *   4. scenes outside a family's assumptions are refused with the reason.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "oracle_testlib.h"
#include "image/metrics.h"
#include "oracle/oracle.h"
#include "oracle/optics_util.h"
#include "render/render.h"
#include "scene/scene.h"

/* The exact value at image point (x, y), which must not be ambiguous. */
static rgb exact_at(const scene_model *s, double x, double y)
{
    rgb c = vec_splat(-1);
    ck_assert_msg(radiance_at(s, x, y, &c) == ORACLE_EXACT, "ambiguous at (%g, %g)", x, y);
    return c;
}

#define ck_assert_rgb_rel(got, want, rel)                                                    \
    do {                                                                                     \
        rgb ck_g3_ = (got), ck_w3_ = (want);                                                 \
        ck_assert_rel(ck_g3_.x, ck_w3_.x, rel);                                              \
        ck_assert_rel(ck_g3_.y, ck_w3_.y, rel);                                              \
        ck_assert_rel(ck_g3_.z, ck_w3_.z, rel);                                              \
    } while (0)

/* ---- 1. helpers ---- */

START_TEST(test_optics_geometric_sum)
{
    /* [ORACLE-MIRRORS-4] 1 + 1/2 + 1/4 + 1/8 = 1.875; q = 1: m terms of 1; q = 0: only q^0;
     * (1 - 0.3^6)/0.7 = 0.999271/0.7. */
    ck_assert_rel(optics_geometric_sum(0.5, 4), 1.875, 1e-15);
    ck_assert_double_eq(optics_geometric_sum(1, 7), 7);
    ck_assert_double_eq(optics_geometric_sum(0, 3), 1);
    ck_assert_double_eq(optics_geometric_sum(0.7, 0), 0);
    ck_assert_rel(optics_geometric_sum(0.3, 6), 0.999271 / 0.7, 1e-15);
    /* q > 1 (Ks + t may reach 2): 1 + 1.5 + 2.25 = 4.75. */
    ck_assert_rel(optics_geometric_sum(1.5, 3), 4.75, 1e-15);
    /* Near q = 1 the textbook form loses digits; a plain sum does not:
     * add the 1000 powers one by one (rounding about 1e-13 relative). */
    double q = 1 - 1e-12, sum = 0, power = 1;
    for (int k = 0; k < 1000; k++) {
        sum += power;
        power *= q;
    }
    ck_assert_rel(optics_geometric_sum(q, 1000), sum, 1e-13);
    rgb g = optics_geometric_sum_rgb(vec_make(0.5, 0, 1), 4);
    ck_assert_vec_near(g, vec_make(1.875, 1, 4), 1e-15);
}
END_TEST

START_TEST(test_optics_slab_hit)
{
    /* [ORACLE-MIRRORS-1] Walls y = 0 and y = 2, from (0, 1, 0) along (0.6, 0.8, 0): step by
     * step, the first hit is 1 up (path 1/0.8 = 1.25, x = 0.75) on the top
     * wall, then each crossing of the slab is 2 high (path 2.5, x + 1.5),
     * alternating walls, the vertical direction flipping each time. */
    optics_slab slab = {{0, 1, 0}, 0, 2};
    vec3 o = vec_make(0, 1, 0), d = vec_make(0.6, 0.8, 0);
    double x[3] = {0.75, 2.25, 3.75}, y[3] = {2, 0, 2}, path[3] = {1.25, 3.75, 6.25};
    for (int k = 0; k < 3; k++) {
        optics_bounce b;
        optics_slab_hit(&slab, o, d, k, &b);
        ck_assert_vec_near(b.point, vec_make(x[k], y[k], 0), 1e-15);
        ck_assert_int_eq(b.wall, k % 2 == 0);
        ck_assert_vec_near(b.dir, vec_make(0.6, k % 2 ? -0.8 : 0.8, 0), 0);
        ck_assert_vec_near(b.inward, vec_make(0, k % 2 ? 1 : -1, 0), 0);
        ck_assert_rel(b.length, path[k], 1e-15);
    }
    /* Going down along (0, -0.6, 0.8): the bottom wall after 1/0.6, then
     * the top after 3/0.6 = 5, z = 0.8 times the path. */
    optics_bounce b;
    optics_slab_hit(&slab, o, vec_make(0, -0.6, 0.8), 0, &b);
    ck_assert_vec_near(b.point, vec_make(0, 0, 0.8 / 0.6), 1e-15);
    ck_assert_int_eq(b.wall, 0);
    optics_slab_hit(&slab, o, vec_make(0, -0.6, 0.8), 1, &b);
    ck_assert_vec_near(b.point, vec_make(0, 2, 4), 1e-14);
    ck_assert_int_eq(b.wall, 1);
    ck_assert_vec_near(b.dir, vec_make(0, 0.6, 0.8), 0);
}
END_TEST

START_TEST(test_optics_slab_shift)
{
    /* [ORACLE-SLAB-2] sin theta 0.6, cos 0.8, n 1.2: sin theta_t = 0.5, cos = sqrt3/2.
     * Along the floor the refracted ray falls short by
     * h (tan theta - tan theta_t) = 0.75 - 1/sqrt3, and the perpendicular
     * distance of two parallel lines is that times cos theta. */
    double want = (0.75 - 1 / sqrt(3.0)) * 0.8;
    ck_assert_rel(optics_slab_shift(1, 0.6, 0.8, 1.2), want, 1e-14);
    ck_assert_rel(optics_slab_shift(2.5, 0.6, 0.8, 1.2), 2.5 * want, 1e-14);
    /* Normal incidence and ior 1 do not shift. */
    ck_assert_double_eq(optics_slab_shift(1, 0, 1, 1.5), 0);
    ck_assert_near(optics_slab_shift(1, 0.6, 0.8, 1), 0, 1e-16);
}
END_TEST

/* A second route for the ball: a 2-D trace in the (z, y) plane, ball at
 * the origin, the ray coming along +z at height y: the line meets the
 * circle, Snell's law in vector form bends it, the chord gives the exit,
 * Snell again.  Returns the exit point and direction. */
static void ball_by_vectors(double y, double radius, double n, double *ez, double *ey, double *dz, double *dy)
{
    double pz = -sqrt(radius * radius - y * y), py = y;
    double nz = pz / radius, ny = py / radius;          /* outward normal */
    double c = -nz, eta = 1 / n;                        /* d = (1, 0): cos i = -n.d */
    double k = 1 - eta * eta * (1 - c * c);
    double tz = eta + (eta * c - sqrt(k)) * nz, ty = (eta * c - sqrt(k)) * ny;
    double s = -2 * (pz * tz + py * ty);                /* the chord */
    *ez = pz + s * tz;
    *ey = py + s * ty;
    nz = -*ez / radius;                                 /* inward normal at the exit */
    ny = -*ey / radius;
    c = -(nz * tz + ny * ty);
    eta = n;
    k = 1 - eta * eta * (1 - c * c);
    *dz = eta * tz + (eta * c - sqrt(k)) * nz;
    *dy = eta * ty + (eta * c - sqrt(k)) * ny;
}

START_TEST(test_optics_ball_trace)
{
    /* [ORACLE-BALL-1, ORACLE-BALL-2] n = sqrt3, y = R sqrt3/2: i = 60, sin r = 1/2 so r = 30, deviation
     * 2(60 - 30) = 60 degrees; the exit's polar angle 2r - i = 0: the ray
     * leaves on the axis at (R, 0), which is where it crosses it. */
    optics_ball_path p;
    double radius = 2, pi = acos(-1.0);
    optics_ball_trace(radius * sqrt(3.0) / 2, radius, sqrt(3.0), &p);
    ck_assert_rel(p.incidence, pi / 3, 1e-15);
    ck_assert_rel(p.refraction, pi / 6, 1e-15);
    ck_assert_rel(p.deviation, pi / 3, 1e-15);
    ck_assert_rel(p.exit_z, radius, 1e-15);
    ck_assert_near(p.exit_y, 0, 1e-15);
    ck_assert_rel(optics_ball_axis_crossing(radius * sqrt(3.0) / 2, radius, sqrt(3.0)), radius, 1e-15);
    /* A screen 2R from the centre: y_s = 0 - (2R - R) tan 60 = -sqrt3 R. */
    ck_assert_rel(optics_ball_screen_height(&p, 2 * radius), -sqrt(3.0) * radius, 1e-14);
    /* Against the vector trace at other heights and indices. */
    double heights[] = {0.01, 0.3, 0.5, 0.77, 0.95, 0.999};
    double indices[] = {1.33, 1.5, 2.2};
    for (int a = 0; a < 6; a++) {
        for (int b = 0; b < 3; b++) {
            double ez, ey, dz, dy;
            ball_by_vectors(heights[a], 1, indices[b], &ez, &ey, &dz, &dy);
            optics_ball_trace(heights[a], 1, indices[b], &p);
            ck_assert_near(p.exit_z, ez, 1e-12);
            ck_assert_near(p.exit_y, ey, 1e-12);
            ck_assert_near(cos(p.deviation), dz, 1e-12);
            ck_assert_near(-sin(p.deviation), dy, 1e-12);
        }
    }
}
END_TEST

START_TEST(test_optics_ball_paraxial_focus)
{
    /* [ORACLE-BALL-3] EFL = nR / (2(n - 1)): n 1.5, R 2 gives 3; n 2 (the focus on the
     * back surface) gives R. */
    ck_assert_rel(optics_ball_paraxial_focus(2, 1.5), 3, 1e-15);
    ck_assert_rel(optics_ball_paraxial_focus(1, 2), 1, 1e-15);
    /* Rays near the axis cross it near EFL: z_c = EFL (1 - O(y^2)); at
     * y = 1e-4 R the gap is about 1e-8 EFL. */
    double efl = optics_ball_paraxial_focus(1, 1.5);
    ck_assert_rel(optics_ball_axis_crossing(1e-4, 1, 1.5), efl, 1e-7);
    /* The same from the vector trace: where its exit line meets y = 0. */
    double ez, ey, dz, dy;
    ball_by_vectors(1e-4, 1, 1.5, &ez, &ey, &dz, &dy);
    ck_assert_rel(ez - ey * dz / dy, efl, 1e-7);
    /* Spherical aberration: marginal rays cross nearer.  y = R/2, n 1.5:
     * sin i = 1/2, cos i = sqrt3/2, sin r = 1/3, cos r = sqrt8/3, so
     * sin(i - r) = (sqrt8 - sqrt3)/6, cos(i - r) = (sqrt24 + 1)/6 and
     * z_c = (1/2) / (2 sin(i - r) cos(i - r)) = 9 / ((sqrt8 - sqrt3)(sqrt24 + 1))
     * = 1.39157 (delta = 21.0576 degrees). */
    ck_assert_rel(optics_ball_axis_crossing(0.5, 1, 1.5), 9 / ((sqrt(8.0) - sqrt(3.0)) * (sqrt(24.0) + 1)), 1e-14);
    ck_assert(optics_ball_axis_crossing(0.5, 1, 1.5) < optics_ball_axis_crossing(0.1, 1, 1.5));
    ck_assert(optics_ball_axis_crossing(0.1, 1, 1.5) < efl);
}
END_TEST

START_TEST(test_optics_critical_sin)
{
    /* [ORACLE-SNELL-1] Glass to air: sin theta_c = 1/1.5, theta_c = 41.81 degrees; air to
     * glass: no total internal reflection (1). */
    ck_assert_rel(optics_critical_sin(1.5, 1), 2.0 / 3, 1e-15);
    ck_assert_near(asin(optics_critical_sin(1.5, 1)) * 180 / acos(-1.0), 41.8103, 1e-4);
    ck_assert_double_eq(optics_critical_sin(1, 1.5), 1);
    ck_assert_double_eq(optics_critical_sin(1.2, 1.2), 1);
}
END_TEST

START_TEST(test_optics_light_terms)
{
    /* [ORACLE-MIRRORS-2] A light at (0, 3, 4) over the origin, N = +y: d = 5, N.L = 3/5;
     * linear, E 10, d0 1: I = 10/6; Kd 0.5: body = 0.5 * 10/6 * 0.6 = 0.5.
     * V = (0, 0.6, -0.8) is L mirrored about N, so V.R = 1:
     * highlight = Ks I = 0.25 * 10/6. */
    scene_light l;
    scene_material m;
    memset(&l, 0, sizeof l);
    memset(&m, 0, sizeof m);
    l.kind = LIGHT_POINT;
    l.position = vec_make(0, 3, 4);
    l.power = vec_splat(10);
    l.d0 = 1;
    l.falloff = FALLOFF_LINEAR;
    m.kd = vec_splat(0.5);
    m.ks = vec_splat(0.25);
    m.n = 7;
    rgb body = vec_splat(0), hl = vec_splat(0);
    vec3 up = vec_make(0, 1, 0), v = vec_make(0, 0.6, -0.8);
    ck_assert_int_eq(optics_light_terms(&l, &m, vec_make(0, 0, 0), up, v, 1, &body, &hl), 1);
    ck_assert_vec_near(body, vec_splat(0.5), 1e-15);
    ck_assert_vec_near(hl, vec_splat(0.25 * 10 / 6.0), 1e-15);
    /* Through S = 0.5 and inverse square: I = 10/36, halved. */
    l.falloff = FALLOFF_INVERSE_SQUARE;
    body = hl = vec_splat(0);
    optics_light_terms(&l, &m, vec_make(0, 0, 0), up, v, 0.5, &body, &hl);
    ck_assert_vec_near(body, vec_splat(0.5 * 10 / 36.0 * 0.6 * 0.5), 1e-15);
    /* Below the horizon nothing is added. */
    l.position = vec_make(0, -3, 4);
    body = hl = vec_splat(0);
    ck_assert_int_eq(optics_light_terms(&l, &m, vec_make(0, 0, 0), up, v, 1, &body, &hl), 1);
    ck_assert_vec_near(vec_add(body, hl), vec_splat(0), 0);
    /* Shininess 0 is a step at V.R = 0: V perpendicular to R = (0, .6, -.8)
     * is ambiguous. */
    l.position = vec_make(0, 3, 4);
    m.n = 0;
    ck_assert_int_eq(optics_light_terms(&l, &m, vec_make(0, 0, 0), up, vec_make(0, 0.8, 0.6), 1, &body, &hl), 0);
}
END_TEST

START_TEST(test_optics_spawn_offset)
{
    /* 2^-42 max(m, max |p_i|) + 1e-300, the figure of intersect.h. */
    ck_assert_double_eq(optics_spawn_offset(4, vec_make(-8, 1, 2)), ldexp(8, -42) + 1e-300);
    ck_assert_double_eq(optics_spawn_offset(16, vec_make(-8, 1, 2)), ldexp(16, -42) + 1e-300);
    ck_assert_double_eq(optics_max_abs(vec_make(1, -7, 3)), 7);
    ck_assert(optics_close(vec_make(1, 2, 0), vec_make(1 + 1e-10, 2, 0), 1e-9));
    ck_assert(!optics_close(vec_make(1, 2, 0), vec_make(1, 2, 1e-300), 1e-9));
}
END_TEST

/* ---- 2. closed forms at chosen pixels ---- */

/* Walls y = 0 and y = 2; a 1 x 1 camera at (0, 1, 0) whose only sample is
 * the forward ray. */
#define MIRRORS(depth, look, walls)                                                         \
    "oracle parallel_mirrors\n"                                                             \
    "image { width 1 height 1 max_depth " depth " }\n"                                      \
    "camera { perspective eye [0, 1, 0] look_at " look " fov 10 }\n" walls

START_TEST(test_parallel_mirrors_closed_series)
{
    /* [ORACLE-MIRRORS-4] One material Kd 0.1, Ks 0.5, Ia 0.5, D 4: 0.05 (1 + 1/2 + 1/4 + 1/8). */
    scene_model *s = load_text(MIRRORS("4", "[1, 0, 0]", "ambient { color 0.5 }\n"
                                    "plane { material { Kd 0.1 Ks 0.5 } }\n"
                                    "plane { point [0, 2, 0] material { Kd 0.1 Ks 0.5 } }\n"));
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.09375), 1e-15);
    scene_free(s);
    /* Floor A (Kd 0.2, Ks 0.5), ceiling B (Kd 0.4, Ks 0.8), Ia 1, D 3.
     * Looking down: A, B, A = 0.2 + 0.5 * 0.4 + 0.5 * 0.8 * 0.2 = 0.48;
     * looking up:   B, A, B = 0.4 + 0.8 * 0.2 + 0.8 * 0.5 * 0.4 = 0.72. */
    const char *walls = "ambient { color 1 }\nplane { material { Kd 0.2 Ks 0.5 } }\n"
                        "plane { point [0, 2, 0] normal [0, -1, 0] material { Kd 0.4 Ks 0.8 } }\n";
    char text[1024];
    snprintf(text, sizeof text, MIRRORS("3", "[1, 0, 0]", "%s"), walls);
    s = load_text(text);
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.48), 1e-15);
    scene_free(s);
    snprintf(text, sizeof text, MIRRORS("3", "[1, 2, 0]", "%s"), walls);
    s = load_text(text);
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.72), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_parallel_mirrors_lit_straight_down)
{
    /* [ORACLE-MIRRORS-2, ORACLE-MIRRORS-3] An orthographic ray straight down through (0, ., 0), light at
     * (0, 1, 0): every hit is 1 from the light, N.L = 1 and V = R, so the
     * local colour is Kd E/1 + Ks E/1 = 0.1*2 + 0.5*2 = 1.2 (Ia 0), and
     * with D 3 the series is 1.2 (1 + 0.5 + 0.25) = 2.1. */
    scene_model *s = load_text("oracle parallel_mirrors\n"
                            "image { width 1 height 1 max_depth 3 }\n"
                            "camera { orthographic eye [0, 1.5, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                            "point_light { position [0, 1, 0] power 2 d0 0 }\n"
                            "plane { material { Kd 0.1 Ks 0.5 n 10 } }\n"
                            "plane { point [0, 2, 0] material { Kd 0.1 Ks 0.5 n 10 } }\n");
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(2.1), 1e-14);
    scene_free(s);
}
END_TEST

/* Reflection step by step (the route the oracle does not take): from o
 * along d between y = 0 and y = 2, mirror at each wall; local colour Kd E /
 * d * N.L + Ks E / d * (V.R)^n for a linear light at p, weights Ks^k. */
static double mirrors_by_steps(vec3 o, vec3 d, vec3 p, double e, double kd, double ks, double n, int depth)
{
    double sum = 0, weight = 1;
    for (int k = 0; k < depth; k++) {
        double wall = d.y > 0 ? 2 : 0, s = (wall - o.y) / d.y;
        vec3 x = vec_madd(o, d, s), nrm = vec_make(0, d.y > 0 ? -1 : 1, 0);
        vec3 to = vec_sub(p, x);
        double dist = vec_length(to);
        vec3 l = vec_scale(to, 1 / dist), r = vec_sub(vec_scale(nrm, 2 * vec_dot(nrm, l)), l);
        double vr = -vec_dot(d, r);
        sum += weight * (kd * e / dist * vec_dot(nrm, l) + ks * e / dist * (vr > 0 ? pow(vr, n) : 0));
        weight *= ks;
        o = x;
        d.y = -d.y;
    }
    return sum;
}

START_TEST(test_parallel_mirrors_lit_oblique)
{
    /* [ORACLE-MIRRORS-1, ORACLE-MIRRORS-2] The forward ray of the 1 x 1 camera, along (3, -1, 0.5), against the
     * step-by-step route; the light off the ray's plane. */
    scene_model *s = load_text(MIRRORS("6", "[3, 0, 0.5]", "point_light { position [4, 1.3, 1] power 2 d0 0 }\n"
                                    "plane { material { Kd 0.2 Ks 0.6 n 5 } }\n"
                                    "plane { point [0, 2, 0] material { Kd 0.2 Ks 0.6 n 5 } }\n"));
    double want = mirrors_by_steps(vec_make(0, 1, 0), vec_normalize(vec_make(3, -1, 0.5)), vec_make(4, 1.3, 1), 2,
                                   0.2, 0.6, 5, 6);
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(want), 1e-13);
    scene_free(s);
}
END_TEST

START_TEST(test_parallel_mirrors_horizon_is_ambiguous)
{
    /* [ORACLE-MIRRORS margins] The forward ray parallel to the walls escapes: ambiguous. */
    rgb c;
    scene_model *s = load_text(MIRRORS("4", "[1, 1, 0]", "plane { material { Ks 0.5 } }\n"
                                    "plane { point [0, 2, 0] material { Ks 0.5 } }\n"));
    ck_assert_int_eq(radiance_at(s, 0.5, 0.5, &c), ORACLE_AMBIGUOUS);
    scene_free(s);
}
END_TEST

/* The slab y in [1, 2] over the floor y = 0; an orthographic camera whose
 * forward ray is (0.6, -0.8, 0) (sin theta 0.6) through the origin. */
#define SLAB(depth, ior, light)                                                             \
    "oracle glass_slab\n"                                                                   \
    "image { width 1 height 1 max_depth " depth " background 0.4 }\n"                        \
    "camera { orthographic eye [-6, 8, 0] look_at [0, 0, 0] width 0.5 }\n" light            \
    "box { from [-50, 1, -50] to [50, 2, 50] material { Kd 0 t 0.9 ior " ior " } }\n"       \
    "plane { material { Kd 0.8 } }\n"

START_TEST(test_glass_slab_shift_seen)
{
    /* [ORACLE-SLAB-2, ORACLE-SLAB-3] n 1.2: sin theta_t = 0.5; the floor point seen moves back along x by
     * h (tan theta - tan theta_t) = 0.75 - 1/sqrt3 (h = 1).  A light at
     * (0, 0.5, 0), E 1, d0 0, linear: with a = 0.75 - 1/sqrt3 the floor is
     * Kd (1/d)(0.5/d) = 0.8 * 0.5 / (a^2 + 0.25), times t^2 = 0.81. */
    scene_model *s = load_text(SLAB("3", "1.2", "point_light { position [0, 0.5, 0] power 1 d0 0 }\n"));
    double a = 0.75 - 1 / sqrt(3.0);
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.81 * 0.8 * 0.5 / (a * a + 0.25)), 1e-13);
    scene_free(s);
    /* Cut at depth 2 and 1: the slab's own colour only, 0 with Kd 0. */
    s = load_text(SLAB("2", "1.2", "point_light { position [0, 0.5, 0] power 1 d0 0 }\n"));
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0), 0);
    scene_free(s);
}
END_TEST

START_TEST(test_glass_slab_light_above)
{
    /* [ORACLE-SLAB-3] A distant light straight down, E 1: the floor receives it through
     * both faces (S = t^2 = 0.81), N.L = 1: floor = 0.8 * 0.81, seen with
     * weight t^2: 0.81 * 0.8 * 0.81 (with n 1.2 as above). */
    scene_model *s = load_text(SLAB("3", "1.2", "distant_light { direction [0, -1, 0] power 1 }\n"));
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.81 * 0.8 * 0.81), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_glass_slab_total_reflection)
{
    /* [ORACLE-SLAB-4] ior 0.5 < sin theta 0.6: total reflection at the top face, the
     * mirror ray goes up to the background: t bg = 0.9 * 0.4.  ior 0.6 =
     * sin theta is the critical angle: ambiguous. */
    rgb c;
    scene_model *s = load_text(SLAB("3", "0.5", ""));
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.36), 1e-15);
    scene_free(s);
    s = load_text(SLAB("3", "0.6", ""));
    ck_assert_int_eq(radiance_at(s, 0.5, 0.5, &c), ORACLE_AMBIGUOUS);
    scene_free(s);
}
END_TEST

/* Inside a glass box y in [-1, 1], a 1 x 1 camera at the origin. */
#define WINDOW(depth, look, light, glass)                                                   \
    "oracle snell_window\n"                                                                 \
    "image { width 1 height 1 max_depth " depth " background 0.5 }\n"                        \
    "camera { perspective eye [0, 0, 0] look_at " look " up [0, 0, 1] fov 10 }\n" light     \
    "box { from [-50, -1, -50] to [50, 1, 50] material { " glass " } }\n"

START_TEST(test_snell_window_closed_series)
{
    /* [ORACLE-SNELL-3] Kd 0.3, t 0.7, Ia 0.5, ior 1.5, D 6: L = (1 - t) Kd Ia = 0.045.
     * At 30 degrees from the faces' normal (sin 0.5 < 2/3) the ray leaves:
     * L + t bg = 0.045 + 0.35; at 44 degrees (sin 0.6947 > 2/3) it is
     * totally reflected every time: L (1 - 0.7^6) / 0.3 = 0.045 * 0.882351
     * / 0.3.  (Past 45 degrees the family would take the side faces.) */
    const char *glass = "Kd 0.3 t 0.7 ior 1.5";
    char text[1024];
    snprintf(text, sizeof text, WINDOW("6", "[0.5, 0.8660254037844386, 0]", "ambient { color 0.5 }\n", "%s"), glass);
    scene_model *s = load_text(text);
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.395), 1e-15);
    scene_free(s);
    snprintf(text, sizeof text,
             WINDOW("6", "[0.6946583704589973, 0.7193398003386512, 0]", "ambient { color 0.5 }\n", "%s"), glass);
    s = load_text(text);
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.045 * 0.882351 / 0.3), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_snell_window_critical_angle_is_ambiguous)
{
    /* [ORACLE-SNELL-1] sin theta = 2/3 exactly in the scene (look_at (2/3, sqrt5/3, 0)):
     * within the 1e-9 margin of the critical angle. */
    rgb c;
    scene_model *s = load_text(WINDOW("4", "[0.6666666666666666, 0.7453559924999299, 0]", "", "Kd 0.3 t 0.7 ior 1.5"));
    ck_assert_int_eq(radiance_at(s, 0.5, 0.5, &c), ORACLE_AMBIGUOUS);
    scene_free(s);
}
END_TEST

START_TEST(test_snell_window_lit)
{
    /* [ORACLE-SNELL-2, ORACLE-SNELL-3] Straight up, light at (0, -0.5, 0), linear E 1, d0 0; Kd 0.2, Ks 0.1,
     * n 5, t 0.6, Ia 0, bg 0.5, D 3.  Hits at the top (d 1.5, I 2/3), the
     * bottom (d 0.5, I 2), the top; N.L = 1 and V = R each time, so the
     * local colour is (1 - t) Kd I + Ks I: 0.12, 0.36, 0.12.  Inside the
     * window each hit but the last also sends t bg = 0.3 out and the path
     * goes on with Ks:  0.12 + 0.3 + 0.1 (0.36 + 0.3) + 0.01 * 0.12. */
    scene_model *s = load_text(WINDOW("3", "[0, 1, 0]", "point_light { position [0, -0.5, 0] power 1 d0 0 }\n",
                                   "Kd 0.2 Ks 0.1 n 5 t 0.6 ior 1.5"));
    ck_assert_rgb_rel(exact_at(s, 0.5, 0.5), vec_splat(0.4872), 1e-14);
    scene_free(s);
}
END_TEST

/* A unit ball at the origin, a screen at z = -2, an orthographic camera
 * along -z, 2 wide and 100 pixels: world x is image x = 50 (x + 1). */
#define BALL(depth, glass, light)                                                           \
    "oracle ball_lens\n"                                                                    \
    "image { width 100 height 100 max_depth " depth " background 0.25 }\n"                   \
    "camera { orthographic eye [0, 0, 5] look_at [0, 0, 0] width 2 }\n" light              \
    "sphere { material { Kd 0 t 0.8 " glass " } }\n"                                        \
    "plane { point [0, 0, -2] normal [0, 0, 1] material { Kd 0.6 } }\n"

START_TEST(test_ball_lens_sixty_degrees)
{
    /* [ORACLE-BALL-2, ORACLE-BALL-4] n = sqrt3, y = sqrt3/2: the ray leaves at (1, 0) on the axis turned
     * 60 degrees, and meets the screen, 2 from the centre along the view,
     * at y_s = -(2 - 1) tan 60 = -sqrt3: world (-sqrt3, 0, -2).
     * A light at (-sqrt3, 0, -1.5): d 0.5, N.L 1, linear E 1: the screen is
     * 0.6 * 2, seen with t^2 = 0.64. */
    scene_model *s = load_text(BALL("3", "ior 1.7320508075688772",
                                 "point_light { position [-1.7320508075688772, 0, -1.5] power 1 d0 0 }\n"));
    double x = 50 * (sqrt(3.0) / 2 + 1);
    ck_assert_rgb_rel(exact_at(s, x, 50), vec_splat(0.64 * 0.6 * 2), 1e-12);
    /* The corner sample (99.5, 0.5) is the ray at world (0.99, 0.99),
     * 0.99 sqrt2 > 1 from the axis: it sees the screen at (0.99, 0.99, -2)
     * straight on, Kd (1/d) (0.5/d). */
    vec3 f = vec_make(0.99, 0.99, -2), l = vec_make(-sqrt(3.0), 0, -1.5);
    double d = vec_length(vec_sub(l, f));
    ck_assert_rgb_rel(exact_at(s, 99.5, 0.5), vec_splat(0.6 / d * (0.5 / d)), 1e-13);
    scene_free(s);
}
END_TEST

START_TEST(test_ball_lens_turns_back_and_depth)
{
    /* [ORACLE-BALL-4] n = sqrt3 turns the rays past 90 degrees for y > 0.9836 (i - r = 45
     * degrees): y = 0.995 sees t^2 bg = 0.64 * 0.25.  Below depth 3 the
     * ball's own colour, 0 with Kd 0 and Ks 0, is all. */
    scene_model *s = load_text(BALL("3", "ior 1.7320508075688772", "ambient { color 1 }\n"));
    ck_assert_rgb_rel(exact_at(s, 50 * 1.995, 50), vec_splat(0.16), 1e-15);
    scene_free(s);
    s = load_text(BALL("2", "ior 1.7320508075688772", "ambient { color 1 }\n"));
    ck_assert_rgb_rel(exact_at(s, 50 * 1.5, 50), vec_splat(0), 0);
    scene_free(s);
}
END_TEST

START_TEST(test_ball_lens_outline_is_ambiguous)
{
    rgb c;
    scene_model *s = load_text(BALL("3", "ior 1.5", "ambient { color 1 }\n"));
    ck_assert_int_eq(radiance_at(s, 100, 50, &c), ORACLE_AMBIGUOUS);
    ck_assert_int_eq(radiance_at(s, 50, 0, &c), ORACLE_AMBIGUOUS);
    scene_free(s);
}
END_TEST

START_TEST(test_ball_lens_focus_seen_by_the_tracer)
{
    /* [ORACLE-BALL-3] The screen at the paraxial focus EFL = nR/(2(n-1)) = 1.5 (n 1.5):
     * rays near the axis all land near the axis point, y_s = O(y^3), so
     * the tracer's pixels near the centre show the screen's colour at the
     * axis point.  A light on the axis 0.4 in front of the screen, E 1,
     * linear: 0.6 * (1/0.4) * 1 * t^2 = 0.96 at the axis; the gradient
     * there is 0 (the light is on the axis), and y_s ~ 1e-7 changes it by
     * about (y_s / 0.4)^2, far less than 1e-11. */
    scene_model *s = load_text("oracle ball_lens\n"
                            "image { width 101 height 101 max_depth 3 }\n"
                            "camera { orthographic eye [0, 0, 5] look_at [0, 0, 0] width 0.202 }\n"
                            "point_light { position [0, 0, -1.1] power 1 d0 0 }\n"
                            "sphere { material { Kd 0 t 0.8 ior 1.5 } }\n"
                            "plane { point [0, 0, -1.5] normal [0, 0, 1] material { Kd 0.6 } }\n");
    tracer t;
    trace_stats st;
    memset(&st, 0, sizeof st);
    ck_assert(tracer_init(&t, s, 0, 0));
    /* Pixel (50 + k, 50) sees the ray at x = 0.002 k: k = 1 .. 3. */
    for (int k = 1; k <= 3; k++) {
        rgb c = render_pixel(&t, 101, 101, 1, 50 + k, 50, &st);
        ck_assert_rel(c.x, 0.96, 1e-11);
        ck_assert_rgb_rel(exact_at(s, 50.5 + k, 50.5), c, 1e-12);
    }
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/* ---- 3. every scene against the tracer ---- */

typedef struct scene_case {
    const char *path;
    const char *family;
    long max_excluded;  /* pixels with an ambiguous sample point */
    double min_spread;  /* the exact image must not be flat */
} scene_case;

static const scene_case scenes[] = {
    {"scenes/analytic/parallel_mirrors.scene", "parallel_mirrors", 100, 0.5},
    {"scenes/analytic/parallel_mirrors_ambient.scene", "parallel_mirrors", 64, 0.05},
    {"scenes/analytic/glass_slab.scene", "glass_slab", 0, 0.5},
    {"scenes/analytic/glass_slab_above.scene", "glass_slab", 0, 0.05},
    {"scenes/analytic/glass_slab_on_floor.scene", "glass_slab", 0, 0.05},
    {"scenes/analytic/snell_window.scene", "snell_window", 10, 0.3},
    {"scenes/analytic/snell_window_lit.scene", "snell_window", 10, 0.3},
    {"scenes/analytic/ball_lens.scene", "ball_lens", 10, 0.5},
};

enum { SCENE_COUNT = sizeof scenes / sizeof scenes[0] };

static double spread(const img_buf *img, const unsigned char *excluded)
{
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (long p = 0; p < (long)img->width * img->height; p++)
        for (int c = 0; c < 3 && !excluded[p]; c++) {
            lo = fmin(lo, img->rgb[3 * p + c]);
            hi = fmax(hi, img->rgb[3 * p + c]);
        }
    return hi - lo;
}

/* Renders s and compares it with its exact image, whose tolerance is within
 * 2 % of `tolerance`; returns the metrics and the excluded count. */
static void compare_scene(const scene_model *s, const char *name, double tolerance, image_metrics *m, long *count,
                          double *range)
{
    const oracle_family *f = family_of(s);
    oracle_view v = view_of(s);
    img_buf traced, exact;
    unsigned char *excluded = calloc((size_t)v.width * (size_t)v.height, 1);
    ck_assert_ptr_nonnull(excluded);
    ck_assert_int_eq(render_image(s, NULL, &traced, NULL), STATUS_OK);
    ck_assert_int_eq(oracle_image(f, &v, &exact, excluded, count), STATUS_OK);
    ck_assert_msg(fabs(f->tolerance(&v, 0) - tolerance) <= 0.02 * tolerance, "%s: tolerance %g, not %g", name,
                  f->tolerance(&v, 0), tolerance);
    metrics_compare(&traced, &exact, excluded, f->tolerance(&v, 0), m);
    *range = spread(&exact, excluded);
    if (getenv("ORACLE_REPORT"))
        printf("%-52s max_rel %.3e  max_abs %.3e  over %ld  excluded %ld of %ld\n", name, m->max_rel, m->max_abs,
               m->over, *count, m->compared + m->excluded);
    ck_assert_msg(m->over == 0, "%s: %ld pixels over 1e-9; max rel %.3e, worst pixel (%d, %d)", name, m->over,
                  m->max_rel, m->worst_x, m->worst_y);
    img_free(&traced);
    img_free(&exact);
    free(excluded);
}

START_TEST(test_oracle_optics_image_matches_render)
{
    const scene_case *sc = &scenes[_i];
    scene_model *s = load_file(sc->path);
    ck_assert_str_eq(s->oracle, sc->family);
    image_metrics m;
    long count = -1;
    double range;
    compare_scene(s, sc->path, 1e-9, &m, &count, &range);
    ck_assert_msg(count <= sc->max_excluded, "%s: %ld pixels excluded (bound %ld)", sc->path, count,
                  sc->max_excluded);
    ck_assert_msg(range > sc->min_spread, "%s: the exact image is nearly flat (%g)", sc->path, range);
    scene_free(s);
}
END_TEST

START_TEST(test_parallel_mirrors_far_from_origin)
{
    /* [ORACLE-MIRRORS margins] The mirror scene moved 5000 away: the
     * tracer's spawn offsets grow to 2^-42 * 5000 = 1.1e-9 of the 2-unit
     * gap, and the slips along the walls pass the tolerance at many pixels
     * (measured without the exclusion: 254 pixels over 1e-9, up to 2.0e-9).
     * The sensitive pixels are excluded, the rest pass, under the floor's
     * term for that offset ([ORACLE-VIEW-ROUNDING-3]): 8 * 2^-42 * 5002
     * (the planes' largest coordinate) / 0.5 (the light below the upper
     * mirror) = 1.82e-8, plus the view's 256 u D / S, D = |eye| + 5002 + 1
     * = 13664 and S = 2 tan 35 deg = 1.4 at the floor 1 below the eye:
     * 2.8e-10; 1.85e-8 in all. */
    scene_model *s = load_text("oracle parallel_mirrors\n"
                            "image { width 96 height 72 max_depth 6 }\n"
                            "camera { eye [5000, 5001, 5000] look_at [5000, 5000.95, 4997] fov 70 }\n"
                            "point_light { position [5000.5, 5001.5, 4994] power 4 d0 0.5 }\n"
                            "plane { point [0, 5000, 0] material { Kd [0.15, 0.15, 0.2] Ks 0.75 n 200 } }\n"
                            "plane { point [0, 5002, 0] normal [0, -1, 0] material { Kd 0.2 Ks 0.6 n 60 } }\n");
    image_metrics m;
    long count = -1;
    double range;
    compare_scene(s, "parallel_mirrors at 5000", 8 * 0x1p-42 * 5002 / 0.5 + 256 * 0x1p-53 * 13664 / 1.4, &m, &count,
                  &range);
    ck_assert(count > 0);
    ck_assert(count < 96 * 72);
    scene_free(s);
}
END_TEST

START_TEST(test_ball_lens_rim_sensitivity)
{
    /* [ORACLE-BALL margins] A strip across the rim of a unit ball (n 1.5)
     * with no ambient: near y = 0.99837 the exit rays turn through 90
     * degrees; the tracer's exit angle (its entry point moved in by the
     * spawn offset, amplified by n cos r / cos i) moves far screen points by
     * more than 1e-9 (measured without the exclusion: 22 pixels over, up to
     * 6.3e-8).  Those are excluded; the rest, the background beyond
     * included, pass. */
    scene_model *s = load_text("oracle ball_lens\n"
                            "image { width 2000 height 1 max_depth 3 background [0.1, 0.2, 0.4] }\n"
                            "camera { orthographic eye [0.99, 0, 6] look_at [0.99, 0, 0] width 0.02 }\n"
                            "point_light { position [0.5, 0.3, -2.4] power 1 d0 0.05 }\n"
                            "sphere { material { Kd 0 t 0.9 ior 1.5 } }\n"
                            "plane { point [0, 0, -3] normal [0, 0, 1] material { Kd 0.9 } }\n");
    image_metrics m;
    long count = -1;
    double range;
    compare_scene(s, "ball_lens rim", 1e-9, &m, &count, &range);
    ck_assert(count > 0);
    ck_assert(count < 400);
    scene_free(s);
}
END_TEST

/* ---- 4. refusals ---- */

typedef struct refusal {
    const char *family;
    const char *text;
    const char *why;
} refusal;

#define BETWEEN "camera { eye [0, 1, 0] look_at [1, 0, 0] }\n"
#define TWO_WALLS "plane { }\nplane { point [0, 2, 0] }\n"
#define SLAB_CAM "camera { orthographic eye [-6, 8, 0] look_at [0, 0, 0] width 1 }\n"
#define SLAB_BOX "box { from [-50, 1, -50] to [50, 2, 50] material { Kd 0 t 0.9 ior 1.5 } }\n"
#define BALL_CAM "camera { orthographic eye [0, 0, 5] look_at [0, 0, 0] width 2 }\n"
#define LENS "sphere { material { Kd 0 t 0.9 ior 1.5 } }\n"
#define SCREEN "plane { point [0, 0, -3] normal [0, 0, 1] }\n"

static const refusal refusals[] = {
    {"parallel_mirrors", BETWEEN "plane { }\n", "parallel_mirrors: the scene must be exactly two planes"},
    {"parallel_mirrors", BETWEEN "plane { }\nplane { point [0, 2, 0] normal [0, 1, 0.1] }\n",
     "parallel_mirrors: the two planes are not parallel"},
    {"parallel_mirrors", BETWEEN "plane { }\nplane { point [0, 2, 0] material { t 0.5 } }\n",
     "parallel_mirrors: plane 2 is transparent (t must be 0)"},
    {"parallel_mirrors", BETWEEN "plane { }\nplane { point [5, 0, 0] }\n",
     "parallel_mirrors: the two planes coincide"},
    {"parallel_mirrors", "camera { eye [0, 3, 0] look_at [1, 0, 0] }\n" TWO_WALLS,
     "parallel_mirrors: the camera is not strictly between the mirrors"},
    {"parallel_mirrors", BETWEEN "point_light { position [0, 2, 0] }\n" TWO_WALLS,
     "parallel_mirrors: point light 1 is not strictly between the mirrors"},
    {"parallel_mirrors", BETWEEN "distributed_light { disk [0, 1, 0] [0, 1, 0] 0.5 }\n" TWO_WALLS,
     "parallel_mirrors: light 1 is distributed (point or distant only)"},
    {"glass_slab", SLAB_CAM SLAB_BOX "sphere { }\n",
     "glass_slab: the scene must be one box (not rotated) and one plane"},
    {"glass_slab", SLAB_CAM SLAB_BOX "plane { normal [0, 1, 1] }\n",
     "glass_slab: the floor's normal must be a coordinate axis"},
    {"glass_slab", SLAB_CAM SLAB_BOX "plane { point [0, 1.5, 0] }\n",
     "glass_slab: the floor must lie below the slab or touch it"},
    {"glass_slab", SLAB_CAM "box { from [-50, 1, -50] to [50, 2, 50] material { Ks 0.1 t 0.9 } }\nplane { }\n",
     "glass_slab: the slab must have Ks = 0 and t > 0"},
    {"glass_slab", SLAB_CAM SLAB_BOX "plane { material { t 0.5 } }\n",
     "glass_slab: the floor must have Ks = 0 and t = 0"},
    {"glass_slab", "camera { eye [-6, 8, 0] look_at [0, 0, 0] }\n" SLAB_BOX "plane { }\n",
     "glass_slab: the camera must be orthographic"},
    {"glass_slab", SLAB_CAM "point_light { position [0, 1.5, 0] }\n" SLAB_BOX "plane { }\n",
     "glass_slab: point light 1 lies within the slab's thickness"},
    {"glass_slab", "camera { orthographic eye [-6, 1.5, 0] look_at [0, 0, 0] width 1 }\n" SLAB_BOX "plane { }\n",
     "glass_slab: the camera must be above the slab, looking down at it"},
    {"glass_slab", SLAB_CAM "box { from [-1, 1, -1] to [1, 2, 1] material { Kd 0 t 0.9 ior 1.5 } }\nplane { }\n",
     "glass_slab: some camera ray does not cross the top and bottom faces (make the slab wider)"},
    {"glass_slab", SLAB_CAM "point_light { position [-20, 3, 0] }\n"
                   "box { from [-3, 1, -3] to [3, 2, 3] material { Kd 0 t 0.9 ior 1.5 } }\nplane { point [0, -5, 0] }\n",
     "glass_slab: light 1 reaches the visible floor past the slab's bottom face (make the slab wider)"},
    {"snell_window", "camera { eye [0, 0, 0] look_at [0, 1, 0] up [0, 0, 1] }\nsphere { }\n",
     "snell_window: the scene must be one box (not rotated)"},
    {"snell_window", "camera { eye [0, 0, 0] look_at [0, 1, 0] up [0, 0, 1] }\nbox { from [-9, -1, -9] to [9, 1, 9] }\n",
     "snell_window: the box must be transparent (t > 0)"},
    {"snell_window", "camera { eye [0, 0, 0] look_at [0, 1, 0] up [0, 0, 1] }\n"
                     "distant_light { direction [0, -1, 0] }\nbox { from [-9, -1, -9] to [9, 1, 9] material { t 0.5 } }\n",
     "snell_window: light 1 is not a point light"},
    {"snell_window", "camera { eye [0, 0, 0] look_at [0, 1, 0] up [0, 0, 1] }\n"
                     "point_light { position [0, 3, 0] }\nbox { from [-9, -1, -9] to [9, 1, 9] material { t 0.5 } }\n",
     "snell_window: point light 1 is not strictly inside the box"},
    {"snell_window", "camera { eye [0, 3, 0] look_at [0, 1, 0] up [0, 0, 1] }\n"
                     "box { from [-9, -1, -9] to [9, 1, 9] material { t 0.5 } }\n",
     "snell_window: the camera is not strictly inside the box"},
    {"snell_window", "camera { eye [0, 0, 0] look_at [1, 0.9, 0] fov 170 }\n"
                     "box { from [-9, -9, -9] to [9, 9, 9] material { t 0.5 } }\n",
     "snell_window: the view must not contain directions parallel to the faces"},
    {"snell_window", "camera { eye [0, 0, 0] look_at [0, 1, 0] up [0, 0, 1] fov 120 }\n"
                     "box { from [-9, -1, -9] to [9, 1, 9] material { t 0.5 } }\n",
     "snell_window: within max_depth some ray reaches a side of the box (make the box wider)"},
    {"ball_lens", BALL_CAM LENS, "ball_lens: the scene must be one sphere and one plane"},
    {"ball_lens", BALL_CAM "sphere { material { Kd 0.1 t 0.9 ior 1.5 } }\n" SCREEN,
     "ball_lens: the sphere must have Kd = 0, Ks = 0, t > 0 and ior > 1"},
    {"ball_lens", BALL_CAM "sphere { material { Kd 0 t 0.9 ior 0.9 } }\n" SCREEN,
     "ball_lens: the sphere must have Kd = 0, Ks = 0, t > 0 and ior > 1"},
    {"ball_lens", BALL_CAM LENS "plane { point [0, 0, -3] normal [0, 0, 1] material { Ks 0.2 } }\n",
     "ball_lens: the screen must have Ks = 0 and t = 0"},
    {"ball_lens", "camera { eye [0, 0, 5] look_at [0, 0, 0] }\n" LENS SCREEN,
     "ball_lens: the camera must be orthographic"},
    {"ball_lens", BALL_CAM LENS "plane { point [0, 0, -3] normal [0, 1, 1] }\n",
     "ball_lens: the screen must be perpendicular to the view"},
    {"ball_lens", "camera { orthographic eye [0, 0, 0.5] look_at [0, 0, 0] width 2 }\n" LENS SCREEN,
     "ball_lens: the camera must be in front of the sphere"},
    {"ball_lens", BALL_CAM LENS "plane { point [0, 0, -1] normal [0, 0, 1] }\n",
     "ball_lens: the screen must be behind the sphere, apart from it"},
    {"ball_lens", BALL_CAM "distant_light { direction [0, 0, -1] }\n" LENS SCREEN,
     "ball_lens: light 1 is not a point light"},
    {"ball_lens", BALL_CAM "point_light { position [0, 0, 3] }\n" LENS SCREEN,
     "ball_lens: point light 1 is not between the sphere and the screen"},
};

enum { REFUSAL_COUNT = sizeof refusals / sizeof refusals[0] };

START_TEST(test_oracle_optics_refuses_with_reason)
{
    assert_refused(refusals[_i].family, refusals[_i].text, refusals[_i].why);
}
END_TEST

Suite *suite_oracle_optics(void)
{
    Suite *s = suite_create("oracle_optics");
    TCase *tc = tcase_create("helpers");
    tcase_add_test(tc, test_optics_geometric_sum);
    tcase_add_test(tc, test_optics_slab_hit);
    tcase_add_test(tc, test_optics_slab_shift);
    tcase_add_test(tc, test_optics_ball_trace);
    tcase_add_test(tc, test_optics_ball_paraxial_focus);
    tcase_add_test(tc, test_optics_critical_sin);
    tcase_add_test(tc, test_optics_light_terms);
    tcase_add_test(tc, test_optics_spawn_offset);
    suite_add_tcase(s, tc);
    tc = tcase_create("closed_forms");
    tcase_add_test(tc, test_parallel_mirrors_closed_series);
    tcase_add_test(tc, test_parallel_mirrors_lit_straight_down);
    tcase_add_test(tc, test_parallel_mirrors_lit_oblique);
    tcase_add_test(tc, test_parallel_mirrors_horizon_is_ambiguous);
    tcase_add_test(tc, test_glass_slab_shift_seen);
    tcase_add_test(tc, test_glass_slab_light_above);
    tcase_add_test(tc, test_glass_slab_total_reflection);
    tcase_add_test(tc, test_snell_window_closed_series);
    tcase_add_test(tc, test_snell_window_critical_angle_is_ambiguous);
    tcase_add_test(tc, test_snell_window_lit);
    tcase_add_test(tc, test_ball_lens_sixty_degrees);
    tcase_add_test(tc, test_ball_lens_turns_back_and_depth);
    tcase_add_test(tc, test_ball_lens_outline_is_ambiguous);
    tcase_add_test(tc, test_ball_lens_focus_seen_by_the_tracer);
    suite_add_tcase(s, tc);
    tc = tcase_create("scenes");
    tcase_add_loop_test(tc, test_oracle_optics_image_matches_render, 0, SCENE_COUNT);
    tcase_add_test(tc, test_parallel_mirrors_far_from_origin);
    tcase_add_test(tc, test_ball_lens_rim_sensitivity);
    suite_add_tcase(s, tc);
    tc = tcase_create("refusals");
    tcase_add_loop_test(tc, test_oracle_optics_refuses_with_reason, 0, REFUSAL_COUNT);
    suite_add_tcase(s, tc);
    return s;
}
