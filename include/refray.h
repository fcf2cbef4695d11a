/*
 * refray.h - the public API of librefray, a verified reference ray tracer
 * for hand-written scene files (spec/language.md, spec/embedding.md).
 *
 * Load a scene from text in memory or from a file, render it whole or one
 * region at a time into a buffer of yours, write it as PNG, OpenEXR, PFM or
 * PPM.  This header is the whole interface: it includes only standard
 * headers, and every name it declares starts with rf_ or RF_.
 *
 *   #include <refray.h>
 *   cc app.c $(pkg-config --cflags --libs refray)
 *
 * Conventions, for every function below:
 *   - A function that can fail returns an rf_status; RF_OK is 0.  Out of
 *     memory is always RF_ERR_NO_MEMORY.  On failure no output handle is
 *     set (it is NULL) and nothing is left to free.
 *   - No global state: handles are independent, so different threads may
 *     load and render different scenes at once.  One handle must not be
 *     used by two threads at the same time, except that any number of
 *     renderers may share one (const) scene; they allocate from the
 *     scene's allocator when they are made and freed, so with threads that
 *     allocator must be thread-safe (malloc is).
 *   - Numbers are double in this interface whatever the library was built
 *     with; pixels handed to you are float (rf_render_region; a value
 *     beyond FLT_MAX is FLT_MAX) or double (rf_image), linear RGB, never
 *     NaN or infinite.
 *   - Nothing touches the file system unless you call a function that names
 *     a path (rf_scene_load_file, rf_image_write) or your own resolver does.
 *   - Nothing is printed: diagnostics go to the callback you give
 *     (rf_diagnostic_print prints them the way the refray program does).
 */
#ifndef REFRAY_H
#define REFRAY_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Version ---------------------------------------------------------- */

#define RF_VERSION_MAJOR 0
#define RF_VERSION_MINOR 2
#define RF_VERSION_PATCH 0
#define RF_VERSION_STRING "0.2.0"
/* MAJOR * 10000 + MINOR * 100 + PATCH */
#define RF_VERSION_NUMBER 200

/* The shared library's ABI: its SONAME is librefray.so.RF_ABI_VERSION. */
#define RF_ABI_VERSION 1

/* Marks the functions the library exports (it is built with everything
 * else hidden). */
#if defined(RF_BUILDING_LIBRARY) && defined(__GNUC__)
#define RF_API __attribute__((visibility("default")))
#else
#define RF_API
#endif

/* The version of the library linked in, "MAJOR.MINOR.PATCH". */
RF_API const char *rf_version(void);

/* The same as RF_VERSION_NUMBER of the library linked in. */
RF_API int rf_version_number(void);

/* ---- Status ----------------------------------------------------------- */

typedef enum rf_status {
    RF_OK = 0,
    RF_ERR_USAGE,        /* a bad argument or option, a format this build lacks */
    RF_ERR_DATA,         /* a bad scene (see the diagnostics), a malformed file,
                            a ray tree over max_tree_rays */
    RF_ERR_NO_INPUT,     /* a file that cannot be opened */
    RF_ERR_NO_MEMORY,    /* an allocation failed */
    RF_ERR_IO,           /* the operating system refused a read or write */
    RF_ERR_CANCELLED,    /* your cancel callback asked to stop */
    RF_ERR_INTERNAL,     /* a broken invariant: a bug in the library */
    RF_ERR_CHECK         /* a check did not pass (not returned by this API) */
} rf_status;

/* A NULL where this reference does not say one is allowed (an out pointer,
 * a scene name, its text with a size > 0, a path, a scene, a renderer, an
 * image, a stream) returns RF_ERR_USAGE, with an out pointer set to NULL;
 * rf_scene_get_info of NULL fills zeros, and so do rf_renderer_size and
 * rf_renderer_stats of a NULL renderer (into the pointers that are not
 * NULL); rf_renderer_fingerprint, rf_image_width and rf_image_height of
 * NULL return 0, rf_image_pixels NULL; an init of NULL, a free of NULL and
 * rf_diagnostic_print with a NULL stream or record do nothing.  Limits above INT_MAX act as
 * INT_MAX for the counts an int holds (width, height, samples, depth). */

