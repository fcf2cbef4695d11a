/*
 * povcheck.c - the measuring half of `make crosscheck` (tests/crosscheck.sh,
 * spec/crosscheck.md): another renderer's image of an analytic scene
 * against the scene's exact image, and refray's own check of the scene,
 * each as one line of shell assignments for the script.
 *
 *   povcheck exact SCENE              family, peak of the exact image, excluded pixels
 *   povcheck compare SCENE IMAGE K S  IMAGE (K times the scene's size: K x K
 *                                     blocks are averaged first, then divided by S,
 *                                     the export's --scale) against the exact image
 *   povcheck refray SCENE             verify_scene: what `refray verify` reports
 *
 * The exact image and its excluded pixels come from verify_exact_build, the
 * same as `refray verify` and `refray oracle` use, so every renderer is
 * measured on the same pixels.  Values are printed with %.6g: a table, not
 * a test.  Reasons (refusals, errors) go to stderr; exit 0 when the line was
 * printed, else the scene's exit code.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "image/image_file.h"
#include "image/metrics.h"
#include "verify/verify.h"

static scene_model *load(const char *path, int *status)
{
    scene_limits limits = scene_default_limits();
    return scene_file_load(path, &limits, stderr, 0, status);
}

/* The exact image of the scene as written; 0 or an exit code. */
static int exact_of(const scene_model *s, verify_exact *e)
{
    verify_opts none;
    char why[512];
    int status;
    memset(&none, 0, sizeof none);
    oracle_view v = verify_view(s, &none);
    const oracle_family *f = verify_family(s, &v, &status, why, sizeof why);
    if (!f) {
        fprintf(stderr, "povcheck: %s\n", why);
        return status;
    }
    return verify_exact_build(f, &v, e);
}

/* Averages k x k blocks of in into out (the scene's size). */
static int downsample(const img_buf *in, int k, img_buf *out)
{
    if (k < 1 || in->width % k || in->height % k || img_create(out, in->width / k, in->height / k))
        return 0;
    for (int y = 0; y < out->height; y++)
        for (int x = 0; x < out->width; x++)
            for (int c = 0; c < 3; c++) {
                double sum = 0;
                for (int j = 0; j < k; j++)
                    for (int i = 0; i < k; i++)
                        sum += img_pixel(in, k * x + i, k * y + j)[c];
                img_pixel(out, x, y)[c] = sum / (k * k);
            }
    return 1;
}

/* max |a - b| / |b| over the channels whose exact value is above 1% of the
 * peak: the relative error a 16-bit file can show (its step is 1.5e-5 of
 * full scale, so near-black channels give any relative error at all). */
static double max_rel_bright(const img_buf *a, const img_buf *b, const unsigned char *excluded, double peak)
{
    double worst = 0;
    for (int y = 0; y < b->height; y++)
        for (int x = 0; x < b->width; x++) {
            if (excluded && excluded[(size_t)y * b->width + x])
                continue;
            for (int c = 0; c < 3; c++) {
                double want = img_pixel(b, x, y)[c];
                if (fabs(want) > 0.01 * peak)
                    worst = fmax(worst, fabs(img_pixel(a, x, y)[c] - want) / fabs(want));
            }
        }
    return worst;
}

static int cmd_exact(const char *path)
{
    int status;
    verify_exact e;
    scene_model *s = load(path, &status);
    if (!s)
        return status;
    status = exact_of(s, &e);
    if (status == 0) {
        double peak = 0;
        for (size_t i = 0; i < 3 * (size_t)e.image.width * e.image.height; i++)
            peak = fmax(peak, e.image.rgb[i]);
        printf("family=%s peak=%.6g excluded=%ld pixels=%d\n", e.family->name, peak, e.excluded_count,
               e.image.width * e.image.height);
        verify_exact_free(&e);
    }
    scene_free(s);
    return status;
}

static int compare_image(const verify_exact *e, const char *image, int k, double scale)
{
    img_buf raw, img;
    image_metrics m;
    char err[512];
    if (img_read(image, &raw, err, sizeof err) != 0) {
        fprintf(stderr, "povcheck: %s\n", err);
        return STATUS_NO_INPUT;
    }
    int ok = downsample(&raw, k, &img) && img.width == e->image.width && img.height == e->image.height;
    img_free(&raw);
    if (!ok) {
        fprintf(stderr, "povcheck: %s is not %d times %dx%d\n", image, k, e->image.width, e->image.height);
        img_free(&img);
        return STATUS_DATA;
    }
    for (size_t i = 0; i < 3 * (size_t)img.width * img.height; i++)
        img.rgb[i] /= scale;
    metrics_compare(&img, &e->image, e->excluded, 1e-9, &m);
    printf("max_abs=%.6g rms=%.6g max_rel=%.6g max_rel_bright=%.6g compared=%ld excluded=%ld worst=%d,%d\n",
           m.max_abs, m.rms, m.max_rel, max_rel_bright(&img, &e->image, e->excluded, m.peak), m.compared,
           m.excluded, m.worst_x, m.worst_y);
    img_free(&img);
    return 0;
}

static int cmd_compare(const char *path, const char *image, int k, double scale)
{
    int status;
    verify_exact e;
    scene_model *s = load(path, &status);
    if (!s)
        return status;
    status = exact_of(s, &e);
    if (status == 0) {
        status = compare_image(&e, image, k, scale);
        verify_exact_free(&e);
    }
    scene_free(s);
    return status;
}

static const char *verdict_word(verify_verdict v)
{
    return v == VERIFY_PASS ? "pass" : v == VERIFY_FAIL ? "FAIL" : v == VERIFY_REFUSED ? "refused" : "error";
}

static int cmd_refray(const char *path)
{
    int status;
    verify_opts none;
    verify_result r;
    scene_model *s = load(path, &status);
    if (!s)
        return status;
    memset(&none, 0, sizeof none);
    memset(&r, 0, sizeof r);
    verify_scene(s, path, &none, &r);
    scene_free(s);
    if (r.verdict != VERIFY_PASS && r.verdict != VERIFY_FAIL) {
        fprintf(stderr, "povcheck: %s\n", r.reason);
        return r.status ? r.status : STATUS_FAIL;
    }
    printf("max_abs=%.6g rms=%.6g max_rel=%.6g seconds=%.6g tolerance=%.3g verdict=%s rays=%ld\n",
           r.metrics.max_abs, r.metrics.rms, r.metrics.max_rel, r.render_seconds, r.tolerance,
           verdict_word(r.verdict), r.rays);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "exact") == 0)
        return cmd_exact(argv[2]);
    if (argc == 6 && strcmp(argv[1], "compare") == 0 && atof(argv[5]) > 0)
        return cmd_compare(argv[2], argv[3], atoi(argv[4]), atof(argv[5]));
    if (argc == 3 && strcmp(argv[1], "refray") == 0)
        return cmd_refray(argv[2]);
    fputs("usage: povcheck exact SCENE | compare SCENE IMAGE K SCALE | refray SCENE\n", stderr);
    return STATUS_USAGE;
}
