/*
 * cli_args.c - the options and argument loops the commands share.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>
#include "api/convert.h"
#include "base/text.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "io/diag_print.h"
#include "io/image_io.h"
#include "io/scene_file.h"

/* before, "refray: ", label and the message, escaped and cut
 * (text_escape): arguments and file names are input too ([REL-ESCAPE-1]). */
static void print_escaped(const char *before, const char *label, const char *fmt, va_list ap, const char *after)
{
    char text[4096], shown[1024];
    vsnprintf(text, sizeof text, fmt, ap);
    text_escape(text, strlen(text), shown, sizeof shown);
    fprintf(stderr, "%srefray: %s%s\n%s", before, label, shown, after);
}

static void print_error(const char *fmt, va_list ap, const char *after)
{
    print_escaped("", "error: ", fmt, ap, after);
}

void cli_note(const char *before, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    print_escaped(before, "", fmt, ap, "");
    va_end(ap);
}

void cli_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    print_error(fmt, ap, "");
    va_end(ap);
}

int cli_usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    print_error(fmt, ap, "(see refray --help)\n");
    va_end(ap);
    return STATUS_USAGE;
}

/* The hard ceiling of every limit: far beyond any real scene, and low
 * enough that the products computed from them cannot overflow. */
enum { LIMIT_CEILING = 1000000000 };

int cli_parse_long(const char *option, const char *text, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    double x = strtod(text, &end);
    if (end == text || *end || errno || x != floor(x) || x < (double)lo || x > (double)hi) {
        cli_usage_error("%s takes a whole number from %ld to %ld, not '%s'", option, lo, hi, text);
        return 0;
    }
    *out = (long)x;
    return 1;
}

int cli_parse_double(const char *option, const char *text, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    if (end == text || *end || errno || !isfinite(*out)) {
        cli_usage_error("%s takes a number, not '%s'", option, text);
        return 0;
    }
    return 1;
}

int cli_take_value(int argc, char **argv, int *i, const char **value)
{
    if (*i + 1 >= argc) {
        cli_usage_error("%s needs a value", argv[*i]);
        return 0;
    }
    *value = argv[++*i];
    return 1;
}

int cli_int_value(int argc, char **argv, int *i, long hi, int *out)
{
    const char *v;
    long x;
    if (!cli_take_value(argc, argv, i, &v) || !cli_parse_long(argv[*i - 1], v, 1, hi, &x))
        return 0;
    *out = (int)x;
    return 1;
}

/* The sizing options take any value up to the ceiling here; they are
 * checked against the limits once every option is read
 * (cli_check_sizes), so that `--width 20000 --max-width 20000` and the
 * reverse order mean the same ([REL-CLI-1]). */
static int size_option(int argc, char **argv, int *i, int *width, int *height, int *samples, int *max_depth,
                       int *light_samples)
{
    const char *opt = argv[*i];
    int *field = strcmp(opt, "--width") == 0          ? width
                 : strcmp(opt, "--height") == 0       ? height
                 : strcmp(opt, "--samples") == 0      ? samples
                 : strcmp(opt, "--max-depth") == 0    ? max_depth
                 : strcmp(opt, "--light-samples") == 0 ? light_samples
                                                       : NULL;
    return field ? cli_int_value(argc, argv, i, LIMIT_CEILING, field) : -1;
}

int cli_render_option(render_opts *o, int argc, char **argv, int *i)
{
    if (strcmp(argv[*i], "--no-shortcuts") == 0)
        return o->no_shortcuts = 1;
    return size_option(argc, argv, i, &o->width, &o->height, &o->samples, &o->max_depth, &o->light_samples);
}

/* One sizing option against its limit; 0 after the usage error. */
static int within(const char *option, long value, long limit, const char *flag)
{
    if (value <= limit)
        return 1;
    if (strcmp(flag, "--max-depth-limit") == 0 && limit >= SCENE_DEPTH_CEILING)
        cli_usage_error("%s %ld is over the ceiling of %d (the tracer's stack: spec/reliability.md, [REL-STACK-1])",
                        option, value, (int)SCENE_DEPTH_CEILING);
    else
        cli_usage_error("%s %ld is over the limit of %ld (raise it with %s)", option, value, limit, flag);
    return 0;
}

int cli_check_sizes(int width, int height, int samples, int light_samples, int max_depth, const scene_limits *lim)
{
    int ok = within("--width", width, lim->max_width, "--max-width") &&
             within("--height", height, lim->max_height, "--max-height") &&
             within("--samples", samples, lim->max_samples, "--max-samples") &&
             within("--light-samples", light_samples, lim->max_light_samples, "--max-light-samples") &&
             within("--max-depth", max_depth, lim->max_depth, "--max-depth-limit");
    return ok ? 0 : STATUS_USAGE;
}

int cli_check_render_sizes(const render_opts *r, const scene_limits *lim)
{
    return cli_check_sizes(r->width, r->height, r->samples, r->light_samples, r->max_depth, lim);
}

