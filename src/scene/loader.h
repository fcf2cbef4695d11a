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

typedef struct loader {
    rf_scene *scene;            /* being filled; owns the sources */
    const rf_limits *limits;
    diag diag;
    arena arena;                /* syntax trees of every file read */
    env env;                    /* constants in scope */
    char **include_stack;       /* real paths of the files being lowered, outermost first */
    int include_depth;
    long loop_iterations;       /* over the whole load */
    int *material_uses;         /* per scene material: how many primitives use it */
    int material_cap, prim_cap, light_cap, mesh_cap;
    src_span image_where;       /* first `image` block (file -1: none yet) */
    src_span camera_where;
    int default_material;       /* index of the implicit material, -1 until needed */
    int out_of_memory;
} loader;

/* The values of one block's properties, by keyword; transforms in order. */
enum { PROPS_MAX_XFORMS = 64 };
typedef struct props {
    const ast *block;                   /* the block itself, for "needs 'x'" errors */
    const ast *by_keyword[KEYWORD_COUNT];
    const ast *xforms[PROPS_MAX_XFORMS];
    int xform_count;
} props;

/* Where a rule of check.c reports: field is a keyword_id naming the
 * property, or one of the pseudo-fields below; the front end maps it to a
 * span only when a rule reports. */
enum {
    CHECK_BLOCK = KEYWORD_COUNT, /* the record as a whole (its block or object) */
    CHECK_TRANSFORM,             /* a primitive's transforms */
    CHECK_RECT_EDGES,            /* a rectangle light's two edges */
    CHECK_RECT_EXTENT            /* a rectangle light's corner and edges */
};
typedef struct check_at {
    src_span (*span)(const void *ctx, int field);
    const void *ctx;
} check_at;

/* lower.c */
int lower_statements(loader *L, const ast *list);
/* Parses sources.files[file] and lowers it in the current scope. */
int loader_lower_file(loader *L, int file);

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

/*
 * check.c: the rules of the scene model, shared by every front end.  Each
 * returns 1 when the value passes, else 0 after reporting at
 * check_span(at, field).
 */
src_span check_span(const check_at *at, int field);
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
int check_image(loader *L, const check_at *at, const double size[4], rgb background, rf_image_spec *im);
/* up, fov, width, and the orthonormal basis derived from eye, look_at, up. */
int check_camera(loader *L, const check_at *at, rf_camera *cam);
int check_ambient(loader *L, const check_at *at, rgb color);
/* power and d0 */
int check_light(loader *L, const check_at *at, const rf_light *light);
int check_light_samples(loader *L, const check_at *at, double x, int *out);
/* the edges span an area and stay finite; sets light->normal. */
int check_rectangle(loader *L, const check_at *at, rf_light *light);
int check_material(loader *L, const check_at *at, const rf_material *m);
int check_radius(loader *L, const check_at *at, double radius);
/* corners a, b differ on every axis; sets the box's lo and hi. */
int check_box(loader *L, const check_at *at, vec3 a, vec3 b, rf_prim *prim);
int check_invert(loader *L, const check_at *at, const xform *to_world, xform *to_local);
/* A primitive as the tracer gets it: finite, unit normals, finite
 * matrices (else an error at CHECK_BLOCK), a triangle with area (else at
 * KW_VERTICES). */
int check_placed(loader *L, const check_at *at, const rf_prim *prim);
/* A check_at that gives *span for every field. */
check_at check_at_fixed(const src_span *span);

/* validate.c: whole-scene checks after lowering, and the feature record. */
int validate_scene(loader *L);

/* loader.c: the load's state; an out-of-memory error is reported once. */
void loader_init(loader *L, rf_scene *s, const rf_limits *limits, FILE *diag_out, int warnings);
void loader_free(loader *L);
void loader_oom(loader *L);
/* The defaults of spec/language.md for what a scene does not say. */
void loader_scene_defaults(rf_scene *s);
/* loader.c: growable arrays of the scene being built; NULL when full or out of memory. */
rf_prim *loader_add_prim(loader *L, src_span where);
rf_light *loader_add_light(loader *L);
rf_material *loader_add_material(loader *L);
rf_mesh *loader_add_mesh(loader *L);
/* A malloc'd copy of text, or NULL after reporting out of memory. */
char *loader_strdup(loader *L, const char *text);
/* Reads the OBJ file `name` (relative to the directory of the file that
 * span `at` is in) into the load's sources, so its errors point into it;
 * 1 with its index in *file, else 0 after reporting at `at`. */
int loader_read_obj(loader *L, const char *name, src_span at, int *file);

/* load_json.c (JSON=1 builds): reads sources.files[file] as a JSON scene
 * (spec/json.md) into the scene, with the rules of check.c. */
int loader_lower_json(loader *L, int file);
/* Whether path names a JSON scene: it ends in ".json" (any case). */
int loader_is_json(const char *path);

#endif
