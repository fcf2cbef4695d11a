/*
 * isect_common.h - the pieces the hit tests share (intersect.c,
 * intersect_quadric.c, intersect_torus.c): below all three, so that each
 * includes it and none includes another's.  Internal to the render layer.
 */
#ifndef REFRAY_ISECT_COMMON_H
#define REFRAY_ISECT_COMMON_H

#include "render/ray.h"

/* The roots of |f + t d| = radius, in increasing order; their number (0, 1
 * for a graze, or 2).  Used by the sphere, the cylinder (across its axis)
 * and the torus (its bounding sphere). */
int isect_sphere_roots(vec3 f, vec3 d, real radius, real t[2]);
/* Fills a hit: prim -1, part 0, no barycentrics, shading normal = n,
 * entering = dir . n < 0. */
void isect_hit_set(hit *h, real t, vec3 p, vec3 n, vec3 dir);
/* The box around a disk of radius R across the unit axis (cylinder and
 * cone ends, the torus's ring). */
void isect_disk_extent(vec3 unit_axis, real radius, vec3 *e);

#endif
