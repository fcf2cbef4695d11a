/*
 * glass_near.h - [NUM-GLASS-3] which points may touch glass: the
 * transparent primitives' boxes, padded, kept in the tracer (glass_box,
 * glass_prim, glass_boxes).  A point farther than the reach from all of
 * them has no transparent surface within reach, so its shadow and mirror
 * rays need no glass_start_gather (glass_touch.h).
 */
#ifndef REFRAY_GLASS_NEAR_H
#define REFRAY_GLASS_NEAR_H

#include "render/trace.h"

/* Fills t's boxes from the scene's transparent primitives, from the
 * scene's allocator; t->glass_boxes -1 (every point gathers) past
 * GLASS_BOX_MAX of them or with an unbounded one (a plane).  Returns 0
 * when out of memory (glass_near_free frees what was made). */
int glass_near_build(tracer *t, const scene_model *s);
void glass_near_free(tracer *t);

/* The box of p padded by 2^-20 of its size (*size, the largest of its
 * corners' and sides' magnitudes): a hit point of p lies within a few ulps
 * of its box.  0, nothing set past lo and hi, for an unbounded p (a plane). */
int glass_near_padded_box(const scene_prim *p, vec3 *lo, vec3 *hi, real *size);

/* Whether the surface of sphere p (in the world frame) may pass within
 * reach (each coordinate) of point: 1 whenever it is not known not to. */
int glass_near_sphere(const scene_prim *p, vec3 point, real reach);

/* Whether a transparent surface may lie within reach of point (each
 * coordinate): 1 whenever it is not known to lie farther. */
int glass_near(const tracer *t, vec3 point, real reach);

#endif
