/*
 * bvh.c - traversal of the bounding volume hierarchy (bvh_build.c builds
 * it).
 *
 * Traversal: an explicit stack of BVH_MAX_DEPTH entries, nearest child
 * first, culling by the shrinking tmax (not when b->exhaustive: then every
 * node is entered, so every primitive is tested in the same order).  The
 * slab test is the robust one of Ize (slab.h).
 */
#include <float.h>
#include <string.h>
#include <assert.h>
#include "base/inline_hint.h"
#include "render/bvh.h"
#include "render/ray_copy.h"
#include "render/slab.h"
#include "render/slab_pair.h"
#include "base/next_up.h"

void bvh_free(bvh *b)
{
    mem m = b->mem;
    mem_free(&m, b->nodes, (size_t)b->node_cap * sizeof *b->nodes);
    mem_free(&m, b->items, b->item_bytes);
    mem_free(&m, b->unbounded, (size_t)b->unbounded_cap * sizeof *b->unbounded);
    mem_free(&m, b->hot, (size_t)b->item_count * sizeof *b->hot);
    mem_free(&m, b->hot_block, b->hot_block_bytes);
    memset(b, 0, sizeof *b);
    b->mem = m;
}

/* Whether the ray meets the node's box within [tmin, tmax]; *enter is the
 * entry distance.  oct is slab_octant(s), a constant in each copy of a
 * walk (HINT_IN_LINE below). */
static inline int node_hit(const bvh_node *nd, const slab_ray *s, int oct, real tmin, real tmax, real *enter)
{
    return slab_box_meets_neg(nd->lo, nd->hi, s, oct & 1, (oct >> 1) & 1, (oct >> 2) & 1, tmin, tmax, enter);
}

/* node_hit for a walk made once for all octants (traverse_from: made per
 * octant, its leaf's callbacks were no longer inlined and room at 40x30
 * took 8.5 % more instructions). */
static inline int node_hit_any(const bvh_node *nd, const slab_ray *s, real tmin, real tmax, real *enter)
{
    return slab_box_meets(nd->lo, nd->hi, s, tmin, tmax, enter);
}

/*
 * The nearest walk is made once per ray octant: each copy is inlined with the
 * octant a constant, so the slab test's three `neg ? hi : lo` choices
 * (a compare and a branch each, at every node: gcc tested inv's sign
 * again per node) fold away.  The arithmetic is slab_box_meets' own, the
 * same bits.  Only an inlining demand; Frama-C need not know it.
 */

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
 * stays one ulp past the window's far end (a primitive accepts t < tmax,
 * and the end belongs to the window), never past the caller's tmax, so
 * that no candidate is culled or rejected whatever was tested before it
 * ([BVH-TIE-ORDER-1]).  When more than TIE_MAX surfaces tie, a second pass
 * over the now known window finds the lowest index among all of them.
 */
#define TIE_REL 0x1p-46
enum { TIE_MAX = 8 };
/* nearest.rest: a candidate made whole, or made again (an item >= 0
 * otherwise). */
enum { REST_NONE = -1, REST_RETEST = -2 };

/* The ray's triangle shear, made at the first triangle test: most rays of
 * a scene with a few triangles test none (room.scene's two-triangle mirror:
 * the shear's divisions for every ray were 3 % of its instructions).  The
 * same shear, isect_shear_make of the same direction, whenever it is made. */
typedef struct lazy_shear {
    const ray *r;
    int made;
    isect_shear sh;
} lazy_shear;

/* Only the test whether the shear is made stays in line: where the making
 * was inlined too (at each triangle test of the walks), its divisions and
 * registers grew the walk's loop for every item (traverse_from of mesh at
 * 40x30: 518 M -> 575 M instructions, tenth round). */
HINT_OUT_OF_LINE static void shear_make_now(lazy_shear *z)
{
    isect_shear_make(z->r, &z->sh);
    z->made = 1;
}

static inline const isect_shear *shear_get(lazy_shear *z)
{
    if (!z->made)
        shear_make_now(z);
    return &z->sh;
}

/* The shear a test of p reads: a mesh's or a world-frame triangle's (the
 * hot triangles), NULL for any other part, which reads none (intersect.c,
 * part_hits: a transformed part makes its own for its local ray). */
static const isect_shear *shear_for(lazy_shear *z, const scene_prim *p)
{
    return p->kind == PRIM_MESH || (p->kind == PRIM_TRIANGLE && !p->frame) ? shear_get(z) : NULL;
}

typedef struct nearest {
    ray rr;
    hit cand[TIE_MAX];  /* the hits within the window of t_near */
    /* How a candidate's full hit is made once it has won: REST_NONE, it
     * is whole; REST_RETEST (a triangle's or plane's: only t, prim and
     * part), by the scene_prim's test on the ray as it was then (tmax
     * included), which gives the same bits; an item i >= 0 (a sphere's:
     * t, point, prim and part, its normal the costly rest), by
     * isect_hot_complete of its t and point with item i's record.
     * The tie rule reads t, prim and part alone. */
    int rest[TIE_MAX];
    real cand_tmax[TIE_MAX];
    int count;
    int overflow;       /* more than TIE_MAX candidates at once */
    int fixed;          /* second pass: rr.tmax is the final window's end */
    real t_near;        /* the least t found; in the second pass the window's end */
    real slack;         /* TIE_REL * |origin| */
    real tmax0;         /* the caller's tmax */
    bvh_stats *stats;
    lazy_shear sh;      /* the ray's triangle shear */
} nearest;

