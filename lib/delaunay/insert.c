/* insert.c - Bowyer-Watson insertion of one vertex, respecting constrained edges. */
#include <math.h>

#include "delaunay_internal.h"
#include "tri2_store.h"
#include "geom/geom_internal.h"

/* A cavity boundary edge: a, b (counter-clockwise as seen from the cavity),
 * the half-edge outside it, its segment, and the flags of the cavity triangle
 * it belonged to. */
/* Most constrained edges one new vertex may split (segments meeting at it). */
#define CVM__MAX_SPLIT 32

enum { B_A = 0, B_B, B_OUTER, B_SEG, B_FLAGS, B_OWNER, B_STRIDE };

/* p strictly inside segment ab, given orient2d(a, b, p) == 0. */
static int between(const double *a, const double *b, const double *p)
{
    if (a[0] != b[0])
        return (p[0] > a[0] && p[0] < b[0]) || (p[0] < a[0] && p[0] > b[0]);
    return (p[1] > a[1] && p[1] < b[1]) || (p[1] < a[1] && p[1] > b[1]);
}

static int on_edge(const cvm__tri2 *T, int32_t a, int32_t b, const double *p)
{
    const double *pa, *pb;
    if (a < 0 || b < 0)
        return 0;
    pa = cvm__tri2_pt(T, a);
    pb = cvm__tri2_pt(T, b);
    return cvm__orient2d(pa, pb, p) == 0 && between(pa, pb, p);
}

static cvm_status push_int(cvm__tri2 *T, int32_t **arr, size_t *cap, size_t n, int32_t val)
{
    if (n >= *cap && cvm__grow(T->ctx, (void **)arr, cap, n + 1, sizeof(int32_t)))
        return CVM_E_NOMEM;
    (*arr)[n] = val;
    return CVM_OK;
}

/* t is a ghost triangle whose hull edge is constrained. The cavity enters such
 * a ghost only to split that edge; it must not spread to the neighbouring
 * ghosts, even where rounding left the hull a few ulps short of convex. */
static int behind_constrained_hull_edge(const cvm__tri2 *T, int32_t t)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    int g;
    if (!T->te)
        return 0;
    g = v[0] == CVM__GHOST ? 0 : v[1] == CVM__GHOST ? 1 : v[2] == CVM__GHOST ? 2 : -1;
    return g >= 0 && T->te[3 * (size_t)t + g] >= 0;
}

/* Unmark the cavity after a failure or a rejection. */
static void unmark(cvm__tri2 *T, size_t ncav)
{
    size_t i;
    for (i = 0; i < ncav; i++)
        T->tf[T->cav[i]] &= (uint8_t)~CVM__TF_MARK;
}

