/*
 * export_json_mesh.c - a mesh of an exported scene: its store (the scene's
 * transforms applied, positions and normals in the store's order, each
 * triangle's corners in the order the tracer holds them) as indexed
 * arrays, inline or in an OBJ file.  The store is written as it is, so a
 * scene read back has the same store bit for bit.  JSON=1 builds only.
 */
#include <stdlib.h>
#include <string.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "export/export_json_impl.h"

static json_t *points(export_json_build *b, const vec3 *v, int count)
{
    json_t *out = json_array();
    for (int i = 0; i < count; i++)
        export_json_append(b, out, export_json_vec3(v[i]));
    return out;
}

static json_t *corners(const int c[3])
{
    return json_pack("[iii]", c[0], c[1], c[2]);
}

/* Whether triangle k has vertex normals (a flat one has -1 for each corner). */
static int smooth(const scene_trimesh *g, int k)
{
    return g->tri_normal && g->tri_normal[k][0] >= 0;
}

static void inline_arrays(export_json_build *b, json_t *out, const scene_trimesh *g)
{
    json_t *tris = json_array(), *tri_normals = json_array();
    for (int k = 0; k < g->tri_count; k++) {
        export_json_append(b, tris, corners(g->tri[k]));
        export_json_append(b, tri_normals, smooth(g, k) ? corners(g->tri_normal[k]) : json_null());
    }
    export_json_set(b, out, "vertices", points(b, g->positions, g->position_count));
    export_json_set(b, out, "normals", points(b, g->normals, g->normal_count));
    export_json_set(b, out, "triangles", tris);
    export_json_set(b, out, "triangle_normals", tri_normals);
}

static int fill_obj(FILE *fp, void *ctx)
{
    const scene_trimesh *g = ctx;
    fprintf(fp, "# refray export: a mesh in world coordinates (spec/json.md, \"Meshes\")\n");
    for (int i = 0; i < g->position_count; i++)
        fprintf(fp, "v %.17g %.17g %.17g\n", (double)g->positions[i].x, (double)g->positions[i].y,
                (double)g->positions[i].z);
    for (int i = 0; i < g->normal_count; i++)
        fprintf(fp, "vn %.17g %.17g %.17g\n", (double)g->normals[i].x, (double)g->normals[i].y,
                (double)g->normals[i].z);
    for (int k = 0; k < g->tri_count; k++) {
        const int *v = g->tri[k];
        if (!smooth(g, k))
            fprintf(fp, "f %d %d %d\n", v[0] + 1, v[1] + 1, v[2] + 1);
        else {
            const int *n = g->tri_normal[k];
            fprintf(fp, "f %d//%d %d//%d %d//%d\n", v[0] + 1, n[0] + 1, v[1] + 1, n[1] + 1, v[2] + 1, n[2] + 1);
        }
    }
    return ferror(fp) ? STATUS_IO : STATUS_OK;
}

/* Writes the OBJ file of mesh m; its reference (mesh_dir/NAME.obj) in *ref. */
static int write_obj(const export_json_opts *o, int m, const scene_trimesh *g, char **ref, char *err, size_t errlen)
{
    char name[300];
    snprintf(name, sizeof name, "%s.mesh%d.obj", o->mesh_stem ? o->mesh_stem : "scene", m);
    *ref = file_join(NULL, o->mesh_dir, name);
    char *dir = file_join(NULL, o->json_dir ? o->json_dir : ".", o->mesh_dir);
    char *path = *ref ? file_join(NULL, o->json_dir ? o->json_dir : ".", *ref) : NULL;
    int rc = STATUS_NO_MEMORY;
    if (!dir || !path)
        snprintf(err, errlen, "out of memory");
    else if ((rc = file_make_dirs(dir, err, errlen)) == 0)
        rc = file_write_atomic(path, fill_obj, (void *)g, err, errlen);
    free(dir);
    free(path);
    return rc;
}

json_t *export_json_mesh(const scene_model *s, int m, const export_json_opts *o, int *status, char *err,
                         size_t errlen)
{
    export_json_build b = {0};
    const scene_mesh *mesh = &s->meshes[m];
    char *ref = NULL;
    if (errlen)
        err[0] = '\0';
    json_t *out = json_object(), *source = json_string(mesh->path);
    export_json_set(&b, out, "kind", json_string("mesh"));
    export_json_set(&b, out, "material", json_integer(s->prims[mesh->prim].material));
    export_json_set(&b, out, "source", source ? source : json_null());
    *status = STATUS_OK;
    if (o->mesh_dir && (*status = write_obj(o, m, &mesh->geom, &ref, err, errlen)) == 0)
        export_json_set(&b, out, "file", json_string(ref));
    else if (*status == 0)
        inline_arrays(&b, out, &mesh->geom);
    free(ref);
    if (*status == 0 && b.failed)
        *status = STATUS_NO_MEMORY;
    if (*status != 0 && errlen && !err[0])
        snprintf(err, errlen, "out of memory");
    if (*status != 0) {
        json_decref(out);
        return NULL;
    }
    return out;
}
