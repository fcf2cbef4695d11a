/*
 * check_compare.c - comparing two images: the metrics on images with known
 * differences, the error map's colours, the exclusion masks, and `refray
 * compare` run as a child process ($REFRAY_BIN, set by `make test`, else
 * build/refray; run from the repository root).
 *
 * The reference B is 4 x 3 pixels of 0.5; A equals B except pixel (1, 0),
 * +0.1 in every channel, and pixel (2, 2), -0.05 in every channel.  By hand:
 *   max abs 0.1 at (1, 0);  max rel 0.1 / 0.5 = 0.2;
 *   sum of squares 3 (0.01) + 3 (0.0025) = 0.0375 over 36 channels:
 *   RMS = sqrt(0.0375 / 36) = 0.032274861218395545;
 *   PSNR = 10 log10(peak^2 / MSE) = 10 log10(0.25 * 36 / 0.0375)
 *        = 10 log10(240) = 23.802112417116060 dB;
 *   over at relative tolerance 0.15: |err| > 0.075: only (1, 0), 1 pixel;
 *   at 0.05: |err| > 0.025: both, 2 pixels.
 */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/image_io.h"
#include "testlib.h"
#include "verify/verify.h"

#ifndef REFRAY_HAVE_PNG
#define REFRAY_HAVE_PNG 0
#endif

enum { W = 4, H = 3, OUT_MAX = 16384 };

static void known_pair(img_buf *a, img_buf *b)
{
    ck_assert_int_eq(img_create(a, W, H), 0);
    ck_assert_int_eq(img_create(b, W, H), 0);
    for (int p = 0; p < 3 * W * H; p++)
        a->rgb[p] = b->rgb[p] = 0.5;
    for (int c = 0; c < 3; c++) {
        img_pixel(a, 1, 0)[c] += 0.1;
        img_pixel(a, 2, 2)[c] -= 0.05;
    }
}

START_TEST(test_metrics_compare_known_differences)
{
    img_buf a, b;
    image_metrics m;
    known_pair(&a, &b);
    metrics_compare(&a, &b, NULL, 0.15, &m);
    ck_assert_near(m.max_abs, 0.1, 1e-15);
    ck_assert_int_eq(m.worst_x, 1);
    ck_assert_int_eq(m.worst_y, 0);
    ck_assert_near(m.max_rel, 0.2, 1e-15);
    ck_assert_near(m.rms, 0.032274861218395545, 1e-15);
    ck_assert_near(m.psnr, 23.802112417116060, 1e-12);
    ck_assert_near(m.peak, 0.5, 0); /* the largest value of B */
    img_free(&a);
    img_free(&b);
}
END_TEST

START_TEST(test_metrics_compare_over_count)
{
    img_buf a, b;
    image_metrics m;
    known_pair(&a, &b);
    metrics_compare(&a, &b, NULL, 0.15, &m);
    ck_assert_int_eq(m.over, 1);
    ck_assert_int_eq(m.compared, W * H);
    metrics_compare(&a, &b, NULL, 0.05, &m);
    ck_assert_int_eq(m.over, 2);
    metrics_compare(&a, &b, NULL, 0.25, &m);
    ck_assert_int_eq(m.over, 0);
    img_free(&a);
    img_free(&b);
}
END_TEST

/* Masking out (1, 0) leaves -0.05 at (2, 2) as the largest error. */
START_TEST(test_metrics_compare_mask)
{
    img_buf a, b;
    image_metrics m;
    unsigned char mask[W * H] = {0};
    known_pair(&a, &b);
    mask[1] = 1;
    metrics_compare(&a, &b, mask, 0.15, &m);
    ck_assert_near(m.max_abs, 0.05, 1e-15);
    ck_assert_int_eq(m.excluded, 1);
    ck_assert_int_eq(m.compared, W * H - 1);
    ck_assert_int_eq(m.over, 0);
    img_free(&a);
    img_free(&b);
}
END_TEST

