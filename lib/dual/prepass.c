/*
 * prepass.c - topology pre-pass of the dual optimiser (CVM_OPT_DUAL_PREPASS):
 * edge collapse and split until edge lengths follow the local size, and
 * re-seeding of the Steiner vertices of triangles below the target angle.
 *
 * Local size h(v): the sizing at v when the caller gave one, else the mean
 * length of v's edges (cvm__dual_mesh_sizes), both taken at the start of each
 * round. The size of an edge is the mean of its ends' sizes.
 *
 * One round:
 *  1. Removal. Steiner vertices (id >= n_input) are visited in id order; a
 *     removable one (cvm__dual_removable: no constrained edge, so no segment
 *     or hull vertex) with no neighbour already picked in this round is picked
 *     when one of its edges is shorter than PRE_SHORT x the edge's size
 *     (collapse), or when it is an end of the shortest edge of one of its
 *     triangles whose smallest angle is below the target angle (re-seed; the
 *     mean of its neighbours is recorded). Picked vertices are removed
 *     (topology.c), then Lawson flips restore the regular triangulation.
 *  2. Re-seeding: a new vertex at the recorded mean of each re-seeded vertex's
 *     former neighbours, inserted by Bowyer-Watson (domain only, rejected when
 *     closer than PRE_SHORT x its size to an existing vertex, or when with
 *     weights its cavity would drop a vertex or is no disc: would_swallow).
 *  3. Split: every unconstrained edge between two domain triangles of the same
 *     region longer than PRE_LONG x its size gets its midpoint inserted the
 *     same way (edges listed first in slot order, then inserted).
 * Vertices that were removed, or added and then rejected, are dropped from
 * the vertex arrays (cvm__tri2_compact); vmap follows. Input points and
 * segments are never touched (no constrained edge is split). Everything is
 * sequential and in slot/id order: deterministic, thread-count independent.
 */
#include <math.h>
#include <string.h>

#include "dual_internal.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

#define PRE_SHORT 0.5
#define PRE_LONG 1.5
#define PRE_ROUNDS 2
#define PRE_BAD_DEG 35.0 /* re-seed below min(this, the target angle) */

typedef struct pre {
    cvm__tri2 *T;
    const cvm__dual_opt_params *p;
    double *h;        /* size per vertex */
    uint8_t *pick;    /* 1 picked for removal, 2 removed (gone) */
    double *seed_xy;  /* 2 per vertex: re-seed point, NaN when none */
    int32_t *dup, *map;
    double *mid;      /* split points, 3 per edge (x, y, h) */
    int32_t *cav;     /* cavity of a point about to be inserted (would_swallow) */
    uint8_t *in_cav;  /* per triangle slot: 1 in that cavity */
    size_t cap, cap_cav, cap_tri; /* entries of the per-vertex, cavity, per-slot arrays */
    double sin2_target;
} pre;

static cvm_status grow(pre *P, size_t need)
{
    cvm__ctx *ctx = P->T->ctx;
    size_t n = need + need / 2 + 16;
    void *a;
    if (need <= P->cap)
        return CVM_OK;
#define RE(ptr, sz)                                                                                \
    do {                                                                                           \
        a = cvm__realloc(ctx, ptr, n * (sz));                                                      \
        if (!a)                                                                                    \
            return CVM_E_NOMEM;                                                                    \
        ptr = a;                                                                                   \
    } while (0)
    RE(P->h, sizeof *P->h);
    RE(P->pick, 1);
    RE(P->seed_xy, 2 * sizeof *P->seed_xy);
    RE(P->dup, sizeof *P->dup);
    RE(P->map, sizeof *P->map);
#undef RE
    P->cap = n;
    return CVM_OK;
}

static cvm_status sizes(pre *P)
{
    cvm__tri2 *T = P->T;
    size_t v;
    cvm__dual_mesh_sizes(T, P->h);
    if (!P->p->size_fn)
        return CVM_OK;
    for (v = 0; v < T->nv; v++) {
        cvm_status s;
        if (T->vtri[v] < 0)
            continue;
        if ((s = P->p->size_fn(P->p->size_payload, T->xy[2 * v], T->xy[2 * v + 1], P->h + v)))
            return s;
    }
    return CVM_OK;
}

