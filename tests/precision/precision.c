/*
 * precision.c - `make precision`: every formula of src/render/shade.c and each
 * intersection routine evaluated in double against a __float128 reference
 * over random and extreme inputs (tests/precision/measure.h), then the
 * robust methods against their naive versions on the stress scenes
 * (tests/precision/naive.h, scenes/stress/).  Prints the tables that
 * spec/numerics.md quotes.
 *
 * usage: precision [-n INPUTS] [-s SEED]    (default 1000000 inputs, seed 1)
 * Exit status 1 when a function passes its documented bound or makes a
 * wrong decision away from the boundary.
 */
#include <quadmath.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/bvh.h"
#include "render/camera.h"
#include "io/scene_file.h"
#include "scene/scene.h"
#include "render/trace.h"

__extension__ typedef __float128 quad;
#define REF quad
#define REF_SQRT sqrtq
#define REF_POW powq
#define REF_FABS fabsq
#define REF_EPSILON ((quad)0x1p-112)
#include "measure.h"

static int print_table(long n, uint64_t seed)
{
    int bad = 0;
    printf("Precision per function: %ld inputs each, seed %llu, reference __float128\n\n", n,
           (unsigned long long)seed);
    printf("| function | unit | worst | bound | wrong decisions | worst input |\n|---|---|---|---|---|---|\n");
    for (int i = 0; i < MEASURE_COUNT; i++) {
        const measure_fn *f = &measure_table[i];
        measure m = {0, "-", 0, 0};
        f->run(n, seed + (uint64_t)i, &m);
        int ok = f->bound == 0 || (m.worst <= f->bound && m.wrong == 0);
        bad |= !ok;
        char bound[32];
        snprintf(bound, sizeof bound, f->bound > 0 ? "%g" : "-", f->bound);
        printf("| %s | %s | %.3g | %s%s | %ld of %ld | `%s` |\n", f->name, f->unit, m.worst, bound,
               ok ? "" : " **FAILED**", m.wrong, m.count, m.input);
    }
    return bad;
}

/* ---- the stress scenes: naive against robust ------------------------------ */

static scene_model *load(const char *name)
{
    char path[256];
    int status;
    snprintf(path, sizeof path, "scenes/stress/%s.scene", name);
    scene_model *s = scene_file_load(path, NULL, stderr, 0, &status);
    if (!s) {
        fprintf(stderr, "precision: cannot load %s (run from the repository root)\n", path);
        exit(2);
    }
    return s;
}

/* Over the camera rays of a scene whose prims[0] is a sphere: wrong hit or
 * miss decisions (away from the silhouette) and the worst distance of the
 * hit point from the sphere, in eps of m, for the textbook formula and for
 * isect_sphere. */
static void sphere_scene(const char *name)
{
    scene_model *s = load(name);
    const scene_prim *p = &s->prims[0];
    int w = s->image.width * 4, h = s->image.height * 4;
    long wrong[2] = {0, 0}, rays = 0;
    double off[2] = {0, 0};
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), w, h, i + 0.5, j + 0.5), rr = r;
            quad want, margin;
            int ref = sphere_ref(p->u.sphere.center, p->u.sphere.radius, &r, &want, &margin);
            if (margin < 1e-6)
                continue;
            rays++;
            real tn;
            hit hh;
            int got[2] = {naive_sphere(p->u.sphere.center, p->u.sphere.radius, &r, &tn),
                          isect_prim(p, &rr, &hh)};
            vec3 at[2] = {got[0] ? ray_at(&r, tn) : r.origin, hh.point};
            for (int k = 0; k < 2; k++) {
                wrong[k] += got[k] != ref;
                if (got[k] && ref) {
                    double e = sphere_surface_err(p->u.sphere.center, p->u.sphere.radius, at[k]);
                    off[k] = e > off[k] ? e : off[k];
                }
            }
        }
    printf("| %s | %ld | %ld | %.3g | %ld | %.3g |\n", name, rays, wrong[0], off[0], wrong[1], off[1]);
    scene_free(s);
}

/* Over the camera rays of a scene whose prims[0] is a cylinder, cone or
 * torus: wrong hit or miss decisions against the __float128 reference
 * (away from its margins) and the worst distance of the hit point from the
 * surface, in eps of m, for refray and (a torus) for the quartic written
 * about the ray's origin. */
