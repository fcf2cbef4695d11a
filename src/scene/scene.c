/*
 * scene.c - the scene model's defaults and its release.
 */
#include <string.h>
#include "scene/scene.h"

scene_limits scene_default_limits(void)
{
    scene_limits l;
    l.max_width = 16384;
    l.max_height = 16384;
    l.max_pixels = 64L * 1024 * 1024;
    l.max_samples = 64;
    l.max_light_samples = 4096;
    l.max_depth = 1000;
    l.max_loop_iterations = 1000000;
    l.max_include_depth = 32;
    l.max_file_bytes = 64L * 1024 * 1024;
    l.max_mesh_triangles = 10L * 1000 * 1000;
    l.max_primitives = 20L * 1000 * 1000;
    l.max_errors = 20;
    l.max_ray_tree = 1000000;
    return l;
}

void scene_free(scene_model *s)
{
    if (!s)
        return;
    mem m = s->mem;
    for (int i = 0; i < s->material_count; i++)
        mem_free_string(&m, s->materials[i].name);
    for (int i = 0; i < s->mesh_count; i++)
        mem_free_string(&m, s->meshes[i].path);
    mem_free(&m, s->materials, (size_t)s->material_cap * sizeof *s->materials);
    mem_free(&m, s->prims, (size_t)s->prim_cap * sizeof *s->prims);
    mem_free(&m, s->meshes, (size_t)s->mesh_cap * sizeof *s->meshes);
    mem_free(&m, s->lights, (size_t)s->light_cap * sizeof *s->lights);
    mem_free_string(&m, s->oracle);
    source_set_free(&s->sources);
    mem_free(&m, s, sizeof *s);
}


void scene_load_opts_init(scene_load_opts *o)
{
    memset(o, 0, sizeof *o);
    o->limits = scene_default_limits();
    o->warnings = 1;
}
