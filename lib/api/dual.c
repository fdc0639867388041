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
#include "dual/dual_internal.h"
#include "api/mesh3.h"

static cvm__ctx *alloc_ctx(const cvm_mesh *m)
{
    return (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
}

static double weight(const cvm__tri2 *T, int32_t v)
{
    return T->w ? T->w[v] : 0.0;
}

/* Power vertex of slot t into out[2]. */
static void tri_vertex(const cvm__tri2 *T, size_t t, double *out)
{
    const int32_t *v = T->tv + 3 * t;
    cvm__power_vertex2d(T->xy + 2 * (size_t)v[0], T->xy + 2 * (size_t)v[1], T->xy + 2 * (size_t)v[2],
                        weight(T, v[0]), weight(T, v[1]), weight(T, v[2]), out);
}

/* 1 when slot t contains its power vertex (closed: on an edge counts). */
static int tri_contains(const cvm__tri2 *T, size_t t)
{
    const int32_t *v = T->tv + 3 * t;
    int k;
    for (k = 0; k < 3; k++) {
        int32_t a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
        if (cvm__power_side2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, T->xy + 2 * (size_t)c,
                              weight(T, a), weight(T, b), weight(T, c)) < 0)
            return 0;
    }
    return 1;
}

cvm_status cvm_mesh_set_weights(cvm_mesh *m, const double *w, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        if (!w && count)
            return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "w is NULL");
        return cvm__mesh3_set_weights(m, w, count);
    }
    cvm__tri2 *T;
    double *old = NULL, *nw;
    size_t v, nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_forget_layers(m);
    T = &m->tri;
    if (!w && count)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "w is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangulation: call cvm_mesh_triangulate() first");
    nv = T->nv;
    if (w && count != nv)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "count %lu is not the vertex count %lu", (unsigned long)count,
                          (unsigned long)nv);
    for (v = 0; w && v < nv; v++)
        if (!isfinite(w[v]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_VERTEX, (int64_t)v,
                              "weight of vertex %lu is not finite", (unsigned long)v);
    /* keep the old weights until the flips succeeded */
    old = T->w;
    nw = w ? cvm__malloc(&m->ctx, (T->cap_v ? T->cap_v : 1) * sizeof *nw) : NULL;
    if (w && !nw)
        return cvm__nomem(&m->ctx);
    if (nw)
        memcpy(nw, w, nv * sizeof *nw);
    T->w = nw;
    if ((s = cvm__tri2_make_regular(T, NULL))) {
        T->w = old;
        cvm__free(&m->ctx, nw);
        return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx) : s;
    }
    cvm__free(&m->ctx, old);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_weights(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = m->triangulated ? m->tri.nv : 0;
    if ((s = cvm__room(dst, dst_len, nv)))
        return s;
    if (nv && m->tri.w)
        memcpy(dst, m->tri.w, nv * sizeof *dst);
    else if (nv)
        memset(dst, 0, nv * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_vertices(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t t, k = 0;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm__room(dst, dst_len, 2 * cvm__mesh_n_triangles(m))) || !m->triangulated)
        return s;
    for (t = 0; t < m->tri.nt; t++)
        if (cvm__tri2_in_domain(&m->tri, (int32_t)t))
            tri_vertex(&m->tri, t, dst + 2 * k++);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_inside(int32_t *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t t, k = 0;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm__room(dst, dst_len, cvm__mesh_n_triangles(m))) || !m->triangulated)
        return s;
    for (t = 0; t < m->tri.nt; t++)
        if (cvm__tri2_in_domain(&m->tri, (int32_t)t))
            dst[k++] = tri_contains(&m->tri, t);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_areas(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    const cvm__tri2 *T;
    size_t t, nv;
    int j;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = m->triangulated ? m->tri.nv : 0;
    if ((s = cvm__room(dst, dst_len, nv)) || !nv)
        return s;
    T = &m->tri;
    memset(dst, 0, nv * sizeof *dst);
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        double V[2];
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        tri_vertex(T, t, V);
        for (j = 0; j < 3; j++) {
            int32_t a = v[j], b = v[(j + 1) % 3];
            const double *p = T->xy + 2 * (size_t)a, *q = T->xy + 2 * (size_t)b;
            double M[2];
            cvm__power_foot2d(p, q, weight(T, a), weight(T, b), M);
            /* kite pieces (p, M, V) and (q, V, M), signed */
            dst[a] += 0.5 * ((M[0] - p[0]) * (V[1] - p[1]) - (M[1] - p[1]) * (V[0] - p[0]));
            dst[b] += 0.5 * ((V[0] - q[0]) * (M[1] - q[1]) - (V[1] - q[1]) * (M[0] - q[0]));
        }
    }
    return CVM_OK;
}

/* Dual edge length of every edge of e (filled by the caller with
 * cvm__domain_edges) into len (e->n entries). */
