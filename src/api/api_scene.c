/*
 * api_scene.c - the public API's scenes: loading from memory and from
 * files, the callbacks between the caller and the loader, the summary
 * (refray.h).
 */
#include <string.h>
#include "api/convert.h"
#include "io/c_locale.h"
#include "io/diag_print.h"
#include "io/scene_file.h"

void rf_load_options_init(rf_load_options *o)
{
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    scene_limits l = scene_default_limits();
    o->limits = api_limits_out(&l);
    o->warnings = 1;
}

/* One load: the caller's options, and its locale for its callbacks
 * ([EMBED-LOCALE-1]: the loader runs in the C locale, the diagnostic and
 * resolver callbacks in the caller's). */
typedef struct load_call {
    const rf_load_options *o;
    c_locale_scope locale;
} load_call;

/* A diagnostic record as the caller's callback sees it. */
static void to_caller(void *user, const diag_record *r)
{
    const load_call *call = user;
    const rf_load_options *o = call->o;
    rf_diagnostic d;
    d.severity = r->level == DIAG_ERROR ? RF_SEVERITY_ERROR : r->level == DIAG_WARNING ? RF_SEVERITY_WARNING
                                                                                       : RF_SEVERITY_NOTE;
    d.file = r->path;
    d.line = r->line;
    d.column = r->column;
    d.message = r->message;
    d.source_line = r->source_line;
    d.source_line_length = r->source_line_length;
    d.span_length = r->span_length;
    c_locale_to_caller(&call->locale);
    o->diagnostic(o->diagnostic_user, &d);
    c_locale_from_caller(&call->locale);
}

void rf_diagnostic_print(void *stream, const rf_diagnostic *d)
{
    diag_record r;
    if (!stream || !d)
        return;
    r.level = d->severity == RF_SEVERITY_ERROR ? DIAG_ERROR : d->severity == RF_SEVERITY_WARNING ? DIAG_WARNING
                                                                                                 : DIAG_NOTE;
    r.path = d->file;
    r.line = d->line;
    r.column = d->column;
    r.message = d->message;
    r.source_line = d->source_line;
    r.source_line_length = d->source_line_length;
    r.span_length = d->span_length;
    diag_print(stream, &r);
}

/* The caller's resolver behind the loader's. */
static int fetch(void *user, const char *from, const char *name, scene_source *out, char *why, size_t why_size)
{
    const load_call *call = user;
    const rf_resolver *r = &call->o->resolver;
    rf_source src;
    memset(&src, 0, sizeof src);
    c_locale_to_caller(&call->locale);
    rf_status status = r->fetch(r->user, from, name, &src, why, why_size);
    if (status == RF_OK && !src.text && src.size > 0 && r->release)
        r->release(r->user, &src);
    c_locale_from_caller(&call->locale);
    if (status == RF_OK && !src.text && src.size > 0) {
        /* Text that is not there: refused here, before it is read. */
        snprintf(why, why_size, "cannot read '%s': the resolver gave %zu bytes of no text", name, src.size);
        return STATUS_DATA;
    }
    if (status != RF_OK && why_size > 0 && why[0] == '\0')
        snprintf(why, why_size, "cannot read '%s': %s", name, rf_status_string(status));
    out->path = src.path;
    out->identity = src.identity;
    out->text = src.text;
    out->len = src.size;
    out->known = 0; /* a host's resolver always gives the text */
    return (int)status;
}

static void release(void *user, scene_source *out)
{
    const load_call *call = user;
    const rf_resolver *r = &call->o->resolver;
    rf_source src = {out->path, out->identity, out->text, out->len};
    if (!r->release)
        return;
    c_locale_to_caller(&call->locale);
    r->release(r->user, &src);
    c_locale_from_caller(&call->locale);
}

/* The loader's options for the caller's call->o (NULL: the defaults). */
static void load_opts(load_call *call, scene_load_opts *out)
{
    const rf_load_options *o = call->o;
    scene_load_opts_init(out);
    if (!o)
        return;
    out->limits = api_limits_in(&o->limits);
    out->warnings = o->warnings;
    if (o->diagnostic) {
        out->sink = to_caller;
        out->sink_user = call;
    }
    if (o->resolver.fetch) {
        out->resolver.fetch = fetch;
        out->resolver.release = release;
        out->resolver.user = call;
    }
    out->mem = api_mem(o->allocator);
    out->cancel = o->cancel;
    out->cancel_user = o->cancel_user;
}

