/*
 * loader.h - state of one scene load, shared by the lowering passes
 * (lower.c statements, lower_props.c property reading, lower_blocks.c
 * camera/image/lights/materials, lower_prims.c primitives, validate.c).
 * Internal to the library: nothing here is public API.
 */
#ifndef REFRAY_LOADER_H
#define REFRAY_LOADER_H

#include "base/arena.h"
#include "lang/ast.h"
#include "base/diag.h"
#include "lang/eval.h"
#include "lang/keywords.h"
#include "scene/scene.h"
#include "lang/schema.h"
#include "lang/polymesh.h"

/* What the load knows of one source file, by its index in the sources. */
typedef struct loader_file {
    char *identity;             /* the resolver's identity of it (freed with the loader) */
    ast *tree;                  /* its statements once parsed (kept: parsed once per load) */
    int parse_failed;           /* parsing it reported errors: it is not lowered again */
} loader_file;

typedef struct loader {
    scene_model *scene;            /* being filled; owns the sources */
    const scene_limits *limits;
    const scene_resolver *resolver;
    const mem *mem;             /* the scene's allocator */
    diag diag;
    arena arena;                /* syntax trees of every file read */
    env env;                    /* constants in scope */
    name_index material_names;  /* over scene->materials, by name (base/names.h) */
    char **include_stack;       /* identities of the files being lowered, outermost first */
    int include_depth, include_cap;
    int nesting;                /* loops and includes open, over every file (LOADER_MAX_NESTING) */
    loader_file *files;         /* per source file */
    int files_cap;
    name_index file_names;      /* over files[].identity */
    long input_bytes;           /* of every file read, each once (--max-input-size) */
    int prims_refused;          /* --max-memory was passed: no more primitives, no more errors */
    int too_deep;               /* the nesting limit was passed: no "in the pass" notes (one per level) */
    long loop_iterations;       /* over the whole load */
    long mesh_triangles;        /* over the whole load: they count as primitives for the limit */
    int *material_uses;         /* per scene material: how many primitives use it */
    int uses_cap;               /* entries allocated in material_uses */
    src_span image_where;       /* first `image` block (file -1: none yet) */
    src_span max_depth_where;   /* its max_depth (or the block; file -1: none) */
    src_span camera_where;
    int default_material;       /* index of the implicit material, -1 until needed */
    const ast *tree;            /* statements of the file being lowered (for "defined later") */
    int out_of_memory;
    cancel_poll cancel;         /* the options' cancel, counted; diag.cancel points here */
    void *json_root;            /* a JSON scene's parse tree (json_t), kept for loader_json_finish */
    int json_file;              /* its text in scene->sources */
} loader;

/* Loops and includes nest at most this deep in all, counted across files
 * ([LANG-LIMIT-NEST-2]): lowering recurses once per level, so the bound
 * keeps the C stack of a load small and known whatever the input (a few
 * hundred bytes a level), where a bound per file let a chain of files
 * each deep within its own limit overflow it. */
enum { LOADER_MAX_NESTING = 256 };

/* The values of one block's properties, by keyword; transforms in order. */
enum { PROPS_MAX_XFORMS = 64 };
typedef struct props {
    const ast *block;                   /* the block itself, for "needs 'x'" errors */
    const ast *by_keyword[KEYWORD_COUNT];
    const ast *xforms[PROPS_MAX_XFORMS];  /* the first xform_count are set */
    int xform_count;
} props;

/* Where a rule of check.c reports: field is a keyword_id naming the
 * property, or one of the pseudo-fields below; the front end maps it to a
 * span only when a rule reports. */
enum {
    CHECK_BLOCK = KEYWORD_COUNT, /* the record as a whole (its block or object) */
    CHECK_TRANSFORM,             /* a primitive's transforms */
    CHECK_RECT_EDGES,            /* a rectangle light's two edges */
    CHECK_RECT_EXTENT,           /* a rectangle light's corner and edges */
    CHECK_CONE_RADIUS0,          /* a cone's radius at from */
    CHECK_CONE_RADIUS1           /* a cone's radius at to */
};
typedef struct check_at {
    src_span (*span)(const void *ctx, int field);
    const void *ctx;
} check_at;

