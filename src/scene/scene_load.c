/*
 * scene_load.c - loading a scene: parse, lower, validate (scene.h).
 */
#include <string.h>
#include "scene/loader.h"

int scene_json_available(void)
{
#ifdef REFRAY_HAVE_JSON
    return 1;
#else
    return 0;
#endif
}

/* The root file as the scene language. */
static int lower_language(loader *L, int file, const scene_source *root)
{
    const char *root_id = root->identity ? root->identity : root->path;
    char *identity = loader_add_file(L, file, root_id, root->len) ? mem_strdup(L->mem, root_id) : NULL;
    if (!identity) {
        loader_oom(L);
        return 0;
    }
    if (!loader_lower_file(L, file, identity))
        return 0;
    /* Without a camera block the default camera's basis is derived by the
     * same rule as any other (a cross product leaves right.y = -0, not the
     * +0 a written-out default would have), so a scene read back from its
     * JSON export, which always derives it, has the same bits. */
    if (L->camera_where.file >= 0)
        return 1;
    src_span none = src_span_none();
    check_at at = check_at_fixed(&none);
    return check_camera(L, &at, &L->scene->camera);
}

/* The root file in the language asked for. */
static int lower_root(loader *L, int file, const scene_source *root, int json)
{
#ifdef REFRAY_HAVE_JSON
    if (json)
        return loader_lower_json(L, file);
#else
    (void)json;
#endif
    return lower_language(L, file, root);
}

static scene_model *load(const scene_source *root, const scene_load_opts *o, int json, int *status)
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
    arena_init_growing(&s->kept, &s->mem, SCENE_KEPT_FIRST, SCENE_KEPT_LAST);
    s->max_render.width = o->limits.max_width;
    s->max_render.height = o->limits.max_height;
    s->max_render.pixels = o->limits.max_pixels;
    s->max_render.samples = o->limits.max_samples;
    s->max_render.light_samples = o->limits.max_light_samples;
    s->max_render.depth = o->limits.max_depth;
    loader_scene_defaults(s);
    loader_init(&L, s, o);
    int file = source_set_add(&s->sources, root->path, root->text, root->len, src_span_none());
    int ok = 0;
    if (file < 0)
        loader_oom(&L);
    else if ((double)root->len > (double)o->limits.max_input_bytes)
        diag_report(&L.diag, DIAG_ERROR, src_span_none(), "'%s' is %zu bytes, over the limit of %ld bytes a load reads "
                    "(--max-input-size)", root->path, root->len, o->limits.max_input_bytes);
    else
        ok = lower_root(&L, file, root, json) && validate_scene(&L) && !cancel_stopped(&L.cancel);
#ifdef REFRAY_HAVE_JSON
    ok = loader_json_finish(&L, ok);
#endif
    *status = ok ? STATUS_OK : cancel_stopped(&L.cancel) ? STATUS_CANCELLED
              : L.out_of_memory ? STATUS_NO_MEMORY : STATUS_DATA;
    if (ok)
        loader_trim(&L);
    loader_free(&L);
    if (!ok) {
        scene_free(s);
        return NULL;
    }
    return s;
}

scene_model *scene_load_source(const scene_source *root, const scene_load_opts *o, int *status)
{
    return load(root, o, 0, status);
}

scene_model *scene_load_json_source(const scene_source *root, const scene_load_opts *o, int *status)
{
    if (scene_json_available())
        return load(root, o, 1, status);
    if (o && o->sink) {
        source_set none; /* no files: only its allocator, for a long message */
        diag d;
        source_set_init(&none, &o->mem);
        diag_init(&d, &none, o->sink, o->sink_user);
        diag_report(&d, DIAG_ERROR, src_span_none(),
                    "'%s' is a JSON scene, and this refray was built without JSON support (JSON=0); rebuild it "
                    "with JSON=1 (libjansson-dev)",
                    root->path);
    }
    *status = STATUS_USAGE;
    return NULL;
}
