/*
 * bvh_bundle.c - the nodes a bundle of shadow rays may reach, and the box
 * parts in them it cannot cross (spec/shading.md, [SHADE-SHORTCUT-BUNDLE-1];
 * bvh.c walks them).
 *
 * The hull.  A ray of the bundle runs from its origin O (within `slack` of
 * the apex P) toward a target q in the box [L, H].  The points of the
 * segments from P to the box are P + s (q - P), s in [0, 1], so on each
 * axis a point of the hull at parameter s lies between P_a + s (L_a - P_a)
 * and P_a + s (H_a - P_a): the hull sits inside the cone of boxes
 *     lo_a - m <= P_a + s (H_a - P_a)  and  P_a + s (L_a - P_a) <= hi_a + m
 * for a box [lo, hi] it meets within m.  Each is one bound on s (its slope
 * H_a - P_a or L_a - P_a, by the slab test's device: a reciprocal made
 * once, signed infinities for a zero slope, a NaN bound narrowing nothing),
 * and a box is left out when the bounds leave no s in [0, 1].
 *
 * The margin m.  Where the walk's slab test lets a box through, the ray's
 * exact point O + t d at the t it found lies within 8 eps |lo - O| of the
 * box on every axis (each slab bound is a rounded product of a rounded
 * difference and a rounded reciprocal, the exit enlarged by 4 eps; an axis
 * whose 1/d_a overflowed moves by less than 2^-1022 t), that point within
 * 4 eps |q - O| of a point O + mu (q - O), mu in [0, 1) (d is q - O
 * rounded and scaled by the rounded 1/|q - O|, tmax < |q - O|), and
 * O + mu (q - O) within |O - P| <= slack (1 + 2^-50) + 2^-52 |P| of the
 * hull's point P + mu (q - P).  This test's own rounding (the slopes,
 * their reciprocals, the bounds) moves a bound by 2^-49 of S in place or
 * by a subnormal's 2^-1074 in s.  S, the sum of the magnitudes of P, L,
 * H, slack and the tree's root box, bounds every coordinate involved, so
 * m = 2^-40 S + 2 slack + 2^-1000 covers all of it with room to spare: a
 * box this test leaves out, no ray of the bundle lets through.
 *
 * A box part (a hot box record: hot_box_crossings, intersect.c) crossed at
 * t puts the ray's exact point O + t d within 2 eps |c - O| + 2^-1074 of
 * the box on every axis, c the nearer corner's coordinate: box_slabs
 * accepts t only between the quotients (l_a - O_a) / d_a and
 * (h_a - O_a) / d_a, each a rounded division of a rounded difference (a
 * quotient held at 2^1020 bounds nothing a ray with 0 <= tmin < t < tmax
 * < 2^402, magnitudes under 2^400, reaches), or, for d_a = 0, with O_a in
 * [l_a, h_a].  That is within the slab test's 8 eps, and the part's box
 * lies in the root box, so the same test with the same margin leaves out
 * only a part no ray of the bundle crosses.  And one more case the hull cannot
 * see: a box behind every ray (`box_segment_apart`'s first case), for an exact
 * origin O (the point's own box, which the apex touches): on some axis O_a >=
 * l_a, O_a >= h_a, and every target's q_a >= L_a >= O_a + g (or the mirror
 * image), g = 2^-40 S + 2^-1000.  Then each ray's l_a - O_a and h_a - O_a
 * round to <= 0, its d_a = (q_a - O_a) rounded times the rounded 1/|q - O| is
 * > 0 (at least g / (2 S) before rounding: no underflow), and tmin > 0, so
 * box_axis_apart answers 1 and the part counts 0 crossings.
 *
 * A triangle part, for an exact origin, is left out where every ray of the
 * bundle passes it by in its sheared plane (triangle_passed_by: the shears
 * the rays may have, shear_bounds; each corner's box over them,
 * corner_boxes; a line through the origin with the three boxes strictly on
 * one side, boxes_apart).  And one where every ray's computed t is at or
 * below -0 (triangle_left_behind, [SHADE-SHORTCUT-BEHIND-1]): the triangle a
 * glass point's shadow rays leave.
 */
