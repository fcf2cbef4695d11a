/*
 * scene_load.c - loading a scene: parse, lower, validate (scene.h).
 */
#include <string.h>
#include "scene/loader.h"

scene_model *scene_load_source(const scene_source *root, const scene_load_opts *o, int *status)
{
    scene_load_opts fallback;
    if (!o) {
        scene_load_opts_init(&fallback);
        o = &fallback;
    }
    mem m = mem_pick(&o->mem);
    scene_model *s = mem_calloc(&m, 1, sizeof *s);
    loader L;
    if (!s) {
        *status = STATUS_NO_MEMORY;
        return NULL;
    }
    s->mem = m;
    loader_scene_defaults(s);
    loader_init(&L, s, o);
    int file = source_set_add(&s->sources, root->path, root->text, root->len, src_span_none());
    char *identity = file >= 0 ? mem_strdup(&m, root->identity ? root->identity : root->path) : NULL;
    int ok = identity && loader_lower_file(&L, file, identity) && validate_scene(&L);
    if (!identity)
        loader_oom(&L);
    *status = ok ? STATUS_OK : L.out_of_memory ? STATUS_NO_MEMORY : STATUS_DATA;
    if (ok)
        loader_trim(&L);
    loader_free(&L);
    if (!ok) {
        scene_free(s);
        return NULL;
    }
    return s;
}