/* Decide whether removable Steiner vertex v is picked (see the file comment). */
static int wants_removal(pre *P, int32_t v)
{
    cvm__tri2 *T = P->T;
    int32_t t0 = T->vtri[v], t = t0;
    const double *pv = T->xy + 2 * (size_t)v;
    double sx = 0, sy = 0, sw = 0;
    size_t n = 0;
    int shortie = 0, bad = 0;
    do {
        int i = cvm__tri2_corner(T, t, v);
        int32_t a = T->tv[3 * (size_t)t + (size_t)(i + 1) % 3];
        int32_t b = T->tv[3 * (size_t)t + (size_t)(i + 2) % 3];
        const double *pa = T->xy + 2 * (size_t)a, *pb = T->xy + 2 * (size_t)b;
        double ea = cvm__dist2(pv, pa), eb = cvm__dist2(pv, pb), ab = cvm__dist2(pa, pb);
        double ha = PRE_SHORT * 0.5 * (P->h[v] + P->h[a]);
        if (P->pick[a])
            return 0; /* a neighbour goes already: keep v this round */
        if (ea < ha * ha)
            shortie = 1;
        if (cvm__min_sin2(pv, pa, pb) < P->sin2_target && (ea <= ab || eb <= ab))
            bad = 1; /* v ends the shortest edge of a triangle below the target */
        sx += pa[0];
        sy += pa[1];
        sw += 1.0;
        n++;
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && n <= T->nt);
    if (!shortie && !bad)
        return 0;
    P->seed_xy[2 * (size_t)v] = P->seed_xy[2 * (size_t)v + 1] = NAN;
    if (!shortie && sw > 0) {
        P->seed_xy[2 * (size_t)v] = sx / sw;
        P->seed_xy[2 * (size_t)v + 1] = sy / sw;
    }
    return 1;
}

/* With weights, Bowyer-Watson insertion (cvm__tri2_insert_vertex) drops every
 * vertex inside the new point's cavity (the point empties its power cell), and
 * no flip brings it back; where the triangulation is not regular (a vertex
 * whose power cell is already empty stays as the blocking corner of an edge
 * no flip can fix, see cvm_mesh_set_weights) the cavity need not even be a
 * disc, and the fan over it corrupts the triangulation; a constrained edge
 * inside the cavity would be taken for one the point splits. All of these
 * break the pre-pass's contract (vertices go only when picked, segments are
 * untouched), so *yes = 1 when the insertion of vertex id would do any: the
 * cavity is grown here as cvm__tri2_insert_vertex grows it (from the triangle
 * containing the point, across unconstrained edges whose triangle is in
 * conflict with it, exact power test) and the point is refused unless the
 * cavity is a disc with no vertex inside (boundary edges = triangles + 2),
 * every boundary edge is seen counter-clockwise from it (exact orient2d), no
 * constrained edge lies inside and the point is not on the line of a
 * constrained edge the cavity touches (the insertion would split it). *yes = 0
 * too when the insertion refuses the point by itself (duplicate, outside,
 * redundant). CVM_OK or CVM_E_NOMEM. */
static cvm_status would_swallow(pre *P, int32_t id, int *yes)
{
    cvm__tri2 *T = P->T;
    cvm__ctx *ctx = T->ctx;
    const double *pp = T->xy + 2 * (size_t)id;
    size_t ncav = 0, i, top = 0;
    int32_t t0;
    int j0;
    cvm__loc loc;
    *yes = 0;
    loc = cvm__tri2_locate(T, pp, -1, &t0, &j0);
    if (t0 < 0 || loc == CVM__LOC_VERTEX || loc == CVM__LOC_OUTSIDE || cvm__tri2_conflict(T, t0, id) <= 0)
        return CVM_OK; /* refused by the insertion (duplicate, outside, redundant) */
    if (T->nt > P->cap_tri) {
        size_t n = T->nt + T->nt / 2 + 16;
        uint8_t *a = cvm__realloc(ctx, P->in_cav, n);
        if (!a)
            return CVM_E_NOMEM;
        memset(a + P->cap_tri, 0, n - P->cap_tri);
        P->in_cav = a;
        P->cap_tri = n;
    }
#define PUSH_CAV(t)                                                                                \
    do {                                                                                           \
        if (ncav + 1 > P->cap_cav) {                                                               \
            size_t n_ = 2 * P->cap_cav + 64;                                                       \
            int32_t *a_ = cvm__realloc(ctx, P->cav, n_ * sizeof *a_);                              \
            if (!a_) {                                                                             \
                for (i = 0; i < ncav; i++)                                                         \
                    P->in_cav[P->cav[i]] = 0;                                                      \
                return CVM_E_NOMEM;                                                                \
            }                                                                                      \
            P->cav = a_;                                                                           \
            P->cap_cav = n_;                                                                       \
        }                                                                                          \
        P->cav[ncav++] = (t);                                                                      \
        P->in_cav[t] = 1;                                                                          \
    } while (0)
    PUSH_CAV(t0);
    /* breadth first over P->cav itself: cav[top..ncav) are still to expand */
    while (top < ncav && !*yes) {
        int32_t t = P->cav[top++];
        int j;
        for (j = 0; j < 3 && !*yes; j++) {
            size_t h = 3 * (size_t)t + (size_t)j;
            int32_t nb = T->tn[h] / 3;
            if (P->in_cav[nb])
                continue;
            if (T->te && T->te[h] >= 0) {
                int32_t a = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3];
                int32_t b = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
                if (a >= 0 && b >= 0 &&
                    cvm__orient2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, pp) == 0)
                    *yes = 1; /* on or in line with a segment: not the pre-pass's to split */
                continue;
            }
            if (cvm__tri2_conflict(T, nb, id) > 0)
                PUSH_CAV(nb);
        }
    }