#include <assert.h>
#include "base/inline_hint.h"
#include "render/bvh.h"

/* The triangles' tests, made at a bundle's making only, kept out of line:
 * inlined, they grew the shadow rays' own code (add_source, into which the
 * link-time optimiser inlines bvh_bundle_make), demo.scene +0.8 %
 * instructions without a triangle. */

/* Each bound of s a node's box gives on one axis: the plane's offset from
 * the apex times the reciprocal of its slope, and whether it bounds s from
 * below. */
typedef struct bundle_cone {
    vec3 apex;
    real inv_lo[3], inv_hi[3];   /* 1 / (H_a - P_a), 1 / (L_a - P_a) */
    int lo_below[3], hi_below[3];
    real margin;
    real gap;                    /* g of the behind test */
    /* tri 1: every ray's triangle shear (isect_shear_make) is one of
     * perm[0 .. perms - 1]'s: its axes, and sx, sy within their bounds
     * (shear_bounds); 0: not known; -1: not looked at yet */
    int tri, perms;
    isect_shear perm[3][2];   /* the axes, and sx, sy: their least, their greatest */
} bundle_cone;

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

/* Whether some s in [0, 1] meets every bound of the box [lo, hi] (m
 * included). */
static int cone_meets(const bundle_cone *c, const real lo[3], const real hi[3])
{
    real sn = 0, sf = 1;
    const real p[3] = {c->apex.x, c->apex.y, c->apex.z};
    for (int a = 0; a < 3; a++) {
        narrow(((lo[a] - p[a]) - c->margin) * c->inv_lo[a], c->lo_below[a], &sn, &sf);
        narrow(((hi[a] - p[a]) + c->margin) * c->inv_hi[a], c->hi_below[a], &sn, &sf);
    }
    return sn <= sf;
}

static int cone_meets_node(const bundle_cone *c, const bvh_node *nd)
{
    const real lo[3] = {nd->lo.x, nd->lo.y, nd->lo.z}, hi[3] = {nd->hi.x, nd->hi.y, nd->hi.z};
    return cone_meets(c, lo, hi);
}

/* The box each corner of g keeps in the sheared plane over the bundle:
 * its x (isect_corner_at, the watertight test's own operations for the
 * bundle's one origin) between x[0][i] and x[1][i], its y likewise.  For
 * a corner, with a = v_k - o_k and z = v_kz - o_kz the same doubles for
 * every ray, the rounded s z is monotone in s (rounding is monotone;
 * increasing for z >= 0, decreasing for z <= 0) and the rounded a - p
 * monotone in p, so the coordinate is monotone in s: between its values at
 * the two bounds of s. */
static void corner_boxes(const isect_shear sh[2], vec3 o, const real *g, real x[2][3], real y[2][3])
{
    int kx = sh[0].kx, ky = sh[0].ky, kz = sh[0].kz;
    const real oa[3] = {o.x, o.y, o.z};
    for (int i = 0; i < 3; i++) {
        /* isect_corner_at's differences, once for the four shears */
        const real *v = g + 3 * i;
        real z = v[kz] - oa[kz], ax = v[kx] - oa[kx], ay = v[ky] - oa[ky];
        real a = isect_corner_of(ax, z, sh[0].sx), b = isect_corner_of(ax, z, sh[1].sx);
        x[0][i] = a < b ? a : b;
        x[1][i] = a < b ? b : a;
        a = isect_corner_of(ay, z, sh[0].sy);
        b = isect_corner_of(ay, z, sh[1].sy);
        y[0][i] = a < b ? a : b;
        y[1][i] = a < b ? b : a;
    }
}

/* Whether the three boxes lie strictly on one side of the line p x + q y = 0
 * (p, q in {0, +-1, +-2}: the products exact, and a rounded sum of two has
 * the exact sum's sign): the least of p x + q y over a box is at the
 * corner the signs of p and q pick. */
