/*
 * export_json.h - a loaded scene as a JSON document (`refray export --to
 * json`, spec/json.md): the validated model with every default explicit,
 * materials resolved, transforms as matrices, meshes inline or as OBJ
 * files, the camera's basis and sample positions, each distributed light's
 * sampling rule, and a header of conventions.  Reading the document back
 * (scene_load_json_source, or any file loader given a .json path) gives
 * the same model, bit for bit, so the same image.
 */
#ifndef REFRAY_EXPORT_JSON_H
#define REFRAY_EXPORT_JSON_H

#include <stddef.h>
#include <stdio.h>
#include "scene/scene.h"

typedef struct export_json_opts {
    const char *source;     /* the scene's path, written as "source"; NULL: null */
    const char *generator;  /* written as format.generator (e.g. "refray 0.2.0"); NULL: left out */
    /* Non-NULL: each mesh goes to an OBJ file instead of inline arrays.  Its
     * "file" member is mesh_dir/NAME.obj, a path relative to the JSON
     * file's directory (as the loader resolves it; absolute when mesh_dir
     * is), and the file is written there: json_dir/mesh_dir/NAME.obj. */
    const char *mesh_dir;
    const char *json_dir;   /* the directory of the JSON output; NULL: "." */
    const char *mesh_stem;  /* NAME is STEM.meshI for mesh I; NULL: "scene" */
} export_json_opts;

/*
 * Writes s as JSON to fp (and the mesh files, when asked, before it).
 * Returns STATUS_OK; STATUS_USAGE when this build has no JSON support
 * (JSON=0); STATUS_NO_MEMORY when out of memory; STATUS_IO when a write
 * failed.  On failure a one-line reason is in err (errlen
 * bytes), except for a failed write to fp itself (err then empty).
 */
int export_json_write(const scene_model *s, const export_json_opts *o, FILE *fp, char *err, size_t errlen);

/* The same into path, atomically (io/filewrite.h file_write_atomic). */
int export_json_file(const scene_model *s, const export_json_opts *o, const char *path, char *err, size_t errlen);

#endif
