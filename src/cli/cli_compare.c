/*
 * cli_compare.c - `refray compare A B`: the metrics of verify for any two
 * image files, B the reference, and an error map.  The images are compared
 * as img_read returns them: EXR and PFM values as stored, PNG and PPM codes
 * decoded to linear values.  A may first be averaged over blocks and scaled
 * (--downsample, --scale); with --manifest the tolerance, the mask and, if
 * B is not given, B itself come from a conformance kit (spec/conformance.md).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/fileio.h"
#include "image/adjust.h"
#include "io/image_io.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "verify/conform.h"

static const char compare_help[] =
    "usage: refray compare A B [OPTIONS]\n"
    "       refray compare A [B] --manifest KIT/manifest.json [--scene NAME] [OPTIONS]\n"
    "Compares image A with the reference B (.exr .pfm .png .ppm; PNG and PPM are\n"
    "decoded to linear values) and prints max abs, RMS and max rel error, PSNR and\n"
    "the pixels over a tolerance.\n"
    "options:\n"
    "  --tolerance REL   count the pixels where some channel has\n"
    "                    |A - B| > REL * max(|B|, 1e-12 * peak); exit 1 if any\n"
    "  --diff MAP        write an error map.  .png/.ppm: e = max over channels\n"
    "                    |A - B| / (max abs), on the scale\n"
    "                      black (0, equal) - purple - red - orange - yellow - white\n"
    "                      (1, the largest error); teal: excluded by --mask;\n"
    "                      green: A or B not finite there.\n"
    "                    .exr/.pfm: |A - B| per channel, not scaled.\n"
    "  --grey            the map in grey levels (black 0, white the largest error)\n"
    "  --mask FILE       skip the pixels a mask marks (.pgm or an image, as\n"
    "                    `refray oracle --mask` writes it)\n"
    "  --json            one JSON object on stdout instead of the text (without\n"
    "                    --tolerance: \"tolerance\" null, \"over\" the pixels that differ)\n"
    "  --downsample K    average K x K blocks of A first (A rendered K times larger)\n"
    "  --scale S         then multiply A by S (S > 0)\n"
    "  --manifest FILE   a kit's manifest.json: the scene's tolerance (|A - B| >\n"
    "                    relative |B| + absolute is over; exit 1 if any) and mask;\n"
    "                    B defaults to the scene's exact image; 'manifest' as the\n"
    "                    value of --downsample or --scale takes the scene's samples\n"
    "                    or 1 / png16_scale\n"
    "  --scene NAME      the kit's scene (default: the one whose exact image is B)\n"
    "  --max-pixels N    refuse an image whose header claims more pixels (67108864)\n"
    "A pixel where A or B is NaN or infinite always fails: it is counted, its\n"
    "first position printed, and shown pure green in the map (the largest\n"
    "value in an .exr/.pfm map); the other figures are over the finite pixels.\n"
    "exit: 0; 1 some pixel over the tolerance, or a non-finite pixel; 64 usage;\n"
    "65 unreadable images or images of different sizes (refused on their headers,\n"
    "before decoding); 66 a missing file; 74 the map could not be written.\n";

typedef struct compare_args {
    const char *a, *b, *diff, *mask, *manifest, *scene;
    long max_pixels;                /* --max-pixels: what an image header may claim */
    double tolerance;
    int has_tolerance, grey, json;
    conform_adjust adjust;          /* downsample 1 and scale 1: A as read */
} compare_args;

/* The kit's side of --manifest: the scene, its tolerance and files. */
typedef struct compare_kit {
    manifest m;
    const manifest_scene *scene;
    char *dir;                      /* the manifest's directory */
    char *exact;                    /* B when not given (malloc'd) */
} compare_kit;

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
    if (strcmp(opt, "--manifest") == 0)
        return cli_take_value(argc, argv, i, &a->manifest);
    if (strcmp(opt, "--scene") == 0)
        return cli_take_value(argc, argv, i, &a->scene);
    if (strcmp(opt, "--downsample") == 0 || strcmp(opt, "--scale") == 0)
        return cli_adjust_option(&a->adjust, argc, argv, i);
    if (strcmp(opt, "--max-pixels") == 0)
        return cli_take_value(argc, argv, i, &v) && cli_parse_long(opt, v, 1, 1000000000, &a->max_pixels);
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
    if (!a->a || (!a->b && !a->manifest))
        return cli_usage_error("compare: needs two images, A and the reference B");
    if (a->manifest && (a->has_tolerance || a->mask))
        return cli_usage_error("compare: --manifest gives the tolerance and the mask: drop %s",
                               a->has_tolerance ? "--tolerance" : "--mask");
    if (!a->manifest && (a->scene || a->adjust.downsample == CONFORM_FROM_MANIFEST ||
                         a->adjust.scale == CONFORM_FROM_MANIFEST))
        return cli_usage_error("compare: %s needs --manifest", a->scene ? "--scene" : "'manifest' as a value");
    if (a->diff && img_format_from_path(a->diff) == IMG_FORMAT_UNKNOWN)
        return cli_usage_error("compare: '%s' has no known image extension (.png .exr .pfm .ppm)", a->diff);
    return 0;
}

