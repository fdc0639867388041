/*
 * geometry.c - the power dual of the domain of a 2D triangulation as
 * geometry: which triangles contain their power vertex, the dual edge of
 * every domain edge, and the area of every vertex's power cell.
 *
 * Containment is decided exactly (cvm__power_side2d); positions, lengths and
 * areas are constructions in plain doubles.
 */
#include <math.h>
#include <string.h>

#include "dual_internal.h"
#include "delaunay/domain.h"

int cvm__dual_tri_contains(const cvm__tri2 *T, int32_t t)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    int k;
    for (k = 0; k < 3; k++) {
        int32_t a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
        if (cvm__power_side2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, T->xy + 2 * (size_t)c,
                              cvm__dual_weight(T, a), cvm__dual_weight(T, b),
                              cvm__dual_weight(T, c)) < 0)
            return 0;
    }
    return 1;
}

void cvm__dual_areas(const cvm__tri2 *T, double *dst)
{
    size_t t;
    int j;
    memset(dst, 0, T->nv * sizeof *dst);
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        double V[2];
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        cvm__dual_tri_vertex(T, (int32_t)t, V);
        for (j = 0; j < 3; j++) {
            int32_t a = v[j], b = v[(j + 1) % 3];
            const double *p = T->xy + 2 * (size_t)a, *q = T->xy + 2 * (size_t)b;
            double M[2];
            cvm__power_foot2d(p, q, cvm__dual_weight(T, a), cvm__dual_weight(T, b), M);
            /* kite pieces (p, M, V) and (q, V, M), signed */
            dst[a] += 0.5 * ((M[0] - p[0]) * (V[1] - p[1]) - (M[1] - p[1]) * (V[0] - p[0]));
            dst[b] += 0.5 * ((V[0] - q[0]) * (M[1] - q[1]) - (V[1] - q[1]) * (M[0] - q[0]));
        }
    }
}

cvm_status cvm__dual_edge_lengths(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *len)
{
    double *ends = cvm__malloc(ctx, (4 * e->n + 1) * sizeof *ends);
    size_t k;
    if (!ends || cvm__dual_edge_ends(ctx, T, e, ends)) {
        cvm__free(ctx, ends);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e->n; k++)
        len[k] = hypot(ends[4 * k] - ends[4 * k + 2], ends[4 * k + 1] - ends[4 * k + 3]);
    cvm__free(ctx, ends);
    return CVM_OK;
}

cvm_status cvm__dual_outside_pct(cvm__ctx *ctx, const cvm__tri2 *T, double *pct)
{
    cvm__edges e;
    uint8_t *on_bnd;
    size_t t, n = 0, nout = 0, nb = 0, nbout = 0, k;
    if (cvm__domain_edges(ctx, T, 0, &e))
        return CVM_E_NOMEM;
    on_bnd = cvm__calloc(ctx, T->nv + 1, 1);
    if (!on_bnd) {
        cvm__edges_free(ctx, &e);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e.n; k++)
        if (e.bnd[k])
            on_bnd[e.ev[2 * k]] = on_bnd[e.ev[2 * k + 1]] = 1;
    cvm__edges_free(ctx, &e);
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        int out;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        out = !cvm__dual_tri_contains(T, (int32_t)t);
        n++;
        nout += (size_t)out;
        if (on_bnd[v[0]] || on_bnd[v[1]] || on_bnd[v[2]]) {
            nb++;
            nbout += (size_t)out;
        }
    }
    cvm__free(ctx, on_bnd);
    pct[0] = n ? 100.0 * (double)nout / (double)n : 0.0;
    pct[1] = nb ? 100.0 * (double)nbout / (double)nb : 0.0;
    return CVM_OK;
}

cvm_status cvm__dual_edge_ends(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *ends)
{
    /* e is sorted by lower vertex: first[v] .. first[v + 1] are the edges whose
     * lower vertex is v, a handful each, so a lookup scans a few entries
     * instead of bisecting the whole list */
    uint8_t *have = cvm__calloc(ctx, e->n + 1, 1);
    size_t *first = cvm__calloc(ctx, T->nv + 2, sizeof *first);
    size_t t, k;
    int j;
    if (!have || !first) {
        cvm__free(ctx, have);
        cvm__free(ctx, first);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e->n; k++)
        first[(size_t)e->ev[2 * k] + 1]++;
    for (k = 0; k < T->nv; k++)
        first[k + 1] += first[k];
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        double V[2];
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        cvm__dual_tri_vertex(T, (int32_t)t, V);
        for (j = 0; j < 3; j++) {
            int32_t a = v[(j + 1) % 3], b = v[(j + 2) % 3];
            int32_t lo = a < b ? a : b, hi = a < b ? b : a;
            double *x;
            for (k = first[lo]; k < first[lo + 1] && e->ev[2 * k + 1] != hi; k++)
                ;
            if (k == first[lo + 1])
                continue; /* cannot happen: e holds every domain edge */
            x = ends + 4 * k;
            if (e->bnd[k]) {
                x[0] = V[0];
                x[1] = V[1];
                cvm__power_foot2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, cvm__dual_weight(T, a),
                                  cvm__dual_weight(T, b), x + 2);
            } else if (have[k]) {
                x[2] = V[0];
                x[3] = V[1];
            } else {
                x[0] = V[0];
                x[1] = V[1];
                have[k] = 1;
            }
        }
    }
    cvm__free(ctx, have);
    cvm__free(ctx, first);
    return CVM_OK;
}
