/*
 * scene.h - the flat, validated scene that the tracer and the oracle read.
 *
 * Invariants once scene_load has returned a scene (checked by the lowering
 * pass, relied on everywhere else):
 *   - every double is finite; every direction and normal has unit length;
 *   - 0 <= Kd, Ks, t <= 1 channel-wise; n >= 0; ior > 0;
 *   - every primitive's material index is valid; triangles are not degenerate;
 *   - the camera basis is orthonormal and the image has at least one pixel.
 * The scene owns all its memory; scene_free releases it in one call.
 */
#ifndef REFRAY_SCENE_H
#define REFRAY_SCENE_H

#include <stddef.h>
#include <stdio.h>
#include "base/vec.h"
#include "base/xform.h"
#include "base/source.h"
#include "base/status.h"

typedef struct rf_material {
    rgb kd;            /* diffuse reflectivity K_d per channel, [0,1] (slide 11) */
    rgb ks;            /* specular coefficient K_s: highlight and mirror weight, [0,1] */
    double n;          /* Phong shininess exponent, >= 0 */
    double t;          /* transparency: 0 opaque, 1 clear, [0,1] */
    double ior;        /* index of refraction of the material's inside, > 0 */
    char *name;        /* NULL for an inline material */
    src_span where;
} rf_material;

typedef enum rf_prim_kind {
    PRIM_SPHERE,
    PRIM_PLANE,
    PRIM_TRIANGLE,     /* a `triangle` statement */
    PRIM_DISK,
    PRIM_BOX,
    PRIM_MESH          /* a `mesh`: many triangles in one compact store */
} rf_prim_kind;

/*
 * The triangles of a mesh, in world space (the mesh's transforms baked in),
 * stored compactly: shared vertices and three indices per triangle, about
 * 24 bytes a triangle for a closed mesh without normals instead of a whole
 * rf_prim.  Coordinates are the doubles the file gave, transformed: nothing
 * is rounded to a smaller type.
 */
typedef struct rf_trimesh {
    vec3 *positions;
    int position_count;
    vec3 *normals;         /* unit vertex normals, NULL when the mesh has none */
    int normal_count;
    int (*tri)[3];         /* corners of each triangle: indices into positions */
    int (*tri_normal)[3];  /* each corner's index into normals, or -1 (a flat
                              triangle); NULL when the mesh has no normals */
    int tri_count;
    unsigned char *open;   /* per triangle, bit k: its edge from corner k to
                              k + 1 belongs to it alone (the hit test counts
                              such an edge as inside, like a lone triangle's;
                              shared ones by the tie rule of intersect.c);
                              NULL when no edge is open */
    int closed;            /* every edge shared by exactly two triangles
                              (src/scene/mesh_topo.h): a solid, whose inside
                              is found by counting crossings, so its winding
                              does not matter; else a set of sheets */
} rf_trimesh;

typedef struct rf_prim {
    rf_prim_kind kind;
    int material;          /* index into scene.materials */
    int mesh;              /* PRIM_MESH: index into scene.meshes, else -1 */
    union {
        struct { vec3 center; double radius; } sphere;
        struct { vec3 point; vec3 normal; } plane;
        struct {
            vec3 p[3];
            vec3 n[3];     /* per-vertex shading normals, unit, when has_normals */
            int has_normals;
        } triangle;
        struct { vec3 center; vec3 normal; double radius; } disk;
        struct { vec3 lo; vec3 hi; } box;
        /* A view of scene.meshes[mesh].geom: the arrays are that mesh's,
         * shared, so a primitive can be intersected on its own. */
        rf_trimesh mesh;
    } u;
    /* Transforms are baked into the parameters above whenever the shape maps
     * to the same kind of shape (triangles, meshes and planes always; spheres and
     * disks under similarities; boxes under translate and axis scale).
     * Otherwise the parameters are in the local frame and these are set. */
    int has_xform;
    xform to_world;
    xform to_local;
    src_span where;
} rf_prim;

/* What the loader found out about a mesh (`refray check` prints it;
 * spec/language.md, section 8). */
typedef struct rf_mesh_report {
    int faces;             /* faces read (polygons of any size) */
    int dropped;           /* faces with no area, and triangles with none after the transforms */
    int nonplanar;         /* polygons whose corners are not on one plane */
    int fanned;            /* polygons cut as a fan: not simple, or past the ear-clipping budget */
    int oriented;          /* every shared edge runs opposite ways in its two triangles */
    int components;        /* pieces connected through shared edges */
    int open_edges;        /* edges of one triangle only */
    int crowded_edges;     /* edges of three or more triangles */
} rf_mesh_report;

