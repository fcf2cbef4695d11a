/* Tests of src/render/bvh.c.  The reference for every query is brute force:
 * isect_prim over all primitives, each alone, then bvh.h's tie rule: the
 * lowest index among the hits within 2^-46 (|t| + |origin|) of the least t. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "render/bvh.h"
#include "render/bvh_beam.h"
#include "render/slab.h"
#include "render/slab_pair.h"
#include "base/xform.h"

/* Counter-based generator: splitmix64's finaliser of seed and counter. */
typedef struct rng {
    uint64_t seed, counter;
} rng;

static double rng_uniform(rng *g)
{
    uint64_t z = g->seed * 0x9E3779B97F4A7C15u + (g->counter++ + 1) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}

static double rng_range(rng *g, double lo, double hi) { return lo + (hi - lo) * rng_uniform(g); }

static vec3 rng_box(rng *g, double lo, double hi)
{
    double x = rng_range(g, lo, hi), y = rng_range(g, lo, hi);
    return vec_make(x, y, rng_range(g, lo, hi));
}

static vec3 rng_unit(rng *g)
{
    for (;;) {
        vec3 v = rng_box(g, -1, 1);
        double l2 = vec_length2(v);
        if (l2 > 0.01 && l2 <= 1.0)
            return vec_normalize(v);
    }
}

static scene_prim prim_blank(scene_prim_kind kind)
{
    scene_prim p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    p.mesh = -1;
    return p;
}

static scene_prim prim_sphere(vec3 c, double radius)
{
    scene_prim p = prim_blank(PRIM_SPHERE);
    p.u.sphere.center = c;
    p.u.sphere.radius = radius;
    return p;
}

/* One random primitive near c of size about s; kind chosen by k; a local
 * frame goes to *frame. */
static scene_prim random_prim(rng *g, int k, vec3 c, double s, scene_frame *frame)
{
    scene_prim p;
    switch (k % 7) {
    case 0:
    case 1:
        return prim_sphere(c, s * rng_range(g, 0.2, 1));
    case 2:
    case 3:
        p = prim_blank(PRIM_TRIANGLE);
        for (int i = 0; i < 3; i++)
            p.u.triangle.p[i] = vec_add(c, vec_scale(rng_unit(g), s));
        return p;
    case 4:
        p = prim_blank(PRIM_BOX);
        p.u.box.lo = c;
        p.u.box.hi = vec_add(c, rng_box(g, 0.1 * s, s));
        return p;
    case 5:
        p = prim_blank(PRIM_DISK);
        p.u.disk.center = c;
        p.u.disk.normal = rng_unit(g);
        p.u.disk.radius = s * rng_range(g, 0.2, 1);
        return p;
    default: {
        /* An ellipsoid or a turned box in a local frame. */
        p = rng_uniform(g) < 0.5 ? prim_sphere(vec_make(0, 0, 0), 1) : prim_blank(PRIM_BOX);
        if (p.kind == PRIM_BOX) {
            p.u.box.lo = vec_make(-1, -1, -1);
            p.u.box.hi = vec_make(1, 1, 1);
        }
        xform sc = xform_scale(vec_scale(rng_box(g, 0.2, 1), s));
        xform rot = xform_rotate_xyz(rng_box(g, 0, 360)), mv = xform_translate(c);
        xform rs = xform_compose(&rot, &sc);
        frame->to_world = xform_compose(&mv, &rs);
        ck_assert(xform_invert(&frame->to_world, &frame->to_local));
        p.frame = frame;
        return p;
    }
    }
}

/* count primitives in [0,10]^3 plus two planes at the end; their local
 * frames in *frames (to be freed with them), which has one spare entry at
 * count. */
static scene_prim *random_scene(uint64_t seed, int count, int planes, scene_frame **frames)
{
    rng g = {seed, 0};
    scene_prim *prims = calloc((size_t)count + 2, sizeof *prims);
    *frames = calloc((size_t)count + 1, sizeof **frames);
    ck_assert_ptr_nonnull(prims);
    ck_assert_ptr_nonnull(*frames);
    for (int i = 0; i < count; i++)
        prims[i] = random_prim(&g, (int)(rng_uniform(&g) * 7), rng_box(&g, 0, 10), 0.6, &(*frames)[i]);
    /* Every tenth is a copy of a recent one: exact ties in t, which must go
     * to the lower index whatever order the tree visits them in. */
    for (int i = 9; i < count; i += 10)
        prims[i] = prims[i - 1 - (i / 10) % 5];
    for (int i = 0; i < planes; i++) {
        prims[count + i] = prim_blank(PRIM_PLANE);
        prims[count + i].u.plane.point = vec_make(0, i == 0 ? -1 : 11, 0);
        prims[count + i].u.plane.normal = vec_normalize(vec_make(0.1 * i, 1, 0.05));
    }
    return prims;
}

/* Rays of several sorts: general, axis-parallel, starting on a box face or
 * inside things, with narrowed intervals. */
static ray random_ray(rng *g, const scene_prim *prims, int count, int i)
{
    ray r;
    r.origin = rng_box(g, -2, 12);
    r.dir = rng_unit(g);
    r.tmin = 0.0;
    r.tmax = HUGE_VAL;
    if (i % 5 == 1) {
        int axis = (int)(rng_uniform(g) * 3);
        r.dir = vec_make(axis == 0, axis == 1, axis == 2);
        if (rng_uniform(g) < 0.5)
            r.dir = vec_neg(r.dir);
    }
    if (i % 7 == 2 && count > 0) {
        const scene_prim *p = &prims[(int)(rng_uniform(g) * count)];
        vec3 lo, hi;
        if (isect_prim_bounds(p, &lo, &hi))
            r.origin = vec_make(lo.x, r.origin.y, hi.z); /* on two slab planes of its box */
    }
    if (i % 13 == 4 && count > 0) {
        /* Aimed at a vertex, a box corner or a sphere's extreme point: hits
         * that lie exactly on the primitive's bounding box. */
        const scene_prim *p = &prims[(int)(rng_uniform(g) * count)];
        vec3 aim = r.origin;
        if (p->kind == PRIM_TRIANGLE)
            aim = p->u.triangle.p[(int)(rng_uniform(g) * 3)];
        else if (p->kind == PRIM_BOX && !p->frame)
            aim = p->u.box.hi;
        else if (p->kind == PRIM_SPHERE && !p->frame)
            aim = vec_add(p->u.sphere.center, vec_make(0, p->u.sphere.radius, 0));
        if (vec_length2(vec_sub(aim, r.origin)) > 0)
            r.dir = vec_normalize(vec_sub(aim, r.origin));
    }
    if (i % 11 == 3) {
        r.tmin = rng_range(g, 0, 5);
        r.tmax = r.tmin + rng_range(g, 0, 8);
    }
    return r;
}

static int brute_nearest(const scene_prim *prims, int count, ray *r, hit *h)
{
    real least = HUGE_VAL;
    hit hi;
    for (int i = 0; i < count; i++) {
        ray ri = *r;
        if (isect_prim(&prims[i], &ri, &hi) && hi.t < least)
            least = hi.t;
    }
    if (least == HUGE_VAL)
        return 0;
    real o = fmax(fabs(r->origin.x), fmax(fabs(r->origin.y), fabs(r->origin.z)));
    real limit = fmax(least + 0x1p-46 * (fabs(least) + o), nextafter(least, (real)INFINITY));
    for (int i = 0; i < count; i++) {
        ray ri = *r;
        if (isect_prim(&prims[i], &ri, &hi) && hi.t <= limit) {
            *h = hi;
            h->prim = i;
            r->tmax = hi.t;
            return 1;
        }
    }
    return 0;
}

/* Returns how many of the rays hit something. */
static int check_nearest_agrees(const bvh *b, const scene_prim *prims, int count, uint64_t seed,
                                int rays)
{
    rng g = {seed, 0};
    int hits = 0;
    for (int i = 0; i < rays; i++) {
        ray r = random_ray(&g, prims, count, i), rb = r;
        hit h, hb;
        int f = bvh_intersect(b, prims, &r, &h);
        int fb = brute_nearest(prims, count, &rb, &hb);
        ck_assert_int_eq(f, fb);
        if (!f)
            continue;
        hits++;
        ck_assert_int_eq(h.prim, hb.prim);
        ck_assert_msg(h.t == hb.t, "ray %d: t %.17g vs %.17g", i, (double)h.t, (double)hb.t);
        ck_assert(r.tmax == rb.tmax);
        ck_assert(same_vec_bits(h.point, hb.point));
        ck_assert(same_vec_bits(h.normal, hb.normal) && same_vec_bits(h.shading_normal, hb.shading_normal));
        ck_assert_int_eq(h.entering, hb.entering);
    }
    return hits;
}

typedef struct crossing {
    int prim;
    double t;
} crossing;

typedef struct crossing_list {
    crossing c[256];
    int n;
} crossing_list;

static int collect(void *ctx, const hit *h)
{
    crossing_list *l = ctx;
    ck_assert_int_lt(l->n, 256);
    l->c[l->n].prim = h->prim;
    l->c[l->n++].t = h->t;
    return 0;
}

