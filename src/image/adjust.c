/*
 * adjust.c - see adjust.h.
 */
#include <math.h>
#include <string.h>
#include "image/adjust.h"

int img_downsample(const img_buf *in, int k, img_buf *out)
{
    memset(out, 0, sizeof *out);
    if (k < 1 || in->width < k || in->height < k || in->width % k || in->height % k)
        return STATUS_USAGE;
    int status = img_create(out, in->width / k, in->height / k);
    if (status != STATUS_OK)
        return status;
    double n = (double)k * (double)k;
    for (int y = 0; y < out->height; y++)
        for (int x = 0; x < out->width; x++) {
            double *px = img_pixel(out, x, y);
            for (int j = 0; j < k; j++)
                for (int i = 0; i < k; i++)
                    for (int c = 0; c < 3; c++)
                        px[c] += img_pixel(in, k * x + i, k * y + j)[c];
            for (int c = 0; c < 3; c++)
                px[c] /= n;
        }
    return STATUS_OK;
}

void img_scale(img_buf *img, double s)
{
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        img->rgb[i] *= s;
}

long img_count_nonfinite(const img_buf *img)
{
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    long count = 0;
    for (size_t i = 0; i < n; i++)
        count += !isfinite(img->rgb[i]);
    return count;
}
