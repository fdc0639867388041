/* failing_reader.c - memory reader with short reads and a read error after k bytes. */
#include "failing_reader.h"

static long mem_read(void *self, char *buf, size_t len)
{
    cvmtest_reader *tr = (cvmtest_reader *)self;
    size_t n = tr->len - tr->pos, i;
    tr->n_reads++;
    if (tr->fail_after >= 0 && tr->pos >= (size_t)tr->fail_after)
        return -1;
    if (tr->fail_after >= 0 && n > (size_t)tr->fail_after - tr->pos)
        n = (size_t)tr->fail_after - tr->pos;
    if (tr->chunk && n > tr->chunk)
        n = tr->chunk;
    if (n > len)
        n = len;
    for (i = 0; i < n; i++)
        buf[i] = tr->data[tr->pos + i];
    tr->pos += n;
    return (long)n;
}

void cvmtest_reader_init(cvmtest_reader *tr, cvm__reader *r, const char *data, size_t len,
                         size_t chunk, long fail_after)
{
    tr->data = data;
    tr->len = len;
    tr->pos = 0;
    tr->chunk = chunk;
    tr->fail_after = fail_after;
    tr->n_reads = 0;
    r->read = mem_read;
    r->self = tr;
}