/* The body of both loads: root's text when root is given, else the file at
 * path.  A NULL out, or arguments the caller found bad, is RF_ERR_USAGE
 * (with *out NULL when there is an out). */
static rf_status load(const scene_source *root, const char *path, int bad, const rf_load_options *o,
                      rf_scene **out)
{
    scene_load_opts lo;
    load_call call;
    int status;
    if (!out)
        return RF_ERR_USAGE;
    *out = NULL;
    if (bad)
        return RF_ERR_USAGE;
    call.o = o;
    if (c_locale_enter(&call.locale) != 0)
        return RF_ERR_NO_MEMORY;
    load_opts(&call, &lo);
    /* [REL-READ-1] The library reads anywhere unless the host confines it. */
    if (root)
        *out = (rf_scene *)(void *)scene_file_load_source(root, &lo, &status);
    else if (o && o->read_confined)
        *out = (rf_scene *)(void *)scene_file_load_confined(path, &lo, o->read_dirs, &status);
    else
        *out = (rf_scene *)(void *)scene_file_load_anywhere(path, &lo, &status);
    c_locale_leave(&call.locale);
    return api_status(status);
}

rf_status rf_scene_load_memory(const char *name, const char *text, size_t size, const rf_load_options *o,
                               rf_scene **out)
{
    scene_source root = {name, NULL, text, size, 0};
    return load(&root, NULL, !name || (!text && size > 0), o, out);
}

rf_status rf_scene_load_file(const char *path, const rf_load_options *o, rf_scene **out)
{
    return load(NULL, path, !path, o, out);
}

void rf_scene_free(rf_scene *scene)
{
    scene_free((scene_model *)(void *)scene);
}

static unsigned features(const scene_features *f)
{
    return (f->shadows ? RF_FEATURE_SHADOWS : 0u) | (f->specular ? RF_FEATURE_SPECULAR : 0u) |
           (f->reflection ? RF_FEATURE_REFLECTION : 0u) | (f->refraction ? RF_FEATURE_REFRACTION : 0u) |
           (f->sampled_lights ? RF_FEATURE_SAMPLED_LIGHTS : 0u) | (f->meshes ? RF_FEATURE_MESHES : 0u);
}

/* rf_scene_info counts every kind of primitive: a new kind needs a field. */
typedef char every_kind[PRIM_KINDS == 9 ? 1 : -1];

void rf_scene_get_info(const rf_scene *scene, rf_scene_info *info)
{
    const scene_model *s = api_scene(scene);
    if (!info)
        return;
    int *kinds[PRIM_KINDS] = {&info->spheres, &info->planes,    &info->triangles, &info->disks, &info->boxes,
                              &info->cylinders, &info->cones, &info->tori,      &info->meshes};
    long triangles;
    memset(info, 0, sizeof *info);
    if (!s)
        return;
    info->width = s->image.width;
    info->height = s->image.height;
    info->samples = s->image.samples;
    info->max_depth = s->image.max_depth;
    info->primitives = s->prim_count;
    for (int i = 0; i < s->prim_count; i++)
        (*kinds[s->prims[i].kind])++;
    info->mesh_bytes = scene_mesh_bytes(s, &triangles);
    info->mesh_triangles = (int)triangles;
    info->lights = s->light_count;
    info->materials = s->material_count;
    info->features = features(&s->features);
    info->oracle = s->oracle;
}

rf_status rf_scene_get_mesh_info(const rf_scene *scene, int index, rf_mesh_info *info)
{
    const scene_model *s = api_scene(scene);
    if (!info)
        return RF_ERR_USAGE;
    memset(info, 0, sizeof *info);
    if (!s || index < 0 || index >= s->mesh_count)
        return RF_ERR_USAGE;
    const scene_mesh *m = &s->meshes[index];
    const scene_mesh_report *r = &m->report;
    info->path = m->path;
    info->triangles = m->geom.tri_count;
    info->faces = r->faces;
    info->dropped = r->dropped;
    info->nonplanar = r->nonplanar;
    info->fanned = r->fanned;
    info->closed = m->geom.closed;
    info->oriented = r->oriented;
    info->pieces = r->components;
    info->open_edges = r->open_edges;
    info->crowded_edges = r->crowded_edges;
    return RF_OK;
}
