/*
 * aflr.c - advancing-front local reconnection (Marcum 1995; Marcum and
 * Weatherill 1995) inside the Delaunay kernel: fronts grow from marked
 * segments, one point per front edge, every edge carrying a layer index.
 *
 * Layers: a constrained edge is 0 when its segment starts a front (else
 * infinite); an edge v-u made by inserting v for a front edge of layer L is
 * one more than the lowest of L and the layers of the two cavity boundary
 * edges at u beside it (L is infinite for a point from a segment split);
 * every other edge is infinite. A triangle is good when each edge is shorter than
 * AF_SIZE_BAD x the mean size at its ends and its smallest angle meets the
 * bound. A front edge is a front-starting segment or an edge between a good
 * and a bad triangle; a bad triangle with a front edge is queued, and its best
 * front edge (lowest layer, then shortest relative to the size) is its base.
 * The point lies on the base edge's perpendicular bisector, inside the bad
 * triangle's circumcircle: the nearest to the edge of the equilateral point
 * at the local size, the circumcentre and the shape- and size-optimal
 * off-centres; a candidate closer than AF_PROX x the edge to an existing
 * vertex (uniform grid, proximity_grid.c) is skipped. Insertion is
 * Bowyer-Watson with the refiner's encroachment rules (cvm__rf_insert_free),
 * so the "local reconnection" is the Delaunay cavity.
 *
 * Changes to the published rules (figures in docs/design/refiners.md):
 * - a new edge takes its layer from the base edge and the cavity boundary
 *   edges beside it, not the minimum over the whole cavity boundary: the
 *   first cavities reach across the domain to other boundaries, so the
 *   minimum labelled deep points layer 1 (islands of low layers);
 * - the queue orders by the Delaunay-refinement key (largest circumradius /
 *   size first, then worst shape), layer and relative edge length only
 *   breaking ties: in strict layer order curved fronts pile up their errors
 *   layer after layer;
 * - the equilateral point is taken at the local size clamped to
 *   [AF_SHRINK, AF_GROW] x the edge so one layer never jumps in size, and a
 *   rejected candidate falls back to the next one instead of dropping the edge.
 * The Delaunay-refinement clean-up (cvm__rf_delaunay), then the frontal
 * post-processing (swap, smooth, Delaunay restore), follow in refiner.c.
 *
 * Interleaved smoothing (CVM_OPT_AFLR_SMOOTH_LAYERS = N > 0): vertex layer k
 * holds the points placed for front edges of layer k - 1. The queue above
 * never finishes a layer before the end of the pass, so with N > 0 the
 * queue takes only front edges of layers below done + N (the key order holds
 * inside that band) and the others wait in a second queue; when the first
 * runs empty, layers done+1 .. done+N are complete: their free points whose
 * star is all good (and those of the group before, now off the front) are
 * smoothed, the Delaunay property restored (Bowyer-Watson cavities need it),
 * encroached subsegments split, the cached qualities and layers of the
 * changed triangles renewed, and both queues rebuilt for the next band.
 * The band order, not the smoothing, costs regularity on curved fronts,
 * hence off by default.
 *
 * Determinism: the edge-layer table is only looked up, never iterated; the
 * queue orders by (key, vertex ids).
 *
 * Cost: each triangle is measured once, when made (its quality is kept with
 * its edge layers per slot: the vertices do not move during the pass), and
 * the points carry frontal.c's 1e-9 jitter off the lattice.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine_internal.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Good needs every edge shorter than this times the mean size at its ends. */
#define AF_SIZE_BAD 1.5
/* A candidate point closer than this times the base edge to a vertex is rejected. */
#define AF_PROX 0.7
/* The equilateral point's edge length: the local size within these bounds x the base edge. */
#define AF_SHRINK 0.8
#define AF_GROW 1.25
/* Off-centres are used above this requested angle (degrees). */
#define AF_SHAPE_MIN_DEG 1.0
/* Weight of layer and edge length against shape in the queue key. */
#define AF_TIE 1e-6
/* A skinny (not too big) triangle is treated only from a front edge at least
 * this times the local size long; shorter ones are left to the clean-up. */
#define AF_MIN_BASE 0.5
/* Triangle qualities. */
enum { AF_OK = 0, AF_BIG = 1, AF_SKINNY = 2 };
/* With neither a sizing nor CVM_OPT_MAX_AREA nothing bounds the pass but the
 * shortest input edge, and above about 30 degrees its points cascade down to
 * that scale over the whole domain (millions on the cylinder at 34 degrees,
 * where Delaunay refinement needs 557): the pass then stops after this many
 * points per vertex it started with (about what Delaunay refinement needs on
 * the example domains), and the Delaunay clean-up finishes. */
#define AF_SIZELESS_CAP 4
/* Layer "infinite". */
#define AF_INF INT32_MAX
/* Interleaved smoothing (CVM_OPT_AFLR_SMOOTH_LAYERS): relaxation and smart
 * (or max-min) sweeps per completed group of layers. */
#define AF_SM_RELAX 2
#define AF_SM_SWEEPS 2
#ifndef AF_SM_BACK
#define AF_SM_BACK 1
#endif
/* The next and the previous corner of a triangle (faster than % 3 in the hot loops). */
static const int af_n1[3] = {1, 2, 0}, af_n2[3] = {2, 0, 1};

