/*
 * area_family.c - see area_family.h and spec/analytic.md (section `area_lights`).
 *
 * A sample point's ray meets the floor's plane at t = (p0 - o).n / (D.n) and
 * the occluder's plane likewise; the occluder is hit when that point lies
 * within its radius.  The side seen is the one facing the ray (N.D < 0), as
 * the tracer turns its normal.  The light at the hit is Kd (Ia + E I) with I
 * the mean of phi over the visible part of the light (area_light.h); the
 * occluder's shadow is the central projection of the occluder from the hit
 * onto the light's plane: a disk of radius b h/h_o about the occluder's
 * centre pushed out by h/h_o.
 */
#include <math.h>
#include <string.h>
#include "oracle/area_family.h"
#include "oracle/area_light.h"
#include "oracle/oracle_geom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define PARALLEL_TOL 1e-9   /* |sin| of the angle between planes taken as parallel */
#define EDGE_MARGIN 1e-9    /* relative margin of the occluder's outline and of grazing rays */
#define BOUND_DELTA 1e-9    /* failure probability of Bernstein's bound per sample point */
#define GRAD_STEPS 64       /* sub-intervals of the gradient's sup */

static const char *light_name(scene_light_kind k)
{
    return k == LIGHT_RECTANGLE ? "rectangle" : "disk";
}

static void tangents(vec3 n, vec3 *e1, vec3 *e2)
{
    vec3 a = fabs(n.x) < 0.6 ? vec_make(1, 0, 0) : vec_make(0, 1, 0);
    *e1 = vec_normalize(vec_sub(a, vec_scale(n, vec_dot(a, n))));
    *e2 = vec_cross(n, *e1);
}

static int opaque_lambert(const scene_model *sc, const scene_prim *p)
{
    const scene_material *m = &sc->materials[p->material];
    return m->t == 0 && vec_max_component(m->ks) == 0;
}

/* The floor, the occluder, and nothing else. */
static int read_prims(const oracle_view *v, const area_kind *k, area_setup *s, char *why, size_t n)
{
    const scene_model *sc = v->scene;
    for (int i = 0; i < sc->prim_count; i++) {
        const scene_prim *p = &sc->prims[i];
        if (p->kind == PRIM_PLANE && !s->floor)
            s->floor = p;
        else if (p->kind == PRIM_DISK && k->occluded && !s->occluder && !p->frame)
            s->occluder = p;
        else
            return oracle_refuse(why, n, "%s: primitive %d is not the family's (one plane%s)", k->family, i + 1,
                                 k->occluded ? " and one untransformed disk" : "");
        if (!opaque_lambert(sc, p))
            return oracle_refuse(why, n, "%s: primitive %d must be opaque Lambert (t = 0, Ks = 0)", k->family,
                                 i + 1);
    }
    if (!s->floor)
        return oracle_refuse(why, n, "%s: the scene has no plane (the floor)", k->family);
    if (k->occluded && !s->occluder)
        return oracle_refuse(why, n, "%s: the scene has no disk (the occluder)", k->family);
    return 1;
}

static int parallel_normals(vec3 a, vec3 b)
{
    return vec_length(vec_cross(a, b)) <= PARALLEL_TOL;
}

/* The light parallel to the floor and off its plane; its area. */
static int read_light(const area_kind *k, area_setup *s, char *why, size_t n)
{
    const scene_light *l = s->light;
    double size;
    if (l->kind == LIGHT_RECTANGLE) {
        double lu = vec_length(l->edge_u), lv = vec_length(l->edge_v);
        if (fabs(vec_dot(l->edge_u, s->n)) > PARALLEL_TOL * lu || fabs(vec_dot(l->edge_v, s->n)) > PARALLEL_TOL * lv)
            return oracle_refuse(why, n, "%s: the rectangle light is not parallel to the floor", k->family);
        s->area = vec_length(vec_cross(l->edge_u, l->edge_v));
        size = lu + lv;
    } else {
        if (!parallel_normals(l->normal, s->n))
            return oracle_refuse(why, n, "%s: the disk light is not parallel to the floor", k->family);
        s->area = M_PI * l->radius * l->radius;
        size = l->radius;
    }
    double h = vec_dot(vec_sub(l->position, s->floor->u.plane.point), s->n);
    if (fabs(h) <= PARALLEL_TOL * size)
        return oracle_refuse(why, n, "%s: the light lies in the floor's plane", k->family);
    return 1;
}

