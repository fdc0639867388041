/*
 * quality.c - quality measures and histograms of the domain triangles
 * (cvm_mesh_get_measure, cvm_mesh_copy_histogram).
 *
 * These are measures, not topology: plain doubles, no exact arithmetic.
 * Angles come from atan2(|cross|, dot), which is accurate for small and
 * large angles alike. Near the limits of the double range (an edge vector
 * beyond 2^500 or below 2^-500, or one whose difference overflows) each edge
 * vector is scaled by a power of two before the products, so angles stay
 * right where plain products would give inf - inf, and areas are scaled back
 * (inf only when the true area exceeds the largest double). Inside that
 * range nothing is scaled, so the values there are as before. A triangle is
 * "obtuse" (not well-centred: its circumcentre lies outside it) when the dot
 * product of the two edges at one of its corners is negative; a right
 * triangle, whose circumcentre lies on its edge, is not counted. Interior
 * vertices are vertices of domain triangles that lie on no boundary edge of
 * the domain; interior edges have a domain triangle on both sides
 * (constrained or not). The dual edge of an interior edge joins the power
 * vertices of its two triangles (the circumcentres when no weights are set):
 * the power dual.
 *
 * Each group of values (triangles, degrees, the dual) is computed once per
 * state of the mesh and kept in its cvm__quality_cache (api_internal.h).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "geom/measure.h"
#include "api/mesh3.h"

typedef cvm__tri_quality qstats;

#define NBIN_ANGLE CVM__NBIN_ANGLE
#define NBIN_DEGREE CVM__NBIN_DEGREE

static void add_area(qstats *q, double x)
{
    double t = q->area + x;
    if (!(fabs(t) <= DBL_MAX)) {
        q->area = t; /* overflow: the compensation would be inf - inf */
        return;
    }
    if (fabs(q->area) >= fabs(x))
        q->area_c += (q->area - t) + x;
    else
        q->area_c += (x - t) + q->area;
    q->area = t;
}

static void triangle_stats(const cvm_mesh *m, qstats *q)
{
    int32_t t;
    memset(q, 0, sizeof *q);
    q->min_angle = q->min_edge = q->min_area = HUGE_VAL;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)) {
        const int32_t *c = cvm__store_cell(m, (size_t)t);
        const double *p[3];
        double obtuse = 0, area;
        int k;
        for (k = 0; k < 3; k++)
            p[k] = cvm__store_point(m, (size_t)c[k]);
        for (k = 0; k < 3; k++) {
            double dot, a = cvm__corner_angle_deg_safe(p[k], p[(k + 1) % 3], p[(k + 2) % 3], &dot);
            double len = hypot(p[(k + 1) % 3][0] - p[k][0], p[(k + 1) % 3][1] - p[k][1]);
            int bin = a >= 0 && a < 10.0 * NBIN_ANGLE ? (int)(a / 10.0) : a >= 0 ? NBIN_ANGLE - 1 : 0;
            q->min_angle = a < q->min_angle ? a : q->min_angle;
            q->max_angle = a > q->max_angle ? a : q->max_angle;
            q->n_regular += a >= 55.0 && a <= 65.0;
            q->angle_hist[bin < 0 ? 0 : bin >= NBIN_ANGLE ? NBIN_ANGLE - 1 : bin] += 1.0;
            q->min_edge = len < q->min_edge ? len : q->min_edge;
            q->max_edge = len > q->max_edge ? len : q->max_edge;
            if (dot < 0)
                obtuse = 1;
        }
        q->n_obtuse += obtuse != 0;
        area = cvm__tri_area_safe(p[0], p[1], p[2]);
        add_area(q, area);
        q->min_area = area < q->min_area ? area : q->min_area;
        q->nt++;
    }
}

/* Degrees of the interior vertices: hist (NBIN_DEGREE bins), *n_interior. */
static cvm_status degree_stats(cvm_mesh *m, double *hist, size_t *n_interior)
{
    size_t nv = cvm__store_nv(m), v;
    int32_t *deg = cvm__calloc(&m->ctx, nv + 1, sizeof *deg);
    uint8_t *on_bnd = cvm__calloc(&m->ctx, nv + 1, 1);
    int32_t t;
    int j;
    if (!deg || !on_bnd) {
        cvm__free(&m->ctx, deg);
        cvm__free(&m->ctx, on_bnd);
        return cvm__nomem(&m->ctx);
    }
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)) {
        const int32_t *c = cvm__store_cell(m, (size_t)t);
        for (j = 0; j < 3; j++) {
            int32_t u = cvm__store_across(m, (size_t)t, j);
            int32_t v1 = c[(j + 1) % 3], v2 = c[(j + 2) % 3];
            int bnd = !cvm__store_in_domain(m, u);
            if (!bnd && u < t)
                continue; /* counted from u */
            deg[v1]++;
            deg[v2]++;
            if (bnd)
                on_bnd[v1] = on_bnd[v2] = 1;
        }
    }
    memset(hist, 0, NBIN_DEGREE * sizeof *hist);
    *n_interior = 0;
    for (v = 0; v < nv; v++) {
        if (deg[v] == 0 || on_bnd[v])
            continue;
        hist[deg[v] < NBIN_DEGREE - 1 ? deg[v] : NBIN_DEGREE - 1] += 1.0;
        (*n_interior)++;
    }
    cvm__free(&m->ctx, deg);
    cvm__free(&m->ctx, on_bnd);
    return CVM_OK;
}

/* The triangle statistics of m, computed once per state of m. */
static const qstats *cached_triangle_stats(cvm_mesh *m)
{
    if (!(m->quality.have & CVM__HAVE_TRI)) {
        triangle_stats(m, &m->quality.tri);
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
        if ((s = degree_stats(m, m->quality.degree_hist, &m->quality.n_interior)))
            return s;
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
    const qstats *q;
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
    if (cvm__optimise_measure_needs_triangles(which))
        return (s = need_triangles(m)) ? s : cvm__optimise_measure(out, m, which);
    if (cvm__optimise_measure(out, m, which) == CVM_OK)
        return CVM_OK; /* the report of the last dual optimisation (lib/api/optimise.c) */
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
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_copy_histogram");
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
