/* test_quality.c - dual quality q1..q5 (lib/dual/quality.c through lib/api/dual_quality.c) against the test's own computation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dual/dual_tests.h"

#define TOL 1e-9 /* measures are floating-point */
#define PI 3.14159265358979323846

/* Power vertex by Cramer's rule on absolute coordinates (not the library's formula). */
static void vertex_of(const double *a, const double *b, const double *c, double wa, double wb,
                      double wc, double *out)
{
    double m11 = 2 * (b[0] - a[0]), m12 = 2 * (b[1] - a[1]);
    double m21 = 2 * (c[0] - a[0]), m22 = 2 * (c[1] - a[1]);
    double r1 = b[0] * b[0] + b[1] * b[1] - a[0] * a[0] - a[1] * a[1] - wb + wa;
    double r2 = c[0] * c[0] + c[1] * c[1] - a[0] * a[0] - a[1] * a[1] - wc + wa;
    double det = m11 * m22 - m12 * m21;
    out[0] = (r1 * m22 - m12 * r2) / det;
    out[1] = (m11 * r2 - r1 * m21) / det;
}

/* Smallest angle by the law of cosines (the library uses atan2). */
static double min_angle(const double *p[3])
{
    double best = 180;
    int k;
    for (k = 0; k < 3; k++) {
        const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
        double ab = hypot(b[0] - a[0], b[1] - a[1]), ac = hypot(c[0] - a[0], c[1] - a[1]);
        double bc = hypot(c[0] - b[0], c[1] - b[1]);
        double ang = acos((ab * ab + ac * ac - bc * bc) / (2 * ab * ac)) * 180.0 / PI;
        best = ang < best ? ang : best;
    }
    return best;
}

/* Crossing of line (v1, v2) with line (p, q), by intersecting the two lines. */
static void crossing(const double *p, const double *q, const double *v1, const double *v2,
                     double *out)
{
    double dx = q[0] - p[0], dy = q[1] - p[1], ex = v2[0] - v1[0], ey = v2[1] - v1[1];
    double den = dx * ey - dy * ex;
    double s = ((v1[0] - p[0]) * ey - (v1[1] - p[1]) * ex) / den;
    out[0] = p[0] + s * dx;
    out[1] = p[1] + s * dy;
}

/* The expected q values of d (weights w), computed from the public arrays. */
typedef struct expect {
    double *q1, *q2, *q3, *q4, *q5;
    uint8_t *interior;
} expect;

static ptrdiff_t find(const dtest_mesh *d, cvm_index a, cvm_index b)
{
    size_t lo = 0, hi = d->ne;
    cvm_index x = a < b ? a : b, y = a < b ? b : a;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        const cvm_index *e = d->edge + 2 * mid;
        if (e[0] < x || (e[0] == x && e[1] < y))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < d->ne && d->edge[2 * lo] == x && d->edge[2 * lo + 1] == y ? (ptrdiff_t)lo : -1;
}

