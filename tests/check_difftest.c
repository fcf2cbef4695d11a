/*
 * The pieces of `make difftest` that need no POV-Ray (spec/crosscheck.md,
 * section 6): the random scene generator (tests/difftest/gen.c) and the
 * ray-tree hash (trace_stats.path) by which edge pixels are told from
 * interior ones.
 */
#include <stdio.h>
#include <string.h>
#include "testlib.h"
#include "difftest/gen.h"
#include "export/export_pov.h"
#include "io/scene_file.h"
#include "render/camera.h"
#include "render/trace.h"
#include "scene/scene.h"

static scene_model *load(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text("test.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d):\n%s", status, text);
    return s;
}

/* [XCHK-DIFF-GEN-1] One seed, one text; another seed, another text. */
START_TEST(test_dtgen_is_reproducible)
{
    static dtgen_scene a, b;
    dtgen_make(&a, 77, DTGEN_EXACT, "tests/obj");
    dtgen_make(&b, 77, DTGEN_EXACT, "tests/obj");
    ck_assert_uint_eq(a.len, b.len);
    ck_assert(memcmp(a.text, b.text, a.len) == 0);
    dtgen_make(&b, 78, DTGEN_EXACT, "tests/obj");
    ck_assert(a.len != b.len || memcmp(a.text, b.text, a.len) != 0);
    ck_assert_int_ge(a.count, 3);
    ck_assert(strncmp(a.text, "image {", 7) == 0);
    ck_assert(strncmp(a.text + a.start[1], "camera {", 8) == 0);
}
END_TEST

/* [XCHK-DIFF-GEN-1] A subset keeps the image and the camera and exactly
 * the statements asked for, in order. */
START_TEST(test_dtgen_subset)
{
    static dtgen_scene g;
    static char text[DTGEN_TEXT_MAX];
    unsigned char keep[DTGEN_STMT_MAX];
    dtgen_make(&g, 5, DTGEN_EXACT, "tests/obj");
    memset(keep, 0, sizeof keep);
    keep[g.count - 1] = 1;
    size_t len = dtgen_subset(&g, keep, text, sizeof text);
    size_t want = g.start[2] + (g.start[g.count] - g.start[g.count - 1]);
    ck_assert_uint_eq(len, want);
    ck_assert(memcmp(text, g.text, g.start[2]) == 0);
    ck_assert(memcmp(text + g.start[2], g.text + g.start[g.count - 1], len - g.start[2]) == 0);
    ck_assert_uint_eq(dtgen_subset(&g, keep, text, 10), 0);
}
END_TEST

/* [XCHK-DIFF-GEN-1] The EXACT profile stays inside what the export maps
 * exactly, as the campaign compares (smooth meshes' shadow rays from the
 * facet, [XCHK-MAP-MESH-3]): every scene loads, and at least 9 in 10 have
 * no approximation to list (the rest: a plane's horizon past 1e7 and the
 * like, which the campaign drops). */
START_TEST(test_dtgen_exact_scenes_export_exactly)
{
    static dtgen_scene g;
    int exact = 0;
    for (int i = 0; i < 100; i++) {
        int status;
        pov_opts o;
        pov_notes n;
        memset(&o, 0, sizeof o);
        o.facet_shadows = 1;
        dtgen_make(&g, (uint64_t)i, DTGEN_EXACT, "tests/obj");
        scene_model *s = scene_file_load_text("random.scene", g.text, g.len, NULL, stderr, 0, &status);
        ck_assert_msg(s != NULL, "generated scene %d did not load:\n%s", i, g.text);
        exact += pov_export_check(s, &o, &n) && n.count == 0;
        scene_free(s);
    }
    ck_assert_int_ge(exact, 90);
}
END_TEST

/* The hash of the ray tree of the camera ray through (x, y). */
static uint64_t path_at(const tracer *t, double x, double y)
{
    trace_stats st;
    memset(&st, 0, sizeof st);
    st.record_path = 1;
    const scene_camera *cam = &t->scene->camera;
    ray r = camera_ray(cam, camera_half(cam), t->scene->image.width, t->scene->image.height, x, y);
    (void)trace_ray(t, &r, 1, &t->eye_media, 0, &st);
    return st.path;
}

/* [XCHK-DIFF-EDGE-1] A floor with a sphere on it and its shadow, seen from
 * above (orthographic, 10 units wide over 10 pixels, so x = 5 is the
 * origin): rays that meet the same surface, lit the same way, have one
 * hash; the sphere, the floor in the sphere's shadow, the lit floor and
 * the background (the floor is a disk) have four different ones. */
START_TEST(test_trace_path_tells_what_rays_met)
{
    scene_model *s = load("image { width 10 height 10 }\n"
                          "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n"
                          "distant_light { direction [-1, -1, 0] }\n"
                          "sphere { center [0, 1, 0] radius 1 }\n"
                          "disk { radius 4 }\n");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    uint64_t sphere = path_at(&t, 5, 5), shade = path_at(&t, 3.6, 5), lit = path_at(&t, 7.5, 5),
             none = path_at(&t, 0.2, 0.2);
    ck_assert(sphere == path_at(&t, 5.1, 5.1));
    ck_assert(shade == path_at(&t, 3.5, 5));
    ck_assert(lit == path_at(&t, 7.5, 6));
    ck_assert(sphere != shade && sphere != lit && sphere != none && shade != lit && shade != none && lit != none);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/* [XCHK-DIFF-EDGE-2] The hash is kept only when asked (record_path): a
 * render leaves trace_stats.path as it found it, and the colour of a ray
 * does not depend on whether its tree was hashed. */
START_TEST(test_trace_path_only_when_asked)
{
    scene_model *s = load("image { width 10 height 10 }\n"
                          "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, -1] width 10 }\n"
                          "distant_light { direction [-1, -1, 0] }\n"
                          "box { from [-1, 0, -1] to [1, 2, 1] }\n"
                          "cylinder { from [2, 0, 2] to [2, 1, 2] radius 0.5 }\n"
                          "disk { radius 4 }\n");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    for (double x = 0.5; x < 10; x += 1) {
        trace_stats off, on;
        memset(&off, 0, sizeof off);
        memset(&on, 0, sizeof on);
        off.path = 12345;
        on.path = 12345;
        on.record_path = 1;
        ray r = camera_ray(&s->camera, camera_half(&s->camera), 10, 10, x, 0.37 * x + 1);
        rgb a = trace_ray(&t, &r, 1, &t.eye_media, 0, &off), b = trace_ray(&t, &r, 1, &t.eye_media, 0, &on);
        ck_assert(same_vec_bits(a, b));
        ck_assert(off.path == 12345);
        ck_assert(on.path != 12345);
    }
    tracer_free(&t);
    scene_free(s);
}
END_TEST

Suite *suite_difftest(void)
{
    Suite *s = suite_create("difftest");
    TCase *tc = tcase_create("difftest");
    tcase_set_timeout(tc, 20);
    tcase_add_test(tc, test_dtgen_is_reproducible);
    tcase_add_test(tc, test_dtgen_subset);
    tcase_add_test(tc, test_dtgen_exact_scenes_export_exactly);
    tcase_add_test(tc, test_trace_path_tells_what_rays_met);
    tcase_add_test(tc, test_trace_path_only_when_asked);
    suite_add_tcase(s, tc);
    return s;
}