static real tie_end(real t_near, real slack)
{
    real limit = t_near + (TIE_REL * fabs(t_near) + slack);
    return limit > t_near ? limit : real_next_up(t_near);
}

static real tie_limit(const nearest *ns)
{
    return tie_end(ns->t_near, ns->slack);
}

real bvh_tie_end(real t_near, vec3 origin)
{
    return tie_end(t_near, TIE_REL * vec_max_abs(origin));
}

/* The tmax that accepts every t <= limit the caller's ray accepts. */
static real window_tmax(const nearest *ns, real limit)
{
    real past = real_next_up(limit);
    return past < ns->tmax0 ? past : ns->tmax0;
}

/* Orders hits by primitive, then part: the tie-break of the window. */
static int hit_order(const hit *a, const hit *b)
{
    if (a->prim != b->prim)
        return a->prim < b->prim ? -1 : 1;
    return (a->part > b->part) - (a->part < b->part);
}

/* Adds h to the candidates and drops those now beyond the window.  In the
 * second pass only the lowest index counts. */
static void nearest_add(nearest *ns, const hit *h, int rest)
{
    real tmax = ns->rr.tmax;
    if (ns->fixed) {
        if (ns->count == 0 || hit_order(h, &ns->cand[0]) < 0) {
            ns->cand[0] = *h;
            ns->rest[0] = rest;
            ns->cand_tmax[0] = tmax;
        }
        ns->count = 1;
        ns->rr.tmax = window_tmax(ns, ns->t_near);   /* t_near: the window's end, set by the caller */
        return;
    }
    if (ns->count == 0 || h->t < ns->t_near)
        ns->t_near = h->t;
    real limit = tie_limit(ns);
    int kept = 0;
    for (int i = 0; i < ns->count; i++)
        if (ns->cand[i].t <= limit) {
            /* Kept in place (most often) is not copied onto itself. */
            if (kept != i) {
                ns->rest[kept] = ns->rest[i];
                ns->cand_tmax[kept] = ns->cand_tmax[i];
                hit_copy(&ns->cand[kept], &ns->cand[i]);
            }
            kept++;
        }
    if (h->t <= limit) {
        if (kept < TIE_MAX) {
            ns->rest[kept] = rest;
            ns->cand_tmax[kept] = tmax;
            hit_copy(&ns->cand[kept++], h);
        } else
            ns->overflow = 1;
    }
    ns->count = kept;
    ns->rr.tmax = window_tmax(ns, limit);
}

static void nearest_test(nearest *ns, const scene_prim *prims, bvh_ref ref)
{
    hit h;
    const scene_prim *p = &prims[ref.prim];
    if (ns->stats)
        ns->stats->prims_tested++;
    /* A plane without a transform (unbounded: tested first, on every ray)
     * is a deferred candidate as a triangle is: its t alone, by the
     * plane_t its full test makes, and its point and normal only once it
     * has won (a ray that meets something before it, the floor behind a
     * ball, makes none). */
    if (p->kind == PRIM_PLANE && !p->frame) {
        hit d; /* deferred, as nearest_run_hit's */
        if (!isect_plane_nearest(p->u.plane.point, p->u.plane.normal, &ns->rr, &d.t))
            return;
        d.prim = ref.prim;
        d.part = ref.part;
        nearest_add(ns, &d, REST_RETEST);
        return;
    }
    if (!isect_part_sheared(p, ref.part, &ns->rr, shear_for(&ns->sh, p), &h))
        return;
    h.prim = ref.prim;
    nearest_add(ns, &h, REST_NONE);
}

/* Item i of the tree, not a triangle's record: by its hot record when it
 * has one. */
static void nearest_test_item(nearest *ns, const bvh *b, const scene_prim *prims, int i)
{
    bvh_hot hr = b->hot[i];
    if (hr.code == ISECT_HOT_NONE) {
        nearest_test(ns, prims, b->items[i]);
        return;
    }
    if (ns->stats)
        ns->stats->prims_tested++;
    hit h; /* a candidate (isect_hot_candidate), a miss is not read */
    /* A box makes its full hit at once, as isect_part (a winner made
     * again would cost a second test), a sphere all of it but the normal,
     * made once it has won from the point kept (a nearer hit found later
     * makes it needless: for 30 % of nested_glass's sphere hits); a
     * triangle's record does not come here (visit_hits' runs: its hit is
     * deferred). */
    /* The walk's own ray, not a copy (8 reals a test): the test shrinks
     * only its tmax, to the hit's t, and nearest_add reads the tmax it
     * had (the deferred candidates' cand_tmax), put back first. */
    real tmax = ns->rr.tmax;
    int met = isect_hot_candidate(hr.code, b->hot_reals + hr.at, &ns->rr, &h);
    ns->rr.tmax = tmax;
    assert(met >= 0);
    if (met > 0) {
        h.prim = b->items[i].prim;
        nearest_add(ns, &h, ISECT_HOT_KIND(hr.code) == ISECT_HOT_SPHERE ? i : REST_NONE);
    }
}

