/*
 * Tests of the local-shading and shadow families of the analytic oracle
 * (src/oracle/{ambient, lambert_sphere, plane_point, phong_plane,
 * phong_sphere, sphere_shadow, transparent_shadow, stacked_sheets}.c and
 * oracle_util.c; spec/analytic.md, one section per family):
 *   1. the helpers and each closed form against numbers worked out by hand
 *      in the comments (3-4-5 triangles and the like), at world points
 *      placed in the image with oracle_image_point;
 *   2. every scene of these families rendered by the tracer and compared
 *      with its exact image at 1e-9 relative, with a bound on the pixels
 *      excluded as ambiguous (ORACLE_REPORT=1 prints the measured errors);
 *   3. the Phong peaks: place (the mirror point, found analytically, is the
 *      brightest pixel of the tracer's highlight) and value;
 *   4. scenes outside a family's assumptions are refused with the reason.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "oracle_testlib.h"
#include "image/metrics.h"
#include "oracle/oracle.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"
#include "render/render.h"
#include "scene/scene.h"

/* Loads text as a scene of the given family (the `oracle` statement is
 * prepended). */
static scene_model *load_family(const char *family, const char *text)
{
    char *full = malloc(strlen(text) + 64);
    ck_assert_ptr_nonnull(full);
    snprintf(full, strlen(text) + 64, "oracle %s\n%s", family, text);
    scene_model *s = load_text(full);
    free(full);
    return s;
}

/* The image point where the camera sees world point p. */
static void image_point(const scene_model *s, vec3 p, double *x, double *y)
{
    oracle_view v = view_of(s);
    ck_assert(oracle_image_point(&v, p, x, y));
}

static oracle_status radiance_at_world(const scene_model *s, vec3 p, rgb *out)
{
    double x, y;
    image_point(s, p, &x, &y);
    return radiance_at(s, x, y, out);
}

/* The exact value where the camera sees p, which must not be ambiguous. */
static rgb exact_at_world(const scene_model *s, vec3 p)
{
    rgb c = vec_splat(-1);
    ck_assert_msg(radiance_at_world(s, p, &c) == ORACLE_EXACT, "ambiguous at (%g, %g, %g)", (double)p.x,
                  (double)p.y, (double)p.z);
    return c;
}

static int ambiguous_at_world(const scene_model *s, vec3 p)
{
    rgb c;
    return radiance_at_world(s, p, &c) == ORACLE_AMBIGUOUS;
}

#define ck_assert_rgb_rel(got, want, rel)                                                    \
    do {                                                                                     \
        rgb ck_g3_ = (got), ck_w3_ = (want);                                                 \
        ck_assert_rel(ck_g3_.x, ck_w3_.x, rel);                                              \
        ck_assert_rel(ck_g3_.y, ck_w3_.y, rel);                                              \
        ck_assert_rel(ck_g3_.z, ck_w3_.z, rel);                                              \
    } while (0)

/* An orthographic camera straight down on y = 0, 100 x 100, 10 wide:
 * world (x, 0, z) is image point (50 + 10x, 50 + 10z). */
#define DOWN_10 "image { width 100 height 100 max_depth 1 background 0 }\n" \
                "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n"
/* An orthographic camera along -z on a unit sphere, 100 x 100, 2 wide. */
#define FRONT_2 "image { width 100 height 100 max_depth 1 background [0.1, 0.2, 0.3] }\n" \
                "camera { orthographic eye [0, 0, 10] look_at [0, 0, 0] up [0, 1, 0] width 2 }\n"

/* ---- 1. helpers ---- */

START_TEST(test_oracle_falloff)
{
    /* E = 6, d = 2, d0 = 1: linear 6/3 = 2, inverse square 6/9, none 6. */
    ck_assert_near(oracle_falloff(vec_splat(6), 2, 1, FALLOFF_LINEAR).x, 2, 1e-15);
    ck_assert_near(oracle_falloff(vec_splat(6), 2, 1, FALLOFF_INVERSE_SQUARE).y, 6.0 / 9, 1e-15);
    ck_assert_near(oracle_falloff(vec_make(6, 5, 4), 2, 1, FALLOFF_NONE).z, 4, 0);
}
END_TEST

START_TEST(test_oracle_line_sphere)
{
    /* Unit sphere at the origin, line x = 0.6 along -z: off 0.6, half 0.8,
     * entry normal (0.6, 0, 0.8), exit normal (0.6, 0, -0.8). */
    vec3 d = vec_make(0, 0, -1), c = vec_splat(0);
    oracle_chord ch;
    ck_assert_int_eq(oracle_line_sphere(vec_make(0.6, 0, 5), d, c, 1, &ch), ORACLE_CHORD_HIT);
    ck_assert_near(ch.along, 5, 1e-15);
    ck_assert_near(ch.off, 0.6, 1e-15);
    ck_assert_near(ch.half, 0.8, 1e-15);
    ck_assert_vec_near(oracle_chord_normal(&ch, d, 1, 0), vec_make(0.6, 0, 0.8), 1e-15);
    ck_assert_vec_near(oracle_chord_normal(&ch, d, 1, 1), vec_make(0.6, 0, -0.8), 1e-15);
    ck_assert_int_eq(oracle_line_sphere(vec_make(1.5, 0, 5), d, c, 1, &ch), ORACLE_CHORD_MISS);
    ck_assert_int_eq(oracle_line_sphere(vec_make(0, 1, 5), d, c, 1, &ch), ORACLE_CHORD_GRAZE);
    ck_assert_int_eq(oracle_line_sphere(vec_make(0, 1 + 2e-6, 5), d, c, 1, &ch), ORACLE_CHORD_MISS);
}
END_TEST

START_TEST(test_oracle_path_distance)
{
    /* From the origin to a point light at (4, 0, 0): the centre (2, 1, 0) is
     * 1 from the segment; (6, 1, 0) is past its end, sqrt(5) from (4, 0, 0);
     * (-3, 4, 0) is before its start, 5 from the origin.  Toward a distant
     * light along +x the path never ends: (100, 2, 0) is 2 from it. */
    scene_light point = {0}, distant = {0};
    point.kind = LIGHT_POINT;
    point.position = vec_make(4, 0, 0);
    point.power = vec_splat(1);
    distant.kind = LIGHT_DISTANT;
    distant.direction = vec_make(-1, 0, 0);
    oracle_light_at la;
    vec3 o = vec_splat(0);
    ck_assert(oracle_light_toward(&point, o, &la));
    ck_assert_near(oracle_path_distance(o, &la, vec_make(2, 1, 0)), 1, 1e-15);
    ck_assert_near(oracle_path_distance(o, &la, vec_make(6, 1, 0)), sqrt(5.0), 1e-15);
    ck_assert_near(oracle_path_distance(o, &la, vec_make(-3, 4, 0)), 5, 1e-15);
    ck_assert(oracle_light_toward(&distant, o, &la));
    ck_assert_near(oracle_path_distance(o, &la, vec_make(100, 2, 0)), 2, 1e-13);
}
END_TEST