static inline int boxes_apart(real x[2][3], real y[2][3], real p, real q)
{
    int side = 0;
    for (int i = 0; i < 3; i++) {
        real least = p * x[p < 0][i] + q * y[q < 0][i], most = p * x[p >= 0][i] + q * y[q >= 0][i];
        int here = least > 0 ? 1 : most < 0 ? -1 : 0;
        if (here == 0 || (i > 0 && here != side))
            return 0;
        side = here;
    }
    return 1;
}

/* Whether every ray of the bundle (one origin, c->tri) has its triangle
 * test of g answer no crossing: under each shear it may have, its three
 * sheared corners strictly on one side of a line through the origin.  The
 * origin is then no point of the closed triangle of the rounded corners,
 * and triangle_solve, whose edge functions have the exact signs of those
 * corners' (intersect.c, triangle_apart, where the line is x = 0 or
 * y = 0), answers no crossing. */
HINT_OUT_OF_LINE static int triangle_passed_by(const bundle_cone *c, vec3 o, const real *g)
{
    for (int p = 0; p < c->perms; p++) {
        real x[2][3], y[2][3];
        corner_boxes(c->perm[p], o, g, x, y);
        /* the lines one by one, p and q constants in each inlined test */
        if (!(boxes_apart(x, y, 1, 0) || boxes_apart(x, y, 0, 1) || boxes_apart(x, y, 1, 1) ||
              boxes_apart(x, y, 1, -1) || boxes_apart(x, y, 1, 2) || boxes_apart(x, y, 2, 1) ||
              boxes_apart(x, y, 1, -2) || boxes_apart(x, y, 2, -1)))
            return 0;
    }
    return 1;
}

/* The least and greatest rounded product of a in [a0, a1] and b in [b0,
 * b1]: the exact product's extremes are at the corners, and rounding is
 * monotone. */
static void product_bounds(real a0, real a1, real b0, real b1, real *lo, real *hi)
{
    real p = a0 * b0, q = a0 * b1, r = a1 * b0, s = a1 * b1;
    real l = p < q ? p : q, h = p < q ? q : p;
    l = r < l ? r : l;
    h = r > h ? r : h;
    *lo = s < l ? s : l;
    *hi = s > h ? s : h;
}

/* Edge function i (triangle_solve's e_i = x_q y_p - y_q x_p, p = i + 1,
 * q = i + 2) of every ray, from the corners' boxes: monotone rounding. */
static void edge_bounds(real x[2][3], real y[2][3], int i, real *lo, real *hi)
{
    int p = (i + 1) % 3, q = (i + 2) % 3;
    real al, ah, bl, bh;
    product_bounds(x[0][q], x[1][q], y[0][p], y[1][p], &al, &ah);
    product_bounds(y[0][q], y[1][q], x[0][p], x[1][p], &bl, &bh);
    *lo = al - bh;
    *hi = ah - bl;
}

/*
 * [SHADE-SHORTCUT-BEHIND-1] Whether every ray of the bundle (one origin O,
 * c->tri) has triangle_solve's t for g at or below -0, below its tmin > 0:
 * mostly the triangle a glass point's shadow rays leave.  Per shear: the
 * corners' differences a_i, b_i, z_i from O on the axes kx, ky, kz (the same
 * doubles for every ray), R their largest magnitude; every ray's e_i of one
 * strict sign sigma and |det| >= dmin >= 2^-16 (edge_bounds); its dz of the
 * sign tau shear_bounds found.  For such a ray, with m = max |z_i|, t <= -0
 * where sigma tau P < -fl((2^-48 m + 2^-1000) |det|), P = (e0 z0 + e1 z1) +
 * e2 z2 as rounded (spec/numerics.md [NUM-TRI-BEHIND-1]); and every ray's P
 * is within 2^-44 R^3 + 2^-1000 of the exact determinant of the rows (a_i,
 * b_i, z_i), which the shear leaves unchanged, so within twice that of p0,
 * the same sum at sx = sy = 0.  Hence the test on p0 with the margin at
 * the greatest |det| and the two error terms doubled (they cover the
 * rounding of this sum).  R < 2^300: no product overflows.
 */
