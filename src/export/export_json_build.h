/*
 * export_json_build.h - the helpers every part of the JSON export builds
 * its values with (export_json_impl.h): the lowest of its files, so the
 * document, the conventions and the meshes all stand on it.  JSON=1
 * builds only.
 */
#ifndef REFRAY_EXPORT_JSON_BUILD_H
#define REFRAY_EXPORT_JSON_BUILD_H

#ifdef REFRAY_HAVE_JSON

#include <jansson.h>
#include "base/vec.h"

/* A document being built: one flag for every allocation that failed, so
 * the builders need no error path of their own. */
typedef struct export_json_build {
    int failed;
} export_json_build;

/* obj[key] = v (v's reference taken; NULL v or obj marks a failure). */
void export_json_set(export_json_build *b, json_t *obj, const char *key, json_t *v);
void export_json_append(export_json_build *b, json_t *array, json_t *v);
json_t *export_json_vec3(vec3 v);
/* A 64-bit constant as "0x..." (JSON numbers do not carry 64 bits exactly
 * in most readers). */
json_t *export_json_hex(unsigned long long x);

#endif
#endif
