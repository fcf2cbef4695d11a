/*
 * measure_shapes.h - the cylinder, cone and torus hit tests against REF
 * (spec/numerics.md, "Cylinders, cones and tori").  Included by measure.h
 * before its table, with its helpers in scope.
 *
 * The references are computed another way than refray computes them:
 *   - cylinder and cone: the side's quadratic formed and solved in REF from
 *     the ray as given (no perpendicular foot, no refinement), every cap
 *     and side crossing tested, the first in front kept;
 *   - torus: the quartic formed in REF about the line's nearest point to
 *     the centre, its real roots isolated by a Sturm sequence (exact root
 *     counts in an interval, up to REF's rounding) and bisected to REF's
 *     precision; no derivative cascade, no Newton step on the distance.
 * Each reference also says how far the ray is from a change of the answer
 * (a graze of the side or the tube, the rim of a cap), relative; a
 * disagreement closer to the boundary than the double input itself can
 * decide is not counted as wrong.
 */
#ifndef REFRAY_MEASURE_SHAPES_H
#define REFRAY_MEASURE_SHAPES_H

/* ---- cylinder and cone ------------------------------------------------- */

typedef struct qcone {
    qv from, a;          /* the end `from` and the unit axis */
    REF len, r0, r1, k;  /* length, radii at from and to, slope (r1 - r0)/len */
    int open;
} qcone;

static qcone qcone_of(vec3 from, vec3 to, double r0, double r1, int open)
{
    qcone c;
    qv w = q_sub(q_of(to), q_of(from));
    c.from = q_of(from);
    c.len = q_len(w);
    c.a = q_scale(w, 1 / c.len);
    c.r0 = r0;
    c.r1 = r1;
    c.k = (c.r1 - c.r0) / c.len;
    c.open = open;
    return c;
}

static REF qmin(REF a, REF b) { return a < b ? a : b; }
static REF qmax(REF a, REF b) { return a > b ? a : b; }

/* The first crossing of the line o + t d in front (t > tmin) in REF: 1
 * with *t, the cosine |n.d|/|d| and the outward unit normal there;
 * *margin the least relative distance of the ray from a graze of the side
 * or from a rim, over every crossing candidate. */
static int qcone_ref_q(const qcone *c, qv o, qv d, REF tmin, REF *t, REF *margin, REF *cosine, qv *normal)
{
    qv f = q_sub(o, c->from);
    REF z0 = q_dot(f, c->a), dz = q_dot(d, c->a), size = qmax(c->r0, c->r1);
    qv fp = q_sub(f, q_scale(c->a, z0)), dp = q_sub(d, q_scale(c->a, dz));
    REF rho0 = c->r0 + c->k * z0, sig = c->k * dz;
    REF A = q_dot(dp, dp) - sig * sig, B = q_dot(fp, dp) - rho0 * sig, C = q_dot(fp, fp) - rho0 * rho0;
    REF disc = B * B - A * C, best = 0, cand[4];
    int n = 0, found = 0;
    *margin = REF_FABS(disc) / (B * B + REF_FABS(A * C) + (REF)1e-300);
    if (A != 0 && disc >= 0) {
        cand[n++] = (-B - REF_SQRT(disc)) / A;
        cand[n++] = (-B + REF_SQRT(disc)) / A;
    } else if (A == 0 && B != 0) {
        cand[n++] = -C / (2 * B);
    }
    for (int i = 0; i < n; i++) {
        REF z = z0 + cand[i] * dz;
        *margin = qmin(*margin, qmin(REF_FABS(z), REF_FABS(c->len - z)) / c->len);
        if (z >= 0 && z <= c->len && cand[i] > tmin && (!found || cand[i] < best)) {
            best = cand[i];
            found = 1;
        }
    }
    for (int e = 0; e < 2 && !c->open && dz != 0; e++) {
        REF tt = ((e ? c->len : 0) - z0) / dz, rim = e ? c->r1 : c->r0;
        REF across = q_len(q_add(fp, q_scale(dp, tt)));
        *margin = qmin(*margin, REF_FABS(across - rim) / size);
        if (across <= rim && tt > tmin && (!found || tt < best)) {
            best = tt;
            found = 1;
        }
    }
    *t = best;
    *cosine = 1;
    if (found) {
        qv q = q_sub(q_add(o, q_scale(d, best)), c->from), e = q_unit(d);
        REF z = q_dot(q, c->a);
        qv across = q_sub(q, q_scale(c->a, z));
        int cap = !c->open && (REF_FABS(z) < 1e-20 * c->len || REF_FABS(z - c->len) < 1e-20 * c->len ||
                               z <= 0 || z >= c->len);
        *normal = cap ? q_scale(c->a, z < c->len / 2 ? -1 : 1) : q_unit(q_sub(q_unit(across), q_scale(c->a, c->k)));
        *cosine = REF_FABS(q_dot(*normal, e));
    }
    return found;
}

