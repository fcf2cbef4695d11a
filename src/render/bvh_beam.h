/*
 * bvh_beam.h - camera-ray beams: the nearest walk of a run of camera rays
 * on a pruned copy of the tree (spec/numerics.md [BVH-BEAM-1]).
 *
 * Every ray of a run shares its origin (the eye), tmin = 0, tmax = +inf
 * and its octant, and its inverse direction lies per axis in [lo, hi]
 * (finite, nonzero).  bvh_beam_prune keeps the nodes some ray of the run
 * may take candidates from, each as the top of its chain of nodes with one
 * kept child (the top's box, the bottom's children or parts), and
 * bvh_beam_intersect walks that tree for a ray of the run: the same
 * candidates as bvh_intersect_ties on the whole tree, in the same order,
 * so the same hit and tie count to the bit; only bvh_stats' counts move.
 */
#ifndef REFRAY_BVH_BEAM_H
#define REFRAY_BVH_BEAM_H

#include "render/bvh.h"

typedef struct bvh_beam {
    vec3 o;            /* the rays' origin */
    vec3 lo, hi;       /* per axis, the least and the largest 1/d */
    int neg[3];        /* the octant: 1/d < 0 on axis k */
} bvh_beam;

/* A pruned tree: nodes[0] is its root; count 0: no ray of the run meets
 * a box; count < 0: none made (use the whole tree). */
typedef struct bvh_beam_tree {
    bvh_node *nodes;   /* owned by the caller, cap entries */
    int cap;
    int count;
} bvh_beam_tree;

/* The beam of rays[0..n-1] in *out; returns 1, or 0 (no beam) when n < 1
 * or a ray differs from the first in its origin's bits, its tmin (0) or
 * tmax (+inf), or its octant, or has a zero or non-finite 1/d. */
int bvh_beam_bounds(const ray *rays, int n, bvh_beam *out);
/* Whether some ray with inverse direction within the beam (and its
 * origin, tmin 0 and tmax +inf) passes slab_box_meets_neg on [lo, hi]:
 * 1 whenever one does (it may pass a box no ray meets). */
int bvh_beam_meets(const bvh_beam *beam, vec3 lo, vec3 hi);
/* Prunes b for the beam into tree; returns 1, or 0 when b is exhaustive
 * or the nodes kept would pass tree->cap (then count is -1). */
int bvh_beam_prune(const bvh *b, const bvh_beam *beam, bvh_beam_tree *tree);
/* bvh_intersect_ties for a ray of the beam tree was pruned for, on the
 * pruned tree (tree NULL or count < 0: the whole tree). */
int bvh_beam_intersect(const bvh *b, const bvh_beam_tree *tree, const scene_prim *prims, ray *r, hit *h,
                       bvh_stats *stats, int *tied);

#endif