typedef struct af_state {
    int32_t *sl;               /* per triangle slot, 3: layer of each edge */
    int32_t *sv;               /* per slot, 3: its vertices when sl was written (sl is
                                  valid while they match the slot's) */
    unsigned char *sq;         /* per slot: quality (AF_OK ...) of the triangle in it,
                                  valid with sl (vertices fixed during the pass) */
    size_t cap_sl, cap_sv, cap_sq; /* in elements */
    int32_t *lo;               /* scratch per star triangle: layer of its outer edge */
    size_t cap_lo;
    unsigned char *front;      /* per segment id: starts a front */
    size_t nfront;
    cvm__vertex_grid grid;
    size_t ngrid;              /* vertices 0..ngrid-1 are in the grid */
    double lmin0;              /* shortest domain edge when the pass started */
    /* interleaved smoothing, only with nsm > 0 (see af_layers_done) */
    int32_t nsm;               /* CVM_OPT_AFLR_SMOOTH_LAYERS */
    cvm__bad_queue later;      /* triangles queued for a front edge of layer >= done + nsm */
    int32_t *vlay;             /* per vertex: its layer (base edge's + 1), AF_INF: none */
    size_t cap_vlay;
    int32_t done;              /* vertex layers 1..done are complete (and were smoothed) */
    int32_t maxlay;            /* highest vertex layer made so far */
    uint8_t *mask;             /* scratch: per vertex */
    int32_t *list;             /* scratch: the vertices of a group */
    double *old;               /* scratch: their coordinates before smoothing */
    int32_t *chg;              /* triangles whose records the smoothing renewed */
    size_t cap_mask, cap_list, cap_old, nchg, cap_chg;
} af_state;

static const double *af_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

/* Grow *p (int32_t) to at least need elements, the new ones set to fill;
 * 0, or 1 on NOMEM. */
static int af_grow_fill(cvm__ctx *ctx, int32_t **p, size_t *cap, size_t need, int32_t fill)
{
    size_t k = *cap;
    if (need <= *cap)
        return 0;
    if (cvm__grow(ctx, (void **)p, cap, need, sizeof **p))
        return 1;
    for (; k < *cap; k++)
        (*p)[k] = fill;
    return 0;
}

/* ---- edge layers, per triangle slot ---- */

/* 1 when the layers stored for slot t belong to the triangle now in it. */
static inline int af_slot_valid(const af_state *A, const cvm__tri2 *T, int32_t t)
{
    return 3 * (size_t)t + 2 < A->cap_sv && cvm__tri2_slot_holds(T, t, A->sv + 3 * (size_t)t);
}

/* Layer of edge j of triangle t: from its segment when constrained, else
 * what slot t (or the triangle across) stored, else AF_INF. */
static int32_t af_edge_layer(const cvm__refiner *R, int32_t t, int j)
{
    const af_state *A = R->aflr;
    const cvm__tri2 *T = R->T;
    int32_t seg = T->te[3 * (size_t)t + (size_t)j], h;
    if (seg >= 0)
        return (size_t)seg < A->nfront && A->front[seg] ? 0 : AF_INF;
    if (af_slot_valid(A, T, t))
        return A->sl[3 * (size_t)t + (size_t)j];
    h = T->tn[3 * (size_t)t + (size_t)j];
    if (af_slot_valid(A, T, h / 3))
        return A->sl[(size_t)h];
    return AF_INF;
}

/* Record the three edge layers of slot t and the quality q of its triangle.
 * CVM_OK or CVM_E_NOMEM. */
static cvm_status af_store(af_state *A, cvm__refiner *R, int32_t t, const int32_t *l, int q)
{
    size_t need = 3 * (size_t)t + 3;
    int k;
    if ((need > A->cap_sl && cvm__grow(R->ctx, (void **)&A->sl, &A->cap_sl, need, sizeof *A->sl)) ||
        af_grow_fill(R->ctx, &A->sv, &A->cap_sv, need, -1) || /* new slots hold no record */
        ((size_t)t >= A->cap_sq &&
         cvm__grow(R->ctx, (void **)&A->sq, &A->cap_sq, (size_t)t + 1, sizeof *A->sq)))
        return CVM_E_NOMEM;
    A->sq[t] = (unsigned char)q;
    for (k = 0; k < 3; k++) {
        A->sl[3 * (size_t)t + (size_t)k] = l[k];
        A->sv[3 * (size_t)t + (size_t)k] = R->T->tv[3 * (size_t)t + (size_t)k];
    }
    return CVM_OK;
}

/* ---- classification ---- */

/* Quality of domain triangle t: AF_OK (edges within the size, shape above
 * the bound, area within CVM_OPT_MAX_AREA; a triangle exempted at a small
 * input angle counts as good), AF_BIG (an edge or the area too large) or
 * AF_SKINNY (only the shape is bad). */
static int af_quality(cvm__refiner *R, int32_t t)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    const double *p[3];
    double l[3], cross, sin2;
    int k;
    for (k = 0; k < 3; k++)
        p[k] = af_pt(R, tv[k]);
    for (k = 0; k < 3; k++) {
        const double *a = p[af_n1[k]], *b = p[af_n2[k]];
        double ls = (R->vls[tv[af_n1[k]]] + R->vls[tv[af_n2[k]]]) / 2;
        l[k] = cvm__dist2(a, b);
        if (isfinite(ls) && !(l[k] < AF_SIZE_BAD * AF_SIZE_BAD * ls * ls))
            return AF_BIG;
    }
    cross = cvm__cross2(p[0], p[1], p[2]);
    if (cvm__rf_max_area(R, t) > 0 && cross / 2 > cvm__rf_max_area(R, t))
        return AF_BIG;
    sin2 = cross > 0 ? cvm__min_sin2_sides(l[0], l[1], l[2], cross) : 0.0;
    if (sin2 >= R->sin2_min && cross > 0)
        return AF_OK;
    return cvm__rf_classify(R, t, &sin2) == 3 ? AF_OK : AF_SKINNY;
}