HINT_OUT_OF_LINE static int triangle_left_behind(const bundle_cone *c, vec3 o, const real *g)
{
    const real oa[3] = {o.x, o.y, o.z};
    /* The corners' differences from O on every axis, and R, are the same
     * for every shear: made once. */
    real diff[3][3], r = 0;
    for (int i = 0; i < 3; i++)
        for (int axis = 0; axis < 3; axis++) {
            diff[i][axis] = g[3 * i + axis] - oa[axis];
            r = fabs(diff[i][axis]) > r ? fabs(diff[i][axis]) : r;
        }
    if (!(r < 0x1p300))
        return 0;
    for (int k = 0; k < c->perms; k++) {
        const isect_shear *sh = c->perm[k];
        real a[3], b[3], z[3], m = 0, x[2][3], y[2][3], lo[3], hi[3];
        for (int i = 0; i < 3; i++) {
            a[i] = diff[i][sh[0].kx];
            b[i] = diff[i][sh[0].ky];
            z[i] = diff[i][sh[0].kz];
            m = fabs(z[i]) > m ? fabs(z[i]) : m;
        }
        corner_boxes(sh, o, g, x, y);
        for (int i = 0; i < 3; i++)
            edge_bounds(x, y, i, &lo[i], &hi[i]);
        int sigma = lo[0] > 0 && lo[1] > 0 && lo[2] > 0 ? 1 : hi[0] < 0 && hi[1] < 0 && hi[2] < 0 ? -1 : 0;
        real dlo = lo[0] + lo[1] + lo[2], dhi = hi[0] + hi[1] + hi[2];
        real dmin = sigma > 0 ? dlo : -dhi, dmax = sigma > 0 ? dhi : -dlo;
        if (sigma == 0 || !(dmin >= 0x1p-16))
            return 0;
        real e0 = a[2] * b[1] - b[2] * a[1], e1 = a[0] * b[2] - b[0] * a[2], e2 = a[1] * b[0] - b[1] * a[0];
        real p0 = e0 * z[0] + e1 * z[1] + e2 * z[2];
        real sp = (sigma > 0) == (sh[0].dz > 0) ? p0 : -p0;
        real need = (0x1p-48 * m + 0x1p-1000) * dmax + (0x1p-42 * (r * r * r) + 0x1p-998);
        if (!(sp < -need))
            return 0;
    }
    return 1;
}

/* The least and greatest of p / q over p in [p0, p1], q in [q0, q1] (q of
 * one strict sign, so the quotient is monotone in each: its extremes are at
 * the corners), widened by m = 2^-40 (|least| + |greatest|) + 2^-1000, and
 * held to [-1, 1] (a shear's sx, sy are: isect_shear_make). */
static void ratio_bounds(real p0, real p1, real q0, real q1, real *least, real *most)
{
    real a = p0 / q0, b = p0 / q1, c = p1 / q0, d = p1 / q1;
    real lo = a < b ? a : b, hi = a > b ? a : b;
    lo = c < lo ? c : lo;
    lo = d < lo ? d : lo;
    hi = c > hi ? c : hi;
    hi = d > hi ? d : hi;
    real m = 0x1p-40 * (fabs(lo) + fabs(hi)) + 0x1p-1000;
    lo -= m;
    hi += m;
    *least = lo > -1 ? lo : -1;
    *most = hi < 1 ? hi : 1;
}

/* Where every ray starts at rays->origin (exact), the shears its rays may
 * have: c->tri = 1 when found.  A ray toward a target q in [L, H] has dir =
 * D c' rounded per axis, D = q - O rounded (each D_a between L_a - O_a and
 * H_a - O_a rounded: rounding is monotone) and one factor c' > 0 for every
 * axis (unit_toward: the rounded 1 / |D|, or a division by |D|).  Axis j
 * is never the shear's kz where another axis's least |D_a| over the box
 * exceeds j's greatest by the factor 1 + 2^-30 (the rounded |dir_a| then
 * exceeds |dir_j|: each is |D_a| c' within a relative eps, and |D| is
 * normal below).  Every other axis k must have D_k of one strict sign,
 * |D_k| >= 2^-400, on the whole box; a ray with kz = k then has dz of D_k's
 * sign, (kx, ky) as shear_set turns them, and sx = dir_kx / dz rounded
 * (shear_ratio: the magnitudes' quotient, signed), which is D_kx / D_kz
 * within a relative 4 eps, plus 2^-1074 where dir_kx is subnormal;
 * ratio_bounds' margin covers both, as |sx| <= 1.  sy likewise. */
