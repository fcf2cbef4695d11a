/*
 * gather_alone.c - [SHADE-SHORTCUT-GATHER-2] the transparent primitives'
 * neighbours and the test whether a hit is alone (gather_alone.h; the
 * argument is in spec/shading.md).
 */
#include <math.h>
#include "base/inline_hint.h"
#include "render/gather_alone.h"
#include "render/glass_near.h"
#include "render/intersect.h"

/* GATHER_BUILD_WORK bounds the build's box constructions, transparent
 * primitives times all primitives: without it 64 glass balls among 300 000
 * others cost 1.5 s before the first pixel (attack 18, finding 2); past it
 * the gather walks the tree as with the shortcut off, the same crossings. */
enum { GATHER_ALONE_MAX = 64, GATHER_NEAR_MAX = 8, GATHER_BUILD_WORK = 1 << 18 };

/* glass_near's padded box, finite: a plane or an infinite size is no box. */
static int padded_box(const scene_prim *p, vec3 *lo, vec3 *hi, real *size)
{
    return glass_near_padded_box(p, lo, hi, size) && *size < INFINITY;
}

/* Whether every point of the box [lo, hi] (size its magnitude) is farther
 * than 2 reach from the plane n . (x - p0) = 0, with room for the plane's
 * hit points, projected onto it to the rounding of their coordinates. */
HINT_IN_LINE static inline int off_plane(vec3 n, vec3 p0, vec3 lo, vec3 hi, real size, real reach)
{
    vec3 c = vec_scale(vec_add(lo, hi), 0.5), e = vec_scale(vec_sub(hi, lo), 0.5);
    real n1 = vec_sum_abs(n);
    real half = fabs(n.x) * e.x + fabs(n.y) * e.y + fabs(n.z) * e.z;
    real pad = n1 * (2 * reach + 0x1p-20 * (vec_max_abs(p0) + size + reach));
    return fabs(vec_dot(n, vec_sub(c, p0))) - half > 2 * pad;
}

/* Whether the box [lo, hi] is farther than 2 reach from [olo, ohi] on some
 * axis. */
static int boxes_apart(vec3 lo, vec3 hi, vec3 olo, vec3 ohi, real reach)
{
    return olo.x - hi.x > 2 * reach || lo.x - ohi.x > 2 * reach || olo.y - hi.y > 2 * reach ||
           lo.y - ohi.y > 2 * reach || olo.z - hi.z > 2 * reach || lo.z - ohi.z > 2 * reach;
}

/* [SHADE-SHORTCUT-GATHER-3] Whether every point within 2^-20 of its size
 * of sphere p's surface (every hit point on it) lies more than 4 reach
 * (reach: the largest of a hit on p) from every point within 2^-20 of its
 * size of sphere o's surface (every crossing of o): the two shells nested
 * or apart, their gap D - R - r, R - D - r or r - D - R (D the distance of
 * the centres) larger than twice both pads and 4 reach; 2^-30 of their
 * magnitudes covers this test's own roundings.  Both in the world frame;
 * a NaN says no. */
static int spheres_apart(const scene_prim *p, const scene_prim *o, real reach)
{
    if (p->kind != PRIM_SPHERE || p->frame || o->kind != PRIM_SPHERE || o->frame)
        return 0;
    vec3 c = p->u.sphere.center, oc = o->u.sphere.center;
    real big = p->u.sphere.radius, small = o->u.sphere.radius, d = vec_length(vec_sub(c, oc));
    real pads = 0x1p-20 * (vec_max_abs(c) + big) + 0x1p-20 * (vec_max_abs(oc) + small) + 2 * reach;
    real slack = 2 * pads + 0x1p-30 * (vec_max_abs(c) + vec_max_abs(oc) + big + small + d);
    return d - big - small > slack || big - d - small > slack || small - d - big > slack;
}

/* Prim i's neighbours into near[0..GATHER_NEAR_MAX): the others not apart
 * from its padded box by twice the largest reach of a hit on it.  Returns
 * their count, or -1 when i is not eligible (a mesh, unbounded, a framed
 * plane near it, too many neighbours). */
static int neighbours(const scene_model *s, int i, gather_near *near)
{
    const scene_prim *p = &s->prims[i];
    vec3 lo, hi;
    real size;
    if (isect_part_count(p) != 1 || !padded_box(p, &lo, &hi, &size))
        return -1;
    real m = isect_part_magnitude(p, 0);
    m = m > size ? m : size;
    real reach = 2 * (SPAWN_REL * m + SPAWN_ABS) * (1 + 0x1p-20);
    if (!(reach < INFINITY))
        return -1;
    int n = 0;
    for (int j = 0; j < s->prim_count; j++) {
        const scene_prim *o = &s->prims[j];
        gather_near g = {{0, 0, 0}, {0, 0, 0}, 0, j};
        real osize;
        if (j == i || spheres_apart(p, o, reach))
            continue;
        if (padded_box(o, &g.lo, &g.hi, &osize)) {
            if (boxes_apart(lo, hi, g.lo, g.hi, reach))
                continue;
        } else if (o->kind == PRIM_PLANE && !o->frame) {
            if (off_plane(o->u.plane.normal, o->u.plane.point, lo, hi, size, reach))
                continue;
            g.lo = o->u.plane.normal;
            g.hi = o->u.plane.point;
            g.plane = 1;
        } else
            return -1;
        if (n == GATHER_NEAR_MAX)
            return -1;
        near[n++] = g;
    }
    return n;
}