/* The occluder parallel, strictly between the floor and the light. */
static int read_occluder(const area_kind *k, area_setup *s, char *why, size_t n)
{
    const scene_prim *o = s->occluder;
    if (!parallel_normals(o->u.disk.normal, s->n))
        return oracle_refuse(why, n, "%s: the occluder is not parallel to the floor", k->family);
    vec3 p0 = s->floor->u.plane.point;
    double h = vec_dot(vec_sub(s->light->position, p0), s->n);
    double ho = vec_dot(vec_sub(o->u.disk.center, p0), s->n);
    if (!(ho / h > EDGE_MARGIN && ho / h < 1 - EDGE_MARGIN))
        return oracle_refuse(why, n, "%s: the occluder must lie strictly between the floor and the light",
                             k->family);
    return 1;
}

/* A perspective eye on a plane of the scene sees it edge-on. */
static int read_camera(const oracle_view *v, const area_kind *k, area_setup *s, char *why, size_t n)
{
    const scene_camera *c = &v->scene->camera;
    if (c->kind != CAMERA_PERSPECTIVE)
        return 1;
    double df = vec_dot(vec_sub(c->eye, s->floor->u.plane.point), s->n);
    double doc = s->occluder ? vec_dot(vec_sub(c->eye, s->occluder->u.disk.center), s->n) : 1;
    if (df == 0 || doc == 0)
        return oracle_refuse(why, n, "%s: the eye lies in the plane of the floor or the occluder", k->family);
    return 1;
}

int area_setup_read(const oracle_view *v, const area_kind *k, area_setup *s, char *why, size_t n)
{
    const scene_model *sc = v->scene;
    memset(s, 0, sizeof *s);
    s->family = k->family;
    s->scene = sc;
    if (sc->light_count != 1 || sc->lights[0].kind != k->light)
        return oracle_refuse(why, n, "%s: the scene must have exactly one light, a %s distributed_light",
                             k->family, light_name(k->light));
    s->light = &sc->lights[0];
    if (!read_prims(v, k, s, why, n))
        return 0;
    s->n = s->floor->u.plane.normal;
    tangents(s->n, &s->e1, &s->e2);
    if (!read_light(k, s, why, n))
        return 0;
    if (s->occluder && !read_occluder(k, s, why, n))
        return 0;
    return read_camera(v, k, s, why, n);
}

typedef struct receiver {
    vec3 p;                 /* the hit */
    vec3 nf;                /* the floor's normal turned toward the viewer */
    const scene_prim *prim;
} receiver;

enum { LOCATE_AMBIGUOUS = -1, LOCATE_MISS = 0, LOCATE_HIT = 1 };

/* The nearest of the floor and the occluder along r, solved directly. */
static int locate(const area_setup *s, oracle_ray r, receiver *rec)
{
    double dn = vec_dot(r.dir, s->n);
    if (fabs(dn) <= EDGE_MARGIN)
        return LOCATE_AMBIGUOUS;  /* grazing the parallel planes: the horizon */
    vec3 to_floor = vec_sub(s->floor->u.plane.point, r.origin);
    double height = vec_dot(to_floor, s->n), best = HUGE_VAL;
    if (fabs(height) <= EDGE_MARGIN * EDGE_MARGIN * (1 + vec_length(to_floor)))
        return LOCATE_AMBIGUOUS;  /* an orthographic origin on the floor */
    rec->prim = NULL;
    if (height / dn > 0) {
        best = height / dn;
        rec->prim = s->floor;
    }
    if (s->occluder) {
        vec3 c = s->occluder->u.disk.center;
        double t = vec_dot(vec_sub(c, r.origin), s->n) / dn, b = s->occluder->u.disk.radius;
        if (t > 0 && t < best) {
            double off = vec_length(vec_sub(vec_madd(r.origin, r.dir, t), c));
            if (fabs(off - b) <= EDGE_MARGIN * b)
                return LOCATE_AMBIGUOUS;  /* the occluder's outline */
            if (off < b) {
                best = t;
                rec->prim = s->occluder;
            }
        }
    }
    if (!rec->prim)
        return LOCATE_MISS;
    rec->p = vec_madd(r.origin, r.dir, best);
    rec->nf = dn < 0 ? s->n : vec_neg(s->n);
    return LOCATE_HIT;
}

