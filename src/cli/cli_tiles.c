/*
 * cli_tiles.c - see cli_tiles.h.  The bands go out as the jobs of an
 * io/pool.h run; a worker renders its band a row at a time with
 * rf_render_region_double and sends each row, so the parent holds the
 * only copy of the image, draws the one progress bar, and saves each band
 * into the checkpoint when its last row has come.  A pixel does not depend
 * on the band it is rendered in, so the doubles are those of a render in
 * one piece, whatever the number of workers.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/status.h"
#include "cli/cli_progress.h"
#include "cli/cli_signal.h"
#include "cli/cli_args.h"
#include "cli/cli_checkpoint.h"
#include "cli/cli_tiles.h"
#include "io/pool.h"
#include "render/render.h"

/* The messages of a worker, told apart by their first int32. */
enum { MSG_ROW = 1, MSG_OVERFLOW = 2, MSG_STATS = 3 };

typedef struct tiles_run {
    cli_tiles *t;
    int *pending;        /* pool job k is band pending[k] */
    double *row;         /* a row message: one double's room for the kind and y, then the pixels */
    size_t row_bytes;
    cli_progress bar;
    long rows_done, rows_total;
    int stats_seen;
    char why[400];       /* a callback's reason for stopping the run */
} tiles_run;

static size_t region_width(const cli_tiles *t)
{
    return (size_t)(t->target.region.x1 - t->target.region.x0);
}

/* ---- In the worker ---- */

static int send_overflow(const cli_tiles *t, pool_link *link)
{
    rf_render_stats st;
    rf_renderer_stats(t->renderer, &st);
    int32_t msg[4] = {MSG_OVERFLOW, st.overflow_x, st.overflow_y, st.medium_overflows > 0};
    pool_send(link, msg, sizeof msg);
    return STATUS_DATA;
}

static int work(void *ctx, int k, pool_link *link)
{
    tiles_run *run = ctx;
    const cli_tiles *t = run->t;
    tile_rect band = cli_tiles_band(t, run->pending[k]);
    for (int y = band.y0; y < band.y1; y++) {
        int32_t head[2] = {MSG_ROW, y};
        memcpy(run->row, head, sizeof head);
        rf_status s = rf_render_region_double(t->renderer, band.x0, y, band.x1, y + 1, run->row + 1,
                                              3 * region_width(t));
        if (s == RF_ERR_DATA)
            return send_overflow(t, link);
        if (s != RF_OK)
            return (int)s;
        if (pool_send(link, run->row, run->row_bytes) != 0)
            return STATUS_CANCELLED;
    }
    return STATUS_OK;
}

static void finish(void *ctx, pool_link *link)
{
    tiles_run *run = ctx;
    unsigned char msg[sizeof(int32_t) + sizeof(rf_render_stats)];
    int32_t kind = MSG_STATS;
    rf_render_stats st;
    rf_renderer_stats(run->t->renderer, &st);
    memcpy(msg, &kind, sizeof kind);
    memcpy(msg + sizeof kind, &st, sizeof st);
    pool_send(link, msg, sizeof msg);
}

/* ---- In the parent ---- */

static void add_stats(rf_render_stats *sum, const rf_render_stats *s, int first)
{
    if (first) {
        *sum = *s;
        return;
    }
    sum->camera_rays += s->camera_rays;
    sum->shadow_rays += s->shadow_rays;
    sum->reflection_rays += s->reflection_rays;
    sum->refraction_rays += s->refraction_rays;
    sum->total_internal_reflection_rays += s->total_internal_reflection_rays;
    sum->light_samples += s->light_samples;
    sum->light_samples_on_surface += s->light_samples_on_surface;
    sum->nonfinite += s->nonfinite;
    sum->medium_overflows += s->medium_overflows;
    sum->node_visits += s->node_visits;
    sum->primitive_tests += s->primitive_tests;
}

static int take_row(tiles_run *run, int k, const unsigned char *data, size_t len)
{
    cli_tiles *t = run->t;
    tile_rect band = cli_tiles_band(t, run->pending[k]);
    int32_t y;
    memcpy(&y, data + sizeof(int32_t), sizeof y);
    if (len != run->row_bytes || y < band.y0 || y >= band.y1) {
        snprintf(run->why, sizeof run->why, "a worker sent a malformed row");
        return STATUS_INTERNAL;
    }
    size_t w = 3 * region_width(t);
    memcpy(t->pixels + (size_t)(y - t->target.region.y0) * w, data + sizeof(double), w * sizeof(double));
    cli_progress_show(&run->bar, ++run->rows_done, run->rows_total);
    return STATUS_OK;
}

