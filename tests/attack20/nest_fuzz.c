/*
 * nest_fuzz.c - attack 20: root_decides_nothing (bvh.c) and the pair test
 * (slab_pair.h) in the walks.  Random scenes of spheres, boxes, triangles,
 * meshes and planes, framed (scaled, turned, mirrored, moved) or not, at
 * magnitudes 1e-300 .. 1e300 and moved to 1e8: every inner node's
 * children must lie in its box (the premise of leaving the root's test
 * out), and rays (origins on the nodes' slab planes, zero and -0
 * direction components, tmax infinite) must get from the culling walks
 * the nearest hit (t, prim, part, as bits) and the crossings, in order,
 * that the exhaustive walk (b.exhaustive = 1, which never reads a box)
 * gives.  Exit 1 on a difference.  From the repository root after
 * `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/nf \
 *      tests/attack20/nest_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/nf 2000 [SEED]
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "io/scene_file.h"
#include "render/bvh.h"
#include "render/intersect.h"
#include "scene/scene.h"

#define FUZZ_SEED 0x2545F4914F6CDD1Du
#define FUZZ_EVENTS
#include "fuzz_common.h"

static char text[1 << 18];
static int len;
#define ADD(...) (len += snprintf(text + len, sizeof text - (size_t)len, __VA_ARGS__))

static const char *frame(void)
{
    static const char *f[] = {"", "", " scale 2", " scale [1, -2, 0.5]", " rotate [30, 45, 17]", " rotate [0, 90, 0] scale 1e-3",
                              " scale -1 rotate [45, 0, 45]", " scale [1e5, 1, 1]"};
    return f[RI(0, 7)];
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

int main(int argc, char **argv)
{
    int scenes = argc > 1 ? atoi(argv[1]) : 100;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10);
    const char *dir = getenv("NF_DIR") ? getenv("NF_DIR") : "/tmp/a20nf.d";
    mkdir(dir, 0777);
    char spath[512], mpath[512];
    snprintf(spath, sizeof spath, "%s/n.scene", dir);
    snprintf(mpath, sizeof mpath, "%s/m.obj", dir);
    FILE *mf = fopen(mpath, "w");
    fputs("v 0.5 0 0\nv -0.5 0 0\nv 0 0.5 0\nv 0 -0.5 0\nv 0 0 0.5\nv 0 0 -0.5\n"
          "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n", mf);
    fclose(mf);
    static const double Ts[] = {0, 0, 0, 1e3, 1e8, -3e7, 0.5};
    static const double Ss[] = {1, 1, 1, 1e-6, 1e5, 1e-300, 1e146, 1e-150, 1e140, 0x1p-1060};
    long nodes_checked = 0, not_nested = 0, rays_n = 0, bad = 0, made = 0, hits = 0;
    for (int sc = 0; sc < scenes; sc++) {
        double T = pick(Ts, 7), S = pick(Ss, 10);
        if (S < 1e-20 || S > 1e20) T = U() < 0.5 ? 0 : T * S;
        len = 0;
        ADD("image { width 1 height 1 }\ncamera { eye [0, 0, 100] look_at [0, 0, 0] }\n");
        int n = RI(1, 30);
        for (int i = 0; i < n; i++) {
            double x = T + S * L4(-8, 8), y = T + S * L4(-8, 8), z = T + S * L4(-8, 8), w = S * L4(1, 4);
            switch (RI(0, 5)) {
            case 0: ADD("sphere { center [%.17g, %.17g, %.17g] radius %.17g%s }\n", x, y, z, w, frame()); break;
            case 1: ADD("box { from [%.17g, %.17g, %.17g] to [%.17g, %.17g, %.17g]%s }\n", x, y, z, x + w, y + w, z + w, frame()); break;
            case 2: ADD("triangle { vertices [%.17g, %.17g, %.17g] [%.17g, %.17g, %.17g] [%.17g, %.17g, %.17g]%s }\n", x, y, z, x + w, y, z, x, y + w, z + w, frame()); break;
            case 3: ADD("mesh { file \"m.obj\" scale %.17g%s translate [%.17g, %.17g, %.17g] }\n", S * L4(1, 8), frame(), x, y, z); break;
            case 4: if (U() < 0.3) ADD("plane { point [%.17g, %.17g, %.17g] normal [0, 1, 0] }\n", x, y, z); break;
            default: ADD("disk { center [%.17g, %.17g, %.17g] normal [1, 1, 0] radius %.17g%s }\n", x, y, z, w, frame()); break;
            }
        }
        int status;
        scene_model *s = scene_file_load_text(spath, text, (size_t)len, NULL, NULL, 0, &status);
        if (!s)
            continue;
        bvh b;
        if (!bvh_build(&b, s->prims, s->prim_count, NULL)) {
            scene_free(s);
            continue;
        }
        made++;
        for (int k = 0; k < b.node_count; k++) {
            const bvh_node *nd = &b.nodes[k];
            if (nd->count > 0)
                continue;
            for (int c = 0; c < 2; c++) {
                const bvh_node *ch = &b.nodes[nd->first + c];
                nodes_checked++;
                if (!(ch->lo.x >= nd->lo.x && ch->lo.y >= nd->lo.y && ch->lo.z >= nd->lo.z && ch->hi.x <= nd->hi.x &&
                      ch->hi.y <= nd->hi.y && ch->hi.z <= nd->hi.z)) {
                    if (not_nested < 5)
                        printf("NOT NESTED scene %d node %d child %d\n", sc, k, nd->first + c);
                    not_nested++;
                }
            }
        }
        for (int k = 0; k < 300 && b.node_count > 0; k++) {
            /* an origin on some node's slab planes, or anywhere */
            const bvh_node *nd = &b.nodes[RI(0, b.node_count - 1)];
            double o[3], d[3];
            const double lo[3] = {nd->lo.x, nd->lo.y, nd->lo.z}, hi[3] = {nd->hi.x, nd->hi.y, nd->hi.z};
            for (int a = 0; a < 3; a++) {
                int q = RI(0, 4);
                o[a] = q == 0 ? lo[a] : q == 1 ? hi[a] : q == 2 ? T + S * L4(-10, 10) : lo[a] + (hi[a] - lo[a]) * U();
                if (q == 4) o[a] = nextafter(lo[a], -INFINITY);
                int e = RI(0, 5);
                d[a] = e == 0 ? 0.0 : e == 1 ? -0.0 : e == 2 ? 0x1p-1070 : 2 * U() - 1;
            }
            if (d[0] == 0 && d[1] == 0 && d[2] == 0)
                d[RI(0, 2)] = U() < 0.5 ? 1 : -1;
            double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            ray r;
            r.origin = vec_make(o[0], o[1], o[2]);
            r.dir = vec_make(d[0] / l, d[1] / l, d[2] / l);
            if (!isfinite(r.origin.x) || !isfinite(r.origin.y) || !isfinite(r.origin.z))
                continue;
            r.tmin = U() < 0.5 ? 0 : S * 1e-9;
            r.tmax = U() < 0.5 ? INFINITY : S * L4(1, 40);
            ray r1 = r, r2 = r;
            hit h1, h2;
            memset(&h1, 0, sizeof h1);
            memset(&h2, 0, sizeof h2);
            b.exhaustive = 0;
            int f1 = bvh_intersect(&b, s->prims, &r1, &h1);
            static events e1, e2;
            e1.count = e2.count = 0;
            bvh_visit_counts(&b, s->prims, &r, record, &e1, NULL);
            b.exhaustive = 1;
            int f2 = bvh_intersect(&b, s->prims, &r2, &h2);
            bvh_visit_counts(&b, s->prims, &r, record, &e2, NULL);
            b.exhaustive = 0;
            rays_n++;
            hits += f1;
            int ok = f1 == f2 && (!f1 || (same_bits(h1.t, h2.t) && h1.prim == h2.prim && h1.part == h2.part &&
                                          same_bits(r1.tmax, r2.tmax)));
            ok = ok && same_events(&e1, &e2);
            if (!ok) {
                if (bad < 5) {
                    printf("DIFFER scene %d ray %d: culling %d (t %a prim %d), exhaustive %d (t %a prim %d); crossings %d/%d\n", sc, k,
                           f1, h1.t, h1.prim, f2, h2.t, h2.prim, e1.count, e2.count);
                    printf("  origin %a %a %a dir %a %a %a tmin %a tmax %a\n", r.origin.x, r.origin.y, r.origin.z, r.dir.x,
                           r.dir.y, r.dir.z, r.tmin, r.tmax);
                    keep_text(dir, bad, text, len);
                }
                bad++;
            }
        }
        bvh_free(&b);
        scene_free(s);
    }
    printf("nest_fuzz: %d scenes (%ld built), %ld children checked, %ld not nested, %ld rays (%ld hit), %ld differ\n", scenes,
           made, nodes_checked, not_nested, rays_n, hits, bad);
    return bad != 0 || not_nested != 0;
}
