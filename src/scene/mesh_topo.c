/*
 * mesh_topo.c - closed, oriented, pieces (see mesh_topo.h).
 *
 * Vertices are welded by a hash table of positions (open addressing,
 * linear probing, at most half full).  The half-edges (3 t + k: corner k
 * to corner k + 1 of triangle t) are then grouped by their lower welded
 * vertex with a counting sort, and each group, a vertex's few edges, is
 * sorted by the upper vertex: a run of two half-edges is a shared edge, of
 * one an open edge, of three or more a crowded one.  Everything is linear
 * in the triangle count (a vertex of very high degree is sorted by qsort)
 * and walks memory mostly in order.  Pieces come from a union-find over
 * the paired triangles.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "scene/mesh_topo.h"

enum {
    UNPAIRED = -1,   /* nbr[h]: no other half-edge on this edge yet */
    CROWDED = -2     /* nbr[h]: three or more half-edges on this edge */
};

/* splitmix64's finaliser: a cheap hash whose low bits depend on every bit. */
static uint64_t mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* Equal coordinates hash alike: -0 becomes +0, and a long double is hashed
 * through the double it rounds to (equal values round alike). */
static uint64_t coordinate_bits(real x)
{
    double d = (double)x + 0.0;
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

static uint64_t position_hash(vec3 p)
{
    return mix(coordinate_bits(p.x) ^ mix(coordinate_bits(p.y) ^ mix(coordinate_bits(p.z))));
}

static int same_position(vec3 a, vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* A table of at least 2 n slots (a power of two), all -1; NULL when out of
 * memory.  *mask gets the slot count less one. */
static int *table_new(const mem *mm, size_t n, size_t *mask)
{
    size_t size = 16;
    while (size < 2 * n && size < SIZE_MAX / 4 / sizeof(int))
        size *= 2;
    int *t = mem_alloc(mm, size * sizeof *t);
    if (t)
        memset(t, 0xff, size * sizeof *t);
    *mask = size - 1;
    return t;
}

/* canon[i]: the first vertex with the position of vertex i. */
static int weld(const scene_trimesh *m, const mem *mm, int *canon)
{
    size_t mask;
    int *slot = table_new(mm, (size_t)m->position_count, &mask);
    if (!slot)
        return 0;
    for (int i = 0; i < m->position_count; i++) {
        size_t k = (size_t)position_hash(m->positions[i]) & mask;
        while (slot[k] >= 0 && !same_position(m->positions[slot[k]], m->positions[i]))
            k = (k + 1) & mask;
        if (slot[k] < 0)
            slot[k] = i;
        canon[i] = slot[k];
    }
    mem_free(mm, slot, (mask + 1) * sizeof *slot);
    return 1;
}

typedef struct edges {
    const scene_trimesh *m;
    const int *canon;
    int *nbr;          /* per half-edge: its partner, UNPAIRED or CROWDED */
    const mem *mem;    /* where the scratch comes from */
} edges;

static int from_of(const edges *e, int h)
{
    return e->canon[e->m->tri[h / 3][h % 3]];
}

static int to_of(const edges *e, int h)
{
    return e->canon[e->m->tri[h / 3][(h % 3 + 1) % 3]];
}

/* A half-edge with the upper vertex of its edge, for sorting a group. */
typedef struct half {
    int upper;
    int h;
} half;

static int half_order(const void *pa, const void *pb)
{
    const half *a = pa, *b = pb;
    if (a->upper != b->upper)
        return a->upper < b->upper ? -1 : 1;
    return (a->h > b->h) - (a->h < b->h);
}

static void sort_group(half *g, int n)
{
    if (n > 16) {
        qsort(g, (size_t)n, sizeof *g, half_order);
        return;
    }
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && half_order(&g[j - 1], &g[j]) > 0; j--) {
            half t = g[j];
            g[j] = g[j - 1];
            g[j - 1] = t;
        }
}

/* Pairs the half-edges of one group (one lower vertex): runs of equal upper
 * vertex.  Counts crowded edges. */
static void pair_group(edges *e, half *g, int n, int *crowded)
{
    sort_group(g, n);
    for (int i = 0; i < n;) {
        int j = i + 1;
        while (j < n && g[j].upper == g[i].upper)
            j++;
        if (j - i == 2) {
            e->nbr[g[i].h] = g[i + 1].h;
            e->nbr[g[i + 1].h] = g[i].h;
        } else if (j - i > 2) {
            for (int k = i; k < j; k++)
                e->nbr[g[k].h] = CROWDED;
            (*crowded)++;
        }
        i = j;
    }
}

/* start[v] .. start[v + 1]: the half-edges whose lower vertex is v, in
 * list (a counting sort). */
static void group_by_lower(const edges *e, int *start, int *list)
{
    int nv = e->m->position_count, half_count = 3 * e->m->tri_count;
    for (int h = 0; h < half_count; h++) {
        int a = from_of(e, h), b = to_of(e, h);
        start[(a < b ? a : b) + 1]++;
    }
    for (int v = 0; v < nv; v++)
        start[v + 1] += start[v];
    for (int h = 0; h < half_count; h++) {
        int a = from_of(e, h), b = to_of(e, h);
        list[start[a < b ? a : b]++] = h;
    }
    for (int v = nv; v > 0; v--)
        start[v] = start[v - 1];
    start[0] = 0;
}

/* Pairs the half-edges; counts the edges with three or more in *crowded. */
static int pair_edges(edges *e, int *crowded)
{
    int nv = e->m->position_count, widest = 0;
    size_t halves = 3 * (size_t)e->m->tri_count;
    int *start = mem_calloc(e->mem, (size_t)nv + 1, sizeof *start);
    int *list = mem_alloc(e->mem, halves * sizeof *list);
    half *g = NULL;
    int ok = start && list;
    if (ok) {
        group_by_lower(e, start, list);
        for (int v = 0; v < nv; v++)
            widest = start[v + 1] - start[v] > widest ? start[v + 1] - start[v] : widest;
        g = mem_alloc(e->mem, (size_t)widest * sizeof *g);
        ok = g != NULL;
    }
    *crowded = 0;
    for (int v = 0; ok && v < nv; v++) {
        int n = start[v + 1] - start[v];
        for (int i = 0; i < n; i++) {
            int h = list[start[v] + i], a = from_of(e, h), b = to_of(e, h);
            g[i].upper = a < b ? b : a;
            g[i].h = h;
        }
        pair_group(e, g, n, crowded);
    }
    mem_free(e->mem, start, ((size_t)nv + 1) * sizeof *start);
    mem_free(e->mem, list, halves * sizeof *list);
    mem_free(e->mem, g, (size_t)widest * sizeof *g);
    return ok;
}

static int find(int *parent, int t)
{
    while (parent[t] != t) {
        parent[t] = parent[parent[t]];
        t = parent[t];
    }
    return t;
}

/* Open edges, orientation and pieces from the pairing. */
static int summarise(const edges *e, mesh_topo *out, unsigned char *open)
{
    int n = e->m->tri_count;
    int *parent = mem_alloc(e->mem, (size_t)n * sizeof *parent);
    if (!parent)
        return 0;
    for (int t = 0; t < n; t++)
        parent[t] = t;
    out->oriented = 1;
    for (int h = 0; h < 3 * n; h++) {
        int g = e->nbr[h];
        out->open_edges += g == UNPAIRED;
        if (open && g == UNPAIRED)
            open[h / 3] |= (unsigned char)(1u << (h % 3));
        if (g < 0 || g < h)
            continue;
        out->oriented &= from_of(e, h) == to_of(e, g);
        int a = find(parent, h / 3), b = find(parent, g / 3);
        if (a != b)
            parent[a < b ? b : a] = a < b ? a : b;
    }
    for (int t = 0; t < n; t++)
        out->components += find(parent, t) == t;
    mem_free(e->mem, parent, (size_t)n * sizeof *parent);
    return 1;
}

int mesh_topo_analyse(const scene_trimesh *m, const mem *mm, mesh_topo *out, unsigned char *open)
{
    memset(out, 0, sizeof *out);
    if (open)
        memset(open, 0, (size_t)m->tri_count);
    size_t halves = 3 * (size_t)m->tri_count;
    int *canon = mem_alloc(mm, (size_t)m->position_count * sizeof *canon);
    int *nbr = mem_alloc(mm, halves * sizeof *nbr);
    edges e = {m, canon, nbr, mm};
    int ok = canon && nbr && weld(m, mm, canon);
    if (ok) {
        for (size_t h = 0; h < halves; h++)
            nbr[h] = UNPAIRED;
        ok = pair_edges(&e, &out->crowded_edges) && summarise(&e, out, open);
    }
    mem_free(mm, canon, (size_t)m->position_count * sizeof *canon);
    mem_free(mm, nbr, halves * sizeof *nbr);
    if (!ok) {
        memset(out, 0, sizeof *out);
        return 0;
    }
    out->closed = out->open_edges == 0 && out->crowded_edges == 0;
    return 1;
}
