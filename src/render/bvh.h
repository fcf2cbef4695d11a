/*
 * bvh.h - a bounding volume hierarchy over a scene's primitives.
 *
 * Every part of a primitive with finite bounds (each triangle of a mesh,
 * every other primitive whole: intersect.h, "Parts") goes into a binary
 * tree of axis-aligned boxes, built by the binned surface area heuristic
 * and stored as one flat node array; the two children of a node sit side
 * by side.  Planes, and anything else without finite bounds, are kept in a
 * list beside the tree and tested on every ray.
 *
 * The tree holds (primitive, part) pairs of the prims array it was built
 * from; the same array must be passed to every query and must not change.
 * Building is deterministic (same prims, same tree) and the nearest hit
 * does not depend on the tree's shape: among the hits within a tie window
 * of the least t (2^-46 (|t| + |origin|), a few dozen ulps: coplanar
 * surfaces) the lowest primitive index wins, then the lowest part, so a
 * disk lying on a plane shows whichever was declared first, never a noise
 * of both (spec/numerics.md, "Coplanar surfaces").
 * Queries allocate nothing and keep no state, so threads may share a tree.
 */
#ifndef REFRAY_BVH_H
#define REFRAY_BVH_H

#include "base/cancel.h"
#include "base/mem.h"
#include "base/status.h"
#include "render/intersect.h"

/* The tree is at most this deep, so traversal uses a fixed stack: past
 * depth BVH_MEDIAN_DEPTH the build splits at the object median, which
 * halves the count and adds at most 31 more levels for 2^31 primitives. */
#define BVH_MAX_DEPTH 96
#define BVH_MEDIAN_DEPTH 64

typedef struct bvh_node {
    vec3 lo, hi;       /* bounds of everything below, widened on every
                          axis by 2^-40 of the largest magnitude
                          ([BVH-CULL-PAD-1], bvh_build.c) */
    int first;         /* leaf: first slot in bvh.items; inner: the first child
                          (the second is first + 1) */
    int count;         /* leaf: number of parts (>= 1); inner: 0 */
} bvh_node;

typedef struct bvh_ref {
    int prim;          /* index into the prims array */
    int part;          /* which part of it (intersect.h) */
} bvh_ref;

typedef struct bvh {
    bvh_node *nodes;   /* nodes[0] is the root; NULL when nothing is bounded */
    int node_count;
    int node_cap;      /* entries allocated in nodes */
    int leaf_count;
    int depth;         /* longest root-to-leaf path, in nodes */
    bvh_ref *items;    /* the parts, each leaf's a contiguous run */
    int item_count;
    size_t item_bytes; /* bytes allocated at items (it was the build's array) */
    bvh_ref *unbounded; /* parts of planes etc.: tested linearly on every ray */
    int unbounded_count;
    int exhaustive;    /* 1: no box culls a ray, every primitive is tested, in
                          the order of the tree (the shortcuts-off mode of
                          spec/shading.md, [SHADE-SHORTCUT-BVH-1]); 0 after
                          bvh_build */
    int unbounded_cap;
    bvh_hot *hot;      /* item_count records, beside items (intersect.h): the
                          reals lie in the parts' order (the primitives'), each
                          record aligned to 32 bytes (a sphere's in one cache
                          line) */
    real *hot_reals;   /* inside hot_block, aligned to 32 bytes */
    void *hot_block;
    size_t hot_block_bytes;
    mem mem;           /* where the arrays live */
} bvh;

/* What one query did, accumulated (the caller zeroes it). */
typedef struct bvh_stats {
    long nodes_visited;    /* nodes whose box was tested */
    long prims_tested;     /* part intersection tests, unbounded ones included */
} bvh_stats;

/* Builds the tree over the parts of prims[0..count-1] in memory from m
 * (NULL: the C library).  Returns 1, or 0 when out of memory, count < 0,
 * or there are more than INT_MAX/2 parts (then *b is empty and bvh_free is
 * still safe).  Nothing of prims is kept but the indices. */
int bvh_build(bvh *b, const scene_prim *prims, int count, const mem *m);
/* The same, counting its work into cancel (NULL: never stopped): returns
 * STATUS_OK, STATUS_NO_MEMORY or STATUS_CANCELLED (then *b is empty). */
int bvh_build_polled(bvh *b, const scene_prim *prims, int count, const mem *m, cancel_poll *cancel);
void bvh_free(bvh *b);

/* The nearest hit in (r->tmin, r->tmax), ties resolved as above: shrinks
 * r->tmax to its t, fills *h including h->prim and h->part, returns 1 on a
 * hit.  On a miss *r and *h are unchanged. */
int bvh_intersect(const bvh *b, const scene_prim *prims, ray *r, hit *h);
/* The same, adding to *stats when it is not NULL. */
int bvh_intersect_stats(const bvh *b, const scene_prim *prims, ray *r, hit *h, bvh_stats *stats);
/* The same, with the number of hits in the tie window in *tied (1: none
 * tied with the winner; more than 8: so many that only the winner was
 * kept); 0 on a miss. */
int bvh_intersect_ties(const bvh *b, const scene_prim *prims, ray *r, hit *h, bvh_stats *stats, int *tied);
/* The far end of the tie window of a ray from origin whose least t is
 * t_near: the hits with t up to it tie, and the lowest index wins.  The
 * tracer asks it to find the coincident surfaces a nearest hit stood for
 * (spec/numerics.md [NUM-GLASS-3]). */
real bvh_tie_end(real t_near, vec3 origin);

/*
 * Calls fn for every surface crossing in (r->tmin, r->tmax) (a solid
 * crossed through reports its entry and its exit), in no particular order,
 * with h->prim and h->part set.  Stops as soon as fn returns nonzero and returns that
 * value; returns 0 when all crossings were reported.  Meant for shadow
 * rays through transparent occluders.
 */
