/*
 * scene.h - the flat, validated scene that the tracer and the oracle read.
 *
 * Invariants once scene_load_source has returned a scene (checked by the lowering
 * pass, relied on everywhere else):
 *   - every double is finite; every direction and normal has unit length;
 *   - 0 <= Kd, Ks, t <= 1 channel-wise; n >= 0; ior > 0;
 *   - every primitive's material index is valid; triangles are not degenerate;
 *   - the camera basis is orthonormal and the image has at least one pixel.
 * The scene owns all its memory, taken from the allocator it was loaded
 * with (kept in scene.mem); scene_free releases it in one call.  Loading
 * reads no file itself: the text comes from the caller and every `include`
 * and `mesh` file from the caller's resolver (io/scene_file.h reads files).
 */
#ifndef REFRAY_SCENE_H
#define REFRAY_SCENE_H

#include <stddef.h>
#include "base/arena.h"
#include "base/diag.h"
#include "base/mem.h"
#include "base/vec.h"
#include "base/xform.h"
#include "base/source.h"
#include "base/status.h"

typedef struct scene_material {
    rgb kd;            /* diffuse reflectivity K_d per channel, [0,1] (slide 11) */
    rgb ks;            /* specular coefficient K_s: highlight and mirror weight, [0,1] */
    double n;          /* Phong shininess exponent, >= 0 */
    double t;          /* transparency: 0 opaque, 1 clear, [0,1] */
    double ior;        /* index of refraction of the material's inside, > 0 */
    char *name;        /* NULL for an inline material */
    src_span where;
} scene_material;

typedef enum scene_prim_kind {
    PRIM_SPHERE,
    PRIM_PLANE,
    PRIM_TRIANGLE,     /* a `triangle` statement */
    PRIM_DISK,
    PRIM_BOX,
    PRIM_CYLINDER,     /* closed (a solid) or open (a sheet, like a plane) */
    PRIM_CONE,         /* the same, truncated or with an apex */
    PRIM_TORUS,        /* a ring torus: a solid */
    PRIM_MESH          /* a `mesh`: many triangles in one compact store */
} scene_prim_kind;

enum { PRIM_KINDS = PRIM_MESH + 1 };

/*
 * The triangles of a mesh, in world space (the mesh's transforms baked in),
 * stored compactly: shared vertices and three indices per triangle, about
 * 24 bytes a triangle for a closed mesh without normals instead of a whole
 * scene_prim.  Coordinates are the doubles the file gave, transformed:
 * nothing is rounded to a smaller type.  The arrays come from the scene's
 * allocator; the caps are the entries allocated (a shrink that failed
 * leaves more than the count).
 */
typedef struct scene_trimesh {
    vec3 *positions;
    int position_count, position_cap;
    vec3 *normals;         /* unit vertex normals, NULL when the mesh has none */
    int normal_count, normal_cap;
    int (*tri)[3];         /* corners of each triangle: indices into positions */
    int (*tri_normal)[3];  /* each corner's index into normals, or -1 (a flat
                              triangle); NULL when the mesh has no normals */
    int tri_count, tri_cap, tri_normal_cap;
    unsigned char *open;   /* per triangle, bit k: its edge from corner k to
                              k + 1 belongs to it alone (the hit test counts
                              such an edge as inside, like a lone triangle's;
                              shared ones by the tie rule of intersect.c);
                              NULL when no edge is open (else tri_count bytes) */
    int closed;            /* every edge shared by exactly two triangles
                              (src/scene/mesh_topo.h): a solid, whose inside
                              is found by counting crossings, so its winding
                              does not matter; else a set of sheets */
} scene_trimesh;

/* The matrix pair of a shape that keeps its local frame (see scene_prim). */
typedef struct scene_frame {
    xform to_world;
    xform to_local;
} scene_frame;

/*
 * A primitive: 128 bytes on x86-64 (it was 392 with the matrix pair and a
 * triangle's normals inline: a scene of 100 000 spheres touched 39 MB for
 * them, spec/performance.md section 5), so what few primitives have is
 * kept out of line, in blocks the scene owns (scene.kept).
 */