/* Grow the cavity of p from t0 by depth-first search; fills T->cav and T->bnd. */
static cvm_status grow_cavity(cvm__tri2 *T, int32_t p, int32_t t0, size_t *ncav_out,
                              size_t *nbnd_out, int force_edge_t, int force_edge_j)
{
    const double *pp = cvm__tri2_pt(T, p);
    size_t nstack = 0, ncav = 0, nbnd = 0;
    cvm_status s;

    *ncav_out = 0;
    if ((s = push_int(T, &T->cav, &T->cap_cav, 0, t0)) ||
        (s = push_int(T, &T->stack, &T->cap_stack, 0, t0)))
        return s;
    T->tf[t0] |= CVM__TF_MARK;
    ncav = nstack = 1;
    while (nstack) {
        int32_t t = T->stack[--nstack];
        int j;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * (size_t)t + j;
            int32_t nb = T->tn[h] / 3;
            int32_t seg = T->te ? T->te[h] : -1;
            int32_t a = T->tv[3 * (size_t)t + (j + 1) % 3], b = T->tv[3 * (size_t)t + (j + 2) % 3];
            int cross;
            if (T->tf[nb] & CVM__TF_MARK)
                continue;
            if (seg >= 0)
                cross = (t == force_edge_t && j == force_edge_j) || on_edge(T, a, b, pp);
            else if (behind_constrained_hull_edge(T, t))
                cross = 0; /* v splits that hull edge: it belongs to no other ghost */
            else
                cross = cvm__tri2_conflict(T, nb, p) > 0;
            if (cross) {
                if ((s = push_int(T, &T->cav, &T->cap_cav, ncav, nb)) ||
                    (s = push_int(T, &T->stack, &T->cap_stack, nstack, nb))) {
                    *ncav_out = ncav;
                    return s;
                }
                T->tf[nb] |= CVM__TF_MARK;
                ncav++;
                nstack++;
            } else {
                size_t need = (nbnd + 1) * B_STRIDE;
                if (need > T->cap_bnd &&
                    cvm__grow(T->ctx, (void **)&T->bnd, &T->cap_bnd, need, sizeof(int32_t))) {
                    *ncav_out = ncav;
                    return CVM_E_NOMEM;
                }
                if (T->ta) {
                    if (nbnd + 1 > T->cap_bta &&
                        cvm__grow(T->ctx, (void **)&T->bta, &T->cap_bta, nbnd + 1, sizeof(double))) {
                        *ncav_out = ncav;
                        return CVM_E_NOMEM;
                    }
                    T->bta[nbnd] = T->ta[t];
                }
                T->bnd[nbnd * B_STRIDE + B_A] = a;
                T->bnd[nbnd * B_STRIDE + B_B] = b;
                T->bnd[nbnd * B_STRIDE + B_OUTER] = T->tn[h];
                T->bnd[nbnd * B_STRIDE + B_SEG] = seg;
                T->bnd[nbnd * B_STRIDE + B_FLAGS] = T->tf[t] & CVM__TF_OUT;
                T->bnd[nbnd * B_STRIDE + B_OWNER] = t;
                nbnd++;
            }
        }
    }
    *ncav_out = ncav;
    *nbnd_out = nbnd;
    return CVM_OK;
}

/* Replace the marked cavity by the fan of p over its boundary. Room for the
 * new triangles must be reserved. split: nsplit triples (a, b, segment) of
 * constrained edges p splits; their halves p-a, p-b keep the segment. */
static void fill_fan(cvm__tri2 *T, int32_t p, size_t ncav, size_t nbnd, const int32_t *split,
                     int nsplit)
{
    size_t i;
    int32_t ghost_start = -1, first = -1;
    if (T->w) {
        /* vertices inside the cavity of a regular triangulation vanish */
        for (i = 0; i < ncav; i++) {
            const int32_t *v = T->tv + 3 * (size_t)T->cav[i];
            int k;
            for (k = 0; k < 3; k++)
                if (v[k] >= 0)
                    T->vtri[v[k]] = -1;
        }
    }
    for (i = 0; i < ncav; i++)
        cvm__tri2_kill(T, T->cav[i]);
    for (i = 0; i < nbnd; i++) {
        const int32_t *e = T->bnd + i * B_STRIDE;
        int32_t n = cvm__tri2_new(T);
        int32_t outer = e[B_OUTER];
        size_t n3 = 3 * (size_t)n;
        T->tv[n3] = p;
        T->tv[n3 + 1] = e[B_A];
        T->tv[n3 + 2] = e[B_B];
        T->tf[n] = (uint8_t)e[B_FLAGS];
        T->tn[n3] = outer;
        T->tn[outer] = (int32_t)n3;
        if (T->te) {
            T->te[n3] = e[B_SEG];
            int k;
            for (k = 0; k < nsplit; k++) {
                const int32_t *sp = split + 3 * k;
                if (e[B_A] == sp[0] || e[B_A] == sp[1])
                    T->te[n3 + 2] = sp[2];
                if (e[B_B] == sp[0] || e[B_B] == sp[1])
                    T->te[n3 + 1] = sp[2];
            }
        }
        if (T->ta)
            T->ta[n] = T->bta[i];
        if (e[B_A] >= 0)
            T->vtri[e[B_A]] = n;
        else
            ghost_start = n;
        if (first < 0)
            first = n;
        /* remember the new triangle in the boundary record for linking */
        T->bnd[i * B_STRIDE + B_OUTER] = n;
    }
    for (i = 0; i < nbnd; i++) {
        const int32_t *e = T->bnd + i * B_STRIDE;
        int32_t n = e[B_OUTER];
        int32_t nxt = e[B_B] >= 0 ? T->vtri[e[B_B]] : ghost_start;
        cvm__tri2_link(T, n, 1, nxt, 2);
    }
    T->vtri[p] = first;
    T->last = first;
}

