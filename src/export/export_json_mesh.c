/*
 * export_json_mesh.c - a mesh of an exported scene: its triangles (world
 * coordinates, the scene's transforms applied, corners in the order the
 * tracer holds them) as indexed arrays, inline or in an OBJ file.  Equal
 * corners share an index: "equal" means the same bits, so -0 and +0 stay
 * apart and nothing is merged that the tracer would tell apart.  JSON=1
 * builds only.
 */
#include <stdlib.h>
#include <string.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "base/sampler.h"
#include "export/export_json_impl.h"

/* Distinct points in order of first use, found through an open-addressing
 * table of their bits. */
typedef struct point_set {
    double (*items)[3];
    int count;
    int *slots;        /* index + 1 into items, 0 empty */
    size_t mask;       /* slot count - 1, a power of two minus one */
} point_set;

static int set_init(point_set *ps, size_t most)
{
    size_t n = 16;
    while (n < 2 * most)
        n *= 2;
    ps->items = malloc(most ? most * sizeof *ps->items : sizeof *ps->items);
    ps->slots = calloc(n, sizeof *ps->slots);
    ps->count = 0;
    ps->mask = n - 1;
    return ps->items && ps->slots;
}

static void set_free(point_set *ps)
{
    free(ps->items);
    free(ps->slots);
}

static uint64_t bits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* The index of p, added when new. */
static int set_index(point_set *ps, vec3 v)
{
    double p[3] = {(double)v.x, (double)v.y, (double)v.z};
    size_t h = (size_t)sampler_key(sampler_key(bits(p[0]), bits(p[1])), bits(p[2])) & ps->mask;
    for (;; h = (h + 1) & ps->mask) {
        int at = ps->slots[h] - 1;
        if (at < 0)
            break;
        if (memcmp(ps->items[at], p, sizeof p) == 0)
            return at;
    }
    memcpy(ps->items[ps->count], p, sizeof p);
    ps->slots[h] = ++ps->count;
    return ps->count - 1;
}

/* The mesh's corners as indices into positions (and normals). */
typedef struct indexed {
    point_set positions, normals;
    int (*v)[3], (*vn)[3];   /* vn[i][0] < 0: triangle i has no normals */
    int count;
} indexed;

static int index_mesh(const scene_model *s, const scene_mesh *m, indexed *x)
{
    size_t corners = 3 * (size_t)m->count;
    x->count = m->count;
    x->v = malloc(corners * sizeof(int));
    x->vn = malloc(corners * sizeof(int));
    if (!set_init(&x->positions, corners) || !set_init(&x->normals, corners) || !x->v || !x->vn)
        return 0;
    for (int i = 0; i < m->count; i++) {
        const scene_prim *p = &s->prims[m->first_prim + i];
        for (int k = 0; k < 3; k++) {
            x->v[i][k] = set_index(&x->positions, p->u.triangle.p[k]);
            x->vn[i][k] = p->u.triangle.has_normals ? set_index(&x->normals, p->u.triangle.n[k]) : -1;
        }
    }
    return 1;
}

static void index_free(indexed *x)
{
    set_free(&x->positions);
    set_free(&x->normals);
    free(x->v);
    free(x->vn);
}

static json_t *points(export_json_build *b, const point_set *ps)
{
    json_t *out = json_array();
    for (int i = 0; i < ps->count; i++)
        export_json_append(b, out, json_pack("[fff]", ps->items[i][0], ps->items[i][1], ps->items[i][2]));
    return out;
}

static void inline_arrays(export_json_build *b, json_t *out, const indexed *x)
{
    json_t *tris = json_array(), *tri_normals = json_array();
    for (int i = 0; i < x->count; i++) {
        export_json_append(b, tris, json_pack("[iii]", x->v[i][0], x->v[i][1], x->v[i][2]));
        export_json_append(b, tri_normals, x->vn[i][0] < 0 ? json_null()
                                                           : json_pack("[iii]", x->vn[i][0], x->vn[i][1], x->vn[i][2]));
    }
    export_json_set(b, out, "vertices", points(b, &x->positions));
    export_json_set(b, out, "normals", points(b, &x->normals));
    export_json_set(b, out, "triangles", tris);
    export_json_set(b, out, "triangle_normals", tri_normals);
}

static int fill_obj(FILE *fp, void *ctx)
{
    const indexed *x = ctx;
    fprintf(fp, "# refray export: a mesh in world coordinates (spec/json.md, \"Meshes\")\n");
    for (int i = 0; i < x->positions.count; i++)
        fprintf(fp, "v %.17g %.17g %.17g\n", x->positions.items[i][0], x->positions.items[i][1],
                x->positions.items[i][2]);
    for (int i = 0; i < x->normals.count; i++)
        fprintf(fp, "vn %.17g %.17g %.17g\n", x->normals.items[i][0], x->normals.items[i][1], x->normals.items[i][2]);
    for (int i = 0; i < x->count; i++) {
        if (x->vn[i][0] < 0)
            fprintf(fp, "f %d %d %d\n", x->v[i][0] + 1, x->v[i][1] + 1, x->v[i][2] + 1);
        else
            fprintf(fp, "f %d//%d %d//%d %d//%d\n", x->v[i][0] + 1, x->vn[i][0] + 1, x->v[i][1] + 1, x->vn[i][1] + 1,
                    x->v[i][2] + 1, x->vn[i][2] + 1);
    }
    return ferror(fp) ? STATUS_IO : STATUS_OK;
}

/* Writes the OBJ file of mesh m; its reference (mesh_dir/NAME.obj) in *ref. */
static int write_obj(const export_json_opts *o, int m, const indexed *x, char **ref, char *err, size_t errlen)
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
        rc = file_write_atomic(path, fill_obj, (void *)x, err, errlen);
    free(dir);
    free(path);
    return rc;
}

json_t *export_json_mesh(const scene_model *s, int m, const export_json_opts *o, int *status, char *err,
                         size_t errlen)
{
    export_json_build b = {0};
    const scene_mesh *mesh = &s->meshes[m];
    indexed x;
    char *ref = NULL;
    memset(&x, 0, sizeof x);
    if (errlen)
        err[0] = '\0';
    json_t *out = json_object(), *source = json_string(mesh->path);
    export_json_set(&b, out, "kind", json_string("mesh"));
    export_json_set(&b, out, "material", json_integer(s->prims[mesh->first_prim].material));
    export_json_set(&b, out, "source", source ? source : json_null());
    *status = index_mesh(s, mesh, &x) ? STATUS_OK : STATUS_NO_MEMORY;
    if (*status == 0 && o->mesh_dir && (*status = write_obj(o, m, &x, &ref, err, errlen)) == 0)
        export_json_set(&b, out, "file", json_string(ref));
    else if (*status == 0)
        inline_arrays(&b, out, &x);
    free(ref);
    index_free(&x);
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