typedef struct scene_prim {
    scene_prim_kind kind;
    int material;          /* index into scene.materials */
    int mesh;              /* PRIM_MESH: index into scene.meshes, else -1 */
    /* Transforms are baked into the parameters in u whenever the shape maps
     * to the same kind of shape (triangles, meshes and planes always;
     * spheres, disks, cylinders, cones and tori under similarities; boxes
     * under translate and axis scale).  Otherwise the parameters are in
     * the local frame and frame holds the matrix pair; NULL: no frame. */
    const scene_frame *frame;
    union {
        struct { vec3 center; double radius; } sphere;
        struct { vec3 point; vec3 normal; } plane;
        struct {
            vec3 p[3];
            /* The three per-vertex shading normals, unit, out of line (few
             * triangles have them: scene.kept); NULL: none. */
            const vec3 *n;
        } triangle;
        struct { vec3 center; vec3 normal; double radius; } disk;
        struct { vec3 lo; vec3 hi; } box;
        /* from != to; radius > 0; open: no end caps */
        struct { vec3 from, to; double radius; int open; } cylinder;
        /* radius[0] at from, radius[1] at to, both >= 0, not both 0 */
        struct { vec3 from, to; double radius[2]; int open; } cone;
        /* axis unit; 0 < minor < major: the tube of radius minor around
         * the circle of radius major about center, normal to axis */
        struct { vec3 center, axis; double major, minor; } torus;
        /* A view of scene.meshes[mesh].geom: the arrays are that mesh's,
         * shared, so a primitive can be intersected on its own. */
        scene_trimesh mesh;
    } u;
    src_span where;
} scene_prim;

/* What the loader found out about a mesh (`refray check` prints it;
 * spec/language.md, section 8). */
typedef struct scene_mesh_report {
    int faces;             /* faces read (polygons of any size) */
    int dropped;           /* faces with no area, and triangles with none after the transforms */
    int nonplanar;         /* polygons whose corners are not on one plane */
    int fanned;            /* polygons cut as a fan: not simple, or past the ear-clipping budget */
    int oriented;          /* every shared edge runs opposite ways in its two triangles */
    int components;        /* pieces connected through shared edges */
    int open_edges;        /* edges of one triangle only */
    int crowded_edges;     /* edges of three or more triangles */
} scene_mesh_report;

typedef struct scene_mesh {
    char *path;            /* the OBJ or PLY file as resolved */
    int prim;              /* the PRIM_MESH primitive in scene.prims */
    scene_trimesh geom;    /* owned here; the primitive holds a view */
    scene_mesh_report report;
    src_span where;        /* the `file` value of the mesh statement */
} scene_mesh;

typedef enum scene_falloff {
    FALLOFF_LINEAR,        /* E / (d + d0), the seed's choice (slide 16); the default */
    FALLOFF_INVERSE_SQUARE,/* E / (d + d0)^2 (slide 15 with the d0 guard) */
    FALLOFF_NONE           /* E */
} scene_falloff;

typedef enum scene_light_kind {
    LIGHT_POINT,
    LIGHT_DISTANT,
    LIGHT_RECTANGLE,       /* distributed light over a parallelogram */
    LIGHT_DISK             /* distributed light over a disk */
} scene_light_kind;

typedef struct scene_light {
    scene_light_kind kind;
    rgb power;             /* E_p; for distributed lights the total over all samples */
    double d0;             /* falloff offset, >= 0 */
    scene_falloff falloff;    /* distant lights: always FALLOFF_NONE */
    vec3 position;         /* point: the position; rectangle: a corner; disk: the centre */
    vec3 direction;        /* distant: unit direction the light travels */
    vec3 edge_u, edge_v;   /* rectangle: the two edges from the corner */
    vec3 normal;           /* disk: unit normal */
    double radius;         /* disk: radius, > 0 */
    int samples;           /* distributed: number of point sources, >= 1 */
    src_span where;
} scene_light;

typedef enum scene_camera_kind {
    CAMERA_PERSPECTIVE,
    CAMERA_ORTHOGRAPHIC
} scene_camera_kind;

typedef struct scene_camera {
    scene_camera_kind kind;
    vec3 eye, look_at, up;  /* as written (up need not be orthogonal to the view) */
    double fov;             /* perspective: horizontal field of view in degrees, (0,180) */
    double width;           /* orthographic: horizontal extent of the view in scene units */
    vec3 forward, right, true_up; /* orthonormal basis derived at load time */
    src_span where;
    src_span width_where;   /* the `width` value (the block when not written) */
} scene_camera;

