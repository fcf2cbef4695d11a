/*
 * keywords.h - every reserved word of the scene language, in one table.
 *
 * The scanner classifies a word only through keyword_lookup, so this table
 * is the complete list of the language's words; the spec test walks it to
 * make sure spec/language.md documents each one.
 */
#ifndef REFRAY_KEYWORDS_H
#define REFRAY_KEYWORDS_H

#include <stddef.h>

typedef enum keyword_class {
    KWC_STATEMENT,   /* let for in include oracle material: structural words */
    KWC_BLOCK,       /* block names: reserved everywhere */
    KWC_PROPERTY,    /* property names: keywords only where a property may
                        start, names everywhere else (the scanner decides) */
    KWC_FUNCTION     /* built-in functions */
} keyword_class;

typedef enum keyword_id {
    /* structural */
    KW_LET, KW_FOR, KW_IN, KW_INCLUDE, KW_ORACLE, KW_MATERIAL,
    /* blocks */
    KW_IMAGE, KW_CAMERA, KW_AMBIENT, KW_POINT_LIGHT, KW_DISTANT_LIGHT, KW_DISTRIBUTED_LIGHT,
    KW_SPHERE, KW_PLANE, KW_TRIANGLE, KW_DISK, KW_BOX, KW_MESH,
    KW_CYLINDER, KW_CONE, KW_TORUS,
    /* properties */
    KW_WIDTH, KW_HEIGHT, KW_SAMPLES, KW_MAX_DEPTH, KW_BACKGROUND,
    KW_PERSPECTIVE, KW_ORTHOGRAPHIC, KW_EYE, KW_LOOK_AT, KW_UP, KW_FOV,
    KW_COLOR, KW_POSITION, KW_POWER, KW_D0, KW_FALLOFF, KW_DIRECTION, KW_RECTANGLE,
    KW_KD, KW_KS, KW_N, KW_T, KW_IOR,
    KW_CENTER, KW_RADIUS, KW_POINT, KW_NORMAL, KW_VERTICES, KW_FROM, KW_TO, KW_FILE,
    KW_TRANSLATE, KW_ROTATE, KW_SCALE,
    KW_OPEN, KW_RADII, KW_AXIS, KW_MAJOR, KW_MINOR,
    /* functions */
    KW_SQRT, KW_SIN, KW_COS, KW_TAN, KW_ASIN, KW_ACOS, KW_ATAN2, KW_POW, KW_ABS,
    KW_MIN, KW_MAX, KW_DOT, KW_CROSS, KW_NORMALIZE, KW_LENGTH,
    KW_EXP, KW_LOG, KW_FLOOR, KW_RADIANS, KW_DEGREES,
    KEYWORD_COUNT
} keyword_id;

typedef struct keyword_info {
    const char *name;
    keyword_class cls;
    int arity;       /* functions: argument count; properties: value count; else -1 */
} keyword_info;

/* The entry for id (0 <= id < KEYWORD_COUNT). */
const keyword_info *keyword_get(keyword_id id);

/* The id of the word text[0..len), or -1 when it is not reserved. */
int keyword_lookup(const char *text, size_t len);

const char *keyword_name(keyword_id id);

#endif
