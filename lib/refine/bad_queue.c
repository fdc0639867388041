/* bad_queue.c - the priority queue of poor triangles: a binary heap on (class, key, vertex ids). */
#include "refine_internal.h"

void cvm__bq_init(cvm__bad_queue *q, cvm__ctx *ctx)
{
    q->ctx = ctx;
    q->e = NULL;
    q->n = q->cap = 0;
}

void cvm__bq_destroy(cvm__bad_queue *q)
{
    cvm__free(q->ctx, q->e);
    q->e = NULL;
    q->n = q->cap = 0;
}

void cvm__bq_clear(cvm__bad_queue *q)
{
    q->n = 0;
}

/* Total order: class, key, then the rotated vertex ids (ties never depend on slots). */
static int bq_less(const cvm__bad_entry *a, const cvm__bad_entry *b)
{
    int k;
    if (a->cls != b->cls)
        return a->cls < b->cls;
    if (a->key != b->key)
        return a->key < b->key;
    for (k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k];
    return a->t < b->t;
}

/* Vertices of t rotated so the smallest id comes first (orientation kept). */
static void bq_rotated(const cvm__tri2 *T, int32_t t, int32_t *v)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int s = tv[0] < tv[1] ? (tv[0] < tv[2] ? 0 : 2) : (tv[1] < tv[2] ? 1 : 2);
    v[0] = tv[s];
    v[1] = tv[(s + 1) % 3];
    v[2] = tv[(s + 2) % 3];
}

/* Sift e[i] down in the heap e[0..n). */
static void bq_sift_down(cvm__bad_entry *e, size_t n, size_t i)
{
    cvm__bad_entry x = e[i];
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= n)
            break;
        if (c + 1 < n && bq_less(&e[c + 1], &e[c]))
            c++;
        if (!bq_less(&e[c], &x))
            break;
        e[i] = e[c];
        i = c;
    }
    e[i] = x;
}

/* Drop entries whose triangle is gone and rebuild the heap (Floyd). Entries are
 * only ever dropped when they could not be popped as valid now; the trigger
 * depends on counts alone, so runs stay reproducible. */
static void bq_compact(cvm__bad_queue *q, const cvm__tri2 *T)
{
    size_t i, n = 0;
    for (i = 0; i < q->n; i++)
        if (cvm__bq_valid(T, &q->e[i]))
            q->e[n++] = q->e[i];
    q->n = n;
    for (i = n / 2; i-- > 0;)
        bq_sift_down(q->e, n, i);
}

cvm_status cvm__bq_push(cvm__bad_queue *q, const cvm__tri2 *T, int32_t t, int32_t cls, double key)
{
    cvm__bad_entry x;
    size_t i;
    if (q->n >= q->cap && q->n > 1024 && q->n > 2 * (T->nt - T->n_dead))
        bq_compact(q, T); /* most entries are stale: keep the heap small and cached */
    if (q->n >= q->cap && cvm__grow(q->ctx, (void **)&q->e, &q->cap, q->n + 1, sizeof *q->e))
        return CVM_E_NOMEM;
    x.key = key;
    x.cls = cls;
    x.t = t;
    bq_rotated(T, t, x.v);
    i = q->n++;
    while (i > 0) {
        size_t parent = (i - 1) / 2;
        if (!bq_less(&x, &q->e[parent]))
            break;
        q->e[i] = q->e[parent];
        i = parent;
    }
    q->e[i] = x;
    return CVM_OK;
}

int cvm__bq_pop(cvm__bad_queue *q, cvm__bad_entry *out)
{
    cvm__bad_entry last;
    size_t i = 0;
    if (q->n == 0)
        return 0;
    *out = q->e[0];
    last = q->e[--q->n];
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= q->n)
            break;
        if (c + 1 < q->n && bq_less(&q->e[c + 1], &q->e[c]))
            c++;
        if (!bq_less(&q->e[c], &last))
            break;
        q->e[i] = q->e[c];
        i = c;
    }
    if (q->n > 0)
        q->e[i] = last;
    return 1;
}

int cvm__bq_valid(const cvm__tri2 *T, const cvm__bad_entry *e)
{
    int32_t v[3];
    if (e->t < 0 || (size_t)e->t >= T->nt || !cvm__tri2_in_domain(T, e->t))
        return 0;
    bq_rotated(T, e->t, v);
    return v[0] == e->v[0] && v[1] == e->v[1] && v[2] == e->v[2];
}