/* A short lower-case description of status ("out of memory"). */
RF_API const char *rf_status_string(rf_status status);

/* ---- Allocator -------------------------------------------------------- */

/*
 * Every allocation of a load and of a render goes through the allocator
 * given to the load (rf_load_options.allocator); the scene keeps a copy and
 * its renderers and images use it too.  NULL means malloc, realloc, free.
 *   - alloc(user, size): size > 0; memory aligned for any object, or NULL.
 *   - resize(user, p, old_size, new_size): p's first min(old, new) bytes in
 *     a block of new_size (p itself or a new one, p then released), or NULL
 *     with p untouched.  May be NULL: the library allocates, copies and
 *     releases instead.
 *   - release(user, p, size): frees p; size is exactly the size p was last
 *     allocated or resized to, so a fixed arena or a counter needs no
 *     header of its own.
 * Image files: the pixel planes of an EXR, and the whole file when it goes
 * to a stream that cannot seek, come from the image's allocator; libpng
 * and OpenEXR themselves allocate with the C library's.
 */
typedef struct rf_allocator {
    void *(*alloc)(void *user, size_t size);
    void *(*resize)(void *user, void *p, size_t old_size, size_t new_size);
    void (*release)(void *user, void *p, size_t size);
    void *user;
} rf_allocator;

/* ---- Diagnostics ------------------------------------------------------ */

typedef enum rf_severity {
    RF_SEVERITY_ERROR,
    RF_SEVERITY_WARNING,
    RF_SEVERITY_NOTE
} rf_severity;

/* One message about the scene.  Its pointers are valid during the
 * callback only.  A message that refers to a file that was included is
 * followed by one note "included from here" per include, outermost last
 * ("in the mesh read here" for an OBJ or PLY file read by a mesh; those
 * notes have no source_line). */
typedef struct rf_diagnostic {
    rf_severity severity;
    const char *file;            /* the file's name; NULL: no location */
    int line, column;            /* 1-based; column in bytes; 0 without a location, or
                                    with file alone (a mesh file read earlier, whose
                                    text is no longer kept) */
    const char *message;         /* "radius must be > 0, got -1" */
    const char *source_line;     /* the line the message is about, without its end of
                                    line (not NUL-terminated); NULL: none to show */
    size_t source_line_length;
    size_t span_length;          /* bytes from column on that the message is about */
} rf_diagnostic;

typedef void (*rf_diagnostic_fn)(void *user, const rf_diagnostic *d);

/* An rf_diagnostic_fn that prints d to the FILE * in stream as the refray
 * program does ("scene.scene:3:17: error: ...", the line, a caret under the
 * span; "refray: error: ..." without a location). */
RF_API void rf_diagnostic_print(void *stream, const rf_diagnostic *d);

/* ---- Scenes ----------------------------------------------------------- */

/* A file's text, as a resolver hands it over. */
typedef struct rf_source {
    const char *path;       /* its name in messages, and `from` for what it
                               includes; NULL: the name as written */
    const char *identity;   /* the same file under any name (finds include
                               cycles); NULL: path */
    const char *text;       /* need not be NUL-terminated */
    size_t size;
} rf_source;

/*
 * Where the files a scene names (`include "x.scene"`, `mesh { file
 * "m.obj" }`) come from.  fetch is called with the path of the including
 * file (`from`, as the load knows it) and the name as written; it fills
 * *out and returns RF_OK, or returns another status with a one-line
 * reason in message (at most message_size bytes with the NUL), which
 * becomes an error at the statement (RF_ERR_NO_MEMORY ends the load as out
 * of memory).  After RF_OK the library copies what it needs, then calls
 * release (when not NULL) with the same *out; a mesh file's text is read
 * where it is, without a copy, and released once its mesh is built (before
 * the load returns).  After a failure it calls nothing.  Enforce your own
 * size limits in fetch.  RF_OK with a NULL text and a size > 0 is an error
 * at the statement, as is a failure whose message is empty (the message
 * then names the status).
 */
typedef struct rf_resolver {
    rf_status (*fetch)(void *user, const char *from, const char *name, rf_source *out, char *message,
                       size_t message_size);
    void (*release)(void *user, rf_source *source);
    void *user;
} rf_resolver;

/* Limits on what an input may ask for, checked before anything is
 * allocated for it (the refray program's --max-* options). */