/* Quality of triangle t, AF_BIG outside the domain. */
static int af_quality_any(cvm__refiner *R, int32_t t)
{
    return cvm__tri2_in_domain(R->T, t) ? af_quality(R, t) : AF_BIG;
}

/* af_quality_any, from slot t's record when it is valid: the vertices do not
 * move during the pass, so a triangle's quality never changes, and each
 * triangle is measured once, when made, instead of at every look. */
static inline int af_quality_cached(cvm__refiner *R, int32_t t)
{
    const af_state *A = R->aflr;
    if ((size_t)t < A->cap_sq && af_slot_valid(A, R->T, t))
        return A->sq[t];
    return af_quality_any(R, t);
}

/* 1 when t is only skinny and no size bounds it (no sizing at its corners):
 * queued in class 1 by its shortest edge (af_front_edge). */
static int af_sizeless_skinny(const cvm__refiner *R, int32_t t, int q)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    return q == AF_SKINNY && !isfinite(R->vls[tv[0]]) && !isfinite(R->vls[tv[1]]) &&
           !isfinite(R->vls[tv[2]]);
}

/* Squared shortest edge of the triangle with vertices tv. */
static double af_shortest2(const cvm__refiner *R, const int32_t *tv)
{
    double l0 = cvm__dist2(af_pt(R, tv[1]), af_pt(R, tv[2]));
    double l1 = cvm__dist2(af_pt(R, tv[2]), af_pt(R, tv[0]));
    double l2 = cvm__dist2(af_pt(R, tv[0]), af_pt(R, tv[1]));
    return l0 < l1 ? (l0 < l2 ? l0 : l2) : (l1 < l2 ? l1 : l2);
}

/* Best front edge of bad triangle t of quality q (lowest layer, then shortest relative to
 * the size): *j_out, *layer_out, *key_out (the queue key). When t is only
 * skinny, edges shorter than AF_MIN_BASE x the size at them (without a size:
 * x the shortest edge at the start of the pass) do not count: each point then
 * keeps at least AF_PROX x AF_MIN_BASE x that length from every vertex, which
 * bounds the pass. Returns 0 when t has no front edge. */
static int af_front_edge(cvm__refiner *R, int32_t t, int q, int *j_out, int32_t *layer_out,
                         double *key_out)
{
    const af_state *A = R->aflr;
    const cvm__tri2 *T = R->T;
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int j, found = 0, skinny = q == AF_SKINNY, tvalid = af_slot_valid(A, T, t);
    double best = 0, sin2, tie;
    for (j = 0; j < 3; j++) {
        int32_t a = tv[af_n1[j]], b = tv[af_n2[j]], h = T->tn[3 * (size_t)t + (size_t)j];
        int32_t layer;
        const double *pa, *pb;
        double le2, ls, rel2, dx, dy;
        if (T->te[3 * (size_t)t + (size_t)j] >= 0) {
            layer = af_edge_layer(R, t, j);
            if (layer == AF_INF)
                continue;
        } else {
            int32_t nb = h / 3;
            if (!cvm__tri2_in_domain(T, nb))
                continue;
            if (af_slot_valid(A, T, nb)) { /* both looks at nb's record at once */
                if (A->sq[nb] != AF_OK)
                    continue;
                layer = tvalid ? A->sl[3 * (size_t)t + (size_t)j] : A->sl[(size_t)h];
            } else {
                if (af_quality_any(R, nb) != AF_OK)
                    continue;
                layer = tvalid ? A->sl[3 * (size_t)t + (size_t)j] : AF_INF;
            }
        }
        /* squared lengths: the square root only for the chosen edge */
        pa = af_pt(R, a);
        pb = af_pt(R, b);
        dx = pa[0] - pb[0];
        dy = pa[1] - pb[1];
        le2 = dx * dx + dy * dy;
        ls = (R->vls[a] + R->vls[b]) / 2;
        if (!isfinite(ls)) {
            if (skinny && !(le2 >= AF_MIN_BASE * AF_MIN_BASE * A->lmin0 * A->lmin0))
                continue;
            rel2 = le2;
        } else {
            if (skinny && !(le2 >= AF_MIN_BASE * AF_MIN_BASE * ls * ls))
                continue;
            rel2 = le2 / (ls * ls);
        }
        if (!found || layer < *layer_out || (layer == *layer_out && rel2 < best)) {
            found = 1;
            best = rel2;
            *layer_out = layer;
            *j_out = j;
        }
    }
    if (!found)
        return 0;
    tie = (*layer_out == AF_INF ? 1.0 : 1.0 - 1.0 / (2.0 + *layer_out)) + (sqrt(best) / (1.0 + sqrt(best)));
    if (af_sizeless_skinny(R, t, q)) {
        /* no size: the shortest edge first, as Delaunay refinement orders its
         * skinny triangles; with the worst shape first the points cascade
         * into ever smaller clusters at 34 degrees (millions of points on the
         * cylinder) */
        *key_out = af_shortest2(R, tv) * (1.0 + AF_TIE * tie);
        return 1;
    }
    cvm__rf_classify(R, t, &sin2);
    /* the Delaunay-refinement key: -(circumradius / size)^2 when too big (the
     * largest first), else sin^2 of the smallest angle (the worst first); then
     * lower layer, then shorter edge (tiny terms) */
    *key_out = (isfinite(sin2) ? sin2 : 0) + AF_TIE * tie;
    return 1;
}

