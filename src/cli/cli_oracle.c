/*
 * cli_oracle.c - `refray oracle SCENE -o EXACT`: the exact image of an
 * analytic scene, for checking any renderer against it; optionally the mask
 * of the pixels the family excluded (a sample point within its margin of a
 * discontinuity; their value in EXACT is 0).
 */
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include "io/scene_file.h"
#include "io/image_io.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"

static const char oracle_help[] =
    "usage: refray oracle SCENE -o EXACT [OPTIONS]\n"
    "Writes the exact image of an analytic scene (one with `oracle NAME`) at the\n"
    "points the tracer samples: the mean of the K x K sub-pixel cell centres.\n"
    "options:\n"
    "  -o, --output EXACT     .exr (32-bit float) or .pfm: the exact linear values;\n"
    "                         .png and .ppm work too but quantise to 8 bits (warned)\n"
    "  --mask FILE            the excluded pixels: .pgm (255 excluded, 0 compared)\n"
    "                         or an image (white excluded); for `refray compare --mask`\n"
    "  --width W --height H   override the image size\n"
    "  --samples K            K x K sample points per pixel\n"
    "  --max-depth D          the trace depth the exact image is for\n"
    "and -W and the input limits of `refray --help`.\n"
    "Prints how many pixels were excluded.  exit: 0 written; 64 usage; 65 a bad\n"
    "scene, one without `oracle`, of an unknown family or refused by it; 66 a\n"
    "missing scene; 74 the file could not be written.\n";

typedef struct oracle_args {
    cli_scene_opts scene;
    verify_opts view;
    const char *input, *output, *mask;
} oracle_args;

/* 1: consumed, 0: error (reported), -1: not an oracle option. */
static int oracle_option(void *args, int argc, char **argv, int *i)
{
    oracle_args *a = args;
    const char *opt = argv[*i];
    if (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0)
        return cli_take_value(argc, argv, i, &a->output);
    if (strcmp(opt, "--mask") == 0)
        return cli_take_value(argc, argv, i, &a->mask);
    return cli_view_option(&a->view, 0, argc, argv, i);
}

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(oracle_args *a, int argc, char **argv)
{
    int status = cli_parse_one_scene("oracle", oracle_help, argc, argv, &a->scene, &a->input, oracle_option, a);
    if (status != 0)
        return status;
    const verify_opts *v = &a->view;
    if ((status = cli_check_sizes(v->width, v->height, v->samples, v->light_samples, v->max_depth,
                                  &a->scene.limits)) != 0)
        return status;
    if (!a->output)
        return cli_usage_error("oracle: no output given (-o EXACT)");
    return 0;
}

static int is_pgm(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && strcasecmp(path + n - 4, ".pgm") == 0;
}

/* Refuses an unknown extension before any work; warns for 8-bit formats. */
static int check_formats(const oracle_args *a)
{
    const char *paths[2] = {a->output, a->mask};
    for (int k = 0; k < 2; k++) {
        if (!paths[k] || (k == 1 && is_pgm(paths[k])))
            continue;
        img_format fmt = img_format_from_path(paths[k]);
        if (fmt == IMG_FORMAT_UNKNOWN)
            return cli_usage_error("oracle: '%s' has no known image extension (.exr .pfm .png .ppm%s)", paths[k],
                                   k ? " .pgm" : "");
        if (!img_format_available(fmt))
            return cli_usage_error("oracle: this refray was built without support for '%s'", paths[k]);
    }
    img_format out = img_format_from_path(a->output);
    if (out == IMG_FORMAT_PNG || out == IMG_FORMAT_PPM)
        cli_note("", "warning: '%s' quantises the exact image to 8 bits (sRGB, clamped to [0,1]); write .exr or "
                 ".pfm to keep the exact values", a->output);
    return 0;
}

static int write_files(const oracle_args *a, const verify_exact *e)
{
    char err[512];
    cancel_poll cancel = cancel_poll_make(cli_signal_cancel, NULL);
    img_write_opts wo = img_write_opts_default();
    wo.exr_float = 1;
    wo.cancel = &cancel;
    cli_signal_cooperate(1);
    int status = img_write(a->output, &e->image, &wo, err, sizeof err);
    if (status == STATUS_OK && a->mask)
        status = verify_mask_write(a->mask, e->excluded, e->image.width, e->image.height, err, sizeof err);
    if (status != STATUS_OK) {
        cli_error("%s", err);
        return status;
    }
    long pixels = (long)e->image.width * e->image.height;
    printf("%s: family %s, %dx%d, %dx%d points per pixel: %ld of %ld pixels excluded (%.2f%%)%s; wrote %s%s%s\n",
           a->input, e->family->name, e->image.width, e->image.height, e->view.samples, e->view.samples,
           e->excluded_count, pixels, 100.0 * (double)e->excluded_count / (double)pixels,
           e->excluded_count ? ", written as 0" : "", a->output, a->mask ? " and the mask " : "",
           a->mask ? a->mask : "");
    return STATUS_OK;
}

static int exact_of(const oracle_args *a, const scene_model *s)
{
    oracle_view v = verify_view(s, &a->view);
    char why[512];
    if (!cli_view_fits(&v, &a->scene.limits, why, sizeof why))
        return cli_usage_error("oracle: %s", why);
    /* [LANG-EXTENT-1] As render refuses it: an exact image of rays that
     * start outside the extent is no image refray vouches for (attack 10,
     * finding 8). */
    int status = cli_check_view_size(s, v.width, v.height);
    if (status != 0)
        return status;
    const oracle_family *f = verify_family(s, &v, &status, why, sizeof why);
    if (!f) {
        cli_error("%s: %s", a->input, why);
        return STATUS_DATA;
    }
    verify_exact e;
    if ((status = verify_exact_build(f, &v, &e)) != STATUS_OK) {
        cli_error("%s: %s", a->input, verify_exact_error(status));
        return status == STATUS_FAIL ? STATUS_DATA : status;  /* refused, like a family's refusal */
    }
    status = write_files(a, &e);
    verify_exact_free(&e);
    return status;
}

int cli_oracle(int argc, char **argv)
{
    oracle_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    if ((status = check_formats(&a)) != 0)
        return status;
    cli_signal_cooperate(1);
    scene_model *s = cli_load_scene(&a.scene, a.input, &status);
    if (!s)
        return status;
    /* The exact image is not polled: a signal now takes effect at once. */
    cli_signal_cooperate(0);
    status = exact_of(&a, s);
    scene_free(s);
    return status;
}