static void shape_scene(const char *name)
{
    scene_model *s = load(name);
    const scene_prim *p = &s->prims[0];
    int torus = p->kind == PRIM_TORUS, cone = p->kind == PRIM_CONE;
    qcone qc = cone ? qcone_of(p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1], p->u.cone.open)
                    : qcone_of(p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.radius,
                               p->u.cylinder.open);
    qtorus qt = qtorus_of(p->u.torus.center, p->u.torus.axis, p->u.torus.major, p->u.torus.minor);
    int w = s->image.width * 4, h = s->image.height * 4;
    long wrong[2] = {0, 0}, rays = 0;
    double off[2] = {0, 0};
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), w, h, i + 0.5, j + 0.5), rr = r;
            quad want, margin, cosine;
            int ref = torus ? qtorus_ref(&qt, &r, &want, &margin, &cosine) : qcone_ref(&qc, &r, &want, &margin, &cosine);
            if (margin < 1e-6)
                continue;
            rays++;
            hit hh;
            real tn = 0;
            int got[2] = {isect_prim(p, &rr, &hh),
                          torus && naive_torus(p->u.torus.center, p->u.torus.axis, p->u.torus.major,
                                               p->u.torus.minor, &r, &tn)};
            vec3 at[2] = {hh.point, ray_at(&r, tn)};
            for (int k = 0; k < 1 + torus; k++) {
                wrong[k] += got[k] != ref;
                if (got[k] && ref) {
                    double e = torus ? qtorus_surface_err(&qt, at[k]) : qcone_surface_err(&qc, at[k]);
                    off[k] = e > off[k] ? e : off[k];
                }
            }
        }
    if (torus)
        printf("| %s | %ld | %ld | %.3g | %ld | %.3g |\n", name, rays, wrong[1], off[1], wrong[0], off[0]);
    else
        printf("| %s | %ld | - | - | %ld | %.3g |\n", name, rays, wrong[0], off[0]);
    scene_free(s);
}

/* Shadow rays from prims[0]'s lit camera hits: how many hit prims[0] again
 * (self) or miss everything (leak, when a light is enclosed), with a fixed
 * epsilon and with ray_spawn_hit. */
static void spawn_scene(const char *name, double eps, int count_leaks)
{
    scene_model *s = load(name);
    tracer t;
    if (!tracer_init(&t, s, 0, 0))
        exit(2);
    const scene_light *light = &s->lights[0];
    long tried = 0, bad[2] = {0, 0};
    int w = s->image.width * 4, h = s->image.height * 4;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), w, h, i + 0.5, j + 0.5);
            hit hh, h2;
            if (!bvh_intersect(&t.accel, s->prims, &r, &hh) || hh.prim != 0)
                continue;
            vec3 l = light->kind == LIGHT_DISTANT ? vec_neg(light->direction)
                                                  : vec_normalize(vec_sub(light->position, hh.point));
            if (!(vec_dot(l, hh.normal) > 0))
                continue;
            ray sr[2] = {naive_spawn(hh.point, hh.normal, l, eps), ray_spawn_hit(&s->prims[0], &hh, l)};
            tried++;
            for (int k = 0; k < 2; k++) {
                int any = bvh_intersect(&t.accel, s->prims, &sr[k], &h2);
                bad[k] += count_leaks ? !any : any && h2.prim == 0;
            }
        }
    printf("| %s | %s, fixed %g | %ld | %ld | %ld |\n", name, count_leaks ? "leaks" : "self-hits", eps, tried,
           bad[0], bad[1]);
    tracer_free(&t);
    scene_free(s);
}

/* Rays through every vertex and five points of every edge of the closed
 * icosphere, from its centre and from three places outside: misses by
 * Moller-Trumbore (brute force) and by the tracer, and rays whose number of
 * crossings is not the surface's (1 from the centre, 2 from outside) by the
 * paper's inclusive Woop test (brute force) and by the tracer's bvh_visit. */
