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
 * bitmap in three count-trailing-zeros steps. A bucket is a chain of
 * blocks of CVM__BQ_BLOCK entries, so a bucket is read in memory order and
 * cvm__bq_pop_valid can fetch the triangles of the next entries early: two
 * of three entries are stale by the time they are popped, and each would
 * otherwise cost a cache miss or two.
 *
 * Bucket of (cls, key): cls * 2^16 + the top 16 bits of the key's IEEE-754
 * bit pattern made order-preserving (sign, 11 exponent bits, 4 significand
 * bits). A bucket is therefore [2^e (1 + j/16), 2^e (1 + (j+1)/16)) for
 * positive keys (mirrored for negative ones): relative width 1/31..1/16.
 * The per-bucket table (16 bytes a bucket, 2 MB) is allocated at the first
 * push and only the pages of buckets in use are ever touched.
 */

#define BQ_KEY_BITS 16
#define BQ_PER_CLASS ((size_t)1 << BQ_KEY_BITS)
#define BQ_NBUCKET ((size_t)CVM__BQ_NCLASS * BQ_PER_CLASS)
#define BQ_L0 (BQ_NBUCKET / 64) /* words of the bucket bitmap */
#define BQ_L1 (BQ_L0 / 64)      /* words of the summary bitmap (<= 64 bits in l2) */

#if defined(__GNUC__) || defined(__clang__)
#  define BQ_CTZ(w) ((unsigned)__builtin_ctzll(w))
#  define bq_prefetch(p) __builtin_prefetch(p)
#else
#  define BQ_CTZ(w) bq_ctz_portable(w)
#  define bq_prefetch(p) ((void)(p))
/* Index of the lowest set bit of w (not 0). */
static unsigned bq_ctz_portable(uint64_t w)
{
    unsigned k = 0;
    while (!(w & 1)) {
        w >>= 1;
        k++;
    }
    return k;
}
#endif

/* Bucket b's chain: head block, read position, tail block, write position. */
#define BK_HEAD(q, b) ((q)->bk[4 * (b)])
#define BK_READ(q, b) ((q)->bk[4 * (b) + 1])
#define BK_TAIL(q, b) ((q)->bk[4 * (b) + 2])
#define BK_WRITE(q, b) ((q)->bk[4 * (b) + 3])

typedef struct bq_item {
    double key;
    int32_t t;
    int32_t v[3];
} bq_item;

struct cvm__bq_block {
    int32_t next; /* next block of the bucket, or of the free list */
    bq_item it[CVM__BQ_BLOCK];
};

void cvm__bq_init(cvm__bad_queue *q, cvm__ctx *ctx)
{
    memset(q, 0, sizeof *q);
    q->ctx = ctx;
    q->free = -1;
}

void cvm__bq_destroy(cvm__bad_queue *q)
{
    cvm__free(q->ctx, q->blk);
    cvm__free(q->ctx, q->bk);
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

static int bq_nonempty(const cvm__bad_queue *q, size_t b)
{
    return (q->bits[b >> 6] >> (b & 63)) & 1;
}

/* Least non-empty bucket at or after b (b < BQ_NBUCKET); BQ_NBUCKET if none. */
static size_t bq_next_bucket(const cvm__bad_queue *q, size_t b)
{
    uint64_t w = q->bits[b >> 6] & (~(uint64_t)0 << (b & 63));
    size_t i0, i1;
    if (w)
        return (b & ~(size_t)63) + BQ_CTZ(w);
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
        i1 = BQ_CTZ(w);
        w = q->bits[BQ_L0 + i1];
        i0 = 64 * i1 + BQ_CTZ(w);
    } else {
        i0 = (i0 & ~(size_t)63) + BQ_CTZ(w);
    }
    return 64 * i0 + BQ_CTZ(q->bits[i0]);
}

/* Least non-empty bucket; the queue must not be empty. */
static size_t bq_min_bucket(const cvm__bad_queue *q)
{
    size_t i1 = BQ_CTZ(q->l2);
    size_t i0 = 64 * i1 + BQ_CTZ(q->bits[BQ_L0 + i1]);
    return 64 * i0 + BQ_CTZ(q->bits[i0]);
}

