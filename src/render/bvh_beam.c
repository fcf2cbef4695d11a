/*
 * bvh_beam.c - camera-ray beams (bvh_beam.h, spec/numerics.md
 * [BVH-BEAM-1]).
 */
#include <string.h>
#include "render/bvh_beam.h"
#include "render/slab.h"
#include "render/slab_pair.h"

/* A zero or non-finite 1/d (a direction parallel to an axis's slabs)
 * leaves a 0 * inf in the slab test, whose NaN the beam's bounds do not
 * hold: refused. */
static int inverse_usable(real inv)
{
    return inv != 0 && isfinite(inv);
}

static int same_start(const ray *a, const ray *b)
{
    return memcmp(&a->origin, &b->origin, sizeof a->origin) == 0 && b->tmin == 0 && b->tmax == INFINITY;
}

int bvh_beam_bounds(const ray *rays, int n, bvh_beam *out)
{
    if (n < 1)
        return 0;
    slab_ray s0 = slab_make(&rays[0]);
    out->o = s0.o;
    out->lo = out->hi = s0.inv;
    for (int k = 0; k < 3; k++)
        out->neg[k] = s0.neg[k];
    for (int i = 0; i < n; i++) {
        slab_ray s = slab_make(&rays[i]);
        if (!same_start(&rays[0], &rays[i]) || slab_octant(&s) != slab_octant(&s0))
            return 0;
        if (!inverse_usable(s.inv.x) || !inverse_usable(s.inv.y) || !inverse_usable(s.inv.z))
            return 0;
        out->lo = vec_make(s.inv.x < out->lo.x ? s.inv.x : out->lo.x, s.inv.y < out->lo.y ? s.inv.y : out->lo.y,
                           s.inv.z < out->lo.z ? s.inv.z : out->lo.z);
        out->hi = vec_make(s.inv.x > out->hi.x ? s.inv.x : out->hi.x, s.inv.y > out->hi.y ? s.inv.y : out->hi.y,
                           s.inv.z > out->hi.z ? s.inv.z : out->hi.z);
    }
    return 1;
}

/* One axis of the beam test: slab_ends' entry and exit for 1/d at either
 * end of [lo, hi], the least entry and the largest exit (a rounded product
 * by a fixed difference is monotone in 1/d, so every ray's lie between),
 * then slab_box_meets_neg's selects. */
static void beam_axis(real near, real far, real o, real lo, real hi, real *tn, real *least)
{
    real a = near - o, f = far - o;
    real p = a * lo, q = a * hi, u = f * lo, v = f * hi;
    real t0 = q < p ? q : p, t1 = v > u ? v : u;
    *tn = t0 > *tn ? t0 : *tn;
    *least = t1 < *least ? t1 : *least;
}

int bvh_beam_meets(const bvh_beam *beam, vec3 lo, vec3 hi)
{
    const real tmax = INFINITY;
    real tn = 0, least = INFINITY;
    beam_axis(beam->neg[0] ? hi.x : lo.x, beam->neg[0] ? lo.x : hi.x, beam->o.x, beam->lo.x, beam->hi.x, &tn, &least);
    beam_axis(beam->neg[1] ? hi.y : lo.y, beam->neg[1] ? lo.y : hi.y, beam->o.y, beam->lo.y, beam->hi.y, &tn, &least);
    beam_axis(beam->neg[2] ? hi.z : lo.z, beam->neg[2] ? lo.z : hi.z, beam->o.z, beam->lo.z, beam->hi.z, &tn, &least);
    least *= 1.0 + copysign(SLAB_EXIT_PAD, least);
    return tn <= (least < tmax ? least : tmax);
}

typedef struct prune {
    const bvh *b;
    const bvh_beam *beam;
    bvh_beam_tree *tree;
    int full;          /* the kept nodes passed tree->cap */
#ifdef SLAB_PAIR_SSE2
    __m128d o[3], lo[3], hi[3];
    size_t near_at[3], far_at[3];
#endif
} prune;

#ifdef SLAB_PAIR_SSE2
static void prune_lanes(prune *p)
{
    const bvh_beam *m = p->beam;
    const real o[3] = {m->o.x, m->o.y, m->o.z}, lo[3] = {m->lo.x, m->lo.y, m->lo.z}, hi[3] = {m->hi.x, m->hi.y, m->hi.z};
    for (int k = 0; k < 3; k++) {
        p->o[k] = _mm_set1_pd(o[k]);
        p->lo[k] = _mm_set1_pd(lo[k]);
        p->hi[k] = _mm_set1_pd(hi[k]);
        p->near_at[k] = slab_pair_near_at(k, m->neg[k]);
        p->far_at[k] = slab_pair_far_at(k, m->neg[k]);
    }
}

