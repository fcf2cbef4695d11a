/*
 * intersect.c - ray/primitive intersection.
 *
 * Each shape has one routine `SHAPE_hits(..., const ray *r, hit *out, int max)`
 * that writes up to max accepted hits (t in (tmin, tmax)) in increasing t
 * and returns how many.  The nearest-hit entry points call it with max 1,
 * the all-crossings ones with max ISECT_MAX_CROSSINGS, so both always agree
 * on every t.
 * Nothing here allocates or keeps state.
 */
#include <float.h>
#include "base/inline_hint.h"
#include "render/intersect.h"
#include "render/intersect_shapes.h"
#include "render/isect_common.h"
#include "render/slab.h"
#include "base/xform.h"

/* HINT_FLATTEN (base/inline_hint.h) inlines every call a function makes,
 * recursively, where the body is visible (with LTO, across files).  For sphere_hits (spec/performance.md,
 * "Sixth round: the build"): left to itself, gcc's LTO keeps
 * isect_sphere_roots a call, and the f it passes by value (24 bytes, on the
 * stack) is stored as three doubles and read back as a 16-byte load, which
 * the store cannot forward.  box_hits, plane_t and plane_point take it too
 * (spec/performance.md, eighth round). */

/*@ requires \valid_read(r);
    assigns \nothing;
    ensures EXACT(\result != 0 <==> r->tmin < t < r->tmax);   // doubles too: the comparisons */
static int in_interval(const ray *r, real t) { return t > r->tmin && t < r->tmax; }

static vec3 vec_with(vec3 v, int axis, real value)
{
    if (axis == 0)
        v.x = value;
    else if (axis == 1)
        v.y = value;
    else
        v.z = value;
    return v;
}


/*
 * The point o + t d has an absolute error of about eps |o| + eps |t d|,
 * which for a small sphere far from the origin is huge relative to its
 * radius.  One Newton-like restart fixes it: solve again from o' = o + t d,
 * which lies within that error of the surface, and step by the root of the
 * new solve nearest to the crossing (the lower one for the entry, the
 * upper one for the exit).  Returns the refined t and sets *point.
 */
/*@ requires \valid_read(r) && \valid(point) && \separated(point, r);
    requires vfinite(center) && \is_finite(radius) && radius > 0;   // check_radius, in_range
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(t);
    assigns *point;
    // Not stated: the point on the ray at the returned t, and on the sphere
    // (spec/proofs.md, "Round 6": the provers did not close them). */
static real sphere_refine(vec3 center, real radius, const ray *r, real t, int upper,
                            vec3 *point)
{
    vec3 o2 = ray_at(r, t);
    real t2[2];
    int n = isect_sphere_roots(vec_sub(o2, center), r->dir, radius, t2);
    if (n == 0) {
        *point = o2;
        return t;
    }
    real step = upper ? t2[n - 1] : t2[0];
    *point = vec_madd(o2, r->dir, step);
    return t + step;
}

/* Whether a root, before refinement, could still land in (tmin, tmax).  The
 * refinement moves t by the rounding error of o + t d over |d|, a few ulps
 * of |o|/|d| + |t|; the slack is 1e-9 of that, a million times wider.
 * reach is |o|/|d| (max norms), divided once per sphere, not per root. */
static int sphere_root_possible(const ray *r, real reach, real t)
{
    real slack = 1e-9 * (fabs(t) + reach);
    return t + slack > r->tmin && t - slack < r->tmax;
}

/* Whether a root t of a far origin's first solve (sphere_hits, |f| > 2R)
 * surely stays in (tmin, tmax) after sphere_refine, so that a count can
 * take it without refining ([NUM-SPHERE-3], spec/numerics.md 2.1b).  The
 * refine moves t by a root of isect_sphere_roots(f2, d, R), f2 = o + t d - c
 * rounded as sphere_refine rounds it; every such root (held or not) is at
 * most (|f2| + R)(1 + 2^-18) / |d| in magnitude for |f2| <= 4R, R >= 2^-400
 * and |d|_max in [2^-100, 2^100], grazes included; n1 = |f2|_1 >= |f2| (1 -
 * 2 eps) and |d|_max <= |d|: so t clear of both ends by (n1 + R)(1 +
 * 2^-14) / |d|_max,
 * with 2^-40 |t| for the rounding of t + step, counts as it would refined.
 * The bound is of the step's magnitude, not of the refine's small move, so
 * it asks a sphere to keep about a diameter from the segment's ends. */
static int sphere_root_clear(vec3 center, real radius, const ray *r, real t)
{
    vec3 f2 = vec_sub(ray_at(r, t), center);
    real n1 = vec_sum_abs(f2), dm = vec_max_abs(r->dir);
    /* |d|_max in [2^-100, 2^100]: a = d.d and a gap stay normal or, at a
     * graze, negligibly far from it; outside it the second solve's roots
     * can pass the bound (attack 21, sphere_count_extreme_dir.sh). */
    if (!(radius >= 0x1p-400 && n1 <= 4.0 * radius && dm >= 0x1p-100 && dm <= 0x1p100))
        return 0;
    real m = (n1 + radius) * (1.0 + 0x1p-14) + 0x1p-40 * fabs(t) * dm;
    return (t - r->tmin) * dm > m && (r->tmax - t) * dm > m;
}

/* A sphere's full hit at t, point p: the one place its normal is made, so
 * a hit completed later (isect_hot_complete) has the bits of one made at
 * once. */
static inline void sphere_normal_set(hit *h, real t, vec3 p, vec3 center, vec3 dir)
{
    isect_hit_set(h, t, p, vec_normalize(vec_sub(p, center)), dir);
}

/* What a nearest walk's candidate keeps of a sphere's hit until it has
 * won: its t, read by the walk, and its point, which the normal is made
 * from (sphere_refine's or ray_at's, not to be made again); part 0, read
 * by the tie rule. */
static inline void sphere_point_set(hit *h, real t, vec3 p)
{
    h->t = t;
    h->point = p;
    h->part = 0;
}

/* bare: only each hit's t (and a mesh triangle's part) is written: a
 * shadow ray needs no more; the same for every shape below.  For the
 * sphere, bare 2 is a count (isect_part_crossings, isect_hot_crossings):
 * nothing is written, and a root clear of the interval's ends is counted
 * unrefined (sphere_root_clear); bare 3 writes t, the point and part 0,
 * not the normal (isect_hot_candidate: sphere_normal_set makes the rest
 * from that point once the hit has won). */
HINT_FLATTEN static int sphere_hits(vec3 center, real radius, const ray *r, hit *out, int max,
                                      int bare)
{
    vec3 f = vec_sub(r->origin, center);
    real t[2];
    int roots = isect_sphere_roots(f, r->dir, radius, t), found = 0;
    /* Refine only when the origin is far (|f| > 2R): nearer, o + t d is
     * already as exact as the centre's own coordinates allow. */
    int refine = roots == 2 && vec_length2(f) > 4.0 * radius * radius;
    real reach = refine ? vec_max_abs(r->origin) / vec_max_abs(r->dir) : 0.0;
    for (int i = 0; i < roots && found < max; i++) {
        real ti = t[i];
        vec3 p;
        if (refine) {
            if (!sphere_root_possible(r, reach, ti))
                continue;
            if (bare == 2 && sphere_root_clear(center, radius, r, ti)) {
                found++;
                continue;
            }
            ti = sphere_refine(center, radius, r, ti, i == 1, &p);
        } else {
            p = ray_at(r, ti);
        }
        if (!in_interval(r, ti))
            continue;
        if (bare == 2)
            found++;
        else if (bare == 3)
            sphere_point_set(&out[found++], ti, p);
        else if (bare)
            out[found++].t = ti;
        else
            sphere_normal_set(&out[found++], ti, p, center, r->dir);
    }
    return found;
}

/*
 * Plane n . (x - p0) = 0: t = n . (p0 - o) / (n . d); parallel rays miss.
 * The point is projected back onto the plane, so its error is relative to
 * |p| and |p0|, not to the ray origin (a camera far away).
 */
/* Lemma functions of plane_t (ghost code, make prove only: see the block
 * in base/vec.h): a dot product with a difference written out, and the
 * ring identity that puts t n.d = n.(p0 - o) on the plane. */
/*@ ghost
  /@ requires EXACT(w.x == p.x - o.x && w.y == p.y - o.y && w.z == p.z - o.z);
     assigns \nothing;
     ensures EXACT(vdot(n, w) == n.x * (p.x - o.x) + n.y * (p.y - o.y) + n.z * (p.z - o.z)); @/
  static void lemma_dot_difference(vec3 n, vec3 w, vec3 p, vec3 o) { }

  /@ requires EXACT(dn == n.x * dx + n.y * dy + n.z * dz);
     requires EXACT(w.x == p.x - ox && w.y == p.y - oy && w.z == p.z - oz);
     assigns \nothing;
     ensures EXACT(n.x * (ox + t * dx - p.x) + n.y * (oy + t * dy - p.y) + n.z * (oz + t * dz - p.z) ==
                   t * dn - vdot(n, w)); @/
  static void lemma_plane_gap(vec3 n, vec3 p, vec3 w, real ox, real oy, real oz, real dx, real dy, real dz,
                              real t, real dn)
  {
      vec3 o = { ox, oy, oz };
      lemma_dot_difference(n, w, p, o);
  }
*/

/*@ requires \valid_read(r) && \valid(t) && \separated(t, r);
    requires vfinite(p0) && vfinite(r->origin) && vfinite(r->dir);
    // within the scene's extent ([LANG-EXTENT-1]; spec/proofs.md, "Hit tests")
    requires DOUBLES(vbounded(p0, 0x1p500) && vbounded(r->origin, 0x1p500) && vbounded(r->dir, 4));
    requires DOUBLES(vbounded(n, 4)) && EXACT(vunit(n));   // check_is_unit (scene/check.c, in_range)
    assigns *t;
    ensures \result != 0 ==> \is_finite(*t) && EXACT(r->tmin < *t < r->tmax);   // doubles too
    ensures EXACT(\result != 0 ==> n.x * (r->origin.x + *t * r->dir.x - p0.x) +
                  n.y * (r->origin.y + *t * r->dir.y - p0.y) + n.z * (r->origin.z + *t * r->dir.z - p0.z) == 0);
    // no hit: parallel, t outside (tmin, tmax), or t past 2^1020, held there (isect_quotient)
    ensures EXACT(\result == 0 ==> vdot(n, r->dir) == 0 || !(r->tmin < *t < r->tmax) || \abs(*t) == 0x1p1020); */
HINT_FLATTEN static int plane_t(vec3 p0, vec3 n, const ray *r, real *t)
{
    real dn = vec_dot(n, r->dir);
    if (dn == 0.0)
        return 0;
    vec3 w = vec_sub(p0, r->origin);
    /* the dot product written out (admitted before 2026-12-02) */
    /*@ ghost lemma_dot_difference(n, w, p0, r->origin); */
    /*@ assert EXACT(vdot(n, w) == n.x * (p0.x - r->origin.x) + n.y * (p0.y - r->origin.y) +
                    n.z * (p0.z - r->origin.z)); */
    /* Nearly parallel, t past 2^1020 (it was an infinity the interval
     * rejected): no hit. */
    /*@ assert EXACT(dn == n.x * r->dir.x + n.y * r->dir.y + n.z * r->dir.z); */
    if (!isect_quotient(vec_dot(n, w), dn, t))
        return 0;
    /*@ assert EXACT(dn == n.x * r->dir.x + n.y * r->dir.y + n.z * r->dir.z); */
    /*@ assert EXACT(*t * dn == vdot(n, w)); */
    /* a ring identity, dn and w written out (admitted before 2026-12-02:
     * the provers do not close it with isect_quotient's contract in the
     * context, and close the lemma's instance alone; the ray passed field
     * by field, read as the clause reads it, after *t is written) */
    /*@ ghost lemma_plane_gap(n, p0, w, r->origin.x, r->origin.y, r->origin.z, r->dir.x, r->dir.y, r->dir.z, *t, dn); */
    /*@ assert EXACT(n.x * (r->origin.x + *t * r->dir.x - p0.x) + n.y * (r->origin.y + *t * r->dir.y - p0.y) +
                    n.z * (r->origin.z + *t * r->dir.z - p0.z) == *t * dn - vdot(n, w)); */
    return in_interval(r, *t);
}

/*@ requires \valid_read(r) && \valid(t) && \valid(p) && \separated(t, p, r);
    requires vfinite(p0) && vfinite(r->origin) && vfinite(r->dir);
    requires vunit(n);
    assigns *t, *p;
    ensures \result != 0 ==> r->tmin < *t < r->tmax; */
HINT_FLATTEN static int plane_point(vec3 p0, vec3 n, const ray *r, real *t, vec3 *p)
{
    if (!plane_t(p0, n, r, t))
        return 0;
    vec3 x = ray_at(r, *t);
    *p = vec_madd(x, n, -vec_dot(n, vec_sub(x, p0)) / vec_dot(n, n));
    return 1;
}

static int plane_hits(vec3 p0, vec3 n, const ray *r, hit *out, int bare)
{
    real t;
    vec3 p;
    if (bare)
        return plane_t(p0, n, r, &out->t);
    if (!plane_point(p0, n, r, &t, &p))
        return 0;
    isect_hit_set(out, t, p, vec_normalize(n), r->dir);
    return 1;
}

/* Disk: the plane hit, kept when within the radius (boundary included). */
/*@ requires \valid_read(r) && \valid(out) && \separated(out, r);
    requires vfinite(center) && vfinite(r->origin) && vfinite(r->dir);
    requires vunit(n) && \is_finite(radius) && radius > 0;   // check_is_unit, check_radius
    assigns *out;
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> \old(r->tmin) < out->t < \old(r->tmax); */
static int disk_hits(vec3 center, vec3 n, real radius, const ray *r, hit *out)
{
    real t;
    vec3 p;
    if (!plane_point(center, n, r, &t, &p))
        return 0;
    vec3 w = vec_sub(p, center);
    if (!(vec_length2(w) <= radius * radius))
        return 0;
    /*@ assert EXACT(w.x * w.x + w.y * w.y + w.z * w.z <= radius * radius);   // |p - c| <= R */
    isect_hit_set(out, t, p, vec_normalize(n), r->dir);
    return 1;
}

