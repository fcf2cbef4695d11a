/*
 * oracle_geom.h - the camera as the oracle sees it, derived from the
 * camera's definition (spec/language.md) without camera.c or the basis the
 * loader computed: a bug in either would otherwise be shared.
 */
#ifndef REFRAY_ORACLE_GEOM_H
#define REFRAY_ORACLE_GEOM_H

#include "oracle/oracle.h"

typedef struct oracle_ray {
    vec3 origin;
    vec3 dir;      /* unit */
} oracle_ray;

/* v itself when its largest component is within [2^-511, 2^511) (v.v
 * neither overflows nor loses digits to underflow), else v over that
 * component: the same direction, for a unit vector or a length formed
 * without overflow.  v finite and non-zero. */
vec3 oracle_tame(vec3 v);

/* The camera's frame: forward from eye to look_at; up made perpendicular
 * to it by Gram-Schmidt; right = forward x up (right-handed). */
void oracle_camera_frame(const scene_camera *c, vec3 *forward, vec3 *right, vec3 *up);

/* The camera ray through continuous image point (x, y) of view v. */
oracle_ray oracle_view_ray(const oracle_view *v, double x, double y);

#endif
