/*
 * convert.h - the public API's types and the library's own, one to the
 * other.  The public handles are the library's objects under an opaque
 * name: an rf_scene is a scene_model, an rf_image an api_image, an
 * rf_renderer an api_renderer.  rf_status and the internal status_code have
 * the same values (checked in convert.c).
 */
#ifndef REFRAY_CONVERT_H
#define REFRAY_CONVERT_H

#include "refray.h"
#include "image/image.h"
#include "render/render.h"
#include "scene/scene.h"

struct rf_image {
    img_buf buf;
};

struct rf_renderer {
    renderer r;
    rf_render_options options;   /* the caller's, for progress and cancel */
};

/* The allocator a (NULL: the C library) as the library's mem. */
mem api_mem(const rf_allocator *a);

static inline const scene_model *api_scene(const rf_scene *s)
{
    return (const scene_model *)(const void *)s;
}

static inline rf_status api_status(int status)
{
    return (rf_status)status;
}

scene_limits api_limits_in(const rf_limits *l);
rf_limits api_limits_out(const scene_limits *l);

/* The options o (NULL: the defaults) as the library's, 0 when they are
 * out of range. */
int api_render_opts(const rf_render_options *o, render_opts *out);
void api_render_stats(const render_stats *s, rf_render_stats *out);

/* The write options o (NULL: the defaults) as the library's, with stats
 * (may be NULL) to fill and o's cancel callback in *cancel, which must
 * live as long as the result. */
img_write_opts api_write_opts(const rf_write_options *o, img_write_stats *st, cancel_poll *cancel);

#endif
