/*
 * optimise3.c - cvm_mesh_optimise_dual3(): check the call, mark the faces the
 * optimiser must keep (no neighbour, or an internal facet of the surface),
 * run lib/dual3 on the handle's vertices and weights, keep the report.
 */
#include <string.h>

#include "api/mesh3_internal.h"
#include "dual3/dual3.h"

/* cface[4 t + f] = 1 for the faces with no neighbour and the faces in g->face. */
static cvm_status constrained_faces(cvm__ctx *ctx, const cvm__mesh3 *g, const int32_t *nbr,
                                    uint8_t **out)
{
    uint8_t *cf = cvm__calloc(ctx, 4 * g->ntet + 1, 1);
    cvm__face_key *keys = NULL;
    size_t i;
    cvm_status s;
    if (!cf)
        return cvm__nomem(ctx);
    for (i = 0; i < 4 * g->ntet; i++)
        cf[i] = nbr[i] < 0;
    if (g->nface) {
        if ((s = cvm__mesh3_face_index(ctx, g->tet, g->ntet, &keys))) {
            cvm__free(ctx, cf);
            return s;
        }
        for (i = 0; i < g->nface; i++) {
            const int32_t *f = g->face + 3 * i;
            int32_t slot = cvm__mesh3_find_face(keys, 4 * g->ntet, f[0], f[1], f[2]);
            if (slot < 0)
                continue;
            cf[slot] = 1;
            if (nbr[slot] >= 0)
                cf[nbr[slot]] = 1;
        }
        cvm__free(ctx, keys);
    }
    *out = cf;
    return CVM_OK;
}

cvm_status cvm_mesh_optimise_dual3(cvm_mesh *m)
{
    cvm__mesh3 *g;
    cvm__d3_mesh M;
    cvm__d3_params p;
    cvm__d3_report r;
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
    p.slide = cvm__opt(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY) != 0;
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    if ((s = cvm__mesh3_adjacency(&m->ctx, g->tet, g->ntet, &nbr)))
        return s;
    if ((s = constrained_faces(&m->ctx, g, nbr, &cf))) {
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
    s = cvm__d3_optimise(&m->ctx, &M, &p, &r);
    cvm__free(&m->ctx, nbr);
    cvm__free(&m->ctx, cf);
    if (s == CVM_E_NOMEM) {
        cvm__free(&m->ctx, w_new);
        return s;
    }
    if (w_new)
        g->w = w_new;
    g->gen3[10] = (double)r.sweeps;
    g->gen3[11] = r.ntet ? 100.0 * (double)r.out_before / (double)r.ntet : 0;
    g->gen3[12] = r.ntet ? 100.0 * (double)r.out_after / (double)r.ntet : 0;
    g->gen3[13] = r.nbnd ? 100.0 * (double)r.bout_before / (double)r.nbnd : 0;
    g->gen3[14] = r.nbnd ? 100.0 * (double)r.bout_after / (double)r.nbnd : 0;
    g->gen3[15] = (double)r.moves;
    g->gen3[16] = cvm__now() - t0;
    if (s == CVM_INCOMPLETE_TIME_LIMIT)
        return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1,
                          "time limit reached after %lu sweeps: %lu of %lu tetrahedra still "
                          "outside (the mesh is valid)", (unsigned long)r.sweeps,
                          (unsigned long)r.out_after, (unsigned long)r.ntet);
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
