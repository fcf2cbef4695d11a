/*
 * fuzz_obj.c - libFuzzer harness over the OBJ reader (src/lang/obj.c) and
 * what follows it (fuzz_mesh.h).  `make fuzz FUZZ_TARGETS=obj`.
 */
#include "fuzz_mesh.h"
#include "lang/obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_mesh(data, size, obj_parse);
}
