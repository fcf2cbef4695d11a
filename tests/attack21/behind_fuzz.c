/*
 * behind_fuzz.c - attack 21: [SHADE-SHORTCUT-BEHIND-1] / [NUM-TRI-BEHIND-1]
 * (bvh_bundle.c triangle_left_behind: a one-origin bundle leaves out a
 * triangle every ray leaves behind) against the whole walk, as attack 20's
 * tri_fuzz.c does (its helpers are included: light, walks_agree, nudge3):
 * bvh_visit_counts_bundle must report bvh_visit_counts' crossings in
 * order for every ray toward the light box's corners and samples.  The
 * triangles are put where the new test decides: the shading point's own
 * surface (the plane through the point with its normal, the rays leaving
 * it), wholly behind the bundle's origin O (corners at O minus a part of a
 * ray's direction), through O (O inside the triangle, in its plane), in a
 * plane passing within -4..4 ulps of O, tilted any way (t of a few ulps,
 * either sign), wide ones (corners 1e3 .. 1e7 S away) at 0.5 .. 3 offsets
 * in front of or behind O, some nearly along the rays (small
 * determinants), corners nudged by ulps; scales 1e-115 .. 1e115 and the
 * lattice moved to 1e16.  Exit 1 on a difference.  From the repository
 * root after `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/bf \
 *      tests/attack21/behind_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/bf 2000 [SEED]
 */
#define main tri_fuzz_main
#include "../attack20/tri_fuzz.c"
#undef main

static vec3 rnd3(void) { return vec_make(2 * U() - 1, 2 * U() - 1, 2 * U() - 1); }

/* A triangle for the bundle from O toward targets q: one of the kinds above. */
static void behind_triangle(FILE *f, int *nv, vec3 O, vec3 P, vec3 n, const vec3 *q, int nq, double offset)
{
    vec3 d = vec_sub(q[RI(0, nq - 1)], O), v[3];
    double len_d = vec_length(d) > 0 ? vec_length(d) : S;
    vec3 w = vec_scale(rnd3(), S), u = vec_scale(rnd3(), S);
    int kind = RI(0, 6);
    if (kind == 0) {   /* the point's own surface */
        vec3 a = vec_normalize(vec_cross(n, rnd3())), b = vec_cross(n, a);
        double r = S * pick((const double[]){1, 1e-6, 10, 1e-12}, 4);
        for (int i = 0; i < 3; i++) {
            double ang = 2.1 * i + U();
            v[i] = nudge3(vec_add(P, vec_add(vec_scale(a, r * cos(ang)), vec_scale(b, r * sin(ang)))), 1);
        }
    } else if (kind == 1) {   /* behind O */
        double back = pick((const double[]){1, 1e-3, 1e-9, 1e-15, 0.5}, 5);
        vec3 c = vec_sub(O, vec_scale(d, back));
        for (int i = 0; i < 3; i++)
            v[i] = nudge3(vec_add(c, vec_scale(rnd3(), back * len_d * pick((const double[]){0.5, 2, 1e-3}, 3))), 2);
    } else if (kind == 2) {   /* through O */
        v[0] = vec_add(O, w);
        v[1] = vec_add(O, u);
        v[2] = vec_sub(O, vec_add(w, u));
        for (int i = 0; i < 3; i++)
            v[i] = nudge3(v[i], 2);
    } else if (kind >= 5) {
        /* wide (corners 1e3 .. 1e7 S away: P's rounding about eps R^3) at
         * 0.5 .. 3 times the offset in front of O, so t is near tmin; or
         * (kind 6) nearly along the ray: a small determinant */
        vec3 dn = vec_scale(d, 1 / len_d);
        vec3 m = kind == 5 ? vec_normalize(vec_add(dn, vec_scale(rnd3(), U()))) :
                             vec_normalize(vec_add(vec_normalize(vec_cross(dn, rnd3())), vec_scale(dn, pow(10.0, -8 * U()))));
        vec3 a = vec_normalize(vec_cross(m, rnd3())), b = vec_cross(m, a);
        double gap = offset * (0.5 + 2.5 * U()) * (U() < 0.5 ? 1 : -1);
        vec3 c = vec_madd(O, m, gap);
        for (int i = 0; i < 3; i++) {
            double ang = 2.1 * i + U(), r = S * pow(10.0, 3 + 4 * U());
            v[i] = nudge3(vec_add(c, vec_add(vec_scale(a, r * cos(ang)), vec_scale(b, r * sin(ang)))), 1);
        }
    } else {   /* a plane within ulps of O, tilted any way */
        vec3 m = kind == 3 ? vec_normalize(rnd3()) : vec_normalize(vec_add(vec_scale(d, 1 / len_d), vec_scale(rnd3(), U())));
        vec3 a = vec_normalize(vec_cross(m, rnd3())), b = vec_cross(m, a);
        double mag = fmax(fabs(O.x), fmax(fabs(O.y), fabs(O.z)));
        double shift = (nudge(mag, RI(-4, 4)) - mag) + (U() < 0.3 ? S * 1e-15 * (2 * U() - 1) : 0);
        vec3 c = vec_madd(O, m, shift);
        for (int i = 0; i < 3; i++) {
            double ang = 2.1 * i + U(), r = S * pick((const double[]){1, 1e-3, 100}, 3);
            v[i] = nudge3(vec_add(c, vec_add(vec_scale(a, r * cos(ang)), vec_scale(b, r * sin(ang)))), 1);
        }
    }
    fprintf(f, "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\nv %.17g %.17g %.17g\nf %d %d %d\n", v[0].x, v[0].y, v[0].z,
            v[1].x, v[1].y, v[1].z, v[2].x, v[2].y, v[2].z, *nv + 1, *nv + 2, *nv + 3);
    *nv += 3;
}

