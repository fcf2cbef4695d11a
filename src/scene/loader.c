/*
 * loader.c - the state of one load: the scene being built, its growable
 * arrays, and the out-of-memory flag every pass checks.
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "scene/loader.h"

void loader_oom(loader *L)
{
    if (!L->out_of_memory)
        diag_report(&L->diag, DIAG_ERROR, src_span_none(), "out of memory");
    L->out_of_memory = 1;
}

/* The defaults of spec/language.md for what a scene does not say. */
void loader_scene_defaults(rf_scene *s)
{
    s->image.width = 640;
    s->image.height = 480;
    s->image.samples = 1;
    s->image.max_depth = 5;
    s->image.background = vec_splat(0);
    s->camera.kind = CAMERA_PERSPECTIVE;
    s->camera.eye = vec_make(0, 0, 5);
    s->camera.look_at = vec_make(0, 0, 0);
    s->camera.up = vec_make(0, 1, 0);
    s->camera.fov = 60;
    s->camera.width = 2;
    s->camera.forward = vec_make(0, 0, -1);
    s->camera.right = vec_make(1, 0, 0);
    s->camera.true_up = vec_make(0, 1, 0);
    s->camera.where = src_span_none();
    s->oracle_where = src_span_none();
    source_set_init(&s->sources);
}

/* Doubles *cap until count + 1 fits; refuses past limit.  0 on failure. */
static int grow(void **items, int *cap, int count, size_t size, long limit)
{
    if (count < *cap)
        return 1;
    if (count >= limit || count >= INT_MAX / 2)
        return 0;
    int next = *cap ? 2 * *cap : 16;
    void *grown = realloc(*items, (size_t)next * size);
    if (!grown)
        return 0;
    *items = grown;
    *cap = next;
    return 1;
}

rf_prim *loader_add_prim(loader *L, src_span where)
{
    rf_scene *s = L->scene;
    long used = s->prim_count + L->mesh_triangles;
    if (used >= L->limits->max_primitives) {
        if (used == L->limits->max_primitives)
            diag_report(&L->diag, DIAG_ERROR, where, "more than %ld primitives (--max-primitives)",
                        L->limits->max_primitives);
        s->prim_count++;
        return NULL;
    }
    void *items = s->prims;
    if (!grow(&items, &L->prim_cap, s->prim_count, sizeof *s->prims, L->limits->max_primitives)) {
        loader_oom(L);
        return NULL;
    }
    s->prims = items;
    return &s->prims[s->prim_count++];
}

rf_light *loader_add_light(loader *L)
{
    rf_scene *s = L->scene;
    void *items = s->lights;
    if (!grow(&items, &L->light_cap, s->light_count, sizeof *s->lights, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    s->lights = items;
    return &s->lights[s->light_count++];
}

rf_material *loader_add_material(loader *L)
{
    rf_scene *s = L->scene;
    void *items = s->materials;
    int cap = L->material_cap;
    if (!grow(&items, &cap, s->material_count, sizeof *s->materials, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    s->materials = items;
    if (cap != L->material_cap) {
        int *uses = realloc(L->material_uses, (size_t)cap * sizeof *uses);
        if (!uses) {
            L->material_cap = cap;
            loader_oom(L);
            return NULL;
        }
        L->material_uses = uses;
        L->material_cap = cap;
    }
    L->material_uses[s->material_count] = 0;
    rf_material *m = &s->materials[s->material_count++];
    memset(m, 0, sizeof *m);
    return m;
}

rf_mesh *loader_add_mesh(loader *L)
{
    rf_scene *s = L->scene;
    void *items = s->meshes;
    if (!grow(&items, &L->mesh_cap, s->mesh_count, sizeof *s->meshes, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    s->meshes = items;
    rf_mesh *m = &s->meshes[s->mesh_count++];
    memset(m, 0, sizeof *m);
    return m;
}

void loader_init(loader *L, rf_scene *s, const rf_limits *limits, FILE *diag_out, int warnings)
{
    memset(L, 0, sizeof *L);
    L->scene = s;
    L->limits = limits;
    diag_init(&L->diag, &s->sources, diag_out);
    L->diag.max_errors = (int)limits->max_errors;
    L->diag.warnings_enabled = warnings;
    arena_init(&L->arena);
    env_init(&L->env);
    L->image_where = src_span_none();
    L->camera_where = src_span_none();
    L->default_material = -1;
}

void loader_free(loader *L)
{
    arena_free(&L->arena);
    env_free(&L->env);
    free(L->include_stack);
    free(L->material_uses);
}

