/*
 * loader.c - the state of one load: the scene being built, its growable
 * arrays, the files the resolver gives it, and the out-of-memory flag
 * every pass checks.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "scene/loader.h"

int loader_stop(const loader *L)
{
    return L->out_of_memory || diag_stop(&L->diag);
}

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
    s->camera.width_where = src_span_none();
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
    long want = *cap ? 2L * *cap : 16;
    int next = (int)(want < limit ? want : limit);
    void *grown = mem_resize_array(m, *items, (size_t)*cap, (size_t)next, size);
    if (!grown)
        return 0;
    *items = grown;
    *cap = next;
    return 1;
}

double loader_memory_extra(const loader *L)
{
    return (double)L->input_bytes + (double)L->arena.bytes;
}

/* The primitives that fit in --max-memory beside what the load holds
 * already and the image (scene_memory_estimate), the array growing from
 * its capacity now: while it grows, the old block and the new one are
 * both held. */
static long prims_within_memory(const loader *L)
{
    const scene_model *s = L->scene;
    double budget = (double)L->limits->max_memory_mb * 1048576.0;
    double left = budget - scene_memory_estimate(0, (double)s->image.width * s->image.height, loader_memory_extra(L));
    double n = left / (double)SCENE_BYTES_PER_PRIM, growing = left / (double)sizeof(scene_prim) - s->prim_cap;
    n = floor(n < growing ? n : growing);
    return n <= 0 ? 0 : n < (double)LONG_MAX ? (long)n : LONG_MAX;
}