/* The light as the receiver sees it, in the light's plane about the foot. */
typedef struct light_view {
    area_kernel k;
    double poly[4][2];       /* rectangle: corners */
    double edge[2][2];       /* rectangle: its edges U and V */
    double c[2], r;          /* disk: centre, radius */
    int shadowed;            /* 1: the occluder's shadow disk below applies */
    double sc[2], sr;
} light_view;

static void plane_coords(const area_setup *s, vec3 p, vec3 x, double *out)
{
    vec3 d = vec_sub(x, p);
    out[0] = vec_dot(d, s->e1);
    out[1] = vec_dot(d, s->e2);
}

/* 0 when the light is not on the lit side of the receiver. */
static int view_light(const area_setup *s, const receiver *rec, light_view *lv)
{
    const scene_light *l = s->light;
    double h = vec_dot(vec_sub(l->position, rec->p), rec->nf);
    if (!(h > 0))
        return 0;
    lv->k.h = h;
    lv->k.d0 = l->d0;
    lv->k.falloff = l->falloff;
    lv->shadowed = 0;
    if (l->kind == LIGHT_RECTANGLE) {
        vec3 corner[4] = {l->position, vec_add(l->position, l->edge_u),
                          vec_add(l->position, vec_add(l->edge_u, l->edge_v)), vec_add(l->position, l->edge_v)};
        for (int i = 0; i < 4; i++)
            plane_coords(s, rec->p, corner[i], lv->poly[i]);
        /* From the edges themselves, not corner differences, which keep only
         * the digits the corners' distance leaves them. */
        lv->edge[0][0] = vec_dot(l->edge_u, s->e1), lv->edge[0][1] = vec_dot(l->edge_u, s->e2);
        lv->edge[1][0] = vec_dot(l->edge_v, s->e1), lv->edge[1][1] = vec_dot(l->edge_v, s->e2);
        return 1;
    }
    plane_coords(s, rec->p, l->position, lv->c);
    lv->r = l->radius;
    if (s->occluder && rec->prim == s->floor) {
        double ho = vec_dot(vec_sub(s->occluder->u.disk.center, rec->p), rec->nf), scale = h / ho;
        plane_coords(s, rec->p, s->occluder->u.disk.center, lv->sc);
        lv->sc[0] *= scale;
        lv->sc[1] *= scale;
        lv->sr = s->occluder->u.disk.radius * scale;
        lv->shadowed = 1;
    }
    return 1;
}

/* Is the rectangle a true rectangle (for the corner form)? */
static int right_angled(const scene_light *l)
{
    return fabs(vec_dot(l->edge_u, l->edge_v)) <= 1e-12 * vec_length(l->edge_u) * vec_length(l->edge_v);
}

/* The integral of phi over the visible light: closed forms where they
 * exist (inverse square, d0 = 0: the solid angle), else the contour. */
