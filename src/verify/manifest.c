/*
 * manifest.c - see manifest.h.  The layout of the file is spec/conformance.md's
 * "The manifest"; every member written here is read back by manifest_read
 * except the texts that are there for people (conventions, comparison),
 * which a program needs only once, from the spec.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "base/status.h"
#include "base/text.h"
#include "verify/manifest.h"
#include "verify/verify.h"

#ifndef REFRAY_HAVE_JSON
#define REFRAY_HAVE_JSON 0
#endif

#if REFRAY_HAVE_JSON
#include <jansson.h>

static const char kit_name[] = "refray conformance kit";
#endif

static const char *const file_keys[MANIFEST_FILE_COUNT] = {
    "scene", "json", "pov", "exact_exr", "exact_pfm", "mask_pgm", "mask_png",
};

const char *manifest_file_key(manifest_file f)
{
    return f >= 0 && f < MANIFEST_FILE_COUNT ? file_keys[f] : "";
}

int manifest_add_note(manifest_scene *s, const char *text)
{
    char **grown = realloc(s->notes, (size_t)(s->note_count + 1) * sizeof *grown);
    if (!grown)
        return STATUS_NO_MEMORY;
    s->notes = grown;
    size_t n = strlen(text) + 1;
    if (!(grown[s->note_count] = malloc(n)))
        return STATUS_NO_MEMORY;
    memcpy(grown[s->note_count++], text, n);
    return STATUS_OK;
}

const manifest_scene *manifest_find(const manifest *m, const char *name)
{
    for (int i = 0; i < m->scene_count; i++)
        if (strcmp(m->scenes[i].name, name) == 0)
            return &m->scenes[i];
    return NULL;
}

double manifest_png16_scale(double peak)
{
    if (!(peak > 0) || !isfinite(peak))
        return 1;
    int e;
    double f = frexp(peak, &e); /* peak = f 2^e, f in [0.5, 1) */
    /* f <= 0.8 is in (0.4, 0.8] already; above, f/2 is in (0.4, 0.5). */
    return ldexp(1.0, f > 0.8 ? -e - 1 : -e);
}

double manifest_png16_step(double scale)
{
    return 1.0 / (65535.0 * scale);
}

void manifest_free(manifest *m)
{
    for (int i = 0; i < m->scene_count; i++) {
        for (int k = 0; k < m->scenes[i].note_count; k++)
            free(m->scenes[i].notes[k]);
        free(m->scenes[i].notes);
    }
    free(m->scenes);
    m->scenes = NULL;
    m->scene_count = 0;
}

#if REFRAY_HAVE_JSON

/* ---- Writing ---- */

/* The model's conventions, for people: the short list that each scene's
 * JSON export also carries in its header. */
static const char *const conventions[][2] = {
    {"color", "linear RGB, three channels; no gamma, no tone curve; values may exceed 1"},
    {"rows", "row 0 of an image is its top row; PFM files store the rows bottom to top, as the PFM format "
             "defines"},
    {"pixel", "image coordinates: x right from 0 to width, y down from 0 to height; pixel (i, j) is the mean "
              "of the radiance at the k x k points (i + (a + 0.5)/k, j + (b + 0.5)/k), a, b = 0 .. k-1, "
              "k = samples (a box filter over cell centres, no jitter)"},
    {"camera", "right-handed; perspective fov is the horizontal angle in degrees, the screen at distance 1 "
               "has half-width tan(fov/2); orthographic width is the horizontal extent in scene units"},
    {"depth", "a camera ray has depth 1; a hit at depth d traces its mirror and transmitted rays only while "
              "d < max_depth (max_depth 1: camera rays only); past it the local colour is kept"},
    {"shading", "C = (1 - t) (Kd Ia + sum S Kd I max(0, N.L)) + sum S Ks I max(0, V.R)^n "
                "+ [depth < max_depth] (Ks C(mirror) + t C(transmitted)); N faces the viewer; "
                "R = 2 (N.L) N - L; no 1/pi anywhere"},
    {"falloff", "I = E/(d + d0) (linear, the default), E/(d + d0)^2 (inverse_square) or E (none); distant "
                "lights: E"},
    {"t", "transparency: 0 opaque, 1 clear; the body is weighted by 1 - t, the transmitted ray by t"},
    {"shadows", "shadow rays are not bent; each surface crossed multiplies the light by its t"},
    {"tir", "on total internal reflection the transmitted ray is the mirror ray, so the mirror direction "
            "carries Ks + t"},
    {"sheets", "planes, disks and single triangles have no inside: a transmitted ray passes straight on"},
    {"distributed_lights", "samples point sources of power E/samples, one in each cell of the most square "
                           "rows x cols grid over the light (disks through the concentric map), jittered "
                           "within the cell; the exact image is their limit as samples grow"},
    {"background", "a ray that hits nothing returns the background colour"},
};

