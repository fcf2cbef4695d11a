/*
 * export_json_build.c - see export_json_build.h.  JSON=1 builds only.
 */
#include <stdio.h>
#include "export/export_json_build.h"

void export_json_set(export_json_build *b, json_t *obj, const char *key, json_t *v)
{
    if (json_object_set_new(obj, key, v) != 0)
        b->failed = 1;
}

void export_json_append(export_json_build *b, json_t *array, json_t *v)
{
    if (json_array_append_new(array, v) != 0)
        b->failed = 1;
}

json_t *export_json_vec3(vec3 v)
{
    return json_pack("[fff]", (double)v.x, (double)v.y, (double)v.z);
}

json_t *export_json_hex(unsigned long long x)
{
    char buf[24];
    snprintf(buf, sizeof buf, "0x%llx", x);
    return json_string(buf);
}
