/*
 * render.h - the image loop: every pixel's k x k camera rays, traced and
 * averaged with a box filter (slide 45's RayTrace()).
 */
#ifndef REFRAY_RENDER_H
#define REFRAY_RENDER_H

#include "image/image.h"
#include "scene/scene.h"
#include "render/trace.h"

typedef struct render_opts {
    int width, height;    /* 0: the scene's */
    int samples;          /* k of the k x k grid; 0: the scene's */
    int max_depth;        /* 0: the scene's */
    int light_samples;    /* > 0: samples of every distributed light; 0: each light's own */
    long max_tree_rays;   /* rays per camera ray before the render is refused; 0: no limit */
    /* Called after every row; a non-zero return stops the render (SIGINT). */
    int (*progress)(void *ctx, int rows_done, int rows_total);
    void *progress_ctx;
} render_opts;

typedef struct render_stats {
    trace_stats trace;
    int bvh_nodes, bvh_leaves, bvh_depth;
    long bvh_bytes;      /* the tree's nodes, part references and plane list */
    int shadows, specular, reflection, refraction; /* passes that ran (1) or were left out (0) */
    int width, height, samples, max_depth;
    int overflow_x, overflow_y;  /* the pixel whose ray tree passed the budget */
    double seconds;      /* wall time of the traversal and tracing */
    double build_seconds; /* of the acceleration structure */
} render_stats;

/*
 * Renders scene into out (created here; free it with img_free).  Returns
 * REFRAY_EXIT_OK, REFRAY_EXIT_INTERRUPTED when progress asked to stop,
 * REFRAY_EXIT_DATAERR when a ray tree passed max_tree_rays (stats->trace
 * then says where), or REFRAY_EXIT_SOFTWARE when out of memory; out is
 * freed on every failure.
 */
int render_image(const rf_scene *scene, const render_opts *opts, rf_image *out, render_stats *stats);

/* The colour of one pixel (i, j) with a k x k grid: what render_image
 * stores, exposed for tests and for the oracle's comparisons. */
rgb render_pixel(const tracer *t, int width, int height, int k, int i, int j, trace_stats *st);

/* Seconds on a monotonic clock, for timings. */
double render_clock(void);

#endif
