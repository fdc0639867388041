/* insert3.c - insertion of one point: visibility walk, Bowyer-Watson cavity by the exact in-sphere/power test, re-triangulation of its boundary. */
#include <string.h>

#include "delaunay3/delaunay3_internal.h"
#include "delaunay3/conflict3.h"
#include "geom/geom_internal.h"

#define PT(T, v) ((T)->pt[v].x)

/* walk_pick[f0][m]: the first face f in the order f0, f0 + 1, ... (mod 4) with
 * bit f set in m; 4 when m is 0. */
static const uint8_t walk_pick[4][16] = {
    { 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0 },
    { 4, 0, 1, 1, 2, 2, 1, 1, 3, 3, 1, 1, 2, 2, 1, 1 },
    { 4, 0, 1, 0, 2, 2, 2, 2, 3, 3, 3, 3, 2, 2, 2, 2 },
    { 4, 0, 1, 0, 2, 0, 1, 0, 3, 3, 3, 3, 3, 3, 3, 3 }
};

/* Visibility walk from T->last to a tetrahedron whose closure holds p, or to
 * a ghost tetrahedron whose hull face p lies strictly beyond. Faces are tried
 * from a pseudo-random first one (xorshift in the store: deterministic, no
 * global state), which makes the walk terminate. The four sides are tested
 * together (cvm__orient3d_sides) and the face is picked from a table: a
 * branch on each test would be mispredicted about once a step. The face just
 * crossed needs no exclusion: p is exactly on its positive side. */
static int32_t locate(cvm__tet3 *T, int32_t p)
{
    const double *pp = PT(T, p);
    int32_t t = T->last;
    uint64_t r = T->walk;
    for (;;) {
        const int32_t *v = T->tt + 8 * (size_t)t;
        const double *a, *b, *c, *d;
        unsigned m;
        int f;
        if (v[3] == CVM__T3_GHOST)
            break;
        a = PT(T, v[0]), b = PT(T, v[1]), c = PT(T, v[2]), d = PT(T, v[3]);
        CVM__T3_PREFETCH(T->tt + 8 * (size_t)(v[4] >> 2));
        CVM__T3_PREFETCH(T->tt + 8 * (size_t)(v[5] >> 2));
        CVM__T3_PREFETCH(T->tt + 8 * (size_t)(v[6] >> 2));
        CVM__T3_PREFETCH(T->tt + 8 * (size_t)(v[7] >> 2));
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        if (T->small_int)
            m = (unsigned)(cvm__orient3d_fp(pp, b, c, d) < 0.0)
                | (unsigned)(cvm__orient3d_fp(a, pp, c, d) < 0.0) << 1
                | (unsigned)(cvm__orient3d_fp(a, b, pp, d) < 0.0) << 2
                | (unsigned)(cvm__orient3d_fp(a, b, c, pp) < 0.0) << 3;
        else
            m = cvm__orient3d_sides(a, b, c, d, pp);
        f = walk_pick[r >> 62][m];
        if (f == 4)
            break;
        t = CVM__T3_TN(T, 4 * (size_t)t + (size_t)f) >> 2;
    }
    T->walk = r;
    return t;
}

/* Undo the marks of a cavity that will not be committed. */
static void unmark(cvm__tet3 *T)
{
    cvm__t3_unmark_cavity(T, T->ndead, T->nbf);
}

/* Grow-on-demand pushes of the cavity search; CVM_E_NOMEM on failure. */
#define PUSH(arr, cnt, capv, val)                                                              \
    do {                                                                                       \
        if ((cnt) == (capv)                                                                    \
            && cvm__grow(T->ctx, (void **)&(arr), &(capv), (cnt) + 1, sizeof *(arr)) != CVM_OK) \
            goto nomem;                                                                        \
        (arr)[(cnt)++] = (val);                                                                \
    } while (0)

/* The cavity of p grown from t0 (cvm__t3_dig, conflict3.h): CVM_OK or CVM_E_NOMEM. */
static cvm_status dig_cavity(cvm__tet3 *T, int32_t t0, int32_t p)
{
    int ok = T->w || T->small_int ? cvm__t3_dig(T, t0, p, 0, NULL, 0)
                                   : cvm__t3_dig(T, t0, p, 1, NULL, 0);
    return ok > 0 ? CVM_OK : CVM_E_NOMEM;
}

