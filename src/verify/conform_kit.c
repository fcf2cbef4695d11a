/*
 * conform_kit.c - see conform_kit.h.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "base/status.h"
#include "io/fileio.h"
#include "io/image_io.h"
#include "verify/conform_kit.h"
#include "verify/verify.h"

/* The exact image: the EXR where listed and readable here, else the PFM. */
static int read_exact(const char *kit_dir, const manifest_scene *s, img_buf *exact, char *why, size_t why_size)
{
    int exr = s->files[MANIFEST_FILE_EXACT_EXR][0] && img_format_available(IMG_FORMAT_EXR);
    char *path = file_join(NULL, kit_dir, s->files[exr ? MANIFEST_FILE_EXACT_EXR : MANIFEST_FILE_EXACT_PFM]);
    img_read_opts o = img_read_opts_default();
    o.width = s->width; /* the manifest's size, checked on the header */
    o.height = s->height;
    int status = path ? img_read(path, &o, exact, why, why_size) : STATUS_NO_MEMORY;
    if (!path)
        snprintf(why, why_size, "out of memory");
    free(path);
    return status;
}

/* The masked_pixels of the manifest against the marks of the mask read
 * (rel; NULL for none): STATUS_OK or STATUS_DATA. */
static int check_masked(const manifest_scene *s, const char *rel, const unsigned char *mask, int width, int height,
                        char *why, size_t why_size)
{
    long marked = 0;
    for (size_t p = 0; mask && p < (size_t)width * (size_t)height; p++)
        marked += mask[p] != 0;
    if (marked == s->masked)
        return STATUS_OK;
    if (rel)
        snprintf(why, why_size, "'masked_pixels' is %ld, but its mask '%s' marks %ld: %s", s->masked, rel, marked,
                 CONFORM_KIT_DISAGREES);
    else
        snprintf(why, why_size, "'masked_pixels' is %ld, but it lists no mask (mask_pgm and mask_png are null): %s",
                 s->masked, CONFORM_KIT_DISAGREES);
    return STATUS_DATA;
}

int conform_kit_mask(const char *kit_dir, const manifest_scene *s, int width, int height, unsigned char **mask,
                     char *why, size_t why_size)
{
    /* The PNG where the PGM is not listed, as the PFM where the EXR is not. */
    const char *rel = s->files[MANIFEST_FILE_MASK_PGM][0] ? s->files[MANIFEST_FILE_MASK_PGM]
                                                          : s->files[MANIFEST_FILE_MASK_PNG];
    *mask = NULL;
    int status = STATUS_OK;
    if (rel[0]) {
        char *path = file_join(NULL, kit_dir, rel);
        status = path ? verify_mask_read(path, width, height, mask, why, why_size) : STATUS_NO_MEMORY;
        if (!path)
            snprintf(why, why_size, "out of memory");
        free(path);
    }
    if (status == STATUS_OK)
        status = check_masked(s, rel[0] ? rel : NULL, *mask, width, height, why, why_size);
    if (status != STATUS_OK) {
        free(*mask);
        *mask = NULL;
    }
    return status;
}

int conform_kit_read(const char *kit_dir, const manifest_scene *s, img_buf *exact, unsigned char **mask, char *why,
                     size_t why_size)
{
    *mask = NULL;
    int status = read_exact(kit_dir, s, exact, why, why_size);
    if (status != STATUS_OK)
        return status;
    status = conform_kit_mask(kit_dir, s, s->width, s->height, mask, why, why_size);
    if (status == STATUS_OK)
        status = conform_kit_decisive(s, exact, *mask, why, why_size);
    if (status != STATUS_OK) {
        img_free(exact);
        free(*mask);
        *mask = NULL;
    }
    return status;
}

int conform_bound_decisive(double relative, double absolute, double peak)
{
    return relative * peak + absolute < peak / 2 && absolute <= CONFORM_ABSOLUTE_OF_PEAK * peak;
}

void conform_bound_reason(double relative, double absolute, double peak, char *why, size_t why_size)
{
    if (!(relative * peak + absolute < peak / 2))
        snprintf(why, why_size, "its tolerance, relative %.3g and absolute %.3g, passes a picture of half the light "
                 "of the exact image, whose largest value is %.3g: relative * peak + absolute must be below peak / 2 "
                 "(no verdict, spec/verify.md [VERIFY-UNBOUNDED-3])", relative, absolute, peak);
    else
        snprintf(why, why_size, "its absolute tolerance %.3g passes black wherever the exact image is dimmer than "
                 "that, and its largest value is %.3g: absolute must be at most 2^-14 of it, %.3g (spec/verify.md "
                 "[VERIFY-UNBOUNDED-4])", absolute, peak, CONFORM_ABSOLUTE_OF_PEAK * peak);
}

int conform_kit_decisive(const manifest_scene *s, const img_buf *exact, const unsigned char *mask, char *why,
                         size_t why_size)
{
    double peak = 0;
    size_t n = (size_t)exact->width * (size_t)exact->height;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3 && !(mask && mask[p]); c++)
            peak = fmax(peak, fabs(exact->rgb[3 * p + c]));
    double absolute = fmax(s->absolute, s->absolute_png);
    if (conform_bound_decisive(s->relative, absolute, peak))
        return STATUS_OK;
    conform_bound_reason(s->relative, absolute, peak, why, why_size);
    return STATUS_DATA;
}

int conform_picture_quantized(const char *path)
{
    img_format f = img_format_from_path(path);
    return f == IMG_FORMAT_PNG || f == IMG_FORMAT_PPM;
}

double conform_absolute(const manifest_scene *s, int quantized)
{
    return quantized ? s->absolute_png : s->absolute;
}

int conform_rule(const img_buf *out, const img_buf *exact, const unsigned char *mask, const manifest_scene *s,
                 int quantized, image_metrics *m)
{
    metrics_compare_abs(out, exact, mask, s->relative, conform_absolute(s, quantized), m);
    return m->over == 0 && m->compared > 0;
}

void conform_count_nonfinite(const img_buf *img, const unsigned char *mask, long *judged, long *masked)
{
    size_t n = (size_t)img->width * (size_t)img->height;
    *judged = *masked = 0;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3; c++)
            if (!isfinite(img->rgb[3 * p + c]))
                ++*(mask && mask[p] ? masked : judged);
}