static int compare_crossings(const void *pa, const void *pb)
{
    const crossing *a = pa, *b = pb;
    if (a->prim != b->prim)
        return a->prim < b->prim ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

static void brute_all(const scene_prim *prims, int count, const ray *r, crossing_list *l)
{
    for (int i = 0; i < count; i++) {
        hit out[ISECT_MAX_CROSSINGS];
        int n = isect_prim_all(&prims[i], r, out);
        for (int k = 0; k < n; k++) {
            out[k].prim = i;
            collect(l, &out[k]);
        }
    }
}

START_TEST(test_bvh_intersect_matches_brute_force)
{
    static const int sizes[] = {1, 2, 3, 7, 40, 500, 3000};
    for (int s = 0; s < 7; s++) {
        int n = sizes[s];
        scene_frame *frames;
        scene_prim *prims = random_scene(100 + (uint64_t)s, n, 2, &frames);
        bvh b;
        ck_assert(bvh_build(&b, prims, n + 2, NULL));
        ck_assert_int_eq(b.unbounded_count, 2);
        int hits = check_nearest_agrees(&b, prims, n + 2, 200 + (uint64_t)s, 3000);
        /* The planes alone catch some rays; the rest must be tested too. */
        ck_assert_msg(hits > 600, "too few hits (%d) for the test to mean much", hits);
        bvh_free(&b);
        free(prims);
        free(frames);
    }
}
END_TEST

START_TEST(test_bvh_visit_matches_brute_force)
{
    int n = 2000;
    scene_frame *frames;
    scene_prim *prims = random_scene(300, n, 2, &frames);
    bvh b;
    ck_assert(bvh_build(&b, prims, n + 2, NULL));
    rng g = {301, 0};
    long total = 0, solids_twice = 0;
    for (int i = 0; i < 3000; i++) {
        ray r = random_ray(&g, prims, n + 2, i);
        crossing_list got = {{{0, 0}}, 0}, want = {{{0, 0}}, 0};
        ck_assert_int_eq(bvh_visit(&b, prims, &r, collect, &got), 0);
        brute_all(prims, n + 2, &r, &want);
        ck_assert_int_eq(got.n, want.n);
        qsort(got.c, (size_t)got.n, sizeof got.c[0], compare_crossings);
        qsort(want.c, (size_t)want.n, sizeof want.c[0], compare_crossings);
        for (int k = 0; k < got.n; k++) {
            ck_assert_int_eq(got.c[k].prim, want.c[k].prim);
            ck_assert(got.c[k].t == want.c[k].t);
            solids_twice += k > 0 && got.c[k].prim == got.c[k - 1].prim;
        }
        total += got.n;
    }
    ck_assert_msg(total > 3000, "only %ld crossings", total);
    ck_assert_msg(solids_twice > 100, "solids crossed twice only %ld times", solids_twice);
    bvh_free(&b);
    free(prims);
    free(frames);
}
END_TEST

typedef struct count_list {
    int per_prim[2100];
    long calls;
} count_list;

static int count_into(void *ctx, bvh_ref ref, int crossings)
{
    count_list *l = ctx;
    ck_assert_int_gt(crossings, 0);
    l->per_prim[ref.prim] += crossings;
    l->calls++;
    return 0;
}

/* The count walk (bvh_visit_counts: the shadow rays') gives every part the
 * number of crossings isect_prim_all finds, the two planes (unbounded,
 * counted by isect_plane_crossings at once) and a third plane moved by a
 * transform (counted through its local frame) included. */
START_TEST(test_bvh_visit_counts_match_brute_force)
{
    int n = 2000;
    scene_frame *frames;
    scene_prim *prims = random_scene(310, n, 2, &frames);
    prims = realloc(prims, (size_t)(n + 3) * sizeof *prims);
    ck_assert_ptr_nonnull(prims);
    prims[n + 2] = prims[n];
    frames[n].to_world = xform_translate(vec_make(0, 4, 0));
    ck_assert(xform_invert(&frames[n].to_world, &frames[n].to_local));
    prims[n + 2].frame = &frames[n];
    bvh b;
    ck_assert(bvh_build(&b, prims, n + 3, NULL));
    ck_assert_int_eq(b.unbounded_count, 3);
    rng g = {311, 0};
    long planes = 0;
    for (int i = 0; i < 3000; i++) {
        ray r = random_ray(&g, prims, n + 3, i);
        if (i % 2)
            r.tmax = 0.5 + 20 * rng_uniform(&g);
        static count_list got;
        memset(&got, 0, sizeof got);
        bvh_stats st = {0, 0};
        bvh_visit_counts(&b, prims, &r, count_into, &got, &st);
        /* One assertion per ray, not per part: under Check's fork mode a
         * passed assertion is a message to the parent, and 6 M of them took
         * 21 s of this test at load 13. */
        int wrong = -1, wrong_want = 0;
        for (int k = 0; k < n + 3; k++) {
            hit out[ISECT_MAX_CROSSINGS];
            int want = isect_prim_all(&prims[k], &r, out);
            if (got.per_prim[k] != want && wrong < 0) {
                wrong = k;
                wrong_want = want;
            }
            planes += k >= n ? want : 0;
        }
        ck_assert_msg(wrong < 0, "ray %d part %d: %d crossings counted, %d found", i, wrong,
                      wrong < 0 ? 0 : got.per_prim[wrong], wrong_want);
    }
    ck_assert_msg(planes > 1000, "the planes crossed only %ld times", planes);
    bvh_free(&b);
    free(prims);
    free(frames);
}
END_TEST

/* [SHADE-SHORTCUT-ANY-1] r's any-crossing walk against its counting
 * walk: a crossing found exactly when one is counted, and the part named
 * one counted.  Returns whether r crosses something. */
static int any_agrees(const bvh *b, const scene_prim *prims, const ray *r, int i)
{
    static count_list got;
    memset(&got, 0, sizeof got);
    bvh_visit_counts(b, prims, r, count_into, &got, NULL);
    bvh_ref found = {-1, 0};
    int any = bvh_any_crossing(b, prims, r, &found, NULL);
    ck_assert_msg(any == (got.calls > 0), "ray %d: any %d, %ld parts counted", i, any, got.calls);
    if (any)
        ck_assert_msg(found.prim >= 0 && got.per_prim[found.prim] > 0, "ray %d: part %d not counted", i,
                      found.prim);
    return any;
}

/* Rays of every sort, half of them short (many cross nothing), over the
 * tree and the two planes. */
START_TEST(test_bvh_any_crossing_as_counts)
{
    rng g = {321, 0};
    scene_frame *frames;
    int n = 2000, rays = 4000, met = 0;
    scene_prim *prims = random_scene(320, n, 2, &frames);
    bvh b;
    ck_assert(bvh_build(&b, prims, n + 2, NULL));
    for (int i = 0; i < rays; i++) {
        ray r = random_ray(&g, prims, n + 2, i);
        r.tmax = i % 2 ? 0.05 + 3 * rng_uniform(&g) : r.tmax;
        met += any_agrees(&b, prims, &r, i);
    }
    ck_assert_msg(met > 500 && rays - met > 500, "%d rays of %d met", met, rays);
    bvh_free(&b);
    free(prims);
    free(frames);
}
END_TEST

static int stop_with_seven(void *ctx, const hit *h)
{
    int *calls = ctx;
    (*calls)++;
    ck_assert_int_ge(h->prim, 0);
    return 7;
}

START_TEST(test_bvh_visit_stops_early)
{
    /* Ten spheres on the x axis, all on the ray: the first call stops it. */
    scene_prim prims[10];
    for (int i = 0; i < 10; i++)
        prims[i] = prim_sphere(vec_make(3 * i, 0, 0), 1);
    bvh b;
    ck_assert(bvh_build(&b, prims, 10, NULL));
    ray r = {{-5, 0, 0}, {1, 0, 0}, 0.0, HUGE_VAL};
    int calls = 0;
    ck_assert_int_eq(bvh_visit(&b, prims, &r, stop_with_seven, &calls), 7);
    ck_assert_int_eq(calls, 1);
    crossing_list all = {{{0, 0}}, 0};
    ck_assert_int_eq(bvh_visit(&b, prims, &r, collect, &all), 0);
    ck_assert_int_eq(all.n, 20); /* entry and exit of each */
    /* Sphere i spans x in [3i-1, 3i+1], t in [3i+4, 3i+6].  tmax 11 keeps
     * 4, 6, 7, 9 and 10: five crossings. */
    r.tmax = 11.0;
    crossing_list part = {{{0, 0}}, 0};
    ck_assert_int_eq(bvh_visit(&b, prims, &r, collect, &part), 0);
    ck_assert_int_eq(part.n, 5);
    bvh_free(&b);
}
END_TEST

/* e_axis scaled by s. */
static vec3 axis_vec(int axis, double s) { return vec_make(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0); }

START_TEST(test_bvh_parallel_ray_in_flat_box_plane)
{
    /* A box flat along one axis (lo = hi = 0 there: a closed face, so a ray
     * lying in it hits, see intersect.h) beside a sphere.  A ray in that
     * plane, parallel to it, has its origin on the node's slab planes and a
     * zero direction component: 0 * inf = NaN in the slab test, whichever
     * axis it is on, must not cull the node.  Signed zeros flip the
     * infinities: both signs are tried. */
    for (int flat = 0; flat < 3; flat++) {
        for (int k = 1; k < 3; k++) {
            int along = (flat + k) % 3, third = 3 - flat - along;
            scene_prim prims[2];
            prims[0] = prim_sphere(vec_make(5, 5, 5), 1);
            prims[1] = prim_blank(PRIM_BOX);
            prims[1].u.box.lo = vec_make(0, 0, 0);
            prims[1].u.box.hi = vec_sub(vec_make(1, 1, 1), axis_vec(flat, 1));
            bvh b;
            ck_assert(bvh_build(&b, prims, 2, NULL));
            for (int sign = 0; sign < 2; sign++) {
                /* From 1 before the box (or 2 past it going back), mid-way
                 * across the third axis: t = 1 either way. */
                vec3 o = vec_add(axis_vec(along, sign ? 2.0 : -1.0), axis_vec(third, 0.5));
                double z = sign ? -0.0 : 0.0, u = sign ? -1.0 : 1.0;
                vec3 d = vec_make(along == 0 ? u : z, along == 1 ? u : z, along == 2 ? u : z);
                ray r = {o, d, 0.0, HUGE_VAL}, rb = r;
                hit h, hb;
                ck_assert(brute_nearest(prims, 2, &rb, &hb));
                ck_assert_int_eq(hb.prim, 1);
                ck_assert_near(hb.t, 1.0, 0.0);
                ck_assert_msg(bvh_intersect(&b, prims, &r, &h), "flat %d along %d sign %d", flat,
                              along, sign);
                ck_assert_int_eq(h.prim, 1);
                ck_assert_near(h.t, 1.0, 0.0);
            }
            bvh_free(&b);
        }
    }
}
END_TEST

START_TEST(test_bvh_flat_huge_triangle_not_culled)
{
    /* [BVH-CULL-PAD-1] A triangle lying in y = 0 with corners 1e8 away: its
     * padded box has no thickness in y (2^-40 of 0), but its test's t is a
     * difference of coordinates of 1e8 and is off by about 1e8 eps.  Rays
     * start as a spawned ray does under such a triangle (2^-42 of the point
     * below it, [NUM-SPAWN-1]) and go on down: the exact line never meets
     * the triangle, yet its test reports crossings at t of about 1e-9 for
     * some (attack 17, finding 2).  The walk must give what testing every
     * primitive gives (brute force, and the exhaustive walk), culled or not;
     * before, the box culled them all.  A sphere beside it makes a tree of
     * two leaves, a plane y = 0 is tested beside the tree. */
    scene_prim prims[3];
    prims[0] = prim_blank(PRIM_PLANE);
    prims[0].u.plane.point = vec_make(0, 0, 0);
    prims[0].u.plane.normal = vec_make(0, 1, 0);
    prims[1] = prim_blank(PRIM_TRIANGLE);
    prims[1].u.triangle.p[0] = vec_make(-1e8, 0, -1e8);
    prims[1].u.triangle.p[1] = vec_make(1e8, 0, -1e8);
    prims[1].u.triangle.p[2] = vec_make(0, 0, 1e8);
    prims[2] = prim_sphere(vec_make(0, 5, 0), 1);
    bvh b, e;
    ck_assert(bvh_build(&b, prims, 3, NULL));
    ck_assert(bvh_build(&e, prims, 3, NULL));
    e.exhaustive = 1;
    rng g = {1717, 0};
    int crossed = 0;
    for (int i = 0; i < 2000; i++) {
        vec3 p = vec_make(rng_range(&g, -4, 4), 0, rng_range(&g, -4, 4));
        p.y = -0x1p-42 * vec_max_abs(p);
        vec3 d = rng_unit(&g);
        d.y = -fabs(d.y);
        ray r = {p, d, 0.0, HUGE_VAL}, rb = r, re = r;
        hit h, hb, he;
        int mb = brute_nearest(prims, 3, &rb, &hb), m = bvh_intersect(&b, prims, &r, &h),
            me = bvh_intersect(&e, prims, &re, &he);
        crossed += mb && hb.prim == 1;
        ck_assert_int_eq(me, mb);
        ck_assert_msg(m == mb, "ray %d: the walk %s, testing every primitive %s (t %.17g)", i,
                      m ? "hits" : "misses", mb ? "hits" : "misses", mb ? (double)hb.t : 0.0);
        if (mb) {
            ck_assert_int_eq(h.prim, hb.prim);
            ck_assert_int_eq(he.prim, hb.prim);
            ck_assert(h.t == hb.t && he.t == hb.t);
        }
    }
    /* The case is exercised: some rays cross the triangle by its test. */
    ck_assert_int_gt(crossed, 0);
    bvh_free(&b);
    bvh_free(&e);
}
END_TEST

START_TEST(test_bvh_empty_scene)
{
    bvh b;
    ck_assert(bvh_build(&b, NULL, 0, NULL));
    ck_assert_int_eq(b.node_count, 0);
    ray r = {{0, 0, 0}, {0, 0, 1}, 0.0, HUGE_VAL};
    hit h;
    ck_assert(!bvh_intersect(&b, NULL, &r, &h));
    int calls = 0;
    ck_assert_int_eq(bvh_visit(&b, NULL, &r, stop_with_seven, &calls), 0);
    ck_assert_int_eq(calls, 0);
    bvh_free(&b);
    bvh_free(&b); /* freeing twice is harmless: the struct is zeroed */
}
END_TEST

START_TEST(test_bvh_one_prim_and_planes_only)
{
    /* One sphere: a one-node tree; the hit carries prim 0. */
    scene_prim s = prim_sphere(vec_make(0, 0, 5), 1);
    bvh b;
    ck_assert(bvh_build(&b, &s, 1, NULL));
    ck_assert_int_eq(b.node_count, 1);
    ck_assert_int_eq(b.leaf_count, 1);
    ray r = {{0, 0, 0}, {0, 0, 1}, 0.0, HUGE_VAL};
    hit h;
    ck_assert(bvh_intersect(&b, &s, &r, &h));
    ck_assert_int_eq(h.prim, 0);
    ck_assert_near(h.t, 4.0, 0.0);
    ck_assert_near(r.tmax, 4.0, 0.0);
    bvh_free(&b);
    /* Only planes: no tree, the list finds the nearer (prim 1 at t = 2). */
    scene_prim planes[2] = {prim_blank(PRIM_PLANE), prim_blank(PRIM_PLANE)};
    planes[0].u.plane.point = vec_make(0, 0, 7);
    planes[0].u.plane.normal = vec_make(0, 0, -1);
    planes[1].u.plane.point = vec_make(0, 0, 2);
    planes[1].u.plane.normal = vec_make(0, 0, 1);
    ck_assert(bvh_build(&b, planes, 2, NULL));
    ck_assert_int_eq(b.node_count, 0);
    ck_assert_int_eq(b.unbounded_count, 2);
    r = (ray){{0, 0, 0}, {0, 0, 1}, 0.0, HUGE_VAL};
    ck_assert(bvh_intersect(&b, planes, &r, &h));
    ck_assert_int_eq(h.prim, 1);
    ck_assert_near(h.t, 2.0, 0.0);
    bvh_free(&b);
}
END_TEST

static int count_crossings(void *ctx, const hit *h)
{
    ck_assert(h->t == 5.5 || h->t == 6.5);
    (*(long *)ctx)++;
    return 0;
}

START_TEST(test_bvh_identical_prims_tie_to_lowest_index)
{
    /* 5000 copies of one sphere: the centroids coincide, so every split is
     * an object median; the tree stays shallow and the nearest hit is the
     * copy with the lowest index, as brute force gives. */
    int n = 5000;
    scene_prim *prims = malloc((size_t)n * sizeof *prims);
    ck_assert_ptr_nonnull(prims);
    for (int i = 0; i < n; i++)
        prims[i] = prim_sphere(vec_make(1, 2, 3), 0.5);
    bvh b;
    ck_assert(bvh_build(&b, prims, n, NULL));
    ck_assert_int_le(b.depth, 14); /* ceil(log2(5000 / 4)) + 1 = 12 */
    ray r = {{1, 2, -3}, {0, 0, 1}, 0.0, HUGE_VAL};
    hit h;
    ck_assert(bvh_intersect(&b, prims, &r, &h));
    ck_assert_int_eq(h.prim, 0);
    ck_assert_near(h.t, 5.5, 0.0);
    /* Every one of them is crossed twice, at 5.5 and 6.5. */
    long crossings = 0;
    ray rr = {{1, 2, -3}, {0, 0, 1}, 0.0, HUGE_VAL};
    ck_assert_int_eq(bvh_visit(&b, prims, &rr, count_crossings, &crossings), 0);
    ck_assert_int_eq(crossings, 2 * n);
    bvh_free(&b);
    free(prims);
}
END_TEST

START_TEST(test_bvh_tie_window_end_order_free)
{
    /* [BVH-TIE-ORDER-1] The window's far end belongs to it: a hit at exactly
     * t_near + 2^-46 (|t_near| + |origin|) is a candidate whatever was
     * tested first.  Index 1, a plane (tested before the tree), meets the
     * ray at t = 1; index 0, a box in the tree, at t = 1 + 2^-46, the
     * window's end (origin 0): brute force gives index 0.  A walk that
     * shrank tmax to the window's end would reject t < tmax for the box. */
    scene_prim prims[2];
    real end = 1.0 + 0x1p-46;
    prims[0] = prim_blank(PRIM_BOX);
    prims[0].u.box.lo = vec_make(end, -1, -1);
    prims[0].u.box.hi = vec_make(end + 1, 1, 1);
    prims[1] = prim_blank(PRIM_PLANE);
    prims[1].u.plane.point = vec_make(1, 0, 0);
    prims[1].u.plane.normal = vec_make(-1, 0, 0);
    bvh b;
    ck_assert(bvh_build(&b, prims, 2, NULL));
    ray r = {{0, 0, 0}, {1, 0, 0}, 0.0, HUGE_VAL}, rb = r;
    hit h, hb;
    ck_assert(brute_nearest(prims, 2, &rb, &hb));
    ck_assert_int_eq(hb.prim, 0);
    ck_assert(bvh_intersect(&b, prims, &r, &h));
    ck_assert_int_eq(h.prim, 0);
    ck_assert(h.t == end);
    /* The caller's tmax still bounds the window: with tmax = end the box's
     * hit is outside (tmin, tmax), so the plane wins. */
    ray s = {{0, 0, 0}, {1, 0, 0}, 0.0, end};
    ck_assert(bvh_intersect(&b, prims, &s, &h));
    ck_assert_int_eq(h.prim, 1);
    ck_assert(h.t == 1.0);
    bvh_free(&b);
}
END_TEST

START_TEST(test_bvh_moved_candidate_keeps_its_normal)
{
    /* [BVH-TIE-ORDER-1] with spheres, whose normal the walk makes only for
     * the winner (bvh.c, nearest.rest): three unit spheres on the x axis,
     * met from (0, 0.6, 0) along x at t about 3.2, where the window is
     * 2^-46 (3.2 + 0.6), 122 ulps of t (off the axis, so that the normal
     * tells the centres apart).  X's centre lies 43 ulps of 4 (86 of t)
     * beyond Y's, Z's 24 (48 of t) before: tested X, Y, Z (a leaf of
     * three, in index order), X is dropped when Z comes, Y is kept and
     * moves down, and the lower index of Y and Z wins.  Every order of
     * indices, each against brute force (isect_prim of each sphere): the
     * winner's normal must be made from its own centre. */
    static const int shift[3] = {43, 0, -24}; /* X, Y, Z in units of 2^-50 */
    static const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < 12; k++) {
        /* k >= 6: the mirror image (x -> -x), so that the walk tests X
         * first whichever way a leaf orders them. */
        real side = k < 6 ? 1.0 : -1.0;
        scene_prim prims[3];
        for (int i = 0; i < 3; i++)
            prims[order[k % 6][i]] = prim_sphere(vec_make(side * (4.0 + shift[i] * 0x1p-50), 0, 0), 1.0);
        bvh b;
        ck_assert(bvh_build(&b, prims, 3, NULL));
        ray r = {{0, 0.6, 0}, {side, 0, 0}, 0.0, HUGE_VAL}, rb = r;
        hit h, hb;
        ck_assert(brute_nearest(prims, 3, &rb, &hb));
        /* X lies past Z's window, so Y or Z wins, by index. */
        ck_assert_int_eq(hb.prim, order[k % 6][1] < order[k % 6][2] ? order[k % 6][1] : order[k % 6][2]);
        ck_assert(bvh_intersect(&b, prims, &r, &h));
        ck_assert_int_eq(h.prim, hb.prim);
        ck_assert(h.t == hb.t && same_vec_bits(h.point, hb.point));
        ck_assert_msg(same_vec_bits(h.normal, hb.normal) && same_vec_bits(h.shading_normal, hb.shading_normal),
                      "order %d: normal (%a, %a, %a), brute force (%a, %a, %a)", k, h.normal.x, h.normal.y,
                      h.normal.z, hb.normal.x, hb.normal.y, hb.normal.z);
        ck_assert_int_eq(h.entering, hb.entering);
        bvh_free(&b);
    }
}
END_TEST