/* Collects failures of json_* calls (NULL values, full memory). */
typedef struct writer {
    int failed;
} writer;

static void put(writer *w, json_t *o, const char *key, json_t *v)
{
    if (!v || json_object_set_new(o, key, v) != 0)
        w->failed = 1;
}

/* A string as valid UTF-8 (jansson refuses anything else). */
static json_t *text(const char *s)
{
    size_t n = strlen(s);
    char *clean = malloc(n + 1);
    if (!clean)
        return NULL;
    text_clean(s, n, clean, n + 1);
    json_t *v = json_string(clean);
    free(clean);
    return v;
}

static json_t *text_or_null(const char *s)
{
    return s[0] ? text(s) : json_null();
}

static json_t *conventions_json(writer *w)
{
    json_t *o = json_object();
    for (size_t i = 0; o && i < sizeof conventions / sizeof conventions[0]; i++)
        put(w, o, conventions[i][0], json_string(conventions[i][1]));
    return o;
}

static json_t *comparison_json(writer *w)
{
    json_t *o = json_object();
    if (!o)
        return NULL;
    put(w, o, "metric", json_string("channel_rel_abs"));
    put(w, o, "rule",
        json_string("compare the renderer's image OUT with the scene's exact image EXACT (same size) pixel by "
                    "pixel, skipping the pixels the mask marks (255); a channel c fails when |OUT_c - EXACT_c| > "
                    "relative * |EXACT_c| + absolute (a NaN or infinity fails); the scene passes when no channel "
                    "of a compared pixel fails and at least one pixel is compared"));
    put(w, o, "relative", json_string("1e-4 for deterministic families, or the view's rounding where that is "
                                      "larger (an eye far from the picture for its width); for "
                                      "sampled families (distributed lights) the family's own bound at the "
                                      "scene's light samples, at least 1e-4"));
    put(w, o, "absolute", json_string("for a float picture (PFM, EXR): 2^-20 of the peak, the rounding of a "
                                      "single precision value near black; for a PNG or PPM picture "
                                      "absolute_png instead, one step of a 16-bit PNG written at the scene's "
                                      "png16_scale: 1 / (65535 * png16_scale), in the exact image's units"));
    put(w, o, "reported", json_string("max_abs = max |OUT - EXACT|; rms = sqrt(mean (OUT - EXACT)^2) over all "
                                      "channels of the compared pixels; max_rel = max |OUT - EXACT| / |EXACT| "
                                      "over channels with |EXACT| > 1e-12 * peak"));
    put(w, o, "adjustments", json_string("before comparing, a renderer's image may be averaged over k x k "
                                         "blocks (rendered k times larger, one ray through each pixel "
                                         "centre) and multiplied by a constant (1 / png16_scale for the "
                                         "kit's .pov files)"));
    return o;
}

static json_t *files_json(writer *w, const manifest_scene *s)
{
    json_t *o = json_object();
    for (int f = 0; o && f < MANIFEST_FILE_COUNT; f++)
        put(w, o, file_keys[f], text_or_null(s->files[f]));
    return o;
}

/* Why files are absent, or NULL when none is. */
static json_t *missing_json(writer *w, const manifest_scene *s)
{
    json_t *o = NULL;
    for (int f = 0; f < MANIFEST_FILE_COUNT; f++) {
        if (s->files[f][0])
            continue;
        if (!o && !(o = json_object()))
            return NULL;
        put(w, o, file_keys[f], text(s->missing[f][0] ? s->missing[f] : "not written"));
    }
    return o ? o : json_object();
}