START_TEST(test_oracle_line_plane)
{
    double s = -1;
    ck_assert(oracle_line_plane(vec_make(0, 5, 0), vec_make(0, -1, 0), vec_make(3, 1, 7), vec_make(0, 1, 0), &s));
    ck_assert_near(s, 4, 1e-15);
    /* 45 degrees down from (0, 5, 0) to y = 1: 4 sqrt(2) along the ray. */
    ck_assert(oracle_line_plane(vec_make(0, 5, 0), vec_make(sqrt(0.5), -sqrt(0.5), 0), vec_splat(1), vec_make(0, 1, 0), &s));
    ck_assert_near(s, 4 * sqrt(2.0), 1e-14);
    ck_assert(!oracle_line_plane(vec_make(0, 5, 0), vec_make(1, 0, 0), vec_splat(0), vec_make(0, 1, 0), &s));
}
END_TEST

START_TEST(test_oracle_image_point)
{
    /* Perspective, eye (0, 0, 5) toward the origin, fov 90, 100 x 100: the
     * point (1, 0, 4) is 1 to the right at depth 1, tan 45 = 1: the right
     * edge, x = 100, y = 50.  (0, -0.5, 4): half way down, y = 75. */
    scene_model *s = load_text("image { width 100 height 100 }\ncamera { perspective eye [0, 0, 5] fov 90 }\nsphere { }\n");
    oracle_view v = view_of(s);
    double x, y;
    ck_assert(oracle_image_point(&v, vec_make(1, 0, 4), &x, &y));
    ck_assert_near(x, 100, 1e-12);
    ck_assert_near(y, 50, 1e-12);
    ck_assert(oracle_image_point(&v, vec_make(0, -0.5, 4), &x, &y));
    ck_assert_near(y, 75, 1e-12);
    ck_assert(!oracle_image_point(&v, vec_make(0, 0, 6), &x, &y));
    /* Round trip: the view ray through (x, y) passes through the point. */
    oracle_ray r = oracle_view_ray(&v, 12.25, 80.5);
    ck_assert(oracle_image_point(&v, vec_add(r.origin, vec_scale(r.dir, 3.7)), &x, &y));
    ck_assert_near(x, 12.25, 1e-12);
    ck_assert_near(y, 80.5, 1e-12);
    scene_free(s);
    /* Orthographic DOWN_10: world (2, 0, -3) is (50 + 20, 50 - 30). */
    s = load_text(DOWN_10 "plane { }\n");
    v = view_of(s);
    ck_assert(oracle_image_point(&v, vec_make(2, 0, -3), &x, &y));
    ck_assert_near(x, 70, 1e-12);
    ck_assert_near(y, 20, 1e-12);
    scene_free(s);
}
END_TEST

START_TEST(test_oracle_mirror_point)
{
    /* Eye (0, 4, 6), light (0, 2, -3) over y = 0: the mirror light is
     * (0, -2, -3); the eye's line to it, y = 4 - 6s, meets y = 0 at s = 2/3,
     * z = 6 - 9 * 2/3 = 0.  Eye (1, 1, 0), light (3, 2, 0): mirror (3, -2, 0),
     * s = 1/3, x = 5/3; check: from (5/3, 0) both rise with slope 3/2. */
    vec3 up = vec_make(0, 1, 0), o = vec_splat(0);
    ck_assert_vec_near(oracle_mirror_point(o, up, vec_make(0, 4, 6), vec_make(0, 2, -3)), o, 1e-15);
    ck_assert_vec_near(oracle_mirror_point(o, up, vec_make(1, 1, 0), vec_make(3, 2, 0)), vec_make(5.0 / 3, 0, 0),
                       1e-15);
}
END_TEST

START_TEST(test_oracle_mirror_point_ortho)
{
    /* Looking straight down (V = N): the foot of the light.  Looking down
     * at 45 degrees, f = (1, -1, 0)/sqrt2: V = (-1, 1, 0)/sqrt2, its mirror
     * about +y is m = (1, 1, 0)/sqrt2, so from the light (0, 2, 0) back
     * along m to y = 0: (-2, 0, 0). */
    vec3 up = vec_make(0, 1, 0), o = vec_splat(0);
    ck_assert_vec_near(oracle_mirror_point_ortho(o, up, vec_make(0, -1, 0), vec_make(1, 2, -1)), vec_make(1, 0, -1),
                       1e-15);
    ck_assert_vec_near(oracle_mirror_point_ortho(o, up, vec_make(sqrt(0.5), -sqrt(0.5), 0), vec_make(0, 2, 0)),
                       vec_make(-2, 0, 0), 1e-14);
}
END_TEST

START_TEST(test_oracle_phong_lobe)
{
    int amb = 0;
    ck_assert_near(oracle_phong_lobe(0.5, 2, &amb), 0.25, 0);
    ck_assert_near(oracle_phong_lobe(-0.1, 2, &amb), 0, 0);
    ck_assert_near(oracle_phong_lobe(1 + 1e-15, 300, &amb), 1, 0);
    ck_assert_int_eq(amb, 0);
    /* n < 1: max(0, c)^n jumps (n = 0) or is infinitely steep at c = 0. */
    oracle_phong_lobe(1e-8, 0.5, &amb);
    ck_assert_int_eq(amb, 1);
}
END_TEST

START_TEST(test_oracle_phong_sphere_peak)
{
    /* L = V = +z: the pole (0, 0, 2) of a sphere of radius 2.  L = +x,
     * V = +z: the half vector (1, 0, 1)/sqrt2, the point (sqrt2, 0, sqrt2). */
    vec3 z = vec_make(0, 0, 1);
    ck_assert_vec_near(oracle_phong_sphere_peak(vec_splat(0), 2, z, z), vec_make(0, 0, 2), 1e-15);
    ck_assert_vec_near(oracle_phong_sphere_peak(vec_splat(1), 2, vec_make(1, 0, 0), z),
                       vec_make(1 + sqrt(2.0), 1, 1 + sqrt(2.0)), 1e-15);
}
END_TEST

/* ---- 1. closed forms ---- */

