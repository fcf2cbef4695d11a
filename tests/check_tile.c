/*
 * check_tile.c - tiles (image/tile.h) and tile files (io/tile_file.h): the
 * fixed split into bands, the checks a merge makes (overlaps, gaps), the
 * key's text, and tile files that give back every double exactly, refuse
 * what is not a whole tile, and show viewers the floats a whole image has
 * (spec/scaling.md: [TILE-SPLIT-1], [TILE-FILE-1], [TILE-FILE-2], [TILE-FILE-3],
 * [SCALE-MERGE-3]).
 * Expected bands and gaps are worked out by hand below each case.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/status.h"
#include "cli_testlib.h"
#include "image/image_file.h"
#include "image/tile.h"
#include "io/image_io.h"
#include "io/tile_file.h"

#ifndef REFRAY_HAVE_EXR
#define REFRAY_HAVE_EXR 0
#endif

/* [TILE-SPLIT-1] Bands by hand: 1080 rows in 7 (1080 i / 7 = 0, 154.3,
 * 308.6, 462.9, 617.1, ... so band 3 is [462, 617)); 10 rows from 100 in
 * 4 (10 i / 4 = 0, 2.5, 5, 7.5, 10). */
START_TEST(test_tile_band_by_hand)
{
    static const struct {
        int y0, y1, n, i, want0, want1;
    } cases[] = {
        {0, 1080, 7, 0, 0, 154},     {0, 1080, 7, 3, 462, 617},   {0, 1080, 7, 6, 925, 1080},
        {100, 110, 4, 0, 100, 102},  {100, 110, 4, 1, 102, 105},  {100, 110, 4, 2, 105, 107},
        {100, 110, 4, 3, 107, 110},  {0, 5, 5, 2, 2, 3},          {0, 1, 1, 0, 0, 1},
        {0, 2000000000, 3, 2, 1333333333, 2000000000},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        int a, b;
        tile_band(cases[k].y0, cases[k].y1, cases[k].n, cases[k].i, &a, &b);
        ck_assert_msg(a == cases[k].want0 && b == cases[k].want1, "case %zu: [%d, %d), want [%d, %d)", k, a, b,
                      cases[k].want0, cases[k].want1);
    }
}
END_TEST

/* [TILE-SPLIT-1] For every row count up to 60 and every n up to it: the
 * bands follow each other from y0 to y1, none empty, each floor(R/n) or
 * one more rows. */
START_TEST(test_tile_band_covers_in_order)
{
    for (int rows = 1; rows <= 60; rows++)
        for (int n = 1; n <= rows; n++) {
            int at = 7;
            for (int i = 0; i < n; i++) {
                int a, b;
                tile_band(7, 7 + rows, n, i, &a, &b);
                ck_assert_int_eq(a, at);
                ck_assert(b - a == rows / n || b - a == rows / n + 1);
                at = b;
            }
            ck_assert_int_eq(at, 7 + rows);
        }
}
END_TEST

static tile_rect rect(int x0, int y0, int x1, int y1)
{
    tile_rect r = {x0, y0, x1, y1};
    return r;
}