static void watertight_scene(void)
{
    static const double at[] = {0.5, 0.1, 0.3337, 0.71, 0.9};
    static const double lean[3][3] = {{0.31, -0.17, 0.05}, {-0.23, 0.11, 0.29}, {0.07, 0.37, -0.19}};
    scene_model *s = load("watertight_mesh");
    tracer t;
    if (!tracer_init(&t, s, 0, 0))
        exit(2);
    const scene_trimesh *g = &s->meshes[0].geom;
    vec3 centre = vec_make(0.5, 0.25, 0.125);
    long rays = 0, miss[2] = {0, 0}, wrong[2] = {0, 0};
    for (int k = 0; k < g->tri_count; k++)
        for (int e = 0; e < 3; e++)
            for (int a = -1; a < 5; a++) {
                vec3 p[3], q3[3];
                mesh_triangle(g, k, p);
                vec3 pt = a < 0 ? p[e] : vec_add(p[e], vec_scale(vec_sub(p[(e + 1) % 3], p[e]), at[a]));
                vec3 out = vec_normalize(vec_sub(pt, centre));
                for (int q = 0; q < 4; q++) {
                    vec3 from = q == 0 ? centre
                                       : vec_madd(pt, vec_normalize(vec_add(out, vec_make(lean[q - 1][0], lean[q - 1][1],
                                                                                         lean[q - 1][2]))), 3);
                    ray r = make_ray(from, pt), rr = r;
                    hit hh;
                    int naive = 0, inclusive = 0, visited = 0;
                    real tn;
                    for (int i = 0; i < g->tri_count; i++) {
                        mesh_triangle(g, i, q3);
                        naive += naive_triangle(q3, &r, &tn);
                        inclusive += naive_woop_inclusive(q3, &r);
                    }
                    bvh_visit(&t.accel, s->prims, &r, count_crossing, &visited);
                    rays++;
                    miss[0] += !naive;
                    miss[1] += !bvh_intersect(&t.accel, s->prims, &rr, &hh);
                    wrong[0] += inclusive != (q == 0 ? 1 : 2);
                    wrong[1] += visited != (q == 0 ? 1 : 2);
                }
            }
    printf("| watertight_mesh (1280 triangles) | %ld | %ld | %ld | %ld | %ld |\n", rays, miss[0], miss[1], wrong[0],
           wrong[1]);
    tracer_free(&t);
    scene_free(s);
}

int main(int argc, char **argv)
{
    long n = 1000000;
    uint64_t seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "-n") == 0)
            n = atol(argv[i + 1]);
        else if (strcmp(argv[i], "-s") == 0)
            seed = strtoull(argv[i + 1], NULL, 10);
    }
    int bad = print_table(n, seed);
    printf("\nSpheres on the stress scenes' camera rays (4 x 4 per pixel; off the surface in eps of m)\n\n");
    printf("| scene | rays | textbook: wrong | textbook: off | refray: wrong | refray: off |\n"
           "|---|---|---|---|---|---|\n");
    sphere_scene("tiny_sphere_far");
    sphere_scene("huge_sphere_near");
    sphere_scene("sphere_1e6_far");
    sphere_scene("ortho_far_sphere");
    printf("\nCylinders, cones and tori on the stress scenes' camera rays (4 x 4 per pixel; off the surface in "
           "eps of m; before: the torus's quartic written about the ray's origin)\n\n");
    printf("| scene | rays | before: wrong | before: off | refray: wrong | refray: off |\n"
           "|---|---|---|---|---|---|\n");
    shape_scene("cylinder_grazing");
    shape_scene("cone_apex");
    shape_scene("torus_edge_on");
    shape_scene("torus_hole");
    shape_scene("torus_thin_far");
    printf("\nShadow rays leaving a lit sphere: fixed epsilon against ray_spawn_hit\n\n");
    printf("| scene | counted | rays | fixed | refray |\n|---|---|---|---|---|\n");
    spawn_scene("concentric_gap", 1e-4, 1);
    spawn_scene("acne_offset_1e8", 1e-9, 0);
    spawn_scene("acne_scale_1e6", 1e-9, 0);
    printf("\nRays through the edges and vertices of a closed mesh\n\n");
    printf("| scene | rays | Moller-Trumbore misses | refray misses | inclusive Woop, wrong crossing count | refray, "
           "wrong crossing count |\n|---|---|---|---|---|---|\n");
    watertight_scene();
    return bad;
}
