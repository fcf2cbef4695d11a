/*
 * kit.c - see kit.h.  A scene's files are one table (artifacts[]): each
 * entry names the manifest key, the file's suffix and its writer, and a
 * writer may decline (KIT_ABSENT) with a reason that goes into the
 * manifest, so a build without OpenEXR, libpng or an export still makes a
 * complete, honest kit.  The exact image, its mask and every number of the
 * manifest come from verify_exact_build, the same as `refray verify` and
 * `refray oracle` use.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "base/cancel.h"
#include "export/export_json.h"
#include "io/diag_print.h"
#include "io/fileio.h"
#include "io/filewrite.h"
#include "io/scene_file.h"
#include "export/export_pov.h"
#include "io/image_io.h"
#include "verify/conform_kit.h"
#include "verify/kit.h"
#include "verify/verify.h"

/* A writer's "not written, and that is not an error" (reason in why). */
enum { KIT_ABSENT = -1 };

/* What a writer of one scene's files gets. */
typedef struct kit_job {
    const char *name;          /* NAME */
    const scene_model *scene;
    const verify_exact *exact;
    manifest_scene *entry;     /* notes may be added */
} kit_job;

typedef int (*kit_writer)(const kit_job *job, const char *path, char *why, size_t why_size);

typedef struct kit_artifact {
    manifest_file file;
    const char *suffix;        /* after NAME */
    kit_writer write;
} kit_artifact;

static int write_scene(const kit_job *job, const char *path, char *why, size_t why_size)
{
    const source_file *root = job->scene->sources.files[0];
    return file_write_bytes(path, root->text, root->len, why, why_size);
}

/* The scene as JSON (spec/json.md), what `refray export SCENE --to json
 * -o PATH` writes, meshes inline so the file stands alone. */
static int write_json(const kit_job *job, const char *path, char *why, size_t why_size)
{
    export_json_opts o;
    char source[MANIFEST_NAME_LEN + 8];
    memset(&o, 0, sizeof o);
    snprintf(source, sizeof source, "%s.scene", job->name);
    o.source = source;
    int status = export_json_file(job->scene, &o, path, why, why_size);
    return status == STATUS_USAGE ? KIT_ABSENT : status;
}

static int write_pov(const kit_job *job, const char *path, char *why, size_t why_size)
{
    pov_opts po;
    pov_notes notes;
    char source[MANIFEST_NAME_LEN + 8];
    memset(&po, 0, sizeof po);
    snprintf(source, sizeof source, "%s.scene", job->name);
    po.source = source;
    po.scale = job->entry->png16_scale;
    int status = pov_export_file(job->scene, &po, path, &notes, why, why_size);
    if (status == STATUS_DATA) {
        snprintf(why, why_size, "refused by the POV-Ray export: %s", notes.reason);
        return KIT_ABSENT;
    }
    for (int i = 0; status == 0 && i < notes.count && i < POV_NOTE_MAX; i++)
        status = manifest_add_note(job->entry, notes.text[i]);
    if (status == 0 && notes.count > POV_NOTE_MAX) {
        char more[64];
        snprintf(more, sizeof more, "... and %d more, in the header of the .pov", notes.count - POV_NOTE_MAX);
        status = manifest_add_note(job->entry, more);
    }
    return status;
}

/* The image formats this build lacks are absent, not errors. */
static int available(const char *path, char *why, size_t why_size)
{
    img_format fmt = img_format_from_path(path);
    if (img_format_available(fmt))
        return 1;
    snprintf(why, why_size, "this refray was built without %s", fmt == IMG_FORMAT_EXR ? "OpenEXR (EXR=0)"
                                                                                       : "libpng (PNG=0)");
    return 0;
}

static int write_exact(const kit_job *job, const char *path, char *why, size_t why_size)
{
    if (!available(path, why, why_size))
        return KIT_ABSENT;
    img_write_opts wo = img_write_opts_default();
    wo.exr_float = 1;
    return img_write(path, &job->exact->image, &wo, why, why_size);
}

static int write_mask(const kit_job *job, const char *path, char *why, size_t why_size)
{
    if (img_format_from_path(path) != IMG_FORMAT_UNKNOWN && !available(path, why, why_size))
        return KIT_ABSENT;
    const img_buf *img = &job->exact->image;
    return verify_mask_write(path, job->exact->excluded, img->width, img->height, why, why_size);
}