/* [VERIFY-MAP-1] the scale's ends and stops, and grey. */
START_TEST(test_verify_map_colour_scale)
{
    ck_assert_vec_near(verify_map_colour(0, VERIFY_MAP_COLOUR), vec_make(0, 0, 0), 1e-15);
    ck_assert_vec_near(verify_map_colour(1, VERIFY_MAP_COLOUR), vec_make(1, 1, 1), 1e-15);
    ck_assert_vec_near(verify_map_colour(0.45, VERIFY_MAP_COLOUR), vec_make(0.85, 0.15, 0.15), 1e-15);
    /* halfway from red (0.45) to orange (0.7, [1, 0.55, 0.05]) */
    ck_assert_vec_near(verify_map_colour(0.575, VERIFY_MAP_COLOUR), vec_make(0.925, 0.35, 0.10), 1e-12);
    ck_assert_vec_near(verify_map_colour(0.3, VERIFY_MAP_GREY), vec_make(0.3, 0.3, 0.3), 1e-15);
    ck_assert_vec_near(verify_map_colour(7, VERIFY_MAP_GREY), vec_make(1, 1, 1), 1e-15);
    ck_assert_vec_near(verify_map_colour(-1, VERIFY_MAP_COLOUR), vec_make(0, 0, 0), 1e-15);
}
END_TEST

/* A larger error never looks darker: Rec. 709 luma of the display colour
 * rises along the scale. */
START_TEST(test_verify_map_colour_luma_rises)
{
    double last = -1;
    for (int i = 0; i <= 100; i++) {
        rgb c = verify_map_colour(i / 100.0, VERIFY_MAP_COLOUR);
        double luma = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
        ck_assert_msg(luma > last, "luma falls at e = %.2f", i / 100.0);
        last = luma;
    }
}
END_TEST

/* Grey map of the known pair: (1, 0) white, (2, 2) e = 0.05/0.1 = 0.5,
 * display 0.5, stored linear ((0.5 + 0.055)/1.055)^2.4 = 0.21404114048223255
 * (sRGB, IEC 61966-2-1); others black; a masked pixel teal, display
 * (0, 0.5, 0.5). */
START_TEST(test_verify_diff_map_grey)
{
    img_buf a, b, map;
    unsigned char mask[W * H] = {0};
    known_pair(&a, &b);
    mask[3] = 1;
    ck_assert_int_eq(verify_diff_map(&a, &b, mask, VERIFY_MAP_GREY, &map), 0);
    ck_assert_vec_near(vec_make(img_pixel(&map, 1, 0)[0], img_pixel(&map, 1, 0)[1], img_pixel(&map, 1, 0)[2]),
                       vec_make(1, 1, 1), 1e-15);
    ck_assert_near(img_pixel(&map, 2, 2)[1], 0.21404114048223255, 1e-12);
    ck_assert_near(img_pixel(&map, 0, 0)[0], 0, 0);
    ck_assert_vec_near(vec_make(img_pixel(&map, 3, 0)[0], img_pixel(&map, 3, 0)[1], img_pixel(&map, 3, 0)[2]),
                       vec_make(0, 0.21404114048223255, 0.21404114048223255), 1e-12);
    img_free(&map);
    img_free(&a);
    img_free(&b);
}
END_TEST

START_TEST(test_verify_abs_diff_raw)
{
    img_buf a, b, d;
    known_pair(&a, &b);
    ck_assert_int_eq(verify_abs_diff(&a, &b, NULL, &d), 0);
    ck_assert_near(img_pixel(&d, 1, 0)[2], 0.1, 1e-15);
    ck_assert_near(img_pixel(&d, 2, 2)[0], 0.05, 1e-15);
    ck_assert_near(img_pixel(&d, 0, 1)[0], 0, 0);
    img_free(&d);
    img_buf small;
    ck_assert_int_eq(img_create(&small, 2, 2), 0);
    ck_assert_int_eq(verify_abs_diff(&a, &small, NULL, &d), STATUS_INTERNAL);
    img_free(&small);
    img_free(&a);
    img_free(&b);
}
END_TEST

/* ---- Files and the command line ---- */

typedef struct tmpdir {
    char path[64];
} tmpdir;

static void tmp_make(tmpdir *t)
{
    snprintf(t->path, sizeof t->path, "/tmp/refray-compare-XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(t->path));
}

static const char *tmp_file(const tmpdir *t, const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", t->path, name);
    return buf;
}

static void tmp_remove(const tmpdir *t)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", t->path);
    ck_assert_int_eq(system(cmd), 0);
}

