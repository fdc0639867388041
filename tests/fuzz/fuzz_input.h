/*
 * fuzz_input.h - the fault-injecting input of the reader fuzz targets: the
 * bytes behind an in-memory cvm__reader and a failing allocator, both set up
 * from the input itself so that one corpus covers every fault:
 *   size % 3 == 0  the reader returns short reads (1 + size % 13 bytes);
 *   size % 7 == 0  the reader fails with -1 after size / 2 bytes;
 *   size % 5 == 0  allocation 1 + sum(bytes) % 16 fails.
 */
#ifndef CVM_FUZZ_INPUT_H
#define CVM_FUZZ_INPUT_H

#include <stdint.h>

#include "common/common_internal.h"
#include "io/io_internal.h"
#include "support/failing_alloc.h"

typedef struct fuzz_input {
    const uint8_t *p;
    size_t n, pos;
    size_t chunk;   /* at most this many bytes per read; 0 = no limit */
    size_t fail_at; /* return -1 once pos reaches this; (size_t)-1 = never */
    int failed;     /* 1 once -1 was returned */
} fuzz_input;

/* Set up *src and *r over data[0..size) and *ctx on the failing allocator *a
 * as listed above. */
void fuzz_input_setup(const uint8_t *data, size_t size, fuzz_input *src, cvm__reader *r,
                      cvm__ctx *ctx, cvmtest_alloc *a);

#endif
