/*
 * A run of triangle records tested in one call (isect_hot_triangle_run,
 * src/render/intersect.c) against the records tested one by one with the
 * single-record function the walks used before, isect_hot_nearest: the same
 * first crossed record and the same t, to the bit, for rays of each of the
 * six axis orders of the watertight test, rays exactly through shared edges
 * and vertices (where the tie rule decides, per the record's inclusive
 * edges), coplanar and repeated triangles (t ties: the first in the run
 * wins), intervals ending exactly at a crossing, and the walk's use of it:
 * going on after a crossing with tmax shrunk to it.
 */
#include <string.h>
#include "testlib.h"
#include "render/intersect.h"

enum { MAX_RECORDS = 96 };

typedef struct run_set {
    bvh_hot hot[MAX_RECORDS];
    real reals[MAX_RECORDS * ISECT_HOT_REALS];
    int n;
} run_set;

static double uniform(uint64_t seed, uint64_t *counter)
{
    return (double)(test_mix(seed * 0x100000000u + (*counter)++) >> 11) * 0x1p-53;
}

static int pick(uint64_t seed, uint64_t *counter, int n)
{
    return (int)(uniform(seed, counter) * n);
}

/* A record as isect_hot_make writes a triangle's (code: the kind and the
 * inclusive edges above it; the reals padded to 12). */
static void add(run_set *s, vec3 a, vec3 b, vec3 c, int inclusive)
{
    ck_assert_int_lt(s->n, MAX_RECORDS);
    real *g = s->reals + s->n * ISECT_HOT_REALS;
    vec3 v[3] = {a, b, c};
    for (int i = 0; i < 3; i++) {
        g[3 * i] = v[i].x;
        g[3 * i + 1] = v[i].y;
        g[3 * i + 2] = v[i].z;
    }
    g[9] = g[10] = g[11] = 0.0;
    s->hot[s->n].code = ISECT_HOT_TRIANGLE | inclusive << 2;
    s->hot[s->n].at = s->n * ISECT_HOT_REALS;
    s->n++;
}

/* The point (u, v) of a 4 x 4 grid of unit squares in the plane of
 * axis `normal` at height h. */
static vec3 grid_point(int normal, double h, double u, double v)
{
    return normal == 0 ? vec_make(h, u, v) : normal == 1 ? vec_make(v, h, u) : vec_make(u, v, h);
}

/* The records: in each coordinate plane a grid of squares, each cut into
 * two triangles along one of its diagonals, wound either way, with
 * inclusive edges of every kind (0: a closed mesh's inside, 7: a lone
 * triangle); a triangle over part of a grid in its plane (coplanar: the
 * same t as the grid's triangles there), some records repeated, and
 * random triangles; shuffled. */
static void make_records(run_set *s, uint64_t seed)
{
    uint64_t c = 0;
    s->n = 0;
    for (int normal = 0; normal < 3; normal++) {
        double h = normal - 1.0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                vec3 p00 = grid_point(normal, h, i, j), p10 = grid_point(normal, h, i + 1, j);
                vec3 p01 = grid_point(normal, h, i, j + 1), p11 = grid_point(normal, h, i + 1, j + 1);
                int flip = pick(seed, &c, 2), main_diagonal = pick(seed, &c, 2);
                vec3 a = main_diagonal ? p00 : p10, b = main_diagonal ? p11 : p01;
                vec3 c1 = main_diagonal ? p10 : p11, c2 = main_diagonal ? p01 : p00;
                add(s, a, flip ? c1 : b, flip ? b : c1, pick(seed, &c, 8));
                add(s, a, flip ? b : c2, flip ? c2 : b, pick(seed, &c, 8));
            }
        add(s, grid_point(normal, h, 0.5, 0.5), grid_point(normal, h, 2.5, 0.5), grid_point(normal, h, 0.5, 2.5),
            pick(seed, &c, 8));
    }
    for (int k = 0; k < 6; k++) {
        ck_assert_int_lt(s->n, MAX_RECORDS);
        s->hot[s->n] = s->hot[pick(seed, &c, s->n)];
        s->n++;
    }
    /* Records of other kinds, which end a run: a sphere's and a box's
     * (their reals are never read by the run). */
    for (int k = 0; k < 3; k++) {
        add(s, vec_make(0, 0, 0), vec_make(1, 0, 0), vec_make(0, 1, 0), 0);
        s->hot[s->n - 1].code = k % 2 ? ISECT_HOT_BOX : ISECT_HOT_SPHERE;
    }
    while (s->n < 75) {
        vec3 v[3];
        for (int i = 0; i < 3; i++)
            v[i] = vec_make(4 * uniform(seed, &c) - 1, 4 * uniform(seed, &c) - 1, 4 * uniform(seed, &c) - 1);
        add(s, v[0], v[1], v[2], pick(seed, &c, 8));
    }
    for (int i = s->n - 1; i > 0; i--) {
        int j = pick(seed, &c, i + 1);
        bvh_hot t = s->hot[i];
        s->hot[i] = s->hot[j];
        s->hot[j] = t;
    }
}