/*
 * Box: the slab method.  Per axis the ray is inside the closed slab
 * [lo, hi] for t between (lo - o)/d and (hi - o)/d.  A zero direction
 * component is handled apart (inside the slab for all t, or never), so
 * there is no 0 * inf = NaN when the origin lies on a slab plane; a
 * non-zero one is divided by, never multiplied by an infinite inverse.
 * Ties between axes go to the lower axis.
 */
/*@ requires \valid_read(r) && \valid(tt + (0 .. 1)) && \valid(axis + (0 .. 1));
    requires \separated(tt + (0 .. 1), axis + (0 .. 1), r);
    requires vfinite(lo) && vfinite(hi) && vfinite(r->origin) && vfinite(r->dir);
    requires DOUBLES(vbounded(lo, 0x1p500) && vbounded(hi, 0x1p500) && vbounded(r->origin, 0x1p500));
    assigns tt[0 .. 1], axis[0 .. 1];
    ensures \result == 0 || \result == 1;
    ensures \is_finite(tt[0]) && \is_finite(tt[1]);
    ensures EXACT(\result == 1 ==> tt[0] <= tt[1] && r->tmin < tt[1] && tt[0] < r->tmax);   // doubles too
    ensures \result == 1 ==> 0 <= axis[0] <= 2; */
static int box_slabs(vec3 lo, vec3 hi, const ray *r, real tt[2], int axis[2])
{
    /* -DBL_MAX and DBL_MAX stand for the infinities: every slab's t is
     * within 2^1020 (isect_quotient), so they compare the same. */
    tt[0] = -DBL_MAX;
    tt[1] = DBL_MAX;
    axis[0] = axis[1] = -1;
    //@ ghost int seen = 0;
    /*@ loop invariant 0 <= k <= 3;
        loop invariant -1 <= axis[0] < k;
        loop invariant EXACT(axis[0] >= 0 ==> seen == 1);
        loop invariant EXACT(seen == 1 ==> tt[0] <= tt[1] && r->tmin < tt[1] && tt[0] < r->tmax);
        loop invariant \is_finite(tt[0]) && \is_finite(tt[1]);
        loop assigns k, tt[0 .. 1], axis[0 .. 1], seen;
        loop variant 3 - k; */
    for (int k = 0; k < 3; k++) {
        real o = vec_component(r->origin, k), d = vec_component(r->dir, k);
        real l = vec_component(lo, k), h = vec_component(hi, k);
        if (d == 0.0) {
            if (o < l || o > h)
                return 0;
            continue;
        }
        /* A crossing past 2^1020 (a direction nearly along the slab) is
         * held there: it was an infinity, as beyond every ray's reach. */
        real t0, t1;
        isect_quotient(l - o, d, &t0);
        isect_quotient(h - o, d, &t1);
        if (t0 > t1) {
            real s = t0;
            t0 = t1;
            t1 = s;
        }
        if (t0 > tt[0]) {
            tt[0] = t0;
            axis[0] = k;
        }
        if (t1 < tt[1]) {
            tt[1] = t1;
            axis[1] = k;
        }
        /* The entry only grows and the exit only falls from here on: once
         * they cross, or the exit is at or before tmin, or the entry at or
         * past tmax, no crossing can be accepted; the other axes' divisions
         * are saved. */
        if (tt[0] > tt[1] || tt[1] <= r->tmin || tt[0] >= r->tmax)
            return 0;
        //@ ghost seen = 1;
    }
    return axis[0] >= 0 && tt[0] <= tt[1];
}

/* The hit on the face of axis k crossed at t: entry (exit 0) or exit
 * (exit 1).  The point's k coordinate is set to the face exactly. */
static void box_face_hit(vec3 lo, vec3 hi, const ray *r, real t, int k, int exit, hit *h)
{
    int positive = (vec_component(r->dir, k) > 0.0) == exit; /* the hi face */
    vec3 p = vec_with(ray_at(r, t), k, vec_component(positive ? hi : lo, k));
    vec3 n = vec_with(vec_make(0.0, 0.0, 0.0), k, positive ? 1.0 : -1.0);
    isect_hit_set(h, t, p, n, r->dir);
}

HINT_FLATTEN static int box_hits(vec3 lo, vec3 hi, const ray *r, hit *out, int max, int bare)
{
    real tt[2];
    int axis[2], found = 0;
    if (!box_slabs(lo, hi, r, tt, axis))
        return 0;
    int crossings = tt[0] == tt[1] ? 1 : 2;
    for (int i = 0; i < crossings && found < max; i++)
        if (!in_interval(r, tt[i]))
            continue;
        else if (bare)
            out[found++].t = tt[i];
        else
            box_face_hit(lo, hi, r, tt[i], axis[i], i, &out[found++]);
    return found;
}

/*
 * Triangle: Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection",
 * JCGT 2(1), 2013.  Translate the vertices to the ray origin, permute the
 * axes so that the largest direction component is z (swapping x and y when
 * it is negative, to keep the winding), and shear so the ray becomes +z.
 * The 2D edge functions at the origin are then
 *   U = e(B,C), V = e(C,A), W = e(A,B),  e(P,Q) = Qx Py - Qy Px,
 * the barycentric weights of A, B, C times their sum det.  The sheared
 * coordinates of a vertex depend only on the vertex and the ray, and the
 * two products of e(Q,P) are those of e(P,Q) swapped, so two triangles
 * sharing an edge see exactly opposite values there.
 *
 * Exactly one crossing per surface ([NUM-WATERTIGHT-1]).  Two more steps
 * make a ray that meets a shared edge or vertex of a closed mesh hit
 * exactly one of the triangles there, not both (a glass face counted twice)
 * and not none (a leak):
 *   - the sign of each edge function is exact: fl(p - q) has the sign of
 *     the exact products' difference whenever p = fl(Qx Py) and q =
 *     fl(Qy Px) differ (rounding is monotone), and when they are equal the
 *     exact remainders fma(Qx, Py, -p) and fma(Qy, Px, -q) decide.  So the
 *     signs are those of the exact 2D geometry of the sheared vertices,
 *     which all triangles of the mesh share;
 *   - an edge function that is exactly 0 (the ray passes through the edge's
 *     line) of an edge shared with another triangle of a mesh takes the
 *     sign it would have if the ray were moved by
 *     (delta, delta^2) in the sheared plane, delta -> 0+ ("simulation of
 *     simplicity"): e(P,Q) + delta (Qy - Py) + delta^2 (Px - Qx), so the
 *     sign of Qy - Py, or when that is 0 of Px - Qx, both exact.  The
 *     moved ray lies strictly inside exactly one of the triangles around
 *     an edge or vertex that the mesh folds flat around it, whatever their
 *     winding; at a silhouette (the surface folds back) it meets both or
 *     neither, an even number, as a closed surface must.
 *   - an edge of one triangle only (a lone `triangle`, the rim of an open
 *     mesh) counts an exact 0 as inside, as Woop et al. do: its boundary is
 *     closed, so a ray through the rim of a sheet, or through the tip of a
 *     fan, still hits it (where the rim meets a shared edge, a ray through
 *     that vertex may then hit two triangles of an open mesh).
 * The paper's fallback for a 0 edge function in single precision (recompute
 * in double) is not needed: the working type is double or wider.  This
 * relies on no fused multiply-add contraction of the plain products, which
 * GCC leaves off in ISO C mode (-std=c99).  Exactness needs the products to
 * stay normal doubles (the numeric domain above).
 */
typedef struct tri_bary {
    real t, b[3];
} tri_bary;

/* The exact sign of a b - c d when fl(a b) == fl(c d) (so the rounded
 * difference is 0): the sign of the remainders' difference. */
static int remainder_sign(real a, real b, real c, real d)
{
    real p = a * b, q = c * d;
    real rp = fma(a, b, -p), rq = fma(c, d, -q);
    return (rp > rq) - (rp < rq);
}

/* The tie rule above for an edge P -> Q through the ray: the sign of
 * Qy - Py, else of Px - Qx; 0 only when P and Q coincide in the plane. */
static int tie_sign(real px, real py, real qx, real qy)
{
    if (qy != py)
        return qy > py ? 1 : -1;
    return (px > qx) - (px < qx);
}

/* num/den from the magnitudes an = |num|, ad = |den| > 0, with the sign
 * IEEE division gives (num's, zeros included, turned for a negative den):
 * the same double as num/den.  Eva sees the quotient of the magnitudes
 * the caller's comparisons bounded (an <= ad), which it loses for num/den. */
/*@ requires \is_finite(num) && \is_finite(den) && ad > 0;
    requires EXACT(an == \abs(num) && ad == \abs(den));   // doubles too: fabs is exact
    assigns \nothing;
    ensures \is_finite(\result);
    ensures EXACT(\result == num / den); */
static real shear_ratio(real num, real an, real den, real ad)
{
    real m = copysign(an / ad, num);
    return den < 0.0 ? -m : m;
}

/* The shear for the largest component dz on axis kz (az = |dz|); d1, d2
 * (a1, a2 their magnitudes) are the components on axes kz + 1 and kz + 2
 * (mod 3), swapped when dz is negative to keep the winding. */
/*@ requires \valid(sh) && 0 <= kz <= 2;
    requires \is_finite(dz) && \is_finite(d1) && \is_finite(d2);
    // doubles too: fabs is exact, and the caller compared them
    requires EXACT(az == \abs(dz) && a1 == \abs(d1) && a2 == \abs(d2));
    requires EXACT(a1 <= az && a2 <= az);   // dz is the largest
    assigns *sh;
    ensures 0 <= sh->kx <= 2 && 0 <= sh->ky <= 2 && EXACT(sh->kz == kz && sh->dz == dz);   // copies
    ensures EXACT(dz < 0 ? sh->kx == (kz + 2) % 3 && sh->ky == (kz + 1) % 3
                         : sh->kx == (kz + 1) % 3 && sh->ky == (kz + 2) % 3);
    ensures EXACT(sh->sx * dz == (dz < 0 ? d2 : d1) && sh->sy * dz == (dz < 0 ? d1 : d2));
    ensures EXACT(-1 <= sh->sx <= 1 && -1 <= sh->sy <= 1); */
static void shear_set(isect_shear *sh, int kz, real dz, real az, real d1, real a1, real d2, real a2)
{
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3, turn = dz < 0.0;
    sh->kx = turn ? ky : kx;
    sh->ky = turn ? kx : ky;
    sh->kz = kz;
    sh->dz = dz;
    sh->sx = sh->sy = 0.0;
    if (dz == 0.0)
        return;
    real s1 = shear_ratio(d1, a1, dz, az), s2 = shear_ratio(d2, a2, dz, az);
    sh->sx = turn ? s2 : s1;
    sh->sy = turn ? s1 : s2;
}

/* kz: the axis of the largest magnitude, x on a tie, then y; each case
 * its own call, so that its comparisons bound the magnitudes it divides.
 * Flattened for the compiler: shear_set inlined into each case, its `% 3`
 * and turn folded to constants (the lazy shear's making, about 2 % of
 * mesh.scene); the same operations. */
/*@ logic mreal vcomp(vec3 a, integer k) = k == 0 ? a.x : k == 1 ? a.y : a.z; */
/*@ requires \valid_read(r) && \valid(sh) && \separated(r, sh);
    requires vfinite(r->dir);
    assigns *sh;
    ensures 0 <= sh->kx <= 2 && 0 <= sh->ky <= 2 && 0 <= sh->kz <= 2;
    ensures \is_finite(sh->sx) && \is_finite(sh->sy);
    // kz the largest magnitude's axis, (kx, ky, kz) a rotation of (0, 1, 2) for dz >= 0 and
    // turned (the winding kept) for dz < 0 (doubles too: a choice by comparisons)
    ensures EXACT(sh->dz == vcomp(r->dir, sh->kz) && \abs(sh->dz) == vmaxabs(r->dir) &&
                  (sh->dz < 0 ? sh->kx == (sh->kz + 2) % 3 && sh->ky == (sh->kz + 1) % 3
                              : sh->kx == (sh->kz + 1) % 3 && sh->ky == (sh->kz + 2) % 3));
    // the shear: d_kx - sx dz = 0, d_ky - sy dz = 0 (the ray along +z), |sx|, |sy| <= 1
    // (triangle_solve's Eva driver takes that box)
    ensures EXACT(sh->sx * sh->dz == vcomp(r->dir, sh->kx) && sh->sy * sh->dz == vcomp(r->dir, sh->ky));
    ensures EXACT(-1 <= sh->sx <= 1 && -1 <= sh->sy <= 1); */
HINT_FLATTEN void isect_shear_make(const ray *r, isect_shear *sh)
{
    vec3 d = r->dir;
    real x = fabs(d.x), y = fabs(d.y), z = fabs(d.z);
    if (x >= y) {
        if (x >= z)
            shear_set(sh, 0, d.x, x, d.y, y, d.z, z);
        else
            shear_set(sh, 2, d.z, z, d.x, x, d.y, y);
    } else if (y >= z) {
        shear_set(sh, 1, d.y, y, d.z, z, d.x, x);
    } else {
        shear_set(sh, 2, d.z, z, d.x, x, d.y, y);
    }
}

/* A corner translated to the ray origin, permuted and sheared: (x, y) in
 * the sheared plane, z the distance along the permuted axis. */
static inline vec3 triangle_corner(vec3 v, vec3 o, real sx, real sy, int kx, int ky, int kz)
{
    vec3 a = vec_sub(v, o);
    real z = vec_component(a, kz);
    return vec_make(vec_component(a, kx) - sx * z, vec_component(a, ky) - sy * z, z);
}

/* The three corners, one case per permutation: with the axes as constants
 * the coordinates stay in registers (a loop over arrays indexed by the
 * axes went through the stack, and its 16-byte reloads of two 8-byte
 * stores stalled).  The same operations in the same order. */
#define TRIANGLE_CORNERS(kx, ky, kz)                                \
    do {                                                            \
        q0 = triangle_corner(v[0], o, sx, sy, kx, ky, kz);          \
        q1 = triangle_corner(v[1], o, sx, sy, kx, ky, kz);          \
        q2 = triangle_corner(v[2], o, sx, sy, kx, ky, kz);          \
    } while (0)

