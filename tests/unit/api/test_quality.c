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

/* The right triangle (-X, 0), (X, 0), (0, X) at the largest doubles: its
 * edges and area exceed the largest double, but its angles and the dual's
 * ratios are defined; unscaled products gave inf - inf (NaN angles counted in
 * the 0-10 bin, area NaN). */
START_TEST(huge_right_triangle_has_exact_angles_and_infinite_area)
{
    static const double xy[] = {-1.797e308, 0, 1.797e308, 0, 0, 1.797e308};
    cvm_mesh *m = points(xy, 3);
    double h[20], q1[1], q2[1];
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_ANGLE_DEG), 45, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MAX_ANGLE_DEG), 90, TOL);
    ck_assert(measure(m, CVM_MEASURE_REGULAR_PCT) == 0);
    ck_assert(measure(m, CVM_MEASURE_AREA) == HUGE_VAL);
    ck_assert(measure(m, CVM_MEASURE_MIN_AREA) == HUGE_VAL);
    ck_assert(measure(m, CVM_MEASURE_MAX_EDGE) == HUGE_VAL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 18, m, CVM_HIST_ANGLE_DEG), CVM_OK);
    ck_assert(h[0] == 0 && h[4] == 2 && h[8] + h[9] == 1);
    /* |centroid - circumcentre| / inradius = (X / 3) / (X / (1 + sqrt 2)) */
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_Q2_MAX), (1 + sqrt(2.0)) / 3, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_Q1_MEAN_DEG), 45, TOL);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q1, 1, m, CVM_HIST_Q1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q2, 1, m, CVM_HIST_Q2), CVM_OK);
    ck_assert_double_eq_tol(q1[0], 45, TOL);
    ck_assert_double_eq_tol(q2[0], (1 + sqrt(2.0)) / 3, TOL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 20, m, CVM_HIST_Q2), CVM_OK);
    ck_assert(h[3] == 1); /* 0.8047 in [0.75, 1) */
    cvm_mesh_free(m);
}
END_TEST

/* Coordinates exact in binary: b - a = (2^533, 2^533), c - a = (2^532,
 * 2^532 + 2^490). Each product of the area formula is about 2^1065 and
 * overflows, their difference is exactly 2^1023: area 2^1022. */
START_TEST(thin_triangle_with_overflowing_products_has_its_exact_area)
{
    double xy[6] = {0, 0, 0, 0, 0, 0};
    cvm_mesh *m;
    double h[18];
    xy[2] = xy[3] = ldexp(1, 533);
    xy[4] = ldexp(1, 532);
    xy[5] = ldexp(1, 532) + ldexp(1, 490);
    m = points(xy, 3);
    ck_assert(measure(m, CVM_MEASURE_AREA) == ldexp(1, 1022));
    ck_assert(measure(m, CVM_MEASURE_MIN_AREA) == ldexp(1, 1022));
    ck_assert(measure(m, CVM_MEASURE_MIN_ANGLE_DEG) > 0);
    ck_assert(measure(m, CVM_MEASURE_MIN_ANGLE_DEG) < 1e-9);
    ck_assert(measure(m, CVM_MEASURE_MAX_ANGLE_DEG) > 180 - 1e-9);
    ck_assert(measure(m, CVM_MEASURE_OBTUSE_PCT) == 100);
    ck_assert_int_eq(cvm_mesh_copy_histogram(h, 18, m, CVM_HIST_ANGLE_DEG), CVM_OK);
    ck_assert(h[0] == 2 && h[17] == 1);
    cvm_mesh_free(m);
}
END_TEST

/* At 2^-600 the products of edge components underflow to 0 (atan2(0, 0) gave
 * 0-degree angles); the area 2^-1201 is below the smallest double. */
START_TEST(tiny_right_triangle_has_exact_angles)
{
    double xy[6] = {0, 0, 0, 0, 0, 0};
    cvm_mesh *m;
    xy[2] = ldexp(1, -600);
    xy[5] = ldexp(1, -600);
    m = points(xy, 3);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MIN_ANGLE_DEG), 45, TOL);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_MAX_ANGLE_DEG), 90, TOL);
    ck_assert(measure(m, CVM_MEASURE_MIN_EDGE) == ldexp(1, -600));
    ck_assert(measure(m, CVM_MEASURE_AREA) == 0);
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_Q2_MAX), (1 + sqrt(2.0)) / 3, TOL);
    cvm_mesh_free(m);
}
END_TEST

/* Every measure and histogram of the --quality report, in report order. */
static const cvm_measure k_measures[] = {
    CVM_MEASURE_MIN_ANGLE_DEG, CVM_MEASURE_MAX_ANGLE_DEG, CVM_MEASURE_REGULAR_PCT,
    CVM_MEASURE_OBTUSE_PCT, CVM_MEASURE_DEGREE6_PCT, CVM_MEASURE_MIN_DUAL_EDGE_RATIO,
    CVM_MEASURE_MIN_EDGE, CVM_MEASURE_MAX_EDGE, CVM_MEASURE_AREA, CVM_MEASURE_MIN_AREA,
    CVM_MEASURE_DUAL_OUTSIDE_PCT, CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT,
    CVM_MEASURE_MIN_DUAL_EDGE, CVM_MEASURE_TIME_STEP_PROXY, CVM_MEASURE_VANISHED_VERTICES,
    CVM_MEASURE_Q1_MEAN_DEG, CVM_MEASURE_Q1_MIN_BOUNDARY_DEG, CVM_MEASURE_Q2_MAX,
    CVM_MEASURE_Q2_MEAN, CVM_MEASURE_Q2_MAX_BOUNDARY, CVM_MEASURE_Q3_MAX, CVM_MEASURE_Q4_MAX,
    CVM_MEASURE_Q5_MIN, CVM_MEASURE_Q5_MEAN, CVM_MEASURE_Q5_MIN_BOUNDARY};
