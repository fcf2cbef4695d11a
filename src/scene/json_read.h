/*
 * json_read.h - typed reading of a JSON scene's values, with diagnostics
 * at the offending value (spec/json.md, "Diagnostics").
 *
 * jansson parses the text and keeps no positions; the reader keeps the
 * path of the value it is reading (a JSON pointer) and asks base/jsonloc
 * for the value's span only when it reports.  Every message names the
 * value by its pointer (the loader's diag subject hook) as well as by line
 * and column.  Internal to the JSON front end (load_json.c).
 */
#ifndef REFRAY_JSON_READ_H
#define REFRAY_JSON_READ_H

#ifdef REFRAY_HAVE_JSON

#include <jansson.h>
#include "base/jsonloc.h"
#include "scene/loader.h"

enum { JREAD_MAX_DEPTH = 16 };

typedef struct jreader {
    loader *L;
    int file;                         /* the JSON text in L->scene->sources */
    jsonloc_step path[JREAD_MAX_DEPTH];
    int depth;                        /* steps of path in use: the value being read */
} jreader;

/* An upper bound of the bytes jansson holds while it parses text (its
 * derivation in json_read.c; [REL-MEMORY-2]). */
double jread_tree_bound(const char *text, size_t len);

/* Parses the file's text; on malformed JSON reports jansson's message at
 * its position and returns NULL, as it does (before jansson runs) when
 * the tree's bound would pass --max-memory ([REL-MEMORY-2]). */
json_t *jread_parse(loader *L, int file);

/* The path: push a member or an element before reading it, pop after. */
void jread_push_key(jreader *r, const char *key);
void jread_push_index(jreader *r, size_t index);
void jread_pop(jreader *r);

/* The span of member key of the current value (key NULL: the value
 * itself; an object or array only by its first byte).  A member that is
 * not there gives the current value's span. */
src_span jread_span(const jreader *r, const char *key);
/* The check_at of the current object: a field is its member of the same
 * name as the scene language's property (spec/json.md). */
check_at jread_at(const jreader *r);

/* Reports every member of obj not named in allowed (NULL-terminated). */
int jread_known(jreader *r, json_t *obj, const char *const *allowed);

/* The member, or NULL after "missing field" at the object. */
json_t *jread_member(jreader *r, json_t *obj, const char *key);

/* Typed members of the current object obj; each returns 1 when read, else
 * 0 after reporting (missing, or of the wrong type). */
int jread_number(jreader *r, json_t *obj, const char *key, double *out);
int jread_vec3(jreader *r, json_t *obj, const char *key, vec3 *out);
int jread_enum(jreader *r, json_t *obj, const char *key, const char *const *names, int count, int *out);
int jread_bool(jreader *r, json_t *obj, const char *key, int *out);
/* A string, or null (*out NULL) when nullable. */
int jread_string(jreader *r, json_t *obj, const char *key, int nullable, const char **out);
/* An index in [0, count): an integer-valued number. */
int jread_index(jreader *r, json_t *obj, const char *key, int count, const char *what, int *out);
/* An array (any length); *out borrowed from obj. */
int jread_array(jreader *r, json_t *obj, const char *key, json_t **out);
/* The current value, already known to be there, as an object. */
int jread_is_object(jreader *r, json_t *val);

/* A value (not a member) read at the current path. */
int jread_value_vec3(jreader *r, json_t *val, vec3 *out);
int jread_value_index(jreader *r, json_t *val, int count, const char *what, int *out);

/* load_json_mesh.c: the mesh object p (its material already in proto)
 * as the scene's mesh store and one PRIM_MESH primitive. */
int load_json_mesh(jreader *r, json_t *p, scene_prim *proto);

/* load_json_derived.c: the derived members of the document root against
 * the scene loaded and validated from its primary ones ([JSON-DERIVED-1]);
 * 1 when every one there agrees, else 0 after the first error. */
int load_json_derived(jreader *r, json_t *root);

#endif
#endif
