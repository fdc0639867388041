/* refiner_state.c - what every refinement algorithm does to the shared refiner state: stars of
 * vertices, the record of a new vertex, the Steiner budget and run control, and the queue of
 * subsegments to split. The algorithms (delaunay_refine.c, frontal.c, aflr.c, split_segment.c)
 * call these and refiner.c drives them, so no algorithm file depends on the driver. */
#include "refine_internal.h"

size_t cvm__rf_star(cvm__refiner *R, int32_t v)
{
    size_t n = cvm__tri2_star(R->T, v, R->star, R->cap_star);
    if (n > R->cap_star) {
        if (cvm__grow(R->ctx, (void **)&R->star, &R->cap_star, n, sizeof *R->star))
            return 0;
        n = cvm__tri2_star(R->T, v, R->star, R->cap_star);
    }
    return n;
}

cvm_status cvm__rf_reserve_vertices(cvm__refiner *R, size_t n)
{
    if (cvm__grow(R->ctx, (void **)&R->vls, &R->cap_vls, n, sizeof *R->vls) ||
        cvm__grow(R->ctx, (void **)&R->vseg, &R->cap_vseg, n, sizeof *R->vseg))
        return CVM_E_NOMEM;
    return CVM_OK;
}

cvm_status cvm__rf_new_vertex(cvm__refiner *R, int32_t v, int32_t seg)
{
    const double *p = R->T->xy + 2 * (size_t)v;
    cvm_status s;
    if ((s = cvm__rf_reserve_vertices(R, (size_t)v + 1)))
        return cvm__nomem(R->ctx);
    R->vseg[v] = seg;
    R->steiner++;
    return cvm__sizing_at(R->p->sizing, p[0], p[1], &R->vls[v], R->ctx);
}

cvm_status cvm__rf_may_insert(cvm__refiner *R)
{
    cvm_status s;
    double frac;
    if (R->p->max_steiner && R->steiner >= R->p->max_steiner)
        return cvm__error(R->ctx, CVM_INCOMPLETE_STEINER_LIMIT, CVM_ENT_NONE, -1,
                          "refinement stopped at the Steiner limit (%lu points); the mesh is "
                          "valid but some triangles may not meet the bounds",
                          (unsigned long)R->steiner);
    frac = R->p->max_steiner ? (double)R->steiner / (double)R->p->max_steiner
                             : (double)R->steiner / (double)(R->steiner + R->q.n + 1);
    s = cvm__tick(R->ctx, 1, CVM_STAGE_REFINE, frac);
    if (s)
        return cvm__error(R->ctx, s, CVM_ENT_NONE, -1,
                          "refinement %s after %lu Steiner points; the mesh is valid but some "
                          "triangles may not meet the bounds",
                          s == CVM_INCOMPLETE_CANCELLED ? "was cancelled" : "reached the time limit",
                          (unsigned long)R->steiner);
    return CVM_OK;
}

cvm_status cvm__rf_segq_push(cvm__refiner *R, int32_t a, int32_t b, int32_t seg)
{
    size_t need = 3 * (R->segq_n + 1);
    if (need > R->cap_segq &&
        cvm__grow(R->ctx, (void **)&R->segq, &R->cap_segq, need, sizeof *R->segq))
        return cvm__nomem(R->ctx);
    R->segq[3 * R->segq_n] = a;
    R->segq[3 * R->segq_n + 1] = b;
    R->segq[3 * R->segq_n + 2] = seg;
    R->segq_n++;
    return CVM_OK;
}
