/*
 * oracle_quadric.h - lines against a closed cylinder or cone (a frustum)
 * and against a ring torus, solved as spec/analytic.md derives them, for
 * the families lambert_cylinder, lambert_cone and lambert_torus.  Nothing
 * here calls the tracer's hit tests; the routes differ on purpose:
 *   - cylinder: Pythagoras in the plane across the axis (the line's
 *     nearest point to the axis, then the half chord);
 *   - cone: the apex form ((p - V).w)^2 = cos^2(theta) |p - V|^2, with the
 *     normal cos(theta) (p - V)/|p - V| - w, not the tracer's
 *     radius-along-the-axis form;
 *   - torus: the solid torus as the union of the balls of radius minor
 *     centred on the core circle, so the first point of a line in it is
 *     the least entry into one of those balls, minimised over the circle's
 *     angle; no quartic is formed.
 */
#ifndef REFRAY_ORACLE_QUADRIC_H
#define REFRAY_ORACLE_QUADRIC_H

#include "oracle/oracle_util.h"

/* A closed cylinder (r0 = r1) or cone: the end `from`, unit axis a,
 * length, radius r0 at from and r1 at the other end. */
typedef struct oracle_frustum {
    vec3 from, a;
    double len, r0, r1;
} oracle_frustum;

oracle_frustum oracle_frustum_of(const scene_prim *p);

/* The centre and radius of a ball holding the frustum. */
void oracle_frustum_ball(const oracle_frustum *f, vec3 *centre, double *radius);

/*
 * Where the line o + s d (d unit) first enters the closed frustum: *s and
 * the outward unit normal *n there.  ORACLE_CHORD_GRAZE within
 * ORACLE_EDGE_MARGIN of the outline (of the side or of a cap seen edge-on),
 * of a rim (side and cap entered at the same place) or of a cone's apex.
 */
oracle_chord_kind oracle_line_frustum(const oracle_frustum *f, vec3 o, vec3 d, double *s, vec3 *n);

/* A ring torus: centre c, unit axis a, major R, minor r, and u, v with
 * (u, v, a) orthonormal: the core circle is c + R (cos t u + sin t v). */
typedef struct oracle_ring {
    vec3 c, a, u, v;
    double major, minor;
} oracle_ring;

oracle_ring oracle_ring_of(const scene_prim *p);

/* The first point of the line o + s d (d unit, o outside the torus's
 * bounding sphere) in the solid torus: *s, and the outward unit normal *n.
 * ORACLE_CHORD_GRAZE when the line passes within ORACLE_EDGE_MARGIN minor
 * of touching the tube where it could be seen. */
oracle_chord_kind oracle_line_ring(const oracle_ring *t, vec3 o, vec3 d, double *s, vec3 *n);

/* Whether the half-line p + s l (s > 0, l unit) from a point p of the
 * surface meets the solid torus: 1 shadowed, 0 not, -1 within
 * ORACLE_EDGE_MARGIN minor of grazing it (a shadow's edge). */
int oracle_ring_blocks(const oracle_ring *t, vec3 p, vec3 l);

#endif
