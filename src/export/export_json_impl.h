/*
 * export_json_impl.h - the parts of the JSON export (export_json.h), for
 * its own files only: the builder's helpers (export_json_build.h), the
 * document of the model (export_json_doc.c), the conventions header
 * (export_json_conv.c), meshes (export_json_mesh.c) and the printer
 * (export_json_print.c).  JSON=1 builds only.
 */
#ifndef REFRAY_EXPORT_JSON_IMPL_H
#define REFRAY_EXPORT_JSON_IMPL_H

#ifdef REFRAY_HAVE_JSON

#include "export/export_json.h"
#include "export/export_json_build.h"

/* The header of conventions (spec/json.md, "conventions"). */
json_t *export_json_conventions(export_json_build *b);

/* Mesh m of s: inline arrays, or (o->mesh_dir) an OBJ file written now and
 * referenced.  Returns the object, or NULL with the status and a reason. */
json_t *export_json_mesh(const scene_model *s, int m, const export_json_opts *o, int *status, char *err,
                         size_t errlen);

/* The document of s (export_json.h), or NULL with the status and reason. */
json_t *export_json_document(const scene_model *s, const export_json_opts *o, int *status, char *err, size_t errlen);

/* Writes doc with the layout of spec/json.md (one value per line, short
 * arrays and objects on one line); STATUS_OK or STATUS_IO. */
int export_json_print(FILE *fp, const json_t *doc);

#endif
#endif
