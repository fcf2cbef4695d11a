/*
 * export_json.c - see export_json.h: the entry points, in every build; a
 * build without jansson (JSON=0) refuses with STATUS_USAGE.
 */
#include <stdio.h>
#include "export/export_json.h"
#include "export/export_json_impl.h"
#include "io/filewrite.h"

#ifdef REFRAY_HAVE_JSON

int export_json_write(const scene_model *s, const export_json_opts *o, FILE *fp, char *err, size_t errlen)
{
    int status;
    json_t *doc = export_json_document(s, o, &status, err, errlen);
    if (!doc)
        return status;
    status = export_json_print(fp, doc);
    json_decref(doc);
    return status;
}

#else

int export_json_write(const scene_model *s, const export_json_opts *o, FILE *fp, char *err, size_t errlen)
{
    (void)s;
    (void)o;
    (void)fp;
    snprintf(err, errlen, "this refray was built without JSON support (JSON=0)");
    return STATUS_USAGE;
}

#endif

typedef struct json_job {
    const scene_model *s;
    const export_json_opts *o;
    char *err;
    size_t errlen;
} json_job;

static int fill_json(FILE *fp, void *ctx)
{
    json_job *job = ctx;
    return export_json_write(job->s, job->o, fp, job->err, job->errlen);
}

int export_json_file(const scene_model *s, const export_json_opts *o, const char *path, char *err, size_t errlen)
{
    char why[600];
    json_job job = {s, o, err, errlen};
    if (errlen)
        err[0] = '\0';
    int status = file_write_atomic(path, fill_json, &job, why, sizeof why);
    if (status != STATUS_OK && errlen && !err[0])
        snprintf(err, errlen, "%s", why);
    return status;
}
