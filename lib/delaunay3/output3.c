/* output3.c - the finite tetrahedra in canonical form and order (deterministic output). */
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_internal.h"

/* Turn t[4] by an even permutation (orientation kept): smallest first, then
 * the smallest of the other three by a cyclic turn of the last three. */
static void canonical_turn(int32_t *t)
{
    int32_t a = t[0], b = t[1], c = t[2], d = t[3], x;
    int m = 0, k;
    for (k = 1; k < 4; k++)
        if (t[k] < t[m])
            m = k;
    /* the double transpositions bring position m to the front */
    if (m == 1)
        t[0] = b, t[1] = a, t[2] = d, t[3] = c;
    else if (m == 2)
        t[0] = c, t[1] = d, t[2] = a, t[3] = b;
    else if (m == 3)
        t[0] = d, t[1] = c, t[2] = b, t[3] = a;
    while (t[1] > t[2] || t[1] > t[3])
        x = t[1], t[1] = t[2], t[2] = t[3], t[3] = x;
}

static int tail_less(const int32_t *a, const int32_t *b)
{
    if (a[1] != b[1])
        return a[1] < b[1];
    if (a[2] != b[2])
        return a[2] < b[2];
    return a[3] < b[3];
}

static int cmp_tet(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    int k;
    for (k = 0; k < 4; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* The canonical form of the finite tetrahedron in slot t into o, or 0 for a ghost or free slot. */
static int canonical_tet(const cvm__tet3 *T, size_t t, int32_t *o)
{
    const int32_t *v = T->tt + 8 * t;
    if (v[0] == CVM__T3_DEAD || v[3] == CVM__T3_GHOST)
        return 0;
    o[0] = T->outid[v[0]], o[1] = T->outid[v[1]];
    o[2] = T->outid[v[2]], o[3] = T->outid[v[3]];
    canonical_turn(o);
    return 1;
}

#define DIGIT_BITS 11

/* Stable LSD radix sort of the tetrahedra by their first vertex, `passes`
 * passes of DIGIT_BITS bits from src to dst and back, ending in `out`
 * (which is src or dst by the parity of passes). Streaming writes into 2048
 * buckets: far cheaper than scattering by a random-looking index. */
static void radix_by_first(int32_t *src, int32_t *dst, size_t nt, int passes, size_t *count)
{
    int pass;
    size_t i;
    for (pass = 0; pass < passes; pass++) {
        int shift = pass * DIGIT_BITS;
        size_t sum = 0, mask = ((size_t)1 << DIGIT_BITS) - 1;
        int32_t *t;
        memset(count, 0, ((size_t)1 << DIGIT_BITS) * sizeof *count);
        for (i = 0; i < nt; i++)
            count[((size_t)src[4 * i] >> shift) & mask]++;
        for (i = 0; i <= mask; i++) {
            size_t c = count[i];
            count[i] = sum;
            sum += c;
        }
        for (i = 0; i < nt; i++)
            memcpy(dst + 4 * count[((size_t)src[4 * i] >> shift) & mask]++, src + 4 * i,
                   4 * sizeof *src);
        t = src, src = dst, dst = t;
    }
}

cvm_status cvm__tet3_copy_tets(cvm__tet3 *T, int32_t *dst)
{
    size_t nt = T->n_finite, i, m = 0, lo, *count;
    int32_t *tmp, *first;
    int passes = 1;
    while (passes * DIGIT_BITS < 31 && ((size_t)1 << (passes * DIGIT_BITS)) < T->np)
        passes++;
    count = cvm__malloc(T->ctx, ((size_t)1 << DIGIT_BITS) * sizeof *count);
    tmp = cvm__malloc(T->ctx, 4 * nt * sizeof *tmp + 1);
    if (!count || !tmp) {
        cvm__free(T->ctx, count);
        cvm__free(T->ctx, tmp);
        return cvm__nomem(T->ctx);
    }
    /* write so that the last radix pass lands in dst */
    first = passes % 2 ? tmp : dst;
    for (i = 0; i < T->nslot; i++)
        if (canonical_tet(T, i, first + 4 * m))
            m++;
    radix_by_first(first, first == tmp ? dst : tmp, nt, passes, count);
    /* each run of equal first vertices (about 6 on average): sort by the rest */
    for (lo = 0; lo < nt;) {
        size_t hi = lo + 1, j, k;
        while (hi < nt && dst[4 * hi] == dst[4 * lo])
            hi++;
        if (hi - lo > 64) { /* a vertex of very high degree (the centre of a sphere) */
            qsort(dst + 4 * lo, hi - lo, 4 * sizeof *dst, cmp_tet);
        } else {
            for (j = lo + 1; j < hi; j++) {
                int32_t key[4];
                memcpy(key, dst + 4 * j, sizeof key);
                for (k = j; k > lo && tail_less(key, dst + 4 * (k - 1)); k--)
                    memcpy(dst + 4 * k, dst + 4 * (k - 1), sizeof key);
                memcpy(dst + 4 * k, key, sizeof key);
            }
        }
        lo = hi;
    }
    cvm__free(T->ctx, count);
    cvm__free(T->ctx, tmp);
    return CVM_OK;
}
