/*
 * tonemap.c - scalar display mapping (see tonemap.h for the contracts).
 */
#include <math.h>
#include "image/tonemap.h"

/* sRGB breakpoints (IEC 61966-2-1).  SRGB_DECODE_KNEE is the standard's
 * rounded 12.92 * SRGB_ENCODE_KNEE, which is why the branches do not meet
 * exactly. */
#define SRGB_ENCODE_KNEE 0.0031308
#define SRGB_DECODE_KNEE 0.04045

double tonemap_exposure(double v, double stops)
{
    return v * exp2(stops);
}

double tonemap_clamp(double v)
{
    /* Written so that NaN fails both comparisons and falls to 0. */
    if (v >= 1.0)
        return 1.0;
    if (v > 0.0)
        return v;
    return 0.0;
}

double tonemap_reinhard(double v)
{
    if (!(v > 0.0))
        return 0.0;
    if (isinf(v))
        return 1.0;
    return v / (1.0 + v);
}

double tonemap_srgb_encode(double v)
{
    if (v < SRGB_ENCODE_KNEE)
        return 12.92 * v;
    return 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

double tonemap_srgb_decode(double v)
{
    if (v < SRGB_DECODE_KNEE)
        return v / 12.92;
    return pow((v + 0.055) / 1.055, 2.4);
}

unsigned tonemap_quantize(double v, unsigned maxcode)
{
    /* Range checks first: v * maxcode could be huge or NaN. */
    if (!(v > 0.0))
        return 0;
    if (v >= 1.0)
        return maxcode;
    double code = floor(v * (double)maxcode + 0.5);
    return code >= (double)maxcode ? maxcode : (unsigned)code;
}
