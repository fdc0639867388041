/* suite.c - the api suite: the public contract of include/cvmesh.h, one TCase per concern. */
#include "suites.h"
#include "api/api_tests.h"

Suite *api_suite(void)
{
    Suite *s = suite_create("api");
    suite_add_tcase(s, api_version_tcase());
    suite_add_tcase(s, api_options_tcase());
    suite_add_tcase(s, api_args_tcase());
    suite_add_tcase(s, api_oom_tcase());
    suite_add_tcase(s, api_threads_tcase());
    suite_add_tcase(s, api_output_tcase());
    suite_add_tcase(s, api_quality_tcase());
    suite_add_tcase(s, api_write_tcase());
    suite_add_tcase(s, api_read_vtu_tcase());
    suite_add_tcase(s, api_read_foreign_tcase());
    suite_add_tcase(s, api_read_names_tcase());
    suite_add_tcase(s, api_marker_names_tcase());
    suite_add_tcase(s, api_nd_tcase());
    suite_add_tcase(s, api_sizing_nd_tcase());
    suite_add_tcase(s, api_sizing3_tcase());
    suite_add_tcase(s, api_mesh3_tcase());
    suite_add_tcase(s, api_mesh3_dual_tcase());
    suite_add_tcase(s, api_mesh3_insert_tcase());
    return s;
}