HINT_OUT_OF_LINE static void shear_bounds(const bvh_bundle_rays *rays, bundle_cone *c)
{
    const real o[3] = {rays->origin.x, rays->origin.y, rays->origin.z};
    const real tl[3] = {rays->lo.x, rays->lo.y, rays->lo.z}, th[3] = {rays->hi.x, rays->hi.y, rays->hi.z};
    real dl[3], dh[3], least[3], most[3];
    c->tri = 0;
    c->perms = 0;
    if (!rays->exact)
        return;
    for (int a = 0; a < 3; a++) {
        dl[a] = tl[a] - o[a];
        dh[a] = th[a] - o[a];
        least[a] = dl[a] > 0 ? dl[a] : dh[a] < 0 ? -dh[a] : 0;
        most[a] = fabs(dl[a]) > fabs(dh[a]) ? fabs(dl[a]) : fabs(dh[a]);
    }
    for (int k = 0; k < 3; k++) {
        int j1 = (k + 1) % 3, j2 = (k + 2) % 3;
        real over = (1 + 0x1p-30) * most[k];
        if (least[j1] > over || least[j2] > over)
            continue;   /* never the largest */
        if (!(least[k] >= 0x1p-400))
            return;
        int turn = dh[k] < 0;
        isect_shear *sh = c->perm[c->perms++];
        sh[0].kz = sh[1].kz = k;
        sh[0].dz = sh[1].dz = turn ? -1 : 1;   /* the sign of every such ray's dz */
        sh[0].kx = sh[1].kx = turn ? j2 : j1;
        sh[0].ky = sh[1].ky = turn ? j1 : j2;
        ratio_bounds(dl[sh[0].kx], dh[sh[0].kx], dl[k], dh[k], &sh[0].sx, &sh[1].sx);
        ratio_bounds(dl[sh[0].ky], dh[sh[0].ky], dl[k], dh[k], &sh[0].sy, &sh[1].sy);
    }
    c->tri = c->perms > 0;
}

static int cone_make(const bvh *b, const bvh_bundle_rays *rays, bundle_cone *c)
{
    real size = vec_sum_abs(rays->apex) + vec_sum_abs(rays->lo) + vec_sum_abs(rays->hi) + rays->slack +
                vec_sum_abs(b->nodes[0].lo) + vec_sum_abs(b->nodes[0].hi);
    if (!(rays->slack >= 0 && size < 0x1p400 && rays->lo.x <= rays->hi.x && rays->lo.y <= rays->hi.y &&
          rays->lo.z <= rays->hi.z))
        return 0;
    const real p[3] = {rays->apex.x, rays->apex.y, rays->apex.z};
    const real tl[3] = {rays->lo.x, rays->lo.y, rays->lo.z}, th[3] = {rays->hi.x, rays->hi.y, rays->hi.z};
    c->apex = rays->apex;
    c->margin = 0x1p-40 * size + 2 * rays->slack + 0x1p-1000;
    c->gap = 0x1p-40 * size + 0x1p-1000;
    for (int a = 0; a < 3; a++) {
        /* s (H_a - P_a) >= lo_a - m - P_a bounds s from below where the
         * slope is positive (+0 too: its infinite reciprocal then says
         * whether the bound holds at all), from above where it is
         * negative. */
        c->inv_lo[a] = reciprocal(th[a] - p[a]);
        c->lo_below[a] = !signbit(c->inv_lo[a]);
        /* s (L_a - P_a) <= hi_a + m - P_a: the other way round. */
        c->inv_hi[a] = reciprocal(tl[a] - p[a]);
        c->hi_below[a] = signbit(c->inv_hi[a]) != 0;
    }
    c->tri = -1;   /* shear_bounds at the first triangle: most bundles meet none */
    return 1;
}

/* Whether every ray of the bundle leaves the box [l, h] behind on some
 * axis (see the top: the exact origin, the gap to every target). */
