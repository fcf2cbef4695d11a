/*
 * intersect_shapes.h - the hit tests of the cylinder, cone and torus
 * (intersect_quadric.c, intersect_torus.c), which intersect.c calls; what
 * all of them share is below, in isect_common.h.  Internal to the render
 * layer: the entry points are isect_prim, isect_prim_all and the isect_* of
 * intersect.h.
 *
 * Each SHAPE_hits writes up to max accepted hits (t in (tmin, tmax)) in
 * increasing t and returns how many, with the contract of intersect.h.
 */
#ifndef REFRAY_INTERSECT_SHAPES_H
#define REFRAY_INTERSECT_SHAPES_H

#include "render/ray.h"

/* intersect_quadric.c: a cylinder from `from` to `to` of radius r, a cone
 * with radius r0 at from and r1 at to; open: no end caps (a sheet). */
int isect_cylinder_hits(vec3 from, vec3 to, real radius, int open, const ray *r, hit *out, int max);
int isect_cone_hits(vec3 from, vec3 to, real r0, real r1, int open, const ray *r, hit *out, int max);

/* intersect_torus.c: up to 4 crossings. */
int isect_torus_hits(vec3 center, vec3 axis, real major, real minor, const ray *r, hit *out, int max);

/* Local bounds: the box around the ring (torus). */
void isect_torus_extent(vec3 unit_axis, real major, real minor, vec3 *e);

#endif
