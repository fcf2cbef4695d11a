/*
 * Polygons that are not plainly simple (src/lang/polygon.c, spec/language.md
 * section 8, [MESH-POLY-2] to [MESH-POLY-4]): corners written twice in a
 * row, spikes out and back, polygons through one place twice (a pinch, a
 * keyhole's bridge), coordinates near the ends of the doubles.
 *
 * A cut is judged by what it covers, not by its triangles: every test
 * point of a grid must lie in exactly one triangle when it is inside the
 * polygon's region and in none when outside.  The regions are worked out
 * by hand (boxes) or, for the random polygons, built first as a set of
 * grid cells whose boundary is then written as the face; the points sit
 * at offsets that put none on a line through two corners.  Each polygon is
 * cut from several starting corners and in both windings: the cover must
 * not depend on either (tests/attack14 findings 1, 2 and 4).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "testlib.h"
#include "lang/polygon.h"

enum { MAX_CORNERS = 512 };

/* A region as boxes [x0, x1] x [y0, y1] whose insides do not overlap. */
typedef struct box {
    double x0, y0, x1, y1;
} box;

/* A region as cells [x, x+1] x [y, y+1] of a G x G grid. */
enum { G = 7 };
typedef struct cells {
    unsigned char in[G][G];
} cells;

typedef struct region {
    const box *boxes;
    int box_count;
    const cells *grid;
    const vec3 *outline; /* a polygon, inside by the even-odd rule */
    int outline_count;
} region;

static int in_region(const region *r, double x, double y)
{
    for (int i = 0; i < r->box_count; i++)
        if (x > r->boxes[i].x0 && x < r->boxes[i].x1 && y > r->boxes[i].y0 && y < r->boxes[i].y1)
            return 1;
    if (r->outline) {
        int in = 0;
        for (int i = 0, j = r->outline_count - 1; i < r->outline_count; j = i++) {
            vec3 a = r->outline[i], b = r->outline[j];
            if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x)
                in = !in;
        }
        return in;
    }
    if (r->grid && x > 0 && y > 0 && x < G && y < G)
        return r->grid->in[(int)x][(int)y];
    return 0;
}

