/*
 * convert.c - the public API's types and the library's own (convert.h).
 */
#include <stddef.h>
#include <string.h>
#include "api/convert.h"

/* rf_status is the library's status family under public names. */
typedef char same_ok[(int)RF_OK == STATUS_OK ? 1 : -1];
typedef char same_usage[(int)RF_ERR_USAGE == STATUS_USAGE ? 1 : -1];
typedef char same_data[(int)RF_ERR_DATA == STATUS_DATA ? 1 : -1];
typedef char same_no_input[(int)RF_ERR_NO_INPUT == STATUS_NO_INPUT ? 1 : -1];
typedef char same_no_memory[(int)RF_ERR_NO_MEMORY == STATUS_NO_MEMORY ? 1 : -1];
typedef char same_io[(int)RF_ERR_IO == STATUS_IO ? 1 : -1];
typedef char same_cancelled[(int)RF_ERR_CANCELLED == STATUS_CANCELLED ? 1 : -1];
typedef char same_internal[(int)RF_ERR_INTERNAL == STATUS_INTERNAL ? 1 : -1];
typedef char same_check[(int)RF_ERR_CHECK == STATUS_FAIL ? 1 : -1];

mem api_mem(const rf_allocator *a)
{
    mem m;
    memset(&m, 0, sizeof m);
    if (a) {
        m.alloc = a->alloc;
        m.resize = a->resize;
        m.release = a->release;
        m.user = a->user;
    }
    return mem_pick(&m);
}

/* The limits, field by field: the public struct and the library's hold
 * the same longs under the same names. */
#define LIMIT(field) {offsetof(rf_limits, field), offsetof(scene_limits, field)}
static const struct {
    size_t pub, lib;
} limit_fields[] = {
    LIMIT(max_width), LIMIT(max_height), LIMIT(max_pixels), LIMIT(max_samples), LIMIT(max_light_samples),
    LIMIT(max_depth), LIMIT(max_loop_iterations), LIMIT(max_include_depth), LIMIT(max_file_bytes),
    LIMIT(max_mesh_triangles), LIMIT(max_primitives), LIMIT(max_errors), LIMIT(max_ray_tree),
    LIMIT(max_input_bytes), LIMIT(max_memory_mb),
};
typedef char all_limits[sizeof limit_fields / sizeof limit_fields[0] * sizeof(long) == sizeof(scene_limits) &&
                                sizeof(rf_limits) == sizeof(scene_limits) ? 1 : -1];

scene_limits api_limits_in(const rf_limits *l)
{
    scene_limits s;
    for (size_t i = 0; i < sizeof limit_fields / sizeof limit_fields[0]; i++)
        memcpy((char *)&s + limit_fields[i].lib, (const char *)l + limit_fields[i].pub, sizeof(long));
    return s;
}

rf_limits api_limits_out(const scene_limits *s)
{
    rf_limits l;
    for (size_t i = 0; i < sizeof limit_fields / sizeof limit_fields[0]; i++)
        memcpy((char *)&l + limit_fields[i].pub, (const char *)s + limit_fields[i].lib, sizeof(long));
    return l;
}

int api_render_opts(const rf_render_options *o, render_opts *out)
{
    memset(out, 0, sizeof *out);
    if (!o)
        return 1;
    if (o->width < 0 || o->height < 0 || o->samples < 0 || o->max_depth < 0 ||
        o->max_depth > SCENE_DEPTH_CEILING || o->light_samples < 0 || o->max_tree_rays < 0)
        return 0;
    out->width = o->width;
    out->height = o->height;
    out->samples = o->samples;
    out->max_depth = o->max_depth;
    out->light_samples = o->light_samples;
    out->max_tree_rays = o->max_tree_rays;
    out->no_shortcuts = o->no_shortcuts != 0;
    return 1;
}

void api_render_stats(const render_stats *s, rf_render_stats *out)
{
    const trace_stats *t = &s->trace;
    memset(out, 0, sizeof *out);
    out->width = s->width;
    out->height = s->height;
    out->samples = s->samples;
    out->max_depth = s->max_depth;
    out->camera_rays = t->camera_rays;
    out->shadow_rays = t->shadow_rays;
    out->reflection_rays = t->reflection_rays;
    out->refraction_rays = t->refraction_rays;
    out->total_internal_reflection_rays = t->tir_rays;
    out->light_samples = t->light_samples;
    out->light_samples_on_surface = t->lights_on_surface;
    out->nonfinite = t->nonfinite;
    out->medium_overflows = t->medium_overflow;
    out->node_visits = t->bvh.nodes_visited;
    out->primitive_tests = t->bvh.prims_tested;
    out->bvh_nodes = s->bvh_nodes;
    out->bvh_leaves = s->bvh_leaves;
    out->bvh_depth = s->bvh_depth;
    out->bvh_bytes = s->bvh_bytes;
    out->shadows = s->shadows;
    out->specular = s->specular;
    out->reflection = s->reflection;
    out->refraction = s->refraction;
    out->overflow_x = s->overflow_x;
    out->overflow_y = s->overflow_y;
    out->seconds = s->seconds;
    out->build_seconds = s->build_seconds;
}
