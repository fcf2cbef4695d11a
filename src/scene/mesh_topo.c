/*
 * mesh_topo.c - closed, oriented, pieces (see mesh_topo.h).
 *
 * Two hash tables with open addressing and linear probing, each at most
 * half full: positions to the first vertex index with that position, and
 * undirected edges to the first half-edge (3 t + k: corner k to corner
 * k + 1 of triangle t) found on them.  A second half-edge on an edge pairs
 * with the first; a third marks the edge crowded.  Pieces come from a
 * union-find over the paired triangles.
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
static int *table_new(size_t n, size_t *mask)
{
    size_t size = 16;
    while (size < 2 * n && size < SIZE_MAX / 4 / sizeof(int))
        size *= 2;
    int *t = malloc(size * sizeof *t);
    if (t)
        memset(t, 0xff, size * sizeof *t);
    *mask = size - 1;
    return t;
}

/* canon[i]: the first vertex with the position of vertex i. */
static int weld(const rf_trimesh *m, int *canon)
{
    size_t mask;
    int *slot = table_new((size_t)m->position_count, &mask);
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
    free(slot);
    return 1;
}

typedef struct edges {
    const rf_trimesh *m;
    const int *canon;
    int *nbr;          /* per half-edge: its partner, UNPAIRED or CROWDED */
} edges;

static int from_of(const edges *e, int h)
{
    return e->canon[e->m->tri[h / 3][h % 3]];
}

static int to_of(const edges *e, int h)
{
    return e->canon[e->m->tri[h / 3][(h % 3 + 1) % 3]];
}

static int same_edge(const edges *e, int g, int h)
{
    int a = from_of(e, g), b = to_of(e, g), c = from_of(e, h), d = to_of(e, h);
    return (a == c && b == d) || (a == d && b == c);
}

static uint64_t edge_hash(int a, int b)
{
    uint64_t lo = (uint64_t)(a < b ? a : b), hi = (uint64_t)(a < b ? b : a);
    return mix(hi << 32 | lo);
}

/* Pairs the half-edges; counts the edges with three or more in *crowded. */
static int pair_edges(edges *e, int *crowded)
{
    size_t mask, half = 3 * (size_t)e->m->tri_count;
    int *slot = table_new(half, &mask);
    if (!slot)
        return 0;
    *crowded = 0;
    for (size_t h = 0; h < half; h++) {
        int hi = (int)h;
        size_t k = (size_t)edge_hash(from_of(e, hi), to_of(e, hi)) & mask;
        while (slot[k] >= 0 && !same_edge(e, slot[k], hi))
            k = (k + 1) & mask;
        int first = slot[k];
        if (first < 0) {
            slot[k] = hi;
        } else if (e->nbr[first] == UNPAIRED) {
            e->nbr[first] = hi;
            e->nbr[hi] = first;
        } else {
            if (e->nbr[first] >= 0) {
                e->nbr[e->nbr[first]] = CROWDED;
                e->nbr[first] = CROWDED;
                (*crowded)++;
            }
            e->nbr[hi] = CROWDED;
        }
    }
    free(slot);
    return 1;
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
    int *parent = malloc((size_t)(n > 0 ? n : 1) * sizeof *parent);
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
    free(parent);
    return 1;
}

int mesh_topo_analyse(const rf_trimesh *m, mesh_topo *out, unsigned char *open)
{
    memset(out, 0, sizeof *out);
    if (open)
        memset(open, 0, (size_t)m->tri_count);
    size_t half = 3 * (size_t)m->tri_count;
    int *canon = malloc((size_t)(m->position_count > 0 ? m->position_count : 1) * sizeof *canon);
    int *nbr = malloc((half > 0 ? half : 1) * sizeof *nbr);
    edges e = {m, canon, nbr};
    int ok = canon && nbr && weld(m, canon);
    if (ok) {
        for (size_t h = 0; h < half; h++)
            nbr[h] = UNPAIRED;
        ok = pair_edges(&e, &out->crowded_edges) && summarise(&e, out, open);
    }
    free(canon);
    free(nbr);
    if (!ok) {
        memset(out, 0, sizeof *out);
        return 0;
    }
    out->closed = out->open_edges == 0 && out->crowded_edges == 0;
    return 1;
}
