/*
 * The public API as an embedding program uses it: only refray.h, a scene
 * from memory, a render, a metric.  The pixel is derived by hand: an
 * orthographic view straight down at a plane with Kd 0.5 under ambient 0.2
 * and a distant light from straight above of power 2: 0.5*0.2 + 0.5*2*1.
 */
#include <string.h>
#include "testlib.h"
#include "refray.h"
#include "io/scene_file.h"

START_TEST(test_api_load_render_compare)
{
    static const char text[] =
        "image { width 2 height 2 }\n"
        "camera { orthographic eye [0, 1, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
        "ambient { color 0.2 }\n"
        "distant_light { direction [0, -1, 0] power 2 }\n"
        "plane { material { Kd 0.5 } }\n";
    int status;
    scene_model *s = scene_file_load_text("api.scene", text, strlen(text), NULL, stderr, 1, &status);
    ck_assert_ptr_nonnull(s);
    ck_assert_int_eq(status, STATUS_OK);
    img_buf img, want;
    ck_assert_int_eq(render_image(s, NULL, &img, NULL), STATUS_OK);
    ck_assert_int_eq(img_create(&want, 2, 2), 0);
    for (int i = 0; i < 12; i++)
        want.rgb[i] = 1.1;
    image_metrics m;
    metrics_compare(&img, &want, NULL, 1e-15, &m);
    ck_assert_int_eq(m.over, 0);
    ck_assert(m.max_abs <= 1e-15);
    img_free(&img);
    img_free(&want);
    scene_free(s);
}
END_TEST

Suite *suite_api(void)
{
    Suite *s = suite_create("api");
    TCase *tc = tcase_create("embedding");
    tcase_add_test(tc, test_api_load_render_compare);
    suite_add_tcase(s, tc);
    return s;
}