/* What the walks did per record: the first record of hot[first..] crossed,
 * by isect_hot_nearest of each in turn (and its count), up to the first of
 * another kind. */
static int run_by_each(const run_set *s, int first, int n, const ray *r, const isect_shear *sh, real *t)
{
    for (int i = first; i < first + n; i++) {
        if (ISECT_HOT_KIND(s->hot[i].code) != ISECT_HOT_TRIANGLE)
            return i - first;
        real ti;
        const real *g = s->reals + s->hot[i].at;
        int met = isect_hot_nearest(s->hot[i].code, g, r, sh, &ti);
        if (isect_hot_crossings(s->hot[i].code, g, r, sh) != met)
            ck_abort_msg("record %d: crossings %d, nearest %d", i, isect_hot_crossings(s->hot[i].code, g, r, sh), met);
        if (met) {
            *t = ti;
            return i - first;
        }
    }
    return n;
}

/* One run from first, and the reference, agree: the index, and the t to
 * the bit.  Returns the index. */
static int assert_run(const run_set *s, int first, int n, const ray *r, const isect_shear *sh)
{
    real t_run = -1.0, t_each = -2.0;
    int k_run = isect_hot_triangle_run(s->hot + first, n, s->reals, r, sh, &t_run);
    int k_each = run_by_each(s, first, n, r, sh, &t_each);
    /* Plain tests, ck_abort_msg on failure: in a forked suite each
     * ck_assert writes to a pipe, most of the run's time at this count. */
    if (k_run != k_each)
        ck_abort_msg("run from %d of %d: record %d, one by one %d (dir %a %a %a)", first, n, k_run, k_each,
                     (double)r->dir.x, (double)r->dir.y, (double)r->dir.z);
    if (k_run < n && ISECT_HOT_KIND(s->hot[first + k_run].code) == ISECT_HOT_TRIANGLE &&
        !same_real_bits(t_run, t_each))
        ck_abort_msg("t %La, one by one %La", (long double)t_run, (long double)t_each);
    return k_run;
}

/* The walks' use: a run over the whole set, going on after each crossing
 * from the next record, with tmax shrunk to the crossing (the nearest
 * walk) or not (the count walk). */
static int walk_runs(const run_set *s, ray r, int shrink, int start)
{
    isect_shear sh;
    isect_shear_make(&r, &sh);
    int found = 0;
    for (int i = start; i < s->n;) {
        int k = assert_run(s, i, s->n - i, &r, &sh);
        if (k == s->n - i)
            break;
        if (ISECT_HOT_KIND(s->hot[i + k].code) != ISECT_HOT_TRIANGLE) {
            i += k + 1;   /* the walk tests it by its own kind */
            continue;
        }
        found++;
        if (shrink) {
            real t;
            if (!isect_hot_nearest(s->hot[i + k].code, s->reals + s->hot[i + k].at, &r, &sh, &t))
                ck_abort_msg("record %d not crossed", i + k);
            r.tmax = t;
        }
        i += k + 1;
    }
    return found;
}

/* A direction of small integers, its largest component +-4 on axis kz:
 * the shear (its ratios over 4) and the sheared corners of the grids are
 * then exact, so a ray aimed at a grid's vertex or edge has edge functions
 * exactly 0 there. */
static vec3 direction(uint64_t seed, uint64_t *c, int kz, int negative)
{
    double d[3];
    for (int i = 0; i < 3; i++)
        d[i] = pick(seed, c, 7) - 3;
    d[kz] = negative ? -4 : 4;
    return vec_make(d[0], d[1], d[2]);
}

/* A target on the grids: a vertex, an edge's midpoint, a point of a
 * diagonal (on an edge where the square was cut along it), or anywhere
 * in a square (*kind 3). */
static vec3 target(uint64_t seed, uint64_t *c, int *kind_out)
{
    int normal = pick(seed, c, 3), kind = pick(seed, c, 4);
    *kind_out = kind;
    double u = pick(seed, c, 4), v = pick(seed, c, 4);
    if (kind == 1)
        u += 0.5;
    else if (kind == 2)
        u += 0.25, v += 0.25;
    else if (kind == 3)
        u += uniform(seed, c), v += uniform(seed, c);
    return grid_point(normal, normal - 1.0, u, v);
}

