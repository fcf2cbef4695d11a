/*
 * bvh.c - build and traversal of the bounding volume hierarchy.
 *
 * Build: top-down, binned SAH (Wald, "On fast Construction of SAH-based
 * Bounding Volume Hierarchies", 2007): the centroids of a node's primitives
 * are binned along each axis and the plane between bins of least
 *   C_TRAV + (area_L n_L + area_R n_R) / area
 * wins; a node of at most MAX_LEAF primitives stays a leaf when that is not
 * cheaper than n.  When the centroids coincide, or below BVH_MEDIAN_DEPTH,
 * the node is halved at the object median instead, which bounds the depth.
 * Every choice is a deterministic function of the input.
 *
 * Traversal: an explicit stack of BVH_MAX_DEPTH entries, nearest child
 * first, culling by the shrinking tmax (not when b->exhaustive: then every
 * node is entered, so every primitive is tested in the same order).  The slab test is the robust one of
 * Ize ("Robust BVH Ray Traversal", JCGT 2(2), 2013): the exit distance is
 * enlarged by 1 + 4 eps (> 1 + 2 gamma_3) so rounding never culls a box the
 * ray touches, and a NaN from 0 * inf (origin on a slab plane, direction
 * parallel to it) never narrows the interval because the comparisons that
 * update it are false for NaN.
 */
#include <float.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <assert.h>
#include "render/bvh.h"

#define BINS 32
#define MAX_LEAF 4
#define C_TRAV 1.0
/* Primitive boxes are widened by this fraction of their coordinates' size,
 * so a hit computed a few ulps outside its true box is still inside. */
#define BOUNDS_PAD 0x1p-40
#define EXIT_PAD (4.0 * DBL_EPSILON)

/* A primitive during the build: its padded box, centroid and index.  The
 * build permutes these in place, so each node's are contiguous. */
typedef struct build_item {
    vec3 lo, hi, centroid;
    int index;
} build_item;

typedef struct sort_key {
    real key;
    int index;     /* primitive index: the tie-break that makes the order unique */
    int position;  /* where the item was before sorting */
} sort_key;

typedef struct build_ctx {
    bvh *b;
    build_item *items;    /* the bounded primitives */
    build_item *spare;    /* as many again, for median splits */
    sort_key *keys;
} build_ctx;

typedef struct bin {
    vec3 lo, hi;
    int count;
} bin;

/* Comparisons, not fmin/fmax (a library call each): no NaN gets here. */
static vec3 vmin(vec3 a, vec3 b)
{
    return vec_make(a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z);
}

static vec3 vmax(vec3 a, vec3 b)
{
    return vec_make(a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z);
}

