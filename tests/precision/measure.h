/*
 * measure.h - the precision of every formula of src/render/shade.c and of each
 * intersection routine, measured against a reference computed in a wider
 * type REF over random and extreme inputs (spec/numerics.md, "Precision
 * per function").
 *
 * The includer defines, before including this file:
 *   REF                      the reference type (__float128 or long double)
 *   REF_SQRT, REF_POW, REF_FABS  its functions
 *   REF_EPSILON              its unit roundoff (inputs where the reference
 *                            itself is not sure to a tenth of an eps are skipped)
 * and gets `static const measure_fn measure_table[]`, each entry measuring
 * one function over n inputs of a counter-based generator and returning its
 * worst error (in the entry's unit) with the input that gave it, and the
 * number of wrong discrete decisions (hit or miss, refract or reflect)
 * away from the boundary.  tests/precision/precision.c prints the table
 * over many inputs with __float128; tests/test_stability.c asserts each
 * documented bound over a small sample with long double.
 *
 * Units: "eps" is 2^-52 times the entry's scale: relative error / 2^-52 when
 * the scale is the exact value, absolute error / 2^-52 for cosines and unit
 * vectors (whose scale is 1), and for hit points the distance from the exact
 * surface over 2^-52 times the magnitude m of the coordinates involved
 * (ray_spawn's offset is 1024 of these: every routine must stay below).
 */
#ifndef REFRAY_MEASURE_H
#define REFRAY_MEASURE_H

#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include "render/intersect.h"
#include "render/shade.h"
#include "naive.h"

typedef struct measure {
    double worst;        /* the largest error, in the entry's unit */
    char input[320];     /* the input that gave it, as hex floats */
    long count;          /* inputs measured */
    long wrong;          /* wrong decisions away from the boundary */
} measure;

typedef struct measure_fn {
    const char *name;
    const char *unit;    /* how worst is measured */
    double bound;        /* documented bound on worst; wrong must be 0 */
    void (*run)(long n, uint64_t seed, measure *m);
    int quad_only;       /* the reference needs __float128 (a sliver's plane
                            is not known to long double's 2^-64 times 1e8) */
} measure_fn;

/* ---- the wide reference ---------------------------------------------- */

typedef struct qv {
    REF x, y, z;
} qv;