typedef struct scene_image_spec {
    int width, height;     /* pixels */
    int samples;           /* k: a k x k grid of camera rays per pixel */
    int max_depth;         /* trace depth; 1 means camera rays only (slide 48) */
    rgb background;
} scene_image_spec;

/* What the scene uses, so the tracer can leave out whole passes. */
typedef struct scene_features {
    int shadows;           /* some primitive can occlude some light from some surface */
    int specular;          /* some material has Ks > 0: highlights */
    int reflection;        /* some material has Ks > 0: mirror rays */
    int refraction;        /* some material has t > 0 */
    int sampled_lights;    /* some distributed light */
    int meshes;            /* some mesh */
} scene_features;

/* scene.kept's blocks: a scene with one transformed shape holds a few
 * hundred bytes for it, one with a frame per primitive takes an
 * allocation per 341 frames. */
#define SCENE_KEPT_FIRST 512
#define SCENE_KEPT_LAST 65536

typedef struct scene_model {
    scene_image_spec image;
    scene_camera camera;
    rgb ambient;               /* sum of all ambient blocks, I_a */
    scene_material *materials;
    int material_count, material_cap; /* cap: entries allocated */
    scene_prim *prims;            /* bounded primitives and planes; one PRIM_MESH per mesh */
    int prim_count, prim_cap;
    scene_mesh *meshes;
    int mesh_count, mesh_cap;
    scene_light *lights;          /* point, distant and distributed lights (not ambient) */
    int light_count, light_cap;
    scene_features features;
    char *oracle;              /* `oracle NAME`, or NULL */
    src_span oracle_where;
    source_set sources;        /* every file read, so later passes can point into them */
    /* What a primitive keeps out of line (its frame, a triangle's normals):
     * blocks never move, so copying a scene_prim copies a pointer and
     * growing prims moves nothing it points to.  From mem; blocks double
     * from SCENE_KEPT_FIRST bytes to SCENE_KEPT_LAST. */
    arena kept;
    mem mem;                   /* the allocator everything above came from */
    /* The load's --max-width, --max-height, --max-pixels, --max-samples,
     * --max-light-samples and --max-depth, which a renderer's overrides are
     * held to as the scene's own statements were. */
    struct {
        long width, height, pixels, samples, light_samples, depth;
    } max_render;
} scene_model;

/* Limits on what an input may ask for, enforced before allocation. */
typedef struct scene_limits {
    long max_width, max_height;
    long max_pixels;
    long max_samples;          /* k of the k x k pixel grid */
    long max_light_samples;
    long max_depth;
    long max_loop_iterations;  /* per loop, and in total over a load */
    long max_include_depth;
    long max_file_bytes;       /* per scene, OBJ or PLY file */
    long max_mesh_triangles;   /* per mesh */
    long max_primitives;       /* total, mesh triangles included */
    long max_errors;           /* diagnostics printed before giving up */
    long max_ray_tree;         /* rays traced for one camera ray, all its descendants included */
    long max_input_bytes;      /* of every file a load reads, each counted once */
    long max_memory_mb;        /* the estimate of scene_memory_estimate, in MiB */
} scene_limits;

/* [REL-STACK-1] The deepest trace a render takes, whatever the limits say:
 * the tracer recurses once a bounce (trace_ray -> shade -> a reflected or
 * transmitted trace_ray), so max_depth sets the C stack a render needs
 * (spec/reliability.md gives the bytes a level), and a depth past this
 * overflowed the 8 MiB main stack of a Linux process with a SIGSEGV
 * (tests/attack9, finding 2). */
enum { SCENE_DEPTH_CEILING = 1000 };

/* Defaults a laptop survives; every one but max_depth (SCENE_DEPTH_CEILING)
 * can be raised by a CLI flag. */
scene_limits scene_default_limits(void);

