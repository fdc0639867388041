/* conflict3.h - the in-sphere / power conflict tests and the Bowyer-Watson cavity search, inlined into the serial (insert3.c) and the parallel (parallel3.c) insertion. */
#ifndef CVM_DELAUNAY3_CONFLICT3_H
#define CVM_DELAUNAY3_CONFLICT3_H

#include <string.h>

#include "common/common_internal.h"
#include "delaunay3/delaunay3_internal.h"
#include "geom/geom_internal.h"

#if defined(__GNUC__)
#define CVM__T3_HOT inline __attribute__((always_inline))
#define CVM__T3_PREFETCH(p) __builtin_prefetch(p)
#else
#define CVM__T3_HOT inline
#define CVM__T3_PREFETCH(p) ((void)(p))
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

/* Parallel insertion: does the thread of partition me own the tetrahedron
 * across slot s of one it owns? The three vertices of the shared face are
 * its own, so only the vertex facing it is left to test. */
static CVM__T3_HOT int cvm__t3_owned_across(const int32_t *tt, int32_t s, const uint8_t *part,
                                            uint8_t me)
{
    int32_t x = tt[8 * (size_t)(s >> 2) + (s & 3)];
    return x == CVM__T3_GHOST || part[x] == me;
}

/* Conflict of p with slot u (vertices vu): 1 or 0; pt is T->pt and e p's
 * coordinates, used on the plain path only (held by the caller so that its
 * mark stores do not force reloads; elsewhere they would only be spilled). A ghost tetrahedron
 * conflicts when p lies strictly beyond its hull face, or in the face's plane
 * and in conflict with the finite tetrahedron behind the face (the limit of a
 * far-away apex). -1 only when !mine and the answer would need that finite
 * neighbour's mark, a word the caller does not own. plain: an unweighted store
 * without the small-integer path, where a finite tetrahedron needs only insphere. */
static CVM__T3_HOT int cvm__t3_conflict(const cvm__tet3 *T, const cvm__t3_point *pt,
                                        const double *e, const int32_t *vu, int32_t u,
                                        int32_t p, int mine, int plain)
{
    double o;
    int32_t n;
    if (vu[3] != CVM__T3_GHOST) {
        if (plain) {
            const int32_t *oi = T->orig;
            double det =
                cvm__insphere_inline(pt[vu[0]].x, pt[vu[1]].x, pt[vu[2]].x, pt[vu[3]].x, e);
            if (det != 0.0)
                return det > 0.0;
            return cvm__insphere_sos(pt[vu[0]].x, pt[vu[1]].x, pt[vu[2]].x, pt[vu[3]].x, e,
                                     oi[vu[0]], oi[vu[1]], oi[vu[2]], oi[vu[3]], oi[p])
                   > 0;
        }
        return cvm__t3_finite_conflict(T, vu, p);
    }
    if (!plain)
        pt = T->pt, e = pt[p].x;
    o = cvm__t3_orient(T, pt[vu[0]].x, pt[vu[1]].x, pt[vu[2]].x, e);
    if (o != 0.0)
        return o > 0.0;
    if (!mine)
        return -1;
    n = CVM__T3_TN(T, 4 * (size_t)u + 3) >> 2;
    if (T->tmark[n]) /* parallel: only owned tetrahedra are ever marked, by their owner */
        return T->tmark[n] == 1;
    return cvm__t3_finite_conflict(T, T->tt + 8 * (size_t)n, p);
}

/* Clear the marks of a cavity that will not be filled: dead[0..nd), and the
 * outside of bf[0..nb) where set (a parallel thread writes owned marks only). */
static inline void cvm__t3_unmark_cavity(cvm__tet3 *T, size_t nd, size_t nb)
{
    size_t i;
    for (i = 0; i < nd; i++)
        T->tmark[T->dead[i]] = 0;
    for (i = 0; i < nb; i++)
        if (T->tmark[T->bf[i].out >> 2])
            T->tmark[T->bf[i].out >> 2] = 0;
}

/* The faces of a tetrahedron other than face g, in increasing order. */
static const uint8_t cvm__t3_other3[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };

/* The Bowyer-Watson cavity of p grown from t0 across faces: the tetrahedra in
 * conflict into dead[] (marked 1), the faces where the growth stopped into
 * bf[] (their outside marked 2), T->ndead and T->nbf set. Returns 1.
 * Serial (part NULL): dead[] and bf[] grow as needed; -1 (CVM_E_NOMEM, marks
 * cleared) when they cannot. Parallel (part: the partition of every vertex,
 * me the caller's): only tetrahedra owned by me are marked or dug; 0, marks
 * cleared, when the cavity reaches one it does not own that is in conflict
 * (or might be), or outgrows the fixed dead[] / bf[]. Inlined with constant
 * part and plain, each caller gets its own loop. The store's arrays are read
 * through local copies: the byte stores of the marks would otherwise make the
 * compiler reload every field of T.
 * Branches the processor cannot predict cost more here than the arithmetic:
 * while digging, dead[i > 0] holds the slot through which tetrahedron i was
 * reached (4 u + g, g its face towards the one that dug it), so face g (in the
 * cavity) is not visited again, and a tested face writes both its possible
 * records and keeps one by advancing a counter, without a branch on the test.
 * The order of dead[] and bf[] is that of the plain breadth-first search. */
