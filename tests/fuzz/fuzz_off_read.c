/*
 * fuzz_off_read.c - libFuzzer target: any bytes, parsed as a 3D surface in
 * .off (Object File Format) through an in-memory cvm__reader with injected
 * short reads, read errors and allocation failures (fuzz_input.h), give a
 * status and never a crash or a leak; a surface read is consistent and, when
 * small, validated (fuzz_surf3_common.h).
 */
#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_off_read"
#include "fuzz_surf3_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FUZZ_SURF3_BODY(cvm__read_off(&ctx, &r, "fuzz.off", &s))
    return 0;
}
