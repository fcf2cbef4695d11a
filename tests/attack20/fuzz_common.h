/*
 * fuzz_common.h - what attack 20's fuzz programs share: a splitmix64
 * stream (FUZZ_SEED, settable by the program's seed argument), its
 * uniform doubles and picks, a double nudged by ulps, and (FUZZ_EVENTS)
 * a walk's crossings recorded in order and two such records compared.
 */
#ifndef ATTACK20_FUZZ_COMMON_H
#define ATTACK20_FUZZ_COMMON_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#ifndef FUZZ_SEED
#define FUZZ_SEED 0x9E3779B97F4A7C15u
#endif

static uint64_t st = FUZZ_SEED;
static inline uint64_t R64(void)
{
    uint64_t z = (st += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}
static inline double U(void) { return (double)(R64() >> 11) * 0x1p-53; }
static inline int RI(int lo, int hi) { return lo + (int)((hi - lo + 1) * U()); }
static inline double pick(const double *a, int n) { return a[RI(0, n - 1)]; }
static inline double L4(int lo, int hi) { return RI(lo, hi) * 0.25; }
static inline double nudge(double x, int k)
{
    for (; k > 0; k--)
        x = nextafter(x, INFINITY);
    for (; k < 0; k++)
        x = nextafter(x, -INFINITY);
    return x;
}

#ifdef FUZZ_EVENTS
enum { EV = 4096 };
typedef struct events {
    int count, prim[EV], part[EV], n[EV];
} events;
static inline int record(void *ctx, bvh_ref ref, int crossings)
{
    events *e = ctx;
    if (e->count < EV) {
        e->prim[e->count] = ref.prim;
        e->part[e->count] = ref.part;
        e->n[e->count] = crossings;
    }
    e->count++;
    return 0;
}
static inline int same_events(const events *a, const events *b)
{
    int same = a->count == b->count;
    for (int i = 0; same && i < a->count && i < EV; i++)
        same = a->prim[i] == b->prim[i] && a->part[i] == b->part[i] && a->n[i] == b->n[i];
    return same;
}

/* The bundle of rays from `from` toward the box [lo, hi], as light_bundle
 * makes it (not exact: the caller says where it is). */
static inline bvh_bundle_rays bundle_rays_toward(const shadow_start *from, vec3 lo, vec3 hi)
{
    bvh_bundle_rays rays;
    vec3 n = from->normal;
    memset(&rays, 0, sizeof rays);
    rays.apex = from->point;
    rays.slack = from->offset * (fabs(n.x) + fabs(n.y) + fabs(n.z));
    rays.lo = lo;
    rays.hi = hi;
    return rays;
}

/* bvh_bundle_make, counted: 1 where it made a list (count >= 0). */
static inline int bundle_counted(const bvh *b, const bvh_bundle_rays *rays, bvh_bundle *out, long *bundles, long *exacts)
{
    *exacts += rays->exact;
    bvh_bundle_make(b, rays, out, NULL);
    (*bundles)++;
    return out->count >= 0;
}

/* A scene that showed a difference, kept as DIR/badK.scene. */
static inline void keep_text(const char *dir, long k, const char *text, int len)
{
    char keep[600];
    snprintf(keep, sizeof keep, "%s/bad%ld.scene", dir, k);
    FILE *f = fopen(keep, "w");
    if (f) {
        fwrite(text, 1, (size_t)len, f);
        fclose(f);
    }
}
#endif

#endif
