/*
 * tri_fuzz.c - attack 20: [SHADE-SHORTCUT-BUNDLE-1]'s triangles left out
 * (bvh_bundle.c: shear_bounds, corner_boxes, boxes_apart) against the whole
 * walk.  Scenes of triangles and meshes (closed and open, transparent or
 * not, scaled, turned, moved) on a lattice of 0.25 shared with the lights,
 * so edges and corners pass through the light box's corners and edges and
 * lie on the shear axes; lights: rectangles (flat on an axis, point-like,
 * straddling two dominant axes) and disks; the lattice scaled by 1e-300 ..
 * 1e300 and moved up to 1e8.  Shading points are real hits of rays into
 * the scene (ray_shadow_start) or lattice points with any normal.  The
 * bundle is made as light_bundle makes it (trace_light_setup's box,
 * trace_light_side's exact origin) and its rays aim at the light's own
 * samples (trace_light_point) and at the box's corners.  Each ray's
 * bvh_visit_counts_bundle must report the crossings of bvh_visit_counts, in
 * order.  Exit 1 on a difference.  From the repository root after
 * `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/tf \
 *      tests/attack20/tri_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/tf 300 [SEED]
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
#include "render/trace.h"
#include "scene/scene.h"

#define FUZZ_EVENTS
#include "fuzz_common.h"

static double T, S;
static char text[1 << 18];
static int len;
#define ADD(...) (len += snprintf(text + len, sizeof text - (size_t)len, __VA_ARGS__))
static double W(double x) { return T + S * x; }

/* One ray: the bundle walk against the whole one; 1 where they agree. */
static int walks_agree(const bvh *b, const scene_prim *prims, const ray *r, const bvh_bundle *bundle, long *skipped)
{
    static events whole, part;
    bvh_stats sw = {0, 0}, sp = {0, 0};
    whole.count = part.count = 0;
    bvh_visit_counts(b, prims, r, record, &whole, &sw);
    bvh_visit_counts_bundle(b, prims, r, bundle, record, &part, &sp);
    *skipped += sw.prims_tested - sp.prims_tested;
    return same_events(&whole, &part);
}

static const char *dir;

/* A mesh file: closed (octahedron, cube of 12, a doubled sheet) or open (a grid sheet). */
static void mesh_file(int k)
{
    char path[512];
    snprintf(path, sizeof path, "%s/m%d.obj", dir, k);
    FILE *f = fopen(path, "w");
    int kind = RI(0, 3);
    double cx = L4(-8, 8), cy = L4(-8, 8), cz = L4(-8, 8), r = L4(1, 8);
    if (kind == 0) {
        fprintf(f, "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\nv %.17g %.17g %.17g\n", cx + r, cy, cz, cx - r, cy, cz,
                cx, cy + r, cz);
        fprintf(f, "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\nv %.17g %.17g %.17g\n", cx, cy - r, cz, cx, cy, cz + r,
                cx, cy, cz - r);
        fputs("f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n", f);
    } else if (kind == 1) {
        double w = L4(1, 8), h = L4(1, 8), d = L4(1, 8);
        for (int i = 0; i < 8; i++)
            fprintf(f, "v %.17g %.17g %.17g\n", cx + (i & 1) * w, cy + (i >> 1 & 1) * h, cz + (i >> 2 & 1) * d);
        fputs("f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n", f);
    } else {
        int n = RI(2, 6), axis = RI(0, 2);
        for (int i = 0; i <= n; i++)
            for (int j = 0; j <= n; j++) {
                double a = cx + i * 0.25 * RI(1, 2), b = cy + j * 0.25 * RI(1, 2), c = cz + (kind == 3 ? L4(-1, 1) : 0);
                if (axis == 0) fprintf(f, "v %.17g %.17g %.17g\n", c, a, b);
                else if (axis == 1) fprintf(f, "v %.17g %.17g %.17g\n", a, c, b);
                else fprintf(f, "v %.17g %.17g %.17g\n", a, b, c);
            }
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                int a = i * (n + 1) + j + 1, b = a + 1, c = a + n + 1, d = c + 1;
                if (U() < 0.5) fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c);
                else fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, c, b, d, c);
            }
    }
    fclose(f);
}

