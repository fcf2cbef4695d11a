/*
 * loader.c - the state of one load: the scene being built, its growable
 * arrays, the files the resolver gives it, and the out-of-memory flag
 * every pass checks.
 */
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include "scene/loader.h"

void loader_oom(loader *L)
{
    if (!L->out_of_memory)
        diag_report(&L->diag, DIAG_ERROR, src_span_none(), "out of memory");
    L->out_of_memory = 1;
}

/* The defaults of spec/language.md for what a scene does not say. */
void loader_scene_defaults(scene_model *s)
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
    source_set_init(&s->sources, &s->mem);
}

/* Doubles *cap until count + 1 fits; refuses past limit.  0 on failure. */
static int grow(const mem *m, void **items, int *cap, int count, size_t size, long limit)
{
    if (count < *cap)
        return 1;
    if (count >= limit || count >= INT_MAX / 2)
        return 0;
    int next = *cap ? 2 * *cap : 16;
    void *grown = mem_resize_array(m, *items, (size_t)*cap, (size_t)next, size);
    if (!grown)
        return 0;
    *items = grown;
    *cap = next;
    return 1;
}

scene_prim *loader_add_prim(loader *L, src_span where)
{
    scene_model *s = L->scene;
    long used = s->prim_count + L->mesh_triangles;
    if (used >= L->limits->max_primitives) {
        if (used == L->limits->max_primitives)
            diag_report(&L->diag, DIAG_ERROR, where, "more than %ld primitives (--max-primitives)",
                        L->limits->max_primitives);
        s->prim_count++;
        return NULL;
    }
    void *items = s->prims;
    if (!grow(L->mem, &items, &s->prim_cap, s->prim_count, sizeof *s->prims, L->limits->max_primitives)) {
        loader_oom(L);
        return NULL;
    }
    s->prims = items;
    return &s->prims[s->prim_count++];
}

