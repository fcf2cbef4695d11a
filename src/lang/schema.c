/*
 * schema.c - the property table of every block (see spec/language.md).
 */
#include <stdio.h>
#include <string.h>
#include "lang/schema.h"

#define XFORMS KW_TRANSLATE, KW_ROTATE, KW_SCALE

static const block_schema schemas[] = {
    {KW_IMAGE, 5, {KW_WIDTH, KW_HEIGHT, KW_SAMPLES, KW_MAX_DEPTH, KW_BACKGROUND}},
    {KW_CAMERA, 7, {KW_PERSPECTIVE, KW_ORTHOGRAPHIC, KW_EYE, KW_LOOK_AT, KW_UP, KW_FOV, KW_WIDTH}},
    {KW_AMBIENT, 1, {KW_COLOR}},
    {KW_POINT_LIGHT, 4, {KW_POSITION, KW_POWER, KW_D0, KW_FALLOFF}},
    {KW_DISTANT_LIGHT, 2, {KW_DIRECTION, KW_POWER}},
    {KW_DISTRIBUTED_LIGHT, 6, {KW_RECTANGLE, KW_DISK, KW_POWER, KW_SAMPLES, KW_D0, KW_FALLOFF}},
    {KW_MATERIAL, 5, {KW_KD, KW_KS, KW_N, KW_T, KW_IOR}},
    {KW_SPHERE, 6, {KW_CENTER, KW_RADIUS, KW_MATERIAL, XFORMS}},
    {KW_PLANE, 6, {KW_POINT, KW_NORMAL, KW_MATERIAL, XFORMS}},
    {KW_TRIANGLE, 5, {KW_VERTICES, KW_MATERIAL, XFORMS}},
    {KW_DISK, 7, {KW_CENTER, KW_NORMAL, KW_RADIUS, KW_MATERIAL, XFORMS}},
    {KW_BOX, 6, {KW_FROM, KW_TO, KW_MATERIAL, XFORMS}},
    {KW_MESH, 5, {KW_FILE, KW_MATERIAL, XFORMS}},
    {KW_CYLINDER, 8, {KW_FROM, KW_TO, KW_RADIUS, KW_OPEN, KW_MATERIAL, XFORMS}},
    {KW_CONE, 8, {KW_FROM, KW_TO, KW_RADII, KW_OPEN, KW_MATERIAL, XFORMS}},
    {KW_TORUS, 8, {KW_CENTER, KW_AXIS, KW_MAJOR, KW_MINOR, KW_MATERIAL, XFORMS}},
};

const block_schema *schema_of(keyword_id block)
{
    for (size_t i = 0; i < sizeof schemas / sizeof schemas[0]; i++)
        if (schemas[i].block == block)
            return &schemas[i];
    return NULL;
}

int schema_has(const block_schema *schema, keyword_id prop)
{
    for (int i = 0; i < schema->prop_count; i++)
        if (schema->props[i] == prop)
            return 1;
    return 0;
}

void schema_list(const block_schema *schema, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < schema->prop_count && used < size; i++) {
        int n = snprintf(buf + used, size - used, "%s%s", i ? ", " : "", keyword_name(schema->props[i]));
        if (n < 0)
            break;
        used += (size_t)n;
    }
}