void cvm__tet3_mark_vanished(cvm__tet3 *T, int32_t p)
{
    uint32_t cur;
    size_t i;
    int k;
    if (++T->vstamp == 0) { /* wrapped: forget every old mark */
        memset(T->vseen, 0, T->np * sizeof *T->vseen);
        memset(T->vkeep, 0, T->np * sizeof *T->vkeep);
        T->vstamp = 1;
    }
    cur = T->vstamp;
    for (i = 0; i < T->ndead; i++)
        for (k = 0; k < 4; k++) {
            int32_t v = T->tt[8 * (size_t)T->dead[i] + k];
            if (v >= 0)
                T->vseen[v] = cur;
        }
    for (i = 0; i < T->nbf; i++)
        for (k = 0; k < 4; k++)
            if (T->bf[i].v[k] >= 0)
                T->vkeep[T->bf[i].v[k]] = cur;
    for (i = 0; i < T->ndead; i++)
        for (k = 0; k < 4; k++) {
            int32_t v = T->tt[8 * (size_t)T->dead[i] + k];
            if (v >= 0 && v != p && T->vkeep[v] != cur && T->fate[v] == CVM__T3_VERTEX)
                T->fate[v] = CVM__T3_REDUNDANT;
        }
}

cvm_status cvm__tet3_insert(cvm__tet3 *T, int32_t p)
{
    int32_t t = locate(T, p);
    const int32_t *v = T->tt + 8 * (size_t)t;
    cvm_status s;
    if (v[3] != CVM__T3_GHOST) {
        const double *pp = PT(T, p);
        int k;
        for (k = 0; k < 4; k++) {
            const double *q = PT(T, v[k]);
            if (q[0] == pp[0] && q[1] == pp[1] && q[2] == pp[2]
                && (!T->w || T->w[v[k]] == T->w[p])) {
                T->merged[p] = v[k];
                T->fate[p] = CVM__T3_DUPLICATE;
                return CVM_OK;
            }
        }
        if (T->w && !cvm__t3_finite_conflict(T, v, p)) {
            T->fate[p] = CVM__T3_REDUNDANT;
            return CVM_OK;
        }
    }
    s = dig_cavity(T, t, p);
    if (s != CVM_OK)
        return s;
    s = cvm__tet3_reserve(T, T->nbf);
    if (s == CVM_OK)
        s = cvm__tet3_reserve_hash(T, T->nbf);
    if (s != CVM_OK) {
        unmark(T);
        T->ndead = 0;
        return s;
    }
    if (T->w)
        cvm__tet3_mark_vanished(T, p);
    cvm__tet3_fill_around(T);
    T->fate[p] = CVM__T3_VERTEX;
    if (T->vtet)
        T->vtet[p] = T->last;
    return CVM_OK;
}

/* ---- insertion into a loaded mesh (cvm__tet3_load()) ---- */

#define HAS_CFACE(T, t, f) ((T)->cface && (((T)->cface[t] >> (f)) & 1u))

/* Exactly in the closure of the finite tetrahedron t. */
static int in_closure(const cvm__tet3 *T, int32_t t, const double *x)
{
    const int32_t *v = T->tt + 8 * (size_t)t;
    const double *a = PT(T, v[0]), *b = PT(T, v[1]), *c = PT(T, v[2]), *d = PT(T, v[3]);
    return cvm__orient3d(x, b, c, d) >= 0.0 && cvm__orient3d(a, x, c, d) >= 0.0
           && cvm__orient3d(a, b, x, d) >= 0.0 && cvm__orient3d(a, b, c, x) >= 0.0;
}

/* The walk of locate() that never leaves the mesh; when it would have to (a
 * non-convex domain, a point outside) or walks too long (a mesh that is not
 * Delaunay), the first live finite slot whose closure holds p, in slot order.
 * -1: p is in no tetrahedron (outside the domain or in a hole). */
static int32_t locate_constrained(cvm__tet3 *T, int32_t p)
{
    const double *pp = PT(T, p);
    int32_t t = T->last, came = -1;
    uint64_t r = T->walk;
    size_t steps = 0, i;
    for (;;) {
        const int32_t *v = T->tt + 8 * (size_t)t;
        const double *q[4];
        int k, f0, blocked = 0;
        if (v[3] == CVM__T3_GHOST || ++steps > T->nslot + 16)
            goto scan;
        q[0] = PT(T, v[0]), q[1] = PT(T, v[1]), q[2] = PT(T, v[2]), q[3] = PT(T, v[3]);
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        f0 = (int)(r >> 62);
        for (k = 0; k < 4; k++) {
            int f = (f0 + k) & 3;
            int32_t slot = 4 * t + f;
            const double *keep;
            double o;
            if (slot == came)
                continue;
            keep = q[f], q[f] = pp;
            o = cvm__orient3d_inline(q[0], q[1], q[2], q[3]);
            q[f] = keep;
            if (o < 0.0) {
                /* locating may cross internal facets; only the boundary stops it */
                if (T->tt[8 * (size_t)(CVM__T3_TN(T, slot) >> 2) + 3] == CVM__T3_GHOST) {
                    blocked = 1;
                    continue;
                }
                came = CVM__T3_TN(T, slot);
                t = came >> 2;
                goto next;
            }
        }
        if (blocked)
            goto scan;
        T->walk = r;
        return t;
    next:;
    }
scan:
    T->walk = r;
    for (i = 0; i < T->nslot; i++) {
        const int32_t *v = T->tt + 8 * i;
        if (v[0] != CVM__T3_DEAD && v[3] != CVM__T3_GHOST && in_closure(T, (int32_t)i, pp))
            return (int32_t)i;
    }
    return -1;
}