START_TEST(test_isect_hot_triangle_run_matches_each_triangle)
{
    run_set s;
    int orders[3][3] = {{0}}, seen_edge = 0, found = 0, ties = 0;
    uint64_t c = 0, seed = 16;
    for (int set = 0; set < 40; set++) {
        make_records(&s, seed + (uint64_t)set);
        for (int k = 0; k < 600; k++) {
            int kz = k % 3, negative = k / 3 % 2;
            ray r;
            r.dir = direction(seed, &c, kz, negative);
            int kind;
            vec3 at = target(seed, &c, &kind);
            /* From 1 to 3 steps back along the direction: the origin and
             * the corners' differences stay exact. */
            r.origin = vec_sub(at, vec_scale(r.dir, 1 + pick(seed, &c, 3)));
            r.tmin = 0.0;
            r.tmax = HUGE_VAL;
            isect_shear sh;
            isect_shear_make(&r, &sh);
            if (sh.kz != kz)
                ck_abort_msg("kz %d, not %d", sh.kz, kz);
            orders[sh.kz][sh.kx]++;
            seen_edge += kind < 3;
            found += walk_runs(&s, r, 0, 0);
            found += walk_runs(&s, r, 1, pick(seed, &c, 4));
            /* tmax exactly at the first crossing's t (open: not taken),
             * and an ulp past it (taken, and any tie with it). */
            real t;
            int start = pick(seed, &c, 4), first = start + run_by_each(&s, start, s.n - start, &r, &sh, &t);
            if (first < s.n && ISECT_HOT_KIND(s.hot[first].code) == ISECT_HOT_TRIANGLE) {
                int same = 0;
                for (int i = 0; i < s.n; i++) {
                    real ti;
                    same += ISECT_HOT_KIND(s.hot[i].code) == ISECT_HOT_TRIANGLE &&
                            isect_hot_nearest(s.hot[i].code, s.reals + s.hot[i].at, &r, &sh, &ti) && ti == t;
                }
                ties += same > 1;
                r.tmax = t;
                assert_run(&s, start, s.n - start, &r, &sh);
                r.tmax = nextafter(t, HUGE_VAL);
                assert_run(&s, start, s.n - start, &r, &sh);
                r.tmin = t;
                assert_run(&s, start, s.n - start, &r, &sh);
            }
        }
        /* Random rays, directions of every kind (zeros among them). */
        for (int k = 0; k < 300; k++) {
            ray r;
            double d[3];
            for (int i = 0; i < 3; i++)
                d[i] = pick(seed, &c, 5) == 0 ? 0.0 : 2 * uniform(seed, &c) - 1;
            r.dir = vec_make(d[0], d[1], d[2]);
            r.origin = vec_make(6 * uniform(seed, &c) - 2, 6 * uniform(seed, &c) - 2, 6 * uniform(seed, &c) - 2);
            r.tmin = pick(seed, &c, 2) ? 0.0 : uniform(seed, &c);
            r.tmax = pick(seed, &c, 2) ? HUGE_VAL : r.tmin + 4 * uniform(seed, &c);
            found += walk_runs(&s, r, pick(seed, &c, 2), 0);
        }
    }
    /* Every axis order was tried, rays went through edges, runs found
     * crossings, and some of them tied. */
    int kx_of[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    for (int kz = 0; kz < 3; kz++)
        for (int j = 0; j < 2; j++)
            ck_assert_msg(orders[kz][kx_of[kz][j]] > 0, "no ray with kz %d, kx %d", kz, kx_of[kz][j]);
    ck_assert_int_gt(seen_edge, 10000);
    ck_assert_int_gt(found, 50000);
    ck_assert_int_gt(ties, 3000);
}
END_TEST

/* From (0, 0, -1) along +z, over [0, +Inf). */
static ray up_the_z_axis(void)
{
    ray r;
    r.origin = vec_make(0, 0, -1);
    r.dir = vec_make(0, 0, 1);
    r.tmin = 0.0;
    r.tmax = HUGE_VAL;
    return r;
}

/* The run's quick miss (triangle_apart) at its edges, by hand: a ray along
 * +z from (0, 0, -1), the sheared corners the vertices' (x, y) exactly.
 * Corners on one side of x = 0 (or y = 0) strictly: no crossing; one of
 * them at 0 (the origin on a vertex or an edge): the inclusive edges
 * decide, crossed at t = 1 when the edges through it are inclusive, and
 * the same as the record tested alone (isect_hot_nearest). */
START_TEST(test_isect_hot_triangle_run_corners_on_the_ray)
{
    static const double tri[][6] = {
        {1, 0, 2, 0, 1, 1},     /* x > 0: apart */
        {-1, 1, -2, 0, -1, -1}, /* x < 0, wound the other way: apart */
        {-1, 1, 1, 1, 0, 2},    /* y > 0: apart */
        {0, 0, 1, 0, 0, 1},     /* a corner on the ray, the rest x, y >= 0 */
        {0, -1, 1, 0, 0, 1},    /* an edge on the ray (x = 0), the rest x > 0 */
        {0, -1, 0, 1, -1, 0},   /* the same, x < 0, wound the other way */
        {0, 1, -1, -1, 1, -1},  /* the ray inside, corners of both signs */
        {0x1p-40, 0, 1, 0, 0x1p-40, 1}, /* x > 0 by a hair: apart */
    };
    static const int crossed_with_all_inclusive[] = {0, 0, 0, 1, 1, 1, 1, 0};
    ray r = up_the_z_axis();
    isect_shear sh;
    isect_shear_make(&r, &sh);
    int crossed = 0;
    for (int k = 0; k < (int)(sizeof tri / sizeof tri[0]); k++) {
        for (int inclusive = 0; inclusive < 8; inclusive++) {
            run_set s;
            s.n = 0;
            const double *p = tri[k];
            add(&s, vec_make(p[0], p[1], 0), vec_make(p[2], p[3], 0), vec_make(p[4], p[5], 0), inclusive);
            real t = -1.0, ta;
            int in_run = isect_hot_triangle_run(s.hot, 1, s.reals, &r, &sh, &t) == 0;
            int alone = isect_hot_nearest(s.hot[0].code, s.reals, &r, &sh, &ta);
            ck_assert_msg(in_run == alone, "triangle %d, inclusive %d: run %d, alone %d", k, inclusive, in_run, alone);
            if (inclusive == 7)
                ck_assert_msg(in_run == crossed_with_all_inclusive[k], "triangle %d: crossed %d", k, in_run);
            if (in_run) {
                ck_assert(t == 1.0 && ta == 1.0);
                crossed++;
            }
        }
    }
    ck_assert_int_gt(crossed, 4);
}
END_TEST

/* The edges of the run: none to test, a zero direction (no record is
 * crossed), one record, a record of another kind ending it. */
START_TEST(test_isect_hot_triangle_run_empty_and_zero_direction)
{
    run_set s;
    s.n = 0;
    add(&s, vec_make(-1, -1, 0), vec_make(1, -1, 0), vec_make(0, 1, 0), 7);
    ray r = up_the_z_axis();
    isect_shear sh;
    isect_shear_make(&r, &sh);
    real t = -1.0;
    ck_assert_int_eq(isect_hot_triangle_run(s.hot, 0, s.reals, &r, &sh, &t), 0);
    ck_assert_int_eq(isect_hot_triangle_run(s.hot, 1, s.reals, &r, &sh, &t), 0);
    ck_assert(t == 1.0); /* from z = -1 along +z to the plane z = 0 */
    add(&s, vec_make(-1, -1, 1), vec_make(1, -1, 1), vec_make(0, 1, 1), 7);
    s.hot[1].code = ISECT_HOT_SPHERE;
    r.origin = vec_make(5, 0, -1);   /* misses the triangle */
    ck_assert_int_eq(isect_hot_triangle_run(s.hot, 2, s.reals, &r, &sh, &t), 1);
    ck_assert_int_eq(isect_hot_triangle_run(s.hot + 1, 1, s.reals, &r, &sh, &t), 0);
    r.dir = vec_make(0, 0, 0);
    isect_shear_make(&r, &sh);
    ck_assert_int_eq(isect_hot_triangle_run(s.hot, 1, s.reals, &r, &sh, &t), 1);
    ck_assert_int_eq(isect_hot_triangle_run(s.hot, 2, s.reals, &r, &sh, &t), 1);
}
END_TEST

Suite *suite_tri_run(void)
{
    Suite *s = suite_create("tri_run");
    TCase *tc = tcase_create("run");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, test_isect_hot_triangle_run_matches_each_triangle);
    tcase_add_test(tc, test_isect_hot_triangle_run_empty_and_zero_direction);
    tcase_add_test(tc, test_isect_hot_triangle_run_corners_on_the_ray);
    suite_add_tcase(s, tc);
    return s;
}