static double cross_z(vec3 a, vec3 b, vec3 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/* Whether (x, y) lies strictly inside triangle t, either way round. */
static int in_triangle(const vec3 *at, const int *t, double x, double y)
{
    vec3 p = vec_make(x, y, 0);
    double s0 = cross_z(at[t[0]], at[t[1]], p), s1 = cross_z(at[t[1]], at[t[2]], p);
    double s2 = cross_z(at[t[2]], at[t[0]], p);
    return (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
}

/* polygon_triangulate with scratch of its own. */
static int cut_face(const vec3 *at, int n, int (*t)[3], int *flags)
{
    polygon_work w;
    polygon_work_init(&w, NULL);
    int count = polygon_triangulate(at, n, &w, t, flags);
    polygon_work_free(&w);
    return count;
}

/*
 * Cuts the n corners at[] (at z = 0) and checks the cut against the
 * region: no flag, every triangle wound as the face (sign +1
 * counter-clockwise, -1 clockwise), every point of a grid of `step`
 * covered once inside the region and never outside.  `what` names the
 * case in messages.
 */
static void assert_cut_covers(const vec3 *at, int n, const region *r, double sign, double step, const char *what)
{
    static int t[MAX_CORNERS][3];
    int flags, count = cut_face(at, n, t, &flags);
    ck_assert_msg(count >= 1 && count <= n - 2, "%s: %d triangles from %d corners", what, count, n);
    ck_assert_msg(flags == 0, "%s: flags %d", what, flags);
    for (int k = 0; k < count; k++)
        ck_assert_msg(sign * cross_z(at[t[k][0]], at[t[k][1]], at[t[k][2]]) > 0, "%s: triangle %d wound the wrong way",
                      what, k);
    for (double y = -1.5 + 0.0371828; y < G + 1.5; y += step)
        for (double x = -1.5 + 0.0123457; x < G + 1.5; x += step) {
            int covered = 0;
            for (int k = 0; k < count; k++)
                covered += in_triangle(at, t[k], x, y);
            ck_assert_msg(covered == in_region(r, x, y), "%s: (%g, %g) covered %d times, %s the region", what, x, y,
                          covered, in_region(r, x, y) ? "inside" : "outside");
        }
}

/* The face from corner `start` on, reversed when `reverse`, then cut. */
static void assert_turned_covers(const vec3 *face, int n, const region *r, int start, int reverse, double step,
                                 const char *what)
{
    static vec3 at[MAX_CORNERS];
    for (int i = 0; i < n; i++)
        at[i] = reverse ? face[(start + n - i) % n] : face[(start + i) % n];
    char name[160];
    snprintf(name, sizeof name, "%s from corner %d%s", what, start, reverse ? ", reversed" : "");
    assert_cut_covers(at, n, r, reverse ? -1 : 1, step, name);
}

/* From every starting corner, both ways round. */
static void assert_always_covers(const vec3 *face, int n, const region *r, const char *what)
{
    for (int start = 0; start < n; start++)
        for (int reverse = 0; reverse < 2; reverse++)
            assert_turned_covers(face, n, r, start, reverse, 0.125, what);
}

/* ---- faces worked out by hand ------------------------------------------- */

/* [MESH-POLY-2] tests/attack14/L_repeat.obj: the L hexagon (0 0) (4 0) (4 1)
 * (2 1) (2 1.75) (0 1.75) with its corners 3 and 5 written twice in a row
 * ("f 1 2 3 3 4 5 5 6").  Before, the repeats blocked every ear, the face
 * was fanned with a false "crosses itself" and 93 pixels were lit outside
 * the L. */
static const vec3 l_repeat[8] = {{0, 0, 0}, {4, 0, 0},    {4, 1, 0},    {4, 1, 0},
                                 {2, 1, 0}, {2, 1.75, 0}, {2, 1.75, 0}, {0, 1.75, 0}};
static const box l_boxes[2] = {{0, 0, 4, 1}, {0, 1, 2, 1.75}};

/* [MESH-POLY-2] tests/attack14/spike.obj: the square [0, 4]^2 with a spike
 * out from (4 2) to (5.5 2) and back.  Before, a triangle reached out to
 * the tip.  Then a spike in from a corner to the middle, back not all the
 * way (to (3 3)), on to (0 4); and one out from a corner to (5 5) and back. */
static const vec3 spike_out[7] = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {5.5, 2, 0}, {4, 2, 0}, {4, 4, 0}, {0, 4, 0}};
static const vec3 spike_in[7] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 2, 0}, {3, 3, 0}, {4, 4, 0}, {0, 4, 0}};
static const vec3 spike_corner[6] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {5, 5, 0}, {4, 4, 0}, {0, 4, 0}};
static const box square[1] = {{0, 0, 4, 4}};

/* [MESH-POLY-3] tests/attack14/pinch.obj: two 2 x 2 squares touching at
 * (2 2), one face through that corner twice.  Before, 2 of its 8 starting
 * corners lit 231 pixels in the empty quarters between the squares. */
static const vec3 pinch[8] = {{2, 0, 0}, {2, 2, 0}, {4, 2, 0}, {4, 4, 0}, {2, 4, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 0}};
static const box squares[2] = {{0, 0, 2, 2}, {2, 2, 4, 4}};

/* [MESH-POLY-3] The square [0, 4]^2 with the hole [1, 3]^2 (written
 * clockwise), joined by a bridge from (0 0) to (1 1) and back. */
static const vec3 keyhole[10] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 0},
                                 {1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}, {1, 1, 0}};
static const box ring[4] = {{0, 0, 4, 1}, {0, 3, 4, 4}, {0, 1, 1, 3}, {3, 1, 4, 3}};

/* [MESH-POLY-3] Two squares joined by a corridor of no width, (1 1) to
 * (3 3) and back: the corridor is outside on both sides. */