typedef struct rf_limits {
    long max_width, max_height;   /* pixels */
    long max_pixels;
    long max_samples;             /* k of the k x k camera rays per pixel */
    long max_light_samples;
    long max_depth;               /* at most 1000 whatever is set here: the tracer
                                     recurses once a bounce, about 1.4 KiB of stack
                                     a level (spec/embedding.md, [EMBED-STACK-1]) */
    long max_loop_iterations;     /* per loop, and in total over a load */
    long max_include_depth;
    long max_file_bytes;          /* per file read by rf_scene_load_file (the file
                                     resolver; a resolver of yours bounds its own) */
    long max_mesh_triangles;      /* per mesh */
    long max_primitives;          /* in all, mesh triangles included */
    long max_errors;              /* errors delivered before the load gives up */
    long max_ray_tree;            /* rays below one camera ray */
    long max_input_bytes;         /* of all the files one load reads, each counted once */
    long max_memory_mb;           /* MiB a scene is estimated to need, loaded and
                                     rendered (spec/reliability.md) */
} rf_limits;

typedef struct rf_load_options {
    rf_limits limits;
    int warnings;                 /* 0: warnings are counted, not delivered */
    rf_diagnostic_fn diagnostic;  /* NULL: no messages */
    void *diagnostic_user;
    rf_resolver resolver;         /* for rf_scene_load_memory; fetch NULL: the
                                     scene may not include files or load meshes */
    const rf_allocator *allocator; /* NULL: the C library (copied by the load) */
    /* Asked every few hundred steps of the load (tokens, statements, loop
     * passes, OBJ lines, triangles), so that a stop takes effect within a
     * fraction of a second; non-zero stops the load with RF_ERR_CANCELLED.
     * NULL: never asked. */
    int (*cancel)(void *user);
    void *cancel_user;
    /* rf_scene_load_file's own file resolver (a resolver of yours decides
     * for itself): read_confined 1 reads include and mesh files only from
     * the scene file's directory tree and the trees of read_dirs (a
     * NULL-terminated list of directories, or NULL), judged by each file's
     * real path with every symbolic link resolved; a file elsewhere is an
     * error at the statement that names it.  0 (the default): any file the
     * process can read.  The refray program confines its loads; its
     * --allow-read DIR adds to read_dirs (spec/reliability.md). */
    int read_confined;
    const char *const *read_dirs;
} rf_load_options;

/* The default limits, warnings on, no callback, no resolver, malloc. */
RF_API void rf_load_options_init(rf_load_options *o);

typedef struct rf_scene rf_scene;

/*
 * Loads the scene text[0..size) (no NUL needed), called name in messages,
 * with o (NULL: the defaults).  A name ending in ".json" (any case) makes
 * it a JSON scene (spec/json.md, as `refray export --to json` writes it),
 * any other name a scene in the scene language (spec/language.md).  Reads
 * no file: include and mesh files come from o->resolver only.  Returns
 * RF_OK with *out set, or RF_ERR_DATA (the reasons went to o->diagnostic),
 * RF_ERR_CANCELLED or RF_ERR_NO_MEMORY; RF_ERR_USAGE for a JSON scene when
 * the library was built without JSON support.  A JSON text is parsed by
 * jansson, whose own allocations (freed before the call returns) do not go
 * through o->allocator (spec/embedding.md).  Numbers are read with the
 * decimal point '.' whatever locale the caller has set: the load runs in
 * the C locale on the calling thread only, and gives the caller's locale
 * back on return and while the diagnostic and resolver callbacks run (the
 * cancel callback and the allocator run in the C locale).
 */
RF_API rf_status rf_scene_load_memory(const char *name, const char *text, size_t size,
                                      const rf_load_options *o, rf_scene **out);

/*
 * Loads the scene file path (JSON when it ends in ".json", as above).
 * Unless o has a resolver, include and mesh
 * files are read from the file system relative to the including file, each
 * at most limits.max_file_bytes.  Returns as rf_scene_load_memory, and
 * RF_ERR_NO_INPUT, RF_ERR_DATA (over the size limit) or RF_ERR_IO when path
 * itself cannot be read (reported to o->diagnostic without a location).
 */
