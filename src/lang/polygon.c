/*
 * polygon.c - ear clipping of mesh faces on their plane (see polygon.h).
 *
 * Invariants: the corners still in the polygon form a ring through
 * next[]/prev[], in the face's order; every cut or removal takes one corner
 * out, so the loops end after at most n removals whatever the input (a
 * self-crossing polygon, every corner on one line, NaN-free but huge
 * coordinates); the 2D coordinates are differences from corner 0 scaled by
 * a power of two to the size of 1, so they say the same at every scale and
 * distance from the origin, and the scaling is exact: every sign and
 * comparison below is the unscaled coordinates' own.
 *
 * The ring the clipping sees has no corner that adds no area ([MESH-POLY-2]):
 * a corner at the same place as the one before it, or the tip of a spike
 * (its two edges on one line, the second going back along the first).
 * Taking such a corner out leaves the region as it was, and an ear test
 * cannot tell one corner of a zero-length edge from the other.
 *
 * Two ear tests ([MESH-POLY-3]).  A polygon whose corners are all at
 * different places (every simple polygon) uses the classic one: the corner
 * turns left and no corner that does not turn left lies in its closed
 * triangle.  One that passes through a place twice (a pinch, a keyhole's
 * bridge) needs more, because a corner there can belong to another part of
 * the polygon: the triangle is an ear when no other edge meets its open
 * inside and the polygon's winding number there is 1.  Then the polygon
 * covers the whole triangle once, and cutting it off leaves exactly the
 * rest of the region.
 */
#include <limits.h>
#include <stdint.h>
#include <string.h>
#include "lang/polygon.h"

#define DEFAULT_BUDGET (1L << 26)

/* Bytes of the block that holds room for n corners. */
static size_t block_size(int n)
{
    return (size_t)n * (2 * sizeof(double) + 3 * sizeof(int));
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
    w->aux = w->prev + n;
    w->cap = n;
    return 1;
}

static double max_abs(vec3 d)
{
    return fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
}

/* The exponent e of the power of two 2^e that holds the largest
 * coordinate of c_i - c_0 in [2^(e-1), 2^e); 0 with *ok 0 when every
 * corner is at c_0 or a difference is not finite. */
static int unit_exponent(const vec3 *at, int n, int *ok)
{
    double m = 0;
    int e = 0;
    for (int i = 1; i < n; i++)
        m = fmax(m, max_abs(vec_sub(at[i], at[0])));
    *ok = m > 0 && isfinite(m);
    if (*ok)
        frexp(m, &e);
    return e;
}

/* c_i - c_0 divided by 2^e: exact, and by ldexp rather than a product
 * with 2^-e, which is not a double for e above 1023 or below -1021. */
static vec3 scaled_offset(const vec3 *at, int i, int e)
{
    vec3 d = vec_sub(at[i], at[0]);
    return vec_make(ldexp(d.x, -e), ldexp(d.y, -e), ldexp(d.z, -e));
}

/* Newell's normal, sum of (c_i - c_0) x (c_i+1 - c_0) with the differences
 * divided by 2^e: twice the vector area over 4^e, exact in direction for a
 * planar polygon, and free of overflow and underflow at any scale. */
