/*
 * cli_render.c - `refray render SCENE -o OUT`: load, trace, write atomically,
 * through the public API (refray.h).  A region, a tile, workers or a
 * checkpoint: cli_render_tiles.c.  SIGINT, SIGTERM and SIGHUP stop the
 * load, the render and the write within a fraction of a second, and
 * nothing is written (cli_signal.h; the library is asked through the
 * cancel callback, the worker pool polls the flag).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/cli_render_tiles.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "io/tile_file.h"

static const char render_help[] =
    "usage: refray render SCENE -o OUT [OPTIONS]\n"
    "Renders SCENE into OUT; the format follows OUT's extension:\n"
    "  .exr  linear OpenEXR, half floats (--exr-float for 32-bit)\n"
    "  .pfm  linear portable float map      .ppm  8-bit sRGB, no library needed\n"
    "  .png  8-bit sRGB (--bit-depth 16, --linear for linear codes)\n"
    "options:\n"
    "  -o, --output OUT      where to write (atomically: nothing is left on failure);\n"
    "                        '-' writes to standard output (needs --format)\n"
    "  --format FMT          png, exr, pfm or ppm: the format for -o -\n"
    "  --width W --height H  override the image size\n"
    "  --samples K           K x K camera rays per pixel\n"
    "  --max-depth D         trace depth (1: camera rays only)\n"
    "  --light-samples N     N point sources for every distributed light\n"
    "  --no-shortcuts        run every pass and ray the scene could do without\n"
    "                        (same image to the bit, more work: a check)\n"
    "  --exposure STOPS      PNG/PPM: multiply by 2^STOPS before mapping\n"
    "  --tone clamp|reinhard PNG/PPM: clamp to [0,1] (default) or x/(1+x)\n"
    "  --stats               print ray counts, skipped passes and timings to stderr\n"
    "  -q, --quiet           no progress bar\n"
    "big renders (spec/scaling.md):\n"
    "  --jobs N              N worker processes over bands of rows (default 1;\n"
    "                        0: one per processor); the same pixels as --jobs 1\n"
    "  --region X0 Y0 X1 Y1  only the pixels X0 <= x < X1, Y0 <= y < Y1 (y = 0 at\n"
    "                        the top), as a tile: OUT is .exr or .pfm (+ OUT.tile)\n"
    "  --tile I/N            tile I of N (0 <= I < N): the full-width rows y with\n"
    "                        floor(I*H/N) <= y < floor((I+1)*H/N), as a tile;\n"
    "                        put tiles together with refray merge\n"
    "  --checkpoint DIR      keep every finished band in DIR; the same command\n"
    "                        after an interruption renders only what is missing\n"
    "and -W and the input limits of `refray --help`.\n";

/* --region's four values. */
static int region_option(render_args *a, int argc, char **argv, int *i)
{
    static const char *const names[4] = {"X0", "Y0", "X1", "Y1"};
    for (int k = 0; k < 4; k++) {
        long v;
        if (*i + 1 >= argc) {
            cli_usage_error("--region needs four values, X0 Y0 X1 Y1");
            return 0;
        }
        if (!cli_parse_long(names[k], argv[++*i], 0, 1000000000, &v))
            return 0;
        a->region[k] = (int)v;
    }
    a->has_region = 1;
    return 1;
}

/* --tile I/N. */
static int tile_option(render_args *a, int argc, char **argv, int *i)
{
    const char *v;
    long index, count;
    char text[64], *slash;
    if (!cli_take_value(argc, argv, i, &v))
        return 0;
    snprintf(text, sizeof text, "%s", v);
    slash = strchr(text, '/');
    if (!slash || strlen(v) >= sizeof text) {
        cli_usage_error("--tile takes I/N (tile I of N, 0 <= I < N), not '%s'", v);
        return 0;
    }
    *slash = '\0';
    if (!cli_parse_long("--tile's N", slash + 1, 1, 1000000000, &count) ||
        !cli_parse_long("--tile's I", text, 0, count - 1, &index))
        return 0;
    a->tile_index = (int)index;
    a->tile_count = (int)count;
    return 1;
}

/* The options of big renders; 1, 0 or -1 as render_option. */
static int scaling_option(render_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i];
    long jobs;
    const char *v;
    if (strcmp(opt, "--region") == 0)
        return region_option(a, argc, argv, i);
    if (strcmp(opt, "--tile") == 0)
        return tile_option(a, argc, argv, i);
    if (strcmp(opt, "--checkpoint") == 0)
        return cli_take_value(argc, argv, i, &a->checkpoint);
    if (strcmp(opt, "--jobs") != 0)
        return -1;
    if (!cli_take_value(argc, argv, i, &v) || !cli_parse_long(opt, v, 0, 256, &jobs))
        return 0;
    a->jobs = (int)jobs;
    return 1;
}