/* Every file of a scene, in the order of the manifest's keys. */
static const kit_artifact artifacts[] = {
    {MANIFEST_FILE_SCENE, ".scene", write_scene},
    {MANIFEST_FILE_JSON, ".json", write_json},
    {MANIFEST_FILE_POV, ".pov", write_pov},
    {MANIFEST_FILE_EXACT_EXR, ".exact.exr", write_exact},
    {MANIFEST_FILE_EXACT_PFM, ".exact.pfm", write_exact},
    {MANIFEST_FILE_MASK_PGM, ".mask.pgm", write_mask},
    {MANIFEST_FILE_MASK_PNG, ".mask.png", write_mask},
};

/* ---- One scene ---- */

/* The name of a scene file without its directory and ".scene". */
static void scene_name(const char *path, char *out, size_t size)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t n = strlen(base);
    if (n > 6 && strcmp(base + n - 6, ".scene") == 0)
        n -= 6;
    snprintf(out, size, "%.*s", (int)n, base);
}

/* The largest |value| over the compared pixels (metrics.h's peak). */
static double peak_of(const verify_exact *e)
{
    double peak = 0;
    size_t n = (size_t)e->image.width * (size_t)e->image.height;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3 && !e->excluded[p]; c++)
            peak = fmax(peak, fabs(e->image.rgb[3 * p + c]));
    return peak;
}

/*
 * The RMS order of the tracer's stratified light samples (spec/verify.md):
 * N^-1 where the light is wholly seen or hidden, N^-3/4 where a shadow edge
 * crosses it, which the disk_occluded family has by design; measured by
 * `make report` at -0.97 .. -1.00 and -0.77 .. -0.79.
 */
static void expected_order(manifest_scene *m)
{
    int edge = strcmp(m->family, "disk_occluded") == 0;
    m->expected_order = edge ? -0.75 : -1;
    snprintf(m->order_note, sizeof m->order_note, "%s",
             edge ? "RMS error ~ N^-3/4 in the light samples N: a shadow edge crosses the light (stratified "
                    "sampling; -1 where the light is wholly seen)"
                  : "RMS error ~ N^-1 in the light samples N: stratified sampling of a smooth, unoccluded "
                    "light");
}

/* The manifest's numbers for a scene whose exact image is e. */
static void describe(const scene_model *s, const verify_exact *e, manifest_scene *m)
{
    const oracle_family *f = e->family;
    snprintf(m->family, sizeof m->family, "%s", f->name);
    snprintf(m->checks, sizeof m->checks, "%s", f->isolates);
    m->width = e->view.width;
    m->height = e->view.height;
    m->samples = e->view.samples;
    m->max_depth = e->view.max_depth;
    m->sampled = f->sampled;
    for (int i = 0; i < s->light_count && m->light_count < MANIFEST_LIGHTS_MAX; i++)
        if (s->lights[i].kind == LIGHT_RECTANGLE || s->lights[i].kind == LIGHT_DISK)
            m->light_samples[m->light_count++] = s->lights[i].samples;
    /* The family's own bound where it is the larger (a sampled render's, a
     * far view's rounding: [ORACLE-VIEW-ROUNDING-1]); one that is no bound
     * is kept as it is, for build_scene to refuse (fmax would drop a NaN). */
    double tol = f->tolerance(&e->view, 0);
    m->relative = verify_tolerance_usable(tol) ? fmax(tol, MANIFEST_REL_DETERMINISTIC) : tol;
    m->peak = peak_of(e);
    m->masked = e->excluded_count;
    m->png16_scale = manifest_png16_scale(m->peak);
    m->absolute_png = manifest_png16_step(m->png16_scale);
    m->absolute = MANIFEST_ABS_FLOAT_OF_PEAK * m->peak;
    if (f->sampled)
        expected_order(m);
}

/* Loads path and builds its exact image; 0 or the status, reason in why. */
static int load_exact(const char *path, const kit_opts *o, scene_model **s, verify_exact *e, char *why,
                      size_t why_size)
{
    int status;
    scene_load_opts lo;
    scene_load_opts_init(&lo);
    lo.limits = o->limits;
    lo.warnings = o->warnings;
    lo.sink = o->diag ? diag_print : NULL;
    lo.sink_user = o->diag;
    *s = scene_file_load_confined(path, &lo, o->read_dirs, &status);
    if (!*s) {
        snprintf(why, why_size, "cannot load '%s' (see the messages above)", path);
        return status;
    }
    if ((*s)->sources.count != 1 || (*s)->mesh_count != 0) {
        snprintf(why, why_size, "'%s' reads other files (include or mesh): a kit holds single-file scenes",
                 path);
        return STATUS_DATA;
    }
    char reason[512];
    oracle_view v = verify_view(*s, NULL);
    const oracle_family *f = verify_family(*s, &v, &status, reason, sizeof reason);
    if (!f) {
        snprintf(why, why_size, "'%s' has no exact image: %s", path, reason);
        return STATUS_DATA;
    }
    if ((status = verify_exact_build(f, &v, e)) != 0) {
        snprintf(why, why_size, "'%s': %s", path, verify_exact_error(status));
        return status;
    }
    return 0;
}

