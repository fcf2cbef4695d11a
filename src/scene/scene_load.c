/*
 * scene_load.c - loading a scene: read, parse, lower, validate.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "base/fileio.h"
#include "scene/loader.h"

int scene_json_available(void)
{
#ifdef REFRAY_HAVE_JSON
    return 1;
#else
    return 0;
#endif
}

int loader_is_json(const char *path)
{
    static const char ext[] = ".json";
    size_t n = strlen(path), k = sizeof ext - 1;
    if (n < k)
        return 0;
    for (size_t i = 0; i < k; i++)
        if (tolower((unsigned char)path[n - k + i]) != ext[i])
            return 0;
    return 1;
}

/* The root file in the language its name says. */
static int lower_root(loader *L, int file)
{
#ifdef REFRAY_HAVE_JSON
    if (loader_is_json(L->scene->sources.files[file]->path))
        return loader_lower_json(L, file);
#endif
    if (!loader_lower_file(L, file))
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

rf_scene *scene_load_text(const char *path, const char *text, size_t len, const rf_limits *limits, FILE *diag_out,
                          int warnings, int *status)
{
    rf_limits fallback = scene_default_limits();
    if (loader_is_json(path) && !scene_json_available()) {
        if (diag_out)
            fprintf(diag_out, "refray: error: '%s' is a JSON scene, and this refray was built without JSON support "
                              "(JSON=0); rebuild it with JSON=1 (libjansson-dev)\n", path);
        *status = REFRAY_EXIT_USAGE;
        return NULL;
    }
    rf_scene *s = calloc(1, sizeof *s);
    loader L;
    if (!s) {
        *status = REFRAY_EXIT_SOFTWARE;
        return NULL;
    }
    loader_scene_defaults(s);
    loader_init(&L, s, limits ? limits : &fallback, diag_out, warnings);
    int file = source_set_add(&s->sources, path, text, len, src_span_none());
    int ok = file >= 0 && lower_root(&L, file) && validate_scene(&L);
    if (file < 0)
        loader_oom(&L);
    *status = ok ? REFRAY_EXIT_OK : L.out_of_memory ? REFRAY_EXIT_SOFTWARE : REFRAY_EXIT_DATAERR;
    loader_free(&L);
    if (!ok) {
        scene_free(s);
        return NULL;
    }
    return s;
}

rf_scene *scene_load(const char *path, const rf_limits *limits, FILE *diag_out, int warnings, int *status)
{
    rf_limits fallback = scene_default_limits();
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
    rf_scene *s = scene_load_text(path, text, len, limits, diag_out, warnings, status);
    free(text);
    return s;
}