static CVM__T3_HOT int cvm__t3_dig(cvm__tet3 *T, int32_t t0, int32_t p, int plain,
                                   const uint8_t *part, uint8_t me)
{
    const cvm__t3_point *pt = T->pt;
    const double *e = pt[p].x;
    int32_t *tt = T->tt, *dead = T->dead;
    uint8_t *tm = T->tmark;
    cvm__t3_bface *bf = T->bf;
    size_t nd = 0, head = 1, nb = 0, deadcap = T->deadcap, bfcap = T->bfcap, i;
    int f, k, r = 0;
/* Room for one more item in dead[] or bf[]: grown (serial), or give up (parallel). */
#define CVM__T3_DIG_ROOM(arr, cnt, capv)                                                        \
    do {                                                                                       \
        if ((cnt) == (capv)) {                                                                 \
            if (part                                                                           \
                || cvm__grow(T->ctx, (void **)&T->arr, &T->capv, (cnt) + 1, sizeof *T->arr)    \
                       != CVM_OK) {                                                            \
                r = part ? 0 : -1;                                                             \
                goto fail;                                                                     \
            }                                                                                  \
            arr = T->arr, capv = T->capv;                                                      \
        }                                                                                      \
    } while (0)
/* Test the tetrahedron across face fc of c (vertices and neighbours vc) and file
 * it: into dead[] (as the slot 4 u + g reaching it) or, as a boundary face, into bf[]. */
#define CVM__T3_DIG_VISIT(vc, fc)                                                                \
    do {                                                                                       \
        int32_t s = (vc)[4 + (fc)], u = s >> 2;                                                 \
        const int32_t *vu = tt + 8 * (size_t)u;                                                \
        int mine = part ? cvm__t3_owned_across(tt, s, part, me) : 1, in, g;                    \
        uint8_t mu = mine ? tm[u] : 0;                                                         \
        cvm__t3_bface *b;                                                                      \
        if (mu == 1)                                                                           \
            break;                                                                             \
        in = mu == 2 ? 0 : cvm__t3_conflict(T, pt, e, vu, u, p, mine, plain);                  \
        if (part && in && (!mine || in < 0))                                                   \
            goto fail;                                                                         \
        if (mu != 2 && nd < deadcap && nb < bfcap) { /* both records written, one kept */      \
            for (g = 0; g < 4; g++)                                                            \
                CVM__T3_PREFETCH(tt + 8 * (size_t)(vu[4 + g] >> 2));                           \
            dead[nd] = s;                                                                      \
            b = &bf[nb];                                                                       \
            memcpy(b->v, (vc), sizeof b->v);                                                   \
            b->v[fc] = p;                                                                       \
            b->f = (fc);                                                                        \
            b->out = s;                                                                        \
            if (!part || mine)                                                                 \
                tm[u] = (uint8_t)(2 - in);                                                     \
            nd += (size_t)in;                                                                  \
            nb += (size_t)(1 - in);                                                            \
        } else if (in) {                                                                       \
            CVM__T3_DIG_ROOM(dead, nd, deadcap);                                               \
            tm[u] = 1;                                                                         \
            dead[nd++] = s;                                                                    \
        } else {                                                                               \
            CVM__T3_DIG_ROOM(bf, nb, bfcap);                                                   \
            if (mine)                                                                          \
                tm[u] = 2;                                                                     \
            b = &bf[nb++];                                                                     \
            b->v[0] = (vc)[0], b->v[1] = (vc)[1], b->v[2] = (vc)[2], b->v[3] = (vc)[3];        \
            b->v[fc] = p;                                                                       \
            b->f = (fc);                                                                        \
            b->out = s;                                                                        \
        }                                                                                      \
    } while (0)
    CVM__T3_DIG_ROOM(dead, nd, deadcap);
    tm[t0] = 1;
    dead[nd++] = t0;
    for (f = 0; f < 4; f++) {
        int32_t u = tt[8 * (size_t)t0 + 4 + f] >> 2;
        CVM__T3_PREFETCH(tt + 8 * (size_t)u);
        CVM__T3_PREFETCH(tm + u);
    }
    for (f = 0; f < 4; f++)
        CVM__T3_DIG_VISIT(tt + 8 * (size_t)t0, f);
    /* breadth first, dead[] is the queue: a tetrahedron's neighbours are
     * prefetched when it joins, and used only after everything queued before it */
    while (head < nd) {
        int32_t sc = dead[head++];
        const int32_t *vc = tt + 8 * (size_t)(sc >> 2);
        const uint8_t *other = cvm__t3_other3[sc & 3];
        for (k = 0; k < 3; k++)
            CVM__T3_DIG_VISIT(vc, other[k]);
    }
#undef CVM__T3_DIG_VISIT
#undef CVM__T3_DIG_ROOM
    for (i = 1; i < nd; i++)
        dead[i] >>= 2;
    T->ndead = nd;
    T->nbf = nb;
    return 1;
fail:
    for (i = 1; i < nd; i++)
        dead[i] >>= 2;
    cvm__t3_unmark_cavity(T, nd, nb);
    T->ndead = T->nbf = 0;
    return r;
}

#endif
