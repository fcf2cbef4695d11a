/*
 * interface.h - one interface: the surface a ray hit and every other surface
 * it crosses within the spawn offset of it.  Two glass boxes sharing a face
 * are two coincident surfaces; the transmitted ray is spawned past both at
 * once, so leaving one and entering the other must be one boundary
 * n1 -> n2, not n1 -> air -> n2 with the second crossing never seen
 * (spec/numerics.md, "Coincident surfaces").  An opaque surface among them
 * is where the transmitted ray ends ([NUM-GLASS-3]).
 */
#ifndef REFRAY_INTERFACE_H
#define REFRAY_INTERFACE_H

#include "render/trace.h"

enum { INTERFACE_MAX = 8 };
typedef struct interface {
    const scene_model *scene;
    const hit *self;     /* the hit being shaded: h[0] */
    real reach;          /* a crossing whose point is this close belongs to it */
    int count;
    hit h[INTERFACE_MAX];
    /* The product of the t of every crossing besides the hit, in the walk's
     * order, those past INTERFACE_MAX included: a ninth coincident surface
     * that is opaque still stops the ray.  The solids among those not kept
     * are counted: the medium stack cannot follow them. */
    real through;
    int solids_lost;
    const scene_prim *spawn_prim; /* the crossing of largest magnitude: spawn from it */
    const hit *spawn_hit;
    real spawn_magnitude;         /* isect_part_magnitude of spawn_hit's part */
} interface;

/* Fills f with the hit h on prim and the crossings of the incoming ray in
 * within reach: twice the spawn offset, the distance a spawned ray jumps.
 * magnitude: isect_part_magnitude(prim, h->part), which the caller has. */
void interface_gather(const tracer *t, const scene_prim *prim, const hit *h, real magnitude, const ray *in,
                      interface *f, trace_stats *st);

/* Crossing the interface: every solid left comes off the stack (next, a
 * copy of before), then every solid entered goes on (once).  Returns the
 * number of solid crossings (the product of the t of the crossings besides
 * the hit is f->through). */
int interface_cross(const tracer *t, const interface *f, const medium_stack *before, medium_stack *next,
                    trace_stats *st);

/*
 * [NUM-GLASS-3] Where crossing k lies against an opaque surface it
 * coincides with, in the limit of a gap between them: 0 before it (a
 * transparent solid left: its inside is on the side the ray comes from;
 * a transparent sheet, taken on that side), 1 the opaque one, 2 past it (a
 * transparent solid entered).
 */
int interface_gap_order(const scene_model *sc, const interface *f, const medium_stack *before, int k);

/*
 * [NUM-GLASS-3] An opaque surface in the interface is where the transmitted
 * ray ends, not a filter of t = 0: the ray leaves what lies before it and
 * meets it at distance 0.  Finds the opaque crossing (the lowest index if
 * several), copies it to *end and keeps in f the crossings before it (the
 * hit itself always), f->through the product of their t.  Returns 0, f
 * unchanged, when f holds no opaque crossing or lost some crossings past
 * INTERFACE_MAX (then [NUM-GLASS-1]'s product stands).
 */
int interface_end(const tracer *t, interface *f, const medium_stack *before, hit *end);

/* Whether hit a comes before b in the tie-break of coplanar surfaces: the
 * lower primitive index, then the lower part (bvh.c's order). */
int interface_hit_before(const hit *a, const hit *b);

/* The transparency of the surface h is on. */
real interface_hit_t(const scene_model *sc, const hit *h);

#endif