static int message(void *ctx, int k, const void *data, size_t len)
{
    tiles_run *run = ctx;
    int32_t kind = 0;
    if (len >= sizeof kind)
        memcpy(&kind, data, sizeof kind);
    if (kind == MSG_ROW && k >= 0)
        return take_row(run, k, data, len);
    if (kind == MSG_OVERFLOW && len == 4 * sizeof(int32_t)) {
        int32_t at[4];
        memcpy(at, data, sizeof at);
        run->t->overflow_x = at[1];
        run->t->overflow_y = at[2];
        run->t->overflow_medium = at[3];
        return STATUS_OK;
    }
    if (kind == MSG_STATS && len == sizeof kind + sizeof(rf_render_stats)) {
        rf_render_stats st;
        memcpy(&st, (const unsigned char *)data + sizeof kind, sizeof st);
        add_stats(&run->t->stats, &st, !run->stats_seen++);
        return STATUS_OK;
    }
    snprintf(run->why, sizeof run->why, "a worker sent a malformed message");
    return STATUS_INTERNAL;
}

/* A band that cannot be saved gives up the checkpoint, not the render
 * ([SCALE-RESUME-5]): its pixels are in memory and the output still
 * comes; one warning, and no more saves, since what stopped this one (DIR
 * removed by another render of the same command, a full disk, a changed
 * permission) stops the next. */
static int done(void *ctx, int k)
{
    tiles_run *run = ctx;
    cli_tiles *t = run->t;
    char why[700];
    if (!t->checkpoint || t->checkpoint_lost)
        return STATUS_OK;
    if (cli_checkpoint_save(t, run->pending[k], why, sizeof why) != STATUS_OK) {
        t->checkpoint_lost = 1;
        cli_note(cli_progress_break(&run->bar), "warning: %s; rendering on without the checkpoint (the output is "
                 "still written; the tiles from here on are not kept)", why);
    }
    return STATUS_OK;
}

/* The bands to render, from done[]; their rows already done into *rows. */
static int list_pending(const cli_tiles *t, const unsigned char *done_band, int *pending, long *rows)
{
    int n = 0;
    *rows = 0;
    for (int b = 0; b < t->bands; b++) {
        tile_rect r = cli_tiles_band(t, b);
        if (done_band[b])
            *rows += r.y1 - r.y0;
        else
            pending[n++] = b;
    }
    return n;
}

/* Prints why the run failed, unless it was a stop or a ray tree over the
 * budget, which the caller reports as a render in one piece does. */
static void report_failure(const tiles_run *run, int rc, const pool_failure *f, const char *pool_why)
{
    char generic[100];
    const char *why = run->why[0] ? run->why : pool_why;
    if (rc == STATUS_OK || rc == STATUS_CANCELLED || (rc == STATUS_DATA && !why[0]))
        return;
    if (!why[0]) {
        snprintf(generic, sizeof generic, "%s", status_string(rc));
        why = generic;
    }
    const char *nl = cli_progress_break(&run->bar);
    if (f->job >= 0) {
        tile_rect r = cli_tiles_band(run->t, run->pending[f->job]);
        cli_note(nl, "error: %s while rendering rows %d..%d; nothing written", why, r.y0, r.y1 - 1);
    } else {
        cli_note(nl, "error: %s; nothing written", why);
    }
}

/* Runs the pending bands on the pool. */
static int run_bands(tiles_run *run, int count)
{
    cli_tiles *t = run->t;
    pool_ops ops = {work, finish, message, done, run};
    pool_failure fail;
    char why[300];
    double start = render_clock();
    int rc = pool_run(t->jobs > 1 ? t->jobs : 0, count, &ops, cli_signal_flag(), &fail, why, sizeof why);
    t->stats.seconds = render_clock() - start;
    report_failure(run, rc, &fail, why);
    if (rc == STATUS_OK && run->rows_done != run->rows_total) {
        cli_error("the workers rendered %ld of %ld rows; nothing written", run->rows_done,
                run->rows_total);
        rc = STATUS_INTERNAL;
    }
    return rc;
}

int cli_tiles_render(cli_tiles *t)
{
    int rows = t->target.region.y1 - t->target.region.y0, rc = STATUS_OK;
    tiles_run run;
    memset(&run, 0, sizeof run);
    run.t = t;
    run.rows_total = rows;
    t->bands = cli_tiles_band_count(rows, t->jobs);
    memset(&t->stats, 0, sizeof t->stats);
    unsigned char *done_band = calloc((size_t)rows, 1);
    run.pending = malloc((size_t)rows * sizeof *run.pending);
    run.row_bytes = (1 + 3 * region_width(t)) * sizeof(double);
    run.row = malloc(run.row_bytes);
    if (!done_band || !run.pending || !run.row) {
        fputs("refray: error: out of memory\n", stderr);
        rc = STATUS_NO_MEMORY;
    }
    if (rc == STATUS_OK && t->checkpoint)
        rc = cli_checkpoint_open(t, done_band);
    if (rc == STATUS_OK) {
        int count = list_pending(t, done_band, run.pending, &run.rows_done);
        if (t->checkpoint && count < t->bands && !t->quiet)
            cli_note("", "resuming from '%s': %d of %d tiles are done", t->checkpoint, t->bands - count, t->bands);
        cli_progress_init(&run.bar, !t->quiet, run.rows_done);
        rc = run_bands(&run, count);
        if (rc == STATUS_CANCELLED || rc == STATUS_DATA)
            fputs(cli_progress_break(&run.bar), stderr);
    }
    free(done_band);
    free(run.pending);
    free(run.row);
    return rc;
}