/* beam_axis in both lanes: MINPD and MAXPD return their second operand
 * unless the first is less (greater), the ternaries' own choices. */
static inline void pair_axis(const prune *p, const bvh_node *a, int k, __m128d *tn, __m128d *least)
{
    __m128d n = _mm_sub_pd(slab_pair_load(a, p->near_at[k]), p->o[k]);
    __m128d f = _mm_sub_pd(slab_pair_load(a, p->far_at[k]), p->o[k]);
    __m128d t0 = _mm_min_pd(_mm_mul_pd(n, p->hi[k]), _mm_mul_pd(n, p->lo[k]));
    __m128d t1 = _mm_max_pd(_mm_mul_pd(f, p->hi[k]), _mm_mul_pd(f, p->lo[k]));
    *tn = _mm_max_pd(t0, *tn);
    *least = _mm_min_pd(t1, *least);
}
#endif

/* bvh_beam_meets of node a (bit 0) and a + 1 (bit 1): with SSE2 both at
 * once, each lane the scalar test's operations in its order (the same
 * bits, as slab_pair.h's form is slab_box_meets_neg's). */
static int pair_meets(const prune *p, const bvh_node *a)
{
#ifdef SLAB_PAIR_SSE2
    __m128d tn = _mm_setzero_pd(), least = _mm_load_pd(slab_pair_k[0]);
    pair_axis(p, a, 0, &tn, &least);
    pair_axis(p, a, 1, &tn, &least);
    pair_axis(p, a, 2, &tn, &least);
    real ta, tc;
    return slab_pair_end(tn, least, INFINITY, &ta, &tc);
#else
    return bvh_beam_meets(p->beam, a[0].lo, a[0].hi) | bvh_beam_meets(p->beam, a[1].lo, a[1].hi) << 1;
#endif
}

/*
 * The record in the pruned tree of node x, which the beam meets, in *rec:
 * returns 0 when no ray of the beam can take a candidate below x (x is
 * inner and no child is kept).  A child is kept when the beam meets it and
 * it is kept by this rule.  An inner node with one kept child is that
 * child's record under x's own box (the box its parent's pair test
 * reads); with both kept, their records go into two adjacent new slots.
 * The recursion is at most the tree's depth.
 */
static int keep(prune *p, int x, bvh_node *rec)
{
    const bvh_node *nd = &p->b->nodes[x];
    *rec = *nd;
    if (nd->count > 0)
        return 1;
    if (p->full)
        return 0; /* given up: no more tests */
    bvh_node ra, rc;
    int met = pair_meets(p, &p->b->nodes[nd->first]);
    int ka = (met & 1) && keep(p, nd->first, &ra), kc = (met & 2) && keep(p, nd->first + 1, &rc);
    if (p->full)
        return 0;
    if (ka && kc) {
        bvh_beam_tree *t = p->tree;
        if (t->count > t->cap - 2) {
            p->full = 1;
            return 0;
        }
        t->nodes[t->count] = ra;
        t->nodes[t->count + 1] = rc;
        rec->first = t->count;
        t->count += 2;
        return 1;
    }
    if (!ka && !kc)
        return 0;
    rec->first = ka ? ra.first : rc.first;
    rec->count = ka ? ra.count : rc.count;
    return 1;
}

int bvh_beam_prune(const bvh *b, const bvh_beam *beam, bvh_beam_tree *tree)
{
    prune p;
    p.b = b;
    p.beam = beam;
    p.tree = tree;
    p.full = 0;
    bvh_node root;
    tree->count = -1;
    if (b->exhaustive || tree->cap < 1)
        return 0;
    if (b->node_count == 0) {
        tree->count = 0;
        return 1;
    }
#ifdef SLAB_PAIR_SSE2
    prune_lanes(&p);
#endif
    tree->count = 1; /* slot 0: the root, written last */
    int kept = bvh_beam_meets(beam, b->nodes[0].lo, b->nodes[0].hi) && keep(&p, 0, &root);
    if (p.full) {
        tree->count = -1;
        return 0;
    }
    if (kept)
        tree->nodes[0] = root;
    else
        tree->count = 0;
    return 1;
}

int bvh_beam_intersect(const bvh *b, const bvh_beam_tree *tree, const scene_prim *prims, ray *r, hit *h,
                       bvh_stats *stats, int *tied)
{
    if (!tree || tree->count < 0)
        return bvh_intersect_ties(b, prims, r, h, stats, tied);
    bvh view = *b;
    view.nodes = tree->nodes;
    view.node_count = tree->count;
    return bvh_intersect_ties(&view, prims, r, h, stats, tied);
}
