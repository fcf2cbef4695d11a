/*
 * testjson.h - reading an exported JSON scene in the tests (builds with
 * JSON only): a scene's export parsed by jansson, and values by path.
 */
#ifndef REFRAY_TESTJSON_H
#define REFRAY_TESTJSON_H

#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "export/export_json.h"
#include "testlib.h"

/* The export of s (default options), parsed. */
static inline json_t *testjson_export(const scene_model *s)
{
    char *buf = NULL, err[256] = "";
    size_t len;
    json_error_t e;
    export_json_opts o;
    memset(&o, 0, sizeof o);
    FILE *fp = open_memstream(&buf, &len);
    ck_assert_ptr_nonnull(fp);
    int rc = export_json_write(s, &o, fp, err, sizeof err);
    fclose(fp);
    ck_assert_msg(rc == 0, "export failed (%d): %s", rc, err);
    json_t *doc = json_loadb(buf, len, 0, &e);
    ck_assert_msg(doc != NULL, "the export is not JSON: %d:%d: %s", e.line, e.column, e.text);
    free(buf);
    return doc;
}

/* The value at path ("lights/0/sampling/grid/rows": member names and
 * array indices); fails the test when it is not there. */
static inline json_t *testjson_at(json_t *v, const char *path)
{
    char key[64];
    for (const char *p = path; *p;) {
        size_t n = strcspn(p, "/");
        snprintf(key, sizeof key, "%.*s", (int)n, p);
        v = json_is_array(v) ? json_array_get(v, (size_t)atoi(key)) : json_object_get(v, key);
        ck_assert_msg(v != NULL, "no %s in the export", path);
        p += n + (p[n] == '/');
    }
    return v;
}

static inline double testjson_num(json_t *v, const char *path)
{
    json_t *x = testjson_at(v, path);
    ck_assert_msg(json_is_number(x), "%s is not a number", path);
    return json_number_value(x);
}

#endif