START_TEST(test_ambient_radiance)
{
    /* [ORACLE-AMBIENT-1] Inside: Kd Ia = [0.5*0.2, 0.5*0.4, 1*0.6]; outside:
     * the background; the outline is ambiguous. */
    scene_model *s = load_family("ambient_only", FRONT_2 "ambient { color [0.2, 0.4, 0.6] }\n"
                                    "sphere { radius 0.9 material { Kd [0.5, 0.5, 1] } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.3, 0.5, 0)), vec_make(0.1, 0.2, 0.6), 1e-15);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.8, 0.5, 0)), vec_make(0.1, 0.2, 0.3), 0);
    ck_assert(ambiguous_at_world(s, vec_make(0.9, 0, 0)));
    scene_free(s);
    /* A perspective eye inside the sphere sees its inside everywhere. */
    s = load_family("ambient_only", "image { width 10 height 10 }\ncamera { perspective eye [0.1, 0, 0] look_at [1, 0, 0] }\n"
                  "ambient { color 1 }\nsphere { radius 2 material { Kd 0.25 } }\n");
    rgb c;
    ck_assert_int_eq(radiance_at(s, 0.5, 9.5, &c), ORACLE_EXACT);
    ck_assert_rgb_rel(c, vec_splat(0.25), 0);
    scene_free(s);
}
END_TEST

START_TEST(test_lambert_sphere_radiance)
{
    /* [ORACLE-LAMBERT-SPHERE-1] Screen point (0.6, 0) of a unit sphere:
     * N = (0.6, 0, sqrt(1 - 0.36)) = (0.6, 0, 0.8).  Kd 0.5, Ia 0.1.
     *   light along -z, E 2:   N.L = 0.8,  0.5 (0.1 + 1.6)       = 0.85
     *   plus light along -x, E 2: N.L = 0.6, 0.5 (0.1 + 1.6 + 1.2) = 1.45
     *   a point light at (0.6, 0, 5.8): d = 5, L = +z, linear E 10 -> I = 2:
     *                          0.5 (0.1 + 2 * 0.8)               = 0.85 */
    scene_model *s = load_family("lambert_sphere", FRONT_2 "ambient { color 0.1 }\ndistant_light { direction [0, 0, -1] power 2 }\n"
                                    "sphere { material { Kd 0.5 } }\n");
    vec3 p = vec_make(0.6, 0, 0);
    ck_assert_rgb_rel(exact_at_world(s, p), vec_splat(0.85), 1e-14);
    scene_free(s);
    s = load_family("lambert_sphere", FRONT_2 "ambient { color 0.1 }\ndistant_light { direction [0, 0, -1] power 2 }\n"
                          "distant_light { direction [-1, 0, 0] power 2 }\nsphere { material { Kd 0.5 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, p), vec_splat(1.45), 1e-14);
    /* The light along -x reaches only x > 0: at (-0.6, 0) only the first. */
    ck_assert_rgb_rel(exact_at_world(s, vec_make(-0.6, 0, 0)), vec_splat(0.85), 1e-14);
    /* Outside: background; the outline: ambiguous. */
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.9, 0.9, 0)), vec_make(0.1, 0.2, 0.3), 0);
    ck_assert(ambiguous_at_world(s, vec_make(0, 1, 0)));
    scene_free(s);
    s = load_family("lambert_sphere", FRONT_2 "ambient { color 0.1 }\npoint_light { position [0.6, 0, 5.8] power 10 }\n"
                          "sphere { material { Kd 0.5 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, p), vec_splat(0.85), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_lambert_sphere_terminator_is_ambiguous)
{
    /* Light along -x: the terminator is the great circle x = 0. */
    scene_model *s = load_family("lambert_sphere", FRONT_2 "distant_light { direction [-1, 0, 0] }\nsphere { }\n");
    ck_assert(ambiguous_at_world(s, vec_make(0, 0.3, 0)));
    ck_assert(!ambiguous_at_world(s, vec_make(0.01, 0.3, 0)));
    scene_free(s);
}
END_TEST

START_TEST(test_plane_point_radiance)
{
    /* [ORACLE-PLANE-POINT-1] Light at (0, 3, 0) over y = 0, the point
     * (4, 0, 0): d = 5, cos = 3/5.  Kd 0.5, Ia 0.1, E 10, d0 1:
     *   linear         0.5 (0.1 + 10/6 * 0.6)  = 0.55
     *   inverse_square 0.5 (0.1 + 10/36 * 0.6) = 0.5 (0.1 + 1/6)
     *   none           0.5 (0.1 + 10 * 0.6)    = 3.05 */
    const char *falloff[] = {"linear", "inverse_square", "none"};
    double want[] = {0.55, 0.5 * (0.1 + 1.0 / 6), 3.05};
    for (int k = 0; k < 3; k++) {
        char text[512];
        snprintf(text, sizeof text,
                 DOWN_10 "ambient { color 0.1 }\npoint_light { position [0, 3, 0] power 10 d0 1 falloff %s }\n"
                         "plane { material { Kd 0.5 } }\n",
                 falloff[k]);
        scene_model *s = load_family("plane_point", text);
        ck_assert_rgb_rel(exact_at_world(s, vec_make(4, 0, 0)), vec_splat(want[k]), 1e-14);
        scene_free(s);
    }
}
END_TEST

START_TEST(test_plane_point_radiance_perspective)
{
    /* The same plane seen from an eye at (4, 2, 6) (any route to the point
     * (4, 0, 0) gives the same value: a matte surface), and from below the
     * plane: the lit side is not seen, Kd Ia = 0.05 only. */
    scene_model *s = load_family("plane_point", "image { width 64 height 48 }\ncamera { perspective eye [4, 2, 6] look_at [4, 0, 0] }\n"
                            "ambient { color 0.1 }\npoint_light { position [0, 3, 0] power 10 d0 1 }\n"
                            "plane { material { Kd 0.5 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(4, 0, 0)), vec_splat(0.55), 1e-14);
    scene_free(s);
    s = load_family("plane_point", "image { width 64 height 48 }\ncamera { perspective eye [4, -2, 6] look_at [4, 0, 0] }\n"
                  "ambient { color 0.1 }\npoint_light { position [0, 3, 0] power 10 d0 1 }\n"
                  "plane { material { Kd 0.5 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(4, 0, 0)), vec_splat(0.05), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_phong_plane_radiance)
{
    /* [ORACLE-PHONG-PLANE-1] Straight down (V = N = +y), light (0, 3, 0),
     * E 10, linear, d0 0.  Kd 0.5, Ks 0.25, n 2, Ia 0.1.
     *   at (4, 0, 0): d = 5, I = 2, L = (-4, 3, 0)/5, N.L = 0.6,
     *     R = 2(0.6)N - L = (0.8, 0.6, 0), V.R = 0.6, lobe 0.36:
     *     0.5 (0.1 + 2*0.6) + 0.25 * 2 * 0.36 = 0.65 + 0.18 = 0.83
     *   at the foot (0, 0, 0): d = 3, I = 10/3, V.R = 1:
     *     0.5 (0.1 + 10/3) + 0.25 * 10/3                             */
    scene_model *s = load_family("phong_plane", DOWN_10 "ambient { color 0.1 }\npoint_light { position [0, 3, 0] power 10 }\n"
                                    "plane { material { Kd 0.5 Ks 0.25 n 2 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(4, 0, 0)), vec_splat(0.83), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0, 0, 0)), vec_splat(0.5 * (0.1 + 10.0 / 3) + 0.25 * 10.0 / 3),
                      1e-14);
    scene_free(s);
    /* max_depth 2 adds the mirror ray's background, Ks * 0.4 = 0.1. */
    s = load_family("phong_plane", "image { width 100 height 100 max_depth 2 background 0.4 }\n"
                  "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n"
                  "ambient { color 0.1 }\npoint_light { position [0, 3, 0] power 10 }\n"
                  "plane { material { Kd 0.5 Ks 0.25 n 2 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(4, 0, 0)), vec_splat(0.93), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_phong_sphere_radiance)
{
    /* [ORACLE-PHONG-SPHERE-1] Unit sphere, V = +z, light along -z (L = +z),
     * E 1, Kd 0.5, Ks 0.4, n 3, Ia 0.1.  At screen (0.6, 0): N = (0.6, 0, 0.8),
     * N.L = 0.8, V.R = 2(0.8)(0.8) - 1 = 0.28:
     *   0.5 (0.1 + 0.8) + 0.4 * 0.28^3 = 0.45 + 0.0087808
     * At the centre, N = L = V: 0.5 (0.1 + 1) + 0.4 = 0.95. */
    scene_model *s = load_family("phong_sphere", FRONT_2 "ambient { color 0.1 }\ndistant_light { direction [0, 0, -1] }\n"
                                    "sphere { material { Kd 0.5 Ks 0.4 n 3 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.6, 0, 0)), vec_splat(0.45 + 0.4 * 0.28 * 0.28 * 0.28), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0, 0, 0)), vec_splat(0.95), 1e-14);
    scene_free(s);
}
END_TEST

/* A unit sphere at (0, 2, 0) over y = 0, a point light at (0, 4, 0), E 8,
 * linear, d0 0, seen from straight above.  Kd 0.5 everywhere, Ia 0.1. */
#define SHADOW_SCENE(sphere_material) \
    DOWN_10 "ambient { color 0.1 }\npoint_light { position [0, 4, 0] power 8 }\n" \
            "plane { material { Kd 0.5 } }\nsphere { center [0, 2, 0] material { " sphere_material " } }\n"

START_TEST(test_sphere_shadow_radiance)
{
    /* [ORACLE-SPHERE-SHADOW-1] Plane point (3, 0, 0): the segment to the
     * light, direction (-3, 4)/5 in the xy plane, passes the centre at
     * |(-3, 2) - 3.4 (-0.6, 0.8)| = |(-0.96, -0.72)| = 1.2 > 1: lit; d = 5,
     * cos = 4/5: 0.5 (0.1 + 8/5 * 0.8) = 0.69.
     * (1.5, 0, 0): w = (-1.5, 2), along = 10.25/sqrt18.25, distance^2 =
     * 6.25 - 10.25^2/18.25 = 0.493 < 1: shadowed, 0.05.  (Nearer than 1 to
     * the axis the plane is hidden by the sphere; at 1 the view grazes it.)
     * The sphere's top (0, 3, 0) faces the light at d = 1: 0.5 (0.1 + 8). */
    scene_model *s = load_family("sphere_shadow", SHADOW_SCENE("Kd 0.5"));
    ck_assert_rgb_rel(exact_at_world(s, vec_make(3, 0, 0)), vec_splat(0.69), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(1.5, 0, 0)), vec_splat(0.05), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0, 0, 0)), vec_splat(4.05), 1e-14);
    ck_assert(ambiguous_at_world(s, vec_make(0, 0, 1)));
    scene_free(s);
}
END_TEST

START_TEST(test_sphere_shadow_boundary_is_ambiguous)
{
    /* [ORACLE-SPHERE-SHADOW-2] The tangents from (0, 4) to the unit circle
     * about (0, 2) make 30 degrees with the axis (sin = 1/2): they meet
     * y = 0 at x = 4 tan 30 = 4/sqrt3. */
    scene_model *s = load_family("sphere_shadow", SHADOW_SCENE("Kd 0.5"));
    double edge = 4 / sqrt(3.0);
    ck_assert(ambiguous_at_world(s, vec_make(edge, 0, 0)));
    ck_assert(ambiguous_at_world(s, vec_make(0, 0, -edge)));
    ck_assert_rgb_rel(exact_at_world(s, vec_make(edge - 1e-4, 0, 0)), vec_splat(0.05), 1e-14);
    ck_assert(exact_at_world(s, vec_make(edge + 1e-4, 0, 0)).x > 0.05);
    scene_free(s);
}
END_TEST

START_TEST(test_transparent_shadow_radiance)
{
    /* [ORACLE-TRANSPARENT-SHADOW-1] The same with t 0.5, ior 1, Kd 0.4 on
     * the sphere, Kd 0.5 on the plane, E 8 linear.
     *   plane (1.5, 0, 0), in the shadow: d^2 = 18.25, cos = 4/sqrt18.25,
     *     S = t^2:  0.5 (0.1 + 8/sqrt18.25 * 4/sqrt18.25 * 0.25)
     *             = 0.5 (0.1 + 8/18.25)
     *   plane (3, 0, 0), lit: 0.69 as before.
     * [ORACLE-TRANSPARENT-SHADOW-2] Straight down through the centre,
     * max_depth 5: entry (0, 3, 0), N.L = 1, d = 1, S = 1; exit (0, 1, 0),
     * inward N = +y, d = 3, S = t; then the plane (0, 0, 0), d = 4, S = t^2:
     *   L1 = 0.5 * 0.4 (0.1 + 8)          = 1.62
     *   L2 = 0.5 * 0.4 (0.1 + 8/3 * 0.5)  = 0.2 (0.1 + 4/3)
     *   C3 = 0.5 (0.1 + 2 * 0.25)         = 0.3
     *   C  = L1 + 0.5 (L2 + 0.5 C3)                                      */
    scene_model *s = load_family("transparent_shadow", "image { width 100 height 100 max_depth 5 background 0 }\n"
                            "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n"
                            "ambient { color 0.1 }\npoint_light { position [0, 4, 0] power 8 }\n"
                            "plane { material { Kd 0.5 } }\n"
                            "sphere { center [0, 2, 0] material { Kd 0.4 t 0.5 ior 1 } }\n");
    ck_assert_rgb_rel(exact_at_world(s, vec_make(1.5, 0, 0)), vec_splat(0.5 * (0.1 + 8 / 18.25)), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(3, 0, 0)), vec_splat(0.69), 1e-14);
    double l1 = 1.62, l2 = 0.2 * (0.1 + 4.0 / 3), c3 = 0.3;
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0, 0, 0)), vec_splat(l1 + 0.5 * (l2 + 0.5 * c3)), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_transparent_shadow_depth_cut)
{
    /* The ray through the centre with max_depth 1: L1 only; 2: L1 + t L2. */
    const char *head = "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n"
                       "ambient { color 0.1 }\npoint_light { position [0, 4, 0] power 8 }\n"
                       "plane { material { Kd 0.5 } }\n"
                       "sphere { center [0, 2, 0] material { Kd 0.4 t 0.5 ior 1 } }\n";
    double l1 = 1.62, l2 = 0.2 * (0.1 + 4.0 / 3), want[] = {l1, l1 + 0.5 * l2};
    for (int depth = 1; depth <= 2; depth++) {
        char text[1024];
        snprintf(text, sizeof text, "image { width 100 height 100 max_depth %d }\n%s", depth, head);
        scene_model *s = load_family("transparent_shadow", text);
        ck_assert_rgb_rel(exact_at_world(s, vec_make(0, 0, 0)), vec_splat(want[depth - 1]), 1e-14);
        scene_free(s);
    }
}
END_TEST

/* Floor y = 0 (Kd 0.8), a plane sheet at y = 2 (t 0.5, Kd 0.2), a disk of
 * radius 1 about (0, 1, 0) (t 0.25, Kd 0.6), seen from straight above, Ia 0.1. */
#define SHEETS(light, depth) \
    "image { width 100 height 100 max_depth " depth " }\n" \
    "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n" \
    "ambient { color 0.1 }\n" light "\nplane { material { Kd 0.8 } }\n" \
    "plane { point [0, 2, 0] material { Kd 0.2 t 0.5 } }\n" \
    "disk { center [0, 1, 0] radius 1 material { Kd 0.6 t 0.25 } }\n"

START_TEST(test_stacked_sheets_radiance_light_above)
{
    /* [ORACLE-STACKED-SHEETS-1] Light straight down, E 1.
     * Through the disk: B_A = 0.2 (0.1 + 1) = 0.22, local 0.5 * 0.22 = 0.11;
     *   B_B = 0.6 (0.1 + 0.5) = 0.36, local 0.75 * 0.36 = 0.27;
     *   B_F = 0.8 (0.1 + 0.5 * 0.25) = 0.18;
     *   C = 0.11 + 0.5 * 0.27 + 0.5 * 0.25 * 0.18 = 0.2675.
     * Beside the disk (3, 0, 0): C = 0.11 + 0.5 * 0.8 (0.1 + 0.5) = 0.35. */
    scene_model *s = load_family("stacked_sheets", SHEETS("distant_light { direction [0, -1, 0] }", "5"));
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.3, 0, 0.2)), vec_splat(0.2675), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(3, 0, 0)), vec_splat(0.35), 1e-14);
    ck_assert(ambiguous_at_world(s, vec_make(1, 0, 0)));
    scene_free(s);
}
END_TEST

