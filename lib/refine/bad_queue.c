/* bad_queue.c - the queue of poor triangles: a bucket queue on (class, quantised key), FIFO inside a bucket. */
#include <string.h>

#include "refine_internal.h"

/*
 * Why buckets: refinement pushes and pops millions of entries, most of which
 * go stale before they are popped. A binary heap ordered by (class, key,
 * vertex ids) spent a third of a 1e6-triangle refinement in comparisons and
 * cache misses; the exact order inside a narrow key band buys nothing (the
 * theory of Delaunay refinement needs no order at all; the size-first rule and
 * worst-first shape are heuristics that a quantised key keeps). So, as in
 * Triangle, entries go into buckets by a coarse key and leave each bucket in
 * push order; the least non-empty bucket is found through a three-level
 * bitmap in three count-trailing-zeros steps.
 *
 * Bucket of (cls, key): cls * 2^16 + the top 16 bits of the key's IEEE-754
 * bit pattern made order-preserving (sign, 11 exponent bits, 4 significand
 * bits). A bucket is therefore [2^e (1 + j/16), 2^e (1 + (j+1)/16)) for
 * positive keys (mirrored for negative ones): relative width 1/32..1/16.
 */

#define BQ_KEY_BITS 16
#define BQ_PER_CLASS ((size_t)1 << BQ_KEY_BITS)
#define BQ_NBUCKET ((size_t)CVM__BQ_NCLASS * BQ_PER_CLASS)
#define BQ_L0 (BQ_NBUCKET / 64) /* words of the bucket bitmap */
#define BQ_L1 (BQ_L0 / 64)      /* words of the summary bitmap (<= 64 bits in l2) */

#if defined(__GNUC__) || defined(__clang__)
#  define bq_ctz(w) ((unsigned)__builtin_ctzll(w))
#else
static unsigned bq_ctz(uint64_t w)
{
    unsigned k = 0;
    while (!(w & 1)) {
        w >>= 1;
        k++;
    }
    return k;
}
#endif

void cvm__bq_init(cvm__bad_queue *q, cvm__ctx *ctx)
{
    memset(q, 0, sizeof *q);
    q->ctx = ctx;
    q->free = -1;
}

void cvm__bq_destroy(cvm__bad_queue *q)
{
    cvm__free(q->ctx, q->e);
    cvm__free(q->ctx, q->ht);
    cvm__free(q->ctx, q->bits);
    cvm__bq_init(q, q->ctx);
}

void cvm__bq_clear(cvm__bad_queue *q)
{
    if (q->bits)
        memset(q->bits, 0, (BQ_L0 + BQ_L1) * sizeof *q->bits);
    q->l2 = 0;
    q->n = q->used = 0;
    q->free = -1;
}