/*
 * A leaf's items [i, end), in order: each run of consecutive triangle
 * records is tested by isect_hot_triangle_run, which hands over its
 * crossed records one at a time (run_hit(ctx, item, t)), and every other
 * item goes to other(ctx, item), which counts its own test.  Every walk
 * shares it: the nearest walk, whose run_hit shrinks the ray's tmax (so
 * the run goes on from the next record with the ray as it is then, and *r
 * is read again), and the crossing walks of bvh_visit and
 * bvh_visit_counts.  The records are tested in the order, and with the
 * rays, that one call per item gave.  Stops at the first nonzero answer
 * of a callback and returns it.  Inline, with the callbacks constant at
 * each call.
 */
static inline int visit_hits(const bvh *b, int i, int end, const ray *r, lazy_shear *z, bvh_stats *stats,
                             int (*run_hit)(void *ctx, int item, real t), int (*other)(void *ctx, int item),
                             void *ctx)
{
    while (i < end) {
        if (ISECT_HOT_KIND(b->hot[i].code) != ISECT_HOT_TRIANGLE) {
            int stop = other(ctx, i++);
            if (stop)
                return stop;
            continue;
        }
        real t;
        int k = i + isect_hot_triangle_run(b->hot + i, end - i, b->hot_reals, r, shear_get(z), &t);
        int met = k < end && ISECT_HOT_KIND(b->hot[k].code) == ISECT_HOT_TRIANGLE;
        if (stats)
            stats->prims_tested += k + met - i;
        if (met) {
            int stop = run_hit(ctx, k, t);
            if (stop)
                return stop;
        }
        i = k + met;
    }
    return 0;
}

/* The nearest walk's leaf: visit_hits' callbacks.  A triangle crossed is
 * a deferred candidate (see nearest). */
typedef struct nearest_leaf {
    nearest *ns;
    const bvh *b;
    const scene_prim *prims;
} nearest_leaf;

static int nearest_run_hit(void *ctx, int item, real t)
{
    const nearest_leaf *l = ctx;
    hit h; /* deferred: t, prim and part are all a candidate is read for */
    h.t = t;
    h.prim = l->b->items[item].prim;
    h.part = l->b->items[item].part;
    nearest_add(l->ns, &h, REST_RETEST);
    return 0;
}

static int nearest_other(void *ctx, int item)
{
    const nearest_leaf *l = ctx;
    nearest_test_item(l->ns, l->b, l->prims, item);
    return 0;
}

/* The lowest-index candidate: the nearest hit (see above). */
static int nearest_winner(const nearest *ns)
{
    int best = 0;
    for (int i = 1; i < ns->count; i++)
        if (hit_order(&ns->cand[i], &ns->cand[best]) < 0)
            best = i;
    return best;
}

/* Candidate w made whole in *h (see nearest.rest); r: the caller's ray,
 * whose direction the walk's copy has. */
static void winner_hit(const bvh *b, const scene_prim *prims, nearest *ns, int w, const ray *r, hit *h)
{
    const hit *c = &ns->cand[w];
    if (ns->rest[w] == REST_RETEST) {
        ray at;
        ray_copy(&at, r);
        at.tmax = ns->cand_tmax[w];
        int met = isect_part_sheared(&prims[c->prim], c->part, &at, shear_for(&ns->sh, &prims[c->prim]), h);
        assert(met && h->t == c->t);
        (void)met;
    } else if (ns->rest[w] >= 0) {
        bvh_hot hr = b->hot[ns->rest[w]];
        h->t = c->t;
        h->point = c->point;
        isect_hot_complete(hr.code, b->hot_reals + hr.at, r->dir, h);
    } else {
        hit_copy(h, c);
    }
    h->prim = c->prim;
}

/* r's shear, not made yet (r must outlast it). */
static lazy_shear shear_lazy(const ray *r)
{
    lazy_shear z;
    z.r = r;
    z.made = 0;
    return z;
}

typedef struct stack_entry {
    int node;
    real enter;
} stack_entry;

/* The slab ray of the nearest walk, and where SSE2 tests both children
 * of a node at once its pair form (slab_pair.h), made once the root is
 * met.  The shadow walks (traverse_from) keep the test of one node: made
 * for every shadow ray, or at its first inner node, the pair form cost
 * demo.scene 5 % and 1.6 % more instructions (a bundle's walk starts
 * from kept nodes, many of them leaves). */
typedef struct walk_ray {
    slab_ray s;
#ifdef SLAB_PAIR_SSE2
    slab_pair_ray p;
#endif
} walk_ray;