START_TEST(test_bvh_two_parts_split_by_hand)
{
    /* The SAH of a node of two parts, worked by hand ([BVH-BUILD-PAIR-1]):
     * splitting costs C_TRAV + (A_0 + A_1) / A (half areas, cost 1 each),
     * a leaf costs 2.  Two unit spheres 0.1 apart: 1 + (12 + 12) / 12.4 =
     * 2.94, a leaf, items in the given order.  Five apart along x, or
     * along y only: 1 + 24 / 32 = 1.75, split on the first axis along
     * which the centroids differ, the lower centroid's part first. */
    static const double centres[3][2][3] = {
        {{0.1, 0, 0}, {0, 0, 0}}, {{5, 0, 0}, {0, 0, 0}}, {{0, 5, 0}, {0, 0, 0}}};
    for (int c = 0; c < 3; c++) {
        scene_prim prims[2];
        for (int i = 0; i < 2; i++)
            prims[i] = prim_sphere(vec_make(centres[c][i][0], centres[c][i][1], centres[c][i][2]), 1);
        bvh b;
        ck_assert(bvh_build(&b, prims, 2, NULL));
        ck_assert_int_eq(b.item_count, 2);
        if (c == 0) {
            ck_assert_int_eq(b.node_count, 1);
            ck_assert_int_eq(b.nodes[0].count, 2);
            ck_assert_int_eq(b.items[0].prim, 0);
        } else {
            ck_assert_int_eq(b.node_count, 3);
            ck_assert_int_eq(b.nodes[0].count, 0);
            ck_assert_int_eq(b.nodes[1].count, 1);
            ck_assert_int_eq(b.nodes[2].count, 1);
            ck_assert_int_eq(b.items[b.nodes[1].first].prim, 1);
            ck_assert_int_eq(b.items[b.nodes[2].first].prim, 0);
            /* each child's box is its sphere's, padded by 2^-40 of its size */
            ck_assert_double_le(b.nodes[1].lo.x, -1.0);
            ck_assert_double_ge(b.nodes[1].lo.x, -1.0 - 0x1p-38);
            ck_assert_double_ge(b.nodes[2].hi.x + b.nodes[2].hi.y, 6.0);
        }
        bvh_free(&b);
    }
}
END_TEST

