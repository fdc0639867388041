/* conflict3.h - the in-sphere / power conflict test of a point with a finite tetrahedron, inlined into the serial and the parallel cavity search. */
#ifndef CVM_DELAUNAY3_CONFLICT3_H
#define CVM_DELAUNAY3_CONFLICT3_H

#include "delaunay3/delaunay3_internal.h"
#include "geom/geom_internal.h"

#if defined(__GNUC__)
#define CVM__T3_HOT inline __attribute__((always_inline))
#else
#define CVM__T3_HOT inline
#endif

/* Is p in conflict with the finite tetrahedron of vertices v (circumsphere /
 * orthosphere strictly containing p after symbolic perturbation)? */
static CVM__T3_HOT int cvm__t3_finite_conflict(const cvm__tet3 *T, const int32_t *v, int32_t p)
{
    const double *a = T->pt[v[0]].x, *b = T->pt[v[1]].x, *c = T->pt[v[2]].x, *d = T->pt[v[3]].x;
    const double *e = T->pt[p].x;
    const int32_t *o = T->orig;
    if (T->small_int) { /* lattices: exact in doubles, ties straight to the perturbation */
        double perm, det = cvm__insphere_fp(a, b, c, d, e, &perm);
        if (det != 0.0)
            return det > 0.0;
        return cvm__sos3d_tie(a, b, c, d, e, o[v[0]], o[v[1]], o[v[2]], o[v[3]], o[p], 1) > 0;
    }
    if (!T->w) {
        double det = cvm__insphere_inline(a, b, c, d, e);
        if (det != 0.0)
            return det > 0.0;
        return cvm__insphere_sos(a, b, c, d, e, o[v[0]], o[v[1]], o[v[2]], o[v[3]], o[p]) > 0;
    }
    return cvm__power3d_sos(a, b, c, d, e, T->w[v[0]], T->w[v[1]], T->w[v[2]], T->w[v[3]],
                            T->w[p], o[v[0]], o[v[1]], o[v[2]], o[v[3]], o[p])
           > 0;
}

/* orient3d(a, b, c, d), in plain doubles where T->small_int makes them exact. */
static CVM__T3_HOT double cvm__t3_orient(const cvm__tet3 *T, const double *a, const double *b,
                                         const double *c, const double *d)
{
    return T->small_int ? cvm__orient3d_fp(a, b, c, d) : cvm__orient3d_inline(a, b, c, d);
}

#endif