START_TEST(test_stacked_sheets_radiance_slanted_light)
{
    /* [ORACLE-STACKED-SHEETS-2] Light along (-1, -1, 0): L = (1, 1, 0)/sqrt2,
     * c = N.L = 1/sqrt2.  At x = 0.5 the view crosses the disk; from the
     * disk the path rises to y = 2 (the plane sheet: S = 0.5); from the floor
     * it crosses y = 1 at x = 1.5, outside the disk, then the plane: S = 0.5.
     *   C = 0.5 B_A + 0.5 * 0.75 B_B + 0.5 * 0.25 B_F
     *   B_A = 0.2 (0.1 + c), B_B = 0.6 (0.1 + 0.5c), B_F = 0.8 (0.1 + 0.5c).
     * At x = -1.5 (beside the disk) the floor's path crosses y = 1 at -0.5,
     * inside: S = 0.25 * 0.5:  C = 0.5 B_A + 0.5 * 0.8 (0.1 + 0.125c).
     * max_depth 2 stops at the disk: C = 0.5 B_A + 0.5 * 0.75 B_B. */
    double c = sqrt(0.5), ba = 0.2 * (0.1 + c), bb = 0.6 * (0.1 + 0.5 * c), bf = 0.8 * (0.1 + 0.5 * c);
    scene_model *s = load_family("stacked_sheets", SHEETS("distant_light { direction [-1, -1, 0] }", "5"));
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.5, 0, 0)), vec_splat(0.5 * ba + 0.375 * bb + 0.125 * bf), 1e-14);
    ck_assert_rgb_rel(exact_at_world(s, vec_make(-1.5, 0, 0)), vec_splat(0.5 * ba + 0.4 * (0.1 + 0.125 * c)), 1e-14);
    /* The floor's path at x = -2 grazes the rim (crosses y = 1 at x = -1). */
    ck_assert(ambiguous_at_world(s, vec_make(-2, 0, 0)));
    scene_free(s);
    s = load_family("stacked_sheets", SHEETS("distant_light { direction [-1, -1, 0] }", "2"));
    ck_assert_rgb_rel(exact_at_world(s, vec_make(0.5, 0, 0)), vec_splat(0.5 * ba + 0.375 * bb), 1e-14);
    scene_free(s);
}
END_TEST