/* Reads path, refusing on its header any size but width x height and more
 * pixels than --max-pixels ([REL-IMAGE-1]). */
static int read_image(const compare_args *a, const char *path, int width, int height, img_buf *img)
{
    char err[1024];
    img_read_opts o = img_read_opts_default();
    o.max_pixels = a->max_pixels;
    o.width = width;
    o.height = height;
    int status = img_read(path, &o, img, err, sizeof err);
    if (status != STATUS_OK)
        cli_error("%s", err);
    return status;
}

/* The sizes in the headers of A and B, nothing decoded yet. */
static int read_sizes(const compare_args *a, int size[2][2])
{
    const char *paths[2] = {a->a, a->b};
    img_read_opts o = img_read_opts_default();
    o.max_pixels = a->max_pixels;
    for (int i = 0; i < 2; i++) {
        char err[1024];
        int status = img_read_size(paths[i], &o, &size[i][0], &size[i][1], err, sizeof err);
        if (status != STATUS_OK) {
            cli_error("%s", err);
            return status;
        }
    }
    return STATUS_OK;
}

/* A must be k times B each way (k = 1 without --downsample): refused
 * before either image is decoded, so a small file claiming a huge size
 * costs nothing. */
static int check_sizes(const compare_args *a, const compare_kit *kit, int size[2][2])
{
    int k = kit ? conform_downsample_of(&a->adjust, kit->scene) : a->adjust.downsample;
    if ((long)size[0][0] == (long)k * size[1][0] && (long)size[0][1] == (long)k * size[1][1])
        return STATUS_OK;
    if (k > 1)
        cli_error("with --downsample %d, '%s' must be %ldx%ld (%d times '%s', %dx%d), not %dx%d", k, a->a,
                  (long)k * size[1][0], (long)k * size[1][1], k, a->b, size[1][0], size[1][1], size[0][0],
                  size[0][1]);
    else
        cli_error("the images differ in size: '%s' is %dx%d, '%s' is %dx%d", a->a, size[0][0], size[0][1], a->b,
                  size[1][0], size[1][1]);
    return STATUS_DATA;
}

static void print_text(const compare_args *a, const compare_kit *kit, const img_buf *img, const image_metrics *m)
{
    printf("A:        %s\nB:        %s (reference)\n", a->a, a->b);
    int k = kit ? conform_downsample_of(&a->adjust, kit->scene) : a->adjust.downsample;
    double scale = kit ? conform_scale_of(&a->adjust, kit->scene) : a->adjust.scale;
    if (k != 1 || scale != 1)
        printf("adjusted: A averaged over %dx%d blocks, then times %.17g\n", k, k, scale);
    printf("size:     %dx%d: %ld pixels compared, %ld excluded\n", img->width, img->height, m->compared,
           m->excluded);
    const char *finite = m->nonfinite ? " (finite pixels)" : "";
    if (m->nonfinite)
        printf("NON-FINITE: %ld pixel%s where A or B is NaN or infinite, the first at (%d, %d): each one fails\n",
               m->nonfinite, m->nonfinite == 1 ? "" : "s", m->nonfinite_x, m->nonfinite_y);
    printf("max abs:  %.6e at pixel (%d, %d)%s\n", m->max_abs, m->worst_x, m->worst_y, finite);
    printf("RMS:      %.6e%s\n", m->rms, finite);
    printf("max rel:  %.6e%s\n", m->max_rel, finite);
    if (m->psnr < 1e300)
        printf("PSNR:     %.2f dB (peak %.6g)%s\n", m->psnr, m->peak, finite);
    else if (m->nonfinite)
        printf("PSNR:     not defined (non-finite pixels)\n");
    else
        printf("PSNR:     inf (the images are equal)\n");
    if (kit)
        printf("over:     %ld pixel%s over |A - B| <= %.3g |B| + %.3g (scene %s of %s)\n", m->over,
               m->over == 1 ? "" : "s", kit->scene->relative,
               conform_absolute(kit->scene, conform_picture_quantized(a->a)), kit->scene->name, a->manifest);
    else if (a->has_tolerance)
        printf("over:     %ld pixel%s over the relative tolerance %.3g\n", m->over, m->over == 1 ? "" : "s",
               a->tolerance);
    else
        printf("differ:   %ld pixel%s differ at all (no --tolerance: exit 0)\n", m->over, m->over == 1 ? "" : "s");
}

