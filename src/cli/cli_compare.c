/*
 * cli_compare.c - `refray compare A B`: the metrics of verify for any two
 * image files, B the reference, and an error map.  The images are compared
 * as img_read returns them: EXR and PFM values as stored, PNG and PPM codes
 * decoded to linear values.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/image_file.h"
#include "cli/cli_args.h"
#include "cli/commands.h"

static const char compare_help[] =
    "usage: refray compare A B [OPTIONS]\n"
    "Compares image A with the reference B (.exr .pfm .png .ppm; PNG and PPM are\n"
    "decoded to linear values) and prints max abs, RMS and max rel error, PSNR and\n"
    "the pixels over a tolerance.\n"
    "options:\n"
    "  --tolerance REL   count the pixels where some channel has\n"
    "                    |A - B| > REL * max(|B|, 1e-12 * peak); exit 1 if any\n"
    "  --diff MAP        write an error map.  .png/.ppm: e = max over channels\n"
    "                    |A - B| / (max abs), on the scale\n"
    "                      black (0, equal) - purple - red - orange - yellow - white\n"
    "                      (1, the largest error); teal: excluded by --mask.\n"
    "                    .exr/.pfm: |A - B| per channel, not scaled.\n"
    "  --grey            the map in grey levels (black 0, white the largest error)\n"
    "  --mask FILE       skip the pixels a mask marks (.pgm or an image, as\n"
    "                    `refray oracle --mask` writes it)\n"
    "  --json            one JSON object on stdout instead of the text (without\n"
    "                    --tolerance: \"tolerance\" null, \"over\" the pixels that differ)\n"
    "exit: 0; 1 some pixel over --tolerance; 64 usage; 65 unreadable images or\n"
    "images of different sizes; 66 a missing file; 74 the map could not be written.\n";

typedef struct compare_args {
    const char *a, *b, *diff, *mask;
    double tolerance;
    int has_tolerance, grey, json;
} compare_args;

/* 1: consumed, 0: error (reported), -1: not a compare option. */
static int compare_option(compare_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i], *v;
    if (strcmp(opt, "--diff") == 0)
        return cli_take_value(argc, argv, i, &a->diff);
    if (strcmp(opt, "--mask") == 0)
        return cli_take_value(argc, argv, i, &a->mask);
    if (strcmp(opt, "--grey") == 0 || strcmp(opt, "--gray") == 0)
        return a->grey = 1;
    if (strcmp(opt, "--json") == 0)
        return a->json = 1;
    if (strcmp(opt, "--tolerance") != 0)
        return -1;
    if (!cli_take_value(argc, argv, i, &v) || !cli_parse_double(opt, v, &a->tolerance))
        return 0;
    if (a->tolerance < 0) {
        cli_usage_error("--tolerance must be >= 0, not '%s'", v);
        return 0;
    }
    return a->has_tolerance = 1;
}

static int parse_args(compare_args *a, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(compare_help, stdout);
            return -1;
        }
        if (argv[i][0] != '-' || !argv[i][1]) {
            if (a->b)
                return cli_usage_error("compare: two images, A and B, not '%s' as well", argv[i]);
            *(a->a ? &a->b : &a->a) = argv[i];
            continue;
        }
        int r = compare_option(a, argc, argv, &i);
        if (r == 0)
            return STATUS_USAGE;
        if (r < 0)
            return cli_usage_error("compare: unknown option '%s'", argv[i]);
    }
    if (!a->b)
        return cli_usage_error("compare: needs two images, A and the reference B");
    if (a->diff && img_format_from_path(a->diff) == IMG_FORMAT_UNKNOWN)
        return cli_usage_error("compare: '%s' has no known image extension (.png .exr .pfm .ppm)", a->diff);
    return 0;
}

static int read_image(const char *path, img_buf *img)
{
    char err[512];
    int status = img_read(path, img, err, sizeof err);
    if (status != STATUS_OK)
        fprintf(stderr, "refray: error: %s\n", err);
    return status;
}

