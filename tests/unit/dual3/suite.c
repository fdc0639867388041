/* suite.c - the dual3 suite: the 3D power-dual optimiser (cvm_mesh_optimise_dual3) and merged dual cells. */
#include "suites.h"
#include "dual3/dual3_tests.h"

Suite *dual3_suite(void)
{
    Suite *s = suite_create("dual3");
    suite_add_tcase(s, dual3_optimise_tcase());
    suite_add_tcase(s, dual3_merge_tcase());
    suite_add_tcase(s, dual3_own_mesh_tcase());
    return s;
}
