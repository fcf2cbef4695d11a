/*
 * trace.h - the recursive ray tracer of the seed's pseudocode (slides 45-48):
 * trace(ray, depth) finds the nearest hit or the background; shade() adds
 * ambient, every light through its shadow rays, and the mirror and
 * transmitted rays while depth < max_depth.  spec/shading.md holds the
 * formulas; the choices where the seed is ambiguous are there too.
 *
 * A tracer is built once per scene and then only read, so any number of
 * traces may share it; the counters live in a trace_stats the caller owns.
 */
#ifndef REFRAY_TRACE_H
#define REFRAY_TRACE_H

#include <stdint.h>
#include "base/inline_hint.h"
#include "render/bvh.h"
#include "render/bvh_beam.h"
#include "render/lightsample.h"
#include "render/ray.h"
#include "scene/scene.h"

/* [REL-STACK-1] HINT_OUT_OF_LINE marks what is kept out of the recursion's
 * frame (trace_ray, shade, mirrored). */

enum { TRACE_BLOCKERS = 8 };

typedef struct trace_stats {
    long camera_rays;
    long shadow_rays;
    long reflection_rays;
    long refraction_rays;     /* transmitted rays, straight through sheets included */
    long tir_rays;            /* mirror rays taken on total internal reflection */
    long light_samples;       /* point-source evaluations, distributed samples each */
    long lights_on_surface;   /* samples skipped: the light sits on the shaded point */
    long dark_lights;
    long dark_cells;          /* samples not made: their cell is dark ([SHADE-SHORTCUT-DARK-2]) */
    long absorbed;            /* samples whose highlight the sum absorbs: no shadow ray
                                 ([SHADE-SHORTCUT-ABSORB-1]) */
    long hidden_highlights;   /* Kd = 0 points whose light loop is skipped: their highlight
                                 cannot show ([SHADE-SHORTCUT-HIDDEN-1]) */
    long nonfinite;           /* non-finite results replaced by 0 (must stay 0) */
    long tree_rays;           /* rays below the current camera ray (render_pixel resets it) */
    int tree_overflow;        /* a ray tree passed tracer.max_tree_rays: the render is void */
    long medium_overflow;     /* glass nested deeper than the medium stack holds:
                                 the render is void ([REL-MEDIUM-1]) */
    cancel_poll *cancel;      /* asked once per ray and light sample; NULL: never.
                                 Once stopped, rays return the background at once */
    /* A hash of the ray tree's shape, in order: the primitive (and the face
     * of a box, the cap or side of a cylinder or cone) each ray met, which
     * side of each light the surface faced and what its shadow ray let
     * through, refraction or total reflection.  Two nearby camera rays with
     * the same hash met the same things (make difftest tells edge pixels by
     * it); the image never depends on it. */
    uint64_t path;
    int record_path;          /* 1: fold the ray tree into path (make difftest
                                 sets it); 0: path stays as it is and costs
                                 nothing */
    bvh_stats bvh;
    /* Per light (its index mod TRACE_BLOCKERS) and per kind of shaded
     * point (a camera ray's hit: [0, TRACE_BLOCKERS), a deeper ray's: the
     * next TRACE_BLOCKERS): the opaque part that stopped its last shadow
     * ray, prim 1 + its index (0: none).  A hint the next shadow ray
     * toward that light from a point of that kind tests first
     * (spec/shading.md [SHADE-SHORTCUT-BLOCKER-1]); no image depends on
     * it.  Two kinds: a pixel's camera hit and its mirror ray's hit take
     * turns, and each spoilt the other's hint (grid1k: 29 % of its shadow
     * rays stopped by the hint with one slot, 43 % with two). */
    bvh_ref blocker[2 * TRACE_BLOCKERS];
} trace_stats;

/* The most cell centres of disk lights a tracer keeps ([SHADE-SHORTCUT-DARK-2]). */
enum { TRACE_CELLS_MAX = 4096 };

/* A grid cell's centre on a disk light: position + u t1 + v t2. */
typedef struct light_cell {
    real u, v;
} light_cell;

