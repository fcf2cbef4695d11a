/*
 * bvh_bundle.c - the nodes a bundle of shadow rays may reach
 * (spec/shading.md, [SHADE-SHORTCUT-BUNDLE-1]; bvh.c walks them).
 *
 * The hull.  A ray of the bundle runs from its origin O (within `slack` of
 * the apex P) toward a target q in the ball (C, R).  The points of the
 * segments from P to the ball are P + s (C - P) + s u, s in [0, 1],
 * |u| <= R, so on each axis a point of the hull at parameter s lies
 * within s R of P_a + s D_a (D = C - P): the hull sits inside the cone of
 * cubes
 *     lo_a - m <= P_a + s D_a + s R  and  P_a + s D_a - s R <= hi_a + m
 * for a box [lo, hi] it meets within m.  Each is one bound on s (its slope
 * D_a + R or D_a - R, by the slab test's device: a reciprocal made once,
 * signed infinities for a zero slope, a NaN bound narrowing nothing), and a
 * box is left out when the bounds leave no s in [0, 1].
 *
 * The margin m.  Where the walk's slab test lets a box through, the ray's
 * exact point O + t d at the t it found lies within 8 eps |lo - O| of the
 * box on every axis (each slab bound is a rounded product of a rounded
 * difference and a rounded reciprocal, the exit enlarged by 4 eps; an axis
 * whose 1/d_a overflowed moves by less than 2^-1022 t), that point within
 * 4 eps |q - O| of a point O + mu (q - O), mu in [0, 1) (d is q - O
 * rounded and scaled by the rounded 1/|q - O|, tmax < |q - O|), and
 * O + mu (q - O) within |O - P| <= slack (1 + 2^-50) + 2^-52 |P| of the
 * hull's point P + mu (q - P).  This test's own rounding (D_a, the slopes,
 * their reciprocals, the bounds) moves a bound by 2^-49 of S in place or
 * by a subnormal's 2^-1074 in s.  S, the sum of the magnitudes of P, C,
 * R, slack and the tree's root box, bounds every coordinate involved, so
 * m = 2^-40 S + 2 slack + 2^-1000 covers all of it with room to spare: a
 * box this test leaves out, no ray of the bundle lets through.
 */
#include <assert.h>
#include "render/bvh.h"

/* Each bound of s a node's box gives on one axis: the plane's offset from
 * the apex times the reciprocal of its slope, and whether it bounds s from
 * below. */
typedef struct bundle_cone {
    vec3 apex;
    real inv_lo[3], inv_hi[3];   /* 1 / (D_a + R), 1 / (D_a - R) */
    int lo_below[3], hi_below[3];
    real margin;
} bundle_cone;

static real sum_abs(vec3 a) { return fabs(a.x) + fabs(a.y) + fabs(a.z); }

static real reciprocal(real k) { return k != 0.0 ? 1.0 / k : copysign(INFINITY, k); }

static void narrow(real bound, int below, real *sn, real *sf)
{
    if (below) {
        if (bound > *sn)
            *sn = bound;
    } else if (bound < *sf) {
        *sf = bound;
    }
}

/* Whether some s in [0, 1] meets every bound of the box (m included). */
static int cone_meets(const bundle_cone *c, const bvh_node *nd)
{
    real sn = 0, sf = 1;
    const real lo[3] = {nd->lo.x, nd->lo.y, nd->lo.z}, hi[3] = {nd->hi.x, nd->hi.y, nd->hi.z};
    const real p[3] = {c->apex.x, c->apex.y, c->apex.z};
    for (int a = 0; a < 3; a++) {
        narrow(((lo[a] - p[a]) - c->margin) * c->inv_lo[a], c->lo_below[a], &sn, &sf);
        narrow(((hi[a] - p[a]) + c->margin) * c->inv_hi[a], c->hi_below[a], &sn, &sf);
    }
    return sn <= sf;
}

static int cone_make(const bvh *b, vec3 apex, real slack, vec3 centre, real reach, bundle_cone *c)
{
    real size = sum_abs(apex) + sum_abs(centre) + reach + slack + sum_abs(b->nodes[0].lo) + sum_abs(b->nodes[0].hi);
    if (!(reach >= 0 && slack >= 0 && size < 0x1p400))
        return 0;
    vec3 d = vec_sub(centre, apex);
    const real da[3] = {d.x, d.y, d.z};
    c->apex = apex;
    c->margin = 0x1p-40 * size + 2 * slack + 0x1p-1000;
    for (int a = 0; a < 3; a++) {
        /* s (D_a + R) >= lo_a - m - P_a bounds s from below where the slope
         * is positive (+0 too: its infinite reciprocal then says whether
         * the bound holds at all), from above where it is negative. */
        c->inv_lo[a] = reciprocal(da[a] + reach);
        c->lo_below[a] = !signbit(c->inv_lo[a]);
        /* s (D_a - R) <= hi_a + m - P_a: the other way round. */
        c->inv_hi[a] = reciprocal(da[a] - reach);
        c->hi_below[a] = signbit(c->inv_hi[a]) != 0;
    }
    return 1;
}

void bvh_bundle_make(const bvh *b, vec3 apex, real slack, vec3 centre, real reach, bvh_bundle *out,
                     bvh_stats *stats)
{
    bundle_cone c;
    int stack[BVH_MAX_DEPTH], sp = 0, node = 0;
    out->count = -1;
    if (b->exhaustive || b->node_count == 0 || !cone_make(b, apex, slack, centre, reach, &c))
        return;
    out->count = 0;
    if (stats)
        stats->nodes_visited++;
    if (!cone_meets(&c, &b->nodes[0]))
        return;
    for (;;) {
        const bvh_node *nd = &b->nodes[node];
        if (out->count + sp + 1 >= BVH_BUNDLE_MAX || nd->count > 0) {
            /* A leaf, or the list is full: kept whole, then the pending
             * siblings in the order the walk would take them. */
            out->node[out->count++] = node;
            if (nd->count == 0)
                while (sp > 0)
                    out->node[out->count++] = stack[--sp];
        } else {
            int a = nd->first;
            int ha = cone_meets(&c, &b->nodes[a]), hc = cone_meets(&c, &b->nodes[a + 1]);
            if (stats)
                stats->nodes_visited += 2;
            if (ha || hc) {
                if (ha && hc) {
                    assert(sp < BVH_MAX_DEPTH);
                    stack[sp++] = a + 1;
                }
                node = ha ? a : a + 1;
                continue;
            }
        }
        if (sp == 0)
            return;
        node = stack[--sp];
    }
}