/* Re-derive the boundary records of the marked cavity cav[0..ncav). */
static cvm_status record_boundary(cvm__tri2 *T, size_t ncav, size_t *nbnd_out)
{
    size_t i, nbnd = 0;
    for (i = 0; i < ncav; i++) {
        int32_t t = T->cav[i];
        int j;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * (size_t)t + j;
            int32_t *e;
            if (T->tf[T->tn[h] / 3] & CVM__TF_MARK)
                continue;
            if ((nbnd + 1) * B_STRIDE > T->cap_bnd &&
                cvm__grow(T->ctx, (void **)&T->bnd, &T->cap_bnd, (nbnd + 1) * B_STRIDE,
                          sizeof(int32_t)))
                return CVM_E_NOMEM;
            if (T->ta) {
                if (nbnd + 1 > T->cap_bta &&
                    cvm__grow(T->ctx, (void **)&T->bta, &T->cap_bta, nbnd + 1, sizeof(double)))
                    return CVM_E_NOMEM;
                T->bta[nbnd] = T->ta[t];
            }
            e = T->bnd + nbnd * B_STRIDE;
            e[B_A] = T->tv[3 * (size_t)t + (j + 1) % 3];
            e[B_B] = T->tv[3 * (size_t)t + (j + 2) % 3];
            e[B_OUTER] = T->tn[h];
            e[B_SEG] = T->te ? T->te[h] : -1;
            e[B_FLAGS] = T->tf[t] & CVM__TF_OUT;
            e[B_OWNER] = t;
            nbnd++;
        }
    }
    *nbnd_out = nbnd;
    return CVM_OK;
}

/*
 * A vertex computed inexactly (a rounded segment intersection) and forced
 * onto a constrained edge may see some cavity boundary edges from behind, so
 * the fan would hold inverted triangles. Drop the owners of such edges from
 * the cavity (never the two triangles of the split edge) until every real
 * boundary edge is seen counter-clockwise and the cavity is a disc (boundary
 * edges = triangles + 2). Returns 1 on success, 0 if impossible.
 */
static int shrink_to_visible(cvm__tri2 *T, int32_t p, size_t *ncav, size_t *nbnd, int32_t keep0,
                             int32_t keep1, cvm_status *s_out)
{
    const double *pp = cvm__tri2_pt(T, p);
    *s_out = CVM_OK;
    for (;;) {
        size_t i, bad = (size_t)-1;
        for (i = 0; i < *nbnd && bad == (size_t)-1; i++) {
            const int32_t *e = T->bnd + i * B_STRIDE;
            if (e[B_A] >= 0 && e[B_B] >= 0 &&
                cvm__orient2d(pp, cvm__tri2_pt(T, e[B_A]), cvm__tri2_pt(T, e[B_B])) <= 0)
                bad = i;
        }
        if (bad == (size_t)-1)
            return *nbnd == *ncav + 2;
        {
            int32_t owner = T->bnd[bad * B_STRIDE + B_OWNER];
            if (owner == keep0 || owner == keep1)
                return 0;
            for (i = 0; i < *ncav; i++)
                if (T->cav[i] == owner)
                    break;
            T->cav[i] = T->cav[--*ncav];
            T->tf[owner] &= (uint8_t)~CVM__TF_MARK;
        }
        if ((*s_out = record_boundary(T, *ncav, nbnd)))
            return 0;
    }
}

/* Vertex a, if it is nearer to pp than *best (ties to the lowest id, and only
 * below min_dist), becomes *who; distances are rounded squared distances (the
 * min_dist rule). */
static void take_if_nearer2(const cvm__tri2 *T, const double *pp, int32_t a, double min_dist,
                            double *best, int32_t *who)
{
    const double *pa = cvm__tri2_pt(T, a);
    double d = (pa[0] - pp[0]) * (pa[0] - pp[0]) + (pa[1] - pp[1]) * (pa[1] - pp[1]);
    if (d < *best || (d == *best && *who >= 0 && a < *who && d < min_dist * min_dist)) {
        *best = d;
        *who = a;
    }
}