static double light_integral(const area_setup *s, const receiver *rec, const light_view *lv)
{
    const scene_light *l = s->light;
    int solid_angle = l->falloff == FALLOFF_INVERSE_SQUARE && l->d0 == 0;
    if (l->kind == LIGHT_RECTANGLE) {
        if (!solid_angle || !right_angled(l))
            return area_polygon(&lv->k, (const double (*)[2])lv->poly, 4);
        double lu = vec_length(l->edge_u), lw = vec_length(l->edge_v);
        vec3 off = vec_sub(rec->p, l->position);
        double a = vec_dot(off, l->edge_u) / lu, b = vec_dot(off, l->edge_v) / lw;
        return area_rect_solid_angle(lv->k.h, -a, lu - a, -b, lw - b);
    }
    if (lv->shadowed)
        return area_disk_minus_disk(&lv->k, lv->c[0], lv->c[1], lv->r, lv->sc[0], lv->sc[1], lv->sr);
    if (solid_angle)
        return area_disk_solid_angle(lv->k.h, hypot(lv->c[0], lv->c[1]), lv->r);
    return area_disk(&lv->k, lv->c[0], lv->c[1], lv->r);
}

/* The mean of phi over the light: a whole disk far from the point by its
 * series (inverse square, d0 = 0) or by quadrature about its centre (the
 * other falloffs), a far rectangle by quadrature over it, each giving the
 * mean itself: Paxton's form and the
 * contour lose 1e-16 of the disk's whole solid angle, 1e-16/a^2 on the
 * mean (attack 9, finding 4); else the integral over the area. */
static double light_mean(const area_setup *s, const receiver *rec, const light_view *lv)
{
    const scene_light *l = s->light;
    int solid_angle = l->falloff == FALLOFF_INVERSE_SQUARE && l->d0 == 0;
    double r0 = hypot(lv->c[0], lv->c[1]);
    if (l->kind == LIGHT_DISK && !lv->shadowed && lv->r <= AREA_DISK_FAR * hypot(lv->k.h, r0))
        return solid_angle ? area_disk_mean_far(lv->k.h, r0, lv->r)
                           : area_disk_mean_far_quadrature(&lv->k, r0, lv->r);
    if (l->kind == LIGHT_RECTANGLE) {
        double cx = lv->poly[0][0] + 0.5 * (lv->edge[0][0] + lv->edge[1][0]);
        double cy = lv->poly[0][1] + 0.5 * (lv->edge[0][1] + lv->edge[1][1]);
        double size = vec_length(l->edge_u) + vec_length(l->edge_v);
        if (size <= AREA_DISK_FAR * hypot(lv->k.h, hypot(cx, cy)))
            return area_parallelogram_mean(&lv->k, lv->poly[0], lv->edge[0], lv->edge[1]);
    }
    return light_integral(s, rec, lv) / s->area;
}

static rgb shade(const area_setup *s, const receiver *rec, double mean)
{
    const scene_model *sc = s->scene;
    rgb kd = sc->materials[rec->prim->material].kd;
    return vec_mul(kd, vec_madd(sc->ambient, s->light->power, mean));
}

oracle_status area_radiance(const oracle_view *v, const area_kind *kind, double x, double y, rgb *out)
{
    area_setup s;
    char why[160];
    receiver rec;
    light_view lv;
    if (!area_setup_read(v, kind, &s, why, sizeof why))
        return ORACLE_AMBIGUOUS;
    int where = locate(&s, oracle_view_ray(v, x, y), &rec);
    if (where == LOCATE_AMBIGUOUS)
        return ORACLE_AMBIGUOUS;
    if (where == LOCATE_MISS) {
        *out = v->scene->image.background;
        return ORACLE_EXACT;
    }
    double mean = view_light(&s, &rec, &lv) ? light_mean(&s, &rec, &lv) : 0;
    *out = shade(&s, &rec, mean);
    return ORACLE_EXACT;
}

/* ---- the tolerance (spec "Tolerance") ---- */

double area_bernstein(double var, double range, double delta)
{
    double lambda = log(2 / delta);
    return lambda * range / 3 + sqrt(lambda * lambda * range * range / 9 + 2 * lambda * var);
}

/* The squarest factorisation rows x cols of n, rows <= cols (the sampling
 * model of spec/shading.md, restated here rather than read from the
 * sampler). */
static void grid_for(int n, int *rows, int *cols)
{
    int r = (int)floor(sqrt((double)n));
    while (r > 1 && n % r != 0)
        r--;
    *rows = r < 1 ? 1 : r;
    *cols = n / *rows;
}