static json_t *scene_json(writer *w, const manifest_scene *s)
{
    json_t *o = json_object(), *tol = json_object(), *lights = json_array(), *notes = json_array();
    if (!o || !tol || !lights || !notes) {
        json_decref(o);
        json_decref(tol);
        json_decref(lights);
        json_decref(notes);
        return NULL;
    }
    put(w, o, "name", text(s->name));
    put(w, o, "family", text(s->family));
    put(w, o, "checks", text(s->checks));
    put(w, o, "files", files_json(w, s));
    put(w, o, "missing", missing_json(w, s));
    put(w, o, "width", json_integer(s->width));
    put(w, o, "height", json_integer(s->height));
    put(w, o, "samples", json_integer(s->samples));
    put(w, o, "max_depth", json_integer(s->max_depth));
    for (int i = 0; i < s->light_count; i++)
        if (json_array_append_new(lights, json_integer(s->light_samples[i])) != 0)
            w->failed = 1;
    put(w, o, "light_samples", lights);
    put(w, o, "sampled", json_boolean(s->sampled));
    put(w, o, "metric", json_string("channel_rel_abs"));
    put(w, tol, "relative", json_real(s->relative));
    put(w, tol, "absolute", json_real(s->absolute));
    put(w, tol, "absolute_png", json_real(s->absolute_png));
    put(w, o, "tolerance", tol);
    put(w, o, "peak", json_real(s->peak));
    put(w, o, "masked_pixels", json_integer(s->masked));
    put(w, o, "png16_scale", json_real(s->png16_scale));
    put(w, o, "expected_order", s->sampled ? json_real(s->expected_order) : json_null());
    put(w, o, "order_note", text_or_null(s->order_note));
    for (int i = 0; i < s->note_count; i++)
        if (json_array_append_new(notes, text(s->notes[i])) != 0)
            w->failed = 1;
    put(w, o, "pov_notes", notes);
    return o;
}

static json_t *manifest_json(writer *w, const manifest *m)
{
    json_t *o = json_object(), *scenes = json_array();
    if (!o || !scenes) {
        json_decref(o);
        json_decref(scenes);
        return NULL;
    }
    put(w, o, "kit", json_string(kit_name));
    put(w, o, "format_version", json_integer(MANIFEST_FORMAT_VERSION));
    put(w, o, "refray_version", text(m->refray_version));
    put(w, o, "readme", json_string("README.md"));
    put(w, o, "conventions", conventions_json(w));
    put(w, o, "comparison", comparison_json(w));
    for (int i = 0; i < m->scene_count; i++)
        if (json_array_append_new(scenes, scene_json(w, &m->scenes[i])) != 0)
            w->failed = 1;
    put(w, o, "scenes", scenes);
    return o;
}

int manifest_write(const char *path, const manifest *m, char *why, size_t why_size)
{
    writer w = {0};
    json_t *root = manifest_json(&w, m);
    /* 17 significant digits: every double reads back to the same bits. */
    char *bytes = root && !w.failed ? json_dumps(root, JSON_INDENT(2) | JSON_REAL_PRECISION(17)) : NULL;
    json_decref(root);
    if (!bytes) {
        snprintf(why, why_size, "cannot write '%s': out of memory", path);
        return STATUS_NO_MEMORY;
    }
    /* A text file ends with a line feed; json_dumps writes none. */
    size_t n = strlen(bytes);
    char *line = realloc(bytes, n + 2);
    if (!line) {
        free(bytes);
        snprintf(why, why_size, "cannot write '%s': out of memory", path);
        return STATUS_NO_MEMORY;
    }
    line[n] = '\n';
    line[n + 1] = '\0';
    int status = file_write_bytes(path, line, n + 1, why, why_size);
    free(line);
    return status;
}

/* ---- Reading ---- */

typedef struct reader {
    const char *path;
    int index;            /* the scene being read, -1 for the top */
    const char *name;     /* its name once known */
    char *why;
    size_t why_size;
} reader;