/* e / det, for e zero or of det's sign with |e| <= |det| (det = e0 + e1 +
 * e2 of edge functions of one sign: monotone rounding): in [0, 1] for these
 * doubles, a relation Eva's intervals lose.  For |det| >= 2^-16 the
 * quotient is finite in intervals too (|e| <= 2^1005 within the extent);
 * below, isect_quotient divides the magnitudes (the same double; a zero e
 * gets the sign IEEE division gives, the product's).  The clamp never
 * fires: it holds the weight in [0, 1] where Eva sees it. */
static real triangle_weight_small(real e, real det)
{
    real b;
    isect_quotient(e, det, &b);
    return e == 0.0 ? e * det : b;
}

static inline real triangle_weight_held(real b) { return b > 1.0 ? 1.0 : b < 0.0 ? 0.0 : b; }

/* sh: the ray's permutation and shear (isect_shear_make of r). */
static int triangle_solve(const vec3 v[3], int inclusive, const ray *r, const isect_shear *sh, tri_bary *out)
{
    real dz = sh->dz;
    if (dz == 0.0)
        return 0;
    real sx = sh->sx, sy = sh->sy;
    vec3 o = r->origin, q0, q1, q2;
    switch (sh->kz * 3 + sh->kx) {
    case 0 * 3 + 1:
        TRIANGLE_CORNERS(1, 2, 0);
        break;
    case 0 * 3 + 2:
        TRIANGLE_CORNERS(2, 1, 0);
        break;
    case 1 * 3 + 2:
        TRIANGLE_CORNERS(2, 0, 1);
        break;
    case 1 * 3 + 0:
        TRIANGLE_CORNERS(0, 2, 1);
        break;
    case 2 * 3 + 0:
        TRIANGLE_CORNERS(0, 1, 2);
        break;
    default:
        TRIANGLE_CORNERS(1, 0, 2);
        break;
    }
    /* e_i = e(P, Q) for P, Q the corners after i: written out, the
     * hottest lines of the tracer. */
    real e0 = q2.x * q1.y - q2.y * q1.x, e1 = q0.x * q2.y - q0.y * q2.x, e2 = q1.x * q0.y - q1.y * q0.x;
    int inside = e0 > 0.0 || e1 > 0.0 || e2 > 0.0, outside = e0 < 0.0 || e1 < 0.0 || e2 < 0.0;
    /* A nonzero rounded edge function has its exact sign: only zeros need
     * the remainders and the tie rule. */
    if (inside && outside)
        return 0;
    if (e0 == 0.0 || e1 == 0.0 || e2 == 0.0) {
        real e[3] = {e0, e1, e2}, px[3] = {q0.x, q1.x, q2.x}, py[3] = {q0.y, q1.y, q2.y};
        for (int i = 0; i < 3; i++) {
            int p = (i + 1) % 3, q = (i + 2) % 3;
            if (e[i] != 0.0)
                continue;
            int sign = remainder_sign(px[q], py[p], py[q], px[p]);
            if (sign == 0 && !(inclusive >> i & 1))
                sign = tie_sign(px[p], py[p], px[q], py[q]);
            inside |= sign > 0;
            outside |= sign < 0;
        }
    }
    if (inside == outside)
        return 0;
    real det = e0 + e1 + e2;
    if (det == 0.0)
        return 0;
    /* t = the barycentric mean of the vertices' z distances, over dz.  The
     * paper's sum of e_i pz_i before dividing by det is a product of three
     * coordinates: it overflows for a triangle at 2^342 (and underflows at
     * 2^-342) where the weights b_i = e_i / det, free of scale, do not.
     * An edge decided by its remainders or by the tie rule has e_i = 0,
     * and so weight 0. */
    /* Each sign of det (and of dz below) in its own branch: Eva narrows
     * it by each test, not by their disjunction. */
    real b0, b1, b2;
    if (det >= 0x1p-16) {
        b0 = e0 / det, b1 = e1 / det, b2 = e2 / det;
    } else if (det <= -0x1p-16) {
        b0 = e0 / det, b1 = e1 / det, b2 = e2 / det;
    } else {
        b0 = triangle_weight_small(e0, det);
        b1 = triangle_weight_small(e1, det);
        b2 = triangle_weight_small(e2, det);
    }
    out->b[0] = triangle_weight_held(b0);
    out->b[1] = triangle_weight_held(b1);
    out->b[2] = triangle_weight_held(b2);
    /* num is within 3 2^501 (the weights in [0, 1], the corners' distances
     * within the extent): finite over |dz| >= 2^-500.  Below, t past 2^1020
     * is no hit: a hit point within the extent ([LANG-EXTENT-1]) is at
     * |t| <= 2^502 / |world d|, a transform keeps t, and a world ray's
     * direction has its largest component >= 1/8; only a degenerate local
     * direction passes 2^1020, where the quotient was +Inf or a t no hit
     * can have. */
    real num = out->b[0] * q0.z + out->b[1] * q1.z + out->b[2] * q2.z;
    if (dz >= 0x1p-500) {
        out->t = num / dz;
    } else if (dz <= -0x1p-500) {
        out->t = num / dz;
    } else {
        if (!isect_quotient(num, dz, &out->t))
            return 0;
        if (num == 0.0)
            out->t = num * dz; /* num / dz's zero: its sign is the product's */
    }
    return 1;
}

static int triangle_hits(const vec3 v[3], const vec3 *normals, int inclusive, const ray *r, const isect_shear *sh,
                         hit *out, int bare)
{
    tri_bary s;
    if (!triangle_solve(v, inclusive, r, sh, &s) || !in_interval(r, s.t))
        return 0;
    if (bare) {
        out->t = s.t;
        return 1;
    }
    /* The barycentric point lies in the triangle's plane to rounding of the
     * vertices, which o + t d (error relative to the origin) does not. */
    vec3 p = vec_scale(v[0], s.b[0]);
    p = vec_madd(p, v[1], s.b[1]);
    p = vec_madd(p, v[2], s.b[2]);
    vec3 n = vec_normalize(vec_cross(vec_sub(v[1], v[0]), vec_sub(v[2], v[0])));
    isect_hit_set(out, s.t, p, n, r->dir);
    out->b1 = s.b[1];
    out->b2 = s.b[2];
    if (normals) {
        vec3 sn = vec_scale(normals[0], s.b[0]);
        sn = vec_madd(sn, normals[1], s.b[1]);
        sn = vec_madd(sn, normals[2], s.b[2]);
        sn = vec_normalize(sn);
        /* Opposite vertex normals can cancel; keep the geometric one then. */
        out->shading_normal = vec_length2(sn) > 0.0 ? sn : n;
    }
    return 1;
}

/* Triangle k of a mesh: its corners, and its vertex normals when it has
 * them (returns the normals pointer to pass on, or NULL). */
static const vec3 *mesh_corners(const scene_trimesh *m, int k, vec3 v[3], vec3 n[3])
{
    const int *c = m->tri[k];
    v[0] = m->positions[c[0]];
    v[1] = m->positions[c[1]];
    v[2] = m->positions[c[2]];
    if (!m->tri_normal || m->tri_normal[k][0] < 0)
        return NULL;
    for (int i = 0; i < 3; i++)
        n[i] = m->normals[m->tri_normal[k][i]];
    return n;
}

/* The inclusive edges of triangle k (triangle_solve's numbering): its open
 * edge from corner j to j + 1 is the one opposite corner j + 2. */
static int open_edges(const scene_trimesh *m, int k)
{
    int open = m->open ? m->open[k] : 0;
    return (open >> 1 & 1) | (open >> 2 & 1) << 1 | (open & 1) << 2;
}

static int mesh_triangle_hits(const scene_trimesh *m, int k, const ray *r, const isect_shear *sh, hit *out,
                              int bare)
{
    vec3 v[3], n[3];
    const vec3 *normals = mesh_corners(m, k, v, n);
    if (!triangle_hits(v, normals, open_edges(m, k), r, sh, out, bare))
        return 0;
    out->part = k;
    return 1;
}

/* The nearest crossings of a whole mesh by testing every triangle: for
 * callers without a BVH (tests, one-off queries).  Ties go to the lower
 * triangle index.  Writes up to max in increasing t. */
static int mesh_hits(const scene_trimesh *m, const ray *r, hit *out, int max, int bare)
{
    int found = 0;
    isect_shear sh;
    isect_shear_make(r, &sh);
    for (int k = 0; k < m->tri_count; k++) {
        hit h;
        if (!mesh_triangle_hits(m, k, r, &sh, &h, bare))
            continue;
        int at = found;
        while (at > 0 && h.t < out[at - 1].t)
            at--;
        if (at >= max)
            continue;
        for (int j = found < max ? found : max - 1; j > at; j--)
            out[j] = out[j - 1];
        out[at] = h;
        found += found < max;
    }
    return found;
}

/* sh: r's shear, or NULL to compute it here (a triangle needs it). */
static int local_hits(const scene_prim *p, const ray *r, const isect_shear *sh, hit *out, int max, int bare)
{
    isect_shear own;
    switch (p->kind) {
    case PRIM_SPHERE:
        return sphere_hits(p->u.sphere.center, p->u.sphere.radius, r, out, max, bare);
    case PRIM_PLANE:
        return plane_hits(p->u.plane.point, p->u.plane.normal, r, out, bare);
    case PRIM_TRIANGLE:
        if (!sh) {
            isect_shear_make(r, &own);
            sh = &own;
        }
        return triangle_hits(p->u.triangle.p, p->u.triangle.n, 7, r, sh, out, bare);
    case PRIM_DISK:
        return disk_hits(p->u.disk.center, p->u.disk.normal, p->u.disk.radius, r, out);
    case PRIM_BOX:
        return box_hits(p->u.box.lo, p->u.box.hi, r, out, max, bare);
    case PRIM_CYLINDER:
        return isect_cylinder_hits(p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.open,
                                   r, out, max);
    case PRIM_CONE:
        return isect_cone_hits(p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1],
                               p->u.cone.open, r, out, max);
    case PRIM_TORUS:
        return isect_torus_hits(p->u.torus.center, p->u.torus.axis, p->u.torus.major, p->u.torus.minor, r, out,
                                max);
    case PRIM_MESH: /* prim_hits: a mesh has no local frame */
        break;
    }
    return 0;
}

/*
 * [NUM-FRAME-2] A kept frame that squashes a shape puts the local ray's
 * origin far from it in local units though near it in the world: a sphere
 * scaled by [1, s, 1] seen from 10 above has its local origin 10/s radii
 * away and its local direction 1/s long.  A local solve forms its points
 * o + t d with an error of eps |o| (local units), 1e5 radii at s = 1e-20:
 * the sphere's perpendicular foot and the torus's bounding sphere lose the
 * line and draw holes or nothing, and past s = 1e-154 |d|^2 overflows.
 * That error lies along d's huge component, so it moves a point along the
 * line, not off it: a point of the line placed near the shape, and the
 * solve run from there, has only that point's own error.
 *
 * local_start_of places it, only for a local direction longer than 2^20
 * (max norm): a frame stretching a ray's direction that much squashes the
 * shape across it; any other frame is solved as before, unchanged, at the
 * cost of one test.  The direction is scaled by a power of two to a
 * largest component in [1/2, 1) when it is past 2^64 (exact: t scales
 * back by the same power).  Then, while the origin is
 * more than 2^20 radii of the shape's local ball from its centre, the
 * origin steps to the line's point nearest that centre, less twice the
 * ball's radius and 2^-44 (|t| + reach) (reach = (|o| + |c|) / |d|, max
 * norms: over 200 times the rounding of o + t d and of the foot's t), so
 * that every crossing after tmin stays ahead of it; each step shrinks the
 * distance by about 2^-43, so 32 steps come from 2^1023 radii.  The solve
 * runs on the line from the start, t from 0, and its crossings are
 * shifted and scaled back and held to the ray's interval.  A nearer origin
 * is solved as before.
 *
 * [NUM-FRAME-5] Each step is taken on the world line, q = (o - T) + t d,
 * and the start's local point formed anew as L^-1 q, not stepped in the
 * local frame.  A squash along no local axis (rotate, then scale
 * [1, s, 1]) gives L^-1 (o - T) coordinates of about 10/s in two or three
 * local axes at once, each rounded by eps 10/s on its own: off the line,
 * not along it, and a local step keeps that error (the turned box drew
 * nothing from s = 1e-16).  In the world, q's rounding is eps |q| across
 * the squash (no more than the world line's own, [NUM-FRAME-1]) and
 * eps |q_s| along it, which L^-1 makes eps |q_s| / s along the squashed
 * axis: the local direction's own, to s |d across| / |d along|, so along
 * the line; within 2^-44 reach in t (reach is about |q_s| / |d_s| there).
 * A q near the shape has local coordinates of the shape's size, rounded
 * to the shape's ulps.
 */
enum { START_STEPS = 32 };

typedef struct local_start {
    int on;          /* 0: solved on the local ray as it is */
    real scale;      /* t on the ray = scale (t0 + t from the start) */
    real t0;
    vec3 origin;     /* o + scale t0 d, local */
    vec3 dir;        /* d scale */
} local_start;

/* A ball holding the shape in its own frame (sums of extents: no square
 * root); 0 for a shape without one (a plane). */
static int local_ball(const scene_prim *p, vec3 *c, real *rho)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        *c = p->u.sphere.center;
        *rho = p->u.sphere.radius;
        return 1;
    case PRIM_DISK:
        *c = p->u.disk.center;
        *rho = p->u.disk.radius;
        return 1;
    case PRIM_TORUS:
        *c = p->u.torus.center;
        *rho = p->u.torus.major + p->u.torus.minor;
        return 1;
    case PRIM_BOX: {
        vec3 e = vec_scale(vec_sub(p->u.box.hi, p->u.box.lo), 0.5);
        *c = vec_add(p->u.box.lo, e);
        *rho = fabs(e.x) + fabs(e.y) + fabs(e.z);
        return 1;
    }
    case PRIM_CYLINDER:
    case PRIM_CONE: {
        int cone = p->kind == PRIM_CONE;
        vec3 from = cone ? p->u.cone.from : p->u.cylinder.from, to = cone ? p->u.cone.to : p->u.cylinder.to;
        real r = cone ? fmax(p->u.cone.radius[0], p->u.cone.radius[1]) : p->u.cylinder.radius;
        vec3 e = vec_scale(vec_sub(to, from), 0.5);
        *c = vec_add(from, e);
        *rho = fabs(e.x) + fabs(e.y) + fabs(e.z) + r;
        return 1;
    }
    default:
        return 0;
    }
}