static vec3 newell_normal(const vec3 *at, int n, int e)
{
    vec3 sum = vec_splat(0);
    for (int i = 1; i + 1 < n; i++)
        sum = vec_add(sum, vec_cross(scaled_offset(at, i, e), scaled_offset(at, i + 1, e)));
    return sum;
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

/* Projects the corners, divided by 2^e, by dropping axis k of the normal n,
 * ordered so that the polygon winds counter-clockwise in the plane. */
static void project(const vec3 *at, int n, vec3 normal, int e, polygon_work *w)
{
    vec3 a = vec_make(fabs(normal.x), fabs(normal.y), fabs(normal.z));
    int k = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    int i1 = (k + 1) % 3, i2 = (k + 2) % 3;
    if (vec_component(normal, k) < 0) {
        int t = i1;
        i1 = i2;
        i2 = t;
    }
    for (int i = 0; i < n; i++) {
        vec3 d = scaled_offset(at, i, e);
        w->x[i] = vec_component(d, i1);
        w->y[i] = vec_component(d, i2);
    }
}

/* Twice the signed area of the triangle (a, p) in the plane, with p given
 * by its coordinates: > 0 when it turns counter-clockwise. */
static double orient_to(const polygon_work *w, int a, int b, double px, double py)
{
    return (w->x[b] - w->x[a]) * (py - w->y[a]) - (w->y[b] - w->y[a]) * (px - w->x[a]);
}

static double orient(const polygon_work *w, int a, int b, int c)
{
    return orient_to(w, a, b, w->x[c], w->y[c]);
}

static int same_point(const polygon_work *w, int a, int b)
{
    return w->x[a] == w->x[b] && w->y[a] == w->y[b];
}

/* ---- the ring ---------------------------------------------------------- */

static void unlink_corner(polygon_work *w, int v)
{
    w->next[w->prev[v]] = w->next[v];
    w->prev[w->next[v]] = w->prev[v];
}

/* Whether corner v adds no area: at the place of the corner before it, or
 * the tip of a spike (its edges on one line, pointing apart from v). */
static int adds_nothing(const polygon_work *w, int v)
{
    int p = w->prev[v], q = w->next[v];
    if (same_point(w, p, v))
        return 1;
    double turn = (w->x[v] - w->x[p]) * (w->x[q] - w->x[v]) + (w->y[v] - w->y[p]) * (w->y[q] - w->y[v]);
    return orient(w, p, v, q) == 0 && turn < 0;
}

/*
 * Takes the corners that add no area out of the ring, walking it from v
 * until `clean` corners in a row stayed (the whole ring when it starts;
 * 2 after a cut, which changed the neighbours of two corners only).  A
 * removal changes the neighbours of the corners on either side, so the
 * walk steps back to the one before and looks at both again.  Returns
 * the first corner of the last clean run.
 */
static int settle(polygon_work *w, int v, int *left, int clean)
{
    int stayed = 0, anchor = v;
    while (*left >= 3 && stayed < (clean < *left ? clean : *left)) {
        if (adds_nothing(w, v)) {
            int p = w->prev[v];
            unlink_corner(w, v);
            (*left)--;
            v = p;
            stayed = 0;
            continue;
        }
        if (stayed++ == 0)
            anchor = v;
        v = w->next[v];
    }
    return *left >= 3 ? anchor : v;
}

/* The ring of the n corners with every run of corners at one place
 * written once (its first corner kept, corner 0 for a run that wraps
 * round), then settled; returns the corners left. */
static int make_ring(polygon_work *w, int n)
{
    int last = 0, left = n;
    for (int i = 0; i < n; i++) {
        w->next[i] = (i + 1) % n;
        w->prev[i] = (i + n - 1) % n;
    }
    for (int i = 1; i < n; i++) {
        if (same_point(w, i, last)) {
            unlink_corner(w, i);
            left--;
        } else {
            last = i;
        }
    }
    if (last != 0 && same_point(w, last, 0)) {
        unlink_corner(w, last);
        left--;
    }
    if (left >= 3)
        settle(w, 0, &left, left);
    return left;
}

/* aux[i] = 1 for the corners in the ring (from `first`), 0 for the others:
 * what the fan falls back on when the clipping has used the ring up. */
static void mark_ring(polygon_work *w, int n, int first)
{
    memset(w->aux, 0, (size_t)n * sizeof *w->aux);
    int v = first;
    do {
        w->aux[v] = 1;
        v = w->next[v];
    } while (v != first);
}

/* Whether the ring from `first` (of `left` corners) passes through some
 * place twice: its corners sorted by (x, y) in aux (a heap sort: no
 * recursion, no extra room), then neighbours compared. */
static int before(const polygon_work *w, int a, int b)
{
    return w->x[a] < w->x[b] || (w->x[a] == w->x[b] && w->y[a] < w->y[b]);
}

static void sift_down(const polygon_work *w, int *h, int root, int size)
{
    for (int child; (child = 2 * root + 1) < size; root = child) {
        if (child + 1 < size && before(w, h[child], h[child + 1]))
            child++;
        if (!before(w, h[root], h[child]))
            return;
        int t = h[root];
        h[root] = h[child];
        h[child] = t;
    }
}

static int passes_twice(polygon_work *w, int first, int left)
{
    int *h = w->aux, v = first;
    for (int i = 0; i < left; i++, v = w->next[v])
        h[i] = v;
    for (int i = left / 2 - 1; i >= 0; i--)
        sift_down(w, h, i, left);
    for (int size = left - 1; size > 0; size--) {
        int t = h[0];
        h[0] = h[size];
        h[size] = t;
        sift_down(w, h, 0, size);
    }
    for (int i = 0; i + 1 < left; i++)
        if (same_point(w, h[i], h[i + 1]))
            return 1;
    return 0;
}

/* ---- convex polygons -------------------------------------------------- */

/* Convex with every corner turning strictly left and the boundary going
 * round once (the edge directions change the sign of x and of y at most
 * twice each: a pentagram turns left everywhere but goes round twice). */
static int strictly_convex(const polygon_work *w, int first)
{
    int flips_x = 0, flips_y = 0, sx = 0, sy = 0, i = first;
    do {
        int j = w->next[i], k = w->next[j];
        if (!(orient(w, i, j, k) > 0))
            return 0;
        double dx = w->x[j] - w->x[i], dy = w->y[j] - w->y[i];
        int s = (dx > 0) - (dx < 0), t = (dy > 0) - (dy < 0);
        flips_x += s != 0 && sx != 0 && s != sx;
        flips_y += t != 0 && sy != 0 && t != sy;
        sx = s ? s : sx;
        sy = t ? t : sy;
        i = j;
    } while (i != first);
    return flips_x <= 2 && flips_y <= 2;
}

/* The fan (c0, ck, ck+1) over the corners marked in aux, c0 the first. */
static int fan(const polygon_work *w, int n, int (*out)[3])
{
    int count = 0, apex = -1, last = -1;
    for (int i = 0; i < n; i++) {
        if (!w->aux[i])
            continue;
        if (apex < 0) {
            apex = i;
        } else if (last >= 0) {
            out[count][0] = apex;
            out[count][1] = last;
            out[count][2] = i;
            count++;
        }
        if (i != apex)
            last = i;
    }
    return count;
}

/* ---- ears ------------------------------------------------------------- */

/* Whether corner v of the ring lies in the closed triangle (a, b, c). */
static int inside(const polygon_work *w, int a, int b, int c, int v)
{
    return orient(w, a, b, v) >= 0 && orient(w, b, c, v) >= 0 && orient(w, c, a, v) >= 0;
}

/* The classic test, for a ring whose corners are all at different places:
 * 1 when corner b is an ear, 0 when not, -1 when the budget ran out.  Only
 * corners that do not turn strictly left can lie in an ear's triangle
 * without a reflex one lying there too, so only those are tested. */
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
        if (inside(w, a, b, c, v))
            return 0;
    }
    return 1;
}

