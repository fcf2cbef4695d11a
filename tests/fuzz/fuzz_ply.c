/*
 * fuzz_ply.c - libFuzzer harness over the PLY reader (src/lang/ply.c) and
 * what follows it (fuzz_mesh.h).  `make fuzz FUZZ_TARGETS=ply`.
 */
#include "fuzz_mesh.h"
#include "lang/ply.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_mesh(data, size, ply_parse);
}