/* min_dist in a constrained or weighted triangulation: the nearest vertex to pp
 * need not be on the cavity's boundary (it can lie behind a segment), so walk,
 * edge to edge from the cavity, every triangle whose bounding box meets the box
 * of the disc B(pp, min_dist) (widened by 2^-20 of min_dist: a conservative
 * filter; the triangles meeting a convex box form one edge-connected set), and
 * test the vertices of those in the domain by the rule of insert_from(). Marks:
 * CVM__TF_MARK2, cleared before returning. */
static cvm_status nearest_behind(cvm__tri2 *T, const double *pp, double min_dist, size_t ncav,
                                 double *best, int32_t *who)
{
    double r = min_dist * (1.0 + 0x1p-20);
    size_t i, nq = 0, head;
    cvm_status s = CVM_OK;
    for (i = 0; i < ncav; i++) {
        if ((s = push_int(T, &T->stack, &T->cap_stack, nq, T->cav[i])) != CVM_OK)
            goto done;
        T->tf[T->cav[i]] |= CVM__TF_MARK2;
        nq++;
    }
    for (head = 0; head < nq; head++) {
        int32_t t = T->stack[head];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int j;
        if (!(T->tf[t] & CVM__TF_OUT))
            for (j = 0; j < 3; j++)
                if (tv[j] >= 0)
                    take_if_nearer2(T, pp, tv[j], min_dist, best, who);
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * (size_t)t + j] / 3;
            const int32_t *uv = T->tv + 3 * (size_t)u;
            int ax, meets = 1;
            if ((T->tf[u] & (CVM__TF_MARK2 | CVM__TF_DEAD)) || cvm__tri2_is_ghost(T, u))
                continue;
            for (ax = 0; ax < 2 && meets; ax++) {
                double a = cvm__tri2_pt(T, uv[0])[ax], b = cvm__tri2_pt(T, uv[1])[ax];
                double c = cvm__tri2_pt(T, uv[2])[ax];
                double lo = a < b ? (a < c ? a : c) : (b < c ? b : c);
                double hi = a > b ? (a > c ? a : c) : (b > c ? b : c);
                meets = lo <= pp[ax] + r && hi >= pp[ax] - r;
            }
            if (!meets)
                continue;
            if ((s = push_int(T, &T->stack, &T->cap_stack, nq, u)) != CVM_OK)
                goto done;
            T->tf[u] |= CVM__TF_MARK2;
            nq++;
        }
    }
done:
    for (i = 0; i < nq; i++)
        T->tf[T->stack[i]] &= (uint8_t)~CVM__TF_MARK2;
    return s;
}

static cvm_status insert_from(cvm__tri2 *T, int32_t v, int32_t t0, int fe_t, int fe_j,
                              double min_dist, cvm__ins *res_out, int32_t *other_out)
{
    size_t ncav = 0, nbnd = 0, i;
    int32_t split[3 * CVM__MAX_SPLIT] = {0}; /* read only below nsplit; set for gcc's flow analysis */
    int nsplit = 0;
    cvm_status s = grow_cavity(T, v, t0, &ncav, &nbnd, fe_t, fe_j);
    if (s) {
        unmark(T, ncav);
        return s;
    }
    if (min_dist > 0) {
        const double *pp = cvm__tri2_pt(T, v);
        double best = min_dist * min_dist;
        int32_t who = -1;
        for (i = 0; i < nbnd; i++)
            if (T->bnd[i * B_STRIDE + B_A] >= 0)
                take_if_nearer2(T, pp, T->bnd[i * B_STRIDE + B_A], min_dist, &best, &who);
        if ((T->te || T->w) && (s = nearest_behind(T, pp, min_dist, ncav, &best, &who))) {
            unmark(T, ncav);
            return s;
        }
        if (who >= 0) {
            unmark(T, ncav);
            *res_out = CVM__INS_TOO_CLOSE;
            *other_out = who;
            return CVM_OK;
        }
    }
    if (fe_t >= 0) {
        int32_t nb = T->tn[3 * (size_t)fe_t + fe_j] / 3;
        if (!shrink_to_visible(T, v, &ncav, &nbnd, fe_t, nb, &s)) {
            unmark(T, ncav);
            if (s)
                return s;
            *res_out = CVM__INS_OFF_EDGE;
            return CVM_OK;
        }
    }
    if (nbnd > ncav && cvm__tri2_reserve_triangles(T, T->nt + (nbnd - ncav))) {
        unmark(T, ncav);
        return CVM_E_NOMEM;
    }
    /* constrained edges inside the cavity are the ones v splits (several when
     * segments meet at v) */
    if (T->te) {
        for (i = 0; i < ncav; i++) {
            int32_t t = T->cav[i];
            int j;
            for (j = 0; j < 3; j++) {
                size_t h = 3 * (size_t)t + j;
                int32_t u = T->tn[h] / 3;
                if (T->te[h] < 0 || !(T->tf[u] & CVM__TF_MARK) || u < t)
                    continue;
                if (nsplit == CVM__MAX_SPLIT) {
                    unmark(T, ncav);
                    return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_VERTEX, v,
                                      "vertex %ld lies on more than %d constrained edges",
                                      (long)v, CVM__MAX_SPLIT);
                }
                split[3 * nsplit] = T->tv[3 * (size_t)t + (j + 1) % 3];
                split[3 * nsplit + 1] = T->tv[3 * (size_t)t + (j + 2) % 3];
                split[3 * nsplit + 2] = T->te[h];
                nsplit++;
            }
        }
    }
    fill_fan(T, v, ncav, nbnd, split, nsplit);
    if (fe_t >= 0 && (s = cvm__tri2_legalize_stars(T, &v, 1)))
        return s; /* the triangulation is valid, only not yet Delaunay around v */
    *res_out = CVM__INS_DONE;
    *other_out = -1;
    return CVM_OK;
}

