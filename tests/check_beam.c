/*
 * check_beam.c - camera-ray beams at the render's level (spec/numerics.md
 * [BVH-BEAM-1]): renderer_region, which walks each tile's camera rays on
 * the tile's pruned tree, against render_pixel, which walks the whole
 * tree, on the same tracer.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "io/scene_file.h"
#include "render/render.h"

enum { BEAM_W = 37, BEAM_H = 23, OVERFLOW_RAYS = 5 };
#define OVERFLOW_BALL "sphere { center [7.5, 2, 3] radius 0.5 material glass }\n"

/* Renders text at BEAM_W x BEAM_H with k x k samples by renderer_region
 * and pixel by pixel by render_pixel: the same bits.  Returns the node
 * visits of the region less those of the pixels. */
static long region_against_pixels(const char *text, int k, int no_shortcuts)
{
    static double img[3 * BEAM_W * BEAM_H];
    int status;
    scene_model *s = scene_file_load_text("beam.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d)", status);
    renderer r;
    render_opts o = {0};
    o.width = BEAM_W, o.height = BEAM_H, o.samples = k, o.no_shortcuts = no_shortcuts;
    ck_assert_int_eq(renderer_init(&r, s, &o), STATUS_OK);
    render_target all = {0, 0, BEAM_W, BEAM_H, NULL, img, 3 * (size_t)BEAM_W};
    ck_assert_int_eq(renderer_region(&r, &all), STATUS_OK);
    trace_stats st;
    memset(&st, 0, sizeof st);
    for (int j = 0; j < BEAM_H; j++)
        for (int i = 0; i < BEAM_W; i++) {
            rgb c = render_pixel(&r.tracer, BEAM_W, BEAM_H, k, i, j, &st);
            const double *at = img + 3 * ((size_t)j * BEAM_W + i);
            ck_assert_msg(same_real_bits(c.x, at[0]) && same_real_bits(c.y, at[1]) && same_real_bits(c.z, at[2]),
                          "pixel (%d, %d), %d samples: %.17g %.17g %.17g by region, %.17g %.17g %.17g by pixel", i, j,
                          k, at[0], at[1], at[2], (double)c.x, (double)c.y, (double)c.z);
        }
    ck_assert(st.camera_rays == r.stats.trace.camera_rays && st.shadow_rays == r.stats.trace.shadow_rays);
    long fewer = st.bvh.nodes_visited - r.stats.trace.bvh.nodes_visited;
    renderer_free(&r);
    scene_free(s);
    return fewer;
}

/* A grid of balls, glass among them, boxes with a triangle and a disk in
 * their top faces' plane (coplanar ties), a mirror: camera rays meet
 * every kind of part, and their first hits start the rest. */
static const char beam_scene[] =
    "image { width 40 height 30 samples 1 max_depth 3 }\n"
    "camera { %s }\n"
    "ambient { color 0.1 }\n"
    "point_light { position [5, 15, -2] power 30 d0 1 }\n"
    "material ball { Kd [0.7, 0.5, 0.3] Ks 0.2 n 30 }\n"
    "material glass { Kd 0 Ks 0.1 t 0.9 ior 1.5 }\n"
    "plane { point [0, -1, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.3 } }\n"
    "for i in 0 .. 5 { for j in 0 .. 5 { for k in 0 .. 2 {\n"
    "  sphere { center [i * 1.5, k * 1.5, j * 1.5] radius 0.4 material ball } } } }\n"
    "sphere { center [3.7, 3, 3.7] radius 0.9 material glass }\n"
    "box { from [1, 3.5, 1] to [2.5, 4, 2.5] material { Kd [0.2, 0.6, 0.2] } }\n"
    "triangle { vertices [0.5, 4, 0.5] [3, 4, 0.8] [1, 4, 3] material { Kd [0.6, 0.2, 0.2] } }\n"
    "disk { center [1.7, 4, 1.7] normal [0, 1, 0] radius 0.6 material { Kd [0.2, 0.2, 0.6] } }\n";

static const char *beam_text(const char *camera)
{
    static char text[4096];
    int len = snprintf(text, sizeof text, beam_scene, camera);
    ck_assert(len > 0 && len < (int)sizeof text);
    return text;
}

START_TEST(test_beam_region_is_render_pixel)
{
    const char *cam = "perspective eye [4, 7, -5] look_at [4, 1, 4] up [0, 1, 0] fov 60";
    /* 1, 2 and 9 samples (81 rays a pixel: tiles of three pixels) and a
     * square view (rays of a run on both sides of an axis: refused). */
    ck_assert_int_gt(region_against_pixels(beam_text(cam), 1, 0), 0);
    ck_assert_int_gt(region_against_pixels(beam_text(cam), 2, 0), 0);
    ck_assert_int_gt(region_against_pixels(beam_text(cam), 9, 0), 0);
    const char *head_on = "perspective eye [4, 2, -6] look_at [4, 2, 4] up [0, 1, 0] fov 50";
    ck_assert_int_gt(region_against_pixels(beam_text(head_on), 1, 0), 0);
}
END_TEST