static char *path_of(const char *dir, const char *name, const char *suffix)
{
    size_t n = strlen(dir) + strlen(name) + strlen(suffix) + 2;
    char *p = malloc(n);
    if (p)
        snprintf(p, n, "%s/%s%s", dir, name, suffix);
    return p;
}

/* Writes every file of the table into root/scenes/NAME/. */
static int write_files(const char *root, const kit_job *job, char *why, size_t why_size)
{
    char rel_dir[MANIFEST_NAME_LEN + 16];
    snprintf(rel_dir, sizeof rel_dir, "scenes/%s", job->name);
    char *dir = path_of(root, rel_dir, "");
    int status = dir ? file_make_dirs(dir, why, why_size) : STATUS_NO_MEMORY;
    for (size_t i = 0; status == 0 && i < sizeof artifacts / sizeof artifacts[0]; i++) {
        const kit_artifact *a = &artifacts[i];
        char *path = path_of(dir, job->name, a->suffix);
        char reason[MANIFEST_TEXT_LEN] = "";
        status = path ? a->write(job, path, reason, sizeof reason) : STATUS_NO_MEMORY;
        if (status == KIT_ABSENT) {
            snprintf(job->entry->missing[a->file], MANIFEST_TEXT_LEN, "%s", reason);
            status = 0;
        } else if (status == 0) {
            snprintf(job->entry->files[a->file], MANIFEST_PATH_LEN, "%s/%s%s", rel_dir, job->name, a->suffix);
        } else {
            snprintf(why, why_size, "%s", reason[0] ? reason : "out of memory");
        }
        free(path);
    }
    free(dir);
    return status;
}

static int build_scene(const char *root, const char *path, const kit_opts *o, manifest_scene *m, char *why,
                       size_t why_size)
{
    scene_model *s = NULL;
    verify_exact e;
    memset(&e, 0, sizeof e);
    int status = load_exact(path, o, &s, &e, why, why_size);
    if (status == 0) {
        describe(s, &e, m);
        /* The relative bound alone, for its own reason; then with the
         * absolute one at the peak ([VERIFY-UNBOUNDED-3]: a black image
         * has no verdict either). */
        int relative_ok = verify_tolerance_decisive(m->relative);
        if (!relative_ok || !conform_bound_decisive(m->relative, m->absolute_png, m->peak)) {
            char reason[400];
            conform_bound_reason(m->relative, m->absolute_png, m->peak, reason, sizeof reason);
            if (relative_ok)
                snprintf(why, why_size, "'%s': %s", path, reason);
            else
                snprintf(why, why_size, "'%s': %s (its error bound, relative, is %.3g)", path,
                         verify_tolerance_usable(m->relative) ? VERIFY_UNBOUNDED : VERIFY_INEXACT, m->relative);
            verify_exact_free(&e);
            scene_free(s);
            return STATUS_DATA;
        }
        kit_job job = {m->name, s, &e, m};
        status = write_files(root, &job, why, why_size);
        verify_exact_free(&e);
    }
    if (s)
        scene_free(s);
    return status;
}

/* ---- The whole kit ---- */

static int empty_dir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int entries = 0;
    while (d && (e = readdir(d)) != NULL)
        entries += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return d && entries == 0;
}

/* 1 when dir may be replaced: missing, an empty directory, or a kit. */
static int replaceable(const char *dir, char *why, size_t why_size)
{
    struct stat sb;
    if (stat(dir, &sb) != 0) {
        snprintf(why, why_size, "cannot use '%s': %s", dir, strerror(errno));
        return errno == ENOENT;
    }
    /* A kit is told by its manifest's "kit" member, not by the file's name:
     * a web extension's or an app's manifest.json is not a reason to
     * delete the directory around it. */
    char *manifest_path = path_of(dir, "manifest", ".json");
    int kit = manifest_path && manifest_is_kit(manifest_path);
    free(manifest_path);
    if (S_ISDIR(sb.st_mode) && (kit || empty_dir(dir)))
        return 1;
    snprintf(why, why_size,
             "'%s' exists and is not a kit (no manifest.json of a refray kit): give a new or empty directory", dir);
    return 0;
}

/* The names, checked unique (they are directories of the kit). */
static int name_scenes(const char *const *scenes, int count, manifest *m, char *why, size_t why_size)
{
    for (int i = 0; i < count; i++) {
        manifest_scene *s = &m->scenes[i];
        scene_name(scenes[i], s->name, sizeof s->name);
        m->scene_count = i + 1;
        if (!s->name[0] || manifest_find(m, s->name) != s) {
            snprintf(why, why_size, "two scenes would be called '%s' in the kit ('%s')", s->name, scenes[i]);
            return STATUS_USAGE;
        }
    }
    return 0;
}