int cli_check_view_size(const scene_model *s, int width, int height)
{
    diag d;
    if (width == s->image.width && height == s->image.height)
        return 0; /* the scene's own size: the load checked it */
    diag_init(&d, &s->sources, diag_print, stderr);
    return scene_check_view(s, width, height, &d) ? 0 : STATUS_DATA;
}

int cli_check_view(const rf_scene *scene, const render_opts *r)
{
    const scene_model *s = api_scene(scene);
    return cli_check_view_size(s, r->width ? r->width : s->image.width, r->height ? r->height : s->image.height);
}

int cli_parse_command(const char *command, const char *help, int argc, char **argv, cli_scene_opts *scene,
                      cli_operand_fn operand, cli_option_fn option, void *args)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(help, stdout);
            return -1;
        }
        int used = cli_scene_opt(scene, argc, argv, i);
        if (used < 0)
            return STATUS_USAGE;
        if (used > 0) {
            i += used - 1;
            continue;
        }
        if (argv[i][0] != '-' || !argv[i][1]) {
            int status = operand(args, argv[i]);
            if (status != 0)
                return status;
            continue;
        }
        int r = option(args, argc, argv, &i);
        if (r == 0)
            return STATUS_USAGE;
        if (r < 0)
            return cli_usage_error("%s: unknown option '%s'", command, argv[i]);
    }
    return 0;
}

/* cli_parse_one_scene's arguments, for its operand and option. */
typedef struct one_scene {
    const char *command;
    const char **input;
    cli_option_fn option;
    void *args;
} one_scene;

static int one_scene_operand(void *ctx, const char *arg)
{
    one_scene *o = ctx;
    if (*o->input)
        return cli_usage_error("%s: one scene at a time ('%s' and '%s')", o->command, *o->input, arg);
    *o->input = arg;
    return 0;
}

static int one_scene_option(void *ctx, int argc, char **argv, int *i)
{
    const one_scene *o = ctx;
    return o->option(o->args, argc, argv, i);
}

int cli_parse_one_scene(const char *command, const char *help, int argc, char **argv, cli_scene_opts *scene,
                        const char **input, cli_option_fn option, void *args)
{
    one_scene o = {command, input, option, args};
    int status = cli_parse_command(command, help, argc, argv, scene, one_scene_operand, one_scene_option, &o);
    if (status == 0 && !*input)
        return cli_usage_error("%s: no scene given", command);
    return status;
}

void cli_scene_opts_init(cli_scene_opts *o)
{
    memset(o, 0, sizeof *o);
    o->limits = scene_default_limits();
    o->warnings = 1;
}

rf_load_options cli_load_options(const cli_scene_opts *o)
{
    rf_load_options lo;
    rf_load_options_init(&lo);
    lo.limits = api_limits_out(&o->limits);
    lo.warnings = o->warnings;
    lo.diagnostic = rf_diagnostic_print;
    lo.diagnostic_user = stderr;
    lo.cancel = cli_signal_cancel;
    lo.read_confined = 1;
    lo.read_dirs = o->allow_read;
    return lo;
}

scene_model *cli_load_scene(const cli_scene_opts *o, const char *path, int *status)
{
    scene_load_opts lo;
    scene_load_opts_init(&lo);
    lo.limits = o->limits;
    lo.warnings = o->warnings;
    lo.sink = diag_print;
    lo.sink_user = stderr;
    lo.cancel = cli_signal_cancel;
    scene_model *s = scene_file_load_confined(path, &lo, o->allow_read, status);
    if (*status == STATUS_CANCELLED)
        fputs("refray: interrupted\n", stderr);
    return s;
}

typedef struct limit_flag {
    const char *name;
    size_t offset;
} limit_flag;

#define LIMIT(flag, field) {flag, offsetof(scene_limits, field)}
static const limit_flag limit_flags[] = {
    LIMIT("--max-width", max_width),
    LIMIT("--max-height", max_height),
    LIMIT("--max-pixels", max_pixels),
    LIMIT("--max-samples", max_samples),
    LIMIT("--max-light-samples", max_light_samples),
    LIMIT("--max-depth-limit", max_depth),
    LIMIT("--max-loop", max_loop_iterations),
    LIMIT("--max-include-depth", max_include_depth),
    LIMIT("--max-file-size", max_file_bytes),
    LIMIT("--max-mesh-triangles", max_mesh_triangles),
    LIMIT("--max-primitives", max_primitives),
    LIMIT("--max-errors", max_errors),
    LIMIT("--max-ray-tree", max_ray_tree),
    LIMIT("--max-input-size", max_input_bytes),
    LIMIT("--max-memory", max_memory_mb),
};


/* --allow-read DIR: an existing directory, at most CLI_MAX_ALLOW_READ. */
static int allow_read(cli_scene_opts *o, int argc, char **argv, int i)
{
    struct stat st;
    if (i + 1 >= argc) {
        cli_usage_error("--allow-read needs a directory");
        return -1;
    }
    if (stat(argv[i + 1], &st) != 0 || !S_ISDIR(st.st_mode)) {
        cli_usage_error("--allow-read: '%s' is not a directory", argv[i + 1]);
        return -1;
    }
    if (o->allow_count == CLI_MAX_ALLOW_READ) {
        cli_usage_error("--allow-read: at most %d directories", CLI_MAX_ALLOW_READ);
        return -1;
    }
    o->allow_read[o->allow_count++] = argv[i + 1];
    return 2;
}