/* lower.c */
int lower_statements(loader *L, const ast *list);
/* Parses sources.files[file] and lowers it in the current scope; identity
 * (taken over, freed here) is on the include stack meanwhile. */
int loader_lower_file(loader *L, int file, char *identity);

/* lower_props.c: each returns 1 when the value is usable (given or
 * defaulted), 0 after reporting an error. */
int props_collect(loader *L, const ast *block, props *out);
int props_number(loader *L, const props *p, keyword_id kw, double fallback, double *out);
int props_vector(loader *L, const props *p, keyword_id kw, vec3 fallback, vec3 *out);
int props_color(loader *L, const props *p, keyword_id kw, rgb fallback, rgb *out);
int props_name(loader *L, const props *p, keyword_id kw, const char **out, src_span *where);
int props_string(loader *L, const props *p, keyword_id kw, const char **out, src_span *where);
int props_require(loader *L, const props *p, keyword_id kw);
/* The span of a property's first value (or of the block when absent). */
src_span props_value_span(const props *p, keyword_id kw);
/* The check_at of a block: a property's first value, or the block's head
 * for a pseudo-field or a property not given. */
check_at props_at(const props *p);
int props_value_at(loader *L, const ast *node, value_kind kind, value *out);
/* v / |v| computed without overflow or underflow (v is first divided by its
 * largest component); 0 when v is zero or not finite. */
int loader_unit(vec3 v, vec3 *out);

/* lower_blocks.c */
int lower_image(loader *L, const ast *block);
int lower_camera(loader *L, const ast *block);
int lower_ambient(loader *L, const ast *block);
int lower_light(loader *L, const ast *block);
int lower_material_def(loader *L, const ast *block);
/* The material a primitive names or defines inline (index), or -1 on error. */
int lower_material_ref(loader *L, const props *p);

/* lower_prims.c */
int lower_primitive(loader *L, const ast *block);
/* Parses sources.files[file] (PLY by its name or first line, else OBJ)
 * into *pm, which must be freed after; 1, or 0 after reporting. */
int lower_parse_mesh(loader *L, int file, polymesh *pm);

/* lower_mesh.c: the mesh read from sources.files[file] (its `file` value at
 * `at`; its text held in *held, given back here once the mesh is built)
 * becomes scene.meshes[k] and one PRIM_MESH primitive made from *proto
 * (material set; kind, mesh and u are filled in).  Takes over (and
 * changes) pm's arrays; pm must still be freed.  w and l NULL: the
 * positions are in world coordinates and the normals unit already, kept
 * bit for bit (a JSON scene's); held NULL: no mesh file text to give back.
 * Returns 1, or 0 after reporting an error. */
int lower_mesh(loader *L, polymesh *pm, int file, scene_source *held, src_span at, scene_prim *proto,
               const xform *w, const xform *l);

/* lower_frame.c: a shape's transforms once they are read. */
/* Whether the transform mirrors (negative determinant): triangles then
 * swap two corners to keep their normal on the mirrored side. */
int lower_mirrors(const xform *w);
/* Keeps a shape's local parameters with the matrix pair (to_world,
 * to_local), the pair out of line (scene.kept); 0 when out of memory
 * (reported). */
int lower_keep_frame(loader *L, scene_prim *prim, const xform *to_world, const xform *to_local);
/* A normal or axis n taken to the world by the inverse transpose, made unit
 * (or left zero or non-finite when it cannot be, for the range check). */
vec3 lower_transformed_normal(const xform *to_local, vec3 n);

/* lower_quadrics.c: cylinder, cone and torus (block is KW_CYLINDER,
 * KW_CONE or KW_TORUS); each returns 1 or reports and returns 0. */
int lower_quadric(loader *L, const props *p, keyword_id block, scene_prim *prim);
/* The transforms baked in or the frame kept; 0 when out of memory. */
int lower_place_quadric(loader *L, scene_prim *prim, const xform *to_world, const xform *to_local);