/* The error of the stratified estimate is (1/N) sum_j X_j, X_j = f(q_j) -
 * mean_j f over cell j: zero-mean under uniform jitter.  Per cell: */
typedef struct bound_sum {
    double osc;       /* sum of the cells' oscillations (deterministic bound) */
    double var;       /* sum of the bounds on Var X_j */
    double range;     /* largest oscillation */
} bound_sum;

/* The cells as the bound sees them: every point of cell j lies within
 * `reach` of its centre, paths inside it are at most `diameter` long, and
 * E|X - EX|^2 <= moment for X uniform in it. */
typedef struct cell_model {
    int rows, cols;
    double reach, diameter, moment;
    vec3 t1, t2;      /* disk: the tangent frame of the sampler's model */
} cell_model;

/* Cell j's part: phi is decreasing in d, so over the distances
 * [lo, hi] from the foot its oscillation is at most phi(lo) - phi(hi) and
 * |grad phi| = |phi'(d)| rho/d at most |phi'(d(lo))| hi/d(hi); Var X_j <=
 * min(L^2 moment, osc^2/4) (Lipschitz along paths; Popoviciu).  A cell
 * that the shadow's rim may cut has X_j within [-phi(lo), phi(lo)] (osc
 * phi(lo)); a cell inside the shadow adds nothing. */
static void add_cell(bound_sum *b, const light_view *lv, const cell_model *m, double cx, double cy)
{
    double rho = hypot(cx, cy), lo = fmax(0, rho - m->reach), hi = rho + m->reach, h = lv->k.h;
    double top = area_phi(&lv->k, hypot(h, lo)), osc = top - area_phi(&lv->k, hypot(h, hi)), var;
    if (lv->shadowed) {
        double to_shadow = hypot(cx - lv->sc[0], cy - lv->sc[1]);
        if (to_shadow + m->reach <= lv->sr)
            return;
        if (to_shadow - m->reach < lv->sr) {
            b->osc += top;
            b->var += top * top / 4;
            b->range = fmax(b->range, top);
            return;
        }
    }
    double grad = area_phi_slope(&lv->k, hypot(h, lo)) * hi / hypot(h, hi);
    osc = fmin(osc, grad * m->diameter);
    var = fmin(grad * grad * m->moment, osc * osc / 4);
    b->osc += osc;
    b->var += var;
    b->range = fmax(b->range, osc);
}

/* Shirley-Chiu's concentric map of [0,1]^2 onto the unit disk, as the
 * sampling model states it (wedge |a| > |b|: r = a, angle pi/4 b/a). */
static void concentric(double s, double t, double *x, double *y)
{
    double a = 2 * s - 1, b = 2 * t - 1, r, ang;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    if (fabs(a) > fabs(b)) {
        r = a;
        ang = M_PI / 4 * (b / a);
    } else {
        r = b;
        ang = M_PI / 2 - M_PI / 4 * (a / b);
    }
    *x = r * cos(ang);
    *y = r * sin(ang);
}

/* The centre of cell (row, col) in the light's plane about the foot. */
static void cell_centre(const area_setup *s, const receiver *rec, const cell_model *m, int row, int col, double *out)
{
    const scene_light *l = s->light;
    double u = (col + 0.5) / m->cols, v = (row + 0.5) / m->rows;
    vec3 p;
    if (l->kind == LIGHT_RECTANGLE) {
        p = vec_add(l->position, vec_add(vec_scale(l->edge_u, u), vec_scale(l->edge_v, v)));
    } else {
        double x, y;
        concentric(u, v, &x, &y);
        p = vec_add(l->position, vec_add(vec_scale(m->t1, x * l->radius), vec_scale(m->t2, y * l->radius)));
    }
    plane_coords(s, rec->p, p, out);
}

