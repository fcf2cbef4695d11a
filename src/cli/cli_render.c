/*
 * cli_render.c - `refray render SCENE -o OUT`: load, trace, write atomically.
 *
 * The one piece of global state in refray lives here: the SIGINT flag, as a
 * volatile sig_atomic_t, because a signal handler can reach nothing else.
 * The library never sees it; it is asked through the progress callback.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "base/fileio.h"
#include "image/image_file.h"
#include "render/render.h"

static volatile sig_atomic_t interrupted;

static void on_interrupt(int sig)
{
    (void)sig;
    interrupted = 1;
}

typedef struct render_args {
    cli_scene_opts scene;
    const char *input, *output;
    const char *format;   /* --format, for -o - (standard output) */
    render_opts render;
    img_write_opts image;
    int stats, quiet;
} render_args;

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
    "  --exposure STOPS      PNG/PPM: multiply by 2^STOPS before mapping\n"
    "  --tone clamp|reinhard PNG/PPM: clamp to [0,1] (default) or x/(1+x)\n"
    "  --stats               print ray counts, skipped passes and timings to stderr\n"
    "  -q, --quiet           no progress bar\n"
    "and -W and the input limits of `refray --help`.\n";

static int image_option(render_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i], *v;
    if (strcmp(opt, "--linear") == 0)
        a->image.linear_png = 1;
    else if (strcmp(opt, "--exr-float") == 0)
        a->image.exr_float = 1;
    else if (strcmp(opt, "--exposure") == 0)
        return cli_take_value(argc, argv, i, &v) && cli_parse_double(opt, v, &a->image.exposure_stops);
    else if (strcmp(opt, "--bit-depth") == 0) {
        long bits;
        if (!cli_take_value(argc, argv, i, &v) || !cli_parse_long(opt, v, 8, 16, &bits))
            return 0;
        if (bits != 8 && bits != 16) {
            cli_usage_error("--bit-depth is 8 or 16");
            return 0;
        }
        a->image.png_bits = (int)bits;
    } else if (strcmp(opt, "--tone") == 0) {
        if (!cli_take_value(argc, argv, i, &v))
            return 0;
        if (strcmp(v, "clamp") != 0 && strcmp(v, "reinhard") != 0) {
            cli_usage_error("--tone is clamp or reinhard, not '%s'", v);
            return 0;
        }
        a->image.tone = strcmp(v, "reinhard") == 0 ? IMG_TONE_REINHARD : IMG_TONE_CLAMP;
    } else {
        return -1;
    }
    return 1;
}

/* 1: consumed, 0: error (reported), -1: not a render option. */
static int render_option(void *args, int argc, char **argv, int *i)
{
    render_args *a = args;
    const char *opt = argv[*i];
    int sized = cli_render_option(&a->render, &a->scene.limits, argc, argv, i);
    if (sized >= 0)
        return sized;
    if (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0)
        return cli_take_value(argc, argv, i, &a->output);
    if (strcmp(opt, "--format") == 0)
        return cli_take_value(argc, argv, i, &a->format);
    if (strcmp(opt, "--stats") == 0)
        return a->stats = 1;
    if (strcmp(opt, "-q") == 0 || strcmp(opt, "--quiet") == 0)
        return a->quiet = 1;
    return image_option(a, argc, argv, i);
}

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(render_args *a, int argc, char **argv)
{
    int status = cli_parse_one_scene("render", render_help, argc, argv, &a->scene, &a->input, render_option, a);
    if (status != 0)
        return status;
    if (!a->output)
        return cli_usage_error("render: no output given (-o OUT)");
    return 0;
}

/* The format of standard output, from --format. */
static img_format stdout_format(const char *name)
{
    char probe[16];
    if (!name || strlen(name) > 4)
        return IMG_FORMAT_UNKNOWN;
    snprintf(probe, sizeof probe, "x.%s", name);
    return img_format_from_path(probe);
}