/* Per-light data computed once: the stratification and a disk's frame. */
typedef struct light_setup {
    int samples;        /* point sources this render uses for the light */
    rgb power;          /* each source's: shade_sample_power(power, samples) */
    light_grid grid;
    vec3 t1, t2;
    /* A ball holding every sample point light_point can return (rounding
     * included): centre and reach, reach < 0 where none is known
     * ([SHADE-SHORTCUT-DARK-1]). */
    vec3 centre;
    real reach;
    /* A box holding every sample point too, axis by axis (lo <= hi; only
     * where reach >= 0): the rectangle's own, or the disk's
     * ([SHADE-SHORTCUT-BUNDLE-1] aims the bundles at it). */
    vec3 box_lo, box_hi;
    /* A distant light: |L| = vec_length(-direction), the length its shadow
     * rays' tmin divides by (ray_shadow_along_sized), made once. */
    real along_length;
    /* Sample j's point lies within cell_reach of cells[j], the centre of
     * its grid cell; NULL for a rectangle, a point light, or past
     * TRACE_CELLS_MAX: tracer_build's ([SHADE-SHORTCUT-DARK-2]). */
    const light_cell *cells;
    real cell_reach;
} light_setup;

/* The transparent solids a ray is inside, innermost last (nested glass).
 * A ray inside more than MEDIUM_MAX of them at once cannot be traced right:
 * it counts in trace_stats.medium_overflow, and the render refuses the
 * image (spec/reliability.md, [REL-MEDIUM-1]). */
enum { MEDIUM_MAX = 16 };
typedef struct medium_stack {
    int count;
    int solid[MEDIUM_MAX];    /* solid_id of each enclosing solid */
    real ior[MEDIUM_MAX];
} medium_stack;

/* The bits of tracer.material_terms. */
enum { TRACE_KS = 1, TRACE_NO_BODY = 2 };

typedef struct tracer {
    const scene_model *scene;
    bvh accel;
    light_setup *lights;
    light_cell *cells;        /* the disk lights' cell centres, TRACE_CELLS_MAX at most in all */
    int cell_count;
    real *lobe_floors;        /* per material: shade's V.R floor of a Kd = 0 surface's lobe
                                 ([SHADE-SHORTCUT-LOBE-2]), made once, not per shaded point */
    int *material_terms;      /* per material: TRACE_KS (Ks > 0) and TRACE_NO_BODY (Kd = 0), once, not
                                 per shaded point */
    int max_depth;
    long max_tree_rays;       /* 0: no limit */
    /* The passes that run: off when the scene's features say nothing in the
     * scene could use them (scene_features), so their work is left out. */
    int shadows, specular, reflection, refraction;
    int glass;                /* some material has t > 0 (the scene's, in every
                                 mode): surfaces may touch glass ([NUM-GLASS-3]) */
    int any_walk;             /* no glass and every material's t +0 (not -0): a shadow
                                 ray without a bundle may take bvh_any_crossing
                                 ([SHADE-SHORTCUT-ANY-1]; not with the shortcuts off) */
    int glass_boxes;          /* boxes in glass_box: the transparent primitives', padded;
                                 -1: every point may touch glass (one is unbounded,
                                 there are too many, or the shortcuts are off) */
    int glass_alloc;          /* glass_box's allocated pairs */
    vec3 *glass_box;          /* lo, hi of each */
    int *glass_prim;          /* the primitive of each */
    int *gather_span;         /* per primitive: first neighbour in gather_near and
                                 their count, -1 when its hits are never taken
                                 as alone ([SHADE-SHORTCUT-GATHER-2]); NULL: none */
    struct gather_near *gather_near;
    int gather_alloc;         /* gather_near's allocated entries */
    int terminator_offset;    /* shadow rays of smooth triangles start at the
                                 lifted point (isect_shadow_point): 1 by
                                 default; 0 only to measure the seed's way
                                 (spec/shading.md [SHADE-TERMINATOR-1]) */
    real frame_shift;         /* the largest |translation| (max norm) of a primitive's
                                 frame, 0 without one: bounds how far a hit point
                                 may lie off its ray ([SHADE-SHORTCUT-GATHER-1]) */
    int no_shortcuts;         /* every shortcut off: tracer_no_shortcuts */
    int keyed;                /* a distributed light: a ray's key picks its samples
                                 (direct_light), so two rays' keys matter */
    int bundles;              /* shadow rays toward a distributed light walk
                                 only the nodes their bundle may reach
                                 ([SHADE-SHORTCUT-BUNDLE-1]): 1 by default,
                                 0 with the shortcuts off or to compare */
    real camera_half;         /* camera_half(&scene->camera), once per tracer */
    medium_stack eye_media;   /* what a perspective camera's eye is inside */
    long eye_overflow;        /* eye_media lost solids (each camera ray counts them) */
} tracer;


