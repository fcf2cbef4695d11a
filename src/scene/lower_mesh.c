/*
 * lower_mesh.c - a mesh read from a file (a polymesh) becomes the scene's
 * compact world-space store (scene_trimesh) and one PRIM_MESH primitive.
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

/* The reader's positions, mapped by w in place (w NULL: kept as read) and
 * taken over (unused ones too: range is checked per triangle, so an unused
 * far vertex does not matter). */
static void world_positions(polymesh *pm, const xform *w, scene_trimesh *g)
{
    for (int i = 0; w && i < pm->position_count; i++)
        pm->positions[i] = xform_point(w, pm->positions[i]);
    g->positions = pm->positions;
    g->position_count = pm->position_count;
    g->position_cap = pm->position_cap;
    pm->positions = NULL;
    pm->position_count = pm->position_cap = 0;
}

/* The reader's normals through the inverse transpose, made unit (l NULL:
 * kept as read, already checked to be unit), taken over; one that cannot
 * be (zero or not finite) becomes zero, refused if a triangle uses it. */
static void world_normals(polymesh *pm, const xform *l, scene_trimesh *g)
{
    for (int i = 0; l && i < pm->normal_count; i++)
        if (!loader_unit(xform_normal(l, pm->normals[i]), &pm->normals[i]))
            pm->normals[i] = vec_splat(0);
    g->normals = pm->normals;
    g->normal_count = pm->normal_count;
    g->normal_cap = pm->normal_cap;
    pm->normals = NULL;
    pm->normal_count = pm->normal_cap = 0;
}

static int usable_corners(const scene_trimesh *g, const int *c)
{
    vec3 a = g->positions[c[0]], b = g->positions[c[1]], d = g->positions[c[2]];
    return vec_is_finite(a) && vec_is_finite(b) && vec_is_finite(d) && vec_is_finite(vec_sub(b, a)) &&
           vec_is_finite(vec_sub(d, a)) && vec_is_finite(vec_sub(d, b));
}

/* Whether triangle k uses a normal that could not be made unit (reported). */
static int bad_normal(loader *L, int file, const polymesh *pm, const scene_trimesh *g, int k)
{
    for (int i = 0; pm->tri_normal && i < 3; i++) {
        int n = pm->tri_normal[k][i];
        if (n >= 0 && vec_length2(g->normals[n]) == 0) {
            diag_report(&L->diag, DIAG_ERROR, face_span(file, pm->tri_at[k]), "vertex normal of zero length");
            return 1;
        }
    }
    return 0;
}

static void swap_corners(int *c)
{
    int t = c[1];
    c[1] = c[2];
    c[2] = t;
}

/* Keeps the triangles with area, in file order, moving them down in the
 * reader's arrays, and takes those over; the others are counted in
 * *dropped.  A mirroring transform swaps corners 1 and 2 of each. */
static void keep_triangles(loader *L, polymesh *pm, int file, int mirrored, scene_trimesh *g, polymesh_tally *dropped)
{
    int kept = 0;
    for (int k = 0; k < pm->triangle_count && !diag_too_many(&L->diag); k++) {
        const int *c = pm->tri[k];
        if (!usable_corners(g, c)) {
            diag_report(&L->diag, DIAG_ERROR, face_span(file, pm->tri_at[k]),
                        "this face is out of range after the mesh's transforms: a coordinate passes the largest "
                        "number (about 1.8e308)");
            continue;
        }
        if (check_degenerate(g->positions[c[0]], g->positions[c[1]], g->positions[c[2]])) {
            if (dropped->count++ == 0)
                dropped->first_at = pm->tri_at[k];
            continue;
        }
        const vec3 corners[3] = {g->positions[c[0]], g->positions[c[1]], g->positions[c[2]]};
        if (!check_face_extent(L, face_span(file, pm->tri_at[k]), corners) || bad_normal(L, file, pm, g, k))
            continue;
        memmove(pm->tri[kept], pm->tri[k], sizeof pm->tri[k]);
        if (pm->tri_normal)
            memmove(pm->tri_normal[kept], pm->tri_normal[k], sizeof pm->tri_normal[k]);
        if (mirrored) {
            swap_corners(pm->tri[kept]);
            if (pm->tri_normal)
                swap_corners(pm->tri_normal[kept]);
        }
        kept++;
    }
    g->tri = pm->tri;
    g->tri_normal = pm->tri_normal;
    g->tri_count = kept;
    g->tri_cap = pm->tri_cap;
    g->tri_normal_cap = pm->tri_normal_cap;
    pm->tri = NULL;
    pm->tri_normal = NULL;
    pm->triangle_count = pm->tri_cap = pm->tri_normal_cap = 0;
}

/* Gives back what the reader's doubling arrays hold beyond their counts
 * (up to half of them).  A failed shrink keeps the array as it is. */