/* Fails before the render, not after it, when OUT cannot be written. */
static int check_output(const render_args *a)
{
    const char *path = a->output;
    if (strcmp(path, "-") == 0) {
        img_format f = stdout_format(a->format);
        if (f == IMG_FORMAT_UNKNOWN)
            return cli_usage_error("render: -o - needs --format png, exr, pfm or ppm");
        if (!img_format_available(f))
            return cli_usage_error("render: this refray was built without support for --format %s", a->format);
        if (isatty(1))
            return cli_usage_error("render: refusing to write an image to a terminal");
        return 0;
    }
    if (a->format)
        return cli_usage_error("render: --format is for -o -; a file's format follows its extension");
    img_format fmt = img_format_from_path(path);
    if (fmt == IMG_FORMAT_UNKNOWN)
        return cli_usage_error("render: '%s' has no known image extension (.png .exr .pfm .ppm)", path);
    if (!img_format_available(fmt))
        return cli_usage_error("render: this refray was built without support for '%s' (see make PNG=1 EXR=1)",
                               path);
    char *dir = file_dirname(path);
    int ok = dir && access(dir, W_OK) == 0;
    if (!ok)
        fprintf(stderr, "refray: error: cannot write into '%s': %s\n", dir ? dir : path,
                dir ? "directory missing or not writable" : "out of memory");
    free(dir);
    return ok ? 0 : REFRAY_EXIT_IOERR;
}

typedef struct progress_state {
    int show;
    double start;
} progress_state;

static int progress(void *ctx, int done, int total)
{
    progress_state *p = ctx;
    if (p->show) {
        double elapsed = render_clock() - p->start;
        double eta = done > 0 ? elapsed * (total - done) / done : 0;
        int width = 40, filled = (int)((long)width * done / total);
        fprintf(stderr, "\r[%-*.*s] %3d%%  %.1fs elapsed, ETA %.1fs ", width, filled,
                "########################################", (int)(100L * done / total), elapsed, eta);
        if (done == total)
            fputc('\n', stderr);
        fflush(stderr);
    }
    return interrupted != 0;
}

/* [MESH-SCALE-1] Load time, and the bytes of the mesh stores and of the
 * BVH per mesh triangle (spec/numerics.md, "Meshes at scale"). */
static void print_memory(const rf_scene *scene, const render_stats *s, double load_seconds)
{
    long triangles, mesh = scene_mesh_bytes(scene, &triangles);
    fprintf(stderr, "  load: %.3f s; meshes: %ld triangles in %ld bytes", load_seconds, triangles, mesh);
    if (triangles > 0)
        fprintf(stderr, " (%.1f per triangle); bvh %ld bytes (%.1f per triangle)", (double)mesh / triangles,
                s->bvh_bytes, (double)s->bvh_bytes / triangles);
    else
        fprintf(stderr, "; bvh %ld bytes", s->bvh_bytes);
    fputc('\n', stderr);
}

static void print_stats(const rf_scene *scene, const render_stats *s, const img_write_stats *w, double load_seconds)
{
    const trace_stats *t = &s->trace;
    long rays = t->camera_rays + t->shadow_rays + t->reflection_rays + t->refraction_rays + t->tir_rays;
    fprintf(stderr, "stats: %dx%d pixels, %dx%d camera rays per pixel, max_depth %d\n", s->width, s->height,
            s->samples, s->samples, s->max_depth);
    fprintf(stderr, "  rays: %ld camera, %ld shadow, %ld reflection, %ld refraction, %ld total-internal-reflection; "
            "%ld in all\n", t->camera_rays, t->shadow_rays, t->reflection_rays, t->refraction_rays, t->tir_rays, rays);
    fprintf(stderr, "  light samples: %ld (skipped on the surface: %ld)\n", t->light_samples, t->lights_on_surface);
    fprintf(stderr, "  passes: shadows %s, specular %s, reflection %s, refraction %s\n",
            s->shadows ? "on" : "skipped (nothing can occlude)", s->specular ? "on" : "skipped (every Ks is 0)",
            s->reflection ? "on" : "skipped (no Ks > 0, or max_depth 1)",
            s->refraction ? "on" : "skipped (no t > 0, or max_depth 1)");
    print_memory(scene, s, load_seconds);
    fprintf(stderr, "  bvh: %d nodes, %d leaves, depth %d, built in %.3f s; %ld node visits, %ld primitive tests\n",
            s->bvh_nodes, s->bvh_leaves, s->bvh_depth, s->build_seconds, t->bvh.nodes_visited, t->bvh.prims_tested);
    fprintf(stderr, "  time: %.3f s, %.0f rays/s\n", s->seconds, s->seconds > 0 ? rays / s->seconds : 0.0);
    fprintf(stderr, "  non-finite values: %ld traced, %zu written; medium stack overflows: %ld\n", t->nonfinite,
            w->nonfinite, t->medium_overflow);
}