static cvm_status dual_lengths(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *len)
{
    double *ends = cvm__malloc(ctx, (4 * e->n + 1) * sizeof *ends);
    size_t k;
    if (!ends || cvm__dual_edge_ends(ctx, T, e, ends)) {
        cvm__free(ctx, ends);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e->n; k++)
        len[k] = hypot(ends[4 * k] - ends[4 * k + 2], ends[4 * k + 1] - ends[4 * k + 3]);
    cvm__free(ctx, ends);
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
        cvm__domain_edge_counts(&m->tri, &ne, &ns);
    if ((s = cvm__room(dst, dst_len, ne)) || !ne)
        return s;
    if (cvm__domain_edges(alloc_ctx(m), &m->tri, 0, &e))
        return CVM_E_NOMEM;
    s = dual_lengths(alloc_ctx(m), &m->tri, &e, dst);
    cvm__edges_free(alloc_ctx(m), &e);
    return s;
}

/* Containment counts in one pass: the % of all triangles (*all) and of
 * those with a vertex on the domain boundary (*bnd) whose power vertex lies
 * outside them; computed once per state of m (cvm__quality_cache). */
static cvm_status outside_pct(cvm_mesh *m, double *all, double *bnd)
{
    const cvm__tri2 *T = &m->tri;
    cvm__quality_cache *qc = &m->quality;
    cvm__edges e;
    uint8_t *on_bnd;
    size_t t, n = 0, nout = 0, nb = 0, nbout = 0, k;
    if (!(qc->have & CVM__HAVE_OUTSIDE)) {
        if (cvm__domain_edges(&m->ctx, T, 0, &e))
            return cvm__nomem(&m->ctx);
        on_bnd = cvm__calloc(&m->ctx, T->nv + 1, 1);
        if (!on_bnd) {
            cvm__edges_free(&m->ctx, &e);
            return cvm__nomem(&m->ctx);
        }
        for (k = 0; k < e.n; k++)
            if (e.bnd[k])
                on_bnd[e.ev[2 * k]] = on_bnd[e.ev[2 * k + 1]] = 1;
        cvm__edges_free(&m->ctx, &e);
        for (t = 0; t < T->nt; t++) {
            const int32_t *v = T->tv + 3 * t;
            int out;
            if (!cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            out = !tri_contains(T, t);
            n++;
            nout += (size_t)out;
            if (on_bnd[v[0]] || on_bnd[v[1]] || on_bnd[v[2]]) {
                nb++;
                nbout += (size_t)out;
            }
        }
        cvm__free(&m->ctx, on_bnd);
        qc->pct_outside[0] = n ? 100.0 * (double)nout / (double)n : 0.0;
        qc->pct_outside[1] = nb ? 100.0 * (double)nbout / (double)nb : 0.0;
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
        uint8_t *mark = cvm__malloc(&m->ctx, m->tri.nv + 1);
        if (!mark)
            return cvm__nomem(&m->ctx);
        *out = (double)cvm__tri2_count_unregular(&m->tri, mark);
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
    const cvm__tri2 *T = &m->tri;
    size_t na = m->vattr ? m->in.nattr : 0, v;
    double *a;
    *out = NULL;
    if (!T->w)
        return CVM_OK;
    a = cvm__malloc(&m->ctx, (T->nv * (na + 1) + 1) * sizeof *a);
    if (!a)
        return CVM_E_NOMEM;
    for (v = 0; v < T->nv; v++) {
        a[v * (na + 1)] = T->w[v];
        if (na)
            memcpy(a + v * (na + 1) + 1, m->vattr + v * na, na * sizeof *a);
    }
    *out = a;
    return CVM_OK;
}

cvm_status cvm__dual_edge_ends(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *ends)
{
    /* e is sorted by lower vertex: first[v] .. first[v + 1] are the edges whose
     * lower vertex is v, a handful each, so a lookup scans a few entries
     * instead of bisecting the whole list */
    uint8_t *have = cvm__calloc(ctx, e->n + 1, 1);
    size_t *first = cvm__calloc(ctx, T->nv + 2, sizeof *first);
    size_t t, k;
    int j;
    if (!have || !first) {
        cvm__free(ctx, have);
        cvm__free(ctx, first);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e->n; k++)
        first[(size_t)e->ev[2 * k] + 1]++;
    for (k = 0; k < T->nv; k++)
        first[k + 1] += first[k];
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        double V[2];
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        tri_vertex(T, t, V);
        for (j = 0; j < 3; j++) {
            int32_t a = v[(j + 1) % 3], b = v[(j + 2) % 3];
            int32_t lo = a < b ? a : b, hi = a < b ? b : a;
            double *x;
            for (k = first[lo]; k < first[lo + 1] && e->ev[2 * k + 1] != hi; k++)
                ;
            if (k == first[lo + 1])
                continue; /* cannot happen: e holds every domain edge */
            x = ends + 4 * k;
            if (e->bnd[k]) {
                x[0] = V[0];
                x[1] = V[1];
                cvm__power_foot2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, weight(T, a),
                                  weight(T, b), x + 2);
            } else if (have[k]) {
                x[2] = V[0];
                x[3] = V[1];
            } else {
                x[0] = V[0];
                x[1] = V[1];
                have[k] = 1;
            }
        }
    }
    cvm__free(ctx, have);
    cvm__free(ctx, first);
    return CVM_OK;
}
