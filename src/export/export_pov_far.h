/*
 * export_pov_far.h - where POV-Ray's fixed distances meet a scene
 * (spec/crosscheck.md, [XCHK-MAP-FAR-1], [XCHK-MAP-DISTANT-1]).
 *
 * POV-Ray 3.7 ignores every intersection farther than MAX_DISTANCE = 1e7
 * scene units along a ray (camera, secondary and shadow rays alike:
 * every shape's test drops it), and tests a parallel light's shadow rays
 * only up to the plane through the light's location.  refray has neither
 * limit.  Bounded primitives keep every distance small; planes do not.
 * These functions bound the distances a scene can produce, so the export
 * can put a distant light beyond all of them and list the places where
 * MAX_DISTANCE can cut.
 */
#ifndef REFRAY_EXPORT_POV_FAR_H
#define REFRAY_EXPORT_POV_FAR_H

#include "scene/scene.h"

/* POV-Ray's MAX_DISTANCE (source/backend/configbackend.h). */
#define POV_MAX_DISTANCE 1e7

/* The size POV-Ray must render: k times the scene's image for a k x k
 * pixel grid (whose sub-pixel centres are then POV-Ray's pixel centres).
 * Returns k. */
int pov_render_size(const scene_model *s, int *width, int *height);

/* Centre and radius of a ball holding every camera ray's origin, the
 * positional lights and every bounded primitive (planes are left out). */
typedef struct pov_bounds {
    vec3 centre;
    double radius;        /* >= 1 */
} pov_bounds;

pov_bounds pov_far_bounds(const scene_model *s);

/* The distance from any camera ray's origin across the ball: a ray that
 * leaves a point d from the origin meets a bounded primitive or a light
 * within d + pov_far_spread. */
double pov_far_spread(const scene_model *s, const pov_bounds *b);

/* How far behind the scene's centre a distant light goes: beyond every
 * point POV-Ray can shade by MAX_DISTANCE (each of at most max_trace_level
 * segments of a ray path is shorter than MAX_DISTANCE), so that only
 * MAX_DISTANCE itself, as for every other ray, limits its shadow rays. */
double pov_far_distant_distance(const scene_model *s, const pov_bounds *b, int trace_levels);

/* The farthest distance at which a camera ray (through the centre of a
 * pixel of POV-Ray's render, pov_render_size) meets plane p, whatever lies
 * in front; 0 when none does. */
double pov_far_camera_reach(const scene_model *s, const scene_prim *p);

/* An upper bound of the distance at which a shadow ray toward distant
 * light l meets plane w, from a point of a bounded primitive or a point of
 * another plane met by a camera ray (ignoring what lies in front); 0 when
 * none can. */
double pov_far_shadow_reach(const scene_model *s, const pov_bounds *b, const scene_light *l, const scene_prim *w);

/* POV-Ray's SHADOW_TOLERANCE (backend/render/trace.cpp): a shadow-ray
 * crossing this close to the shaded point, to the light, or to the
 * transparent crossing before it is not counted. */
#define POV_SHADOW_TOLERANCE 1e-3

/* The first primitive other than solid (an index into s->prims; an opaque
 * one when opaque_only) whose surface may come within gap of solid's
 * (they cut or touch), or -1.  For an untransformed sphere exact against
 * planes and untransformed spheres; otherwise bounding boxes stand in (a
 * plane for solid: every plane not parallel to it), so it errs toward
 * finding one. */
int pov_far_near_solid(const scene_model *s, int solid, double gap, int opaque_only);

#endif
