/*
 * bvh_build.c - building the bounding volume hierarchy (see bvh.h).
 *
 * Top-down, binned SAH (Wald, "On fast Construction of SAH-based Bounding
 * Volume Hierarchies", 2007): the centroids of a node's parts are binned
 * along all three axes in one pass, and the plane between bins of least
 *   C_TRAV + (area_L c_L + area_R c_R) / area
 * wins, c being the summed intersection cost of a side's parts (1 for a
 * primitive, TRIANGLE_COST for a mesh triangle); a node of at most
 * MAX_LEAF parts stays a leaf when that is not cheaper than its own cost.  A node of n parts uses min(n, BINS) bins.  The
 * children's boxes come out of the bins exactly, and their centroids'
 * bounds out of the partition pass, so each level reads every part twice.
 * When the centroids coincide, or below
 * BVH_MEDIAN_DEPTH, the node is halved at the object median instead, which
 * bounds the depth.  Every choice is a deterministic function of the input.
 *
 * Memory: a part costs 64 bytes while building (its padded box,
 * reference, cost and hot record's index; the centroid is recomputed),
 * plus its hot record in the parts' order (kept by the tree), the median splits' sort buffers
 * are made only when one happens, and the node array grows as needed.
 */
#include <limits.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <assert.h>
#include "render/bvh.h"

#define BINS 32
#define MAX_LEAF 4
#define C_TRAV 1.0
/* A mesh triangle is tested in about half the time of a sphere or a
 * transformed shape, the cost scale here: leaves of three or four
 * triangles, about half a node per triangle in a large mesh. */
#define TRIANGLE_COST 0.5
/* The hot records' alignment: a sphere's 4 reals in one cache line. */
#define HOT_ALIGN 32

/* A part during the build: its padded box, reference and intersection
 * cost (kept here: reading it from the primitive would be a cache miss per
 * part per level).  The build permutes these in place, so each node's are
 * contiguous. */
typedef struct build_item {
    vec3 lo, hi;
    bvh_ref ref;
    float cost;        /* 1 or TRIANGLE_COST: exact in a float */
    int hot;           /* its record in build_ctx.hot, or -1 */
} build_item;

/* The bounds of some parts' boxes (lo, hi) and of their centroids. */
typedef struct range {
    vec3 lo, hi, clo, chi;
} range;

typedef struct bin {
    vec3 lo, hi;
    int count;
    real cost;        /* summed intersection cost of its parts */
} bin;

typedef struct sort_key {
    real key;
    bvh_ref ref;   /* the tie-break that makes the order unique */
    int position;  /* where the item was before sorting */
} sort_key;

typedef struct build_ctx {
    bvh *b;
    const scene_prim *prims;
    build_item *items;    /* the bounded parts */
    int count;
    build_item *spare;    /* median splits: as many again, made on first use */
    sort_key *keys;
    size_t item_bytes;    /* allocated at items */
    /* The hot records made in the parts' order (classify reads each
     * primitive once, in order: reading the primitives in the tree's order
     * was a cache miss or two per part); their reals stay there, in
     * b->hot_block, and only the codes and offsets are put into the items'
     * final order at the end. */
    bvh_hot *hot;
    real *hot_reals;   /* inside b->hot_block */
    size_t hot_count, hot_reals_size;  /* allocated */
    size_t hot_used;                   /* reals used at hot_reals */
    bin bins[3][BINS];    /* the binning of the node being split */
    int failed;           /* out of memory */
    cancel_poll *cancel;  /* asked once per node, a step per 64 items; NULL: never */
} build_ctx;

/* Comparisons, not fmin/fmax (a library call each): no NaN gets here. */
static vec3 vmin(vec3 a, vec3 b)
{
    return vec_make(a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z);
}

static vec3 vmax(vec3 a, vec3 b)
{
    return vec_make(a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z);
}

static vec3 centroid(const build_item *it)
{
    return vec_scale(vec_add(it->lo, it->hi), 0.5);
}

static range range_empty(void)
{
    range r;
    r.lo = r.clo = vec_splat(INFINITY);
    r.hi = r.chi = vec_splat(-INFINITY);
    return r;
}