/* [SCALE-MERGE-3] The first gap, by hand for each layout (W x H). */
START_TEST(test_tile_find_gap)
{
    static const struct {
        const char *what;
        int width, height, count;
        tile_rect regions[4];
        int found;
        tile_rect gap;
    } cases[] = {
        {"three bands cover 10x6", 10, 6, 3, {{0, 0, 10, 2}, {0, 2, 10, 4}, {0, 4, 10, 6}}, 0, {0, 0, 0, 0}},
        {"the middle band is missing", 10, 6, 2, {{0, 0, 10, 2}, {0, 4, 10, 6}}, 1, {0, 2, 10, 4}},
        {"a hole between two tiles of a row", 10, 4, 2, {{0, 0, 3, 4}, {6, 0, 10, 4}}, 1, {3, 0, 6, 4}},
        /* Row 2 is uncovered at x 4..6; the tile from row 4 touches that run. */
        {"a gap that ends where a tile starts", 10, 6, 4, {{0, 0, 10, 2}, {0, 2, 4, 6}, {7, 2, 10, 6}, {4, 4, 7, 6}},
         1, {4, 2, 7, 4}},
        {"no tiles", 3, 2, 0, {{0, 0, 0, 0}}, 1, {0, 0, 3, 2}},
        {"the last column", 5, 3, 1, {{0, 0, 4, 3}}, 1, {4, 0, 5, 3}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        tile_rect gap = {-1, -1, -1, -1};
        int found = tile_find_gap(cases[k].regions, cases[k].count, cases[k].width, cases[k].height, &gap);
        ck_assert_msg(found == cases[k].found, "%s: found %d", cases[k].what, found);
        if (found)
            ck_assert_msg(gap.x0 == cases[k].gap.x0 && gap.y0 == cases[k].gap.y0 && gap.x1 == cases[k].gap.x1 &&
                              gap.y1 == cases[k].gap.y1,
                          "%s: gap %d %d %d %d", cases[k].what, gap.x0, gap.y0, gap.x1, gap.y1);
    }
}
END_TEST

START_TEST(test_tile_overlap_and_text)
{
    tile_rect a = rect(0, 0, 5, 5), b = rect(4, 4, 9, 9), c = rect(5, 0, 9, 5), both;
    char text[64];
    ck_assert(tile_overlap(&a, &b, &both));
    ck_assert_str_eq(tile_rect_text(&both, text, sizeof text), "x 4..4, y 4..4");
    ck_assert(!tile_overlap(&a, &c, &both));
    ck_assert_int_eq(tile_area(&b), 25);
    ck_assert_str_eq(tile_rect_text(&a, text, sizeof text), "x 0..4, y 0..4");
}
END_TEST

START_TEST(test_tile_key_text)
{
    char text[17];
    uint64_t k = 0;
    tile_key_text(0x0123456789abcdefULL, text);
    ck_assert_str_eq(text, "0123456789abcdef");
    ck_assert(tile_key_parse("fedcba9876543210", &k));
    ck_assert(k == 0xfedcba9876543210ULL);
    ck_assert(!tile_key_parse("0123456789ABCDEF", &k));
    ck_assert(!tile_key_parse("0123456789abcde", &k));
    ck_assert(!tile_key_parse("0123456789abcdef0", &k));
    ck_assert(!tile_key_parse("0123456789abcdeg", &k));
}
END_TEST

START_TEST(test_tile_info_valid)
{
    char why[200];
    tile_info t = {7, 5, {2, 1, 6, 4}, 1};
    ck_assert(tile_info_valid(&t, 100, why, sizeof why));
    ck_assert(!tile_info_valid(&t, 34, why, sizeof why));
    t.region = rect(2, 1, 8, 4);
    ck_assert(!tile_info_valid(&t, 100, why, sizeof why));
    ck_assert_ptr_nonnull(strstr(why, "not inside the 7x5 image"));
    t.region = rect(3, 1, 3, 4);
    ck_assert(!tile_info_valid(&t, 100, why, sizeof why));
    t.region = rect(-1, 1, 3, 4);
    ck_assert(!tile_info_valid(&t, 100, why, sizeof why));
}
END_TEST

/* ---- Files ---- */

/* A 4 x 3 region of a 7 x 5 image holding doubles no float holds (and -0,
 * DBL_MAX-sized ones: whatever a render can write; a negative or
 * non-finite value it never writes, and a read refuses it). */
static tile_info sample_tile(img_buf *px)
{
    static const double values[] = {0.1, 1e-310, -0.0, 1e300, 3.0000000000000004, 3 * DBL_MIN,
                                    1.0 / 3.0, 65504.000000001, 2.5e-8, 1e-40, 7.0, DBL_MAX / 2};
    tile_info t = {7, 5, {2, 1, 6, 4}, 0x9e3779b97f4a7c15ULL};
    ck_assert_int_eq(img_create(px, 4, 3), 0);
    for (size_t i = 0; i < 36; i++)
        px->rgb[i] = values[i % 12] * (1.0 + (double)(i / 12) / 7.0);
    return t;
}

static void same_bits(const img_buf *a, const img_buf *b)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    for (size_t i = 0; i < 3 * (size_t)a->width * (size_t)a->height; i++)
        ck_assert_msg(memcmp(&a->rgb[i], &b->rgb[i], sizeof(double)) == 0, "value %zu: %.17g, want %.17g", i,
                      b->rgb[i], a->rgb[i]);
}

/* [TILE-FILE-1] The doubles come back bit for bit, with the header; a
 * header-only read gives the same header. */