/* Whether the ray meets node a (bit 0) and a + 1 (bit 1), their entries in
 * *ta and *tc: node_hit of each.  oct as node_hit's, a constant in each
 * copy of the walk: the pair test's offsets fold. */
static inline HINT_IN_LINE int children_hit(const bvh_node *a, const walk_ray *w, int oct, real tmin, real tmax,
                                               real *ta, real *tc)
{
#ifdef SLAB_PAIR_SSE2
    int nx = oct & 1, ny = (oct >> 1) & 1, nz = (oct >> 2) & 1;
    return slab_pair_meets(a, &w->p, slab_pair_near_at(0, nx), slab_pair_far_at(0, nx), slab_pair_near_at(1, ny),
                           slab_pair_far_at(1, ny), slab_pair_near_at(2, nz), slab_pair_far_at(2, nz), tmin, tmax, ta,
                           tc);
#else
    return node_hit(a, &w->s, oct, tmin, tmax, ta) | node_hit(a + 1, &w->s, oct, tmin, tmax, tc) << 1;
#endif
}

/*
 * Whether the walks may leave out the test of the root's own box: when it
 * is an inner node they go on only to the children that pass their own
 * tests, and a child passes only where the root would have.  A child's box
 * lies inside its parent's (each is its parts' union widened by 2^-40 of
 * its largest magnitude, and the parent's union and magnitude are the
 * larger: bvh_build.c), the slab test is monotone in the box's bounds
 * (slab.h) and in tmax, which only falls during a walk, and a NaN bound
 * narrows nothing: so a ray that fails the root fails both children, and
 * the same nodes are entered, the same parts tested in the same order.
 * With the tree exhaustive the root's answer was never read.  Only the
 * count of boxes tested (bvh_stats) is one less.
 */
static inline int root_decides_nothing(const bvh *b)
{
    return b->nodes[0].count == 0;
}

/* Among the children of an inner node that the ray meets, goes to the
 * nearer and pushes the other; returns the next node or -1.  all is 3 when
 * the tree is exhaustive (both met), else 0.  Where child a is met, the
 * next node stays a branch (predicted, the next node's loads start before
 * the slab test ends: a select there took 1.30 of the time, an earlier
 * round),
 * but whether c is pushed too is a count (the far child written always):
 * the "both met" branch was grid1k's most mispredicted (spec/performance.md,
 * "Nineteenth round: walks' branches"). */
static inline HINT_IN_LINE int descend(const bvh *b, int node, const walk_ray *s, int oct, nearest *ns,
                                           stack_entry *stack, int *sp, int all)
{
    int a = b->nodes[node].first, c = a + 1;
    real ta, tc;
    int met = children_hit(&b->nodes[a], s, oct, ns->rr.tmin, ns->rr.tmax, &ta, &tc) | all;
    if (ns->stats)
        ns->stats->nodes_visited += 2;
    assert(*sp < BVH_MAX_DEPTH);
    if (met & 1) {
        if ((met >> 1) & (tc < ta)) {
            stack[*sp].node = a;
            stack[(*sp)++].enter = ta;
            return c;
        }
        stack[*sp].node = c;
        stack[*sp].enter = tc;
        *sp += met >> 1;
        return a;
    }
    return met ? c : -1;
}

