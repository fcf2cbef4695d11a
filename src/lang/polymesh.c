/*
 * polymesh.c - the mesh both readers fill (see polymesh.h).
 *
 * Arrays grow by doubling with their limit and size_t overflow checked
 * first; triangles never get room beyond max_triangles.
 */
#include <limits.h>
#include <stdint.h>
#include <string.h>
#include "lang/polymesh.h"

void polymesh_init(polymesh *m, long max_triangles, const mem *mm)
{
    memset(m, 0, sizeof *m);
    m->mem = mem_pick(mm);
    m->max_triangles = max_triangles < 0 ? 0 : max_triangles > INT_MAX ? INT_MAX : max_triangles;
    polygon_work_init(&m->work, &m->mem);
}

/* Bytes of the block of one polygon's corners and cuts, for n corners. */
static size_t cut_block(int n)
{
    return (size_t)n * (sizeof(vec3) + sizeof(int[3]));
}

void polymesh_free(polymesh *m)
{
    mem mm = m->mem;
    mem_free(&mm, m->positions, (size_t)m->position_cap * sizeof *m->positions);
    mem_free(&mm, m->normals, (size_t)m->normal_cap * sizeof *m->normals);
    mem_free(&mm, m->tri, (size_t)m->tri_cap * sizeof *m->tri);
    mem_free(&mm, m->tri_normal, (size_t)m->tri_normal_cap * sizeof *m->tri_normal);
    mem_free(&mm, m->tri_at, (size_t)m->tri_at_cap * sizeof *m->tri_at);
    mem_free(&mm, m->corners, cut_block(m->cut_cap));
    polygon_work_free(&m->work);
    memset(m, 0, sizeof *m);
    m->mem = mm;
}

int polymesh_finish(polymesh *m, diag *d, int errors_before, const src_span *no_faces_at, int stopped,
                    int out_of_memory)
{
    if (d->errors == errors_before && m->face_count == 0 && no_faces_at)
        diag_report(d, DIAG_ERROR, *no_faces_at, "mesh has no faces");
    if (d->errors == errors_before && !stopped)
        return 1;
    polymesh_free(m);
    return out_of_memory ? -1 : 0;
}

void *polymesh_grow(const mem *m, void *array, int *cap, long need, size_t size, long limit)
{
    if (need < 1)
        need = 1; /* so that the result is NULL only on failure */
    if (need <= *cap)
        return array;
    if (need > limit)
        return NULL;
    long n = *cap > 0 ? *cap : 16;
    while (n < need)
        n = n > limit / 2 ? limit : 2 * n;
    if ((size_t)n > SIZE_MAX / size)
        return NULL;
    void *grown = mem_resize_array(m, array, (size_t)*cap, (size_t)n, size);
    if (grown)
        *cap = (int)n;
    return grown;
}

static int append(const mem *mm, vec3 **array, int *count, int *cap, vec3 v)
{
    if (*count == INT_MAX)
        return POLYMESH_TOO_MANY;
    vec3 *a = polymesh_grow(mm, *array, cap, (long)*count + 1, sizeof *a, INT_MAX);
    if (!a)
        return POLYMESH_NO_MEMORY;
    *array = a;
    a[(*count)++] = v;
    return 1;
}

int polymesh_add_position(polymesh *m, vec3 p)
{
    return append(&m->mem, &m->positions, &m->position_count, &m->position_cap, p);
}

int polymesh_add_normal(polymesh *m, vec3 n)
{
    return append(&m->mem, &m->normals, &m->normal_count, &m->normal_cap, n);
}

static void tally(polymesh_tally *t, size_t at)
{
    if (t->count == 0)
        t->first_at = at;
    t->count += t->count < INT_MAX;
}

/* The polygon's positions into m->corners and room for its cuts (one
 * block, filled afresh for every polygon: nothing to copy when it grows). */
static int gather(polymesh *m, const int *v, int n)
{
    if (n > m->cut_cap) {
        if ((size_t)n > SIZE_MAX / cut_block(1))
            return 0;
        vec3 *block = mem_alloc(&m->mem, cut_block(n));
        if (!block)
            return 0;
        mem_free(&m->mem, m->corners, cut_block(m->cut_cap));
        m->corners = block;
        m->cuts = (int(*)[3])(void *)(block + n);
        m->cut_cap = n;
    }
    for (int i = 0; i < n; i++)
        m->corners[i] = m->positions[v[i]];
    return 1;
}

/* Room for `need` triangles in every triangle array (the normal indices
 * only once some face has them); 0 when out of memory. */
static int reserve_triangles(polymesh *m, long need)
{
    int(*tri)[3] = polymesh_grow(&m->mem, m->tri, &m->tri_cap, need, sizeof *m->tri, m->max_triangles);
    if (!tri)
        return 0;
    m->tri = tri;
    size_t *at = polymesh_grow(&m->mem, m->tri_at, &m->tri_at_cap, need, sizeof *m->tri_at, m->max_triangles);
    if (!at)
        return 0;
    m->tri_at = at;
    if (m->tri_normal) {
        int(*tn)[3] = polymesh_grow(&m->mem, m->tri_normal, &m->tri_normal_cap, need, sizeof *m->tri_normal,
                                    m->max_triangles);
        if (!tn)
            return 0;
        m->tri_normal = tn;
    }
    return 1;
}

/* The normal-index array, made on the first face with normals (every
 * triangle before it has none). */
static int start_normals(polymesh *m)
{
    if (m->tri_normal)
        return 1;
    int cap = m->tri_cap > 0 ? m->tri_cap : 1;
    m->tri_normal = mem_alloc(&m->mem, (size_t)cap * sizeof *m->tri_normal);
    if (!m->tri_normal)
        return 0;
    m->tri_normal_cap = cap;
    memset(m->tri_normal, 0xff, (size_t)m->triangle_count * sizeof *m->tri_normal);
    return 1;
}

int polymesh_add_face(polymesh *m, const int *v, const int *vn, int n, size_t at)
{
    int flags, made;
    if (n < 3) {
        m->face_count += m->face_count < INT_MAX;
        tally(&m->no_area, at);
        return 1;
    }
    if ((long)n - 2 > m->max_triangles - m->triangle_count)
        return POLYMESH_TOO_MANY;
    if (!gather(m, v, n) || (made = polygon_triangulate(m->corners, n, &m->work, m->cuts, &flags)) < 0)
        return POLYMESH_NO_MEMORY;
    if (!reserve_triangles(m, (long)m->triangle_count + made) || (vn && !start_normals(m)))
        return POLYMESH_NO_MEMORY;
    for (int k = 0; k < made; k++, m->triangle_count++) {
        for (int i = 0; i < 3; i++) {
            int c = m->cuts[k][i];
            m->tri[m->triangle_count][i] = v[c];
            if (m->tri_normal)
                m->tri_normal[m->triangle_count][i] = vn ? vn[c] : -1;
        }
        m->tri_at[m->triangle_count] = at;
    }
    m->face_count += m->face_count < INT_MAX;
    if (flags & POLYGON_NO_AREA)
        tally(&m->no_area, at);
    if (flags & POLYGON_NONPLANAR)
        tally(&m->nonplanar, at);
    if (flags & POLYGON_FANNED)
        tally(&m->fanned, at);
    return 1;
}