/* A block from the free list or the pool (which must have room). */
static int32_t bq_take_block(cvm__bad_queue *q)
{
    int32_t k = q->free;
    if (k >= 0)
        q->free = q->blk[k].next;
    else
        k = (int32_t)q->used++;
    q->blk[k].next = -1;
    return k;
}

static void bq_give_block(cvm__bad_queue *q, int32_t k)
{
    q->blk[k].next = q->free;
    q->free = k;
}

/* Drop entries whose triangle is gone, keeping the order of the rest. Only
 * entries that could never be popped as valid are dropped, and the trigger
 * depends on counts alone, so runs stay reproducible. */
static void bq_compact(cvm__bad_queue *q, const cvm__tri2 *T)
{
    size_t b = q->l2 ? bq_min_bucket(q) : BQ_NBUCKET;
    while (b < BQ_NBUCKET) {
        int32_t tb = BK_TAIL(q, b), tw = BK_WRITE(q, b);
        int32_t rb = BK_HEAD(q, b), rp = BK_READ(q, b), wb = rb, wp = rp, k;
        while (rb != tb || rp != tw) {
            const bq_item *it = &q->blk[rb].it[rp];
            cvm__bad_entry e;
            e.t = it->t;
            e.v[0] = it->v[0];
            e.v[1] = it->v[1];
            e.v[2] = it->v[2];
            if (cvm__bq_valid(T, &e)) {
                if (wp == CVM__BQ_BLOCK) {
                    wb = q->blk[wb].next;
                    wp = 0;
                }
                q->blk[wb].it[wp++] = *it;
            } else {
                q->n--;
            }
            if (++rp == CVM__BQ_BLOCK && rb != tb) {
                rb = q->blk[rb].next;
                rp = 0;
            }
        }
        if (wb == BK_HEAD(q, b) && wp == BK_READ(q, b)) {
            wb = -1; /* nothing left: the whole chain goes */
            k = BK_HEAD(q, b);
            bq_unmark(q, b);
        } else {
            k = q->blk[wb].next;
            q->blk[wb].next = -1;
            BK_TAIL(q, b) = wb;
            BK_WRITE(q, b) = wp;
        }
        while (wb != tb) {
            int32_t nx = q->blk[k].next;
            bq_give_block(q, k);
            if (k == tb)
                break;
            k = nx;
        }
        if (++b >= BQ_NBUCKET)
            break;
        b = bq_next_bucket(q, b);
    }
}

cvm_status cvm__bq_push(cvm__bad_queue *q, const cvm__tri2 *T, int32_t t, int32_t cls, double key)
{
    size_t b = cvm__bq_bucket(cls, key);
    bq_item *it;
    if (!q->bk) {
        q->bk = cvm__malloc(q->ctx, 4 * BQ_NBUCKET * sizeof *q->bk);
        q->bits = cvm__calloc(q->ctx, BQ_L0 + BQ_L1, sizeof *q->bits);
        if (!q->bk || !q->bits) {
            cvm__free(q->ctx, q->bk);
            cvm__free(q->ctx, q->bits);
            q->bk = NULL;
            q->bits = NULL;
            return CVM_E_NOMEM;
        }
    }
    /* most entries stale and the pool full: drop them (keeps the pool small
     * and cached) before taking a new block */
    if ((!bq_nonempty(q, b) || BK_WRITE(q, b) == CVM__BQ_BLOCK) && q->free < 0 &&
        q->used >= q->cap && q->n > 1024 && q->n > 2 * (T->nt - T->n_dead))
        bq_compact(q, T);
    if (!bq_nonempty(q, b) || BK_WRITE(q, b) == CVM__BQ_BLOCK) {
        int32_t k;
        if (q->free < 0 && q->used >= q->cap &&
            (q->used >= (size_t)INT32_MAX ||
             cvm__grow(q->ctx, (void **)&q->blk, &q->cap, q->used + 1, sizeof *q->blk)))
            return CVM_E_NOMEM;
        k = bq_take_block(q);
        if (!bq_nonempty(q, b)) {
            BK_HEAD(q, b) = k;
            BK_READ(q, b) = 0;
            bq_mark(q, b);
        } else {
            q->blk[BK_TAIL(q, b)].next = k;
        }
        BK_TAIL(q, b) = k;
        BK_WRITE(q, b) = 0;
    }
    it = &q->blk[BK_TAIL(q, b)].it[BK_WRITE(q, b)++];
    it->key = key;
    it->t = t;
    bq_rotated(T, t, it->v);
    q->n++;
    return CVM_OK;
}

