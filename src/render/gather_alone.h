/*
 * gather_alone.h - [SHADE-SHORTCUT-GATHER-2] whether a hit on a transparent
 * primitive has no other primitive within the interface's reach, so that
 * interface_gather tests the primitive itself instead of walking the BVH.
 * Each transparent primitive keeps the few others that come near its box
 * (gather_near); a hit is alone when its point is far from all of them.
 */
#ifndef REFRAY_GATHER_ALONE_H
#define REFRAY_GATHER_ALONE_H

#include "render/trace.h"

/* One primitive near another: its padded box (a sphere in the world
 * frame: its distance from the centre besides), or a plane in the world
 * frame (normal in lo, point in hi). */
typedef struct gather_near {
    vec3 lo, hi;
    int plane;
    int prim;
} gather_near;

/* Fills t's neighbour lists (t->gather_span, t->gather_near, from the
 * scene's allocator) for up to GATHER_ALONE_MAX transparent primitives.
 * Returns 0 when out of memory (gather_alone_free frees what was made). */
int gather_alone_build(tracer *t, const scene_model *s);
void gather_alone_free(tracer *t);

/* Whether no other primitive has a crossing within reach (each coordinate)
 * of h's point, h found by the ray r: 0 whenever that is not known (a ray
 * from far away: the lists' premise needs its crossings near their
 * surfaces), and with the shortcuts off. */
int gather_alone(const tracer *t, const hit *h, const ray *r, real reach);

/* Whether the crossings of h's own part that interface_gather would keep
 * besides h (those of the other side) are surely out of reach: a sphere
 * in the world frame crossed far from tangent.  0 with the shortcuts off. */
int gather_self_apart(const tracer *t, const hit *h, const ray *r, real reach);

#endif