static qv q_of(vec3 v)
{
    qv q = {v.x, v.y, v.z};
    return q;
}
static qv q_make(REF x, REF y, REF z)
{
    qv q = {x, y, z};
    return q;
}
static qv q_add(qv a, qv b) { return q_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static qv q_sub(qv a, qv b) { return q_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static qv q_scale(qv a, REF s) { return q_make(a.x * s, a.y * s, a.z * s); }
static REF q_dot(qv a, qv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static REF q_len(qv a) { return REF_SQRT(q_dot(a, a)); }
static qv q_unit(qv a) { return q_scale(a, 1 / q_len(a)); }
static qv q_cross(qv a, qv b)
{
    return q_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static REF q_maxabs(qv a)
{
    REF x = REF_FABS(a.x), y = REF_FABS(a.y), z = REF_FABS(a.z);
    return x > y ? (x > z ? x : z) : (y > z ? y : z);
}

/* ---- inputs ----------------------------------------------------------- */

typedef struct gen {
    uint64_t seed, counter;
} gen;

static double g_uniform(gen *g)
{
    uint64_t z = g->seed * 0x9E3779B97F4A7C15u + (g->counter++ + 1) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}

static double g_range(gen *g, double lo, double hi) { return lo + (hi - lo) * g_uniform(g); }

/* 10^u for u uniform in [lo, hi]: magnitudes spread over decades. */
static double g_decade(gen *g, double lo, double hi) { return pow(10.0, g_range(g, lo, hi)); }

/* A unit vector in double, as the tracer makes them (normalised, so unit
 * only to rounding). */
static vec3 g_unit(gen *g)
{
    for (;;) {
        vec3 v = vec_make(g_range(g, -1, 1), g_range(g, -1, 1), g_range(g, -1, 1));
        real l2 = vec_length2(v);
        if (l2 > 0.01 && l2 <= 1)
            return vec_normalize(v);
    }
}

/* A unit vector at angle a from unit u (in a random plane through u). */
static vec3 g_at_angle(gen *g, vec3 u, double a)
{
    vec3 w = vec_normalize(vec_cross(u, g_unit(g)));
    return vec_normalize(vec_add(vec_scale(u, cos(a)), vec_scale(w, sin(a))));
}

static double err_units(REF got, REF want, REF scale)
{
    return (double)(REF_FABS(got - want) / (scale * (REF)DBL_EPSILON));
}

static double vec_err_units(vec3 got, qv want, REF scale)
{
    return (double)(q_maxabs(q_sub(q_of(got), want)) / (scale * (REF)DBL_EPSILON));
}

static void note(measure *m, double err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#include <stdarg.h>
static void note(measure *m, double err, const char *fmt, ...)
{
    m->count++;
    if (!(err <= m->worst)) {
        va_list ap;
        m->worst = err;
        va_start(ap, fmt);
        vsnprintf(m->input, sizeof m->input, fmt, ap);
        va_end(ap);
    }
}

#define V3(v) (double)(v).x, (double)(v).y, (double)(v).z
#define V3F "(%a, %a, %a)"

/* ---- shade.c ----------------------------------------------------------- */

static void run_ambient(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 kd = vec_make(g_uniform(&g), g_uniform(&g), g_uniform(&g));
        vec3 ia = vec_make(g_decade(&g, -6, 6), g_decade(&g, -6, 6), g_decade(&g, -6, 6));
        rgb got = shade_ambient(kd, ia);
        REF want = (REF)kd.x * ia.x;
        note(m, err_units(got.x, want, want), "Kd %a Ia %a", (double)kd.x, (double)ia.x);
    }
}

static void run_falloff(long n, uint64_t seed, measure *m, scene_falloff kind)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double e = g_decade(&g, -3, 3), d = g_decade(&g, -300, 300), d0 = i % 3 ? g_decade(&g, -300, 3) : 0;
        rgb got = shade_falloff(vec_splat(e), d, d0, kind);
        REF s = (REF)d + d0, want = kind == FALLOFF_LINEAR ? e / s : e / (s * s);
        if (want > DBL_MAX)
            want = DBL_MAX;
        if (want < DBL_MIN)   /* subnormal results have no relative precision */
            continue;
        note(m, err_units(got.x, want, want), "E %a d %a d0 %a", e, d, d0);
    }
}

static void run_falloff_linear(long n, uint64_t seed, measure *m) { run_falloff(n, seed, m, FALLOFF_LINEAR); }
static void run_falloff_square(long n, uint64_t seed, measure *m) { run_falloff(n, seed, m, FALLOFF_INVERSE_SQUARE); }

static void run_sample_power(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double e = g_decade(&g, -6, 6);
        int k = 1 + (int)(g_uniform(&g) * 4096);
        REF want = e / (REF)k;
        note(m, err_units(shade_sample_power(vec_splat(e), k).x, want, want), "E %a samples %d", e, k);
    }
}

/* N.L for unit-to-rounding inputs, near grazing half of the time: absolute
 * error against the exact cosine of the angle between them. */
static void run_lambert(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 nn = g_unit(&g);
        vec3 l = i % 2 ? g_unit(&g) : g_at_angle(&g, nn, 1.5707963267948966 - g_decade(&g, -12, -1));
        REF c = q_dot(q_unit(q_of(nn)), q_unit(q_of(l)));
        REF want = c > 0 ? (c < 1 ? c : 1) : 0;
        note(m, err_units(shade_lambert(nn, l), want, 1), "N " V3F " L " V3F, V3(nn), V3(l));
    }
}

static void run_diffuse(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 nn = g_unit(&g), l = g_unit(&g);
        double kd = g_uniform(&g), e = g_decade(&g, -3, 3);
        REF c = q_dot(q_unit(q_of(nn)), q_unit(q_of(l))), want = c > 0 ? (REF)kd * e * c : 0;
        note(m, err_units(shade_diffuse(vec_splat(kd), vec_splat(e), nn, l).x, want, (REF)kd * e),
             "Kd %a E %a N " V3F " L " V3F, kd, e, V3(nn), V3(l));
    }
}

/* R = 2 (N.L) N - L with the exact N.L of the given vectors. */
static void run_reflect_about(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 nn = g_unit(&g), l = g_unit(&g);
        qv qn = q_of(nn), ql = q_of(l);
        qv want = q_sub(q_scale(qn, 2 * q_dot(qn, ql)), ql);
        note(m, vec_err_units(shade_reflect_about(l, nn), want, 1), "N " V3F " L " V3F, V3(nn), V3(l));
    }
}

static void run_mirror(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 nn = g_unit(&g), d = g_unit(&g);
        qv qn = q_of(nn), qd = q_of(d);
        qv want = q_sub(qd, q_scale(qn, 2 * q_dot(qn, qd)));
        note(m, vec_err_units(shade_mirror(d, nn), want, 1), "N " V3F " D " V3F, V3(nn), V3(d));
    }
}