static int qcone_ref(const qcone *c, const ray *r, REF *t, REF *margin, REF *cosine)
{
    qv normal;
    return qcone_ref_q(c, q_of(r->origin), q_of(r->dir), r->tmin, t, margin, cosine, &normal);
}

/* The distance of p from the nearest of the side and the cap planes, in
 * eps of the magnitude of the shape and the point. */
static double qcone_surface_err(const qcone *c, vec3 p)
{
    qv q = q_sub(q_of(p), c->from);
    REF z = q_dot(q, c->a), across = q_len(q_sub(q, q_scale(c->a, z)));
    REF side = REF_FABS(across - (c->r0 + c->k * z)) / REF_SQRT(1 + c->k * c->k);
    REF cap = qmin(REF_FABS(z), REF_FABS(z - c->len));
    if (c->open)
        cap = side;
    REF m = qmax(q_maxabs(c->from), q_maxabs(q_add(c->from, q_scale(c->a, c->len)))) + qmax(c->r0, c->r1);
    m = qmax(m, q_maxabs(q_of(p)));
    return (double)(qmin(side, cap) / (m * (REF)DBL_EPSILON));
}

/* Cylinders (cone 0) and cones at scales 1e-6 .. 1e6 and 1e3 of their size
 * off the origin, open (every third) and closed, apexes (every fourth cone
 * has r1 = 0, every eighth r0 = 0), rays from 0.1 to 1e8 sizes away aimed
 * near the surface, grazing the side (every seventh) or running nearly
 * along the axis (every fifth, within 1e-8 .. 0.1 rad). */
static void cone_case(gen *g, long i, int cone, vec3 *from, vec3 *to, double *r0, double *r1, int *open, ray *r)
{
    double s = g_decade(g, -6, 6), len = s * g_range(g, 0.1, 2);
    vec3 c = vec_scale(vec_make(g_range(g, -1, 1), g_range(g, -1, 1), g_range(g, -1, 1)), s * g_decade(g, 0, 3));
    vec3 ax = g_unit(g);
    *from = vec_madd(c, ax, -0.5 * len);
    *to = vec_madd(c, ax, 0.5 * len);
    *r0 = s * g_range(g, 0.01, 1);
    *r1 = !cone ? *r0 : i % 4 == 0 ? 0 : s * g_range(g, 0, 1);
    if (cone && i % 8 == 1)
        *r0 = 0;
    *open = i % 3 == 0;
    double h = g_range(g, -0.1, 1.1), frac = i % 7 == 0 ? 1 - g_decade(g, -12, -2) : g_range(g, 0, 1.2);
    double rho = fmax(0.0, *r0 + (*r1 - *r0) * h);
    vec3 across = vec_normalize(vec_cross(ax, g_unit(g)));
    vec3 target = vec_madd(vec_madd(*from, ax, h * len), across, rho * frac);
    vec3 toward = i % 5 == 0 ? g_at_angle(g, g_uniform(g) < 0.5 ? ax : vec_neg(ax), g_decade(g, -8, -1)) : g_unit(g);
    double dist = s * (i % 3 == 1 ? g_decade(g, 1, 8) : g_decade(g, -1, 2));
    *r = make_ray(vec_madd(target, toward, dist), target);
}

