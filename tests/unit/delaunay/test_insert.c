/* test_insert.c - public point insertion into an existing triangulation (cvm_mesh_insert_points). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_tests.h"
#include "support/mesh_oracle.h"

static cvm_mesh *unit_square(void)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

START_TEST(insert_returns_ids_and_rejects)
{
    cvm_mesh *m = unit_square();
    double pts[] = {0.5, 0.5, 2.0, 2.0, 0.5, 0.5, 0.52, 0.5, 0.5, 0.0, 0.25, 0.75};
    cvm_index ids[6];
    size_t nv;
    ck_assert_int_eq(cvm_mesh_insert_points(ids, m, pts, 6, 0.05), CVM_OK);
    ck_assert_int_eq(ids[0], 4);
    ck_assert_int_eq(ids[1], CVM_REJECTED); /* outside the domain */
    ck_assert_int_eq(ids[2], CVM_REJECTED); /* duplicate */
    ck_assert_int_eq(ids[3], CVM_REJECTED); /* closer than 0.05 */
    ck_assert_int_eq(ids[4], 5);            /* on the boundary segment: splits it */
    ck_assert_int_eq(ids[5], 6);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, 7);
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(insert_many_keeps_constrained_delaunay)
{
    cvm_mesh *m = unit_square();
    size_t n = 5000, i, nseg;
    double *xy = malloc(2 * n * sizeof *xy);
    cvm_index *ids = malloc(n * sizeof *ids);
    dtest_random_points(xy, n, 17);
    ck_assert_int_eq(cvm_mesh_insert_points(ids, m, xy, n, 0), CVM_OK);
    for (i = 0; i < n; i++)
        ck_assert_int_ne(ids[i], CVM_REJECTED);
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_count(&nseg, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(nseg, 4);
    free(xy);
    free(ids);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(insert_bad_arguments)
{
    cvm_mesh *m;
    double p[2] = {NAN, 0};
    cvm_index id;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, 0), CVM_E_STATE);
    cvm_mesh_free(m);
    m = unit_square();
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 0"));
    p[0] = 0.5;
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, -1), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, NULL, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, NULL, p, 1, 0), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

TCase *delaunay_insert_tcase(void)
{
    TCase *tc = tcase_create("insert");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, insert_returns_ids_and_rejects);
    tcase_add_test(tc, insert_many_keeps_constrained_delaunay);
    tcase_add_test(tc, insert_bad_arguments);
    return tc;
}
