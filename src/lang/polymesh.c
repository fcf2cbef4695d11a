/*
 * polymesh.c - the mesh both readers fill (see polymesh.h).
 *
 * Arrays grow by doubling with their limit and size_t overflow checked
 * first; triangles never get room beyond max_triangles.
 */
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "lang/polymesh.h"

void polymesh_init(polymesh *m, long max_triangles)
{
    memset(m, 0, sizeof *m);
    m->max_triangles = max_triangles < 0 ? 0 : max_triangles > INT_MAX ? INT_MAX : max_triangles;
    polygon_work_init(&m->work);
}

void polymesh_free(polymesh *m)
{
    free(m->positions);
    free(m->normals);
    free(m->tri);
    free(m->tri_normal);
    free(m->tri_at);
    free(m->cuts);
    free(m->corners);
    polygon_work_free(&m->work);
    memset(m, 0, sizeof *m);
}

/* Returns array grown to hold at least `need` elements of `size` bytes (its
 * capacity *cap doubling, capped at limit), or NULL when need exceeds limit,
 * the byte count would overflow, or realloc fails; array stays valid then. */
static void *grow(void *array, int *cap, long need, size_t size, long limit)
{
    if (need <= *cap)
        return array;
    if (need > limit)
        return NULL;
    long n = *cap > 0 ? *cap : 16;
    while (n < need)
        n = n > limit / 2 ? limit : 2 * n;
    if ((size_t)n > SIZE_MAX / size)
        return NULL;
    void *grown = realloc(array, (size_t)n * size);
    if (grown)
        *cap = (int)n;
    return grown;
}

static int append(vec3 **array, int *count, int *cap, vec3 v)
{
    if (*count == INT_MAX)
        return POLYMESH_TOO_MANY;
    vec3 *a = grow(*array, cap, (long)*count + 1, sizeof *a, INT_MAX);
    if (!a)
        return POLYMESH_NO_MEMORY;
    *array = a;
    a[(*count)++] = v;
    return 1;
}

int polymesh_add_position(polymesh *m, vec3 p)
{
    return append(&m->positions, &m->position_count, &m->position_cap, p);
}

int polymesh_add_normal(polymesh *m, vec3 n)
{
    return append(&m->normals, &m->normal_count, &m->normal_cap, n);
}

static void tally(polymesh_tally *t, size_t at)
{
    if (t->count == 0)
        t->first_at = at;
    t->count += t->count < INT_MAX;
}

/* The polygon's positions into m->corners and room for its cuts. */
static int gather(polymesh *m, const int *v, int n)
{
    if (n > m->cut_cap) {
        vec3 *c = realloc(m->corners, (size_t)n * sizeof *c);
        if (c)
            m->corners = c;
        int(*cuts)[3] = realloc(m->cuts, (size_t)n * sizeof *cuts);
        if (cuts)
            m->cuts = cuts;
        if (!c || !cuts)
            return 0;
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
    if (need <= m->triangle_cap)
        return 1;
    int cap = m->triangle_cap;
    int(*tri)[3] = grow(m->tri, &cap, need, sizeof *m->tri, m->max_triangles);
    if (!tri)
        return 0;
    m->tri = tri;
    int at_cap = m->triangle_cap;
    size_t *at = grow(m->tri_at, &at_cap, need, sizeof *m->tri_at, m->max_triangles);
    if (!at)
        return 0;
    m->tri_at = at;
    if (m->tri_normal) {
        int n_cap = m->triangle_cap;
        int(*tn)[3] = grow(m->tri_normal, &n_cap, need, sizeof *m->tri_normal, m->max_triangles);
        if (!tn)
            return 0;
        m->tri_normal = tn;
    }
    m->triangle_cap = cap;
    return 1;
}

/* The normal-index array, made on the first face with normals (every
 * triangle before it has none). */
static int start_normals(polymesh *m)
{
    if (m->tri_normal)
        return 1;
    m->tri_normal = malloc((size_t)(m->triangle_cap > 0 ? m->triangle_cap : 1) * sizeof *m->tri_normal);
    if (!m->tri_normal)
        return 0;
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
