/*
 * cli_render.c - `refray render SCENE -o OUT`: load, trace, write atomically,
 * through the public API (refray.h).
 *
 * One of refray's two pieces of global state lives here (the other is
 * cli_conform.c's stop flag): the SIGINT flag, as a volatile sig_atomic_t,
 * because a signal handler can reach nothing else.
 * The library never sees it; it is asked through the progress callback.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "io/fileio.h"

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
    rf_write_options image;
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
    "  --no-shortcuts        run every pass and ray the scene could do without\n"
    "                        (same image to the bit, more work: a check)\n"
    "  --exposure STOPS      PNG/PPM: multiply by 2^STOPS before mapping\n"
    "  --tone clamp|reinhard PNG/PPM: clamp to [0,1] (default) or x/(1+x)\n"
    "  --stats               print ray counts, skipped passes and timings to stderr\n"
    "  -q, --quiet           no progress bar\n"
    "and -W and the input limits of `refray --help`.\n";

static int image_option(render_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i], *v;
    if (strcmp(opt, "--linear") == 0)
        a->image.linear = 1;
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
        a->image.tone = strcmp(v, "reinhard") == 0 ? RF_TONE_REINHARD : RF_TONE_CLAMP;
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
static rf_format stdout_format(const char *name)
{
    char probe[16];
    if (!name || strlen(name) > 4)
        return RF_FORMAT_UNKNOWN;
    snprintf(probe, sizeof probe, "x.%s", name);
    return rf_format_from_path(probe);
}

/* Fails before the render, not after it, when OUT cannot be written. */
static int check_output(const render_args *a)
{
    const char *path = a->output;
    if (strcmp(path, "-") == 0) {
        rf_format f = stdout_format(a->format);
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
    rf_format fmt = rf_format_from_path(path);
    if (fmt == RF_FORMAT_UNKNOWN)
        return cli_usage_error("render: '%s' has no known image extension (.png .exr .pfm .ppm)", path);
    if (!rf_format_available(fmt))
        return cli_usage_error("render: this refray was built without support for '%s' (see make PNG=1 EXR=1)",
                               path);
    char *dir = file_dirname(NULL, path);
    int ok = dir && access(dir, W_OK) == 0;
    if (!ok)
        fprintf(stderr, "refray: error: cannot write into '%s': %s\n", dir ? dir : path,
                dir ? "directory missing or not writable" : "out of memory");
    mem_free_string(NULL, dir);
    return ok ? 0 : STATUS_IO;
}

typedef struct progress_state {
    int show;
    double start;
} progress_state;

static void progress(void *ctx, int done, int total)
{
    const progress_state *p = ctx;
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
}

static int cancel(void *ctx)
{
    (void)ctx;
    return interrupted != 0;
}

/* [MESH-SCALE-1] Load time, and the bytes of the mesh stores and of the
 * BVH per mesh triangle (spec/numerics.md, "Meshes at scale"). */
static void print_memory(const rf_scene *scene, const rf_render_stats *s, double load_seconds)
{
    rf_scene_info info;
    rf_scene_get_info(scene, &info);
    long triangles = info.mesh_triangles;
    fprintf(stderr, "  load: %.3f s; meshes: %ld triangles in %ld bytes", load_seconds, triangles, info.mesh_bytes);
    if (triangles > 0)
        fprintf(stderr, " (%.1f per triangle); bvh %ld bytes (%.1f per triangle)",
                (double)info.mesh_bytes / triangles, s->bvh_bytes, (double)s->bvh_bytes / triangles);
    else
        fprintf(stderr, "; bvh %ld bytes", s->bvh_bytes);
    fputc('\n', stderr);
}

static void print_stats(const rf_scene *scene, const rf_render_stats *s, const rf_write_stats *w,
                        double load_seconds, int no_shortcuts)
{
    long rays = s->camera_rays + s->shadow_rays + s->reflection_rays + s->refraction_rays +
                s->total_internal_reflection_rays;
    fprintf(stderr, "stats: %dx%d pixels, %dx%d camera rays per pixel, max_depth %d\n", s->width, s->height,
            s->samples, s->samples, s->max_depth);
    fprintf(stderr, "  rays: %ld camera, %ld shadow, %ld reflection, %ld refraction, %ld total-internal-reflection; "
            "%ld in all\n", s->camera_rays, s->shadow_rays, s->reflection_rays, s->refraction_rays,
            s->total_internal_reflection_rays, rays);
    fprintf(stderr, "  light samples: %ld (skipped on the surface: %ld)\n", s->light_samples,
            s->light_samples_on_surface);
    fprintf(stderr, "  passes%s: shadows %s, specular %s, reflection %s, refraction %s\n",
            no_shortcuts ? " (every shortcut off)" : "",
            s->shadows ? "on" : "skipped (nothing can occlude)", s->specular ? "on" : "skipped (every Ks is 0)",
            s->reflection ? "on" : "skipped (no Ks > 0, or max_depth 1)",
            s->refraction ? "on" : "skipped (no t > 0, or max_depth 1)");
    print_memory(scene, s, load_seconds);
    fprintf(stderr, "  bvh: %d nodes, %d leaves, depth %d, built in %.3f s; %ld node visits, %ld primitive tests\n",
            s->bvh_nodes, s->bvh_leaves, s->bvh_depth, s->build_seconds, s->node_visits, s->primitive_tests);
    fprintf(stderr, "  time: %.3f s, %.0f rays/s\n", s->seconds, s->seconds > 0 ? rays / s->seconds : 0.0);
    fprintf(stderr, "  non-finite values: %ld traced, %zu written; medium stack overflows: %ld\n", s->nonfinite,
            w->nonfinite, s->medium_overflows);
}

static rf_render_options public_opts(const render_args *a, progress_state *p)
{
    rf_render_options o;
    rf_render_options_init(&o);
    o.width = a->render.width;
    o.height = a->render.height;
    o.samples = a->render.samples;
    o.max_depth = a->render.max_depth;
    o.light_samples = a->render.light_samples;
    o.max_tree_rays = a->scene.limits.max_ray_tree;
    o.no_shortcuts = a->render.no_shortcuts;
    o.progress = progress;
    o.cancel = cancel;
    o.user = p;
    return o;
}

static int render_and_write(render_args *a, const rf_scene *scene, double load_seconds)
{
    rf_image *img = NULL;
    rf_render_stats stats;
    rf_write_stats written = {0, 0};
    progress_state p = {!a->quiet && isatty(2), render_clock()};
    rf_render_options o = public_opts(a, &p);
    int status = interrupted ? STATUS_CANCELLED : (int)rf_render_image(scene, &o, &img, &stats);
    if (status == STATUS_DATA) {
        fprintf(stderr, "refray: error: the rays of pixel (%d, %d) branch into more than %ld rays "
                "(--max-ray-tree); lower max_depth or raise the limit; nothing written\n",
                stats.overflow_x, stats.overflow_y, o.max_tree_rays);
        return status;
    }
    if (status == STATUS_CANCELLED) {
        fprintf(stderr, "%srefray: interrupted; nothing written\n", p.show ? "\n" : "");
        return status;
    }
    if (status != STATUS_OK) {
        fprintf(stderr, "refray: error: out of memory rendering '%s'\n", a->input);
        return status;
    }
    char err[512];
    int wstatus;
    if (strcmp(a->output, "-") == 0) {
        wstatus = (int)rf_image_write_stream(img, stdout, stdout_format(a->format), &a->image, &written, err,
                                             sizeof err);
        if (wstatus == 0 && fflush(stdout) != 0)
            wstatus = STATUS_IO;
    } else {
        wstatus = (int)rf_image_write(img, a->output, &a->image, &written, err, sizeof err);
    }
    rf_image_free(img);
    if (wstatus != 0) {
        fprintf(stderr, "refray: error: %s\n", err);
        return wstatus == STATUS_USAGE ? STATUS_USAGE : STATUS_IO;
    }
    if (a->stats)
        print_stats(scene, &stats, &written, load_seconds, a->render.no_shortcuts);
    return STATUS_OK;
}

int cli_render(int argc, char **argv)
{
    render_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    rf_write_options_init(&a.image);
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    if ((status = check_output(&a)) != 0)
        return status;
    /* From here on SIGINT means "stop, write nothing, exit 130", while the
     * scene loads as well as while it renders. */
    signal(SIGINT, on_interrupt);
    double start = render_clock();
    rf_load_options lo = cli_load_options(&a.scene);
    rf_scene *scene;
    status = (int)rf_scene_load_file(a.input, &lo, &scene);
    double load_seconds = render_clock() - start;
    if (!scene)
        return interrupted ? STATUS_CANCELLED : status;
    rf_scene_info info;
    rf_scene_get_info(scene, &info);
    if ((double)(a.render.width ? a.render.width : info.width) * (a.render.height ? a.render.height : info.height) >
        (double)a.scene.limits.max_pixels) {
        rf_scene_free(scene);
        return cli_usage_error("render: the image would be over --max-pixels %ld", a.scene.limits.max_pixels);
    }
    status = render_and_write(&a, scene, load_seconds);
    rf_scene_free(scene);
    signal(SIGINT, SIG_DFL);
    return status;
}
