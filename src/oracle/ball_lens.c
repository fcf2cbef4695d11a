/*
 * ball_lens.c - family `ball_lens` (spec/analytic.md (section `ball_lens`),
 * [ORACLE-BALL]): a clear glass sphere (radius R, index n > 1,
 * transparency t, Kd 0, Ks 0) in front of a screen (a plane perpendicular
 * to the view), seen by an orthographic camera looking along the axis, the
 * screen lit by point lights between the ball and the screen.  A camera
 * ray at distance y < R from the axis meets the ball at incidence
 * i = asin(y/R), bends to r = asin(sin i / n), leaves by symmetry at
 * incidence r inside and i outside, deviated by delta = 2(i - r) toward the
 * axis, from the point at polar angle 2r - i; it meets the screen at
 * height (optics_ball_screen_height)
 *     y_s = R sin(2r - i) - (z_s - R cos(2r - i)) tan(delta)
 * on its own side of the axis (negative: across it).  The pixel is
 *     t^2 screen(y_s)                 (the ball's own local colour is 0)
 * at max_depth >= 3 (entry, exit, screen), 0 below; a ray with
 * delta > 90 degrees goes back and sees t^2 bg; a ray missing the ball
 * sees the screen straight on.  Paraxially the exit rays cross the axis at
 * EFL = n R / (2 (n - 1)) from the centre.  Ambiguous: the ball's outline
 * (|y - R| within 1e-9 R) and rays whose colour changes by more than a
 * quarter of the tolerance when the exit ray turns by the most the
 * tracer's self-intersection offsets can turn it (exit_uncertainty): near
 * the rim the exit bend amplifies them by n cos r / cos i, and exit rays
 * near parallel to the screen amplify again by 1/cos(delta).
 */
#include <math.h>
#include "oracle/optics_util.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"

#define BALL_GRAZING 1e-5

typedef struct ball_setup {
    const scene_prim *ball, *screen;
    const scene_material *glass, *paint;
    vec3 forward;          /* the camera's view direction: the axis */
    double screen_z;       /* the screen's distance from the centre along it */
} ball_setup;

static int find_parts(const scene_model *s, ball_setup *b)
{
    if (s->prim_count != 2)
        return 0;
    int ball = s->prims[0].kind == PRIM_SPHERE ? 0 : 1;
    b->ball = &s->prims[ball];
    b->screen = &s->prims[1 - ball];
    if (b->ball->kind != PRIM_SPHERE || b->ball->frame || b->screen->kind != PRIM_PLANE)
        return 0;
    b->glass = &s->materials[b->ball->material];
    b->paint = &s->materials[b->screen->material];
    vec3 r, u;
    oracle_camera_frame(&s->camera, &b->forward, &r, &u);
    b->screen_z = vec_dot(vec_sub(b->screen->u.plane.point, b->ball->u.sphere.center), b->forward);
    return 1;
}

/* Distance along the axis from the ball's centre. */
static double axial(const ball_setup *b, vec3 p)
{
    return vec_dot(vec_sub(p, b->ball->u.sphere.center), b->forward);
}

static int accepts_parts(const scene_model *s, ball_setup *b, char *why, size_t n)
{
    if (!find_parts(s, b))
        return oracle_refuse(why, n, "ball_lens: the scene must be one sphere and one plane");
    const scene_material *g = b->glass, *p = b->paint;
    if (vec_max_component(g->kd) != 0 || vec_max_component(g->ks) != 0 || !(g->t > 0) || !(g->ior > 1))
        return oracle_refuse(why, n, "ball_lens: the sphere must have Kd = 0, Ks = 0, t > 0 and ior > 1");
    if (vec_max_component(p->ks) != 0 || p->t != 0)
        return oracle_refuse(why, n, "ball_lens: the screen must have Ks = 0 and t = 0");
    if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
        return oracle_refuse(why, n, "ball_lens: the camera must be orthographic");
    if (vec_length(vec_cross(b->screen->u.plane.normal, b->forward)) > 1e-12)
        return oracle_refuse(why, n, "ball_lens: the screen must be perpendicular to the view");
    double radius = b->ball->u.sphere.radius;
    if (!(axial(b, s->camera.eye) < -radius * (1 + OPTICS_MARGIN)))
        return oracle_refuse(why, n, "ball_lens: the camera must be in front of the sphere");
    if (!(b->screen_z > radius * (1 + OPTICS_MARGIN)))
        return oracle_refuse(why, n, "ball_lens: the screen must be behind the sphere, apart from it");
    return 1;
}

/* Lights strictly between the ball and the screen: the segment from any
 * screen point to them stays behind the ball, so nothing shadows them. */
