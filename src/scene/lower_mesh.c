/*
 * lower_mesh.c - a mesh read from a file (a polymesh) becomes the scene's
 * compact world-space store (rf_trimesh) and one PRIM_MESH primitive.
 *
 * On the way: the transforms are applied to every position and normal (a
 * mirroring one swaps two corners of every triangle, as for `triangle`),
 * triangles with no area after them are dropped, the surface is analysed
 * (closed? consistently oriented? mesh_topo.h), and what was found is
 * reported once per mesh: a warning that counts the dropped faces, one for
 * non-planar polygons, one for polygons that had to be fanned, one for a
 * transparent mesh that is not closed (refracted as sheets), one for a
 * closed mesh wound inconsistently.  Only a mesh left with no triangle is
 * an error (spec/language.md, section 8).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene/loader.h"
#include "scene/mesh_topo.h"

/* "x.obj:12:1", where a face of the mesh's file starts. */
static void face_place(const loader *L, int file, size_t at, char *out, size_t size)
{
    const source_file *f = L->scene->sources.files[file];
    int line, col;
    source_line_col(f, at, &line, &col);
    snprintf(out, size, "%s:%d:%d", f->path, line, col);
}

static src_span face_span(int file, size_t at)
{
    src_span s;
    s.file = file;
    s.begin = at;
    s.end = at + 1;
    return s;
}

static void *array_of(size_t count, size_t size)
{
    return malloc((count > 0 ? count : 1) * size);
}

/* Every position mapped by w (unused ones too; range is checked per
 * triangle, so an unused far vertex does not matter). */
static int world_positions(loader *L, const polymesh *pm, const xform *w, rf_trimesh *g)
{
    g->positions = array_of((size_t)pm->position_count, sizeof *g->positions);
    if (!g->positions) {
        loader_oom(L);
        return 0;
    }
    for (int i = 0; i < pm->position_count; i++)
        g->positions[i] = xform_point(w, pm->positions[i]);
    g->position_count = pm->position_count;
    return 1;
}

/* Every normal through the inverse transpose, made unit; one that cannot be
 * (zero or not finite) is stored as zero and refused if a triangle uses it. */
static int world_normals(loader *L, const polymesh *pm, const xform *l, rf_trimesh *g)
{
    if (pm->normal_count == 0)
        return 1;
    g->normals = array_of((size_t)pm->normal_count, sizeof *g->normals);
    if (!g->normals) {
        loader_oom(L);
        return 0;
    }
    for (int i = 0; i < pm->normal_count; i++)
        if (!loader_unit(xform_normal(l, pm->normals[i]), &g->normals[i]))
            g->normals[i] = vec_splat(0);
    g->normal_count = pm->normal_count;
    return 1;
}

static int usable_corners(const rf_trimesh *g, const polymesh_tri *t)
{
    vec3 a = g->positions[t->v[0]], b = g->positions[t->v[1]], c = g->positions[t->v[2]];
    return vec_is_finite(a) && vec_is_finite(b) && vec_is_finite(c) && vec_is_finite(vec_sub(b, a)) &&
           vec_is_finite(vec_sub(c, a)) && vec_is_finite(vec_sub(c, b));
}

/* Copies triangle t into slot k (corners 1 and 2 swapped when mirrored);
 * 0 after reporting a normal it uses that cannot be made unit. */
static int keep_triangle(loader *L, int file, const polymesh_tri *t, int mirrored, rf_trimesh *g, int k)
{
    static const int order[2][3] = {{0, 1, 2}, {0, 2, 1}};
    const int *o = order[mirrored];
    for (int i = 0; i < 3; i++)
        g->tri[k][i] = t->v[o[i]];
    if (!g->tri_normal)
        return 1;
    for (int i = 0; i < 3; i++) {
        int n = t->vn[o[i]];
        g->tri_normal[k][i] = n;
        if (n >= 0 && vec_length2(g->normals[n]) == 0) {
            diag_report(&L->diag, DIAG_ERROR, face_span(file, t->at), "vertex normal of zero length");
            return 0;
        }
    }
    return 1;
}

/* The triangles with area, in file order; the others counted in *dropped. */
static int keep_triangles(loader *L, const polymesh *pm, int file, int mirrored, rf_mesh *m, polymesh_tally *dropped)
{
    rf_trimesh *g = &m->geom;
    size_t n = (size_t)pm->triangle_count;
    g->tri = array_of(n, sizeof *g->tri);
    g->tri_normal = pm->normal_count > 0 ? array_of(n, sizeof *g->tri_normal) : NULL;
    if (!g->tri || (pm->normal_count > 0 && !g->tri_normal)) {
        loader_oom(L);
        return 0;
    }
    for (int i = 0; i < pm->triangle_count && !diag_too_many(&L->diag); i++) {
        const polymesh_tri *t = &pm->triangles[i];
        if (!usable_corners(g, t)) {
            diag_report(&L->diag, DIAG_ERROR, face_span(file, t->at),
                        "this face is out of range after the mesh's transforms: a coordinate passes the largest "
                        "number (about 1.8e308)");
            continue;
        }
        if (lower_degenerate(g->positions[t->v[0]], g->positions[t->v[1]], g->positions[t->v[2]])) {
            if (dropped->count++ == 0)
                dropped->first_at = t->at;
            continue;
        }
        if (keep_triangle(L, file, t, mirrored, g, g->tri_count))
            g->tri_count++;
    }
    return 1;
}

