/* flip.c - edge flips and Lawson legalisation of the 2D triangulation. */
#include "delaunay_internal.h"
#include "tri2_store.h"
#include "geom/geom_internal.h"

/* Flip edge j of t (not constrained, both sides real). t = (v, a, b), the
 * neighbour u = (w, b, a) across it; afterwards t = (v, a, w), u = (w, b, v). */
void cvm__tri2_flip(cvm__tri2 *T, int32_t t, int j)
{
    size_t t3 = 3 * (size_t)t;
    int32_t h = T->tn[t3 + j], u = h / 3, k = h % 3;
    size_t u3 = 3 * (size_t)u;
    int32_t v = T->tv[t3 + j], a = T->tv[t3 + (j + 1) % 3], b = T->tv[t3 + (j + 2) % 3];
    int32_t w = T->tv[u3 + k];
    int32_t n1 = T->tn[t3 + (j + 1) % 3], n2 = T->tn[t3 + (j + 2) % 3];
    int32_t n3 = T->tn[u3 + (k + 1) % 3], n4 = T->tn[u3 + (k + 2) % 3];
    int32_t e1 = -1, e2 = -1, e3 = -1, e4 = -1;
    if (T->te) {
        e1 = T->te[t3 + (j + 1) % 3];
        e2 = T->te[t3 + (j + 2) % 3];
        e3 = T->te[u3 + (k + 1) % 3];
        e4 = T->te[u3 + (k + 2) % 3];
    }
    T->tv[t3] = v, T->tv[t3 + 1] = a, T->tv[t3 + 2] = w;
    T->tv[u3] = w, T->tv[u3 + 1] = b, T->tv[u3 + 2] = v;
    /* t: opp v (a,w) <- n3; opp a (w,v) <- u; opp w (v,a) <- n2 */
    T->tn[t3] = n3, T->tn[n3] = (int32_t)t3;
    T->tn[t3 + 2] = n2, T->tn[n2] = (int32_t)t3 + 2;
    /* u: opp w (b,v) <- n1; opp b (v,w) <- t; opp v (w,b) <- n4 */
    T->tn[u3] = n1, T->tn[n1] = (int32_t)u3;
    T->tn[u3 + 2] = n4, T->tn[n4] = (int32_t)u3 + 2;
    T->tn[t3 + 1] = (int32_t)u3 + 1, T->tn[u3 + 1] = (int32_t)t3 + 1;
    if (T->te) {
        T->te[t3] = e3, T->te[t3 + 1] = -1, T->te[t3 + 2] = e2;
        T->te[u3] = e1, T->te[u3 + 1] = -1, T->te[u3 + 2] = e4;
    }
    if (v >= 0)
        T->vtri[v] = t;
    if (a >= 0)
        T->vtri[a] = t;
    if (w >= 0)
        T->vtri[w] = u;
    if (b >= 0)
        T->vtri[b] = u;
}

static cvm_status push_edge(cvm__tri2 *T, size_t *n, int32_t h)
{
    if (*n + 1 > T->cap_stack &&
        cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, *n + 1, sizeof(int32_t)))
        return CVM_E_NOMEM;
    T->stack[(*n)++] = h;
    return CVM_OK;
}

/* Lawson flips, seeded with every edge of the triangles around the given
 * vertices, until each unconstrained edge between two real triangles there is
 * locally (constrained) Delaunay by the exact in-circle test. Flipping a valid
 * triangulation this way always converges; a flipped quad's four outer edges
 * are checked again. */
cvm_status cvm__tri2_legalize_stars(cvm__tri2 *T, const int32_t *verts, size_t nverts)
{
    size_t n = 0, q;
    int32_t t;
    cvm_status s;
    for (q = 0; q < nverts; q++) {
        int32_t p = verts[q], t0 = p >= 0 ? T->vtri[p] : -1;
        if (t0 < 0)
            continue;
        t = t0;
        do {
            const int32_t *v = T->tv + 3 * (size_t)t;
            int i = v[0] == p ? 0 : v[1] == p ? 1 : 2, j;
            for (j = 0; j < 3; j++)
                if ((s = push_edge(T, &n, 3 * t + j)))
                    return s;
            t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
        } while (t != t0);
    }
    while (n) {
        int32_t h = T->stack[--n], u, k, w;
        int j = h % 3;
        const int32_t *v;
        t = h / 3;
        v = T->tv + 3 * (size_t)t;
        if (!cvm__tri2_is_live(T, t) || cvm__tri2_is_ghost(T, t) || (T->te && T->te[h] >= 0))
            continue;
        u = T->tn[h] / 3;
        k = T->tn[h] % 3;
        if (cvm__tri2_is_ghost(T, u) || (T->tf[u] & CVM__TF_OUT) != (T->tf[t] & CVM__TF_OUT))
            continue;
        w = T->tv[3 * (size_t)u + k];
        if (cvm__tri2_conflict(T, t, w) <= 0)
            continue;
        {
            const double *pv = cvm__tri2_pt(T, v[j]), *pa = cvm__tri2_pt(T, v[(j + 1) % 3]),
                         *pb = cvm__tri2_pt(T, v[(j + 2) % 3]), *pw = cvm__tri2_pt(T, w);
            if (cvm__orient2d(pv, pa, pw) <= 0 || cvm__orient2d(pw, pb, pv) <= 0)
                continue;
        }
        cvm__tri2_flip(T, t, j);
        /* t = (v, a, w), u = (w, b, v): outer edges are t's 0 and 2, u's 0 and 2 */
        if ((s = push_edge(T, &n, 3 * t)) || (s = push_edge(T, &n, 3 * t + 2)) ||
            (s = push_edge(T, &n, 3 * u)) || (s = push_edge(T, &n, 3 * u + 2)))
            return s;
    }
    return CVM_OK;
}