START_TEST(test_bvh_deterministic_and_well_formed)
{
    int n = 3000;
    scene_frame *frames;
    scene_prim *prims = random_scene(400, n, 2, &frames);
    bvh a, b;
    ck_assert(bvh_build(&a, prims, n + 2, NULL));
    ck_assert(bvh_build(&b, prims, n + 2, NULL));
    ck_assert_int_eq(a.node_count, b.node_count);
    ck_assert(memcmp(a.nodes, b.nodes, (size_t)a.node_count * sizeof *a.nodes) == 0);
    ck_assert(memcmp(a.items, b.items, (size_t)a.item_count * sizeof *a.items) == 0);
    /* Every primitive appears once, in a leaf or in the unbounded list. */
    int *seen = calloc((size_t)n + 2, sizeof *seen);
    ck_assert_ptr_nonnull(seen);
    ck_assert_int_eq(a.item_count + a.unbounded_count, n + 2);
    for (int i = 0; i < a.item_count; i++) {
        ck_assert_int_eq(a.items[i].part, 0);
        seen[a.items[i].prim]++;
    }
    for (int i = 0; i < a.unbounded_count; i++)
        seen[a.unbounded[i].prim]++;
    for (int i = 0; i < n + 2; i++)
        ck_assert_int_eq(seen[i], 1);
    /* Leaves cover the items exactly; inner boxes hold their children;
     * every primitive's box is inside its leaf's. */
    int leaf_items = 0, leaves = 0;
    for (int k = 0; k < a.node_count; k++) {
        const bvh_node *nd = &a.nodes[k];
        if (nd->count > 0) {
            leaves++;
            leaf_items += nd->count;
            for (int i = nd->first; i < nd->first + nd->count; i++) {
                vec3 lo, hi;
                ck_assert(isect_prim_bounds(&prims[a.items[i].prim], &lo, &hi));
                ck_assert(lo.x >= nd->lo.x && lo.y >= nd->lo.y && lo.z >= nd->lo.z);
                ck_assert(hi.x <= nd->hi.x && hi.y <= nd->hi.y && hi.z <= nd->hi.z);
            }
            continue;
        }
        const bvh_node *kids[2] = {&a.nodes[nd->first], &a.nodes[nd->first + 1]};
        ck_assert_int_gt(nd->first, k);
        for (int c = 0; c < 2; c++) {
            ck_assert(kids[c]->lo.x >= nd->lo.x && kids[c]->lo.y >= nd->lo.y && kids[c]->lo.z >= nd->lo.z);
            ck_assert(kids[c]->hi.x <= nd->hi.x && kids[c]->hi.y <= nd->hi.y && kids[c]->hi.z <= nd->hi.z);
        }
    }
    ck_assert_int_eq(leaf_items, a.item_count);
    ck_assert_int_eq(leaves, a.leaf_count);
    ck_assert_int_eq(a.node_count, 2 * a.leaf_count - 1);
    free(seen);
    bvh_free(&a);
    bvh_free(&b);
    free(prims);
    free(frames);
}
END_TEST

/* The union of two boxes, in real (fmin would go through double). */
static void box_join(vec3 *lo, vec3 *hi, vec3 l, vec3 h)
{
    *lo = vec_make(l.x < lo->x ? l.x : lo->x, l.y < lo->y ? l.y : lo->y, l.z < lo->z ? l.z : lo->z);
    *hi = vec_make(h.x > hi->x ? h.x : hi->x, h.y > hi->y ? h.y : hi->y, h.z > hi->z ? h.z : hi->z);
}