static void round_trip(const char *name)
{
    char dir[64], path[300], why[600];
    img_buf px, back, view;
    tile_info t = sample_tile(&px), got, head;
    img_write_opts o = img_write_opts_default();
    o.exr_float = 1;
    cli_scratch(dir, sizeof dir, "tile");
    cli_path(path, sizeof path, dir, name);
    ck_assert_msg(tile_file_write(path, &t, &px, &o, why, sizeof why) == STATUS_OK, "%s", why);
    ck_assert_msg(tile_file_read(path, NULL, &got, &back, why, sizeof why) == STATUS_OK, "%s", why);
    ck_assert(tile_info_equal(&got, &t));
    same_bits(&px, &back);
    ck_assert_int_eq(tile_file_read(path, NULL, &head, NULL, why, sizeof why), STATUS_OK);
    ck_assert(tile_info_equal(&head, &t));
    /* [TILE-FILE-2] What a viewer sees: the floats of the values. */
    ck_assert_msg(img_read(path, NULL, &view, why, sizeof why) == 0, "%s", why);
    ck_assert_int_eq(view.width, 4);
    ck_assert_int_eq(view.height, 3);
    for (size_t i = 0; i < 36; i++)
        ck_assert_msg(view.rgb[i] == (double)img_float_from_double(px.rgb[i], NULL), "value %zu", i);
    img_free(&view);
    img_free(&back);
    img_free(&px);
    ck_assert_int_eq(tile_file_remove(path), 0);
    ck_assert_int_eq(cli_entries(dir), 0);
    cli_remove(dir);
}

START_TEST(test_tile_file_pfm_round_trip)
{
    round_trip("t.pfm");
}
END_TEST

START_TEST(test_tile_file_exr_round_trip)
{
    if (REFRAY_HAVE_EXR)
        round_trip("t.exr");
}
END_TEST

static void truncate_by(const char *path, long delta)
{
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fclose(f);
    ck_assert_int_eq(truncate(path, n + delta), 0);
}

/* XORs the byte at offset `at` of the pixels of the sidecar at path with
 * mask. */
static void change_byte(const char *path, long at, unsigned mask)
{
    char line[128];
    FILE *f = fopen(path, "r+b");
    ck_assert_ptr_nonnull(f);
    for (int i = 0; i < 5; i++)
        ck_assert_ptr_nonnull(fgets(line, sizeof line, f));
    long pixels = ftell(f);
    ck_assert_int_eq(fseek(f, pixels + at, SEEK_SET), 0);
    int c = fgetc(f);
    ck_assert_int_ne(c, EOF);
    ck_assert_int_eq(fseek(f, pixels + at, SEEK_SET), 0);
    ck_assert_int_eq(fputc((int)((unsigned)c ^ mask), f), (int)((unsigned)c ^ mask));
    ck_assert_int_eq(fclose(f), 0);
}

static void expect_refusal(const char *path, int status, const char *text)
{
    char why[600];
    tile_info t;
    img_buf px;
    ck_assert_int_eq(tile_file_read(path, NULL, &t, &px, why, sizeof why), status);
    ck_assert_msg(strstr(why, text) != NULL, "'%s' lacks '%s'", why, text);
    ck_assert_ptr_null(px.rgb);
}

