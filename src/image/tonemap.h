/*
 * tonemap.h - the pure scalar functions that turn a linear radiance value
 * into a display code: exposure, tone curve, sRGB transfer, quantisation.
 *
 * The display mapping of refray (spec: model decisions, "Output") is, per
 * channel:  v -> exposure(v, stops) -> clamp or Reinhard -> sRGB encoding
 * (unless linear output was asked for) -> quantize to 8 or 16 bits.
 * Everything here is double in, double (or a code) out, with no state.
 */
#ifndef REFRAY_TONEMAP_H
#define REFRAY_TONEMAP_H

/* v * 2^stops.  stops = +1 doubles the value, -1 halves it. */
double tonemap_exposure(double v, double stops);

/* v limited to [0, 1]; NaN gives 0 so a bad value can never reach a code. */
double tonemap_clamp(double v);

/* Reinhard's global curve v / (1 + v): 0 at 0, 1/2 at 1, tends to 1 as
 * v -> inf and never reaches it for finite v.  Negative (and NaN) v give 0;
 * +inf gives 1. */
double tonemap_reinhard(double v);

/* IEC 61966-2-1 (sRGB) transfer function, linear -> encoded:
 *   12.92 v                    for v < 0.0031308
 *   1.055 v^(1/2.4) - 0.055    otherwise.
 * Defined for every real v (the linear branch passes negatives through);
 * callers clamp to [0, 1] first when they want a display value.  The two
 * branches of the standard differ by 2.9e-8 at the threshold. */
double tonemap_srgb_encode(double v);

/* The inverse, encoded -> linear:
 *   v / 12.92                  for v < 0.04045
 *   ((v + 0.055) / 1.055)^2.4  otherwise. */
double tonemap_srgb_decode(double v);

/* The integer code nearest to v * maxcode, halves rounded up, limited to
 * [0, maxcode]: floor(v * maxcode + 0.5).  NaN gives 0. */
unsigned tonemap_quantize(double v, unsigned maxcode);

#endif