/* The exact union of the padded boxes of node k's parts into *lo, *hi
 * (recomputed from the parts, not read from the tree), asserting on the
 * way that every node's stored box is that union widened on every axis by
 * 2^-40 of its largest magnitude (bvh_build.c, [BVH-CULL-PAD-1]), to the
 * bit. */
static void exact_box(const bvh *b, const scene_prim *prims, int k, vec3 *lo, vec3 *hi)
{
    const bvh_node *nd = &b->nodes[k];
    *lo = vec_splat(INFINITY);
    *hi = vec_splat(-INFINITY);
    if (nd->count > 0) {
        for (int i = nd->first; i < nd->first + nd->count; i++) {
            vec3 plo, phi;
            ck_assert(isect_part_padded_bounds(&prims[b->items[i].prim], b->items[i].part, &plo, &phi));
            box_join(lo, hi, plo, phi);
        }
    } else {
        for (int c = 0; c < 2; c++) {
            vec3 klo, khi;
            exact_box(b, prims, nd->first + c, &klo, &khi);
            box_join(lo, hi, klo, khi);
        }
    }
    real m = fmax(fmax(vec_max_abs(*lo), vec_max_abs(*hi)), vec_max_abs(vec_sub(*hi, *lo)));
    real w = ldexp(m, -40);
    ck_assert_msg(nd->lo.x == lo->x - w && nd->lo.y == lo->y - w && nd->lo.z == lo->z - w &&
                      nd->hi.x == hi->x + w && nd->hi.y == hi->y + w && nd->hi.z == hi->z + w,
                  "node %d's box is not the union of its parts' boxes, widened", k);
}

START_TEST(test_bvh_boxes_exact_past_one_axis)
{
    /* 9000 parts: the nodes above 4096 parts are binned along one axis,
     * those below along all three (bin_axes), and a child's box comes
     * from the bins; each must be exactly its parts' union, so no bin
     * may lose or gain a part on any axis. */
    int n = 9000;
    scene_frame *frames;
    scene_prim *prims = random_scene(900, n, 0, &frames);
    bvh b;
    ck_assert(bvh_build(&b, prims, n, NULL));
    ck_assert_int_eq(b.unbounded_count, 0);
    ck_assert_int_gt(b.node_count, 1);
    vec3 lo, hi;
    exact_box(&b, prims, 0, &lo, &hi);
    bvh_free(&b);
    free(prims);
    free(frames);
}
END_TEST

START_TEST(test_bvh_skewed_distribution_depth_bounded)
{
    /* 600 spheres at x = 1.5^-k, radius a tenth of that: each SAH split
     * peels off only the few outermost, so SAH alone builds a tree over 100
     * deep; past BVH_MEDIAN_DEPTH median splits take over and the depth
     * stays within BVH_MAX_DEPTH (the build asserts it, traversal relies on
     * it).  The smallest is 1e-106, well inside double's normal range. */
    int n = 600;
    scene_prim *prims = malloc((size_t)n * sizeof *prims);
    ck_assert_ptr_nonnull(prims);
    for (int i = 0; i < n; i++)
        prims[i] = prim_sphere(vec_make(pow(1.5, -i), 0, 0), 0.1 * pow(1.5, -i));
    bvh b;
    ck_assert(bvh_build(&b, prims, n, NULL));
    ck_assert_int_gt(b.depth, BVH_MEDIAN_DEPTH);
    ck_assert_int_le(b.depth, BVH_MAX_DEPTH);
    check_nearest_agrees(&b, prims, n, 501, 500);
    /* Down the axis from the right the biggest sphere is first: x = 1.1. */
    ray r = {{5, 0, 0}, {-1, 0, 0}, 0.0, HUGE_VAL};
    hit h;
    ck_assert(bvh_intersect(&b, prims, &r, &h));
    ck_assert_int_eq(h.prim, 0);
    ck_assert_near(h.t, 5 - 1.1, 1e-15);
    /* From the left every sphere below 1e-16 is met at t = 1 exactly (in
     * double), and those below 2.8e-14 within the tie window 2^-46 (1 + 1)
     * of it: the lowest such index must win, as in brute force. */
    r = (ray){{-1, 0, 0}, {1, 0, 0}, 0.0, HUGE_VAL};
    ray rb = r;
    hit hb;
    ck_assert(bvh_intersect(&b, prims, &r, &h));
    ck_assert(brute_nearest(prims, n, &rb, &hb));
    ck_assert_near(h.t, 1.0, 0x1p-45);
    ck_assert_int_eq(h.prim, hb.prim);
    ck_assert_int_lt(h.prim, 100); /* 1.5^-100 = 2.5e-18 */
    bvh_free(&b);
    free(prims);
}
END_TEST

/* slab_box_meets against slab_box's interval, and by hand where the exit's
 * pad decides.  The hand cases: direction (1, 1, 1) (1/d = 1) from the
 * origin, so each slab's t is its plane's coordinate; the pad makes an exit
 * e into e (1 + 2^-50) for e >= 0 and e (1 - 2^-50) below 0. */