RF_API rf_status rf_scene_load_file(const char *path, const rf_load_options *o, rf_scene **out);

/* Frees the scene (NULL is fine).  Free its renderers first. */
RF_API void rf_scene_free(rf_scene *scene);

/* Features a scene uses (rf_scene_info.features). */
enum {
    RF_FEATURE_SHADOWS = 1,         /* something can occlude a light */
    RF_FEATURE_SPECULAR = 2,        /* some Ks > 0: highlights */
    RF_FEATURE_REFLECTION = 4,      /* some Ks > 0: mirror rays */
    RF_FEATURE_REFRACTION = 8,      /* some t > 0 */
    RF_FEATURE_SAMPLED_LIGHTS = 16, /* some distributed light */
    RF_FEATURE_MESHES = 32
};

/* What a scene holds, as `refray check` reports it.  A mesh is one
 * primitive however many triangles it has (they are in mesh_triangles). */
typedef struct rf_scene_info {
    int width, height;      /* the image, pixels */
    int samples;            /* k of the k x k camera rays per pixel */
    int max_depth;
    int primitives;         /* every primitive, a mesh counting as one */
    int spheres, planes, triangles, disks, boxes, cylinders, cones, tori; /* triangle: a `triangle` statement */
    int meshes, mesh_triangles;
    long mesh_bytes;        /* what the meshes' stores hold (vertices, normals,
                               corner indices, open-edge masks), in bytes */
    int lights;             /* point, distant and distributed (not ambient) */
    int materials;
    unsigned features;      /* RF_FEATURE_* */
    const char *oracle;     /* the `oracle` statement's family, or NULL */
} rf_scene_info;

RF_API void rf_scene_get_info(const rf_scene *scene, rf_scene_info *info);

/* What the load found out about one mesh ("refray check" prints it). */
typedef struct rf_mesh_info {
    const char *path;       /* the OBJ or PLY file as the resolver named it;
                               valid while the scene is */
    int triangles;          /* kept (with area after the transforms) */
    int faces;              /* faces read, polygons of any size */
    int dropped;            /* faces or triangles with no area */
    int nonplanar;          /* polygons not on one plane (cut all the same) */
    int fanned;             /* polygons cut as a fan (not simple) */
    int closed;             /* every edge shared by exactly two triangles: a solid */
    int oriented;           /* every shared edge runs opposite ways in its two triangles */
    int pieces;             /* parts connected through shared edges */
    int open_edges;         /* edges of one triangle only */
    int crowded_edges;      /* edges of three or more triangles */
} rf_mesh_info;

/* Fills *info for mesh number index (0 .. rf_scene_info.meshes - 1, in the
 * order the scene names them).  RF_OK, or RF_ERR_USAGE for another index. */
RF_API rf_status rf_scene_get_mesh_info(const rf_scene *scene, int index, rf_mesh_info *info);

/* ---- Rendering -------------------------------------------------------- */

typedef struct rf_render_options {
    int width, height;      /* 0: the scene's */
    int samples;            /* k of the k x k camera rays per pixel; 0: the scene's */
    int max_depth;          /* 0: the scene's; over 1000: RF_ERR_USAGE ([EMBED-STACK-1]) */
    int light_samples;      /* > 0: samples of every distributed light; 0: each light's own */
    long max_tree_rays;     /* rays below one camera ray before the render is
                               refused with RF_ERR_DATA; 0: no limit */
    int no_shortcuts;       /* 1: a verification switch that never changes an
                               image: every pass, ray and primitive test the
                               scene could do without is done anyway, so the
                               pixels are the same to the bit and only the
                               work (and the rays counted against
                               max_tree_rays) grows; 0: the shortcuts */
    /* Called for each row of a region, in order, once the band of rows
     * holding it is made (rows_total: the region's rows). */
    void (*progress)(void *user, int rows_done, int rows_total);
    /* Asked before the first row, after every row (after progress), and
     * every few hundred rays or light samples within a row and steps of
     * the acceleration structure's build, so that a stop takes effect
     * within a fraction of a second however long one pixel takes;
     * non-zero stops with RF_ERR_CANCELLED (spec/reliability.md). */
    int (*cancel)(void *user);
    void *user;             /* for progress and cancel */
} rf_render_options;