static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    ball_setup b;
    if (!accepts_parts(s, &b, why, n))
        return 0;
    double radius = b.ball->u.sphere.radius;
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind != LIGHT_POINT)
            return oracle_refuse(why, n, "ball_lens: light %d is not a point light", i + 1);
        double z = axial(&b, l->position);
        if (!(z > radius * (1 + OPTICS_MARGIN) && z < b.screen_z * (1 - OPTICS_MARGIN)))
            return oracle_refuse(why, n, "ball_lens: point light %d is not between the sphere and the screen",
                                 i + 1);
    }
    return 1;
}

/* The screen's colour at point p seen along view (toward the viewer). */
static rgb screen_colour(const scene_model *s, const ball_setup *b, vec3 p, vec3 view)
{
    rgb body = vec_mul(b->paint->kd, s->ambient), highlight = vec_splat(0);
    vec3 facing = vec_neg(b->forward);
    for (int i = 0; i < s->light_count; i++)
        (void)optics_light_terms(&s->lights[i], b->paint, p, facing, view, 1, &body, &highlight);
    return body;
}

/* t^2 times the screen's colour seen by the exit ray of path p turned to
 * deviation delta (t^2 bg when it turns back); offset: the unit vector
 * from the axis toward the camera ray. */
static rgb exit_colour(const scene_model *s, const ball_setup *b, const optics_ball_path *p, double delta, vec3 offset)
{
    double c = cos(delta), t2 = b->glass->t * b->glass->t;
    if (!(c > 0))
        return vec_scale(s->image.background, t2);
    optics_ball_path turned = *p;
    turned.deviation = delta;
    double ys = optics_ball_screen_height(&turned, b->screen_z);
    vec3 hit = vec_add(b->ball->u.sphere.center, vec_add(vec_scale(b->forward, b->screen_z), vec_scale(offset, ys)));
    vec3 dir = vec_sub(vec_scale(b->forward, c), vec_scale(offset, sin(delta)));
    return vec_scale(screen_colour(s, b, hit, vec_neg(dir)), t2);
}

/*
 * How far the tracer's exit ray may turn from the exact one: its entry
 * point moves inward by the spawn offset o, which shifts the chord by
 * o sin r and turns the inner exit angle by (o/R) tan r; the exit bend
 * multiplies that by n cos r / cos i (d(sin i') = n d(sin r')).  Twice
 * that, plus a few ulps of the same gain for the rounding of both bends.
 */
static double exit_uncertainty(const ball_setup *b, const optics_ball_path *p)
{
    double radius = b->ball->u.sphere.radius, n = b->glass->ior;
    double o = optics_spawn_offset(optics_max_abs(b->ball->u.sphere.center) + radius, b->ball->u.sphere.center);
    double gain = n * cos(p->refraction) / cos(p->incidence);
    return 2 * gain * (o / radius * tan(p->refraction) + 8 * 2.220446049250313e-16);
}

/* The ray through the ball at distance y from the axis: exact when the
 * colour is stable under the exit ray's uncertainty, else ambiguous (this
 * covers the turn past 90 degrees, where the colour jumps to bg, and the
 * far screen near it, where the hit point runs away as 1/cos(delta)). */
static oracle_status through_ball(const oracle_view *v, const ball_setup *b, double y, vec3 offset, rgb *out)
{
    const scene_model *s = v->scene;
    optics_ball_path p;
    optics_ball_trace(y, b->ball->u.sphere.radius, b->glass->ior, &p);
    if (v->max_depth < 3) {
        *out = vec_splat(0);
        return ORACLE_EXACT;
    }
    double spread = exit_uncertainty(b, &p);
    rgb c = exit_colour(s, b, &p, p.deviation, offset);
    if (!optics_close(c, exit_colour(s, b, &p, p.deviation - spread, offset), OPTICS_SENSITIVITY) ||
        !optics_close(c, exit_colour(s, b, &p, p.deviation + spread, offset), OPTICS_SENSITIVITY))
        return ORACLE_AMBIGUOUS;
    *out = c;
    return ORACLE_EXACT;
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    ball_setup b;
    (void)find_parts(v->scene, &b);
    oracle_ray r = oracle_view_ray(v, x, y);
    vec3 from_centre = vec_sub(r.origin, b.ball->u.sphere.center);
    vec3 off = vec_sub(from_centre, vec_scale(b.forward, vec_dot(from_centre, b.forward)));
    double h = vec_length(off), radius = b.ball->u.sphere.radius;
    if (fabs(h - radius) <= OPTICS_MARGIN * radius)
        return ORACLE_AMBIGUOUS;
    if (h > radius) {
        vec3 hit = vec_madd(r.origin, b.forward, b.screen_z - axial(&b, r.origin));
        *out = screen_colour(v->scene, &b, hit, vec_neg(b.forward));
        return ORACLE_EXACT;
    }
    return through_ball(v, &b, h, h > 0 ? vec_scale(off, 1 / h) : vec_splat(0), out);
}

const oracle_family oracle_ball_lens = {
    "ball_lens", "a ball lens: refraction in angles, deviation 2(i - r), paraxial focus nR/(2(n-1))", 0,
    accepts, radiance, oracle_tolerance_exact,
};
