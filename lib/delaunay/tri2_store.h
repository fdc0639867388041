/* tri2_store.h - slot management of cvm__tri2 shared by the kernel's files. */
#ifndef CVM_TRI2_STORE_H
#define CVM_TRI2_STORE_H

#include "delaunay_internal.h"

/* Make room for need triangle slots (tv, tn, tf, te, ta grow together). */
cvm_status cvm__tri2_reserve_triangles(cvm__tri2 *T, size_t need);
/* Take a slot (from the free list first); room must have been reserved.
 * Flags are cleared and te set to -1; tv, tn and ta are left to the caller. */
int32_t cvm__tri2_new(cvm__tri2 *T);
/* Return slot t to the free list. */
void cvm__tri2_kill(cvm__tri2 *T, int32_t t);

/* Flip edge j of t (unconstrained, both sides real, convex quad): t = (v, a, b)
 * with neighbour u = (w, b, a) becomes t = (v, a, w), u = (w, b, v). */
void cvm__tri2_flip(cvm__tri2 *T, int32_t t, int j);
/* Lawson flips around the stars of verts until locally (constrained) Delaunay. */
cvm_status cvm__tri2_legalize_stars(cvm__tri2 *T, const int32_t *verts, size_t nverts);

/* Link edge j of t and edge k of u as the same edge. */
static inline void cvm__tri2_link(cvm__tri2 *T, int32_t t, int j, int32_t u, int k)
{
    T->tn[3 * (size_t)t + j] = 3 * u + k;
    T->tn[3 * (size_t)u + k] = 3 * t + j;
}

static inline const double *cvm__tri2_pt(const cvm__tri2 *T, int32_t v)
{
    return T->xy + 2 * (size_t)v;
}

#endif
