/*
 * render.h - the image loop: every pixel's k x k camera rays, traced and
 * averaged with a box filter (slide 45's RayTrace()), over a whole image or
 * over one region of it at a time.
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
    int no_shortcuts;     /* 1: every shortcut off (tracer_no_shortcuts); same image, more work */
    /* 1: shadow rays of smooth triangles start on the facet, the seed's
     * way and POV-Ray's, not at Hanika's lifted point (spec/shading.md
     * [SHADE-TERMINATOR-1]); only to compare with such a renderer
     * (make difftest, spec/crosscheck.md [XCHK-MAP-MESH-3]). */
    int facet_shadows;
    /* Called after every row of a region (rows_total: the region's); a
     * non-zero return stops the render (SIGINT). */
    int (*progress)(void *ctx, int rows_done, int rows_total);
    void *progress_ctx;
    /* Asked every CANCEL_STEPS rays or light samples, and while the BVH is
     * built (base/cancel.h); non-zero stops the render within a fraction
     * of a second whatever a pixel costs ([REL-CANCEL-1]).  NULL: never. */
    int (*cancel)(void *ctx);
    void *cancel_ctx;
} render_opts;

typedef struct render_stats {
    trace_stats trace;
    int bvh_nodes, bvh_leaves, bvh_depth;
    long bvh_bytes;      /* the tree's nodes, part references and plane list */
    int shadows, specular, reflection, refraction; /* passes that ran (1) or were left out (0) */
    int no_shortcuts;     /* the render ran with every shortcut off */
    int width, height, samples, max_depth;
    int overflow_x, overflow_y;  /* the pixel whose ray tree passed the budget, or
                                    whose glass nested too deep (trace.medium_overflow) */
    double seconds;      /* wall time of the traversal and tracing */
    double build_seconds; /* of the acceleration structure */
} render_stats;

/* Where a region's pixels go: pixel (x, y) of the region [x0, x1) x
 * [y0, y1) of the image is written to the three elements at
 * (y - y0) * stride + 3 * (x - x0) of f32 (when not NULL) or of f64. */
typedef struct render_target {
    int x0, y0, x1, y1;
    float *f32;
    double *f64;
    size_t stride;       /* elements from one row to the next, >= 3 * (x1 - x0) */
} render_target;

/* A scene made ready to render: its tracer (BVH, light tables, from the
 * scene's allocator), the options, and the statistics summed over every
 * region rendered so far. */
typedef struct renderer {
    tracer tracer;
    render_opts opts;
    render_stats stats;
    cancel_poll cancel;     /* opts.cancel, counted; stats.trace.cancel points here */
    /* Camera-ray beams (bvh_beam.h): a tile's camera rays and its pruned
     * tree, allocated by renderer_init (NULL: out of memory, every ray
     * walks the whole tree). */
    ray *run_rays;
    bvh_node *beam_nodes;
    int beam_tried;         /* the allocation was tried */
} renderer;

/* Builds the tracer for scene with opts (NULL: the scene's settings) and
 * fixes the image size.  Returns STATUS_OK, STATUS_NO_MEMORY,
 * STATUS_CANCELLED, or STATUS_DATA when the size puts an orthographic
 * camera's view outside the scene's extent (scene_view_out; the load
 * checked the scene's own size) (then nothing is left to free).  r must not move
 * afterwards (its statistics point into it). */
int renderer_init(renderer *r, const scene_model *scene, const render_opts *opts);

/* Renders the region of target (inside r->stats.width x height, checked by
 * the caller) into it, adding to r->stats.  Returns STATUS_OK,
 * STATUS_CANCELLED when progress or cancel asked to stop, or STATUS_DATA
 * when a ray tree passed max_tree_rays or a ray was inside more nested
 * glass than the tracer follows (r->stats.overflow_x, _y say where;
 * r->stats.trace.medium_overflow > 0 tells the second); the region's
 * pixels are then partly written. */
int renderer_region(renderer *r, const render_target *target);

void renderer_free(renderer *r);

/*
 * A 64-bit fingerprint of what decides r's pixels: the text of every file
 * its scene's load read (in load order, without their names, so a scene
 * copied to another machine keeps it), the image size, the k x k grid,
 * max_depth, the light-sample override, and the width of `real`.  Two
 * renderers with equal fingerprints render the same pixels (FNV-1a,
 * base/hash.h: an accident, not an attack, is what it guards against).
 */
uint64_t renderer_fingerprint(const renderer *r);

/*
 * Renders scene into out (created here; free it with img_free).  Returns
 * STATUS_OK, STATUS_CANCELLED when progress asked to stop,
 * STATUS_DATA when a ray tree passed max_tree_rays (stats->trace
 * then says where), or STATUS_NO_MEMORY when out of memory; out is
 * freed on every failure.
 */
int render_image(const scene_model *scene, const render_opts *opts, img_buf *out, render_stats *stats);

/* The key of camera sample (a, b) of pixel (i, j) with a k x k grid in an
 * image `width` pixels wide: sampler_key(sampler_key(j * width + i,
 * RENDER_PIXEL_SALT), b * k + a), the root of that ray's light jitter. */
#define RENDER_PIXEL_SALT 0x5eedu
uint64_t render_sample_key(int width, int k, int i, int j, int a, int b);

/* The offset of camera sample a (or b) of a k x k grid from its pixel's
 * corner, in pixels: (a + 0.5) / k. */
double render_sample_offset(int k, int a);

/* The colour of one pixel (i, j) with a k x k grid: what render_image
 * stores, exposed for tests and for the oracle's comparisons. */
rgb render_pixel(const tracer *t, int width, int height, int k, int i, int j, trace_stats *st);

/* Seconds on a monotonic clock, for timings. */
double render_clock(void);

#endif
