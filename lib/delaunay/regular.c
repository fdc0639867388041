/* regular.c - restore the regular (weighted Delaunay) property of a triangulation by exact power-test flips. */
#include <string.h>

#include "delaunay_internal.h"
#include "tri2_store.h"
#include "geom/geom_internal.h"

/*
 * Edge j of live real triangle t is "flip-candidate" when it is not
 * constrained, its neighbour u is a live real triangle with the same domain
 * flag and regional attribute (so a flip never moves the domain boundary or a
 * region border), and the apex d of u conflicts with t: the exact power test
 * (in-circle without weights) with symbolic perturbation by index, the test
 * of cvm__tri2_conflict(). Writes the quad c, e1, d, e2 (counter-clockwise;
 * c apex of t, e1-e2 the shared edge) into q.
 */
static int illegal(const cvm__tri2 *T, int32_t t, int j, int32_t *q)
{
    size_t h = 3 * (size_t)t + (size_t)j;
    int32_t u, k;
    if (!cvm__tri2_is_live(T, t) || cvm__tri2_is_ghost(T, t) || cvm__tri2_edge_seg(T, t, j) >= 0)
        return 0;
    u = T->tn[h] / 3;
    k = T->tn[h] % 3;
    if (cvm__tri2_is_ghost(T, u) || ((T->tf[t] ^ T->tf[u]) & CVM__TF_OUT) ||
        (T->ta && T->ta[t] != T->ta[u]))
        return 0;
    q[0] = T->tv[h];
    q[1] = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3];
    q[2] = T->tv[3 * (size_t)u + (size_t)k];
    q[3] = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
    return cvm__tri2_conflict(T, t, q[2]) > 0;
}

/* The vertex of an illegal edge's quad that blocks its flip (reflex or flat
 * corner e1 or e2), or -1 when the quad is strictly convex. */
static int32_t blocker(const cvm__tri2 *T, const int32_t *q)
{
    const double *c = cvm__tri2_pt(T, q[0]), *d = cvm__tri2_pt(T, q[2]);
    if (cvm__orient2d(c, d, cvm__tri2_pt(T, q[1])) >= 0)
        return q[1];
    if (cvm__orient2d(c, d, cvm__tri2_pt(T, q[3])) <= 0)
        return q[3];
    return -1;
}

/* Flip edge j of t (quad q): t becomes (c, e1, d), u becomes (d, e2, c). */
static void flip(cvm__tri2 *T, int32_t t, int j, const int32_t *q)
{
    size_t h = 3 * (size_t)t + (size_t)j;
    int32_t u = T->tn[h] / 3, k = T->tn[h] % 3;
    size_t t3 = 3 * (size_t)t, u3 = 3 * (size_t)u;
    int32_t n_e2c = T->tn[t3 + (size_t)(j + 1) % 3], n_ce1 = T->tn[t3 + (size_t)(j + 2) % 3];
    int32_t n_e1d = T->tn[u3 + (size_t)(k + 1) % 3], n_de2 = T->tn[u3 + (size_t)(k + 2) % 3];
    int32_t s_e2c = -1, s_ce1 = -1, s_e1d = -1, s_de2 = -1;
    if (T->te) {
        s_e2c = T->te[t3 + (size_t)(j + 1) % 3];
        s_ce1 = T->te[t3 + (size_t)(j + 2) % 3];
        s_e1d = T->te[u3 + (size_t)(k + 1) % 3];
        s_de2 = T->te[u3 + (size_t)(k + 2) % 3];
    }
    T->tv[t3] = q[0];
    T->tv[t3 + 1] = q[1];
    T->tv[t3 + 2] = q[2];
    T->tv[u3] = q[2];
    T->tv[u3 + 1] = q[3];
    T->tv[u3 + 2] = q[0];
    T->tn[t3] = n_e1d;
    T->tn[n_e1d] = (int32_t)t3;
    T->tn[t3 + 2] = n_ce1;
    T->tn[n_ce1] = (int32_t)(t3 + 2);
    T->tn[u3] = n_e2c;
    T->tn[n_e2c] = (int32_t)u3;
    T->tn[u3 + 2] = n_de2;
    T->tn[n_de2] = (int32_t)(u3 + 2);
    cvm__tri2_link(T, t, 1, u, 1);
    if (T->te) {
        T->te[t3] = s_e1d;
        T->te[t3 + 1] = -1;
        T->te[t3 + 2] = s_ce1;
        T->te[u3] = s_e2c;
        T->te[u3 + 1] = -1;
        T->te[u3 + 2] = s_de2;
    }
    T->vtri[q[0]] = t;
    T->vtri[q[1]] = t;
    T->vtri[q[2]] = u;
    T->vtri[q[3]] = u;
    T->last = t;
}

cvm_status cvm__tri2_make_regular(cvm__tri2 *T, size_t *nflips_out)
{
    return cvm__tri2_make_regular_count(T, nflips_out, NULL);
}

cvm_status cvm__tri2_make_regular_count(cvm__tri2 *T, size_t *nflips_out, size_t *ndomain_out)
{
    size_t nh = 3 * T->nt, n = 0, h, nflips = 0, ndomain = 0;
    uint8_t *queued;
    if (nflips_out)
        *nflips_out = 0;
    if (ndomain_out)
        *ndomain_out = 0;
    if (nh > T->cap_stack && cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, nh, sizeof(int32_t)))
        return CVM_E_NOMEM;
    queued = cvm__calloc(T->ctx, nh + 1, 1);
    if (!queued)
        return CVM_E_NOMEM;
    /* Every half-edge is queued at most once at a time, so nh entries suffice. */
    for (h = nh; h-- > 0;) {
        T->stack[n++] = (int32_t)h;
        queued[h] = 1;
    }
    while (n) {
        int32_t he = T->stack[--n], t = he / 3, q[4];
        int j = he % 3, i;
        queued[he] = 0;
        if (!illegal(T, t, j, q) || blocker(T, q) >= 0)
            continue;
        {
            int32_t u = T->tn[he] / 3;
            int32_t outer[4];
            ndomain += !(T->tf[t] & CVM__TF_OUT);
            flip(T, t, j, q);
            outer[0] = 3 * t;
            outer[1] = 3 * t + 2;
            outer[2] = 3 * u;
            outer[3] = 3 * u + 2;
            for (i = 0; i < 4; i++)
                if (!queued[outer[i]]) {
                    queued[outer[i]] = 1;
                    T->stack[n++] = outer[i];
                }
        }
        nflips++;
    }
    cvm__free(T->ctx, queued);
    if (nflips_out)
        *nflips_out = nflips;
    if (ndomain_out)
        *ndomain_out = ndomain;
    return CVM_OK;
}

size_t cvm__tri2_count_unregular(const cvm__tri2 *T, uint8_t *mark)
{
    size_t t, v, count = 0;
    int j;
    memset(mark, 0, T->nv);
    for (t = 0; t < T->nt; t++)
        for (j = 0; j < 3; j++) {
            int32_t q[4], b;
            if (illegal(T, (int32_t)t, j, q) && (b = blocker(T, q)) >= 0)
                mark[b] = 1;
        }
    for (v = 0; v < T->nv; v++)
        count += mark[v] || (T->w && T->vtri[v] < 0);
    return count;
}
