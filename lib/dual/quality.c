/*
 * dual_quality.c - the dual quality measures q1..q5 of the power dual
 * (definitions in include/cvmesh.h, cvm_histogram) as per-element values,
 * histograms and scalar summaries.
 *
 * Measures, not decisions: plain doubles throughout. The crossing of an
 * edge's dual edge with the primal edge line is taken as the power-bisector
 * foot M of the edge, which is where the line through the two power vertices
 * meets it in exact arithmetic (both lie on the power bisector, which is
 * perpendicular to the edge through M); intersecting the two lines in
 * floating point would be ill-conditioned for short dual edges.
 *
 * The summaries and histograms of a mesh come from one pass (the API keeps
 * them in the handle's quality cache). A mesh whose coordinates reach beyond
 * 2^300 (or stay below 2^-300) is measured in a copy scaled by a power of
 * two, since the constructions form cubes of coordinate differences.
 */
#include <math.h>
#include <string.h>

#include "dual_internal.h"
#include "delaunay/domain.h"
#include "geom/measure.h"

#define SQRT3 1.7320508075688772935


void cvm__dual_q_free(cvm__ctx *ctx, cvm__dual_q *d)
{
    int k;
    for (k = 1; k < 6; k++)
        cvm__free(ctx, d->q[k]);
    cvm__free(ctx, d->tb);
    cvm__free(ctx, d->eint);
    cvm__free(ctx, d->eb);
    memset(d, 0, sizeof *d);
}

/* q1 and q2 of every domain triangle. */
static void triangle_values(const cvm__tri2 *T, const uint8_t *on_bnd, cvm__dual_q *d)
{
    size_t t, k = 0;
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        const double *a = T->xy + 2 * (size_t)v[0], *b = T->xy + 2 * (size_t)v[1],
                     *c = T->xy + 2 * (size_t)v[2];
        double V[2], C[2], area2, per, r;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        cvm__power_vertex2d(a, b, c, cvm__dual_weight(T, v[0]), cvm__dual_weight(T, v[1]), cvm__dual_weight(T, v[2]), V);
        C[0] = (a[0] + b[0] + c[0]) / 3.0;
        C[1] = (a[1] + b[1] + c[1]) / 3.0;
        area2 = fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        per = hypot(b[0] - a[0], b[1] - a[1]) + hypot(c[0] - b[0], c[1] - b[1]) +
              hypot(a[0] - c[0], a[1] - c[1]);
        r = area2 / per; /* inradius = 2 area / perimeter */
        d->q[1][k] = cvm__min_angle_deg(a, b, c);
        d->q[2][k] = hypot(C[0] - V[0], C[1] - V[1]) / r;
        d->tb[k] = on_bnd[v[0]] || on_bnd[v[1]] || on_bnd[v[2]];
        k++;
    }
}

/* q3, q4 and q5 of every edge of e, from the dual edge ends. */
static void edge_values(const cvm__tri2 *T, const cvm__edges *e, const double *ends,
                        const uint8_t *on_bnd, cvm__dual_q *d)
{
    size_t k;
    for (k = 0; k < e->n; k++) {
        int32_t a = e->ev[2 * k], b = e->ev[2 * k + 1];
        const double *p = T->xy + 2 * (size_t)a, *q = T->xy + 2 * (size_t)b, *x = ends + 4 * k;
        double M[2], l = hypot(q[0] - p[0], q[1] - p[1]), dual = hypot(x[2] - x[0], x[3] - x[1]);
        cvm__power_foot2d(p, q, cvm__dual_weight(T, a), cvm__dual_weight(T, b), M);
        d->q[3][k] = hypot(M[0] - 0.5 * (p[0] + q[0]), M[1] - 0.5 * (p[1] + q[1])) / l;
        if (e->bnd[k]) {
            d->q[4][k] = dual / (2.0 * l);
            d->q[5][k] = dual * 2.0 * SQRT3 / l;
        } else {
            d->q[4][k] = hypot(M[0] - 0.5 * (x[0] + x[2]), M[1] - 0.5 * (x[1] + x[3])) / l;
            d->q[5][k] = dual * SQRT3 / l;
        }
        d->eint[k] = !e->bnd[k];
        d->eb[k] = on_bnd[a] || on_bnd[b];
    }
}

