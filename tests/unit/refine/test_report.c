/* test_report.c - the refinement report's "where": cvm_mesh_copy_refine_unmet() against the test's own measurements. */
#include <math.h>
#include <stdlib.h>

#include "refine/refine_tests.h"

/* Smallest angle (degrees) of the mesh triangle whose centroid is (x, y);
 * fails when no triangle has that centroid. */
static double angle_at_centroid(cvm_mesh *m, double x, double y)
{
    size_t nv, nt, t, best = (size_t)-1;
    double *xy, bestd = HUGE_VAL, ang = 180;
    cvm_index *tri;
    int k;
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    for (t = 0; t < nt; t++) {
        double gx = 0, gy = 0, d;
        for (k = 0; k < 3; k++) {
            gx += xy[2 * tri[3 * t + k]] / 3;
            gy += xy[2 * tri[3 * t + k] + 1] / 3;
        }
        d = hypot(gx - x, gy - y);
        if (d < bestd) {
            bestd = d;
            best = t;
        }
    }
    ck_assert(bestd <= 1e-12);
    for (k = 0; k < 3; k++) {
        const double *o = xy + 2 * tri[3 * best + k], *a = xy + 2 * tri[3 * best + (k + 1) % 3],
                     *b = xy + 2 * tri[3 * best + (k + 2) % 3];
        double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
        double g = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / 3.14159265358979323846;
        if (g < ang)
            ang = g;
    }
    free(xy);
    free(tri);
    return ang;
}

/* Each entry names a real triangle; its bits agree with the report's counts and
 * with the test's own angle measurement. */
static void check_unmet(cvm_mesh *m)
{
    size_t n, i, n_angle = 0, n_size = 0, n_small = 0;
    double *w, v;
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_REFINE_UNMET), CVM_OK);
    w = malloc((3 * n + 1) * sizeof *w);
    if (n > 0)
        ck_assert_int_eq(cvm_mesh_copy_refine_unmet(w, 3 * n - 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_refine_unmet(w, 3 * n, m), CVM_OK);
    for (i = 0; i < n; i++) {
        int bits = (int)w[3 * i + 2];
        double a = angle_at_centroid(m, w[3 * i], w[3 * i + 1]);
        ck_assert(bits > 0 && bits < 8 && (double)bits == w[3 * i + 2]);
        if (bits & CVM_UNMET_ANGLE) {
            n_angle++;
            ck_assert(a < 30 + 1e-9);
        }
        n_size += (bits & CVM_UNMET_SIZE) != 0;
        n_small += (bits & CVM_UNMET_SMALL_INPUT_ANGLE) != 0;
    }
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_REFINE_UNMET_ANGLE), CVM_OK);
    ck_assert_uint_eq(n_angle, (size_t)v);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_REFINE_UNMET_SIZE), CVM_OK);
    ck_assert_uint_eq(n_size, (size_t)v);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE), CVM_OK);
    ck_assert_uint_eq(n_small, (size_t)v);
    free(w);
}

START_TEST(small_input_angle_is_located)
{
    cvm_mesh *m;
    size_t n;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    rtest_set_wedge(m, 3);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, 0.1, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_REFINE_UNMET), CVM_OK);
    ck_assert_uint_gt(n, 0);
    check_unmet(m);
    /* a new triangulation forgets the report */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_REFINE_UNMET), CVM_OK);
    ck_assert_uint_eq(n, 0);
    ck_assert_int_eq(cvm_mesh_copy_refine_unmet(NULL, 0, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_refine_unmet(NULL, 0, NULL), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(steiner_limit_leaves_located_triangles)
{
    char path[512];
    cvm_mesh *m;
    size_t n;
    rtest_data_path(path, sizeof path, "square.poly");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_STEINER, 40), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, 0.02, CVM_ALGO_FRONTAL), CVM_INCOMPLETE_STEINER_LIMIT);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_REFINE_UNMET), CVM_OK);
    ck_assert_uint_gt(n, 10);
    check_unmet(m);
    cvm_mesh_free(m);
}
END_TEST

/* Input point (0.0135, 0.0065) lies within rounding inside the convex hull
 * edge (0.0075, 0.0005)-(0.0155, 0.0085) (on it in decimal), and a segment
 * runs from it along that edge. Kept, the flat triangle between the edge and
 * the point was a wedge of a vanishing angle that no rounded split point could
 * enter, and the triangles beside it stayed as thin as 0.78 degrees on CVM_OK
 * without being exempt. The hull now passes through the point: every
 * triangle left below the angle is an exempt small input angle, and
 * cvm_mesh_check() accepts the mesh (tests/fuzz/corpus/refine/
 * regression_hull_edge_through_a_point_within_rounding). */
START_TEST(hull_edge_within_rounding_of_a_point_passes_through_it)
{
    static const double xy[] = {0.01, 0.0080000000000000002, 0.0070000000000000001, 0.00975,
        0.0067499999999999999, 0.005875, 0.0045000000000000005, 0.00050000000000000001, 0.0015,
        0.0065000000000000006, 0.00050000000000000001, 0.00050000000000000001, 0.0155,
        0.0085000000000000006, 0.0074999999999999997, 0.0025000000000000001, 0.0155,
        0.0085000000000000006, 0.0135, 0.0065000000000000006, 0.0155, 0.0085000000000000006,
        0.0074999999999999997, 0.00050000000000000001, 0.0025000000000000001, 0.0065000000000000006,
        0.0054999999999999997, 0.0085000000000000006, 0.00050000000000000001, 0.00050000000000000001};
    static const cvm_index segs[] = {0, 1, 1, 2, 2, 0, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
    double unmet_angle, small;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 15, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 9), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, 23.5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_AREA, 6.5e-6), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_ENCROACH_LENS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SWAP, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, NULL, CVM_ALGO_FRONTAL), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_measure(&unmet_angle, m, CVM_MEASURE_REFINE_UNMET_ANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&small, m, CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE), CVM_OK);
    ck_assert_msg(unmet_angle == small, "%g triangles below the angle, %g of them exempt", unmet_angle,
                  small);
    check_unmet(m);
    cvm_mesh_free(m);
}
END_TEST

