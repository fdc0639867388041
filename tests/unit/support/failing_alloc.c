/* failing_alloc.c - counting allocator that fails the k-th allocation and tracks live blocks. */
#include <stdlib.h>
#include <string.h>

#include "failing_alloc.h"

/* Each block carries its size in a header aligned for any object. */
typedef union header {
    size_t size;
    double d;
    long double ld;
    void *p;
    long long ll;
} header;

void cvmtest_alloc_init(cvmtest_alloc *a, long fail_at, int persistent)
{
    memset(a, 0, sizeof *a);
    a->fail_at = fail_at;
    a->persistent = persistent;
}

void cvmtest_alloc_arm(cvmtest_alloc *a, long fail_at, int persistent)
{
    a->fail_at = fail_at;
    a->persistent = persistent;
    a->n_calls = 0;
    a->n_failed = 0;
}

/* Count one allocation; 1 if it must fail. */
static int must_fail(cvmtest_alloc *a)
{
    a->n_calls++;
    if (a->fail_at > 0 &&
        (a->n_calls == a->fail_at || (a->persistent && a->n_calls > a->fail_at))) {
        a->n_failed++;
        return 1;
    }
    return 0;
}

static void account(cvmtest_alloc *a, size_t add, size_t sub)
{
    a->live_bytes = a->live_bytes + add - sub;
    if (a->live_bytes > a->peak_bytes)
        a->peak_bytes = a->live_bytes;
}

void *cvmtest_malloc(void *payload, size_t size)
{
    cvmtest_alloc *a = (cvmtest_alloc *)payload;
    header *h;
    if (must_fail(a) || size > (size_t)-1 - sizeof(header))
        return NULL;
    h = (header *)malloc(sizeof(header) + size);
    if (!h)
        return NULL;
    h->size = size;
    a->live_blocks++;
    account(a, size, 0);
    return h + 1;
}

void *cvmtest_realloc(void *payload, void *ptr, size_t size)
{
    cvmtest_alloc *a = (cvmtest_alloc *)payload;
    header *h, *nh;
    size_t old;
    if (!ptr)
        return cvmtest_malloc(payload, size);
    if (must_fail(a) || size > (size_t)-1 - sizeof(header))
        return NULL;
    h = (header *)ptr - 1;
    old = h->size;
    nh = (header *)realloc(h, sizeof(header) + size);
    if (!nh)
        return NULL;
    nh->size = size;
    account(a, size, old);
    return nh + 1;
}

void cvmtest_free(void *payload, void *ptr)
{
    cvmtest_alloc *a = (cvmtest_alloc *)payload;
    header *h;
    if (!ptr)
        return;
    h = (header *)ptr - 1;
    a->live_blocks--;
    account(a, 0, h->size);
    free(h);
}

cvm_status cvmtest_mesh_create(cvm_mesh **out, cvmtest_alloc *a)
{
    return cvm_mesh_create_with_allocator(out, cvmtest_malloc, cvmtest_realloc, cvmtest_free, a);
}
