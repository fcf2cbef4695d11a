/*
 * oracle_testlib.h - helpers shared by the oracle suites (check_oracle_*.c):
 * load a scene (failing the test with the reason when it does not load),
 * the view a scene asks for, and its family, which must accept it.
 * static inline, so a suite that uses only some of them gets no warning.
 */
#ifndef REFRAY_ORACLE_TESTLIB_H
#define REFRAY_ORACLE_TESTLIB_H

#include <string.h>
#include "testlib.h"
#include "oracle/oracle.h"
#include "io/scene_file.h"
#include "scene/scene.h"

static inline scene_model *load_text(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text("test.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d):\n%s", status, text);
    return s;
}

static inline scene_model *load_file(const char *path)
{
    int status;
    scene_model *s = scene_file_load(path, NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "%s did not load (status %d)", path, status);
    return s;
}

static inline oracle_view view_of(const scene_model *s)
{
    oracle_view v = {s, s->image.width, s->image.height, s->image.samples, s->image.max_depth};
    return v;
}

/* The scene's family, which must accept it. */
static inline const oracle_family *family_of(const scene_model *s)
{
    char why[256] = "";
    ck_assert_ptr_nonnull(s->oracle);
    const oracle_family *f = oracle_find(s->oracle);
    ck_assert_msg(f != NULL, "no family '%s'", s->oracle);
    oracle_view v = view_of(s);
    ck_assert_msg(f->accepts(&v, why, sizeof why), "%s refused: %s", s->oracle, why);
    return f;
}

static inline oracle_status radiance_at(const scene_model *s, double x, double y, rgb *out)
{
    oracle_view v = view_of(s);
    return family_of(s)->radiance(&v, x, y, out);
}

/* A scene the family must refuse, with exactly this reason. */
static inline void assert_refused(const char *family, const char *text, const char *reason)
{
    scene_model *s = load_text(text);
    const oracle_family *f = oracle_find(family);
    char why[256] = "";
    ck_assert_ptr_nonnull(f);
    oracle_view v = view_of(s);
    ck_assert_int_eq(f->accepts(&v, why, sizeof why), 0);
    ck_assert_str_eq(why, reason);
    scene_free(s);
}

#endif
