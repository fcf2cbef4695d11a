/*
 * load_json_mesh.c - a JSON scene's meshes (spec/json.md, "Meshes"): inline
 * arrays of vertices, normals and triangles, or an OBJ or PLY file (as
 * `refray export --mesh-files` writes them).  Either way the mesh becomes
 * the same store and PRIM_MESH primitive as a .scene's (lower_mesh.c), with
 * the triangles in world coordinates and every number stored as read:
 * unlike a .scene's mesh, no transform is applied and no normal is
 * normalised (one that a triangle uses and that is not unit is refused).
 * Built only with JSON=1.
 */
#include <limits.h>
#include <string.h>
#include "scene/json_read.h"

/* An array of 3-vectors into pm (normals: added as read, checked later). */
static int read_points(jreader *r, json_t *p, const char *key, int normals, polymesh *pm)
{
    json_t *list, *item;
    size_t i;
    if (!jread_array(r, p, key, &list))
        return 0;
    if (json_array_size(list) > INT_MAX) {
        loader_oom(r->L);
        return 0;
    }
    int ok = 1;
    jread_push_key(r, key);
    json_array_foreach(list, i, item) {
        vec3 v;
        jread_push_index(r, i);
        ok = jread_value_vec3(r, item, &v);
        jread_pop(r);
        if (ok && (normals ? polymesh_add_normal(pm, v) : polymesh_add_position(pm, v)) != 1) {
            loader_oom(r->L);
            ok = 0;
        }
        if (!ok)
            break;
    }
    jread_pop(r);
    return ok;
}

/* Three indices in [0, count). */
static int read_corners(jreader *r, json_t *corners, int count, const char *what, int out[3])
{
    if (!json_is_array(corners) || json_array_size(corners) != 3) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected an array of 3 %s indices", what);
        return 0;
    }
    int ok = 1;
    for (size_t k = 0; k < 3 && ok; k++) {
        jread_push_index(r, k);
        ok = jread_value_index(r, json_array_get(corners, k), count, what, &out[k]);
        jread_pop(r);
    }
    return ok;
}

/* [JSON-MESH-1] A normal that a triangle uses must be unit, as stored
 * (reported at its entry of "normals"). */
static int unit_normals(jreader *r, const polymesh *pm, const int vn[3])
{
    int ok = 1;
    jread_push_key(r, "normals");
    for (int k = 0; k < 3 && ok; k++) {
        jread_push_index(r, (size_t)vn[k]);
        check_at at = jread_at(r);
        ok = check_unit(r->L, &at, KW_NORMAL, "normal", pm->normals[vn[k]]);
        jread_pop(r);
    }
    jread_pop(r);
    return ok;
}

/* triangles[i] (and triangle_normals[i] when given and not null) into pm
 * as one face; every face is placed at the "triangles" member (at). */
static int read_triangle(jreader *r, json_t *tris, json_t *tri_normals, size_t i, size_t at, polymesh *pm)
{
    json_t *vn = tri_normals ? json_array_get(tri_normals, i) : NULL;
    int v[3], n[3];
    jread_push_key(r, "triangles");
    jread_push_index(r, i);
    int ok = read_corners(r, json_array_get(tris, i), pm->position_count, "vertex", v);
    jread_pop(r);
    jread_pop(r);
    int smooth = vn && !json_is_null(vn);
    if (ok && smooth) {
        jread_push_key(r, "triangle_normals");
        jread_push_index(r, i);
        ok = read_corners(r, vn, pm->normal_count, "normal", n);
        jread_pop(r);
        jread_pop(r);
        ok = ok && unit_normals(r, pm, n);
    }
    if (!ok)
        return 0;
    int added = polymesh_add_face(pm, v, smooth ? n : NULL, 3, at);
    if (added == POLYMESH_NO_MEMORY)
        loader_oom(r->L);
    else if (added != 1)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, "triangles"),
                    "more than %ld triangles in one mesh (--max-mesh-triangles)", r->L->limits->max_mesh_triangles);
    return added == 1;
}

static int inline_mesh(jreader *r, json_t *p, polymesh *pm)
{
    json_t *tris, *tri_normals = json_object_get(p, "triangle_normals");
    if (!read_points(r, p, "vertices", 0, pm) || !read_points(r, p, "normals", 1, pm) ||
        !jread_array(r, p, "triangles", &tris))
        return 0;
    size_t n = json_array_size(tris);
    if (n == 0 || n > (size_t)r->L->limits->max_mesh_triangles) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, "triangles"),
                    n ? "more than %ld triangles in one mesh (--max-mesh-triangles)" : "a mesh needs triangles",
                    r->L->limits->max_mesh_triangles);
        return 0;
    }
    if (tri_normals && !json_is_null(tri_normals) &&
        (!json_is_array(tri_normals) || json_array_size(tri_normals) != n)) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, "triangle_normals"),
                    "expected an array with one entry per triangle (%zu)", n);
        return 0;
    }
    size_t at = jread_span(r, "triangles").begin;
    json_t *normals = json_is_array(tri_normals) ? tri_normals : NULL;
    for (size_t i = 0; i < n; i++)
        if (loader_stop(r->L) || !read_triangle(r, tris, normals, i, at, pm))
            return 0;
    return 1;
}

/* The normals the triangles of a mesh file use must be unit, as read: the
 * message at the face's line. */
static int file_normals_unit(jreader *r, int file, const polymesh *pm)
{
    for (int k = 0; pm->tri_normal && k < pm->triangle_count; k++)
        for (int i = 0; i < 3; i++) {
            int n = pm->tri_normal[k][i];
            src_span span = {file, pm->tri_at[k], pm->tri_at[k] + 1};
            check_at at = check_at_fixed(&span);
            if (n >= 0 && !check_unit(r->L, &at, KW_NORMAL, "normal", pm->normals[n]))
                return 0;
        }
    return 1;
}

int load_json_mesh(jreader *r, json_t *p, scene_prim *proto)
{
    static const char *const inline_keys[] = {"kind", "material", "source", "vertices", "normals", "triangles",
                                              "triangle_normals", NULL};
    static const char *const file_keys[] = {"kind", "material", "source", "file", NULL};
    const char *source = NULL, *name = NULL;
    int from_file = json_object_get(p, "file") != NULL, file = r->file;
    src_span at = jread_span(r, NULL);
    scene_source held, *hold = NULL;
    polymesh pm;
    polymesh_init(&pm, r->L->limits->max_mesh_triangles, r->L->mem);
    int ok = jread_known(r, p, from_file ? file_keys : inline_keys) && jread_string(r, p, "source", 1, &source);
    if (ok && from_file) {
        at = jread_span(r, "file");
        ok = jread_string(r, p, "file", 0, &name) && loader_read_mesh(r->L, name, at, &held, &file);
        hold = ok ? &held : NULL;
        ok = ok && lower_parse_mesh(r->L, file, &pm) && file_normals_unit(r, file, &pm);
    } else if (ok) {
        ok = inline_mesh(r, p, &pm);
    }
    /* The path the scene records: the .scene's mesh file when the export
     * named it, else the file read, else the JSON document. */
    ok = ok && lower_mesh(r->L, &pm, file, hold, at, proto, NULL, NULL);
    if (ok && source) {
        scene_mesh *m = &r->L->scene->meshes[r->L->scene->mesh_count - 1];
        char *copy = loader_strdup(r->L, source);
        ok = copy != NULL;
        if (ok) {
            mem_free_string(r->L->mem, m->path);
            m->path = copy;
        }
    }
    polymesh_free(&pm);
    if (hold)
        loader_release_mesh(r->L, file, hold);
    return ok;
}