/*
 * The bytes a scene of prims primitives and pixels pixels is estimated to
 * hold at its peak, loaded and rendered, beyond extra (the texts and
 * syntax trees of its load): SCENE_BYTES_PER_PRIM a primitive (the
 * primitive, the acceleration structure and the growth of the arrays) and
 * SCENE_BYTES_PER_PIXEL a pixel (the image in double and its encoding),
 * and SCENE_BYTES_FIXED for the small tables of a load.  The 336 bytes
 * beside the primitive were fitted so the estimate stays above the peak
 * RSS measured for a million spheres and a million-triangle mesh (728
 * bytes a primitive on x86-64, against 687 and 716 measured), when a
 * scene_prim was 392 bytes (368 on 32-bit targets); the figure stays that
 * since scene_prim shrank, as a mesh's triangles never were scene_prims.
 * Measured against real peaks in spec/reliability.md ([REL-MEMORY-1]);
 * a load is refused past --max-memory before it allocates that much.
 */
#define SCENE_BYTES_PER_PRIM ((size_t)(sizeof(void *) == 8 ? 392 + 336 : 368 + 336))
#define SCENE_BYTES_PER_PIXEL 40
#define SCENE_BYTES_FIXED (256.0 * 1024)
double scene_memory_estimate(double prims, double pixels, double extra);

/* A file's text as the loader receives it. */
typedef struct scene_source {
    const char *path;      /* the name it goes by: in messages, and as `from` for what it includes */
    const char *identity;  /* the same file under any name (include cycles); NULL: path */
    const char *text;
    size_t len;
    int known;             /* on entry: 1 when the loader accepts a `known` answer;
                              on return, 1: the file this resolver delivered before
                              under identity, not read again (text NULL); the load
                              reuses its copy */
} scene_source;

/*
 * Where `include` and `mesh` files come from.  fetch is asked for the file
 * `name` as written in a statement of the file `from` (its scene_source
 * path) and fills *out, returning STATUS_OK; or it returns another status
 * with a one-line reason in why (reported as an error at the statement;
 * STATUS_NO_MEMORY ends the load as out of memory).  The loader copies the
 * text and names, then calls release (when not NULL) with the same *out;
 * a mesh file's text is read where it is, without a copy (it may be tens
 * of megabytes), and released once its mesh is built.  The text need not
 * be NUL-terminated.  An included file is read once per load
 * ([REL-INPUT-1]): the loader keeps one copy per identity, and when the
 * loader asks with out->known set (an include, never a mesh file) a
 * resolver may answer a file it gave before with its identity and `known`
 * set instead of the text.  The resolver enforces its own limits
 * (io/scene_file.c: --max-file-size); the loader bounds the bytes of all
 * files together (--max-input-size).
 */
typedef struct scene_resolver {
    int (*fetch)(void *user, const char *from, const char *name, scene_source *out, char *why,
                 size_t why_size);
    void (*release)(void *user, scene_source *src);
    void *user;
} scene_resolver;

typedef struct scene_load_opts {
    scene_limits limits;
    int warnings;              /* 0: warnings are counted, not delivered */
    diag_sink sink;            /* receives every diagnostic; NULL: none delivered */
    void *sink_user;
    scene_resolver resolver;   /* fetch NULL: `include` and `mesh` are errors */
    mem mem;                   /* zeroed: the C library's allocator */
    /* Asked every few hundred steps of the load (tokens, statements, loop
     * passes, OBJ lines, triangles): non-zero stops it with
     * STATUS_CANCELLED ([REL-CANCEL-1]).  NULL: never. */
    int (*cancel)(void *user);
    void *cancel_user;
} scene_load_opts;

/* The default limits, warnings on, no sink, no resolver, the C library. */
void scene_load_opts_init(scene_load_opts *o);

/*
 * Parses, evaluates and validates the scene in root.  Returns the scene,
 * or NULL with *status set (STATUS_DATA for a bad scene, STATUS_NO_MEMORY,
 * STATUS_CANCELLED when o->cancel said stop);
 * on success *status is STATUS_OK.  Never returns a partially valid scene,
 * and frees everything it allocated when it fails.
 */
scene_model *scene_load_source(const scene_source *root, const scene_load_opts *o, int *status);

void scene_free(scene_model *scene);

/*
 * The same for a JSON scene (spec/json.md): root's text is one JSON
 * document (root->identity is not used: a JSON scene includes nothing);
 * a mesh's `file` comes from o's resolver.  jansson parses the text with
 * its own allocator (malloc unless a program sets json_set_alloc_funcs):
 * that tree is freed before this returns, the scene comes from o->mem.  A
 * build without JSON support (JSON=0; scene_json_available() is 0) refuses
 * every JSON scene with STATUS_USAGE and an error without location
 * through o->sink.  io/scene_file.h picks the reader by the file name.
 */