static void range_add(range *r, const build_item *it)
{
    vec3 c = centroid(it);
    r->lo = vmin(r->lo, it->lo);
    r->hi = vmax(r->hi, it->hi);
    r->clo = vmin(r->clo, c);
    r->chi = vmax(r->chi, c);
}

static range range_of(const build_ctx *ctx, int begin, int end)
{
    range r = range_empty();
    for (int i = begin; i < end; i++)
        range_add(&r, &ctx->items[i]);
    return r;
}

static real half_area(vec3 lo, vec3 hi)
{
    vec3 e = vec_sub(hi, lo);
    if (!(e.x >= 0.0 && e.y >= 0.0 && e.z >= 0.0))
        return 0.0;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

/* The padded box of part `part` of primitive prims[index]; 0 when it has
 * no finite bounds (isect_part_padded_bounds: the box a kept-frame hit is
 * held to). */
static int item_of(const scene_prim *p, int index, int part, build_item *out)
{
    if (!isect_part_padded_bounds(p, part, &out->lo, &out->hi))
        return 0;
    out->ref.prim = index;
    out->ref.part = part;
    out->cost = p->kind == PRIM_MESH ? (float)TRIANGLE_COST : 1.0f;
    out->hot = -1;
    return 1;
}

/* The binning of a node: per axis, bin = floor((c - lo) * scale), clamped
 * to the node's `bins`; scale 0 for an axis whose centroids coincide (not
 * binned). */
typedef struct binning {
    real lo[3], scale[3];
    int bins;
} binning;

/* c lies in the node's centroid bounds (each centroid made by the same
 * operations), so x lies in [0, bins] up to a few roundings and its
 * conversion is defined: the lower clamp tests the integer, not x (a
 * branch, mispredicted where many centroids share the least coordinate),
 * and gives what a test of x > 0 gave. */
static int bin_of(const binning *bn, int axis, real c)
{
    real x = (c - bn->lo[axis]) * bn->scale[axis];
    int k = (int)x;
    k = k > 0 ? k : 0;
    return k < bn->bins ? k : bn->bins - 1;
}

/* A node of more than ONE_AXIS parts is binned along the widest extent of
 * its centroids only: for big nodes the best plane is nearly always across
 * it, and one axis costs a third of three. */
#define ONE_AXIS 4096

static int widest_axis(vec3 lo, vec3 hi);

static binning binning_of(const range *r, int n)
{
    binning bn;
    int only = n > ONE_AXIS ? widest_axis(r->clo, r->chi) : -1;
    bn.bins = n < BINS ? n : BINS;
    for (int a = 0; a < 3; a++) {
        real lo = vec_component(r->clo, a), extent = vec_component(r->chi, a) - lo, scale = bn.bins / extent;
        bn.lo[a] = lo;
        bn.scale[a] = extent > 0.0 && isfinite(scale) && (only < 0 || a == only) ? scale : 0.0;
    }
    return bn;
}


/* Where axis 0, 1, 2 lies in a vec3, for coordinate. */
static const size_t axis_at[3] = {offsetof(vec3, x), offsetof(vec3, y), offsetof(vec3, z)};

/* Coordinate `at` (axis_at[axis]) of *v: one load, where vec_component
 * chooses by branches. */
static real coordinate(const vec3 *v, size_t at)
{
    return *(const real *)(const void *)((const char *)v + at);
}

/* Adds a run of items (their box, count and summed cost) to a bin. */
static void bin_add(bin *bk, vec3 lo, vec3 hi, int count, real cost)
{
    bk->lo = vmin(bk->lo, lo);
    bk->hi = vmax(bk->hi, hi);
    bk->count += count;
    bk->cost += cost;
}

/* Every item into its bin on one axis: only that coordinate of the
 * centroid is made (the same operations as centroid's), and no axis is
 * chosen per item.  A run of items falling into the same bin is gathered
 * in registers and added to its bin once: updating the bin in memory item
 * by item made each item wait for the last one's stores (neighbouring
 * parts share a bin).  The same bits whatever the grouping: a bin's box is
 * a minimum and a maximum, exact in any order, and its count and cost are
 * sums of 1 and TRIANGLE_COST, multiples of 1/2 far below 2^52, exact in
 * any order too. */
static void bin_axis(build_ctx *ctx, int begin, int end, const binning *bn, int axis)
{
    bin *bins = ctx->bins[axis];
    size_t off = axis_at[axis];
    const build_item *it = &ctx->items[begin];
    if (begin >= end)
        return;
    int k = bin_of(bn, axis, (coordinate(&it->lo, off) + coordinate(&it->hi, off)) * 0.5), count = 1;
    vec3 lo = it->lo, hi = it->hi;
    real cost = it->cost;
    for (int i = begin + 1; i < end; i++) {
        it = &ctx->items[i];
        int j = bin_of(bn, axis, (coordinate(&it->lo, off) + coordinate(&it->hi, off)) * 0.5);
        if (j != k) {
            bin_add(&bins[k], lo, hi, count, cost);
            k = j;
            lo = it->lo;
            hi = it->hi;
            count = 1;
            cost = it->cost;
            continue;
        }
        lo = vmin(lo, it->lo);
        hi = vmax(hi, it->hi);
        count++;
        cost += it->cost;
    }
    bin_add(&bins[k], lo, hi, count, cost);
}

/* Every item into its bin on all three axes in one pass over the items,
 * each bin updated in memory: no branch per item.  A node binned on every
 * axis has at most ONE_AXIS parts, whose items stay in the cache, and its
 * order mixes runs along one axis with changes along another, which made
 * bin_axis's test for the end of a run a mispredicted branch (a third of
 * the build's time in `perf annotate`); the three axes' updates are
 * independent chains.  The same bins as bin_axis's to the bit (a box is a
 * minimum and a maximum, the sums exact in any order). */
static void bin_axes(build_ctx *ctx, int begin, int end, const binning *bn)
{
    bin *bx = ctx->bins[0], *by = ctx->bins[1], *bz = ctx->bins[2];
    for (int i = begin; i < end; i++) {
        const build_item *it = &ctx->items[i];
        bin *b0 = &bx[bin_of(bn, 0, (it->lo.x + it->hi.x) * 0.5)];
        bin *b1 = &by[bin_of(bn, 1, (it->lo.y + it->hi.y) * 0.5)];
        bin *b2 = &bz[bin_of(bn, 2, (it->lo.z + it->hi.z) * 0.5)];
        real cost = it->cost;
        bin_add(b0, it->lo, it->hi, 1, cost);
        bin_add(b1, it->lo, it->hi, 1, cost);
        bin_add(b2, it->lo, it->hi, 1, cost);
    }
}

/* Every item into its bin on each binned axis, an axis at a time (an axis
 * not binned is neither cleared nor read), or all three in one pass when
 * each is binned (bin_axes).  Returns the node's own cost (as
 * a leaf): the sum of a binned axis's bins, which hold every item once and
 * sum exactly in any order (bin_axis), so the items need no pass of their
 * own for it.  Called only when some axis is binned. */
static real fill_bins(build_ctx *ctx, int begin, int end, const binning *bn)
{
    real total = 0.0;
    int summed = -1, all = bn->scale[0] != 0.0 && bn->scale[1] != 0.0 && bn->scale[2] != 0.0;
    for (int a = 0; a < 3; a++) {
        if (bn->scale[a] == 0.0)
            continue;
        for (int k = 0; k < bn->bins; k++) {
            ctx->bins[a][k].lo = vec_splat(INFINITY);
            ctx->bins[a][k].hi = vec_splat(-INFINITY);
            ctx->bins[a][k].count = 0;
            ctx->bins[a][k].cost = 0.0;
        }
        if (!all)
            bin_axis(ctx, begin, end, bn, a);
        summed = summed < 0 ? a : summed;
    }
    if (all)
        bin_axes(ctx, begin, end, bn);
    for (int k = 0; summed >= 0 && k < bn->bins; k++)
        total += ctx->bins[summed][k].cost;
    return total;
}

/* The best plane on one axis: its cost (area-weighted counts, not yet
 * divided by the node's area) and the number of bins on its left.
 * An empty bin changes neither side's box, count nor cost (its box is the
 * empty one, its sums 0), so the plane after it costs exactly what the
 * plane before it did, which was tried first and wins the tie: only the
 * planes after a non-empty bin are tried, and the right side's sums are
 * carried over empty bins instead of made again (small nodes have nb = n
 * bins, most of them empty). */
static real sah_axis(const build_ctx *ctx, int axis, int nb, int *split)
{
    const bin *bins = ctx->bins[axis];
    real right_area[BINS], right_cost[BINS], best = INFINITY, sum = 0.0, area = 0.0;
    int right_count[BINS], count = 0;
    vec3 lo = vec_splat(INFINITY), hi = vec_splat(-INFINITY);
    /* The sums carried in registers, not read back from the arrays (a
     * load waiting on the last store); area starts as half_area of the
     * empty box, 0, which an empty last bin gives. */
    for (int k = nb - 1; k > 0; k--) {
        if (bins[k].count != 0) {
            lo = vmin(lo, bins[k].lo);
            hi = vmax(hi, bins[k].hi);
            count += bins[k].count;
            sum += bins[k].cost;
            area = half_area(lo, hi);
        }
        right_area[k] = area;
        right_count[k] = count;
        right_cost[k] = sum;
    }
    lo = vec_splat(INFINITY);
    hi = vec_splat(-INFINITY);
    count = 0;
    sum = 0.0;
    for (int k = 0; k < nb - 1; k++) {
        if (bins[k].count == 0)
            continue;
        lo = vmin(lo, bins[k].lo);
        hi = vmax(hi, bins[k].hi);
        count += bins[k].count;
        sum += bins[k].cost;
        if (right_count[k + 1] == 0)
            continue;
        real cost = half_area(lo, hi) * sum + right_area[k + 1] * right_cost[k + 1];
        if (cost < best) {
            best = cost;
            *split = k + 1;
        }
    }
    return best;
}

/* The children's boxes: the bins on either side of the split. */
static void kid_boxes(const build_ctx *ctx, int axis, int nb, int split, range kids[2])
{
    kids[0] = kids[1] = range_empty();
    for (int k = 0; k < nb; k++) {
        range *r = &kids[k >= split];
        r->lo = vmin(r->lo, ctx->bins[axis][k].lo);
        r->hi = vmax(r->hi, ctx->bins[axis][k].hi);
    }
}

/* Moves the items whose bin on axis is below split to the front, and
 * gathers each side's centroid bounds into kids[0], kids[1]; returns the
 * first index of the rest. */
static int partition_bins(const build_ctx *ctx, int begin, int end, const binning *bn, int axis, int split,
                          range kids[2])
{
    build_item *items = ctx->items;
    size_t off = axis_at[axis];
    vec3 lo[2] = {kids[0].clo, kids[1].clo}, hi[2] = {kids[0].chi, kids[1].chi};
    int i = begin, j = end - 1;
    while (i <= j) {
        vec3 c = centroid(&items[i]);
        real ca = (coordinate(&items[i].lo, off) + coordinate(&items[i].hi, off)) * 0.5;  /* c's, as bin_axis */
        if (bin_of(bn, axis, ca) < split) {
            lo[0] = vmin(lo[0], c);
            hi[0] = vmax(hi[0], c);
            i++;
        } else {
            lo[1] = vmin(lo[1], c);
            hi[1] = vmax(hi[1], c);
            /* The item from j is read next, at i; this one is done. */
            build_item s = items[i];
            items[i] = items[j];
            items[j--] = s;
        }
    }
    kids[0].clo = lo[0];
    kids[0].chi = hi[0];
    kids[1].clo = lo[1];
    kids[1].chi = hi[1];
    return i;
}

/* Orders references: by primitive, then by part. */
static int ref_order(bvh_ref a, bvh_ref b)
{
    if (a.prim != b.prim)
        return a.prim < b.prim ? -1 : 1;
    return (a.part > b.part) - (a.part < b.part);
}

static int compare_keys(const void *pa, const void *pb)
{
    const sort_key *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return ref_order(a->ref, b->ref);
}

/* Sorts items[begin..end) by centroid on axis, ties by reference (so the
 * order is unique whatever qsort does), and returns the middle; -1 when
 * the sort buffers cannot be made. */
static int median_split(build_ctx *ctx, int begin, int end, int axis)
{
    /* Both buffers or none: a failed keys allocation leaves spare held, and
     * the build goes on making leaves, so the next call must try again
     * rather than take spare's presence for both. */
    if (!ctx->keys) {
        if (!ctx->spare)
            ctx->spare = mem_alloc(&ctx->b->mem, (size_t)ctx->count * sizeof *ctx->spare);
        ctx->keys = ctx->spare ? mem_alloc(&ctx->b->mem, (size_t)ctx->count * sizeof *ctx->keys) : NULL;
        if (!ctx->keys) {
            ctx->failed = 1;
            return -1;
        }
    }
    build_item *items = ctx->items + begin;
    int n = end - begin;
    for (int i = 0; i < n; i++) {
        ctx->keys[i].key = vec_component(centroid(&items[i]), axis);
        ctx->keys[i].ref = items[i].ref;
        ctx->keys[i].position = i;
        ctx->spare[i] = items[i];
    }
    qsort(ctx->keys, (size_t)n, sizeof *ctx->keys, compare_keys);
    for (int i = 0; i < n; i++)
        items[i] = ctx->spare[ctx->keys[i].position];
    return begin + n / 2;
}

static int widest_axis(vec3 lo, vec3 hi)
{
    vec3 e = vec_sub(hi, lo);
    return e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
}

/* choose_split for two parts, the same result without the bins (half the
 * inner nodes of a big tree have two parts).  With n = 2 each axis the
 * binning takes has two bins, the part of the lower centroid in the first:
 * every such axis offers the same single plane at the same cost
 *   half_area(lower) cost(lower) + half_area(upper) cost(upper)
 * (the sum of the same two products), so the first such axis wins; the
 * partition then puts the lower part first, and each child's bounds are
 * its part's box and centroid. */
static int split_pair(build_ctx *ctx, int begin, const range *r, range kids[2])
{
    build_item *it = &ctx->items[begin];
    int axis = -1;
    for (int a = 0; a < 3 && axis < 0; a++) {
        real extent = vec_component(r->chi, a) - vec_component(r->clo, a), scale = 2 / extent;
        if (extent > 0.0 && isfinite(scale))
            axis = a;
    }
    if (axis < 0)
        return -1;
    vec3 c0 = centroid(&it[0]), c1 = centroid(&it[1]);
    int swap = vec_component(c0, axis) > vec_component(c1, axis);
    const build_item *low = &it[swap], *high = &it[!swap];
    real best = half_area(low->lo, low->hi) * (0.0 + low->cost) + half_area(high->lo, high->hi) * (0.0 + high->cost);
    real leaf_cost = 0.0 + it[0].cost + it[1].cost, area = half_area(r->lo, r->hi);
    real split_cost = area > 0.0 ? C_TRAV + best / area : C_TRAV;
    if (!(split_cost < leaf_cost))
        return -1;
    kids[0].lo = low->lo;
    kids[0].hi = low->hi;
    kids[0].clo = kids[0].chi = swap ? c1 : c0;
    kids[1].lo = high->lo;
    kids[1].hi = high->hi;
    kids[1].clo = kids[1].chi = swap ? c0 : c1;
    if (swap) {
        build_item s = it[0];
        it[0] = it[1];
        it[1] = s;
    }
    return begin + 1;
}

/* Where to split items[begin..end) of bounds *r, or -1 for a leaf.  The
 * children's bounds go to kids[0], kids[1]. */
static int choose_split(build_ctx *ctx, int begin, int end, int depth, const range *r, range kids[2])
{
    int n = end - begin, best_split = 0, best_axis = -1;
    real best = INFINITY, leaf_cost = n;
    if (n <= 1)
        return -1;
    if (n == 2 && depth < BVH_MEDIAN_DEPTH && MAX_LEAF >= 2)
        return split_pair(ctx, begin, r, kids);
    binning bn = binning_of(r, n);
    if (depth < BVH_MEDIAN_DEPTH && (bn.scale[0] != 0 || bn.scale[1] != 0 || bn.scale[2] != 0)) {
        leaf_cost = fill_bins(ctx, begin, end, &bn);
        for (int a = 0; a < 3; a++) {
            int split = 0;
            real cost = bn.scale[a] != 0.0 ? sah_axis(ctx, a, bn.bins, &split) : INFINITY;
            if (cost < best) {
                best = cost;
                best_axis = a;
                best_split = split;
            }
        }
    }
    if (best_axis < 0) {
        if (n <= MAX_LEAF)
            return -1;
        int mid = median_split(ctx, begin, end, widest_axis(r->clo, r->chi));
        if (mid < 0)
            return -1;
        kids[0] = range_of(ctx, begin, mid);
        kids[1] = range_of(ctx, mid, end);
        return mid;
    }
    real area = half_area(r->lo, r->hi);
    real split_cost = area > 0.0 ? C_TRAV + best / area : C_TRAV;
    if (n <= MAX_LEAF && !(split_cost < leaf_cost))
        return -1;
    kid_boxes(ctx, best_axis, bn.bins, best_split, kids);
    return partition_bins(ctx, begin, end, &bn, best_axis, best_split, kids);
}

/* Two adjacent nodes; their index, or -1 when out of memory. */
static int new_pair(build_ctx *ctx)
{
    bvh *b = ctx->b;
    if (b->node_count + 2 > b->node_cap) {
        int cap = b->node_cap > INT_MAX / 2 ? INT_MAX : 2 * b->node_cap;
        bvh_node *grown = mem_resize_array(&b->mem, b->nodes, (size_t)b->node_cap, (size_t)cap, sizeof *grown);
        if (!grown) {
            ctx->failed = 1;
            return -1;
        }
        b->nodes = grown;
        b->node_cap = cap;
    }
    b->node_count += 2;
    return b->node_count - 2;
}

/*
 * [BVH-CULL-PAD-1] How far a node's box reaches past its parts' padded
 * boxes, the same on every axis.  A part's box is padded per axis by 2^-40
 * of that axis's coordinates (isect_part_padded_bounds), but a hit test's
 * rounding is relative to the largest coordinate of the part and of the
 * point (its t is a difference of coordinates of that size): a triangle
 * lying in the plane y = 0 with corners 1e8 away has a box of no
 * thickness in y, and its t is off by about 1e8 eps.  A ray spawned 1e-12
 * under it was found to cross it by the exhaustive walk (t = 7e-9) and
 * culled by the box.  2^-40 of the node's largest magnitude on every axis
 * holds each part's box padded by 2^-40 of its own (a part's coordinates
 * are within its node's); the tree's shape is chosen from the unwidened
 * boxes, so only what is culled changes (spec/numerics.md).
 */
static real cull_pad(const range *r)
{
    real m = vec_max_abs(r->lo), n = vec_max_abs(r->hi), s = vec_max_abs(vec_sub(r->hi, r->lo));
    m = m > n ? m : n;
    return 0x1p-40 * (m > s ? m : s);
}

/* Fills node (already allocated) for items[begin..end) of bounds *r and its
 * subtree.  The two children of a node are allocated together, side by
 * side, so a traversal step that tests both reads adjacent memory.  The
 * recursion is at most BVH_MAX_DEPTH deep (see bvh.h). */
static void build_node(build_ctx *ctx, int node, int begin, int end, int depth, const range *r)
{
    bvh *b = ctx->b;
    range kids[2];
    real pad = cull_pad(r);
    b->nodes[node].lo = vec_sub(r->lo, vec_splat(pad));
    b->nodes[node].hi = vec_add(r->hi, vec_splat(pad));
    if (depth > b->depth)
        b->depth = depth;
    /* A stopped build still ends as a valid tree: the rest become leaves
     * (bvh_build_polled then throws it away). */
    int stop = cancel_steps(ctx->cancel, 1 + (end - begin) / 64);
    int mid = stop ? -1 : choose_split(ctx, begin, end, depth, r, kids);
    int first = mid < 0 ? -1 : new_pair(ctx);
    if (first < 0) {
        b->nodes[node].first = begin;
        b->nodes[node].count = end - begin;
        b->leaf_count++;
        return;
    }
    assert(mid > begin && mid < end && depth < BVH_MAX_DEPTH);
    b->nodes[node].first = first;
    b->nodes[node].count = 0;
    build_node(ctx, first, begin, mid, depth + 1, &kids[0]);
    build_node(ctx, first + 1, mid, end, depth + 1, &kids[1]);
}

static void free_sort_buffers(build_ctx *ctx)
{
    mem_free(&ctx->b->mem, ctx->spare, (size_t)ctx->count * sizeof *ctx->spare);
    mem_free(&ctx->b->mem, ctx->keys, (size_t)ctx->count * sizeof *ctx->keys);
    ctx->spare = NULL;
    ctx->keys = NULL;
}

/* The hot record of part k of p into ctx's (prim-order) arrays. */
static void hot_add(build_ctx *ctx, const scene_prim *p, int k, build_item *it)
{
    size_t want = (size_t)isect_hot_reals(p);
    int n = 0;
    if (want == 0 || ctx->hot_used + want > ctx->hot_reals_size)
        return;
    int code = isect_hot_make(p, k, ctx->hot_reals + ctx->hot_used, &n);
    if (code == ISECT_HOT_NONE)
        return;
    it->hot = (int)(it - ctx->items);
    ctx->hot[it->hot].code = code;
    ctx->hot[it->hot].at = (int)ctx->hot_used;   /* < INT_MAX: see bvh_build_polled */
    ctx->hot_used += (size_t)n;
}

/* Sorts parts into build items (bounded) and b->unbounded (a part without
 * finite bounds puts all its primitive's parts there: all of it is then
 * tested on every ray), which is then cut to its count (it was made for
 * every part). */
static int classify(build_ctx *ctx, const scene_prim *prims, int count, build_item *items)
{
    bvh *b = ctx->b;
    int bounded = 0;
    for (int i = 0; i < count; i++) {
        /* A third of a 200 000-sphere build is this pass: polled like the
         * tree's nodes, a step per 64 primitives. */
        if (i % 64 == 0 && cancel_step(ctx->cancel))
            break;
        int parts = isect_part_count(&prims[i]), kept = bounded;
        for (int k = 0; k < parts; k++)
            bounded += item_of(&prims[i], i, k, &items[bounded]);
        if (bounded - kept == parts) {
            for (int k = 0; k < parts && ctx->hot; k++)
                hot_add(ctx, &prims[i], k, &items[kept + k]);
            continue;
        }
        bounded = kept;
        for (int k = 0; k < parts; k++) {
            bvh_ref ref = {i, k};
            b->unbounded[b->unbounded_count++] = ref;
        }
    }
    bvh_ref *fit = mem_resize_array(&b->mem, b->unbounded, (size_t)b->unbounded_cap, (size_t)b->unbounded_count,
                                    sizeof *fit);
    if (fit) {
        b->unbounded = fit;
        b->unbounded_cap = b->unbounded_count;
    }
    return bounded;
}

/* The references of the built items, in their final order, written over
 * the front of the items' own array (reference i goes where item i/8
 * was, already read) and the array shrunk to them: no second array at the
 * build's peak. */
static void keep_references(build_ctx *ctx)
{
    bvh *b = ctx->b;
    bvh_ref *refs = (bvh_ref *)(void *)ctx->items;
    for (int i = 0; i < ctx->count; i++) {
        bvh_ref r = ctx->items[i].ref;
        refs[i] = r;
    }
    size_t want = (size_t)ctx->count * sizeof *refs;
    bvh_ref *fit = mem_resize(&b->mem, refs, ctx->item_bytes, want);
    b->items = fit ? fit : refs;
    b->item_bytes = fit ? want : ctx->item_bytes;
    b->item_count = ctx->count;
    ctx->items = NULL;
}

/* The hot records of b->items (bvh.h), in their order; 0 when out of
 * memory.  Their reals stay where classify made them, in the parts' order
 * (b->hot_block from the start): only the short code and offset move. */
static int keep_hot(build_ctx *ctx)
{
    bvh *b = ctx->b;
    b->hot = mem_alloc(&b->mem, (size_t)ctx->count * sizeof *b->hot);
    if (!b->hot)
        return 0;
    b->hot_reals = ctx->hot_used > 0 ? ctx->hot_reals : NULL;
    for (int i = 0; i < ctx->count; i++) {
        int k = ctx->items[i].hot;
        b->hot[i].code = k < 0 ? ISECT_HOT_NONE : ctx->hot[k].code;
        b->hot[i].at = k < 0 ? 0 : ctx->hot[k].at;
    }
    return 1;
}

/* The tree over ctx->items[0..count-1]; 0 when out of memory.  The node
 * array starts at one node per part (leaves hold about three; untouched
 * pages cost nothing) and shrinks to fit at the end. */
static int build_tree(build_ctx *ctx)
{
    bvh *b = ctx->b;
    b->nodes = mem_alloc(&b->mem, ((size_t)ctx->count + 1) * sizeof *b->nodes);
    if (!b->nodes)
        return 0;
    b->node_cap = ctx->count + 1;
    b->node_count = 1;
    range all = range_of(ctx, 0, ctx->count);
    build_node(ctx, 0, 0, ctx->count, 1, &all);
    if (ctx->failed)
        return 0;
    free_sort_buffers(ctx);
    if (!keep_hot(ctx))
        return 0;
    keep_references(ctx);
    bvh_node *fit = mem_resize_array(&b->mem, b->nodes, (size_t)b->node_cap, (size_t)b->node_count, sizeof *fit);
    if (fit) {
        b->nodes = fit;
        b->node_cap = b->node_count;
    }
    return 1;
}

/* The number of parts of prims[0..count-1], or -1 past INT_MAX/2; *reals
 * is their hot records' size (isect_hot_reals). */
static long count_parts(const scene_prim *prims, int count, size_t *reals)
{
    long parts = 0;
    *reals = 0;
    for (int i = 0; i < count && parts <= INT_MAX / 2; i++) {
        int n = isect_part_count(&prims[i]);
        parts += n;
        *reals += (size_t)n * (size_t)isect_hot_reals(&prims[i]);
    }
    return parts <= INT_MAX / 2 ? parts : -1;
}

int bvh_build(bvh *b, const scene_prim *prims, int count, const mem *m)
{
    return bvh_build_polled(b, prims, count, m, NULL) == STATUS_OK;
}

int bvh_build_polled(bvh *b, const scene_prim *prims, int count, const mem *m, cancel_poll *cancel)
{
    memset(b, 0, sizeof *b);
    b->mem = mem_pick(m);
    build_ctx *ctx = mem_calloc(&b->mem, 1, sizeof *ctx);
    int ok = 0;
    size_t reals = 0;
    long parts = count >= 0 ? count_parts(prims, count, &reals) : -1;
    if (!ctx || parts < 0 || (size_t)parts > SIZE_MAX / 2 / sizeof(build_item)) {
        mem_free(&b->mem, ctx, sizeof *ctx);
        return STATUS_NO_MEMORY;
    }
    ctx->b = b;
    ctx->prims = prims;
    ctx->cancel = cancel;
    ctx->item_bytes = (size_t)parts * sizeof *ctx->items;
    ctx->items = mem_alloc(&b->mem, ctx->item_bytes);
    b->unbounded = mem_alloc(&b->mem, (size_t)parts * sizeof *b->unbounded);
    b->unbounded_cap = b->unbounded ? (int)parts : 0;
    /* Past INT_MAX reals (a 16 GB array) no hot records are made: every
     * part is then tested through its scene_prim. */
    if (reals > 0 && reals <= (size_t)INT_MAX) {
        ctx->hot_count = (size_t)parts;
        ctx->hot_reals_size = reals;
        ctx->hot = mem_alloc(&b->mem, ctx->hot_count * sizeof *ctx->hot);
        /* The tree's own block (bvh_free releases it), the records aligned
         * to 32 bytes: each is 4, 8 or 12 reals. */
        b->hot_block_bytes = reals * sizeof(real) + HOT_ALIGN;
        b->hot_block = mem_alloc(&b->mem, b->hot_block_bytes);
        b->hot_block_bytes = b->hot_block ? b->hot_block_bytes : 0;
        if (b->hot_block)
            ctx->hot_reals = (real *)(void *)((char *)b->hot_block +
                                              (HOT_ALIGN - (uintptr_t)b->hot_block % HOT_ALIGN) % HOT_ALIGN);
    }
    if (ctx->items && b->unbounded && (reals == 0 || reals > (size_t)INT_MAX || (ctx->hot && ctx->hot_reals))) {
        ctx->count = classify(ctx, prims, count, ctx->items);
        ok = !cancel_stopped(cancel) && (ctx->count == 0 || build_tree(ctx));
    }
    mem_free(&b->mem, ctx->items, ctx->item_bytes);
    mem_free(&b->mem, ctx->hot, ctx->hot_count * sizeof *ctx->hot);
    free_sort_buffers(ctx);
    mem_free(&b->mem, ctx, sizeof *ctx);
    if (!ok || cancel_stopped(cancel))
        bvh_free(b);
    return cancel_stopped(cancel) ? STATUS_CANCELLED : ok ? STATUS_OK : STATUS_NO_MEMORY;
}
