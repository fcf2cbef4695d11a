/*
 * conform_kit.h - one scene of a conformance kit as the rule of
 * spec/conformance.md [KIT-RULE-1] reads it, and the rule itself.
 *
 * `refray conform` (verify/conform.h) and `refray compare --manifest`
 * judge a picture with these functions and no other, so the two cannot
 * disagree; tests/conform/kit_check.c is the same rule in one C99 file
 * without the library, and the conform suite checks that it counts the
 * same pixels.  Statuses are those of base/status.h.
 */
#ifndef REFRAY_CONFORM_KIT_H
#define REFRAY_CONFORM_KIT_H

#include <stddef.h>
#include "image/image.h"
#include "image/metrics.h"
#include "verify/manifest.h"

/* The end of the reason of a manifest its kit contradicts (STATUS_DATA:
 * refused as a malformed manifest is, spec/conformance.md [KIT-MASK-1]). */
#define CONFORM_KIT_DISAGREES "the manifest disagrees with its kit"

/*
 * [KIT-MASK-1] Reads the mask of scene s, for an image of width x height:
 * mask_pgm, else mask_png where only that is listed (NULL when neither
 * is), and checks that it marks the manifest's masked_pixels.  Returns
 * STATUS_OK; STATUS_DATA when it marks another count, or when the scene
 * names masked pixels and lists no mask (CONFORM_KIT_DISAGREES); else the
 * reader's status; the reason in why, *mask NULL on failure.
 */
int conform_kit_mask(const char *kit_dir, const manifest_scene *s, int width, int height, unsigned char **mask,
                     char *why, size_t why_size);

/* [VERIFY-UNBOUNDED-4] The largest absolute tolerance, as a fraction of
 * the peak: the kit's own, one 16-bit step at the scale that puts the
 * peak above 0.4, is at most 1 / (0.4 * 65535) = 2^-14.68 of it. */
#define CONFORM_ABSOLUTE_OF_PEAK 0x1p-14

/*
 * [VERIFY-UNBOUNDED-3] 1 when a verdict under |out - exact| <= relative
 * |exact| + absolute can tell an image whose largest value is peak from
 * itself scaled by any s with |1 - s| >= 1/2 (half its light, black, a
 * doubled one): at the peak such a picture errs by |1 - s| peak >= peak /
 * 2, so it fails there exactly when relative peak + absolute < peak / 2.
 * 0 for a black peak: nothing tells black from half of it.  And
 * [VERIFY-UNBOUNDED-4]: 0 when absolute exceeds CONFORM_ABSOLUTE_OF_PEAK
 * peak, which would pass black wherever the exact image is dimmer than
 * absolute (a bound checked at the peak alone does not see them).
 */
int conform_bound_decisive(double relative, double absolute, double peak);

/* The reason of a tolerance conform_bound_decisive refuses, into why. */
void conform_bound_reason(double relative, double absolute, double peak, char *why, size_t why_size);

/* Checks conform_bound_decisive for s's tolerance (the larger absolute,
 * absolute_png) at the largest |value|
 * of exact over the pixels mask leaves (NULL: all).  STATUS_OK, or
 * STATUS_DATA with the reason in why. */
int conform_kit_decisive(const manifest_scene *s, const img_buf *exact, const unsigned char *mask, char *why,
                         size_t why_size);

/*
 * Reads the exact image of scene s of the kit in kit_dir (EXR where the
 * manifest lists one and this build reads it, else PFM) and its mask
 * (conform_kit_mask at the manifest's size), and checks that the
 * tolerance can carry a verdict there (conform_kit_decisive).  Returns
 * STATUS_OK; otherwise the status with the reason in why, and nothing to
 * free.
 */
int conform_kit_read(const char *kit_dir, const manifest_scene *s, img_buf *exact, unsigned char **mask, char *why,
                     size_t why_size);

/* [KIT-TOL-1] 1 when the picture at path is read from integers (PNG,
 * PPM, by its extension as img_read reads it): judged with absolute_png,
 * the 16-bit step; a float picture (PFM, EXR) with absolute. */
int conform_picture_quantized(const char *path);

/* The absolute tolerance of s for a picture quantized or not. */
double conform_absolute(const manifest_scene *s, int quantized);

/*
 * [KIT-RULE-1] Judges out against exact (the same size) over the pixels
 * mask does not mark (mask NULL: every pixel), with s's tolerance for a
 * picture quantized or not (conform_absolute): fills m
 * (metrics_compare_abs) and returns 1 when out passes (no compared pixel
 * over, a NaN or an infinity over, and at least one pixel compared), else
 * 0.  A pixel the mask marks is not judged, whatever it holds.
 */
int conform_rule(const img_buf *out, const img_buf *exact, const unsigned char *mask, const manifest_scene *s,
                 int quantized, image_metrics *m);

/* The channel values of img that are NaN or infinite: in the pixels the
 * rule judges (*judged) and in those mask marks (*masked). */
void conform_count_nonfinite(const img_buf *img, const unsigned char *mask, long *judged, long *masked);

#endif
