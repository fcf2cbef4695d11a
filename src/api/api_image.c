/*
 * api_image.c - the public API's images and image files (refray.h).
 */
#include <string.h>
#include "api/convert.h"
#include "io/image_io.h"

rf_status rf_image_create(int width, int height, const rf_allocator *allocator, rf_image **out)
{
    mem m = api_mem(allocator);
    if (!out)
        return RF_ERR_USAGE;
    *out = NULL;
    rf_image *img = mem_alloc(&m, sizeof *img);
    if (!img)
        return RF_ERR_NO_MEMORY;
    int status = img_create_mem(&img->buf, width, height, &m);
    if (status != STATUS_OK) {
        mem_free(&m, img, sizeof *img);
        return status == STATUS_INTERNAL ? RF_ERR_USAGE : api_status(status);
    }
    *out = img;
    return RF_OK;
}

int rf_image_width(const rf_image *img)
{
    return img ? img->buf.width : 0;
}

int rf_image_height(const rf_image *img)
{
    return img ? img->buf.height : 0;
}

double *rf_image_pixels(rf_image *img)
{
    return img ? img->buf.rgb : NULL;
}

void rf_image_free(rf_image *img)
{
    if (!img)
        return;
    mem m = img->buf.mem;
    img_free(&img->buf);
    mem_free(&m, img, sizeof *img);
}

rf_format rf_format_from_path(const char *path)
{
    switch (img_format_from_path(path)) {
    case IMG_FORMAT_PNG: return RF_FORMAT_PNG;
    case IMG_FORMAT_EXR: return RF_FORMAT_EXR;
    case IMG_FORMAT_PFM: return RF_FORMAT_PFM;
    case IMG_FORMAT_PPM: return RF_FORMAT_PPM;
    default: return RF_FORMAT_UNKNOWN;
    }
}

static img_format format_in(rf_format f)
{
    switch (f) {
    case RF_FORMAT_PNG: return IMG_FORMAT_PNG;
    case RF_FORMAT_EXR: return IMG_FORMAT_EXR;
    case RF_FORMAT_PFM: return IMG_FORMAT_PFM;
    case RF_FORMAT_PPM: return IMG_FORMAT_PPM;
    default: return IMG_FORMAT_UNKNOWN;
    }
}

int rf_format_available(rf_format fmt)
{
    return fmt != RF_FORMAT_UNKNOWN && img_format_available(format_in(fmt));
}

void rf_write_options_init(rf_write_options *o)
{
    img_write_opts d = img_write_opts_default();
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    o->exposure_stops = d.exposure_stops;
    o->tone = d.tone;
    o->linear = d.linear_png;
    o->png_bits = d.png_bits;
    o->exr_float = d.exr_float;
}

img_write_opts api_write_opts(const rf_write_options *o, img_write_stats *st, cancel_poll *cancel)
{
    img_write_opts w = img_write_opts_default();
    *cancel = cancel_poll_make(NULL, NULL);
    if (o) {
        w.exposure_stops = o->exposure_stops;
        w.tone = o->tone;
        w.linear_png = o->linear;
        w.png_bits = o->png_bits;
        w.exr_float = o->exr_float;
        *cancel = cancel_poll_make(o->cancel, o->user);
    }
    w.stats = st;
    w.cancel = cancel;
    return w;
}

static void write_stats(const img_write_stats *st, rf_write_stats *out)
{
    if (out) {
        out->nonfinite = st->nonfinite;
        out->clamped = st->clamped;
    }
}

/* A NULL image, path or stream: RF_ERR_USAGE with the reason. */
static rf_status missing(char *message, size_t message_size, rf_write_stats *stats, const char *why)
{
    img_write_stats none = {0, 0};
    write_stats(&none, stats);
    if (message && message_size > 0)
        snprintf(message, message_size, "%s", why);
    return RF_ERR_USAGE;
}

rf_status rf_image_write(const rf_image *img, const char *path, const rf_write_options *o, rf_write_stats *stats,
                         char *message, size_t message_size)
{
    img_write_stats st = {0, 0};
    if (!img || !path)
        return missing(message, message_size, stats, !img ? "no image to write" : "no path to write to");
    cancel_poll cancel;
    img_write_opts w = api_write_opts(o, &st, &cancel);
    int status = img_write(path, &img->buf, &w, message, message ? message_size : 0);
    write_stats(&st, stats);
    return api_status(status);
}

rf_status rf_image_write_stream(const rf_image *img, FILE *stream, rf_format fmt, const rf_write_options *o,
                                rf_write_stats *stats, char *message, size_t message_size)
{
    img_write_stats st = {0, 0};
    if (!img || !stream)
        return missing(message, message_size, stats, !img ? "no image to write" : "no stream to write to");
    cancel_poll cancel;
    img_write_opts w = api_write_opts(o, &st, &cancel);
    int status = img_write_stream(stream, format_in(fmt), &img->buf, &w, message, message ? message_size : 0);
    write_stats(&st, stats);
    return api_status(status);
}
