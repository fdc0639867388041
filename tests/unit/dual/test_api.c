/* test_api.c - weights, dual arrays and dual measures through the public API (lib/api/dual.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dual/dual_tests.h"
#include "geom/geom_internal.h"

#define TOL 1e-9 /* constructions and measures are floating-point */

static double measure(cvm_mesh *m, cvm_measure which)
{
    double v = -1;
    ck_assert_msg(cvm_mesh_get_measure(&v, m, which) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return v;
}

/* Integer points in [0, 40]^2 (cocircular quadruples and right angles abound). */
static cvm_mesh *integer_points(void)
{
    double xy[2 * 300];
    uint64_t rng = 41;
    size_t i;
    cvm_mesh *m;
    for (i = 0; i < 2 * 300; i++)
        xy[i] = floor(41.0 * dtest_uniform(&rng));
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 300, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

/* Zero weights: power vertices are circumcentres, and "contains" is exactly
 * "no angle above 90 degrees" (integer dot products, exact in doubles). */
static void check_zero_weights(cvm_mesh *m)
{
    dtest_mesh d;
    double *V;
    int32_t *in;
    size_t t, nout = 0, nright = 0;
    dtest_get(m, &d);
    V = malloc(2 * d.nt * sizeof *V);
    in = malloc(d.nt * sizeof *in);
    ck_assert(V && in);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices(V, 2 * d.nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_inside(in, d.nt, m), CVM_OK);
    for (t = 0; t < d.nt; t++) {
        const double *p[3];
        double r[3], dot;
        int k, acute = 1;
        for (k = 0; k < 3; k++)
            p[k] = d.xy + 2 * (size_t)d.tri[3 * t + (size_t)k];
        for (k = 0; k < 3; k++) {
            const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
            r[k] = hypot(V[2 * t] - a[0], V[2 * t + 1] - a[1]);
            dot = (a[0] - c[0]) * (b[0] - c[0]) + (a[1] - c[1]) * (b[1] - c[1]);
            acute &= dot >= 0;
            nright += dot == 0;
        }
        ck_assert_double_eq_tol(r[1], r[0], TOL * r[0]);
        ck_assert_double_eq_tol(r[2], r[0], TOL * r[0]);
        ck_assert_int_eq(in[t], acute);
        nout += !acute;
    }
    ck_assert_uint_gt(nright, 0);
    ck_assert_uint_gt(nout, 0);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL_OUTSIDE_PCT), 100.0 * (double)nout / (double)d.nt);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL_OUTSIDE_PCT), measure(m, CVM_MEASURE_OBTUSE_PCT));
    free(V);
    free(in);
    dtest_free(&d);
}

START_TEST(zero_weights_give_circumcentres_and_angle_test)
{
    cvm_mesh *m = integer_points();
    double *zero;
    size_t nv;
    check_zero_weights(m); /* no weights set */
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    zero = calloc(nv, sizeof *zero);
    ck_assert_ptr_nonnull(zero);
    ck_assert_int_eq(cvm_mesh_set_weights(m, zero, nv), CVM_OK);
    check_zero_weights(m); /* explicit zero weights */
    free(zero);
    cvm_mesh_free(m);
}
END_TEST

