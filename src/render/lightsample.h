/*
 * lightsample.h - where the point sources of a distributed light sit.
 *
 * The seed's distributed light is "many sources" (slide 3): `samples`
 * isotropic point sources, each of power E/samples.  They are stratified:
 * the light's parameter square is cut into rows x cols cells (the most
 * square factorisation of samples) and one source is placed in each cell,
 * jittered by (u1, u2) in [0,1)^2.  A disk maps the square to the disk by
 * Shirley and Chiu's concentric map ("A low distortion map between disk and
 * square", JGT 2(3), 1997), which keeps the cells equal in area.
 */
#ifndef REFRAY_LIGHTSAMPLE_H
#define REFRAY_LIGHTSAMPLE_H

#include "scene/scene.h"

typedef struct light_grid {
    int rows, cols;   /* rows * cols == samples, rows <= cols, rows as large as possible */
} light_grid;

light_grid light_grid_for(int samples);

/* A point of the unit square's cell `index` of grid g, jittered by (u1, u2). */
void light_cell_point(light_grid g, int index, double u1, double u2, double *s, double *t);

/* Shirley-Chiu concentric map of the unit square onto the unit disk. */
void light_concentric(double s, double t, double *x, double *y);

/* Two unit tangents making (t1, t2, n) a right-handed orthonormal frame;
 * branchless form of Duff et al., "Building an orthonormal basis,
 * revisited", JCGT 6(1), 2017. */
void light_frame(vec3 n, vec3 *t1, vec3 *t2);

/* The position of a distributed light's sample for parameter (s, t) in the
 * unit square; t1, t2 as light_frame gives them for a disk (unused for a
 * rectangle). */
vec3 light_point(const scene_light *light, vec3 t1, vec3 t2, double s, double t);

#endif