/*
 * check.c: the rules of the scene model, shared by every front end.  Each
 * returns 1 when the value passes, else 0 after reporting at
 * check_span(at, field).
 */
src_span check_span(const check_at *at, int field);
/* 1 when every number of a placed cylinder, cone or torus is finite and in
 * its domain. */
int lower_quadric_in_range(const scene_prim *prim);
/* lo <= x <= hi, an end exclusive when lo_open / hi_open; what names x. */
int check_range(loader *L, const check_at *at, int field, const char *what, double x, double lo, int lo_open,
                double hi, int hi_open);
int check_color(loader *L, const check_at *at, int field, const char *what, rgb c, double lo, double hi);
/* x a whole number in [lo, hi] into *out (limit_flag names the option that raises hi). */
int check_whole(loader *L, const check_at *at, int field, double x, long lo, long hi, const char *limit_flag,
                long *out);
int check_is_unit(vec3 v);
int check_unit(loader *L, const check_at *at, int field, const char *what, vec3 v);
/* size: width, height, samples, max_depth as read; fills *im. */
int check_image(loader *L, const check_at *at, const double size[4], rgb background, scene_image_spec *im);
/* fov and width in range (and where width is kept in cam->width_where, for
 * check_view_extent); the orthonormal basis derived from eye, look_at and
 * up (a zero view and a zero up both reported); check_camera: both. */
int check_camera_ranges(loader *L, const check_at *at, scene_camera *cam);
int check_camera_basis(loader *L, const check_at *at, scene_camera *cam);
int check_camera(loader *L, const check_at *at, scene_camera *cam);
int check_ambient(loader *L, const check_at *at, rgb color);
/* power and d0 */
int check_light(loader *L, const check_at *at, const scene_light *light);
int check_light_samples(loader *L, const check_at *at, double x, int *out);
/* the edges span an area and stay finite; sets light->normal. */
int check_rectangle(loader *L, const check_at *at, scene_light *light);
int check_material(loader *L, const check_at *at, const scene_material *m);
int check_radius(loader *L, const check_at *at, double radius);
/* corners a, b differ on every axis; sets the box's lo and hi. */
int check_box(loader *L, const check_at *at, vec3 a, vec3 b, scene_prim *prim);
int check_invert(loader *L, const check_at *at, const xform *to_world, xform *to_local);
/* A cylinder's or cone's ends differ (else at KW_TO). */
int check_ends(loader *L, const check_at *at, vec3 from, vec3 to);
/* A cone's radii: each >= 0 (at CHECK_CONE_RADIUS0, 1), one > 0 (at KW_RADII). */
int check_cone_radii(loader *L, const check_at *at, const double radius[2]);
/* major > 0, minor > 0, minor < major, minor >= major * TORUS_THINNEST
 * (at KW_MINOR). */
#define TORUS_THINNEST 0x1p-16
int check_torus(loader *L, const check_at *at, double major, double minor);
/* A primitive as the tracer gets it: finite, unit normals, finite
 * matrices (else an error at CHECK_BLOCK), a triangle with area (else at
 * KW_VERTICES). */
int check_placed(loader *L, const check_at *at, const scene_prim *prim);
/* Whether a triangle has no area: its edges' directions are parallel to
 * within 4 epsilon (the size of the triangle does not matter). */
int check_degenerate(vec3 a, vec3 b, vec3 c);
/* A check_at that gives *span for every field. */
check_at check_at_fixed(const src_span *span);

/* check_extent.c: the scene's extent [LANG-EXTENT-1]: every coordinate
 * and size within 2^500, every non-zero size at least 2^-500.  A placed
 * primitive (at CHECK_BLOCK; a mesh's faces by check_face_extent, at the
 * face), the camera's eye, look_at and width, a light (a point light at
 * KW_POSITION, a disk light at KW_CENTER / KW_RADIUS, a rectangle at
 * CHECK_RECT_EXTENT; a distant light has none). */