/* Whether the edge (p, q) meets the open inside of the counter-clockwise
 * triangle (a, b, c).  Two convex sets are apart exactly when a line along
 * a side of one of them has the open triangle on one side and the edge on
 * the other (or on the line): the triangle's three sides, then the edge's. */
static int meets_inside(const polygon_work *w, int a, int b, int c, int p, int q)
{
    if ((orient(w, a, b, p) <= 0 && orient(w, a, b, q) <= 0) || (orient(w, b, c, p) <= 0 && orient(w, b, c, q) <= 0) ||
        (orient(w, c, a, p) <= 0 && orient(w, c, a, q) <= 0))
        return 0;
    if (same_point(w, p, q))
        return 1;
    double sa = orient(w, p, q, a), sb = orient(w, p, q, b), sc = orient(w, p, q, c);
    return !((sa >= 0 && sb >= 0 && sc >= 0) || (sa <= 0 && sb <= 0 && sc <= 0));
}

/* The ring's winding number about the point (px, py), which lies on none
 * of its edges (Sunday's crossing rule: an upward edge with the point on
 * its left counts +1, a downward one with it on its right -1); INT_MIN
 * when the budget ran out. */
static int winding(polygon_work *w, int start, double px, double py)
{
    int turns = 0, u = start;
    do {
        int v = w->next[u];
        if (--w->budget < 0)
            return INT_MIN;
        if (w->y[u] <= py) {
            if (w->y[v] > py && orient_to(w, u, v, px, py) > 0)
                turns++;
        } else if (w->y[v] <= py && orient_to(w, u, v, px, py) < 0) {
            turns--;
        }
        u = v;
    } while (u != start);
    return turns;
}

