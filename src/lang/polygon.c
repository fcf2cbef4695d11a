/*
 * polygon.c - ear clipping of mesh faces on their plane (see polygon.h).
 *
 * Invariants: the corners still in the polygon form a ring through
 * next[]/prev[]; every cut removes one corner, so the loop ends after at
 * most n - 3 cuts whatever the input (a self-crossing polygon, every
 * corner on one line, NaN-free but huge coordinates); the 2D coordinates
 * are differences from corner 0, so their size is the polygon's, not its
 * distance from the origin.
 */
#include <stdint.h>
#include <string.h>
#include "lang/polygon.h"

#define DEFAULT_BUDGET (1L << 26)

/* Bytes of the block that holds room for n corners. */
static size_t block_size(int n)
{
    return (size_t)n * (2 * sizeof(double) + 2 * sizeof(int));
}

void polygon_work_init(polygon_work *w, const mem *m)
{
    memset(w, 0, sizeof *w);
    w->budget = DEFAULT_BUDGET;
    w->mem = mem_pick(m);
}

void polygon_work_free(polygon_work *w)
{
    mem m = w->mem;
    mem_free(&m, w->x, block_size(w->cap));
    memset(w, 0, sizeof *w);
    w->mem = m;
}

/* Room for n corners; 0 when out of memory (the old room stays).  The
 * arrays are filled afresh for every polygon, so nothing is copied. */
static int reserve(polygon_work *w, int n)
{
    if (n <= w->cap)
        return 1;
    if ((size_t)n > SIZE_MAX / block_size(1))
        return 0;
    double *block = mem_alloc(&w->mem, block_size(n));
    if (!block)
        return 0;
    long budget = w->budget;
    polygon_work_free(w);
    w->budget = budget;
    w->x = block;
    w->y = block + n;
    w->next = (int *)(void *)(block + 2 * (size_t)n);
    w->prev = w->next + n;
    w->cap = n;
    return 1;
}

/* Newell's normal, sum of (c_i - c_0) x (c_i+1 - c_0): twice the vector
 * area, exact in direction for a planar polygon. */
static vec3 newell_normal(const vec3 *at, int n)
{
    vec3 s = vec_splat(0);
    for (int i = 1; i + 1 < n; i++)
        s = vec_add(s, vec_cross(vec_sub(at[i], at[0]), vec_sub(at[i + 1], at[0])));
    return s;
}

/* Whether a corner lies farther than POLYGON_PLANAR_TOL of the polygon's
 * size from the plane of unit normal u through the corners' mid-range. */
static int nonplanar(const vec3 *at, int n, vec3 u)
{
    vec3 lo = at[0], hi = at[0];
    double dmin = 0, dmax = 0;
    for (int i = 0; i < n; i++) {
        double d = vec_dot(vec_sub(at[i], at[0]), u);
        dmin = d < dmin ? d : dmin;
        dmax = d > dmax ? d : dmax;
        lo = vec_min(lo, at[i]);
        hi = vec_max(hi, at[i]);
    }
    double size = vec_max_component(vec_sub(hi, lo));
    return (dmax - dmin) / 2 > POLYGON_PLANAR_TOL * size;
}

/* Projects the corners by dropping axis k of the normal n, ordered so that
 * the polygon winds counter-clockwise in the plane. */
static void project(const vec3 *at, int n, vec3 normal, polygon_work *w)
{
    vec3 a = vec_make(fabs(normal.x), fabs(normal.y), fabs(normal.z));
    int k = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    int i1 = (k + 1) % 3, i2 = (k + 2) % 3;
    if (vec_component(normal, k) < 0) {
        int s = i1;
        i1 = i2;
        i2 = s;
    }
    for (int i = 0; i < n; i++) {
        vec3 d = vec_sub(at[i], at[0]);
        w->x[i] = vec_component(d, i1);
        w->y[i] = vec_component(d, i2);
    }
}

/* Twice the signed area of the triangle (a, b, c) in the plane: > 0 when
 * it turns counter-clockwise. */
static double orient(const polygon_work *w, int a, int b, int c)
{
    return (w->x[b] - w->x[a]) * (w->y[c] - w->y[a]) - (w->y[b] - w->y[a]) * (w->x[c] - w->x[a]);
}

/* Convex with every corner turning strictly left and the boundary going
 * round once (the edge directions change the sign of x and of y at most
 * twice each: a pentagram turns left everywhere but goes round twice). */