/* 1: consumed, 0: error (reported), -1: not a render option. */
static int render_option(void *args, int argc, char **argv, int *i)
{
    render_args *a = args;
    const char *opt = argv[*i];
    int sized = cli_render_option(&a->render, argc, argv, i);
    if (sized >= 0)
        return sized;
    if ((sized = scaling_option(a, argc, argv, i)) >= 0)
        return sized;
    if (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0)
        return cli_take_value(argc, argv, i, &a->output);
    if (strcmp(opt, "--format") == 0)
        return cli_take_value(argc, argv, i, &a->format);
    if (strcmp(opt, "--stats") == 0)
        return a->stats = 1;
    if (strcmp(opt, "-q") == 0 || strcmp(opt, "--quiet") == 0)
        return a->quiet = 1;
    return cli_image_option(&a->image, argc, argv, i);
}

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(render_args *a, int argc, char **argv)
{
    int status = cli_parse_one_scene("render", render_help, argc, argv, &a->scene, &a->input, render_option, a);
    if (status != 0)
        return status;
    if ((status = cli_check_render_sizes(&a->render, &a->scene.limits)) != 0)
        return status;
    if (!a->output)
        return cli_usage_error("render: no output given (-o OUT)");
    if (a->has_region && a->tile_count)
        return cli_usage_error("render: --region and --tile both choose the pixels; give one");
    return 0;
}

/* 1 when a needs the tile engine: a region or tile, workers, a checkpoint. */
static int in_tiles(const render_args *a)
{
    return a->has_region || a->tile_count || a->jobs != 1 || a->checkpoint;
}

/* A tile's output: a tile format, a file. */
static int check_tile_output(const render_args *a)
{
    char why[300];
    if (strcmp(a->output, "-") == 0)
        return cli_usage_error("render: a tile is written to a file (a sidecar, or seeking), not to -o -");
    if (!tile_file_format_ok(a->output, why, sizeof why))
        return cli_usage_error("render: %s", why);
    return 0;
}

/* Fails before the render, not after it, when OUT cannot be written:
 * every check of the writer that needs no image ([REL-OUT-6]). */
static int check_output(const render_args *a)
{
    const char *path = a->output;
    int tile = a->has_region || a->tile_count, status;
    if (tile && (status = check_tile_output(a)) != 0)
        return status;
    if (!tile && strcmp(path, "-") == 0) {
        rf_format f = cli_render_stdout_format(a->format);
        if (f == RF_FORMAT_UNKNOWN)
            return cli_usage_error("render: -o - needs --format png, exr, pfm or ppm");
        if (!rf_format_available(f))
            return cli_usage_error("render: this refray was built without support for --format %s", a->format);
        if (isatty(1))
            return cli_usage_error("render: refusing to write an image to a terminal");
        return 0;
    }
    if (a->format)
        return cli_usage_error("render: --format is for -o -; a file's format follows its extension");
    return tile ? cli_check_output_dir(path) : cli_check_output_file("render", path);
}

static int render_and_write(const render_args *a, const rf_scene *scene)
{
    rf_image *img = NULL;
    rf_render_stats stats;
    rf_write_stats written = {0, 0};
    cli_progress bar;
    cli_progress_init(&bar, !a->quiet, 0);
    rf_render_options o = cli_render_options(a, &bar);
    int status = (int)rf_render_image(scene, &o, &img, &stats);
    if (status != STATUS_OK) {
        cli_render_void at = {stats.overflow_x, stats.overflow_y, stats.medium_overflows > 0};
        cli_render_report(a, status, &at, bar.show ? "\n" : "");
        return status;
    }
    status = cli_render_write(a, img, &written);
    rf_image_free(img);
    if (status == STATUS_OK && a->stats)
        cli_render_print_stats(a, scene, &stats, &written);
    return status;
}

int cli_render(int argc, char **argv)
{
    render_args a;
    memset(&a, 0, sizeof a);
    a.jobs = 1;
    cli_scene_opts_init(&a.scene);
    rf_write_options_init(&a.image);
    a.image.cancel = cli_signal_cancel;
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    if ((status = check_output(&a)) != 0)
        return status;
    /* From here on a signal means "stop, write nothing", while the scene
     * loads as well as while it renders (here or on workers) and while the
     * file is written. */
    cli_signal_cooperate(1);
    double start = render_clock();
    rf_load_options lo = cli_load_options(&a.scene);
    rf_scene *scene;
    status = (int)rf_scene_load_file(a.input, &lo, &scene);
    a.load_seconds = render_clock() - start;
    if (status == STATUS_CANCELLED)
        fputs("refray: interrupted; nothing written\n", stderr);
    if (!scene)
        return status;
    rf_scene_info info;
    rf_scene_get_info(scene, &info);
    double pixels = (double)(a.render.width ? a.render.width : info.width) *
                    (a.render.height ? a.render.height : info.height);
    double need = scene_memory_estimate(info.primitives, pixels, 0);
    if (pixels > (double)a.scene.limits.max_pixels || need > (double)a.scene.limits.max_memory_mb * 1048576.0) {
        rf_scene_free(scene);
        if (pixels > (double)a.scene.limits.max_pixels)
            return cli_usage_error("render: the image would be over --max-pixels %ld", a.scene.limits.max_pixels);
        return cli_usage_error("render: the render would need about %.0f MiB, over --max-memory %ld", need / 1048576.0,
                               a.scene.limits.max_memory_mb);
    }
    if ((status = cli_check_view(scene, &a.render)) == 0)
        status = in_tiles(&a) ? cli_render_tiles(&a, scene) : render_and_write(&a, scene);
    rf_scene_free(scene);
    return status;
}
