/*
 * check_adjust.c - bringing another renderer's picture to the exact
 * image's terms (image/adjust.h), the kit's tolerance rule
 * (metrics_compare_abs) and the 16-bit PNG scale of the manifest, on
 * values worked by hand (spec/conformance.md [KIT-ADJUST-1], [KIT-RULE-1],
 * [KIT-SCALE-1]).
 */
#include <math.h>
#include "image/adjust.h"
#include "image/metrics.h"
#include "testlib.h"
#include "verify/manifest.h"

/* A 4 x 2 image whose channel c of pixel (x, y) is x + 4y + c/4. */
static void ramp(img_buf *img)
{
    ck_assert_int_eq(img_create(img, 4, 2), STATUS_OK);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 4; x++)
            for (int c = 0; c < 3; c++)
                img_pixel(img, x, y)[c] = x + 4 * y + c / 4.0;
}

/* [KIT-ADJUST-1] Block (0, 0) holds 0, 1, 4, 5 (+ c/4): mean 2.5 + c/4;
 * block (1, 0) holds 2, 3, 6, 7: mean 4.5 + c/4. */
START_TEST(test_img_downsample_averages_blocks)
{
    img_buf in, out;
    ramp(&in);
    ck_assert_int_eq(img_downsample(&in, 2, &out), STATUS_OK);
    ck_assert_int_eq(out.width, 2);
    ck_assert_int_eq(out.height, 1);
    for (int c = 0; c < 3; c++) {
        ck_assert_near(img_pixel(&out, 0, 0)[c], 2.5 + c / 4.0, 0);
        ck_assert_near(img_pixel(&out, 1, 0)[c], 4.5 + c / 4.0, 0);
    }
    img_free(&out);
    img_free(&in);
}
END_TEST

/* k = 1 copies; a size that is not whole blocks, or k < 1, is refused
 * with out empty. */
START_TEST(test_img_downsample_one_and_refusals)
{
    img_buf in, out;
    ramp(&in);
    ck_assert_int_eq(img_downsample(&in, 1, &out), STATUS_OK);
    ck_assert_int_eq(out.width, 4);
    ck_assert_near(img_pixel(&out, 3, 1)[2], 7.5, 0);
    img_free(&out);
    ck_assert_int_eq(img_downsample(&in, 3, &out), STATUS_USAGE);
    ck_assert_ptr_null(out.rgb);
    ck_assert_int_eq(img_downsample(&in, 0, &out), STATUS_USAGE);
    ck_assert_int_eq(img_downsample(&in, 4, &out), STATUS_USAGE); /* 2 rows are no 4-row block */
    img_free(&in);
}
END_TEST

START_TEST(test_img_scale_and_nonfinite)
{
    img_buf img;
    ramp(&img);
    img_scale(&img, 0.5);
    ck_assert_near(img_pixel(&img, 3, 1)[2], 3.75, 0);
    ck_assert_int_eq(img_count_nonfinite(&img), 0);
    img_pixel(&img, 0, 0)[0] = NAN;
    img_pixel(&img, 1, 0)[1] = INFINITY;
    img_pixel(&img, 2, 1)[2] = -INFINITY;
    ck_assert_int_eq(img_count_nonfinite(&img), 3);
    img_free(&img);
}
END_TEST

/*
 * [KIT-RULE-1] Over when |A - B| > rel |B| + abs, rel 1e-3, abs 1e-6.
 * B: pixel 0 (1, 0.5, 0), pixel 1 (1, 0.5, 0), pixel 2 (0, 0, 0).
 * Pixel 0: +1.0e-3 on red (bound 1.001e-3): in.  Pixel 1: +1.002e-3 on
 * red: over.  Pixel 2: +0.9e-6 on blue (bound 1e-6 on a black channel):
 * in; the same image with +1.1e-6 there: over.
 */
START_TEST(test_metrics_compare_abs_rule)
{
    img_buf a, b;
    image_metrics m;
    ck_assert_int_eq(img_create(&a, 3, 1), STATUS_OK);
    ck_assert_int_eq(img_create(&b, 3, 1), STATUS_OK);
    for (int x = 0; x < 2; x++) {
        img_pixel(&b, x, 0)[0] = 1;
        img_pixel(&b, x, 0)[1] = 0.5;
    }
    for (int i = 0; i < 9; i++)
        a.rgb[i] = b.rgb[i];
    img_pixel(&a, 0, 0)[0] += 1.0e-3;
    img_pixel(&a, 1, 0)[0] += 1.002e-3;
    img_pixel(&a, 2, 0)[2] = 0.9e-6;
    metrics_compare_abs(&a, &b, NULL, 1e-3, 1e-6, &m);
    ck_assert_int_eq(m.over, 1);
    ck_assert_int_eq(m.compared, 3);
    ck_assert_near(m.max_abs, 1.002e-3, 1e-15);
    ck_assert_int_eq(m.worst_x, 1);
    img_pixel(&a, 2, 0)[2] = 1.1e-6;
    metrics_compare_abs(&a, &b, NULL, 1e-3, 1e-6, &m);
    ck_assert_int_eq(m.over, 2);
    unsigned char mask[3] = {0, 1, 1};
    metrics_compare_abs(&a, &b, mask, 1e-3, 1e-6, &m);
    ck_assert_int_eq(m.over, 0);
    ck_assert_int_eq(m.excluded, 2);
    /* verify's rule (no absolute part) finds the black channel over. */
    unsigned char only_black[3] = {1, 1, 0};
    metrics_compare(&a, &b, only_black, 1e-3, &m);
    ck_assert_int_eq(m.over, 1);
    img_pixel(&a, 0, 0)[1] = NAN;
    metrics_compare_abs(&a, &b, mask, 1, 1, &m);
    ck_assert_int_eq(m.over, 1);
    img_free(&a);
    img_free(&b);
}
END_TEST

/* [KIT-SCALE-1] The power of two that puts the peak in (0.4, 0.8]. */
START_TEST(test_manifest_png16_scale_known_values)
{
    static const double cases[][2] = {
        {0.8, 1},      {0.81, 0.5},   {0.4, 2},       {0.41, 1},   {0.5, 1},       {3.184, 0.25},
        {1e-3, 512},   {1.6, 0.5},    {1.61, 0.25},   {0, 1},      {-2, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double s = manifest_png16_scale(cases[i][0]);
        ck_assert_msg(s == cases[i][1], "peak %g: scale %g, expected %g", cases[i][0], s, cases[i][1]);
    }
    ck_assert(manifest_png16_scale(NAN) == 1);
    ck_assert(manifest_png16_scale(INFINITY) == 1);
    ck_assert_near(manifest_png16_step(0.25), 4.0 / 65535.0, 0);
    ck_assert_near(manifest_png16_step(1), 1.0 / 65535.0, 0);
}
END_TEST

Suite *suite_adjust(void)
{
    Suite *s = suite_create("adjust");
    TCase *tc = tcase_create("adjust");
    tcase_add_test(tc, test_img_downsample_averages_blocks);
    tcase_add_test(tc, test_img_downsample_one_and_refusals);
    tcase_add_test(tc, test_img_scale_and_nonfinite);
    tcase_add_test(tc, test_metrics_compare_abs_rule);
    tcase_add_test(tc, test_manifest_png16_scale_known_values);
    suite_add_tcase(s, tc);
    return s;
}
