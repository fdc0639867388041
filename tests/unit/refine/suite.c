/* suite.c - the refine suite: one TCase per source file under test. */
#include "suites.h"
#include "refine/refine_tests.h"

Suite *refine_suite(void)
{
    Suite *s = suite_create("refine");
    suite_add_tcase(s, refine_sizing_tcase());
    suite_add_tcase(s, refine_sizing_batch_tcase());
    suite_add_tcase(s, refine_bad_queue_tcase());
    suite_add_tcase(s, refine_delaunay_tcase());
    suite_add_tcase(s, refine_frontal_tcase());
    suite_add_tcase(s, refine_aflr_tcase());
    suite_add_tcase(s, refine_swap_smooth_tcase());
    suite_add_tcase(s, refine_report_tcase());
    suite_add_tcase(s, refine_random_domains_tcase());
    suite_add_tcase(s, refine_regions_tcase());
    suite_add_tcase(s, refine_march_tcase());
    suite_add_tcase(s, refine_resample_tcase());
    return s;
}
