/*
 * oracle_surface.h - how near a point comes to a primitive's surface, as
 * [ORACLE-VIEW-ROUNDING-3] (spec/verify.md) needs it: the shortest way a
 * shadow ray from any hit on the primitive can travel to a point light.
 * A primitive's world box is no such bound from inside it (a light just
 * off a sphere's surface, inside its box, is a box's face farther from
 * the box than from the sphere), so the distance is taken to the surface.
 *
 * Written from plain geometry, never from the tracer's hit tests.  Every
 * answer is a lower bound: exact in real arithmetic for every kind but a
 * shape that keeps a frame, then lessened by a bound of its own rounding;
 * never larger than the true distance, which keeps the tolerance on the
 * safe side (a smaller distance gives a larger term, which the cap of
 * [ORACLE-VIEW-ROUNDING-2] holds).
 */
#ifndef REFRAY_ORACLE_SURFACE_H
#define REFRAY_ORACLE_SURFACE_H

#include "scene/scene.h"

/* The distance from q to segment [a, b] (a == b: to the point). */
double oracle_segment_distance(vec3 q, vec3 a, vec3 b);

/* The distance from q to the triangle (a, b, c), a sliver or a segment
 * included, in real arithmetic up to the rounding of its normal. */
double oracle_triangle_distance(vec3 q, vec3 a, vec3 b, vec3 c);

/* The distance from q to the surface of the box [lo, hi]: outside, to the
 * box; inside, to its nearest face (for a primitive in the box, a proxy:
 * view_reach's for an eye inside the boxes, oracle_util.c). */
double oracle_box_distance(vec3 q, vec3 lo, vec3 hi);

/* A lower bound of the distance from q to the surface of p in the world
 * (for a plane, to the plane; for a closed mesh, to its triangles); 0 on
 * or within rounding of it; HUGE_VAL for a primitive with nothing to
 * meet (an empty mesh). */
double oracle_surface_distance(const scene_prim *p, vec3 q);

/* A lower bound of the smallest radius of curvature of p's surface in the
 * world ([ORACLE-VIEW-ROUNDING-4]): a sphere's, a cylinder's or a cone's
 * radius (0 at a cone's apex), a torus's min(minor, major - minor), a
 * frame's local radius times s_min^3 / s_max^2; HUGE_VAL for a flat
 * primitive (plane, disk, box, triangle, mesh: their creases are edges,
 * which the families' edge margins handle). */
double oracle_curvature_radius(const scene_prim *p);

#endif