int cli_scene_opt(cli_scene_opts *o, int argc, char **argv, int i)
{
    if (strcmp(argv[i], "-W") == 0 || strcmp(argv[i], "--no-warnings") == 0) {
        o->warnings = 0;
        return 1;
    }
    if (strcmp(argv[i], "--allow-read") == 0)
        return allow_read(o, argc, argv, i);
    for (size_t k = 0; k < sizeof limit_flags / sizeof limit_flags[0]; k++) {
        if (strcmp(argv[i], limit_flags[k].name) != 0)
            continue;
        long *field = (long *)((char *)&o->limits + limit_flags[k].offset);
        if (i + 1 >= argc) {
            cli_usage_error("%s needs a value", argv[i]);
            return -1;
        }
        /* 0 errors or a ray budget of 0 would mean nothing can be shown or
         * traced: refused ([REL-RAYTREE-2]). */
        long lo = strcmp(argv[i], "--max-errors") == 0 || strcmp(argv[i], "--max-ray-tree") == 0 ? 1 : 0;
        long hi = field == &o->limits.max_depth ? SCENE_DEPTH_CEILING : LIMIT_CEILING;
        return cli_parse_long(argv[i], argv[i + 1], lo, hi, field) ? 2 : -1;
    }
    return 0;
}

int cli_view_option(verify_opts *o, int allow_light, int argc, char **argv, int *i)
{
    return size_option(argc, argv, i, &o->width, &o->height, &o->samples, &o->max_depth,
                       allow_light ? &o->light_samples : NULL);
}

int cli_view_fits(const oracle_view *v, const scene_limits *lim, char *why, size_t why_size)
{
    if ((double)v->width * v->height <= (double)lim->max_pixels)
        return 1;
    snprintf(why, why_size, "the image would be %dx%d, over --max-pixels %ld", v->width, v->height,
             lim->max_pixels);
    return 0;
}

int cli_adjust_option(conform_adjust *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i], *v;
    int downsample = strcmp(opt, "--downsample") == 0;
    long k;
    if (!downsample && strcmp(opt, "--scale") != 0)
        return -1;
    if (!cli_take_value(argc, argv, i, &v))
        return 0;
    if (strcmp(v, "manifest") == 0) {
        if (downsample)
            a->downsample = CONFORM_FROM_MANIFEST;
        else
            a->scale = CONFORM_FROM_MANIFEST;
        return 1;
    }
    if (downsample) {
        if (!cli_parse_long(opt, v, 1, 64, &k))
            return 0;
        a->downsample = (int)k;
        return 1;
    }
    if (!cli_parse_double(opt, v, &a->scale) || !(a->scale > 0)) {
        cli_usage_error("--scale takes a number > 0 or 'manifest', not '%s'", v);
        return 0;
    }
    return 1;
}

int cli_image_option(rf_write_options *o, int argc, char **argv, int *i)
{
    const char *opt = argv[*i], *v;
    if (strcmp(opt, "--linear") == 0)
        o->linear = 1;
    else if (strcmp(opt, "--exr-float") == 0)
        o->exr_float = 1;
    else if (strcmp(opt, "--exposure") == 0)
        return cli_take_value(argc, argv, i, &v) && cli_parse_double(opt, v, &o->exposure_stops);
    else if (strcmp(opt, "--bit-depth") == 0) {
        long bits;
        if (!cli_take_value(argc, argv, i, &v) || !cli_parse_long(opt, v, 8, 16, &bits))
            return 0;
        if (bits != 8 && bits != 16) {
            cli_usage_error("--bit-depth is 8 or 16");
            return 0;
        }
        o->png_bits = (int)bits;
    } else if (strcmp(opt, "--tone") == 0) {
        if (!cli_take_value(argc, argv, i, &v))
            return 0;
        if (strcmp(v, "clamp") != 0 && strcmp(v, "reinhard") != 0) {
            cli_usage_error("--tone is clamp or reinhard, not '%s'", v);
            return 0;
        }
        o->tone = strcmp(v, "reinhard") == 0 ? RF_TONE_REINHARD : RF_TONE_CLAMP;
    } else {
        return -1;
    }
    return 1;
}

int cli_check_output_dir(const char *path)
{
    char err[1024];
    int status = img_write_check(path, err, sizeof err);
    if (status != STATUS_OK)
        cli_error("%s", err);
    return status;
}

int cli_check_output_file(const char *command, const char *path)
{
    rf_format fmt = rf_format_from_path(path);
    if (fmt == RF_FORMAT_UNKNOWN)
        return cli_usage_error("%s: '%s' has no known image extension (.png .exr .pfm .ppm)", command, path);
    if (!rf_format_available(fmt))
        return cli_usage_error("%s: this refray was built without support for '%s' (see make PNG=1 EXR=1)",
                               command, path);
    return cli_check_output_dir(path);
}