/* Prints "path: scenes[i] ('name'): what" into why; returns STATUS_DATA. */
static int bad(reader *r, const char *what, const char *key)
{
    char where[160] = "";
    if (r->index >= 0)
        snprintf(where, sizeof where, " scenes[%d]%s%s%s:", r->index, r->name ? " ('" : "", r->name ? r->name : "",
                 r->name ? "')" : "");
    snprintf(r->why, r->why_size, "%s:%s '%s' %s", r->path, where, key, what);
    return STATUS_DATA;
}

static int get_string(reader *r, json_t *o, const char *key, char *out, size_t size)
{
    const char *s = json_string_value(json_object_get(o, key));
    if (!s)
        return bad(r, "is missing or not a string", key);
    if (strlen(s) >= size)
        return bad(r, "is too long", key);
    strcpy(out, s);
    return 0;
}

/* An optional string: "" when absent or null. */
static int get_optional_string(reader *r, json_t *o, const char *key, char *out, size_t size)
{
    json_t *v = json_object_get(o, key);
    out[0] = '\0';
    return !v || json_is_null(v) ? 0 : get_string(r, o, key, out, size);
}

static int get_long(reader *r, json_t *o, const char *key, long lo, long hi, long *out)
{
    json_t *v = json_object_get(o, key);
    if (!json_is_integer(v) || json_integer_value(v) < lo || json_integer_value(v) > hi) {
        char what[96];
        snprintf(what, sizeof what, "is missing or not a whole number from %ld to %ld", lo, hi);
        return bad(r, what, key);
    }
    *out = (long)json_integer_value(v);
    return 0;
}

static int get_int(reader *r, json_t *o, const char *key, int lo, int hi, int *out)
{
    long v;
    int status = get_long(r, o, key, lo, hi, &v);
    *out = (int)v;
    return status;
}

/* A finite number (integers are numbers too); > 0 when positive is set. */
static int get_number(reader *r, json_t *o, const char *key, int positive, double *out)
{
    json_t *v = json_object_get(o, key);
    *out = json_number_value(v);
    if (!json_is_number(v) || !isfinite(*out) || *out < 0 || (positive && *out == 0))
        return bad(r, positive ? "is missing or not a number > 0" : "is missing or not a number >= 0", key);
    return 0;
}

/* 1 when a kit path stays inside the kit: relative, no ".." part. */
static int inside_kit(const char *p)
{
    if (p[0] == '/' || strcmp(p, "..") == 0 || strncmp(p, "../", 3) == 0)
        return 0;
    size_t n = strlen(p);
    return !strstr(p, "/../") && !(n >= 3 && strcmp(p + n - 3, "/..") == 0);
}

static int read_files(reader *r, json_t *o, manifest_scene *s)
{
    json_t *files = json_object_get(o, "files"), *missing = json_object_get(o, "missing");
    if (!json_is_object(files))
        return bad(r, "is missing or not an object", "files");
    for (int f = 0; f < MANIFEST_FILE_COUNT; f++) {
        int status = get_optional_string(r, files, file_keys[f], s->files[f], sizeof s->files[f]);
        if (status)
            return status;
        if (!inside_kit(s->files[f]))
            return bad(r, "names a file outside the kit", file_keys[f]);
        json_t *why = json_is_object(missing) ? json_object_get(missing, file_keys[f]) : NULL;
        snprintf(s->missing[f], sizeof s->missing[f], "%s", json_is_string(why) ? json_string_value(why) : "");
    }
    if (!s->files[MANIFEST_FILE_EXACT_PFM][0] && !s->files[MANIFEST_FILE_EXACT_EXR][0])
        return bad(r, "names no exact image (exact_exr or exact_pfm)", "files");
    return 0;
}

/* A name is used for directories and reports: letters, digits, _ . -. */
static int plain_name(const char *s)
{
    if (!s[0] || s[0] == '.')
        return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '_' ||
              *s == '-' || *s == '.'))
            return 0;
    return 1;
}

static int read_lights(reader *r, json_t *o, manifest_scene *s)
{
    json_t *a = json_object_get(o, "light_samples");
    if (a && !json_is_array(a))
        return bad(r, "is not an array", "light_samples");
    s->light_count = 0;
    for (size_t i = 0; a && i < json_array_size(a); i++) {
        json_t *v = json_array_get(a, i);
        if (s->light_count == MANIFEST_LIGHTS_MAX || !json_is_integer(v) || json_integer_value(v) < 1 ||
            json_integer_value(v) > 1000000000)
            return bad(r, "holds something other than whole numbers >= 1 (or too many)", "light_samples");
        s->light_samples[s->light_count++] = (int)json_integer_value(v);
    }
    return 0;
}

