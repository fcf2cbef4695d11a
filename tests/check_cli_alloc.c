/*
 * check_cli_alloc.c - the refray program's allocator (src/cli/cli_alloc.h,
 * spec/performance.md [PERF-ALLOC-1]): a block of any size keeps its bytes
 * across every resize (small to big, big to bigger, big to small), is
 * aligned for any object, and goes back by the size it was given.
 */
#include <stdint.h>
#include <string.h>
#include "testlib.h"
#include "cli/cli_alloc.h"

/* Fills n bytes with a pattern that depends on the position and a seed. */
static void fill(unsigned char *p, size_t n, unsigned seed)
{
    for (size_t i = 0; i < n; i++)
        p[i] = (unsigned char)((i * 131u + seed) >> 3);
}

static int same(const unsigned char *p, size_t n, unsigned seed)
{
    for (size_t i = 0; i < n; i++)
        if (p[i] != (unsigned char)((i * 131u + seed) >> 3))
            return 0;
    return 1;
}

/* [PERF-ALLOC-1] */
START_TEST(test_cli_alloc_keeps_bytes)
{
    const rf_allocator *a = cli_allocator();
    size_t small = 1000, big = CLI_ALLOC_BIG + 12345, bigger = 3 * CLI_ALLOC_BIG + 7, back = 5000;
    unsigned char *p = a->alloc(a->user, small);
    ck_assert_ptr_nonnull(p);
    ck_assert_uint_eq((uintptr_t)p % sizeof(double), 0);
    fill(p, small, 1);
    p = a->resize(a->user, p, small, big);
    ck_assert_ptr_nonnull(p);
    ck_assert_uint_eq((uintptr_t)p % sizeof(double), 0);
    ck_assert(same(p, small, 1));
    fill(p, big, 2);
    /* the far end of the block is writable */
    p[big - 1] = 0x5a;
    ck_assert_uint_eq(p[big - 1], 0x5a);
    fill(p, big, 2);
    p = a->resize(a->user, p, big, bigger);
    ck_assert_ptr_nonnull(p);
    ck_assert(same(p, big, 2));
    fill(p, bigger, 3);
    p = a->resize(a->user, p, bigger, big + 1);   /* shrinks within the mapping */
    ck_assert_ptr_nonnull(p);
    ck_assert(same(p, big + 1, 3));
    p = a->resize(a->user, p, big + 1, back);
    ck_assert_ptr_nonnull(p);
    ck_assert(same(p, back, 3));
    a->release(a->user, p, back);
    unsigned char *q = a->alloc(a->user, bigger);
    ck_assert_ptr_nonnull(q);
    fill(q, bigger, 4);
    ck_assert(same(q, bigger, 4));
    a->release(a->user, q, bigger);
    a->release(a->user, NULL, 0);
}
END_TEST

/* A scene loaded and rendered through it gives the image malloc gives. */
START_TEST(test_cli_alloc_render_same)
{
    const char *text = "image { width 8 height 6 }\n"
                       "camera { perspective eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] fov 40 }\n"
                       "point_light { position [3, 6, 4] power 40 d0 1 }\n"
                       "ambient { color 0.3 }\n"
                       "sphere { center [0, 0, 0] radius 1 material { Kd 0.8 } }\n";
    double px[2][8 * 6 * 3];
    for (int k = 0; k < 2; k++) {
        rf_load_options lo;
        rf_load_options_init(&lo);
        lo.allocator = k ? cli_allocator() : NULL;
        rf_scene *s = NULL;
        ck_assert_int_eq(rf_scene_load_memory("t.scene", text, strlen(text), &lo, &s), RF_OK);
        rf_image *img = NULL;
        ck_assert_int_eq(rf_render_image(s, NULL, &img, NULL), RF_OK);
        ck_assert_int_eq(rf_image_width(img), 8);
        memcpy(px[k], rf_image_pixels(img), sizeof px[k]);
        rf_image_free(img);
        rf_scene_free(s);
    }
    ck_assert_mem_eq(px[0], px[1], sizeof px[0]);
}
END_TEST

Suite *suite_cli_alloc(void)
{
    Suite *s = suite_create("cli_alloc");
    TCase *tc = tcase_create("alloc");
    tcase_add_test(tc, test_cli_alloc_keeps_bytes);
    tcase_add_test(tc, test_cli_alloc_render_same);
    suite_add_tcase(s, tc);
    return s;
}