/* The test's own power vertex: Cramer's rule on absolute coordinates. */
static void own_vertex(const double *a, const double *b, const double *c, double wa, double wb,
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

static ptrdiff_t edge_index(const dtest_mesh *d, cvm_index a, cvm_index b)
{
    size_t k;
    cvm_index lo = a < b ? a : b, hi = a < b ? b : a;
    for (k = 0; k < d->ne; k++)
        if (d->edge[2 * k] == lo && d->edge[2 * k + 1] == hi)
            return (ptrdiff_t)k;
    return -1;
}

/* Random weights on a refined square: every array and measure agrees with
 * the test's own computation. */
START_TEST(weighted_measures_match_independent_computation)
{
    const double h = 0.05;
    cvm_mesh *m = dtest_refined_square(h);
    dtest_mesh d;
    uint64_t rng = 5;
    double *w, *V, *own, *len, *area, total = 0, min_dual = HUGE_VAL, min_step = HUGE_VAL;
    int32_t *in;
    uint8_t *bv;
    size_t v, t, nout = 0, nbt = 0, nbout = 0, nv;
    int j, k;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = malloc(nv * sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (v = 0; v < nv; v++)
        w[v] = 0.3 * h * h * dtest_uniform(&rng);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    dtest_get(m, &d);
    V = malloc(2 * d.nt * sizeof *V);
    own = malloc(2 * d.nt * sizeof *own);
    in = malloc(d.nt * sizeof *in);
    len = malloc(d.ne * sizeof *len);
    area = malloc(d.nv * sizeof *area);
    bv = calloc(d.nv, 1);
    ck_assert(V && own && in && len && area && bv);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices(V, 2 * d.nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_inside(in, d.nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_edge_lengths(len, d.ne, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_areas(area, d.nv, m), CVM_OK);
    for (t = 0; t < d.nt; t++)
        for (j = 0; j < 3; j++)
            if (d.nbr[3 * t + (size_t)j] < 0) {
                bv[d.tri[3 * t + (size_t)(j + 1) % 3]] = 1;
                bv[d.tri[3 * t + (size_t)(j + 2) % 3]] = 1;
            }
    for (t = 0; t < d.nt; t++) {
        const cvm_index *tv = d.tri + 3 * t;
        const double *p[3];
        int inside = 1;
        for (k = 0; k < 3; k++)
            p[k] = d.xy + 2 * (size_t)tv[k];
        own_vertex(p[0], p[1], p[2], w[tv[0]], w[tv[1]], w[tv[2]], own + 2 * t);
        ck_assert_double_eq_tol(own[2 * t], V[2 * t], TOL * h);
        ck_assert_double_eq_tol(own[2 * t + 1], V[2 * t + 1], TOL * h);
        for (k = 0; k < 3; k++)
            inside &= cvm__orient2d(p[k], p[(k + 1) % 3], own + 2 * t) >= 0;
        ck_assert_int_eq(in[t], inside);
        nout += !inside;
        if (bv[tv[0]] || bv[tv[1]] || bv[tv[2]]) {
            nbt++;
            nbout += !inside;
        }
    }
    ck_assert_uint_gt(nout, 0); /* the weights do push some power vertices out */
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DUAL_OUTSIDE_PCT),
                            100.0 * (double)nout / (double)d.nt, 1e-12);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT),
                            100.0 * (double)nbout / (double)nbt, 1e-12);
    /* dual edges: between neighbours' power vertices, or to the power foot */
    for (t = 0; t < d.nt; t++)
        for (j = 0; j < 3; j++) {
            cvm_index u = d.nbr[3 * t + (size_t)j];
            cvm_index a = d.tri[3 * t + (size_t)(j + 1) % 3], b = d.tri[3 * t + (size_t)(j + 2) % 3];
            ptrdiff_t e = edge_index(&d, a, b);
            const double *pa = d.xy + 2 * (size_t)a, *pb = d.xy + 2 * (size_t)b;
            double want, prim = hypot(pa[0] - pb[0], pa[1] - pb[1]);
            ck_assert_int_ge(e, 0);
            if (u >= 0) {
                want = hypot(own[2 * t] - own[2 * (size_t)u], own[2 * t + 1] - own[2 * (size_t)u + 1]);
                min_dual = want < min_dual ? want : min_dual;
                min_step = fmin(min_step, fmin(want, prim));
            } else {
                /* foot: the point of line ab with equal power to a and b */
                double s = 0.5 * (prim * prim + w[a] - w[b]) / (prim * prim);
                double fx = pa[0] + s * (pb[0] - pa[0]), fy = pa[1] + s * (pb[1] - pa[1]);
                want = hypot(own[2 * t] - fx, own[2 * t + 1] - fy);
                ck_assert_double_eq_tol((fx - pa[0]) * (fx - pa[0]) + (fy - pa[1]) * (fy - pa[1]) - w[a],
                                        (fx - pb[0]) * (fx - pb[0]) + (fy - pb[1]) * (fy - pb[1]) - w[b],
                                        TOL * h * h);
            }
            ck_assert_double_eq_tol(len[e], want, TOL * h);
        }
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_DUAL_EDGE), min_dual, TOL * h);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_TIME_STEP_PROXY), min_step, TOL * h);
    ck_assert_double_le(measure(m, CVM_MEASURE_TIME_STEP_PROXY), measure(m, CVM_MEASURE_MIN_DUAL_EDGE));
    /* co-volume areas tile the domain (signed pieces sum to the area) */
    for (v = 0; v < d.nv; v++)
        total += area[v];
    ck_assert_double_eq_tol(total, 1.0, 1e-12);
    free(w);
    free(V);
    free(own);
    free(in);
    free(len);
    free(area);
    free(bv);
    dtest_free(&d);
    cvm_mesh_free(m);
}
END_TEST

