/*
 * image.h - the linear RGB frame buffer, the options and statistics of
 * writing it, and the number conversions the file formats share (the
 * files themselves: image_file.h).
 *
 * Contract of the writers (the model decisions, "Output"):
 *   - EXR and PFM store the linear values as they are, > 1 included
 *     (HDR); negative values are kept too.  No exposure, no tone curve.
 *   - PNG and PPM store display codes: exposure (v * 2^stops), then clamp
 *     to [0,1] or Reinhard v/(1+v), then sRGB encoding unless linear_png,
 *     then round-half-up quantisation (tonemap.h).  Negative values
 *     therefore become 0.
 *   - No written pixel is ever NaN or infinite: a non-finite input value
 *     is written as 0 and counted (the tracer guarantees finiteness; this
 *     is a second line of defence), and a finite value too large for the
 *     file's number type (half: 65504, float: FLT_MAX) is written as the
 *     largest finite value of that type, with its sign, and counted.
 *   - img_write is atomic: the data goes to "<path>.tmp.XXXXXX" (mkstemp,
 *     same directory), is flushed, fsync'ed and closed with every result
 *     checked, and only then renamed onto path.  On any error the
 *     temporary file is removed and nothing at path is created or changed.
 *     The new file gets the mode of the file it replaces, or 0666 less the
 *     umask for a new one.
 *
 * Functions return a status of base/status.h (STATUS_OK, STATUS_USAGE for an
 * unknown extension or a format compiled out, STATUS_DATA for a malformed
 * file, STATUS_NO_INPUT when a file cannot be opened, STATUS_INTERNAL for
 * an invalid image passed in, STATUS_NO_MEMORY, STATUS_IO), and every
 * failing call leaves a one-line message in err (err may be NULL; a
 * message longer than errlen is cut).
 */
#ifndef REFRAY_IMAGE_H
#define REFRAY_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "base/cancel.h"
#include "base/mem.h"
#include "base/status.h"

/* The readers' default limit on the pixels a header may claim, the same
 * as the scenes' --max-pixels (a corrupt or hostile header must not make
 * us allocate gigabytes). */
#define IMG_DEFAULT_MAX_PIXELS (64L * 1024 * 1024)

/* Linear RGB, row-major from the top row, 3 doubles per pixel. */
typedef struct img_buf {
    int width, height;
    double *rgb;
    mem mem;           /* where rgb lives; zeroed: the C library */
} img_buf;

/* Allocates a width x height image of zeros.  Returns 0, STATUS_INTERNAL for
 * a size < 1 or too large to address, STATUS_NO_MEMORY when out of memory; on
 * failure *img is empty (no pixels). */
int img_create(img_buf *img, int width, int height);
/* The same with the pixels from the allocator m (NULL: the C library). */
int img_create_mem(img_buf *img, int width, int height, const mem *m);

/* Frees the pixels and resets *img to empty (no pixels); NULL and an already
 * freed image are fine. */
void img_free(img_buf *img);

/* The 3 channels of pixel (x, y), y = 0 the top row. */
static inline double *img_pixel(const img_buf *img, int x, int y)
{
    return img->rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
}

enum { IMG_TONE_CLAMP = 0, IMG_TONE_REINHARD = 1 };

/* What a write had to change so that the file holds only finite values. */
typedef struct img_write_stats {
    size_t nonfinite; /* NaN or infinite values written as 0 */
    size_t clamped;   /* finite values beyond the number type's range, clamped */
} img_write_stats;

typedef struct img_write_opts {
    double exposure_stops;  /* PNG/PPM only: v * 2^stops before the tone step */
    int tone;               /* PNG/PPM only: IMG_TONE_CLAMP (default) or IMG_TONE_REINHARD */
    int linear_png;         /* PNG/PPM: 1 = store linear codes (PNG says gAMA 1.0), no sRGB */
    int png_bits;           /* 8 (default) or 16; PPM is always 8 */
    int exr_float;          /* 1 = EXR channels as 32-bit float, 0 = half (default) */
    img_write_stats *stats; /* optional out: filled by every write that gets to the pixels */
    cancel_poll *cancel;    /* asked once per row encoded: a stop ends the write with
                               STATUS_CANCELLED ([REL-CANCEL-1]); NULL: never */
} img_write_opts;

/* exposure 0, clamp, sRGB, 8-bit PNG, half EXR, no stats, no cancel. */
img_write_opts img_write_opts_default(void);

/* What a reader accepts, checked on the header before anything is
 * allocated for the pixels ([REL-IMAGE-1]). */
typedef struct img_read_opts {
    long max_pixels;       /* a header claiming more is refused (STATUS_DATA) */
    int width, height;     /* > 0: a header of another size is refused */
    int header_only;       /* 1: stop after the header; *out gets the size but no pixels */
} img_read_opts;

/* IMG_DEFAULT_MAX_PIXELS, any size, the whole image. */
img_read_opts img_read_opts_default(void);

/* The pixels an image header may claim under o: o->max_pixels, or
 * IMG_DEFAULT_MAX_PIXELS when o is NULL or sets none. */
long img_max_pixels(const img_read_opts *o);

/* A header's width x height against o: STATUS_OK, or STATUS_DATA with the
 * reason ("the image is 16384x16384, over --max-pixels 67108864", "the
 * image is 9x9, not the 8x8 expected") in err. */
int img_check_header(long width, long height, const img_read_opts *o, char *err, size_t errlen);

/* ---- Pure conversions shared by the writers (exported for the tests) ---- */

/* IEEE 754 binary16 bits of v, rounded to nearest with ties to even,
 * straight from double (going through float would round twice).  Never
 * returns an infinity or NaN code: a v that would round to infinity
 * (|v| >= 65520) becomes +-65504 and sets *clamped to 1 (else 0); NaN
 * becomes +0 (*clamped 0).  clamped may be NULL. */
uint16_t img_half_from_double(double v, int *clamped);

/* v as float, rounded to nearest, with the same clamping rule at FLT_MAX
 * (|v| >= FLT_MAX + half an ulp would round to infinity). */
float img_float_from_double(double v, int *clamped);

/* The PNG/PPM display value of linear v in [0, 1], before quantisation:
 * exposure, tone step, clamp, then sRGB encoding unless o->linear_png.
 * NaN gives 0. */
double img_display_value(double v, const img_write_opts *o);

/* ---- Shared by the format back ends ---- */

/* One row of img about to be encoded counted into o->cancel (a step per
 * 1024 pixels); 1: stop, the write is cancelled. */
int img_row_cancelled(const img_write_opts *o, const img_buf *img);

/* A finite v unchanged; NaN/Inf become 0 and are counted in st. */
double img_sanitize(double v, img_write_stats *st);

/* Formats a message into err (if any) and returns code; for back ends. */
int img_error(char *err, size_t errlen, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

#endif
