/*
 * oracle_surface.c - a lower bound of the distance from a point to a
 * primitive's surface ([ORACLE-VIEW-ROUNDING-3], spec/verify.md, where each
 * kind's derivation is written out).
 *
 * Disks, cylinders, cones and tori are surfaces of revolution about an
 * axis: a point at height h on the axis and rho off it, and a surface
 * point at (h', rho') turned by phi about the axis from it, lie
 *   (h - h')^2 + rho^2 + rho'^2 - 2 rho rho' cos(phi) >= (h - h')^2 + (rho - rho')^2
 * apart squared, with equality at phi = 0: the distance in space is the
 * distance in the half-plane (h, rho) to the shape's profile, a few
 * segments or a circle there.
 */
#include <float.h>
#include <math.h>
#include "oracle/oracle_surface.h"

/* What the arithmetic below may get wrong, in units of DBL_EPSILON / 2 of
 * the sizes involved (the point's and the shape's largest |coordinate|):
 * each route is a dozen operations on coordinates of those sizes, each
 * rounding by one unit of at most twice them; 256 leaves a factor of
 * about ten. */
#define SURFACE_ROUNDING 256

/* A triangle whose normal (the cross product of two edges) is at most
 * 2^-20 of its longest edge squared is taken as its edges: a sliver. The
 * cross product's components round by at most 2 u |e1| |e2| each, so the
 * normal of the others turns by at most 4 u longest^2 / |n| <= 2^-31
 * (taken as 16 u longest^2 / |n|), and the plane's distance moves by that
 * times q's distance from a corner. */
#define SLIVER 0x1p-20
#define NORMAL_TURN 16

static double max_abs(vec3 v)
{
    return fmax(fabs((double)v.x), fmax(fabs((double)v.y), fabs((double)v.z)));
}

double oracle_segment_distance(vec3 q, vec3 a, vec3 b)
{
    vec3 e = vec_sub(b, a), w = vec_sub(q, a);
    double ee = vec_dot(e, e), t = ee > 0 ? vec_dot(w, e) / ee : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return vec_length(vec_sub(w, vec_scale(e, t)));
}

static double edges_distance(vec3 q, vec3 a, vec3 b, vec3 c)
{
    return fmin(oracle_segment_distance(q, a, b),
                fmin(oracle_segment_distance(q, b, c), oracle_segment_distance(q, c, a)));
}

/* The projection of q falls inside the triangle when q sees each edge
 * turn the way the normal does; there the plane's distance is the
 * distance, no larger than the edges' (so the smaller of the two errs only
 * low when rounding calls an outside point inside); outside, the nearest
 * point lies on an edge.  A sliver (or a segment) is taken as its edges
 * less its height over the longest: every point of it lies that near an
 * edge. */
double oracle_triangle_distance(vec3 q, vec3 a, vec3 b, vec3 c)
{
    vec3 ab = vec_sub(b, a), bc = vec_sub(c, b), ca = vec_sub(a, c), n = vec_cross(ab, vec_neg(ca));
    double edges = edges_distance(q, a, b, c), nl = vec_length(n);
    double longest = fmax(vec_length(ab), fmax(vec_length(bc), vec_length(ca)));
    if (!(nl > SLIVER * longest * longest))
        return fmax(0, edges - (longest > 0 ? nl / longest : 0));
    int inside = vec_dot(n, vec_cross(ab, vec_sub(q, a))) >= 0 && vec_dot(n, vec_cross(bc, vec_sub(q, b))) >= 0 &&
                 vec_dot(n, vec_cross(ca, vec_sub(q, c))) >= 0;
    if (!inside)
        return edges;
    double plane = fabs(vec_dot(n, vec_sub(q, a))) / nl;
    double turn = NORMAL_TURN * (DBL_EPSILON / 2) * longest * longest / nl;
    return fmin(edges, plane - turn * vec_length(vec_sub(q, a)));
}

/* (h, rho) of q about the axis through o along the unit a. */
static vec3 meridian(vec3 q, vec3 o, vec3 a)
{
    vec3 w = vec_sub(q, o);
    return vec_make(vec_dot(w, a), vec_length(vec_cross(w, a)), 0);
}

/* A cylinder or a cone: its side from (0, r0) to (H, r1) and, closed, its
 * two caps down to the axis. */
static double tube_distance(vec3 q, vec3 from, vec3 to, double r0, double r1, int open)
{
    vec3 axis = vec_sub(to, from);
    double h = vec_length(axis);
    vec3 m = meridian(q, from, vec_scale(axis, 1 / h));
    vec3 s0 = vec_make(0, r0, 0), s1 = vec_make(h, r1, 0);
    double d = oracle_segment_distance(m, s0, s1);
    if (!open)
        d = fmin(d, fmin(oracle_segment_distance(m, vec_splat(0), s0),
                         oracle_segment_distance(m, vec_make(h, 0, 0), s1)));
    return d;
}

static double box_outside(vec3 q, vec3 lo, vec3 hi)
{
    return vec_length(vec_max(vec_max(vec_sub(lo, q), vec_sub(q, hi)), vec_splat(0)));
}

double oracle_box_distance(vec3 q, vec3 lo, vec3 hi)
{
    double outside = box_outside(q, lo, hi);
    return outside > 0 ? outside : -vec_max_component(vec_max(vec_sub(lo, q), vec_sub(q, hi)));
}

