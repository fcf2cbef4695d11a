/*
 * adjust.c - see adjust.h.
 */
#include <math.h>
#include "image/adjust.h"

int img_downsample(const rf_image *in, int k, rf_image *out)
{
    out->width = out->height = 0;
    out->rgb = NULL;
    if (k < 1 || in->width < k || in->height < k || in->width % k || in->height % k)
        return IMG_EUSAGE;
    int status = img_create(out, in->width / k, in->height / k);
    if (status != IMG_OK)
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
    return IMG_OK;
}

void img_scale(rf_image *img, double s)
{
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        img->rgb[i] *= s;
}

long img_count_nonfinite(const rf_image *img)
{
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    long count = 0;
    for (size_t i = 0; i < n; i++)
        count += !isfinite(img->rgb[i]);
    return count;
}