/* what: 0 the hit point off the surface, 1 t, 2 the textbook cylinder's point. */
static void run_cone_like(long n, uint64_t seed, measure *m, int cone, int what)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 from, to;
        double r0, r1;
        int open;
        ray r, rr;
        cone_case(&g, i, cone, &from, &to, &r0, &r1, &open, &r);
        if (what == 2)
            open = 0;
        rr = r;
        qcone qc = qcone_of(from, to, r0, r1, open);
        REF want, margin, cosine;
        int ref = qcone_ref(&qc, &r, &want, &margin, &cosine);
        hit h;
        real tn = 0;
        int got = what == 2 ? naive_cylinder(from, to, r0, &r, &tn)
                  : cone  ? isect_cone(from, to, r0, r1, open, &rr, &h)
                          : isect_cylinder(from, to, r0, open, &rr, &h);
        if (what != 2 && got)
            tn = h.t;
        REF size = qmax(qc.r0, qc.r1) + qc.len;
        REF doubt = 16 * (REF)DBL_EPSILON * (q_len(q_sub(q_of(r.origin), qc.from)) / size + 1);
        /* A disagreement on which crossing comes first is a wrong decision
         * too; t itself is uncertain by the ray's error over the cosine. */
        REF slack = 1e-6 * (REF_FABS(want) + size) +
                    1e3 * (REF)DBL_EPSILON * (REF_FABS(want) + q_maxabs(q_of(r.origin))) / cosine;
        int same = got == ref && (!got || REF_FABS(tn - want) <= slack);
        if (!same) {
            m->wrong += margin > doubt;
            if (margin > doubt && what != 2 && getenv("MEASURE_DEBUG"))
                fprintf(stderr, "wrong: got %d ref %d t %.17g want %.17g margin %g doubt %g A " V3F " B " V3F
                        " R %a %a%s O " V3F " D " V3F "\n", got, ref, (double)tn, (double)want, (double)margin,
                        (double)doubt, V3(from), V3(to), r0, r1, open ? " open" : "", V3(r.origin), V3(r.dir));
            continue;
        }
        if (!got || margin < doubt || (what == 1 && margin < 1e-6))
            continue;
        /* t moves by the point's error over the crossing's cosine */
        double err = what == 1 ? err_units(tn, want, (REF_FABS(want) + q_maxabs(q_of(r.origin))) / cosine)
                               : qcone_surface_err(&qc, what == 2 ? ray_at(&r, tn) : h.point);
        note(m, err, "A " V3F " B " V3F " R %a %a%s O " V3F " D " V3F, V3(from), V3(to), r0, r1,
             open ? " open" : "", V3(r.origin), V3(r.dir));
    }
}

static void run_cylinder_surface(long n, uint64_t seed, measure *m) { run_cone_like(n, seed, m, 0, 0); }
static void run_cylinder_t(long n, uint64_t seed, measure *m) { run_cone_like(n, seed, m, 0, 1); }
static void run_cylinder_naive(long n, uint64_t seed, measure *m) { run_cone_like(n, seed, m, 0, 2); }
static void run_cone_surface(long n, uint64_t seed, measure *m) { run_cone_like(n, seed, m, 1, 0); }
static void run_cone_t(long n, uint64_t seed, measure *m) { run_cone_like(n, seed, m, 1, 1); }

/* ---- torus ------------------------------------------------------------- */

typedef struct qtorus {
    qv c, a;
    REF major, minor;
} qtorus;

static qtorus qtorus_of(vec3 c, vec3 a, double major, double minor)
{
    qtorus t = {q_of(c), q_unit(q_of(a)), major, minor};
    return t;
}

/* The distance of p from the core circle, and the unit normal there. */
static REF qtorus_distance(const qtorus *tr, qv p, qv *normal)
{
    qv q = q_sub(p, tr->c);
    REF z = q_dot(q, tr->a);
    qv across = q_sub(q, q_scale(tr->a, z));
    REF rho = q_len(across), dr = rho - tr->major, dist = REF_SQRT(dr * dr + z * z);
    if (normal)
        *normal = q_add(q_scale(across, dr / (dist * rho)), q_scale(tr->a, z / dist));
    return dist;
}