typedef struct rf_mesh {
    char *path;            /* the OBJ or PLY file as resolved */
    int prim;              /* the PRIM_MESH primitive in scene.prims */
    rf_trimesh geom;       /* owned here; the primitive holds a view */
    rf_mesh_report report;
    src_span where;        /* the `file` value of the mesh statement */
} rf_mesh;

typedef enum rf_falloff {
    FALLOFF_LINEAR,        /* E / (d + d0), the seed's choice (slide 16); the default */
    FALLOFF_INVERSE_SQUARE,/* E / (d + d0)^2 (slide 15 with the d0 guard) */
    FALLOFF_NONE           /* E */
} rf_falloff;

typedef enum rf_light_kind {
    LIGHT_POINT,
    LIGHT_DISTANT,
    LIGHT_RECTANGLE,       /* distributed light over a parallelogram */
    LIGHT_DISK             /* distributed light over a disk */
} rf_light_kind;

typedef struct rf_light {
    rf_light_kind kind;
    rgb power;             /* E_p; for distributed lights the total over all samples */
    double d0;             /* falloff offset, >= 0 */
    rf_falloff falloff;    /* distant lights: always FALLOFF_NONE */
    vec3 position;         /* point: the position; rectangle: a corner; disk: the centre */
    vec3 direction;        /* distant: unit direction the light travels */
    vec3 edge_u, edge_v;   /* rectangle: the two edges from the corner */
    vec3 normal;           /* disk: unit normal */
    double radius;         /* disk: radius, > 0 */
    int samples;           /* distributed: number of point sources, >= 1 */
    src_span where;
} rf_light;

typedef enum rf_camera_kind {
    CAMERA_PERSPECTIVE,
    CAMERA_ORTHOGRAPHIC
} rf_camera_kind;

typedef struct rf_camera {
    rf_camera_kind kind;
    vec3 eye, look_at, up;  /* as written (up need not be orthogonal to the view) */
    double fov;             /* perspective: horizontal field of view in degrees, (0,180) */
    double width;           /* orthographic: horizontal extent of the view in scene units */
    vec3 forward, right, true_up; /* orthonormal basis derived at load time */
    src_span where;
} rf_camera;

typedef struct rf_image_spec {
    int width, height;     /* pixels */
    int samples;           /* k: a k x k grid of camera rays per pixel */
    int max_depth;         /* trace depth; 1 means camera rays only (slide 48) */
    rgb background;
} rf_image_spec;

/* What the scene uses, so the tracer can leave out whole passes. */
typedef struct rf_features {
    int shadows;           /* some primitive can occlude some light from some surface */
    int specular;          /* some material has Ks > 0: highlights */
    int reflection;        /* some material has Ks > 0: mirror rays */
    int refraction;        /* some material has t > 0 */
    int sampled_lights;    /* some distributed light */
    int meshes;            /* some mesh */
} rf_features;

typedef struct rf_scene {
    rf_image_spec image;
    rf_camera camera;
    rgb ambient;               /* sum of all ambient blocks, I_a */
    rf_material *materials;
    int material_count;
    rf_prim *prims;            /* bounded primitives and planes; one PRIM_MESH per mesh */
    int prim_count;
    rf_mesh *meshes;
    int mesh_count;
    rf_light *lights;          /* point, distant and distributed lights (not ambient) */
    int light_count;
    rf_features features;
    char *oracle;              /* `oracle NAME`, or NULL */
    src_span oracle_where;
    source_set sources;        /* every file read, so later passes can point into them */
} rf_scene;

/* Limits on what an input may ask for, enforced before allocation. */
typedef struct rf_limits {
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
} rf_limits;

/* Defaults a laptop survives; every one can be raised by a CLI flag. */
rf_limits scene_default_limits(void);

/*
 * Reads, parses, evaluates and validates a scene file.  Diagnostics go to
 * diag_out (with warnings when warnings is non-zero).  Returns the scene, or
 * NULL with *status set to one of the exit codes below; on success *status
 * is REFRAY_EXIT_OK.  Never returns a partially valid scene.
 */
rf_scene *scene_load(const char *path, const rf_limits *limits, FILE *diag_out,
                     int warnings, int *status);

/* The same from text in memory (path is used for messages and includes). */
rf_scene *scene_load_text(const char *path, const char *text, size_t len,
                          const rf_limits *limits, FILE *diag_out, int warnings, int *status);

void scene_free(rf_scene *scene);

/* The bytes the meshes' stores hold (positions, normals, corner and normal
 * indices, open-edge masks), and their triangles in *triangles. */
long scene_mesh_bytes(const rf_scene *s, long *triangles);


#endif
