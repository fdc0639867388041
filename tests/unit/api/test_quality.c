/* test_quality.c - quality measures and histograms (lib/api/quality.c) on meshes with known answers. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "support/fixtures.h"

#define TOL 1e-9 /* measures are floating-point: the one place for a tolerance */

static cvm_mesh *points(const double *xy, size_t n)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n, 2), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

static double measure(cvm_mesh *m, cvm_measure which)
{
    double v = -1;
    ck_assert_msg(cvm_mesh_get_measure(&v, m, which) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return v;
}

/* A regular hexagon around its centre: six equilateral triangles. */
static cvm_mesh *hexagon(void)
{
    double xy[14];
    int k;
    xy[0] = xy[1] = 0;
    for (k = 0; k < 6; k++) {
        xy[2 + 2 * k] = cos(k * 3.14159265358979323846 / 3);
        xy[3 + 2 * k] = sin(k * 3.14159265358979323846 / 3);
    }
    return points(xy, 7);
}

START_TEST(hexagon_is_perfectly_regular)
{
    cvm_mesh *m = hexagon();
    double h[18], d[16];
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_ANGLE_DEG), 60, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MAX_ANGLE_DEG), 60, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_REGULAR_PCT), 100, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_OBTUSE_PCT), 0, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DEGREE6_PCT), 100, TOL);
    /* neighbouring circumcentres are 1/sqrt(3) apart across unit spokes */
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO), 1 / sqrt(3.0), TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_EDGE), 1, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MAX_EDGE), 1, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_AREA), 1.5 * sqrt(3.0), TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_AREA), sqrt(3.0) / 4, TOL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 18, m, CVM_HIST_ANGLE_DEG), CVM_OK);
    ck_assert(h[5] + h[6] == 18); /* 60 degrees, rounding on either side */
    ck_assert_int_eq(cvm_mesh_copy_histogram(d, 16, m, CVM_HIST_DEGREE), CVM_OK);
    ck_assert(d[6] == 1);
    cvm_mesh_free(m);
}
END_TEST

/* With weights the dual edge joins power vertices: centre weight w moves the
 * power vertex of each spoke triangle to distance (1 + w) / sqrt(3) from the
 * centre (equal power |V|^2 - w = |V - A|^2 on the triangle's bisector), and
 * neighbouring ones, 60 degrees apart, are that far from each other. */
START_TEST(dual_edge_ratio_uses_power_vertices)
{
    cvm_mesh *m = hexagon();
    double w[7] = {0.5, 0, 0, 0, 0, 0, 0};
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 7), CVM_OK);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO), 1.5 / sqrt(3.0), TOL);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(right_triangles_are_not_obtuse_but_have_zero_dual_edges)
{
    cvm_mesh *m;
    double h[18];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_unit_square), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MAX_ANGLE_DEG), 90, TOL);
    ck_assert(measure(m, CVM_MEASURE_OBTUSE_PCT) == 0);
    ck_assert(measure(m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO) < TOL); /* cocircular square */
    ck_assert(measure(m, CVM_MEASURE_DEGREE6_PCT) == 0);          /* no interior vertex */
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_AREA), 1, TOL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 18, m, CVM_HIST_ANGLE_DEG), CVM_OK);
    ck_assert(h[4] + h[3] == 4 && h[8] + h[9] == 2);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(flat_triangle_is_obtuse)
{
    static const double xy[] = {0, 0, 4, 0, 2, 0.5};
    cvm_mesh *m = points(xy, 3);
    ck_assert(measure(m, CVM_MEASURE_OBTUSE_PCT) == 100);
    ck_assert(measure(m, CVM_MEASURE_MAX_ANGLE_DEG) > 150);
    ck_assert(measure(m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO) == 0); /* no interior edge */
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_AREA), 1, TOL);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(degree_histogram_counts_interior_vertices_only)
{
    double xy[2 * 25], d[16];
    int i, j;
    cvm_mesh *m;
    /* a 5 x 5 grid sheared into nearly equilateral triangles, exact in binary so that the
       sides stay straight and no four points are cocircular: 9 interior vertices */
    for (i = 0; i < 5; i++)
        for (j = 0; j < 5; j++) {
            xy[2 * (5 * i + j)] = j + 0.5 * i;
            xy[2 * (5 * i + j) + 1] = i * 0.875;
        }
    m = points(xy, 25);
    ck_assert_int_eq(cvm_mesh_copy_histogram(d, 16, m, CVM_HIST_DEGREE), CVM_OK);
    ck_assert(d[6] == 9);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DEGREE6_PCT), 100, TOL);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(measures_need_triangles_and_valid_arguments)
{
    cvm_mesh *m;
    double v, h[18];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_MIN_ANGLE_DEG), CVM_E_STATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "triangulate"));
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 18, m, CVM_HIST_ANGLE_DEG), CVM_E_STATE);
    cvm_mesh_free(m);
    m = hexagon();
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, (cvm_measure)0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, (cvm_measure)99), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_get_measure(NULL, m, CVM_MEASURE_AREA), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, NULL, CVM_MEASURE_AREA), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 17, m, CVM_HIST_ANGLE_DEG), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 15, m, CVM_HIST_DEGREE), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 18, m, (cvm_histogram)8), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_histogram(NULL, 18, m, CVM_HIST_DEGREE), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_AREA), CVM_OK);
    ck_assert_str_eq(cvm_mesh_errmsg(m), "");
    cvm_mesh_free(m);
}
END_TEST

TCase *api_quality_tcase(void)
{
    TCase *tc = tcase_create("quality");
    tcase_add_test(tc, hexagon_is_perfectly_regular);
    tcase_add_test(tc, dual_edge_ratio_uses_power_vertices);
    tcase_add_test(tc, right_triangles_are_not_obtuse_but_have_zero_dual_edges);
    tcase_add_test(tc, flat_triangle_is_obtuse);
    tcase_add_test(tc, degree_histogram_counts_interior_vertices_only);
    tcase_add_test(tc, measures_need_triangles_and_valid_arguments);
    return tc;
}