static const char *mat(void)
{
    static const char *m[] = {"material { Kd 0.5 }", "material { Kd 0.5 t 0.5 ior 1 }", "material { Kd 0.2 t 0.7 ior 1.5 }"};
    return m[RI(0, 2)];
}

static void light(void)
{
    int k = RI(0, 6);
    double px = L4(-8, 8), py = L4(-8, 8), pz = L4(-8, 8);
    if (k == 6) {
        static const char *n[] = {"[0,-1,0]", "[1,0,0]", "[1,0,1]", "[1,1,1]", "[0.6,0,0.8]", "[1,-1,0.3]"};
        ADD("distributed_light { disk [%.17g,%.17g,%.17g] %s %.17g power 1 samples %d }\n", W(px), W(py), W(pz),
            n[RI(0, 5)], S * pick((const double[]){0.25, 1, 1e-9, 2}, 4), RI(1, 17));
        return;
    }
    double u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    if (k <= 2) {   /* flat on an axis */
        int a = RI(0, 2), b = (a + RI(1, 2)) % 3;
        u[a] = L4(1, 8) * (U() < 0.3 ? 1e-9 : 1);
        v[b] = L4(-8, 8);
        if (v[b] == 0) v[b] = 0.25;
    } else if (k == 3) {   /* slanted: straddles dominant axes */
        u[0] = L4(1, 4); u[2] = u[0] * (U() < 0.5 ? 1 : -1);
        v[1] = L4(1, 4);
    } else if (k == 4) {   /* point-like */
        u[RI(0, 2)] = 1e-12;
        v[(RI(0, 1) + 1) % 3] = 1e-12;
        if (u[0] == 0 && u[1] == 0) u[2] = 1e-12;
        if ((u[0] != 0 && v[0] != 0) || (u[1] != 0 && v[1] != 0) || (u[2] != 0 && v[2] != 0)) { v[0] = v[1] = v[2] = 0; v[(u[0] != 0) ? 1 : 0] = 1e-12; }
    } else {
        for (int a = 0; a < 3; a++) { u[a] = L4(-4, 4); v[a] = L4(-4, 4); }
        if (u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 && u[0] * v[1] - u[1] * v[0] == 0) { u[0] = 1; v[1] = 1; u[1] = v[0] = 0; u[2] = v[2] = 0.25; v[2] = 0; }
    }
    ADD("distributed_light { rectangle [%.17g,%.17g,%.17g] [%.17g,%.17g,%.17g] [%.17g,%.17g,%.17g] power 1 samples %d }\n",
        W(px), W(py), W(pz), S * u[0], S * u[1], S * u[2], S * v[0], S * v[1], S * v[2], RI(1, 17));
}

static vec3 nudge3(vec3 v, int k)
{
    return vec_make(nudge(v.x, RI(-k, k)), nudge(v.y, RI(-k, k)), nudge(v.z, RI(-k, k)));
}

/* The tangent mode: triangles built around the bundle's own rays.  A
 * light alone gives the box and the samples; a shading point is put so
 * that a box corner lies at a chosen offset D from the bundle's origin
 * (|D_x| and |D_z| within ulps of each other at times: the dominant axis
 * at its tie); then triangles whose corners lie within ulps of the rays
 * toward the box corners and samples (an edge along a ray, a corner on
 * it, the origin in the triangle's plane), in an open mesh (degenerate
 * ones dropped, not refused). */
