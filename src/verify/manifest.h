/*
 * manifest.h - the manifest of a conformance kit (spec/conformance.md):
 * for every analytic scene of the kit its files, family, image settings,
 * the tolerance and how it is applied, the exact image's peak, the masked
 * pixels, the scale a 16-bit PNG needs, and the conventions of the model.
 * `refray kit` writes it, `refray conform` and `refray compare --manifest`
 * read it; anyone else can read it with any JSON library.
 *
 * The manifest is JSON (written and read with jansson): in a build without
 * it (JSON=0) manifest_write and manifest_read return STATUS_USAGE (of
 * base/status.h, as every status here) with a reason that names the
 * missing feature.
 */
#ifndef REFRAY_MANIFEST_H
#define REFRAY_MANIFEST_H

#include <stddef.h>

/* The kit's files of one scene; MANIFEST_FILE_COUNT entries, keys as
 * manifest_file_key gives them. */
typedef enum manifest_file {
    MANIFEST_FILE_SCENE,      /* "scene": the .scene as written */
    MANIFEST_FILE_JSON,       /* "json": the scene as JSON (refray export --to json) */
    MANIFEST_FILE_POV,        /* "pov": POV-Ray 3.7 SDL, lights scaled by png16_scale */
    MANIFEST_FILE_EXACT_EXR,  /* "exact_exr": the exact image, 32-bit float OpenEXR */
    MANIFEST_FILE_EXACT_PFM,  /* "exact_pfm": the same as PFM (float, rows bottom to top) */
    MANIFEST_FILE_MASK_PGM,   /* "mask_pgm": excluded pixels, binary 8-bit PGM, 255 = excluded */
    MANIFEST_FILE_MASK_PNG,   /* "mask_png": the same as an 8-bit PNG */
    MANIFEST_FILE_COUNT
} manifest_file;

enum {
    MANIFEST_FORMAT_VERSION = 1,
    MANIFEST_NAME_LEN = 64,
    MANIFEST_PATH_LEN = 256,
    MANIFEST_TEXT_LEN = 512,
    MANIFEST_LIGHTS_MAX = 64
};

/* The relative tolerance of a deterministic family in a kit: what single
 * precision arithmetic along a few bounces leaves, far below any modelling
 * difference (spec/conformance.md, [KIT-TOL-1]). */
#define MANIFEST_REL_DETERMINISTIC 1e-4

typedef struct manifest_scene {
    char name[MANIFEST_NAME_LEN];      /* the scene file's name without .scene */
    char family[MANIFEST_NAME_LEN];    /* its `oracle` family */
    char checks[MANIFEST_TEXT_LEN];    /* the family's one line: what it isolates */
    char files[MANIFEST_FILE_COUNT][MANIFEST_PATH_LEN];   /* relative to the kit; "" absent */
    char missing[MANIFEST_FILE_COUNT][MANIFEST_TEXT_LEN]; /* why a file is absent */
    int width, height;                 /* the exact image */
    int samples;                       /* k: k x k sample points per pixel */
    int max_depth;
    int sampled;                       /* distributed lights: converges as their samples grow */
    int light_count;                   /* distributed lights, in scene order */
    int light_samples[MANIFEST_LIGHTS_MAX];
    double relative, absolute;         /* the tolerance: |out - exact| <= relative |exact| + absolute */
    double absolute_png;               /* absolute's place for a PNG or PPM picture ([KIT-TOL-1]) */
    double peak;                       /* largest exact value over the compared pixels */
    long masked;                       /* pixels excluded */
    double png16_scale;                /* the power of two that puts peak in (0.4, 0.8] */
    double expected_order;             /* sampled: RMS error ~ N^order; 0 otherwise */
    char order_note[MANIFEST_TEXT_LEN];
    char **notes;                      /* the POV-Ray export's approximations */
    int note_count;
} manifest_scene;

typedef struct manifest {
    char refray_version[32];
    manifest_scene *scenes;
    int scene_count;
} manifest;

/* 1 when this build can write and read manifests (JSON=1); else 0 with
 * the reason, which names the missing feature, in why. */
int manifest_supported(char *why, size_t why_size);

/* "scene", "json", "pov", "exact_exr", "exact_pfm", "mask_pgm", "mask_png". */
const char *manifest_file_key(manifest_file f);

/* Appends a note to s (copied).  Returns STATUS_OK, or STATUS_NO_MEMORY. */
int manifest_add_note(manifest_scene *s, const char *text);

/* The scene called name, or NULL. */
const manifest_scene *manifest_find(const manifest *m, const char *name);

/* The power of two 2^-m that takes peak into (0.4, 0.8]; 1 when peak is
 * not > 0 (a black image needs no scale). */
double manifest_png16_scale(double peak);

/* One step of a 16-bit PNG written at scale s, in the image's units:
 * 1 / (65535 s), the absolute part of the tolerance of a PNG picture. */
double manifest_png16_step(double scale);

/* [KIT-TOL-1] The absolute part of the tolerance of a float picture (PFM,
 * EXR), as a fraction of the peak: 16 units of single precision's 2^-24
 * at the peak, the rounding a float renderer's near-black value carries
 * where terms up to the peak cancel. */
#define MANIFEST_ABS_FLOAT_OF_PEAK 0x1p-20

/* Frees what m holds (m itself is the caller's). */
void manifest_free(manifest *m);

/*
 * Writes m as JSON to path atomically.  Returns STATUS_OK; STATUS_USAGE in
 * a build without JSON; STATUS_IO or STATUS_NO_MEMORY; with the reason in
 * why.
 */
int manifest_write(const char *path, const manifest *m, char *why, size_t why_size);

/*
 * Reads the manifest at path into *m (free it with manifest_free).
 * Returns STATUS_OK; STATUS_NO_INPUT when it cannot be opened; STATUS_DATA
 * when it is not JSON ("path:line:col: ...") or lacks a field ("path:
 * scenes[3] ('name'): ..."), or names a file outside the kit (absolute, or
 * with a ".." part); STATUS_USAGE in a build without JSON; STATUS_IO when
 * a read fails; STATUS_NO_MEMORY.  On failure *m is empty.
 */
int manifest_read(const char *path, manifest *m, char *why, size_t why_size);

/* 1 when path is a JSON object whose "kit" is a refray kit's: what `refray
 * kit` may replace (a manifest.json of anything else is someone's data);
 * 0 otherwise and in a build without JSON. */
int manifest_is_kit(const char *path);

#endif