/* One warning for a tally of faces, pointing at the mesh statement and
 * naming the first face. */
static void warn_tally(loader *L, const rf_mesh *m, int file, polymesh_tally t, const char *what)
{
    char first[600];
    if (t.count == 0)
        return;
    face_place(L, file, t.first_at, first, sizeof first);
    diag_report(&L->diag, DIAG_WARNING, m->where, "%d %s%s (the first at %s)", t.count,
                t.count == 1 ? "face " : "faces ", what, first);
}

static void report_findings(loader *L, const rf_mesh *m, int file, const polymesh *pm, polymesh_tally dropped,
                            double t)
{
    const rf_mesh_report *r = &m->report;
    polymesh_tally nonplanar = pm->nonplanar, fanned = pm->fanned;
    warn_tally(L, m, file, dropped, "with no area dropped (their corners are on one line)");
    warn_tally(L, m, file, nonplanar, "not planar (a corner is off the polygon's plane by more than 1e-4 of its "
                                      "size), cut on their best-fit plane");
    warn_tally(L, m, file, fanned, "cut as a fan (the polygon crosses itself, or the ear-clipping budget ran out)");
    if (t > 0 && !m->geom.closed)
        diag_report(&L->diag, DIAG_WARNING, m->where,
                    "this transparent mesh is not closed (%d open edge%s, %d edge%s of 3 or more triangles): it is "
                    "treated as sheets that let light through unbent, not as a solid that refracts",
                    r->open_edges, r->open_edges == 1 ? "" : "s", r->crowded_edges, r->crowded_edges == 1 ? "" : "s");
    if (m->geom.closed && !r->oriented)
        diag_report(&L->diag, DIAG_WARNING, m->where,
                    "the triangles of this closed mesh are not wound consistently; refray does not need them to be "
                    "(it finds a closed mesh's inside by counting crossings), other renderers may");
}

/* The faces dropped by the reader (no area) and here, as one tally. */
static polymesh_tally all_dropped(const polymesh *pm, polymesh_tally here)
{
    polymesh_tally t = pm->no_area;
    if (here.count > 0 && (t.count == 0 || here.first_at < t.first_at))
        t.first_at = here.first_at;
    t.count += here.count;
    return t;
}

/* The topology into the report, and the open-edge masks when some edge
 * is open (NULL for a closed mesh: nothing to keep). */
static int analyse(loader *L, rf_mesh *m)
{
    mesh_topo topo;
    unsigned char *open = array_of((size_t)m->geom.tri_count, 1);
    if (!open || !mesh_topo_analyse(&m->geom, &topo, open)) {
        free(open);
        loader_oom(L);
        return 0;
    }
    if (topo.open_edges > 0)
        m->geom.open = open;
    else
        free(open);
    m->geom.closed = topo.closed;
    m->report.oriented = topo.oriented;
    m->report.components = topo.components;
    m->report.open_edges = topo.open_edges;
    m->report.crowded_edges = topo.crowded_edges;
    return 1;
}

/* Room for the triangles, mesh triangles of the whole load included, within
 * --max-primitives. */
static int within_limit(loader *L, const polymesh *pm, src_span at)
{
    long total = (long)L->scene->prim_count + L->mesh_triangles + pm->triangle_count;
    if (total <= L->limits->max_primitives)
        return 1;
    diag_report(&L->diag, DIAG_ERROR, at, "more than %ld primitives, mesh triangles included (--max-primitives)",
                L->limits->max_primitives);
    return 0;
}

static char *copy_string(const char *s)
{
    char *c = malloc(strlen(s) + 1);
    if (c)
        strcpy(c, s);
    return c;
}

int lower_mesh(loader *L, const polymesh *pm, int file, src_span at, rf_prim *proto, const xform *w,
               const xform *l)
{
    if (!within_limit(L, pm, at))
        return 0;
    rf_mesh *m = loader_add_mesh(L);
    if (!m)
        return 0;
    int index = L->scene->mesh_count - 1, errors = L->diag.errors;
    polymesh_tally dropped = {0, 0};
    m->where = at;
    m->prim = -1;
    m->path = copy_string(L->scene->sources.files[file]->path);
    if (!m->path) {
        loader_oom(L);
        return 0;
    }
    if (!world_positions(L, pm, w, &m->geom) || !world_normals(L, pm, l, &m->geom) ||
        !keep_triangles(L, pm, file, lower_mirrors(w), m, &dropped) || L->diag.errors != errors)
        return 0;
    m->report.faces = pm->face_count;
    dropped = all_dropped(pm, dropped);
    m->report.dropped = dropped.count;
    m->report.nonplanar = pm->nonplanar.count;
    m->report.fanned = pm->fanned.count;
    if (m->geom.tri_count == 0) {
        diag_report(&L->diag, DIAG_ERROR, at, "mesh has no triangle with area: all %d of its faces were dropped",
                    pm->face_count);
        return 0;
    }
    if (!analyse(L, m))
        return 0;
    report_findings(L, m, file, pm, dropped, L->scene->materials[proto->material].t);
    L->mesh_triangles += m->geom.tri_count;
    proto->kind = PRIM_MESH;
    proto->mesh = index;
    proto->u.mesh = m->geom;
    rf_prim *slot = loader_add_prim(L, proto->where);
    if (!slot)
        return 0;
    *slot = *proto;
    L->scene->meshes[index].prim = L->scene->prim_count - 1;
    return 1;
}