static void *fit(const mem *m, void *array, int *cap, int count, size_t size)
{
    void *fitted = array && count > 0 && count < *cap ? mem_resize_array(m, array, (size_t)*cap, (size_t)count, size)
                                                      : NULL;
    if (!fitted)
        return array;
    *cap = count;
    return fitted;
}

static void fit_arrays(const mem *m, scene_trimesh *g)
{
    g->positions = fit(m, g->positions, &g->position_cap, g->position_count, sizeof *g->positions);
    g->normals = fit(m, g->normals, &g->normal_cap, g->normal_count, sizeof *g->normals);
    g->tri = fit(m, g->tri, &g->tri_cap, g->tri_count, sizeof *g->tri);
    g->tri_normal = fit(m, g->tri_normal, &g->tri_normal_cap, g->tri_count, sizeof *g->tri_normal);
}

/* One warning for a tally of faces, at the mesh statement, naming the
 * first face: "<verb> N face(s) <what>; the first at x.obj:L:C". */
static void warn_tally(loader *L, const scene_mesh *m, int file, polymesh_tally t, const char *verb, const char *what)
{
    char first[600];
    if (t.count == 0)
        return;
    face_place(L, file, t.first_at, first, sizeof first);
    diag_report(&L->diag, DIAG_WARNING, m->where, "%s %d face%s %s; the first at %s", verb, t.count,
                t.count == 1 ? "" : "s", what, first);
}

/* [MESH-WARN-1] The warnings about faces. */
static void report_faces(loader *L, const scene_mesh *m, int file, const polymesh *pm, polymesh_tally dropped)
{
    warn_tally(L, m, file, dropped, "dropped", "with no area (corners on one line, or repeated)");
    warn_tally(L, m, file, pm->nonplanar, "cut",
               "on a plane that does not hold all their corners (one is off the best-fitting plane by more than "
               "1e-4 of the face's size)");
    warn_tally(L, m, file, pm->fanned, "cut",
               "as a fan (the polygon crosses itself, or the ear-clipping budget ran out)");
}

/* [MESH-WARN-2] The warnings about the surface as a whole. */
static void report_surface(loader *L, const scene_mesh *m, double t)
{
    const scene_mesh_report *r = &m->report;
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
static int analyse(loader *L, scene_mesh *m)
{
    mesh_topo topo;
    size_t bytes = (size_t)m->geom.tri_count;
    unsigned char *open = mem_alloc(L->mem, bytes);
    if (!open || !mesh_topo_analyse(&m->geom, L->mem, &topo, open)) {
        mem_free(L->mem, open, bytes);
        loader_oom(L);
        return 0;
    }
    if (topo.open_edges > 0)
        m->geom.open = open;
    else
        mem_free(L->mem, open, bytes);
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

int lower_mesh(loader *L, polymesh *pm, int file, scene_source *held, src_span at, scene_prim *proto,
               const xform *w, const xform *l)
{
    if (!within_limit(L, pm, at))
        return 0;
    scene_mesh *m = loader_add_mesh(L);
    if (!m)
        return 0;
    int index = L->scene->mesh_count - 1, errors = L->diag.errors;
    polymesh_tally dropped = {0, 0};
    m->where = at;
    m->prim = -1;
    m->path = mem_strdup(L->mem, L->scene->sources.files[file]->path);
    if (!m->path) {
        loader_oom(L);
        return 0;
    }
    m->report.faces = pm->face_count;
    world_positions(pm, w, &m->geom);
    world_normals(pm, l, &m->geom);
    keep_triangles(L, pm, file, w && lower_mirrors(w), &m->geom, &dropped);
    fit_arrays(L->mem, &m->geom);
    if (L->diag.errors != errors)
        return 0;
    dropped = all_dropped(pm, dropped);
    m->report.dropped = dropped.count;
    m->report.nonplanar = pm->nonplanar.count;
    m->report.fanned = pm->fanned.count;
    if (m->geom.tri_count == 0) {
        diag_report(&L->diag, DIAG_ERROR, at, "mesh has no triangle with area: all %d of its faces were dropped",
                    m->report.faces);
        return 0;
    }
    report_faces(L, m, file, pm, dropped);
    if (!analyse(L, m))
        return 0;
    /* No message points into the file from here on: its text can go.  Not
     * before the topology has freed its scratch: glibc's malloc raises its
     * threshold for mapping blocks when a large mapped block is freed, and
     * the scratch allocated after that would stay in its heap (measured:
     * 28 MB more at the peak for a million triangles). */
    if (held)
        loader_release_mesh(L, file, held);
    report_surface(L, m, L->scene->materials[proto->material].t);
    L->mesh_triangles += m->geom.tri_count;
    proto->kind = PRIM_MESH;
    proto->mesh = index;
    proto->u.mesh = m->geom;
    scene_prim *slot = loader_add_prim(L, proto->where);
    if (!slot)
        return 0;
    *slot = *proto;
    L->scene->meshes[index].prim = L->scene->prim_count - 1;
    return 1;
}