static int render_and_write(render_args *a, const rf_scene *scene, double load_seconds)
{
    rf_image img = {0, 0, NULL};
    render_stats stats;
    img_write_stats written = {0, 0};
    progress_state p = {!a->quiet && isatty(2), render_clock()};
    a->render.progress = progress;
    a->render.max_tree_rays = a->scene.limits.max_ray_tree;
    a->render.progress_ctx = &p;
    int status = interrupted ? REFRAY_EXIT_INTERRUPTED : render_image(scene, &a->render, &img, &stats);
    if (status == REFRAY_EXIT_DATAERR) {
        fprintf(stderr, "refray: error: the rays of pixel (%d, %d) branch into more than %ld rays "
                "(--max-ray-tree); lower max_depth or raise the limit; nothing written\n",
                stats.overflow_x, stats.overflow_y, a->render.max_tree_rays);
        return status;
    }
    if (status == REFRAY_EXIT_INTERRUPTED) {
        fprintf(stderr, "%srefray: interrupted; nothing written\n", p.show ? "\n" : "");
        return status;
    }
    if (status != REFRAY_EXIT_OK) {
        fprintf(stderr, "refray: error: out of memory rendering '%s'\n", a->input);
        return status;
    }
    char err[512];
    a->image.stats = &written;
    int wstatus;
    if (strcmp(a->output, "-") == 0) {
        wstatus = img_write_stream(stdout, stdout_format(a->format), &img, &a->image, err, sizeof err);
        if (wstatus == 0 && fflush(stdout) != 0)
            wstatus = IMG_EIO;
    } else {
        wstatus = img_write(a->output, &img, &a->image, err, sizeof err);
    }
    img_free(&img);
    if (wstatus != 0) {
        fprintf(stderr, "refray: error: %s\n", err);
        return wstatus == IMG_EUSAGE ? REFRAY_EXIT_USAGE : REFRAY_EXIT_IOERR;
    }
    if (a->stats)
        print_stats(scene, &stats, &written, load_seconds);
    return REFRAY_EXIT_OK;
}

int cli_render(int argc, char **argv)
{
    render_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    a.image = img_write_opts_default();
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? REFRAY_EXIT_OK : status;
    if ((status = check_output(&a)) != 0)
        return status;
    /* From here on SIGINT means "stop, write nothing, exit 130", while the
     * scene loads as well as while it renders. */
    signal(SIGINT, on_interrupt);
    double start = render_clock();
    rf_scene *scene = scene_load(a.input, &a.scene.limits, stderr, a.scene.warnings, &status);
    double load_seconds = render_clock() - start;
    if (!scene)
        return interrupted ? REFRAY_EXIT_INTERRUPTED : status;
    if ((double)(a.render.width ? a.render.width : scene->image.width) *
            (a.render.height ? a.render.height : scene->image.height) > (double)a.scene.limits.max_pixels) {
        scene_free(scene);
        return cli_usage_error("render: the image would be over --max-pixels %ld", a.scene.limits.max_pixels);
    }
    status = render_and_write(&a, scene, load_seconds);
    scene_free(scene);
    signal(SIGINT, SIG_DFL);
    return status;
}
