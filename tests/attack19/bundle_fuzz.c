/*
 * bundle_fuzz.c - attack 19: [SHADE-SHORTCUT-BUNDLE-1]'s box parts (leaf_skip,
 * box_behind, the runs) against the whole walk, on adversarial bundles:
 * boxes on a lattice of 0.25 (exact), so faces, shading points and light
 * targets share coordinates (grazing rays along faces, targets on face
 * planes and at the light box's corners); the lattice scaled by 1e-6 .. 1e5
 * and moved up to 1e8; shading points on box faces (exact face coordinate,
 * ray_shadow_start's own offset) or anywhere with a random normal; flat
 * (rectangle) and solid target boxes.  Each ray's bvh_visit_counts_bundle
 * must report the crossings of bvh_visit_counts, in order.  Exit 1 on a
 * difference.  Build and run from the repository root after `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/bf \
 *      tests/attack19/bundle_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/bf 300 [SEED]
 * ae0ba50: 40000 scenes (seeds default and 7), 192000000 rays, 0 differ; with
 * bundle_cone.gap = 0 (margin kept) 58210 of 24000000 differ (5000 scenes),
 * with margin and gap 0 35508 of 9600000 (2000 scenes): it can fail.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "render/bvh.h"
#include "render/intersect.h"
#include "scene/scene.h"

#define FUZZ_EVENTS
#include "../attack20/fuzz_common.h"

static vec3 lat(double T, double S, double x, double y, double z) { return vec_make(T + S * x, T + S * y, T + S * z); }

int main(int argc, char **argv)
{
    int scenes = argc > 1 ? atoi(argv[1]) : 100;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10);
    long rays_n = 0, bad = 0, bundles = 0, skipped = 0, exacts = 0;
    static char text[65536];
    static const double Ts[] = {0, 0, 1e3, 1e6, 1e8, -3e7, 0.5};
    static const double Ss[] = {1, 1, 1e-6, 1e-3, 1e5, 3};
    for (int sc = 0; sc < scenes; sc++) {
        double T = pick(Ts, 7), S = pick(Ss, 6);
        int len = snprintf(text, sizeof text, "image { width 1 height 1 }\ncamera { eye [0, 0, 100] look_at [0, 0, 0] }\n");
        int nb = RI(1, 60);
        for (int i = 0; i < nb; i++) {
            double x = RI(-8, 8) * 0.25, y = RI(-8, 8) * 0.25, z = RI(-8, 8) * 0.25;
            double w = RI(1, 4) * 0.25, h = RI(1, 8) * 0.25, d = RI(1, 4) * 0.25;
            vec3 lo = lat(T, S, x, y, z), hi = lat(T, S, x + w, y + h, z + d);
            len += snprintf(text + len, sizeof text - (size_t)len,
                            "box { from [%.17g, %.17g, %.17g] to [%.17g, %.17g, %.17g] material { Kd 0.5 t %s } }\n",
                            lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, U() < 0.5 ? "0.5" : "0");
        }
        for (int i = 0; i < RI(0, 5); i++) {
            vec3 c = lat(T, S, RI(-8, 8) * 0.25, RI(-8, 8) * 0.25, RI(-8, 8) * 0.25);
            len += snprintf(text + len, sizeof text - (size_t)len,
                            "sphere { center [%.17g, %.17g, %.17g] radius %.17g material { Kd 0.5 t 0.5 } }\n", c.x, c.y,
                            c.z, 0.25 * S);
        }
        int status;
        scene_model *s = scene_file_load_text("f.scene", text, (size_t)len, NULL, NULL, 0, &status);
        if (!s) {
            fprintf(stderr, "load failed %d\n%s", status, text);
            return 2;
        }
        bvh b;
        if (!bvh_build(&b, s->prims, s->prim_count, NULL))
            return 2;
        for (int k = 0; k < 100; k++) {
            /* the shading point */
            shadow_start from;
            if (U() < 0.7) {
                int pi = RI(0, nb - 1);
                const scene_prim *p = &s->prims[pi];
                if (p->kind != PRIM_BOX)
                    continue;
                int a = RI(0, 2), out = RI(0, 1);
                double f[3];
                for (int j = 0; j < 3; j++)
                    f[j] = U() < 0.3 ? RI(0, 4) * 0.25 : U();
                vec3 lo = p->u.box.lo, hi = p->u.box.hi, q;
                q = vec_make(lo.x + (hi.x - lo.x) * f[0], lo.y + (hi.y - lo.y) * f[1], lo.z + (hi.z - lo.z) * f[2]);
                if (a == 0) q.x = out ? hi.x : lo.x;
                if (a == 1) q.y = out ? hi.y : lo.y;
                if (a == 2) q.z = out ? hi.z : lo.z;
                hit h;
                memset(&h, 0, sizeof h);
                h.point = q;
                h.normal = vec_make(a == 0 ? (out ? 1 : -1) : 0, a == 1 ? (out ? 1 : -1) : 0, a == 2 ? (out ? 1 : -1) : 0);
                h.shading_normal = h.normal;
                h.prim = pi;
                from = ray_shadow_start(p, &h);
            } else {
                hit h;
                memset(&h, 0, sizeof h);
                h.point = lat(T, S, RI(-12, 12) * 0.25 + (U() < 0.5 ? 0 : U()), RI(-12, 12) * 0.25, RI(-12, 12) * 0.25);
                double zz = 2 * U() - 1, an = 6.283185307179586 * U(), rr = sqrt(1 - zz * zz);
                h.normal = U() < 0.5 ? vec_make(rr * cos(an), rr * sin(an), zz) : vec_make(0, 1, 0);
                h.shading_normal = h.normal;
                h.prim = 0;
                from = ray_shadow_start(&s->prims[0], &h);
                from.point = h.point;
                from.normal = h.normal;
            }
            /* the target box: lattice corners, flat on some axis or not */
            double x0 = RI(-12, 12) * 0.25, y0 = RI(-12, 12) * 0.25, z0 = RI(-12, 12) * 0.25;
            double dx = RI(0, 4) * 0.25, dy = U() < 0.6 ? 0 : RI(0, 4) * 0.25, dz = RI(0, 4) * 0.25;
            if (U() < 0.1) { x0 *= 1e3; y0 = 2e3; }
            vec3 tlo = lat(T, S, x0, y0, z0), thi = lat(T, S, x0 + dx, y0 + dy, z0 + dz);
            vec3 n = from.normal;
            bvh_bundle_rays rays = bundle_rays_toward(&from, tlo, thi);
            enum { R = 48 };
            ray r[R];
            vec3 up = ray_shadow_origin(&from, n), down = ray_shadow_origin(&from, vec_neg(n));
            int ups = 0, downs = 0;
            for (int j = 0; j < R; j++) {
                double fx = j < 8 ? (j & 1) : U() < 0.3 ? RI(0, 4) * 0.25 : U();
                double fy = j < 8 ? (j >> 1 & 1) : U() < 0.3 ? RI(0, 4) * 0.25 : U();
                double fz = j < 8 ? (j >> 2 & 1) : U() < 0.3 ? RI(0, 4) * 0.25 : U();
                vec3 q = vec_make(tlo.x + (thi.x - tlo.x) * fx, tlo.y + (thi.y - tlo.y) * fy, tlo.z + (thi.z - tlo.z) * fz);
                if (q.x > thi.x) q.x = thi.x;
                if (q.y > thi.y) q.y = thi.y;
                if (q.z > thi.z) q.z = thi.z;
                r[j] = ray_shadow_to(&from, q);
                ups += r[j].origin.x == up.x && r[j].origin.y == up.y && r[j].origin.z == up.z;
                downs += r[j].origin.x == down.x && r[j].origin.y == down.y && r[j].origin.z == down.z;
            }
            rays.exact = ups == R || downs == R;
            rays.origin = ups == R ? up : down;
            bvh_bundle bundle;
            if (!bundle_counted(&b, &rays, &bundle, &bundles, &exacts))
                continue;
            for (int j = 0; j < R; j++) {
                if (!(r[j].tmax > 0))
                    continue;
                static events whole, part;
                bvh_stats sw = {0, 0}, sp = {0, 0};
                whole.count = part.count = 0;
                bvh_visit_counts(&b, s->prims, &r[j], record, &whole, &sw);
                bvh_visit_counts_bundle(&b, s->prims, &r[j], &bundle, record, &part, &sp);
                rays_n++;
                skipped += sw.prims_tested - sp.prims_tested;
                int same = same_events(&whole, &part);
                if (!same) {
                    if (bad < 5) {
                        printf("DIFFER scene %d (T %g S %g) bundle %d ray %d: whole %d events, bundle %d\n", sc, T, S, k,
                               j, whole.count, part.count);
                        printf("  point %.17g %.17g %.17g normal %g %g %g offset %.17g exact %d\n", from.point.x,
                               from.point.y, from.point.z, n.x, n.y, n.z, from.offset, rays.exact);
                    }
                    bad++;
                }
            }
        }
        bvh_free(&b);
        scene_free(s);
    }
    printf("bundle_fuzz: %d scenes, %ld bundles (%ld exact), %ld rays, %ld part tests saved, %ld differ\n", scenes,
           bundles, exacts, rays_n, skipped, bad);
    return bad != 0;
}