static REF qpoly(const REF *p, int deg, REF u)
{
    REF v = p[deg];
    for (int i = deg - 1; i >= 0; i--)
        v = v * u + p[i];
    return v;
}

/* A Sturm sequence: p, p', then the negated remainders. */
typedef struct qsturm {
    REF c[5][5];
    int deg[5];
    int count;
} qsturm;

static void qsturm_make(const REF *p, int deg, qsturm *s)
{
    REF big = 0;
    for (int i = 0; i <= deg; i++) {
        s->c[0][i] = p[i];
        big = qmax(big, REF_FABS(p[i]));
    }
    s->deg[0] = deg;
    for (int i = 1; i <= deg; i++)
        s->c[1][i - 1] = i * p[i];
    s->deg[1] = deg - 1;
    s->count = 2;
    while (s->count < 5 && s->deg[s->count - 1] > 0) {
        const REF *a = s->c[s->count - 2], *b = s->c[s->count - 1];
        int da = s->deg[s->count - 2], db = s->deg[s->count - 1];
        REF rem[5];
        for (int i = 0; i <= da; i++)
            rem[i] = a[i];
        for (int i = da - db; i >= 0; i--) {
            REF q = rem[db + i] / b[db];
            for (int j = 0; j <= db; j++)
                rem[i + j] -= q * b[j];
        }
        int dr = db - 1;
        while (dr >= 0 && REF_FABS(rem[dr]) <= 1e-28 * big)
            dr--;
        if (dr < 0)
            break;
        for (int i = 0; i <= dr; i++)
            s->c[s->count][i] = -rem[i];
        s->deg[s->count++] = dr;
    }
}

static int qsturm_changes(const qsturm *s, REF u)
{
    int changes = 0, last = 0;
    for (int k = 0; k < s->count; k++) {
        REF v = qpoly(s->c[k], s->deg[k], u);
        int sign = v > 0 ? 1 : v < 0 ? -1 : 0;
        if (sign != 0 && last != 0 && sign != last)
            changes++;
        if (sign != 0)
            last = sign;
    }
    return changes;
}

/* The roots of s's polynomial in (lo, hi], by counting and bisecting. */
static void qsturm_roots(const qsturm *s, REF lo, REF hi, int vlo, int vhi, REF *roots, int *count, int depth)
{
    int inside = vlo - vhi;
    if (inside <= 0 || *count >= 4)
        return;
    const REF *p = s->c[0];
    int deg = s->deg[0];
    if (inside == 1 && (qpoly(p, deg, lo) < 0) != (qpoly(p, deg, hi) < 0)) {
        REF a = lo, b = hi, fa = qpoly(p, deg, a);
        for (int i = 0; i < 200 && b - a > 0; i++) {
            REF mid = (a + b) / 2, fm = qpoly(p, deg, mid);
            if (mid == a || mid == b)
                break;
            if ((fm < 0) == (fa < 0))
                a = mid;
            else
                b = mid;
        }
        roots[(*count)++] = (a + b) / 2;
        return;
    }
    if (depth > 200 || hi - lo <= REF_EPSILON * (REF_FABS(lo) + REF_FABS(hi))) {
        roots[(*count)++] = (lo + hi) / 2;
        return;
    }
    REF mid = (lo + hi) / 2;
    int vmid = qsturm_changes(s, mid);
    qsturm_roots(s, lo, mid, vlo, vmid, roots, count, depth + 1);
    qsturm_roots(s, mid, hi, vmid, vhi, roots, count, depth + 1);
}

static int qsturm_solve(const REF *p, int deg, REF lo, REF hi, REF *roots)
{
    qsturm s;
    int count = 0;
    qsturm_make(p, deg, &s);
    qsturm_roots(&s, lo, hi, qsturm_changes(&s, lo), qsturm_changes(&s, hi), roots, &count, 0);
    return count;
}

/* The first crossing in front in REF: 1 with *t, its cosine and normal;
 * *margin the least of the crossings' cosines |n.e| and of the near
 * misses' clearance (the distance from the tube at a minimum of the
 * quartic that stays positive, over minor). */
