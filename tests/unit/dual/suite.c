/* suite.c - the dual suite: one TCase per source file under test. */
#include "suites.h"
#include "dual/dual_tests.h"

Suite *dual_suite(void)
{
    Suite *s = suite_create("dual");
    suite_add_tcase(s, dual_power_side_tcase());
    suite_add_tcase(s, dual_regular_tcase());
    suite_add_tcase(s, dual_api_tcase());
    suite_add_tcase(s, dual_quality_tcase());
    suite_add_tcase(s, dual_cells_tcase());
    suite_add_tcase(s, dual_fv_tcase());
    suite_add_tcase(s, dual_optimise_tcase());
    suite_add_tcase(s, dual_prepass_tcase());
    return s;
}