/* Queue domain triangle t when it is bad and has a front edge; its quality
 * into *q_out (AF_BIG outside the domain). */
static cvm_status af_queue_triangle(cvm__refiner *R, int32_t t, int *q_out)
{
    af_state *A = R->aflr;
    int j, q;
    int32_t layer;
    double key;
    *q_out = AF_BIG;
    if (!cvm__tri2_in_domain(R->T, t))
        return CVM_OK;
    *q_out = q = af_quality_cached(R, t);
    if (q == AF_OK || !af_front_edge(R, t, q, &j, &layer, &key))
        return CVM_OK;
    /* with interleaved smoothing, the layers beyond the current group wait */
    if (cvm__bq_push(A->nsm && layer != AF_INF && layer >= A->done + A->nsm ? &A->later : &R->q,
                     R->T, t, af_sizeless_skinny(R, t, q), key))
        return cvm__nomem(R->ctx);
    return CVM_OK;
}

/* After vertex v was inserted (by this pass for a front edge of layer
 * base_layer, or by a segment split: AF_INF): give each spoke its layer, one
 * more than the lowest of base_layer and the cavity boundary edges beside
 * the spoke; add it to the grid, queue its star and the triangles
 * across the star's outer edges. */
static cvm_status af_new_vertex(cvm__refiner *R, int32_t v, int32_t base_layer)
{
    af_state *A = R->aflr;
    const cvm__tri2 *T = R->T;
    size_t n = cvm__rf_star(R, v), k;
    cvm_status s;
    if (n == 0 || (n > A->cap_lo && cvm__grow(R->ctx, (void **)&A->lo, &A->cap_lo, n, sizeof *A->lo)))
        return cvm__nomem(R->ctx);
    for (; A->ngrid <= (size_t)v; A->ngrid++)
        if (cvm__vertex_grid_add(&A->grid, (int32_t)A->ngrid, af_pt(R, (int32_t)A->ngrid)))
            return cvm__nomem(R->ctx);
    if (A->nsm) {
        if (af_grow_fill(R->ctx, &A->vlay, &A->cap_vlay, (size_t)v + 1, AF_INF))
            return cvm__nomem(R->ctx);
        A->vlay[v] = base_layer == AF_INF ? AF_INF : base_layer + 1;
        if (base_layer != AF_INF && base_layer + 1 > A->maxlay)
            A->maxlay = base_layer + 1;
    }
    /* the outer (cavity boundary) edge of each star triangle keeps its layer,
     * read from the unchanged triangle across it */
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        int32_t h = T->tn[3 * (size_t)t + (size_t)i];
        A->lo[k] = T->te[3 * (size_t)t + (size_t)i] >= 0 ? af_edge_layer(R, t, i)
                   : af_slot_valid(A, T, h / 3) ? A->sl[(size_t)h] : AF_INF;
    }
    /* each spoke: one more than the lowest of the base edge and the outer
     * edges of the two star triangles beside it (star[k] and star[k + 1]
     * share the spoke opposite tv[i + 1] of star[k]) */
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k], l[3], m;
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        size_t next = (k + 1) % n, prev = (k + n - 1) % n;
        l[i] = A->lo[k];
        m = A->lo[k] < A->lo[next] ? A->lo[k] : A->lo[next];
        m = !cvm__tri2_in_domain(T, t) || !cvm__tri2_in_domain(T, R->star[next]) ? AF_INF : m;
        m = base_layer < m ? base_layer : m;
        l[af_n1[i]] = m == AF_INF ? AF_INF : m + 1;
        m = A->lo[k] < A->lo[prev] ? A->lo[k] : A->lo[prev];
        m = !cvm__tri2_in_domain(T, t) || !cvm__tri2_in_domain(T, R->star[prev]) ? AF_INF : m;
        m = base_layer < m ? base_layer : m;
        l[af_n2[i]] = m == AF_INF ? AF_INF : m + 1;
        if (af_store(A, R, t, l, af_quality_any(R, t)))
            return cvm__nomem(R->ctx);
    }
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        /* the triangle across the outer edge gains a front edge only when t is good */
        int q, qn;
        if ((s = af_queue_triangle(R, t, &q)) ||
            (q == AF_OK && (s = af_queue_triangle(R, T->tn[3 * (size_t)t + (size_t)i] / 3, &qn))))
            return s;
    }
    return CVM_OK;
}

/* R->queue_star during the pass: a vertex inserted by a segment split. */
static cvm_status af_queue_star(cvm__refiner *R, int32_t v)
{
    return af_new_vertex(R, v, AF_INF);
}

/* ---- point placement ---- */

/* Candidate distances from the midpoint of edge j of t along its inward
 * normal, ascending, into d (at most 4); returns their number. */