static void compute_expected(const dtest_mesh *d, expect *x)
{
    double *V = malloc(2 * d->nt * sizeof *V), *ends = malloc(4 * d->ne * sizeof *ends);
    int *seen = calloc(d->ne, sizeof *seen);
    size_t t, k;
    int j;
    x->q1 = malloc(d->nt * sizeof(double));
    x->q2 = malloc(d->nt * sizeof(double));
    x->q3 = malloc(d->ne * sizeof(double));
    x->q4 = malloc(d->ne * sizeof(double));
    x->q5 = malloc(d->ne * sizeof(double));
    x->interior = calloc(d->ne, 1);
    ck_assert(V && ends && seen && x->q1 && x->q2 && x->q3 && x->q4 && x->q5 && x->interior);
    for (t = 0; t < d->nt; t++) {
        const cvm_index *v = d->tri + 3 * t;
        const double *p[3];
        double a, b, c, s, area, r, C[2];
        for (j = 0; j < 3; j++)
            p[j] = d->xy + 2 * (size_t)v[j];
        vertex_of(p[0], p[1], p[2], d->w[v[0]], d->w[v[1]], d->w[v[2]], V + 2 * t);
        a = hypot(p[1][0] - p[0][0], p[1][1] - p[0][1]);
        b = hypot(p[2][0] - p[1][0], p[2][1] - p[1][1]);
        c = hypot(p[0][0] - p[2][0], p[0][1] - p[2][1]);
        s = 0.5 * (a + b + c);
        area = sqrt(s * (s - a) * (s - b) * (s - c)); /* Heron */
        r = area / s;
        C[0] = (p[0][0] + p[1][0] + p[2][0]) / 3;
        C[1] = (p[0][1] + p[1][1] + p[2][1]) / 3;
        x->q1[t] = min_angle(p);
        x->q2[t] = hypot(C[0] - V[2 * t], C[1] - V[2 * t + 1]) / r;
        for (j = 0; j < 3; j++) {
            ptrdiff_t e = find(d, v[j], v[(j + 1) % 3]);
            ck_assert(e >= 0);
            memcpy(ends + 4 * e + 2 * seen[e], V + 2 * t, 2 * sizeof(double));
            seen[e]++;
        }
    }
    for (k = 0; k < d->ne; k++) {
        const double *p = d->xy + 2 * (size_t)d->edge[2 * k], *q = d->xy + 2 * (size_t)d->edge[2 * k + 1];
        double l = hypot(q[0] - p[0], q[1] - p[1]), M[2], len;
        double wp = d->w[d->edge[2 * k]], wq = d->w[d->edge[2 * k + 1]];
        /* foot: |M-p|^2 - wp = |M-q|^2 - wq along pq */
        double tt = 0.5 + (wp - wq) / (2 * l * l);
        ck_assert(seen[k] == 1 || seen[k] == 2);
        x->interior[k] = seen[k] == 2;
        if (seen[k] == 2 && hypot(ends[4 * k + 2] - ends[4 * k], ends[4 * k + 3] - ends[4 * k + 1]) > 0.1 * l)
            crossing(p, q, ends + 4 * k, ends + 4 * k + 2, M); /* well-conditioned */
        else {
            M[0] = p[0] + tt * (q[0] - p[0]);
            M[1] = p[1] + tt * (q[1] - p[1]);
        }
        if (seen[k] == 1)
            memcpy(ends + 4 * k + 2, M, 2 * sizeof(double));
        len = hypot(ends[4 * k + 2] - ends[4 * k], ends[4 * k + 3] - ends[4 * k + 1]);
        x->q3[k] = hypot(M[0] - 0.5 * (p[0] + q[0]), M[1] - 0.5 * (p[1] + q[1])) / l;
        if (seen[k] == 2) {
            x->q4[k] = hypot(M[0] - 0.5 * (ends[4 * k] + ends[4 * k + 2]),
                             M[1] - 0.5 * (ends[4 * k + 1] + ends[4 * k + 3])) / l;
            x->q5[k] = len / (l / sqrt(3.0));
        } else {
            x->q4[k] = len / (2 * l);
            x->q5[k] = len / (l / (2 * sqrt(3.0)));
        }
    }
    free(V);
    free(ends);
    free(seen);
}

static void expect_free(expect *x)
{
    free(x->q1);
    free(x->q2);
    free(x->q3);
    free(x->q4);
    free(x->q5);
    free(x->interior);
}

static void assert_close(const double *got, const double *want, size_t n, double scale, const char *what)
{
    size_t k;
    for (k = 0; k < n; k++)
        ck_assert_msg(fabs(got[k] - want[k]) <= TOL * (scale + fabs(want[k])),
                      "%s %lu: library %.17g, test %.17g", what, (unsigned long)k, got[k], want[k]);
}

