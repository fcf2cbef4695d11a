/*
 * dark2_fuzz.c - attack 22: [SHADE-SHORTCUT-DARK-2] (trace.c light_dark,
 * light_cells_fill, light_view_fill, light_cell_dark) against add_source's
 * own gates, sample by sample.  trace.c is included for its static
 * functions.  For a random disk light (any normal, radius 1e-6 .. 10 of
 * the scale 1e-6 .. 1e6 (SPAN), moved up to 1e12, 4 .. 4096 samples) and a shaded point
 * (unit N and V, Kd > 0 or Kd = 0 with a lobe of n 1 .. 1e7) placed so
 * that the plane N.(x - P) = 0 or the lobe's edge cuts the disk (P within
 * 1e-6 .. 10 radii of it, or, a quarter of the cases, just outside the
 * light's ball: gap 2^-1 .. 2^-15 of its reach; the cut moved by a random
 * fraction of a cell's reach), every cell light_cell_dark calls dark is
 * sampled: its corners
 * (u1, u2 in {0, 1 - 2^-53}), edge middles, random points and
 * light_point_keyed points of random keys; each point goes through
 * add_source's gate as add_source forms it (vec_length_fast, to * 1/d,
 * N.l > 0, V.reflect(l, N) <= lobe_floor).  A dark cell with a point the
 * gates let through, or one on the point (lights_on_surface), is a
 * defect: exit 1.  Also reports how tight the reach is: the largest
 * |p - C_j| over cell_reach seen.  From the repository root after
 * `make build/refray build/librefray-internal.a`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/d2f \
 *      tests/attack22/dark2_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/d2f 20000 [SEED [FACTOR [SPAN]]]
 * FACTOR (default 1) scales cell_reach: a mutant's check (2/3: 1.0 h for 1.5 h).
 * SPAN (default 6): the scale is 10^-SPAN .. 10^SPAN.
 * -DTRACE_C='"FILE"' includes a patched copy of trace.c in its place (the
 * README's mutants).  Every case also checks the lemma alone: 32 points of
 * random cells against their ball; a point outside it exits 1 too.
 */
#ifndef TRACE_C
#define TRACE_C "../../src/render/trace.c"
#endif
#include TRACE_C
#include <stdio.h>
#include <stdint.h>

#include "../fuzz_rng.h"
static int RI(int a, int b) { return a + (int)(U() * (b - a + 1)); }
static vec3 rnd3(void) { return vec_make(2 * U() - 1, 2 * U() - 1, 2 * U() - 1); }
static vec3 unit3(void)
{
    vec3 a;
    do
        a = rnd3();
    while (vec_length2(a) < 1e-4);
    return vec_normalize(a);
}
static vec3 pick_normal(void)
{
    static const double axes[][3] = {{0, -1, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, -1}, {1, -1e-9, 0},
                                      {1e-300, 1, 0}, {0.3, -1, -0.7}, {1, 1, 1}};
    if (U() < 0.4) {
        int k = RI(0, 8);
        return vec_normalize(vec_make(axes[k][0], axes[k][1], axes[k][2]));
    }
    return unit3();
}

/* add_source's gates for the point at: 1 when the sample would be made
 * (lit, and the lobe not surely 0), 2 when it sits on the point. */
static int gate_passes(const surface *s, vec3 at)
{
    vec3 to = vec_sub(at, s->h->point);
    real d = vec_length_fast(to);
    if (!(d > 0))
        return 2;
    real inv = 1.0 / d;
    vec3 l = inv <= REAL_MAX ? vec_scale(to, inv) : vec_make(to.x / d, to.y / d, to.z / d);
    if (!(vec_dot(s->n, l) > 0))
        return 0;
    if (s->no_body && (!s->highlight || vec_dot(s->v, shade_reflect_about(l, s->n)) <= s->lobe_floor))
        return 0;
    return 1;
}