/* ---- 2. every scene of these families against the tracer ---- */

typedef struct scene_case {
    const char *path;
    const char *family;
    long max_excluded;   /* pixels with an ambiguous sample point */
} scene_case;

static const scene_case scenes[] = {
    {"scenes/analytic/ambient_only.scene", "ambient_only", 10},
    {"scenes/analytic/lambert_sphere.scene", "lambert_sphere", 10},
    {"scenes/analytic/plane_point_linear.scene", "plane_point", 0},
    {"scenes/analytic/plane_point_inverse_square.scene", "plane_point", 0},
    {"scenes/analytic/phong_plane.scene", "phong_plane", 0},
    {"scenes/analytic/phong_plane_perspective.scene", "phong_plane", 0},
    {"scenes/analytic/phong_sphere.scene", "phong_sphere", 10},
    {"scenes/analytic/sphere_shadow.scene", "sphere_shadow", 10},
    {"scenes/analytic/sphere_shadow_two_lights.scene", "sphere_shadow", 10},
    {"scenes/analytic/transparent_shadow.scene", "transparent_shadow", 10},
    {"scenes/analytic/transparent_shadow_depth2.scene", "transparent_shadow", 10},
    {"scenes/analytic/stacked_sheets.scene", "stacked_sheets", 10},
    {"scenes/analytic/stacked_sheets_cut.scene", "stacked_sheets", 10},
    {"scenes/analytic/lambert_cylinder.scene", "lambert_cylinder", 10},
    {"scenes/analytic/lambert_cone.scene", "lambert_cone", 20},
    {"scenes/analytic/lambert_cone_apex.scene", "lambert_cone", 10},
    {"scenes/analytic/lambert_torus.scene", "lambert_torus", 20},
    {"scenes/analytic/lambert_torus_edge.scene", "lambert_torus", 20},
};