static int read_notes(reader *r, json_t *o, manifest_scene *s)
{
    json_t *a = json_object_get(o, "pov_notes");
    if (a && !json_is_array(a))
        return bad(r, "is not an array", "pov_notes");
    for (size_t i = 0; a && i < json_array_size(a); i++) {
        const char *t = json_string_value(json_array_get(a, i));
        if (!t)
            return bad(r, "holds something other than strings", "pov_notes");
        if (manifest_add_note(s, t) != 0) {
            snprintf(r->why, r->why_size, "out of memory reading '%s'", r->path);
            return STATUS_NO_MEMORY;
        }
    }
    return 0;
}

static int read_tolerance(reader *r, json_t *o, manifest_scene *s)
{
    json_t *tol = json_object_get(o, "tolerance");
    if (!json_is_object(tol))
        return bad(r, "is missing or not an object", "tolerance");
    int status = get_number(r, tol, "relative", 0, &s->relative);
    if (status == 0 && !verify_tolerance_decisive(s->relative))
        return bad(r, "is 1/2 or more: " VERIFY_UNBOUNDED, "relative");
    status = status ? status : get_number(r, tol, "absolute", 0, &s->absolute);
    /* A kit written before absolute_png judged every format with its one
     * absolute, the PNG step: read so, it is judged as it was. */
    s->absolute_png = s->absolute;
    if (status == 0 && json_object_get(tol, "absolute_png"))
        status = get_number(r, tol, "absolute_png", 0, &s->absolute_png);
    return status;
}

/* [KIT-SCALE-1] png16_scale is a power of two, and [KIT-TOL-1]
 * absolute_png is at most one 16-bit step at it: a larger one is no
 * longer the kit's bound (a smaller one is only stricter), and absolute,
 * a float picture's, is at most absolute_png (a float holds more than 16
 * bits).  The slack of 1e-12 lets the step through written with fewer
 * than 17 digits. */
static int check_scale(reader *r, const manifest_scene *s)
{
    int e;
    if (frexp(s->png16_scale, &e) != 0.5)
        return bad(r, "is not a power of two ([KIT-SCALE-1])", "png16_scale");
    if (s->absolute_png > manifest_png16_step(s->png16_scale) * (1 + 1e-12)) {
        char what[256];
        snprintf(what, sizeof what, "is more than one step of a 16-bit PNG at png16_scale, 1 / (65535 * %.17g) = "
                 "%.17g ([KIT-TOL-1])", s->png16_scale, manifest_png16_step(s->png16_scale));
        return bad(r, what, "absolute_png");
    }
    if (s->absolute > s->absolute_png)
        return bad(r, "is more than absolute_png: a float picture is judged no looser than a PNG ([KIT-TOL-1])",
                   "absolute");
    return 0;
}

static int read_scene(reader *r, json_t *o, manifest_scene *s)
{
    if (!json_is_object(o))
        return bad(r, "is not an object", "scene");
    int status = get_string(r, o, "name", s->name, sizeof s->name);
    if (status)
        return status;
    if (!plain_name(s->name))
        return bad(r, "may hold only letters, digits, '_', '-' and '.' (not first)", "name");
    r->name = s->name;
    long masked = 0;
    json_t *order = json_object_get(o, "expected_order");
    s->sampled = json_is_true(json_object_get(o, "sampled"));
    s->expected_order = json_is_number(order) ? json_number_value(order) : 0;
    if ((status = get_string(r, o, "family", s->family, sizeof s->family)) ||
        (status = get_optional_string(r, o, "checks", s->checks, sizeof s->checks)) ||
        (status = read_files(r, o, s)) || (status = get_int(r, o, "width", 1, 1 << 20, &s->width)) ||
        (status = get_int(r, o, "height", 1, 1 << 20, &s->height)) ||
        (status = get_int(r, o, "samples", 1, 1 << 12, &s->samples)) ||
        (status = get_int(r, o, "max_depth", 1, 1 << 20, &s->max_depth)) || (status = read_lights(r, o, s)) ||
        (status = read_tolerance(r, o, s)) || (status = get_number(r, o, "peak", 0, &s->peak)) ||
        (status = get_long(r, o, "masked_pixels", 0, (long)s->width * s->height, &masked)) ||
        (status = get_number(r, o, "png16_scale", 1, &s->png16_scale)) ||
        (status = get_optional_string(r, o, "order_note", s->order_note, sizeof s->order_note)) ||
        (status = read_notes(r, o, s)))
        return status;
    s->masked = masked;
    return check_scale(r, s);
}