/* On a well-centred mesh the dual areas are the power cells: for the
 * regular hexagon the centre's cell is the hexagon of the edge midpoints
 * and circumcentres, area sqrt(3)/2 (side 1, circumradius 1/sqrt(3)). */
START_TEST(dual_area_of_hexagon_centre)
{
    double xy[14], area[7];
    cvm_mesh *m;
    int k;
    xy[0] = xy[1] = 0;
    for (k = 0; k < 6; k++) {
        xy[2 + 2 * k] = cos(k * 3.14159265358979323846 / 3);
        xy[3 + 2 * k] = sin(k * 3.14159265358979323846 / 3);
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 7, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_areas(area, 7, m), CVM_OK);
    ck_assert_double_eq_tol(area[0], sqrt(3.0) / 2.0, TOL);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL_OUTSIDE_PCT), 0.0);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_DUAL_EDGE), 1.0 / sqrt(3.0), TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_TIME_STEP_PROXY), 1.0 / sqrt(3.0), TOL);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(bad_weights_are_rejected_and_named)
{
    cvm_mesh *m;
    double w[5] = {0.01, 0.02, 0.03, 0.04, 0.05}, got[5], bad[5];
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.4};
    cvm_entity kind;
    int64_t idx;
    size_t i;
    ck_assert_int_eq(cvm_mesh_set_weights(NULL, w, 5), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 5), CVM_E_STATE); /* before triangulate */
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "triangulate"));
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_weights(m, NULL, 5), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 4), CVM_E_ARGUMENT); /* wrong count */
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "count 4"));
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "vertex count 5"));
    memcpy(bad, w, sizeof bad);
    bad[3] = NAN;
    ck_assert_int_eq(cvm_mesh_set_weights(m, bad, 5), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "vertex 3"));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &idx, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_VERTEX);
    ck_assert_int_eq(idx, 3);
    bad[3] = 0.0;
    bad[1] = -INFINITY;
    ck_assert_int_eq(cvm_mesh_set_weights(m, bad, 5), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "vertex 1"));
    /* failures keep the previous weights */
    ck_assert_int_eq(cvm_mesh_copy_weights(got, 5, m), CVM_OK);
    for (i = 0; i < 5; i++)
        ck_assert_double_eq(got[i], w[i]);
    /* buffers too small write nothing */
    ck_assert_int_eq(cvm_mesh_copy_weights(got, 4, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices(got, 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_areas(got, 4, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_edge_lengths(got, 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_inside(NULL, 0, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_inside(NULL, 3, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices(got, 10, NULL), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

/* .node output: the weight is the first vertex attribute. */
START_TEST(node_output_writes_weight_first)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.4};
    double w[5] = {0.125, 0.25, 0.375, 0.5, 0.0625};
    char dir[] = "/tmp/cvmtest_dual_XXXXXX", path[256], line[256];
    cvm_mesh *m;
    FILE *f;
    long nv, dim, nattr, nmark, id;
    double x, y, a0;
    int k;
    ck_assert_ptr_nonnull(mkdtemp(dir));
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 5), CVM_OK);
    snprintf(path, sizeof path, "%s/out.node", dir);
    ck_assert_msg(cvm_mesh_write(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    do
        ck_assert_ptr_nonnull(fgets(line, sizeof line, f));
    while (line[0] == '#');
    ck_assert_int_eq(sscanf(line, "%ld %ld %ld %ld", &nv, &dim, &nattr, &nmark), 4);
    ck_assert_int_eq(nv, 5);
    ck_assert_int_eq(nattr, 1);
    for (k = 0; k < 5; k++) {
        do
            ck_assert_ptr_nonnull(fgets(line, sizeof line, f));
        while (line[0] == '#');
        ck_assert_int_eq(sscanf(line, "%ld %lf %lf %lf", &id, &x, &y, &a0), 4);
        ck_assert_double_eq(a0, w[id]);
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/out.node", dir);
    remove(path);
    snprintf(path, sizeof path, "%s/out.ele", dir);
    remove(path);
    snprintf(path, sizeof path, "%s/out.edge", dir);
    remove(path);
    ck_assert_int_eq(rmdir(dir), 0);
    cvm_mesh_free(m);
}
END_TEST

TCase *dual_api_tcase(void)
{
    TCase *tc = tcase_create("api");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, zero_weights_give_circumcentres_and_angle_test);
    tcase_add_test(tc, weighted_measures_match_independent_computation);
    tcase_add_test(tc, dual_area_of_hexagon_centre);
    tcase_add_test(tc, bad_weights_are_rejected_and_named);
    tcase_add_test(tc, node_output_writes_weight_first);
    return tc;
}
