/*
 * scene_load.c - loading a scene: read, parse, lower, validate.
 */
#include <stdlib.h>
#include "base/fileio.h"
#include "scene/loader.h"

scene_model *scene_load_text(const char *path, const char *text, size_t len, const scene_limits *limits, FILE *diag_out,
                          int warnings, int *status)
{
    scene_limits fallback = scene_default_limits();
    scene_model *s = calloc(1, sizeof *s);
    loader L;
    if (!s) {
        *status = STATUS_NO_MEMORY;
        return NULL;
    }
    loader_scene_defaults(s);
    loader_init(&L, s, limits ? limits : &fallback, diag_out, warnings);
    int file = source_set_add(&s->sources, path, text, len, src_span_none());
    int ok = file >= 0 && loader_lower_file(&L, file) && validate_scene(&L);
    if (file < 0)
        loader_oom(&L);
    *status = ok ? STATUS_OK : L.out_of_memory ? STATUS_NO_MEMORY : STATUS_DATA;
    loader_free(&L);
    if (!ok) {
        scene_free(s);
        return NULL;
    }
    return s;
}

scene_model *scene_load(const char *path, const scene_limits *limits, FILE *diag_out, int warnings, int *status)
{
    scene_limits fallback = scene_default_limits();
    char why[512], *text = NULL;
    size_t len = 0;
    if (!limits)
        limits = &fallback;
    *status = file_read_all(path, limits->max_file_bytes, &text, &len, why, sizeof why);
    if (*status != 0) {
        if (diag_out)
            fprintf(diag_out, "refray: error: %s\n", why);
        return NULL;
    }
    scene_model *s = scene_load_text(path, text, len, limits, diag_out, warnings, status);
    free(text);
    return s;
}