static int read_root(reader *r, json_t *root, manifest *m)
{
    json_t *scenes = json_object_get(root, "scenes");
    if (!json_is_object(root) || !json_is_array(scenes))
        return bad(r, "is missing or not an array (is this a kit's manifest.json?)", "scenes");
    json_t *version = json_object_get(root, "format_version");
    if (!json_is_integer(version) || json_integer_value(version) != MANIFEST_FORMAT_VERSION) {
        snprintf(r->why, r->why_size, "%s: format_version is not %d: a kit of another refray", r->path,
                 MANIFEST_FORMAT_VERSION);
        return STATUS_DATA;
    }
    const char *v = json_string_value(json_object_get(root, "refray_version"));
    snprintf(m->refray_version, sizeof m->refray_version, "%s", v ? v : "");
    size_t n = json_array_size(scenes);
    m->scenes = calloc(n ? n : 1, sizeof *m->scenes);
    if (!m->scenes) {
        snprintf(r->why, r->why_size, "out of memory reading '%s'", r->path);
        return STATUS_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++) {
        r->index = (int)i;
        r->name = NULL;
        m->scene_count = (int)i + 1;
        int status = read_scene(r, json_array_get(scenes, i), &m->scenes[i]);
        if (status)
            return status;
        if (manifest_find(m, m->scenes[i].name) != &m->scenes[i])
            return bad(r, "is the name of an earlier scene too", "name");
    }
    return 0;
}

int manifest_read(const char *path, manifest *m, char *why, size_t why_size)
{
    memset(m, 0, sizeof *m);
    char *bytes;
    size_t len;
    int status = file_read_all(path, 1L << 28, NULL, &bytes, &len, why, why_size);
    if (status)
        return status;
    json_error_t error;
    json_t *root = json_loadb(bytes, len, JSON_REJECT_DUPLICATES, &error);
    free(bytes);
    if (!root) {
        snprintf(why, why_size, "%s:%d:%d: %s", path, error.line, error.column, error.text);
        return STATUS_DATA;
    }
    reader r = {path, -1, NULL, why, why_size};
    status = read_root(&r, root, m);
    json_decref(root);
    if (status)
        manifest_free(m);
    return status;
}

int manifest_is_kit(const char *path)
{
    char *bytes, why[8];
    size_t len;
    if (file_read_all(path, 1L << 28, NULL, &bytes, &len, why, sizeof why))
        return 0;
    json_t *root = json_loadb(bytes, len, 0, NULL);
    free(bytes);
    const char *kit = json_string_value(json_object_get(root, "kit"));
    int is_kit = kit && strcmp(kit, kit_name) == 0;
    json_decref(root);
    return is_kit;
}

int manifest_supported(char *why, size_t why_size)
{
    (void)why;
    (void)why_size;
    return 1;
}

#else /* no JSON */

static int no_json(char *why, size_t why_size)
{
    snprintf(why, why_size, "this refray was built without JSON support (JSON=0, no jansson), which kit "
             "manifests need; rebuild with JSON=1 (Debian: libjansson-dev)");
    return STATUS_USAGE;
}

int manifest_supported(char *why, size_t why_size)
{
    no_json(why, why_size);
    return 0;
}

int manifest_write(const char *path, const manifest *m, char *why, size_t why_size)
{
    (void)path;
    (void)m;
    return no_json(why, why_size);
}

int manifest_read(const char *path, manifest *m, char *why, size_t why_size)
{
    (void)path;
    memset(m, 0, sizeof *m);
    return no_json(why, why_size);
}

int manifest_is_kit(const char *path)
{
    (void)path;
    return 0;
}

#endif
