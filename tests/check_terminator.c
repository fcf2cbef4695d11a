/*
 * The shadow terminator of smooth meshes (spec/shading.md,
 * [SHADE-TERMINATOR-1]): shadow rays of a triangle with vertex normals
 * start from Hanika's lifted point, so a convex smooth mesh never shadows
 * itself where its shading normal faces the light.  The "before" (shadow
 * rays from the flat facet, tracer.terminator_offset = 0) is rendered too
 * and must show the artefact; `make terminator` measures it against the
 * exact Lambert image.
 */
#include <string.h>
#include "io/scene_file.h"
#include "testlib.h"
#include "render/intersect.h"
#include "render/render.h"
#include "render/trace.h"
#include "scene/scene.h"

/* A flat triangle whose vertex normals all equal its geometric normal:
 * the lifted point is the hit point itself, bit for bit. */
START_TEST(test_terminator_flat_triangle_is_not_lifted)
{
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_TRIANGLE;
    p.mesh = -1;
    p.u.triangle.p[0] = vec_make(0.3, -1, 2);
    p.u.triangle.p[1] = vec_make(2, 0.5, 2);
    p.u.triangle.p[2] = vec_make(-0.7, 1.1, 2);
    vec3 n[3];
    for (int i = 0; i < 3; i++)
        n[i] = vec_make(0, 0, 1);
    p.u.triangle.n = n;
    ray r = {vec_make(0.4, 0.2, 5), vec_make(0.01, -0.02, -1), 0, HUGE_VAL};
    hit h;
    ck_assert(isect_prim(&p, &r, &h));
    vec3 q = isect_shadow_point(&p, &h);
    ck_assert(q.x == h.point.x && q.y == h.point.y && q.z == h.point.z);
}
END_TEST

/* A facet of a sphere of radius 1: its corners on the sphere, their
 * normals the sphere's.  At a corner the lifted point is the corner; at
 * the centroid each corner's tangent plane lifts it by (b_i = 1/3)
 *   sum_i b_i max(0, -(p - v_i).n_i) n_i,
 * worked out here in long double; the result lies above the facet. */
START_TEST(test_terminator_lift_on_a_sphere_facet)
{
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_TRIANGLE;
    p.mesh = -1;
    static const double corner[3][3] = {{0.8, 0.6, 0}, {0.6, 0.8, 0}, {0.6, 0.6, 0.5291502622129181}};
    vec3 normals[3];
    for (int i = 0; i < 3; i++) {
        vec3 v = vec_make(corner[i][0], corner[i][1], corner[i][2]);
        p.u.triangle.p[i] = vec_normalize(v);
        normals[i] = vec_normalize(v);
    }
    p.u.triangle.n = normals;
    vec3 c = vec_scale(vec_add(p.u.triangle.p[0], vec_add(p.u.triangle.p[1], p.u.triangle.p[2])), 1.0 / 3);
    ray r = {vec_scale(c, 3), vec_normalize(vec_neg(c)), 0, HUGE_VAL};
    hit h;
    ck_assert(isect_prim(&p, &r, &h));
    vec3 q = isect_shadow_point(&p, &h);
    long double want[3] = {h.point.x, h.point.y, h.point.z}, b[3] = {1 - h.b1 - h.b2, h.b1, h.b2};
    for (int i = 0; i < 3; i++) {
        const vec3 *v = &p.u.triangle.p[i], *n = &p.u.triangle.n[i];
        long double d = ((long double)h.point.x - v->x) * n->x + ((long double)h.point.y - v->y) * n->y +
                        ((long double)h.point.z - v->z) * n->z;
        if (d < 0) {
            want[0] -= b[i] * d * n->x;
            want[1] -= b[i] * d * n->y;
            want[2] -= b[i] * d * n->z;
        }
    }
    ck_assert_near(q.x, (double)want[0], 1e-15);
    ck_assert_near(q.y, (double)want[1], 1e-15);
    ck_assert_near(q.z, (double)want[2], 1e-15);
    vec3 facet_n = vec_normalize(vec_cross(vec_sub(p.u.triangle.p[1], p.u.triangle.p[0]),
                                           vec_sub(p.u.triangle.p[2], p.u.triangle.p[0])));
    double lift = fabs(vec_dot(vec_sub(q, h.point), facet_n));
    ck_assert(lift > 1e-3);
    /* At a corner (weights 1, 0, 0): no lift, the corner itself. */
    h.point = p.u.triangle.p[0];
    h.b1 = h.b2 = 0;
    q = isect_shadow_point(&p, &h);
    ck_assert(q.x == h.point.x && q.y == h.point.y && q.z == h.point.z);
}
END_TEST