static int box_behind(const bundle_cone *c, const bvh_bundle_rays *rays, const real l[3], const real h[3])
{
    const real o[3] = {rays->origin.x, rays->origin.y, rays->origin.z};
    const real tl[3] = {rays->lo.x, rays->lo.y, rays->lo.z}, th[3] = {rays->hi.x, rays->hi.y, rays->hi.z};
    if (!rays->exact)
        return 0;
    for (int a = 0; a < 3; a++) {
        if (o[a] >= l[a] && o[a] >= h[a] && tl[a] - o[a] >= c->gap)
            return 1;
        if (o[a] <= l[a] && o[a] <= h[a] && th[a] - o[a] <= -c->gap)
            return 1;
    }
    return 0;
}

/* The parts of leaf nd that no ray of the bundle crosses: box records the
 * hull misses or that lie behind every ray, and triangle records every ray
 * passes by. */
static unsigned leaf_skip(const bvh *b, bundle_cone *c, const bvh_bundle_rays *rays, const bvh_node *nd)
{
    unsigned skip = 0;
    for (int i = 0; i < nd->count && i < 32; i++) {
        bvh_hot hr = b->hot[nd->first + i];
        if (ISECT_HOT_KIND(hr.code) == ISECT_HOT_TRIANGLE) {
            if (c->tri < 0)
                shear_bounds(rays, c);
            if (c->tri && (triangle_passed_by(c, rays->origin, b->hot_reals + hr.at) ||
                           triangle_left_behind(c, rays->origin, b->hot_reals + hr.at)))
                skip |= 1u << i;
            continue;
        }
        if (ISECT_HOT_KIND(hr.code) != ISECT_HOT_BOX)
            continue;
        const real *g = b->hot_reals + hr.at;
        if (!cone_meets(c, g, g + 3) || box_behind(c, rays, g, g + 3))
            skip |= 1u << i;
    }
    return skip;
}

/* Whether the records [first, first + n) are all triangles' (a leaf or
 * run of them needs no box test: [SHADE-SHORTCUT-OPEN-1]). */
static int triangles_alone(const bvh *b, int first, int n)
{
    for (int i = first; i < first + n; i++)
        if (ISECT_HOT_KIND(b->hot[i].code) != ISECT_HOT_TRIANGLE)
            return 0;
    return 1;
}

/* Appends entry (a node, or ~i for runs[i]) to the list; open: a leaf or
 * run of triangle records alone. */
static void keep(bvh_bundle *out, int entry, int open)
{
    out->boxed += !open;
    out->node[out->count++] = entry;
}

/* Keeps leaf `node`: whole, or as the runs of its parts leaf_skip leaves
 * (each a node of out->runs with the leaf's box, in order), or not at all
 * where it leaves none.  Past BVH_BUNDLE_RUNS runs in all: whole. */
static void keep_leaf(const bvh *b, bundle_cone *c, const bvh_bundle_rays *rays, int node, bvh_bundle *out)
{
    const bvh_node *nd = &b->nodes[node];
    unsigned skip = leaf_skip(b, c, rays, nd);
    int runs = 0, n = nd->count < 32 ? nd->count : 32;
    for (int i = 0; i < n; i++)
        runs += !(skip >> i & 1u) && (i == 0 || skip >> (i - 1) & 1u);
    if (skip == 0 || nd->count > 32 || out->run_count + runs > BVH_BUNDLE_RUNS) {
        keep(out, node, triangles_alone(b, nd->first, nd->count));
        return;
    }
    for (int i = 0; i < n;) {
        int j = i;
        while (j < n && !(skip >> j & 1u))
            j++;
        if (j > i) {
            bvh_node *run = &out->runs[out->run_count];
            *run = *nd;
            run->first = nd->first + i;
            run->count = j - i;
            keep(out, ~out->run_count++, triangles_alone(b, run->first, run->count));
        }
        i = j + 1;
    }
}

