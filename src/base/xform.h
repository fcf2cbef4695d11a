/*
 * xform.h - affine transforms of primitives (translate, rotate, scale in the
 * order written).  A transform is stored with its inverse so that a ray can
 * be taken into a primitive's local frame without a matrix inversion per ray.
 *
 * The matrix is scene data, made once by the loader: it stays double in the
 * long double build (the front end passes double pointers into it), while
 * applying it to points and vectors is done in `real` (vec.h).
 */
#ifndef REFRAY_XFORM_H
#define REFRAY_XFORM_H

#include "base/vec.h"

typedef struct xform {
    double m[3][4];   /* row-major: p' = M[:, :3] p + M[:, 3] */
} xform;

xform xform_identity(void);
xform xform_translate(vec3 t);
xform xform_scale(vec3 s);
/* Rotation by degrees about the x, then y, then z axis (right-hand rule). */
xform xform_rotate_xyz(vec3 degrees);
/* after o before: first apply before, then after. */
xform xform_compose(const xform *after, const xform *before);
/* Returns 0 when the linear part is singular (a zero scale). */
int xform_invert(const xform *a, xform *inverse);

vec3 xform_point(const xform *a, vec3 p);
vec3 xform_vector(const xform *a, vec3 v);
/* Normals transform by the inverse transpose: pass the inverse here. */
vec3 xform_normal(const xform *inverse, vec3 n);

int xform_is_identity(const xform *a);
/* True when the linear part is a rotation times a uniform scale s (s > 0,
 * returned); such a transform maps spheres to spheres and disks to disks. */
int xform_is_similarity(const xform *a, double *scale);

#endif
