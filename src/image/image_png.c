/*
 * image_png.c - PNG through libpng's classic API (compiled only with PNG=1).
 *
 * The simplified API (png_image_write_*) treats 16-bit data as linear, so
 * an sRGB-encoded 16-bit file needs the classic one.  We use it for every
 * PNG: RGB, 8 or 16 bits, no interlace; sRGB data is tagged with sRGB,
 * gAMA (1/2.2) and cHRM chunks (png_set_sRGB_gAMA_and_cHRM), linear data
 * with gAMA 1.0 only.
 *
 * libpng reports errors by longjmp.  Each setjmp lives in one small
 * function (encode_png, decode_png) that calls only libpng between the
 * setjmp and its return, allocates nothing, and keeps what must survive a
 * longjmp in memory its caller owns.
 */
#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include "image/codec.h"
#include "image/tonemap.h"

/* What libpng's error callback leaves for us before it longjmps. */
typedef struct png_failure {
    char msg[200];
    int saved_errno; /* errno when libpng gave up: why its fwrite failed */
    int status;      /* a status other than libpng's failure (cancelled, size refused), or 0 */
} png_failure;

/* PNG allows 2^31 - 1 pixels each way; libpng's own default stops at a
 * million, which would fail a legal image only once it is rendered. */
#define PNG_SIDE_MAX 0x7fffffffu

static void on_png_error(png_structp png, png_const_charp msg)
{
    png_failure *f = png_get_error_ptr(png);
    f->saved_errno = errno;
    snprintf(f->msg, sizeof f->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png; /* warnings (e.g. about ancillary chunks) do not stop us */
    (void)msg;
}

/* ---- Writing ---- */

/* The display codes of the whole image, PNG byte order (16-bit samples
 * big-endian); rowbytes receives the length of one row.  NULL when out of
 * memory or cancelled (*cancelled set). */
static unsigned char *pack_codes(const img_buf *img, const img_write_opts *o, img_write_stats *st,
                                 size_t *rowbytes, int *cancelled)
{
    size_t nb = o->png_bits == 16 ? 2 : 1, row = 3 * (size_t)img->width, n = row * (size_t)img->height;
    unsigned maxcode = o->png_bits == 16 ? 65535u : 255u;
    unsigned char *px = malloc(n * nb);
    *cancelled = 0;
    for (size_t i = 0; px && i < n; i++) {
        if (i % row == 0 && (*cancelled = img_row_cancelled(o, img)) != 0) {
            free(px);
            return NULL;
        }
        unsigned code = tonemap_quantize(img_display_value(img_sanitize(img->rgb[i], st), o), maxcode);
        if (nb == 2)
            px[2 * i] = (unsigned char)(code >> 8);
        px[nb * i + nb - 1] = (unsigned char)(code & 0xFF);
    }
    *rowbytes = 3 * nb * (size_t)img->width;
    return px;
}

static int encode_png(FILE *fp, const img_buf *img, const img_write_opts *o,
                      const unsigned char *px, size_t rowbytes, png_failure *f)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, f, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        snprintf(f->msg, sizeof f->msg, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, fp);
    png_set_user_limits(png, PNG_SIDE_MAX, PNG_SIDE_MAX);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, o->png_bits,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (o->linear_png)
        png_set_gAMA_fixed(png, info, PNG_GAMMA_LINEAR);
    else
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = 0; y < img->height; y++) {
        if (img_row_cancelled(o, img)) {
            f->status = STATUS_CANCELLED;
            png_destroy_write_struct(&png, &info);
            return -1;
        }
        png_write_row(png, px + (size_t)y * rowbytes);
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int img_png_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen)
{
    png_failure f = {"", 0, 0};
    size_t rowbytes;
    int cancelled;
    unsigned char *px = pack_codes(img, o, st, &rowbytes, &cancelled);
    if (!px)
        return cancelled ? img_error(err, errlen, STATUS_CANCELLED, "interrupted")
                         : img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    int failed = encode_png(fp, img, o, px, rowbytes, &f);
    free(px);
    if (!failed)
        return STATUS_OK;
    if (f.status == STATUS_CANCELLED)
        return img_error(err, errlen, STATUS_CANCELLED, "interrupted");
    /* libpng's stdio writer says only "Write Error"; errno said why. */
    if (ferror(fp))
        return img_error(err, errlen, STATUS_IO, "write error: %s", strerror(f.saved_errno));
    /* libpng's only failure that is not about the stream: an allocation. */
    int oom = strstr(f.msg, "emory") != NULL;
    return img_error(err, errlen, oom ? STATUS_NO_MEMORY : STATUS_IO, "PNG encoder: %s", f.msg);
}

/* ---- Reading ---- */

/* How stored codes become linear values (see img_read in image.h). */
typedef enum png_transfer { PNG_TF_SRGB, PNG_TF_LINEAR, PNG_TF_POWER } png_transfer;

