/*
 * lambert_torus.c - family `lambert_torus`: a matte ring torus under
 * distant lights, seen by an orthographic camera: its outline, its Lambert
 * shading and the shadow it casts on itself (spec/analytic.md (section
 * `lambert_torus`), [ORACLE-LAMBERT-TORUS-1], [ORACLE-LAMBERT-TORUS-2]).
 *
 * The solid torus is the union of the balls of radius minor centred on the
 * core circle, so a view ray's first point in it is the least entry into
 * one of those balls over the circle's angle, and a surface point is in
 * its own shadow when the half-line toward the light passes through one of
 * them ahead of the point (oracle_line_ring, oracle_ring_blocks): one
 * minimisation over an angle each, and no quartic.  The value is
 * Kd (Ia + sum E S max(0, N.L)), S = 0 in the shadow, else 1.
 *
 * Ambiguous: the outline (inner and outer), the terminator, the edges of
 * the shadow.
 */
#include "oracle/quadric_family.h"

#define FAMILY "lambert_torus"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_prim *p = &v->scene->prims[0];
    int one = v->scene->prim_count == 1 && p->kind == PRIM_TORUS;
    vec3 c = one ? p->u.torus.center : vec_make(0, 0, 0);
    double r = one ? p->u.torus.major + p->u.torus.minor : 1;
    return quadric_family_accepts(v, PRIM_TORUS, "torus", c, r, 1, FAMILY, why, n);
}

/* 0 in the torus's own shadow, 1 in the light (distant lights only). */
static double shadow(const void *ctx, vec3 p, const oracle_light_at *la, int *ambiguous)
{
    int blocked = oracle_ring_blocks(ctx, p, la->l);
    if (blocked < 0)
        *ambiguous = 1;
    return blocked == 1 ? 0 : 1;
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    oracle_ring t = oracle_ring_of(&v->scene->prims[0]);
    oracle_ray ray = oracle_view_ray(v, x, y);
    double s;
    vec3 nrm;
    oracle_chord_kind kind = oracle_line_ring(&t, ray.origin, ray.dir, &s, &nrm);
    return quadric_family_chord(v, &ray, kind, s, nrm, shadow, &t, out);
}

const oracle_family oracle_lambert_torus = {
    "lambert_torus", "Lambert torus, orthographic view: outline, Kd (Ia + E S max(0, N.L)), its own shadow", 0,
    accepts, radiance, oracle_tolerance_exact,
};