static void clear_excluded(cvm__tet3 *T)
{
    while (T->nexcl > 0)
        T->tmark[T->excl[--T->nexcl]] = 0;
}

/* The cavity of dig_cavity() in a constrained store: growth stops at
 * constrained faces (the far tetrahedron is not tested) and at tetrahedra
 * left out (tmark 3, which stay marked). */
static cvm_status dig_constrained(cvm__tet3 *T, int32_t t0, int32_t p)
{
    size_t nstack = 0;
    T->ndead = 0;
    T->nbf = 0;
    T->tmark[t0] = 1;
    PUSH(T->dead, T->ndead, T->deadcap, t0);
    PUSH(T->stack, nstack, T->stackcap, t0);
    while (nstack > 0) {
        int32_t c = T->stack[--nstack];
        int f;
        for (f = 0; f < 4; f++) {
            int32_t s = CVM__T3_TN(T, 4 * (size_t)c + f), u = s >> 2;
            int wall = HAS_CFACE(T, c, f);
            if (!wall && T->tmark[u] == 1)
                continue;
            if (!wall && T->tmark[u] == 0 && T->tt[8 * (size_t)u + 3] != CVM__T3_GHOST
                && cvm__t3_finite_conflict(T, T->tt + 8 * (size_t)u, p)) {
                T->tmark[u] = 1;
                PUSH(T->dead, T->ndead, T->deadcap, u);
                PUSH(T->stack, nstack, T->stackcap, u);
            } else {
                cvm__t3_bface *b;
                if (T->nbf == T->bfcap
                    && cvm__grow(T->ctx, (void **)&T->bf, &T->bfcap, T->nbf + 1, sizeof *T->bf)
                           != CVM_OK)
                    goto nomem;
                if (T->tmark[u] == 0)
                    T->tmark[u] = 2;
                b = &T->bf[T->nbf++];
                memcpy(b->v, T->tt + 8 * (size_t)c, 4 * sizeof *b->v);
                b->v[f] = p;
                b->f = f;
                b->out = s;
            }
        }
    }
    return CVM_OK;
nomem:
    unmark(T);
    return CVM_E_NOMEM;
}

/* unmark() that keeps the marks of the tetrahedra left out. */
static void unmark_keep_excluded(cvm__tet3 *T)
{
    size_t i;
    unmark(T);
    for (i = 0; i < T->nexcl; i++)
        T->tmark[T->excl[i]] = 3;
    T->ndead = T->nbf = 0;
}

/* Shrink the constrained cavity of p until every boundary face sees p
 * strictly on its inner side and no constrained face has the cavity on both
 * sides: each round leaves out the tetrahedron behind the first bad face and
 * digs again. *ok = 0 when the tetrahedron t0 holding p would have to go
 * (p on a constrained face or edge); the marks are then cleared. */
static cvm_status constrained_cavity(cvm__tet3 *T, int32_t t0, int32_t p, int *ok)
{
    cvm_status s;
    *ok = 0;
    T->nexcl = 0;
    for (;;) {
        size_t i;
        int32_t victim = -1;
        if ((s = dig_constrained(T, t0, p)) != CVM_OK) {
            clear_excluded(T);
            return s;
        }
        for (i = 0; i < T->nbf && victim < 0; i++) {
            const cvm__t3_bface *b = &T->bf[i];
            int32_t owner = CVM__T3_TN(T, b->out) >> 2, far = b->out >> 2;
            if (T->tmark[far] == 1)
                victim = owner == t0 ? far : owner;
            else if (cvm__orient3d(PT(T, b->v[0]), PT(T, b->v[1]), PT(T, b->v[2]),
                                   PT(T, b->v[3]))
                     <= 0.0)
                victim = owner;
        }
        if (victim < 0) {
            *ok = 1;
            return CVM_OK;
        }
        unmark(T);
        T->ndead = T->nbf = 0;
        if (victim == t0) {
            clear_excluded(T);
            return CVM_OK;
        }
        if (T->nexcl == T->exclcap
            && cvm__grow(T->ctx, (void **)&T->excl, &T->exclcap, T->nexcl + 1, sizeof *T->excl)
                   != CVM_OK) {
            clear_excluded(T);
            return CVM_E_NOMEM;
        }
        T->excl[T->nexcl++] = victim;
        unmark_keep_excluded(T);
    }
}