/* Everything 0 (the scene's settings), no callbacks. */
RF_API void rf_render_options_init(rf_render_options *o);

/* What rendering did, summed over the regions rendered. */
typedef struct rf_render_stats {
    int width, height, samples, max_depth;
    long camera_rays, shadow_rays, reflection_rays, refraction_rays;
    long total_internal_reflection_rays;
    long light_samples;            /* point-source evaluations */
    long light_samples_on_surface; /* skipped: the light sits on the shaded point */
    long nonfinite;                /* non-finite results replaced by 0 (stays 0) */
    long medium_overflows;         /* glass nested deeper than the tracer follows */
    long node_visits, primitive_tests;
    int bvh_nodes, bvh_leaves, bvh_depth;
    long bvh_bytes;                /* the tree's nodes, part references and plane list */
    int shadows, specular, reflection, refraction; /* 1: the pass ran */
    int overflow_x, overflow_y;    /* after RF_ERR_DATA: the pixel whose ray tree
                                      passed max_tree_rays */
    double seconds;                /* tracing, wall clock */
    double build_seconds;          /* the acceleration structure */
} rf_render_stats;

typedef struct rf_renderer rf_renderer;

/* Prepares scene for rendering with o (NULL: the scene's settings): builds
 * the acceleration structure, in memory from the scene's allocator.  The
 * scene must outlive the renderer.  RF_OK, RF_ERR_USAGE (bad options, or
 * an image size over the max_width, max_height or max_pixels the scene was
 * loaded with), RF_ERR_DATA (an image size that puts an orthographic
 * camera's view, width times height/width tall, outside the scene's
 * extent: spec/language.md [LANG-EXTENT-1]), RF_ERR_CANCELLED (o->cancel)
 * or RF_ERR_NO_MEMORY. */
RF_API rf_status rf_renderer_create(const rf_scene *scene, const rf_render_options *o, rf_renderer **out);

/* The size of the image the renderer renders. */
RF_API void rf_renderer_size(const rf_renderer *r, int *width, int *height);

/*
 * Renders the region x0 <= x < x1, y0 <= y < y1 of the image (y = 0 is the
 * top row) into rgb: pixel (x, y) goes to the three floats (red, green,
 * blue; linear) at rgb[(y - y0) * row_stride + 3 * (x - x0)], so row_stride
 * (in floats) is at least 3 * (x1 - x0).  A pixel's value does not depend
 * on the region it is rendered in.  Allocates nothing.  Returns RF_OK;
 * RF_ERR_USAGE for a region outside the image, empty, or a short stride
 * (or one so long that the last row lies PTRDIFF_MAX bytes past rgb);
 * RF_ERR_CANCELLED; RF_ERR_DATA when a ray tree passed max_tree_rays, or a
 * ray was inside glass nested deeper than the tracer follows (16 solids;
 * medium_overflows > 0 then), at the pixel of rf_renderer_stats.  After a
 * failure the region is partly written (which pixels, and what the one a
 * stop interrupted holds, is not specified); the renderer stays usable, and a
 * later call (after RF_ERR_CANCELLED too) renders as a fresh renderer does.
 */
RF_API rf_status rf_render_region(rf_renderer *r, int x0, int y0, int x1, int y1, float *rgb,
                                  size_t row_stride);

/* The same region in double: exactly the values rf_render_image stores
 * for those pixels (rf_render_region's floats are these, rounded to
 * nearest).  Returns as rf_render_region. */
RF_API rf_status rf_render_region_double(rf_renderer *r, int x0, int y0, int x1, int y1, double *rgb,
                                         size_t row_stride);

/*
 * A 64-bit fingerprint of everything that decides the renderer's pixels:
 * the library's version, the text of every file the scene's load read (not
 * their names), its meshes as built, the image size, samples, max_depth and
 * light_samples.  Two
 * renderers with the same fingerprint render the same pixels, so regions
 * rendered in different processes or on different machines can be put
 * together when their fingerprints agree (refray merge does).  A
 * fingerprint, not a cryptographic hash.
 */
RF_API unsigned long long rf_renderer_fingerprint(const rf_renderer *r);

RF_API void rf_renderer_stats(const rf_renderer *r, rf_render_stats *stats);

RF_API void rf_renderer_free(rf_renderer *r);