int bvh_visit(const bvh *b, const scene_prim *prims, const ray *r,
              int (*fn)(void *ctx, const hit *h), void *ctx);
int bvh_visit_stats(const bvh *b, const scene_prim *prims, const ray *r,
                    int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats);
/* bvh_visit_stats whose walk enters only the boxes the ray meets within
 * [node_tmin, r->tmax] (node_tmin below r->tmin counts as r->tmin); the parts
 * in them are tested with r itself.  Every crossing in (r->tmin, r->tmax)
 * whose part's box the ray meets past node_tmin is reported, as
 * bvh_visit_stats reports it ([SHADE-SHORTCUT-GATHER-1]). */
int bvh_visit_window(const bvh *b, const scene_prim *prims, const ray *r, real node_tmin,
                     int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats);
/* The same walk for callers that need only which part is crossed and how
 * often (shadow rays): fn(ctx, ref, n) once for each part with n >= 1
 * crossings (isect_part_crossings), in the order bvh_visit reports them,
 * with no hit point or normal computed. */
int bvh_visit_counts(const bvh *b, const scene_prim *prims, const ray *r,
                     int (*fn)(void *ctx, bvh_ref ref, int crossings), void *ctx, bvh_stats *stats);

/* Whether r crosses some part (a crossing bvh_visit_counts would count):
 * 1 with that part in *found, else 0.  Which part, when several are
 * crossed, is not said: the walk stops at the first it finds, farther
 * child first. */
int bvh_any_crossing(const bvh *b, const scene_prim *prims, const ray *r, bvh_ref *found, bvh_stats *stats);

/*
 * Bundles of shadow rays (spec/shading.md, [SHADE-SHORTCUT-BUNDLE-1]): the
 * rays from one shaded point toward the samples of one distributed light.
 * Every such ray starts within `slack` (each coordinate) of `apex` and is
 * aimed at a point of the box [lo, hi] as spawn_to_by aims it
 * (ray_shadow_to: unit direction, tmin > 0, tmax short of the target);
 * where `exact` is 1, every one starts at `origin` itself (the one origin
 * spawn_origin gives for every target of the box).
 * bvh_bundle_make walks the tree once with a test of the bundle's hull and
 * keeps, in depth-first order, the nodes it may touch: a node left out is
 * one whose box every ray of the bundle fails by the walk's own slab test,
 * and so is every node below it.  In a kept leaf, a box's record (a hot
 * box) that no ray of the bundle crosses is left out too, and, where the
 * rays start at `origin` itself, a triangle's record every ray passes by
 * (bvh_bundle.c, triangle_passed_by): a leaf with none
 * left is not kept, and a leaf with some left is kept as the runs of its
 * parts between them, each a node of the bundle's own (runs) with the
 * leaf's box; past BVH_BUNDLE_RUNS of those, the leaf is kept whole.
 * Where the list would pass BVH_BUNDLE_MAX, the nodes still pending are
 * kept whole.  Where every kept node is a leaf or run of triangle records
 * alone (boxed 0), the walk tests their parts without their boxes
 * ([SHADE-SHORTCUT-OPEN-1]).
 */
enum { BVH_BUNDLE_MAX = 24, BVH_BUNDLE_RUNS = 16, BVH_BUNDLE_UNMADE = -2 };
typedef struct bvh_bundle_rays {
    vec3 apex;
    real slack;
    vec3 lo, hi;
    int exact;
    vec3 origin;
} bvh_bundle_rays;
typedef struct bvh_bundle {
    int count;         /* entries in node[]; -1: none (walk the whole tree),
                          BVH_BUNDLE_UNMADE: not made yet */
    /* a node of the tree, or ~i for runs[i] */
    int node[BVH_BUNDLE_MAX + BVH_MAX_DEPTH + BVH_BUNDLE_RUNS];
    int run_count;
    bvh_node runs[BVH_BUNDLE_RUNS];
    int boxed;         /* entries other than a leaf or run of triangle
                          records alone; 0: the walk tests no box
                          ([SHADE-SHORTCUT-OPEN-1]) */
    unsigned planes_passed; /* bit i: no ray of the bundle crosses unbounded
                               part i, a plane (bvh_bundle_planes); 0 from
                               bvh_bundle_make */
    int crosses_nothing;    /* 1: nothing kept and every unbounded part
                               passed: no ray of the bundle crosses a part */
} bvh_bundle;

/* Fills *out for the rays described above; count -1 when the tree is
 * exhaustive, or a magnitude passes 2^400 or is not finite, or lo > hi on
 * some axis. */
void bvh_bundle_make(const bvh *b, const bvh_bundle_rays *rays, bvh_bundle *out, bvh_stats *stats);
/* Marks in out->planes_passed the world-frame planes among the first 32
 * unbounded parts that no ray of the bundle crosses, where every ray
 * starts at rays->origin and out was made for rays (count >= 0):
 * [SHADE-SHORTCUT-PLANE-1]. */
void bvh_bundle_planes(const bvh *b, const scene_prim *prims, const bvh_bundle_rays *rays, bvh_bundle *out);
/* bvh_visit_counts for a ray of the bundle: the same calls of fn in the
 * same order, from the kept nodes' subtrees and runs alone (bundle NULL
 * or count < 0: bvh_visit_counts). */
int bvh_visit_counts_bundle(const bvh *b, const scene_prim *prims, const ray *r, const bvh_bundle *bundle,
                            int (*fn)(void *ctx, bvh_ref ref, int crossings), void *ctx, bvh_stats *stats);

#endif