#define SCENE_JSON_FORMAT "refray-scene"
#define SCENE_JSON_VERSION 1
/* The counters of the light-sampling keys a JSON scene's
 * conventions.light_samples.constants state ([JSON-SAMPLES-1]): the
 * renderer's RENDER_PIXEL_SALT and TRACE_KEY_*, which export_json_conv.c
 * checks at compile time to be these; the JSON reader checks a document
 * against them ([JSON-DERIVED-1]). */
#define SCENE_JSON_PIXEL_SALT 0x5eedu
#define SCENE_JSON_KEY_MIRROR 1u
#define SCENE_JSON_KEY_TRANSMITTED 2u
#define SCENE_JSON_KEY_LIGHT 0x100u
scene_model *scene_load_json_source(const scene_source *root, const scene_load_opts *o, int *status);
int scene_json_available(void);

/* Whether p is a solid whose inside is known on its own: a sphere, a box,
 * a closed cylinder or cone, a torus.  A closed mesh is a solid too, but
 * its inside is found by counting crossings (render/trace.c). */
int scene_prim_is_solid(const scene_prim *p);

/* Whether point lies strictly inside the solid p (in p's own frame when it
 * keeps one); 0 for anything that is not a solid on its own. */
int scene_prim_contains(const scene_prim *p, vec3 point);

/* A world point in f's frame, as L^-1 (point - T) (L, T: to_world's linear
 * part and translation).  to_local's L^-1 point + (-L^-1 T) adds terms of
 * the size of T that cancel, so a shape far from the origin and smaller
 * than an ulp of T got a point that had lost every digit of where it is
 * from the shape (tests/attack9b, finding 1); point - T is exact near T
 * (Sterbenz) and rounds relative to its own size elsewhere ([NUM-FRAME-1],
 * spec/numerics.md).  In scene.c. */
vec3 scene_frame_local(const scene_frame *f, vec3 point);

/* Whether p can shadow itself where N.L > 0: all but the flat ones (plane,
 * disk, triangle), whose shadow rays never meet them again.  A torus or an
 * open tube can from outside, any solid from inside ([LANG-FEATURES-2]). */
int scene_prim_self_shadows(const scene_prim *p);

/* The box around p in its own frame (before the frame it keeps, if any):
 * 1 with its corners in *lo and *hi, or 0 for the unbounded plane and an
 * empty mesh.  In prim_box.c. */
int scene_prim_local_box(const scene_prim *p, vec3 *lo, vec3 *hi);
/* The box around p in the world: its local box, through the frame p keeps
 * if any (the box around the images of its eight corners, up to a few ulps
 * of rounding).  0 when it has none or it is not finite.  In prim_box.c. */
int scene_prim_world_box(const scene_prim *p, vec3 *lo, vec3 *hi);

/* [LANG-EXTENT-1] Whether an orthographic camera's view on an image of
 * width x height pixels leaves the scene's extent: the corners eye +-
 * right w/2 +- true_up (w/2) (height/width), where the camera's rays start,
 * each have every coordinate within 2^500 (0), or not (1, with the first
 * coordinate beyond in *coordinate).  A perspective camera's rays start at
 * its eye: always 0.  The image's aspect reaches 2^30 with --max-height
 * raised, so a width within 2^500 alone let rays start 2^530 away
 * (tests/attack9, finding 1).  In check_extent.c. */
int scene_view_out(const scene_camera *cam, int width, int height, double *coordinate);
/* The same, reported to d at the camera's width as an error when the view
 * leaves the extent (0), else 1: the load with the scene's image, the
 * refray program with its --width and --height. */
int scene_check_view(const scene_model *s, int width, int height, diag *d);

/* The block word of a primitive kind ("sphere", ..., "torus", "mesh"), and its plural. */
const char *scene_prim_name(scene_prim_kind kind);
const char *scene_prim_plural(scene_prim_kind kind);

/* Frees a mesh store allocated from m and empties it. */
void scene_trimesh_free(const mem *m, scene_trimesh *g);

/* The bytes the meshes' stores hold (positions, normals, corner and normal
 * indices, open-edge masks), and their triangles in *triangles. */
long scene_mesh_bytes(const scene_model *s, long *triangles);


#endif