static double mesh_distance(const scene_trimesh *m, vec3 q)
{
    double d = HUGE_VAL;
    for (int i = 0; i < m->tri_count; i++) {
        const int *t = m->tri[i];
        d = fmin(d, oracle_triangle_distance(q, m->positions[t[0]], m->positions[t[1]], m->positions[t[2]]));
    }
    return d;
}

/* The distance from q to p's surface in p's own coordinates, rounded. */
static double own_distance(const scene_prim *p, vec3 q)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        return fabs(vec_length(vec_sub(q, p->u.sphere.center)) - p->u.sphere.radius);
    case PRIM_PLANE: {
        vec3 n = p->u.plane.normal;
        return fabs(vec_dot(n, vec_sub(q, p->u.plane.point))) / vec_length(n);
    }
    case PRIM_TRIANGLE:
        return oracle_triangle_distance(q, p->u.triangle.p[0], p->u.triangle.p[1], p->u.triangle.p[2]);
    case PRIM_DISK: {
        vec3 m = meridian(q, p->u.disk.center, vec_normalize(p->u.disk.normal));
        return oracle_segment_distance(m, vec_splat(0), vec_make(0, p->u.disk.radius, 0));
    }
    case PRIM_BOX:
        return oracle_box_distance(q, p->u.box.lo, p->u.box.hi);
    case PRIM_CYLINDER:
        return tube_distance(q, p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.radius,
                             p->u.cylinder.open);
    case PRIM_CONE:
        return tube_distance(q, p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1],
                             p->u.cone.open);
    case PRIM_TORUS: {
        vec3 m = meridian(q, p->u.torus.center, p->u.torus.axis);
        return fabs(hypot(m.x, m.y - p->u.torus.major) - p->u.torus.minor);
    }
    case PRIM_MESH:
        return mesh_distance(&p->u.mesh, q);
    default:
        return HUGE_VAL;
    }
}

/* sqrt of Gershgorin's bound of the largest eigenvalue of M M^T (which
 * has M^T M's), M the linear part of x: at least M's largest singular
 * value, the most it stretches a length; exact for a turn, an axis scale,
 * and the inverse of a turn after an axis scale (M M^T diagonal). */
static double stretch_bound(const xform *x)
{
    double most = 0;
    for (int i = 0; i < 3; i++) {
        double row = 0;
        for (int j = 0; j < 3; j++) {
            double g = 0;
            for (int k = 0; k < 3; k++)
                g += x->m[i][k] * x->m[j][k];
            row += fabs(g);
        }
        most = fmax(most, row);
    }
    return sqrt(most) * (1 + 0x1p-40);
}

double oracle_surface_distance(const scene_prim *p, vec3 q)
{
    vec3 lo, hi;
    double unit = SURFACE_ROUNDING * DBL_EPSILON / 2;
    if (p->kind == PRIM_PLANE)
        return fmax(0, own_distance(p, q) - unit * (max_abs(q) + max_abs(p->u.plane.point)));
    if (!scene_prim_world_box(p, &lo, &hi))
        return HUGE_VAL;
    double scale = max_abs(q) + fmax(max_abs(lo), max_abs(hi));
    if (!p->frame)
        return fmax(0, own_distance(p, q) - unit * scale);
    /* A frame maps local lengths to world ones no shorter than 1 / |to_local|
     * times, and its local point is rounded relative to |to_local| |to_world|
     * times its size ([NUM-FRAME-1]); outside the world box, the box's
     * distance bounds the surface's too. */
    vec3 ql = scene_frame_local(p->frame, q), llo, lhi;
    scene_prim_local_box(p, &llo, &lhi);
    double shrink = stretch_bound(&p->frame->to_local);
    double lunit = unit * shrink * stretch_bound(&p->frame->to_world);
    double local = (own_distance(p, ql) - lunit * (max_abs(ql) + fmax(max_abs(llo), max_abs(lhi)))) / shrink;
    return fmax(0, fmax(local, box_outside(q, lo, hi) - unit * scale));
}

/* Local radii: a cylinder's and a cone's circles (a cone's meridian is
 * straight, its other principal radius rho / cos(half angle) >= rho); a
 * torus's tube, and its parallels, |major / cos v + minor| >= major - minor.
 * A frame A bends a unit-speed curve of curvature k into one of curvature
 * |Ag' x Ag''| / |Ag'|^3 <= s_max^2 k / s_min^3, and every principal radius
 * is a normal section's. */
double oracle_curvature_radius(const scene_prim *p)
{
    double r;
    switch (p->kind) {
    case PRIM_SPHERE:
        r = p->u.sphere.radius;
        break;
    case PRIM_CYLINDER:
        r = p->u.cylinder.radius;
        break;
    case PRIM_CONE:
        r = fmin(p->u.cone.radius[0], p->u.cone.radius[1]);
        break;
    case PRIM_TORUS:
        r = fmin(p->u.torus.minor, p->u.torus.major - p->u.torus.minor);
        break;
    default:
        return HUGE_VAL;
    }
    if (p->frame) {
        double s_min = 1 / stretch_bound(&p->frame->to_local), s_max = stretch_bound(&p->frame->to_world);
        r *= s_min * s_min * s_min / (s_max * s_max);
    }
    return fmax(0, r * (1 - 0x1p-40));
}