static int qtorus_ref_q(const qtorus *tr, qv o, qv d, REF tmin, REF *t, REF *margin, REF *cosine, qv *hit_normal)
{
    qv e = q_unit(d), f = q_sub(o, tr->c);
    REF dl = q_len(d), L = tr->major + tr->minor;
    REF along = -q_dot(f, e), off = q_len(q_add(f, q_scale(e, along)));
    *margin = REF_FABS(off - L) / L;
    *t = 0;
    *cosine = 1;
    if (off >= L)
        return 0;
    REF half = REF_SQRT((L - off) * (L + off)) / L;
    qv p0 = q_scale(q_add(f, q_scale(e, along)), 1 / L);
    REF big = tr->major / L, small = tr->minor / L;
    REF z0 = q_dot(p0, tr->a), ez = q_dot(e, tr->a);
    qv p0x = q_sub(p0, q_scale(tr->a, z0)), ex = q_sub(e, q_scale(tr->a, ez));
    REF alpha = q_dot(p0, e), beta = q_dot(p0, p0) + big * big - small * small, c[5], dc[4], u[4], w[4];
    c[4] = 1;
    c[3] = 4 * alpha;
    c[2] = 4 * alpha * alpha + 2 * beta - 4 * big * big * q_dot(ex, ex);
    c[1] = 4 * alpha * beta - 8 * big * big * q_dot(p0x, ex);
    c[0] = beta * beta - 4 * big * big * q_dot(p0x, p0x);
    for (int i = 1; i <= 4; i++)
        dc[i - 1] = i * c[i];
    int n = qsturm_solve(c, 4, -half, half, u), nc = qsturm_solve(dc, 3, -half, half, w), found = 0;
    for (int i = 0; i < nc; i++)
        if (qpoly(c, 4, w[i]) > 0) {
            qv at = q_add(o, q_scale(e, (along + w[i] * L)));
            *margin = qmin(*margin, (qtorus_distance(tr, at, NULL) - tr->minor) / tr->minor);
        }
    for (int i = 0; i < n; i++) {
        REF ti = (along + u[i] * L) / dl;
        qv normal;
        qtorus_distance(tr, q_add(o, q_scale(d, ti)), &normal);
        *margin = qmin(*margin, REF_FABS(q_dot(normal, e)));
        if (!found && ti > tmin) {
            *t = ti;
            *cosine = REF_FABS(q_dot(normal, e));
            *hit_normal = normal;
            found = 1;
        }
    }
    return found;
}

static int qtorus_ref(const qtorus *tr, const ray *r, REF *t, REF *margin, REF *cosine)
{
    qv normal;
    return qtorus_ref_q(tr, q_of(r->origin), q_of(r->dir), r->tmin, t, margin, cosine, &normal);
}

static double qtorus_surface_err(const qtorus *tr, vec3 p)
{
    REF m = qmax(q_maxabs(tr->c) + tr->major + tr->minor, q_maxabs(q_of(p)));
    return (double)(REF_FABS(qtorus_distance(tr, q_of(p), NULL) - tr->minor) / (m * (REF)DBL_EPSILON));
}

/* Tori at scales 1e-6 .. 1e6 with minor/major from 1e-3 (thin) to 0.9,
 * centres up to 1e3 of their size off the origin (every ninth up to 1e6:
 * a thin torus far away), rays aimed near the tube from 0.3 to 1e8 sizes
 * away: grazing the tube (every seventh), edge-on (every fifth: across the
 * axis), from inside the hole (every eleventh: the origin near the centre). */