enum { SCENE_COUNT = sizeof scenes / sizeof scenes[0] };

/* The spread of the exact image over its compared pixels: a test must not
 * pass on a blank picture. */
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

static void report(const scene_case *sc, const image_metrics *m, long excluded)
{
    if (getenv("ORACLE_REPORT"))
        printf("%-52s max_rel %.3e  max_abs %.3e  over %ld  excluded %ld of %ld\n", sc->path, m->max_rel, m->max_abs,
               m->over, excluded, m->compared + m->excluded);
}

START_TEST(test_oracle_image_matches_render)
{
    const scene_case *sc = &scenes[_i];
    scene_model *s = load_file(sc->path);
    ck_assert_str_eq(s->oracle, sc->family);
    const oracle_family *f = family_of(s);
    oracle_view v = view_of(s);
    img_buf traced, exact;
    unsigned char *excluded = calloc((size_t)v.width * (size_t)v.height, 1);
    long count = -1;
    image_metrics m;
    ck_assert_ptr_nonnull(excluded);
    ck_assert_int_eq(render_image(s, NULL, &traced, NULL), STATUS_OK);
    ck_assert_int_eq(oracle_image(f, &v, &exact, excluded, &count), STATUS_OK);
    metrics_compare(&traced, &exact, excluded, f->tolerance(&v, 0), &m);
    report(sc, &m, count);
    ck_assert_msg(m.over == 0, "%s: %ld pixels over %g; max rel %.3e, worst pixel (%d, %d)", sc->path, m.over,
                  f->tolerance(&v, 0), m.max_rel, m.worst_x, m.worst_y);
    ck_assert_msg(count <= sc->max_excluded, "%s: %ld pixels excluded (bound %ld)", sc->path, count, sc->max_excluded);
    ck_assert_double_eq(f->tolerance(&v, 0), 1e-9);
    ck_assert_msg(spread(&exact, excluded) > 0.05, "%s: the exact image is nearly flat", sc->path);
    img_free(&traced);
    img_free(&exact);
    free(excluded);
    scene_free(s);
}
END_TEST

/* ---- 3. Phong peaks: place and value ---- */

/* The pixel of the largest first channel of img. */
static void brightest(const img_buf *img, int *bi, int *bj)
{
    double best = -HUGE_VAL;
    for (int j = 0; j < img->height; j++)
        for (int i = 0; i < img->width; i++)
            if (img_pixel((img_buf *)img, i, j)[0] > best) {
                best = img_pixel((img_buf *)img, i, j)[0];
                *bi = i;
                *bj = j;
            }
}

/* Renders s with every Kd and the ambient set to 0 and the background
 * black, so that only the highlight is left, and with every falloff
 * switched off unless keep_falloff: then the highlight is Ks E max(0, V.R)^n,
 * largest exactly where V.R is.  Returns its brightest pixel.  (With the
 * falloff, I(d) tilts the peak toward the light's foot.) */
static void highlight_peak(const char *path, int keep_falloff, int *bi, int *bj)
{
    scene_model *s = load_file(path);
    img_buf img;
    for (int k = 0; k < s->material_count; k++)
        s->materials[k].kd = vec_splat(0);
    for (int k = 0; k < s->light_count && !keep_falloff; k++)
        s->lights[k].falloff = FALLOFF_NONE;
    s->ambient = vec_splat(0);
    s->image.background = vec_splat(0);
    ck_assert_int_eq(render_image(s, NULL, &img, NULL), STATUS_OK);
    brightest(&img, bi, bj);
    img_free(&img);
    scene_free(s);
}

static double traced_pixel(const scene_model *s, int i, int j)
{
    img_buf img;
    ck_assert_int_eq(render_image(s, NULL, &img, NULL), STATUS_OK);
    double value = img_pixel(&img, i, j)[0];
    img_free(&img);
    return value;
}

/* The sample point of pixel (i, j) with samples 1 is its centre. */
static void assert_pixel_centre(double x, double y, int i, int j)
{
    ck_assert_near(x, i + 0.5, 1e-9);
    ck_assert_near(y, j + 0.5, 1e-9);
}

START_TEST(test_phong_plane_peak_orthographic)
{
    /* [ORACLE-PHONG-PLANE-2] Camera along -N: the mirror point is the foot of
     * the light [1, 0, -1], the centre of pixel (50, 20).  Value there
     * (scene header): 0.3 (0.05 + 1) + 0.6 * 1 + 0.6 * 0.1 = 0.975. */
    scene_model *s = load_file("scenes/analytic/phong_plane.scene");
    vec3 f, r, u;
    oracle_camera_frame(&s->camera, &f, &r, &u);
    vec3 m = oracle_mirror_point_ortho(s->prims[0].u.plane.point, s->prims[0].u.plane.normal, f, s->lights[0].position);
    ck_assert_vec_near(m, vec_make(1, 0, -1), 1e-15);
    double x, y;
    int bi = -1, bj = -1;
    image_point(s, m, &x, &y);
    assert_pixel_centre(x, y, 50, 20);
    ck_assert_rgb_rel(exact_at_world(s, m), vec_splat(0.975), 1e-14);
    ck_assert_rel(traced_pixel(s, 50, 20), 0.975, 1e-12);
    /* Straight down, I(d) also peaks at the foot: with or without falloff. */
    for (int keep = 0; keep <= 1; keep++) {
        highlight_peak("scenes/analytic/phong_plane.scene", keep, &bi, &bj);
        ck_assert_int_eq(bi, 50);
        ck_assert_int_eq(bj, 20);
    }
    scene_free(s);
}
END_TEST

