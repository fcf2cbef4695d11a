/*
 * optics_util.c - see optics_util.h.  The derivations are in
 * spec/analytic.md, sections `parallel_mirrors` (unfolding), `glass_slab`
 * (the shift), `snell_window` (the critical angle) and `ball_lens` (the
 * ball's path).
 */
#include <float.h>
#include <math.h>
#include "oracle/optics_util.h"
#include "oracle/oracle_geom.h"
#include "render/intersect.h"

double optics_geometric_sum(double q, int m)
{
    if (m <= 0)
        return 0;
    if (q == 1)
        return m;
    if (q == 0)
        return 1;
    /* 1 - q^m = -expm1(m log q) and log q = log1p(-x): no cancellation
     * when q is near 1, where the textbook (1 - q^m)/(1 - q) loses digits. */
    double x = 1 - q;
    return expm1(m * log1p(-x)) / -x;
}

rgb optics_geometric_sum_rgb(rgb q, int m)
{
    return vec_make(optics_geometric_sum(q.x, m), optics_geometric_sum(q.y, m), optics_geometric_sum(q.z, m));
}

/* Going up the k-th hit is on the hi wall for even k; going down on the lo
 * wall for even k: the path alternates from the wall it meets first. */
void optics_slab_hit(const optics_slab *s, vec3 o, vec3 d, int k, optics_bounce *out)
{
    double zo = vec_dot(s->axis, o), dz = vec_dot(s->axis, d), width = s->hi - s->lo;
    int up = dz > 0, odd = k % 2;
    double level = up ? s->hi + k * width : s->lo - k * width;
    double length = (level - zo) / dz;
    vec3 across = vec_sub(d, vec_scale(s->axis, dz));
    out->wall = up ? !odd : odd;
    double z_wall = out->wall ? s->hi : s->lo;
    /* The unfolded point o + length d, folded: its part across the axis
     * kept, its height replaced by the real wall's. */
    out->point = vec_add(vec_add(o, vec_scale(across, length)), vec_scale(s->axis, z_wall - zo));
    out->dir = vec_add(across, vec_scale(s->axis, odd ? -dz : dz));
    out->inward = out->wall ? vec_neg(s->axis) : s->axis;
    out->length = length;
}

rgb optics_falloff(const scene_light *light, double d)
{
    double s = d + light->d0;
    rgb e = light->power;
    switch (light->falloff) {
    case FALLOFF_LINEAR:
        return vec_scale(e, 1 / s);
    case FALLOFF_INVERSE_SQUARE:
        return vec_scale(e, 1 / (s * s));
    case FALLOFF_NONE:
    default:
        return e;
    }
}

/* The Phong lobe max(0, c)^n with the model's edges: 1 at c >= 1, values
 * under DBL_MIN flushed (spec/shading.md, SHADE-PHONG). */
static double phong_lobe(double c, double shininess)
{
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 1;
    double p = pow(c, shininess);
    return p >= DBL_MIN ? p : 0;
}

int optics_light_terms(const scene_light *light, const scene_material *m, vec3 point, vec3 n, vec3 v, double through,
                       rgb *body, rgb *highlight)
{
    vec3 l;
    rgb intensity;
    if (light->kind == LIGHT_DISTANT) {
        l = vec_neg(light->direction);
        intensity = light->power;
    } else {
        vec3 to = vec_sub(light->position, point);
        double d = vec_length(to);
        l = vec_scale(to, 1 / d);
        intensity = optics_falloff(light, d);
    }
    double nl = vec_dot(n, l);
    if (!(nl > 0))
        return 1;
    intensity = vec_scale(intensity, through);
    *body = vec_madd(*body, vec_mul(m->kd, intensity), nl);
    vec3 r = vec_sub(vec_scale(n, 2 * nl), l);
    double c = vec_dot(v, r);
    /* Shininess 0 makes the lobe a step at V.R = 0. */
    if (m->n == 0 && fabs(c) <= OPTICS_MARGIN && vec_max_component(m->ks) > 0)
        return 0;
    *highlight = vec_madd(*highlight, vec_mul(m->ks, intensity), phong_lobe(c, m->n));
    return 1;
}

/* sin(theta - theta_t) = sin theta cos theta_t - cos theta sin theta_t;
 * cos theta_t = sqrt((1 - s)(1 + s)) keeps digits near grazing. */
double optics_slab_shift(double h, double sin_theta, double cos_theta, double n)
{
    double sin_t = sin_theta / n, cos_t = sqrt((1 - sin_t) * (1 + sin_t));
    return h * (sin_theta * cos_t - cos_theta * sin_t) / cos_t;
}

/*
 * In the (z, y) plane with the centre at the origin, the ray at height y
 * enters at R(-cos i, sin i) with sin i = y/R, bends toward the axis by
 * i - r, crosses a chord that subtends pi - 2r at the centre, so it leaves
 * at polar angle (pi - i) - (pi - 2r) = 2r - i, bending again by i - r.
 */
void optics_ball_trace(double y, double radius, double n, optics_ball_path *p)
{
    double s = y / radius;
    p->incidence = atan2(s, sqrt((1 - s) * (1 + s)));
    p->refraction = asin(s / n);
    p->deviation = 2 * (p->incidence - p->refraction);
    double a = 2 * p->refraction - p->incidence;
    p->exit_z = radius * cos(a);
    p->exit_y = radius * sin(a);
}

/* The exit ray y = exit_y - (z - exit_z) tan(delta) meets y = 0 at
 * z = exit_z + exit_y / tan(delta) = R sin(a + delta) / sin(delta), and
 * a + delta = i. */
double optics_ball_axis_crossing(double y, double radius, double n)
{
    optics_ball_path p;
    optics_ball_trace(y, radius, n, &p);
    if (p.deviation == 0)
        return HUGE_VAL;
    return radius * sin(p.incidence) / sin(p.deviation);
}

double optics_ball_paraxial_focus(double radius, double n)
{
    return n * radius / (2 * (n - 1));
}

double optics_ball_screen_height(const optics_ball_path *p, double zs)
{
    return p->exit_y - (zs - p->exit_z) * tan(p->deviation);
}

double optics_critical_sin(double n1, double n2)
{
    return n1 > n2 ? n2 / n1 : 1;
}

oracle_ray optics_corner_ray(const oracle_view *v, int corner)
{
    return oracle_view_ray(v, (corner & 1) ? v->width : 0, (corner & 2) ? v->height : 0);
}

double optics_max_abs(vec3 v)
{
    return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
}

double optics_spawn_offset(double magnitude, vec3 point)
{
    return SPAWN_REL * fmax(magnitude, optics_max_abs(point)) + SPAWN_ABS;
}

int optics_close(rgb a, rgb b, double rel)
{
    return fabs(b.x - a.x) <= rel * fabs(a.x) && fabs(b.y - a.y) <= rel * fabs(a.y) &&
           fabs(b.z - a.z) <= rel * fabs(a.z);
}