/* Whether the ray starts elsewhere (*s), for a direction past 2^20. */
static int local_start_of(const scene_prim *p, const ray *r, const ray *local, local_start *s)
{
    const double(*w)[4] = p->frame->to_world.m;
    vec3 c, q = vec_sub(r->origin, vec_make(w[0][3], w[1][3], w[2][3]));
    real rho, dm = vec_max_abs(local->dir);
    if (!local_ball(p, &c, &rho))
        return 0;
    s->on = 0;
    s->scale = 1;
    s->t0 = 0;
    s->origin = local->origin;
    s->dir = local->dir;
    if (dm > 0x1p64) {
        int e;
        frexp(dm, &e);
        s->on = 1;
        s->scale = ldexp(1.0, -e);
        s->dir = vec_scale(local->dir, s->scale);
        dm = vec_max_abs(s->dir);
    }
    for (int k = 0; k < START_STEPS; k++) {
        vec3 f = vec_sub(c, s->origin);
        real tm;
        if (!(vec_max_abs(f) > 0x1p20 * rho) || !isect_quotient(vec_dot(f, s->dir), vec_length2(s->dir), &tm))
            break;
        real reach = (vec_max_abs(s->origin) + vec_max_abs(c)) / dm;
        real step = tm - 2 * rho / dm - 0x1p-44 * (fabs(tm) + reach);
        if (!(k ? step > 0 : step * s->scale > local->tmin))
            break;
        s->on = 1;
        s->t0 += step;
        q = vec_madd(q, r->dir, step * s->scale);
        s->origin = xform_vector(&p->frame->to_local, q);
    }
    return s->on;
}

/* local_hits on the local ray, from its start: the crossings in the ray's
 * own t, held to its interval (the start's solve keeps every crossing
 * ahead of it, so none in the interval is crowded out).  Only for a ray
 * that starts elsewhere: prim_hits calls local_hits itself otherwise. */
static int start_hits(const scene_prim *p, const ray *local, const local_start *s, hit *out, int max, int bare)
{
    real from = s->t0 > 0 ? 0 : local->tmin / s->scale;
    ray near = {s->origin, s->dir, from < 0x1p1000 ? from : 0x1p1000, INFINITY};
    hit all[ISECT_MAX_CROSSINGS];
    int n = local_hits(p, &near, NULL, all, ISECT_MAX_CROSSINGS, bare), kept = 0;
    for (int i = 0; i < n && kept < max; i++) {
        real t = s->scale * (s->t0 + all[i].t);
        if (t > local->tmin && t < local->tmax) {
            out[kept] = all[i];
            out[kept++].t = t;
        }
    }
    return kept;
}

/*
 * [NUM-FRAME-6] A frame that stretches a shape across its own axes (turned,
 * then scaled unevenly: `rotate R scale [S, 1, 1]`) has a spread
 * | |L| |L^-1| | of about S: the local line, L^-1 (o - T) + t L^-1 d, is
 * rounded by eps |L^-1| |o - T| in each local coordinate on its own, and L
 * takes that back to the world S times larger, across the line.  The local
 * solve's t is still good (the shift is across the line, along the surface
 * where it meets it: spec/numerics.md 2.17c), so past a spread of 2^10 the
 * point is taken on the world line at that t, within the world line's own
 * rounding, instead of through L (which moved it up to 2^-52 S |o - T| off
 * the line: the lit pixels of a sphere stretched 1e12 off by 4e-5).  Any
 * other frame keeps L x + T, bit for bit.
 *
 * That t is the crossing of a line eps |L^-1| |o - T| off the world one,
 * so the point is as far off the surface, which grows with the eye's
 * distance (past the spawn offset from about 500 sizes away).  It is
 * pulled back by the shape's own solve from b, a point of the line a
 * margin m before it: L^-1 b rounds to the shape's size at the hit, not
 * to the eye's distance, and the crossing there with the hit's entering
 * and within m of it moves the point along d.  The hit keeps its t.
 */
#define FRAME_SPREAD_MAX 0x1p10
static real frame_spread(const scene_frame *f)
{
    /* Row i of |L| |L^-1| sums to sum_j |L_ij| (row j of |L^-1| summed). */
    real inverse_rows[3], worst = 0;
    for (int j = 0; j < 3; j++)
        inverse_rows[j] = fabs(f->to_local.m[j][0]) + fabs(f->to_local.m[j][1]) + fabs(f->to_local.m[j][2]);
    for (int i = 0; i < 3; i++) {
        const double *l = f->to_world.m[i];
        real row = fabs(l[0]) * inverse_rows[0] + fabs(l[1]) * inverse_rows[1] + fabs(l[2]) * inverse_rows[2];
        worst = row > worst ? row : worst;
    }
    return worst;
}

static vec3 frame_world_point(const scene_prim *p, const ray *r, const hit *h, real spread)
{
    if (!(spread > FRAME_SPREAD_MAX))
        return xform_point(&p->frame->to_world, h->point);
    const double(*w)[4] = p->frame->to_world.m;
    vec3 T = vec_make(w[0][3], w[1][3], w[2][3]), q = vec_madd(vec_sub(r->origin, T), r->dir, h->t);
    real dm = vec_max_abs(r->dir), m = 0x1p-20 * (fabs(h->t) + vec_max_abs(vec_sub(r->origin, T)) / dm);
    vec3 back = vec_madd(q, r->dir, -m), dl = xform_vector(&p->frame->to_local, r->dir);
    int e;
    frexp(vec_max_abs(dl), &e);
    real k = ldexp(1.0, e > -1000 ? -e : 0); /* a power of two: exact */
    ray near = {xform_vector(&p->frame->to_local, back), vec_scale(dl, k), 0, INFINITY};
    hit all[ISECT_MAX_CROSSINGS];
    int n = dm > 0 && m > 0 && m < INFINITY && e > -1000 ? local_hits(p, &near, NULL, all, ISECT_MAX_CROSSINGS, 0) : 0;
    real best = m;
    for (int i = 0; i < n; i++) {
        real s = all[i].t * k - m;
        if (all[i].entering == h->entering && fabs(s) < fabs(best))
            best = s;
    }
    return vec_add(best < m ? vec_madd(q, r->dir, best) : q, T);
}

/*
 * A primitive with a local frame: the ray goes in through to_local (its
 * direction is not renormalised, so t is the same in both frames), points
 * come back through to_world and normals through the inverse transpose.
 * entering is kept from the local frame: d . n has the same sign in both,
 * since (L^-1 d) . n_local = d . (L^-T n_local).
 *
 * [NUM-FRAME-1] The origin goes in as L^-1 (o - T) (scene_frame_local).
 * It still rounds to ulps of |o - T|, so a shape far smaller than that
 * distance can be hit by a local ray whose world ray misses its box: a hit
 * counts only within the world ray's stretch in the padded box the BVH
 * holds the part in, found by the BVH's own slab test, so the BVH never
 * culls a hit the exhaustive walk keeps.  The box is made only once there
 * is a hit; a hit outside it runs the test again on that stretch.
 * [NUM-FRAME-3] The stretch is widened by FRAME_GATE_PAD of its ends for
 * the test and the hits are then clamped into it: a shape thinner than
 * the rounding of t (a disk in an axis plane, whose box has no thickness;
 * a shape squashed below eps |t|) has its hits on the stretch's ends to
 * rounding, where the slab's entry (not enlarged) and the hit's own t
 * fall either side.  Clamped, a hit is still within the box's stretch,
 * which is all the BVH's culling asks.
 */
#define FRAME_GATE_PAD (16 * DBL_EPSILON)
static int prim_hits(const scene_prim *p, const ray *r, hit *out, int max, int bare)
{
    if (p->kind == PRIM_MESH)
        return mesh_hits(&p->u.mesh, r, out, max, bare);
    if (!p->frame)
        return local_hits(p, r, NULL, out, max, bare);
    ray local = *r;
    local.origin = scene_frame_local(p->frame, r->origin);
    local.dir = xform_vector(&p->frame->to_local, r->dir);
    local_start start;
    start.on = vec_max_abs(local.dir) > 0x1p20 && local_start_of(p, r, &local, &start);
    int n = start.on ? start_hits(p, &local, &start, out, max, bare) : local_hits(p, &local, NULL, out, max, bare);
    vec3 lo, hi;
    if (n > 0 && isect_part_padded_bounds(p, 0, &lo, &hi)) {
        slab_ray s = slab_make(r);
        real tn = r->tmin, tf = r->tmax;
        slab_box(lo, hi, &s, &tn, &tf);
        if (!(tn < tf))
            return 0;
        real wide_n = tn - FRAME_GATE_PAD * fabs(tn), wide_f = tf + FRAME_GATE_PAD * fabs(tf);
        local.tmin = wide_n > r->tmin ? wide_n : r->tmin;
        local.tmax = wide_f < r->tmax ? wide_f : r->tmax;
        if (out[0].t <= local.tmin || out[n - 1].t >= local.tmax)
            n = start.on ? start_hits(p, &local, &start, out, max, bare) : local_hits(p, &local, NULL, out, max, bare);
        for (int i = 0; i < n; i++)
            out[i].t = out[i].t < tn ? tn : out[i].t > tf ? tf : out[i].t;
    }
    real spread = n > 0 && !bare ? frame_spread(p->frame) : 0;
    for (int i = 0; i < n && !bare; i++) {
        out[i].point = frame_world_point(p, r, &out[i], spread);
        out[i].normal = vec_normalize(xform_normal(&p->frame->to_local, out[i].normal));
        out[i].shading_normal = vec_normalize(xform_normal(&p->frame->to_local, out[i].shading_normal));
    }
    return n;
}

int isect_prim(const scene_prim *p, ray *r, hit *h)
{
    if (!prim_hits(p, r, h, 1, 0))
        return 0;
    r->tmax = h->t;
    return 1;
}

int isect_prim_all(const scene_prim *p, const ray *r, hit out[ISECT_MAX_CROSSINGS])
{
    return prim_hits(p, r, out, ISECT_MAX_CROSSINGS, 0);
}

int isect_part_count(const scene_prim *p)
{
    return p->kind == PRIM_MESH ? p->u.mesh.tri_count : 1;
}

/* sh: r's shear (the world ray's: a transformed primitive makes its own
 * for its local ray), or NULL. */
static int part_hits(const scene_prim *p, int part, const ray *r, const isect_shear *sh, hit *out, int max,
                     int bare)
{
    isect_shear own;
    if (p->kind == PRIM_MESH) {
        if (!sh) {
            isect_shear_make(r, &own);
            sh = &own;
        }
        return mesh_triangle_hits(&p->u.mesh, part, r, sh, out, bare);
    }
    if (!p->frame)
        return local_hits(p, r, sh, out, max, bare);
    return prim_hits(p, r, out, max, bare);
}

int isect_part(const scene_prim *p, int part, ray *r, hit *h)
{
    return isect_part_sheared(p, part, r, NULL, h);
}

int isect_part_sheared(const scene_prim *p, int part, ray *r, const isect_shear *sh, hit *h)
{
    if (!part_hits(p, part, r, sh, h, 1, 0))
        return 0;
    r->tmax = h->t;
    return 1;
}

int isect_part_all(const scene_prim *p, int part, const ray *r, hit out[ISECT_MAX_CROSSINGS])
{
    return isect_part_all_sheared(p, part, r, NULL, out);
}

int isect_part_all_sheared(const scene_prim *p, int part, const ray *r, const isect_shear *sh,
                           hit out[ISECT_MAX_CROSSINGS])
{
    return part_hits(p, part, r, sh, out, ISECT_MAX_CROSSINGS, 0);
}

int isect_part_crossings(const scene_prim *p, int part, const ray *r)
{
    return isect_part_crossings_sheared(p, part, r, NULL);
}

/* [NUM-PLANE-AWAY-1] plane_t's answer.  A ray that starts on one side of the plane and moves
 * away from it (num = n.(p0 - o) and dn = n.d, plane_t's own doubles, of
 * opposite signs as `< 0` tells them) is told without the quotient: there
 * isect_quotient either fails or gives -m, m = |num|/|dn| >= 0 (held at
 * 2^1020), a t <= 0 (a zero num too: -0), which in_interval rejects for
 * tmin >= 0; dn == 0 (either sign of zero: num < 0 then) is plane_t's first
 * miss.  Shadow rays from a floor toward a light above it (mesh.scene:
 * each one's floor test) are such rays. */
static int plane_moving_away(vec3 point, vec3 normal, const ray *r)
{
    real dn = vec_dot(normal, r->dir), num = vec_dot(normal, vec_sub(point, r->origin));
    return r->tmin >= 0.0 && (num < 0.0) != (dn < 0.0);
}

HINT_FLATTEN int isect_plane_crossings(vec3 point, vec3 normal, const ray *r)
{
    real t;
    if (plane_moving_away(point, normal, r))
        return 0;
    return plane_t(point, normal, r, &t);
}

/* The same quick miss ([NUM-PLANE-AWAY-1]: plane_t would answer 0); the
 * miss's *t is not read (bvh.c nearest_test).  Flattened as the count:
 * plane_t's two dot products are the quick miss's. */
HINT_FLATTEN int isect_plane_nearest(vec3 point, vec3 normal, const ray *r, real *t)
{
    if (plane_moving_away(point, normal, r))
        return 0;
    return plane_t(point, normal, r, t);
}

/* A world-frame sphere's count (sphere_hits, bare 2), out of line:
 * inlined, its copy of sphere_hits grew the shadow walk that calls
 * isect_part_crossings_sheared (mesh.scene, without a sphere, +0.08 %). */