/* A random box in [-4, 4]^3. */
static void slab_case_box(rng *g, vec3 *lo, vec3 *hi)
{
    vec3 a = rng_box(g, -4, 4), b = rng_box(g, -4, 4);
    *lo = vec_make(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
    *hi = vec_make(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
}

/* A random ray for the box [lo, hi]: at times with zero direction
 * components (+0 or -0), its origin on a y plane of the box (0 * inf =
 * NaN), tmin below 0 and tmax infinite. */
static void slab_case_ray(rng *g, vec3 lo, vec3 hi, ray *r)
{
    r->origin = rng_box(g, -6, 6);
    r->dir = rng_unit(g);
    int k = (int)(rng_uniform(g) * 8);
    if (k & 1)
        r->dir.x = 0;
    if (k & 2)
        r->origin.y = rng_uniform(g) < 0.5 ? lo.y : hi.y;
    if (k & 4)
        r->dir.y = rng_uniform(g) < 0.5 ? 0.0 : -0.0;
    r->tmin = rng_uniform(g) < 0.25 ? -rng_range(g, 0, 8) : rng_range(g, 0, 2) * (rng_uniform(g) < 0.5);
    r->tmax = rng_uniform(g) < 0.2 ? INFINITY : r->tmin + rng_range(g, 0, 12);
}

/* Exits near an entry, where the pad decides: a box edge moved to an
 * other axis's plane along the ray, nudged by a few ulps. */
static void slab_case_nudge(rng *g, const ray *r, vec3 *lo, vec3 *hi)
{
    if (rng_uniform(g) < 0.3 && r->dir.x != 0 && r->dir.z != 0) {
        real t = (lo->z - r->origin.z) / r->dir.z;
        real x = r->origin.x + t * r->dir.x;
        int ulps = (int)(rng_uniform(g) * 9) - 4;
        x = x + ulps * 0x1p-52 * fabs(x);
        if (r->dir.x > 0 && x > lo->x)
            hi->x = x;
        else if (r->dir.x < 0 && x < hi->x)
            lo->x = x;
    }
}

static int meets_by_hand(vec3 lo, vec3 hi, real tmin, real tmax)
{
    ray r = {vec_make(0, 0, 0), vec_make(1, 1, 1), tmin, tmax};
    slab_ray s = slab_make(&r);
    real enter;
    return slab_box_meets(lo, hi, &s, tmin, tmax, &enter);
}

START_TEST(test_slab_box_meets_is_slab_box)
{
    /* Entry 1 + 2^-52 (y), exit 1 (x): met only through the pad, 1 + 2^-50. */
    ck_assert_int_eq(meets_by_hand(vec_make(0, 1 + 0x1p-52, 0), vec_make(1, 2, 2), -10, 10), 1);
    /* Exit 1 (x) against an entry 1 + 2^-49: past the pad. */
    ck_assert_int_eq(meets_by_hand(vec_make(0, 1 + 0x1p-49, 0), vec_make(1, 2, 2), -10, 10), 0);
    /* Behind the origin: exit -1 padded toward 0, to -1 + 2^-50, holds the
     * entry -1 + 2^-52; a pad of 1 + 2^-50 for it would not. */
    ck_assert_int_eq(meets_by_hand(vec_make(-2, -1 + 0x1p-52, -2), vec_make(-1, 0, 0), -10, 10), 1);
    ck_assert_int_eq(meets_by_hand(vec_make(-2, -1 + 0x1p-51, -2), vec_make(-1, 0, 0), -10, 10), 1);
    ck_assert_int_eq(meets_by_hand(vec_make(-2, -1 + 0x1p-49, -2), vec_make(-1, 0, 0), -10, 10), 0);
    /* tmax is not padded: an entry one ulp past it misses. */
    ck_assert_int_eq(meets_by_hand(vec_make(1 + 0x1p-51, 0, 0), vec_make(5, 5, 5), 0, 1 + 0x1p-52), 0);
    ck_assert_int_eq(meets_by_hand(vec_make(1 + 0x1p-52, 0, 0), vec_make(5, 5, 5), 0, 1 + 0x1p-52), 1);

    /* Random boxes and rays, with zero direction components, origins on
     * slab planes (0 * inf = NaN), boxes behind the origin and infinite
     * tmax: the same answer as slab_box's interval and its entry's bits. */
    rng g = {16, 0};
    for (int i = 0; i < 200000; i++) {
        vec3 lo, hi;
        ray r;
        slab_case_box(&g, &lo, &hi);
        slab_case_ray(&g, lo, hi, &r);
        slab_case_nudge(&g, &r, &lo, &hi);
        slab_ray s = slab_make(&r);
        real tn = r.tmin, tf = r.tmax, enter;
        slab_box(lo, hi, &s, &tn, &tf);
        int want = tn <= tf, got = slab_box_meets(lo, hi, &s, r.tmin, r.tmax, &enter);
        ck_assert_msg(got == want, "case %d: %d, slab_box %d", i, got, want);
        ck_assert_msg(same_real_bits(enter, tn) || (enter != enter && tn != tn),
                      "case %d: entry %.17g vs %.17g", i, (double)enter, (double)tn);
    }
}
END_TEST

#ifdef SLAB_PAIR_SSE2
/* slab_pair_meets of the pair form of s, with the offsets of its neg
 * flags. */
static int pair_meets(const bvh_node nodes[2], const slab_ray *s, real tmin, real tmax, real *ta, real *tc)
{
    slab_pair_ray p;
    slab_pair_make(s, &p);
    return slab_pair_meets(nodes, &p, slab_pair_near_at(0, s->neg[0]), slab_pair_far_at(0, s->neg[0]),
                           slab_pair_near_at(1, s->neg[1]), slab_pair_far_at(1, s->neg[1]),
                           slab_pair_near_at(2, s->neg[2]), slab_pair_far_at(2, s->neg[2]), tmin, tmax, ta, tc);
}

/* slab_pair_meets (and slab_pair_meets_slab, which must agree with it to
 * the bit) for two nodes and a ray: its mask against slab_box's
 * interval for each box, its entries' bits against slab_box's. */
static void check_pair(const bvh_node nodes[2], const ray *r, int i)
{
    slab_ray s = slab_make(r);
    real ta, tc, sa, sc;
    int got = pair_meets(nodes, &s, r->tmin, r->tmax, &ta, &tc);
    int from_slab = slab_pair_meets_slab(nodes, &s, r->tmin, r->tmax, &sa, &sc);
    ck_assert_msg(from_slab == got && same_real_bits(sa, ta) && same_real_bits(sc, tc),
                  "case %d: slab_pair_meets_slab %d, slab_pair_meets %d", i, from_slab, got);
    for (int k = 0; k < 2; k++) {
        real tn = r->tmin, tf = r->tmax, enter = k ? tc : ta;
        slab_box(nodes[k].lo, nodes[k].hi, &s, &tn, &tf);
        ck_assert_msg(((got >> k) & 1) == (tn <= tf), "case %d, node %d: %d, slab_box %d", i, k, (got >> k) & 1,
                      tn <= tf);
        ck_assert_msg(same_real_bits(enter, tn), "case %d, node %d: entry %.17g vs %.17g", i, k, (double)enter,
                      (double)tn);
    }
}
#endif

START_TEST(test_slab_pair_meets_is_slab_box)
{
#ifdef SLAB_PAIR_SSE2
    /* By hand, the ray (0,0,0) + t (1,1,1): node 0 met only through the
     * pad (entry 1 + 2^-52, exit 1), node 1 past it (entry 1 + 2^-49); and
     * swapped, so that each lane is seen both ways. */
    bvh_node n[2] = {{vec_make(0, 1 + 0x1p-52, 0), vec_make(1, 2, 2), 0, 1},
                     {vec_make(0, 1 + 0x1p-49, 0), vec_make(1, 2, 2), 0, 1}};
    ray r = {vec_make(0, 0, 0), vec_make(1, 1, 1), -10, 10};
    slab_ray s = slab_make(&r);
    real ta, tc;
    ck_assert_int_eq(pair_meets(n, &s, -10, 10, &ta, &tc), 1);
    ck_assert(ta == 1 + 0x1p-52 && tc == 1 + 0x1p-49);
    ck_assert_int_eq(slab_pair_meets_slab(n, &s, -10, 10, &ta, &tc), 1);
    bvh_node m[2] = {n[1], n[0]};
    ck_assert_int_eq(pair_meets(m, &s, -10, 10, &ta, &tc), 2);
    ck_assert_int_eq(slab_pair_meets_slab(m, &s, -10, 10, &ta, &tc), 2);
    /* Behind the origin: exit -1 padded toward 0 holds the entry
     * -1 + 2^-51 (node 0), not -1 + 2^-49 (node 1). */
    bvh_node b[2] = {{vec_make(-2, -1 + 0x1p-51, -2), vec_make(-1, 0, 0), 0, 1},
                     {vec_make(-2, -1 + 0x1p-49, -2), vec_make(-1, 0, 0), 0, 1}};
    ck_assert_int_eq(pair_meets(b, &s, -10, 10, &ta, &tc), 1);
    ck_assert_int_eq(slab_pair_meets_slab(b, &s, -10, 10, &ta, &tc), 1);

    /* Random pairs as test_slab_box_meets_is_slab_box's boxes: the ray made
     * for node 0 (its origin on one of node 0's planes at times), node 1
     * nudged to the ray's entry into it, or with the origin on its plane. */
    rng g = {18, 0};
    for (int i = 0; i < 200000; i++) {
        bvh_node nodes[2];
        ray q;
        for (int k = 0; k < 2; k++) {
            slab_case_box(&g, &nodes[k].lo, &nodes[k].hi);
            nodes[k].first = 0;
            nodes[k].count = 1;
        }
        slab_case_ray(&g, nodes[0].lo, nodes[0].hi, &q);
        slab_case_nudge(&g, &q, &nodes[1].lo, &nodes[1].hi);
        if (rng_uniform(&g) < 0.25)
            nodes[1].hi.y = q.origin.y < nodes[1].lo.y ? nodes[1].lo.y : q.origin.y;
        if (rng_uniform(&g) < 0.5) {
            bvh_node t = nodes[0];
            nodes[0] = nodes[1];
            nodes[1] = t;
        }
        check_pair(nodes, &q, i);
    }
#else
    ck_assert_msg(1, "no SSE2: the walks test each child by slab_box_meets_neg");
#endif
}
END_TEST

/* For a ray that meets no part: the boxes and the parts each walk tests
 * (the nearest one and bvh_visit_stats'), which must be nodes and parts. */
static void check_miss_counts(const bvh *b, const scene_prim *prims, const ray *r, long nodes, long parts)
{
    hit h;
    ray q = *r;
    bvh_stats st = {0, 0}, vs = {0, 0};
    long crossings = 0;
    ck_assert(!bvh_intersect_stats(b, prims, &q, &h, &st));
    ck_assert_int_eq(st.nodes_visited, nodes);
    ck_assert_int_eq(st.prims_tested, parts);
    ck_assert_int_eq(bvh_visit_stats(b, prims, r, count_crossings, &crossings, &vs), 0);
    ck_assert_int_eq(crossings, 0);
    ck_assert_int_eq(vs.nodes_visited, nodes);
    ck_assert_int_eq(vs.prims_tested, parts);
}

/* The walks leave out the test of an inner root (root_decides_nothing in
 * bvh.c) and test a leaf root: boxes tested, counted by hand. */
START_TEST(test_bvh_inner_root_not_tested)
{
    scene_prim two[2] = {prim_sphere(vec_make(-5, 0, 0), 1), prim_sphere(vec_make(5, 0, 0), 1)};
    bvh b;
    ck_assert(bvh_build(&b, two, 2, NULL));
    ck_assert_int_eq(b.node_count, 3);
    ck_assert_int_eq(b.nodes[0].count, 0);
    hit h;
    /* Past both: the root's two children tested, nothing else. */
    ray r = {{0, 10, 0}, {0, 1, 0}, 0.0, HUGE_VAL};
    check_miss_counts(&b, two, &r, 2, 0);
    /* Into the ball at x = 5: both children, the ball tested and hit. */
    bvh_stats in = {0, 0};
    ray q = {{5, 10, 0}, {0, -1, 0}, 0.0, HUGE_VAL};
    ck_assert(bvh_intersect_stats(&b, two, &q, &h, &in));
    ck_assert_int_eq(h.prim, 1);
    ck_assert_int_eq(in.nodes_visited, 2);
    ck_assert_int_eq(in.prims_tested, 1);
    bvh_free(&b);
    /* One ball: the root is a leaf, tested, and culls the ray. */
    ck_assert(bvh_build(&b, two, 1, NULL));
    ck_assert_int_eq(b.nodes[0].count, 1);
    bvh_stats one = {0, 0};
    ray o = {{0, 10, 0}, {0, 1, 0}, 0.0, HUGE_VAL};
    ck_assert(!bvh_intersect_stats(&b, two, &o, &h, &one));
    ck_assert_int_eq(one.nodes_visited, 1);
    ck_assert_int_eq(one.prims_tested, 0);
    bvh_free(&b);
}
END_TEST


/* The walks enter only the children the ray meets: the sibling both walks
 * write to their stack at every inner node is kept only when met (bvh.c,
 * descend and traverse_from).  Four balls in a row, a ray down through the
 * corner of the first one's box that misses the ball: tmax stays +inf, and
 * an unmet sibling's entry (+inf, the ray being parallel to its x slab)
 * would pass the pop's `enter <= tmax`.  Counted by hand: the root's two
 * children and the first inner node's two, one ball tested. */
START_TEST(test_bvh_unmet_sibling_not_entered)
{
    scene_prim row[4] = {prim_sphere(vec_make(-15, 0, 0), 1), prim_sphere(vec_make(-5, 0, 0), 1),
                         prim_sphere(vec_make(5, 0, 0), 1), prim_sphere(vec_make(15, 0, 0), 1)};
    bvh b;
    ck_assert(bvh_build(&b, row, 4, NULL));
    ck_assert_int_eq(b.node_count, 7);
    ck_assert_int_eq(b.leaf_count, 4);
    ray r = {{-15.9, 10, 0.9}, {0, -1, 0}, 0.0, HUGE_VAL};
    check_miss_counts(&b, row, &r, 4, 1);
    bvh_free(&b);
}
END_TEST
START_TEST(test_bvh_grid_100k_visits_few_nodes)
{
    /* A 100 x 100 x 10 grid of unit-spaced spheres (100 000).  A ray down
     * a grid row from outside stops at the first sphere: the traversal
     * must test a tiny fraction of the nodes and primitives. */
    int nx = 100, ny = 100, nz = 10, n = nx * ny * nz;
    scene_prim *prims = malloc((size_t)n * sizeof *prims);
    ck_assert_ptr_nonnull(prims);
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++)
                prims[(z * ny + y) * nx + x] = prim_sphere(vec_make(x, y, z), 0.3);
    bvh b;
    ck_assert(bvh_build(&b, prims, n, NULL));
    ck_assert_int_le(b.depth, 40);
    bvh_stats st = {0, 0};
    ray r = {{-10, 37, 4}, {1, 0, 0}, 0.0, HUGE_VAL};
    hit h;
    ck_assert(bvh_intersect_stats(&b, prims, &r, &h, &st));
    ck_assert_int_eq(h.prim, (4 * ny + 37) * nx + 0);
    ck_assert_near(h.t, 9.7, 1e-14);
    /* The ray is parallel to two axes: a slab test that turned -inf * pad
     * into NaN would keep every box in the row (thousands of nodes). */
    ck_assert_msg(st.nodes_visited < 100, "visited %ld nodes", st.nodes_visited);
    ck_assert_msg(st.prims_tested < 10, "tested %ld prims", st.prims_tested);
    /* A diagonal ray slipping between two layers through the whole grid
     * (z half-way between them) passes near a couple of hundred spheres
     * without hitting any: a few hundred nodes, not a fraction of 2e5. */
    bvh_stats miss = {0, 0};
    ray m = {{-1, 0.5, 4.5}, vec_normalize(vec_make(1, 1, 0)), 0.0, HUGE_VAL};
    ck_assert(!bvh_intersect_stats(&b, prims, &m, &h, &miss));
    ck_assert_msg(miss.nodes_visited < 1000, "visited %ld nodes", miss.nodes_visited);
    /* Camera-like rays from above one side into the grid: on average a
     * few dozen nodes, about log2 of the node count plus the boxes the ray
     * grazes on its way down. */
    rng g = {602, 0};
    bvh_stats cam = {0, 0};
    int rays = 2000;
    for (int i = 0; i < rays; i++) {
        vec3 eye = vec_make(50.1, -30, 40), aim = vec_make(rng_range(&g, 0, 99), rng_range(&g, 0, 99), 5);
        ray c = {eye, vec_normalize(vec_sub(aim, eye)), 0.0, HUGE_VAL};
        bvh_intersect_stats(&b, prims, &c, &h, &cam);
    }
    ck_assert_msg(cam.nodes_visited < 100L * rays, "%ld nodes per ray", cam.nodes_visited / rays);
    ck_assert_msg(cam.prims_tested < 10L * rays, "%ld prims per ray", cam.prims_tested / rays);
    check_nearest_agrees(&b, prims, n, 601, 30);
    bvh_free(&b);
    free(prims);
}
END_TEST

/* [BVH-BEAM-1] A run of n camera-like rays from o: unit directions about
 * fwd, spread along side by step each (a row of pixels), all tmin 0 and
 * tmax +inf.  spread 0 gives n copies of one ray. */
static void beam_run(rng *g, vec3 o, vec3 fwd, double step, int n, ray *rays)
{
    vec3 side = vec_normalize(vec_cross(fwd, rng_unit(g))), up = vec_normalize(vec_cross(side, fwd));
    double y = rng_range(g, -1, 1) * step * n;
    for (int i = 0; i < n; i++) {
        rays[i].origin = o;
        rays[i].dir = vec_normalize(vec_add(fwd, vec_add(vec_scale(side, (i - 0.5 * n) * step), vec_scale(up, y))));
        rays[i].tmin = 0;
        rays[i].tmax = INFINITY;
    }
}

/* A box about a point of ray r (sometimes off it, flat, or with a bound on
 * the origin's own coordinate). */
static void beam_box(rng *g, const ray *r, vec3 *lo, vec3 *hi)
{
    vec3 c = vec_add(r->origin, vec_scale(r->dir, rng_range(g, -2, 20)));
    c = vec_add(c, vec_scale(rng_unit(g), rng_range(g, 0, 1) * rng_range(g, 0, 1)));
    vec3 e = rng_box(g, 0, rng_range(g, 1e-3, 1));
    if (rng_uniform(g) < 0.2)
        e.y = 0;
    *lo = vec_sub(c, e);
    *hi = vec_add(c, e);
    if (rng_uniform(g) < 0.1)
        lo->x = r->origin.x;
    if (rng_uniform(g) < 0.1)
        hi->z = r->origin.z;
}

/* Whether the pruned tree of the three-node tree (root, a, a + 1) keeps
 * child k: the pair form of the beam test read through bvh_beam_prune. */
static int beam_kept(const bvh_beam_tree *t, const bvh_node *nodes, int k)
{
    if (t->count == 3)
        return 1;
    return t->count == 1 && t->nodes[0].first == nodes[1 + k].first;
}

START_TEST(test_bvh_beam_meets_every_box_a_ray_meets)
{
    rng g = {2301, 0};
    ray rays[64];
    long met = 0, refused = 0, beam_only = 0, runs = 0;
    for (int i = 0; i < 3000; i++) {
        int n = 1 + (int)(rng_uniform(&g) * 64);
        double step = i % 4 == 0 ? 0 : pow(10, rng_range(&g, -5, -1));
        beam_run(&g, rng_box(&g, -10, 10), rng_unit(&g), step, n, rays);
        bvh_beam beam;
        if (!bvh_beam_bounds(rays, n, &beam)) {
            refused++;
            continue;
        }
        runs++;
        for (int j = 0; j < 20; j++) {
            bvh_node nodes[3];
            beam_box(&g, &rays[(int)(rng_uniform(&g) * n)], &nodes[1].lo, &nodes[1].hi);
            beam_box(&g, &rays[(int)(rng_uniform(&g) * n)], &nodes[2].lo, &nodes[2].hi);
            int any[2] = {0, 0}, by_beam[2];
            for (int k = 0; k < 2; k++) {
                for (int q = 0; q < n; q++) {
                    slab_ray sr = slab_make(&rays[q]);
                    real enter;
                    any[k] |= slab_box_meets(nodes[1 + k].lo, nodes[1 + k].hi, &sr, 0, INFINITY, &enter);
                }
                by_beam[k] = bvh_beam_meets(&beam, nodes[1 + k].lo, nodes[1 + k].hi);
                ck_assert_msg(!any[k] || by_beam[k], "run %d box %d: a ray meets it, the beam fails it", i, j);
                met += any[k];
                beam_only += by_beam[k] && !any[k];
            }
            /* The pair form: the children's kept flags are the scalar test's. */
            nodes[0].lo = vec_min(nodes[1].lo, nodes[2].lo);
            nodes[0].hi = vec_max(nodes[1].hi, nodes[2].hi);
            nodes[0].first = 1;
            nodes[0].count = 0;
            nodes[1].first = 0;
            nodes[2].first = 1;
            nodes[1].count = nodes[2].count = 1;
            bvh tree;
            memset(&tree, 0, sizeof tree);
            tree.nodes = nodes;
            tree.node_count = 3;
            bvh_node out[3];
            bvh_beam_tree t = {out, 3, -1};
            bvh_beam_prune(&tree, &beam, &t);
            ck_assert_int_ge(t.count, 0);
            if (bvh_beam_meets(&beam, nodes[0].lo, nodes[0].hi))
                for (int k = 0; k < 2; k++)
                    ck_assert_msg(beam_kept(&t, nodes, k) == by_beam[k], "run %d box %d: child %d kept %d, met %d", i,
                                  j, k, beam_kept(&t, nodes, k), by_beam[k]);
        }
    }
    /* Not vacuous: rays meet boxes, the beam fails some, runs were made. */
    ck_assert_int_gt(runs, 2000);
    ck_assert_int_gt(met, 10000);
    ck_assert_int_gt(runs * 40 - met - beam_only, 10000);
    ck_assert_int_lt(refused, 1000);
}
END_TEST

/* The beam refuses what [BVH-BEAM-1] does not cover. */
START_TEST(test_bvh_beam_refuses_other_rays)
{
    rng g = {2302, 0};
    ray rays[4];
    bvh_beam beam;
    beam_run(&g, vec_make(1, 2, 3), vec_normalize(vec_make(1, 1, 1)), 1e-3, 4, rays);
    ck_assert(bvh_beam_bounds(rays, 4, &beam));
    ck_assert(!bvh_beam_bounds(rays, 0, &beam));
    ray other[4];
    memcpy(other, rays, sizeof rays);
    other[2].origin.y = nextafter(other[2].origin.y, 10);
    ck_assert(!bvh_beam_bounds(other, 4, &beam));
    memcpy(other, rays, sizeof rays);
    other[3].tmin = 1e-9;
    ck_assert(!bvh_beam_bounds(other, 4, &beam));
    memcpy(other, rays, sizeof rays);
    other[1].tmax = 1e9;
    ck_assert(!bvh_beam_bounds(other, 4, &beam));
    memcpy(other, rays, sizeof rays);
    other[1].dir.x = -other[1].dir.x;
    ck_assert(!bvh_beam_bounds(other, 4, &beam));
    memcpy(other, rays, sizeof rays);
    other[0].dir.z = 0;
    ck_assert(!bvh_beam_bounds(other, 4, &beam));
}
END_TEST

/* The whole walk's and the pruned walk's answers for ray r (a copy each):
 * the same hit, tmax, tie count, to the bit. */
static void beam_same_nearest(const bvh *b, const bvh_beam_tree *t, const scene_prim *prims, const ray *r, int run,
                              int q, long *hits)
{
    ray rw = *r, rp = *r;
    hit hw, hp;
    int tw = -1, tp = -1;
    int fw = bvh_intersect_ties(b, prims, &rw, &hw, NULL, &tw);
    int fp = bvh_beam_intersect(b, t, prims, &rp, &hp, NULL, &tp);
    ck_assert_msg(fw == fp && tw == tp, "run %d ray %d: met %d, tied %d whole; %d, %d pruned", run, q, fw, tw, fp, tp);
    ck_assert(same_real_bits(rw.tmax, rp.tmax));
    if (!fw)
        return;
    ++*hits;
    ck_assert_msg(hw.prim == hp.prim && hw.part == hp.part, "run %d ray %d: prim %d.%d whole, %d.%d pruned", run, q,
                  hw.prim, hw.part, hp.prim, hp.part);
    ck_assert(same_real_bits(hw.t, hp.t) && same_vec_bits(hw.point, hp.point));
    ck_assert(same_vec_bits(hw.normal, hp.normal) && same_vec_bits(hw.shading_normal, hp.shading_normal));
    ck_assert_int_eq(hw.entering, hp.entering);
}

/* Coplanar parts in y = 5 (a box's top, a triangle and a disk on it) and
 * ten copies of one triangle (more than the tie window holds: the second
 * pass), put over prims[at..at + 13). */
static void beam_ties(scene_prim *prims, int at)
{
    prims[at] = prim_blank(PRIM_BOX);
    prims[at].u.box.lo = vec_make(3, 4, 3);
    prims[at].u.box.hi = vec_make(7, 5, 7);
    prims[at + 1] = prim_blank(PRIM_TRIANGLE);
    prims[at + 1].u.triangle.p[0] = vec_make(2, 5, 2);
    prims[at + 1].u.triangle.p[1] = vec_make(8, 5, 3);
    prims[at + 1].u.triangle.p[2] = vec_make(4, 5, 8);
    prims[at + 2] = prim_blank(PRIM_DISK);
    prims[at + 2].u.disk.center = vec_make(5, 5, 5);
    prims[at + 2].u.disk.normal = vec_make(0, 1, 0);
    prims[at + 2].u.disk.radius = 2;
    for (int k = 3; k < 13; k++) {
        prims[at + k] = prim_blank(PRIM_TRIANGLE);
        prims[at + k].u.triangle.p[0] = vec_make(1, 2, 1);
        prims[at + k].u.triangle.p[1] = vec_make(9, 3, 2);
        prims[at + k].u.triangle.p[2] = vec_make(2, 4, 9);
    }
}

START_TEST(test_bvh_beam_nearest_is_the_whole_walks)
{
    long hits = 0, pruned = 0, smaller = 0;
    for (int sc = 0; sc < 12; sc++) {
        scene_frame *frames;
        int n = 60 + 40 * sc;
        scene_prim *prims = random_scene(2400 + (uint64_t)sc, n, sc % 3, &frames);
        beam_ties(prims, n / 2);
        bvh b;
        ck_assert(bvh_build(&b, prims, n + sc % 3, NULL));
        rng g = {2500 + (uint64_t)sc, 0};
        bvh_node nodes[4096];
        ray rays[64];
        for (int run = 0; run < 150; run++) {
            int m = 1 + (int)(rng_uniform(&g) * 64);
            vec3 eye = run % 3 == 0 ? rng_box(&g, 0, 10) : rng_box(&g, -8, 18);
            vec3 aim = run % 5 == 0 ? vec_make(5, 5, 5) : rng_box(&g, 0, 10);
            if (run % 7 == 0)
                eye = vec_make(rng_range(&g, 3, 7), 9, rng_range(&g, 3, 7));  /* down onto y = 5 */
            double step = run % 6 == 0 ? 0 : pow(10, rng_range(&g, -4, -0.5));
            beam_run(&g, eye, vec_normalize(vec_sub(aim, eye)), step, m, rays);
            bvh_beam beam;
            if (!bvh_beam_bounds(rays, m, &beam))
                continue;
            bvh_beam_tree t = {nodes, 4096, -1};
            bvh_beam_prune(&b, &beam, &t);
            ck_assert_int_ge(t.count, 0);
            pruned++;
            smaller += t.count < b.node_count;
            for (int q = 0; q < m; q++)
                beam_same_nearest(&b, &t, prims, &rays[q], run, q, &hits);
        }
        bvh_free(&b);
        free(prims);
        free(frames);
    }
    ck_assert_int_gt(pruned, 1000);
    ck_assert_int_gt(smaller, pruned / 2);
    ck_assert_int_gt(hits, 20000);
}
END_TEST

/* An exhaustive tree and a full buffer make no pruned tree. */
START_TEST(test_bvh_beam_refused_when_exhaustive_or_full)
{
    scene_frame *frames;
    scene_prim *prims = random_scene(2600, 200, 0, &frames);
    bvh b;
    ck_assert(bvh_build(&b, prims, 200, NULL));
    ray rays[8];
    rng g = {2601, 0};
    beam_run(&g, vec_make(-5, 5, 5), vec_normalize(vec_make(1, 0.3, 0.2)), 0.01, 8, rays);
    bvh_beam beam;
    ck_assert(bvh_beam_bounds(rays, 8, &beam));
    bvh_node nodes[1024];
    bvh_beam_tree t = {nodes, 1024, -1};
    bvh_beam_prune(&b, &beam, &t);
    ck_assert_int_gt(t.count, 2);
    bvh_beam_tree small = {nodes, 2, -1};
    bvh_beam_prune(&b, &beam, &small);
    ck_assert_int_eq(small.count, -1);
    b.exhaustive = 1;
    bvh_beam_prune(&b, &beam, &t);
    ck_assert_int_eq(t.count, -1);
    bvh_free(&b);
    free(prims);
    free(frames);
}
END_TEST

Suite *suite_bvh(void)
{
    Suite *s = suite_create("bvh");
    TCase *tc = tcase_create("bvh");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, test_bvh_intersect_matches_brute_force);
    tcase_add_test(tc, test_bvh_visit_matches_brute_force);
    tcase_add_test(tc, test_bvh_visit_counts_match_brute_force);
    tcase_add_test(tc, test_bvh_any_crossing_as_counts);
    tcase_add_test(tc, test_bvh_visit_stops_early);
    tcase_add_test(tc, test_bvh_parallel_ray_in_flat_box_plane);
    tcase_add_test(tc, test_bvh_flat_huge_triangle_not_culled);
    tcase_add_test(tc, test_bvh_empty_scene);
    tcase_add_test(tc, test_bvh_one_prim_and_planes_only);
    tcase_add_test(tc, test_bvh_identical_prims_tie_to_lowest_index);
    tcase_add_test(tc, test_bvh_tie_window_end_order_free);
    tcase_add_test(tc, test_bvh_moved_candidate_keeps_its_normal);
    tcase_add_test(tc, test_bvh_two_parts_split_by_hand);
    tcase_add_test(tc, test_bvh_deterministic_and_well_formed);
    tcase_add_test(tc, test_bvh_boxes_exact_past_one_axis);
    tcase_add_test(tc, test_bvh_skewed_distribution_depth_bounded);
    tcase_add_test(tc, test_bvh_grid_100k_visits_few_nodes);
    tcase_add_test(tc, test_bvh_inner_root_not_tested);
    tcase_add_test(tc, test_bvh_unmet_sibling_not_entered);
    tcase_add_test(tc, test_slab_box_meets_is_slab_box);
    tcase_add_test(tc, test_slab_pair_meets_is_slab_box);
    tcase_add_test(tc, test_bvh_beam_meets_every_box_a_ray_meets);
    tcase_add_test(tc, test_bvh_beam_refuses_other_rays);
    tcase_add_test(tc, test_bvh_beam_nearest_is_the_whole_walks);
    tcase_add_test(tc, test_bvh_beam_refused_when_exhaustive_or_full);
    suite_add_tcase(s, tc);
    return s;
}