static int one_tangent(int sc, long *rays_n, long *bad, long *bundles, long *skipped)
{
    char spath[512], mpath[512];
    snprintf(spath, sizeof spath, "%s/t.scene", dir);
    snprintf(mpath, sizeof mpath, "%s/t.obj", dir);
    len = 0;
    ADD("image { width 1 height 1 }\ncamera { eye [0, 0, 100] look_at [0, 0, 0] }\n");
    light();
    int lightlen = len, status;
    ADD("sphere { center [%.17g, %.17g, %.17g] radius %.17g }\n", W(100), W(100), W(100), S);
    scene_model *s0 = scene_file_load_text(spath, text, (size_t)len, NULL, NULL, 0, &status);
    if (!s0)
        return 0;
    const scene_light *lt0 = &s0->lights[0];
    light_setup setup = trace_light_setup(lt0, lt0->samples);
    if (setup.reach < 0) {
        scene_free(s0);
        return 0;
    }
    vec3 lo = setup.box_lo, hi = setup.box_hi;
    int ci = RI(0, 7);
    vec3 c = vec_make(ci & 1 ? hi.x : lo.x, ci & 2 ? hi.y : lo.y, ci & 4 ? hi.z : lo.z);
    double D[3];
    for (int a = 0; a < 3; a++) D[a] = S * L4(-16, 16) + (U() < 0.3 ? S * U() : 0);
    if (U() < 0.5) {
        int a = RI(0, 2), b = (a + RI(1, 2)) % 3;
        D[b] = nudge(D[a] * (U() < 0.5 ? 1 : -1), RI(-3, 3));
        if (U() < 0.3) { int e = 3 - a - b; D[e] = nudge(D[a] * (U() < 0.5 ? 1 : -1), RI(-3, 3)); }
        if (U() < 0.5) {   /* c: the corner of least |D_a| and greatest |D_b| */
            double la[3] = {lo.x, lo.y, lo.z}, ha[3] = {hi.x, hi.y, hi.z}, cc[3] = {c.x, c.y, c.z};
            cc[a] = D[a] > 0 ? la[a] : ha[a];
            cc[b] = D[b] > 0 ? ha[b] : la[b];
            c = vec_make(cc[0], cc[1], cc[2]);
        }
    }
    shadow_start from;
    vec3 nn[] = {vec_make(0, 1, 0), vec_make(0, -1, 0), vec_make(1, 0, 0), vec_make(0, 0, -1), vec_make(0.6, 0, 0.8),
                 vec_make(0.48, 0.6, 0.64)};
    from.normal = nn[RI(0, 5)];
    from.offset = S * pick((const double[]){0x1p-20, 0x1p-30, 1e-9, 0x1p-40}, 4);
    from.point = vec_make(c.x - D[0], c.y - D[1], c.z - D[2]);
    int side = trace_light_side(&from, &setup);
    if (!side) {
        from.normal = vec_neg(from.normal);
        side = trace_light_side(&from, &setup);
    }
    vec3 O = ray_shadow_origin(&from, side >= 0 ? from.normal : vec_neg(from.normal));
    /* targets: the corners and samples */
    enum { R = 40 };
    vec3 q[R];
    uint64_t key = (uint64_t)(U() * 0x1p53);
    for (int j = 0; j < R; j++) {
        if (j < 8)
            q[j] = vec_make(j & 1 ? hi.x : lo.x, j & 2 ? hi.y : lo.y, j & 4 ? hi.z : lo.z);
        else
            q[j] = trace_light_point(lt0, &setup, 0, key + (uint64_t)j, RI(0, setup.samples - 1));
    }
    vec3 centre = vec_scale(vec_add(lo, hi), 0.5);
    scene_free(s0);
    FILE *f = fopen(mpath, "w");
    int nt = RI(5, 40), nv = 0;
    for (int i = 0; i < nt; i++) {
        vec3 t = q[U() < 0.6 ? RI(0, 7) : RI(0, R - 1)], d = vec_sub(t, O), out = vec_sub(t, centre);
        vec3 w = vec_make(S * (2 * U() - 1), S * (2 * U() - 1), S * (2 * U() - 1));
        double l0 = pick((const double[]){0.5, 0.25, 0.75, 0.125, 1e-3, 0.999}, 6);
        vec3 v0 = nudge3(vec_add(O, vec_scale(d, l0)), 3), v1, v2;
        int kind = RI(0, 4);
        if (kind == 0) {   /* an edge along the ray */
            v1 = nudge3(vec_add(O, vec_scale(d, l0 * 0.5)), 3);
            v2 = vec_add(v0, U() < 0.5 ? out : w);
        } else if (kind == 1) {   /* a corner on the ray, the rest outward */
            v1 = vec_add(v0, vec_scale(out, 0.5 + U()));
            v2 = vec_add(v0, vec_add(vec_scale(out, U()), vec_scale(w, 0.1)));
        } else if (kind == 2) {   /* the origin in the plane */
            v1 = nudge3(vec_add(O, w), 2);
            v2 = nudge3(vec_add(O, vec_scale(w, -1.5 + U())), 2);
            if (U() < 0.5) v2 = vec_add(v0, out);
        } else if (kind == 3) {   /* straddling the ray just barely: two triangles sharing the edge through it */
            vec3 m = vec_add(v0, w);
            v1 = vec_sub(v0, w);
            fprintf(f, "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\nv %.17g %.17g %.17g\nf %d %d %d\n", m.x, m.y, m.z, v1.x,
                    v1.y, v1.z, vec_add(v0, vec_cross(d, w)).x, vec_add(v0, vec_cross(d, w)).y,
                    vec_add(v0, vec_cross(d, w)).z, nv + 1, nv + 2, nv + 3);
            nv += 3;
            v2 = vec_sub(v0, vec_scale(vec_cross(d, w), 1.0 / (vec_length(d) > 0 ? vec_length(d) : 1)));
            v0 = m;
        } else {   /* tiny, at the target */
            v0 = nudge3(t, 2);
            v1 = vec_add(v0, vec_scale(w, 1e-9));
            v2 = vec_add(v0, vec_scale(out, 1e-9));
        }
        fprintf(f, "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\nv %.17g %.17g %.17g\nf %d %d %d\n", v0.x, v0.y, v0.z, v1.x,
                v1.y, v1.z, v2.x, v2.y, v2.z, nv + 1, nv + 2, nv + 3);
        nv += 3;
    }
    fclose(f);
    len = lightlen;
    ADD("mesh { file \"t.obj\" %s }\n", U() < 0.5 ? "material { Kd 0.5 t 0.5 ior 1 }" : "material { Kd 0.5 }");
    scene_model *s = scene_file_load_text(spath, text, (size_t)len, NULL, NULL, 0, &status);
    if (!s)
        return 0;
    bvh b;
    if (!bvh_build(&b, s->prims, s->prim_count, NULL)) {
        scene_free(s);
        return 0;
    }
    vec3 n = from.normal;
    bvh_bundle_rays rays = bundle_rays_toward(&from, lo, hi);
    rays.exact = side != 0;
    rays.origin = O;
    bvh_bundle bundle;
    bvh_bundle_make(&b, &rays, &bundle, NULL);
    (*bundles)++;
    for (int j = 0; bundle.count >= 0 && j < R; j++) {
        ray r = ray_shadow_to(&from, q[j]);
        if (rays.exact && (r.origin.x != O.x || r.origin.y != O.y || r.origin.z != O.z)) {
            printf("ORIGIN tangent scene %d\n", sc);
            (*bad)++;
        }
        if (!(r.tmax > 0))
            continue;
        (*rays_n)++;
        if (!walks_agree(&b, s->prims, &r, &bundle, skipped)) {
            if (*bad < 5) {
                printf("DIFFER tangent scene %d (T %g S %g) ray %d\n", sc, T, S, j);
                printf("  point %a %a %a normal %a %a %a offset %a side %d\n  target %a %a %a\n", from.point.x,
                       from.point.y, from.point.z, n.x, n.y, n.z, from.offset, side, q[j].x, q[j].y, q[j].z);
                FILE *keep = fopen(spath, "w");
                fwrite(text, 1, (size_t)len, keep);
                fclose(keep);
                char cmd[1200];
                snprintf(cmd, sizeof cmd, "cp %s %s/bad%ld.scene; cp %s %s/bad%ld.obj", spath, dir, *bad, mpath, dir, *bad);
                if (system(cmd) != 0)
                    printf("  (not kept)\n");
            }
            (*bad)++;
        }
    }
    bvh_free(&b);
    scene_free(s);
    return 1;
}