cvm_status cvm__tri2_insert_vertex(cvm__tri2 *T, int32_t v, int32_t hint, int flags,
                                   double min_dist, cvm__ins *res_out, int32_t *other_out)
{
    const double *pp = cvm__tri2_pt(T, v);
    int32_t t;
    int j;
    cvm__loc loc = cvm__tri2_locate(T, pp, hint, &t, &j);

    *other_out = -1;
    if (t < 0)
        return CVM_E_INTERNAL;
    if (loc == CVM__LOC_VERTEX) {
        *res_out = CVM__INS_DUPLICATE;
        *other_out = T->tv[3 * (size_t)t + j];
        return CVM_OK;
    }
    if (flags & CVM__INSF_DOMAIN_ONLY) {
        int inside = loc != CVM__LOC_OUTSIDE && !(T->tf[t] & CVM__TF_OUT);
        if (!inside && loc == CVM__LOC_EDGE) {
            int32_t nb = T->tn[3 * (size_t)t + j] / 3;
            inside = !cvm__tri2_is_ghost(T, nb) && !(T->tf[nb] & CVM__TF_OUT);
        }
        if (!inside) {
            *res_out = CVM__INS_OUTSIDE;
            return CVM_OK;
        }
    }
    if (T->w && loc != CVM__LOC_OUTSIDE && cvm__tri2_conflict(T, t, v) <= 0) {
        /* in a regular triangulation a point below the lifted facet of the
         * triangle containing it has an empty power cell */
        *res_out = CVM__INS_REDUNDANT;
        return CVM_OK;
    }
    return insert_from(T, v, t, -1, -1, min_dist, res_out, other_out);
}

cvm_status cvm__tri2_insert_in_cavity(cvm__tri2 *T, int32_t v, const int32_t *cav, size_t ncav)
{
    static const int32_t no_split[3] = {-1, -1, -1};
    size_t i, nbnd = 0;
    cvm_status s;
    if (ncav > T->cap_cav && cvm__grow(T->ctx, (void **)&T->cav, &T->cap_cav, ncav, sizeof *T->cav))
        return CVM_E_NOMEM;
    for (i = 0; i < ncav; i++) {
        T->cav[i] = cav[i];
        T->tf[cav[i]] |= CVM__TF_MARK;
    }
    if ((s = record_boundary(T, ncav, &nbnd)) ||
        (nbnd > ncav && cvm__tri2_reserve_triangles(T, T->nt + (nbnd - ncav)))) {
        unmark(T, ncav);
        return CVM_E_NOMEM;
    }
    fill_fan(T, v, ncav, nbnd, no_split, 0);
    return CVM_OK;
}

cvm_status cvm__tri2_split_edge(cvm__tri2 *T, int32_t v, int32_t t, int j, cvm__ins *res_out)
{
    int32_t other;
    *res_out = CVM__INS_DONE;
    return insert_from(T, v, t, t, j, 0.0, res_out, &other);
}
