/* conflict.c - the exact in-circle / power conflict test of a vertex against a triangle. */
#include "delaunay_internal.h"
#include "tri2_store.h"
#include "geom/geom_internal.h"

/* Position of the ghost vertex in t, or -1. */
static int ghost_pos(const int32_t *v)
{
    return v[0] == CVM__GHOST ? 0 : v[1] == CVM__GHOST ? 1 : v[2] == CVM__GHOST ? 2 : -1;
}

int cvm__tri2_conflict(const cvm__tri2 *T, int32_t t, int32_t p)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    const double *pp = cvm__tri2_pt(T, p);
    int g = ghost_pos(v);
    if (g >= 0) {
        /* ghost (a, b, G) counter-clockwise: the outside of hull edge a->b is on its left */
        int32_t a = v[(g + 1) % 3], b = v[(g + 2) % 3];
        const double *pa = cvm__tri2_pt(T, a), *pb = cvm__tri2_pt(T, b);
        double o = cvm__orient2d(pa, pb, pp);
        if (o != 0)
            return o > 0 ? 1 : -1;
        /* on the hull line: in conflict when strictly between a and b */
        if (pa[0] != pb[0])
            return ((pp[0] > pa[0]) == (pp[0] < pb[0])) && pp[0] != pa[0] && pp[0] != pb[0] ? 1 : -1;
        return ((pp[1] > pa[1]) == (pp[1] < pb[1])) && pp[1] != pa[1] && pp[1] != pb[1] ? 1 : -1;
    }
    if (T->w)
        return cvm__power2d_sos(cvm__tri2_pt(T, v[0]), cvm__tri2_pt(T, v[1]), cvm__tri2_pt(T, v[2]),
                                pp, T->w[v[0]], T->w[v[1]], T->w[v[2]], T->w[p], v[0], v[1], v[2],
                                p);
    return cvm__incircle_sos(cvm__tri2_pt(T, v[0]), cvm__tri2_pt(T, v[1]), cvm__tri2_pt(T, v[2]), pp,
                             v[0], v[1], v[2], p);
}