static void torus_case(gen *g, long i, vec3 *c, vec3 *ax, double *major, double *minor, ray *r)
{
    double s = g_decade(g, -6, 6);
    *c = vec_scale(vec_make(g_range(g, -1, 1), g_range(g, -1, 1), g_range(g, -1, 1)),
                   s * (i % 9 == 0 ? g_decade(g, 3, 6) : g_decade(g, 0, 3)));
    *ax = g_unit(g);
    *major = s;
    *minor = s * (i % 4 == 0 ? g_decade(g, -3, -1) : g_range(g, 0.05, 0.9));
    vec3 u = vec_normalize(vec_cross(*ax, g_unit(g))), v = vec_cross(*ax, u);
    double theta = g_range(g, 0, 6.283185307179586), phi = g_range(g, 0, 6.283185307179586);
    double frac = i % 7 == 0 ? 1 - g_decade(g, -12, -2) : g_range(g, 0, 1.2);
    vec3 radial = vec_add(vec_scale(u, cos(theta)), vec_scale(v, sin(theta)));
    vec3 target = vec_madd(*c, radial, *major);
    target = vec_madd(target, vec_add(vec_scale(radial, cos(phi)), vec_scale(*ax, sin(phi))), *minor * frac);
    if (i % 11 == 0) {
        *r = make_ray(vec_madd(*c, *ax, g_range(g, -0.5, 0.5) * *minor), target);
        return;
    }
    vec3 toward = i % 5 == 0 ? vec_normalize(vec_cross(*ax, g_unit(g))) : g_unit(g);
    double dist = s * (i % 3 == 0 ? g_decade(g, 1, 8) : g_decade(g, -0.5, 1.5));
    *r = make_ray(vec_madd(target, toward, dist), target);
}

/* what: 0 the hit point off the surface, 1 t, 2 the naive quartic's point. */
static void run_torus(long n, uint64_t seed, measure *m, int what)
{
    gen g = {seed, 0};
    for (long i = 0; i < n; i++) {
        vec3 c, ax;
        double major, minor;
        ray r, rr;
        torus_case(&g, i, &c, &ax, &major, &minor, &r);
        rr = r;
        qtorus qt = qtorus_of(c, ax, major, minor);
        REF want, margin, cosine;
        int ref = qtorus_ref(&qt, &r, &want, &margin, &cosine);
        hit h;
        real tn = 0;
        int got = what == 2 ? naive_torus(c, ax, major, minor, &r, &tn) : isect_torus(c, ax, major, minor, &rr, &h);
        if (what != 2 && got)
            tn = h.t;
        /* the ray's own position is uncertain by eps |o - c|: relative to the tube */
        REF doubt = 16 * (REF)DBL_EPSILON * (q_len(q_sub(q_of(r.origin), qt.c)) / qt.minor + qt.major / qt.minor);
        REF slack = 1e-6 * (REF_FABS(want) + qt.major) +
                    1e3 * (REF)DBL_EPSILON * (REF_FABS(want) + q_maxabs(q_of(r.origin))) / cosine;
        int same = got == ref && (!got || REF_FABS(tn - want) <= slack);
        if (!same) {
            m->wrong += margin > doubt;
            if (margin > doubt && what != 2 && getenv("MEASURE_DEBUG"))
                fprintf(stderr, "wrong torus: got %d ref %d t %.17g want %.17g margin %g doubt %g C " V3F " A " V3F
                        " R %a r %a O " V3F " D " V3F "\n", got, ref, (double)tn, (double)want, (double)margin,
                        (double)doubt, V3(c), V3(ax), major, minor, V3(r.origin), V3(r.dir));
            continue;
        }
        if (!got || margin < doubt || (what == 1 && margin < 1e-6))
            continue;
        double err = what == 1 ? err_units(tn, want, (REF_FABS(want) + q_maxabs(q_of(r.origin))) / cosine)
                               : qtorus_surface_err(&qt, what == 2 ? ray_at(&r, tn) : h.point);
        note(m, err, "C " V3F " A " V3F " R %a r %a O " V3F " D " V3F, V3(c), V3(ax), major, minor, V3(r.origin),
             V3(r.dir));
    }
}

static void run_torus_surface(long n, uint64_t seed, measure *m) { run_torus(n, seed, m, 0); }
static void run_torus_t(long n, uint64_t seed, measure *m) { run_torus(n, seed, m, 1); }
static void run_torus_naive(long n, uint64_t seed, measure *m) { run_torus(n, seed, m, 2); }

#endif
