/*
 * ray.h - a ray with its parametric interval, and what a hit reports.
 * An intersect routine accepts a hit only in (tmin, tmax) and shrinks tmax to
 * it, so testing primitives one after another leaves the nearest hit.
 */
#ifndef REFRAY_RAY_H
#define REFRAY_RAY_H

#include "base/vec.h"

typedef struct ray {
    vec3 origin;
    vec3 dir;          /* unit length for rays the tracer makes */
    real tmin, tmax;   /* open interval of accepted hits */
} ray;

typedef struct hit {
    real t;            /* ray parameter of the hit */
    vec3 point;        /* origin + t*dir, as computed by the primitive */
    vec3 normal;       /* geometric unit normal: outward for solids (sphere,
                          box), the declared side for sheets (plane, disk,
                          triangle: (p1-p0)x(p2-p0)) */
    vec3 shading_normal; /* interpolated vertex normal for meshes, else = normal */
    int prim;          /* index into scene.prims */
    int part;          /* which part of the primitive: a mesh's triangle, else 0 */
    int entering;      /* 1 when dir . normal < 0 (the ray meets the front side) */
    real b1, b2;       /* triangles: the barycentric weights of corners 1 and 2 */
} hit;

/*@ requires \valid_read(r);
    assigns \nothing;
    ensures EXACT(\result.x == r->origin.x + r->dir.x * t && \result.y == r->origin.y + r->dir.y * t &&
                  \result.z == r->origin.z + r->dir.z * t); */
static inline vec3 ray_at(const ray *r, real t) { return vec_madd(r->origin, r->dir, t); }

#endif