static const vec3 corridor[10] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {3, 3, 0}, {4, 3, 0},
                                  {4, 4, 0}, {3, 4, 0}, {3, 3, 0}, {1, 1, 0}, {0, 1, 0}};
static const box apart[2] = {{0, 0, 1, 1}, {3, 3, 4, 4}};

/* [MESH-POLY-3] A C whose upper arm dips to touch the top side of the lower
 * one at (2 1): a corner on another edge, no place written twice, so the
 * classic test, with a pocket outside left of the touch.  Judged by the
 * even-odd rule on the outline itself. */
static const vec3 touch[9] = {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 2, 0},
                              {2, 1, 0}, {3, 2, 0}, {3, 3, 0}, {0, 3, 0}};

static const struct {
    const char *what;
    const vec3 *face;
    int n;
    region r;
} by_hand[] = {
    {"L with two corners repeated", l_repeat, 8, {l_boxes, 2, NULL, NULL, 0}},
    {"square with a spike out", spike_out, 7, {square, 1, NULL, NULL, 0}},
    {"square with a spike in", spike_in, 7, {square, 1, NULL, NULL, 0}},
    {"square with a spike from a corner", spike_corner, 6, {square, 1, NULL, NULL, 0}},
    {"two squares at a corner", pinch, 8, {squares, 2, NULL, NULL, 0}},
    {"keyhole", keyhole, 10, {ring, 4, NULL, NULL, 0}},
    {"two squares and a corridor", corridor, 10, {apart, 2, NULL, NULL, 0}},
    {"C touching itself on a side", touch, 9, {NULL, 0, NULL, touch, 9}},
};

START_TEST(test_polygon_covers_its_region)
{
    /* Each face of the table from every corner, both ways round. */
    for (size_t k = 0; k < sizeof by_hand / sizeof by_hand[0]; k++)
        assert_always_covers(by_hand[k].face, by_hand[k].n, &by_hand[k].r, by_hand[k].what);
}
END_TEST