int gather_alone_build(tracer *t, const scene_model *s)
{
    int glass = 0, kept = 0;
    gather_near near[GATHER_NEAR_MAX];
    for (int i = 0; i < s->prim_count; i++)
        glass += s->materials[s->prims[i].material].t > 0;
    if (glass == 0 || glass > GATHER_ALONE_MAX || (long)glass * s->prim_count > GATHER_BUILD_WORK)
        return 1;
    t->gather_span = mem_calloc(&s->mem, 2 * (size_t)s->prim_count, sizeof *t->gather_span);
    t->gather_near = mem_calloc(&s->mem, (size_t)glass * GATHER_NEAR_MAX, sizeof *t->gather_near);
    t->gather_alloc = glass * GATHER_NEAR_MAX;
    if (!t->gather_span || !t->gather_near)
        return 0;
    for (int i = 0; i < s->prim_count; i++) {
        int n = s->materials[s->prims[i].material].t > 0 ? neighbours(s, i, near) : -1;
        t->gather_span[2 * i] = kept;
        t->gather_span[2 * i + 1] = n;
        for (int k = 0; k < n; k++)
            t->gather_near[kept++] = near[k];
    }
    return 1;
}

void gather_alone_free(tracer *t)
{
    const scene_model *s = t->scene;
    mem_free(&s->mem, t->gather_span, t->gather_span ? 2 * (size_t)s->prim_count * sizeof *t->gather_span : 0);
    mem_free(&s->mem, t->gather_near, (size_t)t->gather_alloc * sizeof *t->gather_near);
    t->gather_span = NULL;
    t->gather_near = NULL;
    t->gather_alloc = 0;
}

/* The guard on the lists' premise: a crossing left at o + t d (a graze
 * sphere_refine cannot refine, a box's slab point) lies off its surface by
 * the rounding of o + t d, up to E = 2^-40 (|o| + |t| |d| + F) (F the
 * frames' spread); the pads cover E when |o| + |t_h| |d| + F is at most
 * 2^16 of the hit point's magnitude (spec/shading.md has the argument),
 * which 2 |o| + F <= 2^15 |p_h| ensures: |t_h d| is |p_h - o| to 2^-20 of
 * itself.  A ray from farther (or a hit at 0) is not known alone; a NaN
 * says no. */
static int origin_near(const tracer *t, const ray *r, vec3 at)
{
    return 2 * vec_max_abs(r->origin) + t->frame_shift <= 0x1p15 * vec_max_abs(at);
}

int gather_alone(const tracer *t, const hit *h, const ray *r, real reach)
{
    vec3 at = h->point;
    if (!t->gather_span || t->no_shortcuts || t->gather_span[2 * h->prim + 1] < 0 || !origin_near(t, r, at))
        return 0;
    const gather_near *g = t->gather_near + t->gather_span[2 * h->prim];
    for (int k = 0; k < t->gather_span[2 * h->prim + 1]; k++) {
        const scene_prim *o = &t->scene->prims[g[k].prim];
        if (g[k].plane ? !off_plane(g[k].lo, g[k].hi, at, at, vec_max_abs(at), reach)
                       : !boxes_apart(at, at, g[k].lo, g[k].hi, reach) &&
                             (o->kind != PRIM_SPHERE || o->frame || glass_near_sphere(o, at, reach)))
            return 0;
    }
    return 1;
}

/*
 * A hit on a sphere in the world frame whose ray is far from tangent: its
 * other crossing (the one of the other side, which alone the gather would
 * keep) lies more than reach from it.  Both points lie within
 * 2^-20 (|c| + R) of the sphere (glass_near's premise) and within
 * 2^-20 (|t| |d| + |o|) of the ray ([SHADE-SHORTCUT-GATHER-1]; the other
 * one's t is below tmax = t_h + reach + 2^-40 |t_h|), both below R / 1024
 * here.  Along the ray (unit u, s from the foot of the centre), d.n >=
 * |d| |n| / 4 puts the hit at |s_h| >= 0.245 R, and the chord then at
 * |s| >= 0.24 R for any point that near the sphere; a crossing's side is
 * the sign of d.n at its point, that of its s, so the other crossing is at
 * s of the other sign: at least 0.48 R away, 0.27 R in the max norm, more
 * than reach for R > 8 reach.
 */
int gather_self_apart(const tracer *t, const hit *h, const ray *r, real reach)
{
    const scene_prim *p = &t->scene->prims[h->prim];
    if (t->no_shortcuts || p->kind != PRIM_SPHERE || p->frame)
        return 0;
    vec3 c = p->u.sphere.center, n = vec_sub(h->point, c);
    real radius = p->u.sphere.radius, dm = vec_max_abs(r->dir);
    real size = vec_max_abs(c) + radius + (fabs(h->t) + reach) * dm + vec_max_abs(r->origin);
    /* d.n >= |d| |n| / 4 on d and n scaled to a largest component of 1:
     * squares of 1 to 3, neither overflow nor underflow (a NaN says no). */
    vec3 u = vec_scale(r->dir, 1 / dm), v = vec_scale(n, 1 / vec_max_abs(n));
    real dn = vec_dot(u, v);
    return radius > 8 * (reach + 0x1p-12 * size) && 16 * dn * dn >= vec_length2(u) * vec_length2(v);
}
