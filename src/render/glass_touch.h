/*
 * glass_touch.h - [NUM-GLASS-3] glass touching an opaque surface, taken as
 * the limit of a gap between them (spec/numerics.md 2.8a): the glass a ray
 * spawned from an opaque point meets at its start and the order of tied
 * surfaces (the ray that meets a surface at distance 0 is trace.c's trace_end).
 */
#ifndef REFRAY_GLASS_TOUCH_H
#define REFRAY_GLASS_TOUCH_H

#include "render/trace.h"

/*
 * [NUM-GLASS-3] The transparent surfaces a ray spawned from an opaque point
 * crosses within reach of it (twice the spawn offset) that the ray's own
 * walk does not see: the ray starts off the surface by the offset (a shadow
 * ray past tmin = offset besides), and a glass block standing on the floor
 * has its bottom face at the floor point itself.  In the limit of a gap the
 * ray from the floor crosses that face first: a shadow ray is let through
 * by both of the block's faces (t^2), a mirror ray meets the face.  Opaque
 * surfaces there stay one with the point ([NUM-SPAWN-2]), as does a solid
 * left there (it lies on the other side).  A crossing is taken on the line
 * through the point, within the reach; the walk (from point + offset side)
 * meets the same surface, taken as its tangent plane with normal m turned
 * so that dir.m < 0, at s - offset (side.m)/(dir.m) for the line's
 * parameter s, so that crossing is left to it when that passes its tmin.
 * A closed mesh's winding is not trusted: its crossings count
 * whichever way they go.
 */
typedef struct start_zone {
    const scene_model *scene;
    const hit *self;
    vec3 point, side, dir;   /* the point, its normal on the ray's side, the ray's direction */
    real offset, tmin, reach, back;
    real carried;            /* the product of the t of the crossings */
    hit first;               /* the lowest index among them (prim -1: none) */
} start_zone;

/* Fills z for the ray r spawned from the opaque point h, offset as its
 * spawn was. */
void glass_start_gather(const tracer *t, const hit *h, real offset, const ray *r, start_zone *z, trace_stats *st);

/*
 * The opaque surface a glass point touches, known where a mirror ray from
 * an opaque point met that glass at its start (glass_start_gather): the
 * opaque hit and its normal on the side the mirror ray left it (the
 * zone's side), where the glass lies in the limit of a gap.  Rays the
 * glass point spawns back across that side, its mirror ray and its shadow
 * rays toward a light beyond the opaque surface, meet the surface at
 * distance 0 instead of starting past it.
 */
typedef struct glass_contact {
    const hit *opaque;
    vec3 side;
} glass_contact;

/* Whether a ray along dir from the glass point meets the opaque surface of
 * c at its start: dir goes back across c->side (the opaque surface taken
 * as its tangent plane there). */
int glass_contact_meets(const glass_contact *c, vec3 dir);

/*
 * [NUM-GLASS-3] The surface a ray meets first among those tied with its
 * nearest hit h (bvh.c's window, where the lowest index wins), taken in
 * the limit of a gap between opaque and transparent ones
 * (interface_gap_order): a ray down through a glass block standing on the
 * floor meets the block's bottom face before the floor whichever of the
 * two the file declares first.  Where the tied surfaces are not both opaque
 * and transparent, h stays ([NUM-COPLANAR-1], [NUM-GLASS-1]).  Out of line
 * (HINT_OUT_OF_LINE): the interface is not needed once the winner is known
 * ([REL-STACK-1]).
 */
void glass_first_of_tie(const tracer *t, const ray *r, hit *h, const medium_stack *media, trace_stats *st);

#endif