/* No beams without one eye or with the shortcuts off: the same walks. */
START_TEST(test_beam_none_orthographic_or_no_shortcuts)
{
    const char *ortho = "orthographic eye [4, 7, -5] look_at [4, 1, 4] up [0, 1, 0] width 8";
    ck_assert_int_eq(region_against_pixels(beam_text(ortho), 1, 0), 0);
    const char *cam = "perspective eye [4, 7, -5] look_at [4, 1, 4] up [0, 1, 0] fov 60";
    ck_assert_int_eq(region_against_pixels(beam_text(cam), 2, 1), 0);
}
END_TEST


/* Whether pixel (i, j) alone passes r's max_tree_rays, by render_pixel. */
/* Whether pixel (i, j) overflows, traced alone; its camera and reflection
 * rays are added to *rays. */
static int pixel_overflows(const renderer *r, int k, int i, int j, long *rays)
{
    trace_stats st;
    memset(&st, 0, sizeof st);
    (void)render_pixel(&r->tracer, BEAM_W, BEAM_H, k, i, j, &st);
    *rays += st.camera_rays + st.reflection_rays;
    return st.tree_overflow;
}

/*
 * An overflow is reported at the first overflowing pixel in row-major
 * order, whatever order the beams' tiles make the pixels in: two glass
 * balls, one seen to the right in the top rows, one to the left below it,
 * and a limit of rays a pixel that only pixels seeing glass pass.  The
 * first pixel in row-major order is found by render_pixel pixel by pixel;
 * the test asserts the scene has teeth (an overflowing pixel left of and
 * below the first one, which a tile holding both would meet first), and
 * that the counts are the row-major pixels' up to the first.
 */
START_TEST(test_beam_overflow_is_row_major_first)
{
    static double img[3 * BEAM_W * BEAM_H];
    char text[4096];
    const char *cam = "perspective eye [4, 7, -5] look_at [4, 1, 4] up [0, 1, 0] fov 60";
    int n = snprintf(text, sizeof text, "%s%s", beam_text(cam), OVERFLOW_BALL);
    ck_assert(n > 0 && n < (int)sizeof text);
    int status;
    scene_model *s = scene_file_load_text("beam.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert(s != NULL);
    for (int k = 1; k <= 2; k++) {
        renderer r;
        render_opts o = {0};
        o.width = BEAM_W, o.height = BEAM_H, o.samples = k, o.max_tree_rays = OVERFLOW_RAYS;
        ck_assert_int_eq(renderer_init(&r, s, &o), STATUS_OK);
        int fx = -1, fy = -1, teeth = 0;
        long rays = 0, rays_to_first = 0;   /* camera and reflection rays, row-major, up to the first overflow */
        for (int j = 0; j < BEAM_H; j++)
            for (int i = 0; i < BEAM_W; i++) {
                int over = pixel_overflows(&r, k, i, j, &rays);
                if (fx < 0)
                    rays_to_first = rays;
                if (!over)
                    continue;
                if (fx < 0)
                    fx = i, fy = j;
                else if (j > fy && i < 8)
                    teeth++;
            }
        ck_assert_msg(fx >= 0 && teeth > 0, "k %d: first (%d, %d), %d below and left", k, fx, fy, teeth);
        render_target all = {0, 0, BEAM_W, BEAM_H, NULL, img, 3 * (size_t)BEAM_W};
        ck_assert_int_eq(renderer_region(&r, &all), STATUS_DATA);
        ck_assert_msg(r.stats.overflow_x == fx && r.stats.overflow_y == fy, "k %d: (%d, %d) reported, (%d, %d) first", k,
                      r.stats.overflow_x, r.stats.overflow_y, fx, fy);
        /* The counts are those of the pixels up to the first, each traced
         * once: a tile's pixels traced before the band is made again row by
         * row are not counted twice (attack 24, defect 1). */
        ck_assert_msg(r.stats.trace.camera_rays + r.stats.trace.reflection_rays == rays_to_first,
                      "k %d: %ld camera and reflection rays counted, %ld traced up to the first", k,
                      r.stats.trace.camera_rays + r.stats.trace.reflection_rays, rays_to_first);
        renderer_free(&r);
    }
    scene_free(s);
}
END_TEST

Suite *suite_beam(void)
{
    Suite *s = suite_create("beam");
    TCase *tc = tcase_create("beam");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, test_beam_region_is_render_pixel);
    tcase_add_test(tc, test_beam_none_orthographic_or_no_shortcuts);
    tcase_add_test(tc, test_beam_overflow_is_row_major_first);
    suite_add_tcase(s, tc);
    return s;
}