static void print_json(const compare_args *a, const compare_kit *kit, const image_metrics *m)
{
    fputs("{\"a\": ", stdout);
    verify_json_string(stdout, a->a);
    fputs(", \"b\": ", stdout);
    verify_json_string(stdout, a->b);
    fputs(", ", stdout);
    verify_json_metrics(stdout, m, kit ? kit->scene->relative : a->has_tolerance ? a->tolerance : NAN);
    if (kit) {
        fputs(", \"tolerance_absolute\": ", stdout);
        verify_json_number(stdout, conform_absolute(kit->scene, conform_picture_quantized(a->a)));
        fputs(", \"scene\": ", stdout);
        verify_json_string(stdout, kit->scene->name);
    }
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
        cancel_poll cancel = cancel_poll_make(cli_signal_cancel, NULL);
        img_write_opts wo = img_write_opts_default();
        wo.exr_float = 1;
        wo.cancel = &cancel;
        cli_signal_cooperate(1);
        status = img_write(a->diff, &map, &wo, err, sizeof err);
        cli_signal_cooperate(0);
        img_free(&map);
    }
    if (status != STATUS_OK)
        cli_error("%s", err);
    return status;
}

/* The mask: --mask, or the kit's (conform_kit_mask: checked against the
 * manifest, [KIT-MASK-1]; and the kit's tolerance checked to carry a
 * verdict at B, [VERIFY-UNBOUNDED-3]); NULL for none.  STATUS_OK or the
 * status (*mask NULL then). */
static int read_mask(const compare_args *a, const compare_kit *kit, const img_buf *ref, unsigned char **mask)
{
    char err[1024];
    int status = STATUS_OK;
    *mask = NULL;
    if (a->mask) {
        status = verify_mask_read(a->mask, ref->width, ref->height, mask, err, sizeof err);
        if (status != STATUS_OK)
            cli_error("%s: %s", a->mask, err);
    } else if (kit) {
        status = conform_kit_mask(kit->dir, kit->scene, ref->width, ref->height, mask, err, sizeof err);
        if (status == STATUS_OK)
            status = conform_kit_decisive(kit->scene, ref, *mask, err, sizeof err);
        if (status != STATUS_OK) {
            cli_error("compare: %s: scene '%s': %s", a->manifest, kit->scene->name, err);
            free(*mask);
            *mask = NULL;
        }
    }
    return status;
}

/* Compares the two loaded images; returns the status. */
static int compare_images(const compare_args *a, const compare_kit *kit, const img_buf *x, const img_buf *ref)
{
    unsigned char *mask = NULL;
    int status = read_mask(a, kit, ref, &mask);
    if (status != STATUS_OK)
        return status;
    image_metrics m;
    int pass = 0;
    if (kit)
        pass = conform_rule(x, ref, mask, kit->scene, conform_picture_quantized(a->a), &m);
    else
        metrics_compare(x, ref, mask, a->has_tolerance ? a->tolerance : 0, &m);
    status = a->diff ? write_map(a, x, ref, mask) : STATUS_OK;
    free(mask);
    if (status != STATUS_OK)
        return status;
    if (a->json)
        print_json(a, kit, &m);
    else
        print_text(a, kit, x, &m);
    /* A NaN or an infinity fails with or without a tolerance. */
    if (kit)
        return pass ? STATUS_OK : STATUS_FAIL;
    return (a->has_tolerance && m.over > 0) || m.nonfinite > 0 ? STATUS_FAIL : STATUS_OK;
}