/* The lobe cos^n(angle between V and R) of the normalised inputs, for
 * exponents 1 .. 1e6 and angles that put the lobe between 1 and 1e-300. */
static REF lobe_ref(vec3 v, vec3 r, double e)
{
    REF c = q_dot(q_unit(q_of(v)), q_unit(q_of(r)));
    return c > 0 ? REF_POW(c, (REF)e) : 0;
}

static void lobe_input(gen *g, long i, vec3 *v, vec3 *r, double *e)
{
    *e = i % 4 == 0 ? g_decade(g, 0, 6) : (double)(long)g_decade(g, 0, 6);
    *r = g_unit(g);
    double k = g_range(g, 0, 690);           /* lobe = exp(-k) */
    double a = i % 8 == 7 ? g_range(g, 0, 1.5) : sqrt(2 * k / *e);
    *v = g_at_angle(g, *r, a < 1.5 ? a : 1.5);
}

static void run_phong(long n, uint64_t seed, measure *m, int which)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 v, r;
        double e;
        lobe_input(&g, i, &v, &r, &e);
        REF want = lobe_ref(v, r, e);
        if (want < 1e-300)
            continue;
        real got = which == 0 ? shade_phong_lobe(v, r, e)
                 : which == 1 ? pow(vec_dot(v, r), e)   /* refray before issue 5 */
                              : naive_phong_lobe(vec_dot(v, r), e);
        note(m, err_units(got, want, want), "V " V3F " R " V3F " n %a", V3(v), V3(r), e);
    }
}

static void run_phong_lobe(long n, uint64_t seed, measure *m) { run_phong(n, seed, m, 0); }
static void run_phong_pow_dot(long n, uint64_t seed, measure *m) { run_phong(n, seed, m, 1); }
static void run_phong_exp_log(long n, uint64_t seed, measure *m) { run_phong(n, seed, m, 2); }

/* The whole highlight Ks I lobe(V, R(L, N)): R's own rounding included. */
static void run_specular(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 v, r;
        double e;
        lobe_input(&g, i, &v, &r, &e);
        vec3 nn = vec_normalize(vec_add(v, r)), l = shade_reflect_about(r, nn);
        l = vec_normalize(l);
        qv qn = q_unit(q_of(nn)), ql = q_unit(q_of(l)), qvv = q_unit(q_of(v));
        if (!(q_dot(qn, ql) > 0))
            continue;
        qv qr = q_sub(q_scale(qn, 2 * q_dot(qn, ql)), ql);
        REF c = q_dot(qvv, qr), want = c > 0 ? REF_POW(c, (REF)e) : 0;
        if (want < 1e-300)
            continue;
        note(m, err_units(shade_specular(vec_splat(1), vec_splat(1), v, nn, l, e).x, want, want),
             "V " V3F " N " V3F " L " V3F " n %a", V3(v), V3(nn), V3(l), e);
    }
}

/* Snell in REF for the vectors as given (the contract takes them as unit;
 * how far they are from it is the caller's rounding, not this function's):
 * c = -N.D, k = 1 - eta^2 (1 - c^2), t = eta (D + c N) - sqrt(k) N,
 * normalised as shade_refract normalises.  *margin is |k|. */
static int refract_ref(vec3 d, vec3 nn, double n1, double n2, qv *t, REF *margin)
{
    qv qd = q_of(d), qn = q_of(nn);
    REF c = -q_dot(qn, qd), eta = (REF)n1 / n2;
    c = c < 0 ? 0 : (c > 1 ? 1 : c);
    REF k = 1 - eta * eta * (1 - c * c);
    *margin = REF_FABS(k);
    if (k < 0)
        return 0;
    *t = q_unit(q_add(q_scale(q_add(qd, q_scale(qn, c)), eta), q_scale(qn, -REF_SQRT(k))));
    return 1;
}

/* Incidence near grazing, near the critical angle (within 1e-3 .. 1e-15
 * rad) and anywhere; indices 1e-3 .. 1e3. */
static void refract_input(gen *g, long i, vec3 *d, vec3 *nn, double *n1, double *n2)
{
    *n1 = g_decade(g, -0.5, 0.5);
    *n2 = i % 5 == 0 ? g_decade(g, -3, 3) : g_decade(g, -0.5, 0.5);
    *nn = g_unit(g);
    double a;
    if (i % 3 == 0 && *n1 > *n2)
        a = asin(*n2 / *n1) + (g_uniform(g) < 0.5 ? -1 : 1) * g_decade(g, -15, -3);
    else if (i % 3 == 1)
        a = 1.5707963267948966 - g_decade(g, -12, -1);
    else
        a = g_range(g, 0, 1.5707963);
    *d = vec_neg(g_at_angle(g, *nn, a));
}

