/* test_frontal.c - frontal-Delaunay refinement (lib/refine/frontal.c) through cvm_mesh_refine. */
#include "refine/refine_tests.h"
#include "support/mesh_oracle.h"

void rtest_small_angle_terminates(cvm_algorithm algo, double angle, double h);
void rtest_jagged_star(cvm_algorithm algo, unsigned long seed);

START_TEST(square_meets_angle_and_size)
{
    rtest_shared_geometry("square.poly", 0.03, 1, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(channel_meets_angle_and_size)
{
    rtest_shared_geometry("channel.poly", 0.05, 1, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(annulus_meets_angle_and_size)
{
    rtest_shared_geometry("annulus.poly", 0.2, 0, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(cylinder_meets_angle_and_size)
{
    rtest_shared_geometry("cylinder.poly", 0.5, 0, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(naca0012_meets_angle_and_size)
{
    rtest_shared_geometry("naca0012.poly", 0.5, 0, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(three_degree_wedge_terminates)
{
    rtest_small_angle_terminates(CVM_ALGO_FRONTAL, 3.0, 0.01);
}
END_TEST

START_TEST(jagged_star_terminates)
{
    rtest_jagged_star(CVM_ALGO_FRONTAL, 7);
    rtest_jagged_star(CVM_ALGO_FRONTAL, 8);
}
END_TEST

/* Frontal placement gives more regular meshes than circumcentres on the square. */
START_TEST(frontal_is_more_regular_than_delaunay)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    double reg[2];
    int k;
    for (k = 0; k < 2; k++) {
        cvm_mesh *m;
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(rtest_refine_uniform(m, 0.03, k ? CVM_ALGO_FRONTAL : CVM_ALGO_DELAUNAY), CVM_OK);
        ck_assert_int_eq(cvm_mesh_get_measure(&reg[k], m, CVM_MEASURE_REGULAR_PCT), CVM_OK);
        cvm_mesh_free(m);
    }
    ck_assert_double_gt(reg[1], reg[0] + 30);
}
END_TEST

TCase *refine_frontal_tcase(void)
{
    TCase *tc = tcase_create("frontal");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, square_meets_angle_and_size);
    tcase_add_test(tc, channel_meets_angle_and_size);
    tcase_add_test(tc, annulus_meets_angle_and_size);
    tcase_add_test(tc, cylinder_meets_angle_and_size);
    tcase_add_test(tc, naca0012_meets_angle_and_size);
    tcase_add_test(tc, three_degree_wedge_terminates);
    tcase_add_test(tc, jagged_star_terminates);
    tcase_add_test(tc, frontal_is_more_regular_than_delaunay);
    return tc;
}
