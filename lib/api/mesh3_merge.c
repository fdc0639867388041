/*
 * mesh3_merge.c - merged dual cells of a 3D handle: the handle's mesh handed
 * to lib/dual3's merge rule (dual3.h), the measures 725-728 and
 * cvm_mesh_copy_dual3_merge_groups().
 */
#include "api/mesh3_internal.h"
#include "api/output_internal.h"
#include "dual3/dual3.h"

/* Run the merge rule on g (g->have); group: ntet entries or NULL. CVM_OK or
 * CVM_E_NOMEM (message set in ctx). */
static cvm_status mesh3_merge_run(cvm__ctx *ctx, const cvm_mesh *m, int32_t *group,
                                  cvm__d3_merge_report *r)
{
    const cvm__mesh3 *g = m->m3;
    int32_t *nbr = NULL, *grp = group;
    uint8_t *cf = NULL;
    cvm__d3_mesh M;
    cvm_status s;
    if ((s = cvm__mesh3_adjacency(ctx, g->tet, g->ntet, &nbr)))
        return s;
    if ((s = cvm__mesh3_constrained_faces(ctx, g, nbr, &cf))) {
        cvm__free(ctx, nbr);
        return s;
    }
    if (!grp && !(grp = cvm__malloc(ctx, (g->ntet + 1) * sizeof *grp))) {
        cvm__free(ctx, nbr);
        cvm__free(ctx, cf);
        return cvm__nomem(ctx);
    }
    M.xyz = g->xyz; /* read only: the merge rule moves nothing */
    M.w = g->w;
    M.nv = g->nv;
    M.tet = g->tet;
    M.ntet = g->ntet;
    M.nbr = nbr;
    M.cface = cf;
    s = cvm__d3_merge(ctx, &M, g->tattr, cvm__opt(m, CVM_OPT_DUAL3_MERGE_TOL), grp, r);
    if (grp != group)
        cvm__free(ctx, grp);
    cvm__free(ctx, nbr);
    cvm__free(ctx, cf);
    return s;
}

static double pct(size_t a, size_t b)
{
    return b ? 100.0 * (double)a / (double)b : 0;
}

cvm_status cvm__mesh3_merge_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    cvm__d3_merge_report r;
    cvm_status s;
    if (!m->m3->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no mesh to measure: call cvm_mesh_triangulate() first");
    if ((s = mesh3_merge_run(&m->ctx, m, NULL, &r)))
        return s;
    switch (which) {
    case CVM_MEASURE_DUAL3_MERGED_PCT: *out = pct(r.nmerged, r.ntet); break;
    case CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT: *out = pct(r.nnc, r.ntet); break;
    case CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT: *out = pct(r.nbnc, r.nbnd); break;
    default: *out = (double)r.ndissolved; break;
    }
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual3_merge_groups(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    cvm__ctx tmp;
    cvm__d3_merge_report r;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->m3)
        return CVM_E_UNSUPPORTED;
    if (!m->m3->have)
        return CVM_E_STATE;
    if ((s = cvm__room(dst, dst_len, m->m3->ntet)))
        return s;
    if (!m->m3->ntet)
        return CVM_OK;
    tmp = m->ctx; /* a const reader: an error leaves the handle's message alone */
    /* cvm_index is int32_t: the rule writes the groups straight into dst, and
       on CVM_E_NOMEM before it writes anything */
    return mesh3_merge_run(&tmp, m, dst, &r);
}