/* Builds the acceleration structure, in memory from the scene's allocator.
 * max_depth <= 0 takes the scene's;
 * light_samples > 0 gives every distributed light that many samples instead
 * of its own (for convergence sweeps).  Returns 0 when out of memory. */
int tracer_init(tracer *t, const scene_model *s, int max_depth, int light_samples);
/* The same, its BVH build counted into cancel (NULL: never stopped):
 * STATUS_OK, STATUS_NO_MEMORY or STATUS_CANCELLED (then nothing to free). */
int tracer_build(tracer *t, const scene_model *s, int max_depth, int light_samples, cancel_poll *cancel);
void tracer_free(tracer *t);

/*
 * The keys of the light-sample jitter (spec/json.md, "Light samples"): a
 * camera ray's key is render_sample_key's; a ray spawned at a hit takes
 * sampler_key(key, TRACE_KEY_MIRROR) or sampler_key(key, TRACE_KEY_REFRACT)
 * (the refracted or, on total internal reflection, mirrored transmitted
 * ray); distributed light i at a hit of a ray with key k draws from
 * sampler_key(k, TRACE_KEY_LIGHT + i).
 */
#define TRACE_KEY_MIRROR 1u
#define TRACE_KEY_REFRACT 2u
#define TRACE_KEY_LIGHT 0x100u

/* A distributed light's stratification and (for a disk) frame for a
 * render that gives it `samples` sources: tracer_init's per-light data. */
light_setup trace_light_setup(const scene_light *light, int samples);

/* Where sample j of the light at index `index` of the scene's lights sits
 * for a hit of a ray with key `key`: the point the tracer shades with, bit
 * for bit. */
vec3 trace_light_point(const scene_light *light, const light_setup *setup, int index, uint64_t key, int j);

/* An upper bound of shade_phong_lobe(V, R, n) for unit V, R with V.R = c >
 * 0 (formed as it forms it), made without pow; 1 where it makes none
 * (n < 1, n >= 2^20, c near 1).  [SHADE-SHORTCUT-ABSORB-1] */
real trace_lobe_above(real c, real n);

/* An upper bound of V.R, formed as add_source forms it from unit N and V,
 * for every sample point in the ball of centre P + d and reach `reach` seen
 * from the point P, with m = 2(N.V)N - V; 1 where it makes none.  Sizes as
 * light_dark checks them: |d| - reach at least 2^-16 of the coordinates'
 * size and 2^-400.  [SHADE-SHORTCUT-HIDDEN-1] */
real trace_ball_cosine_above(vec3 d, real reach, vec3 m);

/* The side of from's normal every sample of the light lies on, as
 * spawn_origin decides it for ray_shadow_to(from, sample): 1 (the origin
 * moved along +normal for every sample), -1 (along -normal for every one),
 * 0 (not known).  setup->reach must be >= 0 (its box known). */
int trace_light_side(const shadow_start *from, const light_setup *setup);

/* Turns off every shortcut that leaves out work a scene does not need
 * (spec/shading.md, "Shortcuts"): every pass runs, every surface sends its
 * mirror and transmitted rays while depth < max_depth, every light gets its
 * shadow ray, no walk stops early, the BVH culls nothing.  The image is the
 * same to the bit ([SHADE-SHORTCUT-OFF-1]); only the work and the counts in
 * trace_stats grow (and with them the ray-tree budget's count).  Call it
 * after tracer_init, before tracing. */
void tracer_no_shortcuts(tracer *t);

/* Radiance along r (slide 46); depth 1 for camera rays.  key seeds the
 * jitter of every light sample below this ray. */
rgb trace_ray(const tracer *t, const ray *r, int depth, const medium_stack *media, uint64_t key,
              trace_stats *st);
/* trace_ray at depth 1 for a camera ray of the run beam was pruned for
 * (bvh_beam.h): its first nearest hit alone is found on the pruned tree,
 * the same hit to the bit ([BVH-BEAM-1]); beam NULL: trace_ray. */
rgb trace_camera_ray(const tracer *t, const ray *r, const bvh_beam_tree *beam, const medium_stack *media, uint64_t key,
                     trace_stats *st);

/* The medium stack of a ray that starts at point: the transparent solids
 * containing it, outermost first (a camera inside glass).  A sphere or box
 * contains the point when it is strictly inside (exact test in its frame); a
 * mesh when a probe ray from the point crosses it an odd number of times.
 * Nesting order: the solid the probe leaves first is the innermost.  Empty
 * when the tracer has no refraction pass. */
void trace_media_at(const tracer *t, vec3 point, medium_stack *out, trace_stats *st);

#endif
