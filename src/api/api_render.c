/*
 * api_render.c - the public API's rendering: renderers, regions into the
 * caller's float buffer, whole images (refray.h).
 */
#include <stdint.h>
#include <string.h>
#include "api/convert.h"
#include "base/cancel.h"
#include "base/hash.h"

void rf_render_options_init(rf_render_options *o)
{
    if (o)
        memset(o, 0, sizeof *o);
}

/* Whether the caller's cancel says stop, asked now (base/cancel.h). */
static int stop_asked(const rf_render_options *o)
{
    cancel_poll c = cancel_poll_make(o->cancel, o->user);
    return cancel_now(&c);
}

/* The renderer's progress hook: the caller's progress, then cancel. */
static int on_row(void *ctx, int done, int total)
{
    const rf_render_options *o = &((const rf_renderer *)ctx)->options;
    if (o->progress)
        o->progress(o->user, done, total);
    return stop_asked(o);
}

/* [EMBED-API-11] Whether what ro overrides (the image size, the camera and
 * light samples, the depth) keeps to the limits the scene was loaded with,
 * as the scene's own statements had to (the refray program refuses the
 * same overrides: --samples 65 is over --max-samples 64). */
static int options_fit(const scene_model *s, const render_opts *ro)
{
    double w = ro->width ? ro->width : s->image.width, h = ro->height ? ro->height : s->image.height;
    return w <= (double)s->max_render.width && h <= (double)s->max_render.height &&
           w * h <= (double)s->max_render.pixels && ro->samples <= s->max_render.samples &&
           ro->light_samples <= s->max_render.light_samples && ro->max_depth <= s->max_render.depth;
}

rf_status rf_renderer_create(const rf_scene *scene, const rf_render_options *o, rf_renderer **out)
{
    const scene_model *s = api_scene(scene);
    render_opts ro;
    if (!out)
        return RF_ERR_USAGE;
    *out = NULL;
    if (!s || !api_render_opts(o, &ro) || !options_fit(s, &ro))
        return RF_ERR_USAGE;
    rf_renderer *r = mem_alloc(&s->mem, sizeof *r);
    if (!r)
        return RF_ERR_NO_MEMORY;
    if (o)
        r->options = *o;
    else
        rf_render_options_init(&r->options);
    ro.progress = on_row;
    ro.progress_ctx = r;
    ro.cancel = r->options.cancel;
    ro.cancel_ctx = r->options.user;
    int status = renderer_init(&r->r, s, &ro);
    if (status != STATUS_OK) {
        mem_free(&s->mem, r, sizeof *r);
        return api_status(status);
    }
    *out = r;
    return RF_OK;
}

void rf_renderer_size(const rf_renderer *r, int *width, int *height)
{
    if (width)
        *width = r ? r->r.stats.width : 0;
    if (height)
        *height = r ? r->r.stats.height : 0;
}

/* A float or a double region (one of f32, f64 set), checked first. */
static rf_status region(rf_renderer *r, int x0, int y0, int x1, int y1, float *f32, double *f64, size_t row_stride)
{
    if (!r)
        return RF_ERR_USAGE;
    const render_stats *st = &r->r.stats;
    if (x0 < 0 || y0 < 0 || x1 > st->width || y1 > st->height || x0 >= x1 || y0 >= y1 || (!f32 && !f64) ||
        row_stride < 3 * (size_t)(x1 - x0))
        return RF_ERR_USAGE;
    /* The last row ends (rows - 1) * row_stride + 3 * columns elements in.
     * The bound is in elements a pointer can step over (its byte offset
     * within PTRDIFF_MAX): a bound in elements alone let the byte address
     * wrap, and a stride of SIZE_MAX / 2 floats wrote pixels[-1]. */
    size_t reach = (size_t)PTRDIFF_MAX / (f32 ? sizeof *f32 : sizeof *f64);
    if ((size_t)(y1 - y0 - 1) > (reach - 3 * (size_t)(x1 - x0)) / row_stride)
        return RF_ERR_USAGE;
    if (stop_asked(&r->options))
        return RF_ERR_CANCELLED;
    render_target t = {x0, y0, x1, y1, f32, f64, row_stride};
    return api_status(renderer_region(&r->r, &t));
}

rf_status rf_render_region(rf_renderer *r, int x0, int y0, int x1, int y1, float *pixels, size_t row_stride)
{
    return region(r, x0, y0, x1, y1, pixels, NULL, row_stride);
}

rf_status rf_render_region_double(rf_renderer *r, int x0, int y0, int x1, int y1, double *pixels,
                                  size_t row_stride)
{
    return region(r, x0, y0, x1, y1, NULL, pixels, row_stride);
}

unsigned long long rf_renderer_fingerprint(const rf_renderer *r)
{
    static const char version[] = RF_VERSION_STRING;
    if (!r)
        return 0;
    return hash_bytes(renderer_fingerprint(&r->r), version, sizeof version - 1);
}

void rf_renderer_stats(const rf_renderer *r, rf_render_stats *stats)
{
    if (!stats)
        return;
    if (!r) {
        memset(stats, 0, sizeof *stats);
        return;
    }
    api_render_stats(&r->r.stats, stats);
}

void rf_renderer_free(rf_renderer *r)
{
    if (!r)
        return;
    mem m = r->r.tracer.scene->mem;
    renderer_free(&r->r);
    mem_free(&m, r, sizeof *r);
}

rf_status rf_render_image(const rf_scene *scene, const rf_render_options *o, rf_image **out,
                          rf_render_stats *stats)
{
    const scene_model *s = api_scene(scene);
    rf_renderer *r;
    if (!out)
        return RF_ERR_USAGE;
    *out = NULL;
    if (stats)
        memset(stats, 0, sizeof *stats);
    rf_status status = rf_renderer_create(scene, o, &r);
    if (status != RF_OK)
        return status;
    rf_image *img = mem_alloc(&s->mem, sizeof *img);
    if (!img || img_create_mem(&img->buf, r->r.stats.width, r->r.stats.height, &s->mem) != STATUS_OK)
        status = RF_ERR_NO_MEMORY;
    if (status == RF_OK && !stop_asked(&r->options)) {
        render_target all = {0, 0, img->buf.width, img->buf.height, NULL, img->buf.rgb, 3 * (size_t)img->buf.width};
        status = api_status(renderer_region(&r->r, &all));
    } else if (status == RF_OK) {
        status = RF_ERR_CANCELLED;
    }
    if (stats)
        rf_renderer_stats(r, stats);
    rf_renderer_free(r);
    if (status != RF_OK && img) {
        img_free(&img->buf);
        mem_free(&s->mem, img, sizeof *img);
        img = NULL;
    }
    *out = img;
    return status;
}