static void run_refract(long n, uint64_t seed, measure *m, int naive)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 d, nn, t;
        double n1, n2;
        qv want;
        REF margin;
        refract_input(&g, i, &d, &nn, &n1, &n2);
        int ref = refract_ref(d, nn, n1, n2, &want, &margin);
        int got = naive ? naive_refract(d, nn, n1, n2, &t) : shade_refract(d, nn, n1, n2, &t);
        /* the reference's k = 1 - eta^2 (1 - c^2) is itself off by a few
         * REF_EPSILON eta^2, and its cos th2 = sqrt(k) by that over 2 sqrt(k) */
        REF eta = (REF)n1 / n2, ref_doubt = 8 * REF_EPSILON * eta * eta;
        if (margin < ref_doubt)
            continue;
        if (got != ref) {
            /* refract_discriminant's error is about 2^-104 max(n1, n2)^2 / n2^2 */
            REF big = n1 > n2 ? (REF)n1 / n2 : 1;
            m->wrong += margin > 0x1p-100 * big * big;
            continue;
        }
        if (!ref || ref_doubt / (2 * REF_SQRT(margin)) > 0.1 * (REF)DBL_EPSILON * (eta > 1 ? eta : 1))
            continue;
        /* D + cN, the part along the surface, is a difference of unit
         * vectors with an absolute error of an ulp; Snell scales it by
         * n1/n2.  So the error is measured in eps times max(1, n1/n2). */
        note(m, vec_err_units(t, want, n1 > n2 ? (REF)n1 / n2 : 1), "D " V3F " N " V3F " n1 %a n2 %a", V3(d),
             V3(nn), n1, n2);
    }
}

static void run_refract_refray(long n, uint64_t seed, measure *m) { run_refract(n, seed, m, 0); }
static void run_refract_naive(long n, uint64_t seed, measure *m) { run_refract(n, seed, m, 1); }

/* The critical cosine must be the exact one rounded up: error 0 or 1 ulp
 * up, and the next double down must be below it. */
static void run_critical(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double n1 = g_decade(&g, -3, 3), n2 = n1 * g_range(&g, 0.01, 0.9999999);
        double got = shade_critical_angle_cos(n1, n2);
        REF want = REF_SQRT(((REF)n1 - n2) * ((REF)n1 + n2)) / n1;   /* n1 - n2 exact */
        m->wrong += !((REF)got >= want && (REF)nextafter(got, 0.0) < want);
        note(m, err_units(got, want, want), "n1 %a n2 %a", n1, n2);
    }
}

static void run_blend(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double f = g_decade(&g, -6, 6), b = g_decade(&g, -6, 6), t = g_uniform(&g);
        REF want = (1 - (REF)t) * f + (REF)t * b;
        note(m, err_units(shade_transmit_blend(vec_splat(f), vec_splat(b), t).x, want, want),
             "F %a B %a t %a", f, b, t);
    }
}

static void run_combine(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double b = g_decade(&g, -6, 6), h = g_decade(&g, -6, 6), ks = g_uniform(&g), t = g_uniform(&g);
        double mi = g_decade(&g, -6, 6), tr = g_decade(&g, -6, 6);
        REF want = (1 - (REF)t) * b + h + (REF)ks * mi + (REF)t * tr;
        rgb got = shade_combine(vec_splat(b), vec_splat(h), vec_splat(ks), t, vec_splat(mi), vec_splat(tr));
        note(m, err_units(got.x, want, want), "B %a H %a Ks %a t %a M %a T %a", b, h, ks, t, mi, tr);
    }
}

static void run_shadow(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double a = g_uniform(&g), b = g_uniform(&g);
        REF want = (REF)a * b;
        if (want < DBL_MIN)
            continue;
        note(m, err_units(shade_shadow_transmission(a, b), want, want), "%a %a", a, b);
    }
}

/* ---- intersection ------------------------------------------------------ */

/* A ray for an intersection test: its origin at a scale 10^[-6, 6] away
 * from a target point, the direction through the point (unit to rounding). */
static ray make_ray(vec3 origin, vec3 through)
{
    ray r;
    r.origin = origin;
    r.dir = vec_normalize(vec_sub(through, origin));
    r.tmin = 0;
    r.tmax = HUGE_VAL;
    return r;
}

/* Sphere: random scenes at scales 1e-6 .. 1e6, small spheres far away and
 * huge ones close up, grazing rays.  Exact: the geometric test in REF. */