scene_prim *loader_add_prim(loader *L, src_span where)
{
    scene_model *s = L->scene;
    if (L->prims_refused)
        return NULL;
    long used = s->prim_count + L->mesh_triangles;
    if (used >= L->limits->max_primitives) {
        if (used == L->limits->max_primitives)
            diag_report(&L->diag, DIAG_ERROR, where, "more than %ld primitives (--max-primitives)",
                        L->limits->max_primitives);
        s->prim_count++;
        return NULL;
    }
    /* Checked when the array is about to grow: that is when memory goes. */
    long fit = s->prim_count == s->prim_cap ? prims_within_memory(L) : LONG_MAX;
    if (s->prim_count >= fit) {
        diag_report(&L->diag, DIAG_ERROR, where, "more than %ld primitives would need over --max-memory %ld MiB "
                    "(about %zu bytes each, spec/reliability.md)", fit, L->limits->max_memory_mb,
                    (size_t)SCENE_BYTES_PER_PRIM);
        L->prims_refused = 1;
        return NULL;
    }
    long limit = fit < L->limits->max_primitives ? fit : L->limits->max_primitives;
    void *items = s->prims;
    if (!grow(L->mem, &items, &s->prim_cap, s->prim_count, sizeof *s->prims, limit)) {
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

static const char *file_identity(const void *loader_p, int i)
{
    return ((const loader *)loader_p)->files[i].identity;
}

int loader_add_file(loader *L, int file, const char *identity, size_t len)
{
    if (file >= L->files_cap) {
        int cap = L->files_cap ? 2 * L->files_cap : 8;
        while (cap <= file)
            cap *= 2;
        loader_file *files = mem_resize_array(L->mem, L->files, (size_t)L->files_cap, (size_t)cap, sizeof *files);
        if (!files) {
            loader_oom(L);
            return 0;
        }
        memset(files + L->files_cap, 0, (size_t)(cap - L->files_cap) * sizeof *files);
        L->files = files;
        L->files_cap = cap;
    }
    if (!(L->files[file].identity = mem_strdup(L->mem, identity)) || !name_index_add(&L->file_names, file)) {
        loader_oom(L);
        return 0;
    }
    L->input_bytes += (long)len;
    return 1;
}

/* The index of the file read before under identity, or -1.  It is moved
 * to be included from at, so that messages name the include that read it
 * this time, unless it is being lowered now (a cycle: its chain stays). */
static int known_file(loader *L, const char *identity, src_span at)
{
    int file = name_index_find(&L->file_names, identity);
    for (int i = 0; file >= 0 && i < L->include_depth; i++)
        if (strcmp(L->include_stack[i], identity) == 0)
            return file;
    if (file >= 0)
        L->scene->sources.files[file]->included_from = at;
    return file;
}

/* A new file: counted against --max-input-size, then copied. */
static int new_file(loader *L, const scene_source *src, const char *name, const char *identity, src_span at,
                    char *why, size_t why_size)
{
    long max = L->limits->max_input_bytes;
    if (src->known || !src->text) {
        snprintf(why, why_size, "cannot read '%s': the resolver gave no text", name);
        return -1;
    }
    if ((double)L->input_bytes + (double)src->len > (double)max) {
        snprintf(why, why_size, "'%s' (%zu bytes) would bring the bytes this load reads to %.0f, over the limit of %ld "
                 "(--max-input-size)", name, src->len, (double)L->input_bytes + (double)src->len, max);
        return -1;
    }
    int file = source_set_add(&L->scene->sources, src->path ? src->path : name, src->text, src->len, at);
    if (file < 0) {
        loader_oom(L);
        return -1;
    }
    return loader_add_file(L, file, identity, src->len) ? file : -1;
}

/* Asks the resolver for name into *src; STATUS_OK, or another status with
 * the reason in why (out of memory reported).  accept_known: the resolver
 * may answer a file it gave before with `known` and no text (an include,
 * whose copy the load keeps; a mesh file's text is released once its mesh
 * is built, so it is always read). */
static int ask(loader *L, const char *name, src_span at, int accept_known, scene_source *src, char *why,
               size_t why_size)
{
    const scene_resolver *r = L->resolver;
    const char *from = L->scene->sources.files[at.file]->path;
    memset(src, 0, sizeof *src);
    src->known = accept_known;
    why[0] = '\0';
    int status = STATUS_NO_INPUT;
    if (r->fetch)
        status = r->fetch(r->user, from, name, src, why, why_size);
    else
        snprintf(why, why_size, "cannot read '%s': this load reads no files", name);
    /* A resolver that knows nothing of `known` leaves the flag as it was
     * set on entry: an answer with text is a fresh read whatever it says. */
    if (src->text)
        src->known = 0;
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
    if (ask(L, name, at, 1, &src, why, why_size) != STATUS_OK)
        return -1;
    const char *id = src.identity ? src.identity : src.path ? src.path : name;
    int file = known_file(L, id, at);
    if (file < 0)
        file = new_file(L, &src, name, id, at, why, why_size);
    if (identity && file >= 0 && !(*identity = mem_strdup(L->mem, id))) {
        loader_oom(L);
        file = -1;
    }
    give_back(L, &src);
    return file;
}

int loader_fetch_mesh(loader *L, const char *name, src_span at, scene_source *held, char *why, size_t why_size)
{
    if (ask(L, name, at, 0, held, why, why_size) != STATUS_OK)
        return -1;
    double total = (double)L->input_bytes + (double)held->len;
    if (!held->text || held->known || total > (double)L->limits->max_input_bytes) {
        if (!held->text || held->known)
            snprintf(why, why_size, "cannot read '%s': the resolver gave no text", name);
        else
            snprintf(why, why_size, "'%s' (%zu bytes) would bring the bytes this load reads to %.0f, over the limit "
                     "of %ld (--max-input-size)", name, held->len, total, L->limits->max_input_bytes);
        give_back(L, held);
        return -1;
    }
    int file = source_set_lend(&L->scene->sources, held->path ? held->path : name, held->text, held->len, at);
    if (file < 0) {
        give_back(L, held);
        loader_oom(L);
        return -1;
    }
    L->input_bytes += (long)held->len;
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

static const char *material_name(const void *scene, int i)
{
    return ((const scene_model *)scene)->materials[i].name;
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
    L->cancel = cancel_poll_make(o->cancel, o->cancel_user);
    L->diag.cancel = &L->cancel;
    arena_init(&L->arena, &s->mem);
    env_init(&L->env, &s->mem);
    name_index_init(&L->material_names, material_name, s, &s->mem);
    name_index_init(&L->file_names, file_identity, L, &s->mem);
    L->image_where = src_span_none();
    L->max_depth_where = src_span_none();
    L->camera_where = src_span_none();
    L->default_material = -1;
}

void loader_free(loader *L)
{
    arena_free(&L->arena);
    env_free(&L->env);
    name_index_free(&L->material_names);
    name_index_free(&L->file_names);
    for (int i = 0; i < L->files_cap; i++)
        mem_free_string(L->mem, L->files[i].identity);
    mem_free(L->mem, L->files, (size_t)L->files_cap * sizeof *L->files);
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
