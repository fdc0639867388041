/* resample.c - CVM_OPT_KEEP_SEGMENT_VERTICES = 0 on a mesh handle: lib/boundary re-discretises
 * the smooth chains of segments and rebuilds the triangulation; this file checks the handle's
 * state, carves the result and carries markers, attributes and the input map over. */
#include <string.h>

#include "api_internal.h"
#include "store.h"
#include "boundary/boundary_internal.h"

/* Swap the rebuilt triangulation of R into m and carve it; R->T receives the old one.
 * *fallback = 1 (m unchanged, R->T the rejected one) when carving refuses it. */
static cvm_status adopt(cvm_mesh *m, cvm__resample_result *R, int *fallback)
{
    cvm_status s;
    *fallback = 0;
    cvm__store_exchange_tri2(m, &R->T);
    if ((s = cvm__mesh_carve(m))) {
        cvm__store_exchange_tri2(m, &R->T);
        if (s != CVM_E_NOMEM) {
            *fallback = 1;
            s = CVM_OK;
        }
        return s;
    }
    return CVM_OK;
}

cvm_status cvm__mesh_resample_boundary(cvm_mesh *m, const cvm_sizing *sizing, size_t *n_chains)
{
    cvm__resample_input in;
    cvm__resample_result R;
    int32_t *vmark = NULL;
    double *vattr = NULL;
    size_t v, k, na = m->in.nattr, nv = cvm__store_nv(m), nv2;
    cvm_status s;
    int fallback = 0;
    *n_chains = 0;
    if (nv != m->nv_triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "CVM_OPT_KEEP_SEGMENT_VERTICES = 0 re-discretises the input segments, so it "
                          "needs the mesh as cvm_mesh_triangulate() left it; this one has %lu vertices "
                          "instead of %lu (refined, or points inserted): triangulate again first",
                          (unsigned long)nv, (unsigned long)m->nv_triangulated);
    if (cvm__store_weights(m))
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "CVM_OPT_KEEP_SEGMENT_VERTICES = 0 cannot re-discretise a weighted (regular) "
                          "triangulation: triangulate again without weights first");
    memset(&in, 0, sizeof in);
    in.T = cvm__store_tri2_const(m);
    in.sizing = sizing;
    in.smark = m->in.smark;
    in.nseg = m->in.nseg;
    in.holes = m->in.holes;
    in.nholes = m->in.nholes;
    in.regions = m->in.regions;
    in.nregions = m->in.nregions;
    in.seed = (uint64_t)cvm__opt(m, CVM_OPT_SEED);
    in.keep_hull = cvm__opt(m, CVM_OPT_KEEP_CONVEX_HULL) != 0;
    if ((s = cvm__resample_boundary(&R, &in, &m->ctx)) || !R.n_chains)
        goto done;
    nv2 = R.T.nv;
    vmark = cvm__malloc(&m->ctx, (nv2 + 1) * sizeof *vmark);
    vattr = na ? cvm__malloc(&m->ctx, (nv2 * na + 1) * sizeof *vattr) : NULL;
    if (!vmark || (na && !vattr)) {
        s = CVM_E_NOMEM;
        goto done;
    }
    if ((s = adopt(m, &R, &fallback)) || fallback)
        goto done;
    for (v = 0; v < nv; v++) {
        if (R.newid[v] < 0)
            continue;
        vmark[R.newid[v]] = m->vmark[v];
        if (na)
            memcpy(vattr + (size_t)R.newid[v] * na, m->vattr + v * na, na * sizeof *vattr);
    }
    for (k = 0; k < R.nnew; k++) {
        size_t i, id = R.nkept + k;
        int32_t a = R.ninfo[3 * k + 1], b = R.ninfo[3 * k + 2];
        double f = R.nfrac[k];
        vmark[id] = cvm__segment_marker(m, R.ninfo[3 * k]);
        for (i = 0; i < na; i++)
            vattr[id * na + i] = (1 - f) * m->vattr[(size_t)a * na + i] + f * m->vattr[(size_t)b * na + i];
    }
    cvm__free(&m->ctx, m->vmark);
    m->vmark = vmark;
    m->cap_vmark = nv2 + 1;
    vmark = NULL;
    if (na) {
        cvm__free(&m->ctx, m->vattr);
        m->vattr = vattr;
        m->cap_vattr = nv2 * na + 1;
        vattr = NULL;
    }
    for (k = 0; k < m->in.np; k++)
        if (m->input_map[k] >= 0)
            m->input_map[k] = R.newid[m->input_map[k]];
    m->nv_triangulated = cvm__store_nv(m);
    *n_chains = R.n_chains;
done:
    cvm__resample_result_free(&R, &m->ctx);
    cvm__free(&m->ctx, vmark);
    cvm__free(&m->ctx, vattr);
    if (s == CVM_E_NOMEM)
        return cvm__nomem(&m->ctx);
    return s;
}