/* Pop the first entry of bucket b, the least non-empty one, into *out. */
static void bq_pop_from(cvm__bad_queue *q, cvm__bad_entry *out, size_t b)
{
    int32_t h = BK_HEAD(q, b), r = BK_READ(q, b)++;
    const bq_item *it = &q->blk[h].it[r];
    out->key = it->key;
    out->cls = (int32_t)(b >> BQ_KEY_BITS);
    out->t = it->t;
    out->v[0] = it->v[0];
    out->v[1] = it->v[1];
    out->v[2] = it->v[2];
    if (h == BK_TAIL(q, b) && r + 1 == BK_WRITE(q, b)) {
        bq_give_block(q, h);
        bq_unmark(q, b);
    } else if (r + 1 == CVM__BQ_BLOCK) {
        BK_HEAD(q, b) = q->blk[h].next;
        BK_READ(q, b) = 0;
        bq_give_block(q, h);
    }
    q->n--;
}

int cvm__bq_pop(cvm__bad_queue *q, cvm__bad_entry *out)
{
    if (q->n == 0)
        return 0;
    bq_pop_from(q, out, bq_min_bucket(q));
    return 1;
}

/* cvm__bq_pop_valid fetches the triangle of the entry BQ_AHEAD places ahead
 * (slot arrays and vertex coordinates), and the neighbours of the entry
 * BQ_AHEAD / 2 places ahead (whose adjacency should have arrived by then). */
#define BQ_AHEAD 8

/* Entry k places after the head of bucket b, or NULL (not in the next block). */
static const bq_item *bq_peek(const cvm__bad_queue *q, size_t b, int32_t k)
{
    int32_t h = BK_HEAD(q, b), r = BK_READ(q, b) + k;
    if (r >= CVM__BQ_BLOCK && h != BK_TAIL(q, b)) {
        h = q->blk[h].next;
        r -= CVM__BQ_BLOCK;
    }
    return h != BK_TAIL(q, b) || r < BK_WRITE(q, b) ? &q->blk[h].it[r] : NULL;
}

int cvm__bq_pop_valid(cvm__bad_queue *q, const cvm__tri2 *T, const double *vdata,
                      cvm__bad_entry *out)
{
    while (q->n) {
        size_t b = bq_min_bucket(q);
        const bq_item *it = bq_peek(q, b, BQ_AHEAD);
        if (it && (size_t)it->t < T->nt && T->tn && T->xy) {
            size_t t3 = 3 * (size_t)it->t;
            bq_prefetch(T->tf + it->t);
            bq_prefetch(T->tv + t3);
            bq_prefetch(T->tn + t3);
            if (T->te)
                bq_prefetch(T->te + t3);
            bq_prefetch(T->xy + 2 * (size_t)it->v[0]);
            bq_prefetch(T->xy + 2 * (size_t)it->v[1]);
            bq_prefetch(T->xy + 2 * (size_t)it->v[2]);
            if (vdata) {
                bq_prefetch(vdata + it->v[0]);
                bq_prefetch(vdata + it->v[1]);
                bq_prefetch(vdata + it->v[2]);
            }
        }
        it = bq_peek(q, b, BQ_AHEAD / 2);
        if (it && (size_t)it->t < T->nt && T->tn) {
            const int32_t *tn = T->tn + 3 * (size_t)it->t;
            int k;
            for (k = 0; k < 3; k++)
                if (tn[k] >= 0)
                    bq_prefetch(T->tv + 3 * (size_t)(tn[k] / 3));
        }
        bq_pop_from(q, out, b);
        if (cvm__bq_valid(T, out))
            return 1;
    }
    return 0;
}

int cvm__bq_valid(const cvm__tri2 *T, const cvm__bad_entry *e)
{
    int32_t v[3];
    if (e->t < 0 || (size_t)e->t >= T->nt || !cvm__tri2_in_domain(T, e->t))
        return 0;
    bq_rotated(T, e->t, v);
    return v[0] == e->v[0] && v[1] == e->v[1] && v[2] == e->v[2];
}
