/*
 * mesh_topo.h - how a mesh's triangles fit together: whether it is closed
 * and consistently oriented, and how many pieces it has
 * (spec/language.md, section 8, [MESH-CLOSED-1]).
 *
 * Vertices are matched by position, not by index: two corners are the same
 * vertex when their world coordinates are equal (the watertight hit test
 * sees only coordinates, so a file that repeats a position under two
 * indices still makes a closed surface).  An edge is a pair of distinct
 * vertices; a mesh is closed when every edge of every triangle is shared by
 * exactly two triangles, and consistently oriented when every edge shared
 * by two runs from a to b in one and from b to a in the other.
 */
#ifndef REFRAY_MESH_TOPO_H
#define REFRAY_MESH_TOPO_H

#include "scene/scene.h"

typedef struct mesh_topo {
    int closed;
    int oriented;      /* over the edges shared by exactly two triangles */
    int components;    /* pieces connected through edges shared by two */
    int open_edges;    /* edges of one triangle only */
    int crowded_edges; /* edges of three or more triangles */
} mesh_topo;

/* Fills *out for the triangles of m, and when open is not NULL sets bit k
 * of open[t] for each edge (corner k to k + 1 of triangle t) that belongs
 * to t alone.  Returns 1, or 0 when out of memory (*out is then zero).
 * Linear time and memory in the triangle count; the scratch comes from
 * mm (NULL: the C library) and is freed before the return. */
int mesh_topo_analyse(const scene_trimesh *m, const mem *mm, mesh_topo *out, unsigned char *open);

#endif
