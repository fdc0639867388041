/*
 * dual.c - per-vertex power weights and the power (weighted Voronoi) dual of
 * the domain triangles as API arrays and measures.
 *
 * Decisions (containment, regularity) are exact (lib/dual, lib/delaunay);
 * positions, lengths and areas are plain doubles (constructions and measures).
 * Output order follows output_internal.h: triangles in slot order, edges
 * sorted by (lower, higher) vertex id.
 */
#include <math.h>
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "dual/dual_internal.h"
#include "api/mesh3.h"

static cvm__ctx *alloc_ctx(const cvm_mesh *m)
{
    return (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
}

cvm_status cvm_mesh_set_weights(cvm_mesh *m, const double *w, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        if (!w && count)
            return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "w is NULL");
        return cvm__mesh3_set_weights(m, w, count);
    }
    size_t v, nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_forget_layers(m);
    if (!w && count)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "w is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangulation: call cvm_mesh_triangulate() first");
    nv = cvm__store_nv(m);
    if (w && count != nv)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "count %lu is not the vertex count %lu", (unsigned long)count,
                          (unsigned long)nv);
    for (v = 0; w && v < nv; v++)
        if (!isfinite(w[v]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_VERTEX, (int64_t)v,
                              "weight of vertex %lu is not finite", (unsigned long)v);
    if ((s = cvm__store_set_weights(m, w)))
        return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx) : s;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_weights(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return cvm__mesh3_copy_weights(dst, dst_len, m);
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = m->triangulated ? cvm__store_nv(m) : 0;
    if ((s = cvm__room(dst, dst_len, nv)))
        return s;
    if (nv && cvm__store_weights(m))
        memcpy(dst, cvm__store_weights(m), nv * sizeof *dst);
    else if (nv)
        memset(dst, 0, nv * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_vertices(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    int32_t t;
    size_t k = 0;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm__room(dst, dst_len, 2 * cvm__mesh_n_triangles(m))) || !m->triangulated)
        return s;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t))
        cvm__dual_tri_vertex(cvm__store_tri2_const(m), t, dst + 2 * k++);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_inside(int32_t *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    int32_t t;
    size_t k = 0;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm__room(dst, dst_len, cvm__mesh_n_triangles(m))) || !m->triangulated)
        return s;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t))
        dst[k++] = cvm__dual_tri_contains(cvm__store_tri2_const(m), t);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_areas(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = m->triangulated ? cvm__store_nv(m) : 0;
    if ((s = cvm__room(dst, dst_len, nv)) || !nv)
        return s;
    cvm__dual_areas(cvm__store_tri2_const(m), dst);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_edge_lengths(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t ne = 0, ns = 0;
    cvm__edges e;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (m->triangulated)
        cvm__domain_edge_counts(cvm__store_tri2_const(m), &ne, &ns);
    if ((s = cvm__room(dst, dst_len, ne)) || !ne)
        return s;
    if (cvm__domain_edges(alloc_ctx(m), cvm__store_tri2_const(m), 0, &e))
        return CVM_E_NOMEM;
    s = cvm__dual_edge_lengths(alloc_ctx(m), cvm__store_tri2_const(m), &e, dst);
    cvm__edges_free(alloc_ctx(m), &e);
    return s;
}

/* Containment counts in one pass: the % of all triangles (*all) and of
 * those with a vertex on the domain boundary (*bnd) whose power vertex lies
 * outside them; computed once per state of m (cvm__quality_cache). */
static cvm_status outside_pct(cvm_mesh *m, double *all, double *bnd)
{
    cvm__quality_cache *qc = &m->quality;
    if (!(qc->have & CVM__HAVE_OUTSIDE)) {
        if (cvm__dual_outside_pct(&m->ctx, cvm__store_tri2_const(m), qc->pct_outside))
            return cvm__nomem(&m->ctx);
        qc->have |= CVM__HAVE_OUTSIDE;
    }
    *all = qc->pct_outside[0];
    *bnd = qc->pct_outside[1];
    return CVM_OK;
}

cvm_status cvm__dual_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    double md = 0.0, ms = 0.0, minima[3];
    cvm_status s;
    switch (which) {
    case CVM_MEASURE_DUAL_OUTSIDE_PCT:
    case CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT:
        if ((s = outside_pct(m, &md, &ms)))
            return s;
        *out = which == CVM_MEASURE_DUAL_OUTSIDE_PCT ? md : ms;
        return CVM_OK;
    case CVM_MEASURE_MIN_DUAL_EDGE:
    case CVM_MEASURE_TIME_STEP_PROXY:
        if ((s = cvm__dual_edge_minima(m, minima)))
            return s;
        *out = which == CVM_MEASURE_MIN_DUAL_EDGE ? minima[0] : minima[1];
        return CVM_OK;
    case CVM_MEASURE_VANISHED_VERTICES: {
        uint8_t *mark = cvm__malloc(&m->ctx, cvm__store_nv(m) + 1);
        if (!mark)
            return cvm__nomem(&m->ctx);
        *out = (double)cvm__store_count_vanished(m, mark);
        cvm__free(&m->ctx, mark);
        return CVM_OK;
    }
    default:
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "unknown measure %d",
                          (int)which);
    }
}

cvm_status cvm__mesh_weight_attributes(cvm_mesh *m, double **out)
{
    const double *w = cvm__store_weights(m);
    size_t na = m->vattr ? m->in.nattr : 0, v, nv = cvm__store_nv(m);
    double *a;
    *out = NULL;
    if (!w)
        return CVM_OK;
    a = cvm__malloc(&m->ctx, (nv * (na + 1) + 1) * sizeof *a);
    if (!a)
        return CVM_E_NOMEM;
    for (v = 0; v < nv; v++) {
        a[v * (na + 1)] = w[v];
        if (na)
            memcpy(a + v * (na + 1) + 1, m->vattr + v * na, na * sizeof *a);
    }
    *out = a;
    return CVM_OK;
}
