/*
 * image.c - the frame buffer and the number conversions every writer
 * shares (half, float, display value).
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "image/image.h"
#include "image/tonemap.h"

int img_error(char *err, size_t errlen, int code, const char *fmt, ...)
{
    if (err && errlen > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return code;
}

int img_create(img_buf *img, int width, int height)
{
    return img_create_mem(img, width, height, NULL);
}

int img_create_mem(img_buf *img, int width, int height, const mem *m)
{
    img->width = img->height = 0;
    img->rgb = NULL;
    img->mem = mem_pick(m);
    if (width < 1 || height < 1 || (size_t)width > SIZE_MAX / 3 / sizeof(double) / (size_t)height)
        return STATUS_INTERNAL;
    img->rgb = mem_calloc(&img->mem, (size_t)width * (size_t)height * 3, sizeof(double));
    if (!img->rgb)
        return STATUS_NO_MEMORY;
    img->width = width;
    img->height = height;
    return STATUS_OK;
}

void img_free(img_buf *img)
{
    if (!img)
        return;
    if (img->rgb)
        mem_free(&img->mem, img->rgb, (size_t)img->width * (size_t)img->height * 3 * sizeof(double));
    img->rgb = NULL;
    img->width = img->height = 0;
}

int img_row_cancelled(const img_write_opts *o, const img_buf *img)
{
    return cancel_steps(o->cancel, 1 + img->width / 1024);
}

img_read_opts img_read_opts_default(void)
{
    img_read_opts o = {IMG_DEFAULT_MAX_PIXELS, 0, 0, 0};
    return o;
}

long img_max_pixels(const img_read_opts *o)
{
    return o && o->max_pixels > 0 ? o->max_pixels : IMG_DEFAULT_MAX_PIXELS;
}

int img_check_header(long width, long height, const img_read_opts *o, char *err, size_t errlen)
{
    long max = img_max_pixels(o);
    if (width < 1 || height < 1 || width > INT_MAX || height > INT_MAX)
        return img_error(err, errlen, STATUS_DATA, "bad image size %ldx%ld in the header", width, height);
    /* A size expected (a mask for a given image) is judged first: it is
     * the telling reason, and it bounds the pixels by itself. */
    if (o && o->width > 0 && o->height > 0 && (width != o->width || height != o->height))
        return img_error(err, errlen, STATUS_DATA, "the image is %ldx%ld, not the %dx%d expected", width, height,
                         o->width, o->height);
    if ((double)width * (double)height > (double)max)
        return img_error(err, errlen, STATUS_DATA, "the image is %ldx%ld, over --max-pixels %ld", width, height,
                         max);
    return STATUS_OK;
}

img_write_opts img_write_opts_default(void)
{
    img_write_opts o;
    o.exposure_stops = 0.0;
    o.tone = IMG_TONE_CLAMP;
    o.linear_png = 0;
    o.png_bits = 8;
    o.exr_float = 0;
    o.stats = NULL;
    o.cancel = NULL;
    return o;
}

/* ---- Number conversions ---- */

double img_sanitize(double v, img_write_stats *st)
{
    if (isfinite(v))
        return v;
    st->nonfinite++;
    return 0.0;
}

/* x rounded to the nearest integer, ties to the even one, for 0 <= x <
 * 2^52 (so floor(x) and the comparisons are exact); independent of the
 * floating-point rounding mode. */
static double round_half_even(double x)
{
    double f = floor(x);
    double r = x - f;
    if (r > 0.5 || (r == 0.5 && fmod(f, 2.0) != 0.0))
        return f + 1.0;
    return f;
}

/* binary16: 1 sign bit, 5 exponent bits (bias 15), 10 fraction bits.
 *   subnormal  |v| = m * 2^-24,                 m in [0, 1023], exponent field 0
 *   normal     |v| = (1024 + m) * 2^(E - 10),   E in [-14, 15], field E + 15
 * In both ranges the code is (field << 10) + m, and a rounded m of 1024
 * carries into the exponent field, which is exactly the next binade.  The
 * largest finite half is 65504 = 2047 * 2^5; the halfway point to the next
 * step, 65520, ties to the even neighbour 65536 = infinity, so every
 * |v| >= 65520 would overflow. */
uint16_t img_half_from_double(double v, int *clamped)
{
    if (clamped)
        *clamped = 0;
    if (isnan(v))
        return 0;
    uint16_t sign = signbit(v) ? 0x8000u : 0u;
    double a = fabs(v);
    if (a >= 65520.0) {
        if (clamped)
            *clamped = 1;
        return (uint16_t)(sign | 0x7BFFu);
    }
    if (a < 0x1p-14)
        return (uint16_t)(sign | (uint16_t)round_half_even(a * 0x1p24));
    int e;
    frexp(a, &e); /* a = f * 2^e, f in [0.5, 1): E = e - 1 */
    double m = round_half_even(ldexp(a, 11 - e) - 1024.0);
    return (uint16_t)(sign | (((unsigned)(e - 1 + 15) << 10) + (unsigned)m));
}

/* FLT_MAX = (2 - 2^-23) * 2^127; half an ulp above it, (2 - 2^-24) * 2^127,
 * is the tie that rounds to even, i.e. to 2^128 = infinity. */
#define FLOAT_OVERFLOW_EDGE ((2.0 - 0x1p-24) * 0x1p127)

float img_float_from_double(double v, int *clamped)
{
    if (clamped)
        *clamped = 0;
    if (isnan(v))
        return 0.0f;
    if (fabs(v) >= FLOAT_OVERFLOW_EDGE) {
        if (clamped)
            *clamped = 1;
        return signbit(v) ? -FLT_MAX : FLT_MAX;
    }
    return (float)v;
}

double img_display_value(double v, const img_write_opts *o)
{
    v = tonemap_exposure(v, o->exposure_stops);
    v = o->tone == IMG_TONE_REINHARD ? tonemap_reinhard(v) : tonemap_clamp(v);
    v = tonemap_clamp(v);
    return o->linear_png ? v : tonemap_srgb_encode(v);
}