static real half_area(vec3 lo, vec3 hi)
{
    vec3 e = vec_sub(hi, lo);
    if (!(e.x >= 0.0 && e.y >= 0.0 && e.z >= 0.0))
        return 0.0;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

static real pad(real lo, real hi)
{
    return BOUNDS_PAD * fmax(fmax(fabs(lo), fabs(hi)), hi - lo);
}

/* The padded box of primitive p; 0 when it has no finite bounds. */
static int item_of(const scene_prim *p, int index, build_item *out)
{
    vec3 lo, hi;
    if (!isect_prim_bounds(p, &lo, &hi))
        return 0;
    vec3 e = vec_make(pad(lo.x, hi.x), pad(lo.y, hi.y), pad(lo.z, hi.z));
    out->lo = vec_sub(lo, e);
    out->hi = vec_add(hi, e);
    out->centroid = vec_scale(vec_add(out->lo, out->hi), 0.5);
    out->index = index;
    return vec_is_finite(out->centroid);
}

/* Bounds of the boxes and of the centroids of items[begin..end). */
static void range_bounds(const build_ctx *ctx, int begin, int end, vec3 bounds[2], vec3 cent[2])
{
    bounds[0] = cent[0] = vec_splat(INFINITY);
    bounds[1] = cent[1] = vec_splat(-INFINITY);
    for (int i = begin; i < end; i++) {
        const build_item *it = &ctx->items[i];
        bounds[0] = vmin(bounds[0], it->lo);
        bounds[1] = vmax(bounds[1], it->hi);
        cent[0] = vmin(cent[0], it->centroid);
        cent[1] = vmax(cent[1], it->centroid);
    }
}

/* The binning of one axis: bin = floor((c - lo) * scale), clamped. */
typedef struct binning {
    int axis;
    real lo, scale;
} binning;

static int bin_of(const binning *bn, vec3 c)
{
    real x = (vec_component(c, bn->axis) - bn->lo) * bn->scale;
    int k = x > 0.0 ? (int)x : 0;
    return k < BINS ? k : BINS - 1;
}

/* The best plane on one axis: cost (area-weighted counts, not yet divided
 * by the node's area) and the number of bins on its left. */
static real sah_axis(const build_ctx *ctx, int begin, int end, const binning *bn, int *split)
{
    bin bins[BINS];
    real right_area[BINS];
    int right_count[BINS];
    for (int k = 0; k < BINS; k++) {
        bins[k].lo = vec_splat(INFINITY);
        bins[k].hi = vec_splat(-INFINITY);
        bins[k].count = 0;
    }
    for (int i = begin; i < end; i++) {
        const build_item *it = &ctx->items[i];
        bin *bk = &bins[bin_of(bn, it->centroid)];
        bk->lo = vmin(bk->lo, it->lo);
        bk->hi = vmax(bk->hi, it->hi);
        bk->count++;
    }
    vec3 lo = vec_splat(INFINITY), hi = vec_splat(-INFINITY);
    int count = 0;
    for (int k = BINS - 1; k > 0; k--) {
        lo = vmin(lo, bins[k].lo);
        hi = vmax(hi, bins[k].hi);
        count += bins[k].count;
        right_area[k] = half_area(lo, hi);
        right_count[k] = count;
    }
    real best = INFINITY;
    lo = vec_splat(INFINITY);
    hi = vec_splat(-INFINITY);
    count = 0;
    for (int k = 0; k < BINS - 1; k++) {
        lo = vmin(lo, bins[k].lo);
        hi = vmax(hi, bins[k].hi);
        count += bins[k].count;
        if (count == 0 || right_count[k + 1] == 0)
            continue;
        real cost = half_area(lo, hi) * count + right_area[k + 1] * right_count[k + 1];
        if (cost < best) {
            best = cost;
            *split = k + 1;
        }
    }
    return best;
}

/* Moves the items whose bin is below split to the front; returns the first
 * index of the rest. */
static int partition_bins(const build_ctx *ctx, int begin, int end, const binning *bn, int split)
{
    build_item *items = ctx->items;
    int i = begin, j = end - 1;
    while (i <= j) {
        if (bin_of(bn, items[i].centroid) < split) {
            i++;
        } else {
            build_item s = items[i];
            items[i] = items[j];
            items[j--] = s;
        }
    }
    return i;
}

static int compare_keys(const void *pa, const void *pb)
{
    const sort_key *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return (a->index > b->index) - (a->index < b->index);
}

/* Sorts items[begin..end) by centroid on axis, ties by primitive index (so
 * the order is unique whatever qsort does), and returns the middle. */
static int median_split(const build_ctx *ctx, int begin, int end, int axis)
{
    build_item *items = ctx->items + begin;
    int n = end - begin;
    for (int i = 0; i < n; i++) {
        ctx->keys[i].key = vec_component(items[i].centroid, axis);
        ctx->keys[i].index = items[i].index;
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

/* Where to split items[begin..end), or -1 for a leaf. */
static int choose_split(const build_ctx *ctx, int begin, int end, int depth, const vec3 bounds[2],
                        const vec3 cent[2])
{
    int n = end - begin, best_split = 0;
    real best = INFINITY;
    binning best_bn = {0, 0.0, 0.0};
    if (n <= 1)
        return -1;
    for (int axis = 0; axis < 3 && depth < BVH_MEDIAN_DEPTH; axis++) {
        real lo = vec_component(cent[0], axis), extent = vec_component(cent[1], axis) - lo;
        binning bn = {axis, lo, BINS / extent};
        int split = 0;
        if (!(extent > 0.0) || !isfinite(bn.scale))
            continue;
        real cost = sah_axis(ctx, begin, end, &bn, &split);
        if (cost < best) {
            best = cost;
            best_bn = bn;
            best_split = split;
        }
    }
    if (best == INFINITY)
        return n <= MAX_LEAF ? -1 : median_split(ctx, begin, end, widest_axis(cent[0], cent[1]));
    real area = half_area(bounds[0], bounds[1]);
    real split_cost = area > 0.0 ? C_TRAV + best / area : C_TRAV;
    if (n <= MAX_LEAF && !(split_cost < n))
        return -1;
    return partition_bins(ctx, begin, end, &best_bn, best_split);
}

/* Fills node (already allocated) for items[begin..end) and its subtree.
 * The two children of a node are allocated together, side by side, so a
 * traversal step that tests both reads adjacent memory.  The recursion is
 * at most BVH_MAX_DEPTH deep (see bvh.h). */
static void build_node(const build_ctx *ctx, int node, int begin, int end, int depth)
{
    bvh *b = ctx->b;
    vec3 bounds[2], cent[2];
    range_bounds(ctx, begin, end, bounds, cent);
    b->nodes[node].lo = bounds[0];
    b->nodes[node].hi = bounds[1];
    if (depth > b->depth)
        b->depth = depth;
    int mid = choose_split(ctx, begin, end, depth, bounds, cent);
    if (mid < 0) {
        b->nodes[node].first = begin;
        b->nodes[node].count = end - begin;
        b->leaf_count++;
        return;
    }
    assert(mid > begin && mid < end && depth < BVH_MAX_DEPTH);
    int first = b->node_count;
    b->node_count += 2;
    b->nodes[node].first = first;
    b->nodes[node].count = 0;
    build_node(ctx, first, begin, mid, depth + 1);
    build_node(ctx, first + 1, mid, end, depth + 1);
}

void bvh_free(bvh *b)
{
    mem m = b->mem;
    mem_free(&m, b->nodes, (size_t)b->node_cap * sizeof *b->nodes);
    mem_free(&m, b->items, (size_t)b->item_count * sizeof *b->items);
    mem_free(&m, b->unbounded, (size_t)b->unbounded_cap * sizeof *b->unbounded);
    memset(b, 0, sizeof *b);
    b->mem = m;
}

/* Sorts primitives into build items (bounded) and b->unbounded, which is
 * then cut to its count (it was made for every primitive). */
static int classify(bvh *b, const scene_prim *prims, int count, build_item *items)
{
    int bounded = 0;
    for (int i = 0; i < count; i++) {
        if (item_of(&prims[i], i, &items[bounded]))
            bounded++;
        else
            b->unbounded[b->unbounded_count++] = i;
    }
    int *fit = mem_resize_array(&b->mem, b->unbounded, (size_t)b->unbounded_cap, (size_t)b->unbounded_count,
                                sizeof *fit);
    if (fit) {
        b->unbounded = fit;
        b->unbounded_cap = b->unbounded_count;
    }
    return bounded;
}

/* The tree over ctx->items[0..count-1]; 0 when out of memory. */
static int build_tree(build_ctx *ctx, int count)
{
    bvh *b = ctx->b;
    b->nodes = mem_calloc(&b->mem, 2 * (size_t)count, sizeof *b->nodes);
    if (!b->nodes)
        return 0;
    b->node_cap = 2 * count;
    b->items = mem_calloc(&b->mem, (size_t)count, sizeof *b->items);
    if (!b->items)
        return 0;
    b->item_count = count;
    b->node_count = 1;
    build_node(ctx, 0, 0, count, 1);
    for (int i = 0; i < count; i++)
        b->items[i] = ctx->items[i].index;
    bvh_node *fit = mem_resize_array(&b->mem, b->nodes, (size_t)b->node_cap, (size_t)b->node_count, sizeof *fit);
    if (fit) {
        b->nodes = fit;
        b->node_cap = b->node_count;
    }
    return 1;
}

int bvh_build(bvh *b, const scene_prim *prims, int count, const mem *m)
{
    build_ctx ctx = {b, NULL, NULL, NULL};
    int ok = 0;
    memset(b, 0, sizeof *b);
    b->mem = mem_pick(m);
    if (count < 0 || count > INT_MAX / 2 || (size_t)count > SIZE_MAX / 2 / sizeof(build_item))
        return 0;
    size_t n = (size_t)count;
    ctx.items = mem_calloc(&b->mem, n, sizeof *ctx.items);
    ctx.spare = mem_calloc(&b->mem, n, sizeof *ctx.spare);
    ctx.keys = mem_calloc(&b->mem, n, sizeof *ctx.keys);
    b->unbounded = mem_calloc(&b->mem, n, sizeof *b->unbounded);
    b->unbounded_cap = b->unbounded ? count : 0;
    if (ctx.items && ctx.spare && ctx.keys && b->unbounded) {
        int bounded = classify(b, prims, count, ctx.items);
        ok = bounded == 0 || build_tree(&ctx, bounded);
    }
    mem_free(&b->mem, ctx.items, n * sizeof *ctx.items);
    mem_free(&b->mem, ctx.spare, n * sizeof *ctx.spare);
    mem_free(&b->mem, ctx.keys, n * sizeof *ctx.keys);
    if (!ok)
        bvh_free(b);
    return ok;
}

/* A ray prepared for slab tests: 1/d with signed infinities for d = +-0. */
typedef struct slab_ray {
    vec3 o, inv;
    int neg[3];
} slab_ray;

static real inverse(real d) { return d != 0.0 ? 1.0 / d : copysign(INFINITY, d); }

static slab_ray slab_make(const ray *r)
{
    slab_ray s;
    s.o = r->origin;
    s.inv = vec_make(inverse(r->dir.x), inverse(r->dir.y), inverse(r->dir.z));
    s.neg[0] = signbit(s.inv.x) != 0;
    s.neg[1] = signbit(s.inv.y) != 0;
    s.neg[2] = signbit(s.inv.z) != 0;
    return s;
}

/* Narrows [*tn, *tf] by one slab; NaN leaves it unchanged (see the top). */
static void slab(real lo, real hi, real o, real inv, int neg, real *tn, real *tf)
{
    real t0 = ((neg ? hi : lo) - o) * inv, t1 = ((neg ? lo : hi) - o) * inv;
    /* Enlarge the exit by scaling, not by adding |t1| * pad: for t1 = -inf
     * (a box wholly to one side of a parallel ray) that would be NaN and
     * the box would never be culled. */
    t1 *= t1 >= 0.0 ? 1.0 + EXIT_PAD : 1.0 - EXIT_PAD;
    if (t0 > *tn)
        *tn = t0;
    if (t1 < *tf)
        *tf = t1;
}

/* Whether the ray meets the node's box within [tmin, tmax]; *enter is the
 * entry distance. */
static int node_hit(const bvh_node *nd, const slab_ray *s, real tmin, real tmax, real *enter)
{
    real tn = tmin, tf = tmax;
    slab(nd->lo.x, nd->hi.x, s->o.x, s->inv.x, s->neg[0], &tn, &tf);
    slab(nd->lo.y, nd->hi.y, s->o.y, s->inv.y, s->neg[1], &tn, &tf);
    slab(nd->lo.z, nd->hi.z, s->o.z, s->inv.z, s->neg[2], &tn, &tf);
    *enter = tn;
    return tn <= tf;
}

/*
 * The running nearest hit, with coplanar ties.  Two surfaces in one plane
 * (a disk lying on a plane, a box standing on the floor) give hits whose t
 * differ by an ulp or two of rounding, and "the smaller t" is then noise:
 * z-fighting.  So every hit within the tie window of the nearest t so far
 * is kept, and the lowest primitive index among them wins:
 *   window(t) = TIE_REL (|t| + |origin|),
 * 64 ulps of the larger of the distance and the origin's magnitude, the
 * size of t's own rounding.  The candidates are pruned as the nearest t
 * falls, so the winner does not depend on the order of the tests; rr.tmax
 * stays at the window's far end so that no candidate is culled.  When more
 * than TIE_MAX surfaces tie, a second pass over the now known window finds
 * the lowest index among all of them.
 */
#define TIE_REL 0x1p-46
enum { TIE_MAX = 8 };

typedef struct nearest {
    ray rr;
    hit cand[TIE_MAX];  /* the hits within the window of t_near */
    int count;
    int overflow;       /* more than TIE_MAX candidates at once */
    int fixed;          /* second pass: rr.tmax is the final window's end */
    real t_near;        /* the least t found; in the second pass the window's end */
    real slack;         /* TIE_REL * |origin| */
    bvh_stats *stats;
} nearest;

static real tie_limit(const nearest *ns)
{
    real limit = ns->t_near + (TIE_REL * fabs(ns->t_near) + ns->slack);
    return limit > ns->t_near ? limit : nextafter(ns->t_near, (real)INFINITY);
}

/* Adds h to the candidates and drops those now beyond the window.  In the
 * second pass only the lowest index counts. */
static void nearest_add(nearest *ns, const hit *h)
{
    if (ns->fixed) {
        if (ns->count == 0 || h->prim < ns->cand[0].prim)
            ns->cand[0] = *h;
        ns->count = 1;
        ns->rr.tmax = ns->t_near;   /* the window's end, set by the caller */
        return;
    }
    if (ns->count == 0 || h->t < ns->t_near)
        ns->t_near = h->t;
    real limit = tie_limit(ns);
    int kept = 0;
    for (int i = 0; i < ns->count; i++)
        if (ns->cand[i].t <= limit)
            ns->cand[kept++] = ns->cand[i];
    if (h->t <= limit) {
        if (kept < TIE_MAX)
            ns->cand[kept++] = *h;
        else
            ns->overflow = 1;
    }
    ns->count = kept;
    ns->rr.tmax = limit;
}

static void nearest_test(nearest *ns, const scene_prim *prims, int index)
{
    hit h;
    if (ns->stats)
        ns->stats->prims_tested++;
    if (!isect_prim(&prims[index], &ns->rr, &h))
        return;
    h.prim = index;
    nearest_add(ns, &h);
}

/* The lowest-index candidate: the nearest hit (see above). */
static const hit *nearest_winner(const nearest *ns)
{
    const hit *best = &ns->cand[0];
    for (int i = 1; i < ns->count; i++)
        if (ns->cand[i].prim < best->prim)
            best = &ns->cand[i];
    return best;
}

typedef struct stack_entry {
    int node;
    real enter;
} stack_entry;

/* Among the children of an inner node that the ray meets, goes to the
 * nearer and pushes the other; returns the next node or -1. */
static int descend(const bvh *b, int node, const slab_ray *s, nearest *ns, stack_entry *stack,
                   int *sp)
{
    int a = b->nodes[node].first, c = a + 1;
    real ta, tc;
    int ha = node_hit(&b->nodes[a], s, ns->rr.tmin, ns->rr.tmax, &ta) || b->exhaustive;
    int hc = node_hit(&b->nodes[c], s, ns->rr.tmin, ns->rr.tmax, &tc) || b->exhaustive;
    if (ns->stats)
        ns->stats->nodes_visited += 2;
    if (ha && hc) {
        int far = tc < ta ? a : c;
        assert(*sp < BVH_MAX_DEPTH);
        stack[*sp].node = far;
        stack[(*sp)++].enter = far == a ? ta : tc;
        return far == a ? c : a;
    }
    return ha ? a : hc ? c : -1;
}

static void traverse_nearest(const bvh *b, const scene_prim *prims, nearest *ns)
{
    stack_entry stack[BVH_MAX_DEPTH];
    int sp = 0, node = 0;
    real enter;
    slab_ray s = slab_make(&ns->rr);
    if (ns->stats)
        ns->stats->nodes_visited++;
    if (!node_hit(&b->nodes[0], &s, ns->rr.tmin, ns->rr.tmax, &enter) && !b->exhaustive)
        return;
    for (;;) {
        const bvh_node *nd = &b->nodes[node];
        if (nd->count > 0) {
            for (int i = nd->first; i < nd->first + nd->count; i++)
                nearest_test(ns, prims, b->items[i]);
            node = -1;
        } else {
            node = descend(b, node, &s, ns, stack, &sp);
        }
        while (node < 0) {
            if (sp == 0)
                return;
            sp--;
            if (stack[sp].enter <= ns->rr.tmax || b->exhaustive)
                node = stack[sp].node;
        }
    }
}

static void nearest_pass(const bvh *b, const scene_prim *prims, nearest *ns)
{
    for (int i = 0; i < b->unbounded_count; i++)
        nearest_test(ns, prims, b->unbounded[i]);
    if (b->node_count > 0)
        traverse_nearest(b, prims, ns);
}

int bvh_intersect_stats(const bvh *b, const scene_prim *prims, ray *r, hit *h, bvh_stats *stats)
{
    nearest ns;
    ns.rr = *r;
    ns.count = ns.overflow = ns.fixed = 0;
    ns.t_near = r->tmax;
    ns.slack = TIE_REL * fmax(fabs(r->origin.x), fmax(fabs(r->origin.y), fabs(r->origin.z)));
    ns.stats = stats;
    nearest_pass(b, prims, &ns);
    if (ns.overflow) {
        ns.rr = *r;
        ns.rr.tmax = ns.t_near = tie_limit(&ns);
        ns.count = 0;
        ns.fixed = 1;
        nearest_pass(b, prims, &ns);
    }
    if (ns.count == 0)
        return 0;
    *h = *nearest_winner(&ns);
    r->tmax = h->t;
    return 1;
}

int bvh_intersect(const bvh *b, const scene_prim *prims, ray *r, hit *h)
{
    return bvh_intersect_stats(b, prims, r, h, NULL);
}

static int visit_prim(const scene_prim *prims, int index, const ray *r,
                      int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats)
{
    hit out[ISECT_MAX_CROSSINGS];
    if (stats)
        stats->prims_tested++;
    int n = isect_prim_all(&prims[index], r, out);
    for (int i = 0; i < n; i++) {
        out[i].prim = index;
        int stop = fn(ctx, &out[i]);
        if (stop)
            return stop;
    }
    return 0;
}

/* Depth-first over every node the ray meets; the stack holds at most one
 * pending sibling per level plus the node being expanded. */
static int traverse_all(const bvh *b, const scene_prim *prims, const ray *r,
                        int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats)
{
    int stack[BVH_MAX_DEPTH + 1], sp = 0;
    slab_ray s = slab_make(r);
    stack[sp++] = 0;
    while (sp > 0) {
        const bvh_node *nd = &b->nodes[stack[--sp]];
        real enter;
        if (stats)
            stats->nodes_visited++;
        if (!node_hit(nd, &s, r->tmin, r->tmax, &enter) && !b->exhaustive)
            continue;
        if (nd->count == 0) {
            assert(sp + 2 <= BVH_MAX_DEPTH + 1);
            stack[sp++] = nd->first + 1;
            stack[sp++] = nd->first;
            continue;
        }
        for (int i = nd->first; i < nd->first + nd->count; i++) {
            int stop = visit_prim(prims, b->items[i], r, fn, ctx, stats);
            if (stop)
                return stop;
        }
    }
    return 0;
}

int bvh_visit_stats(const bvh *b, const scene_prim *prims, const ray *r,
                    int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats)
{
    for (int i = 0; i < b->unbounded_count; i++) {
        int stop = visit_prim(prims, b->unbounded[i], r, fn, ctx, stats);
        if (stop)
            return stop;
    }
    return b->node_count > 0 ? traverse_all(b, prims, r, fn, ctx, stats) : 0;
}

int bvh_visit(const bvh *b, const scene_prim *prims, const ray *r,
              int (*fn)(void *ctx, const hit *h), void *ctx)
{
    return bvh_visit_stats(b, prims, r, fn, ctx, NULL);
}