static int af_candidates(cvm__refiner *R, int32_t t, int j, const double *m, const double *nrm,
                         double le, double *d)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    double c[2], dc, rad, h = (R->vls[tv[af_n1[j]]] + R->vls[tv[af_n2[j]]]) / 2;
    double cand[4], lim, L;
    int n = 0, a, b;
    cvm__circumcenter2d(af_pt(R, tv[0]), af_pt(R, tv[1]), af_pt(R, tv[2]), c);
    dc = (c[0] - m[0]) * nrm[0] + (c[1] - m[1]) * nrm[1];
    rad = hypot(c[0] - af_pt(R, tv[af_n1[j]])[0], c[1] - af_pt(R, tv[af_n1[j]])[1]);
    lim = dc + rad; /* beyond this the point leaves t's circumcircle */
    if (!isfinite(lim) || !(lim > 0))
        return 0;
    /* equilateral point at the local size, clamped against jumps */
    L = isfinite(h) ? h : le;
    L = L < AF_SHRINK * le ? AF_SHRINK * le : L > AF_GROW * le ? AF_GROW * le : L;
    cand[n++] = sqrt(L * L - le * le / 4);
    if (dc > 0)
        cand[n++] = dc;
    if (R->p->min_angle_deg >= AF_SHAPE_MIN_DEG)
        cand[n++] = le / (2 * tan(R->p->min_angle_deg * CVM__PI / 360.0));
    if (isfinite(h) && h > le / 2)
        cand[n++] = sqrt(h * h - le * le / 4);
    /* sort (n <= 4) and keep those inside the circumcircle */
    for (a = 1; a < n; a++)
        for (b = a; b > 0 && cand[b] < cand[b - 1]; b--) {
            double x = cand[b];
            cand[b] = cand[b - 1];
            cand[b - 1] = x;
        }
    for (a = b = 0; a < n; a++)
        if (cand[a] > 0 && cand[a] < lim)
            d[b++] = cand[a];
    return b;
}

/* The point for front edge j of bad triangle t into x; 0 when every
 * candidate is too close to an existing vertex. */
static int af_point(cvm__refiner *R, int32_t t, int j, double *x)
{
    af_state *A = R->aflr;
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    const double *p = af_pt(R, tv[af_n1[j]]), *q = af_pt(R, tv[af_n2[j]]);
    double le = hypot(q[0] - p[0], q[1] - p[1]), m[2], nrm[2], d[4], r, jit;
    int n, k;
    if (!(le > 0))
        return 0;
    m[0] = (p[0] + q[0]) / 2;
    m[1] = (p[1] + q[1]) / 2;
    nrm[0] = -(q[1] - p[1]) / le; /* t lies left of p -> q */
    nrm[1] = (q[0] - p[0]) / le;
    n = af_candidates(R, t, j, m, nrm, le, d);
    r = AF_PROX * le;
    jit = cvm__rf_lattice_jitter(R->T->nv);
    for (k = 0; k < n; k++) {
        x[0] = m[0] + d[k] * jit * nrm[0];
        x[1] = m[1] + d[k] * jit * nrm[1];
        if (!cvm__vertex_grid_any_within(&A->grid, R->T->xy, x, r))
            return 1;
    }
    return 0;
}

/* ---- interleaved smoothing (CVM_OPT_AFLR_SMOOTH_LAYERS) ---- */

/* The next band (done was just raised): the waiting triangles go to the
 * queue whose band now holds them, and the triangles renewed by the smoothing
 * (A->chg) and those across their edges are queued again (the smoothing
 * changed their quality, so their front edges). */
static cvm_status af_requeue_next(cvm__refiner *R)
{
    af_state *A = R->aflr;
    cvm__bad_entry e;
    size_t n = 0, k;
    cvm_status s;
    int q;
    while (cvm__bq_pop(&A->later, &e)) {
        if (!cvm__bq_valid(R->T, &e))
            continue;
        if (n >= A->cap_list &&
            cvm__grow(R->ctx, (void **)&A->list, &A->cap_list, n + 1, sizeof *A->list))
            return cvm__nomem(R->ctx);
        A->list[n++] = e.t;
    }
    for (k = 0; k < n; k++)
        if ((s = af_queue_triangle(R, A->list[k], &q)))
            return s;
    for (k = 0; k < A->nchg; k++) {
        int32_t t = A->chg[k];
        int j;
        if ((s = af_queue_triangle(R, t, &q)))
            return s;
        for (j = 0; j < 3; j++)
            if ((s = af_queue_triangle(R, R->T->tn[3 * (size_t)t + (size_t)j] / 3, &q)))
                return s;
    }
    A->nchg = 0;
    return CVM_OK;
}

/* Smooth the free vertices of layers lo+1..hi with the configured method
 * (AF_SM_RELAX + AF_SM_SWEEPS sweeps), restore the Delaunay property (the
 * cavities of the next insertions need it), split the subsegments a moved
 * vertex encroaches, and bring the pass's records up to date: the moved
 * vertices in the proximity grid, the quality (and layers, for the flipped
 * triangles) of every triangle that changed. */
