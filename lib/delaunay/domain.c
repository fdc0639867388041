/* domain.c - enumerates the triangles and unique edges of a triangulation's domain in output order. */
#include <string.h>

#include "domain.h"

size_t cvm__domain_triangles(const cvm__tri2 *T)
{
    size_t t, n = 0;
    for (t = 0; t < T->nt; t++)
        n += cvm__tri2_in_domain(T, (int32_t)t) ? 1 : 0;
    return n;
}

/* The triangle across edge j of domain triangle t, or -1 outside the domain. */
static int32_t across(const cvm__tri2 *T, size_t t, int j)
{
    int32_t a = T->tn[3 * t + (size_t)j];
    if (a < 0 || !cvm__tri2_in_domain(T, a / 3))
        return -1;
    return a / 3;
}

/* Edge j of domain triangle t is listed from t (and not from its twin). */
static int owns(const cvm__tri2 *T, size_t t, int j, int *bnd)
{
    int32_t u = across(T, t, j);
    *bnd = u < 0;
    return u < 0 || (size_t)u > t;
}

void cvm__domain_edge_counts(const cvm__tri2 *T, size_t *nedge, size_t *nseg)
{
    size_t t;
    int j, bnd;
    *nedge = *nseg = 0;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            if (!owns(T, t, j, &bnd))
                continue;
            (*nedge)++;
            if (cvm__tri2_edge_seg(T, (int32_t)t, j) >= 0)
                (*nseg)++;
        }
    }
}

cvm_status cvm__domain_map(cvm__ctx *ctx, const cvm__tri2 *T, int32_t **map_out)
{
    int32_t *map = cvm__malloc(ctx, (T->nt ? T->nt : 1) * sizeof *map);
    size_t t;
    int32_t k = 0;
    *map_out = NULL;
    if (!map)
        return CVM_E_NOMEM;
    for (t = 0; t < T->nt; t++)
        map[t] = cvm__tri2_in_domain(T, (int32_t)t) ? k++ : -1;
    *map_out = map;
    return CVM_OK;
}

void cvm__edges_free(cvm__ctx *ctx, cvm__edges *e)
{
    cvm__free(ctx, e->ev);
    cvm__free(ctx, e->seg);
    cvm__free(ctx, e->bnd);
    memset(e, 0, sizeof *e);
}

/* Counting sort of the n gathered edges by lower vertex, then insertion sort
 * by higher vertex within each bucket (a few entries): O(n + nv). */
static cvm_status sort_edges(cvm__ctx *ctx, size_t nv, const int32_t *ev, const int32_t *seg,
                             const uint8_t *bnd, cvm__edges *out)
{
    size_t *start = cvm__calloc(ctx, nv + 1, sizeof *start);
    size_t k, v, n = out->n;
    if (!start)
        return CVM_E_NOMEM;
    for (k = 0; k < n; k++)
        start[(size_t)ev[2 * k] + 1]++;
    for (v = 0; v < nv; v++)
        start[v + 1] += start[v];
    for (k = 0; k < n; k++) {
        size_t at = start[ev[2 * k]]++;
        out->ev[2 * at] = ev[2 * k];
        out->ev[2 * at + 1] = ev[2 * k + 1];
        out->seg[at] = seg[k];
        out->bnd[at] = bnd[k];
    }
    /* start[v] is now the end of bucket v; sort each bucket by hi */
    for (v = 0, k = 0; v < nv; v++) {
        size_t lo = k, hi = start[v], i;
        for (i = lo + 1; i < hi; i++) {
            int32_t h = out->ev[2 * i + 1], sg = out->seg[i];
            uint8_t b = out->bnd[i];
            size_t p = i;
            while (p > lo && out->ev[2 * (p - 1) + 1] > h) {
                out->ev[2 * p + 1] = out->ev[2 * (p - 1) + 1];
                out->seg[p] = out->seg[p - 1];
                out->bnd[p] = out->bnd[p - 1];
                p--;
            }
            out->ev[2 * p + 1] = h;
            out->seg[p] = sg;
            out->bnd[p] = b;
        }
        k = hi;
    }
    cvm__free(ctx, start);
    return CVM_OK;
}

cvm_status cvm__domain_edges(cvm__ctx *ctx, const cvm__tri2 *T, int constrained_only,
                             cvm__edges *out)
{
    size_t ne, ns, n, t, k = 0;
    int32_t *ev, *seg;
    uint8_t *bnd;
    int j, b;
    cvm_status s;
    memset(out, 0, sizeof *out);
    cvm__domain_edge_counts(T, &ne, &ns);
    n = constrained_only ? ns : ne;
    ev = cvm__malloc(ctx, (2 * n + 1) * sizeof *ev);
    seg = cvm__malloc(ctx, (n + 1) * sizeof *seg);
    bnd = cvm__malloc(ctx, n + 1);
    out->ev = cvm__malloc(ctx, (2 * n + 1) * sizeof *out->ev);
    out->seg = cvm__malloc(ctx, (n + 1) * sizeof *out->seg);
    out->bnd = cvm__malloc(ctx, n + 1);
    if (!ev || !seg || !bnd || !out->ev || !out->seg || !out->bnd) {
        s = CVM_E_NOMEM;
        goto done;
    }
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t a = T->tv[3 * t + (size_t)(j + 1) % 3], c = T->tv[3 * t + (size_t)(j + 2) % 3];
            int32_t sg = cvm__tri2_edge_seg(T, (int32_t)t, j);
            if (!owns(T, t, j, &b) || (constrained_only && sg < 0))
                continue;
            ev[2 * k] = a < c ? a : c;
            ev[2 * k + 1] = a < c ? c : a;
            seg[k] = sg;
            bnd[k] = (uint8_t)b;
            k++;
        }
    }
    out->n = k;
    s = sort_edges(ctx, T->nv, ev, seg, bnd, out);
done:
    cvm__free(ctx, ev);
    cvm__free(ctx, seg);
    cvm__free(ctx, bnd);
    if (s)
        cvm__edges_free(ctx, out);
    return s;
}
