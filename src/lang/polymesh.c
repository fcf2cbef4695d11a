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
    free(m->triangles);
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
    polymesh_tri *t = grow(m->triangles, &m->triangle_cap, (long)m->triangle_count + made, sizeof *t,
                           m->max_triangles);
    if (!t && made > 0)
        return POLYMESH_NO_MEMORY;
    if (t)
        m->triangles = t;
    for (int k = 0; k < made; k++) {
        polymesh_tri *tri = &m->triangles[m->triangle_count++];
        for (int i = 0; i < 3; i++) {
            int c = m->cuts[k][i];
            tri->v[i] = v[c];
            tri->vn[i] = vn ? vn[c] : -1;
        }
        tri->at = at;
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