static cvm_status af_smooth_group(cvm__refiner *R, int32_t lo, int32_t hi)
{
    af_state *A = R->aflr;
    cvm__tri2 *T = R->T;
    const cvm__refine_params *p = R->p;
    size_t nv = T->nv, v, n = 0, first = nv, k, t, moved = 0;
    A->nchg = 0;
    cvm_status s = CVM_OK, s2 = CVM_OK;
    if (nv > A->cap_mask &&
        cvm__grow(R->ctx, (void **)&A->mask, &A->cap_mask, nv, sizeof *A->mask))
        return cvm__nomem(R->ctx);
    for (v = 0; v < nv; v++) {
        int32_t l = v < A->cap_vlay ? A->vlay[v] : AF_INF;
        size_t ns;
        A->mask[v] = 0;
        if (l == AF_INF || l <= lo - AF_SM_BACK * A->nsm || l > hi || R->vseg[v] != -1)
            continue;
        /* a point on the front (a star triangle still bad) waits: the centroid of
         * its neighbours lies in the unrefined part */
        if ((ns = cvm__rf_star(R, (int32_t)v)) == 0)
            return cvm__nomem(R->ctx);
        for (k = 0; k < ns && af_quality_cached(R, R->star[k]) == AF_OK; k++)
            ;
        if (k < ns)
            continue;
        A->mask[v] = 1;
        if ((n >= A->cap_list &&
             cvm__grow(R->ctx, (void **)&A->list, &A->cap_list, n + 1, sizeof *A->list)) ||
            (2 * n + 2 > A->cap_old &&
             cvm__grow(R->ctx, (void **)&A->old, &A->cap_old, 2 * n + 2, sizeof *A->old)))
            return cvm__nomem(R->ctx);
        A->list[n] = (int32_t)v;
        A->old[2 * n] = T->xy[2 * v];
        A->old[2 * n + 1] = T->xy[2 * v + 1];
        n++;
        if (v < first)
            first = v;
    }
    if (n == 0)
        return CVM_OK;
    if (p->smooth_method != 1)
        s = cvm__rf_smooth(R, first, A->mask, AF_SM_RELAX, AF_SM_SWEEPS, NULL);
    if (!s && p->smooth_method != 0)
        s = cvm__rf_smooth_maxmin(R, first, A->mask, AF_SM_SWEEPS, p->smooth_method == 3, NULL);
    /* the mask now marks the vertices that moved; the list keeps only them */
    for (k = 0; k < n; k++) {
        int32_t w = A->list[k];
        const double *x = af_pt(R, w), *o = A->old + 2 * k;
        int m = x[0] != o[0] || x[1] != o[1];
        A->mask[w] = (uint8_t)m;
        if (m && (size_t)w < A->ngrid)
            cvm__vertex_grid_move(&A->grid, w, o, x);
        if (m)
            A->list[moved++] = w;
    }
    if (!moved)
        return s;
    /* only edges at the moved points can have lost the Delaunay property; on
     * NOMEM (and after an error above) the allocation-free global restore */
    if (s || (s2 = cvm__tri2_legalize_stars(T, A->list, moved)) != CVM_OK) {
        (void)cvm__rf_restore_delaunay(T, NULL);
        return s ? s : cvm__nomem(R->ctx);
    }
    /* the triangles at a moved vertex keep their layers but not their quality;
     * a flipped one takes its outer edges' layers from the triangles across */
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        int32_t l[3];
        int j;
        if (T->tf[t] & CVM__TF_DEAD)
            continue;
        if (af_slot_valid(A, T, (int32_t)t)) {
            int touched = 0;
            for (j = 0; j < 3; j++)
                touched |= tv[j] >= 0 && A->mask[tv[j]];
            if (!touched)
                continue;
        }
        for (j = 0; j < 3; j++)
            l[j] = af_edge_layer(R, (int32_t)t, j);
        if (af_store(A, R, (int32_t)t, l, af_quality_any(R, (int32_t)t)) ||
            (A->nchg >= A->cap_chg &&
             cvm__grow(R->ctx, (void **)&A->chg, &A->cap_chg, A->nchg + 1, sizeof *A->chg)))
            return cvm__nomem(R->ctx);
        A->chg[A->nchg++] = (int32_t)t;
    }
    /* a subsegment newly encroached is encroached by a moved point, the apex
     * of a triangle beside it (constrained Delaunay) */
    for (k = 0; k < moved; k++)
        if ((s = cvm__rf_queue_encroached_star(R, A->list[k])))
            return s;
    return cvm__rf_split_queued(R);
}

/* The queue of the current group ran empty: with interleaved smoothing,
 * smooth the group's layers done+1 .. done+nsm and move on to the next group
 * (*more = 1) unless nothing is left (*more = 0). Vertex layer k holds the
 * points placed for front edges of layer k - 1; the queue takes only front
 * edges of layers below done + nsm (the others wait in A->later), so when it
 * is empty no more points of layers <= done + nsm will be placed. */
static cvm_status af_next_group(cvm__refiner *R, int *more)
{
    af_state *A = R->aflr;
    cvm_status s;
    *more = 0;
    if (!A->nsm || (A->later.n == 0 && A->maxlay <= A->done))
        return CVM_OK;
    if ((s = af_smooth_group(R, A->done, A->done + A->nsm)))
        return s;
    A->done += A->nsm;
    *more = 1;
    return af_requeue_next(R);
}

/* ---- set-up and the pass ---- */