HINT_FLATTEN HINT_OUT_OF_LINE static int sphere_count(const scene_prim *p, const ray *r)
{
    hit out[ISECT_MAX_CROSSINGS];
    return sphere_hits(p->u.sphere.center, p->u.sphere.radius, r, out, ISECT_MAX_CROSSINGS, 2);
}

/* Whether sphere_count is > 0: sphere_hits' count stopped at its first
 * crossing (max 1).  Each root is taken or not whatever the other's fate
 * (found is only counted, bare 2 writes nothing), so the first root taken
 * is the one the full count takes first: 1 exactly where that count is >= 1
 * ([NUM-SPHERE-ANY-1]).  Out of line as sphere_count. */
HINT_FLATTEN HINT_OUT_OF_LINE static int sphere_crossed(vec3 center, real radius, const ray *r)
{
    hit out[1];
    return sphere_hits(center, radius, r, out, 1, 2);
}

int isect_part_crossed(const scene_prim *p, int part, const ray *r)
{
    if (p->kind == PRIM_SPHERE && !p->frame)
        return sphere_crossed(p->u.sphere.center, p->u.sphere.radius, r);
    return isect_part_crossings_sheared(p, part, r, NULL) > 0;
}

int isect_part_crossings_sheared(const scene_prim *p, int part, const ray *r, const isect_shear *sh)
{
    hit out[ISECT_MAX_CROSSINGS];
    /* A plane in the world frame (the unbounded parts every walk tests):
     * plane_hits' bare count, without the dispatch through part_hits. */
    if (p->kind == PRIM_PLANE && !p->frame)
        return isect_plane_crossings(p->u.plane.point, p->u.plane.normal, r);
    if (p->kind == PRIM_SPHERE && !p->frame)
        return sphere_count(p, r);
    return part_hits(p, part, r, sh, out, ISECT_MAX_CROSSINGS, 1);
}

int isect_hot_make(const scene_prim *p, int part, real g[ISECT_HOT_REALS], int *reals)
{
    vec3 v[3], n[3];
    int code;
    if (p->kind == PRIM_SPHERE && !p->frame) {
        g[0] = p->u.sphere.center.x;
        g[1] = p->u.sphere.center.y;
        g[2] = p->u.sphere.center.z;
        g[3] = p->u.sphere.radius;
        *reals = 4;
        return ISECT_HOT_SPHERE;
    }
    if (p->kind == PRIM_BOX && !p->frame) {
        g[0] = p->u.box.lo.x;
        g[1] = p->u.box.lo.y;
        g[2] = p->u.box.lo.z;
        g[3] = p->u.box.hi.x;
        g[4] = p->u.box.hi.y;
        g[5] = p->u.box.hi.z;
        g[6] = g[7] = 0.0;
        *reals = 8;
        return ISECT_HOT_BOX;
    }
    if (p->kind == PRIM_MESH) {
        mesh_corners(&p->u.mesh, part, v, n);
        code = ISECT_HOT_TRIANGLE | open_edges(&p->u.mesh, part) << 2;
    } else if (p->kind == PRIM_TRIANGLE && !p->frame) {
        for (int i = 0; i < 3; i++)
            v[i] = p->u.triangle.p[i];
        code = ISECT_HOT_TRIANGLE | 7 << 2;
    } else {
        return ISECT_HOT_NONE;
    }
    for (int i = 0; i < 3; i++) {
        g[3 * i] = v[i].x;
        g[3 * i + 1] = v[i].y;
        g[3 * i + 2] = v[i].z;
    }
    g[9] = g[10] = g[11] = 0.0;
    *reals = 12;
    return code;
}

int isect_hot_reals(const scene_prim *p)
{
    if (p->kind == PRIM_SPHERE && !p->frame)
        return 4;
    if (p->kind == PRIM_BOX && !p->frame)
        return 8;
    return p->kind == PRIM_MESH || (p->kind == PRIM_TRIANGLE && !p->frame) ? 12 : 0;
}

/* A hot record's triangle, bare: triangle_hits' test with triangle_solve
 * inlined (flattened), so the corners stay in registers and the solve's
 * weights never go through memory (called, it took its corners and
 * returned its weights through the stack, and saved six registers, for
 * each of the tens of millions of triangle tests of a mesh scene's shadow
 * rays).  The same operations as triangle_hits(v, NULL, inclusive, r, sh,
 * out, 1).  Kept out of hot_hits: inlined there, its registers and frame
 * were saved and made for every sphere and box test as well (room.scene
 * +1.8 % instructions). */
HINT_FLATTEN HINT_OUT_OF_LINE static int hot_triangle(const real *g, int inclusive, const ray *r, const isect_shear *sh, hit *out)
{
    vec3 v[3] = {vec_make(g[0], g[1], g[2]), vec_make(g[3], g[4], g[5]), vec_make(g[6], g[7], g[8])};
    tri_bary s;
    if (!triangle_solve(v, inclusive, r, sh, &s) || !in_interval(r, s.t))
        return 0;
    out->t = s.t;
    return 1;
}

/* A hot record's sphere: sphere_hits, with the miss of a ray moving away
 * from it told first (isect_sphere_moving_away).  Only the hot records: the
 * scene_prim's test (isect_part, isect_sphere) stays the full one the
 * tests hold this to.  Out of line in the two copies below, sphere_hits
 * flattened into each: inlined into the walks the test grew their loops
 * (mesh.scene, without a sphere, +0.7 % instructions). */
static inline int hot_sphere(const real *g, const ray *r, hit *out, int max, int bare)
{
    vec3 c = vec_make(g[0], g[1], g[2]);
    if (isect_sphere_moving_away(vec_sub(r->origin, c), g[3], r))
        return 0;
    return sphere_hits(c, g[3], r, out, max, bare);
}

/* Two copies, each with its max and bare constant: the nearest walk's
 * candidate (t and point: its normal waits for the win) and the
 * crossings' bare ones (a shadow ray's count), so that
 * neither carries the other's branches, nor a bare hit the point it does
 * not write (one copy with both passed at run time: nested_glass at
 * 120x80 1.8 % and demo 1.1 % more instructions in all).  With max
 * ISECT_MAX_CROSSINGS (isect_hot_crossings: gcc's clone has it constant)
 * hot_sphere_bare is a count and writes no t (sphere_hits' bare 2);
 * hot_hits' max 1 writes it.  A third copy for the count changed the
 * frame of the shadow walk it is inlined into (mesh.scene, without a sphere, +0.08 %). */
HINT_FLATTEN HINT_OUT_OF_LINE static int hot_sphere_nearest(const real *g, const ray *r, hit *out)
{
    return hot_sphere(g, r, out, 1, 3);
}

HINT_FLATTEN HINT_OUT_OF_LINE static int hot_sphere_bare(const real *g, const ray *r, hit *out, int max)
{
    return hot_sphere(g, r, out, max, max == ISECT_MAX_CROSSINGS ? 2 : 1);
}

/* Whether the ray passes the triangle by in the sheared plane: its three
 * corners (isect_corner_at: triangle_corner's x or y alone, the same operations) all
 * on one side of x = 0, or of y = 0, strictly.  triangle_solve then
 * answers no crossing: its edge functions have the exact signs of those of
 * the rounded corners (a nonzero rounded difference of two rounded products
 * has the exact sign, a zero one is told by the remainders), and the
 * origin, strictly apart from the three corners, is no convex combination
 * of them; so, for det != 0, some weight e_i / det is < 0 and, as they sum
 * to 1, another > 0: e_i of both strict signs, rejected.  For det == 0 the
 * e_i sum to 0: both signs again, or all three 0 (det rounds to 0,
 * rejected).  One side strictly: a corner at 0 can leave the origin on an
 * edge, where the tie rule decides.  x0 x1 > 0 and x0 x2 > 0 say it in
 * fewer instructions than six comparisons: a rounded product keeps its
 * exact sign, or is 0 on underflow (then no quick miss), and is no larger
 * than the edge functions' own products.  x first, then y: y's corners
 * are not made for a triangle x tells apart. */
static inline int triangle_apart(const vec3 v[3], vec3 o, real sx, real sy, int kx, int ky, int kz)
{
    real x0 = isect_corner_at(v[0], o, sx, kx, kz), x1 = isect_corner_at(v[1], o, sx, kx, kz),
         x2 = isect_corner_at(v[2], o, sx, kx, kz);
    if (x0 * x1 > 0.0 && x0 * x2 > 0.0)
        return 1;
    real y0 = isect_corner_at(v[0], o, sy, ky, kz), y1 = isect_corner_at(v[1], o, sy, ky, kz),
         y2 = isect_corner_at(v[2], o, sy, ky, kz);
    return y0 * y1 > 0.0 && y0 * y2 > 0.0;
}

/* A run for one permutation of the axes, given as constants at each call
 * below: triangle_solve's switch on the permutation folds away, and the
 * shear, the origin and the interval stay in registers over the run,
 * where a call of hot_triangle per record made its prologue, its switch
 * and its loads again each time.  triangle_solve itself is unchanged (the
 * function Eva analyses); inlined, it does the same operations in the same
 * order, so each record's answer is hot_triangle's to the bit. */
static inline int triangle_run(const bvh_hot *hot, int n, const real *reals, const ray *r, isect_shear sh, int kx,
                               int ky, int kz, real *t)
{
    sh.kx = kx;
    sh.ky = ky;
    sh.kz = kz;
    int i;
    for (i = 0; i < n && ISECT_HOT_KIND(hot[i].code) == ISECT_HOT_TRIANGLE; i++) {
        const real *g = reals + hot[i].at;
        vec3 v[3] = {vec_make(g[0], g[1], g[2]), vec_make(g[3], g[4], g[5]), vec_make(g[6], g[7], g[8])};
        tri_bary s;
        if (triangle_apart(v, r->origin, sh.sx, sh.sy, kx, ky, kz))
            continue;
        if (triangle_solve(v, hot[i].code >> 2, r, &sh, &s) && in_interval(r, s.t)) {
            *t = s.t;
            return i;
        }
    }
    return i;
}

/* Out of line for hot_triangle's reason; called once per run, not per
 * record.  The cases are triangle_solve's: (kz, kx) gives ky. */
HINT_FLATTEN HINT_OUT_OF_LINE int isect_hot_triangle_run(const bvh_hot *hot, int n, const real *reals,
                                                           const ray *r, const isect_shear *sh, real *t)
{
    if (sh->dz == 0.0) {
        int i = 0;  /* triangle_solve's first answer, for every record */
        while (i < n && ISECT_HOT_KIND(hot[i].code) == ISECT_HOT_TRIANGLE)
            i++;
        return i;
    }
    switch (sh->kz * 3 + sh->kx) {
    case 0 * 3 + 1:
        return triangle_run(hot, n, reals, r, *sh, 1, 2, 0, t);
    case 0 * 3 + 2:
        return triangle_run(hot, n, reals, r, *sh, 2, 1, 0, t);
    case 1 * 3 + 2:
        return triangle_run(hot, n, reals, r, *sh, 2, 0, 1, t);
    case 1 * 3 + 0:
        return triangle_run(hot, n, reals, r, *sh, 0, 2, 1, t);
    case 2 * 3 + 0:
        return triangle_run(hot, n, reals, r, *sh, 0, 1, 2, t);
    default:
        return triangle_run(hot, n, reals, r, *sh, 1, 0, 2, t);
    }
}

/* The record's crossings, bare (up to max; isect_hot_nearest passes 1, so
 * a sphere's t is written: hot_sphere_bare counts only at
 * ISECT_MAX_CROSSINGS). */
static int hot_hits(int code, const real *g, const ray *r, const isect_shear *sh, hit *out, int max)
{
    if (ISECT_HOT_KIND(code) == ISECT_HOT_SPHERE)
        return hot_sphere_bare(g, r, out, max);
    if (ISECT_HOT_KIND(code) == ISECT_HOT_BOX)
        return box_hits(vec_make(g[0], g[1], g[2]), vec_make(g[3], g[4], g[5]), r, out, max, 1);
    return hot_triangle(g, code >> 2, r, sh, out);
}

/* Whether the ray's segment lies wholly on one side of the box's slab
 * [lo, hi] (g: lo, then hi; lo <= hi or not) on one axis, so that
 * box_slabs returns 0 there (or at an earlier axis).  Say d > 0 (d < 0 is
 * the mirror image) and a = l - o, b = h - o, rounded as box_slabs rounds
 * them (a rounded difference keeps its sign):
 * - behind: a, b <= 0.  Both of isect_quotient's results are then <= 0 (a
 *   number <= 0 over d > 0 gives -m, +0 or -2^1020), so the exit tt[1]
 *   falls to at most 0 at this axis, and `tt[1] <= r->tmin` returns 0 for
 *   tmin >= 0 ([NUM-FINITE-1]; the caller tests it).
 * - beyond: a, b > p = end d rounded, end = tmax <= 2^1020.  Rounding to
 *   nearest moves end d by at most half the gap between p and the double
 *   next to it on the side of end d, so a > p gives a > end d exactly,
 *   a / d > end, and the quotient, rounded (monotone) or held at 2^1020,
 *   is >= end; so the entry tt[0] rises to at least tmax here and
 *   `tt[0] >= r->tmax` returns 0.  With end = +Inf (tmax past 2^1020, where
 *   a held quotient could fall short of it) p is +Inf and nothing is
 *   beyond.
 * A shadow ray leaving the box it starts on (room.scene's floor and walls)
 * is behind, one ending at a light below the ceiling is short of the
 * ceiling's box: told without box_slabs' divisions. */
static inline int box_axis_apart(real o, real d, real l, real h, real end)
{
    real a = l - o, b = h - o, p = end * d;
    if (d > 0.0)
        return (a <= 0.0 && b <= 0.0) || (a > p && b > p);
    return d < 0.0 && ((a >= 0.0 && b >= 0.0) || (a < p && b < p));
}

/* Whether the segment lies apart from one of the box's slabs (g: lo, then
 * hi): box_slabs would return 0.  A ray with tmin < 0 or NaN, which no
 * tracer makes, is left to box_slabs. */
