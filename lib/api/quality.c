/*
 * quality.c - quality measures and histograms of a mesh handle
 * (cvm_mesh_get_measure, cvm_mesh_copy_histogram): the triangle and degree
 * measures of lib/delaunay/domain_quality.c, the dual's of lib/dual, and the
 * refinement and optimisation reports, dispatched by measure.
 *
 * Each group of values (triangles, degrees, the dual) is computed once per
 * state of the mesh and kept in its cvm__quality_cache (api_internal.h).
 */
#include <math.h>
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "api/mesh3.h"

#define NBIN_ANGLE CVM__NBIN_ANGLE
#define NBIN_DEGREE CVM__NBIN_DEGREE

/* The triangle statistics of m, computed once per state of m. */
static const cvm__tri_quality *cached_triangle_stats(cvm_mesh *m)
{
    if (!(m->quality.have & CVM__HAVE_TRI)) {
        cvm__domain_triangle_stats(cvm__store_tri2_const(m), &m->quality.tri);
        m->quality.have |= CVM__HAVE_TRI;
    }
    return &m->quality.tri;
}

/* The degree histogram of m (NBIN_DEGREE entries) and its number of interior
 * vertices, computed once per state of m. CVM_OK or CVM_E_NOMEM (with its message). */
static cvm_status cached_degree_stats(cvm_mesh *m, const double **hist, size_t *n_interior)
{
    cvm_status s;
    if (!(m->quality.have & CVM__HAVE_DEGREE)) {
        s = cvm__domain_degree_stats(&m->ctx, cvm__store_tri2_const(m), m->quality.degree_hist,
                                     &m->quality.n_interior);
        if (s != CVM_OK) {
            cvm__nomem(&m->ctx); /* the message; s is CVM_E_NOMEM */
            return s;
        }
        m->quality.have |= CVM__HAVE_DEGREE;
    }
    *hist = m->quality.degree_hist;
    *n_interior = m->quality.n_interior;
    return CVM_OK;
}

static cvm_status need_triangles(cvm_mesh *m)
{
    /* the first domain cell is enough (this runs on every call) */
    if (!m->triangulated || cvm__store_next_cell(m, -1) < 0)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangles: call cvm_mesh_triangulate() first");
    return CVM_OK;
}

cvm_status cvm_mesh_get_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    if (out && m && m->m3) {
        CVM__BEGIN_READ(m);
        return cvm__mesh3_measure(out, m, which);
    }
    const cvm__tri_quality *q;
    const double *hist;
    size_t n_int;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN_READ(m);
    if (!out)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "out is NULL");
    if (cvm__refine_measure(out, m, which) == CVM_OK)
        return CVM_OK; /* the report of the last refinement (lib/api/refine.c) */
    if (which == CVM_MEASURE_READ_FLIPS) {
        *out = m->read_flips; /* the report of the last read of a mesh file */
        return CVM_OK;
    }
    if (cvm__quad_report(out, m, (int)which) == CVM_OK)
        return CVM_OK; /* the report of the last quad meshing (lib/api/quadmesh.c) */
    if (cvm__optimise_measure_needs_triangles(which))
        return (s = need_triangles(m)) ? s : cvm__optimise_measure(out, m, which);
    if (cvm__optimise_measure(out, m, which) == CVM_OK)
        return CVM_OK; /* the report of the last dual optimisation (lib/api/optimise.c) */
    if (cvm__mesh3_gen3_report(out, m, (int)which) == CVM_OK)
        return CVM_OK; /* 3D generation's report: 0 on a 2D handle */
    if ((int)which >= (int)CVM_MEASURE_DUAL_OUTSIDE_PCT &&
        (int)which <= (int)CVM_MEASURE_VANISHED_VERTICES)
        return (s = need_triangles(m)) ? s : cvm__dual_measure(out, m, which); /* lib/api/dual.c */
    if ((int)which >= (int)CVM_MEASURE_Q1_MEAN_DEG &&
        (int)which <= (int)CVM_MEASURE_Q5_MIN_BOUNDARY) /* lib/api/dual_quality.c */
        return (s = need_triangles(m)) ? s : cvm__dual_quality_measure(out, m, which);
    if ((int)which < (int)CVM_MEASURE_MIN_ANGLE_DEG || (int)which > (int)CVM_MEASURE_MIN_AREA)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "unknown measure %d",
                          (int)which);
    if ((s = need_triangles(m)))
        return s;
    if (which == CVM_MEASURE_DEGREE6_PCT) {
        if ((s = cached_degree_stats(m, &hist, &n_int)))
            return s;
        *out = n_int ? 100.0 * hist[6] / (double)n_int : 0.0;
        return CVM_OK;
    }
    if (which == CVM_MEASURE_MIN_DUAL_EDGE_RATIO) {
        double minima[3];
        if ((s = cvm__dual_edge_minima(m, minima)))
            return s;
        *out = minima[2];
        return CVM_OK;
    }
    q = cached_triangle_stats(m);
    switch (which) {
    case CVM_MEASURE_MIN_ANGLE_DEG: *out = q->min_angle; break;
    case CVM_MEASURE_MAX_ANGLE_DEG: *out = q->max_angle; break;
    case CVM_MEASURE_REGULAR_PCT: *out = 100.0 * (double)q->n_regular / (3.0 * (double)q->nt); break;
    case CVM_MEASURE_OBTUSE_PCT: *out = 100.0 * (double)q->n_obtuse / (double)q->nt; break;
    case CVM_MEASURE_MIN_EDGE: *out = q->min_edge; break;
    case CVM_MEASURE_MAX_EDGE: *out = q->max_edge; break;
    case CVM_MEASURE_AREA: *out = q->area + q->area_c; break;
    default: *out = q->min_area; break;
    }
    return CVM_OK;
}

cvm_status cvm_mesh_copy_histogram(double *dst, size_t dst_len, cvm_mesh *m, cvm_histogram which)
{
    if (m && m->m3) {
        CVM__BEGIN_READ(m);
        if (!dst)
            return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "dst is NULL");
        return cvm__mesh3_histogram(dst, dst_len, m, which);
    }
    const double *hist;
    size_t need, n_int;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN_READ(m);
    if (!dst)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "dst is NULL");
    if ((int)which < (int)CVM_HIST_ANGLE_DEG || (int)which > (int)CVM_HIST_Q5)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "unknown histogram %d",
                          (int)which);
    if ((s = need_triangles(m)))
        return s;
    if ((int)which >= (int)CVM_HIST_Q1) /* lib/api/dual_quality.c */
        return cvm__dual_quality_histogram(dst, dst_len, m, which);
    need = which == CVM_HIST_ANGLE_DEG ? NBIN_ANGLE : NBIN_DEGREE;
    if (dst_len < need)
        return cvm__error(&m->ctx, CVM_E_BUFFER_TOO_SMALL, CVM_ENT_NONE, -1,
                          "histogram needs %lu entries, dst_len is %lu", (unsigned long)need,
                          (unsigned long)dst_len);
    if (which == CVM_HIST_DEGREE) {
        if ((s = cached_degree_stats(m, &hist, &n_int)))
            return s;
        memcpy(dst, hist, NBIN_DEGREE * sizeof *dst);
        return CVM_OK;
    }
    memcpy(dst, cached_triangle_stats(m)->angle_hist, NBIN_ANGLE * sizeof *dst);
    return CVM_OK;
}
