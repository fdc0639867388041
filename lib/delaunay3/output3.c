/* output3.c - the finite tetrahedra in canonical form and order (deterministic output). */
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "delaunay3/delaunay3_internal.h"

/* Turn t[4] by an even permutation (orientation kept): smallest first, then
 * the smallest of the other three by a cyclic turn of the last three. Table
 * driven, without branches: the order of the indices is random. */
static void canonical_turn(int32_t *t)
{
    /* front[m]: a double transposition (or none) bringing position m first */
    static const int8_t front[4][4] = {
        { 0, 1, 2, 3 }, { 1, 0, 3, 2 }, { 2, 3, 0, 1 }, { 3, 2, 1, 0 }
    };
    static const int8_t turn[3][3] = { { 0, 1, 2 }, { 1, 2, 0 }, { 2, 0, 1 } };
    int32_t q[3];
    int m01 = t[1] < t[0], m23 = 2 + (t[3] < t[2]), m, r;
    int32_t v01 = t[m01], v23 = t[m23], lo;
    m = v23 < v01 ? m23 : m01;
    lo = v23 < v01 ? v23 : v01;
    q[0] = t[front[m][1]], q[1] = t[front[m][2]], q[2] = t[front[m][3]];
    r = q[1] < q[0] ? (q[2] < q[1] ? 2 : 1) : (q[2] < q[0] ? 2 : 0);
    t[0] = lo;
    t[1] = q[turn[r][0]], t[2] = q[turn[r][1]], t[3] = q[turn[r][2]];
}

void cvm__tet3_canonical_turn(int32_t *t)
{
    canonical_turn(t);
}

/* In a valid tetrahedralisation two tetrahedra never share their first three
 * canonical indices (they would lie on one side of the same face), so a run
 * of equal first index sorts on (second, third) as one 64-bit key; the
 * fourth only breaks ties that cannot occur, to keep the order total. */