static inline int box_segment_apart(const real *g, const ray *r)
{
    real end = r->tmax <= 0x1p1020 ? r->tmax : HUGE_VAL;
    return r->tmin >= 0.0 &&
           (box_axis_apart(r->origin.x, r->dir.x, g[0], g[3], end) ||
            box_axis_apart(r->origin.y, r->dir.y, g[1], g[4], end) ||
            box_axis_apart(r->origin.z, r->dir.z, g[2], g[5], end));
}

/* A hot record's box, counted: what box_hits(lo, hi, r, out, max, 1)
 * returns for max >= 2 (box_slabs' one or two crossings, each counted when
 * in the interval), with the corners read where the record holds them and
 * no t stored.  Called through hot_hits, the two corners went by value
 * through the stack for each of the millions of box tests of a room's
 * shadow rays (nearly all misses).  Out of line for the reason of
 * hot_triangle: inlined into the walk it would grow its loop.  A segment
 * apart from one of the box's slabs counts 0 at once. */
HINT_FLATTEN HINT_OUT_OF_LINE static int hot_box_crossings(const real *g, const ray *r)
{
    real tt[2];
    int axis[2];
    if (box_segment_apart(g, r))
        return 0;
    if (!box_slabs(vec_make(g[0], g[1], g[2]), vec_make(g[3], g[4], g[5]), r, tt, axis))
        return 0;
    return in_interval(r, tt[0]) + (tt[0] != tt[1] && in_interval(r, tt[1]));
}

/* isect_hot_crossings' body, shared with isect_hot_crossed: each exported
 * form has one caller in the walks (bvh.c), which gcc inlines it into; one
 * function with two callers went out of line (demo.scene +0.6 %). */
static inline HINT_IN_LINE int hot_crossings(int code, const real *g, const ray *r, const isect_shear *sh)
{
    hit out[ISECT_MAX_CROSSINGS];
    if (ISECT_HOT_KIND(code) == ISECT_HOT_BOX)
        return hot_box_crossings(g, r);
    if (ISECT_HOT_KIND(code) == ISECT_HOT_TRIANGLE)
        return hot_triangle(g, code >> 2, r, sh, out);
    return hot_sphere_bare(g, r, out, ISECT_MAX_CROSSINGS);
}

int isect_hot_crossings(int code, const real *g, const ray *r, const isect_shear *sh)
{
    return hot_crossings(code, g, r, sh);
}

int isect_hot_crossed(int code, const real *g, const ray *r, const isect_shear *sh)
{
    if (ISECT_HOT_KIND(code) == ISECT_HOT_SPHERE) {
        vec3 c = vec_make(g[0], g[1], g[2]);
        return !isect_sphere_moving_away(vec_sub(r->origin, c), g[3], r) && sphere_crossed(c, g[3], r);
    }
    return hot_crossings(code, g, r, sh) > 0;
}

int isect_hot_nearest(int code, const real *g, const ray *r, const isect_shear *sh, real *t)
{
    hit out[1];
    if (!hot_hits(code, g, r, sh, out, 1))
        return 0;
    *t = out[0].t;
    return 1;
}

/* A hit (found != 0, its t in (tmin, tmax)) shrinks the ray's tmax to
 * it; a miss leaves tmax alone: testing primitives one after another keeps
 * the nearest (ray.h). */
/*@ requires \valid(r) && \valid_read(h) && \separated(r, h);
    requires found != 0 ==> r->tmin < h->t < r->tmax;
    assigns r->tmax;
    ensures \result == found;
    ensures found != 0 ==> r->tmax == h->t && \old(r->tmin) < h->t < \old(r->tmax);
    ensures found == 0 ==> r->tmax == \old(r->tmax); */
static int nearest(int found, ray *r, const hit *h);

int isect_hot_candidate(int code, const real *g, ray *r, hit *h)
{
    if (ISECT_HOT_KIND(code) == ISECT_HOT_SPHERE)
        return nearest(hot_sphere_nearest(g, r, h), r, h);
    if (ISECT_HOT_KIND(code) == ISECT_HOT_BOX)
        return nearest(box_hits(vec_make(g[0], g[1], g[2]), vec_make(g[3], g[4], g[5]), r, h, 1, 0), r, h);
    return -1;
}

void isect_hot_complete(int code, const real *g, vec3 dir, hit *h)
{
    if (ISECT_HOT_KIND(code) == ISECT_HOT_SPHERE)
        sphere_normal_set(h, h->t, h->point, vec_make(g[0], g[1], g[2]), dir);
}

int isect_hot_hit(int code, const real *g, ray *r, hit *h)
{
    int met = isect_hot_candidate(code, g, r, h);
    if (met > 0)
        isect_hot_complete(code, g, r->dir, h);
    return met;
}

static int nearest(int found, ray *r, const hit *h)
{
    if (found)
        r->tmax = h->t;
    return found;
}

int isect_sphere(vec3 center, real radius, ray *r, hit *h)
{
    return nearest(sphere_hits(center, radius, r, h, 1, 0), r, h);
}

int isect_plane(vec3 point, vec3 normal, ray *r, hit *h)
{
    return nearest(plane_hits(point, normal, r, h, 0), r, h);
}

int isect_triangle(const vec3 p[3], const vec3 *normals, ray *r, hit *h)
{
    isect_shear sh;
    isect_shear_make(r, &sh);
    return nearest(triangle_hits(p, normals, 7, r, &sh, h, 0), r, h);
}

int isect_disk(vec3 center, vec3 normal, real radius, ray *r, hit *h)
{
    return nearest(disk_hits(center, normal, radius, r, h), r, h);
}

int isect_box(vec3 lo, vec3 hi, ray *r, hit *h)
{
    return nearest(box_hits(lo, hi, r, h, 1, 0), r, h);
}

/*@ requires \valid(r) && \valid(h) && \separated(r, h);
    requires vfinite(from) && vfinite(to) && !veq(from, to);      // [LANG-VALID-2], [LANG-EXTENT-1]
    requires \is_finite(radius) && radius > 0;                     // check_radius
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(r->tmin) && r->tmin >= 0;   // [NUM-FINITE-1]
    assigns *h, r->tmax;
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> \old(r->tmin) < h->t < \old(r->tmax) && r->tmax == h->t;
    ensures \result == 0 ==> r->tmax == \old(r->tmax); */
int isect_cylinder(vec3 from, vec3 to, real radius, int open, ray *r, hit *h)
{
    return nearest(isect_cylinder_hits(from, to, radius, open, r, h, 1), r, h);
}

/*@ requires \valid(r) && \valid(h) && \separated(r, h);
    requires vfinite(from) && vfinite(to) && !veq(from, to);      // [LANG-VALID-2], [LANG-EXTENT-1]
    requires \is_finite(r0) && \is_finite(r1) && r0 >= 0 && r1 >= 0 && (r0 > 0 || r1 > 0);   // check.c: not both 0
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(r->tmin) && r->tmin >= 0;   // [NUM-FINITE-1]
    assigns *h, r->tmax;
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> \old(r->tmin) < h->t < \old(r->tmax) && r->tmax == h->t;
    ensures \result == 0 ==> r->tmax == \old(r->tmax); */
int isect_cone(vec3 from, vec3 to, real r0, real r1, int open, ray *r, hit *h)
{
    return nearest(isect_cone_hits(from, to, r0, r1, open, r, h, 1), r, h);
}

/*@ requires \valid(r) && \valid(h) && \separated(r, h);
    requires vfinite(center) && vfinite(axis);                               // [LANG-VALID-2]
    requires \is_finite(major) && \is_finite(minor) && 0 < minor < major;     // a ring torus (check.c)
    requires vfinite(r->origin) && vfinite(r->dir) && \is_finite(r->tmin) && r->tmin >= 0;   // [NUM-FINITE-1]
    assigns *h, r->tmax;
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> \old(r->tmin) < h->t < \old(r->tmax) && r->tmax == h->t;
    ensures \result == 0 ==> r->tmax == \old(r->tmax); */
int isect_torus(vec3 center, vec3 axis, real major, real minor, ray *r, hit *h)
{
    return nearest(isect_torus_hits(center, axis, major, minor, r, h, 1), r, h);
}

int isect_prim_bounds(const scene_prim *p, vec3 *lo, vec3 *hi)
{
    return scene_prim_world_box(p, lo, hi);
}

int isect_part_bounds(const scene_prim *p, int part, vec3 *lo, vec3 *hi)
{
    if (p->kind != PRIM_MESH)
        return isect_prim_bounds(p, lo, hi);
    vec3 v[3], n[3];
    mesh_corners(&p->u.mesh, part, v, n);
    *lo = vec_min(v[0], vec_min(v[1], v[2]));
    *hi = vec_max(v[0], vec_max(v[1], v[2]));
    return vec_is_finite(*lo) && vec_is_finite(*hi);
}

/* Primitive boxes are widened by this fraction of their coordinates' size,
 * so a hit computed a few ulps outside its true box is still inside. */
#define BOUNDS_PAD 0x1p-40

static real bounds_pad(real lo, real hi)
{
    return BOUNDS_PAD * fmax(fmax(fabs(lo), fabs(hi)), hi - lo);
}

int isect_part_padded_bounds(const scene_prim *p, int part, vec3 *lo, vec3 *hi)
{
    vec3 l, h;
    if (!isect_part_bounds(p, part, &l, &h))
        return 0;
    vec3 e = vec_make(bounds_pad(l.x, h.x), bounds_pad(l.y, h.y), bounds_pad(l.z, h.z));
    *lo = vec_sub(l, e);
    *hi = vec_add(h, e);
    return vec_is_finite(vec_scale(vec_add(*lo, *hi), 0.5));
}

/* fmax(a, b) for magnitudes, a comparison instead of a library call per
 * hit: they are built from fabs and sizes >= 0, so never NaN and never -0,
 * and where a == b the two are the same bits, so either is fmax's. */
static real larger(real a, real b)
{
    return a > b ? a : b;
}

static real triangle_magnitude(const vec3 v[3])
{
    return larger(vec_max_abs(v[0]), larger(vec_max_abs(v[1]), vec_max_abs(v[2])));
}

static inline real sphere_magnitude(const scene_prim *p)
{
    return vec_max_abs(p->u.sphere.center) + p->u.sphere.radius;
}

static real local_magnitude(const scene_prim *p)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        return sphere_magnitude(p);
    case PRIM_PLANE:
        return vec_max_abs(p->u.plane.point);
    case PRIM_TRIANGLE:
        return triangle_magnitude(p->u.triangle.p);
    case PRIM_DISK:
        return vec_max_abs(p->u.disk.center) + p->u.disk.radius;
    case PRIM_BOX:
        return larger(vec_max_abs(p->u.box.lo), vec_max_abs(p->u.box.hi));
    case PRIM_CYLINDER:
        return larger(vec_max_abs(p->u.cylinder.from), vec_max_abs(p->u.cylinder.to)) + p->u.cylinder.radius;
    case PRIM_CONE:
        return larger(vec_max_abs(p->u.cone.from), vec_max_abs(p->u.cone.to)) +
               larger(p->u.cone.radius[0], p->u.cone.radius[1]);
    case PRIM_TORUS:
        return vec_max_abs(p->u.torus.center) + p->u.torus.major + p->u.torus.minor;
    case PRIM_MESH: {
        real m = 0.0;
        for (int i = 0; i < p->u.mesh.position_count; i++)
            m = larger(m, vec_max_abs(p->u.mesh.positions[i]));
        return m;
    }
    }
    return 0.0;
}

/* For a local frame: |L x + T|_max <= |L|_inf |x|_max + |T|_max, with
 * |L|_inf the largest row sum of absolute values. */
real isect_prim_magnitude(const scene_prim *p)
{
    real m = local_magnitude(p);
    if (!p->frame)
        return m;
    real norm = 0.0, shift = 0.0;
    for (int i = 0; i < 3; i++) {
        const double *row = p->frame->to_world.m[i];
        norm = larger(norm, fabs(row[0]) + fabs(row[1]) + fabs(row[2]));
        shift = larger(shift, fabs(row[3]));
    }
    return norm * m + shift;
}

/* The contract other functions' proofs take (assumed, not itself proved: it walks
 * every kind of primitive and a mesh's arrays): a maximum of magnitudes and
 * sizes, >= 0 (finite data, radii > 0: [LANG-VALID-2]), +Inf past DBL_MAX,
 * never NaN (a transform's linear part is invertible, so its norm is > 0). */
/*@ requires \valid_read(p);
    assigns \result \from indirect: *p, indirect: part;
    ensures (\is_finite(\result) && \result >= 0) || \is_plus_infinity(\result);   // admit (assumed, listed by make prove; +Inf allowed: spawn_offset caps it) */
real isect_part_magnitude(const scene_prim *p, int part)
{
    vec3 v[3], n[3];
    /* A sphere in the world frame, the glass balls' every spawn: local_magnitude's
     * value, without its switch and isect_prim_magnitude's frame test. */
    if (p->kind == PRIM_SPHERE && !p->frame)
        return sphere_magnitude(p);
    if (p->kind != PRIM_MESH)
        return isect_prim_magnitude(p);
    mesh_corners(&p->u.mesh, part, v, n);
    return triangle_magnitude(v);
}

/*
 * The shadow terminator (spec/shading.md, [SHADE-TERMINATOR-1]): Hanika,
 * "Hacking the Shadow Terminator", Ray Tracing Gems II, ch. 4, 2021.  A
 * smooth triangle's vertex normals describe a curved surface its flat
 * facet lies below; where a light is above the shading normal's horizon but
 * below the facet's plane, a shadow ray from the facet runs into the
 * neighbouring facets.  The shadow ray starts instead from the point lifted
 * toward that curved surface: for each corner i, the hit point p is
 * projected onto the plane through v_i normal to n_i when it lies below
 * it, and the three projections are averaged with the barycentric weights:
 *   p' = p - sum_i b_i min(0, (p - v_i) . n_i) n_i.
 * (Written as a correction of p, not as the mean of the projected points,
 * so p' keeps p's precision where the correction is 0: on flat parts and
 * at every vertex.)  Flat triangles and other shapes return p.
 */