/* Weighted: a vertex of the cavity on none of its boundary faces (it would
 * lose its power cell to p), the lowest id; -1 when there is none. */
static int32_t vanishing_vertex(cvm__tet3 *T, int32_t p)
{
    uint32_t cur;
    size_t i;
    int k;
    int32_t best = -1;
    if (++T->vstamp == 0) {
        memset(T->vseen, 0, T->np * sizeof *T->vseen);
        memset(T->vkeep, 0, T->np * sizeof *T->vkeep);
        T->vstamp = 1;
    }
    cur = T->vstamp;
    for (i = 0; i < T->nbf; i++)
        for (k = 0; k < 4; k++)
            if (T->bf[i].v[k] >= 0)
                T->vkeep[T->bf[i].v[k]] = cur;
    for (i = 0; i < T->ndead; i++)
        for (k = 0; k < 4; k++) {
            int32_t v = T->tt[8 * (size_t)T->dead[i] + k];
            if (v >= 0 && v != p && T->vkeep[v] != cur && (best < 0 || v < best))
                best = v;
        }
    return best;
}

/* Vertex a, if it is nearer to x than *best (ties to the lowest id), becomes
 * *other; distances are rounded squared distances (the min_dist rule). */
static void take_if_nearer(const cvm__tet3 *T, const double *x, int32_t a, double *best,
                           int32_t *other)
{
    const double *q = PT(T, a);
    double d = (q[0] - x[0]) * (q[0] - x[0]) + (q[1] - x[1]) * (q[1] - x[1])
               + (q[2] - x[2]) * (q[2] - x[2]);
    if (d < *best || (d == *best && *other >= 0 && a < *other)) {
        *best = d;
        *other = a;
    }
}

/* The nearest vertex to x closer than min_dist (rounded squared distance
 * against min_dist^2, ties to the lowest id) into *best / *other. The cavity's
 * vertices first; in a regular or constrained mesh the nearest vertex need not
 * be one of them, so the search then walks, face to face from the cavity, every
 * tetrahedron whose bounding box meets the box of the ball B(x, min_dist)
 * (slightly widened: a conservative filter; those tetrahedra form one
 * face-connected set, the box being convex) and tests their vertices. Marks
 * are bit 0x80 of tmark, cleared before returning. A vertex in no tetrahedron
 * (its power cell vanished) is not seen. */
static cvm_status nearest_within(cvm__tet3 *T, const double *x, double min_dist, int32_t *other)
{
    double best = min_dist * min_dist, r = min_dist * (1.0 + 0x1p-20);
    size_t i, nq = 0, head;
    int k;
    int wide = T->w != NULL || T->cface != NULL;
    cvm_status s = CVM_OK;
    for (i = 0; i < T->ndead; i++) {
        int32_t c = T->dead[i];
        if (wide) {
            if (nq == T->stackcap
                && cvm__grow(T->ctx, (void **)&T->stack, &T->stackcap, nq + 1, sizeof *T->stack)
                       != CVM_OK) {
                s = CVM_E_NOMEM;
                goto done;
            }
            T->tmark[c] |= 0x80;
            T->stack[nq++] = c;
        } else {
            for (k = 0; k < 4; k++)
                if (T->tt[8 * (size_t)c + k] >= 0)
                    take_if_nearer(T, x, T->tt[8 * (size_t)c + k], &best, other);
        }
    }
    for (head = 0; head < nq; head++) {
        int32_t c = T->stack[head];
        const int32_t *v = T->tt + 8 * (size_t)c;
        int f;
        for (k = 0; k < 4; k++)
            if (v[k] >= 0)
                take_if_nearer(T, x, v[k], &best, other);
        for (f = 0; f < 4; f++) {
            int32_t u = CVM__T3_TN(T, 4 * (size_t)c + f) >> 2;
            const int32_t *w = T->tt + 8 * (size_t)u;
            int meets = 1, ax;
            if ((T->tmark[u] & 0x80) || w[3] == CVM__T3_GHOST)
                continue;
            for (ax = 0; ax < 3 && meets; ax++) {
                double lo = PT(T, w[0])[ax], hi = lo;
                for (k = 1; k < 4; k++) {
                    double c2 = PT(T, w[k])[ax];
                    lo = c2 < lo ? c2 : lo;
                    hi = c2 > hi ? c2 : hi;
                }
                meets = lo <= x[ax] + r && hi >= x[ax] - r;
            }
            if (!meets)
                continue;
            if (nq == T->stackcap
                && cvm__grow(T->ctx, (void **)&T->stack, &T->stackcap, nq + 1, sizeof *T->stack)
                       != CVM_OK) {
                s = CVM_E_NOMEM;
                goto done;
            }
            T->tmark[u] |= 0x80;
            T->stack[nq++] = u;
        }
    }
done:
    for (i = 0; i < nq; i++)
        T->tmark[T->stack[i]] &= 0x7f;
    return s;
}