static void sphere_case(gen *g, long i, vec3 *c, double *radius, ray *r)
{
    double s = g_decade(g, -6, 6);
    *c = vec_scale(vec_make(g_range(g, -1, 1), g_range(g, -1, 1), g_range(g, -1, 1)), s * g_decade(g, 0, 3));
    *radius = s * g_range(g, 0.01, 1);
    double far = i % 3 == 0 ? g_decade(g, 1, 8) : g_range(g, 1.01, 10);   /* distance / radius */
    if (i % 3 == 1)
        far = 1 + g_decade(g, -8, -1);                                  /* just off the surface */
    vec3 dirc = g_unit(g), o = vec_madd(*c, dirc, *radius * far);
    /* aim at a point of the disk the sphere shows, grazing for i % 7 == 0 */
    vec3 side = vec_normalize(vec_cross(dirc, g_unit(g)));
    double off = i % 7 == 0 ? 1 - g_decade(g, -12, -2) : g_uniform(g) * 1.2;
    *r = make_ray(o, vec_madd(*c, side, *radius * off));
}

static int sphere_ref(vec3 c, double radius, const ray *r, REF *t, REF *margin)
{
    qv d = q_unit(q_of(r->dir)), f = q_sub(q_of(c), q_of(r->origin));
    REF tca = q_dot(f, d), l = q_len(q_sub(f, q_scale(d, tca)));
    *margin = REF_FABS(radius - l) / radius;
    *t = 0;
    if (l > radius)
        return 0;
    REF half = REF_SQRT((radius - l) * (radius + l));
    REF t0 = tca - half, t1 = tca + half, scale = q_len(q_of(r->dir));
    *t = (t0 > 0 ? t0 : t1) / scale;
    return t0 > 0 || t1 > 0;
}

static double sphere_surface_err(vec3 c, double radius, vec3 p)
{
    REF m = q_maxabs(q_of(c)) + radius;
    if (q_maxabs(q_of(p)) > m)
        m = q_maxabs(q_of(p));
    return (double)(REF_FABS(q_len(q_sub(q_of(p), q_of(c))) - radius) / (m * (REF)DBL_EPSILON));
}

static void run_sphere(long n, uint64_t seed, measure *m, int naive, int surface)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 c;
        double radius;
        ray r, rr;
        sphere_case(&g, i, &c, &radius, &r);
        rr = r;
        REF want, margin;
        int ref = sphere_ref(c, radius, &r, &want, &margin);
        hit h;
        real tn = 0;
        int got = naive ? naive_sphere(c, radius, &r, &tn) : isect_sphere(c, radius, &rr, &h);
        if (!naive && got)
            tn = h.t;
        /* |l|, the line's distance from the centre, is computed from
         * f = o - c: its error is about eps |f|, so the decision is certain
         * only for a margin (R - |l|)/R beyond a few eps |f|/R. */
        REF doubt = 16 * (REF)DBL_EPSILON * (q_len(q_sub(q_of(r.origin), q_of(c))) / radius + 1);
        if (got != ref) {
            m->wrong += margin > doubt;
            continue;
        }
        if (!got || margin < doubt || (!surface && margin < 1e-6))
            continue;   /* t itself: only away from grazing, where it is well-conditioned */
        /* t is measured against its own scale |t| + |o|: the origin's
         * coordinates carry eps |o| of their own. */
        double err = surface ? sphere_surface_err(c, radius, naive ? ray_at(&r, tn) : h.point)
                             : err_units(tn, want, REF_FABS(want) + q_maxabs(q_of(r.origin)));
        note(m, err, "C " V3F " R %a O " V3F " D " V3F, V3(c), radius, V3(r.origin), V3(r.dir));
    }
}

static void run_sphere_t(long n, uint64_t seed, measure *m) { run_sphere(n, seed, m, 0, 0); }
static void run_sphere_surface(long n, uint64_t seed, measure *m) { run_sphere(n, seed, m, 0, 1); }
static void run_sphere_naive_surface(long n, uint64_t seed, measure *m) { run_sphere(n, seed, m, 1, 1); }

/* Triangle: random triangles (some of aspect up to 1e8) at scales 1e-6 ..
 * 1e6, rays through a random point of them from up to 1e4 sizes away;
 * the reference solves the 3x3 system in REF. */