/* The smooth 12x8 sphere under a light from above, rendered three ways:
 * without shadow rays, with them from the facet, with them from the lifted
 * point.  A convex mesh cannot shadow itself where it faces the light, so
 * every pixel where a render with shadow rays differs from the one without
 * is the artefact. */
static int self_shadowed_pixels(int offset)
{
    static const char text[] = "image { width 64 height 48 samples 1 max_depth 1 }\n"
                               "camera { orthographic eye [0, 0, 10] look_at [0, 0, 0] up [0, 1, 0] width 3.2 }\n"
                               "ambient { color 0.1 }\n"
                               "distant_light { direction [0.2, -1, 0.25] power 1 }\n"
                               "mesh { file \"models/sphere_12x8.obj\" scale 1.2 material { Kd 0.8 } }\n";
    int status, count = 0;
    scene_model *s = scene_file_load_text("scenes/t.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_ptr_nonnull(s);
    tracer with, without;
    ck_assert(tracer_init(&with, s, 0, 0) && tracer_init(&without, s, 0, 0));
    ck_assert_int_eq(with.terminator_offset, 1);
    with.terminator_offset = offset;
    without.shadows = 0;
    for (int j = 0; j < 48; j++)
        for (int i = 0; i < 64; i++) {
            trace_stats st;
            memset(&st, 0, sizeof st);
            rgb a = render_pixel(&with, 64, 48, 1, i, j, &st), b = render_pixel(&without, 64, 48, 1, i, j, &st);
            count += a.x != b.x;
        }
    tracer_free(&with);
    tracer_free(&without);
    scene_free(s);
    return count;
}

START_TEST(test_terminator_smooth_sphere_does_not_shadow_itself)
{
    /* [SHADE-TERMINATOR-1] After: none.  Before: the stair steps. */
    ck_assert_int_eq(self_shadowed_pixels(1), 0);
    ck_assert_int_gt(self_shadowed_pixels(0), 30);
}
END_TEST

/* [SHADE-TERMINATOR-1] render_opts.facet_shadows (make difftest's way of
 * comparing with POV-Ray, spec/crosscheck.md [XCHK-MAP-MESH-3]) renders
 * what a tracer with the offset off renders, pixel for pixel; without it,
 * what the default tracer renders; and the two differ (the stair steps). */
START_TEST(test_terminator_facet_shadows_option)
{
    static const char text[] = "image { width 32 height 24 samples 1 max_depth 1 }\n"
                               "camera { orthographic eye [0, 0, 10] look_at [0, 0, 0] up [0, 1, 0] width 3.2 }\n"
                               "distant_light { direction [0.2, -1, 0.25] power 1 }\n"
                               "mesh { file \"models/sphere_12x8.obj\" scale 1.2 material { Kd 0.8 } }\n";
    int status, differ = 0;
    scene_model *s = scene_file_load_text("scenes/t.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_ptr_nonnull(s);
    img_buf img[2];
    for (int facet = 0; facet <= 1; facet++) {
        render_opts o;
        tracer t;
        memset(&o, 0, sizeof o);
        o.facet_shadows = facet;
        ck_assert_int_eq(render_image(s, &o, &img[facet], NULL), STATUS_OK);
        ck_assert(tracer_init(&t, s, 0, 0));
        t.terminator_offset = !facet;
        for (int j = 0; j < 24; j++)
            for (int i = 0; i < 32; i++) {
                trace_stats st;
                memset(&st, 0, sizeof st);
                rgb a = render_pixel(&t, 32, 24, 1, i, j, &st);
                const double *px = img_pixel(&img[facet], i, j);
                /* The image holds doubles: a.x as the image stores it (a
                 * no-op but in the long double build). */
                double ax = (double)a.x;
                ck_assert_msg(memcmp(&ax, &px[0], sizeof ax) == 0, "facet %d, pixel (%d, %d)", facet, i, j);
            }
        tracer_free(&t);
    }
    for (int k = 0; k < 3 * 32 * 24; k++)
        differ += img[0].rgb[k] != img[1].rgb[k];
    ck_assert_int_gt(differ, 0);
    img_free(&img[0]);
    img_free(&img[1]);
    scene_free(s);
}
END_TEST

Suite *suite_terminator(void)
{
    Suite *s = suite_create("terminator");
    TCase *tc = tcase_create("lift");
    tcase_add_test(tc, test_terminator_flat_triangle_is_not_lifted);
    tcase_add_test(tc, test_terminator_lift_on_a_sphere_facet);
    tcase_add_test(tc, test_terminator_smooth_sphere_does_not_shadow_itself);
    tcase_add_test(tc, test_terminator_facet_shadows_option);
    suite_add_tcase(s, tc);
    return s;
}
