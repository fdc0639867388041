/* aflr_front.c - the advancing-front pass's view of a triangle: its quality, its best front edge, the queue of bad triangles with a front edge, the layers of a new vertex's spokes, and the point placed for a front edge (see aflr.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aflr_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

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
int cvm__af_quality_any(cvm__refiner *R, int32_t t)
{
    return cvm__tri2_in_domain(R->T, t) ? af_quality(R, t) : AF_BIG;
}

/* 1 when t is only skinny and no size bounds it (no sizing at its corners):
 * queued in class 1 by its shortest edge (cvm__af_front_edge). */
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
int cvm__af_front_edge(cvm__refiner *R, int32_t t, int q, int *j_out, int32_t *layer_out,
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
            layer = cvm__af_edge_layer(R, t, j);
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
                if (cvm__af_quality_any(R, nb) != AF_OK)
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
cvm_status cvm__af_queue_triangle(cvm__refiner *R, int32_t t, int *q_out)
{
    af_state *A = R->aflr;
    int j, q;
    int32_t layer;
    double key;
    *q_out = AF_BIG;
    if (!cvm__tri2_in_domain(R->T, t))
        return CVM_OK;
    *q_out = q = af_quality_cached(R, t);
    if (q == AF_OK || !cvm__af_front_edge(R, t, q, &j, &layer, &key))
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
cvm_status cvm__af_new_vertex(cvm__refiner *R, int32_t v, int32_t base_layer)
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
        A->lo[k] = T->te[3 * (size_t)t + (size_t)i] >= 0 ? cvm__af_edge_layer(R, t, i)
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
        if (cvm__af_store(A, R, t, l, cvm__af_quality_any(R, t)))
            return cvm__nomem(R->ctx);
    }
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        /* the triangle across the outer edge gains a front edge only when t is good */
        int q, qn;
        if ((s = cvm__af_queue_triangle(R, t, &q)) ||
            (q == AF_OK && (s = cvm__af_queue_triangle(R, T->tn[3 * (size_t)t + (size_t)i] / 3, &qn))))
            return s;
    }
    return CVM_OK;
}

/* R->queue_star during the pass: a vertex inserted by a segment split. */
cvm_status cvm__af_queue_star(cvm__refiner *R, int32_t v)
{
    return cvm__af_new_vertex(R, v, AF_INF);
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
int cvm__af_point(cvm__refiner *R, int32_t t, int j, double *x)
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
