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

/* The canonical form of the finite tetrahedron in slot t, or 0 for a ghost or free slot. */
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

cvm_status cvm__tet3_copy_tets(cvm__tet3 *T, int32_t *dst)
{
    size_t n = T->np, i, *start, sum = 0;
    int32_t o[4];
    start = cvm__calloc(T->ctx, n + 1, sizeof *start);
    if (!start)
        return cvm__nomem(T->ctx);
    /* counting sort on the first vertex (two passes over the store), then an
     * insertion sort of each bucket (about 6 tetrahedra on average) */
    for (i = 0; i < T->nslot; i++)
        if (canonical_tet(T, i, o))
            start[o[0]]++;
    for (i = 0; i <= n; i++) {
        size_t c = start[i];
        start[i] = sum;
        sum += c;
    }
    for (i = 0; i < T->nslot; i++)
        if (canonical_tet(T, i, o))
            memcpy(dst + 4 * start[o[0]]++, o, sizeof o);
    for (i = 0, sum = 0; i < n; i++) {
        size_t lo = sum, hi = start[i], j, k;
        sum = hi;
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
    cvm__free(T->ctx, start);
    return CVM_OK;
}