static scene_model *load(const char *spath)
{
    int status;
    return scene_file_load_text(spath, text, (size_t)len, NULL, NULL, 0, &status);
}

/* A differing scene kept (the first five) as DIR/badN/b.scene with its
 * mesh b.obj beside it; the rest of its rays are not run. */
static void keep_bad(int sc, int ray_index, int side, const char *mpath, long nbad)
{
    printf("DIFFER behind scene %d (T %g S %g) ray %d side %d\n", sc, T, S, ray_index, side);
    if (nbad >= 5)
        return;
    char to[600];
    snprintf(to, sizeof to, "%s/bad%ld", dir, nbad);
    mkdir(to, 0777);
    snprintf(to, sizeof to, "%s/bad%ld/b.obj", dir, nbad);
    if (rename(mpath, to) != 0)
        printf("  (mesh not kept)\n");
    snprintf(to, sizeof to, "%s/bad%ld/b.scene", dir, nbad);
    FILE *f = fopen(to, "w");
    if (f) {
        fprintf(f, "%.*s", len, text);
        fclose(f);
    }
}

static int one_behind(int sc, long *rays_n, long *bad, long *bundles, long *skipped)
{
    char spath[512], mpath[512];
    snprintf(spath, sizeof spath, "%s/b.scene", dir);
    snprintf(mpath, sizeof mpath, "%s/b.obj", dir);
    /* the light alone first (with a far sphere: a scene needs a shape), for its box and samples */
    len = snprintf(text, sizeof text, "camera { eye [0, 0, 100] look_at [0, 0, 0] }\nimage { width 1 height 1 }\n");
    light();
    int lightlen = len;
    ADD("sphere { center [%.17g, %.17g, %.17g] radius %.17g }\n", W(100), W(100), W(100), S);
    scene_model *s0 = load(spath);
    light_setup setup;
    if (s0)
        setup = trace_light_setup(&s0->lights[0], s0->lights[0].samples);
    if (!s0 || setup.reach < 0) {
        scene_free(s0);
        return 0;
    }
    shadow_start from;
    from.normal = vec_normalize(rnd3());
    from.offset = S * pick((const double[]){0x1p-20, 0x1p-30, 1e-9, 0x1p-40}, 4);
    from.point = vec_make(W(L4(-16, 16)) + S * (U() < 0.3 ? U() : 0), W(L4(-16, 16)), W(L4(-16, 16)));
    int side = trace_light_side(&from, &setup);
    vec3 O = ray_shadow_origin(&from, side >= 0 ? from.normal : vec_neg(from.normal));
    enum { R = 40 };
    vec3 q[R], lo = setup.box_lo, hi = setup.box_hi;
    uint64_t key = (uint64_t)(U() * 0x1p53);
    for (int j = 0; j < R; j++)
        q[j] = j < 8 ? vec_make(j & 1 ? hi.x : lo.x, j & 2 ? hi.y : lo.y, j & 4 ? hi.z : lo.z)
                     : trace_light_point(&s0->lights[0], &setup, 0, key + (uint64_t)j, RI(0, setup.samples - 1));
    scene_free(s0);
    FILE *f = fopen(mpath, "w");
    int nt = RI(3, 30), nv = 0;
    for (int i = 0; i < nt; i++)
        behind_triangle(f, &nv, O, from.point, from.normal, q, R, from.offset);
    fclose(f);
    len = lightlen;
    ADD("mesh { file \"b.obj\" %s }\n", U() < 0.5 ? "material { Kd 0.5 t 0.5 ior 1 }" : "material { Kd 0.5 }");
    scene_model *s = load(spath);
    bvh b;
    if (!s || !bvh_build(&b, s->prims, s->prim_count, NULL)) {
        scene_free(s);
        return 0;
    }
    /* the bundle as light_bundle makes it: one exact origin where the side is known */
    bvh_bundle bundle;
    bvh_bundle_rays rays = bundle_rays_toward(&from, lo, hi);
    rays.origin = O;
    rays.exact = side != 0;
    bvh_bundle_make(&b, &rays, &bundle, NULL);
    (*bundles)++;
    int j = 0, agree = 1;
    for (; bundle.count >= 0 && j < R && agree; j++) {
        ray r = ray_shadow_to(&from, q[j]);
        *rays_n += r.tmax > 0;
        agree = !(r.tmax > 0) || walks_agree(&b, s->prims, &r, &bundle, skipped);
    }
    if (!agree)
        keep_bad(sc, j - 1, side, mpath, (*bad)++);
    bvh_free(&b);
    scene_free(s);
    return 1;
}

int main(int argc, char **argv)
{
    int scenes = argc > 1 ? atoi(argv[1]) : 1000;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10);
    dir = getenv("TF_DIR") ? getenv("TF_DIR") : "/tmp/a21bf.d";
    mkdir(dir, 0777);
    long rays_n = 0, bad = 0, bundles = 0, skipped = 0, made = 0;
    static const double Ts[] = {0, 0, 0, 1e3, 1e6, 1e8, -3e7, 0.5, 1e16};
    static const double Ss[] = {1, 1, 1, 1e-6, 1e-3, 1e5, 3, 1e-100, 1e100, 1e-8, 1e-115, 1e115};
    for (int sc = 0; sc < scenes; sc++) {
        T = pick(Ts, 9);
        S = pick(Ss, 12);
        if (S < 1e-20 || S > 1e20)
            T = U() < 0.5 ? 0 : T * S;
        made += one_behind(sc, &rays_n, &bad, &bundles, &skipped);
    }
    printf("behind_fuzz: %d scenes (%ld made), %ld bundles, %ld rays, %ld part tests saved, %ld scenes differ\n", scenes,
           made, bundles, rays_n, skipped, bad);
    return bad != 0;
}