static int tail_less(const int32_t *a, const int32_t *b)
{
    uint64_t ka = ((uint64_t)(uint32_t)a[1] << 32) | (uint32_t)a[2];
    uint64_t kb = ((uint64_t)(uint32_t)b[1] << 32) | (uint32_t)b[2];
    return ka < kb || (ka == kb && a[3] < b[3]);
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

#define LOW_BITS 11

/* Stable counting sort of the n tetrahedra src[lo..) of one high bucket by
 * the low LOW_BITS bits of their first vertex into dst (in cache: a bucket
 * holds about 6.75 * 2^LOW_BITS tetrahedra). */
static void sort_low(const int32_t *src, int32_t *dst, size_t n, size_t *count)
{
    size_t i, sum = 0, mask = ((size_t)1 << LOW_BITS) - 1;
    memset(count, 0, ((size_t)1 << LOW_BITS) * sizeof *count);
    for (i = 0; i < n; i++)
        count[(size_t)src[4 * i] & mask]++;
    for (i = 0; i <= mask; i++) {
        size_t c = count[i];
        count[i] = sum;
        sum += c;
    }
    for (i = 0; i < n; i++)
        memcpy(dst + 4 * count[(size_t)src[4 * i] & mask]++, src + 4 * i, 4 * sizeof *src);
}

/* Sort each run of equal first vertices (about 6 on average) by the rest. */
static void sort_runs(int32_t *dst, size_t nt)
{
    size_t lo, hi, j, k;
    for (lo = 0; lo < nt; lo = hi) {
        for (hi = lo + 1; hi < nt && dst[4 * hi] == dst[4 * lo]; hi++)
            ;
        if (hi - lo > 64) { /* a vertex of very high degree (the centre of a sphere) */
            qsort(dst + 4 * lo, hi - lo, 4 * sizeof *dst, cmp_tet);
            continue;
        }
        for (j = lo + 1; j < hi; j++) {
            int32_t key[4];
            memcpy(key, dst + 4 * j, sizeof key);
            for (k = j; k > lo && tail_less(key, dst + 4 * (k - 1)); k--)
                memcpy(dst + 4 * k, dst + 4 * (k - 1), sizeof key);
            memcpy(dst + 4 * k, key, sizeof key);
        }
    }
}

/* The first canonical index of the finite tetrahedron in slot i, or -1. */
static int32_t first_index(const cvm__tet3 *T, size_t i)
{
    const int32_t *v = T->tt + 8 * i, *out = T->outid;
    int32_t a, b;
    if (v[0] == CVM__T3_DEAD || v[3] == CVM__T3_GHOST)
        return -1;
    a = out[v[0]] < out[v[1]] ? out[v[0]] : out[v[1]];
    b = out[v[2]] < out[v[3]] ? out[v[2]] : out[v[3]];
    return a < b ? a : b;
}

/* cvm__tet3_copy_tets() on nt threads: each counts and scatters a run of
 * slots (into its own part of every bucket), then the buckets are sorted in
 * parallel. The order inside a bucket before its sort depends on the runs,
 * the sorted order does not (the sort key is total). */
static cvm_status copy_tets_parallel(cvm__tet3 *T, int32_t *dst, int nt)
{
    size_t nhigh = (T->np >> LOW_BITS) + 1, sum = 0, big = 0, h;
    size_t *cnt = cvm__calloc(T->ctx, (size_t)nt * nhigh, sizeof *cnt), *end, *low = NULL;
    int32_t *buf = NULL;
    long b, nb = (long)nhigh;
    int t;
    end = cvm__malloc(T->ctx, nhigh * sizeof *end);
    if (!cnt || !end)
        goto nomem;
#ifdef _OPENMP
#pragma omp parallel for schedule(static, 1) num_threads(nt)
#endif
    for (t = 0; t < nt; t++) {
        size_t i, *c = cnt + (size_t)t * nhigh;
        for (i = T->nslot * (size_t)t / (size_t)nt; i < T->nslot * (size_t)(t + 1) / (size_t)nt; i++) {
            int32_t f = first_index(T, i);
            if (f >= 0)
                c[(size_t)f >> LOW_BITS]++;
        }
    }
    for (h = 0; h < nhigh; h++) { /* bucket h: thread 0's part, thread 1's, ... */
        size_t lo = sum;
        for (t = 0; t < nt; t++) {
            size_t c = cnt[(size_t)t * nhigh + h];
            cnt[(size_t)t * nhigh + h] = sum;
            sum += c;
        }
        end[h] = sum;
        big = sum - lo > big ? sum - lo : big;
    }
    buf = cvm__malloc(T->ctx, (size_t)nt * (4 * big + 1) * sizeof *buf);
    low = cvm__malloc(T->ctx, ((size_t)nt << LOW_BITS) * sizeof *low);
    if (!buf || !low)
        goto nomem;
#ifdef _OPENMP
#pragma omp parallel for schedule(static, 1) num_threads(nt)
#endif
    for (t = 0; t < nt; t++) {
        size_t i, *c = cnt + (size_t)t * nhigh;
        int32_t o[4];
        for (i = T->nslot * (size_t)t / (size_t)nt; i < T->nslot * (size_t)(t + 1) / (size_t)nt; i++)
            if (canonical_tet(T, i, o))
                memcpy(dst + 4 * c[(size_t)o[0] >> LOW_BITS]++, o, sizeof o);
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 16) num_threads(nt)
#endif
    for (b = 0; b < nb; b++) {
        size_t lo = b > 0 ? end[b - 1] : 0, hi = end[b];
#ifdef _OPENMP
        int me = omp_get_thread_num();
#else
        int me = 0;
#endif
        int32_t *mine = buf + (size_t)me * (4 * big + 1);
        if (hi - lo < 2)
            continue;
        sort_low(dst + 4 * lo, mine, hi - lo, low + ((size_t)me << LOW_BITS));
        sort_runs(mine, hi - lo);
        memcpy(dst + 4 * lo, mine, 4 * (hi - lo) * sizeof *mine);
    }
    cvm__free(T->ctx, cnt);
    cvm__free(T->ctx, end);
    cvm__free(T->ctx, buf);
    cvm__free(T->ctx, low);
    return CVM_OK;
nomem:
    cvm__free(T->ctx, cnt);
    cvm__free(T->ctx, end);
    cvm__free(T->ctx, buf);
    cvm__free(T->ctx, low);
    return cvm__nomem(T->ctx);
}

/* Two-level sort on the first vertex: the buckets of its high bits are
 * counted first (the first canonical index is the smallest), then each
 * tetrahedron is written in canonical form straight into its bucket of dst
 * (one streaming scatter), then each bucket is sorted in cache by the low
 * bits and its runs by the rest, through a buffer of the largest bucket. */
cvm_status cvm__tet3_copy_tets(cvm__tet3 *T, int32_t *dst)
{
    size_t nhigh = (T->np >> LOW_BITS) + 1, i, sum = 0, big = 0;
    size_t *start, *low;
    int32_t *buf = NULL, o[4];
    int nt = cvm__tet3_build_threads(T);
    if (nt > 1 && T->nslot >= 8 * T->par_min)
        return copy_tets_parallel(T, dst, nt);
    start = cvm__calloc(T->ctx, nhigh + 1, sizeof *start);
    low = cvm__malloc(T->ctx, ((size_t)1 << LOW_BITS) * sizeof *low);
    if (!start || !low)
        goto nomem;
    for (i = 0; i < T->nslot; i++) {
        int32_t f = first_index(T, i);
        if (f >= 0)
            start[(size_t)f >> LOW_BITS]++;
    }
    for (i = 0; i <= nhigh; i++) {
        size_t c = start[i];
        start[i] = sum;
        sum += c;
        big = c > big ? c : big;
    }
    buf = cvm__malloc(T->ctx, 4 * big * sizeof *buf + 1);
    if (!buf)
        goto nomem;
    for (i = 0; i < T->nslot; i++)
        if (canonical_tet(T, i, o)) /* after this, bucket h spans [start[h - 1], start[h]) */
            memcpy(dst + 4 * start[(size_t)o[0] >> LOW_BITS]++, o, sizeof o);
    for (i = 0, sum = 0; i < nhigh; i++) {
        size_t lo = sum, hi = start[i];
        sum = hi;
        if (hi - lo < 2)
            continue;
        sort_low(dst + 4 * lo, buf, hi - lo, low);
        sort_runs(buf, hi - lo);
        memcpy(dst + 4 * lo, buf, 4 * (hi - lo) * sizeof *buf);
    }
    cvm__free(T->ctx, start);
    cvm__free(T->ctx, low);
    cvm__free(T->ctx, buf);
    return CVM_OK;
nomem:
    cvm__free(T->ctx, start);
    cvm__free(T->ctx, low);
    return cvm__nomem(T->ctx);
}
