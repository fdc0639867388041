/*
 * optimise3.c - cvm_mesh_optimise_dual3(): check the call, mark the faces the
 * optimiser must keep (no neighbour, or an internal facet of the surface),
 * run lib/dual3 on the handle's vertices and weights, take back the flipped
 * tetrahedra (CVM_OPT_DUAL3_FLIPS), keep the report.
 */
#include <string.h>

#include "api/mesh3_internal.h"
#include "dual3/dual3.h"

cvm_status cvm_mesh_optimise_dual3(cvm_mesh *m)
{
    cvm__mesh3 *g;
    cvm__d3_mesh M;
    cvm__d3_params p;
    cvm__d3_report r;
    cvm__d3_topo topo;
    int32_t *nbr = NULL;
    uint8_t *cf = NULL;
    double t0 = cvm__now(), *w_new = NULL;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    g = m->m3;
    if (!g)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "cvm_mesh_optimise_dual3() needs a tetrahedral mesh; this handle is 2D "
                          "(use cvm_mesh_optimise_dual())");
    if (!g->have || g->ntet == 0)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no tetrahedral mesh to optimise: call cvm_mesh_generate3() or "
                          "cvm_mesh_triangulate() first");
    memset(&p, 0, sizeof p);
    p.max_sweeps = (int)cvm__opt(m, CVM_OPT_DUAL3_MAX_SWEEPS);
    p.min_dihedral_deg = cvm__opt(m, CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG);
    p.budget = (int)cvm__opt(m, CVM_OPT_DUAL3_BUDGET);
    p.margin = cvm__opt(m, CVM_OPT_DUAL3_MARGIN);
    p.seed = (uint64_t)cvm__opt(m, CVM_OPT_SEED);
    p.slide = (int)cvm__opt(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY);
    p.flips = cvm__opt(m, CVM_OPT_DUAL3_FLIPS) != 0;
    p.solver = (int)cvm__opt(m, CVM_OPT_DUAL3_SOLVER);
    p.cuckoo_budget = (int)cvm__opt(m, CVM_OPT_DUAL3_CUCKOO_BUDGET);
    p.escalate = (int)cvm__opt(m, CVM_OPT_DUAL3_ESCALATE);
    memset(&topo, 0, sizeof topo);
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    if ((s = cvm__mesh3_adjacency(&m->ctx, g->tet, g->ntet, &nbr)))
        return s;
    if ((s = cvm__mesh3_constrained_faces(&m->ctx, g, nbr, &cf))) {
        cvm__free(&m->ctx, nbr);
        return s;
    }
    if (!g->w && !(w_new = cvm__calloc(&m->ctx, g->nv + 1, sizeof *w_new))) {
        cvm__free(&m->ctx, nbr);
        cvm__free(&m->ctx, cf);
        return cvm__nomem(&m->ctx);
    }
    M.xyz = g->xyz;
    M.w = g->w ? g->w : w_new;
    M.nv = g->nv;
    M.tet = g->tet;
    M.ntet = g->ntet;
    M.nbr = nbr;
    M.cface = cf;
    M.attr = g->tattr;
    s = cvm__d3_optimise(&m->ctx, &M, &p, &r, &topo);
    cvm__free(&m->ctx, nbr);
    cvm__free(&m->ctx, cf);
    if (s == CVM_E_NOMEM) {
        cvm__free(&m->ctx, w_new);
        return s;
    }
    if (w_new)
        g->w = w_new;
    if (topo.tet) {
        /* the flipped connectivity: the surface triangles (g->face) are faces of it */
        cvm__free(&m->ctx, g->tet);
        cvm__free(&m->ctx, g->tattr);
        g->tet = topo.tet;
        g->tattr = topo.attr;
        g->ntet = topo.ntet;
    }
    g->gen3[10] = (double)r.sweeps;
    g->gen3[11] = r.ntet ? 100.0 * (double)r.out_before / (double)r.ntet : 0;
    g->gen3[12] = r.ntet_after ? 100.0 * (double)r.out_after / (double)r.ntet_after : 0;
    g->gen3[13] = r.nbnd ? 100.0 * (double)r.bout_before / (double)r.nbnd : 0;
    g->gen3[14] = r.nbnd_after ? 100.0 * (double)r.bout_after / (double)r.nbnd_after : 0;
    g->gen3[15] = (double)r.moves;
    g->gen3[16] = cvm__now() - t0;
    g->gen3[20] = (double)r.flips;
    if (s == CVM_INCOMPLETE_TIME_LIMIT)
        return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1,
                          "time limit reached after %lu sweeps: %lu of %lu tetrahedra still "
                          "outside (the mesh is valid)", (unsigned long)r.sweeps,
                          (unsigned long)r.out_after, (unsigned long)r.ntet_after);
    if (s == CVM_INCOMPLETE_CANCELLED)
        return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1,
                          "cancelled after %lu sweeps (the mesh is valid)", (unsigned long)r.sweeps);
    return s;
}

cvm_status cvm__mesh3_copy_weights(double *dst, size_t dst_len, const cvm_mesh *m)
{
    const cvm__mesh3 *g = m->m3;
    size_t nv = g->have ? g->nv : 0;
    if (!dst && nv)
        return CVM_E_NULL_ARG;
    if (dst_len < nv)
        return CVM_E_BUFFER_TOO_SMALL;
    if (nv && g->w)
        memcpy(dst, g->w, nv * sizeof *dst);
    else if (nv)
        memset(dst, 0, nv * sizeof *dst);
    return CVM_OK;
}