static cvm_status af_setup(cvm__refiner *R)
{
    const cvm__tri2 *T = R->T;
    af_state *A = cvm__calloc(R->ctx, 1, sizeof *A);
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, cs = INFINITY;
    size_t k;
    if (!A)
        return cvm__nomem(R->ctx);
    R->aflr = A;
    cvm__bq_init(&A->later, R->ctx);
    A->nsm = R->p->aflr_smooth_layers > 0 && !T->w ? R->p->aflr_smooth_layers : 0;
    A->nfront = R->nseg;
    A->front = cvm__malloc(R->ctx, R->nseg + 1);
    if (!A->front)
        return cvm__nomem(R->ctx);
    for (k = 0; k < R->nseg; k++)
        A->front[k] = !R->p->seg_front ? 1 : k < R->p->nseg ? R->p->seg_front[k] != 0 : 0;
    for (k = 0; k < T->nt; k++) { /* every unconstrained edge starts at layer infinite */
        static const int32_t inf3[3] = {AF_INF, AF_INF, AF_INF};
        if (af_store(A, R, (int32_t)k, inf3, af_quality_any(R, (int32_t)k)))
            return cvm__nomem(R->ctx);
    }
    for (k = 0; k < T->nv; k++) {
        const double *p = af_pt(R, (int32_t)k);
        if (T->vtri[k] < 0)
            continue;
        x0 = p[0] < x0 ? p[0] : x0;
        x1 = p[0] > x1 ? p[0] : x1;
        y0 = p[1] < y0 ? p[1] : y0;
        y1 = p[1] > y1 ? p[1] : y1;
        if (R->vls[k] < cs)
            cs = R->vls[k];
    }
    if (!isfinite(x0))
        x0 = y0 = 0, x1 = y1 = 1;
    A->lmin0 = INFINITY;
    for (k = 0; k < T->nt; k++) {
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)k))
            continue;
        for (j = 0; j < 3; j++) {
            const double *a = af_pt(R, T->tv[3 * k + (size_t)af_n1[j]]);
            const double *b = af_pt(R, T->tv[3 * k + (size_t)af_n2[j]]);
            double l = hypot(a[0] - b[0], a[1] - b[1]);
            A->lmin0 = l < A->lmin0 ? l : A->lmin0;
        }
    }
    if (cvm__vertex_grid_init(&A->grid, R->ctx, x0, y0, x1, y1, cs, 4 * T->nv + (1u << 20)))
        return cvm__nomem(R->ctx);
    for (; A->ngrid < T->nv; A->ngrid++)
        if (T->vtri[A->ngrid] >= 0 &&
            cvm__vertex_grid_add(&A->grid, (int32_t)A->ngrid, af_pt(R, (int32_t)A->ngrid)))
            return cvm__nomem(R->ctx);
    return CVM_OK;
}

void cvm__rf_aflr_free(cvm__refiner *R)
{
    af_state *A = R->aflr;
    if (!A)
        return;
    cvm__vertex_grid_destroy(&A->grid);
    cvm__free(R->ctx, A->sl);
    cvm__free(R->ctx, A->sv);
    cvm__free(R->ctx, A->sq);
    cvm__free(R->ctx, A->lo);
    cvm__free(R->ctx, A->front);
    cvm__bq_destroy(&A->later);
    cvm__free(R->ctx, A->vlay);
    cvm__free(R->ctx, A->mask);
    cvm__free(R->ctx, A->list);
    cvm__free(R->ctx, A->old);
    cvm__free(R->ctx, A->chg);
    cvm__free(R->ctx, A);
    R->aflr = NULL;
}

cvm_status cvm__rf_aflr(cvm__refiner *R)
{
    cvm__bad_entry e;
    cvm_status s;
    size_t t, cap = (size_t)-1;
    int q;
    if ((s = af_setup(R)))
        return s;
    if (cvm__sizing_is_empty(R->p->sizing) && !(R->p->max_area > 0))
        cap = R->steiner + AF_SIZELESS_CAP * R->T->nv;
    R->queue_star = af_queue_star;
    cvm__bq_clear(&R->q);
    for (t = 0; t < R->T->nt; t++)
        if ((s = af_queue_triangle(R, (int32_t)t, &q)))
            return s;
    for (;;) {
        double key, x[2];
        int32_t v, layer;
        int j, r;
        if (!cvm__bq_pop(&R->q, &e)) {
            /* the current group of layers is complete */
            int more;
            if ((s = af_next_group(R, &more)))
                return s;
            if (!more)
                break;
            continue;
        }
        if (!cvm__bq_valid(R->T, &e) || (q = af_quality_cached(R, e.t)) == AF_OK ||
            !af_front_edge(R, e.t, q, &j, &layer, &key))
            continue;
        if (!af_point(R, e.t, j, x))
            continue; /* every candidate too close: left to the clean-up */
        if (R->steiner >= cap)
            break;
        r = cvm__rf_insert_free(R, e.t, x, &v, &s);
        if (s)
            return s;
        if (r == CVM__RF_DONE)
            s = af_new_vertex(R, v, layer);
        else if (r == CVM__RF_SPLIT && cvm__bq_valid(R->T, &e))
            s = cvm__bq_push(&R->q, R->T, e.t, e.cls, e.key) ? cvm__nomem(R->ctx) : CVM_OK;
        if (!s)
            s = cvm__rf_split_queued(R);
        if (s)
            return s;
    }
    R->queue_star = cvm__rf_queue_star;
    return CVM_OK;
}

/* ---- output: the layer index of each cell ---- */

/* Pass layers on along the ne layerless edges ie (2 vertices each): the
 * fixed point of vl[b] = min(vl[b], vl[a] + 1) over them, i.e. the distance
 * in edges from the layered vertices, each starting at its own layer: one
 * breadth-first search that takes its sources in order of their layer (ties
 * by index), linear in the edges apart from that sort. CVM_OK or CVM_E_NOMEM. */