#undef PUSH_CAV
    /* the fan over the cavity's boundary must be a triangulation: a disc
     * (boundary edges = triangles + 2, so no vertex inside) seen
     * counter-clockwise from the point, with no constrained edge inside */
    if (!*yes) {
        size_t nbnd = 0;
        for (i = 0; i < ncav && !*yes; i++) {
            int32_t t = P->cav[i];
            int j;
            for (j = 0; j < 3 && !*yes; j++) {
                size_t h = 3 * (size_t)t + (size_t)j;
                int32_t a = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3];
                int32_t b = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
                int32_t x = T->tv[3 * (size_t)t + (size_t)j], u = t;
                size_t n = 0;
                /* corner x with every triangle in the cavity: it would vanish */
                while (x >= 0 && !*yes && P->in_cav[u] && n++ <= T->nt) {
                    u = T->tn[3 * (size_t)u + (size_t)(cvm__tri2_corner(T, u, x) + 1) % 3] / 3;
                    if (u == t)
                        *yes = 1;
                }
                if (P->in_cav[T->tn[h] / 3]) {
                    if (T->te && T->te[h] >= 0)
                        *yes = 1;
                    continue;
                }
                nbnd++;
                if (a >= 0 && b >= 0 &&
                    cvm__orient2d(pp, T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b) <= 0)
                    *yes = 1;
            }
        }
        if (nbnd != ncav + 2)
            *yes = 1;
    }
    for (i = 0; i < ncav; i++)
        P->in_cav[P->cav[i]] = 0;
    return CVM_OK;
}

/* Add a vertex at xy and insert it (domain only, min distance md); a rejected
 * one (also one that would_swallow refuses) is flagged gone. *added counts the
 * inserted ones. */
static cvm_status add_point(pre *P, const double *xy, double md, int32_t hint, size_t *added)
{
    cvm__tri2 *T = P->T;
    int32_t id, other;
    cvm__ins res;
    cvm_status s;
    int refuse = 0;
    if ((s = grow(P, T->nv + 1)))
        return s;
    if ((s = cvm__tri2_add_vertex(T, xy, &id)))
        return s;
    P->pick[id] = 0;
    if (T->w && (s = would_swallow(P, id, &refuse))) {
        P->pick[id] = 2;
        return s;
    }
    if (refuse) {
        P->pick[id] = 2;
        return CVM_OK;
    }
    if ((s = cvm__tri2_insert_vertex(T, id, hint, CVM__INSF_DOMAIN_ONLY, md, &res, &other))) {
        P->pick[id] = 2;
        return s;
    }
    if (res != CVM__INS_DONE)
        P->pick[id] = 2;
    else
        (*added)++;
    return CVM_OK;
}