static void print_text(const compare_args *a, const img_buf *img, const image_metrics *m)
{
    printf("A:        %s\nB:        %s (reference)\n", a->a, a->b);
    printf("size:     %dx%d: %ld pixels compared, %ld excluded\n", img->width, img->height, m->compared,
           m->excluded);
    printf("max abs:  %.6e at pixel (%d, %d)\n", m->max_abs, m->worst_x, m->worst_y);
    printf("RMS:      %.6e\n", m->rms);
    printf("max rel:  %.6e\n", m->max_rel);
    if (m->psnr < 1e300)
        printf("PSNR:     %.2f dB (peak %.6g)\n", m->psnr, m->peak);
    else
        printf("PSNR:     inf (the images are equal)\n");
    if (a->has_tolerance)
        printf("over:     %ld pixel%s over the relative tolerance %.3g\n", m->over, m->over == 1 ? "" : "s",
               a->tolerance);
    else
        printf("differ:   %ld pixel%s differ at all (no --tolerance: exit 0)\n", m->over, m->over == 1 ? "" : "s");
}

static void print_json(const compare_args *a, const image_metrics *m)
{
    fputs("{\"a\": ", stdout);
    verify_json_string(stdout, a->a);
    fputs(", \"b\": ", stdout);
    verify_json_string(stdout, a->b);
    fputs(", ", stdout);
    verify_json_metrics(stdout, m, a->has_tolerance ? a->tolerance : NAN);
    fputs("}\n", stdout);
}

static int write_map(const compare_args *a, const img_buf *x, const img_buf *ref, const unsigned char *mask)
{
    img_buf map;
    img_format fmt = img_format_from_path(a->diff);
    int raw = fmt == IMG_FORMAT_EXR || fmt == IMG_FORMAT_PFM;
    int status = raw ? verify_abs_diff(x, ref, mask, &map) : verify_diff_map(x, ref, mask, a->grey, &map);
    char err[512] = "out of memory making the error map";
    if (status == STATUS_OK) {
        img_write_opts wo = img_write_opts_default();
        wo.exr_float = 1;
        status = img_write(a->diff, &map, &wo, err, sizeof err);
        img_free(&map);
    }
    if (status != STATUS_OK)
        fprintf(stderr, "refray: error: %s\n", err);
    return status;
}

/* Compares the two loaded images; returns the exit code. */
static int compare_images(const compare_args *a, const img_buf *x, const img_buf *ref)
{
    if (x->width != ref->width || x->height != ref->height) {
        fprintf(stderr, "refray: error: the images differ in size: '%s' is %dx%d, '%s' is %dx%d\n", a->a, x->width,
                x->height, a->b, ref->width, ref->height);
        return STATUS_DATA;
    }
    unsigned char *mask = NULL;
    char err[512];
    int status = a->mask ? verify_mask_read(a->mask, ref->width, ref->height, &mask, err, sizeof err) : STATUS_OK;
    if (status != STATUS_OK) {
        fprintf(stderr, "refray: error: %s: %s\n", a->mask, err);
        return status;
    }
    image_metrics m;
    metrics_compare(x, ref, mask, a->has_tolerance ? a->tolerance : 0, &m);
    status = a->diff ? write_map(a, x, ref, mask) : STATUS_OK;
    free(mask);
    if (status != STATUS_OK)
        return status;
    if (a->json)
        print_json(a, &m);
    else
        print_text(a, x, &m);
    return a->has_tolerance && m.over > 0 ? STATUS_FAIL : STATUS_OK;
}

int cli_compare(int argc, char **argv)
{
    compare_args a;
    memset(&a, 0, sizeof a);
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    img_buf x = {0}, ref = {0};
    status = read_image(a.a, &x);
    if (status == STATUS_OK)
        status = read_image(a.b, &ref);
    if (status == STATUS_OK)
        status = compare_images(&a, &x, &ref);
    img_free(&x);
    img_free(&ref);
    return status;
}