static const int sample_list[] = {4, 5, 6, 7, 8, 9, 12, 16, 17, 25, 36, 49, 64, 65, 100, 256, 1000, 1024, 4096};
static light_cell cells[TRACE_CELLS_MAX];

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 10000;
    rng = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    /* a mutant's cell reach: the factor 1.5 h replaced by 1.5 h times this */
    double mutant = argc > 3 ? atof(argv[3]) : 1;
    /* the scale 10^-SPAN .. 10^SPAN (default 6) */
    int span = argc > 4 ? atoi(argv[4]) : 6;
    long bad = 0, near = 0, outside = 0, lemma = 0, lobe_cells = 0, dark_cells = 0, some = 0, points = 0, scenes_dark = 0;
    double tight = 0;
    for (long c = 0; c < n; c++) {
        double S = pow(10, RI(-span, span)) * (U() < 0.5 ? 1 : 1 + U());
        double T = U() < 0.5 ? 0 : pow(10, RI(0, 12)) * (U() < 0.5 ? 1 : -1);
        scene_light light;
        memset(&light, 0, sizeof light);
        light.kind = LIGHT_DISK;
        light.position = vec_add(vec_splat(T), vec_scale(rnd3(), S));
        light.normal = pick_normal();
        light.radius = S * pow(10, -6 + 7 * U());
        int samples = sample_list[RI(0, (int)(sizeof sample_list / sizeof *sample_list) - 1)];
        light_setup setup = trace_light_setup(&light, samples);
        if (!(setup.reach >= 0))
            continue;
        light_cells_fill(&light, &setup, cells);
        setup.cell_reach *= mutant;
        /* the shaded point: N, and P so that N's plane cuts the disk near a random cell */
        int j0 = RI(0, samples - 1);
        double a, b, x, y;
        light_cell_point(setup.grid, j0, U(), U(), &a, &b);
        light_concentric(a, b, &x, &y);
        vec3 q = vec_add(light.position, vec_add(vec_scale(setup.t1, x * light.radius), vec_scale(setup.t2, y * light.radius)));
        vec3 N = pick_normal(), V = unit3();
        if (vec_dot(N, V) < 0)
            V = vec_neg(V);
        double far = light.radius * pow(10, -6 + 7 * U());
        vec3 away = unit3();
        /* P's plane through q moved along N by a fraction of the cell reach */
        vec3 along = vec_sub(away, vec_scale(N, vec_dot(away, N)));
        if (vec_length2(along) < 1e-8)
            continue;
        along = vec_normalize(along);
        vec3 P = vec_add(q, vec_scale(along, far + 2 * setup.reach));
        P = vec_add(P, vec_scale(N, setup.cell_reach * (2 * U() - 1) * (U() < 0.5 ? 1 : 1e-3)));
        if (U() < 0.25) {
            /* near: P just outside the light's ball (gap 2^-1 .. 2^-15 of
             * the reach), N's plane through P and q */
            P = vec_add(setup.centre, vec_scale(unit3(), setup.reach * (1 + ldexp(1, -RI(1, 15)))));
            vec3 c = vec_cross(vec_sub(q, P), unit3());
            if (vec_length2(c) == 0)
                continue;
            N = vec_normalize(c);
            if (vec_dot(N, V) < 0)
                N = vec_neg(N);
            P = vec_add(P, vec_scale(N, setup.cell_reach * (2 * U() - 1) * (U() < 0.5 ? 1 : 1e-3)));
            near++;
        }
        hit h;
        memset(&h, 0, sizeof h);
        h.point = P;
        surface s;
        memset(&s, 0, sizeof s);
        s.h = &h;
        s.n = N;
        s.v = V;
        s.no_body = U() < 0.5;
        s.highlight = s.no_body ? U() < 0.8 : 1;
        double shin = pow(10, 7 * U());
        s.lobe_floor = s.no_body && s.highlight ? exp2(-1030 / shin) * (1 - 0x1p-18) : 0;
        if (s.no_body && s.highlight && U() < 0.6) {
            /* the lobe's edge (l.M = floor) through q instead: P = q - dist l
             * for a unit l with l.M = lobe_floor (moved by a fraction of
             * the cell reach), N.l > 0 */
            vec3 m = vec_sub(vec_scale(N, 2 * vec_dot(N, V)), V);
            double ml = vec_length(m), fl = s.lobe_floor / ml;
            vec3 mh = vec_scale(m, 1 / ml), side = unit3();
            side = vec_sub(side, vec_scale(mh, vec_dot(side, mh)));
            if (vec_length2(side) < 1e-8 || fl > 1)
                continue;
            side = vec_normalize(side);
            vec3 l = vec_add(vec_scale(mh, fl), vec_scale(side, sqrt(1 - fl * fl)));
            if (!(vec_dot(N, l) > 0))
                continue;
            double dist = far + 2 * setup.reach;
            h.point = vec_sub(q, vec_scale(l, dist));
            h.point = vec_add(h.point, vec_scale(side, setup.cell_reach * (2 * U() - 1) * (U() < 0.5 ? 1 : 1e-3)));
            P = h.point;
        }
        /* the lemma itself, on every light: a sample of cell j lies within
         * cell_reach of its centre (corners, edge middles, random points) */
        for (int t = 0; t < 32; t++) {
            int j = RI(0, samples - 1);
            double us[4] = {0, 1 - 0x1p-53, 0.5, U()};
            light_cell_point(setup.grid, j, us[t & 3], us[(t >> 2) & 3], &a, &b);
            vec3 p = light_point(&light, setup.t1, setup.t2, a, b);
            vec3 cj = vec_add(light.position, vec_add(vec_scale(setup.t1, cells[j].u), vec_scale(setup.t2, cells[j].v)));
            double f = vec_length(vec_sub(p, cj)) / setup.cell_reach;
            lemma++;
            if (f > tight)
                tight = f;
            if (f > 1) {
                if (outside < 5)
                    printf("case %ld cell %d/%d: a sample at %.6f of the cell's reach\n", c, j, samples, f);
                outside++;
            }
        }
        /* Zeroed whole, as add_distributed zeroes it: since 08143cd
         * light_dark sets only what it finds (with `.some = 0` alone the
         * rest was stale and the run reported false defects). */
        light_view view = {0};
        if (light_dark(&s, &setup, &view)) {
            scenes_dark++;
            continue;
        }
        if (!view.some)
            continue;
        some++;
        light_view_fill(&s, &light, &setup, &view);
        for (int j = 0; j < samples; j++) {
            if (!light_cell_dark(&view, cells[j], setup.cell_reach))
                continue;
            dark_cells++;
            if (!(view.n_at + cells[j].u * view.n_u + cells[j].v * view.n_v + setup.cell_reach * view.n_len <= view.n_lim))
                lobe_cells++;
            for (int k = 0; k < 24; k++) {
                vec3 p;
                if (k < 16) {
                    double us[4] = {0, 1 - 0x1p-53, 0.5, U()};
                    light_cell_point(setup.grid, j, us[k & 3], us[k >> 2], &a, &b);
                    p = light_point(&light, setup.t1, setup.t2, a, b);
                } else {
                    p = light_point_keyed(&light, &setup, R64(), j);
                }
                points++;
                vec3 cj = vec_add(light.position, vec_add(vec_scale(setup.t1, cells[j].u), vec_scale(setup.t2, cells[j].v)));
                double f = vec_length(vec_sub(p, cj)) / setup.cell_reach;
                if (f > tight)
                    tight = f;
                int g = gate_passes(&s, p);
                if (g) {
                    if (bad < 10)
                        printf("case %ld cell %d/%d: %s; P %.17g %.17g %.17g N %.17g %.17g %.17g p %.17g %.17g %.17g\n",
                               c, j, samples, g == 2 ? "on the point" : "the gate lets it through", P.x, P.y, P.z, N.x, N.y,
                               N.z, p.x, p.y, p.z);
                    bad++;
                }
            }
        }
    }
    printf("dark2_fuzz: %ld cases (%ld near the ball), %ld wholly dark, %ld with some cell dark, %ld dark cells (%ld by the lobe alone), %ld points; "
           "largest |p - C|/reach %.4f (%ld lemma points, %ld outside); %ld defects\n",
           n, near, scenes_dark, some, dark_cells, lobe_cells, points, tight, lemma, outside, bad);
    return bad != 0 || outside != 0;
}
