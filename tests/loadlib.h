/*
 * loadlib.h - a scene loaded for a test with every diagnostic it printed
 * kept as text (check_include.c, check_lower.c).  static inline, so a
 * suite that uses only some of them gets no warning.
 */
#ifndef REFRAY_LOADLIB_H
#define REFRAY_LOADLIB_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "io/scene_file.h"
#include "scene/scene.h"

typedef struct loaded {
    scene_model *scene;
    int status;
    char *messages;        /* every diagnostic printed */
    size_t size;
} loaded;

/* Loads text as the file path (limits NULL: the defaults). */
static inline void load_as(loaded *l, const char *path, const char *text, const scene_limits *limits, int warnings)
{
    FILE *out = open_memstream(&l->messages, &l->size);
    ck_assert_ptr_nonnull(out);
    l->scene = scene_file_load_text(path, text, strlen(text), limits, out, warnings, &l->status);
    fclose(out);
}

/* Loads the file at path. */
static inline void load_file(loaded *l, const char *path, const scene_limits *limits)
{
    FILE *out = open_memstream(&l->messages, &l->size);
    ck_assert_ptr_nonnull(out);
    l->scene = scene_file_load(path, limits, out, 1, &l->status);
    fclose(out);
}

static inline void loaded_done(loaded *l)
{
    scene_free(l->scene);
    free(l->messages);
}

/* The first message, its newline cut off in place. */
static inline const char *first_line(loaded *l)
{
    char *nl = strchr(l->messages, '\n');
    if (nl)
        *nl = '\0';
    return l->messages;
}

#endif