static cvm_status round_once(pre *P, size_t nv0, size_t *nrem, size_t *nadd)
{
    cvm__tri2 *T = P->T;
    const cvm__dual_opt_params *p = P->p;
    cvm__ctx *ctx = T->ctx;
    size_t v, t, nv = T->nv, nmid = 0, cap_mid = 0, k, ngone = 0;
    cvm_status s;
    if ((s = grow(P, nv)) || (s = sizes(P)))
        return s;
    memset(P->pick, 0, nv);
    for (v = p->n_input; v < nv; v++)
        if (cvm__dual_removable(T, (int32_t)v, NULL) && wants_removal(P, (int32_t)v))
            P->pick[v] = 1;
    for (v = p->n_input; v < nv; v++)
        if (P->pick[v] == 1) {
            if (cvm__dual_remove_vertex(T, (int32_t)v, -1)) {
                P->pick[v] = 2;
                (*nrem)++;
            } else {
                P->pick[v] = 0;
            }
        }
    if ((s = cvm__tri2_make_regular(T, NULL)))
        return s;
    for (v = p->n_input; v < nv; v++)
        if (P->pick[v] == 2 && !isnan(P->seed_xy[2 * v])) {
            double xy[2];
            xy[0] = P->seed_xy[2 * v];
            xy[1] = P->seed_xy[2 * v + 1];
            if ((s = add_point(P, xy, PRE_SHORT * P->h[v], -1, nadd)))
                return s;
        }
    /* splits: list, then insert */
    for (t = 0; t < T->nt; t++) {
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * t + (size_t)j] / 3;
            int32_t a = T->tv[3 * t + (size_t)(j + 1) % 3], b = T->tv[3 * t + (size_t)(j + 2) % 3];
            double he, l2;
            if ((size_t)u <= t || !cvm__tri2_in_domain(T, u) || cvm__tri2_edge_seg(T, (int32_t)t, j) >= 0 ||
                (T->ta && T->ta[u] != T->ta[t]) || (size_t)a >= nv || (size_t)b >= nv)
                continue;
            he = 0.5 * (P->h[a] + P->h[b]);
            l2 = cvm__dist2(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b);
            if (!(he > 0) || l2 <= PRE_LONG * PRE_LONG * he * he)
                continue;
            if (nmid + 1 > cap_mid) {
                size_t nc = 2 * cap_mid + 64;
                double *m2 = cvm__realloc(ctx, P->mid, nc * 3 * sizeof *m2);
                if (!m2)
                    return CVM_E_NOMEM;
                P->mid = m2;
                cap_mid = nc;
            }
            P->mid[3 * nmid] = 0.5 * (T->xy[2 * (size_t)a] + T->xy[2 * (size_t)b]);
            P->mid[3 * nmid + 1] = 0.5 * (T->xy[2 * (size_t)a + 1] + T->xy[2 * (size_t)b + 1]);
            P->mid[3 * nmid + 2] = he;
            nmid++;
        }
    }
    for (k = 0; k < nmid; k++)
        if ((s = add_point(P, P->mid + 3 * k, PRE_SHORT * P->mid[3 * k + 2], -1, nadd)))
            return s;
    /* drop removed and rejected vertices; vmap follows */
    nv = T->nv;
    for (v = 0; v < nv; v++) {
        P->dup[v] = P->pick[v] == 2 ? 0 : -1; /* vertex 0 is an input point: never gone */
        ngone += P->pick[v] == 2;
    }
    if (!ngone)
        return CVM_OK;
    cvm__tri2_compact(T, P->dup, P->map);
    for (v = 0; v < nv; v++)
        if (P->pick[v] == 2)
            P->map[v] = -1;
    for (v = 0; v < nv0; v++)
        if (p->vmap[v] >= 0)
            p->vmap[v] = P->map[p->vmap[v]];
    return CVM_OK;
}

cvm_status cvm__dual_prepass(cvm__tri2 *T, const cvm__dual_opt_params *p, size_t nv0,
                             size_t *removed, size_t *added)
{
    pre P;
    int r;
    cvm_status s = CVM_OK;
    *removed = *added = 0;
    if (!p->vmap || p->n_input == 0)
        return CVM_OK;
    memset(&P, 0, sizeof P);
    P.T = T;
    P.p = p;
    P.sin2_target = sin((p->target_angle_deg < PRE_BAD_DEG ? p->target_angle_deg : PRE_BAD_DEG) *
                        CVM__PI / 180.0);
    P.sin2_target *= P.sin2_target;
    for (r = 0; r < PRE_ROUNDS && !s; r++) {
        size_t nr = 0, na = 0;
        s = round_once(&P, nv0, &nr, &na);
        *removed += nr;
        *added += na;
        if (!nr && !na)
            break;
    }
    if (!s)
        s = cvm__tri2_make_regular(T, NULL);
    cvm__free(T->ctx, P.h);
    cvm__free(T->ctx, P.pick);
    cvm__free(T->ctx, P.seed_xy);
    cvm__free(T->ctx, P.dup);
    cvm__free(T->ctx, P.map);
    cvm__free(T->ctx, P.mid);
    cvm__free(T->ctx, P.cav);
    cvm__free(T->ctx, P.in_cav);
    return s;
}