static int cmp_pair32(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

static cvm_status af_pass_layers(cvm__refiner *R, int32_t *vl, const int32_t *ie, size_t ne)
{
    size_t nv = R->T->nv, k, ns = 0, head = 0, tail = 0, si = 0;
    size_t *first = cvm__calloc(R->ctx, nv + 2, sizeof *first);
    int32_t *adj = cvm__malloc(R->ctx, (2 * ne + 1) * sizeof *adj);
    int32_t *fifo = cvm__malloc(R->ctx, (nv + 1) * sizeof *fifo);
    int32_t *src = cvm__malloc(R->ctx, (2 * nv + 1) * sizeof *src);
    cvm_status s = CVM_OK;
    if (!first || !adj || !fifo || !src) {
        s = cvm__nomem(R->ctx);
        goto out;
    }
    for (k = 0; k < 2 * ne; k++)
        first[ie[k] + 2]++;
    for (k = 2; k < nv + 2; k++)
        first[k] += first[k - 1];
    for (k = 0; k < ne; k++) {
        adj[first[ie[2 * k] + 1]++] = ie[2 * k + 1];
        adj[first[ie[2 * k + 1] + 1]++] = ie[2 * k];
    }
    for (k = 0; k < nv; k++)
        if (vl[k] != AF_INF && first[k + 1] > first[k]) {
            src[2 * ns] = vl[k];
            src[2 * ns++ + 1] = (int32_t)k;
        }
    qsort(src, ns, 2 * sizeof *src, cmp_pair32);
    /* the FIFO's layers never decrease; the next vertex is the lower of its
     * head and the next source (a source lowered since was queued then) */
    while (head < tail || si < ns) {
        int32_t u, w;
        size_t e;
        if (si < ns && (head == tail || src[2 * si] <= vl[fifo[head]])) {
            u = src[2 * si + 1];
            if (src[2 * si++] != vl[u])
                continue;
        } else {
            u = fifo[head++];
        }
        for (e = first[u]; e < first[u + 1]; e++)
            if (vl[u] + 1 < vl[w = adj[e]]) {
                vl[w] = vl[u] + 1;
                fifo[tail++] = w;
            }
    }
out:
    cvm__free(R->ctx, first);
    cvm__free(R->ctx, adj);
    cvm__free(R->ctx, fifo);
    cvm__free(R->ctx, src);
    return s;
}

cvm_status cvm__rf_aflr_cell_layers(cvm__refiner *R, double **out)
{
    const cvm__tri2 *T = R->T;
    int32_t *vl, *el, *ie; /* ie: the layerless edges, 2 vertices each */
    double *cl;
    size_t t, ne = 0;
    *out = NULL;
    if (!R->aflr)
        return CVM_OK;
    vl = cvm__malloc(R->ctx, (T->nv + 1) * sizeof *vl);
    el = cvm__malloc(R->ctx, (3 * T->nt + 1) * sizeof *el);
    cl = cvm__malloc(R->ctx, (T->nt + 1) * sizeof *cl);
    ie = cvm__malloc(R->ctx, (6 * T->nt + 1) * sizeof *ie);
    if (!vl || !el || !cl || !ie) {
        cvm__free(R->ctx, vl);
        cvm__free(R->ctx, el);
        cvm__free(R->ctx, cl);
        cvm__free(R->ctx, ie);
        return cvm__nomem(R->ctx);
    }
    for (t = 0; t < T->nv; t++)
        vl[t] = AF_INF;
    /* each edge's layer once, and the lowest known layer at each vertex */
    for (t = 0; t < T->nt; t++) {
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t l = af_edge_layer(R, (int32_t)t, j), a = T->tv[3 * t + (size_t)af_n1[j]];
            int32_t b = T->tv[3 * t + (size_t)af_n2[j]];
            el[3 * t + (size_t)j] = l;
            vl[a] = l < vl[a] ? l : vl[a];
            vl[b] = l < vl[b] ? l : vl[b];
            if (l == AF_INF) {
                ie[2 * ne] = a;
                ie[2 * ne + 1] = b;
                ne++;
            }
        }
    }
    /* edges without a layer (made after the fronts stopped) pass one more
     * than the lower end's on */
    if (af_pass_layers(R, vl, ie, ne)) {
        cvm__free(R->ctx, vl);
        cvm__free(R->ctx, el);
        cvm__free(R->ctx, cl);
        cvm__free(R->ctx, ie);
        return CVM_E_NOMEM;
    }
    for (t = 0; t < T->nt; t++) {
        int32_t lo = AF_INF, hi = -1;
        int j;
        cl[t] = -1;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t l = el[3 * t + (size_t)j];
            if (l == AF_INF) { /* made after the pass, or a segment that starts no front */
                int32_t a = vl[T->tv[3 * t + (size_t)af_n1[j]]];
                int32_t b = vl[T->tv[3 * t + (size_t)af_n2[j]]];
                l = a < b ? a : b;
                l = l == AF_INF ? AF_INF : l + 1;
            }
            lo = l < lo ? l : lo;
            hi = l > hi ? l : hi;
        }
        if (hi != AF_INF)
            cl[t] = (double)hi + 0.1 * (double)lo;
    }
    cvm__free(R->ctx, vl);
    cvm__free(R->ctx, el);
    cvm__free(R->ctx, ie);
    *out = cl;
    return CVM_OK;
}
