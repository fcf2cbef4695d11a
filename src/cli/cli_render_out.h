/*
 * cli_render_out.h - what the two halves of `refray render` share: its
 * arguments, its options for the library, and the reports and the write
 * at a render's end.  cli_render.c parses and renders an image in one
 * piece; cli_render_tiles.c renders a region or tile, on worker processes,
 * with a checkpoint (spec/scaling.md).
 */
#ifndef REFRAY_CLI_RENDER_OUT_H
#define REFRAY_CLI_RENDER_OUT_H

#include "cli/cli_args.h"
#include "cli/cli_progress.h"

typedef struct render_args {
    cli_scene_opts scene;
    const char *input, *output;
    const char *format;   /* --format, for -o - (standard output) */
    render_opts render;
    rf_write_options image;
    int stats, quiet;
    int region[4];        /* --region X0 Y0 X1 Y1 */
    int has_region;
    int tile_index, tile_count; /* --tile I/N; tile_count 0: none */
    int jobs;             /* --jobs: 1 (default), 0: every processor */
    const char *checkpoint; /* --checkpoint DIR */
    double load_seconds;  /* the scene's load, for --stats */
} render_args;

/* The library's options for a: sizes, limits, the stop flag as cancel;
 * progress through bar when bar is not NULL. */
rf_render_options cli_render_options(const render_args *a, cli_progress *bar);

/* After STATUS_DATA from a render: the pixel refused, and why. */
typedef struct cli_render_void {
    int x, y;
    int medium;   /* 1: glass nested too deep ([REL-MEDIUM-1]); 0: a ray tree over the budget */
} cli_render_void;

/* Reports a render that did not finish (status not STATUS_OK) the same way
 * for both halves; at: the pixel refused (read after STATUS_DATA only);
 * nl: what ends a progress bar cut short. */
void cli_render_report(const render_args *a, int status, const cli_render_void *at, const char *nl);

/* --stats of a render of scene with a's options. */
void cli_render_print_stats(const render_args *a, const rf_scene *scene, const rf_render_stats *s,
                            const rf_write_stats *w);

/* The format of standard output, from --format. */
rf_format cli_render_stdout_format(const char *name);

/* Writes img to a->output (or standard output), stopped by a signal
 * (a->image.cancel); prints why not; the writer's status. */
int cli_render_write(const render_args *a, const rf_image *img, rf_write_stats *written);

#endif