static int tangent_main(int scenes)
{
    long rays_n = 0, bad = 0, bundles = 0, skipped = 0, made = 0;
    mkdir(dir, 0777);
    static const double Ts[] = {0, 0, 0, 1e3, 1e6, 1e8, -3e7, 0.5, 1e16};
    static const double Ss[] = {1, 1, 1, 1e-6, 1e-3, 1e5, 3, 1e-100, 1e100, 1e-8, 1e-115, 1e115};
    for (int sc = 0; sc < scenes; sc++) {
        T = pick(Ts, 9);
        S = pick(Ss, 12);
        if (S < 1e-20 || S > 1e20) T = U() < 0.5 ? 0 : T * S;
        made += one_tangent(sc, &rays_n, &bad, &bundles, &skipped);
    }
    printf("tri_fuzz tangent: %d scenes (%ld made), %ld bundles, %ld rays, %ld part tests saved, %ld differ\n", scenes,
           made, bundles, rays_n, skipped, bad);
    return bad != 0;
}

int main(int argc, char **argv)
{
    int scenes = argc > 1 ? atoi(argv[1]) : 100;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10);
    dir = getenv("TF_DIR") ? getenv("TF_DIR") : "/tmp/a20tf.d";
    if (argc > 3)
        return tangent_main(scenes);
    mkdir(dir, 0777);
    char spath[512];
    snprintf(spath, sizeof spath, "%s/f.scene", dir);
    long rays_n = 0, bad = 0, bundles = 0, skipped = 0, exacts = 0, off_origin = 0, tris_left = 0;
    long full = 0, runs_full = 0;
    static const double Ts[] = {0, 0, 0, 1e3, 1e6, 1e8, -3e7, 0.5};
    static const double Ss[] = {1, 1, 1, 1e-6, 1e-3, 1e5, 3, 1e-300, 1e300, 1e-150, 1e150, 0x1p-1000};
    for (int sc = 0; sc < scenes; sc++) {
        T = pick(Ts, 8);
        S = pick(Ss, 12);
        if (S < 1e-20 || S > 1e20) T = U() < 0.5 ? 0 : T * S;
        len = 0;
        ADD("image { width 1 height 1 }\ncamera { eye [0, 0, 100] look_at [0, 0, 0] }\n");
        int nl = RI(1, 2);
        for (int i = 0; i < nl; i++)
            light();
        int nt = U() < 0.2 ? RI(100, 600) : RI(0, 40);   /* many: the list and the runs fill */
        for (int i = 0; i < nt; i++) {
            double c[9];
            for (int j = 0; j < 9; j++) c[j] = L4(-8, 8);
            if (U() < 0.3) c[RI(0, 2)] = c[3 + RI(0, 2)];   /* an edge on a lattice line */
            if (U() < 0.3) { int a = RI(0, 2); c[a] = c[3 + a] = c[6 + a]; }   /* flat on an axis */
            /* skip degenerate ones (the language refuses them) */
            double e1[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]}, e2[3] = {c[6] - c[0], c[7] - c[1], c[8] - c[2]};
            if (e1[1] * e2[2] - e1[2] * e2[1] == 0 && e1[2] * e2[0] - e1[0] * e2[2] == 0 && e1[0] * e2[1] - e1[1] * e2[0] == 0)
                continue;
            ADD("triangle { vertices [%.17g,%.17g,%.17g] [%.17g,%.17g,%.17g] [%.17g,%.17g,%.17g] %s }\n", W(c[0]), W(c[1]),
                W(c[2]), W(c[3]), W(c[4]), W(c[5]), W(c[6]), W(c[7]), W(c[8]), mat());
        }
        int nm = RI(0, 4);
        for (int i = 0; i < nm; i++) {
            mesh_file(i);
            ADD("mesh { file \"m%d.obj\" %s", i, mat());
            if (U() < 0.3) ADD(" rotate [%d, %d, %d]", RI(0, 4) * 45, RI(0, 2) * 30, RI(0, 1) * 90);
            ADD(" scale %.17g", S * (U() < 0.2 ? -1 : 1));
            ADD(" translate [%.17g, %.17g, %.17g] }\n", T, T, T);
        }
        if (nt + nm == 0)
            ADD("triangle { vertices [%.17g,0,0] [0,%.17g,0] [0,0,%.17g] }\n", S, S, S);
        int status;
        scene_model *s = scene_file_load_text(spath, text, (size_t)len, NULL, NULL, 0, &status);
        if (!s) {
            continue;   /* refused (a degenerate transform, a magnitude): not this test's */
        }
        bvh b;
        if (!bvh_build(&b, s->prims, s->prim_count, NULL)) {
            scene_free(s);
            continue;
        }
        for (int li = 0; li < s->light_count; li++) {
            const scene_light *lt = &s->lights[li];
            if (lt->kind != LIGHT_RECTANGLE && lt->kind != LIGHT_DISK)
                continue;
            light_setup setup = trace_light_setup(lt, lt->samples);
            if (setup.reach < 0)
                continue;
            for (int k = 0; k < 60; k++) {
                shadow_start from;
                hit h;
                memset(&h, 0, sizeof h);
                int got = 0;
                if (U() < 0.75) {
                    ray cr;
                    cr.origin = vec_make(W(L4(-12, 12)), W(L4(-12, 12)), W(L4(-12, 12)));
                    vec3 to = vec_make(W(L4(-8, 8) + (U() < 0.5 ? U() : 0)), W(L4(-8, 8)), W(L4(-8, 8)));
                    vec3 d = vec_sub(to, cr.origin);
                    real dl = vec_length(d);
                    if (!(dl > 0) || !isfinite(dl))
                        continue;
                    cr.dir = vec_scale(d, 1 / dl);
                    if (!isfinite(cr.dir.x) || !isfinite(cr.dir.y) || !isfinite(cr.dir.z))
                        continue;
                    cr.tmin = 0;
                    cr.tmax = INFINITY;
                    if (bvh_intersect(&b, s->prims, &cr, &h)) {
                        from = ray_shadow_start(&s->prims[h.prim], &h);
                        got = 1;
                    }
                }
                if (!got) {
                    h.point = vec_make(W(L4(-12, 12)), W(L4(-12, 12)), W(L4(-12, 12)));
                    double zz = 2 * U() - 1, an = 6.283185307179586 * U(), rr = sqrt(1 - zz * zz);
                    int q = RI(0, 3);
                    h.normal = q == 0 ? vec_make(rr * cos(an), rr * sin(an), zz) : q == 1 ? vec_make(0, 1, 0) : q == 2 ? vec_make(0.6, 0, -0.8) : vec_make(0, 0, -1);
                    h.shading_normal = h.normal;
                    h.prim = 0;
                    from = ray_shadow_start(&s->prims[0], &h);
                }
                vec3 n = from.normal;
                bvh_bundle_rays rays = bundle_rays_toward(&from, setup.box_lo, setup.box_hi);
                int side = trace_light_side(&from, &setup);
                rays.exact = side != 0;
                if (side)
                    rays.origin = ray_shadow_origin(&from, side > 0 ? n : vec_neg(n));
                bvh_bundle bundle;
                if (!bundle_counted(&b, &rays, &bundle, &bundles, &exacts))
                    continue;
                full += bundle.count >= BVH_BUNDLE_MAX;
                runs_full += bundle.run_count >= BVH_BUNDLE_RUNS - 2;
                enum { R = 40 };
                uint64_t key = (uint64_t)(U() * 0x1p53);
                for (int j = 0; j < R; j++) {
                    vec3 q;
                    if (j < 8) {
                        vec3 lo = setup.box_lo, hi = setup.box_hi;
                        q = vec_make(j & 1 ? hi.x : lo.x, j & 2 ? hi.y : lo.y, j & 4 ? hi.z : lo.z);
                    } else {
                        q = trace_light_point(lt, &setup, li, key + (uint64_t)j, RI(0, setup.samples - 1));
                    }
                    ray r = ray_shadow_to(&from, q);
                    if (rays.exact && (r.origin.x != rays.origin.x || r.origin.y != rays.origin.y || r.origin.z != rays.origin.z)) {
                        off_origin++;
                        if (off_origin < 4)
                            printf("ORIGIN scene %d: a ray's origin is not the bundle's\n", sc);
                    }
                    if (!(r.tmax > 0))
                        continue;
                    rays_n++;
                    if (!walks_agree(&b, s->prims, &r, &bundle, &skipped)) {
                        if (bad < 5) {
                            printf("DIFFER scene %d (T %g S %g) light %d bundle %d ray %d\n", sc, T, S, li, k, j);
                            printf("  point %a %a %a normal %a %a %a offset %a exact %d\n  target %a %a %a\n", from.point.x,
                                   from.point.y, from.point.z, n.x, n.y, n.z, from.offset, rays.exact, q.x, q.y, q.z);
                            keep_text(dir, bad, text, len);
                        }
                        bad++;
                    }
                }
                (void)tris_left;
            }
        }
        bvh_free(&b);
        scene_free(s);
    }
    printf("tri_fuzz: %d scenes, %ld bundles (%ld exact), %ld rays, %ld part tests saved, %ld off-origin, %ld differ\n",
           scenes, bundles, exacts, rays_n, skipped, off_origin, bad);
    printf("  bundles with a full list: %ld, with 14 or more runs: %ld\n", full, runs_full);
    return bad != 0 || off_origin != 0;
}