int check_prim_extent(loader *L, const check_at *at, const scene_prim *prim);
int check_face_extent(loader *L, src_span at, const vec3 p[3]);
int check_camera_extent(loader *L, const check_at *at, const scene_camera *cam);
/* The orthographic view on the scene's own image (scene_view_out), once
 * both the camera and the image are known: at the camera's width. */
int check_view_extent(loader *L, const scene_model *s);
int check_light_extent(loader *L, const check_at *at, const scene_light *light);

/* validate.c: whole-scene checks after lowering, and the feature record. */
int validate_scene(loader *L);

/* loader.c: the load's state; an out-of-memory error is reported once.
 * L must not move after loader_init (its diag points into it). */
void loader_init(loader *L, scene_model *s, const scene_load_opts *o);
/* Out of memory, too many errors, or cancelled: every pass stops.  Counts
 * one step of the cancel poll. */
int loader_stop(const loader *L);
void loader_free(loader *L);
/* Asks the resolver for `name`, written in the statement at `at`, and
 * adds it to the sources as included from `at` (a file already read in
 * this load is not copied again: its index is returned, its included_from
 * moved to `at`).  Returns the file's index, with *identity a copy of its
 * identity (free with mem_free_string) when identity is not NULL; or -1
 * with the reason in why (the resolver's, or --max-input-size passed),
 * not reported, unless memory ran out (then reported, the flag set). */
int loader_fetch(loader *L, const char *name, src_span at, char **identity, char *why, size_t why_size);
/* Records file (just added to the sources) under identity for the rest of
 * the load, its len bytes counted; 0 after reporting when out of memory. */
int loader_add_file(loader *L, int file, const char *identity, size_t len);
/* The same for a mesh file, without copying its text (a mesh file can be
 * tens of megabytes): the sources point into the resolver's text, held in
 * *held, until loader_release_mesh; no line index is built (a message
 * finds its line by scanning).  Returns the file's index or -1 as
 * loader_fetch (nothing then held). */
int loader_fetch_mesh(loader *L, const char *name, src_span at, scene_source *held, char *why, size_t why_size);
/* Gives a mesh file's text back to the resolver once no message will
 * point into it; the file keeps its name (later messages name it without
 * a line).  Call it exactly once after loader_fetch_mesh succeeded. */
void loader_release_mesh(loader *L, int file, scene_source *held);
/* Shrinks the scene's arrays to their counts (the load is over). */
void loader_trim(loader *L);
void loader_oom(loader *L);
/* The defaults of spec/language.md for what a scene does not say. */
void loader_scene_defaults(scene_model *s);
/* The bytes the load holds beside its primitives (texts, syntax trees),
 * for scene_memory_estimate. */
double loader_memory_extra(const loader *L);
/* loader.c: growable arrays of the scene being built; NULL when full or out of memory. */
scene_prim *loader_add_prim(loader *L, src_span where);
scene_light *loader_add_light(loader *L);
scene_material *loader_add_material(loader *L);
scene_mesh *loader_add_mesh(loader *L);
/* A copy of text from the load's allocator, or NULL after reporting out
 * of memory. */
char *loader_strdup(loader *L, const char *text);
/* Fetches the OBJ or PLY file `name`, written at `at`, into the load's
 * sources (loader_fetch_mesh: its text held in *held until
 * loader_release_mesh), so its errors point into it: the one place a mesh
 * file is read.  1 with its index in *file, else 0 after reporting at `at`. */
int loader_read_mesh(loader *L, const char *name, src_span at, scene_source *held, int *file);

/* load_json.c (JSON=1 builds): reads sources.files[file] as a JSON scene
 * (spec/json.md) into the scene, with the rules of check.c. */
int loader_lower_json(loader *L, int file);

/* After the load's validation (ok: it passed): checks the derived members
 * of the JSON scene against it ([JSON-DERIVED-1]) and frees its parse
 * tree.  Returns ok, or 0 after an error of a derived member. */
int loader_json_finish(loader *L, int ok);

#endif