#define N_MEASURES (sizeof k_measures / sizeof k_measures[0])
#define N_HISTS 7
#define N_VALUES (N_MEASURES + 20 * N_HISTS)

/* Every value of the report into v (N_VALUES); when fresh, each is computed
 * after a call that forgets the cached values (setting an option to the
 * value it has), so none comes from an earlier request. */
static void report_values(cvm_mesh *m, int fresh, double *v)
{
    size_t i;
    memset(v, 0, N_VALUES * sizeof *v);
    for (i = 0; i < N_MEASURES + N_HISTS; i++) {
        if (fresh)
            ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, 1), CVM_OK);
        if (i < N_MEASURES)
            v[i] = measure(m, k_measures[i]);
        else
            ck_assert_int_eq(cvm_mesh_copy_histogram(v + N_MEASURES + 20 * (i - N_MEASURES), 20, m,
                                                     (cvm_histogram)(CVM_HIST_ANGLE_DEG + (int)(i - N_MEASURES))),
                             CVM_OK);
    }
}

/* The Delaunay triangulation of n random points, with a few weights when
 * weighted, so that every measure is non-trivial. */
static cvm_mesh *random_mesh(size_t n, uint64_t seed, int weighted)
{
    double *xy = malloc(2 * n * sizeof *xy), *w;
    size_t i, nv;
    cvm_mesh *m;
    ck_assert_ptr_nonnull(xy);
    cvmtest_random_points(xy, n, seed);
    m = points(xy, n);
    free(xy);
    if (!weighted)
        return m;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = calloc(nv, sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (i = 0; i < nv; i += 7)
        w[i] = 1e-5;
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    free(w);
    return m;
}

START_TEST(cached_measures_are_identical_to_recomputed_ones)
{
    cvm_mesh *m = random_mesh(3000, 11, 1);
    double fresh[N_VALUES], cached[N_VALUES], again[N_VALUES], *q1, *q2, sum = 0, mx = 0;
    size_t nt, k;
    report_values(m, 1, fresh);
    report_values(m, 0, cached);
    report_values(m, 0, again);
    ck_assert(memcmp(fresh, cached, sizeof fresh) == 0);
    ck_assert(memcmp(fresh, again, sizeof fresh) == 0);
    /* and the summaries match the per-element values, which are never cached */
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    q1 = malloc(nt * sizeof *q1);
    q2 = malloc(nt * sizeof *q2);
    ck_assert(q1 && q2);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q1, nt, m, CVM_HIST_Q1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_quality(q2, nt, m, CVM_HIST_Q2), CVM_OK);
    for (k = 0; k < nt; k++) {
        sum += q1[k];
        mx = q2[k] > mx ? q2[k] : mx;
    }
    ck_assert(measure(m, CVM_MEASURE_Q1_MEAN_DEG) == sum / (double)nt);
    ck_assert(measure(m, CVM_MEASURE_Q2_MAX) == mx);
    free(q1);
    free(q2);
    cvm_mesh_free(m);
}
END_TEST

/* After each kind of change, the report equals that of a mesh built in that
 * state and never measured before. */
START_TEST(cached_measures_follow_every_change_of_the_mesh)
{
    static const double extra[] = {0.25, 0.5, 0.75, 0.5, 0.5, 0.125};
    cvm_mesh *m = random_mesh(500, 5, 1), *ref;
    double got[N_VALUES], want[N_VALUES], before[N_VALUES];
    cvm_index ids[3];
    report_values(m, 0, before);
    /* insert points */
    ck_assert_int_eq(cvm_mesh_insert_points(ids, m, extra, 3, 0.0), CVM_OK);
    report_values(m, 0, got);
    ref = random_mesh(500, 5, 1);
    ck_assert_int_eq(cvm_mesh_insert_points(ids, ref, extra, 3, 0.0), CVM_OK);
    report_values(ref, 0, want);
    ck_assert(memcmp(got, want, sizeof got) == 0);
    ck_assert(memcmp(got, before, sizeof got) != 0);
    /* remove the weights */
    ck_assert_int_eq(cvm_mesh_set_weights(m, NULL, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_weights(ref, NULL, 0), CVM_OK);
    report_values(m, 0, got);
    report_values(ref, 1, want);
    ck_assert(memcmp(got, want, sizeof got) == 0);
    /* triangulate again from the input alone */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    report_values(m, 0, got);
    cvm_mesh_free(ref);
    ref = random_mesh(500, 5, 0);
    report_values(ref, 1, want);
    ck_assert(memcmp(got, want, sizeof got) == 0);
    cvm_mesh_free(ref);
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
    tcase_add_test(tc, huge_right_triangle_has_exact_angles_and_infinite_area);
    tcase_add_test(tc, thin_triangle_with_overflowing_products_has_its_exact_area);
    tcase_add_test(tc, tiny_right_triangle_has_exact_angles);
    tcase_add_test(tc, cached_measures_are_identical_to_recomputed_ones);
    tcase_add_test(tc, cached_measures_follow_every_change_of_the_mesh);
    return tc;
}