/* ---- Images ----------------------------------------------------------- */

typedef struct rf_image rf_image;

/*
 * Renders the whole image of scene with o into a new image (in double,
 * from the scene's allocator).  stats (may be NULL) is filled also when the
 * render fails.  Returns as rf_renderer_create and rf_render_region.
 */
RF_API rf_status rf_render_image(const rf_scene *scene, const rf_render_options *o, rf_image **out,
                                 rf_render_stats *stats);

/* A width x height image of zeros from allocator (NULL: malloc).
 * RF_ERR_USAGE for a size < 1 or too large to address. */
RF_API rf_status rf_image_create(int width, int height, const rf_allocator *allocator, rf_image **out);

RF_API int rf_image_width(const rf_image *img);
RF_API int rf_image_height(const rf_image *img);

/* The pixels: width * height * 3 doubles, row-major from the top row,
 * red, green, blue, linear. */
RF_API double *rf_image_pixels(rf_image *img);

RF_API void rf_image_free(rf_image *img);

typedef enum rf_format {
    RF_FORMAT_UNKNOWN = 0,
    RF_FORMAT_PNG,          /* 8- or 16-bit display codes, sRGB unless linear */
    RF_FORMAT_EXR,          /* linear half or float */
    RF_FORMAT_PFM,          /* linear float */
    RF_FORMAT_PPM           /* 8-bit sRGB */
} rf_format;

/* The format named by path's extension (.png .exr .pfm .ppm, any case). */
RF_API rf_format rf_format_from_path(const char *path);

/* 1 when this build can write fmt (PNG and EXR are build options). */
RF_API int rf_format_available(rf_format fmt);

enum { RF_TONE_CLAMP = 0, RF_TONE_REINHARD = 1 };

typedef struct rf_write_options {
    double exposure_stops;  /* PNG/PPM: v * 2^stops before the tone step */
    int tone;               /* PNG/PPM: RF_TONE_CLAMP or RF_TONE_REINHARD v/(1+v) */
    int linear;             /* PNG/PPM: 1 = linear codes, no sRGB curve */
    int png_bits;           /* 8 or 16 */
    int exr_float;          /* 1 = 32-bit float channels, 0 = half */
    /* Asked as rows are encoded and before the file is put in place:
     * non-zero stops the write with RF_ERR_CANCELLED, and nothing is left
     * at the path.  NULL: never asked. */
    int (*cancel)(void *user);
    void *user;
} rf_write_options;

/* exposure 0, clamp, sRGB, 8-bit PNG, half EXR. */
RF_API void rf_write_options_init(rf_write_options *o);

/* What a write had to change so that the file holds only finite values. */
typedef struct rf_write_stats {
    size_t nonfinite;       /* NaN or infinite values written as 0 */
    size_t clamped;         /* finite values beyond the file's number type */
} rf_write_stats;

/*
 * Writes img to path in the format of its extension, atomically: nothing
 * at path changes unless the whole file was written (it goes to a
 * temporary ".refray-tmp-PID-XXXXXX" beside it first).  Refused with
 * RF_ERR_IO before anything is written: a path that is a symbolic link or
 * not a regular file, a read-only file, another user's file, a name too
 * long for the file system (spec/reliability.md).  The new file gets the
 * old one's permission bits without setuid, setgid and sticky, or 0666
 * less the umask.  o may be NULL (the defaults), stats may be NULL.
 * Returns RF_OK; RF_ERR_USAGE for an unknown extension, a format this
 * build lacks or bad options; RF_ERR_IO; RF_ERR_NO_MEMORY;
 * RF_ERR_CANCELLED; with a one-line reason in message (may be NULL).
 */
RF_API rf_status rf_image_write(const rf_image *img, const char *path, const rf_write_options *o,
                                rf_write_stats *stats, char *message, size_t message_size);

/* The same encoding to an open stream (flushed, not closed; an EXR for a
 * stream that cannot seek, such as a pipe, is built in memory first). */
RF_API rf_status rf_image_write_stream(const rf_image *img, FILE *stream, rf_format fmt,
                                       const rf_write_options *o, rf_write_stats *stats, char *message,
                                       size_t message_size);

#ifdef __cplusplus
}
#endif

#endif
