/* fuzz_input.c - the fault-injecting reader and allocator of the reader fuzz targets (see fuzz_input.h). */
#include <string.h>

#include "fuzz_input.h"

static long fuzz_read(void *self, char *buf, size_t len)
{
    fuzz_input *s = (fuzz_input *)self;
    size_t k;
    if (s->pos >= s->fail_at) {
        s->failed = 1;
        return -1;
    }
    k = s->n - s->pos;
    if (k > len)
        k = len;
    if (s->chunk && k > s->chunk)
        k = s->chunk;
    if (s->fail_at != (size_t)-1 && s->pos + k > s->fail_at)
        k = s->fail_at - s->pos;
    if (k)
        memcpy(buf, s->p + s->pos, k);
    s->pos += k;
    return (long)k;
}

void fuzz_input_setup(const uint8_t *data, size_t size, fuzz_input *src, cvm__reader *r,
                      cvm__ctx *ctx, cvmtest_alloc *a)
{
    size_t i, sum = 0;
    for (i = 0; i < size; i++)
        sum += data[i];
    cvmtest_alloc_init(a, size % 5 == 0 ? (long)(1 + sum % 16) : 0, 0);
    cvm__ctx_init_default(ctx);
    ctx->alloc_fn = cvmtest_malloc;
    ctx->realloc_fn = cvmtest_realloc;
    ctx->free_fn = cvmtest_free;
    ctx->payload = a;
    src->p = data;
    src->n = size;
    src->pos = 0;
    src->chunk = size % 3 == 0 ? 1 + size % 13 : 0;
    src->fail_at = size % 7 == 0 ? size / 2 : (size_t)-1;
    src->failed = 0;
    r->read = fuzz_read;
    r->self = src;
}