static int strictly_convex(const polygon_work *w, int n)
{
    int flips_x = 0, flips_y = 0, sx = 0, sy = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n, k = (i + 2) % n;
        if (!(orient(w, i, j, k) > 0))
            return 0;
        double dx = w->x[j] - w->x[i], dy = w->y[j] - w->y[i];
        int s = (dx > 0) - (dx < 0), t = (dy > 0) - (dy < 0);
        flips_x += s != 0 && sx != 0 && s != sx;
        flips_y += t != 0 && sy != 0 && t != sy;
        sx = s ? s : sx;
        sy = t ? t : sy;
    }
    return flips_x <= 2 && flips_y <= 2;
}

static int fan(int n, int (*out)[3])
{
    for (int k = 1; k + 1 < n; k++) {
        out[k - 1][0] = 0;
        out[k - 1][1] = k;
        out[k - 1][2] = k + 1;
    }
    return n - 2;
}

static int same_point(const polygon_work *w, int a, int b)
{
    return w->x[a] == w->x[b] && w->y[a] == w->y[b];
}

/* Whether corner v of the ring lies in the closed triangle (a, b, c). */
static int inside(const polygon_work *w, int a, int b, int c, int v)
{
    return orient(w, a, b, v) >= 0 && orient(w, b, c, v) >= 0 && orient(w, c, a, v) >= 0;
}

/* 1 when corner b is an ear, 0 when not, -1 when the budget ran out.  Only
 * corners that do not turn strictly left can lie in an ear's triangle
 * without a reflex one lying there too, so only those are tested; corners
 * at the same place as the ear's own are not in the way. */
static int is_ear(polygon_work *w, int b)
{
    int a = w->prev[b], c = w->next[b];
    if (!(orient(w, a, b, c) > 0))
        return 0;
    for (int v = w->next[c]; v != a; v = w->next[v]) {
        if (--w->budget < 0)
            return -1;
        if (orient(w, w->prev[v], v, w->next[v]) > 0)
            continue;
        if (same_point(w, v, a) || same_point(w, v, b) || same_point(w, v, c))
            continue;
        if (inside(w, a, b, c, v))
            return 0;
    }
    return 1;
}

static void cut(polygon_work *w, int b, int (*out)[3], int *count)
{
    int a = w->prev[b], c = w->next[b];
    out[*count][0] = a;
    out[*count][1] = b;
    out[*count][2] = c;
    (*count)++;
    w->next[a] = c;
    w->prev[c] = a;
}

/* A corner that turns strictly left, searched from b; -1 when none does
 * (what is left has no area). */
static int any_convex(const polygon_work *w, int b, int left)
{
    for (int i = 0; i < left; i++, b = w->next[b])
        if (orient(w, w->prev[b], b, w->next[b]) > 0)
            return b;
    return -1;
}

/* Ear clipping proper; returns the number of triangles, or -1 when the
 * budget ran out (the caller fans the polygon then). */
static int clip(polygon_work *w, int n, int (*out)[3], int *flags)
{
    int count = 0, left = n, b = 0, misses = 0;
    for (int i = 0; i < n; i++) {
        w->next[i] = (i + 1) % n;
        w->prev[i] = (i + n - 1) % n;
    }
    while (left > 3) {
        int ear = is_ear(w, b);
        if (ear < 0)
            return -1;
        if (!ear && ++misses < left) {
            b = w->next[b];
            continue;
        }
        if (!ear) {
            /* A full round without an ear: the polygon crosses itself.
             * Cut a corner that turns left anyway, or stop when none is left. */
            *flags |= POLYGON_FANNED;
            b = any_convex(w, b, left);
            if (b < 0)
                return count;
        }
        int a = w->prev[b];
        cut(w, b, out, &count);
        left--;
        misses = 0;
        b = a;
    }
    if (orient(w, w->prev[b], b, w->next[b]) > 0)
        cut(w, b, out, &count);
    return count;
}

int polygon_triangulate(const vec3 *at, int n, polygon_work *w, int (*out)[3], int *flags)
{
    *flags = 0;
    if (n == 3)
        return fan(n, out);
    vec3 normal = newell_normal(at, n);
    double len = vec_length(normal);
    if (!(len > 0) || !isfinite(len)) {
        *flags = POLYGON_NO_AREA;
        return 0;
    }
    if (nonplanar(at, n, vec_scale(normal, 1 / len)))
        *flags |= POLYGON_NONPLANAR;
    if (!reserve(w, n))
        return -1;
    project(at, n, normal, w);
    if (strictly_convex(w, n))
        return fan(n, out);
    int count = w->budget > 0 ? clip(w, n, out, flags) : -1;
    if (count < 0) {
        *flags |= POLYGON_FANNED;
        return fan(n, out);
    }
    if (count == 0)
        *flags |= POLYGON_NO_AREA;
    return count;
}