static void triangle_case(gen *g, long i, vec3 p[3], ray *r, double bary[3])
{
    double s = g_decade(g, -6, 6);
    vec3 c = vec_scale(vec_make(g_range(g, -1, 1), g_range(g, -1, 1), g_range(g, -1, 1)), s * g_decade(g, 0, 3));
    for (int k = 0; k < 3; k++)
        p[k] = vec_madd(c, g_unit(g), s);
    if (i % 4 == 0)   /* a sliver: the third corner near the first edge */
        p[2] = vec_madd(vec_scale(vec_add(p[0], p[1]), 0.5), g_unit(g), s * g_decade(g, -8, -3));
    double a = g_range(g, -0.1, 1.1), b = g_range(g, -0.1, 1.1);
    bary[1] = a;
    bary[2] = b;
    bary[0] = 1 - a - b;
    vec3 target = vec_add(vec_add(vec_scale(p[0], bary[0]), vec_scale(p[1], a)), vec_scale(p[2], b));
    *r = make_ray(vec_madd(target, g_unit(g), s * g_decade(g, -1, 4)), target);
}

static int triangle_ref(const vec3 p[3], const ray *r, REF *t, REF *margin, qv *point)
{
    qv o = q_of(r->origin), d = q_of(r->dir), a = q_of(p[0]);
    qv e1 = q_sub(q_of(p[1]), a), e2 = q_sub(q_of(p[2]), a), s = q_sub(o, a);
    qv pv = q_cross(d, e2), qq = q_cross(s, e1);
    REF det = q_dot(e1, pv);
    *margin = 0;
    *t = 0;
    if (det == 0)
        return 0;
    REF u = q_dot(s, pv) / det, v = q_dot(d, qq) / det, w = 1 - u - v;
    *t = q_dot(e2, qq) / det;
    *margin = u < v ? (u < w ? u : w) : (v < w ? v : w);
    *margin = REF_FABS(*margin);
    *point = q_add(o, q_scale(d, *t));
    return u >= 0 && v >= 0 && w >= 0 && *t > 0;
}

static void run_triangle(long n, uint64_t seed, measure *m, int slivers, int surface)
{
    gen g = {seed, 0};
    const int naive = 0;
    for (long i = 0; i < n; i++) {
        vec3 p[3];
        double bary[3];
        ray r, rr;
        triangle_case(&g, i, p, &r, bary);
        if (slivers >= 0 && (i % 4 == 0) != slivers)
            continue;
        rr = r;
        REF want, margin;
        qv wp;
        int ref = triangle_ref(p, &r, &want, &margin, &wp);
        hit h;
        real tn = 0;
        int got = naive ? naive_triangle(p, &r, &tn) : isect_triangle(p, NULL, &rr, &h);
        if (!naive && got)
            tn = h.t;
        /* The edge functions carry an absolute error of a few eps D^2, D
         * the vertices' distance from the origin, against their sum, twice
         * the projected area: the barycentric doubt is their ratio. */
        REF dd = 0, det = REF_FABS(q_dot(q_of(r.dir), q_cross(q_sub(q_of(p[1]), q_of(p[0])),
                                                               q_sub(q_of(p[2]), q_of(p[0])))));
        for (int k = 0; k < 3; k++) {
            REF dk = q_len(q_sub(q_of(p[k]), q_of(r.origin)));
            dd = dk > dd ? dk : dd;
        }
        REF cond = dd * dd / det, doubt = 16 * (REF)DBL_EPSILON * cond;
        if (got != ref) {
            m->wrong += margin > doubt;
            continue;
        }
        if (!got || margin < doubt)
            continue;
        double err;
        if (surface) {
            /* distance of the point from the triangle's plane, in eps of m */
            qv nq = q_unit(q_cross(q_sub(q_of(p[1]), q_of(p[0])), q_sub(q_of(p[2]), q_of(p[0]))));
            vec3 at = naive ? ray_at(&r, tn) : h.point;
            REF mag = q_maxabs(q_of(p[0]));
            for (int k = 1; k < 3; k++)
                mag = q_maxabs(q_of(p[k])) > mag ? q_maxabs(q_of(p[k])) : mag;
            err = (double)(REF_FABS(q_dot(nq, q_sub(q_of(at), q_of(p[0])))) / (mag * (REF)DBL_EPSILON));
        } else {
            err = err_units(tn, want, (REF_FABS(want) + q_maxabs(q_of(r.origin))) * cond);
        }
        note(m, err, "P " V3F " " V3F " " V3F " O " V3F " D " V3F, V3(p[0]), V3(p[1]), V3(p[2]), V3(r.origin),
             V3(r.dir));
    }
}

