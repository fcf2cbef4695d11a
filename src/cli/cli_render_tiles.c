/*
 * cli_render_tiles.c - refray render with --region, --tile, --jobs or
 * --checkpoint (spec/scaling.md): the region is rendered in bands of rows
 * by cli_tiles.c into an image of doubles, then written as the image (a
 * render of all of it) or as a tile file with the whole image's size, the
 * region and the render's key (--region, --tile).
 */
#include <stdio.h>
#include <string.h>
#include "api/convert.h"
#include "cli/cli_checkpoint.h"
#include "cli/cli_render_tiles.h"
#include "cli/cli_tiles.h"
#include "io/pool.h"
#include "io/tile_file.h"

/* The region a asks for in the width x height image: the tile, the
 * region, or all of it.  0, or the usage error after printing it. */
static int pick_region(const render_args *a, int width, int height, tile_rect *r)
{
    r->x0 = 0;
    r->y0 = 0;
    r->x1 = width;
    r->y1 = height;
    if (a->tile_count > height)
        return cli_usage_error("render: --tile %d/%d: the image has %d rows, so N is at most %d", a->tile_index,
                               a->tile_count, height, height);
    if (a->tile_count) {
        tile_band(0, height, a->tile_count, a->tile_index, &r->y0, &r->y1);
        return 0;
    }
    if (!a->has_region)
        return 0;
    const int *g = a->region;
    if (g[0] >= g[2] || g[1] >= g[3] || g[2] > width || g[3] > height)
        return cli_usage_error("render: --region %d %d %d %d is not inside the %dx%d image (0 <= X0 < X1 <= %d, "
                               "0 <= Y0 < Y1 <= %d)", g[0], g[1], g[2], g[3], width, height, width, height);
    r->x0 = g[0];
    r->y0 = g[1];
    r->x1 = g[2];
    r->y1 = g[3];
    return 0;
}

/* Writes the finished region: a tile file, or the image. */
static int write_result(const render_args *a, const cli_tiles *t, const rf_image *img, rf_write_stats *written)
{
    if (!a->has_region && !a->tile_count)
        return cli_render_write(a, img, written);
    char why[700];
    img_write_stats st = {0, 0};
    cancel_poll cancel;
    img_write_opts o = api_write_opts(&a->image, &st, &cancel);
    int status = tile_file_write(a->output, &t->target, &img->buf, &o, why, sizeof why);
    written->nonfinite = st.nonfinite;
    written->clamped = st.clamped;
    if (status == STATUS_CANCELLED)
        fputs("refray: interrupted; nothing written\n", stderr);
    else if (status != STATUS_OK)
        cli_error("%s", why);
    return status;
}

/* Renders and writes with the renderer made: t->renderer. */
static int render_region(const render_args *a, const rf_scene *scene, cli_tiles *t)
{
    rf_image *img = NULL;
    rf_write_stats written = {0, 0};
    const tile_rect *r = &t->target.region;
    int status = (int)rf_image_create(r->x1 - r->x0, r->y1 - r->y0, NULL, &img);
    if (status != STATUS_OK) {
        cli_render_report(a, status, NULL, "");
        return status;
    }
    t->pixels = rf_image_pixels(img);
    t->jobs = a->jobs ? a->jobs : pool_cpu_count();
    t->checkpoint = a->checkpoint;
    t->output = a->output;
    t->quiet = a->quiet;
    t->read = img_read_opts_default();
    t->read.max_pixels = a->scene.limits.max_pixels;
    t->overflow_x = t->overflow_y = -1;
    status = cli_tiles_render(t);
    cli_render_void at = {t->overflow_x, t->overflow_y, t->overflow_medium};
    if (status == STATUS_CANCELLED || (status == STATUS_DATA && t->overflow_x >= 0))
        cli_render_report(a, status, &at, "");
    if (status == STATUS_OK)
        status = write_result(a, t, img, &written);
    if (status == STATUS_OK && a->checkpoint)
        cli_tiles_checkpoint_clear(t);
    if (status == STATUS_OK && a->stats)
        cli_render_print_stats(a, scene, &t->stats, &written);
    rf_image_free(img);
    return status;
}

int cli_render_tiles(const render_args *a, const rf_scene *scene)
{
    rf_render_options o = cli_render_options(a, NULL);
    cli_tiles t;
    memset(&t, 0, sizeof t);
    int status = (int)rf_renderer_create(scene, &o, &t.renderer);
    if (status != STATUS_OK) {
        cli_render_report(a, status, NULL, "");
        return status;
    }
    rf_renderer_size(t.renderer, &t.target.width, &t.target.height);
    t.target.key = rf_renderer_fingerprint(t.renderer);
    status = pick_region(a, t.target.width, t.target.height, &t.target.region);
    if (status == 0)
        status = render_region(a, scene, &t);
    rf_renderer_free(t.renderer);
    return status;
}
