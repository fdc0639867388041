/*
 * dual_cells.c - the power (Voronoi) cell polygon of every vertex, restricted
 * to the domain, as CSR arrays.
 *
 * Each cell is gathered by walking the fan of domain triangles around its
 * vertex counter-clockwise through the adjacency (tn): in triangle t with
 * the vertex at position i, the next triangle counter-clockwise lies across
 * edge (i+1)%3 and the previous one across edge (i+2)%3. A fan that meets the
 * domain boundary is opened there and closed by the vertex and the
 * power-bisector feet of its two boundary edges. Corners are constructions
 * (plain doubles).
 */
#include <limits.h>
#include <string.h>

#include "dual_internal.h"

/* Domain triangles incident to each vertex, CSR: first (nv+1), list. */
typedef struct incidence {
    int32_t *first, *list;
    uint8_t *seen; /* per slot: visited by the current walk */
} incidence;

static void inc_free(cvm__ctx *ctx, incidence *in)
{
    cvm__free(ctx, in->first);
    cvm__free(ctx, in->list);
    cvm__free(ctx, in->seen);
}

static cvm_status inc_build(cvm__ctx *ctx, const cvm__tri2 *T, incidence *in)
{
    size_t t, v;
    int j;
    memset(in, 0, sizeof *in);
    in->first = cvm__calloc(ctx, T->nv + 2, sizeof *in->first);
    in->list = cvm__malloc(ctx, (3 * T->nt + 1) * sizeof *in->list);
    in->seen = cvm__calloc(ctx, T->nt + 1, 1);
    if (!in->first || !in->list || !in->seen) {
        inc_free(ctx, in);
        return CVM_E_NOMEM;
    }
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            for (j = 0; j < 3; j++)
                in->first[T->tv[3 * t + (size_t)j] + 2]++;
    for (v = 0; v < T->nv; v++)
        in->first[v + 2] += in->first[v + 1];
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            for (j = 0; j < 3; j++)
                in->list[in->first[T->tv[3 * t + (size_t)j] + 1]++] = (int32_t)t;
    return CVM_OK;
}

/* Domain triangle across edge j of t, or -1. */
static int32_t across(const cvm__tri2 *T, int32_t t, int j)
{
    int32_t a = T->tn[3 * (size_t)t + (size_t)j], u = a < 0 ? -1 : a / 3;
    return u >= 0 && cvm__tri2_in_domain(T, u) ? u : -1;
}

static void put(double *xy, size_t *k, const double *p)
{
    if (xy) {
        xy[2 * *k] = p[0];
        xy[2 * *k + 1] = p[1];
    }
    (*k)++;
}

/* Corners of vertex v's cell appended at xy[2*k..] (xy NULL: count only). */
static void cell(const cvm__tri2 *T, incidence *in, int32_t v, double *xy, size_t *k)
{
    int32_t i, f;
    const double *pv = T->xy + 2 * (size_t)v;
    for (i = in->first[v]; i < in->first[v + 1]; i++)
        in->seen[in->list[i]] = 0;
    /* fans that meet the boundary first, in slot order of their first triangle */
    for (f = 0; f < 2; f++) {
        for (i = in->first[v]; i < in->first[v + 1]; i++) {
            int32_t t = in->list[i], u;
            double P[2];
            int p = cvm__tri2_corner(T, t, v);
            if (in->seen[t] || (f == 0 && across(T, t, (p + 2) % 3) >= 0))
                continue;
            if (f == 0) { /* open fan starting at boundary edge (v, tv[p+1]) */
                int32_t a = T->tv[3 * (size_t)t + (size_t)(p + 1) % 3];
                put(xy, k, pv);
                cvm__power_foot2d(pv, T->xy + 2 * (size_t)a, cvm__dual_weight(T, v), cvm__dual_weight(T, a), P);
                put(xy, k, P);
            }
            for (u = t; u >= 0 && !in->seen[u]; u = across(T, u, (cvm__tri2_corner(T, u, v) + 1) % 3)) {
                const int32_t *tv = T->tv + 3 * (size_t)u;
                in->seen[u] = 1;
                if (xy)
                    cvm__power_vertex2d(T->xy + 2 * (size_t)tv[0], T->xy + 2 * (size_t)tv[1],
                                        T->xy + 2 * (size_t)tv[2], cvm__dual_weight(T, tv[0]),
                                        cvm__dual_weight(T, tv[1]), cvm__dual_weight(T, tv[2]), P);
                put(xy, k, P);
                t = u;
            }
            if (f == 0) { /* close at boundary edge (tv[p+2], v) of the last triangle */
                int32_t b = T->tv[3 * (size_t)t + (size_t)(cvm__tri2_corner(T, t, v) + 2) % 3];
                cvm__power_foot2d(pv, T->xy + 2 * (size_t)b, cvm__dual_weight(T, v), cvm__dual_weight(T, b), P);
                put(xy, k, P);
            }
        }
    }
}

cvm_status cvm__dual_cells(cvm__ctx *ctx, const cvm__tri2 *T, int32_t *off, double *xy)
{
    incidence in;
    size_t v, k = 0;
    if (inc_build(ctx, T, &in))
        return CVM_E_NOMEM;
    for (v = 0; v < T->nv; v++) {
        off[v] = (int32_t)k;
        cell(T, &in, (int32_t)v, xy, &k);
        if (k > (size_t)INT32_MAX) {
            inc_free(ctx, &in);
            return CVM_E_TOO_LARGE;
        }
    }
    off[T->nv] = (int32_t)k;
    inc_free(ctx, &in);
    return CVM_OK;
}
