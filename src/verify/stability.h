/*
 * stability.h - how stable is a picture?  The same scene rendered with the
 * tracer's `real` as double and as long double (src/base/vec.h), and the two
 * images compared pixel by pixel: where they differ and by how much is the
 * part of the picture that rounding decides (spec/numerics.md, "The
 * stability tool").
 *
 * The two renders come from two programs (refray and its long double twin
 * refray-ld, `make refray-ld`); the twin hands its image over as a raw
 * dump, a text file that is lossless for any long double:
 *
 *   refray-raw 1 WIDTH HEIGHT REAL NONFINITE\n      REAL: double or long-double
 *   R G B\n                                         one line per pixel, rows
 *   ...                                             from the top, each value
 *                                                   in C99 hex-float form (%La)
 *
 * Values are kept as long double on both sides, so a double render loses
 * nothing either.
 */
#ifndef REFRAY_STABILITY_H
#define REFRAY_STABILITY_H

#include <stdio.h>
#include "image/image.h"
#include "render/render.h"
#include "scene/scene.h"

typedef struct stab_image {
    int width, height;
    long double *rgb;    /* 3 per pixel, rows from the top */
    int long_double;     /* rendered with real = long double */
    long nonfinite;      /* the tracer's non-finite counter over the render */
} stab_image;

/* The name of this build's `real`: "double" or "long-double". */
const char *stability_real_name(void);

/*
 * Renders scene as render_image does (opts as there; NULL for the scene's
 * own settings) but keeps every pixel in this build's `real`, unrounded.
 * Returns STATUS_OK, STATUS_DATA when a ray tree passed the budget or
 * glass nested too deep, STATUS_CANCELLED (opts->cancel), or
 * STATUS_NO_MEMORY when out of memory (out is then empty).
 */
int stability_render(const scene_model *scene, const render_opts *opts, stab_image *out);
void stability_free(stab_image *img);

/* Writes img as a raw dump; returns 0, or -1 on a write error (errno). */
int stability_write_raw(FILE *f, const stab_image *img);

/* Reads a raw dump into out (allocated here).  Returns 0, or -1 with a
 * message in err (malformed, truncated, out of memory). */
int stability_read_raw(FILE *f, stab_image *out, char *err, size_t errlen);

/* Relative difference bands of the report: [0] identical, then below
 * 1e-15, 1e-15..1e-12, 1e-12..1e-9, 1e-9..1e-6, 1e-6 and more. */
enum { STAB_BANDS = 6 };

typedef struct stab_report {
    long pixels;
    long double max_abs, max_rel;   /* over channels and pixels */
    int abs_x, abs_y, rel_x, rel_y; /* where (-1 when the images are identical) */
    long beyond;                    /* pixels with a channel beyond the threshold */
    long band[STAB_BANDS];          /* pixels by their largest relative difference */
} stab_report;

/*
 * Compares a with the reference b (same size): per channel the absolute
 * difference and the relative one |a - b| / max(|a|, |b|) (0 when both are
 * 0).  When map is not NULL it is created (img_create) with, per pixel and
 * channel, the decade of the relative difference scaled to [0, 1]:
 * (17 + log10 rel) / 17 clamped, 0 where identical, so 1e-16 is 0.06,
 * 1e-9 is 0.47 and 1e-3 is 0.82.  Returns 0, -1 when the sizes differ or
 * the map cannot be allocated.
 */
int stability_compare(const stab_image *a, const stab_image *b, long double threshold, stab_report *r,
                      img_buf *map);

#endif
