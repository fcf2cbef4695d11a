/*
 * metrics.h - how far one image is from another (verify, compare).
 *
 * For a test image A against a reference B, over the pixels not excluded:
 *   max abs   max over channels |A - B|
 *   rms       sqrt(mean over channels (A - B)^2)
 *   max rel   max over channels |A - B| / |B|, over channels with |B| > floor
 *   psnr      20 log10(peak / rms), peak = the largest value of B (1 if B <= 1
 *             everywhere is not assumed: HDR references have peaks above 1)
 *   over      pixels where some channel has |A - B| > tol * max(|B|, floor)
 * floor = 1e-12 * peak keeps near-black channels from dividing by zero.
 * metrics_compare_abs counts `over` by the conformance kit's rule instead
 * (spec/conformance.md): |A - B| > rel * |B| + abs_tol.
 *
 * A pixel where either image holds a NaN or an infinity in some channel
 * is counted in `nonfinite` (and in `over`, whatever the tolerance), its
 * first position kept; it takes no part in max abs, RMS, max rel, PSNR and
 * peak, which describe the finite pixels ([REL-NONFINITE-1]): an error
 * that cannot be measured is never reported as no error.
 */
#ifndef REFRAY_METRICS_H
#define REFRAY_METRICS_H

#include "image/image.h"

typedef struct image_metrics {
    double max_abs;
    double rms;
    double max_rel;
    double psnr;           /* +inf when the images are equal */
    double peak;           /* largest reference value */
    long over;             /* pixels over the tolerance */
    long compared;         /* pixels compared */
    long excluded;         /* pixels skipped by the mask */
    int worst_x, worst_y;  /* pixel of max_abs */
    long nonfinite;        /* pixels with a NaN or infinity in A or B (also in over) */
    int nonfinite_x, nonfinite_y; /* the first of them, row by row; -1 when none */
} image_metrics;

/* 1 when every channel of pixel p of a and of b is finite. */
int metrics_pixel_finite(const img_buf *a, const img_buf *b, size_t p);

/* a and b must have the same size.  excluded: width*height bytes, non-zero
 * to skip a pixel, or NULL.  tol: the relative tolerance for `over`. */
void metrics_compare(const img_buf *a, const img_buf *b, const unsigned char *excluded, double tol,
                     image_metrics *m);

/* The same metrics, with `over` the pixels where some channel has
 * |A - B| > rel * |B| + abs_tol (a NaN counts as over). */
void metrics_compare_abs(const img_buf *a, const img_buf *b, const unsigned char *excluded, double rel,
                         double abs_tol, image_metrics *m);

#endif
