/*
 * scene.c - the scene model's defaults and its release.
 */
#include <stdlib.h>
#include "scene/scene.h"

rf_limits scene_default_limits(void)
{
    rf_limits l;
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

void scene_free(rf_scene *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->material_count; i++)
        free(s->materials[i].name);
    for (int i = 0; i < s->mesh_count; i++) {
        rf_mesh *m = &s->meshes[i];
        free(m->path);
        free(m->geom.positions);
        free(m->geom.normals);
        free(m->geom.tri);
        free(m->geom.tri_normal);
        free(m->geom.open);
    }
    free(s->materials);
    free(s->prims);
    free(s->meshes);
    free(s->lights);
    free(s->oracle);
    source_set_free(&s->sources);
    free(s);
}


long scene_mesh_bytes(const rf_scene *s, long *triangles)
{
    long bytes = 0;
    *triangles = 0;
    for (int i = 0; i < s->mesh_count; i++) {
        const rf_trimesh *g = &s->meshes[i].geom;
        long t = g->tri_count;
        *triangles += t;
        bytes += (long)(g->position_count * sizeof *g->positions + g->normal_count * sizeof *g->normals);
        bytes += t * (long)sizeof *g->tri + (g->tri_normal ? t * (long)sizeof *g->tri_normal : 0) + (g->open ? t : 0);
    }
    return bytes;
}
