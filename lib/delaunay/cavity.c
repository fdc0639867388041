/* cavity.c - replace a set of triangles by a given set of new ones, restoring adjacency. */
#include <stdlib.h>

#include "delaunay_internal.h"
#include "tri2_store.h"
#include "cavity.h"

typedef struct edge_key {
    int32_t lo, hi;
    int32_t half;   /* half-edge 3t+j */
    int32_t outer;  /* 1: boundary edge of the old cavity (half is its outside half-edge) */
    int32_t seg;
} edge_key;

static int cmp_edge(const void *pa, const void *pb)
{
    const edge_key *a = pa, *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    if (a->outer != b->outer)
        return a->outer < b->outer ? -1 : 1;
    return a->half < b->half ? -1 : a->half > b->half;
}

static void set_key(edge_key *k, int32_t u, int32_t v, int32_t half, int32_t outer, int32_t seg)
{
    k->lo = u < v ? u : v;
    k->hi = u < v ? v : u;
    k->half = half;
    k->outer = outer;
    k->seg = seg;
}

cvm_status cvm__tri2_replace(cvm__tri2 *T, const int32_t *cav, size_t ncav, const int32_t *newtri,
                             size_t nnew, int32_t ca, int32_t cb, int32_t cseg)
{
    size_t nkeys = 0, i;
    edge_key *keys;
    uint8_t flags = ncav ? (uint8_t)(T->tf[cav[0]] & CVM__TF_OUT) : 0;
    double ta = (ncav && T->ta) ? T->ta[cav[0]] : 0.0;

    if (nnew > ncav && cvm__tri2_reserve_triangles(T, T->nt + nnew - ncav))
        return CVM_E_NOMEM;
    keys = cvm__malloc(T->ctx, (3 * ncav + 3 * nnew) * sizeof *keys);
    if (!keys)
        return CVM_E_NOMEM;
    for (i = 0; i < ncav; i++)
        T->tf[cav[i]] |= CVM__TF_MARK;
    for (i = 0; i < ncav; i++) {
        int32_t t = cav[i];
        int j;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * (size_t)t + j;
            if (T->tf[T->tn[h] / 3] & CVM__TF_MARK)
                continue;
            set_key(&keys[nkeys++], T->tv[3 * (size_t)t + (j + 1) % 3],
                    T->tv[3 * (size_t)t + (j + 2) % 3], T->tn[h], 1, T->te ? T->te[h] : -1);
        }
    }
    for (i = 0; i < ncav; i++)
        cvm__tri2_kill(T, cav[i]);
    for (i = 0; i < nnew; i++) {
        int32_t n = cvm__tri2_new(T);
        int j;
        T->tf[n] = flags;
        if (T->ta)
            T->ta[n] = ta;
        for (j = 0; j < 3; j++) {
            int32_t v = newtri[3 * i + j];
            T->tv[3 * (size_t)n + j] = v;
            if (v >= 0)
                T->vtri[v] = n;
        }
        for (j = 0; j < 3; j++)
            set_key(&keys[nkeys++], newtri[3 * i + (j + 1) % 3], newtri[3 * i + (j + 2) % 3],
                    3 * n + j, 0, -1);
        T->last = n;
    }
    qsort(keys, nkeys, sizeof *keys, cmp_edge);
    for (i = 0; i + 1 < nkeys; i += 2) {
        edge_key *k0 = &keys[i], *k1 = &keys[i + 1];
        int32_t seg;
        /* the new half-edge sorts first (outer 0 before 1) */
        T->tn[k0->half] = k1->half;
        T->tn[k1->half] = k0->half;
        if (!T->te)
            continue;
        seg = k1->outer ? k1->seg : -1;
        if ((k0->lo == ca && k0->hi == cb) || (k0->lo == cb && k0->hi == ca))
            seg = cseg;
        T->te[k0->half] = seg;
        T->te[k1->half] = seg;
    }
    cvm__free(T->ctx, keys);
    return CVM_OK;
}