/* Over the interior edges of e: the smallest dual edge (minima[0]), the
 * smallest min(primal, dual) (minima[1]) and the smallest dual / primal
 * ratio (minima[2]); 0 when there is no interior edge. */
static void interior_minima(const cvm__tri2 *T, const cvm__edges *e, const double *ends,
                            double *minima)
{
    double md = HUGE_VAL, ms = HUGE_VAL, mr = HUGE_VAL;
    size_t k;
    for (k = 0; k < e->n; k++) {
        const double *p = T->xy + 2 * (size_t)e->ev[2 * k], *q = T->xy + 2 * (size_t)e->ev[2 * k + 1];
        double prim, r, len = hypot(ends[4 * k] - ends[4 * k + 2], ends[4 * k + 1] - ends[4 * k + 3]);
        if (e->bnd[k])
            continue;
        prim = hypot(p[0] - q[0], p[1] - q[1]);
        r = len / prim;
        md = len < md ? len : md;
        ms = prim < ms ? prim : ms;
        ms = len < ms ? len : ms;
        mr = r < mr ? r : mr;
    }
    minima[0] = md == HUGE_VAL ? 0.0 : md;
    minima[1] = ms == HUGE_VAL ? 0.0 : ms;
    minima[2] = mr == HUGE_VAL ? 0.0 : mr;
}

#define SCALE_LIMIT 300 /* cubes of differences of coordinates below 2^300 stay finite */

cvm_status cvm__scaled_view(cvm__ctx *ctx, const cvm__tri2 *T, cvm__tri2 *view, int *k)
{
    double mx = 0, *xy, *w = NULL;
    size_t v;
    int e;
    *view = *T;
    *k = 0;
    for (v = 0; v < 2 * T->nv; v++)
        mx = fmax(mx, fabs(T->xy[v]));
    if (!(mx > 0) || ((e = ilogb(mx)) >= -SCALE_LIMIT && e <= SCALE_LIMIT))
        return CVM_OK;
    xy = cvm__malloc(ctx, (2 * T->nv + 1) * sizeof *xy);
    if (T->w)
        w = cvm__malloc(ctx, (T->nv + 1) * sizeof *w);
    if (!xy || (T->w && !w)) {
        cvm__free(ctx, xy);
        cvm__free(ctx, w);
        return CVM_E_NOMEM;
    }
    for (v = 0; v < 2 * T->nv; v++)
        xy[v] = ldexp(T->xy[v], -e);
    for (v = 0; w && v < T->nv; v++)
        w[v] = ldexp(T->w[v], -2 * e);
    view->xy = xy;
    view->w = w;
    *k = e;
    return CVM_OK;
}

void cvm__scaled_view_free(cvm__ctx *ctx, const cvm__tri2 *T, cvm__tri2 *view)
{
    if (view->xy != T->xy)
        cvm__free(ctx, view->xy);
    if (view->w != T->w)
        cvm__free(ctx, view->w);
    *view = *T;
}

/* Compute every value of d for the domain of T, and when minima is not NULL
 * the interior minima into minima[0..2]. CVM_OK or CVM_E_NOMEM (no message). */
