/* test_regular.c - cvm_mesh_set_weights restores the regular property by exact power flips (lib/delaunay/regular.c). */
#include <stdlib.h>
#include <string.h>

#include "dual/dual_tests.h"

static double measure(cvm_mesh *m, cvm_measure which)
{
    double v = -1;
    ck_assert_msg(cvm_mesh_get_measure(&v, m, which) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return v;
}

/* Random weights on a frontal mesh of the square, at the smallest amplitude
 * from 0.4 h^2 up that breaks a power test (the mesh is near equilateral): the
 * Delaunay mesh fails the power test somewhere; after cvm_mesh_set_weights
 * every interior non-segment edge passes it (the test's own exact check), the
 * segments and the vertices are untouched and nothing vanished. */
START_TEST(random_weights_make_refined_square_regular)
{
    const double h = 0.05;
    cvm_mesh *m = dtest_refined_square(h);
    dtest_mesh d0, d1;
    uint64_t rng = 2026;
    double *w;
    size_t v;
    dtest_get(m, &d0);
    w = malloc(d0.nv * sizeof *w);
    ck_assert_ptr_nonnull(w);
    {
        /* the smallest amplitude (from 0.4 h^2 up) at which flips are needed: the
           more regular the refiner gets, the larger the weights this takes */
        double amp;
        size_t bad = 0;
        for (amp = 0.4; amp <= 1.0 && bad == 0; amp *= 1.1) {
            uint64_t r = rng;
            for (v = 0; v < d0.nv; v++)
                w[v] = amp * h * h * dtest_uniform(&r);
            bad = dtest_power_violations(&d0, w);
        }
        ck_assert_uint_gt(bad, 0); /* flips are needed */
    }
    ck_assert_msg(cvm_mesh_set_weights(m, w, d0.nv) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    dtest_get(m, &d1);
    ck_assert_uint_eq(dtest_power_violations(&d1, w), 0);
    ck_assert_uint_eq(d1.nv, d0.nv);
    ck_assert_uint_eq(d1.nt, d0.nt);
    ck_assert_uint_eq(d1.nseg, d0.nseg);
    ck_assert_int_eq(memcmp(d1.seg, d0.seg, 2 * d0.nseg * sizeof *d0.seg), 0);
    ck_assert_int_eq(memcmp(d1.xy, d0.xy, 2 * d0.nv * sizeof *d0.xy), 0);
    ck_assert_int_eq(memcmp(d1.w, w, d0.nv * sizeof *w), 0);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_double_eq(measure(m, CVM_MEASURE_VANISHED_VERTICES), 0.0);
    /* removing the weights gives the constrained Delaunay mesh back */
    ck_assert_int_eq(cvm_mesh_set_weights(m, NULL, 0), CVM_OK);
    dtest_free(&d1);
    dtest_get(m, &d1);
    for (v = 0; v < d1.nv; v++)
        ck_assert_double_eq(d1.w[v], 0.0);
    ck_assert_uint_eq(dtest_power_violations(&d1, d1.w), 0);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    dtest_free(&d0);
    dtest_free(&d1);
    free(w);
    cvm_mesh_free(m);
}
END_TEST

/* Same on an unconstrained point set (flips across the whole hull). */
START_TEST(random_weights_make_point_set_regular)
{
    cvm_mesh *m;
    dtest_mesh d0, d1;
    uint64_t rng = 7;
    double xy[2 * 400], *w;
    size_t v;
    for (v = 0; v < 2 * 400; v++)
        xy[v] = dtest_uniform(&rng);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 400, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    dtest_get(m, &d0);
    w = malloc(d0.nv * sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (v = 0; v < d0.nv; v++)
        w[v] = 2e-4 * dtest_uniform(&rng); /* mean spacing 0.05: up to (0.28 h)^2 */
    ck_assert_uint_gt(dtest_power_violations(&d0, w), 0);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, d0.nv), CVM_OK);
    dtest_get(m, &d1);
    ck_assert_uint_eq(dtest_power_violations(&d1, w), 0);
    ck_assert_double_eq(measure(m, CVM_MEASURE_VANISHED_VERTICES), 0.0);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    dtest_free(&d0);
    dtest_free(&d1);
    free(w);
    cvm_mesh_free(m);
}
END_TEST

/* A vertex whose power cell is empty is kept and counted, never dropped. */
START_TEST(vertex_with_empty_power_cell_is_reported)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.4, 0.45};
    double w[5] = {0, 0, 0, 0, -10};
    size_t nv;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_double_eq(measure(m, CVM_MEASURE_VANISHED_VERTICES), 0.0);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 5), CVM_OK);
    ck_assert_double_eq(measure(m, CVM_MEASURE_VANISHED_VERTICES), 1.0);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, 5);
    /* a weight that gives it a cell back makes the mesh regular again */
    w[4] = 0;
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 5), CVM_OK);
    ck_assert_double_eq(measure(m, CVM_MEASURE_VANISHED_VERTICES), 0.0);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvm_mesh_free(m);
}
END_TEST

/* A point inserted below the lifted facet of its triangle has an empty power
 * cell: it is rejected, and the mesh stays regular. */
START_TEST(insert_with_empty_power_cell_is_rejected)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    double w[5] = {0, 0, 0, 0, 0.2};
    double p[2] = {0.5, 0.55};
    cvm_index id = 7;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, 5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, 0), CVM_OK);
    ck_assert_int_eq(id, CVM_REJECTED);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    /* far from the heavy vertex a point is inserted normally */
    p[0] = 0.05;
    p[1] = 0.9;
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, 0), CVM_OK);
    ck_assert_int_eq(id, 5);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
}
END_TEST

TCase *dual_regular_tcase(void)
{
    TCase *tc = tcase_create("regular");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, random_weights_make_refined_square_regular);
    tcase_add_test(tc, random_weights_make_point_set_regular);
    tcase_add_test(tc, vertex_with_empty_power_cell_is_reported);
    tcase_add_test(tc, insert_with_empty_power_cell_is_rejected);
    return tc;
}