vec3 isect_shadow_point(const scene_prim *p, const hit *h)
{
    vec3 v[3], n[3];
    const vec3 *normals = NULL;
    if (p->kind == PRIM_MESH) {
        normals = mesh_corners(&p->u.mesh, h->part, v, n);
    } else if (p->kind == PRIM_TRIANGLE && p->u.triangle.n) {
        for (int i = 0; i < 3; i++)
            v[i] = p->u.triangle.p[i];
        normals = p->u.triangle.n;
    }
    if (!normals)
        return h->point;
    real b[3] = {1.0 - h->b1 - h->b2, h->b1, h->b2};
    vec3 q = h->point;
    for (int i = 0; i < 3; i++) {
        real below = vec_dot(vec_sub(h->point, v[i]), normals[i]);
        if (below < 0.0)
            q = vec_madd(q, normals[i], -b[i] * below);
    }
    return q;
}

/*@ // o is p moved by offset along n, to the side of toward (make prove)
  predicate is_spawned(vec3 o, vec3 p, vec3 n, vec3 toward, mreal offset) =
    \let s = vdot(toward, n) >= 0 ? offset : -offset;
    o.x == p.x + s * n.x && o.y == p.y + s * n.y && o.z == p.z + s * n.z;
*/

/* How far a secondary ray is pushed off a surface: SPAWN_REL of the
 * magnitude its point's rounding is relative to, plus the floor.
 * Defensive: a primitive's magnitude passes DBL_MAX (+Inf) when its data
 * nears it (a sphere at 1e308 of radius 1e308); it is capped there, so the
 * offset stays finite (at most 2^-42 DBL_MAX) and no other ray changes. */
/*@ requires vfinite(point);
    requires !\is_NaN(magnitude) && magnitude >= 0;  // isect_part_magnitude: max |data| (+Inf past DBL_MAX)
    assigns \nothing;
    ensures \is_finite(\result) && \result >= SPAWN_ABS && DOUBLES(\result <= 0x1p983);
    ensures EXACT(magnitude <= DBL_MAX ==>
                  \result == SPAWN_REL * \max(magnitude, vmaxabs(point)) + SPAWN_ABS);
    ensures EXACT(vbounded(point, 0x1p1022) ==> \result <= 0x1p983); */
static real spawn_offset(vec3 point, real magnitude)
{
    real m = magnitude <= DBL_MAX ? magnitude : DBL_MAX, at = vec_max_abs(point);
    /* The larger by a comparison, not fmax (a call into libm), fmax's value:
     * m is never NaN, a NaN `at` (a point the contract excludes) gives m as
     * fmax does, and where the two are equal (0 and -0 at most differ) the
     * product with SPAWN_REL plus SPAWN_ABS is the same double. */
    return SPAWN_REL * (at > m ? at : m) + SPAWN_ABS;
}

/* p + step without forming an infinity: a coordinate at or past 2^1023 (a
 * hit on a plane 9e307 away) is moved by halves, which round as p + step
 * does, and held at DBL_MAX where that passes it. */
/*@ requires \is_finite(p) && \is_finite(step) && DOUBLES(\abs(step) <= 0x1p990);
    assigns \nothing;
    ensures \is_finite(\result);
    ensures EXACT(\abs(p + step) <= 0x1p1023 ==> \result == p + step); */
static real offset_coord(real p, real step)
{
    if (p < 0x1p1023 && p > -0x1p1023)
        return p + step;
    real h = 0.5 * p + 0.5 * step;
    return h > 0.5 * DBL_MAX ? DBL_MAX : h < -0.5 * DBL_MAX ? -DBL_MAX : 2 * h;
}

/* The origin moved off the surface by offset to the side of toward: +n
 * when toward . n >= 0, else -n. */
/*@ requires vfinite(point);
    requires vfinite(normal) && vbounded(normal, 4);    // [LANG-VALID-2]: unit normals (isect_*)
    requires vfinite(toward) && vbounded(toward, 0x1p1020);
    requires \is_finite(offset) && offset > 0 && DOUBLES(offset <= 0x1p983);  // spawn_offset
    assigns \nothing;
    ensures \is_finite(\result.x) && \is_finite(\result.y) && \is_finite(\result.z);
    ensures EXACT(vbounded(point, 0x1p1022) && offset <= 0x1p983 ==> is_spawned(\result, point, normal, toward, offset)); */
HINT_IN_LINE static inline vec3 spawn_origin(vec3 point, vec3 normal, vec3 toward, real offset)
{
    real s = vec_dot(toward, normal) >= 0.0 ? offset : -offset;
    return vec_make(offset_coord(point.x, normal.x * s), offset_coord(point.y, normal.y * s),
                    offset_coord(point.z, normal.z * s));
}

/* A shadow ray's tmin: the offset again, along the ray.  A surface closer
 * than that to the point left is one with it: at a concave edge (a floor
 * meeting a wall) the rounded point lies behind the other surface as often
 * as in front, and light must not be stopped by it (spec/numerics.md,
 * "Concave corners").  Mirror and refracted rays keep tmin = 0: inside a
 * closed mirror box one that leaves a face next to an edge must still meet
 * the adjacent face, 1e-14 away. */
/*@ requires \is_finite(offset) && offset > 0 && DOUBLES(offset <= 0x1p983);  // spawn_offset
    requires vfinite(dir) && vbounded(dir, 4);  // a unit direction (add_source: L)
    requires DOUBLES(\abs(dir.x) >= 0.125 || \abs(dir.y) >= 0.125 || \abs(dir.z) >= 0.125);
    assigns \nothing;
    ensures \is_finite(\result) && \result >= 0;
    ensures EXACT(vzero(dir) ==> \result == 0);
    ensures EXACT(!vzero(dir) ==> \result * \result * vnorm2(dir) == offset * offset); */
static real shadow_tmin(real offset, vec3 dir)
{
    real len = vec_length(dir);
    /*@ assert EXACT(len > 0 ==> (offset / len) * len == offset); */
    return len > 0 ? offset / len : 0;
}

/*@ requires vfinite(point);
    requires vfinite(normal) && vbounded(normal, 4);
    requires vfinite(dir) && vbounded(dir, 4);
    requires shadow ==> DOUBLES(\abs(dir.x) >= 0.125 || \abs(dir.y) >= 0.125 || \abs(dir.z) >= 0.125);
    requires \is_finite(offset) && offset > 0 && DOUBLES(offset <= 0x1p983);
    assigns \nothing;
    ensures vfinite(\result.origin);
    ensures EXACT(vbounded(point, 0x1p1022) && offset <= 0x1p983 ==> is_spawned(\result.origin, point, normal, dir, offset));
    ensures EXACT(veq(\result.dir, dir));
    ensures \is_finite(\result.tmin) && \result.tmin >= 0 && DOUBLES(\is_plus_infinity(\result.tmax));
    ensures EXACT(!shadow ==> \result.tmin == 0);
    ensures EXACT(shadow && !vzero(dir) ==> \result.tmin * \result.tmin * vnorm2(dir) == offset * offset); */
static ray spawn_by(vec3 point, vec3 normal, vec3 dir, real offset, int shadow)
{
    ray r;
    r.origin = spawn_origin(point, normal, dir, offset);
    r.dir = dir;
    r.tmin = shadow ? shadow_tmin(offset, dir) : 0;
    r.tmax = HUGE_VAL;
    return r;
}

/*@ requires vfinite(point);
    requires vfinite(normal) && vbounded(normal, 4);
    requires vfinite(dir) && vbounded(dir, 4);
    requires shadow ==> DOUBLES(\abs(dir.x) >= 0.125 || \abs(dir.y) >= 0.125 || \abs(dir.z) >= 0.125);
    requires !\is_NaN(magnitude) && magnitude >= 0;
    assigns \nothing;
    ensures vfinite(\result.origin) && \is_finite(\result.tmin) && \result.tmin >= 0;
    ensures EXACT(vbounded(point, 0x1p1022) && magnitude <= 0x1p1022 ==>
                  is_spawned(\result.origin, point, normal, dir,
                             SPAWN_REL * \max(magnitude, vmaxabs(point)) + SPAWN_ABS));
    ensures EXACT(veq(\result.dir, dir) && (!shadow ==> \result.tmin == 0)); */
static ray spawn(vec3 point, vec3 normal, vec3 dir, real magnitude, int shadow)
{
    return spawn_by(point, normal, dir, spawn_offset(point, magnitude), shadow);
}

/* The unit vector along to (a shadow ray's direction), the zero vector for
 * a zero to, and |to| (vec_length_fast) in *dist.  1/|to| overflows for
 * |to| <= 2^-1024 (a light 1e-316 from the spawned origin), and to * Inf
 * is NaN where a component of to is 0: there each component is divided by
 * |to| instead (|to_i| <= |to|).  d > 1/REAL_MAX (which rounds to 2^-1024,
 * 2^-16384 for long double) holds exactly when 1/d is finite, so every
 * other direction is to * (1/d) as before, the same bits (trace.c
 * add_source's inv <= REAL_MAX guard, decided without forming the
 * infinity, which Eva counts as an alarm). */
/*@ requires vfinite(to) && DOUBLES(vbounded(to, 0x1p1022));   // vec_length_fast's: spawn_to_by's to
    requires \valid(dist);
    assigns *dist \from to;
    assigns \result \from to;
    ensures \initialized(dist) && \is_finite(*dist) && *dist >= 0;
    ensures \is_finite(\result.x) && \is_finite(\result.y) && \is_finite(\result.z) &&
            DOUBLES(-8 <= \result.x <= 8 && -8 <= \result.y <= 8 && -8 <= \result.z <= 8);
    ensures EXACT(*dist == 0 ==> vzero(\result));
    ensures EXACT(*dist > 0 ==> \result.x * *dist == to.x && \result.y * *dist == to.y && \result.z * *dist == to.z); */
static vec3 unit_toward(vec3 to, real *dist)
{
    real d = vec_length_fast(to);
    *dist = d;
    if (d > 1 / REAL_MAX) {
        real inv = 1.0 / d;
        /*@ assert EXACT(inv * d == 1); */
        /* with vec_length_fast's d^2 = |to|^2 among the hypotheses the
         * provers no longer close the z part alone (round 6) */
        /*@ ghost lemma_inverse_back(to.x, inv, d); lemma_inverse_back(to.y, inv, d); lemma_inverse_back(to.z, inv, d); */
        /*@ assert EXACT((to.x * inv) * d == to.x && (to.y * inv) * d == to.y && (to.z * inv) * d == to.z); */
        return vec_scale(to, inv);
    }
    return d > 0.0 ? vec_make(to.x / d, to.y / d, to.z / d) : vec_make(0.0, 0.0, 0.0);
}

/* A shadow ray toward target: the origin pushed off to the target's side,
 * tmin the offset, tmax >= 0, a zero dir where tmax is 0, else dir along
 * target - origin, reaching it at tmax / (1 - SPAWN_SHADOW_SHRINK).  Open
 * (spec/proofs.md, "Rays and lights"): dir of unit length (WP). */
/*@ requires vfinite(point) && vbounded(point, 0x1p1019);  // [LANG-EXTENT-1] (check_extent.c): a bounded shape's hit within 2^502; a plane's: open (spec/proofs.md)
    requires vfinite(normal) && vbounded(normal, 4);         // [LANG-VALID-2]: unit normals (isect_*)
    requires vfinite(target) && vbounded(target, 0x1p503);   // [LANG-EXTENT-1]: light_point within 2^503
    requires \is_finite(offset) && offset > 0 && DOUBLES(offset <= 0x1p983);  // spawn_offset
    assigns \nothing;
    ensures EXACT(\result.tmin == offset);   // Eva: the interval, no relation (the clause below)
    ensures EXACT(offset <= 0x1p983 ==> \let s = vdot(target, normal) >= vdot(point, normal) ? offset : -offset;
                  \result.origin.x == point.x + s * normal.x && \result.origin.y == point.y + s * normal.y &&
                  \result.origin.z == point.z + s * normal.z);
    ensures \result.tmax >= 0;
    ensures EXACT(\result.tmax == 0 ==> vzero(\result.dir));
    ensures vfinite(\result.origin) && vfinite(\result.dir) && \is_finite(\result.tmax) &&
            \is_finite(\result.tmin) && \result.tmin > 0 && DOUBLES(vbounded(\result.dir, 8));
    ensures EXACT(\result.tmax > 0 ==> \let k = 1 - SPAWN_SHADOW_SHRINK;
                  \result.dir.x * \result.tmax == (target.x - \result.origin.x) * k &&
                  \result.dir.y * \result.tmax == (target.y - \result.origin.y) * k &&
                  \result.dir.z * \result.tmax == (target.z - \result.origin.z) * k); */
static ray spawn_to_by(vec3 point, vec3 normal, vec3 target, real offset)
{
    ray r;
    r.origin = spawn_origin(point, normal, vec_sub(target, point), offset);
    real dist;
    r.dir = unit_toward(vec_sub(target, r.origin), &dist);
    r.tmin = offset;
    r.tmax = dist * (1.0 - SPAWN_SHADOW_SHRINK);
    return r;
}

static ray spawn_to(vec3 point, vec3 normal, vec3 target, real magnitude)
{
    return spawn_to_by(point, normal, target, spawn_offset(point, magnitude));
}

/*@ requires vfinite(point);
    requires vfinite(geometric_normal) && vbounded(geometric_normal, 4);
    requires vfinite(dir) && vbounded(dir, 4);
    assigns \nothing;
    ensures vfinite(\result.origin);
    ensures EXACT(vbounded(point, 0x1p1022) ==>
                  is_spawned(\result.origin, point, geometric_normal, dir, SPAWN_REL * vmaxabs(point) + SPAWN_ABS));
    ensures EXACT(veq(\result.dir, dir) && \result.tmin == 0); */
ray ray_spawn(vec3 point, vec3 geometric_normal, vec3 dir)
{
    return spawn(point, geometric_normal, dir, 0.0, 0);
}

ray ray_spawn_to(vec3 point, vec3 geometric_normal, vec3 target)
{
    return spawn_to(point, geometric_normal, target, 0.0);
}

