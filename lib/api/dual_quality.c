/* dual_quality.c - the dual quality measures q1..q5 of a mesh handle (computed by
 * lib/dual/quality.c): per-element copies, and summaries and histograms kept in the handle's
 * quality cache (api_internal.h). */
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "api/mesh3.h"

cvm_status cvm_mesh_copy_dual_quality(double *dst, size_t dst_len, const cvm_mesh *m,
                                      cvm_histogram which)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm__ctx *ctx;
    size_t nt = 0, ne = 0, ns = 0, need;
    int w = (int)which - (int)CVM_HIST_Q1 + 1;
    cvm__dual_q d;
    if (!m)
        return CVM_E_NULL_ARG;
    if (w < 1 || w > 5)
        return CVM_E_ARGUMENT;
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    if (m->triangulated) {
        nt = cvm__domain_triangles(cvm__store_tri2_const(m));
        cvm__domain_edge_counts(cvm__store_tri2_const(m), &ne, &ns);
    }
    need = w < 3 ? nt : ne;
    if (dst_len < need)
        return CVM_E_BUFFER_TOO_SMALL;
    if (!need)
        return CVM_OK;
    ctx = (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
    if (cvm__dual_q_compute(ctx, cvm__store_tri2_const(m), &d, NULL))
        return CVM_E_NOMEM;
    memcpy(dst, d.q[w], need * sizeof *dst);
    cvm__dual_q_free(ctx, &d);
    return CVM_OK;
}

/* The summaries of m's dual, computed in one pass on the first request after
 * a change of m (api_internal.h, cvm__quality_cache). CVM_OK or CVM_E_NOMEM
 * (with its message). */
static cvm_status dual_summary(cvm_mesh *m, const cvm__dual_summary **out)
{
    cvm__dual_summary *r = &m->quality.dual;
    cvm__dual_q d;
    int w;
    if (m->quality.have & CVM__HAVE_DUAL) {
        *out = r;
        return CVM_OK;
    }
    if (cvm__dual_q_compute(&m->ctx, cvm__store_tri2_const(m), &d, r->minima))
        return cvm__nomem(&m->ctx);
#define Q(which) r->q[(int)(which) - (int)CVM_MEASURE_Q1_MEAN_DEG]
    Q(CVM_MEASURE_Q1_MEAN_DEG) = cvm__dual_q_summarise(&d, 1, 0).mean;
    Q(CVM_MEASURE_Q2_MAX) = cvm__dual_q_summarise(&d, 2, 0).max;
    Q(CVM_MEASURE_Q2_MEAN) = cvm__dual_q_summarise(&d, 2, 0).mean;
    Q(CVM_MEASURE_Q3_MAX) = cvm__dual_q_summarise(&d, 3, 0).max;
    Q(CVM_MEASURE_Q4_MAX) = cvm__dual_q_summarise(&d, 4, 0).max;
    Q(CVM_MEASURE_Q5_MIN) = cvm__dual_q_summarise(&d, 5, 0).min;
    Q(CVM_MEASURE_Q5_MEAN) = cvm__dual_q_summarise(&d, 5, 0).mean;
    Q(CVM_MEASURE_Q1_MIN_BOUNDARY_DEG) = cvm__dual_q_summarise(&d, 1, 1).min;
    Q(CVM_MEASURE_Q2_MAX_BOUNDARY) = cvm__dual_q_summarise(&d, 2, 1).max;
    Q(CVM_MEASURE_Q5_MIN_BOUNDARY) = cvm__dual_q_summarise(&d, 5, 1).min;
#undef Q
    for (w = 1; w <= 5; w++)
        cvm__dual_q_histogram(&d, w, r->hist[w - 1]);
    cvm__dual_q_free(&m->ctx, &d);
    m->quality.have |= CVM__HAVE_DUAL;
    *out = r;
    return CVM_OK;
}

cvm_status cvm__dual_quality_histogram(double *dst, size_t dst_len, cvm_mesh *m,
                                       cvm_histogram which)
{
    int w = (int)which - (int)CVM_HIST_Q1 + 1;
    const cvm__dual_summary *r;
    size_t nb;
    double width;
    cvm_status s;
    cvm__dual_q_bins(w, &nb, &width);
    if (dst_len < nb)
        return cvm__error(&m->ctx, CVM_E_BUFFER_TOO_SMALL, CVM_ENT_NONE, -1,
                          "histogram needs %lu entries, dst_len is %lu", (unsigned long)nb,
                          (unsigned long)dst_len);
    if ((s = dual_summary(m, &r)))
        return s;
    memcpy(dst, r->hist[w - 1], nb * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm__dual_quality_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    const cvm__dual_summary *r;
    cvm_status s;
    if ((int)which < (int)CVM_MEASURE_Q1_MEAN_DEG || (int)which > (int)CVM_MEASURE_Q5_MIN_BOUNDARY)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "unknown measure %d",
                          (int)which);
    if ((s = dual_summary(m, &r)))
        return s;
    *out = r->q[(int)which - (int)CVM_MEASURE_Q1_MEAN_DEG];
    return CVM_OK;
}

cvm_status cvm__dual_edge_minima(cvm_mesh *m, double *out)
{
    const cvm__dual_summary *r;
    cvm_status s;
    if ((s = dual_summary(m, &r)))
        return s;
    memcpy(out, r->minima, sizeof r->minima);
    return CVM_OK;
}