START_TEST(test_phong_plane_peak_perspective)
{
    /* [ORACLE-PHONG-PLANE-2] The eye-to-mirror-light line meets the plane at
     * the origin, the image centre: pixel (40, 30).  There I = 13/13 = 1,
     * N.L = 2/sqrt13: 0.4 (0.1 + 2/sqrt13) + 0.5. */
    scene_model *s = load_file("scenes/analytic/phong_plane_perspective.scene");
    vec3 m = oracle_mirror_point(s->prims[0].u.plane.point, s->prims[0].u.plane.normal, s->camera.eye,
                                 s->lights[0].position);
    double x, y, want = 0.4 * (0.1 + 2 / sqrt(13.0)) + 0.5;
    int bi = -1, bj = -1;
    ck_assert_vec_near(m, vec_splat(0), 1e-15);
    image_point(s, m, &x, &y);
    assert_pixel_centre(x, y, 40, 30);
    ck_assert_rgb_rel(exact_at_world(s, m), vec_splat(want), 1e-14);
    ck_assert_rel(traced_pixel(s, 40, 30), want, 1e-12);
    highlight_peak("scenes/analytic/phong_plane_perspective.scene", 0, &bi, &bj);
    ck_assert_int_eq(bi, 40);
    ck_assert_int_eq(bj, 30);
    /* With the inverse-square falloff the product I(d) lobe peaks nearer the
     * light's foot (0, 0, -3), which lies up the image: one row up. */
    highlight_peak("scenes/analytic/phong_plane_perspective.scene", 1, &bi, &bj);
    ck_assert_int_eq(bi, 40);
    ck_assert_int_eq(bj, 29);
    scene_free(s);
}
END_TEST

START_TEST(test_phong_sphere_peak)
{
    /* [ORACLE-PHONG-SPHERE-2] Peak at c + r normalize(L + V) = [0.36, 0.48,
     * 0.8], the centre of pixel (52, 21); value 0.87 (scene header). */
    scene_model *s = load_file("scenes/analytic/phong_sphere.scene");
    vec3 p = oracle_phong_sphere_peak(s->prims[0].u.sphere.center, s->prims[0].u.sphere.radius,
                                      vec_neg(s->lights[0].direction), vec_neg(s->camera.forward));
    double x, y;
    int bi = -1, bj = -1;
    ck_assert_vec_near(p, vec_make(0.36, 0.48, 0.8), 1e-12);
    image_point(s, p, &x, &y);
    assert_pixel_centre(x, y, 52, 21);
    ck_assert_rgb_rel(exact_at_world(s, p), vec_splat(0.87), 1e-12);
    ck_assert_rel(traced_pixel(s, 52, 21), 0.87, 1e-12);
    highlight_peak("scenes/analytic/phong_sphere.scene", 1, &bi, &bj);
    ck_assert_int_eq(bi, 52);
    ck_assert_int_eq(bj, 21);
    scene_free(s);
}
END_TEST

/* ---- 4. refusals ---- */

typedef struct refusal {
    const char *family;
    const char *text;
    const char *why;
} refusal;

#define ORTHO_FRONT "camera { orthographic eye [0, 0, 10] width 4 }\n"
#define PERSP_HIGH "camera { perspective eye [0, 5, 5] look_at [0, 0, 0] }\n"