/*
 * A ray that goes into a box starts strictly inside it, by the offset, on
 * every axis.  A hit next to an edge has its other coordinates on, or an
 * ulp beyond, the adjacent face; a mirror ray from there that heads out
 * through that face meets it at t <= 0 and leaves a closed mirror box
 * (spec/numerics.md, "Box edges").  A turned box (local frame) is clamped
 * in its own frame, by the offset measured there: the world distance to
 * the face of local axis k is the local one times |row k of to_local|^-1,
 * so a local margin of offset |row k| is offset in the world, far more than
 * the rounding of the map back.  Boxes thinner than twice the margin are
 * left alone along that axis.
 */
static vec3 clamp_inside(vec3 lo, vec3 hi, vec3 origin, vec3 margin)
{
    for (int k = 0; k < 3; k++) {
        real o = vec_component(origin, k), m = vec_component(margin, k);
        real a = vec_component(lo, k) + m, b = vec_component(hi, k) - m;
        if (a < b)
            origin = vec_with(origin, k, o < a ? a : o > b ? b : o);
    }
    return origin;
}

/*@ requires \valid_read(p);
    assigns \nothing;   // not proved (spec/proofs.md): returns a value, writes no memory */
static vec3 keep_inside(const scene_prim *p, vec3 origin, real offset)
{
    if (!p->frame)
        return clamp_inside(p->u.box.lo, p->u.box.hi, origin, vec_splat(offset));
    const double(*m)[4] = p->frame->to_local.m;
    vec3 margin = vec_splat(0.0);
    for (int k = 0; k < 3; k++)
        margin = vec_with(margin, k, offset * vec_length(vec_make(m[k][0], m[k][1], m[k][2])));
    vec3 local = clamp_inside(p->u.box.lo, p->u.box.hi, scene_frame_local(p->frame, origin), margin);
    return xform_point(&p->frame->to_world, local);
}

/*
 * The same for a closed mesh, which has no axes to clamp on: the point is
 * first moved along the triangle toward its centroid by the offset (at most
 * half way).  A hit next to an edge may lie an ulp beyond the plane of the
 * triangle across that edge; pushed off along its own normal only, a ray
 * from there into the solid that heads through the other triangle meets it
 * at t <= 0 and leaves (spec/numerics.md, "Mesh edges").  Moved away from
 * the edge by the offset it lies inside the other triangle's plane by about
 * the offset times the sine of the angle between the faces.  Done for rays
 * to either side: which side is inside, a closed mesh's winding does not
 * say (trace.c).
 */
/*@ requires \valid_read(p) && \valid_read(h);
    assigns \nothing;   // not proved (spec/proofs.md): returns a value, writes no memory */
static vec3 off_the_edges(const scene_prim *p, const hit *h, real offset)
{
    vec3 v[3], n[3];
    mesh_corners(&p->u.mesh, h->part, v, n);
    vec3 c = vec_scale(vec_add(v[0], vec_add(v[1], v[2])), 1.0 / 3.0), to = vec_sub(c, h->point);
    real d = vec_length(to), q;
    if (!(d > 0.0))
        return h->point;
    /* fmin(offset, d/2)/d, in [0, 1]: isect_quotient never holds it and
     * gives the same double (num >= 0, den > 0, so +0 for 0); the clamp to
     * [0, 1] changes nothing and is where Eva, which keeps no relation
     * between num and den, sees the bound (spec/proofs.md, "The hit's
     * mirror and refracted rays"). */
    isect_quotient(fmin(offset, d / 2), d, &q);
    return vec_madd(h->point, to, fmax(0.0, fmin(q, 1.0)));
}

/* Contract (make prove, spec/proofs.md "The hit's mirror and refracted
 * rays"): the direction kept, tmin = 0, tmax = +Inf; the origin finite
 * (Eva) but for a box with a local frame, whose matrices validation does
 * not bound ([LANG-EXTENT-1] checks such a box in its own frame). */
/*@ requires \valid_read(p) && \valid_read(h);
    requires vfinite(h->point);                                 // a hit's point (isect_*)
    // a closed mesh's and a box's hit: within the extent ([LANG-EXTENT-1], check_extent.c: 2^502)
    requires p->kind == PRIM_BOX || p->kind == PRIM_MESH ==> DOUBLES(vbounded(h->point, 0x1p1019));
    requires vfinite(h->normal) && vbounded(h->normal, 4);      // [LANG-VALID-2]: unit normals (isect_*)
    requires vfinite(dir) && vbounded(dir, 4);                  // a unit direction (shade_mirror, shade_refract of unit ones), as ray_spawn's
    assigns \nothing;
    ensures !(p->kind == PRIM_BOX && p->frame != \null) ==> vfinite(\result.origin);
    ensures \is_finite(\result.tmin) && \result.tmin >= 0 && DOUBLES(\is_plus_infinity(\result.tmax));
    ensures EXACT(veq(\result.dir, dir));
    ensures EXACT(\result.tmin == 0); */
ray ray_spawn_hit(const scene_prim *p, const hit *h, vec3 dir)
{
    return ray_spawn_hit_sized(p, h, dir, isect_part_magnitude(p, h->part));
}

/* ray_spawn_hit with m, isect_part_magnitude(p, h->part), given: the
 * tracer finds it once a shaded point for its shadow rays' start, its
 * mirror ray and its transmitted ray (about 36 instructions a call on a
 * sphere).  The contract is ray_spawn_hit's, with m as that one's
 * (isect_part_magnitude's ensures). */
/* In line (HINT_IN_LINE_EXTERN; LTO carries it into trace.c's mirror and
 * transmitted rays): its direction and ray went through the stack
 * (spec/performance.md, twenty-third round). */
/*@ requires \valid_read(p) && \valid_read(h);
    requires vfinite(h->point);                                 // a hit's point (isect_*)
    // a closed mesh's and a box's hit: within the extent ([LANG-EXTENT-1], check_extent.c: 2^502)
    requires p->kind == PRIM_BOX || p->kind == PRIM_MESH ==> DOUBLES(vbounded(h->point, 0x1p1019));
    requires vfinite(h->normal) && vbounded(h->normal, 4);      // [LANG-VALID-2]: unit normals (isect_*)
    requires vfinite(dir) && vbounded(dir, 4);                  // a unit direction (shade_mirror, shade_refract of unit ones), as ray_spawn's
    requires (\is_finite(m) && m >= 0) || \is_plus_infinity(m); // isect_part_magnitude's
    assigns \nothing;
    ensures !(p->kind == PRIM_BOX && p->frame != \null) ==> vfinite(\result.origin);
    ensures \is_finite(\result.tmin) && \result.tmin >= 0 && DOUBLES(\is_plus_infinity(\result.tmax));
    ensures EXACT(veq(\result.dir, dir));
    ensures EXACT(\result.tmin == 0); */
HINT_IN_LINE_EXTERN ray ray_spawn_hit_sized(const scene_prim *p, const hit *h, vec3 dir, real m)
{
    vec3 from = p->kind == PRIM_MESH && p->u.mesh.closed ? off_the_edges(p, h, spawn_offset(h->point, m)) : h->point;
    ray r = spawn(from, h->normal, dir, m, 0);
    if (p->kind == PRIM_BOX && vec_dot(dir, h->normal) < 0)
        r.origin = keep_inside(p, r.origin, spawn_offset(h->point, m));
    return r;
}

/* Contracts of the hit's spawn functions (make prove, spec/proofs.md): the
 * hit's point finite (the hit tests' contracts), its geometric normal a
 * unit one ([LANG-VALID-2]; vec_normalize's box to Eva), the primitive's
 * magnitude as isect_part_magnitude's contract gives it.  Toward a
 * target, the origin is point + tmin normal on the target's side (tmin the
 * offset, > 0).  Along dir, the side is ray_shadow_along's clause (the
 * same ray from ray_shadow_start's offset); stated here, with the offset
 * unnamed, the provers do not close it (spec/proofs.md). */
/*@ requires \valid_read(p) && \valid_read(h);
    requires vfinite(h->point);                                 // a hit's point (isect_*)
    requires vfinite(h->normal) && vbounded(h->normal, 4);      // [LANG-VALID-2]: unit normals (isect_*)
    requires vfinite(dir) && vbounded(dir, 4);                  // add_source's L: vec_normalize's or -direction
    requires DOUBLES(\abs(dir.x) >= 0.125 || \abs(dir.y) >= 0.125 || \abs(dir.z) >= 0.125);
    assigns \nothing;
    ensures vfinite(\result.origin) && \is_finite(\result.tmin) && \result.tmin >= 0;
    ensures EXACT(veq(\result.dir, dir)); */
ray ray_spawn_hit_shadow(const scene_prim *p, const hit *h, vec3 dir)
{
    return spawn_by(h->point, h->normal, dir, spawn_offset(h->point, isect_part_magnitude(p, h->part)), 1);
}

int isect_smooth(const scene_prim *p)
{
    return (p->kind == PRIM_MESH && p->u.mesh.tri_normal) || (p->kind == PRIM_TRIANGLE && p->u.triangle.n);
}

/*@ requires \valid_read(p) && \valid_read(h);
    requires vfinite(h->point) && vbounded(h->point, 0x1p1019);  // spawn_to_by's: [LANG-EXTENT-1], a plane's hit open
    requires vfinite(h->normal) && vbounded(h->normal, 4);       // [LANG-VALID-2]: unit normals (isect_*)
    requires vfinite(target) && vbounded(target, 0x1p503);       // [LANG-EXTENT-1]: light_point within 2^503
    assigns \nothing;
    ensures vfinite(\result.origin) && vfinite(\result.dir) && \is_finite(\result.tmax) && \result.tmax >= 0 &&
            \is_finite(\result.tmin) && \result.tmin > 0;
    ensures EXACT(\result.tmax == 0 ==> vzero(\result.dir));
    ensures EXACT(\let s = vdot(target, h->normal) >= vdot(h->point, h->normal) ? \result.tmin : -\result.tmin;
                  \result.origin.x == h->point.x + s * h->normal.x && \result.origin.y == h->point.y + s * h->normal.y &&
                  \result.origin.z == h->point.z + s * h->normal.z); */
ray ray_spawn_hit_to(const scene_prim *p, const hit *h, vec3 target)
{
    return spawn_to_by(h->point, h->normal, target, spawn_offset(h->point, isect_part_magnitude(p, h->part)));
}

/*@ requires \valid_read(p) && \valid_read(h);
    requires vfinite(h->point);                                 // a hit's point (isect_*)
    requires vfinite(h->normal) && vbounded(h->normal, 4);      // [LANG-VALID-2]: unit normals (isect_*)
    assigns \nothing;
    ensures EXACT(veq(\result.point, h->point) && veq(\result.normal, h->normal));
    ensures \is_finite(\result.offset) && \result.offset >= SPAWN_ABS && DOUBLES(\result.offset <= 0x1p983);
    ensures EXACT(vbounded(h->point, 0x1p1022) ==> \result.offset <= 0x1p983); */
shadow_start ray_shadow_start(const scene_prim *p, const hit *h)
{
    return ray_shadow_start_sized(h, isect_part_magnitude(p, h->part));
}

/* ray_shadow_start with m, isect_part_magnitude(p, h->part), given (as
 * ray_spawn_hit_sized). */
/*@ requires \valid_read(h);
    requires vfinite(h->point);                                 // a hit's point (isect_*)
    requires vfinite(h->normal) && vbounded(h->normal, 4);      // [LANG-VALID-2]: unit normals (isect_*)
    requires (\is_finite(m) && m >= 0) || \is_plus_infinity(m); // isect_part_magnitude's
    assigns \nothing;
    ensures EXACT(veq(\result.point, h->point) && veq(\result.normal, h->normal));
    ensures \is_finite(\result.offset) && \result.offset >= SPAWN_ABS && DOUBLES(\result.offset <= 0x1p983);
    ensures EXACT(vbounded(h->point, 0x1p1022) ==> \result.offset <= 0x1p983); */
shadow_start ray_shadow_start_sized(const hit *h, real m)
{
    shadow_start st;
    st.point = h->point;
    st.normal = h->normal;
    st.offset = spawn_offset(h->point, m);
    return st;
}

ray ray_shadow_to(const shadow_start *st, vec3 target)
{
    return spawn_to_by(st->point, st->normal, target, st->offset);
}

vec3 ray_shadow_origin(const shadow_start *st, vec3 toward)
{
    return spawn_origin(st->point, st->normal, toward, st->offset);
}

/*@ requires \valid_read(st);
    requires vfinite(st->point);
    requires vfinite(st->normal) && vbounded(st->normal, 4);
    requires \is_finite(st->offset) && st->offset > 0 && DOUBLES(st->offset <= 0x1p983);  // ray_shadow_start (spawn_offset)
    requires vfinite(dir) && vbounded(dir, 4);  // L of add_source: -direction ([LANG-VALID-2])
    requires DOUBLES(\abs(dir.x) >= 0.125 || \abs(dir.y) >= 0.125 || \abs(dir.z) >= 0.125);
    assigns \nothing;
    ensures vfinite(\result.origin) && \is_finite(\result.tmin) && \result.tmin >= 0;
    ensures EXACT(vbounded(st->point, 0x1p1022) && st->offset <= 0x1p983 ==>
                  is_spawned(\result.origin, st->point, st->normal, dir, st->offset));
    ensures EXACT(veq(\result.dir, dir));
    ensures EXACT(!vzero(dir) ==> \result.tmin * \result.tmin * vnorm2(dir) == st->offset * st->offset); */
ray ray_shadow_along(const shadow_start *st, vec3 dir)
{
    return spawn_by(st->point, st->normal, dir, st->offset, 1);
}

/* ray_shadow_along with length = vec_length(dir) given: a distant light's
 * L is the same at every point, so its length is made once a light
 * (light_setup.along_length), not at every sample (three divisions, a
 * square root and a product before the walk can start).  spawn_by's ray,
 * its tmin shadow_tmin's quotient of that length: the same bits
 * (test_ray_shadow_along_sized_is_ray_shadow_along). */
ray ray_shadow_along_sized(const shadow_start *st, vec3 dir, real length)
{
    ray r = spawn_by(st->point, st->normal, dir, st->offset, 0);
    r.tmin = length > 0 ? st->offset / length : 0;
    return r;
}