static cvm_status dq_compute_in(cvm__ctx *ctx, const cvm__tri2 *T, cvm__dual_q *d, double *minima)
{
    cvm__edges e;
    double *ends = NULL;
    uint8_t *on_bnd = NULL;
    size_t k;
    int j, fail = 0;
    memset(d, 0, sizeof *d);
    if (cvm__domain_edges(ctx, T, 0, &e))
        return CVM_E_NOMEM;
    d->nt = cvm__domain_triangles(T);
    d->ne = e.n;
    for (j = 1; j < 6; j++)
        fail |= !(d->q[j] = cvm__malloc(ctx, ((j < 3 ? d->nt : d->ne) + 1) * sizeof(double)));
    d->tb = cvm__malloc(ctx, d->nt + 1);
    d->eint = cvm__malloc(ctx, d->ne + 1);
    d->eb = cvm__malloc(ctx, d->ne + 1);
    ends = cvm__malloc(ctx, (4 * e.n + 1) * sizeof *ends);
    on_bnd = cvm__calloc(ctx, T->nv + 1, 1);
    if (fail || !d->tb || !d->eint || !d->eb || !ends || !on_bnd ||
        cvm__dual_edge_ends(ctx, T, &e, ends)) {
        cvm__free(ctx, ends);
        cvm__free(ctx, on_bnd);
        cvm__edges_free(ctx, &e);
        cvm__dual_q_free(ctx, d);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e.n; k++)
        if (e.bnd[k])
            on_bnd[e.ev[2 * k]] = on_bnd[e.ev[2 * k + 1]] = 1;
    triangle_values(T, on_bnd, d);
    edge_values(T, &e, ends, on_bnd, d);
    if (minima)
        interior_minima(T, &e, ends, minima);
    cvm__free(ctx, ends);
    cvm__free(ctx, on_bnd);
    cvm__edges_free(ctx, &e);
    return CVM_OK;
}

/* cvm__dual_q_compute: dq_compute_in() in the frame of cvm__scaled_view(): the q values and
 * minima[2] are ratios, unchanged by the scale; minima[0..1] are lengths,
 * scaled back. */
cvm_status cvm__dual_q_compute(cvm__ctx *ctx, const cvm__tri2 *T, cvm__dual_q *d, double *minima)
{
    cvm__tri2 view;
    cvm_status s;
    int k;
    memset(d, 0, sizeof *d);
    if (cvm__scaled_view(ctx, T, &view, &k))
        return CVM_E_NOMEM;
    s = dq_compute_in(ctx, &view, d, minima);
    cvm__scaled_view_free(ctx, T, &view);
    if (!s && minima) {
        minima[0] = ldexp(minima[0], k);
        minima[1] = ldexp(minima[1], k);
    }
    return s;
}

/* Bins of histogram w (1..5): count, width; the last bin of q2..q5 is open. */
void cvm__dual_q_bins(int w, size_t *n, double *width)
{
    static const size_t k_n[6] = {0, 12, 20, 20, 20, 20};
    static const double k_w[6] = {0, 5.0, 0.25, 0.05, 0.05, 0.1};
    *n = k_n[w];
    *width = k_w[w];
}

/* Histogram w (1..5) of d into dst (its cvm__dual_q_bins() count of entries). */
void cvm__dual_q_histogram(const cvm__dual_q *d, int w, double *dst)
{
    size_t nb, n, k;
    double width;
    cvm__dual_q_bins(w, &nb, &width);
    memset(dst, 0, nb * sizeof *dst);
    n = w < 3 ? d->nt : d->ne;
    for (k = 0; k < n; k++) {
        double x = d->q[w][k], b;
        if (w >= 3 && !d->eint[k])
            continue; /* q3..q5 histograms count interior edges */
        b = floor(x / width);
        dst[!(b >= 0) ? 0 : b >= (double)nb ? nb - 1 : (size_t)b] += 1.0;
    }
}

cvm__dual_q_summary cvm__dual_q_summarise(const cvm__dual_q *d, int w, int boundary_only)
{
    cvm__dual_q_summary s = {0, 0, 0};
    size_t k, n = w < 3 ? d->nt : d->ne, cnt = 0;
    double sum = 0;
    for (k = 0; k < n; k++) {
        double x = d->q[w][k];
        if (w >= 3 && !d->eint[k])
            continue;
        if (boundary_only && !(w < 3 ? d->tb[k] : d->eb[k]))
            continue;
        if (cnt == 0 || x < s.min)
            s.min = x;
        if (cnt == 0 || x > s.max)
            s.max = x;
        sum += x;
        cnt++;
    }
    s.mean = cnt ? sum / (double)cnt : 0.0;
    return s;
}