scene_light *loader_add_light(loader *L)
{
    scene_model *s = L->scene;
    void *items = s->lights;
    if (!grow(L->mem, &items, &s->light_cap, s->light_count, sizeof *s->lights, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    s->lights = items;
    return &s->lights[s->light_count++];
}

scene_material *loader_add_material(loader *L)
{
    scene_model *s = L->scene;
    void *items = s->materials;
    if (!grow(L->mem, &items, &s->material_cap, s->material_count, sizeof *s->materials, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    s->materials = items;
    items = L->material_uses;
    if (!grow(L->mem, &items, &L->uses_cap, s->material_count, sizeof *L->material_uses, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    L->material_uses = items;
    L->material_uses[s->material_count] = 0;
    scene_material *m = &s->materials[s->material_count++];
    memset(m, 0, sizeof *m);
    return m;
}

scene_mesh *loader_add_mesh(loader *L)
{
    scene_model *s = L->scene;
    void *items = s->meshes;
    if (!grow(L->mem, &items, &s->mesh_cap, s->mesh_count, sizeof *s->meshes, INT_MAX)) {
        loader_oom(L);
        return NULL;
    }
    s->meshes = items;
    scene_mesh *m = &s->meshes[s->mesh_count++];
    memset(m, 0, sizeof *m);
    return m;
}

/* Shrinks one array to count entries; keeps it as it is when that fails. */
static void trim(const mem *m, void **items, int *cap, int count, size_t size)
{
    if (count >= *cap)
        return;
    if (count == 0) {
        mem_free(m, *items, (size_t)*cap * size);
        *items = NULL;
        *cap = 0;
        return;
    }
    void *fit = mem_resize_array(m, *items, (size_t)*cap, (size_t)count, size);
    if (fit) {
        *items = fit;
        *cap = count;
    }
}

void loader_trim(loader *L)
{
    scene_model *s = L->scene;
    void *p = s->prims;
    trim(L->mem, &p, &s->prim_cap, s->prim_count, sizeof *s->prims);
    s->prims = p;
    p = s->lights;
    trim(L->mem, &p, &s->light_cap, s->light_count, sizeof *s->lights);
    s->lights = p;
    p = s->materials;
    trim(L->mem, &p, &s->material_cap, s->material_count, sizeof *s->materials);
    s->materials = p;
    p = s->meshes;
    trim(L->mem, &p, &s->mesh_cap, s->mesh_count, sizeof *s->meshes);
    s->meshes = p;
}

/* Asks the resolver for name into *src; STATUS_OK, or another status with
 * the reason in why (out of memory reported). */
static int ask(loader *L, const char *name, src_span at, scene_source *src, char *why, size_t why_size)
{
    const scene_resolver *r = L->resolver;
    const char *from = L->scene->sources.files[at.file]->path;
    memset(src, 0, sizeof *src);
    why[0] = '\0';
    int status = STATUS_NO_INPUT;
    if (r->fetch)
        status = r->fetch(r->user, from, name, src, why, why_size);
    else
        snprintf(why, why_size, "cannot read '%s': this load reads no files", name);
    if (status == STATUS_NO_MEMORY)
        loader_oom(L);
    return status;
}

static void give_back(loader *L, scene_source *src)
{
    if (L->resolver->release)
        L->resolver->release(L->resolver->user, src);
    memset(src, 0, sizeof *src);
}

int loader_fetch(loader *L, const char *name, src_span at, char **identity, char *why, size_t why_size)
{
    scene_source src;
    if (ask(L, name, at, &src, why, why_size) != STATUS_OK)
        return -1;
    int file = source_set_add(&L->scene->sources, src.path ? src.path : name, src.text, src.len, at);
    if (identity && file >= 0) {
        *identity = mem_strdup(L->mem, src.identity ? src.identity : L->scene->sources.files[file]->path);
        if (!*identity)
            file = -1;
    }
    give_back(L, &src);
    if (file < 0)
        loader_oom(L);
    return file;
}

int loader_fetch_mesh(loader *L, const char *name, src_span at, scene_source *held, char *why, size_t why_size)
{
    if (ask(L, name, at, held, why, why_size) != STATUS_OK)
        return -1;
    int file = source_set_lend(&L->scene->sources, held->path ? held->path : name, held->text, held->len, at);
    if (file < 0) {
        give_back(L, held);
        loader_oom(L);
        return -1;
    }
    L->scene->sources.files[file]->is_mesh = 1;
    return file;
}

void loader_release_mesh(loader *L, int file, scene_source *held)
{
    if (!L->scene->sources.files[file]->lent)
        return;
    source_set_release(&L->scene->sources, file);
    give_back(L, held);
}

void loader_init(loader *L, scene_model *s, const scene_load_opts *o)
{
    memset(L, 0, sizeof *L);
    L->scene = s;
    L->limits = &o->limits;
    L->resolver = &o->resolver;
    L->mem = &s->mem;
    diag_init(&L->diag, &s->sources, o->sink, o->sink_user);
    L->diag.max_errors = (int)o->limits.max_errors;
    L->diag.warnings_enabled = o->warnings;
    arena_init(&L->arena, &s->mem);
    env_init(&L->env, &s->mem);
    L->image_where = src_span_none();
    L->camera_where = src_span_none();
    L->default_material = -1;
}

void loader_free(loader *L)
{
    arena_free(&L->arena);
    env_free(&L->env);
    for (int i = 0; i < L->include_depth; i++)
        mem_free_string(L->mem, L->include_stack[i]);
    mem_free(L->mem, L->include_stack, (size_t)L->include_cap * sizeof *L->include_stack);
    mem_free(L->mem, L->material_uses, (size_t)L->uses_cap * sizeof *L->material_uses);
}

/* Reads the OBJ file into the load's sources, so its errors point into it. */
int loader_read_mesh(loader *L, const char *name, src_span at, scene_source *held, int *file)
{
    char why[512];
    *file = loader_fetch_mesh(L, name, at, held, why, sizeof why);
    if (*file < 0 && !L->out_of_memory)
        diag_report(&L->diag, DIAG_ERROR, at, "%s", why);
    return *file >= 0;
}

char *loader_strdup(loader *L, const char *text)
{
    char *copy = mem_strdup(L->mem, text);
    if (!copy)
        loader_oom(L);
    return copy;
}
