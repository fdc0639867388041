/* aflr_smooth.c - interleaved smoothing of the advancing-front pass (CVM_OPT_AFLR_SMOOTH_LAYERS, see aflr.c): each completed group of layers is smoothed, the Delaunay property restored and the pass's records and queues renewed. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aflr_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

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
        if ((s = cvm__af_queue_triangle(R, A->list[k], &q)))
            return s;
    for (k = 0; k < A->nchg; k++) {
        int32_t t = A->chg[k];
        int j;
        if ((s = cvm__af_queue_triangle(R, t, &q)))
            return s;
        for (j = 0; j < 3; j++)
            if ((s = cvm__af_queue_triangle(R, R->T->tn[3 * (size_t)t + (size_t)j] / 3, &q)))
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
            l[j] = cvm__af_edge_layer(R, (int32_t)t, j);
        if (cvm__af_store(A, R, (int32_t)t, l, cvm__af_quality_any(R, (int32_t)t)) ||
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
cvm_status cvm__af_next_group(cvm__refiner *R, int *more)
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