static cvm_mesh *weighted_square(double h, double wscale, uint64_t seed)
{
    cvm_mesh *m = dtest_refined_square(h);
    size_t nv, v;
    double *w;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = malloc(nv * sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (v = 0; v < nv; v++)
        w[v] = wscale * h * h * dtest_uniform(&seed);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    free(w);
    return m;
}

/* Raw values, histograms and summaries agree with the test's computation. */
START_TEST(dual_quality_matches_independent_computation)
{
    static const size_t nbins[6] = {0, 12, 20, 20, 20, 20};
    static const double width[6] = {0, 5, 0.25, 0.05, 0.05, 0.1};
    cvm_mesh *m = weighted_square(0.05, 0.3, 9);
    dtest_mesh d;
    expect x;
    double *got, hist[20], mine[20], v, q5min = HUGE_VAL, q2max = 0, q1sum = 0;
    const double *want[6];
    size_t k, n;
    int w;
    dtest_get(m, &d);
    compute_expected(&d, &x);
    want[1] = x.q1; want[2] = x.q2; want[3] = x.q3; want[4] = x.q4; want[5] = x.q5;
    got = malloc((d.ne + d.nt) * sizeof *got);
    ck_assert_ptr_nonnull(got);
    for (w = 1; w <= 5; w++) {
        n = w < 3 ? d.nt : d.ne;
        ck_assert_int_eq(cvm_mesh_copy_dual_quality(got, n - 1, m, (cvm_histogram)(CVM_HIST_Q1 + w - 1)),
                         CVM_E_BUFFER_TOO_SMALL);
        ck_assert_int_eq(cvm_mesh_copy_dual_quality(got, n, m, (cvm_histogram)(CVM_HIST_Q1 + w - 1)), CVM_OK);
        assert_close(got, want[w], n, w == 1 ? 60 : 1, "q");
        /* histogram: bin the library's values with the documented edges */
        memset(mine, 0, sizeof mine);
        for (k = 0; k < n; k++) {
            double b = floor(got[k] / width[w]);
            if (w >= 3 && !x.interior[k])
                continue;
            mine[b >= (double)nbins[w] ? nbins[w] - 1 : (size_t)b] += 1;
        }
        ck_assert_int_eq(cvm_mesh_copy_histogram(hist, nbins[w] - 1, m, (cvm_histogram)(CVM_HIST_Q1 + w - 1)),
                         CVM_E_BUFFER_TOO_SMALL);
        ck_assert_int_eq(cvm_mesh_copy_histogram(hist, 20, m, (cvm_histogram)(CVM_HIST_Q1 + w - 1)), CVM_OK);
        for (k = 0; k < nbins[w]; k++)
            ck_assert_msg(hist[k] == mine[k], "q%d bin %lu: %g vs %g", w, (unsigned long)k, hist[k], mine[k]);
    }
    for (k = 0; k < d.nt; k++) {
        q2max = x.q2[k] > q2max ? x.q2[k] : q2max;
        q1sum += x.q1[k];
    }
    for (k = 0; k < d.ne; k++)
        if (x.interior[k] && x.q5[k] < q5min)
            q5min = x.q5[k];
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_Q2_MAX), CVM_OK);
    ck_assert_double_eq_tol(v, q2max, TOL * (1 + q2max));
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_Q1_MEAN_DEG), CVM_OK);
    ck_assert_double_eq_tol(v, q1sum / (double)d.nt, 1e-9);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_Q5_MIN), CVM_OK);
    ck_assert_double_eq_tol(v, q5min, TOL);
    ck_assert(q5min > 0);
    for (w = CVM_MEASURE_Q1_MEAN_DEG; w <= CVM_MEASURE_Q5_MIN_BOUNDARY; w++) {
        ck_assert_int_eq(cvm_mesh_get_measure(&v, m, (cvm_measure)w), CVM_OK);
        ck_assert(isfinite(v) && v >= 0);
    }
    free(got);
    expect_free(&x);
    dtest_free(&d);
    cvm_mesh_free(m);
}
END_TEST

/* Without weights the crossing is the edge midpoint: q3 = 0 up to rounding. */
START_TEST(zero_weights_cross_at_midpoints)
{
    cvm_mesh *m = dtest_refined_square(0.1);
    size_t ne, k;
    double *q3, v;
    ck_assert_int_eq(cvm_mesh_count(&ne, m, CVM_ENT_EDGE), CVM_OK);
    q3 = malloc(ne * sizeof *q3);
    ck_assert_ptr_nonnull(q3);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q3, ne, m, CVM_HIST_Q3), CVM_OK);
    for (k = 0; k < ne; k++)
        ck_assert(q3[k] < 1e-12);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_Q3_MAX), CVM_OK);
    ck_assert(v < 1e-12);
    free(q3);
    cvm_mesh_free(m);
}
END_TEST

/* An equilateral triangle: q1 = 60, q2 = 0; its edges are boundary edges, each
 * with a dual half edge of l / (2 sqrt 3), so q5 = 1. */
START_TEST(equilateral_triangle_is_ideal)
{
    const double xy[6] = {0, 0, 2, 0, 1, 1.7320508075688772};
    cvm_mesh *m;
    double q[3];
    int k;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 3, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q, 1, m, CVM_HIST_Q1), CVM_OK);
    ck_assert_double_eq_tol(q[0], 60, 1e-6);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q, 1, m, CVM_HIST_Q2), CVM_OK);
    ck_assert(q[0] < 1e-6);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q, 3, m, CVM_HIST_Q5), CVM_OK);
    for (k = 0; k < 3; k++)
        ck_assert_double_eq_tol(q[k], 1, 1e-6);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q, 3, m, (cvm_histogram)2), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q, 3, NULL, CVM_HIST_Q5), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(NULL, 3, m, CVM_HIST_Q5), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_histogram(q, 3, m, (cvm_histogram)8), CVM_E_ARGUMENT);
    cvm_mesh_free(m);
}
END_TEST

TCase *dual_quality_tcase(void)
{
    TCase *tc = tcase_create("quality");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, dual_quality_matches_independent_computation);
    tcase_add_test(tc, zero_weights_cross_at_midpoints);
    tcase_add_test(tc, equilateral_triangle_is_ideal);
    return tc;
}