static void run_triangle_t(long n, uint64_t seed, measure *m) { run_triangle(n, seed, m, 0, 0); }
static void run_triangle_t_slivers(long n, uint64_t seed, measure *m) { run_triangle(n, seed, m, 1, 0); }
static void run_triangle_surface(long n, uint64_t seed, measure *m) { run_triangle(n, seed, m, 0, 1); }
static void run_triangle_surface_slivers(long n, uint64_t seed, measure *m) { run_triangle(n, seed, m, 1, 1); }

/* Plane and disk: grazing rays (to 1e-8 rad) and far origins. */
static void run_plane_disk(long n, uint64_t seed, measure *m, int disk)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double s = g_decade(&g, -6, 6), radius = s * g_range(&g, 0.1, 1);
        vec3 p0 = vec_scale(g_unit(&g), s * g_decade(&g, 0, 3)), nn = g_unit(&g);
        vec3 target = vec_madd(p0, vec_normalize(vec_cross(nn, g_unit(&g))), radius * g_range(&g, 0, 1.2));
        double a = i % 3 == 0 ? g_decade(&g, -8, -1) : g_range(&g, 0.05, 1.5707963);
        vec3 from = g_at_angle(&g, nn, 1.5707963267948966 - a);
        ray r = make_ray(vec_madd(target, from, s * g_decade(&g, -1, 4)), target), rr = r;
        qv qn = q_unit(q_of(nn)), o = q_of(r.origin), d = q_of(r.dir);
        REF want = q_dot(qn, q_sub(q_of(p0), o)) / q_dot(qn, d);
        qv wp = q_add(o, q_scale(d, want));
        REF rho = q_len(q_sub(wp, q_of(p0)));
        int ref = want > 0 && (!disk || rho <= radius);
        hit h;
        int got = disk ? isect_disk(p0, nn, radius, &rr, &h) : isect_plane(p0, nn, &rr, &h);
        /* the point o + t d is off by about eps |o| / |n.d| along the plane */
        REF doubt = 16 * (REF)DBL_EPSILON * (q_maxabs(o) + q_maxabs(q_of(p0))) / (radius * REF_FABS(q_dot(qn, d)));
        if (got != ref) {
            m->wrong += !disk || REF_FABS(rho - radius) / radius > doubt;
            continue;
        }
        if (!got)
            continue;
        REF mag = q_maxabs(q_of(p0)) > q_maxabs(q_of(h.point)) ? q_maxabs(q_of(p0)) : q_maxabs(q_of(h.point));
        REF off = REF_FABS(q_dot(qn, q_sub(q_of(h.point), q_of(p0))));
        note(m, (double)(off / (mag * (REF)DBL_EPSILON)), "P " V3F " N " V3F " O " V3F " D " V3F, V3(p0), V3(nn),
             V3(r.origin), V3(r.dir));
    }
}

static void run_plane(long n, uint64_t seed, measure *m) { run_plane_disk(n, seed, m, 0); }
static void run_disk(long n, uint64_t seed, measure *m) { run_plane_disk(n, seed, m, 1); }

/* Box: slabs in REF; the measure is t (faces are exact by construction). */
static void run_box(long n, uint64_t seed, measure *m)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        double s = g_decade(&g, -6, 6);
        vec3 c = vec_scale(g_unit(&g), s * g_decade(&g, 0, 3));
        vec3 e = vec_make(s * g_range(&g, 0.01, 1), s * g_range(&g, 0.01, 1), s * g_range(&g, 0.01, 1));
        vec3 lo = vec_sub(c, e), hi = vec_add(c, e);
        vec3 target = vec_add(c, vec_mul(e, vec_make(g_range(&g, -1.2, 1.2), g_range(&g, -1.2, 1.2),
                                                     g_range(&g, -1.2, 1.2))));
        ray r = make_ray(vec_madd(target, g_unit(&g), s * g_decade(&g, 0.5, 4)), target), rr = r;
        REF tn = -1e300, tf = 1e300, margin = 1e300;
        for (int k = 0; k < 3; k++) {
            REF o = vec_component(r.origin, k), d = vec_component(r.dir, k);
            REF a = (vec_component(lo, k) - o) / d, b = (vec_component(hi, k) - o) / d;
            if (a > b) {
                REF x = a;
                a = b;
                b = x;
            }
            tn = a > tn ? a : tn;
            tf = b < tf ? b : tf;
        }
        margin = (tf - tn) / (tf > 0 ? tf : 1);
        int ref = tn <= tf && tf > 0;
        hit h;
        int got = isect_box(lo, hi, &rr, &h);
        if (got != ref) {
            m->wrong += REF_FABS(margin) > 1e-9;
            continue;
        }
        if (!got || REF_FABS(margin) < 1e-9)
            continue;
        REF want = tn > 0 ? tn : tf;
        note(m, err_units(h.t, want, REF_FABS(want) + q_maxabs(q_of(r.origin))), "lo " V3F " hi " V3F " O " V3F " D " V3F, V3(lo), V3(hi),
             V3(r.origin), V3(r.dir));
    }
}

