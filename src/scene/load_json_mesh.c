/*
 * load_json_mesh.c - a JSON scene's meshes (spec/json.md, "Meshes"): inline
 * arrays of vertices, normals and triangles, or an OBJ file (as `refray
 * export --mesh-files` writes them).  Either way the triangles are in world
 * coordinates and every number is stored as read: unlike a .scene's mesh,
 * no transform is applied and no normal is normalised (one that is not
 * unit is refused).  Built only with JSON=1.
 */
#include <limits.h>
#include <string.h>
#include "lang/obj.h"
#include "scene/json_read.h"

/* An array of 3-vectors (normals: each unit) into *out, *cap entries
 * from the load's allocator. */
static int read_points(jreader *r, json_t *p, const char *key, int normals, vec3 **out, int *count, int *cap)
{
    json_t *list, *item;
    size_t i;
    if (!jread_array(r, p, key, &list))
        return 0;
    size_t n = json_array_size(list) ? json_array_size(list) : 1;
    if (n > INT_MAX || !(*out = mem_calloc(r->L->mem, n, sizeof **out))) {
        loader_oom(r->L);
        return 0;
    }
    *cap = (int)n;
    *count = (int)json_array_size(list);
    int ok = 1;
    jread_push_key(r, key);
    json_array_foreach(list, i, item) {
        jread_push_index(r, i);
        check_at at = jread_at(r);
        ok = jread_value_vec3(r, item, &(*out)[i]) &&
             (!normals || check_unit(r->L, &at, KW_NORMAL, "normal", (*out)[i]));
        jread_pop(r);
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

/* triangles[i] into t->v, triangle_normals[i] (when given and not null) into t->vn. */
static int read_triangle(jreader *r, json_t *tris, json_t *tri_normals, size_t i, const obj_mesh *m, obj_triangle *t)
{
    json_t *vn = tri_normals ? json_array_get(tri_normals, i) : NULL;
    t->vn[0] = t->vn[1] = t->vn[2] = -1;
    jread_push_key(r, "triangles");
    jread_push_index(r, i);
    int ok = read_corners(r, json_array_get(tris, i), m->position_count, "vertex", t->v);
    jread_pop(r);
    jread_pop(r);
    if (!ok || !vn || json_is_null(vn))
        return ok;
    jread_push_key(r, "triangle_normals");
    jread_push_index(r, i);
    ok = read_corners(r, vn, m->normal_count, "normal", t->vn);
    jread_pop(r);
    jread_pop(r);
    return ok;
}

static int inline_mesh(jreader *r, json_t *p, obj_mesh *m)
{
    json_t *tris, *tri_normals = json_object_get(p, "triangle_normals");
    if (!read_points(r, p, "vertices", 0, &m->positions, &m->position_count, &m->position_cap) ||
        !read_points(r, p, "normals", 1, &m->normals, &m->normal_count, &m->normal_cap) ||
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
    m->triangles = mem_calloc(r->L->mem, n, sizeof *m->triangles);
    if (!m->triangles) {
        loader_oom(r->L);
        return 0;
    }
    m->triangle_cap = m->triangle_count = (int)n;
    for (size_t i = 0; i < n; i++) {
        m->triangles[i].where = src_span_none();
        if (!read_triangle(r, tris, json_is_array(tri_normals) ? tri_normals : NULL, i, m, &m->triangles[i]))
            return 0;
    }
    return 1;
}

static int file_mesh(jreader *r, json_t *p, obj_mesh *m)
{
    const char *name;
    int file;
    if (!jread_string(r, p, "file", 0, &name) || !loader_read_obj(r->L, name, jread_span(r, "file"), &file))
        return 0;
    int parsed = obj_parse(&r->L->scene->sources, file, &r->L->diag, r->L->limits->max_mesh_triangles, m);
    if (parsed < 0)
        r->L->out_of_memory = 1; /* obj_parse said so at the place it ran out */
    return parsed > 0;
}

/* Triangle i of m as a primitive; an inline triangle reports at its entry
 * of "triangles", a file's at its `f` line. */
static int emit_triangle(jreader *r, const obj_mesh *m, int i, const scene_prim *proto)
{
    const obj_triangle *t = &m->triangles[i];
    scene_prim prim = *proto;
    int from_file = t->where.file >= 0;
    check_at at = check_at_fixed(&t->where);
    if (from_file)
        prim.where = t->where;
    else {
        jread_push_key(r, "triangles");
        jread_push_index(r, (size_t)i);
        at = jread_at(r);
    }
    prim.u.triangle.has_normals = t->vn[0] >= 0;
    int ok = 1;
    for (int k = 0; k < 3; k++) {
        prim.u.triangle.p[k] = m->positions[t->v[k]];
        if (prim.u.triangle.has_normals) {
            prim.u.triangle.n[k] = m->normals[t->vn[k]];
            ok = ok && (!from_file || check_unit(r->L, &at, KW_NORMAL, "normal", prim.u.triangle.n[k]));
        }
    }
    ok = ok && check_placed(r->L, &at, &prim);
    if (!from_file) {
        jread_pop(r);
        jread_pop(r);
    }
    scene_prim *slot = ok ? loader_add_prim(r->L, prim.where) : NULL;
    if (slot)
        *slot = prim;
    return slot != NULL;
}

static int emit_mesh(jreader *r, json_t *p, const obj_mesh *m, scene_prim *proto)
{
    const char *source = NULL;
    json_t *file = json_object_get(p, "file");
    if (!jread_string(r, p, "source", 1, &source))
        return 0;
    scene_mesh *mesh = loader_add_mesh(r->L);
    if (!mesh)
        return 0;
    const char *path = source ? source : json_is_string(file) ? json_string_value(file)
                                                               : r->L->scene->sources.files[r->file]->path;
    mesh->path = loader_strdup(r->L, path);
    mesh->where = proto->where;
    mesh->first_prim = r->L->scene->prim_count;
    proto->kind = PRIM_TRIANGLE;
    proto->mesh = r->L->scene->mesh_count - 1;
    int ok = mesh->path != NULL;
    for (int i = 0; ok && i < m->triangle_count && !diag_too_many(&r->L->diag); i++)
        ok = emit_triangle(r, m, i, proto);
    r->L->scene->meshes[proto->mesh].count = r->L->scene->prim_count - r->L->scene->meshes[proto->mesh].first_prim;
    return ok;
}

int load_json_mesh(jreader *r, json_t *p, scene_prim *proto)
{
    static const char *const inline_keys[] = {"kind", "material", "source", "vertices", "normals", "triangles",
                                              "triangle_normals", NULL};
    static const char *const file_keys[] = {"kind", "material", "source", "file", NULL};
    obj_mesh m;
    memset(&m, 0, sizeof m);
    m.mem = *r->L->mem;
    int from_file = json_object_get(p, "file") != NULL;
    int ok = jread_known(r, p, from_file ? file_keys : inline_keys) &&
             (from_file ? file_mesh(r, p, &m) : inline_mesh(r, p, &m)) && emit_mesh(r, p, &m, proto);
    obj_free(&m);
    return ok;
}