/* Builds everything in tmp, then README and manifest last. */
static int fill_kit(const char *tmp, const char *const *scenes, int count, const kit_opts *o, manifest *m,
                    char *why, size_t why_size)
{
    int status = 0;
    cancel_poll stop = cancel_poll_make(o->cancel, o->cancel_user);
    for (int i = 0; status == 0 && i < count; i++) {
        if (cancel_now(&stop)) {
            snprintf(why, why_size, "interrupted");
            return STATUS_CANCELLED;
        }
        status = build_scene(tmp, scenes[i], o, &m->scenes[i], why, why_size);
    }
    char *readme = status == 0 ? path_of(tmp, "README", ".md") : NULL;
    char *manifest_path = status == 0 ? path_of(tmp, "manifest", ".json") : NULL;
    if (status == 0 && (!readme || !manifest_path))
        status = STATUS_NO_MEMORY;
    if (status == 0)
        status = kit_readme_write(readme, m, why, why_size);
    if (status == 0)
        status = manifest_write(manifest_path, m, why, why_size);
    free(readme);
    free(manifest_path);
    return status;
}

/* Puts the finished tmp in dir's place. */
static int install(const char *tmp, const char *dir, char *why, size_t why_size)
{
    int status = file_remove_tree(dir, why, why_size);
    if (status == 0 && rename(tmp, dir) != 0) {
        snprintf(why, why_size, "cannot rename '%s' to '%s': %s", tmp, dir, strerror(errno));
        status = STATUS_IO;
    }
    return status;
}

/* A new directory "DIR.tmp-XXXXXX" beside dir (its parents made), with
 * the mode mkdir(2) would give it rather than mkdtemp's 0700, so the kit
 * can be shared as it is. */
static char *make_temp_beside(const char *dir, char *why, size_t why_size)
{
    char *parent = file_dirname(NULL, dir);
    int status = parent ? file_make_dirs(parent, why, why_size) : STATUS_NO_MEMORY;
    free(parent);
    size_t n = strlen(dir) + sizeof ".tmp-XXXXXX";
    char *tmp = status == 0 ? malloc(n) : NULL;
    if (tmp)
        snprintf(tmp, n, "%s.tmp-XXXXXX", dir);
    if (tmp && mkdtemp(tmp)) {
        unsigned mode = file_new_mode(); /* 0666 less the umask: add x where r is */
        chmod(tmp, (mode_t)(mode | (mode & 0444) >> 2));
        return tmp;
    }
    if (status == 0)
        snprintf(why, why_size, "cannot create a directory beside '%s': %s", dir,
                 tmp ? strerror(errno) : "out of memory");
    free(tmp);
    return NULL;
}

int kit_build(const char *dir_arg, const char *const *scenes, int count, const kit_opts *o, manifest *out,
              char *why, size_t why_size)
{
    memset(out, 0, sizeof *out);
    /* "k/" names k: a trailing slash must not put the temporary inside it. */
    char dir[4096];
    size_t n = strlen(dir_arg);
    while (n > 1 && dir_arg[n - 1] == '/')
        n--;
    if (n == 0 || n >= sizeof dir) {
        snprintf(why, why_size, "the kit directory's name is empty or too long");
        return STATUS_USAGE;
    }
    snprintf(dir, sizeof dir, "%.*s", (int)n, dir_arg);
    if (!manifest_supported(why, why_size))
        return STATUS_USAGE;
    snprintf(out->refray_version, sizeof out->refray_version, "%s", o->version ? o->version : "");
    out->scenes = calloc(count > 0 ? (size_t)count : 1, sizeof *out->scenes);
    if (!out->scenes) {
        snprintf(why, why_size, "out of memory");
        return STATUS_NO_MEMORY;
    }
    int status = name_scenes(scenes, count, out, why, why_size);
    if (status == 0 && !replaceable(dir, why, why_size))
        status = STATUS_USAGE;
    char *tmp = status == 0 ? make_temp_beside(dir, why, why_size) : NULL;
    if (status == 0 && !tmp)
        status = STATUS_IO;
    if (status == 0)
        status = fill_kit(tmp, scenes, count, o, out, why, why_size);
    if (status == 0)
        status = install(tmp, dir, why, why_size);
    if (tmp && status != 0) {
        char ignored[256];
        file_remove_tree(tmp, ignored, sizeof ignored);
    }
    free(tmp);
    if (status != 0)
        manifest_free(out);
    return status;
}
