/*
 * fuzz_scene.c - libFuzzer harness over the whole front end: scan, parse,
 * evaluate, lower, validate, and print every diagnostic (the caret printer
 * is part of what hostile input reaches).  `make fuzz FUZZ_SECONDS=N`.
 *
 * An input that starts with '{' is read as a JSON scene (spec/json.md), so
 * the JSON front end is fuzzed by the same harness.
 *
 * Limits are lowered so that a legal but huge scene (a loop of a million
 * spheres) costs milliseconds, not seconds: the fuzzer looks for crashes,
 * leaks and undefined behaviour, and a slow input would only hide them.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "io/scene_file.h"
#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    scene_limits limits = scene_default_limits();
    limits.max_loop_iterations = 2000;
    limits.max_primitives = 2000;
    limits.max_mesh_triangles = 2000;
    limits.max_errors = 8;
    limits.max_include_depth = 4;
    limits.max_file_bytes = 1 << 16;
    FILE *sink = fopen("/dev/null", "w");
    int status;
    const char *path = size > 0 && data[0] == '{' ? "fuzz.json" : "fuzz.scene";
    scene_model *s = scene_file_load_text(path, (const char *)data, size, &limits, sink, 1, &status);
    if (s && status != STATUS_OK)
        __builtin_trap(); /* a scene comes back only when it is valid */
    if (!s && status == STATUS_OK)
        __builtin_trap();
    scene_free(s);
    if (sink)
        fclose(sink);
    return 0;
}