/* The exact bytes of a PGM mask: "P5\n4 3\n255\n" then 255 or 0 a pixel. */
START_TEST(test_verify_mask_write_pgm_bytes)
{
    tmpdir t;
    char path[128], bytes[64];
    unsigned char mask[W * H] = {0};
    mask[5] = 1;
    tmp_make(&t);
    tmp_file(&t, "m.pgm", path, sizeof path);
    char err[256];
    ck_assert_int_eq(verify_mask_write(path, mask, W, H, err, sizeof err), 0);
    FILE *fp = fopen(path, "rb");
    ck_assert_ptr_nonnull(fp);
    size_t n = fread(bytes, 1, sizeof bytes, fp);
    fclose(fp);
    ck_assert_int_eq((int)n, 11 + W * H);
    ck_assert(memcmp(bytes, "P5\n4 3\n255\n", 11) == 0);
    for (int p = 0; p < W * H; p++)
        ck_assert_int_eq((unsigned char)bytes[11 + p], p == 5 ? 255 : 0);
    tmp_remove(&t);
}
END_TEST

/* Written and read back, as PGM and as PFM; a wrong size is refused. */
START_TEST(test_verify_mask_read_round_trip)
{
    tmpdir t;
    char path[128], err[256];
    const char *names[] = {"m.pgm", "m.pfm"};
    unsigned char mask[W * H] = {0}, *back;
    mask[0] = mask[7] = mask[11] = 1;
    tmp_make(&t);
    for (int k = 0; k < 2; k++) {
        tmp_file(&t, names[k], path, sizeof path);
        ck_assert_int_eq(verify_mask_write(path, mask, W, H, err, sizeof err), 0);
        ck_assert_int_eq(verify_mask_read(path, W, H, &back, err, sizeof err), 0);
        ck_assert(memcmp(back, mask, sizeof mask) == 0);
        free(back);
        ck_assert_int_eq(verify_mask_read(path, W + 1, H, &back, err, sizeof err), STATUS_DATA);
        ck_assert_ptr_null(back);
        ck_assert_msg(strstr(err, "4x3") != NULL, "message: %s", err);
    }
    tmp_remove(&t);
}
END_TEST

/* [VERIFY-MASK-1] A mask is black or white only: a PGM byte other than 0
 * and its maxval (1, 128, 254 of 255; 1 of maxval 2), and an image pixel
 * that is grey (0.5), off white (0.99) or coloured (1, 0, 0), is refused
 * with the reason, not read as a mark or not (before: a PGM byte over half
 * the maxval marked, an image value over 0.5; attack 13, finding 4).  0 and
 * maxval 2 read as they are. */
START_TEST(test_verify_mask_read_refuses_grey)
{
    tmpdir t;
    char path[128], err[256];
    unsigned char *back;
    static const char *const pgm[] = {"P5\n4 3\n255\n", "P5\n4 3\n2\n"};
    static const int bytes[][2] = {{0, 1}, {0, 128}, {0, 254}, {1, 1}, {1, 2}};
    tmp_make(&t);
    tmp_file(&t, "m.pgm", path, sizeof path);
    for (size_t k = 0; k < sizeof bytes / sizeof bytes[0]; k++) {
        FILE *f = fopen(path, "wb");
        ck_assert_ptr_nonnull(f);
        fputs(pgm[bytes[k][0]], f);
        for (int p = 0; p < W * H; p++)
            fputc(p == 6 ? bytes[k][1] : 0, f);
        ck_assert_int_eq(fclose(f), 0);
        int st = verify_mask_read(path, W, H, &back, err, sizeof err);
        if (bytes[k][0] == 1 && bytes[k][1] == 2) {
            ck_assert_int_eq(st, 0);
            for (int p = 0; p < W * H; p++)
                ck_assert_int_eq(back[p], p == 6);
            free(back);
            continue;
        }
        ck_assert_msg(st == STATUS_DATA, "byte %d: %d", bytes[k][1], st);
        ck_assert_ptr_null(back);
        ck_assert_msg(strstr(err, MASK_NOT_BINARY) && strstr(err, "pixel (2, 1)"), "message: %s", err);
    }
    static const double px[][3] = {{0.5, 0.5, 0.5}, {0.99, 0.99, 0.99}, {1, 0, 0}};
    static const char *const names[] = {"m.pfm", "m.png"};
    /* A build without libpng writes no PNG: its mask is a PFM only. */
    for (int n = 0; n < (REFRAY_HAVE_PNG ? 2 : 1); n++)
        for (size_t k = 0; k < sizeof px / sizeof px[0]; k++) {
            img_buf img;
            ck_assert_int_eq(img_create(&img, W, H), 0);
            for (int c = 0; c < 3; c++)
                img_pixel(&img, 2, 1)[c] = px[k][c];
            tmp_file(&t, names[n], path, sizeof path);
            ck_assert_int_eq(img_write(path, &img, NULL, err, sizeof err), 0);
            img_free(&img);
            ck_assert_int_eq(verify_mask_read(path, W, H, &back, err, sizeof err), STATUS_DATA);
            ck_assert_ptr_null(back);
            ck_assert_msg(strstr(err, MASK_NOT_BINARY) && strstr(err, "pixel (2, 1)"), "%s: %s", names[n], err);
        }
    tmp_remove(&t);
}
END_TEST

