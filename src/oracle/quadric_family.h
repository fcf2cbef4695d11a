/*
 * quadric_family.h - what the families lambert_cylinder, lambert_cone and
 * lambert_torus share: their assumptions (one untransformed matte shape,
 * an orthographic camera whose image plane lies outside a ball around it,
 * lights outside that ball) and the shading of the first point a view ray
 * meets (spec/analytic.md).
 */
#ifndef REFRAY_QUADRIC_FAMILY_H
#define REFRAY_QUADRIC_FAMILY_H

#include "oracle/oracle_quadric.h"

/* 1 when the scene is one primitive of kind `kind`, untransformed, matte,
 * with point and distant lights outside the ball (c, r) (distant_only:
 * distant lights alone) and an orthographic camera whose image plane lies
 * wholly in front of that ball; else refuses with the reason. */
int quadric_family_accepts(const oracle_view *v, scene_prim_kind kind, const char *what, vec3 c, double r,
                           int distant_only, const char *family, char *why, size_t n);

/* The Lambert value Kd (Ia + sum I S max(0, N.L)) at p with normal n for a
 * view along d, shadow() as oracle_shade_direct takes it; *out is set when
 * ORACLE_EXACT. */
oracle_status quadric_family_shade(const oracle_view *v, vec3 p, vec3 n, vec3 d, oracle_shadow_fn shadow,
                                   const void *ctx, rgb *out);

/* What a view ray's meeting with the shape (kind, at distance s with
 * normal n) shows: ORACLE_AMBIGUOUS where it grazes, the background where
 * it misses, else quadric_family_shade at its point. */
oracle_status quadric_family_chord(const oracle_view *v, const oracle_ray *ray, oracle_chord_kind kind, double s,
                                   vec3 n, oracle_shadow_fn shadow, const void *ctx, rgb *out);

/* The radiance of families lambert_cylinder and lambert_cone at (x, y): the
 * view ray's first point on the closed frustum (oracle_line_frustum)
 * shaded by quadric_family_shade, the background where it misses, and
 * ORACLE_AMBIGUOUS where it grazes. */
oracle_status quadric_family_frustum_radiance(const oracle_view *v, double x, double y, rgb *out);

#endif