/* What decode_png produces; owned by the caller so a longjmp loses nothing. */
typedef struct png_decoded {
    unsigned char *px;   /* rows of 8- or 16-bit RGB, PNG byte order */
    png_bytep *rows;     /* pointers into px */
    png_uint_32 width, height;
    int bits;            /* 8 or 16 after the transforms */
    png_transfer transfer;
    double file_gamma;   /* for PNG_TF_POWER: code = linear^file_gamma */
    const img_read_opts *opts;
} png_decoded;

static void choose_transfer(png_const_structrp png, png_const_inforp info, png_decoded *d)
{
    int intent;
    png_fixed_point g;
    d->transfer = PNG_TF_SRGB;
    if (png_get_sRGB(png, info, &intent))
        return;
    if (!png_get_gAMA_fixed(png, info, &g) || g <= 0)
        return;
    d->file_gamma = g / 100000.0;
    /* 1% as libpng itself uses to call a gamma "1.0" */
    d->transfer = d->file_gamma > 0.99 && d->file_gamma < 1.01 ? PNG_TF_LINEAR : PNG_TF_POWER;
}

/* Expands palette, grey and low bit depths to 8- or 16-bit RGB, drops alpha. */
static void set_rgb_transforms(png_structrp png)
{
    png_set_expand(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    (void)png_set_interlace_handling(png);
}

/* Allocates d->px and d->rows for the transformed image; 0 or -1. */
static int alloc_rows(png_structrp png, png_inforp info, png_decoded *d, png_failure *f)
{
    size_t rowbytes = png_get_rowbytes(png, info);
    d->bits = png_get_bit_depth(png, info);
    if (png_get_channels(png, info) != 3 || rowbytes != 3 * (size_t)(d->bits / 8) * d->width) {
        snprintf(f->msg, sizeof f->msg, "unexpected pixel layout after conversion to RGB");
        return -1;
    }
    d->px = malloc(rowbytes * d->height);
    d->rows = malloc(sizeof *d->rows * d->height);
    if (!d->px || !d->rows) {
        snprintf(f->msg, sizeof f->msg, "out of memory");
        return -1;
    }
    for (png_uint_32 y = 0; y < d->height; y++)
        d->rows[y] = d->px + (size_t)y * rowbytes;
    return 0;
}

static int decode_png(FILE *fp, png_decoded *d, png_failure *f)
{
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, f, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_read_struct(&png, NULL, NULL);
        snprintf(f->msg, sizeof f->msg, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    png_init_io(png, fp);
    png_set_user_limits(png, PNG_SIDE_MAX, PNG_SIDE_MAX);
    png_read_info(png, info);
    d->width = png_get_image_width(png, info);
    d->height = png_get_image_height(png, info);
    /* The size is judged before a byte of pixels is decoded or allocated. */
    f->status = img_check_header((long)d->width, (long)d->height, d->opts, f->msg, sizeof f->msg);
    if (f->status != STATUS_OK || d->opts->header_only) {
        png_destroy_read_struct(&png, &info, NULL);
        return f->status != STATUS_OK ? -1 : 0;
    }
    choose_transfer(png, info, d);
    set_rgb_transforms(png);
    png_read_update_info(png, info);
    if (alloc_rows(png, info, d, f) != 0)
        png_longjmp(png, 1);
    png_read_image(png, d->rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    return 0;
}

static double code_to_linear(unsigned code, unsigned maxcode, const png_decoded *d)
{
    double v = (double)code / (double)maxcode;
    switch (d->transfer) {
    case PNG_TF_LINEAR: return v;
    case PNG_TF_POWER: return pow(v, 1.0 / d->file_gamma);
    default: return tonemap_srgb_decode(v);
    }
}

static void unpack_linear(const png_decoded *d, img_buf *out)
{
    size_t n = 3 * (size_t)d->width * d->height;
    unsigned maxcode = d->bits == 16 ? 65535u : 255u;
    for (size_t i = 0; i < n; i++) {
        unsigned code = d->bits == 16 ? (unsigned)d->px[2 * i] << 8 | d->px[2 * i + 1] : d->px[i];
        out->rgb[i] = code_to_linear(code, maxcode, d);
    }
}

int img_png_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen)
{
    png_failure f = {"", 0, 0};
    png_decoded d;
    memset(&d, 0, sizeof d);
    d.opts = o;
    int rc = STATUS_OK;
    if (decode_png(fp, &d, &f) != 0)
        rc = f.status ? img_error(err, errlen, f.status, "%s", f.msg)
             : ferror(fp) ? img_error(err, errlen, STATUS_IO, "read error: %s", strerror(f.saved_errno))
                          : img_error(err, errlen, STATUS_DATA, "PNG decoder: %s", f.msg);
    if (rc == STATUS_OK && o->header_only) {
        out->width = (int)d.width;
        out->height = (int)d.height;
        return STATUS_OK;
    }
    if (rc == STATUS_OK && (rc = img_create(out, (int)d.width, (int)d.height)) != STATUS_OK)
        rc = img_error(err, errlen, rc, "out of memory");
    if (rc == STATUS_OK)
        unpack_linear(&d, out);
    free(d.px);
    free(d.rows);
    return rc;
}