size_t cvm__bq_bucket(int32_t cls, double key)
{
    uint64_t u;
    key += 0.0; /* -0 -> +0 */
    memcpy(&u, &key, sizeof u);
    u = (u >> 63) ? ~u : u | ((uint64_t)1 << 63);
    if (cls < 0)
        cls = 0;
    if (cls >= CVM__BQ_NCLASS)
        cls = CVM__BQ_NCLASS - 1;
    return (size_t)cls * BQ_PER_CLASS + (size_t)(u >> (64 - BQ_KEY_BITS));
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

static void bq_mark(cvm__bad_queue *q, size_t b)
{
    q->bits[b >> 6] |= (uint64_t)1 << (b & 63);
    q->bits[BQ_L0 + (b >> 12)] |= (uint64_t)1 << ((b >> 6) & 63);
    q->l2 |= (uint64_t)1 << (b >> 12);
}

static void bq_unmark(cvm__bad_queue *q, size_t b)
{
    if ((q->bits[b >> 6] &= ~((uint64_t)1 << (b & 63))) != 0)
        return;
    if ((q->bits[BQ_L0 + (b >> 12)] &= ~((uint64_t)1 << ((b >> 6) & 63))) != 0)
        return;
    q->l2 &= ~((uint64_t)1 << (b >> 12));
}

/* Least non-empty bucket at or after b (b < BQ_NBUCKET); BQ_NBUCKET if none. */
static size_t bq_next_bucket(const cvm__bad_queue *q, size_t b)
{
    uint64_t w = q->bits[b >> 6] & (~(uint64_t)0 << (b & 63));
    size_t i0, i1;
    if (w)
        return (b & ~(size_t)63) + bq_ctz(w);
    i0 = (b >> 6) + 1;
    if (i0 >= BQ_L0)
        return BQ_NBUCKET;
    w = q->bits[BQ_L0 + (i0 >> 6)] & (~(uint64_t)0 << (i0 & 63));
    if (!w) {
        i1 = (i0 >> 6) + 1;
        if (i1 >= BQ_L1)
            return BQ_NBUCKET;
        w = q->l2 & (~(uint64_t)0 << i1);
        if (!w)
            return BQ_NBUCKET;
        i1 = bq_ctz(w);
        w = q->bits[BQ_L0 + i1];
        i0 = 64 * i1 + bq_ctz(w);
    } else {
        i0 = (i0 & ~(size_t)63) + bq_ctz(w);
    }
    return 64 * i0 + bq_ctz(q->bits[i0]);
}

/* Least non-empty bucket; the queue must not be empty. */
static size_t bq_min_bucket(const cvm__bad_queue *q)
{
    size_t i1 = bq_ctz(q->l2);
    size_t i0 = 64 * i1 + bq_ctz(q->bits[BQ_L0 + i1]);
    return 64 * i0 + bq_ctz(q->bits[i0]);
}

/* Drop entries whose triangle is gone, keeping the order of the rest. Only
 * entries that could never be popped as valid are dropped, and the trigger
 * depends on counts alone, so runs stay reproducible. */
static void bq_compact(cvm__bad_queue *q, const cvm__tri2 *T)
{
    size_t b = q->l2 ? bq_min_bucket(q) : BQ_NBUCKET;
    while (b < BQ_NBUCKET) {
        int32_t i = q->ht[2 * b], last = -1;
        while (i >= 0) {
            int32_t nx = q->e[i].next;
            if (cvm__bq_valid(T, &q->e[i].x)) {
                if (last < 0)
                    q->ht[2 * b] = i;
                else
                    q->e[last].next = i;
                last = i;
            } else {
                q->e[i].next = q->free;
                q->free = i;
                q->n--;
            }
            i = nx;
        }
        if (last < 0) {
            bq_unmark(q, b);
        } else {
            q->e[last].next = -1;
            q->ht[2 * b + 1] = last;
        }
        if (++b >= BQ_NBUCKET)
            break;
        b = bq_next_bucket(q, b);
    }
}

cvm_status cvm__bq_push(cvm__bad_queue *q, const cvm__tri2 *T, int32_t t, int32_t cls, double key)
{
    size_t b = cvm__bq_bucket(cls, key);
    int32_t i;
    if (!q->ht) {
        q->ht = cvm__malloc(q->ctx, 2 * BQ_NBUCKET * sizeof *q->ht);
        q->bits = cvm__calloc(q->ctx, BQ_L0 + BQ_L1, sizeof *q->bits);
        if (!q->ht || !q->bits) {
            cvm__free(q->ctx, q->ht);
            cvm__free(q->ctx, q->bits);
            q->ht = NULL;
            q->bits = NULL;
            return CVM_E_NOMEM;
        }
    }
    if (q->free < 0 && q->used >= q->cap && q->n > 1024 && q->n > 2 * (T->nt - T->n_dead))
        bq_compact(q, T); /* most entries are stale: keep the pool small and cached */
    if (q->free >= 0) {
        i = q->free;
        q->free = q->e[i].next;
    } else {
        if (q->used >= (size_t)INT32_MAX ||
            (q->used >= q->cap &&
             cvm__grow(q->ctx, (void **)&q->e, &q->cap, q->used + 1, sizeof *q->e)))
            return CVM_E_NOMEM;
        i = (int32_t)q->used++;
    }
    q->e[i].x.key = key;
    q->e[i].x.cls = (int32_t)(b >> BQ_KEY_BITS);
    q->e[i].x.t = t;
    bq_rotated(T, t, q->e[i].x.v);
    q->e[i].next = -1;
    if (q->bits[b >> 6] & ((uint64_t)1 << (b & 63))) {
        q->e[q->ht[2 * b + 1]].next = i;
    } else {
        q->ht[2 * b] = i;
        bq_mark(q, b);
    }
    q->ht[2 * b + 1] = i;
    q->n++;
    return CVM_OK;
}

int cvm__bq_pop(cvm__bad_queue *q, cvm__bad_entry *out)
{
    size_t b;
    int32_t i;
    if (q->n == 0)
        return 0;
    b = bq_min_bucket(q);
    i = q->ht[2 * b];
    *out = q->e[i].x;
    if (q->e[i].next < 0)
        bq_unmark(q, b);
    else
        q->ht[2 * b] = q->e[i].next;
    q->e[i].next = q->free;
    q->free = i;
    q->n--;
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