/* A rectangle's cells are the parallelograms a = U/cols, b = V/rows: reach
 * half the longer diagonal, E|X - EX|^2 = (|a|^2 + |b|^2)/12.  A disk's are
 * images of the squares 1/cols x 1/rows under the concentric map, whose
 * paths stretch by at most 2R times the largest operator norm of its
 * Jacobian: J^T J has trace T = 1 + alpha^2 + pi^2/16 <= 1 + pi^2/8 and
 * determinant pi^2/16, so its largest eigenvalue is at most
 * (T + sqrt(T^2 - pi^2/4))/2 (1.382^2; the Frobenius norm, sqrt T = 1.495,
 * was looser): the square's reach, diameter and moment scaled by it.  The
 * disk's tangent frame is the model's (Duff et al. 2017, lightsample.h). */
static void cell_model_for(const scene_light *l, int samples, cell_model *m)
{
    grid_for(samples, &m->rows, &m->cols);
    double w = 1.0 / m->cols, v = 1.0 / m->rows;
    m->t1 = m->t2 = vec_splat(0);
    if (l->kind == LIGHT_RECTANGLE) {
        vec3 a = vec_scale(l->edge_u, w), b = vec_scale(l->edge_v, v);
        m->diameter = fmax(vec_length(vec_add(a, b)), vec_length(vec_sub(a, b)));
        m->reach = m->diameter / 2;
        m->moment = (vec_length2(a) + vec_length2(b)) / 12;
        return;
    }
    double trace = 1 + M_PI * M_PI / 8;
    double lip = 2 * l->radius * sqrt((trace + sqrt(trace * trace - M_PI * M_PI / 4)) / 2);
    vec3 n = l->normal;
    m->diameter = lip * hypot(w, v);
    m->reach = m->diameter / 2;
    m->moment = lip * lip * (w * w + v * v) / 12;
    double sign = copysign(1.0, n.z), a = -1.0 / (sign + n.z), c = n.x * n.y * a;
    m->t1 = vec_make(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    m->t2 = vec_make(c, sign + n.y * n.y * a, -n.y);
}

/* The relative bound at one sample point (0 when it shows no light):
 * |error| <= min(sum osc, Bernstein) / N on the mean of phi, times E,
 * over the pixel's exact value Ia + E mean, per channel (Kd cancels). */
static double point_bound(const area_setup *s, const oracle_view *v, double x, double y, const cell_model *m)
{
    receiver rec;
    light_view lv;
    if (locate(s, oracle_view_ray(v, x, y), &rec) != LOCATE_HIT || !view_light(s, &rec, &lv))
        return 0;
    bound_sum b = {0, 0, 0};
    for (int row = 0; row < m->rows; row++) {
        for (int col = 0; col < m->cols; col++) {
            double c[2];
            cell_centre(s, &rec, m, row, col, c);
            add_cell(&b, &lv, m, c[0], c[1]);
        }
    }
    double n = (double)m->rows * m->cols;
    double err = fmin(b.osc, area_bernstein(b.var, b.range, BOUND_DELTA)) / n;
    if (err == 0)
        return 0;
    double mean = light_mean(s, &rec, &lv), worst = 0;
    double ia[3] = {s->scene->ambient.x, s->scene->ambient.y, s->scene->ambient.z};
    double e[3] = {s->light->power.x, s->light->power.y, s->light->power.z};
    for (int c = 0; c < 3; c++) {
        double exact = ia[c] + e[c] * mean;
        if (e[c] > 0)
            worst = fmax(worst, exact > 0 ? e[c] * err / exact : HUGE_VAL);
    }
    return worst;
}

double area_tolerance(const oracle_view *v, const area_kind *kind, int light_samples)
{
    area_setup s;
    char why[160];
    cell_model m;
    if (!area_setup_read(v, kind, &s, why, sizeof why))
        return 0;
    cell_model_for(s.light, light_samples > 0 ? light_samples : s.light->samples, &m);
    int k = v->samples;
    double tol = 1e-9;
    for (int j = 0; j < v->height; j++)
        for (int i = 0; i < v->width; i++)
            for (int b = 0; b < k; b++)
                for (int a = 0; a < k; a++)
                    tol = fmax(tol, point_bound(&s, v, i + (a + 0.5) / k, j + (b + 0.5) / k, &m));
    return tol;
}