static const refusal refusals[] = {
    {"ambient_only", ORTHO_FRONT "point_light { position [0, 0, 5] }\nsphere { }\n",
     "ambient_only: the scene must have no lights (it has 1)"},
    {"ambient_only", ORTHO_FRONT "sphere { material { Ks 0.1 } }\n",
     "ambient_only: the sphere's material must have Ks = 0 and t = 0"},
    {"lambert_sphere", PERSP_HIGH "sphere { }\n", "lambert_sphere: the camera must be orthographic"},
    {"lambert_sphere", "camera { orthographic eye [0, 0, 0.5] look_at [0, 0, 0] }\nsphere { }\n",
     "lambert_sphere: the sphere must lie wholly in front of the camera's image plane"},
    {"lambert_sphere", ORTHO_FRONT "distributed_light { disk [0, 0, 5] [0, 0, -1] 1 }\nsphere { }\n",
     "lambert_sphere: light 1 is distributed (only point and distant lights have an exact image here)"},
    {"lambert_sphere", ORTHO_FRONT "point_light { position [0, 0, 0.5] }\nsphere { }\n",
     "lambert_sphere: point light 1 is inside or on the sphere"},
    {"lambert_sphere", ORTHO_FRONT "sphere { scale [1, 2, 1] }\n",
     "lambert_sphere: primitive 1 keeps a transform (an ellipsoid, a mirrored or turned shape)"},
    {"plane_point", PERSP_HIGH "point_light { position [3, 0, 1] }\nplane { }\n",
     "plane_point: point light 1 lies in the plane"},
    {"plane_point", PERSP_HIGH "plane { material { Ks 0.5 } }\n",
     "plane_point: the plane's material must have Ks = 0 and t = 0"},
    {"phong_plane", PERSP_HIGH "plane { material { t 0.5 } }\n",
     "phong_plane: the plane's material must be opaque (t = 0)"},
    {"phong_plane", PERSP_HIGH "plane { }\nsphere { }\n", "phong_plane: the scene must be one plane"},
    {"phong_sphere", ORTHO_FRONT "sphere { material { t 0.2 } }\n",
     "phong_sphere: the sphere's material must be opaque (t = 0)"},
    {"sphere_shadow", PERSP_HIGH "plane { }\nsphere { center [0, 0.5, 0] }\n",
     "sphere_shadow: the sphere touches or cuts the plane"},
    {"sphere_shadow", PERSP_HIGH "point_light { position [0, -1, 0] }\nplane { }\nsphere { center [0, 2, 0] }\n",
     "sphere_shadow: point light 1 is not on the sphere's side of the plane"},
    {"sphere_shadow", PERSP_HIGH "distant_light { direction [0, 1, 0] }\nplane { }\nsphere { center [0, 2, 0] }\n",
     "sphere_shadow: distant light 1 does not shine from the sphere's side of the plane"},
    {"sphere_shadow", "camera { eye [0, -3, 0] look_at [0, 0, 0] up [0, 0, 1] }\nplane { }\nsphere { center [0, 2, 0] }\n",
     "sphere_shadow: the eye is not on the sphere's side of the plane"},
    {"sphere_shadow", "camera { eye [0, 2.5, 0] look_at [0, 0, 0] up [0, 0, 1] }\nplane { }\nsphere { center [0, 2, 0] }\n",
     "sphere_shadow: the eye is inside the sphere"},
    {"sphere_shadow", PERSP_HIGH "plane { }\nsphere { center [0, 2, 0] material { t 0.5 } }\n",
     "sphere_shadow: the sphere's material must have Ks = 0 and t = 0"},
    {"transparent_shadow", PERSP_HIGH "plane { }\nsphere { center [0, 2, 0] material { t 0.5 ior 1.5 } }\n",
     "transparent_shadow: the sphere's material must have t > 0, ior 1 and Ks = 0"},
    {"transparent_shadow", PERSP_HIGH "plane { }\nsphere { center [0, 2, 0] }\nsphere { center [3, 2, 0] }\n",
     "transparent_shadow: the scene must be one sphere and one plane"},
    {"stacked_sheets", "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, 1] }\n"
                       "plane { }\ndisk { center [0, 1, 0] normal [0, 1, 0.1] }\n",
     "stacked_sheets: sheet 2 is not parallel to the others"},
    {"stacked_sheets", "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, 1] }\n"
                       "plane { material { t 0.5 } }\ndisk { center [0, 1, 0] }\n",
     "stacked_sheets: the lowest surface must be an opaque plane (t = 0)"},
    {"stacked_sheets", "camera { orthographic eye [0, 10, 1] look_at [0, 0, 0] up [0, 0, 1] }\n"
                       "plane { }\ndisk { center [0, 1, 0] }\n",
     "stacked_sheets: an orthographic camera must look straight down at the sheets"},
    {"stacked_sheets", "camera { eye [0, 10, 1] look_at [0, 0, 0] }\n"
                       "plane { }\ndisk { center [0, 1, 0] material { Ks 0.2 } }\n",
     "stacked_sheets: primitive 2 has Ks > 0 (mirror rays)"},
    {"stacked_sheets", "camera { eye [0, 10, 1] look_at [0, 0, 0] }\npoint_light { position [2, 1, 0] }\n"
                       "plane { }\ndisk { center [0, 1, 0] }\n",
     "stacked_sheets: point light 1 lies in the plane of primitive 2"},
    {"stacked_sheets", "camera { eye [0, 10, 1] look_at [0, 0, 0] }\n"
                       "plane { }\ndisk { center [0, 1, 0] }\ndisk { center [3, 1, 0] }\n",
     "stacked_sheets: primitives 2 and 3 lie at the same height"},
    {"lambert_cylinder", FRONT_2 "cylinder { open }\n",
     "lambert_cylinder: the cylinder must be closed (an open one shows, and shadows, its inside)"},
    {"lambert_cylinder", "cylinder { }\n", "lambert_cylinder: the camera must be orthographic"},
    {"lambert_cylinder", FRONT_2 "cylinder { }\nsphere { center [5, 0, 0] }\n",
     "lambert_cylinder: the scene must be one cylinder"},
    {"lambert_cylinder", FRONT_2 "point_light { position [0, 0.5, 0.5] }\ncylinder { }\n",
     "lambert_cylinder: point light 1 is inside the ball around the cylinder"},
    {"lambert_cylinder", FRONT_2 "cylinder { material { Ks 0.5 } }\n",
     "lambert_cylinder: the material must have Ks = 0 and t = 0"},
    {"lambert_cone", FRONT_2 "cone { radii 0.5 0.5 }\n",
     "lambert_cone: the radii are equal: that is a cylinder (family lambert_cylinder)"},
    {"lambert_cone", "camera { orthographic eye [0, 0, 0.9] }\ncone { }\n",
     "lambert_cone: the cone must lie wholly in front of the camera's image plane"},
    {"lambert_torus", FRONT_2 "point_light { position [5, 5, 5] }\ntorus { }\n",
     "lambert_torus: light 1 is a point light (distant lights only)"},
    {"lambert_torus", FRONT_2 "torus { scale [1, 2, 1] }\n",
     "lambert_torus: primitive 1 keeps a transform (an ellipsoid, a mirrored or turned shape)"},
};

enum { REFUSAL_COUNT = sizeof refusals / sizeof refusals[0] };

START_TEST(test_oracle_accepts_refuses_with_reason)
{
    assert_refused(refusals[_i].family, refusals[_i].text, refusals[_i].why);
}
END_TEST

Suite *suite_oracle_local(void)
{
    Suite *s = suite_create("oracle_local");
    TCase *tc = tcase_create("helpers");
    tcase_add_test(tc, test_oracle_falloff);
    tcase_add_test(tc, test_oracle_line_sphere);
    tcase_add_test(tc, test_oracle_path_distance);
    tcase_add_test(tc, test_oracle_line_plane);
    tcase_add_test(tc, test_oracle_image_point);
    tcase_add_test(tc, test_oracle_mirror_point);
    tcase_add_test(tc, test_oracle_mirror_point_ortho);
    tcase_add_test(tc, test_oracle_phong_lobe);
    tcase_add_test(tc, test_oracle_phong_sphere_peak);
    suite_add_tcase(s, tc);
    tc = tcase_create("closed_forms");
    tcase_add_test(tc, test_ambient_radiance);
    tcase_add_test(tc, test_lambert_sphere_radiance);
    tcase_add_test(tc, test_lambert_sphere_terminator_is_ambiguous);
    tcase_add_test(tc, test_plane_point_radiance);
    tcase_add_test(tc, test_plane_point_radiance_perspective);
    tcase_add_test(tc, test_phong_plane_radiance);
    tcase_add_test(tc, test_phong_sphere_radiance);
    tcase_add_test(tc, test_sphere_shadow_radiance);
    tcase_add_test(tc, test_sphere_shadow_boundary_is_ambiguous);
    tcase_add_test(tc, test_transparent_shadow_radiance);
    tcase_add_test(tc, test_transparent_shadow_depth_cut);
    tcase_add_test(tc, test_stacked_sheets_radiance_light_above);
    tcase_add_test(tc, test_stacked_sheets_radiance_slanted_light);
    suite_add_tcase(s, tc);
    tc = tcase_create("scenes");
    tcase_add_loop_test(tc, test_oracle_image_matches_render, 0, SCENE_COUNT);
    tcase_add_test(tc, test_phong_plane_peak_orthographic);
    tcase_add_test(tc, test_phong_plane_peak_perspective);
    tcase_add_test(tc, test_phong_sphere_peak);
    suite_add_tcase(s, tc);
    tc = tcase_create("refusals");
    tcase_add_loop_test(tc, test_oracle_accepts_refuses_with_reason, 0, REFUSAL_COUNT);
    suite_add_tcase(s, tc);
    return s;
}