#include "measure_shapes.h"

/* ---- the table --------------------------------------------------------- */

/* Bounds are the measured worst over 10^6 inputs (make precision), rounded
 * up; spec/numerics.md has the figures and the inputs that give them.
 * The cylinder, cone and torus rows measure t against (|t| + |o|)/cos, cos
 * the crossing's cosine |n.d|: a ray nearly along the surface moves its t
 * by the point's error over that cosine, which no method avoids.  For
 * triangles D is the largest distance of a vertex from the ray's origin and
 * A the triangle's area projected across the ray: D^2/2A is the condition
 * of the barycentric weights (about the aspect ratio for a near origin).
 * Entries whose name starts with "before:" are the naive methods of
 * naive.h and refray's own earlier versions: no bound (0), not asserted. */
static const measure_fn measure_table[] = {
    {"shade_ambient", "eps of value", 0.5, run_ambient, 0},
    {"shade_falloff linear", "eps of value", 1, run_falloff_linear, 0},
    {"shade_falloff inverse_square", "eps of value", 2, run_falloff_square, 0},
    {"shade_sample_power", "eps of value", 0.5, run_sample_power, 0},
    {"shade_lambert", "eps (abs.)", 3, run_lambert, 0},
    {"shade_diffuse", "eps of Kd*I", 4, run_diffuse, 0},
    {"shade_reflect_about", "eps (abs.)", 4, run_reflect_about, 0},
    {"shade_mirror", "eps (abs.)", 4, run_mirror, 0},
    {"shade_phong_lobe", "eps of value", 1e4, run_phong_lobe, 0},
    {"shade_specular", "eps of value", 1e5, run_specular, 0},
    {"shade_refract", "eps max(1, n1/n2)", 4, run_refract_refray, 0},
    {"shade_critical_angle_cos", "eps of value", 1, run_critical, 0},
    {"shade_transmit_blend", "eps of value", 2, run_blend, 0},
    {"shade_combine", "eps of value", 3, run_combine, 0},
    {"shade_shadow_transmission", "eps of value", 0.5, run_shadow, 0},
    {"isect_sphere t", "eps of |t|+|o|", 500, run_sphere_t, 0},
    {"isect_sphere point", "eps of m off surface", 4, run_sphere_surface, 0},
    {"isect_triangle t", "eps of (|t|+|o|) D^2/2A", 2, run_triangle_t, 0},
    {"isect_triangle t, aspect to 1e8", "eps of (|t|+|o|) D^2/2A", 2, run_triangle_t_slivers, 0},
    {"isect_triangle point", "eps of m off plane", 4, run_triangle_surface, 0},
    {"isect_triangle point, aspect to 1e8", "eps of m off plane", 4, run_triangle_surface_slivers, 1},
    {"isect_plane point", "eps of m off plane", 2, run_plane, 0},
    {"isect_disk point", "eps of m off plane", 2, run_disk, 0},
    {"isect_box t", "eps of |t|+|o|", 2, run_box, 0},
    {"isect_cylinder point", "eps of m off surface", 4, run_cylinder_surface, 0},
    {"isect_cylinder t", "eps of (|t|+|o|)/cos", 16, run_cylinder_t, 0},
    {"isect_cone point", "eps of m off surface", 4, run_cone_surface, 0},
    {"isect_cone t", "eps of (|t|+|o|)/cos", 16, run_cone_t, 0},
    {"isect_torus point", "eps of m off surface", 4, run_torus_surface, 0},
    {"isect_torus t", "eps of (|t|+|o|)/cos", 8, run_torus_t, 0},
    {"before: phong pow(V.R, n)", "eps of value", 0, run_phong_pow_dot, 0},
    {"before: phong exp(n log V.R)", "eps of value", 0, run_phong_exp_log, 0},
    {"before: textbook refract", "eps max(1, n1/n2)", 0, run_refract_naive, 0},
    {"before: textbook sphere point", "eps of m off surface", 0, run_sphere_naive_surface, 0},
    {"before: textbook cylinder point", "eps of m off surface", 0, run_cylinder_naive, 0},
    {"before: unshifted torus quartic point", "eps of m off surface", 0, run_torus_naive, 0},
};

enum { MEASURE_COUNT = sizeof measure_table / sizeof measure_table[0] };

#endif