START_TEST(test_polygon_repeated_corners)
{
    /* [MESH-POLY-2] The L with repeats is the hexagon's 4 triangles; with
     * every corner written three times and the last the same as the first,
     * too.  A quad with one corner written twice is its triangle; a face
     * whose corners are two places has no area. */
    int t[17][3], flags;
    ck_assert_int_eq(cut_face(l_repeat, 8, t, &flags), 4);
    ck_assert_int_eq(flags, 0);
    static const int hexagon[6] = {0, 1, 2, 4, 5, 7};
    vec3 thrice[19];
    for (int i = 0; i < 18; i++)
        thrice[i] = l_repeat[hexagon[i / 3]];
    thrice[18] = l_repeat[0];
    const region r = {l_boxes, 2, NULL, NULL, 0};
    assert_always_covers(thrice, 19, &r, "L with every corner thrice");
    ck_assert_int_eq(cut_face(thrice, 19, t, &flags), 4);
    static const vec3 quad[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    ck_assert_int_eq(cut_face(quad, 4, t, &flags), 1);
    ck_assert_int_eq(flags, 0);
    ck_assert(t[0][0] == 0 && t[0][1] == 1 && t[0][2] == 3);
    static const vec3 two[4] = {{0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {1, 1, 0}};
    ck_assert_int_eq(cut_face(two, 4, t, &flags), 0);
    ck_assert_int_eq(flags, POLYGON_NO_AREA);
}
END_TEST

START_TEST(test_polygon_spike_tip_unused)
{
    /* [MESH-POLY-2] Without its spike the square has a corner on its right
     * side, (4 2): 3 triangles, none at the tip (corner 3). */
    int t[5][3], flags;
    ck_assert_int_eq(cut_face(spike_out, 7, t, &flags), 3);
    ck_assert_int_eq(flags, 0);
    for (int k = 0; k < 3; k++)
        ck_assert(t[k][0] != 3 && t[k][1] != 3 && t[k][2] != 3);
}
END_TEST

START_TEST(test_polygon_scale_free)
{
    /* [MESH-POLY-4] tests/attack14/quad_far.obj: the unit square written
     * in units of 1e160 (its cross products would pass 1e308) or 1e-170
     * (they would fall under the smallest double), down to 1e-310 (a
     * subnormal, where 2^-e itself would pass the largest double), has the
     * area it has at size 1: 2 triangles, the same corners; the L of 4
     * triangles too. */
    static const vec3 quad[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    static const vec3 l[6] = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
    static const double units[5] = {1e160, 1e-170, 1e300, 1e-300, 1e-310};
    int want[4][3], got[4][3], flags;
    for (int shape = 0; shape < 2; shape++) {
        const vec3 *face = shape ? l : quad;
        int n = shape ? 6 : 4, count = cut_face(face, n, want, &flags);
        ck_assert_int_eq(count, n - 2);
        for (int u = 0; u < 5; u++) {
            vec3 at[6];
            for (int i = 0; i < n; i++)
                at[i] = vec_add(vec_make(3 * units[u], -units[u], 0), vec_scale(face[i], units[u]));
            ck_assert_int_eq(cut_face(at, n, got, &flags), n - 2);
            ck_assert_int_eq(flags, 0);
            ck_assert(memcmp(got, want, sizeof(int[3]) * (size_t)(n - 2)) == 0);
        }
    }
}
END_TEST

/* ---- random polygons of grid cells --------------------------------------- */

static int cell_in(const cells *c, int x, int y)
{
    return x >= 0 && y >= 0 && x < G && y < G && c->in[x][y];
}

/* Random cells, then only those joined to the first one through sides or
 * corners: a region that may touch itself at corners (a pinch). */
static void random_cells(uint64_t seed, cells *c)
{
    cells all;
    int stack[G * G], top = 0, first = -1;
    for (int i = 0; i < G * G; i++) {
        all.in[i / G][i % G] = test_mix(seed * 1000 + (uint64_t)i) % 100 < 55;
        if (all.in[i / G][i % G] && first < 0)
            first = i;
    }
    memset(c, 0, sizeof *c);
    if (first < 0)
        return;
    stack[top++] = first;
    c->in[first / G][first % G] = 1;
    while (top > 0) {
        int i = stack[--top];
        for (int dx = -1; dx <= 1; dx++)
            for (int dy = -1; dy <= 1; dy++) {
                int x = i / G + dx, y = i % G + dy;
                if (cell_in(&all, x, y) && !c->in[x][y]) {
                    c->in[x][y] = 1;
                    stack[top++] = x * G + y;
                }
            }
    }
}

/* The boundary edge leaving grid point (x, y) in direction d (0 east,
 * 1 north, 2 west, 3 south) with the region on its left. */
static int boundary_edge(const cells *c, int x, int y, int d)
{
    switch (d) {
    case 0:
        return cell_in(c, x, y) && !cell_in(c, x, y - 1);
    case 1:
        return cell_in(c, x - 1, y) && !cell_in(c, x, y);
    case 2:
        return cell_in(c, x - 1, y - 1) && !cell_in(c, x - 1, y);
    default:
        return cell_in(c, x, y - 1) && !cell_in(c, x - 1, y - 1);
    }
}

/*
 * The region's boundary as one face, counter-clockwise, every grid point on
 * it a corner: from the lowest cell's lower edge, at each point the most
 * rightward boundary edge, which passes through a pinch into the other
 * part instead of closing a loop.  Returns the corners, or 0 when the
 * boundary is more than one loop (a hole).
 */
static int trace(const cells *c, vec3 *at, int *visits)
{
    int edges = 0, x0 = -1, y0 = 0;
    for (int x = 0; x <= G; x++)
        for (int y = 0; y <= G; y++)
            for (int d = 0; d < 4; d++)
                edges += boundary_edge(c, x, y, d);
    for (int x = 0; x < G && x0 < 0; x++)
        for (int y = 0; y < G && x0 < 0; y++)
            if (c->in[x][y] && !cell_in(c, x, y - 1))
                x0 = x, y0 = y;
    static const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
    int n = 0, x = x0, y = y0, d = 0;
    memset(visits, 0, sizeof(int) * (G + 1) * (G + 1));
    do {
        at[n++] = vec_make(x, y, 0);
        visits[x * (G + 1) + y]++;
        x += dx[d], y += dy[d];
        for (int turn = 3; turn <= 5; turn++)
            if (boundary_edge(c, x, y, (d + turn) % 4)) {
                d = (d + turn) % 4;
                break;
            }
    } while ((x != x0 || y != y0 || d != 0) && n < MAX_CORNERS / 2);
    return n == edges ? n : 0;
}

/*
 * The traced face with some corners dropped (those on a straight run: a
 * corner inside an edge is kept by the cut, so half are kept), some written
 * twice, and spikes to the middle of a cell beside a corner the face passes
 * once (in or out of the region: in a cell, nothing of the boundary is in
 * the way).
 */
static int decorate(uint64_t seed, const vec3 *in, int n, const int *visits, vec3 *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        vec3 p = in[(i + n - 1) % n], v = in[i], q = in[(i + 1) % n];
        uint64_t r = test_mix(seed * 7919 + (uint64_t)i);
        if (cross_z(p, v, q) == 0 && r % 2 == 0)
            continue;
        out[m++] = v;
        if (r % 7 == 1)
            out[m++] = v;
        if (r % 9 == 2 && visits[(int)v.x * (G + 1) + (int)v.y] == 1) {
            out[m++] = vec_make(v.x + ((r >> 8) % 2 ? 0.5 : -0.5), v.y + ((r >> 9) % 2 ? 0.5 : -0.5), 0);
            out[m++] = v;
        }
    }
    return m;
}

START_TEST(test_polygon_random_cells)
{
    /* [MESH-POLY-1..3] 700 random regions of grid cells, joined through
     * sides or corners (so with pinches), written as one face with corners
     * repeated and spikes: each cut from 6 starting corners, both ways
     * round, covers its cells and nothing else, and is never fanned. */
    static vec3 traced[MAX_CORNERS], face[MAX_CORNERS];
    int visits[(G + 1) * (G + 1)], tested = 0, pinched = 0;
    for (uint64_t seed = 1; seed <= 700; seed++) {
        cells c;
        random_cells(seed, &c);
        int n = trace(&c, traced, visits);
        if (n == 0)
            continue;
        int m = decorate(seed, traced, n, visits, face);
        const region r = {NULL, 0, &c, NULL, 0};
        char what[64];
        snprintf(what, sizeof what, "cells of seed %d (%d corners)", (int)seed, m);
        for (int k = 0; k < 6; k++) {
            int start = (int)(test_mix(seed + 77 * (uint64_t)k) % (uint64_t)m);
            for (int reverse = 0; reverse < 2; reverse++)
                assert_turned_covers(face, m, &r, start, reverse, 0.5, what);
        }
        tested++;
        for (int i = 0; i < (G + 1) * (G + 1); i++)
            if (visits[i] > 1) {
                pinched++;
                break;
            }
    }
    /* The generator must give enough of each kind for this to mean
     * something: one loop (no hole) for most seeds, a pinch for many. */
    ck_assert_int_ge(tested, 200);
    ck_assert_int_ge(pinched, 100);
}
END_TEST

Suite *suite_polygon(void)
{
    Suite *s = suite_create("polygon");
    TCase *tc = tcase_create("weakly simple");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_polygon_covers_its_region);
    tcase_add_test(tc, test_polygon_repeated_corners);
    tcase_add_test(tc, test_polygon_spike_tip_unused);
    tcase_add_test(tc, test_polygon_scale_free);
    tcase_add_test(tc, test_polygon_random_cells);
    suite_add_tcase(s, tc);
    return s;
}
