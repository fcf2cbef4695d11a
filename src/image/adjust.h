/*
 * adjust.h - bringing another renderer's picture to the exact image's
 * terms before they are compared: averaging k x k blocks (a renderer that
 * samples a pixel's k x k sub-pixel centres by rendering k times larger)
 * and multiplying by a constant (a renderer whose lights were scaled so
 * that a bright picture fits a 16-bit file).
 */
#ifndef REFRAY_ADJUST_H
#define REFRAY_ADJUST_H

#include "image/image.h"

/*
 * out = in with every k x k block averaged: out(x, y) is the mean of
 * in(k x + i, k y + j) for i, j in [0, k), channel by channel.  in must be
 * a whole number of blocks on both axes.  Returns STATUS_OK; STATUS_USAGE
 * for k < 1 or a size that is not a multiple of k (out is then empty);
 * STATUS_NO_MEMORY when out of memory.
 */
int img_downsample(const img_buf *in, int k, img_buf *out);

/* Every channel of every pixel of img multiplied by s. */
void img_scale(img_buf *img, double s);

/* The number of channel values of img that are NaN or infinite. */
long img_count_nonfinite(const img_buf *img);

#endif