/* A averaged over k x k blocks and scaled, in place (the sizes are
 * checked already); STATUS_OK or the status. */
static int adjust_image(const compare_args *a, const compare_kit *kit, img_buf *x)
{
    int k = kit ? conform_downsample_of(&a->adjust, kit->scene) : a->adjust.downsample;
    double scale = kit ? conform_scale_of(&a->adjust, kit->scene) : a->adjust.scale;
    if (k > 1) {
        img_buf small;
        int status = img_downsample(x, k, &small);
        if (status != STATUS_OK)
            return status;
        img_free(x);
        *x = small;
    }
    if (scale != 1)
        img_scale(x, scale);
    return STATUS_OK;
}

/* 1 when path names the kit file rel: equal, or ending in "/" rel. */
static int names_file(const char *path, const char *rel)
{
    size_t n = strlen(path), r = strlen(rel);
    return r > 0 && n >= r && strcmp(path + n - r, rel) == 0 && (n == r || path[n - r - 1] == '/');
}

/* The scene of --scene, or the one whose exact image B is. */
static const manifest_scene *kit_scene(const compare_args *a, const manifest *m)
{
    if (a->scene) {
        const manifest_scene *s = manifest_find(m, a->scene);
        if (!s)
            cli_usage_error("compare: %s has no scene '%s'", a->manifest, a->scene);
        return s;
    }
    for (int i = 0; a->b && i < m->scene_count; i++)
        if (names_file(a->b, m->scenes[i].files[MANIFEST_FILE_EXACT_EXR]) ||
            names_file(a->b, m->scenes[i].files[MANIFEST_FILE_EXACT_PFM]))
            return &m->scenes[i];
    if (m->scene_count == 1)
        return &m->scenes[0];
    if (a->b)
        cli_usage_error("compare: name the kit's scene with --scene NAME ('%s' is not one of its exact images)",
                        a->b);
    else
        cli_usage_error("compare: name the kit's scene with --scene NAME (no B given; the kit has %d scenes)",
                        m->scene_count);
    return NULL;
}

/* Reads --manifest and picks the scene; B defaults to its exact image. */
static int load_kit(compare_args *a, compare_kit *kit)
{
    char why[1024];
    int status = manifest_read(a->manifest, &kit->m, why, sizeof why);
    if (status != STATUS_OK) {
        cli_error("compare: %s", why);
        return status;
    }
    kit->dir = file_dirname(NULL, a->manifest);
    if (!(kit->scene = kit_scene(a, &kit->m)))
        return STATUS_USAGE;
    if (!a->b) {
        const manifest_scene *s = kit->scene;
        int exr = s->files[MANIFEST_FILE_EXACT_EXR][0] && img_format_available(IMG_FORMAT_EXR);
        kit->exact = file_join(NULL, kit->dir, s->files[exr ? MANIFEST_FILE_EXACT_EXR : MANIFEST_FILE_EXACT_PFM]);
        a->b = kit->exact;
    }
    return kit->dir && a->b ? STATUS_OK : STATUS_NO_MEMORY;
}

int cli_compare(int argc, char **argv)
{
    compare_args a;
    compare_kit kit;
    memset(&a, 0, sizeof a);
    memset(&kit, 0, sizeof kit);
    a.adjust.downsample = 1;
    a.adjust.scale = 1;
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    if (a.manifest)
        status = load_kit(&a, &kit);
    const compare_kit *k = a.manifest ? &kit : NULL;
    img_buf x = {0}, ref = {0};
    int size[2][2];
    if (status == STATUS_OK)
        status = read_sizes(&a, size);
    if (status == STATUS_OK)
        status = check_sizes(&a, k, size);
    if (status == STATUS_OK)
        status = read_image(&a, a.a, size[0][0], size[0][1], &x);
    if (status == STATUS_OK)
        status = read_image(&a, a.b, size[1][0], size[1][1], &ref);
    if (status == STATUS_OK)
        status = adjust_image(&a, k, &x);
    if (status == STATUS_OK)
        status = compare_images(&a, k, &x, &ref);
    img_free(&x);
    img_free(&ref);
    manifest_free(&kit.m);
    free(kit.dir);
    free(kit.exact);
    return status;
}