/* The test for a ring through some place twice: corner b turns left, no
 * other edge meets the open inside of its triangle (so the winding number
 * is the same all over it), and that winding number is 1.  1, 0, or -1
 * when the budget ran out. */
static int is_ear_weak(polygon_work *w, int b)
{
    int a = w->prev[b], c = w->next[b];
    if (!(orient(w, a, b, c) > 0))
        return 0;
    for (int v = c; v != a; v = w->next[v]) {
        if (--w->budget < 0)
            return -1;
        if (meets_inside(w, a, b, c, v, w->next[v]))
            return 0;
    }
    int turns = winding(w, b, (w->x[a] + w->x[b] + w->x[c]) / 3, (w->y[a] + w->y[b] + w->y[c]) / 3);
    return turns == INT_MIN ? -1 : turns == 1;
}

static void cut(polygon_work *w, int b, int (*out)[3], int *count)
{
    int a = w->prev[b], c = w->next[b];
    out[*count][0] = a;
    out[*count][1] = b;
    out[*count][2] = c;
    (*count)++;
    unlink_corner(w, b);
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

/* Ear clipping proper, from corner b of a ring of `left` corners, with the
 * weak test from the start when `weak`; returns the number of triangles,
 * or -1 when the budget ran out (the caller fans the polygon then). */
static int clip(polygon_work *w, int b, int left, int weak, int (*out)[3], int *flags)
{
    int count = 0, misses = 0;
    while (left > 3) {
        int ear = weak ? is_ear_weak(w, b) : is_ear(w, b);
        if (ear < 0)
            return -1;
        if (!ear && ++misses < left) {
            b = w->next[b];
            continue;
        }
        if (!ear && !weak) {
            /* A full round without a classic ear: the polygon touches
             * itself somewhere.  The weak test is right there too, on a
             * ring settled again (a cut may have left a spike). */
            weak = 1;
            misses = 0;
            b = settle(w, b, &left, left);
            continue;
        }
        if (!ear) {
            /* No ear at all: the polygon crosses itself.  Cut a corner
             * that turns left anyway, or stop when none is left. */
            *flags |= POLYGON_FANNED;
            b = any_convex(w, b, left);
            if (b < 0)
                return count;
        }
        int a = w->prev[b];
        cut(w, b, out, &count);
        left--;
        misses = 0;
        b = weak ? settle(w, a, &left, 2) : a;
    }
    if (left == 3 && orient(w, w->prev[b], b, w->next[b]) > 0)
        cut(w, b, out, &count);
    return count;
}

int polygon_triangulate(const vec3 *at, int n, polygon_work *w, int (*out)[3], int *flags)
{
    *flags = 0;
    if (n == 3) {
        for (int i = 0; i < 3; i++)
            out[0][i] = i;
        return 1;
    }
    int ok, e = unit_exponent(at, n, &ok);
    vec3 normal = newell_normal(at, n, e);
    double len = vec_length(normal);
    if (!ok || !(len > 0) || !isfinite(len)) {
        *flags = POLYGON_NO_AREA;
        return 0;
    }
    if (nonplanar(at, n, vec_scale(normal, 1 / len)))
        *flags |= POLYGON_NONPLANAR;
    if (!reserve(w, n))
        return -1;
    project(at, n, normal, e, w);
    int left = make_ring(w, n), first = 0;
    if (left < 3) {
        *flags |= POLYGON_NO_AREA;
        return 0;
    }
    for (first = 0; w->next[w->prev[first]] != first; first++)
        ;
    int convex = strictly_convex(w, first);
    int weak = !convex && passes_twice(w, first, left);
    mark_ring(w, n, first);
    if (convex)
        return fan(w, n, out);
    int count = w->budget > 0 ? clip(w, first, left, weak, out, flags) : -1;
    if (count < 0) {
        *flags |= POLYGON_FANNED;
        return fan(w, n, out);
    }
    if (count == 0)
        *flags |= POLYGON_NO_AREA;
    return count;
}