static const char *refray_bin(void)
{
    const char *bin = getenv("REFRAY_BIN");
    if (!bin || !*bin)
        bin = "build/refray";
    ck_assert_msg(access(bin, X_OK) == 0, "no refray binary at %s (set REFRAY_BIN)", bin);
    return bin;
}

/* Runs refray with args (NULL-terminated, args[0] the command), stdout
 * into out, stderr into err (each NUL-terminated, cut at OUT_MAX).
 * Returns the exit code, -1 when it did not exit normally. */
static int run_refray(const char *const *args, char *out, char *err)
{
    const char *bin = refray_bin();
    char *argv[16];
    int n = 0;
    argv[n++] = (char *)bin;
    while (args[n - 1] && n < 15) {
        argv[n] = (char *)args[n - 1];
        n++;
    }
    argv[n] = NULL;
    int po[2], pe[2];
    ck_assert_int_eq(pipe(po), 0);
    ck_assert_int_eq(pipe(pe), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        dup2(po[1], 1);
        dup2(pe[1], 2);
        close(po[0]);
        close(pe[0]);
        execv(bin, argv);
        _exit(127);
    }
    close(po[1]);
    close(pe[1]);
    size_t no = 0, ne = 0;
    ssize_t got = 1;
    /* Outputs are small: read stdout to the end, then stderr. */
    while ((got = read(po[0], out + no, OUT_MAX - 1 - no)) > 0)
        no += (size_t)got;
    while ((got = read(pe[0], err + ne, OUT_MAX - 1 - ne)) > 0)
        ne += (size_t)got;
    out[no] = err[ne] = '\0';
    close(po[0]);
    close(pe[0]);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The number after "key": in a JSON text. */
static double json_value(const char *json, const char *key)
{
    char pattern[64];
    snprintf(pattern, sizeof pattern, "\"%s\": ", key);
    const char *p = strstr(json, pattern);
    ck_assert_msg(p != NULL, "no %s in %s", key, json);
    return strtod(p + strlen(pattern), NULL);
}

static void write_pair(const tmpdir *t, char *pa, char *pb, size_t size)
{
    img_buf a, b;
    char err[256];
    known_pair(&a, &b);
    ck_assert_int_eq(img_write(tmp_file(t, "a.pfm", pa, size), &a, NULL, err, sizeof err), 0);
    ck_assert_int_eq(img_write(tmp_file(t, "b.pfm", pb, size), &b, NULL, err, sizeof err), 0);
    img_free(&a);
    img_free(&b);
}

/* PFM holds floats: 0.6f - 0.5 = 0.10000002384185791, so 1e-6 slack. */
START_TEST(test_cli_compare_json_and_exit)
{
    tmpdir t;
    char pa[128], pb[128], out[OUT_MAX], err[OUT_MAX];
    tmp_make(&t);
    write_pair(&t, pa, pb, sizeof pa);
    const char *over[] = {"compare", pa, pb, "--tolerance", "0.15", "--json", NULL};
    ck_assert_int_eq(run_refray(over, out, err), 1);
    ck_assert_near(json_value(out, "max_abs"), 0.1, 1e-6);
    ck_assert_near(json_value(out, "rms"), 0.032274861218395545, 1e-6);
    ck_assert_near(json_value(out, "psnr"), 23.802112417116060, 1e-4);
    ck_assert_near(json_value(out, "over"), 1, 0);
    ck_assert_near(json_value(out, "tolerance"), 0.15, 1e-15);
    const char *within[] = {"compare", pa, pb, "--tolerance", "0.25", NULL};
    ck_assert_int_eq(run_refray(within, out, err), 0);
    ck_assert_msg(strstr(out, "over:     0 pixels") != NULL, "output: %s", out);
    const char *no_tol[] = {"compare", pa, pb, NULL};
    ck_assert_int_eq(run_refray(no_tol, out, err), 0);
    ck_assert_msg(strstr(out, "differ:   2 pixels") != NULL, "output: %s", out);
    tmp_remove(&t);
}
END_TEST

START_TEST(test_cli_compare_errors)
{
    tmpdir t;
    char pa[128], pb[128], pc[128], out[OUT_MAX], err[OUT_MAX], e2[256];
    tmp_make(&t);
    write_pair(&t, pa, pb, sizeof pa);
    img_buf c;
    ck_assert_int_eq(img_create(&c, W + 1, H), 0);
    ck_assert_int_eq(img_write(tmp_file(&t, "c.pfm", pc, sizeof pc), &c, NULL, e2, sizeof e2), 0);
    img_free(&c);
    const char *sizes[] = {"compare", pa, pc, NULL};
    ck_assert_int_eq(run_refray(sizes, out, err), 65);
    ck_assert_msg(strstr(err, "differ in size") && strstr(err, "4x3") && strstr(err, "5x3"), "stderr: %s", err);
    const char *missing[] = {"compare", pa, "/nonexistent/x.pfm", NULL};
    ck_assert_int_eq(run_refray(missing, out, err), 66);
    const char *one[] = {"compare", pa, NULL};
    ck_assert_int_eq(run_refray(one, out, err), 64);
    const char *neg[] = {"compare", pa, pb, "--tolerance", "-1", NULL};
    ck_assert_int_eq(run_refray(neg, out, err), 64);
    tmp_remove(&t);
}
END_TEST

/* --diff writes the map (read back: the largest error white, equal pixels
 * black); --mask removes pixel (1, 0) from the comparison. */
START_TEST(test_cli_compare_diff_and_mask)
{
    tmpdir t;
    char pa[128], pb[128], pm[128], pd[128], out[OUT_MAX], err[OUT_MAX], e2[256];
    tmp_make(&t);
    write_pair(&t, pa, pb, sizeof pa);
    const char *diff[] = {"compare", pa, pb, "--diff", tmp_file(&t, "d.pfm", pd, sizeof pd), NULL};
    ck_assert_int_eq(run_refray(diff, out, err), 0);
    img_buf d;
    ck_assert_int_eq(img_read(pd, NULL, &d, e2, sizeof e2), 0);
    ck_assert_near(img_pixel(&d, 1, 0)[0], 0.1, 1e-6);
    ck_assert_near(img_pixel(&d, 0, 0)[0], 0, 0);
    img_free(&d);
    unsigned char mask[W * H] = {0};
    mask[1] = 1;
    ck_assert_int_eq(verify_mask_write(tmp_file(&t, "m.pgm", pm, sizeof pm), mask, W, H, e2, sizeof e2), 0);
    const char *masked[] = {"compare", pa, pb, "--mask", pm, "--json", "--tolerance", "0.05", NULL};
    ck_assert_int_eq(run_refray(masked, out, err), 1);
    ck_assert_near(json_value(out, "max_abs"), 0.05, 1e-6);
    ck_assert_near(json_value(out, "excluded"), 1, 0);
    ck_assert_near(json_value(out, "over"), 1, 0);
    tmp_remove(&t);
}
END_TEST

Suite *suite_compare(void)
{
    Suite *s = suite_create("compare");
    TCase *tc = tcase_create("compare");
    tcase_add_test(tc, test_metrics_compare_known_differences);
    tcase_add_test(tc, test_metrics_compare_over_count);
    tcase_add_test(tc, test_metrics_compare_mask);
    tcase_add_test(tc, test_verify_map_colour_scale);
    tcase_add_test(tc, test_verify_map_colour_luma_rises);
    tcase_add_test(tc, test_verify_diff_map_grey);
    tcase_add_test(tc, test_verify_abs_diff_raw);
    tcase_add_test(tc, test_verify_mask_write_pgm_bytes);
    tcase_add_test(tc, test_verify_mask_read_round_trip);
    tcase_add_test(tc, test_verify_mask_read_refuses_grey);
    tcase_add_test(tc, test_cli_compare_json_and_exit);
    tcase_add_test(tc, test_cli_compare_errors);
    tcase_add_test(tc, test_cli_compare_diff_and_mask);
    suite_add_tcase(s, tc);
    return s;
}