/* [TILE-FILE-3] What is not a whole tile is refused with its reason. */
START_TEST(test_tile_file_refusals)
{
    char dir[64], pfm[300], side[320], exr[300], why[600];
    img_buf px;
    tile_info t = sample_tile(&px);
    cli_scratch(dir, sizeof dir, "tile");
    cli_path(pfm, sizeof pfm, dir, "t.pfm");
    snprintf(side, sizeof side, "%s.tile", pfm);
    ck_assert_int_eq(tile_file_write(pfm, &t, &px, NULL, why, sizeof why), STATUS_OK);
    truncate_by(side, -1);
    expect_refusal(pfm, STATUS_DATA, "does not match its region");
    truncate_by(side, 2);
    expect_refusal(pfm, STATUS_DATA, "does not match its region");
    FILE *f = fopen(side, "r+b");
    ck_assert_ptr_nonnull(f);
    fputs("refray-tile 9", f);
    fclose(f);
    expect_refusal(pfm, STATUS_DATA, "not a refray tile sidecar");
    /* The first layout had no checksum: refused with what to do. */
    f = fopen(side, "r+b");
    ck_assert_ptr_nonnull(f);
    fputs("refray-tile 1", f);
    fclose(f);
    expect_refusal(pfm, STATUS_DATA, "render the tile again");
    /* [TILE-FILE-4] One changed bit of a value, still one a render writes
     * (the lowest of 0.1's mantissa: tests/attack12 finding 3, merged
     * silently before), is caught by the checksum. */
    ck_assert_int_eq(tile_file_write(pfm, &t, &px, NULL, why, sizeof why), STATUS_OK);
    change_byte(side, 0, 0x01);
    expect_refusal(pfm, STATUS_DATA, "do not match their checksum");
    change_byte(side, 0, 0x01);
    tile_info same;
    img_buf back;
    ck_assert_msg(tile_file_read(pfm, NULL, &same, &back, why, sizeof why) == STATUS_OK, "%s", why);
    img_free(&back);
    change_byte(side, 8 * 35 + 7, 0x01);
    expect_refusal(pfm, STATUS_DATA, "do not match their checksum");
    unlink(side);
    expect_refusal(pfm, STATUS_NO_INPUT, "sidecar");
    cli_path(exr, sizeof exr, dir, "whole.exr");
    if (REFRAY_HAVE_EXR) {
        ck_assert_int_eq(img_write(exr, &px, NULL, why, sizeof why), 0);
        expect_refusal(exr, STATUS_DATA, "not a refray tile");
    }
    cli_path(exr, sizeof exr, dir, "missing.exr");
    expect_refusal(exr, REFRAY_HAVE_EXR ? STATUS_NO_INPUT : STATUS_USAGE, REFRAY_HAVE_EXR ? "No such" : "EXR=0");
    cli_path(exr, sizeof exr, dir, "t.png");
    expect_refusal(exr, STATUS_USAGE, "display codes");
    /* A tile's sidecar, as a glob lists it beside the tile (attack 14,
     * finding 5: refused as PNG and PPM before). */
    expect_refusal(side, STATUS_USAGE, "is the sidecar of the tile");
    cli_path(exr, sizeof exr, dir, "t.txt");
    expect_refusal(exr, STATUS_USAGE, "a tile is .exr or .pfm, not");
    /* A value no render writes, over the first double of a whole sidecar
     * (tests/attack9 finding 7: merged as 0, 0 and -1 before). */
    static const double damaged[] = {-1, HUGE_VAL, -HUGE_VAL, NAN, -DBL_MIN};
    for (size_t k = 0; k < sizeof damaged / sizeof damaged[0]; k++) {
        ck_assert_int_eq(tile_file_write(pfm, &t, &px, NULL, why, sizeof why), STATUS_OK);
        FILE *g = fopen(side, "r+b");
        ck_assert_ptr_nonnull(g);
        char line[128];
        for (int i = 0; i < 5; i++)
            ck_assert_ptr_nonnull(fgets(line, sizeof line, g));
        unsigned char le[8];
        uint64_t bits;
        memcpy(&bits, &damaged[k], sizeof bits);
        for (int i = 0; i < 8; i++)
            le[i] = (unsigned char)(bits >> (8 * i));
        ck_assert_int_eq(fseek(g, ftell(g), SEEK_SET), 0);
        ck_assert_int_eq(fwrite(le, 1, 8, g), 8);
        fclose(g);
        expect_refusal(pfm, STATUS_DATA, "pixel (2, 1) of the tile holds");
        expect_refusal(pfm, STATUS_DATA, "a value no render writes");
    }
    ck_assert_int_eq(tile_file_write(exr, &t, &px, NULL, why, sizeof why), STATUS_USAGE);
    img_free(&px);
    cli_remove(dir);
}
END_TEST

Suite *suite_tile(void)
{
    Suite *s = suite_create("tile");
    TCase *tc = tcase_create("tile");
    tcase_add_test(tc, test_tile_band_by_hand);
    tcase_add_test(tc, test_tile_band_covers_in_order);
    tcase_add_test(tc, test_tile_find_gap);
    tcase_add_test(tc, test_tile_overlap_and_text);
    tcase_add_test(tc, test_tile_key_text);
    tcase_add_test(tc, test_tile_info_valid);
    tcase_add_test(tc, test_tile_file_pfm_round_trip);
    tcase_add_test(tc, test_tile_file_exr_round_trip);
    tcase_add_test(tc, test_tile_file_refusals);
    suite_add_tcase(s, tc);
    return s;
}
