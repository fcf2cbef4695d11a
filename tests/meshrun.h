/*
 * meshrun.h - one mesh file read by its reader for a test (check_obj.c,
 * check_ply.c): the file "m.EXT" included from a one-line scene, its
 * diagnostics kept as text so their exact wording is checked.  static
 * inline, so a suite that uses only some of them gets no warning.
 */
#ifndef REFRAY_MESHRUN_H
#define REFRAY_MESHRUN_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "base/diag.h"
#include "base/source.h"
#include "io/diag_print.h"
#include "lang/polymesh.h"

typedef struct run {
    source_set set;
    diag d;
    FILE *out;         /* NULL: diagnostics only counted */
    char *log;
    size_t log_size;
    polymesh mesh;
    int ok;
} run;

/* A mesh reader: obj_parse or ply_parse. */
typedef int (*meshrun_reader)(const source_set *sources, int file, diag *d, long max_triangles, polymesh *out);

/* Reads text (len bytes) as the file name through read; logged: the
 * diagnostics kept in r->log. */
static inline void meshrun_parse(run *r, const char *name, meshrun_reader read, const char *text, size_t len,
                                 long max_triangles, int logged)
{
    char scene[64];
    int n = snprintf(scene, sizeof scene, "mesh \"%s\"\n", name);
    memset(r, 0, sizeof *r);
    source_set_init(&r->set, NULL);
    int root = source_set_add(&r->set, "s.scene", scene, (size_t)n, src_span_none());
    src_span from = {root, 0, 4};
    int file = source_set_add(&r->set, name, text, len, from);
    ck_assert_int_eq(file, 1);
    if (logged) {
        r->out = open_memstream(&r->log, &r->log_size);
        ck_assert_ptr_nonnull(r->out);
    }
    diag_init(&r->d, &r->set, r->out ? diag_print : NULL, r->out);
    r->ok = read(&r->set, file, &r->d, max_triangles, &r->mesh);
    if (r->out)
        fflush(r->out);
}

static inline void run_free(run *r)
{
    if (r->out)
        fclose(r->out);
    free(r->log);
    polymesh_free(&r->mesh);
    source_set_free(&r->set);
}

/* The first line of the diagnostics, without its newline ("" if none). */
static inline const char *first_line(run *r, char *buf, size_t size)
{
    const char *log = r->log ? r->log : "";
    size_t n = strcspn(log, "\n");
    if (n >= size)
        n = size - 1;
    memcpy(buf, log, n);
    buf[n] = '\0';
    return buf;
}

#endif
