/*
 * intersect_shapes.h - the hit tests of the cylinder, cone and torus
 * (intersect_quadric.c, intersect_torus.c), and the two pieces of
 * intersect.c they share.  Internal to the render layer: the entry points
 * are isect_prim, isect_prim_all and the isect_* of intersect.h.
 *
 * Each SHAPE_hits writes up to max accepted hits (t in (tmin, tmax)) in
 * increasing t and returns how many, with the contract of intersect.h.
 */
#ifndef REFRAY_INTERSECT_SHAPES_H
#define REFRAY_INTERSECT_SHAPES_H

#include "render/ray.h"

/* intersect.c: the roots of |f + t d| = radius (sphere_roots), in
 * increasing order; their number (0, 1 for a graze, or 2). */
int isect_sphere_roots(vec3 f, vec3 d, real radius, real t[2]);
/* intersect.c: fills a hit (prim -1, shading normal = n, entering = d.n < 0). */
void isect_hit_set(hit *h, real t, vec3 p, vec3 n, vec3 dir);

/* intersect_quadric.c: a cylinder from `from` to `to` of radius r, a cone
 * with radius r0 at from and r1 at to; open: no end caps (a sheet). */
int isect_cylinder_hits(vec3 from, vec3 to, real radius, int open, const ray *r, hit *out, int max);
int isect_cone_hits(vec3 from, vec3 to, real r0, real r1, int open, const ray *r, hit *out, int max);

/* intersect_torus.c: up to 4 crossings. */
int isect_torus_hits(vec3 center, vec3 axis, real major, real minor, const ray *r, hit *out, int max);

/* Local bounds: the box around the two end disks (cylinder and cone), or
 * around the ring (torus). */
void isect_disk_extent(vec3 unit_axis, real radius, vec3 *e);
void isect_torus_extent(vec3 unit_axis, real major, real minor, vec3 *e);

#endif
