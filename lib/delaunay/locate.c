/* locate.c - point location by a remembering stochastic visibility walk (Devillers, Pion, Teillaud 2002). */
#include "delaunay_internal.h"
#include "tri2_store.h"
#include "geom/geom_internal.h"

/* Any live triangle, preferring T->last. */
static int32_t any_live(const cvm__tri2 *T, int32_t start)
{
    size_t t;
    if (start >= 0 && (size_t)start < T->nt && cvm__tri2_is_live(T, start))
        return start;
    if (T->last >= 0 && (size_t)T->last < T->nt && cvm__tri2_is_live(T, T->last))
        return T->last;
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_is_live(T, (int32_t)t))
            return (int32_t)t;
    return -1;
}

cvm__loc cvm__tri2_locate(cvm__tri2 *T, const double *p, int32_t start, int32_t *t_out,
                          int *j_out)
{
    int32_t t = any_live(T, start), prev = -1;
    uint32_t rnd = 0x9E3779B9u ^ (uint32_t)t;
    double o[3];
    int j, k, zeros, zj = 0;

    *j_out = 0;
    if (t < 0) {
        *t_out = -1;
        return CVM__LOC_OUTSIDE;
    }
    if (cvm__tri2_is_ghost(T, t)) {
        /* step to the real neighbour across the hull edge */
        const int32_t *v = T->tv + 3 * (size_t)t;
        j = v[0] == CVM__GHOST ? 0 : v[1] == CVM__GHOST ? 1 : 2;
        t = T->tn[3 * (size_t)t + j] / 3;
    }
    for (;;) {
        const int32_t *v = T->tv + 3 * (size_t)t;
        int moved = 0;
        if (cvm__tri2_is_ghost(T, t)) {
            *t_out = t;
            return CVM__LOC_OUTSIDE;
        }
        rnd = rnd * 1664525u + 1013904223u;
        j = (int)((rnd >> 16) % 3u);
        for (k = 0; k < 3; k++, j = j == 2 ? 0 : j + 1) {
            int32_t nb = T->tn[3 * (size_t)t + j] / 3;
            if (nb == prev)
                continue;
            if (cvm__orient2d_inline(cvm__tri2_pt(T, v[(j + 1) % 3]), cvm__tri2_pt(T, v[(j + 2) % 3]), p) < 0) {
                prev = t;
                t = nb;
                moved = 1;
                break;
            }
        }
        if (!moved)
            break;
    }
    /* p lies in the closed triangle t: classify */
    {
        const int32_t *v = T->tv + 3 * (size_t)t;
        zeros = 0;
        for (j = 0; j < 3; j++) {
            o[j] = cvm__orient2d(cvm__tri2_pt(T, v[(j + 1) % 3]), cvm__tri2_pt(T, v[(j + 2) % 3]), p);
            if (o[j] == 0) {
                zeros++;
                zj = j;
            }
        }
        *t_out = t;
        T->last = t;
        if (zeros == 0)
            return CVM__LOC_INSIDE;
        if (zeros == 1) {
            *j_out = zj;
            return CVM__LOC_EDGE;
        }
        /* two zero edges meet at the vertex opposite the non-zero one */
        for (j = 0; j < 3; j++)
            if (o[j] != 0)
                *j_out = j;
        return CVM__LOC_VERTEX;
    }
}