/* The options of fuzz_refine's regression seeds below: frontal, hull kept,
 * 20 + 13 x 69 / 255 (about 23.5) degrees, maximum area 6.5e-6, lens,
 * marching; then every triangle left below the angle must be an exempt small
 * input angle, and cvm_mesh_check() must accept the mesh. */
static void refine_like_fuzz_seed(const double *xy, size_t np, const cvm_index *segs, size_t nseg,
                                  double seed)
{
    double unmet_angle, small;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, nseg), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, 20.0 + 13.0 * 69 / 255.0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_AREA, 1e-3 * 1e-3 * 6.5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_ENCROACH_LENS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MARCH_SEGMENTS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SWAP, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, -1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_RELAX_SWEEPS, -1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_STEINER, 5000), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, seed), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, NULL, CVM_ALGO_FRONTAL), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_measure(&unmet_angle, m, CVM_MEASURE_REFINE_UNMET_ANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&small, m, CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE), CVM_OK);
    ck_assert_msg(unmet_angle == small, "%g triangles below the angle, %g of them exempt", unmet_angle,
                  small);
    check_unmet(m);
    cvm_mesh_free(m);
}

/* Input point (0.0135, 0.0065) lies about 1e-19 off the free segment
 * (0.0155, 0.0085)-(0.0075, 0.0005) (on it in decimal), and another segment
 * runs from it to (0.0155, 0.0085): the flat triangles between the two
 * chains are wedges no rounded split point can enter, so every split of the
 * piece was refused, and a 5.6-degree triangle beside it stayed unexempt on
 * CVM_OK. The chain of the segment now passes through the vertex
 * (tests/fuzz/corpus/refine/regression_segment_routed_through_a_point_within_rounding). */
START_TEST(segment_within_rounding_of_a_point_passes_through_it)
{
    static const double xy[] = {0.01, 0.0080000000000000002, 0.0070000000000000001, 0.00975,
        0.0090000000000000011, 0.00087500000000000002, 0.0015, 0.00050000000000000001,
        0.0045000000000000005, 0.00050000000000000001, 0.0015, 0.0065000000000000006,
        0.00050000000000000001, 0.00050000000000000001, 0.0155, 0.0085000000000000006,
        0.0074999999999999997, 0.0025000000000000001, 0.0155, 0.0085000000000000006,
        0.0135, 0.0065000000000000006, 0.0155, 0.0085000000000000006,
        0.0074999999999999997, 0.00050000000000000001, 0.0025000000000000001, 0.0065000000000000006,
        0.0054999999999999997, 0.0085000000000000006};
    static const cvm_index segs[] = {0, 1, 1, 2, 2, 0, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
    refine_like_fuzz_seed(xy, 15, segs, 9, 0);
}
END_TEST

/* Input point (0.0075, 0.0025), where the segment from (0.0005, 0.0005) ends,
 * lies 2e-19 off the hull segment (0.0045, 0.0005)-(0.0135, 0.0065) (on it in
 * decimal): an input angle of 17.7 degrees. The hull segment's chain missed the
 * point, its splits fell at midpoints instead of on shells around the join, and
 * the exemption found no join: unexempt triangles clustered within 2e-7 of the
 * point on CVM_OK. The hull segment now passes through the point, and an end
 * within the chain tolerance of another segment is a join
 * (tests/fuzz/corpus/refine/regression_hull_segment_through_a_segment_end_within_rounding). */
START_TEST(hull_segment_within_rounding_of_a_segment_end_passes_through_it)
{
    static const double xy[] = {0.0065000000000000006, 0.013375, 0.0070000000000000001, 0.00975,
        0.0052500000000000003, 0.0013749999999999999, 0.00050000000000000001, 0.00050000000000000001,
        0.00050000000000000001, 0.00050000000000000001, 0.00050000000000000001, 0.00050000000000000001,
        0.0015, 0.00050000000000000001, 0.0045000000000000005, 0.00050000000000000001,
        0.0135, 0.0065000000000000006, 0.00050000000000000001, 0.00050000000000000001,
        0.0074999999999999997, 0.0025000000000000001};
    static const cvm_index segs[] = {0, 1, 1, 2, 2, 0, 5, 6, 7, 8, 9, 10};
    refine_like_fuzz_seed(xy, 11, segs, 6, 80);
}
END_TEST

TCase *refine_report_tcase(void)
{
    TCase *tc = tcase_create("report");
    tcase_add_test(tc, small_input_angle_is_located);
    tcase_add_test(tc, steiner_limit_leaves_located_triangles);
    tcase_add_test(tc, hull_edge_within_rounding_of_a_point_passes_through_it);
    tcase_add_test(tc, segment_within_rounding_of_a_point_passes_through_it);
    tcase_add_test(tc, hull_segment_within_rounding_of_a_segment_end_passes_through_it);
    return tc;
}
