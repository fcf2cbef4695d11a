/*
 * ray_copy.h - copies of a ray and of a hit field by field, for the hot
 * paths of the tracer and the tree's walk.  A whole-struct copy reads
 * 16-byte blocks: where the struct was just written by narrower stores
 * (a vec3 as 16 + 8 bytes, as ray_spawn_hit_sized, camera_ray and these
 * copies write a ray; a hit's ints 4 bytes each), a block straddles two
 * stores and the store buffer cannot forward it, a stall of some ten
 * cycles (spec/performance.md, "Eighteenth round: stalls, glass and
 * grids").  Field by field the loads match those stores.  The same values.
 * Not included by the proved units: no contracts here.
 */
#ifndef REFRAY_RAY_COPY_H
#define REFRAY_RAY_COPY_H

#include "render/ray.h"

static inline void ray_copy(ray *to, const ray *r)
{
    to->origin = r->origin;
    to->dir = r->dir;
    to->tmin = r->tmin;
    to->tmax = r->tmax;
}

static inline void hit_copy(hit *to, const hit *h)
{
    to->t = h->t;
    to->point = h->point;
    to->normal = h->normal;
    to->shading_normal = h->shading_normal;
    to->prim = h->prim;
    to->part = h->part;
    to->entering = h->entering;
    to->b1 = h->b1;
    to->b2 = h->b2;
}

#endif
