/*
 * oracle.h - exact images of analytic scenes (spec/analytic.md).
 *
 * A family of analytic scenes (`oracle NAME` in the scene) knows the closed
 * form of the image for every scene that fits its assumptions, read from the
 * scene's own parameters.  The closed form takes a different route from the
 * tracer (the pixel's geometry solved directly, a series summed in closed
 * form, an area light integrated exactly), so a bug the two shared could not
 * hide.  The oracle is evaluated at the very points the tracer samples: the
 * centres of the k x k cells of each pixel (render.c), averaged.
 */
#ifndef REFRAY_ORACLE_H
#define REFRAY_ORACLE_H

#include <stddef.h>
#include "image/image.h"
#include "scene/scene.h"

/* What a family says of one image point. */
typedef enum oracle_status {
    ORACLE_EXACT,       /* *out holds the exact radiance */
    ORACLE_AMBIGUOUS    /* the point lies within the family's margin of a
                           discontinuity (an edge, a shadow boundary, the
                           critical angle): the pixel is excluded and counted */
} oracle_status;

/* The render the exact image is for. */
typedef struct oracle_view {
    const scene_model *scene;
    int width, height;  /* pixels */
    int samples;        /* k: k x k camera rays per pixel */
    int max_depth;      /* the depth the tracer stops at */
} oracle_view;

typedef struct oracle_family {
    const char *name;       /* as written after `oracle` */
    const char *isolates;   /* one line: the feature the family checks */
    int sampled;            /* 1: distributed lights; the tracer converges to
                               the exact image as light samples grow */
    /* 1 when the scene (with max_depth of the view) fits the family's
     * assumptions; else 0 and the reason in why. */
    int (*accepts)(const oracle_view *v, char *why, size_t why_size);
    /* The exact radiance at image point (x, y), continuous image coordinates
     * as camera_ray takes them. */
    oracle_status (*radiance)(const oracle_view *v, double x, double y, rgb *out);
    /* The relative tolerance a render with light_samples per distributed
     * light must meet (1e-9 for deterministic families); 0 for light_samples
     * means the scene's own. */
    double (*tolerance)(const oracle_view *v, int light_samples);
} oracle_family;

/* Every family, in a fixed order. */
const oracle_family *const *oracle_families(int *count);

/* The family called name, or NULL. */
const oracle_family *oracle_find(const char *name);

/*
 * The exact image of view v: each pixel the mean of the k x k sample
 * points.  excluded (width*height bytes, may be NULL) marks pixels with an
 * ambiguous sample point; *excluded_count counts them (their value in out
 * is 0).  Returns 0, STATUS_NO_MEMORY when out of memory, or STATUS_FAIL
 * when the family gave a point a non-finite or negative radiance (it cannot
 * give this image; out is then empty).
 */
int oracle_image(const oracle_family *f, const oracle_view *v, img_buf *out, unsigned char *excluded,
                 long *excluded_count);

/* Writes the reason a scene is refused into why; returns 0 (for accepts). */
int oracle_refuse(char *why, size_t why_size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
