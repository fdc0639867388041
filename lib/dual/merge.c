/* merge.c - the merge rule of the power dual: which adjacent triangles share a cell because their dual edge is tiny. */
#include <math.h>

#include "dual_internal.h"

static double weight(const cvm__tri2 *T, int32_t v)
{
    return T->w ? T->w[v] : 0.0;
}

static const double *pt(const cvm__tri2 *T, int32_t v)
{
    return T->xy + 2 * (size_t)v;
}

void cvm__dual_mesh_sizes(const cvm__tri2 *T, double *vsize)
{
    size_t v, t;
    int j;
    /* sum of edge lengths at each vertex: an interior edge is seen from both
     * of its triangles, so it counts half each time; the degree below is
     * counted the same way */
    for (v = 0; v < T->nv; v++)
        vsize[v] = 0.0;
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t a = tv[(j + 1) % 3], b = tv[(j + 2) % 3];
            int32_t u = T->tn[3 * t + (size_t)j] / 3;
            double len = hypot(pt(T, a)[0] - pt(T, b)[0], pt(T, a)[1] - pt(T, b)[1]);
            /* an interior edge is visited from both sides: half each time */
            double share = cvm__tri2_in_domain(T, u) ? 0.5 : 1.0;
            vsize[a] += share * len;
            vsize[b] += share * len;
        }
    }
    /* divide by the number of edges: the degree counted the same way */
    for (v = 0; v < T->nv; v++) {
        double deg = 0.0;
        int32_t t0 = T->vtri[v], u;
        if (t0 < 0 || vsize[v] == 0.0)
            continue;
        u = t0;
        do {
            const int32_t *tv = T->tv + 3 * (size_t)u;
            int i = tv[0] == (int32_t)v ? 0 : tv[1] == (int32_t)v ? 1 : 2;
            int32_t next = T->tn[3 * (size_t)u + (size_t)(i + 1) % 3] / 3;
            if (cvm__tri2_in_domain(T, u)) {
                int32_t n1 = T->tn[3 * (size_t)u + (size_t)(i + 1) % 3] / 3;
                int32_t n2 = T->tn[3 * (size_t)u + (size_t)(i + 2) % 3] / 3;
                deg += cvm__tri2_in_domain(T, n1) ? 0.5 : 1.0;
                deg += cvm__tri2_in_domain(T, n2) ? 0.5 : 1.0;
            }
            u = next;
        } while (u != t0);
        vsize[v] = deg > 0 ? vsize[v] / deg : 0.0;
    }
}

void cvm__dual_tri_vertex(const cvm__tri2 *T, int32_t t, double *out)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    cvm__power_vertex2d(pt(T, v[0]), pt(T, v[1]), pt(T, v[2]), weight(T, v[0]), weight(T, v[1]),
                        weight(T, v[2]), out);
}

int cvm__dual_edge_mergeable(const cvm__tri2 *T, const double *vsize, double tol, int32_t t, int j,
                             const double *Vt, const double *Vu)
{
    size_t h = 3 * (size_t)t + (size_t)j;
    int32_t u = T->tn[h] / 3, a = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3];
    int32_t b = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
    double l, d;
    if (tol <= 0 || cvm__tri2_edge_seg(T, t, j) >= 0 || !cvm__tri2_in_domain(T, u) ||
        (T->ta && T->ta[t] != T->ta[u]))
        return 0;
    l = 0.5 * (vsize[a] + vsize[b]);
    d = hypot(Vt[0] - Vu[0], Vt[1] - Vu[1]);
    return d < tol * l / sqrt(3.0);
}

int cvm__dual_tri_compliance(const cvm__tri2 *T, const double *vsize, double tol, const double *V,
                             int32_t t)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    int k, out = CVM__DUAL_INSIDE;
    for (k = 0; k < 3; k++) {
        int32_t a = v[(k + 1) % 3], b = v[(k + 2) % 3], c = v[k];
        if (cvm__power_side2d(pt(T, a), pt(T, b), pt(T, c), weight(T, a), weight(T, b),
                              weight(T, c)) >= 0)
            continue;
        /* beyond edge k (opposite c) */
        if (!cvm__dual_edge_mergeable(T, vsize, tol, t, k, V + 2 * (size_t)t,
                                      V + 2 * (size_t)(T->tn[3 * (size_t)t + (size_t)k] / 3)))
            return CVM__DUAL_NONCOMPLIANT;
        out = CVM__DUAL_MERGED;
    }
    return out;
}

static int32_t find(int32_t *g, int32_t x)
{
    while (g[x] != x) {
        g[x] = g[g[x]];
        x = g[x];
    }
    return x;
}

cvm_status cvm__dual_merge_groups(cvm__ctx *ctx, const cvm__tri2 *T, const double *vsize, double tol,
                                  const double *V, int32_t *group)
{
    size_t t;
    int j;
    (void)ctx;
    for (t = 0; t < T->nt; t++)
        group[t] = cvm__tri2_in_domain(T, (int32_t)t) ? (int32_t)t : -1;
    for (t = 0; t < T->nt; t++) {
        if (group[t] < 0)
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * t + (size_t)j] / 3, ru, rt;
            if ((size_t)u <= t ||
                !cvm__dual_edge_mergeable(T, vsize, tol, (int32_t)t, j, V + 2 * t, V + 2 * (size_t)u))
                continue;
            rt = find(group, (int32_t)t);
            ru = find(group, u);
            /* the smaller slot is the root, so the root is the group's smallest slot */
            if (rt < ru)
                group[ru] = rt;
            else if (ru < rt)
                group[rt] = ru;
        }
    }
    for (t = 0; t < T->nt; t++)
        if (group[t] >= 0)
            group[t] = find(group, (int32_t)t);
    return CVM_OK;
}