static inline HINT_IN_LINE void traverse_nearest_oct(const bvh *b, const scene_prim *prims, nearest *ns,
                                                        const slab_ray *sr, int oct)
{
    stack_entry stack[BVH_MAX_DEPTH];
    int sp = 0, node = 0;
    const int all = b->exhaustive ? 3 : 0; /* exhaustive: both children met */
    real enter;
    walk_ray w, *s = &w;
    w.s = *sr;
    /* An inner root is not tested (root_decides_nothing); a leaf is. */
    if (!root_decides_nothing(b)) {
        if (ns->stats)
            ns->stats->nodes_visited++;
        if (!node_hit(&b->nodes[0], &w.s, oct, ns->rr.tmin, ns->rr.tmax, &enter) && !b->exhaustive)
            return;
    }
#ifdef SLAB_PAIR_SSE2
    slab_pair_make(&w.s, &w.p);
#endif
    for (;;) {
        const bvh_node *nd = &b->nodes[node];
        if (nd->count > 0) {
            nearest_leaf l = {ns, b, prims};
            visit_hits(b, nd->first, nd->first + nd->count, &ns->rr, &ns->sh, ns->stats, nearest_run_hit,
                       nearest_other, &l);
            node = -1;
        } else {
            node = descend(b, node, s, oct, ns, stack, &sp, all);
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

/* One copy of the walk per octant (HINT_IN_LINE). */
static void traverse_nearest(const bvh *b, const scene_prim *prims, nearest *ns)
{
    slab_ray s = slab_make(&ns->rr);
    switch (slab_octant(&s)) {
    case 0: traverse_nearest_oct(b, prims, ns, &s, 0); break;
    case 1: traverse_nearest_oct(b, prims, ns, &s, 1); break;
    case 2: traverse_nearest_oct(b, prims, ns, &s, 2); break;
    case 3: traverse_nearest_oct(b, prims, ns, &s, 3); break;
    case 4: traverse_nearest_oct(b, prims, ns, &s, 4); break;
    case 5: traverse_nearest_oct(b, prims, ns, &s, 5); break;
    case 6: traverse_nearest_oct(b, prims, ns, &s, 6); break;
    default: traverse_nearest_oct(b, prims, ns, &s, 7); break;
    }
}

static void nearest_pass(const bvh *b, const scene_prim *prims, nearest *ns)
{
    for (int i = 0; i < b->unbounded_count; i++)
        nearest_test(ns, prims, b->unbounded[i]);
    if (b->node_count > 0)
        traverse_nearest(b, prims, ns);
}

int bvh_intersect_ties(const bvh *b, const scene_prim *prims, ray *r, hit *h, bvh_stats *stats, int *tied)
{
    nearest ns;
    ray_copy(&ns.rr, r);
    ns.count = ns.overflow = ns.fixed = 0;
    ns.t_near = ns.tmax0 = r->tmax;
    ns.slack = TIE_REL * vec_max_abs(r->origin);
    ns.stats = stats;
    ns.sh = shear_lazy(r);
    nearest_pass(b, prims, &ns);
    if (ns.overflow) {
        ray_copy(&ns.rr, r);
        ns.t_near = tie_limit(&ns);
        ns.rr.tmax = window_tmax(&ns, ns.t_near);
        ns.count = 0;
        ns.fixed = 1;
        nearest_pass(b, prims, &ns);
    }
    if (tied)
        *tied = ns.overflow ? TIE_MAX + 1 : ns.count;
    if (ns.count == 0)
        return 0;
    winner_hit(b, prims, &ns, nearest_winner(&ns), r, h);
    r->tmax = h->t;
    return 1;
}

int bvh_intersect_stats(const bvh *b, const scene_prim *prims, ray *r, hit *h, bvh_stats *stats)
{
    return bvh_intersect_ties(b, prims, r, h, stats, NULL);
}

int bvh_intersect(const bvh *b, const scene_prim *prims, ray *r, hit *h)
{
    return bvh_intersect_stats(b, prims, r, h, NULL);
}

/* One walk over every crossing: either each crossing (fn) or each part's
 * number of crossings (count_fn). */
typedef struct walk {
    const scene_prim *prims;
    const ray *r;
    int (*fn)(void *ctx, const hit *h);
    int (*count_fn)(void *ctx, bvh_ref ref, int crossings);
    void *ctx;
    bvh_stats *stats;
    lazy_shear *sh;
    real node_tmin; /* the nodes' slab tests start here (>= r->tmin) */
} walk;

/* A part's crossings, to fn or counted, its test not counted in stats. */
/* The crossings the counting walks count for a part tested by its own
 * test (no hot record). */
static int part_crossings(const scene_prim *prims, bvh_ref ref, const ray *r, lazy_shear *sh)
{
    const scene_prim *p = &prims[ref.prim];
    return isect_part_crossings_sheared(p, ref.part, r, shear_for(sh, p));
}

/* The same for an unbounded part (every walk tests it): a plane in the
 * world frame is counted by isect_plane_crossings at once, as
 * isect_part_crossings would count it, without a frame for hits.  One
 * function for bvh_visit_counts and bvh_any_crossing, whose answers
 * [SHADE-SHORTCUT-ANY-1] needs to agree. */
static int unbounded_crossings(const scene_prim *prims, bvh_ref ref, const ray *r, lazy_shear *sh)
{
    const scene_prim *p = &prims[ref.prim];
    if (p->kind == PRIM_PLANE && !p->frame)
        return isect_plane_crossings(p->u.plane.point, p->u.plane.normal, r);
    return part_crossings(prims, ref, r, sh);
}

static int visit_part_uncounted(const walk *w, bvh_ref ref)
{
    hit out[ISECT_MAX_CROSSINGS];
    if (w->count_fn) {
        int n = part_crossings(w->prims, ref, w->r, w->sh);
        return n > 0 ? w->count_fn(w->ctx, ref, n) : 0;
    }
    int n = isect_part_all_sheared(&w->prims[ref.prim], ref.part, w->r, shear_for(w->sh, &w->prims[ref.prim]), out);
    for (int i = 0; i < n; i++) {
        out[i].prim = ref.prim;
        int stop = w->fn(w->ctx, &out[i]);
        if (stop)
            return stop;
    }
    return 0;
}

static int visit_part(const walk *w, bvh_ref ref)
{
    if (w->stats)
        w->stats->prims_tested++;
    return visit_part_uncounted(w, ref);
}

/* The walks' leaf: visit_hits' callbacks.  A triangle's record crossed
 * counts 1 (isect_hot_crossings); for fn its one crossing is made by the
 * part's own test, which finds it as the record did (intersect.h: the
 * same bits), and a record not crossed has none to report.  Any other
 * item is counted by its hot record when it has one. */
typedef struct walk_leaf {
    const walk *w;
    const bvh *b;
} walk_leaf;

static int walk_run_hit(void *ctx, int item, real t)
{
    const walk_leaf *l = ctx;
    (void)t;
    if (!l->w->count_fn)
        return visit_part_uncounted(l->w, l->b->items[item]);
    return l->w->count_fn(l->w->ctx, l->b->items[item], 1);
}

static int walk_other(void *ctx, int item)
{
    const walk_leaf *l = ctx;
    const walk *w = l->w;
    bvh_hot hr = l->b->hot[item];
    if (!w->count_fn || hr.code == ISECT_HOT_NONE)
        return visit_part(w, l->b->items[item]);
    if (w->stats)
        w->stats->prims_tested++;
    int n = isect_hot_crossings(hr.code, l->b->hot_reals + hr.at, w->r, NULL);
    return n > 0 ? w->count_fn(w->ctx, l->b->items[item], n) : 0;
}

#ifdef SLAB_PAIR_SSE2
/* The pair test for traverse_from, out of line: inlined, it grew the
 * walk's loop, which a bundle's walk (many starts, few inner nodes) runs
 * through far more often than it descends (demo.scene +1.4 %). */
HINT_OUT_OF_LINE static int children_meet_any(const bvh_node *a, const slab_ray *s, real tmin, real tmax)
{
    real ta, tc;
    return slab_pair_meets_slab(a, s, tmin, tmax, &ta, &tc);
}
#endif

/* The shadow walks' way down from an inner node whose children a and
 * a + 1 the ray meets as met says (bit 0: a, bit 1: a + 1): the next node,
 * a where it is met, else a + 1 where it is, else NULL; a met a + 1 is
 * pushed beside a.  The sibling written always, kept when met: a count,
 * not a branch (grid1k: its branch mispredicted 219 k of 1.68 M). */
static inline HINT_IN_LINE const bvh_node *enter_met(const bvh *b, int a, int met, int *stack, int *sp)
{
    if (met & 1) {
        assert(*sp < BVH_MAX_DEPTH);
        stack[*sp] = a + 1;
        *sp += met >> 1;
        return &b->nodes[a];
    }
    return met & 2 ? &b->nodes[a + 1] : NULL;
}

/* Depth-first over every node below each of start[0..starts-1] (itself
 * included) that the ray meets, the starts in turn, the first child first.
 * Both children of an inner node are tested together (adjacent in memory,
 * so their loads overlap) and only those met are entered; the stack holds
 * at most one pending sibling per level.  One loop for the whole list, not
 * a call per start: a bundle keeps about two nodes per shadow ray, and each
 * call copied the slab ray and saved its registers again.  A start below 0
 * is ~i, the bundle's own node runs[i]: a run of a kept leaf's parts, with
 * the leaf's box (bvh_bundle_make). */
static int traverse_from(const bvh *b, const walk *w, const slab_ray *sr, const int *start, const bvh_node *runs,
                         int starts)
{
    int stack[BVH_MAX_DEPTH];
    real tmin = w->node_tmin, tmax = w->r->tmax, enter;
    const int all = b->exhaustive ? 3 : 0; /* exhaustive: both children met */
    /* A copy: through the pointer each test would load it again, the
     * callback being opaque to the compiler. */
    const slab_ray copy = *sr, *s = &copy;
    for (int k = 0; k < starts; k++) {
        int sp = 0;
        const bvh_node *nd = start[k] >= 0 ? &b->nodes[start[k]] : &runs[~start[k]];
        /* The root, when inner, is not tested (root_decides_nothing); a
         * bundle's kept node is: its parents were not. */
        if (start[k] != 0 || !root_decides_nothing(b)) {
            if (w->stats)
                w->stats->nodes_visited++;
            if (!node_hit_any(nd, s, tmin, tmax, &enter) && !b->exhaustive)
                continue;
        }
        for (;;) {
            if (nd->count == 0) {
                int a = nd->first;
#ifdef SLAB_PAIR_SSE2
                int met = children_meet_any(&b->nodes[a], s, tmin, tmax);
#else
                int met = node_hit_any(&b->nodes[a], s, tmin, tmax, &enter) |
                          node_hit_any(&b->nodes[a + 1], s, tmin, tmax, &enter) << 1;
#endif
                met |= all;
                if (w->stats)
                    w->stats->nodes_visited += 2;
                const bvh_node *next = enter_met(b, a, met, stack, &sp);
                if (next) {
                    nd = next;
                    continue;
                }
            } else {
                walk_leaf l = {w, b};
                int stop = visit_hits(b, nd->first, nd->first + nd->count, w->r, w->sh, w->stats, walk_run_hit,
                                      walk_other, &l);
                if (stop)
                    return stop;
            }
            if (sp == 0)
                break;
            nd = &b->nodes[stack[--sp]];
        }
    }
    return 0;
}

/* An unbounded part: counted by unbounded_crossings, or its hits made. */
static int visit_unbounded(const walk *w, bvh_ref ref)
{
    if (!w->count_fn)
        return visit_part(w, ref);
    if (w->stats)
        w->stats->prims_tested++;
    int n = unbounded_crossings(w->prims, ref, w->r, w->sh);
    return n > 0 ? w->count_fn(w->ctx, ref, n) : 0;
}

/*
 * [SHADE-SHORTCUT-OPEN-1] A bundle's kept leaves and runs, each of
 * triangle records alone (bundle->boxed 0), their parts tested in the
 * list's order without their boxes.  A box test only decides whether the
 * parts are tested: a box the ray fails holds no t its parts' tests report
 * ([BVH-CULL-PAD-1]; the exhaustive walk of [SHADE-SHORTCUT-BVH-1] rests
 * on the same), so such a part reports no crossing and makes no call of
 * fn; the calls are the boxed walk's, in its order.  The leaves' boxes
 * failed only about one test in eleven (mesh.scene), and the slab ray's
 * three divisions and each box's test cost more than the triangles they
 * kept out, most of which the run's quick miss tells apart.
 */
static int walk_open(const bvh *b, const walk *w, const bvh_bundle *bundle)
{
    for (int k = 0; k < bundle->count; k++) {
        int e = bundle->node[k];
        const bvh_node *nd = e >= 0 ? &b->nodes[e] : &bundle->runs[~e];
        walk_leaf l = {w, b};
        int stop = visit_hits(b, nd->first, nd->first + nd->count, w->r, w->sh, w->stats, walk_run_hit, walk_other,
                              &l);
        if (stop)
            return stop;
    }
    return 0;
}

/* The unbounded parts, then the tree: from its root, or (bundle) from the
 * nodes a bundle kept, in their order. */
static int walk_all(const bvh *b, const walk *w, const bvh_bundle *bundle)
{
    unsigned passed = bundle ? bundle->planes_passed : 0;   /* [SHADE-SHORTCUT-PLANE-1] */
    for (int i = 0; i < b->unbounded_count; i++) {
        if (i < 32 && passed >> i & 1u)
            continue;
        int stop = visit_unbounded(w, b->unbounded[i]);
        if (stop)
            return stop;
    }
    if (b->node_count == 0 || (bundle && bundle->count == 0))
        return 0;
    if (bundle && bundle->boxed == 0 && !b->exhaustive)
        return walk_open(b, w, bundle);
    static const int root = 0;
    slab_ray s = slab_make(w->r);
    return traverse_from(b, w, &s, bundle ? bundle->node : &root, bundle ? bundle->runs : NULL,
                         bundle ? bundle->count : 1);
}

/*
 * The any-crossing walk (bvh_any_crossing): stops at the first part with a
 * crossing, so the order of its tests is free, and it takes the farther
 * child first where both are met (the one nearer the light): on grid1k a
 * blocked ray then made 25.8 node tests, against 35.7 nearer child first
 * and 35.1 in the tree's order (spec/performance.md, twenty-first round,
 * shadow and reflection walks).  A part's crossings are counted as bvh_visit_counts
 * counts them (visit_unbounded, walk_other, walk_run_hit: the same tests
 * on the same ray), so a part crossed here is one it reports.
 */
typedef struct any_leaf {
    const bvh *b;
    const scene_prim *prims;
    const ray *r;
    lazy_shear *sh;
    bvh_stats *stats;
    bvh_ref found;
} any_leaf;

static int any_found(any_leaf *l, bvh_ref ref)
{
    l->found = ref;
    return 1;
}

static int any_run_hit(void *ctx, int item, real t)
{
    any_leaf *l = ctx;
    (void)t;
    return any_found(l, l->b->items[item]);
}

static int any_other(void *ctx, int item)
{
    any_leaf *l = ctx;
    bvh_hot hr = l->b->hot[item];
    bvh_ref ref = l->b->items[item];
    if (l->stats)
        l->stats->prims_tested++;
    int crossed = hr.code == ISECT_HOT_NONE ? part_crossings(l->prims, ref, l->r, l->sh) > 0
                                            : isect_hot_crossed(hr.code, l->b->hot_reals + hr.at, l->r, NULL);
    return crossed ? any_found(l, ref) : 0;
}

/* The tree's part of the walk for one octant (a constant in each copy, as
 * traverse_nearest_oct's), the pair form made once. */
static inline HINT_IN_LINE int any_walk_oct(const bvh *b, any_leaf *l, const slab_ray *sr, int oct)
{
    int stack[BVH_MAX_DEPTH], sp = 0;
    const int all = b->exhaustive ? 3 : 0; /* exhaustive: both children met */
    real tmin = l->r->tmin, tmax = l->r->tmax, ta, tc;
    walk_ray w;
    w.s = *sr;
    const bvh_node *nd = &b->nodes[0];
    if (!root_decides_nothing(b)) {
        if (l->stats)
            l->stats->nodes_visited++;
        if (!node_hit(nd, &w.s, oct, tmin, tmax, &ta) && !b->exhaustive)
            return 0;
    }
#ifdef SLAB_PAIR_SSE2
    slab_pair_make(&w.s, &w.p);
#endif
    for (;;) {
        if (nd->count == 0) {
            int a = nd->first;
            int met = children_hit(&b->nodes[a], &w, oct, tmin, tmax, &ta, &tc) | all;
            if (l->stats)
                l->stats->nodes_visited += 2;
            assert(sp < BVH_MAX_DEPTH);
            if (met == 3 && ta < tc) {
                stack[sp++] = a;
                nd = &b->nodes[a + 1];
                continue;
            }
            const bvh_node *next = enter_met(b, a, met, stack, &sp);
            if (next) {
                nd = next;
                continue;
            }
        } else if (visit_hits(b, nd->first, nd->first + nd->count, l->r, l->sh, l->stats, any_run_hit, any_other,
                              l)) {
            return 1;
        }
        if (sp == 0)
            return 0;
        nd = &b->nodes[stack[--sp]];
    }
}

static int any_walk(const bvh *b, any_leaf *l)
{
    slab_ray s = slab_make(l->r);
    switch (slab_octant(&s)) {
    case 0: return any_walk_oct(b, l, &s, 0);
    case 1: return any_walk_oct(b, l, &s, 1);
    case 2: return any_walk_oct(b, l, &s, 2);
    case 3: return any_walk_oct(b, l, &s, 3);
    case 4: return any_walk_oct(b, l, &s, 4);
    case 5: return any_walk_oct(b, l, &s, 5);
    case 6: return any_walk_oct(b, l, &s, 6);
    default: return any_walk_oct(b, l, &s, 7);
    }
}

int bvh_any_crossing(const bvh *b, const scene_prim *prims, const ray *r, bvh_ref *found, bvh_stats *stats)
{
    lazy_shear sh = shear_lazy(r);
    any_leaf l = {b, prims, r, &sh, stats, {-1, 0}};
    for (int i = 0; i < b->unbounded_count; i++) {
        if (stats)
            stats->prims_tested++;
        if (unbounded_crossings(prims, b->unbounded[i], r, &sh) > 0) {
            *found = b->unbounded[i];
            return 1;
        }
    }
    if (b->node_count > 0 && any_walk(b, &l)) {
        *found = l.found;
        return 1;
    }
    return 0;
}

int bvh_visit_stats(const bvh *b, const scene_prim *prims, const ray *r,
                    int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats)
{
    return bvh_visit_window(b, prims, r, r->tmin, fn, ctx, stats);
}

/* [SHADE-SHORTCUT-GATHER-1] Only the nodes change: every part tested
 * gets the ray r itself, so it reports the same crossings, bit for bit, in
 * the same order; a box the ray meets only before node_tmin is left out. */
int bvh_visit_window(const bvh *b, const scene_prim *prims, const ray *r, real node_tmin,
                     int (*fn)(void *ctx, const hit *h), void *ctx, bvh_stats *stats)
{
    lazy_shear sh = shear_lazy(r);
    walk w = {prims, r, fn, NULL, ctx, stats, &sh, node_tmin > r->tmin ? node_tmin : r->tmin};
    return walk_all(b, &w, NULL);
}

int bvh_visit(const bvh *b, const scene_prim *prims, const ray *r,
              int (*fn)(void *ctx, const hit *h), void *ctx)
{
    return bvh_visit_stats(b, prims, r, fn, ctx, NULL);
}

int bvh_visit_counts(const bvh *b, const scene_prim *prims, const ray *r,
                     int (*fn)(void *ctx, bvh_ref ref, int crossings), void *ctx, bvh_stats *stats)
{
    lazy_shear sh = shear_lazy(r);
    walk w = {prims, r, NULL, fn, ctx, stats, &sh, r->tmin};
    return walk_all(b, &w, NULL);
}

/*
 * [SHADE-SHORTCUT-BUNDLE-1] The walk of bvh_visit_counts over the kept
 * nodes alone.  A box that holds another gets through the slab test
 * whenever the inner one does (each slab bound is a rounded product of a
 * rounded difference, monotone in the plane's coordinate; a NaN bound
 * narrows nothing), and a child's box lies inside its parent's (each is
 * its parts' union widened by 2^-40 of its largest magnitude, and the
 * parent's union and magnitude are the larger: bvh_build.c), so the
 * whole walk reaches a node exactly when the node's own box passes.  The
 * nodes left out are ones no ray of the bundle passes, and the kept ones
 * come in depth-first order: the same parts are tested in the same order.
 */
int bvh_visit_counts_bundle(const bvh *b, const scene_prim *prims, const ray *r, const bvh_bundle *bundle,
                            int (*fn)(void *ctx, bvh_ref ref, int crossings), void *ctx, bvh_stats *stats)
{
    if (!bundle || bundle->count < 0)
        return bvh_visit_counts(b, prims, r, fn, ctx, stats);
    lazy_shear sh = shear_lazy(r);
    walk w = {prims, r, NULL, fn, ctx, stats, &sh, r->tmin};
    return walk_all(b, &w, bundle);
}