void bvh_bundle_make(const bvh *b, const bvh_bundle_rays *rays, bvh_bundle *out, bvh_stats *stats)
{
    bundle_cone c;
    int stack[BVH_MAX_DEPTH], sp = 0, node = 0;
    out->count = -1;
    out->planes_passed = 0;
    out->crosses_nothing = 0;
    if (b->exhaustive || b->node_count == 0 || !cone_make(b, rays, &c))
        return;
    out->count = out->run_count = out->boxed = 0;
    if (stats)
        stats->nodes_visited++;
    if (!cone_meets_node(&c, &b->nodes[0]))
        return;
    for (;;) {
        const bvh_node *nd = &b->nodes[node];
        if (nd->count > 0) {
            keep_leaf(b, &c, rays, node, out);
        } else if (out->count + sp + 1 >= BVH_BUNDLE_MAX) {
            /* The list is full: kept whole, then the pending siblings in
             * the order the walk would take them. */
            keep(out, node, 0);
            while (sp > 0)
                keep(out, stack[--sp], 0);
        } else {
            int a = nd->first;
            int ha = cone_meets_node(&c, &b->nodes[a]), hc = cone_meets_node(&c, &b->nodes[a + 1]);
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

/*
 * [SHADE-SHORTCUT-PLANE-1] Whether every ray of the bundle (one origin O,
 * tmin >= 0) is told apart by isect_plane_crossings' first test: num =
 * n.(p0 - O), the same double for every ray (made here by the same
 * operations), and dn = n.d of the sign that makes (num < 0) != (dn < 0).
 * A ray's d is D c' rounded per axis (shear_bounds: D_a between L_a - O_a
 * and H_a - O_a rounded, c' > 0 one factor), so its rounded dn is within
 * c' 5 eps sum |n_a| |D_a| (+ 3 2^-1074 for underflow) of c' n.D, and
 * n.D is at least `least` (the box's corner the signs of n pick, rounded
 * within 8 eps N S, N = sum |n_a|, S the magnitudes of O, L, H summed).
 * So least > 2^-40 N S + 2^-1000 makes every ray's dn > 0: c' n.D minus
 * the errors is at least c' 2^-42 N S >= 2^-45 N (|D| <= 4 S), far above
 * the underflow's term for N >= 1/2.  `most` < minus as much makes every
 * dn < 0 likewise.  Such a plane's test answers 0 for every ray, and
 * makes no call of the callback: the walk leaves it out.
 */
static int plane_passed(const scene_prim *p, const bvh_bundle_rays *rays)
{
    vec3 o = rays->origin, n = p->u.plane.normal;
    real num = vec_dot(n, vec_sub(p->u.plane.point, o));
    real size = vec_sum_abs(o) + vec_sum_abs(rays->lo) + vec_sum_abs(rays->hi), nsum = vec_sum_abs(n);
    if (!(size < 0x1p400 && nsum >= 0.5 && nsum < 16))
        return 0;
    const real oa[3] = {o.x, o.y, o.z}, na[3] = {n.x, n.y, n.z};
    const real tl[3] = {rays->lo.x, rays->lo.y, rays->lo.z}, th[3] = {rays->hi.x, rays->hi.y, rays->hi.z};
    real least = 0, most = 0, tol = 0x1p-40 * nsum * size + 0x1p-1000;
    for (int a = 0; a < 3; a++) {
        least += na[a] * ((na[a] >= 0 ? tl[a] : th[a]) - oa[a]);
        most += na[a] * ((na[a] >= 0 ? th[a] : tl[a]) - oa[a]);
    }
    return num < 0 ? least > tol : most < -tol;
}

void bvh_bundle_planes(const bvh *b, const scene_prim *prims, const bvh_bundle_rays *rays, bvh_bundle *out)
{
    if (out->count < 0 || !rays->exact)
        return;
    for (int i = 0; i < b->unbounded_count && i < 32; i++) {
        const scene_prim *p = &prims[b->unbounded[i].prim];
        if (p->kind == PRIM_PLANE && !p->frame && plane_passed(p, rays))
            out->planes_passed |= 1u << i;
    }
    out->crosses_nothing = out->count == 0 && b->unbounded_count <= 32 &&
                           out->planes_passed == (b->unbounded_count == 32 ? ~0u : (1u << b->unbounded_count) - 1);
}