cvm_status cvm__tet3_insert_point(cvm__tet3 *T, const double *x, int32_t sos, double min_dist,
                                  cvm__t3_ins *res, int32_t *other)
{
    int32_t p = (int32_t)T->np, t;
    const int32_t *v;
    double attr0 = 0.0;
    cvm_status s;
    size_t i;
    int k;
    *other = -1;
    memset(&T->pt[p], 0, sizeof T->pt[p]);
    T->pt[p].x[0] = x[0], T->pt[p].x[1] = x[1], T->pt[p].x[2] = x[2];
    if (T->w)
        T->w[p] = 0.0;
    T->orig[p] = sos;
    T->merged[p] = -1;
    T->outid[p] = p;
    T->fate[p] = CVM__T3_PENDING;
    t = T->cface ? locate_constrained(T, p) : locate(T, p);
    if (t < 0 || T->tt[8 * (size_t)t + 3] == CVM__T3_GHOST) {
        *res = CVM__T3_INS_OUTSIDE;
        return CVM_OK;
    }
    v = T->tt + 8 * (size_t)t;
    for (k = 0; k < 4; k++) {
        const double *q = PT(T, v[k]);
        if (q[0] == x[0] && q[1] == x[1] && q[2] == x[2]) {
            *res = CVM__T3_INS_DUPLICATE;
            *other = v[k];
            return CVM_OK;
        }
    }
    if (T->w && !cvm__t3_finite_conflict(T, v, p)) {
        *res = CVM__T3_INS_REDUNDANT;
        return CVM_OK;
    }
    if (T->sattr)
        attr0 = T->sattr[t];
    if (T->cface) {
        int ok;
        if ((s = constrained_cavity(T, t, p, &ok)) != CVM_OK)
            return s;
        if (!ok) {
            *res = CVM__T3_INS_ON_CONSTRAINT;
            return CVM_OK;
        }
    } else if ((s = dig_cavity(T, t, p)) != CVM_OK) {
        return s;
    }
    if (min_dist > 0) {
        if ((s = nearest_within(T, x, min_dist, other)) != CVM_OK) {
            unmark(T);
            clear_excluded(T);
            T->ndead = T->nbf = 0;
            *other = -1;
            return s;
        }
        if (*other >= 0) {
            unmark(T);
            clear_excluded(T);
            T->ndead = T->nbf = 0;
            *res = CVM__T3_INS_TOO_CLOSE;
            return CVM_OK;
        }
    }
    if (T->w && (*other = vanishing_vertex(T, p)) >= 0) {
        unmark(T);
        T->ndead = T->nbf = 0;
        *res = CVM__T3_INS_HIDES;
        return CVM_OK;
    }
    s = cvm__tet3_reserve(T, T->nbf);
    if (s == CVM_OK)
        s = cvm__tet3_reserve_hash(T, T->nbf);
    if (s != CVM_OK) {
        unmark(T);
        clear_excluded(T);
        T->ndead = T->nbf = 0;
        return s;
    }
    cvm__tet3_fill_around(T);
    clear_excluded(T);
    for (i = 0; i < T->nbf; i++) {
        const cvm__t3_bface *b = &T->bf[i];
        if (T->cface)
            T->cface[b->tet] = (uint8_t)(HAS_CFACE(T, b->out >> 2, b->out & 3) << b->f);
        if (T->sattr)
            T->sattr[b->tet] = attr0;
    }
    T->nbf = 0;
    T->fate[p] = CVM__T3_VERTEX;
    T->np++;
    *res = CVM__T3_INS_DONE;
    return CVM_OK;
}
