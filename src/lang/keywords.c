/*
 * keywords.c - the table behind keywords.h.  Order matches keyword_id.
 * Property arities are the number of values a property takes; the parser
 * reads any number and the lowering pass holds them to these.
 */
#include <string.h>
#include "lang/keywords.h"

static const keyword_info table[KEYWORD_COUNT] = {
    {"let", KWC_STATEMENT, -1},
    {"for", KWC_STATEMENT, -1},
    {"in", KWC_STATEMENT, -1},
    {"include", KWC_STATEMENT, -1},
    {"oracle", KWC_STATEMENT, -1},
    {"material", KWC_STATEMENT, 1},

    {"image", KWC_BLOCK, -1},
    {"camera", KWC_BLOCK, -1},
    {"ambient", KWC_BLOCK, -1},
    {"point_light", KWC_BLOCK, -1},
    {"distant_light", KWC_BLOCK, -1},
    {"distributed_light", KWC_BLOCK, -1},
    {"sphere", KWC_BLOCK, -1},
    {"plane", KWC_BLOCK, -1},
    {"triangle", KWC_BLOCK, -1},
    {"disk", KWC_BLOCK, 3},
    {"box", KWC_BLOCK, -1},
    {"mesh", KWC_BLOCK, -1},
    {"cylinder", KWC_BLOCK, -1},
    {"cone", KWC_BLOCK, -1},
    {"torus", KWC_BLOCK, -1},

    {"width", KWC_PROPERTY, 1},
    {"height", KWC_PROPERTY, 1},
    {"samples", KWC_PROPERTY, 1},
    {"max_depth", KWC_PROPERTY, 1},
    {"background", KWC_PROPERTY, 1},
    {"perspective", KWC_PROPERTY, 0},
    {"orthographic", KWC_PROPERTY, 0},
    {"eye", KWC_PROPERTY, 1},
    {"look_at", KWC_PROPERTY, 1},
    {"up", KWC_PROPERTY, 1},
    {"fov", KWC_PROPERTY, 1},
    {"color", KWC_PROPERTY, 1},
    {"position", KWC_PROPERTY, 1},
    {"power", KWC_PROPERTY, 1},
    {"d0", KWC_PROPERTY, 1},
    {"falloff", KWC_PROPERTY, 1},
    {"direction", KWC_PROPERTY, 1},
    {"rectangle", KWC_PROPERTY, 3},
    {"Kd", KWC_PROPERTY, 1},
    {"Ks", KWC_PROPERTY, 1},
    {"n", KWC_PROPERTY, 1},
    {"t", KWC_PROPERTY, 1},
    {"ior", KWC_PROPERTY, 1},
    {"center", KWC_PROPERTY, 1},
    {"radius", KWC_PROPERTY, 1},
    {"point", KWC_PROPERTY, 1},
    {"normal", KWC_PROPERTY, 1},
    {"vertices", KWC_PROPERTY, 3},
    {"from", KWC_PROPERTY, 1},
    {"to", KWC_PROPERTY, 1},
    {"file", KWC_PROPERTY, 1},
    {"translate", KWC_PROPERTY, 1},
    {"rotate", KWC_PROPERTY, 1},
    {"scale", KWC_PROPERTY, 1},
    {"open", KWC_PROPERTY, 0},
    {"radii", KWC_PROPERTY, 2},
    {"axis", KWC_PROPERTY, 1},
    {"major", KWC_PROPERTY, 1},
    {"minor", KWC_PROPERTY, 1},

    {"sqrt", KWC_FUNCTION, 1},
    {"sin", KWC_FUNCTION, 1},
    {"cos", KWC_FUNCTION, 1},
    {"tan", KWC_FUNCTION, 1},
    {"asin", KWC_FUNCTION, 1},
    {"acos", KWC_FUNCTION, 1},
    {"atan2", KWC_FUNCTION, 2},
    {"pow", KWC_FUNCTION, 2},
    {"abs", KWC_FUNCTION, 1},
    {"min", KWC_FUNCTION, 2},
    {"max", KWC_FUNCTION, 2},
    {"dot", KWC_FUNCTION, 2},
    {"cross", KWC_FUNCTION, 2},
    {"normalize", KWC_FUNCTION, 1},
    {"length", KWC_FUNCTION, 1},
    {"exp", KWC_FUNCTION, 1},
    {"log", KWC_FUNCTION, 1},
    {"floor", KWC_FUNCTION, 1},
    {"radians", KWC_FUNCTION, 1},
    {"degrees", KWC_FUNCTION, 1},
};

const keyword_info *keyword_get(keyword_id id)
{
    return &table[id];
}

const char *keyword_name(keyword_id id)
{
    return table[id].name;
}

/* A linear scan: about 80 words, called once per word of a scene file. */
int keyword_lookup(const char *text, size_t len)
{
    for (int i = 0; i < KEYWORD_COUNT; i++)
        if (strlen(table[i].name) == len && memcmp(table[i].name, text, len) == 0)
            return i;
    return -1;
}
