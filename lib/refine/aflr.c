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
 * Bowyer-Watson with the refiner's encroachment rules (cvm__rf_try_interior_point),
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
 *
 * Files: this one sets the pass up and runs it; aflr_front.c judges
 * triangles, finds their front edges, queues them and places points;
 * aflr_smooth.c smooths completed groups of layers; aflr_layers.c keeps the
 * edge layers and gives the output's cell layers; aflr_internal.h holds the
 * state and the tuning constants.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aflr_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

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
        if (cvm__af_store(A, R, (int32_t)k, inf3, cvm__af_quality_any(R, (int32_t)k)))
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
    R->queue_star = cvm__af_queue_star;
    cvm__bq_clear(&R->q);
    for (t = 0; t < R->T->nt; t++)
        if ((s = cvm__af_queue_triangle(R, (int32_t)t, &q)))
            return s;
    for (;;) {
        double key, x[2];
        int32_t v, layer;
        int j, r;
        if (!cvm__bq_pop(&R->q, &e)) {
            /* the current group of layers is complete */
            int more;
            if ((s = cvm__af_next_group(R, &more)))
                return s;
            if (!more)
                break;
            continue;
        }
        if (!cvm__bq_valid(R->T, &e) || (q = af_quality_cached(R, e.t)) == AF_OK ||
            !cvm__af_front_edge(R, e.t, q, &j, &layer, &key))
            continue;
        if (!cvm__af_point(R, e.t, j, x))
            continue; /* every candidate too close: left to the clean-up */
        if (R->steiner >= cap)
            break;
        r = cvm__rf_try_interior_point(R, e.t, x, &v, &s);
        if (s)
            return s;
        if (r == CVM__RF_DONE)
            s = cvm__af_new_vertex(R, v, layer);
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
