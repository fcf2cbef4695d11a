/*
 * render.c - see render.h.  Pixel (i, j) is sampled at the centres of a
 * k x k grid of equal cells, (i + (a + 0.5)/k, j + (b + 0.5)/k): with k = 1,
 * the pixel centre.  The sub-samples are not jittered, so a render is a
 * deterministic function of the scene (the light samples are jittered by a
 * counter-based hash of the pixel and sub-sample, which is deterministic
 * too).
 */
#include <string.h>
#include <time.h>
#include "render/camera.h"
#include "render/render.h"
#include "base/sampler.h"
#include "render/shade.h"

double render_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

rgb render_pixel(const tracer *t, int width, int height, int k, int i, int j, trace_stats *st)
{
    uint64_t pixel_key = sampler_key((uint64_t)j * (uint64_t)width + (uint64_t)i, 0x5eed);
    rgb sum = vec_splat(0);
    for (int b = 0; b < k; b++) {
        for (int a = 0; a < k; a++) {
            real x = i + (a + 0.5) / k, y = j + (b + 0.5) / k;
            ray r = camera_ray(&t->scene->camera, width, height, x, y);
            medium_stack media = t->eye_media;
            if (t->scene->camera.kind == CAMERA_ORTHOGRAPHIC)
                trace_media_at(t, r.origin, &media, st);
            st->camera_rays++;
            st->tree_rays = 0;
            rgb c = trace_ray(t, &r, 1, &media, sampler_key(pixel_key, (uint64_t)(b * k + a)), st);
            sum = shade_saturate(vec_add(sum, c));
        }
    }
    return vec_scale(sum, 1.0 / ((real)k * k));
}

static void record_setup(const tracer *t, render_stats *stats)
{
    stats->bvh_nodes = t->accel.node_count;
    stats->bvh_leaves = t->accel.leaf_count;
    stats->bvh_depth = t->accel.depth;
    stats->bvh_bytes = (long)(t->accel.node_count * sizeof(bvh_node) + t->accel.item_count * sizeof(bvh_ref) +
                              t->accel.unbounded_count * sizeof(bvh_ref));
    stats->shadows = t->shadows;
    stats->specular = t->specular;
    stats->reflection = t->reflection;
    stats->refraction = t->refraction;
}

static int trace_rows(const tracer *t, const render_opts *opts, rf_image *out, render_stats *stats)
{
    for (int j = 0; j < out->height; j++) {
        for (int i = 0; i < out->width; i++) {
            rgb c = render_pixel(t, out->width, out->height, stats->samples, i, j, &stats->trace);
            double *px = img_pixel(out, i, j);
            px[0] = c.x;
            px[1] = c.y;
            px[2] = c.z;
            if (stats->trace.tree_overflow) {
                stats->overflow_x = i;
                stats->overflow_y = j;
                return REFRAY_EXIT_DATAERR;
            }
        }
        if (opts && opts->progress && opts->progress(opts->progress_ctx, j + 1, out->height))
            return REFRAY_EXIT_INTERRUPTED;
    }
    return REFRAY_EXIT_OK;
}

int render_image(const rf_scene *scene, const render_opts *opts, rf_image *out, render_stats *stats)
{
    render_stats local;
    tracer t;
    if (!stats)
        stats = &local;
    memset(stats, 0, sizeof *stats);
    stats->width = opts && opts->width > 0 ? opts->width : scene->image.width;
    stats->height = opts && opts->height > 0 ? opts->height : scene->image.height;
    stats->samples = opts && opts->samples > 0 ? opts->samples : scene->image.samples;
    double start = render_clock();
    if (!tracer_init(&t, scene, opts ? opts->max_depth : 0, opts ? opts->light_samples : 0))
        return REFRAY_EXIT_SOFTWARE;
    t.max_tree_rays = opts ? opts->max_tree_rays : 0;
    stats->max_depth = t.max_depth;
    stats->build_seconds = render_clock() - start;
    record_setup(&t, stats);
    if (img_create(out, stats->width, stats->height) != 0) {
        tracer_free(&t);
        return REFRAY_EXIT_SOFTWARE;
    }
    start = render_clock();
    int status = trace_rows(&t, opts, out, stats);
    stats->seconds = render_clock() - start;
    tracer_free(&t);
    if (status != REFRAY_EXIT_OK)
        img_free(out);
    return status;
}
